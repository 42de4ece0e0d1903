"""cic as a Python package (issue 57): its version and dist-info, type stubs and docstrings,
`pip install --no-build-isolation .` (pyproject.toml, setup.py) into a venv, and
scripts/run.sh building it with the first command."""

import ast
import importlib.metadata
import inspect
import json
import os
import pydoc
import re
import subprocess
import sys
import textwrap

import numpy as np

import cic
from conftest import CIC, SOURCE

PACKAGE = os.path.dirname(cic.__file__)


def cmake_version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        return re.search(r"project\(cic VERSION ([0-9.]+)", f.read()).group(1)


def public_classes():
    return [getattr(cic, n) for n in cic.__all__ if inspect.isclass(getattr(cic, n))]


def own_methods(cls):
    """The functions a class defines itself: its public ones and the dunders people call."""
    return {n: f for n, f in vars(cls).items() if inspect.isfunction(f) and
            (not n.startswith("_") or n in ("__init__", "__enter__", "__exit__", "__len__"))}


def test_the_version_is_cmakes_and_importlib_metadata_finds_it():
    assert cic.__version__ == cmake_version()
    assert importlib.metadata.version("cic") == cic.__version__
    assert importlib.metadata.metadata("cic")["Name"] == "cic"
    assert os.path.exists(os.path.join(PACKAGE, "py.typed"))


def test_the_stubs_cover_the_whole_public_api():
    with open(os.path.join(PACKAGE, "__init__.pyi")) as f:
        stub = ast.parse(f.read())
    top = {}
    for node in stub.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            top[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            top[node.target.id] = node
    assert set(cic.__all__) == {n for n in top if not n.startswith("_") or n == "__version__"}
    for cls in public_classes():
        node = top[cls.__name__]
        members = {n.name if isinstance(n, ast.FunctionDef) else n.target.id
                   for n in node.body if isinstance(n, (ast.FunctionDef, ast.AnnAssign))}
        missing = set(own_methods(cls)) - members
        assert not missing, (cls.__name__, missing)
        source = inspect.getsource(cls)
        for m in members:   # each attribute the stub names is one the class sets or defines
            assert m in vars(cls) or f"self.{m} =" in source or f'"{m}"' in source, (cls.__name__, m)


def test_every_public_name_has_its_own_docstring_constructors_included():
    for name in cic.__all__:
        if name != "__version__":
            assert inspect.getdoc(getattr(cic, name)), name
    for cls in public_classes():
        for name, f in own_methods(cls).items():
            assert f.__doc__ and f.__doc__.strip(), f"{cls.__name__}.{name}"
        text = pydoc.render_doc(cls, renderer=pydoc.plaintext).split("inherited from builtins")[0]   # its own part
        assert "Initialize self" not in text, cls.__name__
        assert not re.search(r"^\s*\|?\s*# ", text, re.M), text   # no stray code comment shown as help


def test_pip_installs_it_offline_into_a_venv_with_debians_packages(tmp_path):
    venv = tmp_path / "venv"
    subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(venv)], check=True)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "CIC_EXECUTABLE")}
    env["CIC_BUILD_DIR"] = os.path.dirname(os.path.abspath(CIC))   # the build this test runs in: nothing to compile
    env["PIP_NO_INDEX"] = "1"   # offline, as on a machine with Debian's archive only
    p = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation", "."], cwd=SOURCE, env=env,
                       capture_output=True, text=True, timeout=900)
    assert p.returncode == 0, p.stdout + p.stderr
    script = textwrap.dedent("""
        import importlib.metadata, json, warnings, cic
        warnings.simplefilter("ignore", cic.CicNote)
        with cic.Evaluator("r1_gait.xml", set={"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5}) as ev:
            f = ev.evaluate([[0.5] * ev.dimension]).fitness[0]
        print(json.dumps({"file": cic.__file__, "version": cic.__version__, "exe": cic.executable(),
                          "metadata": importlib.metadata.version("cic"), "settings": ev.settings_file,
                          "fitness": float(f).hex()}))
    """)
    out = subprocess.run([str(venv / "bin" / "python"), "-c", script], cwd=tmp_path, env=env, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout)
    assert got["file"].startswith(str(venv)), got
    assert got["version"] == got["metadata"] == cmake_version()
    assert got["exe"] == str(venv / "bin" / "cic")   # the binary came with it, as cmake --install lays it out
    assert got["settings"] == str(venv / "share" / "cic" / "settings" / "r1_gait.xml")
    with cic.Evaluator(os.path.join(SOURCE, "settings", "r1_gait.xml"),
                       set={"Simulator.sample_to": 3, "Simulator.delayed_start": 0.5}) as ev:
        assert float(ev.evaluate([[0.5] * ev.dimension]).fitness[0]).hex() == got["fitness"]   # the same bits
    assert os.path.exists(os.path.join(os.path.dirname(got["file"]), "py.typed"))
    info = subprocess.run([str(venv / "bin" / "cic"), "eval", "--settings", "r1_gait.xml", "--info"], cwd=tmp_path,
                          env=env, capture_output=True, text=True)
    assert json.loads(info.stdout)["dimension"] == 37, info.stderr


def test_run_sh_installs_and_builds_the_package():
    # README's first command: the run set of install-deps.sh has what the package needs, and run.sh builds it.
    packages = subprocess.run(["bash", "-c", 'eval "$(sed -n "/^RUN_PACKAGES=(/,/^)/p" scripts/install-deps.sh)"; '
                               'echo "${RUN_PACKAGES[@]}"'], cwd=SOURCE, capture_output=True, text=True,
                              check=True).stdout.split()
    for p in ("pybind11-dev", "python3-dev", "python3-numpy", "python3-pandas"):
        assert p in packages, p
    with open(os.path.join(SOURCE, "scripts", "run.sh")) as f:
        setup_line = next(l for l in f if "cic_setup" in l and not l.startswith("#"))
    assert "cic_python" in setup_line.split(), setup_line
