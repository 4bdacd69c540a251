"""The K nearest faces of every face by descriptor, with faiss, and the candidate pairs they make.

Descriptors are standardised per dimension over the faces searched together (one side of one hoard), then
L2-normalised, so that the inner product is a cosine similarity. Up to ``EXACT_BELOW`` faces the search is
exact (``IndexFlatIP``: n^2 d multiply-adds, a fraction of a second for 10,000 faces); above it an HNSW
graph (``IndexHNSWFlat``) answers in O(n log n).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import IntArray
from coindie.errors import ParameterError

#: Faces up to which the exact index is used.
EXACT_BELOW = 20_000
#: HNSW parameters: links per node, and breadth of the search at build and query time.
HNSW_M = 32
HNSW_EF_CONSTRUCTION = 200
HNSW_EF_SEARCH = 256


def normalised(descriptors: NDArray[np.floating]) -> NDArray[np.float32]:
    """Standardised per dimension (constant dimensions left at 0), then unit length per row."""
    X = np.asarray(descriptors, dtype=np.float64)
    if X.ndim != 2 or len(X) == 0:
        raise ParameterError(f"descriptors must be a non-empty (n, d) array, got shape {X.shape}")
    std = X.std(axis=0)
    X = (X - X.mean(axis=0)) / np.where(std > 0, std, 1.0)
    norms = np.linalg.norm(X, axis=1, keepdims=True)
    return np.ascontiguousarray(X / np.where(norms > 0, norms, 1.0), dtype=np.float32)


def nearest_neighbours(
    descriptors: NDArray[np.floating], k: int, *, exact_below: int = EXACT_BELOW
) -> tuple[IntArray, NDArray[np.float32]]:
    """(neighbours, similarities), each (n, min(k, n - 1)): row i lists the faces most like face i,
    best first, face i itself left out."""
    import faiss

    if k < 1:
        raise ParameterError(f"k must be >= 1, got {k}")
    X = normalised(descriptors)
    n, d = X.shape
    k = min(k, n - 1)
    if k == 0:
        return np.empty((n, 0), dtype=np.int64), np.empty((n, 0), dtype=np.float32)
    if n <= exact_below:
        index = faiss.IndexFlatIP(d)
    else:
        index = faiss.IndexHNSWFlat(d, HNSW_M, faiss.METRIC_INNER_PRODUCT)
        index.hnsw.efConstruction = HNSW_EF_CONSTRUCTION
        index.hnsw.efSearch = max(HNSW_EF_SEARCH, 2 * k)
    index.add(X)
    similarities, found = index.search(X, k + 1)
    return _without_self(found.astype(np.int64), similarities, k)


def _without_self(
    found: IntArray, similarities: NDArray[np.float32], k: int
) -> tuple[IntArray, NDArray[np.float32]]:
    """Drop each row's own index (usually first, but ties may put it elsewhere) and faiss's -1 fillers."""
    n = len(found)
    out = np.full((n, k), -1, dtype=np.int64)
    out_similarity = np.full((n, k), -np.inf, dtype=np.float32)
    for i in range(n):
        keep = (found[i] != i) & (found[i] >= 0)
        row, sim = found[i][keep][:k], similarities[i][keep][:k]
        out[i, : len(row)], out_similarity[i, : len(row)] = row, sim
    return out, out_similarity


def candidate_pairs(neighbours: IntArray) -> set[tuple[int, int]]:
    """The undirected pairs (i < j) linked by the neighbour lists (a link either way is enough)."""
    pairs = set()
    for i, row in enumerate(neighbours):
        for j in row[row >= 0]:
            pairs.add((min(i, int(j)), max(i, int(j))))
    return pairs
