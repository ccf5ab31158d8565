"""Tests for :mod:`oceanrender.vision.brightness`."""

import math

import numpy as np
import pytest

from oceanrender.vision.brightness import (
    BRIGHTNESS_METHODS,
    adaptation_luminance_log_average,
    BRIGHTNESS_RESPONSES,
    brightness_response,
    brightness_scale_factor,
    response_ReinhardDevlin2005,
    scale_factor_ReinhardDevlin2005,
    semi_saturation_ReinhardDevlin2005,
    scale_factor_Ferwerda1996,
    scale_factor_Ward1994,
    threshold_photopic_Ferwerda1996,
)
from tests.tolerances import ROUNDOFF

#: Closed forms (powers, log10/10^x) evaluated two ways: float64 round-off, relative.
RTOL = ROUNDOFF


# ---------------------------------------------------------------- Ward 1994


@pytest.mark.parametrize("L_dmax", [80.0, 100.0, 250.0, 1000.0])
def test_Ward1994_unity_at_display_adaptation(L_dmax):
    L_da = L_dmax / 2
    np.testing.assert_allclose(scale_factor_Ward1994(L_da, L_dmax), 1.0, rtol=RTOL)


def test_Ward1994_monotone_decreasing():
    L_wa = np.logspace(-4, 6, 201)
    m = scale_factor_Ward1994(L_wa, 100.0)
    assert np.all(np.diff(m) < 0)
    # Display luminance of the adaptation level m·L_wa still rises with L_wa:
    # bright scenes stay brighter than dark ones.
    assert np.all(np.diff(m * L_wa) > 0)


def test_Ward1994_hand_computed():
    # L_dmax = 100 cd/m² → L_da = 50 cd/m²; L_wa = 1000 cd/m².
    #   50^0.4   = exp(0.4 ln 50) = exp(1.5648092)  = 4.7817625
    #   1000^0.4 = 10^1.2                            = 15.8489319
    #   ratio    = (1.219 + 4.7817625) / (1.219 + 15.8489319)
    #            = 6.0007625 / 17.0679319             = 0.35158111
    #   m        = 0.35158111^2.5 = exp(2.5 ln 0.35158111)
    #            = exp(2.5 × -1.0452989) = exp(-2.6132473) = 0.0732932
    assert scale_factor_Ward1994(1000.0, 100.0) == pytest.approx(0.0732932, rel=1e-6)


def test_Ward1994_broadcasts():
    L_wa = np.array([[10.0, 100.0], [1e3, 1e4]])
    m = scale_factor_Ward1994(L_wa, 100.0)
    assert m.shape == (2, 2)
    np.testing.assert_allclose(m[1, 0], scale_factor_Ward1994(1e3, 100.0), rtol=RTOL)


# ------------------------------------------------------------ Ferwerda 1996


def _log_t_p_branches(x):
    """The three published branches of log10 t_p, evaluated at log10 L_a = x."""
    return -0.72, (0.249 * x + 0.65) ** 2.7 - 0.72, x - 1.255


def test_Ferwerda1996_tvi_continuous_at_lower_breakpoint():
    # log10 L_a = -2.6: the transition branch gives (0.249·-2.6 + 0.65)^2.7 - 0.72
    # = 0.0026^2.7 - 0.72 = -0.7199999, i.e. continuous to ~1e-7 decades.
    low, middle, _ = _log_t_p_branches(-2.6)
    assert abs(middle - low) < 1e-6
    eps = 1e-9
    left = np.log10(threshold_photopic_Ferwerda1996(10 ** (-2.6 - eps)))
    right = np.log10(threshold_photopic_Ferwerda1996(10 ** (-2.6 + eps)))
    assert abs(right - left) < 1e-6


def test_Ferwerda1996_tvi_continuous_at_upper_breakpoint():
    # log10 L_a = 1.9: transition branch (0.249·1.9 + 0.65)^2.7 - 0.72
    # = 1.1231^2.7 - 0.72 = 0.6481375; Weber branch 1.9 - 1.255 = 0.645.
    # The published (rounded) constants leave a 3.1e-3-decade step (0.72 % in
    # t_p): continuous to the precision of the published fit, not exactly.
    _, middle, weber = _log_t_p_branches(1.9)
    assert middle - weber == pytest.approx(3.1375e-3, abs=1e-6)
    eps = 1e-9
    left = np.log10(threshold_photopic_Ferwerda1996(10 ** (1.9 - eps)))
    right = np.log10(threshold_photopic_Ferwerda1996(10 ** (1.9 + eps)))
    assert abs(right - left) < 5e-3
    assert left == pytest.approx(middle, abs=1e-6)
    assert right == pytest.approx(weber, abs=1e-6)


def test_Ferwerda1996_tvi_branches_selected():
    # Dark branch: constant 10^-0.72 cd/m² below 10^-2.6 cd/m².
    np.testing.assert_allclose(threshold_photopic_Ferwerda1996([1e-5, 1e-3]), 10**-0.72, rtol=RTOL)
    # Transition branch at L_a = 1 cd/m²: 0.65^2.7 - 0.72 = -0.4074885.
    assert np.log10(threshold_photopic_Ferwerda1996(1.0)) == pytest.approx(-0.4074885, abs=1e-7)
    # Weber branch: t_p = L_a · 10^-1.255.
    assert threshold_photopic_Ferwerda1996(1e4) == pytest.approx(1e4 * 10**-1.255, rel=RTOL)


def test_Ferwerda1996_tvi_zero_and_negative():
    with np.errstate(all="raise"):
        assert threshold_photopic_Ferwerda1996(0.0) == pytest.approx(10**-0.72, rel=RTOL)
    assert np.isnan(threshold_photopic_Ferwerda1996(np.nan))
    assert np.isnan(threshold_photopic_Ferwerda1996(-1.0))


@pytest.mark.parametrize("L_dmax", [80.0, 100.0, 250.0, 1000.0])
def test_Ferwerda1996_unity_at_display_adaptation(L_dmax):
    np.testing.assert_allclose(scale_factor_Ferwerda1996(L_dmax / 2, L_dmax), 1.0, rtol=RTOL)


def test_Ferwerda1996_hand_computed():
    # L_dmax = 100 → L_da = 50: log10 50 = 1.6989700 (transition branch)
    #   (0.249 × 1.6989700 + 0.65)^2.7 - 0.72 = 1.0730435^2.7 - 0.72
    #   = 1.2096697 - 0.72 = 0.4896697
    # L_wa = 1000 (Weber branch): log10 t_p = 3 - 1.255 = 1.745
    # m = 10^(0.4896697 - 1.745) = 10^-1.2553303 = 0.0555482
    assert scale_factor_Ferwerda1996(1000.0, 100.0) == pytest.approx(0.0555482, rel=1e-5)
    # L_wa = 1 (transition): log10 t_p = 0.65^2.7 - 0.72 = -0.4074885
    # m = 10^(0.4896697 + 0.4074885) = 10^0.8971582 = 7.891475
    assert scale_factor_Ferwerda1996(1.0, 100.0) == pytest.approx(7.891475, rel=1e-5)


def test_Ferwerda1996_weber_branch_inverse_proportional():
    L_wa = np.array([100.0, 1e3, 5e3, 3e4, 1e5])  # all above 10^1.9 ≈ 79.4 cd/m²
    m = scale_factor_Ferwerda1996(L_wa, 100.0)
    # m ∝ 1/L_wa: the adaptation level always lands on the same display luminance.
    np.testing.assert_allclose(m * L_wa, (m * L_wa)[0], rtol=RTOL)
    np.testing.assert_allclose(m[1] / m[2], 5.0, rtol=RTOL)


def test_Ferwerda1996_monotone_decreasing():
    L_wa = np.logspace(-2.5, 6, 301)  # above the constant dark branch
    assert np.all(np.diff(scale_factor_Ferwerda1996(L_wa, 100.0)) < 0)


# ------------------------------------------------------------ entry point


@pytest.mark.parametrize("method", list(BRIGHTNESS_METHODS))
def test_brightness_scale_factor_dispatch(method):
    expected = BRIGHTNESS_METHODS[method](1234.0, 120.0)
    assert brightness_scale_factor(method, 1234.0, 120.0) == pytest.approx(expected, rel=RTOL)


def test_brightness_methods_names():
    assert set(BRIGHTNESS_METHODS) == {"Ward 1994", "Ferwerda 1996", "Reinhard Devlin 2005"}
    assert set(BRIGHTNESS_RESPONSES) == set(BRIGHTNESS_METHODS)
    assert BRIGHTNESS_METHODS["Ward 1994"] is scale_factor_Ward1994
    assert BRIGHTNESS_METHODS["Ferwerda 1996"] is scale_factor_Ferwerda1996
    assert BRIGHTNESS_METHODS["Reinhard Devlin 2005"] is scale_factor_ReinhardDevlin2005
    assert BRIGHTNESS_RESPONSES["Reinhard Devlin 2005"] is response_ReinhardDevlin2005


def test_brightness_scale_factor_unknown_method():
    with pytest.raises(ValueError, match="Ward 1994") as info:
        brightness_scale_factor("Reinhard 2002", 100.0, 100.0)
    assert "Ferwerda 1996" in str(info.value)
    assert "Reinhard 2002" in str(info.value)


def test_brightness_response_unknown_method():
    with pytest.raises(ValueError, match="Reinhard Devlin 2005"):
        brightness_response("Reinhard 2002", [1.0])


# ------------------------------------------------ Reinhard & Devlin 2005


def test_ReinhardDevlin2005_response_half_at_semi_saturation():
    # V = I/(I + σ): 0 at I = 0, 1/2 at I = σ, 3/4 at 3σ, 1/(1 + 1/x) in general.
    x = np.array([0.0, 1.0, 3.0, 0.01, 1e6])
    np.testing.assert_allclose(response_ReinhardDevlin2005(x), x / (1.0 + x), rtol=ROUNDOFF)
    assert response_ReinhardDevlin2005(1.0) == pytest.approx(0.5, rel=ROUNDOFF)


def test_ReinhardDevlin2005_response_bounded_monotone_odd():
    x = np.concatenate([-np.logspace(8, -8, 200), [0.0], np.logspace(-8, 8, 200)])
    V = response_ReinhardDevlin2005(x)
    assert np.all(np.abs(V) < 1.0) and np.all(np.diff(V) > 0)
    np.testing.assert_array_equal(response_ReinhardDevlin2005(-x), -V)
    # It never reaches display white: V < 1 for any finite input; 8-bit 255 needs V > 254.5/255 in sRGB,
    # i.e. linear V > 0.9955, which takes x > 220.
    assert response_ReinhardDevlin2005(220.0) < 0.9955 < response_ReinhardDevlin2005(222.0)


def test_ReinhardDevlin2005_response_non_finite():
    V = response_ReinhardDevlin2005([np.nan, np.inf, -np.inf])
    assert np.isnan(V[0]) and V[1] == 1.0 and V[2] == -1.0


def test_ReinhardDevlin2005_semi_saturation():
    # σ = (f I_a)^m
    assert semi_saturation_ReinhardDevlin2005(200.0) == pytest.approx(200.0, rel=ROUNDOFF)
    assert semi_saturation_ReinhardDevlin2005(200.0, 2.0, 0.5) == pytest.approx(20.0, rel=ROUNDOFF)
    for f, m in [(0.0, 1.0), (1.0, 0.0), (1.0, 1.5)]:
        with pytest.raises(ValueError):
            semi_saturation_ReinhardDevlin2005(200.0, f, m)


@pytest.mark.parametrize("L_wa", [1.0, 150.0, 4000.0, 3e5])
def test_ReinhardDevlin2005_adaptation_luminance_displays_as_18_percent_grey(L_wa):
    m = scale_factor_ReinhardDevlin2005(L_wa, 100.0)
    assert response_ReinhardDevlin2005(m * L_wa / 100.0) == pytest.approx(0.18, rel=ROUNDOFF)


def test_ReinhardDevlin2005_independent_of_luminance_unit():
    # Scaling the scene and its adaptation luminance together leaves the display unchanged (m = 1).
    L = np.logspace(0, 5, 11)
    for k in (1e-3, 7.0, 1e4):
        np.testing.assert_allclose(scale_factor_ReinhardDevlin2005(k * 300.0) * k * L,
                                   scale_factor_ReinhardDevlin2005(300.0) * L, rtol=ROUNDOFF)


# ---------------------------------------------------------- log-average


@pytest.mark.parametrize("L", [0.01, 1.0, 250.0, 8000.0])
def test_log_average_constant_image(L):
    Y = np.full((4, 5), L)
    delta = 1e-4
    assert adaptation_luminance_log_average(Y, delta) == pytest.approx(L + delta, rel=ROUNDOFF)
    assert adaptation_luminance_log_average(Y, 0.0) == pytest.approx(L, rel=ROUNDOFF)


def test_log_average_geometric_mean():
    # exp(mean(ln 1, ln 100)) = exp(ln 10) = 10 with delta = 0.
    assert adaptation_luminance_log_average([1.0, 100.0], delta=0.0) == pytest.approx(10.0, rel=ROUNDOFF)
    # Default delta: exp((ln 1.0001 + ln 100.0001) / 2) = sqrt(1.0001 × 100.0001)
    assert adaptation_luminance_log_average([1.0, 100.0]) == pytest.approx(
        math.sqrt(1.0001 * 100.0001), rel=ROUNDOFF
    )


def test_log_average_ignores_non_finite():
    Y = np.array([[1.0, np.nan], [100.0, np.inf]])
    assert adaptation_luminance_log_average(Y, 0.0) == pytest.approx(10.0, rel=ROUNDOFF)
    Y = np.array([10.0, -np.inf, np.nan])
    assert adaptation_luminance_log_average(Y, 0.0) == pytest.approx(10.0, rel=ROUNDOFF)


def test_log_average_negative_clipped_to_black():
    # -5 is treated as 0: exp((ln(1e-4) + ln(100 + 1e-4)) / 2)
    expected = math.sqrt(1e-4 * (100.0 + 1e-4))
    assert adaptation_luminance_log_average([-5.0, 100.0]) == pytest.approx(expected, rel=ROUNDOFF)


def test_log_average_all_nan_raises():
    with pytest.raises(ValueError, match="finite"):
        adaptation_luminance_log_average(np.full(3, np.nan))
