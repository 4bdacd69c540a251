"""The die-link network: which obverse dies struck with which reverse dies, its chains and their order.

A coin's two faces share its number (``L0082D`` and ``L082R`` are coin 82, see :mod:`coindie.ids`). Each
coin with both faces labelled links its obverse die to its reverse die; a link's weight is its number of
coins. The network is bipartite (networkx ``Graph``, nodes ``O:<die>`` and ``R:<die>`` with ``side``
``obverse`` / ``reverse``); a die whose coins have only that face is an isolated node.

**Chains** are the connected components: dies joined, directly or through other dies, by coins.

**Seriation** (the order suggested inside a chain) is spectral: the dies are sorted by their value in the
Fiedler vector (the eigenvector of the second-smallest eigenvalue) of the weighted Laplacian of the
chain's graph (networkx ``fiedler_vector``). The Fiedler vector is the one-dimensional placement that
minimises ``sum w_ij (x_i - x_j)**2`` for unit-norm, zero-mean ``x``: dies that share many coins get close
positions, so a chain that was used in sequence (obverse A with reverses 1, 2; obverse B with 2, 3; ...)
comes out in that sequence (Atkins, Boman and Hendrickson, "A spectral algorithm for seriation and the
consecutive ones problem", *SIAM J. Computing* 28, 1998). The direction of the order is arbitrary (the
eigenvector's sign): it is fixed so that the chain's largest obverse die comes in its first half. The
order is a suggestion of relative sequence, not a chronology: which end came first needs other evidence
(hoards, die wear, style).
"""

from __future__ import annotations

import csv
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import networkx as nx
import numpy as np

from coindie.ids import Face, parse_face_id
from coindie.numismatics.sources import SideDies

OBVERSE, REVERSE = "obverse", "reverse"


def node_name(side: str, die: str) -> str:
    """``O:<die>`` for an obverse die, ``R:<die>`` for a reverse die."""
    return f"{'O' if side == OBVERSE else 'R'}:{die}"


@dataclass(frozen=True)
class Chain:
    """One connected group of dies, in seriation order."""

    index: int
    obverses: list[str]
    reverses: list[str]
    order: list[str]
    n_coins: int
    n_links: int


@dataclass
class DieLinks:
    """The network with its chains, and the coins behind it."""

    graph: nx.Graph
    coins: dict[str, tuple[str, str]]  # coin key -> (obverse die, reverse die), coins with both faces
    obverse_only: list[str] = field(default_factory=list)
    reverse_only: list[str] = field(default_factory=list)
    chains: list[Chain] = field(default_factory=list)

    @property
    def n_links(self) -> int:
        return self.graph.number_of_edges()

    def dies(self, side: str) -> list[str]:
        return [d["die"] for _, d in self.graph.nodes(data=True) if d["side"] == side]

    def summary(self) -> dict[str, object]:
        linked = [c for c in self.chains if c.obverses and c.reverses]
        return {
            "obverse_dies": len(self.dies(OBVERSE)),
            "reverse_dies": len(self.dies(REVERSE)),
            "coins_with_both_faces": len(self.coins),
            "combinations": self.n_links,
            "obverse_only_coins": len(self.obverse_only),
            "reverse_only_coins": len(self.reverse_only),
            "chains": len(linked),
            "largest_chain": _chain_size(linked[0]) if linked else None,
            "unlinked_dies": sum(1 for c in self.chains if not (c.obverses and c.reverses)),
        }


def _chain_size(chain: Chain) -> dict[str, int]:
    return {"obverse_dies": len(chain.obverses), "reverse_dies": len(chain.reverses), "coins": chain.n_coins}


def _as_labels(dies: SideDies | Mapping[str, str]) -> dict[str, str]:
    mapping = dies.dies if isinstance(dies, SideDies) else dies
    return {parse_face_id(face).key: str(die) for face, die in mapping.items()}


def build_die_links(obverse: SideDies | Mapping[str, str], reverse: SideDies | Mapping[str, str]) -> DieLinks:
    """The network from the obverse dies and the reverse dies of the faces (face id -> die)."""
    obv, rev = _as_labels(obverse), _as_labels(reverse)
    by_coin: dict[str, dict[Face, str]] = {}
    for labels, face in ((obv, Face.OBVERSE), (rev, Face.REVERSE)):
        for key, die in labels.items():
            fid = parse_face_id(key)
            by_coin.setdefault(fid.coin_key, {})[face] = die
    graph = nx.Graph()
    for labels, side in ((obv, OBVERSE), (rev, REVERSE)):
        for die in sorted(set(labels.values())):
            graph.add_node(node_name(side, die), side=side, die=die, coins=0, bipartite=int(side == REVERSE))
        for die in labels.values():
            graph.nodes[node_name(side, die)]["coins"] += 1
    coins: dict[str, tuple[str, str]] = {}
    obverse_only, reverse_only = [], []
    for coin, faces in sorted(by_coin.items()):
        if Face.OBVERSE in faces and Face.REVERSE in faces:
            o, r = node_name(OBVERSE, faces[Face.OBVERSE]), node_name(REVERSE, faces[Face.REVERSE])
            coins[coin] = (faces[Face.OBVERSE], faces[Face.REVERSE])
            if graph.has_edge(o, r):
                graph[o][r]["weight"] += 1
                graph[o][r]["coin_ids"] += f";{coin}"
            else:
                graph.add_edge(o, r, weight=1, coin_ids=coin)
        elif Face.OBVERSE in faces:
            obverse_only.append(coin)
        else:
            reverse_only.append(coin)
    links = DieLinks(graph, coins, obverse_only, reverse_only)
    links.chains = find_chains(graph)
    for chain in links.chains:
        for position, node in enumerate(chain.order):
            graph.nodes[node]["chain"] = chain.index
            graph.nodes[node]["position"] = position
    return links


def seriate(graph: nx.Graph) -> list[str]:
    """The nodes of one connected graph in spectral (Fiedler-vector) order, oriented as the module says.

    The graph is first copied with its nodes and links in sorted order, and dies with equal Fiedler values
    are ordered by name, so that the order does not depend on Python's string hashing (networkx's own
    ``spectral_ordering`` iterates a set of nodes, and ties then come out in a different order per run).
    """
    nodes = sorted(graph.nodes)
    if len(nodes) <= 2:
        return sorted(nodes, key=lambda n: (graph.nodes[n]["side"] != OBVERSE, n))
    copy = nx.Graph()
    copy.add_nodes_from(nodes)
    copy.add_weighted_edges_from(sorted((*sorted((a, b)), w) for a, b, w in graph.edges(data="weight")))
    fiedler = nx.fiedler_vector(copy, weight="weight", method="tracemin_lu", seed=0)
    order = [node for _, node in sorted(zip(np.round(fiedler, 9).tolist(), nodes, strict=True))]
    obverses = [n for n in order if graph.nodes[n]["side"] == OBVERSE]
    if obverses:
        largest = max(obverses, key=lambda n: (graph.nodes[n]["coins"], n))
        if order.index(largest) > (len(order) - 1) / 2:
            order.reverse()
    return order


def link_spread(graph: nx.Graph, order: list[str]) -> float:
    """Coin-weighted mean distance, in positions of ``order``, between the two dies of each link: how well
    an order keeps linked dies together (the quantity spectral seriation makes small)."""
    position = {node: i for i, node in enumerate(order)}
    edges = [(a, b, w) for a, b, w in graph.subgraph(order).edges(data="weight")]
    total = sum(w for _, _, w in edges)
    return sum(w * abs(position[a] - position[b]) for a, b, w in edges) / total if total else 0.0


def find_chains(graph: nx.Graph) -> list[Chain]:
    """The connected components, largest first (coins, then dies), each in seriation order."""
    chains = []
    for component in nx.connected_components(graph):
        sub = graph.subgraph(component)
        order = seriate(sub)
        coins = sum(w for _, _, w in sub.edges(data="weight"))
        if not coins:  # an isolated die: its coins have only this face
            coins = sum(sub.nodes[n]["coins"] for n in sub)
        chains.append(
            Chain(
                index=0,
                obverses=[n for n in order if sub.nodes[n]["side"] == OBVERSE],
                reverses=[n for n in order if sub.nodes[n]["side"] == REVERSE],
                order=order,
                n_coins=int(coins),
                n_links=sub.number_of_edges(),
            )
        )
    chains.sort(key=lambda c: (-bool(c.n_links), -c.n_coins, -len(c.order), c.order[0]))
    return [Chain(i + 1, c.obverses, c.reverses, c.order, c.n_coins, c.n_links) for i, c in enumerate(chains)]


# ------------------------------------------------------------------------------------------------ exports


def write_exports(links: DieLinks, out_dir: str | Path, stem: str = "die_links") -> dict[str, Path]:
    """``<stem>.csv`` (one row per link), ``<stem>_dies.csv`` (one per die: side, coins, chain, position),
    ``<stem>.graphml`` and ``<stem>.gexf`` (networkx writers)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths = {
        "links_csv": out / f"{stem}.csv",
        "dies_csv": out / f"{stem}_dies.csv",
        "graphml": out / f"{stem}.graphml",
        "gexf": out / f"{stem}.gexf",
    }
    g = links.graph
    with paths["links_csv"].open("w", newline="") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(["obverse_die", "reverse_die", "coins", "chain", "coin_ids"])
        for chain in links.chains:
            for o in chain.obverses:
                for r in sorted(g[o], key=chain.order.index):
                    e = g[o][r]
                    writer.writerow(
                        [g.nodes[o]["die"], g.nodes[r]["die"], e["weight"], chain.index, e["coin_ids"]]
                    )
    with paths["dies_csv"].open("w", newline="") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(["node", "side", "die", "coins", "chain", "position", "linked_dies"])
        for chain in links.chains:
            for node in chain.order:
                d = g.nodes[node]
                writer.writerow(
                    [node, d["side"], d["die"], d["coins"], chain.index, d["position"], g.degree(node)]
                )
    nx.write_graphml(g, paths["graphml"])
    nx.write_gexf(g, paths["gexf"])
    return paths


# ---------------------------------------------------------------------------------------------- diagram

OBVERSE_COLOUR, REVERSE_COLOUR, LINK_COLOUR = "#8c5a2b", "#2b5f8c", "#555555"


def draw_die_links(
    links: DieLinks, path: str | Path, *, title: str | None = None, max_width_in: float = 60.0
):
    """The diagram: obverse dies on the upper row, reverse dies on the lower, chains side by side (largest
    first) with their dies in seriation order; a link's width grows with its coins, a die's marker with
    its coins. Dies with no link (their coins have one face only) are left out and counted in the title.
    Chains that do not fit beside the largest one wrap onto further bands. The format follows the
    suffix (``.svg``, ``.png``, ``.pdf``); returns the figure's path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    g = links.graph
    linked = [c for c in links.chains if c.n_links]
    widths = [max(len(c.obverses), len(c.reverses)) for c in linked]
    # Chains side by side, wrapped onto bands no wider than the largest chain (at least 40 dies).
    band_width = max([*widths, min(40, sum(widths) + len(widths) - 1)]) if widths else 1
    x: dict[str, float] = {}
    band_of: dict[str, int] = {}
    bounds = []
    band, start = 0, 0.0
    for chain, width in zip(linked, widths, strict=True):
        if start > 0 and start + width > band_width:
            band, start = band + 1, 0.0
        for row in (chain.obverses, chain.reverses):  # each row spread evenly over the chain's width
            for i, node in enumerate(row):
                x[node] = start - 0.5 + (i + 0.5) * width / len(row)
                band_of[node] = band
        bounds.append((start - 0.5, start + width - 0.5, band, chain))
        start += width + 1.0
    n_bands = band + 1
    fig_w = min(max_width_in, max(6.0, 0.16 * band_width + 1.5))
    fig, ax = plt.subplots(figsize=(fig_w, 0.6 + 2.0 * n_bands))
    step = 1.8  # vertical distance between bands

    def y(node: str) -> float:
        return (1.0 if g.nodes[node]["side"] == OBVERSE else 0.0) - step * band_of[node]

    top = max((w for _, _, w in g.edges(data="weight")), default=1)
    for o, r, w in g.edges(data="weight"):
        ax.plot(
            [x[o], x[r]],
            [y(o), y(r)],
            color=LINK_COLOUR,
            alpha=0.55,
            lw=0.4 + 3.6 * w / top,
            solid_capstyle="round",
            zorder=1,
        )
    for side, colour in ((OBVERSE, OBVERSE_COLOUR), (REVERSE, REVERSE_COLOUR)):
        nodes = [n for n in x if g.nodes[n]["side"] == side]
        sizes = [8 + 4 * g.nodes[n]["coins"] for n in nodes]
        ax.scatter(
            [x[n] for n in nodes],
            [y(n) for n in nodes],
            s=sizes,
            color=colour,
            zorder=2,
            edgecolors="white",
            linewidths=0.4,
            label=f"{side} dies",
        )
    for low, high, b, chain in bounds:
        base = -step * b
        if len(linked) > 1:
            colour = "#f0ebe4" if chain.index % 2 else "#e4ebf0"
            ax.fill_between([low, high], base - 0.2, base + 1.2, color=colour, zorder=0, lw=0)
        ax.text((low + high) / 2, base - 0.24, str(chain.index), ha="center", va="top", fontsize=6)
    if band_width < 80:
        for node, pos in x.items():
            obverse = g.nodes[node]["side"] == OBVERSE
            ax.text(
                pos,
                y(node) + (0.09 if obverse else -0.09),
                g.nodes[node]["die"],
                ha="center",
                va="bottom" if obverse else "top",
                fontsize=6,
            )
    ax.set_xlim(-1, band_width)
    ax.set_ylim(-step * (n_bands - 1) - 0.45, 1.3)
    ticks = [v for b in range(n_bands) for v in (-step * b, 1 - step * b)]
    ax.set_yticks(ticks, ["reverse", "obverse"] * n_bands, fontsize=7)
    ax.set_xticks([])
    for spine in ax.spines.values():
        spine.set_visible(False)
    unlinked = sum(1 for c in links.chains if not c.n_links)
    s = links.summary()
    heading = title or "Die links"
    ax.set_title(
        f"{heading}: {s['obverse_dies']} obverse and {s['reverse_dies']} reverse dies, {s['combinations']} "
        f"combinations on {s['coins_with_both_faces']} coins, {len(linked)} chain{'s' * (len(linked) != 1)} "
        "(numbered below)" + (f"; {unlinked} dies without a linked coin not drawn" if unlinked else ""),
        fontsize=8,
    )
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
