"""The best gaits of issue 38's comparison on the largest robots (docs/scaling.md,
item 6; scaling-report.py strips). Standard library only.

Per robot (default the 96- and 88-hinge centipedes) and per method (a compare
variant is METHOD.TUNED_CONFIG, or METHOD), the finished run with the highest
raw eq. 7.1 in RESULTS/compare-raw.csv (`scaling-report.py results` writes it;
a cached score counts only if the ledger has that run done with the same
best_ever; ties: the lowest seed). Each pick is replayed by `cic assess`, whose
own columns are its verdicts (nothing is judged here), and drawn by
scripts/screenshot-strip.sh into IMAGES/scaling-strip-<robot>-<method>.png.
RESULTS/strips.md gets one table per robot, the strips and the command.
Each pick's `cic assess` row is cached in RESULTS/compare-strips.csv (keyed like
compare-raw.csv by study, config, seed and best_ever), so the page can be
written again on a machine whose run folders are gone (they are never
committed): such a pick keeps its cached row and the strip drawn before (in
IMAGES), and the page says so.
Everything is checked before anything is written: a missing file, a robot
without scored runs, or a picked run whose folder is gone and that has no
cached row (or, when drawing, no strip) is refused (exit 2)."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

import scaling_compare as sc
from scaling_results import LABELS, finished, ledger_rows, method_of, read_cache, robot_of

LARGEST = ["centipede-16", "centipede-16-irregular"]
CACHE = "compare-strips.csv"
STRIP_TIMES = "2 5 8 11 14"   # seconds of the 15 s replay (screenshot-strip.sh's default)
# `cic assess`'s columns shown in the table, in its order, with their units.
ASSESS_COLUMNS = [("verdict", "verdict"), ("distance", "distance (m)"), ("elevation", "elevation (m)"),
                  ("dominant_hz", "dominant Hz"), ("mean_height", "mean height"), ("min_height", "min height"),
                  ("final_up", "final up"), ("flipped", "flipped"), ("shaking", "shaking")]
CACHE_FIELDS = ["study", "config", "seed", "best_ever", "raw_fitness", "duty_factors"] + [c for c, _ in ASSESS_COLUMNS]


def picks(results, studies, robots):
    """{robot: {method: pick}} of the highest cached raw eq. 7.1 among the ledger's finished runs."""
    ledger_path = os.path.join(results, "scaling-runs.csv")
    cache_path = os.path.join(results, "compare-raw.csv")
    for path, maker in ((ledger_path, "scripts/scaling.sh ledger"), (cache_path, "scaling-report.py results")):
        if not os.path.exists(path):
            raise sc.Refusal(f"strips: {path} is missing (written by {maker})")
    done = {(r["study"], r["config"], r["seed"], r["best_ever"]): r for r in finished(ledger_rows(results))}
    cache = read_cache(cache_path)
    out = {}
    for robot in robots:
        best = {}
        for key, c in cache.items():
            if key[0] != f"compare-{robot}" or key not in done:
                continue   # another robot, or a score of a run since rerun (its best_ever differs)
            raw, m = float(c["raw_fitness"]), method_of(key[1])
            if m not in best or (raw, -int(key[2])) > (best[m]["raw"], -int(best[m]["seed"])):
                best[m] = {"study": key[0], "config": key[1], "seed": key[2], "raw": raw, "key": key,
                           "study_dir": os.path.join(studies, key[0]),
                           "run_dir": done[key]["run_dir"], "path": os.path.join(studies, key[0], done[key]["run_dir"])}
        if not best:
            raise sc.Refusal(f"strips: {robot}: no finished compare-{robot} run is scored in {cache_path} "
                             f"(run scaling-report.py results first; robots: {', '.join(robots)})")
        out[robot] = {m: best[m] for m in sc.METHODS if m in best}
    return out


def check_gone(chosen, strip_cache, images, draw):
    """The picks whose folder is gone: each needs its cached assess row and, when drawing, its strip
    drawn before; else refused, saying how to get the folder back."""
    for robot, by_method in chosen.items():
        for m, p in by_method.items():
            if sc.finished_run(p["path"]):
                continue
            png = os.path.join(images, image_name(robot, m))
            lacks = (f"{CACHE} has no row for it" if p["key"] not in strip_cache else
                     f"its strip {png} is missing" if draw and not os.path.exists(png) else None)
            if lacks:
                sweep = os.path.join(sc.ROOT, "experiments", "scaling", f"{p['study']}.xml")
                raise sc.Refusal(f"strips: {robot} {p['config']} seed {p['seed']} is the best {m} run, "
                                 f"but {p['path']} is gone, and {lacks}: one seed fixes a run, so rerun it "
                                 f"with `cic sweep {sweep} --output {p['study_dir']} "
                                 "--task N` (its N from --dry-run)")


def assess(cic, paths):
    """{path: assess row} of the picks, one `cic assess` for all."""
    tmp = tempfile.mkdtemp(prefix="scaling-strips-")
    try:
        out_csv = os.path.join(tmp, "assess.csv")
        p = subprocess.run([cic, "--quiet", "assess", *paths, "--out", out_csv], capture_output=True, text=True)
        if p.returncode != 0:
            raise sc.Refusal(f"strips: cic assess failed: {p.stderr.strip()}")
        got = {r["input"]: r for r in csv.DictReader(open(out_csv))}
    finally:
        shutil.rmtree(tmp)
    missing = [d for d in paths if d not in got]
    if missing:
        raise sc.Refusal(f"strips: cic assess gave no row for {missing[0]}")
    return got


def viewer_missing(cic):
    """Why no strip can be drawn, or None: `cic view` needs the viewer build and an X server or xvfb-run."""
    if subprocess.run([cic, "view", "--help"], capture_output=True).returncode != 0:
        return f"{cic} was built without the viewer (`cic view` is missing)"
    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run") is None:
        return "there is no X display and no xvfb-run"
    return None


class StripFailed(Exception):
    """`cic view` failed on a run: not bad input (exit 1)."""


def strip(cic, run, png, times):
    script = os.path.join(sc.ROOT, "scripts", "screenshot-strip.sh")
    p = subprocess.run(["bash", script, run, png, "--at", times], capture_output=True, text=True,
                       env={**os.environ, "CIC": cic})
    if p.returncode != 0:
        raise StripFailed(f"strips: screenshot-strip.sh {run}: {p.stderr.strip()}")


def image_name(robot, method):
    return f"scaling-strip-{robot}-{method}.png"


def robot_section(robot, chosen, rows, results, images, drawn):
    out = [f"## {robot} ({sc.hinges(robot)} hinges)", "",
           "| method | run | seed | raw eq. 7.1 | " + " | ".join(h for _, h in ASSESS_COLUMNS) + " |",
           "|---" * (4 + len(ASSESS_COLUMNS)) + "|"]
    notes = []
    for m in sc.METHODS:
        if m not in chosen:
            out.append(f"| {LABELS[m]} | no finished run scored | | |" + " |" * len(ASSESS_COLUMNS))
            continue
        p = chosen[m]
        a = rows[p["path"]]
        out.append(f"| {LABELS[m]} | {p['study']}/{p['run_dir']} | {p['seed']} | {p['raw']:.3f} | "
                   + " | ".join(a[c] for c, _ in ASSESS_COLUMNS) + " |")
        replayed = float(a["raw_fitness"])
        if a.get("cached"):
            notes.append(f"- {LABELS[m]}: the run's folder is gone here; its row is the one `cic assess` gave "
                         f"when it was there (`{CACHE}`), and its strip the one drawn then.")
        if abs(replayed - p["raw"]) > 1e-9 * max(1.0, abs(p["raw"])):
            notes.append(f"- {LABELS[m]}: `cic assess` now replays this run to raw {replayed:.6g}, "
                         f"compare-raw.csv has {p['raw']:.6g} (a different cic build?).")
    out += [""] + notes + ([""] if notes else [])
    out += ["Duty factors per foot (`cic assess`, column duty_factors):", ""]
    out += [f"- {LABELS[m]}: {rows[chosen[m]['path']]['duty_factors'] or '(none)'}" for m in sc.METHODS if m in chosen]
    out.append("")
    for m in sc.METHODS:
        if m in chosen and drawn:
            rel = os.path.relpath(os.path.join(images, image_name(robot, m)), results)
            out += [f"![{robot}, {LABELS[m]}: {chosen[m]['study']}/{chosen[m]['run_dir']}]({rel})", ""]
    return out


def strips(results, studies, cic, images, robots, times, command, draw=True):
    allowed = sc.CENTIPEDES + sorted(sc.R_ROBOTS)
    robots = list(dict.fromkeys(robots))   # each robot once, in the order given
    for robot in robots:
        if robot not in allowed:
            raise sc.Refusal(f"strips: --robots: unknown robot '{robot}' (allowed: {', '.join(allowed)})")
    try:
        ok = times.split() and all(float(t) >= 0 for t in times.split())
    except ValueError:
        ok = False
    if not ok:
        raise sc.Refusal(f"strips: --at takes seconds >= 0 separated by spaces, e.g. \"{STRIP_TIMES}\"; got '{times}'")
    chosen = picks(results, studies, robots)
    strip_cache = read_cache(os.path.join(results, CACHE))
    check_gone(chosen, strip_cache, images, draw)
    present = [p for by_method in chosen.values() for p in by_method.values() if sc.finished_run(p["path"])]
    if draw and present:
        why = viewer_missing(cic)
        if why:
            raise sc.Refusal(f"strips: cannot draw strips: {why} (--no-strips writes the verdicts only)")
    rows = assess(cic, [p["path"] for p in present]) if present else {}
    for by_method in chosen.values():
        for p in by_method.values():
            if p["path"] not in rows:
                rows[p["path"]] = dict(strip_cache[p["key"]], cached=True)
            else:
                strip_cache[p["key"]] = {**dict(zip(CACHE_FIELDS[:4], p["key"])),
                                         **{c: rows[p["path"]].get(c, "") for c in CACHE_FIELDS[4:]}}
    if draw:
        os.makedirs(images, exist_ok=True)
        for p in present:
            strip(cic, p["path"], os.path.join(images, image_name(robot_of(p["study"]), method_of(p["config"]))),
                  times)
    out = ["# The best gaits on the largest robots (issue 38)", "",
           "Written by `scripts/scaling-report.py strips`: per robot and method the finished comparison run with",
           "the highest raw eq. 7.1 of its replayed best (`compare-raw.csv`, from `scaling-report.py results`),",
           "replayed by `cic assess` (its own columns: the verdict is flipped, shaking, walking, standing up or",
           "sliding; distance and elevation are eq. 7.1's two parts; shaking means a dominant command frequency",
           f"above 4 Hz) and drawn by `scripts/screenshot-strip.sh` (fixed camera, trail; frames at t = {times} s).",
           "", "```sh", command, "```", ""]
    if not draw:
        out += ["No strips were drawn (--no-strips).", ""]
    for robot in robots:
        out += robot_section(robot, chosen[robot], rows, results, images, draw)
    if present:
        sc.write_rows_atomically(os.path.join(results, CACHE), CACHE_FIELDS, strip_cache)
    path = os.path.join(results, "strips.md")
    sc.write_atomically(path, "\n".join(out))
    print(f"scaling-report.py: wrote {path}" + (f" and {sum(map(len, chosen.values()))} strips in {images}"
                                               if draw else ""), file=sys.stderr)
