"""The typer application and its top-level options."""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable
from functools import wraps
from typing import Annotated, ParamSpec, TypeVar

import typer

from coindie import __version__
from coindie.errors import CoinDieError

app = typer.Typer(
    name="coindie",
    help="Find which ancient coins were struck by the same die, from 3D scans.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)

P = ParamSpec("P")
R = TypeVar("R")

#: Optional back-ends reported by ``coindie --version``: import name -> what it is used for.
OPTIONAL_BACKENDS = {
    "open3d": "registration (ICP, FPFH, RANSAC)",
    "torch": "learned descriptors (FCGF, DIP)",
    "dask.distributed": "scheduling pairs on a cluster",
    "faiss": "candidate search",
}


def exits_cleanly(command: Callable[P, R]) -> Callable[P, R]:
    """Turn a ``CoinDieError`` into a one-line message on stderr and exit code 2."""

    @wraps(command)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        try:
            return command(*args, **kwargs)
        except CoinDieError as error:
            typer.echo(f"coindie: error: {error}", err=True)
            raise typer.Exit(code=2) from None

    return wrapper


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


# Command groups register themselves on ``app`` when imported.
from coindie.cli import bench as _bench  # noqa: E402,F401
from coindie.cli import cluster as _cluster  # noqa: E402,F401
from coindie.cli import demo as _demo  # noqa: E402,F401
from coindie.cli import numismatics as _numismatics  # noqa: E402,F401
from coindie.cli import project as _project  # noqa: E402,F401
from coindie.cli import registration as _registration  # noqa: E402,F401
from coindie.cli import scans as _scans  # noqa: E402,F401
from coindie.cli import serve as _serve  # noqa: E402,F401
from coindie.cli import similarity as _similarity  # noqa: E402,F401
from coindie.cli import synth as _synth  # noqa: E402,F401
from coindie.cli import train as _train  # noqa: E402,F401
