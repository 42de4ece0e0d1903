#!/usr/bin/env python3
"""Scripts.ScalingReportLedgerAndEstimate: scripts/scaling-report.py merges a
study's index.csv into the ledger, keeps a finished run whose folder is gone
(while the index gives it the same run key; an index of other settings replaces it, and so
does a folder that is there and ended otherwise; a rerun of the same run key under way does not), keeps a run that left the sweep file as superseded (counted nowhere),
lets a row found again replace its own, names the winner by median best_ever,
and multiplies the plan out from seconds per evaluation.

    scaling_report_test.py SOURCE_DIR WORK_DIR
"""
import csv
import importlib.util
import io
import pathlib
import shutil
import sys

source, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
(work / "studies" / "tune-direct-c8").mkdir(parents=True)
(work / "results").mkdir()
spec = importlib.util.spec_from_file_location("scaling_report", source / "scripts" / "scaling-report.py")
sr = importlib.util.module_from_spec(spec)
spec.loader.exec_module(sr)


def check(condition, message):
    if not condition:
        print(f"scaling_report_test: {message}", file=sys.stderr)
        sys.exit(1)


HEADER = "run_dir,config,Gait.optimizer,seed,status,final_best,generations,evaluations,wall_seconds,best_ever,commit,run_key\n"


def merge():
    """Merge the index into the ledger: (finished runs, the ledger's rows by (config, seed))."""
    n = sr.ledger(str(work / "studies"), str(work / "results"), ["tune-direct-c8"])
    return n, {(r["config"], r["seed"]): r for r in csv.DictReader(open(work / "results" / "scaling-runs.csv"))}


def index(rows, keys=None):
    """Rows (config, seed, status, best, wall); each run's key is k<config><seed> unless keys says otherwise."""
    keys = keys or {}
    text = HEADER + "".join(
        f"runs/{c}/s{s},{c},x,{s},{st},{b},10,2500,{w},{b},abc,{keys.get((c, s), f'k{c}{s}')}\n" for c, s, st, b, w in rows)
    (work / "studies" / "tune-direct-c8" / "index.csv").write_text(text)


index([("a", 101, "done", 3.0, 100.0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.0, 50.0),
       ("b", 102, "pending", "", 0)])
n, rows = merge()
check(n == 3, f"3 finished runs expected, got {n}")
# A later sitting: a's s101 folder is gone (pending again), b's s102 finished, b's s101 found again, changed.
index([("a", 101, "pending", "", 0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)])
n, rows = merge()
check(n == 4, f"4 finished runs expected, got {n}")
check(rows[("a", "101")]["best_ever"] == "3.0", "a finished run whose folder is gone keeps its row")
check(rows[("b", "101")]["best_ever"] == "4.5", "a run found again replaces its row")
# A configuration that left the sweep file (cic sweep leaves it out of index.csv): its rows are
# kept as superseded and no longer count; listed again, it counts again.
index([("a", 101, "pending", "", 0), ("a", 102, "done", 5.0, 100.0)])
n, rows = merge()
check(n == 2 and rows[("b", "101")]["status"] == "superseded" and rows[("b", "101")]["best_ever"] == "4.5",
      f"b left the sweep: kept, superseded, not counted ({n}, {rows[('b', '101')]})")
check(rows[("a", "101")]["status"] == "done", "a run whose folder is gone is still not superseded")
index([("a", 101, "pending", "", 0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)])
n, rows = merge()
check(n == 4, f"b back in the sweep: its runs count again, 4 expected, got {n}")
# The sweep was edited: a's s101 is now a run of other settings (another key), still to do.
# The done row of the old settings proves nothing about it and gives way; with the old key back, nothing changes.
index([("a", 101, "pending", "", 0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)], keys={("a", 101): "kother"})
n, rows = merge()
check(n == 3 and rows[("a", "101")]["status"] == "pending" and rows[("a", "101")]["run_key"] == "kother",
      f"a done row of other settings is kept ({n}, {rows[('a', '101')]})")
check(rows[("a", "102")]["run_key"] == "ka102", f"the ledger keeps the run key: {rows[('a', '102')]}")
index([("a", 101, "done", 3.0, 100.0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)])
n, rows = merge()
check(n == 4, f"a's s101 of the first settings, found again: 4 expected, got {n}")
# An index of a cic older than run keys (no run_key column) says nothing of the settings: a done
# row whose folder is gone stays.
index([("a", 101, "pending", "", 0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)])
path = work / "studies" / "tune-direct-c8" / "index.csv"
path.write_text("\n".join(line.rsplit(",", 1)[0] for line in path.read_text().splitlines()) + "\n")
check(path.read_text().startswith("run_dir,config,Gait.optimizer,seed,status,final_best,generations,evaluations,"
                                  "wall_seconds,best_ever,commit\n"), path.read_text())
n, rows = merge()
check(n == 4 and rows[("a", "101")]["status"] == "done",
      f"an older cic's index dropped a done row ({n}, {rows[('a', '101')]})")
# The same run being rerun (scaling.sh posture-runs brings back a gone folder): while it runs, the
# done row stands; one seed fixes a run, and the rerun's row replaces it when it ends.
index([("a", 101, "running", "", 0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)])
n, rows = merge()
check(n == 4 and rows[("a", "101")]["status"] == "done" and rows[("a", "101")]["best_ever"] == "3.0",
      f"a rerun under way took its run's done row ({n}, {rows[('a', '101')]})")
# A done row whose folder is there and says interrupted was never done (cic before the run loop's
# status line read a Switch-HybrID run stopped in its gait phase as done): the index's row wins.
index([("a", 101, "interrupted", 2.0, 40.0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)])
n, rows = merge()
check(n == 3 and rows[("a", "101")]["status"] == "interrupted",
      f"an interrupted folder kept its wrong done row ({n}, {rows[('a', '101')]})")
index([("a", 101, "done", 3.0, 100.0), ("a", 102, "done", 5.0, 100.0), ("b", 101, "done", 4.5, 50.0),
       ("b", 102, "done", 6.0, 50.0)])
merge()
sr.summary(str(work / "results"))
md = (work / "results" / "tune-direct.md").read_text()
check("| b | 2 | 5.25 |" in md, "b's median of 4.5 and 6.0\n" + md)
check("Winner so far: **b** (median 5.25)" in md, "b wins on the median\n" + md)
check("| a | 2 | 4.00 | [3.50, 4.50] | 100 | 40.0 |" in md, "a's row: median, IQR, s per run, ms per evaluation\n" + md)

# A hybrid study tunes two methods: a winner for each, not one over both.
(work / "studies" / "tune-hybrid-c8").mkdir()
(work / "studies" / "tune-hybrid-c8" / "index.csv").write_text(HEADER + "".join(
    f"runs/{c}/s{s},{c},x,{s},done,{b},10,2500,50,{b},abc,k{c}{s}\n"
    for c, s, b in [("offset-s0.1", 101, 7.0), ("offset-s0.3", 101, 8.0), ("switch-0.3", 101, 20.0),
                    ("switch-0.5", 101, 25.0)]))
sr.ledger(str(work / "studies"), str(work / "results"), ["tune-direct-c8", "tune-hybrid-c8"])
sr.summary(str(work / "results"))
md = (work / "results" / "tune-direct.md").read_text()
check("Winner so far (offset): **offset-s0.3** (median 8.00)" in md, "the offset hybrid's winner\n" + md)
check("Winner so far (switch): **switch-0.5** (median 25.00)" in md, "the switch hybrid's winner\n" + md)
check("Winner so far: **b** (median 5.25)" in md, "the direct study still has one winner\n" + md)

# The estimate: every robot at 1 s per evaluation gives the plan's evaluations in hours.
robots = ["R1", "R2"] + sr.CENTIPEDES
sys.stdin = io.StringIO("".join(f"{r} 1.0\n" for r in robots))
sr.estimate(str(work / "results"))
est = (work / "results" / "estimate.md").read_text()
want = sum(m * s * e * c for _, _, m, c, s, e in sr.plan(10)) / 3600
check(f"**{want:.1f}**" in est, f"total {want:.1f} h expected\n" + est)
check(sum(m * s for _, _, m, _, s, _ in sr.plan(5)) < sum(m * s for _, _, m, _, s, _ in sr.plan(10)),
      "fewer seeds on the middle sizes, fewer runs")
print("scaling_report_test: ok")
