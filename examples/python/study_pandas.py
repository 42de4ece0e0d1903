#!/usr/bin/python3
"""A study read into pandas and plotted with matplotlib: median best-so-far per configuration.

    /usr/bin/python3 examples/python/study_pandas.py STUDY_FOLDER [OUT.png]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import cic

if len(sys.argv) < 2:
    sys.exit(__doc__)
study = cic.read_study(sys.argv[1])
out = sys.argv[2] if len(sys.argv) > 2 else "study.png"
print(study)
print(study.index.groupby("config")["best_ever"].median().rename("median best_ever").to_string())

stats = study.stats.copy()
stats["best_so_far"] = stats.groupby(["config", "seed"])["best"].cummax()
curves = stats.groupby(["config", "evaluations"])["best_so_far"].median().unstack(0)
ax = curves.plot(drawstyle="steps-post")
ax.set_xlabel("evaluations")
ax.set_ylabel("best so far (median over seeds)")
ax.set_title(study.folder)
plt.savefig(out, dpi=100, bbox_inches="tight")
print(f"wrote {out}")
