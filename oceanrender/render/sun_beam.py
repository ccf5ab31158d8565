"""The sun's beam under the sea traced on the device, from the same fields that shade the camera's hits (issue 41).

:mod:`oceanrender.surface.sunlight` follows the beam in numpy from a sea sampled point by
point; here the same light tracing runs in Dr.Jit — one code path for the CPU (``llvm``)
and GPU (``cuda``) variants — from the sea's level fields already on the device
(:class:`~oceanrender.render.sea_shading.SeaShading`), so the light under the water is
refracted by exactly the surface the camera sees, and a frame's planes cost one kernel:

1. a square grid of rest points (spacing h) over a window of the sea;
2. at each, the fields at shading spacing Δ = h (all eight channels: the displaced
   position, the slopes and the displacement gradient, :meth:`SeaShading.fields_at`), the
   vector area N = ∂p/∂x₀ × ∂p/∂y₀ and the unit normal;
3. the power E_n max(0, ŝ·N) h² T (E_n = 1: the planes are per unit normal irradiance of
   the sun), T and the refracted direction from Mitsuba's ``fresnel`` and ``refract``
   (unpolarised Fresnel, Snell's law);
4. on each plane, the landing point and a bilinear share of the power added to its four
   cells (``scatter_reduce``), the cells' power over their area.

Bias and resolution as in :mod:`oceanrender.surface.sunlight` (the cell; the ray spacing,
which must be finer where the light focuses).
"""

from __future__ import annotations

import math

import numpy as np

from .buffers import jit_floats

__all__ = ["sun_rays", "splat_plane", "splat_points", "TerrainCaustics", "view_centre", "camera_water_hits", "ray_window", "device_plane_irradiance", "FloorCaustics", "VolumeBeam", "SUN_CONE"]


def sun_rays(shading, sun, n_water: float, window: tuple[float, float, float], ray: float):
    """The sun's rays under the sea from a square window of rest positions, on the device.

    Returns ((x, y, z) of the facets [m, world], refracted unit directions, power [W per W m⁻²
    of the sun's normal irradiance], lit): one ray per rest point (x₀ + (j + ½) h, y₀ + (i + ½) h)
    of ``window`` = (x₀, y₀, side) [m], h = ``ray`` [m] (also the fields' shading spacing).
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    from .sea_shading import ALL_CHANNELS  # noqa: PLC0415

    x0, y0, side = (float(v) for v in window)
    count = int(np.ceil(side / ray))
    index = dr.arange(mi.UInt32, count * count)
    i, j = index // count, index % count
    ox, oy = float(shading.origin.x[0]), float(shading.origin.y[0])
    rest = mi.Point2f(x0 - ox + (mi.Float(j) + 0.5) * ray, y0 - oy + (mi.Float(i) + 0.5) * ray)
    eta, dx, dy, sx, sy, xx, yy, xy = shading.fields_at(rest, mi.Float(float(ray)), mi.Bool(True), ALL_CHANNELS)
    area = shading.area_normal(sx, sy, xx, yy, xy)  # ∂p/∂x₀ × ∂p/∂y₀ per unit rest area
    normal = dr.normalize(area)
    s = mi.Vector3f(*(float(c) for c in np.asarray(sun, float) / np.linalg.norm(sun)))
    cos_i = dr.dot(normal, s)
    lit = cos_i > 0.0
    reflectance, cos_t, _, eta_ti = mi.fresnel(dr.maximum(cos_i, 1e-6), mi.Float(float(n_water)))
    # refract(ω_i, m, cos θ_t, η_ti): ω_i towards the sun, its refraction below the facet
    direction = mi.refract(mi.Vector3f(s), mi.Normal3f(normal), cos_t, eta_ti)
    lit &= direction.z < 0.0
    power = dr.select(lit, dr.dot(area, s) * (1.0 - reflectance) * (ray * ray), 0.0)
    if getattr(shading, "foam_layout", None) is not None:  # the whitecaps' opaque foam lets nothing through
        facet = dr.zeros(mi.SurfaceInteraction3f, count * count)
        facet.uv, facet.n = mi.Point2f(rest.x, rest.y), mi.Normal3f(0.0, 0.0, 1.0)
        power *= 1.0 - dr.clip(shading.foam_at(facet, lit), 0.0, 1.0)
    points = mi.Point3f(rest.x + ox + dx, rest.y + oy + dy, eta)
    return points, direction, power, lit


def splat_plane(points, direction, power, lit, z: float, origin: tuple[float, float], cell: float,
                shape: tuple[int, int], weights=(None,), targets=None, offset: int = 0):
    """Per cell of the plane at height ``z`` [m], the power of the rays landing on it (bilinear shares),
    for each entry of ``weights`` (None: the power itself; a callable of the path length s [m]: the
    power times it) — device buffers (ny·nx,), rows along y; power landing outside is dropped.
    ``targets``: buffers to add into instead, from entry ``offset`` on."""
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    ny, nx = int(shape[0]), int(shape[1])
    path = (float(z) - points.z) / dr.minimum(direction.z, -1e-6)
    on = lit & (path >= 0.0)
    if targets is None:
        targets = [dr.zeros(mi.Float, nx * ny) for _ in weights]
    values = [power if w is None else power * w(path) for w in weights]
    return splat_points(points.x + path * direction.x, points.y + path * direction.y, on, values, origin, cell,
                        shape, targets, offset)


#: Fixed-point steps per the largest share of a launch in :func:`splat_points` (2⁴⁰: a cell may take 2²³ such
#: shares before its 64-bit sum overflows; the shares are rounded to 2⁻⁴⁰ of the largest).
FIXED_POINT_STEPS = float(2**40)


def splat_points(x, y, on, values, origin: tuple[float, float], cell: float, shape: tuple[int, int], targets,
                 offset: int = 0):
    """Add ``values`` at points (x, y) [m] (lanes ``on``) to the cells of ``targets`` (rows along y, (ny, nx) =
    ``shape`` from entry ``offset`` on, corner ``origin`` [m], side ``cell`` [m]) in bilinear shares between
    the cells' centres; what lands outside is dropped.

    The shares are summed in 64-bit fixed point (:data:`FIXED_POINT_STEPS` per the launch's largest share):
    integer addition is associative, so the sums do not depend on the order in which the threads' atomic
    adds land — the same map bit for bit in every run, process and machine (float atomics are not: a Dask
    worker's frame differed from the single process's in the last bit). Each value's sums are then added
    to its target once per cell.
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    int64 = dr.int64_array_t(mi.Float)
    float64 = dr.float64_array_t(mi.Float)
    ny, nx = int(shape[0]), int(shape[1])
    # (per-launch numbers as opaque values, not literals: one compiled kernel for every frame and launch)
    corner = mi.Point2f(float(origin[0]), float(origin[1]))
    dr.make_opaque(corner)
    u = (x - corner.x) / cell - 0.5
    v = (y - corner.y) / cell - 0.5
    ju, iv = dr.floor(u), dr.floor(v)
    fu, fv = u - ju, v - iv
    values = [float64(dr.select(on, value, 0.0)) for value in values]
    dr.eval(u, v, on, *values)  # (the rays traced once, in one kernel, before their largest share is found)
    scales = [float64(FIXED_POINT_STEPS / max(float(dr.max(dr.abs(value))[0]), 1e-30)) for value in values]
    dr.make_opaque(*scales)
    sums = [dr.zeros(int64, nx * ny) for _ in values]
    for dj, di, share in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)), (0, 1, (1 - fu) * fv),
                          (1, 1, fu * fv)):
        jj, ii = mi.Int32(ju) + dj, mi.Int32(iv) + di
        inside = on & (jj >= 0) & (jj < nx) & (ii >= 0) & (ii < ny)
        flat = mi.UInt32(dr.select(inside, ii * nx + jj, 0))
        for total, value, scale in zip(sums, values, scales):
            dr.scatter_reduce(dr.ReduceOp.Add, total, int64(dr.round(value * float64(share) * scale)), flat, inside)
    cells = dr.arange(mi.UInt32, nx * ny) + int(offset)
    for target, total, scale in zip(targets, sums, scales):
        dr.scatter_reduce(dr.ReduceOp.Add, target, mi.Float(float64(total) / scale), cells)
    return targets


def device_plane_irradiance(shading, sun, n_water: float, window: tuple[float, float, float], ray: float,
                            depths, cell: float, shape: tuple[int, int], plane_origins, attenuation: float = 0.0):
    """Irradiance [W m⁻² per W m⁻² of the sun's normal irradiance] on horizontal planes below the sea.

    Parameters
    ----------
    shading : SeaShading           The sea's fields on the device (their rest coordinates relative to
                                   ``shading.origin``, as the mesh's texture coordinates).
    sun : 3 floats                 Unit vector towards the sun (z up).
    n_water : float                The water's refractive index relative to air [-].
    window : (x₀, y₀, side)        Rest positions [m, world] of the rays: the square from (x₀, y₀).
    ray : float                    Rest spacing h of the rays [m] (and the fields' shading spacing).
    depths : sequence of float     Heights z of the planes [m] (below the surface: negative).
    cell : float                   Side of the square cells [m].
    shape : (ny, nx)               Cells per plane.
    plane_origins : sequence of (float, float)   Corner of each plane's cells [m, world].
    attenuation : float            Beam attenuation a + b [m⁻¹] over the path from the surface.

    Returns
    -------
    ndarray (len(depths), ny, nx), float64. Power that lands outside a plane is dropped.
    """
    import drjit as dr  # noqa: PLC0415

    rays = sun_rays(shading, sun, n_water, window, ray)
    ny, nx = int(shape[0]), int(shape[1])
    planes = []
    for z, origin in zip(depths, plane_origins):
        (target,) = splat_plane(*rays, z, origin, cell, shape, weights=(lambda s: dr.exp(-float(attenuation) * s),))
        planes.append(np.asarray(target, np.float64).reshape(ny, nx))
    return np.stack(planes) / (float(cell) ** 2)


#: Angular radius of ``sunsky``'s sun [rad]: Mitsuba's aperture 0.5358° / 2 (measured: a uniform disk to 0.26°,
#: nothing from 0.27°; docs/sunlight.md).
SUN_RADIUS = math.radians(0.5358 / 2)

#: The cone of directions around the sun that the floor's map takes over from the path tracer [rad]: the sun's
#: disk and 5 % more (the sky inside it is 10⁻⁵ of the sun's light there, left out).
SUN_CONE = 1.05 * SUN_RADIUS

#: Rays per cell side of the floor's map [-]: the rays must part by less than a cell where the waves focus.
RAYS_PER_CELL = 4


def window_margin(depth: float) -> float:
    """How far beyond the flat sea's beam [m] the rays that reach ``depth`` [m] down may leave the surface:
    0.35 d + 1 m, for the tilted facets and the choppy displacement."""
    return 0.35 * float(depth) + 1.0


def ray_window(sun, n_water: float, centre, side: float, depths: tuple[float, float], margin: float | None = None):
    """(corner (x₀, y₀) [m] of a square map of ``side`` [m] centred on ``centre``, the rest window
    (x, y, side) [m] of the sun's rays that reach it on planes from ``depths[0]`` to ``depths[1]`` [m] down).

    The flat sea's refracted beam lands a horizontal distance d tan θ_t down-sun of where it left
    the surface at depth d; the window covers that shift over the range of depths, plus ``margin`` [m]
    (None: :func:`window_margin`).
    """
    sin_t = math.hypot(sun[0], sun[1]) / n_water
    horizontal = -np.asarray(sun[:2]) / max(math.hypot(sun[0], sun[1]), 1e-12) * sin_t
    shifts = [horizontal * d / math.sqrt(1.0 - sin_t * sin_t) for d in depths]
    lo, hi = np.minimum(*shifts), np.maximum(*shifts)
    margin = window_margin(max(depths)) if margin is None else float(margin)
    x0 = float(centre[0]) - side / 2
    y0 = float(centre[1]) - side / 2
    return (x0, y0), (x0 - hi[0] - margin, y0 - hi[1] - margin, side + float(np.max(hi - lo)) + 2 * margin)


#: Std [cells] of the Gaussian over which :func:`blur_by_path` takes the rays' mean path (depth varies slowly).
PATH_SMOOTHING = 8.0

#: Blur widths of the floor maps' roughness levels [cells] (:func:`blur_by_path`): a cell's blur is interpolated
#: between the two levels around its own.
BLUR_LEVELS = (0.0, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0)


def shading_alpha(shading, spacing: float) -> float:
    """Beckmann α [-] of the sea's fields at shading spacing ``spacing`` [m] (:meth:`SeaShading.alpha_at`, on the host)."""
    table = np.asarray(shading.alpha, float)
    u = (math.log(spacing) - shading.log_spacing_0) / shading.log_spacing_step
    return float(np.interp(u, np.arange(table.size), table))


def refraction_spread(alpha: float, sun, n_water: float) -> float:
    """Std of the refracted direction [rad] through microfacets of Beckmann roughness ``alpha`` [-], sun ``sun``.

    The microfacets' slopes have a variance α²/2 per axis (Beckmann: Walter et al. 2007, Eq. 33); tilting the
    normal by δ turns the refracted ray, in the plane of incidence, by δ (1 − cos θ_i / (n cos θ_t))
    (Snell's law differentiated; 1 − 1/n at normal incidence). Taken for both axes (isotropic, first order)."""
    cos_i = float(np.clip(np.asarray(sun, float)[2] / np.linalg.norm(sun), 1e-6, 1.0))
    sin_t = math.sqrt(1.0 - cos_i * cos_i) / n_water
    cos_t = math.sqrt(1.0 - sin_t * sin_t)
    return abs(1.0 - cos_i / (n_water * cos_t)) * float(alpha) / math.sqrt(2.0)


def blur_by_path(power, path_power, count: int, cell: float, spread: float):
    """The maps (power, power × path) [any units] of ``count``² cells of ``cell`` [m] blurred, each cell by a Gaussian
    of std s̄ ``spread`` [m], s̄ = path_power / power its rays' mean path [m] in the water (device buffers in and out).

    The rays carry the resolved waves' refraction; the waves finer than the rays' spacing (the surface's
    roughness α there) turn each ray by a further ``spread`` [rad] (:func:`refraction_spread`), which over a
    path s spreads its light over s·spread on the floor — what the path tracer's rough surface does to the
    same light. Gaussian blurs at :data:`BLUR_LEVELS` (scipy.ndimage, energy-preserving, edges mirrored), and
    per cell the linear interpolation between the two levels around its own width, from the mean path of the
    rays within :data:`PATH_SMOOTHING` cells (a gather: on a floor of slowly varying depth every cell near a
    point takes the point's width, so its power is kept).
    """
    from scipy.ndimage import gaussian_filter  # noqa: PLC0415

    if spread <= 0.0:
        return power, path_power
    e = np.asarray(power, np.float64).reshape(count, count)
    es = np.asarray(path_power, np.float64).reshape(count, count)
    # the paths' mean over PATH_SMOOTHING cells: defined where a cell's own rays are few or none (a shadow's edge)
    near, near_path = (gaussian_filter(a, PATH_SMOOTHING, mode="mirror") for a in (e, es))
    width = np.where(near > 0, near_path / np.maximum(near, 1e-30), 0.0) * spread / cell  # [cells]
    levels = np.asarray(BLUR_LEVELS)
    k = np.clip(np.searchsorted(levels, width) - 1, 0, len(levels) - 2)
    f = np.clip((width - levels[k]) / (levels[k + 1] - levels[k]), 0.0, 1.0)
    out_e, out_es = np.zeros_like(e), np.zeros_like(es)
    for j, sigma in enumerate(levels):
        share = np.where(k == j, 1.0 - f, 0.0) + np.where(k + 1 == j, f, 0.0)
        if not share.any():
            continue
        blurred = [a if sigma == 0 else gaussian_filter(a, sigma, mode="mirror") for a in (e, es)]
        out_e += share * blurred[0]
        out_es += share * blurred[1]
    return jit_floats(out_e), jit_floats(out_es)


class _BeamMap:
    """What the maps of the sun's beam share in the render kernel: the sun's cone and its spectrum."""

    sun = None
    spectrum = None
    cos_cone = float(math.cos(SUN_CONE))
    wavelength_0, wavelength_step = 360.0, 5.0

    def set_sun(self, sun, sun_spectrum, wavelengths) -> None:
        """The frame's sun: unit vector towards it, its normal irradiance [W m⁻² nm⁻¹] at ``wavelengths`` [nm]."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.sun = mi.Vector3f(*(float(c) for c in sun))
        self.wavelength_0 = float(wavelengths[0])
        self.wavelength_step = float(wavelengths[1] - wavelengths[0])
        self.spectrum = jit_floats(sun_spectrum)
        dr.make_opaque(self.sun, self.spectrum)

    def in_cone(self, direction):
        """Directions (unit, in the air) inside the sun's cone :data:`SUN_CONE`."""
        import drjit as dr  # noqa: PLC0415

        return dr.dot(direction, self.sun) >= self.cos_cone

    def sun_irradiance(self, wavelengths, active):
        """The sun's normal irradiance E_n [W m⁻² nm⁻¹] at ``wavelengths`` [nm] (a Spectrum), linear in λ."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        size = dr.width(self.spectrum)
        channels = []
        for c in range(dr.size_v(mi.Spectrum)):
            u = dr.clip((wavelengths[c] - self.wavelength_0) / self.wavelength_step, 0.0, size - 1.000001)
            i = mi.UInt32(dr.floor(u))
            channels.append(dr.lerp(dr.gather(mi.Float, self.spectrum, i, active),
                                    dr.gather(mi.Float, self.spectrum, i + 1, active), u - dr.floor(u)))
        return mi.Spectrum(channels)


class FloorCaustics(_BeamMap):
    """The sun's beam on the open sea's flat floor, traced per frame, for the in-water path tracer.

    A square map of ``side`` [m] in cells of ``cell`` [m] on the floor's plane z = ``floor_z``
    [m], centred under the camera: per cell the irradiance E₀ of the sun's beam refracted once
    by the sea's fields (per W m⁻² of the sun's normal irradiance, unattenuated) and E₀ s̄, s̄ the
    power-weighted path length from the surface [m]. At a floor vertex inside the map the
    tracer adds f_r E₀ E_n(λ) exp(−σ_t(λ) s̄) and leaves out every strategy that would reach
    the sun's cone (:data:`SUN_CONE`) from it through the surface, so the two add up to the
    unbiased estimator's expectation up to the map's resolution (docs/sunlight.md).
    """

    def __init__(self, floor_shape, floor_z: float, cell: float, side: float, n_water: float):
        self.floor, self.z, self.cell, self.n_water = floor_shape, float(floor_z), float(cell), float(n_water)
        self._empty_map(side)

    def _empty_map(self, side: float) -> None:
        """A dark square map of ``side`` [m] in cells of :attr:`cell`, and no sun yet."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.count = int(round(float(side) / self.cell))
        self.side = self.count * self.cell
        self.irradiance = dr.zeros(mi.Float, self.count * self.count)
        self.path_irradiance = dr.zeros(mi.Float, self.count * self.count)
        self.origin = mi.Point2f(0.0, 0.0)
        dr.make_opaque(self.irradiance, self.path_irradiance, self.origin)
        self.set_sun((0.0, 0.0, 1.0), np.zeros(2), (360.0, 365.0))

    def update(self, shading, sun, sun_spectrum, wavelengths, centre) -> None:
        """Trace the frame's beam: ``sun`` (unit, towards it), its normal irradiance ``sun_spectrum`` [W m⁻² nm⁻¹]
        at the evenly spaced ``wavelengths`` [nm], the map centred on ``centre`` (x, y) [m]."""
        sun = np.asarray(sun, float) / np.linalg.norm(sun)
        depth = max(-self.z, 0.0)
        (x0, y0), window = ray_window(sun, self.n_water, centre, self.side, (depth, depth))
        h = self.cell / RAYS_PER_CELL
        rays = sun_rays(shading, sun, self.n_water, window, h)
        power, path_power = splat_plane(*rays, self.z, (x0, y0), self.cell, (self.count, self.count),
                                        weights=(None, lambda s: s))
        self._store(power, path_power, shading_alpha(shading, h), (x0, y0), sun, sun_spectrum, wavelengths)

    def _store(self, power, path_power, alpha: float, corner, sun, sun_spectrum, wavelengths) -> None:
        """Keep a traced frame's map: the cells' power and power × path blurred by the roughness ``alpha`` [-]
        the rays did not resolve (:func:`blur_by_path`), over the cells' area; its ``corner`` (x₀, y₀) [m] and
        the frame's sun (:meth:`set_sun`)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        power, path_power = blur_by_path(power, path_power, self.count, self.cell,
                                         refraction_spread(alpha, sun, self.n_water))
        area = self.cell * self.cell
        self.irradiance, self.path_irradiance = power / area, path_power / area
        self.origin = mi.Point2f(float(corner[0]), float(corner[1]))
        dr.make_opaque(self.irradiance, self.path_irradiance, self.origin)
        self.set_sun(sun, sun_spectrum, wavelengths)

    def leave_out(self) -> None:
        """Move the map out of every floor's reach until the next :meth:`update` (an opaque origin: no new
        kernel): the path tracer lights the floor alone."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.origin = mi.Point2f(BEYOND_WINDOW, BEYOND_WINDOW)
        dr.make_opaque(self.origin)

    # ---- traced into the render kernel

    def on_floor(self, si):
        """Hits on the floor (its shape)."""
        import mitsuba as mi  # noqa: PLC0415

        return si.shape == mi.ShapePtr(self.floor)

    def at(self, p, active):
        """(E₀ [W m⁻² per W m⁻²], s̄ [m], inside the map) at floor points ``p``, bilinear between cell centres."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        n = self.count
        u = (p.x - self.origin.x) / self.cell - 0.5
        v = (p.y - self.origin.y) / self.cell - 0.5
        inside = mi.Bool(active) & (u >= 0.0) & (v >= 0.0) & (u <= n - 1.0) & (v <= n - 1.0)
        ju, iv = dr.floor(u), dr.floor(v)
        fu, fv = u - ju, v - iv
        j0 = dr.minimum(mi.UInt32(dr.maximum(ju, 0.0)), n - 2)
        i0 = dr.minimum(mi.UInt32(dr.maximum(iv, 0.0)), n - 2)
        e, es = mi.Float(0.0), mi.Float(0.0)
        for dj, di, share in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)), (0, 1, (1 - fu) * fv),
                              (1, 1, fu * fv)):
            index = (i0 + di) * n + j0 + dj
            e += share * dr.gather(mi.Float, self.irradiance, index, inside)
            es += share * dr.gather(mi.Float, self.path_irradiance, index, inside)
        path = dr.select(e > 0.0, es / dr.maximum(e, 1e-30), 0.0)
        return e, path, inside


#: Rays of the terrain's map traced per kernel launch [-] (memory: ~30 floats per ray).
TERRAIN_BATCH = 1 << 22

#: Vertical rays per side of the terrain's map that find its deepest floor (:meth:`TerrainCaustics.deepest_under`),
#: and the shapes (water, objects) each may pass on its way down.
DEPTH_PROBE = 32
MAX_SHAPES_ABOVE_FLOOR = 4

#: Camera rays per image side (columns, rows) that find where the terrain's map is centred (:func:`view_centre`).
VIEW_PROBE = (48, 27)


def camera_water_hits(scene, water, columns: int, rows: int):
    """(seen (rows, columns) bool, the hits): where the rays through the centres of a grid of the camera's
    film (the scene's first sensor) meet the water's upper surface (``water``: the body's shape) first."""
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    from .sea_shading import TOP_NORMAL_Z  # noqa: PLC0415

    index = dr.arange(mi.UInt32, columns * rows)
    film = mi.Point2f((mi.Float(index % columns) + 0.5) / columns, (mi.Float(index // columns) + 0.5) / rows)
    ray, _ = scene.sensors()[0].sample_ray(0.0, 0.5, film, mi.Point2f(0.5, 0.5))
    si = scene.ray_intersect(ray)
    seen = si.is_valid() & (si.shape == mi.ShapePtr(water)) & (si.n.z > TOP_NORMAL_Z)
    return np.asarray(seen, bool).reshape(rows, columns), si


def view_centre(scene, water, side: float, fallback):
    """(x, y) [m]: the median of where the camera's rays meet the water's upper surface within ``side`` [m] of
    the camera — the water in view that the maps can cover (``fallback`` where none does). ``water``: the
    water body's shape; the camera is the scene's first sensor (a :data:`VIEW_PROBE` grid of its rays)."""
    seen, si = camera_water_hits(scene, water, *VIEW_PROBE)
    seen = seen.ravel() & (np.asarray(si.t) <= float(side))
    if not seen.any():
        return tuple(float(c) for c in fallback[:2])
    return float(np.median(np.asarray(si.p.x)[seen])), float(np.median(np.asarray(si.p.y)[seen]))


class TerrainCaustics(FloorCaustics):
    """The sun's beam on ground under the water (the coast's sand and rocks), traced per frame by casting rays.

    The coast's floor is no plane, and its water no sea of fields everywhere: the sun's rays (spacing
    h = ``cell`` / :data:`RAYS_PER_CELL` on a horizontal grid) are cast against the frame's own scene —
    the water body's mesh, the terrain, the objects (whose shadows they keep) — with Mitsuba's ray
    tracing. At a ray's first hit on the water's upper surface the normal is the one the camera's hits
    are shaded with, at spacing h: the sea's fields (joined with the body's own surface where it is a
    coast inside the sea, :meth:`SeaShading._area_at`) with the visible-area weight
    w = max(0, ŝ·N) / ŝ·N_g of the fields' facet over the mesh's (as
    :meth:`SeaShading.shading_frame`), or the mesh's interpolated normal where the body has no fields
    (w then Veach's adjoint correction for shading normals). The ray carries the flux E_n h² ŝ_z through
    its horizontal cell (E_n = 1), times w, the unpolarised Fresnel transmittance 1 − F and 1 − the
    foam's weight (opaque white water); refracted (Snell) it is traced on, and where it meets
    the floor's shapes first its power, and its power times the length of its path in the water,
    are added in bilinear shares to the map's cells at the landing point's (x, y). The map holds flux
    per horizontal area P/A_h; the tracer's f_r (Mitsuba's ``eval``: the BRDF times the cosine towards
    the zenith, n_z on sloping ground) turns it into ρ/π times the ground's irradiance (P/A_h) n_z.

    The map (side ``side`` [m]) is centred on the water in view (:func:`view_centre`); its rays start
    above the scene's highest point, up-sun of the map by the flat sea's beam over the deepest ground
    under it (:meth:`deepest_under`, at most ``depth`` [m]) plus :func:`window_margin`; the roughness
    the rays do not resolve blurs it (:func:`blur_by_path`; ``alpha`` where there are no fields).
    """

    def __init__(self, scene, water, floors, cell: float, side: float, n_water: float, depth: float,
                 margin: float | None = None, foam=None, alpha: float = 0.0):
        self.scene, self.water, self.floors = scene, water, tuple(floors)
        self.cell, self.n_water, self.depth = float(cell), float(n_water), max(float(depth), 0.0)
        #: how far beyond the flat sea's beam the rays leave the surface [m] (None: :func:`window_margin`)
        self.margin = margin
        #: the surface's fresh-foam weight at a hit, ``(si, active) -> Float`` [-] (None: no foam): the foam is an
        #: opaque layer on that fraction of the surface (:func:`~.renderer.foamy_surface_bsdf`), no light passes it
        self.foam = foam
        #: Beckmann α [-] of the surface where it has no fields (its mesh's roughness): the maps' blur
        self.alpha = float(alpha)
        self._empty_map(side)

    def on_floor(self, si):
        """Hits on the floor's shapes (the terrain, and the sea's floor beyond it)."""
        import mitsuba as mi  # noqa: PLC0415

        found = mi.Bool(False)
        for shape in self.floors:
            found |= si.shape == mi.ShapePtr(shape)
        return found

    def update(self, shading, sun, sun_spectrum, wavelengths, centre) -> None:
        """Trace the frame's beam (as :meth:`FloorCaustics.update`; ``shading``: the sea's fields, or None where
        the body has none), the map centred on the water in view (``centre``: where there is none)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        sun = np.asarray(sun, float) / np.linalg.norm(sun)
        if sun[2] <= 1e-6:
            return
        centre = view_centre(self.scene, self.water, self.side, centre)
        top = float(self.scene.bbox().max.z) + 1.0  # above every shape: where the rays start
        depth = self.deepest_under(centre, top)
        (x0, y0), (wx, wy, wside) = ray_window(sun, self.n_water, centre, self.side, (0.0, depth), self.margin)
        lift = top / sun[2]  # from the still level up along the sun's direction to the start plane
        h = self.cell / RAYS_PER_CELL
        count = int(np.ceil(wside / h))
        rows = max(1, TERRAIN_BATCH // count)
        shape = (self.count, self.count)
        targets = [dr.zeros(mi.Float, self.count * self.count) for _ in range(2)]
        # (the frame's numbers as opaque values, not literals: one compiled kernel for every frame and launch)
        corner = mi.Point3f(float(wx + lift * sun[0]), float(wy + lift * sun[1]), float(top))
        rays = mi.Vector3f(*(float(c) for c in sun))
        dr.make_opaque(corner, rays)
        for first in range(0, count, rows):
            n_rows = min(rows, count - first)
            index = dr.arange(mi.UInt32, n_rows * count)
            i, j = index // count + first, index % count
            start = mi.Point3f(corner.x + (mi.Float(j) + 0.5) * h, corner.y + (mi.Float(i) + 0.5) * h, corner.z)
            power, landing, path, on = self._trace(shading, rays, start, h)
            splat_points(landing.x, landing.y, on, [power, power * path], (x0, y0), self.cell, shape, targets)
            dr.eval(*targets)
        alpha = self.alpha if shading is None else shading_alpha(shading, h)
        self._store(*targets, alpha, (x0, y0), sun, sun_spectrum, wavelengths)

    def deepest_under(self, centre, top: float) -> float:
        """The deepest floor [m below z = 0] under the map centred on ``centre`` (x, y) [m], at most
        :attr:`depth`: vertical rays from height ``top`` [m] on a :data:`DEPTH_PROBE`² grid over it (the rays'
        window follows it)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        n = DEPTH_PROBE
        index = dr.arange(mi.UInt32, n * n)
        corner = mi.Point3f(float(centre[0]) - self.side / 2, float(centre[1]) - self.side / 2, float(top))
        dr.make_opaque(corner)
        x = corner.x + (mi.Float(index % n) + 0.5) / n * self.side
        y = corner.y + (mi.Float(index // n) + 0.5) / n * self.side
        si = self.scene.ray_intersect(mi.Ray3f(mi.Point3f(x, y, corner.z), mi.Vector3f(0.0, 0.0, -1.0)))
        # (through the water and the objects: only the floor's shapes count)
        z = np.asarray(dr.select(si.is_valid() & self.on_floor(si), si.p.z, 0.0), float)
        for _ in range(MAX_SHAPES_ABOVE_FLOOR):
            missed = si.is_valid() & ~self.on_floor(si)
            if not np.asarray(missed).any():
                break
            si = self.scene.ray_intersect(si.spawn_ray(mi.Vector3f(0.0, 0.0, -1.0)), missed)
            z = np.where(np.asarray(missed & si.is_valid() & self.on_floor(si)), np.asarray(si.p.z, float), z)
        return float(np.clip(-z.min(), 0.0, self.depth))

    def _trace(self, shading, sun, start, h: float):
        """(power [W per W m⁻² of the sun's normal irradiance], landing point [m], path in the water [m], landed)
        of the sun's rays from ``start`` [m] (spacing ``h`` [m]) through the water onto the floor; ``sun`` the
        unit vector towards it (a Vector3f)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        from .sea_shading import TOP_NORMAL_Z  # noqa: PLC0415

        s = sun  # (an opaque Vector3f, unit, towards the sun)
        si = self.scene.ray_intersect(mi.Ray3f(start, -s))
        on = si.is_valid() & (si.shape == mi.ShapePtr(self.water)) & (si.n.z > TOP_NORMAL_Z)
        weight = mi.Float(1.0)
        normal = mi.Vector3f(si.sh_frame.n)
        if shading is not None:  # the camera's shading of the hit (its ray comes from the sun: si.wi), at spacing h
            normal, weight, _ = shading.shading_frame(si, on, spacing=h)
        cos_i = dr.dot(normal, s)
        on &= cos_i > 0.0
        reflectance, cos_t, _, eta_ti = mi.fresnel(dr.maximum(cos_i, 1e-6), mi.Float(self.n_water))
        direction = mi.refract(s, mi.Normal3f(normal), cos_t, eta_ti)
        on &= direction.z < 0.0
        if shading is None:
            # the mesh's interpolated normal shades a flat triangle: the adjoint of the path tracer's
            # transmission (Veach 1997, Eq. 5.19), |s·n_s| |d·n_g| / (|s·n_g| |d·n_s|), so that the flux the
            # triangle intercepts (s·n_g) is spread as the camera's paths see it through n_s
            geometric = mi.Vector3f(si.n)
            weight = (cos_i * dr.abs(dr.dot(direction, geometric))
                      / dr.maximum(dr.abs(dr.dot(s, geometric)) * dr.abs(cos_t), 1e-12))
        below = si.spawn_ray(direction)
        floor = self.scene.ray_intersect(below, on)
        on &= floor.is_valid() & self.on_floor(floor)
        if self.foam is not None:  # the opaque foam's share of the surface lets nothing through
            weight *= 1.0 - dr.clip(self.foam(si, on), 0.0, 1.0)
        power = dr.select(on, (h * h) * s.z * weight * (1.0 - reflectance), 0.0)
        return power, floor.p, floor.t, on


#: Spacing of the volume's planes [m].
SHAFT_PLANE_STEP = 0.5

#: Highest point of the water [m over the mean level] at which the volume's beam is read (above every crest).
BEAM_TOP = 10.0

#: Half-width of the region [m] around the window in which the volume's beam is read: beyond the window, the
#: window's mean profile (far past any visible sea: the camera's water body ends at its outer radius).
BEYOND_WINDOW = 1.0e6


def flat_beam_shear(sun, n_water: float) -> tuple[float, float]:
    """(d_x/d_z, d_y/d_z) of the flat sea's refracted beam [-]: a ray that leaves the mean level at (x, y) is at
    (x, y) + z (d_x/d_z, d_y/d_z) at height z < 0 (Snell's law, sin θ_t = sin θ_i / n)."""
    sun = np.asarray(sun, float) / np.linalg.norm(sun)
    sin_i = math.hypot(sun[0], sun[1])
    if sin_i < 1e-12:
        return 0.0, 0.0
    sin_t = sin_i / n_water
    tan_t = sin_t / math.sqrt(1.0 - sin_t * sin_t)
    return float(sun[0] / sin_i * tan_t), float(sun[1] / sin_i * tan_t)


#: Points per in-water segment at which the volume's beam is read (:meth:`VolumeBeam.along`) [-]: on a path's
#: first in-water segment, and on the later ones.
SHAFT_MARCH_POINTS = 8
SHAFT_MARCH_POINTS_AFTER = 2

#: Rays per cell side of the volume's planes [-] (the shafts are seen integrated along the view: fewer than the floor).
VOLUME_RAYS_PER_CELL = 2


class VolumeBeam(_BeamMap):
    """The sun's beam in the water's volume — the shafts — traced per frame onto horizontal planes.

    Planes every ``dz`` [m] from ``dz`` below the mean level down ``depth`` [m], each a square of
    ``side`` [m] in cells of ``cell`` [m] centred under the camera and sheared along the flat sea's
    refracted beam (plane k's cells start z_k (d_x/d_z, d_y/d_z) from the corner: a shaft stays in its
    cells from plane to plane). Per cell, from the rays that land in it: the beam's scalar irradiance
    Σ P/|d_z| over the cell's area (per W m⁻² of the sun, unattenuated: the flux through a horizontal
    cell over the cosine of each ray's direction), and the same weighted by the path length s from the
    surface, its square, and the rays' horizontal directions and their products (the paths' and the
    directions' means and spreads). Beyond the window each plane's mean over it stands for the beam
    (the caustics there are not resolved). Along every in-water segment of a path the tracer
    integrates σ_s p(θ) E₀ E_n(λ) exp(−σ_t s̄) (:meth:`along`), and at a scattering vertex inside the
    planes' depths it leaves out every strategy that reaches the sun's cone (docs/sunlight.md).
    """

    #: Σ P w/|d_z| for w = 1, s, d_x, d_y, s², d_x², d_y², d_x d_y
    CHANNELS = 8

    def __init__(self, cell: float, dz: float, side: float, depth: float, n_water: float):
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.cell, self.dz, self.n_water = float(cell), float(dz), float(n_water)
        self.count = int(round(float(side) / self.cell))
        self.side = self.count * self.cell
        self.planes = max(2, int(round(float(depth) / self.dz)))
        size = self.planes * self.count * self.count
        #: the planes' cells, their CHANNELS sums side by side (one cell: two Vector4f gathers)
        self.packed = dr.zeros(mi.Float, size * self.CHANNELS)
        #: per plane, its cells' CHANNELS sums averaged: the beam read beyond the window
        self.profile = dr.zeros(mi.Float, self.planes * self.CHANNELS)
        self.origin = mi.Point2f(0.0, 0.0)
        self.shear = mi.Point2f(0.0, 0.0)
        dr.make_opaque(self.packed, self.profile, self.origin, self.shear)
        self.set_sun((0.0, 0.0, 1.0), np.zeros(2), (360.0, 365.0))

    def height(self, k: int) -> float:
        """Height of plane k [m]: −(k + 1) dz."""
        return -(k + 1) * self.dz

    def update(self, shading, sun, sun_spectrum, wavelengths, centre) -> None:
        """Trace the frame's beam into the planes (as :meth:`FloorCaustics.update`), each plane's cells
        sheared along the flat sea's refracted beam (:meth:`at`)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        sun = np.asarray(sun, float) / np.linalg.norm(sun)
        shear = flat_beam_shear(sun, self.n_water)
        x0, y0 = float(centre[0]) - self.side / 2, float(centre[1]) - self.side / 2
        # every plane reads the same window of the surface (the shear follows the flat sea's beam)
        margin = window_margin(self.planes * self.dz)
        window = (x0 - margin, y0 - margin, self.side + 2 * margin)
        points, direction, power, lit = sun_rays(shading, sun, self.n_water, window,
                                                 self.cell / VOLUME_RAYS_PER_CELL)
        dr.eval(points, direction, power, lit)  # (traced once for all the planes)
        inverse = 1.0 / dr.maximum(-direction.z, 1e-6)
        weights = (lambda s: inverse, lambda s: s * inverse, lambda s: direction.x * inverse,
                   lambda s: direction.y * inverse, lambda s: s * s * inverse,
                   lambda s: direction.x * direction.x * inverse, lambda s: direction.y * direction.y * inverse,
                   lambda s: direction.x * direction.y * inverse)
        n2 = self.count * self.count
        values = [dr.zeros(mi.Float, self.planes * n2) for _ in range(self.CHANNELS)]
        for k in range(self.planes):
            z = self.height(k)
            splat_plane(points, direction, power, lit, z, (x0 + shear[0] * z, y0 + shear[1] * z), self.cell,
                        (self.count, self.count), weights, targets=values, offset=k * n2)
        area = self.cell * self.cell
        packed = dr.zeros(mi.Float, self.planes * n2 * self.CHANNELS)
        profile = dr.zeros(mi.Float, self.planes * self.CHANNELS)
        cells, planes = dr.arange(mi.UInt32, self.planes * n2), dr.arange(mi.UInt32, self.planes)
        for c, value in enumerate(values):
            dr.scatter(packed, value / area, cells * self.CHANNELS + c)
            # beyond the window: each plane's sums averaged over its cells (the beam's mean over the window)
            dr.scatter(profile, dr.block_sum(value, n2) / (n2 * area), planes * self.CHANNELS + c)
        self.packed, self.profile = packed, profile
        self.origin = mi.Point2f(x0, y0)
        self.shear = mi.Point2f(*shear)
        dr.make_opaque(self.packed, self.profile, self.origin, self.shear)
        self.set_sun(sun, sun_spectrum, wavelengths)

    # ---- traced into the render kernel

    def bounds(self):
        """The box [m] inside which :meth:`at` reads the beam: the planes' depths up to :data:`BEAM_TOP` over
        the mean level (the water above the first plane), and horizontally everywhere (beyond the window,
        the window's mean profile)."""
        import mitsuba as mi  # noqa: PLC0415

        far = BEYOND_WINDOW
        return mi.BoundingBox3f(mi.Point3f(self.origin.x - far, self.origin.y - far, -self.planes * self.dz),
                                mi.Point3f(self.origin.x + far, self.origin.y + far, BEAM_TOP))

    def along(self, ray, t_end, mei, phase, phase_ctx, weight, sigma_t, sampler, active, first):
        """The beam once scattered towards the ray's origin along the segment [0, ``t_end``] of ``ray`` [m]:

            ∫ e^{−σ_t t} σ_s p(θ(t)) E₀(t) E_n(λ) e^{−σ_t s̄(t)} dt   [W m⁻² sr⁻¹ nm⁻¹ per unit throughput],

        times ``weight``, estimated from :data:`SHAFT_MARCH_POINTS` points on the lanes' ``first`` in-water
        segment (the camera's, or the one after its first surface: the shafts the eye sees directly) and
        :data:`SHAFT_MARCH_POINTS_AFTER` on later ones (light scattered more than once: smooth), stratified in the inverse
        CDF of e^{−σ_min t} truncated to the part of the segment inside :meth:`bounds` (σ_min the
        smallest of the lanes' σ_t: every wavelength's integrand then decays at least as fast as the
        density, and its weight stays below the truncated density's normaliser). The strata's offset is
        drawn from ``sampler`` (one per segment, with the beam's directions at each point: :meth:`at`); the
        points' lengths are evaluated, not sampled by the path, so the path's wavelength densities stay as
        they are (as strategy D).
        """
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        hit, near, far = self.bounds().ray_intersect(ray)
        t0 = dr.maximum(near, 0.0)
        length = dr.minimum(far, t_end) - t0
        on = mi.Bool(active) & hit & (length > 0.0)
        length = dr.select(on, length, 0.0)
        sigma_min = dr.maximum(dr.min(sigma_t), 0.0)
        optical = sigma_min * length
        uniform = optical < 1e-4  # (the truncated exponential → uniform)
        mass = dr.select(optical < 1e-3, optical * (1.0 - 0.5 * optical), 1.0 - dr.exp(-optical))  # 1 − e^{−σ L}
        sun = self.sun_irradiance(ray.wavelengths, on) * mei.sigma_s * weight
        # the phase function's interaction: towards the ray's origin (as Mitsuba's free flight sets it)
        scatterer = dr.zeros(mi.MediumInteraction3f)
        scatterer.wi = -ray.d
        scatterer.sh_frame = mi.Frame3f(scatterer.wi)
        scatterer.wavelengths = ray.wavelengths
        total = mi.Spectrum(0.0)
        points = dr.select(mi.Bool(first), mi.Float(SHAFT_MARCH_POINTS), mi.Float(SHAFT_MARCH_POINTS_AFTER))
        u = sampler.next_1d(on)
        for i in range(SHAFT_MARCH_POINTS):
            on_i = on & (points > i) if i >= SHAFT_MARCH_POINTS_AFTER else on
            xi = (i + u) / points
            s = dr.select(uniform, xi * length, -dr.log(dr.maximum(1.0 - xi * mass, 1e-30)) / dr.maximum(sigma_min, 1e-30))
            inverse_pdf = dr.select(uniform, length, mass / dr.maximum(sigma_min, 1e-30) * dr.exp(sigma_min * s))
            scatterer.p = ray(t0 + s)
            e, path, spread, direction, inside = self.at(scatterer.p, on_i, sampler.next_2d(on_i))
            phase_value, _ = phase.eval_pdf(phase_ctx, scatterer, -direction, inside)
            # e^{−σ_t s} averaged over the cell's paths to second order: exp(−σ_t s̄ + σ_t² var(s)/2), the
            # correction capped at its first-order size (the cumulant expansion, Jensen's gap of exp(−σ_t s̄))
            optical_path = sigma_t * (t0 + s + path) - dr.minimum(0.5 * sigma_t * sigma_t * spread, sigma_t * path)
            value = dr.exp(-optical_path) * (e * phase_value * inverse_pdf / points)
            total += dr.select(inside, value, 0.0)
        return dr.select(on, sun * total, 0.0)

    def _locate(self, p, active):
        """Where points ``p`` read the planes: (inside, in the window, beyond it, the corner cell (j₀, i₀) and
        plane k₀, the fractions (f_u, f_v, f_w), the height over the first plane in plane spacings (< 0 above it))."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        n, planes = self.count, self.planes
        # the cells of plane k start at origin + z_k shear: the flat sea's beam line through p meets
        # every plane at the same (u, v), so a shaft along the beam stays in its cells from plane to plane
        u = (p.x - self.origin.x - self.shear.x * p.z) / self.cell - 0.5
        v = (p.y - self.origin.y - self.shear.y * p.z) / self.cell - 0.5
        above = -p.z / self.dz - 1.0  # < 0 above the first plane
        w = dr.maximum(above, 0.0)
        inside = mi.Bool(active) & (w <= planes - 1.0) & (p.z <= BEAM_TOP)
        window = inside & (u >= 0.0) & (v >= 0.0) & (u <= n - 1.0) & (v <= n - 1.0)
        ju, iv, kw = dr.floor(u), dr.floor(v), dr.floor(w)
        j0 = dr.minimum(mi.UInt32(dr.maximum(ju, 0.0)), n - 2)
        i0 = dr.minimum(mi.UInt32(dr.maximum(iv, 0.0)), n - 2)
        k0 = dr.minimum(mi.UInt32(dr.maximum(kw, 0.0)), planes - 2)
        return inside, window, inside & ~window, (j0, i0, k0), (u - ju, v - iv, w - kw), above

    def _plane_sums(self, where, dk: int, channels: int):
        """The first ``channels`` (4 or :attr:`CHANNELS`) sums of plane k₀ + ``dk`` at the points :meth:`_locate`
        found: bilinear between the cells' centres in the window, the plane's mean over it beyond."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        _, window, beyond, (j0, i0, k0), (fu, fv, _), _ = where
        n, vectors = self.count, channels // 4
        sums = [mi.Float(0.0) for _ in range(channels)]
        for dj, di, share in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)), (0, 1, (1 - fu) * fv),
                              (1, 1, fu * fv)):
            index = 2 * (((k0 + dk) * n + i0 + di) * n + j0 + dj)
            parts = [dr.gather(mi.Vector4f, self.packed, index + h, window) for h in range(vectors)]
            for c in range(channels):
                sums[c] += share * parts[c // 4][c % 4]
        # beyond the window: the plane's mean over the window (caustics there are not resolved; the
        # waves' mean redistribution of the beam is)
        parts = [dr.gather(mi.Vector4f, self.profile, 2 * (k0 + dk) + h, beyond) for h in range(vectors)]
        return [dr.select(beyond, parts[c // 4][c % 4], sums[c]) for c in range(channels)]

    def lit(self, p, active):
        """Points ``p`` at which :meth:`at` reads a beam (inside, E₀ > 0): where the tracer leaves the sun to it."""
        where = self._locate(p, active)
        fw = where[4][2]
        e = (1 - fw) * self._plane_sums(where, 0, 4)[0] + fw * self._plane_sums(where, 1, 4)[0]
        return where[0] & (e > 0.0)

    def at(self, p, active, jitter=None):
        """The beam at points ``p`` in the water, trilinear between the cells' centres and the planes
        (above the first plane: the first plane's E₀ and directions, its path shortened by the height over it;
        beyond the window, linear between the planes' means over it, :attr:`profile`).

        Returns (E₀ [W m⁻² per W m⁻² of the sun], s̄ [m], var(s) [m²], a unit direction of the beam, inside).
        The direction is the rays' power-weighted mean; with ``jitter`` (two uniform numbers in [0, 1)) it
        is drawn from the Gaussian of the rays' horizontal directions' mean and covariance, so that a phase
        function evaluated at it is that function averaged over the beam's spread of directions (to the
        spread's second moments: the rays a cell mixes come from facets of different slopes).
        """
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        where = self._locate(p, active)
        inside, fw, above = where[0], where[4][2], where[5]
        # per plane: bilinear sums, normalised to the rays' moments there; between the planes the moments
        # (not the sums: the path grows by dz/cos θ from plane to plane, no spread within a cell) linearly
        e, weight, moments = mi.Float(0.0), mi.Float(0.0), [mi.Float(0.0) for _ in range(self.CHANNELS - 1)]
        for dk, sk in ((0, 1 - fw), (1, fw)):
            sums = self._plane_sums(where, dk, self.CHANNELS)
            e += sk * sums[0]
            lit = sums[0] > 0.0  # (a plane no ray reaches here has no moments: the other plane's)
            share_k = dr.select(lit, sk, 0.0)
            weight += share_k
            # this plane's means (s̄, d̄_x, d̄_y) and (co)variances: a cell's own spread, not the planes' difference
            m_s, m_x, m_y, m_ss, m_xx, m_yy, m_xy = (sums[c] * dr.select(lit, 1.0 / dr.maximum(sums[0], 1e-30), 0.0)
                                                     for c in range(1, self.CHANNELS))
            stats = (m_s, m_x, m_y, m_ss - m_s * m_s, m_xx - m_x * m_x, m_yy - m_y * m_y, m_xy - m_x * m_y)
            for c, value in enumerate(stats):
                moments[c] += share_k * value
        positive = e > 0.0
        moments = [m / dr.maximum(weight, 1e-30) for m in moments]
        mean_path, mx, my, spread, cxx, cyy, cxy = moments  # mx, my: the rays' mean horizontal components
        spread = dr.maximum(spread, 0.0)
        # above the first plane (within dz of the surface) the beam has come a shorter way: the first
        # plane's mean path less the height over it along the mean beam (the irradiance is the plane's)
        cos_mean = dr.sqrt(dr.maximum(1.0 - mx * mx - my * my, 1e-6))
        path = dr.maximum(mean_path + dr.minimum(above, 0.0) * self.dz / cos_mean, 0.0)
        if jitter is not None:
            # a draw from N(m, C), C the horizontal components' covariance (its Cholesky factor)
            cxx, cyy = dr.maximum(cxx, 0.0), dr.maximum(cyy, 0.0)
            lxx = dr.sqrt(cxx)
            lyx = dr.select(lxx > 1e-7, cxy / dr.maximum(lxx, 1e-7), 0.0)
            lyy = dr.sqrt(dr.maximum(cyy - lyx * lyx, 0.0))
            # (inside (0, 1): a stratified sampler's numbers can round to 0 or 1 in float32, where Box–Muller's
            # logarithm is infinite and the direction NaN)
            g = mi.warp.square_to_std_normal(dr.clip(mi.Point2f(jitter), 1e-7, 0.99999994))
            mx, my = mx + lxx * g.x, my + lyx * g.x + lyy * g.y
        horizontal = dr.minimum(mx * mx + my * my, 1.0 - 1e-6)
        direction = dr.normalize(mi.Vector3f(mx, my, -dr.sqrt(1.0 - horizontal)))
        return e, path, spread, direction, inside & positive
