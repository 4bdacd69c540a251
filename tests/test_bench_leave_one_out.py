"""Leave one axis out: a relief model trained with the axis at its middle, judged at its extremes and
on the all-hard mix."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

pytestmark = pytest.mark.slow


def test_leave_one_out_trains_at_the_middle_and_judges_the_extremes(tmp_path: Path) -> None:
    from coindie.bench.generalization import row_project
    from coindie.bench.leave_one_out import ALL_HARD, HELD_OUT, SHIPPED, run_leave_one_out
    from coindie.synth.hoard import synthesize
    from coindie.synth.physics import NOISE_MM, physics_by_name

    out = tmp_path / "gen"
    hoard = out / "hoards" / "noise-high"
    synthesize(hoard, preset="study", scale=0.2, physics=physics_by_name("noise:high"), seed=5)
    row_project(out / "projects" / "noise-high", hoard, workers=1)
    hard = out / "hoards" / "hard"
    synthesize(hard, preset="study", scale=0.2, physics=physics_by_name("hard"), seed=6)
    row_project(out / "projects" / "hard", hard, workers=1)

    lines: list[str] = []
    results = run_leave_one_out(out, ["noise"], seed=7, workers=1, scale=0.2, echo=lines.append)

    # the extreme OUT holds, and the all-hard mix (every axis at its hard extreme, the noise among them)
    assert {(r.axis, r.level, r.model) for r in results} == {
        ("noise", "high", HELD_OUT),
        ("noise", "high", SHIPPED),
        ("noise", ALL_HARD, HELD_OUT),
        ("noise", ALL_HARD, SHIPPED),
    }
    held = next(r for r in results if r.model == HELD_OUT and r.level == "high")
    assert 0 < held.training_same_die < held.training_pairs
    # The training hoard is the wide world with the noise at its middle, every face alike ...
    truth = json.loads((out / "leave-one-out" / "hoards" / "wide-noise-middle" / "truth.json").read_text())
    noise = {face["physics"]["spec"]["scan"]["noise_mm"] for face in truth["faces"].values()}
    assert sorted(noise) == pytest.approx([sum(NOISE_MM) / 2])
    # ... and a model that never saw the high noise still separates the dies there.
    assert held.auc > 0.9
    table = (out / "leave-one-out.md").read_text()
    assert "| noise | high |" in table and "| noise | hard |" in table
    hard_held = next(r for r in results if r.model == HELD_OUT and r.level == ALL_HARD)
    assert np.isfinite(hard_held.fmi) and hard_held.auc > 0.5
    assert (out / "leave-one-out.png").stat().st_size > 0
    assert not any("no project of" in line for line in lines)
