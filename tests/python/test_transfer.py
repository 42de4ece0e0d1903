"""Transfer from Python (issue 55, docs/transfer.md): an Evaluator of one robot scores a genotype
read from a run on another, to the bits `cic transfer` gives."""

import csv
import io
import os
import subprocess

import numpy as np

import cic
from conftest import CIC, SOURCE, cic_run


def test_an_evaluator_of_another_robot_scores_a_runs_trees_as_cic_transfer_does(tmp_path):
    robots = os.path.join(SOURCE, "settings", "robots")
    run = cic_run(os.path.join(SOURCE, "settings", "r1_switch_hybrid.xml"), tmp_path / "c2",
                  f"Simulator.robotFile={robots}/centipede-2.xml", "Neural.switchPatience=0", "Neural.switchShare=0",
                  "Control.maximumIterations=2", "GP.generatedPopulationSize=6", "Experiment.workers=1")
    best = cic.read_run(run)
    out = subprocess.run([CIC, "--quiet", "transfer", run, "--robot", f"{robots}/centipede-4.xml"],
                         check=True, capture_output=True, text=True).stdout
    rows = {r["robot"]: r for r in csv.DictReader(io.StringIO(out))}
    with cic.Evaluator(os.path.join(run, "settings.xml"),
                       set={"Simulator.robotFile": f"{robots}/centipede-4.xml"}) as ev:
        there = ev.evaluate([best.best_genotype])
    assert there.fitness[0] == float(rows["centipede-4"]["raw_fitness"])
    assert np.isclose(there.distance[0], float(rows["centipede-4"]["distance"]), atol=1e-4)
    # On its own robot the genotype gives its stored fitness.
    assert float(rows["centipede-2"]["raw_fitness"]) == best.best_fitness
