"""How good a die clustering is, against the experts' (or the synthetic truth's) dies.

The paper reports the Fowlkes-Mallows index (FMI) and the adjusted Rand index (ARI); we add the adjusted
mutual information (AMI), the pairwise precision and recall behind the FMI (FMI is their geometric mean),
the number of clusters against the number of dies, and the mistakes an expert would have to correct: dies
split over several clusters and clusters that merge several dies. Every figure is scikit-learn's.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

from coindie.errors import ParameterError


@dataclass(frozen=True)
class Mistake:
    """A die split over several clusters (``kind="split"``: ``members`` maps cluster -> faces) or a
    cluster holding several dies (``kind="merged"``: ``members`` maps die -> faces)."""

    kind: str
    name: str
    members: dict[str, list[str]]


@dataclass(frozen=True)
class Evaluation:
    fmi: float
    ari: float
    ami: float
    precision: float
    recall: float
    n_clusters: int
    n_dies: int
    n_faces: int
    mistakes: list[Mistake] = field(default_factory=list)
    missing: list[str] = field(default_factory=list)  # labelled faces the clustering does not have
    unlabelled: list[str] = field(default_factory=list)  # clustered faces without a label

    def scores(self) -> dict[str, float | int]:
        """The headline figures: ``{"fmi", "ari", "ami", "n_clusters", "n_dies"}`` and the rest."""
        return {
            "fmi": self.fmi, "ari": self.ari, "ami": self.ami, "n_clusters": self.n_clusters,
            "n_dies": self.n_dies, "precision": self.precision, "recall": self.recall,
            "n_faces": self.n_faces,
        }  # fmt: skip

    def to_dict(self) -> dict[str, Any]:
        return {**self.scores(), **{k: asdict(self)[k] for k in ("mistakes", "missing", "unlabelled")}}


def evaluate(predicted: Mapping[str, object], truth: Mapping[str, object]) -> Evaluation:
    """Compare cluster labels with true dies on the faces both name (face id -> label, canonical keys).

    Raises:
        ParameterError: no face is in both.
    """
    from sklearn import metrics

    common = sorted(set(predicted) & set(truth))
    if not common:
        raise ParameterError("the clustering and the labels have no face in common")
    pred = [str(predicted[f]) for f in common]
    true = [str(truth[f]) for f in common]
    tp, fp, fn = pairwise_counts(pred, true)
    return Evaluation(
        fmi=float(metrics.fowlkes_mallows_score(true, pred)),
        ari=float(metrics.adjusted_rand_score(true, pred)),
        ami=float(metrics.adjusted_mutual_info_score(true, pred)),
        precision=float(tp / (tp + fp)) if tp + fp else 1.0,
        recall=float(tp / (tp + fn)) if tp + fn else 1.0,
        n_clusters=len(set(pred)),
        n_dies=len(set(true)),
        n_faces=len(common),
        mistakes=mistakes(dict(zip(common, pred, strict=True)), dict(zip(common, true, strict=True))),
        missing=sorted(set(truth) - set(predicted)),
        unlabelled=sorted(set(predicted) - set(truth)),
    )


def mistakes(predicted: Mapping[str, str], truth: Mapping[str, str]) -> list[Mistake]:
    """Dies split over clusters, then clusters merging dies (each with its faces)."""
    found = [Mistake("split", die, groups) for die, groups in _spread(truth, predicted).items()]
    found += [Mistake("merged", label, groups) for label, groups in _spread(predicted, truth).items()]
    return found


def _spread(outer: Mapping[str, str], inner: Mapping[str, str]) -> dict[str, dict[str, list[str]]]:
    """Each ``outer`` label whose faces carry several ``inner`` labels -> {inner label: faces}."""
    groups: dict[str, dict[str, list[str]]] = {}
    for face in sorted(outer):
        groups.setdefault(outer[face], {}).setdefault(inner[face], []).append(face)
    return {name: parts for name, parts in sorted(groups.items()) if len(parts) > 1}


def pairwise_counts(predicted: list[str], truth: list[str]) -> tuple[int, int, int]:
    """(TP, FP, FN) over pairs of faces, as the paper defines them for the FMI."""
    from sklearn.metrics.cluster import pair_confusion_matrix

    (_, fp), (fn, tp) = np.asarray(pair_confusion_matrix(truth, predicted)) // 2
    return int(tp), int(fp), int(fn)
