"""The wide world's axes: each new scanner and damage axis does what docs/synthetic.md says, the named
physics (default, wide, hard, AXIS:LEVEL) are deterministic and within their documented ranges."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest
from scipy.spatial import cKDTree
from typer.testing import CliRunner

from coindie.cli import app
from coindie.errors import ParameterError
from coindie.synth.circulation import CirculationParams, CirculationSpec, circulate, crust_heights, dent_share
from coindie.synth.design import Family, make_die, make_type
from coindie.synth.face import FaceSpec, make_face, sample_face_spec
from coindie.synth.life import LifeParams
from coindie.synth.physics import (
    AXES,
    BENCHMARK_ROWS,
    HIGH,
    LEVELS,
    LOW,
    MIDDLE,
    PhysicsParams,
    axis_physics,
    hard_physics,
    physics_by_name,
    wide_physics,
)
from coindie.synth.scanner import ScanParams
from coindie.synth.strike import StrikeParams, coin_grid, sample_strike, strike, weak_share
from coindie.synth.writer import HOARD_FILE, read_truth, to_jsonable

ORDINARY = StrikeParams(double_probability=0, bend_probability=0, chunk_probability=0, flaw_probability=0)
CALM_LIFE = LifeParams(softening_blur_mm=0.0, relief_loss=0.0, cracks_mean=0.0)


@pytest.fixture(scope="module")
def die():
    return make_die(make_type(Family.OBVERSE, 11), "D1", 1, life=CALM_LIFE)


def spec_with(seed: int = 0, **scan_changes) -> FaceSpec:
    """An ordinary, undamaged face at 0.1 mm with noise; ``scan_changes`` set its scan spec."""
    scan = ScanParams(spacing_mm=0.1, noise_mm=(0.01, 0.01))
    spec = sample_face_spec(np.random.default_rng(seed), 0.3, strike=ORDINARY, scan=scan)
    strike_spec = dataclasses.replace(spec.strike, weak=())
    return dataclasses.replace(
        spec,
        strike=strike_spec,
        circulation=CirculationSpec(),
        scan=dataclasses.replace(spec.scan, **scan_changes),
    )


def coin_frame(face, spec: FaceSpec) -> tuple[np.ndarray, np.ndarray]:
    T = np.linalg.inv(spec.scan.T_scan_coin())
    n = face.info["n_face_points"]
    return face.scan.points[:n] @ T[:3, :3].T + T[:3, 3], face.scan.normals[:n] @ T[:3, :3].T


# --- the default leaves hoards as they were ------------------------------------------------------------


def test_new_axes_at_their_defaults_are_left_out_of_the_records():
    physics = to_jsonable(PhysicsParams())
    assert "scanners" not in physics
    assert "smoothing_mm" not in physics["scan"] and "hole_share" not in physics["scan"]
    assert "crust_share" not in physics["circulation"] and "wear_min" not in physics["circulation"]
    assert "off_centre_max_share" not in physics["strike"]
    spec = to_jsonable(sample_face_spec(np.random.default_rng(0), 0.5))
    assert "holes" not in spec["scan"] and "crust_seed" not in spec["circulation"]
    # ... and are written once used.
    assert to_jsonable(ScanParams(smoothing_mm=0.05))["smoothing_mm"] == 0.05


def test_switched_off_axes_draw_nothing():
    """A spec drawn with the new axes explicitly off is the default one: the random draws are unchanged."""
    off = sample_face_spec(
        np.random.default_rng(4),
        0.5,
        strike=StrikeParams(off_centre_max_share=1.0),
        circulation=CirculationParams(wear_min=0.0, crust_share=(0.0, 0.0)),
        scan=ScanParams(estimated_normals=0.0, hole_share=(0.0, 0.0), smoothing_mm=0.0),
    )
    assert off == sample_face_spec(np.random.default_rng(4), 0.5)


# --- scanner axes ------------------------------------------------------------------------------------------


def test_holes_remove_the_asked_share_of_the_face_in_a_few_blobs(die):
    full = spec_with()
    holed = sample_face_spec(
        np.random.default_rng(0),
        0.3,
        strike=ORDINARY,
        scan=ScanParams(spacing_mm=0.1, hole_share=(0.12, 0.12)),
    )
    spec = dataclasses.replace(
        full, scan=dataclasses.replace(full.scan, hole_share=0.12, holes=holed.scan.holes)
    )
    a, b = make_face(die, full, "L0001D", 1), make_face(die, spec, "L0001D", 1)
    n_full, n_holed = a.info["n_face_points"], b.info["n_face_points"]
    assert abs(n_holed / n_full - 0.88) < 0.01
    # The missing vertices form blobs: seen from the kept ones, they are far from every kept vertex.
    kept_xy = coin_frame(b, spec)[0][:, :2]
    missing = cKDTree(kept_xy).query(coin_frame(a, full)[0][:, :2])[0] > 0.2
    assert missing.sum() > 0.5 * (n_full - n_holed)
    assert 1 <= len(spec.scan.holes) <= 3


def test_estimated_normals_differ_from_the_mesh_normals_and_face_up(die):
    mesh_spec = spec_with(2)
    est_spec = dataclasses.replace(
        mesh_spec, scan=dataclasses.replace(mesh_spec.scan, estimated_normals=True)
    )
    mesh = coin_frame(make_face(die, mesh_spec, "L0001D", 3), mesh_spec)[1]
    estimated = coin_frame(make_face(die, est_spec, "L0001D", 3), est_spec)[1]
    assert np.allclose(np.linalg.norm(estimated, axis=1), 1.0)
    assert (estimated[:, 2] > 0).all()
    angle = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", mesh, estimated), -1, 1)))
    assert np.median(angle) > 1.0  # their own errors, not the mesh's
    assert np.median(angle) < 15.0  # but the same surface


def _roughness(points: np.ndarray) -> float:
    """Variance of each height about the mean of its 8 nearest neighbours (the high frequencies)."""
    _, index = cKDTree(points[:, :2]).query(points[:, :2], k=9)
    return float(np.var(points[:, 2] - points[index[:, 1:], 2].mean(axis=1)))


def test_smoothing_lowers_the_high_frequency_height_variance(die):
    raw_spec = spec_with(3, noise_mm=0.02)
    smooth_spec = dataclasses.replace(raw_spec, scan=dataclasses.replace(raw_spec.scan, smoothing_mm=0.15))
    raw = coin_frame(make_face(die, raw_spec, "L0001D", 4), raw_spec)[0]
    smooth = coin_frame(make_face(die, smooth_spec, "L0001D", 4), smooth_spec)[0]
    assert len(raw) == len(smooth) and np.allclose(raw[:, :2], smooth[:, :2])
    assert _roughness(smooth) < 0.3 * _roughness(raw)
    # The low frequencies (the flan's shape) stay: the mean height barely moves.
    assert abs(smooth[:, 2].mean() - raw[:, 2].mean()) < 0.01


# --- damage axes ---------------------------------------------------------------------------------------


def test_crusts_cover_their_share_of_the_flan_with_raised_patches(die):
    spec = spec_with(5)
    surface = strike(die, 0.3, spec.strike, coin_grid(spec.strike, 0.05))
    damage = CirculationSpec(crust_share=0.25, crust_height_mm=0.1, crust_seed=7)
    crust = crust_heights(surface, damage)
    on_flan = surface.inside_depth > 0
    assert abs((crust[on_flan] > 0).mean() - 0.25) < 0.01
    assert crust.min() >= 0 and 0.05 < crust.max() <= 0.1 + 1e-12
    before = surface.relief.copy()
    circulate(surface, damage)
    assert np.allclose(surface.relief - before, crust)
    # A few patches, not a sprinkle: most crust pixels have crust all around them.
    padded = np.pad(crust > 0, 1)
    inner = padded[:-2, 1:-1] & padded[2:, 1:-1] & padded[1:-1, :-2] & padded[1:-1, 2:]
    assert (inner & (crust > 0)).sum() > 0.9 * (crust > 0).sum()


def test_high_wear_takes_seventy_percent_off_the_high_points(die):
    spec = spec_with(6)
    surface = strike(die, 0.3, spec.strike, coin_grid(spec.strike, 0.05))
    on_flan = surface.inside_depth > 0
    before = surface.relief[on_flan]
    top = surface.design_top()
    circulate(surface, CirculationSpec(wear=0.7))
    after = surface.relief[on_flan]
    assert abs(surface.design_top() / top - 0.3) < 0.03
    # The high points stay the highest (planed, not turned into hollows); the low relief barely changes.
    order = np.argsort(before, kind="stable")
    assert np.diff(after[order]).min() > -1e-9
    low = before < 0.1 * top
    assert np.abs(after[low] - before[low]).max() < 0.1 * top


def test_off_centre_is_clipped_at_its_share_of_the_diameter():
    params = axis_physics("offcentre", HIGH).strike
    rng = np.random.default_rng(0)
    strikes = [sample_strike(rng, params) for _ in range(300)]
    share = np.array([np.hypot(*s.offset_mm) / (2 * s.flan_radius_mm) for s in strikes])
    assert share.max() <= 1 / 3 + 1e-9 and share.max() > 0.3 and np.median(share) > 0.1


def test_high_levels_reach_the_issues_extremes():
    rng = np.random.default_rng(1)
    weak = axis_physics("weak", HIGH).strike
    shares = [weak_share(sample_strike(rng, weak), 0.2) for _ in range(100)]
    assert 0.4 < np.percentile(shares, 90) < 0.75  # weak zones over up to about half the face
    corrosion = axis_physics("corrosion", HIGH).circulation
    pits = [dent_share(sample_circulation_pits(rng, corrosion), 10.5) for _ in range(3)]
    assert 0.2 < np.mean(pits) < 0.4 and corrosion.crust_share == (0.15, 0.3)
    cup = axis_physics("cupping", HIGH).strike
    cups = np.array([sample_strike(rng, cup).cup_mm for _ in range(400)])
    differences = np.abs(cups[::2] - cups[1::2])
    assert 0.25 < np.percentile(differences, 90) < 0.5
    wear = axis_physics("wear", HIGH).circulation
    assert (wear.wear_min, wear.wear_max) == (0.35, 0.7)


def sample_circulation_pits(rng, params):
    from coindie.synth.circulation import sample_circulation

    return sample_circulation(rng, params, 10.5).pits


# --- named physics -----------------------------------------------------------------------------------------


def _scanners(physics: PhysicsParams) -> list[ScanParams]:
    return list(physics.all_scanners())


def test_axis_levels_stay_in_the_documented_ranges():
    for axis in AXES:
        low, middle, high = (axis_physics(axis, level) for level in (LOW, MIDDLE, HIGH))
        assert low != high and middle not in (low, high), axis
        for physics in (low, middle, high):
            for scan in _scanners(physics):
                assert 0.02 <= scan.spacing_mm <= 0.15 or scan.spacing_mm == 0.05
                assert scan.hole_share[1] <= 0.15 and scan.smoothing_mm <= 0.15
                assert scan.noise_mm[1] <= 0.03
            assert physics.strike.cup_mm <= 0.15 and physics.strike.off_centre_max_share <= 1.0
            assert physics.circulation.wear_max <= 0.7 and physics.circulation.crust_share[1] <= 0.3
    assert axis_physics("spacing", LOW).scan.spacing_mm == 0.02
    assert axis_physics("spacing", HIGH).scan.spacing_mm == 0.15
    assert axis_physics("noise", HIGH).scan.noise_mm == (0.03, 0.03)
    assert axis_physics("spacing", MIDDLE).scan.spacing_mm == pytest.approx(0.085)
    mixed = axis_physics("scanners", HIGH)
    assert len(mixed.scanners) == 1 and mixed.scanners[0].spacing_mm > 2 * mixed.scan.spacing_mm


def test_hard_sets_every_axis_and_rows_cover_every_axis():
    hard = hard_physics()
    for axis in AXES:
        assert axis_physics(axis, HIGH) != PhysicsParams()
    assert hard.scan.spacing_mm == 0.15 and hard.scan.noise_mm == (0.03, 0.03)
    assert hard.strike.bend_probability == 0.5 and hard.circulation.wear_max == 0.7
    assert len(hard.scanners) == 1
    assert {row.split(":")[0] for row in BENCHMARK_ROWS} == {*AXES, "hard"}
    assert set(LEVELS) == {LOW, MIDDLE, HIGH}


def test_wide_is_a_function_of_the_seed_and_holds_the_asked_axes():
    assert wide_physics(3) == wide_physics(3) == physics_by_name("wide").resolve(3)
    draws = [wide_physics(s) for s in range(8)]
    assert len({d.strike.cup_mm for d in draws}) == 8
    assert len({len(d.scanners) for d in draws}) > 1  # some hoards mix scanners
    spacings = [s.spacing_mm for d in draws for s in d.all_scanners()]
    assert 0.02 <= min(spacings) and max(spacings) <= 0.15
    held = physics_by_name("wide,noise:middle").resolve(3)
    assert all(s.noise_mm == (0.0165, 0.0165) for s in held.all_scanners())
    free = wide_physics(3)
    assert held.strike == free.strike and held.circulation == free.circulation  # the other axes stay


def test_physics_names_are_parsed_and_bad_ones_refused_by_name():
    assert physics_by_name("default").resolve(0) == PhysicsParams()
    assert physics_by_name("noise:high").resolve(0) == axis_physics("noise", HIGH)
    assert physics_by_name("hard").resolve(5) == hard_physics()
    both = physics_by_name("noise:high,spacing:high").resolve(0)
    assert both.scan.noise_mm == (0.03, 0.03) and both.scan.spacing_mm == 0.15
    for bad, word in (("nope", "unknown physics"), ("noise:extreme", "unknown level"), ("fur:high", "axis")):
        with pytest.raises(ParameterError, match=word):
            physics_by_name(bad)


# --- hoards ------------------------------------------------------------------------------------------------


def test_a_hoard_mixes_its_scanners_face_by_face(tmp_path):
    from coindie.synth.hoard import synthesize

    physics = PhysicsParams(scan=ScanParams(spacing_mm=0.15), scanners=(ScanParams(spacing_mm=0.12),))
    synthesize(tmp_path, preset="tiny", seed=1, physics=physics)
    truth = read_truth(tmp_path)
    by_scanner: dict[int, set[float]] = {}
    for record in truth["faces"].values():
        scanner = record["physics"]["scanner"]
        by_scanner.setdefault(scanner, set()).add(record["physics"]["spec"]["scan"]["spacing_mm"])
    assert by_scanner == {0: {0.15}, 1: {0.12}}
    assert json.loads((tmp_path / HOARD_FILE).read_text())["physics"] == "custom"


def test_cli_makes_a_wide_hoard_and_records_its_physics(tmp_path):
    out = tmp_path / "wide"
    args = ["synth", str(out), "--preset", "tiny", "--physics", "wide", "--spacing", "0.15", "--quiet"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    hoard = json.loads((out / HOARD_FILE).read_text())
    assert hoard["physics"] == "wide (spacing 0.15 mm)"
    assert hoard["parameters"]["physics"]["strike"]["cup_mm"] == wide_physics(0).strike.cup_mm
    bad = CliRunner().invoke(app, ["synth", str(tmp_path / "x"), "--physics", "nope", "--quiet"])
    assert bad.exit_code == 2 and "unknown physics" in bad.output


def test_a_rescanned_hoard_has_the_same_coins_and_other_scans():
    from coindie.synth.physics import rescanned

    physics = wide_physics(2)
    again = rescanned(physics, noise_factor=2.0, spacing_factor=2.0, added_cup_mm=0.15)
    assert again.scan.noise_mm == (2 * physics.scan.noise_mm[0], 2 * physics.scan.noise_mm[1])
    assert again.scan.spacing_mm == 2 * physics.scan.spacing_mm
    cups = []
    for seed in range(30):
        a, b = (
            sample_face_spec(
                np.random.default_rng(seed), 0.5, strike=p.strike, circulation=p.circulation, scan=p.scan
            )
            for p in (physics, again)
        )
        assert a.circulation == b.circulation and a.scan.yaw_deg == b.scan.yaw_deg
        assert dataclasses.replace(b.strike, cup_mm=a.strike.cup_mm) == a.strike
        assert b.scan.noise_mm == pytest.approx(2 * a.scan.noise_mm)
        cups.append(b.strike.cup_mm - a.strike.cup_mm)
    assert max(np.abs(cups)) <= 0.15 and np.ptp(cups) > 0.2


def test_study_preset_has_twelve_unbalanced_dies_all_in_the_clustering_test():
    from collections import Counter

    from coindie.synth import get_preset, plan_hoard

    plan = plan_hoard(get_preset("study"), 0)
    sizes = Counter(f.die_id for f in plan.faces)
    assert len(plan.faces) == 80 and len(sizes) == 12
    assert sum(n for d, n in sizes.items() if d.startswith("R")) == 40
    assert all("cluster_test" in f.splits for f in plan.faces)
    registration = {f.die_id for f in plan.faces if "registration_test" in f.splits}
    assert len(registration) == 6 and {d[0] for d in registration} == {"D", "R"}
    assert max(sizes.values()) >= 10 and min(sizes.values()) <= 2
    assert len({f.coin for f in plan.faces}) == 40  # every coin has both faces


def test_synthesize_takes_a_physics_by_name_and_resolves_it_with_the_hoard_seed():
    from coindie.synth.hoard import resolve_physics

    assert resolve_physics("wide", 4) == (wide_physics(4), "wide")
    assert resolve_physics(physics_by_name("noise:high"), 4) == (axis_physics("noise", HIGH), "noise:high")
    assert resolve_physics(None, 4) == (PhysicsParams(), "default")
    assert resolve_physics(hard_physics(), 4) == (hard_physics(), "custom")
