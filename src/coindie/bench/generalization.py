"""``coindie bench generalization``: the die study on hoards of other scanners, flans and wear.

One row per hoard: a ``study`` hoard (80 faces, 12 dies) made with one axis of the wide world
(:mod:`coindie.synth.physics`) at one of its extremes, the all-hard mix, and the ``riedones`` preset
(the paper's protocol, scaled). Each hoard goes through what a user runs, scans only, shipped defaults:
a project (``coindie init``, ``coindie run``: every same-side pair registered once by ``relief``, both the
relief features and the paper's histogram stored), then for each scorer its probabilities, the per-hoard
calibration, the clustering of ``coindie cluster --auto`` (average linkage on the consensus of the calibrated
probabilities, :mod:`coindie.clustering.consensus`, cut where the silhouette of its clusters is best; where
they do not stand out, each face's pull on its scores taken off, :mod:`coindie.similarity.face_effects`,
and cut again where their modularity is best: :mod:`coindie.clustering.second_pass`), and the hidden
labels to judge:

- FMI and ARI of the clusters;
- the share of same-die pairs refused (registration refused, or nothing to score);
- the pair AUC (same-die against different-die pairs, refused pairs at probability 0);
- the time per pair (registration plus the scorer's own measure).

Scorers: ``relief`` (the default) and ``paper`` (the distance histogram and the shipped paper model).
Hoards and projects are kept under OUT and resumed, so a rerun only does what is missing.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from coindie.errors import ParameterError

#: The paper's protocol row: the riedones preset at this scale with the default physics.
RIEDONES_ROW = "riedones"
SCORER_NAMES = ("relief", "paper")
#: How the rows cluster: what ``coindie cluster --auto`` does (consensus of the calibrated probabilities).
CLUSTERING = "consensus"
COLUMNS = ("fmi", "ari", "same_refused", "auc", "seconds_per_pair", "clusters", "dies", "threshold")


@dataclass(frozen=True)
class RowResult:
    row: str
    scorer: str
    fmi: float
    ari: float
    same_refused: float
    auc: float
    seconds_per_pair: float
    clusters: int
    dies: int
    threshold: float
    threshold_from: str
    separates: bool


def benchmark_rows() -> list[str]:
    """Every row of the matrix: each axis at its two extremes, the all-hard mix, the riedones preset."""
    from coindie.synth.physics import BENCHMARK_ROWS

    return [*BENCHMARK_ROWS, RIEDONES_ROW]


def run_generalization(
    out: str | Path,
    rows: Sequence[str] | None = None,
    *,
    seed: int = 1000,
    workers: int = 2,
    riedones_scale: float = 0.05,
    models: dict[str, Any] | None = None,
    evaluate_only: bool = False,
    echo: Callable[[str], None] = print,
) -> list[RowResult]:
    """Run (or resume) every row; write ``results.csv``, ``results.json``, ``results.md`` and
    ``generalization.png`` in ``out``; return the results. ``evaluate_only``: apply the scorers to the
    pairs the rows' projects already hold (other models, another threshold rule), running nothing."""
    out = Path(out)
    rows = list(rows) if rows else benchmark_rows()
    known = set(benchmark_rows())
    unknown = [r for r in rows if r not in known]
    if unknown:
        raise ParameterError(f"unknown benchmark row(s) {unknown}; known: {', '.join(sorted(known))}")
    models = models or _shipped_models()
    results: list[RowResult] = []
    for k, row in enumerate(rows):
        name = row.replace(":", "-")
        if evaluate_only:
            from coindie.project import open_project

            if not (out / "projects" / name / "project.sqlite").exists():
                echo(f"{row:>16}: no project yet in {out / 'projects' / name}, left out")
                continue
            hoard, project = out / "hoards" / name, open_project(out / "projects" / name)
        else:
            hoard = _hoard(out / "hoards" / name, row, seed + k, workers, riedones_scale)
            project = row_project(out / "projects" / name, hoard, workers)
        for scorer in SCORER_NAMES:
            result = evaluate_row(row, scorer, models[scorer], project, hoard)
            results.append(result)
            echo(
                f"{row:>16} {scorer:>6}: FMI {result.fmi:.3f} ARI {result.ari:.3f} AUC {result.auc:.3f} "
                f"same refused {result.same_refused:.1%} {result.clusters} clusters for {result.dies} dies "
                f"(tau {result.threshold:g} {result.threshold_from})"
            )
        write_results(out, results)
    if not results:
        raise ParameterError(f"no row of {rows} has a project in {out / 'projects'}")
    return results


def _shipped_models() -> dict[str, Any]:
    from coindie.similarity.scorers import default_scorer

    return {name: default_scorer(name) for name in SCORER_NAMES}


def _hoard(folder: Path, row: str, seed: int, workers: int, riedones_scale: float) -> Path:
    from coindie.synth.hoard import synthesize
    from coindie.synth.physics import physics_by_name

    if row == RIEDONES_ROW:
        synthesize(folder, preset="riedones", scale=riedones_scale, seed=seed, workers=workers)
    else:
        synthesize(folder, preset="study", physics=physics_by_name(row), seed=seed, workers=workers)
    return folder


def row_project(folder: Path, hoard: Path, workers: int, *, histograms: bool = True) -> Any:
    from coindie.project import init_project, open_project
    from coindie.project.run import RunConfig, run_project

    project = open_project(folder) if (folder / "project.sqlite").exists() else init_project(folder, hoard)[0]
    # Every pair stores both scorers' inputs (relief features and histogram), so a project is scored once
    # and each scorer applied to what it stored (as coindie run would apply it). The run is the shipped
    # default's, relays included (coindie.project.relay): a relay keeps the pose the default scorer scores
    # higher, and the paper's scorer is measured on those same poses. ``histograms=False``: a project that
    # only trains or judges the relief scorer (leave-one-out's training hoards) leaves the histogram out.
    config = RunConfig(mode="exhaustive", workers=workers, histograms=histograms)
    run_project(project, config, echo=lambda line: None)
    return project


def evaluate_row(row: str, scorer_name: str, scorer: Any, project: Any, hoard: Path) -> RowResult:
    from sklearn.metrics import roc_auc_score

    from coindie.clustering import combined, evaluate, read_clusters
    from coindie.clustering.second_pass import cluster_twice

    truth = read_clusters(hoard / "labels.csv")
    pairs = project.scored_pairs()
    raw = np.array([_probability(p, scorer) for p in pairs])
    valid = np.array([_scored(p, scorer) for p in pairs], dtype=bool)
    same = np.array([truth[p["source"]] == truth[p["target"]] for p in pairs], dtype=bool)
    populations = getattr(scorer, "populations", None) or None
    # as coindie cluster --auto (Project.auto_graph): each side cut where the silhouette of its consensus
    # clusters is best, on probabilities calibrated on the hoard; where those clusters do not stand out,
    # each face's pull fitted on the pairs across them and taken off, calibrated and cut again
    calibrated, all_separate = np.zeros(len(pairs)), True
    parts, cuts = [], []
    for side in sorted({p["side"] for p in pairs}):
        on = np.array([p["side"] == side for p in pairs], dtype=bool)
        mine = [p for p, o in zip(pairs, on, strict=True) if o]
        side_faces = [s.face_id for s in project.scans("ok") if s.side == side]
        last: dict[str, Any] = {}
        side_graph = partial(_side_graph, mine, raw[on], valid[on], populations, side_faces, last)
        first_graph = side_graph(None)  # and whether the scorer vetoed the hoard's calibration
        separates = last["separates"]
        result = cluster_twice(
            partial(_first_or_again, first_graph, side_graph),
            CLUSTERING,
            partial(_vetoed_graph, side_graph, last),
        )
        chosen = {frozenset((a, b)): w for a, b, w in result.graph.edges()}  # the weights clustered
        calibrated[on] = [chosen.get(frozenset((p["source"], p["target"])), 0.0) for p in mine]
        all_separate &= separates or result.overruled_scorer
        cuts.append(result.choice.threshold)
        parts.append(result.clusters)
    tau, how = float(np.mean(cuts)), "mixture" if all_separate else "silhouette"
    clusters = combined(parts, CLUSTERING)
    scores = evaluate(clusters.labels, truth).scores()
    seconds = [_seconds(p, scorer) for p in pairs if p.get("timings")]
    auc = float(roc_auc_score(same, calibrated)) if 0 < same.sum() < len(same) else float("nan")
    return RowResult(
        row, scorer_name, float(scores["fmi"]), float(scores["ari"]),
        float((~valid & same).sum() / max(1, same.sum())), auc, float(np.median(seconds)) if seconds else 0.0,
        int(scores["n_clusters"]), int(scores["n_dies"]), float(tau), how, bool(all_separate),
    )  # fmt: skip


def _first_or_again(first: Any, side_graph: Callable[[Any], Any], across: dict[str, Any] | None) -> Any:
    """The first pass's graph (already made), or the side's graph made again across a first clustering."""
    return first if across is None else side_graph(across)


def _vetoed_graph(side_graph: Callable[..., Any], last: dict[str, Any], across: dict[str, Any] | None) -> Any:
    """The side's graph calibrated by the hoard's mixture where only the scorer's veto refused it (as
    ``Project._vetoed_mixture``), else None."""
    side_graph(across)
    return side_graph(across, scorer_veto=False) if last["vetoed_now"] else None


def _side_graph(
    pairs: list[dict[str, Any]],
    raw: np.ndarray,
    valid: np.ndarray,
    populations: dict[str, tuple[float, float]] | None,
    faces: list[str],
    last: dict[str, Any],
    across: dict[str, Any] | None,
    *,
    scorer_veto: bool = True,
) -> Any:
    """One side's graph of probabilities calibrated on the hoard, after each face's pull (fitted across
    the clusters ``across``) is taken off, as ``Project.probability_graph(side, across=...)`` (the bench
    scores each pair with each scorer, so it cannot read the project's stored probabilities); the weights
    kept in ``last``, and whether the first pass's scores separate."""
    from coindie.clustering import ProbabilityGraph
    from coindie.similarity.calibration import calibrated_side

    sources, targets = [p["source"] for p in pairs], [p["target"] for p in pairs]
    last["weights"], calibration = calibrated_side(
        raw, valid, sources, targets, across=across, prior=populations, scorer_veto=scorer_veto
    )
    if scorer_veto:
        last["vetoed_now"] = calibration.vetoed
        if across is None:
            last["separates"] = calibration.separates
    edges = [(p["source"], p["target"], float(w)) for p, w in zip(pairs, last["weights"], strict=True)]
    return ProbabilityGraph.from_edges(edges, faces)


def _input(pair: dict[str, Any], scorer: Any) -> np.ndarray:
    data = pair.get("histogram") if scorer.INPUT == "histogram" else pair.get("features")
    return np.zeros(1) if data is None else np.asarray(data)


def _scored(pair: dict[str, Any], scorer: Any) -> bool:
    """The registration found a pose, the scorer has something to read, and does not refuse the pair."""
    residual = float("nan") if pair.get("residual") is None else float(pair["residual"])
    return bool(pair["valid"]) and bool(_input(pair, scorer).any()) and not scorer.refuses(residual)


def _probability(pair: dict[str, Any], scorer: Any) -> float:
    if not _scored(pair, scorer):
        return 0.0
    return float(scorer.predict_proba(_input(pair, scorer)[None, :])[0])


def _seconds(pair: dict[str, Any], scorer: Any) -> float:
    t = pair["timings"]
    return float(t.get("register", 0.0)) + float(
        t.get("histogram" if scorer.INPUT == "histogram" else "features", 0.0)
    )


# ------------------------------------------------------------------------------------------------ reports


def write_results(out: Path, results: list[RowResult]) -> None:
    from coindie.bench.plots import write_records

    write_records(out, "results", results, results_table(results))
    plot_results(results, out / "generalization.png")


def results_table(results: list[RowResult]) -> str:
    """A markdown table: one line per row, the two scorers side by side."""
    by_row: dict[str, dict[str, RowResult]] = {}
    for r in results:
        by_row.setdefault(r.row, {})[r.scorer] = r
    head = "| row | " + " | ".join(
        f"{c} {s}" for c in ("FMI", "ARI", "same refused", "AUC", "s/pair") for s in SCORER_NAMES
    )
    lines = [head + " | clusters / dies (relief) |", "|---" * (2 + 5 * len(SCORER_NAMES)) + "|"]
    for row, scorers in by_row.items():
        cells = []
        for key, fmt in (
            ("fmi", "{:.3f}"), ("ari", "{:.3f}"), ("same_refused", "{:.1%}"), ("auc", "{:.3f}"),
            ("seconds_per_pair", "{:.3f}"),
        ):  # fmt: skip
            cells += [fmt.format(getattr(scorers[s], key)) if s in scorers else "" for s in SCORER_NAMES]
        relief = scorers.get("relief")
        count = f"{relief.clusters} / {relief.dies}" if relief else ""
        lines.append(f"| {row} | " + " | ".join(cells) + f" | {count} |")
    return "\n".join(lines) + "\n"


def plot_results(results: list[RowResult], path: Path) -> None:
    from coindie.bench.plots import fmi_bars

    rows = list(dict.fromkeys(r.row for r in results))
    series = {s: {r.row: r.fmi for r in results if r.scorer == s} for s in SCORER_NAMES}
    fmi_bars(
        rows, series, path, title="Die clustering on hoards of other scanners, flans and wear",
        ylabel="FMI (no labels, shipped defaults)",
    )  # fmt: skip
