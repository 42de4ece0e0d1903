#!/usr/bin/env python3
"""Scripts.ScalingStrips: scripts/scaling-report.py strips on a synthetic
ledger and compare-raw.csv whose picks are two tiny real gait runs: per robot
and method the finished run with the highest cached raw eq. 7.1 (a score of a
run since rerun, a failed run and other robots do not count; ties: the lowest
seed), `cic assess`'s own verdict columns in results/strips.md, the strip PNGs
and their links (only when `cic view` can render: the viewer build and an X
display or xvfb-run; otherwise that part is skipped, saying so), the cache
(compare-strips.csv, one assess row per pick: with the run folders gone the
page comes out of it, keeping the strips drawn before byte for byte, and says
so per pick), and the refusals: exit 2, one line, nothing written.

    scaling_strips_test.py SOURCE_DIR CIC WORK_DIR
"""
import csv
import os
import pathlib
import shutil
import struct
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
REPORT = [sys.executable, str(source / "scripts" / "scaling-report.py")]
LEDGER = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit"]
CACHE = ["study", "config", "seed", "best_ever", "run_dir", "raw_fitness"]
SHOWN = ["verdict", "distance", "elevation", "dominant_hz", "mean_height", "min_height", "final_up", "flipped",
         "shaking"]


def check(condition, message):
    if not condition:
        print(f"scaling_strips_test: {message}", file=sys.stderr)
        sys.exit(1)


def run(args, env=None):
    return subprocess.run(args, capture_output=True, text=True, env=env)


def without_leak_check():
    """The environment for children that render (Mesa's GL drivers under xvfb-run): as
    tests/support/child_env.hpp says, those dlopen modules keep allocations and are unloaded
    at exit, so LeakSanitizer reports `<unknown module>` frames no suppression can name."""
    env = dict(os.environ)
    env["ASAN_OPTIONS"] = (env["ASAN_OPTIONS"] + ":" if env.get("ASAN_OPTIONS") else "") + "detect_leaks=0"
    return env


# ---- two tiny real gait runs (2 s replays, 12 evaluations) and what cic assess says of them ----
real = {}
for name, seed in (("a", "1"), ("b", "2")):
    p = run([cic, "--quiet", "--settings", str(source / "settings" / "r1_gait.xml"), "--seed", seed,
             "--set", "Gait.evaluations=12", "--set", "Gait.populationSize=6", "--set", "Simulator.sample_to=2",
             "--set", "Simulator.delayed_start=0.5", "--output", str(work / "tiny" / name)])
    check(p.returncode == 0, f"a tiny gait run: {p.stderr}")
    real[name] = next((work / "tiny" / name).iterdir())
assessed = {}
for name, folder in real.items():
    p = run([cic, "--quiet", "assess", str(folder)])
    check(p.returncode == 0, f"cic assess {folder}: {p.stderr}")
    assessed[name] = next(csv.DictReader(p.stdout.splitlines()))
raw_a, raw_b = float(assessed["a"]["raw_fitness"]), float(assessed["b"]["raw_fitness"])

# ---- the synthetic study: (robot, config, seed, raw, status, picked run or None) ----
# centipede-16: direct's best is seed 2 (scored as cic assess replays it); a score cached
# for an older best_ever of seed 4 and a failed run's score must not count; hypergp-gait
# ties (the lowest seed wins). centipede-16-irregular has no switch-hybrid run.
# centipede-8's high scores belong to another robot.
D, H, O, S = "direct.sepcmaes-s0.15", "hypergp-gait", "offset-hybrid.offset-s0.1", "switch-hybrid.switch-0.3"
ENTRIES = [
    ("centipede-16", D, 1, raw_a - 1, "done", None), ("centipede-16", D, 2, raw_a, "done", "a"),
    ("centipede-16", D, 3, raw_a - 0.5, "done", None),
    ("centipede-16", H, 1, 2.0, "done", "a"), ("centipede-16", H, 2, 2.0, "done", None),
    ("centipede-16", O, 1, 0.5, "done", None), ("centipede-16", O, 2, 0.7, "done", "a"),
    ("centipede-16", S, 1, 4.0, "done", None), ("centipede-16", S, 2, 6.0, "done", "a"),
    ("centipede-16", S, 3, 50.0, "failed", None),
    ("centipede-16-irregular", D, 1, raw_b, "done", "b"), ("centipede-16-irregular", H, 1, 1.0, "done", "b"),
    ("centipede-16-irregular", O, 1, 8.0, "done", "b"), ("centipede-16-irregular", O, 2, 7.0, "done", None),
    ("centipede-8", D, 1, 90.0, "done", None),
]
STALE = ("centipede-16", D, 4, 99.0)   # cached for best_ever 104; the ledger now has 204 (the run was rerun)


def make_results(folder, studies, entries=ENTRIES, cache=True):
    folder.mkdir(parents=True)
    ledger, cached = [], []
    for robot, config, seed, raw, status, pick in entries:
        run_dir = f"runs/{config}/s{seed}"
        ledger.append({"study": f"compare-{robot}", "config": config, "seed": seed, "status": status,
                       "best_ever": raw + 100, "evaluations": 2500, "wall_seconds": 1, "run_dir": run_dir,
                       "commit": "x"})
        cached.append({"study": f"compare-{robot}", "config": config, "seed": seed, "best_ever": raw + 100,
                       "run_dir": "unused", "raw_fitness": repr(raw)})
        if pick is not None and studies is not None:
            shutil.copytree(real[pick], studies / f"compare-{robot}" / run_dir)
    robot, config, seed, raw = STALE
    ledger.append({"study": f"compare-{robot}", "config": config, "seed": seed, "status": "done", "best_ever": 204,
                   "evaluations": 2500, "wall_seconds": 1, "run_dir": f"runs/{config}/s{seed}", "commit": "x"})
    cached.append({"study": f"compare-{robot}", "config": config, "seed": seed, "best_ever": 104, "run_dir": "x",
                   "raw_fitness": raw})
    for name, fields, rows in (("scaling-runs.csv", LEDGER, ledger), ("compare-raw.csv", CACHE, cached)):
        if name == "compare-raw.csv" and not cache:
            continue
        with open(folder / name, "w", newline="") as f:
            w = csv.DictWriter(f, fields, lineterminator="\n")
            w.writeheader()
            w.writerows(rows)


def strips(results, studies, *extra, env=None):
    return run(REPORT + ["strips", "--results", str(results), "--studies", str(studies), "--cic", cic, *extra], env)


def refused(p, text, results, images=None):
    check(p.returncode == 2, f"exit 2 expected ({text}), got {p.returncode}: {p.stderr}")
    check(p.stderr.count("\n") == 1 and text in p.stderr, f"one clear line saying '{text}': {p.stderr!r}")
    check(not (results / "strips.md").exists(), f"nothing written when refused ({text})")
    check(images is None or not images.exists(), f"no image written when refused ({text})")


studies = work / "studies"
results = work / "results"
make_results(results, studies)

# ---- refusals ----
make_results(work / "no-cache", None, cache=False)
refused(strips(work / "no-cache", studies, "--no-strips"), "compare-raw.csv is missing", work / "no-cache")
refused(strips(results, studies, "--robots", "centipede-8-irregular", "--out-images", str(work / "r1")),
        "centipede-8-irregular: no finished compare-centipede-8-irregular run is scored", results, work / "r1")
refused(strips(results, studies, "--robots", "centipede-99"), "unknown robot 'centipede-99' (allowed: centipede-2,",
        results)
refused(strips(results, studies, "--at", "1 x"), "--at takes seconds >= 0", results)
make_results(work / "gone", None)   # the same scores, but no run folder on disk
refused(strips(work / "gone", work / "nowhere", "--no-strips"),
        f"centipede-16 {D} seed 2 is the best direct run, but {work / 'nowhere'}/compare-centipede-16/runs/{D}/s2 "
        f"is gone, and compare-strips.csv has no row for it: one seed fixes a run, so rerun it with `cic sweep {source}/experiments/scaling/compare-centipede-16.xml "
        f"--output {work / 'nowhere'}/compare-centipede-16 --task N`", work / "gone")
p = run(REPORT + ["strips", "--results", str(results), "--cic", cic])
check(p.returncode == 2 and "--studies is required" in p.stderr, f"--studies is required: {p.stderr}")


# ---- the picks and assess's verdicts ----
def row(method, study, run_dir, seed, raw, name):
    a = assessed[name]
    return f"| {method} | {study}/{run_dir} | {seed} | {raw:.3f} | " + " | ".join(a[c] for c in SHOWN) + " |"


WANT = [row("best direct", "compare-centipede-16", f"runs/{D}/s2", 2, raw_a, "a"),
        row("HyperGP-gait", "compare-centipede-16", f"runs/{H}/s1", 1, 2.0, "a"),
        row("Offset-HybrID", "compare-centipede-16", f"runs/{O}/s2", 2, 0.7, "a"),
        row("Switch-HybrID", "compare-centipede-16", f"runs/{S}/s2", 2, 6.0, "a"),
        row("best direct", "compare-centipede-16-irregular", f"runs/{D}/s1", 1, raw_b, "b"),
        row("HyperGP-gait", "compare-centipede-16-irregular", f"runs/{H}/s1", 1, 1.0, "b"),
        row("Offset-HybrID", "compare-centipede-16-irregular", f"runs/{O}/s1", 1, 8.0, "b"),
        "| Switch-HybrID | no finished run scored |"]


def check_tables(md):
    check("## centipede-16 (96 hinges)" in md and "## centipede-16-irregular (88 hinges)" in md,
          "a section per largest robot\n" + md)
    check(md.index("## centipede-16 (96") < md.index("## centipede-16-irregular"), "the regular robot first")
    check("| verdict | distance (m) | elevation (m) | dominant Hz |" in md, "assess's columns as headers\n" + md)
    for w in WANT:
        check(w in md, f"expected row missing: {w}\n{md}")
    check(f"| {assessed['a']['verdict']} |" in md and f"| {assessed['b']['verdict']} |" in md,
          "assess's verdict text in the table")
    check("centipede-8" not in md.replace("centipede-8-", ""), "another robot's runs are not shown\n" + md)
    check("99.000" not in md and "50.000" not in md, "a stale score and a failed run are not picked\n" + md)
    check(f"- best direct: {assessed['a']['duty_factors']}" in md, "assess's duty factors per pick\n" + md)
    # The replay check: direct's cached raw is assess's; HyperGP-gait's synthetic 2.0 is not.
    check("- HyperGP-gait: `cic assess` now replays this run to raw" in md and
          "- best direct: `cic assess` now replays" not in md, "a cached raw the replay disagrees with is noted\n" + md)
    check(all(line.count("|") == 14 for line in md.splitlines() if line.startswith("| ")),
          "every table row has the header's 13 cells\n" + md)


# ---- verdicts only ----
p = strips(results, studies, "--no-strips", "--out-images", str(work / "unused"))
check(p.returncode == 0, f"strips --no-strips: {p.stderr}")
md = (results / "strips.md").read_text()
check_tables(md)
check("No strips were drawn (--no-strips)." in md and "![" not in md, "no image links without strips\n" + md)
check(not (work / "unused").exists(), "no images without strips")


def shown(path):
    """A path as the page names it: from the repository's root when inside it (the test's work
    folder is, in a build folder under the source tree), else as given."""
    real, root = os.path.realpath(path), os.path.realpath(source)
    return os.path.relpath(real, root) if os.path.commonpath([real, root]) == root else str(path)


check(f"scripts/scaling-report.py strips --results {shown(results)} --studies {shown(studies)} --cic {shown(cic)} "
      "--no-strips" in md, "the command that made it\n" + md)

# ---- the picks' folders gone: their cached assess rows (compare-strips.csv, one per pick) ----
cached_rows = list(csv.DictReader(open(results / "compare-strips.csv")))
check(len(cached_rows) == 7 and {r["verdict"] for r in cached_rows} == {assessed["a"]["verdict"], assessed["b"]["verdict"]},
      f"compare-strips.csv: one row per pick, assess's own: {cached_rows}")
shutil.copy(results / "compare-strips.csv", work / "gone" / "compare-strips.csv")
p = strips(work / "gone", work / "nowhere", "--no-strips")
check(p.returncode == 0, f"strips from the cache: {p.stderr}")
gone_md = (work / "gone" / "strips.md").read_text()
check_tables(gone_md)
check(gone_md.count("the run's folder is gone here; its row is the one `cic assess` gave") == 7,
      "each pick from the cache says so\n" + gone_md)
check((work / "gone" / "compare-strips.csv").read_bytes() == (results / "compare-strips.csv").read_bytes(),
      "nothing replayed, so the cache is unchanged")


# ---- with strips, when cic view can render ----
def viewer_missing():
    if run([cic, "view", "--help"]).returncode != 0:
        return f"{cic} has no `cic view` (built without the viewer)"
    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run") is None:
        return "no X display and no xvfb-run"
    return None


why = viewer_missing()
if why:
    p = strips(results, studies)
    check(p.returncode == 2 and "--no-strips writes the verdicts only" in p.stderr, f"no viewer: refused {p.stderr}")
    print(f"scaling_strips_test: skipped the strip PNGs: {why}")
else:
    images = work / "img"
    (results / "strips.md").unlink()
    p = strips(results, studies, "--out-images", str(images), "--at", "0.5 1 1.5", env=without_leak_check())
    check(p.returncode == 0, f"strips: {p.stderr}")
    md = (results / "strips.md").read_text()
    check_tables(md)
    check("No strips were drawn" not in md and "frames at t = 0.5 1 1.5 s" in md, "strips drawn, times said\n" + md)
    pngs = sorted(f.name for f in images.iterdir())
    want = sorted([f"scaling-strip-centipede-16-{m}.png" for m in ("direct", "hypergp-gait", "offset-hybrid",
                                                                    "switch-hybrid")] +
                  [f"scaling-strip-centipede-16-irregular-{m}.png" for m in ("direct", "hypergp-gait",
                                                                              "offset-hybrid")])
    check(pngs == want, f"one strip per pick: {pngs}")
    for name in pngs:
        head = (images / name).read_bytes()[:24]
        check(head[:8] == b"\x89PNG\r\n\x1a\n", f"{name} is a PNG")
        width, height = struct.unpack(">II", head[16:24])
        check((width, height) == (3 * 320, 240), f"{name}: three 320x240 frames side by side, got {width}x{height}")
    check(f"![centipede-16, best direct: compare-centipede-16/runs/{D}/s2](../img/scaling-strip-centipede-16-direct.png)"
          in md, "the strip's link, relative to results/\n" + md)
    check("scaling-strip-centipede-16-irregular-switch-hybrid.png" not in md, "no link without a run")
    # The folders gone: the strips drawn before stay, byte for byte; without them, refused.
    drawn = {f.name: f.read_bytes() for f in images.iterdir()}
    (work / "gone" / "strips.md").unlink()
    p = strips(work / "gone", work / "nowhere", "--out-images", str(images))
    check(p.returncode == 0 and {f.name: f.read_bytes() for f in images.iterdir()} == drawn,
          f"strips with the folders gone keep the strips drawn before: {p.stderr}")
    check("(../img/scaling-strip-centipede-16-direct.png)" in (work / "gone" / "strips.md").read_text(),
          "the kept strips are linked")
    (work / "gone" / "strips.md").unlink()
    refused(strips(work / "gone", work / "nowhere", "--out-images", str(work / "no-img")),
            f"is gone, and its strip {work / 'no-img'}/scaling-strip-centipede-16-direct.png is missing", work / "gone",
            work / "no-img")
print("scaling_strips_test: ok")
