"""The same-die classifier: separation, calibration, JSON round-trip, the paper's scaler."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.similarity import ClassifierError, HistogramSettings, SameDieClassifier
from real_data import real_file

CENTRES = (np.arange(70) + 0.5) * 0.6 / 70


def _histograms(n: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Density histograms of gamma-like distances: same-die pairs peak near 0.03 mm, other pairs near
    0.06-0.12 mm, with overlap, so that the classes are not separable and calibration matters."""
    same = rng.random(n) < 0.3
    peak = np.where(same, rng.normal(0.035, 0.012, n), rng.normal(0.08, 0.025, n)).clip(0.01)
    H = (CENTRES[None, :] / peak[:, None]) ** 2 * np.exp(-2 * CENTRES[None, :] / peak[:, None])
    H += rng.gamma(2.0, 0.002, H.shape)
    H /= H.sum(axis=1, keepdims=True) * (0.6 / 70)
    return H, same


@pytest.fixture(scope="module")
def fitted() -> SameDieClassifier:
    H, same = _histograms(3000, np.random.default_rng(0))
    return SameDieClassifier().fit(H, same)


def test_separates_same_die_pairs(fitted: SameDieClassifier) -> None:
    from sklearn.metrics import roc_auc_score

    H, same = _histograms(2000, np.random.default_rng(1))
    p = fitted.predict_proba(H)
    assert p.shape == (2000,) and np.all((p >= 0) & (p <= 1))
    assert roc_auc_score(same, p) > 0.9


def test_probabilities_are_calibrated(fitted: SameDieClassifier) -> None:
    H, same = _histograms(6000, np.random.default_rng(2))
    p = fitted.predict_proba(H)
    bins = np.clip((p * 10).astype(int), 0, 9)
    # Expected calibration error: per decile of predictions, |observed frequency - mean prediction|,
    # weighted by the decile's share of pairs.
    ece = sum(np.mean(bins == b) * abs(same[bins == b].mean() - p[bins == b].mean()) for b in np.unique(bins))
    assert ece < 0.03
    assert abs(p.mean() - same.mean()) < 0.02


def test_save_and_load_round_trip(fitted: SameDieClassifier, tmp_path: Path) -> None:
    path = fitted.save(tmp_path / "model.json")
    data = json.loads(path.read_text())
    assert data["version"] == 1 and len(data["coef"]) == 70 and data["settings"]["bins"] == 70
    loaded = SameDieClassifier.load(path)
    H, _ = _histograms(50, np.random.default_rng(3))
    np.testing.assert_array_equal(loaded.predict_proba(H), fitted.predict_proba(H))
    assert loaded.settings == fitted.settings


def test_the_papers_scaler_imports_and_stays_fixed() -> None:
    path = real_file("histogram_scaler.json")
    raw = json.loads(path.read_text())
    model = SameDieClassifier.from_paper_scaler(path)
    assert model.mean is not None and model.mean.shape == (70,)
    # The authors' mean sums to 70 (a density over a unit range); in our units it integrates to 1 over
    # 0-0.6 mm, the std scaled alike: the standardised values are the paper's.
    assert np.sum(model.mean) * 0.6 / 70 == pytest.approx(1.0)
    h = np.asarray(raw["mean"]) * 0.5 + 0.1
    ours = h / 0.6
    np.testing.assert_allclose(
        (ours - model.mean) / model.std, (h - np.asarray(raw["mean"])) / 1.72, atol=1e-4
    )
    # It peaks around 0.03 mm, the residual distance of aligned real scans.
    assert 0.02 <= CENTRES[np.argmax(model.mean)] <= 0.05
    mean = model.mean.copy()
    H, same = _histograms(600, np.random.default_rng(4))
    model.fit(H, same)
    np.testing.assert_array_equal(model.mean, mean)
    assert model.std == pytest.approx(1.72 / 0.6, rel=1e-4)


def test_unfitted_and_bad_inputs_are_refused(tmp_path: Path) -> None:
    with pytest.raises(ClassifierError, match="not fitted"):
        SameDieClassifier().predict_proba(np.zeros((1, 70)))
    with pytest.raises(ParameterError, match="both"):
        SameDieClassifier().fit(np.zeros((4, 70)), [True] * 4)
    with pytest.raises(ParameterError, match=r"\(n, 70\)"):
        SameDieClassifier().fit(np.zeros((4, 10)), [True, False] * 2)
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "something else"}')
    with pytest.raises(ClassifierError, match="bad.json"):
        SameDieClassifier.load(bad)
    with pytest.raises(ClassifierError, match="no such"):
        SameDieClassifier.load(tmp_path / "missing.json")
    scaler = tmp_path / "scaler.json"
    scaler.write_text('{"mean": [1, 2], "std": 1.0}')
    with pytest.raises(ClassifierError, match="70 finite means"):
        SameDieClassifier.from_paper_scaler(scaler)


def test_settings_travel_with_the_model(tmp_path: Path) -> None:
    settings = HistogramSettings.authors_code(symmetric=True)
    H, same = _histograms(300, np.random.default_rng(5))
    model = SameDieClassifier(settings=settings).fit(H, same)
    assert SameDieClassifier.load(model.save(tmp_path / "m.json")).settings == settings
