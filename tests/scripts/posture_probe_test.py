#!/usr/bin/env python3
"""Scripts.PostureProbe: scripts/posture-probe.py on a real gait run (R2, a few
evaluations): the "original" variant, decoded and written back, replays to the
run's own fitness (the probe reads the unit box as cic does); "offsets 0" is
another gait; a run that is not a sine gait is refused with exit 2.

    posture_probe_test.py SOURCE_DIR CIC WORK_DIR
Exit 77 (skipped) without numpy.
"""
import csv
import io
import pathlib
import shutil
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
try:
    import numpy  # noqa: F401
except ImportError as e:
    print(f"posture_probe_test: skipped: {e}")
    sys.exit(77)
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)


def check(condition, message):
    if not condition:
        print(f"posture_probe_test: {message}", file=sys.stderr)
        sys.exit(1)


subprocess.run([cic, "--quiet", "--settings", str(source / "settings/r1_gait_ipop.xml"), "--set", "Gait.evaluations=40",
                "--set", "Simulator.robot_type=2", "--set", "Experiment.workers=1", "--output", str(work / "runs")],
               check=True, capture_output=True)
run = next((work / "runs").iterdir())
own = subprocess.run([cic, "--quiet", "assess", str(run)], check=True, capture_output=True, text=True).stdout
own = float(next(csv.DictReader(io.StringIO(own)))["raw_fitness"])
probe = [sys.executable, str(source / "scripts/posture-probe.py"), "--cic", cic, "--work", str(work / "probe")]
r = subprocess.run([*probe, str(run)], capture_output=True, text=True)
check(r.returncode == 0, f"the probe failed: {r.stderr}")
rows = {line.split("|")[1].strip(): line.split("|")[2].strip() for line in r.stdout.splitlines() if line.startswith("| ")}
check(rows.get("original") == f"{own:.2f}", f"original {rows.get('original')} is not the run's {own:.2f}:\n{r.stdout}")
check("offsets 0" in rows and "by axis, 2 terms" in rows and "mirrored" in rows, f"rows: {sorted(rows)}")
# Not a sine gait: refused by name, nothing replayed.
settings = (run / "settings.xml").read_text()
(run / "settings.xml").write_text(settings.replace("<controller>sine</controller>", "<controller>cpg</controller>"))
r = subprocess.run([*probe, str(run)], capture_output=True, text=True)
check(r.returncode == 2 and "Gait.controller must be sine" in r.stderr, f"a CPG run: {r.returncode} {r.stderr}")
shutil.rmtree(work)
print("posture_probe_test: ok")
