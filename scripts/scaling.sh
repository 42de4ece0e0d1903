#!/usr/bin/env bash
# scripts/scaling.sh [--jobs N] [--output DIR] [--commit] [--summary-only] [--dry-run] STAGE...
# Issue 38's scaling study (docs/scaling.md): tuning, then the comparison.
# Resumable like every `cic sweep`: rerun the same command after an
# interruption and only what is missing runs. Seeds are fixed in the sweep
# files (experiments/scaling/). Stages:
#   tune-direct  IPOP-CMA-ES and separable CMA-ES (sigma0 0.15 or 0.3), tuning
#                seeds 101..105: R1 at 15,000 evaluations (tune-direct-r1.xml)
#                and the 48-hinge centipede at 2,500 (tune-direct-c8.xml);
#                results/tune-direct.md names each robot's direct baseline
#   tune-hybrid  Offset-HybrID (offsetSigma 0.1 or 0.3) and Switch-HybrID (share
#                0.3 or 0.5), tuning seeds 101..105, on the same two robots and
#                budgets (tune-hybrid-c8.xml, tune-hybrid-r1.xml); the summary
#                names each hybrid's configuration per robot
#   compare      the comparison, seeds 1..10 on every robot: every
#                experiments/scaling/compare-*.xml, smallest robot first, R1 and
#                R2 last; write them first with `scaling-report.py compare-sweeps`
#                (refused while one is provisional)
#   posture-runs rerun the finished compare runs the posture page needs (the
#                best direct method's and Offset-HybrID's) whose folders are gone
#                and whose replays are not cached in results/compare-posture.csv,
#                so that `report` can write every robot's rows again; each must
#                end on the best_ever the ledger scores it by, else the stage
#                stops (exit 1) before the ledger is written
#   ledger       run nothing: merge the studies' index.csv (tuning and compare)
#                into results/scaling-runs.csv and write results/tune-direct.md
#   report       run nothing: the comparison's pages from the ledger and the
#                runs in --output (scaling-report.py results, anytime, posture
#                and strips: results/compare.md, anytime.md, posture.md,
#                strips.md and docs/img/scaling-*); Debian's python3 (scipy,
#                numpy, matplotlib) unless PYTHON says otherwise, and the strips
#                need the viewer build; every page is tried, a failed one named;
#                when all are written, docs/scaling.md's quoted tables follow
#                them (scripts/docs-blocks.py)
#   status       run nothing: what is left of the comparison, from its sweeps
#                and the committed ledger (safe beside a running study): per
#                study the runs done and to go, core-hours left at the measured
#                seconds per evaluation, wall time at --jobs (scaling-report.py status;
#                with a cic, done rows count only under the sweeps' run keys, and
#                the runs posture-runs would rerun in --output are counted too)
#   estimate     run nothing but timing: CPU seconds per evaluation of every
#                robot of the study (cic simulate), and results/estimate.md, the whole
#                study's run time with comparison seeds cut on the middle sizes
# Options:
#   --jobs N        runs at a time (default 1), each with one worker process
#   --output DIR    study folders (default runs/scaling); the run store is DIR/store
#   --commit        after every run, `git commit` the ledger and summary
#                   (experiments/scaling/results/ only)
#   --summary-only  run nothing; ledger and summary of what is there
#   --dry-run       run and write nothing: list the runs each stage would start,
#                   one "STUDY TASK RUN_DIR" line each (after the ledger's skips)
#   --only ROBOT    run only the tuning studies of one robot: c8 or r1 (the
#                   ledger still covers every study; compare ignores it)
# The studies' runs share one pool of --jobs slots, each slot taking the next
# run when its own ends; the ledger and summary are written after every run.
# A run the committed ledger records as done is not run again, even when its
# folder is gone (run folders are never committed: a study carried on from a
# clean clone on another machine runs only what the ledger lacks), but only if
# the ledger's run key is the one the sweep now gives that run (`cic sweep
# --dry-run --csv`'s run_key): a row of a run of other settings (an edited sweep or base
# file, a changed robot file) or without a key proves nothing, and the run runs.
# Environment: CIC (default build/cic), PYTHON (default python3).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HERE="$ROOT/experiments/scaling"
CIC=${CIC:-$ROOT/build/cic}
PY=${PYTHON:-python3}
jobs=1 output=runs/scaling commit=0 summary_only=0 dry_run=0 only='' stages=()
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) jobs="$2"; shift 2 ;;
    --output) output="$2"; shift 2 ;;
    --commit) commit=1; shift ;;
    --summary-only) summary_only=1; shift ;;
    --dry-run) dry_run=1; shift ;;
    --only) only="$2"; shift 2
            [[ "$only" =~ ^(c8|r1)$ ]] || { echo "scaling.sh: --only takes c8 or r1, got '$only'" >&2; exit 2; } ;;
    -h|--help) sed -n '2,/^set /p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'; exit 0 ;;
    tune-direct|tune-hybrid|compare|posture-runs|ledger|report|status|estimate) stages+=("$1"); shift ;;
    *) echo "scaling.sh: unknown option or stage '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ ${#stages[@]} -gt 0 ] || { echo "scaling.sh: name a stage: tune-direct, tune-hybrid, compare, posture-runs, ledger, report, status, estimate (see --help)" >&2; exit 2; }
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "scaling.sh: --jobs takes a positive number, got '$jobs'" >&2; exit 2; }
# The pool of runs waits for whichever run ends first: `wait -n -p`, bash 5.1 on
# (only the stages that run something need it).
if [ "$summary_only$dry_run" = 00 ] && [[ " ${stages[*]} " =~ \ (tune-direct|tune-hybrid|compare|posture-runs)\  ]] &&
   ! (( BASH_VERSINFO[0] > 5 || (BASH_VERSINFO[0] == 5 && BASH_VERSINFO[1] >= 1) )); then
  echo "scaling.sh: running a study needs bash 5.1 or later (wait -n -p); this is bash $BASH_VERSION" >&2; exit 2
fi
if [ "${stages[*]}" != status ]; then   # status reads files only
  [ -x "$CIC" ] || { echo "scaling.sh: no cic binary at $CIC (build first, or set CIC)" >&2; exit 2; }
fi
if [ "$dry_run" = 1 ]; then
  for stage in "${stages[@]}"; do
    [[ "$stage" =~ ^(tune-direct|tune-hybrid|compare|posture-runs)$ ]] ||
      { echo "scaling.sh: --dry-run lists the runs of tune-direct, tune-hybrid, compare and posture-runs; '$stage' runs none" >&2; exit 2; }
  done
  [ "$summary_only" = 0 ] || { echo "scaling.sh: --dry-run and --summary-only: choose one" >&2; exit 2; }
  [ "$commit" = 0 ] || { echo "scaling.sh: --dry-run writes nothing, so nothing to --commit" >&2; exit 2; }
fi
[ "$dry_run" = 1 ] || mkdir -p "$HERE/results"

tune_studies=(tune-direct-c8 tune-direct-r1)   # the centipede first: the new question
hybrid_studies=(tune-hybrid-c8 tune-hybrid-r1)
# The comparison's sweeps (scaling-report.py compare-sweeps), smallest robot first.
compare_studies=()
for r in centipede-2 centipede-2-irregular centipede-4 centipede-4-irregular centipede-8 centipede-8-irregular \
         centipede-16 centipede-16-irregular r1 r2; do
  if [ -f "$HERE/compare-$r.xml" ]; then compare_studies+=("compare-$r"); fi
done
all_studies=("${tune_studies[@]}" "${hybrid_studies[@]}" "${compare_studies[@]}")

ledger() {   # merge every study's index.csv, then the summary
  local s
  for s in "${all_studies[@]}"; do
    if [ -d "$output/$s" ]; then "$CIC" --quiet sweep "$HERE/$s.xml" --output "$output/$s" --index-only; fi
  done
  "$PY" "$ROOT/scripts/scaling-report.py" ledger --studies "$output" --results "$HERE/results" "${all_studies[@]}" >/dev/null
  "$PY" "$ROOT/scripts/scaling-report.py" summary --results "$HERE/results"
}

# A failed commit (another git command holding the index lock) is retried, and
# never stops the study: the next run's commit takes its rows along.
commit_results() {   # MESSAGE
  [ "$commit" = 1 ] || return 0
  local try
  for try in 1 2 3; do
    if git -C "$ROOT" add "$HERE/results" &&
       { git -C "$ROOT" diff --cached --quiet -- "$HERE/results" ||
         git -C "$ROOT" commit --quiet -m "$1" -- "$HERE/results"; }; then
      return 0
    fi
    sleep 5
  done
  echo "scaling.sh: could not commit the ledger (the next run's commit will carry it)" >&2
}

# "TASK STATUS RUN_DIR RUN_KEY BEST_EVER" of every run of STUDY's sweep, read from
# `cic sweep --dry-run --csv` by the one reader of it (scaling_status.sweep_runs).
runs_of() {   # STUDY
  "$PY" "$ROOT/scripts/scaling-report.py" runs --sweep "$HERE/$1.xml" --output "$output/$1" --cic "$CIC"
}

# The studies' pending tasks (`cic sweep --task`, each resumable) run in one
# pool of --jobs slots across the studies, in order: a slot takes the next task
# as soon as its run ends (a study's runs differ in length by method, and
# lockstep batches left a core idle); the ledger is written (and with --commit
# committed) after every run. Tasks of one study running at once share its
# index under its lock. A task whose run the ledger records as done, with the
# run key the sweep gives it, is skipped: its folder went with an earlier
# sitting's machine, and its row is the record.
run_studies() {   # STUDY...
  local s item listing tasks=() pending kept verdicts skipped stale
  local ledger_csv="$HERE/results/scaling-runs.csv"
  [ -f "$ledger_csv" ] || ledger_csv=/dev/null
  for s in "$@"; do
    if [ -n "$only" ] && [[ "$s" == tune-* ]] && [[ "$s" != *-"$only" ]]; then continue; fi
    # "TASK RUN_DIR KEY" of every run not done in its folder (a cic that cannot list
    # its runs with their keys, as one older than this script, is refused: exit 2).
    listing=$(runs_of "$s") || exit 2
    mapfile -t pending < <(awk '$2 != "done" { print $1 " " $3 " " $4 }' <<< "$listing")
    # Each pending run against the ledger's done rows (columns found by name), matched
    # by study and run folder: "skip" (same run key), "stale TASK RUN_DIR" (a row of
    # another key, or none: it runs again) or "run TASK RUN_DIR" (no done row).
    # (The ledger is read in BEGIN: with NR == FNR an empty or missing ledger would
    # take the pending runs for its own rows, and nothing would run.)
    mapfile -t verdicts < <(printf '%s\n' "${pending[@]}" |
      awk -v s="$s" -v ledger="$ledger_csv" 'BEGIN {
            while ((getline line < ledger) > 0) {
              n = split(line, f, ",")
              if (++row == 1) { for (i = 1; i <= n; i++) col[f[i]] = i; continue }
              if (f[col["study"]] == s && f[col["status"]] == "done")
                done_key[f[col["run_dir"]]] = ("run_key" in col) ? f[col["run_key"]] : ""
            } }
          !NF { next }
          !($2 in done_key) { print "run " $1 " " $2; next }
          done_key[$2] == $3 && $3 != "" { print "skip"; next }
          { print "stale " $1 " " $2 }')
    kept=() skipped=0 stale=0
    for item in "${verdicts[@]}"; do
      case "$item" in
        skip) skipped=$((skipped + 1)) ;;
        stale\ *) stale=$((stale + 1)); kept+=("${item#stale }") ;;
        run\ *) kept+=("${item#run }") ;;
      esac
    done
    [ "$skipped" = 0 ] || echo "== $s: $skipped runs the ledger records as done are not run again" >&2
    [ "$stale" = 0 ] ||
      echo "== $s: $stale runs the ledger records as done, but of other settings (its run key is not the sweep's), run again" >&2
    echo "== $s: ${#kept[@]} runs to go" >&2
    # Every run already in the store (another study ran it): link them, so the ledger sees the study.
    if [ ${#pending[@]} = 0 ] && [ "$dry_run" = 0 ]; then "$CIC" --quiet sweep "$HERE/$s.xml" --output "$output/$s" --index-only; fi
    for item in "${kept[@]}"; do tasks+=("$s $item"); done   # "STUDY TASK RUN_DIR"
  done
  run_pool "${tasks[@]}"
}

# Runs TASKs ("STUDY TASK RUN_DIR [BEST_EVER]") --jobs at a time, the ledger and its
# commit after each; with --dry-run, lists them. A task with BEST_EVER (posture-runs:
# a rerun of a run the ledger scores) must end done on exactly that best_ever: if it
# does not, the other runs are stopped and the stage exits 1 before the ledger is
# written, so the ledger keeps the row it scores.
run_pool() {   # TASK...
  local tasks=("$@")
  if [ "$dry_run" = 1 ]; then
    [ ${#tasks[@]} = 0 ] || printf '%s\n' "${tasks[@]}"
    return 0
  fi
  local next=0 running=0 pid study task run expect status got done_now
  local -A what=() tries=()   # running pid -> "STUDY TASK RUN_DIR [BEST_EVER]"; "STUDY TASK" -> starts
  while [ $next -lt ${#tasks[@]} ] || [ $running -gt 0 ]; do
    while [ $running -lt "$jobs" ] && [ $next -lt ${#tasks[@]} ]; do
      read -r study task run expect <<< "${tasks[next]}"
      "$CIC" --quiet sweep "$HERE/$study.xml" --output "$output/$study" --task "$task" --workers 1 >&2 &
      what[$!]="${tasks[next]}"
      tries["$study $task"]=$(( ${tries["$study $task"]:-0} + 1 ))
      running=$((running + 1)) next=$((next + 1))
    done
    # A run that fails shows as such in the ledger; the study goes on.
    pid=''
    wait -n -p pid "${!what[@]}" || true
    [ -n "$pid" ] || { echo "scaling.sh: wait -n gave no finished run (bash ${BASH_VERSION}); stopping" >&2; exit 1; }
    read -r study task run expect <<< "${what[$pid]}"
    local item="${what[$pid]}"
    unset "what[$pid]"
    running=$((running - 1))
    # A task started while another's index write probed its lock skips itself as
    # "running elsewhere" and ends pending: queue it again (three starts at most).
    # awk reads the whole listing: stopping at the match would end the lister with SIGPIPE,
    # and under pipefail that failure would stop the study (it did, on a 40-run sweep).
    read -r status got < <(runs_of "$study" | awk -v t="$task" '$1 == t {print $2, $5}') || status='?'
    [ "$status" != '?' ] || echo "scaling.sh: could not read $study task $task's status" >&2
    if [[ "$status" =~ ^(pending|interrupted)$ ]] && [ "${tries["$study $task"]}" -lt 3 ]; then
      echo "scaling.sh: $study $run ended $status; queued again" >&2
      tasks+=("$item")
    fi
    if [ -n "$expect" ] && [ "$status" = done ] && [ "$got" != "$expect" ]; then
      echo "scaling.sh: $study $run was rerun and ended on best_ever $got, but the ledger scores it $expect: not the same run (one seed should fix it; see docs/scaling.md). Stopping before the ledger is written; the rerun's folder is $output/$study/$run, and the next ledger (any stage) would take its row" >&2
      for pid in "${!what[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
      wait || true
      exit 1
    fi
    # The other slot's run goes on whatever the ledger does; the next run's commit retries it.
    ledger || echo "scaling.sh: the ledger failed after $study $run (the next run's retries it)" >&2
    done_now=$(awk -F, -v s="$study" '$1 == s && $4 == "done"' "$HERE/results/scaling-runs.csv" | wc -l)
    commit_results "Ledger (issue 38): $study, $done_now runs done, the last $run; scaling-runs.csv and tune-direct.md as of these runs"
  done
}

# The stages run from one function, called on the last line with `exit` after it:
# bash reads a script as it goes, so an edit to this file while a study runs
# (hours) must not be read in the middle of it.
main() {
  for stage in "${stages[@]}"; do
    case "$stage" in
      tune-direct)
        if [ "$summary_only" = 0 ]; then
          run_studies "${tune_studies[@]}"
        fi
        [ "$dry_run" = 1 ] || { ledger; commit_results "Ledger (issue 38): tune-direct summary"; } ;;
      tune-hybrid)
        if [ "$summary_only" = 0 ]; then
          run_studies "${hybrid_studies[@]}"
        fi
        [ "$dry_run" = 1 ] || { ledger; commit_results "Ledger (issue 38): tune-hybrid summary"; } ;;
      compare)
        [ ${#compare_studies[@]} = 10 ] || { echo "scaling.sh: compare needs the 10 experiments/scaling/compare-*.xml, found ${#compare_studies[@]}: write them with $PY scripts/scaling-report.py compare-sweeps --results $HERE/results --out $HERE" >&2; exit 2; }
        for s in "${compare_studies[@]}"; do
          if grep -q PROVISIONAL "$HERE/$s.xml"; then
            echo "scaling.sh: $HERE/$s.xml is provisional (written before the tuning finished): rewrite it with scaling-report.py compare-sweeps without --provisional" >&2; exit 2
          fi
        done
        if [ "$summary_only" = 0 ]; then
          run_studies "${compare_studies[@]}"
        fi
        [ "$dry_run" = 1 ] || { ledger; commit_results "Ledger (issue 38): compare summary"; } ;;
      posture-runs)
        # "STUDY TASK RUN_DIR BEST_EVER" of each run to rerun (refused, exit 2, when a sweep
        # now gives such a run another run key than the ledger's).
        listing=$("$PY" "$ROOT/scripts/scaling-report.py" posture-runs --results "$HERE/results" --studies "$output" \
                  --cic "$CIC" --sweeps "$HERE") || exit 2
        items=(); [ -z "$listing" ] || mapfile -t items <<< "$listing"
        echo "== posture-runs: ${#items[@]} runs to rerun" >&2
        [ "$summary_only" = 1 ] || run_pool "${items[@]}"
        [ "$dry_run" = 1 ] || [ ${#items[@]} = 0 ] || { ledger; commit_results "Ledger (issue 38): posture-runs summary"; } ;;
      ledger)
        ledger ;;
      report)
        # scipy, numpy and matplotlib are Debian's; a pyenv python3 first on PATH lacks them.
        rpy=${PYTHON:-/usr/bin/python3} failed=()
        for page in results anytime posture strips; do
          args=(--results "$HERE/results" --studies "$output")
          [ "$page" = anytime ] || args+=(--cic "$CIC")
          [ "$page" != strips ] || args+=(--out-images "$ROOT/docs/img")
          echo "== report: $page" >&2
          "$rpy" "$ROOT/scripts/scaling-report.py" "$page" "${args[@]}" || failed+=("$page")
        done
        [ ${#failed[@]} = 0 ] || { echo "scaling.sh: report: ${failed[*]} failed (see above)" >&2; exit 1; }
        # Every page written: docs/scaling.md's quoted tables follow them.
        "$rpy" "$ROOT/scripts/docs-blocks.py" "$ROOT/docs/scaling.md" || { echo "scaling.sh: report: docs/scaling.md's quoted parts could not be written (see above)" >&2; exit 1; } ;;
      status)
        # With a cic, done rows count only under the sweeps' run keys, as compare decides, and
        # the runs posture-runs would rerun are counted too.
        keys=(); [ -x "$CIC" ] && keys=(--cic "$CIC")
        [ -x "$CIC" ] && [ -d "$output" ] && keys+=(--studies "$output")
        "$PY" "$ROOT/scripts/scaling-report.py" status --results "$HERE/results" --sweeps "$HERE" --jobs "$jobs" "${keys[@]}" ;;
      estimate)
        robots=(R1 R2 centipede-2 centipede-4 centipede-8 centipede-16
                centipede-2-irregular centipede-4-irregular centipede-8-irregular centipede-16-irregular)
        cpu() {   # CIC ARGS...: CPU seconds of one cic process
          { TIMEFORMAT='%3U %3S'; time "$@" >/dev/null 2>&1; } 2>&1 | awk '{print $1 + $2}'
        }
        # A process's start-up (reading the robot, ODE's set-up), taken off each evaluation below.
        startup=$(for _ in 1 2 3; do cpu "$CIC" simulate --robot R1 --controller sine:0.6,0.5 --seconds 0.05; done | sort -g | head -1)
        for r in "${robots[@]}"; do
          # The centipedes as their sweeps run them: collision search sweep (simple's bits, faster).
          arg=$r space=0; [[ "$r" == centipede* ]] && arg="$ROOT/settings/robots/$r.xml" space=1
          best=""
          for _ in 1 2 3; do
            # CPU seconds, less at the mercy of the machine's load than wall time.
            w=$(cpu "$CIC" simulate --robot "$arg" --controller sine:0.6,0.5 --set Simulator.collisionSpace=$space |
                awk -v s="$startup" '{print $1 - s}')
            if [ -z "$best" ] || awk -v a="$w" -v b="$best" 'BEGIN {exit !(a < b)}'; then best=$w; fi
          done
          echo "$r $best"
        done | "$PY" "$ROOT/scripts/scaling-report.py" estimate --results "$HERE/results"
        echo "scaling.sh: wrote $HERE/results/estimate.md" >&2 ;;
    esac
  done
}

main; exit
