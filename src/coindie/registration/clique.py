"""Maximum clique of a consistency graph, with work and time limits (TEASER++'s pruning step).

Written by hand: TEASER++ (whose parallel maximum-clique solver this replaces) has no installable wheel,
networkx's and igraph's clique searches have no time limit (igraph did not finish in 10 minutes on a
2,000-vertex consistency graph of coin matches), and a registration must return in bounded time.

The search follows the usual recipe: k-core numbers bound the clique size (a vertex of an (s+1)-clique has
core number >= s); a greedy clique grown from high-core vertices gives a lower bound that prunes the graph;
an exact branch and bound with greedy-colouring bounds (Tomita's MCQ) on bitsets (Python integers) finishes
the job, or stops at a work or time limit and keeps the best clique found. Work is counted in vertex
colourings (0.4–1 million a second here): a work limit stops at the same point on every machine, so results
are reproducible; the time limit is a safety net.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.spatial.distance import pdist, squareform

from coindie.arrays import FloatArray, IntArray

BoolMatrix = NDArray[np.bool_]

#: Greedy cliques are grown from at most this many start vertices (the highest core numbers).
_GREEDY_STARTS = 8
#: The clock is read every this many search nodes.
_CLOCK_EVERY = 256


@dataclass(frozen=True)
class CliqueResult:
    members: IntArray  # sorted vertex indices
    stop: str  # "optimal", "work limit" or "time limit"
    nodes: int  # branch-and-bound nodes visited
    work: int  # vertex colourings done (the work measure of the limit)

    @property
    def exact(self) -> bool:
        return self.stop == "optimal"


def consistency_graph(src: FloatArray, dst: FloatArray, bound: float) -> BoolMatrix:
    """Adjacency of correspondences i, j whose pairwise distances agree: |‖dst_i-dst_j‖ - ‖src_i-src_j‖| <=
    bound (rigid maps keep distances, so two correct matches always agree within twice the noise)."""
    if len(src) < 2:
        return np.zeros((len(src), len(src)), dtype=bool)
    agree = np.abs(pdist(dst) - pdist(src)) <= bound
    return squareform(agree)


def core_numbers(adjacency: BoolMatrix) -> IntArray:
    """The k-core number of every vertex, by peeling all vertices of degree <= k at once."""
    degree = adjacency.sum(axis=1).astype(np.int64)
    core = np.zeros(len(degree), dtype=np.int64)
    remaining = np.ones(len(degree), dtype=bool)
    k = 0
    while remaining.any():
        k = max(k, int(degree[remaining].min()))
        batch = remaining & (degree <= k)
        while batch.any():
            core[batch] = k
            remaining &= ~batch
            degree -= adjacency[batch].sum(axis=0)
            batch = remaining & (degree <= k)
    return core


def greedy_clique(adjacency: BoolMatrix, core: IntArray) -> IntArray:
    """A large clique: from each of the highest-core vertices, repeatedly add the candidate (a vertex
    adjacent to all members) with the most neighbours among the candidates; the largest of these."""
    best = np.zeros(0, dtype=np.int64)
    for v in np.argsort(-core, kind="stable")[:_GREEDY_STARTS]:
        if core[v] + 1 <= len(best):
            break
        if v in best:  # would mostly grow the same clique again
            continue
        members = _grow(adjacency, int(v), np.flatnonzero(adjacency[v] & (core >= len(best))))
        if len(members) > len(best):
            best = members
    return np.sort(best)


def _grow(adjacency: BoolMatrix, start: int, candidates: IntArray) -> IntArray:
    members = [start]
    degree = adjacency[np.ix_(candidates, candidates)].sum(axis=1)
    while len(candidates):
        u = int(candidates[np.argmax(degree)])
        members.append(u)
        keep = adjacency[u, candidates]
        removed = candidates[~keep]
        candidates = candidates[keep]
        # Degrees among the candidates, updated for the ones that left (cheaper than recounting).
        degree = degree[keep] - adjacency[np.ix_(candidates, removed)].sum(axis=1)
    return np.array(members, dtype=np.int64)


def maximum_clique(adjacency: BoolMatrix, *, time_limit: float, work_limit: int) -> CliqueResult:
    """A maximum clique (``stop == "optimal"``) or the largest found within the limits."""
    if len(adjacency) == 0:
        return CliqueResult(np.zeros(0, dtype=np.int64), "optimal", 0, 0)
    core = core_numbers(adjacency)
    best = greedy_clique(adjacency, core)
    # Only vertices with core number >= |best| can belong to a larger clique.
    pool = np.flatnonzero(core >= len(best))
    if len(pool) <= len(best) or core.max() + 1 <= len(best):
        return CliqueResult(best, "optimal", 0, 0)
    search = _BranchAndBound(adjacency, pool, len(best), time_limit, work_limit)
    found, stop = search.run()
    members = best if found is None else np.sort(found)
    return CliqueResult(members, stop, search.nodes, search.work)


class _BranchAndBound:
    """Tomita & Seki's MCQ on bitsets, iterative (cliques may be deeper than Python's recursion limit)."""

    def __init__(self, adjacency: BoolMatrix, pool: IntArray, best_size: int, time_limit: float, limit: int):
        # Relabel the pool by decreasing degree: colouring in that order gives tighter bounds.
        sub = adjacency[np.ix_(pool, pool)]
        order = np.argsort(-sub.sum(axis=1), kind="stable")
        self.labels = pool[order]
        self.neighbours = _bitsets(sub[np.ix_(order, order)])
        self.best_size = best_size
        self.best: list[int] | None = None
        self.deadline = time.perf_counter() + time_limit
        self.work_limit = limit
        self.nodes = 0
        self.work = 0

    def run(self) -> tuple[IntArray | None, str]:
        everything = (1 << len(self.neighbours)) - 1
        stack = [_Frame([], everything, *self._colour(everything))]
        while stack:
            frame = stack[-1]
            if not frame.order or len(frame.clique) + frame.colours[-1] <= self.best_size:
                stack.pop()
                continue
            stop = self._visit(frame, stack)
            if stop:
                return self._found(), stop
        return self._found(), "optimal"

    def _visit(self, frame: _Frame, stack: list[_Frame]) -> str:
        v = frame.order.pop()
        frame.colours.pop()
        candidates = frame.candidates & self.neighbours[v]
        frame.candidates &= ~(1 << v)
        clique = [*frame.clique, v]
        if candidates:
            stack.append(_Frame(clique, candidates, *self._colour(candidates)))
        elif len(clique) > self.best_size:
            self.best, self.best_size = clique, len(clique)
        self.nodes += 1
        if self.work >= self.work_limit:
            return "work limit"
        if self.nodes % _CLOCK_EVERY == 0 and time.perf_counter() > self.deadline:
            return "time limit"
        return ""

    def _colour(self, candidates: int) -> tuple[list[int], list[int]]:
        """Greedy sequential colouring; vertices listed by increasing colour (the bound of each branch)."""
        order: list[int] = []
        colours: list[int] = []
        uncoloured, colour = candidates, 0
        self.work += candidates.bit_count()
        while uncoloured:
            colour += 1
            free = uncoloured
            while free:
                lowest = free & -free
                v = lowest.bit_length() - 1
                free &= ~lowest & ~self.neighbours[v]
                uncoloured &= ~lowest
                order.append(v)
                colours.append(colour)
        return order, colours

    def _found(self) -> IntArray | None:
        return None if self.best is None else self.labels[np.array(self.best, dtype=np.int64)]


@dataclass
class _Frame:
    clique: list[int]
    candidates: int
    order: list[int]
    colours: list[int]


def _bitsets(adjacency: BoolMatrix) -> list[int]:
    """Row i as a Python integer whose bit j is set when i and j are adjacent."""
    packed = np.packbits(adjacency, axis=1, bitorder="little")
    return [int.from_bytes(row.tobytes(), "little") for row in packed]
