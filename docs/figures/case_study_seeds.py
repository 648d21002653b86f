#!/usr/bin/python3
"""The case-study table of docs/validation.md: each scenario over many seeds (one part pair per
seed), the mean axial resistance of each run (summary.json, constrained stage), as median and
quartiles.

  /usr/bin/python3 docs/figures/case_study_seeds.py [SEEDS] > docs/figures/case-study-seeds.csv
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENARIOS = ["paper-case1-h7js6", "paper-case1-h7js6-paper", "paper-case1-h7g6",
             "paper-case1-h7g6-paper", "pin-cylindrical"]


def quartiles(values):
    q = statistics.quantiles(values, n=4, method="inclusive")
    return q[0], q[1], q[2]


def main():
    seeds = int(sys.argv[1]) if len(sys.argv) > 1 else 40
    print("scenario,seeds,axial_q25_N,axial_median_N,axial_q75_N,axial_max_N,"
          "below_1.2N,tick_p99_median_us")
    with tempfile.TemporaryDirectory() as runs:
        for name in SCENARIOS:
            axial, p99 = [], []
            for seed in range(1, seeds + 1):
                out = os.path.join(runs, f"{name}-{seed}")
                subprocess.run([os.path.join(ROOT, "build/bin/fitfeel"), "run",
                                f"scenarios/{name}.yaml", "--seed", str(seed), "--out", out],
                               cwd=ROOT, check=True, capture_output=True)
                with open(os.path.join(out, "summary.json")) as f:
                    summary = json.load(f)
                axial.append(summary["axial_resistance_N"]["mean"])
                p99.append(summary["tick_us"]["p99"])
            q25, med, q75 = quartiles(axial)
            low = sum(1 for a in axial if a < 1.2)
            print(f"{name},{seeds},{q25:.3g},{med:.3g},{q75:.3g},{max(axial):.3g},{low},"
                  f"{statistics.median(p99):.3g}", flush=True)


if __name__ == "__main__":
    main()
