"""The hoard generator's physics: determinism, exact ground truth, and each effect where it belongs."""

from __future__ import annotations

import dataclasses
import hashlib
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation

from coindie.errors import ParameterError
from coindie.synth._params import describe
from coindie.synth.circulation import CirculationParams, CirculationSpec, Dent, Scratch
from coindie.synth.design import DieParams, Family, make_die, make_type
from coindie.synth.face import FaceSpec, make_face, sample_face_spec
from coindie.synth.life import LifeParams, die_height
from coindie.synth.scanner import ScanParams
from coindie.synth.strike import (
    Bend,
    Chunk,
    DoubleStrike,
    Flaw,
    StrikeParams,
    WeakZone,
    outline_radius,
    sample_strike,
)

QUIET_SCAN = ScanParams(spacing_mm=0.1, noise_mm=(0.0, 0.0), normal_noise_deg=0.0)
#: Ordinary coins: every rare accident switched off.
ORDINARY = StrikeParams(double_probability=0, bend_probability=0, chunk_probability=0, flaw_probability=0)
NO_DAMAGE = CirculationSpec()
CALM_LIFE = LifeParams(softening_blur_mm=0.0, relief_loss=0.0, cracks_mean=0.0)


@pytest.fixture(scope="module")
def obverse_type():
    return make_type(Family.OBVERSE, 11)


@pytest.fixture(scope="module")
def calm_die(obverse_type):
    """A die that neither wears nor cracks: differences between its faces come from the coin alone."""
    return make_die(obverse_type, "D1", 1, life=CALM_LIFE)


def plain_spec(seed: int = 0, **strike_changes) -> FaceSpec:
    """A face with no damage and no scanner noise; ``strike_changes`` replace fields of its strike."""
    spec = sample_face_spec(np.random.default_rng(seed), 0.3, strike=ORDINARY, scan=QUIET_SCAN)
    strike = dataclasses.replace(spec.strike, weak=(), **strike_changes)
    return dataclasses.replace(spec, strike=strike, circulation=NO_DAMAGE)


def coin_frame(face, spec: FaceSpec) -> tuple[np.ndarray, np.ndarray]:
    """Points and normals of a face back in its coin frame."""
    T = np.linalg.inv(spec.scan.T_scan_coin())
    return face.scan.points @ T[:3, :3].T + T[:3, 3], face.scan.normals @ T[:3, :3].T


def die_frame(face) -> tuple[np.ndarray, np.ndarray]:
    T = np.linalg.inv(face.T_scan_die)
    return face.scan.points @ T[:3, :3].T + T[:3, 3], face.scan.normals @ T[:3, :3].T


# --- determinism -----------------------------------------------------------------------------------------


def _face_digest(family: str, seed: int) -> str:
    die = make_die(make_type(family, 5), "D", seed)
    spec = sample_face_spec(np.random.default_rng(seed), 0.7, scan=ScanParams(spacing_mm=0.1))
    face = make_face(die, spec, "L0001D", seed)
    digest = hashlib.sha256()
    for array in (face.scan.points, face.scan.normals, face.scan.colors, face.T_scan_die):
        digest.update(np.ascontiguousarray(array).tobytes())
    return digest.hexdigest()


def test_same_inputs_give_identical_faces_and_other_seeds_do_not(obverse_type):
    die = make_die(obverse_type, "D1", 3)
    spec = sample_face_spec(np.random.default_rng(4), 0.5, scan=ScanParams(spacing_mm=0.1))
    assert spec == sample_face_spec(np.random.default_rng(4), 0.5, scan=ScanParams(spacing_mm=0.1))
    a, b = make_face(die, spec, "L0001D", 9), make_face(die, spec, "L0001D", 9)
    for x, y in (
        (a.scan.points, b.scan.points),
        (a.scan.normals, b.scan.normals),
        (a.T_scan_die, b.T_scan_die),
    ):
        assert np.array_equal(x, y)
    assert json.dumps(a.info) == json.dumps(b.info)
    c = make_face(die, spec, "L0001D", 10)
    assert c.scan.n_points != a.scan.n_points or not np.array_equal(c.scan.points, a.scan.points)
    other = sample_face_spec(np.random.default_rng(5), 0.5, scan=ScanParams(spacing_mm=0.1))
    assert other != spec


def test_a_face_is_bit_identical_in_another_process():
    code = (
        f"import sys; sys.path.insert(0, {str(Path(__file__).parent)!r}); "
        "from test_synth_physics import _face_digest; print(_face_digest('reverse', 3))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == _face_digest("reverse", 3)


def test_dies_are_deterministic_and_differ_from_each_other(obverse_type):
    a, b, c = (make_die(obverse_type, "D", s) for s in (1, 1, 2))
    assert a == b and hash(a) == hash(b)
    assert a.primitives != c.primitives
    assert not np.array_equal(a.relief()[1], c.relief()[1])


# --- ground truth ----------------------------------------------------------------------------------------


def _relief_points(face, other) -> np.ndarray:
    """Die-frame face points on the relief: facing up (within 30 deg), 1 mm away from both coins' edges."""
    p, n = die_frame(face)
    q, _ = die_frame(other)
    keep = (n[:, 2] > np.cos(np.radians(30))) & ~face.is_wall
    for edge in (p[face.is_wall], q[other.is_wall]):
        keep &= cKDTree(edge[:, :2]).query(p[:, :2])[0] > 1.0
    keep &= cKDTree(q[~other.is_wall, :2]).query(p[:, :2])[0] < 0.1  # inside the other flan
    return p[keep]


def _point_to_plane_icp(
    src: np.ndarray, dst: np.ndarray, dst_normals: np.ndarray, iters: int = 15
) -> np.ndarray:
    """A few linearised point-to-plane steps: the best rigid fit near a given start (test helper)."""
    tree = cKDTree(dst)
    for _ in range(iters):
        d, i = tree.query(src)
        near = d < 0.3
        p, q, n = src[near], dst[i[near]], dst_normals[i[near]]
        x = np.linalg.lstsq(np.hstack([np.cross(p, n), n]), np.sum((q - p) * n, axis=1), rcond=None)[0]
        src = src @ Rotation.from_rotvec(x[:3]).as_matrix().T + x[3:]
    return src


def _residuals(a, b, refine: bool = False) -> np.ndarray:
    """NN distances from a's relief to b after the die-frame (true for one die) alignment."""
    src = _relief_points(a, b)
    q, qn = die_frame(b)
    if refine:
        src = _point_to_plane_icp(src, q[~b.is_wall], qn[~b.is_wall])
    return cKDTree(q).query(src)[0]


@pytest.fixture(scope="module")
def dies_of_one_type(obverse_type):
    return make_die(obverse_type, "D1", 1), make_die(obverse_type, "D2", 2)


def _ordinary_face(die, seed: int, age: float, spacing: float):
    spec = sample_face_spec(
        np.random.default_rng(seed), age, strike=ORDINARY, scan=ScanParams(spacing_mm=spacing)
    )
    return make_face(die, spec, "L0001D", seed)


def test_true_transform_maps_a_face_onto_another_face_of_its_die(dies_of_one_type):
    die = dies_of_one_type[0]
    a = _ordinary_face(die, 1, 0.2, 0.1)
    b = _ordinary_face(die, 2, 0.8, 0.05)
    T_b_a = b.T_scan_die @ np.linalg.inv(a.T_scan_die)
    mapped = a.scan.transformed(T_b_a)
    src = mapped.points[_mask_of(a, _relief_points(a, b))]
    distances = cKDTree(b.scan.points).query(src)[0]
    assert len(distances) > 10_000
    assert np.median(distances) < 0.05
    R = a.T_scan_die[:3, :3]
    assert np.allclose(R @ R.T, np.eye(3)) and np.isclose(np.linalg.det(R), 1.0)


def _mask_of(face, relief_die_points: np.ndarray) -> np.ndarray:
    p, _ = die_frame(face)
    return cKDTree(p).query(relief_die_points)[1]


def test_two_dies_of_one_type_differ_clearly_more_than_two_coins_of_one_die(dies_of_one_type):
    d1, d2 = dies_of_one_type
    same = [_residuals(_ordinary_face(d1, s, 0.3, 0.1), _ordinary_face(d1, s + 1, 0.6, 0.05)) for s in (3, 5)]
    other = [
        _residuals(_ordinary_face(d1, s, 0.3, 0.1), _ordinary_face(d2, s + 1, 0.6, 0.05), refine=True)
        for s in (3, 5)
    ]
    for d_same, d_other in zip(same, other, strict=True):
        far_same, far_other = np.mean(d_same > 0.1), np.mean(d_other > 0.1)
        assert far_other > 0.05 and far_other > 5 * far_same
        assert np.mean(d_other) > 1.5 * np.mean(d_same)
        # ...yet the dies are copies of one design: most of the relief still matches closely.
        assert np.median(d_other) < 0.1


# --- die life --------------------------------------------------------------------------------------------


def test_a_crack_appears_only_after_its_start_age_and_along_its_path(obverse_type):
    life = LifeParams(softening_blur_mm=0.0, relief_loss=0.0, cracks_mean=10.0, crack_start_age=(0.5, 0.5))
    die = make_die(obverse_type, "D9", 4, life=life)
    crack = die.cracks[0]
    xs = np.linspace(-12, 12, 241)
    xy = np.stack(np.meshgrid(xs, xs), axis=-1).reshape(-1, 2)
    path = np.asarray(crack.path)
    full_age, half_age = 0.5 + life.crack_growth, 0.5 + life.crack_growth / 2
    for where in (xy, path):
        assert np.array_equal(die_height(die, 0.49, where), die_height(die, 0.0, where))
    # Along its path: the crest rises by its full height once the crack is fully open...
    rise_full = die_height(die, full_age, path) - die_height(die, 0.0, path)
    assert np.median(rise_full) > 0.9 * crack.height
    # ...over a shorter stretch while it grows...
    rise_half = die_height(die, half_age, path) - die_height(die, 0.0, path)
    assert 0 < np.count_nonzero(rise_half > 0.01) < np.count_nonzero(rise_full > 0.01)
    # ...and nowhere else.
    grown = die_height(die, full_age, xy) - die_height(die, 0.0, xy)
    near_any = np.zeros(len(xy), dtype=bool)
    for c in die.cracks:
        near_any |= cKDTree(np.asarray(c.path)).query(xy)[0] < c.half_width + 0.15
    assert np.all(np.abs(grown[~near_any]) < 1e-9)


def test_a_crack_shows_on_a_struck_face_only_after_its_start(obverse_type):
    life = LifeParams(softening_blur_mm=0.0, relief_loss=0.0, cracks_mean=3.0, crack_start_age=(0.5, 0.5))
    die = make_die(obverse_type, "D9", 6, life=life)
    spec = plain_spec(2, offset_mm=(0.0, 0.0))
    young, old = (make_face(die, dataclasses.replace(spec, die_age=a), "x", 1) for a in (0.3, 0.95))
    assert young.info["open_cracks"] == [] and old.info["open_cracks"]
    p_young, _ = coin_frame(young, spec)
    p_old, _ = coin_frame(old, spec)
    n_face = young.info["n_face_points"]
    rise = (p_old[:, 2] - p_young[:, 2])[:n_face]
    raised = p_young[:n_face][rise > 0.01]
    assert len(raised) > 20
    paths = np.vstack([np.asarray(c.path) for c in die.cracks])
    assert np.all(cKDTree(paths).query(raised[:, :2])[0] < 0.3)


def test_die_softening_lowers_the_relief_with_age(obverse_type):
    die = make_die(obverse_type, "D1", 1, life=LifeParams(cracks_mean=0.0, relief_loss=0.2))
    xs = np.linspace(-8, 8, 161)
    xy = np.stack(np.meshgrid(xs, xs), axis=-1).reshape(-1, 2)
    young, old = die_height(die, 0.0, xy) - die.dish(xy), die_height(die, 1.0, xy) - die.dish(xy)
    top = young > np.percentile(young, 95)
    assert np.mean(young[top] - old[top]) > 0.1 * np.mean(young[top])


# --- strike ----------------------------------------------------------------------------------------------


def test_off_centre_strike_moves_the_design_within_the_flan(calm_die):
    centred = plain_spec(3, offset_mm=(0.0, 0.0))
    off = dataclasses.replace(centred, strike=dataclasses.replace(centred.strike, offset_mm=(1.5, -1.0)))
    p0, _ = coin_frame(make_face(calm_die, centred, "x", 1), centred)
    p1, _ = coin_frame(make_face(calm_die, off, "x", 1), off)
    inner0, inner1 = p0[np.hypot(p0[:, 0], p0[:, 1]) < 7], p1[np.hypot(p1[:, 0], p1[:, 1]) < 7]
    tree0 = cKDTree(inner0[:, :2])
    _, same_place = tree0.query(inner1[:, :2])
    _, moved_place = tree0.query(inner1[:, :2] + np.array([1.5, -1.0]))
    dish = calm_die.dish
    z1 = inner1[:, 2] - dish(inner1[:, :2] + [1.5, -1.0])
    err_moved = np.abs(z1 - (inner0[moved_place, 2] - dish(inner0[moved_place, :2])))
    err_same = np.abs(z1 - (inner0[same_place, 2] - dish(inner0[same_place, :2])))
    assert np.median(err_moved) < 0.01
    assert np.percentile(err_same, 90) > 5 * np.percentile(err_moved, 90)


def test_incomplete_strike_lowers_relief_only_in_the_weak_zone(calm_die):
    zone = WeakZone(centre=(-3.0, 2.0), radius_mm=3.0, depth=0.6)
    full = plain_spec(4, offset_mm=(0.0, 0.0))
    weak = dataclasses.replace(full, strike=dataclasses.replace(full.strike, weak=(zone,)))
    p_full, _ = coin_frame(make_face(calm_die, full, "x", 1), full)
    p_weak, _ = coin_frame(make_face(calm_die, weak, "x", 1), weak)
    drop = p_full[:, 2] - p_weak[:, 2]
    distance = np.hypot(p_full[:, 0] + 3.0, p_full[:, 1] - 2.0)
    pixel = 0.08  # bilinear sampling reaches one surface pixel beyond the zone
    assert np.all(np.abs(drop[distance > zone.radius_mm + pixel]) < 1e-12)
    assert drop[distance < zone.radius_mm].max() > 0.1 and drop.min() > -1e-9


def test_double_strike_adds_a_shifted_ghost(calm_die):
    single = plain_spec(5, offset_mm=(0.0, 0.0))
    second = DoubleStrike(shift_mm=(0.8, 0.3), rotation_deg=0.0, strength=0.5)
    double = dataclasses.replace(single, strike=dataclasses.replace(single.strike, double=second))
    p1, _ = coin_frame(make_face(calm_die, single, "x", 1), single)
    p2, _ = coin_frame(make_face(calm_die, double, "x", 1), double)
    n = int(np.count_nonzero(np.hypot(p1[:, 0], p1[:, 1]) < 9))
    face = np.hypot(p1[:, 0], p1[:, 1]) < 9
    rise = (p2[:, 2] - p1[:, 2])[face]
    assert rise.min() > -1e-9
    ghost = p1[face][rise > 0.03, :2]
    assert len(ghost) > 0.01 * n
    relief = die_height(calm_die, 0.3, ghost) - calm_die.dish(ghost)
    shifted = die_height(calm_die, 0.3, ghost + [0.8, 0.3]) - calm_die.dish(ghost + [0.8, 0.3])
    assert np.median(shifted) > np.median(relief) + 0.1


def test_a_broken_chunk_removes_points_beyond_the_break(calm_die):
    whole = plain_spec(6, offset_mm=(0.0, 0.0))
    broken = dataclasses.replace(whole, strike=dataclasses.replace(whole.strike, chunks=(Chunk(30.0, 3.0),)))
    f_whole, f_broken = make_face(calm_die, whole, "x", 1), make_face(calm_die, broken, "x", 1)
    u = np.array([np.cos(np.radians(30.0)), np.sin(np.radians(30.0))])
    cut = whole.strike.flan_radius_mm - 3.0
    beyond_whole = (coin_frame(f_whole, whole)[0][:, :2] @ u > cut + 0.05) & ~f_whole.is_wall
    along_break = coin_frame(f_broken, broken)[0][:, :2] @ u - cut
    assert beyond_whole.sum() > 500 and np.all(along_break[~f_broken.is_wall] < 0.05)
    # The wall follows the break: straight down its edge (leaning out by at most the flare).
    assert np.mean(np.abs(along_break[f_broken.is_wall]) < 0.6) > 0.05
    assert f_broken.scan.n_points < f_whole.scan.n_points


def test_a_flaw_is_a_deep_void_where_it_is(calm_die):
    plain = plain_spec(7, offset_mm=(0.0, 0.0))
    flaw = Flaw(centre=(2.0, -3.0), length_mm=4.0, width_mm=1.0, angle_deg=30.0, depth_mm=0.4)
    flawed = dataclasses.replace(plain, strike=dataclasses.replace(plain.strike, flaws=(flaw,)))
    p0, _ = coin_frame(make_face(calm_die, plain, "x", 1), plain)
    p1, _ = coin_frame(make_face(calm_die, flawed, "x", 1), flawed)
    drop = p0[:, 2] - p1[:, 2]
    a = np.radians(30.0)
    d = p0[:, :2] - [2.0, -3.0]
    u, v = (d @ [np.cos(a), np.sin(a)]) / 2.0, (d @ [-np.sin(a), np.cos(a)]) / 0.5
    inside = u * u + v * v
    assert np.all(np.abs(drop[inside > 1.3]) < 1e-12)
    assert np.median(drop[inside < 0.3]) > 0.3


def test_a_bent_coin_folds_beyond_its_line_and_not_before(calm_die):
    flat = plain_spec(8, offset_mm=(0.0, 0.0))
    bend = Bend(axis_deg=0.0, distance_mm=2.0, angle_deg=10.0, width_mm=1.0)
    bent = dataclasses.replace(flat, strike=dataclasses.replace(flat.strike, bend=bend))
    p0, _ = coin_frame(make_face(calm_die, flat, "x", 1), flat)
    p1, n1 = coin_frame(make_face(calm_die, bent, "x", 1), bent)
    before = p0[:, 0] < 2.0
    assert np.allclose(p1[before], p0[before])
    far = p0[:, 0] > 6.0
    lift = p1[far, 2] - p0[far, 2]
    expected = (p0[far, 0] - 2.5) * np.sin(np.radians(10.0))
    assert np.median(np.abs(lift - expected)) < 0.1
    assert np.allclose(np.linalg.norm(n1, axis=1), 1.0)


def test_sampled_bends_turn_the_smaller_side_so_the_die_truth_holds_for_most_of_the_face():
    rng = np.random.default_rng(0)
    bends = [sample_strike(rng, StrikeParams(bend_probability=1.0)) for _ in range(200)]
    for spec in bends:
        r, d = spec.flan_radius_mm, spec.bend.distance_mm
        # Area of the disc segment beyond the fold line, as a share of the disc.
        segment = r * r * np.arccos(d / r) - d * np.sqrt(r * r - d * d)
        assert 0 < d < r
        assert segment / (np.pi * r * r) < 0.4


# --- circulation -----------------------------------------------------------------------------------------


def test_wear_lowers_high_points_more_than_the_field(calm_die):
    fresh = plain_spec(9, offset_mm=(0.0, 0.0))
    worn = dataclasses.replace(fresh, circulation=CirculationSpec(wear=0.5))
    p0, _ = coin_frame(make_face(calm_die, fresh, "x", 1), fresh)
    p1, _ = coin_frame(make_face(calm_die, worn, "x", 1), worn)
    face = np.hypot(p0[:, 0], p0[:, 1]) < 9
    relief = die_height(calm_die, 0.3, p0[face, :2]) - calm_die.dish(p0[face, :2])
    loss = (p0[:, 2] - p1[:, 2])[face]
    high, field = relief > np.percentile(relief, 97), relief < 0.02
    assert np.mean(loss[high]) > 0.1
    assert np.mean(np.abs(loss[field])) < 0.005


def test_scratches_nicks_and_pits_cut_into_the_surface_where_they_are(calm_die):
    clean = plain_spec(10, offset_mm=(0.0, 0.0))
    damage = CirculationSpec(
        scratches=(Scratch((-5.0, -5.0), (3.0, -5.0), 0.0, 0.05, 0.04),),
        nicks=(Dent((4.0, 4.0), 0.4, 0.15),),
        pits=(Dent((-4.0, 4.0), 0.1, 0.05),),
    )
    hit = dataclasses.replace(clean, circulation=damage)
    p0, _ = coin_frame(make_face(calm_die, clean, "x", 1), clean)
    p1, _ = coin_frame(make_face(calm_die, hit, "x", 1), hit)
    cut = p0[:, 2] - p1[:, 2]
    xy = p0[:, :2]
    on_scratch = (np.abs(xy[:, 1] + 5.0) < 0.05) & (xy[:, 0] > -4.5) & (xy[:, 0] < 2.5)
    in_nick = np.hypot(*(xy - [4.0, 4.0]).T) < 0.2
    near = (np.abs(xy[:, 1] + 5.0) < 0.15) & (xy[:, 0] > -5.2) & (xy[:, 0] < 3.2)
    near |= np.hypot(*(xy - [4.0, 4.0]).T) < 0.5
    near |= np.hypot(*(xy - [-4.0, 4.0]).T) < 0.2
    assert cut[on_scratch].mean() > 0.02 and cut[in_nick].min() > 0.05
    assert np.all(np.abs(cut[~near]) < 1e-12) and cut.min() > -1e-9


# --- scanning --------------------------------------------------------------------------------------------


def test_edge_wall_exists_below_the_rim_with_outward_normals(calm_die):
    spec = plain_spec(11)
    face = make_face(calm_die, spec, "x", 1)
    p, n = coin_frame(face, spec)
    wall = face.is_wall
    assert wall.sum() > 2000 and face.info["n_wall_points"] == wall.sum()
    radial = p[wall, :2] / np.linalg.norm(p[wall, :2], axis=1, keepdims=True)
    assert np.mean(np.sum(n[wall, :2] * radial, axis=1) > 0.5) > 0.98
    r_wall = np.hypot(p[wall, 0], p[wall, 1])
    rim = outline_radius(spec.strike, np.arctan2(p[wall, 1], p[wall, 0]))
    assert np.all(r_wall > rim - 0.02)
    _, nearest_face = cKDTree(p[~wall, :2]).query(p[wall, :2])
    assert np.all(p[wall, 2] < p[~wall][nearest_face, 2] + 0.02)
    assert np.ptp(p[wall, 2] - p[~wall][nearest_face, 2]) > 0.3


def test_noise_along_the_normal_has_the_requested_sd(calm_die):
    quiet = plain_spec(12)
    noisy_scan = dataclasses.replace(quiet.scan, noise_mm=0.008)
    noisy = dataclasses.replace(quiet, scan=noisy_scan)
    p0, n0 = coin_frame(make_face(calm_die, quiet, "x", 1), quiet)
    p1, _ = coin_frame(make_face(calm_die, noisy, "x", 1), noisy)
    along = np.sum((p1 - p0) * n0, axis=1)
    assert abs(np.std(along) / 0.008 - 1.0) < 0.03
    assert np.allclose(p1 - p0, n0 * along[:, None], atol=1e-9)


@pytest.mark.parametrize("spacing", [0.1, 0.05])
def test_vertex_spacing_matches_the_parameter(calm_die, spacing):
    spec = sample_face_spec(
        np.random.default_rng(13), 0.3, strike=ORDINARY, scan=ScanParams(spacing_mm=spacing)
    )
    face = make_face(calm_die, spec, "x", 1)
    p, _ = coin_frame(face, spec)
    phi = np.linspace(-np.pi, np.pi, 20001)
    area = 0.5 * np.trapezoid(outline_radius(spec.strike, phi) ** 2, phi)
    density_spacing = np.sqrt(area / face.info["n_face_points"])
    assert abs(density_spacing / spacing - 1.0) < 0.03
    nn = cKDTree(p[~face.is_wall, :2]).query(p[~face.is_wall, :2], k=2)[0][:, 1]
    assert 0.6 * spacing < np.median(nn) < 1.05 * spacing


def test_normals_are_unit_and_face_up_on_the_field(calm_die):
    spec = plain_spec(14, offset_mm=(0.0, 0.0))
    face = make_face(calm_die, spec, "x", 1)
    p, n = coin_frame(face, spec)
    assert np.allclose(np.linalg.norm(face.scan.normals, axis=1), 1.0)
    inner = ~face.is_wall & (np.hypot(p[:, 0], p[:, 1]) < spec.strike.flan_radius_mm * 0.8)
    # The field: no relief within 0.15 mm (the foot of a stroke is low but steep).
    field = np.ones(int(inner.sum()), dtype=bool)
    for a in np.linspace(0, 2 * np.pi, 8, endpoint=False):
        for r in (0.0, 0.15):
            xy = p[inner, :2] + r * np.array([np.cos(a), np.sin(a)])
            field &= die_height(calm_die, 0.3, xy) - calm_die.dish(xy) < 0.01
    assert field.sum() > 1000
    assert np.all(n[inner][field, 2] > np.cos(np.radians(10)))
    colors_again = np.clip(np.rint((face.scan.normals + 1) * 127.5), 0, 255)
    assert np.array_equal(face.scan.colors, colors_again.astype(np.uint8))


def test_poses_are_rigid_placements_in_the_four_spots_of_the_plate():
    rng = np.random.default_rng(15)
    params = ScanParams(tilt_deg=4.0, plate_offset_mm=20.0, plate_jitter_mm=2.0)
    spots = np.array([[1, 1], [-1, 1], [-1, -1], [1, -1]]) * 20.0
    used = set()
    for _ in range(40):
        T = sample_face_spec(rng, 0.3, scan=params).scan.T_scan_coin()
        R = T[:3, :3]
        assert np.allclose(R.T @ R, np.eye(3)) and np.isclose(np.linalg.det(R), 1.0)
        assert np.degrees(np.arccos(np.clip(R[2, 2], -1, 1))) <= 4.0 + 1e-9
        distance = np.linalg.norm(spots - T[:2, 3], axis=1)
        assert distance.min() < 4 * 2.0 * np.sqrt(2)
        used.add(int(distance.argmin()))
    assert used == {0, 1, 2, 3}


# --- designs and parameters ------------------------------------------------------------------------------


def test_the_three_families_have_their_own_designs():
    obverse, beard, reverse = (make_type(f, 1) for f in Family)
    assert len(beard.primitives) > len(obverse.primitives)
    assert len({obverse.primitives, beard.primitives, reverse.primitives}) == 3
    die = make_die(reverse, "R1", 1)
    assert die.dish_mm > 0 and make_die(obverse, "D1", 1).dish_mm < 0
    grid, relief = die.relief()
    assert grid.nx * grid.pitch >= 30.0 and 0.4 < relief.max() < 1.2


@pytest.mark.parametrize(
    ("cls", "changes", "name"),
    [
        (DieParams, {"element_shift_mm": -0.1}, "element_shift_mm"),
        (LifeParams, {"crack_start_age": (0.9, 0.2)}, "crack_start_age"),
        (StrikeParams, {"off_centre_mm": 100.0}, "off_centre_mm"),
        (CirculationParams, {"wear_max": float("nan")}, "wear_max"),
        (ScanParams, {"spacing_mm": 0.0}, "spacing_mm"),
    ],
)
def test_parameters_outside_their_range_are_refused_by_name(cls, changes, name):
    with pytest.raises(ParameterError, match=name):
        cls(**changes)
    rows = describe(cls)
    assert rows and all(row["doc"] and row["unit"] for row in rows)
    assert name in {row["name"] for row in rows}


def test_an_unknown_family_is_refused_by_name():
    with pytest.raises(ParameterError, match="unknown coin family 'horse'"):
        make_type("horse", 1)
