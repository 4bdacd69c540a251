"""A global descriptor of a coin face, unchanged by rotation and translation of the coin.

Built on the ``relief`` method's per-face image (``coindie.registration.relief``): the high-passed relief
of the face in its canonical frame, on a 0.2 mm grid. Then, as in the Fourier–Mellin rotation search of
:mod:`coindie.registration.relief_search`:

1. the magnitude of the image's 2-D Fourier transform does not change when the coin is translated (a
   strike off-centre, a scan not centred) and turns with the coin;
2. resampled in polar coordinates (radius = spatial frequency, angle in [0, pi)), a rotation becomes a
   circular shift along the angle;
3. the magnitudes of a 1-D Fourier transform along the angle do not change under circular shifts: per
   band of frequencies (log-spaced), the first ``harmonics`` angular harmonics are the descriptor.

Two faces of one die share their design down to the engraver's slips, so their spectra match closely; faces
of other dies of the same type share the layout but not the details. Measured on synthetic hoards (see
BENCHMARK.md, "Candidate search"): a same-die partner is among the 10 nearest faces for over 99 % of faces.

Written by hand (a few FFTs) because no maintained library offers a rotation-invariant descriptor of a
height map; the FFTs and resampling are scipy's.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray
from scipy import fft, ndimage

from coindie.arrays import FloatArray
from coindie.errors import ParameterError
from coindie.params import Configurable, Rule, param
from coindie.scan import Scan

#: Bumped whenever the descriptor's computation changes, so that cached descriptors are recomputed.
DESCRIPTOR_VERSION = 1
#: The relief image's band (the sigma of the Gaussian taken off the heights, mm): that of the candidate
#: recall measured in BENCHMARK.md ("Candidate search"). The ``relief`` method's own turn sweep has since
#: moved to a finer band (0.4 mm), where its poses are better; what the finer band does to the candidates'
#: recall has not been measured, so the descriptor keeps its own.
DESCRIPTOR_HIGH_PASS_MM = 0.8


@dataclass(frozen=True)
class DescriptorSettings(Configurable):
    """How the descriptor is computed (the relief image itself follows the ``relief`` method's defaults).

    Attributes:
        bands: log-spaced bands of spatial frequency (radii of the polar spectrum).
        harmonics: angular harmonics kept per band (0 = the band's mean level).
        n_angles: samples of the polar spectrum over [0, pi).
        window_px: the image is faded to zero over this many pixels inside its footprint, so that the
            outline of the flan does not dominate the spectrum.
    """

    RULES: ClassVar[tuple[Rule, ...]] = (
        Rule(("harmonics", "n_angles"), lambda s: s.harmonics < s.n_angles // 2, "harmonics < n_angles / 2"),
    )

    bands: int = param(24, doc="log-spaced bands of spatial frequency", low=2)
    harmonics: int = param(24, doc="angular harmonics kept per band", low=0)
    n_angles: int = param(360, doc="samples of the polar spectrum over [0, pi)", low=2)
    window_px: int = param(3, doc="fade to zero over this many pixels inside the footprint", unit="px", low=0)

    @property
    def size(self) -> int:
        """Length of the descriptor (at most: close low bands may merge on small images)."""
        return self.bands * (self.harmonics + 1)

    def digest(self) -> str:
        """A short hash of the settings and the descriptor's version (cache key)."""
        text = json.dumps({"version": DESCRIPTOR_VERSION, **asdict(self)}, sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()[:16]


def relief_descriptor(
    detail: FloatArray, mask: NDArray[np.bool_], settings: DescriptorSettings | None = None
) -> NDArray[np.float32]:
    """The descriptor of a relief image (``detail`` in mm on a square grid, ``mask`` its footprint): the
    angular-harmonic magnitudes of its polar power spectrum, per frequency band, as float32."""
    settings = settings or DescriptorSettings()
    if detail.ndim != 2 or detail.shape[0] != detail.shape[1] or detail.shape != mask.shape:
        raise ParameterError(f"the relief image must be square with a mask of its shape, got {detail.shape}")
    inside = ndimage.distance_transform_cdt(np.pad(mask, 1), metric="taxicab")[1:-1, 1:-1]
    fade = max(1, settings.window_px)
    window = ndimage.gaussian_filter((inside > settings.window_px).astype(np.float64), fade)
    image = np.where(mask, detail, 0.0) * window
    size = image.shape[0]
    spectrum = np.abs(fft.fftshift(fft.fft2(image)))
    radii = np.arange(2, size // 2 - 1, dtype=np.float64)
    angles = np.linspace(0.0, np.pi, settings.n_angles, endpoint=False)
    rows = size / 2 + radii[:, None] * np.sin(angles)[None, :]
    cols = size / 2 + radii[:, None] * np.cos(angles)[None, :]
    # heights in mm are small: scale to microns before log1p so that the log compresses the peaks
    polar = np.log1p(1e3 * ndimage.map_coordinates(spectrum, [rows, cols], order=1))
    edges = _band_edges(len(radii), settings.bands)
    bands = np.stack([polar[a:b].mean(axis=0) for a, b in zip(edges[:-1], edges[1:], strict=True)])
    harmonics = np.abs(fft.rfft(bands, axis=1))[:, : settings.harmonics + 1] / settings.n_angles
    out = np.zeros((settings.bands, settings.harmonics + 1), dtype=np.float32)
    out[: len(harmonics)] = harmonics
    return out.ravel()


def _band_edges(n_radii: int, n_bands: int) -> list[int]:
    """Log-spaced, strictly increasing band edges over ``n_radii`` radii (each band at least one radius)."""
    edges = [0]
    for value in np.geomspace(1, n_radii, n_bands + 1)[1:]:
        edges.append(max(edges[-1] + 1, int(round(value))))
    return [e for e in edges if e <= n_radii] or [0, n_radii]


def face_descriptor(scan: Scan, settings: DescriptorSettings | None = None) -> NDArray[np.float32]:
    """The descriptor of a face (grid-sampled at 0.1 mm, as the ``relief`` method registers it): its relief
    image made as the ``relief`` method makes it, in the band of :data:`DESCRIPTOR_HIGH_PASS_MM`, then
    :func:`relief_descriptor`."""
    from coindie.registration import get_method
    from coindie.registration.clouds import Cloud

    pipeline = get_method("relief", **{"relief.high_pass": DESCRIPTOR_HIGH_PASS_MM})
    prepared = pipeline.estimator.prepare(Cloud.canonical(scan))  # type: ignore[attr-defined]
    return relief_descriptor(prepared.image.detail, prepared.image.mask, settings)
