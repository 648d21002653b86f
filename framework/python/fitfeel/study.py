"""A fit study spread over a Dask cluster.

    /usr/bin/python3 -m fitfeel.study FILE --pairs N [--seed S] [--scheduler tcp://HOST:PORT]
                                      [--workers K] [--out DIR]

Pair i is computed by fitfeel.study_pair(FILE, S, i) on whichever worker Dask gives it: the same
seed and the same row as `fitfeel study FILE --pairs N --seed S` computes, whatever the number of
workers, so pairs.csv is byte-identical to the CLI's; study.json and study.png follow as the CLI
writes them. A worker lost mid-study loses only the pairs it held; Dask runs them again elsewhere
(each task is a pure function of FILE, S and i). Without --scheduler, a local cluster of K worker
processes (default: the machine's cores) is started on 127.0.0.1. With --scheduler, the scheduler
must answer within a few seconds and its workers must import fitfeel and read FILE at the same
path (start them with `fitfeel-worker ADDRESS`), else the study stops before submitting anything,
with exit status 2 and what to do. Progress and an estimate of the time left go to stderr.
"""
import argparse
import os
import sys
import time

import fitfeel

# How long the scheduler and its first worker are waited for: enough for a loaded machine to
# answer, short enough that a wrong address is reported before a user gives up.
CONNECT_TIMEOUT_S = 5


class SetupError(Exception):
    """The cluster cannot run the study; the message says what to do."""


def _pair(file, seed, index):
    # Runs on a worker: imports fitfeel there, loads the plugins once per worker process.
    import fitfeel as worker_fitfeel
    return worker_fitfeel.study_pair(file, seed, index)


# Sent to the workers by value: a function of this module would be pickled by reference and
# fail to load exactly where fitfeel is missing, which is what it must report.
_PROBE_SOURCE = '''
def probe(file):
    import os, sys
    try:
        import fitfeel
    except Exception as e:
        return {"python": sys.executable, "error": f"{type(e).__name__}: {e}"}
    return {"python": sys.executable, "error": None, "module": fitfeel.__file__,
            "readable": os.access(file, os.R_OK)}
'''


def _probe_function():
    namespace = {"__name__": "fitfeel_worker_probe"}
    exec(compile(_PROBE_SOURCE, "fitfeel_worker_probe", "exec"), namespace)
    return namespace["probe"]


def _dask():
    try:
        from dask import distributed
    except ImportError as e:
        raise SetupError(
            f"{sys.executable} cannot import Dask ({e}): run the study with Debian's "
            "/usr/bin/python3 (apt-get install python3-distributed), whose modules fitfeel is "
            "built for") from None
    return distributed


def connect(address, timeout=CONNECT_TIMEOUT_S):
    """A Client of the scheduler at `address`, or SetupError when none answers within
    `timeout` seconds."""
    distributed = _dask()
    try:
        return distributed.Client(address, timeout=timeout)
    except Exception as e:  # refused, unreachable, malformed: the same advice
        raise SetupError(
            f"--scheduler {address}: no Dask scheduler answered within {timeout} s ({e}); start "
            "one with `dask-scheduler` (Debian's python3-distributed) and pass the address it "
            "prints, tcp://HOST:PORT") from None


def check_workers(client, file, timeout=CONNECT_TIMEOUT_S):
    """Raises SetupError unless the cluster has a worker and every worker imports fitfeel and
    reads `file`."""
    address = client.scheduler.address
    try:
        client.wait_for_workers(1, timeout=timeout)
    except Exception:
        raise SetupError(
            f"the scheduler {address} has no worker (none joined within {timeout} s); start "
            f"workers with `fitfeel-worker {address}`") from None
    answers = client.run(_probe_function(), file)
    missing = {w: a for w, a in answers.items() if a["error"]}
    if missing:
        worker, answer = sorted(missing.items())[0]
        raise SetupError(
            f"{len(missing)} of {len(answers)} workers of {address} cannot import fitfeel "
            f"(worker {worker}, {answer['python']}: {answer['error']}); start workers with "
            f"`fitfeel-worker {address}`, which puts the module on their path, or set "
            "PYTHONPATH=<prefix>/lib/python3/dist-packages for dask-worker")
    unreadable = sorted(w for w, a in answers.items() if not a["readable"])
    if unreadable:
        raise SetupError(
            f"{len(unreadable)} of {len(answers)} workers of {address} cannot read {file} "
            f"(worker {unreadable[0]}); the scenario must be readable at the same path on every "
            "worker")


class Progress:
    """A line on `stream` every `step` percent or `every_s` seconds, with the time left
    estimated from the pace so far."""

    def __init__(self, total, stream=sys.stderr, step=5, every_s=5.0):
        self.total, self.stream, self.every_s = total, stream, every_s
        self.step = max(1, total * step // 100)
        self.start = time.monotonic()
        self.last_done, self.last_time = 0, self.start

    def update(self, done):
        now = time.monotonic()
        if done == 0:  # submitted: the pace counts from here, not from a cluster's start
            self.start = self.last_time = now
            return
        if done < self.total and done - self.last_done < self.step and \
                now - self.last_time < self.every_s:
            return
        self.last_done, self.last_time = done, now
        elapsed = now - self.start
        left = elapsed / done * (self.total - done) if done else float("nan")
        print(f"fitfeel.study: {done}/{self.total} pairs ({100 * done // self.total}%), "
              f"{elapsed:.1f} s, about {left:.0f} s left", file=self.stream, flush=True)


def run_on_dask(file, pairs, seed=1, client=None, workers=None, out=None, progress=None):
    """Computes pairs 0 .. pairs-1 on a Dask client (a new local cluster if none) and returns
    them in order; with `out`, writes pairs.csv, study.json and study.png there as
    `fitfeel study` does. `progress`, if given, is called with 0 once the pairs are submitted, then with the count
    of pairs done after each."""
    distributed = _dask()
    file = os.path.abspath(file)
    fitfeel.validate(file)  # every refusal of the scene before any worker starts
    own = None
    if client is None:
        n = workers or os.cpu_count() or 1
        # Several workers keep the cores busy with pairs: each pair prepares on its worker's own
        # thread (a prepare's result does not depend on its thread count).
        env = {"FITFEEL_PREPARE_THREADS": "1"} if n > 1 else {}
        cluster = distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                           host="127.0.0.1", dashboard_address=None, env=env)
        own = (cluster, distributed.Client(cluster))
        client = own[1]
    try:
        start = time.monotonic()
        # Pure tasks keyed by their arguments: a lost worker's pairs are recomputed, not lost.
        futures = [client.submit(_pair, file, seed, i, pure=True, retries=2,
                                 key=f"fitfeel-pair-{seed}-{i}-{file}")
                   for i in range(pairs)]
        if progress is not None:
            progress(0)
        rows = []
        for future in distributed.as_completed(futures):
            rows.append(future.result())
            if progress is not None:
                progress(len(rows))
        wall = time.monotonic() - start
        n_workers = len(client.scheduler_info().get("workers", {}))
    finally:
        if own is not None:
            own[1].close()
            own[0].close()
    rows.sort(key=lambda r: r["pair"])
    if out is not None:
        fitfeel.write_study(out, file, seed, pairs, rows, max(n_workers, 1), wall)
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m fitfeel.study", description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("--pairs", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (tcp://HOST:PORT)")
    ap.add_argument("--workers", type=int, help="local cluster's worker processes (default: cores)")
    ap.add_argument("--out", help="output folder (default: out/<file name>-study)")
    args = ap.parse_args(argv)
    if args.pairs < 1 or args.seed < 0 or (args.workers is not None and args.workers < 1):
        ap.error("--pairs must be >= 1, --seed >= 0, --workers >= 1")
    out = args.out or os.path.join(
        "out", os.path.splitext(os.path.basename(args.file))[0] + "-study")
    client = None
    try:
        fitfeel.validate(args.file)
        if args.scheduler:
            client = connect(args.scheduler)
            check_workers(client, os.path.abspath(args.file))
        rows = run_on_dask(args.file, args.pairs, args.seed, client, args.workers, out,
                           Progress(args.pairs).update)
    except (fitfeel.UserError, SetupError) as e:
        print(f"fitfeel.study: {e}", file=sys.stderr)
        return 2
    finally:
        if client is not None:
            client.close()
    print(f"fitfeel.study: {len(rows)} pairs -> {out}/pairs.csv, {out}/study.json, "
          f"{out}/study.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
