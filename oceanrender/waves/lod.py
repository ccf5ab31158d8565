"""Level of detail that filters by wavenumber: every vertex keeps the waves its spacing resolves.

A mesh vertex spaced Δ from its neighbours can carry a wave of length λ only
if λ is a few Δ long: at λ = 2Δ (the Nyquist limit) a wave aliases into a
pattern of the wrong length and direction, and at a few Δ its
piecewise-linear reconstruction facets. The resolution rule used here:

* waves at least 8 vertices long (λ ≥ 8Δ) are kept at full amplitude,
* waves at most 2 vertices long (λ ≤ 2Δ, the Nyquist limit) are removed,
* in between the amplitude fades continuously with Δ (by octaves, below),

so a cascade is never dropped as a whole: its long waves reach as far as the
mesh resolves them (a 2.4 km wave survives on vertices 300 m apart). What is
removed is not lost: its slope variance moves into the surface BSDF's
roughness (:meth:`CascadeLevels.resolved_variance`; Bruneton, Neyret &
Holzschuch 2010, §4), so the mean appearance does not change with distance.

How. Each cascade's band [k_lo, k_top) is stored as a pyramid of low-passed
copies (levels): level j holds the modes |k| < K_j = k_top / 2^j of the band
on a grid just fine enough for them (:data:`LEVEL_POINTS_PER_WAVELENGTH`
points per shortest wavelength), an exact spectral prefilter (the common modes
have identical amplitudes, since the noise is hashed per mode). A vertex of
spacing Δ sits at the fractional level s = log₂(k_top / k_f) with
k_f = 2π / (:data:`FADE_VERTICES_PER_WAVELENGTH` Δ) = π/(2Δ), and takes
(1 − f) level ⌊s⌋ + f level ⌊s⌋ + 1 with f = s − ⌊s⌋. A mode of the octave
[K_{m+1}, K_m) is whole while k_f ≥ K_m, fades as k_f falls from K_m to
K_{m+1}, and is gone below: whole for k ≤ k_f/2 (λ ≥ 8Δ), gone for
k ≥ 2 k_f = π/Δ (λ ≤ 2Δ).

This is the mip-map prefiltering of Bruneton et al. (2010) done in the
Fourier domain (each level is its own inverse FFT of the lower modes), rather
than by box-filtering the finest map.

References
----------
.. [1] E. Bruneton, F. Neyret and N. Holzschuch, "Real-time realistic ocean
   lighting using seamless transitions from geometry to BRDF", Computer
   Graphics Forum 29(2), 487–496, 2010, doi:10.1111/j.1467-8659.2009.01618.x.
.. [2] L. Williams, "Pyramidal parametrics", SIGGRAPH 1983 (mip-maps).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from .fft_ocean import FFTOcean, OceanGrid

__all__ = [
    "FADE_VERTICES_PER_WAVELENGTH",
    "LEVEL_POINTS_PER_WAVELENGTH",
    "fade_wavenumber",
    "level_coordinate",
    "level_weights",
    "bilinear_power_gain",
    "level_cutoffs",
    "level_resolution",
    "GainCompensated",
    "CascadeLevels",
]

FADE_VERTICES_PER_WAVELENGTH: float = 4.0
"""Vertices per wavelength at the centre of the fade [-]: waves twice as long are whole, half as long gone."""

LEVEL_POINTS_PER_WAVELENGTH: float = 6.0
"""Grid points per shortest wavelength of a level (and of a cascade's band top) [-].

Bilinear interpolation of a grid damps a mode by the mean power gain
(2 + cos k_x Δ)(2 + cos k_y Δ)/9 (:func:`bilinear_power_gain`): 0.83 for a
wave 6 points long, along an axis or a diagonal, against 0.67 at 4 points
and 1/3 at the Nyquist wavenumber. Each level's amplitudes are divided by
√g (:class:`GainCompensated`), so the interpolated surface has the
spectrum's variance on average over positions; 6 points keep that boost
under 10 % in amplitude.
"""


def fade_wavenumber(spacing: NDArray) -> NDArray:
    """k_f = 2π / (4 Δ), the wavenumber at the centre of the fade at vertex spacing Δ [rad m⁻¹]."""
    return 2.0 * np.pi / (FADE_VERTICES_PER_WAVELENGTH * np.maximum(np.asarray(spacing, dtype=float), 1e-12))


def level_coordinate(spacing: NDArray, top: float, levels: int) -> NDArray:
    """Fractional pyramid level s = log₂(k_top / k_f) of vertices spaced Δ, in [0, levels − 1] [-].

    Parameters
    ----------
    spacing : array_like   Vertex spacing Δ [m].
    top : float            Band top k_top of the cascade, the cutoff of level 0 [rad m⁻¹].
    levels : int           Levels of the pyramid, the last one empty (no mode below its cutoff).
    """
    return np.clip(np.log2(top / fade_wavenumber(spacing)), 0.0, levels - 1.0)


def level_weights(spacing: NDArray, top: float, levels: int) -> NDArray:
    """Weight of each level at each vertex, shape (levels, *spacing.shape) [-].

    (1 − f) on level ⌊s⌋ and f on level ⌊s⌋ + 1 (s of :func:`level_coordinate`);
    the weights of a vertex add up to 1.
    """
    s = level_coordinate(spacing, top, levels)
    low = np.minimum(np.floor(s).astype(np.int64), levels - 1)
    frac = s - low
    weights = np.zeros((levels, *np.shape(s)))
    np.put_along_axis(weights, low[None], (1.0 - frac)[None], axis=0)
    upper = np.minimum(low + 1, levels - 1)
    # NOTE: at the last level frac = 0, so adding to the same row changes nothing
    weights += np.where(np.arange(levels).reshape(-1, *([1] * np.ndim(s))) == upper[None], frac[None], 0.0)
    return weights


def bilinear_power_gain(kx: NDArray, ky: NDArray, cell: float) -> NDArray:
    """Mean power gain of bilinear interpolation of a plane wave (kx, ky) on a grid of cell Δ [-].

    Linear interpolation of cos(kx + φ) from nodes Δ apart, at a random
    point and phase, has mean square (2 + cos kΔ)/6 against 1/2 for the wave;
    bilinear interpolation is the product of the two axes:
    g = (2 + cos k_x Δ)(2 + cos k_y Δ)/9. 1 at k = 0, 1/9 at the grid's corner mode.
    """
    return (2.0 + np.cos(np.asarray(kx) * cell)) * (2.0 + np.cos(np.asarray(ky) * cell)) / 9.0


def level_cutoffs(band_bottom: float, band_top: float, fundamental: float) -> tuple[float, ...]:
    """Cutoffs K_j = k_top / 2^j of a band's levels, down to the first one below the band [rad m⁻¹].

    The last cutoff is ≤ max(k_lo, Δk/2): that level holds no mode (Δk/2
    keeps even the fundamental's lattice cell, whose nearest corner is at
    Δk/√2, out of it).
    """
    floor = max(band_bottom, fundamental / 2.0)
    cutoffs = [band_top]
    while cutoffs[-1] > floor:
        cutoffs.append(cutoffs[-1] / 2.0)
    return tuple(cutoffs)


def level_resolution(cutoff: float, patch_size: float, finest: int) -> int:
    """Grid points per side for a level of cutoff K on a patch of side L: a power of 2, at most ``finest`` [-].

    The smallest power of two (at least 8) with :data:`LEVEL_POINTS_PER_WAVELENGTH`
    points per wavelength 2π/K, i.e. N ≥ p K L / (2π).
    """
    needed = LEVEL_POINTS_PER_WAVELENGTH * cutoff * patch_size / (2.0 * np.pi)
    return int(min(finest, max(8, 2 ** int(np.ceil(np.log2(max(needed, 1.0)))))))


@dataclass(frozen=True)
class GainCompensated:
    """Ψ(k) / g(k): a spectrum whose modes, bilinearly interpolated from a grid of cell Δ, keep their power [m⁴].

    Parameters
    ----------
    spectrum : callable   Ψ(kx, ky) [m⁴].
    cell : float          Grid spacing Δ of the patch that samples it [m].

    Notes
    -----
    Bilinear interpolation multiplies a mode's expected power by g(k)
    (:func:`bilinear_power_gain`); drawing its amplitude from Ψ/g makes the
    interpolated surface's expected power Ψ at every k (the idea of the
    prefilter of interpolating splines, Unser 1999, §III), while the grid
    nodes themselves carry slightly more (at most 1/0.69 in power at
    :data:`LEVEL_POINTS_PER_WAVELENGTH` = 6).
    """

    spectrum: object
    cell: float

    def __call__(self, kx, ky):
        kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
        return self.spectrum(kx, ky) / bilinear_power_gain(kx, ky, self.cell)


@dataclass(frozen=True, eq=False)
class CascadeLevels:
    """The low-passed levels of one cascade, level 0 being the whole band.

    Parameters
    ----------
    grid : OceanGrid
        The cascade's grid (level 0).
    band_bottom, band_top : float
        Edges of its band [rad m⁻¹].
    make_level : callable
        ``make_level(grid, k_max) -> FFTOcean``: the cascade (seed, noise
        index, λ, depth, loop period) on ``grid`` with its band cut at
        ``k_max`` and its amplitudes compensated for bilinear interpolation
        (:class:`GainCompensated`).
    """

    grid: OceanGrid
    band_bottom: float
    band_top: float
    make_level: object

    @cached_property
    def cutoffs(self) -> tuple[float, ...]:
        """K_j of each level [rad m⁻¹]; the last level is empty."""
        return level_cutoffs(self.band_bottom, self.band_top, self.grid.dk)

    @property
    def count(self) -> int:
        """Number of levels, the empty last one included [-]."""
        return len(self.cutoffs)

    @cached_property
    def oceans(self) -> tuple[FFTOcean | None, ...]:
        """One FFT ocean per level (None for the empty last one)."""
        oceans: list[FFTOcean | None] = [self.make_level(self.grid, self.band_top)]
        for cutoff in self.cutoffs[1:-1]:
            n = level_resolution(cutoff, self.grid.patch_size, self.grid.resolution)
            oceans.append(self.make_level(OceanGrid(n, self.grid.patch_size), cutoff))
        oceans.append(None)
        return tuple(oceans)

    def weights(self, spacing: NDArray | None, shape: tuple[int, ...]) -> NDArray:
        """Level weights (count, *shape) at vertices of ``spacing`` [m]; ``None``: level 0 everywhere."""
        if spacing is None:
            weights = np.zeros((self.count, *shape))
            weights[0] = 1.0
            return weights
        return level_weights(np.broadcast_to(spacing, shape), self.band_top, self.count)

    def _gram(self, slope: bool) -> NDArray:
        """G[a, b] = Σ P(k) over the modes of level max(a, b): the height (or slope) power levels a and b share.

        P(k) is the interpolated power of a mode, Ψ Δk² (× k² for the slope,
        the slope spectrum of Phillips 1977, §4.7) [m² or -]: the level's
        amplitudes undo the interpolation's gain (:class:`GainCompensated`).
        """
        levels = self.count - 1
        gram = np.zeros((self.count, self.count))
        for b in range(levels):
            ocean = self.oceans[b]
            grid = ocean.grid
            power = ocean.spectrum_values * bilinear_power_gain(grid.kx, grid.ky, grid.spacing) * grid.dk**2
            power = power * grid.mode_mask * (grid.k**2 if slope else 1.0)
            gram[: b + 1, b] = gram[b, : b + 1] = float(np.sum(power))
        return gram

    @cached_property
    def _grams(self) -> tuple[NDArray, NDArray]:
        return self._gram(False), self._gram(True)

    def resolved_variance(self, weights: NDArray) -> tuple[NDArray, NDArray]:
        """Expected (height variance [m²], slope variance ⟨s_x² + s_y²⟩ [-]) the vertices carry.

        Parameters
        ----------
        weights : ndarray, shape (count, ...)
            Level weights of the vertices (:meth:`weights`).

        Notes
        -----
        A vertex's field is Σ_j w_j F_j, F_j the interpolated level j. A mode
        of wavenumber k is in every level whose cutoff exceeds |k|, with the
        same phase (hashed noise) and, after interpolation, on average the
        same power P(k), so its expected power at the vertex is
        P(k) (Σ_{j: K_j > |k|} w_j)², and the vertex carries wᵀ G w
        (G of :meth:`_gram`). The difference between two levels' interpolation
        errors is neglected (second order in k Δ).
        """
        heights, slopes = self._grams
        w = np.moveaxis(np.asarray(weights, dtype=float), 0, -1)
        return np.einsum("...a,ab,...b->...", w, heights, w), np.einsum("...a,ab,...b->...", w, slopes, w)
