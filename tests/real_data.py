"""Where the real Riedones3D facts lie for the tests: ``../shared/data/riedones3d`` beside the repository
(CI's layout). Tests that need them skip when the folder is not there."""

from __future__ import annotations

from pathlib import Path

RIEDONES3D = Path(__file__).resolve().parents[2] / "shared" / "data" / "riedones3d"
