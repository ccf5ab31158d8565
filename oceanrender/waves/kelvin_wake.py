"""Linear Kelvin ship wake: the steady waves of a pressure patch moving over the sea.

A moving hull is modelled as a smooth surface pressure p(x, y) [Pa] travelling at a
constant speed U [m s⁻¹] along +x over water of depth h [m]. In the frame of the body
(body at the origin, the water streaming past towards −x) the linearised potential flow
has a steady surface elevation η(x, y) [m] whose Fourier transform is the pressure's
times a transfer function (:func:`wake_response`, after Lamb [1] and Wehausen & Laitone
[2]); :func:`kelvin_wake_grid` evaluates it with a 2-D FFT on a periodic grid. The waves
trail behind the body (x < 0) inside a wedge whose half-angle, the cusp angle, is
asin(1/3) ≈ 19.47° in deep water and widens as the depth Froude number U/√(g h)
approaches 1 (Havelock [3], :func:`kelvin_cusp_angle`).

The wake is a disturbance in the body frame, to be added to the height of the sea
surface; nothing here knows about the wind sea or the coastal solver.

Conventions: lengths in m, time in s, wavenumbers in rad m⁻¹, pressure in Pa; arrays
on a grid are indexed ``[iy, ix]`` as in :mod:`oceanrender.waves.fft_ocean`.

References
----------
.. [1] H. Lamb, Hydrodynamics, 6th ed., Cambridge University Press, 1932, §§ 242–243
   (surface pressure travelling over water, Rayleigh's fictitious dissipation) and
   § 256 (ship waves).
.. [2] J. V. Wehausen and E. V. Laitone, "Surface waves", in Handbuch der Physik,
   vol. 9, Springer, 1960, pp. 446–778 (moving pressure distributions).
.. [3] T. H. Havelock, "The propagation of groups of waves in dispersive media, with
   application to waves on water produced by a travelling disturbance", Proc. R. Soc.
   Lond. A 81(549), 398–430, 1908, doi:10.1098/rspa.1908.0097 (§ 13 deep water,
   § 15 finite depth).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.fft
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from .wave_spectra import GRAVITY, SEAWATER_DENSITY, dispersion_relation, wavenumber_from_frequency

__all__ = [
    "KELVIN_ANGLE_DEEP_WATER",
    "WAKE_WRAP_EFOLDS",
    "WAKE_SOURCE_CUTOFF",
    "WakeSource",
    "depth_froude_number",
    "kelvin_cusp_angle",
    "wake_response",
    "default_wake_damping",
    "kelvin_wake_spacing",
    "kelvin_wake_grid",
]

KELVIN_ANGLE_DEEP_WATER: float = float(np.arcsin(1 / 3))
"""Half-angle of the deep-water Kelvin wedge, asin(1/3) ≈ 19.47° [rad] (Kelvin 1887; [3] § 13)."""

WAKE_WRAP_EFOLDS: float = 3.0
"""E-folds by which the default Rayleigh damping attenuates the wake's waves on their way to
the nearest periodic image of the grid [-] (see :func:`default_wake_damping`)."""

WAKE_SOURCE_CUTOFF: float = 3.0
"""k σ beyond which the footprint's transform is below e^{−k²σ²/2} = e^{−4.5} ≈ 1 % of its peak [-]
(see :func:`kelvin_wake_spacing`)."""

#: The footprint is exp(−8 ξ² − 8 ζ²), ξ = x/L, ζ = y/B: a Gaussian whose standard
#: deviations are a quarter of the hull's length and beam, so that ±2σ spans the hull.
_FOOTPRINT_SHARPNESS = 8.0

#: Brent's method to the last bits: the smallest relative tolerance scipy accepts.
_RTOL = 4 * float(np.finfo(np.float64).eps)


@dataclass(frozen=True)
class WakeSource:
    """A moving hull as a smooth surface pressure patch p(x, y) [Pa].

    Parameters
    ----------
    length : float
        Hull length L along the track [m]; > 0.
    beam : float
        Hull beam (width) B [m]; > 0.
    draft : float
        Draft D [m]; > 0. The peak pressure is ρ g D, the hydrostatic pressure at the
        keel, so a body at rest would depress the surface by D at its centre.

    Notes
    -----
    The footprint is a Gaussian, p = ρ g D exp(−8 (x/L)² − 8 (y/B)²): standard
    deviations σ_x = L/4, σ_y = B/4, so ±2σ spans the hull and 91 % of the force acts
    inside the L × B rectangle. A Gaussian is chosen over compact shapes (raised cosines,
    ellipses) because its Fourier transform is again a Gaussian, known in closed form and
    falling faster than any power of k: the short waves it excites, and the aliasing of
    a sampled footprint, are bounded by exp(−(k σ)²/2) instead of a slow power law, so the
    grid spacing alone sets how much of the wake is resolved. The displaced volume of
    the static depression is ∫∫ p/(ρ g) = (π/8) L B D ≈ 0.39 L B D, a slender hull's
    block coefficient.
    """

    length: float
    beam: float
    draft: float

    def __post_init__(self) -> None:
        for name in ("length", "beam", "draft"):
            value = getattr(self, name)
            if not (np.isfinite(value) and value > 0):
                raise ValueError(f"{name} must be a finite positive length [m], got {value!r}")

    @property
    def widths(self) -> tuple[float, float]:
        """Standard deviations (σ_x, σ_y) = (L/4, B/4) of the Gaussian footprint [m]."""
        return (self.length / 4, self.beam / 4)

    @property
    def displaced_volume(self) -> float:
        """Volume of the static depression ∫∫ p/(ρ g) dx dy = (π/8) L B D [m³]."""
        return float(np.pi / _FOOTPRINT_SHARPNESS * self.length * self.beam * self.draft)

    def pressure(self, x: ArrayLike, y: ArrayLike, g: float = GRAVITY,
                 density: float = SEAWATER_DENSITY) -> NDArray[np.float64]:
        """Surface pressure p(x, y) of the hull centred at the origin [Pa].

        Parameters
        ----------
        x, y : array_like
            Position along and across the track, relative to the hull's centre [m].
        g : float, optional
            Gravitational acceleration [m s⁻²].
        density : float, optional
            Water density ρ [kg m⁻³].

        Returns
        -------
        ndarray
            p = ρ g D exp(−8 (x/L)² − 8 (y/B)²) [Pa].
        """
        xi = np.asarray(x, dtype=np.float64) / self.length
        zeta = np.asarray(y, dtype=np.float64) / self.beam
        return density * g * self.draft * np.exp(-_FOOTPRINT_SHARPNESS * (xi**2 + zeta**2))

    def pressure_spectrum(self, kx: ArrayLike, ky: ArrayLike, g: float = GRAVITY,
                          density: float = SEAWATER_DENSITY) -> NDArray[np.float64]:
        """Fourier transform p̂(k) = ∫∫ p(x) e^{−i k·x} dx dy of :meth:`pressure` [Pa m²].

        Parameters
        ----------
        kx, ky : array_like
            Wavenumber components along and across the track [rad m⁻¹].
        g : float, optional
            Gravitational acceleration [m s⁻²].
        density : float, optional
            Water density ρ [kg m⁻³].

        Returns
        -------
        ndarray
            p̂ = ρ g D 2π σ_x σ_y exp(−(k_x² σ_x² + k_y² σ_y²)/2) [Pa m²], real and even
            because the footprint is centred and symmetric.
        """
        sx, sy = self.widths
        kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
        gaussian = np.exp(-0.5 * ((kx * sx) ** 2 + (ky * sy) ** 2))  # transform of exp(−x²/2σ²)
        return density * g * self.draft * 2 * np.pi * sx * sy * gaussian


def _require_positive(name: str, value: float, unit: str, allow_inf: bool = False) -> float:
    """``value`` as a float, or a ValueError naming ``name`` when it is not a positive number."""
    value = float(value)
    if not (value > 0 and (allow_inf or np.isfinite(value))):
        kind = "positive" if allow_inf else "finite positive"
        raise ValueError(f"{name} must be a {kind} number [{unit}], got {value!r}")
    return value


def depth_froude_number(speed: ArrayLike, depth: ArrayLike, g: float = GRAVITY) -> NDArray[np.float64]:
    """Depth Froude number Fr_h = U/√(g h) [-].

    Parameters
    ----------
    speed : array_like
        Speed U of the body [m s⁻¹].
    depth : array_like
        Water depth h [m]; ``np.inf`` gives 0 (deep water).
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    ndarray
        U/√(g h) [-]: the body's speed over the fastest (longest) wave's speed √(g h).

    References
    ----------
    .. [1] T. H. Havelock, Proc. R. Soc. Lond. A 81, 398–430, 1908, § 15,
       doi:10.1098/rspa.1908.0097.
    """
    return np.asarray(speed, dtype=np.float64) / np.sqrt(g * np.asarray(depth, dtype=np.float64))


def _tanhc(kappa: float) -> float:
    """tanh(κ)/κ, 1 at κ = 0 [-]."""
    return 1.0 if kappa == 0 else float(np.tanh(kappa) / kappa)


def _group_ratio_terms(kappa: float) -> tuple[float, float]:
    """n = c_g/c = ½ + κ/sinh 2κ and dn/dκ at κ = k h, without overflow at large κ."""
    q = np.exp(-2 * kappa)  # e^{−2κ}; 1/sinh 2κ = 2q/(1 − q²)
    one_minus_q2 = -np.expm1(-4 * kappa)  # 1 − q², accurate for small κ
    inv_sinh = 2 * q / one_minus_q2
    coth = (1 + q * q) / one_minus_q2
    n = 0.5 + kappa * inv_sinh  # c_g/c of ω² = g k tanh(kh), in Eq. 2 of kelvin_cusp_angle
    dn = inv_sinh * (1 - 2 * kappa * coth)  # d(κ/sinh 2κ)/dκ
    return float(n), float(dn)


def _cusp_condition(kappa: float, froude: float) -> float:
    """d(tan ψ)/dt up to a positive factor, along the stationary waves parameterised by κ = k h.

    Stationary waves have phase speed U cos θ: tanh(κ)/κ = Fr² cos²θ, so t² = tan²θ =
    κ Fr²/tanh κ − 1. Their ray makes tan ψ = n t/(1 − n + t²) with the track; its maximum
    over t (the cusp) is where n′(t) t (1 + t²) = n (t² + n − 1).
    """
    tanh = np.tanh(kappa)
    sech2 = 4 * np.exp(-2 * kappa) / (1 + np.exp(-2 * kappa)) ** 2  # 1 − tanh², no cancellation
    t2 = kappa * froude**2 / tanh - 1  # Eq. 1 of kelvin_cusp_angle
    n, dn_dkappa = _group_ratio_terms(kappa)
    # dκ/dt from tanh(κ)/κ = Fr²/(1 + t²): t dκ/dt (1 + t²) = 2 t² κ tanh κ/(tanh κ − κ sech²κ)
    dn_term = dn_dkappa * 2 * t2 * kappa * tanh / (tanh - kappa * sech2)
    return float(dn_term - n * (t2 + n - 1))  # Eq. 3 of kelvin_cusp_angle


def _cusp_angle_scalar(froude: float) -> float:
    """Cusp half-angle for one depth Froude number ≥ 0 [rad]."""
    if np.isnan(froude):
        return np.nan
    if froude == 0:
        return KELVIN_ANGLE_DEEP_WATER  # deep water, § 13 of Havelock (1908)
    if froude >= 1:
        return float(np.arcsin(1 / froude))  # supercritical: the Mach wedge, § 15 of Havelock (1908)
    # the cusp lies between the transverse wave on the track (t = 0) and t = 1 (θ = 45°)
    kappa_track = brentq(lambda kappa: _tanhc(kappa) - froude**2, 0.0, 1 / froude**2 + 1, xtol=1e-300, rtol=_RTOL)
    kappa_45 = brentq(lambda kappa: _tanhc(kappa) - froude**2 / 2, 0.0, 2 / froude**2 + 1, xtol=1e-300, rtol=_RTOL)
    kappa = brentq(_cusp_condition, kappa_track, kappa_45, args=(froude,), xtol=1e-300, rtol=_RTOL)
    t = np.sqrt(max(kappa * froude**2 / np.tanh(kappa) - 1, 0.0))
    n, _ = _group_ratio_terms(kappa)
    return float(np.arctan2(n * t, 1 - n + t * t))  # Eq. 2 of kelvin_cusp_angle: the ray of the cusp wave


def kelvin_cusp_angle(depth_froude: ArrayLike) -> NDArray[np.float64]:
    """Half-angle ψ_c of the cusp lines of a Kelvin wake at depth Froude number Fr_h [rad].

    Parameters
    ----------
    depth_froude : array_like
        Fr_h = U/√(g h) [-], ≥ 0; 0 is deep water (see :func:`depth_froude_number`).

    Returns
    -------
    ndarray
        ψ_c [rad]: asin(1/3) ≈ 19.47° at Fr_h = 0, rising monotonically to 90° at
        Fr_h = 1; asin(1/Fr_h) for Fr_h ≥ 1. NaN where Fr_h is NaN.

    Raises
    ------
    ValueError
        If any ``depth_froude`` is negative.

    Notes
    -----
    Waves that stand still behind the body have phase speed U cos θ, θ the angle of
    their wavevector to the track, so with κ = k h and finite-depth gravity dispersion

        tanh(κ)/κ = Fr_h² cos²θ.                                     (Eq. 1)

    Their energy moves relative to the body at c_g k̂ − U x̂, c_g = n c with
    n = ½ + κ/sinh 2κ, so the wave of direction θ is found along the ray

        tan ψ = n t/(1 − n + t²),   t = tan θ.                       (Eq. 2)

    The cusp is the largest ψ reached, where d(tan ψ)/dt = 0:

        t (1 + t²) dn/dt = n (t² + n − 1).                           (Eq. 3)

    In deep water n = ½: t² = ½ and tan ψ = 1/√8, sin ψ = 1/3. For 0 < Fr_h < 1 the
    root of Eq. 3 is found by Brent's method in κ between the transverse wave on the
    track (t = 0, where the left side is 0 and the right side −n(1 − n) < 0) and the
    wave at θ = 45° (t = 1, where the sign is reversed). Near Fr_h = 1 the long waves
    are nearly non-dispersive and the expansion κ² ≪ 1 of Eq. 1–3 gives
    tan ψ_c ≈ 1/√(8 (1 − Fr_h²)), so ψ_c → 90°. Above Fr_h = 1 no transverse waves
    exist (Eq. 1 needs cos θ ≤ 1/Fr_h), and the largest ray angle is that of the
    longest, non-dispersive waves (n → 1, θ → acos(1/Fr_h)): sin ψ_c = 1/Fr_h, the
    Mach angle of the shallow-water wave speed [1] § 15.

    References
    ----------
    .. [1] T. H. Havelock, "The propagation of groups of waves in dispersive media, with
       application to waves on water produced by a travelling disturbance", Proc. R.
       Soc. Lond. A 81(549), 398–430, 1908, doi:10.1098/rspa.1908.0097, §§ 13, 15.
    .. [2] H. Lamb, Hydrodynamics, 6th ed., Cambridge University Press, 1932, § 256.

    Examples
    --------
    >>> round(float(np.degrees(kelvin_cusp_angle(0.0))), 3)
    19.471
    """
    froude = np.asarray(depth_froude, dtype=np.float64)
    if np.any(froude < 0):
        raise ValueError(f"depth_froude must be ≥ 0 [-], got {depth_froude!r}")
    return np.vectorize(_cusp_angle_scalar, otypes=[np.float64])(froude)


def wake_response(
    kx: ArrayLike,
    ky: ArrayLike,
    speed: float,
    depth: float,
    damping: float,
    g: float = GRAVITY,
    density: float = SEAWATER_DENSITY,
) -> NDArray[np.complex128]:
    """Steady elevation per unit surface pressure of a pressure moving along +x, η̂/p̂ [m Pa⁻¹].

    Parameters
    ----------
    kx, ky : array_like
        Wavenumber components along and across the track [rad m⁻¹], in the convention
        η(x) = ∫∫ η̂(k) e^{i k·x} dk / (2π)².
    speed : float
        Speed U of the pressure along +x [m s⁻¹].
    depth : float
        Water depth h [m]; ``np.inf`` for deep water.
    damping : float
        Rayleigh's damping rate ε [s⁻¹], > 0: the limit ε → 0⁺ is the physical wake.
    g : float, optional
        Gravitational acceleration [m s⁻²].
    density : float, optional
        Water density ρ [kg m⁻³].

    Returns
    -------
    ndarray
        η̂/p̂ = −(k tanh(k h)/ρ) / (ω² − (U k_x + i ε)²), ω² = g k tanh(k h) [m Pa⁻¹];
        0 at k = 0 (the periodic grid conserves volume), −1/(ρ g) for U → 0 (hydrostatic).

    Notes
    -----
    In the frame of the body the water streams past at −U x̂. The perturbation potential
    φ obeys ∇²φ = 0 in −h < z < 0 with ∂φ/∂z = 0 on the bed, and on z = 0 the linearised
    kinematic and dynamic (Bernoulli) conditions

        (∂/∂t − U ∂/∂x) η = ∂φ/∂z,    (∂/∂t − U ∂/∂x) φ + g η + p/ρ = 0.

    Following Rayleigh and Lamb [1], the pressure is switched on slowly, p ∝ e^{εt},
    so ∂/∂t → ε. For a Fourier mode e^{i k·x}, φ ∝ cosh k(z + h)/cosh kh gives
    ∂φ/∂z = k tanh(kh) φ on z = 0, and with s = ε − i U k_x the two conditions become
    s η̂ = k tanh(kh) φ̂ and s φ̂ + g η̂ = −p̂/ρ, whence

        η̂ = −(k tanh(kh)/ρ) p̂ / (ω² + s²) = −(k tanh(kh)/ρ) p̂ / (ω² − (U k_x + i ε)²).

    The poles ω(k) = ± U k_x are the Kelvin waves, which stand still behind the body.
    ε > 0 is the radiation condition: it moves the poles so that the waves appear
    behind the body (x < 0) and not ahead; ε < 0 would put them ahead. For finite ε the
    result is exactly the Laplace transform at s = ε of the response to the disturbance
    history, so a wave of age τ is attenuated by e^{−ετ}: Rayleigh's frictional term μ
    of [1] § 242 is μ = 2ε to first order. The response is Hermitian,
    η̂/p̂(−k) = conj(η̂/p̂(k)), so a real pressure gives a real elevation.

    References
    ----------
    .. [1] H. Lamb, Hydrodynamics, 6th ed., Cambridge University Press, 1932, §§ 242–243
       and § 256.
    .. [2] J. V. Wehausen and E. V. Laitone, "Surface waves", in Handbuch der Physik,
       vol. 9, Springer, 1960, pp. 446–778.
    .. [3] T. H. Havelock, Proc. R. Soc. Lond. A 81, 398–430, 1908, § 15,
       doi:10.1098/rspa.1908.0097 (finite depth).
    """
    kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
    omega2 = dispersion_relation(np.hypot(kx, ky), depth, g) ** 2  # ω² = g k tanh(kh)
    restoring = omega2 / g  # k tanh(kh) [rad m⁻¹]
    denominator = omega2 - (speed * kx + 1j * damping) ** 2  # ω² + s², s = ε − i U k_x
    return -(restoring / density) / denominator  # the last equation of the Notes; [1] § 256 with Rayleigh's ε


def _pair(value: ArrayLike, name: str) -> tuple[float, float]:
    """A scalar or a pair as two floats, or a ValueError naming ``name``."""
    try:
        pair = np.broadcast_to(np.asarray(value, dtype=np.float64), (2,))
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number or a pair of numbers, got {value!r}") from None
    return float(pair[0]), float(pair[1])


def _grid_layout(size: ArrayLike, resolution: ArrayLike, ahead: float):
    """Validated (lx, ly, nx, ny, n_ahead) of a wake grid."""
    lx, ly = _pair(size, "size")
    for value in (lx, ly):
        _require_positive("size", value, "m")
    nx, ny = _pair(resolution, "resolution")
    if not all(np.isfinite(n) and n == int(n) and n >= 2 for n in (nx, ny)):
        raise ValueError(f"resolution must be integers ≥ 2, got {resolution!r}")
    if not (0 <= float(ahead) < 1):
        raise ValueError(f"ahead must be a fraction in [0, 1) [-], got {ahead!r}")
    nx, ny = int(nx), int(ny)
    return lx, ly, nx, ny, int(round(ahead * nx))


def default_wake_damping(speed: float, depth: float, size: ArrayLike, ahead: float = 0.15,
                         g: float = GRAVITY) -> float:
    """Rayleigh damping ε that attenuates the waves by e^{−3} on their way to a periodic image [s⁻¹].

    Parameters
    ----------
    speed : float
        Speed U of the body [m s⁻¹].
    depth : float
        Water depth h [m]; ``np.inf`` for deep water.
    size : float or (float, float)
        Grid extent (L_x along the track, L_y across) [m].
    ahead : float, optional
        Fraction of L_x ahead of the body [-].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    float
        ε = :data:`WAKE_WRAP_EFOLDS` U / d_wrap [s⁻¹], with d_wrap = min((1 − ahead) L_x,
        L_y/(2 sin ψ_c)) the shortest path of a wave from an image of the body into the
        grid, ψ_c the cusp angle (:func:`kelvin_cusp_angle`).

    Notes
    -----
    A stationary wave moves relative to the body at c_g k̂ − U x̂, whose speed is at most
    U because c_g ≤ c = U cos θ; a wave at distance r from its source is therefore at
    least r/U old and attenuated by at least e^{−ε r/U}. The image ahead of the body is
    L_x away along the track and its wake enters the grid (1 − ahead) L_x behind it; the
    images beside it are L_y away across the track, and their waves, confined to the
    wedge |ψ| ≤ ψ_c, travel at least L_y/(2 sin ψ_c) before they cross into the grid.
    Their waves therefore reach the grid attenuated by at least e^{−3}, on top of the
    geometric decay of the wake.
    """
    lx, ly = _pair(size, "size")
    cusp = float(kelvin_cusp_angle(depth_froude_number(speed, depth, g)))
    d_wrap = min((1 - ahead) * lx, ly / (2 * np.sin(cusp)))  # shortest path from an image into the grid
    return float(WAKE_WRAP_EFOLDS * speed / d_wrap)


def kelvin_wake_spacing(source: WakeSource, speed: float, depth: float = np.inf, g: float = GRAVITY) -> float:
    """Largest grid spacing that resolves every Kelvin wave the footprint excites above 1 % [m].

    Parameters
    ----------
    source : WakeSource
        The hull.
    speed : float
        Speed U of the hull [m s⁻¹].
    depth : float, optional
        Water depth h [m]; ``np.inf`` for deep water.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    float
        Δ = π/k_max [m], k_max the wavenumber of frequency ω = 3 U/σ_x
        (:func:`~oceanrender.waves.wave_spectra.wavenumber_from_frequency`).

    Notes
    -----
    A Kelvin wave has ω(k) = U |k_x|, and the footprint's transform is below
    e^{−(k_x σ_x)²/2} ≤ e^{−4.5} once |k_x| σ_x > :data:`WAKE_SOURCE_CUTOFF` = 3; every
    wave stronger than that has ω ≤ 3 U/σ_x, so k ≤ k_max and the grid's Nyquist
    wavenumber π/Δ reaches it. In deep water Δ = π g σ_x²/(9 U²). The hull's own static
    depression is resolved only when also Δ ≲ σ_y = B/4.
    """
    omega_max = WAKE_SOURCE_CUTOFF * speed / source.widths[0]  # encounter frequency U k_x at k_x σ_x = 3
    return float(np.pi / wavenumber_from_frequency(omega_max, depth, g))


def kelvin_wake_grid(
    source: WakeSource,
    speed: float,
    depth: float,
    size: ArrayLike,
    resolution: ArrayLike,
    *,
    ahead: float = 0.15,
    damping: float | None = None,
    g: float = GRAVITY,
    density: float = SEAWATER_DENSITY,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Steady linear wake elevation η(x, y) of a moving hull on a periodic grid [m].

    Parameters
    ----------
    source : WakeSource
        The hull as a pressure patch centred at the origin.
    speed : float
        Speed U of the hull along +x [m s⁻¹]; finite, > 0.
    depth : float
        Water depth h [m]; > the draft; ``np.inf`` for deep water.
    size : float or (float, float)
        Extent (L_x along the track, L_y across) of the periodic grid [m].
    resolution : int or (int, int)
        Number of points (N_x, N_y); spacing L_x/N_x, L_y/N_y [m].
    ahead : float, optional
        Fraction of L_x lying ahead of the hull (x > 0) [-]; the rest is the wake.
    damping : float, optional
        Rayleigh damping rate ε [s⁻¹]; default :func:`default_wake_damping`. Waves of age
        τ are attenuated by e^{−ετ}, i.e. at least e^{−ε r/U} at distance r from the hull.
    g : float, optional
        Gravitational acceleration [m s⁻²].
    density : float, optional
        Water density ρ [kg m⁻³]; η does not depend on it (p ∝ ρ).

    Returns
    -------
    x : ndarray, shape (N_x,)
        Position along the track, the hull at 0 and moving towards +x [m].
    y : ndarray, shape (N_y,)
        Position across the track [m].
    eta : ndarray, shape (N_y, N_x)
        Surface elevation η[iy, ix] [m], float64, the wake trailing towards −x; its mean
        over the grid is 0.

    Raises
    ------
    ValueError
        Naming the argument, for a non-finite or non-positive speed, a depth ≤ 0 or not
        above the draft, a bad size, resolution, ahead fraction or damping.

    Notes
    -----
    η = F⁻¹[:func:`wake_response` · p̂], with p̂ the closed-form transform
    :meth:`WakeSource.pressure_spectrum` sampled on the grid's wavenumbers 2π m/L: by
    Poisson's summation the Fourier series with coefficients p̂ η̂/p̂ / (L_x L_y) is the
    sum of the wake and all its periodic images, low-passed at the grid's Nyquist
    wavenumber π/Δ, without aliasing of the footprint. Two errors remain:

    * **Wrap-around.** Images of the hull are L_x and L_y away; the default damping
      attenuates their waves by at least e^{−3} before they reach the grid (on top of the
      r^{−1/3} … r^{−1/2} geometric decay of a Kelvin wake), and the wake near the hull,
      where it is largest, by far more.
    * **Damping.** The wake itself fades behind the hull: transverse waves (relative
      speed U/2 in deep water) by e^{−2εr/U}, short diverging waves by ≈ e^{−εr/U}.

    The zero wavenumber is dropped, so the grid's mean elevation is 0: the static
    depression's volume (:attr:`WakeSource.displaced_volume`) is spread over the grid as
    a uniform rise of V/(L_x L_y). The spacing should resolve the waves the footprint
    excites: :func:`kelvin_wake_spacing` gives the largest that does.

    References
    ----------
    .. [1] H. Lamb, Hydrodynamics, 6th ed., Cambridge University Press, 1932, § 256.
    .. [2] J. V. Wehausen and E. V. Laitone, "Surface waves", in Handbuch der Physik,
       vol. 9, Springer, 1960, pp. 446–778.
    """
    speed = float(speed)
    if not (np.isfinite(speed) and speed > 0):
        raise ValueError(f"speed must be a finite positive speed [m s⁻¹], got {speed!r}")
    depth = _require_positive("depth", depth, "m", allow_inf=True)
    if depth <= source.draft:
        raise ValueError(f"depth must exceed the draft {source.draft!r} m, got {depth!r}")
    lx, ly, nx, ny, n_ahead = _grid_layout(size, resolution, ahead)
    if damping is None:
        damping = default_wake_damping(speed, depth, (lx, ly), n_ahead / nx, g)
    damping = _require_positive("damping", damping, "s⁻¹")

    dx, dy = lx / nx, ly / ny
    x = dx * (np.arange(nx) - (nx - n_ahead))  # hull at index nx − n_ahead
    y = dy * (np.arange(ny) - ny // 2)  # hull at index ny // 2
    kx = 2 * np.pi * scipy.fft.rfftfreq(nx, dx)  # kx ≥ 0: η is real, the rest is Hermitian
    ky = 2 * np.pi * scipy.fft.fftfreq(ny, dy)[:, None]
    p_hat = source.pressure_spectrum(kx, ky, g, density)  # [Pa m²]
    eta_hat = wake_response(kx, ky, speed, depth, damping, g, density) * p_hat  # [m³]
    # Fourier-series coefficients F(k)/(L_x L_y) (Poisson), shifted to the grid's first point
    coefficients = eta_hat / (lx * ly) * np.exp(1j * (kx * x[0] + ky * y[0]))
    eta = scipy.fft.irfft2(coefficients * (nx * ny), s=(ny, nx))
    return x, y, np.ascontiguousarray(eta, dtype=np.float64)
