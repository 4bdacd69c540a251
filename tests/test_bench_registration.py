"""The registration benchmark on a tiny synthetic hoard whose transforms are known exactly."""

from __future__ import annotations

import csv
import itertools
import json

import numpy as np
import pytest
from typer.testing import CliRunner

from coindie.bench.registration import (
    SITUATIONS,
    benchmark_registration,
    plan_pairs,
    random_turn,
    read_pairs,
    timed_in_situation,
)
from coindie.cli.app import app
from coindie.errors import ParameterError
from coindie.io.truth import TruthError, load_truth
from coindie.transforms import rotation_angle_deg


@pytest.fixture(scope="module")
def hoard(training_hoard):
    """The tiny preset at 0.1 mm, no bends or double strikes, whose truth is not rigid (conftest)."""
    return training_hoard


def test_plan_covers_every_pair_within_each_die_of_the_split(hoard) -> None:
    truth = load_truth(hoard)
    by_die: dict[str, list[str]] = {}
    for face in truth.faces_in("registration_test"):
        by_die.setdefault(face.die, []).append(face.face_id)
    expected = {(d, *sorted(p)) for d, ids in by_die.items() for p in itertools.combinations(ids, 2)}
    planned = plan_pairs(truth, "registration_test")
    assert {(d, a, b) for d, a, b, _ in planned} == expected
    assert {truth.faces[a].family for _, a, _, _ in planned} == {"R", "DB", "D"}


def test_max_pairs_lets_every_die_take_its_turn(hoard) -> None:
    truth = load_truth(hoard)
    dies = {face.die for face in truth.faces_in("registration_test")}
    planned = plan_pairs(truth, "registration_test", max_pairs=len(dies))
    assert len(planned) == len(dies)
    assert {die for die, *_ in planned} == dies


def test_random_turns_are_seeded_and_within_the_papers_ranges() -> None:
    turns = [random_turn(0, f"L{i:04d}D", "L9999D") for i in range(200)]
    assert np.array_equal(turns[5], random_turn(0, "L0005D", "L9999D"))
    assert not np.array_equal(turns[5], random_turn(1, "L0005D", "L9999D"))
    tilts = [np.degrees(np.arccos(np.clip(T[2, 2], -1, 1))) for T in turns]
    assert max(tilts) <= np.hypot(25.0, 25.0) + 1e-6
    spins = [rotation_angle_deg(T[:3, :3]) for T in turns]
    assert max(spins) > 150.0  # z covers ±180°


def test_relief_recovers_the_true_transforms_and_icp_alone_does_not(hoard, tmp_path) -> None:
    summary = benchmark_registration(hoard, ["relief", "icp"], tmp_path, max_pairs=6)
    rows = read_pairs(tmp_path / "pairs.csv")
    assert len(rows) == 12
    relief = [r for r in rows if r["method"] == "relief"]
    assert all(r["success"] for r in relief)
    assert max(float(r["sre"]) for r in relief) < 0.02  # SRE x 1000 < 20
    # the faces' own plane: laid within a tenth of a degree and 0.05 mm; ICP from a turn is not
    assert max(float(r["twist_error_deg"]) for r in relief) < 0.1
    assert max(float(r["planar_error_mm"]) for r in relief) < 0.05
    assert summary["relief"]["planar_success"] == 1.0
    assert summary["icp"]["planar_success"] < 1.0
    assert summary["relief"]["All"] < 20.0
    # ICP from a start turned by up to 180 degrees is far off: the benchmark must see it.
    assert summary["icp"]["All"] > 5 * summary["relief"]["All"]
    stored = json.loads((tmp_path / "summary.json").read_text())
    assert set(stored) == {"relief", "icp"}
    assert {"R", "DB", "D", "All", "time_s"} <= set(stored["relief"])
    with (tmp_path / "per_die.csv").open() as handle:
        table = list(csv.reader(handle))
    assert [row[0] for row in table[1:]] == ["relief", "icp"]
    assert "FCGF (5000) + TEASER + ICP" in (tmp_path / "summary.md").read_text()
    assert (tmp_path / "per_die.png").stat().st_size > 0


def test_an_interrupted_run_resumes_without_redoing_pairs(hoard, tmp_path) -> None:
    benchmark_registration(hoard, ["relief"], tmp_path, max_pairs=2)
    first = read_pairs(tmp_path / "pairs.csv")
    with (tmp_path / "pairs.csv").open("a") as handle:
        handle.write("relief,R1,R,L00")  # a row cut short by a crash
    summary = benchmark_registration(hoard, ["relief"], tmp_path, max_pairs=4)
    rows = read_pairs(tmp_path / "pairs.csv")
    assert len(rows) == 4
    assert rows[:2] == first  # the first two were kept, not recomputed
    assert summary["relief"]["n_pairs"] == 4


def test_two_workers_give_the_same_errors_as_one(hoard, tmp_path) -> None:
    one = benchmark_registration(hoard, ["relief"], tmp_path / "one", max_pairs=3, workers=1)
    two = benchmark_registration(hoard, ["relief"], tmp_path / "two", max_pairs=3, workers=2)
    assert one["relief"]["All"] == pytest.approx(two["relief"]["All"], rel=1e-9)


def test_a_folder_without_splits_is_a_clear_error(hoard, tmp_path) -> None:
    (tmp_path / "labels.csv").write_text((hoard / "labels.csv").read_text())
    with pytest.raises(TruthError, match="splits.csv"):
        benchmark_registration(tmp_path, ["relief"], tmp_path / "out")


def test_cli_runs_the_benchmark_and_rejects_unknown_methods(hoard, tmp_path) -> None:
    runner = CliRunner()
    result = runner.invoke(app, ["bench", "registration", str(hoard), "--out", str(tmp_path / "b"),
                                 "--methods", "relief", "--max-pairs", "2"])  # fmt: skip
    assert result.exit_code == 0, result.output
    assert len(read_pairs(tmp_path / "b" / "pairs.csv")) == 2
    result = runner.invoke(app, ["bench", "registration", str(hoard), "--out", str(tmp_path / "c"),
                                 "--methods", "relief,nope"])  # fmt: skip
    assert result.exit_code == 2
    assert "nope" in result.output


def test_a_method_label_may_carry_checked_parameters() -> None:
    from coindie.bench.registration import parse_method

    assert parse_method("relief") == ("relief", {})
    assert parse_method("fcgf+icp[matcher.n_points=250; teaser.noise_bound=0.3]") == (
        "fcgf+icp",
        {"matcher.n_points": 250, "teaser.noise_bound": 0.3},
    )
    for bad, message in [
        ("nope[x=1]", "Unknown registration method"),
        ("fcgf[matcher.n_points=two]", "n_points"),
        ("fcgf[matcher.n_points=250", r"name\[key=value"),
        ("fcgf[n_points]", "not key=value"),
    ]:
        with pytest.raises(ParameterError, match=message):
            parse_method(bad)


class _Recorder:
    """A registration method that records what it is asked."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, str]] = []

    def register(self, source: str, target: str) -> str:
        self.calls.append((source, target))
        return f"{source}->{target}"


@pytest.mark.parametrize(
    "situation, seen",
    [("cold", []), ("new source", [("b", "b")]), ("all-pairs", [("b", "b"), ("a", "a")])],
)
def test_a_situation_shows_the_method_its_faces_first(situation: str, seen: list) -> None:
    """The speed benchmarks' situations: the faces a study has already met are registered first, and
    only the pair itself is timed and returned."""
    method = _Recorder()
    seconds, result = timed_in_situation(situation, method, "a", "b")
    assert method.calls == [*seen, ("a", "b")] and result == "a->b" and seconds >= 0.0
    assert situation in SITUATIONS
    with pytest.raises(ParameterError, match="situation"):
        timed_in_situation("warm", _Recorder(), "a", "b")
