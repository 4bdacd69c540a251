"""Training pairs of a tiny synthetic hoard: true matches, seeded augmentation, held-out dies."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coindie.io.truth import FaceTruth, HoardTruth, TruthError, load_truth
from coindie.registration.learned.pairs import (
    TRAINING,
    VALIDATION,
    Augmentation,
    PairSet,
    crop,
    face_pairs,
    match_points,
    split_pairs,
)
from coindie.transforms import transform_points

VOXEL = 0.2


@pytest.fixture(scope="module")
def hoard(training_hoard):
    return training_hoard


@pytest.fixture(scope="module")
def pairs(hoard) -> PairSet:
    return PairSet(hoard, voxel=VOXEL)


def test_pairs_are_the_faces_of_one_die_in_the_training_split(hoard, pairs) -> None:
    truth = load_truth(hoard)
    train = {f.face_id for f in truth.faces_in("registration_train")}
    assert pairs.pairs and all(a in train and b in train and a < b for a, b in pairs.pairs)
    assert all(truth.faces[a].die == truth.faces[b].die for a, b in pairs.pairs)
    assert len(PairSet(hoard, "registration_test", voxel=VOXEL)) > len(pairs)  # 3 dies of 2-3 faces


@pytest.mark.parametrize("augmentation", [TRAINING, VALIDATION])
def test_matched_points_are_the_same_place_of_the_die(pairs, augmentation) -> None:
    pair = pairs.make(0, [0, 1, 0], augmentation)
    i, j = pair.matches.T
    assert len(pair.matches) > 0.5 * min(len(pair.source), len(pair.target))
    moved = transform_points(pair.T_target_source, pair.source[i])
    # Within one voxel in the die's frame, i.e. within the target's scale (<= 1.2) times a voxel here.
    assert np.linalg.norm(moved - pair.target[j], axis=1).max() <= 1.2 * VOXEL
    # Unaugmented, the truth of truth.json itself puts them within one voxel.
    a, b = pairs.pairs[0]
    T = pairs.truth.T_true(a, b)
    source, target = pairs.cloud(a), pairs.cloud(b)
    assert np.linalg.norm(transform_points(T, source[i]) - target[j], axis=1).max() <= VOXEL


def test_points_without_a_partner_within_the_radius_are_not_matched() -> None:
    source = np.array([[0.0, 0, 0], [1, 0, 0], [5, 5, 5]])
    target = np.array([[1.05, 0, 0], [2.0, 0, 0], [0.0, 0.02, 0]])
    T = np.eye(4)
    np.testing.assert_array_equal(match_points(source, target, T, 0.1), [[0, 2], [1, 0]])
    T[:3, 3] = [1.0, 0, 0]  # moved by 1 mm along x: 0 -> 1.05 (target 0), 1 -> 2 (target 1)
    np.testing.assert_array_equal(match_points(source, target, T, 0.1), [[0, 0], [1, 1]])


def test_augmentation_is_drawn_from_the_seed(pairs) -> None:
    a, b = pairs.make(0, [5, 2, 0]), pairs.make(0, [5, 2, 0])
    np.testing.assert_array_equal(a.source, b.source)
    np.testing.assert_array_equal(a.matches, b.matches)
    assert not np.allclose(pairs.make(0, [5, 3, 0]).source, a.source)


def test_augmentations_stay_within_the_papers_ranges() -> None:
    rng = np.random.default_rng(0)
    center = np.array([1.0, 2.0, 3.0])
    for _ in range(200):
        A = TRAINING.draw(rng, center)
        scale = np.cbrt(np.linalg.det(A[:3, :3]))
        assert 0.9 <= scale <= 1.2
        angles = Rotation.from_matrix(A[:3, :3] / scale).as_euler("xyz", degrees=True)
        assert np.all(np.abs(angles[:2]) <= 25.0 + 1e-9)
        np.testing.assert_allclose(A[:3, :3] @ center + A[:3, 3], center)  # about the centroid
    spins = [
        Rotation.from_matrix(VALIDATION.draw(rng, center)[:3, :3]).as_euler("xyz")[2] for _ in range(200)
    ]
    assert np.ptp(spins) > np.radians(300)  # z turns cover the circle
    assert np.allclose(np.linalg.det(VALIDATION.draw(rng, center)[:3, :3]), 1.0)
    still = Augmentation(tilt_deg=0, spin_deg=0, scale=(1, 1)).draw(rng, center)
    np.testing.assert_allclose(still, np.eye(4), atol=1e-12)


def test_the_two_clouds_of_a_pair_share_one_scale_but_not_one_rotation() -> None:
    rng = np.random.default_rng(1)
    scales, turns = [], []
    for _ in range(50):
        A, B = TRAINING.draw_pair(rng, np.zeros(3), np.ones(3))
        scale_a, scale_b = (np.cbrt(np.linalg.det(M[:3, :3])) for M in (A, B))
        scales.append(scale_a)
        assert scale_a == pytest.approx(scale_b)
        turns.append(np.allclose(A[:3, :3] / scale_a, B[:3, :3] / scale_b))
    assert np.ptp(scales) > 0.2  # the scale is drawn per pair, over 0.9-1.2
    assert not any(turns)


def _truth(dies: dict[str, int]) -> HoardTruth:
    faces, number = {}, 0
    for die, size in dies.items():
        for _ in range(size):
            number += 1
            face = f"L{number:04d}D"
            faces[face] = FaceTruth(face, die, "D", Path(f"{face}.ply"), np.eye(4))
    return HoardTruth(Path("."), faces, {"registration_train": set(faces)})


def test_validation_holds_out_whole_dies() -> None:
    truth = _truth({"D1": 5, "D2": 4, "D3": 3, "D4": 6})
    pairs = face_pairs(truth, "registration_train")
    assert len(pairs) == 10 + 6 + 3 + 15
    train, val = split_pairs(pairs, truth, 0.2, seed=0)
    assert sorted(train + val) == sorted(pairs) and val
    val_dies = {truth.faces[a].die for a, _ in val}
    assert not val_dies & {truth.faces[a].die for a, _ in train}
    assert split_pairs(pairs, truth, 0.2, seed=0) == (train, val)
    assert split_pairs(pairs, truth, 0.0, seed=0) == (pairs, [])


def test_a_single_die_lends_some_of_its_pairs_and_a_single_pair_serves_both() -> None:
    truth = _truth({"D1": 5})
    pairs = face_pairs(truth, "registration_train")
    train, val = split_pairs(pairs, truth, 0.2, seed=1)
    assert len(val) == 2 and sorted(train + val) == sorted(pairs)
    one = face_pairs(_truth({"D1": 2}), "registration_train")
    assert split_pairs(one, _truth({"D1": 2}), 0.2, seed=0) == (one, one)


def test_a_split_without_pairs_is_refused(hoard) -> None:
    with pytest.raises(TruthError, match="cluster_val"):
        PairSet(hoard, "cluster_val")  # one face per die there


def test_normals_turn_with_the_augmentation_and_stay_unit(pairs) -> None:
    pair = pairs.make(0, [0, 4, 0], TRAINING)
    a = pairs.pairs[0][0]
    assert np.allclose(np.linalg.norm(pair.source_normals, axis=1), 1.0)
    # Turned back by the augmentation's rotation (recovered from the points), they are the face's own.
    A = _augmentation_of(pairs.cloud(a), pair.source)
    back = pair.source_normals @ A
    assert np.allclose(back, pairs.normals(a), atol=1e-9)


def _augmentation_of(original: np.ndarray, moved: np.ndarray) -> np.ndarray:
    """The rotation R (3 x 3) of a similarity moved = s R original + t, from the point sets."""
    a, b = original - original.mean(0), moved - moved.mean(0)
    u, _, vt = np.linalg.svd(b.T @ a)
    return u @ np.diag([1, 1, np.linalg.det(u @ vt)]) @ vt


def test_a_cropped_pair_keeps_true_matches_inside_the_balls(pairs) -> None:
    pair = pairs.make(0, [0, 5, 1], TRAINING)
    cut = crop(pair, 3.0, np.random.default_rng(2))
    assert 0 < len(cut.source) < len(pair.source) and 0 < len(cut.target) < len(pair.target)
    assert len(cut.source_normals) == len(cut.source) and len(cut.target_normals) == len(cut.target)
    assert len(cut.matches) > 0.3 * min(len(cut.source), len(cut.target))
    moved = transform_points(cut.T_target_source, cut.source[cut.matches[:, 0]])
    scale = np.cbrt(abs(np.linalg.det(cut.T_target_source[:3, :3])))
    assert np.median(np.linalg.norm(moved - cut.target[cut.matches[:, 1]], axis=1)) < VOXEL * scale
    assert np.ptp(cut.source, axis=0)[:2].max() <= 6.0 + 1e-9
