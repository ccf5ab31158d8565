"""The unified directional wave spectrum of Elfouhaily, Chapron, Katsaros & Vandemark (1997).

One spectrum for every wavelength that matters to light on the sea: from the
peak of the wind sea (JONSWAP-like, with the fetch entering through the
inverse wave age Ω_c) down to the gravity–capillary waves around
λ_m = 2π/k_m ≈ 1.7 cm, whose slopes dominate the sea's mean-square slope.
The paper built it to agree with the sun-glitter slopes of Cox & Munk
(1954) and with short-wave measurements (Jähne & Riemer 1990, Hara et al.
1994), as its abstract states [1].

Conventions as in :mod:`oceanrender.waves.wave_spectra`: wavenumbers in
rad m⁻¹, lengths in m, wind speed U₁₀ in m s⁻¹ 10 m above the sea, angles in
radians counter-clockwise from +x; the wind direction is the direction the
wind blows toward.

Quantities:

* the curvature spectrum B(k) = k³ S(k) = B_l + B_h [-] (long- and short-wave parts);
* the omnidirectional elevation spectrum S(k) [m³], ∫₀^∞ S dk = m0 = ⟨η²⟩ [m²];
* the spreading Φ(k, φ) = (1 + Δ(k) cos 2φ)/(2π) [rad⁻¹], ∫ Φ dφ = 1 over the
  circle, φ measured from the wind;
* the directional spectrum Ψ(kx, ky) = S(k) Φ(k, φ)/k [m⁴], ∫∫ Ψ dkx dky = m0,
  as published (centrosymmetric) or folded onto the downwind half plane
  (:func:`fold_downwind`), the form the FFT ocean uses;
* the mean-square slope upwind and crosswind between two wavenumbers
  (:func:`mean_square_slope_Elfouhaily1997`).

Each function implements one relation of the paper and is named
``quantity_Elfouhaily1997``; the friction velocity u* that the short waves and the
spreading need has the paper's own relation and Wu's (1982) drag law [3] as
alternatives. Equation numbers refer to [1]; how they were checked and where
published implementations disagree is in :func:`spectrum_Elfouhaily1997`.

References
----------
.. [1] T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified
   directional spectrum for long and short wind-driven waves", J. Geophys.
   Res. 102(C7), 15781–15796, 1997, doi:10.1029/97JC00467.
.. [2] C. Cox and W. Munk, "Measurement of the roughness of the sea surface
   from photographs of the sun's glitter", J. Opt. Soc. Am. 44(11), 838–850,
   1954, doi:10.1364/JOSA.44.000838.
.. [3] J. Wu, "Wind-stress coefficients over sea surface from breeze to
   hurricane", J. Geophys. Res. 87(C12), 9704–9706, 1982,
   doi:10.1029/JC087iC12p09704.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "ELFOUHAILY_FETCH_SCALE",
    "ELFOUHAILY_FULLY_DEVELOPED",
    "ELFOUHAILY_KM",
    "ELFOUHAILY_CM",
    "VON_KARMAN",
    "inverse_wave_age_Elfouhaily1997",
    "peak_wavenumber_Elfouhaily1997",
    "phase_speed_Elfouhaily1997",
    "friction_velocity_Elfouhaily1997",
    "friction_velocity_Wu1982",
    "peak_enhancement_Elfouhaily1997",
    "long_wave_curvature_Elfouhaily1997",
    "short_wave_parameter_Elfouhaily1997",
    "short_wave_curvature_Elfouhaily1997",
    "omnidirectional_spectrum_Elfouhaily1997",
    "spreading_ratio_Elfouhaily1997",
    "spreading_Elfouhaily1997",
    "fold_downwind",
    "spectrum_Elfouhaily1997",
    "MeanSquareSlope",
    "mean_square_slope_Elfouhaily1997",
]

# NOTE: the same value as oceanrender.waves.wave_spectra.GRAVITY (a test checks
# it); it is repeated because wave_spectra imports this module, not the reverse.
_GRAVITY = 9.81

ELFOUHAILY_FETCH_SCALE: float = 2.2e4
"""Dimensionless fetch scale X₀ of the inverse-wave-age law, Eq. 37 of [1] [-]."""

ELFOUHAILY_FULLY_DEVELOPED: float = 0.84
"""Inverse wave age Ω_c = U₁₀/c_p of a fully developed sea, the X → ∞ limit of Eq. 37 of [1] [-]."""

ELFOUHAILY_KM: float = 370.0
"""Wavenumber k_m of the minimum phase speed of gravity–capillary waves, λ_m ≈ 1.7 cm, of [1] [rad m⁻¹]."""

ELFOUHAILY_CM: float = 0.23
"""Minimum phase speed c_m of gravity–capillary waves, reached at k_m, of [1] [m s⁻¹]."""

VON_KARMAN: float = 0.41
"""Von Kármán constant κ of the logarithmic wind profile U(z) = (u*/κ) ln(z/z₀) [-]."""


def inverse_wave_age_Elfouhaily1997(
    wind_speed_10: ArrayLike, fetch: ArrayLike, g: float = _GRAVITY
) -> NDArray[np.float64]:
    """Inverse wave age Ω_c = U₁₀/c_p of a fetch-limited wind sea [-].

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹], > 0.
    fetch : array_like
        Fetch F [m], in (0, inf]; ``np.inf`` is a fully developed sea.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        Ω_c = 0.84 tanh[(X/X₀)^0.4]^−0.75 with X = g F/U₁₀² and X₀ = 2.2 × 10⁴ [-]:
        0.84 for X → ∞ (fully developed), about 1 at X = X₀, 5 at X ≈ 58.

    References
    ----------
    .. [1] T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified
       directional spectrum for long and short wind-driven waves", J. Geophys.
       Res. 102(C7), 15781–15796, 1997, doi:10.1029/97JC00467, Eq. 37.

    Examples
    --------
    >>> float(inverse_wave_age_Elfouhaily1997(10.0, np.inf))
    0.84
    """
    with np.errstate(divide="ignore"):  # U = 0: X = inf, the fully developed limit
        dimensionless_fetch = g * np.asarray(fetch, dtype=np.float64) / np.square(wind_speed_10)  # X = k₀ F
    scaled = (dimensionless_fetch / ELFOUHAILY_FETCH_SCALE) ** 0.4
    return ELFOUHAILY_FULLY_DEVELOPED * np.tanh(scaled) ** -0.75  # Eq. 37 of [1]


def peak_wavenumber_Elfouhaily1997(
    wind_speed_10: ArrayLike, inverse_wave_age: ArrayLike, g: float = _GRAVITY
) -> NDArray[np.float64]:
    """Wavenumber of the spectral peak k_p = k₀ Ω_c², k₀ = g/U₁₀² [rad m⁻¹].

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹].
    inverse_wave_age : array_like
        Ω_c [-] (:func:`inverse_wave_age_Elfouhaily1997`).
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        k_p [rad m⁻¹]; deep-water gravity waves at k_p travel at U₁₀/Ω_c.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, text below Eq. 3.
    """
    with np.errstate(divide="ignore"):  # U = 0: k_p = inf, a calm sea
        k0 = g / np.square(np.asarray(wind_speed_10, dtype=np.float64))  # k₀ of [1]
    return k0 * np.square(inverse_wave_age)  # k_p of [1]


def phase_speed_Elfouhaily1997(k: ArrayLike, g: float = _GRAVITY) -> NDArray[np.float64]:
    """Phase speed of deep-water gravity–capillary waves c(k) = √(g/k (1 + (k/k_m)²)) [m s⁻¹].

    Parameters
    ----------
    k : array_like
        Wavenumber [rad m⁻¹], ≥ 0.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        c [m s⁻¹]; inf at k = 0, minimum √(2 g/k_m) ≈ 0.230 m s⁻¹ = c_m at k = k_m.

    Notes
    -----
    The paper's k_m = 370 rad m⁻¹ stands for √(ρ g/σ_s) (ρ density, σ_s surface
    tension); :func:`oceanrender.waves.wave_spectra.dispersion_relation` with
    σ_s = 0.074 N m⁻¹, ρ = 1025 kg m⁻³ has k_m = 368.6 rad m⁻¹.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eq. 24.
    """
    k = np.asarray(k, dtype=np.float64)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):  # k = 0 → inf; k ≳ 1e154: inf
        return np.sqrt(g / k * (1 + np.square(k / ELFOUHAILY_KM)))  # Eq. 24 of [1]


def friction_velocity_Elfouhaily1997(
    wind_speed_10: ArrayLike, inverse_wave_age: ArrayLike, g: float = _GRAVITY
) -> NDArray[np.float64]:
    """Friction velocity of the wind over a sea of a given wave age u* [m s⁻¹].

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹].
    inverse_wave_age : array_like
        Ω = U₁₀/c_p [-] (c_p the phase speed at the peak).
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        u* = κ U₁₀ / ln(10 m/z₀) with the roughness length
        z₀ = 3.7 × 10⁻⁵ (U₁₀²/g) Ω^0.9 of Donelan et al. [2] and κ = 0.41 [m s⁻¹];
        0.096, 0.40 and 0.65 m s⁻¹ at U₁₀ = 3, 10 and 15 m s⁻¹ for a fully developed sea.

    Notes
    -----
    This is the relation [1] uses (its Eqs. 60 and 66): the logarithmic wind
    profile of a neutral atmosphere with a roughness that grows as the sea gets
    younger. :func:`friction_velocity_Wu1982` (a drag coefficient that depends
    on U₁₀ only) gives 2–4 % less at 3–15 m s⁻¹ for a fully developed sea and
    2–9 % less at a fetch of 50 km. κ = 0.41 is the value the
    implementations of Eq. 60 that were read (see :func:`spectrum_Elfouhaily1997`)
    use; 0.40 would lower u* by 2.4 %.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eqs. 60 and 66.
    .. [2] M. A. Donelan, F. W. Dobson, S. D. Smith and R. J. Anderson, "On the
       dependence of sea surface roughness on wave development", J. Phys.
       Oceanogr. 23(9), 2143–2149, 1993,
       doi:10.1175/1520-0485(1993)023<2143:OTDOSS>2.0.CO;2.
    """
    U = np.asarray(wind_speed_10, dtype=np.float64)
    z0 = 3.7e-5 * np.square(U) / g * np.asarray(inverse_wave_age, dtype=np.float64) ** 0.9  # Eq. 66 of [1], [2]
    with np.errstate(divide="ignore"):  # U = 0: z₀ = 0, ln = inf, u* = 0
        return VON_KARMAN * U / np.log(10.0 / z0)  # Eq. 60 of [1] at z = 10 m


def friction_velocity_Wu1982(wind_speed_10: ArrayLike) -> NDArray[np.float64]:
    """Friction velocity from Wu's drag coefficient u* = √C_D U₁₀ [m s⁻¹].

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹].

    Returns
    -------
    ndarray
        u* with C_D = (0.8 + 0.065 U₁₀) × 10⁻³ [m s⁻¹] (U₁₀ in m s⁻¹); 0.381 m s⁻¹ at 10 m s⁻¹.

    Notes
    -----
    An alternative to the paper's :func:`friction_velocity_Elfouhaily1997`,
    independent of the sea state; pass it as ``friction_velocity`` to the
    spectrum functions of this module.

    References
    ----------
    .. [1] J. Wu, "Wind-stress coefficients over sea surface from breeze to
       hurricane", J. Geophys. Res. 87(C12), 9704–9706, 1982,
       doi:10.1029/JC087iC12p09704.
    """
    U = np.asarray(wind_speed_10, dtype=np.float64)
    drag = (0.8 + 0.065 * U) * 1e-3  # C_D of [1]
    return np.sqrt(drag) * U  # u*² = C_D U₁₀²


def peak_enhancement_Elfouhaily1997(inverse_wave_age: ArrayLike) -> NDArray[np.float64]:
    """JONSWAP peak enhancement γ of a sea of inverse wave age Ω_c [-].

    Parameters
    ----------
    inverse_wave_age : array_like
        Ω_c [-], in [0.84, 5) where [1] defines γ.

    Returns
    -------
    ndarray
        γ = 1.7 for Ω_c < 1 and 1.7 + 6 log₁₀ Ω_c for Ω_c ≥ 1 [-] (continuous at 1;
        3.07 at Ω_c = 1.69, 5.89 at Ω_c = 5).

    Notes
    -----
    Above Ω_c = 5 (fetches below about 60 U₁₀²/g, i.e. 60 m at 10 m s⁻¹) the
    second branch is extrapolated.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, text below Eq. 3.
    """
    omega_c = np.asarray(inverse_wave_age, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):  # the first branch is taken there
        return np.where(omega_c < 1, 1.7, 1.7 + 6 * np.log10(omega_c))  # γ(Ω_c) of [1]


def _peak_shape(k: NDArray[np.float64], k_p: NDArray[np.float64], omega_c: NDArray[np.float64]):
    """(√(k/k_p), L_PM J_p): the Pierson–Moskowitz cut-off times the JONSWAP peak enhancement [-]."""
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):  # k → 0: (k_p/k)² = inf, L_PM = 0
        root = np.sqrt(k / k_p)
        cut_off = np.exp(-1.25 * np.square(k_p / k))  # L_PM, Eq. 2 of [1]
        sigma = 0.08 * (1 + 4 * omega_c**-3.0)  # σ, Eq. 3 of [1]
        big_gamma = np.exp(-np.square(root - 1) / (2 * np.square(sigma)))  # Γ, Eq. 3 of [1]
        enhancement = peak_enhancement_Elfouhaily1997(omega_c) ** big_gamma  # J_p = γ^Γ, Eq. 3 of [1]
    return root, cut_off * enhancement


def long_wave_curvature_Elfouhaily1997(
    k: ArrayLike, wind_speed_10: ArrayLike, inverse_wave_age: ArrayLike, g: float = _GRAVITY
) -> NDArray[np.float64]:
    """Long-wave (gravity-wave) curvature spectrum B_l(k) = ½ α_p (c_p/c) F_p [-].

    Parameters
    ----------
    k : array_like
        Wavenumber [rad m⁻¹], ≥ 0.
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹], > 0.
    inverse_wave_age : array_like
        Ω_c [-] (:func:`inverse_wave_age_Elfouhaily1997`).
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        B_l [-], with

        * α_p = 6 × 10⁻³ √Ω (Eq. 34), Ω = U₁₀/c_p and c_p = c(k_p) (Eq. 24);
        * F_p = L_PM J_p exp(−(Ω/√10)(√(k/k_p) − 1)) (Eq. 32);
        * L_PM = exp(−(5/4)(k_p/k)²) (Eq. 2), J_p = γ^Γ,
          Γ = exp(−(√(k/k_p) − 1)²/(2σ²)), σ = 0.08 (1 + 4 Ω_c⁻³) (Eq. 3),
          γ from :func:`peak_enhancement_Elfouhaily1997`.

        0 at k = 0.

    Notes
    -----
    At the peak, B_l(k_p) = ½ α_p γ e^{−5/4}. Ω = U₁₀/c(k_p) is the paper's
    inverse wave age of the peak; it differs from Ω_c only through the
    capillary term of c, by (k_p/k_m)²/2 < 10⁻⁶ relative for any sea with
    k_p < 0.5 rad m⁻¹.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eqs. 2, 3, 24, 31, 32 and 34.
    """
    k = np.asarray(k, dtype=np.float64)
    omega_c = np.asarray(inverse_wave_age, dtype=np.float64)
    U = np.asarray(wind_speed_10, dtype=np.float64)
    k_p = peak_wavenumber_Elfouhaily1997(U, omega_c, g)
    c_p = phase_speed_Elfouhaily1997(k_p, g)
    omega = U / c_p  # Ω, text after Eq. 31 of [1]
    alpha_p = 6e-3 * np.sqrt(omega)  # Eq. 34 of [1]
    root, shape = _peak_shape(k, k_p, omega_c)
    with np.errstate(over="ignore", invalid="ignore"):  # shape = 0 where the exponential would be large
        side = shape * np.exp(-omega / np.sqrt(10) * (root - 1))  # F_p, Eq. 32 of [1]
        curvature = 0.5 * alpha_p * (c_p / phase_speed_Elfouhaily1997(k, g)) * side  # Eq. 31 of [1]
    return np.where(shape == 0, 0.0, curvature)


def short_wave_parameter_Elfouhaily1997(friction_velocity: ArrayLike) -> NDArray[np.float64]:
    """Generalised Phillips–Kitaigorodskii parameter of the short waves α_m [-].

    Parameters
    ----------
    friction_velocity : array_like
        Friction velocity u* [m s⁻¹], ≥ 0.

    Returns
    -------
    ndarray
        α_m = 10⁻² (1 + ln(u*/c_m)) for u* ≤ c_m and 10⁻² (1 + 3 ln(u*/c_m)) above,
        c_m = 0.23 m s⁻¹ (continuous at c_m), and 0 where that is negative [-].

    Notes
    -----
    Deviation from [1]: Eq. 44 becomes negative for u* < c_m/e ≈ 0.085 m s⁻¹
    (U₁₀ below about 2.7 m s⁻¹), which would make S(k) negative at short
    waves; α_m is held at 0 there, so the lightest winds have no short-wave
    part (their mean-square slope comes from B_l only).

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eq. 44.
    """
    u_star = np.asarray(friction_velocity, dtype=np.float64)
    with np.errstate(divide="ignore"):  # u* = 0: ln = −inf, clipped to 0 below
        log_ratio = np.log(u_star / ELFOUHAILY_CM)
    alpha_m = 1e-2 * (1 + np.where(u_star <= ELFOUHAILY_CM, 1.0, 3.0) * log_ratio)  # Eq. 44 of [1]
    return np.maximum(alpha_m, 0.0)


def short_wave_curvature_Elfouhaily1997(
    k: ArrayLike,
    wind_speed_10: ArrayLike,
    inverse_wave_age: ArrayLike,
    friction_velocity: ArrayLike,
    g: float = _GRAVITY,
) -> NDArray[np.float64]:
    """Short-wave (gravity–capillary) curvature spectrum B_h(k) = ½ α_m (c_m/c) F_m [-].

    Parameters
    ----------
    k : array_like
        Wavenumber [rad m⁻¹], ≥ 0.
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹], > 0.
    inverse_wave_age : array_like
        Ω_c [-].
    friction_velocity : array_like
        Friction velocity u* [m s⁻¹] (:func:`friction_velocity_Elfouhaily1997`).
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        B_h [-] with α_m of :func:`short_wave_parameter_Elfouhaily1997` (Eq. 44),
        c from Eq. 24 and F_m = L_PM J_p exp(−¼ (k/k_m − 1)²) (Eq. 41 times
        L_PM J_p, see Notes); ½ α_m (c_m/c(k_m)) L_PM J_p at k = k_m; 0 at k = 0.

    Notes
    -----
    Deviation from the printed Eq. 41 of [1], whose F_m is exp(−¼ (k/k_m − 1)²)
    alone: without a long-wave cut-off B_h/k³ grows as k^{−5/2} towards k = 0
    and the elevation variance diverges. McDaniel [2] and Bruneton et al. [3]
    multiply by L_PM; here by L_PM J_p, the same factor as in F_p, so that the
    two parts share one low-wavenumber shape.
    This changes the mean-square slope by less than 0.001 at 3–15 m s⁻¹.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eqs. 40, 41 and 44.
    .. [2] S. T. McDaniel, "Small-slope predictions of microwave backscatter from
       the sea surface", Waves in Random Media 11(3), 343–360, 2001,
       doi:10.1088/0959-7174/11/3/309.
    .. [3] E. Bruneton, F. Neyret and N. Holzschuch, "Real-time realistic ocean
       lighting using seamless transitions from geometry to BRDF", Computer
       Graphics Forum 29(2), 487–496, 2010, doi:10.1111/j.1467-8659.2009.01618.x.
    """
    k = np.asarray(k, dtype=np.float64)
    omega_c = np.asarray(inverse_wave_age, dtype=np.float64)
    k_p = peak_wavenumber_Elfouhaily1997(wind_speed_10, omega_c, g)
    alpha_m = short_wave_parameter_Elfouhaily1997(friction_velocity)  # Eq. 44 of [1]
    _, shape = _peak_shape(k, k_p, omega_c)
    with np.errstate(over="ignore", invalid="ignore"):  # k ≳ 1e154: (k/k_m)² = inf, F_m = 0
        side = shape * np.exp(-0.25 * np.square(k / ELFOUHAILY_KM - 1))  # F_m, Eq. 41 of [1] × L_PM J_p
        curvature = 0.5 * alpha_m * (ELFOUHAILY_CM / phase_speed_Elfouhaily1997(k, g)) * side  # Eq. 40 of [1]
    return np.where(side == 0, 0.0, curvature)


class _SeaState(NamedTuple):
    """Ω_c, u* and the wind speed of one sea, broadcast together."""

    wind_speed_10: NDArray[np.float64]
    inverse_wave_age: NDArray[np.float64]
    friction_velocity: NDArray[np.float64]


def _sea_state(wind_speed_10, fetch, friction_velocity, g) -> _SeaState:
    """Ω_c from the fetch and u* from the paper's relation unless given."""
    U = np.asarray(wind_speed_10, dtype=np.float64)
    omega_c = inverse_wave_age_Elfouhaily1997(U, fetch, g)
    if friction_velocity is None:
        with np.errstate(divide="ignore", invalid="ignore"):  # U = 0: masked by the callers
            omega = U / phase_speed_Elfouhaily1997(peak_wavenumber_Elfouhaily1997(U, omega_c, g), g)
        friction_velocity = friction_velocity_Elfouhaily1997(U, omega, g)
    return _SeaState(U, omega_c, np.asarray(friction_velocity, dtype=np.float64))


def omnidirectional_spectrum_Elfouhaily1997(
    k: ArrayLike,
    wind_speed_10: ArrayLike,
    fetch: ArrayLike = np.inf,
    friction_velocity: ArrayLike | None = None,
    g: float = _GRAVITY,
) -> NDArray[np.float64]:
    """Omnidirectional elevation spectrum S(k) = k⁻³ (B_l + B_h) [m³].

    Parameters
    ----------
    k : array_like
        Wavenumber [rad m⁻¹], ≥ 0.
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹], > 0.
    fetch : array_like, optional
        Fetch F [m], in (0, inf]; inf (default) is a fully developed sea.
    friction_velocity : array_like or None, optional
        u* [m s⁻¹]; ``None`` uses :func:`friction_velocity_Elfouhaily1997`.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        S [m³], broadcast over the arguments; ∫₀^∞ S dk = m0 [m²]. 0 at k = 0.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eq. 30.
    """
    k = np.asarray(k, dtype=np.float64)
    sea = _sea_state(wind_speed_10, fetch, friction_velocity, g)
    curvature = long_wave_curvature_Elfouhaily1997(k, sea.wind_speed_10, sea.inverse_wave_age, g) + (
        short_wave_curvature_Elfouhaily1997(k, sea.wind_speed_10, sea.inverse_wave_age, sea.friction_velocity, g)
    )
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):  # B = 0 where k⁻³ would overflow
        spectrum = curvature / k**3  # Eq. 30 of [1]
    return np.where(curvature == 0, 0.0, spectrum)


def spreading_ratio_Elfouhaily1997(
    k: ArrayLike,
    wind_speed_10: ArrayLike,
    inverse_wave_age: ArrayLike,
    friction_velocity: ArrayLike,
    g: float = _GRAVITY,
) -> NDArray[np.float64]:
    """Upwind–crosswind ratio of the spreading Δ(k) [-].

    Parameters
    ----------
    k : array_like
        Wavenumber [rad m⁻¹], ≥ 0.
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹].
    inverse_wave_age : array_like
        Ω_c [-].
    friction_velocity : array_like
        u* [m s⁻¹].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        Δ = tanh(a₀ + a_p (c/c_p)^2.5 + a_m (c_m/c)^2.5) [-], a₀ = ln 2/4,
        a_p = 4, a_m = 0.13 u*/c_m (Eq. 59), c from Eq. 24, c_p = c(k_p);
        in [tanh(ln 2/4), 1] = [3 − 2√2, 1] ≈ [0.172, 1]: close to 1 at the peak
        and below it, smallest between the peak and k_m.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eqs. 57 and 59.
    """
    c = phase_speed_Elfouhaily1997(k, g)
    c_p = phase_speed_Elfouhaily1997(peak_wavenumber_Elfouhaily1997(wind_speed_10, inverse_wave_age, g), g)
    a_0, a_p = np.log(2) / 4, 4.0  # Eq. 59 of [1]
    a_m = 0.13 * np.asarray(friction_velocity, dtype=np.float64) / ELFOUHAILY_CM  # Eq. 59 of [1]
    with np.errstate(over="ignore", invalid="ignore"):  # k → 0: (c/c_p)^2.5 = inf, tanh = 1
        return np.tanh(a_0 + a_p * (c / c_p) ** 2.5 + a_m * (ELFOUHAILY_CM / c) ** 2.5)  # Eq. 57 of [1]


def spreading_Elfouhaily1997(
    phi: ArrayLike,
    k: ArrayLike,
    wind_speed_10: ArrayLike,
    fetch: ArrayLike = np.inf,
    friction_velocity: ArrayLike | None = None,
    g: float = _GRAVITY,
) -> NDArray[np.float64]:
    """Directional spreading Φ(k, φ) = (1 + Δ(k) cos 2φ)/(2π) [rad⁻¹].

    Parameters
    ----------
    phi : array_like
        Direction of the wave vector relative to the wind [rad].
    k : array_like
        Wavenumber [rad m⁻¹].
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹].
    fetch : array_like, optional
        Fetch F [m]; inf is fully developed.
    friction_velocity : array_like or None, optional
        u* [m s⁻¹]; ``None`` uses :func:`friction_velocity_Elfouhaily1997`.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        Φ ≥ 0 [rad⁻¹] with ∫_{−π}^{π} Φ dφ = 1, Δ from
        :func:`spreading_ratio_Elfouhaily1997`.

    Notes
    -----
    Φ(φ + π) = Φ(φ): the spreading is centrosymmetric, as waves travelling with
    and against the wind carry the same variance. Only the second-order
    statistics of the sea are modelled, which cannot tell the two apart; see
    :func:`fold_downwind`.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467, Eq. 49.
    """
    sea = _sea_state(wind_speed_10, fetch, friction_velocity, g)
    delta = spreading_ratio_Elfouhaily1997(k, sea.wind_speed_10, sea.inverse_wave_age, sea.friction_velocity, g)
    return (1 + delta * np.cos(2 * np.asarray(phi, dtype=np.float64))) / (2 * np.pi)  # Eq. 49 of [1]


def fold_downwind(
    psi: ArrayLike, psi_reversed: ArrayLike, kx: ArrayLike, ky: ArrayLike, wind_direction: ArrayLike
) -> NDArray[np.float64]:
    """A directional spectrum moved onto the half plane of waves travelling downwind [m⁴].

    Parameters
    ----------
    psi : array_like
        Ψ(k) at the wave vectors (kx, ky) [m⁴].
    psi_reversed : array_like
        Ψ(−k) at the same points [m⁴].
    kx, ky : array_like
        Wave-vector components [rad m⁻¹].
    wind_direction : array_like
        Direction the wind blows toward, counter-clockwise from +x [rad].

    Returns
    -------
    ndarray
        Ψ_f(k) = Ψ(k) + Ψ(−k) where k·ŵ > 0, 0 where k·ŵ < 0 and
        (Ψ(k) + Ψ(−k))/2 on the line k·ŵ = 0 [m⁴].

    Notes
    -----
    A Gaussian sea η(x, t) = Σ a_k cos(k·x − ω t + ε_k) has covariances of
    heights, slopes and curvatures that depend on Ψ(k) + Ψ(−k) only: the
    height covariance is ∫ Ψ(k) cos(k·r) dk, the slope covariance
    ∫ k_i k_j Ψ(k) dk, and both integrands are unchanged by k → −k except
    through Ψ. Folding keeps Ψ(k) + Ψ(−k), hence m0, ⟨s_x²⟩, ⟨s_y²⟩,
    ⟨s_x s_y⟩ and the whole glitter pattern of [1], and turns a
    centrosymmetric spectrum into one whose waves all travel with the wind
    (the FFT ocean moves the variance Ψ(k) along +k), as Bruneton et al. [2]
    do with the same spectrum. It changes what only the phases see: no wave
    now travels upwind.

    References
    ----------
    .. [1] C. Cox and W. Munk, "Measurement of the roughness of the sea surface
       from photographs of the sun's glitter", J. Opt. Soc. Am. 44(11),
       838–850, 1954, doi:10.1364/JOSA.44.000838.
    .. [2] E. Bruneton, F. Neyret and N. Holzschuch, Computer Graphics Forum
       29(2), 487–496, 2010, doi:10.1111/j.1467-8659.2009.01618.x.
    """
    along = np.asarray(kx, dtype=np.float64) * np.cos(wind_direction) + np.asarray(ky, dtype=np.float64) * np.sin(
        wind_direction
    )  # k·ŵ
    total = np.asarray(psi, dtype=np.float64) + np.asarray(psi_reversed, dtype=np.float64)
    return np.where(along > 0, total, np.where(along < 0, 0.0, 0.5 * total))


def spectrum_Elfouhaily1997(
    kx: ArrayLike,
    ky: ArrayLike,
    wind_speed: ArrayLike,
    wind_direction: ArrayLike,
    fetch: ArrayLike = 100e3,
    small_wave_length: ArrayLike = 0.0,
    folded: bool = True,
    g: float = _GRAVITY,
) -> NDArray[np.float64]:
    """Elfouhaily et al. (1997) directional wavenumber spectrum Ψ(kx, ky) [m⁴].

    Parameters
    ----------
    kx, ky : array_like
        Wavenumber components along +x (east) and +y (north) [rad m⁻¹].
    wind_speed : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹], ≥ 0 (0: a calm sea, Ψ = 0).
    wind_direction : array_like
        Direction the wind blows toward, counter-clockwise from +x [rad].
    fetch : array_like, optional
        Fetch F [m], in (0, inf]; inf is fully developed. The default is the
        default fetch of :class:`~oceanrender.waves.wave_spectra.DirectionalSpectrum`.
    small_wave_length : array_like, optional
        Length ℓ below which waves are suppressed by exp(−k² ℓ²) [m] (Tessendorf
        2001, eq. 24); 0 keeps the spectrum as published.
    folded : bool, optional
        True (default): all variance on the downwind half plane
        (:func:`fold_downwind`), the form the FFT ocean uses. False: the
        centrosymmetric spectrum as published.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        Ψ = S(k) Φ(k, φ)/k [m⁴], S of :func:`omnidirectional_spectrum_Elfouhaily1997`
        (u* of :func:`friction_velocity_Elfouhaily1997`), Φ of
        :func:`spreading_Elfouhaily1997`, φ the angle between k and the wind;
        ∫∫ Ψ dkx dky = ∫ S dk = m0 either way. Ψ(0, 0) = 0; finite for finite input.

    Notes
    -----
    The 1/k is the polar Jacobian, dkx dky = k dk dφ (Eq. 67 of [1]).

    *Sources checked.* The paper's full text was not at hand; its equation
    numbers and constants were checked against the abstract and against
    independent implementations that cite them: RTTOV's sun-glint model
    (``rttov_refsun``, with equation numbers), the OceanSAR simulator
    (``oceansar/spec/elfouhaily.py``, ``oceansar/spread/elfouhaily.py``),
    the code of Bruneton et al. [3] and several MATLAB/Python versions. Where
    they disagree, this module follows:

    * α_p = 6 × 10⁻³ √Ω (Eq. 34; RTTOV, OceanSAR, Bruneton), not 6 × 10⁻³ Ω_c^0.55
      found in some codes;
    * γ = 1.7 + 6 log₁₀ Ω_c (RTTOV, OceanSAR), not the natural logarithm of one code;
    * a₀ = ln 2/4 (Eq. 59), not ln 2/2;
    * k_m = 370 rad m⁻¹ and c_m = 0.23 m s⁻¹ as printed, not √(ρ g/σ_s) or
      2π/1.7 cm;
    * u* from the paper's Eqs. 60 and 66 (RTTOV's comments, Bruneton), not a
      fixed drag coefficient (1.44 × 10⁻³, or U₁₀/25 as RTTOV runs it) or the
      (0.8 + 0.065 U₁₀) × 10⁻³ law OceanSAR takes from McDaniel (2001); that
      law is :func:`friction_velocity_Wu1982`;
    * F_m with the factor L_PM J_p (see :func:`short_wave_curvature_Elfouhaily1997`);
    * the spreading normalised over the full circle, ∫ Φ dφ = 1 (OceanSAR's
      log records a normalisation fixed twice).

    References
    ----------
    .. [1] T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified
       directional spectrum for long and short wind-driven waves", J. Geophys.
       Res. 102(C7), 15781–15796, 1997, doi:10.1029/97JC00467.
    .. [2] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       eq. 24.
    .. [3] E. Bruneton, F. Neyret and N. Holzschuch, Computer Graphics Forum
       29(2), 487–496, 2010, doi:10.1111/j.1467-8659.2009.01618.x.

    Examples
    --------
    >>> psi = spectrum_Elfouhaily1997(0.2, 0.0, 10.0, 0.0)
    >>> bool(psi > 0), float(spectrum_Elfouhaily1997(-0.2, 0.0, 10.0, 0.0))
    (True, 0.0)
    """
    kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
    U = np.asarray(wind_speed, dtype=np.float64)
    k = np.hypot(kx, ky)
    # NOTE: k = 0 and U = 0 are replaced by 1 and masked at the end, so Ψ(0) = 0 and a
    # calm sea is 0 without warnings, while NaN inputs still propagate.
    k_safe = np.where(k == 0, 1.0, k)
    U_safe = np.where(U == 0, 1.0, U)
    ux, uy = kx / k_safe, ky / k_safe  # k̂ (dividing first: no underflow of k² for tiny k)
    cos_phi = ux * np.cos(wind_direction) + uy * np.sin(wind_direction)  # k̂·ŵ
    sin_phi = uy * np.cos(wind_direction) - ux * np.sin(wind_direction)  # k̂ × ŵ
    # NOTE: cos 2φ from squares is exactly even under k → −k, so Ψ(−k) = Ψ(k) to the bit.
    cos_2phi = np.clip(np.square(cos_phi) - np.square(sin_phi), -1.0, 1.0)
    sea = _sea_state(U_safe, fetch, None, g)
    omni = omnidirectional_spectrum_Elfouhaily1997(k_safe, U_safe, fetch, sea.friction_velocity, g)
    delta = spreading_ratio_Elfouhaily1997(k_safe, U_safe, sea.inverse_wave_age, sea.friction_velocity, g)
    spreading = (1 + delta * cos_2phi) / (2 * np.pi)  # Eq. 49 of [1]
    suppression = np.exp(-np.square(k_safe * small_wave_length))  # Eq. 24 of [2]
    psi = omni * spreading / k_safe * suppression  # Eq. 67 of [1]
    if folded:
        psi = fold_downwind(psi, psi, kx, ky, wind_direction)  # Ψ(−k) = Ψ(k), see the NOTE above
    return np.where((k == 0) | (U == 0), 0.0, psi)


class MeanSquareSlope(NamedTuple):
    """Mean-square slopes of the sea surface along and across the wind [-]."""

    upwind: NDArray[np.float64]
    """⟨s_u²⟩, the slope variance along the wind direction [-]."""
    crosswind: NDArray[np.float64]
    """⟨s_c²⟩, the slope variance across the wind [-]."""

    @property
    def total(self) -> NDArray[np.float64]:
        """⟨s_u²⟩ + ⟨s_c²⟩ = ⟨|∇η|²⟩ [-]."""
        return self.upwind + self.crosswind


def mean_square_slope_Elfouhaily1997(
    wind_speed_10: ArrayLike,
    fetch: ArrayLike,
    k_min: float,
    k_max: float,
    friction_velocity: ArrayLike | None = None,
    samples: int = 4097,
    g: float = _GRAVITY,
) -> MeanSquareSlope:
    """Upwind and crosswind mean-square slope of the waves with k_min ≤ k ≤ k_max [-].

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed U₁₀ [m s⁻¹], > 0.
    fetch : array_like
        Fetch F [m], in (0, inf].
    k_min, k_max : float
        Wavenumber range [rad m⁻¹], 0 < k_min < k_max; e.g. 2π/(2560 m) and
        2π/(1 mm).
    friction_velocity : array_like or None, optional
        u* [m s⁻¹]; ``None`` uses :func:`friction_velocity_Elfouhaily1997`.
    samples : int, optional
        Nodes of the trapezoidal rule in ln k [-]. When the range holds the
        whole spectrum (e.g. 2π/2560 m to 2π/1 mm) the integrand vanishes
        smoothly at both ends and the rule converges to round-off (257 nodes
        are within 1e-12 of 2¹⁸); a range that cuts the spectrum converges as
        the square of the spacing, about 1e-6 relative with the default.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    MeanSquareSlope
        ``upwind`` = ∫ B (1 + Δ/2)/2 d(ln k), ``crosswind`` = ∫ B (1 − Δ/2)/2 d(ln k)
        and their sum ``total`` = ∫ B d(ln k) [-], each of the broadcast shape of
        the wind speed, fetch and u*.

    Notes
    -----
    ⟨s_u²⟩ = ∫∫ (k cos φ)² Ψ k dk dφ = ∫ k² S(k) ∫ cos²φ Φ dφ dk, and
    ∫ cos²φ (1 + Δ cos 2φ) dφ/(2π) = (1 + Δ/2)/2; with k² S dk = B d(ln k).
    Folding (:func:`fold_downwind`) leaves all three unchanged.

    References
    ----------
    .. [1] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781–15796, 1997,
       doi:10.1029/97JC00467.
    .. [2] C. Cox and W. Munk, J. Opt. Soc. Am. 44(11), 838–850, 1954,
       doi:10.1364/JOSA.44.000838.
    """
    ln_k = np.linspace(np.log(k_min), np.log(k_max), samples)
    k = np.exp(ln_k)
    sea = _sea_state(wind_speed_10, fetch, friction_velocity, g)
    U, omega_c, u_star = (np.asarray(value)[..., None] for value in np.broadcast_arrays(*sea))
    curvature = long_wave_curvature_Elfouhaily1997(k, U, omega_c, g) + short_wave_curvature_Elfouhaily1997(
        k, U, omega_c, u_star, g
    )
    half_delta = spreading_ratio_Elfouhaily1997(k, U, omega_c, u_star, g) / 2
    upwind = np.trapezoid(curvature * (1 + half_delta) / 2, ln_k, axis=-1)  # ∫ cos²φ Φ dφ = (1 + Δ/2)/2
    crosswind = np.trapezoid(curvature * (1 - half_delta) / 2, ln_k, axis=-1)  # ∫ sin²φ Φ dφ = (1 − Δ/2)/2
    return MeanSquareSlope(upwind, crosswind)
