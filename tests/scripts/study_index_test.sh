#!/usr/bin/env bash
# scripts/lib/study-index.sh: finished runs, one run's status and a robot's best
# finished run, read by header name from index.csv as `cic sweep` writes it
# (a varied value quoted for its comma; an older index without best_ever).
# Usage: study_index_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
. "$1/scripts/lib/study-index.sh"
work=$2
rm -rf "$work" && mkdir -p "$work/study" "$work/old"
cat > "$work/study/index.csv" <<'CSV'
run_dir,config,Neural.synapseTypes,seed,status,final_best,generations,evaluations,wall_seconds,best_ever,commit
runs/R1/s1,R1,"a,b",1,done,3,300,15000,1.000,5.5,abc (dirty)
runs/R1/s2,R1,"a,b",2,running,3,120,6000,1.000,9.5,abc
runs/R1/s3,R1,"a,b",3,done,3,300,15000,1.000,7.25,abc
runs/R1/s4,R1,"a,b",4,done,3,300,15000,1.000,7.25,abc
runs/R2/s1,R2,c,1,done,3,300,15000,1.000,1,abc
runs/done/s1,done,c,1,pending,,0,0,0.000,,
CSV
cat > "$work/old/index.csv" <<'CSV'
run_dir,config,seed,status,final_best,generations,evaluations,wall_seconds
runs/R0/s1,R0,1,done,2,10,500,1.000
CSV
fail=0
expect() {   # WHAT EXPECTED ACTUAL
  if [ "$2" != "$3" ]; then echo "FAIL $1: expected [$2], got [$3]"; fail=1; else echo "ok   $1"; fi
}
expect "finished runs" "$work/study/runs/R1/s1 $work/study/runs/R1/s3 $work/study/runs/R1/s4 $work/study/runs/R2/s1" \
  "$(finished_runs "$work/study" | tr '\n' ' ' | sed 's/ $//')"
expect "finished runs, older index" "$work/old/runs/R0/s1" "$(finished_runs "$work/old")"
expect "finished runs, no index" "" "$(finished_runs "$work/none")"
expect "a running run is not finished" 1 "$(run_is_finished "$work/study" runs/R1/s2 && echo 0 || echo 1)"
expect "a done run is finished" 0 "$(run_is_finished "$work/study" runs/R1/s3 && echo 0 || echo 1)"
expect "a config named done is no status" 1 "$(run_is_finished "$work/study" runs/done/s1 && echo 0 || echo 1)"
expect "no index: nothing finished" 1 "$(run_is_finished "$work/none" runs/R1/s1 && echo 0 || echo 1)"
expect "best finished run (a higher one still running; the first on a tie)" runs/R1/s3 "$(best_finished_run "$work/study" R1)"
expect "best finished run of another robot" runs/R2/s1 "$(best_finished_run "$work/study" R2)"
expect "no such robot" "" "$(best_finished_run "$work/study" R3)"
expect "older index: no best_ever, no best" "" "$(best_finished_run "$work/old" R0)"
exit $fail
