"""How fast each method of issue 38's comparison finds its walk (scaling-report.py anytime).

Veenstra et al. 2017 found a generative encoding more efficient early in a run
and no different later; Switch-HybrID bets on that. This module measures it on
the comparison's own runs: for every finished compare run, the best fitness it
had found by 5 %, 10 %, ..., 100 % of its budget (2,500 evaluations on the
centipedes, 15,000 on R1 and R2), read from the run's stats.csv (column `best`
per generation, `evaluations` cumulative, Switch-HybrID's gait phase
continuing its HyperGP phase's count). Evaluations past the budget do not
count, so the GP methods' re-bred extra evaluations (scaling_results.py's
counts) are cut off here.

These are the fitnesses the runs recorded, the best found so far: the direct
method keeps its best gait, so its 100 % point is the score it is judged on.
HyperGP-gait and Offset-HybrID keep no elite (Table B.1, elitism 0), so the
individual a run ends with can be worse than the best it found; the
comparison's table (scaling_results.py) scores that final individual's raw
eq. 7.1. The page lists both, so the cost of losing the best shows.

Each run's points are cached in RESULTS/compare-anytime.csv (keyed like
compare-raw.csv by study, config, seed and best_ever), so the table and the
figure can be written again without the run folders. The page's third table,
what Switch-HybrID handed over, is scaling_handover.py's."""
import csv
import os
import statistics
import sys

import scaling_compare as sc
from scaling_handover import handover_gap_table, handover_records
from scaling_results import LABELS, compare_rows, finished, method_of, read_cache, robot_of, save_svg

STEPS = [5 * k for k in range(1, 21)]   # per cent of the budget
TABLE_STEPS = [10, 20, 30, 50, 70, 100]
CACHE_FIELDS = ["study", "config", "seed", "best_ever", "budget"] + [f"at_{s}" for s in STEPS]


def budget_of(robot):
    return sc.R_BUDGET if robot in sc.R_ROBOTS else sc.CENTIPEDE_BUDGET


def best_so_far(stats_path, budget):
    """[best fitness found within s % of the budget, for s in STEPS] from a run's stats.csv ('' where no
    generation had finished by then)."""
    rows = list(csv.DictReader(open(stats_path)))
    if not rows or "best" not in rows[0] or "evaluations" not in rows[0]:
        raise sc.Refusal(f"anytime: {stats_path} has no 'best' and 'evaluations' columns")
    points = []   # (cumulative evaluations, best so far)
    best = float("-inf")
    for r in rows:
        best = max(best, float(r["best"]))
        points.append((int(r["evaluations"]), best))
    out = []
    for s in STEPS:
        limit = budget * s / 100
        got = [b for e, b in points if e <= limit]
        out.append(repr(got[-1]) if got else "")
    return out


def anytime_rows(results, studies, ledger, writes):
    """{(study, config, seed): [value or None per STEPS]} of LEDGER's finished compare runs (superseded
    rows left out), reading the new ones' stats.csv; their cache's new text goes on WRITES, (path,
    fields, rows), for the caller to write once nothing more can be refused."""
    cache_path = os.path.join(results, "compare-anytime.csv")
    cache = read_cache(cache_path)
    changed = False
    out = {}
    for r in ledger:
        key = (r["study"], r["config"], r["seed"], r["best_ever"])
        if key not in cache:
            folder = os.path.join(studies, r["study"], r["run_dir"])
            stats = os.path.join(folder, "stats.csv")
            if not sc.finished_run(folder) or not os.path.isfile(stats):
                raise sc.Refusal(f"anytime: {r['study']} {r['config']} seed {r['seed']} is done in the ledger "
                                 f"but {stats} is gone (or its run is still going), and compare-anytime.csv has "
                                 "no points for it")
            budget = budget_of(robot_of(r["study"]))
            cache[key] = dict(zip(CACHE_FIELDS, key + (str(budget),)),
                              **dict(zip([f"at_{s}" for s in STEPS], best_so_far(stats, budget))))
            changed = True
        c = cache[key]
        out[key[:3]] = [float(c[f"at_{s}"]) if c[f"at_{s}"] != "" else None for s in STEPS]
    if changed:
        writes.append((cache_path, CACHE_FIELDS, cache))
    return out


def by_method(rows):
    """{robot: {method: [[value per STEPS] per run]}}"""
    g = {}
    for (study, config, _), values in rows.items():
        g.setdefault(robot_of(study), {}).setdefault(method_of(config), []).append(values)
    return g


def values_at(runs, step):
    """The runs' points at STEP per cent, of the runs that had one."""
    k = STEPS.index(step)
    return [r[k] for r in runs if r[k] is not None]


def median_at(runs, step):
    """Median over the runs that had a point by STEP per cent, and how many had one."""
    v = values_at(runs, step)
    return (statistics.median(v) if v else None), len(v)


def raw_by_run(results, ledger):
    """{(study, config, seed): raw eq. 7.1 of the final best} of LEDGER's runs, from compare-raw.csv
    (scaling_results.py)."""
    path = os.path.join(results, "compare-raw.csv")
    if not os.path.exists(path):
        return {}
    runs = {(r["study"], r["config"], r["seed"], r["best_ever"]) for r in ledger}
    return {(r["study"], r["config"], r["seed"]): float(r["raw_fitness"]) for r in csv.DictReader(open(path))
            if (r["study"], r["config"], r["seed"], r["best_ever"]) in runs}


def final_scores(raw):
    """{(robot, method): median raw eq. 7.1 of the final best} of raw_by_run's runs."""
    g = {}
    for (study, config, _), v in raw.items():
        g.setdefault((robot_of(study), method_of(config)), []).append(v)
    return {k: statistics.median(v) for k, v in g.items()}


def handover_table(rows, raw):
    """Switch-HybrID against HyperGP-gait seed by seed, on the centipedes. Until it hands over (on
    stagnation, 10 generations without a better best, so after 11 generations at the earliest, 550
    evaluations at the least; else at 30 % of the budget) a Switch-HybrID run is the HyperGP-gait run of the
    same seed, byte for byte, so each pair shows what handing over did against going on. The page
    checks that the pairs' points agree up to 20 % (500 evaluations), before any hand-over."""
    out = ["| robot | hinges | pairs | same to 20 % | best by 30 % | HyperGP-gait's gain, 30 to 100 % | "
           "Switch-HybrID's gain, 30 to 100 % | Switch-HybrID gained nothing | Switch-HybrID ends ahead | "
           "Switch-HybrID / HyperGP-gait, final |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    k30, k100, early = STEPS.index(30), STEPS.index(100), [STEPS.index(s) for s in STEPS if s <= 20]
    for robot in sc.CENTIPEDES:
        runs = {}
        for (study, config, seed), values in rows.items():
            if robot_of(study) == robot and method_of(config) in ("hypergp-gait", "switch-hybrid"):
                runs.setdefault(seed, {})[method_of(config)] = (values, raw.get((study, config, seed)))
        pairs = [(p["hypergp-gait"], p["switch-hybrid"]) for p in runs.values() if len(p) == 2 and
                 all(v is not None and v[k30] is not None and v[k100] is not None for v, _ in p.values())
                 and all(f is not None for _, f in p.values())]
        if not pairs:
            continue
        same = sum(all(h[0][k] == s[0][k] for k in early) for h, s in pairs)
        gain_h = [h[0][k100] - h[0][k30] for h, _ in pairs]
        gain_s = [s[0][k100] - s[0][k30] for _, s in pairs]
        ahead = sum(s[1] > h[1] for h, s in pairs)
        ratios = [s[1] / h[1] for h, s in pairs if h[1] > 0]
        out.append(f"| {robot} | {sc.hinges(robot)} | {len(pairs)} | {same} of {len(pairs)} | "
                   f"{statistics.median(s[0][k30] for _, s in pairs):.2f} | {statistics.median(gain_h):+.2f} | "
                   f"{statistics.median(gain_s):+.2f} | {sum(g <= 0 for g in gain_s)} of {len(pairs)} | "
                   f"{ahead} of {len(pairs)} | " + (f"{statistics.median(ratios):.2f}" if ratios else "–") + " |")
    return out if len(out) > 2 else []


def table(g, finals):
    head = " | ".join(f"{s} %" for s in TABLE_STEPS)
    out = [f"| robot | hinges | method | n | {head} | raw eq. 7.1 of the final best |",
           "|---|---|---|---|" + "---|" * len(TABLE_STEPS) + "---|"]
    for robot in sc.in_study_order(g):
        direct = g[robot].get("direct")
        for m in sc.METHODS:
            if m not in g[robot]:
                continue
            runs = g[robot][m]
            cells = []
            for s in TABLE_STEPS:
                med, n = median_at(runs, s)
                if med is None:
                    cells.append("–")
                    continue
                text = f"{med:.2f}" + (f" ({n} of {len(runs)})" if n < len(runs) else "")
                if m != "direct" and direct:
                    d, _ = median_at(direct, s)
                    if d:
                        text += f" ×{med / d:.2f}"
                cells.append(text)
            final = finals.get((robot, m))
            out.append(f"| {robot} | {sc.hinges(robot)} | {LABELS[m]} | {len(runs)} | " + " | ".join(cells) +
                       " | " + (f"{final:.2f}" if final is not None else "") + " |")
    return out


def figure(g, path):
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "issue-38-anytime"   # fixed ids: the same runs, the same bytes
    import matplotlib.pyplot as plt
    rows = [[r for r in sc.CENTIPEDES if not r.endswith("-irregular")],
            [r for r in sc.CENTIPEDES if r.endswith("-irregular")], list(sc.R_ROBOTS)]
    fig, axes = plt.subplots(3, 4, figsize=(11, 7.5))
    for row, robots in zip(axes, rows):
        for ax, robot in zip(row, robots + [None] * (4 - len(robots))):
            if robot is None or robot not in g:
                ax.set_visible(robot is not None)
                if robot is not None:
                    ax.set_title(f"{robot}: no runs yet", fontsize=8)
                    ax.set_xticks([])
                    ax.set_yticks([])
                continue
            budget = budget_of(robot)
            for k, m in enumerate(sc.METHODS):
                if m not in g[robot]:
                    continue
                xs, med, lo, hi = [], [], [], []
                for s in STEPS:
                    v = values_at(g[robot][m], s)
                    if len(v) * 2 < len(g[robot][m]):
                        continue   # fewer than half the runs had a point: no median worth drawing
                    q = statistics.quantiles(v, n=4, method="inclusive") if len(v) > 1 else [v[0]] * 3
                    xs.append(budget * s / 100)
                    med.append(statistics.median(v))
                    lo.append(q[0])
                    hi.append(q[2])
                line, = ax.plot(xs, med, marker="os^v"[k], ms=3, lw=1.2, color=f"C{k}",
                                label=f"{LABELS[m]} (n = {len(g[robot][m])})")
                ax.fill_between(xs, lo, hi, alpha=0.15, color=line.get_color())
            ax.set_title(f"{robot} ({sc.hinges(robot)} hinges)", fontsize=9)
            ax.tick_params(labelsize=7)
            ax.legend(fontsize=6, loc="lower right")
    for ax in axes[:, 0]:
        ax.set_ylabel("best fitness found so far", fontsize=8)
    for ax in axes[-1, :2]:
        ax.set_xlabel("evaluations", fontsize=8)
    fig.suptitle("Issue 38: the best fitness each run had found by each share of its budget "
                 "(median and IQR; recorded eq. 7.1)", fontsize=10)
    fig.tight_layout()
    save_svg(fig, path)


def anytime(results, studies, figure_path, command):
    try:
        import matplotlib  # noqa: F401
    except ImportError as e:
        raise sc.Refusal(f"anytime needs matplotlib ({e}): run it with Debian's /usr/bin/python3")
    ledger = finished(compare_rows(results))
    writes = []   # the caches' new rows, written once every run has been read without a refusal
    rows = anytime_rows(results, studies, ledger, writes)
    g = by_method(rows)
    if not g:
        raise sc.Refusal(f"anytime: no finished compare run in {os.path.join(results, 'scaling-runs.csv')}")
    records = handover_records(results, studies, ledger, writes)
    for path, fields, cache in writes:
        sc.write_rows_atomically(path, fields, cache)
    out = ["# How fast each method finds its walk (issue 38, docs/scaling.md)", "",
           f"Written by `{command}`. Per robot and method: the median over the finished",
           "comparison runs of the best fitness each had found (recorded eq. 7.1, stats.csv) by a share of its",
           "budget, evaluations past the budget not counted; ×r is the ratio to the best direct method's median",
           "at the same share. \"(k of n)\" says that only k runs had finished a generation by then. The last",
           "column is the comparison's own score: the median raw eq. 7.1 of the individual each run ended with",
           "(compare-raw.csv). The direct method keeps its best gait, so its 100 % point is that score;",
           "HyperGP-gait and Offset-HybrID keep no elite (elitism 0), so theirs can end below their best.",
           "On the centipedes Switch-HybrID runs HyperGP-gait's own first generations (the same settings and",
           "seed, so the same bytes) until it",
           "hands over, at 30 % of the budget or on stagnation (its run.log says which). R1's and R2's",
           "HyperGP-gait are issue 21's runs, which the comparison's table borrows by their scores alone:",
           "they have no row here.", ""]
    raw = raw_by_run(results, ledger)
    out += table(g, final_scores(raw))
    pairs = handover_table(rows, raw)
    if pairs:
        out += ["", "## The hand-over, seed by seed", "",
                "Switch-HybrID against HyperGP-gait of the same seed, on the centipedes. Until it hands over (on",
                "stagnation, after 11 generations at the earliest, so after 550 evaluations at the least; else at",
                "30 % of the budget) a Switch-HybrID run is that HyperGP-gait run, byte for byte; *same to 20 %*",
                "counts the pairs whose points up to 20 %, before any hand-over, agree. *Best by 30 %*: the",
                "pairs' median best found by then. (Switch-HybrID hands over its last generation's best gait,",
                "which with elitism 0 can be below that; its run.log names it.) The gains are the median best",
                "found from 30 % to the end of the budget (recorded eq. 7.1): HyperGP going on, against separable",
                "CMA-ES taking over. *Gained nothing*: Switch-HybrID runs that found nothing better after 30 %.",
                "*Ends ahead* and the median ratio compare each pair's final raw eq. 7.1 (compare-raw.csv).",
                "Descriptive: no test, and no part of the Holm family.",
                ""]
        out += pairs
    gaps, unrecorded = handover_gap_table(records)
    if gaps or unrecorded:
        out += ["", "## What Switch-HybrID handed over", "",
                "Switch-HybrID starts its gait phase from the best gait of HyperGP's last generation, which with",
                "elitism 0 can be below the best HyperGP had found. Per robot, from each finished run's run.log",
                "and stats.csv (cached in compare-handover.csv): when it handed over (median evaluations; *on",
                "stagnation*: 10 generations without a better best, else at 30 % of the budget or when another",
                "generation would pass it), how many handed",
                "over a gait below the best found by then, the shortfall in per cent of that best (median over",
                "the runs that handed over, zeros included, and the largest), and how many gait phases found a",
                "gait better than that best. *Runs recorded*: finished runs whose folder was here to read."]
        if unrecorded:
            out.append("No Switch-HybrID run of " + ", ".join(unrecorded) + " is recorded: their folders were gone "
                       "before this table existed.")
        if gaps:
            out += [""] + gaps
    sc.write_atomically(os.path.join(results, "anytime.md"), "\n".join(out) + "\n")
    figure(g, figure_path)
    print(f"scaling-report.py: wrote {os.path.join(results, 'anytime.md')} and {figure_path}", file=sys.stderr)
