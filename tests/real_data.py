"""Where the real Riedones3D facts lie for the tests: ``../shared/data/riedones3d`` beside the repository
(CI's layout). Tests that need them skip when the folder is not there, saying where it was looked for."""

from __future__ import annotations

from pathlib import Path

import pytest

RIEDONES3D = Path(__file__).resolve().parents[2] / "shared" / "data" / "riedones3d"


def real_file(name: str) -> Path:
    """The path of one of the real facts; the test is skipped, naming the path and the layout, when it is
    not there (a clone without ``../shared`` beside it)."""
    path = RIEDONES3D / name
    if not path.is_file():
        pytest.skip(f"{path} not found: the real Riedones3D facts are read from ../shared beside the clone")
    return path
