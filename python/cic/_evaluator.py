"""Evaluator and simulate: cic's robots scored from Python, to the last bit of a run.

Every number comes from cic's own C++ code (cic._core over the run layer's
EvaluationSession): the same job texts and ``cic worker`` processes as a run of
the same settings, so ODE's process-global state is handled as it is there.
"""

import warnings

import numpy as np

from . import _core, _paths


class CicWarning(RuntimeWarning):
    """Trouble that does not stop a batch: a worker replaced, a job retried or scored as failed; a float32
    batch converted to float64."""


class CicNote(UserWarning):
    """A note from cic that is not trouble: which installed settings file a bare name such as
    "r1_gait.xml" found. Silence it with warnings.filterwarnings("ignore", category=cic.CicNote)."""


def _say_notes(session, stacklevel):
    # cic's notes (the C++ side would print them on stderr) go through Python's warnings, so they can be silenced.
    for line in session.take_notes():
        warnings.warn(line, CicNote, stacklevel=stacklevel + 1)


def _float64(arr, what):
    """arr as float64; a float of fewer bits is converted with a CicWarning (its values are kept exactly, but
    they are not the float64 numbers an optimiser had before rounding them to float32)."""
    if arr.dtype.kind == "f" and arr.dtype.itemsize < 8:
        warnings.warn(f"{what} is {arr.dtype}: converted to float64 (cic scores float64 genotypes; a float32 value is "
                      f"rounded, so its fitness is not that of the float64 number it came from)", CicWarning,
                      stacklevel=4)
    return np.ascontiguousarray(arr, dtype=np.float64)


def _overrides(set):
    """A dict of 'Section.key' -> value as cic's --set texts (checked by cic, exactly like --set)."""
    if set is None:
        return []
    if not isinstance(set, dict):
        raise ValueError(f"set must be a dict of 'Section.key' -> value, got {type(set).__name__}")
    out = []
    for key, value in set.items():
        if not isinstance(key, str):
            raise ValueError(f"set: keys are 'Section.key' strings, got {key!r}")
        if isinstance(value, bool):
            value = int(value)
        out.append(f"{key}={value}")
    return out


class Evaluation:
    """The scores of one batch, one entry per genotype in batch order.

    fitness    the run's score (with the oscillation penalty or a type's own score where the settings have one)
    distance   eq. 7.1's walk along the robot's preferred axis, m (0 when failed)
    elevation  eq. 7.1's elevation gained by the centre module, m (0 when failed)
    failed     bool array: the physics failed or the worker could not run it (fitness is then Simulator.failureFitness)
    failure    why, per genotype ('' when it did not fail)
    descriptor (n, d) array of behaviour descriptors when the settings ask for one (MapElites), else None;
               a failed evaluation's row is NaN
    """

    def __init__(self, d):
        """Made by Evaluator.evaluate from the core's arrays (not meant to be built by hand)."""
        self.fitness = d["fitness"]
        self.distance = d["distance"]
        self.elevation = d["elevation"]
        self.failed = d["failed"]
        self.failure = list(d["failure"])
        self.descriptor = d.get("descriptor")

    def __len__(self):
        """The number of genotypes scored."""
        return len(self.fitness)

    def __repr__(self):
        """One line: how many genotypes and the best fitness."""
        best = f", best {self.fitness.max():.6g}" if len(self) else ""
        return f"<cic.Evaluation of {len(self)} genotypes{best}>"

    def to_dataframe(self):
        """The scores as a pandas DataFrame (descriptor columns d0, d1, ... when there are any)."""
        import pandas as pd

        frame = pd.DataFrame({"fitness": self.fitness, "distance": self.distance, "elevation": self.elevation,
                              "failed": self.failed, "failure": self.failure})
        if self.descriptor is not None:
            for j in range(self.descriptor.shape[1]):
                frame[f"d{j}"] = self.descriptor[:, j]
        return frame


class Simulation:
    """The whole of one evaluation (cic.simulate): per control step of Simulator.sample_step seconds,

    time     (n,)          s
    centre   (n, 3)        the centre module's position x, y, z, m
    angles   (n, joints)   each actuated joint's measured angle, rad (joint_names gives the order)
    targets  (n, joints)   each joint's commanded angle after the simulator's clamp, rad
    feet     (n, feet)     bool: the foot (a branch end, foot_names) touched the ground during the step

    and fitness, distance, elevation, failed, failure as in Evaluation. Without trace the arrays have no rows.
    duty_factors() gives each foot's duty factor as `cic assess` counts it.
    """

    def __init__(self, d):
        """Made by cic.simulate and Evaluator.simulate (not meant to be built by hand)."""
        self._duty_factors = d["duty_factors"]
        for key in ("fitness", "distance", "elevation", "failed", "failure", "time", "centre", "angles", "targets"):
            setattr(self, key, d[key])
        self.feet = d["feet"].astype(bool)
        self.joint_names = list(d["joint_names"])
        self.foot_names = list(d["foot_names"])

    def duty_factors(self):
        """Each foot's duty factor, in foot_names order: the share of the physics steps from the delayed start
        (Simulator.delayed_start) on in which it touched the ground. `cic assess` and MAP-Elites' duty-factor
        descriptor count exactly so. The mean of `feet` differs: it counts control steps, and from time 0,
        while the robot is still settling. Needs the trace (simulate(..., trace=True), the default)."""
        if len(self.time) == 0:
            raise ValueError("duty_factors needs the trace: simulate with trace=True")
        return self._duty_factors.copy()

    def __repr__(self):
        """One line: fitness, steps, joints and feet."""
        return (f"<cic.Simulation fitness {self.fitness:.6g}, {len(self.time)} steps, "
                f"{len(self.joint_names)} joints, {len(self.foot_names)} feet>")


class Evaluator:
    """Scores batches of genotypes for one settings file.

    >>> with cic.Evaluator("r1_gait_ipop.xml", workers=2) as ev:
    ...     scores = ev.evaluate(np.random.default_rng(1).random((8, ev.dimension)))

    settings_path  found like ``cic --settings`` (as given, else among the installed settings)
    workers        ``cic worker`` processes (1 or N give identical arrays)
    set            {'Section.key': value} overrides, checked exactly like ``--set``

    A settings file found nowhere raises FileNotFoundError, other bad input ValueError with cic's
    message (a gait vector outside the unit box too: in_box reads it as the run would). A worker
    that dies is replaced and its job retried, as in a run (a CicWarning says so). Ctrl-C during a
    batch raises KeyboardInterrupt and ends the workers; the next batch starts new ones. One
    Evaluator may be shared by threads: its calls run one at a time, with the GIL released while a
    batch runs.
    """

    def __init__(self, settings_path, workers=1, set=None):
        """Reads and checks the settings (as ``cic --settings`` does) and the robot; the workers start with the
        first batch. Raises FileNotFoundError for a settings file found nowhere, ValueError for bad settings,
        a symbolic-regression experiment or workers < 1. A bare name found among the installed settings is
        said with a CicNote warning."""
        if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)):
            raise ValueError(f"workers must be a whole number >= 1, got {workers!r}")
        self._session = _core.Session(str(settings_path), int(workers), _overrides(set), _paths.executable())
        _say_notes(self._session, 2)
        self.form = self._session.form                  # 'vector' (gait, CPG) or 'forest' (HyperGP trees)
        self.dimension = self._session.dimension        # a vector's length, or the trees of a forest
        self.offset_count = self._session.offset_count  # Offset-HybrID's direct offsets per forest (0: none)
        # The gait vector's length when gait vectors are taken: the gait family's, or beside trees a
        # Switch-HybrID run's genotype after its hand-over (Run.form 'vector'); else 0.
        self.vector_dimension = self._session.vector_dimension
        self.workers = self._session.workers
        self.settings_file = self._session.settings_file   # the file found
        self.experiment = self._session.experiment      # Experiment.type
        self.descriptor = self._session.descriptor      # 'none' or the MapElites descriptor
        self._closed = False

    def __enter__(self):
        """The Evaluator itself: ``with cic.Evaluator(...) as ev:`` closes it at the end of the block."""
        return self

    def __exit__(self, *exc):
        """Closes the Evaluator (ends its workers); exceptions go on."""
        self.close()
        return False

    def __del__(self):
        """Closes the Evaluator when it is collected, should close() not have been called."""
        try:
            self.close()
        except Exception:
            pass

    def close(self):
        """Ends the worker processes (also at the end of a with block)."""
        if not getattr(self, "_closed", True):
            self._closed = True
            self._session.close()

    def __repr__(self):
        """One line: experiment, genotype form and size, settings file and workers."""
        return (f"<cic.Evaluator {self.experiment} ({self.form} of {self.dimension}) from {self.settings_file}, "
                f"{self.workers} worker{'s' if self.workers != 1 else ''}>")

    def _points(self, x, reading):
        if self.vector_dimension == 0:
            raise ValueError("these settings evolve HyperGP trees: there is no gait vector to read into the unit box")
        if isinstance(x, (str, bytes)):
            raise ValueError("a gait vector is numbers, not a string")
        arr = np.asarray(x)
        if arr.dtype.kind not in "fiu" or arr.ndim not in (1, 2):
            raise ValueError(f"a gait vector (1-D) or a batch of them (2-D) of numbers; got dtype {arr.dtype}, "
                             f"shape {arr.shape}")
        rows = np.atleast_2d(_float64(arr, "the vector"))
        out = np.array([self._session.in_box(row.tolist(), reading) for row in rows]).reshape(rows.shape)
        return out[0] if arr.ndim == 1 else out

    def in_box(self, x):
        """The point of the unit box that the run reads `x` as (its Gait.bounds: reflect or clip; phases wrap),
        for one vector (1-D) or a batch (2-D). ``ev.evaluate(ev.in_box(x))`` gives the fitness a run gives x,
        bit for bit: what an optimiser that does not keep to [0, 1] (scipy's Nelder-Mead, pycma without
        bounds) hands to evaluate. A vector inside the box comes back unchanged."""
        return self._points(x, "settings")

    def reflect(self, x):
        """`x` read into the unit box by reflecting at its bounds (1.2 -> 0.8, -0.3 -> 0.3; phases wrap),
        whatever the settings' Gait.bounds: the continuous reading, as Gait.bounds=reflect does."""
        return self._points(x, "reflect")

    def clip(self, x):
        """`x` read into the unit box by clipping to its bounds (1.2 -> 1, -0.3 -> 0; phases wrap), whatever
        the settings' Gait.bounds: as Gait.bounds=clamp does."""
        return self._points(x, "clip")

    def decode(self, x):
        """The sine gait a gait vector in the unit box stands for, as a pandas DataFrame: one row per joint
        (robot order), with the columns joint (its name), amplitude, phase and offset in radians (and
        amplitude2, phase2 with Gait.secondHarmonic), and frequency in Hz (the same in every row, x[0]; also
        in frame.attrs["frequency"]). The numbers summary.txt gives. Layout: x[0] the frequency, then per
        joint amplitude, phase, offset [, amplitude2, phase2]."""
        import pandas as pd

        if isinstance(x, (str, bytes)):
            raise ValueError("a gait vector is numbers, not a string")
        arr = np.asarray(x)
        if arr.dtype.kind not in "fiu" or arr.ndim != 1:
            raise ValueError(f"decode takes one gait vector (1-D numbers); got dtype {arr.dtype}, shape {arr.shape}")
        d = self._session.decode(_float64(arr, "the vector").tolist())
        columns = {"joint": list(d["joint_names"]), "amplitude": d["amplitude"], "phase": d["phase"],
                   "offset": d["offset"]}
        if d["second_harmonic"]:
            columns.update(amplitude2=d["amplitude2"], phase2=d["phase2"])
        columns["frequency"] = np.full(len(columns["joint"]), d["frequency"])
        frame = pd.DataFrame(columns)
        frame.attrs["frequency"] = d["frequency"]
        return frame

    def evaluate(self, batch, offsets=None):
        """Scores a batch: a 2-D array or list of unit-box vectors (gait, CPG), or a list of
        S-expression strings / lists of strings (HyperGP trees, one list per forest). With
        Offset-HybrID settings (Evaluator.offset_count > 0) `offsets` gives each forest's direct
        offsets, one row per genotype (units of pi/2, as Run.best_offsets). Returns an Evaluation."""
        if self._closed:
            raise ValueError("this Evaluator is closed")
        if self.form == "vector" or (self.vector_dimension and _numbers(batch)):
            if offsets is not None:
                raise ValueError("offsets go beside HyperGP trees (Offset-HybrID), not gait vectors")
            result = self._session.evaluate_vectors(_vector_batch(batch, self.vector_dimension))
        else:
            forests = _forest_batch(batch)
            result = self._session.evaluate_forests(forests, _offset_rows(offsets, len(forests), self.offset_count))
        for line in self._session.take_warnings():
            warnings.warn(line, CicWarning, stacklevel=2)
        return Evaluation(result)

    def simulate(self, genotype, trace=True, offsets=None):
        """The whole evaluation of one genotype, in this process (see cic.simulate)."""
        if self._closed:
            raise ValueError("this Evaluator is closed")
        return _simulate(self._session, self.form, genotype, trace, offsets)


def _vector_batch(batch, dimension):
    if isinstance(batch, (str, bytes)):
        raise ValueError("a batch of gait vectors is a 2-D array or a list of vectors, not a string")
    try:
        arr = np.asarray(batch)
    except ValueError as e:   # ragged lists
        raise ValueError(f"a batch of gait vectors must be rectangular (every vector {dimension} numbers): {e}") from None
    if arr.size == 0 and arr.ndim <= 2:
        return np.zeros((0, dimension))
    if arr.dtype.kind not in "fiu":
        raise ValueError(f"a batch of gait vectors holds real numbers; got dtype {arr.dtype}")
    if arr.ndim != 2:
        hint = " (one genotype: pass [x])" if arr.ndim == 1 else ""
        raise ValueError(f"a batch of gait vectors is 2-D, one row per genotype; got {arr.ndim}-D, shape {arr.shape}{hint}")
    return _float64(arr, "the batch")


def _forest_batch(batch):
    if isinstance(batch, (str, bytes)):
        raise ValueError("a batch is a list of genotypes; for one tree pass [tree]")
    if isinstance(batch, np.ndarray) and batch.dtype.kind in "fiub":
        raise ValueError("these settings evolve HyperGP trees: a genotype is an S-expression string or a list of them")
    forests = []
    for i, g in enumerate(batch):
        if isinstance(g, str):
            forests.append([g])
        elif isinstance(g, (list, tuple)) and all(isinstance(t, str) for t in g):
            forests.append(list(g))
        else:
            raise ValueError(f"genotype {i}: a HyperGP genotype is an S-expression string or a list of them "
                             f"(a forest), got {type(g).__name__}")
    return forests


def _numbers(batch):
    """Whether a batch (or one genotype) is numbers: gait vectors, not S-expressions."""
    if isinstance(batch, (str, bytes)):
        return False
    if isinstance(batch, np.ndarray):
        return batch.dtype.kind in "fiu"   # an empty float batch too
    try:
        arr = np.asarray(batch)
    except ValueError:
        return False
    return arr.size > 0 and arr.dtype.kind in "fiu"


def _offset_rows(offsets, count, per_genotype):
    """Offset-HybrID's offsets as one list of floats per genotype, or [] for none."""
    if offsets is None:
        if per_genotype and count:
            raise ValueError(f"these settings are Offset-HybrID's (Neural.directOffsets): pass offsets=, "
                             f"{per_genotype} per genotype (Run.best_offsets)")
        return []
    if isinstance(offsets, (str, bytes)):
        raise ValueError("offsets are numbers, one row per genotype")
    try:
        arr = np.asarray(offsets, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"offsets: a 2-D array of numbers, one row per genotype: {e}") from None
    if count == 0 and arr.size == 0:
        return []
    if arr.ndim != 2 or arr.shape[0] != count:
        raise ValueError(f"offsets: a 2-D array of numbers, one row per genotype ({count}); got shape {arr.shape}")
    return arr.tolist()


def _simulate(session, form, genotype, trace, offsets=None):
    if form == "vector" or (session.vector_dimension and _numbers(genotype)):
        if offsets is not None:
            raise ValueError("offsets go beside HyperGP trees (Offset-HybrID), not gait vectors")
        if isinstance(genotype, (str, bytes)):
            raise ValueError("these settings evolve gait vectors: a genotype is a sequence of numbers")
        arr = np.asarray(genotype)
        if arr.dtype.kind not in "fiu" or arr.ndim != 1:
            raise ValueError(f"a gait genotype is a 1-D sequence of numbers; got dtype {arr.dtype}, shape {arr.shape}")
        return Simulation(session.simulate(_float64(arr, "the genotype").tolist(), [], bool(trace), []))
    trees = _forest_batch([genotype])[0]
    if offsets is None:
        if session.offset_count:
            raise ValueError(f"these settings are Offset-HybrID's (Neural.directOffsets): pass offsets=, "
                             f"{session.offset_count} numbers (Run.best_offsets)")
        return Simulation(session.simulate([], trees, bool(trace), []))
    if isinstance(offsets, (str, bytes)):
        raise ValueError("one genotype's offsets are a 1-D sequence of numbers, not a string")
    arr = np.asarray(offsets)
    if arr.dtype.kind not in "fiu" or arr.ndim != 1:
        raise ValueError(f"one genotype's offsets are a 1-D sequence of numbers; got dtype {arr.dtype}, "
                         f"shape {arr.shape}")
    return Simulation(session.simulate([], trees, bool(trace), arr.astype(np.float64).tolist()))


def simulate(settings_path, genotype, trace=True, set=None, offsets=None):
    """The whole evaluation of one genotype for these settings, in this process: a Simulation with the
    time, the centre's path, joint angles and targets and each foot's contacts, as numpy arrays, and
    the fitness a run would give it (bit for bit). What a fitness of your own, such as walking in a
    circle, needs. `offsets`: an Offset-HybrID genotype's direct offsets beside its trees."""
    session = _core.Session(str(settings_path), 1, _overrides(set), _paths.executable())
    _say_notes(session, 2)
    try:
        return _simulate(session, session.form, genotype, trace, offsets)
    finally:
        session.close()
