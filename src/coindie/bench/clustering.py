"""The paper's clustering benchmark (Riedones3D, section 4.3, Table 3) on a hoard with known dies.

For each group of faces — reverses (R), obverses with beard (DB), obverses without beard (D) — every pair of
faces of the clustering test split is registered (``relief`` by default), its distance histogram measured and
its same-die probability estimated; the probability graph is clustered and scored (FMI, ARI as in the paper;
AMI, pairwise precision/recall, clusters vs dies, mistakes). The classifier is trained on the clustering
training split (or given). The threshold τ is chosen

- on the validation split by the best FMI (the paper's way; the beard obverses have no validation split, so
  they take the obverses' τ, as the paper did),
- without labels, on the test graph itself, by the best silhouette on 1 - p (for a new hoard),
- and the paper's τ = 0.95 is reported too,

for each clustering method (``components``, the paper's; ``average``; ``leiden``).

``max_faces`` restricts each group of each split to a sample of faces (dies in random order, at most an
eighth of the cap from one die, so that a group keeps at least 8 dies when it has them), to fit a run into
a day on a few cores: the full test sets are ~87k pairs.
Outputs in ``out``: ``pairs.csv`` (every measured pair, resumable), ``model.json`` (when trained here),
``graph_<split>_<group>.json`` (the paper's node-link graphs), ``clusters_<group>.csv`` (the paper's
``name, die``, components at the validation τ), ``summary.json``, ``summary.md``, ``fmi_vs_threshold.png``.
"""

from __future__ import annotations

import argparse
import itertools
import json
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from coindie.clustering import (
    METHODS,
    PAPER_THRESHOLD,
    ConnectedComponents,
    ProbabilityGraph,
    ThresholdChoice,
    evaluate,
    get_algorithm,
    select_threshold,
    select_threshold_unsupervised,
    write_clusters,
    write_graph,
)
from coindie.io.truth import FaceTruth, HoardTruth, load_truth
from coindie.params import Configurable, param
from coindie.project.backends import Backend, make_backend
from coindie.similarity import PairScore, SameDieClassifier
from coindie.similarity.batch import BatchConfig, PairTask, measure_pairs

GROUPS = {"R": "reverses", "DB": "obverses with beard", "D": "obverses without beard"}
#: Where each group's τ is chosen (the beard obverses have no validation split: the obverses' τ).
THRESHOLD_FROM = {"R": "R", "DB": "D", "D": "D"}
#: The paper's Table 3 (FMI, ARI) and cluster counts (found, true dies) on the real test sets.
PAPER_TABLE_3 = {"R": (0.87, 0.86, 35, 30), "DB": (0.99, 0.99, None, 7), "D": (0.98, 0.97, 16, 14)}
SPLITS = ("cluster_val", "cluster_test")


@dataclass(frozen=True)
class BenchOptions(Configurable):
    method: str = param("relief", doc="the registration method (coindie methods)")
    params: tuple[tuple[str, Any], ...] = ()
    model: Path | None = None  # a trained classifier; None: train one on the training split
    max_faces: int | None = param(
        None, int, doc="at most this many faces per group and split", low=1, optional=True
    )
    train_pairs: int = param(2000, doc="training pairs when training the classifier", low=1)
    train_faces: int = param(200, doc="faces the training pairs are drawn among", low=1)
    methods: tuple[str, ...] = param(
        METHODS, doc="the clustering algorithms compared", item=str, choices=METHODS
    )
    groups: tuple[str, ...] = param(
        tuple(GROUPS), doc="the groups of the paper's Table 3", item=str, choices=tuple(GROUPS)
    )
    workers: int = param(1, doc="worker processes", low=1)
    dask: str | None = param(
        None, str, doc="a Dask scheduler's address or 'local': the pairs are measured there", optional=True
    )
    seed: int = param(0, doc="seed of the face and pair samples", low=0)


def benchmark_clustering(
    data: str | Path,
    out: str | Path,
    options: BenchOptions | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> dict[str, Any]:
    """Run the benchmark (resuming ``out/pairs.csv``), write every output, return the summary."""
    options = options or BenchOptions()
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    truth = load_truth(data)
    wanted = {"cluster_val": {THRESHOLD_FROM[g] for g in options.groups}, "cluster_test": set(options.groups)}
    faces = {
        (split, group): chosen_faces(truth, split, group, options.max_faces, options.seed)
        for split in SPLITS
        for group in GROUPS
        if group in wanted[split]
    }
    backend = make_backend(options.workers, options.dask)
    try:
        classifier = _classifier(truth, out, options, backend, progress)
        config = BatchConfig(options.method, options.params, classifier.settings)
        tasks = [t for group_faces in faces.values() for t in all_pairs(group_faces)]
        scores = measure_pairs(
            tasks, out / "pairs.csv", config, parallel_map=backend.map_ordered, progress=progress
        )
    finally:
        backend.close()
    graphs = {key: probability_graph(f, scores, classifier) for key, f in faces.items()}
    for (split, group), graph in graphs.items():
        if graph.n_nodes:
            write_graph(graph, out / f"graph_{split}_{group}.json")
    summary = summarize(graphs, faces, options)
    summary["run"] = _run_facts(truth, options, classifier, scores, tasks)
    (out / "summary.json").write_text(json.dumps(_json_ready(summary), indent=2) + "\n")
    (out / "summary.md").write_text(summary_markdown(summary))
    _write_clusters(graphs, summary, out)
    _plot(graphs, faces, summary, out / "fmi_vs_threshold.png")
    return summary


def rerun_arguments(parser: argparse.ArgumentParser) -> None:
    """The command line shared by the scripts that re-analyse a run of this benchmark without registering
    again (``benchmarks/bench_clustering_*.py``): its output folder, the hoard, the training pairs written
    by ``coindie train similarity``, the face limit the run was given, and where to write (default: the
    run's folder)."""
    parser.add_argument("bench", type=Path, help="the folder coindie bench clustering wrote")
    parser.add_argument("--hoard", type=Path, required=True)
    parser.add_argument(
        "--train-pairs", type=Path, required=True, help="MODEL.pairs.csv of coindie train similarity"
    )
    parser.add_argument("--max-faces", type=int, default=None, help="as given to coindie bench clustering")
    parser.add_argument("--out", type=Path, default=None, help="output folder (default: BENCH)")


def chosen_faces(
    truth: HoardTruth, split: str, group: str, max_faces: int | None, seed: int = 0
) -> list[FaceTruth]:
    """The faces of ``group`` in ``split``; with ``max_faces``, dies in a seeded random order, at most an
    eighth of the cap (and at least 2) faces of each die, until the cap."""
    faces = sorted((f for f in truth.faces_in(split) if f.family == group), key=lambda f: f.face_id)
    if max_faces is None or len(faces) <= max_faces:
        return faces
    by_die: dict[str, list[FaceTruth]] = {}
    for face in faces:
        by_die.setdefault(face.die, []).append(face)
    rng = np.random.default_rng([seed, len(split), len(group)])
    per_die, chosen = max(2, max_faces // 8), []
    for die in rng.permutation(sorted(by_die)):
        chosen += by_die[str(die)][: min(per_die, max_faces - len(chosen))]
        if len(chosen) >= max_faces:
            break
    return sorted(chosen, key=lambda f: f.face_id)


def all_pairs(faces: list[FaceTruth]) -> list[PairTask]:
    """Every unordered pair once: the face with the smaller id is the source."""
    return [
        PairTask(a.face_id, b.face_id, str(a.path), str(b.path)) for a, b in itertools.combinations(faces, 2)
    ]


def probability_graph(
    faces: list[FaceTruth], scores: dict[tuple[str, str], PairScore], classifier: SameDieClassifier
) -> ProbabilityGraph:
    """The graph of the faces' pairs with the classifier's probabilities (0 for invalid registrations)."""
    pairs = [scores[(t.source, t.target)] for t in all_pairs(faces)]
    valid = [s for s in pairs if s.valid and s.histogram.any()]
    probabilities = dict.fromkeys(((s.source_id, s.target_id) for s in pairs), 0.0)
    if valid:
        p = classifier.predict_proba(np.stack([s.histogram for s in valid]))
        probabilities.update({(s.source_id, s.target_id): float(q) for s, q in zip(valid, p, strict=True)})
    edges = [(a, b, p) for (a, b), p in probabilities.items()]
    return ProbabilityGraph.from_edges(edges, [f.face_id for f in faces])


def summarize(
    graphs: dict[tuple[str, str], ProbabilityGraph],
    faces: dict[tuple[str, str], list[FaceTruth]],
    options: BenchOptions,
) -> dict[str, Any]:
    """Per group and method: τ from validation, τ without labels, and the test scores at each τ."""
    dies = {key: {f.face_id: f.die for f in group} for key, group in faces.items()}
    thresholds: dict[tuple[str, str], ThresholdChoice] = {}
    for method in options.methods:
        for group in {THRESHOLD_FROM[g] for g in options.groups}:
            val = graphs[("cluster_val", group)]
            if val.n_nodes >= 2:
                thresholds[(method, group)] = select_threshold(val, dies[("cluster_val", group)], method)
    results: dict[str, Any] = {}
    for group in options.groups:
        test, truth = graphs[("cluster_test", group)], dies[("cluster_test", group)]
        if test.n_nodes < 2:
            continue
        entry: dict[str, Any] = {
            "n_faces": test.n_nodes, "n_dies": len(set(truth.values())), "pairs": pair_figures(test, truth),
            "methods": {},
        }  # fmt: skip
        for method in options.methods:
            rows = {}
            chosen = thresholds.get((method, THRESHOLD_FROM[group]))
            auto = select_threshold_unsupervised(test, method)
            for label, tau in (
                ("validation", chosen.threshold if chosen else None),
                ("silhouette", auto.threshold),
                ("paper", PAPER_THRESHOLD),
            ):
                if tau is None:
                    continue
                result = evaluate(get_algorithm(method, threshold=tau).fit(test).clustering_.labels, truth)
                rows[label] = {"threshold": tau, **result.scores(), "mistakes": len(result.mistakes)}
            rows["best_possible"] = _oracle(test, truth, method)
            entry["methods"][method] = rows
        results[group] = entry
    return {"groups": results}


def pair_figures(graph: ProbabilityGraph, truth: dict[str, str]) -> dict[str, float | int]:
    """How well the probabilities alone separate same-die from different-die pairs (where clustering
    scores saturate, this still tells classifiers apart): ROC AUC, same-die pairs at probability 0 (their
    registration was refused), the highest different-die probability and how many pass 0.5."""
    from sklearn.metrics import roc_auc_score

    same = np.array([truth[a] == truth[b] for a, b, _ in graph.edges()], dtype=bool)
    p = graph.probability
    figures: dict[str, float | int] = {"n_pairs": int(len(p)), "n_same_die": int(same.sum())}
    if same.any() and (~same).any():
        figures["auc"] = float(roc_auc_score(same, p))
        figures["max_other_probability"] = float(p[~same].max())
        figures["other_above_half"] = int(np.sum(p[~same] > 0.5))
    if same.any():
        figures["same_die_at_zero"] = int(np.sum(p[same] == 0.0))
    return figures


def _oracle(test: ProbabilityGraph, truth: dict[str, str], method: str) -> dict[str, Any]:
    """The test set's own best τ (with its labels): how much the τ choice costs, not a result."""
    best = select_threshold(test, truth, method)
    return {
        "threshold": best.threshold,
        **evaluate(
            get_algorithm(method, threshold=best.threshold).fit(test).clustering_.labels, truth
        ).scores(),
    }


def _classifier(
    truth: HoardTruth,
    out: Path,
    options: BenchOptions,
    backend: Backend,
    progress: Callable[[int, int], None] | None,
) -> SameDieClassifier:
    if options.model is not None:
        return SameDieClassifier.load(options.model)
    from coindie.similarity.training import train_similarity

    model = train_similarity(
        truth, out / "train_pairs.csv", config=BatchConfig(options.method, options.params),
        max_pairs=options.train_pairs, max_faces=options.train_faces,
        parallel_map=backend.map_ordered,
        seed=options.seed, progress=progress,
    )  # fmt: skip
    model.save(out / "model.json")
    return model


def _run_facts(
    truth: HoardTruth,
    options: BenchOptions,
    classifier: SameDieClassifier,
    scores: dict[tuple[str, str], PairScore],
    tasks: list[PairTask],
) -> dict[str, Any]:
    measured = [scores[(t.source, t.target)] for t in tasks]
    times = [s.timings.get("total", 0.0) for s in measured if s.timings]
    return {
        "data": str(truth.root), "registration": options.method, "max_faces": options.max_faces,
        "model": str(options.model) if options.model else "trained on cluster_train (model.json)",
        "classifier_pairs": classifier.metadata.get("n_pairs"), "n_pairs": len(measured),
        "valid_share": float(np.mean([s.valid for s in measured])) if measured else float("nan"),
        "median_time_per_pair_s": float(np.median(times)) if times else float("nan"),
        "settings": classifier.settings.to_dict(),
    }  # fmt: skip


# ------------------------------------------------------------------------------------------------ reports


def summary_markdown(summary: dict[str, Any]) -> str:
    """Table 3 of the paper for our pipeline, per group: FMI / ARI / AMI and clusters for true dies."""
    header = ["group", "method", "τ from", "τ", "FMI", "ARI", "AMI", "precision", "recall", "clusters / dies"]
    lines = [_row(header), _row(["---", "---", "---"] + ["---:"] * (len(header) - 3))]
    for group, entry in summary["groups"].items():
        for method, rows in entry["methods"].items():
            for label, r in rows.items():
                name = "test labels (oracle)" if label == "best_possible" else label
                lines.append(
                    _row(
                        [
                            f"{group} ({entry['n_faces']} faces)", method, name, f"{r['threshold']:.4g}",
                            f"{r['fmi']:.3f}", f"{r['ari']:.3f}", f"{r['ami']:.3f}", f"{r['precision']:.3f}",
                            f"{r['recall']:.3f}", f"{r['n_clusters']} / {r['n_dies']}",
                        ]
                    )
                )  # fmt: skip
    lines += ["", "Pairs of each test group (the probabilities alone):", ""]
    lines += [_row(["group", "pairs", "same-die", "AUC", "same-die at 0", "max other p", "others > 0.5"])]
    lines += [_row(["---"] + ["---:"] * 6)]
    for group, entry in summary["groups"].items():
        f = entry.get("pairs", {})
        cells = [
            group,
            str(f.get("n_pairs", "–")),
            str(f.get("n_same_die", "–")),
            _maybe(f.get("auc"), ".4f"),
        ]
        cells += [str(f.get("same_die_at_zero", "–")), _maybe(f.get("max_other_probability"), ".3f")]
        lines.append(_row([*cells, str(f.get("other_above_half", "–"))]))
    lines += [
        "",
        "The paper's Table 3 (real Riedones3D test sets, FCGF + TEASER registration, τ = 0.95):",
        "",
    ]
    lines += [_row(["group", "FMI", "ARI", "clusters / dies"]), _row(["---", "---:", "---:", "---:"])]
    for group, (fmi, ari, found, dies) in PAPER_TABLE_3.items():
        lines.append(
            _row([GROUPS[group], f"{fmi:.2f}", f"{ari:.2f}", f"{found or '7 dies, one coin wrong'} / {dies}"])
        )
    run = summary.get("run", {})
    if run:
        lines += ["", f"Run: {json.dumps(_json_ready(run))}"]
    return "\n".join(lines) + "\n"


def _maybe(value: float | None, spec: str) -> str:
    return "–" if value is None else format(value, spec)


def _row(cells: list[str]) -> str:
    return "| " + " | ".join(cells) + " |"


def _json_ready(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _json_ready(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_json_ready(v) for v in value]
    if isinstance(value, float | np.floating):
        return float(value) if np.isfinite(value) else None
    if isinstance(value, np.integer):
        return int(value)
    return value


def _write_clusters(
    graphs: dict[tuple[str, str], ProbabilityGraph], summary: dict[str, Any], out: Path
) -> None:
    for group, entry in summary["groups"].items():
        rows = entry["methods"].get("components", {})
        tau = rows.get("validation", rows.get("paper", {})).get("threshold", PAPER_THRESHOLD)
        write_clusters(
            ConnectedComponents(threshold=tau).fit(graphs[("cluster_test", group)]).clustering_,
            out / f"clusters_{group}.csv",
        )


def _plot(
    graphs: dict[tuple[str, str], ProbabilityGraph],
    faces: dict[tuple[str, str], list[FaceTruth]],
    summary: dict[str, Any],
    path: Path,
) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = list(summary["groups"])
    if not groups:
        return
    fig, axes = plt.subplots(1, len(groups), figsize=(4.5 * len(groups), 3.8), squeeze=False)
    grid = np.linspace(0.01, 0.999, 60)
    for ax, group in zip(axes[0], groups, strict=True):
        test = graphs[("cluster_test", group)]
        truth = {f.face_id: f.die for f in faces[("cluster_test", group)]}
        for method, rows in summary["groups"][group]["methods"].items():
            curve = select_threshold(test, truth, method, thresholds=grid)
            (line,) = ax.plot(curve.thresholds, curve.scores, label=method)
            if "validation" in rows:
                ax.axvline(rows["validation"]["threshold"], color=line.get_color(), ls=":", lw=1)
        ax.set_title(f"{GROUPS[group]} (test, {test.n_nodes} faces)", fontsize=9)
        ax.set_xlabel("threshold τ")
        ax.set_ylim(0, 1.02)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("FMI (dotted: τ chosen on validation)")
    axes[0][-1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
