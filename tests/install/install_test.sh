#!/bin/bash
# The installed package as a third party uses it: installs the build tree to a temporary prefix,
# builds examples/ against it with find_package(fitfeel) (an out-of-tree surface plugin and a host
# program), then checks that the installed `fitfeel plugins` finds its own plugins and, through
# FITFEEL_PLUGIN_PATH, the out-of-tree one, and that the host runs a scene with it.
#
# install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

# The README's snippets are copied from the example files this test builds and runs: every line
# of its cmake, cpp and c blocks in "Using fitfeel from other programs" is a line of those files.
for kind in cmake cpp c python; do
  awk -v k="$kind" '/^## Using fitfeel from other programs/{s=1} /^## Layout/{s=0}
    s && $0 == "```" k {b=1; next} b && /^```/ {b=0} b' "$source/README.md" | while IFS= read -r line; do
    grep -qxF -- "$line" <(sed 's/^ *//' "$source/examples/CMakeLists.txt" "$source/examples/host/host.cc" \
                                 "$source/examples/c_host/c_host.c" "$source/examples/python/example.py") ||
      grep -qxF -- "$line" "$source/examples/CMakeLists.txt" "$source/examples/host/host.cc" ||
      { echo "README line not in examples/: $line"; exit 1; }
  done
done

cmake --install "$build" --prefix "$prefix" >/dev/null
test -f "$prefix/lib/cmake/fitfeel/fitfeelConfig.cmake" || { echo "no package config installed"; exit 1; }
test -f "$prefix/include/fitfeel/framework/model/surface_type.h" || { echo "no headers installed"; exit 1; }

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Unoptimised: the test checks that the package builds and loads, not how fast the examples run.
cmake -S "$source/examples" -B "$work/examples" -G Ninja -DCMAKE_BUILD_TYPE= \
  -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" >/dev/null
cmake --build "$work/examples" >/dev/null

# The installed CLI finds the installed plugins (relative to its library, wherever the prefix is)
# and the out-of-tree plugin through FITFEEL_PLUGIN_PATH. Run from an empty folder, so nothing of
# the source tree is found by accident.
cd "$work"
listing=$(FITFEEL_PLUGIN_PATH="$work/examples" "$prefix/bin/fitfeel" plugins)
echo "$listing"
for id in fitfeel.surface.cylindrical fitfeel.device.simulated fitfeel.surface.example_slide; do
  grep -q "$id" <<<"$listing" || { echo "installed fitfeel plugins does not list $id"; exit 1; }
done
# Every plugin but the example from the prefix: the build tree is not searched by an install.
grep -q "library: $prefix/lib/fitfeel/plugins/libfitfeel_surface_cylindrical.so" <<<"$listing" ||
  { echo "the installed plugins were not loaded from the prefix"; exit 1; }
if grep -q "(build tree)" <<<"$listing"; then echo "an install searched the build tree"; exit 1; fi

FITFEEL_PLUGIN_PATH="$work/examples" "$work/examples/fitfeel_example_host" \
  "$source/tests/example_slide/test/conformance.yaml" "$work/out"
test -s "$work/out/trace.csv" && test -s "$work/out/summary.json" ||
  { echo "the host's run wrote no outputs"; exit 1; }

# The C host: half a second of its own 1 kHz loop on the paper's case, through libfitfeel_c.
c_out=$("$work/examples/fitfeel_example_c_host" "$source/scenarios/paper-case1-h7js6.yaml" 500)
echo "$c_out"
grep -q "^500 ticks at 1 kHz" <<<"$c_out" || { echo "the C host did not run 500 ticks"; exit 1; }
# A C-only consumer: find_package(fitfeel COMPONENTS c) from a C project, with the C++ headers'
# dependencies made unfindable. The same configure asking for the C++ component as well must
# fail, else the check hides nothing.
hidden=(-DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=TRUE -DCMAKE_DISABLE_FIND_PACKAGE_Boost=TRUE
        -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=TRUE)
cmake -S "$source/tests/install/c_consumer" -B "$work/c_consumer" -G Ninja -DCMAKE_BUILD_TYPE= \
  -DCMAKE_PREFIX_PATH="$prefix" "${hidden[@]}" >/dev/null
cmake --build "$work/c_consumer" >/dev/null
c_out=$("$work/c_consumer/fitfeel_c_consumer" "$source/scenarios/paper-case1-h7js6.yaml" 100)
grep -q "^100 ticks at 1 kHz" <<<"$c_out" || { echo "the C-only consumer did not run"; exit 1; }
mkdir -p "$work/cxx_hidden"
printf 'cmake_minimum_required(VERSION 3.25)\nproject(x LANGUAGES C)\nfind_package(fitfeel REQUIRED COMPONENTS c cxx)\n' \
  >"$work/cxx_hidden/CMakeLists.txt"
if cmake -S "$work/cxx_hidden" -B "$work/cxx_hidden/build" -DCMAKE_PREFIX_PATH="$prefix" \
     "${hidden[@]}" >/dev/null 2>&1; then
  echo "the C++ component is found with its dependencies hidden: the check hides nothing"; exit 1
fi
echo "C-only consumer: configured and built without Eigen3, Boost or nlohmann_json"
# Python: the installed package, imported from the prefix only (not the build tree).
if [ -d "$prefix/lib/python3/dist-packages/fitfeel" ]; then
  py_out=$(PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c \
    'import fitfeel, os, sys; print(os.path.dirname(fitfeel.__file__))')
  [ "$py_out" = "$prefix/lib/python3/dist-packages/fitfeel" ] ||
    { echo "python imported fitfeel from $py_out, not the prefix"; exit 1; }
  py_out=$(PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 \
    "$source/examples/python/example.py" "$source/scenarios/paper-case1-h7js6.yaml" "$work/py-study")
  echo "$py_out"
  grep -q "^P(interference)" <<<"$py_out" && test -s "$work/py-study/pairs.csv" ||
    { echo "the Python example did not run its study"; exit 1; }
  test -s "$work/py-study/study.png" || { echo "the Python study drew no study.png"; exit 1; }
  # The Dask worker script finds the installed package beside it, with nothing on PYTHONPATH.
  worker_path=$(env -u PYTHONPATH "$prefix/bin/fitfeel-worker" --fitfeel-path)
  [ "$worker_path" = "$prefix/lib/python3/dist-packages" ] ||
    { echo "fitfeel-worker found $worker_path, not the prefix's package"; exit 1; }
else
  echo "install test: no Python package installed (pybind11 missing?)"; exit 1
fi
echo "install test: ok"
