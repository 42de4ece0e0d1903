#!/usr/bin/env python3
"""Scripts.ScalingShReport: `scripts/scaling.sh report` runs the comparison's four
pages from the ledger and the runs. In a scratch copy of the study's layout
(scripts/ and experiments/scaling/results/), with two tiny real gait runs as
centipede-2's direct compare runs: results, anytime and posture write their
pages (each names the runs it read), strips fails for want of centipede-16 runs,
and the stage says which page failed and exits 1 after trying them all.

    scaling_sh_report_test.py SOURCE_DIR CIC WORK_DIR
Exit 77 (skipped) without scipy, numpy or matplotlib.
"""
import csv
import shutil
import subprocess
import sys

try:
    import matplotlib  # noqa: F401
    import numpy  # noqa: F401
    import scipy  # noqa: F401
except ImportError as e:
    print(f"scaling_sh_report_test: skipped: {e}")
    sys.exit(77)
from scaling_scratch import Scratch  # noqa: E402 (after the skip)

scratch = Scratch("scaling_sh_report_test")
check = scratch.check
source, cic, work, root, studies, results = (scratch.source, scratch.cic, scratch.work, scratch.root, scratch.studies,
                                             scratch.results)


def run(args, **kw):
    return subprocess.run(args, capture_output=True, text=True, **kw)


D = "direct.sepcmaes-s0.15"
rows = []
for seed in ("1", "2"):
    out = work / "tiny" / seed
    p = run([cic, "--quiet", "--settings", str(source / "settings" / "r1_gait.xml"), "--seed", seed,
             "--set", "Gait.evaluations=16", "--set", "Gait.populationSize=8", "--set", "Simulator.sample_to=2",
             "--set", "Simulator.delayed_start=0.5", "--set", "Experiment.workers=1",
             "--set", f"Simulator.robotFile={source / 'settings' / 'robots' / 'centipede-2.xml'}",
             "--set", "Simulator.collisionSpace=1", "--output", str(out)])
    check(p.returncode == 0, f"a tiny gait run: {p.stderr}")
    run_dir = f"runs/{D}/s{seed}"
    shutil.copytree(next(out.iterdir()), studies / "compare-centipede-2" / run_dir)
    stats = list(csv.DictReader(open(studies / "compare-centipede-2" / run_dir / "stats.csv")))
    rows.append(dict(study="compare-centipede-2", config=D, seed=seed, status="done",
                     best_ever=repr(max(float(r["best"]) for r in stats)), evaluations=stats[-1]["evaluations"], wall_seconds=1,
                     run_dir=run_dir, commit="x"))
with open(results / "scaling-runs.csv", "w", newline="") as f:
    w = csv.DictWriter(f, list(rows[0]), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)

p = scratch.scaling("report")
check(p.returncode == 1, f"report: exit {p.returncode} (strips has no centipede-16 run to show)\n{p.stderr}")
check("scaling.sh: report: strips failed" in p.stderr, f"the failed page is not named: {p.stderr}")
for page in ("compare.md", "anytime.md", "posture.md"):
    check((results / page).exists(), f"report wrote no {page}: {p.stderr}")
check("centipede-2 | 12 | best direct | 2 |" in (results / "compare.md").read_text(),
      f"compare.md: {(results / 'compare.md').read_text()}")
check("| centipede-2 | 12 | best direct | 2 |" in (results / "anytime.md").read_text(),
      f"anytime.md: {(results / 'anytime.md').read_text()}")
check("| centipede-2 | 12 | 2 |" in (results / "posture.md").read_text(),
      f"posture.md: {(results / 'posture.md').read_text()}")
# scaling.sh passes absolute paths; a page names those inside the repository from its root, so
# the committed pages do not change with the machine that wrote them.
for page in ("anytime.md", "posture.md"):
    check("--results experiments/scaling/results --studies " in (results / page).read_text(),
          f"{page} names its results folder by a machine's path: {(results / page).read_text()[:400]}")
for figure in ("scaling-ratio.svg", "scaling-anytime.svg"):
    check((root / "docs" / "img" / figure).exists(), f"report drew no {figure}")
shutil.rmtree(work)
print("scaling_sh_report_test: ok")
