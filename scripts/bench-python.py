#!/usr/bin/python3
"""scripts/bench-python.py BUILD [--evaluations N] [--batch B] [--workers W]

Evaluations per second from Python (cic.Evaluator) against cic's own run on the
same settings (R1's gait, CMA-ES: settings/r1_gait.xml), with the same batch size
(the run's population) and the same workers, measured in one run of this script;
and the per-call overhead of a batch of one (a short walk): the call's wall time
less the simulation's own, measured in process with cic.simulate. Issue 37's
target: Python at >= 95 % of cic's throughput.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

ap = argparse.ArgumentParser()
ap.add_argument("build")
ap.add_argument("--evaluations", type=int, default=480)
ap.add_argument("--batch", type=int, default=16)
ap.add_argument("--workers", type=int, default=2)
ap.add_argument("--repeats", type=int, default=3)
args = ap.parse_args()
sys.path.insert(0, os.path.join(args.build, "python"))
import numpy as np  # noqa: E402

import cic  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
settings = os.path.join(root, "settings", "r1_gait.xml")
cic_bin = os.path.join(args.build, "cic")
sets = {"Gait.evaluations": args.evaluations, "Gait.populationSize": args.batch, "Experiment.workers": args.workers}


def cic_run():
    out = tempfile.mkdtemp(prefix="cic-bench-")
    try:
        cmd = [cic_bin, "--settings", settings, "--output", out, "--quiet"]
        for k, v in sets.items():
            cmd += ["--set", f"{k}={v}"]
        t = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        return time.perf_counter() - t
    finally:
        shutil.rmtree(out)


def python_run():
    rng = np.random.default_rng(1)
    t = time.perf_counter()
    with cic.Evaluator(settings, workers=args.workers) as ev:   # worker start-up counted, as in a run
        for _ in range(args.evaluations // args.batch):
            ev.evaluate(rng.random((args.batch, ev.dimension)))
    return time.perf_counter() - t


print(f"== Python vs cic: R1 gait, {args.evaluations} evaluations in batches of {args.batch}, {args.workers} workers "
      f"(best of {args.repeats}, interleaved)")
c, p = [], []
for _ in range(args.repeats):
    c.append(cic_run())
    p.append(python_run())
ce, pe = args.evaluations / min(c), args.evaluations / min(p)
print(f"  cic's own run:   {ce:7.2f} evaluations/s  ({min(c):.2f} s)")
print(f"  cic.Evaluator:   {pe:7.2f} evaluations/s  ({min(p):.2f} s)")
print(f"  Python / cic:    {pe / ce * 100:6.1f} %")

quick = {"Simulator.sample_to": 0.5, "Simulator.delayed_start": 0.0}
x = np.full((1, 37), 0.5)
with cic.Evaluator(settings, workers=1, set=quick) as ev:
    ev.evaluate(x)   # workers up
    calls = []
    for _ in range(50):
        t = time.perf_counter()
        ev.evaluate(x)
        calls.append(time.perf_counter() - t)
    sims = []
    for _ in range(50):
        t = time.perf_counter()
        ev.simulate(x[0], trace=False)
        sims.append(time.perf_counter() - t)
call, sim = float(np.median(calls)), float(np.median(sims))
print(f"== A batch of one (0.5 s walk, median of 50): call {call * 1e3:.3f} ms, simulation in process "
      f"{sim * 1e3:.3f} ms, overhead {(call - sim) * 1e3:.3f} ms per call")
