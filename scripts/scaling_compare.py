"""The comparison stage of issue 38's scaling study (docs/scaling.md, item 5):
the tuning winners read from the ledger, and one sweep file per robot written
from them (scaling-report.py compare-sweeps). Standard library only.

Every value of a tuned method is copied from its tuning sweep file (the
variant's <set> lines and the sweep's own), never typed here: the tuning file
stays the one source of truth. The one thing computed is how the direct
method's base (settings/r1_gait.xml) differs from the hybrids' base
(settings/r1_switch_hybrid.xml), which a sweep's single <base> needs; those
values come from `cic settings`, and the written variant is checked to give
exactly the tuning run's effective settings."""
import csv
import os
import statistics
import subprocess
import xml.etree.ElementTree as ET
from xml.sax.saxutils import escape

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Smallest first: the order the comparison runs in (scripts/scaling.sh compare).
CENTIPEDES = ["centipede-2", "centipede-2-irregular", "centipede-4", "centipede-4-irregular",
              "centipede-8", "centipede-8-irregular", "centipede-16", "centipede-16-irregular"]
# docs/scaling.md, "Run-time estimate": the whole plan passes 30 hours, so the
# middle sizes first lost comparison seeds (seeds 1..5). Seeds 6..10 came back on
# 2026-12-05 ("Methods", "What the middle sizes can show"): at 5 runs a side no
# cell can pass Holm over the table's 30 cells, so every robot runs seeds 1..10.
MIDDLE = {"centipede-4", "centipede-8", "centipede-4-irregular", "centipede-8-irregular"}
MIDDLE_SEEDS = 10   # was 5
R_ROBOTS = {"r1": 1, "r2": 2}   # Simulator.robot_type
# Issue 21's direct runs on R1 and R2 at 15,000 evaluations (docs/baselines.md): they stand for
# R1's and R2's direct method when tune-direct-r1's winner has exactly their settings.
ISSUE21_DIRECT = os.path.join(ROOT, "experiments", "baselines", "walk-15000-cmaes-gait.xml")
CENTIPEDE_BUDGET, R_BUDGET = 2500, 15000
ROBOTS = CENTIPEDES + list(R_ROBOTS)   # the study's robots, in the order its pages list them


def study_rank(robot):
    """A robot's place in ROBOTS' order; a robot outside the study last."""
    return ROBOTS.index(robot) if robot in ROBOTS else len(ROBOTS)


def in_study_order(robots):
    return sorted(robots, key=study_rank)
ROBOT_KEYS = {"Simulator.robotFile", "Simulator.robot_type"}
HYPERGP_GAIT = ["Neural.switchPatience=0", "Neural.switchShare=0", "Neural.directOffsets=0"]   # both hybrids off
METHODS = ["direct", "hypergp-gait", "offset-hybrid", "switch-hybrid"]


class Refusal(Exception):
    """Bad input or an unfinished tuning study: one line, exit 2, nothing written."""


def hinges(robot):
    """Hinge count of a robot of the study: R1 and R2 have 12; a generated centipede
    (docs/robots.md) 6 per pair, the irregular twin one fewer per shortened leg
    (the front ceil(P/2) pairs)."""
    if robot in R_ROBOTS:
        return 12
    pairs = int(robot.split("-")[1])
    return 6 * pairs - ((pairs + 1) // 2 if robot.endswith("-irregular") else 0)


def seeds_of(robot):
    return MIDDLE_SEEDS if robot in MIDDLE else 10


# ---- the winner rule (also the summary's, scaling-report.py) ----

def config_medians(rows, study):
    """Median best_ever of every configuration of STUDY over its finished runs."""
    out = {}
    for config in sorted({r["config"] for r in rows if r["study"] == study and r["status"] == "done"}):
        out[config] = statistics.median(float(r["best_ever"]) for r in rows
                                        if r["study"] == study and r["config"] == config and r["status"] == "done")
    return out


def method_of(config):
    """A hybrid study tunes two methods, offset-* and switch-*: a winner for each."""
    return config.split("-")[0]


def winner(medians, method=None):
    """Highest median; ties: the first configuration in name order."""
    pool = [c for c in sorted(medians) if method is None or method_of(c) == method]
    return max(pool, key=lambda c: medians[c]) if pool else None


# ---- the tuning sweep files ----

def read_sweep(path):
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        raise Refusal(f"{path}: cannot read the tuning sweep: {e}")
    sweep = {"path": path, "name": root.get("name"), "sets": [], "variants": {}}
    for c in root:
        if c.tag == "base":
            sweep["base"] = os.path.normpath(os.path.join(os.path.dirname(path), c.text.strip()))
        elif c.tag == "store":
            sweep["store"] = c.text.strip()
        elif c.tag == "set":
            sweep["sets"].append(c.text.strip())
        elif c.tag == "variant":
            sweep["variants"][c.get("name")] = [s.text.strip() for s in c if s.tag == "set"]
        elif c.tag == "repeats":
            sweep["runs"] = len(sweep["variants"]) * int(c.get("count"))
            first = int(c.get("firstSeed", "1"))
            sweep["seeds"] = list(range(first, first + int(c.get("count"))))
    if "base" not in sweep or "runs" not in sweep or not sweep["variants"]:
        raise Refusal(f"{path}: a tuning sweep needs <base>, <variant>s and <repeats>")
    return sweep


def key_of(set_line):
    return set_line.split("=", 1)[0].strip()


def tuned(rows, sweep, methods, provisional, ledger_path):
    """{method: winning configuration} of one tuning study, or a Refusal."""
    name = sweep["name"]
    done = sum(1 for r in rows if r["study"] == name and r["status"] == "done" and r["config"] in sweep["variants"])
    if done < sweep["runs"] and not provisional:
        raise Refusal(f"compare-sweeps: {name} has {done} of its {sweep['runs']} runs finished ({ledger_path}); "
                      "wait for the tuning to finish, or pass --provisional")
    medians = {c: m for c, m in config_medians(rows, name).items() if c in sweep["variants"]}
    out = {}
    for m in methods:
        w = winner(medians, m)
        if w is None:
            raise Refusal(f"compare-sweeps: {name} has no finished run{'' if m is None else ' of ' + m + '-*'} "
                          f"({ledger_path}): no winner to compare, even a provisional one")
        runs_of_w = sum(1 for r in rows if r["study"] == name and r["status"] == "done" and r["config"] == w)
        out[m] = (w, medians[w], done, runs_of_w)
    return out


# ---- effective settings (cic settings) ----

def effective(cic, base, sets):
    """Every key's effective value, 'Section.key' -> text, of BASE with --set SETS."""
    cmd = [cic, "settings", base] + [a for s in sets for a in ("--set", s)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise Refusal(f"compare-sweeps: `{' '.join(cmd)}` failed: {p.stderr.strip()}")
    root = ET.fromstring(p.stdout)
    return {f"{sec.tag}.{k.tag}": (k.text or "").strip() for sec in root for k in sec}


def absolute(sets, sweep_dir):
    """Paths in --set values are relative to the sweep file; `cic settings` needs them absolute."""
    out = []
    for s in sets:
        k, v = s.split("=", 1)
        out.append(f"{k}={os.path.normpath(os.path.join(sweep_dir, v))}" if k == "Simulator.robotFile" else s)
    return out


# ---- the comparison sweeps ----

def robot_sets(robot, out):
    if robot in R_ROBOTS:
        return [f"Simulator.robot_type={R_ROBOTS[robot]}"]
    rel = os.path.relpath(os.path.join(ROOT, "settings", "robots", robot + ".xml"), out)
    return [f"Simulator.robotFile={rel}", "Simulator.collisionSpace=1"]


def top_sets(robot, hybrid, out):
    """The sweep's own <set>s: the robot, then the hybrid tuning sweep's, robot keys excepted."""
    own = robot_sets(robot, out)
    return own + [s for s in hybrid["sets"] if key_of(s) not in ROBOT_KEYS | {key_of(o) for o in own}]


def direct_variant(cic, robot, out, top, hybrid, direct, config):
    """The direct method's <set>s on the hybrids' base: the keys where the bases
    differ (values from `cic settings` of the gait base), then the direct tuning
    sweep's own sets and its winner's, copied. Checked against the tuning run."""
    copied = [s for s in direct["sets"] if key_of(s) not in ROBOT_KEYS] + direct["variants"][config]
    want = effective(cic, direct["base"], absolute(robot_sets(robot, out) + copied, out))
    have = effective(cic, hybrid["base"], absolute(top, out))
    covered = {key_of(s) for s in copied}
    bases = [f"{k}={want[k]}" for k in want if want[k] != have.get(k) and k not in covered and k != "Experiment.seed"]
    sets = bases + copied
    got = effective(cic, hybrid["base"], absolute(top + sets, out))
    diff = sorted(k for k in set(want) | set(got) if want.get(k) != got.get(k))
    if diff:
        raise Refusal(f"compare-sweeps: the direct variant of {robot} differs from {direct['name']}'s {config} in {diff}")
    return sets, len(bases)


def sweep_text(name, robot, budget, out, hybrid, top, variants, notes, unfinished):
    seeds = seeds_of(robot) if robot not in R_ROBOTS else 10
    why = ("comparison seeds 1..5 only: a middle size, whose seeds are cut first because the whole\n"
           "     plan passes 30 hours (docs/scaling.md, \"Run-time estimate\")" if seeds == 5
           else "comparison seeds 1..10" + (" (a middle size: seeds 6..10 came back so that its cells\n"
                                            "     can pass Holm; docs/scaling.md, \"Methods\")"
                                            if robot in MIDDLE else ""))
    base = os.path.relpath(hybrid["base"], out)
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             f"<!-- Issue 38, the comparison on {robot} at {budget:,} evaluations (docs/scaling.md, \"Plan\"),",
             f"     {why}.",
             "     Written by scripts/scaling-report.py compare-sweeps from the tuning winners in",
             "     results/scaling-runs.csv; every value is copied from the tuning sweep files. Do not edit:",
             "     rerun compare-sweeps. Variants:"]
    lines += [f"       {n}" for n in notes]
    if unfinished:
        # (An XML comment cannot hold two dashes: the option is named without them.)
        lines += [f"     PROVISIONAL: written with the option provisional while {', '.join(unfinished)}",
                  "     had not finished; the winners may change. Rewrite without it before the comparison runs."]
    lines += ["     Run: scripts/scaling.sh compare -->"]
    lines += [f'<sweep name="{name}">', f"  <base>{escape(base)}</base>",
              f"  <output>runs/scaling/{name}</output>", f"  <store>{escape(hybrid.get('store', '../store'))}</store>"]
    lines += [f"  <set>{escape(s)}</set>" for s in top]
    for vname, sets in variants:
        lines.append(f'  <variant name="{vname}">' + "".join(f"<set>{escape(s)}</set>" for s in sets) + "</variant>")
    lines += [f'  <repeats count="{seeds}" firstSeed="1" seeds="same"/>', "</sweep>", ""]
    return "\n".join(lines)


def finished_run(folder):
    """Whether FOLDER holds a run that ended, as its summary.txt says (read as cic's run_end_of_summary
    does: the last "status: " line; before those lines, no "stopped: interrupted"). A folder a rerun or
    a resumed run is still writing is not one: its stats.csv and population are partial."""
    path = os.path.join(folder, "summary.txt")
    if not os.path.isfile(path):
        return False
    said, older_interrupted = None, False
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("status: "):
                said = line[len("status: "):]
            older_interrupted = older_interrupted or line.startswith("stopped: interrupted")
    return said == "done" if said is not None else not older_interrupted


def write_atomically(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def write_rows_atomically(path, fields, rows):
    """{(study, config, seed, ...): row} as a CSV sorted by study, config and seed (a number), atomically."""
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as out:
        w = csv.DictWriter(out, fields, lineterminator="\n")
        w.writeheader()
        for key in sorted(rows, key=lambda k: (k[0], k[1], int(k[2]))):
            w.writerow(rows[key])
    os.replace(tmp, path)


def same_as_issue21(cic, direct_r1, config, issue21):
    """Whether tune-direct-r1's winning configuration runs exactly issue 21's direct runs on R1
    (the same effective settings, seed aside): then those runs are R1's and R2's direct method."""
    theirs = read_sweep(issue21)
    if "R1" not in theirs["variants"]:
        raise Refusal(f"compare-sweeps: {issue21} has no variant R1")
    mine = effective(cic, direct_r1["base"], absolute(direct_r1["sets"] + direct_r1["variants"][config],
                                                      os.path.dirname(direct_r1["path"])))
    other = effective(cic, theirs["base"], theirs["sets"] + theirs["variants"]["R1"])
    return {k: v for k, v in mine.items() if k != "Experiment.seed"} == \
        {k: v for k, v in other.items() if k != "Experiment.seed"}


def compare_sweeps(results, out, tuning_dir, cic, provisional, issue21=ISSUE21_DIRECT):
    """Write OUT/compare-<robot>.xml for the 8 centipedes, R1 and R2; returns the paths."""
    ledger_path = os.path.join(results, "scaling-runs.csv")
    if not os.path.exists(ledger_path):
        raise Refusal(f"compare-sweeps: no ledger at {ledger_path} (scripts/scaling.sh ledger writes it)")
    rows = list(csv.DictReader(open(ledger_path)))
    direct = {r: read_sweep(os.path.join(tuning_dir, f"tune-direct-{r}.xml")) for r in ("c8", "r1")}
    hybrid = {r: read_sweep(os.path.join(tuning_dir, f"tune-hybrid-{r}.xml")) for r in ("c8", "r1")}
    # Every refusal before anything is written.
    won = {}
    for r in ("c8", "r1"):
        won[f"direct-{r}"] = tuned(rows, direct[r], [None], provisional, ledger_path)[None]
        for m, w in tuned(rows, hybrid[r], ["offset", "switch"], provisional, ledger_path).items():
            won[f"{m}-{r}"] = w
    unfinished = [s["name"] for s in (direct["c8"], direct["r1"], hybrid["c8"], hybrid["r1"])
                  if sum(1 for r in rows if r["study"] == s["name"] and r["status"] == "done") < s["runs"]]
    r1_is_issue21 = same_as_issue21(cic, direct["r1"], won["direct-r1"][0], issue21)

    def note(method, study, w):
        return (f"{method}: {study['name']}'s winner {w[0]} (median best_ever {w[1]:.2f} of its {w[3]} runs; "
                f"{w[2]} of the study's runs finished)")

    texts = {}
    for robot in CENTIPEDES + list(R_ROBOTS):
        r = "r1" if robot in R_ROBOTS else "c8"
        top = top_sets(robot, hybrid[r], out)
        variants, notes = [], []
        dw = won[f"direct-{r}"]
        if r == "c8" or not r1_is_issue21:
            sets, nbase = direct_variant(cic, robot, out, top, hybrid[r], direct[r], dw[0])
            variants.append((f"direct.{dw[0]}", sets))
            notes.append(note(f"direct.{dw[0]}", direct[r], dw)
                         + f";\n         its first {nbase} sets turn the hybrids' base into {os.path.basename(direct[r]['base'])}")
        if r == "c8":
            variants.append(("hypergp-gait", HYPERGP_GAIT))
            notes.append(f"hypergp-gait: the base of {hybrid['c8']['name']}, switch and offsets off")
        for m in ("offset", "switch"):
            w = won[f"{m}-{r}"]
            variants.append((f"{m}-hybrid.{w[0]}", hybrid[r]["variants"][w[0]]))
            notes.append(note(f"{m}-hybrid.{w[0]}", hybrid[r], w))
        budget = R_BUDGET if r == "r1" else CENTIPEDE_BUDGET
        if not any(key_of(s) == "Gait.evaluations" and s.endswith(f"={budget}") for s in top):
            raise Refusal(f"compare-sweeps: {hybrid[r]['name']} does not set Gait.evaluations={budget}")
        if r == "r1" and r1_is_issue21:
            notes.append(f"the direct method ({direct['r1']['name']}'s winner {dw[0]}, with exactly the settings of "
                         f"issue 21's\n         {os.path.basename(issue21)}) and HyperGP-gait at 15,000: "
                         "issue 21's runs")
        elif r == "r1":
            notes.append(f"HyperGP-gait at 15,000: issue 21's runs; its direct runs are not {direct['r1']['name']}'s "
                         f"winner,\n         so the direct method runs here")
        texts[robot] = sweep_text(f"compare-{robot}", robot, budget, out, hybrid[r], top, variants, notes, unfinished)
    os.makedirs(out, exist_ok=True)
    paths = []
    for robot, text in texts.items():
        paths.append(os.path.join(out, f"compare-{robot}.xml"))
        write_atomically(paths[-1], text)
    return paths
