#!/usr/bin/env bash
# scripts/fuzz.sh TARGET SECONDS [BUILD_DIR]
# Coverage-guided fuzzing of the parsers with libFuzzer (docs/fuzzing.md).
#   TARGET     settings | population | sexpr | robot | sweep | index | archive | gait | all (each in turn, SECONDS each)
#   SECONDS    how long to fuzz one target
#   BUILD_DIR  default build-fuzz; configured once with clang, CIC_FUZZ=ON
#              (ASan + UBSan + coverage), no tests, benchmarks, viewer or MPI.
# The seed corpus fuzz/corpus/TARGET is copied into BUILD_DIR/corpus/TARGET,
# which grows across runs (fuzz/corpus itself is never written). Crashes, leaks,
# timeouts (> 1 s) and out-of-memory inputs go to BUILD_DIR/artifacts/TARGET/;
# the full log to BUILD_DIR/logs/TARGET.log. Exits non-zero when libFuzzer
# found anything. CIC_JOBS sets the build parallelism (default 1);
# CIC_FUZZ_ARGS adds libFuzzer options (e.g. "-jobs=2 -workers=2" or "-max_len=20000").
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ALL_TARGETS=(settings population sexpr robot sweep index archive gait)

usage() {
  echo "usage: scripts/fuzz.sh TARGET SECONDS [BUILD_DIR]   (TARGET: ${ALL_TARGETS[*]} | all)" >&2
  exit 2
}
[ $# -ge 2 ] && [ $# -le 3 ] || usage
TARGET="$1" SECONDS_EACH="$2"
BUILD="${3:-$ROOT/build-fuzz}"
case "$BUILD" in /*) ;; *) BUILD="$PWD/$BUILD" ;; esac
[[ "$SECONDS_EACH" =~ ^[0-9]+$ ]] && [ "$SECONDS_EACH" -gt 0 ] || usage
if [ "$TARGET" = all ]; then
  TARGETS=("${ALL_TARGETS[@]}")
else
  case " ${ALL_TARGETS[*]} " in *" $TARGET "*) TARGETS=("$TARGET") ;; *) usage ;; esac
fi

# --- toolchain ----------------------------------------------------------------
bash "$ROOT/scripts/install-deps.sh"   # a no-op when everything is there
for tool in clang clang++ cmake ninja; do
  command -v "$tool" >/dev/null 2>&1 || {
    echo "fuzz.sh: $tool not found; install clang, libclang-rt-14-dev, llvm, cmake and ninja-build" >&2
    exit 1
  }
done
if [ ! -f "$(clang++ -print-resource-dir)/lib/linux/libclang_rt.fuzzer-$(uname -m).a" ]; then
  echo "fuzz.sh: libFuzzer runtime missing (Debian: apt-get install libclang-rt-14-dev)" >&2
  exit 1
fi

# --- configure once, build the fuzz programs ----------------------------------
# Under a lock, so that two fuzz.sh started together (two targets on two cores)
# do not run two builds in one folder.
mkdir -p "$BUILD"
exec 9>"$BUILD/.fuzz-build.lock"
flock 9
if [ ! -f "$BUILD/build.ninja" ]; then
  CC=clang CXX=clang++ cmake -S "$ROOT" -B "$BUILD" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCIC_FUZZ=ON -DCIC_BUILD_TESTS=OFF -DCIC_BUILD_BENCHMARKS=OFF \
    -DCIC_WITH_VIEWER=OFF -DCIC_WITH_MPI=OFF >&2
fi
programs=()
for t in "${TARGETS[@]}"; do programs+=("fuzz_$t"); done
cmake --build "$BUILD" -j "${CIC_JOBS:-1}" --target "${programs[@]}" >&2
flock -u 9
exec 9>&-

# --- run ------------------------------------------------------------------------
SYMBOLIZER="$(command -v llvm-symbolizer || true)"
[ -n "$SYMBOLIZER" ] || SYMBOLIZER="$(ls /usr/lib/llvm-*/bin/llvm-symbolizer 2>/dev/null | tail -n 1 || true)"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}${SYMBOLIZER:+:external_symbolizer_path=$SYMBOLIZER}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

status=0
summary=()
for t in "${TARGETS[@]}"; do
  corpus="$BUILD/corpus/$t" artifacts="$BUILD/artifacts/$t" log="$BUILD/logs/$t.log"
  mkdir -p "$corpus" "$artifacts" "$BUILD/logs"
  cp -n "$ROOT/fuzz/corpus/$t/"* "$corpus/"   # seeds; the working corpus keeps what it found before
  dict=()
  [ -f "$ROOT/fuzz/$t.dict" ] && dict=(-dict="$ROOT/fuzz/$t.dict")
  found_before=$(find "$artifacts" -type f | wc -l)
  echo "fuzz.sh: $t for ${SECONDS_EACH}s (corpus $corpus, log $log)" >&2
  rc=0
  # shellcheck disable=SC2086  # CIC_FUZZ_ARGS is a list of options
  "$BUILD/fuzz/fuzz_$t" -max_total_time="$SECONDS_EACH" -timeout=1 -rss_limit_mb=2048 -detect_leaks=1 \
    -artifact_prefix="$artifacts/" -print_final_stats=1 "${dict[@]}" ${CIC_FUZZ_ARGS:-} "$corpus" \
    >"$log" 2>&1 || rc=$?
  found=$(( $(find "$artifacts" -type f | wc -l) - found_before ))
  # The final stats line: "#N DONE cov: C ft: F corp: U/Sb ... exec/s: E rss: R"
  stats="$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE|INITED)' "$log" | tail -n 1 || true)"
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)"
  speed="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)"
  if [ "$rc" -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    echo "fuzz.sh: $t FOUND SOMETHING (exit $rc, $found new artifact(s) in $artifacts):" >&2
    grep -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|fuzz_[a-z]+: |Test unit written' "$log" \
      | head -n 20 >&2 || true
  fi
  # Any input over 1 s is a timeout above; for the record, the slowest input of
  # the working corpus when replayed one by one ("Executed FILE in N ms"). Each
  # batch starts with a seed from fuzz/corpus as a warm-up, left out of the figure.
  warm="$(find "$ROOT/fuzz/corpus/$t" -type f | sort | head -n 1)"
  slowest="$(find "$corpus" -type f -print0 \
    | xargs -0 -r -n 500 "$BUILD/fuzz/fuzz_$t" -runs=1 "$warm" 2>&1 \
    | grep -vF "Executed $warm in" \
    | sed -n 's/^Executed \(.*\) in \([0-9]*\) ms$/\2/p' | sort -n | tail -n 1 || true)"
  line="$t: ${stats:-no stats line (see $log)} | execs ${execs:-?} | exec/s ${speed:-?} | slowest corpus input ${slowest:-?} ms | $( [ "$rc" -eq 0 ] && [ "$found" -eq 0 ] && echo ok || echo FOUND)"
  echo "$line"
  summary+=("$line")
done
if [ ${#TARGETS[@]} -gt 1 ]; then
  echo "fuzz.sh: summary"
  printf '  %s\n' "${summary[@]}"
fi
exit "$status"
