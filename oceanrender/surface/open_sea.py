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
from functools import cached_property, lru_cache

import numpy as np
from numpy.typing import NDArray

from ..scene import Scene
from ..waves.cascades import sampled_field
from ..waves.fft_ocean import OceanFields, OceanGrid
from ..optics.foam import fresh_foam_decay_time
from ..waves.foam import crest_acceleration_threshold, lace_tile_Perlin1985, two_stage_foam_step
from ..waves.sea import SurfacePoints
from .frame import FoamField, FrameGeometry, ShadingCascade, ShadingFields, Terrain
from .patch_mesh import water_body_faces, water_body_vertices
from .radial_mesh import RadialGrid, horizon_radius, radial_body_faces, radial_body_vertices

#: Most history steps of the foam accumulation per frame of a moving camera [-] (its history is not shared).
FOAM_STEPS_MOVING = 8

#: Segments of the foam's field-resolution grid (field shading): a polar grid of square cells, 2π/1024 of the
#: distance wide (0.25 m at 40 m, 6 cm at 10 m), out to ``[foam] radius`` (1.0 million points at 200 m).
FOAM_SEGMENTS = 1024

#: The foam's lace tile (:func:`~oceanrender.waves.foam.lace_tile_Perlin1985`): side [m], texels per side,
#: the wavelength of its field's peak [m] (the mesh of decaying whitecap foam, tens of centimetres) and the
#: elongation of its lines along the wind [-].
LACE_SIZE, LACE_RESOLUTION, LACE_SCALE, LACE_STRETCH = 16.0, 1024, 0.3, 2.0

#: Shading spacings Δ of the α table of :class:`~.frame.ShadingFields` [m]: 1 mm to 100 km, 16 per decade
#: (α² is smooth in log Δ: linear interpolation between them is within 1 % of the exact value).
SHADING_SPACINGS = np.logspace(-3.0, 5.0, 129)

#: The fields a cascade level gives the renderer, in :data:`~.frame.SHADING_CHANNELS` order.
SHADING_NAMES = ("height", "displacement_x", "displacement_y", "slope_x", "slope_y", "xx", "yy", "xy")


def foam_lace(scene: Scene) -> NDArray[np.float32]:
    """The scene's foam lace tile (:data:`LACE_SIZE` m, :func:`~oceanrender.waves.foam.lace_tile_Perlin1985`),
    drawn out along the waves' direction (the wind's, or the sea state's), seeded by ``[ocean] seed``."""
    ocean = scene.ocean
    direction = ocean.direction if ocean.form != "wind" and ocean.direction is not None else ocean.wind_direction
    return _lace_tile(float(direction), int(ocean.seed))


@lru_cache(maxsize=2)
def _lace_tile(direction_deg: float, seed: int) -> NDArray[np.float32]:
    """:func:`foam_lace`'s tile, made once per (direction, seed): a sequence's frames share it."""
    return lace_tile_Perlin1985(LACE_SIZE, LACE_RESOLUTION, LACE_SCALE, LACE_STRETCH, math.radians(direction_deg),
                                seed)


def scene_foam_lace(scene: Scene) -> tuple[NDArray[np.float32], float] | None:
    """(tile, side [m]) the foam of a frame is drawn through: with foam and ``[render] surface_shading = "fields"``
    (:func:`foam_lace`), else None (the foam as computed, the look before issue 40)."""
    if not scene.foam.enabled or scene.render.surface_shading != "fields":
        return None
    return foam_lace(scene), LACE_SIZE


#: σ of the Gaussian the renderer's B is smoothed with on the foam grid, in cells [-]: a crest breaking at one
#: node would otherwise be drawn as the bilinear stencil's diamond (looked at in turbid_estuary).
FOAM_SMOOTHING_CELLS = 1.0


def smoothed_polar(grid: RadialGrid, values: NDArray, sigma: float) -> NDArray[np.float32]:
    """``values`` at a :class:`RadialGrid`'s points (centre, then ring by ring) smoothed by a Gaussian of
    ``sigma`` cells along the rings (periodic) and across them (edges held); the centre is kept.

    The cells are square (Δr = r Δθ), so the kernel is round on the sea; its sum is 1, so the
    mean over a ring band is kept.
    """
    from scipy.ndimage import gaussian_filter  # noqa: PLC0415

    rings = np.asarray(values, float)[1:].reshape(grid.rings, grid.segments)
    smooth = gaussian_filter(rings, sigma, mode=("nearest", "wrap"))
    return np.concatenate([[float(values[0])], smooth.ravel()]).astype(np.float32)


def polar_grid_sample(grid: RadialGrid, values: NDArray, x: NDArray, y: NDArray, outside: float) -> NDArray:
    """Values given at a :class:`RadialGrid`'s points (centre, then ring by ring), bilinear in (ring, angle) at (x, y) [m].

    Inside the first ring: between the centre's value and the first ring's, linear in r; beyond the last
    ring: ``outside``. The same lookup as the renderer's foam texture (:mod:`oceanrender.render.sea_shading`).
    """
    dx, dy = np.asarray(x, float) - grid.center[0], np.asarray(y, float) - grid.center[1]
    r = np.hypot(dx, dy)
    ring_values = np.asarray(values, float)[1:].reshape(grid.rings, grid.segments)
    q = np.log(grid.outer_radius / grid.inner_radius) / (grid.rings - 1)
    j = np.log(np.maximum(r, 1e-12) / grid.inner_radius) / q
    a = np.mod(np.arctan2(dy, dx) / (2 * np.pi), 1.0) * grid.segments
    i0 = np.floor(a).astype(np.int64) % grid.segments
    i1 = (i0 + 1) % grid.segments
    fa = a - np.floor(a)
    j0 = np.clip(np.floor(j).astype(np.int64), 0, grid.rings - 1)
    j1 = np.minimum(j0 + 1, grid.rings - 1)
    fj = np.clip(j - j0, 0.0, 1.0)
    inner = (1 - fa) * ring_values[j0, i0] + fa * ring_values[j0, i1]
    outer = (1 - fa) * ring_values[j1, i0] + fa * ring_values[j1, i1]
    value = (1 - fj) * inner + fj * outer
    centre = float(values[0])
    value = np.where(r < grid.inner_radius, centre + (r / grid.inner_radius) * (value - centre), value)
    return np.where(r > grid.outer_radius * (1 + 1e-6), outside, value)  # (the last ring itself inside)


def shading_cascades(sea, t: float) -> tuple[ShadingCascade, ...]:
    """The level pyramids of ``sea``'s cascades (a :class:`~oceanrender.waves.sea.SeaSurface`) at t [s], every
    level's :data:`~.frame.SHADING_NAMES` at its own nodes (float32), as the renderer shades from them."""
    cascades = []
    for levels in sea.levels:
        stacks = []
        for ocean in levels.oceans[:-1]:
            f = ocean.fields(float(t))
            stack = np.empty((*f.height.shape, len(SHADING_NAMES)), np.float32)  # filled per channel: no float64 copy
            for k, name in enumerate(SHADING_NAMES):
                stack[..., k] = sampled_field(f, name)
            stacks.append(stack)
        cascades.append(ShadingCascade(float(levels.grid.patch_size), float(levels.band_top), tuple(stacks)))
    return tuple(cascades)


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
        self._foam_last: tuple | None = None  # ((t, J_c), (F, B), far mean) of the last foam_state
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
        if self.foam_grid is not None:
            x, y = self.foam_grid_at(t).points.T
            return x, y, np.ones(x.shape, bool)
        rest_x, rest_y = self.rest_points(t)
        if self.radial is None:
            return rest_x, rest_y, np.ones(np.shape(rest_x), bool)
        cx, cy = self.grid_at(t).center
        return rest_x, rest_y, np.hypot(rest_x - cx, rest_y - cy) <= self.scene.foam.radius

    @cached_property
    def foam_grid(self) -> RadialGrid | None:
        """The foam's own grid when every hit is shaded from the fields (radial mesh): a polar grid of
        :data:`FOAM_SEGMENTS` square cells from the mesh's inner radius to ``[foam] radius``; else None
        (foam at the mesh's vertices)."""
        if self.radial is None or not self.shades_from_fields or not self.scene.foam.enabled:
            return None
        return RadialGrid.square_cells(self.radial.center, self.radial.inner_radius,
                                       max(self.scene.foam.radius, 2.0 * self.radial.inner_radius), FOAM_SEGMENTS)

    def foam_grid_at(self, t: float) -> RadialGrid:
        """The foam grid under the camera at t [s] (it follows the camera like the mesh)."""
        return replace(self.foam_grid, center=self.grid_at(t).center)

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
        if self.foam_grid is not None:
            return self._crest_field(np.ravel(x), np.ravel(y), float(t)).reshape(np.shape(x))
        xx, yy = self.sea._weighted(np.asarray(x, float), np.asarray(y, float), float(t), spacing, slice(5, 7))
        return 1.0 + xx + yy  # 1 + λ ∇·D: λ a_z/g of each deep-water mode

    def _crest_field(self, x: NDArray, y: NDArray, t: float) -> NDArray[np.float64]:
        """1 + λ ∇·D of the waves a ``filter_spacing`` mesh carries at rest points (x, y), time t [s] [-].

        The same value as the ``"crest acceleration"`` branch of :meth:`_foam_jacobian`
        (every point has the one spacing, so each cascade's two level weights are
        constants), summed by the compiled periodic stencil
        (:func:`~oceanrender.waves.grid_sampling.add_periodic_bilinear`).
        """
        from ..waves.grid_sampling import add_periodic_bilinear  # noqa: PLC0415

        out = np.ones(x.shape)
        for levels in self.sea.levels:
            weights = levels.weights(np.asarray(self.scene.foam.filter_spacing), ())
            for j, ocean in enumerate(levels.oceans):
                if ocean is None or not weights[j] > 0:
                    continue
                f = ocean.fields(t)
                divergence = (f.jacobian_xx - 1) + (f.jacobian_yy - 1)
                add_periodic_bilinear(divergence, ocean.grid.patch_size, x, y, float(weights[j]), out)
        return out

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
        """Whitecap coverage F and fresh-foam coverage B at the rest points of time t [s] [-] (:meth:`_foam_state`;
        the last time's kept: a frame asks twice, for its vertices and for its foam grid)."""
        key = (t, self.foam_threshold)  # (the criterion: scripts/whitecap_coverage.py changes it on one body)
        if self._foam_last is None or self._foam_last[0] != key:
            self._foam_last = (key, self._foam_state(t), self._foam_mean.copy())
        self._foam_mean = self._foam_last[2].copy()
        return self._foam_last[1]

    def _foam_state(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
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
        spacing = self.foam_grid_at(t).spacing if self.foam_grid is not None else self.spacing
        area = spacing[tracked] ** 2 if spacing is not None else np.ones(x.shape)
        mean = values.reshape(2, -1) @ area.ravel() / area.sum()  # area-weighted mean of the tracked foam
        self._foam_mean = mean
        if self.radial is None:  # (the patch mesh's grid shape back from the flat tracked points)
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
        if self.foam_grid is not None:  # the grid's foam at the mesh's rest points
            grid = self.foam_grid_at(t)
            x, y = self.rest_points(t)
            coverage = polar_grid_sample(grid, coverage, x, y, self._foam_mean[0])
            fresh = polar_grid_sample(grid, fresh, x, y, self._foam_mean[1])
        out = np.zeros((2, count), np.float32)
        for row, top in enumerate((coverage, fresh)):
            if self.radial is None:  # the patch mesh repeats row/column 0 at the far edge
                top = np.pad(top, ((0, 1), (0, 1)), mode="wrap")
            out[row, : top.size] = top.ravel()
            if self.radial is not None:  # the far ring: the far sea's mean foam
                out[row, top.size: top.size + self.radial.segments] = self._foam_mean[row]
        return out[0], out[1]

    @cached_property
    def shading_alpha(self) -> NDArray[np.float64]:
        """Beckmann α [-] at the shading spacings :data:`SHADING_SPACINGS`: √(total − resolved slope variance)."""
        return np.sqrt(self.sea.unresolved_slope_variance(SHADING_SPACINGS))

    @property
    def shades_from_fields(self) -> bool:
        """Whether the renderer shades every hit from the sea's fields: ``[render] surface_shading = "fields"``
        and an FFT sea with ``surface_roughness = "auto"`` (its α then follows the footprint)."""
        return (self.sea.cascades is not None and self.scene.water.surface_roughness == "auto"
                and self.scene.render.surface_shading == "fields")

    def texcoords(self, t: float, vertex_count: int) -> tuple[NDArray[np.float32], tuple[float, float]]:
        """Texture coordinates (rest (x, y) − origin) [m] of the body's vertices at t [s], and the origin [m].

        The origin is the grid's centre (radial mesh) or (0, 0) (patch), so the
        coordinates keep float32's millimetres near the camera. Skirt and bottom: 0.
        """
        out = np.zeros((vertex_count, 2), np.float32)
        if self.radial is None:
            n = self.scene.ocean.resolution
            edge = np.arange(n + 1) * (self.scene.ocean.patch_size / n) - self.scene.ocean.patch_size / 2
            xx, yy = np.meshgrid(edge, edge)
            out[: (n + 1) ** 2] = np.column_stack([xx.ravel(), yy.ravel()])
            return out, (0.0, 0.0)
        grid = self.grid_at(t)
        cx, cy = grid.center
        out[: len(grid.points)] = grid.points - (cx, cy)
        far = horizon_radius(self.camera_height(t), self.radial.outer_radius, self.radial.segments)
        theta = 2.0 * np.pi * np.arange(grid.segments) / grid.segments
        out[len(grid.points): len(grid.points) + grid.segments] = np.column_stack([far * np.cos(theta),
                                                                                   far * np.sin(theta)])
        return out, (float(cx), float(cy))

    def shading_fields(self, t: float, vertex_count: int) -> ShadingFields:
        """The cascades' level pyramids at t [s] as the renderer shades from them (:class:`~.frame.ShadingFields`).

        Every level's slopes and displacement gradient at its own nodes: the same
        (gain-compensated, hashed-phase) levels the mesh's vertices are sampled from
        (:class:`~oceanrender.waves.lod.CascadeLevels`), so the shading carries the
        geometry's waves with their phases.
        """
        coords, origin = self.texcoords(t, vertex_count)
        return ShadingFields(shading_cascades(self.sea, t), SHADING_SPACINGS, self.shading_alpha, origin, coords,
                             self.foam_field(t, origin))

    def foam_field(self, t: float, origin: tuple[float, float]) -> FoamField | None:
        """B on the foam grid at t [s] (:meth:`foam_state`), for the renderer; None without the foam grid."""
        if self.foam_grid is None:
            return None
        grid = self.foam_grid_at(t)
        _, fresh = self.foam_state(t)
        fresh = smoothed_polar(grid, fresh, FOAM_SMOOTHING_CELLS)
        return FoamField((grid.center[0] - origin[0], grid.center[1] - origin[1]), grid.inner_radius,
                         grid.outer_radius, grid.rings, grid.segments, np.asarray(fresh, np.float32),
                         float(self._foam_mean[1]), foam_lace(self.scene), LACE_SIZE)

    def frame_layout(self, t: float) -> FrameGeometry | None:
        """A calm stand-in for :meth:`frame` at t [s]: the same vertices, attributes and array shapes, with the
        sea at rest (no displacement, normals up, no foam, zero level fields, α = 0), in milliseconds (no FFT, no
        foam history); None for the patch mesh.

        For loading the renderer and compiling its kernels while the real frame is computed
        (:class:`~oceanrender.pipeline.Sequence`): a kernel's code depends on which arrays there are and
        their sizes, never on their values. What a loaded scene keeps from its first geometry is the same as
        the real frame's: the body's skirt and bottom hang from the far ring, which no wave displaces (the
        seafloor's extent is taken from them), so only the radial mesh has a stand-in.
        """
        if self.radial is None:
            return None
        grid = self.grid_at(t)
        far = horizon_radius(self.camera_height(t), self.radial.outer_radius, self.radial.segments)
        up = np.tile([0.0, 0.0, 1.0], (len(grid.points), 1))
        positions, normals = radial_body_vertices(grid, np.zeros((len(grid.points), 3)), up, self.scene.water.depth,
                                                  far_radius=far)
        count = len(positions)
        foam = np.zeros(count, np.float32) if self.scene.foam.enabled else None
        roughness = np.zeros(count, np.float32) if self.per_vertex_roughness else None
        shading = None
        if self.shades_from_fields:
            cascades = tuple(
                ShadingCascade(float(levels.grid.patch_size), float(levels.band_top),
                               tuple(np.zeros((o.grid.resolution, o.grid.resolution, len(SHADING_NAMES)), np.float32)
                                     for o in levels.oceans[:-1]))
                for levels in self.sea.levels)
            coords, origin = self.texcoords(t, count)
            foam_field = None
            if self.foam_grid is not None:
                g = self.foam_grid_at(t)
                foam_field = FoamField((g.center[0] - origin[0], g.center[1] - origin[1]), g.inner_radius,
                                       g.outer_radius, g.rings, g.segments, np.zeros(len(g.points), np.float32),
                                       0.0, foam_lace(self.scene), LACE_SIZE)
            shading = ShadingFields(cascades, SHADING_SPACINGS, np.zeros(SHADING_SPACINGS.size), origin, coords,
                                    foam_field)
        return FrameGeometry(positions, normals, foam, roughness, shading, scene_foam_lace(self.scene))

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
        shading = self.shading_fields(t, len(positions)) if self.shades_from_fields else None
        return FrameGeometry(positions, normals, foam, roughness, shading, scene_foam_lace(self.scene))
