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
    """

    positions: NDArray[np.float32]
    normals: NDArray[np.float32]
    foam: NDArray[np.float32] | None
    roughness: NDArray[np.float32] | None = None

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
