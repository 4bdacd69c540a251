"""Candidate search: propose the few likely same-die partners of every face, so that a big hoard does
not need every pair registered.

Per face, a global descriptor of its relief that does not change when the coin is turned or moved
(:mod:`coindie.candidates.descriptor`); per side, an index of the descriptors that returns each face's K
nearest neighbours (:mod:`coindie.candidates.index`, faiss); the union of those links is the set of pairs
that get full registration. :mod:`coindie.candidates.recall` measures what the search keeps on a hoard
with known dies.
"""

from coindie.candidates.descriptor import DESCRIPTOR_VERSION, DescriptorSettings, relief_descriptor
from coindie.candidates.index import candidate_pairs, nearest_neighbours
from coindie.candidates.recall import CandidateRecall, candidate_recall

__all__ = [
    "DESCRIPTOR_VERSION",
    "CandidateRecall",
    "DescriptorSettings",
    "candidate_pairs",
    "candidate_recall",
    "nearest_neighbours",
    "relief_descriptor",
]
