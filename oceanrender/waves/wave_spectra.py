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

from .dispersion import (
    GRAVITY,
    SEAWATER_DENSITY,
    SEAWATER_SURFACE_TENSION,
    dispersion_relation,
    group_velocity,
    wavenumber_from_frequency,
)
from .elfouhaily import (
    ELFOUHAILY_KM,
    inverse_wave_age_Elfouhaily1997,
    omnidirectional_spectrum_Elfouhaily1997,
    peak_wavenumber_Elfouhaily1997,
    phase_speed_Elfouhaily1997,
    spectrum_Elfouhaily1997,
)
from .spectrum_shapes import (
    JONSWAP_GAMMA,
    JONSWAP_SIGMA_A,
    JONSWAP_SIGMA_B,
    PHILLIPS_ALPHA,
    PIERSON_MOSKOWITZ_ALPHA,
    PIERSON_MOSKOWITZ_BETA,
    PIERSON_MOSKOWITZ_WIND_RATIO,
    depth_function_Kitaigorodskii1975,
    depth_function_ThompsonVincent1983,
    elevation_variance_Phillips2001,
    elevation_variance_PiersonMoskowitz1964,
    peak_frequency_JONSWAP1973,
    peak_frequency_PiersonMoskowitz1964,
    phillips_constant_JONSWAP1973,
    significant_wave_height_Phillips2001,
    significant_wave_height_PiersonMoskowitz1964,
    spectrum_JONSWAP1973,
    spectrum_Phillips2001,
    spectrum_PiersonMoskowitz1964,
    spectrum_TMA1985,
    spectrum_swell,
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
