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

__all__ = ["sun_rays", "splat_plane", "ray_window", "device_plane_irradiance", "FloorCaustics", "VolumeBeam", "SUN_CONE"]


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
    u = (points.x + path * direction.x - float(origin[0])) / cell - 0.5
    v = (points.y + path * direction.y - float(origin[1])) / cell - 0.5
    ju, iv = dr.floor(u), dr.floor(v)
    fu, fv = u - ju, v - iv
    if targets is None:
        targets = [dr.zeros(mi.Float, nx * ny) for _ in weights]
    values = [power if w is None else power * w(path) for w in weights]
    for dj, di, share in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)), (0, 1, (1 - fu) * fv),
                          (1, 1, fu * fv)):
        jj, ii = mi.Int32(ju) + dj, mi.Int32(iv) + di
        inside = on & (jj >= 0) & (jj < nx) & (ii >= 0) & (ii < ny)
        flat = mi.UInt32(dr.select(inside, ii * nx + jj, 0)) + int(offset)
        for target, value in zip(targets, values):
            dr.scatter_reduce(dr.ReduceOp.Add, target, value * share, flat, inside)
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


def ray_window(sun, n_water: float, centre, side: float, depths: tuple[float, float]):
    """(corner (x₀, y₀) [m] of a square map of ``side`` [m] centred on ``centre``, the rest window
    (x, y, side) [m] of the sun's rays that reach it on planes from ``depths[0]`` to ``depths[1]`` [m] down).

    The flat sea's refracted beam lands a horizontal distance d tan θ_t down-sun of where it left
    the surface at depth d; the window covers that shift over the range of depths, plus a margin
    of 0.35 d + 1 m for the tilted facets and the choppy displacement.
    """
    sin_t = math.hypot(sun[0], sun[1]) / n_water
    horizontal = -np.asarray(sun[:2]) / max(math.hypot(sun[0], sun[1]), 1e-12) * sin_t
    shifts = [horizontal * d / math.sqrt(1.0 - sin_t * sin_t) for d in depths]
    lo, hi = np.minimum(*shifts), np.maximum(*shifts)
    margin = 0.35 * max(depths) + 1.0
    x0 = float(centre[0]) - side / 2
    y0 = float(centre[1]) - side / 2
    return (x0, y0), (x0 - hi[0] - margin, y0 - hi[1] - margin, side + float(np.max(hi - lo)) + 2 * margin)


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
        self.spectrum = mi.Float(np.asarray(sun_spectrum, np.float32))
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
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.floor, self.z, self.cell, self.n_water = floor_shape, float(floor_z), float(cell), float(n_water)
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
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        sun = np.asarray(sun, float) / np.linalg.norm(sun)
        depth = max(-self.z, 0.0)
        (x0, y0), window = ray_window(sun, self.n_water, centre, self.side, (depth, depth))
        rays = sun_rays(shading, sun, self.n_water, window, self.cell / RAYS_PER_CELL)
        power, path_power = splat_plane(*rays, self.z, (x0, y0), self.cell, (self.count, self.count),
                                        weights=(None, lambda s: s))
        area = self.cell * self.cell
        self.irradiance, self.path_irradiance = power / area, path_power / area
        self.origin = mi.Point2f(x0, y0)
        dr.make_opaque(self.irradiance, self.path_irradiance, self.origin)
        self.set_sun(sun, sun_spectrum, wavelengths)

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


#: Spacing of the volume's planes [m].
SHAFT_PLANE_STEP = 0.5

#: Rays per cell side of the volume's planes [-] (the shafts are seen integrated along the view: fewer than the floor).
VOLUME_RAYS_PER_CELL = 2


class VolumeBeam(_BeamMap):
    """The sun's beam in the water's volume — the shafts — traced per frame onto horizontal planes.

    Planes every ``dz`` [m] from ``dz`` below the mean level down ``depth`` [m], each a square of
    ``side`` [m] in cells of ``cell`` [m] centred under the camera. Per cell, from the rays that
    land in it: the beam's scalar irradiance Σ P/|d_z| over the cell's area (per W m⁻² of the sun,
    unattenuated: the flux through a horizontal cell over the cosine of each ray's direction), the
    same weighted by the path length s from the surface and by the rays' horizontal directions
    (their power-weighted mean direction). At a scattering vertex inside the planes the tracer adds
    σ_s p(θ) E₀ E_n(λ) exp(−σ_t s̄), θ between the beam's mean direction and the view, trilinear
    between cells and planes, and leaves out every strategy that reaches the sun's cone from there.
    """

    CHANNELS = 4  # Σ P/|d_z|, Σ P s/|d_z|, Σ P d_x/|d_z|, Σ P d_y/|d_z|

    def __init__(self, cell: float, dz: float, side: float, depth: float, n_water: float):
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.cell, self.dz, self.n_water = float(cell), float(dz), float(n_water)
        self.count = int(round(float(side) / self.cell))
        self.side = self.count * self.cell
        self.planes = max(2, int(round(float(depth) / self.dz)))
        size = self.planes * self.count * self.count
        self.values = [dr.zeros(mi.Float, size) for _ in range(self.CHANNELS)]
        self.origin = mi.Point2f(0.0, 0.0)
        dr.make_opaque(*self.values, self.origin)
        self.set_sun((0.0, 0.0, 1.0), np.zeros(2), (360.0, 365.0))

    def height(self, k: int) -> float:
        """Height of plane k [m]: −(k + 1) dz."""
        return -(k + 1) * self.dz

    def update(self, shading, sun, sun_spectrum, wavelengths, centre) -> None:
        """Trace the frame's beam into the planes (as :meth:`FloorCaustics.update`)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        sun = np.asarray(sun, float) / np.linalg.norm(sun)
        # every plane's rays leave the surface up-sun of it: the rays' window covers them all
        (x0, y0), window = ray_window(sun, self.n_water, centre, self.side, (0.0, self.planes * self.dz))
        points, direction, power, lit = sun_rays(shading, sun, self.n_water, window,
                                                 self.cell / VOLUME_RAYS_PER_CELL)
        inverse = 1.0 / dr.maximum(-direction.z, 1e-6)
        weights = (lambda s: inverse, lambda s: s * inverse, lambda s: direction.x * inverse,
                   lambda s: direction.y * inverse)
        n2 = self.count * self.count
        values = [dr.zeros(mi.Float, self.planes * n2) for _ in range(self.CHANNELS)]
        for k in range(self.planes):
            splat_plane(points, direction, power, lit, self.height(k), (x0, y0), self.cell,
                        (self.count, self.count), weights, targets=values, offset=k * n2)
        area = self.cell * self.cell
        self.values = [v / area for v in values]
        self.origin = mi.Point2f(x0, y0)
        dr.make_opaque(*self.values, self.origin)
        self.set_sun(sun, sun_spectrum, wavelengths)

    # ---- traced into the render kernel

    def at(self, p, active):
        """(E₀ [W m⁻² per W m⁻²], s̄ [m], the beam's unit mean direction, inside) at points ``p`` in the water,
        trilinear between the cells' centres and the planes (above the first plane: the first plane's E₀ and
        direction, its path shortened by the height over it)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        n, planes = self.count, self.planes
        u = (p.x - self.origin.x) / self.cell - 0.5
        v = (p.y - self.origin.y) / self.cell - 0.5
        above = -p.z / self.dz - 1.0  # < 0 above the first plane
        w = dr.maximum(above, 0.0)
        inside = mi.Bool(active) & (u >= 0.0) & (v >= 0.0) & (u <= n - 1.0) & (v <= n - 1.0) & (w <= planes - 1.0)
        ju, iv, kw = dr.floor(u), dr.floor(v), dr.floor(w)
        fu, fv, fw = u - ju, v - iv, w - kw
        j0 = dr.minimum(mi.UInt32(dr.maximum(ju, 0.0)), n - 2)
        i0 = dr.minimum(mi.UInt32(dr.maximum(iv, 0.0)), n - 2)
        k0 = dr.minimum(mi.UInt32(dr.maximum(kw, 0.0)), planes - 2)
        sums = [mi.Float(0.0) for _ in range(self.CHANNELS)]
        for dk, sk in ((0, 1 - fw), (1, fw)):
            for dj, di, share in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)), (0, 1, (1 - fu) * fv),
                                  (1, 1, fu * fv)):
                index = ((k0 + dk) * n + i0 + di) * n + j0 + dj
                for c in range(self.CHANNELS):
                    sums[c] += sk * share * dr.gather(mi.Float, self.values[c], index, inside)
        e, es, ex, ey = sums
        positive = e > 0.0
        scale = dr.select(positive, 1.0 / dr.maximum(e, 1e-30), 0.0)
        mx, my = ex * scale, ey * scale  # the weighted mean of the rays' horizontal components
        direction = dr.normalize(mi.Vector3f(mx, my, -dr.sqrt(dr.maximum(1.0 - mx * mx - my * my, 1e-6))))
        # above the first plane (within dz of the surface) the beam has come a shorter way: the first
        # plane's mean path less the height over it along the beam (the irradiance is the plane's)
        path = dr.maximum(es * scale + dr.minimum(above, 0.0) * self.dz / dr.maximum(-direction.z, 1e-3), 0.0)
        return e, path, direction, inside & positive
