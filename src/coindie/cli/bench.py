"""``coindie bench ...``: the benchmarks that reproduce the paper's tables."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import Dask, exits_cleanly
from coindie.errors import ParameterError

bench = typer.Typer(help="Benchmarks that reproduce the paper's tables.", no_args_is_help=True)


@bench.command("registration")
@exits_cleanly
def registration(
    data: Annotated[Path, typer.Argument(help="Hoard folder: scans, labels.csv, splits.csv, truth.json.")],
    out: Annotated[Path, typer.Option("--out", help="Folder for pairs.csv, per_die.csv, summary.*")],
    methods: Annotated[
        str,
        typer.Option(
            help="Comma-separated method names (coindie methods), each optionally with parameters: "
            "fcgf+icp[matcher.n_points=250]."
        ),
    ] = "relief",
    max_pairs: Annotated[int | None, typer.Option(help="At most this many pairs (dies take turns).")] = None,
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
    dask: Dask = None,
    seed: Annotated[int, typer.Option(help="Seed of the random rotations.")] = 0,
    split: Annotated[str, typer.Option(help="Split whose dies are benchmarked.")] = "registration_test",
    transforms: Annotated[
        Path | None, typer.Option(help="Ground-truth transforms (truth.json format) for real scans.")
    ] = None,
) -> None:
    """The paper's registration benchmark: SRE x 1000 per die and per family, time per pair."""
    from rich.console import Console
    from rich.markdown import Markdown

    from coindie.bench.registration import benchmark_registration, parse_method
    from coindie.cli.progress import counting_progress
    from coindie.registration import list_methods, method_info

    names = [m.strip() for m in methods.split(",") if m.strip()]
    if not names:
        raise ParameterError(f"no method in {methods!r}; known: {', '.join(list_methods())}")
    for name in names:  # methods and the parameters in their labels are checked before any pair runs
        method, params = parse_method(name)
        method_info(method).build(params)
    if workers < 1:
        raise ParameterError(f"--workers must be at least 1. Got {workers}.")
    with counting_progress("pairs") as progress:
        summary = benchmark_registration(
            data, names, out, max_pairs=max_pairs, workers=workers, dask=dask, seed=seed, split=split,
            transforms=transforms, progress=progress,
        )  # fmt: skip
    Console().print(Markdown((out / "summary.md").read_text().split("\n\nThe paper's")[0]))
    typer.echo(f"{sum(int(e['n_pairs']) for e in summary.values())} results in {out}")


@bench.command("clustering")
@exits_cleanly
def clustering(
    data: Annotated[Path, typer.Argument(help="Hoard folder: scans, labels.csv, splits.csv.")],
    out: Annotated[Path, typer.Option("--out", help="Folder for pairs.csv, graphs, clusters, summary.*")],
    method: Annotated[str, typer.Option(help="Registration method (coindie methods).")] = "relief",
    model: Annotated[
        Path | None, typer.Option(help="Same-die classifier JSON; default: train one on cluster_train.")
    ] = None,
    max_faces: Annotated[
        int | None, typer.Option(help="At most this many faces per group and split (whole-die samples).")
    ] = None,
    train_pairs: Annotated[int, typer.Option(help="Training pairs when training the classifier.")] = 2000,
    train_faces: Annotated[int, typer.Option(help="Faces the training pairs are drawn among.")] = 200,
    groups: Annotated[str, typer.Option(help="Comma-separated groups: R, DB, D.")] = "R,DB,D",
    clustering_methods: Annotated[
        str, typer.Option("--clustering", help="Comma-separated: components, average, leiden.")
    ] = "components,average,leiden",
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
    dask: Dask = None,
    seed: Annotated[int, typer.Option(help="Seed of the face and pair samples.")] = 0,
) -> None:
    """The paper's clustering benchmark (Table 3): FMI/ARI and clusters per group, τ by validation."""
    from rich.console import Console
    from rich.markdown import Markdown

    from coindie.bench.clustering import BenchOptions, benchmark_clustering
    from coindie.cli.progress import counting_progress
    from coindie.registration import list_methods

    if method not in list_methods():
        raise ParameterError(f"unknown method {method!r}; known: {', '.join(list_methods())}")
    if workers < 1:
        raise ParameterError(f"--workers must be at least 1. Got {workers}.")
    options = BenchOptions(
        method=method, model=model, max_faces=max_faces, train_pairs=train_pairs, train_faces=train_faces,
        methods=tuple(m.strip() for m in clustering_methods.split(",") if m.strip()),
        groups=tuple(g.strip().upper() for g in groups.split(",") if g.strip()), workers=workers, dask=dask,
        seed=seed,
    )  # fmt: skip
    with counting_progress("pairs") as progress:
        benchmark_clustering(data, out, options, progress=progress)
    Console().print(Markdown((out / "summary.md").read_text().split("\n\nThe paper's")[0]))
    typer.echo(f"results in {out}")


@bench.command("generalization")
@exits_cleanly
def generalization(
    out: Annotated[Path, typer.Option("--out", help="Folder for the hoards, projects and results.*")],
    rows: Annotated[
        str,
        typer.Option(help="Comma-separated rows (AXIS:low, AXIS:high, hard, riedones); default: every row."),
    ] = "",
    seed: Annotated[int, typer.Option(help="Seed of the first row's hoard (the next rows count up).")] = 1000,
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 2,
    riedones_scale: Annotated[float, typer.Option(help="Scale of the riedones preset's row.")] = 0.05,
    evaluate_only: Annotated[
        bool,
        typer.Option(help="Score the pairs the rows' projects hold with the shipped models; run nothing."),
    ] = False,
    leave_one_out: Annotated[
        bool,
        typer.Option(
            help="Per axis, train a relief model with the axis at its middle and test it on the rows "
            "of its extremes and the all-hard row that OUT holds (leave-one-out.md); no matrix rows are run."
        ),
    ] = False,
    axes: Annotated[str, typer.Option(help="Comma-separated axes for --leave-one-out (default: all).")] = "",
    training_scale: Annotated[
        float, typer.Option(help="Scale of the study hoard each --leave-one-out model trains on.")
    ] = 0.5,
) -> None:
    """Die clustering, scans only and shipped defaults, on hoards of other scanners, flans and wear:
    FMI, ARI, same-die pairs refused, pair AUC and time per pair, for the relief and paper scorers."""
    from coindie.bench.generalization import run_generalization

    if workers < 1:
        raise ParameterError(f"--workers must be at least 1. Got {workers}.")
    if leave_one_out:
        from coindie.bench.leave_one_out import run_leave_one_out

        chosen_axes = [a.strip() for a in axes.split(",") if a.strip()] or None
        run_leave_one_out(
            out, chosen_axes, seed=seed + 2000, workers=workers, scale=training_scale, echo=typer.echo
        )
        typer.echo((out / "leave-one-out.md").read_text())
        return
    chosen = [r.strip() for r in rows.split(",") if r.strip()] or None
    run_generalization(
        out, chosen, seed=seed, workers=workers, riedones_scale=riedones_scale,
        evaluate_only=evaluate_only, echo=typer.echo,
    )  # fmt: skip
    typer.echo((out / "results.md").read_text())
