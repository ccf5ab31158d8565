"""From the scene's ``[ocean]`` settings to a sea surface sampled on the render mesh.

This is the model-chain layer of the geometry stage (pvlib's three layers):
:func:`directional_spectrum` turns the settings into the spectrum object,
:func:`build_sea` into a surface model (FFT cascades, sum of sines or Gerstner
waves), and :class:`SeaSurface` samples it where the renderer's mesh has its
vertices, filtering, per vertex, the waves that the local vertex spacing
cannot carry by wavenumber (:mod:`.lod`: they would alias into noise), and
gives per vertex the slope variance of what it removed, which the surface
BSDF carries as roughness instead (:meth:`SeaSurface.unresolved_slope_variance`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..scene import OceanSettings
from .cascades import (SAMPLED, BandLimitedSpectrum, CascadeOcean, bilinear_corners,
                       cascade_band_edges_resolved, cascade_patch_sizes, sampled_field)
from .fft_ocean import FFTOcean, OceanGrid
from .fractal import estimate_fbm_parameters, fractal_detail
from .gerstner import gerstner_fields, sum_of_sines_fields, wave_components_from_spectrum
from .lod import LEVEL_POINTS_PER_WAVELENGTH, CascadeLevels, GainCompensated
from .query import Sampler, SurfaceSample
from .roughness import elevation_variance, unresolved_slope_variance
from .sea_state import Partition, PartitionedSpectrum, TabulatedSpectrum
from .wave_spectra import DirectionalSpectrum, make_spectrum


def directional_spectrum(ocean: OceanSettings):
    """The scene's directional wavenumber spectrum Ψ(kx, ky) [m⁴] (angles converted to rad), in its form.

    * wind: :func:`~.wave_spectra.make_spectrum` (a :class:`DirectionalSpectrum`);
    * sea state: a :class:`~.sea_state.PartitionedSpectrum` of (hs, tp, ...) and ``partitions``;
    * file: a :class:`~.sea_state.TabulatedSpectrum` of the file's E(f, θ) at the time and site.
    """
    common = {"depth": ocean.wave_depth, "small_wave_length": ocean.small_wave_length,
              "surface_tension": ocean.surface_tension}
    if ocean.form == "file":
        from ..io.spectrum_files import read_spectrum_file  # noqa: PLC0415

        table = read_spectrum_file(ocean.spectrum_file, ocean.spectrum_format, ocean.spectrum_time,
                                   ocean.spectrum_site)
        return TabulatedSpectrum(frequency=table.frequency, direction=table.direction, table=table.density,
                                 tail_exponent=ocean.spectrum_tail, **common)
    if ocean.form == "sea state":
        direction = ocean.wind_direction if ocean.direction is None else ocean.direction
        first = Partition(ocean.spectrum, ocean.hs, ocean.tp, ocean.gamma, ocean.sigma_a, ocean.sigma_b,
                          math.radians(direction), ocean.spreading_s)
        rest = tuple(Partition(p.spectrum, p.hs, p.tp, p.gamma, p.sigma_a, p.sigma_b, math.radians(p.direction),
                               p.spreading_s) for p in ocean.partitions)
        return PartitionedSpectrum(partitions=(first,) + rest, **common)
    swell = {"swell_height": ocean.swell_height, "swell_period": ocean.swell_period,
             "swell_direction": math.radians(ocean.swell_direction), "swell_spreading_s": ocean.swell_spreading_s}
    wind = {"spreading": ocean.spreading, "wind_speed": ocean.wind_speed,
            "wind_direction": math.radians(ocean.wind_direction), **swell, **common}
    if ocean.spectrum not in ("Phillips 2001", "Pierson-Moskowitz 1964"):
        wind.update(fetch=ocean.fetch, gamma=ocean.gamma)
    if ocean.alpha is not None:
        wind["alpha"] = ocean.alpha
    if ocean.spectrum == "Phillips 2001":
        wind.pop("depth")  # deep water by definition: the depth is the dispersion relation's (SeaSurface)
    return make_spectrum(ocean.spectrum, **wind)


def sea_description(ocean: OceanSettings, spectrum=None) -> dict[str, object]:
    """The sea's form and statistics for sidecars and logs: Hs [m], Tp [s], mean direction of travel [deg].

    Hs = 4 √m0 and the mean direction from the spectrum over 60 km to 1 mm
    waves (:func:`~.roughness.elevation_variance` and the energy-weighted
    circular mean); Tp = 2π/ω_p.
    """
    spectrum = directional_spectrum(ocean) if spectrum is None else spectrum
    m0 = elevation_variance(spectrum, LONGEST_WAVENUMBER, 2.0 * np.pi / SHORTEST_WAVELENGTH)
    k = np.geomspace(LONGEST_WAVENUMBER, 2.0 * np.pi / SHORTEST_WAVELENGTH, 4000)
    theta = (np.arange(360) + 0.5) * (2 * np.pi / 360)
    psi = spectrum(k[:, None] * np.cos(theta), k[:, None] * np.sin(theta)) * k[:, None]
    weights = np.trapezoid(psi, k, axis=0)
    mean = math.degrees(math.atan2(float(np.sum(weights * np.sin(theta))), float(np.sum(weights * np.cos(theta)))))
    described = {"form": ocean.form, "significant_wave_height_m": 4.0 * math.sqrt(m0),
                 "peak_period_s": 2.0 * math.pi / float(spectrum.peak_frequency), "mean_direction_deg": mean,
                 "surface_tension_N_m": ocean.surface_tension, "depth_m": ocean.wave_depth}
    if ocean.form == "file":
        described.update(spectrum_file=ocean.spectrum_file, spectrum_time=ocean.spectrum_time,
                         spectrum_site=ocean.spectrum_site)
    elif ocean.form == "sea state":
        described.update(partitions=[{"spectrum": ocean.spectrum, "hs_m": ocean.hs, "tp_s": ocean.tp,
                                      "direction_deg": ocean.wind_direction if ocean.direction is None
                                      else ocean.direction, "spreading_s": ocean.spreading_s}]
                         + [{"spectrum": p.spectrum, "hs_m": p.hs, "tp_s": p.tp, "direction_deg": p.direction,
                             "spreading_s": p.spreading_s} for p in ocean.partitions])
    else:
        described.update(spectrum=ocean.spectrum, wind_speed_10m_m_s=ocean.wind_speed, fetch_m=ocean.fetch)
    return described


#: Shortest wave of the spectrum counted in its total slope variance [m] (gravity–capillary waves;
#: shorter ones are damped by viscosity within a few periods, Phillips 1977 §3.3).
SHORTEST_WAVELENGTH = 1e-3

#: Wavenumber below which the spectrum's slope variance is left out of the total [rad m⁻¹]
#: (waves over 60 km long: nothing of any sea spectrum here).
LONGEST_WAVENUMBER = 1e-4


def elevation_std(ocean: OceanSettings) -> float:
    """Standard deviation σ_η [m] of the whole sea's elevation (wind sea and swell, 60 km to 1 mm waves).

    From the spectrum's zeroth moment (:func:`~.roughness.elevation_variance`),
    before any band limit of the geometry: an upper bound of what a mesh carries.
    """
    return float(np.sqrt(elevation_variance(directional_spectrum(ocean), LONGEST_WAVENUMBER,
                                            2.0 * np.pi / SHORTEST_WAVELENGTH)))


def _fractal_weight(spacing: NDArray, cell: float) -> NDArray:
    """Weight in [0, 1] of the fractal tile (grid cell ``cell`` [m]) at vertex ``spacing`` [m].

    1 where the vertices are at least as fine as the tile's grid, 0 where
    they are four times coarser, linear in log₂ between.
    """
    return np.clip(1.0 - np.log2(np.maximum(spacing, 1e-12) / cell) / 2.0, 0.0, 1.0)


def _normals(jxx, jyy, jxy, sx, sy):
    """Unit normals of the displaced surface from its horizontal Jacobian and slopes."""
    normal = np.stack([jxy * sy - jyy * sx, jxy * sx - jxx * sy, jxx * jyy - jxy * jxy], axis=-1)
    normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
    return normal


@dataclass(frozen=True)
class SurfacePoints:
    """The displaced surface at a set of rest points.

    Attributes
    ----------
    displacement : (..., 3) ndarray   (dx, dy, η) [m].
    normals : (..., 3) ndarray        Unit normals of the displaced surface.
    jacobian : (...) ndarray          Determinant of the horizontal map [-] (folding where < 0).
    """

    displacement: NDArray
    normals: NDArray
    jacobian: NDArray


@dataclass(frozen=True)
class FractalDetail:
    """A periodic fBm tile continuing the base waves' statistics to smaller scales.

    Attributes
    ----------
    height, slope_x, slope_y : (M, M) ndarray   η_fractal [m] and its slopes [-].
    spacing : float                            Tile grid spacing [m].
    hurst, sigma : float                       fBm parameters H [-] and σ [m] (rms difference at 1 m).
    """

    height: NDArray
    slope_x: NDArray
    slope_y: NDArray
    spacing: float
    hurst: float
    sigma: float

    @classmethod
    def from_base(cls, base_height: NDArray, base_spacing: float, size: int, seed: int) -> "FractalDetail":
        """Estimate (H, σ) from the base heights (structure function) and synthesise the tile.

        The tile's spacing is half the base grid's, so the detail carries the
        octave just below the finest resolved waves and beyond.
        """
        fit = estimate_fbm_parameters(np.asarray(base_height, dtype=float), base_spacing)
        hurst = float(np.clip(fit.hurst, 0.05, 0.95))
        spacing = base_spacing / 2.0
        height = fractal_detail(size, spacing, hurst, fit.sigma, seed)
        # central differences on the periodic tile [-]
        slope_x = (np.roll(height, -1, axis=1) - np.roll(height, 1, axis=1)) / (2 * spacing)
        slope_y = (np.roll(height, -1, axis=0) - np.roll(height, 1, axis=0)) / (2 * spacing)
        return cls(height, slope_x, slope_y, spacing, hurst, float(fit.sigma))

    def sample(self, x: NDArray, y: NDArray) -> tuple[NDArray, NDArray, NDArray]:
        """(η, ∂η/∂x, ∂η/∂y) bilinearly interpolated at (x, y) [m], periodic."""
        n = self.height.shape[0]
        u, v = np.asarray(x, float) / self.spacing, np.asarray(y, float) / self.spacing
        i0, j0 = np.floor(u).astype(np.int64), np.floor(v).astype(np.int64)
        fu, fv = u - i0, v - j0
        i0 %= n
        j0 %= n
        i1, j1 = (i0 + 1) % n, (j0 + 1) % n
        out = []
        for field in (self.height, self.slope_x, self.slope_y):
            out.append((1 - fu) * (1 - fv) * field[j0, i0] + fu * (1 - fv) * field[j0, i1]
                       + (1 - fu) * fv * field[j1, i0] + fu * fv * field[j1, i1])
        return out[0], out[1], out[2]


class SeaSurface:
    """A sea surface model that can be sampled at arbitrary rest points at time t.

    FFT cascades end each band :data:`~.lod.LEVEL_POINTS_PER_WAVELENGTH`
    points per wavelength short of their grid's limit
    (:func:`~.cascades.cascade_band_edges_resolved`) and are sampled through
    their level pyramids (:class:`~.lod.CascadeLevels`), so a vertex keeps
    every wave its spacing resolves.

    With ``fractal_gamma`` > 0 the fractal detail of :class:`FractalDetail`
    is added, ζ = η + γ η_fractal (heights and slopes), at full weight where
    the vertex spacing resolves its grid and none where it is four times
    coarser. NOTE: the detail is a static tile (it has no dispersion): it adds
    texture below the finest FFT waves, not motion; it is not part of the
    spectrum's slope budget.
    """

    def __init__(self, ocean: OceanSettings, disturbances=(), spectrum=None):
        self.settings = ocean
        #: Ψ(kx, ky) [m⁴]: the scene's (:func:`directional_spectrum`), or ``spectrum`` (e.g. a band of it)
        self.spectrum = directional_spectrum(ocean) if spectrum is None else spectrum
        self._query_stacks: tuple[tuple, dict] | None = None  # level stacks of the last (t, spacing) queried
        #: Disturbances added to the sea (ship wakes): objects with ``sample(x, y, t) -> (η, ∂η/∂x, ∂η/∂y)``.
        self.disturbances: tuple = tuple(disturbances)
        self.levels: tuple[CascadeLevels, ...] = ()
        if ocean.model == "FFT":
            sizes = cascade_patch_sizes(ocean.patch_size, ocean.cascades)
            grids = [OceanGrid(ocean.resolution, size) for size in sizes]
            self.cascades = CascadeOcean(
                self.spectrum, sizes, resolution=ocean.resolution, seed=ocean.seed, choppiness=ocean.choppiness,
                depth=ocean.wave_depth, surface_tension=ocean.surface_tension, loop_period=ocean.loop_period or None,
                band_edges=cascade_band_edges_resolved(grids, LEVEL_POINTS_PER_WAVELENGTH),
            )
            edges = self.cascades.band_edges
            self.levels = tuple(
                CascadeLevels(grid, edges[i], edges[i + 1], self._level_maker(i, edges[i], edges[i + 1]))
                for i, grid in enumerate(self.cascades.grids)
            )
            self.components = None
        else:
            self.cascades = None
            self.components = wave_components_from_spectrum(
                self.spectrum, ocean.wave_count, ocean.seed, k_min=2 * np.pi / ocean.patch_size,
                k_max=np.pi * ocean.resolution / ocean.patch_size, patch_size=ocean.patch_size,
            )
        self.fractal = None
        if ocean.fractal_gamma > 0 and self.cascades is not None:
            finest = len(self.cascades.grids) - 1
            base = self.cascades.cascades[finest].fields(0.0).height
            self.fractal = FractalDetail.from_base(base, self.cascades.grids[finest].spacing,
                                                   ocean.fractal_size, ocean.seed)

    def _level_maker(self, cascade: int, band_bottom: float, band_top: float):
        """``make(grid, k_max)``: cascade ``cascade`` on ``grid``, its band cut at k_max, gain-compensated.

        The band's own edges weight the lattice cells they cross by area
        (:func:`~.cascades.annulus_fraction`: adjacent cascades share them);
        a level's cut below the band top is sharp, so a mode is in a level or
        not and the resolution rule of :mod:`.lod` holds mode by mode.
        """
        ocean = self.settings

        def make(grid: OceanGrid, k_max: float) -> FFTOcean:
            band = BandLimitedSpectrum(self.spectrum, band_bottom, band_top, grid.dk)
            if k_max < band_top:
                band = BandLimitedSpectrum(band, 0.0, k_max)
            return FFTOcean(grid, seed=ocean.seed, choppiness=ocean.choppiness, depth=ocean.wave_depth,
                            surface_tension=ocean.surface_tension, dtype=self.cascades.dtype, loop_period=ocean.loop_period or None, cascade=cascade,
                            spectrum_function=GainCompensated(band, grid.spacing))

        return make

    @property
    def finest_cell(self) -> float:
        """π / k_max, k_max the largest wavenumber the geometry carries [m] (half the shortest wave)."""
        if self.cascades is None:
            return self.settings.patch_size / self.settings.resolution
        return float(np.pi / self.cascades.band_edges[-1])

    @property
    def total_slope_variance(self) -> float:
        """⟨s_x² + s_y²⟩ of all the spectrum's waves, from 60 km down to 1 mm long [-]."""
        return unresolved_slope_variance(self.spectrum, LONGEST_WAVENUMBER, SHORTEST_WAVELENGTH)

    def resolved_variance(self, spacing: NDArray | None) -> tuple[NDArray, NDArray]:
        """Expected (height variance [m²], slope variance [-]) the vertices of ``spacing`` [m] carry.

        The sum over cascades of :meth:`~.lod.CascadeLevels.resolved_variance`
        (bilinear interpolation losses included); ``spacing`` None is the
        full sea of every cascade. Only for the FFT model.
        """
        if self.cascades is None:
            raise ValueError("the resolved variance is defined for the FFT model only")
        shape = np.shape(spacing) if spacing is not None else ()
        height, slope = np.zeros(shape), np.zeros(shape)
        for levels in self.levels:
            h, s = levels.resolved_variance(levels.weights(spacing, shape))
            height, slope = height + h, slope + s
        return height, slope

    def unresolved_slope_variance(self, spacing: NDArray | None) -> NDArray:
        """Slope variance the geometry at vertex spacing ``spacing`` [m] leaves out [-] (≥ 0).

        Total (:attr:`total_slope_variance`) minus what the vertices carry
        (:meth:`resolved_variance`), so the two add up to the spectrum's at
        every distance (Bruneton, Neyret & Holzschuch 2010, Eq. 4 and §4.2).
        For the sum-of-sines and Gerstner models, the waves beyond their
        largest component wavenumber.
        """
        if self.cascades is None:
            value = unresolved_slope_variance(self.spectrum, np.pi / self.finest_cell, SHORTEST_WAVELENGTH)
            return np.full(np.shape(spacing) if spacing is not None else (), value)
        distinct, inverse = np.unique(np.asarray(spacing if spacing is not None else 0.0), return_inverse=True)
        _, resolved = self.resolved_variance(None if spacing is None else distinct)
        missing = np.maximum(self.total_slope_variance - resolved, 0.0)
        return missing if spacing is None else missing[inverse].reshape(np.shape(spacing))

    def _level_stack(self, cascade: int, level: int, t: float, names: tuple[str, ...]) -> NDArray:
        """The (N², q) stack of the fields ``names`` of one level at time t [s].

        One interleaved stack, so each corner is one gather of q values; a copy (the
        fields are views of buffers the level's next synthesis reuses).
        """
        f = self.levels[cascade].oceans[level].fields(t)
        return np.stack([sampled_field(f, name) for name in names], axis=-1).reshape(-1, len(names))

    def _weighted(self, x: NDArray, y: NDArray, t: float, spacing: NDArray | None, columns: slice,
                  cache: dict | None = None) -> NDArray:
        """Σ over levels of weight × the bilinearly sampled quantities ``SAMPLED[columns]``, shape (q, *x.shape).

        Only the levels some point weights are synthesised. ``cache``: a dict of the level
        stacks of this (t, columns), filled and reused (repeated queries at one time).
        """
        names = SAMPLED[columns]
        shape = np.shape(x)
        total = np.zeros((len(names), int(np.prod(shape))))
        flat_x, flat_y = np.ravel(x), np.ravel(y)
        flat_spacing = None if spacing is None else np.ravel(np.broadcast_to(spacing, shape))
        weights = [levels.weights(flat_spacing, (flat_x.size,)) for levels in self.levels]
        for i, j in ((i, j) for i, levels in enumerate(self.levels) for j in range(levels.count - 1)):
            w = weights[i][j]
            where = np.flatnonzero(w > 0)
            if where.size == 0:
                continue
            stack = None if cache is None else cache.get((i, j))
            if stack is None:
                stack = self._level_stack(i, j, t, names)
                if cache is not None:
                    cache[(i, j)] = stack
            grid = self.levels[i].oceans[j].grid
            corners, bilinear = bilinear_corners(grid, flat_x[where], flat_y[where])
            part = sum(np.take(stack, c, axis=0) * b[:, None] for c, b in zip(corners, bilinear))
            total[:, where] += (w[where][:, None] * part).T
        return total.reshape(len(names), *shape)

    def sample(self, x: NDArray, y: NDArray, t: float, spacing: NDArray | None = None) -> SurfacePoints:
        """The surface above rest points (x, y) [m] at time t [s].

        ``spacing`` [m], per point, filters the waves by wavenumber to what
        that spacing resolves (:mod:`.lod`); ``None`` keeps every wave.
        """
        if self.cascades is None:
            if not self.disturbances:
                return self._sample_components(x, y, t)
            f = self._component_fields(x, y, t)
            height, dx, dy, sx, sy = f.height, f.displacement_x, f.displacement_y, f.slope_x, f.slope_y
            xx, yy, xy = f.jacobian_xx - 1, f.jacobian_yy - 1, f.jacobian_xy
        else:
            height, dx, dy, sx, sy, xx, yy, xy = self._weighted(np.asarray(x, float), np.asarray(y, float), t,
                                                                 spacing, slice(0, 8))
        if self.fractal is not None:
            gamma = self.settings.fractal_gamma
            weight = 1.0 if spacing is None else _fractal_weight(spacing, self.fractal.spacing)
            detail, detail_x, detail_y = self.fractal.sample(x, y)
            height = height + gamma * weight * detail  # ζ = η + γ η_fractal
            sx, sy = sx + gamma * weight * detail_x, sy + gamma * weight * detail_y
        for disturbance in self.disturbances:  # ship wakes, at the rest points (their own slopes are small)
            eta, ex, ey = disturbance.sample(x, y, t)
            height, sx, sy = height + eta, sx + ex, sy + ey
        jxx, jyy = xx + 1, yy + 1
        return SurfacePoints(np.stack([dx, dy, height], axis=-1), _normals(jxx, jyy, xy, sx, sy), jxx * jyy - xy * xy)

    def jacobian(self, x: NDArray, y: NDArray, t: float, spacing: NDArray | None = None) -> NDArray:
        """Only the Jacobian determinant J of the horizontal map at rest points (x, y) at t [-].

        The same value as ``sample(...).jacobian`` at less cost (three
        interpolated fields instead of eight): foam needs J alone.
        """
        if self.cascades is None:
            return self._sample_components(x, y, t).jacobian
        xx, yy, xy = self._weighted(np.asarray(x, float), np.asarray(y, float), t, spacing, slice(5, 8))
        return (1 + xx) * (1 + yy) - xy * xy

    def surface_sample(self, x: NDArray, y: NDArray, t: float, spacing: float | None = None,
                       disturbed: bool = True) -> SurfaceSample:
        """The sea at rest points (x, y) [m] at time t [s] as a height query needs it.

        Displacement (Dx, Dy), height η [m], slope ∂η/∂x₀, ∂η/∂y₀ and the displacement
        gradient ∇D [-], for :func:`~.query.query_height` (through :meth:`sampler`), with
        the :attr:`disturbances` (wakes) added. ``spacing`` [m]: keep only the waves a grid
        of that spacing resolves (FFT sea; :mod:`.lod`), None: every wave. ``disturbed`` False: the
        sea alone (what a floating object rides: not its own wake).
        """
        x, y = np.asarray(x, float), np.asarray(y, float)
        sample = self._undisturbed_sample(x, y, t, spacing)
        for disturbance in self.disturbances if disturbed else ():
            eta, sx, sy = disturbance.sample(x, y, t)
            sample = SurfaceSample(sample.displacement, sample.height + eta,
                                   sample.slope + np.stack([sx, sy], -1), sample.displacement_gradient)
        return sample

    def _undisturbed_sample(self, x: NDArray, y: NDArray, t: float, spacing: float | None) -> SurfaceSample:
        if self.cascades is None:
            f = self._component_fields(x, y, t)
            gradient = np.stack([np.stack([f.jacobian_xx - 1, f.jacobian_xy], -1),
                                 np.stack([f.jacobian_xy, f.jacobian_yy - 1], -1)], -2)
            return SurfaceSample(np.stack([f.displacement_x, f.displacement_y], -1), np.asarray(f.height, float),
                                 np.stack([f.slope_x, f.slope_y], -1), gradient)
        if self._query_stacks is None or self._query_stacks[0] != (t, spacing):
            self._query_stacks = ((t, spacing), {})  # Newton's steps query one time often: synthesise levels once
        cell = None if spacing is None else np.full(x.shape, float(spacing))
        height, dx, dy, sx, sy, xx, yy, xy = self._weighted(x, y, t, cell, slice(0, 8), self._query_stacks[1])
        if self.fractal is not None and spacing is None:
            gamma = self.settings.fractal_gamma
            detail, detail_x, detail_y = self.fractal.sample(x, y)
            height, sx, sy = height + gamma * detail, sx + gamma * detail_x, sy + gamma * detail_y  # ζ = η + γ η_f
        gradient = np.stack([np.stack([xx, xy], -1), np.stack([xy, yy], -1)], -2)
        return SurfaceSample(np.stack([dx, dy], -1), height, np.stack([sx, sy], -1), gradient)

    def sampler(self, t: float, spacing: float | None = None, disturbed: bool = True) -> Sampler:
        """The sea at time t [s] as a :data:`~.query.Sampler` of rest points, for height queries
        (``spacing`` [m]: the waves a grid of that spacing resolves, None: all; ``disturbed``: with wakes)."""
        return lambda x, y: self.surface_sample(x, y, t, spacing, disturbed)

    def _component_fields(self, x, y, t):
        ocean = self.settings
        if ocean.model == "Gerstner":
            return gerstner_fields(self.components, x, y, t, depth=ocean.wave_depth,
                                   steepness=ocean.gerstner_steepness)
        return sum_of_sines_fields(self.components, x, y, t, depth=ocean.wave_depth)

    def _sample_components(self, x, y, t) -> SurfacePoints:
        f = self._component_fields(x, y, t)
        displacement = np.stack([f.displacement_x, f.displacement_y, f.height], axis=-1)
        return SurfacePoints(displacement, f.normals, f.jacobian)
