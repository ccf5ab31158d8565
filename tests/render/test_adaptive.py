"""Adaptive sampling (render/adaptive.py): the allocation rules, and a real adaptive frame."""

import numpy as np
import pytest

from oceanrender.render.adaptive import (
    budget_allocation,
    needed_extra_samples,
    render_adaptive,
    smoothed_error,
    stochastic_round,
)
from oceanrender.render.pixels import PixelSampler
from oceanrender.render.renderer import K_M
from tests.render.constant_sky import cmf_integrals, constant_sky_scene
from tests.tolerances import ROUNDOFF


def test_smoothing_keeps_a_uniform_error_and_spreads_a_spike():
    np.testing.assert_allclose(smoothed_error(np.full((5, 7), 2.0)), 2.0, rtol=ROUNDOFF)
    spike = np.zeros((5, 5))
    spike[2, 2] = 3.0
    out = smoothed_error(spike)
    # √(9 / 9) = 1 on the spike's 3×3 neighbourhood, 0 outside it.
    np.testing.assert_allclose(out[1:4, 1:4], 1.0, rtol=ROUNDOFF)
    assert out[0].max() == 0.0 and out[:, 4].max() == 0.0


def test_extra_samples_follow_the_inverse_square_root_law():
    counts = np.array([16.0, 16.0, 16.0])
    # e = 2 t: 4× the samples (48 more, clipped to 3 × 16); e = t: none; e = 0.5 t: none.
    np.testing.assert_allclose(needed_extra_samples(np.array([2.0, 1.0, 0.5]), counts, 1.0, 3.0), [48, 0, 0])
    np.testing.assert_allclose(needed_extra_samples(np.array([4.0]), np.array([16.0]), 1.0, 3.0), [48])  # clipped
    with pytest.raises(ValueError):
        needed_extra_samples(counts, counts, 0.0, 3.0)


def test_budget_allocation_minimises_the_mean_error(rng):
    error = rng.uniform(0.5, 8.0, 200)
    counts = np.full(200, 8.0)
    a = error * np.sqrt(counts)
    best = budget_allocation(error, counts, 200 * 32.0)
    assert best.sum() == pytest.approx(200 * 32.0, rel=ROUNDOFF)

    def mean_error(n):
        return np.mean(a / np.sqrt(n))

    # Any other allocation of the same total does worse (uniform, ∝ a², random perturbations).
    for other in (np.full(200, 32.0), 200 * 32.0 * a**2 / np.sum(a**2)):
        assert mean_error(best) < mean_error(other)
    for _ in range(20):
        perturbed = best * rng.uniform(0.8, 1.2, 200)
        assert mean_error(best) < mean_error(perturbed * best.sum() / perturbed.sum())


def test_stochastic_rounding_is_unbiased(rng):
    values = np.array([0.25, 1.5, 3.0, 7.9])
    draws = np.stack([stochastic_round(values, rng) for _ in range(4000)])
    assert draws.dtype.kind == "i" and np.all(draws >= np.floor(values)) and np.all(draws <= np.ceil(values))
    # Bernoulli fractions: standard error ≤ 0.5 / √4000 = 0.008; 5 of them.
    np.testing.assert_allclose(draws.mean(axis=0), values, atol=0.04)


@pytest.mark.render
def test_an_adaptive_frame_spends_its_budget_where_the_error_is(variant):
    # A constant sky seen by a real PixelSampler; the caller's error measure says the left half
    # is 4× as noisy as the right (a weighted half difference). With the budget binding, the
    # mean-error optimum gives the left ≈ 4^(2/3) = 2.5× the samples of the right.
    scene = constant_sky_scene(16, 8, 4)
    weight = np.ones((8, 16))
    weight[:, :8] = 4.0

    def error_of(a, b):
        return weight * np.abs(a[..., 1] - b[..., 1]) / (a[..., 1] + b[..., 1])

    sampler = PixelSampler(scene, lanes=4096)
    result = render_adaptive([(sampler, 1.0)], error_of, target=1e-6, initial_spp=8, budget_spp=32, seed=3)
    counts = result.sums[0].per_pixel_counts()
    # The budget holds (stochastic rounding: within a few samples of 32 × 128 in all).
    assert counts.sum() <= 32 * counts.size * 1.02 and counts.sum() >= 32 * counts.size * 0.9
    assert counts.min() >= 8 and len(result.history) >= 2
    ratio = counts[:, :8].mean() / counts[:, 8:].mean()
    assert 1.8 < ratio < 3.5, ratio
    # The frame is still the sky's: K_m ∫ȳ dλ (CIE 015:2018 Eq. 7.1) within the Monte Carlo error
    # of 4096 spectral samples (≲ 1 %).
    assert result.image()[..., 1].mean() == pytest.approx(K_M * cmf_integrals()[1], rel=0.02)
