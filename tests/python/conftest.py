"""Shared fixtures of the Python package's tests (tests/python, run by CTest with
PYTHONPATH at the build tree's package and CIC_BINARY at its cic)."""

import os
import subprocess
import sys

import pytest

SOURCE = os.environ.get("CIC_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
CIC = os.environ.get("CIC_BINARY", "cic")

# A HyperGP run small enough for a test: R0, 2.5 s walks, 6 individuals.
TINY_HYPERGP = """<?xml version="1.0"?>
<settings>
  <Experiment><type>hypergp</type><seed>5</seed><workers>2</workers></Experiment>
  <GP><generatedPopulationSize>6</generatedPopulationSize><tournament_size>3</tournament_size>
      <expectedGeneratedTreeSize>10</expectedGeneratedTreeSize><maximumGeneratedTreeDepth>4</maximumGeneratedTreeDepth>
      <elitism>1</elitism>{gp}</GP>
  <Simulator><robot_type>0</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
  <Control><maximumIterations>2</maximumIterations></Control>{extra}
</settings>
"""


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return str(path)


def cic_run(settings, out, *sets):
    """Runs `cic --settings SETTINGS --output OUT [--set ...]` and returns its one run folder."""
    args = [CIC, "--settings", str(settings), "--output", str(out), "--quiet"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    runs = sorted(os.path.join(out, d) for d in os.listdir(out))
    assert len(runs) == 1, runs
    return runs[0]


def gait_sets(evaluations=40):
    """R1's gait on a 3 s walk: quick, and still the gait family's whole path."""
    return [f"Gait.evaluations={evaluations}", "Gait.populationSize=8", "Simulator.sample_to=3",
            "Simulator.delayed_start=0.5", "Experiment.workers=2"]


@pytest.fixture(scope="session")
def runs(tmp_path_factory):
    """One finished run of each family: gait (CMA-ES), CPG (CMA-ES), HyperGP (a forest of 2
    CPG trees), Offset-HybrID (trees plus offsets), Switch-HybrID past its hand-over and a gait
    MAP-Elites archive."""
    base = tmp_path_factory.mktemp("runs")
    gait_xml = os.path.join(SOURCE, "settings", "r1_gait.xml")
    out = {}
    out["gait"] = cic_run(gait_xml, base / "gait", *gait_sets())
    out["cpg"] = cic_run(gait_xml, base / "cpg", *gait_sets(), "Gait.controller=cpg")
    hgp = write(base / "hypergp.xml", TINY_HYPERGP.format(gp="", extra=""))
    out["hypergp"] = cic_run(hgp, base / "hypergp")
    forest = write(base / "forest.xml", TINY_HYPERGP.format(
        gp="<numberOfTreesInForestGenotype>2</numberOfTreesInForestGenotype>",
        extra="<Neural><substrate>cpg</substrate><cpgFeedback>2</cpgFeedback></Neural>"))
    out["forest"] = cic_run(forest, base / "forest")
    offset = write(base / "offset.xml", TINY_HYPERGP.format(gp="", extra=(
        "<Neural><substrate>gait</substrate><directOffsets>1</directOffsets><offsetSigma>0.3</offsetSigma>"
        "<offsetRate>0.5</offsetRate></Neural>")))
    out["offset"] = cic_run(offset, base / "offset")   # Offset-HybrID: trees plus per-hinge offsets
    # Switch-HybrID past its hand-over (at 0.3 of 400 evaluations): its best is a gait vector.
    out["switch"] = cic_run(os.path.join(SOURCE, "settings", "r1_switch_hybrid.xml"), base / "switch",
                            "Gait.evaluations=400", "GP.generatedPopulationSize=10", "Neural.switchShare=0.3",
                            "Simulator.sample_to=3", "Simulator.delayed_start=0.5", "Experiment.workers=2")
    me = os.path.join(SOURCE, "settings", "r1_gait_map_elites.xml")
    out["map_elites"] = cic_run(me, base / "me", "MapElites.evaluations=24", "MapElites.batch=8",
                                "MapElites.initial=8", "Simulator.sample_to=3",
                                "Simulator.delayed_start=0.5", "Experiment.workers=2")
    return out


def children_of(pid):
    """The process ids whose parent is `pid` (Linux /proc)."""
    kids = []
    for task in os.listdir(f"/proc/{pid}/task"):
        try:
            with open(f"/proc/{pid}/task/{task}/children") as f:
                kids += [int(p) for p in f.read().split()]
        except FileNotFoundError:
            pass
    return kids


sys.path.insert(0, os.path.dirname(__file__))
