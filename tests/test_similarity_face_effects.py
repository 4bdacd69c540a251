"""Each face's pull on its scores: fitted on the pairs across a first clustering, taken off the log-odds."""

from __future__ import annotations

import numpy as np
from sklearn.metrics import roc_auc_score

from coindie.similarity.face_effects import face_effects, without_face_effects, without_face_effects_across


def _hoard(sizes: list[int], seed: int, pull_sd: float = 1.5) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Every pair of a side: log-odds = face i's pull + face j's pull + 3 (same die) + noise."""
    rng = np.random.default_rng(seed)
    die = np.repeat(np.arange(len(sizes)), sizes)
    n = len(die)
    pull = rng.normal(0.0, pull_sd, n)
    i, j = np.triu_indices(n, k=1)
    same = die[i] == die[j]
    log_odds = -3.0 + pull[i] + pull[j] + 3.0 * same + rng.normal(0.0, 0.7, len(i))
    return {"i": i, "j": j, "same": same, "die": die, "log_odds": log_odds}, pull


def _probability(log_odds: np.ndarray) -> np.ndarray:
    return 1.0 / (1.0 + np.exp(-log_odds))


def test_the_pulls_are_recovered_from_the_pairs_across_the_dies() -> None:
    pairs, pull = _hoard([12, 10, 8, 6, 4], seed=0)
    across = ~pairs["same"]
    a = face_effects(pairs["log_odds"], pairs["i"], pairs["j"], across, len(pull))
    # centred on the median face: compare up to a constant
    error = (a - np.median(a)) - (pull - np.median(pull))
    assert np.median(np.abs(error)) < 0.3 < np.std(pull)


def test_taking_the_pulls_off_separates_same_die_pairs_better() -> None:
    for seed in range(4):
        pairs, _ = _hoard([12, 10, 8, 6, 4], seed=seed)
        p = _probability(pairs["log_odds"])
        valid = np.ones(len(p), dtype=bool)
        before = roc_auc_score(pairs["same"], p)
        after = roc_auc_score(
            pairs["same"], without_face_effects(p, valid, pairs["i"], pairs["j"], ~pairs["same"])
        )
        assert after > before + 0.05


def test_a_die_holding_half_the_faces_is_not_pulled_down_when_fitted_across_clusters() -> None:
    """Fitted on all its pairs, a face of a die with half the hoard takes its same-die pairs for its
    typical pair; fitted across a first clustering (here a noisy one: a tenth of the faces misplaced),
    its same-die pairs keep most of their lead."""
    pairs, _ = _hoard([30, 8, 6, 4, 2], seed=1, pull_sd=0.5)
    p = _probability(pairs["log_odds"])
    valid = np.ones(len(p), dtype=bool)
    rng = np.random.default_rng(1)
    first = pairs["die"].copy()
    moved = rng.choice(len(first), size=len(first) // 10, replace=False)
    first[moved] = rng.integers(0, 5, len(moved))
    names = [f"L{k:04d}D" for k in range(len(first))]
    sources, targets = [names[k] for k in pairs["i"]], [names[k] for k in pairs["j"]]
    across = without_face_effects_across(p, valid, sources, targets, dict(zip(names, first, strict=True)))
    everything = without_face_effects(p, valid, pairs["i"], pairs["j"], valid)
    big = pairs["same"] & (pairs["die"][pairs["i"]] == 0)
    assert np.median(across[big]) > np.median(everything[big]) + 0.1
    assert roc_auc_score(pairs["same"], across) > roc_auc_score(pairs["same"], everything) + 0.1


def test_refused_pairs_keep_their_probability_and_few_pairs_give_no_pull() -> None:
    p = np.array([0.2, 0.9, 0.0, 0.4])
    valid = np.array([True, True, False, True])
    out = without_face_effects(p, valid, np.array([0, 0, 1, 2]), np.array([1, 2, 2, 3]), valid)
    assert out[2] == 0.0
    np.testing.assert_allclose(out[valid], p[valid])  # no face has MIN_PAIRS pairs: nothing taken off
