"""The registration interface: one protocol, one result type, a registry of methods built by name.

``get_method("fpfh+teaser+icp", noise_bound=0.3).register(source, target)`` returns a
:class:`RegistrationResult` whose ``T_target_source`` maps source points onto the target (4x4, mm). Every
method runs the same frame (:class:`Pipeline`): inputs are checked and put in a canonical order, the method
estimates a transform, and the pose is scored on the full clouds and accepted or not with a reason.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field, fields, is_dataclass
from typing import Any, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coindie.arrays import FloatArray
from coindie.caches import LRUCache
from coindie.errors import ParameterError
from coindie.params import Configurable, Param
from coindie.registration.clouds import Cloud, as_scan, content_key
from coindie.registration.quality import Acceptance, alignment
from coindie.scan import Scan


@dataclass(frozen=True)
class Matches:
    """Matched point pairs: ``source[i]`` (source frame) corresponds to ``target[i]`` (target frame)."""

    source: FloatArray
    target: FloatArray

    def __len__(self) -> int:
        return len(self.source)

    def subset(self, index: ArrayLike) -> Matches:
        return Matches(self.source[index], self.target[index])


@dataclass(frozen=True)
class Estimate:
    """What a method found before scoring: a transform (None when it found none) and its evidence."""

    T_target_source: FloatArray | None
    n_correspondences: int = 0
    n_inliers: int = 0
    inliers: Matches | None = None
    failure: str = ""
    notes: tuple[str, ...] = ()


@dataclass(frozen=True)
class RegistrationResult:
    """The outcome of registering a source scan onto a target scan.

    ``valid`` is False with a ``reason`` when the method found no transform or the transform does not
    align the clouds (see :class:`~coindie.registration.quality.Acceptance`); ``T_target_source`` is then
    the method's best guess (identity when it had none), never to be used silently.
    """

    T_target_source: FloatArray
    valid: bool
    method: str
    params: dict[str, Any]
    fitness: float
    inlier_rmse: float
    residual: float
    n_correspondences: int
    n_inliers: int
    timings: dict[str, float]
    reason: str = ""
    notes: tuple[str, ...] = ()
    inliers: Matches | None = field(default=None, repr=False)

    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready dictionary (the transform as a list of rows)."""
        return {
            "method": self.method,
            "valid": self.valid,
            "reason": self.reason,
            "T_target_source": self.T_target_source.tolist(),
            "fitness": self.fitness,
            "inlier_rmse": _finite_or_none(self.inlier_rmse),
            "residual": _finite_or_none(self.residual),
            "n_correspondences": self.n_correspondences,
            "n_inliers": self.n_inliers,
            "timings": self.timings,
            "notes": list(self.notes),
            "params": self.params,
        }


def _finite_or_none(x: float) -> float | None:
    return x if np.isfinite(x) else None


@dataclass(frozen=True)
class SolverOutcome:
    """What a robust solver makes of matched points: a transform (None on failure), which matches it
    keeps as inliers, and why it failed."""

    T_target_source: FloatArray | None
    inliers: NDArray[np.bool_]
    failure: str = ""
    notes: tuple[str, ...] = ()


class CorrespondenceSolver(Protocol):
    """A robust estimator of the rigid transform from putative matches (many of them wrong)."""

    def solve(self, matches: Matches) -> SolverOutcome: ...


class Registrar(Protocol):
    """Anything that registers a source scan onto a target scan."""

    name: str

    def register(self, source: Scan, target: Scan) -> RegistrationResult: ...


class Timer:
    """Seconds per named stage (a stage entered twice adds up)."""

    def __init__(self) -> None:
        self.seconds: dict[str, float] = {}

    @contextmanager
    def __call__(self, stage: str) -> Iterator[None]:
        start = time.perf_counter()
        try:
            yield
        finally:
            self.seconds[stage] = self.seconds.get(stage, 0.0) + time.perf_counter() - start


class Estimator(Protocol):
    """The method-specific step of a pipeline."""

    def estimate(self, source: Cloud, target: Cloud, timer: Timer) -> Estimate: ...


#: Faces a pipeline keeps ready (canonical order, normals, search tree): ~5 MB each at 50k points.
CLOUD_CACHE_SIZE = 8


class Pipeline:
    """A registrar: checks inputs, runs an estimator, scores and accepts its transform.

    Built by :func:`get_method` for registered methods, or directly from parts, e.g.
    ``Pipeline("mine", Refined(FeatureRegistration(FPFH(), MutualNN(), TeaserSolver()), PatchICP()))``;
    the parameters recorded with each result are then collected from the parts.
    """

    def __init__(
        self,
        name: str,
        estimator: Estimator,
        check: Acceptance | None = None,
        params: dict[str, Any] | None = None,
        *,
        cloud_cache_size: int = CLOUD_CACHE_SIZE,
    ) -> None:
        self.name = name
        self.estimator = estimator
        self.check = Acceptance() if check is None else check
        self.params = collect_params(estimator, self.check) if params is None else params
        self._clouds: LRUCache[bytes, Cloud] = LRUCache(cloud_cache_size)

    def _cloud(self, scan: Scan) -> Cloud:
        """The scan as a Cloud in canonical order (a permutation of the input points cannot change the
        result), from a small cache: in an all-pairs study each face comes back many times, and its
        order, normals and search tree are then reused."""
        key = content_key(scan.points, scan.normals if scan.normals is not None else np.empty(0))
        return self._clouds.get(key, lambda: Cloud.canonical(scan, key))

    @property
    def refines_from_pose(self) -> bool:
        """Whether ``register`` can start from a given pose (the estimator has ``estimate_from``)."""
        return hasattr(self.estimator, "estimate_from")

    def register(
        self, source: Scan | ArrayLike, target: Scan | ArrayLike, *, T_init: FloatArray | None = None
    ) -> RegistrationResult:
        """Register ``source`` onto ``target`` (Scans, or (N, 3) arrays in mm); from the pose ``T_init``
        (T_target_source) instead of the method's own global step when it is given, which only methods
        that :attr:`refines_from_pose` accept.

        Raises:
            InvalidScanError: a cloud is empty, has NaN coordinates, is not (N, 3) or has too few points.
        """
        start, timer = time.perf_counter(), Timer()
        with timer("prepare"):
            source_cloud = self._cloud(as_scan(source, "source"))
            target_cloud = self._cloud(as_scan(target, "target"))
        if T_init is None:
            estimate = self.estimator.estimate(source_cloud, target_cloud, timer)
        elif self.refines_from_pose:
            estimate = self.estimator.estimate_from(  # type: ignore[attr-defined]
                source_cloud, target_cloud, np.asarray(T_init, dtype=np.float64), timer
            )
        else:
            raise ParameterError(f"Method {self.name!r} cannot start from a given pose.")
        with timer("score"):
            T = np.eye(4) if estimate.T_target_source is None else estimate.T_target_source
            scored = source_cloud.points[:: -(-len(source_cloud.points) // self.check.max_points)]
            up = source_cloud.plane.up if self.check.overlap == "footprint" else None
            figures = alignment(scored, target_cloud, T, self.check.overlap_distance, source_up=up)
        reason = estimate.failure or self.check.judge(figures)
        timer.seconds["total"] = time.perf_counter() - start
        return RegistrationResult(
            T_target_source=T,
            valid=not reason,
            method=self.name,
            params=dict(self.params),
            fitness=figures.fitness,
            inlier_rmse=figures.inlier_rmse,
            residual=figures.residual,
            n_correspondences=estimate.n_correspondences,
            n_inliers=estimate.n_inliers,
            timings=timer.seconds,
            reason=reason,
            notes=estimate.notes,
            inliers=estimate.inliers,
        )


def collect_params(*parts: object) -> dict[str, Any]:
    """``part.param`` -> value of every Configurable among ``parts`` and, recursively, their dataclass
    fields."""
    found: dict[str, Any] = {}
    for part in parts:
        if isinstance(part, Configurable):
            found |= {f"{part.NAME}.{k}": v for k, v in part.values().items()}
        elif is_dataclass(part) and not isinstance(part, type):
            found |= collect_params(*(getattr(part, f.name) for f in fields(part)))
    return found


# ---------------------------------------------------------------------------------------------- registry

Factory = Callable[..., Estimator]


@dataclass(frozen=True)
class MethodInfo:
    """A registered method: its parts (each a Configurable whose NAME prefixes its parameters) and how
    to assemble them into an estimator."""

    name: str
    summary: str
    parts: tuple[type[Configurable], ...]
    factory: Factory
    local: bool = False  # True: only refines a start near the truth (see ``register_method``)

    def params(self) -> dict[str, Param]:
        """``part.param`` -> declaration, for every part (the acceptance check included)."""
        return {f"{part.NAME}.{name}": p for part in self._all_parts() for name, p in part.declared().items()}

    def _all_parts(self) -> tuple[type[Configurable], ...]:
        return (*self.parts, Acceptance)

    def build(self, params: Mapping[str, Any], *, cloud_cache_size: int = CLOUD_CACHE_SIZE) -> Pipeline:
        grouped = self._grouped(params)
        built = {part.NAME: part(**grouped.get(part.NAME, {})) for part in self._all_parts()}
        check = built.pop(Acceptance.NAME)
        assert isinstance(check, Acceptance)
        return Pipeline(
            self.name,
            self.factory(**built),
            check,
            collect_params(*built.values(), check),
            cloud_cache_size=cloud_cache_size,
        )

    def _grouped(self, params: Mapping[str, Any]) -> dict[str, dict[str, Any]]:
        grouped: dict[str, dict[str, Any]] = {}
        for key, value in params.items():
            part, name = self.resolve(key).split(".", 1)
            grouped.setdefault(part, {})[name] = value
        return grouped

    def resolve(self, key: str) -> str:
        """The full ``part.param`` name of a parameter given in full or by its short name when unique."""
        known = self.params()
        if key in known:
            return key
        matches = [full for full in known if full.split(".", 1)[1] == key]
        if len(matches) == 1:
            return matches[0]
        if matches:
            raise ParameterError(
                f"The parameter {key!r} of method {self.name!r} is ambiguous: "
                f"say one of {', '.join(matches)}."
            )
        raise ParameterError(
            f"Method {self.name!r} has no parameter {key!r}. Its parameters: {', '.join(known)}."
        )

    def parse(self, key: str, text: str) -> tuple[str, Any]:
        """A ``key=value`` given as text (command line), resolved and checked."""
        full = self.resolve(key)
        part, name = full.split(".", 1)
        return full, self.params()[full].parse(part, name, text)

    def for_coins(self, params: Mapping[str, Any], scale: float) -> dict[str, Any]:
        """``params`` for coins ``scale`` times the size the defaults were set for: each part's
        ``DESIGN_LENGTHS`` (pixels, bands, windows: the size of a die's details) that ``params`` leaves at
        its default, scaled; lengths the scanner sets (an ICP's reach) and those given, unchanged."""
        scaled = dict(params)
        if scale == 1.0:
            return scaled
        given = {self.resolve(key) for key in params}
        for part in self._all_parts():
            declared = part.declared()
            for name in getattr(part, "DESIGN_LENGTHS", ()):
                key = f"{part.NAME}.{name}"
                if key not in given:
                    scaled[key] = declared[name].default * scale
        return scaled

    def parse_items(self, items: Iterable[str], written: Callable[[str], str]) -> dict[str, Any]:
        """``key=value`` items as full parameter names and checked values (the command line's
        ``--param`` and the benchmarks' ``method[key=value;...]``); ``written(item)`` is the message of a
        ``ParameterError`` for an item that is not ``key=value``."""
        params = {}
        for item in items:
            key, equals, text = item.partition("=")
            if not equals or not key.strip():
                raise ParameterError(written(item))
            full, value = self.parse(key.strip(), text.strip())
            params[full] = value
        return params


_REGISTRY: dict[str, MethodInfo] = {}


def register_method(
    name: str, factory: Factory, *, parts: tuple[type[Configurable], ...], summary: str, local: bool = False
) -> None:
    """Register a method: ``factory(**{part.NAME: part_instance})`` returns its estimator. ``local``
    methods only refine a nearby start (they are not expected to recover large rotations): to start one
    from a guess ``T0``, register ``source.transformed(T0)`` and compose the result with ``T0``."""
    names = [part.NAME for part in parts]
    if len(set(names)) != len(names) or Acceptance.NAME in names:
        raise ValueError(f"parts of {name!r} need distinct names other than 'check': {names}")
    _REGISTRY[name] = MethodInfo(name, summary, parts, factory, local)


def get_method(name: str, *, cloud_cache_size: int = CLOUD_CACHE_SIZE, **params: Any) -> Pipeline:
    """The registered method ``name`` built with ``params`` (``part.param`` or unique short names); its
    pipeline keeps the prepared clouds of the last ``cloud_cache_size`` faces."""
    return method_info(name).build(params, cloud_cache_size=cloud_cache_size)


def method_info(name: str) -> MethodInfo:
    if name not in _REGISTRY:
        raise ParameterError(f"Unknown registration method {name!r}. Known methods: {', '.join(_REGISTRY)}.")
    return _REGISTRY[name]


def list_methods() -> list[str]:
    """The names of the registered methods, in registration order."""
    return list(_REGISTRY)
