"""Each face's own pull on its scores: taken off before a hoard's pairs are calibrated.

A well-preserved, finely scanned coin correlates better with *every* face of its design than a worn,
crusted or coarsely scanned one does, whatever the die. On the all-hard synthetic obverses one face's
pairs scored around 0.44 (relief correlation) with every other face, another's around 0.66: the quality
of the two faces moves a pair's score as much as sharing a die does. Most pairs of a hoard are of
different dies, so each face's typical score with faces of *other* dies measures that pull, and a pair's
log-odds are read against the pull of its two faces (a two-way additive model, fitted by medians as
Tukey's median polish does, so that the same-die pairs among them do not drag it):

    log-odds(i, j) = m + a_i + a_j + die evidence(i, j)

Which pairs are of other dies is not known before clustering: the caller gives the pairs to fit on
(:func:`without_face_effects` ``use``), those across the clusters of a first clustering. Taking the pairs
of each face across all its scored pairs instead fails where one die holds half a side's faces (its faces'
typical pair is then a same-die pair). The model holds within one type: a coin of a second type scores
low with every coin of the first, a pull that is its type, not its state; :mod:`coindie.clustering.
second_pass` uses it only where a hoard's first clusters do not stand out.

Measured on four synthetic all-hard hoards (BENCHMARK.md, "Generalisation"): the pair AUC of the
calibrated probabilities rose from 0.77-0.82 to 0.82-0.89 on the obverses and from 0.87-0.96 to 0.92-0.99
on the reverses.

Written by hand: statsmodels' median polish works on a full table; a hoard's pairs are a sparse,
symmetric one (candidate pairs, refused pairs), fitted here on the pairs given.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from numpy.typing import ArrayLike

from coindie.arrays import FloatArray

#: A face's pull is estimated from at least this many of its pairs; with fewer it is taken as 0.
MIN_PAIRS = 8
#: Rounds of the median polish (it settles in two or three).
ROUNDS = 5
_MAX_LOG_ODDS = 30.0


def face_effects(
    log_odds: ArrayLike,
    sources: ArrayLike,
    targets: ArrayLike,
    use: ArrayLike,
    n_faces: int,
) -> FloatArray:
    """The pull ``a`` (n_faces,) of each face on the log-odds of its pairs (``sources``, ``targets``:
    face indices), fitted on the pairs where ``use`` is True: the median over a face's pairs of the pair's
    log-odds less its other face's pull, centred so that the median face pulls by 0."""
    L = np.asarray(log_odds, dtype=np.float64)
    i, j = np.asarray(sources, dtype=np.int64), np.asarray(targets, dtype=np.int64)
    on = np.asarray(use, dtype=bool)
    face = np.concatenate([i[on], j[on]])
    other = np.concatenate([j[on], i[on]])
    values = np.concatenate([L[on], L[on]])
    order = np.argsort(face, kind="stable")
    face, other, values = face[order], other[order], values[order]
    starts = np.searchsorted(face, np.arange(n_faces + 1))
    a = np.zeros(n_faces)
    for _ in range(ROUNDS):
        residual = values - a[other]
        new = np.full(n_faces, np.nan)
        for f in range(n_faces):
            if starts[f + 1] - starts[f] >= MIN_PAIRS:
                new[f] = np.median(residual[starts[f] : starts[f + 1]])
        if np.isnan(new).all():
            return np.zeros(n_faces)
        a = np.nan_to_num(new - np.nanmedian(new))
    return a


def without_face_effects(
    probabilities: ArrayLike, valid: ArrayLike, sources: ArrayLike, targets: ArrayLike, use: ArrayLike
) -> FloatArray:
    """The pairs' probabilities with their two faces' pulls (:func:`face_effects`, fitted on the valid
    pairs where ``use`` is True) taken off their log-odds; refused pairs (not ``valid``) keep theirs."""
    p = np.asarray(probabilities, dtype=np.float64)
    ok = np.asarray(valid, dtype=bool)
    i, j = np.asarray(sources, dtype=np.int64), np.asarray(targets, dtype=np.int64)
    if len(p) == 0:
        return p.copy()
    n_faces = int(max(i.max(), j.max())) + 1
    eps = np.exp(-_MAX_LOG_ODDS)
    log_odds = np.log(np.clip(p, eps, 1.0)) - np.log(np.clip(1.0 - p, eps, 1.0))
    a = face_effects(log_odds, i, j, ok & np.asarray(use, dtype=bool), n_faces)
    centred = np.clip(log_odds - a[i] - a[j], -_MAX_LOG_ODDS, _MAX_LOG_ODDS)
    return np.where(ok, 1.0 / (1.0 + np.exp(-centred)), p)


def without_face_effects_across(
    probabilities: ArrayLike,
    valid: ArrayLike,
    sources: Sequence[str],
    targets: Sequence[str],
    clusters: Mapping[str, object],
) -> FloatArray:
    """:func:`without_face_effects` of pairs named by face id, the pulls fitted on the pairs whose two
    faces lie in different clusters of a first clustering ``clusters`` (face id -> label): those are
    mostly of different dies, whatever the size of a die."""
    faces = sorted(set(sources) | set(targets))
    index = {face: k for k, face in enumerate(faces)}
    i = np.array([index[face] for face in sources], dtype=np.int64)
    j = np.array([index[face] for face in targets], dtype=np.int64)
    across = np.array(
        [clusters.get(a, a) != clusters.get(b, b) for a, b in zip(sources, targets, strict=True)], dtype=bool
    )
    return without_face_effects(probabilities, valid, i, j, across)
