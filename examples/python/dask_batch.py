#!/usr/bin/env python3
"""A batch of episodes on a Dask cluster: the trial grid of `rtamp batch` (here 2 algorithms x
2 changes x 4 trials of 3-block-tray in the symbolic world), one Dask task per 2 trials, merged
into the CSV `rtamp batch --output` writes.

By default it starts a local cluster (a scheduler and two worker processes on 127.0.0.1); give
--scheduler tcp://HOST:PORT to use a running one (every worker needs rtamp on its PYTHONPATH).

Run: PYTHONPATH=<build>/python /usr/bin/python3 examples/python/dask_batch.py --out DIR
"""
import argparse
import csv
import os

from dask.distributed import Client, LocalCluster

import rtamp.batch

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--out", default=".", help="directory for batch.csv")
parser.add_argument("--scheduler", help="address of a running Dask scheduler")
args = parser.parse_args()
os.makedirs(args.out, exist_ok=True)
output = os.path.join(args.out, "batch.csv")

if __name__ == "__main__":
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None)
        client = Client(cluster)
    print(f"cluster: {len(client.scheduler_info()['workers'])} workers")
    text = rtamp.batch.run("3-block-tray", algorithms=["astar-exp", "dijkstra"], changes=["relocate", "add"],
                           trials=4, seed=1, world="symbolic", client=client, chunk=2, output=output)
    rows = list(csv.DictReader(text.splitlines()))
    ok = sum(r["success"] == "1" for r in rows)
    print(f"{len(rows)} episodes, {ok} succeeded: {output}")
    client.close()
    assert len(rows) == 16
