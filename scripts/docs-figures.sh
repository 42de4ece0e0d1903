#!/usr/bin/env bash
# scripts/docs-figures.sh [OUT_DIR]
# Makes the figures of docs/visualisation.md with the shipped commands, from a
# small study made for them (a few minutes on two cores): each plot kind of
# `cic plot`, a network trace, and a screenshot strip. OUT_DIR defaults to
# docs/img; the runs go to a temporary folder, removed at the end.
# Environment: CIC=path to the cic binary (default: build/cic, then cic on PATH).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-$ROOT/docs/img}"
CIC=${CIC:-}
if [ -z "$CIC" ]; then
  if [ -x "$ROOT/build/cic" ]; then CIC="$ROOT/build/cic"; else CIC=$(command -v cic || true); fi
fi
[ -n "$CIC" ] && [ -x "$CIC" ] || { echo "docs-figures.sh: no cic binary (set CIC)" >&2; exit 2; }
mkdir -p "$OUT"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# A study: HyperGP's best configuration before issue 21, on R0, two tournament sizes, three
# seeds, 8 generations.
cat > "$WORK/figures.xml" <<XML
<sweep name="figures">
  <base>$ROOT/experiments/baselines/bases/hypergp-best.xml</base>
  <output>$WORK/study</output>
  <set>Simulator.robot_type=0</set>
  <set>Control.maximumIterations=8</set>
  <set>GP.generatedPopulationSize=20</set>
  <set>Simulator.sample_to=8</set>
  <grid><vary key="GP.tournament_size">2 5</vary></grid>
  <repeats count="3" firstSeed="1"/>
</sweep>
XML
"$CIC" --quiet sweep "$WORK/figures.xml" --jobs 2
run="$WORK/study/runs/tournament_size=5/s1"

"$CIC" plot "$WORK/study" --median --out "$OUT/plot-study.png" --title "cic plot STUDY --median: one colour per configuration" \
  --width 1000 --height 720
"$CIC" plot "$WORK/study/runs/tournament_size=5/s1" "$WORK/study/runs/tournament_size=5/s2" \
  --out "$OUT/plot-runs.png" --title "cic plot RUN...: best, mean, depth, size" --width 1000 --height 720
"$CIC" plot --by-evaluations "$WORK/study" --median --out "$OUT/plot-by-evaluations.png" \
  --title "cic plot --by-evaluations STUDY" --width 800 --height 500
"$CIC" trace "$run" --out "$WORK/trace.csv"
"$CIC" plot --trace "$WORK/trace.csv" --joints leg+x-y.0,leg+x-y.1 --out "$OUT/plot-trace.png" \
  --title "cic plot --trace" --width 800 --height 480
CIC="$CIC" "$ROOT/scripts/screenshot-strip.sh" "$run" "$OUT/strip.png" --at "1 3 5 7" --width 320 --height 240
echo "docs-figures.sh: figures in $OUT" >&2
