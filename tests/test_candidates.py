"""Candidate search: the descriptor ignores how the coin lies, the index finds same-die partners, and the
recall figures count what they should."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from coindie.candidates import candidate_pairs, candidate_recall, nearest_neighbours
from coindie.candidates.descriptor import face_descriptor
from coindie.preprocess import grid_sample
from coindie.transforms import rigid


@pytest.fixture(scope="module")
def hoard(tmp_path_factory) -> Path:
    from coindie.synth.hoard import PhysicsParams, synthesize
    from coindie.synth.scanner import ScanParams

    out = tmp_path_factory.mktemp("hoard")
    # riedones at 3 %: several dies of one type per group, the hard case for a global descriptor
    synthesize(
        out,
        preset="riedones",
        scale=0.03,
        seed=2,
        physics=PhysicsParams(scan=ScanParams(spacing_mm=0.1)),
        workers=2,
    )
    return out


@pytest.fixture(scope="module")
def described(hoard) -> tuple[list[str], np.ndarray, list[str]]:
    from coindie.io import open_dataset

    dataset = open_dataset(hoard)
    assert dataset.labels is not None
    ids, descriptors = [], []
    for scan in dataset.iter_scans():
        ids.append(str(scan.id))
        descriptors.append(face_descriptor(grid_sample(scan, 0.1)))
    return ids, np.stack(descriptors), [dataset.labels[i] for i in ids]


def _cosine(a: np.ndarray, b: np.ndarray) -> float:
    return float(a @ b / np.linalg.norm(a) / np.linalg.norm(b))


def test_descriptor_ignores_rotation_and_translation(hoard, described) -> None:
    from coindie.io import read_scan

    ids, descriptors, dies = described
    scan = grid_sample(read_scan(hoard / f"{ids[0]}.ply"), 0.1)
    angle = np.radians(73.0)
    turn = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
    moved = face_descriptor(scan.transformed(rigid(turn, np.array([3.0, -2.0, 1.5]))))
    same = _cosine(moved, descriptors[0])
    centred = descriptors - descriptors.mean(axis=0)
    others = [j for j in range(len(ids)) if dies[j] != dies[0] and ids[j][-1] == ids[0][-1]]
    assert same > 0.99
    # closer to itself turned than to any face of another die, in the index's own (standardised) metric
    moved_centred = moved - descriptors.mean(axis=0)
    assert _cosine(moved_centred, centred[0]) > max(_cosine(moved_centred, centred[j]) for j in others)


def test_same_die_partners_are_found_among_few_candidates(described) -> None:
    ids, descriptors, dies = described
    for side in "DR":
        rows = [i for i, face in enumerate(ids) if face.endswith(side)]
        neighbours, similarity = nearest_neighbours(descriptors[rows], k=3)
        assert np.all(np.diff(similarity, axis=1) <= 1e-6)  # best first
        assert all(i not in row for i, row in enumerate(neighbours))  # never itself
        recall = candidate_recall(neighbours, [dies[i] for i in rows])
        assert recall.face_recall >= 0.95, (side, recall)
        assert recall.die_connected >= 0.9, (side, recall)
        assert recall.n_candidate_pairs < len(rows) * (len(rows) - 1) // 2


def test_recall_figures_on_a_known_neighbour_table() -> None:
    # dies: A = {0, 1, 2}, B = {3, 4}, C = {5} (no partner)
    dies = ["A", "A", "A", "B", "B", "C"]
    neighbours = np.array([[1], [5], [3], [0], [3], [4]])
    recall = candidate_recall(neighbours, dies)
    assert recall.n_same_die_pairs == 3 + 1
    # candidate pairs: 0-1, 1-5, 2-3, 0-3, 3-4, 4-5 -> same-die: 0-1, 3-4
    assert recall.n_candidate_pairs == 6
    assert recall.pair_recall == pytest.approx(2 / 4)
    # faces with a partner: 0..4; those finding one: 0 (1), 4 (3); 3 finds 0 (wrong)
    assert recall.face_recall == pytest.approx(2 / 5)
    # die A: 2 is not linked to 0 or 1 -> not connected; die B connected
    assert recall.die_connected == pytest.approx(1 / 2)
    assert candidate_pairs(neighbours) == {(0, 1), (1, 5), (2, 3), (0, 3), (3, 4), (4, 5)}


def test_hnsw_index_agrees_with_the_exact_one() -> None:
    rng = np.random.default_rng(0)
    centres = rng.normal(size=(50, 32))
    points = np.repeat(centres, 4, axis=0) + 0.05 * rng.normal(size=(200, 32))
    exact, _ = nearest_neighbours(points, k=3)
    approximate, _ = nearest_neighbours(points, k=3, exact_below=0)
    agreement = np.mean([len(set(a) & set(b)) / 3 for a, b in zip(exact, approximate, strict=True)])
    assert agreement > 0.95
    groups = np.arange(200) // 4
    assert np.all(groups[exact] == groups[:, None])  # the three others of each cluster
