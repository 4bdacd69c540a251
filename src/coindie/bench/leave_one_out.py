"""``coindie bench generalization --leave-one-out``: does the relief scorer generalise along each axis?

For each axis of the wide world (:mod:`coindie.synth.physics`), a relief model is trained on a hoard of
the wide world with that axis held at its middle (``wide,AXIS:middle``: every other axis still drawn
over its whole range), and applied to the matrix's rows with that axis at its extremes (``AXIS:low``,
``AXIS:high``; their projects are the generalisation matrix's own, under ``OUT/projects``). Beside it,
the shipped model (trained on the whole wide world) on the same rows: where the held-out model does as
well, the scorer did not need to see the extreme to handle it.

Each held-out model is also judged on the all-hard mix (the ``hard`` row, extreme ``hard`` in the
table), when ``OUT/projects`` holds its project: there every axis is at its hard extreme at once, the
held-out one among them. The single-axis rows separate their dies so well that every model clusters them
without a mistake (FMI 1.000 at each of the 28 extremes, held-out and shipped models alike, BENCHMARK.md);
the all-hard mix is where leaving an axis out of training can still show.

Each training hoard is a ``study`` hoard scaled by ``scale`` (default 0.5: 40 faces), registered and
measured like any row (a project under ``OUT/leave-one-out/projects``); the model is fitted on every
valid pair it holds (hidden labels), with the shipped model's settings. Judged like the matrix: per-hoard
calibration, τ from the mixture (or the silhouette), FMI, ARI and pair AUC.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from coindie.errors import ParameterError

HELD_OUT, SHIPPED = "held out", "shipped"
#: The matrix's all-hard row (every axis at its hard extreme), on which each held-out model is judged too.
ALL_HARD = "hard"


@dataclass(frozen=True)
class LeaveOneOutResult:
    axis: str
    level: str
    model: str
    fmi: float
    ari: float
    auc: float
    training_pairs: int
    training_same_die: int


def run_leave_one_out(
    out: str | Path,
    axes: Sequence[str] | None = None,
    *,
    seed: int = 3000,
    workers: int = 2,
    scale: float = 0.5,
    echo: Callable[[str], None] = print,
) -> list[LeaveOneOutResult]:
    """Train per axis on ``wide,AXIS:middle``, test on the matrix's ``AXIS:low`` / ``AXIS:high`` rows
    that have a project in ``out/projects`` (run them with ``coindie bench generalization --rows``), and
    on its all-hard row (``hard``) when it has one.
    Writes ``leave-one-out.{csv,json,md,png}`` in ``out``."""
    from coindie.bench.generalization import row_project
    from coindie.similarity.scorers import default_scorer
    from coindie.synth.physics import AXES, HIGH, LOW

    out = Path(out)
    names = list(AXES)
    axes = list(axes) if axes else names
    unknown = [a for a in axes if a not in names]
    if unknown:
        raise ParameterError(f"unknown axis/axes {unknown}; known: {', '.join(names)}")
    shipped = default_scorer("relief")
    shipped_on: dict[Path, Any] = {}  # the shipped model's judgement of each row folder, made once
    results: list[LeaveOneOutResult] = []
    for k, axis in enumerate(axes):
        rows = [(level, out / "projects" / f"{axis}-{level}") for level in (LOW, HIGH)]
        rows = [(level, folder) for level, folder in rows if (folder / "project.sqlite").exists()]
        if not rows:
            echo(f"{axis:>12}: no project of {axis}:low or {axis}:high in {out / 'projects'}, left out")
            continue
        if (out / "projects" / ALL_HARD / "project.sqlite").exists():
            rows.append((ALL_HARD, out / "projects" / ALL_HARD))
        name = f"wide-{axis}-middle"
        hoard = _training_hoard(out / "leave-one-out" / "hoards" / name, axis, seed + k, workers, scale)
        project = row_project(out / "leave-one-out" / "projects" / name, hoard, workers, histograms=False)
        model, n_pairs, n_same = train_on_project(project, hoard, like=shipped)
        for level, folder in rows:
            results += _judge(axis, level, folder, out, model, shipped, shipped_on, n_pairs, n_same)
            for r in results[-2:]:
                echo(f"{axis:>12}:{level:<4} {r.model:>8}: FMI {r.fmi:.3f} ARI {r.ari:.3f} AUC {r.auc:.3f}")
        write_leave_one_out(out, results)
    if not results:
        raise ParameterError(f"no axis of {axes} has a low or high row's project in {out / 'projects'}")
    return results


def _training_hoard(folder: Path, axis: str, seed: int, workers: int, scale: float) -> Path:
    from coindie.synth.hoard import synthesize
    from coindie.synth.physics import MIDDLE, physics_by_name

    physics = physics_by_name(f"wide,{axis}:{MIDDLE}")
    synthesize(folder, preset="study", scale=scale, physics=physics, seed=seed, workers=workers)
    return folder


def train_on_project(project: Any, hoard: Path, *, like: Any) -> tuple[Any, int, int]:
    """A relief model (the settings of ``like``) fitted on every valid pair of ``project`` that has
    features, labelled by the hoard's hidden labels; with its pair and same-die counts."""
    from coindie.clustering import read_clusters
    from coindie.similarity.relief_classifier import ReliefClassifier

    truth = read_clusters(hoard / "labels.csv")
    X, y = [], []
    for pair in project.scored_pairs():
        features = pair.get("features")
        if not pair["valid"] or features is None or not np.asarray(features).any():
            continue
        X.append(np.asarray(features, dtype=np.float64))
        y.append(truth[pair["source"]] == truth[pair["target"]])
    model = ReliefClassifier(C=like.C, features=like.features, used=like.used, settings=like.settings)
    model.fit(np.array(X), np.array(y), seed=0)
    return model, len(y), int(np.sum(y))


def _judge(
    axis: str,
    level: str,
    folder: Path,
    out: Path,
    held_out: Any,
    shipped: Any,
    shipped_on: dict[Path, Any],
    n_pairs: int,
    n_same: int,
) -> list[LeaveOneOutResult]:
    """The held-out and the shipped model on one row. The shipped model's judgement of a row is kept in
    ``shipped_on``: the all-hard row comes back for every axis, and the same model gives the same result."""
    from coindie.bench.generalization import evaluate_row
    from coindie.project import open_project

    project, hoard = open_project(folder), out / "hoards" / folder.name
    row = ALL_HARD if level == ALL_HARD else f"{axis}:{level}"
    if folder not in shipped_on:
        shipped_on[folder] = evaluate_row(row, "relief", shipped, project, hoard)
    judged = []
    for label, r in (
        (HELD_OUT, evaluate_row(row, "relief", held_out, project, hoard)),
        (SHIPPED, shipped_on[folder]),
    ):
        judged.append(LeaveOneOutResult(axis, level, label, r.fmi, r.ari, r.auc, n_pairs, n_same))
    return judged


def write_leave_one_out(out: Path, results: list[LeaveOneOutResult]) -> None:
    from coindie.bench.plots import write_records

    write_records(out, "leave-one-out", results, leave_one_out_table(results))
    plot_leave_one_out(results, out / "leave-one-out.png")


def leave_one_out_table(results: list[LeaveOneOutResult]) -> str:
    """One line per (axis, extreme): FMI and AUC of the held-out and the shipped model."""
    cells: dict[tuple[str, str], dict[str, LeaveOneOutResult]] = {}
    for r in results:
        cells.setdefault((r.axis, r.level), {})[r.model] = r
    lines = [
        "| axis | extreme | FMI held out | FMI shipped | AUC held out | AUC shipped "
        "| training pairs (same-die) |",
        "|---|---|---|---|---|---|---|",
    ]
    for (axis, level), by_model in cells.items():
        held, ship = by_model.get(HELD_OUT), by_model.get(SHIPPED)

        def show(r: LeaveOneOutResult | None, key: str) -> str:
            return "" if r is None else f"{getattr(r, key):.3f}"

        training = f"{held.training_pairs} ({held.training_same_die})" if held else ""
        lines.append(
            f"| {axis} | {level} | {show(held, 'fmi')} | {show(ship, 'fmi')} | {show(held, 'auc')} | "
            f"{show(ship, 'auc')} | {training} |"
        )
    return "\n".join(lines) + "\n"


def plot_leave_one_out(results: list[LeaveOneOutResult], path: Path) -> None:
    from coindie.bench.plots import fmi_bars

    keys = list(dict.fromkeys(f"{r.axis}:{r.level}" for r in results))
    series = {
        f"relief model: {model}": {f"{r.axis}:{r.level}": r.fmi for r in results if r.model == model}
        for model in (HELD_OUT, SHIPPED)
    }
    fmi_bars(
        keys, series, path, ylabel="FMI (no labels)",
        title="Leave one axis out: trained with the axis at its middle, tested at its extremes and on "
        "the all-hard mix",
    )  # fmt: skip
