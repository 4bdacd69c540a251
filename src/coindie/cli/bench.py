"""``coindie bench ...``: the benchmarks that reproduce the paper's tables."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.app import app, exits_cleanly
from coindie.errors import ParameterError

bench = typer.Typer(help="Benchmarks that reproduce the paper's tables.", no_args_is_help=True)
app.add_typer(bench, name="bench")


@bench.command("registration")
@exits_cleanly
def registration(
    data: Annotated[Path, typer.Argument(help="Hoard folder: scans, labels.csv, splits.csv, truth.json.")],
    out: Annotated[Path, typer.Option("--out", help="Folder for pairs.csv, per_die.csv, summary.*")],
    methods: Annotated[str, typer.Option(help="Comma-separated method names (coindie methods).")] = "relief",
    max_pairs: Annotated[int | None, typer.Option(help="At most this many pairs (dies take turns).")] = None,
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
    seed: Annotated[int, typer.Option(help="Seed of the random rotations.")] = 0,
    split: Annotated[str, typer.Option(help="Split whose dies are benchmarked.")] = "registration_test",
    transforms: Annotated[
        Path | None, typer.Option(help="Ground-truth transforms (truth.json format) for real scans.")
    ] = None,
) -> None:
    """The paper's registration benchmark: SRE x 1000 per die and per family, time per pair."""
    from rich.console import Console
    from rich.markdown import Markdown

    from coindie.bench.registration import benchmark_registration
    from coindie.cli.progress import counting_progress
    from coindie.registration import list_methods

    names = [m.strip() for m in methods.split(",") if m.strip()]
    unknown = [m for m in names if m not in list_methods()]
    if unknown or not names:
        raise ParameterError(f"unknown method(s) {unknown or methods!r}; known: {', '.join(list_methods())}")
    if workers < 1:
        raise ParameterError(f"--workers must be at least 1. Got {workers}.")
    with counting_progress("pairs") as progress:
        summary = benchmark_registration(
            data, names, out, max_pairs=max_pairs, workers=workers, seed=seed, split=split,
            transforms=transforms, progress=progress,
        )  # fmt: skip
    Console().print(Markdown((out / "summary.md").read_text().split("\n\nThe paper's")[0]))
    typer.echo(f"{sum(int(e['n_pairs']) for e in summary.values())} results in {out}")
