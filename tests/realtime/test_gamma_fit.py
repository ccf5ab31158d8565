"""CIEDE2000 maps and statistics; the γ fit recovers a known γ on synthetic views."""

import numpy as np
import pytest

from oceanrender.realtime.compare import delta_E_2000, display_to_Lab, error_stats
from oceanrender.realtime.gamma_fit import FitView, fit_gamma, mean_delta_E
from oceanrender.realtime.model import fresnel_mix
from tests.tolerances import ROUNDOFF


def synthetic_views(rng, gamma, count=3, pixels=400, noise=0.0):
    """Views whose reference is the model at ``gamma`` (plus optional noise), water-like colours."""
    views = []
    for _ in range(count):
        F = rng.uniform(0.02, 0.6, pixels)
        sky = rng.uniform(0.3, 1.0, (pixels, 3)) * [0.6, 0.8, 1.0]
        water = rng.uniform(0.02, 0.4, (pixels, 3)) * [0.2, 0.7, 1.0]
        reference = fresnel_mix(F, sky, water, gamma) + noise * rng.normal(size=(pixels, 3))
        views.append(FitView(F=F, T_refl=sky, C_water=water, reference_Lab=display_to_Lab(reference)))
    return views


@pytest.mark.parametrize("true_gamma", [0.45, 1.0, 2.2])
def test_fit_recovers_a_known_gamma(rng, true_gamma):
    fit = fit_gamma(synthetic_views(rng, true_gamma))
    assert fit.gamma == pytest.approx(true_gamma, rel=2e-3)
    assert fit.after.mean < 0.02
    if true_gamma != 1.0:
        assert fit.before.mean > 1.0  # the exact Fresnel weight is visibly off
    assert fit.after.pixels == 1200


def test_fit_with_noisy_references_still_finds_gamma(rng):
    fit = fit_gamma(synthetic_views(rng, 0.7, noise=0.01))
    assert fit.gamma == pytest.approx(0.7, rel=0.05)
    assert fit.after.mean < fit.before.mean
    assert mean_delta_E(synthetic_views(rng, 0.7, noise=0.01), fit.gamma) < fit.before.mean


def test_fit_refuses_empty_views():
    with pytest.raises(ValueError, match="no water pixels"):
        fit_gamma([])


def test_delta_E_of_display_images():
    white, grey = np.ones(3), np.full(3, 0.18)
    # Lab: L has scale 100, a and b are 0 for white; 1e-6 is far below ΔE ≈ 1 (just noticeable).
    np.testing.assert_allclose(display_to_Lab(white), [100.0, 0.0, 0.0], atol=1e-6)
    assert delta_E_2000(grey, grey) == pytest.approx(0.0, abs=ROUNDOFF)  # ΔE scale 1 (just noticeable)
    # Over-white pixels are seen as white: clipped before the conversion.
    assert delta_E_2000(np.full(3, 1.7), white) == pytest.approx(0.0, abs=ROUNDOFF)
    # Sharma et al. (2005), test pair 1: Lab (50, 2.6772, -79.7751) vs (50, 0, -82.7485): ΔE00 = 2.0425.
    import colour

    assert float(colour.delta_E([50, 2.6772, -79.7751], [50, 0, -82.7485], method="CIE 2000")) == pytest.approx(
        2.0425, abs=1e-4)


def test_error_stats():
    values = np.arange(101.0)
    stats = error_stats(values)
    # Mean and percentile are sums and an interpolation at index 0.95·100: round-off, relative.
    assert (stats.mean, stats.p95, stats.max) == pytest.approx((50.0, 95.0, 100.0), rel=ROUNDOFF)
    assert stats.pixels == 101
    masked = error_stats(values, values < 10)
    assert masked.max == 9.0 and masked.pixels == 10
    assert np.isnan(error_stats([]).mean)
