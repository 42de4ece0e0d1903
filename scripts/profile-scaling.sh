#!/usr/bin/env bash
# scripts/profile-scaling.sh [BUILD_DIR] [PAIRS...]
# Where one evaluation's cost goes as the centipede grows (issue 55), counted, not
# timed: callgrind runs benchmarks/bench_scaling.cpp once per size (sweep, 15 s) with
# a cache model of this machine's L1d (48 KiB) and L2 (1 MiB, as "LL"). Per module it
# prints instructions, L1d misses and L2 misses inside cic::sim::evaluate, and the
# share of QuickStep's row update (the hottest function in libode; a static function,
# so callgrind names it by address) in each. Counts repeat on a loaded machine where
# CPU time does not. Default sizes 2 32 64 pairs (15, 255, 511 modules); about 15
# minutes on 2 cores. Needs valgrind. Results: docs/simulator.md, "Collision space".
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=${1:-$ROOT/build}
shift || true
pairs=("$@")
[ ${#pairs[@]} -gt 0 ] || pairs=(2 32 64)
bench="$build/benchmarks/cic_bench_scaling"
[[ -x $bench ]] || { echo "no $bench: cmake --build $build --target cic_bench_scaling" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "profile-scaling.sh: needs valgrind" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for p in "${pairs[@]}"; do   # two at a time: the machine has 2 cores
  valgrind --tool=callgrind --cache-sim=yes --D1=49152,12,64 --LL=1048576,8,64 \
    --callgrind-out-file="$out/$p.out" "$bench" --benchmark_filter="BM_CentipedeEvaluation/$p/1/" \
    --benchmark_min_time=0.000001 >"$out/$p.log" 2>&1 &
  [ $(jobs -r | wc -l) -lt 2 ] || wait -n
done
wait
for p in "${pairs[@]}"; do
  echo "== $p"
  # awk reads to the end: no SIGPIPE for pipefail to trip on
  callgrind_annotate --inclusive=yes "$out/$p.out" | awk 'index($0, "cic::sim::evaluate(") && !n++'
  callgrind_annotate --inclusive=no "$out/$p.out" | awk 'index($0, "libode") && !n++'
done | python3 -c '
import re, sys
# Events in the order callgrind records them with --cache-sim=yes.
ev = ["Ir", "Dr", "Dw", "I1mr", "D1mr", "D1mw", "ILmr", "DLmr", "DLmw"]
def counts(line):   # the numbers before "file:function"; percentages dropped
    nums = []
    for tok in line.split():
        if ":" in tok: break
        if tok.startswith("(") or tok.endswith("%)"): continue
        nums.append(0 if tok == "." else int(tok.replace(",", "")))
    return dict(zip(ev, nums))
rows, p = {}, None
for line in sys.stdin:
    if line.startswith("== "): p = int(line[3:]); rows[p] = []; continue
    rows[p].append(counts(line))
print("  modules  Mi/module  L1d miss/module  L2 miss/module   row update: share of Ir, L1d misses, L2 misses")
first = last = None
for p, (e, top) in sorted(rows.items()):
    m = 8 * p - 1
    ir, l1, l2 = e["Ir"], e["D1mr"] + e["D1mw"], e["DLmr"] + e["DLmw"]
    tir, t1, t2 = top["Ir"], top["D1mr"] + top["D1mw"], top["DLmr"] + top["DLmw"]
    print(f"  {m:7d} {ir / m / 1e6:10.2f} {l1 / m:16.0f} {l2 / m:15.0f}   "
          f"{100 * tir / ir:5.1f} %  {100 * t1 / max(l1, 1):5.1f} %  {100 * t2 / max(l2, 1):5.1f} %")
    first = first or (m, ir / m, l1 / m, l2 / m)
    last = (m, ir / m, l1 / m, l2 / m)
print(f"  per module at {last[0]} / at {first[0]} modules: instructions {last[1] / first[1]:.2f}x, "
      f"L1d misses {last[2] / first[2]:.0f}x, L2 misses {last[3] / first[3]:.0f}x")
'
