#!/usr/bin/python3
"""scipy's differential evolution tunes R1's gait, a whole population per cic batch.

    /usr/bin/python3 examples/python/scipy_de.py [--generations 30] [--popsize 4] [--workers 2]

scipy's `vectorized=True` hands the objective every trial vector of a generation
at once: one call of cic.Evaluator.evaluate, spread over the worker processes.
"""
import argparse

import numpy as np
from scipy.optimize import differential_evolution

import cic

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--settings", default="r1_gait.xml")
ap.add_argument("--generations", type=int, default=30)
ap.add_argument("--popsize", type=int, default=4, help="scipy's multiplier: popsize x 37 trial vectors")
ap.add_argument("--workers", type=int, default=2)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--quick", action="store_true", help="3 s walks (tests)")
args = ap.parse_args()
quick = {"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5} if args.quick else None

with cic.Evaluator(args.settings, workers=args.workers, set=quick) as ev:
    calls = []

    def cost(xs):   # xs: (dimension, S), one column per trial vector; scipy minimises
        scores = ev.evaluate(np.ascontiguousarray(xs.T))
        calls.append(len(scores))
        return -scores.fitness

    result = differential_evolution(cost, [(0.0, 1.0)] * ev.dimension, maxiter=args.generations,
                                    popsize=args.popsize, seed=args.seed, vectorized=True, updating="deferred",
                                    polish=False, tol=0)
    print(f"{sum(calls)} evaluations in {len(calls)} batches")
    check = ev.evaluate([result.x]).fitness[0]
print(f"best fitness {-result.fun:.6f} (evaluated again: {check:.6f})")
