"""``coindie estimate`` and ``coindie dielinks`` on label CSVs (both headers), with clear errors."""

from __future__ import annotations

import json

import networkx as nx
from typer.testing import CliRunner

from coindie.cli.app import app


def _write(tmp_path):
    obverse = tmp_path / "obverse.csv"
    obverse.write_text("name, die\nL001D, A\nL002D, A\nL003D, B\nL004D, B\nL005D, B\nL006D, C\n")
    reverse = tmp_path / "reverse.csv"
    reverse.write_text("coin_id,die_id\nL0001R,x\nL0002R,y\nL0003R,y\nL0004R,z\nL0005R,z\nL0007R,w\n")
    return obverse, reverse


def test_estimate_json_gives_the_counts_and_every_estimator(tmp_path) -> None:
    obverse, _ = _write(tmp_path)
    result = CliRunner().invoke(app, ["estimate", str(obverse), "--json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)["obverse"]
    assert (report["n"], report["d"], report["d1"], report["d2"]) == (6, 3, 1, 1)
    assert abs(report["coverage"]["value"] - (1 - 1 / 6)) < 1e-12
    names = [e["name"] for e in report["estimators"]]
    assert names == [
        "Good / Esty 1986 (d/C)",
        "geometric model (Esty 2011)",
        "Chao1 (bias-corrected)",
        "ACE",
        "Carter (1983)",
    ]
    good = report["estimators"][0]
    assert abs(good["value"] - 3 / (5 / 6)) < 1e-9 and good["low"] <= good["value"] <= good["high"]
    table = CliRunner().invoke(app, ["estimate", str(obverse)])
    assert table.exit_code == 0 and "Chao1" in table.output and "n = 6 coins" in table.output


def test_dielinks_writes_every_export(tmp_path) -> None:
    obverse, reverse = _write(tmp_path)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["dielinks", str(obverse), str(reverse), "-o", str(out), "--json"])
    assert result.exit_code == 0, result.output
    summary = json.loads(result.output)["die_links"]
    assert summary["coins_with_both_faces"] == 5 and summary["combinations"] == 4 and summary["chains"] == 1
    for name in (
        "die_links.csv",
        "die_links_dies.csv",
        "die_links.graphml",
        "die_links.gexf",
        "die_links.svg",
        "die_links.png",
        "accumulation_obverse.png",
        "accumulation_reverse.svg",
        "estimates.json",
    ):
        assert (out / name).stat().st_size > 0, name
    graph = nx.read_graphml(out / "die_links.graphml")
    assert int(graph["O:B"]["R:z"]["weight"]) == 2


def test_bad_inputs_are_named(tmp_path) -> None:
    obverse, _ = _write(tmp_path)
    runner = CliRunner()
    alone = runner.invoke(app, ["dielinks", str(obverse)])
    assert alone.exit_code == 2 and "reverse" in alone.output
    missing = runner.invoke(app, ["estimate", str(tmp_path / "nope.csv")])
    assert missing.exit_code == 2 and "nope.csv" in missing.output
    wrong_side = runner.invoke(app, ["dielinks", str(obverse), str(obverse), "-o", str(tmp_path / "o")])
    assert wrong_side.exit_code == 2 and "no reverse faces" in wrong_side.output
