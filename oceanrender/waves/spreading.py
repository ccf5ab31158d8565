"""Directional spreading functions D(θ) of wind seas and swell.

A spreading function distributes the variance of one frequency over the
directions of travel θ, measured from the mean (wind) direction, so that

    ∫_{−π}^{π} D(θ) dθ = 1   [rad⁻¹ integrated over rad].

Every function here takes θ *relative to the mean direction* [rad] (any real
value; it is wrapped to [−π, π)), returns D [rad⁻¹], and is symmetric about
θ = 0, where it peaks. Methods are chosen by name through :data:`SPREADING`
and :func:`directional_spreading`, which forwards only the keywords a method
accepts, so one set of settings (ω, ω_p, U₁₀, g) can be passed to any method.

Conventions: angles in radians, angular frequencies in rad s⁻¹, wind speed
in m s⁻¹ at 10 m above the sea.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import gammaln

__all__ = [
    "wrap_angle",
    "spreading_cos2",
    "spreading_cos2s",
    "normalisation_cos2s",
    "spreading_parameter_Mitsuyasu1975",
    "spreading_Mitsuyasu1975",
    "spreading_parameter_Hasselmann1980",
    "spreading_Hasselmann1980",
    "spreading_width_DonelanBanner1985",
    "spreading_DonelanBanner1985",
    "SPREADING",
    "directional_spreading",
]

# NOTE: the same value as oceanrender.waves.wave_spectra.GRAVITY (a test checks
# it); it is repeated because spectra imports this module, not the reverse.
_GRAVITY = 9.81


def wrap_angle(theta: ArrayLike) -> NDArray[np.float64]:
    """Angle wrapped to [−π, π) [rad].

    Parameters
    ----------
    theta : array_like
        Angle [rad].

    Returns
    -------
    ndarray
        θ + 2πn in [−π, π) [rad].
    """
    theta = np.asarray(theta, dtype=np.float64)
    return np.mod(theta + np.pi, 2 * np.pi) - np.pi


def spreading_cos2(theta: ArrayLike) -> NDArray[np.float64]:
    """One-sided cos² spreading D(θ) = (2/π) cos²θ for |θ| < π/2, zero behind [rad⁻¹].

    Parameters
    ----------
    theta : array_like
        Direction of travel relative to the wind [rad].

    Returns
    -------
    ndarray
        D [rad⁻¹]; ∫_{−π}^{π} D dθ = 1.

    Notes
    -----
    ∫_{−π/2}^{π/2} cos²θ dθ = π/2, hence the factor 2/π. All variance travels
    with the wind. Tessendorf's (2001) |k̂·ŵ|² is the *symmetric* variant,
    cos²θ/π over the full circle, which sends half of the variance against the
    wind; it is built into ``"Phillips 2001"``
    (:func:`oceanrender.waves.wave_spectra.spectrum_Phillips2001`) and is not a
    separate entry here.

    References
    ----------
    .. [1] W. J. Pierson, G. Neumann and R. W. James, "Practical methods for
       observing and forecasting ocean waves by means of wave spectra and
       statistics", H.O. Pub. 603, U.S. Navy Hydrographic Office, 1955.
    .. [2] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes, eq. 23.
    """
    theta = wrap_angle(theta)
    return np.where(np.abs(theta) < np.pi / 2, 2 / np.pi * np.square(np.cos(theta)), 0.0)


def normalisation_cos2s(s: ArrayLike) -> NDArray[np.float64]:
    """Normalisation G(s) = Γ(s + 1) / (2 √π Γ(s + ½)) of cos^{2s}(θ/2) [rad⁻¹].

    Parameters
    ----------
    s : array_like
        Spreading parameter s ≥ 0 [-].

    Returns
    -------
    ndarray
        G(s) [rad⁻¹], so that ∫_{−π}^{π} G(s) cos^{2s}(θ/2) dθ = 1.

    Notes
    -----
    ∫_{−π}^{π} cos^{2s}(θ/2) dθ = 2 ∫_{−π/2}^{π/2} cos^{2s}u du = 2 √π Γ(s + ½)/Γ(s + 1)
    (a Beta integral). By Legendre's duplication formula this equals the form
    2^{2s−1} Γ(s + 1)² / (π Γ(2s + 1)) quoted by Mitsuyasu et al. (1975).
    Evaluated through ln Γ, so large s does not overflow.

    References
    ----------
    .. [1] M. S. Longuet-Higgins, D. E. Cartwright and N. D. Smith, "Observations
       of the directional spectrum of sea waves using the motions of a floating
       buoy", in Ocean Wave Spectra, Prentice-Hall, 1963, pp. 111–136.
    """
    s = np.asarray(s, dtype=np.float64)
    return np.exp(gammaln(s + 1) - gammaln(s + 0.5)) / (2 * np.sqrt(np.pi))


def spreading_cos2s(theta: ArrayLike, s: ArrayLike) -> NDArray[np.float64]:
    """Longuet-Higgins cos-2s spreading D(θ) = G(s) cos^{2s}(θ/2) [rad⁻¹].

    Parameters
    ----------
    theta : array_like
        Direction of travel relative to the mean direction [rad].
    s : array_like
        Spreading parameter s ≥ 0 [-]; larger is narrower, s = 0 is isotropic.

    Returns
    -------
    ndarray
        D [rad⁻¹]; ∫_{−π}^{π} D dθ = 1 (see :func:`normalisation_cos2s`).

    References
    ----------
    .. [1] M. S. Longuet-Higgins, D. E. Cartwright and N. D. Smith, "Observations
       of the directional spectrum of sea waves using the motions of a floating
       buoy", in Ocean Wave Spectra, Prentice-Hall, 1963, pp. 111–136.
    """
    half = np.abs(np.cos(wrap_angle(theta) / 2))  # ≥ 0 on [−π, π); abs guards rounding at ±π
    return normalisation_cos2s(s) * half ** (2 * np.asarray(s, dtype=np.float64))


def spreading_parameter_Mitsuyasu1975(
    omega: ArrayLike, peak_frequency: ArrayLike, wind_speed_10: ArrayLike, g: float = _GRAVITY
) -> NDArray[np.float64]:
    """Mitsuyasu et al. (1975) cos-2s spreading parameter s(ω) [-].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    peak_frequency : array_like
        Peak angular frequency ω_p of the spectrum [rad s⁻¹].
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        s = s_p (ω/ω_p)⁵ for ω ≤ ω_p and s_p (ω/ω_p)^−2.5 above, with
        s_p = 11.5 (U₁₀ ω_p / g)^−2.5 [-].

    References
    ----------
    .. [1] H. Mitsuyasu, F. Tasai, T. Suhara, S. Mizuno, M. Ohkusu, T. Honda and
       K. Rikiishi, "Observations of the directional spectrum of ocean waves
       using a cloverleaf buoy", J. Phys. Oceanogr. 5(4), 750–760, 1975,
       doi:10.1175/1520-0485(1975)005<0750:OOTDSO>2.0.CO;2.
    """
    ratio = np.asarray(omega, dtype=np.float64) / peak_frequency
    s_peak = 11.5 * (np.asarray(wind_speed_10) * peak_frequency / g) ** -2.5  # s_max of [1]
    with np.errstate(divide="ignore", over="ignore"):  # ω → 0: ratio^−2.5 is unused there
        return s_peak * np.where(ratio <= 1, ratio**5, ratio**-2.5)  # s(f) of [1]


def spreading_Mitsuyasu1975(
    theta: ArrayLike,
    omega: ArrayLike,
    peak_frequency: ArrayLike,
    wind_speed_10: ArrayLike,
    g: float = _GRAVITY,
) -> NDArray[np.float64]:
    """Mitsuyasu et al. (1975) frequency-dependent cos-2s spreading D(θ; ω) [rad⁻¹].

    Parameters
    ----------
    theta : array_like
        Direction of travel relative to the wind [rad].
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    peak_frequency : array_like
        Peak angular frequency ω_p [rad s⁻¹].
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        D = G(s) cos^{2s}(θ/2) with s from
        :func:`spreading_parameter_Mitsuyasu1975` [rad⁻¹]; ∫ D dθ = 1.

    References
    ----------
    .. [1] H. Mitsuyasu et al., "Observations of the directional spectrum of
       ocean waves using a cloverleaf buoy", J. Phys. Oceanogr. 5(4), 750–760,
       1975, doi:10.1175/1520-0485(1975)005<0750:OOTDSO>2.0.CO;2.
    .. [2] C. J. Horvath, "Empirical directional wave spectra for computer
       graphics", Proc. DigiPro 2015, 29–39, doi:10.1145/2791261.2791267.
    """
    s = spreading_parameter_Mitsuyasu1975(omega, peak_frequency, wind_speed_10, g)
    return spreading_cos2s(theta, s)


def spreading_parameter_Hasselmann1980(
    omega: ArrayLike, peak_frequency: ArrayLike, wind_speed_10: ArrayLike, g: float = _GRAVITY
) -> NDArray[np.float64]:
    """Hasselmann, Dunckel & Ewing (1980) cos-2s spreading parameter s(ω) [-].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    peak_frequency : array_like
        Peak angular frequency ω_p [rad s⁻¹].
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        s = 6.97 (ω/ω_p)^4.06 for ω < ω_p and 9.77 (ω/ω_p)^μ for ω ≥ ω_p, with
        μ = −2.33 − 1.45 (U₁₀/c_p − 1.17) and c_p = g/ω_p [-].

    Notes
    -----
    c_p is the deep-water phase speed at the peak, as in the paper's deep-water
    data, also when the spectrum is used in finite depth.

    References
    ----------
    .. [1] D. E. Hasselmann, M. Dunckel and J. A. Ewing, "Directional wave
       spectra observed during JONSWAP 1973", J. Phys. Oceanogr. 10(8),
       1264–1280, 1980, doi:10.1175/1520-0485(1980)010<1264:DWSODJ>2.0.CO;2.
    """
    ratio = np.asarray(omega, dtype=np.float64) / peak_frequency
    inverse_wave_age = np.asarray(wind_speed_10) * peak_frequency / g  # U/c_p, c_p = g/ω_p
    mu = -2.33 - 1.45 * (inverse_wave_age - 1.17)  # μ of [1]
    with np.errstate(divide="ignore", over="ignore"):  # ω → 0: ratio^μ is unused there
        return np.where(ratio < 1, 6.97 * ratio**4.06, 9.77 * ratio**mu)  # s(f) of [1]


def spreading_Hasselmann1980(
    theta: ArrayLike,
    omega: ArrayLike,
    peak_frequency: ArrayLike,
    wind_speed_10: ArrayLike,
    g: float = _GRAVITY,
) -> NDArray[np.float64]:
    """Hasselmann, Dunckel & Ewing (1980) cos-2s spreading D(θ; ω) [rad⁻¹].

    Parameters
    ----------
    theta : array_like
        Direction of travel relative to the wind [rad].
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    peak_frequency : array_like
        Peak angular frequency ω_p [rad s⁻¹].
    wind_speed_10 : array_like
        Wind speed 10 m above the sea U₁₀ [m s⁻¹].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        D = G(s) cos^{2s}(θ/2) with s from
        :func:`spreading_parameter_Hasselmann1980` [rad⁻¹]; ∫ D dθ = 1.

    References
    ----------
    .. [1] D. E. Hasselmann, M. Dunckel and J. A. Ewing, "Directional wave
       spectra observed during JONSWAP 1973", J. Phys. Oceanogr. 10(8),
       1264–1280, 1980, doi:10.1175/1520-0485(1980)010<1264:DWSODJ>2.0.CO;2.
    """
    s = spreading_parameter_Hasselmann1980(omega, peak_frequency, wind_speed_10, g)
    return spreading_cos2s(theta, s)


def spreading_width_DonelanBanner1985(omega: ArrayLike, peak_frequency: ArrayLike) -> NDArray[np.float64]:
    """Width parameter β(ω) of the sech² spreading of Donelan et al. (1985) and Banner (1990) [rad⁻¹].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    peak_frequency : array_like
        Peak angular frequency ω_p [rad s⁻¹].

    Returns
    -------
    ndarray
        β [rad⁻¹]: 2.61 (ω/ω_p)^1.3 for 0.56 < ω/ω_p < 0.95,
        2.28 (ω/ω_p)^−1.3 for 0.95 ≤ ω/ω_p < 1.6 (Donelan et al. 1985),
        10^{−0.4 + 0.8393 exp(−0.567 ln((ω/ω_p)²))} for ω/ω_p ≥ 1.6
        (Banner 1990), and 1.24 for ω/ω_p ≤ 0.56.

    Notes
    -----
    Donelan et al. fitted 0.56 < ω/ω_p < 1.6 and set β = 1.24 elsewhere;
    Banner's extension, from stereo-photographic wavenumber spectra, replaces
    the constant above 1.6 ω_p by a broadening that tends to β = 10^−0.4 ≈ 0.40.
    The pieces meet within 1 % at 0.56, 0.95 and 1.6 ω_p.

    References
    ----------
    .. [1] M. A. Donelan, J. Hamilton and W. H. Hui, "Directional spectra of
       wind-generated waves", Phil. Trans. R. Soc. Lond. A 315(1534), 509–562,
       1985, doi:10.1098/rsta.1985.0054.
    .. [2] M. L. Banner, "Equilibrium spectra of wind waves", J. Phys. Oceanogr.
       20(7), 966–984, 1990, doi:10.1175/1520-0485(1990)020<0966:ESOWW>2.0.CO;2.
    .. [3] C. J. Horvath, "Empirical directional wave spectra for computer
       graphics", Proc. DigiPro 2015, 29–39, doi:10.1145/2791261.2791267.
    """
    ratio = np.asarray(omega, dtype=np.float64) / peak_frequency
    # NOTE: each branch sees the ratio clipped to its own range, so no power overflows
    rising = 2.61 * np.clip(ratio, 0.56, 0.95) ** 1.3  # β of [1]
    falling = 2.28 * np.clip(ratio, 0.95, 1.6) ** -1.3  # β of [1]
    banner = 10.0 ** (-0.4 + 0.8393 * np.exp(-0.567 * np.log(np.square(np.maximum(ratio, 1.6)))))  # [2], as in [3]
    beta = np.where(ratio < 0.95, rising, falling)
    beta = np.where(ratio >= 1.6, banner, beta)
    return np.where(ratio <= 0.56, 1.24, beta)


def spreading_DonelanBanner1985(theta: ArrayLike, omega: ArrayLike, peak_frequency: ArrayLike) -> NDArray[np.float64]:
    """sech² spreading of Donelan et al. (1985) with Banner's (1990) high-frequency extension [rad⁻¹].

    Parameters
    ----------
    theta : array_like
        Direction of travel relative to the wind [rad].
    omega : array_like
        Angular frequency ω [rad s⁻¹].
    peak_frequency : array_like
        Peak angular frequency ω_p [rad s⁻¹].

    Returns
    -------
    ndarray
        D = β sech²(β θ) / (2 tanh(β π)) with β from
        :func:`spreading_width_DonelanBanner1985` [rad⁻¹]; ∫_{−π}^{π} D dθ = 1 exactly.

    Notes
    -----
    Donelan et al. write D = (β/2) sech²(βθ), normalised over the whole real
    line; over the circle its integral is tanh(βπ) (0.9992 at β = 1.24, 0.85
    at Banner's β → 0.40). The closed-form factor 1/tanh(βπ) used here makes
    ∫_{−π}^{π} D dθ = 1 to rounding error.

    References
    ----------
    .. [1] M. A. Donelan, J. Hamilton and W. H. Hui, "Directional spectra of
       wind-generated waves", Phil. Trans. R. Soc. Lond. A 315(1534), 509–562,
       1985, doi:10.1098/rsta.1985.0054.
    .. [2] M. L. Banner, "Equilibrium spectra of wind waves", J. Phys. Oceanogr.
       20(7), 966–984, 1990, doi:10.1175/1520-0485(1990)020<0966:ESOWW>2.0.CO;2.
    """
    beta = spreading_width_DonelanBanner1985(omega, peak_frequency)
    x = np.abs(beta * wrap_angle(theta))
    e = np.exp(-2 * x)
    sech2 = 4 * e / np.square(1 + e)  # sech²x without overflow of cosh
    return beta * sech2 / (2 * np.tanh(beta * np.pi))  # D of [1], renormalised on the circle


SPREADING: dict[str, Callable[..., NDArray[np.float64]]] = {
    "cos2": spreading_cos2,
    "Mitsuyasu 1975": spreading_Mitsuyasu1975,
    "Hasselmann 1980": spreading_Hasselmann1980,
    "Donelan-Banner 1985": spreading_DonelanBanner1985,
}
"""Directional spreading functions D(θ; ω) [rad⁻¹] by method name."""


def directional_spreading(method: str, theta: ArrayLike, **kwargs) -> NDArray[np.float64]:
    """Directional spreading D(θ) [rad⁻¹] by method name.

    Parameters
    ----------
    method : str
        One of the keys of :data:`SPREADING`.
    theta : array_like
        Direction of travel relative to the wind [rad].
    **kwargs
        ``omega`` [rad s⁻¹], ``peak_frequency`` [rad s⁻¹], ``wind_speed_10``
        [m s⁻¹], ``g`` [m s⁻²]; keywords the method does not accept are ignored.

    Returns
    -------
    ndarray
        D [rad⁻¹].

    Raises
    ------
    ValueError
        If ``method`` is not a known spreading; the message lists the known ones.
    """
    if method not in SPREADING:
        raise ValueError(f"unknown directional spreading {method!r}; known: {', '.join(map(repr, SPREADING))}")
    function = SPREADING[method]
    accepted = inspect.signature(function).parameters
    return function(theta, **{key: value for key, value in kwargs.items() if key in accepted})
