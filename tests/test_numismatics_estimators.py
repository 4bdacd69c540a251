"""The estimators of the original number of dies: hand-computed cases, published figures, simulations."""

from __future__ import annotations

import math

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.numismatics.accumulation import accumulation_curve, extrapolate, plot_accumulation
from coindie.numismatics.estimators import (
    DieCounts,
    ace_estimate,
    chao1_estimate,
    estimate,
    geometric_estimate,
    good_estimate,
    goods_coverage,
)

# 23 coins of 8 dies: d1 = 3, d2 = 2.
SMALL = (1, 1, 1, 2, 2, 3, 5, 8)


def test_counts_are_n_d_d1_d2() -> None:
    c = DieCounts(SMALL)
    assert (c.n, c.d, c.d1, c.d2) == (23, 8, 3, 2)
    assert DieCounts.from_labels({"a": "1", "b": "1", "c": "2"}).counts == (2, 1)
    with pytest.raises(ParameterError):
        DieCounts(())


def test_good_on_the_published_example_318_coins_69_dies_12_singletons() -> None:
    # 12 singletons and 57 dies sharing the other 306 coins (21 x 6 + 36 x 5): only n, d, d1 matter.
    counts = [1] * 12 + [6] * 21 + [5] * 36
    c = DieCounts(counts)
    assert (c.n, c.d, c.d1) == (318, 69, 12)
    assert round(good_estimate(c).value, 1) == 71.7
    assert goods_coverage(c).value == pytest.approx(1 - 12 / 318)


def test_esty_interval_by_hand() -> None:
    n, d1, d2, d = 23, 3, 2, 8
    se = math.sqrt((d1 * (n - d1) + 2 * n * d2) / n**3)
    cov = goods_coverage(SMALL)
    assert cov.low == pytest.approx(1 - (d1 / n + 1.959964 * se), abs=1e-4)
    assert cov.high == pytest.approx(min(1.0, 1 - (d1 / n - 1.959964 * se)), abs=1e-4)
    good = good_estimate(SMALL)
    assert good.value == pytest.approx(d / (1 - d1 / n))
    assert good.low == pytest.approx(d / cov.high) and good.high == pytest.approx(d / cov.low)
    # another confidence level uses the same formula with its z
    narrow = goods_coverage(SMALL, confidence=0.8)
    assert narrow.low == pytest.approx(1 - (d1 / n + 1.281552 * se), abs=1e-4)


def test_rrc_361_1_coverage_estimate_is_a_lower_bound_of_the_attested_dies() -> None:
    """RRC 361/1 (ANS, sequential die marks): 412 obverse dies observed at a coverage of 98.4 %, while the
    control marks attest 487-488 dies. A sample with those two figures (n = 1000 coins, d1 = 16) gives
    Good's d/C = 412 / 0.984 = 418.7. What we check: (1) the code reproduces d/C from d and C; (2) it lies
    between d and the attested count, its interval too: Good's C is the share of the *coins* struck by the
    dies seen, so with unequal dies d/C underestimates; the 76 dies never seen struck at most 1.6 % of the
    coinage, i.e. on average about a tenth of an observed die's output (0.016/76 vs 0.984/412)."""
    counts = [1] * 16 + [3] * 192 + [2] * 204
    c = DieCounts(counts)
    assert (c.d, c.n) == (412, 1000)
    cov, good = goods_coverage(c), good_estimate(c)
    assert cov.value == pytest.approx(0.984)
    assert good.value == pytest.approx(412 / 0.984) and round(good.value, 1) == 418.7
    assert c.d <= good.low <= good.value <= good.high < 487  # the upper coverage is clipped at 1: low = d
    missing_share_per_die = (1 - cov.value) / (488 - 412)
    seen_share_per_die = cov.value / 412
    assert missing_share_per_die / seen_share_per_die == pytest.approx(0.088, abs=0.002)


def test_chao1_bias_corrected_and_its_log_normal_interval_by_hand() -> None:
    d, d1, d2 = 8, 3, 2
    value = d + d1 * (d1 - 1) / (2 * (d2 + 1))
    var = (d1 * (d1 - 1) / (2 * (d2 + 1)) + d1 * (2 * d1 - 1) ** 2 / (4 * (d2 + 1) ** 2)
           + d1**2 * d2 * (d1 - 1) ** 2 / (4 * (d2 + 1) ** 4))  # fmt: skip
    t = value - d
    k = math.exp(1.959964 * math.sqrt(math.log(1 + var / t**2)))
    chao = chao1_estimate(SMALL)
    assert chao.value == pytest.approx(9.0)
    assert chao.low == pytest.approx(d + t / k, rel=1e-5) and chao.high == pytest.approx(d + t * k, rel=1e-5)


def test_ace_by_hand() -> None:
    # rare dies (<= 10 coins): 1, 1, 2, 3, 4 -> S_rare 5, N_rare 11, F1 2, C = 9/11; one abundant die (12).
    c_ace = 1 - 2 / 11
    gamma = max(5 / c_ace * (2 * 1 + 3 * 2 + 4 * 3) / (11 * 10) - 1, 0)
    expected = 1 + 5 / c_ace + 2 / c_ace * gamma
    ace = ace_estimate([1, 1, 2, 3, 4, 12])
    assert ace.value == pytest.approx(expected)
    assert ace.low <= ace.value <= ace.high


def test_geometric_model_by_hand_and_on_geometric_samples() -> None:
    geo = geometric_estimate(SMALL)
    assert geo.value == pytest.approx(23 * 8 / (23 - 8))
    assert 8 <= geo.low <= geo.value <= geo.high
    # 300 dies whose sample counts are geometric with q = 0.6: the estimate finds them (within its noise)
    rng = np.random.default_rng(1)
    hits = 0
    for _ in range(20):
        draws = rng.geometric(0.4, size=300) - 1
        est = geometric_estimate(draws[draws > 0], replicates=300)
        hits += est.low <= 300 <= est.high
    assert hits >= 15  # a 95 % interval: at least 15 of 20 (binomial 5th percentile is 17)


def test_good_is_close_to_the_truth_when_dies_are_equal() -> None:
    rng = np.random.default_rng(2)
    values = []
    for _ in range(100):
        sample = np.bincount(rng.integers(0, 100, size=250), minlength=100)
        values.append(good_estimate(sample[sample > 0]).value)
    assert np.mean(values) == pytest.approx(100, rel=0.03)


def test_every_singleton_and_carter_are_reported_not_invented() -> None:
    result = estimate([1, 1, 1])
    assert result.get("Good / Esty 1986 (d/C)").value is None
    assert result.get("geometric model (Esty 2011)").value is None
    carter = result.get("Carter (1983)")
    assert carter.value is None and "could not be sourced" in carter.note
    assert result.to_dict()["n"] == 3
    # one doubleton and many singletons: the coverage interval reaches 0, d/C's upper end is unbounded
    wide = good_estimate([1] * 9 + [2])
    assert wide.high == math.inf and wide.to_dict()["high"] == "inf"


def test_accumulation_curve_and_extrapolation(tmp_path) -> None:
    c = DieCounts(SMALL)
    curve = accumulation_curve(c, permutations=100)
    assert curve.mean[0] == 1 and curve.mean[-1] == c.d
    assert (
        np.all(np.diff(curve.mean) >= 0)
        and np.all(curve.low <= curve.mean)
        and np.all(curve.mean <= curve.high)
    )
    chao = chao1_estimate(c)
    far = extrapolate(c, chao.value, np.array([0, 10, 10_000]))
    assert far[0] == c.d and c.d < far[1] < chao.value and far[2] == pytest.approx(chao.value, abs=1e-6)
    path = plot_accumulation(c, chao, tmp_path / "curve.svg", curve=curve)
    assert path.read_text().lstrip().startswith("<?xml")
