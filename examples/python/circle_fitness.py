#!/usr/bin/python3
"""A fitness of your own from the whole walk: R1 walking in a circle.

    /usr/bin/python3 examples/python/circle_fitness.py [--evaluations 200]

cic.simulate gives the centre's path; the score is how far the robot turns around
the middle of its own path (radians swept), times how round the path is, so a
robot that walks a circle scores high, one that walks straight or stands scores low.
A (1+4)-ES searches the gait vector with it.
"""
import argparse

import numpy as np

import cic

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--settings", default="r1_gait.xml")
ap.add_argument("--evaluations", type=int, default=200)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--quick", action="store_true", help="3 s walks (tests)")
args = ap.parse_args()
quick = {"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5} if args.quick else None


def circling(walk):
    """Radians the centre sweeps around the middle of its path, times the path's roundness."""
    if walk.failed:
        return 0.0
    xy = walk.centre[:, :2]
    rel = xy - xy.mean(axis=0)
    radius = np.hypot(rel[:, 0], rel[:, 1])
    if radius.mean() < 0.02:   # standing still: nothing to circle
        return 0.0
    swept = np.abs(np.unwrap(np.arctan2(rel[:, 1], rel[:, 0]))[-1] - np.arctan2(rel[0, 1], rel[0, 0]))
    roundness = 1.0 / (1.0 + radius.std() / radius.mean())
    return swept * roundness


rng = np.random.default_rng(args.seed)
with cic.Evaluator(args.settings, set=quick) as ev:
    parent = rng.random(ev.dimension)
    best = circling(ev.simulate(parent))
    for used in range(1, args.evaluations, 4):
        for child in np.clip(parent + rng.normal(0, 0.1, (4, ev.dimension)), 0, 1):
            score = circling(ev.simulate(child))
            if score > best:
                parent, best = child, score
        print(f"{used + 3:4d} walks  circling {best:.3f} rad")
    walk = ev.simulate(parent)
print(f"best circling {best:.4f} rad; eq. 7.1 fitness of that gait {walk.fitness:.4f}")
