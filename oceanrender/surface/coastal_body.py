"""The coastal water body per frame, from the stored simulation fields.

The counterpart of :class:`oceanrender.surface.open_sea.WaterBody` for a scene
with a [coastal] section: the same interface (``faces``, ``frame(t)``,
``spectrum``, ``finest_cell``, ``total_slope_variance``, ``terrain``; the
:class:`~.frame.WaterSurface` protocol), so the renderer and the pipeline treat
both alike.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..coastal.simulation import read_frame_fields
from ..scene import arrays
from .coastal_mesh import terrain_mesh, water_body_faces, water_body_vertices
from .frame import FrameGeometry, Terrain


class CoastalBody:
    """Frames of the coastal water body, read from a simulation store (see :mod:`.simulation`)."""

    def __init__(self, scene, store: str | Path):
        from ..waves.sea import directional_spectrum  # noqa: PLC0415

        self.scene = scene
        self.coastal = scene.coastal
        self.store = Path(store)
        self.faces = water_body_faces(self.coastal.shape)
        self.bed = arrays.bathymetry(self.coastal)
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

    def terrain(self) -> Terrain:
        """The terrain: a heightfield of the bed with sand and rock cover (:class:`~.frame.Terrain`)."""
        positions, faces, normals = terrain_mesh(self.bed, self.coastal.spacing, self.coastal.origin)
        rock = arrays.rock_mask(self.coastal).ravel().astype(np.float32)
        return Terrain(positions, faces, normals, rock, self.coastal.sand_albedo, self.coastal.rock_albedo)
