"""The Mitsuba Monte Carlo slab (render/slab.py) against closed forms, and the four-flux model against it.

Issue 19, item 3: K_d and R(0⁻) of the four-flux model with coefficients from the phase
function and the refracted sun within 5 % of a Mitsuba Monte Carlo slab with the same
IOPs and phase function. The whole grid is in docs/optics.md (scripts/fourflux_slab_mc.py,
scripts/fourflux_agreement.py); here three cells at small sample counts.
"""

import math

import numpy as np
import pytest

from oceanrender.optics.components import tabulated_fournier_forand
from oceanrender.optics.fourflux import four_flux
from oceanrender.optics.streams import deep_layer, legendre_moments, stream_coefficients
from oceanrender.render.slab import first_optical_depth_K, slab_light_field
from tests.chandrasekhar import h_function

pytestmark = pytest.mark.render

ISOTROPIC = (np.array([-1.0, 0.0, 1.0]), np.full(3, 1.0 / (4.0 * np.pi)))


def test_unscattered_beam_follows_beer_lambert(variant):
    """b → 0: E_d(z) = cos θ e^{−a z / cos θ}. The meter sees the beam only through paths that
    reach the plane unscattered (a Bernoulli estimate): 5σ plus 0.2 % for the emitter calibration."""
    a, zenith, z = 0.1, 30.0, np.array([1.0, 5.0])
    light = slab_light_field(a, 1e-9, ISOTROPIC, zenith, z, spp=4096, passes=3)
    mu = math.cos(math.radians(zenith))
    exact = mu * np.exp(-a * z / mu)
    assert np.all(np.abs(light.E_d - exact) <= 5 * light.E_d_error + 2e-3 * exact)


def test_isotropic_half_space_albedo_matches_chandrasekhar(variant):
    """R(0⁻) of a deep isotropic medium under a normal beam = 1 − H(1) √(1 − ω) (Chandrasekhar
    1960): 0.5355 at ω = 0.95. Within 5σ of the Monte Carlo plus 0.5 % (the slab's finite width
    and depth, e^{−14} and e^{−30})."""
    omega = 0.95
    light = slab_light_field(0.1, 0.1 * omega / (1 - omega), ISOTROPIC, 0.0, [1.0], spp=8192, passes=3, spp_up=16384)
    exact = 1.0 - h_function(omega, 1.0) * math.sqrt(1.0 - omega)
    assert abs(light.R - exact) <= 5 * light.E_u0_error + 5e-3 * exact


@pytest.mark.slow
@pytest.mark.parametrize(("bb_over_a", "omega", "zenith_air"), [(1.0, 0.95, 0.0), (0.1, 0.8, 60.0)])
def test_four_flux_from_the_phase_function_agrees_with_monte_carlo(variant, bb_over_a, omega, zenith_air):
    """K_d over the first optical depth and R(0⁻) within 5 % (the issue's goal) of the Mitsuba slab
    with the same a, b and Fournier–Forand phase function; the fixed closure of today misses
    both cells by 13–45 % (docs/optics.md). Monte Carlo noise here: ≤ 1 % (asserted)."""
    a = 0.1
    b, bb = a * omega / (1 - omega), bb_over_a * a
    mu, p = tabulated_fournier_forand(bb / b)
    theta_w = math.degrees(math.asin(math.sin(math.radians(zenith_air)) / 1.334))
    mu_w = math.cos(math.radians(theta_w))
    layer = deep_layer(a, b, legendre_moments(mu, p, 65), mu_w)
    z1 = 1.0 / float(np.squeeze(four_flux([a], [bb], 1.0, 0.0, theta_w, np.inf, 0.0, [0.0], b=[b], n_water=1.0,
                                          coefficients=stream_coefficients([a], [b], mu, p[None], mu_w)).K_d))
    z = z1 * np.array([0.85, 1.0, 1.15])
    light = slab_light_field(a, b, (mu, p), theta_w, z, spp=16384, passes=3, spp_up=32768, seed=5)
    assert np.all(light.E_d_error <= 0.01 * light.E_d) and light.E_u0_error <= 0.01 * light.E_u0
    K_mc = first_optical_depth_K(z, light.E_d, light.E_d0)
    model = four_flux([a], [bb], 1.0, 0.0, theta_w, np.inf, 0.0, [0.0], b=[b], n_water=1.0,
                      coefficients=stream_coefficients([a], [b], mu, p[None], mu_w))
    assert float(model.K_d[0]) == pytest.approx(K_mc, rel=0.05)
    assert float(model.R[0]) == pytest.approx(light.R, rel=0.05)
    assert layer.E_u0 / mu_w == pytest.approx(light.R, rel=0.05)  # the discrete ordinates the coefficients use


# --- a level surface (issue 43): the slab under Fresnel, Snell and internal reflection ---------------------------

def test_level_surface_passes_the_refracted_beam(variant):
    """b → 0 under a dielectric top, Eq. (2): E_d(z) = (1 − F(θ_s)) e^{−a z/μ_w} per unit horizontal irradiance
    above, so K̄_d = a/μ_w; 5σ plus 0.5 % (the emitter calibration and the Fresnel lobe chosen at random)."""
    from oceanrender.optics.fresnel import N_AIR, reflectance_Fresnel, refracted_cosine
    from oceanrender.render.slab import NEAR_SURFACE_M, slab_kd

    a, n = 0.1, 1.34
    mu_s = math.cos(math.radians(30.0))
    mu_w, F = float(refracted_cosine(mu_s, N_AIR, n)), float(reflectance_Fresnel(mu_s, N_AIR, n))
    r = slab_kd(a, 1e-9, ISOTROPIC, [30.0], [1.0], 2.0, n, spp=16384, passes=3)
    assert abs(r.E_d[0] - (1 - F) * math.exp(-a * NEAR_SURFACE_M / mu_w)) <= 0.01 * r.E_d[0]
    assert abs(r.K - a / mu_w) <= 5 * r.K_error + 0.005 * a / mu_w


def test_level_surface_slab_agrees_with_the_discrete_ordinates(variant):
    """An isotropic, strongly scattering slab (ω = 0.95, R(0⁻) ≈ 0.57: the upwelling the surface reflects back is
    40 % of E_d(0⁻)) under a level surface: K̄_d over 0-2 m of the Monte Carlo within 5σ + 1 % of the discrete
    ordinates' (which have the same level surface); measured 0.6 %."""
    from oceanrender.optics.fresnel import N_AIR, refracted_cosine
    from oceanrender.render.slab import NEAR_SURFACE_M, slab_kd

    a, b, n, H = 0.1, 1.9, 1.34, 2.0
    mu_w = float(refracted_cosine(math.cos(math.radians(30.0)), N_AIR, n))
    layer = deep_layer(a, b, legendre_moments(*ISOTROPIC, 65), mu_w, n_water=n)
    E_s, E_dif, _ = layer.irradiances(np.array([NEAR_SURFACE_M, H]))
    E = E_s + E_dif
    exact = math.log(E[0] / E[1]) / (H - NEAR_SURFACE_M)
    r = slab_kd(a, b, ISOTROPIC, [30.0], [1.0], H, n, spp=8192, passes=3)
    assert abs(r.K - exact) <= 5 * r.K_error + 0.01 * exact


def test_slab_under_hydrolight_conditions_reaches_hydrolight(variant):
    """Jerlov 9C at 500 nm (Solonenko & Mobley 2015): the Monte Carlo K̄_d over 0-10 m under a level surface,
    the sun at 30° and two rings of a 15 % sky, within 10 % of HydroLight's K_d^H (the issue's bound; the
    comparison of all six types is docs/data/kd_hydrolight.md)."""
    from oceanrender.optics.jerlov_kd import KdConditions, hydrolight_phase, solonenko2015_water, surface_beams
    from oceanrender.render.slab import slab_kd

    conditions = KdConditions()
    a, b, b_w, kd_h = solonenko2015_water("9C", [500.0])
    mu, p = hydrolight_phase(b, b_w)
    zeniths, weights = surface_beams(conditions, 2)
    r = slab_kd(a[0], b[0], (mu, p[0]), zeniths, weights, conditions.layer_m, conditions.n_water, spp=2048, passes=3)
    assert r.K_error < 0.02 * r.K
    assert abs(r.K / kd_h[0] - 1) < 0.10
