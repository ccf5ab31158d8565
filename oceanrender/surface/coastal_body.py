"""The coastal water body per frame, from the stored simulation fields.

The counterpart of :class:`oceanrender.surface.open_sea.WaterBody` for a scene
with a [coastal] section: the same interface (``faces``, ``frame(t)``,
``spectrum``, ``finest_cell``, ``total_slope_variance``, ``terrain``; the
:class:`~.frame.WaterSurface` protocol), so the renderer and the pipeline treat
both alike.

White water (``[foam] enabled``): where the stored flow dissipates energy in
bores (:func:`oceanrender.coastal.whitewater.bore_dissipation_rate` above
``[foam] whitewater_dissipation``), foam forms and stays where the bore left
it, fading with the foam's decay times: a frame's foam is the largest of
the white water of the stored frames of the last ``history × decay_time``
seconds, each decayed by its age (coverage e^{−a/τ}, fresh foam
e^{−a/τ − a/τ_f}). The renderer draws the fresh part, as on the open sea.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..coastal.simulation import read_frame_fields
from ..coastal.whitewater import bore_dissipation_rate, whitewater_coverage
from ..optics.foam import fresh_foam_decay_time
from ..scene import arrays
from .coastal_mesh import terrain_mesh, water_body_faces, water_body_vertices
from .frame import FrameGeometry, Terrain
from .open_sea import scene_foam_lace


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
        self._whitewater: dict[int, np.ndarray] = {}  # white-water coverage of stored frames (kept for the next)
        #: the wind sea finer than the cells, as the surface's shading fields (:mod:`.coast_ripples`), or None
        self.ripples = None
        if self.shades_from_fields:
            from .coast_ripples import CoastRipples  # noqa: PLC0415

            size = np.asarray(self.coastal.shape[::-1], float) * np.asarray(self.coastal.spacing, float)
            ripples = CoastRipples(scene, self.finest_cell, tuple(np.asarray(self.coastal.origin) + size / 2))
            if ripples.resolves_any:  # (an [ocean] whose cascades stop short of the band: its roughness alone)
                self.ripples = ripples

    @property
    def shades_from_fields(self) -> bool:
        """Whether the surface is shaded from the wind sea's fields finer than the cells (:mod:`.coast_ripples`):
        ``[render] surface_shading = "fields"``, an FFT ``[ocean]`` and ``[water] surface_roughness = "auto"``."""
        scene = self.scene
        return (scene.render.surface_shading == "fields" and scene.ocean.model == "FFT"
                and scene.water.surface_roughness == "auto")

    def frame_fields(self, t: float) -> dict[str, np.ndarray]:
        """The stored fields of the frame at scene time t [s]."""
        frame = int(round(t * self.scene.output.fps))
        return read_frame_fields(self.store, frame)

    def whitewater(self, frame: int) -> np.ndarray:
        """White-water coverage (ny, nx) of a stored frame [-]: the bore dissipation criterion."""
        if frame not in self._whitewater:
            fields = read_frame_fields(self.store, frame)
            rate = bore_dissipation_rate(fields["h"], fields["hu"], fields["hv"], self.coastal.spacing,
                                         self.coastal.h_min)
            self._whitewater[frame] = whitewater_coverage(rate, self.scene.foam.whitewater_dissipation)
        return self._whitewater[frame]

    def foam_state(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """(F, B): white-water coverage and fresh-foam coverage (ny, nx) at scene time t [s] [-].

        The maximum over the stored frames of the last ``history ×
        decay_time`` seconds (from the first rendered frame on) of their white
        water decayed by age a: e^{−a/τ} for F, e^{−a/τ − a/τ_f} for B.
        Depends only on the store and t: a resumed run gets what an
        uninterrupted one did.
        """
        foam = self.scene.foam
        fps = self.scene.output.fps
        frame = int(round(t * fps))
        tau_f = foam.fresh_decay_time or fresh_foam_decay_time(foam.decay_time)
        first = max(self.scene.output.frames[0], frame - int(np.ceil(foam.history * foam.decay_time * fps)))
        coverage = np.zeros(self.coastal.shape)
        fresh = np.zeros(self.coastal.shape)
        for earlier in range(first, frame + 1):
            age = (frame - earlier) / fps
            white = self.whitewater(earlier)
            coverage = np.maximum(coverage, white * np.exp(-age / foam.decay_time))
            fresh = np.maximum(fresh, white * np.exp(-age / foam.decay_time - age / tau_f))
        for old in [k for k in self._whitewater if k < first]:
            del self._whitewater[old]
        return coverage, fresh

    def vertex_foam(self, t: float, vertex_count: int | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(F, B) per vertex of the body at t [s] [-]; 0 on the walls and the base, and where dry."""
        coverage, fresh = self.foam_state(t)
        wet = self.frame_fields(t)["h"] > self.coastal.h_min
        out = np.zeros((2, vertex_count or self.vertex_count), np.float32)
        out[0, : coverage.size] = np.where(wet, coverage, 0.0).ravel()
        out[1, : fresh.size] = np.where(wet, fresh, 0.0).ravel()
        return out[0], out[1]

    def frame(self, t: float) -> FrameGeometry:
        """The closed water body at scene time t [s]; with ``[foam] enabled`` its foam is the fresh white water B."""
        fields = self.frame_fields(t)
        positions, normals = water_body_vertices(self.bed, fields["h"], self.coastal.spacing, self.coastal.origin,
                                                 self.coastal.h_min)
        positions, normals = self.rotated(positions, normals)
        foam = self.vertex_foam(t, len(positions))[1] if self.scene.foam.enabled else None
        shading = None
        if self.ripples is not None:
            wet = (fields["h"] > self.coastal.h_min).ravel()
            shading = self.ripples.fields(t, positions, wet.size, (self.coastal.still_level - self.bed).ravel(), wet)
        return FrameGeometry(positions, normals, foam, shading=shading, foam_lace=scene_foam_lace(self.scene))

    def rotated(self, positions: np.ndarray, normals: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Positions and normals turned by ``[coastal] rotation`` about ``origin`` (world = origin + R (p − origin))."""
        if self.coastal.rotation == 0.0:
            return positions, normals
        angle = np.radians(self.coastal.rotation)
        turn = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
        origin = np.asarray(self.coastal.origin, dtype=np.float64)
        positions = positions.astype(np.float64)
        normals = normals.astype(np.float64)
        positions[:, :2] = (positions[:, :2] - origin) @ turn.T + origin
        normals[:, :2] = normals[:, :2] @ turn.T
        return positions.astype(np.float32), normals.astype(np.float32)

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
        positions, normals = self.rotated(positions, normals)
        rock = arrays.rock_mask(self.coastal).ravel().astype(np.float32)
        return Terrain(positions, faces, normals, rock, self.coastal.sand_albedo, self.coastal.rock_albedo)
