#!/bin/bash
# Tick compute time of the default scenario in real time, without a viewer (`fitfeel run
# --realtime`) and with `fitfeel view --realtime --wait` and headless Chromium connected for the
# whole run, alternating ROUNDS times; prints each run's p50 / p99 / max (us) and the medians.
# Run from the repository root after a Release build: bash docs/figures/viewer-tick.sh [ROUNDS]
set -euo pipefail
rounds=${1:-5}
fitfeel=build/bin/fitfeel
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
stats() { /usr/bin/python3 -c "import json,sys; t=json.load(open(sys.argv[1]))['tick_us']; print(t['p50'], t['p99'], t['max'])" "$1"; }
for r in $(seq 1 "$rounds"); do
  "$fitfeel" run --realtime --out "$work/run$r" >/dev/null
  echo "run $(stats "$work/run$r/summary.json")" | tee -a "$work/all"
  "$fitfeel" view --realtime --wait --port 0 --exit-after 1 --out "$work/view$r" >"$work/log" 2>&1 &
  server=$!
  for _ in $(seq 1 100); do grep -aq "http://127.0.0.1:" "$work/log" && break; sleep 0.1; done
  port=$(grep -ao "http://127.0.0.1:[0-9]*" "$work/log" | head -1 | sed 's/.*://')
  # 200 state frames at 60 Hz keep the page connected past the 4 s run.
  node --no-warnings --experimental-websocket tests/browser/screenshot.mjs \
    "http://127.0.0.1:$port/" "$work/shot.png" --min-frames 200 --timeout 60 >/dev/null
  wait "$server"
  echo "view $(stats "$work/view$r/summary.json")" | tee -a "$work/all"
done
/usr/bin/python3 - "$work/all" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
for kind in ("run", "view"):
    v = [list(map(float, r[1:])) for r in rows if r[0] == kind]
    med = [statistics.median(c) for c in zip(*v)]
    print(f"median {kind}: p50 {med[0]:.2f} us, p99 {med[1]:.2f} us, max {med[2]:.1f} us over {len(v)} runs")
PY
