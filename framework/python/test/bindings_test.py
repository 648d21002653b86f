#!/usr/bin/python3
"""The Python bindings against the CLI they wrap: the same runs, shapes and study rows; scenario
errors as fitfeel.ScenarioError with the CLI's located message.

    bindings_test.py FITFEEL_CLI   (PYTHONPATH=build/python, from the source folder)
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import fitfeel

CLI = sys.argv.pop(1) if len(sys.argv) > 1 else "build/bin/fitfeel"
SCENE = "scenarios/paper-case1-h7js6.yaml"


class Bindings(unittest.TestCase):
    def test_validate_prints_what_the_cli_prints(self):
        cli = subprocess.run([CLI, "validate", SCENE], capture_output=True, text=True, check=True)
        self.assertEqual(fitfeel.validate(SCENE) + "valid\n", cli.stdout)

    def test_scenario_errors_are_located_exceptions(self):
        with tempfile.TemporaryDirectory() as d:
            bad = os.path.join(d, "bad.yaml")
            with open(SCENE) as f:
                text = f.read().replace("friction: 0.15", "friction: lots")
            with open(bad, "w") as f:
                f.write(text)
            with self.assertRaises(fitfeel.ScenarioError) as e:
                fitfeel.validate(bad)
            cli = subprocess.run([CLI, "validate", bad], capture_output=True, text=True)
            self.assertEqual(cli.returncode, 2)
            self.assertIn(str(e.exception), cli.stderr)
            self.assertIn(bad + ":", str(e.exception))
            self.assertIn("model.friction", str(e.exception))
            self.assertIsInstance(e.exception, fitfeel.UserError)
            self.assertIsInstance(e.exception, ValueError)
        with self.assertRaises(fitfeel.UserError):
            fitfeel.run("no/such/scene.yaml")

    def test_run_gives_the_cli_run_as_arrays(self):
        trace, summary = fitfeel.run(SCENE, seed=4)
        with tempfile.TemporaryDirectory() as d:
            subprocess.run([CLI, "run", SCENE, "--seed", "4", "--out", d], check=True,
                           capture_output=True)
            with open(os.path.join(d, "summary.json")) as f:
                cli = json.load(f)
            with open(os.path.join(d, "trace.csv")) as f:
                rows = list(csv.DictReader(f))
        self.assertEqual(summary["axial_resistance_N"], cli["axial_resistance_N"])
        self.assertEqual(summary["constrained_ticks"], cli["constrained_ticks"])
        self.assertEqual(len(trace["t_s"]), len(rows))
        fy = np.array([float(r["fy_N"]) for r in rows])
        # trace.csv prints forces to 0.01 N (its contract); the arrays hold them exactly.
        self.assertLess(np.max(np.abs(trace["fy_N"] - fy)), 0.0051)
        self.assertEqual(int(np.sum(trace["stage"] == 1)), cli["constrained_ticks"])

    def test_skin_model_shapes_are_arrays_inside_their_drawing(self):
        shapes = fitfeel.skin_model_shapes(SCENE, seed=9)
        again = fitfeel.skin_model_shapes(SCENE, seed=9)
        shaft = shapes["shaft"]
        self.assertEqual(shaft["variation"].shape, (shaft["rows"], shaft["columns"]))
        self.assertTrue(np.array_equal(shaft["variation"], again["shaft"]["variation"]))
        self.assertFalse(np.array_equal(
            shaft["variation"], fitfeel.skin_model_shapes(SCENE, seed=10)["shaft"]["variation"]))
        # Radial V of a shaft -8/+8 um (diameter): every two-point size within 16 um of range.
        v = shaft["variation"]
        opposite = np.roll(v, shaft["columns"] // 2, axis=1)
        self.assertLessEqual(np.max(v + opposite), 8e-6 + 1e-12)
        self.assertGreaterEqual(np.min(v + opposite), -8e-6 - 1e-12)
        self.assertEqual(shapes["bushing"]["role"], "outer")

    def test_study_rows_are_the_cli_study_rows(self):
        rows, study = fitfeel.study_on_threads(SCENE, pairs=3, seed=5, threads=2)
        self.assertEqual(study["pairs"], 3)
        with tempfile.TemporaryDirectory() as d:
            subprocess.run([CLI, "study", SCENE, "--pairs", "3", "--seed", "5", "--out", d],
                           check=True, capture_output=True)
            with open(os.path.join(d, "pairs.csv")) as f:
                cli = list(csv.DictReader(f))
            fitfeel.write_study(os.path.join(d, "py"), SCENE, 5, 3,
                                [fitfeel.study_pair(SCENE, 5, i) for i in range(3)], 1, 0.0)
            with open(os.path.join(d, "pairs.csv")) as a, open(os.path.join(d, "py/pairs.csv")) as b:
                self.assertEqual(a.read(), b.read())
        for row, c in zip(rows, cli):
            self.assertEqual(row["seed"], int(c["seed"]))
            self.assertEqual(repr(row["axial_max_N"]), c["axial_max_N"])


if __name__ == "__main__":
    unittest.main()
