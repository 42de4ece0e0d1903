"""read_run and read_study: a run folder and a study folder as Python objects and pandas DataFrames."""

import os

from . import _core


def _read_csv(path):
    import pandas as pd

    return pd.read_csv(path)


class Run:
    """One run folder.

    best_genotype  one element Evaluator.evaluate accepts: a 1-D array (gait, CPG), an S-expression
                   string (one tree) or a list of them (a forest)
    best_offsets   Offset-HybrID's direct offsets beside best_genotype's trees (a 1-D array, empty
                   without them): pass them as Evaluator.evaluate(..., offsets=[run.best_offsets])
    best_fitness   its stored fitness (float): evaluating best_genotype gives these bits
    generation     the checkpoint it was read from (a MAP-Elites run: the batch)
    settings       the run's settings.xml (pass it to cic.Evaluator)
    stats          stats.csv as a pandas DataFrame
    """

    def __init__(self, folder):
        """Reads the run folder (see cic.read_run)."""
        self.folder = os.fspath(folder)
        best = _core.read_run_best(self.folder)
        self.form = best["form"]
        if self.form == "vector":
            self.best_genotype = best["vector"]
        else:
            trees = list(best["trees"])
            self.best_genotype = trees[0] if len(trees) == 1 else trees
        self.best_offsets = best["offsets"]
        self.best_fitness = float(best["fitness"])
        self.generation = int(best["generation"])
        self.settings = best["settings"]
        stats = os.path.join(self.folder, "stats.csv")
        self.stats = _read_csv(stats) if os.path.exists(stats) else None

    def __repr__(self):
        """One line: the folder, the best fitness and its generation."""
        return f"<cic.Run {self.folder}: best {self.best_fitness!r} at generation {self.generation}>"


def read_run(folder):
    """Reads a run folder (cic --settings ...'s RUN): its best genotype and fitness, and stats.csv.
    Raises FileNotFoundError when there is no such folder, ValueError when it is not a run's."""
    if not os.path.isdir(folder):
        raise FileNotFoundError(f"{folder}: no such run folder")
    return Run(folder)


class Study:
    """One study folder (cic sweep).

    index  index.csv: one row per (configuration, seed) with status, final and best-ever fitness, evaluations,
           wall time and the commit that made it
    stats  every run's stats.csv, one DataFrame, with the columns config, seed and run_dir in front
    """

    def __init__(self, folder):
        """Reads the study folder (see cic.read_study)."""
        import pandas as pd

        self.folder = os.fspath(folder)
        index = os.path.join(self.folder, "index.csv")
        if not os.path.exists(index):
            raise ValueError(f"{self.folder}: not a study folder (no index.csv; cic sweep writes it)")
        self.index = _read_csv(index)
        frames = []
        for row in self.index.itertuples(index=False):
            stats = os.path.join(self.folder, str(row.run_dir), "stats.csv")
            if not os.path.exists(stats):
                continue
            frame = _read_csv(stats)
            frame.insert(0, "run_dir", row.run_dir)
            frame.insert(0, "seed", row.seed)
            frame.insert(0, "config", row.config)
            frames.append(frame)
        self.stats = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()

    def run(self, config, seed):
        """The Run of one configuration and seed."""
        rows = self.index[(self.index["config"] == config) & (self.index["seed"] == seed)]
        if rows.empty:
            raise ValueError(f"{self.folder}: no run of configuration {config!r} with seed {seed}")
        return Run(os.path.join(self.folder, str(rows.iloc[0]["run_dir"])))

    def __repr__(self):
        """One line: the folder, its runs and configurations."""
        configs = self.index["config"].nunique() if len(self.index) else 0
        return f"<cic.Study {self.folder}: {len(self.index)} runs, {configs} configurations>"


def read_study(folder):
    """Reads a study folder: its index and every run's statistics as pandas DataFrames. Raises
    FileNotFoundError when there is no such folder, ValueError when it is not a study's."""
    if not os.path.isdir(folder):
        raise FileNotFoundError(f"{folder}: no such study folder")
    return Study(folder)


__all__ = ["Run", "Study", "read_run", "read_study"]
