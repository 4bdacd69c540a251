"""Normals whose signs mean nothing (never oriented, a mesh wound either way) are read pointing out of the
coin, and a scan without normals gets outward ones, whatever the pose the scan was written in."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coindie.io import read_ply, read_scan, write_ply
from coindie.io.orientation import sign_agreement, up_evidence
from coindie.registration.clouds import with_normals
from coindie.scan import Scan


def _turned_over(scan: Scan, seed: int) -> Scan:
    """The scan in a random pose whose face looks down (the scanner's +z is no guide to its up side)."""
    rng = np.random.default_rng(seed)
    turn = Rotation.from_rotvec([np.pi, 0.0, 0.0]) * Rotation.random(random_state=rng)
    R = turn.as_matrix()
    up = R @ np.array([0.0, 0.0, 1.0])
    if up[2] > 0:  # turn it over again about x: the face then looks down
        R = Rotation.from_rotvec([np.pi, 0.0, 0.0]).as_matrix() @ R
    points = scan.points @ R.T + rng.uniform(-50.0, 50.0, 3)
    assert scan.normals is not None
    return Scan(points=points, normals=scan.normals @ R.T, id=scan.id)


def _agreement(normals: np.ndarray, truth: np.ndarray) -> float:
    return float(np.mean(np.einsum("ij,ij->i", normals, truth) > 0))


@pytest.fixture(scope="module")
def faces(training_hoard: Path) -> list[Scan]:
    """Four faces of a synthetic hoard (with their edge wall), each in a pose that turns it face down."""
    paths = sorted(training_hoard.glob("*.ply"))[:4]
    return [_turned_over(read_scan(path), seed) for seed, path in enumerate(paths)]


def test_normals_that_agree_are_read_as_written_unless_all_point_into_the_coin(
    faces: list[Scan], tmp_path: Path
) -> None:
    """Outward normals come back exactly as written (a scanner's consistent normals are not second-guessed);
    the same normals all turned inwards (a mesh wound inside out) come back all turned out again."""
    for i, scan in enumerate(faces):
        assert scan.normals is not None
        for sign in (1.0, -1.0):
            written = Scan(points=scan.points, normals=sign * scan.normals, id=scan.id)
            path = write_ply(tmp_path / f"L000{i + 1}D.ply", written, dtype=np.float64)
            np.testing.assert_allclose(read_scan(path).normals, sign * read_ply(path).normals, atol=1e-12)


def test_normals_of_random_sign_are_read_pointing_out_of_the_coin(faces: list[Scan], tmp_path: Path) -> None:
    """Each normal's sign drawn at random (local PCA never oriented), the face looking down: on reading,
    the normals point out of the coin again, up on the face and outwards on its wall."""
    rng = np.random.default_rng(7)
    for i, scan in enumerate(faces):
        assert scan.normals is not None
        signs = rng.choice([-1.0, 1.0], size=(scan.n_points, 1))
        written = Scan(points=scan.points, normals=signs * scan.normals, id=scan.id)
        assert sign_agreement(written.points, written.normals) < 0.6
        read = read_scan(write_ply(tmp_path / f"L000{i + 1}D.ply", written, dtype=np.float64))
        assert read.normals is not None
        assert _agreement(read.normals, scan.normals) > 0.99


def test_a_scan_without_normals_gets_outward_ones_in_any_pose(faces: list[Scan]) -> None:
    """Normals estimated by local PCA are turned by the face's geometry (its wall below, its relief
    raised), not to the scanner's +z side, which a face looking down does not keep."""
    for scan in faces:
        assert scan.normals is not None
        estimated = with_normals(Scan(points=scan.points, id=scan.id))
        assert estimated.normals is not None
        assert _agreement(estimated.normals, scan.normals) > 0.97


def test_both_cues_point_up_and_the_relief_decides_without_a_wall(faces: list[Scan]) -> None:
    """The wall lies below the face's surface and the relief's heights lean upwards; a face cut inside
    its outline (no wall) is still told up from down by its relief."""
    for scan in faces:
        assert scan.normals is not None
        true_up = scan.normals.mean(axis=0)
        evidence = up_evidence(scan.points, scan.normals)
        assert evidence.cue == "wall"
        assert evidence.sign * evidence.axis @ true_up > 0
        assert evidence.relief_skewness * evidence.axis @ true_up > 0
        centred = scan.points - scan.points.mean(axis=0)
        across = np.linalg.norm(centred - np.outer(centred @ evidence.axis, evidence.axis), axis=1)
        inner = across < 0.7 * across.max()
        cropped = up_evidence(scan.points[inner], scan.normals[inner])
        assert cropped.cue == "relief"
        assert cropped.sign * cropped.axis @ true_up > 0


def test_a_mesh_wound_either_way_is_read_with_outward_normals(tmp_path: Path) -> None:
    """An STL whose triangles on one half of the face are wound the other way (a mesh stitched from two
    scans): the vertex normals of that half point into the coin as written, out of it as read."""
    import trimesh

    from synthetic_pairs import random_relief

    relief = random_relief(3)
    axis = np.arange(-8.0, 8.0 + 1e-9, 0.1)
    x, y = np.meshgrid(axis, axis)
    inside = (x**2 + y**2 <= 64.0).ravel()
    xy = np.column_stack([x.ravel(), y.ravel()])
    vertices = np.column_stack([xy, relief.height(xy)])
    index = np.arange(len(axis) ** 2).reshape(len(axis), len(axis))
    a, b = index[:-1, :-1].ravel(), index[:-1, 1:].ravel()
    c, d = index[1:, :-1].ravel(), index[1:, 1:].ravel()
    triangles = np.concatenate([np.column_stack([a, b, d]), np.column_stack([a, d, c])])
    triangles = triangles[inside[triangles].all(axis=1)]
    flipped = vertices[triangles, 0].mean(axis=1) > 0
    triangles[flipped] = triangles[flipped][:, ::-1]
    R = Rotation.from_rotvec([2.5, 0.4, 0.0]).as_matrix()  # the face looks down
    mesh = trimesh.Trimesh(vertices @ R.T, triangles, process=False)
    path = tmp_path / "L0001D.stl"
    mesh.export(path)
    read = read_scan(path)
    assert read.normals is not None
    truth = relief.normals((read.points @ R)[:, :2]) @ R.T  # the points back in the face's frame
    assert _agreement(read.normals, truth) > 0.99


def test_normals_all_into_a_worn_coin_are_turned_out_by_its_wall_alone(tmp_path: Path) -> None:
    """A face whose relief leans downwards (worn high points, pits and crusts: the relief's lean then
    points the wrong way) is still told up by its wall: its normals, all written into the coin, are read
    out of it; written out of it, they are read as written."""
    from test_preprocess_synthetic import BUMPS, SyntheticCoin, make_scan

    pitted = tuple((x, y, -height, sigma) for x, y, height, sigma in BUMPS)
    scan = _turned_over(make_scan(SyntheticCoin(spacing=0.1, bumps=pitted)), 5)
    assert scan.normals is not None
    true_up = scan.normals.mean(axis=0)
    evidence = up_evidence(scan.points, scan.normals)
    assert evidence.cue == "wall" and evidence.sign * evidence.axis @ true_up > 0
    assert evidence.relief_skewness * evidence.axis @ true_up < 0  # the relief's lean says down
    for sign in (1.0, -1.0):
        written = Scan(points=scan.points, normals=sign * scan.normals, id=scan.id)
        read = read_scan(write_ply(tmp_path / "L0001D.ply", written, dtype=np.float64))
        assert read.normals is not None
        np.testing.assert_allclose(read.normals, read_ply(tmp_path / "L0001D.ply").normals * sign, atol=1e-12)


def _bordered_face(ridge_mm: float = 0.25, wall_mm: float = 0.4, spacing: float = 0.05) -> Scan:
    """A face of 20 mm whose outline cuts through its border (a ridge ``ridge_mm`` high over its outer
    0.5 mm, steep-sided), with a wall going ``wall_mm`` down from the ridge's top, as a scanner looking down
    samples it: outward normals, 0.01 mm of noise on the field, face down in a random pose."""
    rng = np.random.default_rng(0)
    axis = np.arange(-10.0, 10.0 + 1e-9, spacing)
    x, y = (a.ravel() for a in np.meshgrid(axis, axis))
    r = np.hypot(x, y)
    inside = r <= 10.0 - spacing
    x, y, r = x[inside], y[inside], r[inside]
    z = np.where(r >= 9.5, ridge_mm, 0.0) + 0.4 * np.exp(-((x - 2.0) ** 2 + (y + 1.0) ** 2) / 4.0)
    face = np.column_stack([x, y, z + rng.normal(0.0, 0.01, len(z))])
    angles = np.arange(0.0, 2 * np.pi, spacing / 9.5)

    def band(radius: float, low: float, high: float, outward: float) -> tuple[np.ndarray, np.ndarray]:
        a, h = (v.ravel() for v in np.meshgrid(angles, np.arange(low, high, spacing)))
        radial = np.column_stack([np.cos(a), np.sin(a), np.zeros_like(a)])
        return radial * [radius, radius, 0.0] + np.outer(h, [0.0, 0.0, 1.0]), outward * radial

    inner, inner_normals = band(9.5 - spacing / 2, spacing / 2, ridge_mm, -1.0)  # the border's inner flank
    outer, outer_normals = band(10.0, ridge_mm - wall_mm, ridge_mm, 1.0)  # its outer flank, the wall
    points = np.concatenate([face, inner, outer])
    normals = np.concatenate([np.tile([0.0, 0.0, 1.0], (len(face), 1)), inner_normals, outer_normals])
    return _turned_over(Scan(points=points, normals=normals, id="L0001D"), 3)


def test_outward_normals_of_a_face_cut_through_its_border_are_read_as_written(tmp_path: Path) -> None:
    """A steep-sided border at the outline and a shallow wall put most of the points off the face's axis
    at or above the field (a die's border near the flan's edge; ``benchmarks/blind_hoards.py`` read 2 of
    400 faces face down for it): the wall's height then says down, but its normals, mostly pointing away
    from the face's axis, say the scanner's normals point out of the coin, and they are read as written."""
    from coindie.io.orientation import wall_normals_outward

    scan = _bordered_face()
    assert scan.normals is not None
    true_up = scan.normals.mean(axis=0)
    evidence = up_evidence(scan.points, scan.normals)
    assert evidence.cue == "wall" and evidence.sign * evidence.axis @ true_up < 0  # its height misleads
    share = wall_normals_outward(scan.points, scan.normals)
    assert share is not None and share > 0.5
    assert wall_normals_outward(scan.points, -scan.normals) == pytest.approx(1.0 - share)
    path = write_ply(tmp_path / "L0001D.ply", scan, dtype=np.float64)
    np.testing.assert_allclose(read_scan(path).normals, read_ply(path).normals, atol=1e-12)
