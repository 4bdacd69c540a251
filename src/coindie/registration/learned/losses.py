"""The contrastive loss with hardest-negative mining that trains FCGF (Riedones3D paper, eq. 1).

For positive matches ``(i, j)`` (source point i and target point j are the same place of the die):

    L = mean [ |F_i - G_j| - m+ ]_+^2
      + 1/2 mean [ m- - min_k |F_i - G_k| ]_+^2     (k: target candidates, not near j)
      + 1/2 mean [ m- - min_k |F_k - G_j| ]_+^2     (k: source candidates, not near i)

Positives are a random subset of the matches; the hardest negatives are searched among a random subset
of each cloud's points ("candidates"), excluding those within ``negative_radius`` of the true match
(they are the same place, up to the voxel size: calling them negatives would fight the positives).
Means rather than the paper's sums, so that the loss does not scale with the number of positives.
"""

from __future__ import annotations

from dataclasses import dataclass

import torch
from torch import Tensor

from coindie.params import Configurable, param


@dataclass(frozen=True)
class ContrastiveLoss(Configurable):
    """The loss's settings (the paper's margins: m+ = 0.1, m- = 1.4)."""

    pos_margin: float = param(0.1, doc="matched descriptors closer than this cost nothing", low=0.0)
    neg_margin: float = param(1.4, doc="unmatched descriptors farther than this cost nothing", low=0.0)
    n_positives: int = param(1024, doc="true matches per pair in the loss", low=1)
    n_candidates: int = param(256, doc="candidates searched for the hardest negative", low=1)
    negative_radius: float = param(
        0.3, doc="points this close to a match are not its negatives", unit="mm", low=0.0
    )

    def __call__(
        self,
        f_source: Tensor,
        f_target: Tensor,
        matches: Tensor,
        x_source: Tensor,
        x_target: Tensor,
        generator: torch.Generator | None = None,
    ) -> dict[str, Tensor]:
        """Loss terms of one pair: descriptors (N, D) and (M, D), matches (K, 2) rows (source, target),
        point positions (N, 3) and (M, 3) in mm (each in its own frame). Returns ``loss`` (to minimise),
        ``positive`` and ``negative`` (its parts), ``pos_distance`` and ``neg_distance`` (means)."""
        chosen = _sample(len(matches), self.n_positives, generator, matches.device)
        i, j = matches[chosen, 0], matches[chosen, 1]
        d_pos = _row_distances(f_source[i], f_target[j])
        hard_t = self._hardest(f_source[i], f_target, x_target[j], x_target, generator)
        hard_s = self._hardest(f_target[j], f_source, x_source[i], x_source, generator)
        positive = torch.relu(d_pos - self.pos_margin).pow(2).mean()
        negative = 0.5 * (
            torch.relu(self.neg_margin - hard_t).pow(2).mean()
            + torch.relu(self.neg_margin - hard_s).pow(2).mean()
        )
        return {
            "loss": positive + negative,
            "positive": positive.detach(),
            "negative": negative.detach(),
            "pos_distance": d_pos.detach().mean(),
            "neg_distance": torch.cat([hard_t, hard_s]).detach().mean(),
        }

    def _hardest(
        self,
        anchors: Tensor,
        features: Tensor,
        x_true: Tensor,
        x_all: Tensor,
        generator: torch.Generator | None,
    ) -> Tensor:
        """Per anchor, the smallest descriptor distance to a candidate farther than ``negative_radius``
        from the anchor's true match (``neg_margin`` when every candidate is near: no loss)."""
        k = _sample(len(features), self.n_candidates, generator, features.device)
        distances = _pairwise_distances(anchors, features[k])
        near = torch.cdist(x_true.double(), x_all[k].double()) <= self.negative_radius
        far_enough = distances.masked_fill(near, float("inf")).min(dim=1).values
        return far_enough.clamp_max(self.neg_margin)


def _sample(n: int, k: int, generator: torch.Generator | None, device: torch.device) -> Tensor:
    """``min(n, k)`` distinct random rows of ``n``."""
    order = torch.randperm(n, generator=generator)
    return order[: min(n, k)].to(device)


def _row_distances(a: Tensor, b: Tensor) -> Tensor:
    # Clamped before the square root: its gradient is infinite at 0 (identical descriptors).
    return (a - b).pow(2).sum(dim=1).clamp_min(1e-12).sqrt()


def _pairwise_distances(a: Tensor, b: Tensor) -> Tensor:
    squared = a.pow(2).sum(1, keepdim=True) + b.pow(2).sum(1)[None, :] - 2.0 * a @ b.T
    return squared.clamp_min(1e-12).sqrt()
