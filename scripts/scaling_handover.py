"""What Switch-HybrID handed over (scaling-report.py anytime, its third table).

Switch-HybrID's gait phase starts from the best gait of HyperGP's *last*
generation (src/search/switch_hybrid.cpp). With elitism 0 (Table B.1) that can
be below the best gait HyperGP had found in an earlier generation, so the
evolution strategy may start behind. This module measures how often and by how
much, from each finished Switch-HybrID run's run.log (the line "switch: HyperGP
hands over after generation G (E evaluations): WHY; ... (fitness F) ...") and
its stats.csv (the best of each generation up to G). It also counts the runs
whose gait phase never found a gait better than the HyperGP phase's best.

Each run's record is cached in RESULTS/compare-handover.csv (keyed like
compare-anytime.csv by study, config, seed and best_ever), so the table comes
out the same without the run folders. A run whose folder was gone before it
was cached has no record: the table counts the recorded runs against all
finished ones, and names the robots with none."""
import csv
import os
import re
import statistics

import scaling_compare as sc
from scaling_results import method_of, read_cache, robot_of

CACHE_FIELDS = ["study", "config", "seed", "best_ever", "generation", "evaluations", "cause", "handed_over",
                "best_found"]
LINE = re.compile(r"^switch: HyperGP hands over after generation (\d+) \((\d+) evaluations\): (.*?); \S+ starts "
                  r"from individual \d+'s gait \(fitness (\S+)\)", re.M)
CAUSES = [("has not improved", "stagnation"), ("has spent", "share"), ("would pass the budget", "budget")]


NO_ROOM = "the budget leaves no room for the gait phase"   # summary.txt of a run that never handed over


def record(folder):
    """The hand-over of the Switch-HybrID run in FOLDER: {generation, evaluations, cause, handed_over,
    best_found}; every field empty when the run never handed over, which its summary.txt must say
    (HyperGP spent the budget). A run.log naming no hand-over otherwise is refused, not taken for one
    that never handed over: a log of a resumed gait phase alone, or one whose wording this reader
    does not know, would be cached as a wrong record for good."""
    log, stats, summary = (os.path.join(folder, f) for f in ("run.log", "stats.csv", "summary.txt"))
    for path in (log, stats):
        if not os.path.isfile(path):
            raise sc.Refusal(f"anytime: {path} is missing")
    # A session stopped as HyperGP handed over resumes from its last population and logs the same
    # hand-over again (one seed fixes a run); two different ones would be two runs in one folder.
    found = sorted(set(LINE.findall(open(log).read())))
    if not found:
        if os.path.isfile(summary) and NO_ROOM in open(summary).read():
            return dict.fromkeys(CACHE_FIELDS[4:], "")
        raise sc.Refusal(f"anytime: {log} names no hand-over, and {summary} does not say the run had no room for "
                         "one")
    if len(found) > 1:
        raise sc.Refusal(f"anytime: {log} names {len(found)} different hand-overs")
    generation, evaluations, why, handed = found[0]
    cause = next((name for text, name in CAUSES if text in why), None)
    if cause is None:
        raise sc.Refusal(f"anytime: {log}: a hand-over for a reason not known here: {why}")
    rows = list(csv.DictReader(open(stats)))
    if not rows or not {"generation", "best", "evaluations"} <= set(rows[0]):
        raise sc.Refusal(f"anytime: {stats} has no 'generation', 'best' and 'evaluations' columns")
    before = [r for r in rows if int(r["generation"]) <= int(generation)]
    last = [r for r in before if r["generation"] == generation]
    if not last or last[0]["evaluations"] != evaluations:
        raise sc.Refusal(f"anytime: {stats} has no generation {generation} at {evaluations} evaluations, where "
                         f"{log} says HyperGP handed over")
    return dict(generation=generation, evaluations=evaluations, cause=cause, handed_over=handed,
                best_found=repr(max(float(r["best"]) for r in before)))


def handover_records(results, studies, ledger, writes):
    """{(study, config, seed): record or None} of LEDGER's finished Switch-HybrID runs: None where the
    run's folder is gone and compare-handover.csv has no record of it. The cache's new text goes on
    WRITES, (path, fields, rows), for the caller to write."""
    path = os.path.join(results, "compare-handover.csv")
    cache = read_cache(path)
    changed, out = False, {}
    for r in ledger:
        if method_of(r["config"]) != "switch-hybrid":
            continue
        key = (r["study"], r["config"], r["seed"], r["best_ever"])
        folder = os.path.join(studies, r["study"], r["run_dir"])
        if key not in cache and sc.finished_run(folder):   # a rerun still going is not the ledger's run yet
            cache[key] = dict(zip(CACHE_FIELDS, key), **record(folder))
            changed = True
        out[key[:3]] = dict(cache[key], run_best=float(r["best_ever"])) if key in cache else None
    if changed:
        writes.append((path, CACHE_FIELDS, cache))
    return out


def handover_gap_table(records):
    """Per robot: the Switch-HybrID runs recorded, when they handed over, how far the gait handed over
    was below the best HyperGP had found, and how many gait phases passed that best."""
    by_robot = {}
    for (study, _, _), rec in records.items():
        by_robot.setdefault(robot_of(study), []).append(rec)
    out = ["| robot | hinges | runs recorded | handed over | at evaluations (median) | on stagnation | "
           "handed over below the best found | shortfall, median [max] | gait phase passed the best found |",
           "|---|---|---|---|---|---|---|---|---|"]
    unrecorded = []
    for robot in sc.in_study_order(by_robot):
        recs = [r for r in by_robot[robot] if r is not None]
        if not recs:
            unrecorded.append(robot)
            continue
        handed = [r for r in recs if r["generation"] != ""]
        n = len(handed)
        if not handed:
            out.append(f"| {robot} | {sc.hinges(robot)} | {len(recs)} of {len(by_robot[robot])} | 0 of {len(recs)} "
                       "| – | – | – | – | – |")
            continue
        # In per cent of a positive best (a shortfall from a best of 0 or below has no share).
        short = [100 * (float(r["best_found"]) - float(r["handed_over"])) / float(r["best_found"]) for r in handed
                 if float(r["best_found"]) > 0]
        below = sum(float(r["handed_over"]) < float(r["best_found"]) for r in handed)
        passed = sum(r["run_best"] > float(r["best_found"]) for r in handed)
        out.append(f"| {robot} | {sc.hinges(robot)} | {len(recs)} of {len(by_robot[robot])} | {n} of {len(recs)} | "
                   f"{statistics.median(int(r['evaluations']) for r in handed):,.0f} | "
                   f"{sum(r['cause'] == 'stagnation' for r in handed)} of {n} | {below} of {n} | "
                   + (f"{statistics.median(short):.1f} % [{max(short):.1f} %]" if short else "–") +
                   f" | {passed} of {n} |")
    return (out if len(out) > 2 else []), unrecorded
