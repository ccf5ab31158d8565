"""Fresnel reflectance: closed forms, limits, symmetries and published diffuse values."""

import numpy as np
import pytest

from oceanrender.optics.fresnel import (
    N_WATER,
    critical_cosine,
    diffuse_reflectance_Fresnel,
    diffuse_transmittance_Fresnel,
    fresnel_correction,
    reflectance_components_Fresnel,
    reflectance_Fresnel,
    refracted_cosine,
    transmittance_Fresnel,
)
from tests.tolerances import ROUNDOFF

N = N_WATER


@pytest.mark.parametrize("n1, n2", [(1.0, N), (N, 1.0), (1.0, 1.5), (1.5, 1.0)])
def test_normal_incidence_is_the_closed_form(n1, n2):
    expected = ((n1 - n2) / (n1 + n2)) ** 2
    R_s, R_p = reflectance_components_Fresnel(1.0, n1, n2)
    assert reflectance_Fresnel(1.0, n1, n2) == pytest.approx(expected, rel=ROUNDOFF)
    assert R_s == pytest.approx(expected, rel=ROUNDOFF) and R_p == pytest.approx(expected, rel=ROUNDOFF)
    # 2.04 % for air → water, the textbook value.
    if (n1, n2) == (1.0, N):
        assert float(reflectance_Fresnel(1.0, n1, n2)) == pytest.approx(0.0204, abs=1e-4)


@pytest.mark.parametrize("n1, n2", [(1.0, N), (N, 1.0)])
def test_brewster_angle_p_vanishes_s_is_closed_form(n1, n2):
    theta_B = np.arctan(n2 / n1)  # tan θ_B = n2/n1
    R_s, R_p = reflectance_components_Fresnel(np.cos(theta_B), n1, n2)
    assert float(R_p) == pytest.approx(0.0, abs=ROUNDOFF)  # reflectance, scale 1
    # θ_i + θ_t = 90° at Brewster, so R_s = sin²(θ_i − θ_t) = cos²(2 θ_B).
    assert float(R_s) == pytest.approx(np.cos(2 * theta_B) ** 2, rel=ROUNDOFF)
    # Brewster from water (36.9°) lies below the critical angle (48.6°).
    assert np.degrees(theta_B) == pytest.approx(53.12 if n1 == 1.0 else 36.88, abs=0.01)


def test_components_match_the_sine_tangent_forms(rng):
    theta_i = rng.uniform(0.01, 1.5, 200)
    for n1, n2 in [(1.0, N), (N, 1.0)]:
        keep = np.sin(theta_i) * n1 / n2 < 1
        ti = theta_i[keep]
        tt = np.arcsin(n1 / n2 * np.sin(ti))
        R_s, R_p = reflectance_components_Fresnel(np.cos(ti), n1, n2)
        # Different formulas (arcsin vs √(1 − sin²θ_t)), ill-conditioned near the critical
        # angle: 1e-9 relative. R_p → 0 at Brewster, so its absolute part is on the
        # reflectance scale 1 (r_p there is a cancellation residual of ~ε).
        np.testing.assert_allclose(R_s, np.sin(ti - tt) ** 2 / np.sin(ti + tt) ** 2, rtol=1e-9)
        np.testing.assert_allclose(R_p, np.tan(ti - tt) ** 2 / np.tan(ti + tt) ** 2, rtol=1e-9, atol=ROUNDOFF)


def test_grazing_incidence_reflects_everything():
    assert float(reflectance_Fresnel(0.0, 1.0, N)) == pytest.approx(1.0, abs=ROUNDOFF)  # scale 1
    assert float(transmittance_Fresnel(0.0, 1.0, N)) == pytest.approx(0.0, abs=ROUNDOFF)  # scale 1
    # Monotone increase from normal to grazing incidence from the air side.
    F = reflectance_Fresnel(np.linspace(1.0, 0.0, 500), 1.0, N)
    assert np.all(np.diff(F) > 0)


def test_critical_angle_and_total_internal_reflection():
    mu_c = critical_cosine(N, 1.0)
    theta_c = np.degrees(np.arccos(mu_c))
    assert theta_c == pytest.approx(np.degrees(np.arcsin(1 / N)), rel=ROUNDOFF)
    assert theta_c == pytest.approx(48.6, abs=0.05)
    beyond = np.cos(np.radians(np.linspace(theta_c + 1e-6, 90.0, 50)))
    # Exact: total internal reflection sets R_s = R_p = 1.0 (np.where), no arithmetic on it.
    np.testing.assert_array_equal(reflectance_Fresnel(beyond, N, 1.0), 1.0)
    np.testing.assert_array_equal(reflectance_components_Fresnel(beyond, N, 1.0), 1.0)
    assert np.all(np.isnan(refracted_cosine(beyond, N, 1.0)))
    # Continuous at the critical angle; partial below it.
    assert float(reflectance_Fresnel(mu_c * (1 + 1e-12), N, 1.0)) > 0.999
    assert 0 < float(reflectance_Fresnel(np.cos(np.radians(45.0)), N, 1.0)) < 0.2
    # No total internal reflection from the rarer side.
    assert float(critical_cosine(1.0, N)) == 0.0  # exact: n2/n1 is clipped to 1, √(1 − 1) = 0


def test_reciprocity_air_to_water_equals_water_to_air(rng):
    mu_air = rng.uniform(0.0, 1.0, 300)
    mu_water = refracted_cosine(mu_air, 1.0, N)
    # Two code paths. Near grazing incidence from the air μ_water sits at the critical
    # angle, where μ_air = √(1 − n²(1 − μ_water²)) cancels: the rounding of μ_water is
    # amplified by d ln μ_air / d ln μ_water = n² μ_water²/μ_air², i.e. an absolute error in
    # μ_air (and in F, whose slope there is O(1)) of ε n² μ_water²/μ_air. Cosines and
    # reflectances have scale 1.
    tolerance = ROUNDOFF * N**2 * mu_water**2 / mu_air
    error = np.abs(reflectance_Fresnel(mu_air, 1.0, N) - reflectance_Fresnel(mu_water, N, 1.0))
    np.testing.assert_array_less(error, tolerance)
    np.testing.assert_array_less(np.abs(refracted_cosine(mu_water, N, 1.0) - mu_air), tolerance)


def test_matched_indices_do_not_reflect():
    mu = np.linspace(0.01, 1, 20)
    # Reflectance scale 1: μ_t = √(1 − (1 − μ²)) differs from μ by ~ε/μ², so F ~ (ε/μ²)²
    # (up to 1e-24 at μ = 0.01), not exactly 0.
    np.testing.assert_allclose(reflectance_Fresnel(mu, N, N), 0.0, atol=ROUNDOFF)
    assert float(diffuse_reflectance_Fresnel(N, N)) == pytest.approx(0.0, abs=ROUNDOFF)


def test_diffuse_reflectance_against_published_values_and_brute_force():
    r_aw, r_wa = float(diffuse_reflectance_Fresnel(1.0, N)), float(diffuse_reflectance_Fresnel(N, 1.0))
    # Preisendorfer (1976), Mobley (1994): 0.066 for a uniform sky over a level sea.
    assert r_aw == pytest.approx(0.066, abs=0.001)
    # Uniform radiance from below: 0.47–0.49 is the published range (n = 1.33–1.34).
    assert 0.47 < r_wa < 0.49
    # Exact reciprocity: 1 − r̄_wa = (1 − r̄_aw)/n².
    assert 1 - r_wa == pytest.approx((1 - r_aw) / N**2, rel=ROUNDOFF)
    # Independent brute-force integration of 2 ∫ F μ dμ (trapezoid, 2e6 panels; its error
    # at the √ kink of F at the critical angle is ~3e-10, hence 1e-8).
    mu = np.linspace(0.0, 1.0, 2_000_001)
    for n1, n2, r in [(1.0, N, r_aw), (N, 1.0, r_wa)]:
        assert np.trapezoid(2 * reflectance_Fresnel(mu, n1, n2) * mu, mu) == pytest.approx(r, abs=1e-8)
    assert float(diffuse_transmittance_Fresnel(1.0, N)) == pytest.approx(1 - r_aw, rel=ROUNDOFF)


def test_broadcasting_nan_and_invalid_inputs():
    mu = np.linspace(0, 1, 3)[:, None]
    n2 = np.array([1.2, 1.333, 1.5, 2.0])
    assert reflectance_Fresnel(mu, 1.0, n2).shape == (3, 4)
    assert diffuse_reflectance_Fresnel(1.0, n2).shape == (4,)
    assert np.isnan(reflectance_Fresnel(np.nan, 1.0, N))
    with pytest.raises(ValueError, match=r"\[0, 1\]"):
        reflectance_Fresnel(-0.1, 1.0, N)
    with pytest.raises(ValueError, match="positive"):
        reflectance_Fresnel(0.5, 0.0, N)


def test_fresnel_correction_power_law():
    F = reflectance_Fresnel(np.linspace(0, 1, 101), 1.0, N)
    # γ = 1 is the identity; F**1.0 goes through pow (libm or SIMD), not a copy: last bits.
    np.testing.assert_allclose(fresnel_correction(F, 1.0), F, rtol=ROUNDOFF)
    np.testing.assert_allclose(fresnel_correction(F, 0.5), np.sqrt(F), rtol=ROUNDOFF)
    assert np.all(fresnel_correction(F, 0.7) >= F) and np.all(fresnel_correction(F, 1.5) <= F)
    # Exact: pow(0, γ > 0) = 0 and pow(1, γ) = 1 are IEEE 754 special cases (the fixed points).
    np.testing.assert_array_equal(fresnel_correction([0.0, 1.0], 0.3), [0.0, 1.0])
    with pytest.raises(ValueError, match="gamma"):
        fresnel_correction(F, 0.0)
    with pytest.raises(ValueError, match=r"\[0, 1\]"):
        fresnel_correction(1.2, 1.0)
