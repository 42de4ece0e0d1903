"""Every example in examples/python runs (short budgets, 3 s walks) and says what it found."""

import os
import subprocess
import sys

import pytest

from conftest import CIC, SOURCE, write

EXAMPLES = os.path.join(SOURCE, "examples", "python")


def run_example(name, *args, cwd=None):
    p = subprocess.run([sys.executable, os.path.join(EXAMPLES, name), *args], capture_output=True, text=True,
                       timeout=600, cwd=cwd, env=dict(os.environ, MPLBACKEND="Agg"))
    assert p.returncode == 0, p.stdout + p.stderr
    return p.stdout


def last_number(out, words):
    line = [l for l in out.splitlines() if words in l][-1]
    return float(line.split(words)[1].split()[0].rstrip(",;"))


def test_deap_cma_tunes_the_gait():
    out = run_example("deap_cma.py", "--evaluations", "48", "--quick", "--settings",
                      os.path.join(SOURCE, "settings", "r1_gait.xml"))
    assert last_number(out, "best fitness") > 0


def test_scipy_differential_evolution_evaluates_whole_generations():
    out = run_example("scipy_de.py", "--generations", "1", "--popsize", "1", "--quick")
    assert "in 2 batches" in out, out   # the initial population and one generation, each one batch
    assert last_number(out, "best fitness") > 0


def test_map_elites_fills_cells():
    out = run_example("map_elites.py", "--evaluations", "32", "--batch", "16", "--quick")
    assert 0 < last_number(out, "coverage") <= 1


def test_circle_fitness_uses_the_whole_walk():
    out = run_example("circle_fitness.py", "--evaluations", "9", "--quick")
    assert last_number(out, "best circling") >= 0


def test_a_study_into_pandas_and_matplotlib(tmp_path):
    sweep = write(tmp_path / "tiny.xml", f"""<sweep name="tiny">
  <base>{os.path.join(SOURCE, "settings", "r1_gait.xml")}</base>
  <set>Gait.evaluations=16</set><set>Gait.populationSize=8</set>
  <set>Simulator.sample_to=3</set><set>Simulator.delayed_start=0.5</set><set>Experiment.workers=1</set>
  <grid><vary key="Gait.sigma0">0.1 0.3</vary></grid>
  <repeats count="2" firstSeed="1" seeds="same"/>
</sweep>
""")
    subprocess.run([CIC, "sweep", sweep, "--jobs", "2", "--output", str(tmp_path / "study"), "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    study = tmp_path / "study"
    if not (study / "index.csv").exists():   # the sweep's own folder under --output
        study = next(p for p in study.iterdir() if (p / "index.csv").exists())
    png = tmp_path / "study.png"
    out = run_example("study_pandas.py", str(study), str(png))
    assert "4 runs, 2 configurations" in out, out
    assert png.stat().st_size > 5000
