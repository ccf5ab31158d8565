"""Adaptive sampling: more samples where a frame's estimated error is above a target (issue 16).

A frame is rendered in passes by :class:`~oceanrender.render.pixels.PixelSampler`.
Each pixel's samples alternate between two halves A and B, so the halves are
independent estimates and the error of their mean is estimated per pixel from
their difference, in whatever measure the caller gives (``benchmarks/bench_quality.py``
uses ΔE00 after the vision model: ``error_of(A, B)``). For unbiased Monte Carlo the
error of an n-sample mean falls as n^(−1/2) (e.g. Pharr, Jakob & Humphreys 2016,
*PBRT* 3rd ed., §13.11 "adaptive sampling", and Rousselle, Knaus & Zwicker 2011,
doi:10.1145/2070781.2024193, who drive sample density by estimated error), so a
pixel at error e after n samples needs ≈ n (e / target)² to reach the target;
when the budget cannot buy that everywhere, the rest is spent to minimise the
mean error (:func:`budget_allocation`).
The per-pixel estimate from two halves is itself noisy; it is smoothed over a
3×3 neighbourhood (mean of e²) before it decides.

Choosing counts from the samples already taken makes the final mean slightly
biased (the stopping rule depends on the estimate); the benchmark reports that
bias (BENCHMARKS.md, "Time to quality").
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from .pixels import PixelSampler, PixelSums


def smoothed_error(error: np.ndarray, radius: int = 1) -> np.ndarray:
    """√(mean of e² over the (2r+1)² neighbourhood) of a per-pixel error map (H, W), edges replicated."""
    e2 = np.pad(np.asarray(error, dtype=np.float64) ** 2, radius, mode="edge")
    h, w = np.shape(error)
    total = np.zeros((h, w))
    for dy in range(2 * radius + 1):
        for dx in range(2 * radius + 1):
            total += e2[dy:dy + h, dx:dx + w]
    return np.sqrt(total / (2 * radius + 1) ** 2)


def needed_extra_samples(error: np.ndarray, counts: np.ndarray, target: float, max_growth: float) -> np.ndarray:
    """Samples to add per pixel [-] (float): n (e/target)² − n, clipped to [0, max_growth · n]."""
    if not target > 0:
        raise ValueError(f"target error must be > 0, got {target}")
    counts = np.asarray(counts, dtype=np.float64)
    wanted = counts * (np.asarray(error, dtype=np.float64) / target) ** 2 - counts
    return np.clip(np.nan_to_num(wanted, nan=0.0, posinf=max_growth * counts.max()), 0.0, max_growth * counts)


def budget_allocation(error: np.ndarray, counts: np.ndarray, total: float) -> np.ndarray:
    """Samples per pixel [-] (float) that minimise the *mean* error for ``total`` samples in all.

    With e_p = a_p / √n_p (a_p = e_p √n_p from the current estimate) the mean of e_p
    under Σ n_p = total is smallest for n_p ∝ a_p^(2/3) (Lagrange: a_p n_p^(−3/2) equal
    for all p).
    """
    a = np.asarray(error, dtype=np.float64) * np.sqrt(np.asarray(counts, dtype=np.float64))
    weight = np.nan_to_num(a, nan=0.0, posinf=0.0) ** (2.0 / 3.0)
    if weight.sum() <= 0:
        return np.full(np.shape(error), total / np.size(error))
    return total * weight / weight.sum()


def stochastic_round(values: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Integers with the expectation of ``values`` (≥ 0): floor + 1 with probability of the fraction."""
    floor = np.floor(values)
    return (floor + (rng.random(np.shape(values)) < values - floor)).astype(np.int64)


@dataclass
class AdaptiveResult:
    """The passes of an adaptive frame: per-pixel sums per integrator, and what each pass did."""

    sums: list[PixelSums]
    history: list[dict]

    def image(self) -> np.ndarray:
        """Mean XYZ (H, W, 3) [cd m⁻²]: the sum over the integrators' passes (each estimates its own part)."""
        return sum(s.image() for s in self.sums)

    def halves(self) -> tuple[np.ndarray, np.ndarray]:
        a = sum(s.halves()[0] for s in self.sums)
        b = sum(s.halves()[1] for s in self.sums)
        return a, b


def render_adaptive(samplers: list[tuple[PixelSampler, float]], error_of: Callable[[np.ndarray, np.ndarray], np.ndarray],
                    target: float, initial_spp: int, budget_spp: float, seed: int, max_passes: int = 8,
                    max_growth: float = 3.0) -> AdaptiveResult:
    """Render a frame adaptively.

    Parameters
    ----------
    samplers : [(PixelSampler, fraction)]  The integrators whose passes add up to the image (one, or the
                                           two of a two-pass frame), each with its share of a pixel's
                                           samples [-] (1, and ``render.in_water_fraction``).
    error_of : (A, B) → (H, W)             Error of the mean of two half images, per pixel.
    target : float                         Error to reach per pixel, in ``error_of``'s unit.
    initial_spp : int                      Uniform samples per pixel of the first pass (≥ 2).
    budget_spp : float                     Mean samples per pixel of the whole frame, first pass included.
    seed : int                             Seeds ``seed·2²⁰ + …`` are used (disjoint per frame seed).
    max_passes : int                       Passes at most, the first included.
    max_growth : float                     A pass adds at most this many times a pixel's count so far.
    """
    if initial_spp < 2:
        raise ValueError(f"initial_spp must be ≥ 2 (two halves), got {initial_spp}")
    first, _ = samplers[0]
    shape = (first.height, first.width)
    rng = np.random.default_rng([int(seed), 0x5EED])
    sums = [PixelSums(first.width, first.height) for _ in samplers]
    counts = np.full(shape, int(initial_spp), dtype=np.int64)
    budget = float(budget_spp) * counts.size
    spent, history, launch = 0, [], int(seed) << 20
    for number in range(max_passes):
        for (sampler, fraction), target_sums in zip(samplers, sums):
            share = counts if fraction >= 1.0 else (
                np.maximum(2 * (counts > 0), stochastic_round(fraction * counts, rng)) if number == 0
                else stochastic_round(fraction * counts, rng))
            sampler.render(share, seed=launch, into=target_sums)
            launch += -(-int(share.sum()) // sampler.lanes)
        spent += int(counts.sum())
        a, b = AdaptiveResult(sums, []).halves()
        error = smoothed_error(error_of(a, b))
        so_far = sums[0].per_pixel_counts()
        history.append({"pass": number, "samples": int(counts.sum()), "mean_error": float(error.mean()),
                        "above_target": float((error > target).mean())})
        extra = needed_extra_samples(error, so_far, target, np.inf)
        room = budget - spent
        if room <= 0 or extra.sum() < 1:
            break
        if extra.sum() > room:
            # The target cannot be reached everywhere: spend what is left where it lowers the mean
            # error most, never beyond what a pixel needs for the target.
            extra = np.minimum(extra, np.clip(budget_allocation(error, so_far, budget) - so_far, 0.0, None))
        # A pass trusts its noisy error estimate only so far.
        extra = np.minimum(extra, max_growth * so_far)
        if extra.sum() > room:
            extra *= room / extra.sum()
        counts = stochastic_round(extra, rng)
    return AdaptiveResult(sums, history)
