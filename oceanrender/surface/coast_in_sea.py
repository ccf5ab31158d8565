"""The coast inside the open sea: one closed water body from the beach to the horizon.

A scene with ``[coastal] waves = "open sea"`` renders one body, the camera's
radial mesh (:class:`~.open_sea.WaterBody`), whose surface is the FFT sea
everywhere except near the coast, where the shallow-water solver's surface
takes over. At a rest point x of the mesh, with all heights relative to the
still level (docs/coastal.md, "The coast inside the open sea"):

    z = τ_s (η_F − η_L) + τ_L (1 − w) η_L + w η_S,
    D = τ_s (D_F − D_L) + τ_L (1 − w) D_L                                 (horizontal displacement)

* η_F, D_F: the FFT sea (every cascade, the mesh's level of detail);
* η_L, D_L: its long waves, the exact modes the solver's offshore side is
  driven by (:func:`~oceanrender.coastal.embedding.sea_long_modes`), so
  η_F − η_L are the waves the solver does not carry;
* η_S: the solver's surface, bilinear in its cell centres;
* w: the solver's weight, 1 inside the domain, a C¹ smoothstep to 0 over
  ``blend_width`` at its offshore and lateral sides, 0 outside
  (:func:`~oceanrender.coastal.embedding.blend_weight`);
* τ_s, τ_L: the depth-limited saturation of the waves no solver carries,
  tanh(γ d / H_rms) of the still depth d of the terrain, with H_rms of the
  short waves and of the whole sea (:func:`~oceanrender.coastal.embedding.depth_taper`).

Far from the coast w = 0 and τ = 1, so z = η_F and the body *is* the open sea;
inside the domain w = 1: the solver's surface plus the short waves, which
fade where the water gets shallow. Across the join every term is continuous
with continuous first derivatives, so heights and slopes are continuous; the
slopes are those of this formula (the product rule on w and τ included).
Where, inside the blend, only one of the two surfaces (sea, solver) is above
the terrain, their depths are blended instead (:func:`_depth_blend`; the same
z where both are wet), so the solver's swash fades with w on a beach the sea
leaves dry. A point is wet where z lies more than max(``h_min``, :data:`RENDERED_FILM`) above the terrain; elsewhere
the surface is put at least ``dry_drop`` below it, as on the isolated coast
(:mod:`.coastal_mesh`), and the beach hides it. The terrain
(:func:`~oceanrender.coastal.embedding.terrain_height`: the solver's bed
continued along the coast, inland and offshore) is a heightfield on the same
triangles, out to the horizon ring, so no water or land ends in a void.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..coastal.embedding import (blend_weight, depth_taper, domain_frame, grid_sample, long_wave_cutoff,
                                 sea_long_modes, side_distances, terrain_height)
from ..scene import arrays
from .coastal_body import CoastalBody
from .coastal_mesh import DRY_DROP
from .frame import FrameGeometry, JoinShading, Terrain
from .open_sea import WaterBody, scene_foam_lace
from .radial_mesh import horizon_radius, radial_body_faces, radial_body_vertices

#: A taper within this of 1 counts as 1 [-]: the sea there is the FFT sea to 1e-4 of its height.
TAPER_ONE = 1e-4

#: Thinnest water drawn as water [m]; thinner films are drawn as land. Mitsuba 3 starts a ray spawned at a
#: surface point p at (1 + max|p_i|) × 8.9e-5 m from it along the normal (``math::RayEpsilon`` of float32
#: times the coordinates' scale): 3.7 mm at 40 m from the origin, 9 mm at 100 m. A ray leaving the sand under a
#: thinner film starts above the water surface, misses it, and the film renders black-blue (measured: 20 % of
#: the dry sand's luminance under 2 mm films, where ~55 % is expected for wet sand under a film, Lekner &
#: Dorf 1988). 1 cm keeps every film in view 3× thicker than the offset within 30 m of the origin.
RENDERED_FILM = 0.01


#: Cells the water level is carried into dry land for the surface under it (:func:`extended_level`) [-].
LEVEL_PASSES = 6

#: Distance over which the rock cover fades out at the grid's edges [m] (no rock pattern outside).
ROCK_FADE = 10.0

#: Steepest slope sand can rest at [-]: tan 34°, the angle of repose of dry quartz sand (Bagnold 1941,
#: "The Physics of Blown Sand and Desert Dunes", ch. 13: 32–34°). Steeper terrain is bare rock.
SAND_REPOSE_SLOPE = math.tan(math.radians(34.0))


def binomial_smooth(field: NDArray) -> NDArray[np.float64]:
    """The (1 2 1)/4 ⊗ (1 2 1)/4 filter of a (ny, nx) field, edges repeated: a sum of non-negative weights 1."""
    f = np.pad(np.asarray(field, float), 1, mode="edge")
    rows = 0.25 * f[:-2] + 0.5 * f[1:-1] + 0.25 * f[2:]
    return 0.25 * rows[:, :-2] + 0.5 * rows[:, 1:-1] + 0.25 * rows[:, 2:]


@dataclass(frozen=True)
class JoinGeometry:
    """The time-independent parts of the join at a set of world points (module docstring).

    x, y [m]; terrain z_b [m] and its gradient [-]; the tapers τ_s, τ_L [-] and
    their derivatives by the still depth [m⁻¹]; the solver's weight w [-] and its
    gradient [m⁻¹].
    """

    x: NDArray
    y: NDArray
    terrain: NDArray
    terrain_gx: NDArray
    terrain_gy: NDArray
    tau_s: NDArray
    dtau_s: NDArray
    tau_l: NDArray
    dtau_l: NDArray
    w: NDArray
    wx: NDArray
    wy: NDArray


def extended_level(level: NDArray, wet: NDArray, passes: int) -> NDArray[np.float64]:
    """The water level of wet cells carried ``passes`` cells into the dry ones [m].

    Each pass gives every dry cell next to a wet (or already reached) cell the
    mean level of those 4-neighbours; cells never reached keep ``level``. Under
    a dry point the water surface then lies at the level of the water beside it,
    so the surface crosses the rising beach where the water's level meets it,
    not at the next dry vertex of a coarse triangle.
    """
    value = np.where(wet, level, 0.0)
    known = np.asarray(wet, bool).copy()
    for _ in range(passes):
        v = np.pad(np.where(known, value, 0.0), 1)
        k = np.pad(known.astype(float), 1)
        total = v[:-2, 1:-1] + v[2:, 1:-1] + v[1:-1, :-2] + v[1:-1, 2:]
        count = k[:-2, 1:-1] + k[2:, 1:-1] + k[1:-1, :-2] + k[1:-1, 2:]
        reach = ~known & (count > 0)
        value = np.where(reach, total / np.maximum(count, 1.0), value)
        known |= reach
    return np.where(known, value, level)


def _depth_blend(w, wx, wy, bed, bed_g, sea_z, sea_g, solver_z, solver_g):
    """Where exactly one of the two surfaces is above the terrain inside the blend (0 < w < 1): depths blended.

    All heights [m] above the still level, gradients [-] as (x, y) pairs, at the same points:
    w, ∇w [m⁻¹] the solver's weight, bed z_b, and the two surfaces z_sea = τ_s η_short + τ_L η_L
    and z_solver = τ_s η_short + η_S. With a = max(z_sea − z_b, 0), b = max(z_solver − z_b, 0),
    z = z_b + (1 − w) a + w b and ∇z = ∇z_b + (1 − w) ∇a + w ∇b + (b − a) ∇w. Where both are
    wet this is the height blend (1 − w) z_sea + w z_solver exactly, so it is only applied where
    one is dry; there it keeps the other's water on the land instead of pulling it under by
    (1 − w) z_b: a thin swash film then fades with w across the lateral blend rather than
    vanishing where w drops below ~0.9 (a 13 m step of the shoreline within 8 m along the
    grid's end, seen from the cliff). Returns (indices, z, ∂z/∂x, ∂z/∂y) of those points, or None.
    """
    a, b = sea_z - bed, solver_z - bed
    sel = np.flatnonzero((w > 0) & (w < 1) & ((a > 0) != (b > 0)))
    if not sel.size:
        return None
    w, a, b = w[sel], np.maximum(a[sel], 0.0), np.maximum(b[sel], 0.0)
    wet_a, wet_b = (a > 0).astype(float), (b > 0).astype(float)
    out = [bed[sel] + (1 - w) * a + w * b]
    for bg, sg, rg, wg in zip(bed_g, sea_g, solver_g, (wx, wy)):
        bg = bg[sel]
        out.append(bg + (1 - w) * wet_a * (sg[sel] - bg) + w * wet_b * (rg[sel] - bg) + (b - a) * wg[sel])
    return sel, *out


class CoastInSea:
    """The water body of a coastal scene inside the open sea (the :class:`~.frame.WaterSurface` protocol)."""

    def __init__(self, scene, store: str | Path):
        self.scene = scene
        self.coastal = c = scene.coastal
        self.sea_body = WaterBody(scene)
        self.coast = CoastalBody(scene, store)
        self.domain = domain_frame(c)
        self.faces = self.sea_body.faces
        self.vertex_count = self.sea_body.vertex_count
        self.grid = self.sea_body.radial
        self.rest_x, self.rest_y = self.sea_body.rest_x, self.sea_body.rest_y
        self.modes = sea_long_modes(self.sea_body.sea, long_wave_cutoff(c, arrays.offshore_depth(c, self.coast.bed)))
        total = float(self.sea_body.sea.cascades.elevation_variance)
        self.rms_short = math.sqrt(8.0 * max(total - self.modes.variance, 0.0))  # H_rms = √8 σ (Rayleigh)
        self.rms_total = math.sqrt(8.0 * total)
        self.mesh = self.geometry(self.rest_x, self.rest_y)
        #: the mesh's terrain and its gradient at the rest points [m, -]
        self.terrain_z, self.terrain_gx, self.terrain_gy = self.mesh.terrain, self.mesh.terrain_gx, self.mesh.terrain_gy

    def geometry(self, x: NDArray, y: NDArray) -> "JoinGeometry":
        """The time-independent quantities of the join at world points (x, y) [m]."""
        c = self.coastal
        terrain, gx, gy = self._terrain_at(x, y)
        depth = c.still_level - terrain
        tau_s, dtau_s = depth_taper(depth, self.rms_short)
        tau_l, dtau_l = depth_taper(depth, self.rms_total)
        for tau, slope in ((tau_s, dtau_s), (tau_l, dtau_l)):
            one = tau > 1.0 - TAPER_ONE
            tau[one], slope[one] = 1.0, 0.0
        w, wx, wy = blend_weight(self.domain, c.offshore_side, c.blend_width, x, y)
        return JoinGeometry(np.asarray(x, float), np.asarray(y, float), terrain, gx, gy, tau_s, dtau_s, tau_l,
                            dtau_l, w, wx, wy)

    def _terrain_at(self, x: NDArray, y: NDArray) -> tuple[NDArray, NDArray, NDArray]:
        """Terrain height [m] and its world gradient [-] at world points (central differences over a cell)."""
        c = self.coastal

        def height(px, py):
            return terrain_height(self.coast.bed, self.domain, c.spacing, c.offshore_side, c.still_level,
                                  c.outer_slope, c.outer_depth, px, py)

        # NOTE: differences over one cell, not an infinitesimal step: the gradient of the bilinear bed is
        # constant per cell, and its shading showed every cell of a steep cliff as a facet.
        e = float(max(c.spacing))
        gx = (height(x + e, y) - height(x - e, y)) / (2 * e)
        gy = (height(x, y + e) - height(x, y - e)) / (2 * e)
        return height(x, y), gx, gy

    # -- the WaterSurface protocol -------------------------------------------------------------------
    @property
    def spectrum(self):
        """The open sea's directional spectrum Ψ(kx, ky) [m⁴]."""
        return self.sea_body.spectrum

    @property
    def finest_cell(self) -> float:
        """Finest resolved spacing of the geometry [m]: the FFT sea's."""
        return self.sea_body.finest_cell

    @property
    def per_vertex_roughness(self) -> bool:
        return self.sea_body.per_vertex_roughness

    @property
    def vertex_roughness(self) -> NDArray[np.float32]:
        """Beckmann α per vertex [-]: the open sea's (the waves the mesh does not resolve there)."""
        return self.sea_body.vertex_roughness

    def total_slope_variance(self, roughness: float) -> float:
        """Mean-square slope of the open sea's waves [-] (the sun lobe's width; the sea fills most of the view)."""
        return self.sea_body.total_slope_variance(roughness)

    def far_radius(self) -> float:
        """Radius of the flat horizon ring [m] (:func:`~.radial_mesh.horizon_radius`)."""
        return horizon_radius(self.sea_body.camera_height(0.0), self.grid.outer_radius, self.grid.segments)

    def solver_fields(self, t: float, x: NDArray, y: NDArray, terrain: NDArray) -> NDArray[np.float64]:
        """(η_S, ∂η_S/∂x, ∂η_S/∂y) at world points (x, y) inside the domain at scene time t [s] [m, -, -].

        η_S is the terrain there (``terrain`` [m]) plus the depth, bilinear in
        the cell centres, so the water meets the terrain exactly where the depth
        goes to zero. The depth is first smoothed by the 3 × 3 binomial filter
        (:func:`binomial_smooth`; rendering only, the stored fields stay
        exact): a swash front seen from a few metres otherwise shows the
        staircase of the cells where it stopped. The slopes are central
        differences of z_b + h where wet and z_b where dry on the cells (as
        :func:`~.coastal_mesh.water_body_vertices` shades), bilinear between
        cell centres and turned into world axes. A fourth row is the level of
        the water beside dry cells (:func:`extended_level`), where a dry point's
        surface is put.
        """
        c = self.coastal
        h, bed = binomial_smooth(self.coast.frame_fields(t)["h"]), self.coast.bed
        wet = h > max(c.h_min, RENDERED_FILM)
        gy, gx = np.gradient(np.where(h > c.h_min, bed + h, bed), c.spacing[1], c.spacing[0])
        level = extended_level(bed + h, wet, LEVEL_PASSES)
        depth, sx, sy, beside = (grid_sample(f, self.domain, c.spacing, x, y) for f in (h, gx, gy, level))
        wx, wy = self.domain.vector_to_world(sx, sy)
        return np.stack([terrain + depth - c.still_level, wx, wy, beside - c.still_level])

    def surface(self, t: float) -> tuple[NDArray, NDArray, NDArray]:
        """(displacement (V_top, 3) [m], slopes (V_top, 2) [-], wet (V_top,) bool) of the joined surface at t [s]."""
        return self.join(self.mesh, self.sea_body.surface(t), t)

    def surface_at(self, x: NDArray, y: NDArray, t: float, spacing: NDArray | None = None):
        """:meth:`surface` at any world points (x, y) [m], the sea filtered to ``spacing`` [m] (None: every wave)."""
        geometry = self.geometry(x, y)
        return self.join(geometry, self.sea_body.sea.sample(geometry.x, geometry.y, t, spacing), t)

    def join(self, g: "JoinGeometry", sea, t: float) -> tuple[NDArray, NDArray, NDArray]:
        """The module docstring's z and D, and ∇z, at the points of ``g`` from the sea sampled there at t [s]."""
        c = self.coastal
        disp = np.array(sea.displacement, dtype=np.float64)
        n = np.asarray(sea.normals, dtype=np.float64)
        slope = -n[:, :2] / n[:, 2:3]
        near = np.flatnonzero((g.w > 0) | (g.tau_s < 1.0) | (g.tau_l < 1.0))  # elsewhere z = η_F exactly
        under = disp[:, 2] + c.still_level
        if near.size:
            eta_l, dlx, dly, slx, sly = self.modes.fields(g.x[near], g.y[near], t)
            tau_s, tau_l = g.tau_s[near], g.tau_l[near]
            w, wx, wy = g.w[near], g.wx[near], g.wy[near]
            short = disp[near, 2] - eta_l
            eta_s = np.zeros(near.size)
            grad_s = np.zeros((2, near.size))
            beside = np.zeros(near.size)
            solver = w > 0
            if np.any(solver):
                eta_s[solver], grad_s[0, solver], grad_s[1, solver], beside[solver] = self.solver_fields(
                    t, g.x[near][solver], g.y[near][solver], g.terrain[near][solver])
            # the two surfaces and their gradients by the product rule; ∇τ = τ'(d) ∇d, ∇d = −∇z_b
            gdx, gdy = -g.terrain_gx[near], -g.terrain_gy[near]
            shx = tau_s * (slope[near, 0] - slx) + short * g.dtau_s[near] * gdx
            shy = tau_s * (slope[near, 1] - sly) + short * g.dtau_s[near] * gdy
            sea_z = tau_s * short + tau_l * eta_l
            sea_g = (shx + tau_l * slx + eta_l * g.dtau_l[near] * gdx, shy + tau_l * sly + eta_l * g.dtau_l[near] * gdy)
            solver_z = tau_s * short + eta_s
            solver_g = (shx + grad_s[0], shy + grad_s[1])
            z = (1 - w) * sea_z + w * solver_z
            sx = (1 - w) * sea_g[0] + w * solver_g[0] + (solver_z - sea_z) * wx
            sy = (1 - w) * sea_g[1] + w * solver_g[1] + (solver_z - sea_z) * wy
            under[near] = z + w * (beside - eta_s) + c.still_level  # a dry point's surface: the water beside it
            mixed = _depth_blend(w, wx, wy, g.terrain[near] - c.still_level, (g.terrain_gx[near], g.terrain_gy[near]),
                                 sea_z, sea_g, solver_z, solver_g)
            disp[near, 0] = tau_s * (disp[near, 0] - dlx) + tau_l * (1 - w) * dlx
            disp[near, 1] = tau_s * (disp[near, 1] - dly) + tau_l * (1 - w) * dly
            disp[near, 2] = z
            slope[near, 0], slope[near, 1] = sx, sy
            if mixed is not None:
                sel, zm, sxm, sym = mixed
                disp[near[sel], 2] = zm
                slope[near[sel], 0], slope[near[sel], 1] = sxm, sym
        disp[:, 2] += c.still_level
        wet = disp[:, 2] - g.terrain > max(c.h_min, RENDERED_FILM)
        dry = ~wet
        disp[dry, 0] = disp[dry, 1] = 0.0
        # NOTE: a dry point keeps the height of the water beside it when that is below the land (the sea's
        # own height outside the grid, the solver's level carried into the dry cells inside): the water and
        # the terrain then cross where that level meets the beach, a straight shoreline, where z_b − DRY_DROP
        # everywhere made it follow the dry vertices of the coarse far triangles (steps).
        disp[dry, 2] = np.minimum(under[dry], g.terrain[dry] - DRY_DROP)
        slope[dry, 0], slope[dry, 1] = g.terrain_gx[dry], g.terrain_gy[dry]
        return disp, slope, wet

    def frame(self, t: float) -> FrameGeometry:
        """The closed body at scene time t [s]; with ``[render] surface_shading = "fields"`` its shading fields
        (the sea's, joined as :meth:`join_shading` says)."""
        sea = self.sea_body.surface(t)
        disp, slope, wet = self.join(self.mesh, sea, t)
        normals = np.column_stack([-slope[:, 0], -slope[:, 1], np.ones(len(slope))])
        normals /= np.linalg.norm(normals, axis=1, keepdims=True)
        positions, normals = radial_body_vertices(self.grid, disp, normals, self.scene.water.depth,
                                                  far_radius=self.far_radius())
        solver_fresh = self.coast.foam_state(t)[1] if self.scene.foam.enabled else None
        foam = self.vertex_foam(t, wet, len(positions), solver_fresh) if solver_fresh is not None else None
        roughness = self.vertex_roughness if self.per_vertex_roughness else None
        shading = None
        if self.sea_body.shades_from_fields:
            shading = replace(self.sea_body.shading_fields(t, len(positions)),
                              join=self.join_shading(sea, positions, normals, wet, solver_fresh))
        return FrameGeometry(positions, normals, foam, roughness, shading, scene_foam_lace(self.scene))

    def join_shading(self, sea, positions: NDArray, normals: NDArray, wet: NDArray,
                     solver_fresh: NDArray | None) -> JoinShading:
        """How a hit takes the sea's detail (:class:`~.frame.JoinShading`; docs/pixel_detail.md).

        ``sea``: the FFT sea at the rest points (its displacement [m] and unit normals),
        ``positions`` and ``normals`` the body's vertices (all of them), ``wet`` the rest points
        under water, ``solver_fresh`` the solver's fresh white water B_S on its cells (None: no
        foam). On the surface τ_s of the join and the foam terms (A, C) of :meth:`foam_terms`,
        all 0 where dry; on the far ring
        τ_s = A = 1 (the sea itself); 0 on the skirt and bottom (never field-shaded).
        """
        g = self.mesh
        top = wet.size
        count = len(normals)
        own = np.array(normals, dtype=np.float32)
        own[:top] = sea.normals
        own_positions = np.array(positions, dtype=np.float32)
        own_positions[:top] = np.column_stack([g.x, g.y, np.zeros(top)]) + sea.displacement
        tau = np.zeros(count, np.float32)
        scale = np.zeros(count, np.float32)
        offset = np.zeros(count, np.float32)
        tau[:top] = np.where(wet, g.tau_s, 0.0)
        scale[:top], offset[:top] = self.foam_terms(wet, solver_fresh)
        tau[top: top + self.grid.segments] = scale[top: top + self.grid.segments] = 1.0
        return JoinShading(own, own_positions, tau, scale, offset)

    def foam_terms(self, wet: NDArray, solver_fresh: NDArray | None) -> tuple[NDArray, NDArray]:
        """(A, C) per rest point [-]: the fresh foam there is A·B_sea + C, B_sea the sea's whitecaps.

        A = (1 − w) τ_s (the sea's foam fades with the solver's weight and the short waves'
        depth taper), C = w B_S (the solver's white water ``solver_fresh`` on its cells, bilinear;
        None: no foam, C = 0); both 0 where dry (``wet`` False).
        """
        g = self.mesh
        scale = np.where(wet, (1.0 - g.w) * g.tau_s, 0.0)
        offset = np.zeros(wet.size)
        inside = np.flatnonzero((g.w > 0) & wet)
        if inside.size and solver_fresh is not None:
            offset[inside] = g.w[inside] * grid_sample(solver_fresh, self.domain, self.coastal.spacing, g.x[inside],
                                                       g.y[inside])
        return scale, offset

    def vertex_foam(self, t: float, wet: NDArray, count: int, solver_fresh: NDArray) -> NDArray[np.float32]:
        """Fresh-foam weight per vertex [-]: the solver's white water inside, the sea's whitecaps outside, blended by w
        (:meth:`foam_terms`; ``solver_fresh`` the solver's B_S at t [s])."""
        fresh = np.array(self.sea_body.vertex_foam(t, count)[1], dtype=np.float64)
        scale, offset = self.foam_terms(wet, solver_fresh)
        fresh[: wet.size] = scale * fresh[: wet.size] + offset
        return fresh.astype(np.float32)

    @cached_property
    def _terrain_mesh(self) -> Terrain:
        c = self.coastal
        segments = self.grid.segments
        theta = 2.0 * np.pi * np.arange(segments) / segments
        far = self.far_radius()
        cx, cy = self.grid.center
        fx, fy = far * np.cos(theta) + cx, far * np.sin(theta) + cy
        fz, fgx, fgy = self._terrain_at(fx, fy)
        x = np.concatenate([self.rest_x, fx])
        y = np.concatenate([self.rest_y, fy])
        z = np.concatenate([self.terrain_z, fz])
        gx = np.concatenate([self.terrain_gx, fgx])
        gy = np.concatenate([self.terrain_gy, fgy])
        positions = np.column_stack([x, y, z]).astype(np.float32)
        normals = np.column_stack([-gx, -gy, np.ones_like(gx)])
        normals = (normals / np.linalg.norm(normals, axis=1, keepdims=True)).astype(np.float32)
        rings = self.grid.rings + 1
        faces = radial_body_faces(rings, segments)[: segments * (1 + 2 * (rings - 1))]  # the top: fan and rings
        rock = grid_sample(arrays.rock_mask(c), self.domain, c.spacing, x, y)
        xi, zeta = self.domain.to_local(x, y)
        edge = np.min([d for d, _ in side_distances(self.domain, xi, zeta).values()], axis=0)
        rock *= np.clip(edge / ROCK_FADE, 0.0, 1.0)
        # sand cannot rest steeper than its angle of repose: rock there, fading in over ±20 % of the slope
        steep = np.clip((np.hypot(gx, gy) / SAND_REPOSE_SLOPE - 0.8) / 0.4, 0.0, 1.0)
        rock = np.maximum(rock, steep)
        return Terrain(positions, faces, normals, rock.astype(np.float32), c.sand_albedo, c.rock_albedo)

    def terrain(self) -> Terrain:
        """The terrain on the body's own top triangles, out to the horizon ring (:class:`~.frame.Terrain`)."""
        return self._terrain_mesh
