"""``relief``: our registration method, built on what coins are — nearly flat reliefs.

Per face, once (cached by content):
    1. the canonical frame: the face's best-fit plane is z = 0, relief up (robust to the edge wall);
    2. the relief as an image on a square grid centred on the frame's origin, heights above the best-fit
       quadric (cupping removed), high-passed, its footprint shrunk by a margin (no edge wall, no outline);
    3. the polar log-spectrum of that image (for the rotation search) and a sample of relief points
       (for the ICP).
Per pair:
    4. planar alignment (:mod:`coindie.registration.relief_search`): every turn about z (8° apart, the best
       refined) and every translation scored by masked normalised cross-correlation in batches of FFTs —
       a global search, where random-search ICP tries starts one by one;
    5. the 2-D result lifted to 3-D through both canonical frames;
    6. point-to-plane ICP on the relief points refines the remaining tilt, height and sub-pixel offsets;
       its pose is kept only if it does not lower the relief images' correlation, and its last stage
       runs only if the first stages have not already lowered it (``icp_early_refusal``);
    7. block matching of the two reliefs at finer pixels (:mod:`coindie.registration.relief_blocks`) moves
       the pose in the target's plane where the die's elements agree window by window, where it moves it by
       more than a pixel (on worn, crusted, bent or cupped coins the search and the ICP leave it a degree or
       a few tenths of a millimetre off; within a pixel the ICP sees further).

The correlation score of step 4 is kept in the result's notes: it is a die-similarity cue in itself.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from scipy import ndimage

from coindie.arrays import BoolArray, FloatArray, IntArray
from coindie.params import Configurable, param
from coindie.preprocess.canonical import CanonicalFrame, canonical_frame
from coindie.preprocess.heightmap import height_map
from coindie.registration.base import Estimate, Timer
from coindie.registration.clouds import Cloud
from coindie.registration.icp import MIN_CORRESPONDENCES, IcpOutcome, point_to_plane_icp
from coindie.registration.projective import ProjectedCloud
from coindie.registration.relief_blocks import REACH_MM, FineRelief, refine_planar
from coindie.registration.relief_search import PlanarAlignment, ReliefImage, align_reliefs, pose_score
from coindie.scan import Scan
from coindie.transforms import transform_points

#: Points of the relief whose normal is within this angle of the face's up direction (the edge wall and
#: steep flaws are left out of the ICP).
_RELIEF_MAX_NORMAL_ANGLE_DEG = 60.0


@dataclass(frozen=True, kw_only=True)
class ReliefSearch(Configurable):
    """The global step: relief images and their FFT correlation."""

    NAME = "relief"
    #: The lengths set by the size of a die's details, for coins of about 21 mm (``MethodInfo.for_coins``).
    DESIGN_LENGTHS: ClassVar[tuple[str, ...]] = ("pixel", "field_size", "high_pass", "margin")

    pixel: float = param(
        0.2, unit="mm", low=0.02, high=1.0, doc="pixel of the relief images (the ICP refines below it)"
    )
    field_size: float = param(
        32.0, unit="mm", low=5.0, high=200.0, doc="side of the square relief image (larger faces are cropped)"
    )
    # 0.4 mm, not 0.8: with a wider band the bust and the other large elements of the design, whose shape
    # wear, weak strikes and a coarse scanner change from coin to coin, outweigh the die's fine details in
    # the turn sweep, and a wrong turn of a worn or coarsely scanned pair outscores the right one. Planar
    # poses within 5 degrees and 1 mm of the truth: 0.856 -> 0.938 of 160 same-die pairs of four held-out
    # hoards of the independent generator, 0.927 -> 0.940 of 150 of coindie's (BENCHMARK.md, "A finer band
    # for the turn sweep").
    high_pass: float = param(
        0.4, unit="mm", low=0, low_open=True, doc="relief detail: heights minus their Gaussian blur (sigma)"
    )
    margin: float = param(
        0.6, unit="mm", low=0, doc="band inside the flan outline left out (edge wall, flan border)"
    )
    # Off by default. On 120 same-die pairs of each of three all-hard hoards, one of each generator (blind
    # hard-33, outsider hard-33, coindie's hard 5001; `coindie bench registration`), clipping at 3 put
    # more poses within 2 degrees (0.492 -> 0.542, 0.742 -> 0.792, 0.600 -> 0.633), but in the die
    # studies of the first two, relays and all, it did not (obverses 0.683 -> 0.695 and 0.826 -> 0.797)
    # and the outsider's FMI fell 0.961 -> 0.937 (BENCHMARK.md, "One element cannot carry a correlation").
    clip: float = param(
        0.0,
        low=0,
        doc="the relief detail clipped at this many robust standard deviations (1.4826 x its median "
        "absolute deviation) before any correlation, so that one strong element (a pellet, a crust, a "
        "pit) cannot carry the search; 0: not clipped",
    )
    angle_search: str = param(
        "exhaustive",
        choices=("exhaustive", "spectrum"),
        doc="how the rotation is found: every turn by angle_step scored at reduced resolution "
        "(exhaustive), or the peaks of the polar spectra's correlation (spectrum: faster, misses more "
        "where flans overlap in part or crusts, holes or double strikes fill the spectrum)",
    )
    angle_step: float = param(
        8.0, unit="deg", low=0.5, high=30.0, doc="turns tried by the exhaustive rotation search"
    )
    angle_peaks: int = param(
        4,
        low=1,
        high=8,
        doc="rotation candidates kept: the best turns of the exhaustive search (each tried again a "
        "third of a step to either side), or the spectrum's peaks (each with its 180° twin)",
    )
    coarse_step: int = param(
        2, low=1, high=4, doc="subsampling of the images to choose among angles (1 = full resolution)"
    )
    sweep_step: int = param(
        2,
        low=1,
        high=6,
        doc="subsampling of the images for the exhaustive search's sweep of every turn (its best turns "
        "are scored again at coarse_step); 3 takes a third off the planar search but moved the FMI of "
        "the all-hard hoards by -0.046 to +0.019 (BENCHMARK.md)",
    )
    frame_points: int = param(
        6000, low=100, doc="points (a regular subsample) that fit the canonical frame's plane and quadric"
    )
    icp_points: int = param(
        2000, low=100, doc="relief points of the source used by the ICP's first stages (last: final_points)"
    )
    icp_tolerance: float = param(
        0.02,
        low=0,
        high=2,
        doc="the ICP's pose is kept unless it lowers the relief images' correlation by more than this",
    )
    # Measured on 90 pairs (60 drawn among all, 30 of one die) of each of six synthetic hoards: with 0.05,
    # the last stage was skipped on 64-86 % of the pairs of three all-hard hoards, and the full ICP would
    # have kept its pose on 4 of their 270 pairs; on cupping:high, noise:high and riedones it was skipped on
    # 13-23 % and none would have been kept. Asking with icp_tolerance itself (0.02) changed 2-8 of 90.
    icp_early_refusal: float = param(
        0.05,
        low=0,
        high=2,
        doc="the ICP's last stage is not run, and its pose refused, when its first stages have already "
        "lowered the relief images' correlation by more than this (2: the last stage always runs)",
    )


@dataclass(frozen=True, kw_only=True)
class ReliefICP(Configurable):
    """The local step: point-to-plane ICP from the planar alignment, in two stages of shrinking reach.

    The planar alignment is within ~0.1 mm and ~0.5° of the truth; pairing points farther apart than
    that only lets the flan border and worn or weakly struck areas pull the pose (measured on synthetic
    hoards: a 0.3 mm reach doubles the error). The paper's 0.1 mm reach comes first, then a finer one.
    The last stage sets the pose's precision on a noisy or coarse scanner: with 2,000 source points,
    pairs of a 0.03 mm noise scanner registered at 2.4 times the error of FCGF + ICP on the same pairs
    (0.15 mm vertex spacing: 1.75 times); with 6,000, within 1.4 times on every row of the generalisation
    benchmark (BENCHMARK.md, "Registration on every row"). On the noisy scanner the last stage is still
    closing in when it stops (15 iterations, each a few per cent nearer the truth): stopping once an update
    is within its own standard error gave up half the gain. The relief features barely see the difference
    (pair AUC of the all-hard hoard of seed 3000, 0.865 and 0.936 by side; 0.863 and 0.938 with 2,000).
    """

    NAME = "icp"

    max_distance: float = param(
        0.1, unit="mm", low=0, low_open=True, doc="first stage: points pair within this distance (paper)"
    )
    final_distance: float = param(
        0.05, unit="mm", low=0, low_open=True, doc="second stage: points pair within this distance"
    )
    rescue_distance: float = param(
        0.3, unit="mm", low=0, low_open=True, doc="reach of a first stage run only when too few points pair"
    )
    correspondences: str = param(
        "mixed",
        choices=("mixed", "projective", "kdtree"),
        doc="how source points find target points: the point under them in the target's plane "
        "(projective), the nearest in 3-D (kdtree), or projective then kdtree for the last stage (mixed)",
    )
    pixel: float = param(
        0.05, unit="mm", low=0.01, high=1.0, doc="pixel of the target's image for projective correspondences"
    )
    final_points: int = param(
        6000,
        low=100,
        doc="relief points of the source used by the second stage (the first stages use the search's "
        "icp_points): on a noisy scanner, 6,000 halve the rotation error of 2,000",
    )
    max_iterations: int = param(15, low=1, doc="iterations at most, per stage")
    first_tolerance: float = param(
        1e-3, low=0, doc="the rescue and first stages stop when the update (rad and mm) is smaller (paper)"
    )
    tolerance: float = param(1e-4, low=0, doc="the second stage stops when the update is smaller")

    def run(
        self,
        source: FloatArray,
        target: Cloud,
        T_init: FloatArray,
        early: Cloud | None = None,
        final_source: FloatArray | None = None,
        worth_refining: Callable[[FloatArray], bool] | None = None,
    ) -> IcpOutcome:
        """Refine ``T_init``; a rescue stage first when under half of the points pair within reach.

        ``early``, when given, is searched instead of ``target`` by the rescue and first stages (a
        projective index of the target: cheaper, a little less exact than the last stage's search);
        ``final_source``, when given, are the points of the last stage (``source`` otherwise);
        ``worth_refining``, when given, is asked about the first stages' pose, and the last stage runs
        only when it says yes (the first stages' outcome is returned otherwise)."""
        T, early = T_init, target if early is None else early
        distances, _ = early.nearest(transform_points(T, source), self.max_distance)
        if np.isfinite(distances).mean() < 0.5:
            T = self._stage(source, early, T, self.rescue_distance, self.first_tolerance).T_target_source
        first = self._stage(source, early, T, self.max_distance, self.first_tolerance)
        if first.n_correspondences < MIN_CORRESPONDENCES:
            return first
        if worth_refining is not None and not worth_refining(first.T_target_source):
            return first
        last = early if self.correspondences == "projective" else target
        final = source if final_source is None else final_source
        second = self._stage(final, last, first.T_target_source, self.final_distance, self.tolerance)
        if second.n_correspondences < MIN_CORRESPONDENCES:
            return first
        return IcpOutcome(
            second.T_target_source,
            second.n_correspondences,
            first.iterations + second.iterations,
            second.converged,
        )

    def _stage(
        self, source: FloatArray, target: Cloud, T: FloatArray, reach: float, tolerance: float
    ) -> IcpOutcome:
        return point_to_plane_icp(
            source, target, T, max_iterations=self.max_iterations, max_distance=reach, tolerance=tolerance
        )


@dataclass(frozen=True, kw_only=True)
class ReliefBlocks(Configurable):
    """The last step: the pose in the plane refined by block matching of the two reliefs
    (:mod:`coindie.registration.relief_blocks`), coarse to fine down to ``pixel``."""

    NAME = "blocks"
    DESIGN_LENGTHS: ClassVar[tuple[str, ...]] = ("pixel", "high_pass", "window")

    pixel: float = param(
        0.1, unit="mm", low=0.0, low_open=True, high=1.0, doc="finest pixel of the block matching"
    )
    levels: int = param(3, low=0, high=5, doc="pyramid steps, each twice the pixel of the next (0: off)")
    high_pass: float = param(
        1.0, unit="mm", low=0, low_open=True, doc="relief detail matched: heights minus their Gaussian blur"
    )
    window: float = param(2.4, unit="mm", low=0.3, doc="side of the windows matched one by one")
    reach: int = param(
        2, low=1, high=8, doc="shifts tried per window, in pixels of each step, to either side"
    )
    iterations: int = param(2, low=1, high=10, doc="matchings per step at most")

    @property
    def steps(self) -> tuple[int, ...]:
        return tuple(2**k for k in range(self.levels))


@dataclass(eq=False)
class PreparedFace:
    """The per-face work of the method (see the module docstring, steps 1–3); the projective index is
    made the first time the face is a target."""

    frame: CanonicalFrame
    image: ReliefImage
    relief: BoolArray  # the relief points (not the wall) of the face's cloud
    fine: FineRelief | None = None  # for block matching (None when it is off)
    projected: ProjectedCloud | None = None

    def as_target(self, cloud: Cloud, icp: ReliefICP) -> Cloud:
        """The cloud the ICP's first stages search: the face's projective index, or the cloud itself."""
        if icp.correspondences == "kdtree":
            return cloud
        if self.projected is None:
            self.projected = ProjectedCloud.over_plane(
                cloud, self.frame.T_canonical_scan, self.relief, icp.pixel
            )
        return self.projected


@dataclass
class ReliefRegistration:
    """The ``relief`` estimator; it keeps the per-face work of the last ``cache_size`` faces."""

    search: ReliefSearch
    icp: ReliefICP
    blocks: ReliefBlocks = field(default_factory=ReliefBlocks)
    cache_size: int = 64
    _cache: OrderedDict[bytes, PreparedFace] = field(default_factory=OrderedDict, repr=False)

    def estimate(self, source: Cloud, target: Cloud, timer: Timer) -> Estimate:
        with timer("relief images"):
            prepared_source, prepared_target = self.prepare(source), self.prepare(target)
        with timer("planar search"):
            planar, T_init = self.planar_pose(prepared_source, prepared_target)
        found = f"relief correlation {planar.score:.3f} at {np.degrees(planar.angle_rad):.2f}°"
        return self._refined(source, target, prepared_source, prepared_target, T_init, found, timer)

    def estimate_from(self, source: Cloud, target: Cloud, T_init: FloatArray, timer: Timer) -> Estimate:
        """Steps 6-7 from a given pose instead of the planar search's (a pose composed through a third
        face, :mod:`coindie.project.relay`): the ICP, its pose check and the block matching."""
        with timer("relief images"):
            prepared_source, prepared_target = self.prepare(source), self.prepare(target)
        angle, _ = _planar_of(T_init, prepared_source.frame, prepared_target.frame)
        given = f"from a given pose at {np.degrees(angle):.2f}°"
        return self._refined(source, target, prepared_source, prepared_target, T_init, given, timer)

    def _refined(
        self,
        source: Cloud,
        target: Cloud,
        prepared_source: PreparedFace,
        prepared_target: PreparedFace,
        T_init: FloatArray,
        found: str,
        timer: Timer,
    ) -> Estimate:
        """Steps 6-7 from ``T_init``; ``found`` says where the pose came from (the result's first note)."""
        with timer("pose check"):
            start = self._agreement(T_init, prepared_source, prepared_target)
        refined, first_agreement = True, start  # set by the early check where the ICP asks it

        def worth_refining(T_first: FloatArray) -> bool:
            # The pose check, asked early: on worn, bent or crusted pairs (and most pairs of different
            # dies) the first stages already slide off the die pattern, and the last stage, most of the
            # ICP's time, would not bring them back (see ReliefSearch.icp_early_refusal).
            nonlocal refined, first_agreement
            with timer("pose check"):
                first_agreement = self._agreement(T_first, prepared_source, prepared_target)
            refined = first_agreement >= start - self.search.icp_early_refusal
            return refined

        with timer("icp"):
            relief_index = np.flatnonzero(prepared_source.relief)
            sample = self._icp_sample(relief_index, self.search.icp_points)
            final = self._icp_sample(relief_index, self.icp.final_points)
            early = prepared_target.as_target(target, self.icp)
            outcome = self.icp.run(
                source.points[sample], target, T_init, early, source.points[final], worth_refining
            )
            n_points = max(len(sample), len(final))  # the source points a stage paired at most
        notes = (
            found,
            f"ICP: {outcome.iterations} iterations, converged={outcome.converged}"
            + ("" if refined else ", last stage not run"),
        )
        if outcome.n_correspondences < MIN_CORRESPONDENCES:
            failure = f"ICP found {outcome.n_correspondences} point pairs after the planar alignment"
            return Estimate(T_init, outcome.n_correspondences, failure=failure, notes=notes)
        with timer("pose check"):
            kept = (
                first_agreement
                if not refined
                else self._agreement(outcome.T_target_source, prepared_source, prepared_target)
            )
        if kept < start - self.search.icp_tolerance:
            # The ICP slid away from the die pattern (a cupping or bend difference pulls a rigid fit of
            # the whole surface off the design): the planar pose aligns the reliefs better.
            notes = (
                *notes,
                f"ICP pose refused: relief agreement {kept:.3f} < {start:.3f} at the planar pose",
            )
            T_final = T_init
        else:
            T_final = outcome.T_target_source
        with timer("block matching"):
            T_final, note = self._block_matched(T_final, prepared_source, prepared_target)
        return Estimate(T_final, n_points, outcome.n_correspondences, notes=(*notes, note))

    def _block_matched(
        self, T_target_source: FloatArray, source: PreparedFace, target: PreparedFace
    ) -> tuple[FloatArray, str]:
        """The pose with its in-plane part (about the target's canonical z) refined by block matching;
        tilt and height stay the ICP's. Kept only where the reliefs' windows agree better than before."""
        if source.fine is None or target.fine is None:
            return T_target_source, "block matching off"
        angle, shift = _planar_of(T_target_source, source.frame, target.frame)
        blocks = self.blocks
        refined = refine_planar(
            source.fine, target.fine, angle, shift,
            window_mm=blocks.window, reach_px=blocks.reach, iterations=blocks.iterations,
        )  # fmt: skip
        summary = (
            f"block matching: {refined.windows} windows, {refined.consistent:.0%} consistent, "
            f"agreement {refined.agreement_before:.3f} -> {refined.agreement_after:.3f}"
        )
        if not refined.improved:
            return T_target_source, summary + " (refused)"
        # the correction in the target's canonical plane: new planar pose after the inverse of the old one
        turn = refined.angle_rad - angle
        moved = (
            np.hypot(refined.shift_mm[0] - shift[0], refined.shift_mm[1] - shift[1]) + abs(turn) * REACH_MM
        )
        if moved < blocks.pixel:
            # Within a pixel the ICP's thousands of points see further than the windows' correlations:
            # on the riedones preset the ICP's poses are within 0.002 mm of the truth, the windows' within
            # 0.01-0.03 mm (the rasterised reliefs' own noise), which they would trade for.
            return T_target_source, summary + " (within a pixel: kept)"
        c, s = np.cos(turn), np.sin(turn)
        correction = np.eye(4)
        correction[:2, :2] = [[c, -s], [s, c]]
        correction[:2, 3] = np.asarray(refined.shift_mm) - correction[:2, :2] @ np.asarray(shift)
        T_frame = target.frame.T_canonical_scan
        return np.linalg.inv(T_frame) @ correction @ T_frame @ T_target_source, summary

    def planar_pose(self, source: PreparedFace, target: PreparedFace) -> tuple[PlanarAlignment, FloatArray]:
        """Steps 4-5: the planar alignment of two prepared faces, and T_target_source lifted from it."""
        planar = align_reliefs(
            source.image,
            target.image,
            n_angle_peaks=self.search.angle_peaks,
            coarse_step=self.search.coarse_step,
            search=self.search.angle_search,
            angle_step_deg=self.search.angle_step,
            sweep_step=self.search.sweep_step,
        )
        return planar, _lift(planar.matrix(), source.frame, target.frame)

    @staticmethod
    def _agreement(T_target_source: FloatArray, source: PreparedFace, target: PreparedFace) -> float:
        """The relief images' masked NCC at a 3-D pose, through both canonical frames (tilt ignored)."""
        return pose_score(
            source.image, target.image, *_planar_of(T_target_source, source.frame, target.frame)
        )

    def prepare(self, cloud: Cloud) -> PreparedFace:
        """Steps 1–3 for one face, from the cache when this exact cloud was seen."""
        key = cloud.key
        if key in self._cache:
            self._cache.move_to_end(key)
            return self._cache[key]
        prepared = self._prepare(cloud)
        self._cache[key] = prepared
        if len(self._cache) > self.cache_size:
            self._cache.popitem(last=False)
        return prepared

    def _prepare(self, cloud: Cloud) -> PreparedFace:
        scan = Scan(points=cloud.points, normals=cloud.normals)
        stride = -(-len(cloud.points) // self.search.frame_points)
        frame = canonical_frame(scan.subset(np.arange(0, len(cloud.points), stride)))
        relief = height_map(scan, resolution=self.search.pixel, frame=frame, detrend="quadric")
        grid = _centred_grid(relief, self.search.pixel, self.search.field_size)
        image = ReliefImage.from_grid(
            grid,
            self.search.pixel,
            high_pass_mm=self.search.high_pass,
            margin_mm=self.search.margin,
            clip_sd=self.search.clip,
        )
        relief_points = cloud.normals @ frame.up >= np.cos(np.radians(_RELIEF_MAX_NORMAL_ANGLE_DEG))
        fine = None
        if self.blocks.levels > 0:
            fine_relief = height_map(scan, resolution=self.blocks.pixel, frame=frame, detrend="quadric")
            fine = FineRelief.from_grid(
                _centred_grid(fine_relief, self.blocks.pixel, self.search.field_size),
                self.blocks.pixel,
                high_pass_mm=self.blocks.high_pass,
                margin_mm=self.search.margin,
                steps=self.blocks.steps,
                clip_sd=self.search.clip,
            )
        return PreparedFace(frame, image, relief_points, fine)

    @staticmethod
    def _icp_sample(relief_index: IntArray, n_points: int) -> IntArray:
        """Every k-th relief point in canonical order (sorted by x), about ``n_points`` of them: spread over
        the face, and the same whatever the order of the input points."""
        return relief_index[:: -(-len(relief_index) // n_points)]


def _centred_grid(relief, pixel: float, field_size: float) -> FloatArray:  # noqa: ANN001 (HeightMap)
    """The height map resampled on a square grid whose centre is the canonical origin, rows along +y."""
    size = int(round(field_size / pixel))
    coordinates = (np.arange(size) - (size - 1) / 2.0) * pixel
    y, x = np.meshgrid(coordinates, coordinates, indexing="ij")
    rows, cols = relief.mm_to_pixel(x, y)
    values = np.asarray(relief.values, dtype=np.float64)
    return ndimage.map_coordinates(values, [rows, cols], order=1, mode="constant", cval=np.nan)


def _planar_of(
    T_target_source: FloatArray, source: CanonicalFrame, target: CanonicalFrame
) -> tuple[float, tuple[float, float]]:
    """The turn about z (rad) and the shift in the plane (mm) of a 3-D pose seen from source canonical to
    target canonical coordinates, tilt ignored: the inverse of :func:`_lift` for a planar pose."""
    T = target.T_canonical_scan @ T_target_source @ np.linalg.inv(source.T_canonical_scan)
    return float(np.arctan2(T[1, 0], T[0, 0])), (float(T[0, 3]), float(T[1, 3]))


def _lift(T_planar: FloatArray, source: CanonicalFrame, target: CanonicalFrame) -> FloatArray:
    """T_target_source from the planar T (source canonical -> target canonical, about z)."""
    T_canonical = np.eye(4)
    T_canonical[:2, :2] = T_planar[:2, :2]
    T_canonical[:2, 3] = T_planar[:2, 2]
    return np.linalg.inv(target.T_canonical_scan) @ T_canonical @ source.T_canonical_scan
