#!/usr/bin/env python3
"""Scripts.QdReportCellsAndLedgers: scripts/qd-report.py bins a duty factor as
the archive does (gp::GridSpec::cell_of: floor(v * 5), clamped), keeps a
ledger's rows whose run folders are gone while a row found again replaces its
own, replays a run's best_ever from the checkpoint of the first generation
that reached it, and tabulates where the references walk.

    qd_report_test.py SOURCE_DIR WORK_DIR
"""
import contextlib
import importlib.util
import io
import pathlib
import shutil
import sys

source, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
sys.path.insert(0, str(source / "scripts"))
spec = importlib.util.spec_from_file_location("qd_report", source / "scripts" / "qd-report.py")
qd = importlib.util.module_from_spec(spec)
spec.loader.exec_module(qd)
qd.RESULTS = work / "results"


def check(condition, message):
    if not condition:
        print(f"qd_report_test: {message}", file=sys.stderr)
        sys.exit(1)


# Bins: the archive's floor(v * 5), the edges clamped into the grid.
check(qd.cell_of("0.195 0.400 0.999 1.000") == "0,2,4,4", f"cell_of: {qd.cell_of('0.195 0.400 0.999 1.000')}")
check(qd.cell_of("0.000 0.199 0.200 -0.100") == "0,0,1,0", "cell_of at the lower edges")

# Ledgers: rows of folders gone stay, a row found again replaces its own, the order is by key.
key = lambda r: (r["study"], r["config"], int(r["seed"]))
with contextlib.redirect_stderr(io.StringIO()):
    qd.merge(qd.RESULTS / "refs.csv", qd.REF_FIELDS, key,
             [{"study": "s", "config": "R1", "seed": "2", "raw_fitness": "5", "duty_factors": "0.1 0.2"},
              {"study": "s", "config": "R1", "seed": "10", "raw_fitness": "7", "duty_factors": "0.3 0.4"}])
    rows = qd.merge(qd.RESULTS / "refs.csv", qd.REF_FIELDS, key,
                    [{"study": "s", "config": "R1", "seed": "2", "raw_fitness": "6", "duty_factors": "0.5 0.6"},
                     {"study": "s", "config": "R1", "seed": "1", "raw_fitness": "4", "duty_factors": "0.7 0.8"}])
on_disk = qd.read_csv(qd.RESULTS / "refs.csv")
check([r["seed"] for r in on_disk] == ["1", "2", "10"], f"ledger order: {[r['seed'] for r in on_disk]}")
check([r["raw_fitness"] for r in on_disk] == ["4", "6", "7"], "a row found again replaces its own, the others stay")
check(len(rows) == 3 and not (qd.RESULTS / "refs.csv.tmp").exists(), "merge returns the rows and leaves no temp file")

# best_ever: the first generation that reached the best, its checkpoint when kept.
run = work / "run"
(run / "populations").mkdir(parents=True)
(run / "stats.csv").write_text("generation,best\n0,1.5\n1,3.25\n2,3.25\n3,2.0\n")
check(qd.best_ever_input(run) == run, "no checkpoint kept: the run folder")
(run / "populations" / "gen-0001.xml").write_text("<population/>")
check(qd.best_ever_input(run) == run / "populations" / "gen-0001.xml", "the first generation that reached the best")

# Where the references walk: pairs, cells filled, and the elite against the reference.
(qd.RESULTS / "qd-cellmatch.csv").write_text(
    ",".join(qd.MATCH_FIELDS) + "\n"
    "me-gait-15000,R1,1,walk-15000-cmaes-gait,1,30,\"1,1,1,1\",6\n"
    "me-gait-15000,R1,1,walk-15000-cmaes-gait,2,20,\"0,1,1,1\",\n"
    "me-gait-15000,R1,2,walk-15000-cmaes-gait,1,30,\"1,1,1,1\",12\n")
out = io.StringIO()
with contextlib.redirect_stdout(out):
    qd.cellmatch()
table = out.getvalue()
want = "| R1 | MAP-Elites, gait vector (2 runs) | CMA-ES gait, IPOP (2 runs) | 3 | 2 (67%) | 30.00 [25.00, 30.00] | 9.00"
check(want in table, f"cellmatch table:\n{table}")
# The curve ledger: a finished run's points every 500 evaluations and its last; a run not done gives none.
study = work / "studies" / "me-gait-15000"
for seed, status in ((1, "done"), (2, "running")):
    folder = study / "runs" / "R1" / f"s{seed}"
    folder.mkdir(parents=True)
    (folder / "stats.csv").write_text("generation,best,evaluations,qd_score,coverage,filled\n" + "".join(
        f"{g},{g + 1},{(g + 1) * 250},{10 * (g + 1)},{0.1 * (g + 1):.1f},{g + 1}\n" for g in range(5)))
(study / "index.csv").write_text("run_dir,config,seed,status,wall_seconds\nruns/R1/s1,R1,1,done,9.5\n"
                                 "runs/R1/s2,R1,2,running,1.0\n")
points = qd.found_curve_points(work / "studies")
check([(p["seed"], p["evaluations"]) for p in points] == [("1", "500"), ("1", "1000"), ("1", "1250")],
      f"curve points: {[(p['seed'], p['evaluations']) for p in points]}")
check([(r["seed"], r["batches"], r["qd_score"]) for r in qd.found_rows(work / "studies")] == [("1", 5, "50")],
      "the run ledger takes a finished run's last row")
series = qd.curve_series(points)
check(series[("me-gait-15000", "R1")][1250] == {"qd_score": [50.0], "coverage": [0.5]}, f"curve series: {series}")

# Still filling: the run above at 750 evaluations (500 before its end at 1,250) against its end.
out = io.StringIO()
with contextlib.redirect_stdout(out):
    qd.growth(qd.found_curve_points(work / "studies") + [
        {"study": "me-gait-15000", "config": "R1", "seed": "1", "evaluations": "750", "qd_score": "30",
         "coverage": "0.3", "best": "3"}], last=500)
want = "| R1 | MAP-Elites, gait vector | 1 | 0.60 [0.60, 0.60] | 0.300 [0.300, 0.300] | 0.500 [0.500, 0.500] |"
check(want in out.getvalue(), f"growth table:\n{out.getvalue()}")

# Open arms: fewer runs than the design's 10 are named, in the status line and on their tests.
status = qd.ledger_status({("R1", "A"): 10, ("R1", "B"): 3, ("R2", "A"): 10})
check("R1: A 10, B 3; R2: A 10." in status and "Open (their tests may still change): B on R1 (3 of 10)." in status,
      f"ledger status: {status}")
check(qd.ledger_status({("R1", "A"): 10}).endswith("Every arm is complete."), "a complete ledger")
check(qd.open_note(10, 3) == " (open: 3 of 10 runs)" and qd.open_note(10, 10) == "", "open note")

print("qd_report_test: ok")
