"""Shaded relief renders: size, outline, lighting direction, options."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from coindie.errors import InvalidScanError, ParameterError
from coindie.preprocess import height_map
from coindie.render import AMBIENT, TONES, hillshade, render_relief, save_render
from coindie.scan import Scan
from test_preprocess_synthetic import SyntheticCoin, make_scan

# One bump at the centre, no dome: its lit and shaded sides are easy to find in the image.
BUMP = SyntheticCoin(spacing=0.1, dome=0.0, bumps=((0.0, 0.0, 0.6, 1.5),))


@pytest.fixture(scope="module")
def scan():
    return make_scan(BUMP)


def _luminance(image: Image.Image, x: float, y: float) -> float:
    """Mean grey level around the image point at fractions (x right, y down) of its size."""
    grey = np.asarray(image.convert("RGB").convert("L"), dtype=np.float64)
    row, col = int(y * grey.shape[0]), int(x * grey.shape[1])
    return float(grey[row - 3 : row + 4, col - 3 : col + 4].mean())


def test_the_render_has_the_requested_width_and_a_transparent_outside(scan):
    image = render_relief(scan, width_px=300)
    assert image.mode == "RGBA" and image.width == 300
    assert image.height == pytest.approx(300, abs=3)  # a round coin
    alpha = np.asarray(image.getchannel("A"))
    assert alpha[0, 0] == 0 and alpha[-1, -1] == 0 and alpha[150, 150] == 255
    inside = (alpha > 127).mean()
    assert inside == pytest.approx(np.pi / 4, abs=0.05)  # the coin's disc in its bounding square


def test_light_from_the_upper_left_lights_the_upper_left_flank(scan):
    image = render_relief(scan, width_px=400, background=(0, 0, 0))
    flank = 1.0 / 20.0  # the bump's sigma (1.5 mm) is 1/13 of the 20 mm coin
    upper_left = _luminance(image, 0.5 - flank, 0.5 - flank)
    lower_right = _luminance(image, 0.5 + flank, 0.5 + flank)
    field = _luminance(image, 0.25, 0.75)
    assert upper_left > field + 20 > lower_right + 40
    flipped = render_relief(scan, width_px=400, light_azimuth_deg=135, background=(0, 0, 0))
    assert _luminance(flipped, 0.5 - flank, 0.5 - flank) < _luminance(flipped, 0.5 + flank, 0.5 + flank)


def test_a_flat_face_is_evenly_lit_at_the_altitude_angle():
    flat = make_scan(SyntheticCoin(spacing=0.2, dome=0.0, bumps=()))
    relief = height_map(flat, resolution=0.2)
    shade = hillshade(relief, 315.0, 30.0, 2.0)[relief.mask]
    assert np.allclose(shade, AMBIENT + (1 - AMBIENT) * np.sin(np.radians(30.0)), atol=1e-6)


def test_background_and_tone_options(scan):
    image = render_relief(scan, width_px=120, background=(10, 20, 30), tone="grey")
    assert image.mode == "RGB"
    assert image.getpixel((0, 0)) == (10, 20, 30)
    r, g, b = image.getpixel((60, 60))
    assert r == g == b  # grey ramp
    dark, _, light = TONES["grey"]
    assert dark[0] <= r <= light[0]


def test_save_render_writes_a_png(scan, tmp_path):
    path = save_render(scan, tmp_path / "coin.png", width_px=64)
    with Image.open(path) as image:
        assert image.format == "PNG" and image.width == 64


@pytest.mark.parametrize(
    "kwargs",
    [
        {"width_px": 0},
        {"width_px": 100_000},
        {"light_altitude_deg": 0},
        {"exaggeration": 0},
        {"tone": "gold"},
    ],
)
def test_bad_options_are_refused(scan, kwargs):
    with pytest.raises(ParameterError):
        render_relief(scan, **kwargs)


def test_a_scan_without_extent_is_refused():
    with pytest.raises(InvalidScanError, match="nothing to render"):
        render_relief(Scan(points=np.zeros((5, 3))), width_px=50)
