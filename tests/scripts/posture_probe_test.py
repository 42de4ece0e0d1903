#!/usr/bin/env python3
"""Scripts.PostureProbe: scripts/posture-probe.py on real gait runs (R2, and the
12-hinge centipede of a robot file, a few evaluations each): the "original"
variant, decoded and written back, replays to the run's own fitness (the probe
reads the unit box as cic does); "offsets 0" is another gait; a run that is not
a sine gait is refused with exit 2, and one whose robot file is gone too.

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


probe = [sys.executable, str(source / "scripts/posture-probe.py"), "--cic", cic, "--work", str(work / "probe")]


def probed(robot_sets, name):
    """A 40-evaluation gait run on the robot, probed: its rows, checked against its own replay."""
    subprocess.run([cic, "--quiet", "--settings", str(source / "settings/r1_gait_ipop.xml"), "--set", "Gait.evaluations=40",
                    *robot_sets, "--set", "Experiment.workers=1", "--output", str(work / name)],
                   check=True, capture_output=True)
    run = next((work / name).iterdir())
    own = subprocess.run([cic, "--quiet", "assess", str(run)], check=True, capture_output=True, text=True).stdout
    own = float(next(csv.DictReader(io.StringIO(own)))["raw_fitness"])
    r = subprocess.run([*probe, str(run)], capture_output=True, text=True)
    check(r.returncode == 0, f"{name}: the probe failed: {r.stderr}")
    rows = {line.split("|")[1].strip(): line.split("|")[2].strip() for line in r.stdout.splitlines() if line.startswith("| ")}
    check(rows.get("original") == f"{own:.2f}", f"{name}: original {rows.get('original')} is not the run's {own:.2f}:\n{r.stdout}")
    check("offsets 0" in rows and "by axis, 2 terms" in rows and "mirrored" in rows, f"{name}: rows: {sorted(rows)}")
    return run


centipede = work / "centipede-2.xml"   # a robot file outside the source tree, removed below
shutil.copy(source / "settings/robots/centipede-2.xml", centipede)
walker = probed(["--set", f"Simulator.robotFile={centipede}", "--set", "Simulator.collisionSpace=1"], "centipede")
centipede.unlink()
r = subprocess.run([*probe, str(walker)], capture_output=True, text=True)
check(r.returncode == 2 and "Simulator.robotFile" in r.stderr and "no such file" in r.stderr,
      f"a robot file gone: {r.returncode} {r.stderr}")
run = probed(["--set", "Simulator.robot_type=2"], "runs")
# Not a sine gait: refused by name, nothing replayed.
settings = (run / "settings.xml").read_text()
(run / "settings.xml").write_text(settings.replace("<controller>sine</controller>", "<controller>cpg</controller>"))
r = subprocess.run([*probe, str(run)], capture_output=True, text=True)
check(r.returncode == 2 and "Gait.controller must be sine" in r.stderr, f"a CPG run: {r.returncode} {r.stderr}")
shutil.rmtree(work)
print("posture_probe_test: ok")
