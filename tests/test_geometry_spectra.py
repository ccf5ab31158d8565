"""Tests for oceanrender.geometry.spectra: closed forms, limits, method dispatch."""

import numpy as np
import pytest

from oceanrender.geometry.spectra import (
    GRAVITY,
    PHILLIPS_ALPHA,
    SPECTRA,
    dispersion_relation,
    elevation_variance_Phillips2001,
    significant_wave_height_Phillips2001,
    spectrum_Phillips2001,
    wave_spectrum,
)

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
    assert elevation_variance_Phillips2001(wind_speed) == pytest.approx(expected, rel=1e-12)


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
    np.testing.assert_allclose(significant_wave_height_Phillips2001(U), 4 * np.sqrt(m0), rtol=1e-12)
    # 2 √α U²/g at 10 m/s with √α = 0.09: 18/9.81 m
    assert significant_wave_height_Phillips2001(10.0) == pytest.approx(18 / 9.81, rel=1e-12)


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
    # two-sided: Ψ(−k) = Ψ(k)
    np.testing.assert_allclose(spectrum_Phillips2001(-kx, -ky, 8.0, direction), psi, rtol=1e-14)
    # no waves travel across the wind
    across = spectrum_Phillips2001(-np.sin(direction) * 0.1, np.cos(direction) * 0.1, 8.0, direction)
    assert across == pytest.approx(0.0, abs=1e-20)
    # rotating k and the wind together changes nothing
    c, s = np.cos(1.1), np.sin(1.1)
    rotated = spectrum_Phillips2001(c * kx - s * ky, s * kx + c * ky, 8.0, direction + 1.1)
    np.testing.assert_allclose(rotated, psi, rtol=1e-12)


def test_phillips_broadcasts():
    k = np.linspace(0.01, 1, 5)[:, None]
    U = np.array([5.0, 10.0, 15.0])
    assert spectrum_Phillips2001(k, 0.0, U, 0.0).shape == (5, 3)


def test_dispersion_deep_water_limit():
    k = np.geomspace(1e-3, 1e2, 50)
    np.testing.assert_array_equal(dispersion_relation(k), np.sqrt(GRAVITY * k))
    # tanh(kd) → 1 once kd ≳ 20
    np.testing.assert_allclose(dispersion_relation(k[k > 0.1], depth=200.0), np.sqrt(GRAVITY * k[k > 0.1]), rtol=1e-12)
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
    np.testing.assert_array_equal(via, direct)


def test_wave_spectrum_unknown_method_lists_known():
    with pytest.raises(ValueError, match="Phillips 2001") as error:
        wave_spectrum("JONSWAP 1937", 0.1, 0.1, wind_speed=5.0, wind_direction=0.0)
    assert "JONSWAP 1937" in str(error.value)
    assert all(name in str(error.value) for name in SPECTRA)
