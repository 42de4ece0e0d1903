#!/usr/bin/python3
"""Issue 55's study (docs/transfer.md): one genotype for every body.

  transfer.py run STUDIES... [--jobs N] [--commit]   run the sweeps' pending runs, N at a time (one
                                                     worker each); the ledger after every run, and with
                                                     --commit its commit (experiments/transfer/results/)
  transfer.py ledger                                 merge every study's index.csv into the ledger
  transfer.py zero-shot [--jobs N]                   `cic transfer` of every finished source run onto
                                                     every target robot (cached by run and best_ever)
  transfer.py report                                 results/zero-shot.md and results/budget.md
  transfer.py status                                 runs done and to go, per study

STUDIES: budget (experiments/transfer/budget-centipede-16.xml), sources (source-*.xml) or a sweep's
name. Resumable like every `cic sweep`: rerun after an interruption and only what is missing runs;
a run the committed ledger records as done under the run key the sweep now gives it is not run again
even when its folder is gone (run folders are never committed). Environment: CIC (default
build/cic), TRANSFER_RUNS (the studies' folders, default runs/transfer)."""
import argparse
import csv
import io
import os
import statistics as st
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study_stats as ss  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HERE = os.path.join(ROOT, "experiments", "transfer")
RESULTS = os.path.join(HERE, "results")
LEDGER = os.path.join(RESULTS, "transfer-runs.csv")
RAW = os.path.join(RESULTS, "zero-shot-raw.csv")
CIC = os.environ.get("CIC", os.path.join(ROOT, "build", "cic"))
RUNS = os.environ.get("TRANSFER_RUNS", os.path.join(ROOT, "runs", "transfer"))
LEDGER_FIELDS = ["study", "config", "seed", "status", "best_ever", "evaluations", "wall_seconds", "run_dir",
                 "commit", "run_key"]
RAW_FIELDS = ["study", "config", "seed", "best_ever", "target", "hinges", "rule", "raw_fitness", "distance",
              "elevation", "verdict"]
# The bodies a source genotype is replayed on: 24 to 384 hinges and the irregular twins.
TARGETS = [f"centipede-{p}{t}" for p in (4, 8, 16, 32, 64) for t in ("", "-irregular")]
# Issue 38's from-scratch runs (comparison seeds 1..10, 2,500 evaluations): the reference medians.
SCRATCH = os.path.join(ROOT, "experiments", "scaling", "results", "compare-raw.csv")
METHOD = {"hypergp-gait": "HyperGP-gait", "direct.sepcmaes-s0.15": "best direct"}


def studies(names):
    out = []
    for n in names:
        if n == "budget":
            out.append("budget-centipede-16")
        elif n == "sources":
            out += sorted(f[:-4] for f in os.listdir(HERE) if f.startswith("source-") and f.endswith(".xml"))
        elif os.path.exists(os.path.join(HERE, n + ".xml")):
            out.append(n)
        else:
            sys.exit(f"transfer.py: no study {n} (budget, sources, or a sweep of {HERE})")
    return out


def sweep_runs(study):
    p = subprocess.run([CIC, "--quiet", "sweep", os.path.join(HERE, study + ".xml"), "--dry-run", "--csv",
                        "--output", os.path.join(RUNS, study)], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"transfer.py: {CIC} sweep {study} --dry-run --csv failed: {p.stderr.strip()}")
    return list(csv.DictReader(io.StringIO(p.stdout)))


def read_csv(path):
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def write_csv(path, fields, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fields, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, path)


def ledger():
    """The ledger: every study's index.csv rows (paths relative to the study), merged with the
    committed rows of runs whose folders are gone."""
    rows = {(r["study"], r["run_dir"]): r for r in read_csv(LEDGER)}
    for study in studies(["budget", "sources"]):
        folder = os.path.join(RUNS, study)
        if not os.path.isdir(folder):
            continue
        subprocess.run([CIC, "--quiet", "sweep", os.path.join(HERE, study + ".xml"), "--output", folder,
                        "--index-only"], check=True)
        for r in read_csv(os.path.join(folder, "index.csv")):
            old = rows.get((study, r["run_dir"]))
            if r["status"] != "done" and old and old["status"] == "done":
                continue   # a rerun under way keeps its run's done row
            rows[(study, r["run_dir"])] = {"study": study, **{k: r.get(k, "") for k in LEDGER_FIELDS[1:]}}
    write_csv(LEDGER, LEDGER_FIELDS, sorted(rows.values(), key=lambda r: (r["study"], r["config"], int(r["seed"]))))
    return rows


def commit(message):
    subprocess.run(["git", "-C", ROOT, "add", RESULTS], check=False)
    if subprocess.run(["git", "-C", ROOT, "diff", "--cached", "--quiet", "--", RESULTS]).returncode != 0:
        subprocess.run(["git", "-C", ROOT, "commit", "--quiet", "-m", message, "--", RESULTS], check=False)


def run(names, jobs, do_commit):
    done = {(r["study"], r["run_dir"]): r["run_key"] for r in read_csv(LEDGER) if r["status"] == "done"}
    tasks = []
    for study in studies(names):
        for r in sweep_runs(study):
            if r["status"] != "done" and done.get((study, r["run_dir"])) != r["run_key"]:
                tasks.append((study, r["task"], r["run_dir"]))
    print(f"transfer.py: {len(tasks)} runs to go", file=sys.stderr)
    running = []
    while tasks or running:
        while tasks and len(running) < jobs:
            study, task, run_dir = tasks.pop(0)
            cmd = [CIC, "--quiet", "sweep", os.path.join(HERE, study + ".xml"), "--task", task, "--workers", "1",
                   "--output", os.path.join(RUNS, study)]
            running.append((subprocess.Popen(cmd), study, run_dir))
        pid, _ = os.wait()
        for item in [x for x in running if x[0].pid == pid]:
            running.remove(item)
            ledger()
            if do_commit:
                commit(f"Ledger (issue 55): {item[1]} {item[2]} done")


def zero_shot():
    """`cic transfer` of every finished source run, cached by (study, config, seed, best_ever)."""
    cache = read_csv(RAW)
    have = {(r["study"], r["config"], r["seed"], r["best_ever"]) for r in cache}
    # Seed by seed, every method of a seed together: an interrupted pass leaves comparable cells.
    for r in sorted(ledger().values(), key=lambda r: (r["study"], int(r["seed"]), r["config"])):
        key = (r["study"], r["config"], r["seed"], r["best_ever"])
        if not r["study"].startswith("source-") or r["status"] != "done" or key in have:
            continue
        folder = os.path.join(RUNS, r["study"], r["run_dir"])
        if not os.path.isdir(folder):
            continue
        args = [CIC, "--quiet", "transfer", folder]
        for t in TARGETS:
            args += ["--robot", t]
        p = subprocess.run(args, capture_output=True, text=True)
        if p.returncode != 0:
            sys.exit(f"transfer.py: cic transfer {folder}: {p.stderr.strip()}")
        for row in csv.DictReader(io.StringIO(p.stdout)):
            if row["rule"] == "own":
                continue
            cache.append({"study": r["study"], "config": r["config"], "seed": r["seed"], "best_ever": r["best_ever"],
                          "target": row["robot"], "hinges": row["hinges"], "rule": row["rule"],
                          "raw_fitness": row["raw_fitness"], "distance": row["distance"],
                          "elevation": row["elevation"], "verdict": row["verdict"]})
        write_csv(RAW, RAW_FIELDS, cache)
        print(f"transfer.py: {r['study']} {r['config']} s{r['seed']} transferred", file=sys.stderr)


def ratio_interval(x, y, resamples=2000):
    import random
    rng = random.Random(1)
    vals = sorted(st.median([rng.choice(x) for _ in x]) / st.median([rng.choice(y) for _ in y])
                  for _ in range(resamples))
    return vals[int(0.025 * resamples)], vals[int(0.975 * resamples) - 1]


def f2(v):
    return "—" if v is None else f"{v:.2f}"


def pval(p):
    return "—" if p is None else f"{p:.3g}"


def report():
    scratch = {}
    for r in read_csv(SCRATCH):
        scratch.setdefault((r["study"].replace("compare-", ""), r["config"]), []).append(float(r["raw_fitness"]))
    raw = read_csv(RAW)
    groups = {}
    for r in raw:
        groups.setdefault((r["study"], r["config"], r["target"], int(r["hinges"])), []).append(r)
    lines = ["# Zero-shot transfer (issue 55)", "",
             "Written by `scripts/transfer.py report` from `zero-shot-raw.csv` (each finished source run's best",
             "genotype replayed unchanged by `cic transfer`: HyperGP-gait's trees queried at the bigger body's",
             "substrate, the best direct method's gait tiled leg pair by leg pair). Raw eq. 7.1, m. *Share*: the",
             "cell's median over the from-scratch median at the target size (issue 38's comparison, seeds 1..10,",
             "2,500 evaluations; — where no from-scratch runs exist). The test: the transferred HyperGP genotypes",
             "against the tiled direct gait evolved on the same small robot (centipede-2 for the several-bodies",
             "and absolute-layout sources), two-sided Mann-Whitney U with Holm over every row, A12 (the chance a",
             "HyperGP genotype walks farther) and the ratio of medians, bootstrap 95 % intervals.", "",
             "| evolved | target | hinges | n | median | IQR | walking | share of scratch HyperGP-gait "
             "| share of scratch direct | tiled direct median | p | p (Holm) | A12 [95 %] | ratio [95 %] | verdict |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    rows, ps = [], []
    for (study, config, target, hinges), hr in sorted(groups.items(), key=lambda kv: (kv[0][0], kv[0][1], kv[0][3],
                                                                                      kv[0][2])):
        if config == "direct.sepcmaes-s0.15":
            continue
        base = "source-centipede-2" if study == "source-bodies" else study
        label = {"hypergp-gait": base.replace("source-", "") + ", HyperGP-gait",
                 "bodies-mean": "centipede-2 + centipede-4 (mean), HyperGP-gait",
                 "absolute": "centipede-2, HyperGP-gait, absolute layout"}.get(config, f"{study} {config}")
        h = [float(r["raw_fitness"]) for r in hr]
        d = [float(r["raw_fitness"]) for r in groups.get((base, "direct.sepcmaes-s0.15", target, hinges), [])]
        p = ss.mann_whitney_p(h, d) if len(h) > 1 and len(d) > 1 else None
        rows.append((label, target, hinges, h, d, hr))
        ps.append(p)
    holm = ss.holm(ps)
    for (label, target, hinges, h, d, hr), p, ph in zip(rows, ps, holm):
        sh = scratch.get((target, "hypergp-gait"))
        sd = scratch.get((target, "direct.sepcmaes-s0.15"))
        mh = st.median(h) if h else None
        walking = sum(1 for r in hr if r["verdict"] == "walking")
        if h and d and p is not None:
            a = ss.a12(h, d)
            lo, hi = ss.a12_interval(h, d)
            rl, rh = ratio_interval(h, d) if st.median(d) > 0 else (None, None)
            a_text = f"{a:.2f} [{lo:.2f}, {hi:.2f}]"
            r_text = f"{mh / st.median(d):.2f} [{f2(rl)}, {f2(rh)}]" if st.median(d) > 0 else "—"
            verdict = ("no difference shown at n = %d and %d" % (len(h), len(d))) if ph >= 0.05 else \
                ("HyperGP farther" if mh > st.median(d) else "tiled direct farther")
        else:
            a_text = r_text = "—"
            verdict = "runs to go"
        q = ss.quartiles(h) if h else None
        lines.append(f"| {label} | {target} | {hinges} | {len(h)} | {f2(mh)} | "
                     f"{'[%s, %s]' % (f2(q[0]), f2(q[1])) if q else '—'} | {walking} of {len(h)} | "
                     f"{f2(mh / st.median(sh)) if h and sh else '—'} | {f2(mh / st.median(sd)) if h and sd else '—'} | "
                     f"{f2(st.median(d)) if d else '—'} | {pval(p)} | {pval(ph)} | {a_text} | {r_text} | {verdict} |")
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "zero-shot.md") + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(os.path.join(RESULTS, "zero-shot.md") + ".tmp", os.path.join(RESULTS, "zero-shot.md"))

    runs = [r for r in read_csv(LEDGER) if r["study"] == "budget-centipede-16"]
    by = {}
    for r in runs:
        by.setdefault(r["config"], []).append(r)
    out = ["# The budget question (issue 55)", "",
           "Written by `scripts/transfer.py report` from the ledger (`transfer-runs.csv`): centipede-16 (96 hinges) at",
           "15,000 evaluations, seeds 201..210, best_ever (m) of the finished runs. At 2,500 evaluations (issue 38)",
           "HyperGP-gait walked 1.63 [1.47, 2.05] times as far as the best direct method.", "",
           "| method | done | running or to go | median | IQR |", "|---|---|---|---|---|"]
    done = {}
    for config in ("hypergp-gait", "direct.sepcmaes-s0.15"):
        rs = by.get(config, [])
        v = [float(r["best_ever"]) for r in rs if r["status"] == "done"]
        done[config] = v
        q = ss.quartiles(v) if v else None
        out.append(f"| {METHOD[config]} | {len(v)} | {10 - len(v)} | {f2(st.median(v)) if v else '—'} | "
                   f"{'[%s, %s]' % (f2(q[0]), f2(q[1])) if q else '—'} |")
    h, d = done["hypergp-gait"], done["direct.sepcmaes-s0.15"]
    if len(h) > 1 and len(d) > 1:
        p = ss.mann_whitney_p(h, d)
        out += ["", f"HyperGP-gait / best direct: {st.median(h) / st.median(d):.2f}, A12 {ss.a12(h, d):.2f}, "
                    f"p {pval(p)} (n = {len(h)} and {len(d)}; provisional until all 20 runs are in)."]
    else:
        out += ["", "No comparison yet: it needs at least two finished runs of each method."]
    with open(os.path.join(RESULTS, "budget.md") + ".tmp", "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(os.path.join(RESULTS, "budget.md") + ".tmp", os.path.join(RESULTS, "budget.md"))


def status():
    for study in studies(["budget", "sources"]):
        rs = sweep_runs(study)
        n = sum(1 for r in rs if r["status"] == "done")
        print(f"{study}: {n} of {len(rs)} done")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("stage", choices=["run", "ledger", "zero-shot", "report", "status"])
    ap.add_argument("studies", nargs="*")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--commit", action="store_true")
    a = ap.parse_args()
    if a.jobs < 1:
        ap.error("--jobs takes a positive number")
    if a.stage == "run":
        if not a.studies:
            ap.error("run: name the studies (budget, sources, or a sweep's name)")
        run(a.studies, a.jobs, a.commit)
    elif a.stage == "ledger":
        ledger()
    elif a.stage == "zero-shot":
        zero_shot()
    elif a.stage == "report":
        report()
    else:
        status()


if __name__ == "__main__":
    main()
