"""The same-die scorers by name, and loading any scorer's model file.

- ``relief`` (the default): :class:`~coindie.similarity.relief_classifier.ReliefClassifier` on the
  scale-free relief features, trained on hoards of the ``wide`` synthetic world;
- ``paper``: the paper's :class:`~coindie.similarity.classifier.SameDieClassifier`, a logistic regression
  on the 70-bin cloud-to-cloud distance histogram, trained on the ``riedones`` preset; the paper-protocol
  benchmarks keep it.

Both read one registered :class:`~coindie.similarity.score.PairScore` (``INPUT`` says which part of it)
and return calibrated probabilities; the per-hoard calibration (:mod:`coindie.similarity.calibration`)
then adapts them to a hoard's own score distribution.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Protocol

from numpy.typing import ArrayLike, NDArray

from coindie.errors import ParameterError
from coindie.similarity.classifier import SameDieClassifier, read_model
from coindie.similarity.histogram import HistogramSettings
from coindie.similarity.relief_classifier import FORMAT as RELIEF_FORMAT
from coindie.similarity.relief_classifier import ReliefClassifier

#: The scorer a run uses when none is named.
DEFAULT_SCORER = "relief"
SCORERS: dict[str, type[SameDieClassifier] | type[ReliefClassifier]] = {
    "relief": ReliefClassifier,
    "paper": SameDieClassifier,
}


class Scorer(Protocol):
    NAME: str
    INPUT: str
    settings: HistogramSettings

    def predict_proba(self, X: ArrayLike) -> NDArray[Any]: ...

    def refuses(self, residual: float) -> str: ...

    def to_dict(self) -> dict[str, Any]: ...


def default_scorer(name: str = DEFAULT_SCORER) -> Scorer:
    """The shipped model of the named scorer."""
    if name not in SCORERS:
        raise ParameterError(f"The scorer must be one of {', '.join(SCORERS)}. Got {name!r}.")
    return SCORERS[name].load_default()


def scorer_from_dict(data: dict[str, Any], where: str | Path = "classifier") -> Scorer:
    """A scorer from its JSON (either kind, told apart by its ``format`` field)."""
    if isinstance(data, dict) and data.get("format") == RELIEF_FORMAT:
        return ReliefClassifier.from_dict(data, where)
    return SameDieClassifier.from_dict(data, where)


def load_scorer(path: str | Path) -> Scorer:
    """A scorer's model file (``coindie train similarity`` writes either kind)."""
    return scorer_from_dict(read_model(path), path)
