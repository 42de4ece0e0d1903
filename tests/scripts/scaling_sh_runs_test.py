#!/usr/bin/env python3
"""Scripts.ScalingShRuns: `scripts/scaling.sh compare` runs only what the
committed ledger lacks. Run folders are never committed, so a study carried on
from a clean clone finds its sweeps' earlier runs pending in `cic sweep` while
the ledger records them done; they must not run again, and their rows must stay.
In a scratch copy of the study's layout, with ten tiny real compare sweeps (one
variant, seeds 1 and 2) and a ledger that has every run done but two (one
missing, one failed):
  --dry-run lists exactly those two and writes nothing;
  --dry-run with another stage, --commit or --summary-only is refused (exit 2);
  the real stage runs those two (both done in the ledger after it), keeps the
  other eighteen rows as they were, and says how many it skipped per study.

    scaling_sh_runs_test.py SOURCE_DIR CIC WORK_DIR
"""
import csv
import pathlib
import shutil
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)


def check(condition, message):
    if not condition:
        print(f"scaling_sh_runs_test: {message}", file=sys.stderr)
        sys.exit(1)


root, studies = work / "root", work / "studies"
shutil.copytree(source / "scripts", root / "scripts")
here = root / "experiments" / "scaling"
results = here / "results"
results.mkdir(parents=True)
ROBOTS = ["centipede-2", "centipede-2-irregular", "centipede-4", "centipede-4-irregular", "centipede-8",
          "centipede-8-irregular", "centipede-16", "centipede-16-irregular", "r1", "r2"]
for robot in ROBOTS:
    # Every sweep runs the 12-hinge centipede: the names are the study's, the runs tiny.
    (here / f"compare-{robot}.xml").write_text(f"""<?xml version="1.0" encoding="UTF-8"?>
<sweep name="compare-{robot}">
  <base>{source / 'settings' / 'r1_gait.xml'}</base>
  <set>Simulator.robotFile={source / 'settings' / 'robots' / 'centipede-2.xml'}</set>
  <set>Simulator.collisionSpace=1</set>
  <set>Gait.evaluations=16</set>
  <set>Gait.populationSize=8</set>
  <set>Simulator.sample_to=2</set>
  <set>Simulator.delayed_start=0.5</set>
  <variant name="direct"><set>Gait.sigma0=0.15</set></variant>
  <repeats count="2" firstSeed="1" seeds="same"/>
</sweep>
""")

FIELDS = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit"]
rows = []
for robot in ROBOTS:
    for seed in ("1", "2"):
        study = f"compare-{robot}"
        if (robot, seed) == ("centipede-2", "2"):
            continue   # never started in the earlier sitting
        status = "failed" if (robot, seed) == ("centipede-4", "2") else "done"
        rows.append(dict(study=study, config="direct", seed=seed, status=status, best_ever="1.5" if status == "done" else "",
                         evaluations="16", wall_seconds="1.000", run_dir=f"runs/direct/s{seed}", commit="earlier"))
ledger = results / "scaling-runs.csv"
with open(ledger, "w", newline="") as f:
    w = csv.DictWriter(f, FIELDS, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
before = ledger.read_bytes()

env = {"PATH": "/usr/bin:/bin", "CIC": cic, "PYTHON": sys.executable}


def scaling(*args):
    return subprocess.run(["bash", str(root / "scripts" / "scaling.sh"), "--output", str(studies), *args],
                          capture_output=True, text=True, env=env)


p = scaling("--dry-run", "compare")
check(p.returncode == 0, f"--dry-run compare: exit {p.returncode}\n{p.stderr}")
listed = [line.split() for line in p.stdout.splitlines()]
check([(s, d) for s, _, d in listed] == [("compare-centipede-2", "runs/direct/s2"), ("compare-centipede-4", "runs/direct/s2")],
      f"--dry-run lists {listed}, not the missing and the failed run\n{p.stderr}")
check("== compare-centipede-2: 1 runs the ledger records as done are not run again" in p.stderr and
      "== compare-r2: 2 runs the ledger records as done are not run again" in p.stderr,
      f"the skips are not named: {p.stderr}")
check(not studies.exists() and ledger.read_bytes() == before and sorted(results.iterdir()) == [ledger],
      "--dry-run wrote something")

for args, says in ((["--dry-run", "ledger"], "--dry-run lists the runs"), (["--dry-run", "--commit", "compare"], "nothing to --commit"),
                   (["--dry-run", "--summary-only", "compare"], "choose one")):
    p = scaling(*args)
    check(p.returncode == 2 and says in p.stderr, f"{args}: exit {p.returncode}, {p.stderr}")
check(not studies.exists() and ledger.read_bytes() == before, "a refusal wrote something")

p = scaling("--jobs", "2", "compare")
check(p.returncode == 0, f"compare: exit {p.returncode}\n{p.stderr}")
after = {(r["study"], r["seed"]): r for r in csv.DictReader(open(ledger))}
check(len(after) == 20, f"the ledger has {len(after)} rows, not 20")
for key in (("compare-centipede-2", "2"), ("compare-centipede-4", "2")):
    check(after[key]["status"] == "done" and float(after[key]["best_ever"]) > 0, f"{key} did not run: {after[key]}")
for r in rows:
    key = (r["study"], r["seed"])
    if key != ("compare-centipede-4", "2"):
        check(after[key] == r, f"an earlier sitting's row changed: {r} -> {after[key]}")
ran = sorted(str(d.relative_to(studies)) for d in studies.glob("*/runs/direct/s*"))
check(ran == ["compare-centipede-2/runs/direct/s2", "compare-centipede-4/runs/direct/s2"], f"the stage ran {ran}")
shutil.rmtree(work)
print("scaling_sh_runs_test: ok")
