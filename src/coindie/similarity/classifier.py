"""The same-die classifier: a calibrated logistic regression on standardised distance histograms.

As in the paper (section 3.2.2 and the authors' code), a histogram ``h`` is standardised as
``(h - mean) / std`` with a per-bin ``mean`` and one scalar ``std`` (the authors' 1.72): one scale for every
bin keeps the histogram's shape, where a per-bin scale would blow up the nearly-empty far bins. An L2
logistic regression (C = 1) then scores it.

A logistic regression fitted on separable pairs is over-confident, and a clustering threshold needs
probabilities that mean what they say. So the probability is calibrated by Platt scaling: a 1-D logistic
fit ``p = 1 / (1 + exp(-(a f + b)))`` of the same-die labels on *out-of-fold* decision values ``f`` (each
pair scored by a regression that did not see it, k-fold), after which the regression is refitted on every
pair. Everything (scaler, coefficients, Platt's ``a, b``, the histogram settings it was trained with, the
version) is stored as JSON, never a pickle.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike

from coindie.arrays import FloatArray
from coindie.errors import CoinDieError, ParameterError
from coindie.params import Configurable, param
from coindie.similarity.histogram import HistogramSettings
from coindie.similarity.logistic import fit_platt_logistic, sigmoid

#: Version of the JSON format written by :meth:`SameDieClassifier.save`.
FORMAT_VERSION = 1
#: The shipped default model, inside the package.
DEFAULT_MODEL = "same_die_classifier.json"


class ClassifierError(CoinDieError, ValueError):
    """A classifier file cannot be read, or a classifier is used before it was fitted."""


@dataclass
class SameDieClassifier(Configurable):
    """Probability that two registered faces were struck by the same die, from their distance histogram.

    ``fit`` learns the scaler (unless it was given, e.g. the paper's), the regression and the calibration;
    ``predict_proba`` returns one probability per histogram.
    """

    #: The scorer's name (``coindie run --scorer``) and what it reads of a pair (``PairScore.histogram``).
    NAME: ClassVar[str] = "paper"
    OWNER: ClassVar[str] = "SameDieClassifier"
    INPUT: ClassVar[str] = "histogram"

    C: float = param(
        1.0, doc="inverse regularisation strength of the logistic regression", low=0.0, low_open=True
    )
    settings: HistogramSettings = field(default_factory=HistogramSettings)
    mean: FloatArray | None = None
    std: float | None = None
    fixed_scaler: bool = False
    coef: FloatArray | None = None
    intercept: float = 0.0
    platt: tuple[float, float] = (1.0, 0.0)
    metadata: dict[str, Any] = field(default_factory=dict)
    #: Pairs whose median point-to-plane residual (mm) exceeds this score 0 (0: none). The shipped model
    #: was trained on pairs that passed the registration's old 0.02 mm test, so it keeps that test.
    max_residual: float = param(
        0.0, doc="pairs of a larger median residual score 0 (0: none)", unit="mm", low=0.0
    )

    def refuses(self, residual: float) -> str:
        """Why a pair of this residual (mm) scores 0 without the regression ("" when it does not)."""
        if self.max_residual > 0 and not residual <= self.max_residual:
            return (
                f"median point-to-plane residual {residual:.4f} mm exceeds the paper scorer's "
                f"{self.max_residual} mm"
            )
        return ""

    # ---------------------------------------------------------------------------------------- training

    def fit(self, histograms: ArrayLike, same_die: ArrayLike, *, seed: int = 0) -> SameDieClassifier:
        """Fit on ``histograms`` (n, bins) and boolean labels ``same_die`` (n,); returns ``self``.

        scikit-learn's ``CalibratedClassifierCV(method="sigmoid", ensemble=False)`` does the calibration:
        Platt's sigmoid on out-of-fold decision values, then the regression refitted on every pair
        (:func:`coindie.similarity.logistic.fit_platt_logistic`).
        """
        X, y = self._checked_training(histograms, same_die)
        if not self.fixed_scaler:
            self.mean = X.mean(axis=0)
            std = float(np.std(X - self.mean))
            self.std = std if std > 0 else 1.0
        fitted = fit_platt_logistic(self._standardised(X), y, self.C, seed)
        self.coef, self.intercept, self.platt = fitted.coef, fitted.intercept, fitted.platt
        self.metadata = {**self.metadata, "n_pairs": int(len(y)), "n_same_die": int(y.sum())}
        return self

    def _checked_training(self, histograms: ArrayLike, same_die: ArrayLike) -> tuple[FloatArray, np.ndarray]:
        X = self._checked_histograms(histograms)
        y = np.asarray(same_die).astype(bool).astype(int).ravel()
        if len(y) != len(X):
            raise ParameterError(f"{len(X)} histograms but {len(y)} labels")
        if len(np.unique(y)) < 2:
            raise ParameterError("training needs both same-die and different-die pairs; got one class only")
        return X, y

    # ---------------------------------------------------------------------------------------- scoring

    @property
    def is_fitted(self) -> bool:
        return self.coef is not None and self.mean is not None and self.std is not None

    def decision_function(self, histograms: ArrayLike) -> FloatArray:
        """The regression's log-odds, before calibration."""
        if not self.is_fitted:
            raise ClassifierError("the same-die classifier is not fitted (call fit, or load a model file)")
        assert self.coef is not None
        return self._standardised(self._checked_histograms(histograms)) @ self.coef + self.intercept

    def predict_proba(self, histograms: ArrayLike) -> FloatArray:
        """Calibrated probability (n,) that each pair was struck by the same die."""
        a, b = self.platt
        return sigmoid(a * self.decision_function(histograms) + b)

    def _standardised(self, X: FloatArray) -> FloatArray:
        assert self.mean is not None and self.std is not None
        return (X - self.mean) / self.std

    def _checked_histograms(self, histograms: ArrayLike) -> FloatArray:
        return checked_rows(histograms, self.settings.bins, "histograms")

    # ---------------------------------------------------------------------------------------- files

    def to_dict(self) -> dict[str, Any]:
        if not self.is_fitted:
            raise ClassifierError("cannot save a same-die classifier that is not fitted")
        assert self.mean is not None and self.coef is not None
        return {
            "format": "coindie.same_die_classifier",
            "version": FORMAT_VERSION,
            "model": "logistic regression (L2) on (histogram - mean) / std, Platt-calibrated",
            "C": self.C,
            "settings": self.settings.to_dict(),
            "scaler": {"mean": self.mean.tolist(), "std": self.std, "fixed": self.fixed_scaler},
            "coef": self.coef.tolist(),
            "intercept": self.intercept,
            "platt": {"a": self.platt[0], "b": self.platt[1]},
            "acceptance": {"max_residual": self.max_residual},
            "metadata": self.metadata,
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any], where: str | Path = "classifier") -> SameDieClassifier:
        try:
            if data.get("format") != "coindie.same_die_classifier":
                raise ValueError("not a coindie same-die classifier (no 'format' field of that name)")
            if int(data["version"]) > FORMAT_VERSION:
                raise ValueError(f"format version {data['version']} is newer than this coindie's")
            model = cls(
                C=float(data["C"]),
                settings=HistogramSettings.from_dict(data["settings"]),
                mean=np.asarray(data["scaler"]["mean"], dtype=np.float64),
                std=float(data["scaler"]["std"]),
                fixed_scaler=bool(data["scaler"].get("fixed", False)),
                coef=np.asarray(data["coef"], dtype=np.float64),
                intercept=float(data["intercept"]),
                platt=(float(data["platt"]["a"]), float(data["platt"]["b"])),
                metadata=dict(data.get("metadata", {})),
                max_residual=float(data.get("acceptance", {}).get("max_residual", 0.0)),
            )
        except (KeyError, TypeError, ValueError) as error:
            raise ClassifierError(f"{where}: not a usable classifier file ({error})") from None
        bins = model.settings.bins
        assert model.mean is not None and model.coef is not None
        if model.mean.shape != (bins,) or model.coef.shape != (bins,):
            raise ClassifierError(f"{where}: scaler and coefficients must have {bins} values (the bins)")
        return model

    def save(self, path: str | Path) -> Path:
        return write_model(path, self.to_dict())

    @classmethod
    def load(cls, path: str | Path) -> SameDieClassifier:
        return cls.from_dict(read_model(path), path)

    @classmethod
    def load_default(cls) -> SameDieClassifier:
        """The shipped model, trained on the synthetic ``riedones`` hoard's clustering training split
        (see docs/clustering.md for the command that reproduces it)."""
        resource = resources.files("coindie") / "data" / DEFAULT_MODEL
        return cls.from_dict(json.loads(resource.read_text()), f"coindie/data/{DEFAULT_MODEL}")

    @classmethod
    def from_paper_scaler(
        cls, path: str | Path, *, C: float = 1.0, settings: HistogramSettings | None = None
    ) -> SameDieClassifier:
        """An unfitted classifier whose standardisation is the paper's (the authors' ``mean_std.json``:
        ``mean`` of 70 bins, scalar ``std``); ``fit`` then learns only the regression and calibration.

        The authors' histograms are normalised differently from ours: their mean sums to 70 (the number
        of bins, a density over a unit range), where ours integrate to 1 over 0-0.6 mm. The mean and the
        std are rescaled by the same factor, so that the paper's mean becomes a density in our units and
        the standardised values are unchanged.
        """
        path = Path(path)
        try:
            data = json.loads(path.read_text())
            mean = np.asarray(data["mean"], dtype=np.float64)
            std = float(np.asarray(data["std"], dtype=np.float64).ravel()[0])
        except FileNotFoundError:
            raise ClassifierError(f"{path}: no such scaler file") from None
        except (OSError, KeyError, TypeError, ValueError, IndexError, json.JSONDecodeError) as error:
            raise ClassifierError(f"{path}: not a scaler file with 'mean' and 'std' ({error})") from None
        settings = settings or HistogramSettings()
        if mean.shape != (settings.bins,) or not np.isfinite(mean).all() or not std > 0 or not mean.sum() > 0:
            raise ClassifierError(
                f"{path}: the scaler needs {settings.bins} finite means and a positive std; "
                f"got {mean.shape} means and std {std}"
            )
        factor = 1.0 / (mean.sum() * settings.max_distance_mm / settings.bins)
        return cls(
            C=C, settings=settings, mean=mean * factor, std=std * factor, fixed_scaler=True,
            metadata={"scaler": path.name, "scaler_rescaled_by": factor},
        )  # fmt: skip


def checked_rows(X: ArrayLike, width: int, what: str) -> FloatArray:
    """``X`` as a finite (n, ``width``) float array, or a ParameterError naming ``what``."""
    rows = np.atleast_2d(np.asarray(X, dtype=np.float64))
    if rows.ndim != 2 or rows.shape[1] != width:
        raise ParameterError(f"{what} must be (n, {width}) arrays. Got shape {rows.shape}.")
    if not np.isfinite(rows).all():
        raise ParameterError(f"{what} contain NaN or infinite values")
    return rows


def read_model(path: str | Path) -> dict[str, Any]:
    """A model file's JSON, or a ClassifierError naming the file."""
    path = Path(path)
    try:
        return json.loads(path.read_text())
    except FileNotFoundError:
        raise ClassifierError(f"{path}: no such classifier file") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as error:
        raise ClassifierError(f"{path}: not a JSON classifier file ({error})") from None


def write_model(path: str | Path, data: dict[str, Any]) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=1) + "\n")
    return path
