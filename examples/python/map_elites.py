#!/usr/bin/python3
"""MAP-Elites in numpy over R1's gait, binned by each foot's duty factor (cic's descriptor).

    /usr/bin/python3 examples/python/map_elites.py [--evaluations 2000] [--bins 5] [--workers 2]
"""
import argparse

import numpy as np

import cic

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--settings", default="r1_gait_map_elites.xml", help="settings whose MapElites.descriptor cic measures")
ap.add_argument("--evaluations", type=int, default=2000)
ap.add_argument("--batch", type=int, default=50)
ap.add_argument("--bins", type=int, default=5)
ap.add_argument("--sigma", type=float, default=0.1)
ap.add_argument("--workers", type=int, default=2)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--quick", action="store_true", help="3 s walks (tests)")
args = ap.parse_args()
quick = {"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5} if args.quick else None
rng = np.random.default_rng(args.seed)
archive = {}   # cell (tuple of bins) -> (fitness, genotype)

with cic.Evaluator(args.settings, workers=args.workers, set=quick) as ev:
    for used in range(0, args.evaluations, args.batch):
        if len(archive) < 2:   # random genotypes until there is something to vary
            xs = rng.random((args.batch, ev.dimension))
        else:
            elites = list(archive.values())
            parents = np.array([elites[i][1] for i in rng.integers(len(elites), size=args.batch)])
            xs = np.clip(parents + rng.normal(0.0, args.sigma, parents.shape), 0.0, 1.0)
        s = ev.evaluate(xs)
        for x, f, d, failed in zip(xs, s.fitness, s.descriptor, s.failed):
            if failed:
                continue
            cell = tuple(np.minimum((d * args.bins).astype(int), args.bins - 1))
            if cell not in archive or f > archive[cell][0]:
                archive[cell] = (f, x)
        best = max(f for f, _ in archive.values())
        print(f"{used + args.batch:5d} evaluations  {len(archive)} cells  best {best:.4f}")
print(f"coverage {len(archive) / args.bins ** s.descriptor.shape[1]:.3f}, best fitness {best:.6f}")
