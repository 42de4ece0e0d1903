"""cic.Evaluator, cic.simulate and cic.read_run: the same bits as cic's own runs (issue 37)."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
import warnings

import numpy as np
import pytest

import cic
from conftest import CIC, SOURCE, children_of

R1_GAIT = os.path.join(SOURCE, "settings", "r1_gait.xml")
QUICK = {"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5}


def bits(a):
    return np.asarray(a, dtype=np.float64).view(np.uint64)


# --- the same bits as a run ---------------------------------------------------------

@pytest.mark.parametrize("family", ["gait", "cpg", "hypergp", "forest", "map_elites"])
def test_best_genotype_scores_its_stored_fitness_to_the_last_bit(runs, family):
    run = cic.read_run(runs[family])
    with cic.Evaluator(run.settings, workers=1) as ev:
        scores = ev.evaluate([run.best_genotype])
    assert bits(scores.fitness[0]) == bits(run.best_fitness), (scores.fitness[0], run.best_fitness)
    assert not scores.failed[0]
    if family == "map_elites":
        assert scores.descriptor.shape == (1, 4)   # R1's four feet: duty factors
        assert ((scores.descriptor >= 0) & (scores.descriptor <= 1)).all()
    else:
        assert scores.descriptor is None


@pytest.mark.parametrize("family", ["gait", "hypergp"])
def test_distance_and_elevation_are_eq71_terms_of_the_fitness(runs, family):
    run = cic.read_run(runs[family])
    with cic.Evaluator(run.settings) as ev:
        s = ev.evaluate([run.best_genotype])
    assert s.distance[0] >= 0
    assert s.distance[0] + s.elevation[0] == s.fitness[0]   # no penalty in these settings


def test_read_run_gives_stats_as_a_dataframe(runs):
    run = cic.read_run(runs["gait"])
    assert list(run.stats.columns[:3]) == ["generation", "best", "mean"]
    assert len(run.stats) == 5   # 40 evaluations in generations of 8
    assert isinstance(run.best_genotype, np.ndarray) and run.best_genotype.ndim == 1
    forest = cic.read_run(runs["forest"])
    assert isinstance(forest.best_genotype, list) and len(forest.best_genotype) == 2
    assert isinstance(cic.read_run(runs["hypergp"]).best_genotype, str)


def test_one_and_two_workers_give_identical_arrays():
    xs = np.random.default_rng(7).random((10, 37))
    with cic.Evaluator(R1_GAIT, workers=1, set=QUICK) as one, cic.Evaluator(R1_GAIT, workers=2, set=QUICK) as two:
        a, b = one.evaluate(xs), two.evaluate(xs)
        c = two.evaluate(list(xs))   # a list of vectors is the same batch
    for key in ("fitness", "distance", "elevation"):
        assert (bits(getattr(a, key)) == bits(getattr(b, key))).all()
        assert (bits(getattr(a, key)) == bits(getattr(c, key))).all()
    assert len(set(a.fitness)) > 1   # ten different gaits, not one number ten times


def test_simulate_returns_the_whole_walk_with_the_runs_fitness(runs):
    run = cic.read_run(runs["gait"])
    walk = cic.simulate(run.settings, run.best_genotype)
    assert bits(walk.fitness) == bits(run.best_fitness)
    steps = len(walk.time)
    assert steps == 240   # 3 s at 0.0125 s
    assert walk.centre.shape == (steps, 3)
    assert walk.angles.shape == walk.targets.shape == (steps, 12)
    assert walk.feet.shape == (steps, 4) and walk.feet.dtype == bool
    assert walk.feet.any() and not walk.feet.all()   # feet touch and lift
    assert walk.joint_names and walk.foot_names
    # The centre's path gives eq. 7.1's distance: along y for R1, from the delayed start on.
    start = int(round(0.5 / 0.0125))
    assert abs(abs(walk.centre[-1, 1] - walk.centre[start, 1]) - walk.distance) < 0.05
    quiet = cic.simulate(run.settings, run.best_genotype, trace=False)
    assert bits(quiet.fitness) == bits(walk.fitness) and len(quiet.time) == 0


def test_simulate_a_hypergp_forest(runs):
    run = cic.read_run(runs["forest"])
    walk = cic.simulate(run.settings, run.best_genotype)
    assert bits(walk.fitness) == bits(run.best_fitness)
    assert walk.angles.shape[1] == 8   # R0: four legs of two hinges


def test_an_offset_hybrid_genotype_scores_its_stored_fitness_with_its_offsets(runs):
    run = cic.read_run(runs["offset"])
    assert run.best_offsets.shape == (8,) and np.any(run.best_offsets != 0)   # R0's eight hinges
    with cic.Evaluator(run.settings, workers=2) as ev:
        assert ev.offset_count == 8
        scores = ev.evaluate([run.best_genotype], offsets=[run.best_offsets])
        assert bits(scores.fitness[0]) == bits(run.best_fitness)
        # The same trees without their offsets walk otherwise: the offsets are not ignored.
        zero = ev.evaluate([run.best_genotype], offsets=[np.zeros(8)])
        assert bits(zero.fitness[0]) != bits(run.best_fitness)
        walk = ev.simulate(run.best_genotype, offsets=run.best_offsets)
        assert bits(walk.fitness) == bits(run.best_fitness)
        with pytest.raises(ValueError, match="pass offsets="):
            ev.evaluate([run.best_genotype])
        with pytest.raises(ValueError, match="7 offsets, but .* 8"):
            ev.evaluate([run.best_genotype], offsets=[np.zeros(7)])
        with pytest.raises(ValueError, match="one row per genotype"):
            ev.evaluate([run.best_genotype], offsets=np.zeros(8))
        with pytest.raises(ValueError, match="offset 0 is 9"):
            ev.evaluate([run.best_genotype], offsets=[[9.0] + [0.0] * 7])
        with pytest.raises(ValueError, match="1-D sequence"):
            ev.simulate(run.best_genotype, offsets=[run.best_offsets])
        with pytest.raises(ValueError, match="pass offsets="):
            ev.simulate(run.best_genotype)
        assert len(ev.evaluate([])) == 0   # an empty batch needs no offsets
    with cic.Evaluator(cic.read_run(runs["hypergp"]).settings) as plain:
        assert plain.offset_count == 0
        with pytest.raises(ValueError, match="Neural.directOffsets = 0"):
            plain.evaluate(["x0"], offsets=[[0.1]])
    assert cic.read_run(runs["hypergp"]).best_offsets.shape == (0,)


def test_a_switch_hybrid_run_past_its_hand_over_scores_its_gait_and_its_trees(runs):
    run = cic.read_run(runs["switch"])
    assert run.form == "vector" and run.best_genotype.shape == (37,)
    with cic.Evaluator(run.settings, workers=2) as ev:
        assert (ev.form, ev.vector_dimension) == ("forest", 37)   # trees first, the gait after the hand-over
        scores = ev.evaluate([run.best_genotype])
        assert bits(scores.fitness[0]) == bits(run.best_fitness)
        assert bits(ev.simulate(run.best_genotype).fitness) == bits(run.best_fitness)
        trees = ev.evaluate([["x0"] * ev.dimension])
        assert np.isfinite(trees.fitness[0])
        with pytest.raises(ValueError, match="36 values"):
            ev.evaluate([np.full(36, 0.5)])
        assert len(ev.evaluate(np.zeros((0, 37)))) == 0
        two = ev.evaluate([np.clip(run.best_genotype, 0, 1), run.best_genotype])   # replies in batch order
        assert bits(two.fitness[1]) == bits(run.best_fitness)
    with cic.Evaluator(cic.read_run(runs["hypergp"]).settings) as plain:
        assert plain.vector_dimension == 0
        with pytest.raises(ValueError, match="S-expression"):
            plain.evaluate([[0.5, 0.5]])


# --- bad input: a Python exception, never a dead interpreter --------------------------

@pytest.fixture(scope="module")
def gait_ev():
    with cic.Evaluator(R1_GAIT, set=QUICK) as ev:
        yield ev


@pytest.mark.parametrize("batch, words", [
    (np.zeros((2, 36)), "36 values"),
    (np.zeros(37), "2-D"),
    (np.zeros((2, 37, 1)), "2-D"),
    (np.array([["a"] * 37]), "dtype"),
    (np.full((1, 37), np.nan), "outside the unit box"),
    (np.full((1, 37), 1.5), "outside the unit box"),
    ([[0.5] * 37, [0.5] * 36], "rectangular"),
    (["(add x0 x1)"], "dtype"),
])
def test_bad_vector_batches_raise_value_error(gait_ev, batch, words):
    with pytest.raises(ValueError, match=words):
        gait_ev.evaluate(batch)


def test_an_empty_batch_gives_empty_scores(gait_ev):
    assert len(gait_ev.evaluate(np.zeros((0, 37)))) == 0


def test_bad_trees_raise_value_error(runs):
    run = cic.read_run(runs["hypergp"])
    with cic.Evaluator(run.settings) as ev:
        with pytest.raises(ValueError, match="unknown function.*frobnicate|frobnicate"):
            ev.evaluate(["(frobnicate x0 x1)"])
        with pytest.raises(ValueError, match="x9"):
            ev.evaluate(["(add x0 x9)"])
        with pytest.raises(ValueError, match="2 trees, but GP.numberOfTreesInForestGenotype is 1"):
            ev.evaluate([["(add x0 x1)", "x2"]])
        with pytest.raises(ValueError, match="list of genotypes"):
            ev.evaluate("(add x0 x1)")
        with pytest.raises(ValueError, match="S-expression"):
            ev.evaluate([[0.5, 0.5]])


def test_bad_settings_raise_value_error_naming_the_key():
    with pytest.raises(ValueError, match=r"Gait.*evaluation.*did you mean.*evaluations"):
        cic.Evaluator(R1_GAIT, set={"Gait.evaluation": 100})
    with pytest.raises(ValueError, match="sample_step"):
        cic.Evaluator(R1_GAIT, set={"Simulator.sample_step": -1})
    with pytest.raises(ValueError, match="workers"):
        cic.Evaluator(R1_GAIT, workers=0)
    with pytest.raises(ValueError, match="symbolic regression"):
        cic.Evaluator(os.path.join(SOURCE, "settings", "symreg_settings.xml"))
    with pytest.raises(ValueError, match="dict"):
        cic.Evaluator(R1_GAIT, set=["Gait.evaluations=3"])


def test_a_closed_evaluator_refuses_and_leaves_no_worker():
    ev = cic.Evaluator(R1_GAIT, workers=2, set=QUICK)
    ev.evaluate(np.full((2, 37), 0.5))
    assert len(children_of(os.getpid())) >= 2
    with ev:
        pass
    assert children_of(os.getpid()) == []
    with pytest.raises(ValueError, match="closed"):
        ev.evaluate(np.full((1, 37), 0.5))


def test_a_worker_that_dies_is_replaced_and_its_job_retried():
    xs = np.random.default_rng(3).random((60, 37))   # 15 s walks: about a second of work to interrupt
    with cic.Evaluator(R1_GAIT, workers=2) as ev:
        want = ev.evaluate(xs)
        got = {}
        worker = threading.Thread(target=lambda: got.setdefault("s", ev.evaluate(xs)))
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            worker.start()
            time.sleep(0.3)
            victims = children_of(os.getpid())
            assert victims
            os.kill(victims[0], signal.SIGKILL)
            worker.join()
        assert (bits(got["s"].fitness) == bits(want.fitness)).all()
    # The replaced worker is said, as in a run (warnings go to the process-wide filters).
    assert any(issubclass(w.category, cic.CicWarning) and "replaced" in str(w.message) for w in caught), \
        [str(w.message) for w in caught]


def test_the_gil_is_released_while_a_batch_runs():
    xs = np.random.default_rng(5).random((60, 37))   # long enough for the counter to tick many times
    with cic.Evaluator(R1_GAIT, workers=1, set=QUICK) as ev:
        ticks = []
        done = threading.Event()

        def count():
            while not done.is_set():
                ticks.append(1)
                time.sleep(0.001)

        counter = threading.Thread(target=count)
        counter.start()
        start = time.monotonic()
        ev.evaluate(xs)
        elapsed = time.monotonic() - start
        done.set()
        counter.join()
    # With the GIL held for the batch the counter could not run at all.
    assert elapsed > 0.1 and len(ticks) > 20, (elapsed, len(ticks))


def test_ctrl_c_during_a_batch_raises_keyboard_interrupt_and_leaves_no_worker(tmp_path):
    script = tmp_path / "interrupt.py"
    script.write_text(textwrap.dedent(f"""
        import os, sys, numpy as np, cic
        sys.path.insert(0, {os.path.dirname(__file__)!r})
        from conftest import children_of
        ev = cic.Evaluator({R1_GAIT!r}, workers=2)
        print("ready", flush=True)
        try:
            ev.evaluate(np.random.default_rng(1).random((400, 37)))
            print("finished")
        except KeyboardInterrupt:
            print("interrupted", len(children_of(os.getpid())), flush=True)
        s = ev.evaluate(np.full((1, 37), 0.5))   # the next batch starts new workers
        print("again", len(s))
    """))
    p = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True, env=os.environ)
    assert p.stdout.readline().strip() == "ready"
    time.sleep(1.0)
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=120)
    assert p.returncode == 0, out
    assert "interrupted 0" in out, out
    assert "again 1" in out, out


# --- Python's conventions (issue 57) ----------------------------------------------------

def test_a_missing_file_is_file_not_found_and_other_bad_input_stays_value_error(tmp_path):
    with pytest.raises(FileNotFoundError, match="no-such-settings.xml.*not found"):
        cic.Evaluator("no-such-settings.xml")
    with pytest.raises(FileNotFoundError, match="not found"):
        cic.simulate(str(tmp_path / "gone.xml"), np.full(37, 0.5))
    with pytest.raises(FileNotFoundError):
        cic.read_run(tmp_path / "no-run")
    with pytest.raises(FileNotFoundError):
        cic.read_study(tmp_path / "no-study")
    with pytest.raises(ValueError, match="not a regular file"):
        cic.Evaluator(str(tmp_path))   # there, but not a settings file: bad input
    with pytest.raises(ValueError):
        cic.read_run(tmp_path)   # a folder, but no run's


def test_the_settings_a_bare_name_found_are_a_cic_note_that_can_be_silenced(capfd):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with cic.Evaluator("r1_gait.xml", set=QUICK) as ev:
            assert os.path.samefile(ev.settings_file, R1_GAIT)
        cic.simulate("r1_gait.xml", np.full(37, 0.5), trace=False, set=QUICK)
    notes = [str(w.message) for w in caught if issubclass(w.category, cic.CicNote)]
    assert len(notes) == 2 and all("r1_gait.xml: using" in n for n in notes), notes
    assert all(w.filename == __file__ for w in caught)   # said at the caller's line
    assert capfd.readouterr().err == ""   # not printed by C++ where warnings cannot reach it
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warnings.filterwarnings("ignore", category=cic.CicNote)
        cic.Evaluator("r1_gait.xml", set=QUICK).close()
    assert caught == []


def test_a_killed_sessions_folder_is_removed_by_the_next_start(tmp_path, monkeypatch):
    script = textwrap.dedent(f"""
        import time, cic
        ev = cic.Evaluator({R1_GAIT!r})
        print("ready", flush=True)
        time.sleep(300)
    """)
    p = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                         env=dict(os.environ, TMPDIR=str(tmp_path)))
    try:
        assert p.stdout.readline().strip() == "ready"
        theirs = list(tmp_path.glob("cic-eval-*"))
        assert len(theirs) == 1
        monkeypatch.setenv("TMPDIR", str(tmp_path))
        cic.Evaluator(R1_GAIT, set=QUICK).close()
        assert theirs[0].exists()   # a live session's folder is its own
    finally:
        p.kill()   # SIGKILL: no destructor, no atexit
        p.wait()
    assert theirs[0].exists()
    with cic.Evaluator(R1_GAIT, set=QUICK):
        mine = list(tmp_path.glob("cic-eval-*"))
        assert len(mine) == 1 and mine != theirs
    assert list(tmp_path.glob("cic-eval-*")) == []


def test_a_float32_batch_is_converted_with_a_warning(gait_ev):
    x = np.random.default_rng(9).random((2, 37))
    x32 = x.astype(np.float32)
    with pytest.warns(cic.CicWarning, match="float32.*converted to float64"):
        got = gait_ev.evaluate(x32)
    want = gait_ev.evaluate(x32.astype(np.float64))   # the float32 values, exactly
    assert (bits(got.fitness) == bits(want.fitness)).all()
    with pytest.warns(cic.CicWarning, match="float32"):
        gait_ev.simulate(x32[0], trace=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")   # float64 and integers: nothing to say
        gait_ev.evaluate(x)
        gait_ev.evaluate(np.zeros((1, 37), dtype=np.int64))


# --- the genotype, for people who optimise it (issue 57) ---------------------------------

def test_a_point_outside_the_box_is_read_as_the_run_reads_it(gait_ev):
    rng = np.random.default_rng(2)
    x = rng.random(37) * 1.6 - 0.3   # what scipy's Nelder-Mead or pycma without bounds try
    x[1], x[2], x[4] = 1.2, -0.3, 1.5   # an amplitude, a phase, an amplitude
    with pytest.raises(ValueError, match="outside the unit box"):
        gait_ev.evaluate([x])
    inside = gait_ev.in_box(x)   # r1_gait.xml: Gait.bounds reflect
    assert ((inside >= 0) & (inside <= 1)).all()
    assert (bits(inside) == bits(gait_ev.reflect(x))).all()
    assert inside[1] == pytest.approx(0.8) and inside[4] == pytest.approx(0.5)   # mirrored
    assert inside[2] == pytest.approx(0.7)   # a phase wraps (periodic)
    clipped = gait_ev.clip(x)
    assert (clipped[1], clipped[4]) == (1.0, 1.0) and clipped[2] == pytest.approx(0.7)
    assert np.isfinite(gait_ev.evaluate([inside]).fitness[0])
    y = rng.random(37)
    assert (bits(gait_ev.in_box(y)) == bits(y)).all()   # inside the box nothing changes
    both = gait_ev.in_box(np.stack([x, y]))
    assert both.shape == (2, 37) and (bits(both[0]) == bits(inside)).all()
    with cic.Evaluator(R1_GAIT, set=dict(QUICK, **{"Gait.bounds": "clamp"})) as clamp:
        assert (bits(clamp.in_box(x)) == bits(clipped)).all()
    with pytest.raises(ValueError, match="36 values"):
        gait_ev.in_box(np.zeros(36))


def test_the_run_reads_its_points_so_in_box_gives_the_runs_fitness(runs):
    # read_run hands the champion over in the box (the optimiser's own point may be outside it):
    # in_box of a point is that point's reading, so re-reading changes nothing.
    run = cic.read_run(runs["gait"])
    with cic.Evaluator(run.settings) as ev:
        assert (bits(ev.in_box(run.best_genotype)) == bits(run.best_genotype)).all()
        assert bits(ev.evaluate(ev.in_box([run.best_genotype])).fitness[0]) == bits(run.best_fitness)


def test_decode_gives_the_gait_as_summary_txt_does(runs):
    run = cic.read_run(runs["gait"])
    with cic.Evaluator(run.settings) as ev:
        frame = ev.decode(run.best_genotype)
        x = np.random.default_rng(4).random(37)
        layout = ev.decode(x)
        with pytest.raises(ValueError, match="outside the unit box"):
            ev.decode(np.full(37, 1.5))
    assert list(frame.columns) == ["joint", "amplitude", "phase", "offset", "frequency"]
    assert len(frame) == 12 and frame["joint"].is_unique
    # The layout: x[0] the frequency, then per joint amplitude, phase, offset.
    assert layout.attrs["frequency"] == pytest.approx(0.1 + x[0] * (3.0 - 0.1))
    assert (layout["frequency"] == layout.attrs["frequency"]).all()
    assert np.allclose(layout["amplitude"], x[1::3] * np.pi / 2)
    assert np.allclose(layout["phase"], x[2::3] * 2 * np.pi)
    assert np.allclose(layout["offset"], (2 * x[3::3] - 1) * np.pi / 2)
    # summary.txt's line for the same champion, to its printed digits.
    with open(os.path.join(runs["gait"], "summary.txt")) as f:
        line = next(l for l in f if "per joint amplitude/phase/offset" in l)
    hz = float(line.split("frequency ")[1].split(" Hz")[0])
    assert f"{frame.attrs['frequency']:.4f}" == f"{hz:.4f}"
    joints = [g.split() for g in line.split("[")[1:]]
    assert [[f"{v:.3f}" for v in row] for row in frame[["amplitude", "phase", "offset"]].to_numpy()] == \
        [[g.rstrip("]") for g in j[:3]] for j in joints]


def test_duty_factors_are_cic_assess_to_the_digit(runs):
    run = cic.read_run(runs["gait"])
    walk = cic.simulate(run.settings, run.best_genotype)
    p = subprocess.run([CIC, "assess", runs["gait"]], capture_output=True, text=True, check=True)
    duty = dict(f.split(":") for f in p.stdout.splitlines()[1].rsplit(",", 1)[1].split())
    got = walk.duty_factors()
    assert got.shape == (len(walk.foot_names),)
    assert [f"{v:.3f}" for v in got] == [duty[name] for name in walk.foot_names], (got, duty)
    with pytest.raises(ValueError, match="trace=True"):
        cic.simulate(run.settings, run.best_genotype, trace=False).duty_factors()
