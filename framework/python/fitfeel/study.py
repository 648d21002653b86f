"""A fit study spread over a Dask cluster.

    python3 -m fitfeel.study FILE --pairs N [--seed S] [--scheduler tcp://HOST:PORT]
                             [--workers K] [--out DIR]

Pair i is computed by fitfeel.study_pair(FILE, S, i) on whichever worker Dask gives it: the same
seed and the same row as `fitfeel study FILE --pairs N --seed S` computes, whatever the number of
workers, so pairs.csv is byte-identical to the CLI's. A worker lost mid-study loses only the pairs
it held; Dask runs them again elsewhere (each task is a pure function of FILE, S and i). Without
--scheduler, a local cluster of K worker processes (default: the machine's cores) is started on
127.0.0.1. The scenario must be readable at the same path on every worker.
"""
import argparse
import os
import sys
import time

import fitfeel


def _pair(file, seed, index):
    # Runs on a worker: imports fitfeel there, loads the plugins once per worker process.
    import fitfeel as worker_fitfeel
    return worker_fitfeel.study_pair(file, seed, index)


def run_on_dask(file, pairs, seed=1, client=None, workers=None, out=None):
    """Computes pairs 0 .. pairs-1 on a Dask client (a new local cluster if none) and returns
    them in order; with `out`, writes pairs.csv and study.json there as `fitfeel study` does."""
    from dask.distributed import Client, LocalCluster

    file = os.path.abspath(file)
    fitfeel.validate(file)  # every refusal of the scene now, before any worker starts
    own = None
    if client is None:
        n = workers or os.cpu_count() or 1
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        own = (cluster, Client(cluster))
        client = own[1]
    try:
        start = time.monotonic()
        # Pure tasks keyed by their arguments: a lost worker's pairs are recomputed, not lost.
        futures = [client.submit(_pair, file, seed, i, pure=True, retries=2,
                                 key=f"fitfeel-pair-{seed}-{i}-{file}")
                   for i in range(pairs)]
        rows = client.gather(futures)
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
    if args.scheduler:
        from dask.distributed import Client
        client = Client(args.scheduler)
    try:
        rows = run_on_dask(args.file, args.pairs, args.seed, client, args.workers, out)
    except fitfeel.UserError as e:
        print(f"fitfeel.study: {e}", file=sys.stderr)
        return 2
    finally:
        if client is not None:
            client.close()
    print(f"fitfeel.study: {len(rows)} pairs -> {out}/pairs.csv, {out}/study.json")
    return 0


if __name__ == "__main__":
    sys.exit(main())
