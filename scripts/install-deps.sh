#!/usr/bin/env bash
# Installs every build, run and test dependency of cic with apt-get (Debian 12).
# Non-interactive and idempotent: does nothing when all packages are present.
# Runs as root, or through sudo when available.
set -euo pipefail

PACKAGES=(
  # build
  build-essential cmake ninja-build pkg-config dpkg-dev
  # libraries
  libode-dev libeigen3-dev libxml2-dev libcli11-dev libfmt-dev libpagmo-dev
  libopenscenegraph-dev libopenmpi-dev openmpi-bin
  # tests and benchmarks
  libgtest-dev libgmock-dev googletest libbenchmark-dev libxml2-utils valgrind python3-scipy
  # plots, POV-Ray scenes and videos, offscreen viewer screenshots
  gnuplot-nox povray ffmpeg xvfb xauth libgl1-mesa-dri libglx-mesa0 libegl-mesa0
  # fuzzing (scripts/fuzz.sh): clang's libFuzzer runtime and a symbolizer for reports
  clang libclang-rt-14-dev llvm
  # DEAP comparison (scripts/compare-deap.sh)
  python3 python3-deap
)

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
