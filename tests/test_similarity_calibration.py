"""The per-hoard calibration: two populations recovered from a hoard's own scores, without labels."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.similarity.calibration import (
    MIN_SEPARATION,
    MIXTURE_THRESHOLD,
    OVERRULE_SEPARATION,
    calibrate_hoard,
    calibrated_probabilities,
    calibrated_side,
    log_odds,
)

# Linear algebra under test (the mixture fit and the logistic calibration):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric


def _mixture(share: float, n: int, seed: int, same=(5.0, 2.5), different=(-7.0, 1.5)) -> tuple:
    rng = np.random.default_rng(seed)
    same_die = rng.random(n) < share
    z = np.where(same_die, rng.normal(*same, n), rng.normal(*different, n))
    return 1.0 / (1.0 + np.exp(-z)), same_die


@pytest.mark.parametrize("share", [0.03, 0.12, 0.3])
def test_the_same_die_share_of_a_score_mixture_is_recovered(share: float) -> None:
    probabilities, same_die = _mixture(share, 3000, seed=int(share * 100))
    calibration = calibrate_hoard(probabilities)
    assert calibration.separates, calibration.message
    assert abs(calibration.same_share - same_die.mean()) < 0.02
    assert calibration.same[0] == pytest.approx(5.0, abs=0.5)
    assert calibration.different[0] == pytest.approx(-7.0, abs=0.3)


def test_a_prior_from_another_scanner_is_corrected_by_the_hoard() -> None:
    """The scorer's training populations sit elsewhere (another scanner): EM moves to this hoard's."""
    probabilities, same_die = _mixture(0.15, 2000, seed=4, same=(1.0, 1.0), different=(-4.0, 1.0))
    prior = {"same": (8.0, 3.0), "different": (-8.0, 2.0)}
    calibration = calibrate_hoard(probabilities, prior=prior)
    assert calibration.separates
    assert abs(calibration.same_share - same_die.mean()) < 0.03
    calibrated = calibration.probability(log_odds(probabilities))
    # on this hoard, the model's own 0.5 (log-odds 0) would miss most same-die pairs (mean log-odds 1)
    # and the calibrated probabilities keep most of them while keeping few different-die pairs (the t
    # components' heavy tails leave some doubt on the lower same-die pairs, so fewer pass 0.9 than 0.5)
    assert (calibrated[same_die] > 0.5).mean() > 0.9 and (calibrated[~same_die] > 0.5).mean() < 0.01
    kept = calibrated > MIXTURE_THRESHOLD
    assert kept[same_die].mean() > 0.7 and kept[~same_die].mean() < 0.01


def test_calibrated_probabilities_never_fall_as_the_score_rises() -> None:
    """A same-die component wider than the other would claim the far left tail too: it must not."""
    probabilities, _ = _mixture(0.2, 2000, seed=5, same=(4.0, 4.0), different=(-6.0, 1.0))
    calibration = calibrate_hoard(probabilities)
    grid = np.linspace(-30, 30, 601)
    posterior = calibration.probability(grid)
    assert np.all(np.diff(posterior) >= -1e-12)
    assert posterior[0] < 0.01 and posterior[-1] > 0.99


def test_other_dies_of_one_design_do_not_pass_for_the_same_die() -> None:
    """A hoard's different-die pairs are a mixture: other designs far below, other dies of the same
    design close below the same-die pairs, a heavier upper tail than a Gaussian's. The calibration must
    not hand that tail to the same die (Gaussian components do: 34 of these different-die pairs above
    0.9 and the same-die share 4.7 points too high)."""
    rng = np.random.default_rng(9)
    n = 2000
    same_die = rng.random(n) < 0.3
    design_mate = rng.random(n) < 0.2
    different = np.where(design_mate, rng.normal(-2.0, 1.5, n), rng.normal(-5.0, 1.0, n))
    z = np.where(same_die, rng.normal(12.0, 7.0, n), different)
    calibration = calibrate_hoard(1.0 / (1.0 + np.exp(-z)))
    assert calibration.separates, calibration.message
    assert abs(calibration.same_share - same_die.mean()) < 0.02
    calibrated = calibration.probability(z)
    assert (calibrated[~same_die] > MIXTURE_THRESHOLD).sum() <= 0.005 * (~same_die).sum()
    assert (calibrated[same_die] > MIXTURE_THRESHOLD).mean() > 0.85


def test_same_die_scores_piled_at_the_largest_log_odds_still_claim_the_lower_same_die_pairs() -> None:
    """A sharp scorer on a clean hoard: most same-die probabilities round to 1, so their log-odds pile
    at the clip. The same-die component must not shrink onto that pile and hand the same-die pairs just
    below it to the other dies (it did, at the smallest scale: a pair at log-odds 22 got 0.008)."""
    rng = np.random.default_rng(11)
    n = 1500
    same_die = rng.random(n) < 0.2
    z = np.where(same_die, rng.normal(40.0, 8.0, n), rng.normal(-2.0, 4.0, n))
    probabilities = 1.0 / (1.0 + np.exp(-z))  # those above ~37 are exactly 1.0
    assert (probabilities[same_die] == 1.0).mean() > 0.5
    calibration = calibrate_hoard(probabilities)
    assert calibration.separates, calibration.message
    calibrated = calibration.probability(log_odds(probabilities))
    lower_same = same_die & (z > 22.0) & (z < 28.0)  # 6 to 7 of the other dies' sd above their mean
    assert lower_same.sum() >= 10
    assert (calibrated[lower_same] > MIXTURE_THRESHOLD).all()
    assert (calibrated[~same_die] > MIXTURE_THRESHOLD).mean() < 0.01


def test_scores_of_one_population_are_reported_as_not_separating() -> None:
    rng = np.random.default_rng(6)
    z = rng.normal(-2.0, 1.5, 500)
    calibration = calibrate_hoard(1.0 / (1.0 + np.exp(-z)), refused=300, what="obverse pairs")
    assert not calibration.separates
    assert "do not separate" in calibration.message and "300 of 800" in calibration.message
    # the scorer's own probabilities are kept
    np.testing.assert_allclose(calibration.probability(z), 1.0 / (1.0 + np.exp(-z)), atol=1e-9)


def test_refused_pairs_stay_at_zero_and_too_few_pairs_do_not_calibrate() -> None:
    probabilities, _ = _mixture(0.2, 400, seed=7)
    valid = np.ones(400, dtype=bool)
    valid[:50] = False
    calibrated, calibration = calibrated_probabilities(probabilities, valid)
    assert calibration.refused == 50 and np.all(calibrated[:50] == 0)
    few = calibrate_hoard(probabilities[:5])
    assert not few.separates and "only 5" in few.message


def test_most_pairs_same_die_is_implausible_for_every_pair_but_not_for_candidates() -> None:
    """Among every pair of a side most are of different dies; candidate search picks each face's nearest
    faces, mostly of its own die."""
    probabilities, same_die = _mixture(0.7, 1000, seed=8)
    every_pair = calibrate_hoard(probabilities)
    assert not every_pair.separates and "more than 50%" in every_pair.message
    candidates = calibrate_hoard(probabilities, max_same_share=0.95)
    assert candidates.separates and abs(candidates.same_share - same_die.mean()) < 0.03


def test_a_scorer_from_other_scans_vetoes_a_split_that_the_hoard_can_still_have() -> None:
    """Another scanner lowers every same-die score below log-odds 0, yet they stand apart from the other
    dies' (an independent generator's coarse scanner: -5.1 +- 3.3 against -16.2 +- 1.4). The scorer's
    judgement refuses the split and says it alone did (``vetoed``); without the veto the hoard's mixture
    is a split, with the right share. Any other failure is not a veto alone."""
    probabilities, same_die = _mixture(0.12, 1500, seed=21, same=(-5.0, 2.5), different=(-16.0, 1.5))
    vetoed = calibrate_hoard(probabilities)
    assert not vetoed.separates and vetoed.vetoed
    assert "judged different-die by the scorer" in vetoed.message and "unless" in vetoed.message
    mixture = calibrate_hoard(probabilities, scorer_veto=False)
    assert mixture.separates and not mixture.vetoed
    assert abs(mixture.same_share - same_die.mean()) < 0.02
    calibrated = mixture.probability(log_odds(probabilities))
    assert (calibrated[same_die] > MIXTURE_THRESHOLD).mean() > 0.85  # the populations overlap below that
    assert (calibrated[~same_die] > MIXTURE_THRESHOLD).mean() < 0.005
    # most pairs in the upper component as well: not a split, veto or not
    crowded, _ = _mixture(0.7, 1000, seed=22, same=(-5.0, 2.5), different=(-16.0, 1.5))
    for veto in (True, False):
        refused = calibrate_hoard(crowded, scorer_veto=veto)
        assert not refused.separates and not refused.vetoed and "more than 50%" in refused.message


def test_once_the_pulls_are_off_a_split_that_is_not_clear_is_asked_of_the_hoards_clusters() -> None:
    """A murky side's split, vetoed by the scorer, far apart (not designs) but wide: Ashman's D between 2 and
    3 (the blind generator's hard-34 reverses once the pulls were off: 2.98, 9.8 log-odds apart). Before
    the pulls are off such a split is not asked (only a clear one is); after, it is. A close split (designs)
    is not asked either way, and neither is one below D 2."""
    rng = np.random.default_rng(34)
    same_die = rng.random(780) < 0.17  # worn, crusted same-die pairs: a wide, heavy-tailed population
    z = np.where(same_die, -8.0 + 4.0 * rng.standard_t(3, 780), rng.normal(-14.5, 1.6, 780))
    probabilities = 1.0 / (1.0 + np.exp(-z))
    first = calibrate_hoard(probabilities)
    assert MIN_SEPARATION <= first.separation < OVERRULE_SEPARATION, first.separation
    assert not first.separates and not first.vetoed
    pulls_off = calibrate_hoard(probabilities, overrule_separation=MIN_SEPARATION)
    assert not pulls_off.separates and pulls_off.vetoed and "unless" in pulls_off.message
    # calibrated_side asks it once each face's pull is off (``across``), not before
    faces = [f"L{k:04d}D" for k in range(40)]
    i, j = np.triu_indices(40, k=1)
    sources, targets = [faces[a] for a in i], [faces[b] for b in j]
    valid = np.ones(len(i), dtype=bool)
    one_cluster_each = {face: k for k, face in enumerate(faces)}
    _, before = calibrated_side(probabilities, valid, sources, targets)
    _, after = calibrated_side(probabilities, valid, sources, targets, across=one_cluster_each)
    assert not before.vetoed and after.vetoed
    # two designs: as wide a split, but the components close; and a split that is no split (D < 2)
    close, _ = _mixture(0.3, 780, seed=35, same=(-15.0, 1.2), different=(-18.0, 0.6))
    blurred, _ = _mixture(0.17, 780, seed=35, same=(-11.0, 3.0), different=(-14.5, 1.6))
    for probabilities in (close, blurred):
        calibration = calibrate_hoard(probabilities, overrule_separation=MIN_SEPARATION)
        assert not calibration.separates and not calibration.vetoed, calibration.message


def test_em_started_far_from_another_scanners_scores_still_finds_its_same_die_pairs() -> None:
    """A coarse scanner's scores all lie far below the scorer's training populations, its different-die
    pairs a narrow heavy-tailed bulk (other designs a little below other dies of one design). EM started
    from the prior alone split that bulk in two; started also from the data's upper tail, the fit of the
    higher likelihood is the same-die population (an independent generator's coarse hoard: -8.3 against
    -20.3, 7.5 % of the pairs, 7.8 % of one die)."""
    rng = np.random.default_rng(31)
    n = 780
    same_die = rng.random(n) < 0.08
    other_design = rng.random(n) < 0.55
    z = np.where(
        same_die,
        -8.3 + 1.5 * rng.standard_normal(n),
        np.where(other_design, -20.8, -19.6) + 0.4 * rng.standard_t(3, n),
    )
    probabilities = 1.0 / (1.0 + np.exp(-z))
    prior = {"same": (10.7, 5.0), "different": (-9.1, 3.2)}
    calibration = calibrate_hoard(probabilities, prior=prior, scorer_veto=False)
    assert calibration.separates, calibration.message
    assert abs(calibration.same_share - same_die.mean()) < 0.02
    assert calibration.same[0] == pytest.approx(-8.3, abs=1.0)
    calibrated = calibration.probability(log_odds(probabilities))
    assert (calibrated[same_die] > MIXTURE_THRESHOLD).mean() > 0.9
    assert (calibrated[~same_die] > MIXTURE_THRESHOLD).mean() < 0.005


def _two_designs(n_same: int, seed: int, same=(12.0, 4.0)) -> tuple:
    """The pairs of a 40-coin side of two designs whose dies are mostly known from one coin: ``n_same``
    same-die pairs scored around ``same``, the other pairs of one design at log-odds -15 +- 1.2 and those
    of two designs at -19 +- 0.6 (an independent generator's ordinary hoard of seed 19, 36 dies of 40
    coins: 4 and 5 same-die pairs at 2.7-20, the rest as here)."""
    rng = np.random.default_rng(seed)
    i, j = np.triu_indices(40, k=1)
    design_pair = (i % 2) == (j % 2)
    same_die = np.zeros(len(i), dtype=bool)
    same_die[rng.choice(np.flatnonzero(design_pair), n_same, replace=False)] = True
    z = np.where(design_pair, rng.normal(-15.0, 1.2, len(i)), rng.normal(-19.0, 0.6, len(i)))
    z[same_die] = rng.normal(*same, n_same)
    return 1.0 / (1.0 + np.exp(-z)), same_die


@pytest.mark.parametrize("seed", range(3))
def test_same_die_pairs_above_the_pairs_of_one_design_keep_the_scorers_veto(seed: int) -> None:
    """The mixture splits the pairs of one design (half of the pairs, far below log-odds 0) from those of
    two; the scorer judges the few same-die pairs same-die, far above them. Its scale holds on these scans:
    the split is neither kept nor left for the hoard's clusters to overrule (they would be the designs),
    and the scorer's own probabilities tell the same-die pairs apart, in words and numbers."""
    probabilities, same_die = _two_designs(5, seed)
    for veto in (True, False):
        calibration = calibrate_hoard(probabilities, scorer_veto=veto)
        assert calibration.scorer_holds and not calibration.vetoed and not calibration.separates
    assert "the scorer judges 5 same-die" in calibration.message
    assert "pairs of one design" in calibration.message
    calibrated = calibration.probability(log_odds(probabilities))
    assert (calibrated[same_die] > 0.5).all() and (calibrated[~same_die] < 0.01).all()


def test_a_tail_of_the_upper_population_across_log_odds_0_is_no_level_above_it() -> None:
    """A two-scanner hoard: the same-die pairs of the better scanner score above 0, those of the worse
    below, one population whose tail crosses 0 without a gap. The scorer's veto is still left to the
    hoard's clusters; and so is a split whose upper pairs all score below 0."""
    crossing, _ = _mixture(0.1, 780, seed=41, same=(-2.0, 5.0), different=(-19.0, 1.7))
    below, _ = _mixture(0.12, 780, seed=42, same=(-9.0, 1.5), different=(-19.5, 1.0))
    for probabilities in (crossing, below):
        calibration = calibrate_hoard(probabilities)
        assert calibration.vetoed and not calibration.scorer_holds, calibration.message


def test_pairs_of_one_design_without_die_links_are_not_left_to_the_hoards_clusters() -> None:
    """Two designs and no die link: the mixture splits the pairs of one design from those of two,
    clearly (Ashman's D above 3), and the scorer vetoes it. Its upper component stands 4 log-odds above
    the other, where other dies' same-die pairs on other scans stood 7.8 or more: the veto is not left to
    the hoard's clusters to overrule (they would be the designs), and the message says why."""
    probabilities, same_die = _two_designs(0, seed=5)
    assert not same_die.any()
    calibration = calibrate_hoard(probabilities)
    assert calibration.separation > 3 and not calibration.vetoed and not calibration.scorer_holds
    gap = calibration.same[0] - calibration.different[0]
    assert 3.5 < gap < 4.5 and f"stands only {gap:.1f} log-odds above" in calibration.message
    # the same split 11 log-odds apart: other dies on other scans, left to the clusters
    far = log_odds(probabilities)
    far[far > -17.0] += 7.0
    assert calibrate_hoard(1.0 / (1.0 + np.exp(-far))).vetoed


def test_same_die_pairs_the_scorer_judges_different_die_above_the_pairs_of_one_design() -> None:
    """A coarse scanner lowers every score: the few same-die pairs of a two-design hoard score below 0, but
    stand apart above the pairs of one design (seed 19's coarse hoard: -10.5 to -8.4 against at most -14.9).
    The upper component is not the dies: no overrule, the scorer's own probabilities, and the pairs above
    are named for a reviewer (``apart``), not linked."""
    probabilities, same_die = _two_designs(5, seed=7, same=(-5.0, 0.8))
    calibration = calibrate_hoard(probabilities)
    assert not calibration.vetoed and not calibration.scorer_holds and not calibration.separates
    assert calibration.apart is not None and calibration.apart[0] == 5
    assert calibration.apart[1] == pytest.approx(log_odds(probabilities)[same_die].min())
    assert "5 pairs stand apart above it" in calibration.message
    assert (calibration.probability(log_odds(probabilities)) < 0.5).all()
    # a split of other dies on other scans has no such level above it
    assert (
        calibrate_hoard(_mixture(0.12, 780, seed=43, same=(-9.0, 1.5), different=(-19.5, 1.0))[0]).apart
        is None
    )


def test_one_coin_scanned_twice_does_not_keep_a_clear_split_from_the_hoards_clusters() -> None:
    """A coarse scanner's clear split of its dies, which the scorer vetoes, and one coin scanned twice: that
    pair scores at the top of the scale, far above the rest. One pair is no level of likeness: the split
    is still left to the hoard's clusters. Two such pairs are."""
    probabilities, _ = _mixture(0.12, 780, seed=44, same=(-9.0, 1.5), different=(-19.5, 1.0))
    duplicate = 1.0 - 1e-12
    once = calibrate_hoard(np.append(probabilities, duplicate))
    assert once.vetoed and once.apart is None and not once.scorer_holds, once.message
    twice = calibrate_hoard(np.append(probabilities, [duplicate, duplicate]))
    assert twice.scorer_holds and not twice.vetoed
