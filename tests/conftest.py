"""Fixtures shared by several test modules."""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def training_hoard(tmp_path_factory) -> Path:
    """The ``tiny`` preset at 0.1 mm, without bent or double-struck coins: a hoard whose registration
    training split has faces of one die to pair (the learned descriptors' tests train on it)."""
    from coindie.synth.design import DieParams
    from coindie.synth.hoard import PhysicsParams, synthesize
    from coindie.synth.scanner import ScanParams
    from coindie.synth.strike import StrikeParams

    out = tmp_path_factory.mktemp("training_hoard")
    physics = PhysicsParams(
        die=DieParams(pitch_mm=0.05),
        strike=StrikeParams(bend_probability=0.0, double_probability=0.0),
        scan=ScanParams(spacing_mm=0.1),
    )
    synthesize(out, preset="tiny", seed=3, physics=physics, workers=1)
    return out
