"""Training the same-die classifier on a hoard with known dies.

Training pairs are drawn from one split (the clustering training split by default), within each side of the
coin (obverses with obverses, reverses with reverses): every same-die pair (or a sample of them when they
are too many) and a sample of different-die pairs, ``negatives`` per positive. Negatives are hard ones: the
other dies of the same family (same design, so their faces register onto each other and differ only in the
engraver's details); pairs across families (obverses with and without beard) fill in only when there are
too few. ``max_faces`` restricts the pairs to a sample of faces (whole dies in random order, at most a tenth
of the faces from one die), so that each face takes part in many pairs and its per-face work (relief images,
sampled clouds) is shared. Each pair is registered and its
histogram measured in a resumable batch (:mod:`coindie.similarity.batch`); the classifier is fitted on the
pairs whose registration is valid (an invalid registration scores 0 without the classifier).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from coindie.errors import ParameterError
from coindie.io.truth import FaceTruth, HoardTruth, hoard_recipe
from coindie.similarity.batch import BatchConfig, PairTask, ParallelMap, measure_pairs
from coindie.similarity.classifier import SameDieClassifier
from coindie.similarity.score import PairScore
from coindie.similarity.scorers import Scorer


@dataclass(frozen=True)
class LabelledPair:
    source: FaceTruth
    target: FaceTruth

    @property
    def same_die(self) -> bool:
        return self.source.die == self.target.die

    def task(self) -> PairTask:
        return PairTask(
            self.source.face_id, self.target.face_id, str(self.source.path), str(self.target.path)
        )


def side(face: FaceTruth) -> str:
    """``R`` for reverses, ``D`` for obverses (with or without beard): faces compared with each other."""
    return "R" if face.family == "R" else "D"


def labelled_pairs(
    truth: HoardTruth,
    split: str = "cluster_train",
    *,
    max_pairs: int | None = 2000,
    negatives: float = 2.0,
    max_faces: int | None = None,
    families: tuple[str, ...] = ("R", "D", "DB"),
    seed: int = 0,
) -> list[LabelledPair]:
    """Same-die and different-die pairs of ``split`` (see the module's docstring), at most ``max_pairs``
    in all, ``negatives`` different-die pairs per same-die pair. Deterministic for a seed."""
    if not negatives > 0:
        raise ParameterError(
            f"The 'negatives' parameter must be a positive number per positive pair. Got {negatives}."
        )
    rng = np.random.default_rng(seed)
    faces = [f for f in truth.faces_in(split) if f.family in families]
    if max_faces is not None:
        faces = sample_faces(faces, max_faces, rng)
    positives, hard, other = [], [], []
    for a, b in itertools.combinations(sorted(faces, key=lambda f: f.face_id), 2):
        if side(a) != side(b):
            continue
        pair = LabelledPair(a, b)
        (positives if pair.same_die else hard if a.family == b.family else other).append(pair)
    if not positives:
        raise ParameterError(f"split {split!r} has no two faces of one die: nothing to learn same-die from")
    n_pos = len(positives)
    if max_pairs is not None:
        n_pos = min(n_pos, max(1, round(max_pairs / (1 + negatives))))
    n_neg = min(len(hard) + len(other), round(n_pos * negatives))
    chosen = _sample(positives, n_pos, rng)
    n_hard = min(len(hard), n_neg)
    chosen += _sample(hard, n_hard, rng) + _sample(other, n_neg - n_hard, rng)
    return chosen


def sample_faces(faces: list[FaceTruth], max_faces: int, rng: np.random.Generator) -> list[FaceTruth]:
    """At most ``max_faces`` faces, split evenly between the sides present: dies in random order, at most
    a tenth of ``max_faces`` (and at least 2) faces of each die."""
    if max_faces < 2:
        raise ParameterError(f"The 'max_faces' parameter must be at least 2. Got {max_faces}.")
    by_side: dict[str, dict[str, list[FaceTruth]]] = {}
    for face in sorted(faces, key=lambda f: f.face_id):
        by_side.setdefault(side(face), {}).setdefault(face.die, []).append(face)
    per_side = max_faces // max(1, len(by_side))
    per_die = max(2, max_faces // 10)
    chosen: list[FaceTruth] = []
    for side_name in sorted(by_side):
        dies = by_side[side_name]
        room = per_side
        for die in rng.permutation(sorted(dies)):
            take = dies[str(die)][: min(per_die, room)]
            chosen += take
            room -= len(take)
            if room <= 0:
                break
    return chosen


def _sample(pairs: list[LabelledPair], n: int, rng: np.random.Generator) -> list[LabelledPair]:
    if n >= len(pairs):
        return list(pairs)
    return [pairs[k] for k in sorted(rng.choice(len(pairs), size=n, replace=False))]


def fit_classifier(
    scores: dict[tuple[str, str], PairScore],
    pairs: list[LabelledPair],
    classifier: Scorer | None = None,
    *,
    seed: int = 0,
) -> Scorer:
    """Fit ``classifier`` (a new ``paper`` one with C = 1 by default) on the valid pairs' histograms, or
    their relief features for a ``relief`` scorer."""
    classifier = classifier or SameDieClassifier()

    def reads(score: PairScore) -> np.ndarray:
        return score.histogram if classifier.INPUT == "histogram" else score.features

    used = [(scores[(p.source.face_id, p.target.face_id)], p.same_die) for p in pairs]
    used = [(s, same) for s, same in used if s.valid and reads(s).any()]
    if not used:
        raise ParameterError("no training pair registered validly: nothing to fit the classifier on")
    X = np.stack([reads(s) for s, _ in used])
    y = np.array([same for _, same in used])
    classifier.fit(X, y, seed=seed)
    invalid = {True: 0, False: 0}
    for p in pairs:
        if not scores[(p.source.face_id, p.target.face_id)].valid:
            invalid[p.same_die] += 1
    classifier.metadata.update(
        {"invalid_same_die_pairs": invalid[True], "invalid_other_pairs": invalid[False]}
    )
    return classifier


def train_similarity(
    truth: HoardTruth | list[HoardTruth],
    work_csv: str | Path,
    *,
    split: str = "cluster_train",
    config: BatchConfig | None = None,
    max_pairs: int | None = 2000,
    negatives: float = 2.0,
    max_faces: int | None = 200,
    families: tuple[str, ...] = ("R", "D", "DB"),
    classifier: Scorer | None = None,
    parallel_map: ParallelMap = map,
    seed: int = 0,
    progress: Callable[[int, int], None] | None = None,
) -> Scorer:
    """Draw the training pairs of each hoard (``max_pairs`` per hoard), measure them (resuming
    ``work_csv``, one file per hoard after the first: ``NAME-2.csv``, ...), fit and return the classifier.
    Several hoards train one model: the ``wide`` world draws its physics per hoard. The pairs are measured
    through ``parallel_map`` (:func:`coindie.similarity.batch.measure_pairs`; default: in this process)."""
    truths = truth if isinstance(truth, list) else [truth]
    if not truths:
        raise ParameterError("no hoard to train on")
    config = config or BatchConfig(settings=classifier.settings if classifier else BatchConfig().settings)
    if classifier is not None and classifier.settings != config.settings:
        raise ParameterError(
            "the classifier's histogram settings differ from the batch's: it would be trained on histograms "
            f"it does not describe ({classifier.settings} vs {config.settings})"
        )
    scores: dict[tuple[str, str], PairScore] = {}
    pairs: list[LabelledPair] = []
    for k, hoard in enumerate(truths):
        drawn = labelled_pairs(
            hoard, split, max_pairs=max_pairs, negatives=negatives, max_faces=max_faces, families=families,
            seed=seed + k,
        )  # fmt: skip
        csv = Path(work_csv) if k == 0 else Path(work_csv).with_name(f"{Path(work_csv).stem}-{k + 1}.csv")
        measured = measure_pairs(
            [p.task() for p in drawn], csv, config, parallel_map=parallel_map, progress=progress
        )
        # ids repeat between hoards: key each hoard's pairs by its index too
        scores.update({(f"{k}:{a}", f"{k}:{b}"): v for (a, b), v in measured.items()})
        pairs += [_in_hoard(p, k) for p in drawn]
    classifier = classifier or SameDieClassifier(settings=config.settings)
    fitted = fit_classifier(scores, pairs, classifier, seed=seed)
    fitted.metadata.update(
        {
            "trained_on": [str(t.root) for t in truths], "hoards": [hoard_recipe(t.root) for t in truths],
            "split": split, "method": config.method, "seed": seed,
            "families": list(families), "negatives_per_positive": negatives, "max_faces": max_faces,
            "max_pairs": max_pairs,
        }
    )  # fmt: skip
    if len(truths) == 1:
        fitted.metadata["trained_on"], fitted.metadata["hoard"] = (
            str(truths[0].root),
            hoard_recipe(truths[0].root),
        )
        del fitted.metadata["hoards"]
    return fitted


def _in_hoard(pair: LabelledPair, k: int) -> LabelledPair:
    from dataclasses import replace

    return LabelledPair(
        replace(pair.source, face_id=f"{k}:{pair.source.face_id}"),
        replace(pair.target, face_id=f"{k}:{pair.target.face_id}"),
    )
