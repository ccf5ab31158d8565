"""Tests for oceanrender.waves.wave_spectra: closed forms, limits, method dispatch."""

import numpy as np
import pytest
from scipy.integrate import quad

from oceanrender.waves.spreading import SPREADING
from oceanrender.waves.wave_spectra import (
    FREQUENCY_SPECTRA,
    GRAVITY,
    JONSWAP_GAMMA,
    PHILLIPS_ALPHA,
    PIERSON_MOSKOWITZ_ALPHA,
    PIERSON_MOSKOWITZ_BETA,
    PIERSON_MOSKOWITZ_WIND_RATIO,
    SEAWATER_SURFACE_TENSION,
    SPECTRA,
    WAVENUMBER_SPECTRA,
    DirectionalSpectrum,
    depth_function_Kitaigorodskii1975,
    depth_function_ThompsonVincent1983,
    dispersion_relation,
    elevation_variance_Phillips2001,
    elevation_variance_PiersonMoskowitz1964,
    frequency_spectrum,
    group_velocity,
    peak_frequency_JONSWAP1973,
    peak_frequency_PiersonMoskowitz1964,
    phillips_constant_JONSWAP1973,
    significant_wave_height_Phillips2001,
    significant_wave_height_PiersonMoskowitz1964,
    spectrum_JONSWAP1973,
    spectrum_Phillips2001,
    spectrum_PiersonMoskowitz1964,
    spectrum_swell,
    spectrum_TMA1985,
    wave_spectrum,
    wavenumber_from_frequency,
)
from tests.tolerances import QUADRATURE, ROUNDOFF

#: Relative tolerance of numerical quadrature against closed forms.
QUADRATURE_RTOL = 1e-3


def polar_integral(wind_speed, wind_direction, small_wave_length=0.0):
    """∫∫ Ψ dkx dky on a polar grid, trapezoids in ln k and a periodic sum in θ [m²]."""
    L_w = wind_speed**2 / GRAVITY
    ln_k = np.linspace(np.log(1e-2 / L_w), np.log(1e3 / L_w), 4001)
    theta = np.linspace(0, 2 * np.pi, 256, endpoint=False)  # periodic: the plain sum is exact for cos²
    k = np.exp(ln_k)[:, None]
    psi = spectrum_Phillips2001(
        k * np.cos(theta), k * np.sin(theta), wind_speed, wind_direction, small_wave_length=small_wave_length
    )
    # dkx dky = k dk dθ = k² d(ln k) dθ
    radial = psi.sum(axis=1) * (2 * np.pi / theta.size) * k[:, 0] ** 2
    return np.trapezoid(radial, ln_k)


@pytest.mark.parametrize("wind_speed", [3.0, 10.0, 25.0])
def test_phillips_variance_matches_closed_form(wind_speed):
    expected = PHILLIPS_ALPHA * wind_speed**4 / (4 * GRAVITY**2)
    assert polar_integral(wind_speed, 0.7) == pytest.approx(expected, rel=QUADRATURE_RTOL)
    assert elevation_variance_Phillips2001(wind_speed) == pytest.approx(expected, rel=ROUNDOFF)


def test_phillips_variance_with_small_wave_suppression():
    # the K₁ closed form, with ℓ a sizeable fraction of L_w so the suppression matters
    wind_speed, ell = 5.0, 0.5
    numeric = polar_integral(wind_speed, -1.0, small_wave_length=ell)
    closed = elevation_variance_Phillips2001(wind_speed, small_wave_length=ell)
    assert numeric == pytest.approx(closed, rel=QUADRATURE_RTOL)
    assert closed < elevation_variance_Phillips2001(wind_speed)
    # ℓ → 0 tends continuously to the sharp closed form
    assert elevation_variance_Phillips2001(wind_speed, small_wave_length=1e-6) == pytest.approx(
        elevation_variance_Phillips2001(wind_speed), rel=1e-6
    )


def test_significant_wave_height_closed_form():
    U = np.array([5.0, 10.0, 20.0])
    m0 = elevation_variance_Phillips2001(U)
    np.testing.assert_allclose(significant_wave_height_Phillips2001(U), 4 * np.sqrt(m0), rtol=ROUNDOFF)
    # 2 √α U²/g at 10 m/s with √α = 0.09: 18/9.81 m
    assert significant_wave_height_Phillips2001(10.0) == pytest.approx(18 / 9.81, rel=ROUNDOFF)


def test_phillips_zero_wavenumber_and_calm_sea_are_zero():
    with np.errstate(all="raise"):
        assert spectrum_Phillips2001(0.0, 0.0, 10.0, 0.3) == 0.0
        assert spectrum_Phillips2001(0.1, 0.2, 0.0, 0.3) == 0.0
    assert np.isnan(spectrum_Phillips2001(np.nan, 0.1, 10.0, 0.0))


def test_phillips_direction_and_symmetry(rng):
    kx, ky = rng.normal(0, 0.2, (2, 100))
    direction = 0.6
    psi = spectrum_Phillips2001(kx, ky, 8.0, direction)
    assert np.all(psi >= 0)
    # NOTE: relative to the largest value: nearly across the wind (cos² of the angle ~ 0) and at
    # small k (e^{−1/(k L)²}) the values are many orders smaller, and round-off of the angle
    # changes them by large factors that no physical quantity sees.
    scale = psi.max()
    # two-sided: Ψ(−k) = Ψ(k)
    np.testing.assert_allclose(spectrum_Phillips2001(-kx, -ky, 8.0, direction), psi, rtol=0, atol=ROUNDOFF * scale)
    # no waves travel across the wind (compared with the value downwind at the same |k|)
    across = spectrum_Phillips2001(-np.sin(direction) * 0.1, np.cos(direction) * 0.1, 8.0, direction)
    downwind = spectrum_Phillips2001(np.cos(direction) * 0.1, np.sin(direction) * 0.1, 8.0, direction)
    assert across == pytest.approx(0.0, abs=ROUNDOFF * downwind)
    # rotating k and the wind together changes nothing
    c, s = np.cos(1.1), np.sin(1.1)
    rotated = spectrum_Phillips2001(c * kx - s * ky, s * kx + c * ky, 8.0, direction + 1.1)
    np.testing.assert_allclose(rotated, psi, rtol=0, atol=ROUNDOFF * scale)


def test_phillips_broadcasts():
    k = np.linspace(0.01, 1, 5)[:, None]
    U = np.array([5.0, 10.0, 15.0])
    assert spectrum_Phillips2001(k, 0.0, U, 0.0).shape == (5, 3)


def test_dispersion_deep_water_limit():
    k = np.geomspace(1e-3, 1e2, 50)
    np.testing.assert_allclose(dispersion_relation(k), np.sqrt(GRAVITY * k), rtol=ROUNDOFF)
    # tanh(kd) → 1 once kd ≳ 20
    np.testing.assert_allclose(dispersion_relation(k[k > 0.1], depth=200.0), np.sqrt(GRAVITY * k[k > 0.1]),
                               rtol=ROUNDOFF)
    assert dispersion_relation(0.0) == 0.0


def test_dispersion_shallow_water_limit():
    depth = 2.0
    k = np.geomspace(1e-5, 1e-3, 20)  # kd ≤ 2e-3
    # ω = k √(g d) (1 − (kd)²/6 + …): relative error ≤ (kd)²/6 < 1e-6
    np.testing.assert_allclose(dispersion_relation(k, depth), k * np.sqrt(GRAVITY * depth), rtol=1e-6)


def test_wave_spectrum_dispatch():
    kx, ky = np.array([0.1, 0.2]), np.array([0.05, -0.1])
    direct = spectrum_Phillips2001(kx, ky, 9.0, 0.2, small_wave_length=0.3)
    via = wave_spectrum("Phillips 2001", kx, ky, wind_speed=9.0, wind_direction=0.2, small_wave_length=0.3, fetch=1e5)
    np.testing.assert_array_equal(via, direct)  # the dispatcher calls the same function with the same arguments


def test_wave_spectrum_unknown_method_lists_known():
    with pytest.raises(ValueError, match="Phillips 2001") as error:
        wave_spectrum("JONSWAP 1937", 0.1, 0.1, wind_speed=5.0, wind_direction=0.0)
    assert "JONSWAP 1937" in str(error.value)
    assert all(name in str(error.value) for name in SPECTRA)


# ---------------------------------------------------------------------------
# Frequency spectra S(ω)
# ---------------------------------------------------------------------------



def integrate_omega(spectrum, omega_p):
    """∫₀^∞ S dω by adaptive quadrature, split at the peak [m²]."""
    pieces = [(0.0, omega_p), (omega_p, 3 * omega_p), (3 * omega_p, np.inf)]
    return sum(quad(spectrum, a, b, limit=400, epsabs=0.0, epsrel=1e-12)[0] for a, b in pieces)


@pytest.mark.parametrize("wind_speed", [5.0, 15.0, 30.0])
def test_pierson_moskowitz_variance_closed_form(wind_speed):
    omega_p = peak_frequency_PiersonMoskowitz1964(wind_speed)
    numeric = integrate_omega(lambda w: spectrum_PiersonMoskowitz1964(w, wind_speed), omega_p)
    closed = elevation_variance_PiersonMoskowitz1964(wind_speed)
    assert numeric == pytest.approx(closed, rel=1e-4)
    # m0 = α U⁴/(4 β g²) = 2.736e-3 U⁴/g²
    assert closed == pytest.approx(2.7365e-3 * wind_speed**4 / GRAVITY**2, rel=1e-4)


def test_pierson_moskowitz_significant_wave_height_constant():
    U = np.array([5.0, 10.0, 20.0])
    hs = significant_wave_height_PiersonMoskowitz1964(U)
    np.testing.assert_allclose(hs, 4 * np.sqrt(elevation_variance_PiersonMoskowitz1964(U)), rtol=ROUNDOFF)
    # exact constant 2 √(α/β) = 0.20925, the "0.21 U²/g" of the literature to 0.4 %
    constant = hs * GRAVITY / U**2
    np.testing.assert_allclose(constant, 2 * np.sqrt(PIERSON_MOSKOWITZ_ALPHA / PIERSON_MOSKOWITZ_BETA), rtol=ROUNDOFF)
    np.testing.assert_allclose(constant, 0.20925, rtol=1e-4)
    np.testing.assert_allclose(constant, 0.21, rtol=5e-3)


def test_pierson_moskowitz_peak_frequency():
    U = 12.0
    omega_p = peak_frequency_PiersonMoskowitz1964(U)
    assert omega_p == pytest.approx(0.87716 * GRAVITY / U, rel=1e-5)
    omega = omega_p * np.linspace(0.9, 1.1, 20001)
    assert omega[np.argmax(spectrum_PiersonMoskowitz1964(omega, U))] == pytest.approx(omega_p, rel=1e-5)


def test_jonswap_with_unit_gamma_is_pierson_moskowitz_shaped():
    U, F = 11.0, 40e3
    alpha, omega_p = phillips_constant_JONSWAP1973(U, F), peak_frequency_JONSWAP1973(U, F)
    omega = np.geomspace(0.3, 20, 200) * omega_p
    # β ω₀⁴ = (5/4) ω_p⁴ with β = 5/4: ω₀ = ω_p, i.e. "U₁₉.₅" = g/ω_p
    pm_shaped = spectrum_PiersonMoskowitz1964(omega, GRAVITY / omega_p, alpha=alpha, beta=1.25)
    # relative to the peak: at 0.3 ω_p the spectra are e^{−154} ≈ 1e-67 of it, where the round-off
    # of the exponent (two formulas) is all a relative comparison would see
    scale = pm_shaped.max()
    np.testing.assert_allclose(spectrum_JONSWAP1973(omega, U, F, gamma=1.0) / scale, pm_shaped / scale, rtol=0,
                               atol=ROUNDOFF)


@pytest.mark.parametrize("gamma", [1.0, 2.0, JONSWAP_GAMMA, 7.0])
def test_jonswap_peak_enhancement_equals_gamma(gamma):
    U, F = 9.0, 120e3
    omega_p = peak_frequency_JONSWAP1973(U, F)
    ratio = spectrum_JONSWAP1973(omega_p, U, F, gamma=gamma) / spectrum_JONSWAP1973(omega_p, U, F, gamma=1.0)
    assert ratio == pytest.approx(gamma, rel=ROUNDOFF)
    # far from the peak the enhancement is gone
    far = 3 * omega_p
    plain = spectrum_JONSWAP1973(far, U, F, gamma=1.0)
    assert spectrum_JONSWAP1973(far, U, F, gamma=gamma) == pytest.approx(plain, rel=ROUNDOFF)


def test_jonswap_fetch_laws():
    U, F = 10.0, 100e3
    x = GRAVITY * F / U**2  # dimensionless fetch
    assert phillips_constant_JONSWAP1973(U, F) == pytest.approx(0.076 * x**-0.22, rel=ROUNDOFF)
    assert peak_frequency_JONSWAP1973(U, F) * U / GRAVITY == pytest.approx(22 * x ** (-1 / 3), rel=ROUNDOFF)
    # fully developed limit quoted in the docstring: ω_p reaches the PM peak at x ≈ 1.7e4
    x_full = (22 / (0.87716 / PIERSON_MOSKOWITZ_WIND_RATIO)) ** 3
    assert x_full == pytest.approx(1.7e4, rel=0.01)
    fetch_full = x_full * U**2 / GRAVITY
    pm_peak = peak_frequency_PiersonMoskowitz1964(PIERSON_MOSKOWITZ_WIND_RATIO * U)
    assert peak_frequency_JONSWAP1973(U, fetch_full) == pytest.approx(pm_peak, rel=1e-4)


def test_tma_tends_to_jonswap_in_deep_water_and_is_smaller_in_shallow():
    U, F = 12.0, 60e3
    omega = np.geomspace(0.3, 10, 300) * peak_frequency_JONSWAP1973(U, F)
    jonswap = spectrum_JONSWAP1973(omega, U, F)
    # relative to the peak (at 0.3 ω_p the spectrum is ~1e-67 of it)
    scale = jonswap.max()
    np.testing.assert_allclose(spectrum_TMA1985(omega, U, F, np.inf) / scale, jonswap / scale, rtol=0, atol=ROUNDOFF)
    np.testing.assert_allclose(spectrum_TMA1985(omega, U, F, 1e4) / scale, jonswap / scale, rtol=0, atol=ROUNDOFF)
    shallow = spectrum_TMA1985(omega, U, F, 4.0)
    omega_p = peak_frequency_JONSWAP1973(U, F)
    assert np.all(shallow <= jonswap)
    assert np.all(shallow[omega < 2 * omega_p] < jonswap[omega < 2 * omega_p])
    deep_m0 = integrate_omega(lambda w: spectrum_JONSWAP1973(w, U, F), omega_p)
    assert integrate_omega(lambda w: spectrum_TMA1985(w, U, F, 4.0), omega_p) < 0.9 * deep_m0


def test_depth_function_limits_and_approximation():
    depth = 5.0
    omega_h = np.linspace(1e-3, 4, 4001)
    omega = omega_h * np.sqrt(GRAVITY / depth)
    exact = depth_function_Kitaigorodskii1975(omega, depth)
    assert np.all(np.diff(exact) > 0) and np.all((exact > 0) & (exact < 1))
    # shallow limit φ → ω_h²/2
    assert exact[0] == pytest.approx(0.5 * omega_h[0] ** 2, rel=1e-5)
    # the Thompson & Vincent (1983) piecewise form is a close approximation
    approx = depth_function_ThompsonVincent1983(omega, depth)
    assert np.max(np.abs(approx - exact)) < 0.025
    assert depth_function_Kitaigorodskii1975(1.0, np.inf) == 1.0
    assert depth_function_Kitaigorodskii1975(0.0, depth) == 0.0


def test_swell_variance_and_peak():
    height, period = 1.8, 13.0
    omega_s = 2 * np.pi / period
    numeric = quad(spectrum_swell, 0, 3 * omega_s, args=(height, period), points=[omega_s], epsabs=0, epsrel=1e-12)[0]
    assert numeric == pytest.approx((height / 4) ** 2, rel=1e-10)  # quad asked for 1e-12
    omega = omega_s * np.linspace(0.95, 1.05, 10001)
    assert omega[np.argmax(spectrum_swell(omega, height, period))] == pytest.approx(omega_s, rel=1e-5)
    with np.errstate(divide="raise", over="raise", invalid="raise"):
        assert spectrum_swell(np.array([0.0, -1.0, 1e-300]), height, period).tolist() == [0.0, 0.0, 0.0]


def test_frequency_spectrum_dispatch():
    omega = np.array([0.5, 1.0, 2.0])
    via = frequency_spectrum("TMA 1985", omega, wind_speed_10=8.0, fetch=2e4, depth=6.0, alpha=0.1, spreading="cos2")
    np.testing.assert_array_equal(via, spectrum_TMA1985(omega, 8.0, 2e4, 6.0))  # dispatch: the same call
    with pytest.raises(ValueError, match="JONSWAP 1973") as error:
        frequency_spectrum("Phillips 2001", omega)
    assert "Phillips 2001" in str(error.value)


# ---------------------------------------------------------------------------
# DirectionalSpectrum
# ---------------------------------------------------------------------------

#: A wind sea with a cross swell, used by several tests.
SEA = dict(wind_speed=12.0, wind_direction=0.4, fetch=30e3, swell_height=1.0, swell_period=12.0, swell_direction=-1.0)


@pytest.mark.parametrize("spreading", list(SPREADING))
def test_directional_variance_equals_frequency_integral(spreading):
    spec = DirectionalSpectrum("JONSWAP 1973", spreading=spreading, **SEA)
    expected = integrate_omega(lambda w: spectrum_JONSWAP1973(w, 12.0, 30e3), spec.peak_frequency) + (1.0 / 4) ** 2
    assert spec.elevation_variance() == pytest.approx(expected, rel=1e-4)
    assert spec.significant_wave_height() == pytest.approx(4 * np.sqrt(expected), rel=1e-4)


@pytest.mark.parametrize(
    ("method", "spreading", "depth"),
    [("Pierson-Moskowitz 1964", "Donelan-Banner 1985", np.inf), ("TMA 1985", "Hasselmann 1980", 5.0),
     ("JONSWAP 1973", "cos2", 5.0)],
)
def test_directional_variance_other_methods_and_finite_depth(method, spreading, depth):
    sea = {k: v for k, v in SEA.items() if not (k == "fetch" and method == "Pierson-Moskowitz 1964")}
    spec = DirectionalSpectrum(method, spreading=spreading, depth=depth, **sea)
    expected = integrate_omega(spec.wind_sea_frequency_spectrum, spec.peak_frequency) + spec.swell_variance
    assert spec.elevation_variance() == pytest.approx(expected, rel=1e-4)
    if method == "Pierson-Moskowitz 1964":
        closed = elevation_variance_PiersonMoskowitz1964(PIERSON_MOSKOWITZ_WIND_RATIO * 12.0) + spec.swell_variance
        assert spec.elevation_variance() == pytest.approx(closed, rel=1e-4)


def test_directional_phillips_uses_the_phillips_function():
    spec = DirectionalSpectrum("Phillips 2001", wind_speed=9.0, wind_direction=0.2, small_wave_length=0.3)
    assert spec.spreading is None
    kx, ky = np.meshgrid(np.linspace(-1, 1, 9), np.linspace(-1, 1, 7))
    direct = spectrum_Phillips2001(kx, ky, 9.0, 0.2, small_wave_length=0.3)
    np.testing.assert_array_equal(spec(kx, ky), direct)  # the same function with the same arguments
    closed = elevation_variance_Phillips2001(9.0, small_wave_length=0.3)
    assert spec.elevation_variance() == pytest.approx(closed, rel=1e-4)
    # swell adds its variance to the Phillips sea
    with_swell = DirectionalSpectrum("Phillips 2001", wind_speed=9.0, swell_height=2.0, swell_period=11.0)
    expected = elevation_variance_Phillips2001(9.0) + (2.0 / 4) ** 2
    assert with_swell.elevation_variance() == pytest.approx(expected, rel=1e-4)


@pytest.mark.parametrize("depth", [np.inf, 8.0])
def test_directional_jacobian_recovers_frequency_spectrum(depth):
    # ∫ Ψ(k(ω), θ) dθ · k / c_g = S(ω) at every ω: the Jacobian pointwise
    spec = DirectionalSpectrum("JONSWAP 1973", spreading="Donelan-Banner 1985", depth=depth, **SEA)
    omega = spec.peak_frequency * np.array([0.7, 1.0, 1.5, 4.0])
    k = wavenumber_from_frequency(omega, depth)[:, None]
    theta = np.linspace(0, 2 * np.pi, 2048, endpoint=False)
    ring = spec(k * np.cos(theta), k * np.sin(theta)).mean(axis=1) * 2 * np.pi
    recovered = ring * k[:, 0] / group_velocity(k[:, 0], depth)
    # the ring by the periodic rectangle rule in 2048 directions (2e-8 off, measured)
    np.testing.assert_allclose(recovered, spec.frequency_spectrum(omega), rtol=QUADRATURE)


def test_directional_zero_wavenumber_and_extremes_are_finite():
    k = np.array([0.0, 1e-300, 1e-12, 1e-3, 1.0, 1e3, 1e8, 1e12])
    with np.errstate(divide="raise", over="raise", invalid="raise"):
        for method in SPECTRA:
            spreading = None if method in WAVENUMBER_SPECTRA else "Mitsuyasu 1975"  # those carry their own
            sea = {k: v for k, v in SEA.items()
                   if not (k == "fetch" and method in ("Phillips 2001", "Pierson-Moskowitz 1964"))}
            spec = DirectionalSpectrum(method, spreading=spreading, depth=3.0, small_wave_length=0.01, **sea)
            psi = spec(k[:, None], np.array([0.0, -1e-9, 2.0]))
            assert spec(0.0, 0.0) == 0.0
            assert np.all(np.isfinite(psi)) and np.all(psi >= 0)
    assert np.isnan(DirectionalSpectrum()(np.nan, 0.1))


@pytest.mark.parametrize("spreading", list(SPREADING))
def test_directional_symmetric_about_wind_and_peaks_downwind(spreading):
    direction = 0.9
    spec = DirectionalSpectrum("JONSWAP 1973", spreading=spreading, wind_direction=direction)
    k = wavenumber_from_frequency(spec.peak_frequency * np.array([0.8, 1.0, 2.0]))[:, None]
    offset = np.linspace(0, np.pi, 61)
    left = spec(k * np.cos(direction + offset), k * np.sin(direction + offset))
    right = spec(k * np.cos(direction - offset), k * np.sin(direction - offset))
    # NOTE: compared relative to each wavenumber's maximum over direction. Directly
    # upwind (offset = π) the spreading is ~1e-60…1e-110 of its peak, and there the
    # round-off of cos(direction ± π) in the last bit (~1e-16 rad) changes the value
    # by orders of magnitude between numpy builds; no physical quantity sees it.
    scale = left.max(axis=1, keepdims=True)
    np.testing.assert_allclose(left / scale, right / scale, rtol=0, atol=ROUNDOFF)
    assert np.all(np.argmax(left, axis=1) == 0)


def test_small_wave_length_reduces_variance():
    base = DirectionalSpectrum("JONSWAP 1973", wind_speed=8.0)
    cut = DirectionalSpectrum("JONSWAP 1973", wind_speed=8.0, small_wave_length=0.5)
    expected = integrate_omega(cut.frequency_spectrum, cut.peak_frequency)
    assert cut.elevation_variance() == pytest.approx(expected, rel=1e-4)
    assert cut.elevation_variance() < 0.99 * base.elevation_variance()


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        (dict(method="JONSWAP 1937"), "method"),
        (dict(spreading="cos4"), "spreading"),
        (dict(method="Phillips 2001", spreading="cos2"), "spreading"),
        (dict(wind_speed=0.0), "wind_speed"),
        (dict(wind_speed=-3.0), "wind_speed"),
        (dict(wind_speed=np.nan), "wind_speed"),
        (dict(wind_direction=np.inf), "wind_direction"),
        (dict(fetch=0.0), "fetch"),
        (dict(fetch=-1e3), "fetch"),
        (dict(gamma=0.5), "gamma"),
        (dict(depth=0.0), "depth"),
        (dict(depth=-5.0), "depth"),
        (dict(small_wave_length=-0.1), "small_wave_length"),
        (dict(alpha=0.01), "alpha"),
        (dict(method="Pierson-Moskowitz 1964", alpha=-0.01), "alpha"),
        (dict(swell_height=-1.0), "swell_height"),
        (dict(swell_period=0.0), "swell_period"),
        (dict(swell_spreading_s=-2.0), "swell_spreading_s"),
        (dict(swell_bandwidth=0.0), "swell_bandwidth"),
        (dict(g=0.0), "g"),
    ],
)
def test_directional_bad_inputs_name_the_field(changes, field):
    with pytest.raises(ValueError, match=rf"^{field}\b"):
        DirectionalSpectrum(**changes)


def test_directional_unknown_names_list_known():
    with pytest.raises(ValueError) as error:
        DirectionalSpectrum(method="JONSWAP 1937")
    assert all(name in str(error.value) for name in SPECTRA)
    with pytest.raises(ValueError) as error:
        DirectionalSpectrum(spreading="cos4")
    assert all(name in str(error.value) for name in SPREADING)


def test_wave_spectrum_builds_directional_spectrum_for_frequency_spectra():
    kx, ky = np.array([0.05, 0.2, -0.1]), np.array([0.01, -0.1, 0.3])
    via = wave_spectrum("JONSWAP 1973", kx, ky, wind_speed=9.0, wind_direction=0.2, small_wave_length=0.0,
                        g=GRAVITY, fetch=5e4)
    direct = DirectionalSpectrum("JONSWAP 1973", wind_speed=9.0, wind_direction=0.2, fetch=5e4)(kx, ky)
    np.testing.assert_array_equal(via, direct)  # the same spectrum built with the same parameters
    # Every parameter the method cannot use is an error, not dropped (issue 23, item 4).
    for method, bad, match in (("JONSWAP 1973", {"alpha": PHILLIPS_ALPHA}, "alpha"), ("JONSWAP 1973", {"seed": 3}, "seed"),
                               ("Pierson-Moskowitz 1964", {"fetch": 5e4}, "fetch"),
                               ("Phillips 2001", {"gamma": 2.0}, "gamma"), ("Phillips 2001", {"depth": 20.0}, "depth")):
        with pytest.raises(ValueError, match=match):
            wave_spectrum(method, kx, ky, wind_speed=9.0, **bad)
    for method in FREQUENCY_SPECTRA:
        assert np.all(wave_spectrum(method, kx, ky, wind_speed=9.0, wind_direction=0.2, depth=20.0) > 0)
    with pytest.raises(ValueError, match="wind_speed"):
        wave_spectrum("TMA 1985", kx, ky, wind_speed=0.0, wind_direction=0.0)


# ---------------------------------------------------------------------------
# Dispersion relation with capillarity, group velocity, inverse
# ---------------------------------------------------------------------------

def test_capillary_term_raises_frequency_of_short_waves():
    k = np.array([1e-2, 1.0, 100.0, 1000.0])
    gravity = dispersion_relation(k)
    capillary = dispersion_relation(k, surface_tension=SEAWATER_SURFACE_TENSION)
    assert np.all(capillary > gravity)
    assert capillary[0] == pytest.approx(gravity[0], rel=1e-8)  # long waves: σk²/(2ρg) ≈ 4e-10, no effect
    assert capillary[-1] > 2 * gravity[-1]  # 6 mm waves: capillary dominated


def test_minimum_phase_speed_of_capillary_gravity_waves():
    k = np.geomspace(50, 2000, 100001)
    speed = dispersion_relation(k, surface_tension=SEAWATER_SURFACE_TENSION) / k
    i = np.argmin(speed)
    assert speed[i] == pytest.approx(0.23, abs=0.005)
    assert 2 * np.pi / k[i] == pytest.approx(0.017, abs=0.0005)
    # closed forms c_min = (4 g σ/ρ)^¼ at k_m = √(ρ g/σ)
    tension = SEAWATER_SURFACE_TENSION / 1025.0
    assert speed[i] == pytest.approx((4 * GRAVITY * tension) ** 0.25, rel=1e-6)
    assert k[i] == pytest.approx(np.sqrt(GRAVITY / tension), rel=1e-3)


def test_group_velocity_limits_and_derivative():
    k = np.geomspace(1e-3, 1e2, 40)
    np.testing.assert_allclose(group_velocity(k), dispersion_relation(k) / (2 * k), rtol=ROUNDOFF)
    depth = 3.0
    shallow = np.geomspace(1e-6, 1e-4, 5)
    # c_g = √(g d) (1 − (kd)²/2 + …): (kd)²/2 ≤ 4.5e-8 here
    np.testing.assert_allclose(group_velocity(shallow, depth), np.sqrt(GRAVITY * depth), rtol=1e-7)
    assert group_velocity(0.0, depth) == pytest.approx(np.sqrt(GRAVITY * depth), rel=ROUNDOFF)
    # analytic dω/dk against central differences, with depth and capillarity (h = 1e-6 k:
    # truncation ~1e-12, round-off ε/1e-6 ≈ 1e-10)
    for d in (np.inf, 0.5, 20.0):
        h = 1e-6 * k
        slope = (dispersion_relation(k + h, d, surface_tension=SEAWATER_SURFACE_TENSION)
                 - dispersion_relation(k - h, d, surface_tension=SEAWATER_SURFACE_TENSION)) / (2 * h)
        np.testing.assert_allclose(group_velocity(k, d, surface_tension=SEAWATER_SURFACE_TENSION), slope, rtol=1e-8)


@pytest.mark.parametrize("depth", [0.1, 2.0, 50.0, np.inf])
def test_wavenumber_from_frequency_inverts_dispersion(depth):
    omega = np.geomspace(1e-4, 1e2, 200)
    # Newton iterated to convergence: the inverse holds to round-off
    np.testing.assert_allclose(dispersion_relation(wavenumber_from_frequency(omega, depth), depth), omega,
                               rtol=ROUNDOFF)
    assert wavenumber_from_frequency(0.0, depth) == 0.0
