#!/usr/bin/env python3
"""The tables of docs/baselines.md from the baseline studies' folders.

    scripts/baselines-report.py [--studies DIR] [--results DIR]

DIR (default runs/baselines) holds the study folders that scripts/baselines.sh
writes; --results (default experiments/baselines/results) holds the gait
assessments (<study>-gaits.csv from `cic assess`) and sine-grid.csv. Per robot
and budget: each method's runs (n), median and IQR of best_ever (the best
fitness found within the budget), Mann-Whitney U (two-sided) and A12 between
HyperGP (its best configuration where that study exists, else Table B.1) and
CMA-ES, and whether each method's best gait walks (dominant command frequency,
centre height, flipped, shaking; `cic assess` replays, of the run with the
highest best_ever, the individual that reached it: baselines.sh assesses the
saved population of the first generation at that fitness, since a HyperGP run
without elitism may have lost it by its last generation). A shaking gait does
not win its cell (thesis 7.3.2.1). Statistics follow docs/statistics.md and `cic compare`: scipy's
two-sided Mann-Whitney U with method="auto" (at ten runs a side: the normal approximation with
continuity correction; no p without scipy), A12 as the probability that a HyperGP run beats a
CMA-ES run (ties half).
Methods whose study has not run are listed as "not run".
"""
import argparse
import csv
import pathlib
import statistics as st
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--studies", default="runs/baselines")
ap.add_argument("--results", default=str(ROOT / "experiments" / "baselines" / "results"))
args = ap.parse_args()
STUDIES, RESULTS = pathlib.Path(args.studies), pathlib.Path(args.results)

# (budget, method label, study, is HyperGP)
METHODS = [
    (2500, "HyperGP, Table B.1", "hypergp-b1-2500", True),
    (2500, "HyperGP, best configuration", "hypergp-best-2500", True),
    (2500, "CMA-ES gait", "gait-2500", False),
    (2500, "CMA-ES gait, clamped bounds", "gait-clamp-2500", False),
    (15000, "HyperGP, best configuration", "hypergp-best-15000", True),
    (15000, "CMA-ES gait", "gait-15000", False),
]
ROBOTS = ["R0", "R1", "R2", "R1-6legs"]


def runs(study):
    """{variant: [(best_ever, run folder)]} of the finished runs."""
    index = STUDIES / study / "index.csv"
    if not index.exists():
        return None
    out = {}
    with open(index, newline="") as f:
        reader = csv.DictReader(f)
        missing = {"run_dir", "config", "status", "best_ever"} - set(reader.fieldnames or [])
        if missing:
            fail(f"{index}:1: header has no column {', '.join(sorted(missing))} (an index.csv from cic sweep "
                 "has them; rewrite it with `cic sweep FILE --index-only`)")
        for r in reader:
            if r["status"] != "done" or not r["best_ever"]:
                continue
            try:
                fitness = float(r["best_ever"])
            except ValueError:
                fail(f"{index}:{reader.line_num}: column 'best_ever': '{r['best_ever']}' is not a number")
            out.setdefault(r["config"], []).append((fitness, STUDIES / study / r["run_dir"]))
    return out


def fail(message):
    print(f"baselines-report.py: {message}", file=sys.stderr)
    sys.exit(2)


def run_of(input_path):
    """The run folder of an assessed input: the folder itself, or RUN/populations/gen-NNNN.xml."""
    p = pathlib.Path(input_path)
    return (p.parent.parent if p.suffix == ".xml" and p.parent.name == "populations" else p).resolve()


def gaits(study):
    f = RESULTS / f"{study}-gaits.csv"
    return {run_of(r["input"]): r for r in csv.DictReader(open(f))} if f.exists() else {}


def a12(x, y):
    return sum(1 if a > b else 0.5 if a == b else 0 for a in x for b in y) / (len(x) * len(y))


def mann_whitney_p(x, y):
    try:
        from scipy.stats import mannwhitneyu
    except ImportError:
        return None
    return mannwhitneyu(x, y, alternative="two-sided").pvalue


def quartiles(v):
    q = st.quantiles(v, n=4, method="inclusive") if len(v) > 1 else [v[0]] * 3
    return q[0], q[2]


sine, sine_spec = {}, {}
if (RESULTS / "sine-grid.csv").exists():
    # robot,fitness,controller where the controller spec itself holds commas (sine:A,F,P)
    for line in open(RESULTS / "sine-grid.csv").read().splitlines()[1:]:
        robot, fitness, controller = line.split(",", 2)
        sine[robot] = float(fitness)
        sine_spec[robot] = controller

print("# HyperGP against parameter-optimised gaits: the tables\n")
print("Made by `scripts/baselines-report.py` from the studies in "
      f"`{STUDIES}`; metric best_ever (the best fitness found within the budget).\n")
winners = []   # (budget, robot, text)
goals = []     # (budget, robot, HyperGP best's median, CMA-ES median, p, A12)
for budget in (2500, 15000):
    robots = ROBOTS if budget == 2500 else ["R1"]
    print(f"## {budget:,} evaluations\n")
    print("| robot | method | n | median | IQR [Q1, Q3] | best run's gait: Hz, height m, flipped, shaking "
          "| runs whose best gait shakes / flipped |")
    print("|---|---|---|---|---|---|---|")
    for robot in robots:
        samples = {}
        ranked = []   # (median, label, shakes) of every method with runs
        for b, label, study, _ in METHODS:
            if b != budget:
                continue
            found = runs(study)
            if found is None:
                print(f"| {robot} | {label} | not run | | | | |")
                continue
            v = found.get(robot, [])
            if not v:
                print(f"| {robot} | {label} | 0 | | | | |")
                continue
            fitness = [f for f, _ in v]
            samples[label] = fitness
            q1, q3 = quartiles(fitness)
            best_run = max(v)[1].resolve()
            g = gaits(study).get(best_run)
            walk = (f"{float(g['dominant_hz']):.1f}, {float(g['mean_height']):.2f}, "
                    f"{'yes' if g['flipped'] == '1' else 'no'}, {'**shaking**' if g['shaking'] == '1' else 'no'}"
                    if g else "not assessed")
            ranked.append((st.median(fitness), label, g is not None and g["shaking"] == "1", g is None))
            assessed = [gaits(study).get(run.resolve()) for _, run in v]
            assessed = [a for a in assessed if a]
            counts = (f"{sum(a['shaking'] == '1' for a in assessed)} / {sum(a['flipped'] == '1' for a in assessed)}"
                      f" of {len(assessed)}" if assessed else "not assessed")
            print(f"| {robot} | {label} | {len(fitness)} | {st.median(fitness):.2f} | "
                  f"{q3 - q1:.2f} [{q1:.2f}, {q3:.2f}] | {walk} | {counts} |")
        if budget == 2500:
            if robot in sine:
                # The grid's frequencies are 0.25..2 Hz: a sine gait cannot shake.
                print(f"| {robot} | sine grid (deterministic) | 1 | {sine[robot]:.2f} | | "
                      f"{sine_spec.get(robot, '')} | |")
                ranked.append((sine[robot], "sine grid", False, False))
            else:
                print(f"| {robot} | sine grid | not run | | | | |")
        cma = samples.get("CMA-ES gait")
        for which in ("Table B.1", "best configuration"):
            hypergp = samples.get(f"HyperGP, {which}")
            if not (hypergp and cma):
                continue
            p = mann_whitney_p(hypergp, cma)
            ptext = f"p = {p:.3g}" if p is not None else "p: scipy missing"
            print(f"| {robot} | **HyperGP ({which}) vs CMA-ES** | | | | {ptext}, A12 = {a12(hypergp, cma):.2f} | |")
            if which == "best configuration":
                goals.append((budget, robot, st.median(hypergp), st.median(cma), p, a12(hypergp, cma)))
        # The cell's winner: the highest median whose best gait walks (thesis 7.3.2.1).
        ranked.sort(reverse=True)
        walking = [(m, label, unassessed) for m, label, shakes, unassessed in ranked if not shakes]
        if walking:
            m, label, unassessed = walking[0]
            text = f"{label} (median {m:.2f})" + (" — its best gait not assessed yet" if unassessed else "")
            above = [f"{l} ({x:.2f})" for x, l, shakes, _ in ranked if shakes and x > m]
            if above:
                text += f"; passed over for shaking: {', '.join(above)}"
            winners.append((budget, robot, text))
        elif ranked:
            winners.append((budget, robot, "none: every method's best gait shakes"))
    print()

print("## Winner of each cell\n")
print("The highest median whose best gait walks; a method whose best gait moves by "
      "shaking (dominant command frequency above 4 Hz, thesis 7.3.2.1) does not win.\n")
print("| budget | robot | winner |")
print("|---|---|---|")
for budget, robot, text in winners:
    print(f"| {budget:,} | {robot} | {text} |")
print()

print("## The goal: HyperGP's best configuration beats CMA-ES\n")
print("Met in a cell when HyperGP's best configuration has the higher median and the two-sided "
      "Mann-Whitney p is below 0.05.\n")
if goals:
    print("| budget | robot | HyperGP best, median | CMA-ES, median | p | A12 | goal |")
    print("|---|---|---|---|---|---|---|")
    for budget, robot, mh, mc, p, a in goals:
        met = p is not None and p < 0.05 and mh > mc
        verdict = ("**met**" if met else "not met: " + ("CMA-ES is ahead" if p is not None and p < 0.05
                                                         else "no significant difference"))
        ptext = f"{p:.3g}" if p is not None else "scipy missing"
        print(f"| {budget:,} | {robot} | {mh:.2f} | {mc:.2f} | {ptext} | {a:.2f} | {verdict} |")
    cells = len(ROBOTS) + 1
    missing = f" ({cells} when every study has run)" if len(goals) < cells else ""
    print(f"\n{sum(1 for b, r, mh, mc, p, a in goals if p is not None and p < 0.05 and mh > mc)} of "
          f"{len(goals)} cells met{missing}.\n")
else:
    print("Not measured yet: HyperGP's best configuration or CMA-ES has not run.\n")

print("## Compute\n")
print("| study | runs done | run time, sum (h) |")
print("|---|---|---|")
seconds = {}   # run folder (resolved: a run shared through the store once) -> run time
for index in sorted(STUDIES.glob("*/index.csv")):
    study = index.parent.name
    rows = [r for r in csv.DictReader(open(index)) if r["status"] == "done"]
    hours = sum(float(r["wall_seconds"] or 0) for r in rows) / 3600
    for r in rows:
        seconds[(STUDIES / study / r["run_dir"]).resolve()] = float(r["wall_seconds"] or 0)
    print(f"| {study} | {len(rows)} | {hours:.2f} |")
print(f"| all: {len(seconds)} runs (a run that studies share through the run store counted once) | | "
      f"{sum(seconds.values()) / 3600:.2f} |")
