#!/bin/bash
# End-to-end test of a live view (`fitfeel view --edit` or `--compare`) in headless Chromium: the
# view runs its scene in real time, passes one after another; ACT.js (awaited in the page) edits
# or switches and checks what the page then shows, and must give true; the screenshot is taken
# after it and must show the parts.
#
# live_browser_test.sh FITFEEL OUT.png ACT.js VIEW-ARGUMENTS...   (LIVE_SIZE=WxH: the window, 1280x800)
set -euo pipefail
fitfeel=$1 out=$2 act=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/view_server.sh"

# --exit-after bounds the server's life if this script is killed.
start_view "http://127.0.0.1:" "$@" --exit-after 400
# The page's helpers (sleep, until) before the test's actions, in one expression.
script=$(mktemp)
trap 'cleanup; rm -f "$script"' EXIT
cat "$here/live_act_helpers.js" "$act" >"$script"

status=0
node --no-warnings --experimental-websocket "$here/screenshot.mjs" "$url/" "$out" \
  --timeout 200 --min-frames 2 --size "${LIVE_SIZE:-1280x800}" --act-file "$script" || status=$?
echo "--- fitfeel view said:"
cat "$log"
[ "$status" -eq 0 ] || exit "$status"

check_picture "$out"
