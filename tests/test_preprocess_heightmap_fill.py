"""The hole filling of height maps: which pixels it fills, by the disc's closing or the distance
transforms' (the same pixels), and that it leaves large holes and the outside empty."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from coindie.preprocess.heightmap import _closing, fill_small_holes


def _by_distance_transforms(observed: np.ndarray, radius_px: float) -> tuple[np.ndarray, np.ndarray]:
    """The closing as two Euclidean distance transforms: the definition the disc must match."""
    dilated = ndimage.distance_transform_edt(~observed) <= radius_px
    return dilated, ndimage.distance_transform_edt(dilated) > radius_px


def _sparse_disc(seed: int, size: int, density: float, pad: int) -> np.ndarray:
    """A coin's footprint seen by a sparse scan: a disc of random observed pixels, ``pad`` pixels from the
    image's edge at least (none where ``pad`` is negative: the disc runs off the image)."""
    rng = np.random.default_rng(seed)
    rows, cols = np.mgrid[0:size, 0:size]
    centre, radius = (size - 1) / 2.0, size / 2.0 - max(pad, 0)
    inside = (rows - centre) ** 2 + (cols - centre) ** 2 <= radius**2
    if pad < 0:
        inside = (rows - centre) ** 2 + (cols - centre) ** 2 <= (size / 2.0 - pad) ** 2
    return inside & (rng.random((size, size)) < density)


# 0.3 mm / 0.1 mm is 2.9999999999999996 in floating point: the offsets at exactly 3 pixels are out
@pytest.mark.parametrize("radius_px", [0.3 / 0.1, 3.0, 1.5, 2.0, 4.2, 6.0])
@pytest.mark.parametrize("pad", [5, 0, -10])
@pytest.mark.parametrize("density", [0.15, 0.3, 0.8])
def test_the_discs_closing_is_the_distance_transforms(radius_px: float, pad: int, density: float) -> None:
    observed = _sparse_disc(int(10 * radius_px) + pad, 70, density, pad)
    dilated, closed = _closing(observed, radius_px)
    expected_dilated, expected_closed = _by_distance_transforms(observed, radius_px)
    np.testing.assert_array_equal(dilated, expected_dilated)
    if dilated.all():
        # no pixel outside the dilation: the transform measures distances to the image's edge along one
        # axis, the closing of a full image is full (a height map keeps empty pixels round its edge)
        assert closed.all()
        return
    np.testing.assert_array_equal(closed, expected_closed)
    assert closed.any() and not closed.all()


def test_a_wide_radius_takes_the_distance_transforms() -> None:
    observed = _sparse_disc(3, 90, 0.05, 12)
    dilated, closed = _closing(observed, 9.5)
    expected_dilated, expected_closed = _by_distance_transforms(observed, 9.5)
    np.testing.assert_array_equal(dilated, expected_dilated)
    np.testing.assert_array_equal(closed, expected_closed)


def test_small_holes_are_filled_and_large_ones_and_the_outside_are_not() -> None:
    """A plane z = 0.01 x seen on a disc with a one-pixel hole and a 12-pixel hole: the small one takes
    the plane's height from its neighbours, the large one and the outside stay empty."""
    size = 80
    rows, cols = np.mgrid[0:size, 0:size].astype(np.float64)
    inside = (rows - 39.5) ** 2 + (cols - 39.5) ** 2 <= 32.0**2
    large = (rows - 30.0) ** 2 + (cols - 45.0) ** 2 <= 12.0**2
    observed = inside & ~large
    observed[50, 30] = False
    values = np.where(observed, 0.01 * cols, np.nan)
    filled = fill_small_holes(values, observed, 0.3 / 0.1)
    assert filled[50, 30] == pytest.approx(0.3, abs=1e-9)
    assert np.isnan(filled[30, 45]) and np.isnan(filled[0, 0])
    assert np.isfinite(filled[observed]).all()
