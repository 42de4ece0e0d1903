"""What is left of issue 38's comparison (scaling-report.py status), read from the sweep files and
the ledger alone.

Per compare sweep (SWEEPS/compare-*.xml): its runs (variants times seeds), those the ledger has
done, and the rest to go (a run under way or interrupted counts whole, so the figure is an upper
bound). A run to go costs its budget times the seconds per evaluation measured on the study's
own finished runs: the median wall_seconds / evaluations of the same method, else of the tuning
runs of the same configuration on the same robot (centipede-8 and R1 were tuned at the
comparison's budgets), else of the robot's finished runs, else results/estimate.md's CPU figure
for the robot (which the finished runs matched within about 10 %: docs/scaling.md, "The study's
record"), scaled by its twin's measured over estimated seconds when the twin (the regular robot
of an irregular one, or the other way) has finished runs: the 96-hinge centipede's runs took 1.17
times its figure, so its 88-hinge twin's are expected to as well. Nothing is written, so it is
safe beside a running study. Given a cic (--cic), a done row
counts only when its run key is the one `cic sweep --dry-run --csv` gives the run now, as `scaling.sh
compare` decides; a row of other settings (an edit that kept a configuration's name) counts as
to go, and the page says how many. Without one, the ledger's done rows are taken as they are.
Given the study folders too (--studies), a last row counts the runs `scaling.sh posture-runs`
would rerun (scaling_posture.reruns: finished runs the posture page needs whose folders are gone
and whose replays are not cached), each at the wall time its ledger row records; where that stage
would refuse (a sweep that now gives such a run another run key), the page says so in its place."""
import csv
import io
import os
import re
import statistics
import subprocess

import scaling_compare as sc
from scaling_results import finished, ledger_rows, method_of

TUNED_ON = {"centipede-8": "c8", "r1": "r1"}   # the tuning studies' robots (tune-*-c8.xml, tune-*-r1.xml)


def estimate_figures(results):
    """{robot: CPU seconds per evaluation} from RESULTS/estimate.md's first table (robot names lower-cased)."""
    path = os.path.join(results, "estimate.md")
    if not os.path.exists(path):
        return {}
    out = {}
    for line in open(path):
        m = re.match(r"\| (\S+) \| ([0-9.]+) \|$", line.strip())
        if m:
            out[m.group(1).lower()] = float(m.group(2))
    return out


def per_evaluation(done):
    return statistics.median(float(r["wall_seconds"]) / int(r["evaluations"]) for r in done)


def twin(robot):
    return robot[:-len("-irregular")] if robot.endswith("-irregular") else robot + "-irregular"


def twin_scale(robot, measured, figures):
    """The twin's measured over estimated seconds per evaluation, or 1 (no twin with finished runs)."""
    other = twin(robot)
    if other in measured and figures.get(other):
        return measured[other] / figures[other]
    return 1.0


def sweep_runs(cic, path, output=None):
    """Every run of the sweep at PATH (its study in OUTPUT, else the sweep's own <output>), as
    `cic sweep --dry-run --csv` lists it, which writes nothing: one dict per run by index.csv's
    column names, with its `task` (the index --task takes), `status` and `run_key`. The one reader
    of a sweep's runs for scaling.sh (scaling-report.py runs) and status."""
    command = [cic, "--quiet", "sweep", path, "--dry-run", "--csv"] + (["--output", output] if output else [])
    try:
        p = subprocess.run(command, capture_output=True, text=True)
    except OSError as e:
        raise sc.Refusal(f"cannot run {cic}: {e}")
    if p.returncode != 0:
        raise sc.Refusal(f"{cic} sweep {path} --dry-run --csv failed (a cic older than this script? build cic from "
                         f"this checkout): {p.stderr.strip()}")
    rows = list(csv.DictReader(io.StringIO(p.stdout)))
    if not rows or not {"task", "run_dir", "status", "run_key"} <= set(rows[0]):
        raise sc.Refusal(f"{cic} sweep {path} --dry-run --csv gives no runs with their run keys (a cic older than "
                         f"this script? build cic from this checkout)")
    return rows


def sweep_keys(cic, path):
    """{run_dir: run key} of every run of the sweep at PATH."""
    try:
        return {r["run_dir"]: r["run_key"] for r in sweep_runs(cic, path)}
    except sc.Refusal as e:
        raise sc.Refusal(f"status: {e}") from None


def posture_reruns(results, studies, cic, sweeps, ledger):
    """(runs, core-hours, None) of what scaling.sh posture-runs would rerun, each at its ledger row's
    wall time; (0, 0.0, why) where that stage would refuse."""
    import scaling_posture
    try:
        runs = scaling_posture.reruns(results, studies, cic, sweeps)
    except sc.Refusal as e:
        return 0, 0.0, str(e)
    seconds = {(r["study"], r["run_dir"]): float(r["wall_seconds"]) for r in ledger}
    return len(runs), sum(seconds[(study, run_dir)] for study, _, run_dir, _ in runs) / 3600, None


def status(results, sweeps, jobs, cic=None, studies=None):
    """The table's lines: per compare sweep what is done, what is to go and its core-hours; the total.
    With CIC, a done row counts only under the run key the sweep now gives its run; with STUDIES too,
    a row for the runs posture-runs would rerun."""
    ledger = os.path.join(results, "scaling-runs.csv")
    if not os.path.exists(ledger):
        raise sc.Refusal(f"status: no ledger at {ledger}")
    robots = [r for r in sc.ROBOTS if os.path.exists(os.path.join(sweeps, f"compare-{r}.xml"))]
    if not robots:
        raise sc.Refusal(f"status: no compare sweep in {sweeps} (scaling-report.py compare-sweeps writes them)")
    finished_rows = finished(ledger_rows(results))
    done_rows = {(r["study"], r["config"], r["seed"]): r for r in finished_rows if r["study"].startswith("compare-")}
    figures = estimate_figures(results)
    plans = {}   # robot: its sweep's name and (study, config, seed) runs
    stale = 0    # done rows of other settings than the sweep's now (with cic)
    for robot in robots:
        path = os.path.join(sweeps, f"compare-{robot}.xml")
        sweep = sc.read_sweep(path)
        plans[robot] = [(sweep["name"], v, str(seed)) for v in sweep["variants"] for seed in sweep["seeds"]]
        if cic:
            keys = sweep_keys(cic, path)
            for study, config, seed in plans[robot]:
                row = done_rows.get((study, config, seed))
                if row and row.get("run_key", "") != keys.get(f"runs/{config}/s{seed}"):
                    del done_rows[(study, config, seed)]
                    stale += 1
    # robot: the median s per evaluation of its finished runs (of the sweep as it is)
    measured = {robot: per_evaluation([done_rows[k] for k in planned if k in done_rows])
                for robot, planned in plans.items() if any(k in done_rows for k in planned)}
    out = ["| study | runs | done | to go | s per evaluation | core-hours left |", "|---|---|---|---|---|---|"]
    totals = [0, 0, 0, 0.0]
    for robot in robots:
        planned = plans[robot]
        done = [done_rows[k] for k in planned if k in done_rows]
        left = [k for k in planned if k not in done_rows]
        budget = sc.R_BUDGET if robot in sc.R_ROBOTS else sc.CENTIPEDE_BUDGET
        robot_sec = measured.get(robot)
        scale = twin_scale(robot, measured, figures)   # for estimate.md's figure
        hours = 0.0
        for _, config, _ in left:
            same = [d for d in done if method_of(d["config"]) == method_of(config)]
            tuned = [r for r in finished_rows if robot in TUNED_ON and "." in config and
                     r["study"] in (f"tune-direct-{TUNED_ON[robot]}", f"tune-hybrid-{TUNED_ON[robot]}") and
                     r["config"] == config.split(".", 1)[1]]
            if same or tuned:
                sec = per_evaluation(same or tuned)
            elif robot_sec is not None:
                sec = robot_sec
            elif robot in figures:
                sec = figures[robot] * scale
            else:
                raise sc.Refusal(f"status: compare-{robot} has runs to go, no finished run to time them by and "
                                 f"no figure for {robot} in {os.path.join(results, 'estimate.md')} "
                                 "(scripts/scaling.sh estimate writes it)")
            hours += budget * sec / 3600
        if robot_sec is not None:
            spe = f"{robot_sec:.3f}"
        elif robot in figures and scale != 1.0:
            spe = f"{figures[robot] * scale:.3f} (estimate.md's {figures[robot]:.3f} × {scale:.2f}, as its twin's runs took)"
        else:
            spe = f"{figures[robot]:.3f} (estimate.md)" if robot in figures else ""
        out.append(f"| compare-{robot} | {len(planned)} | {len(done)} | {len(left)} | {spe} | {hours:.1f} |")
        totals = [totals[0] + len(planned), totals[1] + len(done), totals[2] + len(left), totals[3] + hours]
    refused = None
    if cic and studies:
        n, hours, refused = posture_reruns(results, studies, cic, sweeps, finished_rows)
        if refused is None:
            out.append(f"| posture-runs (reruns of done runs) | {n} | | {n} | the ledger's wall time | {hours:.1f} |")
            totals = [totals[0] + n, totals[1], totals[2] + n, totals[3] + hours]
    out.append(f"| **total** | {totals[0]} | {totals[1]} | {totals[2]} | | **{totals[3]:.1f}** |")
    if refused:
        out += ["", f"posture-runs is not counted: it would refuse ({refused})."]
    if stale:
        out += ["", f"{stale} done row{'s' if stale > 1 else ''} of the ledger {'are' if stale > 1 else 'is'} of other "
                "settings than the sweeps give now (another run key): counted as to go."]
    out += ["", f"About {totals[3] / jobs:.1f} hours of wall time at {jobs} run{'s' if jobs > 1 else ''} at a time "
            "(runs under way or interrupted count whole: an upper bound)."]
    return out
