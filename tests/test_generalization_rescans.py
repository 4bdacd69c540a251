"""The die study does not depend on one scanner: the same coins rescanned noisier, coarser, or with other
cupping give the same clusters, with the shipped defaults and no labels; no same-die pair is refused for a
scale; a hoard whose scores do not separate is told so by ``coindie run``."""

from __future__ import annotations

from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

SEED = 11


def _base_physics():
    from coindie.synth.design import DieParams
    from coindie.synth.hoard import PhysicsParams
    from coindie.synth.scanner import ScanParams
    from coindie.synth.strike import StrikeParams

    return PhysicsParams(
        die=DieParams(pitch_mm=0.05),
        strike=StrikeParams(bend_probability=0.0, double_probability=0.0),
        scan=ScanParams(spacing_mm=0.07, noise_mm=(0.008, 0.012)),
    )


def _study(folder: Path, physics) -> dict:  # noqa: ANN001
    """Hoard -> project -> run -> ``coindie cluster --auto``, as a user runs it."""
    from typer.testing import CliRunner

    from coindie.cli import app
    from coindie.clustering import Clustering, read_clusters
    from coindie.project import init_project
    from coindie.project.run import RunConfig, run_project
    from coindie.synth.hoard import synthesize

    synthesize(folder / "hoard", preset="tiny", seed=SEED, physics=physics, workers=1)
    project, _ = init_project(folder / "project", folder / "hoard")
    lines: list[str] = []
    run_project(project, RunConfig(mode="exhaustive", workers=1), echo=lines.append)
    out = folder / "clusters.csv"
    result = CliRunner().invoke(app, ["cluster", str(folder / "project"), "--auto", "-o", str(out)])
    assert result.exit_code == 0, result.output
    clusters = Clustering({face: int(label) for face, label in read_clusters(out).items()})
    truth = read_clusters(folder / "hoard" / "labels.csv")
    return {"clusters": clusters, "truth": truth, "project": project}


@pytest.fixture(scope="module")
def studies(tmp_path_factory) -> dict[str, dict]:
    from coindie.synth.physics import rescanned

    base = _base_physics()
    variants = {
        "original": base,
        "noise x2": rescanned(base, noise_factor=2.0),
        "spacing x2": rescanned(base, spacing_factor=2.0),
        "cupping +-0.3 mm": rescanned(base, added_cup_mm=0.15),
    }
    root = tmp_path_factory.mktemp("rescans")
    return {name: _study(root / name.replace(" ", "_"), physics) for name, physics in variants.items()}


def test_the_original_hoard_is_clustered_into_its_dies(studies) -> None:
    from coindie.clustering import evaluate

    original = studies["original"]
    assert evaluate(original["clusters"].labels, original["truth"]).fmi >= 0.9


@pytest.mark.parametrize("variant", ["noise x2", "spacing x2", "cupping +-0.3 mm"])
def test_a_rescanned_hoard_gives_the_same_clusters(studies, variant: str) -> None:
    from sklearn.metrics import adjusted_rand_score

    original, other = studies["original"]["clusters"].labels, studies[variant]["clusters"].labels
    faces = sorted(original)
    assert sorted(other) == faces
    assert adjusted_rand_score([original[f] for f in faces], [other[f] for f in faces]) == pytest.approx(1.0)


@pytest.mark.parametrize("variant", ["original", "noise x2", "spacing x2", "cupping +-0.3 mm"])
def test_no_same_die_pair_is_refused(studies, variant: str) -> None:
    study = studies[variant]
    truth = study["truth"]
    refused = [
        (p["source"], p["target"], p["reason"])
        for p in study["project"].scored_pairs()
        if truth[p["source"]] == truth[p["target"]] and not p["valid"]
    ]
    assert refused == []


def test_run_warns_when_the_scores_do_not_separate(tmp_path: Path) -> None:
    """One face of each die: every pair is of two dies, so there is no same-die population to find (the
    mixture's upper component is then other dies of one design, or nothing). The run says so in words
    rather than inventing links, and so does the status."""
    import shutil

    from typer.testing import CliRunner

    from coindie.cli.app import app
    from coindie.clustering import read_clusters
    from coindie.synth.hoard import synthesize

    synthesize(tmp_path / "hoard", preset="riedones", scale=0.05, seed=SEED, workers=1)
    (tmp_path / "one").mkdir()
    first: dict[str, str] = {}
    for face, die in sorted(read_clusters(tmp_path / "hoard" / "labels.csv").items()):
        first.setdefault(str(die), face)
    for face in first.values():
        shutil.copy(tmp_path / "hoard" / f"{face}.ply", tmp_path / "one")
    runner = CliRunner()
    assert runner.invoke(app, ["init", str(tmp_path / "p"), str(tmp_path / "one")]).exit_code == 0
    result = runner.invoke(app, ["run", str(tmp_path / "p"), "--workers", "1", "--exhaustive"])
    assert result.exit_code == 0, result.output
    assert "WARNING" in result.output and "do not separate" in result.output
    status = runner.invoke(app, ["status", str(tmp_path / "p")])
    assert "WARNING" in status.output
    clustered = runner.invoke(app, ["cluster", str(tmp_path / "p"), "--auto", "-o", str(tmp_path / "c.csv")])
    assert clustered.exit_code == 0 and "do not separate" in clustered.output
