"""The ``relief`` method's ICP on a noisy scanner: its last stage's points set the pose's precision."""

from __future__ import annotations

import numpy as np

from coindie.registration import get_method
from coindie.registration.metrics import rotation_error_deg
from synthetic_pairs import make_coin_pair


def test_the_last_stages_points_set_the_precision_on_a_noisy_scanner() -> None:
    """Pairs of a 0.03 mm noise scanner (the wide world's noisiest): a last stage of 6,000 source points
    (the default) turns the pose about half as far from the truth as one of the first stages' 2,000."""
    errors: dict[int, list[float]] = {2000: [], 6000: []}
    for seed in range(6):
        pair = make_coin_pair(seed=seed, radius=8.0, spacing=0.07, noise=0.03)
        for n_points, found in errors.items():
            method = get_method("relief", **{"icp.final_points": n_points})
            found.append(
                rotation_error_deg(
                    method.register(pair.source, pair.target).T_target_source, pair.T_target_source
                )
            )
    assert np.mean(errors[6000]) < 0.7 * np.mean(errors[2000])
    assert max(errors[6000]) < 0.1  # degrees: every pose right


def test_the_last_stage_is_skipped_only_where_its_pose_would_be_refused() -> None:
    """Coins of different reliefs: the ICP's first stages slide off the pattern, and the last stage is not
    run; the pose that comes back is the one the full ICP gives (the planar pose, the ICP's refused).
    Coins of one relief: every stage runs, and the pose is the full ICP's."""
    from synthetic_pairs import random_relief, scan_relief

    early = get_method("relief")
    full = get_method("relief", **{"relief.icp_early_refusal": 2.0})
    skipped = 0
    for seed in range(6):
        scanner = {"radius": 10.0, "spacing": 0.1, "noise": 0.01}
        source = scan_relief(random_relief(seed), seed=seed, face_id="a", **scanner)
        target = scan_relief(random_relief(seed + 100), seed=seed + 1, face_id="b", **scanner)
        quick, whole = early.register(source, target), full.register(source, target)
        if any("last stage not run" in note for note in quick.notes):
            skipped += 1
            assert any("ICP pose refused" in note for note in whole.notes)
            np.testing.assert_allclose(quick.T_target_source, whole.T_target_source, atol=1e-9)
    assert skipped >= 3
    for seed in range(3):
        pair = make_coin_pair(seed=seed, radius=8.0)
        quick, whole = early.register(pair.source, pair.target), full.register(pair.source, pair.target)
        assert not any("last stage not run" in note for note in quick.notes)
        np.testing.assert_allclose(quick.T_target_source, whole.T_target_source, atol=1e-9)


def test_a_registration_started_from_a_given_pose_comes_to_the_truth() -> None:
    """``register(..., T_init=...)`` skips the global search: from the true pose turned by 4° about the
    target's up axis and moved 0.4 mm (a pose composed through a third face is about that far off), the ICP
    and the block matching bring it within 0.1° and 0.05 mm of the truth; the notes say where it started. A
    method without a local start refuses the argument."""
    import pytest

    from coindie.errors import ParameterError
    from coindie.registration.metrics import translation_error_mm

    method = get_method("relief")
    for seed in range(3):
        pair = make_coin_pair(seed=seed, radius=9.0, spacing=0.05, noise=0.005)
        turn = np.radians(4.0)
        off = np.eye(4)
        off[:2, :2] = [[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]]
        off[:2, 3] = (0.3, -0.27)
        T_off = off @ pair.T_target_source  # the target's scan frame: its face lies near z = const
        assert rotation_error_deg(pair.T_target_source, T_off) > 3.9
        result = method.register(pair.source, pair.target, T_init=T_off)
        assert result.valid, result.reason
        assert result.notes[0].startswith("from a given pose")
        assert rotation_error_deg(pair.T_target_source, result.T_target_source) < 0.1
        assert translation_error_mm(pair.T_target_source, result.T_target_source) < 0.05
    with pytest.raises(ParameterError, match="cannot start from a given pose"):
        get_method("fpfh+teaser+icp").register(pair.source, pair.target, T_init=T_off)
