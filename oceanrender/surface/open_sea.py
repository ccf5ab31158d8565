"""The closed water body of a frame: fixed triangles, vertices that move with the sea.

Two layouts (scene ``[mesh] kind``): ``"patch"``, one periodic FFT patch as a
closed box (:mod:`.patch_mesh`), and ``"radial"``, a camera-centred polar grid out
to the horizon (:mod:`.radial_mesh`). Foam, when enabled, is a per-vertex
coverage in [0, 1] accumulated from the folding of the surface over a window
of history before each frame, so every frame follows from (scene, t) alone.

With a moving camera (``[[camera.keys]]``) the radial grid follows it: at
time t its rest points are the grid translated to the camera's (x, y) at t;
the triangles never change. The radial body ends in a flat far ring out to
:func:`~.radial_mesh.horizon_radius` of the camera's height at t, so the sea
reaches the horizon.

Roughness. With ``[water] surface_roughness = "auto"`` and the radial mesh of
an FFT sea, every vertex carries its own Beckmann α (:attr:`FrameGeometry.roughness`):
the slope variance of the waves its spacing does not resolve
(:meth:`~oceanrender.waves.sea.SeaSurface.unresolved_slope_variance`), so
resolved plus unresolved slopes add up to the spectrum's at every distance.
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from ..scene import Scene
from ..waves.fft_ocean import OceanFields, OceanGrid
from ..waves.foam import foam_step
from ..waves.sea import SeaSurface, SurfacePoints
from .frame import FrameGeometry, Terrain
from .patch_mesh import water_body_faces, water_body_vertices
from .radial_mesh import RadialGrid, horizon_radius, radial_body_faces, radial_body_vertices

#: Most history steps of the foam accumulation per frame [-].
FOAM_STEPS = 4


class WaterBody:
    """Builds the frames of a scene's water body; the triangles never change."""

    def __init__(self, scene: Scene):
        self.scene = scene
        self.sea = SeaSurface(scene.ocean)
        mesh = scene.mesh
        self.camera_path = None
        self._moved_grid: tuple[float, RadialGrid] | None = None  # (t, grid) of the last grid_at(t)
        self._history: dict[float, NDArray] = {}  # foam history: Jacobian at grid times (still camera)
        if mesh.kind == "radial":
            from ..scene.motion import camera_motion  # noqa: PLC0415

            self.camera_path = camera_motion(scene)
            center = (scene.camera.position[0], scene.camera.position[1])
            self.radial = RadialGrid.square_cells(center, mesh.inner_radius, mesh.outer_radius, mesh.segments)
            self.faces = radial_body_faces(self.radial.rings + 1, self.radial.segments)  # + the far ring
            self.rest_x, self.rest_y = self.radial.points.T
            self.spacing = self.radial.spacing
        else:
            self.radial = None
            grid = OceanGrid(scene.ocean.resolution, scene.ocean.patch_size)
            self.faces = water_body_faces(grid.resolution)
            self.rest_x, self.rest_y = grid.x, grid.y
            self.spacing = None
        self.vertex_count = int(self.faces.max()) + 1

    @property
    def spectrum(self):
        """The directional wave spectrum Ψ(kx, ky) [m⁴] of the sea."""
        return self.sea.spectrum

    @property
    def finest_cell(self) -> float:
        """Finest resolved grid spacing of the geometry [m]."""
        return self.sea.finest_cell

    def total_slope_variance(self, roughness: float) -> float:
        """Mean-square slope of all the sea's waves [-]: the spectrum's, from 60 km down to 1 mm long.

        (``roughness`` is the part already in that integral.)
        """
        return self.sea.total_slope_variance

    @property
    def per_vertex_roughness(self) -> bool:
        """True when every vertex carries its own α: radial mesh, FFT sea, ``surface_roughness = "auto"``."""
        return (self.radial is not None and self.sea.cascades is not None
                and self.scene.water.surface_roughness == "auto")

    @cached_property
    def vertex_roughness(self) -> NDArray[np.float32]:
        """Beckmann α per vertex [-]: √(unresolved slope variance) on the rings, √(total) beyond.

        The far ring, the skirt and the bottom carry no waves: all the
        spectrum's slopes are roughness there. Fixed for the body (the
        spacing of a vertex never changes).
        """
        top = np.sqrt(self.sea.unresolved_slope_variance(self.spacing))
        alpha = np.full(self.vertex_count, np.sqrt(self.sea.total_slope_variance))
        alpha[: top.size] = top
        return alpha.astype(np.float32)

    def camera_height(self, t: float) -> float:
        """Height of the camera above the mean sea level at time t [s] [m]."""
        if self.camera_path is not None:
            return float(self.camera_path.at(t).position[2])
        return float(self.scene.camera.position[2])

    def terrain(self) -> Terrain | None:
        """No terrain in the open sea."""
        return None

    def grid_at(self, t: float) -> RadialGrid | None:
        """The radial grid of time t [s]: centred under the camera at t (None for the patch mesh).

        The grid of the last t asked for is kept: a frame asks three times
        (surface, foam, mesh), and each new grid recomputes its points.
        """
        if self.radial is None or self.camera_path is None:
            return self.radial
        if self._moved_grid is None or self._moved_grid[0] != t:
            x, y = self.camera_path.at(t).position[:2]
            self._moved_grid = (t, replace(self.radial, center=(float(x), float(y))))
        return self._moved_grid[1]

    def rest_points(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Rest positions (x, y) of the surface vertices at time t [s] [m]."""
        if self.camera_path is None:
            return self.rest_x, self.rest_y
        x, y = self.grid_at(t).points.T
        return x, y

    def surface(self, t: float) -> SurfacePoints:
        """The displaced surface at the mesh's rest points at time t [s]."""
        return self.sea.sample(*self.rest_points(t), t, self.spacing)

    def foam(self, t: float, jacobian_now: NDArray | None = None) -> NDArray[np.float64]:
        """Foam coverage at the rest points of time t [s], accumulated over the preceding history.

        With a moving radial grid the history is accumulated at the rest
        points of time t (fixed points of the sea), not along the grid's path.

        The accumulation (:func:`~oceanrender.waves.foam.foam_step`) starts
        from clear water on the grid of times k Δ (Δ = ``history × decay_time``
        / steps, half a decay time or more, at most ``FOAM_STEPS`` steps) just
        over ``history × decay_time`` before t, steps along that grid with the
        Jacobian at each grid time, and ends with a part step to t itself, so it
        is frame-rate independent and every frame follows from (scene, t) alone.

        NOTE: the grid times do not depend on t, so consecutive frames of a
        still camera share their history: its Jacobians are kept
        (:attr:`_history`) and a frame computes one, not three. A kept value is
        the same computation on the same inputs as a fresh one, so a resumed
        run renders what an uninterrupted one does.
        """
        foam = self.scene.foam
        window = foam.history * foam.decay_time
        steps = int(min(FOAM_STEPS, max(2, np.ceil(2 * foam.history))))
        step = window / steps
        last = math.floor(t / step + 1e-9)  # the last grid time at or before t
        times = [(last - steps + 1 + j) * step for j in range(steps)]
        rest_x, rest_y = self.rest_points(t)
        reuse = self.camera_path is None  # the rest points never move
        kept = self._history if reuse else {}
        coverage = np.zeros(np.shape(rest_x))
        previous = times[0] - step
        for time in times:
            if abs(time - t) < 1e-9 and jacobian_now is not None:
                jacobian = jacobian_now  # the grid time is t itself: reuse the frame's own J
            elif time in kept:
                jacobian = kept[time]
            else:
                jacobian = self.sea.jacobian(rest_x, rest_y, float(time), self.spacing)
            kept[time] = jacobian
            coverage = foam_step(coverage, jacobian, time - previous, foam.threshold, foam.decay_time, foam.gain)
            previous = time
        if t - previous > 1e-9:
            jacobian = jacobian_now if jacobian_now is not None else self.sea.jacobian(rest_x, rest_y, t, self.spacing)
            coverage = foam_step(coverage, jacobian, t - previous, foam.threshold, foam.decay_time, foam.gain)
        if reuse:
            self._history = {time: kept[time] for time in times}
        return coverage

    def frame(self, t: float) -> FrameGeometry:
        """The closed body at time t [s]."""
        depth = self.scene.water.depth
        surface = self.surface(t)
        if self.radial is not None:
            far = horizon_radius(self.camera_height(t), self.radial.outer_radius, self.radial.segments)
            positions, normals = radial_body_vertices(self.grid_at(t), surface.displacement, surface.normals, depth,
                                                      far_radius=far)
        else:
            d = surface.displacement
            fields = OceanFields(d[..., 2], d[..., 0], d[..., 1], np.zeros_like(d[..., 0]), np.zeros_like(d[..., 0]),
                                 surface.jacobian, surface.normals)
            positions, normals = water_body_vertices(fields, self.scene.ocean.patch_size, depth)
        foam = None
        if self.scene.foam.enabled:
            top = self.foam(t, surface.jacobian)
            if self.radial is None:  # the patch mesh repeats row/column 0 at the far edge
                top = np.pad(top, ((0, 1), (0, 1)), mode="wrap")
            foam = np.zeros(len(positions), np.float32)
            foam[: top.size] = top.ravel()
        roughness = self.vertex_roughness if self.per_vertex_roughness else None
        return FrameGeometry(positions, normals, foam, roughness)
