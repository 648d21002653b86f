#!/bin/bash
# The C# binding against the C interface, bit for bit: compiles the runtime (Fitfeel.dll) and the
# console host (examples/csharp_host) with mcs, records the device states of a `fitfeel run` of
# SCENARIO, and steps them through the C replay host and the C# host; their outputs (every tick's
# wrench as the bits of its doubles) must be equal, and the C host's must equal the wrenches the
# run commanded (it fails otherwise). Then a refused scenario must come back as a
# ScenarioException located at its file, line, column and key.
#
# host_matches_c_test.sh SOURCE_DIR FITFEEL REPLAY_HOST LIBFITFEEL_C SCENARIO
set -euo pipefail
source=$1 fitfeel=$2 replay=$3 lib=$4 scenario=$5
command -v mcs >/dev/null && command -v mono >/dev/null ||
  { echo "mcs and mono are needed: apt-get install mono-mcs mono-runtime (make test does)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mcs -nologo -warnaserror+ -target:library -out:"$work/Fitfeel.dll" "$source"/bindings/csharp/Runtime/*.cs
mcs -nologo -warnaserror+ -r:"$work/Fitfeel.dll" -r:System.Numerics -out:"$work/fitfeel_csharp_host.exe" \
  "$source"/examples/csharp_host/*.cs

grep -q "outputs: \[trace, summary\]" "$source/$scenario" || { echo "the scenario's outputs line changed"; exit 1; }
sed 's/outputs: \[trace, summary\]/outputs: [trace, summary, recording]/' "$source/$scenario" >"$work/scene.yaml"
"$fitfeel" run "$work/scene.yaml" --out "$work/run" >/dev/null

"$replay" "$work/scene.yaml" "$work/run/recording.csv" >"$work/c.txt"
LD_LIBRARY_PATH="$(dirname "$lib")" mono "$work/fitfeel_csharp_host.exe" "$work/scene.yaml" \
  "$work/run/recording.csv" >"$work/csharp.txt"
diff "$work/c.txt" "$work/csharp.txt" >"$work/diff.txt" ||
  { head -20 "$work/diff.txt"; echo "the C# host's wrenches differ from the C host's"; exit 1; }
ticks=$(grep -c '^[0-9]* [0-9a-f]\{16\} ' "$work/csharp.txt")
[ "$ticks" -ge 1000 ] || { echo "only $ticks ticks stepped"; exit 1; }
tail -1 "$work/csharp.txt"
echo "C# host: $ticks ticks, every wrench equal bit for bit to the C host's and fitfeel run's"

sed 's/^  speed: 10 mm\/s /  speed: 10 mm /' "$work/scene.yaml" >"$work/refused.yaml"
status=0
LD_LIBRARY_PATH="$(dirname "$lib")" mono "$work/fitfeel_csharp_host.exe" "$work/refused.yaml" \
  "$work/run/recording.csv" >/dev/null 2>"$work/error.txt" || status=$?
cat "$work/error.txt"
[ "$status" -eq 2 ] || { echo "a refused scenario exited $status, not 2"; exit 1; }
line=$(grep -n '^  speed: 10 mm ' "$work/refused.yaml" | cut -d: -f1)
grep -q "^ScenarioException at $work/refused.yaml line $line column 10 key 'device.speed': " "$work/error.txt" ||
  { echo "the refusal is not a located ScenarioException"; exit 1; }
