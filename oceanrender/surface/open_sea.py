"""The closed water body of a frame: fixed triangles, vertices that move with the sea.

Two layouts (scene ``[mesh] kind``): ``"patch"``, one periodic FFT patch as a
closed box (:mod:`.patch_mesh`), and ``"radial"``, a camera-centred polar grid out
to the horizon (:mod:`.radial_mesh`). Foam, when enabled, is whitecap coverage F
and fresh-foam coverage B per vertex, accumulated from breaking crests (the
crest-acceleration criterion of :mod:`oceanrender.waves.foam`) over a window
of history on a fixed time grid before each frame, so every frame follows from
(scene, t) alone; the frame's ``foam`` is B (docs/whitecaps.md).

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
from ..optics.foam import fresh_foam_decay_time
from ..waves.foam import crest_acceleration_threshold, two_stage_foam_step
from ..waves.sea import SurfacePoints
from .frame import FrameGeometry, Terrain
from .patch_mesh import water_body_faces, water_body_vertices
from .radial_mesh import RadialGrid, horizon_radius, radial_body_faces, radial_body_vertices

#: Most history steps of the foam accumulation per frame of a moving camera [-] (its history is not shared).
FOAM_STEPS_MOVING = 8


class WaterBody:
    """Builds the frames of a scene's water body; the triangles never change."""

    def __init__(self, scene: Scene):
        self.scene = scene
        from .objects import scene_sea  # noqa: PLC0415

        self.sea = scene_sea(scene)  # the sea with the wakes of moving objects
        mesh = scene.mesh
        self.camera_path = None
        self._moved_grid: tuple[float, RadialGrid] | None = None  # (t, grid) of the last grid_at(t)
        self._history: dict[float, NDArray] = {}  # foam history: Jacobian at grid times (still camera)
        self._foam_mean = np.zeros(2)  # (F, B) of the far sea, from the last foam_state
        self._foam_window: tuple | None = None  # (key, states) of the last accumulation
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

    @cached_property
    def foam_threshold(self) -> float:
        """J_c of the scene's breaking criterion [-] (:func:`~oceanrender.waves.foam.crest_acceleration_threshold`).

        The whole sea's mean-square slope against that of the waves the
        foam's Jacobian keeps (those of a mesh spaced ``filter_spacing``).
        """
        foam = self.scene.foam
        if foam.criterion == "Jacobian":
            return float(foam.threshold)
        total = self.sea.total_slope_variance
        resolved = total - float(self.sea.unresolved_slope_variance(np.asarray(foam.filter_spacing)))
        return float(crest_acceleration_threshold(foam.breaking_acceleration, self.scene.ocean.choppiness,
                                                  resolved, total))

    @cached_property
    def fresh_decay_time(self) -> float:
        """τ_f of the foam's reflectance [s]: the scene's, or Koepke's (1984) efficiency 0.4 (:mod:`~oceanrender.optics.foam`)."""
        foam = self.scene.foam
        return float(foam.fresh_decay_time or fresh_foam_decay_time(foam.decay_time))

    def foam_points(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
        """Rest points (x, y) [m] of the surface vertices at t [s], and which of them track their own foam.

        Radial mesh: those within ``[foam] radius`` of the camera (the rest
        take the tracked foam's mean); patch mesh: all.
        """
        rest_x, rest_y = self.rest_points(t)
        if self.radial is None:
            return rest_x, rest_y, np.ones(np.shape(rest_x), bool)
        cx, cy = self.grid_at(t).center
        return rest_x, rest_y, np.hypot(rest_x - cx, rest_y - cy) <= self.scene.foam.radius

    def _foam_jacobian(self, x: NDArray, y: NDArray, t: float) -> NDArray[np.float64]:
        """The field the breaking criterion compares with J_c, at rest points (x, y), time t [s] [-].

        Of the waves a mesh spaced ``[foam] filter_spacing`` carries.
        ``"Jacobian"``: J itself. ``"crest acceleration"``: its first-order
        part 1 + λ ∇·D = 1 + λ a_z/g (deep water; Tessendorf 2001), whose
        statistics are Gaussian like the acceleration's: J's own lower tail
        is thinner (the λ² term (∂Dx/∂x)(∂Dy/∂y) − (∂Dx/∂y)² is > 0 on crests),
        by a factor that changes with the wind (0.48 of the Gaussian's at 8 m s⁻¹,
        0.79 at 16, on the default scene's threshold), which would bend the
        criterion's wind dependence.
        """
        spacing = np.full(np.shape(x), self.scene.foam.filter_spacing)
        if self.scene.foam.criterion == "Jacobian" or self.sea.cascades is None:
            return self.sea.jacobian(x, y, float(t), spacing)
        xx, yy = self.sea._weighted(np.asarray(x, float), np.asarray(y, float), float(t), spacing, slice(5, 7))
        return 1.0 + xx + yy  # 1 + λ ∇·D: λ a_z/g of each deep-water mode

    def foam_grid_times(self, t: float) -> tuple[list[float], float]:
        """The foam history's grid times for a frame at t [s] and the grid step [s].

        The grid is k Δ, k integer, Δ = ``time_step`` (a still camera) or at
        least a window of ``history × decay_time`` / :data:`FOAM_STEPS_MOVING`
        (a moving one, whose history is not shared by frames); the list runs
        from just over one window before t to the first grid time at or after t.
        """
        foam = self.scene.foam
        window = foam.history * foam.decay_time
        step = foam.time_step if self.camera_path is None else max(foam.time_step, window / FOAM_STEPS_MOVING)
        steps = max(1, math.ceil(window / step - 1e-9))
        after = math.ceil(t / step - 1e-9)  # the first grid time at or after t
        return [(after - steps + j) * step for j in range(steps + 1)], step

    def _accumulate(self, times: list[float], x: NDArray, y: NDArray) -> list[tuple[NDArray, NDArray]]:
        """(F, B) at the last two grid times of ``times``, from clear water at ``times[0]``, at rest points (x, y)."""
        foam = self.scene.foam
        reuse = self.camera_path is None  # the rest points never move
        kept = self._history if reuse else {}
        coverage = fresh = np.zeros(x.shape)
        states = [(coverage, fresh)]  # clear water at times[0]
        for previous, time in zip(times[:-1], times[1:]):
            if time not in kept:
                kept[time] = self._foam_jacobian(x, y, time)
            coverage, fresh = two_stage_foam_step(coverage, fresh, kept[time], time - previous, self.foam_threshold,
                                                  foam.decay_time, self.fresh_decay_time, foam.gain)
            states.append((coverage, fresh))
        if reuse:
            self._history = {time: kept[time] for time in times[1:]}
        return states[-2:]

    def foam_state(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Whitecap coverage F and fresh-foam coverage B at the rest points of time t [s] [-].

        The accumulation (:func:`~oceanrender.waves.foam.two_stage_foam_step`)
        starts from clear water at the first grid time of
        :meth:`foam_grid_times`, steps along the grid with the Jacobian of
        each grid time, and a frame between two grid times g ≤ t < g + Δ
        takes (F, B) linearly between their states, so every frame follows
        from (scene, t) alone and the foam moves smoothly from frame to frame.

        Beyond ``[foam] radius`` from the camera, and on the far ring, a
        vertex has the area-weighted mean of the tracked foam (vertex cells
        are ∝ spacing²); from radius/2 it blends into that mean linearly.

        NOTE: the grid times do not depend on t, so consecutive frames of a
        still camera share their history: its Jacobians are kept
        (:attr:`_history`), and a frame computes one every ``time_step`` s of
        scene time. A kept value is the same computation on the same inputs
        as a fresh one, so a resumed run renders what an uninterrupted one does.
        """
        foam = self.scene.foam
        times, step = self.foam_grid_times(t)
        rest_x, rest_y, tracked = self.foam_points(t)
        x, y = rest_x[tracked], rest_y[tracked]
        key = (tuple(times), self.foam_threshold, None if self.camera_path is None else t)  # what decides the states
        if self._foam_window is not None and self._foam_window[0] == key:
            states = self._foam_window[1]  # the same window, points and criterion: the same accumulation
        else:
            states = self._accumulate(times, x, y)
            self._foam_window = (key, states)
        weight = min(max((t - times[-2]) / step, 0.0), 1.0)  # t in [times[-2], times[-1]]
        (f0, b0), (f1, b1) = states[-2], states[-1]
        values = np.stack([(1 - weight) * f0 + weight * f1, (1 - weight) * b0 + weight * b1])
        area = self.spacing[tracked] ** 2 if self.spacing is not None else np.ones(x.shape)
        mean = values.reshape(2, -1) @ area.ravel() / area.sum()  # area-weighted mean of the tracked foam
        self._foam_mean = mean
        if tracked.all():  # (the patch mesh's grid shape back from the flat tracked points)
            return values[0].reshape(np.shape(rest_x)), values[1].reshape(np.shape(rest_x))
        cx, cy = self.grid_at(t).center
        blend = np.clip(np.hypot(x - cx, y - cy) / (0.5 * foam.radius) - 1.0, 0.0, 1.0)  # 0 at R/2, 1 at R
        full = np.empty((2, tracked.size))
        full[:, tracked] = (1 - blend) * values + blend * mean[:, None]
        full[:, ~tracked] = mean[:, None]
        return full[0], full[1]

    def foam(self, t: float) -> NDArray[np.float64]:
        """Whitecap coverage F at the rest points of time t [s] [-] (see :meth:`foam_state`)."""
        return self.foam_state(t)[0]

    def vertex_foam(self, t: float, vertex_count: int | None = None) -> tuple[NDArray[np.float32], NDArray[np.float32]]:
        """(F, B) per vertex of the body at t [s] [-]; 0 on the skirt and the bottom.

        The frame's ``foam`` is B, the fraction of the surface that reflects
        like fresh foam (the renderer's foam weight); F, the whitecap coverage,
        is what "showing foam" counts (scripts/whitecap_coverage.py).
        """
        coverage, fresh = self.foam_state(t)
        count = vertex_count or self.vertex_count
        out = np.zeros((2, count), np.float32)
        for row, top in enumerate((coverage, fresh)):
            if self.radial is None:  # the patch mesh repeats row/column 0 at the far edge
                top = np.pad(top, ((0, 1), (0, 1)), mode="wrap")
            out[row, : top.size] = top.ravel()
            if self.radial is not None:  # the far ring: the far sea's mean foam
                out[row, top.size: top.size + self.radial.segments] = self._foam_mean[row]
        return out[0], out[1]

    def frame(self, t: float) -> FrameGeometry:
        """The closed body at time t [s]; its ``foam`` is the fresh-foam coverage B (:meth:`vertex_foam`)."""
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
            foam = self.vertex_foam(t, len(positions))[1]
        roughness = self.vertex_roughness if self.per_vertex_roughness else None
        return FrameGeometry(positions, normals, foam, roughness)
