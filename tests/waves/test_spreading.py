"""Tests for oceanrender.waves.spreading: normalisation, symmetry, published parameters, dispatch."""

import inspect

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import gamma as gamma_function

from oceanrender.waves.spreading import (
    SPREADING,
    directional_spreading,
    normalisation_cos2s,
    spreading_cos2,
    spreading_cos2s,
    spreading_DonelanBanner1985,
    spreading_parameter_Hasselmann1980,
    spreading_parameter_Mitsuyasu1975,
    spreading_width_DonelanBanner1985,
    wrap_angle,
)
from oceanrender.waves.wave_spectra import GRAVITY
from tests.tolerances import ROUNDOFF

#: Tolerance of ∫ D dθ = 1.
NORMALISATION_TOL = 1e-6

#: Relative tolerance between the two forms of the cos^2s normalisation: Γ(2s + 1) reaches
#: 1e284 at s = 80, and the gamma functions' error grows with their argument (4e-14 measured).
GAMMA_RTOL = 10 * ROUNDOFF

#: Peak frequency [rad s⁻¹] and U₁₀ [m s⁻¹] of a young wind sea (U/c_p ≈ 1.3).
OMEGA_P, WIND_SPEED = 1.0, 12.0

#: Frequencies across all branches of the parameterisations [rad s⁻¹].
OMEGAS = OMEGA_P * np.array([0.3, 0.56, 0.8, 0.95, 1.0, 1.3, 1.6, 3.0, 10.0])

SETTINGS = dict(peak_frequency=OMEGA_P, wind_speed_10=WIND_SPEED, g=GRAVITY)


def circle_integral(function):
    """∫_{−π}^{π} f dθ, split at the kinks of the one-sided cos² [-]."""
    pieces = [(-np.pi, -np.pi / 2), (-np.pi / 2, 0), (0, np.pi / 2), (np.pi / 2, np.pi)]
    return sum(quad(function, a, b, epsabs=1e-13, epsrel=1e-12, limit=200)[0] for a, b in pieces)


@pytest.mark.parametrize("method", list(SPREADING))
@pytest.mark.parametrize("omega", OMEGAS)
def test_spreading_integrates_to_one(method, omega):
    total = circle_integral(lambda theta: directional_spreading(method, theta, omega=omega, **SETTINGS))
    assert total == pytest.approx(1.0, abs=NORMALISATION_TOL)


@pytest.mark.parametrize("method", list(SPREADING))
def test_spreading_symmetric_periodic_and_peaked_on_the_wind(method):
    theta = np.linspace(0, np.pi, 181)[:, None]
    omega = OMEGAS[None, :]
    d = directional_spreading(method, theta, omega=omega, **SETTINGS)
    # NOTE: relative to each frequency's peak (on the wind). Behind the wind a narrow spreading
    # is many orders below it, and there the round-off of the wrapped angle (~1e-16 rad)
    # changes the value by large factors that no physical quantity sees.
    peak = d.max(axis=0)
    np.testing.assert_allclose(directional_spreading(method, -theta, omega=omega, **SETTINGS) / peak, d / peak,
                               rtol=0, atol=ROUNDOFF)
    np.testing.assert_allclose(directional_spreading(method, theta + 2 * np.pi, omega=omega, **SETTINGS) / peak,
                               d / peak, rtol=0, atol=ROUNDOFF)
    assert np.all(d >= 0)
    assert np.all(np.argmax(d, axis=0) == 0)
    # non-increasing away from the wind, up to round-off of the peak's scale
    assert np.all(np.diff(d, axis=0) <= ROUNDOFF * peak)


@pytest.mark.parametrize("s", [0.0, 0.3, 1.0, 2.7, 11.5, 80.0])
def test_cos2s_normalisation_against_quadrature(s):
    numeric = quad(lambda theta: np.cos(theta / 2) ** (2 * s), -np.pi, np.pi, epsabs=0, epsrel=1e-13)[0]
    assert normalisation_cos2s(s) == pytest.approx(1 / numeric, rel=1e-10)  # quad asked for 1e-13
    # Mitsuyasu et al.'s form 2^{2s−1} Γ(s+1)² / (π Γ(2s+1)), by the duplication formula
    mitsuyasu = 2 ** (2 * s - 1) * gamma_function(s + 1) ** 2 / (np.pi * gamma_function(2 * s + 1))
    assert normalisation_cos2s(s) == pytest.approx(mitsuyasu, rel=GAMMA_RTOL)
    assert circle_integral(lambda theta: spreading_cos2s(theta, s)) == pytest.approx(1.0, abs=1e-10)


def test_cos2s_large_s_does_not_overflow():
    with np.errstate(divide="raise", over="raise", invalid="raise"):
        value = spreading_cos2s(0.0, 1e4)
    # Laplace: G(s) → √(s/π)/2 for s → ∞ (the next term, 1/(8s) ≈ 1e-5 of it)
    assert value == pytest.approx(np.sqrt(1e4 / np.pi) / 2, rel=1e-4)


def test_cos2_is_one_sided_and_half_of_tessendorf_in_front():
    theta = np.linspace(-np.pi, np.pi, 721)
    d = spreading_cos2(theta)
    behind = np.abs(theta) >= np.pi / 2
    assert np.all(d[behind] == 0)
    # the symmetric variant of Tessendorf (2001), cos²θ/π, has half the density in front
    # relative to the peak 2/π: the values fall to ~0 at ±π/2, where cos θ is all round-off
    np.testing.assert_allclose(d[~behind], 2 * np.cos(theta[~behind]) ** 2 / np.pi, rtol=0, atol=ROUNDOFF * 2 / np.pi)
    assert spreading_cos2(0.0) == pytest.approx(2 / np.pi, rel=ROUNDOFF)


def test_mitsuyasu_spreading_parameter():
    s_peak = 11.5 * (WIND_SPEED * OMEGA_P / GRAVITY) ** -2.5
    s = spreading_parameter_Mitsuyasu1975(OMEGAS, OMEGA_P, WIND_SPEED)
    assert s[OMEGAS == OMEGA_P][0] == pytest.approx(s_peak, rel=ROUNDOFF)
    np.testing.assert_allclose(s[OMEGAS < OMEGA_P], s_peak * (OMEGAS[OMEGAS < OMEGA_P] / OMEGA_P) ** 5, rtol=ROUNDOFF)
    np.testing.assert_allclose(s[OMEGAS > OMEGA_P], s_peak * (OMEGAS[OMEGAS > OMEGA_P] / OMEGA_P) ** -2.5,
                               rtol=ROUNDOFF)
    # narrowest at the peak
    assert np.argmax(s) == np.flatnonzero(OMEGAS == OMEGA_P)[0]


def test_hasselmann_spreading_parameter():
    below = spreading_parameter_Hasselmann1980(0.5 * OMEGA_P, OMEGA_P, WIND_SPEED)
    assert below == pytest.approx(6.97 * 0.5**4.06, rel=ROUNDOFF)
    assert spreading_parameter_Hasselmann1980(OMEGA_P, OMEGA_P, WIND_SPEED) == pytest.approx(9.77, rel=ROUNDOFF)
    # at U/c_p = 1.17 the exponent above the peak is −2.33
    wind = 1.17 * GRAVITY / OMEGA_P
    assert spreading_parameter_Hasselmann1980(2 * OMEGA_P, OMEGA_P, wind) == pytest.approx(9.77 * 2**-2.33,
                                                                                           rel=ROUNDOFF)


def test_donelan_banner_width():
    ratio = np.array([0.3, 0.7, 0.95, 1.2, 1.6, 2.5, 1e3])
    beta = spreading_width_DonelanBanner1985(ratio * OMEGA_P, OMEGA_P)
    np.testing.assert_allclose(
        beta[:5], [1.24, 2.61 * 0.7**1.3, 2.28 * 0.95**-1.3, 2.28 * 1.2**-1.3, 10 ** (-0.4 + 0.8393 * 1.6**-1.134)],
        rtol=ROUNDOFF,
    )
    # the pieces meet within 1 % and Banner's branch tends to 10^−0.4
    for edge in (0.56, 0.95, 1.6):
        below, above = spreading_width_DonelanBanner1985(edge * np.array([1 - 1e-9, 1 + 1e-9]), 1.0)
        assert below == pytest.approx(above, rel=0.01)
    assert beta[-1] == pytest.approx(10**-0.4, rel=1e-3)


def test_donelan_banner_closed_form_normalisation_differs_from_the_line_one():
    # (β/2) sech²(βθ) integrates to tanh(βπ) on the circle; the closed-form factor restores 1
    omega = 1e3 * OMEGA_P  # Banner's broad limit, β → 0.40
    beta = spreading_width_DonelanBanner1985(omega, OMEGA_P)
    line = circle_integral(lambda theta: beta / 2 / np.cosh(beta * theta) ** 2)
    assert line == pytest.approx(np.tanh(beta * np.pi), rel=1e-10)
    assert line < 0.9
    d = circle_integral(lambda theta: spreading_DonelanBanner1985(theta, omega, OMEGA_P))
    assert d == pytest.approx(1.0, abs=1e-10)


def test_wrap_angle():
    wrapped = wrap_angle([0.0, np.pi / 2, 3 * np.pi / 2, -5 * np.pi / 2])
    np.testing.assert_allclose(wrapped, [0, np.pi / 2, -np.pi / 2, -np.pi / 2], rtol=0, atol=ROUNDOFF * np.pi)
    assert np.all((wrap_angle(np.linspace(-20, 20, 101)) >= -np.pi) & (wrap_angle(np.linspace(-20, 20, 101)) < np.pi))


def test_zero_frequency_and_nan():
    with np.errstate(divide="raise", over="raise", invalid="raise"):
        for method in SPREADING:
            d = directional_spreading(method, np.array([0.0, 1.0, 3.0]), omega=np.array([0.0, 1e-300, 1e-150]),
                                      **SETTINGS)
            assert np.all(np.isfinite(d))
    for method in ("Mitsuyasu 1975", "Hasselmann 1980", "Donelan-Banner 1985"):
        assert np.isnan(directional_spreading(method, 0.1, omega=np.nan, **SETTINGS))


def test_dispatch_ignores_extra_keywords_and_refuses_unknown_names():
    d = directional_spreading("cos2", 0.3, omega=2.0, peak_frequency=1.0, depth=5.0)
    assert d == spreading_cos2(0.3)  # dispatch: the same function, the same argument
    with pytest.raises(ValueError, match="cos4") as error:
        directional_spreading("cos4", 0.0)
    assert all(name in str(error.value) for name in SPREADING)


def test_gravity_default_matches_spectra():
    for function in SPREADING.values():
        parameters = inspect.signature(function).parameters
        if "g" in parameters:
            assert parameters["g"].default == GRAVITY
