#!/usr/bin/env bash
# scripts/bench-slurm-overhead.sh [CIC] [TASKS]
# The per-task overhead of running a study through Slurm instead of `cic sweep
# --jobs`: the same study of TASKS tiny HyperGP runs (R0, 3 generations), once
# locally 2 at a time and once as a job array on the local cluster
# (scripts/slurm-local.sh start [--nodes N]) at most 2 at a time, both with 1
# worker per run; prints both wall times and (slurm - local) / TASKS * 2, the
# extra seconds each task costs a 2-slot cluster. Figures: docs/cluster.md.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CIC=$(realpath "${1:-$ROOT/build/cic}")
TASKS=${2:-12}
[ $((TASKS % 2)) -eq 0 ] || { echo "TASKS must be even" >&2; exit 2; }
sinfo -h >/dev/null 2>&1 || { echo "no Slurm answers: start one with scripts/slurm-local.sh start" >&2; exit 1; }
WORK=$(mktemp -d /tmp/cic-slurm-overhead.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
sweep() {   # NAME
  cat <<XML
<sweep name="$1">
  <base>$ROOT/settings/r0_settings.xml</base>
  <output>$WORK/$1</output>
  <set>GP.generatedPopulationSize=8</set>
  <set>GP.tournament_size=3</set>
  <set>Control.maximumIterations=3</set>
  <set>Simulator.sample_to=4</set>
  <set>Simulator.delayed_start=0.5</set>
  <grid><vary key="GP.elitism">0 1</vary></grid>
  <repeats count="$((TASKS / 2))"/>
</sweep>
XML
}
sweep local >"$WORK/local.xml"
sweep slurm >"$WORK/slurm.xml"
t0=$(date +%s.%N)
"$CIC" --quiet sweep "$WORK/local.xml" --jobs 2 --workers 1 >/dev/null
t1=$(date +%s.%N)
"$CIC" --quiet sweep "$WORK/slurm.xml" --slurm --jobs 2 --workers 1 >/dev/null
sbatch --wait "$WORK/slurm/slurm.sh" >/dev/null
t2=$(date +%s.%N)
awk -v a="$t0" -v b="$t1" -v c="$t2" -v n="$TASKS" -v nodes="$(sinfo -h -N -o %N | sort -u | wc -l)" 'BEGIN {
  printf "tasks %d, 2 at a time, %d node(s)\nlocal --jobs 2: %.1f s\nslurm array %%2: %.1f s\noverhead per task: %.2f s\n",
         n, nodes, b - a, c - b, (c - b - (b - a)) / n * 2 }'
cmp -s <(cd "$WORK/local/runs" && find . -name population.xml -exec md5sum {} + | sort) \
       <(cd "$WORK/slurm/runs" && find . -name population.xml -exec md5sum {} + | sort) &&
  echo "populations: identical" || { echo "populations differ" >&2; exit 1; }
