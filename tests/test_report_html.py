"""The die catalogue on a small synthetic project (the ``tiny`` hoard, every pair scored, built once for this
module): transforms chained along each die's best links match the hoard's truth, the HTML holds one plate
per die with embedded images, the metadata and the verified flag; Chromium prints and shoots it; the
aligned PLY models per die lie on their reference."""

from __future__ import annotations

import json
import re
from pathlib import Path

import networkx as nx
import numpy as np
import pytest
from scipy.spatial import cKDTree
from typer.testing import CliRunner

from coindie.cli.app import app
from coindie.io import read_scan
from coindie.numismatics.sources import project_dies
from coindie.project import init_project, open_project
from coindie.report import build_report, chromium_binary, print_pdf, project_alignments, screenshot
from coindie.report.alignment import align_die, scan_paths
from coindie.synth.writer import read_truth, true_transform

NO_CHROMIUM = "headless Chromium is not installed (/usr/bin/chromium; apt-get install chromium)"


@pytest.fixture(scope="module")
def study(tmp_path_factory) -> Path:
    """A scored project of the ``tiny`` hoard (16 faces; the shipped classifier needs its 0.05 mm scans)."""
    from coindie.project.run import RunConfig, run_project
    from coindie.synth.hoard import synthesize

    out = tmp_path_factory.mktemp("numismatic_study")
    synthesize(out / "hoard", preset="tiny", seed=5, workers=2)
    project, _ = init_project(out / "project", out / "hoard", out / "hoard" / "labels.csv")
    run_project(project, RunConfig(workers=2, mode="exhaustive"), echo=lambda _: None)
    (out / "coins.csv").write_text(
        "coin_id,weight,findspot\nL1,3.10,Rennes\nL0002,3.30,Rennes\nL3,2.90,Paris\n"
    )
    return out


def _rotation_z(degrees: float, shift: tuple[float, float, float] = (0, 0, 0)) -> np.ndarray:
    a = np.radians(degrees)
    T = np.eye(4)
    T[:2, :2] = [[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]]
    T[:3, 3] = shift
    return T


def test_transforms_compose_along_the_maximum_spanning_tree() -> None:
    """a -> b -> c registered with high probability; a wrong direct a - c registration of low probability
    is not used: T_ref_c must be the product along the path."""
    T_b_a, T_c_b = _rotation_z(10, (1, 0, 0)), _rotation_z(20, (0, 2, 0))
    graph = nx.Graph()
    graph.add_edge("a", "b", weight=0.99, T=("b", "a", T_b_a))  # stored as source a, target b
    graph.add_edge("c", "b", weight=0.98, T=("c", "b", T_c_b))  # stored as source b, target c
    graph.add_edge("a", "c", weight=0.10, T=("c", "a", _rotation_z(90)))
    graph.add_edge("d", "e", weight=0.9, T=("e", "d", np.eye(4)))  # another die's faces: not used
    alignment = align_die("D", "0", ["a", "b", "c"], graph)
    assert alignment.reference == "b"  # the best-linked face
    assert np.allclose(alignment.T_reference_face["a"], T_b_a)
    assert np.allclose(alignment.T_reference_face["c"], np.linalg.inv(T_c_b))
    assert {(x, y) for x, y, _ in alignment.tree} == {("a", "b"), ("b", "c")}
    lonely = align_die("D", "1", ["a", "z"], graph)
    assert lonely.unaligned == ["z"] or lonely.unaligned == ["a"]


def test_chained_transforms_match_the_hoards_truth(study) -> None:
    truth = read_truth(study / "hoard")
    paths = scan_paths(study / "project")
    checked = 0
    for dies in project_alignments(study / "project").values():
        for alignment in dies:
            assert not alignment.unaligned
            for face, T in alignment.T_reference_face.items():
                xyz = read_scan(paths[face]).points
                points = np.c_[xyz, np.ones(len(xyz))]
                expected = true_transform(truth, face, alignment.reference)
                error = np.linalg.norm(points @ T.T - points @ expected.T, axis=1)
                assert error.max() < 0.2, (face, alignment.reference, error.max())
                checked += face != alignment.reference
    assert checked >= 6


@pytest.fixture(scope="module")
def report(study) -> Path:
    """The report, built once, after an expert verified one obverse die."""
    first_die = next(iter(project_dies(study / "project")["D"].members().values()))
    open_project(study / "project").add_edit("expert", "verify", a=first_die[0])
    return build_report(study / "project", study / "report.html", metadata=study / "coins.csv")


def test_report_has_one_plate_per_die_with_embedded_images(study, report) -> None:
    dies = project_dies(study / "project")
    out = report
    html = out.read_text()
    plates = re.findall(r'<section class="plate[^"]*" data-side="(\w)" data-die="([^"]+)"', html)
    expected = {(side, die) for side, d in dies.items() for die in d.members()}
    assert sorted(plates) == sorted(expected) and len(plates) == len(expected)
    n_faces = sum(len(d.dies) for d in dies.values())
    assert html.count('src="data:image/jpeg;base64,') == n_faces
    assert 'src="http' not in html and "file://" not in html  # self-contained
    assert html.count('class="verified"') == 1
    weights = {"L0001": 3.10, "L0002": 3.30, "L0003": 2.90}  # coins.csv
    members = next(m for m in dies["D"].members().values() if "L0001D" in m)
    known = [weights[f[:-1]] for f in members if f[:-1] in weights]
    assert f"mean weight {sum(known) / len(known):.3g} (n = {len(known)})" in html
    assert "Chao1 (bias-corrected)" in html and "Carter (1983)" in html
    assert "data:image/svg+xml;base64," in html  # the die-link diagram and the curves


@pytest.mark.skipif(chromium_binary() is None, reason=NO_CHROMIUM)
def test_report_renders_in_headless_chromium(report, tmp_path) -> None:
    html = report
    pdf = print_pdf(html, tmp_path / "report.pdf")
    head = pdf.read_bytes()[:5]
    assert head == b"%PDF-" and pdf.stat().st_size > 50_000  # the plates' images are in it
    shot = screenshot(html, tmp_path / "report.png", 1000, 1200)
    from PIL import Image

    with Image.open(shot) as image:
        assert image.size == (1000, 1200)
        pixels = np.asarray(image.convert("RGB").resize((100, 120))).reshape(-1, 3)
    colours = len(np.unique(pixels, axis=0))
    assert colours > 50  # a page with text, tables and images, not a blank


@pytest.mark.slow
def test_cli_report_and_export_dies(study, tmp_path) -> None:
    runner = CliRunner()
    args = ["report", str(study / "project"), "-o", str(tmp_path / "r.html"), "--width-px", "64"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    assert (tmp_path / "r.html").stat().st_size > 10_000
    result = runner.invoke(app, ["export", "dies", str(study / "project"), str(tmp_path / "dies")])
    assert result.exit_code == 0, result.output
    files = sorted((tmp_path / "dies").rglob("*.ply"))
    assert len(files) == len(list((study / "hoard").glob("*.ply")))
    assert not [f for f in files if "unaligned" in f.name]
    for dies in project_alignments(study / "project").values():
        for alignment in dies:
            folder = tmp_path / "dies" / f"{alignment.side}_{alignment.die}"
            reference = read_scan(folder / f"{alignment.reference}.ply").points
            tree = cKDTree(reference)
            for face in alignment.faces:
                if face == alignment.reference:
                    continue
                distance, _ = tree.query(read_scan(folder / f"{face}.ply").points)
                assert np.median(distance) < 0.1, (face, np.median(distance))  # on the reference's relief
    estimate = runner.invoke(app, ["estimate", str(study / "project"), "--json"])
    assert estimate.exit_code == 0, estimate.output
    sides = json.loads(estimate.output)
    assert sides["obverse"]["n"] == 8 and sides["reverse"]["n"] == 8  # every face of the tiny hoard
    assert sides["obverse"]["d"] == len(project_dies(study / "project")["D"].members())
    auto = runner.invoke(app, ["estimate", str(study / "project"), "--auto", "--json"])
    assert auto.exit_code == 0 and json.loads(auto.output)["reverse"]["n"] == 8
    both = runner.invoke(app, ["estimate", str(study / "project"), "--auto", "--threshold", "0.5"])
    assert both.exit_code == 2 and "not both" in both.output
    init_project(tmp_path / "unrun", study / "hoard")
    unrun = runner.invoke(app, ["estimate", str(tmp_path / "unrun")])
    assert unrun.exit_code == 2 and "coindie run" in unrun.output
    bad = runner.invoke(app, ["report", str(tmp_path)])
    assert bad.exit_code == 2 and "not a coindie project" in bad.output
