#!/usr/bin/env python3
"""Read a cic study into pandas and redraw its fitness curves (docs/analysis.md).

    study_to_pandas.py STUDY_FOLDER OUT.png

Reads STUDY/index.csv (one row per run) and `cic export STUDY` (one row per
individual per saved generation), prints each configuration's median best
fitness of the last generation, and draws the median over seeds of each
generation's best fitness per configuration with its quartiles.
Debian: python3-pandas python3-matplotlib.
"""
import io
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")   # no display needed
import matplotlib.pyplot as plt
import pandas as pd

study, out = sys.argv[1], sys.argv[2]
cic = sys.argv[3] if len(sys.argv) > 3 else "cic"

runs = pd.read_csv(f"{study}/index.csv")
individuals = pd.read_csv(io.StringIO(subprocess.run([cic, "export", study], check=True, capture_output=True,
                                                     text=True).stdout))

# Each run's best individual per generation, then the median over the seeds of a configuration.
best = individuals.groupby(["config", "seed", "generation"])["fitness"].max().reset_index()
curves = best.groupby(["config", "generation"])["fitness"].quantile([0.25, 0.5, 0.75]).unstack()

last = best[best.generation == best.generation.max()].groupby("config")["fitness"].median()
print("median best fitness of the last generation, per configuration:")
for config, value in last.items():
    print(f"  {config}: {value:.6g}  ({(runs.config == config).sum()} runs)")

fig, ax = plt.subplots(figsize=(6, 4))
for config, c in curves.groupby(level="config"):
    c = c.droplevel("config")
    ax.plot(c.index, c[0.5], label=config)
    ax.fill_between(c.index, c[0.25], c[0.75], alpha=0.2)
ax.set_xlabel("generation")
ax.set_ylabel("best fitness (median, quartiles)")
ax.xaxis.get_major_locator().set_params(integer=True)
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=100)
print(f"wrote {out}")
