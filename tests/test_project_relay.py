"""Relays (coindie.project.relay): which pairs are registered again through a third face, from which pose,
and a run that brings back a same-die pair whose own registration was lost."""

from __future__ import annotations

import sqlite3
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coindie.project.relay import plan_relays


def _pose(seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    T = np.eye(4)
    T[:3, :3] = Rotation.random(random_state=seed).as_matrix()
    T[:3, 3] = rng.uniform(-5, 5, 3)
    return T


def _pair(source: str, target: str, p: float, T: np.ndarray | None, scored: bool = True) -> dict:
    return {"source": source, "target": target, "probability": p, "T_target_source": T, "scored": scored}


def test_a_relay_composes_the_two_poses_through_the_third_face_in_the_stored_direction() -> None:
    """Faces a, b, c, each in its scan frame (T_world_x): the relay starts b <- a from T_b_c @ T_c_a
    whichever way each link was stored; only the weak pair is tried, and each (pair, via) only once."""
    T_world = {face: _pose(seed) for seed, face in enumerate("abc")}

    def T(to: str, frm: str) -> np.ndarray:
        return np.linalg.inv(T_world[to]) @ T_world[frm]

    pairs = [
        _pair("a", "b", 0.05, np.eye(4)),  # its registration went wrong
        _pair("c", "a", 0.9, T("a", "c")),  # stored the other way round
        _pair("b", "c", 0.8, T("c", "b")),
    ]
    relays = plan_relays(pairs, neighbours=2)
    assert [(r.source, r.target, r.via) for r in relays] == [("a", "b", "c")]
    np.testing.assert_allclose(relays[0].T_target_source, T("b", "a"), atol=1e-9)
    assert relays[0].before == 0.05 and relays[0].chain == 0.8
    assert plan_relays(pairs, neighbours=2, tried={("a", "b", "c")}) == []
    assert plan_relays(pairs, neighbours=0) == []


def test_only_chains_stronger_than_the_pair_are_tried_the_strongest_first_and_unposed_links_never() -> None:
    """Face 0 against faces 1..4 through the others: a chain is tried only where its weaker link beats the
    pair's own score, at most ``per_pair`` per pair, strongest first; a link whose registration was refused
    carries no pose and relays nothing."""
    faces = [f"f{i}" for i in range(5)]
    p = {
        ("f0", "f1"): 0.1,
        ("f0", "f2"): 0.7,
        ("f0", "f3"): 0.6,
        ("f0", "f4"): 0.95,
        ("f1", "f2"): 0.8,
        ("f1", "f3"): 0.9,
        ("f1", "f4"): 0.05,
        ("f2", "f3"): 0.3,
        ("f2", "f4"): 0.2,
        ("f3", "f4"): 0.4,
    }
    pairs = [_pair(a, b, prob, np.eye(4), scored=(a, b) != ("f1", "f4")) for (a, b), prob in p.items()]
    relays = plan_relays(pairs, neighbours=4, per_pair=2)
    chains: dict[tuple[str, str], list[str]] = {}
    for relay in relays:
        chains.setdefault((relay.source, relay.target), []).append(relay.via)
        link_a = p[tuple(sorted((relay.source, relay.via)))]  # type: ignore[index]
        link_b = p[tuple(sorted((relay.via, relay.target)))]  # type: ignore[index]
        assert relay.chain == min(link_a, link_b) > relay.before == p[relay.source, relay.target]
        assert (relay.source, relay.via) != ("f1", "f4") and (relay.via, relay.target) != ("f1", "f4")
    # f0-f1 (0.1): through f2 (0.7), f3 (0.6); through f4 no, its link to f1 was refused
    assert chains[("f0", "f1")] == ["f2", "f3"]
    assert all(len(vias) <= 2 for vias in chains.values())
    assert ("f0", "f4") not in chains  # 0.95: no chain beats it
    # every chain stronger than its pair whose links are posed is among those tried, up to per_pair
    for a, b in p:
        stronger = [
            c
            for c in faces
            if c not in (a, b)
            and "f1f4" not in {"".join(sorted((a, c))), "".join(sorted((c, b)))}
            and min(p[tuple(sorted((a, c)))], p[tuple(sorted((c, b)))]) > p[a, b]  # type: ignore[index]
        ]
        assert len(chains.get((a, b), [])) == min(len(stronger), 2)


# ------------------------------------------------------------------------------------------- a run


@pytest.fixture(scope="module")
def hoard(tmp_path_factory) -> Path:
    from coindie.synth.hoard import PhysicsParams, synthesize
    from coindie.synth.scanner import ScanParams

    out = tmp_path_factory.mktemp("hoard")
    # 16 faces; dies D1, R1 and R3 struck three faces each
    synthesize(out, preset="tiny", seed=5, physics=PhysicsParams(scan=ScanParams(spacing_mm=0.1)), workers=2)
    return out


def test_a_same_die_pair_whose_registration_was_lost_comes_back_through_a_third_face(hoard, tmp_path) -> None:
    """A scored project loses one same-die pair (its pose and probability wiped, as a failed global search
    leaves them); the next run's relays register it again from the pose through a third face of its die,
    back to the true pose and a same-die probability, and raise no different-die pair over 0.5. A further
    run tries no (pair, via) twice."""
    from coindie.project import init_project, open_project
    from coindie.project.run import RunConfig, run_project
    from coindie.registration.metrics import rotation_error_deg, translation_error_mm
    from coindie.similarity.scorers import default_scorer
    from coindie.synth.writer import read_truth, true_transform

    truth = read_truth(hoard)
    die = {face: record["die_id"] for face, record in truth["faces"].items()}
    project, _ = init_project(tmp_path / "project", hoard, hoard / "labels.csv")
    run_project(project, RunConfig(workers=2, mode="exhaustive", relay_neighbours=0), echo=lambda _: None)
    pairs = project.scored_pairs()
    # the relief scorer does not read the paper's distance histogram: a run measures none unless asked
    assert pairs and all(q["histogram"] is None for q in pairs)
    p = {(q["source"], q["target"]): float(q["probability"]) for q in pairs}
    same = sorted((q for q in pairs if die[q["source"]] == die[q["target"]]), key=lambda q: -q["probability"])

    def chained(a: str, b: str) -> bool:
        links = [(min(p.get((a, c), p.get((c, a), 0)), p.get((c, b), p.get((b, c), 0)))) for c in die]
        return max(links) > 0.5

    lost = next(q for q in same if q["probability"] > 0.5 and chained(q["source"], q["target"]))
    a, b = lost["source"], lost["target"]
    with sqlite3.connect(tmp_path / "project" / "project.sqlite") as db:
        db.execute(
            "UPDATE pairs SET valid = 0, probability = 0, reason = 'lost by the test', T_target_source = ? "
            "WHERE source = ? AND target = ?",
            ("[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]", a, b),
        )
    project = open_project(tmp_path / "project")
    config = RunConfig(workers=2, mode="exhaustive", histograms=True)
    report = run_project(project, config, echo=lambda _: None)
    assert report.pairs_done == 0 and report.relays_tried > 0 and report.relays_kept >= 1
    after = {(q["source"], q["target"]): q for q in project.scored_pairs()}
    back = after[a, b]
    assert back["valid"] and back["probability"] > 0.5, back["reason"]
    assert rotation_error_deg(true_transform(truth, a, b), back["T_target_source"]) < 1.0
    assert translation_error_mm(true_transform(truth, a, b), back["T_target_source"]) < 0.3
    # asked for histograms, the relay measured the paper's at its pose (relays that cannot be kept measure
    # none); the pairs already done are not scored again for it
    settings = default_scorer().settings
    assert np.isclose(back["histogram"].sum() * settings.max_distance_mm / settings.bins, 1.0, atol=1e-3)
    assert sum(q["histogram"] is not None for q in after.values()) == report.relays_kept
    for key, q in after.items():
        if die[key[0]] != die[key[1]]:
            assert q["probability"] < 0.5 or p[key] >= 0.5, key
    tried = project.relay_counts(project.current_params())[0]
    again = run_project(open_project(tmp_path / "project"), RunConfig(workers=2), echo=lambda _: None)
    assert project.relay_counts(project.current_params())[0] == tried + again.relays_tried


def test_a_relay_replaces_its_pair_only_where_it_raises_the_odds_clearly(hoard, tmp_path) -> None:
    """A pair at 0.2: a relay at 0.25 (log-odds +0.29, the spread of registering one pose again) is
    recorded and not kept; one at 0.6 (+1.79) replaces the pair's figures; a refused pair (0) takes any
    relay that scores it."""
    from coindie.project import init_project
    from coindie.project.relay import MIN_GAIN

    project, _ = init_project(tmp_path / "project", hoard)
    run = project.start_run("h", "{}", "test", 0, "here")
    project.plan_pairs("h", "D", "exhaustive", run, [("L0001D", "L0002D"), ("L0001D", "L0003D")])
    done = {"status": "done", "method": "relief", "valid": True, "reason": "", "T_target_source": "[]",
            "histogram": b"", "features": b""}  # fmt: skip
    project.commit_pairs(
        "h", run,
        [
            {**done, "source": "L0001D", "target": "L0002D", "probability": 0.2},
            {**done, "source": "L0001D", "target": "L0003D", "probability": 0.0, "valid": False},
        ],
        0.0,
    )  # fmt: skip

    def relay(target: str, via: str, p: float) -> dict:
        return {**done, "source": "L0001D", "target": target, "via": via, "probability": p, "timings": "{}"}

    kept = project.commit_relays(
        "h", run, [relay("L0002D", "L0004D", 0.25), relay("L0003D", "L0004D", 0.01)], MIN_GAIN
    )
    assert kept == 1
    assert project.commit_relays("h", run, [relay("L0002D", "L0005D", 0.6)], MIN_GAIN) == 1
    probability = {(p["source"], p["target"]): p["probability"] for p in project.scored_pairs("h")}
    assert probability == {("L0001D", "L0002D"): 0.6, ("L0001D", "L0003D"): 0.01}
    assert project.relay_counts("h") == (3, 2)
