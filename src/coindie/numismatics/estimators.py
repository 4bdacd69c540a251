"""How many dies there were: estimators of the original number of dies from the observed die frequencies.

The data are the number of coins (faces of one side) each observed die struck in the sample: ``n`` coins,
``d`` dies, ``d1`` dies seen once (singletons), ``d2`` seen twice (doubletons). Every estimator here comes
with an interval (95 % by default) and a line saying where its formula comes from.

Sources, and what is by hand:

- Good's coverage ``C = 1 - d1/n`` and ``D = d / C``: I. J. Good, "The population frequencies of species and
  the estimation of population parameters", *Biometrika* 40 (1953) 237-264. scikit-bio's
  ``goods_coverage`` computes C (checked against hand values in the tests).
- Esty's coverage interval: W. W. Esty, "A normal limit law for a nonparametric estimator of the coverage
  of a random sample", *Annals of Statistics* 11 (1983) 905-912, used for die studies in W. W. Esty,
  "Estimation of the size of a coinage: a survey and comparison of methods", *Numismatic Chronicle* 146
  (1986) 185-215. scikit-bio's ``esty_ci`` gives the interval of the uncovered share ``d1/n``; the die
  estimate's interval is ``d / C`` at both ends of the coverage interval (by hand: a division).
- The geometric model: W. W. Esty, "The geometric model for estimating the number of dies", in
  F. de Callatay (ed.), *Quantifying monetary supplies in Greco-Roman times* (Bari, 2011) 43-58. The
  model: each die's number of coins in the sample is geometric, ``P(r) = (1 - q) q**r`` (dies that break
  at a constant rate, hence exponential outputs). Its estimate follows from the model by the method of
  moments: the observed dies' mean ``n/d = 1/(1 - q)``, so ``q = 1 - d/n`` and ``D = d/q = n d / (n - d)``.
  The same formula is stated, as the estimate for an exponential die-frequency distribution (a constant
  breakage rate), in D. Hamilton's notes "Estimating die numbers" / "Numbered die issues" (glebecoins.net).
  We could not consult Esty's printed interval; the interval here is a parametric bootstrap under the same
  fitted model (written by hand: no library has it).
- Chao1, bias-corrected, ``D = d + d1 (d1 - 1) / (2 (d2 + 1))``, with its log-normal interval: A. Chao,
  "Nonparametric estimation of the number of classes in a population", *Scand. J. Statistics* 11 (1984)
  265-270, and "Estimating the population size for capture-recapture data with unequal catchability",
  *Biometrics* 43 (1987) 783-791; variance and interval as in the EstimateS manual (R. K. Colwell),
  equations 6 and 13. scikit-bio's ``chao1`` / ``chao1_ci``.
- ACE: A. Chao and S.-M. Lee, "Estimating the number of classes via sample coverage", *JASA* 87 (1992)
  210-217, rare dies those with at most 10 coins. scikit-bio's ``ace``. No library gives its interval: a
  bootstrap variance of the coins (resampled with replacement) with Chao's log-normal interval (by hand).
- Carter: G. F. Carter, "A simplified method for calculating the original number of dies from die link
  statistics", *ANS Museum Notes* 28 (1983) 195-206. We could not source its coefficients from a
  published statement we could read, so it is **not computed**: :func:`estimate` lists it with that
  reason rather than a guessed formula.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import asdict, dataclass, field

import numpy as np
from numpy.typing import NDArray
from scipy.stats import norm

from coindie.errors import ParameterError
from coindie.params import Configurable, param

#: Dies with at most this many coins are "rare" in ACE (Chao and Lee 1992; EstimateS' default).
ACE_RARE_THRESHOLD = 10
#: Bootstrap replicates of the intervals computed by resampling.
BOOTSTRAP_REPLICATES = 1000


@dataclass(frozen=True)
class Estimate:
    """One estimator's value and interval; ``value`` is None (with ``note``) when it cannot be computed."""

    name: str
    value: float | None
    low: float | None
    high: float | None
    source: str
    note: str = ""

    def to_dict(self) -> dict[str, object]:
        """As a dictionary; an infinite bound becomes the string ``"inf"`` (JSON has no infinity)."""
        return {k: "inf" if isinstance(v, float) and math.isinf(v) else v for k, v in asdict(self).items()}


@dataclass(frozen=True)
class DieCounts(Configurable):
    """The die frequencies of one side: n coins, d dies, d1 singletons, d2 doubletons."""

    counts: tuple[int, ...] = param(
        kind=tuple,
        doc="coins of each die (the estimators need at least one die)",
        item=int,
        low=1,
        min_length=1,
    )
    n: int = field(init=False)
    d: int = field(init=False)
    d1: int = field(init=False)
    d2: int = field(init=False)

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "n", int(sum(self.counts)))
        object.__setattr__(self, "d", len(self.counts))
        object.__setattr__(self, "d1", sum(1 for c in self.counts if c == 1))
        object.__setattr__(self, "d2", sum(1 for c in self.counts if c == 2))

    @classmethod
    def from_labels(cls, labels: Mapping[str, object]) -> DieCounts:
        """Counts of coins per die from ``face -> die``."""
        sizes: dict[str, int] = {}
        for die in labels.values():
            sizes[str(die)] = sizes.get(str(die), 0) + 1
        return cls(tuple(sorted(sizes.values(), reverse=True)))

    @property
    def array(self) -> NDArray[np.int64]:
        return np.asarray(self.counts, dtype=np.int64)


@dataclass(frozen=True)
class Estimates:
    """Everything :func:`estimate` says about one side."""

    counts: DieCounts
    coverage: Estimate
    estimators: tuple[Estimate, ...]
    confidence: float

    def to_dict(self) -> dict[str, object]:
        c = self.counts
        return {
            "n": c.n,
            "d": c.d,
            "d1": c.d1,
            "d2": c.d2,
            "confidence": self.confidence,
            "coverage": self.coverage.to_dict(),
            "estimators": [e.to_dict() for e in self.estimators],
        }

    def get(self, name: str) -> Estimate:
        for e in self.estimators:
            if e.name == name:
                return e
        raise KeyError(name)


def _z(confidence: float) -> float:
    if not 0 < confidence < 1:
        raise ParameterError(f"the confidence level must be in (0, 1), got {confidence}")
    return float(norm.ppf(0.5 + confidence / 2))


def _counts(counts: DieCounts | Iterable[int]) -> DieCounts:
    return counts if isinstance(counts, DieCounts) else DieCounts(tuple(int(c) for c in counts))


def goods_coverage(counts: DieCounts | Iterable[int], confidence: float = 0.95) -> Estimate:
    """Good's (1953) coverage ``C = 1 - d1/n`` with Esty's (1983) normal interval.

    Esty's standard error of ``d1/n`` is ``sqrt((d1 (n - d1) + 2 n d2) / n**3)``; the interval of C is
    ``1 - (d1/n +- z se)``, clipped to [0, 1]. scikit-bio computes C (``goods_coverage``) and, at 95 %,
    the interval of ``d1/n`` (``esty_ci``); at another level the same formula is applied here.
    """
    from skbio.diversity.alpha import esty_ci
    from skbio.diversity.alpha import goods_coverage as skbio_goods

    c = _counts(counts)
    value = float(skbio_goods(c.array))
    if math.isclose(confidence, 0.95):
        low_miss, high_miss = (float(v) for v in esty_ci(c.array))
    else:  # esty_ci is fixed at z = 1.96
        se = math.sqrt((c.d1 * (c.n - c.d1) + 2 * c.n * c.d2) / c.n**3)
        low_miss, high_miss = c.d1 / c.n - _z(confidence) * se, c.d1 / c.n + _z(confidence) * se
    return Estimate(
        "coverage (Good 1953, Esty 1983 interval)",
        value,
        float(np.clip(1 - high_miss, 0, 1)),
        float(np.clip(1 - low_miss, 0, 1)),
        "Good (1953) C = 1 - d1/n; Esty (1983) normal interval",
    )


def good_estimate(counts: DieCounts | Iterable[int], confidence: float = 0.95) -> Estimate:
    """Good's ``D = d / C`` (Esty 1986's coverage estimate), its interval ``d / C`` at the ends of Esty's
    coverage interval (infinite when the coverage's lower end is 0)."""
    c = _counts(counts)
    cov = goods_coverage(c, confidence)
    if c.d1 == c.n:
        return Estimate(
            "Good / Esty 1986 (d/C)",
            None,
            None,
            None,
            "Good (1953); Esty (1986)",
            "every die is a singleton: the coverage is 0 and d/C is infinite",
        )
    high = math.inf if not cov.low else c.d / cov.low
    return Estimate(
        "Good / Esty 1986 (d/C)",
        c.d / float(cov.value or 1.0),
        c.d / float(cov.high or 1.0),
        high,
        "Good (1953) D = d/C; interval from Esty's (1983) coverage interval (Esty 1986)",
    )


def geometric_estimate(
    counts: DieCounts | Iterable[int],
    confidence: float = 0.95,
    replicates: int = BOOTSTRAP_REPLICATES,
    seed: int = 0,
) -> Estimate:
    """The geometric model's ``D = n d / (n - d)`` (Esty 2011's model; the estimate by the method of
    moments, see the module's docstring) with a parametric-bootstrap percentile interval.

    The bootstrap (by hand: no library fits this model) draws ``round(D)`` dies, each with a geometric
    number of coins of parameter ``q = 1 - d/n``, keeps the dies seen at least once, and estimates again.
    """
    c = _counts(counts)
    source = "Esty (2011) geometric model; D = nd/(n - d); parametric bootstrap interval"
    if c.n == c.d:
        return Estimate(
            "geometric model (Esty 2011)",
            None,
            None,
            None,
            source,
            "every die is a singleton: n = d and the model's D is infinite",
        )
    value = c.n * c.d / (c.n - c.d)
    q = 1 - c.d / c.n
    rng = np.random.default_rng(seed)
    # numpy's geometric counts trials to the first success (>= 1): minus one is the number of coins.
    draws = rng.geometric(1 - q, size=(replicates, max(1, round(value)))) - 1
    n_star, d_star = draws.sum(axis=1), (draws > 0).sum(axis=1)
    ok = n_star > d_star
    again = n_star[ok] * d_star[ok] / (n_star[ok] - d_star[ok])
    alpha = 1 - confidence
    low, high = (float(v) for v in np.quantile(again, [alpha / 2, 1 - alpha / 2]))
    return Estimate("geometric model (Esty 2011)", value, max(low, float(c.d)), high, source)


def chao1_estimate(counts: DieCounts | Iterable[int], confidence: float = 0.95) -> Estimate:
    """Chao1 bias-corrected ``d + d1 (d1 - 1) / (2 (d2 + 1))`` (Chao 1984, 1987) with the log-normal
    interval (EstimateS eqs 6 and 13), by scikit-bio."""
    from skbio.diversity.alpha import chao1, chao1_ci

    c = _counts(counts)
    low, high = chao1_ci(c.array, bias_corrected=True, zscore=_z(confidence))
    return Estimate(
        "Chao1 (bias-corrected)",
        float(chao1(c.array, bias_corrected=True)),
        float(low),
        float(high),
        "Chao (1984, 1987); log-normal interval (EstimateS eqs 6, 13); scikit-bio",
    )


def ace_estimate(
    counts: DieCounts | Iterable[int],
    confidence: float = 0.95,
    rare_threshold: int = ACE_RARE_THRESHOLD,
    replicates: int = BOOTSTRAP_REPLICATES,
    seed: int = 0,
) -> Estimate:
    """ACE (Chao and Lee 1992), by scikit-bio, with a log-normal interval around a bootstrap variance.

    The interval is by hand (no library has it): the n coins are resampled with replacement from the
    observed dies, ACE is computed on each replicate, and its variance goes into Chao's (1987) log-normal
    interval ``d + T/K .. d + T K``, ``T = ACE - d``, ``K = exp(z sqrt(log(1 + var / T**2))))``.
    """
    from skbio.diversity.alpha import ace

    c = _counts(counts)
    source = "Chao and Lee (1992); scikit-bio; bootstrap variance, log-normal interval"
    name = "ACE"
    try:
        value = float(ace(c.array, rare_threshold=rare_threshold))
    except ValueError:  # every rare die is a singleton: ACE's coverage is 0
        return Estimate(name, None, None, None, source, "every rare die is a singleton: ACE is undefined")
    rng = np.random.default_rng(seed)
    draws = rng.multinomial(c.n, c.array / c.n, size=replicates)
    values = []
    for row in draws:
        row = row[row > 0]
        try:
            values.append(float(ace(row, rare_threshold=rare_threshold)))
        except ValueError:
            continue
    t = value - c.d
    if t <= 0 or len(values) < 2:
        return Estimate(name, value, float(c.d), value, source)
    k = math.exp(_z(confidence) * math.sqrt(math.log(1 + float(np.var(values, ddof=1)) / t**2)))
    return Estimate(name, value, c.d + t / k, c.d + t * k, source)


def carter_estimate(counts: DieCounts | Iterable[int], confidence: float = 0.95) -> Estimate:
    """Carter (1983): listed, not computed; its coefficients could not be sourced (module docstring)."""
    return Estimate(
        "Carter (1983)",
        None,
        None,
        None,
        "Carter, ANS Museum Notes 28 (1983) 195-206",
        "not computed: the formula's coefficients could not be sourced from a published statement",
    )


def estimate(counts: DieCounts | Iterable[int], confidence: float = 0.95, seed: int = 0) -> Estimates:
    """Coverage and every estimator for one side's die frequencies (coins per die)."""
    c = _counts(counts)
    return Estimates(
        counts=c,
        coverage=goods_coverage(c, confidence),
        estimators=(
            good_estimate(c, confidence),
            geometric_estimate(c, confidence, seed=seed),
            chao1_estimate(c, confidence),
            ace_estimate(c, confidence, seed=seed),
            carter_estimate(c, confidence),
        ),
        confidence=confidence,
    )
