"""Calibration on each hoard, without labels: what a same-die probability means on *this* hoard's scans.

A scorer's probabilities were calibrated on its training hoards. On another scanner (noisier, coarser,
smoothed) or other flans, the scores of both populations move, and a fixed probability no longer means
the same. But a hoard carries its own answer: most of its same-side pairs are of different dies, a
minority of the same die, and the two form two modes of the scorer's log-odds. So the log-odds of a
hoard's registered pairs are fitted by a two-component mixture of Student-t distributions (EM started
from the scorer's training populations and from the data's bulk and upper tail, the fit of the higher
likelihood kept; the upper component is the same-die one), and a pair's
calibrated probability is its posterior of the same-die component — made non-decreasing in the score
(the smallest posterior at or above it), since the component with the larger spread would otherwise
also claim the far tail on the other side. The mixture gives the hoard's same-die share and the
clustering threshold (τ = 0.9 on the calibrated probability, see :data:`MIXTURE_THRESHOLD`).

Why Student-t and not Gaussian components: a hoard's different-die pairs are themselves a mixture, pairs
of other designs far below and pairs of other dies of one design close below the same-die pairs, so
their upper tail is heavier than a Gaussian's. A Gaussian fitted to their bulk is narrow, and the
same-die component then claims its tail: on a `study` hoard of the default physics (seed 1022), 32
different-die obverse pairs were calibrated above 0.5 (a one-coin die's coin near 1 with most coins of a
20-coin die of its design), 15 with t components (:data:`TAIL_DOF`), none above 0.99, while the same-die
share came closer to the truth (42.1 % and 39.2 % for 36.4 %). The t mixture is the usual robust
mixture (Peel & McLachlan, "Robust mixture modelling using the t distribution", Statistics and Computing
10, 2000); its EM is written here by hand (scikit-learn's mixtures are Gaussian; scipy fits one t, not
a mixture), with the degrees of freedom held fixed.

When the log-odds do not split into a same-die and a different-die mode (Ashman's D < 2 between the
components; an upper component of less than one pair or of most pairs; or one whose typical pair the
scorer itself judges different-die), the hoard's scores do not separate: the scorer's own probabilities are
kept and :attr:`HoardCalibration.message` says so in words, with the numbers, for ``coindie run`` and
``coindie status``.

The last test is the scorer's own judgement, and a scorer's sense of scale comes from its training hoards:
on another scanner the same-die pairs can all fall below log-odds 0 and still stand apart from the rest
(a coarse, noisy scanner of an independent generator: upper component -5.1 ± 3.3 against -16.2 ± 1.4).
Where only that test fails and the split is clear (Ashman's D at least :data:`OVERRULE_SEPARATION`, or
any split once each face's pull is off, :data:`OVERRULE_SEPARATION_AFTER_PULLS`; the upper component at
least :data:`OVERRULE_MIN_GAP` log-odds above the other),
:attr:`HoardCalibration.vetoed` says so, and ``calibrate_hoard(..., scorer_veto=False)`` gives the
mixture's calibration all the same; whether to trust it is left to the hoard's own clusters
(:func:`coindie.clustering.second_pass.cluster_twice`). Unless pairs the scorer judges same-die stand
apart above that upper component: then it is a level below the dies (pairs of one design, other dies, in a
hoard where most dies are known from one coin), the scorer's scale holds on these scans, and its own
probabilities are kept (:attr:`HoardCalibration.scorer_holds`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from coindie.arrays import FloatArray
from coindie.errors import ParameterError

#: Ashman's D between the two components below which they are not told apart.
MIN_SEPARATION = 2.0
#: Ashman's D a split must reach for the hoard's clusters to be asked to overrule the scorer's veto
#: (:attr:`HoardCalibration.vetoed`): a clear bimodality, not a mere one. On five all-hard hoards of
#: coindie's generator the vetoed splits below it (D 2.4-2.8) include one whose own clusters, at
#: silhouette 0.596 (a hair below the gate), would have taken its side from FMI 0.95 to 0.81; the splits
#: kept (D 3.2-3.9) and those of the independent generator's coarse and two-scanner hoards (4.0-5.5)
#: held (BENCHMARK.md, "An independent generator").
OVERRULE_SEPARATION = 3.0
#: The same, once each face's pull is taken off (the second pass, :func:`calibrated_side` with ``across``):
#: a split at all (:data:`MIN_SEPARATION`). The pulls were what made a murky hoard's split unclear; once they
#: are off, what remains between the components is the dies, and the split is still only asked, its
#: clusters kept where they stand out (:data:`coindie.clustering.second_pass.OVERRULE_AFTER_PULLS_SILHOUETTE`)
#: and its components far enough apart not to be designs (:data:`OVERRULE_MIN_GAP`). On fresh hoards of the
#: blind generator's hard kind (seed 34), two sides' second splits stood at D 2.98 and 2.79, a hair below
#: 3: their scorer's own probabilities, which no cut of the consensus reads, gave FMI 0.696 and 0.685, the
#: split's clusters (silhouettes 0.64) 0.954 and 0.932 (BENCHMARK.md, "Knife edges").
OVERRULE_SEPARATION_AFTER_PULLS = MIN_SEPARATION
#: Log-odds by which the upper component must stand above the other for the hoard's clusters to be asked
#: to overrule the scorer's veto (a likelihood ratio of e^5.5, about 250). A scanner unlike the scorer's
#: training scans lowers every same-die score but leaves them far above the rest: 7.8-17.5 on the vetoed
#: splits of sixteen hoards of the independent generator (seeds 15-18: coarse 10.1-11.0, two scanners
#: 16.8-17.5, all-hard 7.8-11.8) and 8.6 on coindie's all-hard hoard of the matrix. Pairs of one design and
#: other dies stand 2.8-3.7 above those of two designs (seed 19's hoards of two designs with few or no die
#: links; 1.9-2.0 on seed 20's coarse one, made after), where the overrule would take the designs for dies
#: (BENCHMARK.md, "A hoard of two designs and few die links"). Midway between the two: every value from
#: 3.8 to 7.7 gives the same clusters on every hoard measured.
OVERRULE_MIN_GAP = 5.5
#: Width, in scales of the mixture's upper component, of the empty band above it past which pairs the
#: scorer itself judges same-die show the upper component to be a level below the dies (pairs of one design,
#: other dies: :func:`_dies_above`). On the 32 sides of sixteen hoards of the independent generator
#: (seeds 15-18; every kind, vetoed or not) the widest band above the upper component's location was 1.0
#: of its scales; on a hoard of two designs where most dies are known from one coin (seed 19, 36 dies of
#: 40 coins a side), 10.4 and 13.1, with the 4 and 5 same-die pairs above it (BENCHMARK.md, "A hoard of
#: two designs and few die links").
DESIGN_LEVEL_GAP = 4.0
#: Fewest pairs past that band that make a level of likeness: a single pair far above the rest may be one
#: coin scanned twice (a duplicate scores at the top of the scale on any scanner), which would otherwise keep
#: a coarse hoard's clear split of its dies from its clusters.
MIN_PAIRS_APART = 2
#: Largest share of same-die pairs a hoard's mixture may claim: most of *all* same-side pairs are of
#: different dies. Pairs planned by candidate search are each face's nearest faces, mostly of its own die,
#: and may be up to :data:`MAX_SAME_SHARE_CANDIDATES` same-die.
MAX_SAME_SHARE = 0.5
MAX_SAME_SHARE_CANDIDATES = 0.95
#: Fewest scored pairs a mixture is fitted on.
MIN_PAIRS = 10
#: Log-odds are clipped to +-this before fitting (a probability of exactly 0 or 1 has no finite logit).
_MAX_LOG_ODDS = 30.0
#: Probabilities are clipped to [this, 1 - this] before their logit (1.0 and 0.0 have none)...
_PROBABILITY_CLIP = 1e-13
#: ... so a same-die population located above this sits on the clip (logit(1 - clip) - 1).
_SATURATED = float(np.log((1.0 - _PROBABILITY_CLIP) / _PROBABILITY_CLIP)) - 1.0
#: Smallest scale of a component (log-odds units): no component collapses onto a few pairs.
_MIN_SD = 0.25
#: Degrees of freedom of each component's Student-t (fixed: a heavy tail, a finite variance).
TAIL_DOF = 3.0
#: EM stops when the log-likelihood gains less than this share of itself, or after this many rounds.
_EM_TOLERANCE = 1e-9
_EM_ROUNDS = 500
#: Threshold on the calibrated probability. Dies are connected components of the kept links, so a false
#: link merges two whole dies while a missed one rarely splits a die (its coins are linked many times
#: over): the Bayes decision with a false link costing nine missed ones keeps a link above 0.9.
MIXTURE_THRESHOLD = 0.9


@dataclass(frozen=True)
class HoardCalibration:
    """The two populations of one hoard's scores, and whether they separate.

    ``same`` and ``different`` are (location, scale) of the log-odds of each component (a Student-t with
    :data:`TAIL_DOF` degrees of freedom); ``same_share`` the mixture weight of the same-die component;
    ``separation`` Ashman's D on the two scales; ``refused`` the pairs whose registration was refused (no
    pose), which the mixture does not see; ``vetoed``: the scores do not separate only because the
    scorer judges the upper component's typical pair different-die, and the mixture is otherwise a clear
    split (Ashman's D at least :data:`OVERRULE_SEPARATION`, or the ``overrule_separation`` it was fitted
    with; the components at least :data:`OVERRULE_MIN_GAP` apart); ``scorer_holds``: the scores do not
    separate as a mixture, but pairs the scorer judges same-die stand apart above the mixture's upper
    component (pairs of one design: :func:`_dies_above`), and its own probabilities are kept with its veto;
    ``apart``: where such pairs stand apart above the upper component but the scorer judges them
    different-die all the same, their number, lowest and highest log-odds and the empty band's width in
    scales (the upper component is not the dies, and those pairs are for a reviewer to look at).
    """

    n_pairs: int
    refused: int
    same_share: float
    same: tuple[float, float]
    different: tuple[float, float]
    separation: float
    separates: bool
    message: str
    vetoed: bool = False
    scorer_holds: bool = False
    apart: tuple[int, float, float, float] | None = None

    def probability(self, log_odds: ArrayLike) -> FloatArray:
        """Calibrated probability of each log-odds value: the mixture's posterior when the populations
        separate, else the scorer's own probability."""
        z = np.clip(np.asarray(log_odds, dtype=np.float64), -_MAX_LOG_ODDS, _MAX_LOG_ODDS)
        if not self.separates:
            return 0.5 * (1.0 + np.tanh(0.5 * z))
        grid = np.linspace(-_MAX_LOG_ODDS, _MAX_LOG_ODDS, 4001)
        posterior = self._posterior(grid)
        # Beyond each component's location, the other's tail (the wider or the heavier) may claim the
        # far scores again, an artefact of the mixture's shapes: above the typical same-die pair a score
        # keeps the largest posterior reached since, below the typical different-die pair the smallest;
        # then each score takes the smallest posterior at or above it (non-decreasing).
        above, below = grid >= self.same[0], grid <= self.different[0]
        posterior[above] = np.maximum.accumulate(posterior[above])
        posterior[below] = np.minimum.accumulate(posterior[below][::-1])[::-1]
        posterior = np.minimum.accumulate(posterior[::-1])[::-1]
        return np.interp(z, grid, posterior)

    def _posterior(self, z: FloatArray) -> FloatArray:
        w = self.same_share
        log_same = np.log(w) + _log_t(z, *self.same)
        log_different = np.log1p(-w) + _log_t(z, *self.different)
        return 1.0 / (1.0 + np.exp(np.clip(log_different - log_same, -700, 700)))

    def split(self, what: str, upper: str) -> str:
        """The two populations in words and numbers: ``N {what} scored: S% in {upper} (log-odds ...,
        Ashman's D ...)``, and the pairs the registration refused, if any."""
        (same, same_sd), (different, different_sd) = self.same, self.different
        return (
            f"{self.n_pairs} {what} scored: {self.same_share:.1%} in {upper} (log-odds {same:.2f} ± "
            f"{same_sd:.2f} against {different:.2f} ± {different_sd:.2f}, Ashman's D {self.separation:.2f})"
            + _refused_note(self.refused, self.n_pairs + self.refused)
        )

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def log_odds(probabilities: ArrayLike) -> FloatArray:
    """The logit of probabilities, clipped to a finite range."""
    p = np.clip(np.asarray(probabilities, dtype=np.float64), _PROBABILITY_CLIP, 1 - _PROBABILITY_CLIP)
    return np.clip(np.log(p) - np.log1p(-p), -_MAX_LOG_ODDS, _MAX_LOG_ODDS)


def calibrate_hoard(
    probabilities: ArrayLike,
    *,
    refused: int = 0,
    prior: Mapping[str, tuple[float, float]] | None = None,
    what: str = "same-side pairs",
    max_same_share: float = MAX_SAME_SHARE,
    scorer_veto: bool = True,
    overrule_separation: float = OVERRULE_SEPARATION,
) -> HoardCalibration:
    """Fit the two populations of a hoard's scored pairs (``probabilities`` of the pairs whose
    registration found a pose; ``refused`` the others). ``prior``: the scorer's training populations
    ``{"same": (mean, sd), "different": (mean, sd)}`` of the log-odds, where EM starts (as location
    and scale).
    ``max_same_share``: the largest plausible same-die share (:data:`MAX_SAME_SHARE` for every pair of
    a side, :data:`MAX_SAME_SHARE_CANDIDATES` for pairs planned by candidate search).
    ``scorer_veto``: whether an upper component whose typical pair the scorer judges different-die is
    refused (the default); False keeps the mixture where it is otherwise a split.
    ``overrule_separation``: the Ashman's D from which a split the scorer vetoes is :attr:`HoardCalibration.
    vetoed` (asked of the hoard's clusters), :data:`OVERRULE_SEPARATION` or, once each face's pull is off,
    :data:`OVERRULE_SEPARATION_AFTER_PULLS`."""
    z = log_odds(probabilities).ravel()
    total = len(z) + refused
    if refused < 0:
        raise ParameterError(f"refused must be >= 0. Got {refused}.")
    if len(z) < MIN_PAIRS:
        return _not_separated(
            z, refused, 0.0,
            f"only {len(z)} of {total} {what} could be scored, too few to tell same-die from different-die",
        )  # fmt: skip
    means, sds, weights = _fit(z, prior)
    (mean_d, mean_s), (sd_d, sd_s), share = means, sds, float(weights[1])
    if mean_s > _SATURATED:
        # most same-die pairs scored beyond what a stored probability holds: their log-odds pile at the
        # clip, so the spread of their population is unknown, and a scale fitted to the pile would hand
        # every same-die pair below it to the other dies (a sharp scorer on a clean hoard: a same-die pair
        # at log-odds 22 got 0.008). It is taken no narrower than the other population's.
        sd_s = max(sd_s, sd_d)
    separation = float(np.sqrt(2.0) * (mean_s - mean_d) / np.sqrt(sd_s**2 + sd_d**2))
    refused_note = _refused_note(refused, total)
    failures = _implausible(separation, share, len(z), max_same_share)
    judged_different = mean_s < 0.0  # by the scorer itself: its veto
    if judged_different and (scorer_veto or failures):
        failures.append(_VETO)
    above = _dies_above(z, mean_s, sd_s) if judged_different else None
    if above is not None and above[1] <= 0.0:
        # a level of likeness above the upper component, which the scorer judges different-die all the
        # same: that component is not the dies either (no overrule), and those pairs are for a reviewer
        n_top, low, high, band = above
        failures.append(
            f"{n_top} pairs stand apart above it (log-odds {low:.2f} to {high:.2f}, "
            f"past an empty band {band:.1f} of its scales wide): it is not the dies"
        )
    elif above is not None:  # the scorer's scale holds on these scans: no overrule either
        n_top, low, high, band = above
        message = (
            f"{len(z)} {what} scored: the scorer judges {n_top} same-die (log-odds {low:.2f} to {high:.2f}), "
            f"apart above the hoard's upper population ({share:.1%} of the pairs, log-odds {mean_s:.2f} ± "
            f"{sd_s:.2f} against {mean_d:.2f} ± {sd_d:.2f}) past an empty band {band:.1f} of its scales "
            f"wide: that population holds pairs of one design and other dies, and the scorer's own "
            f"probabilities are kept{refused_note}"
        )
        return _not_separated(
            z, refused, separation, message, share, (mean_s, sd_s), (mean_d, sd_d), scorer_holds=True
        )
    if failures:
        clear = failures == [_VETO] and separation >= overrule_separation
        close = mean_s - mean_d < OVERRULE_MIN_GAP
        alone = clear and not close
        unless = ", unless the clusters of the hoard's own mixture stand out (coindie cluster --auto)"
        near = (
            f"; the upper component stands only {mean_s - mean_d:.1f} log-odds above the other, less than "
            f"the {OVERRULE_MIN_GAP:g} of other dies on other scans (it may hold pairs of one design)"
        )
        reason = (
            f"the scores of {len(z)} {what} do not separate into same-die and different-die populations "
            f"({'; '.join(failures)}; upper component log-odds {mean_s:.2f} ± {sd_s:.2f} against "
            f"{mean_d:.2f} ± {sd_d:.2f}){refused_note}: the scorer's own probabilities are kept"
            + (unless if alone else near if clear else "")
            + "; check the scans' quality and the registrations"
        )
        return _not_separated(
            z, refused, separation, reason, share, (mean_s, sd_s), (mean_d, sd_d), vetoed=alone, apart=above
        )
    calibration = HoardCalibration(
        len(z), refused, share, (float(mean_s), float(sd_s)), (float(mean_d), float(sd_d)), separation, True,
        "",
    )  # fmt: skip
    message = calibration.split(what, "the same-die population")
    if judged_different:
        message += " (kept although the scorer judges its typical same-die pair different-die)"
    return replace(calibration, message=message)


def calibrated_probabilities(
    probabilities: ArrayLike,
    valid: ArrayLike,
    *,
    prior: Mapping[str, tuple[float, float]] | None = None,
    what: str = "same-side pairs",
    max_same_share: float = MAX_SAME_SHARE,
    scorer_veto: bool = True,
    overrule_separation: float = OVERRULE_SEPARATION,
) -> tuple[FloatArray, HoardCalibration]:
    """The hoard-calibrated probability of each pair of one side (0 where the registration was refused,
    ``valid`` False), and the calibration."""
    p = np.asarray(probabilities, dtype=np.float64)
    ok = np.asarray(valid, dtype=bool)
    calibration = calibrate_hoard(
        p[ok], refused=int((~ok).sum()), prior=prior, what=what, max_same_share=max_same_share,
        scorer_veto=scorer_veto, overrule_separation=overrule_separation,
    )  # fmt: skip
    out = np.zeros_like(p)
    out[ok] = calibration.probability(log_odds(p[ok]))
    return out, calibration


def calibrated_side(
    probabilities: ArrayLike,
    valid: ArrayLike,
    sources: Sequence[str],
    targets: Sequence[str],
    *,
    across: Mapping[str, object] | None = None,
    prior: Mapping[str, tuple[float, float]] | None = None,
    what: str = "same-side pairs",
    max_same_share: float = MAX_SAME_SHARE,
    scorer_veto: bool = True,
) -> tuple[FloatArray, HoardCalibration]:
    """:func:`calibrated_probabilities` of one side's pairs, named by their faces (``sources``,
    ``targets``); with ``across`` (a first clustering, face id -> label), each face's pull on its scores,
    fitted on the pairs across those clusters, is taken off first
    (:func:`coindie.similarity.face_effects.without_face_effects_across`), and a split the scorer vetoes is
    asked of the hoard's clusters from :data:`OVERRULE_SEPARATION_AFTER_PULLS`."""
    from coindie.similarity.face_effects import without_face_effects_across

    p = np.asarray(probabilities, dtype=np.float64)
    if across is not None and len(p):
        p = without_face_effects_across(p, valid, sources, targets, across)
    overrule = OVERRULE_SEPARATION if across is None else OVERRULE_SEPARATION_AFTER_PULLS
    return calibrated_probabilities(
        p, valid, prior=prior, what=what, max_same_share=max_same_share, scorer_veto=scorer_veto,
        overrule_separation=overrule,
    )  # fmt: skip


#: The scorer's veto on a mixture (:func:`calibrate_hoard`): its typical member is judged different-die by
#: the scorer itself (log-odds < 0: on the scorer's own kind of scans, the split is then between kinds of
#: different-die pairs, such as other designs and other dies of one design).
_VETO = "its typical pair is judged different-die by the scorer (mean log-odds < 0)"


def _implausible(separation: float, share: float, n: int, max_same_share: float) -> list[str]:
    """Why a fitted mixture is not a same-die / different-die split ([] when it is), the scorer's veto
    aside: its components overlap; its upper one holds less than one pair, or most pairs (most pairs of
    a hoard are of different dies)."""
    failures = []
    if separation < MIN_SEPARATION:
        failures.append(f"Ashman's D {separation:.2f} < {MIN_SEPARATION:g}")
    if share * n < 1.0:
        failures.append(f"upper component {share:.1%} of the pairs, less than one pair")
    if share > max_same_share:
        failures.append(f"upper component {share:.1%} of the pairs, more than {max_same_share:.0%}")
    return failures


def _dies_above(z: FloatArray, mean_s: float, sd_s: float) -> tuple[int, float, float, float] | None:
    """Pairs standing apart above the mixture's upper component: past the widest empty band above its
    location, where that band is at least :data:`DESIGN_LEVEL_GAP` of its scales wide and they are at least
    :data:`MIN_PAIRS_APART`. Their number,
    lowest and highest log-odds, and the band's width in scales; None where there are none.

    A hoard of two designs whose dies are mostly known from one coin each: its mixture splits the pairs of
    one design (other dies, half the pairs) from those of two, and their clusters, the designs, stand out
    as dies would. The few same-die pairs stand apart above that upper component, the finest level of
    likeness. Where the scorer judges them same-die (log-odds > 0), its scale holds on these scans; where
    it does not (a coarse scanner: an independent generator's two-design hoard of seed 19, 4 same-die
    obverse pairs at -10.5 to -8.4 above pairs of one design up to -14.9), the upper component is still not
    the dies. Where it is the dies, its tail reaches its highest pairs without such a gap."""
    tail = np.sort(z[z > mean_s])
    if len(tail) < 2:
        return None
    gaps = np.diff(tail)
    widest = int(np.argmax(gaps))
    top = tail[widest + 1 :]
    if gaps[widest] < DESIGN_LEVEL_GAP * sd_s or len(top) < MIN_PAIRS_APART:
        return None
    return len(top), float(top[0]), float(top[-1]), float(gaps[widest] / sd_s)


def _fit(z: FloatArray, prior: Mapping[str, tuple[float, float]] | None) -> tuple[FloatArray, ...]:
    """Locations, scales and weights of the (different, same) components: EM from the prior and from the
    data's bulk and upper tail, the fit of the higher likelihood kept.

    The prior alone is not enough: on another scanner both populations can lie far from the scorer's
    training ones, and EM started there may split the bulk of the different-die pairs instead (a coarse
    scanner of the independent generator, obverses: 57 % of the pairs at log-odds -19.4 against -20.8,
    log-likelihood -1,579; from the data's upper tail, 7.5 % at -8.3 against -20.3, -1,449, where 7.8 %
    are of one die). Multiple starts are the usual guard of EM against such local optima."""
    starts = [
        (np.array([np.median(z), np.quantile(z, 0.98)]), np.full(2, max(float(np.std(z)) / 2.0, _MIN_SD)))
    ]
    if prior and "same" in prior and "different" in prior:
        location = np.array([prior["different"][0], prior["same"][0]], dtype=np.float64)
        scale = np.maximum([prior["different"][1], prior["same"][1]], _MIN_SD).astype(np.float64)
        starts.insert(0, (location, scale))
    best, best_likelihood = None, -np.inf
    for location, scale in starts:
        if location[1] <= location[0]:
            location[1] = location[0] + 2 * scale.max()
        fit = _t_mixture_em(z, location, scale, np.array([0.9, 0.1]))
        likelihood = _log_likelihood(z, *fit)
        if best is None or likelihood > best_likelihood + 1e-9 * abs(best_likelihood):
            best, best_likelihood = fit, likelihood
    assert best is not None
    return best


def _log_likelihood(z: FloatArray, location: FloatArray, scale: FloatArray, weight: FloatArray) -> float:
    """Log-likelihood of a fitted two-component t mixture."""
    joint = np.stack([np.log(w) + _log_t(z, m, s) for m, s, w in zip(location, scale, weight, strict=True)])
    return float(np.sum(np.logaddexp(joint[0], joint[1])))


def _t_mixture_em(
    z: FloatArray, location: FloatArray, scale: FloatArray, weight: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """EM for a two-component mixture of Student-t with :data:`TAIL_DOF` degrees of freedom: each
    pair's responsibility per component, and its weight in that component (a pair far from the
    location weighs less: the t as a Gaussian scale mixture), then weighted location and scale."""
    nu = TAIL_DOF
    previous = -np.inf
    for _ in range(_EM_ROUNDS):
        densities = [_log_t(z, m, s) for m, s in zip(location, scale, strict=True)]
        joint = np.log(weight)[None, :] + np.stack(densities, axis=1)
        top = joint.max(axis=1, keepdims=True)
        log_likelihood = float(np.sum(top[:, 0] + np.log(np.exp(joint - top).sum(axis=1))))
        responsibility = np.exp(joint - top)
        responsibility /= responsibility.sum(axis=1, keepdims=True)
        for k in range(2):
            u = (nu + 1.0) / (nu + ((z - location[k]) / scale[k]) ** 2)
            r, ru = responsibility[:, k], responsibility[:, k] * u
            if r.sum() <= 1e-12:
                continue
            location[k] = float(np.sum(ru * z) / ru.sum())
            scale[k] = max(float(np.sqrt(np.sum(ru * (z - location[k]) ** 2) / r.sum())), _MIN_SD)
        weight = np.clip(responsibility.mean(axis=0), 1e-9, 1.0 - 1e-9)
        if log_likelihood - previous <= _EM_TOLERANCE * abs(log_likelihood):
            break
        previous = log_likelihood
    order = np.argsort(location)
    return location[order], scale[order], weight[order]


def _refused_note(refused: int, total: int) -> str:
    return f"; {refused} of {total} ({refused / total:.0%}) refused by the registration" if refused else ""


def _not_separated(
    z: FloatArray,
    refused: int,
    separation: float,
    message: str,
    share: float = float("nan"),
    same: tuple[float, float] = (float("nan"), float("nan")),
    different: tuple[float, float] = (float("nan"), float("nan")),
    *,
    vetoed: bool = False,
    scorer_holds: bool = False,
    apart: tuple[int, float, float, float] | None = None,
) -> HoardCalibration:
    return HoardCalibration(
        len(z), refused, share, (float(same[0]), float(same[1])), (float(different[0]), float(different[1])),
        separation, False, message, vetoed, scorer_holds, apart,
    )  # fmt: skip


def _log_t(z: FloatArray, location: float, scale: float) -> FloatArray:
    """Log-density of a Student-t with :data:`TAIL_DOF` degrees of freedom (``scipy.stats.t.logpdf``,
    written out: EM calls it twice a round on every pair of a side)."""
    from scipy.special import gammaln

    nu = TAIL_DOF
    constant = gammaln((nu + 1.0) / 2.0) - gammaln(nu / 2.0) - 0.5 * np.log(nu * np.pi) - np.log(scale)
    return constant - (nu + 1.0) / 2.0 * np.log1p(((np.asarray(z) - location) / scale) ** 2 / nu)
