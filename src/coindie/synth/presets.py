"""Hoard presets: how many dies and coins of each family, and which splits they go to.

A preset is a list of die groups. A group is a set of whole dies of one family whose faces all go to the
same splits (the paper's splits are made of whole dies), with its number of dies and of coins. The
``riedones`` preset reproduces the counts of the Riedones3D study (Horache et al. 2021, section "Baseline"):

- obverses with beard: 81 coins from 7 dies, clustering test only; 6 of the dies (80 coins) form the
  registration test set (the paper's table names them DB1a, DB2a, DB3a, DB1b, DB2b, DB3b: six distinct dies,
  since the registration benchmark counts 27 dies = 15 reverse + 6 beard + 6 without beard);
- obverses without beard: 887 coins from 74 dies; registration test 80 coins (6 dies), registration
  training 200 coins (inside the clustering training set), clustering train / val / test 418 / 181 / 288
  coins, the test set with 14 dies;
- reverses: 1,102 coins from 212 dies (the paper's count; the experts' file has 213); registration test 79
  coins (15 dies); clustering train / val / test 510 / 299 / 293 coins, the test set with 30 dies.

The registration test dies are taken inside the clustering test sets (as the beard dies must be, since
beard coins are test-only): training faces never appear in a test set. Die counts the paper does not give
(train and validation groups) are proportional to their coin counts.
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass, field, replace
from typing import ClassVar

from coindie.errors import ParameterError
from coindie.params import Configurable, Rule, param

BEARD, OBVERSE, REVERSE = "beard", "obverse", "reverse"
#: Families of faces: obverses with beard, obverses without beard, reverses.
FAMILIES = (BEARD, OBVERSE, REVERSE)

REG_TEST, REG_TRAIN = "registration_test", "registration_train"
CLUSTER_TRAIN, CLUSTER_VAL, CLUSTER_TEST = "cluster_train", "cluster_val", "cluster_test"
#: Split names written in ``splits.csv``; a face is in at most one registration and one clustering split.
SPLITS = (REG_TEST, REG_TRAIN, CLUSTER_TRAIN, CLUSTER_VAL, CLUSTER_TEST)


@dataclass(frozen=True)
class DieGroup(Configurable):
    """Whole dies of one family whose faces go to the same splits."""

    RULES: ClassVar[tuple[Rule, ...]] = (
        Rule(("n_dies", "n_coins"), lambda g: g.n_dies <= g.n_coins, "n_dies <= n_coins"),
    )

    family: str = param(kind=str, doc="the coin family of the dies", choices=FAMILIES)
    n_dies: int = param(kind=int, doc="dies of the group", low=1)
    n_coins: int = param(kind=int, doc="coins struck by them", low=1)
    splits: tuple[str, ...] = param(kind=tuple, doc="the splits its faces go to", item=str, choices=SPLITS)

    @property
    def name(self) -> str:
        return f"{self.family}:{'+'.join(self.splits)}"


@dataclass(frozen=True)
class PairTarget:
    """A number of same-die face pairs wanted over some groups (a figure the paper quotes)."""

    groups: tuple[int, ...]  # indices into Preset.groups
    pairs: int
    source: str = ""


@dataclass(frozen=True)
class LinkParams(Configurable):
    """How obverse and reverse dies share the mint's time line (this makes the die-link network).

    Attributes:
        obverse_overlap: fraction (0-0.5, default 0.2) of the shorter life of two consecutive obverse
            dies during which both are in use. Obverse dies are used one after the other.
        reverse_parallel: number of reverse dies in use at once (1-20, default 2). Each struck coin takes
            one of them at random; a reverse die is retired when it has struck its share of the hoard.
        beard_first: whether the obverses with beard were struck before those without beard.
    """

    obverse_overlap: float = param(
        0.2,
        numbers.Real,
        doc="share of the shorter life two consecutive obverse dies overlap",
        low=0.0,
        high=0.5,
    )
    reverse_parallel: int = param(2, numbers.Real, doc="reverse dies in use at once", low=1, high=20)
    beard_first: bool = param(True, doc="the obverses with beard were struck first")


@dataclass(frozen=True)
class Preset(Configurable):
    """A hoard's structure: die groups, pair-count targets, die-link parameters.

    ``obverse_only_share`` is the share of obverses without beard whose coin has no labelled reverse
    (Riedones3D: 6 of 887). Every beard coin has both faces; the remaining reverses are reverse-only coins.
    """

    RULES: ClassVar[tuple[Rule, ...]] = (
        Rule(
            ("pair_targets", "groups"),
            lambda p: all(0 <= g < len(p.groups) for t in p.pair_targets for g in t.groups),
            "every pair target names existing groups",
        ),
    )

    name: str = param(kind=str, doc="the preset's name")
    groups: tuple[DieGroup, ...]
    pair_targets: tuple[PairTarget, ...] = ()
    obverse_only_share: float = param(
        6 / 887,
        numbers.Real,
        doc="share of the obverses without beard with no labelled reverse",
        low=0.0,
        high=1.0,
    )
    links: LinkParams = field(default_factory=LinkParams)
    scale: float = 1.0

    def n_coins(self, family: str) -> int:
        return sum(g.n_coins for g in self.groups if g.family == family)

    def n_dies(self, family: str) -> int:
        return sum(g.n_dies for g in self.groups if g.family == family)

    def scaled(self, scale: float) -> Preset:
        """The preset shrunk proportionally: dies and coins of every group times ``scale`` (at least one
        die per group, at least one coin per die). Pair targets are the paper's figures for the whole
        hoard and are dropped (a shrunk group's pair count is set by its few dies)."""
        if not 0.0 < scale <= 1.0:
            raise ParameterError(f"scale must be in (0, 1], got {scale}")
        if scale == 1.0:
            return self
        groups = tuple(_scaled_group(g, scale) for g in self.groups)
        return replace(self, groups=groups, pair_targets=(), scale=self.scale * scale)


def _scaled_group(group: DieGroup, scale: float) -> DieGroup:
    n_dies = max(1, round(group.n_dies * scale))
    return replace(group, n_dies=n_dies, n_coins=max(n_dies, round(group.n_coins * scale)))


def _riedones() -> Preset:
    groups = (
        DieGroup(BEARD, 6, 80, (REG_TEST, CLUSTER_TEST)),
        DieGroup(BEARD, 1, 1, (CLUSTER_TEST,)),
        DieGroup(OBVERSE, 6, 80, (REG_TEST, CLUSTER_TEST)),
        DieGroup(OBVERSE, 8, 208, (CLUSTER_TEST,)),
        DieGroup(OBVERSE, 20, 200, (REG_TRAIN, CLUSTER_TRAIN)),
        DieGroup(OBVERSE, 22, 218, (CLUSTER_TRAIN,)),
        DieGroup(OBVERSE, 18, 181, (CLUSTER_VAL,)),
        DieGroup(REVERSE, 15, 79, (REG_TEST, CLUSTER_TEST)),
        DieGroup(REVERSE, 15, 214, (CLUSTER_TEST,)),
        DieGroup(REVERSE, 115, 510, (CLUSTER_TRAIN,)),
        DieGroup(REVERSE, 67, 299, (CLUSTER_VAL,)),
    )
    targets = (
        PairTarget((0, 2, 7), 2158, "registration benchmark: 2158 pairs over 27 dies"),
        PairTarget((4,), 2132, "FCGF training set: 200 obverses make 2132 pairs"),
    )
    return Preset("riedones", groups, targets)


def _tiny() -> Preset:
    groups = (
        DieGroup(BEARD, 1, 2, (REG_TEST, CLUSTER_TEST)),
        DieGroup(OBVERSE, 1, 3, (REG_TEST, CLUSTER_TEST)),
        DieGroup(OBVERSE, 1, 2, (REG_TRAIN, CLUSTER_TRAIN)),
        DieGroup(OBVERSE, 1, 1, (CLUSTER_VAL,)),
        DieGroup(REVERSE, 2, 4, (REG_TEST, CLUSTER_TEST)),
        DieGroup(REVERSE, 1, 3, (CLUSTER_TRAIN,)),
        DieGroup(REVERSE, 1, 1, (CLUSTER_VAL,)),
    )
    return Preset("tiny", groups, obverse_only_share=0.0)


def _study() -> Preset:
    """80 faces, 12 dies: 40 coins with both faces, 6 obverse and 6 reverse dies. Every face is in the
    clustering test split; half the dies of each side are also a registration test set. Sizes are resampled
    from the experts' real ones within each group, so a few dies are large and some hold one or two coins."""
    groups = (
        DieGroup(OBVERSE, 3, 24, (REG_TEST, CLUSTER_TEST)),
        DieGroup(OBVERSE, 3, 16, (CLUSTER_TEST,)),
        DieGroup(REVERSE, 3, 22, (REG_TEST, CLUSTER_TEST)),
        DieGroup(REVERSE, 3, 18, (CLUSTER_TEST,)),
    )
    return Preset("study", groups, obverse_only_share=0.0)


#: Die sizes (coins per die) of the experts' final labels, as {size: number of dies}: obverses without beard
#: (experts_obverse_dies.csv: 887 coins, 74 dies) and reverses (experts_reverse_dies.csv: 1,102 coins, 213
#: dies), from the Riedones3D authors' graph_visualizer repository (CC BY-NC-ND 3.0 data). No sizes are
#: published for the beard dies: they are drawn from the obverse list.
REAL_DIE_SIZES: dict[str, dict[int, int]] = {
    OBVERSE: {
        97: 1,
        53: 1,
        46: 1,
        36: 1,
        32: 1,
        31: 2,
        30: 1,
        29: 1,
        27: 1,
        25: 1,
        24: 2,
        21: 5,
        20: 3,
        19: 1,
        18: 1,
        17: 2,
        16: 1,
        10: 4,
        7: 3,
        6: 2,
        5: 5,
        4: 2,
        3: 3,
        2: 6,
        1: 23,
    },
    REVERSE: {
        35: 1,
        30: 1,
        29: 1,
        28: 1,
        27: 3,
        24: 1,
        21: 1,
        20: 1,
        19: 2,
        18: 3,
        17: 2,
        16: 1,
        15: 3,
        14: 5,
        13: 5,
        12: 4,
        11: 4,
        10: 4,
        9: 2,
        8: 2,
        7: 7,
        6: 7,
        5: 3,
        4: 12,
        3: 17,
        2: 21,
        1: 99,
    },
}


def real_die_sizes(family: str) -> list[int]:
    """Die sizes (largest first) that ``family``'s sizes are drawn from; beard: the obverse list."""
    table = REAL_DIE_SIZES[REVERSE if family == REVERSE else OBVERSE]
    return [size for size, count in sorted(table.items(), reverse=True) for _ in range(count)]


#: Presets by name.
PRESETS: dict[str, Preset] = {"riedones": _riedones(), "tiny": _tiny(), "study": _study()}


def get_preset(name: str, scale: float = 1.0) -> Preset:
    """The named preset, shrunk by ``scale``."""
    if name not in PRESETS:
        raise ParameterError(f"unknown hoard preset {name!r}; known: {', '.join(PRESETS)}")
    return PRESETS[name].scaled(scale)
