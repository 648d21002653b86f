#!/usr/bin/python3
"""The elastic law's prepare against its accuracy, per model setting, as a README table.

Runs each fit's scenario (scenarios/fits-20mm-h7<fit>.yaml) once per seed with the shipped model
and once per seed with each cheaper setting (coupled orders, depth step, solve columns, plane
sections), on one prepare thread, and prints per setting and fit: the prepare's wall time on
that thread (CPU time, with one thread; the median over the seeds), the change of the mean axial
resistance of the constrained stage against the shipped model's, seed by seed, and the largest
change anywhere in the constrained stage's trace as a share of the trace's largest resistance
(the worst seed).

    /usr/bin/python3 tools/fits/elastic_settings.py [--fits k6,n6,s6] [--seeds 1,2,3]
        [--fitfeel build/bin/fitfeel] [--out DIR]
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import tempfile

# Each setting as the keys it adds: `depth_step` replaces the model's `depth_step: auto`, the
# others join `model.options`.
SETTINGS = [
    ("shipped (6 orders, 120 columns, depth step 0.5 mm)", {}),
    ("`axial_orders: 3`", {"axial_orders": "3"}),
    ("`axial_orders: 1`", {"axial_orders": "1"}),
    ("`axial_orders: 0` (breathing mode alone)", {"axial_orders": "0"}),
    ("`depth_step: 1 mm`", {"depth_step": "1 mm"}),
    ("`depth_step: 2 mm`", {"depth_step": "2 mm"}),
    ("`columns: 90`", {"columns": "90"}),
    ("`columns: 60`", {"columns": "60"}),
    ("`axial_orders: 0`, `depth_step: 2 mm`", {"axial_orders": "0", "depth_step": "2 mm"}),
    ("`axial_orders: 0`, `columns: 60`, `depth_step: 2 mm`",
     {"axial_orders": "0", "columns": "60", "depth_step": "2 mm"}),
    ("`axial_coupling: false` (plane sections)", {"axial_coupling": "false"}),
    ("`axial_coupling: false`, `depth_step: 2 mm`",
     {"axial_coupling": "false", "depth_step": "2 mm"}),
]
SHIPPED_OPTIONS = "options: {tilt: free}"
SHIPPED_STEP = "depth_step: auto"


def variant(text, keys):
    """The scenario text with the setting's keys; fails loudly if the shipped lines moved."""
    if SHIPPED_OPTIONS not in text or SHIPPED_STEP not in text:
        raise SystemExit("the fit scenarios no longer read '%s' and '%s': update %s" %
                         (SHIPPED_OPTIONS, SHIPPED_STEP, __file__))
    options = "".join(", %s: %s" % (k, v) for k, v in keys.items() if k != "depth_step")
    text = text.replace(SHIPPED_OPTIONS, "options: {tilt: free%s}" % options)
    if "depth_step" in keys:
        text = text.replace(SHIPPED_STEP, "depth_step: " + keys["depth_step"])
    return text


def run(fitfeel, scenario, seed, out):
    """(prepare seconds, mean axial resistance, the constrained stage's axial force per tick)."""
    env = dict(os.environ, FITFEEL_PREPARE_THREADS="1")
    subprocess.run([fitfeel, "run", scenario, "--out", out, "--seed", str(seed)], check=True,
                   env=env, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "trace.csv")) as f:
        trace = [float(r["fy_N"]) for r in csv.DictReader(f) if r["stage"] == "constrained"]
    return summary["prepare_s"]["total"], summary["axial_resistance_N"]["mean"], trace


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fits", default="k6,n6,s6")
    ap.add_argument("--seeds", default="1,2,3")
    ap.add_argument("--fitfeel", default="build/bin/fitfeel")
    ap.add_argument("--out", help="keep the runs here (default: a temporary folder)")
    args = ap.parse_args()
    fits = args.fits.split(",")
    seeds = [int(s) for s in args.seeds.split(",")]
    work = args.out or tempfile.mkdtemp(prefix="fitfeel-elastic-settings-")
    cells = {}
    for fit in fits:
        with open("scenarios/fits-20mm-h7%s.yaml" % fit) as f:
            text = f.read()
        reference = {}
        for index, (name, keys) in enumerate(SETTINGS):
            scenario = os.path.join(work, "h7%s-%d.yaml" % (fit, index))
            with open(scenario, "w") as f:
                f.write(variant(text, keys))
            seconds, changes, largest = [], [], 0.0
            for seed in seeds:
                out = os.path.join(work, "h7%s-%d-seed%d" % (fit, index, seed))
                prepare, mean, trace = run(args.fitfeel, scenario, seed, out)
                if not keys:
                    reference[seed] = (mean, trace)
                ref_mean, ref_trace = reference[seed]
                if len(trace) != len(ref_trace):
                    raise SystemExit("h7%s %s seed %d: the constrained stage is %d ticks, the "
                                     "shipped model's %d" % (fit, name, seed, len(trace),
                                                             len(ref_trace)))
                seconds.append(prepare)
                changes.append((mean - ref_mean) / ref_mean)
                scale = max(abs(x) for x in ref_trace)
                largest = max(largest, max(abs(a - b) for a, b in zip(trace, ref_trace)) / scale)
            cells[(name, fit)] = "%.0f ms, %s %%, %.1f %%" % (
                statistics.median(seconds) * 1e3,
                " / ".join("%+.2f" % (100 * c) for c in changes), 100 * largest)
    print("| setting | " + " | ".join("H7/" + fit for fit in fits) + " |")
    print("|---|" + "---|" * len(fits))
    for name, _ in SETTINGS:
        print("| %s | %s |" % (name, " | ".join(cells[(name, fit)] for fit in fits)))


if __name__ == "__main__":
    main()
