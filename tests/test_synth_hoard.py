"""The hoard side of the generator: presets, plan (die sizes, die links, splits), outputs, CLI.

Plan-level tests run on the full ``riedones`` preset (planning 2,070 faces is pure data); generation tests
use the ``tiny`` preset with coarse settings.
"""

from __future__ import annotations

import filecmp
import json
from collections import Counter, defaultdict

import numpy as np
import pytest
from scipy.spatial import cKDTree
from scipy.stats import ks_2samp, spearmanr
from typer.testing import CliRunner

from coindie.cli import app
from coindie.errors import ParameterError
from coindie.io import open_dataset, read_labels, read_ply
from coindie.synth import get_preset, plan_hoard
from coindie.synth.plan import draw_group_sizes, link_stats, same_die_pairs
from coindie.synth.presets import (
    BEARD,
    CLUSTER_TEST,
    CLUSTER_TRAIN,
    CLUSTER_VAL,
    OBVERSE,
    REG_TEST,
    REG_TRAIN,
    REVERSE,
    DieGroup,
    real_die_sizes,
)
from coindie.synth.writer import HOARD_FILE, read_splits, read_truth, true_transform
from real_data import RIEDONES3D

CLUSTER_SPLITS = (CLUSTER_TRAIN, CLUSTER_VAL, CLUSTER_TEST)


@pytest.fixture(scope="module")
def riedones():
    return plan_hoard(get_preset("riedones"), seed=11)


def _faces(plan, split, family):
    return [f for f in plan.faces_in(split) if f.family == family]


def _n_dies(faces):
    return len({f.die_id for f in faces})


# --- presets and plan ------------------------------------------------------------------------------------


def test_riedones_has_the_studys_faces_dies_and_coins(riedones):
    families = Counter(f.family for f in riedones.faces)
    assert families == {BEARD: 81, OBVERSE: 887, REVERSE: 1102}
    assert Counter(d.family for d in riedones.dies) == {BEARD: 7, OBVERSE: 74, REVERSE: 212}
    assert len({f.face_id for f in riedones.faces}) == 2070
    beard_coins = sorted(f.coin for f in riedones.faces if f.family == BEARD)
    assert beard_coins == list(range(1, 82))  # L0001D-L0081D are the beard obverses
    obverse, reverse = riedones.coin_dies()
    plain_both = set(obverse) & set(reverse) - set(beard_coins)
    assert len(plain_both) == 881 and set(beard_coins) <= set(reverse)
    for die in riedones.dies:
        assert die.size == sum(f.die_id == die.die_id for f in riedones.faces)


def test_riedones_splits_have_the_papers_counts(riedones):
    assert [len(_faces(riedones, REG_TEST, f)) for f in (BEARD, OBVERSE, REVERSE)] == [80, 80, 79]
    assert [_n_dies(_faces(riedones, REG_TEST, f)) for f in (BEARD, OBVERSE, REVERSE)] == [6, 6, 15]
    assert len(riedones.faces_in(REG_TRAIN)) == len(_faces(riedones, REG_TRAIN, OBVERSE)) == 200
    assert [len(_faces(riedones, s, OBVERSE)) for s in CLUSTER_SPLITS] == [418, 181, 288]
    assert [len(_faces(riedones, s, REVERSE)) for s in CLUSTER_SPLITS] == [510, 299, 293]
    assert [len(_faces(riedones, s, BEARD)) for s in CLUSTER_SPLITS] == [0, 0, 81]
    tests = [_n_dies(_faces(riedones, CLUSTER_TEST, f)) for f in (BEARD, OBVERSE, REVERSE)]
    assert tests == [7, 14, 30]


def test_riedones_meets_the_papers_pair_counts(riedones):
    def pairs(faces):
        return same_die_pairs(np.array(list(Counter(f.die_id for f in faces).values())))

    assert pairs(riedones.faces_in(REG_TEST)) == 2158  # the registration benchmark's pairs
    assert pairs(riedones.faces_in(REG_TRAIN)) == 2132  # FCGF's training pairs


@pytest.mark.parametrize("scale", [1.0, 0.05])
def test_splits_are_whole_dies_and_disjoint(scale):
    plan = plan_hoard(get_preset("riedones", scale), seed=3)
    splits_of_die = defaultdict(set)
    for face in plan.faces:
        splits_of_die[face.die_id].add(face.splits)
        assert sum(s in face.splits for s in CLUSTER_SPLITS) == 1  # exactly one clustering split
        assert not (REG_TEST in face.splits and REG_TRAIN in face.splits)
        if REG_TRAIN in face.splits:
            assert CLUSTER_TRAIN in face.splits
    assert all(len(s) == 1 for s in splits_of_die.values())  # every face of a die in the same splits
    reg_test_dies = {f.die_id for f in plan.faces_in(REG_TEST)}
    assert reg_test_dies.isdisjoint({f.die_id for f in plan.faces_in(REG_TRAIN)})
    assert reg_test_dies.isdisjoint({f.die_id for f in plan.faces_in(CLUSTER_TRAIN)})


@pytest.mark.parametrize("scale", [0.03, 0.1])
def test_scaled_preset_shrinks_every_group_proportionally(scale):
    full, small = get_preset("riedones"), get_preset("riedones", scale)
    for big, little in zip(full.groups, small.groups, strict=True):
        assert little.splits == big.splits and little.family == big.family
        assert little.n_dies == max(1, round(big.n_dies * scale))
        assert little.n_coins == max(little.n_dies, round(big.n_coins * scale))
    plan = plan_hoard(small, seed=5)
    families = Counter(f.family for f in plan.faces)
    assert families == {family: small.n_coins(family) for family in (BEARD, OBVERSE, REVERSE)}
    assert abs(len(plan.faces) - 2070 * scale) <= len(full.groups)


def test_plan_is_a_function_of_the_seed():
    preset = get_preset("riedones", 0.1)
    assert plan_hoard(preset, 4) == plan_hoard(preset, 4)
    assert plan_hoard(preset, 4).labels() != plan_hoard(preset, 5).labels()


def test_die_sizes_resemble_the_experts_and_hit_group_totals(riedones):
    for family in (OBVERSE, REVERSE):
        sizes = [d.size for d in riedones.dies if d.family == family]
        assert ks_2samp(sizes, real_die_sizes(family)).statistic < 0.25
    rng = np.random.default_rng(0)
    pool = np.array(real_die_sizes(REVERSE))
    for n_dies, n_coins in [(15, 79), (15, 214), (3, 3), (1, 40)]:
        sizes = draw_group_sizes(rng, pool, n_dies, n_coins)
        assert len(sizes) == n_dies and sizes.sum() == n_coins and sizes.min() >= 1


def test_die_link_network_pairs_long_obverse_dies_with_short_reverse_dies(riedones):
    obverse, reverse = riedones.coin_dies()
    partners = defaultdict(set)
    for coin in set(obverse) & set(reverse):
        partners[obverse[coin]].add(reverse[coin])
    big = [die for die, n in Counter(obverse.values()).items() if n >= 10]
    assert all(len(partners[die]) >= 2 for die in big)
    stats = link_stats(obverse, reverse)
    assert stats.mean_reverse_per_obverse > 2 and stats.max_obverse_per_reverse >= 2
    lives = {fam: np.mean([d.life for d in riedones.dies if d.family == fam]) for fam in (OBVERSE, REVERSE)}
    assert lives[REVERSE] < lives[OBVERSE]


def test_strikes_fall_within_the_lives_of_both_dies(riedones):
    dies = {d.die_id: d for d in riedones.dies}
    for face in riedones.faces:
        die = dies[face.die_id]
        assert die.start - 1e-12 <= face.strike_time <= die.end + 1e-12
        assert 0.0 <= face.die_age <= 1.0
    by_coin = defaultdict(set)
    for face in riedones.faces:
        by_coin[face.coin].add(face.strike_time)
    assert all(len(times) == 1 for times in by_coin.values())  # both faces of a coin: one strike


def test_catalogue_numbers_are_not_in_striking_order(riedones):
    plain = [f for f in riedones.faces if f.family == OBVERSE]
    rho = spearmanr([f.coin for f in plain], [f.strike_time for f in plain]).statistic
    assert abs(rho) < 0.2


def test_bad_presets_are_refused():
    with pytest.raises(ParameterError, match="unknown hoard preset"):
        get_preset("nope")
    for scale in (0.0, -1.0, 1.5):
        with pytest.raises(ParameterError, match="scale"):
            get_preset("tiny", scale)
    with pytest.raises(ParameterError, match="n_dies"):
        DieGroup(OBVERSE, 5, 3, (CLUSTER_TEST,))
    with pytest.raises(
        ParameterError, match=r"The 'splits' parameter of DieGroup must be .* Got \('holdout',\)\."
    ):
        DieGroup(OBVERSE, 1, 3, ("holdout",))


@pytest.mark.skipif(not RIEDONES3D.is_dir(), reason="the real facts are not next to the repository")
def test_embedded_real_die_sizes_are_the_experts_files():
    for family, name in ((OBVERSE, "experts_obverse_dies.csv"), (REVERSE, "experts_reverse_dies.csv")):
        labels = read_labels(RIEDONES3D / name)
        assert sorted(Counter(labels.values()).values(), reverse=True) == real_die_sizes(family)


# --- generation --------------------------------------------------------------------------------------------


def _coarse_physics():
    from coindie.synth.design import DieParams
    from coindie.synth.hoard import PhysicsParams
    from coindie.synth.scanner import ScanParams
    from coindie.synth.strike import StrikeParams

    # Coarse and without the rare large deformations (bends, double strikes), which the truth test excludes.
    strike = StrikeParams(bend_probability=0.0, double_probability=0.0, cup_mm=0.01)
    return PhysicsParams(die=DieParams(pitch_mm=0.05), strike=strike, scan=ScanParams(spacing_mm=0.1))


@pytest.fixture(scope="module")
def tiny_hoards(tmp_path_factory):
    from coindie.synth.hoard import synthesize

    made = {}
    for workers in (1, 2):
        out = tmp_path_factory.mktemp(f"tiny_w{workers}")
        synthesize(out, preset="tiny", seed=7, physics=_coarse_physics(), workers=workers)
        made[workers] = out
    return made


def test_hoard_is_identical_whatever_the_number_of_workers(tiny_hoards):
    one, two = tiny_hoards[1], tiny_hoards[2]
    names = sorted(p.name for p in one.iterdir())
    assert names == sorted(p.name for p in two.iterdir())
    assert sum(n.endswith(".ply") for n in names) == 16
    _, mismatch, errors = filecmp.cmpfiles(one, two, [n for n in names if n != HOARD_FILE], shallow=False)
    assert mismatch == [] and errors == []
    settings = [json.loads((d / HOARD_FILE).read_text())["parameters"] for d in (one, two)]
    assert settings[0] == settings[1]


@pytest.mark.slow
def test_hoard_made_on_a_dask_cluster_is_the_same(tiny_hoards, tmp_path):
    from coindie.synth.hoard import synthesize

    one = tiny_hoards[1]
    synthesize(tmp_path, preset="tiny", seed=7, physics=_coarse_physics(), workers=2, dask="local")
    names = sorted(p.name for p in one.iterdir() if p.name != HOARD_FILE)
    _, mismatch, errors = filecmp.cmpfiles(one, tmp_path, names, shallow=False)
    assert mismatch == [] and errors == []


def test_outputs_are_readable_and_agree_with_the_plan(tiny_hoards):
    out = tiny_hoards[1]
    plan = plan_hoard(get_preset("tiny"), seed=7)
    labels = read_labels(out / "labels.csv")
    assert {str(k): v for k, v in labels.items()} == plan.labels()
    splits = read_splits(out / "splits.csv")
    assert {(f, s) for s, faces in splits.items() for f in faces} == set(plan.split_rows())
    dataset = open_dataset(out)
    assert len(dataset) == len(plan.faces) and dataset.labels is not None
    hoard = json.loads((out / HOARD_FILE).read_text())
    assert (hoard["preset"], hoard["seed"], hoard["n_faces"]) == ("tiny", 7, 16)
    truth = read_truth(out)
    assert set(truth["faces"]) == {f.face_id for f in plan.faces}
    assert truth["faces"]["L0001D"]["die_age"] == plan.faces[0].die_age


def _relief(out, truth, face_id):
    scan = read_ply(out / f"{face_id}.ply")
    return scan.subset(np.arange(truth["faces"][face_id]["physics"]["n_face_points"]))


def test_true_transforms_map_a_face_onto_the_other_faces_of_its_die(tiny_hoards):
    out = tiny_hoards[1]
    truth = read_truth(out)
    by_die = defaultdict(list)
    for face_id, record in sorted(truth["faces"].items()):
        by_die[record["die_id"]].append(face_id)
    pairs = [(faces[0], b) for faces in by_die.values() for b in faces[1:]]
    assert len(pairs) >= 5
    for a, b in pairs:
        source, target = _relief(out, truth, a), _relief(out, truth, b)
        T_b_a = true_transform(truth, a, b)
        moved = source.points @ T_b_a[:3, :3].T + T_b_a[:3, 3]
        distance, nearest = cKDTree(target.points).query(moved)
        along_normal = np.abs(np.einsum("ij,ij->i", moved - target.points[nearest], target.normals[nearest]))
        assert np.median(distance) < 0.1  # sampling-limited at 0.1 mm spacing
        assert np.median(along_normal) < 0.05
        lifted = moved + 0.2 * target.normals.mean(axis=0)  # 0.2 mm off the face: must not land on it
        assert np.median(cKDTree(target.points).query(lifted)[0]) > 0.1


def test_true_transform_refuses_faces_of_different_dies(tiny_hoards):
    truth = read_truth(tiny_hoards[1])
    a, b = (
        "L0001D",
        next(f for f, r in truth["faces"].items() if r["die_id"] != truth["faces"]["L0001D"]["die_id"]),
    )
    with pytest.raises(ParameterError, match="same die"):
        true_transform(truth, a, b)


def test_a_rerun_reuses_finished_faces_and_other_settings_are_refused(tiny_hoards):
    from coindie.synth.hoard import synthesize

    out = tiny_hoards[1]
    before = {p.name: p.stat().st_mtime_ns for p in out.glob("*.ply")}
    report = synthesize(out, preset="tiny", seed=7, physics=_coarse_physics())
    assert (report.n_made, report.n_reused) == (0, 16)
    assert before == {p.name: p.stat().st_mtime_ns for p in out.glob("*.ply")}
    with pytest.raises(ParameterError, match="other settings"):
        synthesize(out, preset="tiny", seed=8, physics=_coarse_physics())


def test_cli_synth_writes_a_tiny_hoard(tmp_path):
    out = tmp_path / "hoard"
    args = ["synth", str(out), "--preset", "tiny", "--seed", "2", "--spacing", "0.15", "--quiet"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "16 faces" in result.output
    assert len(list(out.glob("*.ply"))) == 16 and (out / "truth.json").exists()
    bad = CliRunner().invoke(app, ["synth", str(tmp_path / "x"), "--preset", "nope", "--quiet"])
    assert bad.exit_code == 2 and "unknown hoard preset" in bad.output


# --- calibration measures ----------------------------------------------------------------------------------


def test_link_stats_count_a_known_network():
    obverse = {1: "D1", 2: "D1", 3: "D1", 4: "D2", 5: "D2"}
    reverse = {1: "R1", 2: "R2", 3: "R2", 4: "R2", 6: "R3"}
    stats = link_stats(obverse, reverse)
    assert (stats.coins_with_both, stats.combinations) == (4, 3)
    assert (stats.max_reverse_per_obverse, stats.max_obverse_per_reverse) == (2, 2)


def test_c2c_histogram_finds_a_known_offset(tiny_hoards):
    from coindie.synth.calibration import bin_centres, histogram_distances, histogram_mode, pair_histogram

    out = tiny_hoards[1]
    face = _relief(out, read_truth(out), "L0001D")
    itself = pair_histogram(face, face, np.eye(4))
    assert histogram_mode(itself) < 0.05
    assert np.sum(itself) * (bin_centres()[1] - bin_centres()[0]) == pytest.approx(1.0)
    lift = np.eye(4)
    lift[:3, 3] = 0.3 * face.normals.mean(axis=0) / np.linalg.norm(face.normals.mean(axis=0))
    lifted = pair_histogram(face, face, lift)  # every point 0.3 mm off the other copy
    assert histogram_mode(lifted) == pytest.approx(0.3, abs=0.02)
    assert histogram_distances(itself, itself) == {"l1": 0.0, "wasserstein_mm": 0.0}
    assert histogram_distances(itself, lifted)["wasserstein_mm"] > 0.2


@pytest.mark.skipif(not RIEDONES3D.is_dir(), reason="the real facts are not next to the repository")
def test_real_mean_histogram_is_read_as_a_unit_density():
    from coindie.synth.calibration import bin_centres, histogram_mode, real_link_stats, real_mean_histogram

    real = real_mean_histogram(RIEDONES3D)
    assert real.shape == (70,) and np.sum(real) * (bin_centres()[1] - bin_centres()[0]) == pytest.approx(1.0)
    assert 0.025 <= histogram_mode(real) <= 0.05
    stats = real_link_stats(RIEDONES3D)
    assert (stats.coins_with_both, stats.combinations, stats.max_reverse_per_obverse) == (881, 326, 29)
