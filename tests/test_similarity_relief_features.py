"""Relief features of a registered pair: scale-free correlations of the two reliefs' bands."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from coindie.errors import ParameterError
from coindie.scan import Scan
from coindie.similarity.relief_features import (
    FEATURE_NAMES,
    ReliefFeatureSettings,
    _gaussian,
    relief_features,
)


@pytest.mark.parametrize("sigma_px", [2.5, 6.0, 10.0, 15.0, 30.0])
@pytest.mark.parametrize("shape", [(120, 120), (37, 150), (3, 90)])
def test_the_blurs_are_scipys_gaussian_filter(sigma_px: float, shape: tuple[int, int]) -> None:
    """Wide blurs are taken by FFT: scipy's values (zeros beyond the image, the kernel cut at 4 sigma) to
    float32 rounding, on images narrower than the kernel too."""
    image = np.random.default_rng(4).standard_normal(shape).astype(np.float32)
    image[:, : shape[1] // 3] = 0.0  # a footprint's edge
    expected = ndimage.gaussian_filter(image, sigma_px, mode="constant", cval=0.0)
    blurred = _gaussian(image, sigma_px)
    assert blurred.dtype == np.float32 and blurred.shape == shape
    np.testing.assert_allclose(blurred, expected, rtol=0, atol=1e-6 * float(np.abs(expected).max()))


def _face(
    relief_seed: int, noise_seed: int, T: np.ndarray, pellet: tuple[float, float] | None = None
) -> Scan:
    """A 16 mm face (0.05 mm grid) of a die's random relief, cupped, with scanner noise, moved by T;
    ``pellet``: where a 1.2 mm pellet 0.4 mm high stands on the die (its relief is tenfold the rest's)."""
    grid = np.arange(-8.0, 8.0, 0.05)
    x, y = np.meshgrid(grid, grid)
    inside = np.hypot(x, y) < 7.5
    die = ndimage.gaussian_filter(np.random.default_rng(relief_seed).standard_normal(x.shape), 4) * 0.3
    if pellet is not None:
        r = np.hypot(x - pellet[0], y - pellet[1]) / 0.6
        die = np.maximum(die, 0.4 * np.sqrt(np.clip(1 - r**2, 0, None)))
    z = die + 0.004 * (x**2 + y**2) + np.random.default_rng(noise_seed).normal(0, 0.003, x.shape)
    points = np.column_stack([x[inside], y[inside], z[inside]])
    gy, gx = np.gradient(z, 0.05)
    normals = np.column_stack([-gx[inside], -gy[inside], np.ones(inside.sum())])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return Scan(points=points @ T[:3, :3].T + T[:3, 3], normals=normals @ T[:3, :3].T)


def test_a_same_die_pair_correlates_and_another_die_does_not() -> None:
    """At the true pose two strikes of one die (other noise, another place in the scanner) correlate in
    both bands and over most windows; a face of another die does not (its fine band and its windows); the
    overlap is the whole face either way."""
    angle = 0.6
    T = np.eye(4)
    T[:2, :2] = [[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]
    T[:3, 3] = [3.0, -2.0, 0.5]
    target = _face(1, 10, np.eye(4))
    same = dict(zip(FEATURE_NAMES, relief_features(_face(1, 11, T), target, np.linalg.inv(T)), strict=True))
    other = dict(zip(FEATURE_NAMES, relief_features(_face(2, 12, T), target, np.linalg.inv(T)), strict=True))
    assert same["ncc_fine"] > 0.8 and same["ncc_coarse"] > 0.9 and same["local_median"] > 0.8
    assert abs(other["ncc_fine"]) < 0.3 and other["local_median"] < 0.3
    # the coarse band keeps some of the shared cupping near the outline: lower, not near 0
    assert other["ncc_coarse"] < same["ncc_coarse"] - 0.2
    assert same["overlap"] > 0.95 and other["overlap"] > 0.95


def test_one_strong_element_in_common_does_not_make_two_dies_correlate() -> None:
    """Two dies whose only shared detail is one pellet in the same place (a wrong pose can put a pellet
    of each on the other): without clipping the pellet carries the fine band's correlation and the best
    windows'; with each band clipped at 3 robust standard deviations the pair reads as two dies, while two
    strikes of one die with that pellet still correlate."""
    angle = 0.6
    T = np.eye(4)
    T[:2, :2] = [[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]
    T[:3, 3] = [3.0, -2.0, 0.5]
    pellet = (2.0, 1.0)
    target = _face(1, 10, np.eye(4), pellet)
    features = {}
    for clip_sd in (0.0, ReliefFeatureSettings().clip_sd):
        settings = ReliefFeatureSettings(clip_sd=clip_sd)
        for name, source in (("same", _face(1, 11, T, pellet)), ("other", _face(2, 12, T, pellet))):
            values = relief_features(source, target, np.linalg.inv(T), settings)
            features[name, clip_sd] = dict(zip(FEATURE_NAMES, values, strict=True))
    assert ReliefFeatureSettings().clip_sd == 3.0
    assert features["other", 0.0]["ncc_fine"] > 0.5 and features["other", 0.0]["local_p90"] > 0.7
    assert features["other", 3.0]["ncc_fine"] < 0.3 and features["other", 3.0]["local_p90"] < 0.5
    assert features["same", 3.0]["ncc_fine"] > 0.85 and features["same", 3.0]["local_median"] > 0.85


def test_settings_written_before_clipping_describe_unclipped_features() -> None:
    """A model file's feature settings without ``clip_sd`` were written before the bands were clipped:
    they read back as no clipping, and today's settings round-trip as they are."""
    old = {k: v for k, v in ReliefFeatureSettings().to_dict().items() if k != "clip_sd"}
    assert ReliefFeatureSettings.from_dict(old).clip_sd == 0.0
    assert ReliefFeatureSettings.from_dict(ReliefFeatureSettings().to_dict()) == ReliefFeatureSettings()


@pytest.mark.parametrize("scale", [0.55, 1.6])
def test_a_pair_and_its_copy_at_another_coin_size_give_the_same_features(scale: float) -> None:
    """Coins `scale` times as large in every direction (the die's details with them): with the settings
    for such coins the features are the ones of the pair at its own size; with the 20 mm coins' settings the
    fine band reads other details (the coin's size is a length the features depend on)."""
    angle = 0.6
    T = np.eye(4)
    T[:2, :2] = [[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]
    T[:3, 3] = [3.0, -2.0, 0.5]
    S = np.diag([scale, scale, scale, 1.0])
    settings = ReliefFeatureSettings()

    def scaled(face: Scan) -> Scan:
        return Scan(points=face.points * scale, normals=face.normals)

    moved = []
    for source in (_face(1, 11, T), _face(2, 12, T)):  # one die, another die
        target = _face(1, 10, np.eye(4))
        T_target_source = np.linalg.inv(T)
        T_scaled = S @ T_target_source @ np.linalg.inv(S)
        own = relief_features(source, target, T_target_source, settings)
        copy = relief_features(scaled(source), scaled(target), T_scaled, settings.for_coins(scale))
        fixed = relief_features(scaled(source), scaled(target), T_scaled, settings)
        np.testing.assert_allclose(copy, own, atol=2e-3)  # float32 rasters
        moved.append(np.abs(fixed - own).max())
    assert max(moved) > 0.2


def test_settings_for_coins_of_the_reference_size_are_these() -> None:
    settings = ReliefFeatureSettings()
    assert settings.for_coins(1.0) is settings
    half = settings.for_coins(0.5)
    assert half.fine_sigma_mm == settings.fine_sigma_mm / 2 and half.size_px == settings.size_px
    with pytest.raises(ParameterError, match="positive"):
        settings.for_coins(0.0)
