"""The second pass of unsupervised clustering: each face's pull taken off where the first clusters are
murky, not where they stand out."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.clustering import ProbabilityGraph, cluster, evaluate, second_pass, select_threshold_unsupervised
from coindie.clustering.second_pass import cluster_twice
from coindie.similarity.face_effects import without_face_effects_across
from scored_projects import unevenly_worn_scores


def _graphs(die: np.ndarray, log_odds: np.ndarray, side: str = "D"):  # noqa: ANN202 (a closure)
    """Names, truth, and the calibrated-graph callback cluster_twice takes (probabilities = sigmoid)."""
    n = len(die)
    i, j = np.triu_indices(n, k=1)
    names = [f"L{k:04d}{side}" for k in range(n)]
    sources, targets = [names[k] for k in i], [names[k] for k in j]
    p = 1.0 / (1.0 + np.exp(-log_odds))
    valid = np.ones(len(p), dtype=bool)

    def calibrated_graph(across):  # noqa: ANN001, ANN202
        w = p if across is None else without_face_effects_across(p, valid, sources, targets, across)
        return ProbabilityGraph.from_edges(list(zip(sources, targets, w, strict=True)), names)

    return dict(zip(names, die, strict=True)), calibrated_graph


def _worn_hoard(seed: int) -> tuple[np.ndarray, np.ndarray]:
    """One type; each face's pull (wear, crusts, scanner) as large as the same-die gap."""
    rng = np.random.default_rng(seed)
    die = np.repeat(np.arange(5), [12, 10, 8, 6, 4])
    pull = rng.normal(0.0, 1.2, len(die))
    i, j = np.triu_indices(len(die), k=1)
    return die, -3.0 + pull[i] + pull[j] + 3.0 * (die[i] == die[j]) + rng.normal(0.0, 0.7, len(i))


def _two_types(seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Clean scans of two types: three dies of one, two (4 coins and 1) of the other."""
    rng = np.random.default_rng(seed)
    die = np.repeat(np.arange(5), [10, 8, 6, 4, 1])
    kind = (die >= 3).astype(int)
    pull = rng.normal(0.0, 0.5, len(die))
    i, j = np.triu_indices(len(die), k=1)
    base = np.where(kind[i] == kind[j], -3.0, -10.0)
    return die, base + 12.0 * (die[i] == die[j]) + pull[i] + pull[j] + rng.normal(0.0, 1.0, len(i))


@pytest.mark.parametrize("seed", range(4))
def test_a_worn_hoard_is_clustered_again_and_better(seed: int) -> None:
    truth, calibrated_graph = _graphs(*_worn_hoard(seed))
    first_graph = calibrated_graph(None)
    cut = select_threshold_unsupervised(first_graph, "consensus").threshold
    first = cluster(first_graph, "consensus", cut)
    result = cluster_twice(calibrated_graph, "consensus")
    assert result.second_pass and result.first_silhouette < second_pass.CLEAR_SILHOUETTE
    assert evaluate(result.clusters.labels, truth).fmi > evaluate(first.labels, truth).fmi
    # the second pass compares faces by direction alone, and says so to whoever clusters its graph again
    assert result.params == {"measure": second_pass.SECOND_MEASURE}
    again = cluster(result.graph, "consensus", result.choice.threshold, **result.params)
    assert again.labels == result.clusters.labels


def test_clear_clusters_of_two_types_are_kept_as_they_are(monkeypatch: pytest.MonkeyPatch) -> None:
    """The second type's faces score low with every coin of the first: its pull is its type, and taking
    it off would join the second type's two dies. Its clusters stand out, so the second pass is not run."""
    merged_when_forced = 0
    for seed in range(4):
        truth, calibrated_graph = _graphs(*_two_types(seed), side="R")
        result = cluster_twice(calibrated_graph, "consensus")
        assert not result.second_pass and result.first_silhouette >= second_pass.CLEAR_SILHOUETTE
        assert evaluate(result.clusters.labels, truth).fmi == 1.0
        with monkeypatch.context() as patch:
            patch.setattr(second_pass, "CLEAR_SILHOUETTE", 2.0)
            forced = cluster_twice(calibrated_graph, "consensus")
        merged_when_forced += forced.clusters.n_clusters < result.clusters.n_clusters
    assert merged_when_forced >= 3


def test_a_hoard_left_in_singletons_gets_its_second_pass() -> None:
    """Every probability near 0 (a hoard the scorer finds hard everywhere): the first pass leaves each face
    alone, nothing stands out, and the pulls (fitted on every pair) are taken off."""
    die, log_odds = _worn_hoard(0)
    truth, calibrated_graph = _graphs(die, log_odds - 12.0)
    result = cluster_twice(calibrated_graph, "consensus")
    assert result.first_silhouette == 0.0 and result.second_pass
    assert second_pass.clusters_stand_out(result.graph, {face: 0 for face in truth}) == 0.0


def _same_die_pairs_across(truth: dict[str, int], labels: dict[str, int]) -> float:
    faces = list(truth)
    pairs = [(a, b) for k, a in enumerate(faces) for b in faces[k + 1 :] if truth[a] == truth[b]]
    return float(np.mean([labels[a] != labels[b] for a, b in pairs]))


def test_the_pulls_are_fitted_across_clusters_that_keep_the_dies_together() -> None:
    """The pairs the pulls are fitted on should be of other dies. On worn hoards the silhouette's cut
    splits dies (same-die pairs across its clusters); the clusters the pulls are fitted across are the
    first graph's at its cut of best modularity, which leave fewer of a die's pairs across."""
    fewer = 0
    for seed in range(8):
        truth, calibrated_graph = _graphs(*_worn_hoard(seed))
        seen: list[dict[str, int]] = []

        def recording(across, graphs=calibrated_graph, seen=seen):  # noqa: ANN001, ANN202
            if across is not None:
                seen.append(dict(across))
            return graphs(across)

        assert cluster_twice(recording, "consensus").second_pass
        first_graph = calibrated_graph(None)
        params = {"measure": second_pass.FIRST_MEASURE}
        cut = select_threshold_unsupervised(first_graph, "consensus", **params).threshold
        by_silhouette = cluster(first_graph, "consensus", cut, **params).labels
        split = _same_die_pairs_across(truth, by_silhouette)
        fitted_across = _same_die_pairs_across(truth, seen[0])
        assert fitted_across <= split
        fewer += fitted_across < split - 0.05
    assert fewer >= 2


def _vetoed_hoard(seed: int, gap: float) -> tuple[np.ndarray, np.ndarray]:
    """Scans unlike the scorer's training scans: every same-die pair below log-odds 0, ``gap`` above the
    other dies' pairs of the design."""
    rng = np.random.default_rng(seed)
    die = np.repeat(np.arange(6), [9, 7, 6, 4, 3, 2])
    i, j = np.triu_indices(len(die), k=1)
    same = die[i] == die[j]
    return die, np.where(same, -16.0 + gap, -16.0) + rng.normal(0.0, 1.5, len(i))


def _mixture_graph(die: np.ndarray, log_odds: np.ndarray) -> ProbabilityGraph:
    """The graph calibrated by the hoard's mixture, the scorer's veto set aside."""
    from coindie.similarity.calibration import calibrate_hoard

    calibration = calibrate_hoard(1.0 / (1.0 + np.exp(-log_odds)), scorer_veto=False)
    assert calibration.separates
    n = len(die)
    i, j = np.triu_indices(n, k=1)
    names = [f"L{k:04d}D" for k in range(n)]
    weights = calibration.probability(log_odds)
    return ProbabilityGraph.from_edges(
        [(names[a], names[b], w) for a, b, w in zip(i, j, weights, strict=True)], names
    )


@pytest.mark.parametrize("seed", range(3))
def test_the_hoards_own_clusters_overrule_a_scorers_veto_where_they_stand_out(seed: int) -> None:
    die, log_odds = _vetoed_hoard(seed, gap=11.0)
    truth, calibrated_graph = _graphs(die, log_odds)
    kept = cluster_twice(calibrated_graph, "consensus")
    overruled = cluster_twice(calibrated_graph, "consensus", lambda across: _mixture_graph(die, log_odds))
    assert not kept.overruled_scorer and kept.first_silhouette < second_pass.CLEAR_SILHOUETTE
    assert overruled.overruled_scorer and overruled.overrule_silhouette >= second_pass.CLEAR_SILHOUETTE
    assert not overruled.second_pass
    assert evaluate(overruled.clusters.labels, truth).fmi > 0.95
    assert evaluate(overruled.clusters.labels, truth).fmi > evaluate(kept.clusters.labels, truth).fmi


def test_a_vetoed_mixture_whose_clusters_do_not_stand_out_is_not_used() -> None:
    """The mixture's own clusters murky too (a worn hoard: each face's pull as large as the same-die gap):
    the veto stands, and the clustering is the one without the mixture (the second pass)."""
    die, log_odds = _worn_hoard(0)
    _, calibrated_graph = _graphs(die, log_odds)
    tried = []

    def murky_mixture(across) -> ProbabilityGraph:  # noqa: ANN001
        tried.append(across)
        return calibrated_graph(None)

    result = cluster_twice(calibrated_graph, "consensus", murky_mixture)
    alone = cluster_twice(calibrated_graph, "consensus")
    assert tried[0] is None and tried[1] is not None  # tried in each pass
    assert not result.overruled_scorer and result.second_pass
    assert result.clusters.labels == alone.clusters.labels


@pytest.mark.parametrize("seed", range(3))
def test_a_vetoed_mixture_is_tried_again_once_each_faces_pull_is_off(seed: int) -> None:
    """The mixture of the raw scores is murky (the pulls blur the dies), but once each face's pull is
    taken off its clusters stand out: the second pass keeps them, and finds the dies the veto hid."""
    from coindie.similarity.calibration import calibrate_hoard

    die, log_odds = unevenly_worn_scores(seed)
    truth, calibrated_graph = _graphs(die, log_odds)
    names = list(truth)
    i, j = np.triu_indices(len(die), k=1)
    sources, targets = [names[k] for k in i], [names[k] for k in j]
    p = 1.0 / (1.0 + np.exp(-log_odds))

    def mixture(across):  # noqa: ANN001, ANN202
        q = (
            p
            if across is None
            else without_face_effects_across(p, np.ones(len(p), bool), sources, targets, across)
        )
        L = np.log(q) - np.log1p(-q)
        weights = calibrate_hoard(q, scorer_veto=False).probability(L)
        return ProbabilityGraph.from_edges(list(zip(sources, targets, weights, strict=True)), names)

    kept = cluster_twice(calibrated_graph, "consensus")
    overruled = cluster_twice(calibrated_graph, "consensus", mixture)
    assert overruled.second_pass and overruled.overruled_scorer and not kept.overruled_scorer
    assert overruled.overrule_silhouette >= second_pass.OVERRULE_AFTER_PULLS_SILHOUETTE
    assert evaluate(overruled.clusters.labels, truth).fmi > 0.9
    assert evaluate(overruled.clusters.labels, truth).fmi > evaluate(kept.clusters.labels, truth).fmi + 0.1
