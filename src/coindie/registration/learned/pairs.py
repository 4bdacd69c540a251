"""Training pairs for FCGF from a hoard folder: two faces of one die, their true matches, augmented.

Faces come from one split of the hoard (``registration_train``: in the ``riedones`` preset, 200 obverses
without beard), grid-sampled at the model's voxel (mean position per cell). A pair is two faces of the same
die; its matches are the source points whose position moved by the truth (``T_true(source, target)`` of
truth.json) has a target point within ``match_radius`` (one voxel). Each face is then moved by its own
random rotation about its centroid (the paper's: within ±25° about x and y, ±180° about z) and both by
one random scale (0.9-1.2); the matches, made before, stay true. Everything is drawn from a seed: the same
seed, epoch and pair give the same training pair.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

from coindie.arrays import FloatArray, IntArray
from coindie.io.truth import HoardTruth, TruthError, load_truth
from coindie.transforms import euler_rotation, transform_points

FacePair = tuple[str, str]


@dataclass(frozen=True)
class Augmentation:
    """Random similarity of a cloud about its centroid: rotation (Euler x, y, z in degrees) and scale."""

    tilt_deg: float = 25.0  # about x and about y, within ±
    spin_deg: float = 180.0  # about z, within ±
    scale: tuple[float, float] = (0.9, 1.2)

    def draw(self, rng: np.random.Generator, center: FloatArray, scale: float | None = None) -> FloatArray:
        """A 4x4 similarity ``p -> s R (p - center) + center`` (``s`` drawn unless given)."""
        angles = [rng.uniform(-self.tilt_deg, self.tilt_deg) for _ in range(2)]
        angles.append(rng.uniform(-self.spin_deg, self.spin_deg))
        s = rng.uniform(*self.scale) if scale is None else scale
        A = np.eye(4)
        A[:3, :3] = s * euler_rotation(angles)
        A[:3, 3] = center - A[:3, :3] @ center
        return A

    def draw_pair(
        self, rng: np.random.Generator, center_a: FloatArray, center_b: FloatArray
    ) -> tuple[FloatArray, FloatArray]:
        """Similarities of the two clouds of a pair: each its own rotation, one scale for both.

        As FCGF's training does: the scale stands for another voxel size (or another coin size), the same
        for both clouds; scaling them apart would ask the descriptors to match a place with a copy of it
        up to 1.33 times larger, which a die study must tell apart (dies are cut at one size)."""
        scale = rng.uniform(*self.scale)
        return self.draw(rng, center_a, scale), self.draw(rng, center_b, scale)


#: The paper's training augmentation; validation turns clouds like the benchmark does, without scaling.
TRAINING = Augmentation()
VALIDATION = Augmentation(scale=(1.0, 1.0))


@dataclass(frozen=True)
class TrainingPair:
    """Two augmented clouds (mm) and their true matches (rows: source index, target index)."""

    name: str
    source: FloatArray
    target: FloatArray
    matches: IntArray
    T_target_source: FloatArray  # 4x4 similarity: augmented source frame -> augmented target frame
    source_normals: FloatArray  # unit normals of the augmented clouds (DIP's frames use them)
    target_normals: FloatArray


def face_pairs(truth: HoardTruth, split: str) -> list[FacePair]:
    """Every pair (a, b), a < b, of faces of one die in ``split``, die by die."""
    by_die: dict[str, list[str]] = {}
    for face in truth.faces_in(split):
        by_die.setdefault(face.die, []).append(face.face_id)
    return [p for die in sorted(by_die) for p in itertools.combinations(sorted(by_die[die]), 2)]


def split_pairs(
    pairs: Sequence[FacePair], truth: HoardTruth, val_fraction: float, seed: int
) -> tuple[list[FacePair], list[FacePair]]:
    """(training, validation) pairs: whole dies go to validation (unseen patterns), drawn at random
    among those that keep it within ``val_fraction`` of the pairs (the die of fewest pairs when none
    does). With a single die, pairs are drawn instead; with a single pair, it serves for both."""
    if val_fraction <= 0 or not pairs:
        return list(pairs), []
    rng = np.random.default_rng([seed, 7])
    per_die: dict[str, int] = {}
    for a, _ in pairs:
        per_die[truth.faces[a].die] = per_die.get(truth.faces[a].die, 0) + 1
    if len(per_die) == 1:
        return _split_within(list(pairs), val_fraction, rng)
    wanted, held = val_fraction * len(pairs), set()
    for die in rng.permutation(sorted(per_die)):
        if sum(per_die[d] for d in held) + per_die[die] <= wanted:
            held.add(str(die))
    held = held or {min(sorted(per_die), key=per_die.__getitem__)}
    val = [p for p in pairs if truth.faces[p[0]].die in held]
    return [p for p in pairs if truth.faces[p[0]].die not in held], val


def _split_within(pairs: list[FacePair], val_fraction: float, rng: np.random.Generator) -> tuple[list, list]:
    if len(pairs) == 1:
        return pairs, pairs
    n_val = min(len(pairs) - 1, max(1, math.ceil(val_fraction * len(pairs))))
    order = rng.permutation(len(pairs))
    return [pairs[i] for i in sorted(order[n_val:])], [pairs[i] for i in sorted(order[:n_val])]


def match_points(
    source: FloatArray, target: FloatArray, T_target_source: FloatArray, radius: float
) -> IntArray:
    """(K, 2) rows (source index, index of the nearest target point) where the moved source point has a
    target point within ``radius``."""
    distances, nearest = cKDTree(target).query(
        transform_points(T_target_source, source), distance_upper_bound=radius
    )
    found = np.flatnonzero(np.isfinite(distances))
    return np.column_stack([found, nearest[found]]).astype(np.int64)


class PairSet:
    """The face pairs of a hoard split, made into training pairs on demand (faces read once)."""

    def __init__(
        self,
        root: str | Path,
        split: str = "registration_train",
        *,
        voxel: float = 0.1,
        match_radius: float | None = None,
        pairs: Sequence[FacePair] | None = None,
    ) -> None:
        self.truth = load_truth(root)
        self.split, self.voxel = split, voxel
        self.match_radius = voxel if match_radius is None else match_radius
        self.pairs = list(face_pairs(self.truth, split) if pairs is None else pairs)
        if not self.pairs:
            raise TruthError(f"{self.truth.root}: split {split!r} has no two faces of one die to pair")
        self._clouds: dict[str, tuple[FloatArray, FloatArray]] = {}

    def __len__(self) -> int:
        return len(self.pairs)

    def subset(self, pairs: Sequence[FacePair]) -> PairSet:
        """The same hoard (and read faces) with other pairs."""
        other = object.__new__(PairSet)
        other.__dict__ |= self.__dict__ | {"pairs": list(pairs)}
        return other

    @cached_property
    def faces(self) -> list[str]:
        return sorted({face for pair in self.pairs for face in pair})

    def cloud(self, face_id: str) -> FloatArray:
        """The face's points grid-sampled at ``voxel`` (kept in memory)."""
        return self._sampled(face_id)[0]

    def normals(self, face_id: str) -> FloatArray:
        """The unit normals of :meth:`cloud`'s points."""
        return self._sampled(face_id)[1]

    def _sampled(self, face_id: str) -> tuple[FloatArray, FloatArray]:
        if face_id not in self._clouds:
            from coindie.io import read_scan
            from coindie.preprocess.sampling import grid_sample

            sampled = grid_sample(read_scan(self.truth.faces[face_id].path), self.voxel)
            assert sampled.normals is not None
            self._clouds[face_id] = (sampled.points, sampled.normals)
        return self._clouds[face_id]

    def make(
        self,
        index: int,
        seed: Sequence[int] | int,
        augmentation: Augmentation = TRAINING,
        turn_tolerance_deg: float | None = None,
    ) -> TrainingPair:
        """Training pair ``index``, augmented by draws from ``seed`` (e.g. ``[seed, epoch, index]``).

        With ``turn_tolerance_deg``, the source is first put where the truth says it lies on the target
        and turned about the target's axis by at most that angle; both clouds then get the same
        augmentation (a model that searches turns when matching learns only small ones, in every pose)."""
        a, b = self.pairs[index]
        source, target = self.cloud(a), self.cloud(b)
        T = self.truth.T_true(a, b)
        matches = match_points(source, target, T, self.match_radius)
        rng = np.random.default_rng(seed)
        if turn_tolerance_deg is None:
            A_source, A_target = augmentation.draw_pair(rng, source.mean(0), target.mean(0))
        else:
            from coindie.registration.learned.fcgf import levelling, spin

            target_levelled = levelling(target, self.normals(b))
            turn = rng.uniform(-turn_tolerance_deg, turn_tolerance_deg)
            centre = target.mean(0)
            turn_about_axis = np.linalg.inv(target_levelled) @ spin(turn, centre) @ target_levelled
            A_target = augmentation.draw(rng, centre)
            A_source = A_target @ turn_about_axis @ T
        return TrainingPair(
            f"{a}>{b}",
            transform_points(A_source, source),
            transform_points(A_target, target),
            matches,
            A_target @ T @ np.linalg.inv(A_source),
            _turned(A_source, self.normals(a)),
            _turned(A_target, self.normals(b)),
        )


def level_pair(pair: TrainingPair) -> TrainingPair:
    """Both clouds turned so that their fitted planes are z = 0
    (:func:`coindie.registration.learned.fcgf.levelling`), the truth between them carried along."""
    from coindie.registration.learned.fcgf import levelling

    L_source = levelling(pair.source, pair.source_normals)
    L_target = levelling(pair.target, pair.target_normals)
    return TrainingPair(
        pair.name,
        transform_points(L_source, pair.source),
        transform_points(L_target, pair.target),
        pair.matches,
        L_target @ pair.T_target_source @ np.linalg.inv(L_source),
        _turned(L_source, pair.source_normals),
        _turned(L_target, pair.target_normals),
    )


def _turned(A: FloatArray, normals: FloatArray) -> FloatArray:
    """Normals under the similarity ``A``: its rotation (a uniform scale does not turn them)."""
    turned = normals @ A[:3, :3].T
    return turned / np.linalg.norm(turned, axis=1, keepdims=True)


def crop(pair: TrainingPair, radius: float, rng: np.random.Generator) -> TrainingPair:
    """The pair cut to the discs of ``radius`` mm (in the coin's plane and out of it: balls) around a
    random matched place: a source point and its true image in the target.

    FCGF is fully convolutional, so it can learn on parts of the faces (as it learns on fragments of
    scenes): a 6 mm crop has a quarter of a coin's voxels, so a step costs a quarter as much, and the
    descriptors, whose receptive field is ~5 mm, see the same kind of neighbourhoods."""
    centre = pair.source[pair.matches[rng.integers(len(pair.matches)), 0]]
    keep_source = np.flatnonzero(np.linalg.norm(pair.source - centre, axis=1) <= radius)
    image = transform_points(pair.T_target_source, centre[None, :])[0]
    keep_target = np.flatnonzero(np.linalg.norm(pair.target - image, axis=1) <= radius)
    new_source = np.full(len(pair.source), -1)
    new_source[keep_source] = np.arange(len(keep_source))
    new_target = np.full(len(pair.target), -1)
    new_target[keep_target] = np.arange(len(keep_target))
    matches = np.column_stack([new_source[pair.matches[:, 0]], new_target[pair.matches[:, 1]]])
    return TrainingPair(
        pair.name,
        pair.source[keep_source],
        pair.target[keep_target],
        matches[(matches >= 0).all(axis=1)],
        pair.T_target_source,
        pair.source_normals[keep_source],
        pair.target_normals[keep_target],
    )
