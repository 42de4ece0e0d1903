"""The scoring of issue 38's comparison (docs/scaling.md, item 6; scaling-report.py results).

Every method is scored on the raw eq. 7.1 of its replayed best: `cic assess`
replays each finished compare run once, and its raw_fitness is cached in
RESULTS/compare-raw.csv (keyed by study, config, seed and the run's best_ever,
so a rerun run is assessed again). Per robot: median and IQR per method; each
HyperGP method against the best direct one by the two-sided Mann-Whitney U
(scipy), Holm over every cell of the table, A12 with a bootstrap 95 % interval
(study_stats.py, as walk-report.py); the ratio of medians with a bootstrap 95 %
interval against hinge count, regular and irregular centipedes, as an SVG.
R1 and R2 take HyperGP-gait at 15,000 evaluations from issue 21's runs, and
their direct method too unless their compare sweeps run one (compare-sweeps
does when R1's tuning winner is not issue 21's configuration), read
(raw_fitness) from experiments/baselines/results/walk-runs.csv. The issue's
second goal gets a section of its own: each hybrid on R1 and R2 against issue
21's IPOP-CMA-ES, whatever won R1's tuning, Holm over those cells alone."""
import csv
import os
import random
import statistics
import subprocess
import sys

import scaling_compare as sc
from study_stats import a12, a12_interval, holm, mann_whitney_p, quartiles

CACHE_FIELDS = ["study", "config", "seed", "best_ever", "run_dir", "raw_fitness"]
LABELS = {"direct": "best direct", "hypergp-gait": "HyperGP-gait", "offset-hybrid": "Offset-HybrID",
          "switch-hybrid": "Switch-HybrID"}
# issue 21's studies standing in for R1's and R2's direct method and HyperGP-gait (walk-runs.csv)
BASELINE_STUDIES = {"walk-15000-cmaes-gait": "direct", "walk-15000-hgp-gait": "hypergp-gait"}
ALPHA = 0.05
RESAMPLES = 2000


def method_of(config):
    """A compare variant is METHOD.TUNED_CONFIG (scaling_compare.py), or METHOD."""
    return config.split(".")[0]


def robot_of(study):
    return study[len("compare-"):]


def ratio_interval(x, y, resamples=RESAMPLES):
    """Bootstrap 95 % interval of median(x) / median(y), both groups resampled (fixed seed)."""
    rng = random.Random(1)
    values = []
    for _ in range(resamples):
        d = statistics.median([rng.choice(y) for _ in y])
        values.append(statistics.median([rng.choice(x) for _ in x]) / d if d > 0 else float("inf"))
    values.sort()
    return values[int(0.025 * resamples)], values[int(0.975 * resamples) - 1]


def read_cache(path):
    if not os.path.exists(path):
        return {}
    return {(r["study"], r["config"], r["seed"], r["best_ever"]): r for r in csv.DictReader(open(path))}


def write_cache(path, cache):
    sc.write_rows_atomically(path, CACHE_FIELDS, cache)


def assess(cic, run_dirs, out_csv):
    """{run_dir: raw eq. 7.1} of the runs' replayed bests, one `cic assess` for all."""
    p = subprocess.run([cic, "--quiet", "assess", *run_dirs, "--out", out_csv], capture_output=True, text=True)
    if p.returncode != 0:
        raise sc.Refusal(f"results: cic assess failed: {p.stderr.strip()}")
    got = {r["input"]: r["raw_fitness"] for r in csv.DictReader(open(out_csv))}
    os.remove(out_csv)
    missing = [d for d in run_dirs if d not in got]
    if missing:
        raise sc.Refusal(f"results: cic assess gave no row for {missing[0]}")
    return got


def ledger_rows(results):
    """Every row of the ledger, RESULTS/scaling-runs.csv."""
    return list(csv.DictReader(open(os.path.join(results, "scaling-runs.csv"))))


def compare_rows(results):
    """The ledger's compare rows, every status."""
    return [r for r in ledger_rows(results) if r["study"].startswith("compare-")]


def finished(rows):
    return [r for r in rows if r["status"] == "done"]


def unfinished_robots(rows):
    """The robots with a compare run that is neither done nor superseded (left the sweep file)."""
    return {robot_of(r["study"]) for r in rows if r["status"] not in ("done", "superseded")}


def raw_scores(results, studies, cic):
    """[(study, config, seed, raw)] of every finished compare run in the ledger, assessing the new ones."""
    rows = finished(compare_rows(results))
    cache_path = os.path.join(results, "compare-raw.csv")
    cache = read_cache(cache_path)
    todo = {}
    for r in rows:
        key = (r["study"], r["config"], r["seed"], r["best_ever"])
        if key not in cache:
            run_dir = os.path.join(studies, r["study"], r["run_dir"])
            if not sc.finished_run(run_dir):
                raise sc.Refusal(f"results: {r['study']} {r['config']} seed {r['seed']} is done in the ledger but "
                                 f"{run_dir} is gone (or holds a run still going), and compare-raw.csv has no score "
                                 "for it")
            todo[run_dir] = key
    if todo:
        got = assess(cic, list(todo), cache_path + ".assess.csv")
        for run_dir, key in todo.items():
            cache[key] = dict(zip(CACHE_FIELDS, key), run_dir=run_dir, raw_fitness=got[run_dir])
        write_cache(cache_path, cache)
    return [(r["study"], r["config"], r["seed"], float(cache[(r["study"], r["config"], r["seed"], r["best_ever"])]
                                                      ["raw_fitness"])) for r in rows]


def planned_methods(results):
    """{robot: {method}} of every compare run in the ledger, finished or not, but not superseded
    (left the sweep file): what each robot's compare sweep runs."""
    out = {}
    for r in compare_rows(results):
        if r["status"] != "superseded":
            out.setdefault(robot_of(r["study"]), set()).add(method_of(r["config"]))
    return out


def groups(scores, baselines, planned=None):
    """({robot: {method: [raw]}}, {robot: [method taken from issue 21]}): R1 and R2 get issue 21's
    direct and HyperGP-gait runs for the methods their compare sweeps do not run (compare-sweeps
    runs the direct method there when R1's tuning winner is not issue 21's configuration). A
    method a sweep runs (`planned`, finished or not) is never borrowed: until its runs finish,
    its cells wait."""
    out = {}
    for study, config, _, raw in scores:
        out.setdefault(robot_of(study), {}).setdefault(method_of(config), []).append(raw)
    own = {robot: set(methods) | (planned or {}).get(robot, set()) for robot, methods in out.items()}
    borrowed = {}
    if os.path.exists(baselines):
        for r in csv.DictReader(open(baselines)):
            robot, method = r["config"].lower(), BASELINE_STUDIES.get(r["study"])
            if method and robot in out and method not in own[robot]:
                out[robot].setdefault(method, []).append(float(r["raw_fitness"]))
                if method not in borrowed.setdefault(robot, []):
                    borrowed[robot].append(method)
    return out, borrowed


def cells(g):
    """Every (robot, method) of a HyperGP method with a direct side to face: the table's cells."""
    out = []
    for robot in sc.in_study_order(g):
        for m in sc.METHODS[1:]:
            if m in g[robot] and "direct" in g[robot]:
                out.append((robot, m))
    return out


def score(g, waiting=frozenset()):
    """Per cell: n, p, Holm-adjusted p, A12 and its interval, ratio of medians and its interval. The
    cells of a robot in WAITING (runs still to come) get no Holm-adjusted p and stay out of the
    family, so a robot's verdicts do not move with another robot's partial runs; when every run is
    in, the family is every cell."""
    cs = cells(g)
    ps = [mann_whitney_p(g[r][m], g[r]["direct"]) for r, m in cs]
    family = [i for i, (r, _) in enumerate(cs) if r not in waiting]
    adj = [None] * len(cs)
    for i, q in zip(family, holm([ps[i] for i in family])):
        adj[i] = q
    out = {}
    for (r, m), p, q in zip(cs, ps, adj):
        x, y = g[r][m], g[r]["direct"]
        md = statistics.median(y)
        out[(r, m)] = {"p": p, "holm": q, "a12": a12(x, y), "a12_ci": a12_interval(x, y),
                       "ratio": statistics.median(x) / md if md > 0 else float("inf"),
                       "ratio_ci": ratio_interval(x, y)}
    return out


def n_text(g, robot):
    ns = sorted({len(v) for v in g[robot].values()})
    return "n = " + " and ".join(str(n) for n in ns)


def verdict(cell, g, robot, against=LABELS["direct"]):
    if cell["holm"] is None:
        return f"runs to come ({n_text(g, robot)} so far)"
    if cell["holm"] < ALPHA:
        return f"better than {against}" if cell["a12"] > 0.5 else f"worse than {against}"
    return f"no difference shown at {n_text(g, robot)}"


def table(g, sc_cells, against=LABELS["direct"], short="direct"):
    """The table's rows; AGAINST (SHORT in the header) names the group each cell faces, g[robot]["direct"]."""
    out = ["| robot | hinges | method | n | median | IQR | p (Mann-Whitney) | p (Holm) | A12 [95 %] | "
           f"median / {short} [95 %] | verdict |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for robot in sc.in_study_order(g):
        h = sc.hinges(robot)
        for m in sc.METHODS:
            if m not in g[robot]:
                continue
            v = g[robot][m]
            lo, hi = quartiles(v)
            label = against if m == "direct" else LABELS[m]
            row = f"| {robot} | {h} | {label} | {len(v)} | {statistics.median(v):.2f} | [{lo:.2f}, {hi:.2f}] |"
            c = sc_cells.get((robot, m))
            if c is None:
                row += " | | | | |" if m == "direct" else " | | | | no direct runs to face |"
            else:
                holm_text = "" if c["holm"] is None else f"{c['holm']:.3g}"
                row += (f" {c['p']:.3g} | {holm_text} | {c['a12']:.2f} [{c['a12_ci'][0]:.2f}, {c['a12_ci'][1]:.2f}] |"
                        f" {c['ratio']:.2f} [{c['ratio_ci'][0]:.2f}, {c['ratio_ci'][1]:.2f}] |"
                        f" {verdict(c, g, robot, against)} |")
            out.append(row)
    return out


def crossover(g, sc_cells, waiting):
    """The issue's question in one line: the smallest robot (by hinges) on which some HyperGP method beats
    the best direct one after Holm, or none; 'so far' while the study has runs to come (WAITING)."""
    wins = sorted((sc.hinges(r), r, m) for (r, m), c in sc_cells.items()
                  if c["holm"] is not None and c["holm"] < ALPHA and c["a12"] > 0.5)
    lead = "Crossover so far" if waiting else "Crossover"
    if not wins:
        top = max(sc.hinges(r) for r in g)
        return (f"{lead}: no HyperGP method beats the best direct one after Holm on any robot of this table "
                f"(up to {top} hinges).")
    h = wins[0][0]
    at = [(r, m) for hh, r, m in wins if hh == h]
    robots = sorted({r for r, _ in at})
    return (f"{lead}: the smallest robot on which a HyperGP method beats the best direct one after Holm has {h} "
            f"hinges: " + "; ".join(f"{r} ({', '.join(LABELS[m] for rr, m in at if rr == r)})" for r in robots) + ".")


IPOP_LABEL = "IPOP-CMA-ES (issue 21)"
HYBRIDS = ["offset-hybrid", "switch-hybrid"]


def ipop_runs(baselines):
    """{robot: [raw]}: issue 21's IPOP-CMA-ES runs on R1 and R2 at 15,000 evaluations (walk-runs.csv)."""
    out = {}
    if os.path.exists(baselines):
        for r in csv.DictReader(open(baselines)):
            if BASELINE_STUDIES.get(r["study"]) == "direct" and r["config"].lower() in sc.R_ROBOTS:
                out.setdefault(r["config"].lower(), []).append(float(r["raw_fitness"]))
    return out


def against_ipop(g, ipop, waiting, unfinished=frozenset()):
    """The issue's second goal, cell by cell: each hybrid on R1 and R2 against issue 21's IPOP-CMA-ES,
    whichever direct method won R1's tuning. Holm runs over these cells only, a family apart from the
    table's, and, as there, not over a robot in UNFINISHED (runs to come); WAITING says "so far"."""
    h = {r: dict({m: g[r][m] for m in HYBRIDS if m in g.get(r, {})}, direct=ipop[r])
         for r in sc.R_ROBOTS if r in ipop and any(m in g.get(r, {}) for m in HYBRIDS)}
    if not h:
        return []
    s = score(h, unfinished)
    tested = sum(c["holm"] is not None for c in s.values())
    out = ["", "## The second goal: a hybrid against IPOP-CMA-ES on R1 and R2", "",
           "Each hybrid faces issue 21's IPOP-CMA-ES runs at the same 15,000 evaluations (study "
           "walk-15000-cmaes-gait in", "experiments/baselines/results/walk-runs.csv, the method docs/baselines.md "
           "found 2-3 times ahead), with Holm over these cells only"
           + ("" if tested == len(s) else
              f" ({tested} of {len(s)} so far: a robot with runs to come waits for them)") + ".", ""]
    out += table(h, s, IPOP_LABEL, "IPOP")
    won = [r for r in sc.R_ROBOTS if any(c["holm"] is not None and c["holm"] < ALPHA and c["a12"] > 0.5
                                         for (rr, _), c in s.items() if rr == r)]
    lead = "So far, a" if waiting else "A"
    if len(won) == len(sc.R_ROBOTS):
        head = f"{lead} hybrid beats IPOP-CMA-ES on R1 and R2 after Holm."
    elif won:
        head = f"{lead} hybrid beats IPOP-CMA-ES after Holm on {won[0].upper()} only."
    else:
        head = f"{'So far, no' if waiting else 'No'} hybrid beats IPOP-CMA-ES on R1 or R2 after Holm."
    each = "; ".join(f"{r.upper()} {LABELS[m]}: {verdict(c, h, r, IPOP_LABEL)} ({c['ratio']:.2f} of IPOP's median)"
                     for (r, m), c in s.items())
    return out + ["", f"{head} Cell by cell: {each}."] + run_values(g, ipop)


def run_values(g, ipop):
    """Every run's raw eq. 7.1 on R1 and R2, per method, lowest first: a median hides how often a run
    finds a fast gait, and on these robots the runs of one method can fall far apart."""
    out = ["", "Each run's raw eq. 7.1 on R1 and R2, lowest first (issue 21's runs for IPOP-CMA-ES and "
           "HyperGP-gait):", "", "| robot | method | n | runs |", "|---|---|---|---|"]
    for r in sc.in_study_order(set(ipop) | {x for x in sc.R_ROBOTS if x in g}):
        groups = ([(IPOP_LABEL, ipop[r])] if r in ipop else []) + \
                 [(LABELS[m], g[r][m]) for m in sc.METHODS if m in g.get(r, {})]
        for label, v in groups:
            out.append(f"| {r} | {label} | {len(v)} | " + ", ".join(f"{x:.1f}" for x in sorted(v)) + " |")
    return out


def evaluation_counts(results):
    """Lines of the real evaluation counts per robot and method (finished compare runs): GP-based
    methods count every re-bred and re-evaluated individual, so they may pass the budget a little."""
    counts = {}
    for r in finished(compare_rows(results)):
        counts.setdefault((robot_of(r["study"]), method_of(r["config"])), []).append(int(r["evaluations"]))
    out = ["", "Evaluations per run (the real counts; median [least, most]):", "",
           "| robot | method | evaluations |", "|---|---|---|"]
    for (robot, m), v in sorted(counts.items(), key=lambda kv: (sc.study_rank(kv[0][0]), sc.METHODS.index(kv[0][1])
                                                                if kv[0][1] in sc.METHODS else 9)):
        out.append(f"| {robot} | {LABELS.get(m, m)} | {statistics.median(v):,.0f} [{min(v):,}, {max(v):,}] |")
    return out if counts else []


def complete_robots(rows):
    """The robots all of whose compare runs (superseded ones aside) are done: the figure's. An unfinished
    robot's interval would stand for the few runs in so far, or for none (a point without a bar)."""
    return {robot_of(r["study"]) for r in finished(rows)} - unfinished_robots(rows)


def figure(g, sc_cells, path, shown):
    """Each HyperGP method's ratio of medians against hinge count, for the robots in SHOWN."""
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "issue-38"   # fixed ids: the same runs, the same bytes
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.8), sharey=True)
    for ax, irregular in zip(axes, (False, True)):
        robots = [r for r in sc.CENTIPEDES if r.endswith("-irregular") == irregular and r in g and r in shown]
        for k, m in enumerate(sc.METHODS[1:]):
            pts = [(sc.hinges(r), sc_cells[(r, m)]) for r in robots if (r, m) in sc_cells]
            if not pts:
                continue
            x = [h * (1 + 0.04 * (k - 1)) for h, _ in pts]   # methods side by side at each size
            y = [c["ratio"] for _, c in pts]
            err = [[c["ratio"] - c["ratio_ci"][0] for _, c in pts], [c["ratio_ci"][1] - c["ratio"] for _, c in pts]]
            # Hollow: no difference shown after Holm; filled: the cell's verdict is a difference.
            bars = ax.errorbar(x, y, yerr=err, marker="os^"[k], capsize=3, label=LABELS[m], mfc="white")
            hit = [(xi, yi) for xi, yi, (_, c) in zip(x, y, pts) if c["holm"] is not None and c["holm"] < ALPHA]
            if hit:
                ax.plot(*zip(*hit), ls="none", marker="os^"[k], color=bars[0].get_color(), zorder=3)
        ax.axhline(1.0, color="grey", lw=0.8, ls="--")
        ax.set_xscale("log", base=2)
        ax.set_xticks([sc.hinges(r) for r in robots] or [12])
        ax.set_xticklabels([str(sc.hinges(r)) for r in robots] or ["12"])
        ax.set_xlabel("hinges")
        ax.set_title("irregular twins" if irregular else "regular centipedes")
    axes[0].set_ylabel("median raw eq. 7.1 / best direct's")
    if axes[0].get_legend_handles_labels()[0]:
        axes[0].legend(fontsize=8)
    fig.suptitle("Issue 38: each HyperGP method over the best direct one, 2,500 evaluations "
                 "(bootstrap 95 %; filled: p < 0.05 after Holm)", fontsize=9)
    fig.tight_layout()
    save_svg(fig, path)


def save_svg(fig, path):
    """Write FIG to PATH atomically, with no date in it: the same runs, the same bytes."""
    import matplotlib.pyplot as plt
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + ".tmp.svg"
    fig.savefig(tmp, format="svg", metadata={"Date": None})
    plt.close(fig)
    os.replace(tmp, path)


def results(results_dir, studies, cic, figure_path, baselines):
    try:
        import matplotlib  # noqa: F401
        import scipy.stats  # noqa: F401
    except ImportError as e:
        raise sc.Refusal(f"results needs scipy and matplotlib ({e}): run it with Debian's /usr/bin/python3")
    planned = planned_methods(results_dir)
    g, borrowed = groups(raw_scores(results_dir, studies, cic), baselines, planned)
    if not g:
        raise sc.Refusal(f"results: no finished compare run in {os.path.join(results_dir, 'scaling-runs.csv')}")
    rows = compare_rows(results_dir)
    unfinished = unfinished_robots(rows)
    s = score(g, unfinished)
    tested = sum(c["holm"] is not None for c in s.values())
    family = (f"all {tested} cells of the table" if tested == len(s) else
              f"the {tested} cells of the robots whose runs are all in (a robot with runs to come shows its p "
              "but no verdict until they are in)")
    out = ["# The comparison of issue 38 (docs/scaling.md)", "",
           "Written by `scripts/scaling-report.py results` from `scaling-runs.csv`'s compare rows. Every run is",
           "scored on the raw eq. 7.1 of its replayed best (`cic assess`, cached in `compare-raw.csv`). Each",
           "HyperGP method faces the best direct method on the same robot: two-sided Mann-Whitney U, Holm over",
           f"{family}, A12 (the chance that the HyperGP method's run beats the direct one's)",
           "and the ratio of medians with bootstrap 95 % intervals."]
    # "so far" while any of the design's robots, a planned method or a listed run is not in yet
    any_waiting = (bool(unfinished) or any(r not in g for r in sc.ROBOTS) or
                   any(m not in g.get(robot, {}) for robot, ms in planned.items() for m in ms))
    for robot in sorted(g):
        waiting = sorted(m for m in planned.get(robot, set()) if m not in g[robot])
        if waiting:
            out.append(f"{robot}: {' and '.join(LABELS[m] for m in waiting)} "
                       f"{'has' if len(waiting) == 1 else 'have'} no finished run yet.")
    for robot, methods in sorted(borrowed.items()):
        out.append(f"{robot.upper() if robot in sc.R_ROBOTS else robot}: "
                   f"{' and '.join(LABELS[m] for m in methods)} {'is' if len(methods) == 1 else 'are'} issue 21's "
                   "runs at 15,000 evaluations (experiments/baselines/results/walk-runs.csv).")
    out.append("")
    out += table(g, s)
    out += evaluation_counts(results_dir)
    quiet = [r for r in g if r not in unfinished and any((r, m) in s for m in sc.METHODS) and
             not any(s[(r, m)]["holm"] < ALPHA for m in sc.METHODS if (r, m) in s)]
    if quiet:
        out += ["", "No difference shown after Holm: " + "; ".join(f"{r} ({n_text(g, r)})" for r in quiet) + "."]
    out += ["", crossover(g, s, any_waiting)]
    shown = complete_robots(rows)
    left_out = [r for r in sc.in_study_order(g) if r in sc.CENTIPEDES and r not in shown]
    if left_out:
        out += ["", f"The figure leaves out {', '.join(left_out)}: not all of {'its' if len(left_out) == 1 else 'their'} "
                "runs are in."]
    r_waiting = (bool(unfinished & set(sc.R_ROBOTS)) or any(r not in g for r in sc.R_ROBOTS) or
                 any(m not in g.get(robot, {}) for robot in sc.R_ROBOTS for m in HYBRIDS))
    out += against_ipop(g, ipop_runs(baselines), r_waiting, unfinished)
    sc.write_atomically(os.path.join(results_dir, "compare.md"), "\n".join(out) + "\n")
    figure(g, s, figure_path, shown)
    print(f"scaling-report.py: wrote {os.path.join(results_dir, 'compare.md')} and {figure_path}", file=sys.stderr)
