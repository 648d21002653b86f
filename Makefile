# Thin wrapper: everything real is in CMake (presets) and ctest. Run as root on Debian 12.
#   make run    install missing packages, build (Release), run the default scenario and draw
#               its force trace next to its CSV
#   make test   install missing packages, build, run the whole test suite
#   make stress-test  the whole suite STRESS_ROUNDS times (default 5) with more ctest jobs than
#               cores and a CPU hog on every core (tools/stress/stress_test.sh); reports every
#               failure
#   make bench  build (benchmarks on) and run the benchmarks, then every shipped scenario as a
#               whole run (table of medians)
#   make clean  remove the build tree and the outputs
#   make check-sanitizers  the whole suite under AddressSanitizer + UndefinedBehaviorSanitizer
#               (preset asan, build-asan/) and the concurrency test under ThreadSanitizer (tsan)
#   make fuzz   build the libFuzzer targets (preset fuzz: clang, ASan, UBSan; FUZZ_PACKAGES) and
#               run each for FUZZ_SECONDS (default 60) from its seed corpus; fails on a finding
#               (the input is kept in build-fuzz/artifacts/)
#   make campaign  the generated-input campaign over scenarios, recordings and command lines
#               (tools/campaign/run.py; CAMPAIGN_CASES, default 10000)
#   make fem-check  rerun the CalculiX reference of the elastic contact model (tools/fem) and
#               compare it with the committed data the tests use (about two hours, most of
#               it the 3-D cases; needs no build)

PACKAGES := build-essential cmake ninja-build ccache libeigen3-dev libfcl-dev libccd-dev \
            libboost-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libgtest-dev \
            libgmock-dev libbenchmark-dev gnuplot-nox libjs-three chromium nodejs python3 \
            pybind11-dev python3-dev python3-numpy python3-distributed mono-mcs mono-runtime \
            libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev \
            libocct-foundation-dev libocct-ocaf-dev libtbb-dev
# Only for `make fem-check`: the tests use the committed FEM data and need no solver.
FEM_PACKAGES := calculix-ccx python3-numpy
# Only for `make fuzz`: clang and its libFuzzer runtime (Debian 12 ships it in libclang-rt-14-dev).
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZ_SECONDS ?= 60
FUZZERS := quantity_fuzzer recording_fuzzer scenario_fuzzer cli_fuzzer
CAMPAIGN_CASES ?= 10000
STRESS_ROUNDS ?= 5
JOBS ?= $(shell nproc)
# Where `fitfeel run` puts the default scenario's outputs (out/<scenario name>).
DEFAULT_RUN := out/paper-case1-h7js6

.PHONY: run test stress-test bench clean deps fem-deps fuzz-deps configure build fem-check check-sanitizers \
        fuzz campaign

# apt-get only for what dpkg does not already list as installed; update only then.
deps fem-deps fuzz-deps: PACKAGES_WANTED = $(if $(filter fem-deps,$@),$(FEM_PACKAGES),\
                                            $(if $(filter fuzz-deps,$@),$(FUZZ_PACKAGES),$(PACKAGES)))
deps fem-deps fuzz-deps:
	@missing=""; \
	for p in $(PACKAGES_WANTED); do \
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

stress-test: build
	tools/stress/stress_test.sh build $(STRESS_ROUNDS)

# Benchmarks are off in a plain configure (they measure, the tests assert): switched on here.
bench: deps
	cmake --preset release -DFITFEEL_BUILD_BENCHMARKS=ON
	cmake --build --preset release -j $(JOBS)
	@for b in build/bench/*; do \
	  [ -x "$$b" ] && [ "$$b" != build/bench/scene_benchmark ] && "$$b"; \
	done; true
	build/bench/scene_benchmark

clean:
	rm -rf build build-debug build-fuzz out

fem-check: fem-deps
	@tmp=$$(mktemp -d) && trap 'rm -rf "$$tmp"' EXIT && \
	/usr/bin/python3 tools/fem/fem.py all "$$tmp" && \
	/usr/bin/python3 tools/fem/fem.py compare "$$tmp/harmonic.csv" tools/fem/data/harmonic.csv && \
	/usr/bin/python3 tools/fem/fem.py compare "$$tmp/contact.csv" tools/fem/data/contact.csv && \
	/usr/bin/python3 tools/fem/fem.py compare "$$tmp/axisymmetric.csv" \
	  tools/fem/data/axisymmetric.csv && \
	/usr/bin/python3 tools/fem/fem.py compare "$$tmp/solid.csv" tools/fem/data/solid.csv && \
	/usr/bin/python3 tools/fem/fem.py compare "$$tmp/bearing.csv" tools/fem/data/bearing.csv && \
	/usr/bin/python3 tools/fem/fem.py compare "$$tmp/key.csv" tools/fem/data/key.csv && \
	echo "fem-check: CalculiX reproduces tools/fem/data within 0.5 %"

# Not part of `make test`: a sanitized build of everything takes about as long again as the
# release build.
check-sanitizers: deps
	cmake --preset asan
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan
	cmake --preset tsan
	cmake --build build-tsan --target concurrent_runs_test -j $(JOBS)
	ctest --test-dir build-tsan -R ConcurrentRunsTest --no-tests=error --output-on-failure

# Each target from its corpus in the repository (framework/<module>/fuzz/corpus/<name>; the scenario
# loader also from scenarios/) copied to build-fuzz/corpus/<name>, where what libFuzzer adds stays.
# -timeout: an input that takes longer than 20 s is a finding (a hang).
fuzz: deps fuzz-deps
	cmake --preset fuzz
	cmake --build build-fuzz -j $(JOBS) --target fitfeel_fuzzers
	@mkdir -p build-fuzz/artifacts
	@set -e; for f in $(FUZZERS); do \
	  seeds=$$(find framework -path "*/fuzz/corpus/$$f" -type d); \
	  extra=$$([ $$f = scenario_fuzzer ] && echo scenarios || true); \
	  mkdir -p build-fuzz/corpus/$$f; \
	  echo "fuzz: $$f for $(FUZZ_SECONDS) s"; \
	  rc=0; ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  timeout -s KILL $$(( $(FUZZ_SECONDS) + 300 )) \
	  build-fuzz/fuzz/$$f build-fuzz/corpus/$$f $$seeds $$extra -max_total_time=$(FUZZ_SECONDS) \
	    -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
	    -artifact_prefix=build-fuzz/artifacts/$$f- > build-fuzz/$$f.log 2>&1 || rc=$$?; \
	  tail -n 12 build-fuzz/$$f.log; \
	  [ $$rc != 137 ] || echo "fuzz: $$f killed 300 s past its time: libFuzzer's own report hung \
	    (its out-of-memory heap profile can, on a large heap) before saving the input; the input \
	    it was running is the newest $${TMPDIR:-/tmp}/fitfeel-fuzz-*"; \
	  [ $$rc = 0 ] || { echo "fuzz: $$f found a problem (build-fuzz/$$f.log, artifacts/)"; exit 1; }; \
	done; echo "fuzz: no finding in $(FUZZERS)"

campaign: build
	/usr/bin/python3 tools/campaign/run.py --cases $(CAMPAIGN_CASES)
