"""The canonical order of a cloud's points: (x, y, z) lexicographic, whatever the file's order."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.registration.clouds import canonical_permutation


def _tied_cloud(seed: int) -> np.ndarray:
    """A 0.05 mm grid cloud stored as float32 (many points share an x), with points that share x and y
    (a wall) and exact duplicates."""
    rng = np.random.default_rng(seed)
    xy = rng.integers(0, 400, (20_000, 2)) * 0.05
    z = rng.normal(0.0, 0.1, len(xy))
    points = np.column_stack([xy, z]).astype(np.float32).astype(np.float64)
    wall = np.repeat(points[:50], 3, axis=0)
    wall[:, 2] += np.tile([0.0, 0.1, -0.1], 50)
    return np.vstack([points, wall, points[:20]])


def test_the_canonical_order_is_the_lexicographic_order_of_x_y_z() -> None:
    points = _tied_cloud(0)
    x = np.sort(points[:, 0])
    assert (x[1:] == x[:-1]).sum() > 1000  # the case the tie handling is for
    order = canonical_permutation(points)
    assert np.array_equal(order, np.lexsort(points.T[::-1]))


def test_a_shuffled_cloud_comes_back_in_the_same_order() -> None:
    points = _tied_cloud(1)
    shuffled = points[np.random.default_rng(2).permutation(len(points))]
    assert np.array_equal(points[canonical_permutation(points)], shuffled[canonical_permutation(shuffled)])


def test_a_frozen_scans_content_key_is_its_contents_and_is_kept(monkeypatch: pytest.MonkeyPatch) -> None:
    """Content keys follow the contents: a writeable array that changes gets a new key; a frozen scan
    (read-only arrays) keeps its arrays' digests, gives the key its contents give afresh, and refuses
    changes."""
    import hashlib

    from coindie.registration import clouds
    from coindie.scan import Scan

    rng = np.random.default_rng(3)
    points, normals = rng.normal(size=(500, 3)), np.tile([0.0, 0.0, 1.0], (500, 1))
    before = clouds.content_key(points, normals)
    points[0, 0] += 1e-9
    assert clouds.content_key(points, normals) != before
    scan = clouds.freeze(Scan(points=points.copy(), normals=normals.copy()))
    fresh = clouds.content_key(points, normals)
    calls: list[object] = []
    real = hashlib.sha256

    def counted(*args: bytes) -> object:
        calls.append(args)
        return real(*args)

    monkeypatch.setattr(hashlib, "sha256", counted)
    assert clouds.content_key(scan.points, scan.normals) == fresh
    assert len(calls) == 3  # each array's digest, and the key
    assert clouds.content_key(scan.points, scan.normals) == fresh
    assert len(calls) == 4  # the key alone: the digests were kept
    with pytest.raises(ValueError, match="read-only"):
        scan.points[0, 0] = 0.0
