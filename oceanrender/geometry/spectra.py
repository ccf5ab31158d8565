"""Directional wave spectra and the dispersion relation of surface gravity waves.

Conventions: wavenumbers in rad m⁻¹, angular frequencies in rad s⁻¹, lengths in
m, wind speed in m s⁻¹. The wind direction is an angle in radians measured
counter-clockwise from +x (east); converting from degrees is the caller's job.

A *directional wavenumber spectrum* Ψ(kx, ky) [m⁴] here is the variance
density of the surface elevation over the wavenumber plane, so that

    ∫∫ Ψ(kx, ky) dkx dky = m0 = ⟨η²⟩ [m²],

and the significant wave height is Hs = 4 √m0.

Methods are chosen by name through :data:`SPECTRA` and :func:`wave_spectrum`.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import k1

__all__ = [
    "GRAVITY",
    "PHILLIPS_ALPHA",
    "spectrum_Phillips2001",
    "elevation_variance_Phillips2001",
    "significant_wave_height_Phillips2001",
    "dispersion_relation",
    "SPECTRA",
    "wave_spectrum",
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
    psi = alpha / 2 * k_safe**-4 * low_cut * high_cut * spreading  # F(k)/k · D(θ), F of [2]
    return np.where(k == 0, 0.0, psi)


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


def dispersion_relation(
    k: ArrayLike, depth: ArrayLike = np.inf, g: float = GRAVITY
) -> NDArray[np.float64]:
    """Angular frequency of linear surface gravity waves ω(k) [rad s⁻¹].

    Parameters
    ----------
    k : array_like
        Wavenumber magnitude [rad m⁻¹].
    depth : array_like, optional
        Water depth d [m]; ``np.inf`` (default) uses the deep-water limit exactly.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        ω = √(g k tanh(k d)) [rad s⁻¹].

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       eqs. 14 and 15.
    """
    k = np.asarray(k, dtype=np.float64)
    depth = np.asarray(depth, dtype=np.float64)
    deep = np.isinf(depth)
    # NOTE: tanh(k·inf) is NaN at k = 0; the deep-water branch avoids it.
    tanh_kd = np.where(deep, 1.0, np.tanh(k * np.where(deep, 1.0, depth)))
    return np.sqrt(g * k * tanh_kd)  # Eq. 15 of [1]; eq. 14 when d = inf


SPECTRA: dict[str, Callable[..., NDArray[np.float64]]] = {
    "Phillips 2001": spectrum_Phillips2001,
}
"""Directional wavenumber spectra Ψ(kx, ky) [m⁴] by method name."""


def wave_spectrum(method: str, kx: ArrayLike, ky: ArrayLike, **kwargs) -> NDArray[np.float64]:
    """Directional wavenumber spectrum Ψ(kx, ky) [m⁴] by method name.

    Parameters
    ----------
    method : str
        One of the keys of :data:`SPECTRA`.
    kx, ky : array_like
        Wavenumber components [rad m⁻¹].
    **kwargs
        Parameters of the method; keywords it does not accept are ignored, so one
        set of settings can be passed to any method.

    Returns
    -------
    ndarray
        Ψ [m⁴].

    Raises
    ------
    ValueError
        If ``method`` is not a known spectrum; the message lists the known ones.
    """
    if method not in SPECTRA:
        raise ValueError(f"unknown wave spectrum {method!r}; known: {', '.join(map(repr, SPECTRA))}")
    function = SPECTRA[method]
    accepted = inspect.signature(function).parameters
    return function(kx, ky, **{key: value for key, value in kwargs.items() if key in accepted})
