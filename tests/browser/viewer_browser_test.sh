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
. "$here/view_server.sh"

# Virtual clock: the run is done at once and the page opens it as a finished run with a slider.
start_view "run finished" "$scenario" --virtual --exit-after 300

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

check_picture "$out"
