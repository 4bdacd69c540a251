"""The relief classifier reads every stored feature and uses only the ones its model names."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.similarity.classifier import ClassifierError
from coindie.similarity.relief_classifier import USED_FEATURES, ReliefClassifier
from coindie.similarity.relief_features import FEATURE_NAMES
from coindie.similarity.scorers import load_scorer


def _pairs(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Feature rows whose fine correlations separate the dies and whose coarse one is noise."""
    rng = np.random.default_rng(seed)
    same = rng.random(n) < 0.3
    X = np.empty((n, len(FEATURE_NAMES)))
    X[:, 0] = np.where(same, 0.6, 0.2) + 0.1 * rng.standard_normal(n)  # ncc_fine
    X[:, 1] = 0.5 + 0.3 * rng.standard_normal(n)  # ncc_coarse: the type, not the die
    X[:, 2] = X[:, 0] - 0.05 + 0.05 * rng.standard_normal(n)  # local_median
    X[:, 3] = X[:, 0] + 0.1 + 0.05 * rng.standard_normal(n)  # local_p90
    X[:, 4] = rng.uniform(0.7, 1.0, n)  # overlap
    return np.clip(X, -0.99, 0.99), same


def test_a_new_model_leaves_the_coarse_band_out_and_separates_the_dies() -> None:
    X, same = _pairs(400, 0)
    model = ReliefClassifier().fit(X, same)
    assert model.used == USED_FEATURES and "ncc_coarse" not in model.used
    assert model.coef is not None and model.coef.shape == (len(USED_FEATURES),)
    test, truth = _pairs(400, 1)
    p = model.predict_proba(test)
    assert np.mean((p > 0.5) == truth) > 0.95
    moved = test.copy()
    moved[:, FEATURE_NAMES.index("ncc_coarse")] = 0.99  # whatever the coarse band says
    np.testing.assert_array_equal(model.predict_proba(moved), p)


def test_the_used_features_round_trip_and_an_older_file_uses_all_five(tmp_path: Path) -> None:
    X, same = _pairs(300, 2)
    model = ReliefClassifier(used=("ncc_fine", "overlap")).fit(X, same)
    again = load_scorer(model.save(tmp_path / "model.json"))
    assert isinstance(again, ReliefClassifier)
    assert again.used == ("ncc_fine", "overlap")
    np.testing.assert_allclose(again.predict_proba(X), model.predict_proba(X), rtol=1e-12)
    # a model file written before the choice existed: its five coefficients are the five features
    old = ReliefClassifier(used=FEATURE_NAMES).fit(X, same).to_dict()
    del old["used_features"]
    loaded = ReliefClassifier.from_dict(old)
    assert loaded.used == FEATURE_NAMES
    old["coef"] = old["coef"][:4]
    with pytest.raises(ClassifierError, match="5 values"):
        ReliefClassifier.from_dict(old, "old.json")


def test_unknown_or_repeated_features_are_refused() -> None:
    with pytest.raises(ParameterError, match="used"):
        ReliefClassifier(used=("ncc_fine", "ncc_fine"))
    with pytest.raises(ParameterError, match="used"):
        ReliefClassifier(used=("sharpness",))
    bad = ReliefClassifier().fit(*_pairs(200, 3)).to_dict()
    bad["used_features"] = ["ncc_fine", "residual_mm"]
    with pytest.raises(ClassifierError, match="not a usable relief classifier"):
        ReliefClassifier.from_dict(json.loads(json.dumps(bad)), "bad.json")
