#!/usr/bin/env bash
# scripts/bench.sh [--quick] [--deap N] [--r1] [--tricks]
# Prints every speed figure the issues ask for, each measured within one run of this
# script (the machine is shared: compare ratios, not absolute numbers, across days):
#   GP node evaluations per second (Operon's protocol), 1 and 2 threads;
#   simulator real-time factor, cost over bare ODE, evaluations/s with 1 and 2 workers;
#   sweep overhead per run and --jobs 2 x 1 worker vs --jobs 1 x 2 workers;
#   per-evaluation breakdown (substrate build, network steps, physics);
#   MAP-Elites: the archive's cost per evaluation (variation, offer, checkpoint) against physics;
#   Python (cic.Evaluator) against cic's own run, and a batch of one's overhead;
#   one evaluation's cost against robot size, centipedes of 15-511 modules, per collision space
#     (median of 3 repetitions interleaved at random; 1 with --quick);
#   with --deap N: DEAP vs cic on DEAP's symbreg example over N seeds (default off);
#   with --r1: the default R1 run (50 x 50, seed 1, 2 workers): wall time and best fitness;
#   with --tricks: whether the GP loop's speed tricks pay (scripts/bench-gp-tricks.sh).
# Builds the benchmark programs into build/ first (Release).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/setup.sh
source "$ROOT/scripts/setup.sh"
deap=0 r1=0 tricks=0 min_time=0.5 scaling_reps=3
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) min_time=0.1 scaling_reps=1; shift ;;
    --deap) deap="$2"; shift 2 ;;
    --r1) r1=1; shift ;;
    --tricks) tricks=1; shift ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "bench.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
cic_setup release "$ROOT/build" cic cic_bench_tree_eval cic_bench_sim cic_bench_nn cic_bench_map_elites cic_bench_scaling
B="$ROOT/build/benchmarks"

echo "== machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%FT%TZ)"
echo
echo "== GP node evaluations per second (1000 random trees of 1-64 nodes, 12,800 rows x 10 variables)"
"$B/cic_bench_tree_eval" --benchmark_filter=BM_GPops --benchmark_min_time="$min_time" \
  --benchmark_format=json 2>/dev/null | python3 -c '
import json, sys
for b in json.load(sys.stdin)["benchmarks"]:
    name = b["name"].split("/")
    sets = "{+,-,*,/,sin,exp}" if "sinexp:1" in name else "{+,-,*,/}"
    threads = [n for n in name if n.startswith("threads:")][0].split(":")[1]
    gpops = b["GPops"] / 1e9
    print(f"  {sets:18} {threads} thread(s): {gpops:6.2f} GPops/s (x1e9)")
'
echo
echo "== Simulator"
bash "$ROOT/scripts/bench-sim.sh" "$ROOT/build"
echo
if [ -f "$ROOT/build/python/cic/__init__.py" ]; then   # the Python package (docs/python.md)
  /usr/bin/python3 "$ROOT/scripts/bench-python.py" "$ROOT/build"
  echo
fi
echo "== Studies (cic sweep)"
bash "$ROOT/scripts/bench-sweep.sh" "$ROOT/build"
echo
echo "== Per-evaluation breakdown, R1 6 legs, 15 s at 0.0125 s (1200 control steps)"
"$B/cic_bench_nn" --benchmark_min_time="$min_time" --benchmark_format=json 2>/dev/null | python3 -c '
import json, sys
runs = {b["name"]: b for b in json.load(sys.stdin)["benchmarks"]}
def ms(name): 
    b = runs[name]; unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0}[b["time_unit"]]
    return b["cpu_time"] * unit
sub, net, phys = ms("BM_SubstrateBuild/20"), ms("BM_NetworkEvaluation/20"), ms("BM_PhysicsEvaluationSine")
print(f"  substrate build:      {sub:8.3f} ms")
print(f"  network, 1200 steps:  {net:8.3f} ms")
print(f"  physics (sine gait):  {phys:8.3f} ms")
print(f"  substrate + network = {100*(sub+net)/phys:.1f}% of physics (goal < 10%)")
'
echo
echo "== MAP-Elites: the archive's cost per evaluation (625-cell duty-factor grid, batches of 50), CPU time"
"$B/cic_bench_map_elites" --benchmark_min_time="$min_time" --benchmark_format=json 2>/dev/null | python3 -c '
import json, sys
runs = {b["name"]: b for b in json.load(sys.stdin)["benchmarks"]}
def ms(name):
    b = runs[name]; unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0}[b["time_unit"]]
    return b["cpu_time"] * unit
gait, forest = ms("BM_ArchiveStepGait") / 50, ms("BM_ArchiveStepForest") / 50
cmame, replay = ms("BM_ArchiveStepCmaMe") / 50, ms("BM_CmaMeResumeReplay")
ckpt, phys = ms("BM_ArchiveCheckpoint") / 50, ms("BM_PhysicsEvaluationDutyFactors")
print(f"  vary + offer, gait vector (37):   {gait*1000:8.2f} us")
print(f"  vary + offer, 3-tree genotype:    {forest*1000:8.2f} us")
print(f"  ask + offer + tell, CMA-ME (37):  {cmame*1000:8.2f} us")
print(f"  checkpoint (602 elites) / 50:     {ckpt*1000:8.2f} us")
print(f"  physics, R1 15 s, duty factors:   {phys:8.2f} ms")
print(f"  archive = {100*(forest+ckpt)/phys:.2f}% of physics (HyperGP, checkpoint every batch)")
print(f"  archive = {100*(cmame+ckpt)/phys:.2f}% of physics (CMA-ME, checkpoint every batch)")
print(f"  CMA-ME resume, replay of a 300-generation start: {replay:8.1f} ms, once")
'
echo
echo "== Evaluation cost against robot size (centipedes, 15 s, Simulator.collisionSpace), CPU time,"
echo "   median of $scaling_reps repetitions interleaved at random (the load drifts; sizes timed minutes apart drift with it)"
"$B/cic_bench_scaling" --benchmark_repetitions="$scaling_reps" --benchmark_enable_random_interleaving=true \
  --benchmark_format=json 2>/dev/null | python3 -c '
import json, statistics, sys
from collections import defaultdict
runs = defaultdict(list)
for b in json.load(sys.stdin)["benchmarks"]:
    if b.get("error_occurred"):
        print("  failed:", b["name"], b.get("error_message")); continue
    if b.get("run_type", "iteration") != "iteration": continue
    _, p, space = b["name"].split("/")[:3]
    unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
    runs[(int(p), int(space))].append((b["cpu_time"] * unit, int(b["modules"])))
t = {k: (statistics.median(ms for ms, _ in v), v[0][1]) for k, v in runs.items()}
names = {0: "simple", 1: "sweep", 2: "sap"}
pairs = sorted({p for p, _ in t})
print("  " + "modules".rjust(7) + "".join((" " + names[s] + " ms").rjust(11) + " ms/module" for s in names))
for p in pairs:
    m = next(t[(p, s)][1] for s in names if (p, s) in t)
    print(f"  {m:7d} " + " ".join(f"{t[(p, s)][0]:10.1f} {t[(p, s)][0] / m:9.3f}" if (p, s) in t else " " * 20
                                 for s in names))
lo, hi = pairs[0], pairs[-1]
for s in names:
    if (lo, s) in t and (hi, s) in t:
        r = (t[(hi, s)][0] / t[(hi, s)][1]) / (t[(lo, s)][0] / t[(lo, s)][1])
        verdict = "ok" if r <= 1.25 else "MISSED"
        goal = "goal <= 1.25x " + verdict if s == 1 else "(1 = linear)"
        print(f"  {names[s]:6}: time per module at {t[(hi, s)][1]} modules / at {t[(lo, s)][1]} = {r:.2f}x  {goal}")
print("  (instructions, not time: scripts/profile-scaling.sh; docs/simulator.md, Collision space)")
'
if [ "$deap" != 0 ]; then
  echo
  echo "== DEAP vs cic, DEAP's symbreg example, $deap seeds"
  CIC="$ROOT/build/cic" bash "$ROOT/scripts/compare-deap.sh" "$deap"
fi
if [ "$r1" = 1 ]; then
  echo
  echo "== Default R1 run (settings/r1_settings.xml, seed 1, 2 workers)"
  out=$(mktemp -d)
  start=$(date +%s.%N)
  "$ROOT/build/cic" --settings "$ROOT/settings/r1_settings.xml" --set Experiment.workers=2 --output "$out" --quiet
  end=$(date +%s.%N)
  run=$(ls -d "$out"/*/)
  python3 - "$run/stats.csv" "$start" "$end" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print(f"  wall time: {float(sys.argv[3]) - float(sys.argv[2]):.1f} s for {len(rows)} generations")
print(f"  best fitness: generation 0 (random genotypes) {float(rows[0]['best']):.3f}, final {float(rows[-1]['best']):.3f}")
PY
  echo "  run folder: $run"
fi
if [ "$tricks" = 1 ]; then
  echo
  bash "$ROOT/scripts/bench-gp-tricks.sh"
fi
