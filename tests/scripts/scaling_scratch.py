"""The scratch copy of issue 38's study layout that the scripts/scaling.sh tests run in.

    scratch = Scratch("scaling_sh_runs_test")   # reads SOURCE_DIR CIC WORK_DIR from sys.argv
    scratch.check(condition, message)           # exit 1 with the test's name and the message
    scratch.scaling("--dry-run", "compare")     # scripts/scaling.sh in the copy, --output its studies

WORK_DIR is emptied; ROOT (WORK_DIR/root) gets a copy of the checkout's scripts/ and an empty
experiments/scaling/results/, and the studies go in WORK_DIR/studies. scaling.sh runs with a
bare PATH, the test's cic and this Python (which has the packages the test checked for)."""
import pathlib
import shutil
import subprocess
import sys


class Scratch:
    def __init__(self, name):
        self.name = name
        self.source, self.cic, self.work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
        shutil.rmtree(self.work, ignore_errors=True)
        self.work.mkdir(parents=True)
        self.root, self.studies = self.work / "root", self.work / "studies"
        shutil.copytree(self.source / "scripts", self.root / "scripts")
        self.here = self.root / "experiments" / "scaling"
        self.results = self.here / "results"
        self.results.mkdir(parents=True)
        self.env = {"PATH": "/usr/bin:/bin", "CIC": self.cic, "PYTHON": sys.executable}

    def check(self, condition, message):
        if not condition:
            print(f"{self.name}: {message}", file=sys.stderr)
            sys.exit(1)

    def scaling(self, *args, cic=None):
        """scripts/scaling.sh ARGS in the copy, its studies in WORK_DIR/studies; CIC for another cic."""
        env = dict(self.env, CIC=str(cic)) if cic else self.env
        return subprocess.run(["bash", str(self.root / "scripts" / "scaling.sh"), "--output", str(self.studies), *args],
                              capture_output=True, text=True, env=env)
