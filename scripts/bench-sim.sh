#!/usr/bin/env bash
# Simulator benchmarks (benchmarks/bench_sim.cpp) and a summary against the goals.
# Usage: scripts/bench-sim.sh [BUILD_DIR]   (default: build). Takes about a minute.
set -euo pipefail
build=${1:-build}
bench="$build/benchmarks/cic_bench_sim"
[[ -x $bench ]] || { echo "no $bench: cmake --build $build --target cic_bench_sim" >&2; exit 2; }
json=$(mktemp)
trap 'rm -f "$json"' EXIT
"$bench" --benchmark_format=json --benchmark_out="$json" --benchmark_out_format=json >/dev/null
python3 - "$json" <<'PY'
import json, sys
import re
runs = {re.sub(r"/min_time:[0-9.]+", "", b["name"]): b for b in json.load(open(sys.argv[1]))["benchmarks"]}
def get(name, key): return runs[name][key]
thesis = get("BM_R1Sine/125/1", "realtime_x")
no_self = get("BM_R1Sine/125/0", "realtime_x")
fine = get("BM_R1Sine/50/1", "realtime_x")
bare = get("BM_BareOdeLoop", "realtime_x")
one = get("BM_WorkerPool/1/real_time", "evals_per_s")
two = get("BM_WorkerPool/2/real_time", "evals_per_s")
rss = max(get("BM_WorkerPool/1/real_time", "worker_maxrss_MB"), get("BM_WorkerPool/2/real_time", "worker_maxrss_MB"))
def verdict(ok): return "ok" if ok else "MISSED"
print("R1 6 legs, tripod sine gait, 15 s evaluations, one core, self-collision on unless said")
print(f"  real-time factor, dt 12.5 ms (thesis):   {thesis:7.1f}x   goal >= 300x  {verdict(thesis >= 300)}")
print(f"  the same, self-collision off:            {no_self:7.1f}x")
print(f"  cost of self-collision (on / off):       {no_self / thesis:7.3f}x  goal <= 1.15x {verdict(no_self / thesis <= 1.15)}")
print(f"  real-time factor, dt 5 ms (reference):   {fine:7.1f}x")
print(f"  bare ODE loop, dt 12.5 ms, same contacts:{bare:7.1f}x")
print(f"  simulator cost over bare ODE:            {bare / thesis:7.3f}x  goal <= 1.05x {verdict(bare / thesis <= 1.05)}")
print(f"  evaluations/s, 1 worker process:         {one:7.2f}")
print(f"  evaluations/s, 2 worker processes:       {two:7.2f}")
print(f"  speed-up 2 vs 1 workers:                 {two / one:7.2f}x  goal >= 1.8x  {verdict(two / one >= 1.8)}")
print(f"  peak memory per worker (ru_maxrss):      {rss:7.1f} MB")
with open("/proc/loadavg") as f:
    load = float(f.read().split()[0])
print(f"  load average during the run:             {load:7.2f}  (speed-up figures need an idle machine)")
PY
