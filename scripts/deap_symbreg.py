#!/usr/bin/python3
"""DEAP's symbolic-regression example (examples/gp/symbreg.py of DEAP 1.3),
run over many seeds, for the side-by-side with cic (scripts/compare-deap.sh).

Settings exactly as DEAP's example:
  target   x^4 + x^3 + x^2 + x on the 20 points x/10 for x in -10..9, i.e. [-1, 0.9]
  set      add sub mul protectedDiv neg cos sin, x, ephemeral randint(-1, 1)
  init     genHalfAndHalf depth 1..2, population 300
  loop     eaSimple, 40 generations, crossover 0.5 (cxOnePoint), mutation 0.1
           (mutUniform with genFull depth 0..2), tournament 3, static height limit 17
  fitness  mean squared error (DEAP's example), or --fitness sae for cic's
           sum of absolute errors; selection is the only thing that changes
Changes, none of which alter the search:
  * each run is seeded with random.seed(seed) (the example always uses 318);
  * no per-generation statistics (the example's numpy MultiStatistics only
    prints); a HallOfFame(1) keeps the best ever individual, as in the example;
  * a tree whose evaluation raises (sin of inf: ValueError, OverflowError)
    gets fitness +inf instead of aborting the run (the example would crash).
Success: the hall-of-fame individual is within 0.01 of the target on all 20
points ("hits", as cic counts them).

Usage: scripts/deap_symbreg.py [--seeds N] [--start S] [--fitness mse|sae] [--verbose]
Prints one line per run with --verbose, then a summary and a machine-readable
line "RESULT runs=N successes=K seconds=T per_run=M cpu_seconds=C" (wall
seconds of the runs alone, without Python start-up; C = process CPU time).
Needs Debian's python3-deap (the shebang is /usr/bin/python3 on purpose).
"""
import argparse
import math
import operator
import random
import sys
import time

from deap import algorithms, base, creator, gp, tools

POINTS = [x / 10. for x in range(-10, 10)]
HIT_TOLERANCE = 0.01


def protectedDiv(left, right):
    try:
        return left / right
    except ZeroDivisionError:
        return 1


def target(x):
    return x**4 + x**3 + x**2 + x


def build_toolbox(fitness_kind):
    pset = gp.PrimitiveSet("MAIN", 1)
    pset.addPrimitive(operator.add, 2)
    pset.addPrimitive(operator.sub, 2)
    pset.addPrimitive(operator.mul, 2)
    pset.addPrimitive(protectedDiv, 2)
    pset.addPrimitive(operator.neg, 1)
    pset.addPrimitive(math.cos, 1)
    pset.addPrimitive(math.sin, 1)
    pset.addEphemeralConstant("rand101", lambda: random.randint(-1, 1))
    pset.renameArguments(ARG0='x')

    creator.create("FitnessMin", base.Fitness, weights=(-1.0,))
    creator.create("Individual", gp.PrimitiveTree, fitness=creator.FitnessMin)

    toolbox = base.Toolbox()
    toolbox.register("expr", gp.genHalfAndHalf, pset=pset, min_=1, max_=2)
    toolbox.register("individual", tools.initIterate, creator.Individual, toolbox.expr)
    toolbox.register("population", tools.initRepeat, list, toolbox.individual)
    toolbox.register("compile", gp.compile, pset=pset)

    def evalSymbReg(individual, points):
        func = toolbox.compile(expr=individual)
        try:
            if fitness_kind == "mse":
                sqerrors = ((func(x) - x**4 - x**3 - x**2 - x)**2 for x in points)
                return math.fsum(sqerrors) / len(points),
            return math.fsum(abs(func(x) - target(x)) for x in points),
        except (ValueError, OverflowError):
            return math.inf,

    toolbox.register("evaluate", evalSymbReg, points=POINTS)
    toolbox.register("select", tools.selTournament, tournsize=3)
    toolbox.register("mate", gp.cxOnePoint)
    toolbox.register("expr_mut", gp.genFull, min_=0, max_=2)
    toolbox.register("mutate", gp.mutUniform, expr=toolbox.expr_mut, pset=pset)
    toolbox.decorate("mate", gp.staticLimit(key=operator.attrgetter("height"), max_value=17))
    toolbox.decorate("mutate", gp.staticLimit(key=operator.attrgetter("height"), max_value=17))
    return toolbox


def hits(toolbox, individual):
    func = toolbox.compile(expr=individual)
    try:
        return sum(1 for x in POINTS if abs(func(x) - target(x)) <= HIT_TOLERANCE)
    except (ValueError, OverflowError):
        return 0


def run(toolbox, seed):
    random.seed(seed)
    pop = toolbox.population(n=300)
    hof = tools.HallOfFame(1)
    algorithms.eaSimple(pop, toolbox, 0.5, 0.1, 40, halloffame=hof, verbose=False)
    best = hof[0]
    return best, best.fitness.values[0], hits(toolbox, best)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seeds", type=int, default=1, help="number of runs (default 1)")
    ap.add_argument("--start", type=int, default=1, help="first seed (default 1)")
    ap.add_argument("--fitness", choices=["mse", "sae"], default="mse",
                    help="mse = DEAP's example (default); sae = sum of absolute errors as cic")
    ap.add_argument("--verbose", action="store_true", help="one line per run")
    args = ap.parse_args()
    if args.seeds < 1:
        ap.error("--seeds must be >= 1")

    toolbox = build_toolbox(args.fitness)
    successes = 0
    total = 0.0
    cpu0 = time.process_time()
    for seed in range(args.start, args.start + args.seeds):
        t0 = time.perf_counter()
        best, fitness, h = run(toolbox, seed)
        dt = time.perf_counter() - t0
        total += dt
        ok = h == len(POINTS)
        successes += ok
        if args.verbose:
            print(f"seed {seed}: {args.fitness} {fitness:.6g} hits {h}/{len(POINTS)} "
                  f"{'success' if ok else 'fail'} {dt:.3f} s  {best}", flush=True)
    cpu = time.process_time() - cpu0
    per_run = total / args.seeds
    print(f"DEAP {args.fitness}: runs {args.seeds}, successes {successes} "
          f"({100.0 * successes / args.seeds:.0f}%), total {total:.2f} s wall ({cpu:.2f} s CPU), "
          f"per run {per_run:.3f} s")
    print(f"RESULT runs={args.seeds} successes={successes} seconds={total:.4f} per_run={per_run:.4f} "
          f"cpu_seconds={cpu:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
