"""What the renderer needs of a water body, the same for the open sea and the coast.

A body (:class:`~oceanrender.surface.open_sea.WaterBody`,
:class:`~oceanrender.surface.coastal_body.CoastalBody`) has fixed triangles
(``faces``) and, per frame time t, a :class:`FrameGeometry` (vertex positions,
normals, per-vertex foam); for the surface roughness it gives its wave spectrum,
its finest resolved cell and its total slope variance; and it may carry a
:class:`Terrain` (the coastal seafloor and beach) rendered inside the water.
All plain arrays in metres: the renderer turns them into Mitsuba shapes.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Protocol

import numpy as np
from numpy.typing import NDArray


@dataclass(frozen=True)
class FrameGeometry:
    """One frame's water body.

    Attributes
    ----------
    positions, normals : (V, 3) float32   Vertex positions [m] and unit normals.
    foam : (V,) float32 or None            Fresh-foam weight per vertex [-]: the fraction of the surface that reflects like fresh foam (open sea: whitecap coverage × its reflectance decay, docs/whitecaps.md; coast: white water), 0 off the surface.
    roughness : (V,) float32 or None       Beckmann α of the surface BSDF per vertex [-]: the slopes of
                                           the waves the mesh does not carry there; None: one scene-wide α.
    shading : ShadingFields or None        The sea's fields for shading every hit (``[render] surface_shading
                                           = "fields"``, FFT sea); None: vertex shading.
    foam_lace : (tile, size) or None       The lace the foam is drawn through (a periodic tile uniform on
                                           [0, 1) and its side [m]; :class:`FoamField`); None: foam as it is.
    """

    positions: NDArray[np.float32]
    normals: NDArray[np.float32]
    foam: NDArray[np.float32] | None
    roughness: NDArray[np.float32] | None = None
    shading: "ShadingFields | None" = None
    foam_lace: tuple[NDArray[np.float32], float] | None = None

    def non_finite(self) -> dict[str, int]:
        """How many values of each field are NaN or infinite (fields with none left out) [-]."""
        counts = {}
        for name in ("positions", "normals", "foam", "roughness"):
            values = getattr(self, name)
            if values is not None:
                bad = int(np.count_nonzero(~np.isfinite(values)))
                if bad:
                    counts[name] = bad
        return counts


#: Number of values per node of a :class:`ShadingFields` level: η, D_x, D_y [m] (the displaced surface's
#: position), ∂η/∂x₀, ∂η/∂y₀, ∂Dx/∂x₀, ∂Dy/∂y₀, ∂Dx/∂y₀ [-] (its normal).
SHADING_CHANNELS = 8


@dataclass(frozen=True)
class ShadingCascade:
    """One periodic cascade of the sea as the renderer shades from it: its low-passed levels at one time.

    Attributes
    ----------
    patch_size : float                 Side L of the periodic patch [m]; node (i, j) of a level of N² nodes
                                       is at rest position (i L/N − L/2, j L/N − L/2).
    band_top : float                   k_top, the cutoff of level 0 [rad m⁻¹]: level j keeps |k| < k_top / 2^j.
    levels : tuple of (N_j, N_j, 5) float32
                                       The level's fields at its nodes, rows along y (channels
                                       :data:`SHADING_CHANNELS`: slopes and the displacement gradient, with
                                       respect to rest coordinates). The pyramid's last, empty level
                                       (no mode below its cutoff) is left out: it is zero.
    """

    patch_size: float
    band_top: float
    levels: tuple[NDArray[np.float32], ...]

    @property
    def level_count(self) -> int:
        """Levels of the pyramid, the empty last one included [-]."""
        return len(self.levels) + 1


@dataclass(frozen=True)
class FoamField:
    """The fresh-foam coverage B on a polar grid of the foam's own (field) resolution, and its lace.

    Attributes
    ----------
    center : (float, float)              The grid's centre, relative to :attr:`ShadingFields.origin` [m].
    inner_radius, outer_radius : float   Radii of its first and last rings [m] (geometric in between).
    rings, segments : int                Rings, and points per ring [-].
    fresh : (1 + rings·segments,) float32   B [-] at the centre, then ring by ring (angle 2π i/segments from +x).
    outside : float                      B beyond the last ring: the tracked foam's area mean [-].
    lace : (M, M) float32                A periodic tile uniform on [0, 1) (rows along y,
                                         :func:`~oceanrender.waves.foam.lace_tile_Worley1996`): foam is drawn
                                         where lace < B, so its mean cover stays B.
    lace_size : float                    Side of the lace tile [m].
    """

    center: tuple[float, float]
    inner_radius: float
    outer_radius: float
    rings: int
    segments: int
    fresh: NDArray[np.float32]
    outside: float
    lace: NDArray[np.float32]
    lace_size: float


@dataclass(frozen=True)
class JoinShading:
    """How a body whose surface is not the FFT sea everywhere (the coast inside the open sea) takes the sea's
    detail at a hit (docs/pixel_detail.md, "The coast inside the open sea").

    The body's vertex normals are its own surface's; the sea's fields add what its mesh
    does not carry, scaled as the body scales the sea's short waves:
    s = s_body + τ_s (s_fields − s_sea), s the slope (−n_x/n_z, −n_y/n_z) of the interpolated
    unit normal of the body, of the fields at the hit's footprint and of the sea's own vertices.
    Where τ_s = 1 and the body is the sea, s_body = s_sea and s = s_fields.

    Attributes
    ----------
    sea_normals : (V, 3) float32   The FFT sea's own unit vertex normals (the surface its mesh would carry).
    sea_positions : (V, 3) float32 The FFT sea's own vertex positions [m] (rest + displacement, mean level 0):
                                   the parallax step moves a hit by τ_s times the fields' offset from them.
    short_taper : (V,) float32     τ_s [-]: the factor of the sea's short waves in the body (0 off the water).
    foam_scale, foam_offset : (V,) float32
                                   A, C [-]: the fresh foam at a hit is A·B_grid + C, B_grid the foam grid's
                                   (the sea's whitecaps; A = (1 − w) τ_s) and C the body's own (the solver's
                                   white water, w B_S), interpolated over the triangle.
    """

    sea_normals: NDArray[np.float32]
    sea_positions: NDArray[np.float32]
    short_taper: NDArray[np.float32]
    foam_scale: NDArray[np.float32]
    foam_offset: NDArray[np.float32]


@dataclass(frozen=True)
class ShadingFields:
    """What the renderer needs to shade every water hit from the sea's own fields (docs/pixel_detail.md).

    The renderer finds a hit's rest position from the mesh's texture coordinates
    (``texcoords`` = rest (x, y) − ``origin``: the preimage of the hit under the
    piecewise-linear displacement the mesh carries), its shading spacing Δ from its
    footprint, and then takes, per cascade, levels ⌊s⌋ and ⌊s⌋ + 1 of the fractional
    level s = log₂(k_top / k_f), k_f = π / (2Δ) (the rule of :mod:`oceanrender.waves.lod`):
    the normal of the waves Δ resolves, and as Beckmann α the slopes of the rest, so that
    resolved and unresolved slopes add up to the spectrum's at every Δ.

    Attributes
    ----------
    cascades : tuple of ShadingCascade   The sea's cascades at the frame's time.
    spacing : (M,) float64               Shading spacings Δ [m], increasing, log-spaced.
    alpha : (M,) float64                 Beckmann α at each Δ [-]: √(total − resolved slope variance).
    origin : (float, float)              Rest position of texture coordinate (0, 0) [m].
    texcoords : (V, 2) float32           Per vertex of the body: rest (x, y) − origin [m] (0 off the surface).
    foam : FoamField or None             The foam at field resolution (None: no foam, or the vertices' foam).
    join : JoinShading or None           How the body combines its own surface with the fields (None: the body is
                                         the sea).
    """

    cascades: tuple[ShadingCascade, ...]
    spacing: NDArray[np.float64]
    alpha: NDArray[np.float64]
    origin: tuple[float, float]
    texcoords: NDArray[np.float32]
    foam: FoamField | None = None
    join: JoinShading | None = None


class FrameError(RuntimeError):
    """A frame that cannot be made right from its scene (non-finite fields or pixels): one line naming the frame,
    the stage and the keys behind it. Raised by :mod:`oceanrender.pipeline`; the frames before it are kept."""


#: The scene keys that shape each field of a :class:`FrameGeometry`, named when a field comes out non-finite.
FIELD_KEYS = {
    "positions": "the wave model's heights and displacement: [ocean] (or [coastal])",
    "normals": "the wave model's slopes: [ocean] (or [coastal])",
    "foam": "the foam model: [foam] with [ocean] wind_speed and choppiness",
    "roughness": "the unresolved slopes: [water] surface_roughness with the [ocean] spectrum",
}


@dataclass(frozen=True)
class Terrain:
    """A seafloor and beach mesh inside the water body, with its reflectance.

    Attributes
    ----------
    positions, normals : (V, 3) float32   Vertex positions [m] and unit normals.
    faces : (F, 3) int                     Triangles, counter-clockwise seen from above.
    rock : (V,) float32                    Rock coverage per vertex [-]: 0 sand, 1 rock.
    sand_albedo, rock_albedo : (float, float)   Lambertian reflectances [-] at 400 and 700 nm,
                                                linear in wavelength between and beyond.
    """

    positions: NDArray[np.float32]
    faces: NDArray[np.integer]
    normals: NDArray[np.float32]
    rock: NDArray[np.float32]
    sand_albedo: tuple[float, float]
    rock_albedo: tuple[float, float]


class WaterSurface(Protocol):
    """The interface of a water body that :mod:`oceanrender.pipeline` and the renderer use."""

    faces: NDArray[np.integer]

    @property
    def spectrum(self) -> Callable:
        """The directional wave spectrum Ψ(kx, ky) [m⁴] of the waves the body carries."""

    @property
    def finest_cell(self) -> float:
        """Finest resolved spacing of the geometry [m]."""

    def frame(self, t: float) -> FrameGeometry:
        """The body at scene time t [s]."""

    def total_slope_variance(self, roughness: float) -> float:
        """Mean-square slope of all its waves [-], given the unresolved Beckmann α ``roughness``
        (the scene-wide α; bodies with a per-vertex α already count it in the spectrum's total)."""

    def terrain(self) -> Terrain | None:
        """The terrain rendered inside the water, or None (open sea)."""
