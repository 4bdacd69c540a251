"""Runs of a die-study project on a tiny synthetic hoard: resumable after a killed worker or a killed run,
identical on local processes and on a Dask LocalCluster, bad scans recorded, new scans add only their pairs.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import psutil
import pytest

from coindie.project import init_project, open_project
from coindie.project.run import RunConfig, run_project, tile_batches
from coindie.project.status import project_status

#: What a result is, apart from its timings: every stored figure of a pair.
RESULT_FIELDS = ("source", "target", "side", "origin", "status", "method", "valid", "reason", "probability")


@pytest.fixture(scope="module")
def hoard(tmp_path_factory) -> Path:
    from coindie.synth.hoard import PhysicsParams, synthesize
    from coindie.synth.scanner import ScanParams

    out = tmp_path_factory.mktemp("hoard")
    # A 0.1 mm scanner keeps the faces small and the runs short.
    synthesize(out, preset="tiny", seed=5, physics=PhysicsParams(scan=ScanParams(spacing_mm=0.1)), workers=2)
    for path in out.glob("L000[78]?.ply"):  # 12 faces, 30 pairs: enough batches to kill one mid-run
        path.unlink()
    return out


@pytest.fixture(scope="module")
def classifier(tmp_path_factory) -> str:
    """The shipped same-die model, saved as a model file."""
    from coindie.similarity import SameDieClassifier

    path = tmp_path_factory.mktemp("model") / "classifier.json"
    SameDieClassifier.load_default().save(path)
    return str(path)


@pytest.fixture(scope="module")
def reference(hoard, classifier, tmp_path_factory) -> list[dict]:
    """An uninterrupted run on local processes: the pairs every other run must reproduce."""
    folder = tmp_path_factory.mktemp("reference")
    project, _ = init_project(folder, hoard, hoard / "labels.csv")
    run_project(project, RunConfig(workers=2, mode="exhaustive", classifier=classifier), echo=lambda _: None)
    return _results(folder)


def _results(folder: Path) -> list[dict]:
    return open_project(folder).scored_pairs()


def assert_same_pairs(found: list[dict], expected: list[dict]) -> None:
    assert [(p["source"], p["target"]) for p in found] == [(p["source"], p["target"]) for p in expected]
    for a, b in zip(found, expected, strict=True):
        assert {k: a[k] for k in RESULT_FIELDS} == {k: b[k] for k in RESULT_FIELDS}
        np.testing.assert_array_equal(a["T_target_source"], b["T_target_source"])
        np.testing.assert_array_equal(a["histogram"], b["histogram"])


def test_reference_scores_every_same_side_pair_once(reference, hoard) -> None:
    faces = sorted(p.stem for p in hoard.glob("*.ply"))
    per_side = {side: [f for f in faces if f.endswith(side)] for side in "DR"}
    expected = sum(len(v) * (len(v) - 1) // 2 for v in per_side.values())
    assert len(reference) == expected
    assert all(p["source"][-1] == p["target"][-1] == p["side"] for p in reference)  # no cross-side pair
    assert len({(p["source"], p["target"]) for p in reference}) == expected
    # the faces were registered: same-die pairs of the tiny hoard align (their truth is known)
    labels = _labels(hoard)
    same = [p for p in reference if labels[p["source"]] == labels[p["target"]]]
    assert same and np.mean([p["valid"] for p in same]) >= 0.8


def _labels(hoard: Path) -> dict[str, str]:
    from coindie.io.labels import read_labels

    return {str(k): v for k, v in read_labels(hoard / "labels.csv").items()}


def _start_run(folder: Path, classifier: str) -> subprocess.Popen:
    coindie = Path(sys.executable).parent / "coindie"
    command = [str(coindie), "run", str(folder), "--workers", "2", "--exhaustive"]
    command += ["--classifier", classifier, "--batch-faces", "2"]
    return subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True, text=True
    )


def _done(folder: Path) -> int:
    import sqlite3

    try:
        with sqlite3.connect(folder / "project.sqlite", timeout=30) as db:
            return db.execute("SELECT COUNT(*) FROM pairs WHERE status = 'done'").fetchone()[0]
    except sqlite3.OperationalError:  # tables not made yet
        return 0


def _wait_for(condition, timeout: float = 120.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.2)


def test_a_killed_worker_is_replaced_and_nothing_is_lost(hoard, classifier, reference, tmp_path) -> None:
    init_project(tmp_path, hoard)
    run = _start_run(tmp_path, classifier)
    _wait_for(lambda: _done(tmp_path) >= 4)
    children = psutil.Process(run.pid).children(recursive=True)
    workers = [p for p in children if "spawn_main" in " ".join(p.cmdline())]  # not the resource tracker
    assert workers, "no worker process to kill"
    os.kill(workers[0].pid, signal.SIGKILL)  # mid-run: the batches it held are run again
    output, _ = run.communicate(timeout=300)
    assert run.returncode == 0, output
    assert "died and were replaced 1 time(s)" in output
    assert_same_pairs(_results(tmp_path), reference)


def test_kill_9_of_the_run_then_resume_repeats_no_committed_pair(
    hoard, classifier, reference, tmp_path
) -> None:
    init_project(tmp_path, hoard)
    run = _start_run(tmp_path, classifier)
    _wait_for(lambda: _done(tmp_path) >= 6)
    os.killpg(run.pid, signal.SIGKILL)  # the run and its workers, at once, mid-batch
    run.wait()
    before = {(p["source"], p["target"]): (p["run_id"], p["done_at"]) for p in _results(tmp_path)}
    assert 0 < len(before) < len(reference)
    # rerun (in this process: also covers the killed run's stale 'running' row)
    project = open_project(tmp_path)
    report = run_project(project, RunConfig(workers=2, mode="exhaustive", classifier=classifier), echo=print)
    assert report.pairs_done == len(reference) - len(before)
    after = _results(tmp_path)
    assert_same_pairs(after, reference)
    kept = {(p["source"], p["target"]): (p["run_id"], p["done_at"]) for p in after}
    assert all(kept[key] == value for key, value in before.items())  # committed pairs were not redone
    runs = [r["status"] for r in project.db.execute("SELECT status FROM runs ORDER BY run_id")]
    assert runs == ["killed", "finished"]


def test_dask_local_cluster_gives_the_same_pairs(hoard, classifier, reference, tmp_path) -> None:
    pytest.importorskip("dask.distributed")
    project, _ = init_project(tmp_path, hoard)
    config = RunConfig(workers=2, dask="local", mode="exhaustive", classifier=classifier, batch_faces=3)
    report = run_project(project, config, echo=lambda _: None)
    assert "LocalCluster of 2" in report.backend
    assert_same_pairs(_results(tmp_path), reference)


def test_a_bad_scan_is_recorded_and_new_scans_only_add_their_pairs(
    hoard, classifier, reference, tmp_path
) -> None:
    from coindie.project.status import project_status

    scans = tmp_path / "scans"
    scans.mkdir()
    later = {"L0003D.ply", "L0006R.ply"}
    for path in hoard.glob("*.ply"):
        if path.name not in later:
            shutil.copy(path, scans / path.name)
    (scans / "L0099D.ply").write_bytes(
        b"ply\nformat binary_little_endian 1.0\nelement vertex 10\nend_header\n"
    )
    project, _ = init_project(tmp_path / "project", scans)
    config = RunConfig(workers=2, mode="exhaustive", classifier=classifier)
    first = run_project(project, config, echo=lambda _: None)
    bad = [s for s in project.scans() if s.status == "error"]
    assert [s.face_id for s in bad] == ["L0099D"]
    assert "L0099D.ply" in bad[0].error and len(first.faces_failed) == 1
    assert "bad scan: L0099D" in project_status(project).text()
    for name in later:
        shutil.copy(hoard / name, scans / name)
    second = run_project(project, config, echo=lambda _: None)
    assert second.faces_prepared == 2  # the bad scan is not tried again while its file is unchanged
    assert second.pairs_done == len(reference) - first.pairs_done
    new = [p for p in _results(tmp_path / "project") if p["run_id"] == second.run_id]
    assert new and all({p["source"], p["target"]} & {"L0003D", "L0006R"} for p in new)
    assert_same_pairs(_results(tmp_path / "project"), reference)


def test_tiles_cover_every_pair_once_bound_the_faces_per_batch_and_run_each_source_in_one_go() -> None:
    faces = [f"L{i:04d}D" for i in range(40)]
    rng = np.random.default_rng(1)
    pairs = sorted({tuple(sorted(rng.choice(faces, 2, replace=False))) for _ in range(300)})
    batches = tile_batches(pairs, batch_faces=4)
    flat = [pair for batch in batches for pair in batch]
    assert sorted(flat) == pairs
    assert all(len({f for pair in batch for f in pair}) <= 8 for batch in batches)
    # a source's pairs run one after another (the relief search keeps the last few sources' turns)
    for batch in batches:
        sources = [source for source, _ in batch]
        assert len([s for k, s in enumerate(sources) if k == 0 or s != sources[k - 1]]) == len(set(sources))


def test_a_worker_does_not_take_one_projects_face_for_anothers(tmp_path: Path) -> None:
    """One worker runs in the caller's process and keeps the faces it loaded: two projects in turn whose
    faces share an id (every hoard has an L0001D) each get their own."""
    import numpy as np

    from coindie.project.workers import _Worker

    worker = _Worker()
    worker.cache_faces = 4
    paths = []
    for k in range(2):
        path = tmp_path / f"project{k}" / "face.npz"
        path.parent.mkdir()
        points = np.full((20, 3), float(k))
        np.savez(path, points=points.astype(np.float32), normals=np.tile([0.0, 0.0, 1.0], (20, 1)))
        paths.append(str(path))
    first, second = (worker.face("L0001D", p) for p in paths)
    assert first.points[0, 0] == 0.0 and second.points[0, 0] == 1.0
    assert worker.face("L0001D", paths[0]) is first  # still cached: loaded once per file


def test_the_run_command_registers_with_the_method_parameters_it_is_given(hoard, tmp_path: Path) -> None:
    """``coindie run --param``: the run's method takes the parameters (stored with the run), and its pairs
    are a parameter set of their own, beside the defaults' (a project can compare both)."""
    import json

    from typer.testing import CliRunner

    from coindie.cli.app import app

    init_project(tmp_path / "p", hoard)
    common = ["run", str(tmp_path / "p"), "--workers", "1", "--exhaustive", "--relay-neighbours", "0"]
    given = CliRunner().invoke(app, [*common, "-p", "relief.angle_search=spectrum", "-p", "blocks.levels=0"])
    assert given.exit_code == 0, given.output
    project = open_project(tmp_path / "p")
    run = project.latest_run()
    assert run is not None
    assert json.loads(run["config"])["method_params"] == {
        "relief.angle_search": "spectrum",
        "blocks.levels": 0,
    }
    assert CliRunner().invoke(app, common).exit_code == 0
    project = open_project(tmp_path / "p")
    defaults = project.latest_run()
    assert defaults is not None and defaults["params_hash"] != run["params_hash"]
    given_pairs, default_pairs = (project.scored_pairs(r["params_hash"]) for r in (run, defaults))
    assert len(given_pairs) == 30
    assert [(p["source"], p["target"]) for p in given_pairs] == [
        (p["source"], p["target"]) for p in default_pairs
    ]


def test_a_hoard_of_small_coins_is_scored_with_the_lengths_of_its_size(
    hoard, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Four coins of the tiny hoard and their copies 0.55 times as large (10-12 mm, the die's details with
    them): the run measures the small coins, says so, scales the shipped scorer's lengths (a parameter set
    of its own) and judges every pair as on the coins of the size it was trained on. The shipped model is
    loaded once a run, and each face's diameter is kept."""
    import json
    from dataclasses import replace

    from typer.testing import CliRunner

    import coindie.similarity.scorers as scorers
    from coindie.cli.app import app
    from coindie.io import read_scan, write_ply

    loads = []
    shipped = scorers.default_scorer
    monkeypatch.setattr(scorers, "default_scorer", lambda *args: loads.append(args) or shipped(*args))

    own, small = tmp_path / "own", tmp_path / "small"
    own.mkdir(), small.mkdir()
    for path in sorted(hoard.glob("L000[1-4]?.ply")):
        shutil.copy(path, own / path.name)
        scan = read_scan(path)
        write_ply(small / path.name, replace(scan, points=scan.points * 0.55))
    outputs, runs, pairs = {}, {}, {}
    for name, scans in (("own", own), ("small", small)):
        init_project(tmp_path / f"p-{name}", scans)
        command = [
            "run",
            str(tmp_path / f"p-{name}"),
            "--workers",
            "1",
            "--exhaustive",
            "--relay-neighbours",
            "0",
        ]
        loads.clear()
        result = CliRunner().invoke(app, command)
        assert result.exit_code == 0, result.output
        assert len(loads) == 1
        project = open_project(tmp_path / f"p-{name}")
        outputs[name], runs[name], pairs[name] = result.output, project.latest_run(), project.scored_pairs()
        kept = project.db.execute("SELECT COUNT(*) FROM meta WHERE key LIKE 'diameter:%'").fetchone()[0]
        assert kept == 8  # each face's diameter, measured once

    assert "coins of" not in outputs["own"] and "coin_scale" not in json.loads(runs["own"]["config"])
    scale = json.loads(runs["small"]["config"])["coin_scale"]
    assert 2**-1 <= scale <= 2**-0.5  # 0.55 within half a step
    assert re.search(
        rf"coins of 1[0-3]\.\d mm \(the median of 8 faces\).* scaled by {scale:.3g} ", outputs["small"]
    )
    assert runs["small"]["params_hash"] != runs["own"]["params_hash"]
    told = f"scaled by {scale:.3g} to the coins' size"
    assert told in project_status(open_project(tmp_path / "p-small")).text()
    assert told not in project_status(open_project(tmp_path / "p-own")).text()
    assert [(p["source"], p["target"]) for p in pairs["small"]] == [
        (p["source"], p["target"]) for p in pairs["own"]
    ]
    labels = _labels(hoard)
    same = [labels[p["source"]] == labels[p["target"]] for p in pairs["own"]]
    assert 0 < sum(same) < len(same)
    for a, b, same_die in zip(pairs["own"], pairs["small"], same, strict=True):
        assert (a["probability"] > 0.5) == (b["probability"] > 0.5) == same_die, (a, b)
