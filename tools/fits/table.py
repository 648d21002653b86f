#!/usr/bin/python3
"""The seven 20 mm fits as a table for docs/validation.md (markdown on stdout).

Runs `fitfeel study` on scenarios/fits-20mm-h7*.yaml and sets each fit's force distribution beside
the closed form of DIN 7190-1 at the fit's mean interference and a handbook's description of how
the fit is assembled.

    /usr/bin/python3 tools/fits/table.py [--pairs N] [--fitfeel build/bin/fitfeel] [--out DIR]
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

FITS = ["g6", "h6", "js6", "k6", "n6", "p6", "s6"]
# How the fits are assembled, as machine-element handbooks' fit-selection tables describe them
# (e.g. Roloff/Matek, Maschinenelemente, tolerances chapter; Machinery's Handbook, ANSI B4.2
# preferred fits): sliding, by hand, light mallet, press.
HANDBOOK = {
    "g6": "sliding fit: slides together by hand",
    "h6": "sliding fit: pushed together by hand",
    "js6": "transition: by hand or a light mallet",
    "k6": "transition: a light mallet",
    "n6": "transition: a press (or a heavy hammer)",
    "p6": "interference: a press",
    "s6": "interference: a press, or shrinking",
}


def limits(fitfeel, scenario):
    """(shaft lower, shaft upper, hole lower, hole upper) deviations in um from `fitfeel validate`."""
    out = subprocess.run([fitfeel, "validate", scenario], check=True, capture_output=True,
                         text=True).stdout
    found = re.findall(r"deviations ([-+]?[\d.]+) \.\. ([-+]?[\d.]+) um", out)
    (sl, su), (hl, hu) = found[0], found[1]
    return float(sl), float(su), float(hl), float(hu)


def din7190_press_force(interference_um):
    """DIN 7190-1 at full engagement for the scenes' pair: solid C45 shaft, hub 20/30 mm, 20 mm long,
    mu 0.15, Rz 1.6 um on both parts (smoothing 0.8 (Rz_i + Rz_a)). None without interference."""
    d, da, length, e, nu, mu, rz = 20e-3, 30e-3, 20e-3, 210e9, 0.3, 0.15, 1.6e-6
    u = interference_um * 1e-6 - 0.8 * (rz + rz)
    if u <= 0:
        return None
    q = d / da
    p = e * (u / d) / ((1 + q * q) / (1 - q * q) + nu + (1 - nu))
    return mu * p * math.pi * d * length


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--fitfeel", default="build/bin/fitfeel")
    ap.add_argument("--out", help="keep the studies here (default: a temporary folder)")
    args = ap.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="fitfeel-fits-")
    rows = []
    for fit in FITS:
        scenario = f"scenarios/fits-20mm-h7{fit}.yaml"
        folder = os.path.join(out, fit)
        subprocess.run([args.fitfeel, "study", scenario, "--pairs", str(args.pairs), "--seed",
                        str(args.seed), "--out", folder], check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(folder, "study.json")) as f:
            s = json.load(f)
        sl, su, hl, hu = limits(args.fitfeel, scenario)
        mean_u = (sl + su) / 2 - (hl + hu) / 2  # centred capable processes
        din = din7190_press_force(mean_u)
        rows.append((fit, mean_u, s, din))
        print(f"{fit}: {s['pairs']} pairs in {s['wall_s']:.1f} s", file=sys.stderr)

    def force(x):
        return f"{x:.3g}" if x < 1000 else f"{x / 1000:.3g} k"

    print(f"| fit | mean interference, um | P(interference) | axial max N: p5 / median / p95 "
          f"| DIN 7190 at mean, N | P(yield) | handbook |")
    print("|---|---|---|---|---|---|---|")
    for fit, mean_u, s, din in rows:
        m = s["axial_max_N"]
        y = s.get("probability_of_yield")
        print(f"| H7/{fit} | {mean_u:+.1f} | {s['probability_of_interference']:.2f} | "
              f"{force(m['p5'])} / {force(m['p50'])} / {force(m['p95'])} | "
              f"{force(din) if din else '-'} | {'-' if y is None else f'{y:.2f}'} | "
              f"{HANDBOOK[fit]} |")
    print(f"\n{args.pairs} pairs per fit, seed {args.seed}.")


if __name__ == "__main__":
    main()
