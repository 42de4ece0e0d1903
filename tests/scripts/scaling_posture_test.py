#!/usr/bin/env python3
"""Scripts.ScalingPosture: scripts/scaling-report.py posture on a synthetic
ledger whose direct compare runs are tiny real gait runs (two on the 12-hinge
centipede's robot file, one on R1): per robot the gaits probed (not the other
methods', not a failed run's), the median of their own raw eq. 7.1 as `cic
assess` replays them, and a share kept per posture replacement. Every run's
replays are cached (compare-posture.csv): with the folders gone the page comes
out byte for byte the same; a finished run with neither folder nor cached row
leaves its robot out, named on the page. The refusals (no ledger; no direct run
with a folder or a cached row): exit 2, one line, nothing written.

    scaling_posture_test.py SOURCE_DIR CIC WORK_DIR
Exit 77 (skipped) without numpy.
"""
import csv
import pathlib
import re
import shutil
import statistics
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
try:
    import numpy  # noqa: F401
except ImportError as e:
    print(f"scaling_posture_test: skipped: {e}")
    sys.exit(77)
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
REPORT = [sys.executable, str(source / "scripts" / "scaling-report.py")]
LEDGER = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit"]


def check(condition, message):
    if not condition:
        print(f"scaling_posture_test: {message}", file=sys.stderr)
        sys.exit(1)


def run(args):
    return subprocess.run(args, capture_output=True, text=True)


def raw_of(folder):
    """The raw eq. 7.1 of FOLDER's best as cic assess replays it."""
    p = run([cic, "--quiet", "assess", str(folder)])
    check(p.returncode == 0, f"cic assess {folder}: {p.stderr}")
    return float(next(csv.DictReader(p.stdout.splitlines()))["raw_fitness"])


def tiny_run(name, settings, seed, *sets):
    """A tiny real run of SETTINGS (2 s walks, one worker) and its best's raw eq. 7.1."""
    p = run([cic, "--quiet", "--settings", str(source / "settings" / settings), "--seed", seed,
             "--set", "Simulator.sample_to=2", "--set", "Simulator.delayed_start=0.5",
             "--set", "Experiment.workers=1", *sets, "--output", str(work / "tiny" / name)])
    check(p.returncode == 0, f"a tiny {settings} run: {p.stderr}")
    folder = next((work / "tiny" / name).iterdir())
    return folder, raw_of(folder)


def gait_run(name, seed, *sets):
    """A tiny real gait run (16 evaluations)."""
    return tiny_run(name, "r1_gait.xml", seed, "--set", "Gait.evaluations=16", "--set", "Gait.populationSize=8",
                    *sets)


centipede = ["--set", f"Simulator.robotFile={source / 'settings' / 'robots' / 'centipede-2.xml'}",
             "--set", "Simulator.collisionSpace=1"]


def offset_hybrid_run(name, seed):
    """A tiny real Offset-HybrID run on the 12-hinge centipede (2 generations of 8)."""
    return tiny_run(name, "r1_offset_hybrid.xml", seed, "--set", "GP.generatedPopulationSize=8",
                    "--set", "GP.tournament_size=2", "--set", "Control.maximumIterations=2", *centipede)


o1, raw_o1 = offset_hybrid_run("o1", "1")
# The same run with its direct offsets 0, replayed by hand: what the page's second table must give.
zeroed = work / "tiny" / "o1-zeroed"
zeroed.mkdir()
shutil.copy(o1 / "settings.xml", zeroed / "settings.xml")
(zeroed / "population.xml").write_text(re.sub(r"<offsets>([^<]*)</offsets>",
                                              lambda m: "<offsets>" + " ".join("0" for _ in m.group(1).split())
                                              + "</offsets>", (o1 / "population.xml").read_text()))
raw_o1_zeroed = raw_of(zeroed)
check(raw_o1_zeroed != raw_o1, "the tiny Offset-HybrID run's offsets change nothing: the check below would be idle")
c1, raw_c1 = gait_run("c1", "1", *centipede)
c2, raw_c2 = gait_run("c2", "2", *centipede)
r1, raw_r1 = gait_run("r1", "1")

# The study folders as scaling.sh's sweeps leave them, and the ledger naming them.
studies, results = work / "studies", work / "results"
results.mkdir()
D = "direct.sepcmaes-s0.15"
rows = []
for study, config, seed, status, folder in (
        ("compare-centipede-2", D, 1, "done", c1), ("compare-centipede-2", D, 2, "done", c2),
        ("compare-centipede-2", D, 3, "failed", None),              # not probed: failed, no folder
        ("compare-centipede-2", "hypergp-gait", 1, "done", None),   # not probed: not the direct method
        ("compare-r1", D, 1, "done", r1), ("tune-direct-r1", "sepcmaes-s0.15", 101, "done", None),
        ("compare-centipede-2", "offset-hybrid.offset-s0.1", 1, "done", o1)):
    run_dir = f"runs/{config}/s{seed}"
    if folder:
        shutil.copytree(folder, studies / study / run_dir)
    rows.append(dict(study=study, config=config, seed=seed, status=status, best_ever=1.0, evaluations=16,
                     wall_seconds=1, run_dir=run_dir, commit="x"))


def write_ledger(rows):
    with open(results / "scaling-runs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, LEDGER, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)


write_ledger(rows)
posture = [*REPORT, "posture", "--results", str(results), "--studies", str(studies), "--cic", cic]
p = run(posture)
check(p.returncode == 0, f"posture failed: {p.stderr}")
text = (results / "posture.md").read_text()
table = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[2:-1]]
         for line in text.split("## Offset-HybrID")[0].splitlines()
         if line.startswith("| ") and not line.startswith("| robot")}
check(set(table) == {"centipede-2", "r1"}, f"robots: {sorted(table)}\n{text}")
hinges, gaits, median, *kept = table["centipede-2"]
check((hinges, gaits) == ("12", "2"), f"centipede-2: {hinges} hinges, {gaits} gaits\n{text}")
check(median == f"{statistics.median([raw_c1, raw_c2]):.2f}", f"centipede-2's median {median}, "
      f"cic assess gives {raw_c1} and {raw_c2}")
check(len(kept) == 5 and all(k.endswith("%") for k in kept), f"centipede-2's shares: {kept}")
check(table["r1"][:3] == ["12", "1", f"{raw_r1:.2f}"], f"r1: {table['r1']}")
check("scripts/scaling-report.py posture" in text, "the page names its command")
# The second table: Offset-HybrID's run as it is and with its direct offsets 0.
offsets = [line for line in text.split("## Offset-HybrID's direct offsets")[-1].splitlines() if line.startswith("| centipede")]
check(len(offsets) == 1, f"Offset-HybrID's table: {offsets}\n{text}")
check([c.strip() for c in offsets[0].split("|")[1:-1]] ==
      ["centipede-2", "12", "1", f"{raw_o1:.2f}", f"{raw_o1_zeroed:.2f}", f"{raw_o1_zeroed / raw_o1:.0%}"],
      f"Offset-HybrID's row: {offsets[0]}, cic assess gives {raw_o1} and {raw_o1_zeroed} with offsets 0")

# The cache: every probed run has its row, and the page needs no folder to be written again.
cache = {(r["study"], r["seed"], r["config"]): r for r in csv.DictReader(open(results / "compare-posture.csv"))}
check(sorted(cache) == [("compare-centipede-2", "1", D), ("compare-centipede-2", "1", "offset-hybrid.offset-s0.1"),
                        ("compare-centipede-2", "2", D), ("compare-r1", "1", D)], f"the cache's runs: {sorted(cache)}")
r1_row = cache[("compare-r1", "1", D)]
# The probe replays the original as the run saved it: cic assess's raw eq. 7.1, to the last bit.
check(float(r1_row["original"]) == raw_r1, f"the cache's r1 row: {r1_row}, cic assess gives {raw_r1!r}")
before = (results / "posture.md").read_bytes()
shutil.rmtree(studies)
p = run(posture)
check(p.returncode == 0 and (results / "posture.md").read_bytes() == before,
      f"from the cache alone: exit {p.returncode} {p.stderr}\n{(results / 'posture.md').read_text()}")
# A finished run with neither folder nor cached row: its robot is left out and named.
write_ledger(rows + [dict(rows[4], seed=2, run_dir=f"runs/{D}/s2")])
p = run(posture)
text = (results / "posture.md").read_text()
check(p.returncode == 0 and "no row in `compare-posture.csv`: r1 (1 direct runs). `scripts/scaling.sh posture-runs` reruns them" in text and "| r1 |" not in text
      and "| centipede-2 | 12 | 2 |" in text, f"a run with no folder and no row: {p.returncode} {p.stderr}\n{text}")

# Refusals: exit 2, one line, posture.md untouched.
before = (results / "posture.md").read_bytes()
(results / "compare-posture.csv").unlink()
p = run(posture)
check(p.returncode == 2 and "no finished direct compare run has its folder" in p.stderr
      and len(p.stderr.strip().splitlines()) == 1, f"no folder and no cache: {p.returncode} {p.stderr}")
check((results / "posture.md").read_bytes() == before and not (results / "compare-posture.csv").exists(),
      "a refusal wrote posture.md or the cache")
(results / "scaling-runs.csv").unlink()
p = run(posture)
check(p.returncode == 2 and "scaling-runs.csv is missing" in p.stderr, f"no ledger: {p.returncode} {p.stderr}")
shutil.rmtree(work)
print("scaling_posture_test: ok")
