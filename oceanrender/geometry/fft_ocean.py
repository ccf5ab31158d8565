"""Tessendorf's FFT ocean in physical units.

A periodic square patch of side L [m] sampled on N × N points carries the
surface elevation η(x, t) = Σ_k h̃(k, t) exp(i k·x) [m], with k on the lattice
2π n / L [rad m⁻¹]. The amplitudes are drawn from a directional wavenumber
spectrum Ψ [m⁴] (see :mod:`oceanrender.geometry.spectra`) so that the expected
elevation variance is Σ_k Ψ(k) Δk², the band-limited m0 of the spectrum.

Array layout: every (N, N) array is indexed ``[iy, ix]`` (row = y = north,
column = x = east), as ``np.meshgrid(x, y, indexing="xy")``; spectral arrays
use numpy's FFT ordering along both axes.

The pieces are pure functions (:func:`initial_amplitudes`,
:func:`time_amplitudes`, :func:`ocean_fields`); :class:`FFTOcean` only ties
them to a set of parameters and caches what does not depend on time.

Equation numbers refer to the 2001 course notes [1].

References
----------
.. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes
   (Course 47), 2001.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.fft
from numpy.typing import ArrayLike, DTypeLike, NDArray

from .spectra import GRAVITY, PHILLIPS_ALPHA, SPECTRA, dispersion_relation, wave_spectrum

__all__ = [
    "OceanGrid",
    "OceanFields",
    "initial_amplitudes",
    "elevation_variance",
    "negate_wavenumber",
    "time_amplitudes",
    "ocean_fields",
    "FFTOcean",
]


def _read_only(array: NDArray) -> NDArray:
    array.flags.writeable = False
    return array


@dataclass(frozen=True)
class OceanGrid:
    """A periodic square patch sampled on N × N points and its wavenumber lattice.

    Parameters
    ----------
    resolution : int
        Number of grid points N per side [-].
    patch_size : float
        Side L of the periodic patch [m].

    Notes
    -----
    The points are x_i = −L/2 + i L/N, i = 0 … N−1 (likewise y); the
    wavenumbers are k = 2π n / L with n in numpy FFT order. For even N the
    Nyquist row and column (n = N/2) have no distinct partner −k and are
    excluded by :attr:`mode_mask`, as is k = 0 (the mean level).

    Array-valued properties are computed once per grid and are read-only.
    """

    resolution: int
    patch_size: float

    def __post_init__(self) -> None:
        if int(self.resolution) != self.resolution or self.resolution < 2:
            raise ValueError(f"resolution must be an integer ≥ 2, got {self.resolution!r}")
        if not (np.isfinite(self.patch_size) and self.patch_size > 0):
            raise ValueError(f"patch_size must be a positive length [m], got {self.patch_size!r}")

    @property
    def dk(self) -> float:
        """Lattice spacing of the wavenumbers Δk = 2π/L [rad m⁻¹]."""
        return 2 * np.pi / self.patch_size

    @property
    def spacing(self) -> float:
        """Distance between neighbouring grid points L/N [m]."""
        return self.patch_size / self.resolution

    @cached_property
    def indices(self) -> NDArray[np.int64]:
        """Signed integer wavenumber indices n in FFT order, shape (N,) [-]."""
        n = self.resolution
        return _read_only(np.fft.fftfreq(n, 1.0 / n).round().astype(np.int64))

    @cached_property
    def kx(self) -> NDArray[np.float64]:
        """x component of the wavenumber, shape (N, N), FFT order [rad m⁻¹]."""
        return _read_only(np.broadcast_to(self.dk * self.indices, (self.resolution,) * 2).copy())

    @cached_property
    def ky(self) -> NDArray[np.float64]:
        """y component of the wavenumber, shape (N, N), FFT order [rad m⁻¹]."""
        return _read_only(np.ascontiguousarray(self.kx.T))

    @cached_property
    def k(self) -> NDArray[np.float64]:
        """Wavenumber magnitude |k|, shape (N, N) [rad m⁻¹]."""
        return _read_only(np.hypot(self.kx, self.ky))

    @cached_property
    def mode_mask(self) -> NDArray[np.bool_]:
        """True for the modes that carry waves: not k = 0, not a Nyquist row/column."""
        n = self.resolution
        # NOTE: numpy's FFT order stores the Nyquist index N/2 as −N/2, at position N/2
        nyquist = (np.arange(n) == n // 2) & (n % 2 == 0)
        mask = ~(nyquist[None, :] | nyquist[:, None])
        mask[0, 0] = False
        return _read_only(mask)

    @cached_property
    def coordinates(self) -> NDArray[np.float64]:
        """Grid point coordinates along one axis, −L/2 + i L/N, shape (N,) [m]."""
        return _read_only(-self.patch_size / 2 + self.spacing * np.arange(self.resolution))

    @cached_property
    def x(self) -> NDArray[np.float64]:
        """x (east) coordinate of the grid points, shape (N, N) [m]."""
        return _read_only(np.broadcast_to(self.coordinates, (self.resolution,) * 2).copy())

    @cached_property
    def y(self) -> NDArray[np.float64]:
        """y (north) coordinate of the grid points, shape (N, N) [m]."""
        return _read_only(np.ascontiguousarray(self.x.T))

    @cached_property
    def origin_sign(self) -> NDArray[np.float64]:
        """exp(i k·x₀) = (−1)^(nx+ny) for the first grid point x₀ = (−L/2, −L/2) [-].

        Multiplying a spectrum by it before the inverse FFT evaluates
        Σ c_k exp(i k·x) at the grid points x_i rather than at i L/N.
        """
        parity = (self.indices[None, :] + self.indices[:, None]) % 2
        return _read_only(1.0 - 2.0 * parity)

    @cached_property
    def spectral_operators(self) -> NDArray[np.complex128]:
        """Packed spectral multipliers used by :func:`ocean_fields`, shape (4, N, N) [-]."""
        # NOTE: 4 N² complex values (64 MiB at 1024²) that depend on the grid only,
        # kept on the immutable grid rather than in a module-level cache.
        return _read_only(_spectral_operators(self))

    @cached_property
    def spectral_operators_complex64(self) -> NDArray[np.complex64]:
        """:attr:`spectral_operators` in single precision, shape (4, N, N) [-]."""
        return _read_only(self.spectral_operators.astype(np.complex64))


@dataclass(frozen=True, eq=False)
class OceanFields:
    """Surface fields of the FFT ocean at one time, each sampled on the N × N grid.

    Attributes
    ----------
    height : ndarray, shape (N, N)
        Elevation η above the mean level [m].
    displacement_x, displacement_y : ndarray, shape (N, N)
        Horizontal displacement λ D of the surface point [m] (λ included).
    slope_x, slope_y : ndarray, shape (N, N)
        ∂η/∂x, ∂η/∂y with respect to the undisplaced grid coordinates [-].
    jacobian : ndarray, shape (N, N)
        Determinant J of the horizontal map x ↦ x + λ D [-]; J < 0 where the
        surface folds over itself (Tessendorf's whitecap indicator).
    normals : ndarray, shape (N, N, 3)
        Unit normal (x, y, z) of the displaced surface [-]; its z component
        has the sign of ``jacobian``, so it points up wherever the surface is
        not folded.
    """

    height: NDArray[np.float64]
    displacement_x: NDArray[np.float64]
    displacement_y: NDArray[np.float64]
    slope_x: NDArray[np.float64]
    slope_y: NDArray[np.float64]
    jacobian: NDArray[np.float64]
    normals: NDArray[np.float64]

    @property
    def resolution(self) -> int:
        """Number of grid points N per side [-]."""
        return self.height.shape[0]


def initial_amplitudes(grid: OceanGrid, spectrum_values: ArrayLike, seed: int | None) -> NDArray[np.complex128]:
    """Random Fourier amplitudes h̃₀(k) of the surface at t = 0 [m].

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    spectrum_values : array_like, shape (N, N)
        Directional wavenumber spectrum Ψ on ``grid.kx, grid.ky`` [m⁴].
    seed : int or None
        Seed of ``np.random.default_rng``; the same seed gives the same amplitudes.

    Returns
    -------
    ndarray, complex128, shape (N, N)
        h̃₀ in FFT order [m]; zero at k = 0 and on the Nyquist row and column.

    Notes
    -----
    h̃₀(k) = (ξ_r + i ξ_i) √(Ψ(k) Δk² / 4) with ξ standard normal, i.e.
    Tessendorf's eq. 25 with P_h(k) = Ψ(k) Δk² / 2. Normalisation: with
    h̃(k, t) of eq. 26, E|h̃₀(k)|² = Ψ(k) Δk²/2 and h̃₀(k), h̃₀(−k) are
    independent, so E|h̃(k, t)|² = (Ψ(k) + Ψ(−k)) Δk²/2 for every t, and by
    Parseval the spatial variance of η is Σ_k |h̃(k, t)|², whose expectation is
    Σ_k Ψ(k) Δk² over the kept modes (:func:`elevation_variance`), the
    discrete form of m0 = ∫∫ Ψ dkx dky.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes, eqs. 25–26.
    """
    psi = np.asarray(spectrum_values, dtype=np.float64)
    if psi.shape != (grid.resolution,) * 2:
        raise ValueError(f"spectrum_values must have shape {(grid.resolution,) * 2}, got {psi.shape}")
    if not np.all(np.isfinite(psi) & (psi >= 0)):
        raise ValueError("spectrum_values must be finite and non-negative [m⁴]")
    xi = np.random.default_rng(seed).standard_normal((2, *psi.shape))
    amplitude = np.sqrt(psi * grid.dk**2 / 4) * grid.mode_mask  # P_h = Ψ Δk²/2 in eq. 25 of [1]
    return (xi[0] + 1j * xi[1]) * amplitude  # Eq. 25 of [1]


def elevation_variance(grid: OceanGrid, spectrum_values: ArrayLike) -> float:
    """Expected elevation variance of the FFT ocean, Σ_k Ψ(k) Δk² over the kept modes [m²].

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    spectrum_values : array_like, shape (N, N)
        Directional wavenumber spectrum Ψ on ``grid.kx, grid.ky`` [m⁴].

    Returns
    -------
    float
        Band-limited m0 [m²]; Hs = 4 √m0.
    """
    return float(np.sum(np.asarray(spectrum_values) * grid.mode_mask) * grid.dk**2)


def negate_wavenumber(spectrum: NDArray) -> NDArray:
    """The array at −k, a(−k), for arrays in numpy FFT order on the last two axes."""
    return np.roll(spectrum[..., ::-1, ::-1], 1, axis=(-2, -1))


def time_amplitudes(
    h0: NDArray[np.complexfloating], omega: ArrayLike, t: float, dtype: DTypeLike = np.complex128
) -> NDArray[np.complexfloating]:
    """Fourier amplitudes of the surface at time t, h̃(k, t) [m].

    Parameters
    ----------
    h0 : ndarray, complex, shape (N, N)
        Amplitudes at t = 0 in FFT order [m] (:func:`initial_amplitudes`).
    omega : array_like, shape (N, N)
        Angular frequency ω(|k|) [rad s⁻¹]; must satisfy ω(−k) = ω(k).
    t : float
        Time [s].
    dtype : dtype_like, optional
        ``np.complex128`` or ``np.complex64`` (faster, phase good to ~1e-7 rad).

    Returns
    -------
    ndarray, complex, shape (N, N)
        h̃(k, t), Hermitian: h̃(−k, t) = conj h̃(k, t), so η is real.

    Notes
    -----
    With eq. 26's sign, the part h̃₀(k) exp(i(k·x + ωt)) travels along −k and
    conj h̃₀(−k) exp(−iωt) along +k. Spectra symmetric in k (the Phillips
    spectrum) are unaffected; a one-sided spectrum would need the sign of t
    flipped to make waves run down-wind.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes, eqs. 26–27.
    """
    dtype = np.dtype(dtype)
    cycles = np.asarray(omega, dtype=np.float64) * (t / (2 * np.pi))
    # NOTE: ωt is reduced to one cycle in float64 first, so the phase keeps its
    # precision at large t, also when the trigonometry runs in single precision.
    angle = ((2 * np.pi) * (cycles - np.rint(cycles))).astype(np.finfo(dtype).dtype)
    phase = np.empty(angle.shape, dtype)
    phase.real, phase.imag = np.cos(angle), np.sin(angle)  # e^{iωt}
    h0 = np.asarray(h0).astype(dtype, copy=False)
    return h0 * phase + np.conj(negate_wavenumber(h0) * phase)  # Eq. 26 of [1]


def _spectral_operators(grid: OceanGrid) -> NDArray[np.complex128]:
    """Multipliers of h̃ giving 8 real fields, packed in pairs f + i g, shape (4, N, N).

    Order: (η, Dx), (∂η/∂x, ∂η/∂y), (Dy, ∂Dx/∂y = ∂Dy/∂x), (∂Dx/∂x, ∂Dy/∂y); the
    origin shift to x₀ = (−L/2, −L/2) is folded in.
    """
    kx, ky, k = grid.kx, grid.ky, grid.k
    k_safe = np.where(k == 0, 1.0, k)
    ux, uy = kx / k_safe, ky / k_safe  # k̂, zero at k = 0
    one = np.ones_like(kx)
    # each real field's multiplier m(k) satisfies m(−k) = conj m(k), so the field is real
    pairs = (
        (one, -1j * ux),  # η, Dx: eqs. 19 and 29 of [1]
        (1j * kx, 1j * ky),  # ∇η: eq. 20 of [1]
        (-1j * uy, kx * uy),  # Dy; ∂Dx/∂y = (i ky)(−i kx/k)
        (kx * ux, ky * uy),  # ∂Dx/∂x = kx²/k, ∂Dy/∂y = ky²/k
    )
    packed = np.stack([f + 1j * g for f, g in pairs])
    return packed * grid.origin_sign


def ocean_fields(
    grid: OceanGrid,
    h0: NDArray[np.complex128],
    omega: ArrayLike,
    t: float,
    choppiness: float = 1.0,
    dtype: DTypeLike = np.float64,
) -> OceanFields:
    """Surface elevation, choppy displacement, slopes, Jacobian and normals at time t.

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    h0 : ndarray, complex, shape (N, N)
        Amplitudes at t = 0 in FFT order [m] (:func:`initial_amplitudes`);
        complex64 saves a cast in single precision.
    omega : array_like, shape (N, N)
        Angular frequency ω(|k|) [rad s⁻¹].
    t : float
        Time [s].
    choppiness : float, optional
        Horizontal displacement scale λ [-]; 0 gives a height field.
    dtype : dtype_like, optional
        ``np.float64``, or ``np.float32`` for single-precision transforms
        (about 2× faster; relative errors ~1e-6, below the float32 mesh's).

    Returns
    -------
    OceanFields
        Fields on the grid points x_i = −L/2 + i L/N, of the given dtype.

    Notes
    -----
    All derivatives are spectral: ∂/∂x ↔ i kx. With D = Σ −i (k/|k|) h̃ e^{ik·x}
    (eq. 29) the derivatives of the horizontal map are ∂Dx/∂x = Σ kx²/|k| h̃ e^{ik·x},
    ∂Dy/∂y = Σ ky²/|k| h̃ e^{ik·x}, ∂Dx/∂y = ∂Dy/∂x = Σ kx ky/|k| h̃ e^{ik·x}.

    The 8 real fields are computed with 4 complex inverse FFTs: each of their
    spectra is Hermitian, so the transform of f̂ + i ĝ is f + i g.

    The displaced surface is P(x, y) = (x + λDx, y + λDy, η), and the normal is
    ∂P/∂x × ∂P/∂y = (λ Dxy ∂yη − (1 + λ Dyy) ∂xη, λ Dxy ∂xη − (1 + λ Dxx) ∂yη, J),
    normalised; for λ = 0 it is (−∂xη, −∂yη, 1)/‖·‖.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       eqs. 19–20, 26 and 29, and the Jacobian of its choppy-wave section.
    """
    single = np.dtype(dtype) == np.float32
    if not single and np.dtype(dtype) != np.float64:
        raise ValueError(f"dtype must be float32 or float64, got {np.dtype(dtype)}")
    h = time_amplitudes(h0, omega, t, np.complex64 if single else np.complex128)
    spectra = (grid.spectral_operators_complex64 if single else grid.spectral_operators) * h
    # η(x) = Σ h̃ e^{+ik·x}: the inverse transform without its 1/N² (eq. 19 of [1])
    packed = scipy.fft.ifft2(spectra, norm="forward", workers=-1, overwrite_x=True)
    height, dx = packed[0].real.copy(), choppiness * packed[0].imag
    slope_x, slope_y = packed[1].real.copy(), packed[1].imag.copy()
    dy, dxy = choppiness * packed[2].real, choppiness * packed[2].imag
    jxx, jyy = choppiness * packed[3].real + 1, choppiness * packed[3].imag + 1
    jacobian = jxx * jyy - dxy * dxy  # J = Jxx Jyy − Jxy Jyx, choppy waves of [1]
    normals = _unit_cross_product(jxx, dxy, slope_x, dxy, jyy, slope_y, jacobian)
    return OceanFields(height, dx, dy, slope_x, slope_y, jacobian, normals)


def _unit_cross_product(ax, ay, az, bx, by, bz, z=None) -> NDArray[np.floating]:
    """Unit vectors along a × b for (N, N) component arrays, shape (N, N, 3).

    ``z``, when given, is the already computed z component ax·by − ay·bx.
    """
    # NOTE: written with in-place operations; np.linalg.norm on the (N, N, 3)
    # result alone took as long as the single-precision FFTs at 1024².
    cx = ay * bz
    cx -= az * by
    cy = az * bx
    cy -= ax * bz
    cz = ax * by - ay * bx if z is None else z
    inverse_length = cx * cx
    inverse_length += cy * cy
    inverse_length += cz * cz
    np.sqrt(inverse_length, out=inverse_length)
    np.reciprocal(inverse_length, out=inverse_length)
    unit = np.empty((*cx.shape, 3), cx.dtype)
    for i, component in enumerate((cx, cy, cz)):
        np.multiply(component, inverse_length, out=unit[..., i])
    return unit


@dataclass(frozen=True)
class FFTOcean:
    """A Tessendorf ocean: one set of parameters, amplitudes cached, fields at any time.

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    wind_speed : float
        Wind speed U [m s⁻¹].
    wind_direction : float
        Direction the wind blows toward, counter-clockwise from +x [rad].
    seed : int, optional
        Seed of the random amplitudes.
    choppiness : float, optional
        Horizontal displacement scale λ [-].
    depth : float, optional
        Water depth used in the dispersion relation [m]; ``np.inf`` for deep water.
    alpha : float, optional
        Phillips constant α [-].
    small_wave_length : float, optional
        Small-wave suppression length ℓ [m].
    spectrum : str, optional
        Name of the wave spectrum, a key of :data:`oceanrender.geometry.spectra.SPECTRA`.
    g : float, optional
        Gravitational acceleration [m s⁻²].
    dtype : dtype_like, optional
        Precision of the fields, ``np.float64`` or ``np.float32`` (faster).

    Notes
    -----
    The depth only enters the dispersion relation; the spectrum stays the
    deep-water one.

    Examples
    --------
    >>> ocean = FFTOcean(OceanGrid(64, 100.0), wind_speed=8.0, wind_direction=0.0, seed=1)
    >>> ocean.fields(2.5).height.shape
    (64, 64)
    """

    grid: OceanGrid
    wind_speed: float
    wind_direction: float
    seed: int = 0
    choppiness: float = 1.0
    depth: float = np.inf
    alpha: float = PHILLIPS_ALPHA
    small_wave_length: float = 0.0
    spectrum: str = "Phillips 2001"
    g: float = GRAVITY
    dtype: DTypeLike = np.float64

    def __post_init__(self) -> None:
        if self.spectrum not in SPECTRA:
            raise ValueError(f"unknown wave spectrum {self.spectrum!r}; known: {', '.join(map(repr, SPECTRA))}")
        if not self.wind_speed >= 0:
            raise ValueError(f"wind_speed must be ≥ 0 [m s⁻¹], got {self.wind_speed!r}")
        if not self.depth > 0:
            raise ValueError(f"depth must be > 0 [m], got {self.depth!r}")
        if not self.choppiness >= 0:
            raise ValueError(f"choppiness must be ≥ 0, got {self.choppiness!r}")
        if np.dtype(self.dtype) not in (np.float32, np.float64):
            raise ValueError(f"dtype must be float32 or float64, got {self.dtype!r}")

    @cached_property
    def spectrum_values(self) -> NDArray[np.float64]:
        """Ψ on the wavenumber lattice, FFT order [m⁴]."""
        psi = wave_spectrum(
            self.spectrum,
            self.grid.kx,
            self.grid.ky,
            wind_speed=self.wind_speed,
            wind_direction=self.wind_direction,
            alpha=self.alpha,
            small_wave_length=self.small_wave_length,
            g=self.g,
        )
        return _read_only(psi)

    @cached_property
    def h0(self) -> NDArray[np.complex128]:
        """Amplitudes at t = 0, h̃₀(k) [m]."""
        return _read_only(initial_amplitudes(self.grid, self.spectrum_values, self.seed))

    @cached_property
    def omega(self) -> NDArray[np.float64]:
        """Angular frequency ω(|k|) on the lattice [rad s⁻¹]."""
        return _read_only(dispersion_relation(self.grid.k, self.depth, self.g))

    @property
    def elevation_variance(self) -> float:
        """Expected elevation variance of the band-limited sea, Σ Ψ Δk² [m²]."""
        return elevation_variance(self.grid, self.spectrum_values)

    @property
    def significant_wave_height(self) -> float:
        """Expected significant wave height of the band-limited sea, 4 √m0 [m]."""
        return 4 * np.sqrt(self.elevation_variance)

    def fields(self, t: float) -> OceanFields:
        """Surface fields at time t [s]; see :func:`ocean_fields`."""
        return ocean_fields(self.grid, self._h0_working, self.omega, t, self.choppiness, self.dtype)

    @cached_property
    def _h0_working(self) -> NDArray[np.complexfloating]:
        # h̃₀ in the working precision, so a single-precision frame does not cast it
        single = np.dtype(self.dtype) == np.float32
        return self.h0.astype(np.complex64) if single else self.h0
