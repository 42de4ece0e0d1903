#!/usr/bin/env bash
# scripts/quality-diversity.sh [--jobs N] [--output DIR] [--baselines DIR] [--summary-only]
# Issue 26's study (docs/quality-diversity.md): MAP-Elites with HyperGP-gait
# genotypes and with the gait vector (Gaussian and CMA-ME emitters) on R1 and R2
# (4 legs, 625 duty-factor cells), 15,000 evaluations, seeds 1..10
# (experiments/quality-diversity/*.xml),
# then the summary: results/qd-runs.csv (the ledger, merged across sittings;
# results/qd-curve-points.csv keeps each run's curve),
# results/qd.md (the tables), an archive heatmap of each method's best R1 run and
# a screenshot strip of four elites of it from distant cells.
# Resumable: rerun the same command after an interruption; finished runs are
# kept. The plain references are issue 21's 15,000-evaluation cells
# (scripts/baselines.sh walk-long, experiments/baselines/results/walk-runs.csv);
# where their run folders are at hand (--baselines, default runs/baselines, the
# output of baselines.sh) each one's best gait is replayed to find its cell in
# the archives (results/qd-refs.csv, results/qd-cellmatch.csv).
# Environment: CIC (default build/cic), PYTHON (default python3; needs scipy).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/lib/study-index.sh"
HERE="$ROOT/experiments/quality-diversity"
CIC=${CIC:-$ROOT/build/cic}
PY=${PYTHON:-python3}
jobs=1 output=runs/quality-diversity baselines=runs/baselines summary_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) jobs="$2"; shift 2 ;;
    --output) output="$2"; shift 2 ;;
    --baselines) baselines="$2"; shift 2 ;;
    --summary-only) summary_only=1; shift ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    *) echo "quality-diversity.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "quality-diversity.sh: --jobs takes a positive number, got '$jobs'" >&2; exit 2; }
[ -x "$CIC" ] || { echo "quality-diversity.sh: no cic binary at $CIC (build first, or set CIC)" >&2; exit 2; }
studies=(me-gait-15000 me-hgp-15000 me-cmame-15000)
if [ "$summary_only" = 0 ]; then
  for s in "${studies[@]}"; do
    "$CIC" sweep "$HERE/$s.xml" --output "$output/$s" --jobs "$jobs"
  done
fi
mkdir -p "$HERE/results"
report() { "$PY" "$ROOT/scripts/qd-report.py" --studies "$output" --baselines "$baselines" --results "$HERE/results" --cic "$CIC" "$@"; }
report ledger
report compare > "$HERE/results/qd.md"
report curves
# The best R1 run of each method (by the ledger, every sitting's runs): its archive, and four
# elites from distant cells. Drawn while its folder is here, and again only when the best run
# changed (strip-STUDY-R1.txt names the run drawn); a best run whose folder is gone keeps what
# an earlier sitting drew.
for s in "${studies[@]}"; do
  best=$("$PY" - "$HERE/results/qd-runs.csv" "$s" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["study"] == sys.argv[2] and r["config"] == "R1" and r["best"]]
print(max(rows, key=lambda r: float(r["best"]))["run_dir"] if rows else "")
PY
)
  [ -n "$best" ] || continue
  if grep -qs "^$s R1 $(basename "$best"):" "$HERE/results/strip-$s-R1.txt"; then continue; fi
  # Only a finished run (index.csv says done): a folder may hold the same run still going.
  if ! run_is_finished "$output/$s" "$best"; then
    echo "quality-diversity.sh: $s's best R1 run ($best) is not finished in $output; its archive and strip stay as drawn" >&2
    continue
  fi
  run="$output/$s/$best"
  "$CIC" plot "$run" --archive --out "$HERE/results/archive-$s-R1.svg" --title "$s, R1, $(basename "$best"): best fitness per cell (feet 1 and 2; feet 3 and 4 collapsed)"
  strips=()
  while IFS=$'\t' read -r cell fitness descriptor; do
    img="$HERE/results/.strip-$s-${cell//,/-}.png"
    CIC="$CIC" bash "$ROOT/scripts/screenshot-strip.sh" "$run" "$img" --at "4 8 12" --width 280 --height 210 --view "--cell $cell" >/dev/null </dev/null
    strips+=("$img")
    echo "$s R1 $(basename "$best"): cell $cell, fitness $fitness, duty factors $descriptor" >> "$HERE/results/strip-$s-R1.txt.new"
  done < <(report cells "$run")
  mv "$HERE/results/strip-$s-R1.txt.new" "$HERE/results/strip-$s-R1.txt"
  inputs=() ; for i in "${strips[@]}"; do inputs+=(-i "$i"); done
  ffmpeg -loglevel error -y "${inputs[@]}" -filter_complex "vstack=inputs=${#strips[@]}" "$HERE/results/strip-$s-R1.png"
  rm -f "${strips[@]}"
done
echo "quality-diversity.sh: wrote $HERE/results/qd.md" >&2
