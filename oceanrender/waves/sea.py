"""From the scene's ``[ocean]`` settings to a sea surface sampled on the render mesh.

This is the model-chain layer of the geometry stage (pvlib's three layers):
:func:`directional_spectrum` turns the settings into the spectrum object,
:func:`build_sea` into a surface model (FFT cascades, sum of sines or Gerstner
waves), and :class:`SeaSurface` samples it where the renderer's mesh has its
vertices, fading out, per vertex, the waves that the local vertex spacing
cannot carry (they would alias into noise; their slopes are accounted for by
the surface roughness instead).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..scene import OceanSettings
from .cascades import CascadeOcean, SurfaceSample, bilinear_corners, cascade_patch_sizes
from .fractal import estimate_fbm_parameters, fractal_detail
from .gerstner import gerstner_fields, sum_of_sines_fields, wave_components_from_spectrum
from .wave_spectra import DirectionalSpectrum


def directional_spectrum(ocean: OceanSettings) -> DirectionalSpectrum:
    """The scene's directional wavenumber spectrum Ψ(kx, ky) [m⁴] (angles converted to rad)."""
    return DirectionalSpectrum(
        method=ocean.spectrum,
        spreading=ocean.spreading,
        wind_speed=ocean.wind_speed,
        wind_direction=math.radians(ocean.wind_direction),
        fetch=ocean.fetch,
        gamma=ocean.gamma,
        depth=ocean.wave_depth,
        small_wave_length=ocean.small_wave_length,
        alpha=ocean.alpha,
        swell_height=ocean.swell_height,
        swell_period=ocean.swell_period,
        swell_direction=math.radians(ocean.swell_direction),
        swell_spreading_s=ocean.swell_spreading_s,
    )


def lod_weight(spacing: NDArray, cell: float) -> NDArray:
    """Weight in [0, 1] of a wave band with grid cell ``cell`` [m] at vertex ``spacing`` [m].

    1 where the vertices are at least as fine as the band's own grid, 0 where
    they are four times coarser (its shortest waves, 2·cell long, would be
    sampled at fewer than half a vertex per wavelength), linear in log₂ between.
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

    With ``fractal_gamma`` > 0 the fractal detail of :class:`FractalDetail`
    is added, ζ = η + γ η_fractal (heights and slopes), fading out with the
    mesh's vertex spacing like the cascades. NOTE: the detail is a static tile
    (it has no dispersion): it adds texture below the finest FFT waves, not motion.
    """

    def __init__(self, ocean: OceanSettings):
        self.settings = ocean
        self.spectrum = directional_spectrum(ocean)
        if ocean.model == "FFT":
            self.cascades = CascadeOcean(
                self.spectrum,
                cascade_patch_sizes(ocean.patch_size, ocean.cascades),
                resolution=ocean.resolution,
                seed=ocean.seed,
                choppiness=ocean.choppiness,
                depth=ocean.wave_depth,
                loop_period=ocean.loop_period or None,
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

    @property
    def finest_cell(self) -> float:
        """Grid cell of the finest resolved waves [m] (half their wavelength)."""
        return self.settings.patch_size / self.settings.resolution if self.cascades is None else min(
            g.spacing for g in self.cascades.grids)

    def sample(self, x: NDArray, y: NDArray, t: float, spacing: NDArray | None = None) -> SurfacePoints:
        """The surface above rest points (x, y) [m] at time t [s].

        ``spacing`` [m], per point, fades out the cascades too fine for it
        (:func:`lod_weight`); ``None`` keeps every wave.
        """
        if self.cascades is None:
            return self._sample_components(x, y, t)
        frame = self.cascades.frame(t)
        total = np.zeros((8, *np.shape(x)))
        for i, grid in enumerate(self.cascades.grids):
            weight = 1.0 if spacing is None else lod_weight(spacing, grid.spacing)
            if np.all(weight == 0):
                continue
            s: SurfaceSample = frame.sample(x, y, cascades=[i])
            parts = (s.height, s.displacement_x, s.displacement_y, s.slope_x, s.slope_y,
                     s.jacobian_xx - 1, s.jacobian_yy - 1, s.jacobian_xy)
            total += weight * np.stack(parts)
        height, dx, dy, sx, sy, xx, yy, xy = total
        if self.fractal is not None:
            gamma = self.settings.fractal_gamma
            weight = 1.0 if spacing is None else lod_weight(spacing, self.fractal.spacing)
            detail, detail_x, detail_y = self.fractal.sample(x, y)
            height = height + gamma * weight * detail  # ζ = η + γ η_fractal
            sx, sy = sx + gamma * weight * detail_x, sy + gamma * weight * detail_y
        jxx, jyy = xx + 1, yy + 1
        return SurfacePoints(np.stack([dx, dy, height], axis=-1), _normals(jxx, jyy, xy, sx, sy), jxx * jyy - xy * xy)

    def jacobian(self, x: NDArray, y: NDArray, t: float, spacing: NDArray | None = None) -> NDArray:
        """Only the Jacobian determinant J of the horizontal map at rest points (x, y) at t [-].

        The same value as ``sample(...).jacobian`` at less than half the cost
        (three interpolated fields instead of eight): foam needs J alone.
        """
        if self.cascades is None:
            return self._sample_components(x, y, t).jacobian
        frame = self.cascades.frame(t)
        xx = np.zeros(np.shape(x))
        yy, xy = np.zeros_like(xx), np.zeros_like(xx)
        for i, grid in enumerate(self.cascades.grids):
            weight = 1.0 if spacing is None else lod_weight(spacing, grid.spacing)
            if np.all(weight == 0):
                continue
            corners, weights = bilinear_corners(grid, np.asarray(x, float), np.asarray(y, float))
            stack = frame.stacks[i][:, 5:8]  # J_xx − 1, J_yy − 1, J_xy
            part = sum(np.take(stack, c, axis=0) * w[..., None] for c, w in zip(corners, weights))
            xx += weight * part[..., 0]
            yy += weight * part[..., 1]
            xy += weight * part[..., 2]
        return (1 + xx) * (1 + yy) - xy * xy

    def _sample_components(self, x, y, t) -> SurfacePoints:
        ocean = self.settings
        if ocean.model == "Gerstner":
            f = gerstner_fields(self.components, x, y, t, depth=ocean.wave_depth, steepness=ocean.gerstner_steepness)
        else:
            f = sum_of_sines_fields(self.components, x, y, t, depth=ocean.wave_depth)
        displacement = np.stack([f.displacement_x, f.displacement_y, f.height], axis=-1)
        return SurfacePoints(displacement, f.normals, f.jacobian)
