"""Every face of a die moved into the frame of one reference face of the die, as the Riedones3D authors'
rendering script did: transforms chained along the die's best links.

Per die: the graph of its faces weighted by the project's same-die probabilities (the scored pairs inside
the die); its **maximum spanning tree** keeps, for every face, the most trusted chain of registrations to
the others. The **reference** is the face with the largest sum of probabilities to the die's other faces
(the best-linked coin). A face's transform is the product of the tree's registrations along its path to
the reference: for the path ``ref = a0, a1, ..., ak = face``,
``T_ref_face = T_a0_a1 @ T_a1_a2 @ ... @ T_a(k-1)_ak``, each ``T_ai_aj`` the stored ``T_target_source``
of the pair (inverted when the pair was stored the other way). Faces the tree does not reach (a die made
by a method that does not need links, or pairs not scored) keep no transform and are reported.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import networkx as nx
import numpy as np
from numpy.typing import NDArray

from coindie.numismatics.sources import SideDies, project_dies

Progress = Callable[[int, int], None]


@dataclass
class DieAlignment:
    """One die: its faces, reference, transforms into the reference's frame, and the tree's links."""

    side: str
    die: str
    faces: list[str]
    reference: str
    T_reference_face: dict[str, NDArray[np.float64]] = field(default_factory=dict)
    tree: list[tuple[str, str, float]] = field(default_factory=list)

    @property
    def unaligned(self) -> list[str]:
        return [f for f in self.faces if f not in self.T_reference_face]


def _pair_graph(pairs: list[dict]) -> nx.Graph:
    graph = nx.Graph()
    for p in pairs:
        if p.get("T_target_source") is None:
            continue
        graph.add_edge(
            p["source"], p["target"], weight=float(p["probability"] or 0.0),
            T=(p["target"], p["source"], np.asarray(p["T_target_source"], dtype=np.float64)),
        )  # fmt: skip
    return graph


def _edge_transform(graph: nx.Graph, into: str, moved: str) -> NDArray[np.float64]:
    """``T_into_moved`` from the stored pair (``T_target_source``), inverted when stored the other way."""
    target, source, T = graph[into][moved]["T"]
    if (target, source) == (into, moved):
        return T
    return np.linalg.inv(T)


def align_die(side: str, die: str, faces: list[str], pairs_graph: nx.Graph) -> DieAlignment:
    """The alignment of one die's faces (module docstring)."""
    faces = sorted(faces)
    # A sorted copy: networkx subgraph views iterate a set, and the spanning tree's ties (many links at
    # probability 1) would then be broken differently from run to run.
    sub = nx.Graph()
    sub.add_nodes_from(f for f in faces if f in pairs_graph)
    view = pairs_graph.subgraph(faces)
    edges = sorted((*sorted((a, b)), w) for a, b, w in view.edges(data="weight"))
    sub.add_weighted_edges_from(edges)
    strength = {f: sum(w for _, _, w in sub.edges(f, data="weight")) if f in sub else 0.0 for f in faces}
    reference = max(faces, key=lambda f: (strength[f], -faces.index(f)))
    alignment = DieAlignment(side, die, faces, reference, {reference: np.eye(4)})
    if reference not in sub or sub.number_of_edges() == 0:
        return alignment
    component = nx.node_connected_component(sub, reference)
    linked = nx.Graph()
    linked.add_nodes_from(f for f in faces if f in component)
    linked.add_weighted_edges_from(e for e in edges if e[0] in component)
    tree = nx.maximum_spanning_tree(linked, weight="weight")
    alignment.tree = sorted((a, b, float(w)) for a, b, w in tree.edges(data="weight"))
    for face, path in nx.single_source_shortest_path(tree, reference).items():
        T = np.eye(4)
        for into, moved in zip(path[:-1], path[1:], strict=True):
            T = T @ _edge_transform(pairs_graph, into, moved)
        alignment.T_reference_face[face] = T
    return alignment


def project_alignments(
    project_folder: str | Path,
    sides: dict[str, SideDies] | None = None,
    *,
    threshold: float | None = None,
    method: str = "components",
    auto: bool = False,
) -> dict[str, list[DieAlignment]]:
    """Per side, the alignment of every die of the project's clusters (largest die first)."""
    from coindie.project import open_project

    project = open_project(project_folder)
    sides = sides or project_dies(project_folder, method, threshold, auto)
    out: dict[str, list[DieAlignment]] = {}
    for side, dies in sides.items():
        graph = _pair_graph(project.scored_pairs(side=side))
        out[side] = [align_die(side, die, members, graph) for die, members in dies.members().items()]
    return out


def scan_paths(project_folder: str | Path) -> dict[str, Path]:
    """Face id -> scan file, for the project's usable faces."""
    from coindie.project import open_project

    return {s.face_id: Path(s.path) for s in open_project(project_folder).scans("ok")}


def export_aligned_dies(
    project_folder: str | Path,
    out_dir: str | Path,
    *,
    threshold: float | None = None,
    method: str = "components",
    auto: bool = False,
    progress: Progress | None = None,
) -> dict[str, list[Path]]:
    """``OUT/<side>_<die>/<face>.ply`` for every face, in its die's reference frame (the reference's own
    file frame, millimetres); unaligned faces are written in their own frame, their name suffixed
    ``_unaligned``. A face whose scan cannot be read is skipped and the others go on."""
    from coindie.errors import CoinDieError
    from coindie.io import read_scan, write_ply
    from coindie.project import open_project

    alignments = project_alignments(project_folder, threshold=threshold, method=method, auto=auto)
    paths = scan_paths(project_folder)
    unit = open_project(project_folder).unit
    out = Path(out_dir)
    total = sum(len(a.faces) for dies in alignments.values() for a in dies)
    if progress:
        progress(0, total)
    written: dict[str, list[Path]] = {}
    for side, dies in alignments.items():
        for alignment in dies:
            folder = out / f"{side}_{alignment.die}"
            folder.mkdir(parents=True, exist_ok=True)
            files = written.setdefault(folder.name, [])
            for face in alignment.faces:
                try:
                    scan = read_scan(paths[face], unit=unit)
                    T = alignment.T_reference_face.get(face)
                    name = f"{face}.ply" if T is not None else f"{face}_unaligned.ply"
                    files.append(write_ply(folder / name, scan if T is None else scan.transformed(T)))
                except (CoinDieError, KeyError, OSError):
                    pass  # one unreadable scan does not stop the export; the report lists missing faces
                if progress:
                    progress(1, 0)
    return written
