# Shared by run.sh and test.sh (sourced; needs ROOT): dependencies, configure, build.
# cic_setup PRESET BUILD_DIR [TARGET...]: installs missing packages, configures
# BUILD_DIR with the CMake preset the first time, then builds (incrementally).
# CIC_DEPS=run (scripts/run.sh) installs and configures only what running
# needs: no tests, no benchmarks; the default (all) turns them on again.
cic_setup() {
  local preset="$1" build_dir="$2"
  shift 2
  local deps="${CIC_DEPS:-all}" extra=()
  bash "$ROOT/scripts/install-deps.sh" "$deps"
  if [ "$deps" = run ]; then
    extra=(-DCIC_BUILD_TESTS=OFF -DCIC_BUILD_BENCHMARKS=OFF)
  elif [ -f "$build_dir/CMakeCache.txt" ] && grep -q '^CIC_BUILD_TESTS:BOOL=OFF' "$build_dir/CMakeCache.txt"; then
    # Configured by run.sh (the release preset): the tests and benchmarks come back on.
    (cd "$ROOT" && cmake --preset "$preset" -DCIC_BUILD_TESTS=ON -DCIC_BUILD_BENCHMARKS=ON) >&2
  fi
  if [ ! -f "$build_dir/build.ninja" ]; then
    (cd "$ROOT" && cmake --preset "$preset" "${extra[@]}") >&2
  fi
  local targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$build_dir" -j "${CIC_JOBS:-$(nproc)}" "${targets[@]}" >&2
}
