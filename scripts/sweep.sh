#!/usr/bin/env bash
# scripts/sweep.sh -s SETTINGS [-s SETTINGS...] [-n SEEDS] [-o OUTPUT] [-- cic options...]
# Runs every settings file with seeds 1..SEEDS (default 10). Each configuration's runs
# land in OUTPUT/<settings stem>-NNN, so `cic plot OUTPUT/<stem>-*` gives mean curves and
# `cic plot OUTPUT/*` one curve per configuration. Options after -- go to every cic call
# (e.g. -- --set Control.maximumIterations=20). Runs one after the other; each run uses
# Experiment.workers processes.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CIC="${CIC:-$ROOT/build/cic}"
settings=() seeds=10 output=runs/sweep
while [ $# -gt 0 ]; do
  case "$1" in
    -s) settings+=("$2"); shift 2 ;;
    -n) seeds="$2"; shift 2 ;;
    -o) output="$2"; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "sweep.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ ${#settings[@]} -gt 0 ] || { echo "sweep.sh: give at least one -s SETTINGS" >&2; exit 2; }
[[ "$seeds" =~ ^[1-9][0-9]*$ ]] || { echo "sweep.sh: -n takes a positive number, got '$seeds'" >&2; exit 2; }
[ -x "$CIC" ] || { echo "sweep.sh: no $CIC; build first (scripts/run.sh builds it)" >&2; exit 2; }
for s in "${settings[@]}"; do
  name="$(basename "${s%.xml}")"
  for seed in $(seq 1 "$seeds"); do
    echo "== $name seed $seed" >&2
    "$CIC" --settings "$s" --seed "$seed" --output "$output" --set "Experiment.name=$name" --quiet "$@" > /dev/null
  done
done
echo "done: $output (plot with: $CIC plot $output/* --out $output/fitness.svg)" >&2
