"""The die-accumulation curve: dies found against coins examined, and its extrapolation.

The curve is the mean, over random orders of the sample's coins, of the number of distinct dies among the
first m coins, with a band (2.5-97.5 % of the orders by default). Its flattening says how close the
sample is to having seen every die.

The extrapolation beyond the n coins examined follows Chao et al. (A. Chao, N. J. Gotelli, T. C. Hsieh
et al., "Rarefaction and extrapolation with Hill numbers", *Ecological Monographs* 84, 2014, 45-67,
eq. for q = 0; also R. K. Colwell et al., *J. Plant Ecology* 5, 2012, 3-21): with ``f0`` the estimated
number of unseen dies (the chosen estimator minus d), ``S(n + m) = d + f0 (1 - (1 - d1 / (n f0 + d1))**m)``,
which rises toward the estimator's value. Written by hand (a one-line formula; scikit-bio has no
extrapolation).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from coindie.numismatics.estimators import DieCounts, Estimate


@dataclass(frozen=True)
class AccumulationCurve:
    """Dies found after m = 1..n coins: mean and band over random orders."""

    coins: NDArray[np.int64]
    mean: NDArray[np.float64]
    low: NDArray[np.float64]
    high: NDArray[np.float64]
    permutations: int


def accumulation_curve(
    counts: DieCounts, permutations: int = 200, band: float = 0.95, seed: int = 0
) -> AccumulationCurve:
    """The curve over ``permutations`` random orders of the coins."""
    rng = np.random.default_rng(seed)
    dies = np.repeat(np.arange(counts.d), counts.array)
    n = counts.n
    found = np.empty((permutations, n), dtype=np.int64)
    for p in range(permutations):
        order = dies[rng.permutation(n)]
        first = np.zeros(n, dtype=np.int64)
        _, first_index = np.unique(order, return_index=True)
        first[first_index] = 1  # a die counts from the first of its coins in this order
        found[p] = np.cumsum(first)
    alpha = (1 - band) / 2
    return AccumulationCurve(
        coins=np.arange(1, n + 1),
        mean=found.mean(axis=0),
        low=np.quantile(found, alpha, axis=0),
        high=np.quantile(found, 1 - alpha, axis=0),
        permutations=permutations,
    )


def extrapolate(counts: DieCounts, estimated: float, extra_coins: NDArray[np.int64]) -> NDArray[np.float64]:
    """Expected dies after ``n + m`` coins (module docstring), for each m of ``extra_coins``."""
    f0 = max(float(estimated) - counts.d, 0.0)
    m = np.asarray(extra_coins, dtype=np.float64)
    if f0 == 0 or counts.d1 == 0:
        return np.full_like(m, float(counts.d))
    return counts.d + f0 * (1 - (1 - counts.d1 / (counts.n * f0 + counts.d1)) ** m)


def plot_accumulation(
    counts: DieCounts,
    estimator: Estimate,
    path: str | Path,
    *,
    title: str = "",
    curve: AccumulationCurve | None = None,
    extend: float = 2.0,
) -> Path:
    """The curve with its band, the extrapolation to ``extend`` times the sample, and the estimator's
    value and interval as a horizontal line and band; SVG / PNG / PDF by the suffix."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    curve = curve or accumulation_curve(counts)
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.fill_between(
        curve.coins,
        curve.low,
        curve.high,
        color="#8c5a2b",
        alpha=0.25,
        lw=0,
        label=f"95 % of {curve.permutations} random orders",
    )
    ax.plot(curve.coins, curve.mean, color="#8c5a2b", lw=1.6, label="dies found (mean)")
    extra = np.arange(0, int(counts.n * (extend - 1)) + 1)
    if estimator.value is not None:
        ax.plot(
            counts.n + extra,
            extrapolate(counts, estimator.value, extra),
            color="#8c5a2b",
            ls="--",
            lw=1.2,
            label=f"extrapolation ({estimator.name})",
        )
        ax.axhline(estimator.value, color="#2b5f8c", lw=1.0, label=f"{estimator.name}: {estimator.value:.1f}")
        if estimator.low is not None and estimator.high is not None and np.isfinite(estimator.high):
            ax.axhspan(
                estimator.low,
                estimator.high,
                color="#2b5f8c",
                alpha=0.12,
                lw=0,
                label=f"its interval {estimator.low:.1f}-{estimator.high:.1f}",
            )
    ax.axvline(counts.n, color="#999999", lw=0.8, ls=":")
    ax.set_xlabel("coins examined")
    ax.set_ylabel("dies found")
    ax.set_title(title or f"Die accumulation: n = {counts.n} coins, d = {counts.d} dies", fontsize=10)
    ax.legend(fontsize=7, loc="lower right")
    ax.set_xlim(0, counts.n * extend)
    ax.set_ylim(0, None)
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path
