"""Same-die similarity of two registered faces (Riedones3D, section 3.2.2).

>>> from coindie.similarity import score_pair, SameDieClassifier, HistogramSettings
>>> score = score_pair(source_scan, target_scan)  # doctest: +SKIP  (relief + the shipped classifier)
>>> score.probability, score.valid, score.histogram.shape  # doctest: +SKIP
"""

from coindie.similarity.classifier import ClassifierError, SameDieClassifier
from coindie.similarity.histogram import (
    HistogramSettings,
    c2c_distances,
    c2c_histogram,
    density_histogram,
    main_normal,
)
from coindie.similarity.score import PairScore, add_histogram, measure_pair, score_pair

__all__ = [
    "ClassifierError",
    "HistogramSettings",
    "PairScore",
    "SameDieClassifier",
    "add_histogram",
    "c2c_distances",
    "c2c_histogram",
    "density_histogram",
    "main_normal",
    "measure_pair",
    "score_pair",
]
