"""Caches are objects sized by their constructor, passed down explicitly: no module global is patched."""

from __future__ import annotations

import json
import pickle

import pytest

from coindie.caches import LRUCache
from coindie.errors import ParameterError
from coindie.project.workers import _Worker
from coindie.registration import base as registration_base
from coindie.registration import get_method
from coindie.similarity import histogram
from coindie.similarity.scorers import default_scorer


def test_lru_cache_keeps_the_most_recently_used() -> None:
    cache: LRUCache[str, int] = LRUCache(2)
    computed: list[str] = []

    def value(key: str) -> int:
        return cache.get(key, lambda: computed.append(key) or len(computed))

    assert [value("a"), value("b"), value("a"), value("c")] == [1, 2, 1, 3]  # c drops b, not a
    assert value("a") == 1 and value("b") == 4
    assert computed == ["a", "b", "c", "b"] and len(cache) == 2
    with pytest.raises(ParameterError, match="'size'"):
        LRUCache(0)


def test_a_pipeline_and_its_cache_pickle() -> None:
    cache: LRUCache[str, int] = LRUCache(3)
    cache.get("a", lambda: 1)
    copy = pickle.loads(pickle.dumps(cache))
    assert copy.size == 3 and copy.get("a", lambda: 2) == 1
    assert pickle.loads(pickle.dumps(get_method("icp", cloud_cache_size=5)))._clouds.size == 5


def test_get_method_builds_its_cloud_cache_of_the_size_asked() -> None:
    assert get_method("icp")._clouds.size == registration_base.CLOUD_CACHE_SIZE
    assert get_method("icp", cloud_cache_size=30)._clouds.size == 30


def test_worker_sizes_its_own_caches_for_the_batch() -> None:
    config = {
        "method": "icp",
        "method_params": {},
        "registration_grid_mm": 0.1,
        "classifier": default_scorer().to_dict(),
    }
    before = (registration_base.CLOUD_CACHE_SIZE, histogram.FACE_CACHE_SIZE)
    worker = _Worker()
    worker.configure(json.dumps(config), cache_faces=40)
    assert worker.registrar is not None and worker.registrar.inner._clouds.size == 42
    assert worker.sampled_faces is not None and worker.sampled_faces.size == 84
    assert (registration_base.CLOUD_CACHE_SIZE, histogram.FACE_CACHE_SIZE) == before
