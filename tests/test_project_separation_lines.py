"""What ``coindie run`` and ``coindie status`` say of a hoard's scores: a split that the scorer's own scale
refused but whose clusters stand out is told with its numbers, not as a warning; a split whose clusters
do not stand out keeps the warning."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from coindie.project import Project
from coindie.project.status import separation_lines
from scored_projects import scored_project as _project
from scored_projects import two_designs as _two_designs
from scored_projects import unevenly_worn_scores


def _scores(upper: np.ndarray, seed: int) -> np.ndarray:
    """Scans unlike the scorer's training scans: the ``upper`` pairs near log-odds -5, the others near -16,
    every one judged different-die by the scorer."""
    rng = np.random.default_rng(seed)
    return np.where(upper, -5.0, -16.0) + rng.normal(0.0, 1.2, len(upper))


@pytest.mark.parametrize("seed", range(2))
def test_a_vetoed_split_whose_clusters_stand_out_is_told_without_a_warning(tmp_path: Path, seed: int) -> None:
    die = np.repeat(np.arange(7), [9, 7, 6, 5, 4, 3, 2])
    i, j = np.triu_indices(len(die), k=1)
    project = _project(tmp_path, die[i] == die[j], _scores(die[i] == die[j], seed), len(die))
    calibration = project.calibration("D")
    assert calibration.vetoed and not calibration.separates
    (line,) = separation_lines(project)
    assert not line.startswith("WARNING"), line
    assert "judges different-die" in line and "stand out" in line
    assert f"coindie serve {project.folder}" in line  # where to look at them
    # the numbers told are the calibration's and the clustering's own
    assert f"Ashman's D {calibration.separation:.2f}" in line
    assert f"{calibration.same_share:.1%} in an upper population" in line
    found = project.overrule("D")
    assert found is not None and f"silhouette {found.silhouette:.2f}" in line


@pytest.mark.parametrize("seed", range(2))
def test_a_vetoed_split_whose_clusters_do_not_stand_out_keeps_the_warning(tmp_path: Path, seed: int) -> None:
    """The same two populations, but a third of the pairs in the upper one, drawn at random: they form no
    dies (a link from one coin to two others is no link between those two), so no cut's clusters stand
    out and the veto stands. (At an eighth of the pairs, a random link pattern is mostly disjoint pairs of
    faces, which do stand out.)"""
    n_faces = 36
    i, _ = np.triu_indices(n_faces, k=1)
    upper = np.random.default_rng(seed).random(len(i)) < 0.3
    project = _project(tmp_path, upper, _scores(upper, seed), n_faces)
    assert project.calibration("D").vetoed
    assert project.overrule("D") is None
    (line,) = separation_lines(project)
    assert line.startswith("WARNING, side D:") and "do not separate" in line


def _auto_clusters(project: Project) -> dict[str, int]:
    """What ``coindie cluster --auto`` makes of the project's obverses."""
    from coindie.clustering import cluster

    graph, threshold, _, params = project.auto_graph("D", "consensus")
    return cluster(graph, "consensus", threshold, **params).labels


def test_pairs_of_one_design_are_not_taken_for_dies_where_the_scorer_sees_the_few_die_links(
    tmp_path: Path,
) -> None:
    """Two designs, 40 coins, 36 dies: the hoard's mixture splits the pairs of one design (half the pairs,
    far below log-odds 0) from those of two, and their clusters, the designs, stand out. The scorer judges
    the 4 same-die pairs same-die, far above them: ``cluster --auto`` keeps its probabilities and finds
    the die links, not two dies of 20 coins, and the run's line says why, without a warning (an
    independent generator's hoard of seed 19: FMI 0.109 before, four clusters of 20 faces)."""
    project, i, j, same_die = _two_designs(tmp_path, 4, (12.0, 4.0), seed=3)
    (line,) = separation_lines(project)
    assert not line.startswith("WARNING") and "the scorer judges 4 same-die" in line, line
    assert project.overrule("D") is None
    labels = _auto_clusters(project)
    names = [f"L{k + 1:04d}D" for k in range(40)]
    found = np.array([labels[names[a]] == labels[names[b]] for a, b in zip(i, j, strict=True)])
    assert found[same_die].all() and not found[~same_die].any()


def test_two_designs_without_die_links_are_not_taken_for_two_dies(tmp_path: Path) -> None:
    """40 coins of two designs, every die known from one coin: the pairs of one design (log-odds -15) stand
    apart from those of two (-19), and their clusters, the designs, stand out, but only 4 log-odds above:
    the scorer's veto stands, the run warns, and ``cluster --auto`` joins no faces (an independent
    generator's hoard of seed 19 with 40 dies: two clusters of 20 faces on its reverses before)."""
    project, _, _, same_die = _two_designs(tmp_path, 0, (0.0, 1.0), seed=4)
    assert not same_die.any()
    (line,) = separation_lines(project)
    assert line.startswith("WARNING, side D:") and "pairs of one design" in line, line
    assert project.overrule("D") is None
    assert max(np.bincount(list(_auto_clusters(project).values()))) == 1


def test_pairs_apart_above_the_pairs_of_one_design_are_named_for_a_reviewer(tmp_path: Path) -> None:
    """The two-design hoard on scans that lower every score: its 4 same-die pairs score below 0 but stand
    apart above the pairs of one design. The run warns, joins no faces, and names those pairs for a look
    in the review app (seed 20's coarse two-design hoard: its 4 and 5 same-die pairs, and only they)."""
    project, _, _, _ = _two_designs(tmp_path, 4, (-5.0, 0.8), seed=5)
    warning, hint = separation_lines(project)
    assert warning.startswith("WARNING, side D:") and "4 pairs stand apart above it" in warning
    assert hint.startswith("  the 4 pairs standing apart") and f"coindie serve {project.folder}" in hint
    assert max(np.bincount(list(_auto_clusters(project).values()))) == 1


def _worn_project(folder: Path, seed: int, pull: float) -> tuple[Project, dict[str, int]]:
    """A project of :func:`unevenly_worn_scores`'s hoard, and its faces' dies."""
    die, log_odds = unevenly_worn_scores(seed, pull)
    i, j = np.triu_indices(len(die), k=1)
    project = _project(folder, die[i] == die[j], log_odds, len(die))
    return project, {f"L{k + 1:04d}D": int(d) for k, d in enumerate(die)}


@pytest.mark.parametrize("seed", [1, 3, 5])
def test_the_run_tells_the_split_cluster_auto_keeps_once_the_pulls_are_off(tmp_path: Path, seed: int) -> None:
    """Unevenly worn faces blur the side's own split (no clear split: the scorer's veto is not what refused
    it), but once each face's pull is taken off, the split is clear, vetoed, and its clusters stand out:
    ``cluster --auto`` keeps them. The run warns of the murky scores and, on a second line, tells that split
    with its numbers, instead of stopping at "the scorer's own probabilities are kept" (the independent
    generator's hard hoards of seeds 22 and 23: Ashman's D 1.67 and 1.77, FMI 0.98 and 0.97)."""
    project, dies = _worn_project(tmp_path, seed, pull=2.5)
    calibration = project.calibration("D")
    assert not calibration.separates and not calibration.vetoed
    found = project.overrule("D")
    assert found is not None and found.after_pulls and found.calibration.vetoed
    warning, told = separation_lines(project)
    assert warning.startswith("WARNING, side D:") and "do not separate" in warning
    assert told.startswith("  once each face's pull is taken off, ") and "stand out" in told, told
    assert f"Ashman's D {found.calibration.separation:.2f}" in told
    assert f"{found.calibration.same_share:.1%} in an upper population" in told
    assert f"silhouette {found.silhouette:.2f}" in told and f"coindie serve {project.folder}" in told
    # what the line tells is what cluster --auto does, and those clusters are the dies
    _, _, how, _ = project.auto_graph("D", "consensus")
    assert "each face's pull taken off" in how and "which the scorer had judged different-die" in how
    from coindie.clustering import evaluate

    assert evaluate(_auto_clusters(project), dies).fmi > 0.9


def test_a_clear_vetoed_split_kept_once_the_pulls_are_off_says_so(tmp_path: Path) -> None:
    """The side's own split is clear and vetoed, and its clusters stand out only once each face's pull is
    off: one line, no warning, saying so."""
    project, _ = _worn_project(tmp_path, 0, pull=2.5)
    assert project.calibration("D").vetoed
    found = project.overrule("D")
    assert found is not None and found.after_pulls
    (line,) = separation_lines(project)
    assert (
        line.startswith("scores of side D:")
        and "its clusters, once each face's pull is taken off, stand" in line
    )
