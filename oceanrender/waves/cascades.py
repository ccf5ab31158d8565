"""A sea from several FFT patches of incommensurate sizes, each carrying its own wavenumber band.

One FFT patch of side L on N points resolves wavelengths from L down to 2L/N
and repeats every L: seen from a ship, a 1 km patch at 1024² is tiled after
1 km and has no ripple shorter than 2 m. Cascades (as in the "water cascades"
of production ocean simulators) stack patches of decreasing size L₀ > L₁ > …,
each covering one annulus of the wavenumber plane,

    band i = {k : k_i ≤ |k| < k_{i+1}},   0 = k_0 < k_1 < … < k_n,

so every wavenumber belongs to exactly one patch: the spectrum of patch i is
Ψ(k) 1[k_i ≤ |k| < k_{i+1}] (:class:`BandLimitedSpectrum`), the variances add
up without double counting, and the sum of the patches has the variance of
the spectrum over the disk |k| < k_n. On each patch's lattice a cell that an
edge crosses carries the fraction of its area inside the band
(:func:`annulus_fraction`), which keeps the lattice sums within ~0.5 % of the
integral where cutting at the cell centres was off by up to 4 %.

Patch sizes. With L_i = L₀/r^i, the ratio of patches i and j is r^{j−i};
it should be far from every fraction p/q of small denominator, or the two
patches repeat together after q L_j ≈ p L_i. r = 4.389675
(:data:`PATCH_SIZE_RATIO`) maximises the worst q² |r^m − p/q| over m ≤ 4
(five patches) and q ≤ 20 on [3.8, 4.8], at 0.25 (a number cannot beat 0.5
at q = 1). The golden ratio, often used, fails this: φ³ = 4.236 is a Pisot
number, its powers approach integers (φ⁶ = 17.94, φ⁹ = 75.99), so patches 0
and 2 of an φ³ cascade nearly tile together every 18 small tiles (score 0.003).

Band edges (:func:`cascade_band_edges`): k_i between patch i−1 and patch i is
the geometric mean of the fundamental 2π/L_i of the finer patch and the
Nyquist wavenumber π N_{i−1}/L_{i−1} of the coarser one, as far (in octaves)
from either patch's resolution limit as possible; k_n is the Nyquist
wavenumber of the finest patch.

Each patch is a :class:`~oceanrender.waves.fft_ocean.FFTOcean` with the
patch index hashed into its noise. :meth:`CascadeOcean.fields_at` samples the
summed surface at arbitrary points by periodic bilinear interpolation of each
patch's FFT fields; the renderer samples it on its own mesh.

References
----------
.. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes.
.. [2] A. Ya. Khinchin, Continued Fractions, Dover, 1997, ch. II (rational
   approximation; q² |x − p/q| stays bounded below for badly approximable x).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, DTypeLike, NDArray

from .fft_ocean import FFTOcean, OceanFields, OceanGrid
from .wave_spectra import GRAVITY

__all__ = [
    "PATCH_SIZE_RATIO",
    "commensurability",
    "cascade_patch_sizes",
    "cascade_band_edges",
    "cascade_band_edges_resolved",
    "annulus_fraction",
    "BandLimitedSpectrum",
    "SurfaceSample",
    "CascadeFrame",
    "CascadeOcean",
]

PATCH_SIZE_RATIO: float = 4.389675
"""Default ratio of consecutive patch sizes [-]; see the module docstring and :func:`commensurability`."""


def commensurability(ratios: ArrayLike, max_denominator: int = 20) -> float:
    """How close size ratios come to simple fractions: min over q ≤ Q of q² |x − p/q| [-].

    Parameters
    ----------
    ratios : array_like
        Ratios x > 0 of patch sizes.
    max_denominator : int, optional
        Largest denominator Q tried.

    Returns
    -------
    float
        The smallest q² |x − round(q x)/q| over the ratios and q = 1 … Q; 0 for
        a rational ratio with denominator ≤ Q, at most 0.5. Larger is better:
        patches with ratio x tile together only after q L with q² |x − p/q| small.

    References
    ----------
    .. [1] A. Ya. Khinchin, Continued Fractions, Dover, 1997, ch. II.
    """
    x = np.asarray(ratios, dtype=np.float64).reshape(-1, 1)
    q = np.arange(1, max_denominator + 1)
    return float(np.min(q * q * np.abs(x - np.round(q * x) / q)))


def cascade_patch_sizes(largest: float, count: int, ratio: float = PATCH_SIZE_RATIO) -> tuple[float, ...]:
    """Patch sizes L_i = L₀ / r^i, largest first [m].

    Parameters
    ----------
    largest : float
        Side L₀ of the largest patch [m].
    count : int
        Number of patches [-].
    ratio : float, optional
        r > 1, with powers far from simple fractions (:data:`PATCH_SIZE_RATIO`).

    Returns
    -------
    tuple of float
        (L₀, L₀/r, …, L₀/r^{count−1}) [m].
    """
    if not (largest > 0 and np.isfinite(largest)):
        raise ValueError(f"largest must be a positive length [m], got {largest!r}")
    if int(count) != count or count < 1:
        raise ValueError(f"count must be a positive integer, got {count!r}")
    if not ratio > 1:
        raise ValueError(f"ratio must be > 1, got {ratio!r}")
    return tuple(float(largest / ratio**i) for i in range(int(count)))


def cascade_band_edges(grids: Sequence[OceanGrid]) -> tuple[float, ...]:
    """Wavenumber edges 0 = k_0 < k_1 < … < k_n of the bands of nested patches [rad m⁻¹].

    Parameters
    ----------
    grids : sequence of OceanGrid
        The patches, largest first.

    Returns
    -------
    tuple of float
        n + 1 edges: k_i = √((2π/L_i) (π N_{i−1}/L_{i−1})) for 0 < i < n, and
        k_n = π N_{n−1}/L_{n−1}, the Nyquist wavenumber of the finest patch.

    Raises
    ------
    ValueError
        If the patches do not shrink, or a patch would carry no mode beyond
        its fundamental: every band needs k_i > 2π/L_i and k_{i+1} below the
        Nyquist wavenumber of patch i.
    """
    edges = [0.0]
    for coarse, fine in zip(grids[:-1], grids[1:]):
        if not fine.patch_size < coarse.patch_size:
            raise ValueError("patches must be given largest first, each smaller than the one before")
        edges.append(float(np.sqrt(fine.dk * coarse.nyquist_wavenumber)))
    edges.append(float(grids[-1].nyquist_wavenumber))
    for i, grid in enumerate(grids):
        if not (edges[i + 1] > edges[i] and edges[i + 1] <= grid.nyquist_wavenumber and edges[i + 1] > grid.dk):
            raise ValueError(f"patch {i} (L = {grid.patch_size} m, N = {grid.resolution}) has an empty band "
                             f"[{edges[i]:.4g}, {edges[i + 1]:.4g}) rad/m: use more points or a smaller size ratio")
    return tuple(edges)


def cascade_band_edges_resolved(grids: Sequence[OceanGrid], points_per_wavelength: float) -> tuple[float, ...]:
    """Band edges that end each patch's band where its grid still has ``points_per_wavelength`` [rad m⁻¹].

    Parameters
    ----------
    grids : sequence of OceanGrid
        The patches, largest first.
    points_per_wavelength : float
        p > 2: the top of band i is k_{i+1} = 2π / (p Δ_i), Δ_i the grid
        spacing of patch i, so its shortest wave spans p grid points.

    Returns
    -------
    tuple of float
        n + 1 edges 0 = k_0 < k_1 < … < k_n.

    Notes
    -----
    Unlike :func:`cascade_band_edges` (the geometric mean of one patch's
    Nyquist wavenumber and the next one's fundamental), this keeps every band
    p points per wavelength away from its own grid's limit, where bilinear
    interpolation of the patch damps a mode's power by at most 1 − (2 +
    cos(2π/p))²/9 (17 % at p = 6, against 67 % at the Nyquist wavenumber), and
    lets the largest patch carry waves down to p of its cells: a 2.4 km patch
    on 1024² points holds the peak of a 10 m/s sea, so the surface does not
    repeat at the period of a smaller patch.

    Raises
    ------
    ValueError
        If the patches do not shrink, p ≤ 2, or a band holds no mode of its
        patch's lattice. (A band that starts within a few fundamentals of its
        patch samples its bottom coarsely: k_i/Δk_i = N/(p r) for patches of
        ratio r on N points, 39 at N = 1024, p = 6, r = 4.39.)
    """
    if not points_per_wavelength > 2:
        raise ValueError(f"points_per_wavelength must be > 2, got {points_per_wavelength!r}")
    edges = [0.0]
    for coarse, fine in zip(grids[:-1], grids[1:]):
        if not fine.patch_size < coarse.patch_size:
            raise ValueError("patches must be given largest first, each smaller than the one before")
        edges.append(2.0 * np.pi / (points_per_wavelength * coarse.spacing))
    edges.append(2.0 * np.pi / (points_per_wavelength * grids[-1].spacing))
    for i, grid in enumerate(grids):
        if not (edges[i + 1] > edges[i] and edges[i + 1] > grid.dk):
            raise ValueError(f"patch {i} (L = {grid.patch_size} m, N = {grid.resolution}) has an empty band "
                             f"[{edges[i]:.4g}, {edges[i + 1]:.4g}) rad/m: "
                             "use more points or a smaller size ratio")
    return tuple(edges)


def annulus_fraction(
    kx: ArrayLike, ky: ArrayLike, k_min: float, k_max: float, cell: float = 0.0, subsamples: int = 16
) -> NDArray[np.float64]:
    """Fraction of the lattice cell centred on (kx, ky) that lies in k_min ≤ |k| < k_max [-].

    Parameters
    ----------
    kx, ky : array_like
        Cell centres [rad m⁻¹].
    k_min, k_max : float
        Edges of the annulus [rad m⁻¹].
    cell : float, optional
        Side Δk of the square cell [rad m⁻¹]; 0 gives the indicator of the centre.
    subsamples : int, optional
        Sub-cells per side used for the cells that an edge crosses.

    Returns
    -------
    ndarray
        Fraction in [0, 1]; 0 or 1 away from the edges.

    Notes
    -----
    The lattice sum Σ Ψ(k) Δk² is the midpoint rule of ∫∫ Ψ dk. With the plain
    indicator a cell on a band edge counts fully or not at all, an error of
    order Δk along the edge; for a k⁻⁴ spectrum, whose variance crowds at the
    inner edge of each band, it reached 4 % of a band's variance. Weighting
    the edge cells by their area inside the band leaves the second-order error
    of the midpoint rule. Adjacent bands share an edge, so the weights of one
    wavenumber over all bands add up to 1.
    """
    kx, ky = np.broadcast_arrays(np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64))
    k = np.hypot(kx, ky)
    fraction = ((k >= k_min) & (k < k_max)).astype(np.float64)
    if cell > 0:
        reach = cell / np.sqrt(2)  # half the diagonal: farther cells are not crossed
        near = (np.abs(k - k_max) < reach) | ((k_min > 0) & (np.abs(k - k_min) < reach))
        offsets = ((np.arange(subsamples) + 0.5) / subsamples - 0.5) * cell
        sub_k = np.hypot(kx[near][:, None, None] + offsets[None, :, None], ky[near][:, None, None] + offsets[None, None, :])
        fraction[near] = np.mean((sub_k >= k_min) & (sub_k < k_max), axis=(1, 2))
    return fraction


@dataclass(frozen=True)
class BandLimitedSpectrum:
    """Ψ(kx, ky) times the share of the annulus k_min ≤ |k| < k_max in the lattice cell at k [m⁴].

    Parameters
    ----------
    spectrum : callable
        Ψ(kx, ky) → ndarray [m⁴], wavenumbers in rad m⁻¹.
    k_min, k_max : float
        Edges of the annulus [rad m⁻¹]; k_min inclusive, k_max exclusive.
    cell : float, optional
        Lattice spacing Δk of the patch that samples it [rad m⁻¹]; cells
        crossed by an edge get the fraction of their area inside
        (:func:`annulus_fraction`). 0 (default) cuts at the cell centres.
    """

    spectrum: Callable[[NDArray, NDArray], NDArray]
    k_min: float
    k_max: float
    cell: float = 0.0

    def __call__(self, kx: ArrayLike, ky: ArrayLike) -> NDArray[np.float64]:
        kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
        weight = annulus_fraction(kx, ky, self.k_min, self.k_max, self.cell)
        inside = weight > 0
        psi = np.zeros(weight.shape)
        psi[inside] = np.broadcast_to(np.asarray(self.spectrum(kx, ky), dtype=np.float64), weight.shape)[inside]
        return psi * weight


@dataclass(frozen=True, eq=False)
class SurfaceSample:
    """The summed sea surface at arbitrary undisplaced points (shapes of the query points).

    Attributes
    ----------
    height : ndarray
        Elevation η [m].
    displacement_x, displacement_y : ndarray
        Horizontal displacement λ D [m]: the surface point above (x, y) at
        rest sits at (x + displacement_x, y + displacement_y, height).
    slope_x, slope_y : ndarray
        ∂η/∂x, ∂η/∂y with respect to the undisplaced coordinates [-].
    jacobian : ndarray
        Determinant of the summed horizontal map [-].
    normals : ndarray, shape (..., 3)
        Unit normal of the displaced surface [-].
    jacobian_xx, jacobian_yy, jacobian_xy : ndarray
        Entries of the Jacobian matrix of the summed horizontal map [-].
    """

    height: NDArray[np.floating]
    displacement_x: NDArray[np.floating]
    displacement_y: NDArray[np.floating]
    slope_x: NDArray[np.floating]
    slope_y: NDArray[np.floating]
    jacobian: NDArray[np.floating]
    normals: NDArray[np.floating]
    jacobian_xx: NDArray[np.floating]
    jacobian_yy: NDArray[np.floating]
    jacobian_xy: NDArray[np.floating]


#: Quantities interpolated per patch, in the order of :meth:`CascadeFrame.stacks`;
#: the Jacobian-matrix entries enter as deviations from the identity, which add.
_SAMPLED = ("height", "displacement_x", "displacement_y", "slope_x", "slope_y", "xx", "yy", "xy")


def sampled_field(fields: OceanFields, name: str) -> NDArray:
    """One interpolated quantity of a patch's fields, by its name in :data:`SAMPLED` (J entries minus the identity)."""
    if name == "xx":
        return fields.jacobian_xx - 1
    if name == "yy":
        return fields.jacobian_yy - 1
    if name == "xy":
        return fields.jacobian_xy
    return getattr(fields, name)


#: Public name of the sampled quantities (used by :mod:`oceanrender.waves.sea`).
SAMPLED = _SAMPLED


def _bilinear_corners(grid: OceanGrid, x: NDArray, y: NDArray):
    """Flat indices of the 4 surrounding nodes and their bilinear weights, periodic in L."""
    n = grid.resolution

    def axis(coordinate):
        u = (coordinate + grid.patch_size / 2) / grid.spacing
        nearest = np.rint(u)
        # NOTE: points within 1e-9 cells of a node take the node's value exactly,
        # so sampling on a patch's own grid reproduces its fields bit for bit.
        u = np.where(np.abs(u - nearest) < 1e-9, nearest, u)
        lower = np.floor(u)
        fraction = u - lower
        i0 = lower.astype(np.int64)
        i0 %= n
        i1 = i0 + 1
        i1[i1 == n] = 0
        return i0, i1, fraction

    ix0, ix1, fx = axis(x)
    iy0, iy1, fy = axis(y)
    corners = (iy0 * n + ix0, iy0 * n + ix1, iy1 * n + ix0, iy1 * n + ix1)
    weights = ((1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy)
    return corners, weights


#: Public name of the periodic bilinear stencil (used by :mod:`oceanrender.waves.sea`).
bilinear_corners = _bilinear_corners


@dataclass(frozen=True, eq=False)
class CascadeFrame:
    """The fields of every patch at one time, ready to be sampled anywhere.

    Parameters
    ----------
    grids : tuple of OceanGrid
        The patches, largest first.
    fields : tuple of OceanFields
        Each patch's fields at time ``time``.
    time : float
        Time [s].
    """

    grids: tuple[OceanGrid, ...]
    fields: tuple[OceanFields, ...]
    time: float

    @cached_property
    def stacks(self) -> tuple[NDArray[np.floating], ...]:
        """Per patch, the 8 sampled quantities interleaved, shape (N², 8), so one gather fetches all."""
        stacks = []
        for f in self.fields:
            n = f.resolution
            stack = np.empty((n, n, len(_SAMPLED)), f.height.dtype)
            for i, name in enumerate(_SAMPLED):
                stack[..., i] = sampled_field(f, name)
            stacks.append(stack.reshape(n * n, len(_SAMPLED)))
        return tuple(stacks)

    def sample(self, x: ArrayLike, y: ArrayLike, cascades: Sequence[int] | None = None) -> SurfaceSample:
        """The summed surface at undisplaced points (x, y) [m]; see :class:`SurfaceSample`.

        Parameters
        ----------
        x, y : array_like
            Undisplaced (rest) coordinates, east and north [m]; broadcast together.
        cascades : sequence of int, optional
            Indices of the patches to sum; all by default.

        Returns
        -------
        SurfaceSample
            Bilinear periodic interpolation of each patch's fields, summed;
            the Jacobian and the normal are those of the summed map.

        Notes
        -----
        Bilinear interpolation reproduces the nodes exactly; in between it
        damps a mode of wavenumber k by the mean power gain
        (2 + cos kx Δ)(2 + cos ky Δ)/9 at random points (Δ the patch's grid
        spacing): 0.90 for a wave along x with 8 points per wavelength, 1/3 at the Nyquist
        wavenumber, so the finest patch's top octave is smoothed.

        Interpolating the derivative fields (slopes, ∂D) rather than
        differentiating the interpolated height keeps them spectral-accurate
        at the nodes and continuous in between.
        """
        x, y = np.broadcast_arrays(np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64))
        selected = range(len(self.fields)) if cascades is None else list(cascades)
        dtype = np.result_type(*(self.fields[i].height.dtype for i in selected)) if selected else np.float64
        total = np.zeros((*x.shape, len(_SAMPLED)), dtype)
        for i in selected:
            corners, weights = _bilinear_corners(self.grids[i], x, y)
            stack = self.stacks[i]
            for corner, weight in zip(corners, weights):
                gathered = np.take(stack, corner, axis=0)  # (..., 8): one gather per corner
                gathered *= weight.astype(dtype)[..., None]
                total += gathered
        height, dx, dy, slope_x, slope_y, xx, yy, xy = np.moveaxis(total, -1, 0)
        jxx, jyy = xx + 1, yy + 1
        jacobian = jxx * jyy - xy * xy
        normal = np.stack([xy * slope_y - jyy * slope_x, xy * slope_x - jxx * slope_y, jacobian], axis=-1)
        normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
        return SurfaceSample(height, dx, dy, slope_x, slope_y, jacobian, normal, jxx, jyy, xy)


@dataclass(frozen=True)
class CascadeOcean:
    """A sea summed from FFT patches of incommensurate sizes, one wavenumber band each.

    Parameters
    ----------
    spectrum : callable
        Directional wavenumber spectrum Ψ(kx, ky) → ndarray [m⁴] (wavenumbers
        in rad m⁻¹), e.g. ``functools.partial(spectrum_Phillips2001,
        wind_speed=8.0, wind_direction=0.3)``.
    patch_sizes : sequence of float
        Patch sides L_i, largest first [m] (:func:`cascade_patch_sizes`).
    resolution : int or sequence of int
        Grid points per side, one for all patches or one per patch [-].
    seed : int, optional
        Random seed; patch i hashes (seed, i) into its noise.
    choppiness : float, optional
        Horizontal displacement scale λ [-].
    depth : float, optional
        Water depth of the dispersion relation [m].
    surface_tension : float, optional
        Surface tension σ of the dispersion relation [N m⁻¹]; 0: gravity waves.
    loop_period : float, optional
        Period after which the whole sea repeats [s] (same T for every patch).
    band_edges : sequence of float, optional
        The n + 1 edges k_0 = 0 < … < k_n [rad m⁻¹]; :func:`cascade_band_edges` by default.
    g : float, optional
        Gravitational acceleration [m s⁻²].
    dtype : dtype_like, optional
        Precision of the patch fields.
    fft_backend : str, optional
        FFT library.
    workers : int, optional
        Threads per patch frame.

    Examples
    --------
    >>> from functools import partial
    >>> from oceanrender.waves.wave_spectra import spectrum_Phillips2001
    >>> sea = CascadeOcean(partial(spectrum_Phillips2001, wind_speed=8.0, wind_direction=0.0),
    ...                    cascade_patch_sizes(500.0, 3), 64, seed=1)
    >>> sea.fields_at(np.array([0.0, 1234.5]), np.array([0.0, -20.0]), t=3.0).height.shape
    (2,)
    """

    spectrum: Callable[[NDArray, NDArray], NDArray]
    patch_sizes: tuple[float, ...]
    resolution: int | tuple[int, ...] = 256
    seed: int = 0
    choppiness: float = 1.0
    depth: float = np.inf
    loop_period: float | None = None
    band_edges: tuple[float, ...] | None = None
    g: float = GRAVITY
    surface_tension: float = 0.0
    dtype: DTypeLike = np.float32
    fft_backend: str = "auto"
    workers: int | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "patch_sizes", tuple(float(size) for size in self.patch_sizes))
        count = len(self.patch_sizes)
        if count < 1:
            raise ValueError("at least one patch size is needed")
        resolutions = (self.resolution,) * count if np.ndim(self.resolution) == 0 else tuple(self.resolution)
        if len(resolutions) != count:
            raise ValueError(f"{count} patches but {len(resolutions)} resolutions")
        object.__setattr__(self, "resolution", tuple(int(n) for n in resolutions))
        if self.band_edges is None:
            object.__setattr__(self, "band_edges", cascade_band_edges(self.grids))
        else:
            edges = tuple(float(k) for k in self.band_edges)
            if len(edges) != count + 1 or edges[0] != 0 or np.any(np.diff(edges) <= 0):
                raise ValueError(f"band_edges must be {count + 1} increasing wavenumbers from 0, got {edges}")
            object.__setattr__(self, "band_edges", edges)

    @cached_property
    def grids(self) -> tuple[OceanGrid, ...]:
        """The patches' grids, largest first."""
        return tuple(OceanGrid(n, size) for n, size in zip(self.resolution, self.patch_sizes))

    @cached_property
    def cascades(self) -> tuple[FFTOcean, ...]:
        """One :class:`~oceanrender.waves.fft_ocean.FFTOcean` per patch, carrying its band."""
        edges = self.band_edges
        return tuple(
            FFTOcean(grid, seed=self.seed, choppiness=self.choppiness, depth=self.depth, g=self.g,
                     surface_tension=self.surface_tension, dtype=self.dtype,
                     spectrum_function=BandLimitedSpectrum(self.spectrum, edges[i], edges[i + 1], grid.dk),
                     loop_period=self.loop_period, cascade=i, fft_backend=self.fft_backend, workers=self.workers)
            for i, grid in enumerate(self.grids)
        )

    @property
    def elevation_variance(self) -> float:
        """Expected elevation variance of the summed sea, Σ over patches of Σ Ψ Δk² [m²]."""
        return float(sum(ocean.elevation_variance for ocean in self.cascades))

    @property
    def significant_wave_height(self) -> float:
        """Expected significant wave height 4 √m0 of the summed sea [m]."""
        return 4 * np.sqrt(self.elevation_variance)

    def frame(self, t: float) -> CascadeFrame:
        """Every patch's fields at time t [s], to sample with :meth:`CascadeFrame.sample`."""
        return CascadeFrame(self.grids, tuple(ocean.fields(t) for ocean in self.cascades), float(t))

    def fields_at(self, x: ArrayLike, y: ArrayLike, t: float, cascades: Sequence[int] | None = None) -> SurfaceSample:
        """The summed surface at undisplaced points (x, y) [m] at time t [s].

        Computes every patch's FFT fields at t; to sample several point sets
        at one time, keep ``frame = ocean.frame(t)`` and call ``frame.sample``.
        """
        return self.frame(t).sample(x, y, cascades)
