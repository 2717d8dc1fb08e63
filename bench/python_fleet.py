#!/usr/bin/env python3
"""fogdrift.train_fleet: six units' campaigns trained serially (one and two threads a unit) and
as Dask tasks on a LocalCluster of two single-threaded worker processes; the same models from
all three (checked).

    PYTHONPATH=build/python python3 bench/python_fleet.py [--units 6] [--repeats 3]

Each unit: a simulated calibration campaign (4 temperatures × 2 repetitions, its own seed),
SSA-SVR with 10 sparrows and 5 iterations. Prints the median seconds of the repeats.
"""
import argparse
import statistics
import tempfile
import time

from dask.distributed import Client, LocalCluster

import fogdrift


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--units", type=int, default=6)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        units = []
        for s in range(args.units):
            units.append(f"{tmp}/unit{s}")
            fogdrift.simulate("calibration", out=units[-1], seed=10 + s,
                              temps_degc=[-40, -10, 20, 50], repetitions=2)
        options = dict(method="ssa-svr", population=10, iterations=5, seed=1)
        times = {"serial, 1 thread a unit": [], "serial, 2 threads a unit": [],
                 "LocalCluster, 2 workers × 1 thread": []}
        models = []
        with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, \
                Client(cluster) as client:
            for _ in range(args.repeats):
                for (name, t), kwargs in zip(times.items(), [dict(threads=1), dict(threads=2),
                                                             dict(client=client)]):
                    start = time.perf_counter()
                    fleet = fogdrift.train_fleet(units, **kwargs, **options)
                    t.append(time.perf_counter() - start)
                    models.append([r["model"].to_json() for r in fleet])
        same = all(m == models[0] for m in models)
        print(f"| {args.units} units | median s (of {args.repeats}) | speed-up |")
        print("|---|---|---|")
        first = statistics.median(next(iter(times.values())))
        for name, t in times.items():
            m = statistics.median(t)
            print(f"| {name} | {m:.2f} | {first / m:.2f}× |")
        print(f"\nthe same model bytes from every run: {same}")


if __name__ == "__main__":
    main()
