#!/usr/bin/env bash
# scripts/baselines.sh [--jobs N] [--output DIR] [--summary-only] STAGE...
#
# The studies of docs/baselines.md (HyperGP against parameter-optimised gaits),
# resumable like every `cic sweep`: rerun after an interruption and only what is
# missing runs. Seeds are fixed in the sweep files (experiments/baselines/).
# Stages:
#   search    HyperGP configurations on R1 at 2,500 evaluations, tuning seeds
#             101..105 (search-a.xml, search-clock.xml, then search-b.xml)
#   compare   the comparison at 2,500 evaluations on R0, R1, R2 (4 legs) and R1
#             (6 legs): HyperGP at Table B.1 values, HyperGP's best configuration
#             and CMA-ES gaits (gait-2500.xml; gait-clamp-2500.xml, the earlier
#             run with clamped bounds), seeds 1..10, and the deterministic sine grid
#             (scripts/tune-sine.sh, once: results/sine-grid.csv is kept; delete
#             it to run the grid again); curves of best fitness against evaluations
#             and a screenshot strip of each robot's best gait from each method
#   long      15,000 evaluations on R1: HyperGP's best configuration and CMA-ES
#             gaits, seeds 1..10 (hypergp-best-15000.xml, gait-15000.xml)
#   gap       what would close the gap to CMA-ES: HyperGP's best with a bias
#             input, or with a faster clock, on R1 and R2, tuning seeds (gap.xml)
#   walk-tune issue 21's tuning stage, R1, 2,500 evaluations, tuning seeds
#             101..105: the evolved clock, HyperGP-CPG, HyperGP-gait
#             (walk-tune-hypergp.xml) and CMA-ES with IPOP restarts on the gait
#             and on the CPG (walk-tune-cmaes.xml); results/walk-tune.md
#   walk      issue 21's comparison at 2,500 evaluations, seeds 1..10, on R0,
#             R1, R2, R1 6 legs and the cross (walk-2500-*.xml); results/walk.md,
#             and results/walk-winners.md with the settings/r{0,1,2}_best*.xml it ships
#   walk-long the same at 15,000 evaluations, R1 and R2, for HyperGP's old best
#             and the tuning stage's three strongest (walk-15000-*.xml)
#   walk-ledger run nothing: assess the finished runs of every comparison study
#             under --output, keep them in results/walk-runs.csv and each
#             study's best run per robot in results/best/ (replayable), cheaply:
#             no plots, strips or winners. Run it, and commit results/, after
#             each run: run folders are never committed, and a sitting's may be
#             gone by the next one.
# Tables and plots go to experiments/baselines/results/.
#   --jobs N        runs at a time (default 2)
#   CIC_WALK_METHODS="hgp-cpg cmaes-gait"  walk stages: only these methods
#   --output DIR    study folders (default runs/baselines); the run store is shared
#                   with the chapter-7 studies (runs/thesis-ch7/store)
#   --summary-only  run nothing; summarise what is there
#   --config NAME   run only this configuration of each study (repeatable, e.g.
#                   --config R1 first: every method on one robot before the next)
# PYTHON names the interpreter for the report (default python3; the p-values
# need scipy, Debian's python3-scipy).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/lib/study-index.sh"
HERE="$ROOT/experiments/baselines"
if [ -z "${CIC:-}" ]; then
  if [ -x "$ROOT/build/cic" ]; then CIC="$ROOT/build/cic"; else CIC="$(command -v cic || true)"; fi
fi
[ -n "$CIC" ] && [ -x "$CIC" ] || { echo "baselines.sh: no cic found; build it (scripts/run.sh) or set CIC" >&2; exit 2; }

jobs=2 output=runs/baselines summary_only=0 stages=() only=()
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) jobs="$2"; shift 2 ;;
    --output) output="$2"; shift 2 ;;
    --summary-only) summary_only=1; shift ;;
    --config) only+=(--config "$2"); shift 2 ;;
    -h|--help) sed -n '2,/^set /p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'; exit 0 ;;
    search|compare|long|gap|walk-tune|walk|walk-long|walk-ledger) stages+=("$1"); shift ;;
    *) echo "baselines.sh: unknown option or stage '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ ${#stages[@]} -gt 0 ] || { echo "baselines.sh: name a stage: search, compare, long, gap, walk-tune, walk, walk-long, walk-ledger (see --help)" >&2; exit 2; }
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "baselines.sh: --jobs takes a positive number, got '$jobs'" >&2; exit 2; }

mkdir -p "$HERE/results"
summarise() {   # STUDY
  "$CIC" --quiet sweep "$HERE/$1.xml" --output "$output/$1" --index-only
  if ! grep -q ',done,' "$output/$1/index.csv"; then
    echo "== $1: no finished run yet, nothing to summarise" >&2
    return 0
  fi
  # The comparison's studies span sittings: their tables come from results/walk-runs.csv
  # (walk-report.py ledger), so each study's own summary of the runs at hand stays beside them.
  local dest="$HERE/results/$1"
  if [[ "$1" =~ ^walk-[0-9]+- ]]; then
    mkdir -p "$output/$1/summary"
    dest="$output/$1/summary/$1"
  fi
  # best_ever: CMA-ES keeps its best, HyperGP at Table B.1 values (no elitism) may lose it.
  "$CIC" compare "$output/$1" --metric best_ever --out "$dest" > /dev/null
  "$CIC" plot "$output/$1" --title "$1 (median, Q1..Q3)" --median --out "$dest.svg"
  # Walking or shaking (thesis 7.3.2.1): each finished run's best, replayed.
  mapfile -t done_runs < <(finished_runs "$output/$1")
  local inputs=() run
  for run in "${done_runs[@]}"; do inputs+=("$(best_ever_input "$run")"); done
  if [ ${#inputs[@]} -gt 0 ]; then
    "$CIC" --quiet assess "${inputs[@]}" --out "$dest-gaits.csv"
  fi
}
# What to replay for a run's best_ever: a HyperGP run without elitism may have
# lost it by its last generation, so the saved population of the first
# generation that reached it (RUN/populations/gen-NNNN.xml); a gait run keeps
# its best in the run folder's population file.
best_ever_input() {   # RUN
  local g
  g=$(awk -F, 'NR > 1 && (best == "" || $2 + 0 > best + 0) {best = $2; g = $1} END {print g}' "$1/stats.csv")
  local file
  file=$(printf '%s/populations/gen-%04d.xml' "$1" "$g")
  if [ -n "$g" ] && [ -f "$file" ]; then echo "$file"; else echo "$1"; fi
}
study() {   # STUDY
  if [ ! -f "$HERE/$1.xml" ]; then
    echo "== $1: no sweep file yet (experiments/baselines/$1.xml), skipped" >&2
    return 0
  fi
  echo "== $1" >&2
  [ "$summary_only" = 1 ] || "$CIC" sweep "$HERE/$1.xml" --output "$output/$1" --jobs "$jobs" "${only[@]}" >&2
  summarise "$1"
}
# A screenshot strip of each robot's best gait from each method (results/strip-METHOD-ROBOT.png):
# the run with the highest best_ever, replayed at the individual that reached it.
strips() {   # STUDY...
  local s r run
  for s in "$@"; do
    [ -f "$output/$s/index.csv" ] || continue
    for r in R0 R1 R2 R1-6legs cross; do
      run=$(best_finished_run "$output/$s" "$r")
      [ -n "$run" ] || continue
      CIC="$CIC" "$ROOT/scripts/screenshot-strip.sh" "$(best_ever_input "$output/$s/$run")" \
        "$HERE/results/strip-$s-$r.png" >&2
    done
  done
}
# The comparison's best run of each study and robot (walk-report.py best: the highest score in
# the ledger), kept replayable in results/best/STUDY/ROBOT: its settings.xml and the population
# file that holds its best individual, as population.xml (`cic view`, `assess`, `trace` and
# screenshot-strip.sh take the folder). Copied from the run folder while it is here; a best run
# whose folder is gone keeps what an earlier sitting kept. source.txt names the run and score.
keep_best() {
  local study config run_dir score dest kept src missing=0
  while IFS=, read -r study config run_dir score; do
    dest="$HERE/results/best/$study/$config"
    kept="$run_dir $score"
    [ -f "$dest/source.txt" ] && [ "$(cat "$dest/source.txt")" = "$kept" ] && continue
    # Only a finished run (index.csv says done): a folder may hold a run still going, or one
    # cut off, whose row in the ledger came from an earlier sitting.
    if ! run_is_finished "$output/$study" "$run_dir"; then
      # Kept from another run: it was the best once, and the best's own folder is gone.
      [ -f "$dest/source.txt" ] && echo "baselines.sh: results/best/$study/$config keeps" \
        "$(cat "$dest/source.txt"); the best run, $run_dir ($score), is not in $output" >&2
      missing=$((missing + 1))
      continue
    fi
    rm -rf "$dest.tmp" && mkdir -p "$dest.tmp"
    cp "$output/$study/$run_dir/settings.xml" "$dest.tmp/settings.xml"
    src=$(best_ever_input "$output/$study/$run_dir")
    [ -d "$src" ] && src="$src/population.xml"   # a gait run keeps its best in population.xml
    cp "$src" "$dest.tmp/population.xml"
    echo "$kept" > "$dest.tmp/source.txt"
    rm -rf "$dest" && mv "$dest.tmp" "$dest"
  done < <("${PYTHON:-python3}" "$ROOT/scripts/walk-report.py" --studies "$output" best)
  [ "$missing" = 0 ] || echo "baselines.sh: $missing best runs are neither here nor kept in results/best" \
    "(their sittings were before it was kept)" >&2
}
# The strip of each kept best (results/strip-STUDY-ROBOT.png), drawn again only when the kept
# run changed (results/best/STUDY/ROBOT/strip.txt: the source.txt it was drawn from).
walk_strips() {
  local dest study config
  for dest in "$HERE"/results/best/*/*; do
    [ -f "$dest/source.txt" ] || continue
    config=$(basename "$dest") study=$(basename "$(dirname "$dest")")
    cmp -s "$dest/source.txt" "$dest/strip.txt" && [ -f "$HERE/results/strip-$study-$config.png" ] && continue
    CIC="$CIC" "$ROOT/scripts/screenshot-strip.sh" "$dest" "$HERE/results/strip-$study-$config.png" >&2
    cp "$dest/source.txt" "$dest/strip.txt"
  done
}
sine_strips() {   # from results/sine-grid.csv: robot,fitness,controller
  local robot fitness controller legs
  while IFS=, read -r robot fitness controller; do
    [ "$robot" = robot ] && continue
    legs=""
    [ "$robot" = R1-6legs ] && legs="--middle-legs"
    CIC="$CIC" "$ROOT/scripts/screenshot-strip.sh" - "$HERE/results/strip-sine-grid-$robot.png" \
      --view "--robot ${robot%-6legs} $legs --controller $controller" >&2 < /dev/null   # stdin is the CSV
  done < "$HERE/results/sine-grid.csv"
}
# Best fitness so far against evaluations, per robot: every method of a budget that has runs.
curves() {   # [PREFIX] BUDGET ROBOT STUDY... (results/PREFIXcurves-BUDGET-ROBOT.svg)
  local prefix=""
  [[ "$1" =~ ^[0-9]+$ ]] || { prefix="$1"; shift; }
  local budget="$1" robot="$2" found=()
  shift 2
  for s in "$@"; do grep -qs ',done,' "$output/$s/index.csv" && found+=("$output/$s"); done
  [ ${#found[@]} -gt 0 ] || return 0
  "$CIC" --quiet plot --by-evaluations "${found[@]}" --config "$robot" --median \
    --title "$robot, $budget evaluations: best fitness so far" --out "$HERE/results/${prefix}curves-$budget-$robot.svg" ||
    echo "baselines.sh: no curves for $robot at $budget evaluations yet" >&2
}

for stage in "${stages[@]}"; do
  case "$stage" in
    search) study search-a; study search-clock; study search-b ;;
    compare)
      study hypergp-b1-2500
      study hypergp-best-2500
      study gait-2500
      study gait-clamp-2500
      for r in R0 R1 R2 R1-6legs cross; do curves 2500 "$r" hypergp-b1-2500 hypergp-best-2500 gait-2500 gait-clamp-2500; done
      strips hypergp-b1-2500 hypergp-best-2500 gait-2500 gait-clamp-2500
      # Deterministic: run once; delete results/sine-grid.csv to run it again.
      if [ "$summary_only" = 0 ] && [ ! -s "$HERE/results/sine-grid.csv" ]; then
        echo "== sine grid" >&2
        {
          echo "robot,fitness,controller"
          for r in R0 R1 R2; do
            CIC="$CIC" "$ROOT/scripts/tune-sine.sh" "$r" | head -1 | awk -v r="$r" '{print r "," $1 "," $2}'
          done
          CIC="$CIC" "$ROOT/scripts/tune-sine.sh" R1 --middle-legs | head -1 | awk '{print "R1-6legs," $1 "," $2}'
        } > "$HERE/results/sine-grid.csv"
      fi
      [ -f "$HERE/results/sine-grid.csv" ] && sine_strips
      ;;
    long)
      study hypergp-best-15000
      study gait-15000
      curves 15000 R1 hypergp-best-15000 gait-15000
      strips hypergp-best-15000 gait-15000
      ;;
    gap) study gap ;;
    walk-tune)
      study walk-tune-hypergp
      study walk-tune-cmaes
      "${PYTHON:-python3}" "$ROOT/scripts/walk-report.py" --studies "$output" tune > "$HERE/results/walk-tune.md"
      ;;
    walk|walk-long)
      budget=2500 robots="R0 R1 R2 R1-6legs cross"
      [ "$stage" = walk-long ] && budget=15000 robots="R1 R2"
      # At 15,000 the three strongest methods of the tuning stage and HyperGP's old best (the
      # evolved clock and CMA-ES's CPG were the two weakest): ~11 h instead of ~17 h on 2 cores.
      methods="hgp-best hgp-clock hgp-cpg hgp-gait cmaes-gait cmaes-cpg"
      [ "$stage" = walk-long ] && methods="hgp-best hgp-cpg hgp-gait cmaes-gait"
      # CIC_WALK_METHODS="m1 m2": only these (a sitting whose run folders are gone runs the
      # methods the ledger lacks first; the summary still reads every study's index).
      methods=${CIC_WALK_METHODS:-$methods}
      walk_studies=()
      for m in $methods; do
        study "walk-$budget-$m"
        walk_studies+=("walk-$budget-$m")
      done
      for r in $robots; do curves walk- "$budget" "$r" "${walk_studies[@]}"; done
      "${PYTHON:-python3}" "$ROOT/scripts/walk-report.py" --studies "$output" ledger
      keep_best
      walk_strips
      "${PYTHON:-python3}" "$ROOT/scripts/walk-report.py" --studies "$output" compare > "$HERE/results/walk.md"
      # The shipped settings/r{0,1,2}_best*.xml follow the winners (docs/baselines.md, "Shipped settings").
      "${PYTHON:-python3}" "$ROOT/scripts/walk-report.py" --studies "$output" winners > "$HERE/results/walk-winners.md"
      CIC="$CIC" "${PYTHON:-python3}" "$ROOT/scripts/ship-winners.py"
      ;;
    walk-ledger)
      # Only the studies that have a folder here: --index-only would make one for the others.
      for f in "$HERE"/walk-[0-9]*-*.xml; do
        s=$(basename "$f" .xml)
        [ -f "$output/$s/index.csv" ] && summarise "$s"
      done
      "${PYTHON:-python3}" "$ROOT/scripts/walk-report.py" --studies "$output" ledger
      keep_best
      ;;
  esac
done
# results/report.md covers the stages before issue 21 (walk* stages have their own tables): only
# those stages rewrite it, so a walk stage on a machine without their run folders leaves it be.
if printf '%s\n' "${stages[@]}" | grep -qvx 'walk-tune\|walk\|walk-long\|walk-ledger'; then
  "${PYTHON:-python3}" "$ROOT/scripts/baselines-report.py" --studies "$output" > "$HERE/results/report.md"
  echo "baselines.sh: tables and plots in $HERE/results (summary: results/report.md)" >&2
else
  echo "baselines.sh: tables and plots in $HERE/results (summary: results/walk-tune.md, results/walk.md)" >&2
fi
