#!/usr/bin/env bash
# How the physics step changes a simulation (docs/simulator.md, "Step size").
# Usage: scripts/step-size.sh [BUILD_DIR] [RUN_DIR]
# Prints, for R1 with 4 legs under the sine gait of `cic simulate`, the fitness,
# how deep parts sink into the ground and the fastest body at each step; with
# RUN_DIR (a HyperGP run folder), also the fitness of its best individual
# replayed at each step. Coarse steps are allowed here (allowCoarseStep) so
# that their artefacts can be seen.
set -euo pipefail
build=${1:-build}
run=${2:-}
cic="$build/cic"
[[ -x $cic ]] || { echo "no $cic: build cic first" >&2; exit 2; }
# control step (s), extraTimeStepDivider
steps=("0.0125 20" "0.0125 5" "0.0125 1" "0.025 1" "0.5 20" "0.05 1" "0.1 1" "0.5 1")
printf '%-8s %-7s %-9s %-9s %-11s %-10s %s\n' control divider physics fitness sink_m fastest best_replayed
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in "${steps[@]}"; do
  read -r step div <<<"$s"
  out=$("$cic" simulate --robot R1 --set "Simulator.sample_step=$step" --set "Simulator.extraTimeStepDivider=$div" \
        --set Simulator.allowCoarseStep=1 --set Simulator.maxBodySpeed=1e9 2>&1 || true)
  fitness=$(awk '/^fitness/ {print $2}' <<<"$out")
  sink=$(awk '/^deepest ground contact/ {print $4}' <<<"$out")
  fastest=$(awk '/^deepest ground contact/ {print $8}' <<<"$out")
  replayed=-
  if [[ -n $run ]]; then
    rm -rf "$tmp/run" && cp -r "$run" "$tmp/run"
    sed -i -e "s|<sample_step>[^<]*</sample_step>|<sample_step>$step</sample_step>|" \
           -e "s|<extraTimeStepDivider>[^<]*</extraTimeStepDivider>|<extraTimeStepDivider>$div</extraTimeStepDivider>|" \
           -e "s|<allowCoarseStep>[^<]*</allowCoarseStep>|<allowCoarseStep>1</allowCoarseStep>|" \
           -e "s|<maxBodySpeed>[^<]*</maxBodySpeed>|<maxBodySpeed>1e9</maxBodySpeed>|" "$tmp/run/settings.xml"
    replayed=$("$cic" trace "$tmp/run" --out "$tmp/trace.csv" 2>&1 | sed -n 's/.*fitness \([^;]*\);.*/\1/p')
  fi
  printf '%-8s %-7s %-9s %-9s %-11s %-10s %s\n' "$step" "$div" "$(awk -v a="$step" -v b="$div" 'BEGIN {printf "%.5f", a / b}')" \
    "$fitness" "$sink" "$fastest" "$replayed"
done
