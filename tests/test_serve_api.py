"""The review app's HTTP API: the guard (token, Host), clear errors, images, edits, exports, bare graphs."""

from __future__ import annotations

import csv
import io
import json
import math
import shutil

import networkx as nx
import numpy as np
import pytest
from fastapi.testclient import TestClient
from PIL import Image

from coindie.clustering import read_graph
from coindie.serve import create_app, open_source
from coindie.similarity.histogram import HistogramSettings
from real_data import RIEDONES3D

TOKEN = "t0ken-for-tests"
HEADERS = {"X-Coindie-Token": TOKEN}


@pytest.fixture
def served(fresh_project):
    source = open_source(fresh_project, threshold=0.5)
    return source, TestClient(create_app(source, TOKEN), base_url="http://127.0.0.1:8765")


def _pair(source) -> tuple[str, str]:
    """The most probable scored pair."""
    a, b, _ = max(source.graph.edges(), key=lambda e: e[2])
    return a, b


def _not_blank(png: bytes) -> float:
    image = np.asarray(Image.open(io.BytesIO(png)).convert("RGBA"), dtype=np.float64)
    opaque = image[..., 3] > 0
    assert opaque.mean() > 0.2, "the image is mostly transparent"
    return float(image[..., :3][opaque].std())


# --------------------------------------------------------------------------------------------- guard


def test_serve_refuses_missing_and_wrong_token_and_foreign_host(served):
    _, client = served
    missing = client.get("/api/state")
    assert missing.status_code == 403 and "no access token" in missing.json()["error"]
    wrong = client.get("/api/state", headers={"X-Coindie-Token": "guess"})
    assert wrong.status_code == 403 and "wrong access token" in wrong.json()["error"]
    wrong_query = client.get("/api/state?token=guess")
    assert wrong_query.status_code == 403
    foreign = client.get("/api/state", headers={**HEADERS, "Host": "evil.example:8765"})
    assert foreign.status_code == 400 and "evil.example" in foreign.json()["error"]
    assert client.get("/", headers={"Host": "evil.example"}).status_code == 400
    assert client.get("/api/state", headers={**HEADERS, "Host": "127.0.0.1.evil.example"}).status_code == 400
    for own in ("localhost:8765", "127.0.0.1", "[::1]:8765"):
        assert client.get("/api/state", headers={**HEADERS, "Host": own}).status_code == 200, own


def test_serve_token_in_url_sets_a_cookie_for_images(served):
    _, client = served
    page = client.get(f"/?token={TOKEN}")
    assert page.status_code == 200 and "<title>coindie review</title>" in page.text
    assert client.get("/api/state").status_code == 200  # the cookie now carries the token


# ---------------------------------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    "route", ["/api/clusters", "/api/queue", "/api/export/clusters.csv", "/api/faces/{a}"]
)
@pytest.mark.parametrize("value", ["2", "-0.1", "nan", "abc", "inf"])
def test_serve_bad_threshold_is_refused(served, route, value):
    source, client = served
    response = client.get(route.format(a=source.graph.nodes[0]), params={"threshold": value}, headers=HEADERS)
    assert response.status_code == 400
    assert "threshold must be a number in [0, 1]" in response.json()["error"]


def test_serve_bad_ids_are_404_with_the_id(served):
    source, client = served
    a = source.graph.nodes[0]
    for route in [
        "/api/faces/L9999D",
        "/api/faces/L9999D/thumbnail.png",
        f"/api/pairs/{a}/NOPE",
        f"/api/pairs/NOPE/{a}/heat.png",
        "/api/faces/L9999D/relief.json",
    ]:
        response = client.get(route, headers=HEADERS)
        assert response.status_code == 404, route
        assert "no face" in response.json()["error"], route
    unscored = next(
        (a, b) for a in source.graph.nodes for b in source.graph.nodes if a < b and a[-1] != b[-1]
    )  # an obverse and a reverse: never scored
    response = client.get(f"/api/pairs/{unscored[0]}/{unscored[1]}", headers=HEADERS)
    assert response.status_code == 404 and "not scored" in response.json()["error"]
    a, b = _pair(source)
    assert client.get(f"/api/pairs/{a}/{b}/nope.png", headers=HEADERS).status_code == 404
    assert client.get("/api/export/secrets.txt", headers=HEADERS).status_code == 404
    assert client.get("/api/edits?since=x", headers=HEADERS).status_code == 400


TRAVERSALS = [
    "..%2F..%2Fapp.py",
    "%2e%2e/%2e%2e/app.py",
    "..%2F..%2F..%2F..%2Fetc%2Fpasswd",
    "%2Fetc%2Fpasswd",
    "....//....//app.py",
    "..%5C..%5Capp.py",
]


@pytest.mark.parametrize("attack", TRAVERSALS)
def test_serve_path_traversal_is_refused_on_every_file_route(served, attack):
    source, client = served
    a, b = _pair(source)
    routes = [
        f"/static/{attack}",
        f"/api/faces/{attack}/thumbnail.png",
        f"/api/faces/{attack}/relief.png",
        f"/api/faces/{attack}/relief.json",
        f"/api/pairs/{a}/{attack}/heat.png",
        f"/api/pairs/{attack}/{b}/target.png",
        f"/api/pairs/{a}/{b}/{attack}.png",
        f"/api/pairs/{a}/{attack}/clouds.json",
        f"/api/export/{attack}",
    ]
    for route in routes:
        response = client.get(route, headers=HEADERS)
        assert response.status_code in (404, 400), (route, response.status_code)
        assert "root:" not in response.text and "import" not in response.text
        assert response.headers["content-type"].startswith("application/json"), route
        assert response.json()["error"]


# ------------------------------------------------------------------------------------------ content


def test_serve_state_counts_match_the_clustering(served):
    source, client = served
    state = client.get("/api/state", headers=HEADERS).json()
    assert len(state["nodes"]) == source.graph.n_nodes and len(state["edges"]) == source.graph.n_edges
    clusters = client.get("/api/clusters", params={"threshold": 0.5}, headers=HEADERS).json()
    sizes = sorted(len(c["members"]) for c in clusters["clusters"])
    assert sum(sizes) == source.graph.n_nodes and clusters["n_singletons"] == sizes.count(1)
    labels = source.labels
    # The demo hoard clusters well: faces of one cluster share a die for the most part.
    pure = sum(len({labels[f] for f in c["members"]}) == 1 for c in clusters["clusters"])
    assert pure >= 0.8 * len(clusters["clusters"])


def test_serve_images_are_pngs_with_content(served):
    source, client = served
    a, b = _pair(source)
    assert _not_blank(client.get(f"/api/faces/{a}/thumbnail.png", headers=HEADERS).content) > 5
    for kind in ("target", "source", "difference", "heat"):
        response = client.get(f"/api/pairs/{a}/{b}/{kind}.png", headers=HEADERS)
        assert response.status_code == 200 and response.headers["content-type"] == "image/png"
        assert _not_blank(response.content) > 1, kind
    clouds = client.get(f"/api/pairs/{a}/{b}/clouds.json", headers=HEADERS).json()
    target, moved = np.reshape(clouds["target"], (-1, 3)), np.reshape(clouds["source"], (-1, 3))
    # A same-die pair, registered: where the flans overlap, the source lies on the target (the median
    # nearest distance is a fraction of a millimetre; flans differ, so centroids need not match).
    from scipy.spatial import cKDTree

    distances, _ = cKDTree(target).query(moved)
    assert np.median(distances) < 0.2


def test_serve_edit_conflict_is_409_and_nothing_lost(served):
    source, client = served
    a, b = _pair(source)
    first = client.post(
        "/api/edits", json={"action": "cut", "a": a, "b": b, "base_seq": 0, "client": "one"}, headers=HEADERS
    )
    assert first.status_code == 200 and first.json()["seq"] == 1
    second = client.post(
        "/api/edits", json={"action": "link", "a": a, "b": b, "base_seq": 0, "client": "two"}, headers=HEADERS
    )
    assert second.status_code == 409 and "refused" in second.json()["error"]
    edits = client.get("/api/edits?since=0", headers=HEADERS).json()
    assert [e["action"] for e in edits["edits"]] == ["cut"] and edits["seq"] == 1
    bad = client.post("/api/edits", json={"action": "explode", "base_seq": 1}, headers=HEADERS)
    assert bad.status_code == 400 and "unknown edit action" in bad.json()["error"]
    stale = client.post("/api/edits", json={"action": "cut", "a": a, "b": b, "base_seq": 9}, headers=HEADERS)
    assert stale.status_code == 400


def test_serve_exports_parse_and_agree(served, tmp_path):
    source, client = served
    a, b = _pair(source)
    client.post("/api/edits", json={"action": "cut", "a": a, "b": b, "base_seq": 0}, headers=HEADERS)
    n = source.graph.n_nodes
    ours = list(
        csv.DictReader(
            io.StringIO(client.get("/api/export/clusters.csv?threshold=0.5", headers=HEADERS).text)
        )
    )
    assert len(ours) == n and set(ours[0]) == {"face_id", "cluster", "size", "verified"}
    paper = client.get("/api/export/clusters_paper.csv?threshold=0.5", headers=HEADERS).text
    assert paper.splitlines()[0] == "name, die" and len(paper.splitlines()) == n + 1
    document = client.get("/api/export/graph.json", headers=HEADERS).json()
    assert "links" in document and len(document["nodes"]) == n
    (tmp_path / "g.json").write_text(json.dumps(document))
    back = read_graph(tmp_path / "g.json")
    assert set(back.nodes) == set(source.graph.nodes)
    assert back.n_edges == source.graph.n_edges - 1  # the cut link is not exported
    for name, reader in (("graph.graphml", nx.read_graphml), ("graph.gexf", nx.read_gexf)):
        (tmp_path / name).write_text(client.get(f"/api/export/{name}", headers=HEADERS).text)
        g = reader(tmp_path / name)
        assert g.number_of_nodes() == n and not g.has_edge(a, b), name


def test_serve_manual_registration_by_points_recovers_the_transform(served):
    from serve_support import corresponding_pixels

    source, client = served
    a, b = _pair(source)
    automatic = source.pair_record(a, b)
    target_pixels, source_pixels = corresponding_pixels(source, a, b)
    response = client.post(
        f"/api/pairs/{a}/{b}/register",
        headers=HEADERS,
        json={
            "target_pixels": target_pixels,
            "source_pixels": source_pixels,
            "reason": "test",
            "base_seq": 0,
        },
    )
    assert response.status_code == 200, response.text
    info = client.get(f"/api/pairs/{a}/{b}", headers=HEADERS).json()
    assert info["origin"] == "expert" and info["reason"] == "test"
    T, T_auto = np.asarray(info["T_target_source"]), automatic.T_target_source
    rotation = np.linalg.inv(T_auto[:3, :3]) @ T[:3, :3]
    angle = math.degrees(math.acos(np.clip((np.trace(rotation) - 1) / 2, -1, 1)))
    corners = np.array([[-8.0, -8.0, 0.0], [8.0, -8.0, 0.0], [0.0, 8.0, 0.0]]) + T_auto[:3, 3]
    moved = corners @ T[:3, :3].T + T[:3, 3] - (corners @ T_auto[:3, :3].T + T_auto[:3, 3])
    assert angle < 1.0 and np.abs(moved).max() < 0.2  # the automatic registration, found again
    assert info["probability"] > 0.5  # the same die, re-scored
    edits = client.get("/api/edits", headers=HEADERS).json()["edits"]
    assert edits[-1]["action"] == "register" and edits[-1]["payload"]["origin"] == "expert"
    too_few = client.post(
        f"/api/pairs/{a}/{b}/register",
        headers=HEADERS,
        json={"target_pixels": target_pixels[:2], "source_pixels": source_pixels[:2], "base_seq": 1},
    )
    assert too_few.status_code == 400 and ">= 3" in too_few.json()["error"]


@pytest.mark.skipif(not (RIEDONES3D / "beard_probability_graph.json").is_file(), reason="no Riedones3D data")
def test_serve_bare_beard_graph_loads_without_images(tmp_path):
    graph_path = tmp_path / "graph.json"
    shutil.copy(RIEDONES3D / "beard_probability_graph.json", graph_path)
    source = open_source(graph_path)
    client = TestClient(create_app(source, TOKEN), base_url="http://127.0.0.1:8765")
    state = client.get("/api/state", headers=HEADERS).json()
    assert len(state["nodes"]) == 81 and len(state["edges"]) == 3240 and not state["has_images"]
    response = client.get("/api/faces/L1D/thumbnail.png", headers=HEADERS)  # padding-tolerant id
    assert response.status_code == 404 and "no scan" in response.json()["error"]
    assert client.get("/api/faces/L1D", headers=HEADERS).json()["face"] == "L0001D"
    client.post("/api/edits", json={"action": "cut", "a": "L1D", "b": "L2D", "base_seq": 0}, headers=HEADERS)
    assert (tmp_path / "graph.json.edits.sqlite").is_file()


def test_serve_measures_the_distance_histogram_of_a_pair_whose_run_did_not(served):
    """coindie run leaves the paper's histogram out for the relief scorer; the pair view measures it from
    the scans at the pair's pose: a density over 0..max distance, most of it near 0 for a registered
    same-die pair."""
    source, client = served
    a, b = _pair(source)
    assert source.pair_record(a, b).histogram is None  # the run did not measure it
    info = client.get(f"/api/pairs/{a}/{b}", headers=HEADERS).json()
    histogram = np.asarray(info["histogram"])
    settings = HistogramSettings()
    assert histogram.shape == (settings.bins,)
    width = info["max_distance_mm"] / settings.bins
    assert histogram.sum() * width == pytest.approx(1.0, abs=1e-6)
    near = int(round(0.1 / width))  # the share of distances under 0.1 mm
    assert histogram[:near].sum() * width > 0.5
