"""The ``relief`` same-die scorer: a calibrated logistic regression on the scale-free relief features.

Its input is :data:`coindie.similarity.relief_features.FEATURE_NAMES` of a registered pair: correlations,
taken to Fisher's z (``atanh``, which makes a correlation's sampling spread nearly constant), and the
overlap share. Each is standardised by its training mean and standard deviation, then an L2 logistic
regression with Platt calibration (:mod:`coindie.similarity.logistic`) gives the probability.

The model also keeps the distribution of its calibrated log-odds over the training pairs of each class:
the starting point of the per-hoard calibration (:mod:`coindie.similarity.calibration`), which then
re-estimates both populations from a new hoard's own pairs. Stored as JSON, never a pickle.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike

from coindie.arrays import FloatArray
from coindie.errors import ParameterError
from coindie.params import Configurable, Rule, param
from coindie.similarity.classifier import ClassifierError, checked_rows, write_model
from coindie.similarity.histogram import HistogramSettings
from coindie.similarity.logistic import fit_platt_logistic, sigmoid
from coindie.similarity.relief_features import FEATURE_NAMES, ReliefFeatureSettings

FORMAT = "coindie.relief_classifier"
FORMAT_VERSION = 1
#: The shipped default model, inside the package.
DEFAULT_MODEL = "relief_classifier.json"
#: Correlations are clipped to this before Fisher's z (a perfect copy would give infinity).
_MAX_CORRELATION = 0.999
#: The features a new model is fitted on. ``ncc_coarse`` (the 0.3-1 mm band) is measured and stored but
#: left out: dies of one type share their design at that scale (they differ by where the engraver put
#: each stroke, 0.1-0.2 mm), so it tells the type, not the die, and its weight made a worn or coarsely
#: scanned pair of one die look like two dies (BENCHMARK.md, "The coarse band leaves the scorer").
USED_FEATURES = ("ncc_fine", "local_median", "local_p90", "overlap")


@dataclass
class ReliefClassifier(Configurable):
    """Probability that two registered faces were struck by the same die, from their relief features."""

    NAME: ClassVar[str] = "relief"
    OWNER: ClassVar[str] = "ReliefClassifier"
    INPUT: ClassVar[str] = "features"
    RULES: ClassVar[tuple[Rule, ...]] = (
        Rule(
            ("used",),
            lambda m: (
                len(m.used) > 0
                and len(set(m.used)) == len(m.used)
                and all(name in FEATURE_NAMES for name in m.used)
            ),
            f"distinct names among {FEATURE_NAMES}",
        ),
    )

    C: float = param(
        1.0, doc="inverse regularisation strength of the logistic regression", low=0.0, low_open=True
    )
    features: ReliefFeatureSettings = field(default_factory=ReliefFeatureSettings)
    #: which of :data:`FEATURE_NAMES` the regression uses (a model file keeps its own)
    used: tuple[str, ...] = USED_FEATURES
    settings: HistogramSettings = field(default_factory=HistogramSettings)  # the cache's grids
    mean: FloatArray | None = None
    scale: FloatArray | None = None
    coef: FloatArray | None = None
    intercept: float = 0.0
    platt: tuple[float, float] = (1.0, 0.0)
    #: mean and sd of the calibrated log-odds of the training pairs: {"same": (m, s), "different": (m, s)}
    populations: dict[str, tuple[float, float]] = field(default_factory=dict)
    metadata: dict[str, Any] = field(default_factory=dict)

    def for_coins(self, scale: float) -> ReliefClassifier:
        """This model on coins ``scale`` times as large as those it was trained on: its feature lengths
        scaled (:meth:`ReliefFeatureSettings.for_coins`), the regression the same."""
        return self if scale == 1.0 else replace(self, features=self.features.for_coins(scale))

    @property
    def is_fitted(self) -> bool:
        return self.coef is not None and self.mean is not None and self.scale is not None

    def refuses(self, residual: float) -> str:
        """No pair is refused for its residual: a residual in mm measures the scanner as much as the die."""
        return ""

    def fit(self, features: ArrayLike, same_die: ArrayLike, *, seed: int = 0) -> ReliefClassifier:
        """Fit on ``features`` (n, len(FEATURE_NAMES)) and boolean labels ``same_die``; returns ``self``."""
        X = self._transformed(features)
        y = np.asarray(same_die).astype(bool).astype(int).ravel()
        if len(y) != len(X):
            raise ParameterError(f"{len(X)} feature rows but {len(y)} labels")
        if len(np.unique(y)) < 2:
            raise ParameterError("training needs both same-die and different-die pairs; got one class only")
        self.mean = X.mean(axis=0)
        scale = X.std(axis=0)
        self.scale = np.where(scale > 0, scale, 1.0)
        fitted = fit_platt_logistic((X - self.mean) / self.scale, y, self.C, seed)
        self.coef, self.intercept, self.platt = fitted.coef, fitted.intercept, fitted.platt
        logits = self.log_odds(features)
        self.populations = {
            name: (float(np.mean(logits[y == k])), float(np.std(logits[y == k])))
            for name, k in (("same", 1), ("different", 0))
        }
        self.metadata = {**self.metadata, "n_pairs": int(len(y)), "n_same_die": int(y.sum())}
        return self

    def decision_function(self, features: ArrayLike) -> FloatArray:
        """The regression's log-odds, before calibration."""
        if not self.is_fitted:
            raise ClassifierError("the relief classifier is not fitted (call fit, or load a model file)")
        assert self.mean is not None and self.scale is not None and self.coef is not None
        X = self._transformed(features)
        return ((X - self.mean) / self.scale) @ self.coef + self.intercept

    def log_odds(self, features: ArrayLike) -> FloatArray:
        """The calibrated log-odds ``a f + b`` (the logit of :meth:`predict_proba`)."""
        a, b = self.platt
        return a * self.decision_function(features) + b

    def predict_proba(self, features: ArrayLike) -> FloatArray:
        """Calibrated probability (n,) that each pair was struck by the same die."""
        return sigmoid(self.log_odds(features))

    def _transformed(self, features: ArrayLike) -> FloatArray:
        """The used columns of ``features`` (every stored feature, in :data:`FEATURE_NAMES` order),
        correlations taken to Fisher's z."""
        X = checked_rows(features, len(FEATURE_NAMES), "relief features")
        return transform_features(X[:, [FEATURE_NAMES.index(name) for name in self.used]], self.used)

    # ---------------------------------------------------------------------------------------- files

    def to_dict(self) -> dict[str, Any]:
        if not self.is_fitted:
            raise ClassifierError("cannot save a relief classifier that is not fitted")
        assert self.mean is not None and self.scale is not None and self.coef is not None
        return {
            "format": FORMAT,
            "version": FORMAT_VERSION,
            "model": "logistic regression (L2) on standardised relief features (correlations as Fisher z), "
            "Platt-calibrated",
            "feature_names": list(FEATURE_NAMES),
            "used_features": list(self.used),
            "C": self.C,
            "features": self.features.to_dict(),
            "settings": self.settings.to_dict(),
            "scaler": {"mean": self.mean.tolist(), "scale": self.scale.tolist()},
            "coef": self.coef.tolist(),
            "intercept": self.intercept,
            "platt": {"a": self.platt[0], "b": self.platt[1]},
            "populations": {k: list(v) for k, v in self.populations.items()},
            "metadata": self.metadata,
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any], where: str | Path = "classifier") -> ReliefClassifier:
        try:
            if data.get("format") != FORMAT:
                raise ValueError(f"not a coindie relief classifier (no 'format' field {FORMAT!r})")
            if int(data["version"]) > FORMAT_VERSION:
                raise ValueError(f"format version {data['version']} is newer than this coindie's")
            if list(data["feature_names"]) != list(FEATURE_NAMES):
                raise ValueError(
                    f"its features {data['feature_names']} are not this coindie's {FEATURE_NAMES}"
                )
            model = cls(
                C=float(data["C"]),
                used=tuple(data.get("used_features", FEATURE_NAMES)),
                features=ReliefFeatureSettings.from_dict(data["features"]),
                settings=HistogramSettings.from_dict(data["settings"]),
                mean=np.asarray(data["scaler"]["mean"], dtype=np.float64),
                scale=np.asarray(data["scaler"]["scale"], dtype=np.float64),
                coef=np.asarray(data["coef"], dtype=np.float64),
                intercept=float(data["intercept"]),
                platt=(float(data["platt"]["a"]), float(data["platt"]["b"])),
                populations={k: (float(v[0]), float(v[1])) for k, v in data.get("populations", {}).items()},
                metadata=dict(data.get("metadata", {})),
            )
        except (KeyError, TypeError, ValueError, ParameterError) as error:
            raise ClassifierError(f"{where}: not a usable relief classifier file ({error})") from None
        n = len(model.used)
        assert model.mean is not None and model.scale is not None and model.coef is not None
        if model.mean.shape != (n,) or model.scale.shape != (n,) or model.coef.shape != (n,):
            raise ClassifierError(
                f"{where}: scaler and coefficients must have {n} values (the used features)"
            )
        return model

    def save(self, path: str | Path) -> Path:
        return write_model(path, self.to_dict())

    @classmethod
    def load_default(cls) -> ReliefClassifier:
        """The shipped model, trained on hoards of the ``wide`` synthetic world (docs/clustering.md)."""
        resource = resources.files("coindie") / "data" / DEFAULT_MODEL
        return cls.from_dict(json.loads(resource.read_text()), f"coindie/data/{DEFAULT_MODEL}")


def transform_features(X: FloatArray, names: tuple[str, ...] = FEATURE_NAMES) -> FloatArray:
    """Fisher's z of the correlations among the columns ``names`` (every feature but the overlap share)."""
    out = np.array(X, dtype=np.float64, copy=True)
    correlations = [k for k, name in enumerate(names) if name != "overlap"]
    out[:, correlations] = np.arctanh(np.clip(out[:, correlations], -_MAX_CORRELATION, _MAX_CORRELATION))
    return out
