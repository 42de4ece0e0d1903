#!/usr/bin/env python3
"""Scripts.ScalingShRuns: `scripts/scaling.sh compare` runs only what the
committed ledger lacks. Run folders are never committed, so a study carried on
from a clean clone finds its sweeps' earlier runs pending in `cic sweep` while
the ledger records them done; they must not run again, and their rows must stay.
In a scratch copy of the study's layout, with ten tiny real compare sweeps (one
variant, seeds 1 and 2) and a ledger that has every run done but two (one
missing, one failed), and two done rows that prove nothing of the run the
sweep now asks for (one of another run key, as after an edit of the sweep,
one without a key):
  --dry-run lists exactly those four and writes nothing (and, before there is
  a ledger, all twenty);
  --dry-run with another stage, --commit or --summary-only, or with a cic
  that cannot list its runs with their keys (`cic sweep --dry-run --csv`), is
  refused (exit 2);
  the real stage runs those four (done in the ledger after it, with the
  sweep's run keys), keeps the other sixteen rows as they were, and says how
  many it skipped, and how many it runs again, per study.

    scaling_sh_runs_test.py SOURCE_DIR CIC WORK_DIR
"""
import csv
import shutil
import subprocess

from scaling_scratch import Scratch

scratch = Scratch("scaling_sh_runs_test")
check, scaling = scratch.check, scratch.scaling
source, cic, work, studies, here, results = (scratch.source, scratch.cic, scratch.work, scratch.studies, scratch.here,
                                             scratch.results)
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

# Every sweep runs the same settings, so each seed has one run key: `cic sweep --dry-run`'s key=.
dry = subprocess.run([cic, "sweep", str(here / "compare-r1.xml"), "--output", str(work / "dry"), "--dry-run"],
                     capture_output=True, text=True)
keys = {w[2].rsplit("/s", 1)[1]: w[3][len("key="):] for w in (ln.split() for ln in dry.stdout.splitlines())
        if len(w) > 3 and w[2].startswith("runs/") and w[3].startswith("key=")}
check(dry.returncode == 0 and sorted(keys) == ["1", "2"] and all(len(k) == 16 for k in keys.values()),
      f"the dry run gives no run keys: {dry.stdout}{dry.stderr}")
check(not (work / "dry").exists(), "cic sweep --dry-run wrote its study folder")

FIELDS = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit", "run_key"]
RERUN = {("centipede-2", "2"), ("centipede-4", "2"), ("r1", "1"), ("r2", "1")}
rows = []
for robot in ROBOTS:
    for seed in ("1", "2"):
        study = f"compare-{robot}"
        if (robot, seed) == ("centipede-2", "2"):
            continue   # never started in the earlier sitting
        status = "failed" if (robot, seed) == ("centipede-4", "2") else "done"
        # r1's seed 1 was run with other settings (another key); r2's row predates run keys.
        key = {("r1", "1"): "0123456789abcdef", ("r2", "1"): ""}.get((robot, seed), keys[seed])
        rows.append(dict(study=study, config="direct", seed=seed, status=status, best_ever="1.5" if status == "done" else "",
                         evaluations="16", wall_seconds="1.000", run_dir=f"runs/direct/s{seed}", commit="earlier",
                         run_key=key))


# No ledger yet (a new study): every run is to go.
p = scaling("--dry-run", "compare")
check(p.returncode == 0 and len(p.stdout.splitlines()) == 20 and "not run again" not in p.stderr,
      f"--dry-run without a ledger lists {len(p.stdout.splitlines())} runs, not all 20\n{p.stdout}{p.stderr}")

ledger = results / "scaling-runs.csv"
with open(ledger, "w", newline="") as f:
    w = csv.DictWriter(f, FIELDS, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
before = ledger.read_bytes()


p = scaling("--dry-run", "compare")
check(p.returncode == 0, f"--dry-run compare: exit {p.returncode}\n{p.stderr}")
listed = [line.split() for line in p.stdout.splitlines()]
check([(s, d) for s, _, d in listed] == [("compare-centipede-2", "runs/direct/s2"), ("compare-centipede-4", "runs/direct/s2"),
                                          ("compare-r1", "runs/direct/s1"), ("compare-r2", "runs/direct/s1")],
      f"--dry-run lists {listed}, not the missing, the failed and the two unproven runs\n{p.stderr}")
check("== compare-centipede-2: 1 runs the ledger records as done are not run again" in p.stderr and
      "== compare-centipede-8: 2 runs the ledger records as done are not run again" in p.stderr and
      "== compare-r1: 1 runs the ledger records as done are not run again" in p.stderr,
      f"the skips are not named: {p.stderr}")
check("== compare-r1: 1 runs the ledger records as done, but of other settings" in p.stderr and
      "== compare-r2: 1 runs the ledger records as done, but of other settings" in p.stderr,
      f"the runs of other settings are not named: {p.stderr}")
check(not studies.exists() and ledger.read_bytes() == before and sorted(results.iterdir()) == [ledger],
      "--dry-run wrote something")

for args, says in ((["--dry-run", "ledger"], "--dry-run lists the runs"), (["--dry-run", "--commit", "compare"], "nothing to --commit"),
                   (["--dry-run", "--summary-only", "compare"], "choose one")):
    p = scaling(*args)
    check(p.returncode == 2 and says in p.stderr, f"{args}: exit {p.returncode}, {p.stderr}")
# A cic older than this script: one without `--dry-run --csv`, and one whose listing has no
# run keys. Both refused, since no ledger row could be matched.
for name, body in (("no-csv", "case \"$*\" in *--csv*) echo 'The following argument was not expected: --csv' >&2; exit 109;; esac\n"
                              f"exec '{cic}' \"$@\"\n"),
                   ("no-keys", f"'{cic}' \"$@\" | sed '1s/,run_key,/,key,/'\n")):
    older = work / f"older-cic-{name}"
    older.write_text("#!/bin/sh\n" + body)
    older.chmod(0o755)
    p = scaling("--dry-run", "compare", cic=older)
    check(p.returncode == 2 and "build cic from this checkout" in p.stderr and not p.stdout,
          f"an older cic ({name}): exit {p.returncode}, {p.stderr}")
    check(not studies.exists() and ledger.read_bytes() == before, f"a refusal ({name}) wrote something")

p = scaling("--jobs", "2", "compare")
check(p.returncode == 0, f"compare: exit {p.returncode}\n{p.stderr}")
after = {(r["study"], r["seed"]): r for r in csv.DictReader(open(ledger))}
check(len(after) == 20, f"the ledger has {len(after)} rows, not 20")
for robot, seed in RERUN:
    r = after[(f"compare-{robot}", seed)]
    check(r["status"] == "done" and float(r["best_ever"]) > 0 and r["run_key"] == keys[seed], f"{robot} s{seed} did not run: {r}")
for r in rows:
    if (r["study"][len("compare-"):], r["seed"]) not in RERUN:
        check(after[(r["study"], r["seed"])] == r, f"an earlier sitting's row changed: {r} -> {after[(r['study'], r['seed'])]}")
ran = sorted(str(d.relative_to(studies)) for d in studies.glob("*/runs/direct/s*"))
check(ran == ["compare-centipede-2/runs/direct/s2", "compare-centipede-4/runs/direct/s2", "compare-r1/runs/direct/s1",
              "compare-r2/runs/direct/s1"], f"the stage ran {ran}")
shutil.rmtree(work)
print("scaling_sh_runs_test: ok")
