"""How large a hoard's coins are, and the scale of the design's details that follows from it.

The lengths that describe a die's details (the relief images' pixels and bands, the block matching's
windows, the relief features' bands and windows) were set for coins of about 20 mm: the paper's Riedones
staters ("a coin of 2 cm diameter"), the flans of ``coindie synth`` (medians of 21.4 mm with ``--physics
wide``, on which the shipped scorer was trained, and 22.3 mm with the default physics, as
:func:`face_diameter` measures them) and the coins of the independent generator (20.3-20.5 mm). An
engraver cuts a small coin's letters and pellets smaller, and two dies of one type differ by
proportionally smaller moves: on coins of 10-12 mm the fine band (< 0.3 mm) holds the type's elements as
well as the die's, and the shipped scorer, which reads that band, took dies of one type for one die
(``benchmarks/outsider_hoards.py --scale 0.55``: FMI 0.68, BENCHMARK.md). The hoard's coin scale is the
median face diameter over :data:`REFERENCE_DIAMETER_MM`, in steps of a quarter octave (19 %): a hoard of
19.6-23.3 mm coins keeps exactly the lengths the scorer was trained with, and one added scan seldom
moves it.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from coindie.arrays import FloatArray
from coindie.errors import ParameterError

#: The coin diameter (mm) the design lengths were set for: the median of the faces the shipped scorer was
#: trained on (``coindie synth --physics wide``), as :func:`face_diameter` measures them.
REFERENCE_DIAMETER_MM = 21.4
#: Coin scales come in steps of 2 ** (1 / this).
STEPS_PER_OCTAVE = 4
#: Coin scales are kept within these (coins of 5.4-86 mm, from the smallest fractions to medallions): every
#: scaled length stays within its parameter's range, and a hoard read in the wrong unit still runs.
SCALE_RANGE = (0.25, 4.0)
#: Points of a face used to measure its diameter (a regular subsample of larger clouds).
_DIAMETER_POINTS = 20000
#: The share of points left out at either end of each extent (stray points, a scanner's fringe).
_TAIL = 0.002


def face_diameter(points: FloatArray) -> float:
    """A face's diameter (mm): its longest extent along the two in-plane axes of its best-fit plane,
    between the 0.2 % and 99.8 % quantiles. A flan broken along a chord keeps its diameter across it; an
    edge wall, steep to the plane, adds nothing."""
    points = np.asarray(points, dtype=np.float64)
    if len(points) < 3:
        return 0.0
    sample = points[:: -(-len(points) // _DIAMETER_POINTS)]
    centred = sample - sample.mean(axis=0)
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    in_plane = centred @ vt[:2].T
    low, high = np.quantile(in_plane, [_TAIL, 1.0 - _TAIL], axis=0)
    return float(np.max(high - low))


def hoard_diameter(diameters_mm: Iterable[float]) -> float | None:
    """The hoard's coin diameter (mm): the median of its faces' measured ``diameters_mm`` (a face too
    small to measure, 0 or NaN, left out); None when there is none."""
    measured = np.asarray([d for d in diameters_mm if np.isfinite(d) and d > 0], dtype=np.float64)
    return float(np.median(measured)) if len(measured) else None


def coin_scale(diameter_mm: float) -> float:
    """``diameter_mm`` (a hoard's, :func:`hoard_diameter`) over :data:`REFERENCE_DIAMETER_MM`, rounded to a
    power of 2 ** (1 / :data:`STEPS_PER_OCTAVE`) within :data:`SCALE_RANGE`: exactly 1 for 19.6-23.3 mm."""
    if not (np.isfinite(diameter_mm) and diameter_mm > 0):
        raise ParameterError(f"A coin diameter must be a positive number of mm. Got {diameter_mm}.")
    octaves = np.log2(diameter_mm / REFERENCE_DIAMETER_MM)
    steps = int(np.round(octaves * STEPS_PER_OCTAVE))
    if steps == 0:
        return 1.0
    return float(np.clip(2.0 ** (steps / STEPS_PER_OCTAVE), *SCALE_RANGE))
