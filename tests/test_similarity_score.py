"""score_pair and the resumable pair batch on a tiny synthetic hoard whose dies are known."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from coindie.io import read_scan
from coindie.io.truth import load_truth
from coindie.registration import get_method
from coindie.similarity import PairScore, SameDieClassifier, add_histogram, score_pair
from coindie.similarity.batch import BatchConfig, PairTask, measure_pairs, read_scores, tiles
from coindie.similarity.relief_classifier import ReliefClassifier
from coindie.similarity.scorers import load_scorer
from coindie.similarity.training import fit_classifier, labelled_pairs


@pytest.fixture(scope="module")
def hoard(tmp_path_factory) -> Path:
    from coindie.synth.hoard import synthesize

    # The default scanner (0.05 mm, like the riedones hoard the shipped model was trained on): distances
    # between coarser scans are larger, and the model would not apply.
    out = tmp_path_factory.mktemp("tiny_hoard")
    synthesize(out, preset="tiny", seed=3, workers=1)
    return out


def _pairs_by_die(hoard: Path) -> tuple[tuple[str, str], tuple[str, str]]:
    """One same-die and one different-die pair of obverses without beard."""
    truth = load_truth(hoard)
    faces = sorted((f for f in truth.faces.values() if f.family == "D"), key=lambda f: f.face_id)
    same = next((a, b) for a in faces for b in faces if a.face_id < b.face_id and a.die == b.die)
    other = next((a, b) for a in faces for b in faces if a.face_id < b.face_id and a.die != b.die)
    return (str(same[0].path), str(same[1].path)), (str(other[0].path), str(other[1].path))


def test_shipped_model_scores_same_die_pairs_higher(hoard: Path) -> None:
    (a, b), (c, d) = _pairs_by_die(hoard)
    registrar = get_method("relief")
    same = score_pair(read_scan(a), read_scan(b), registrar)
    other = score_pair(read_scan(c), read_scan(d), registrar)
    assert same.valid and same.probability > 0.5
    assert other.probability < same.probability
    assert same.histogram.shape == (70,) and set(same.timings) >= {
        "register",
        "histogram",
        "classify",
        "total",
    }
    assert SameDieClassifier.load_default().settings.bins == 70


def test_pair_score_round_trips_through_json(hoard: Path) -> None:
    (a, b), _ = _pairs_by_die(hoard)
    score = score_pair(read_scan(a), read_scan(b))
    again = PairScore.from_dict(json.loads(json.dumps(score.to_dict())))
    assert again.source_id == score.source_id and again.probability == score.probability
    np.testing.assert_array_equal(again.T_target_source, score.T_target_source)
    np.testing.assert_array_equal(again.histogram, score.histogram)


def test_a_score_without_its_histogram_gets_the_same_one_later_and_the_same_probability(hoard: Path) -> None:
    """``with_histogram=False`` (relays that may be thrown away) changes neither pose nor probability of the
    relief scorer; :func:`add_histogram` measures what the full score holds. The paper scorer, which reads
    the histogram, measures it regardless."""
    (a, b), _ = _pairs_by_die(hoard)
    source, target = read_scan(a), read_scan(b)
    full = score_pair(source, target)
    bare = score_pair(source, target, with_histogram=False)
    assert not bare.histogram.any() and "histogram" not in bare.timings
    assert bare.probability == full.probability
    np.testing.assert_array_equal(bare.T_target_source, full.T_target_source)
    np.testing.assert_allclose(add_histogram(bare, source, target).histogram, full.histogram, atol=1e-12)
    paper = SameDieClassifier.load_default()
    assert score_pair(source, target, classifier=paper, with_histogram=False).histogram.any()


class _Refuses:
    """A registrar that never finds a transform (a real method's invalid result, made certain)."""

    name = "refuses"

    def register(self, source, target):  # noqa: ANN001, ANN201
        result = get_method("relief").register(source, target)
        from dataclasses import replace

        return replace(result, valid=False, reason="refused for the test")


def test_invalid_registration_scores_zero(hoard: Path) -> None:
    (a, b), _ = _pairs_by_die(hoard)
    score = score_pair(read_scan(a), read_scan(b), _Refuses())
    assert not score.valid and score.probability == 0.0 and score.reason == "refused for the test"


def test_batch_resumes_and_records_bad_scans(hoard: Path, tmp_path: Path) -> None:
    truth = load_truth(hoard)
    # The clustering test split has several dies per side (the training split of the tiny preset has one).
    pairs = labelled_pairs(truth, "cluster_test", max_pairs=None, negatives=1.0)
    tasks = [p.task() for p in pairs]
    broken = tmp_path / "L0099D.ply"
    broken.write_text("ply\nformat nonsense\n")
    tasks.append(PairTask("L0099D", tasks[0].target, str(broken), tasks[0].target_path))
    out = tmp_path / "pairs.csv"
    seen: list[tuple[int, int]] = []
    scores = measure_pairs(tasks, out, BatchConfig(), progress=lambda a, t: seen.append((a, t)))
    assert seen[0] == (0, len(tasks)) and sum(a for a, t in seen[1:]) == len(tasks)
    bad = scores[("L0099D", tasks[0].target)]
    assert not bad.valid and "L0099D.ply" in bad.reason
    assert sum(s.valid for s in scores.values()) >= len(tasks) // 2
    # A second run finds every pair done; the stored rows read back equal.
    seen.clear()
    again = measure_pairs(tasks, out, BatchConfig(), progress=lambda a, t: seen.append((a, t)))
    assert seen == [(len(tasks), len(tasks))]
    key = (tasks[0].source, tasks[0].target)
    np.testing.assert_allclose(again[key].histogram, scores[key].histogram, rtol=1e-5)
    assert set(read_scores(out)) == set(scores)
    # A classifier fits on the stored histograms.
    model = fit_classifier(scores, pairs)
    assert model.is_fitted and model.metadata["n_pairs"] >= 2


def test_tiles_cover_every_task_once() -> None:
    tasks = [PairTask(f"s{i}", f"t{j}", "", "") for i in range(20) for j in range(7)]
    grouped = tiles(tasks, block=5)
    flat = [t for tile in grouped for t in tile]
    assert sorted(flat, key=str) == sorted(tasks, key=str)
    assert all(len({t.source for t in tile} | {t.target for t in tile}) <= 10 for tile in grouped)


def test_train_similarity_command_writes_a_loadable_model(hoard: Path, tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from coindie.cli.app import app

    out = tmp_path / "model.json"
    args = [
        "train",
        "similarity",
        str(hoard),
        "--out",
        str(out),
        "--split",
        "cluster_test",
        "--max-pairs",
        "30",
    ]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    model = load_scorer(out)
    assert isinstance(model, ReliefClassifier) and model.NAME == "relief"
    assert model.metadata["split"] == "cluster_test" and model.metadata["method"] == "relief"
    assert (tmp_path / "model.pairs.csv").is_file()
    # the paper's scorer from the same measured pairs (the CSV is resumed: nothing is registered again)
    paper = CliRunner().invoke(app, [*args, "--scorer", "paper", "--work", str(tmp_path / "model.pairs.csv")])
    assert paper.exit_code == 0, paper.output
    assert SameDieClassifier.load(out).NAME == "paper"
    bad = CliRunner().invoke(app, [*args[:5], "--method", "nope"])
    assert bad.exit_code == 2 and "unknown method" in bad.output


def test_a_tile_whose_worker_was_lost_is_recorded_as_failed_and_the_batch_goes_on(tmp_path: Path) -> None:
    from coindie.errors import WorkerLost

    # 15 faces: two tiles (one tile would be measured in this process, without the backend)
    tasks = [PairTask(f"L{k:04d}D", "L0099D", str(tmp_path / f"L{k:04d}D.ply"), "") for k in range(14)]

    def lost_workers(function, tiles):  # a backend's map_ordered whose every worker died for good
        return [WorkerLost("its worker process died 3 times") for _ in tiles]

    out = tmp_path / "pairs.csv"
    scores = measure_pairs(tasks, out, BatchConfig(), parallel_map=lost_workers)
    assert len(scores) == len(tasks) and not any(s.valid for s in scores.values())
    assert all(s.reason == "worker lost: its worker process died 3 times" for s in scores.values())
    assert set(read_scores(out)) == {(t.source, t.target) for t in tasks}


def test_a_tile_that_raises_stops_the_batch(tmp_path: Path) -> None:
    tasks = [PairTask(f"L{k:04d}D", "L0099D", "", "") for k in range(14)]  # two tiles

    def broken(function, tiles):
        return [RuntimeError("a bug, not a bad scan") for _ in tiles]

    with pytest.raises(RuntimeError, match="a bug"):
        measure_pairs(tasks, tmp_path / "pairs.csv", BatchConfig(), parallel_map=broken)
