# Shared by run.sh and test.sh (sourced; needs ROOT): dependencies, configure, build.
# cic_setup PRESET BUILD_DIR [TARGET...]: installs missing packages, configures
# BUILD_DIR with the CMake preset the first time, then builds (incrementally).
cic_setup() {
  local preset="$1" build_dir="$2"
  shift 2
  bash "$ROOT/scripts/install-deps.sh"
  if [ ! -f "$build_dir/build.ninja" ]; then
    (cd "$ROOT" && cmake --preset "$preset") >&2
  fi
  local targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$build_dir" -j "${CIC_JOBS:-$(nproc)}" "${targets[@]}" >&2
}
