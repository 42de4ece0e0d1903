#!/usr/bin/env python3
"""Scripts.ScalingStatus: scripts/scaling-report.py status counts each compare sweep's runs
(variants times seeds) against the ledger's finished ones, ignores ledger rows of variants
the sweep no longer runs, times the runs to go by the same method's finished runs, else the
robot's, else results/estimate.md (scaled by the twin robot's measured over estimated
seconds when the twin has finished runs), and refuses bad input with exit 2. Given cic, a
done row counts only under the run key the shipped sweep gives its run now.

    scaling_status_test.py SOURCE_DIR CIC WORK_DIR
"""
import csv
import pathlib
import shutil
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
results, sweeps = work / "results", work / "sweeps"
results.mkdir(parents=True)
sweeps.mkdir()
REPORT = [sys.executable, str(source / "scripts" / "scaling-report.py"), "status"]


def check(condition, message):
    if not condition:
        print(f"scaling_status_test: {message}", file=sys.stderr)
        sys.exit(1)


def sweep(robot, variants):
    (sweeps / f"compare-{robot}.xml").write_text(
        f'<sweep name="compare-{robot}"><base>x.xml</base>'
        + "".join(f'<variant name="{v}"><set>GP.seed=1</set></variant>' for v in variants)
        + '<repeats count="3" firstSeed="1" seeds="same"/></sweep>\n')


FIELDS = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit"]


def ledger(rows):
    with open(results / "scaling-runs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS, lineterminator="\n")
        w.writeheader()
        for study, config, seed, status, wall in rows:
            w.writerow({"study": study, "config": config, "seed": seed, "status": status, "best_ever": 1,
                        "evaluations": 2500, "wall_seconds": wall, "run_dir": "x", "commit": "x"})


def run(*extra):
    return subprocess.run(REPORT + ["--results", str(results), "--sweeps", str(sweeps), *extra],
                          capture_output=True, text=True)


sweep("centipede-2", ["direct.a", "hypergp-gait"])
sweep("centipede-2-irregular", ["direct.a"])
sweep("r1", ["direct.sepcmaes-s0.15", "offset-hybrid.b", "switch-hybrid.c"])
(results / "estimate.md").write_text("| robot | s per evaluation |\n|---|---|\n| R1 | 0.036 |\n| centipede-2 | 0.100 |\n"
                                     "| centipede-2-irregular | 0.300 |\n")
ledger([("compare-centipede-2", "direct.a", 1, "done", 250),          # 0.1 s per evaluation
        ("compare-centipede-2", "direct.a", 2, "done", 500),          # 0.2
        ("compare-centipede-2", "hypergp-gait", 1, "done", 1000),     # 0.4
        ("compare-centipede-2", "hypergp-gait", 2, "running", ""),
        ("compare-centipede-2", "switch-hybrid.old", 1, "superseded", 5),
        ("compare-centipede-2", "direct.gone", 1, "done", 5),         # a variant the sweep no longer runs
        ("tune-direct-c8", "direct.a", 1, "done", 5),                 # centipede-2 was not tuned
        ("tune-direct-r1", "sepcmaes-s0.15", 101, "done", 125),       # R1's direct configuration: 0.05
        ("tune-direct-r1", "cmaes-s0.15", 101, "done", 500)])
p = run("--jobs", "2")
check(p.returncode == 0, f"status: {p.stderr}")
lines = p.stdout.splitlines()
# centipede-2: direct seed 3 at its own 0.15, HyperGP-gait seeds 2 and 3 at its own 0.4:
# 2500 * (0.15 + 0.8) / 3600 = 0.66 core-hours; the robot's median of 0.1, 0.2, 0.4 is 0.200.
check("| compare-centipede-2 | 6 | 3 | 3 | 0.200 | 0.7 |" in lines, "timed by the same method first\n" + p.stdout)
# The 11-hinge twin: nothing finished; estimate.md's 0.3 times its twin's 0.200 measured over 0.100
# estimated: 0.6 s per evaluation, 3 * 2500 * 0.6 / 3600 = 1.25 core-hours.
check("| compare-centipede-2-irregular | 3 | 0 | 3 | 0.600 (estimate.md's 0.300 × 2.00, as its twin's runs took) | 1.2 |"
      in lines, "scaled by its twin's measured over estimated time\n" + p.stdout)
# R1: nothing finished (and no twin); the direct runs at their tuning runs' 0.05, the hybrids at estimate.md's 0.036,
# 15,000 evaluations: 3 * 15000 * 0.05 / 3600 + 6 * 15000 * 0.036 / 3600 = 1.525 core-hours.
check("| compare-r1 | 9 | 0 | 9 | 0.036 (estimate.md) | 1.5 |" in lines,
      "the tuning runs of the same configuration, else estimate.md\n" + p.stdout)
check("| **total** | 18 | 3 | 15 | | **3.4** |" in lines, "the total\n" + p.stdout)
check(lines[-1].startswith("About 1.7 hours of wall time at 2 runs at a time"), "wall time at --jobs 2\n" + p.stdout)
check(run("--jobs", "1").stdout.splitlines()[-1].startswith("About 3.4 hours of wall time at 1 run at a time"),
      "wall time at --jobs 1")
check(not any(results.glob("*.tmp*")) and sorted(x.name for x in results.iterdir()) == ["estimate.md",
                                                                                        "scaling-runs.csv"],
      "status writes nothing")

# ---- refusals: exit 2, one line, the reason named ----
for extra, want in ((["--jobs", "0"], "--jobs takes a positive whole number, got '0'"),
                    (["--bogus", "1"], "unknown or incomplete option '--bogus'")):
    p = run(*extra)
    check(p.returncode == 2 and want in p.stderr and p.stdout == "", f"{extra}: {p.returncode} {p.stderr}")
(results / "estimate.md").write_text("| robot | s per evaluation |\n|---|---|\n| centipede-2 | 9.000 |\n"
                                     "| centipede-2-irregular | 9.000 |\n")
p = run()
check(p.returncode == 2 and "compare-r1 has runs to go" in p.stderr and "scripts/scaling.sh estimate" in p.stderr,
      f"no way to time R1: {p.returncode} {p.stderr}")
(results / "scaling-runs.csv").unlink()
p = run()
check(p.returncode == 2 and "no ledger at" in p.stderr, f"no ledger: {p.returncode} {p.stderr}")
p = subprocess.run(REPORT + ["--results", str(source / "experiments" / "scaling" / "results"),
                             "--sweeps", str(work / "none")], capture_output=True, text=True)
check(p.returncode == 2 and "no compare sweep in" in p.stderr, f"no sweeps: {p.returncode} {p.stderr}")
# scripts/scaling.sh status: the shipped sweeps and ledger, and no cic binary needed.
p = subprocess.run(["bash", str(source / "scripts" / "scaling.sh"), "status", "--jobs", "2"], capture_output=True,
                   text=True, env={"PATH": "/usr/bin:/bin", "CIC": str(work / "no-cic"), "PYTHON": sys.executable})
check(p.returncode == 0 and "| compare-centipede-16 | 40 |" in p.stdout and "| **total** | " in p.stdout and
      "hours of wall time at 2 runs at a time" in p.stdout, f"scaling.sh status: {p.returncode} {p.stderr}\n{p.stdout}")

# ---- with cic: the shipped sweeps' run keys decide what is done ----
shipped = source / "experiments" / "scaling"
dry = subprocess.run([cic, "--quiet", "sweep", str(shipped / "compare-centipede-2.xml"), "--dry-run"],
                     capture_output=True, text=True)
key = {d: k for d, k in (line.split()[2:4] for line in dry.stdout.splitlines() if " key=" in line)}
check(dry.returncode == 0 and key, f"the shipped sweep's dry run: {dry.returncode} {dry.stderr}")
runs = sorted(key)[:2]   # e.g. runs/direct.sepcmaes-s0.15/s1 and .../s10
keyed = results / "keyed"
keyed.mkdir()
(keyed / "estimate.md").write_text((shipped / "results" / "estimate.md").read_text())   # every robot timed
with open(keyed / "scaling-runs.csv", "w", newline="") as f:
    w = csv.DictWriter(f, FIELDS + ["run_key"], lineterminator="\n")
    w.writeheader()
    for d, k in ((runs[0], key[runs[0]][4:]), (runs[1], "0123456789abcdef")):   # the sweep's key; another
        config, seed = d.split("/")[1], d.split("/")[2][1:]
        w.writerow({"study": "compare-centipede-2", "config": config, "seed": seed, "status": "done", "best_ever": 1,
                    "evaluations": 2500, "wall_seconds": 250, "run_dir": d, "commit": "x", "run_key": k})


def keyed_status(*extra):
    return subprocess.run(REPORT + ["--results", str(keyed), "--sweeps", str(shipped), *extra],
                          capture_output=True, text=True)


p = keyed_status()
check(p.returncode == 0 and "| compare-centipede-2 | 40 | 2 | 38 |" in p.stdout, f"without cic, rows as they are\n{p}")
p = keyed_status("--cic", cic)
check(p.returncode == 0 and "| compare-centipede-2 | 40 | 1 | 39 |" in p.stdout and
      "1 done row of the ledger is of other settings than the sweeps give now (another run key): counted as to go."
      in p.stdout, f"with cic, the row of another key is to go\n{p.stdout}\n{p.stderr}")
p = keyed_status("--cic", str(work / "no-cic"))
check(p.returncode == 2 and f"cannot run {work / 'no-cic'}" in p.stderr, f"a cic that cannot run: {p}")
p = keyed_status("--studies", str(work))
check(p.returncode == 2 and "--studies goes with --cic" in p.stderr, f"--studies without --cic: {p}")
p = keyed_status("--cic", cic, "--studies", str(work / "no-such-folder"))
check(p.returncode == 2 and "is no folder" in p.stderr, f"--studies that is no folder: {p}")

# scaling-report.py runs: what scaling.sh starts runs by, every run of the sweep with its
# status and key, as `cic sweep --dry-run --csv` gives them (writes nothing).
p = subprocess.run([sys.executable, str(source / "scripts" / "scaling-report.py"), "runs", "--sweep",
                    str(shipped / "compare-centipede-2.xml"), "--output", str(work / "c2-study"), "--cic", cic],
                   capture_output=True, text=True)
listed = [line.split() for line in p.stdout.splitlines()]
check(p.returncode == 0 and [w[0] for w in listed] == [str(i) for i in range(40)] and
      all(w[1] == "pending" for w in listed) and {w[2]: "key=" + w[3] for w in listed} == key,
      f"runs: tasks 0..39, pending, with the text dry run's keys: {p.returncode} {p.stderr}\n{p.stdout}")
check(not (work / "c2-study").exists(), "runs wrote the study folder")
p = subprocess.run([sys.executable, str(source / "scripts" / "scaling-report.py"), "runs", "--sweep",
                    str(shipped / "compare-centipede-2.xml"), "--output", str(work / "c2-study")],
                   capture_output=True, text=True)
check(p.returncode == 2 and "--cic is required" in p.stderr, f"runs without --cic: {p.returncode} {p.stderr}")
print("scaling_status_test: ok")
