"""Typed errors. Every error about a file names the file and the problem in one line."""

from __future__ import annotations

from pathlib import Path


class CoinDieError(Exception):
    """Base class of every error coindie raises on purpose."""


class ParameterError(CoinDieError, ValueError):
    """A parameter is outside its documented range or of the wrong kind."""


class InvalidScanError(CoinDieError, ValueError):
    """The content of a scan is unusable (no points, NaN coordinates, zero-length normals, ...)."""

    def __init__(self, problem: str, path: str | Path | None = None) -> None:
        self.path = Path(path) if path is not None else None
        self.problem = problem
        super().__init__(f"{self.path}: {problem}" if self.path is not None else problem)


class ScanReadError(InvalidScanError):
    """A scan file cannot be read: missing, truncated, wrong header, too large, unknown format."""

    def __init__(self, problem: str, path: str | Path) -> None:
        super().__init__(problem, path)


class LabelsError(CoinDieError, ValueError):
    """A label CSV cannot be read or contradicts itself."""

    def __init__(self, problem: str, path: str | Path | None = None) -> None:
        self.path = Path(path) if path is not None else None
        self.problem = problem
        super().__init__(f"{self.path}: {problem}" if self.path is not None else problem)


class WorkerLost(Exception):
    """The worker running a task died (killed, out of memory) ``MAX_ATTEMPTS`` times
    (:mod:`coindie.project.backends`): handed back in place of the task's result."""
