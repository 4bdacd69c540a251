"""The die-link network on small networks whose chains and order are known, its exports, and the
experts' real labels (887 obverses in 74 dies, 1,102 reverses in 213 dies, 881 coins, 326 combinations)."""

from __future__ import annotations

import csv
import random

import networkx as nx
import pytest

from coindie.numismatics.die_links import build_die_links, draw_die_links, link_spread, write_exports
from coindie.numismatics.metadata import read_metadata
from coindie.numismatics.sources import load_side
from real_data import RIEDONES3D


def _small():
    obverse = {"L001D": "A", "L002D": "A", "L003D": "B", "L0004D": "B", "L005D": "C", "L006D": "D"}
    reverse = {"L0001R": "x", "L002R": "y", "L003R": "y", "L004R": "z", "L005R": "w", "L007R": "v"}
    return build_die_links(obverse, reverse)


def test_small_network_chains_weights_and_order() -> None:
    links = _small()
    g = links.graph
    assert set(links.coins) == {"L0001", "L0002", "L0003", "L0004", "L0005"}
    assert links.obverse_only == ["L0006"] and links.reverse_only == ["L0007"]
    assert g["O:A"]["R:y"]["weight"] == 1 and g.nodes["O:A"]["coins"] == 2
    linked = [c for c in links.chains if c.n_links]
    assert [set(c.order) for c in linked] == [{"O:A", "O:B", "R:x", "R:y", "R:z"}, {"O:C", "R:w"}]
    assert linked[0].n_coins == 4 and linked[1].n_coins == 1
    order = linked[
        0
    ].order  # the chain is the path x - A - y - B - z: seriation gives it, one way or the other
    assert order in (["R:x", "O:A", "R:y", "O:B", "R:z"], ["R:z", "O:B", "R:y", "O:A", "R:x"])
    unlinked = {c.order[0] for c in links.chains if not c.n_links}
    assert unlinked == {"O:D", "R:v"}
    s = links.summary()
    assert (s["obverse_dies"], s["reverse_dies"], s["combinations"], s["chains"]) == (4, 5, 5, 2)


def test_seriation_recovers_a_shuffled_sequence_of_dies() -> None:
    # obverse i struck with reverses i and i+1 (a die replaced one at a time): names shuffled.
    rng = random.Random(3)
    names = [f"o{v}" for v in rng.sample(range(100), 8)]
    rnames = [f"r{v}" for v in rng.sample(range(100), 9)]
    obverse, reverse, coin = {}, {}, 1
    for i, o in enumerate(names):
        for r, k in ((rnames[i], 3), (rnames[i + 1], 2)):
            for _ in range(k):
                obverse[f"L{coin}D"], reverse[f"L{coin}R"] = o, r
                coin += 1
    links = build_die_links(obverse, reverse)
    (chain,) = links.chains
    expected = [f"O:{o}" for o in names]
    assert chain.obverses in (expected, expected[::-1])
    expected_r = [f"R:{r}" for r in rnames]
    assert chain.reverses in (expected_r, expected_r[::-1])
    # obverse i sits between reverses i and i+1: every link is one or two positions long
    assert 1 <= link_spread(links.graph, chain.order) <= 2
    assert link_spread(links.graph, sorted(chain.order)) > link_spread(links.graph, chain.order)


def test_exports_read_back(tmp_path) -> None:
    links = _small()
    paths = write_exports(links, tmp_path)
    for reader in (nx.read_graphml, nx.read_gexf):
        back = reader(paths["graphml" if reader is nx.read_graphml else "gexf"])
        assert back.number_of_edges() == 5 and back.number_of_nodes() == 9
        assert int(back["O:A"]["R:x"]["weight"]) == 1
    rows = list(csv.DictReader(paths["links_csv"].open()))
    assert len(rows) == 5 and {r["coin_ids"] for r in rows} >= {"L0001", "L0005"}
    dies = list(csv.DictReader(paths["dies_csv"].open()))
    assert len(dies) == 9
    for suffix in ("svg", "png"):
        path = draw_die_links(links, tmp_path / f"links.{suffix}")
        assert path.stat().st_size > 1000


def test_metadata_summary_per_die(tmp_path) -> None:
    path = tmp_path / "coins.csv"
    path.write_text('coin_id,weight,findspot\nL1,3.1,Rennes\nL0002D,"3,3",Rennes\nL3,2.9,Paris\n')
    meta = read_metadata(path)
    assert meta.numeric == {"weight"}
    summary = meta.summary(["L0001D", "L0002D"])
    assert summary["weight"]["mean"] == pytest.approx(3.2) and summary["findspot"] == {"Rennes": 2}
    assert meta.for_coin("L003R")["findspot"] == "Paris"


@pytest.mark.skipif(not RIEDONES3D.is_dir(), reason=f"real Riedones3D labels not found at {RIEDONES3D}")
def test_the_experts_labels_give_the_published_counts() -> None:
    obverse = load_side(RIEDONES3D / "experts_obverse_dies.csv", "D")
    reverse = load_side(RIEDONES3D / "experts_reverse_dies.csv", "R")
    assert (len(obverse.dies), len(set(obverse.dies.values()))) == (887, 74)
    assert (len(reverse.dies), len(set(reverse.dies.values()))) == (1102, 213)
    links = build_die_links(obverse, reverse)
    assert len(links.coins) == 881 and links.n_links == 326
    assert sum(w for _, _, w in links.graph.edges(data="weight")) == 881


@pytest.mark.skipif(not RIEDONES3D.is_dir(), reason=f"real Riedones3D labels not found at {RIEDONES3D}")
def test_the_worked_example_is_one_command(tmp_path) -> None:
    import importlib.util
    from pathlib import Path

    script = Path(__file__).resolve().parents[1] / "benchmarks" / "numismatics_riedones.py"
    spec = importlib.util.spec_from_file_location("numismatics_riedones", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    docs = tmp_path / "docs"
    docs.mkdir()
    (docs / "numismatics.md").write_text(f"# kept\n\n{module.BEGIN}\nold\n{module.END}\n\nreading kept\n")
    assert module.main(["--data", str(RIEDONES3D), "--out", str(tmp_path / "out"), "--docs", str(docs)]) == 0
    text = (docs / "numismatics.md").read_text()
    assert text.startswith("# kept") and text.endswith("reading kept\n") and "\nold\n" not in text
    assert "| faces labelled (n) | 887 | 1102 |" in text and "| dies (d) | 74 | 213 |" in text
    assert "in 326 distinct combinations" in text and "Seriation of chain 1" in text
    for name in ("die_links", "accumulation_obverse", "accumulation_reverse"):
        assert (docs / "images" / f"numismatics_riedones_{name}.png").stat().st_size > 10_000
    assert (tmp_path / "out" / "die_links.gexf").is_file()
