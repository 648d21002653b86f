#!/usr/bin/python3
"""fitfeel from Python, as the README shows it: a scene's run as arrays, a part's shape, a study.

    PYTHONPATH=<prefix>/lib/python3/dist-packages python3 example.py SCENARIO OUT_DIR
"""
import sys

import fitfeel

scene, out = sys.argv[1], sys.argv[2]
print(fitfeel.validate(scene))
trace, summary = fitfeel.run(scene, seed=2)
print("peak axial resistance", abs(trace["fy_N"]).max(), "N over", len(trace["t_s"]), "ticks")
shaft = fitfeel.skin_model_shapes(scene, seed=2)["shaft"]["variation"]  # rows x columns, m
print("shaft V from", shaft.min(), "to", shaft.max(), "m")
rows, study = fitfeel.study_on_threads(scene, pairs=4, seed=1, threads=2, out=out)
print("P(interference)", study["probability_of_interference"])
try:
    fitfeel.validate("no-such-scene.yaml")
except fitfeel.UserError as error:
    print("refused:", error)
