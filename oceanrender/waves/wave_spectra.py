"""Wave spectra, directional wave spectra and the dispersion relation of surface waves.

Conventions: wavenumbers in rad m⁻¹, angular frequencies in rad s⁻¹, lengths in
m, wind speed in m s⁻¹. The wind direction is an angle in radians measured
counter-clockwise from +x (east); converting from degrees is the caller's job.

A *directional wavenumber spectrum* Ψ(kx, ky) [m⁴] here is the variance
density of the surface elevation over the wavenumber plane, so that

    ∫∫ Ψ(kx, ky) dkx dky = m0 = ⟨η²⟩ [m²],

and the significant wave height is Hs = 4 √m0.

Two kinds of published spectra are implemented:

* *frequency spectra* S(ω) [m² s] with ∫ S dω = m0 (Pierson & Moskowitz 1964,
  JONSWAP 1973, TMA 1985), which :class:`DirectionalSpectrum` combines with a
  directional spreading D(θ; ω) of :mod:`oceanrender.waves.spreading` and
  the dispersion relation into Ψ;
* spectra defined directly as Ψ(kx, ky): Tessendorf's (2001) Phillips
  spectrum and the unified long- and short-wave spectrum of Elfouhaily et al.
  (1997, :mod:`oceanrender.waves.elfouhaily`), which reaches the
  gravity–capillary waves that set the sea's mean-square slope.

:class:`DirectionalSpectrum` is the one object the rest of the package uses.
Methods are chosen by name through :data:`SPECTRA` (all names),
:data:`FREQUENCY_SPECTRA`, :func:`frequency_spectrum` and :func:`wave_spectrum`.
"""

from __future__ import annotations

import dataclasses
import inspect
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import k1

from .elfouhaily import (
    ELFOUHAILY_KM,
    inverse_wave_age_Elfouhaily1997,
    omnidirectional_spectrum_Elfouhaily1997,
    peak_wavenumber_Elfouhaily1997,
    phase_speed_Elfouhaily1997,
    spectrum_Elfouhaily1997,
)
from .spreading import SPREADING, directional_spreading, spreading_cos2s

__all__ = [
    "GRAVITY",
    "PHILLIPS_ALPHA",
    "PIERSON_MOSKOWITZ_ALPHA",
    "PIERSON_MOSKOWITZ_BETA",
    "PIERSON_MOSKOWITZ_WIND_RATIO",
    "JONSWAP_GAMMA",
    "JONSWAP_SIGMA_A",
    "JONSWAP_SIGMA_B",
    "SEAWATER_SURFACE_TENSION",
    "SEAWATER_DENSITY",
    "DEFAULT_SPREADING",
    "spectrum_Phillips2001",
    "elevation_variance_Phillips2001",
    "significant_wave_height_Phillips2001",
    "spectrum_PiersonMoskowitz1964",
    "peak_frequency_PiersonMoskowitz1964",
    "elevation_variance_PiersonMoskowitz1964",
    "significant_wave_height_PiersonMoskowitz1964",
    "phillips_constant_JONSWAP1973",
    "peak_frequency_JONSWAP1973",
    "spectrum_JONSWAP1973",
    "depth_function_Kitaigorodskii1975",
    "depth_function_ThompsonVincent1983",
    "spectrum_TMA1985",
    "spectrum_swell",
    "dispersion_relation",
    "group_velocity",
    "wavenumber_from_frequency",
    "FREQUENCY_SPECTRA",
    "WAVENUMBER_SPECTRA",
    "SPECTRA",
    "frequency_spectrum",
    "DirectionalSpectrum",
    "wave_spectrum",
    "make_spectrum",
]

GRAVITY: float = 9.81
"""Standard gravitational acceleration used throughout [m s⁻²]."""

PHILLIPS_ALPHA: float = 8.1e-3
"""Phillips' saturation-range constant α [-] (Phillips 1958; Pierson & Moskowitz 1964)."""


def spectrum_Phillips2001(
    kx: ArrayLike,
    ky: ArrayLike,
    wind_speed: ArrayLike,
    wind_direction: ArrayLike,
    alpha: ArrayLike = PHILLIPS_ALPHA,
    small_wave_length: ArrayLike = 0.0,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """Phillips directional wavenumber spectrum Ψ(kx, ky) of Tessendorf (2001) [m⁴].

    Parameters
    ----------
    kx, ky : array_like
        Wavenumber components along +x (east) and +y (north) [rad m⁻¹].
    wind_speed : array_like
        Wind speed U [m s⁻¹].
    wind_direction : array_like
        Direction the wind blows toward, counter-clockwise from +x [rad].
    alpha : array_like, optional
        Phillips constant α [-].
    small_wave_length : array_like, optional
        Length ℓ below which waves are suppressed by exp(−k² ℓ²) [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        Elevation variance density Ψ [m⁴]; ∫∫ Ψ dkx dky = m0 [m²]. Ψ(0, 0) = 0.

    Notes
    -----
    Ψ(k, θ) = (α/2) k⁻⁴ exp(−1/(k L_w)²) exp(−k² ℓ²) cos²(θ − θ_w)/π with
    L_w = U²/g, where k = |k| and θ is the direction of k.

    Derivation, in the physical units Tessendorf leaves open ("A" in his eq. 23):

    * Phillips' (1958) saturation range S(ω) = α g² ω⁻⁵ [m² s] with deep-water
      dispersion ω² = g k gives the omnidirectional wavenumber spectrum
      F(k) = S(ω) dω/dk = (α/2) k⁻³ [m³].
    * Tessendorf's spreading |k̂·ŵ|² = cos²(θ − θ_w) is normalised over the full
      circle, ∫₀^{2π} cos²θ dθ / π = 1, so Ψ(k, θ) = F(k) cos²(θ − θ_w)/(π k)
      (the 1/k is the polar Jacobian, dkx dky = k dk dθ). The spreading is
      symmetric, k and −k carry the same variance: the sea has waves running
      both with and against the wind, as in Tessendorf's eq. 23.
    * Tessendorf's low-k cut-off exp(−1/(k L_w)²) is exactly the
      Pierson–Moskowitz (1964) factor exp(−β (ω₀/ω)⁴), ω₀ = g/U, written in k
      with β = 1 (Pierson–Moskowitz use β = 0.74 with U at 19.5 m).
    * For ℓ = 0 the variance has the closed form m0 = α U⁴/(4 g²), so
      Hs = 4 √m0 = 2 √α U²/g (see :func:`elevation_variance_Phillips2001`).

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes
       (Course 47), 2001, eqs. 23–24.
    .. [2] O. M. Phillips, "The equilibrium range in the spectrum of
       wind-generated waves", J. Fluid Mech. 4(4), 426–434, 1958,
       doi:10.1017/S0022112058000550.
    .. [3] W. J. Pierson and L. Moskowitz, "A proposed spectral form for fully
       developed wind seas based on the similarity theory of S. A.
       Kitaigorodskii", J. Geophys. Res. 69(24), 5181–5190, 1964,
       doi:10.1029/JZ069i024p05181.

    Examples
    --------
    >>> float(spectrum_Phillips2001(0.1, 0.0, 10.0, 0.0))  # doctest: +ELLIPSIS
    4.9...
    """
    kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
    k = np.hypot(kx, ky)
    # NOTE: k = 0 is replaced by 1 and masked at the end, so Ψ(0) = 0 without
    # warnings while NaN inputs still propagate.
    k_safe = np.where(k == 0, 1.0, k)
    L_w = np.square(wind_speed) / g  # largest wave from a continuous wind, eq. 23 of [1]
    with np.errstate(divide="ignore"):  # U = 0: 1/(k L_w)² = inf, a calm sea
        low_cut = np.exp(-1.0 / np.square(k_safe * L_w))  # Eq. 23 of [1]
    high_cut = np.exp(-np.square(k_safe * small_wave_length))  # Eq. 24 of [1]
    cos_theta = (kx * np.cos(wind_direction) + ky * np.sin(wind_direction)) / k_safe  # k̂·ŵ
    spreading = np.square(cos_theta) / np.pi  # |k̂·ŵ|² of [1], ∫ dθ = 1
    with np.errstate(over="ignore", invalid="ignore"):  # k ≲ 1e-77: k⁻⁴ = inf where low_cut = 0
        psi = alpha / 2 * k_safe**-4 * low_cut * high_cut * spreading  # F(k)/k · D(θ), F of [2]
    return np.where((k == 0) | (low_cut == 0), 0.0, psi)


def elevation_variance_Phillips2001(
    wind_speed: ArrayLike,
    alpha: ArrayLike = PHILLIPS_ALPHA,
    small_wave_length: ArrayLike = 0.0,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """Surface elevation variance m0 = ∫∫ Ψ dkx dky of :func:`spectrum_Phillips2001` [m²].

    Parameters
    ----------
    wind_speed : array_like
        Wind speed U [m s⁻¹].
    alpha : array_like, optional
        Phillips constant α [-].
    small_wave_length : array_like, optional
        Small-wave suppression length ℓ [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        m0 [m²].

    Notes
    -----
    With u = 1/k², m0 = (α/4) ∫₀^∞ exp(−u/L_w² − ℓ²/u) du, and
    ∫₀^∞ exp(−a u − b/u) du = 2 √(b/a) K₁(2 √(ab)) [2], so

        m0 = (α/2) ℓ L_w K₁(2 ℓ/L_w),   L_w = U²/g,

    which tends to α L_w²/4 = α U⁴/(4 g²) as ℓ → 0 (K₁(z) ≈ 1/z).

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes, eq. 23.
    .. [2] I. S. Gradshteyn and I. M. Ryzhik, Table of Integrals, Series, and
       Products, 7th ed., Academic Press, 2007, formula 3.471.9.
    """
    L_w = np.square(np.asarray(wind_speed, dtype=np.float64)) / g
    ell = np.asarray(small_wave_length, dtype=np.float64)
    m0_sharp = alpha * np.square(L_w) / 4  # ℓ = 0 limit
    z = 2 * ell / np.where(L_w == 0, 1.0, L_w)
    with np.errstate(invalid="ignore", divide="ignore"):
        m0_smooth = alpha / 2 * ell * L_w * k1(z)  # Eq. 3.471.9 of [2]
    return np.where((ell == 0) | (L_w == 0), m0_sharp, m0_smooth)


def significant_wave_height_Phillips2001(
    wind_speed: ArrayLike,
    alpha: ArrayLike = PHILLIPS_ALPHA,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """Significant wave height Hs = 4 √m0 = 2 √α U²/g of the Phillips spectrum, ℓ = 0 [m].

    Parameters
    ----------
    wind_speed : array_like
        Wind speed U [m s⁻¹].
    alpha : array_like, optional
        Phillips constant α [-].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        Hs [m].

    Notes
    -----
    Derived in :func:`spectrum_Phillips2001`; for α = 8.1 × 10⁻³ and U = 10 m/s,
    Hs ≈ 1.83 m (the Pierson–Moskowitz law, β = 0.74 and U at 19.5 m, gives 2.13 m).

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes, eq. 23.
    """
    return 2 * np.sqrt(alpha) * np.square(wind_speed) / g  # Hs = 4 √(α U⁴ / (4 g²))


# ---------------------------------------------------------------------------
# Frequency spectra S(ω) [m² s]
# ---------------------------------------------------------------------------

PIERSON_MOSKOWITZ_ALPHA: float = 8.1e-3
"""Pierson–Moskowitz (1964) constant α [-]."""

PIERSON_MOSKOWITZ_BETA: float = 0.74
"""Pierson–Moskowitz (1964) constant β [-] of exp(−β (g/(U₁₉.₅ ω))⁴)."""

PIERSON_MOSKOWITZ_WIND_RATIO: float = 1.026
"""U₁₉.₅ / U₁₀ [-]: neutral log wind profile, drag coefficient 1.3 × 10⁻³ (Stewart 2008, eq. 16.29)."""

JONSWAP_GAMMA: float = 3.3
"""Mean JONSWAP peak-enhancement factor γ [-] (Hasselmann et al. 1973)."""

JONSWAP_SIGMA_A: float = 0.07
"""JONSWAP relative peak width σ_a below the peak, ω ≤ ω_p [-]."""

JONSWAP_SIGMA_B: float = 0.09
"""JONSWAP relative peak width σ_b above the peak, ω > ω_p [-]."""

SEAWATER_SURFACE_TENSION: float = 0.074
"""Surface tension of sea water against air σ [N m⁻¹], to pass as ``surface_tension``."""

SEAWATER_DENSITY: float = 1025.0
"""Density of sea water ρ [kg m⁻³]."""


def _pierson_moskowitz_shape(
    omega: ArrayLike, alpha: ArrayLike, omega_c: ArrayLike, beta: ArrayLike, g: float
) -> NDArray[np.float64]:
    """α g² ω⁻⁵ exp(−β (ω_c/ω)⁴) [m² s]; 0 for ω ≤ 0 and where the exponential underflows."""
    omega = np.asarray(omega, dtype=np.float64)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        x = beta * (omega_c / omega) ** 4
        s = alpha * g**2 * omega**-5.0 * np.exp(-x)
    # NOTE: for x > 700 the true value is below 1e-300 but ω⁻⁵ · 0 may read inf · 0;
    # NaN inputs fail both comparisons and propagate.
    return np.where((omega <= 0) | (x > 700), 0.0, s)


def spectrum_PiersonMoskowitz1964(
    omega: ArrayLike,
    wind_speed_19_5: ArrayLike,
    alpha: ArrayLike = PIERSON_MOSKOWITZ_ALPHA,
    beta: ArrayLike = PIERSON_MOSKOWITZ_BETA,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """Pierson–Moskowitz spectrum of a fully developed sea S(ω) [m² s].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    wind_speed_19_5 : array_like
        Wind speed 19.5 m above the sea U₁₉.₅ [m s⁻¹]; U₁₉.₅ ≈ 1.026 U₁₀
        (:data:`PIERSON_MOSKOWITZ_WIND_RATIO`).
    alpha : array_like, optional
        Constant α [-], 8.1 × 10⁻³ in [1].
    beta : array_like, optional
        Constant β [-], 0.74 in [1].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        S = α g² ω⁻⁵ exp(−β (ω₀/ω)⁴), ω₀ = g/U₁₉.₅ [m² s]; 0 for ω ≤ 0.

    Notes
    -----
    Closed forms (with u = ω⁻⁴, du = −4 ω⁻⁵ dω):

    * m0 = ∫₀^∞ S dω = α g²/(4 β ω₀⁴) = α U⁴/(4 β g²) = 2.736 × 10⁻³ U⁴/g²
      (:func:`elevation_variance_PiersonMoskowitz1964`);
    * Hs = 4 √m0 = 2 √(α/β) U²/g = 0.20925 U²/g, the "0.21 U²/g" of [2]
      (:func:`significant_wave_height_PiersonMoskowitz1964`);
    * dS/dω = 0 at ω_p = (4β/5)^{1/4} ω₀ = 0.87715 g/U
      (:func:`peak_frequency_PiersonMoskowitz1964`).

    References
    ----------
    .. [1] W. J. Pierson and L. Moskowitz, "A proposed spectral form for fully
       developed wind seas based on the similarity theory of S. A.
       Kitaigorodskii", J. Geophys. Res. 69(24), 5181–5190, 1964,
       doi:10.1029/JZ069i024p05181.
    .. [2] R. H. Stewart, Introduction to Physical Oceanography, Texas A&M
       University, 2008, eqs. 16.29–16.33.

    Examples
    --------
    >>> float(spectrum_PiersonMoskowitz1964(0.8, 10.0))  # doctest: +ELLIPSIS
    0.446...
    """
    with np.errstate(divide="ignore"):  # U = 0: ω₀ = inf, a calm sea
        omega_0 = g / np.asarray(wind_speed_19_5, dtype=np.float64)
    return _pierson_moskowitz_shape(omega, alpha, omega_0, beta, g)  # S(ω) of [1]


def peak_frequency_PiersonMoskowitz1964(
    wind_speed_19_5: ArrayLike, beta: ArrayLike = PIERSON_MOSKOWITZ_BETA, g: float = GRAVITY
) -> NDArray[np.float64]:
    """Peak angular frequency ω_p = (4β/5)^{1/4} g/U₁₉.₅ ≈ 0.877 g/U₁₉.₅ of Pierson–Moskowitz [rad s⁻¹].

    Parameters
    ----------
    wind_speed_19_5 : array_like
        Wind speed 19.5 m above the sea U₁₉.₅ [m s⁻¹].
    beta : array_like, optional
        Constant β [-].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        ω_p [rad s⁻¹]; from dS/dω = 0, i.e. −5/ω + 4 β ω₀⁴/ω⁵ = 0.

    References
    ----------
    .. [1] R. H. Stewart, Introduction to Physical Oceanography, Texas A&M
       University, 2008, eq. 16.30.
    """
    return (4 * np.asarray(beta) / 5) ** 0.25 * g / np.asarray(wind_speed_19_5, dtype=np.float64)


def elevation_variance_PiersonMoskowitz1964(
    wind_speed_19_5: ArrayLike,
    alpha: ArrayLike = PIERSON_MOSKOWITZ_ALPHA,
    beta: ArrayLike = PIERSON_MOSKOWITZ_BETA,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """Elevation variance m0 = ∫ S dω = α U₁₉.₅⁴/(4 β g²) of the Pierson–Moskowitz spectrum [m²].

    Parameters
    ----------
    wind_speed_19_5 : array_like
        Wind speed 19.5 m above the sea U₁₉.₅ [m s⁻¹].
    alpha, beta : array_like, optional
        Constants α and β [-].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        m0 [m²]; 2.736 × 10⁻³ U⁴/g² for the constants of [1].

    Notes
    -----
    With u = ω⁻⁴: ∫₀^∞ α g² ω⁻⁵ exp(−β ω₀⁴ u) dω
    = (α g²/4) ∫₀^∞ exp(−β ω₀⁴ u) du
    = α g²/(4 β ω₀⁴), and ω₀ = g/U.

    References
    ----------
    .. [1] W. J. Pierson and L. Moskowitz, J. Geophys. Res. 69(24), 5181–5190,
       1964, doi:10.1029/JZ069i024p05181.
    .. [2] R. H. Stewart, Introduction to Physical Oceanography, Texas A&M
       University, 2008, eq. 16.32.
    """
    U = np.asarray(wind_speed_19_5, dtype=np.float64)
    return alpha * U**4 / (4 * np.asarray(beta) * g**2)  # m0 = α g²/(4 β ω₀⁴)


def significant_wave_height_PiersonMoskowitz1964(
    wind_speed_19_5: ArrayLike,
    alpha: ArrayLike = PIERSON_MOSKOWITZ_ALPHA,
    beta: ArrayLike = PIERSON_MOSKOWITZ_BETA,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """Significant wave height Hs = 2 √(α/β) U₁₉.₅²/g ≈ 0.209 U₁₉.₅²/g, Pierson–Moskowitz [m].

    Parameters
    ----------
    wind_speed_19_5 : array_like
        Wind speed 19.5 m above the sea U₁₉.₅ [m s⁻¹].
    alpha, beta : array_like, optional
        Constants α and β [-].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        Hs = 4 √m0 [m]; the constant 2 √(8.1 × 10⁻³/0.74) = 0.20925 is the
        "0.21" of [1] (≈ 0.22 U₁₀²/g with U₁₉.₅ = 1.026 U₁₀).

    References
    ----------
    .. [1] R. H. Stewart, Introduction to Physical Oceanography, Texas A&M
       University, 2008, eq. 16.33.
    """
    U = np.asarray(wind_speed_19_5, dtype=np.float64)
    return 2 * np.sqrt(np.asarray(alpha) / beta) * U**2 / g  # 4 √(α U⁴/(4 β g²))


def phillips_constant_JONSWAP1973(
    wind_speed_10: ArrayLike, fetch: ArrayLike, g: float = GRAVITY
) -> NDArray[np.float64]:
    """JONSWAP fetch law for the Phillips constant α = 0.076 (U₁₀²/(F g))^0.22 [-].

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    fetch : array_like
        Fetch F, the distance over which the wind has blown [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        α [-].

    References
    ----------
    .. [1] K. Hasselmann et al., "Measurements of wind-wave growth and swell
       decay during the Joint North Sea Wave Project (JONSWAP)", Ergänzungsheft
       zur Deutschen Hydrographischen Zeitschrift, Reihe A (8), Nr. 12, 1973,
       hdl:10013/epic.20654.
    """
    dimensionless_fetch = g * np.asarray(fetch, dtype=np.float64) / np.square(wind_speed_10)  # x̃ = g F/U²
    return 0.076 * dimensionless_fetch**-0.22  # α(x̃) of [1]


def peak_frequency_JONSWAP1973(wind_speed_10: ArrayLike, fetch: ArrayLike, g: float = GRAVITY) -> NDArray[np.float64]:
    """JONSWAP fetch law for the peak angular frequency ω_p = 22 (g²/(U₁₀ F))^{1/3} [rad s⁻¹].

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    fetch : array_like
        Fetch F [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        ω_p [rad s⁻¹] (f_p = 3.5 (g²/(U F))^{1/3} in [1]; 2π × 3.5 = 22).

    References
    ----------
    .. [1] K. Hasselmann et al., Dt. Hydrogr. Z. Erg.-H. A (8), Nr. 12, 1973,
       hdl:10013/epic.20654.
    """
    return 22.0 * (g**2 / (np.asarray(wind_speed_10, dtype=np.float64) * fetch)) ** (1 / 3)  # ω_p(x̃) of [1]


def spectrum_JONSWAP1973(
    omega: ArrayLike,
    wind_speed_10: ArrayLike,
    fetch: ArrayLike,
    gamma: ArrayLike = JONSWAP_GAMMA,
    sigma_a: ArrayLike = JONSWAP_SIGMA_A,
    sigma_b: ArrayLike = JONSWAP_SIGMA_B,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """JONSWAP spectrum of a fetch-limited wind sea S(ω) [m² s].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    fetch : array_like
        Fetch F [m].
    gamma : array_like, optional
        Peak-enhancement factor γ ≥ 1 [-]; γ = 1 is the Pierson–Moskowitz shape.
    sigma_a, sigma_b : array_like, optional
        Relative peak widths below (ω ≤ ω_p) and above the peak [-].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        S = α g² ω⁻⁵ exp(−(5/4)(ω_p/ω)⁴) γ^r, r = exp(−(ω − ω_p)²/(2 σ² ω_p²)),
        with α and ω_p from the fetch laws :func:`phillips_constant_JONSWAP1973`
        and :func:`peak_frequency_JONSWAP1973` [m² s]; 0 for ω ≤ 0.

    Notes
    -----
    At ω = ω_p, r = 1: the spectrum is γ times the Pierson–Moskowitz-shaped
    spectrum with the same α and ω_p (β ω₀⁴ = (5/4) ω_p⁴).

    *Fully developed limit.* The fetch laws keep growing the sea with fetch;
    ω_p falls to the Pierson–Moskowitz peak 0.877 g/U₁₉.₅ = 0.855 g/U₁₀ at the
    dimensionless fetch g F/U₁₀² = (22/0.855)³ ≈ 1.7 × 10⁴ (α is then 8.9 × 10⁻³,
    near the 8.1 × 10⁻³ of Pierson & Moskowitz). Beyond that fetch the sea is
    fully developed; use "Pierson-Moskowitz 1964" (or cap the fetch) there.
    No cap is applied here.

    References
    ----------
    .. [1] K. Hasselmann et al., "Measurements of wind-wave growth and swell
       decay during the Joint North Sea Wave Project (JONSWAP)", Ergänzungsheft
       zur Deutschen Hydrographischen Zeitschrift, Reihe A (8), Nr. 12, 1973,
       hdl:10013/epic.20654.
    """
    omega = np.asarray(omega, dtype=np.float64)
    alpha = phillips_constant_JONSWAP1973(wind_speed_10, fetch, g)
    omega_p = peak_frequency_JONSWAP1973(wind_speed_10, fetch, g)
    sigma = np.where(omega <= omega_p, sigma_a, sigma_b)
    r = np.exp(-np.square(omega - omega_p) / (2 * np.square(sigma * omega_p)))  # r of [1]
    return _pierson_moskowitz_shape(omega, alpha, omega_p, 1.25, g) * np.power(gamma, r)  # S(ω) of [1]


def depth_function_Kitaigorodskii1975(omega: ArrayLike, depth: ArrayLike, g: float = GRAVITY) -> NDArray[np.float64]:
    """Kitaigorodskii depth function φ(ω, d) = tanh²(kd) / (1 + 2kd / sinh 2kd) [-].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω ≥ 0 [rad s⁻¹].
    depth : array_like
        Water depth d [m]; ``np.inf`` gives φ = 1.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        φ in [0, 1] [-]; k = k(ω, d) from :func:`wavenumber_from_frequency`.

    Notes
    -----
    This is the exact form: φ is the ratio of k⁻³ dk/dω in depth d to its
    deep-water value 2 g²/ω⁵, i.e. the k⁻³ saturation range expressed in ω.
    With ω² = g k tanh(kd) and dω/dk = (ω/2k)(1 + 2kd/sinh 2kd) the ratio is
    ω⁴/(g² k² (1 + 2kd/sinh 2kd)) = tanh²(kd)/(1 + 2kd/sinh 2kd).
    Shallow: φ → ω_h²/2, ω_h = ω √(d/g); deep: φ → 1.

    References
    ----------
    .. [1] S. A. Kitaigorodskii, V. P. Krasitskii and M. M. Zaslavskii, "On
       Phillips' theory of equilibrium range in the spectra of wind-generated
       gravity waves", J. Phys. Oceanogr. 5(3), 410–420, 1975,
       doi:10.1175/1520-0485(1975)005<0410:OPTOER>2.0.CO;2.
    .. [2] E. Bouws, H. Günther, W. Rosenthal and C. L. Vincent, "Similarity of
       the wind wave spectrum in finite depth water: 1. Spectral form",
       J. Geophys. Res. 90(C1), 975–986, 1985, doi:10.1029/JC090iC01p00975.
    """
    depth = np.asarray(depth, dtype=np.float64)
    deep = np.isinf(depth)
    x = 2 * wavenumber_from_frequency(omega, depth, g) * np.where(deep, 1.0, depth)  # 2kd
    with np.errstate(invalid="ignore", over="ignore"):
        # x / sinh x = 2x e^{−x} / (1 − e^{−2x}), without overflow; → 1 as x → 0
        x_over_sinh = np.where(x > 0, 2 * x * np.exp(-x) / -np.expm1(-2 * x), 1.0)
        phi = np.square(np.tanh(x / 2)) / (1 + x_over_sinh)  # φ of [1]
    return np.where(deep, 1.0, phi)


def depth_function_ThompsonVincent1983(omega: ArrayLike, depth: ArrayLike, g: float = GRAVITY) -> NDArray[np.float64]:
    """Piecewise approximation of the Kitaigorodskii depth function φ(ω_h) [-].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω ≥ 0 [rad s⁻¹].
    depth : array_like
        Water depth d [m]; ``np.inf`` gives φ = 1.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        φ = ω_h²/2 for ω_h ≤ 1, 1 − (2 − ω_h)²/2 for 1 < ω_h < 2 and 1 above,
        ω_h = ω √(d/g) [-].

    Notes
    -----
    Provided for comparison; :func:`spectrum_TMA1985` uses the exact form
    :func:`depth_function_Kitaigorodskii1975` (they differ by less than 0.025).

    References
    ----------
    .. [1] E. F. Thompson and C. L. Vincent, "Prediction of wave height in
       shallow water", Proc. Coastal Structures '83, ASCE, 1000–1008, 1983.
    """
    depth = np.asarray(depth, dtype=np.float64)
    deep = np.isinf(depth)
    omega_h = np.asarray(omega, dtype=np.float64) * np.sqrt(np.where(deep, 1.0, depth) / g)
    phi = np.where(omega_h <= 1, 0.5 * np.square(omega_h), 1 - 0.5 * np.square(2 - omega_h))  # φ(ω_h) of [1]
    return np.where(deep | (omega_h >= 2), 1.0, phi)


def spectrum_TMA1985(
    omega: ArrayLike,
    wind_speed_10: ArrayLike,
    fetch: ArrayLike,
    depth: ArrayLike,
    gamma: ArrayLike = JONSWAP_GAMMA,
    sigma_a: ArrayLike = JONSWAP_SIGMA_A,
    sigma_b: ArrayLike = JONSWAP_SIGMA_B,
    g: float = GRAVITY,
) -> NDArray[np.float64]:
    """TMA spectrum of a wind sea in finite depth S(ω) [m² s].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    fetch : array_like
        Fetch F [m].
    depth : array_like
        Water depth d [m]; ``np.inf`` gives the JONSWAP spectrum.
    gamma : array_like, optional
        Peak-enhancement factor γ [-].
    sigma_a, sigma_b : array_like, optional
        Relative peak widths below and above the peak [-].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        S_TMA = S_JONSWAP(ω) φ(ω, d) [m² s], φ the exact Kitaigorodskii depth
        function (:func:`depth_function_Kitaigorodskii1975`).

    Notes
    -----
    Deviation from [1]: Bouws et al. fit α and ω_p of finite-depth seas
    separately (α from the wavenumber form); here both come from the
    deep-water JONSWAP fetch laws, so TMA → JONSWAP as d → ∞ and the depth
    only removes low-frequency variance (φ ≤ 1).

    References
    ----------
    .. [1] E. Bouws, H. Günther, W. Rosenthal and C. L. Vincent, "Similarity of
       the wind wave spectrum in finite depth water: 1. Spectral form",
       J. Geophys. Res. 90(C1), 975–986, 1985, doi:10.1029/JC090iC01p00975.
    .. [2] S. A. Kitaigorodskii, V. P. Krasitskii and M. M. Zaslavskii,
       J. Phys. Oceanogr. 5(3), 410–420, 1975,
       doi:10.1175/1520-0485(1975)005<0410:OPTOER>2.0.CO;2.
    """
    jonswap = spectrum_JONSWAP1973(omega, wind_speed_10, fetch, gamma, sigma_a, sigma_b, g)
    return jonswap * depth_function_Kitaigorodskii1975(omega, depth, g)  # S_TMA of [1]


def spectrum_swell(
    omega: ArrayLike,
    significant_wave_height: ArrayLike,
    peak_period: ArrayLike,
    bandwidth: ArrayLike = 0.05,
) -> NDArray[np.float64]:
    """Narrow swell spectrum, a Gaussian in ln ω peaking at ω_s = 2π/T_p, S(ω) [m² s].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    significant_wave_height : array_like
        Significant wave height of the swell Hs [m].
    peak_period : array_like
        Peak period T_p [s].
    bandwidth : array_like, optional
        Standard deviation b of ln ω [-]; for small b it is the relative width
        σ_ω/ω_s of the peak.

    Returns
    -------
    ndarray
        S = m0 exp(−(ln ω − μ)²/(2b²)) / (ω b √(2π)), μ = ln ω_s + b²,
        m0 = (Hs/4)² [m² s]; 0 for ω ≤ 0. ∫₀^∞ S dω = m0 exactly and
        dS/dω = 0 exactly at ω_s.

    Notes
    -----
    A log-normal density in ω, i.e. a Gaussian in ln ω, is this package's model of
    one narrow, long-travelled swell system, not a published fit: its variance
    and peak are exact in closed form and its width is one number. Unlike a
    Gaussian in ω, it vanishes faster than any power of ω as ω → 0, which keeps
    Ψ = S c_g/k finite at k → 0 (deep water c_g/k = g²/(2ω³)).
    """
    omega = np.asarray(omega, dtype=np.float64)
    b = np.asarray(bandwidth, dtype=np.float64)
    m0 = np.square(np.asarray(significant_wave_height, dtype=np.float64) / 4)  # Hs = 4 √m0
    mu = np.log(2 * np.pi / np.asarray(peak_period, dtype=np.float64)) + np.square(b)  # mode at ω_s
    omega_safe = np.where(omega > 0, omega, 1.0)
    density = np.exp(-np.square(np.log(omega_safe) - mu) / (2 * np.square(b))) / (omega_safe * b * np.sqrt(2 * np.pi))
    return np.where(omega > 0, m0 * density, np.where(np.isnan(omega), np.nan, 0.0))


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


# ---------------------------------------------------------------------------
# Method dispatch
# ---------------------------------------------------------------------------

FREQUENCY_SPECTRA: dict[str, Callable[..., NDArray[np.float64]]] = {
    "Pierson-Moskowitz 1964": spectrum_PiersonMoskowitz1964,
    "JONSWAP 1973": spectrum_JONSWAP1973,
    "TMA 1985": spectrum_TMA1985,
}
"""Frequency spectra S(ω) [m² s] by method name."""

WAVENUMBER_SPECTRA: dict[str, Callable[..., NDArray[np.float64]]] = {
    "Phillips 2001": spectrum_Phillips2001,
    "Elfouhaily 1997": spectrum_Elfouhaily1997,
}
"""Spectra defined directly as Ψ(kx, ky) [m⁴] by method name."""

SPECTRA: dict[str, Callable[..., NDArray[np.float64]]] = {**WAVENUMBER_SPECTRA, **FREQUENCY_SPECTRA}
"""All wave spectra by method name: the published function of each, Ψ(kx, ky) [m⁴]
for :data:`WAVENUMBER_SPECTRA`, S(ω) [m² s] for :data:`FREQUENCY_SPECTRA`.
:func:`wave_spectrum` gives Ψ for every name."""

DEFAULT_SPREADING: str = "Mitsuyasu 1975"
"""Spreading used by :class:`DirectionalSpectrum` when a frequency spectrum is given none."""


def frequency_spectrum(method: str, omega: ArrayLike, **kwargs) -> NDArray[np.float64]:
    """Frequency spectrum S(ω) [m² s] by method name.

    Parameters
    ----------
    method : str
        One of the keys of :data:`FREQUENCY_SPECTRA`.
    omega : array_like
        Angular frequency [rad s⁻¹].
    **kwargs
        Parameters of the method (``wind_speed_19_5``, ``wind_speed_10``,
        ``fetch``, ``depth``, ``gamma``, ``g``, ...); keywords it does not
        accept are ignored.

    Returns
    -------
    ndarray
        S [m² s].

    Raises
    ------
    ValueError
        If ``method`` is not a known frequency spectrum; the message lists the known ones.
    """
    if method not in FREQUENCY_SPECTRA:
        known = ", ".join(map(repr, FREQUENCY_SPECTRA))
        raise ValueError(f"unknown frequency spectrum {method!r}; known: {known}")
    function = FREQUENCY_SPECTRA[method]
    accepted = inspect.signature(function).parameters
    return function(omega, **{key: value for key, value in kwargs.items() if key in accepted})


# ---------------------------------------------------------------------------
# The directional wavenumber spectrum used by the rest of the package
# ---------------------------------------------------------------------------


def _require(name: str, value, condition: bool, allowed: str) -> None:
    """Raise a ValueError naming the field and its allowed range unless ``condition``."""
    if not condition:
        raise ValueError(f"{name} must be {allowed}, got {value!r}")


@dataclass(frozen=True)
class DirectionalSpectrum:
    """A directional wavenumber spectrum Ψ(kx, ky) [m⁴]: wind sea plus optional swell.

    Calling it, ``spec(kx, ky)``, gives Ψ [m⁴] with ∫∫ Ψ dkx dky = m0 [m²].

    Parameters
    ----------
    method : str, optional
        Wave spectrum, a key of :data:`SPECTRA`.
    spreading : str or None, optional
        Directional spreading, a key of
        :data:`oceanrender.waves.spreading.SPREADING`; ``None`` (default) is
        :data:`DEFAULT_SPREADING` for the frequency spectra. The
        :data:`WAVENUMBER_SPECTRA` carry their own spreading and require
        ``None``, which they keep: "Phillips 2001" the symmetric cos²
        (Tessendorf's |k̂·ŵ|²), "Elfouhaily 1997" (1 + Δ(k) cos 2φ)/(2π)
        folded downwind (:func:`~oceanrender.waves.elfouhaily.spectrum_Elfouhaily1997`).
    wind_speed : float, optional
        Wind speed 10 m above the sea U₁₀ [m s⁻¹], in (0, inf). The
        Pierson–Moskowitz spectrum is evaluated at U₁₉.₅ = 1.026 U₁₀
        (:data:`PIERSON_MOSKOWITZ_WIND_RATIO`); "Phillips 2001" uses it as
        Tessendorf's U.
    wind_direction : float, optional
        Direction the wind blows toward, counter-clockwise from +x [rad].
    fetch : float, optional
        Fetch F [m], in (0, inf); used by "JONSWAP 1973", "TMA 1985" and
        "Elfouhaily 1997", which also accepts ``np.inf`` (a fully developed sea).
    gamma : float, optional
        JONSWAP peak enhancement γ [-], in [1, 10]; "JONSWAP 1973", "TMA 1985".
        "Elfouhaily 1997" takes γ from its inverse wave age and refuses any
        value but the default :data:`JONSWAP_GAMMA`.
    depth : float, optional
        Water depth d [m], in (0, inf]; ``np.inf`` is deep water. Enters the
        dispersion relation of every frequency spectrum (so Ψ(k) changes but
        m0 does not) and the TMA depth function; the :data:`WAVENUMBER_SPECTRA`
        ignore it (their Ψ(k) is deep-water as published; only their
        :meth:`frequency_spectrum` uses it).
    small_wave_length : float, optional
        Suppression length ℓ [m], in [0, inf): Ψ is multiplied by exp(−k² ℓ²).
    alpha : float or None, optional
        Overrides α of "Phillips 2001" (default :data:`PHILLIPS_ALPHA`) or of
        "Pierson-Moskowitz 1964" (default :data:`PIERSON_MOSKOWITZ_ALPHA`) [-],
        in (0, inf). Not accepted by the fetch-law spectra (JONSWAP, TMA) nor
        by "Elfouhaily 1997" (α_p and α_m follow from the wave age and u*).
    swell_height : float, optional
        Significant wave height of the swell [m], in [0, inf); 0 (default) is no swell.
    swell_period : float, optional
        Peak period of the swell [s], in (0, inf).
    swell_direction : float, optional
        Direction the swell travels toward, counter-clockwise from +x [rad].
    swell_spreading_s : float, optional
        cos-2s spreading parameter of the swell [-], in [0, inf); 25 is a
        typical swell value after short decay distances, 75 after long ones (Goda).
    swell_bandwidth : float, optional
        Width of the swell peak, the standard deviation of ln ω [-] (≈ σ_ω/ω_s),
        in (0, 0.5]; see :func:`spectrum_swell`.
    g : float, optional
        Gravitational acceleration [m s⁻²], in (0, inf).
    surface_tension : float, optional
        Surface tension σ of the dispersion relation [N m⁻¹], in [0, inf); 0
        (default) is gravity waves only. It enters ω(k) and c_g(k) of the
        frequency spectra's transform to Ψ(k).

    Raises
    ------
    ValueError
        Naming the field and its allowed range, for any value out of range or
        an unknown method or spreading name; and for a parameter the method
        cannot use (fetch or γ for "Phillips 2001" and "Pierson-Moskowitz 1964",
        α for the fetch-law spectra, a finite depth for "Phillips 2001").

    Notes
    -----
    For a frequency spectrum S(ω) and a spreading D(θ; ω) (∫ D dθ = 1),

        Ψ(k, θ) = S(ω(k)) · c_g(k) · D(θ − θ_w; ω(k)) / k · exp(−k² ℓ²),

    with ω(k) the gravity-wave dispersion relation in depth d and
    c_g = dω/dk: the variance in dω dθ equals that in k dk dθ = dkx dky. The
    swell adds the same transform of :func:`spectrum_swell` with a
    cos-2s spreading about ``swell_direction``. Ψ(0, 0) = 0.

    The spreading functions need the peak frequency ω_p
    (:attr:`peak_frequency`): JONSWAP and TMA use the JONSWAP fetch law,
    Pierson–Moskowitz 0.877 g/U₁₉.₅.

    "Elfouhaily 1997" is Ψ of
    :func:`~oceanrender.waves.elfouhaily.spectrum_Elfouhaily1997` with
    ``folded=True``: its centrosymmetric spreading is moved onto the downwind
    half plane, which keeps every second-order statistic of heights and
    slopes (they depend on Ψ(k) + Ψ(−k) only) and makes all its waves travel
    with the wind. Swell and ℓ act on it as on the other spectra.

    References
    ----------
    .. [1] L. H. Holthuijsen, Waves in Oceanic and Coastal Waters, Cambridge
       University Press, 2007, doi:10.1017/CBO9780511618536.
    .. [2] Y. Goda, Random Seas and Design of Maritime Structures, 3rd ed.,
       World Scientific, 2010, doi:10.1142/7425.

    Examples
    --------
    >>> spec = DirectionalSpectrum("JONSWAP 1973", wind_speed=10.0, fetch=50e3)
    >>> round(spec.significant_wave_height(), 2)
    1.45
    """

    method: str = "JONSWAP 1973"
    spreading: str | None = None
    wind_speed: float = 10.0
    wind_direction: float = 0.0
    fetch: float = 100e3
    gamma: float = JONSWAP_GAMMA
    depth: float = np.inf
    small_wave_length: float = 0.0
    alpha: float | None = None
    swell_height: float = 0.0
    swell_period: float = 10.0
    swell_direction: float = 0.0
    swell_spreading_s: float = 25.0
    swell_bandwidth: float = 0.05
    g: float = GRAVITY
    surface_tension: float = 0.0

    def __post_init__(self) -> None:
        if self.method not in SPECTRA:
            raise ValueError(f"method: unknown wave spectrum {self.method!r}; known: {', '.join(map(repr, SPECTRA))}")
        if self.method in WAVENUMBER_SPECTRA:
            if self.spreading is not None:
                own = ("symmetric cos² spreading (Tessendorf's |k̂·ŵ|²)" if self.method == "Phillips 2001"
                       else "spreading (1 + Δ(k) cos 2φ)/(2π) of Elfouhaily et al. (1997), folded downwind")
                raise ValueError(
                    f"spreading: {self.method!r} carries its own {own}; "
                    f"leave spreading unset (None), got {self.spreading!r}"
                )
        elif self.spreading is None:
            object.__setattr__(self, "spreading", DEFAULT_SPREADING)
        elif self.spreading not in SPREADING:
            known = ", ".join(map(repr, SPREADING))
            raise ValueError(f"spreading: unknown directional spreading {self.spreading!r}; known: {known}")
        finite = _finite  # short alias for the checks below
        U = self.wind_speed
        _require("wind_speed", U, finite(U) and U > 0, "in (0, inf) [m s⁻¹]")
        _require("wind_direction", self.wind_direction, finite(self.wind_direction), "finite [rad]")
        if self.method == "Elfouhaily 1997":
            _require("fetch", self.fetch, _number(self.fetch) and self.fetch > 0,
                     "in (0, inf] [m] (np.inf for a fully developed sea)")
        else:
            _require("fetch", self.fetch, finite(self.fetch) and self.fetch > 0, "in (0, inf) [m]")
        _require("gamma", self.gamma, finite(self.gamma) and 1 <= self.gamma <= 10, "in [1, 10] [-]")
        if self.method == "Elfouhaily 1997" and self.gamma != JONSWAP_GAMMA:
            raise ValueError(
                f"gamma: 'Elfouhaily 1997' takes γ from its inverse wave age (1.7 + 6 log₁₀ Ω_c, Eq. 3 of "
                f"Elfouhaily et al. 1997); leave gamma at its default {JONSWAP_GAMMA}, got {self.gamma!r}"
            )
        _require("depth", self.depth, _number(self.depth) and self.depth > 0, "in (0, inf] [m] (np.inf for deep water)")
        ell = self.small_wave_length
        _require("small_wave_length", ell, finite(ell) and ell >= 0, "in [0, inf) [m]")
        if self.alpha is not None:
            if self.method == "Elfouhaily 1997":
                raise ValueError(
                    f"alpha: 'Elfouhaily 1997' takes α_p from the inverse wave age and α_m from the friction "
                    f"velocity (Eqs. 34 and 44 of Elfouhaily et al. 1997); leave alpha unset (None), got {self.alpha!r}"
                )
            if self.method not in ("Phillips 2001", "Pierson-Moskowitz 1964"):
                raise ValueError(
                    f"alpha: {self.method!r} takes α from the JONSWAP fetch law; leave alpha unset (None), "
                    f"got {self.alpha!r}"
                )
            _require("alpha", self.alpha, finite(self.alpha) and self.alpha > 0, "None or in (0, inf) [-]")
        h = self.swell_height
        _require("swell_height", h, finite(h) and h >= 0, "in [0, inf) [m] (0: no swell)")
        T = self.swell_period
        _require("swell_period", T, finite(T) and T > 0, "in (0, inf) [s]")
        _require("swell_direction", self.swell_direction, finite(self.swell_direction), "finite [rad]")
        s = self.swell_spreading_s
        _require("swell_spreading_s", s, finite(s) and s >= 0, "in [0, inf) [-]")
        w = self.swell_bandwidth
        _require("swell_bandwidth", w, finite(w) and 0 < w <= 0.5, "in (0, 0.5] [-]")
        _require("g", self.g, finite(self.g) and self.g > 0, "in (0, inf) [m s⁻²]")
        _require("surface_tension", self.surface_tension, finite(self.surface_tension) and self.surface_tension >= 0,
                 "in [0, inf) [N m⁻¹]")
        defaults = {f.name: f.default for f in dataclasses.fields(DirectionalSpectrum)}
        unused = {"Phillips 2001": ("fetch", "gamma"), "Pierson-Moskowitz 1964": ("fetch", "gamma")}
        for name in unused.get(self.method, ()):
            if getattr(self, name) != defaults[name]:
                raise ValueError(f"{name}: {self.method!r} does not use it (it has no fetch law); leave it out, "
                                 f"got {getattr(self, name)!r}")

    # -- derived parameters --------------------------------------------------

    @property
    def wind_speed_19_5(self) -> float:
        """Wind speed 19.5 m above the sea used by Pierson–Moskowitz, 1.026 U₁₀ [m s⁻¹]."""
        return PIERSON_MOSKOWITZ_WIND_RATIO * self.wind_speed

    @property
    def peak_frequency(self) -> float:
        """Peak angular frequency ω_p of the wind sea [rad s⁻¹].

        JONSWAP and TMA: the fetch law :func:`peak_frequency_JONSWAP1973`;
        Pierson–Moskowitz: 0.877 g/U₁₉.₅; Phillips 2001: the peak (4/5)^{1/4} g/U of
        its deep-water frequency spectrum α g² ω⁻⁵ exp(−(g/(U ω))⁴); Elfouhaily 1997:
        ω = k_p c(k_p) of its peak wavenumber k_p = g Ω_c²/U₁₀² (Eqs. 3, 24 and 37 of
        Elfouhaily et al. 1997), ≈ Ω_c g/U₁₀.
        """
        if self.method == "Elfouhaily 1997":
            omega_c = inverse_wave_age_Elfouhaily1997(self.wind_speed, self.fetch, self.g)
            k_p = peak_wavenumber_Elfouhaily1997(self.wind_speed, omega_c, self.g)
            return float(k_p * phase_speed_Elfouhaily1997(k_p, self.g))
        if self.method == "Pierson-Moskowitz 1964":
            return float(peak_frequency_PiersonMoskowitz1964(self.wind_speed_19_5, g=self.g))
        if self.method in ("JONSWAP 1973", "TMA 1985"):
            return float(peak_frequency_JONSWAP1973(self.wind_speed, self.fetch, self.g))
        return float(peak_frequency_PiersonMoskowitz1964(self.wind_speed, beta=1.0, g=self.g))

    @property
    def swell_variance(self) -> float:
        """Elevation variance of the swell (Hs_swell/4)² [m²]."""
        return (self.swell_height / 4) ** 2

    # -- spectra ---------------------------------------------------------------

    def wind_sea_frequency_spectrum(self, omega: ArrayLike) -> NDArray[np.float64]:
        """S(ω) of the wind sea as published, without ℓ suppression or swell [m² s].

        Parameters
        ----------
        omega : array_like
            Angular frequency [rad s⁻¹].

        Returns
        -------
        ndarray
            S [m² s]. For "Phillips 2001", F(k) dk/dω with F(k) = (α/2) k⁻³ exp(−1/(k L_w)²)
            and k = k(ω, d); for "Elfouhaily 1997", S(k) dk/dω with S(k) of
            :func:`~oceanrender.waves.elfouhaily.omnidirectional_spectrum_Elfouhaily1997`
            and the same gravity-wave k(ω, d) (the dispersion relation the FFT ocean
            moves the waves with, not the paper's capillary c(k)), so ∫ S dω = ∫ S dk.
        """
        omega = np.asarray(omega, dtype=np.float64)
        if self.method == "Pierson-Moskowitz 1964":
            alpha = PIERSON_MOSKOWITZ_ALPHA if self.alpha is None else self.alpha
            return spectrum_PiersonMoskowitz1964(omega, self.wind_speed_19_5, alpha=alpha, g=self.g)
        if self.method == "JONSWAP 1973":
            return spectrum_JONSWAP1973(omega, self.wind_speed, self.fetch, self.gamma, g=self.g)
        if self.method == "TMA 1985":
            return spectrum_TMA1985(omega, self.wind_speed, self.fetch, self.depth, self.gamma, g=self.g)
        k = wavenumber_from_frequency(omega, self.depth, self.g)
        if self.method == "Elfouhaily 1997":
            omni = omnidirectional_spectrum_Elfouhaily1997(k, self.wind_speed, self.fetch, g=self.g)
            with np.errstate(invalid="ignore"):  # ω = 0: S = 0, c_g = inf
                return np.where((omega <= 0) | (omni == 0), 0.0,
                                omni / group_velocity(k, self.depth, self.g, self.surface_tension))
        alpha = PHILLIPS_ALPHA if self.alpha is None else self.alpha
        L_w = self.wind_speed**2 / self.g
        with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
            x = 1 / np.square(k * L_w)
            omni = alpha / 2 * k**-3.0 * np.exp(-x) / group_velocity(k, self.depth, self.g,
                                                                       self.surface_tension)  # F(k) dk/dω
        return np.where((omega <= 0) | (x > 700), 0.0, omni)

    def frequency_spectrum(self, omega: ArrayLike) -> NDArray[np.float64]:
        """Omnidirectional spectrum of Ψ in frequency, ∫ Ψ k dθ · dk/dω, wind sea plus swell [m² s].

        Parameters
        ----------
        omega : array_like
            Angular frequency [rad s⁻¹].

        Returns
        -------
        ndarray
            S(ω) including the exp(−k² ℓ²) suppression [m² s]; ∫ S dω = m0.
        """
        omega = np.asarray(omega, dtype=np.float64)
        total = self.wind_sea_frequency_spectrum(omega)
        if self.swell_height > 0:
            total = total + spectrum_swell(omega, self.swell_height, self.swell_period, self.swell_bandwidth)
        if self.small_wave_length > 0:
            k = wavenumber_from_frequency(omega, self.depth, self.g)
            total = total * np.exp(-np.square(k * self.small_wave_length))
        return total

    def _polar(
        self, k: NDArray[np.float64], theta: NDArray[np.float64], kx=None, ky=None, folded: bool = True
    ) -> NDArray[np.float64]:
        """Ψ at wavenumber magnitude k > 0 and direction θ (or components kx, ky, if given) [m⁴].

        ``folded=False`` gives "Elfouhaily 1997" as published (centrosymmetric), with the
        same second-order statistics; the other methods ignore it.
        """
        if self.method == "Elfouhaily 1997":
            if kx is None:
                kx, ky = k * np.cos(theta), k * np.sin(theta)
            psi = spectrum_Elfouhaily1997(
                kx, ky, self.wind_speed, self.wind_direction, fetch=self.fetch,
                small_wave_length=self.small_wave_length, folded=folded, g=self.g,
            )
            if self.swell_height == 0:
                return psi
        elif self.method in WAVENUMBER_SPECTRA:
            alpha = PHILLIPS_ALPHA if self.alpha is None else self.alpha
            if kx is None:
                kx, ky = k * np.cos(theta), k * np.sin(theta)
            psi = spectrum_Phillips2001(
                kx, ky, self.wind_speed, self.wind_direction,
                alpha=alpha, small_wave_length=self.small_wave_length, g=self.g,
            )
            if self.swell_height == 0:
                return psi
        omega = dispersion_relation(k, self.depth, self.g, self.surface_tension)
        suppression = np.exp(-np.square(k * self.small_wave_length))  # Eq. 24 of Tessendorf (2001)
        with np.errstate(over="ignore"):  # k → 0: c_g/k → inf where S = 0, masked below
            jacobian = group_velocity(k, self.depth, self.g, self.surface_tension) / k  # S dω dθ = Ψ k dk dθ

        def density(variance: NDArray[np.float64], spreading: NDArray[np.float64]) -> NDArray[np.float64]:
            with np.errstate(invalid="ignore"):
                return np.where(variance == 0, 0.0, variance * jacobian * spreading * suppression)

        if self.method in FREQUENCY_SPECTRA:
            spreading = directional_spreading(
                self.spreading, theta - self.wind_direction,
                omega=omega, peak_frequency=self.peak_frequency, wind_speed_10=self.wind_speed, g=self.g,
            )
            psi = density(self.wind_sea_frequency_spectrum(omega), spreading)
        if self.swell_height > 0:
            swell = spectrum_swell(omega, self.swell_height, self.swell_period, self.swell_bandwidth)
            psi = psi + density(swell, spreading_cos2s(theta - self.swell_direction, self.swell_spreading_s))
        return psi

    def __call__(self, kx: ArrayLike, ky: ArrayLike) -> NDArray[np.float64]:
        """Ψ(kx, ky) [m⁴].

        Parameters
        ----------
        kx, ky : array_like
            Wavenumber components along +x (east) and +y (north) [rad m⁻¹].

        Returns
        -------
        ndarray
            Ψ [m⁴], broadcast over kx and ky; Ψ(0, 0) = 0 and finite everywhere.
        """
        kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
        k = np.hypot(kx, ky)
        # NOTE: k = 0 is replaced by 1 and masked at the end, so Ψ(0) = 0 without warnings.
        k_safe = np.where(k == 0, 1.0, k)
        psi = self._polar(k_safe, np.arctan2(ky, kx), kx, ky)
        return np.where(k == 0, 0.0, psi)

    def _frequency_range(self) -> tuple[float, float]:
        """Angular frequencies outside which the variance is below 1e-8 of m0 [rad s⁻¹]."""
        omega_p = self.peak_frequency
        # below: exp(−β (ω₀/ω)⁴) < e⁻⁷⁰⁰; above: the ω⁻⁵ tail holds < 1e-8 of m0
        low, high = 0.2 * omega_p, 100 * omega_p
        if self.swell_height > 0:
            b = self.swell_bandwidth
            ln_omega = np.log(2 * np.pi / self.swell_period) + b**2  # μ of spectrum_swell
            low = min(low, float(np.exp(ln_omega - 10 * b)))  # ± 10 standard deviations of ln ω
            high = max(high, float(np.exp(ln_omega + 10 * b)))
        return low, high

    def elevation_variance(self, radial_samples: int = 2048, angular_samples: int = 256) -> float:
        """Elevation variance m0 = ∫∫ Ψ dkx dky, by quadrature on a polar grid [m²].

        Parameters
        ----------
        radial_samples : int, optional
            Samples in ln k (trapezoids) [-].
        angular_samples : int, optional
            Directions, equally spaced from the wind direction (periodic rule) [-];
            a multiple of 4 puts the kinks of the one-sided cos² on nodes.

        Returns
        -------
        float
            m0 [m²], within 1e-4 relative of the exact integral with the defaults.

        Notes
        -----
        The radial range is k(0.2 ω_p) to k(100 ω_p), widened to ± 10 standard
        deviations of ln ω around the swell peak and cut at k = 10/ℓ: the
        omitted variance is below 1e-8 of m0.
        dkx dky = k² d(ln k) dθ.

        "Elfouhaily 1997" is integrated unfolded (the same m0, see the class
        Notes): its folded form jumps on the line across the wind, which the
        periodic rule would see, while the published form is a polynomial of
        degree 2 in cos θ, integrated exactly. Its range reaches at least
        10 k_m = 3700 rad m⁻¹, past the capillary peak at k_m, so that the
        omitted variance stays below 1e-8 of m0 at every wind speed.
        """
        omega_low, omega_high = self._frequency_range()
        # NOTE: the deep-water k is the smaller one; "Phillips 2001" is cut in deep-water k at any depth.
        low = float(wavenumber_from_frequency(omega_low, np.inf, self.g))
        high = float(wavenumber_from_frequency(omega_high, self.depth, self.g))
        if self.method == "Elfouhaily 1997":
            high = max(high, 10 * ELFOUHAILY_KM)  # past the capillary peak: F_m(10 k_m) = e^{−81/4}
        if self.small_wave_length > 0:
            high = max(min(high, 10 / self.small_wave_length), 2 * low)
        ln_k = np.linspace(np.log(low), np.log(high), radial_samples)
        theta = self.wind_direction + np.linspace(0, 2 * np.pi, angular_samples, endpoint=False)
        k = np.exp(ln_k)[:, None]
        psi = self._polar(k, theta[None, :], folded=False)
        radial = psi.sum(axis=1) * (2 * np.pi / angular_samples) * k[:, 0] ** 2
        return float(np.trapezoid(radial, ln_k))

    def significant_wave_height(self, **quadrature) -> float:
        """Significant wave height Hs = 4 √m0 [m]; ``quadrature`` goes to :meth:`elevation_variance`."""
        return 4 * float(np.sqrt(self.elevation_variance(**quadrature)))


def _number(value) -> bool:
    """True for a real number that is not NaN (inf allowed)."""
    try:
        return not np.isnan(float(value))
    except (TypeError, ValueError):
        return False


def _finite(value) -> bool:
    """True for a finite real number."""
    return _number(value) and bool(np.isfinite(float(value)))


def wave_spectrum(method: str, kx: ArrayLike, ky: ArrayLike, **kwargs) -> NDArray[np.float64]:
    """Directional wavenumber spectrum Ψ(kx, ky) [m⁴] by method name.

    Parameters
    ----------
    method : str
        One of the keys of :data:`SPECTRA`.
    kx, ky : array_like
        Wavenumber components [rad m⁻¹].
    **kwargs
        Parameters of the method: the fields of :class:`DirectionalSpectrum`.
        A keyword that is not one, or that the method cannot use, is an error
        (the same rules as the scene files, which build their spectra through
        :class:`DirectionalSpectrum` too).

    Returns
    -------
    ndarray
        Ψ [m⁴].

    Raises
    ------
    ValueError
        If ``method`` is not a known spectrum; the message lists the known ones.
        Out-of-range parameters of a frequency spectrum raise as in
        :class:`DirectionalSpectrum`.

    Notes
    -----
    :data:`WAVENUMBER_SPECTRA` ("Phillips 2001", "Elfouhaily 1997") are called
    directly, with their own keywords (array parameters broadcast; a calm sea,
    U = 0, gives 0); "Elfouhaily 1997" takes ``fetch`` (default 100 km) and ignores
    ``alpha``, and is folded downwind as in :class:`DirectionalSpectrum`.
    :data:`FREQUENCY_SPECTRA` are turned into Ψ by a :class:`DirectionalSpectrum`
    built from the keywords that are its fields (``spreading``, ``fetch``,
    ``gamma``, ``depth``, swell, ...; ``alpha`` is dropped for JONSWAP and TMA).
    """
    return make_spectrum(method, **kwargs)(kx, ky)


def make_spectrum(method: str, **parameters) -> DirectionalSpectrum:
    """The one way to build a wind-driven spectrum by name: a :class:`DirectionalSpectrum`, strictly.

    An unknown keyword, or one the method cannot use (see
    :class:`DirectionalSpectrum`, Raises), is a ValueError naming it; the
    Python API (:class:`~oceanrender.waves.fft_ocean.FFTOcean`,
    :func:`wave_spectrum`) and scene files (:func:`oceanrender.waves.sea.directional_spectrum`)
    all come here.
    """
    if method not in SPECTRA:
        raise ValueError(f"unknown wave spectrum {method!r}; known: {', '.join(map(repr, SPECTRA))}")
    known = {f.name for f in dataclasses.fields(DirectionalSpectrum)} - {"method"}
    unknown = sorted(set(parameters) - known)
    if unknown:
        raise ValueError(f"{unknown[0]}: not a parameter of a wave spectrum (known: {', '.join(sorted(known))})")
    if method == "Phillips 2001" and np.isfinite(parameters.get("depth", np.inf)):
        raise ValueError("depth: 'Phillips 2001' is a deep-water wavenumber spectrum; give the depth to the "
                         "dispersion relation (FFTOcean depth) or use 'TMA 1985'")
    if method in ("JONSWAP 1973", "TMA 1985", "Elfouhaily 1997") and parameters.get("alpha") is not None:
        raise ValueError(f"alpha: {method!r} takes α from its own laws; leave it out, got {parameters['alpha']!r}")
    return DirectionalSpectrum(method, **parameters)
