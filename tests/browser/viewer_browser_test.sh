#!/bin/bash
# End-to-end test of `fitfeel view` in a real browser: serves a shipped scenario, checks the HTTP
# surface with curl (the page, the WebSocket handshake's 101, 404 for traversal and unknown
# paths), loads the page in headless Chromium (screenshot.mjs, DevTools protocol), scrubs the
# finished run's time slider, and checks the screenshot shows the parts (not a blank canvas) and,
# when given, that EXPECT (JavaScript evaluated in the page, or a file of it) gives true.
#
# viewer_browser_test.sh FITFEEL SCENARIO OUT.png [EXPECT | EXPECT.js]
set -euo pipefail
fitfeel=$1 scenario=$2 out=$3 expect_js=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
log=$(mktemp)
server=""
cleanup() {
  [ -n "$server" ] && kill "$server" 2>/dev/null || true
  rm -f "$log"
}
trap cleanup EXIT

# Virtual clock: the run is done at once and the page opens it as a finished run with a slider.
# The waits below are bounds against a hang, not measurements: a loaded machine may take long.
"$fitfeel" view "$scenario" --port 0 --virtual --exit-after 300 >"$log" 2>&1 &
server=$!
for _ in $(seq 1 1200); do
  grep -aq "run finished" "$log" && break
  kill -0 "$server" 2>/dev/null || { cat "$log"; echo "fitfeel view exited early"; exit 1; }
  sleep 0.1
done
port=$(grep -ao "http://127.0.0.1:[0-9]*" "$log" | head -1 | sed 's/.*://')
[ -n "$port" ] || { cat "$log"; echo "no URL printed"; exit 1; }
url="http://127.0.0.1:$port"

# The status code only: a kept-open WebSocket ends curl by its --max-time, which is not a failure
# (10 s: time for the handshake on a loaded machine; each such check costs that long).
status() { curl -s --path-as-is -o /dev/null -w "%{http_code}" "$@" || true; }
expect() {
  local want=$1; shift
  local got
  got=$(status "$@")
  [ "$got" = "$want" ] || { echo "expected $want, got $got: curl $*"; exit 1; }
}
curl -s "$url/" | grep -q "<title>fitfeel view</title>" || { echo "curl / did not return the page"; exit 1; }
expect 200 "$url/"
expect 404 "$url/../../etc/passwd"
expect 404 "$url/nope"
expect 404 "$url/three/../../../etc/passwd"
expect 101 --max-time 10 -H "Connection: Upgrade" -H "Upgrade: websocket" \
  -H "Sec-WebSocket-Version: 13" -H "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==" "$url/ws"
expect 403 --max-time 10 -H "Connection: Upgrade" -H "Upgrade: websocket" -H "Origin: http://evil.example" \
  -H "Sec-WebSocket-Version: 13" -H "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==" "$url/ws"

expectation=()
if [ -f "$expect_js" ]; then expectation=(--expect-file "$expect_js")
elif [ -n "$expect_js" ]; then expectation=(--expect "$expect_js"); fi
# The slider to 45 % of the run: the server answers with that instant's pressure map.
node --no-warnings --experimental-websocket "$here/screenshot.mjs" "$url/" "$out" --timeout 150 \
  --eval "const t = document.getElementById('time'); t.value = Math.round(0.45 * t.max); t.dispatchEvent(new Event('input'))" \
  "${expectation[@]}"

# The 3D view is the left part of the window (the panel is 290 px on the right): the parts must
# cover a share of it (a key's thin flanks cover 4 %, a shaft 30 %), in shades of lit surfaces.
stats=$(/usr/bin/python3 "$here/png_stats.py" "$out" 0 0 980 800)
echo "screenshot $out: $stats"
/usr/bin/python3 - "$stats" <<'PY'
import json, sys
s = json.loads(sys.argv[1])
assert s["foreground_fraction"] > 0.02, f"blank canvas? only {s['foreground_fraction']:.3f} drawn"
assert s["distinct_colours"] > 20, f"flat picture: {s['distinct_colours']} colours"
PY
