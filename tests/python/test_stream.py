"""`cic eval`: the JSON-lines stream for any language (docs/python.md, "The stream")."""

import json
import os
import shutil
import subprocess

import numpy as np
import pytest

import cic
from conftest import CIC, SOURCE

R1_GAIT = os.path.join(SOURCE, "settings", "r1_gait.xml")
QUICK = ["--set", "Simulator.sample_to=3", "--set", "Simulator.delayed_start=0.5"]


def stream(lines, *args):
    p = subprocess.run([CIC, "eval", "--settings", R1_GAIT, *QUICK, *args], input="".join(l + "\n" for l in lines),
                       capture_output=True, text=True, timeout=300)
    return p.returncode, [json.loads(l) for l in p.stdout.splitlines()], p.stderr


def test_each_line_gets_the_evaluators_bits_in_order():
    xs = np.random.default_rng(11).random((5, 37))
    lines = [json.dumps({"id": i, "genotype": list(x)}) for i, x in enumerate(xs)]
    lines.insert(2, "")   # blank lines are skipped
    rc, replies, err = stream(lines, "--workers", "2")
    assert rc == 0, err
    assert [r["id"] for r in replies] == list(range(5))
    with cic.Evaluator(R1_GAIT, set={"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5}) as ev:
        want = ev.evaluate(xs)
    for r, f, d, e in zip(replies, want.fitness, want.distance, want.elevation):
        assert (r["fitness"], r["distance"], r["elevation"], r["failed"]) == (f, d, e, False)


def test_an_offset_hybrid_line_carries_its_offsets(runs):
    run = cic.read_run(runs["offset"])
    trees = [run.best_genotype] if isinstance(run.best_genotype, str) else run.best_genotype
    line = json.dumps({"id": "best", "genotype": trees, "offsets": list(run.best_offsets)})
    p = subprocess.run([CIC, "eval", "--settings", run.settings], input=line + "\n" + json.dumps(trees) + "\n",
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    best, bare = [json.loads(l) for l in p.stdout.splitlines()]
    assert best["id"] == "best" and best["fitness"] == run.best_fitness
    assert "error" in bare and "offsets" in bare["error"]   # settings with offsets need them
    info = json.loads(subprocess.run([CIC, "eval", "--settings", run.settings, "--info"], capture_output=True,
                                     text=True).stdout)
    assert info["offset_count"] == 8


def test_a_switch_hybrid_stream_takes_its_gait_and_its_trees(runs):
    run = cic.read_run(runs["switch"])
    info = json.loads(subprocess.run([CIC, "eval", "--settings", run.settings, "--info"], capture_output=True,
                                     text=True).stdout)
    assert (info["form"], info["vector_dimension"]) == ("forest", 37)
    lines = [json.dumps(list(run.best_genotype)), json.dumps(["x0"] * info["dimension"])]
    p = subprocess.run([CIC, "eval", "--settings", run.settings], input="\n".join(lines) + "\n",
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    gait, trees = [json.loads(l) for l in p.stdout.splitlines()]
    assert gait["fitness"] == run.best_fitness and "fitness" in trees
    # Offsets go beside trees only.
    line = json.dumps({"genotype": list(run.best_genotype), "offsets": [0.0] * 12})
    p = subprocess.run([CIC, "eval", "--settings", run.settings], input=line + "\n", capture_output=True, text=True,
                       timeout=300)
    assert "not beside a gait vector" in json.loads(p.stdout)["error"]


def test_readmes_line_finds_the_settings_by_bare_name_from_any_folder(tmp_path):
    # README.md's line, verbatim, run in an empty folder with the build's cic first on PATH.
    with open(os.path.join(SOURCE, "README.md")) as f:
        line = next(l for l in f if l.startswith("cic eval --settings"))
    command = line.split("#")[0].strip()
    assert command == "cic eval --settings r1_gait.xml < genotypes.jsonl"
    (tmp_path / "genotypes.jsonl").write_text(json.dumps({"id": 1, "genotype": [0.5] * 37}) + "\n")
    env = dict(os.environ, PATH=os.path.dirname(os.path.abspath(CIC)) + os.pathsep + os.environ["PATH"])
    p = subprocess.run(["bash", "-c", command], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    reply = json.loads(p.stdout)
    assert reply["id"] == 1 and "fitness" in reply, reply
    assert "r1_gait.xml: using " + os.path.realpath(R1_GAIT) in p.stderr, p.stderr


def test_a_bare_vector_is_a_genotype_too():
    rc, replies, _ = stream([json.dumps([0.5] * 37)])
    assert rc == 0 and "fitness" in replies[0] and "id" not in replies[0]


def test_a_bad_line_gets_its_error_and_the_others_their_scores():
    rc, replies, _ = stream(['{"id": "a", "genotype": [0.5]}', "not json", json.dumps({"id": "b", "genotype": [0.5] * 37}),
                             json.dumps({"id": "c", "genotype": [2.0] * 37}), '{"id": "d"}'])
    assert rc == 0
    assert [r.get("id") for r in replies] == ["a", None, "b", "c", "d"]
    assert "1 values" in replies[0]["error"]
    assert "not a JSON genotype" in replies[1]["error"]
    assert "fitness" in replies[2] and "error" not in replies[2]
    assert "unit box" in replies[3]["error"]
    assert "genotype" in replies[4]["error"]


def test_info_describes_the_genotypes_and_bad_settings_exit_2():
    p = subprocess.run([CIC, "eval", "--settings", R1_GAIT, "--info"], capture_output=True, text=True)
    info = json.loads(p.stdout)
    assert (info["protocol"], info["form"], info["dimension"], info["experiment"]) == (1, "vector", 37, "gait")
    p = subprocess.run([CIC, "eval", "--settings", R1_GAIT, "--set", "Gait.evaluation=3"], input="", capture_output=True,
                       text=True)
    assert p.returncode == 2 and "did you mean" in p.stderr and p.stdout == ""


@pytest.mark.skipif(shutil.which("octave-cli") is None and shutil.which("octave") is None, reason="no octave")
def test_the_octave_example_talks_to_the_stream(tmp_path):
    octave = shutil.which("octave-cli") or shutil.which("octave")
    env = dict(os.environ, CIC=CIC, CIC_SETTINGS=R1_GAIT, CIC_QUICK="1")
    p = subprocess.run([octave, "--no-gui", "--quiet", "--no-window-system",
                        os.path.join(SOURCE, "examples", "python", "octave_stream.m")],
                       cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "best fitness" in p.stdout, p.stdout
