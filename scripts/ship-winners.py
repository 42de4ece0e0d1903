#!/usr/bin/env python3
"""Writes settings/r{0,1,2}_best.xml and r{0,1,2}_best_hypergp.xml from
experiments/baselines/results/walk-winners.csv (`scripts/walk-report.py winners`).

    CIC=build/cic scripts/ship-winners.py

Each file is the winning study's configuration for that robot, exactly as the
comparison ran it (its base with the sweep's overrides, seed 1), budget
included: `cic sweep --dry-run --csv` gives the command, so this script reads no sweep
file itself. The test SweepFile.ShippedBestSettingsAreTheComparisonWinners
holds the shipped files to the CSV.
"""
import csv
import io
import os
import pathlib
import shlex
import subprocess
import sys
import tempfile
import textwrap
import xml.etree.ElementTree as ET

ROOT = pathlib.Path(__file__).resolve().parent.parent
CIC = os.environ.get("CIC", str(ROOT / "build" / "cic"))
WINNERS = ROOT / "experiments" / "baselines" / "results" / "walk-winners.csv"
LABELS = {"hgp-best": "HyperGP's best configuration before issue 21 (recurrent network, 1 s clock)",
          "hgp-clock": "HyperGP with the evolved clock", "hgp-cpg": "HyperGP-CPG",
          "hgp-gait": "HyperGP-gait (the tree gives each joint's amplitude, phase and offset)",
          "cmaes-gait": "CMA-ES with IPOP restarts on the open-loop gait",
          "cmaes-cpg": "CMA-ES with IPOP restarts on the CPG's weights"}


def fail(message):
    print(f"ship-winners.py: {message}", file=sys.stderr)
    sys.exit(2)


def command_of(study, config):
    """(base settings file, [overrides]) of the study's seed-1 run of config, as cic sweep plans it."""
    with tempfile.TemporaryDirectory() as tmp:
        out = subprocess.run([CIC, "--quiet", "sweep", str(ROOT / "experiments" / "baselines" / f"{study}.xml"),
                              "--output", tmp, "--dry-run", "--csv"], capture_output=True, text=True)
    if out.returncode != 0:
        fail(f"{study}: cic sweep --dry-run --csv failed: {out.stderr.strip()}")
    for row in csv.DictReader(io.StringIO(out.stdout)):
        if row["run_dir"] == f"runs/{config}/s1":
            argv = shlex.split(row["command"])
            base = argv[argv.index("--settings") + 1]
            sets = [argv[i + 1] for i, a in enumerate(argv) if a == "--set"]
            return base, [s for s in sets if not s.startswith("Experiment.seed=")]
    fail(f"{study}: no run runs/{config}/s1 in its plan")


def apply(root, override):
    key, value = override.split("=", 1)
    section, name = key.split(".", 1)
    sec = root.find(section)
    if sec is None:
        sec = ET.SubElement(root, section)
    el = sec.find(name)
    if el is None:
        el = ET.SubElement(sec, name)
    el.text = value


def header(row, method, overrides):
    budget = int(row["budget"])
    text = (f"Issue 21's winner on robot {row['robot']} (docs/baselines.md, \"Shipped settings\"): {method}, "
            f"as the comparison ran it ({row['study']}.xml, variant {row['config']}), {budget:,} evaluations. "
            f"Median raw eq. 7.1 over {row['n']} comparison seeds: {float(row['median']):.2f} "
            f"(HyperGP's old best: {float(row['incumbent_median']):.2f}"
            + (f"; Mann-Whitney p {row['p']}, Holm {row['p_holm']}). " if row["p"] else "). ")
            + "The rule that chose it: scripts/walk-report.py winners; this file is written by "
            "scripts/ship-winners.py from results/walk-winners.csv. Every key not given here takes its "
            "default (`cic settings` prints them). Run: scripts/run.sh " + row["file"])
    return "<!-- " + "\n     ".join(textwrap.wrap(text, 80)) + " -->"


def main():
    if not WINNERS.exists():
        fail(f"{WINNERS} is missing: run scripts/walk-report.py winners first")
    with open(WINNERS, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        base, overrides = command_of(row["study"], row["config"])
        tree = ET.parse(base)
        for o in overrides:
            apply(tree.getroot(), o)
        ET.indent(tree, space="  ")
        method = LABELS.get(row["study"].split("-", 2)[2], row["study"])
        text = ('<?xml version="1.0" encoding="UTF-8"?>\n' + header(row, method, overrides) + "\n"
                + ET.tostring(tree.getroot(), encoding="unicode") + "\n")
        dest = ROOT / row["file"]
        tmp = dest.with_suffix(".xml.tmp")
        tmp.write_text(text)
        tmp.replace(dest)
        print(f"ship-winners.py: {row['file']} = {row['study']} {row['config']}", file=sys.stderr)


main()
