"""Discrete ordinates and the four-flux coefficients derived from them (issue 19, item 3).

The discrete-ordinate solver is checked against closed forms it does not share code
with: Legendre moments of Henyey–Greenstein (χ_l = g^l), the plane albedo of a
semi-infinite isotropically scattering medium from Chandrasekhar's H-function, and the
asymptotic attenuation of isotropic scattering from its transcendental equation. The
coefficients are then checked for what they are built to do.
"""

import math

import numpy as np
import pytest

from oceanrender.optics.components import (
    PRESETS,
    _tabulate,
    composition_iops,
    composition_optics,
    medium_phase_table,
    tabulated_fournier_forand,
)
from oceanrender.optics.fourflux import four_flux
from oceanrender.optics.streams import (
    deep_layer,
    first_optical_depth,
    legendre_moments,
    stream_block,
    stream_coefficients,
)
from tests.chandrasekhar import h_function


def _isotropic_moments(count=65):
    chi = np.zeros(count)
    chi[0] = 1.0
    return chi


def test_legendre_moments_of_henyey_greenstein_are_powers_of_g():
    """χ_l = g^l (Henyey & Greenstein 1941). The table is piecewise linear in μ on 1201 log-θ
    nodes: 2e-4 absolute (χ_l ≤ 1) covers that discretisation at g = 0.9, l ≤ 30."""
    g = 0.9
    mu, p = _tabulate(lambda angles: (1 - g * g) / (4 * np.pi * (1 + g * g - 2 * g * np.cos(np.radians(angles))) ** 1.5))
    chi = legendre_moments(mu, p, 31)
    np.testing.assert_allclose(chi, g ** np.arange(31), atol=2e-4)


@pytest.mark.parametrize(("omega", "mu_w"), [(0.5, 1.0), (0.95, 1.0), (0.95, 0.6), (0.999, 0.8)])
def test_plane_albedo_of_isotropic_half_space_matches_theh_function(omega, mu_w):
    """E_u(0)/E_d(0) = 1 − H(μ_w) √(1 − ω) (Chandrasekhar 1960, § 47), to 1e-6 relative
    (the H-function iteration and 32 double-Gauss streams are both converged far below it)."""
    a, b = 0.1 * (1 - omega), 0.1 * omega
    layer = deep_layer(a, b, _isotropic_moments(), mu_w)
    exact = 1.0 - h_function(omega, mu_w) * math.sqrt(1.0 - omega)
    assert layer.E_u0 / mu_w == pytest.approx(exact, rel=1e-6)


@pytest.mark.parametrize("omega", [0.3, 0.8, 0.99])
def test_asymptotic_attenuation_of_isotropic_scattering(omega):
    """K_∞ = κ c with (ω/2κ) ln((1 + κ)/(1 − κ)) = 1 (Case & Zweifel 1967), to 1e-4 relative.

    At small ω, κ → 1 and the mode's radiance ∝ 1/(1 − κμ) peaks at μ = 1, which 32
    double-Gauss streams resolve to 2e-5 (ω = 0.3); 1e-9 at ω ≥ 0.8."""
    lo, hi = 1e-12, 1.0 - 1e-15
    for _ in range(200):
        k = 0.5 * (lo + hi)
        if omega / (2 * k) * math.log((1 + k) / (1 - k)) > 1.0:  # increasing in κ
            hi = k
        else:
            lo = k
    c = 0.4
    layer = deep_layer(c * (1 - omega), c * omega, _isotropic_moments(), 1.0)
    assert layer.K_inf == pytest.approx(0.5 * (lo + hi) * c, rel=1e-4)


def test_stream_block_has_the_asymptotic_modes():
    """The symmetric block's eigenpairs are (−K, (1, R)) and (+K, (R, 1)), to rounding."""
    a, K, R = 0.1, 0.23, 0.05
    mu, bb = stream_block(a, K, R)
    alpha, beta = (a + bb) / mu, bb / mu
    M = np.array([[-alpha, beta], [-beta, alpha]])
    np.testing.assert_allclose(M @ [1.0, R], -K * np.array([1.0, R]), rtol=1e-12)
    np.testing.assert_allclose(M @ [R, 1.0], K * np.array([R, 1.0]), rtol=1e-12)


@pytest.mark.parametrize(("bb_over_b", "omega", "zenith"), [(0.02, 0.8, 0.0), (0.005, 0.95, 40.0), (0.2, 0.5, 20.0)])
def test_four_flux_with_derived_coefficients_keeps_the_exact_anchors(bb_over_b, omega, zenith):
    """By construction: R(0⁻) and K_d over the first optical depth of the deep layer equal the
    discrete ordinates' (1e-6, the four-flux K_d's Newton tolerance is far below), and the
    deep attenuation is K_∞ (d ln E_d/dz at 40 optical depths, 1e-4)."""
    a, b = 0.1, 0.1 * omega / (1 - omega)
    mu, p = tabulated_fournier_forand(bb_over_b)
    mu_w = math.cos(math.radians(zenith))
    layer = deep_layer(a, b, legendre_moments(mu, p, 65), mu_w)
    co = stream_coefficients([a], [b], mu, p[None], mu_w)
    deep = 40.0 / layer.K_inf
    model = four_flux([a], [bb_over_b * b], 1.0, 0.0, zenith, np.inf, 0.0, [deep, deep + 0.01], b=[b],
                      n_water=1.0, coefficients=co)
    assert float(model.R[0]) == pytest.approx(layer.E_u0 / mu_w, rel=1e-6)
    assert float(model.K_d[0]) == pytest.approx(1.0 / first_optical_depth(layer), rel=1e-6)
    slope = -np.log(model.E_d[0, 1] / model.E_d[0, 0]) / 0.01
    assert slope == pytest.approx(layer.K_inf, rel=1e-4)


def test_medium_phase_table_keeps_the_renderers_backscatter_ratio():
    """The HG blend tabulated for the coefficients has the composition's b_b/b (1 %: the
    piecewise-linear table of the forward peak), so the model and the render share it."""
    optics = composition_optics(PRESETS["green coastal"])
    wl = np.array([400.0, 550.0, 700.0])
    mu, p = medium_phase_table(optics, wl)
    # the table is piecewise linear in μ: put a node at μ = 0 (linear there) to split the hemispheres exactly
    j = np.searchsorted(mu, 0.0)
    p0 = p[:, j - 1] + (p[:, j] - p[:, j - 1]) * (0.0 - mu[j - 1]) / (mu[j] - mu[j - 1])
    mu_back, p_back = np.append(mu[:j], 0.0), np.column_stack([p[:, :j], p0])
    ratio = np.trapezoid(p_back, mu_back, axis=1) / np.trapezoid(p, mu, axis=1)
    truth = composition_iops(PRESETS["green coastal"], wl)
    np.testing.assert_allclose(ratio, truth.backscattering / truth.scattering, rtol=0.01)


@pytest.mark.parametrize(("omega", "mu_w"), [(0.95, 1.0), (0.5, 0.7)])
def test_nadir_radiance_of_isotropic_half_space(omega, mu_w):
    """Emergent radiance along the vertical, (ω/4π) μ₀/(1 + μ₀) H(1) H(μ₀) per unit normal irradiance
    (Chandrasekhar 1960, § 47), to 1e-8 relative: the natural interpolation of the discrete ordinates."""
    layer = deep_layer(0.1 * (1 - omega), 0.1 * omega, np.eye(1, 65)[0], mu_w)
    exact = omega / (4 * math.pi) * mu_w / (1 + mu_w) * h_function(omega, 1.0) * h_function(omega, mu_w)
    assert layer.nadir_radiance == pytest.approx(exact, rel=1e-8)


def test_single_scattering_correction_restores_the_backward_phase_function():
    """ω₀ = 0.01, HG g = 0.95: the nadir radiance is single scattering, b p(Θ) μ_w/(c (1 + μ_w)) with
    cos Θ = −μ_w, to O(ω₀) (multiple scattering: +1.0 % measured). Without the TMS correction the
    64-term δ-M series is 58 % off there (asserted > 20 %); with it, within 2 %."""
    g, omega, mu_w = 0.95, 0.01, 0.8
    chi = g ** np.arange(65)
    a, b = 0.1 * (1 - omega), 0.1 * omega
    back = (1 - g * g) / (4 * math.pi * (1 + g * g + 2 * g * mu_w) ** 1.5)
    single = b * back * mu_w / ((a + b) * (1 + mu_w))
    plain = deep_layer(a, b, chi, mu_w).nadir_radiance
    corrected = deep_layer(a, b, chi, mu_w, back_phase=back).nadir_radiance
    assert abs(plain / single - 1) > 0.20
    assert corrected == pytest.approx(single, rel=0.02)


def test_surface_terms_give_the_four_flux_model_the_transports_upwelling():
    """Under a level surface and a uniform sky: the four-flux E_u(0⁻) and L_u(nadir) = E_u/Q equal the
    discrete ordinates' (built so; 1e-9), and Q lies in the 3–6 sr of measured oceans, not π."""
    from oceanrender.optics.fresnel import N_AIR, reflectance_Fresnel
    from oceanrender.optics.streams import surface_light

    a, b, n, zenith = 0.1, 0.4, 1.34, 30.0
    mu, p = tabulated_fournier_forand(0.02)
    mu_w, sky = surface_light(1.0, 0.3, zenith, n)
    co = stream_coefficients([a], [b], mu, p[None], mu_w, n_water=n, sky=[sky])
    model = four_flux([a], [0.02 * b], 1.0, 0.3, zenith, np.inf, 0.0, [0.0], b=[b], n_water=n,
                      internal_reflection=True, coefficients=co)
    layer = deep_layer(a, b, legendre_moments(mu, p, 65), mu_w, n_water=n, sky=float(sky),
                       back_phase=float(np.interp(-mu_w, mu, p)))
    mu_s = math.cos(math.radians(zenith))
    beam = mu_s * (1 - reflectance_Fresnel(mu_s, N_AIR, n)) / mu_w  # in-water normal irradiance
    assert float(model.E_upwell[0]) == pytest.approx(layer.E_u0 * beam, rel=1e-9)
    assert float(model.L_u[0]) == pytest.approx(layer.nadir_radiance * beam, rel=1e-9)
    assert 3.0 < float(co.Q[0]) < 6.0
