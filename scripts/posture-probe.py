#!/usr/bin/env python3
"""Could HyperGP-gait's trees write CMA-ES's posture? (docs/baselines.md, "Why")

    scripts/posture-probe.py [--cic PATH] [--work DIR] GAIT_RUN...

GAIT_RUN: a `gait` run folder (settings.xml, population.xml), e.g. a kept best
in experiments/baselines/results/best/walk-15000-cmaes-gait/R2, on R0, R1, R2
or a robot file (Simulator.robotFile: the centipedes of docs/scaling.md). Its champion
(a point of the unit box, include/cic/experiments/gait/encoding.hpp) is
decoded into per-joint amplitude, phase and offset; the offsets are then
replaced by least-squares fits over the points HyperGP-gait's trees are asked
at (the joints' plan coordinates u, v in [-1, 1], hypergp::substrate_geometry),
and each variant is replayed with `cic assess` (raw eq. 7.1; amplitudes,
phases and frequency untouched):

  offsets 0            no posture at all
  smooth, 2 terms      a·u + b·u·v (odd in u: the legs mirrored)
  smooth, 4 terms      a·u + b·u·v + c·u³ + d·u³·v
  by axis, 2 terms     [axis = y]·(a·u + b·u·v): the same two terms, on the
                       joints that pitch only (a tree told each joint's axis)
  mirrored             o(−u, v) = −o(u, v) exactly, every value free

Markdown on stdout: each variant's fitness and the share of the original kept,
one row per variant, medians over the inputs; with --csv, the rows
run,variant,raw_fitness instead (scaling-report.py posture reads them). Needs numpy (Debian's
python3-numpy). Writes the variants under --work (default a temporary folder).
"""
import argparse
import csv
import math
import pathlib
import re
import shutil
import statistics as st
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

ROOT = pathlib.Path(__file__).resolve().parent.parent


def fail(message):
    print(f"posture-probe.py: {message}", file=sys.stderr)
    sys.exit(2)


try:
    import numpy as np
except ImportError:
    fail("needs numpy (Debian's python3-numpy)")

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--cic", default=str(ROOT / "build" / "cic"))
ap.add_argument("--work", default=None)
ap.add_argument("--csv", action="store_true", help="one CSV row per gait and variant (run,variant,raw_fitness)")
ap.add_argument("runs", nargs="+")
args = ap.parse_args()


def setting(tree, where, section, key):
    node = tree.find(f"{section}/{key}")
    if node is None:
        fail(f"{where}: no <{section}><{key}> (not a run's effective settings?)")
    return (node.text or "").strip()


def robot_file(tree, where):
    """The robot's module file: Simulator.robotFile (a generated robot such as the
    centipedes of docs/scaling.md; relative to the settings file), or R0, R1, R2."""
    path = setting(tree, where, "Simulator", "robotFile")
    if path:
        file = pathlib.Path(path) if pathlib.Path(path).is_absolute() else pathlib.Path(where).parent / path
        if not file.is_file():
            fail(f"{where}: Simulator.robotFile {path}: no such file")
        return file
    if setting(tree, where, "Neural", "useMiddleLegs") != "0":
        fail(f"{where}: Neural.useMiddleLegs = 1; only the 4-legged robots are probed")
    kind = setting(tree, where, "Simulator", "robot_type")
    if kind not in ("0", "1", "2"):
        fail(f"{where}: Simulator.robot_type '{kind}' is not 0, 1 or 2")
    return ROOT / "settings" / "robots" / f"r{kind}.xml"


def joints_of(robot):
    """(u, v, axis) of each actuated module, in module order, as substrate_geometry normalises them."""
    modules = ET.parse(robot).getroot().findall("module")
    xs = [float(m.get("x")) for m in modules]
    ys = [float(m.get("y")) for m in modules]

    def norm(value, lo, hi):
        return 0.0 if lo == hi else (2 * value - lo - hi) / (hi - lo)
    return [(norm(float(m.get("x")), min(xs), max(xs)), norm(float(m.get("y")), min(ys), max(ys)), m.get("axis"))
            for m in modules if m.get("axis") != "fixed"]


def reflect(v):   # gait::to_unit, Bounds::Reflect
    v = abs(v) % 2.0
    return 2.0 - v if v > 1.0 else v


def fit(y, features):
    X = np.column_stack(features)
    c, *_ = np.linalg.lstsq(X, y, rcond=None)
    return X @ c


VARIANTS = ["original", "offsets 0", "smooth, 2 terms", "smooth, 4 terms", "by axis, 2 terms", "mirrored"]


def variants(run, work):
    where = run / "settings.xml"
    if not where.is_file() or not (run / "population.xml").is_file():
        fail(f"{run}: not a run folder (settings.xml and population.xml)")
    tree = ET.parse(where).getroot()
    if setting(tree, where, "Experiment", "type") != "gait":
        fail(f"{where}: Experiment.type is not gait")
    for key, want in (("controller", "sine"), ("bounds", "reflect"), ("secondHarmonic", "0")):
        if setting(tree, where, "Gait", key) != want:
            fail(f"{where}: Gait.{key} must be {want} for this probe")
    joints = joints_of(robot_file(tree, where))
    text = (run / "population.xml").read_text()
    m = re.search(r"(<champion[^>]*>)([^<]*)(</champion>)", text)
    if not m:
        fail(f"{run / 'population.xml'}: no <champion>")
    x = [float(t) for t in m.group(2).split()]
    if len(x) != 1 + 3 * len(joints):
        fail(f"{run / 'population.xml'}: {len(x)} numbers, the robot's {len(joints)} joints need {1 + 3 * len(joints)}")
    u = np.array([j[0] for j in joints])
    v = np.array([j[1] for j in joints])
    pitch = np.array([1.0 if j[2] == "y" else 0.0 for j in joints])
    off = np.array([(2 * reflect(x[3 + 3 * i]) - 1) * math.pi / 2 for i in range(len(joints))])
    # The mirror of joint i: the joint at (−u, v).
    mirror = [min(range(len(joints)), key=lambda k: abs(u[k] + u[i]) + abs(v[k] - v[i])) for i in range(len(joints))]
    offsets = {
        "original": off,
        "offsets 0": np.zeros(len(joints)),
        "smooth, 2 terms": fit(off, [u, u * v]),
        "smooth, 4 terms": fit(off, [u, u * v, u**3, u**3 * v]),
        "by axis, 2 terms": fit(off, [pitch * u, pitch * u * v]),
        "mirrored": (off - off[mirror]) / 2,
    }
    dirs = []
    for i, name in enumerate(VARIANTS):
        d = work / f"{run.parent.name}-{run.name}-{i}"
        shutil.rmtree(d, ignore_errors=True)
        d.mkdir(parents=True)
        shutil.copy(where, d / "settings.xml")
        y = list(x)
        # The original keeps its genes as the run saved them (re-encoding its offsets
        # could move the last bits), so its replay is the run's own raw eq. 7.1.
        for j, o in enumerate(offsets[name] if name != "original" else []):
            y[3 + 3 * j] = (max(-1.0, min(1.0, o / (math.pi / 2))) + 1) / 2
        edited = text[:m.start(2)] + " ".join(repr(t) for t in y) + text[m.end(2):]
        # The champion is edited on purpose: the copy drops the checkpoint's
        # content hash, which cic would refuse as a hand edit otherwise, and is
        # written as format version 1, which holds none (cic assess then notes
        # that the stored fitness does not replay: the variant's is the replay's).
        edited = re.sub(r' contentHash="[0-9a-f]*"', "", edited, count=1)
        (d / "population.xml").write_text(re.sub(r' version="2"', ' version="1"', edited, count=1))
        dirs.append(d)
    return dirs


work = pathlib.Path(args.work) if args.work else pathlib.Path(tempfile.mkdtemp(prefix="posture-probe-"))
runs = [pathlib.Path(r) for r in args.runs]
folders = [d for r in runs for d in variants(r, work)]
out = subprocess.run([args.cic, "--quiet", "assess", *map(str, folders)], capture_output=True, text=True)
if out.returncode != 0:
    fail(f"cic assess failed ({out.returncode}): {out.stderr.strip()}")
lines = out.stdout.strip().splitlines()
header = lines[0].split(",")
scores = [float(dict(zip(header, line.split(",")))["raw_fitness"]) for line in lines[1:]]
per_run = [scores[i:i + len(VARIANTS)] for i in range(0, len(scores), len(VARIANTS))]
if args.csv:
    w = csv.writer(sys.stdout, lineterminator="\n")
    w.writerow(["run", "variant", "raw_fitness"])
    for run, s in zip(runs, per_run):
        for name, value in zip(VARIANTS, s):
            w.writerow([str(run), name, repr(value)])
    sys.exit(0)
print(f"Posture probe (`scripts/posture-probe.py`), {len(runs)} gait(s): raw eq. 7.1 of each gait replayed with its "
      "offsets replaced, median over the gaits, and the median share of each gait's own distance kept.\n")
print("| offsets | median fitness | share kept | " + " | ".join(f"{r.parent.name}/{r.name}" for r in runs) + " |")
print("|---|---|---|" + "---|" * len(runs))
for k, name in enumerate(VARIANTS):
    values = [s[k] for s in per_run]
    shares = [s[k] / s[0] for s in per_run if s[0] > 0]
    print(f"| {name} | {st.median(values):.2f} | {st.median(shares):.0%} | "
          + " | ".join(f"{v:.2f}" for v in values) + " |")
