#!/usr/bin/env bash
# scripts/bench-gp-tricks.sh [ROUNDS=30]
# Do the GP loop's two speed tricks pay? Builds benchmarks/cic_bench_symreg_run
# (whole runs at DEAP's symbreg settings) three times from a scratch copy of
# HEAD: as it is, and with each trick undone by a patch in benchmarks/variants/
#   bulk-release.patch  frees the bred-from generation at once, not one
#                       individual per breeding event (malloc's per-thread cache);
#   map-index.patch     looks parents up in a std::unordered_map, not ParentIndex.
# Then runs the three alternately ROUNDS times and prints, per variant, the
# median paired CPU-time ratio to HEAD with a Wilcoxon signed-rank p-value
# (scipy; ratios only without it). A ratio above 1 means the trick pays.
# Results are the same bytes in every variant: only memory handling differs.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ROUNDS=${1:-30}
[[ "$ROUNDS" =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [ROUNDS>=1]" >&2; exit 2; }
WORK=$(mktemp -d)
trap 'git -C "$ROOT" worktree remove --force "$WORK/src" >/dev/null 2>&1 || true; rm -rf "$WORK"' EXIT
git -C "$ROOT" worktree add --detach "$WORK/src" HEAD >/dev/null 2>&1
cmake -S "$WORK/src" -B "$WORK/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCIC_WITH_VIEWER=OFF -DCIC_BUILD_TESTS=OFF >/dev/null
build() {   # build NAME: the bench as the worktree stands, copied to $WORK/NAME
  cmake --build "$WORK/build" --target cic_bench_symreg_run >/dev/null
  cp "$WORK/build/benchmarks/cic_bench_symreg_run" "$WORK/$1"
}
build head
for v in bulk-release map-index; do
  git -C "$WORK/src" apply "$ROOT/benchmarks/variants/$v.patch"
  build "$v"
  git -C "$WORK/src" checkout -- src/gp/evolution.cpp
done
echo "== GP loop tricks: $ROUNDS alternating rounds of 40 DEAP-symbreg runs each, load $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 0; r < ROUNDS; r++)); do
  for v in head bulk-release map-index; do
    printf '%s ' "$v"
    "$WORK/$v" --benchmark_format=json 2>/dev/null |
      python3 -c 'import json, sys; print(json.load(sys.stdin)["benchmarks"][0]["cpu_time"])'
  done
done > "$WORK/times.txt"
PY=python3
/usr/bin/python3 -c 'import scipy' 2>/dev/null && PY=/usr/bin/python3
"$PY" - "$WORK/times.txt" <<'PY'
import collections, statistics, sys
t = collections.defaultdict(list)
for line in open(sys.argv[1]):
    v, ms = line.split()
    t[v].append(float(ms))
print(f"  HEAD: median {statistics.median(t['head']):.2f} ms CPU per run")
for v in ("bulk-release", "map-index"):
    ratios = [a / b for a, b in zip(t[v], t["head"])]
    q = statistics.quantiles(ratios, n=4)
    line = f"  without the trick ({v}): {statistics.median(ratios):.3f} x HEAD's time (IQR {q[0]:.3f}-{q[2]:.3f})"
    try:
        from scipy.stats import wilcoxon
        line += f", Wilcoxon p = {wilcoxon([a - b for a, b in zip(t[v], t['head'])]).pvalue:.2g}"
    except ImportError:
        pass
    print(line)
PY
