"""Exports of the current (corrected) state: clusters CSV, node-link JSON, GraphML and GEXF.

- ``clusters.csv``: ``face_id, cluster, size, verified``, one face a line (ours);
- ``clusters_paper.csv``: the paper's ``name, die`` (:func:`coindie.clustering.write_clusters`);
- ``graph.json``: networkx node-link with the ``links`` key, link ``weight`` = probability after the expert's
  corrections (cut links dropped, forced ones at 1), loadable by the paper's viewer and by coindie;
- ``graph.graphml`` / ``graph.gexf``: the same graph for Gephi, nodes carrying their cluster.
"""

from __future__ import annotations

import io
import json
import tempfile
from pathlib import Path

import networkx as nx

from coindie.clustering import Clustering, write_clusters
from coindie.clustering.corrections import Corrections, corrected_graph, pair
from coindie.serve.source import ReviewSource

#: File name -> media type.
EXPORTS = {
    "clusters.csv": "text/csv",
    "clusters_paper.csv": "text/csv",
    "graph.json": "application/json",
    "graph.graphml": "application/xml",
    "graph.gexf": "application/xml",
}


def export(source: ReviewSource, corrections: Corrections, clusters: Clustering, name: str) -> str:
    """The text of export ``name`` (one of :data:`EXPORTS`)."""
    if name == "clusters_paper.csv":
        with tempfile.TemporaryDirectory() as folder:
            return write_clusters(clusters, Path(folder) / name).read_text()
    sizes: dict[int, int] = {}
    for label in clusters.labels.values():
        sizes[label] = sizes.get(label, 0) + 1
    members: dict[int, list[str]] = {}
    for face, label in clusters.labels.items():
        members.setdefault(label, []).append(face)
    verified = {label: corrections.is_verified(faces) for label, faces in members.items()}
    if name == "clusters.csv":
        out = io.StringIO()
        out.write("face_id,cluster,size,verified\n")
        for face in sorted(clusters.labels, key=lambda f: (clusters.labels[f], f)):
            label = clusters.labels[face]
            out.write(f"{face},{label},{sizes[label]},{int(verified[label])}\n")
        return out.getvalue()
    g = _graph(source, corrections, clusters, verified)
    if name == "graph.json":
        document = nx.node_link_data(g, edges="links")
        return json.dumps(document) + "\n"
    buffer = io.BytesIO()
    if name == "graph.graphml":
        nx.write_graphml(g, buffer)
    elif name == "graph.gexf":
        nx.write_gexf(g, buffer)
    else:
        raise KeyError(f"no export {name!r}: one of {', '.join(EXPORTS)}")
    return buffer.getvalue().decode()


def _graph(source: ReviewSource, corrections: Corrections, clusters: Clustering, verified: dict) -> nx.Graph:
    g = nx.Graph()
    for face in source.graph.nodes:
        label = clusters.labels[face]
        x, y = source.layout.get(face, (0.0, 0.0))
        g.add_node(face, cluster=int(label), verified=bool(verified[label]), x=float(x), y=float(y))
    for a, b, p in corrected_graph(source.graph, corrections).edges():
        key = pair(a, b)
        if key in corrections.cut:
            continue
        state = (
            "forced" if key in corrections.forced else "expert" if key in corrections.probability else "auto"
        )
        g.add_edge(a, b, weight=float(p), state=state)
    return g
