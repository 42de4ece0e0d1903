#!/usr/bin/env python3
"""The ledger and summary of issue 38's scaling study (docs/scaling.md).

  scaling-report.py ledger  --studies DIR --results DIR STUDY...
      merge each STUDY's index.csv (DIR/STUDY/index.csv, written by `cic sweep`)
      into RESULTS/scaling-runs.csv: one row per (study, config, seed), kept
      across sittings (a run whose folder is gone keeps its last row, while
      its run key, the fingerprint of its settings, is the one the index
      gives; an index of other settings replaces it); a row
      the study's index no longer lists (its configuration or seed left the
      sweep file, which `cic sweep` leaves out of index.csv too) is kept as
      status "superseded", which no table counts
  scaling-report.py summary --results DIR
      RESULTS/tune-direct.md from the ledger: per study and configuration the
      finished runs, median and IQR of best_ever, mean wall time per run and
      per evaluation, and each study's winner (highest median; ties: the first)
  scaling-report.py estimate --results DIR < TIMES
      RESULTS/estimate.md: the study's run time from measured seconds per
      evaluation (TIMES: lines "ROBOT SECONDS", as scripts/scaling.sh measures
      them), for the whole plan of issue 38 item 5 and with comparison seeds
      cut on the middle sizes
  scaling-report.py compare-sweeps --results DIR --out DIR [--provisional]
                    [--tuning DIR] [--cic CIC]
      OUT/compare-<robot>.xml, the comparison stage's sweeps (seeds 1..10 on every
      robot), from the tuning winners in RESULTS/scaling-runs.csv and
      the tuning sweeps in TUNING (default experiments/scaling); refuses (exit 2)
      while a tuning study has runs to go, unless --provisional
  scaling-report.py results --results DIR --studies DIR --cic CIC
                    [--figure SVG] [--baselines CSV]
      RESULTS/compare.md and the figure (default docs/img/scaling-ratio.svg) from
      the ledger's compare rows, each run scored by `cic assess` (raw eq. 7.1,
      cached in RESULTS/compare-raw.csv); scipy, matplotlib (Debian's python3)
  scaling-report.py strips --results DIR --studies DIR --cic CIC
                    [--out-images DIR] [--robots R,R] [--at "T T ..."] [--no-strips]
      RESULTS/strips.md: per robot (default centipede-16,centipede-16-irregular)
      and method the finished compare run with the highest raw eq. 7.1 in
      RESULTS/compare-raw.csv, its `cic assess` verdicts and a strip by
      scripts/screenshot-strip.sh (OUT-IMAGES, default docs/img:
      scaling-strip-<robot>-<method>.png; frames at --at, default "2 5 8 11 14");
      each pick's assess row is cached in RESULTS/compare-strips.csv, so a pick
      whose folder is gone keeps its row and the strip drawn before
  scaling-report.py posture --results DIR --studies DIR --cic CIC
      RESULTS/posture.md: scripts/posture-probe.py on every finished run of the
      best direct method of the comparison, per robot the median share of its
      own raw eq. 7.1 each posture replacement keeps, and per robot the share
      each Offset-HybrID run keeps with its direct offsets 0 (scaling_posture.py);
      every run's replays are cached in RESULTS/compare-posture.csv, so a run whose
      folder is gone still counts; a robot with a run in neither is left out, named
  scaling-report.py anytime --results DIR --studies DIR [--figure SVG]
      RESULTS/anytime.md and the figure (default docs/img/scaling-anytime.svg):
      per robot and method the median best fitness the finished compare runs
      had found by 5 %, 10 %, ..., 100 % of the budget (their stats.csv, cached
      in RESULTS/compare-anytime.csv), against the best direct method's; and what
      each Switch-HybrID run handed over, against the best HyperGP had found
      (run.log and stats.csv, cached in RESULTS/compare-handover.csv)
      (scaling_anytime.py, scaling_handover.py; matplotlib)
  scaling-report.py status --results DIR [--sweeps DIR] [--jobs N] [--cic CIC [--studies DIR]]
      print what is left of the comparison, read from the compare sweeps in SWEEPS
      (default experiments/scaling) and the ledger alone (safe beside a running
      study): per sweep its runs, those done and those to go, the core-hours left
      at the seconds per evaluation its finished runs took (else RESULTS/estimate.md's
      figure), and the wall time at N runs at a time (default 2); with CIC a done row
      counts only under the run key the sweep gives its run now (cic sweep --dry-run --csv),
      and with the study folders in DIR too, a last row counts the runs posture-runs
      would rerun, at the wall time the ledger records for them (scaling_status.py)
  scaling-report.py runs --sweep FILE --output DIR --cic CIC
      print every run of the sweep FILE (its study in DIR) as "TASK STATUS
      RUN_DIR RUN_KEY BEST_EVER" (BEST_EVER empty until it has one), one line
      each, from `cic sweep --dry-run --csv` (writes nothing;
      scaling_status.sweep_runs): what scripts/scaling.sh starts runs and reads
      their ends by
  scaling-report.py posture-runs --results DIR --studies DIR --cic CIC [--sweeps DIR]
      print "STUDY TASK RUN_DIR BEST_EVER", one line per finished compare run the
      posture page needs (the best direct method's and Offset-HybrID's) whose
      folder is gone and whose replays are not in RESULTS/compare-posture.csv:
      what scripts/scaling.sh posture-runs reruns, each to end on BEST_EVER, the
      ledger's; SWEEPS (default experiments/scaling) holds the compare sweeps
Standard library only, but for results and anytime (and numpy for posture)."""
import csv
import os
import re
import shlex
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scaling_compare as sc   # noqa: E402 (the script's own folder)

FIELDS = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir", "commit", "run_key"]


def ledger(studies, results, names):
    path = os.path.join(results, "scaling-runs.csv")
    rows = {}
    if os.path.exists(path):
        for r in csv.DictReader(open(path)):
            rows[(r["study"], r["config"], r["seed"])] = r
    for name in names:
        index = os.path.join(studies, name, "index.csv")
        if not os.path.exists(index):
            continue
        listed = set()
        for r in csv.DictReader(open(index)):
            key = (name, r["config"], r["seed"])
            listed.add(key)
            old = rows.get(key)
            key_now = r.get("run_key", "")   # none in an index of a cic older than run keys
            if (r["status"] in ("pending", "running") and old and old["status"] == "done" and
                    (not key_now or old.get("run_key", "") == key_now)):
                # A finished run of an earlier sitting whose folder is gone, or which is being rerun
                # under the same run key (scaling.sh posture-runs): one seed fixes a run, so its row
                # stands; the rerun's own row replaces it when it ends.
                continue
            # A done row of another run key is of settings the sweep no longer asks, and a folder
            # that is there and ended otherwise (interrupted, failed) says the row was wrong:
            # both are replaced.
            rows[key] = {"study": name, **{f: r.get(f, "") for f in FIELDS if f != "study"}}
        for key, row in rows.items():
            if key[0] == name and key not in listed:
                row["status"] = "superseded"   # its record stays; the sweep no longer runs it
    sc.write_rows_atomically(path, FIELDS, rows)
    return sum(r["status"] == "done" for r in rows.values())


def quartiles(v):
    if len(v) < 2:
        return v[0], v[0]
    q = statistics.quantiles(v, n=4, method="inclusive")
    return q[0], q[2]


def summary(results):
    rows = [r for r in csv.DictReader(open(os.path.join(results, "scaling-runs.csv"))) if r["status"] == "done"]
    out = ["# Tuning the direct side and the hybrids (issue 38)", "",
           "Written by `scripts/scaling.sh` from `scaling-runs.csv` (the ledger); best_ever in metres",
           "(eq. 7.1 of the run's best gait), over the finished runs of tuning seeds 101..105.", ""]
    for study in sorted({r["study"] for r in rows if r["study"].startswith("tune-")}):   # compare-*: results
        out += [f"## {study}", "", "| config | runs | median | IQR | s per run | ms per evaluation |",
                "|---|---|---|---|---|---|"]
        medians = sc.config_medians(rows, study)
        for config in medians:
            rs = [r for r in rows if r["study"] == study and r["config"] == config]
            best = sorted(float(r["best_ever"]) for r in rs)
            wall = statistics.mean(float(r["wall_seconds"]) for r in rs)
            evals = statistics.mean(float(r["evaluations"]) for r in rs)
            lo, hi = quartiles(best)
            out.append(f"| {config} | {len(rs)} | {medians[config]:.2f} | [{lo:.2f}, {hi:.2f}] | {wall:.0f} | "
                       f"{1000 * wall / evals:.1f} |")
        complete = all(sum(1 for r in rows if r["study"] == study and r["config"] == c) == 5 for c in medians)
        # A hybrid study tunes two methods (offset-*, switch-*): a winner for each.
        methods = sorted({sc.method_of(c) for c in medians}) if study.startswith("tune-hybrid") else [None]
        out.append("")
        for m in methods:
            winner = sc.winner(medians, m)
            out.append(f"Winner so far{'' if m is None else ' (' + m + ')'}: **{winner}** (median {medians[winner]:.2f})"
                       + ("" if complete else "; not every configuration has its 5 runs yet") + ".")
        out.append("")
    with open(os.path.join(results, "tune-direct.md"), "w") as f:
        f.write("\n".join(out))


# The plan of issue 38 item 5 (docs/scaling.md). Runs: (stage, robot, methods, seeds, evaluations).
# HyperGP methods cost their physics plus HyperGP's substrate and network (under 10 %
# of physics, scripts/bench.sh): counted as 1.1 times the physics.
CENTIPEDES = ["centipede-2", "centipede-4", "centipede-8", "centipede-16",
              "centipede-2-irregular", "centipede-4-irregular", "centipede-8-irregular", "centipede-16-irregular"]
MIDDLE = {"centipede-4", "centipede-8", "centipede-4-irregular", "centipede-8-irregular"}
HYPERGP_COST = 1.1


def plan(middle_seeds):
    runs = []
    # Tuning, seeds 101..105 on R1 (15,000) and the 48-hinge centipede (2,500).
    runs.append(("tune: direct (4 configs, tune-direct-*.xml)", "R1", 4, 1.0, 5, 15000))
    runs.append(("tune: direct (4 configs, tune-direct-*.xml)", "centipede-8", 4, 1.0, 5, 2500))
    runs.append(("tune: hybrids (assumed 2 configs each)", "R1", 4, HYPERGP_COST, 5, 15000))
    runs.append(("tune: hybrids (assumed 2 configs each)", "centipede-8", 4, HYPERGP_COST, 5, 2500))
    # Comparison, seeds 1..10: best direct, HyperGP-gait, Offset-HybrID, Switch-HybrID.
    for robot in CENTIPEDES:
        seeds = middle_seeds if robot in MIDDLE else 10
        runs.append(("compare: best direct", robot, 1, 1.0, seeds, 2500))
        runs.append(("compare: 3 HyperGP methods", robot, 3, HYPERGP_COST, seeds, 2500))
    # R1 and R2 at 15,000: issue 21 ran IPOP-CMA-ES and HyperGP-gait (walk-15000-*.xml); the hybrids are new.
    for robot in ("R1", "R2"):
        runs.append(("compare: 2 hybrids (15,000)", robot, 2, HYPERGP_COST, 10, 15000))
    return runs


def estimate(results):
    times = {}
    for line in sys.stdin:
        if line.strip():
            robot, sec = line.split()
            times[robot] = float(sec)
    out = ["# Run-time estimate of the scaling study (issue 38)", "",
           "Written by `scripts/scaling.sh estimate`: CPU seconds per evaluation measured on this machine",
           "(the least of three `cic simulate` processes, 15 s under a sine gait, less a process's start-up; centipedes with",
           "`Simulator.collisionSpace = 1`), times the plan's evaluations, HyperGP methods at 1.1 times",
           "the physics. Hours of one core, one run at a time, one worker.", "",
           "| robot | s per evaluation |", "|---|---|"]
    out += [f"| {r} | {times[r]:.3f} |" for r in times]
    for middle in (10, 5, 3):
        rows = plan(middle)
        total = 0.0
        out += ["", f"### Comparison seeds on the middle sizes (centipedes 4 and 8, both twins): {middle}", "",
                "| stage | robot | runs | hours |", "|---|---|---|---|"]
        for stage, robot, methods, cost, seeds, evals in rows:
            h = methods * seeds * evals * times[robot] * cost / 3600
            total += h
            out.append(f"| {stage} | {robot} | {methods * seeds} | {h:.1f} |")
        out.append(f"| **total** | | {sum(m * s for _, _, m, _, s, _ in rows)} | **{total:.1f}** |")
    with open(os.path.join(results, "estimate.md"), "w") as f:
        f.write("\n".join(out) + "\n")


def usage(line):
    print(line, file=sys.stderr)
    sys.exit(2)


def page_command(argv):
    """The command a page says wrote it, with paths inside the repository relative to its root,
    so a page written through scaling.sh (which passes absolute paths) reads the same as one
    written by hand from the root, on any machine."""
    root = os.path.realpath(sc.ROOT)

    def shown(arg):
        if os.path.isabs(arg) and os.path.commonpath([os.path.realpath(arg), root]) == root:
            return os.path.relpath(os.path.realpath(arg), root)
        return arg
    return " ".join(shlex.quote(shown(a)) for a in ["scripts/scaling-report.py"] + argv[1:])


def main(argv):
    if len(argv) >= 2 and argv[1] == "ledger":
        args, names = {}, []
        i = 2
        while i < len(argv):
            if argv[i] in ("--studies", "--results"):
                args[argv[i]] = argv[i + 1]
                i += 2
            else:
                names.append(argv[i])
                i += 1
        print(ledger(args["--studies"], args["--results"], names))
    elif len(argv) == 4 and argv[1] == "estimate" and argv[2] == "--results":
        estimate(argv[3])
    elif len(argv) == 4 and argv[1] == "summary" and argv[2] == "--results":
        summary(argv[3])
    elif len(argv) >= 2 and argv[1] in ("compare-sweeps", "results", "strips", "posture", "anytime", "status", "runs",
                                             "posture-runs"):
        flags = {"compare-sweeps": {"--provisional"}, "results": set(), "strips": {"--no-strips"},
                 "posture": set(), "anytime": set(), "status": set(), "runs": set(), "posture-runs": set()}[argv[1]]
        known = {"compare-sweeps": {"--results", "--out", "--tuning", "--cic"},
                 "results": {"--results", "--studies", "--cic", "--figure", "--baselines"},
                 "strips": {"--results", "--studies", "--cic", "--out-images", "--robots", "--at"},
                 "posture": {"--results", "--studies", "--cic"},
                 "anytime": {"--results", "--studies", "--figure"},
                 "status": {"--results", "--sweeps", "--jobs", "--cic", "--studies"},
                 "runs": {"--sweep", "--output", "--cic"},
                 "posture-runs": {"--results", "--studies", "--cic", "--sweeps"}}[argv[1]]
        args, i = {}, 2
        while i < len(argv):
            if argv[i] in flags:
                args[argv[i]] = True
                i += 1
            elif argv[i] in known and i + 1 < len(argv):
                args[argv[i]] = argv[i + 1]
                i += 2
            else:
                usage(f"scaling-report.py {argv[1]}: unknown or incomplete option '{argv[i]}' (allowed: "
                      f"{', '.join(sorted(known | flags))})")
        need = {"compare-sweeps": ("--results", "--out"), "results": ("--results", "--studies", "--cic"),
                "strips": ("--results", "--studies", "--cic"), "posture": ("--results", "--studies", "--cic"),
                "anytime": ("--results", "--studies"), "status": ("--results",),
                "runs": ("--sweep", "--output", "--cic"),
                "posture-runs": ("--results", "--studies", "--cic")}[argv[1]]
        for n in need:
            if n not in args:
                usage(f"scaling-report.py {argv[1]}: {n} is required")
        if argv[1] == "status" and "--studies" in args and "--cic" not in args:
            usage("scaling-report.py status: --studies goes with --cic (the reruns are found by their run keys)")
        if argv[1] == "status" and "--studies" in args and not os.path.isdir(args["--studies"]):
            usage(f"scaling-report.py status: --studies {args['--studies']} is no folder (every run would count as gone)")
        try:
            if argv[1] == "compare-sweeps":
                for p in sc.compare_sweeps(args["--results"], args["--out"],
                                           args.get("--tuning", os.path.join(sc.ROOT, "experiments", "scaling")),
                                           args.get("--cic", os.path.join(sc.ROOT, "build", "cic")),
                                           args.get("--provisional", False)):
                    print(p)
            elif argv[1] == "runs":
                import scaling_status
                for r in scaling_status.sweep_runs(args["--cic"], args["--sweep"], args["--output"]):
                    print(r["task"], r["status"], r["run_dir"], r["run_key"], r["best_ever"])
            elif argv[1] == "posture-runs":
                import scaling_posture
                for run in scaling_posture.reruns(args["--results"], args["--studies"], args["--cic"],
                                                  args.get("--sweeps", os.path.join(sc.ROOT, "experiments", "scaling"))):
                    print(*run)
            elif argv[1] == "status":
                import scaling_status
                jobs = args.get("--jobs", "2")
                if not re.fullmatch(r"[1-9][0-9]*", jobs):
                    usage(f"scaling-report.py status: --jobs takes a positive whole number, got '{jobs}'")
                print("\n".join(scaling_status.status(
                    args["--results"], args.get("--sweeps", os.path.join(sc.ROOT, "experiments", "scaling")), int(jobs),
                    args.get("--cic"), args.get("--studies"))))
            elif argv[1] == "anytime":
                import scaling_anytime
                scaling_anytime.anytime(args["--results"], args["--studies"],
                                        args.get("--figure", os.path.join(sc.ROOT, "docs", "img", "scaling-anytime.svg")),
                                        page_command(argv))
            elif argv[1] == "posture":
                import scaling_posture
                scaling_posture.posture(args["--results"], args["--studies"], args["--cic"],
                                        page_command(argv))
            elif argv[1] == "strips":
                import scaling_strips
                robots = args.get("--robots", ",".join(scaling_strips.LARGEST)).split(",")
                command = page_command(argv)
                try:
                    scaling_strips.strips(args["--results"], args["--studies"], args["--cic"],
                                          args.get("--out-images", os.path.join(sc.ROOT, "docs", "img")), robots,
                                          args.get("--at", scaling_strips.STRIP_TIMES), command,
                                          draw=not args.get("--no-strips", False))
                except scaling_strips.StripFailed as e:
                    print(f"scaling-report.py: {e}", file=sys.stderr)
                    sys.exit(1)
            else:
                import scaling_results
                scaling_results.results(args["--results"], args["--studies"], args["--cic"],
                                        args.get("--figure", os.path.join(sc.ROOT, "docs", "img", "scaling-ratio.svg")),
                                        args.get("--baselines", os.path.join(sc.ROOT, "experiments", "baselines",
                                                                             "results", "walk-runs.csv")))
        except sc.Refusal as e:
            print(f"scaling-report.py: {e}", file=sys.stderr)
            sys.exit(2)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
