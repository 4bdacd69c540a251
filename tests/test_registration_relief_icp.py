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
