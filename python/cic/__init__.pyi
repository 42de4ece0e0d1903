# Type stubs of the cic package (PEP 561: py.typed beside them). The whole public API;
# docs/python.md says what each name does. tests/python/test_packaging.py checks that
# every public name of the package is here and nothing else.
import os
from typing import Any, ContextManager, Literal, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt
import pandas as pd

__version__: str

_Path = Union[str, "os.PathLike[str]"]
_Settings = Optional[Mapping[str, Union[str, int, float, bool]]]
# One genotype: a gait or CPG vector, one S-expression tree, or a forest of them.
_Genotype = Union[npt.ArrayLike, str, Sequence[str]]
_Batch = Union[npt.ArrayLike, Sequence[str], Sequence[Sequence[str]]]

class CicWarning(RuntimeWarning): ...
class CicNote(UserWarning): ...

class Evaluation:
    fitness: npt.NDArray[np.float64]
    distance: npt.NDArray[np.float64]
    elevation: npt.NDArray[np.float64]
    failed: npt.NDArray[np.bool_]
    failure: list[str]
    descriptor: Optional[npt.NDArray[np.float64]]
    def __init__(self, d: Mapping[str, Any]) -> None: ...
    def __len__(self) -> int: ...
    def to_dataframe(self) -> pd.DataFrame: ...

class Simulation:
    fitness: float
    distance: float
    elevation: float
    failed: bool
    failure: str
    time: npt.NDArray[np.float64]
    centre: npt.NDArray[np.float64]
    angles: npt.NDArray[np.float64]
    targets: npt.NDArray[np.float64]
    feet: npt.NDArray[np.bool_]
    joint_names: list[str]
    foot_names: list[str]
    def __init__(self, d: Mapping[str, Any]) -> None: ...
    def duty_factors(self) -> npt.NDArray[np.float64]: ...

class Evaluator(ContextManager["Evaluator"]):
    form: Literal["vector", "forest"]
    dimension: int
    offset_count: int
    vector_dimension: int
    workers: int
    settings_file: str
    experiment: str
    descriptor: str
    def __init__(self, settings_path: _Path, workers: int = 1, set: _Settings = None) -> None: ...
    def __enter__(self) -> "Evaluator": ...
    def __exit__(self, *exc: object) -> Literal[False]: ...
    def close(self) -> None: ...
    def evaluate(self, batch: _Batch, offsets: Optional[npt.ArrayLike] = None) -> Evaluation: ...
    def simulate(self, genotype: _Genotype, trace: bool = True,
                 offsets: Optional[npt.ArrayLike] = None) -> Simulation: ...
    def in_box(self, x: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def reflect(self, x: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def clip(self, x: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def decode(self, x: npt.ArrayLike) -> pd.DataFrame: ...

def simulate(settings_path: _Path, genotype: _Genotype, trace: bool = True, set: _Settings = None,
             offsets: Optional[npt.ArrayLike] = None) -> Simulation: ...

class Run:
    folder: str
    form: Literal["vector", "forest"]
    best_genotype: Union[npt.NDArray[np.float64], str, list[str]]
    best_offsets: npt.NDArray[np.float64]
    best_fitness: float
    generation: int
    settings: str
    stats: Optional[pd.DataFrame]
    def __init__(self, folder: _Path) -> None: ...

class Study:
    folder: str
    index: pd.DataFrame
    stats: pd.DataFrame
    def __init__(self, folder: _Path) -> None: ...
    def run(self, config: str, seed: int) -> Run: ...

def read_run(folder: _Path) -> Run: ...
def read_study(folder: _Path) -> Study: ...
def executable() -> str: ...
