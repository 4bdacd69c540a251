"""``coindie register`` and ``coindie methods`` through typer's CliRunner, on PLY files of a known pair."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from coindie.cli.app import app
from coindie.io import write_ply
from coindie.registration import list_methods, rotation_error_deg, translation_error_mm
from coindie.transforms import euler_rigid
from synthetic_pairs import CoinPair, make_coin_pair

runner = CliRunner()


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> tuple[Path, Path, CoinPair]:
    pair = make_coin_pair(seed=4, radius=4.0, T_target_source=euler_rigid((1, 2, 6), (0.3, 0.1, -0.2)))
    folder = tmp_path_factory.mktemp("scans")
    source = write_ply(folder / "L0001D.ply", pair.source)
    target = write_ply(folder / "L0002D.ply", pair.target)
    return source, target, pair


def test_register_prints_the_transform_and_figures_as_json(files) -> None:
    source, target, pair = files
    result = runner.invoke(app, ["register", str(source), str(target), "--method", "icp", "--json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)
    T = np.array(report["T_target_source"])
    assert rotation_error_deg(pair.T_target_source, T) < 0.5
    assert translation_error_mm(pair.T_target_source, T) < 0.1
    assert report["valid"] is True
    assert report["method"] == "icp"
    assert report["source"]["id"] == "L0001D"
    assert report["params"]["icp.max_distance"] == 1.0
    assert {"prepare", "icp", "score", "total"} <= set(report["timings"])


def test_register_prints_a_readable_report_and_takes_parameters(files) -> None:
    source, target, _ = files
    args = [
        "register",
        str(source),
        str(target),
        "-m",
        "icp",
        "-p",
        "max_iterations=80",
        "--param",
        "init=centroids",
    ]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "valid            yes" in result.output
    assert "T_target_source (mm)" in result.output
    assert "residual" in result.output and "fitness" in result.output


def test_an_invalid_result_exits_with_code_1_and_says_why(files, tmp_path: Path) -> None:
    source, target, pair = files
    far = write_ply(tmp_path / "far.ply", pair.source.transformed(euler_rigid((0, 0, 0), (1000, 0, 0))))
    result = runner.invoke(app, ["register", str(far), str(target), "--method", "icp"])
    assert result.exit_code == 1
    assert "valid            NO:" in result.output
    assert "overlap" in result.output


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--method", "nope"], "Unknown registration method 'nope'"),
        (["--method", "icp", "--param", "max_iterations=0"], "The 'max_iterations' parameter of icp must be"),
        (["--method", "icp", "--param", "max_iterations"], "--param must be written key=value"),
        (["--method", "icp", "--param", "noise_bound=0.1"], "has no parameter 'noise_bound'"),
        (["--grid", "-1"], "--grid must be >= 0"),
    ],
)
def test_bad_arguments_exit_with_code_2_and_one_line(files, extra: list[str], message: str) -> None:
    source, target, _ = files
    result = runner.invoke(app, ["register", str(source), str(target), *extra])
    assert result.exit_code == 2
    assert message in result.output


def test_a_missing_file_is_named(files, tmp_path: Path) -> None:
    _, target, _ = files
    missing = tmp_path / "L0009R.ply"
    result = runner.invoke(app, ["register", str(missing), str(target), "--method", "icp"])
    assert result.exit_code == 2
    assert str(missing) in result.output and "no such file" in result.output


def test_methods_lists_every_method_with_its_parameters() -> None:
    result = runner.invoke(app, ["methods"])
    assert result.exit_code == 0
    for method in list_methods():
        assert f"{method}: " in result.output
    assert "teaser.noise_bound" in result.output and "(0, inf) mm" in result.output


def test_methods_as_json_for_one_method() -> None:
    result = runner.invoke(app, ["methods", "fpfh+teaser+icp", "--json"])
    assert result.exit_code == 0
    (method,) = json.loads(result.output)
    assert method["name"] == "fpfh+teaser+icp"
    assert method["params"]["teaser.noise_bound"]["default"] == 0.5
    assert method["params"]["refine.source_radius"]["unit"] == "mm"
    assert runner.invoke(app, ["methods", "nope"]).exit_code == 2


def test_register_defaults_to_our_relief_method_and_recovers_a_large_turn(tmp_path) -> None:
    turn = euler_rigid((4, -3, 120), (0.5, -0.3, 0.1))
    pair = make_coin_pair(seed=9, radius=6.0, T_target_source=turn)
    source = write_ply(tmp_path / "L0010D.ply", pair.source)
    target = write_ply(tmp_path / "L0011D.ply", pair.target)
    result = runner.invoke(app, ["register", str(source), str(target), "--json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)
    assert report["method"] == "relief"
    T = np.array(report["T_target_source"])
    assert rotation_error_deg(pair.T_target_source, T) < 0.5
    assert translation_error_mm(pair.T_target_source, T) < 0.1
