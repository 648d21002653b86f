#!/usr/bin/python3
"""The Python bindings against the CLI they wrap: the same runs (every trace column), shapes,
study rows and study files; scenario errors as fitfeel.ScenarioError with the CLI's located message.

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

    def test_run_gives_every_trace_column_the_cli_writes(self):
        # The default scene, a joint of two features (a column per feature) and a screw (the
        # joint's columns): the same names in the same order, and every value the one trace.csv
        # prints (its shortest decimals read back exactly), the stage by name.
        for scene in (SCENE, "scenarios/keyed-hub.yaml", "scenarios/bolt-m10.yaml"):
            with self.subTest(scene=scene):
                self.check_run_against_the_cli(scene)

    def check_run_against_the_cli(self, scene):
        trace, summary = fitfeel.run(scene, seed=4)
        with tempfile.TemporaryDirectory() as d:
            subprocess.run([CLI, "run", scene, "--seed", "4", "--out", d], check=True,
                           capture_output=True)
            with open(os.path.join(d, "summary.json")) as f:
                cli = json.load(f)
            with open(os.path.join(d, "trace.csv")) as f:
                header = f.readline().strip().split(",")
                rows = [line.strip().split(",") for line in f]
        self.assertEqual(list(trace), header)
        self.assertEqual(summary["axial_resistance_N"], cli["axial_resistance_N"])
        self.assertEqual(summary["constrained_ticks"], cli["constrained_ticks"])
        for k, name in enumerate(header):
            column = trace[name]
            self.assertEqual(len(column), len(rows), name)
            if name == "tick_us":
                continue  # a measurement of this process's clock, not the model
            if name == "stage":
                self.assertEqual([fitfeel.STAGES[s] for s in column], [r[k] for r in rows])
            else:
                self.assertTrue(np.array_equal(column, np.array([float(r[k]) for r in rows])),
                                name)
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
            # The CLI's three files, the chart drawn by the same C++ code.
            for name in ("pairs.csv", "study.json", "study.png"):
                with open(os.path.join(d, "py", name), "rb") as f:
                    self.assertGreater(len(f.read()), 0, name)
            with open(os.path.join(d, "py/study.png"), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
            fitfeel.study_on_threads(SCENE, pairs=3, seed=5, threads=2,
                                     out=os.path.join(d, "threads"))
            self.assertEqual(sorted(os.listdir(os.path.join(d, "threads"))),
                             ["pairs.csv", "study.json", "study.png"])
        for row, c in zip(rows, cli):
            self.assertEqual(row["seed"], int(c["seed"]))
            self.assertEqual(repr(row["axial_max_N"]), c["axial_max_N"])


if __name__ == "__main__":
    unittest.main()
