#!/usr/bin/env bash
# scripts/docs-figures.sh [OUT_DIR]
# Makes the figures of docs/visualisation.md with the shipped commands, from a
# small study made for them, a short CMA-ES run with IPOP restarts and a short
# MAP-Elites run (a few minutes on two cores): each plot kind of `cic plot`
# (GP, gait, MAP-Elites with its heatmap, --path, --by-evaluations), a network
# trace, a still and a screenshot strip with the trail, and a screenshot of
# `cic report` rendered by headless Chromium (skipped without chromium).
# OUT_DIR defaults to docs/img; the runs go to a temporary folder, removed at the end.
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
"$CIC" --quiet view "$run" --screenshot "$OUT/still-trail.png" --at 8 --width 640 --height 420
"$CIC" plot --path "$WORK/study" --out "$OUT/plot-path.png" --title "cic plot --path STUDY: each configuration's best run" \
  --width 800

# A short CMA-ES run with IPOP restarts on R1 (restarts after 3 generations without progress),
# and a short MAP-Elites run of gait vectors on R1: their own panels, and the archive's heatmap.
"$CIC" --quiet --settings "$ROOT/settings/r1_gait_ipop.xml" --output "$WORK/gait" --set Gait.evaluations=400 \
  --set Gait.restartPatience=3 --set Simulator.sample_to=8
"$CIC" plot "$WORK"/gait/*-001 --out "$OUT/plot-gait.png" --title "cic plot GAIT_RUN: CMA-ES with IPOP restarts" \
  --width 1000 --height 420
"$CIC" --quiet --settings "$ROOT/settings/r1_gait_map_elites.xml" --output "$WORK/me" --set MapElites.evaluations=600 \
  --set Simulator.sample_to=8
"$CIC" plot "$WORK"/me/*-001 --out "$OUT/plot-map-elites.png" --title "cic plot MAP_ELITES_RUN" --width 1000 --height 720

# cic report on the study, and the top of the page as headless Chromium draws it.
"$CIC" --quiet report "$WORK/study" --out "$WORK/report.html"
if command -v chromium >/dev/null; then
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run --disable-background-networking \
    --user-data-dir="$WORK/chromium" --window-size=1100,1500 --screenshot="$OUT/report.png" \
    "file://$WORK/report.html" >/dev/null 2>&1
else
  echo "docs-figures.sh: chromium is missing; report.png not made" >&2
fi
echo "docs-figures.sh: figures in $OUT" >&2
