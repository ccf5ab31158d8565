"""The coastal water body per frame, from the stored simulation fields.

The counterpart of :class:`oceanrender.geometry.body.WaterBody` for a scene
with a [coastal] section: the same interface (``faces``, ``frame(t)``,
``spectrum``, ``finest_cell``, ``total_slope_variance``, ``extra_shapes``), so
the renderer and the sequence code treat both alike.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..geometry.body import FrameGeometry
from . import inputs
from .mesh import terrain_mesh, water_body_faces, water_body_vertices
from .simulation import read_frame_fields

#: Wavelengths [nm] at which the linear seafloor reflectances are given, and the film's range.
ALBEDO_WAVELENGTHS = (400.0, 700.0)


def linear_reflectance(wavelengths, at_400_700: tuple[float, float]) -> np.ndarray:
    """Reflectance [-] linear in wavelength through its values at 400 and 700 nm, clipped to [0, 1]."""
    (l0, l1), (r0, r1) = ALBEDO_WAVELENGTHS, at_400_700
    w = np.asarray(wavelengths, dtype=np.float64)
    return np.clip(r0 + (r1 - r0) * (w - l0) / (l1 - l0), 0.0, 1.0)


class CoastalBody:
    """Frames of the coastal water body, read from a simulation store (see :mod:`.simulation`)."""

    def __init__(self, scene, store: str | Path):
        from ..geometry.sea import directional_spectrum  # noqa: PLC0415

        self.scene = scene
        self.coastal = scene.coastal
        self.store = Path(store)
        self.faces = water_body_faces(self.coastal.shape)
        self.bed = inputs.bathymetry(self.coastal)
        self.spectrum = directional_spectrum(scene.ocean)
        self.finest_cell = float(min(self.coastal.spacing))
        self.vertex_count = int(self.faces.max()) + 1

    def frame_fields(self, t: float) -> dict[str, np.ndarray]:
        """The stored fields of the frame at scene time t [s]."""
        frame = int(round(t * self.scene.output.fps))
        return read_frame_fields(self.store, frame)

    def frame(self, t: float) -> FrameGeometry:
        """The closed water body at scene time t [s] (no foam in the coastal zone)."""
        fields = self.frame_fields(t)
        positions, normals = water_body_vertices(self.bed, fields["h"], self.coastal.spacing, self.coastal.origin,
                                                 self.coastal.h_min)
        return FrameGeometry(positions, normals, None)

    def total_slope_variance(self, roughness: float) -> float:
        """Mean-square slope [-]: the unresolved roughness² plus the simulated surface's over wet cells.

        The simulated slopes are those of the first rendered frame (waves have
        arrived after the spin-up).
        """
        first = self.scene.output.frames[0] / self.scene.output.fps
        h = self.frame_fields(first)["h"]
        eta = self.bed + h
        dy, dx = self.coastal.spacing[1], self.coastal.spacing[0]
        gy, gx = np.gradient(eta, dy, dx)
        wet = h > self.coastal.h_min
        resolved = float(np.mean((gx**2 + gy**2)[wet])) if np.any(wet) else 0.0
        return roughness**2 + resolved

    def extra_shapes(self) -> dict:
        """The terrain: a heightfield of the bed with sand and rock (Mitsuba dicts/objects)."""
        from ..render.renderer import terrain_shape  # noqa: PLC0415

        positions, faces, normals = terrain_mesh(self.bed, self.coastal.spacing, self.coastal.origin)
        rock = inputs.rock_mask(self.coastal).ravel().astype(np.float32)
        return {"terrain": terrain_shape(positions, faces, normals, rock, self.coastal.sand_albedo,
                                         self.coastal.rock_albedo)}
