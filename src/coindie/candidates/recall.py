"""What a candidate search keeps of the same-die pairs, on a hoard whose dies are known.

Three figures per K (pair recall alone cannot reach 99 % once a die has more than K + 1 faces, and
clustering does not need it):

* ``pair_recall``: the share of all same-die pairs among the candidate pairs (for information);
* ``face_recall``: the share of faces having a same-die partner that find one among their K candidates;
* ``die_connected``: the share of dies (of two faces or more) whose faces form one connected component of
  the candidate graph restricted to the die (links either way) — what clustering by connected components
  or by communities needs to recover the die.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import asdict, dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from coindie.arrays import IntArray
from coindie.candidates.index import candidate_pairs


@dataclass(frozen=True)
class CandidateRecall:
    """Recall figures of a candidate search at one K (see the module docstring)."""

    k: int
    n_faces: int
    n_dies: int
    n_candidate_pairs: int
    n_same_die_pairs: int
    pair_recall: float
    face_recall: float
    die_connected: float

    def to_dict(self) -> dict[str, float]:
        return asdict(self)


def candidate_recall(neighbours: IntArray, dies: Sequence[str], k: int | None = None) -> CandidateRecall:
    """The figures of the first ``k`` columns of ``neighbours`` (all of them by default) for faces whose
    die is ``dies[i]``."""
    k = neighbours.shape[1] if k is None else k
    top = neighbours[:, :k]
    labels = np.asarray(dies)
    n = len(labels)
    sizes = {die: int(count) for die, count in zip(*np.unique(labels, return_counts=True), strict=True)}
    safe = np.where(top >= 0, top, 0)
    same = (labels[safe] == labels[:, None]) & (top >= 0)
    has_partner = np.array([sizes[die] > 1 for die in labels])
    pairs = candidate_pairs(top)
    same_pairs = [(i, j) for i, j in pairs if labels[i] == labels[j]]
    total_same = sum(s * (s - 1) // 2 for s in sizes.values())
    return CandidateRecall(
        k=k,
        n_faces=n,
        n_dies=len(sizes),
        n_candidate_pairs=len(pairs),
        n_same_die_pairs=total_same,
        pair_recall=len(same_pairs) / total_same if total_same else 1.0,
        face_recall=float(same.any(axis=1)[has_partner].mean()) if has_partner.any() else 1.0,
        die_connected=_dies_connected(same_pairs, labels, sizes),
    )


def _dies_connected(same_pairs: list[tuple[int, int]], labels: np.ndarray, sizes: dict[str, int]) -> float:
    """Share of dies of two faces or more that are one component of the same-die candidate links."""
    multi = [die for die, size in sizes.items() if size > 1]
    if not multi:
        return 1.0
    n = len(labels)
    rows = np.array([i for i, _ in same_pairs], dtype=np.int64)
    cols = np.array([j for _, j in same_pairs], dtype=np.int64)
    graph = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(n, n))
    _, component = connected_components(graph, directed=False)
    connected = [len(set(component[labels == die])) == 1 for die in multi]
    return float(np.mean(connected))
