"""The graph of same-die probabilities between faces, and the paper's file formats.

Nodes are face ids (canonical keys: ``L082D`` and ``L0082D`` are one node); each undirected edge carries the
probability that its two faces were struck by the same die. A pair scored in both directions keeps the mean
of its two probabilities. Files:

- the paper's ``graph.json``: networkx node-link JSON, link ``weight`` = probability (the authors' viewer
  and ``beard_probability_graph.json`` use it);
- a pairs CSV ``source,target,probability`` (other columns are ignored; ``weight`` is accepted for
  ``probability``).
"""

from __future__ import annotations

import csv
import json
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from coindie.arrays import FloatArray, IntArray
from coindie.errors import CoinDieError
from coindie.ids import parse_face_id


class GraphError(CoinDieError, ValueError):
    """A probability graph or pairs file cannot be read or is inconsistent."""


@dataclass(frozen=True, eq=False)
class ProbabilityGraph:
    """Faces and the same-die probability of some of their pairs.

    Attributes:
        nodes: face ids, in a fixed order (canonical keys).
        i, j: (m,) node indices of each edge, ``i < j``, no duplicates.
        probability: (m,) probability of each edge, in [0, 1].
    """

    nodes: tuple[str, ...]
    i: IntArray
    j: IntArray
    probability: FloatArray

    @classmethod
    def from_edges(
        cls, edges: Iterable[tuple[str, str, float]], nodes: Iterable[str] = (), where: str = "graph"
    ) -> ProbabilityGraph:
        """A graph from ``(face_a, face_b, probability)`` triples; ``nodes`` adds faces without edges.

        Raises:
            GraphError: a probability outside [0, 1] or not a number, or an edge from a face to itself.
        """
        index: dict[str, int] = {}
        for node in nodes:
            index.setdefault(_key(node), len(index))
        sums: dict[tuple[int, int], list[float]] = {}
        for a, b, p in edges:
            ka, kb = _key(a), _key(b)
            if ka == kb:
                raise GraphError(f"{where}: an edge from {ka} to itself")
            p = float(p)
            if not 0.0 <= p <= 1.0:  # NaN fails too
                raise GraphError(f"{where}: the probability of {ka}-{kb} is {p}, not in [0, 1]")
            ia, ib = index.setdefault(ka, len(index)), index.setdefault(kb, len(index))
            pair = (min(ia, ib), max(ia, ib))
            entry = sums.setdefault(pair, [0.0, 0.0])
            entry[0] += p
            entry[1] += 1
        pairs = np.array(list(sums), dtype=np.int64).reshape(-1, 2)
        values = np.array([s / n for s, n in sums.values()], dtype=np.float64)
        return cls(tuple(index), pairs[:, 0], pairs[:, 1], values)

    @property
    def n_nodes(self) -> int:
        return len(self.nodes)

    @property
    def n_edges(self) -> int:
        return len(self.probability)

    def edges(self) -> Iterator[tuple[str, str, float]]:
        for a, b, p in zip(self.i, self.j, self.probability, strict=True):
            yield self.nodes[a], self.nodes[b], float(p)

    def index(self) -> dict[str, int]:
        return {node: k for k, node in enumerate(self.nodes)}

    def matrix(self) -> FloatArray:
        """The dense symmetric (n, n) probability matrix: 1 on the diagonal, 0 for unscored pairs."""
        P = np.zeros((self.n_nodes, self.n_nodes))
        P[self.i, self.j] = self.probability
        P[self.j, self.i] = self.probability
        np.fill_diagonal(P, 1.0)
        return P

    def subgraph(self, faces: Iterable[str]) -> ProbabilityGraph:
        """The faces among ``faces`` that are nodes, and the edges between them."""
        wanted = {_key(f) for f in faces}
        keep = np.array([node in wanted for node in self.nodes], dtype=bool)
        new_index = np.cumsum(keep) - 1
        edge_keep = keep[self.i] & keep[self.j] if self.n_edges else np.zeros(0, dtype=bool)
        nodes = tuple(node for node, k in zip(self.nodes, keep, strict=True) if k)
        return ProbabilityGraph(
            nodes, new_index[self.i[edge_keep]], new_index[self.j[edge_keep]], self.probability[edge_keep]
        )


def read_graph(path: str | Path) -> ProbabilityGraph:
    """A graph from the paper's node-link ``graph.json`` or a pairs CSV (by the file's content)."""
    path = Path(path)
    try:
        text = path.read_text()
    except FileNotFoundError:
        raise GraphError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError) as error:
        raise GraphError(f"{path}: cannot be read ({error})") from None
    if text.lstrip().startswith("{"):
        return _from_node_link(text, path)
    return _from_pairs_csv(text.splitlines(), path)


def write_graph(graph: ProbabilityGraph, path: str | Path) -> Path:
    """Write ``graph`` as node-link JSON (``.json``, the paper's format) or as a pairs CSV (otherwise)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.suffix.lower() == ".json":
        document = {
            "directed": False,
            "multigraph": False,
            "graph": {},
            "nodes": [{"id": node} for node in graph.nodes],
            "links": [{"weight": p, "source": a, "target": b} for a, b, p in graph.edges()],
        }
        path.write_text(json.dumps(document) + "\n")
        return path
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["source", "target", "probability"])
        writer.writerows([a, b, repr(p)] for a, b, p in graph.edges())
    return path


def _from_node_link(text: str, path: Path) -> ProbabilityGraph:
    try:
        document = json.loads(text)
        nodes = [str(node["id"]) for node in document["nodes"]]
        links = document.get("links", document.get("edges"))
        edges = [
            (str(e["source"]), str(e["target"]), float(e.get("weight", e.get("probability")))) for e in links
        ]
    except (json.JSONDecodeError, KeyError, TypeError, ValueError) as error:
        raise GraphError(f"{path}: not a node-link graph with weighted links ({error})") from None
    return ProbabilityGraph.from_edges(edges, nodes, where=str(path))


def _from_pairs_csv(lines: Sequence[str], path: Path) -> ProbabilityGraph:
    reader = csv.DictReader(lines, skipinitialspace=True)
    fields = [f.strip().lower() for f in reader.fieldnames or []]
    column = next((c for c in ("probability", "weight") if c in fields), None)
    if not {"source", "target"} <= set(fields) or column is None:
        raise GraphError(f"{path}: a pairs CSV needs the columns source, target, probability; got {fields}")
    edges = []
    for line, row in enumerate(reader, start=2):
        row = {k.strip().lower(): (v or "").strip() for k, v in row.items() if k is not None}
        try:
            edges.append((row["source"], row["target"], float(row[column])))
        except ValueError:
            raise GraphError(f"{path}: line {line}: probability {row[column]!r} is not a number") from None
    return ProbabilityGraph.from_edges(edges, where=str(path))


def _key(face: str) -> str:
    return parse_face_id(str(face)).key
