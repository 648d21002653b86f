"""The C example host (examples/c_host) over a whole scene against `fitfeel run`: the host sets
only the device's state, the scene's part_motion gives the part's radial load to both, so the
resistance statistics the host prints equal summary.json's as doubles (no tolerance).

c_host_matches_run_test.py C_HOST FITFEEL SCENARIO
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

c_host, fitfeel, scenario = sys.argv[1:4]

with tempfile.TemporaryDirectory() as work:
    subprocess.run([fitfeel, "run", scenario, "--out", work], check=True,
                   stdout=subprocess.DEVNULL)
    summary = json.loads((pathlib.Path(work) / "summary.json").read_text())
host = subprocess.run([c_host, scenario], check=True, capture_output=True, text=True).stdout
print(host, end="")

failures = 0
ticks = int(re.search(r"^(\d+) ticks at 1 kHz", host, re.M).group(1))
constrained = int(re.search(r"^constrained ticks (\d+)$", host, re.M).group(1))
for name, got, want in [("ticks", ticks, summary["ticks"]),
                        ("constrained ticks", constrained, summary["constrained_ticks"])]:
    if got != want:
        print(f"{name}: C host {got}, fitfeel run {want}")
        failures += 1
for key, label in [("axial_resistance_N", "axial resistance "),
                   ("radial_resistance_N", "radial resistance")]:
    line = re.search(rf"^{label} mean (\S+) N, min (\S+) N, max (\S+) N$", host, re.M)
    for stat, text in zip(["mean", "min", "max"], line.groups()):
        got, want = float(text), summary[key][stat]
        if got != want:
            print(f"{key} {stat}: C host {got!r}, fitfeel run {want!r}")
            failures += 1
# fitfeel run's own line, to the digits it prints: what a user compares by eye.
print(f"fitfeel run: peak axial resistance {summary['axial_resistance_N']['max']:.3g} N")
sys.exit(1 if failures else 0)
