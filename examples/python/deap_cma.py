#!/usr/bin/python3
"""DEAP's CMA-ES (deap.cma) tunes R1's open-loop gait through cic.Evaluator.

    /usr/bin/python3 examples/python/deap_cma.py [--evaluations 2500] [--workers 2] [--seed 1]

Each generation is one batch for cic's worker processes. CMA-ES samples the whole
space; cic's gait lives in the unit box, so samples are clipped into it (cic's own
CMA-ES reflects them instead: Gait.bounds).
"""
import argparse

import numpy as np
from deap import base, cma, creator

import cic

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--settings", default="r1_gait.xml")
ap.add_argument("--evaluations", type=int, default=2500)
ap.add_argument("--workers", type=int, default=2)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--quick", action="store_true", help="3 s walks (tests)")
args = ap.parse_args()
quick = {"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5} if args.quick else None

np.random.seed(args.seed)   # deap.cma draws from numpy's global generator
creator.create("FitnessMax", base.Fitness, weights=(1.0,))
creator.create("Individual", list, fitness=creator.FitnessMax)

with cic.Evaluator(args.settings, workers=args.workers, set=quick) as ev:
    strategy = cma.Strategy(centroid=[0.5] * ev.dimension, sigma=0.15)
    best, used = -np.inf, 0
    while used + strategy.lambda_ <= args.evaluations:
        population = strategy.generate(creator.Individual)
        scores = ev.evaluate(np.clip(np.array(population), 0.0, 1.0))
        for ind, f in zip(population, scores.fitness):
            ind.fitness.values = (f,)
        strategy.update(population)
        used += len(population)
        best = max(best, scores.fitness.max())
        print(f"{used:5d} evaluations  best {best:.4f}  generation best {scores.fitness.max():.4f}")
print(f"best fitness {best:.6f} after {used} evaluations")
