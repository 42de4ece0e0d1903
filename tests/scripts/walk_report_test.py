#!/usr/bin/env python3
"""Scripts.WalkReportLedger: scripts/walk-report.py keeps the comparison's runs
across sittings (results/walk-runs.csv): a run whose folder is gone keeps its
row, a run found again replaces its row, a new run is added, compare reads the
merged rows, and a broken ledger is refused with FILE:LINE and exit 2.

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

# A ledger cell that is not a number: FILE:LINE, exit 2, nothing rewritten.
text = (results / "walk-runs.csv").read_text()
(results / "walk-runs.csv").write_text(text.replace(",9.5,", ",nine,", 1))
r = run("ledger")
check(r.returncode == 2, f"a broken ledger was accepted: {r.returncode}")
check(f"{results / 'walk-runs.csv'}:" in r.stderr and "best_ever" in r.stderr, f"message: {r.stderr}")
check("nine" in (results / "walk-runs.csv").read_text(), "a refused ledger was rewritten")
shutil.rmtree(work)
print("walk_report_test: ok")
