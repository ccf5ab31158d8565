"""The dispersion relation of surface gravity–capillary waves over a finite depth, its group velocity
and its inverse, with the physical constants they use (g, sea water's surface tension and density).

Part of the wave spectra of :mod:`.wave_spectra` (which re-exports every name here); its docstring gives
the conventions, and each function its formula and source.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

GRAVITY: float = 9.81
"""Standard gravitational acceleration used throughout [m s⁻²]."""

SEAWATER_SURFACE_TENSION: float = 0.074
"""Surface tension of sea water against air σ [N m⁻¹], to pass as ``surface_tension``."""

SEAWATER_DENSITY: float = 1025.0
"""Density of sea water ρ [kg m⁻³]."""


# ---------------------------------------------------------------------------
# Dispersion relation
# ---------------------------------------------------------------------------


def _depth_terms(k: NDArray[np.float64], depth: ArrayLike):
    """(deep mask, depth with inf → 1, tanh kd, sech² kd) without overflow or NaN."""
    depth = np.asarray(depth, dtype=np.float64)
    deep = np.isinf(depth)
    d = np.where(deep, 1.0, depth)
    kd = k * d
    # NOTE: tanh(k·inf) is NaN at k = 0; the deep-water branch avoids it.
    tanh_kd = np.where(deep, 1.0, np.tanh(kd))
    e = np.exp(-2 * np.abs(kd))
    sech2_kd = np.where(deep, 0.0, 4 * e / np.square(1 + e))  # sech² kd, no cosh overflow
    return deep, d, tanh_kd, sech2_kd


def dispersion_relation(
    k: ArrayLike,
    depth: ArrayLike = np.inf,
    g: float = GRAVITY,
    surface_tension: ArrayLike = 0.0,
    density: ArrayLike = SEAWATER_DENSITY,
) -> NDArray[np.float64]:
    """Angular frequency of linear surface waves ω(k) [rad s⁻¹].

    Parameters
    ----------
    k : array_like
        Wavenumber magnitude [rad m⁻¹].
    depth : array_like, optional
        Water depth d [m]; ``np.inf`` (default) uses the deep-water limit exactly.
    g : float, optional
        Gravitational acceleration [m s⁻²].
    surface_tension : array_like, optional
        Surface tension σ [N m⁻¹]; 0 (default) gives pure gravity waves, pass
        :data:`SEAWATER_SURFACE_TENSION` (0.074) for gravity–capillary waves.
    density : array_like, optional
        Water density ρ [kg m⁻³].

    Returns
    -------
    ndarray
        ω = √((g k + σ k³/ρ) tanh(k d)) [rad s⁻¹].

    Notes
    -----
    With capillarity the phase speed c = ω/k has its minimum
    c_min = (4 g σ/ρ)^{1/4} ≈ 0.231 m s⁻¹ at k_m = √(ρ g/σ), λ_m = 2π/k_m ≈ 1.70 cm
    (deep water, σ = 0.074 N m⁻¹, ρ = 1025 kg m⁻³).

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       eqs. 14 and 15.
    .. [2] H. Lamb, Hydrodynamics, 6th ed., Cambridge University Press, 1932
       (waves under gravity and capillarity).
    """
    k = np.asarray(k, dtype=np.float64)
    _, _, tanh_kd, _ = _depth_terms(k, depth)
    restoring = g * k
    if np.any(np.asarray(surface_tension) != 0):
        restoring = restoring + np.asarray(surface_tension) / density * k**3  # capillary term of [2]
    return np.sqrt(restoring * tanh_kd)  # Eq. 15 of [1]; eq. 14 when d = inf


def group_velocity(
    k: ArrayLike,
    depth: ArrayLike = np.inf,
    g: float = GRAVITY,
    surface_tension: ArrayLike = 0.0,
    density: ArrayLike = SEAWATER_DENSITY,
) -> NDArray[np.float64]:
    """Group velocity c_g = dω/dk of linear surface waves [m s⁻¹].

    Parameters
    ----------
    k : array_like
        Wavenumber magnitude [rad m⁻¹].
    depth : array_like, optional
        Water depth d [m]; ``np.inf`` for deep water.
    g : float, optional
        Gravitational acceleration [m s⁻²].
    surface_tension : array_like, optional
        Surface tension σ [N m⁻¹]; 0 for pure gravity waves.
    density : array_like, optional
        Water density ρ [kg m⁻³].

    Returns
    -------
    ndarray
        c_g = [(g + 3σk²/ρ) tanh kd + (g k + σk³/ρ) d sech² kd] / (2ω) [m s⁻¹],
        the derivative of :func:`dispersion_relation`. Deep gravity waves:
        ω/(2k); shallow: → √(g d). At k = 0 the limit √(g d) (inf in deep water).

    References
    ----------
    .. [1] H. Lamb, Hydrodynamics, 6th ed., Cambridge University Press, 1932
       (group velocity; waves under gravity and capillarity).
    """
    k = np.asarray(k, dtype=np.float64)
    deep, d, tanh_kd, sech2_kd = _depth_terms(k, depth)
    tension = np.asarray(surface_tension, dtype=np.float64) / density  # σ/ρ [m³ s⁻²]
    omega = dispersion_relation(k, depth, g, surface_tension, density)
    numerator = (g + 3 * tension * k**2) * tanh_kd + (g * k + tension * k**3) * d * sech2_kd  # d(ω²)/dk
    with np.errstate(divide="ignore", invalid="ignore"):
        c_g = numerator / (2 * omega)  # dω/dk = (dω²/dk)/(2ω)
    long_wave_limit = np.where(deep, np.inf, np.sqrt(g * d))
    return np.where(omega == 0, long_wave_limit, c_g)


def wavenumber_from_frequency(omega: ArrayLike, depth: ArrayLike = np.inf, g: float = GRAVITY) -> NDArray[np.float64]:
    """Wavenumber of a gravity wave of angular frequency ω, the inverse of :func:`dispersion_relation` [rad m⁻¹].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω ≥ 0 [rad s⁻¹].
    depth : array_like, optional
        Water depth d [m]; ``np.inf`` gives k = ω²/g.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        k with ω² = g k tanh(k d) [rad m⁻¹] (no surface tension), to rounding error.

    Notes
    -----
    Fenton & McKee's explicit approximation kd ≈ y coth(y^{3/4})^{2/3},
    y = ω² d/g, is refined by Newton steps on x tanh x = y, which converge
    monotonically and quadratically from it.

    References
    ----------
    .. [1] J. D. Fenton and W. D. McKee, "On calculating the lengths of water
       waves", Coastal Engineering 14(6), 499–513, 1990,
       doi:10.1016/0378-3839(90)90032-R.
    """
    omega = np.asarray(omega, dtype=np.float64)
    depth = np.asarray(depth, dtype=np.float64)
    deep = np.isinf(depth)
    d = np.where(deep, 1.0, depth)
    k_deep = np.square(omega) / g  # Eq. 14 of Tessendorf (2001) inverted
    y = k_deep * d
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        x = np.where(y > 0, y / np.tanh(y**0.75) ** (2 / 3), 0.0)  # explicit kd of [1]
        for _ in range(6):  # relative error ≲ 1e-2 → 1e-4 → 1e-8 → 1e-16
            tanh_x = np.tanh(x)
            e = np.exp(-2 * x)
            slope = tanh_x + x * 4 * e / np.square(1 + e)  # d(x tanh x)/dx
            x = np.where(slope > 0, x - (x * tanh_x - y) / slope, x)
    return np.where(deep, k_deep, x / d)
