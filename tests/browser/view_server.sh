# Sourced by the browser tests: start_view LINE ARGUMENTS... starts `fitfeel view ARGUMENTS...`
# (any free port) in the background, waits until its output has a line matching LINE and sets
# `port` and `url`; the server is killed and its log removed when the script exits.
# check_picture OUT.png: the screenshot shows parts, not a blank or flat canvas. The wait is a
# bound against a hang, not a measurement: a loaded machine may take long.
log=$(mktemp)
server=""
cleanup() {
  [ -n "$server" ] && kill "$server" 2>/dev/null || true
  rm -f "$log"
}
trap cleanup EXIT

start_view() {
  local line=$1
  shift
  "$fitfeel" view "$@" --port 0 >"$log" 2>&1 &
  server=$!
  for _ in $(seq 1 1200); do
    grep -aq "$line" "$log" && break
    kill -0 "$server" 2>/dev/null || { cat "$log"; echo "fitfeel view exited early"; exit 1; }
    sleep 0.1
  done
  port=$(grep -ao "http://127.0.0.1:[0-9]*" "$log" | head -1 | sed 's/.*://')
  [ -n "$port" ] || { cat "$log"; echo "no URL printed"; exit 1; }
  url="http://127.0.0.1:$port"
}

# The 3D view is the left part of the window (the panel is 290 px on the right): the parts must
# cover a share of it (a key's thin flanks cover 4 %, a shaft 30 %), in shades of lit surfaces.
check_picture() {
  local stats
  stats=$(/usr/bin/python3 "$here/png_stats.py" "$1" 0 0 980 800)
  echo "screenshot $1: $stats"
  /usr/bin/python3 - "$stats" <<'PY'
import json, sys
s = json.loads(sys.argv[1])
assert s["foreground_fraction"] > 0.02, f"blank canvas? only {s['foreground_fraction']:.3f} drawn"
assert s["distinct_colours"] > 20, f"flat picture: {s['distinct_colours']} colours"
PY
}
