#!/bin/bash
# The Unity package's layout (bindings/csharp): the files Unity's package manager and a user
# look for exist, the runtime compiles on its own (no UnityEngine: its asmdef references none),
# the sample MonoBehaviour compiles against it and a stub of the UnityEngine names it uses, and
# the README's snippet compiles. Unity itself is not run.
#
# unity_package_test.sh SOURCE_DIR
set -euo pipefail
package=$1/bindings/csharp
command -v mcs >/dev/null ||
  { echo "mcs is needed: apt-get install mono-mcs mono-runtime (make test does)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for f in package.json README.md Plugins/README.md Runtime/Fitfeel.Runtime.asmdef \
         Runtime/NativeMethods.cs Runtime/SceneHandle.cs Runtime/Scene.cs \
         Samples~/FixedUpdateHost/FitfeelStepper.cs; do
  test -f "$package/$f" || { echo "missing: bindings/csharp/$f"; exit 1; }
done
/usr/bin/python3 - "$package" <<'PY'
import json, pathlib, sys
package = pathlib.Path(sys.argv[1])
manifest = json.loads((package / "package.json").read_text())
for key in ("name", "version", "displayName", "unity"):
    assert key in manifest, f"package.json has no {key}"
assert manifest["name"] == manifest["name"].lower(), "Unity package names are lower case"
for sample in manifest.get("samples", []):
    assert (package / sample["path"]).is_dir(), f"sample folder {sample['path']} missing"
asmdef = json.loads((package / "Runtime/Fitfeel.Runtime.asmdef").read_text())
assert asmdef["name"] == "Fitfeel.Runtime" and asmdef["noEngineReferences"]
PY

mcs -nologo -warnaserror+ -target:library -out:"$work/Fitfeel.dll" "$package"/Runtime/*.cs
mcs -nologo -warnaserror+ -target:library -r:"$work/Fitfeel.dll" -out:"$work/Sample.dll" \
  "$package/Samples~/FixedUpdateHost/FitfeelStepper.cs" "$package/Tests~/UnityEngineStub.cs"
# The README's C# lines, inside a method, as a user pastes them.
{
  echo 'using Fitfeel; static class Snippet { static void Run() {'
  awk '/^```csharp$/{b=1; next} b && /^```/{b=0} b' "$package/README.md"
  echo '} }'
} >"$work/Snippet.cs"
mcs -nologo -warnaserror+ -target:library -r:"$work/Fitfeel.dll" -out:"$work/Snippet.dll" "$work/Snippet.cs"
echo "unity package: files present, runtime, sample and README snippet compile"
