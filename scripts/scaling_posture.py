"""Why the direct gaits win, robot by robot (docs/scaling.md; scaling-report.py
posture). Standard library here; the probe needs numpy.

HyperGP's trees write every hinge's posture as a function of the hinge's place
on the body. scripts/posture-probe.py replays a direct gait with its per-hinge
offsets replaced by such functions (none, smooth fits, the mirror image) and
scores each by raw eq. 7.1. Here it probes every finished run of the best
direct method of issue 38's comparison (the compare-<robot> studies) and writes
RESULTS/posture.md: per robot, the median share of each gait's own eq. 7.1
that each replacement keeps. A share near 100 % for a smooth fit says the
direct optimum is regular enough for an indirect encoding to write; a small one
says its walk lives in per-hinge detail that one tree over the body cannot hold.
A second table asks the same of Offset-HybrID, whose trees come with one
directly encoded offset per hinge: each finished Offset-HybrID compare run's
final best replayed as it is and with those offsets set to 0, the median share
kept. A large share lost says the run's walk leans on its direct offsets, as
the direct gaits' does on theirs.
Every run's replays are cached in RESULTS/compare-posture.csv (keyed like
compare-raw.csv by study, config, seed and best_ever), so the page can be
written again on a clean clone whose run folders are gone (they are never
committed). A robot with a finished run that has neither its folder nor a
cached row is left out of the page, and named in it.
Refused (exit 2) before anything is written: no ledger, or no finished direct
compare run with its folder or a cached row."""
import csv
import io
import os
import pathlib
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

import scaling_compare as sc
from scaling_results import compare_rows, finished, method_of, read_cache, robot_of

PROBE = os.path.join(sc.ROOT, "scripts", "posture-probe.py")
VARIANTS = ["offsets 0", "smooth, 2 terms", "smooth, 4 terms", "by axis, 2 terms", "mirrored"]


CACHE = "compare-posture.csv"
ZEROED = "direct offsets 0"   # an Offset-HybrID run replayed with its direct offsets 0
CACHE_FIELDS = ["study", "config", "seed", "best_ever", "run_dir", "original", *VARIANTS, ZEROED]


def method_runs(results, studies, method):
    """{robot: [(cache key, run folder)]} of the ledger's finished compare runs of METHOD, in seed order."""
    ledger = os.path.join(results, "scaling-runs.csv")
    if not os.path.exists(ledger):
        raise sc.Refusal(f"posture: {ledger} is missing (written by scripts/scaling.sh ledger)")
    out = {}
    for r in sorted(finished(compare_rows(results)), key=lambda r: (r["study"], int(r["seed"]))):
        if method_of(r["config"]) != method:
            continue
        key = (r["study"], r["config"], r["seed"], r["best_ever"])
        out.setdefault(robot_of(r["study"]), []).append((key, os.path.join(studies, r["study"], r["run_dir"])))
    return out


def to_replay(runs_by_robot, cache):
    """{robot: [run folder]} of the runs with a folder and no cached row."""
    out = {}
    for robot, runs in runs_by_robot.items():
        todo = [path for key, path in runs if key not in cache and sc.finished_run(path)]
        if todo:
            out[robot] = todo
    return out


def available(runs_by_robot, cache, columns):
    """({robot: [{column: raw eq. 7.1}]} of the robots whose every run is cached, {robot: runs missing})."""
    got, missing = {}, {}
    for robot, runs in runs_by_robot.items():
        rows = [cache[key] for key, _ in runs if key in cache]
        if len(rows) < len(runs):
            missing[robot] = len(runs) - len(rows)
        else:
            got[robot] = [{c: float(r[c]) for c in columns} for r in rows]
    return got, missing


OFFSETS = re.compile(r"<offsets>([^<]*)</offsets>")


def offsets_zeroed(run, folder):
    """FOLDER: a copy of RUN's settings and population with every individual's direct offsets 0. cic assess
    replays the best by gp::better: recorded fitness, then size, then id, none of which the edit touches, so
    it replays the same individual (the edit breaks each one's hash, which only marks it for re-evaluation)."""
    text = open(os.path.join(run, "population.xml")).read()
    if not OFFSETS.search(text):
        raise sc.Refusal(f"posture: {run}/population.xml has no <offsets> (not an Offset-HybrID run?)")
    os.makedirs(folder)
    shutil.copy(os.path.join(run, "settings.xml"), os.path.join(folder, "settings.xml"))
    with open(os.path.join(folder, "population.xml"), "w") as f:
        f.write(OFFSETS.sub(lambda m: "<offsets>" + " ".join("0" for _ in m.group(1).split()) + "</offsets>", text))


def offset_shares(cic, runs_by_robot):
    """{run folder: (raw eq. 7.1 as it is, with its direct offsets 0)}, from one cic assess."""
    with tempfile.TemporaryDirectory(prefix="scaling-posture-offsets-") as work:
        pairs = []
        for robot, runs in runs_by_robot.items():
            for k, run in enumerate(runs):
                zeroed = os.path.join(work, f"{robot}-{k}")
                offsets_zeroed(run, zeroed)
                pairs.append((robot, run, zeroed))
        if not pairs:
            return {}
        out_csv = os.path.join(work, "assess.csv")
        p = subprocess.run([cic, "--quiet", "assess", *[x for _, run, zeroed in pairs for x in (run, zeroed)],
                            "--out", out_csv], capture_output=True, text=True)
        if p.returncode != 0:
            raise sc.Refusal(f"posture: cic assess failed ({p.returncode}): {p.stderr.strip()}")
        got = {r["input"]: float(r["raw_fitness"]) for r in csv.DictReader(open(out_csv))}
    return {run: (got[run], got[zeroed]) for _, run, zeroed in pairs}


def probe(cic, runs):
    """{run: {variant: raw eq. 7.1}}, the original under "original", from one posture-probe.py."""
    with tempfile.TemporaryDirectory(prefix="scaling-posture-") as work:   # the probe's edited copies
        p = subprocess.run([sys.executable, PROBE, "--cic", cic, "--csv", "--work", work, *runs],
                           capture_output=True, text=True)
    if p.returncode != 0:
        raise sc.Refusal(f"posture: posture-probe.py failed ({p.returncode}): {p.stderr.strip()}")
    spelled = {str(pathlib.Path(run)): run for run in runs}   # the probe names a run as pathlib spells it
    out = {}
    for row in csv.DictReader(io.StringIO(p.stdout)):
        out.setdefault(spelled[row["run"]], {})[row["variant"]] = float(row["raw_fitness"])
    if set(out) != set(runs):
        raise sc.Refusal(f"posture: posture-probe.py gave no scores for {sorted(set(runs) - set(out))}")
    return out


def table(scores_by_robot):
    head = ("| robot | hinges | gaits | median eq. 7.1 | " + " | ".join(f"{v}: kept" for v in VARIANTS) + " |\n"
            + "|---|---|---|---|" + "---|" * len(VARIANTS) + "\n")
    lines = []
    for robot in [r for r in sc.ROBOTS if r in scores_by_robot]:
        scores = scores_by_robot[robot]
        h = sc.hinges(robot)
        kept = []
        for v in VARIANTS:
            shares = [s[v] / s["original"] for s in scores if s["original"] > 0]
            kept.append(f"{statistics.median(shares):.0%}" if shares else "–")
        lines.append(f"| {robot} | {h} | {len(scores)} | {statistics.median(s['original'] for s in scores):.2f} | "
                     + " | ".join(kept) + " |")
    return head + "\n".join(lines) + "\n"


def offset_table(shares):
    lines = ["| robot | hinges | runs | median eq. 7.1 | median eq. 7.1, offsets 0 | offsets 0: kept |",
             "|---|---|---|---|---|---|"]
    for robot in [r for r in sc.ROBOTS if r in shares]:
        pairs = [(r["original"], r[ZEROED]) for r in shares[robot]]
        kept = [z / o for o, z in pairs if o > 0]
        lines.append(f"| {robot} | {sc.hinges(robot)} | {len(pairs)} | {statistics.median(o for o, _ in pairs):.2f} | "
                     f"{statistics.median(z for _, z in pairs):.2f} | "
                     + (f"{statistics.median(kept):.0%}" if kept else "–") + " |")
    return "\n".join(lines) + "\n"


def left_out(gone, hybrid_gone):
    """The line naming the robots whose finished runs have neither a folder nor a cached row."""
    if not gone and not hybrid_gone:
        return ""
    parts = []
    for robot in [r for r in sc.ROBOTS if r in gone or r in hybrid_gone]:
        counts = [f"{n[robot]} {what}" for n, what in ((gone, "direct"), (hybrid_gone, "Offset-HybrID")) if robot in n]
        parts.append(f"{robot} ({' and '.join(counts)} runs)")
    return ("Left out, for finished runs whose folders are gone and that have no row in `" + CACHE + "`: "
            + ", ".join(parts) + ". `scripts/scaling.sh posture-runs` reruns them (one seed fixes a run, and each must end on its "
            "ledger's best) to put their robots back.\n\n")


def reruns(results, studies, cic, sweeps):
    """[(study, task, run_dir, best_ever)] of the finished runs the page needs (the best direct method's and
    Offset-HybrID's) whose folder is gone and whose replays are not cached, each with its task in the study's
    sweep (SWEEPS/STUDY.xml) and the ledger's best_ever, which its rerun must end on (scaling.sh posture-runs).
    Refused when the sweep now gives such a run another run key than the ledger's: its rerun would be
    another run, not this one."""
    import scaling_status
    cache = read_cache(os.path.join(results, CACHE))
    keys = {(r["study"], r["config"], r["seed"]): r.get("run_key", "") for r in compare_rows(results)}
    wanted = {}   # study: [(config, seed, best_ever, run_dir)]
    for method in ("direct", "offset-hybrid"):
        for runs in method_runs(results, studies, method).values():
            for (study, config, seed, best), path in runs:
                if (study, config, seed, best) not in cache and not sc.finished_run(path):
                    wanted.setdefault(study, []).append((config, seed, best, os.path.relpath(path, os.path.join(studies, study))))
    out = []
    for study in sorted(wanted):
        sweep = os.path.join(sweeps, study + ".xml")
        if not os.path.exists(sweep):
            raise sc.Refusal(f"posture-runs: {study}'s sweep {sweep} is missing")
        listed = {r["run_dir"]: r for r in scaling_status.sweep_runs(cic, sweep, os.path.join(studies, study))}
        for config, seed, best, run_dir in sorted(wanted[study], key=lambda w: (w[0], int(w[1]))):
            row = listed.get(run_dir)
            if row is None:
                raise sc.Refusal(f"posture-runs: {study} {run_dir} is in the ledger but no run of {sweep}")
            if row["run_key"] != keys[(study, config, seed)]:
                raise sc.Refusal(f"posture-runs: {sweep} now gives {run_dir} the run key {row['run_key']}, the "
                                 f"ledger's row has {keys[(study, config, seed)] or 'none'}: a rerun would be "
                                 "another run than the one the ledger scores")
            out.append((study, row["task"], run_dir, best))
    return out


def posture(results, studies, cic, command):
    runs = method_runs(results, studies, "direct")
    if not runs:
        raise sc.Refusal(f"posture: {os.path.join(results, 'scaling-runs.csv')} has no finished direct run of a "
                         "compare study")
    hybrid_runs = method_runs(results, studies, "offset-hybrid")
    cache = read_cache(os.path.join(results, CACHE))
    # Replay what is not cached yet: the probe per robot, the hybrids in one cic assess.
    fresh = {}
    for robot, paths in to_replay(runs, cache).items():
        for path, scores in probe(cic, paths).items():
            fresh[path] = {"original": scores["original"], **{v: scores[v] for v in VARIANTS}}
    for path, (as_is, zeroed) in offset_shares(cic, to_replay(hybrid_runs, cache)).items():
        fresh[path] = {"original": as_is, ZEROED: zeroed}
    for key, path in [x for group in (*runs.values(), *hybrid_runs.values()) for x in group]:
        if path in fresh:
            cache[key] = {**dict(zip(CACHE_FIELDS, key)), "run_dir": path,
                          **{c: repr(v) for c, v in fresh[path].items()}}
    scores, gone = available(runs, cache, ["original", *VARIANTS])
    hybrid, hybrid_gone = available(hybrid_runs, cache, ["original", ZEROED])
    if not scores:
        raise sc.Refusal(f"posture: no finished direct compare run has its folder under {studies} or a row in "
                         f"{os.path.join(results, CACHE)}")
    if fresh:
        sc.write_rows_atomically(os.path.join(results, CACHE), CACHE_FIELDS, cache)
    text = ("# The best direct gaits' postures (issue 38)\n\n"
            "Written by `" + command + "` (scripts/posture-probe.py on every finished run of the best direct "
            "method in the comparison). Each gait is replayed with its per-hinge offsets replaced, and the "
            "columns give the median share of its own raw eq. 7.1 kept: *offsets 0* none; *smooth* the "
            "least-squares fit a·u + b·u·v (2 terms; 4 adds u³ and u³·v) over the hinges' body coordinates "
            "u, v in [-1, 1], where HyperGP's trees are asked; *by axis* the 2-term fit on the pitching "
            "hinges only; *mirrored* the offsets made exactly odd in u. Amplitudes, phases and frequency "
            "are untouched. Each run's replays are cached in `" + CACHE + "`.\n\n" + left_out(gone, hybrid_gone)
            + table(scores))
    if hybrid:
        text += ("\n## Offset-HybrID's direct offsets\n\n"
                 "Every finished Offset-HybrID run's final best (its trees and one directly encoded offset per "
                 "hinge), replayed as it is and with those offsets set to 0 (the gait its trees write, their "
                 "offsets included, untouched): the median share of its raw eq. 7.1 kept.\n\n" + offset_table(hybrid))
    path = os.path.join(results, "posture.md")
    sc.write_atomically(path, text)
    print(path)
