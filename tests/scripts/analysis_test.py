#!/usr/bin/env python3
"""Analysis.StudyIntoPandas: the example of docs/analysis.md runs on a real
study: a small sweep, `cic export`, examples/analysis/study_to_pandas.py.

    analysis_test.py SOURCE_DIR CIC WORK_DIR
Exit 77 (skipped) without pandas or matplotlib.
"""
import pathlib
import shutil
import subprocess
import sys

source, cic, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
try:
    import matplotlib  # noqa: F401
    import pandas  # noqa: F401
except ImportError as e:
    print(f"analysis_test: skipped: {e}")
    sys.exit(77)
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
(work / "s.xml").write_text(f"""<sweep name="s">
  <base>{source}/settings/symreg_settings.xml</base>
  <output>{work}/study</output>
  <set>Control.maximumIterations=3</set>
  <set>GP.generatedPopulationSize=30</set>
  <grid><vary key="GP.tournament_size">2 5</vary></grid>
  <repeats count="2" firstSeed="1"/>
</sweep>
""")
subprocess.run([cic, "--quiet", "sweep", str(work / "s.xml"), "--jobs", "2"], check=True)
out = subprocess.run([sys.executable, str(source / "examples/analysis/study_to_pandas.py"), str(work / "study"),
                      str(work / "curves.png"), cic], check=True, capture_output=True, text=True).stdout
print(out)
for line in ("tournament_size=2: ", "tournament_size=5: ", "(2 runs)", f"wrote {work / 'curves.png'}"):
    if line not in out:
        print(f"analysis_test: no '{line}' in the output", file=sys.stderr)
        sys.exit(1)
png = (work / "curves.png").read_bytes()
if not png.startswith(b"\x89PNG") or len(png) < 5000:
    print("analysis_test: curves.png is not a drawn PNG", file=sys.stderr)
    sys.exit(1)
shutil.rmtree(work)
