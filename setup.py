"""`pip install --no-build-isolation .`: cic's Python package, built by CMake (docs/python.md, "Install").

setuptools only packs what CMake builds and installs: the package (its module, stubs and
py.typed) from `cmake --install`, and beside it, as the wheel's data, the `cic` binary its
workers run and the shipped settings and robots, so that a venv (or ~/.local with --user)
gets the same layout as `cmake --install` gives a prefix: PREFIX/bin/cic,
PREFIX/share/cic/settings, PREFIX/lib/python3.X/site-packages/cic.

The CMake build folder is $CIC_BUILD_DIR, else the source tree's build/ (scripts/run.sh's):
an existing one is reused (built incrementally, its options kept), a missing one is
configured as run.sh does (Release, no tests). Debian's tools only, no network:
python3-setuptools, python3-wheel, pybind11-dev, cmake, ninja-build (scripts/install-deps.sh).
"""

import glob
import os
import re
import shutil
import subprocess
import sys

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

ROOT = os.path.dirname(os.path.abspath(__file__))


def cmake_version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(cic VERSION ([0-9.]+)", f.read()).group(1)


def cache_value(build, key):
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        for line in f:
            if line.startswith(key + ":"):
                return line.split("=", 1)[1].strip()
    return None


class BinaryDistribution(Distribution):
    """A compiled module inside: the wheel is tagged for this Python and platform."""

    def has_ext_modules(self):
        return True


class CMakeBuild(build_py):
    """Builds cic with CMake, then takes the package and the data files from `cmake --install`."""

    def run(self):
        build = os.path.abspath(os.environ.get("CIC_BUILD_DIR") or os.path.join(ROOT, "build"))
        python = os.path.realpath(sys.executable)   # a venv's python is a link to the interpreter it was made from
        if os.path.exists(os.path.join(build, "CMakeCache.txt")):
            built_for = cache_value(build, "Python_EXECUTABLE")
            if built_for and os.path.realpath(built_for) != python:
                sys.exit(f"setup.py: {build} builds cic's module for {built_for}, not {sys.executable}: "
                         f"set CIC_BUILD_DIR to another folder, or use that Python")
            if cache_value(build, "CIC_WITH_PYTHON") == "OFF":
                sys.exit(f"setup.py: {build} was configured with CIC_WITH_PYTHON=OFF")
        else:
            self.spawn(["cmake", "-S", ROOT, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                        "-DCIC_BUILD_TESTS=OFF", "-DCIC_BUILD_BENCHMARKS=OFF", "-DCIC_WITH_PYTHON=ON",
                        f"-DPython_EXECUTABLE={python}"])
        jobs = os.environ.get("CIC_JOBS") or str(os.cpu_count() or 1)
        # What `cmake --install` installs (the binary with every layer, the man page and examples, the
        # package), not the tests and benchmarks of a test build.
        self.spawn(["cmake", "--build", build, "-j", jobs, "--target", "cic", "cic_python", "cic_install_files"])
        stage = os.path.abspath(os.path.join(self.build_lib, "..", "cic-stage"))
        shutil.rmtree(stage, ignore_errors=True)
        subprocess.run(["cmake", "--install", build, "--prefix", stage], check=True, stdout=subprocess.DEVNULL)

        package = glob.glob(os.path.join(stage, "lib", "python3*", "dist-packages", "cic"))
        if len(package) != 1:
            sys.exit(f"setup.py: `cmake --install {build}` installed no Python package: is pybind11-dev, "
                     f"python3-dev and python3-numpy there? (CMake's summary says why it was left out)")
        target = os.path.join(self.build_lib, "cic")
        shutil.rmtree(target, ignore_errors=True)
        shutil.copytree(package[0], target, ignore=shutil.ignore_patterns("__pycache__"))

        # The data beside it: what the package's workers run and read (its _build.py finds
        # PREFIX/bin/cic four folders up), and the man page.
        data = {}
        for path in ["bin/cic", *glob.glob("share/cic/**/*", root_dir=stage, recursive=True),
                     "share/man/man1/cic.1"]:
            if os.path.isfile(os.path.join(stage, path)):
                data.setdefault(os.path.dirname(path), []).append(os.path.join(stage, path))
        self.distribution.data_files = sorted(data.items())


# setuptools' own folders (egg-info, build/lib...) inside the build folder, not in the source tree.
SETUPTOOLS_DIR = os.path.join(ROOT, "build", "setuptools")
os.makedirs(SETUPTOOLS_DIR, exist_ok=True)

setup(
    name="cic",
    version=cmake_version(),
    description="Evolve walking controllers for modular robots with HyperGP: cic's robots scored from Python",
    license="LGPL-3.0-or-later",
    python_requires=">=3.9",
    install_requires=["numpy", "pandas"],
    packages=["cic"],
    package_dir={"cic": "python/cic"},
    distclass=BinaryDistribution,
    cmdclass={"build_py": CMakeBuild},
    options={"build": {"build_base": SETUPTOOLS_DIR}, "egg_info": {"egg_base": SETUPTOOLS_DIR}},
    zip_safe=False,
)
