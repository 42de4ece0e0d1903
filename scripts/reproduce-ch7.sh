#!/usr/bin/env bash
# scripts/reproduce-ch7.sh [--jobs N] [--slurm] [--output DIR] [--only NAME,...] [--no-long] [--summary-only]
#
# Re-runs the thesis's chapter-7 comparisons (experiments/thesis-ch7/*.xml, 10
# fixed seeds each) with `cic sweep`, then writes their tables and plots into
# experiments/thesis-ch7/results/. Resumable: run it again after an interruption
# and only what is missing runs; finished runs are skipped. Runs shared between
# comparisons (R1 at Table B.1 values is in all eight 50-generation ones) run once, in the study
# store DIR/store.
#   --jobs N        runs at a time (default 2; each gets cores/N worker processes)
#   --slurm         write each study's Slurm job-array script and submit it with
#                   sbatch, one after the other (afterany); rerun without --slurm
#                   (or with --summary-only) once they have finished, for the tables
#   --output DIR    study folders (default runs/thesis-ch7)
#   --only A,B      only these comparisons (file names without .xml)
#   --no-long       leave out the 300-generation runs (long-runs.xml)
#   --summary-only  run nothing; summarise what is there (unfinished runs left out)
# cic: $CIC, else build/cic of this checkout, else `cic` on PATH (an installed cic).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/lib/study-index.sh"
HERE="$ROOT/experiments/thesis-ch7"
if [ -z "${CIC:-}" ]; then
  if [ -x "$ROOT/build/cic" ]; then CIC="$ROOT/build/cic"; else CIC="$(command -v cic || true)"; fi
fi
[ -n "$CIC" ] && [ -x "$CIC" ] || { echo "reproduce-ch7.sh: no cic found; build it (scripts/run.sh) or set CIC" >&2; exit 2; }

jobs=2 slurm=0 output=runs/thesis-ch7 only="" long=1 summary_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) jobs="$2"; shift 2 ;;
    --slurm) slurm=1; shift ;;
    --output) output="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --no-long) long=0; shift ;;
    --summary-only) summary_only=1; shift ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "reproduce-ch7.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "reproduce-ch7.sh: --jobs takes a positive number, got '$jobs'" >&2; exit 2; }

# The order puts the shared baselines first, so that a study cut short has them.
studies=(topology forest legs sample-step averaging integrating penalty clock)
[ "$long" = 1 ] && studies+=(long-runs)
if [ -n "$only" ]; then
  IFS=, read -r -a wanted <<< "$only"
  for w in "${wanted[@]}"; do
    [ -f "$HERE/$w.xml" ] || { echo "reproduce-ch7.sh: --only $w: no $HERE/$w.xml" >&2; exit 2; }
  done
  studies=("${wanted[@]}")
fi

start=$(date +%s)
if [ "$summary_only" = 0 ]; then
  previous=""
  for s in "${studies[@]}"; do
    echo "== $s" >&2
    if [ "$slurm" = 1 ]; then
      "$CIC" sweep "$HERE/$s.xml" --output "$output/$s" --jobs "$jobs" --slurm >&2
      dep=(); [ -n "$previous" ] && dep=(--dependency="afterany:$previous")
      previous="$(sbatch --parsable "${dep[@]}" "$output/$s/slurm.sh")"
      echo "submitted $s as job $previous" >&2
    else
      "$CIC" sweep "$HERE/$s.xml" --output "$output/$s" --jobs "$jobs" >&2
    fi
  done
  if [ "$slurm" = 1 ]; then
    echo "submitted; when the jobs have ended: $0 --summary-only --output $output" >&2
    exit 0
  fi
fi

# Tables and plots, from the finished runs of each study. The index is rebuilt
# from the run folders first (a study's runs may have been done by another
# study sharing the store); that runs nothing.
mkdir -p "$HERE/results"
for s in "${studies[@]}"; do
  [ -f "$output/$s/index.csv" ] || { echo "reproduce-ch7.sh: $s has not run yet; skipped" >&2; continue; }
  "$CIC" --quiet sweep "$HERE/$s.xml" --output "$output/$s" --index-only
  "$CIC" compare "$output/$s" --out "$HERE/results/$s" > /dev/null
  "$CIC" plot "$output/$s" --title "$s (mean, +-1 sd)" --out "$HERE/results/$s.svg"
  # Is each finished run's best gait walking or shaking (thesis 7.3.2.1)?
  mapfile -t done_runs < <(finished_runs "$output/$s")
  if [ ${#done_runs[@]} -gt 0 ]; then
    "$CIC" --quiet assess "${done_runs[@]}" --out "$HERE/results/$s-gaits.csv"
  fi
done
echo "reproduce-ch7.sh: done in $(( $(date +%s) - start )) s; tables and plots in $HERE/results" >&2
