"""The typer application: its top-level options, and every command module registered on it.

The command modules import nothing of each other: each holds a ``commands`` Typer (and its groups), and
``_register`` joins them here.
"""

from __future__ import annotations

import importlib
import sys
from typing import Annotated

import typer

from coindie import __version__

app = typer.Typer(
    name="coindie",
    help="Find which ancient coins were struck by the same die, from 3D scans.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)

#: Optional back-ends reported by ``coindie --version``: import name -> what it is used for.
OPTIONAL_BACKENDS = {
    "open3d": "registration (ICP, FPFH, RANSAC)",
    "torch": "learned descriptors (FCGF, DIP)",
    "dask.distributed": "scheduling pairs on a cluster",
    "faiss": "candidate search",
}


def backend_report() -> list[tuple[str, str, str]]:
    """(module, version or 'not installed: reason', purpose) for each optional back-end."""
    rows = []
    for module, purpose in OPTIONAL_BACKENDS.items():
        try:
            loaded = importlib.import_module(module)
            top = sys.modules[module.split(".")[0]]
            version = getattr(loaded, "__version__", None) or getattr(top, "__version__", "loaded")
            rows.append((module, str(version), purpose))
        except Exception as error:  # an optional back-end may fail in many ways (missing .so, ...)
            rows.append((module, f"not available ({type(error).__name__}: {error})".splitlines()[0], purpose))
    return rows


def _version_callback(value: bool) -> None:
    if not value:
        return
    typer.echo(f"coindie {__version__} (Python {sys.version.split()[0]})")
    for module, status, purpose in backend_report():
        typer.echo(f"  {module:<18} {status:<40} {purpose}")
    raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[
        bool,
        typer.Option("--version", callback=_version_callback, is_eager=True, help="Version and back-ends."),
    ] = False,
) -> None:
    """Find which ancient coins were struck by the same die, from 3D scans."""


def main() -> None:
    app()


def _register() -> None:
    """Every command, in the order of ``coindie --help``; groups after the top-level commands."""
    from coindie.cli import (
        bench,
        cluster,
        demo,
        numismatics,
        project,
        registration,
        scans,
        serve,
        similarity,
        synth,
        train,
    )

    for module in (cluster, demo, numismatics, project, registration, scans, serve, synth):
        app.add_typer(module.commands)
    train.train.add_typer(similarity.commands)
    app.add_typer(bench.bench, name="bench")
    app.add_typer(numismatics.export, name="export")
    app.add_typer(train.train, name="train")


_register()
