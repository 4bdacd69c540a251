"""A progress bar with an ETA for long commands (rich), fed by ``(advance, new_total)`` calls."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager

from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)


@contextmanager
def counting_progress(what: str) -> Iterator[Callable[[int, int], None]]:
    """Yield ``update(advance, total)``: ``total`` > 0 sets the total (with ``advance`` already done)."""
    columns = (
        TextColumn(f"{what:>8}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TextColumn("ETA"),
        TimeRemainingColumn(),
    )  # fmt: skip
    with Progress(*columns, transient=False) as bar:
        task = bar.add_task(what, total=None)

        def update(advance: int, total: int) -> None:
            if total:
                bar.update(task, total=total, completed=advance)
            else:
                bar.advance(task, advance)

        yield update
