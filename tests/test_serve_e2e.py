"""The review app end to end in a real headless Chromium (Debian's, driven by Playwright for Python)."""

from __future__ import annotations

import csv
import json
import shutil
import urllib.parse
import urllib.request
from pathlib import Path

import networkx as nx
import numpy as np
import pytest
from PIL import Image

from real_data import RIEDONES3D

CHROMIUM = Path("/usr/bin/chromium")
pytestmark = [
    pytest.mark.skipif(
        not CHROMIUM.is_file(), reason="no /usr/bin/chromium (make test installs Debian's chromium)"
    ),
    pytest.mark.slow,
]
#: Software WebGL for sigma.js and three.js in a headless browser without a GPU.
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--ignore-gpu-blocklist",
]


@pytest.fixture
def browser():
    """A fresh browser per test: pages left open (polling, a 3D view) would slow the next test down."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        yield browser
        browser.close()


def api(url: str, path: str) -> dict:
    """GET a JSON route of the server at ``url`` (the printed URL, token included)."""
    parts = urllib.parse.urlsplit(url)
    token = urllib.parse.parse_qs(parts.query)["token"][0]
    request = urllib.request.Request(
        f"{parts.scheme}://{parts.netloc}{path}", headers={"X-Coindie-Token": token}
    )
    with urllib.request.urlopen(request, timeout=60) as response:
        return json.loads(response.read())


def open_page(browser, url: str, context=None):  # noqa: ANN001, ANN201
    if context is None:
        page = browser.new_page(viewport={"width": 1400, "height": 900}, accept_downloads=True)
    else:
        page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(url)
    page.wait_for_function("window.coindie && window.coindie.ready", timeout=60000)
    page.errors = errors
    return page


def set_threshold(page, value: float) -> None:  # noqa: ANN001
    page.evaluate(
        "v => { const s = document.getElementById('threshold'); s.value = v; "
        "s.dispatchEvent(new Event('input')); }",
        value,
    )


def counts(page) -> tuple[int, int]:  # noqa: ANN001
    text = page.text_content("#counts")
    clusters, singletons = text.split(" clusters, ")
    return int(clusters), int(singletons.split()[0])


def wait_saved(page, before: int) -> None:  # noqa: ANN001
    page.wait_for_function(f"window.coindie.seq > {before}", timeout=30000)


def image_spread(page, selector: str) -> float:  # noqa: ANN001
    """Standard deviation of the opaque pixels of a loaded <img> (0: blank). The server renders each image
    from the scans (a neighbour list asks for 24 thumbnails first): on a 2-core machine running other
    tests beside it, a minute was seen to pass before the pair's images came."""
    page.wait_for_function(
        f"document.querySelector('{selector}').complete && "
        f"document.querySelector('{selector}').naturalWidth > 0",
        timeout=180000,
    )
    return page.evaluate(
        """sel => { const img = document.querySelector(sel); const c = document.createElement('canvas');
        c.width = img.naturalWidth; c.height = img.naturalHeight; const g = c.getContext('2d');
        g.drawImage(img, 0, 0); const d = g.getImageData(0, 0, c.width, c.height).data;
        let n = 0, s = 0, s2 = 0; for (let k = 0; k < d.length; k += 4) { if (d[k + 3] === 0) continue;
        const v = (d[k] + d[k + 1] + d[k + 2]) / 3; n++; s += v; s2 += v * v; }
        return n < 100 ? 0 : Math.sqrt(s2 / n - (s / n) ** 2); }""",
        selector,
    )


@pytest.fixture
def server(fresh_project):
    from serve_support import served

    with served(fresh_project, "--threshold", "0.5") as url:
        yield url, fresh_project


def test_e2e_slider_changes_cluster_count_as_the_server_says(browser, server):
    url, _ = server
    page = open_page(browser, url)
    for tau in (0.5, 0.99, 0.0, 0.8):
        set_threshold(page, tau)
        expected = api(url, f"/api/clusters?threshold={tau}")
        assert counts(page) == (expected["n_clusters"], expected["n_singletons"]), tau
    low, high = api(url, "/api/clusters?threshold=0.0"), api(url, "/api/clusters?threshold=0.99")
    assert low["n_clusters"] < high["n_clusters"]  # the slider does change the clusters
    assert not page.errors


def test_e2e_project_opens_on_cluster_auto_and_its_slider_agrees_with_the_server(browser, fresh_project):
    from serve_support import served

    with served(fresh_project) as url:  # no --threshold: each side as coindie cluster --auto cuts it
        page = open_page(browser, url)
        state = api(url, "/api/state")
        assert state["method"] == "consensus" and state["links"]
        assert page.evaluate("window.coindie.tau") == state["threshold"]
        for t in (state["threshold"], 0.9, 0.1):
            set_threshold(page, t)
            expected = api(url, f"/api/clusters?threshold={t}")
            assert counts(page) == (expected["n_clusters"], expected["n_singletons"]), t
        assert not page.errors


def test_e2e_search_padding_and_pair_view_images(browser, server):
    url, _ = server
    page = open_page(browser, url)
    face = api(url, "/api/state")["nodes"][3]["id"]
    unpadded = "L" + str(int(face[1:-1])) + face[-1]  # L0004D -> L4D
    page.fill("#search", unpadded)
    page.press("#search", "Enter")
    page.wait_for_function(f"document.getElementById('face-id')?.textContent === '{face}'", timeout=30000)
    assert image_spread(page, "#panel img.thumb") > 5
    page.click("#neighbours tr.neighbour >> nth=0")
    page.wait_for_selector("#pair:not([hidden])")
    for kind in ("target", "source", "difference", "heat"):
        assert image_spread(page, f"#img-{kind}") > 1, kind
    page.wait_for_selector("#three canvas", timeout=60000)
    title = page.text_content("#pair-title")
    page.keyboard.press("ArrowRight")  # next candidate
    page.wait_for_function(f"document.getElementById('pair-title').textContent !== '{title}'", timeout=30000)
    assert not page.errors


def test_e2e_cut_create_link_and_undo(browser, server):
    url, _ = server
    page = open_page(browser, url)
    state = api(url, "/api/state")
    s, t, _, _ = max(state["edges"], key=lambda e: e[2])
    a, b = state["nodes"][s]["id"], state["nodes"][t]["id"]
    page.fill("#link-a", a)
    page.fill("#link-b", b)
    page.click("#link-cut")
    wait_saved(page, 0)
    page.click("#link-create")
    wait_saved(page, 1)
    edits = api(url, "/api/edits?since=0")["edits"]
    assert [(e["action"], e["a"], e["b"]) for e in edits] == [
        ("cut", *sorted((a, b))),
        ("link", *sorted((a, b))),
    ]
    states = {
        tuple(sorted((state["nodes"][e[0]]["id"], state["nodes"][e[1]]["id"]))): e[3]
        for e in api(url, "/api/state")["edges"]
    }
    assert states[tuple(sorted((a, b)))] == "forced"
    page.click("#undo")
    wait_saved(page, 2)
    now = api(url, "/api/state")
    states = {tuple(sorted((now["nodes"][e[0]]["id"], now["nodes"][e[1]]["id"]))): e[3] for e in now["edges"]}
    assert states[tuple(sorted((a, b)))] == "cut" and now["redo_target"] == 2
    page.click("#redo")
    wait_saved(page, 3)
    assert api(url, "/api/edits?since=3")["edits"][0]["action"] == "redo"
    assert not page.errors


def test_e2e_fix_registration_by_picked_points(browser, server):
    from coindie.serve import open_source
    from serve_support import corresponding_pixels

    url, project = server
    source = open_source(project, threshold=0.5)
    a, b, _ = max(source.graph.edges(), key=lambda e: e[2])
    target_pixels, source_pixels = corresponding_pixels(source, a, b)
    page = open_page(browser, url)
    page.fill("#search", a)
    page.press("#search", "Enter")
    page.wait_for_function(f"document.getElementById('face-id')?.textContent === '{a}'", timeout=30000)
    page.click(f"#neighbours tr.neighbour[data-face='{b}']")
    page.wait_for_selector("#pair:not([hidden])")
    page.click("#pair-fix")
    for role in ("target", "source"):
        page.wait_for_function(f"document.querySelector('#pick-{role} img').naturalWidth > 0", timeout=180000)
    for (tc, tr), (sc, sr) in zip(target_pixels, source_pixels, strict=True):
        for role, col, row in (("target", tc, tr), ("source", sc, sr)):
            size = page.evaluate(
                f"(() => {{ const i = document.querySelector('#pick-{role} img'); "
                f"return [i.naturalWidth, i.clientWidth]; }})()"
            )
            scale = size[1] / size[0]
            page.click(f"#pick-{role} img", position={"x": col * scale, "y": row * scale})
    page.fill("#fix-reason", "RANSAC flipped the face")
    page.click("#fix-run")
    wait_saved(page, 0)
    info = api(url, f"/api/pairs/{a}/{b}")
    assert info["origin"] == "expert" and info["reason"] == "RANSAC flipped the face"
    assert info["probability"] > 0.5
    page.wait_for_function(
        "document.getElementById('pair-info').textContent.includes('expert')", timeout=30000
    )
    assert not page.errors


def test_e2e_exports_each_file(browser, server, tmp_path):
    url, _ = server
    page = open_page(browser, url)
    n = len(api(url, "/api/state")["nodes"])
    page.click("#exports summary")
    files = {}
    for selector, name in [
        ("[data-export='clusters.csv']", "clusters.csv"),
        ("[data-export='clusters_paper.csv']", "paper.csv"),
        ("[data-export='graph.json']", "graph.json"),
        ("[data-export='graph.graphml']", "g.graphml"),
        ("[data-export='graph.gexf']", "g.gexf"),
        ("#export-png", "view.png"),
        ("#export-svg", "view.svg"),
    ]:
        page.evaluate("document.getElementById('exports').open = true")
        with page.expect_download() as download:
            page.click(selector)
        files[name] = tmp_path / name
        download.value.save_as(files[name])
    assert len(list(csv.DictReader(files["clusters.csv"].open()))) == n
    assert files["paper.csv"].read_text().splitlines()[0] == "name, die"
    assert len(json.loads(files["graph.json"].read_text())["nodes"]) == n
    assert nx.read_graphml(files["g.graphml"]).number_of_nodes() == n
    assert nx.read_gexf(files["g.gexf"]).number_of_nodes() == n
    png = np.asarray(Image.open(files["view.png"]).convert("RGB"), dtype=np.float64)
    assert png.std() > 1  # nodes and links drawn, not a blank canvas
    svg = files["view.svg"].read_text()
    assert svg.startswith("<svg") and svg.count("<circle") == n


def test_e2e_edits_survive_a_restart(browser, fresh_project):
    from serve_support import served

    with served(fresh_project, "--threshold", "0.5") as url:
        page = open_page(browser, url)
        state = api(url, "/api/state")
        s, t, _, _ = state["edges"][0]
        page.fill("#link-a", state["nodes"][s]["id"])
        page.fill("#link-b", state["nodes"][t]["id"])
        page.click("#link-cut")
        wait_saved(page, 0)
        before = api(url, "/api/clusters?threshold=0.5")
        page.close()
    with served(fresh_project, "--threshold", "0.5") as url:
        page = open_page(browser, url)
        assert page.evaluate("window.coindie.seq") == 1
        assert api(url, "/api/edits")["edits"][0]["action"] == "cut"
        assert api(url, "/api/clusters?threshold=0.5")["clusters"] == before["clusters"]


def test_e2e_conflicting_edits_from_two_pages(browser, server):
    url, _ = server
    context = browser.new_context(viewport={"width": 1400, "height": 900})
    one, two = open_page(browser, url, context), open_page(browser, url, context)
    state = api(url, "/api/state")
    s, t, _, _ = state["edges"][0]
    a, b = state["nodes"][s]["id"], state["nodes"][t]["id"]
    two.evaluate("window.coindie.pollPaused = true")  # tab two has not seen tab one's edit yet
    for page in (one, two):
        page.fill("#link-a", a)
        page.fill("#link-b", b)
    one.click("#link-cut")
    wait_saved(one, 0)
    two.click("#link-create")
    two.wait_for_function("document.getElementById('toast').textContent.includes('refused')", timeout=30000)
    assert [e["action"] for e in api(url, "/api/edits")["edits"]] == ["cut"]  # one refused, none lost
    wait_saved(two, 0)  # the refusal reloaded tab two's state
    two.click("#link-create")  # made again, knowingly
    wait_saved(two, 1)
    assert [e["action"] for e in api(url, "/api/edits")["edits"]] == ["cut", "link"]
    one.wait_for_function("window.coindie.seq === 2", timeout=30000)  # tab one sees it by polling
    context.close()


@pytest.mark.skipif(not (RIEDONES3D / "beard_probability_graph.json").is_file(), reason="no Riedones3D data")
def test_e2e_real_beard_graph(browser, tmp_path):
    from serve_support import served

    graph = tmp_path / "beard.json"
    shutil.copy(RIEDONES3D / "beard_probability_graph.json", graph)
    with served(graph) as url:
        page = open_page(browser, url)
        expected = api(url, "/api/clusters?threshold=0.95")
        assert counts(page) == (expected["n_clusters"], expected["n_singletons"])
        page.fill("#search", "L7D")
        page.press("#search", "Enter")
        page.wait_for_function("document.getElementById('face-id')?.textContent === 'L0007D'", timeout=30000)
        assert page.locator("#neighbours tr.neighbour").count() == 24  # 80 partners, the 24 best listed
        assert not page.errors
