#!/usr/bin/env bash
# Side-by-side of DEAP's symbolic-regression example and cic on the same
# Koza-1 settings (population 300, 40 generations, tournament 3, crossover 0.5,
# mutation 0.1, {add sub mul div neg sin cos}, constants -1 0 1, 20 points in
# [-1, 0.9]); see docs/symreg.md for what is and is not equivalent.
#
# Usage: scripts/compare-deap.sh [N=100] [START=1]
#   Runs DEAP over seeds START..START+N-1, then cic over the same seeds, one
#   after the other (never at the same time), and prints both success rates and
#   the time ratio DEAP / cic per run, by wall clock and by CPU time (CPU time is
#   the fairer figure on a loaded machine).
# Environment: CIC=path to the cic binary (default: build/cic, then build-*/cic)
#              DEAP_FITNESS=mse (DEAP's example, default) or sae (cic's fitness)
#              KEEP=1 keeps cic's run folders (printed at the end)
#              PER_PROCESS=1 starts one cic process per seed instead of --seeds
set -euo pipefail

N=${1:-100}
START=${2:-1}
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SETTINGS="$ROOT/settings/symreg_deap.xml"
DEAP_FITNESS=${DEAP_FITNESS:-mse}

if ! [[ "$N" =~ ^[1-9][0-9]*$ && "$START" =~ ^[0-9]+$ ]]; then
    echo "usage: $0 [N>=1] [START>=0]" >&2
    exit 2
fi
if [[ -z "${CIC:-}" ]]; then
    for c in "$ROOT/build/cic" "$ROOT"/build*/cic; do
        if [[ -x "$c" ]]; then CIC=$c; break; fi
    done
fi
if [[ -z "${CIC:-}" || ! -x "$CIC" ]]; then
    echo "compare-deap: no cic binary (build it, or set CIC=/path/to/cic)" >&2
    exit 2
fi
if ! /usr/bin/python3 -c 'import deap' 2>/dev/null; then
    echo "compare-deap: DEAP is missing (apt-get install python3-deap)" >&2
    exit 2
fi

calc() { awk "BEGIN { printf \"%.6f\", $1 }"; }

WORK=$(mktemp -d "${TMPDIR:-/tmp}/cic-compare-deap.XXXXXX")
if [[ "${KEEP:-0}" != 1 ]]; then trap 'rm -rf "$WORK"' EXIT; fi

echo "== DEAP ($DEAP_FITNESS), seeds $START..$((START + N - 1))"
deap_out=$(/usr/bin/python3 "$ROOT/scripts/deap_symbreg.py" --seeds "$N" --start "$START" --fitness "$DEAP_FITNESS")
echo "$deap_out" | grep -v '^RESULT'
result=$(echo "$deap_out" | grep '^RESULT')
field() { echo "$result" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
deap_success=$(field successes)
deap_wall=$(field seconds)
deap_cpu=$(field cpu_seconds)

echo "== cic ($CIC), seeds $START..$((START + N - 1))"
TIMEFORMAT='%R %U %S'
# Like DEAP's script (all seeds in one Python process), cic runs all seeds in one
# process with --seeds; every run still writes its own run folder. With
# PER_PROCESS=1 each seed is a separate cic process (start-up counted N times).
times="$WORK/time"
if [[ "${PER_PROCESS:-0}" == 1 ]]; then
    { time for ((seed = START; seed < START + N; seed++)); do
        "$CIC" --settings "$SETTINGS" --seed "$seed" --output "$WORK/runs" --quiet > "$WORK/log-$seed" 2>&1 ||
            { echo "compare-deap: cic failed on seed $seed:" >&2; cat "$WORK/log-$seed" >&2; exit 1; }
      done; } 2> "$times"
else
    if ! { time "$CIC" --settings "$SETTINGS" --seeds "$START-$((START + N - 1))" --output "$WORK/runs" --quiet \
        > "$WORK/log" 2>&1; } 2> "$times"; then
        echo "compare-deap: cic failed:" >&2
        cat "$WORK/log" >&2
        exit 1
    fi
fi
read -r cic_wall user sys < <(tail -n 1 "$times")
cic_cpu=$(calc "$user + $sys")
runs=$(find "$WORK/runs" -name summary.txt | wc -l)
if [[ "$runs" -ne "$N" ]]; then
    echo "compare-deap: expected $N summary.txt files from cic, found $runs (in $WORK/runs)" >&2
    exit 1
fi
cic_success=$(grep -l '(success)' "$WORK"/runs/*/summary.txt | wc -l)
printf 'cic: runs %d, successes %d (%.0f%%), total %.2f s wall (%.2f s CPU), per run %.3f s\n' \
    "$N" "$cic_success" "$(calc "100 * $cic_success / $N")" "$cic_wall" "$cic_cpu" "$(calc "$cic_wall / $N")"

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.1f", a / b; else printf "n/a" }'; }
echo "== summary over $N seeds"
printf 'success rate: DEAP %d/%d, cic %d/%d\n' "$deap_success" "$N" "$cic_success" "$N"
echo "time per run, DEAP / cic: $(ratio "$deap_wall" "$cic_wall")x by wall clock, $(ratio "$deap_cpu" "$cic_cpu")x by CPU time"
echo "(cic's figures include writing every run folder, with fsync; neither side counts its start-up N times)"
if [[ "${KEEP:-0}" == 1 ]]; then echo "cic run folders kept in $WORK"; fi
