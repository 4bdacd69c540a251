"""Options several commands share."""

from __future__ import annotations

from typing import Annotated

import typer

#: Where a long job's tasks run instead of local worker processes (coindie.project.backends).
Dask = Annotated[
    str | None,
    typer.Option(help="Dask scheduler address (tcp://host:8786), or 'local' for a LocalCluster."),
]
