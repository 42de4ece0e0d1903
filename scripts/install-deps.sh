#!/usr/bin/env bash
# scripts/install-deps.sh [run|all]
# Installs cic's dependencies with apt-get (Debian 12): `run`, what building
# cic and its Python package and running experiments needs (scripts/run.sh); `all` (the default), also
# what the tests, benchmarks, videos, fuzzing and the DEAP comparison use
# (scripts/test.sh, CI). Non-interactive and idempotent: does nothing when all
# packages are present. Runs as root, or through sudo when available.
set -euo pipefail

profile="${1:-all}"
case "$profile" in
  run|all) ;;
  *) echo "install-deps.sh: unknown profile '$profile' (allowed: run, all)" >&2; exit 2 ;;
esac

RUN_PACKAGES=(
  # build (python3: every build checks the layers' include graph, scripts/check-layers.py;
  # a minimal Debian has none, found by timing README's commands on a fresh debootstrap)
  build-essential cmake ninja-build pkg-config dpkg-dev python3
  # libraries
  libode-dev libeigen3-dev libxml2-dev libcli11-dev libfmt-dev libpagmo-dev
  libopenscenegraph-dev libopenmpi-dev openmpi-bin
  # `cic eval`'s JSON lines (header-only)
  nlohmann-json3-dev
  # the plots a run draws (Control.useMatlabPlot)
  gnuplot-nox
  # the Python package (docs/python.md), built by run.sh for Debian's /usr/bin/python3
  pybind11-dev python3-dev python3-numpy python3-pandas
)
MORE_PACKAGES=(
  # tests and benchmarks (file: cpack's dependency scan for the .deb; groff: the man page test)
  libgtest-dev libgmock-dev googletest libbenchmark-dev libxml2-utils valgrind python3-scipy file groff-base
  # POV-Ray scenes and videos, offscreen viewer screenshots
  povray ffmpeg xvfb xauth libgl1-mesa-dri libglx-mesa0 libegl-mesa0
  # fuzzing (scripts/fuzz.sh): clang's libFuzzer runtime and a symbolizer for reports
  clang libclang-rt-14-dev llvm
  # DEAP comparison (scripts/compare-deap.sh)
  python3-deap
  # docs/analysis.md: a figure redrawn with matplotlib
  python3-matplotlib
  # the Python package's tests, `pip install .` into a venv (setup.py: Debian's setuptools
  # and wheel, no network), and the Octave example of the JSON-lines stream
  python3-pytest python3-pip python3-venv python3-setuptools python3-wheel octave
  # cic report's test: the page rendered in headless Chromium, which must fetch nothing;
  # libpng: the tests read the pixels of figures and screenshots (tests/support/png_image.hpp)
  chromium libpng-dev
)

PACKAGES=("${RUN_PACKAGES[@]}")
[ "$profile" = all ] && PACKAGES+=("${MORE_PACKAGES[@]}")

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1; then
  SUDO=(sudo)
else
  echo "install-deps.sh: missing packages: ${missing[*]}" >&2
  echo "install-deps.sh: run this script as root (sudo is not available)" >&2
  exit 1
fi

echo "install-deps.sh: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -q
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
