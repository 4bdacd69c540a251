"""The calibrated logistic regression both same-die scorers fit (``paper`` on histograms, ``relief`` on
relief features): L2 regression, then Platt scaling on out-of-fold decision values.

A logistic regression fitted on separable pairs is over-confident, and a clustering threshold needs
probabilities that mean what they say. So the probability is calibrated by Platt scaling: a 1-D logistic
fit ``p = 1 / (1 + exp(-(a f + b)))`` of the same-die labels on *out-of-fold* decision values ``f`` (each
pair scored by a regression that did not see it, k-fold), after which the regression is refitted on every
pair. scikit-learn's ``CalibratedClassifierCV(method="sigmoid", ensemble=False)`` does it; its numbers are
copied out so that a model is plain JSON.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from coindie.arrays import FloatArray

#: Folds of the out-of-fold decision values that calibrate the probabilities.
CALIBRATION_FOLDS = 5


@dataclass(frozen=True)
class PlattLogistic:
    """A fitted regression: ``coef``, ``intercept`` and Platt's ``(a, b)``."""

    coef: FloatArray
    intercept: float
    platt: tuple[float, float]


def fit_platt_logistic(Z: ArrayLike, y: ArrayLike, C: float, seed: int = 0) -> PlattLogistic:
    """Fit on standardised inputs ``Z`` (n, k) and 0/1 labels ``y``; the regression's own probabilities
    when a class is too small to hold any pair out."""
    from sklearn.calibration import CalibratedClassifierCV
    from sklearn.linear_model import LogisticRegression
    from sklearn.model_selection import StratifiedKFold

    Z, y = np.asarray(Z, dtype=np.float64), np.asarray(y).astype(int)
    regression = LogisticRegression(C=C, max_iter=5000)  # L2 is scikit-learn's default penalty
    folds = min(CALIBRATION_FOLDS, int(np.bincount(y).min()))
    if folds >= 2:
        splitter = StratifiedKFold(n_splits=folds, shuffle=True, random_state=seed)
        fitted = CalibratedClassifierCV(regression, method="sigmoid", cv=splitter, ensemble=False)
        calibrated = fitted.fit(Z, y).calibrated_classifiers_[0]
        regression, sigmoid = calibrated.estimator, calibrated.calibrators[0]
        # scikit-learn's sigmoid is 1 / (1 + exp(a f + b)); ours is 1 / (1 + exp(-(a f + b))).
        platt = (-float(sigmoid.a_), -float(sigmoid.b_))
    else:
        regression.fit(Z, y)
        platt = (1.0, 0.0)
    return PlattLogistic(regression.coef_[0].astype(np.float64), float(regression.intercept_[0]), platt)


def sigmoid(z: ArrayLike) -> FloatArray:
    return 0.5 * (1.0 + np.tanh(0.5 * np.asarray(z, dtype=np.float64)))
