# Reading a study's index.csv (written by `cic sweep`) from the shell. Source
# this file; each function takes the study folder (the one that holds
# index.csv), and a missing index reads as a study with no runs.
#
# Columns are found by their header name. run_dir and config come first and
# are folder-safe (no commas); the columns after the sweep's varied keys
# (seed, status, ..., best_ever, commit) are counted from the end of the line,
# so a varied value quoted because it holds a comma cannot shift them.
_study_index_awk='NR == 1 {for (i = 1; i <= NF; i++) {h[$i] = i; e[$i] = NF - i}; next}
function col(name) {return name == "run_dir" || name == "config" ? $h[name] : (name in e ? $(NF - e[name]) : "")}'

# The folders of the study's finished runs (status done), one per line, as STUDY/RUN_DIR.
finished_runs() {   # STUDY
  awk -F, -v s="$1" "$_study_index_awk"'
    col("status") == "done" {print s "/" col("run_dir")}' "$1/index.csv" 2>/dev/null || true
}

# Succeeds if RUN_DIR (as index.csv names it: runs/CONFIG/sSEED) is finished.
run_is_finished() {   # STUDY RUN_DIR
  awk -F, -v d="$2" "$_study_index_awk"'
    col("run_dir") == d && col("status") == "done" {found = 1} END {exit !found}' "$1/index.csv" 2>/dev/null
}

# The RUN_DIR of CONFIG's finished run with the highest best_ever (the first
# one on a tie); nothing if CONFIG has no finished run with a best_ever.
best_finished_run() {   # STUDY CONFIG
  awk -F, -v c="$2" "$_study_index_awk"'
    col("config") == c && col("status") == "done" && col("best_ever") != "" &&
    (best == "" || col("best_ever") + 0 > best + 0) {best = col("best_ever"); dir = col("run_dir")}
    END {print dir}' "$1/index.csv" 2>/dev/null || true
}
