"""Cloud-to-cloud histograms on hand-built clouds whose distances are known exactly."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.scan import Scan
from coindie.similarity import HistogramSettings, c2c_distances, c2c_histogram, main_normal
from coindie.similarity.histogram import clear_cache, density_histogram, sampled_face

# Linear algebra under test (transformed points, distances and bin edges):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric

SHIFT = np.array([5.0, -3.0, 1.0])


def _plane(size_mm: float = 2.0, step: float = 0.05) -> Scan:
    """A flat target z = 0, one point at the centre of each 0.05 mm cell, normals up."""
    u = np.arange(step / 2, size_mm, step)
    x, y = np.meshgrid(u, u)
    points = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    return Scan(points=points, normals=np.tile([0.0, 0.0, 1.0], (len(points), 1)), id="target")


def _source(heights: list[float], steep: int = 0) -> Scan:
    """Source points above target points (one per 0.1 mm cell) at known heights, shifted by SHIFT; plus
    ``steep`` points whose normal is horizontal (left out by the 1 rad filter)."""
    cells = [(0.025 + 0.1 * (k % 10), 0.025 + 0.1 * (k // 10)) for k in range(len(heights) + steep)]
    points = np.array([[x, y, h] for (x, y), h in zip(cells, heights + [0.01] * steep, strict=True)])
    sideways = [[(-1.0) ** k, 0.0, 0.0] for k in range(steep)]  # the rim's wall: its normals cancel out
    normals = np.array([[0.0, 0.0, 1.0]] * len(heights) + sideways)
    return Scan(points=points + SHIFT, normals=normals, id="source")


def _T_target_source() -> np.ndarray:
    T = np.eye(4)
    T[:3, 3] = -SHIFT
    return T


def test_histogram_matches_a_hand_computed_case() -> None:
    clear_cache()
    settings = HistogramSettings()
    width = 0.6 / 70
    # bins: 0.004 -> 0; 0.013, 0.016 -> 1; 0.304 -> 35; 0.7 and 0.65 are dropped (over 0.6 mm). Every
    # distance lies well inside its bin (0.3 would sit on the edge of bins 34 and 35: the last bit decides).
    source = _source([0.004, 0.013, 0.016, 0.304, 0.7, 0.65], steep=3)
    histogram = c2c_histogram(source, _plane(), _T_target_source(), settings)
    expected = np.zeros(70)
    expected[[0, 1, 35]] = [1, 2, 1]
    expected /= 4 * width  # density over the 4 kept distances
    assert histogram.shape == (70,)
    np.testing.assert_allclose(histogram, expected, rtol=1e-9)
    assert np.sum(histogram) * width == pytest.approx(1.0)


def test_distances_use_the_transform_and_drop_steep_points() -> None:
    source = _source([0.01, 0.02, 0.03], steep=2)
    d = np.sort(c2c_distances(source, _plane(), _T_target_source()))
    np.testing.assert_allclose(d, [0.01, 0.02, 0.03], atol=1e-12)
    # Without the transform the source is 5 mm away: nothing within 0.6 mm, an all-zero histogram.
    assert not c2c_histogram(source, _plane(), np.eye(4)).any()


def test_the_search_stopped_at_the_maximum_gives_the_whole_searchs_histogram() -> None:
    """The histogram asks the k-d tree for distances up to its maximum only: the distances within it are
    the whole search's, those beyond come back infinite, and the histogram is the same, including a
    distance that equals the maximum to the last bit."""
    clear_cache()
    source, target, T = _source([0.2, 0.5999, 0.6, 0.6001, 0.9, 0.05]), _plane(), _T_target_source()
    whole = c2c_distances(source, target, T)
    edge = float(whole[2])  # about 0.6 mm: the maximum, to the last bit
    settings = HistogramSettings(max_distance_mm=edge)
    cut = c2c_distances(source, target, T, up_to=float(np.nextafter(edge, np.inf)))
    within = whole <= edge
    np.testing.assert_array_equal(cut[within], whole[within])
    assert np.isinf(cut[~within]).all() and (~within).sum() == 2
    np.testing.assert_array_equal(
        c2c_histogram(source, target, T, settings), density_histogram(whole, settings)
    )
    with pytest.raises(ParameterError, match="up_to"):
        c2c_distances(source, target, T, up_to=-0.6)


def test_bins_range_and_normal_angle_are_settable() -> None:
    source = _source([0.01, 0.02, 0.03, 0.25], steep=2)
    coarse = HistogramSettings(bins=3, max_distance_mm=0.3, max_normal_angle_rad=np.pi / 2 + 0.1)
    histogram = c2c_histogram(source, _plane(), _T_target_source(), coarse)
    # 6 distances (the steep points at 0.01 now count): 5 in the first bin [0, 0.1), 1 in the last.
    np.testing.assert_allclose(histogram * 0.1, [5 / 6, 0.0, 1 / 6])


def test_grids_are_the_papers_and_settable() -> None:
    paper = HistogramSettings()
    assert (paper.source_grid_mm, paper.target_grid_mm) == (0.1, 0.05)
    code = HistogramSettings.authors_code()
    assert (code.source_grid_mm, code.target_grid_mm) == (0.05, 0.1)
    target = _plane()
    fine = sampled_face(target, 0.05, 1.0).points
    coarse = sampled_face(target, 0.1, 1.0).points
    assert len(fine) == len(target.points) and len(coarse) == len(fine) // 4


def test_symmetric_histogram_is_the_mean_of_both_directions() -> None:
    rng = np.random.default_rng(0)
    target = _plane()
    noisy = target.points + rng.normal(0.0, 0.02, target.points.shape)
    source = Scan(points=noisy[::3], normals=target.normals[::3], id="noisy")
    same = HistogramSettings(source_grid_mm=0.05, target_grid_mm=0.05)
    one_way = c2c_histogram(source, target, np.eye(4), same)
    other_way = c2c_histogram(target, source, np.eye(4), same)
    both = c2c_histogram(
        source, target, np.eye(4), HistogramSettings(**{**same.to_dict(), "symmetric": True})
    )
    np.testing.assert_allclose(both, 0.5 * (one_way + other_way))
    assert not np.allclose(one_way, other_way)


def test_main_normal_is_the_faces_up_direction() -> None:
    normals = np.array([[0.0, 0.0, 1.0]] * 8 + [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])
    np.testing.assert_allclose(main_normal(normals), [0.0, 0.0, 1.0])


@pytest.mark.parametrize(
    "changes",
    [{"bins": 0}, {"max_distance_mm": -1.0}, {"source_grid_mm": 0.0}, {"max_normal_angle_rad": 4.0}],
)
def test_bad_settings_are_refused(changes: dict) -> None:
    with pytest.raises(ParameterError):
        HistogramSettings(**changes)


def test_a_bad_transform_is_refused() -> None:
    with pytest.raises(ParameterError, match="4x4"):
        c2c_histogram(_source([0.01]), _plane(), np.eye(3))
