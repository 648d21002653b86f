#!/bin/bash
# The whole suite, ROUNDS times in a row, with more ctest jobs than cores and a CPU hog on every
# core beside it: a test that depends on how threads or processes are scheduled, on wall-clock
# time or on a folder another test also uses fails here long before it fails a newcomer.
#
# tools/stress/stress_test.sh BUILD_DIR [ROUNDS] [JOBS]
#   ROUNDS  whole-suite runs (default 5)
#   JOBS    ctest's parallel jobs (default: cores + 1)
# Prints each round's failed tests and a closing "N passed, M failed" over rounds; exits 1 when a
# round failed. Each round's ctest output is kept in BUILD_DIR/stress/round-K.log.
set -uo pipefail
build=${1:?usage: stress_test.sh BUILD_DIR [ROUNDS] [JOBS]}
rounds=${2:-5}
cores=$(nproc)
jobs=${3:-$((cores + 1))}
logs="$build/stress"
mkdir -p "$logs"

hogs=()
stop_hogs() {
  for pid in "${hogs[@]}"; do kill "$pid" 2>/dev/null; done
  wait 2>/dev/null
}
trap stop_hogs EXIT
for _ in $(seq 1 "$cores"); do
  ( while :; do :; done ) &
  hogs+=($!)
done
echo "stress-test: $rounds rounds of the whole suite, ctest -j$jobs, $cores CPU hogs beside it"

passed=0 failed=0
for round in $(seq 1 "$rounds"); do
  log="$logs/round-$round.log"
  start=$(date +%s)
  if ctest --test-dir "$build" -j "$jobs" --output-on-failure >"$log" 2>&1; then
    passed=$((passed + 1))
    echo "round $round: passed ($(grep -m1 -o 'out of [0-9]*' "$log" | sed 's/out of //') tests,\
 $(($(date +%s) - start)) s)"
  else
    failed=$((failed + 1))
    echo "round $round: FAILED ($(($(date +%s) - start)) s; $log)"
    sed -n '/The following tests FAILED/,$p' "$log" | grep -E '^\s+[0-9]+ - ' || tail -5 "$log"
  fi
done
echo "stress-test: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
