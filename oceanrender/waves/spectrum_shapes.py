"""The omnidirectional spectra by family: Tessendorf's Phillips wavenumber spectrum (2001) and the
frequency spectra S(ω) [m² s] of Pierson & Moskowitz (1964), JONSWAP (1973), TMA (1985, with the
Kitaigorodskii and Thompson–Vincent depth functions) and swell.

Part of the wave spectra of :mod:`.wave_spectra` (which re-exports every name here); its docstring gives
the conventions, and each function its formula and source.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import k1

from .dispersion import GRAVITY, wavenumber_from_frequency

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
