"""Tessendorf's FFT ocean in physical units.

A periodic square patch of side L [m] sampled on N × N points carries the
surface elevation η(x, t) = Σ_k h̃(k, t) exp(i k·x) [m], with k on the lattice
2π n / L [rad m⁻¹]. The amplitudes are drawn from a directional wavenumber
spectrum Ψ [m⁴] (see :mod:`oceanrender.waves.wave_spectra`) so that the expected
elevation variance is Σ_k Ψ(k) Δk², the band-limited m0 of the spectrum.

Array layout: every (N, N) array is indexed ``[iy, ix]`` (row = y = north,
column = x = east), as ``np.meshgrid(x, y, indexing="xy")``; spectral arrays
use numpy's FFT ordering along both axes.

The pieces are pure functions (:func:`initial_amplitudes`,
:func:`time_amplitudes`, :func:`quantised_frequency`, :func:`ocean_fields`);
:class:`OceanSynthesis` holds what a frame needs that does not depend on time,
and :class:`FFTOcean` ties them to a set of parameters.

Four departures from [1]:

* **Direction of travel.** h̃(k, t) = h̃₀(k) e^{−iωt} + conj h̃₀(−k) e^{iωt}
  (eq. 26 with the sign of ωt flipped), so the variance Ψ(k) travels along +k
  and a one-sided (down-wind) spreading function makes waves run down-wind.

* **Seed-stable amplitudes.** The Gaussian noise of mode (nx, ny) is a hash of
  (seed, cascade, nx, ny) (:mod:`oceanrender.waves.noise`), so a finer grid
  of the same patch keeps exactly the same large waves.
* **Loop period.** With ω̄ = ⌊ω/ω₀⌋ ω₀, ω₀ = 2π/T, the sea repeats exactly
  after T seconds (:func:`quantised_frequency`).
* **Speed.** A frame is four packed complex inverse FFTs (:func:`inverse_fft2`;
  ducc0 when installed, else scipy) between two compiled passes over the grid
  (numba when installed, else numpy), on several threads, in single precision
  by default; the transforms take about three quarters of the time.

Equation numbers refer to the 2001 course notes [1].

References
----------
.. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes
   (Course 47), 2001.
"""

from __future__ import annotations

import importlib.util
import math
import os
import sys
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from functools import cache, cached_property

import numpy as np
import scipy.fft
from numpy.typing import ArrayLike, DTypeLike, NDArray

from .noise import mode_gaussian
from .wave_spectra import GRAVITY, SPECTRA, dispersion_relation, make_spectrum

__all__ = [
    "OceanGrid",
    "OceanFields",
    "initial_amplitudes",
    "elevation_variance",
    "negate_wavenumber",
    "quantised_frequency",
    "time_amplitudes",
    "FFT_BACKENDS",
    "inverse_fft2",
    "ENGINES",
    "OceanSynthesis",
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

    @property
    def nyquist_wavenumber(self) -> float:
        """Largest wavenumber along an axis the grid carries, π N / L [rad m⁻¹]."""
        return np.pi * self.resolution / self.patch_size

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
        """Packed spectral multipliers of the 8 real fields for λ = 1, shape (4, N, N) [-].

        See :func:`spectral_operators`; 64 bytes per grid point, built on first use.
        """
        return _read_only(spectral_operators(self, 1.0))


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
    jacobian_xx, jacobian_yy, jacobian_xy : ndarray, shape (N, N), optional
        Entries of the Jacobian matrix of the horizontal map, 1 + λ ∂Dx/∂x,
        1 + λ ∂Dy/∂y and λ ∂Dx/∂y = λ ∂Dy/∂x [-]; what a sum of patches
        (:mod:`oceanrender.waves.cascades`) needs to combine Jacobians.

    Notes
    -----
    :class:`OceanSynthesis` returns the real and imaginary parts of four packed
    complex arrays (strided views); copy a field to keep it without the others.
    """

    height: NDArray[np.floating]
    displacement_x: NDArray[np.floating]
    displacement_y: NDArray[np.floating]
    slope_x: NDArray[np.floating]
    slope_y: NDArray[np.floating]
    jacobian: NDArray[np.floating]
    normals: NDArray[np.floating]
    jacobian_xx: NDArray[np.floating] | None = None
    jacobian_yy: NDArray[np.floating] | None = None
    jacobian_xy: NDArray[np.floating] | None = None

    @property
    def resolution(self) -> int:
        """Number of grid points N per side [-]."""
        return self.height.shape[0]


def initial_amplitudes(
    grid: OceanGrid, spectrum_values: ArrayLike, seed: int | None, cascade: int = 0
) -> NDArray[np.complex128]:
    """Random Fourier amplitudes h̃₀(k) of the surface at t = 0 [m].

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    spectrum_values : array_like, shape (N, N)
        Directional wavenumber spectrum Ψ on ``grid.kx, grid.ky`` [m⁴].
    seed : int or None
        Random seed; the same seed gives the same amplitudes. ``None`` draws a
        fresh seed from the operating system.
    cascade : int, optional
        Index of the patch in a cascade, hashed with the seed so that
        cascades get independent noise.

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

    Deviation from [1]: ξ of mode (nx, ny) is
    :func:`~oceanrender.waves.noise.mode_gaussian` of (seed, cascade, nx,
    ny), a hash rather than the next numbers of a sequential generator, so two
    grids of the same patch size share the amplitudes of their common modes.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes, eqs. 25–26.
    """
    psi = np.asarray(spectrum_values, dtype=np.float64)
    if psi.shape != (grid.resolution,) * 2:
        raise ValueError(f"spectrum_values must have shape {(grid.resolution,) * 2}, got {psi.shape}")
    if not np.all(np.isfinite(psi) & (psi >= 0)):
        raise ValueError("spectrum_values must be finite and non-negative [m⁴]")
    if seed is None:
        seed = int(np.random.SeedSequence().entropy)
    xi = mode_gaussian(seed, cascade, grid.indices[None, :], grid.indices[:, None])
    amplitude = np.sqrt(psi * grid.dk**2 / 4) * grid.mode_mask  # P_h = Ψ Δk²/2 in eq. 25 of [1]
    return xi * amplitude  # Eq. 25 of [1]


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


def quantised_frequency(omega: ArrayLike, loop_period: float | None) -> NDArray[np.float64]:
    """Angular frequencies rounded down to multiples of 2π/T, so the sea repeats after T [rad s⁻¹].

    Parameters
    ----------
    omega : array_like
        Angular frequency ω ≥ 0 [rad s⁻¹].
    loop_period : float or None
        Loop period T [s]; ``None`` returns ω unchanged.

    Returns
    -------
    ndarray
        ω̄ = ⌊ω/ω₀⌋ ω₀ with ω₀ = 2π/T; 0 ≤ ω − ω̄ < ω₀.

    Notes
    -----
    Every mode then completes a whole number of cycles in T, so the surface
    at t + T equals the surface at t. Waves with ω < ω₀ stand still
    (ω̄ = 0): choose T well above the period of the longest wave that should
    move. The relative change of the phase speed, < ω₀/ω, is below 1 % for
    waves at least 100 periods shorter than T.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course
       Notes, section "Looping in time", eq. 17.
    """
    omega = np.asarray(omega, dtype=np.float64)
    if loop_period is None:
        return omega
    if not (np.isfinite(loop_period) and loop_period > 0):
        raise ValueError(f"loop_period must be a positive time [s], got {loop_period!r}")
    omega_0 = 2 * np.pi / loop_period  # Eq. 17 of [1]
    return np.floor(omega / omega_0) * omega_0


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
    Deviation from [1]: the sign of ωt. Eq. 26 reads h̃₀(k) e^{iωt} +
    conj h̃₀(−k) e^{−iωt}, whose part h̃₀(k) e^{i(k·x + ωt)} travels along −k,
    against the direction in which Ψ(k) puts its variance. Here

        h̃(k, t) = h̃₀(k) e^{−iωt} + conj h̃₀(−k) e^{+iωt},

    so the variance Ψ(k) Δk² travels along +k, the oceanographic convention
    for directional spectra: with a one-sided spreading function the waves
    run down-wind. Spectra symmetric in k (Tessendorf's Phillips spectrum)
    give the same statistics either way.

    This is the reference form; :class:`OceanSynthesis` computes the same
    amplitudes blockwise, fused with the spectral multipliers.

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
    phase.real, phase.imag = np.cos(angle), -np.sin(angle)  # e^{−iωt}
    h0 = np.asarray(h0).astype(dtype, copy=False)
    return h0 * phase + np.conj(negate_wavenumber(h0) * phase)  # Eq. 26 of [1], sign of ωt flipped


def spectral_operators(grid: OceanGrid, choppiness: float = 1.0) -> NDArray[np.complex128]:
    """Multipliers of h̃ giving 8 real fields, packed in pairs f + i g, shape (4, N, N) [-].

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    choppiness : float, optional
        Horizontal displacement scale λ [-], folded into the displacement terms.

    Returns
    -------
    ndarray, complex128
        Pairs (η, λDx), (∂η/∂x, ∂η/∂y), (λDy, λ∂Dx/∂y = λ∂Dy/∂x),
        (λ∂Dx/∂x, λ∂Dy/∂y); the origin shift to x₀ = (−L/2, −L/2) is folded in.

    Notes
    -----
    Each real field's multiplier m(k) satisfies m(−k) = conj m(k), so with a
    Hermitian h̃ its transform is real and the inverse transform of f̂ + i ĝ
    is f + i g.
    """
    kx, ky, k = grid.kx, grid.ky, grid.k
    k_safe = np.where(k == 0, 1.0, k)
    ux, uy = choppiness * kx / k_safe, choppiness * ky / k_safe  # λ k̂, zero at k = 0
    pairs = (
        (1.0, -1j * ux),  # η, Dx: eqs. 19 and 29 of [1]
        (1j * kx, 1j * ky),  # ∇η: eq. 20 of [1]
        (-1j * uy, kx * uy),  # Dy; ∂Dx/∂y = (i ky)(−i kx/k)
        (kx * ux, ky * uy),  # ∂Dx/∂x = kx²/k, ∂Dy/∂y = ky²/k
    )
    packed = np.stack([np.broadcast_to(f + 1j * g, kx.shape) for f, g in pairs])
    return packed * grid.origin_sign


def _fft_ducc0(spectra: NDArray, workers: int) -> None:
    import ducc0  # noqa: PLC0415

    ducc0.fft.c2c(spectra, axes=(-2, -1), forward=False, inorm=0, out=spectra, nthreads=workers)


def _fft_scipy(spectra: NDArray, workers: int) -> None:
    result = scipy.fft.ifft2(spectra, norm="forward", workers=workers, overwrite_x=True)
    if result.ctypes.data != spectra.ctypes.data or result.strides != spectra.strides:
        spectra[...] = result


def _fft_numpy(spectra: NDArray, workers: int) -> None:
    # NOTE: numpy's ``out=`` must not alias the input (measured: wrong results in place)
    spectra[...] = np.fft.ifft2(spectra, norm="forward")


FFT_BACKENDS: dict[str, Callable[[NDArray, int], None]] = {
    "ducc0": _fft_ducc0,
    "scipy": _fft_scipy,
    "numpy": _fft_numpy,
}
"""In-place, unnormalised inverse 2-D FFTs over the last two axes, by library name."""


def _default_backend() -> str:
    try:
        import ducc0  # noqa: F401, PLC0415
    except ImportError:
        return "scipy"
    return "ducc0"


def _resolve(backend: str, workers: int | None) -> tuple[str, int]:
    backend = _default_backend() if backend == "auto" else backend
    if backend not in FFT_BACKENDS:
        raise ValueError(f"unknown FFT backend {backend!r}; known: 'auto', {', '.join(map(repr, FFT_BACKENDS))}")
    if workers is None:
        workers = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    if int(workers) != workers or workers < 1:
        raise ValueError(f"workers must be a positive integer, got {workers!r}")
    return backend, int(workers)


def inverse_fft2(spectra: NDArray[np.complexfloating], backend: str = "auto", workers: int | None = None) -> None:
    """In place: spectra ← Σ_k c_k e^{+2πi k·j/N} over the last two axes (no 1/N² factor).

    Parameters
    ----------
    spectra : ndarray, complex64 or complex128, shape (..., N, N)
        C-contiguous spectra in FFT order; overwritten by the transforms.
    backend : str, optional
        ``"auto"`` (ducc0 when installed, else scipy) or a key of :data:`FFT_BACKENDS`.
    workers : int, optional
        Threads; all the CPUs this process may use by default.
    """
    backend, workers = _resolve(backend, workers)
    FFT_BACKENDS[backend](spectra, workers)


def _row_blocks(function: Callable[[slice], None], rows: int, columns: int, workers: int,
                pool: ThreadPoolExecutor | None) -> None:
    """Call function(rows slice) over blocks of about 16k points, on ``workers`` threads of ``pool``.

    Each thread gets one contiguous range of rows and walks it block by block,
    so the temporaries of a block stay in cache and numpy, which releases the
    GIL inside its loops, runs the threads in parallel.
    """
    block = max(1, 16384 // columns)

    def run(start: int, stop: int) -> None:
        for first in range(start, stop, block):
            function(slice(first, min(first + block, stop)))

    _split_rows(run, rows, pool, workers)


ENGINES: tuple[str, ...] = ("numba", "numpy") if importlib.util.find_spec("numba") else ("numpy",)
"""Pointwise engines installed here: compiled loops (numba, optional), or numpy array operations."""


@cache
def _default_engine() -> str:
    """numba if it imports (it pins the numpy versions it supports), else numpy."""
    try:
        import numba  # noqa: F401, PLC0415
    except ImportError:
        return "numpy"
    return "numba"


def _prepare_spectra(start, stop, cos_t, sin_t, index, s, d, kx, ky, lam, one, tiny, pairs, f0, f1, f2, f3):
    """Rows of the packed spectra, compiled by numba (:func:`_kernels`); arrays of (re, im) pairs as floats.

    Row i (start ≤ i < stop ≤ N/2 + 1) from h̃ = (Re S c − Im S s) + i (Re D s + Im D c), with
    c = cos ωt and s = −sin ωt looked up in (cos_t, sin_t) (see :class:`OceanSynthesis`),
    and row N − i from h̃(−k) = conj h̃(k), read
    backwards from row i's buffer. Then per point, with u = λ/k:
    (η, λDx): h̃ (1 + kx u); (∂xη, ∂yη): h̃ (i kx − ky);
    (λDy, λDxy): h̃ i ky u (kx − 1); (λDxx, λDyy): h̃ u (kx² + i ky²).
    """
    n = kx.shape[0]
    h = np.empty(2 * n, s.dtype)
    g = np.empty(2 * n, s.dtype)
    for i in range(start, stop):
        for j in range(n):
            c, sn = cos_t[index[i, j]], sin_t[index[i, j]]
            h[2 * j] = s[i, 2 * j] * c - s[i, 2 * j + 1] * sn
            h[2 * j + 1] = d[i, 2 * j] * sn + d[i, 2 * j + 1] * c
        m = n - i
        g[0], g[1] = h[0], -h[1]
        for j in range(1, n):
            g[2 * j], g[2 * j + 1] = h[2 * (n - j)], -h[2 * (n - j) + 1]
        for side in range(2):
            if side == 1 and not 0 < i < m:
                break  # rows 0 and N/2 are their own mirror
            row, values = (i, h) if side == 0 else (m, g)
            y = ky[row]
            yy = y * y
            a0, a1, a2, a3 = f0[row], f1[row], f2[row], f3[row]
            for j in range(n):
                x = kx[j]
                hr, hi = values[2 * j], values[2 * j + 1]
                u = lam / np.sqrt(x * x + yy + tiny)  # λ/k; finite at k = 0, where h̃ = 0
                f = one + x * u
                a0[2 * j], a0[2 * j + 1] = hr * f, hi * f
                a1[2 * j], a1[2 * j + 1] = -y * hr - x * hi, x * hr - y * hi
                if pairs == 4:  # loop-invariant: compiled as two loops
                    f = y * u * (x - one)
                    a2[2 * j], a2[2 * j + 1] = -f * hi, f * hr
                    p, q = x * x * u, yy * u
                    a3[2 * j], a3[2 * j + 1] = p * hr - q * hi, q * hr + p * hi


def _finish_fields(start, stop, f1, f2, f3, one, jacobian, normals):
    """J and unit normals of rows start … stop − 1 from the transformed pairs 1–3, compiled by numba."""
    for i in range(start, stop):
        a, b, c, jac, nor = f1[i], f2[i], f3[i], jacobian[i], normals[i]
        for j in range(jacobian.shape[1]):
            sx, sy, jxy, jxx, jyy = a[2 * j], a[2 * j + 1], b[2 * j + 1], c[2 * j], c[2 * j + 1]
            det = jxx * jyy - jxy * jxy
            cx = jxy * sy - jyy * sx
            cy = jxy * sx - jxx * sy
            inverse_length = one / np.sqrt(cx * cx + cy * cy + det * det)
            jac[j] = det
            nor[j, 0], nor[j, 1], nor[j, 2] = cx * inverse_length, cy * inverse_length, det * inverse_length


@cache
def _kernels() -> tuple[Callable, Callable]:
    """The compiled (prepare, finish) kernels; numba is imported here, on first use (~0.5 s)."""
    import numba  # noqa: PLC0415

    # Fast-math without nnan/ninf: reordering and approximate reciprocal square
    # roots (vectorised), but NaN and inf inputs still propagate.
    # NOTE: serial kernels over a range of rows, run on Python threads (they release
    # the GIL) rather than numba's parallel=True: its OpenMP layer kept idle threads
    # spinning, which slowed the FFT library's threads on a 2-core machine.
    jit = numba.njit(nogil=True, cache=True, error_model="numpy",
                     fastmath={"contract", "arcp", "afn", "reassoc", "nsz"})
    return jit(_prepare_spectra), jit(_finish_fields)


def _split_rows(kernel: Callable, rows: int, pool: ThreadPoolExecutor | None, workers: int, *args) -> None:
    """kernel(start, stop, *args) over [0, rows) cut into ``workers`` ranges run on ``pool``."""
    bounds = np.linspace(0, rows, min(workers, rows) + 1).round().astype(int)
    if len(bounds) == 2:
        kernel(0, rows, *args)
        return
    for future in [pool.submit(kernel, a, b, *args) for a, b in zip(bounds[:-1], bounds[1:])]:
        future.result()


class OceanSynthesis:
    """The time-independent part of a frame: fields of one sea at any time t, fast.

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    h0 : array_like, complex, shape (N, N)
        Amplitudes at t = 0 in FFT order [m] (:func:`initial_amplitudes`).
    omega : array_like, shape (N, N)
        Angular frequency [rad s⁻¹], ω(−k) = ω(k).
    choppiness : float, optional
        Horizontal displacement scale λ [-]; 0 gives a height field (two
        transforms instead of four).
    dtype : dtype_like, optional
        ``np.float32`` (rendering) or ``np.float64`` (tests, analysis).
    backend : str, optional
        FFT library, see :func:`inverse_fft2`.
    workers : int, optional
        Threads for the transforms and the pointwise work.
    engine : str, optional
        ``"auto"`` (numba when installed), ``"numba"`` or ``"numpy"``: how the
        pointwise work before and after the transforms is done.

    Notes
    -----
    A frame (:meth:`__call__`):

    1. e^{−iω_u t} for each distinct ω_u (ω depends on |k| only, so there are
       about ten times fewer distinct values than modes at 1024²), with ωt
       reduced to one cycle in float64;
    2. h̃(k, t) = h̃₀(k) e^{−iωt} + conj(h̃₀(−k)) e^{iωt} (eq. 26 of [1], the
       sign of :func:`time_amplitudes`) for the rows 0 … N/2, written with
       c = cos ωt, s = −sin ωt as Re h̃ = Re S c − Im S s,
       Im h̃ = Re D s + Im D c with S = h̃₀(k) + h̃₀(−k) and
       D = h̃₀(k) − h̃₀(−k) (origin shift folded in); the other rows follow
       from h̃(−k) = conj h̃(k). The four packed spectra are formed on the fly
       from h̃, kx and ky (:func:`spectral_operators`, λ folded in), plus 1 + i at
       k = 0 of the last pair, which adds the 1 of the Jacobian matrix 1 + λ∇D;
    3. four in-place complex inverse FFTs;
    4. J and the unit normals in one pass.

    Steps 2 and 4 are compiled loops (numba) run on ``workers`` Python threads; the
    numpy engine does the same with precomputed multipliers, row block by row
    block. Memory held between frames: S, D and an index on half the plane,
    10 bytes per point in single precision (numpy engine: 52). A frame
    allocates the four packed spectra (which the returned fields are views
    of), J and the normals: 48 bytes per point in single precision, 96 in
    double, or reuses the previous frame's arrays when the caller no longer
    holds them (or when given as ``out=``). Not thread-safe: one frame at a time.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       eqs. 19–20, 26 and 29, and the Jacobian of its choppy-wave section.
    """

    def __init__(
        self,
        grid: OceanGrid,
        h0: ArrayLike,
        omega: ArrayLike,
        choppiness: float = 1.0,
        dtype: DTypeLike = np.float32,
        backend: str = "auto",
        workers: int | None = None,
        engine: str = "auto",
    ) -> None:
        real = np.dtype(dtype)
        if real not in (np.float32, np.float64):
            raise ValueError(f"dtype must be float32 or float64, got {real}")
        engine = _default_engine() if engine == "auto" else engine
        if engine not in ENGINES:
            raise ValueError(f"unknown or unavailable engine {engine!r}; available: 'auto', "
                             f"{', '.join(map(repr, ENGINES))}")
        shape = (grid.resolution,) * 2
        h0, omega = np.asarray(h0, dtype=np.complex128), np.asarray(omega, dtype=np.float64)
        if h0.shape != shape or omega.shape != shape:
            raise ValueError(f"h0 and omega must have shape {shape}, got {h0.shape} and {omega.shape}")
        self.grid, self.choppiness, self.dtype, self.engine = grid, float(choppiness), real, engine
        # NOTE: the surface is displaced by −λD with D of eq. 29 of [1]. With [1]'s
        # sign a single wave η = a cos kx moves to x + λ a sin kx, which stretches
        # the crests and sharpens the troughs; the Lagrangian (Gerstner) solution
        # moves particles towards the crests, x − a sin kx, and sharpens the
        # crests. The operators and kernels below therefore get −λ.
        self._signed_choppiness = -self.choppiness
        self.backend, self.workers = _resolve(backend, workers)
        self.complex_dtype = np.result_type(real, np.complex64)
        self.pairs = 4 if self.choppiness else 2
        self._recycled: list[NDArray | None] = [None] * 6
        frequency, index = np.unique(omega / (2 * np.pi), return_inverse=True)
        self._frequency = _read_only(frequency)  # distinct ω / 2π [Hz]
        index = index.reshape(shape).astype(np.int32)
        if engine == "numba":
            half = slice(0, grid.resolution // 2 + 1)
            reflected = negate_wavenumber(h0)
            sign = grid.origin_sign
            self._sum = _read_only(((h0 + reflected) * sign)[half].astype(self.complex_dtype))
            self._difference = _read_only(((h0 - reflected) * sign)[half].astype(self.complex_dtype))
            self._index = _read_only(np.ascontiguousarray(index[half]))
            self._k = _read_only((grid.dk * grid.indices).astype(real))
        else:
            self._h0 = _read_only(h0.astype(self.complex_dtype))
            self._h0_reflected = _read_only(np.conj(negate_wavenumber(h0)).astype(self.complex_dtype))
            self._index = _read_only(index)
            operators = spectral_operators(grid, self._signed_choppiness)[: self.pairs]
            self._operators = _read_only(operators.astype(self.complex_dtype))

    @cached_property
    def _pool(self) -> ThreadPoolExecutor | None:
        # idle between frames; threads wait on a queue, they do not spin
        return ThreadPoolExecutor(self.workers, thread_name_prefix="ocean") if self.workers > 1 else None

    @property
    def nbytes(self) -> int:
        """Bytes held between frames [B]."""
        names = ("_frequency", "_index", "_sum", "_difference", "_k", "_h0", "_h0_reflected", "_operators")
        return sum(getattr(self, name).nbytes for name in names if hasattr(self, name))

    def phase_table(self, t: float) -> tuple[NDArray[np.floating], NDArray[np.floating]]:
        """cos ω_u t and −sin ω_u t (the parts of e^{−iω_u t}) for each distinct ω_u [-]."""
        cycles = self._frequency * t
        cycles -= np.rint(cycles)  # one cycle in float64, as in :func:`time_amplitudes`
        angle = (-2 * np.pi * cycles).astype(self.dtype)
        return np.cos(angle), np.sin(angle)

    def _buffers(self, out: OceanFields | None) -> tuple[list[NDArray], NDArray, NDArray]:
        n = self.grid.resolution
        shapes = [(n, n)] * 5 + [(n, n, 3)]
        dtypes = [self.complex_dtype] * 4 + [self.dtype] * 2
        if out is not None:
            arrays = [out.height.base, out.slope_x.base, out.displacement_y.base, out.jacobian_xx.base,
                      out.jacobian, out.normals]
            if not all(isinstance(a, np.ndarray) and a.shape == s and a.dtype == d and a.flags.c_contiguous
                       and a.flags.writeable for a, s, d in zip(arrays, shapes, dtypes)):
                raise ValueError("out must be the fields of an earlier frame of this synthesis (same grid and dtype)")
        else:
            # NOTE: the arrays of the previous frame are reused when nothing outside
            # holds them any more (CPython reference count: the list slot, the local
            # name and getrefcount's argument). A fresh 48 MB at 1024² costs the
            # kernel ~10 ms of page zeroing, a quarter of a frame; a caller that
            # keeps a frame (or any of its arrays) gets new arrays next time.
            previous = self._recycled if hasattr(sys, "getrefcount") else [None] * 6
            arrays = []
            for i in range(6):
                array = previous[i]
                if array is None or sys.getrefcount(array) > 3:
                    array = np.empty(shapes[i], dtypes[i])
                arrays.append(array)
                array = None
        self._recycled = arrays
        return arrays[:4], arrays[4], arrays[5]

    def __call__(self, t: float, out: OceanFields | None = None) -> OceanFields:
        """Surface fields at time t [s]; see :func:`ocean_fields`.

        Parameters
        ----------
        t : float
            Time [s].
        out : OceanFields, optional
            Fields returned by an earlier call of this synthesis, overwritten
            in place. Without it, the previous frame's arrays are reused if
            nothing refers to them any more, else new ones are allocated.
        """
        n, pairs = self.grid.resolution, self.pairs
        cos_t, sin_t = self.phase_table(t)
        spectra, jacobian, normals = self._buffers(out)
        if self.engine == "numba":
            real = self.dtype.type
            prepare, _ = _kernels()
            _split_rows(prepare, n // 2 + 1, self._pool, self.workers, cos_t, sin_t, self._index,
                        self._sum.view(self.dtype), self._difference.view(self.dtype), self._k, self._k,
                        real(self._signed_choppiness), real(1), real(1e-30), pairs, *(a.view(self.dtype) for a in spectra))
        else:
            self._prepare_numpy(cos_t, sin_t, spectra)
        if pairs == 4:
            spectra[3][0, 0] = 1 + 1j  # the identity of 1 + λ∇D
        for pair in spectra[:pairs]:
            FFT_BACKENDS[self.backend](pair, self.workers)
        if pairs == 2:  # λ = 0: no displacement, J = 1 exactly
            spectra[0].imag = 0
            spectra[2].fill(0)
            spectra[3].fill(1 + 1j)
        # η(x) = Σ h̃ e^{+ik·x}: the inverse transform without its 1/N² (eq. 19 of [1])
        jxx, jyy, jxy = spectra[3].real, spectra[3].imag, spectra[2].imag
        if self.engine == "numba":
            _, finish = _kernels()
            _split_rows(finish, n, self._pool, self.workers, *(a.view(self.dtype) for a in spectra[1:]),
                        self.dtype.type(1), jacobian, normals)
        else:
            def finish(rows: slice) -> None:
                _jacobian_and_normals(jxx[rows], jyy[rows], jxy[rows], spectra[1].real[rows],
                                      spectra[1].imag[rows], jacobian[rows], normals[rows])

            _row_blocks(finish, n, n, self.workers, self._pool)
        return OceanFields(spectra[0].real, spectra[0].imag, spectra[2].real, spectra[1].real, spectra[1].imag,
                           jacobian, normals, jxx, jyy, jxy)

    def _prepare_numpy(self, cos_t: NDArray, sin_t: NDArray, spectra: list[NDArray]) -> None:
        n, pairs = self.grid.resolution, self.pairs
        table = np.empty(cos_t.shape, self.complex_dtype)
        table.real, table.imag = cos_t, sin_t

        def prepare(rows: slice) -> None:
            phase = np.take(table, self._index[rows])
            h = self._h0[rows] * phase
            np.conjugate(phase, out=phase)
            phase *= self._h0_reflected[rows]
            h += phase  # Eq. 26 of [1]
            for j in range(pairs):
                np.multiply(self._operators[j, rows], h, out=spectra[j][rows])

        _row_blocks(prepare, n, n, self.workers, self._pool)


def _jacobian_and_normals(jxx, jyy, jxy, slope_x, slope_y, jacobian, normals) -> None:
    """J = Jxx Jyy − Jxy² and the unit normal of P = (x + λDx, y + λDy, η), written into the outputs.

    The normal is ∂P/∂x × ∂P/∂y = (Jxy ∂yη − Jyy ∂xη, Jxy ∂xη − Jxx ∂yη, J).
    """
    # NOTE: in-place operations on small blocks: np.linalg.norm on the whole
    # (N, N, 3) result alone took as long as the single-precision FFTs at 1024².
    np.multiply(jxx, jyy, out=jacobian)
    scratch = jxy * jxy
    jacobian -= scratch  # J = Jxx Jyy − Jxy Jyx, choppy waves of [1]
    cx = jxy * slope_y
    np.multiply(jyy, slope_x, out=scratch)
    cx -= scratch
    cy = jxy * slope_x
    np.multiply(jxx, slope_y, out=scratch)
    cy -= scratch
    inverse_length = cx * cx
    np.multiply(cy, cy, out=scratch)
    inverse_length += scratch
    np.multiply(jacobian, jacobian, out=scratch)
    inverse_length += scratch
    np.sqrt(inverse_length, out=inverse_length)
    np.reciprocal(inverse_length, out=inverse_length)
    np.multiply(cx, inverse_length, out=normals[..., 0])
    np.multiply(cy, inverse_length, out=normals[..., 1])
    np.multiply(jacobian, inverse_length, out=normals[..., 2])


def ocean_fields(
    grid: OceanGrid,
    h0: NDArray[np.complexfloating],
    omega: ArrayLike,
    t: float,
    choppiness: float = 1.0,
    dtype: DTypeLike = np.float64,
    backend: str = "auto",
    workers: int | None = None,
    engine: str = "auto",
) -> OceanFields:
    """Surface elevation, choppy displacement, slopes, Jacobian and normals at time t.

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    h0 : ndarray, complex, shape (N, N)
        Amplitudes at t = 0 in FFT order [m] (:func:`initial_amplitudes`).
    omega : array_like, shape (N, N)
        Angular frequency ω(|k|) [rad s⁻¹].
    t : float
        Time [s].
    choppiness : float, optional
        Horizontal displacement scale λ [-]; 0 gives a height field.
    dtype : dtype_like, optional
        ``np.float64``, or ``np.float32`` for single-precision transforms
        (about 2× faster; relative errors ~1e-6, below the float32 mesh's).
    backend : str, optional
        FFT library (:func:`inverse_fft2`).
    workers : int, optional
        Threads.
    engine : str, optional
        Pointwise engine, ``"auto"``, ``"numba"`` or ``"numpy"`` (:class:`OceanSynthesis`).

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

    This builds an :class:`OceanSynthesis` for one frame; to render many
    frames, keep one (as :class:`FFTOcean` does).

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
       eqs. 19–20, 26 and 29, and the Jacobian of its choppy-wave section.
    """
    return OceanSynthesis(grid, h0, omega, choppiness, dtype, backend, workers, engine)(t)


@dataclass(frozen=True)
class FFTOcean:
    """A Tessendorf ocean: one set of parameters, amplitudes cached, fields at any time.

    Parameters
    ----------
    grid : OceanGrid
        Patch and wavenumber lattice.
    wind_speed : float
        Wind speed U [m s⁻¹] (Phillips spectrum; ignored with ``spectrum_function``).
    wind_direction : float
        Direction the wind blows toward, counter-clockwise from +x [rad]
        (Phillips spectrum; ignored with ``spectrum_function``).
    seed : int, optional
        Seed of the random amplitudes.
    choppiness : float, optional
        Horizontal displacement scale λ [-].
    depth : float, optional
        Water depth [m]; ``np.inf`` for deep water. It enters the dispersion
        relation and, for the frequency spectra, their transform to Ψ(k) and
        TMA's depth function ("Phillips 2001" is a deep-water spectrum: there
        the depth is the dispersion relation's only).
    alpha : float or None, optional
        Phillips constant α [-] ("Phillips 2001", "Pierson-Moskowitz 1964";
        None: the spectrum's default; an error for the fetch-law spectra).
    small_wave_length : float, optional
        Small-wave suppression length ℓ [m].
    spectrum : str, optional
        Name of the wave spectrum, a key of :data:`oceanrender.waves.wave_spectra.SPECTRA`.
    g : float, optional
        Gravitational acceleration [m s⁻²].
    surface_tension : float, optional
        Surface tension σ [N m⁻¹] of the dispersion relation ω² = (g k + σk³/ρ) tanh kd;
        0 (default): gravity waves.
    dtype : dtype_like, optional
        Precision of the fields: ``np.float32`` (default, rendering) or ``np.float64``.
    spectrum_function : callable, optional
        Any Ψ(kx, ky) → ndarray [m⁴] (wavenumbers in rad m⁻¹), e.g.
        ``functools.partial(spectrum_Phillips2001, wind_speed=8.0, wind_direction=0.3)``
        or a directional-spectrum object; overrides ``spectrum``, ``wind_speed``,
        ``wind_direction``, ``alpha`` and ``small_wave_length``.
    loop_period : float, optional
        Period T [s] after which the sea repeats exactly (:func:`quantised_frequency`);
        ``None`` (default) for the exact dispersion relation.
    cascade : int, optional
        Index hashed into the noise (:func:`initial_amplitudes`); 0 for a single patch.
    fft_backend : str, optional
        FFT library (:func:`inverse_fft2`); ``"auto"`` picks ducc0 when installed.
    workers : int, optional
        Threads for a frame; all the CPUs this process may use by default.
    engine : str, optional
        Pointwise engine (:class:`OceanSynthesis`): ``"auto"`` uses numba when installed.

    Notes
    -----
    A named spectrum is built by :func:`~oceanrender.waves.wave_spectra.make_spectrum`,
    the same function the scene files use, so every parameter it cannot use
    is an error rather than silently dropped.

    Examples
    --------
    >>> ocean = FFTOcean(OceanGrid(64, 100.0), wind_speed=8.0, wind_direction=0.0, seed=1)
    >>> ocean.fields(2.5).height.shape
    (64, 64)
    """

    grid: OceanGrid
    wind_speed: float = 0.0
    wind_direction: float = 0.0
    seed: int = 0
    choppiness: float = 1.0
    depth: float = np.inf
    alpha: float | None = None
    small_wave_length: float = 0.0
    spectrum: str = "Phillips 2001"
    g: float = GRAVITY
    surface_tension: float = 0.0
    dtype: DTypeLike = np.float32
    spectrum_function: Callable[[NDArray, NDArray], NDArray] | None = None
    loop_period: float | None = None
    cascade: int = 0
    fft_backend: str = "auto"
    workers: int | None = None
    engine: str = "auto"

    def __post_init__(self) -> None:
        if self.spectrum_function is None and self.spectrum not in SPECTRA:
            raise ValueError(f"unknown wave spectrum {self.spectrum!r}; known: {', '.join(map(repr, SPECTRA))}")
        if self.spectrum_function is not None and not callable(self.spectrum_function):
            raise ValueError(f"spectrum_function must be callable Ψ(kx, ky), got {self.spectrum_function!r}")
        if not self.wind_speed >= 0:
            raise ValueError(f"wind_speed must be ≥ 0 [m s⁻¹], got {self.wind_speed!r}")
        if not self.depth > 0:
            raise ValueError(f"depth must be > 0 [m], got {self.depth!r}")
        if not self.choppiness >= 0:
            raise ValueError(f"choppiness must be ≥ 0, got {self.choppiness!r}")
        if np.dtype(self.dtype) not in (np.float32, np.float64):
            raise ValueError(f"dtype must be float32 or float64, got {self.dtype!r}")
        if self.loop_period is not None and not (np.isfinite(self.loop_period) and self.loop_period > 0):
            raise ValueError(f"loop_period must be a positive time [s] or None, got {self.loop_period!r}")
        _resolve(self.fft_backend, self.workers)
        if self.engine not in ("auto", *ENGINES):
            raise ValueError(f"unknown or unavailable engine {self.engine!r}; available: 'auto', "
                             f"{', '.join(map(repr, ENGINES))}")

    @cached_property
    def spectrum_values(self) -> NDArray[np.float64]:
        """Ψ on the wavenumber lattice, FFT order [m⁴]."""
        if self.spectrum_function is not None:
            psi = np.asarray(self.spectrum_function(self.grid.kx, self.grid.ky), dtype=np.float64)
            return _read_only(np.broadcast_to(psi, self.grid.kx.shape).copy())
        parameters = {"wind_speed": self.wind_speed, "wind_direction": self.wind_direction,
                      "small_wave_length": self.small_wave_length, "g": self.g,
                      "surface_tension": self.surface_tension}
        if self.alpha is not None:
            parameters["alpha"] = self.alpha
        if self.spectrum != "Phillips 2001":  # Phillips is deep water: the depth is the dispersion's alone
            parameters["depth"] = self.depth
        psi = make_spectrum(self.spectrum, **parameters)(self.grid.kx, self.grid.ky)
        return _read_only(np.asarray(psi, dtype=np.float64))

    @cached_property
    def h0(self) -> NDArray[np.complex128]:
        """Amplitudes at t = 0, h̃₀(k) [m]."""
        return _read_only(initial_amplitudes(self.grid, self.spectrum_values, self.seed, self.cascade))

    @cached_property
    def omega(self) -> NDArray[np.float64]:
        """Angular frequency ω(|k|) on the lattice, quantised with ``loop_period`` [rad s⁻¹]."""
        omega = dispersion_relation(self.grid.k, self.depth, self.g, self.surface_tension)
        return _read_only(quantised_frequency(omega, self.loop_period))

    @property
    def elevation_variance(self) -> float:
        """Expected elevation variance of the band-limited sea, Σ Ψ Δk² [m²]."""
        return elevation_variance(self.grid, self.spectrum_values)

    @property
    def significant_wave_height(self) -> float:
        """Expected significant wave height of the band-limited sea, 4 √m0 [m]."""
        return 4 * np.sqrt(self.elevation_variance)

    @cached_property
    def synthesis(self) -> OceanSynthesis:
        """The precomputed frame machinery (:class:`OceanSynthesis`)."""
        return OceanSynthesis(self.grid, self.h0, self.omega, self.choppiness, self.dtype,
                              self.fft_backend, self.workers, self.engine)

    def fields(self, t: float, out: OceanFields | None = None) -> OceanFields:
        """Surface fields at time t [s]; see :func:`ocean_fields`.

        ``out``, the fields of an earlier call, is overwritten instead of
        allocating new arrays (:meth:`OceanSynthesis.__call__`).
        """
        if self.loop_period is not None:
            t = math.fmod(t, self.loop_period)  # exact; keeps ωt small for large t
        return self.synthesis(t, out)
