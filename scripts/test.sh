#!/usr/bin/env bash
# scripts/test.sh [ctest options...]
# Installs missing dependencies, builds Release into build/ when needed, then
# runs the whole test suite through CTest. With CIC_SANITIZE=1 it builds
# build-asan (AddressSanitizer + UndefinedBehaviorSanitizer) and tests there.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/setup.sh
source "$ROOT/scripts/setup.sh"

if [ "${CIC_SANITIZE:-0}" = "1" ]; then
  PRESET=asan BUILD="$ROOT/build-asan"
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
  export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$ROOT/tests/lsan.supp:print_suppressions=0}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
else
  PRESET=release BUILD="$ROOT/build"
fi
cic_setup "$PRESET" "$BUILD"
ctest --test-dir "$BUILD" --output-on-failure -j "${CIC_TEST_JOBS:-2}" "$@"
