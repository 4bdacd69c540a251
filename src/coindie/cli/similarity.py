"""``coindie train similarity``: the same-die classifier from a hoard's labelled training split."""

from __future__ import annotations

from contextlib import closing
from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import Dask, exits_cleanly
from coindie.errors import ParameterError

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()


@commands.command("similarity")
@exits_cleanly
def similarity(
    data: Annotated[
        list[Path],
        typer.Argument(help="Hoard folder(s): scans, labels.csv, splits.csv; several train one model."),
    ],
    out: Annotated[Path, typer.Option("--out", help="The model file to write (JSON).")],
    scorer: Annotated[
        str,
        typer.Option(help="relief (scale-free relief features, the default) or paper (distance histogram)."),
    ] = "relief",
    split: Annotated[str, typer.Option(help="Split whose labelled pairs train the model.")] = "cluster_train",
    method: Annotated[str, typer.Option(help="Registration method (coindie methods).")] = "relief",
    max_pairs: Annotated[int, typer.Option(help="Training pairs in all (0: every same-die pair).")] = 2000,
    max_faces: Annotated[int, typer.Option(help="Pairs among at most this many faces (0: all).")] = 200,
    negatives: Annotated[float, typer.Option(help="Different-die pairs per same-die pair.")] = 2.0,
    paper_scaler: Annotated[
        Path | None, typer.Option(help="Use the paper's standardisation (its mean_std.json) instead.")
    ] = None,
    symmetric: Annotated[bool, typer.Option(help="Symmetric histograms (mean of both directions).")] = False,
    authors_grids: Annotated[
        bool, typer.Option(help="Source 0.05 mm / target 0.1 mm grids (the authors' code), not the paper's.")
    ] = False,
    work: Annotated[
        Path | None,
        typer.Option(help="CSV of the measured pairs (resumed if present); default OUT.pairs.csv."),
    ] = None,
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
    dask: Dask = None,
    seed: Annotated[int, typer.Option(help="Seed of the pair sample and the calibration folds.")] = 0,
) -> None:
    """Register labelled pairs, measure them (relief features and distance histogram), fit the calibrated
    logistic regression of the chosen scorer."""
    from coindie.cli.progress import counting_progress
    from coindie.io.truth import load_truth
    from coindie.project.backends import make_backend
    from coindie.registration import list_methods
    from coindie.similarity import HistogramSettings, SameDieClassifier
    from coindie.similarity.batch import BatchConfig
    from coindie.similarity.relief_classifier import ReliefClassifier
    from coindie.similarity.scorers import SCORERS
    from coindie.similarity.training import train_similarity

    if scorer not in SCORERS:
        raise ParameterError(f"--scorer must be one of {', '.join(SCORERS)}. Got {scorer!r}.")
    if scorer == "relief" and (paper_scaler or symmetric or authors_grids):
        raise ParameterError(
            "--paper-scaler, --symmetric and --authors-grids describe histograms: use --scorer paper"
        )
    if method not in list_methods():
        raise ParameterError(f"unknown method {method!r}; known: {', '.join(list_methods())}")
    if workers < 1:
        raise ParameterError(f"--workers must be at least 1. Got {workers}.")
    settings = HistogramSettings.authors_code if authors_grids else HistogramSettings
    chosen = settings(symmetric=symmetric)
    classifier = (
        ReliefClassifier(settings=chosen)
        if scorer == "relief"
        else SameDieClassifier.from_paper_scaler(paper_scaler, settings=chosen)
        if paper_scaler
        else SameDieClassifier(settings=chosen)
    )
    backend = make_backend(workers, dask)
    with counting_progress("pairs") as progress, closing(backend):
        model = train_similarity(
            [load_truth(d) for d in data], work or out.with_suffix(".pairs.csv"), split=split,
            config=BatchConfig(method=method, settings=chosen), max_pairs=max_pairs or None,
            negatives=negatives, max_faces=max_faces or None, classifier=classifier,
            parallel_map=backend.map_ordered,
            seed=seed, progress=progress,
        )  # fmt: skip
    model.save(out)
    meta = model.metadata
    typer.echo(
        f"{out}: trained on {meta['n_pairs']} pairs ({meta['n_same_die']} same-die; invalid registrations "
        f"left out: {meta['invalid_same_die_pairs']} same-die, {meta['invalid_other_pairs']} other)"
    )
