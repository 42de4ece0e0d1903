"""cic from Python: score cic's robots with your own optimiser, fitness or archive, bit for bit.

    import cic, numpy as np
    with cic.Evaluator("r1_gait_ipop.xml", workers=2) as ev:
        scores = ev.evaluate(np.random.default_rng(1).random((16, ev.dimension)))
    walk = cic.simulate("r1_gait_ipop.xml", np.full(ev.dimension, 0.5))   # the whole walk
    run = cic.read_run("runs/r1_gait_ipop-001")                          # best_genotype, best_fitness, stats

docs/python.md has the whole API, the JSON-lines stream (`cic eval`) and the examples.
"""

from ._core import __version__
from ._evaluator import CicNote, CicWarning, Evaluation, Evaluator, Simulation, simulate
from ._results import Run, Study, read_run, read_study
from ._paths import executable

__all__ = ["Evaluator", "Evaluation", "Simulation", "CicWarning", "CicNote", "simulate", "read_run", "read_study",
           "Run", "Study", "executable", "__version__"]
