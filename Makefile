# Thin wrapper: everything real is in CMake (presets) and ctest. Run as root on Debian 12.
#   make run    install missing packages, build (Release), run the default scenario and draw
#               its force trace next to its CSV
#   make test   install missing packages, build, run the whole test suite
#   make bench  build (benchmarks on) and run the benchmarks
#   make clean  remove the build tree and the outputs

PACKAGES := build-essential cmake ninja-build ccache libeigen3-dev libfcl-dev libccd-dev \
            libboost-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libgtest-dev \
            libgmock-dev libbenchmark-dev gnuplot-nox libjs-three chromium nodejs
JOBS ?= $(shell nproc)
# Where `fitfeel run` puts the default scenario's outputs (out/<scenario name>).
DEFAULT_RUN := out/paper-case1-h7js6

.PHONY: run test bench clean deps configure build

# apt-get only for what dpkg does not already list as installed; update only then.
deps:
	@missing=""; \
	for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' "$$p" 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  if [ "$$(id -u)" -ne 0 ]; then echo "make: run as root to install:$$missing" >&2; exit 1; fi; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update && apt-get install -y --no-install-recommends $$missing; \
	fi

configure: deps
	cmake --preset release -DFITFEEL_BUILD_BENCHMARKS=OFF

build: configure
	cmake --build --preset release -j $(JOBS)

run: build
	build/bin/fitfeel run
	build/bin/fitfeel plot trace $(DEFAULT_RUN) -o $(DEFAULT_RUN)/trace.png
	@echo "force trace chart: $(DEFAULT_RUN)/trace.png"

test: build
	ctest --preset release

# Benchmarks are off in a plain configure (they measure, the tests assert): switched on here.
bench: deps
	cmake --preset release -DFITFEEL_BUILD_BENCHMARKS=ON
	cmake --build --preset release -j $(JOBS)
	@for b in build/bench/*; do [ -x "$$b" ] && "$$b"; done

clean:
	rm -rf build build-debug out
