#!/usr/bin/env python3
"""Scripts.ScalingCompareAndResults: scripts/scaling-report.py compare-sweeps
picks each tuning study's winner by median best_ever from a synthetic ledger,
writes the ten comparison sweeps (seeds, budgets, robots, the winners' <set>
lines copied), which `cic sweep --dry-run` accepts and whose direct variant has
exactly the tuning run's effective settings; refuses (exit 2, one line, nothing
written) while a tuning study has runs to go, unless --provisional. Then
`results` on a synthetic compare ledger: a real run scored by `cic assess` and
cached, Mann-Whitney against scipy, Holm and A12 against hand-computed values,
the table's verdicts and the figure.

    scaling_compare_test.py SOURCE_DIR CIC WORK_DIR
Exit 77 (skipped) without scipy or matplotlib.
"""
import csv
import io
import pathlib
import re
import shlex
import shutil
import statistics
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
try:
    import matplotlib  # noqa: F401
    from scipy.stats import mannwhitneyu
except ImportError as e:
    print(f"scaling_compare_test: skipped: {e}")
    sys.exit(77)
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
sys.path.insert(0, str(source / "scripts"))
import scaling_compare as sc  # noqa: E402
import scaling_results as sr  # noqa: E402
from study_stats import a12, holm  # noqa: E402

REPORT = [sys.executable, str(source / "scripts" / "scaling-report.py")]


def check(condition, message):
    if not condition:
        print(f"scaling_compare_test: {message}", file=sys.stderr)
        sys.exit(1)


def run(args, **kw):
    return subprocess.run(args, capture_output=True, text=True, **kw)


# ---- tuning files: the shipped ones, their <base> made absolute (they now live in WORK/tuning) ----
tuning = work / "tuning"
tuning.mkdir()
for f in (source / "experiments" / "scaling").glob("tune-*.xml"):
    text = f.read_text().replace("<base>../../settings/", f"<base>{source}/settings/")
    text = text.replace("Simulator.robotFile=../../settings/", f"Simulator.robotFile={source}/settings/")
    (tuning / f.name).write_text(text)

# A ledger where the median and the mean disagree: cmaes-s0.3 has the best mean, sepcmaes-s0.15 the best median.
VALUES = {
    "tune-direct-c8": {"cmaes-s0.15": [1, 2, 3, 4, 5], "cmaes-s0.3": [0, 0, 1, 50, 60],
                       "sepcmaes-s0.15": [4, 4, 6, 7, 7], "sepcmaes-s0.3": [2, 3, 5, 6, 6]},
    # R1's winner is not issue 21's configuration (cmaes, sigma0 0.15): the direct method runs on R1 and R2.
    "tune-direct-r1": {"cmaes-s0.15": [20, 21, 22, 23, 24], "cmaes-s0.3": [10, 10, 10, 10, 10],
                       "sepcmaes-s0.15": [9, 9, 9, 9, 9], "sepcmaes-s0.3": [30, 30, 31, 31, 31]},
    # The second round's configurations too; on c8 one of them wins (switch-sep-0.3, three sets to copy).
    "tune-hybrid-c8": {"offset-s0.1": [3, 3, 3, 3, 3], "offset-s0.3": [1, 1, 2, 9, 9],
                       "offset-s0.1-r0.5": [2, 2, 2, 2, 2], "offset-s0.3-r0.5": [1, 1, 1, 1, 1],
                       "switch-0.3": [5, 5, 5, 5, 5], "switch-0.5": [4, 4, 4, 40, 40],
                       "switch-sep-0.3": [6, 6, 6, 6, 6], "switch-sep-0.5": [2, 2, 2, 2, 2]},
    "tune-hybrid-r1": {"offset-s0.1": [1, 1, 1, 1, 1], "offset-s0.3": [2, 2, 2, 2, 2],
                       "offset-s0.1-r0.5": [1, 1, 1, 1, 1], "offset-s0.3-r0.5": [1, 1, 1, 1, 1],
                       "switch-0.3": [6, 6, 6, 6, 6], "switch-0.5": [7, 7, 7, 7, 7],
                       "switch-sep-0.3": [5, 5, 5, 5, 5]},
}
FIELDS = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit"]


def write_ledger(folder, rows):
    folder.mkdir(parents=True, exist_ok=True)
    with open(folder / "scaling-runs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)


def tuning_rows(drop=None, values=None):
    rows = []
    for study, configs in (values or VALUES).items():
        for config, values in configs.items():
            for seed, v in zip(range(101, 106), values):
                done = (study, config, seed) != drop
                rows.append({"study": study, "config": config, "seed": seed, "status": "done" if done else "pending",
                             "best_ever": v if done else "", "evaluations": 2500, "wall_seconds": 1,
                             "run_dir": f"runs/{config}/s{seed}", "commit": "x"})
    return rows


def compare_sweeps(results, out, *extra):
    return run(REPORT + ["compare-sweeps", "--results", str(results), "--out", str(out), "--tuning", str(tuning),
                         "--cic", cic, *extra])


# ---- refusal: one run of tune-hybrid-r1 to go ----
write_ledger(work / "unfinished", tuning_rows(drop=("tune-hybrid-r1", "switch-0.5", 105)))
p = compare_sweeps(work / "unfinished", work / "refused")
check(p.returncode == 2, f"an unfinished tuning study is refused with exit 2, got {p.returncode}: {p.stderr}")
check(p.stderr.count("\n") == 1 and "tune-hybrid-r1 has 34 of its 35 runs finished" in p.stderr,
      f"one clear line naming the study: {p.stderr!r}")
check(not (work / "refused").exists() or not any((work / "refused").iterdir()), "nothing written when refused")
p = compare_sweeps(work / "unfinished", work / "provisional", "--provisional")
check(p.returncode == 0, f"--provisional writes the sweeps: {p.stderr}")
text = (work / "provisional" / "compare-r1.xml").read_text()
check("PROVISIONAL" in text and "tune-hybrid-r1" in text.split("PROVISIONAL")[1][:200],
      "a provisional file says so and names the unfinished study\n" + text)

# ---- the finished ledger: winners, files, seeds ----
write_ledger(work / "finished", tuning_rows())
out = work / "exp"
p = compare_sweeps(work / "finished", out)
check(p.returncode == 0, f"compare-sweeps on a finished ledger: {p.stderr}")
files = sorted(f.name for f in out.glob("compare-*.xml"))
want = sorted([f"compare-{r}.xml" for r in sc.CENTIPEDES] + ["compare-r1.xml", "compare-r2.xml"])
check(files == want, f"ten sweeps expected, got {files}")
check("PROVISIONAL" not in (out / "compare-centipede-2.xml").read_text(), "a finished tuning is not provisional")
for name in files:
    text = (out / name).read_text()
    variants = re.findall(r'<variant name="([^"]+)">(.*?)</variant>', text)
    names = [v for v, _ in variants]
    if name in ("compare-r1.xml", "compare-r2.xml"):
        check(names == ["direct.sepcmaes-s0.3", "offset-hybrid.offset-s0.3", "switch-hybrid.switch-0.5"],
              f"{name}: R1's direct winner (not issue 21's configuration) and tune-hybrid-r1's winners, got {names}")
        check("its direct runs are not tune-direct-r1's" in text, f"{name}: says why the direct method runs\n" + text)
        check("<set>Gait.evaluations=15000</set>" in text, f"{name}: 15,000 evaluations")
        check(f"<set>Simulator.robot_type={name[-5]}</set>" in text, f"{name}: its robot type")
        check("collisionSpace" not in text, f"{name}: R1 and R2 keep the default collision space")
    else:
        robot = name[len("compare-"):-4]
        check(names == ["direct.sepcmaes-s0.15", "hypergp-gait", "offset-hybrid.offset-s0.1",
                        "switch-hybrid.switch-sep-0.3"], f"{name}: the winners by median, got {names}")
        check(f"settings/robots/{robot}.xml</set>" in text and "<set>Simulator.collisionSpace=1</set>" in text,
              f"{name}: its robot and the sweep collision space")
        check("<set>Gait.evaluations=2500</set>" in text, f"{name}: 2,500 evaluations")
        direct = dict(variants)["direct.sepcmaes-s0.15"]
        check(direct.endswith("<set>Gait.optimizer=sepcmaes</set><set>Gait.sigma0=0.15</set>"),
              f"{name}: the tuning variant's own <set> lines, copied: {direct}")
        check(dict(variants)["offset-hybrid.offset-s0.1"] ==
              "<set>Neural.switchPatience=0</set><set>Neural.switchShare=0</set><set>Neural.directOffsets=1</set>"
              "<set>Neural.offsetSigma=0.1</set>", f"{name}: the offset winner's sets")
    seeds = 10   # every robot, the middle sizes too since their seeds 6..10 came back
    check(f'<repeats count="{seeds}" firstSeed="1" seeds="same"/>' in text, f"{name}: comparison seeds 1..{seeds}")
    check(("seeds 6..10 came back" in text) == (name[len("compare-"):-4] in sc.MIDDLE),
          f"{name}: the comment states the seeds and why")
    p = run([cic, "sweep", str(out / name), "--output", str(work / "dry" / name[:-4]), "--dry-run"])
    check(p.returncode == 0, f"cic sweep --dry-run refuses {name}: {p.stderr}")
    check(f"{len(names)} configurations x {seeds} repeats" in p.stdout, f"{name}: {p.stdout.splitlines()[0]}")


def effective(sweep, config, seed):
    """`cic settings` of the command `cic sweep --dry-run --csv` gives for one run, seed left out."""
    p = run([cic, "sweep", str(sweep), "--output", str(work / "dry" / sweep.stem), "--dry-run", "--csv"])
    row = next(r for r in csv.DictReader(io.StringIO(p.stdout)) if r["run_dir"] == f"runs/{config}/s{seed}")
    args = shlex.split(row["command"])
    q = run([cic, "settings", args[2]] + args[3:])
    check(q.returncode == 0, f"cic settings of {config}: {q.stderr}")
    return re.sub(r"<seed>\d+</seed>", "", q.stdout)


# The direct variant on the hybrids' base is the tuning run, key by key.
check(effective(out / "compare-centipede-8.xml", "direct.sepcmaes-s0.15", 1) ==
      effective(tuning / "tune-direct-c8.xml", "sepcmaes-s0.15", 101),
      "the compare direct variant's effective settings are tune-direct-c8's sepcmaes-s0.15")
check(effective(out / "compare-centipede-8.xml", "switch-hybrid.switch-sep-0.3", 1) ==
      effective(tuning / "tune-hybrid-c8.xml", "switch-sep-0.3", 101), "the switch winner is the tuning run")
check("<optimizer>sepcmaes</optimizer>" in effective(out / "compare-centipede-8.xml", "switch-hybrid.switch-sep-0.3", 1),
      "the switch winner hands over to separable CMA-ES, as its tuning runs did")
check(effective(out / "compare-r2.xml", "offset-hybrid.offset-s0.3", 1).replace("<robot_type>2<", "<robot_type>1<") ==
      effective(tuning / "tune-hybrid-r1.xml", "offset-s0.3", 101), "R2's offset hybrid is R1's winner on R2")
check(effective(out / "compare-r1.xml", "direct.sepcmaes-s0.3", 1) ==
      effective(tuning / "tune-direct-r1.xml", "sepcmaes-s0.3", 101), "R1's direct variant is the tuning run")
check(effective(out / "compare-r2.xml", "direct.sepcmaes-s0.3", 1).replace("<robot_type>2<", "<robot_type>1<") ==
      effective(tuning / "tune-direct-r1.xml", "sepcmaes-s0.3", 101), "R2's direct variant is R1's winner on R2")

# When R1's winner is issue 21's configuration, its runs are R1's and R2's direct method: no direct variant.
issue21 = dict(VALUES, **{"tune-direct-r1": dict(VALUES["tune-direct-r1"], **{"cmaes-s0.15": [40] * 5})})
write_ledger(work / "issue21", tuning_rows(values=issue21))
p = compare_sweeps(work / "issue21", work / "exp21")
check(p.returncode == 0, f"compare-sweeps with issue 21's configuration winning: {p.stderr}")
for name in ("compare-r1.xml", "compare-r2.xml"):
    text = (work / "exp21" / name).read_text()
    names = re.findall(r'<variant name="([^"]+)">', text)
    check(names == ["offset-hybrid.offset-s0.3", "switch-hybrid.switch-0.5"], f"{name}: hybrids only, got {names}")
    check("winner cmaes-s0.15, with exactly the settings of issue 21's" in text, f"{name}: says whose runs\n" + text)
check((work / "exp21" / "compare-centipede-8.xml").read_text() == (out / "compare-centipede-8.xml").read_text(),
      "R1's tuning leaves the centipedes' sweeps alone")

# Issue 21's runs fill only the methods a robot's compare runs lack.
base_csv = work / "walk-runs.csv"
base_csv.write_text("study,config,seed,raw_fitness\n" + "".join(
    f"{st},R1,{k},{v}\n" for st, v in (("walk-15000-cmaes-gait", 5.0), ("walk-15000-hgp-gait", 2.0)) for k in (1, 2)))
grouped, borrowed = sr.groups([("compare-r1", "direct.sepcmaes-s0.3", "1", 9.0),
                               ("compare-r1", "offset-hybrid.offset-s0.3", "1", 3.0)], str(base_csv))
check(grouped["r1"] == {"direct": [9.0], "offset-hybrid": [3.0], "hypergp-gait": [2.0, 2.0]} and
      borrowed == {"r1": ["hypergp-gait"]}, f"issue 21 fills HyperGP-gait only: {grouped} {borrowed}")
grouped, borrowed = sr.groups([("compare-r1", "offset-hybrid.offset-s0.3", "1", 3.0)], str(base_csv))
check(grouped["r1"]["direct"] == [5.0, 5.0] and borrowed == {"r1": ["direct", "hypergp-gait"]},
      f"and the direct method where the compare runs none: {grouped} {borrowed}")
grouped, borrowed = sr.groups([("compare-r1", "offset-hybrid.offset-s0.3", "1", 3.0)], str(base_csv),
                              {"r1": {"direct", "offset-hybrid"}})
check("direct" not in grouped["r1"] and borrowed == {"r1": ["hypergp-gait"]},
      f"a direct method the sweep runs, unfinished, is not replaced by issue 21's: {grouped} {borrowed}")

# ---- statistics on known data ----
check(holm([0.01, 0.04, 0.03, 0.5]) == [0.04, 0.09, 0.09, 0.5], f"Holm: {holm([0.01, 0.04, 0.03, 0.5])}")
check(abs(a12([3, 4, 5], [1, 2, 3]) - 8.5 / 9) < 1e-12, "A12 of [3,4,5] over [1,2,3] is 8.5/9")
check(a12([1, 2], [1, 2]) == 0.5, "A12 of equal samples is 0.5")
direct = [float(v) for v in range(10, 20)]
g = {"centipede-2": {"direct": direct, "hypergp-gait": [v + 20 for v in direct],          # all above
                     "offset-hybrid": [v + 0.5 for v in direct],                           # overlapping
                     "switch-hybrid": [v - 20 for v in direct]},                          # all below
     # 23 of 25 pairs won: p = 0.032 alone, 0.063 after Holm over 4 cells
     "centipede-4": {"direct": direct[:5], "hypergp-gait": [12.5, 14.5, 15, 16, 17]}}
s = sr.score(g)
cells = [("centipede-2", "hypergp-gait"), ("centipede-2", "offset-hybrid"), ("centipede-2", "switch-hybrid"),
         ("centipede-4", "hypergp-gait")]
check(list(s) == cells, f"the cells, in order: {list(s)}")
ps = [mannwhitneyu(g[r][m], g[r]["direct"], alternative="two-sided").pvalue for r, m in cells]
for c, p in zip(cells, ps):
    check(abs(s[c]["p"] - p) < 1e-15, f"{c}: Mann-Whitney p {s[c]['p']} against scipy's {p}")
order = sorted(range(4), key=lambda i: ps[i])
running, adjusted = 0.0, [0.0] * 4
for rank, i in enumerate(order):
    running = max(running, min(1.0, (4 - rank) * ps[i]))
    adjusted[i] = running
for c, q in zip(cells, adjusted):
    check(abs(s[c]["holm"] - q) < 1e-15, f"{c}: Holm over the 4 cells {s[c]['holm']} against {q}")
check(s[cells[3]]["p"] < 0.05 < s[cells[3]]["holm"], f"Holm takes centipede-4's cell over 0.05: {s[cells[3]]}")
# A robot with runs to come stays out of the family: its cell keeps its p and gets no Holm p, and the
# others are adjusted over their own 3 cells, whatever its partial runs give.
w = sr.score(g, {"centipede-4"})
check(w[cells[3]]["holm"] is None and w[cells[3]]["p"] == s[cells[3]]["p"], f"the waiting cell: {w[cells[3]]}")
order3 = sorted(range(3), key=lambda i: ps[i])
running, adjusted3 = 0.0, [0.0] * 3
for rank, i in enumerate(order3):
    running = max(running, min(1.0, (3 - rank) * ps[i]))
    adjusted3[i] = running
for c, q in zip(cells[:3], adjusted3):
    check(abs(w[c]["holm"] - q) < 1e-15, f"{c}: Holm over the 3 cells of the finished robot {w[c]['holm']} against {q}")
check(sr.verdict(w[cells[3]], g, "centipede-4") == "runs to come (n = 5 so far)", sr.verdict(w[cells[3]], g, "centipede-4"))
check(s[cells[0]]["a12"] == 1.0 and s[cells[2]]["a12"] == 0.0, "A12 1 above and 0 below")
check(abs(s[cells[0]]["ratio"] - 34.5 / 14.5) < 1e-12, f"ratio of medians {s[cells[0]]['ratio']}")
lo, hi = s[cells[0]]["ratio_ci"]
check(lo <= s[cells[0]]["ratio"] <= hi and lo > 1, f"the ratio's interval holds it: {lo, hi}")
check(sr.ratio_interval([2.0] * 5, [1.0] * 5) == (2.0, 2.0), "constant samples: a point interval")

# ---- results end to end: a real run assessed once, the rest cached ----
studies = work / "studies"
p = run([cic, "--quiet", "--settings", str(source / "settings" / "r1_gait.xml"), "--set", "Gait.evaluations=12",
         "--set", "Gait.populationSize=6", "--output", str(studies / "compare-centipede-2" / "runs" / "direct.x")])
check(p.returncode == 0, f"a tiny gait run: {p.stderr}")
real = next((studies / "compare-centipede-2" / "runs" / "direct.x").iterdir())
p = run([cic, "assess", str(real)])
raw_real = float(next(csv.DictReader(p.stdout.splitlines()))["raw_fitness"])
rows, cache = [], []
for robot, groups in g.items():
    for method, values in groups.items():
        config = "direct.x" if method == "direct" else method + ".y"
        for seed, v in enumerate(values, 1):
            run_dir = f"runs/{config}/s{seed}"
            if robot == "centipede-2" and method == "direct" and seed == 1:
                run_dir = f"runs/direct.x/{real.name}"   # scored by cic assess
            else:
                cache.append({"study": f"compare-{robot}", "config": config, "seed": seed, "best_ever": v + 100,
                              "run_dir": "unused", "raw_fitness": v})
            rows.append({"study": f"compare-{robot}", "config": config, "seed": seed, "status": "done",
                         "best_ever": v + 100, "evaluations": 2500, "wall_seconds": 1, "run_dir": run_dir,
                         "commit": "x"})
results = work / "results"
# centipede-4 has a run to go: its cells are scored, but the figure waits for all its runs.
rows.append({"study": "compare-centipede-4", "config": "hypergp-gait.y", "seed": 6, "status": "pending",
             "best_ever": "", "evaluations": "", "wall_seconds": "", "run_dir": "runs/hypergp-gait.y/s6",
             "commit": "x"})
write_ledger(results, tuning_rows() + rows)
with open(results / "compare-raw.csv", "w", newline="") as f:
    w = csv.DictWriter(f, sr.CACHE_FIELDS, lineterminator="\n")
    w.writeheader()
    w.writerows(cache)
svg = work / "img" / "scaling-ratio.svg"
args = REPORT + ["results", "--results", str(results), "--studies", str(studies), "--cic", cic, "--figure", str(svg),
                 "--baselines", str(work / "none.csv")]
p = run(args)
check(p.returncode == 0, f"results: {p.stderr}")
cached = {(r["study"], r["config"], r["seed"]): r for r in csv.DictReader(open(results / "compare-raw.csv"))}
check(float(cached[("compare-centipede-2", "direct.x", "1")]["raw_fitness"]) == raw_real,
      "the real run's raw eq. 7.1 is cic assess's, cached")
md = (results / "compare.md").read_text()
check("| centipede-2 | 12 | HyperGP-gait | 10 |" in md, "a row per robot and method\n" + md)
check("better than best direct" in md and "worse than best direct" in md, "significant cells say which way\n" + md)
check("| centipede-4 | 24 | HyperGP-gait | 5 |" in md and "runs to come (n = 5 so far) |" in md,
      "the robot with a run to go: its p, no verdict\n" + md)
check("Holm over\nthe 3 cells of the robots whose runs are all in" in md, "the family is the finished robots' cells\n" + md)
check("No difference shown after Holm" not in md, "a robot with runs to come is not called quiet\n" + md)
check("Crossover so far: the smallest robot on which a HyperGP method beats the best direct one after Holm has 12 "
      "hinges: centipede-2 (HyperGP-gait)." in md,
      "the crossover line names the smallest robot won, 'so far' with 8 of the 10 robots missing\n" + md)
# The crossover line on known cells: none won; the smallest of two; "so far" while runs wait.
none = {"centipede-2": {"direct": direct, "switch-hybrid": [v - 20 for v in direct]}}
check(sr.crossover(none, sr.score(none), False) == "Crossover: no HyperGP method beats the best direct one after "
      "Holm on any robot of this table (up to 12 hinges).", f"no win: {sr.crossover(none, sr.score(none), False)}")
two = {"centipede-16": {"direct": direct, "offset-hybrid": [v + 20 for v in direct]},
       "centipede-8-irregular": {"direct": direct, "switch-hybrid": [v + 20 for v in direct]},
       "centipede-8": {"direct": direct, "hypergp-gait": [v - 20 for v in direct]}}
check(sr.crossover(two, sr.score(two), True) == "Crossover so far: the smallest robot on which a HyperGP method beats "
      "the best direct one after Holm has 44 hinges: centipede-8-irregular (Switch-HybrID).",
      f"the smallest of two wins, a loss not counted: {sr.crossover(two, sr.score(two), True)}")
check("| centipede-2 | HyperGP-gait | 2,500 [2,500, 2,500] |" in md, "the real evaluation counts\n" + md)
check("The figure leaves out centipede-4: not all of its runs are in." in md, "an unfinished robot is named\n" + md)
check(sr.complete_robots([{"study": "compare-a", "status": "done"}, {"study": "compare-a", "status": "superseded"},
                          {"study": "compare-b", "status": "done"}, {"study": "compare-b", "status": "running"},
                          {"study": "compare-c", "status": "pending"}]) == {"a"},
      "the figure's robots: every run done, superseded ones aside")
only = {"centipede-2": g["centipede-2"]}
sr.figure(g, sr.score(g), str(work / "img" / "shown.svg"), {"centipede-2"})
sr.figure(only, sr.score(only), str(work / "img" / "only.svg"), {"centipede-2"})
check((work / "img" / "shown.svg").read_bytes() == (work / "img" / "only.svg").read_bytes(),
      "the figure draws the robots shown and no other")
# A filled marker is a cell whose verdict is a difference after Holm: centipede-2's HyperGP-gait
# (all above) and Switch-HybrID (all below); Offset-HybrID (overlapping) stays hollow.
drawn = []
save_svg, sr.save_svg = sr.save_svg, lambda fig, path: drawn.append(fig)
sr.figure(only, sr.score(only), "unused.svg", {"centipede-2"})
sr.save_svg = save_svg
filled = sorted(line.get_marker() for line in drawn[0].axes[0].lines
                if line.get_linestyle() == "None" and line.get_marker() in ("o", "s", "^"))
check(filled == sorted(["o", "^"]),
      f"filled markers for the cells with a difference (o HyperGP-gait, ^ Switch-HybrID), got {filled}")
bars = [line for line in drawn[0].axes[0].lines if line.get_linestyle() != "None" and line.get_marker() in ("o", "s", "^")]
check(len(bars) == 3 and all(line.get_markerfacecolor() == "white" for line in bars), "the bars' own markers are hollow")
check(svg.read_text().lstrip().startswith("<?xml") and "<svg" in svg.read_text(), "the figure is an SVG")
first = svg.read_bytes()
# Scored once: with the run folder gone, the cache still scores it, and the same bytes come out.
shutil.rmtree(real)
p = run(args)
check(p.returncode == 0, f"results from the cache: {p.stderr}")
check(svg.read_bytes() == first, "the figure's bytes are the same from the same runs")
# A finished run neither cached nor on disk is refused.
(results / "compare-raw.csv").write_text(",".join(sr.CACHE_FIELDS) + "\n")
p = run(args)
check(p.returncode == 2 and "is gone" in p.stderr, f"an unscored vanished run is refused: {p.returncode} {p.stderr}")
# ---- the second goal: each hybrid on R1 and R2 against issue 21's IPOP-CMA-ES, a Holm family of its own ----
check(sr.ipop_runs(str(base_csv)) == {"r1": [5.0, 5.0]}, f"issue 21's IPOP runs: {sr.ipop_runs(str(base_csv))}")
ipop = {"r1": direct[::-1], "r2": direct}   # R1's given highest first: the values table sorts them
# R1's best direct method is far ahead of IPOP: the section must face IPOP, not it.
goal = {"r1": {"direct": [v + 100 for v in direct], "offset-hybrid": [v - 20 for v in direct],
               "switch-hybrid": [v + 20 for v in direct]},
        "r2": {"direct": direct, "offset-hybrid": [v + 0.5 for v in direct], "switch-hybrid": [v - 20 for v in direct]}}


def closing(section):
    """The section's verdict line (the paragraph after its table)."""
    return next(x for x in section if x.startswith(("A hybrid", "No hybrid", "So far")))


lines = sr.against_ipop(goal, ipop, False)
text = "\n".join(lines)
# Every run's value, lowest first, after the verdict: IPOP's first, then the study's methods.
values = lines[lines.index(closing(lines)) + 1:]
check(values[:5] == ["", "Each run's raw eq. 7.1 on R1 and R2, lowest first (issue 21's runs for IPOP-CMA-ES and "
                     "HyperGP-gait):", "", "| robot | method | n | runs |", "|---|---|---|---|"] and
      values[5] == "| r1 | IPOP-CMA-ES (issue 21) | 10 | " + ", ".join(f"{x:.1f}" for x in sorted(direct)) + " |" and
      values[7] == "| r1 | Offset-HybrID | 10 | " + ", ".join(f"{x - 20:.1f}" for x in sorted(direct)) + " |" and
      len(values) == 5 + 8, "each run's values\n" + "\n".join(values))
want = sr.score({r: dict({m: goal[r][m] for m in sr.HYBRIDS}, direct=direct) for r in ("r1", "r2")})
check(len(want) == 4 and "Holm over these cells only." in text, "Holm over the section's 4 cells\n" + text)
check(f"| r1 | 12 | IPOP-CMA-ES (issue 21) | 10 | {statistics.median(direct):.2f} |" in text,
      "the reference row is issue 21's IPOP runs\n" + text)
check(f"{want[('r1', 'switch-hybrid')]['holm']:.3g} | 1.00 [1.00, 1.00] |" in text and
      "| better than IPOP-CMA-ES (issue 21) |" in text, "R1's Switch-HybrID beats IPOP (not R1's best direct)\n" + text)
check(closing(lines).startswith("A hybrid beats IPOP-CMA-ES after Holm on R1 only. Cell by cell: R1 Offset-HybrID: "
                           f"worse than IPOP-CMA-ES (issue 21) ({want[('r1', 'offset-hybrid')]['ratio']:.2f} of IPOP's "
                           "median); R1 Switch-HybrID: better than"),
      "the goal's line, R1 only, cell by cell\n" + closing(lines))
check("R2 Offset-HybrID: no difference shown at n = 10 (1.03 of IPOP's median)" in closing(lines), closing(lines))
goal["r2"]["switch-hybrid"] = [v + 20 for v in direct]
check(closing(sr.against_ipop(goal, ipop, True)).startswith("So far, a hybrid beats IPOP-CMA-ES on R1 and R2 after Holm."),
      "both robots won, so far\n" + closing(sr.against_ipop(goal, ipop, True)))
lost = {"r1": {"direct": direct, "offset-hybrid": [v - 20 for v in direct]}}
check(closing(sr.against_ipop(lost, ipop, False)).startswith("No hybrid beats IPOP-CMA-ES on R1 or R2 after Holm."),
      "none won\n" + closing(sr.against_ipop(lost, ipop, False)))
check(sr.against_ipop(g, ipop, False) == [] and sr.against_ipop(lost, {}, False) == [],
      "no section without a hybrid on R1/R2 or without issue 21's runs")
# End to end: `results` reads issue 21's runs from --baselines and says "so far" while R2 has no runs.
r1 = work / "results-r1"
rows, cache = [], []
for method, values in (("direct", [v + 100 for v in direct]), ("switch-hybrid", [v + 20 for v in direct])):
    config = method + ".y"
    for seed, v in enumerate(values, 1):
        rows.append({"study": "compare-r1", "config": config, "seed": seed, "status": "done", "best_ever": v,
                     "evaluations": 15000, "wall_seconds": 1, "run_dir": f"runs/{config}/s{seed}", "commit": "x"})
        cache.append({"study": "compare-r1", "config": config, "seed": seed, "best_ever": v, "run_dir": "unused",
                      "raw_fitness": v})
write_ledger(r1, tuning_rows() + rows)
with open(r1 / "compare-raw.csv", "w", newline="") as f:
    w = csv.DictWriter(f, sr.CACHE_FIELDS, lineterminator="\n")
    w.writeheader()
    w.writerows(cache)
ipop_csv = work / "walk-runs-ipop.csv"
ipop_csv.write_text(base_csv.read_text().splitlines()[0] + "\n" + "".join(
    f"walk-15000-cmaes-gait,R1,{k},{v}\n" for k, v in enumerate(direct, 1)))
p = run(REPORT + ["results", "--results", str(r1), "--studies", str(studies), "--cic", cic,
                  "--figure", str(work / "img" / "r1.svg"), "--baselines", str(ipop_csv)])
md = (r1 / "compare.md").read_text()
check(p.returncode == 0 and "## The second goal: a hybrid against IPOP-CMA-ES on R1 and R2" in md and
      "So far, a hybrid beats IPOP-CMA-ES after Holm on R1 only." in md and
      "| r1 | 12 | Switch-HybrID | 10 |" in md, f"results' second-goal section: {p.stderr}\n" + md)
print("scaling_compare_test: ok")
