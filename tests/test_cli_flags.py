"""Library errors name parameters; the CLI names the flag that sets each."""

from __future__ import annotations

from pathlib import Path

from typer.testing import CliRunner

from coindie.cli.app import app
from coindie.cli.common import command_flags, with_flags


def test_with_flags_names_the_flag_of_each_parameter() -> None:
    flags = {"candidates": "--candidates", "max_faces": "--max-faces"}
    assert with_flags("The 'k' parameter of RunConfig must be >= 1. Got 0.", flags) == (
        "The 'k' parameter (--candidates) of RunConfig must be >= 1. Got 0."
    )
    message = with_flags("'max_faces' must be at least 2", flags)
    assert message == "'max_faces' (--max-faces) must be at least 2"
    # a parameter the command has no flag for stays as it is
    assert with_flags("The 'bins' parameter must be >= 1.", flags) == "The 'bins' parameter must be >= 1."


def test_command_flags_reads_the_declared_flags() -> None:
    from coindie.cli.project import run

    flags = command_flags(run)
    assert flags["candidates"] == "--candidates" and flags["exhaustive"] == "--exhaustive"
    assert flags["max_minutes"] == "--max-minutes" and "project" not in flags  # an argument


def test_run_names_its_flag_for_a_bad_parameter(tmp_path: Path) -> None:
    result = CliRunner().invoke(app, ["run", str(tmp_path / "nowhere"), "--workers", "-1"])
    assert result.exit_code == 2
    assert "'workers' parameter (--workers) of RunConfig must be an int in the range [0, inf)" in (
        result.output
    )


def test_run_refuses_a_bad_method_parameter_before_opening_the_project(tmp_path: Path) -> None:
    for param, message in (
        ("relief.angle_step", "--param must be written key=value"),
        ("relief.no_such=1", "has no parameter"),
        ("relief.angle_step=0", "angle_step"),
    ):
        result = CliRunner().invoke(app, ["run", str(tmp_path / "nowhere"), "--param", param])
        assert result.exit_code == 2 and message in result.output, (param, result.output)
        assert "nowhere" not in result.output  # the parameter, not the missing project, is told
