"""The statistics every study report shares (walk-report.py, qd-report.py):
quartiles, Vargha-Delaney A12 with a bootstrap interval, the two-sided
Mann-Whitney p (scipy, as `cic compare`) and Holm's step-down adjustment."""
import random
import statistics as st


def quartiles(v):
    q = st.quantiles(v, n=4, method="inclusive") if len(v) > 1 else [v[0]] * 3
    return q[0], q[2]


def a12(x, y):
    return sum(1 if a > b else 0.5 if a == b else 0 for a in x for b in y) / (len(x) * len(y))


def a12_interval(x, y, resamples=2000):
    rng = random.Random(1)
    values = sorted(a12([rng.choice(x) for _ in x], [rng.choice(y) for _ in y]) for _ in range(resamples))
    return values[int(0.025 * resamples)], values[int(0.975 * resamples) - 1]


def mann_whitney_p(x, y):
    try:
        from scipy.stats import mannwhitneyu
    except ImportError:
        return None
    return float(mannwhitneyu(x, y, alternative="two-sided").pvalue)


def holm(ps):
    """Holm's step-down adjustment of a list of p-values (None stays None)."""
    order = sorted((p, i) for i, p in enumerate(ps) if p is not None)
    out, running = [None] * len(ps), 0.0
    for rank, (p, i) in enumerate(order):
        running = max(running, min(1.0, (len(order) - rank) * p))
        out[i] = running
    return out
