#!/usr/bin/env python3
"""Scripts.WalkReportLedger: scripts/walk-report.py keeps the comparison's runs
across sittings (results/walk-runs.csv): a run whose folder is gone keeps its
row, a run found again replaces its row, a new run is added, compare reads the
merged rows, and a broken ledger is refused with FILE:LINE and exit 2; winners
replaces HyperGP's old best only with a method that beats it after Holm, at the
largest budget where every method has 10 runs; compare reads nothing from a
cell until every method of its budget has its 10 runs there.

    walk_report_test.py SOURCE_DIR WORK_DIR
"""
import csv
import pathlib
import shutil
import subprocess
import sys

source, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
script = source / "scripts" / "walk-report.py"
shutil.rmtree(work, ignore_errors=True)
studies, results = work / "studies", work / "results"
results.mkdir(parents=True)
FIELDS = ["study", "run_dir", "config", "seed", "best_ever", "evaluations", "wall_seconds", "fitness", "dominant_hz",
          "mean_height", "min_height", "final_up", "flipped", "shaking", "raw_fitness"]


def check(condition, message):
    if not condition:
        print(f"walk_report_test: {message}", file=sys.stderr)
        sys.exit(1)


def run(*args):
    return subprocess.run([sys.executable, str(script), "--studies", str(studies), "--results", str(results), *args],
                          capture_output=True, text=True)


def ledger():
    with open(results / "walk-runs.csv", newline="") as f:
        return {(r["study"], r["run_dir"]): r for r in csv.DictReader(f)}


# An earlier sitting's rows: R1 seeds 1 and 2 of HyperGP's best; seed 2 will be found again.
with open(results / "walk-runs.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=FIELDS, lineterminator="\n")
    w.writeheader()
    for seed, best in ((1, "9.5"), (2, "1.0")):
        w.writerow({"study": "walk-2500-hgp-best", "run_dir": f"runs/R1/s{seed}", "config": "R1", "seed": seed,
                    "best_ever": best, "evaluations": "", "wall_seconds": "", "fitness": best, "dominant_hz": "1.0",
                    "mean_height": "0.8", "min_height": "0.5", "final_up": "1", "flipped": "0", "shaking": "0",
                    "raw_fitness": best})

# This sitting: the study folder holds seed 2 (again, better assessed) and seed 3 (new); seed 1's folder is gone.
study = studies / "walk-2500-hgp-best"
(study / "summary").mkdir(parents=True)
with open(study / "index.csv", "w") as f:
    f.write("run_dir,config,seed,status,final_best,generations,evaluations,wall_seconds,best_ever,commit\n")
    f.write("runs/R1/s2,R1,2,done,8,50,2500,100.5,8.25,abc\n")
    f.write("runs/R1/s3,R1,3,done,7,50,2480,99.0,7.5,abc\n")
    f.write("runs/R1/s4,R1,4,running,,,,,,\n")
with open(study / "summary" / "walk-2500-hgp-best-gaits.csv", "w") as f:
    f.write("input,fitness,dominant_hz,mean_height,min_height,final_up,flipped,shaking,raw_fitness\n")
    f.write(f"{study}/runs/R1/s2/populations/gen-0040.xml,8.25,1.00,0.8,0.5,1,0,0,8.0\n")

r = run("ledger")
check(r.returncode == 0, f"ledger failed: {r.stderr}")
rows = ledger()
check(set(rows) == {("walk-2500-hgp-best", f"runs/R1/s{s}") for s in (1, 2, 3)}, f"rows: {sorted(rows)}")
check(rows[("walk-2500-hgp-best", "runs/R1/s1")]["best_ever"] == "9.5", "a run whose folder is gone lost its row")
s2 = rows[("walk-2500-hgp-best", "runs/R1/s2")]
check(s2["best_ever"] == "8.25" and s2["raw_fitness"] == "8.0" and s2["evaluations"] == "2500",
      f"a run found again did not replace its row: {s2}")
check(rows[("walk-2500-hgp-best", "runs/R1/s3")]["raw_fitness"] == "", "an unassessed run got a score")

r = run("compare")
check(r.returncode == 0, f"compare failed: {r.stderr}")
# R1: 9.5 (raw), 8.0 (raw), 7.5 (best_ever, not assessed: *); median 8.0.
check("| R1 | HyperGP, best configuration | 3 | 8.00* |" in r.stdout, f"compare table:\n{r.stdout}")
check("2480–2500 (1 not recorded)" in r.stdout, f"evaluations:\n{r.stdout}")

# best: the run whose gait compare describes (highest score, by raw eq. 7.1 where assessed).
r = run("best")
check(r.returncode == 0 and r.stdout == "walk-2500-hgp-best,R1,runs/R1/s1,9.5\n", f"best: {r.stdout!r} {r.stderr}")

# A ledger cell that is not a number: FILE:LINE, exit 2, nothing rewritten.
text = (results / "walk-runs.csv").read_text()
(results / "walk-runs.csv").write_text(text.replace(",9.5,", ",nine,", 1))
r = run("ledger")
check(r.returncode == 2, f"a broken ledger was accepted: {r.returncode}")
check(f"{results / 'walk-runs.csv'}:" in r.stderr and "best_ever" in r.stderr, f"message: {r.stderr}")
check("nine" in (results / "walk-runs.csv").read_text(), "a refused ledger was rewritten")
# winners: a ledger of its own. R0: HyperGP-gait far ahead (replaces the old best in both
# files); R1: CMA-ES's median higher but not shown better (the old best stays); R2: the
# 15,000 cell lacks a run, so 2,500 decides, where CMA-ES is far ahead.
shutil.rmtree(studies)
with open(results / "walk-runs.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=FIELDS, lineterminator="\n")
    w.writeheader()
    cells = [("walk-2500-hgp-best", "R0", range(10)), ("walk-2500-hgp-gait", "R0", range(20, 30)),
             ("walk-2500-cmaes-gait", "R0", range(5, 15)),
             ("walk-2500-hgp-best", "R1", range(10)), ("walk-2500-cmaes-gait", "R1", range(1, 11)),
             ("walk-2500-hgp-best", "R2", range(10)), ("walk-2500-cmaes-gait", "R2", range(40, 50)),
             ("walk-15000-hgp-best", "R2", range(9)), ("walk-15000-cmaes-gait", "R2", range(10))]
    for study_name, robot, scores in cells:
        for seed, score in enumerate(scores, 1):
            w.writerow({"study": study_name, "run_dir": f"runs/{robot}/s{seed}", "config": robot, "seed": seed,
                        "best_ever": score, "evaluations": "", "wall_seconds": "", "fitness": score,
                        "dominant_hz": "1.0", "mean_height": "0.8", "min_height": "0.5", "final_up": "1",
                        "flipped": "0", "shaking": "0", "raw_fitness": score})
r = run("winners")
try:
    import scipy  # noqa: F401
except ImportError:   # no p-values, no winners: refused plainly, nothing written
    check(r.returncode == 2 and "scipy" in r.stderr, f"winners without scipy: {r.returncode} {r.stderr}")
    check(not (results / "walk-winners.csv").exists(), "winners without scipy wrote its CSV")
    shutil.rmtree(work)
    print("walk_report_test: ok (winners' rule not checked: no scipy)")
    sys.exit(0)
check(r.returncode == 0, f"winners failed: {r.stderr}")
with open(results / "walk-winners.csv", newline="") as f:
    won = {row["file"]: (row["study"], row["config"]) for row in csv.DictReader(f)}
check(won == {"settings/r0_best.xml": ("walk-2500-hgp-gait", "R0"),
              "settings/r0_best_hypergp.xml": ("walk-2500-hgp-gait", "R0"),
              "settings/r1_best.xml": ("walk-2500-hgp-best", "R1"),
              "settings/r1_best_hypergp.xml": ("walk-2500-hgp-best", "R1"),
              "settings/r2_best.xml": ("walk-2500-cmaes-gait", "R2"),
              "settings/r2_best_hypergp.xml": ("walk-2500-hgp-best", "R2")}, f"winners: {won}\n{r.stdout}")
# compare on the same ledger: a cell is open until every method run at its budget has its
# 10 runs there (R1 and R2 at 2,500 lack HyperGP-gait; R2 at 15,000 lacks a run).
r = run("compare")
check(r.returncode == 0, f"compare failed: {r.stderr}")
check("- 2,500, R0: met by HyperGP-gait" in r.stdout, f"R0's cell:\n{r.stdout}")
check("- 2,500, R1: open, 20 of 30 runs (CMA-ES gait, IPOP 10, HyperGP, best configuration 10, HyperGP-gait 0)"
      in r.stdout, f"R1's open cell:\n{r.stdout}")
check("- 15,000, R2: open, 19 of 20 runs (CMA-ES gait, IPOP 10, HyperGP, best configuration 9)" in r.stdout,
      f"R2's open cell:\n{r.stdout}")
check("| R2 | HyperGP, best configuration | 4.00 | CMA-ES gait, IPOP | 4.50 |" in r.stdout and
      "cell open: n = 9 so far |" in r.stdout, f"an open cell's test was read:\n{r.stdout}")
check("The goal is open" in r.stdout, f"goal line:\n{r.stdout}")
shutil.rmtree(work)
print("walk_report_test: ok")
