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


# ------------------------------------------------------------------------------ the review app (serve)
@pytest.fixture(scope="session")
def review_project(tmp_path_factory) -> Path:
    """A small scored project (a few dozen faces), built once and shared by the xdist workers."""
    import os

    from serve_support import build_project

    if os.environ.get("COINDIE_TEST_REVIEW_ROOT"):  # a folder to build it in once and keep (development)
        return build_project(Path(os.environ["COINDIE_TEST_REVIEW_ROOT"]))
    base = tmp_path_factory.getbasetemp()  # xdist: the workers' common parent is this session's
    return build_project((base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base) / "serve-project")


@pytest.fixture
def fresh_project(review_project, tmp_path) -> Path:
    """A copy of ``review_project`` whose edit log a test may write."""
    from serve_support import copy_project

    return copy_project(review_project, tmp_path / "project")
