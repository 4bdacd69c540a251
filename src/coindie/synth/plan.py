"""The plan of a hoard: dies and their sizes, the mint's time line, coins, faces and splits. Pure data.

Planning draws everything that is about the hoard's structure and nothing about surfaces:

1. Die sizes, group by group: the experts' real die sizes resampled with a seeded generator, then
   adjusted so that each group has its exact number of coins and the paper's pair counts are met.
2. The time line (mint time 0..1 over the hoard's production). Obverse dies are used one after the other
   (the beard series first), consecutive lives overlapping a little; their coins are struck at uniform
   times in their die's life. Reverse dies wear out faster: a few are in use at once, each coin takes one at
   random, and a reverse die is retired once it has struck its share, so each obverse die meets several
   reverse dies (the die-link network).
3. Coins: every beard coin has both faces; of the coins without beard, a few are obverse-only and the
   others have both faces; the remaining reverses are reverse-only coins (their obverse was not labelled,
   it was still struck by some obverse die of the time line). Catalogue numbers are shuffled: beard coins
   are L0001.., the others follow, none in striking order.
4. Die ids: ``DB<k>`` (beard), ``D<k>`` (without beard), ``R<k>`` (reverse), numbered by their first coin
   in catalogue order, as the experts' files number them.
"""

from __future__ import annotations

import hashlib
from collections import Counter, defaultdict
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import IntArray
from coindie.ids import Face, canonical_face_id
from coindie.synth.presets import BEARD, FAMILIES, OBVERSE, REVERSE, PairTarget, Preset, real_die_sizes

#: Random redraws of one die size while fitting a group's coin total (then sizes are nudged by one coin),
#: and redraws without progress after which the nudging starts.
MAX_REDRAWS = 20_000
SIZE_PATIENCE = 500
#: Random one-coin moves without progress after which fitting a pair count stops.
PAIR_PATIENCE = 20_000
PAIR_EXPLORE = 50
#: Die-id prefix of each family.
DIE_PREFIX = {BEARD: "DB", OBVERSE: "D", REVERSE: "R"}


@dataclass(frozen=True)
class DiePlan:
    """One die: its family, group, splits, size in the hoard and life on the mint's time line."""

    die_id: str
    family: str
    group: int
    splits: tuple[str, ...]
    size: int
    start: float
    end: float

    @property
    def life(self) -> float:
        return self.end - self.start


@dataclass(frozen=True)
class FacePlan:
    """One face of one coin: the die that struck it, when, and how worn the die was (age 0..1)."""

    face_id: str
    coin: int
    family: str
    die_id: str
    strike_time: float
    die_age: float
    splits: tuple[str, ...]


@dataclass(frozen=True)
class HoardPlan:
    """The whole hoard as data. Faces are sorted by face id."""

    preset: Preset
    seed: int
    dies: tuple[DiePlan, ...]
    faces: tuple[FacePlan, ...]

    def labels(self) -> dict[str, str]:
        """Face id -> die id."""
        return {f.face_id: f.die_id for f in self.faces}

    def split_rows(self) -> list[tuple[str, str]]:
        """(face id, split) rows: one per face and split it belongs to."""
        return [(f.face_id, split) for f in self.faces for split in f.splits]

    def faces_in(self, split: str) -> list[FacePlan]:
        return [f for f in self.faces if split in f.splits]

    def die(self, die_id: str) -> DiePlan:
        return self._die_index()[die_id]

    def _die_index(self) -> dict[str, DiePlan]:
        return {d.die_id: d for d in self.dies}

    def coin_dies(self) -> tuple[dict[int, str], dict[int, str]]:
        """(coin -> obverse die, coin -> reverse die), beard obverses included."""
        obverse = {f.coin: f.die_id for f in self.faces if f.family != REVERSE}
        reverse = {f.coin: f.die_id for f in self.faces if f.family == REVERSE}
        return obverse, reverse


@dataclass(frozen=True)
class LinkStats:
    """Figures of a die-link network (coins with both faces labelled)."""

    coins_with_both: int
    combinations: int
    max_reverse_per_obverse: int
    mean_reverse_per_obverse: float
    max_obverse_per_reverse: int
    mean_obverse_per_reverse: float


def link_stats(obverse_die: dict[int, str], reverse_die: dict[int, str]) -> LinkStats:
    """Die-link figures from coin -> die maps of both faces."""
    both = set(obverse_die) & set(reverse_die)
    combos = {(obverse_die[c], reverse_die[c]) for c in both}
    per_obverse = Counter(o for o, _ in combos)
    per_reverse = Counter(r for _, r in combos)
    return LinkStats(
        coins_with_both=len(both),
        combinations=len(combos),
        max_reverse_per_obverse=max(per_obverse.values(), default=0),
        mean_reverse_per_obverse=float(np.mean(list(per_obverse.values()))) if combos else 0.0,
        max_obverse_per_reverse=max(per_reverse.values(), default=0),
        mean_obverse_per_reverse=float(np.mean(list(per_reverse.values()))) if combos else 0.0,
    )


def derived_seed(seed: int, *names: str) -> int:
    """A 63-bit seed for one named stream of a hoard (``"die", "D12"``), the same in every process."""
    # Python's hash() is salted per process: names are hashed with sha256 to stay reproducible.
    words = [int.from_bytes(hashlib.sha256(name.encode()).digest()[:8], "little") for name in names]
    state = np.random.SeedSequence([seed, *words]).generate_state(1, np.uint64)
    return int(state[0] >> np.uint64(1))


def plan_hoard(preset: Preset, seed: int) -> HoardPlan:
    """Plan a hoard from a (possibly scaled) preset; the same preset and seed give the same plan."""
    rng = np.random.default_rng(derived_seed(seed, "plan"))
    sizes = draw_die_sizes(rng, preset)
    slots = _strike_time_line(rng, preset, sizes)
    coins = _catalogue_numbers(rng, slots)
    die_ids = _die_ids(slots, coins)
    return _assemble(preset, seed, slots, coins, die_ids)


# --- 1. die sizes --------------------------------------------------------------------------------------


def draw_die_sizes(rng: np.random.Generator, preset: Preset) -> list[IntArray]:
    """Die sizes of each group (same order as ``preset.groups``), pair targets met as far as possible."""
    sizes = [
        draw_group_sizes(rng, np.asarray(real_die_sizes(g.family)), g.n_dies, g.n_coins)
        for g in preset.groups
    ]
    for target in preset.pair_targets:
        meet_pair_target(rng, sizes, target)
    return sizes


def draw_group_sizes(rng: np.random.Generator, pool: IntArray, n_dies: int, n_coins: int) -> IntArray:
    """``n_dies`` sizes resampled from ``pool``, then redrawn one at a time (keeping redraws that do not
    move away from ``n_coins``) and finally nudged by single coins to sum to ``n_coins`` exactly."""
    sizes = rng.choice(pool, n_dies).astype(np.int64)
    picks, draws = rng.integers(n_dies, size=MAX_REDRAWS), rng.choice(pool, MAX_REDRAWS)
    best, since_best = abs(n_coins - int(sizes.sum())), 0
    for i, new in zip(picks, draws, strict=True):
        gap = n_coins - int(sizes.sum())
        if gap == 0 or since_best >= SIZE_PATIENCE:
            break
        if abs(gap + sizes[i] - new) <= abs(gap):
            sizes[i] = new
        best, since_best = (abs(gap), 0) if abs(gap) < best else (best, since_best + 1)
    return _nudged_to_total(rng, sizes, n_coins)


def _nudged_to_total(rng: np.random.Generator, sizes: IntArray, n_coins: int) -> IntArray:
    while (gap := n_coins - int(sizes.sum())) != 0:
        candidates = np.flatnonzero(sizes > 1) if gap < 0 else np.arange(len(sizes))
        sizes[rng.choice(candidates)] += 1 if gap > 0 else -1
    return sizes


def same_die_pairs(sizes: IntArray) -> int:
    return int((sizes * (sizes - 1) // 2).sum())


def meet_pair_target(rng: np.random.Generator, sizes: list[IntArray], target: PairTarget) -> None:
    """Move single coins between dies of a group (totals unchanged) until the groups' pairs hit the target.

    Moves that do not move away from the target are kept, and one in ``PAIR_EXPLORE`` other moves too (so
    that the search leaves multisets where no single move helps); the closest sizes seen are kept. It gives
    up after ``PAIR_PATIENCE`` moves without getting closer."""
    groups = [g for g in target.groups if len(sizes[g]) > 1]
    gap = target.pairs - sum(same_die_pairs(sizes[g]) for g in target.groups)
    best, best_sizes, since_best = abs(gap), [s.copy() for s in sizes], 0
    while groups and best != 0 and since_best < PAIR_PATIENCE:
        s = sizes[groups[rng.integers(len(groups))]]
        i, j = rng.integers(len(s)), rng.integers(len(s))
        change = s[j] - s[i] + 1  # pairs gained by moving one coin from die i to die j
        if i != j and s[i] > 1 and (abs(gap - change) <= abs(gap) or rng.integers(PAIR_EXPLORE) == 0):
            s[i] -= 1
            s[j] += 1
            gap -= int(change)
        if abs(gap) < best:
            best, best_sizes, since_best = abs(gap), [s.copy() for s in sizes], 0
        else:
            since_best += 1
    for g, s in enumerate(best_sizes):
        sizes[g][:] = s


# --- 2. time line ----------------------------------------------------------------------------------------


@dataclass
class _Slots:
    """Working arrays of the time line; dies are indexed over all groups, coins over all faces' coins."""

    die_group: IntArray  # group of each die
    die_start: NDArray[np.float64]
    die_end: NDArray[np.float64]
    coin_time: NDArray[np.float64]  # strike time of each coin
    coin_beard: NDArray[np.bool_]
    coin_obverse: IntArray  # obverse die of each coin, -1 when its obverse is not in the hoard
    coin_reverse: IntArray  # reverse die, -1 when none


def _strike_time_line(rng: np.random.Generator, preset: Preset, sizes: list[IntArray]) -> _Slots:
    die_group = np.concatenate([np.full(len(s), g) for g, s in enumerate(sizes)]).astype(np.int64)
    die_size = np.concatenate(sizes)
    family = np.array([preset.groups[g].family for g in die_group])
    start, end = _obverse_lives(rng, preset, family, die_size)
    # Obverse faces: each obverse die strikes its coins at uniform times in its life.
    obverse_dies = np.flatnonzero(family != REVERSE)
    coin_obverse = np.repeat(obverse_dies, die_size[obverse_dies])
    times = rng.uniform(start[coin_obverse], end[coin_obverse])
    beard = family[coin_obverse] == BEARD
    has_reverse = _with_reverse(rng, preset, beard)
    # Reverse-only coins: struck by an unlabelled coin of some obverse die without beard.
    n_reverse_only = max(0, preset.n_coins(REVERSE) - int(has_reverse.sum()))
    plain = obverse_dies[family[obverse_dies] == OBVERSE]
    extra_times = _hidden_obverse_times(rng, n_reverse_only, plain, die_size, (start, end))
    slots = _Slots(
        die_group=die_group,
        die_start=start,
        die_end=end,
        coin_time=np.concatenate([times, extra_times]),
        coin_beard=np.concatenate([beard, np.zeros(n_reverse_only, bool)]),
        coin_obverse=np.concatenate([coin_obverse, np.full(n_reverse_only, -1)]),
        coin_reverse=np.full(len(times) + n_reverse_only, -1),
    )
    wants_reverse = np.concatenate([has_reverse, np.ones(n_reverse_only, bool)])
    _assign_reverses(rng, preset, slots, np.flatnonzero(family == REVERSE), die_size, wants_reverse)
    return slots


def _obverse_lives(
    rng: np.random.Generator, preset: Preset, family: NDArray[np.str_], die_size: IntArray
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Lives of the obverse dies, one after the other, each as long as its size; reverse lives come later."""
    beard = rng.permutation(np.flatnonzero(family == BEARD))
    plain = rng.permutation(np.flatnonzero(family == OBVERSE))
    order = np.concatenate([beard, plain] if preset.links.beard_first else [plain, beard])
    start, end = np.zeros(len(family)), np.zeros(len(family))
    clock = 0.0
    for previous, die in zip(np.r_[-1, order[:-1]], order, strict=True):
        if previous >= 0:
            clock -= preset.links.obverse_overlap * min(die_size[die], die_size[previous])
        start[die], end[die] = clock, clock + die_size[die]
        clock = end[die]
    span = clock if clock > 0 else 1.0
    return start / span, end / span


def _with_reverse(rng: np.random.Generator, preset: Preset, beard: NDArray[np.bool_]) -> NDArray[np.bool_]:
    """Which obverse coins also have a reverse: every beard coin, all but a few of the others."""
    plain = np.flatnonzero(~beard)
    n_reverses_left = preset.n_coins(REVERSE) - int(beard.sum())
    n_obverse_only = max(round(len(plain) * preset.obverse_only_share), len(plain) - max(n_reverses_left, 0))
    has_reverse = np.ones(len(beard), bool)
    has_reverse[rng.choice(plain, min(n_obverse_only, len(plain)), replace=False)] = False
    return has_reverse


def _hidden_obverse_times(
    rng: np.random.Generator,
    n: int,
    dies: IntArray,
    die_size: IntArray,
    life: tuple[NDArray[np.float64], NDArray[np.float64]],
) -> NDArray[np.float64]:
    """Strike times of ``n`` coins whose obverse is not in the hoard (its die chosen by size)."""
    if n == 0 or len(dies) == 0:
        return rng.uniform(0.0, 1.0, n)
    chosen = rng.choice(dies, n, p=die_size[dies] / die_size[dies].sum())
    return rng.uniform(life[0][chosen], life[1][chosen])


def _assign_reverses(
    rng: np.random.Generator,
    preset: Preset,
    slots: _Slots,
    reverse_dies: IntArray,
    die_size: IntArray,
    wants: NDArray[np.bool_],
) -> None:
    """Reverse dies in random order, ``reverse_parallel`` in use at once; each coin (in time order) takes
    one of them at random; a die leaves when it has struck its share and the next one takes its place."""
    coins = np.flatnonzero(wants)
    coins = coins[np.argsort(slots.coin_time[coins], kind="stable")]
    queue = list(rng.permutation(reverse_dies))
    remaining = die_size.copy()
    active = [queue.pop(0) for _ in range(min(preset.links.reverse_parallel, len(queue)))]
    slots.die_start[active] = 0.0
    for coin in coins:
        slot = int(rng.integers(len(active)))
        die = active[slot]
        slots.coin_reverse[coin] = die
        remaining[die] -= 1
        if remaining[die] == 0:
            slots.die_end[die] = slots.coin_time[coin]
            if queue:
                active[slot] = queue.pop(0)
                slots.die_start[active[slot]] = slots.coin_time[coin]
            else:
                active.pop(slot)


# --- 3-4. catalogue numbers, die ids, faces -------------------------------------------------------------


def _catalogue_numbers(rng: np.random.Generator, slots: _Slots) -> IntArray:
    """Coin number of each coin: beard coins first (1..B), the others after, shuffled within each."""
    numbers = np.zeros(len(slots.coin_time), np.int64)
    beard = np.flatnonzero(slots.coin_beard)
    plain = np.flatnonzero(~slots.coin_beard)
    numbers[beard] = 1 + rng.permutation(len(beard))
    numbers[plain] = 1 + len(beard) + rng.permutation(len(plain))
    return numbers


def _die_ids(slots: _Slots, numbers: IntArray) -> dict[int, str]:
    """Die index -> id, numbered in each family by the die's first coin in catalogue order."""
    first: dict[int, int] = {}
    for column in (slots.coin_obverse, slots.coin_reverse):
        for die, number in zip(column, numbers, strict=True):
            if die >= 0:
                first[int(die)] = min(first.get(int(die), number), int(number))
    return first


def _assemble(
    preset: Preset, seed: int, slots: _Slots, numbers: IntArray, first: dict[int, int]
) -> HoardPlan:
    family_of = {d: preset.groups[slots.die_group[d]].family for d in first}
    ids: dict[int, str] = {}
    for family in FAMILIES:
        ranked = sorted((first[d], d) for d in first if family_of[d] == family)
        ids.update({d: f"{DIE_PREFIX[family]}{k}" for k, (_, d) in enumerate(ranked, start=1)})
    dies = tuple(
        sorted(
            (_die_plan(preset, slots, d, ids[d], family_of[d]) for d in ids),
            key=lambda die: (FAMILIES.index(die.family), int(die.die_id.lstrip("DBR"))),
        )
    )
    faces = [
        _face_plan(preset, slots, coin, int(numbers[coin]), int(die), ids[int(die)], face)
        for face, column in ((Face.OBVERSE, slots.coin_obverse), (Face.REVERSE, slots.coin_reverse))
        for coin, die in enumerate(column)
        if die >= 0
    ]
    return HoardPlan(preset, seed, dies, tuple(sorted(faces, key=lambda f: f.face_id)))


def _die_plan(preset: Preset, slots: _Slots, die: int, die_id: str, family: str) -> DiePlan:
    group = int(slots.die_group[die])
    size = int((slots.coin_obverse == die).sum() + (slots.coin_reverse == die).sum())
    start, end = float(slots.die_start[die]), float(slots.die_end[die])
    return DiePlan(die_id, family, group, preset.groups[group].splits, size, start, end)


def _face_plan(
    preset: Preset, slots: _Slots, coin: int, number: int, die: int, die_id: str, face: Face
) -> FacePlan:
    group = preset.groups[slots.die_group[die]]
    start, end, time = slots.die_start[die], slots.die_end[die], slots.coin_time[coin]
    age = float(np.clip((time - start) / max(end - start, 1e-12), 0.0, 1.0))
    return FacePlan(
        canonical_face_id(number, face), number, group.family, die_id, float(time), age, group.splits
    )


def group_lifetimes(plan: HoardPlan) -> dict[str, list[float]]:
    """Life lengths (mint time) of the dies of each family."""
    lives: dict[str, list[float]] = defaultdict(list)
    for die in plan.dies:
        lives[die.family].append(die.life)
    return dict(lives)
