"""Variants of the similarity and clustering stages, on pairs a clustering benchmark already measured.

    python benchmarks/bench_clustering_variants.py BENCH_DIR --hoard H --train-pairs TRAIN.csv [--out OUT]

``BENCH_DIR`` is the output of ``coindie bench clustering`` (its ``pairs.csv`` holds every validation and
test pair's registration and histogram); ``TRAIN.csv`` the pairs CSV written by ``coindie train similarity``
(``MODEL.pairs.csv``). Nothing is registered again: each classifier variant is fitted on the training
histograms and applied to the stored ones, τ is chosen on the validation split by FMI (beard obverses take
the obverses' τ) and the test split is scored, for every clustering method. Variants: the shipped form
(own scaler, C = 1, Platt-calibrated), the paper's scaler (``histogram_scaler.json``), C = 0.1 and 10, and
the regression without calibration. Writes ``OUT/variants.md`` and ``OUT/variants.json`` (OUT defaults to
BENCH_DIR).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from coindie.bench.clustering import rerun_arguments

PAPER_SCALER = (
    Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "riedones3d" / "histogram_scaler.json"
)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    rerun_arguments(parser)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    out = args.out or args.bench
    out.mkdir(parents=True, exist_ok=True)

    from coindie.bench.clustering import GROUPS, SPLITS, THRESHOLD_FROM, chosen_faces, probability_graph
    from coindie.clustering import METHODS, cluster, evaluate, select_threshold
    from coindie.io.truth import load_truth
    from coindie.similarity import SameDieClassifier
    from coindie.similarity.batch import read_scores

    truth = load_truth(args.hoard)
    measured = read_scores(args.bench / "pairs.csv")
    train = read_scores(args.train_pairs)
    X, y = _training_set(train, truth)
    variants = {
        "own scaler, C=1, Platt (shipped form)": SameDieClassifier(),
        "paper's scaler, C=1, Platt": SameDieClassifier.from_paper_scaler(PAPER_SCALER),
        "own scaler, C=0.1, Platt": SameDieClassifier(C=0.1),
        "own scaler, C=10, Platt": SameDieClassifier(C=10.0),
    }
    fitted = {name: model.fit(X, y, seed=args.seed) for name, model in variants.items()}
    raw = SameDieClassifier().fit(X, y, seed=args.seed)
    raw.platt = (1.0, 0.0)
    fitted["own scaler, C=1, no calibration"] = raw
    faces = {
        (split, group): chosen_faces(truth, split, group, args.max_faces, args.seed)
        for split in SPLITS
        for group in GROUPS
    }
    faces = {k: f for k, f in faces.items() if f and all(_have(measured, f))}
    results: dict[str, dict] = {}
    for name, model in fitted.items():
        graphs = {key: probability_graph(f, measured, model) for key, f in faces.items()}
        dies = {key: {f.face_id: f.die for f in group} for key, group in faces.items()}
        entry = {}
        for group in GROUPS:
            if ("cluster_test", group) not in graphs or ("cluster_val", THRESHOLD_FROM[group]) not in graphs:
                continue
            for method in METHODS:
                val_key = ("cluster_val", THRESHOLD_FROM[group])
                tau = select_threshold(graphs[val_key], dies[val_key], method).threshold
                r = evaluate(
                    cluster(graphs[("cluster_test", group)], method, tau).labels,
                    dies[("cluster_test", group)],
                )
                entry[f"{group}/{method}"] = {"threshold": tau, **r.scores()}
        results[name] = entry
    (out / "variants.json").write_text(json.dumps(results, indent=2) + "\n")
    (out / "variants.md").write_text(_markdown(results, len(y), int(np.sum(y))))
    print((out / "variants.md").read_text())
    return 0


def _have(measured: dict, faces: list) -> list[bool]:
    ids = [f.face_id for f in faces]
    return [(a, b) in measured for i, a in enumerate(ids) for b in ids[i + 1 :]]


def _training_set(train: dict, truth) -> tuple[np.ndarray, np.ndarray]:  # noqa: ANN001
    rows = [(s.histogram, truth.faces[a].die == truth.faces[b].die) for (a, b), s in train.items() if s.valid]
    rows = [(h, same) for h, same in rows if h.any()]
    return np.stack([h for h, _ in rows]), np.array([same for _, same in rows])


def _markdown(results: dict[str, dict], n_pairs: int, n_same: int) -> str:
    groups = ("R", "DB", "D")
    lines = [
        f"Classifier variants, fitted on {n_pairs} valid training pairs ({n_same} same-die). Test FMI / ARI "
        "/ clusters:dies per group, τ chosen on validation by FMI.",
        "",
        "| variant | clustering | " + " | ".join(groups) + " |",
        "| --- | --- | " + " | ".join("---:" for _ in groups) + " |",
    ]
    for name, entry in results.items():
        methods = sorted({key.split("/")[1] for key in entry})
        for method in methods:
            cells = []
            for group in groups:
                e = entry.get(f"{group}/{method}")
                cells.append(_cell(e) if e else "–")
            lines.append(f"| {name} | {method} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def _cell(e: dict) -> str:
    return f"{e['fmi']:.3f} / {e['ari']:.3f} / {e['n_clusters']}:{e['n_dies']} (τ {e['threshold']:.3g})"


if __name__ == "__main__":
    sys.exit(main())
