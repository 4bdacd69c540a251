"""Synthetic hoards: coins struck by known dies, scanned, with the exact truth.

The physics (``design``, ``life``, ``strike``, ``circulation``, ``scanner``, ``face.make_face``) makes one
face; the hoard side plans a whole hoard (``presets``, ``plan``: dies, die links, strike times, splits),
generates it in parallel (``hoard``), writes its files (``writer``) and compares it with the real study
(``calibration``). Start with :func:`coindie.synth.hoard.synthesize` or ``coindie synth``.
"""

from coindie.synth.plan import DiePlan, FacePlan, HoardPlan, derived_seed, link_stats, plan_hoard
from coindie.synth.presets import FAMILIES, PRESETS, SPLITS, DieGroup, LinkParams, Preset, get_preset

__all__ = [
    "FAMILIES",
    "PRESETS",
    "SPLITS",
    "DieGroup",
    "DiePlan",
    "FacePlan",
    "HoardPlan",
    "LinkParams",
    "Preset",
    "derived_seed",
    "get_preset",
    "link_stats",
    "plan_hoard",
]
