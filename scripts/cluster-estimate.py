#!/usr/bin/env python3
"""Wall time of a set of studies on a cluster, from the run times they took.

usage: scripts/cluster-estimate.py [--slots S] [--overhead SEC] [--nodes 1,2,4,8,16] FILE...

FILE is a study's index.csv (one row per run, wall_seconds of each done run) or
a `cic compare` configurations table (*-configs.csv: runs and wall_seconds_mean
per configuration). The estimate for N nodes of S run slots each (a slot = one
run with its workers) is the greater of the longest run and the total run time,
plus OVERHEAD seconds per run (Slurm's per-task cost, docs/cluster.md), spread
over N x S slots. It assumes runs of the same length on every node (the
machine that measured them): scale the figures by the ratio of the nodes'
speed. Plain python3, no third-party module.
"""
import argparse
import csv
import sys


def runs_of(path):
    """Run times in seconds, one per run, from an index.csv or a configs table."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return []
    if "wall_seconds_mean" in rows[0] and "runs" in rows[0]:
        out = []
        for r in rows:
            if r["wall_seconds_mean"]:
                out += [float(r["wall_seconds_mean"])] * int(r["n"] or r["runs"])
        return out
    if "wall_seconds" in rows[0] and "status" in rows[0]:
        return [float(r["wall_seconds"]) for r in rows if r["status"] == "done" and r["wall_seconds"]]
    sys.exit(f"{path}: neither a study index (wall_seconds, status) nor a configs table (runs, wall_seconds_mean)")


def hours(seconds):
    return f"{seconds / 3600:.2f} h" if seconds >= 3600 else f"{seconds / 60:.0f} min"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+")
    ap.add_argument("--slots", type=int, default=2, help="runs at once per node (default 2)")
    ap.add_argument("--overhead", type=float, default=0.0, help="seconds each run costs the scheduler")
    ap.add_argument("--nodes", default="1,2,4,8,16")
    a = ap.parse_args()
    runs = [t for f in a.files for t in runs_of(f)]
    if not runs:
        sys.exit("no finished run in the files given")
    total = sum(runs) + a.overhead * len(runs)
    print(f"{len(runs)} runs, {hours(sum(runs))} of run time (mean {sum(runs) / len(runs):.0f} s, "
          f"longest {max(runs):.0f} s), {a.overhead:g} s overhead per run, {a.slots} slots per node")
    print()
    print("| nodes | slots | wall time |")
    print("|---|---|---|")
    for n in (int(x) for x in a.nodes.split(",")):
        slots = n * a.slots
        print(f"| {n} | {slots} | {hours(max(max(runs), total / slots))} |")


if __name__ == "__main__":
    main()
