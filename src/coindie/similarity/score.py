"""One pair's same-die score: register, histogram of the aligned distances, probability.

:func:`score_pair` is a pure function of two scans and its parameters, so that a scheduler can run pairs
anywhere (processes, a Dask cluster) and store the :class:`PairScore` as JSON. The per-face work it needs is
cached by content: the registrar's (see ``coindie.registration``) and the histogram's grid-sampled faces and
k-d trees (see :mod:`coindie.similarity.histogram`), so that scoring many sources against one target pays
for the target once.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from coindie.arrays import FloatArray
from coindie.registration.base import Registrar
from coindie.scan import Scan
from coindie.similarity.histogram import FaceCache, HistogramSettings, c2c_histogram
from coindie.similarity.relief_features import FEATURE_NAMES, ReliefFeatureSettings, relief_features
from coindie.similarity.scorers import Scorer, default_scorer


@dataclass(frozen=True)
class PairScore:
    """The outcome of scoring ``source`` against ``target``.

    ``probability`` is 0 when the registration is not valid (``reason`` says why) or when no point of the
    source came within the histogram's range of the target; ``timings`` are seconds per stage
    (``register``, ``histogram``, ``classify``, ``total``).
    """

    T_target_source: FloatArray
    valid: bool
    reason: str
    histogram: FloatArray
    probability: float
    timings: dict[str, float] = field(default_factory=dict)
    source_id: str = ""
    target_id: str = ""
    method: str = ""
    residual: float = float("nan")
    features: FloatArray = field(default_factory=lambda: np.zeros(0))

    def classified(self, classifier: Scorer) -> PairScore:
        """This pair with its probability from ``classifier``, which reads the histogram (``paper``) or
        the relief features (``relief``): 0 when the registration is invalid or its input empty (no
        aligned point within range of the target, or no overlap of the two reliefs)."""
        if not self.valid:
            return replace(self, probability=0.0)
        refused = classifier.refuses(self.residual)
        if refused:
            return replace(self, probability=0.0, reason=refused)
        mark = time.perf_counter()
        reads = self.histogram if classifier.INPUT == "histogram" else self.features
        if reads.any():
            probability, reason = float(classifier.predict_proba(reads[None, :])[0]), ""
        elif classifier.INPUT == "histogram":
            probability = 0.0
            reason = f"no aligned point within {classifier.settings.max_distance_mm} mm of the target"
        else:
            probability, reason = 0.0, "the two reliefs do not overlap once aligned"
        timings = {**self.timings, "classify": time.perf_counter() - mark}
        timings["total"] = timings.get("total", 0.0) + timings["classify"]
        return replace(self, probability=probability, reason=reason, timings=timings)

    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready dictionary (arrays as lists, a NaN residual as None)."""
        return {
            "source_id": self.source_id,
            "target_id": self.target_id,
            "method": self.method,
            "valid": self.valid,
            "reason": self.reason,
            "probability": self.probability if np.isfinite(self.probability) else None,
            "T_target_source": np.asarray(self.T_target_source).tolist(),
            "histogram": np.asarray(self.histogram).tolist(),
            "residual": self.residual if np.isfinite(self.residual) else None,
            "timings": dict(self.timings),
            "features": np.asarray(self.features).tolist(),
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> PairScore:
        residual = data.get("residual")
        return cls(
            T_target_source=np.asarray(data["T_target_source"], dtype=np.float64),
            valid=bool(data["valid"]),
            reason=str(data.get("reason", "")),
            histogram=np.asarray(data["histogram"], dtype=np.float64),
            probability=float("nan") if data["probability"] is None else float(data["probability"]),
            timings={k: float(v) for k, v in data.get("timings", {}).items()},
            source_id=str(data.get("source_id", "")),
            target_id=str(data.get("target_id", "")),
            method=str(data.get("method", "")),
            residual=float("nan") if residual is None else float(residual),
            features=np.asarray(data.get("features", []), dtype=np.float64),
        )


def score_pair(
    source: Scan,
    target: Scan,
    registrar: Registrar | None = None,
    settings: HistogramSettings | None = None,
    classifier: Scorer | None = None,
    faces: FaceCache | None = None,
    *,
    T_init: FloatArray | None = None,
    with_histogram: bool = True,
) -> PairScore:
    """Register ``source`` onto ``target``, measure the aligned pair (the paper's distance histogram and
    the relief features), and estimate the probability that both faces were struck by the same die.

    Defaults: the ``relief`` registration method, the classifier's own histogram settings (those it was
    trained with; the paper's when neither is given), the shipped ``relief`` scorer, the histogram module's
    cache of sampled faces (``faces``: a caller scoring many pairs passes one sized for its faces).
    ``T_init`` (T_target_source) starts the registration from a given pose instead of the method's global
    step (a pose composed through a third face); only methods that ``refines_from_pose`` accept it.
    ``with_histogram=False`` leaves the histogram out (zeros) where the classifier does not read it: a
    caller that may throw the result away measures it later with :func:`add_histogram`.
    """
    classifier = classifier if classifier is not None else _default_classifier()
    settings = settings if settings is not None else classifier.settings
    features = getattr(classifier, "features", None)
    histogram = with_histogram or classifier.INPUT == "histogram"
    measured = measure_pair(
        source, target, registrar, settings, features, faces, T_init=T_init, with_histogram=histogram
    )
    return measured.classified(classifier)


def add_histogram(
    score: PairScore,
    source: Scan,
    target: Scan,
    settings: HistogramSettings | None = None,
    faces: FaceCache | None = None,
) -> PairScore:
    """``score`` with the distance histogram of its pose measured (a score made ``with_histogram=False``);
    an invalid registration keeps its zeros."""
    if not score.valid:
        return score
    mark = time.perf_counter()
    histogram = c2c_histogram(source, target, score.T_target_source, settings, faces)
    spent = time.perf_counter() - mark
    timings = {**score.timings, "histogram": spent, "total": score.timings.get("total", 0.0) + spent}
    return replace(score, histogram=histogram, timings=timings)


def measure_pair(
    source: Scan,
    target: Scan,
    registrar: Registrar | None = None,
    settings: HistogramSettings | None = None,
    features: ReliefFeatureSettings | None = None,
    faces: FaceCache | None = None,
    *,
    T_init: FloatArray | None = None,
    with_histogram: bool = True,
) -> PairScore:
    """:func:`score_pair` without the classifier (``probability`` is NaN for a valid registration, 0 for
    an invalid one): what a batch stores, so that either scorer can be trained on, or applied to, the
    histograms and relief features later without registering again."""
    from coindie.registration import get_method

    start = time.perf_counter()
    registrar = registrar if registrar is not None else get_method("relief")
    settings = settings if settings is not None else HistogramSettings()
    result = (
        registrar.register(source, target)
        if T_init is None
        else registrar.register(source, target, T_init=T_init)
    )
    timings = {"register": time.perf_counter() - start}
    ids = {"source_id": str(source.id), "target_id": str(target.id), "method": result.method}
    if not result.valid:
        timings["total"] = timings["register"]
        return PairScore(
            result.T_target_source, False, result.reason or "registration failed", np.zeros(settings.bins),
            0.0, timings, residual=result.residual, features=np.zeros(len(FEATURE_NAMES)), **ids,
        )  # fmt: skip
    histogram = np.zeros(settings.bins)
    if with_histogram:
        mark = time.perf_counter()
        histogram = c2c_histogram(source, target, result.T_target_source, settings, faces)
        timings["histogram"] = time.perf_counter() - mark
    mark = time.perf_counter()
    relief = relief_features(source, target, result.T_target_source, features)
    timings["features"] = time.perf_counter() - mark
    timings["total"] = time.perf_counter() - start
    return PairScore(
        result.T_target_source, True, "", histogram, float("nan"), timings, residual=result.residual,
        features=relief, **ids,
    )  # fmt: skip


_DEFAULT: list[Scorer] = []


def _default_classifier() -> Scorer:
    if not _DEFAULT:
        _DEFAULT.append(default_scorer())
    return _DEFAULT[0]
