#!/usr/bin/env python3
"""Scripts.ScalingShPostureRuns: `scripts/scaling.sh posture-runs` reruns the
finished compare runs the posture page needs (the direct method's and
Offset-HybrID's), when their folders are gone and their replays are not cached,
and each must end on the best_ever its ledger row scores it by.
In a scratch copy of the study's layout, with one tiny real compare sweep (a
direct, an Offset-HybrID and a HyperGP-gait variant, seeds 1 and 2) run by
`cic sweep` and merged into a ledger, then its folders and store removed:
  --dry-run lists the direct and Offset-HybrID runs (not HyperGP-gait's, nor a
  run with a cached replay row), writes nothing, and `scaling.sh status` counts
  them at their ledger rows' wall time;
  the stage reruns them: their folders are back, on the ledger's best_ever, and
  the ledger's scores are unchanged;
  with a ledger row's best_ever altered (a rerun that would end elsewhere), the
  stage exits 1 naming the run, and the ledger's bytes are unchanged;
  a sweep that now gives a run another run key is refused (exit 2), nothing run.

    scaling_sh_posture_runs_test.py SOURCE_DIR CIC WORK_DIR
"""
import csv
import shutil
import subprocess

from scaling_scratch import Scratch

scratch = Scratch("scaling_sh_posture_runs_test")
check, scaling = scratch.check, scratch.scaling
source, cic, studies, here, results = scratch.source, scratch.cic, scratch.studies, scratch.here, scratch.results
SWEEP = here / "compare-centipede-2.xml"
sweep_text = f"""<?xml version="1.0" encoding="UTF-8"?>
<sweep name="compare-centipede-2">
  <base>{source / 'settings' / 'r1_switch_hybrid.xml'}</base>
  <store>../store</store>
  <set>Simulator.robotFile={source / 'settings' / 'robots' / 'centipede-2.xml'}</set>
  <set>Simulator.collisionSpace=1</set>
  <set>Simulator.sample_to=2</set>
  <set>Simulator.delayed_start=0.5</set>
  <set>Control.maximumIterations=2</set>
  <set>GP.generatedPopulationSize=6</set>
  <variant name="direct.tiny"><set>Experiment.type=gait</set><set>GP.numberOfTreesInForestGenotype=1</set><set>Neural.synopsisThreshold=0.2</set><set>Neural.neuronModel=tanh</set><set>Neural.substrate=network</set><set>Neural.switchPatience=0</set><set>Neural.switchShare=0</set><set>Gait.evaluations=16</set><set>Gait.populationSize=8</set><set>Gait.sigma0=0.15</set></variant>
  <variant name="hypergp-gait"><set>Neural.switchPatience=0</set><set>Neural.switchShare=0</set><set>Neural.directOffsets=0</set></variant>
  <variant name="offset-hybrid.tiny"><set>Neural.switchPatience=0</set><set>Neural.switchShare=0</set><set>Neural.directOffsets=1</set><set>Neural.offsetSigma=0.1</set></variant>
  <repeats count="2" firstSeed="1" seeds="same"/>
</sweep>
"""
SWEEP.write_text(sweep_text)
def ledger_rows():
    return {(r["config"], r["seed"]): r for r in csv.DictReader(open(results / "scaling-runs.csv"))}


def gone():
    shutil.rmtree(studies / "compare-centipede-2")
    shutil.rmtree(studies / "store")


p = subprocess.run([cic, "--quiet", "sweep", str(SWEEP), "--output", str(studies / "compare-centipede-2"), "--jobs", "2"],
                   capture_output=True, text=True)
check(p.returncode == 0, f"the tiny sweep: {p.stderr}")
p = scaling("ledger")
check(p.returncode == 0, f"ledger: {p.stderr}")
first = ledger_rows()
check(len(first) == 6 and all(r["status"] == "done" and r["best_ever"] for r in first.values()),
      f"the ledger after the sweep: {first}")
gone()

# A run whose replays are cached is not needed again.
with open(results / "compare-posture.csv", "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["study", "config", "seed", "best_ever", "run_dir", "original", "offsets 0", "smooth, 2 terms",
                "smooth, 4 terms", "by axis, 2 terms", "mirrored", "direct offsets 0"])
    w.writerow(["compare-centipede-2", "offset-hybrid.tiny", "2", first[("offset-hybrid.tiny", "2")]["best_ever"],
                "x", 1, "", "", "", "", "", 0.5])
p = scaling("--dry-run", "posture-runs")
listed = sorted(line.split()[2] for line in p.stdout.splitlines())
check(p.returncode == 0 and listed == ["runs/direct.tiny/s1", "runs/direct.tiny/s2", "runs/offset-hybrid.tiny/s1"],
      f"--dry-run posture-runs lists {listed}\n{p.stdout}{p.stderr}")
check(not (studies / "compare-centipede-2").exists(), "--dry-run posture-runs wrote the study folder")

# status counts the same three reruns, each at its own ledger row's wall time (1, 2 and 3 hours for
# the three; HyperGP-gait's and the cached run's rows 10 hours, which must not count).
ledger_bytes = (results / "scaling-runs.csv").read_bytes()
rows = list(csv.DictReader(open(results / "scaling-runs.csv")))
hours = {("direct.tiny", "1"): 1, ("direct.tiny", "2"): 2, ("offset-hybrid.tiny", "1"): 3}
for r in rows:
    r["wall_seconds"] = str(3600 * hours.get((r["config"], r["seed"]), 10))
with open(results / "scaling-runs.csv", "w", newline="") as f:
    w = csv.DictWriter(f, list(rows[0]), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
p = scaling("--jobs", "2", "status")
check(p.returncode == 0 and "| posture-runs (reruns of done runs) | 3 | | 3 | the ledger's wall time | 6.0 |" in p.stdout
      and "| **total** | 9 | 6 | 3 | | **6.0** |" in p.stdout, f"status with posture-runs to go: {p.stdout}{p.stderr}")
(results / "scaling-runs.csv").write_bytes(ledger_bytes)
(results / "compare-posture.csv").unlink()

p = scaling("--jobs", "2", "posture-runs")
check(p.returncode == 0 and "== posture-runs: 4 runs to rerun" in p.stderr, f"posture-runs: {p.returncode}\n{p.stderr}")
for config, seed in (("direct.tiny", 1), ("direct.tiny", 2), ("offset-hybrid.tiny", 1), ("offset-hybrid.tiny", 2)):
    check((studies / "compare-centipede-2" / "runs" / config / f"s{seed}" / "summary.txt").exists(),
          f"{config} s{seed} was not rerun")
check(not (studies / "compare-centipede-2" / "runs" / "hypergp-gait" / "s1" / "summary.txt").exists(), "HyperGP-gait was rerun")
after = ledger_rows()
check({k: r["best_ever"] for k, r in after.items()} == {k: r["best_ever"] for k, r in first.items()},
      f"the reruns changed the ledger's scores: {after}")

# A rerun that ends elsewhere than its ledger row: stopped before the ledger is written.
gone()
rows = list(csv.DictReader(open(results / "scaling-runs.csv")))
for r in rows:
    if (r["config"], r["seed"]) == ("direct.tiny", "1"):
        r["best_ever"] = "0.123"
with open(results / "scaling-runs.csv", "w", newline="") as f:
    w = csv.DictWriter(f, list(rows[0]), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
before = (results / "scaling-runs.csv").read_bytes()
p = scaling("posture-runs")
check(p.returncode == 1 and "runs/direct.tiny/s1 was rerun and ended on best_ever" in p.stderr and
      "the ledger scores it 0.123" in p.stderr, f"a rerun off its ledger row: {p.returncode}\n{p.stderr}")
check((results / "scaling-runs.csv").read_bytes() == before, "the ledger was written after a rerun off its row")

# A sweep that now asks other settings of a run (another run key): refused before anything runs.
gone()
SWEEP.write_text(sweep_text.replace("Gait.sigma0=0.15", "Gait.sigma0=0.3"))
p = scaling("posture-runs")
check(p.returncode == 2 and "now gives runs/direct.tiny/s" in p.stderr and "another run than the one the ledger scores"
      in p.stderr, f"another run key: {p.returncode}\n{p.stderr}")
check(not (studies / "compare-centipede-2").exists(), "a refused posture-runs wrote the study folder")
# status still gives its table, and says why posture-runs is not counted.
studies.mkdir(exist_ok=True)
p = scaling("--jobs", "2", "status")
check(p.returncode == 0 and "| **total** | 6 |" in p.stdout and "posture-runs is not counted: it would refuse" in p.stdout
      and "another run than the one the ledger scores" in p.stdout, f"status beside a refusing posture-runs: {p.stdout}"
      f"{p.stderr}")
print("scaling_sh_posture_runs_test: ok")
