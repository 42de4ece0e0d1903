#!/usr/bin/env python3
"""Scripts.ScalingAnytime: scripts/scaling-report.py anytime on a synthetic
ledger. Its runs' stats.csv are written by hand, so every median is known:
the best found so far at a share of the budget (2,500 evaluations on a
centipede, 15,000 on R1), evaluations past the budget not counted, a run with
no generation by a share counted as "(k of n)", the ratio to the direct
method at the same share, and the final best's raw eq. 7.1 from
compare-raw.csv; and the hand-over table, Switch-HybrID against HyperGP-gait
seed by seed (their points agreeing to 20 %, their gains from 30 % to the end,
which ends ahead); and what each Switch-HybrID run handed over, read from
its run.log against the best of its stats.csv up to the hand-over (a
hand-over logged twice by a resumed session is one; two different ones are
refused, as is a folder without its run.log). One stats.csv comes from a real tiny gait run, so the
columns cic writes are the ones read. The points are cached: with the run
folders gone the page and the figure come out byte for byte the same, and
hand-overs never recorded are named as such. The
refusals (a finished run with neither folder nor cached points): exit 2, one
line, nothing written.

    scaling_anytime_test.py SOURCE_DIR CIC WORK_DIR
Exit 77 (skipped) without matplotlib.
"""
import csv
import pathlib
import shutil
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
try:
    import matplotlib  # noqa: F401
except ImportError as e:
    print(f"scaling_anytime_test: skipped: {e}")
    sys.exit(77)
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
REPORT = [sys.executable, str(source / "scripts" / "scaling-report.py")]
LEDGER = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit"]
STATS = ["generation", "best", "mean", "evaluations"]


def check(condition, message):
    if not condition:
        print(f"scaling_anytime_test: {message}", file=sys.stderr)
        sys.exit(1)


def run(args):
    return subprocess.run(args, capture_output=True, text=True)


studies, results = work / "studies", work / "results"
results.mkdir()
rows, raw = [], []


def add(study, config, seed, generations, status="done", final=None, handover=None):
    """A run of STUDY whose generation k ends at generations[k] = (cumulative evaluations, best); a
    Switch-HybrID run's HANDOVER = (generation, why, fitness handed over) goes in its run.log."""
    run_dir = f"runs/{config}/s{seed}"
    folder = studies / study / run_dir
    folder.mkdir(parents=True)
    if config.startswith("switch-hybrid"):
        lines = ["cic: a run.log"]
        if handover:
            g, why, fitness = handover
            lines.append(f"switch: HyperGP hands over after generation {g} ({generations[g][0]} evaluations): {why}; "
                         f"sepcmaes starts from individual 7's gait (fitness {fitness!r}) for the remaining "
                         f"{2500 - generations[g][0]} evaluations")
        (folder / "run.log").write_text("\n".join(lines) + "\n")
    (folder / "summary.txt").write_text("status: done\n")   # a run that ended (a rerun under way has none)
    with open(folder / "stats.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(STATS)
        for k, (evaluations, best) in enumerate(generations):
            w.writerow([k, best, best / 2, evaluations])
    best_ever = max(b for _, b in generations)
    rows.append(dict(study=study, config=config, seed=seed, status=status, best_ever=repr(best_ever),
                     evaluations=generations[-1][0], wall_seconds=1, run_dir=run_dir, commit="x"))
    if final is not None:
        raw.append(dict(study=study, config=config, seed=seed, best_ever=repr(best_ever), run_dir=str(folder),
                        raw_fitness=final))


C2, D, H, S = "compare-centipede-2", "direct.sepcmaes-s0.15", "hypergp-gait", "switch-hybrid.switch-sep-0.3"
# Direct: 10 % of 2,500 is 250 evaluations, 20 % 500, 30 % 750, 50 % 1,250, 70 % 1,750, 100 % 2,500.
add(C2, D, 1, [(250, 2.0), (500, 4.0), (750, 6.0), (1250, 8.0), (2500, 10.0)], final=10.0)
add(C2, D, 2, [(250, 4.0), (500, 6.0), (750, 8.0), (1250, 10.0), (2500, 12.0)], final=12.0)
# HyperGP-gait: its first generation ends past 10 % in seed 2 ("1 of 2" there); it loses its best
# (final below best found); seed 1's last generation passes the budget and does not count.
add(C2, H, 1, [(200, 5.0), (500, 5.0), (700, 7.0), (1300, 7.0), (2400, 8.0), (2600, 99.0)], final=6.0)
add(C2, H, 2, [(300, 3.0), (450, 4.0), (760, 9.0), (1250, 4.0), (2500, 4.0)], final=4.0)
# Switch-HybrID: the gait phase continues the HyperGP phase's count.
add(C2, S, 1, [(250, 5.0), (765, 6.0), (821, 6.5), (2500, 20.0)], final=20.0,
    handover=(1, "it has spent 765 of 2500 evaluations (switchShare 0.3)", 6.0))
# Stopped as it handed over and resumed: the same hand-over logged twice is one.
C2_LOG = studies / C2 / "runs" / S / "s1" / "run.log"
HANDOVER_LINE = C2_LOG.read_text().splitlines()[1]
C2_LOG.write_text(C2_LOG.read_text() + HANDOVER_LINE + "\n")
# The hand-over table's pairs (Switch-HybrID and HyperGP-gait of one seed) on centipede-4: seed 1 the
# same to 20 %, its Switch-HybrID gaining nothing after 30 % and ending behind; seed 2 apart at 10 %,
# Switch-HybrID ahead; seed 3 without a partner.
C4 = "compare-centipede-4"
add(C4, H, 1, [(250, 5.0), (600, 6.0), (1000, 8.0), (2500, 10.0)], final=9.0)
# What they handed over: seed 1 on stagnation, 5.6 against the 7.0 found by then (20 % short), its gait
# phase never passing 7.0; seed 2 at its share, its last generation's best the best found.
add(C4, S, 1, [(250, 5.0), (600, 6.0), (700, 7.0), (2500, 7.0)], final=6.5,
    handover=(2, "its best (7, generation 2) has not improved for 10 generations", 5.6))
add(C4, H, 2, [(250, 4.0), (600, 5.0), (2500, 6.0)], final=6.0)
add(C4, S, 2, [(250, 4.5), (600, 5.0), (2500, 12.0)], final=12.0,
    handover=(1, "it has spent 600 of 2500 evaluations (switchShare 0.3)", 5.0))
add(C4, H, 3, [(250, 4.0), (2500, 6.0)], final=6.0)
# centipede-8: a Switch-HybrID run whose HyperGP spent the budget (its summary.txt says there was no
# room for the gait phase), and one whose hand-over record goes with its folder before it was cached.
C8 = "compare-centipede-8"
add(C8, S, 1, [(250, 3.0), (2500, 4.0)], final=4.0)
(studies / C8 / "runs" / S / "s1" / "summary.txt").write_text(
    "HyperGP phase:\nstopped: handed over at generation 1\nthe budget leaves no room for the gait phase\n")
add(C8, S, 2, [(250, 3.0), (700, 3.5), (2500, 5.0)], final=5.0,
    handover=(1, "it has spent 700 of 2500 evaluations (switchShare 0.3)", 3.5))
# Not counted: a superseded configuration, a failed run, a tuning run.
add(C2, "switch-hybrid.switch-0.3", 1, [(250, 50.0), (2500, 50.0)], status="superseded")
add(C2, D, 3, [(250, 50.0)], status="failed")
add("tune-direct-c8", "sepcmaes-s0.15", 101, [(250, 50.0)])
# R1: 15,000 evaluations; 10 % is 1,500.
add("compare-r1", D, 1, [(1500, 3.0), (15000, 30.0)], final=30.0)


def gait_run():
    """A tiny real gait run's folder (16 evaluations, 8 per generation)."""
    p = run([cic, "--quiet", "--settings", str(source / "settings" / "r1_gait.xml"), "--seed", "1",
             "--set", "Gait.evaluations=16", "--set", "Gait.populationSize=8", "--set", "Simulator.sample_to=2",
             "--set", "Simulator.delayed_start=0.5", "--set", "Experiment.workers=1", "--output", str(work / "tiny")])
    check(p.returncode == 0, f"a tiny gait run: {p.stderr}")
    return next((work / "tiny").iterdir())


tiny = gait_run()
tiny_rows = list(csv.DictReader(open(tiny / "stats.csv")))
tiny_best = max(float(r["best"]) for r in tiny_rows)
shutil.copytree(tiny, studies / "compare-r2" / "runs" / D / "s1")
rows.append(dict(study="compare-r2", config=D, seed=1, status="done", best_ever=repr(tiny_best),
                 evaluations=tiny_rows[-1]["evaluations"], wall_seconds=1, run_dir=f"runs/{D}/s1", commit="x"))

with open(results / "scaling-runs.csv", "w", newline="") as f:
    w = csv.DictWriter(f, LEDGER, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
with open(results / "compare-raw.csv", "w", newline="") as f:
    w = csv.DictWriter(f, ["study", "config", "seed", "best_ever", "run_dir", "raw_fitness"], lineterminator="\n")
    w.writeheader()
    w.writerows(raw)

figure = work / "anytime.svg"
anytime = [*REPORT, "anytime", "--results", str(results), "--studies", str(studies), "--figure", str(figure)]
p = run(anytime)
check(p.returncode == 0, f"anytime failed: {p.stderr}")
text = (results / "anytime.md").read_text()
first, _, handover = text.partition("## The hand-over, seed by seed")
handover, _, handed = handover.partition("## What Switch-HybrID handed over")


def cells(part):
    return [[x.strip() for x in line.split("|")[1:-1]] for line in part.splitlines()
            if line.startswith("| ") and not line.startswith("| robot")]


table = {(c[0], c[2]): c for c in cells(first)}
check(set(table) == {("centipede-2", "best direct"), ("centipede-2", "HyperGP-gait"),
                     ("centipede-2", "Switch-HybrID"), ("centipede-4", "HyperGP-gait"),
                     ("centipede-4", "Switch-HybrID"), ("centipede-8", "Switch-HybrID"), ("r1", "best direct"),
                     ("r2", "best direct")},
      f"rows: {sorted(table)}\n{text}")
# The hand-over, seed by seed: robot, hinges, pairs, same to 20 %, best by 30 %, HyperGP-gait's gain,
# Switch-HybrID's gain, gained nothing, ends ahead, final ratio (median).
check(cells(handover) == [["centipede-2", "12", "1", "1 of 1", "5.00", "+1.00", "+15.00", "0 of 1", "1 of 1", "3.33"],
                          ["centipede-4", "24", "2", "1 of 2", "6.00", "+2.50", "+3.50", "1 of 2", "1 of 2", "1.36"]],
      f"the hand-over table: {cells(handover)}\n{text}")
# What was handed over: robot, hinges, runs recorded, handed over, at evaluations (median), on stagnation,
# below the best found, shortfall median [max], gait phase passed the best found.
check(cells(handed) == [["centipede-2", "12", "1 of 1", "1 of 1", "765", "0 of 1", "0 of 1", "0.0 % [0.0 %]",
                         "1 of 1"],
                        ["centipede-4", "24", "2 of 2", "2 of 2", "650", "1 of 2", "1 of 2", "10.0 % [20.0 %]",
                         "1 of 2"],
                        ["centipede-8", "48", "2 of 2", "1 of 2", "700", "0 of 1", "0 of 1", "0.0 % [0.0 %]",
                         "1 of 1"]],
      f"what was handed over: {cells(handed)}\n{text}")
check("is recorded" not in handed, f"every Switch-HybrID run is recorded here: {handed}")
# robot, hinges, method, n, 10 %, 20 %, 30 %, 50 %, 70 %, 100 %, final
check(table[("centipede-2", "best direct")][1:] == ["12", "best direct", "2", "3.00", "5.00", "7.00", "9.00",
                                                    "9.00", "11.00", "11.00"], f"direct: {table[('centipede-2', 'best direct')]}")
check(table[("centipede-2", "HyperGP-gait")][3:] == ["2", "5.00 (1 of 2) ×1.67", "4.50 ×0.90", "5.50 ×0.79",
                                                     "8.00 ×0.89", "8.00 ×0.89", "8.50 ×0.77", "5.00"],
      f"HyperGP-gait: {table[('centipede-2', 'HyperGP-gait')]}")
check(table[("centipede-2", "Switch-HybrID")][3:] == ["1", "5.00 ×1.67", "5.00 ×1.00", "5.00 ×0.71", "6.50 ×0.72",
                                                      "6.50 ×0.72", "20.00 ×1.82", "20.00"],
      f"Switch-HybrID: {table[('centipede-2', 'Switch-HybrID')]}")
check(table[("r1", "best direct")][4] == "3.00" and table[("r1", "best direct")][9] == "30.00",
      f"R1's budget is 15,000: {table[('r1', 'best direct')]}")
check(table[("r2", "best direct")][4] == f"{tiny_best:.2f}", f"a real run's stats.csv: {table[('r2', 'best direct')]} "
      f"against its best {tiny_best}")
check("scripts/scaling-report.py anytime" in text, "the page names its command")
check(figure.read_text().startswith("<?xml"), "the figure is an SVG")

# The cache: with the run folders gone, the same page and the same figure bytes.
page, svg = (results / "anytime.md").read_bytes(), figure.read_bytes()
shutil.rmtree(studies)
p = run(anytime)
check(p.returncode == 0, f"anytime from the cache failed: {p.stderr}")
check((results / "anytime.md").read_bytes() == page, "the page changed when read from the cache")
check(figure.read_bytes() == svg, "the figure's bytes changed when read from the cache")
check((results / "compare-handover.csv").is_file(), "the hand-overs were not cached")

# A robot with a run recorded and one not (its record gone with its folder): counted apart.
handover_cache = (results / "compare-handover.csv").read_bytes()
kept = [line for line in handover_cache.decode().splitlines(keepends=True) if not line.startswith(f"{C8},{S},2,")]
(results / "compare-handover.csv").write_text("".join(kept))
p = run(anytime)
mixed = cells((results / "anytime.md").read_text().partition("## What Switch-HybrID handed over")[2])
check(p.returncode == 0 and mixed[-1] == ["centipede-8", "48", "1 of 2", "0 of 1", "–", "–", "–", "–", "–"],
      f"a robot with one record of two: {p.stderr} {mixed}")
(results / "compare-handover.csv").write_bytes(handover_cache)

# Hand-overs not recorded before the folders went: the page says so, and the other tables stay.
(results / "compare-handover.csv").unlink()
p = run(anytime)
check(p.returncode == 0, f"anytime without the hand-over records failed: {p.stderr}")
unrecorded = (results / "anytime.md").read_text()
check("No Switch-HybrID run of centipede-2, centipede-4, centipede-8 is recorded" in unrecorded and
      unrecorded.partition("## What Switch-HybrID handed over")[0] == page.decode().partition(
          "## What Switch-HybrID handed over")[0] and
      not cells(unrecorded.partition("## What Switch-HybrID handed over")[2]), f"unrecorded hand-overs: {unrecorded}")

# Refusal: a Switch-HybrID run's folder without its run.log, so what it handed over cannot be read.
check(not (results / "compare-handover.csv").exists(), "nothing to record, yet the hand-over cache was written")
(results / "anytime.md").unlink()
folder = studies / C4 / "runs" / S / "s1"
folder.mkdir(parents=True)
(folder / "stats.csv").write_text("generation,best,mean,evaluations\n0,1.0,0.5,50\n")
(folder / "summary.txt").write_text("status: done\n")
p = run(anytime)
check(p.returncode == 2 and "run.log is missing" in p.stderr and len(p.stderr.strip().splitlines()) == 1,
      f"a Switch-HybrID run without its run.log: exit {p.returncode}, {p.stderr}")
check(not (results / "anytime.md").exists() and not (results / "compare-handover.csv").exists(),
      "a refusal wrote the page or the hand-over cache")
# A run.log that names no hand-over, beside a summary that does not say there was no room: refused,
# not recorded as a run that never handed over.
# Its points are read anew too (their cached row removed), and are not cached by a refused page.
(folder / "run.log").write_text("Switch-HybrID: continuing the gait phase (HyperGP handed over after generation 1)\n")
anytime_cache = (results / "compare-anytime.csv").read_bytes()
(results / "compare-anytime.csv").write_text("".join(
    line for line in anytime_cache.decode().splitlines(keepends=True) if not line.startswith(f"{C4},{S},1,")))
without = (results / "compare-anytime.csv").read_bytes()
p = run(anytime)
check(p.returncode == 2 and "names no hand-over" in p.stderr, f"a log without its hand-over: {p.returncode}, {p.stderr}")
check(not (results / "anytime.md").exists() and not (results / "compare-handover.csv").exists() and
      (results / "compare-anytime.csv").read_bytes() == without, "a refusal wrote the page or a cache")
(results / "compare-anytime.csv").write_bytes(anytime_cache)
# Two different hand-overs in one run.log: refused.
(folder / "run.log").write_text(HANDOVER_LINE + "\n" + HANDOVER_LINE.replace("(fitness 6.0)", "(fitness 5.0)") + "\n")
p = run(anytime)
check(p.returncode == 2 and "2 different hand-overs" in p.stderr, f"two hand-overs: exit {p.returncode}, {p.stderr}")
check(not (results / "anytime.md").exists() and not (results / "compare-handover.csv").exists(),
      "a refusal wrote the page or the hand-over cache")
shutil.rmtree(studies)
(results / "compare-handover.csv").write_bytes(handover_cache)
p = run(anytime)
check(p.returncode == 0 and (results / "anytime.md").read_bytes() == page, f"the page from both caches again: {p.stderr}")

# Refusal: a finished run neither on disk nor cached; nothing written.
with open(results / "scaling-runs.csv", "a", newline="") as f:
    csv.DictWriter(f, LEDGER, lineterminator="\n").writerow(
        dict(study=C2, config=D, seed=4, status="done", best_ever="1.0", evaluations=2500, wall_seconds=1,
             run_dir=f"runs/{D}/s4", commit="x"))
(results / "anytime.md").unlink()
figure.unlink()
cache = (results / "compare-anytime.csv").read_bytes()
p = run(anytime)
check(p.returncode == 2, f"a gone run: exit {p.returncode}, {p.stderr}")
check(len(p.stderr.strip().splitlines()) == 1 and "compare-anytime.csv has no points" in p.stderr,
      f"a gone run's message: {p.stderr}")
check(not (results / "anytime.md").exists() and not figure.exists(), "a refusal wrote the page or the figure")
check((results / "compare-anytime.csv").read_bytes() == cache, "a refusal rewrote the cache")
# Its folder back, as a rerun still going leaves it (a partial stats.csv, no summary.txt): not the
# ledger's run yet, so refused the same way rather than read.
partial = studies / C2 / "runs" / D / "s4"
partial.mkdir(parents=True)
(partial / "stats.csv").write_text("generation,evaluations,best\n0,100,0.5\n")
p = run(anytime)
check(p.returncode == 2 and "still going" in p.stderr and not (results / "anytime.md").exists(),
      f"a run still going was read as the ledger's: exit {p.returncode}, {p.stderr}")
shutil.rmtree(studies)
p = run([*REPORT, "anytime", "--results", str(results)])
check(p.returncode == 2 and "--studies is required" in p.stderr, f"no --studies: {p.returncode} {p.stderr}")
print("scaling_anytime_test: ok")
