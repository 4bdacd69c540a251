"""Relays: a pair registered again from a pose composed through a third face.

A pair of faces of one die can fail where each of them registers well with a third face of that die: a
worn, bent or half-struck face shares too little relief with one face for the global search to find the
pose, but the two poses through the third face compose into a start the local refinement (the ICP and the
block matching, :meth:`coindie.registration.base.Pipeline.register` with ``T_init``) brings home. This is
the loop closure of SLAM, and the "die chains" a numismatist follows by hand: if a is linked to c and c to
b, look at a against b again, placed as c says.

Which pairs (:func:`plan_relays`, a pure function of one side's scored pairs):

- each face's ``neighbours`` best partners by probability form a nearest-neighbour graph;
- a pair (a, b) is tried through c when c is a neighbour of both, or a and b are both neighbours of c,
  and both links through c score higher than the pair itself (a relay can only help a pair that its
  own registration scored lower than the chain through c);
- at most ``per_pair`` relays per pair (the strongest chains, by their weaker link), each (pair, via)
  once per parameter set (the project's ``relays`` table records every attempt).

The pair keeps the relay's result only where it scores clearly higher than its own, its log-odds raised
by more than :data:`MIN_GAIN` (:meth:`coindie.project.store.Project.commit_relays`): a wrong start that
the refinement cannot mend scores lower and changes nothing. Rounds repeat this on the updated scores,
so chains longer than two links close in turn.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

#: Partners per face in the nearest-neighbour graph (hard-1 of benchmarks/outsider_hoards.py: 3 and 4
#: tried, BENCHMARK.md "Relays").
DEFAULT_NEIGHBOURS = 4
#: Rounds of relays: each runs on the scores the last one left.
DEFAULT_ROUNDS = 3
#: Relays tried per pair and round, the strongest chains first.
PER_PAIR = 2
#: A relay replaces its pair's result only where it raises the pair's log-odds by more than this: less is
#: the spread of registering one pose again from a nearby start (on four hoards the relays that raised
#: pairs of two dies raised them by 0.5-0.8 in the median), and keeping the best of such draws would lift
#: the hoard's different-die population unevenly. BENCHMARK.md, "Relays, and the veto asked again".
MIN_GAIN = 1.0


def log_odds_gain(before: float, after: float) -> float:
    """``logit(after) - logit(before)``, probabilities clipped to [1e-12, 1 - 1e-12] (a refused pair is 0)."""
    a, b = np.clip([after, before], 1e-12, 1.0 - 1e-12)
    return float(np.log(a / (1.0 - a)) - np.log(b / (1.0 - b)))


@dataclass(frozen=True)
class Relay:
    """Register ``source`` onto ``target`` again from ``T_target_source``, composed through ``via``;
    ``before`` is the pair's probability now, ``chain`` the weaker link's."""

    source: str
    target: str
    via: str
    T_target_source: FloatArray
    before: float
    chain: float


def plan_relays(
    pairs: Iterable[Mapping[str, Any]],
    neighbours: int = DEFAULT_NEIGHBOURS,
    tried: set[tuple[str, str, str]] | None = None,
    per_pair: int = PER_PAIR,
) -> list[Relay]:
    """The relays worth trying among one side's done pairs (dictionaries with ``source``, ``target``,
    ``probability``, ``T_target_source`` and ``scored``: whether the pose is usable), skipping the
    ``(source, target, via)`` already ``tried``; sorted by pair, strongest chain first."""
    tried = tried or set()
    probability: dict[frozenset[str], float] = {}
    pose: dict[tuple[str, str], FloatArray] = {}  # (to, from) -> T_to_from
    source_of: dict[frozenset[str], str] = {}  # the direction each pair was planned (and is stored) in
    for pair in pairs:
        a, b = str(pair["source"]), str(pair["target"])
        probability[frozenset((a, b))] = float(pair["probability"] or 0.0)
        source_of[frozenset((a, b))] = a
        if pair["scored"] and pair.get("T_target_source") is not None:
            T_b_a = np.asarray(pair["T_target_source"], dtype=np.float64)
            pose[b, a] = T_b_a
            pose[a, b] = np.linalg.inv(T_b_a)
    if neighbours < 1 or not pose:
        return []
    partners: dict[str, list[tuple[float, str]]] = {}
    for to, frm in pose:
        partners.setdefault(frm, []).append((probability[frozenset((to, frm))], to))
    nearest = {
        face: {other for _, other in sorted(found, key=lambda x: (-x[0], x[1]))[:neighbours]}
        for face, found in partners.items()
    }
    chosen_by: dict[str, set[str]] = {}  # c -> the faces having c among their neighbours
    for face, near in nearest.items():
        for c in near:
            chosen_by.setdefault(c, set()).add(face)
    vias: dict[tuple[str, str], set[str]] = {}
    for c in nearest:
        # a and b both neighbours of c, or c a neighbour of both
        for group in (nearest[c], chosen_by.get(c, set())):
            ordered = sorted(group)
            for i, a in enumerate(ordered):
                for b in ordered[i + 1 :]:
                    vias.setdefault((a, b), set()).add(c)
    relays = []
    for (a, b), through in sorted(vias.items()):
        key = frozenset((a, b))
        if key not in source_of:
            continue  # not a planned pair (candidate mode)
        source = source_of[key]
        target = b if source == a else a
        before = probability[key]
        chains = []
        for c in through:
            if (c, source) not in pose or (target, c) not in pose:
                continue
            chain = min(probability[frozenset((source, c))], probability[frozenset((c, target))])
            if chain > before and (source, target, c) not in tried:
                chains.append((chain, c))
        for chain, c in sorted(chains, key=lambda x: (-x[0], x[1]))[:per_pair]:
            T_target_source = pose[target, c] @ pose[c, source]
            relays.append(Relay(source, target, c, T_target_source, before, chain))
    return relays
