"""`coindie demo` (what `make demo` runs) on a very small hoard: every stage runs on the files it wrote."""

from __future__ import annotations

import json

from typer.testing import CliRunner

from coindie.cli.app import app
from coindie.io import read_scan


def test_demo_generates_loads_renders_and_registers(tmp_path) -> None:
    result = CliRunner().invoke(app, ["demo", str(tmp_path), "--scale", "0.02", "--workers", "2"])
    assert result.exit_code == 0, result.output
    hoard = tmp_path / "hoard"
    scans = sorted(hoard.glob("*.ply"))
    assert len(scans) >= 40
    assert "0 unreadable" in result.output
    renders = sorted((tmp_path / "renders").glob("*.png"))
    assert renders and all(read_scan(hoard / f"{png.stem}.ply") for png in renders)
    summary = json.loads((tmp_path / "registration" / "summary.json").read_text())
    assert summary["relief"]["n_pairs"] >= 3
    assert summary["relief"]["success"] == 1.0
    assert summary["relief"]["All"] < 20.0
