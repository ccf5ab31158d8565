"""Open sea as a finite sum of waves: sum of sines and Gerstner (trochoidal) waves.

The alternatives to the FFT ocean of :mod:`oceanrender.waves.fft_ocean`.
A sea is a set of :class:`WaveComponent` (amplitude a [m], wavevector k
[rad m⁻¹], phase φ [rad]); each component runs along +k with the angular
frequency ω(|k|) of :func:`oceanrender.waves.wave_spectra.dispersion_relation`,
the same dispersion relation as the FFT ocean. Its phase at the point x and
time t is

    θ_i(x, t) = k_i·x − ω_i t + φ_i.

* :func:`sum_of_sines_fields` is the height field η = Σ a_i cos θ_i.
* :func:`gerstner_fields` moves each surface point x also horizontally, by
  −Σ Q_i a_i k̂_i sin θ_i: Gerstner's trochoidal wave [1] in the form used in
  computer graphics [2]–[4]; the crests sharpen and the troughs flatten.

Both evaluate at arbitrary points (grids or scattered points: x and y
broadcast against each other) and return :class:`OceanFields`, the FFT
ocean's result type, so the mesh and renderer take either.

:func:`wave_components_from_spectrum` draws the components from a directional
wavenumber spectrum Ψ(kx, ky) [m⁴] so that Σ a_i²/2, the elevation variance of
the sum, equals ∫∫ Ψ dkx dky over the sampled band: the finite sum has the
same sea state, in metres, as the FFT ocean drawn from the same spectrum.

References
----------
.. [1] F. J. Gerstner, "Theorie der Wellen", Abhandlungen der Königlichen
   Böhmischen Gesellschaft der Wissenschaften, Prague, 1802.
.. [2] A. Fournier and W. T. Reeves, "A simple model of ocean waves",
   Computer Graphics (Proc. SIGGRAPH '86) 20(4), 75–84, 1986,
   doi:10.1145/15886.15894.
.. [3] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes
   (Course 47), 2001, section "Gerstner Waves".
.. [4] M. Finch, "Effective Water Simulation from Physical Models", in
   R. Fernando (ed.), GPU Gems, ch. 1, Addison-Wesley, 2004, section
   "Gerstner Waves".
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .fft_ocean import OceanFields
from .wave_spectra import GRAVITY, dispersion_relation

__all__ = [
    "WaveComponent",
    "wave_components_from_spectrum",
    "wave_components_variance",
    "sum_of_sines_fields",
    "steepness_Finch2004",
    "steepness_Tessendorf2001",
    "GERSTNER_STEEPNESS",
    "gerstner_fields",
]

#: Elements of the (points × components) phase array evaluated at once; bounds memory (≈ 16 MiB per array).
_BLOCK_ELEMENTS = 1 << 21

# NOTE: OceanFields gained optional Jacobian-matrix entries (for summing cascades) while this
# module was written; fill them when the class has them, so both versions work.
_HAS_JACOBIAN_MATRIX = "jacobian_xx" in {field.name for field in fields(OceanFields)}


def _ocean_fields(height, dx, dy, slope_x, slope_y, jxx, jyy, jxy, jacobian, normals) -> OceanFields:
    matrix = dict(jacobian_xx=jxx, jacobian_yy=jyy, jacobian_xy=jxy) if _HAS_JACOBIAN_MATRIX else {}
    return OceanFields(height, dx, dy, slope_x, slope_y, jacobian, normals, **matrix)


@dataclass(frozen=True)
class WaveComponent:
    """One progressive wave of the sum: η_i = a cos(k·x − ω(|k|) t + φ).

    Parameters
    ----------
    amplitude : float
        Amplitude a, half the crest-to-trough height [m]; ≥ 0.
    wavenumber_x, wavenumber_y : float
        Wavevector k; the wave runs along +k [rad m⁻¹]; |k| > 0.
    phase : float, optional
        Phase φ at x = 0, t = 0 [rad].
    """

    amplitude: float
    wavenumber_x: float
    wavenumber_y: float
    phase: float = 0.0

    def __post_init__(self) -> None:
        values = (self.amplitude, self.wavenumber_x, self.wavenumber_y, self.phase)
        if not all(np.isfinite(values)):
            raise ValueError(f"wave component values must be finite, got {values!r}")
        if self.amplitude < 0:
            raise ValueError(f"amplitude must be ≥ 0 [m], got {self.amplitude!r}")
        if self.wavenumber == 0:
            raise ValueError("the wavevector must not be zero [rad m⁻¹]")

    @property
    def wavenumber(self) -> float:
        """|k| [rad m⁻¹]."""
        return float(np.hypot(self.wavenumber_x, self.wavenumber_y))

    @property
    def wavelength(self) -> float:
        """2π/|k| [m]."""
        return 2 * np.pi / self.wavenumber

    @property
    def direction(self) -> float:
        """Direction of travel, counter-clockwise from +x [rad]."""
        return float(np.arctan2(self.wavenumber_y, self.wavenumber_x))

    def angular_frequency(self, depth: float = np.inf, g: float = GRAVITY) -> float:
        """ω(|k|) of :func:`~oceanrender.waves.wave_spectra.dispersion_relation` [rad s⁻¹]."""
        return float(dispersion_relation(self.wavenumber, depth, g))


def _divisor_near_sqrt(count: int) -> int:
    """The largest divisor of ``count`` not above √count."""
    return max(d for d in range(1, int(np.sqrt(count)) + 1) if count % d == 0)


def wave_components_from_spectrum(
    spectrum: Callable[[NDArray, NDArray], ArrayLike],
    count: int,
    seed: int | None,
    k_min: float,
    k_max: float,
    directions: int | None = None,
    jitter: bool = True,
    patch_size: float | None = None,
) -> tuple[WaveComponent, ...]:
    """Draw wave components from a directional wavenumber spectrum, in physical units.

    Parameters
    ----------
    spectrum : callable
        Ψ(kx, ky) [m⁴], vectorised over arrays of kx, ky [rad m⁻¹], e.g.
        ``lambda kx, ky: wave_spectrum("Phillips 2001", kx, ky, wind_speed=8.0, wind_direction=0.3)``.
    count : int
        Number of components.
    seed : int or None
        Seed of ``np.random.default_rng``: positions within the cells and phases.
    k_min, k_max : float
        Band of wavenumber magnitudes sampled, 0 < k_min < k_max [rad m⁻¹].
    directions : int, optional
        Number of direction strata n_θ; must divide ``count``. Default: the
        largest divisor of ``count`` not above √count (16 × 16 for 256,
        8 directions × 16 bands for 128; a prime count gets one stratum).
    jitter : bool, optional
        True (default): one uniformly random point per cell (stratified Monte
        Carlo, unbiased); False: the cell centres (midpoint rule; only the
        phases are random).
    patch_size : float, optional
        Side L of a periodic patch [m]. When given, every wavevector is moved
        to the nearest lattice point 2π n/L, so the sea tiles with period L as
        the FFT ocean does; needs k_min ≥ 2π/L. The amplitudes are kept, so
        Σ a_i²/2 is unchanged, but each k moves by up to π√2/L (ω follows the
        moved k), and components landing on the same lattice point add
        coherently (their sum's variance is then right only on average).

    Returns
    -------
    tuple of WaveComponent
        ``count`` components; ordered by wavenumber band, then direction.

    Notes
    -----
    The band is cut into n_k = count/n_θ equal intervals of ln k and n_θ equal
    sectors of direction θ ∈ [−π, π), and one component is placed in each cell
    at (ln k_i, θ_i). Since dkx dky = k dk dθ = k² d(ln k) dθ, the cell's
    share of the plane at that point is ΔA_i = k_i² Δ(ln k) Δθ, and

        a_i = √(2 Ψ(k_i) ΔA_i),   φ_i ~ U[0, 2π),

    so that Σ a_i²/2 = Σ Ψ(k_i) ΔA_i: with jitter, an unbiased stratified
    Monte Carlo estimate of m0 = ∫∫ Ψ dkx dky over k_min ≤ |k| < k_max (error
    O(1/count) for a smooth Ψ, against O(1/√count) without strata: 2.6 % rms
    for 256 components of a Phillips sea over 2.7 decades of k, 0.6 % for
    1024); without, its midpoint-rule quadrature. The mean of cos²(θ + φ) over the random
    phase is 1/2, so the expected spatial variance of η is Σ a_i²/2 — the
    same Parseval bookkeeping as :func:`~oceanrender.waves.fft_ocean.initial_amplitudes`.
    Sampling ln k rather than k spends the components evenly per octave, as
    the sea's variance spreads over decades of k (Fréchot [1] discusses how to
    sample a spectrum for Gerstner waves).

    A two-sided spectrum (Ψ(−k) = Ψ(k), as Tessendorf's Phillips spectrum)
    gives waves running both with and against the wind, as in the FFT ocean.

    References
    ----------
    .. [1] J. Fréchot, "Realistic simulation of ocean surface using wave
       spectra", Journal of Virtual Reality and Broadcasting, 2007
       (https://www.jvrb.org/archiv/1229); first at GRAPP 2006.
    """
    count = int(count)
    if count < 1:
        raise ValueError(f"count must be ≥ 1, got {count}")
    if not (np.isfinite(k_min) and np.isfinite(k_max) and 0 < k_min < k_max):
        raise ValueError(f"expected 0 < k_min < k_max [rad m⁻¹], got {k_min!r}, {k_max!r}")
    n_theta = _divisor_near_sqrt(count) if directions is None else int(directions)
    if n_theta < 1 or count % n_theta:
        raise ValueError(f"directions must divide count = {count}, got {directions!r}")
    if patch_size is not None and not (np.isfinite(patch_size) and k_min * patch_size >= 2 * np.pi):
        raise ValueError(f"with patch_size L, k_min must be ≥ 2π/L; got L = {patch_size!r}, k_min = {k_min!r}")
    n_k = count // n_theta
    rng = np.random.default_rng(seed)
    phases = rng.uniform(0, 2 * np.pi, count)
    offsets = rng.random((2, n_k, n_theta)) if jitter else np.full((2, n_k, n_theta), 0.5)
    d_ln_k = np.log(k_max / k_min) / n_k
    d_theta = 2 * np.pi / n_theta
    ln_k = np.log(k_min) + d_ln_k * (np.arange(n_k)[:, None] + offsets[0])
    theta = -np.pi + d_theta * (np.arange(n_theta)[None, :] + offsets[1])
    k = np.exp(ln_k).ravel()
    kx, ky = k * np.cos(theta.ravel()), k * np.sin(theta.ravel())
    psi = np.broadcast_to(np.asarray(spectrum(kx, ky), dtype=np.float64), kx.shape)
    if not np.all(np.isfinite(psi) & (psi >= 0)):
        raise ValueError("the spectrum must be finite and non-negative [m⁴] on the sampled band")
    amplitude = np.sqrt(2 * psi * k**2 * d_ln_k * d_theta)  # a_i = √(2 Ψ ΔA_i), ΔA_i = k_i² Δln k Δθ
    if patch_size is not None:
        dk = 2 * np.pi / patch_size
        kx, ky = dk * np.rint(kx / dk), dk * np.rint(ky / dk)
    return tuple(WaveComponent(*values) for values in zip(amplitude.tolist(), kx.tolist(), ky.tolist(),
                                                          phases.tolist()))


def wave_components_variance(components: Sequence[WaveComponent]) -> float:
    """Elevation variance of a sum of waves with independent phases, Σ a_i²/2 [m²].

    Hs = 4 √(Σ a_i²/2) is the significant wave height of the sum.
    """
    return float(sum(c.amplitude**2 for c in components) / 2)


def _component_arrays(components: Sequence[WaveComponent], t: float, depth: float, g: float):
    """a, kx, ky, |k| and the phase φ − ω t reduced to [0, 2π), as float64 arrays."""
    a = np.array([c.amplitude for c in components], dtype=np.float64)
    kx = np.array([c.wavenumber_x for c in components], dtype=np.float64)
    ky = np.array([c.wavenumber_y for c in components], dtype=np.float64)
    phi = np.array([c.phase for c in components], dtype=np.float64)
    k = np.hypot(kx, ky)
    omega = dispersion_relation(k, depth, g)
    # NOTE: reduced before it meets k·x, so a large ωt costs no precision there
    offset = np.mod(phi - omega * t, 2 * np.pi)
    return a, kx, ky, k, offset


def _points(x: ArrayLike, y: ArrayLike) -> tuple[NDArray, NDArray, tuple[int, ...]]:
    x, y = np.broadcast_arrays(np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64))
    return x.ravel(), y.ravel(), x.shape


def _wave_sums(x, y, kx, ky, offset, cos_weights, sin_weights):
    """Σ_i w_i cos θ_i for each row of ``cos_weights`` and likewise for sin, at every point.

    Returns two arrays of shape (len(cos_weights), P) and (len(sin_weights), P).
    """
    n_points = x.size
    cos_sums = np.zeros((len(cos_weights), n_points))
    sin_sums = np.zeros((len(sin_weights), n_points))
    if kx.size == 0 or n_points == 0:
        return cos_sums, sin_sums
    cos_w, sin_w = np.asarray(cos_weights).T, np.asarray(sin_weights).T  # (M, fields)
    block = max(1, _BLOCK_ELEMENTS // kx.size)
    for start in range(0, n_points, block):
        part = slice(start, start + block)
        theta = np.multiply.outer(x[part], kx)
        theta += np.multiply.outer(y[part], ky)
        theta += offset  # θ_i = k_i·x − ω_i t + φ_i
        cos_sums[:, part] = (np.cos(theta) @ cos_w).T
        sin_sums[:, part] = (np.sin(theta) @ sin_w).T
    return cos_sums, sin_sums


def _unit_normals(jxx, jyy, jxy, slope_x, slope_y, jacobian) -> NDArray[np.float64]:
    """Unit ∂P/∂x × ∂P/∂y of P = (x + Dx, y + Dy, η), shape (..., 3); z has the sign of J.

    Where the product vanishes (the cusp of a trochoid with Q k a = 1 exactly)
    the normal is undefined; (0, 0, 1) is returned there, never NaN.
    """
    normal = np.stack([jxy * slope_y - jyy * slope_x, jxy * slope_x - jxx * slope_y, jacobian], axis=-1)
    length = np.linalg.norm(normal, axis=-1, keepdims=True)
    # NOTE: the mesh passes these normals to the renderer as they are: no NaN at a cusp
    cusp = length[..., 0] == 0
    if np.any(cusp):
        normal[cusp], length[cusp] = (0.0, 0.0, 1.0), 1.0
    return normal / length


def sum_of_sines_fields(
    components: Sequence[WaveComponent],
    x: ArrayLike,
    y: ArrayLike,
    t: float,
    depth: float = np.inf,
    g: float = GRAVITY,
) -> OceanFields:
    """Height field of a sum of sines η = Σ a_i cos(k_i·x − ω_i t + φ_i) and its slopes and normals.

    Parameters
    ----------
    components : sequence of WaveComponent
        The waves.
    x, y : array_like
        East and north coordinates of the points [m]; broadcast together to the
        shape S of the result (a grid from ``np.meshgrid`` or scattered points).
    t : float
        Time [s].
    depth : float, optional
        Water depth in the dispersion relation [m]; ``np.inf`` for deep water.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    OceanFields
        Arrays of shape S (normals S + (3,)): η [m]; no horizontal
        displacement (zeros) and Jacobian 1; analytic slopes
        ∂η/∂x = −Σ a_i k_x,i sin θ_i, ∂η/∂y = −Σ a_i k_y,i sin θ_i [-];
        unit normals (−∂η/∂x, −∂η/∂y, 1)/‖·‖, always pointing up. The
        constant fields (displacements, Jacobian) share one read-only array each.

    Notes
    -----
    Each component travels at the phase speed ω_i/|k_i| along +k_i. The sea is
    periodic only if every k_i is on a lattice 2π n/L (see ``patch_size`` of
    :func:`wave_components_from_spectrum`). Cost: O(points × components).

    References
    ----------
    .. [1] M. Finch, "Effective Water Simulation from Physical Models", GPU Gems,
       ch. 1, 2004, section "The Sum of Sines Approximation".
    """
    xs, ys, shape = _points(x, y)
    a, kx, ky, _, offset = _component_arrays(components, t, depth, g)
    (height,), (minus_slope_x, minus_slope_y) = _wave_sums(xs, ys, kx, ky, offset, [a], [a * kx, a * ky])
    height, slope_x, slope_y = height.reshape(shape), -minus_slope_x.reshape(shape), -minus_slope_y.reshape(shape)
    zeros, ones = np.zeros(shape), np.ones(shape)
    zeros.flags.writeable = ones.flags.writeable = False
    normals = _unit_normals(ones, ones, zeros, slope_x, slope_y, ones)
    return _ocean_fields(height, zeros, zeros, slope_x, slope_y, ones, ones, zeros, ones, normals)


def steepness_Finch2004(amplitude: ArrayLike, wavenumber: ArrayLike, steepness: float) -> NDArray[np.float64]:
    """Per-wave steepness factors Q_i = q/(k_i a_i N) of Finch (2004) [-].

    Parameters
    ----------
    amplitude : array_like
        a_i [m].
    wavenumber : array_like
        |k_i| [rad m⁻¹].
    steepness : float
        Global steepness q ∈ [0, 1] [-]; q = 1 is the sharpest sea that cannot loop.

    Returns
    -------
    ndarray
        Q_i [-]; 0 for components of zero amplitude, which do not count in N.

    Notes
    -----
    Finch writes Q_i = Q/(w_i A_i × numWaves) with w_i the spatial frequency,
    here |k_i|. Every wave then has Q_i k_i a_i = q/N, so the horizontal map has
    J ≥ 1 − q everywhere (see :func:`gerstner_fields`): no loops for q ≤ 1,
    whatever the phases. The horizontal amplitude Q_i a_i = q/(N k_i) does not
    depend on a_i: long waves move the surface sideways most. Meant for a
    handful of chosen waves; with many components each one's choppiness is
    divided by N, so the sea looks nearly sinusoidal.

    References
    ----------
    .. [1] M. Finch, "Effective Water Simulation from Physical Models", GPU Gems,
       ch. 1, 2004, section "Gerstner Waves".
    """
    a, k = np.asarray(amplitude, dtype=np.float64), np.asarray(wavenumber, dtype=np.float64)
    waves = a > 0
    n = max(int(np.count_nonzero(waves)), 1)
    return np.where(waves, steepness / (np.where(waves, k * a, 1.0) * n), 0.0)  # Q_i = q/(k_i a_i N), [1]


def steepness_Tessendorf2001(amplitude: ArrayLike, wavenumber: ArrayLike, steepness: float) -> NDArray[np.float64]:
    """Per-wave steepness factors Q_i = q, the same for every wave [-].

    Parameters
    ----------
    amplitude : array_like
        a_i [m] (sets the shape of the result only).
    wavenumber : array_like
        |k_i| [rad m⁻¹] (unused).
    steepness : float
        q [-]; q = 1 is Gerstner's trochoid: each surface particle circles with
        radius a_i for each wave.

    Notes
    -----
    Tessendorf's Gerstner waves x = x₀ − Σ (k_i/k_i) A_i sin(k_i·x₀ − ω_i t + φ_i)
    are q = 1; q plays the role of the FFT ocean's choppiness λ. The horizontal
    amplitude q a_i is proportional to the wave's own amplitude, so the
    spectrum sets the choppiness of each scale; the surface loops (J < 0)
    where the local steepness Σ q k_i a_i cos θ_i (along a direction) exceeds 1,
    e.g. for one wave where q k a > 1.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       section "Gerstner Waves".
    """
    return np.full(np.shape(amplitude), float(steepness))  # Q_i = q; q = 1 in [1]


GERSTNER_STEEPNESS: dict[str, Callable[..., NDArray[np.float64]]] = {
    "Finch 2004": steepness_Finch2004,
    "Tessendorf 2001": steepness_Tessendorf2001,
}
"""Normalisations of the Gerstner steepness, Q_i(a_i, |k_i|, q), by method name."""


def gerstner_fields(
    components: Sequence[WaveComponent],
    x: ArrayLike,
    y: ArrayLike,
    t: float,
    depth: float = np.inf,
    steepness: float = 1.0,
    normalisation: str = "Finch 2004",
    g: float = GRAVITY,
) -> OceanFields:
    """Gerstner (trochoidal) waves: elevation, horizontal displacement, slopes, Jacobian, normals.

    The surface point labelled by its rest position x = (x, y) is at

        P(x, t) = (x − Σ Q_i a_i (k_x,i/k_i) sin θ_i,
                   y − Σ Q_i a_i (k_y,i/k_i) sin θ_i,
                   Σ a_i cos θ_i),   θ_i = k_i·x − ω_i t + φ_i.

    Parameters
    ----------
    components : sequence of WaveComponent
        The waves.
    x, y : array_like
        Rest positions [m]; broadcast together to the shape S of the result.
    t : float
        Time [s].
    depth : float, optional
        Water depth in the dispersion relation [m]; ``np.inf`` for deep water.
    steepness : float, optional
        Global steepness q ≥ 0 [-]; q = 0 is :func:`sum_of_sines_fields`.
    normalisation : str, optional
        How q becomes the per-wave Q_i, a key of :data:`GERSTNER_STEEPNESS`:
        ``"Finch 2004"`` (Q_i = q/(k_i a_i N), loop-free for q ≤ 1) or
        ``"Tessendorf 2001"`` (Q_i = q, the trochoid at q = 1).
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    OceanFields
        Arrays of shape S (normals S + (3,)): η [m], displacement D [m],
        slopes ∂η/∂x, ∂η/∂y with respect to the rest position [-], Jacobian J
        of x ↦ x + D [-] and unit normals of the displaced surface, z with the
        sign of J — the conventions of the FFT ocean's fields.

    Notes
    -----
    Analytic derivatives (k̂_i = k_i/|k_i|, c_i = cos θ_i, s_i = sin θ_i):

        ∂η/∂x = −Σ a_i k_x,i s_i,   ∂Dx/∂x = −Σ Q_i a_i k_x,i²/k_i c_i,
        ∂Dy/∂y = −Σ Q_i a_i k_y,i²/k_i c_i,   ∂Dx/∂y = ∂Dy/∂x = −Σ Q_i a_i k_x,i k_y,i/k_i c_i,

    J = (1 + ∂Dx/∂x)(1 + ∂Dy/∂y) − (∂Dx/∂y)². For one wave
    J = 1 − Q k a cos θ: the crests (θ = 0) are compressed, and the surface
    loops there once Q k a > 1. In general I + ∇D = I − Σ Q_i k_i a_i c_i k̂_i k̂_iᵀ
    has eigenvalues ≥ 1 − Σ Q_i k_i a_i, so with Finch's normalisation J ≥ 1 − q.
    The normal is ∂P/∂x × ∂P/∂y, exact; Finch's closed form for it evaluates
    the sums at the displaced point, an approximation.

    Sign convention: this is Tessendorf's x₀ − k̂ A sin θ (with η = A cos θ) and
    Finch's +Q A D cos(·) with η = A sin(·), shifted by a quarter period; both
    sharpen the crests. (Fournier & Reeves [2] build the same trochoidal
    orbits from a rolling-circle construction.)

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       section "Gerstner Waves".
    .. [2] A. Fournier and W. T. Reeves, "A simple model of ocean waves",
       Computer Graphics (Proc. SIGGRAPH '86) 20(4), 75–84, 1986.
    .. [3] M. Finch, "Effective Water Simulation from Physical Models", GPU Gems,
       ch. 1, 2004, section "Gerstner Waves".
    """
    if normalisation not in GERSTNER_STEEPNESS:
        known = ", ".join(map(repr, GERSTNER_STEEPNESS))
        raise ValueError(f"unknown Gerstner steepness normalisation {normalisation!r}; known: {known}")
    if not (np.isfinite(steepness) and steepness >= 0):
        raise ValueError(f"steepness must be finite and ≥ 0, got {steepness!r}")
    xs, ys, shape = _points(x, y)
    a, kx, ky, k, offset = _component_arrays(components, t, depth, g)
    q = GERSTNER_STEEPNESS[normalisation](a, k, steepness)
    qa = q * a
    ux, uy = (kx / k, ky / k) if k.size else (k, k)
    cos_sums, sin_sums = _wave_sums(
        xs, ys, kx, ky, offset,
        [a, qa * kx * ux, qa * ky * uy, qa * kx * uy],  # η; −∂Dx/∂x, −∂Dy/∂y, −∂Dx/∂y
        [a * kx, a * ky, qa * ux, qa * uy],  # −∂η/∂x, −∂η/∂y; −Dx, −Dy
    )
    height, dxx, dyy, dxy = cos_sums.reshape(4, *shape)
    minus_sx, minus_sy, minus_dx, minus_dy = sin_sums.reshape(4, *shape)
    slope_x, slope_y = -minus_sx, -minus_sy
    jxx, jyy, jxy = 1 - dxx, 1 - dyy, -dxy
    jacobian = jxx * jyy - jxy * jxy
    normals = _unit_normals(jxx, jyy, jxy, slope_x, slope_y, jacobian)
    return _ocean_fields(height.copy(), -minus_dx, -minus_dy, slope_x, slope_y, jxx, jyy, jxy, jacobian, normals)
