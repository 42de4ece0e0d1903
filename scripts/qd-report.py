#!/usr/bin/env python3
"""The tables of docs/quality-diversity.md (issue 26).

    scripts/qd-report.py [--studies DIR] [--baselines DIR] [--results DIR] ledger|compare|curves|cells RUN

DIR (default runs/quality-diversity) holds the study folders that
scripts/quality-diversity.sh writes (me-hgp-15000, me-gait-15000,
me-cmame-15000); --results
(default experiments/quality-diversity/results) holds the ledger.

  ledger   merges the finished MAP-Elites runs found in DIR into
           results/qd-runs.csv, one row per run: the last stats.csv row's
           QD-score (offset -1), coverage, cells filled and best elite, and the
           evaluations spent. A run whose folder is gone keeps its row (run
           folders are never committed); a run found again replaces it.
           With the plain references' run folders (--baselines, default
           runs/baselines: walk-15000-hgp-gait, walk-15000-cmaes-gait) it also
           keeps results/qd-refs.csv, each reference's best_ever individual
           replayed by `cic assess` as scripts/baselines.sh does (raw eq. 7.1,
           as in walk-runs.csv, and each foot's duty factor), and
           results/qd-cellmatch.csv: for every MAP-Elites run and every
           reference best of its robot, the elite the archive holds in the
           reference best's cell (its 5 bins per foot, from the duty factors
           to 3 decimals), empty when the cell is.
  compare  from the ledger: first a line of how many of the design's 10
           seeds each robot and method has (an arm with fewer is open, and
           each of its tests says so); then per robot and method, median and IQR of QD-score,
           coverage and best elite; MAP-Elites with HyperGP, and with the
           CMA-ME emitter, against MAP-Elites with the gait vector's Gaussian
           emitter on QD-score and coverage (CMA-ME on the best elite too);
           and each MAP-Elites
           method's best elite against the plain runs' best at the same budget
           of 15,000 evaluations (HyperGP-gait and CMA-ES gait with IPOP, from
           experiments/baselines/results/walk-runs.csv, scored alike: raw eq.
           7.1 of the best individual; a MAP-Elites elite's stored fitness is
           raw eq. 7.1, as these settings have no penalty). Two-sided
           Mann-Whitney p (scipy), Holm over every test of the page at once,
           A12 with a 95% bootstrap interval (2,000 resamples, seed 1).
           Then, from qd-cellmatch.csv, the cells where the references walk:
           how many of them each method's archives fill, and how far their
           elites walk there against the references. Last, from the curve
           ledger, whether the archives still fill at the budget: QD-score,
           coverage and best 5,000 evaluations before the end and at it.
  curves   QD-score and coverage against evaluations, median and IQR over
           the runs of each method in results/qd-curve-points.csv (the ledger
           stage keeps each finished run's QD-score, coverage and best every
           500 evaluations and at its end, so the curves too outlive the run
           folders), one panel each per robot (gnuplot), to
           results/qd-curves.svg.
  cells    four elites of RUN far apart in the descriptor space, among those
           that walk at least half as far as the best (greedy farthest points
           from the best): one "I,J,...  fitness  descriptor" line each, for
           the screenshot strip.
"""
import argparse
import csv
import math
import pathlib
import statistics as st
import subprocess
import sys

from study_stats import a12, a12_interval, holm, mann_whitney_p, quartiles

STUDIES_OF = {"me-hgp-15000": "MAP-Elites, HyperGP-gait", "me-gait-15000": "MAP-Elites, gait vector",
              "me-cmame-15000": "MAP-Elites, gait vector, CMA-ME"}
PLAIN_OF = {"walk-15000-hgp-gait": "HyperGP-gait (plain)", "walk-15000-cmaes-gait": "CMA-ES gait, IPOP"}
SEEDS = 10   # the design: seeds 1-10 per robot and method; fewer in the ledger = the arm is still open
FIELDS = ["study", "run_dir", "config", "seed", "evaluations", "batches", "best", "qd_score", "coverage", "filled",
          "wall_seconds"]


def fail(message):
    print(f"qd-report.py: {message}", file=sys.stderr)
    sys.exit(2)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def finished_runs(studies):
    """(study, its index.csv row, the run's stats.csv rows) for every finished MAP-Elites run in `studies`."""
    for study in STUDIES_OF:
        index = studies / study / "index.csv"
        if not index.exists():
            continue
        for r in read_csv(index):
            if r["status"] != "done":
                continue
            stats = studies / study / r["run_dir"] / "stats.csv"
            if not stats.exists():
                fail(f"{stats}: missing for a run index.csv calls done")
            rows = read_csv(stats)
            for column in ("qd_score", "coverage", "filled", "best", "evaluations"):
                if not rows or column not in rows[-1]:
                    fail(f"{stats}:1: no column {column} (not a MAP-Elites run?)")
            yield study, r, rows


def found_rows(studies):
    rows = []
    for study, r, stats in finished_runs(studies):
        last = stats[-1]
        rows.append({"study": study, "run_dir": r["run_dir"], "config": r["config"], "seed": r["seed"],
                     "evaluations": last["evaluations"], "batches": int(last["generation"]) + 1,
                     "best": last["best"], "qd_score": last["qd_score"], "coverage": last["coverage"],
                     "filled": last["filled"], "wall_seconds": r["wall_seconds"]})
    return rows


def merge(path, fields, key, found):
    """Rewrites the ledger `path`: its rows, those of `found` replacing any with the same key."""
    rows = {key(r): r for r in (read_csv(path) if path.exists() else [])}
    for r in found:
        rows[key(r)] = r
    RESULTS.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        for k in sorted(rows):
            w.writerow(rows[k])
    tmp.replace(path)
    print(f"qd-report.py: {len(rows)} rows in {path}", file=sys.stderr)
    return list(rows.values())


CURVE_FIELDS = ["study", "config", "seed", "evaluations", "qd_score", "coverage", "best"]
CURVE_STEP = 500   # evaluations between the points a run keeps in the curve ledger (and its last)


def found_curve_points(studies):
    """Each finished run's QD-score, coverage and best every CURVE_STEP evaluations, and at its end."""
    points = []
    for study, r, rows in finished_runs(studies):
        for i, row in enumerate(rows):
            if int(row["evaluations"]) % CURVE_STEP == 0 or i == len(rows) - 1:
                points.append({"study": study, "config": r["config"], "seed": r["seed"],
                               "evaluations": row["evaluations"], "qd_score": row["qd_score"],
                               "coverage": row["coverage"], "best": row["best"]})
    return points


REF_FIELDS = ["study", "config", "seed", "raw_fitness", "duty_factors"]
MATCH_FIELDS = ["me_study", "config", "seed", "ref_study", "ref_seed", "ref_fitness", "ref_cell", "elite_fitness"]
BINS = 5   # per foot, as both MAP-Elites sweeps use (MapElites.bins)


def cic_csv(*args):
    out = subprocess.run([CIC, *map(str, args)], capture_output=True, text=True)
    if out.returncode != 0:
        fail(f"cic {' '.join(map(str, args))}: {out.stderr.strip()}")
    return list(csv.DictReader(out.stdout.splitlines()))


def best_ever_input(run):
    """What scripts/baselines.sh replays for a run's best_ever: HyperGP without
    elitism may lose it, so the checkpoint of the first generation that reached
    it (RUN/populations/gen-NNNN.xml) when kept, else the run folder."""
    best, generation = None, None
    for row in read_csv(run / "stats.csv"):
        if best is None or float(row["best"]) > best:
            best, generation = float(row["best"]), int(row["generation"])
    file = run / "populations" / f"gen-{generation:04d}.xml"
    return file if generation is not None and file.exists() else run


def found_refs():
    rows = []
    for study in PLAIN_OF:
        index = BASELINES / study / "index.csv"
        if not index.exists():
            continue
        for r in read_csv(index):
            if r["status"] != "done":
                continue
            a = cic_csv("assess", best_ever_input(BASELINES / study / r["run_dir"]))[0]
            duty = " ".join(part.rsplit(":", 1)[1] for part in a["duty_factors"].split())
            rows.append({"study": study, "config": r["config"], "seed": r["seed"], "raw_fitness": a["raw_fitness"],
                         "duty_factors": duty})
    return rows


def cell_of(duty):
    return ",".join(str(min(BINS - 1, max(0, math.floor(float(v) * BINS)))) for v in duty.split())


def found_matches(me_rows, refs):
    rows = []
    for r in me_rows:
        elites = {e["cell"]: e["fitness"] for e in cic_csv("export", STUDIES / r["study"] / r["run_dir"])}
        for ref in refs:
            if ref["config"] != r["config"]:
                continue
            cell = cell_of(ref["duty_factors"])
            rows.append({"me_study": r["study"], "config": r["config"], "seed": r["seed"], "ref_study": ref["study"],
                         "ref_seed": ref["seed"], "ref_fitness": ref["raw_fitness"], "ref_cell": cell,
                         "elite_fitness": elites.get(cell, "")})
    return rows


def ledger():
    me = found_rows(STUDIES)
    merge(RESULTS / "qd-runs.csv", FIELDS, lambda r: (r["study"], r["config"], int(r["seed"]), r["run_dir"]), me)
    refs = merge(RESULTS / "qd-refs.csv", REF_FIELDS, lambda r: (r["study"], r["config"], int(r["seed"])),
                 found_refs())
    merge(RESULTS / "qd-cellmatch.csv", MATCH_FIELDS,
          lambda r: (r["me_study"], r["config"], int(r["seed"]), r["ref_study"], int(r["ref_seed"])),
          found_matches(me, refs))
    merge(RESULTS / "qd-curve-points.csv", CURVE_FIELDS,
          lambda r: (r["study"], r["config"], int(r["seed"]), int(r["evaluations"])), found_curve_points(STUDIES))


def median_iqr(v, digits=2):
    if not v:
        return "–"
    q1, q3 = quartiles(v)
    return f"{st.median(v):.{digits}f} [{q1:.{digits}f}, {q3:.{digits}f}]"


def verdict(p, a, first, second, n):
    if p is None:
        return "no scipy"
    if p >= 0.05:
        return f"no difference shown at n = {n}"
    return f"{first} higher" if a > 0.5 else f"{second} higher"


def open_note(nx, ny):
    """A test of an arm with fewer runs than the design's: its verdict may still change."""
    short = min(nx, ny)
    return f" (open: {short} of {SEEDS} runs)" if short < SEEDS else ""


def ledger_status(counts):
    """One line: how many of the design's runs each robot and method has, and which arms are open.
    counts: {(robot, label): n}."""
    robots = sorted({robot for robot, _ in counts})
    parts = [f"{robot}: " + ", ".join(f"{label} {n}" for (r, label), n in counts.items() if r == robot)
             for robot in robots]
    open_arms = [f"{label} on {robot} ({n} of {SEEDS})" for (robot, label), n in counts.items() if n < SEEDS]
    line = f"Runs in the ledger, of {SEEDS} seeds per robot and method: " + "; ".join(parts) + "."
    if open_arms:
        line += " Open (their tests may still change): " + ", ".join(open_arms) + "."
    else:
        line += " Every arm is complete."
    return line


def compare():
    me = read_csv(RESULTS / "qd-runs.csv") if (RESULTS / "qd-runs.csv").exists() else []
    plain = read_csv(WALK_LEDGER) if WALK_LEDGER.exists() else []
    def values(study, config, column, source):
        return [float(r[column]) for r in source if r["study"] == study and r["config"] == config and r[column]]
    robots = sorted({r["config"] for r in me})
    counts = {}
    for robot in robots:
        for study, label in list(STUDIES_OF.items()) + list(PLAIN_OF.items()):
            n = len(values(study, robot, "qd_score", me) if study in STUDIES_OF else
                    values(study, robot, "raw_fitness", plain))
            if n:
                counts[(robot, label)] = n
    print(ledger_status(counts))
    print()
    print("| robot | method | n | evaluations | QD-score | coverage | cells filled | best elite [m] |")
    print("|---|---|---|---|---|---|---|---|")
    for robot in robots:
        for study, label in STUDIES_OF.items():
            qd = values(study, robot, "qd_score", me)
            if not qd:
                continue
            ev = sorted({int(float(e)) for e in values(study, robot, "evaluations", me)})
            print(f"| {robot} | {label} | {len(qd)} | {', '.join(map(str, ev))} | {median_iqr(qd, 0)} | "
                  f"{median_iqr(values(study, robot, 'coverage', me), 3)} | "
                  f"{median_iqr(values(study, robot, 'filled', me), 0)} | {median_iqr(values(study, robot, 'best', me))} |")
        for study, label in PLAIN_OF.items():
            best = values(study, robot, "raw_fitness", plain)
            if best:
                ev = values(study, robot, "evaluations", plain)
                span = f"{int(min(ev))}–{int(max(ev))}" if ev else "not recorded"
                print(f"| {robot} | {label} | {len(best)} | {span} | – | – | – | {median_iqr(best)} |")
    print()
    tests = []   # (robot, what, first label, x, second label, y)
    for robot in robots:
        for column, what in (("qd_score", "QD-score"), ("coverage", "coverage")):
            for first, second in (("me-hgp-15000", "me-gait-15000"), ("me-cmame-15000", "me-gait-15000")):
                tests.append((robot, what, STUDIES_OF[first], values(first, robot, column, me),
                              STUDIES_OF[second], values(second, robot, column, me)))
        tests.append((robot, "best", STUDIES_OF["me-cmame-15000"], values("me-cmame-15000", robot, "best", me),
                      STUDIES_OF["me-gait-15000"], values("me-gait-15000", robot, "best", me)))
        for me_study, plain_study in (("me-hgp-15000", "walk-15000-hgp-gait"), ("me-gait-15000", "walk-15000-cmaes-gait"),
                                      ("me-hgp-15000", "walk-15000-cmaes-gait"),
                                      ("me-cmame-15000", "walk-15000-cmaes-gait")):
            tests.append((robot, "best", STUDIES_OF[me_study], values(me_study, robot, "best", me),
                          PLAIN_OF[plain_study], values(plain_study, robot, "raw_fitness", plain)))
    tests = [t for t in tests if len(t[3]) >= 2 and len(t[5]) >= 2]
    ps = [mann_whitney_p(t[3], t[5]) for t in tests]
    adjusted = holm(ps)
    print("| robot | measure | method | median | against | median | n | p | p (Holm) | A12 [95% CI] | verdict |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for (robot, what, la, x, lb, y), p, ph in zip(tests, ps, adjusted):
        a = a12(x, y)
        lo, hi = a12_interval(x, y)
        digits = 3 if what == "coverage" else 2
        print(f"| {robot} | {what} | {la} | {st.median(x):.{digits}f} | {lb} | {st.median(y):.{digits}f} | "
              f"{len(x)} vs {len(y)} | {p:.3g} | {ph:.3g} | {a:.2f} [{lo:.2f}, {hi:.2f}] | "
              f"{verdict(ph, a, la, lb, f'{len(x)} vs {len(y)}' if len(x) != len(y) else len(x))}"
              f"{open_note(len(x), len(y))} |" if p is not None else f"| {robot} | {what} | {la} | | {lb} | | | | | | no scipy |")
    print()
    print(f"{len(tests)} tests; Holm over all of them. A12 = P(first method's run > second's).")
    cellmatch()
    growth(read_csv(RESULTS / "qd-curve-points.csv") if (RESULTS / "qd-curve-points.csv").exists() else [])


def growth(points, last=5000):
    """Are the archives still filling at the budget? Per robot and method, over the runs in the curve
    ledger: the share of the final QD-score reached `last` evaluations before the end, and the
    coverage and best elite then and at the end."""
    runs = {}
    for r in points:
        runs.setdefault((r["study"], r["config"], r["seed"]), {})[int(r["evaluations"])] = r
    table = {}
    for (study, robot, _), pts in runs.items():
        end = max(pts)
        if study not in STUDIES_OF or end - last not in pts:
            continue
        a, b = pts[end - last], pts[end]
        t = table.setdefault((robot, study), {"share": [], "cov0": [], "cov1": [], "best0": [], "best1": [], "end": end})
        t["share"].append(float(a["qd_score"]) / float(b["qd_score"]))
        t["cov0"].append(float(a["coverage"]))
        t["cov1"].append(float(b["coverage"]))
        t["best0"].append(float(a["best"]))
        t["best1"].append(float(b["best"]))
    if not table:
        return
    print()
    print(f"Still filling at the budget? The last {last:,} evaluations of each run in results/qd-curve-points.csv "
          "(the runs whose folders a sitting had at hand; medians [IQR]).")
    print()
    print("| robot | method | runs | QD-score reached before them | coverage before | coverage at the end | "
          "best before [m] | best at the end [m] |")
    print("|---|---|---|---|---|---|---|---|")
    for robot, study in sorted(table, key=lambda k: (k[0], list(STUDIES_OF).index(k[1]))):
        t = table[(robot, study)]
        print(f"| {robot} | {STUDIES_OF[study]} | {len(t['share'])} | {median_iqr(t['share'])} | "
              f"{median_iqr(t['cov0'], 3)} | {median_iqr(t['cov1'], 3)} | {median_iqr(t['best0'])} | "
              f"{median_iqr(t['best1'])} |")


def cellmatch():
    path = RESULTS / "qd-cellmatch.csv"
    rows = read_csv(path) if path.exists() else []
    if not rows:
        return
    print()
    print("Where the references walk: the cell of each plain run's best gait (its feet's duty factors), and the elite "
          "each MAP-Elites archive of the same robot holds there.")
    print()
    print("| robot | archive | reference | pairs | cells filled | reference best [m] | elite there [m] | "
          "elite / reference |")
    print("|---|---|---|---|---|---|---|---|")
    for robot in sorted({r["config"] for r in rows}):
        for me_study, me_label in STUDIES_OF.items():
            for ref_study, ref_label in PLAIN_OF.items():
                pairs = [r for r in rows if r["config"] == robot and r["me_study"] == me_study
                         and r["ref_study"] == ref_study]
                if not pairs:
                    continue
                filled = [r for r in pairs if r["elite_fitness"]]
                refs = [float(r["ref_fitness"]) for r in pairs]
                there = [float(r["elite_fitness"]) for r in filled]
                ratio = [float(r["elite_fitness"]) / float(r["ref_fitness"]) for r in filled
                         if float(r["ref_fitness"]) > 0]
                n_me = len({r["seed"] for r in pairs})
                n_ref = len({r["ref_seed"] for r in pairs})
                print(f"| {robot} | {me_label} ({n_me} runs) | {ref_label} ({n_ref} runs) | {len(pairs)} | "
                      f"{len(filled)} ({len(filled) / len(pairs):.0%}) | {median_iqr(refs)} | {median_iqr(there)} | "
                      f"{median_iqr(ratio)} |")
    print()
    print("Medians [IQR] over the pairs; the elite column over the filled ones.")


def curve_series(points):
    """(study, robot) -> {evaluations: {column: [values over runs]}}, from the curve ledger's rows."""
    series = {}
    for row in points:
        if row["study"] not in STUDIES_OF:
            continue
        cell = series.setdefault((row["study"], row["config"]), {}).setdefault(int(row["evaluations"]), {})
        for column in ("qd_score", "coverage"):
            cell.setdefault(column, []).append(float(row[column]))
    return series


def curves():
    import shutil
    import tempfile
    series = curve_series(read_csv(RESULTS / "qd-curve-points.csv") if (RESULTS / "qd-curve-points.csv").exists()
                          else [])
    if not series:
        fail(f"no curve points in {RESULTS / 'qd-curve-points.csv'} (run the ledger stage first)")
    robots = sorted({robot for _, robot in series})
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="qd-curves-"))
    plots = []
    colours = {"me-hgp-15000": "#d62728", "me-gait-15000": "#1f77b4", "me-cmame-15000": "#2ca02c"}
    for robot in robots:
        for column, label in (("qd_score", "QD-score (offset -1)"), ("coverage", "coverage (share of 625 cells)")):
            lines = []
            for study in STUDIES_OF:
                data = series.get((study, robot))
                if not data:
                    continue
                f = tmp / f"{study}-{robot}-{column}.dat"
                with open(f, "w") as out:
                    for ev in sorted(data):
                        v = data[ev][column]
                        q1, q3 = quartiles(v)
                        out.write(f"{ev} {st.median(v)} {q1} {q3}\n")
                n = len(data[max(data)][column])
                lines.append(f"'{f}' using 1:3:4 with filledcurves lc rgb '{colours[study]}' fs transparent solid 0.2 "
                             f"notitle, '{f}' using 1:2 with lines lw 2 lc rgb '{colours[study]}' "
                             f"title '{STUDIES_OF[study]} (n = {n})'")
            plots.append(f"set title '{robot}: {label}'\nplot " + ", ".join(lines))
    out_file = RESULTS / "qd-curves.svg"
    script = (f"set terminal svg size 1000,{330 * len(robots)} dynamic noenhanced font 'Sans,12' background rgb 'white'\n"
              f"set output '{out_file}'\nset multiplot layout {len(robots)},2\nset grid\nset key bottom right\n"
              "set xlabel 'evaluations'\n" + "\n".join(plots) + "\nunset multiplot\n")
    (tmp / "plot.gp").write_text(script)
    done = subprocess.run(["gnuplot", str(tmp / "plot.gp")], capture_output=True, text=True)
    shutil.rmtree(tmp)
    if done.returncode != 0:
        fail(f"gnuplot: {done.stderr.strip()}")
    print(f"qd-report.py: wrote {out_file}", file=sys.stderr)


def cells(run):
    out = subprocess.run([CIC, "export", str(run)], capture_output=True, text=True)
    if out.returncode != 0:
        fail(f"cic export {run}: {out.stderr.strip()}")
    rows = list(csv.DictReader(out.stdout.splitlines()))
    if not rows:
        fail(f"{run}: the archive holds no elite")
    for r in rows:
        r["d"] = [float(v) for v in r["descriptor"].split()]
        r["f"] = float(r["fitness"])
    best = max(rows, key=lambda r: r["f"])
    pool = [r for r in rows if r["f"] >= 0.5 * best["f"]]
    chosen = [best]
    while len(chosen) < min(4, len(pool)):
        far = max((r for r in pool if r not in chosen),
                  key=lambda r: min(sum((a - b) ** 2 for a, b in zip(r["d"], c["d"])) for c in chosen))
        chosen.append(far)
    for r in chosen:
        print(f"{r['cell']}\t{r['f']:.2f}\t{' '.join(f'{v:.2f}' for v in r['d'])}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--studies", default="runs/quality-diversity")
    parser.add_argument("--baselines", default="runs/baselines")
    parser.add_argument("--results", default="experiments/quality-diversity/results")
    parser.add_argument("--walk-ledger", default="experiments/baselines/results/walk-runs.csv")
    parser.add_argument("--cic", default="build/cic")
    parser.add_argument("stage", choices=["ledger", "compare", "curves", "cells"])
    parser.add_argument("run", nargs="?")
    args = parser.parse_args()
    STUDIES, RESULTS, BASELINES = pathlib.Path(args.studies), pathlib.Path(args.results), pathlib.Path(args.baselines)
    WALK_LEDGER, CIC = pathlib.Path(args.walk_ledger), args.cic
    if args.stage == "ledger":
        ledger()
    elif args.stage == "compare":
        compare()
    elif args.stage == "curves":
        curves()
    else:
        if not args.run:
            fail("cells needs a MAP-Elites run folder")
        cells(pathlib.Path(args.run))
