#!/usr/bin/env bash
# Sweep figures (issue 11), measured within one run of this script:
#   the sweep's overhead per run: sweep wall time minus the runs' own evolution
#   time (stats.csv wall_seconds), over 12 one-generation runs, --jobs 1;
#   throughput of --jobs 2 with 1 worker each against --jobs 1 with 2 workers,
#   on a study of 8 short HyperGP runs (R1, 12 individuals, 3 generations, 6 s).
# Usage: scripts/bench-sweep.sh [BUILD_DIR]   (default: build). About a minute.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=${1:-$ROOT/build}
cic="$build/cic"
[[ -x $cic ]] || { echo "no $cic: build cic first" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

sweep() {   # NAME GENERATIONS POPULATION SECONDS REPEATS
  cat > "$tmp/$1.xml" <<XML
<sweep name="$1">
  <base>$ROOT/settings/r1_settings.xml</base>
  <output>$tmp/$1</output>
  <set>GP.generatedPopulationSize=$3</set>
  <set>Control.maximumIterations=$2</set>
  <set>Simulator.sample_to=$4</set>
  <grid><vary key="GP.tournament_size">2 3</vary></grid>
  <repeats count="$5" firstSeed="1"/>
</sweep>
XML
}
now() { date +%s.%N; }
evolution_seconds() {   # sum of the runs' own wall time, from index.csv
  python3 - "$1/index.csv" <<'PY'
import csv, sys
print(sum(float(r["wall_seconds"]) for r in csv.DictReader(open(sys.argv[1]))))
PY
}

sweep overhead 1 4 2.5 6
t0=$(now); "$cic" --quiet sweep "$tmp/overhead.xml" --jobs 1 --workers 1; t1=$(now)
runs=12
evo=$(evolution_seconds "$tmp/overhead")
python3 -c "w=$t1-$t0; e=$evo; print(f'  sweep overhead per run (12 runs, --jobs 1): {(w-e)/$runs:6.3f} s   goal < 0.5 s  ' + ('ok' if (w-e)/$runs < 0.5 else 'MISSED') + f'   (wall {w:.2f} s, evolution {e:.2f} s)')"

sweep jobs2 3 12 6 4
sweep jobs1 3 12 6 4
t0=$(now); "$cic" --quiet sweep "$tmp/jobs2.xml" --jobs 2 --workers 1; t1=$(now)
"$cic" --quiet sweep "$tmp/jobs1.xml" --jobs 1 --workers 2; t2=$(now)
python3 -c "a=$t1-$t0; b=$t2-$t1; print(f'  8 short HyperGP runs: --jobs 2 x 1 worker {a:6.2f} s, --jobs 1 x 2 workers {b:6.2f} s: throughput ratio {b/a:5.2f}x')"
echo "  load average: $(cut -d' ' -f1-3 /proc/loadavg)"
