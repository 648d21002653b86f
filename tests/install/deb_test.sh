#!/bin/bash
# The Debian package (`cpack -G DEB`) as a user gets it: built from the build tree, its
# dependencies listed, unpacked into a scratch root, and its fitfeel run from an empty folder far
# from any source tree: the default scenario (found under the package's share/fitfeel), a starting
# scenario of each kind from `fitfeel new`, and the refusals a user meets there (exit 2).
#
# deb_test.sh BUILD_DIR
set -euo pipefail
build=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

(cd "$build" && cpack -G DEB -B "$work/pkg" >"$work/cpack.log" 2>&1) ||
  { cat "$work/cpack.log"; echo "cpack -G DEB failed"; exit 1; }
deb=$(ls "$work"/pkg/fitfeel_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libyaml-cpp libfcl libc6; do
  grep -q "$lib" <<<"$depends" || { echo "the package does not depend on $lib"; exit 1; }
done
dpkg-deb -x "$deb" "$work/root"
fitfeel=$work/root/usr/bin/fitfeel
test -x "$fitfeel" || { echo "no usr/bin/fitfeel in the package"; exit 1; }
test -f "$work/root/usr/share/fitfeel/scenarios/paper-case1-h7js6.yaml" ||
  { echo "no shipped scenarios under usr/share/fitfeel"; exit 1; }
test -f "$work/root/usr/share/doc/fitfeel/README.md" || { echo "no README installed"; exit 1; }

# An empty folder, and no variable that points at a source tree.
mkdir "$work/user" && cd "$work/user"
unset FITFEEL_SOURCE_DIR FITFEEL_PLUGIN_PATH
run=$("$fitfeel" run --out default)
echo "$run"
grep -q "$work/root/usr/share/fitfeel/scenarios/paper-case1-h7js6.yaml" <<<"$run" ||
  { echo "the default run did not take the package's scenario"; exit 1; }
test -s default/summary.json && test -s default/trace.csv || { echo "the default run wrote nothing"; exit 1; }

"$fitfeel" new --list | grep -q "press-fit" || { echo "fitfeel new --list lists no press-fit"; exit 1; }
for kind in $("$fitfeel" new --list | sed -n 's/^  \([a-z-]*\):.*/\1/p'); do
  "$fitfeel" new "$kind" >/dev/null
  grep -q "^scenario: $kind$" "$kind.yaml" || { echo "fitfeel new $kind: not named $kind"; exit 1; }
  "$fitfeel" validate "$kind.yaml" >/dev/null || { echo "fitfeel new $kind: does not validate"; exit 1; }
done
"$fitfeel" run press-fit.yaml --out press >/dev/null
test -s press/summary.json || { echo "the started press fit did not run"; exit 1; }

expect_refusal() {
  local what=$1; shift
  set +e
  out=$("$@" 2>&1)
  rc=$?
  set -e
  [ "$rc" -eq 2 ] && grep -q "$what" <<<"$out" ||
    { echo "expected exit 2 and '$what' from: $*; got $rc: $out"; exit 1; }
}
expect_refusal "exists; give another name or --force" "$fitfeel" new press-fit
expect_refusal "unknown kind 'gearbox'" "$fitfeel" new gearbox
touch before
ls >"$work/listing-before"
expect_refusal "must be a .yaml file" "$fitfeel" new key key.txt
ls | diff - "$work/listing-before" || { echo "a refused new wrote a file"; exit 1; }
echo "deb test: ok"
