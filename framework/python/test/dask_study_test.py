#!/usr/bin/python3
"""A study on a local Dask cluster (two worker processes on 127.0.0.1) gives the same pairs.csv as
`fitfeel study`, also when one worker is killed while it holds pairs.

    dask_study_test.py FITFEEL_CLI   (PYTHONPATH=build/python, from the source folder)
"""
import os
import signal
import subprocess
import sys
import tempfile
import unittest

from dask.distributed import Client, LocalCluster, as_completed

import fitfeel
import fitfeel.study as dask_study

CLI = sys.argv.pop(1) if len(sys.argv) > 1 else "build/bin/fitfeel"
SCENE = os.path.abspath("scenarios/paper-case1-h7js6.yaml")
PAIRS, SEED = 10, 7


def read(path):
    with open(path) as f:
        return f.read()


class DaskStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="fitfeel-dask-")
        subprocess.run([CLI, "study", SCENE, "--pairs", str(PAIRS), "--seed", str(SEED), "--out",
                        os.path.join(cls.dir, "cli")], check=True, capture_output=True)
        cls.expected = read(os.path.join(cls.dir, "cli", "pairs.csv"))

    def test_same_pairs_as_the_cli(self):
        out = os.path.join(self.dir, "dask")
        rows = dask_study.run_on_dask(SCENE, PAIRS, SEED, workers=2, out=out)
        self.assertEqual([r["pair"] for r in rows], list(range(PAIRS)))
        self.assertEqual(read(os.path.join(out, "pairs.csv")), self.expected)

    def test_a_worker_killed_mid_study_costs_only_its_pairs(self):
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        client = Client(cluster)
        try:
            pids = client.run(os.getpid)
            self.assertEqual(len(pids), 2)
            futures = [client.submit(dask_study._pair, SCENE, SEED, i, pure=True,
                                     key=f"kill-test-{i}") for i in range(PAIRS)]
            killed = None
            done = 0
            for _ in as_completed(futures):
                done += 1
                if killed is None:
                    # The other pairs are queued on both workers: kill the one that did not just
                    # finish a pair, while it works.
                    killed = list(pids.values())[-1]
                    os.kill(killed, signal.SIGKILL)
            self.assertEqual(done, PAIRS)
            rows = sorted(client.gather(futures), key=lambda r: r["pair"])
            self.assertNotIn(killed, client.run(os.getpid).values())  # the nanny started anew
        finally:
            client.close()
            cluster.close()
        out = os.path.join(self.dir, "killed")
        fitfeel.write_study(out, SCENE, SEED, PAIRS, rows, 2, 0.0)
        self.assertEqual(read(os.path.join(out, "pairs.csv")), self.expected)


if __name__ == "__main__":
    unittest.main()
