"""A face's diameter, and the hoard's coin scale that the design lengths follow."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.preprocess.coin_size import (
    REFERENCE_DIAMETER_MM,
    SCALE_RANGE,
    coin_scale,
    face_diameter,
    hoard_diameter,
)


def disc_face(diameter: float, *, broken: float = 1.0, tilt_deg: float = 35.0, seed: int = 0) -> np.ndarray:
    """A domed face of ``diameter`` mm on a 0.05 mm grid, cut along a chord at ``broken`` x its radius
    (1: whole), with a 1.2 mm edge wall, tilted and moved in the scanner's frame."""
    radius = diameter / 2
    grid = np.arange(-radius, radius, 0.05)
    x, y = (a.ravel() for a in np.meshgrid(grid, grid))
    on = (np.hypot(x, y) <= radius) & (x <= broken * radius)
    x, y = x[on], y[on]
    face = np.column_stack([x, y, 0.3 * np.cos(np.hypot(x, y) / radius)])
    angles = np.linspace(0, 2 * np.pi, 600, endpoint=False)
    rim = np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])
    rim = rim[rim[:, 0] <= broken * radius]
    wall = np.concatenate([np.column_stack([rim, np.full(len(rim), -d)]) for d in np.arange(0, 1.2, 0.05)])
    points = np.concatenate([face, wall])
    t = np.radians(tilt_deg)
    R = np.array([[1, 0, 0], [0, np.cos(t), -np.sin(t)], [0, np.sin(t), np.cos(t)]])
    shuffled = np.random.default_rng(seed).permutation(len(points))
    return points[shuffled] @ R.T + [40.0, -12.0, 7.0]


@pytest.mark.parametrize("diameter", [10.0, 20.0, 34.0])
def test_a_faces_diameter_is_measured_whatever_its_pose(diameter):
    assert face_diameter(disc_face(diameter)) == pytest.approx(diameter, rel=0.02)


def test_a_flan_broken_along_a_chord_keeps_its_diameter():
    assert face_diameter(disc_face(20.0, broken=0.5)) == pytest.approx(20.0, rel=0.02)


def test_the_reference_coins_keep_scale_one():
    rng = np.random.default_rng(1)
    # faces about the medians measured on the generators' hoards: the independent one's (20.3-20.5 mm),
    # coindie synth's with the wide physics (21.4) and with the default one (22.3)
    for low, high in [(18.3, 22.3), (20.4, 22.4), (21.3, 23.3)]:
        assert coin_scale(hoard_diameter(rng.uniform(low, high, 40))) == 1.0


def test_a_hoard_without_a_measured_face_has_no_diameter_and_a_diameter_must_be_one():
    assert hoard_diameter([]) is None
    assert hoard_diameter([np.nan, 0.0]) is None
    assert hoard_diameter([np.nan, 0.0, 14.0, 16.0, 30.0]) == 16.0  # the faces measured, their median
    for bad in (0.0, -3.0, np.nan):
        with pytest.raises(ParameterError, match="coin diameter"):
            coin_scale(bad)


@pytest.mark.parametrize("median", [8.0, 11.0, 15.0, 27.0, 33.0, 45.0])
def test_other_coins_scale_to_their_size_within_half_a_step(median):
    diameters = median * np.array([0.95, 1.0, 1.0, 1.05, 1.3])  # one outlier does not move the median
    scale = coin_scale(hoard_diameter(diameters))
    assert scale != 1.0
    assert abs(np.log2(scale * REFERENCE_DIAMETER_MM / median)) <= 1 / 8 + 1e-9
    assert np.log2(scale) * 4 == pytest.approx(round(np.log2(scale) * 4))  # on a step


@pytest.mark.parametrize("median", [0.5, 2.0, 150.0, 400.0])
def test_coins_read_in_the_wrong_unit_keep_a_scale_every_length_accepts(median):
    """Coins of 2 mm are a hoard in centimetres read as millimetres: the run must still go on."""
    from coindie.registration import method_info
    from coindie.similarity.relief_features import ReliefFeatureSettings

    scale = coin_scale(median)
    assert scale == (SCALE_RANGE[0] if median < REFERENCE_DIAMETER_MM else SCALE_RANGE[1])
    method_info("relief").build(method_info("relief").for_coins({}, scale))
    ReliefFeatureSettings().for_coins(scale)
