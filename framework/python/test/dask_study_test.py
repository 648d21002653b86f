#!/usr/bin/python3
"""`python3 -m fitfeel.study` on Dask as a user runs it: against a loopback `dask-scheduler` with
two `fitfeel-worker` processes, one killed while the study runs, it writes the pairs.csv
`fitfeel study` writes, byte for byte, with study.json, study.png and progress on stderr; on a
local cluster (no --scheduler) the same. A scheduler that does not answer, a scheduler without
workers and workers that cannot import fitfeel stop it before anything is submitted: exit status 2,
a message saying what to do, no traceback.

    dask_study_test.py FITFEEL_CLI FITFEEL_WORKER   (PYTHONPATH=build/python, from the source folder)
"""
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

from dask.distributed import Client

CLI = sys.argv.pop(1) if len(sys.argv) > 1 else "build/bin/fitfeel"
WORKER = sys.argv.pop(1) if len(sys.argv) > 1 else "build/bin/fitfeel-worker"
PYTHON = "/usr/bin/python3"
# The fastest shipped scene; enough pairs that a worker dies holding some.
SCENE = os.path.abspath("scenarios/paper-case1-h7js6.yaml")
PAIRS, SEED = 60, 7


def read(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def without_fitfeel():
    """The environment less the module's path: a worker started in it cannot import fitfeel."""
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)
    return env


class Scheduler:
    """A dask-scheduler on 127.0.0.1 at a free port, its address read from its scheduler file."""

    def __init__(self, folder):
        self.file = os.path.join(folder, "scheduler.json")
        self.process = subprocess.Popen(
            [PYTHON, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0",
             "--no-dashboard", "--scheduler-file", self.file],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.workers = []
        client = None
        for _ in range(600):  # the file appears once the scheduler listens
            if os.path.exists(self.file):
                try:
                    client = Client(scheduler_file=self.file, timeout=10)
                    break
                except (OSError, ValueError):
                    pass
            time.sleep(0.05)
        if client is None:
            self.close()
            raise RuntimeError("dask-scheduler did not start")
        self.client = client
        self.address = client.scheduler.address

    def add_worker(self, command, env=None):
        self.workers.append(subprocess.Popen(
            command + [self.address, "--nthreads", "1", "--no-nanny", "--no-dashboard"],
            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        self.client.wait_for_workers(len(self.workers), timeout=60)

    def close(self):
        if getattr(self, "client", None) is not None:
            self.client.close()
        for p in self.workers + [self.process]:
            if p.poll() is None:
                p.terminate()
        for p in self.workers + [self.process]:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()


def study(args):
    return subprocess.run([PYTHON, "-m", "fitfeel.study", SCENE, *args], capture_output=True,
                          text=True)


class DaskStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="fitfeel-dask-")
        subprocess.run([CLI, "study", SCENE, "--pairs", str(PAIRS), "--seed", str(SEED), "--out",
                        os.path.join(cls.dir, "cli")], check=True, capture_output=True)
        cls.expected = read(os.path.join(cls.dir, "cli", "pairs.csv"))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def assertRefused(self, result, *words):
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        self.assertTrue(result.stderr.startswith("fitfeel.study: "), result.stderr)
        for word in words:
            self.assertIn(word, result.stderr)

    def test_a_worker_killed_mid_study_costs_only_its_pairs(self):
        folder = tempfile.mkdtemp(dir=self.dir)
        scheduler = Scheduler(folder)
        try:
            scheduler.add_worker([WORKER])
            scheduler.add_worker([WORKER])
            out = os.path.join(folder, "study")
            run = subprocess.Popen(
                [PYTHON, "-m", "fitfeel.study", SCENE, "--pairs", str(PAIRS), "--seed", str(SEED),
                 "--scheduler", scheduler.address, "--out", out],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            progress = []
            victim = scheduler.workers[1]
            for line in run.stderr:
                if "pairs (" in line:
                    progress.append(line)
                    # The first progress line: pairs are done, the rest queued on both workers.
                    if victim.poll() is None:
                        victim.send_signal(signal.SIGKILL)
            stdout = run.stdout.read()
            self.assertEqual(run.wait(), 0, "".join(progress))
            self.assertIsNotNone(victim.poll())  # it died while the study ran
        finally:
            scheduler.close()
        self.assertEqual(read(os.path.join(out, "pairs.csv")), self.expected)
        self.assertEqual(read(os.path.join(out, "study.png"), "rb")[:8], b"\x89PNG\r\n\x1a\n")
        self.assertIn('"pairs": 60', read(os.path.join(out, "study.json")))
        self.assertIn("study.png", stdout)
        # Progress with the time left, and a last line at the end.
        self.assertGreaterEqual(len(progress), 2)
        self.assertIn("s left", progress[0])
        self.assertIn(f"{PAIRS}/{PAIRS} pairs (100%)", progress[-1])

    def test_a_local_cluster_gives_the_cli_pairs(self):
        out = os.path.join(self.dir, "local")
        result = study(["--pairs", str(PAIRS), "--seed", str(SEED), "--workers", "2",
                        "--out", out])
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(read(os.path.join(out, "pairs.csv")), self.expected)

    def test_a_scheduler_that_does_not_answer_is_refused(self):
        with socket.socket() as s:  # a port nothing listens on
            s.bind(("127.0.0.1", 0))
            address = f"tcp://127.0.0.1:{s.getsockname()[1]}"
        result = study(["--pairs", "2", "--scheduler", address])
        self.assertRefused(result, f"--scheduler {address}: no Dask scheduler answered",
                           "dask-scheduler")

    def test_workers_without_fitfeel_are_refused_before_any_pair(self):
        folder = tempfile.mkdtemp(dir=self.dir)
        scheduler = Scheduler(folder)
        try:
            out = os.path.join(folder, "study")
            result = study(["--pairs", "2", "--scheduler", scheduler.address, "--out", out])
            self.assertRefused(result, "has no worker", f"fitfeel-worker {scheduler.address}")
            scheduler.add_worker([PYTHON, "-m", "distributed.cli.dask_worker"],
                                 env=without_fitfeel())
            result = study(["--pairs", "2", "--scheduler", scheduler.address, "--out", out])
        finally:
            scheduler.close()
        self.assertRefused(result, "cannot import fitfeel", "No module named 'fitfeel'",
                           f"fitfeel-worker {scheduler.address}")
        self.assertFalse(os.path.exists(out))

    def test_the_worker_script_finds_the_package(self):
        path = subprocess.run([WORKER, "--fitfeel-path"], capture_output=True, text=True,
                              check=True, env=without_fitfeel()).stdout.strip()
        self.assertTrue(os.path.isfile(os.path.join(path, "fitfeel", "__init__.py")), path)


if __name__ == "__main__":
    unittest.main()
