#!/usr/bin/env python3
"""The tables of docs/baselines.md, "Walking like the best" (issue 21).

    scripts/walk-report.py [--studies DIR] [--results DIR] tune|ledger|compare|winners|best

DIR (default runs/baselines) holds the study folders that scripts/baselines.sh
writes; --results (default experiments/baselines/results) holds each study's
gait assessments (<study>-gaits.csv from `cic assess`, one row per finished
run: its best_ever individual replayed).

Every method is scored alike: the raw eq. 7.1 fitness of its best individual,
replayed (column raw_fitness: without HyperGP's oscillation penalty, which
best_ever includes). A run without an assessment row is scored by best_ever and
marked with *. Evaluations are the counts index.csv records.

  ledger   merges the comparison's finished runs found in DIR into
           results/walk-runs.csv, one row per run (study, config, seed, best_ever,
           evaluations, wall seconds and its gait assessment). A run whose folder
           is gone keeps its row: the study spans sittings and machines, and run
           folders are never committed. A run found again replaces its row.
  tune     the tuning studies (walk-tune-*.xml, tuning seeds 101..105): per
           configuration n, median, IQR, evaluations, and how its best gait
           moves; the winner of each method is the highest median whose best
           gait neither shakes nor flipped, decided before the comparison runs.
  compare  the comparison (walk-2500-*.xml, walk-15000-*.xml, seeds 1..10), from
           results/walk-runs.csv merged with the runs found in DIR: per
           budget and robot, each method's median and IQR; every HyperGP method
           against the best CMA-ES of the cell (the higher median of the two):
           two-sided Mann-Whitney p (scipy, method auto, as `cic compare`), Holm
           over every comparison of the table at once, A12 = P(HyperGP run >
           CMA-ES run) with a 95% bootstrap interval (2,000 resamples, seed 1);
           and the goal per cell. A cell is open, and nothing is read from it,
           until every method run at its budget has its 10 runs there.
  winners  which configuration each of settings/r{0,1,2}_best.xml and
           r{0,1,2}_best_hypergp.xml ships, by a rule fixed before R2 at 15,000
           was in: on each robot, at the largest budget where every method run
           there has 10 runs, the method with the highest median replaces
           HyperGP's old best (hgp-best, the incumbent) only if it beats it,
           two-sided Mann-Whitney p (Holm over the distinct challengers of the
           table) < 0.05; _best draws from every method, _best_hypergp from the HyperGP
           ones. Writes results/walk-winners.csv, which the test
           SweepFile.ShippedBestSettingsAreTheComparisonWinners holds the shipped
           files to, and prints the table.
  best     study,config,run_dir,score of each comparison study's best run per
           robot (the highest score, the run whose gait compare describes), one
           CSV line each: baselines.sh keeps each one replayable in
           results/best/STUDY/CONFIG (its settings and the population file that
           holds its best individual), so its strip and its gait outlive the
           run folder.
"""
import argparse
import csv
import pathlib
import statistics as st
import sys

from study_stats import a12, a12_interval, holm, mann_whitney_p, quartiles

ROOT = pathlib.Path(__file__).resolve().parent.parent
ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--studies", default="runs/baselines")
ap.add_argument("--results", default=str(ROOT / "experiments" / "baselines" / "results"))
ap.add_argument("mode", choices=["tune", "ledger", "compare", "winners", "best"])
args = ap.parse_args()
STUDIES, RESULTS = pathlib.Path(args.studies), pathlib.Path(args.results)

TUNING = ["walk-tune-hypergp", "walk-tune-cmaes"]
# (label, study suffix, is HyperGP); the study is walk-BUDGET-SUFFIX
METHODS = [
    ("HyperGP, best configuration", "hgp-best", True),
    ("HyperGP, evolved clock", "hgp-clock", True),
    ("HyperGP-CPG", "hgp-cpg", True),
    ("HyperGP-gait", "hgp-gait", True),
    ("CMA-ES gait, IPOP", "cmaes-gait", False),
    ("CMA-ES CPG, IPOP", "cmaes-cpg", False),
]
ROBOTS = ["R0", "R1", "R2", "R1-6legs", "cross"]
SEEDS = 10   # comparison seeds per cell (1..10)


def fail(message):
    print(f"walk-report.py: {message}", file=sys.stderr)
    sys.exit(2)


def run_of(input_path):
    """The run folder of an assessed input: the folder itself, or RUN/populations/gen-NNNN.xml."""
    p = pathlib.Path(input_path)
    return (p.parent.parent if p.suffix == ".xml" and p.parent.name == "populations" else p).resolve()


def number(text, where, column):
    try:
        return float(text)
    except ValueError:
        fail(f"{where}: column '{column}': '{text}' is not a number")


def read_gaits(gfile):
    """{run folder: row} of a `cic assess` CSV; {} when the file is absent."""
    gaits = {}
    if gfile.exists():
        with open(gfile, newline="") as f:
            reader = csv.DictReader(f)
            if "raw_fitness" not in (reader.fieldnames or []):
                fail(f"{gfile}:1: no column raw_fitness (made by an older cic assess; rerun the summary)")
            for r in reader:
                gaits[run_of(r["input"])] = r
    return gaits


def runs(study):
    """{config: [run]} of the study's finished runs in --studies (None when it has no index)."""
    if not (STUDIES / study / "index.csv").exists():
        return None
    return ledger_runs(found_rows(study), study) or {}


LEDGER_FIELDS = ["study", "run_dir", "config", "seed", "best_ever", "evaluations", "wall_seconds", "fitness",
                 "dominant_hz", "mean_height", "min_height", "final_up", "flipped", "shaking", "raw_fitness"]
GAIT_FIELDS = LEDGER_FIELDS[7:]


def found_rows(study):
    """Ledger rows of the study's finished runs in --studies (none when the study folder is absent)."""
    index = STUDIES / study / "index.csv"
    if not index.exists():
        return []
    # baselines.sh leaves a comparison study's assessments beside its runs (summary/);
    # --results holds those of sittings before it did.
    gfile = STUDIES / study / "summary" / f"{study}-gaits.csv"
    if not gfile.exists():
        gfile = RESULTS / f"{study}-gaits.csv"
    gaits = read_gaits(gfile)
    rows = []
    with open(index, newline="") as f:
        reader = csv.DictReader(f)
        missing = {"run_dir", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds"} - \
            set(reader.fieldnames or [])
        if missing:
            fail(f"{index}:1: header has no column {', '.join(sorted(missing))}")
        for r in reader:
            if r["status"] != "done" or not r["best_ever"]:
                continue
            where = f"{index}:{reader.line_num}"
            for column in ("best_ever", "evaluations"):
                number(r[column], where, column)
            g = gaits.get((STUDIES / study / r["run_dir"]).resolve())
            row = {"study": study, "run_dir": r["run_dir"], "config": r["config"], "seed": r["seed"],
                   "best_ever": r["best_ever"], "evaluations": r["evaluations"], "wall_seconds": r["wall_seconds"]}
            row.update({k: (g[k] if g else "") for k in GAIT_FIELDS})
            rows.append(row)
    return rows


def comparison_studies():
    return [f"walk-{budget}-{suffix}" for budget in (2500, 15000) for _, suffix, _ in METHODS]


def merged_ledger():
    """The committed ledger with every run found in --studies put in (a run found replaces its row)."""
    ledger = {}
    path = RESULTS / "walk-runs.csv"
    if path.exists():
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            if reader.fieldnames != LEDGER_FIELDS:
                fail(f"{path}:1: the header is not {','.join(LEDGER_FIELDS)}")
            for r in reader:
                where = f"{path}:{reader.line_num}"
                number(r["best_ever"], where, "best_ever")
                for column in ("raw_fitness", "evaluations"):
                    if r[column]:
                        number(r[column], where, column)
                ledger[(r["study"], r["run_dir"])] = r
    for study in comparison_studies():
        for row in found_rows(study):
            ledger[(row["study"], row["run_dir"])] = row
    order = {s: i for i, s in enumerate(comparison_studies())}
    return sorted(ledger.values(), key=lambda r: (order.get(r["study"], len(order)), r["study"], r["config"],
                                                  int(r["seed"])))


def write_csv_atomically(path, fields, rows):
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    tmp.replace(path)


def write_ledger():
    rows = merged_ledger()
    path = RESULTS / "walk-runs.csv"
    write_csv_atomically(path, LEDGER_FIELDS, rows)
    print(f"walk-report.py: {len(rows)} runs in {path}", file=sys.stderr)


def ledger_runs(ledger, study):
    """{config: [run]} of one comparison study, from the merged ledger."""
    out = {}
    for r in ledger:
        if r["study"] != study:
            continue
        g = r if r["raw_fitness"] else None
        score = float(r["raw_fitness"]) if g else float(r["best_ever"])
        out.setdefault(r["config"], []).append({"score": score, "star": g is None, "gait": g, "run_dir": r["run_dir"],
                                                "evaluations": int(float(r["evaluations"])) if r["evaluations"] else None})
    return out or None


def gait_text(best_run):
    g = best_run["gait"]
    if not g:
        return "not assessed"
    moves = "flipped" if g["flipped"] == "1" else "shaking" if g["shaking"] == "1" else "steps"
    return f"{moves} at {float(g['dominant_hz']):.2f} Hz, centre {float(g['mean_height']):.2f} m"


def walks(best_run):
    g = best_run["gait"]
    return g is not None and g["flipped"] != "1" and g["shaking"] != "1"


def describe(v):
    scores = [r["score"] for r in v]
    q1, q3 = quartiles(scores)
    evals = [r["evaluations"] for r in v if r["evaluations"] is not None]
    star = "*" if any(r["star"] for r in v) else ""
    best = max(v, key=lambda r: r["score"])
    if not evals:
        ev = "not recorded"
    else:
        ev = f"{min(evals)}" if min(evals) == max(evals) else f"{min(evals)}–{max(evals)}"
        if len(evals) < len(v):
            ev += f" ({len(v) - len(evals)} not recorded)"
    return scores, f"{len(v)} | {st.median(scores):.2f}{star} | [{q1:.2f}, {q3:.2f}] | {ev} | {gait_text(best)}"


def tune():
    print("# Walking like the best: the tuning stage\n")
    print(f"Made by `scripts/walk-report.py tune` from `{STUDIES}`: R1, 2,500 evaluations, tuning seeds "
          "101..105; score = raw eq. 7.1 of each run's best individual, replayed (* = best_ever, not assessed).\n")
    for study in TUNING:
        found = runs(study)
        print(f"## {study}\n")
        if found is None:
            print("not run\n")
            continue
        print("| configuration | n | median | IQR [Q1, Q3] | evaluations | best run's gait |")
        print("|---|---|---|---|---|---|")
        families = {}
        for config in sorted(found):
            v = found[config]
            scores, text = describe(v)
            print(f"| {config} | {text} |")
            family = config.split("-")[0]
            best = max(v, key=lambda r: r["score"])
            families.setdefault(family, []).append((st.median(scores), config, walks(best), len(v)))
        print()
        for family, rows in sorted(families.items()):
            ok = sorted((r for r in rows if r[2]), reverse=True)
            passed = [r[1] for r in rows if not r[2]]
            complete = all(r[3] == 5 for r in rows)
            if ok:
                print(f"- **{family}**: winner {ok[0][1]} (median {ok[0][0]:.2f})"
                      + (f"; passed over (best gait shakes, flipped or not assessed): {', '.join(passed)}" if passed else "")
                      + ("" if complete else " — provisional: not every configuration has 5 runs"))
            else:
                print(f"- **{family}**: no configuration whose best gait walks")
        print()


def compute(ledger):
    """Run time summed over runs: the comparison from the ledger (a run made before the
    ledger kept one row per run counts at its study's mean, and is said so), the tuning
    stage from its `cic compare` tables (runs x mean wall seconds per configuration)."""
    print("## Compute\n")
    print("Wall seconds of each run summed (one run = one process with its worker processes, on the "
          "2-core machine, usually beside other runs, which inflates the figures).\n")
    print("| study | runs | hours | of which estimated |")
    print("|---|---|---|---|")
    total = estimated_total = 0.0
    for study in TUNING:
        path = RESULTS / f"{study}-configs.csv"
        if not path.exists():
            continue
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        n = sum(int(r["runs"]) for r in rows)
        hours = sum(int(r["runs"]) * float(r["wall_seconds_mean"]) for r in rows) / 3600
        total += hours
        print(f"| {study} | {n} | {hours:.1f} | – |")
    for study in comparison_studies():
        rows = [r for r in ledger if r["study"] == study]
        if not rows:
            continue
        known = [float(r["wall_seconds"]) for r in rows if r["wall_seconds"]]
        missing = len(rows) - len(known)
        estimate = missing * (st.mean(known) if known else 0.0) / 3600
        hours = sum(known) / 3600 + estimate
        total += hours
        estimated_total += estimate
        print(f"| {study} | {len(rows)} | {hours:.1f} | {estimate:.1f} ({missing} runs) |" if missing
              else f"| {study} | {len(rows)} | {hours:.1f} | – |")
    print(f"| **total** | | **{total:.1f}** | {estimated_total:.1f} |\n")


def compare():
    print("# Walking like the best: the comparison\n")
    print(f"Made by `scripts/walk-report.py compare` from `results/walk-runs.csv` (one row per finished run, kept "
          f"across sittings) merged with the runs in `{STUDIES}`: seeds 1..10; score = raw eq. 7.1 of each "
          "run's best individual, replayed (* = best_ever, not assessed). Holm over every comparison below.\n")
    ledger = merged_ledger()
    table, tests = [], []   # tests: (budget, robot, method, p, A12, interval, hgp median, cma median, cma label)
    for budget in (2500, 15000):
        for robot in ROBOTS:
            cell = {}
            for label, suffix, is_hgp in METHODS:
                found = ledger_runs(ledger, f"walk-{budget}-{suffix}")
                if found and robot in found:
                    cell[label] = (found[robot], is_hgp)
            if not cell:
                continue
            table.append((budget, robot, cell))
            cmas = [(st.median([r["score"] for r in v]), label, v) for label, (v, h) in cell.items() if not h]
            if not cmas:
                continue
            cma_median, cma_label, cma_runs = max(cmas)
            y = [r["score"] for r in cma_runs]
            for label, (v, is_hgp) in cell.items():
                if not is_hgp:
                    continue
                x = [r["score"] for r in v]
                tests.append([budget, robot, label, mann_whitney_p(x, y), a12(x, y), a12_interval(x, y),
                              st.median(x), cma_median, cma_label, min(len(x), len(y))])
    adjusted = holm([t[3] for t in tests])
    # A cell is open until every method run at its budget (on any robot) has its 10 runs there:
    # its tests stay in the Holm family, but nothing is read from it yet.
    planned = {b: {label for budget, _, cell in table if budget == b for label in cell} for b in (2500, 15000)}
    open_cells = {}
    for budget, robot, cell in table:
        counts = {label: len(cell[label][0]) if label in cell else 0 for label in sorted(planned[budget])}
        if any(n < SEEDS for n in counts.values()):
            open_cells[(budget, robot)] = counts
    for budget in (2500, 15000):
        rows = [t for t in table if t[0] == budget]
        if not rows:
            continue
        print(f"## {budget:,} evaluations\n")
        print("| robot | method | n | median | IQR [Q1, Q3] | evaluations | best run's gait |")
        print("|---|---|---|---|---|---|---|")
        for _, robot, cell in rows:
            for label, (v, _) in cell.items():
                print(f"| {robot} | {label} | {describe(v)[1]} |")
        print()
        print("| robot | HyperGP method | median | best CMA-ES | median | p | p (Holm) | A12 [95% CI] | reading |")
        print("|---|---|---|---|---|---|---|---|---|")
        for t, p_holm in zip(tests, adjusted):
            if t[0] != budget:
                continue
            _, robot, label, p, a, (lo, hi), mx, my, cma, n = t
            if (budget, robot) in open_cells:
                reading = f"cell open: n = {n} so far"
            elif p_holm is None:
                reading = "no p (scipy missing)"
            elif p_holm < 0.05:
                reading = "HyperGP better" if mx > my else "CMA-ES better"
            else:
                reading = f"no difference shown at n = {n}"
            ptext = "–" if p is None else f"{p:.3g}"
            htext = "–" if p_holm is None else f"{p_holm:.3g}"
            print(f"| {robot} | {label} | {mx:.2f} | {cma} | {my:.2f} | {ptext} | {htext} | {a:.2f} [{lo:.2f}, {hi:.2f}] "
                  f"| {reading} |")
        print()
    if any(r["evaluations"] is None for _, _, cell in table for v, _ in cell.values() for r in v):
        print("Evaluations \"not recorded\": runs made before `results/walk-runs.csv` kept one row per run "
              "(R1 and R2 at 2,500, HyperGP's best at 15,000 on R1); their ranges are in the first table "
              "(`git show 075acaa:experiments/baselines/results/walk.md`).\n")
    compute(ledger)
    print("## The goal, cell by cell\n")
    print("Some HyperGP method beats the best CMA-ES median with p (Holm) < 0.05 at 15,000 evaluations, and is not "
          "significantly worse at 2,500.\n")
    failed = []
    for budget in (2500, 15000):
        for robot in ROBOTS:
            cell = [(t, p) for t, p in zip(tests, adjusted) if t[0] == budget and t[1] == robot]
            if not cell:
                continue
            if (budget, robot) in open_cells:
                counts = open_cells[(budget, robot)]
                print(f"- {budget:,}, {robot}: open, {sum(counts.values())} of {SEEDS * len(counts)} runs ("
                      + ", ".join(f"{label} {n}" for label, n in counts.items()) + ")")
                continue
            if budget == 15000:
                met = [t[2] for t, p in cell if p is not None and p < 0.05 and t[6] > t[7]]
            else:
                met = [t[2] for t, p in cell if p is not None and not (p < 0.05 and t[6] < t[7])]
            print(f"- {budget:,}, {robot}: " + (f"met by {', '.join(met)}" if met else "not met"))
            if not met:
                failed.append(f"{budget:,}, {robot}")
    # The goal asks for every robot: one cell not met decides it, whatever the open cells give.
    if failed:
        print(f"\n**The goal is not met**: not met at {'; '.join(failed)}.")
    elif open_cells:
        print("\nThe goal is open: no cell failed so far, and some cells are open.")
    else:
        print("\n**The goal is met** in every cell.")
    print()


WINNER_FIELDS = ["robot", "file", "budget", "study", "config", "n", "median", "incumbent_median", "p", "p_holm"]


def winners():
    try:
        import scipy  # noqa: F401  (the rule needs its p-values: no winner without them)
    except ImportError:
        fail("winners needs scipy (Debian's python3-scipy): the rule decides by Mann-Whitney p")
    ledger = merged_ledger()
    picks = []   # [robot, file, budget, suffix, n, median, incumbent median, p]
    for robot in ("R0", "R1", "R2"):
        cells = {}
        for budget in (2500, 15000):
            cell = {}
            for _, suffix, is_hgp in METHODS:
                found = ledger_runs(ledger, f"walk-{budget}-{suffix}")
                if found and robot in found:
                    cell[suffix] = ([r["score"] for r in found[robot]], is_hgp)
            if cell and "hgp-best" in cell and all(len(v) == 10 for v, _ in cell.values()):
                cells[budget] = cell
        if not cells:
            fail(f"{robot}: no budget where every method has 10 runs")
        budget = max(cells)
        cell = cells[budget]
        incumbent = cell["hgp-best"][0]
        for file, pool in ((f"settings/{robot.lower()}_best.xml", cell),
                           (f"settings/{robot.lower()}_best_hypergp.xml", {k: v for k, v in cell.items() if v[1]})):
            top = max(pool, key=lambda k: st.median(pool[k][0]))
            x = pool[top][0]
            p = None if top == "hgp-best" else mann_whitney_p(x, incumbent)
            picks.append([robot, file, budget, top, len(x), st.median(x), st.median(incumbent), p])
    # One test per (robot, challenger): _best and _best_hypergp may name the same one.
    tests = sorted({(t[0], t[3]): t[7] for t in picks if t[7] is not None}.items())
    holm_of = dict(zip([k for k, _ in tests], holm([p for _, p in tests])))
    adjusted = [holm_of.get((t[0], t[3])) for t in picks]
    rows = []
    print("| file | budget | highest median | median | HyperGP's old best | p | p (Holm) | ships |")
    print("|---|---|---|---|---|---|---|---|")
    for (robot, file, budget, top, n, med, inc, p), p_holm in zip(picks, adjusted):
        wins = top == "hgp-best" or (p_holm < 0.05 and med > inc)
        chosen = top if wins else "hgp-best"
        label = {suffix: lab for lab, suffix, _ in METHODS}
        ptext = "–" if p is None else f"{p:.3g}"
        htext = "–" if p_holm is None else f"{p_holm:.3g}"
        print(f"| `{file}` | {budget:,} | {label[top]} | {med:.2f} | {inc:.2f} | {ptext} | {htext} | {label[chosen]} |")
        cm = med if wins else inc
        rows.append({"robot": robot, "file": file, "budget": budget, "study": f"walk-{budget}-{chosen}",
                     "config": robot, "n": n, "median": f"{cm:.4f}", "incumbent_median": f"{inc:.4f}",
                     "p": "" if p is None else f"{p:.4g}", "p_holm": "" if p_holm is None else f"{p_holm:.4g}"})
    path = RESULTS / "walk-winners.csv"
    write_csv_atomically(path, WINNER_FIELDS, rows)
    print(f"\nwalk-report.py: the shipped winners in {path}", file=sys.stderr)


def best():
    """study,config,run_dir,score of each comparison study's best run per configuration (the run
    whose gait `compare` describes), for baselines.sh to keep it replayable."""
    ledger = merged_ledger()
    w = csv.writer(sys.stdout, lineterminator="\n")
    for study in comparison_studies():
        for config, v in sorted((ledger_runs(ledger, study) or {}).items()):
            top = max(v, key=lambda r: r["score"])
            w.writerow([study, config, top["run_dir"], repr(top["score"])])


if args.mode == "tune":
    tune()
elif args.mode == "ledger":
    write_ledger()
elif args.mode == "winners":
    winners()
elif args.mode == "best":
    best()
else:
    compare()
