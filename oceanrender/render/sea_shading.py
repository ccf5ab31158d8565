"""Shading every water hit from the sea's own fields: normals, roughness and foam to the pixel.

The water body's mesh carries the displacement (silhouettes, horizon, parallax),
but its vertices are centimetres (near the camera) to metres (40 m away) apart,
while the cascades resolve waves down to 2.7 cm. Here every ray–water
intersection is shaded from the cascades themselves
(:class:`~oceanrender.surface.frame.ShadingFields`), in one code path for the
CPU (``llvm``) and GPU (``cuda``) variants (and ``scalar``):

1. **Rest position.** The hit's texture coordinates: the mesh's vertices carry
   their rest positions (x₀, y₀), so the barycentric interpolation Mitsuba
   does is the preimage of the hit under the piecewise-linear displacement the
   mesh carries — the choppy displacement inverted exactly for the surface
   that is rendered.
2. **Footprint.** w = d θ_px / √|cos θ| with d the distance from the camera,
   θ_px the angle of a pixel and θ the angle between the ray and the geometric
   normal: the side of a square with the area of the pixel's elliptical
   footprint on the surface (its width d θ_px across the view, d θ_px / cos θ
   along it). Secondary rays use the same distance to the camera (the pixel's
   cone where the path meets the surface again: a lower bound of their
   footprint). The shading spacing is Δ = w/2, so waves are whole at
   λ ≥ 4w (two pixels per half wave), fade out around λ = 2w (the pixel's
   Nyquist wavelength) and are gone at λ ≤ w (:mod:`oceanrender.waves.lod`).
3. **Normal.** Per cascade, levels ⌊s⌋ and ⌊s⌋ + 1 of s = log₂(k_top / k_f),
   k_f = π/(2Δ), bilinearly at the rest position (periodic), weighted
   (1 − f, f): the slopes ∂η/∂x₀, ∂η/∂y₀ and the displacement gradient, from
   which the normal of the displaced surface
   n ∝ (J_xy s_y − J_yy s_x, J_xy s_x − J_xx s_y, det J) (Tessendorf 2001, §4.3;
   the normal of the map (x₀, y₀) ↦ (x₀ + λD_x, y₀ + λD_y, η)).
4. **Roughness.** Beckmann α(Δ) = √(σ²_total − σ²_resolved(Δ)), tabulated per
   frame over Δ (:attr:`ShadingFields.alpha`): what the footprint does not
   resolve stays in the BSDF, so each pixel keeps the spectrum's whole slope
   variance (Bruneton, Neyret & Holzschuch 2010, Eq. 4).

5. **Parallax at the camera's hit** (:meth:`SeaShading.parallax`). The mesh
   misses the waves between its vertex spacing and the pixel by centimetres,
   which a ray 15° above the horizon turns into a shift of several pixel
   footprints. Two Newton steps on P(x) = (x + D_x, y + D_y, η) of the fields at Δ
   (all eight channels: position, slopes, displacement gradient) move the camera
   hit to where its ray meets that fine surface, so foreshortening and hiding of
   the fine waves are shape, as in brute-force geometry; the hit then counts as
   sampled (weight 1), and one that ends on a facet turned away from the ray (it
   crossed a crest it grazes) takes the mesh's normal.
   **Visible normals elsewhere.** At the other hits (rays from under the water,
   reflected rays meeting another wave) the BSDF's values are scaled by the ratio
   of the fields' projected area to the mesh's (:meth:`SeaShading.shading_frame`),
   so the normals a ray averages are the visible ones (Heitz 2014): they are many
   per camera sample, and a parallax there costs more than it changes. A path's hit on
   the sea is prepared once (:meth:`SeaSurfaceBSDF.prepared`: frame, α and foam) for all
   of that hit's BSDF calls, and each level of each cascade is read only in packets where
   some lane reads it with a weight (symbolic branches): the lookups at these many hits
   were the field shading's whole cost (docs/pixel_detail.md, "Cost").
6. **Foam.** The fresh-foam coverage B of the foam's own polar grid at the rest
   position (:meth:`SeaShading.foam_at`), drawn through a lace tile
   (:func:`lace_weight`): on average the fraction B of the surface, as a sheet
   where B → 1 and as thin lines where B is small.

The surface BSDF (``roughdielectric``, blended with foam) is wrapped by
:class:`SeaSurfaceBSDF`, which gives it the shading frame of (3) — as
Mitsuba's ``normalmap`` does, with the normal in world space — and reads α of
(4) through the texture :class:`SeaRoughness` and the foam of (6) through
:class:`SeaFoam` (:class:`LaceFoam` for foam given per vertex, the coast's).
The plugins are instantiated here and handed to the scene as objects (they hold
the shared :class:`SeaShading`), not looked up by name. Hits on the body's skirt
and bottom (geometric normal not upward) keep the vertex shading.

7. **A body that is not the sea everywhere** (the coast inside the open sea,
   :class:`~oceanrender.surface.frame.JoinShading`) keeps its own vertex normals
   and takes from the fields the detail its mesh lacks, scaled as it scales the
   sea's short waves: slope s = s_body + τ_s (s_fields − s_sea), vector area
   (−s, 1) det(I + τ_s (J − I)), foam A·B_grid + C (two per-vertex attributes,
   :data:`SEA_NORMAL_ATTRIBUTE` and :data:`JOIN_ATTRIBUTE`). Where τ_s = 1 and the
   body is the sea this is the sea's own shading exactly. α(Δ) stays the sea's: the
   waves below the pixel are centimetre wind ripples, deep-water waves (kd ≫ 1) on
   any water deeper than a few centimetres, which the depth limit τ_s (made for the
   metre-scale short waves) does not reach.

References
----------
.. [1] J. Tessendorf, "Simulating ocean water," SIGGRAPH 2001 course notes
   (the normal of the choppy surface).
.. [2] E. Bruneton, F. Neyret and N. Holzschuch, "Real-time realistic ocean
   lighting using seamless transitions from geometry to BRDF," Computer
   Graphics Forum 29(2), 487–496, 2010 (the slope budget).
.. [3] L. Williams, "Pyramidal parametrics," SIGGRAPH 1983 (level from footprint).
.. [4] Mitsuba 3.9.1 sources, ``src/bsdfs/normalmap.cpp`` (the perturbed shading frame).
.. [5] E. Heitz, "Understanding the masking-shadowing function in microfacet-based
   BRDFs," Journal of Computer Graphics Techniques 3(2), 48–107, 2014 (Eq. 2: the
   projected area of the microsurface equals the macrosurface's).
.. [6] K. Perlin, "An image synthesizer," SIGGRAPH 1985 (the lace's turbulence).
.. [7] T. Kaneko, T. Takahei, M. Inami, N. Kawakami, Y. Yanagida, T. Maeda and S. Tachi,
   "Detailed shape representation with parallax mapping," ICAT 2001 (parallax mapping).
.. [8] F. Policarpo, M. M. Oliveira and J. L. D. Comba, "Real-time relief mapping on
   arbitrary polygonal surfaces," I3D 2005 (the ray's intersection with a height field).
"""

from __future__ import annotations

import math

import numpy as np

from .buffers import jit_floats, jit_uints

__all__ = ["SHADING_SPACING_PER_FOOTPRINT", "MIN_COSINE", "SEA_NORMAL_ATTRIBUTE", "SEA_POSITION_ATTRIBUTE",
           "JOIN_ATTRIBUTE", "pixel_angle", "SeaShading", "sea_surface", "sea_roughness", "sea_foam", "lace_foam",
           "lace_weight"]

#: Shading spacing Δ per footprint w [-]: waves fade out around λ = 4Δ = 2w, the pixel's Nyquist wavelength.
SHADING_SPACING_PER_FOOTPRINT = 0.5

#: Exponent e of the footprint's elongation 1/|cos θ|^e [-]: 0, the footprint is the pixel's width across the
#: view (its minor axis); ½, the side of a square of the pixel's elliptical area on the surface.
ELONGATION = 0.5

#: Smallest |cos θ| the footprint's elongation uses [-]: 1/√0.02 ≈ 7 at grazing angles (θ > 88.9°).
MIN_COSINE = 0.02

#: Smallest det J the normal uses [-]: a folded crest (J ≤ 0) keeps a steep normal, not an inverted one.
MIN_JACOBIAN = 0.05

#: Width ε of the lace's edge, in the tile's uniform value [-]: foam fades in over B ∈ (L − ε/2, L + ε/2).
LACE_EDGE = 0.1

#: Largest visible-area weight of a hit (:meth:`SeaShading.shading_frame`) [-]: the ratio exceeds it only
#: where the ray grazes the mesh's triangle (|ω_i·N_g| → 0), a vanishing share of the pixel.
MAX_AREA_WEIGHT = 8.0

#: Geometric normals with n_z below this are the body's skirt and bottom: vertex shading there [-].
TOP_NORMAL_Z = 0.1

#: Mesh attribute of a joined body (:class:`~oceanrender.surface.frame.JoinShading`): the sea's own unit
#: vertex normals.
SEA_NORMAL_ATTRIBUTE = "vertex_sea_normal"

#: Mesh attribute of a joined body: the sea's own vertex positions [m] (:class:`~oceanrender.surface.frame.JoinShading`).
SEA_POSITION_ATTRIBUTE = "vertex_sea_position"

#: Mesh attribute of a joined body: (τ_s, A, C) per vertex [-] (:class:`~oceanrender.surface.frame.JoinShading`).
JOIN_ATTRIBUTE = "vertex_join"

#: Channels of :data:`~oceanrender.surface.frame.SHADING_CHANNELS` for the normal: s_x, s_y, J_xx − 1, J_yy − 1, J_xy.
NORMAL_CHANNELS = (3, 4, 5, 6, 7)

#: Channels for the surface's position: η, D_x, D_y [m].
POSITION_CHANNELS = (0, 1, 2)

#: Every channel: the surface's position and normal.
ALL_CHANNELS = POSITION_CHANNELS + NORMAL_CHANNELS

#: Newton steps of the parallax [-].
PARALLAX_ITERATIONS = 2

#: Largest parallax step, in shading spacings Δ [-].
MAX_PARALLAX_STEPS = 16.0

#: Smallest n_z of a unit normal whose slope (−n_x/n_z, −n_y/n_z) a joined body uses [-] (slopes ≤ 100).
MIN_NORMAL_Z = 0.01


def pixel_angle(fov_deg: float, width: int) -> float:
    """Angle subtended by one pixel at the image centre [rad]: 2 tan(fov/2) / width (fov horizontal)."""
    return 2.0 * math.tan(math.radians(float(fov_deg)) / 2.0) / int(width)


def level_layout(cascades) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per-level (offset [nodes], resolution, spacing [m]) of :class:`ShadingFields` cascades (:func:`level_tables`).

    Level j of cascade c is entry ``c·M + j`` (M the largest level count), its first node at
    ``offsets``; entries of empty levels have resolution 0 (their fields are zero).
    """
    width = max(c.level_count for c in cascades)
    offsets = np.zeros(len(cascades) * width, np.uint32)
    sizes = np.zeros(len(cascades) * width, np.uint32)
    spacings = np.ones(len(cascades) * width, np.float32)
    start = 0
    for c, cascade in enumerate(cascades):
        for j, level in enumerate(cascade.levels):
            n = level.shape[0]
            offsets[c * width + j], sizes[c * width + j] = start, n
            spacings[c * width + j] = cascade.patch_size / n
            start += n * n
    if start * len(NORMAL_CHANNELS) >= 2**32:
        raise ValueError("the shading fields exceed 2³² values")
    return offsets, sizes, spacings


def level_tables(cascades) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Flat field buffers and per-level (offset, resolution, spacing) of :class:`ShadingFields` cascades.

    Returns (positions, normals, offsets, sizes, spacings): the levels' channels
    :data:`POSITION_CHANNELS` (η, D_x, D_y: 3 a node) and :data:`NORMAL_CHANNELS` (5 a node), node
    after node, in two buffers: the many hits that need only the normal read 20 bytes a node.
    The tables are :func:`level_layout`'s.
    """
    offsets, sizes, spacings = level_layout(cascades)
    levels = [level.reshape(level.shape[0] ** 2, -1) for cascade in cascades for level in cascade.levels]
    start = sum(len(level) for level in levels)
    positions = np.empty((start, len(POSITION_CHANNELS)), np.float32)
    normals = np.empty((start, len(NORMAL_CHANNELS)), np.float32)
    row = 0
    for level in levels:
        positions[row: row + len(level)] = level[:, POSITION_CHANNELS[0]: POSITION_CHANNELS[-1] + 1]
        normals[row: row + len(level)] = level[:, NORMAL_CHANNELS[0]: NORMAL_CHANNELS[-1] + 1]
        row += len(level)
    return positions.reshape(-1), normals.reshape(-1), offsets, sizes, spacings


def lace_weight(fresh, x, y, lace, n: int, size, active=True):
    """Foam weight [-] of fresh-foam coverage B = ``fresh`` drawn as lace at (x, y) [m]:
    clip((B − L)/ε + ½, 0, 1), L the periodic lace tile (n × n texels over ``size`` m, uniform on [0, 1),
    texel centres at (i + ½) size/n) bilinearly at (x, y), ε = :data:`LACE_EDGE`."""
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    u = x * (n / size) - 0.5
    v = y * (n / size) - 0.5
    u = u - n * dr.floor(u / n)
    v = v - n * dr.floor(v / n)
    li, lj = dr.floor(u), dr.floor(v)
    fu, fv = u - li, v - lj
    li0 = dr.minimum(mi.UInt32(li), n - 1)
    lj0 = dr.minimum(mi.UInt32(lj), n - 1)
    li1 = dr.select(li0 + 1 >= n, 0, li0 + 1)
    lj1 = dr.select(lj0 + 1 >= n, 0, lj0 + 1)

    def texel(jj, ii):
        return dr.gather(mi.Float, lace, jj * n + ii, active)

    tile = dr.lerp(dr.lerp(texel(lj0, li0), texel(lj0, li1), fu), dr.lerp(texel(lj1, li0), texel(lj1, li1), fu), fv)
    return dr.clip((fresh - tile) / LACE_EDGE + 0.5, 0.0, 1.0)


class SeaShading:
    """The sea's shading fields on the device and the camera's footprint model, shared by the water's plugins.

    Build it with the first frame's fields (their layout — cascades, level sizes — is then
    fixed); :meth:`update` replaces the values per frame and :meth:`set_camera` the
    footprint's origin, both without recompiling (opaque kernel parameters).
    """

    def __init__(self, fields, camera_position, pixel_angle_rad: float):
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.layout = tuple((c.patch_size, c.band_top, tuple(level.shape[0] for level in c.levels))
                            for c in fields.cascades)
        self.width = max(c.level_count for c in fields.cascades)
        self.band_tops = [c.band_top for c in fields.cascades]
        self.counts = [c.level_count for c in fields.cascades]
        offsets, sizes, spacings = level_layout(fields.cascades)
        #: the first node of each level [nodes]
        self.offsets, self.sizes, self.spacings = jit_uints(offsets), jit_uints(sizes), jit_floats(spacings)
        self.log_spacing_0 = float(np.log(fields.spacing[0]))
        self.log_spacing_step = float(np.log(fields.spacing[1] / fields.spacing[0]))
        self.table_size = int(fields.spacing.size)
        #: whether hits combine the body's own normals with the fields (:class:`JoinShading`)
        self.join = fields.join is not None
        self.camera = mi.Point3f(0.0, 0.0, 0.0)
        self.pixel_angle = mi.Float(float(pixel_angle_rad))
        dr.make_opaque(self.pixel_angle)
        self.update(fields)
        self.set_camera(camera_position)

    def update(self, fields) -> None:
        """Load a frame's :class:`~oceanrender.surface.frame.ShadingFields` (same layout as the first)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        layout = tuple((c.patch_size, c.band_top, tuple(level.shape[0] for level in c.levels))
                       for c in fields.cascades)
        if layout != self.layout:
            raise ValueError("a frame's shading fields must keep the first frame's cascades and levels")
        if (fields.join is not None) != self.join:
            raise ValueError("a frame's shading fields must keep the first frame's join (or its absence)")
        positions, normals = level_tables(fields.cascades)[:2]
        spacing = np.asarray(fields.spacing, float)
        if not np.allclose(np.diff(np.log(spacing)), self.log_spacing_step) or spacing.size != self.table_size:
            raise ValueError("the α table must keep the first frame's log-spaced shading spacings")
        self.position_values, self.normal_values = jit_floats(positions), jit_floats(normals)
        dr.make_opaque(self.position_values, self.normal_values)
        self.alpha = jit_floats(fields.alpha)
        self.origin = mi.Point2f(float(fields.origin[0]), float(fields.origin[1]))
        dr.make_opaque(self.alpha, self.origin)
        foam = fields.foam
        if (foam is None) != (getattr(self, "foam_layout", None) is None) and hasattr(self, "foam_layout"):
            raise ValueError("a frame's shading fields must keep the first frame's foam grid")
        self.foam_layout = None if foam is None else (foam.rings, foam.segments, foam.lace.shape)
        if foam is not None:
            self.foam_rings, self.foam_segments = int(foam.rings), int(foam.segments)
            self.lace_n = int(foam.lace.shape[0])
            self.foam_fresh = jit_floats(foam.fresh)
            self.lace = jit_floats(foam.lace)
            # (centre x, centre y, inner radius, ln ratio per ring, outer radius, outside B, lace size)
            self.foam_params = [mi.Float(float(v)) for v in (
                foam.center[0], foam.center[1], foam.inner_radius,
                math.log(foam.outer_radius / foam.inner_radius) / (foam.rings - 1), foam.outer_radius,
                foam.outside, foam.lace_size)]
            dr.make_opaque(self.foam_fresh, self.lace, *self.foam_params)

    def set_pixel_angle(self, value: float) -> None:
        """The angle of a pixel [rad] (:func:`pixel_angle`), after a change of field of view."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.pixel_angle = mi.Float(float(value))
        dr.make_opaque(self.pixel_angle)

    def set_camera(self, position) -> None:
        """Where the footprints are measured from: the camera's pinhole [m]."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        self.camera = mi.Point3f(*(float(v) for v in position))
        dr.make_opaque(self.camera)

    # ---- per-hit evaluation (drjit, traced into the render kernel)

    def on_top(self, si):
        """Hits on the sea's upper surface (geometric normal upward): the ones shaded from the fields."""
        return si.n.z > TOP_NORMAL_Z

    def spacing(self, si):
        """Shading spacing Δ [m] of a hit: w/2, w = d θ_px / √max(|cos θ|, :data:`MIN_COSINE`)."""
        import drjit as dr  # noqa: PLC0415

        to_camera = self.camera - si.p
        distance = dr.norm(to_camera)
        footprint = distance * self.pixel_angle
        if ELONGATION > 0:
            cosine = dr.maximum(dr.abs(dr.dot(si.to_world(si.wi), si.n)), MIN_COSINE)
            footprint = footprint * dr.power(cosine, -ELONGATION)
        return SHADING_SPACING_PER_FOOTPRINT * dr.maximum(footprint, 1e-6)

    def alpha_at(self, spacing):
        """Beckmann α(Δ) [-], linear in log Δ between the table's entries (clamped at its ends)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        u = (dr.log(spacing) - self.log_spacing_0) / self.log_spacing_step
        u = dr.clip(u, 0.0, self.table_size - 1.000001)
        i = mi.UInt32(dr.floor(u))
        f = u - dr.floor(u)
        a0 = dr.gather(mi.Float, self.alpha, i)
        a1 = dr.gather(mi.Float, self.alpha, i + 1)
        return dr.lerp(a0, a1, f)

    def _level(self, entry, x, y, weight, active, channels):
        """weight × the fields ``channels`` (indices of :data:`~oceanrender.surface.frame.SHADING_CHANNELS`) of
        level table entry ``entry``, bilinearly at rest (x, y), periodic."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        n = dr.gather(mi.UInt32, self.sizes, entry, active)
        active = active & (n > 0) & (weight > 0)
        offset = dr.gather(mi.UInt32, self.offsets, entry, active)
        h = dr.gather(mi.Float, self.spacings, entry, active)
        n_f = mi.Float(dr.maximum(n, 1))
        patch = n_f * h
        u = (x + 0.5 * patch) / h
        v = (y + 0.5 * patch) / h
        u = u - n_f * dr.floor(u / n_f)  # periodic: u in [0, N)
        v = v - n_f * dr.floor(v / n_f)
        i0, j0 = dr.floor(u), dr.floor(v)
        fx, fy = u - i0, v - j0
        i0 = dr.minimum(mi.UInt32(i0), dr.maximum(n, 1) - 1)
        j0 = dr.minimum(mi.UInt32(j0), dr.maximum(n, 1) - 1)
        i1 = dr.select(i0 + 1 >= n, 0, i0 + 1)
        j1 = dr.select(j0 + 1 >= n, 0, j0 + 1)
        # each channel from its buffer: positions (3 a node) or normals (5 a node)
        reads = [(self.position_values, len(POSITION_CHANNELS), channel) if channel in POSITION_CHANNELS else
                 (self.normal_values, len(NORMAL_CHANNELS), channel - len(POSITION_CHANNELS)) for channel in channels]
        out = [mi.Float(0.0) for _ in channels]
        for (jj, ii, w) in ((j0, i0, (1 - fx) * (1 - fy)), (j0, i1, fx * (1 - fy)),
                            (j1, i0, (1 - fx) * fy), (j1, i1, fx * fy)):
            node = offset + jj * n + ii
            for k, (source, stride, channel) in enumerate(reads):
                out[k] += w * dr.gather(mi.Float, source, node * stride + channel, active)
        return [dr.select(active, weight * o, 0.0) for o in out]

    def join_at(self, si, active):
        """(τ_s, A, C) [-] of a joined body at a hit (:class:`~oceanrender.surface.frame.JoinShading`)."""
        value = si.shape.eval_attribute_3(JOIN_ATTRIBUTE, si, active)
        return value[0], value[1], value[2]

    def fields_at(self, rest, spacing, active, channels=NORMAL_CHANNELS):
        """The fields ``channels`` of the waves Δ resolves at rest position ``rest`` [m] (by default
        (s_x, s_y, J_xx − 1, J_yy − 1, J_xy) [-]; :data:`POSITION_CHANNELS`: (η, D_x, D_y) [m])."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        total = [mi.Float(0.0) for _ in channels]
        for c, (top, count) in enumerate(zip(self.band_tops, self.counts)):
            k_f = math.pi / (2.0 * spacing)
            s = dr.clip(dr.log2(top / k_f), 0.0, count - 1.0)
            low = dr.floor(s)
            frac = s - low
            level = mi.UInt32(low)
            entry = mi.UInt32(c * self.width) + level
            for step, w in ((0, 1.0 - frac), (1, frac)):
                # the last level is empty (zero): only levels below it, with weight, are read; and only in
                # packets of lanes where some lane reads it (a symbolic branch: far hits skip the fine
                # cascades, near ones the second level of the coarse cascades)
                on = mi.Bool(active) & (level + step < count - 1) & (w > 0)
                part = dr.if_stmt(
                    (entry + step, rest.x, rest.y, w, on), on,
                    lambda e, x, y, w, on: self._level(e, x, y, w, on, channels),
                    lambda e, x, y, w, on: [mi.Float(0.0) for _ in channels])
                total = [a + b for a, b in zip(total, part)]
        return total

    def parallax(self, si, rest, spacing, active, tau=None):
        """The rest position [m] where the hit's ray meets the fields' surface, from the mesh's hit at
        rest position ``rest`` [m] (parallax mapping by Newton's method).

        Near the hit p the fine surface is Q(x) = p + (1 − τ) T (x − x₀) + τ (P(x) − P_sea(x₀)),
        P(x) = (x + D_x, y + D_y, η) the fields at Δ, T = (∂p/∂u, ∂p/∂v) the triangle's tangents
        (the rest coordinates are u, v) and, for the open sea, τ = 1 and P_sea(x₀) = p: the fields'
        own surface. (A joined body, :class:`~oceanrender.surface.frame.JoinShading`, adds τ_s
        times the fields' offset from the sea's own mesh to its own triangle.) The ray is
        p + s ω. :data:`PARALLAX_ITERATIONS` Newton steps on F(x, s) = Q(x) − p − s ω = 0, with
        the Jacobian [∂Q/∂x ∂Q/∂y −ω] solved by Cramer's rule, each from one lookup of all eight
        channels (position and its derivatives: Tessendorf 2001 for ∂P/∂x₀), land x where the ray
        meets the fine surface, to second order per step (Kaneko et al. 2001 take one step along
        a fixed tangent plane; Policarpo, Oliveira & Comba 2005 search along the ray). The whole
        move is capped at :data:`MAX_PARALLAX_STEPS` shading spacings (grazing rays). ``tau``: τ_s of
        a joined body at the hit (:meth:`join_at`), None for the sea itself.
        """
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        d = -si.to_world(si.wi)  # the ray's direction
        if tau is not None:  # the body's own surface plus τ_s × the fields' offset from the sea's own mesh
            sea = si.shape.eval_attribute_3(SEA_POSITION_ATTRIBUTE, si, active)
            sea = mi.Vector3f(sea[0], sea[1], sea[2])
        else:
            tau, sea = mi.Float(1.0), mi.Vector3f(si.p)
        x, y, s = mi.Float(rest.x), mi.Float(rest.y), mi.Float(0.0)
        for _ in range(PARALLAX_ITERATIONS):
            eta, dx, dy, sx, sy, xx, yy, xy = self.fields_at(mi.Point2f(x, y), spacing, active, ALL_CHANNELS)
            # Q(x) = p + (1 − τ) T (x − x₀) + τ (P(x) − P_sea(x₀)), T = (∂p/∂u, ∂p/∂v) the triangle's
            # tangents, P = (x + D_x, y + D_y, η) the fields' surface: the fine surface near the hit
            # (the fields' own where τ = 1 and the body is the sea, P_sea(x₀) = p).
            a = (1.0 - tau) * si.dp_du + tau * mi.Vector3f(1.0 + xx, xy, sx)  # ∂Q/∂x
            b = (1.0 - tau) * si.dp_dv + tau * mi.Vector3f(xy, 1.0 + yy, sy)  # ∂Q/∂y
            offset = (1.0 - tau) * (si.dp_du * (x - rest.x) + si.dp_dv * (y - rest.y)) \
                + tau * (mi.Vector3f(x + dx, y + dy, eta) - sea)
            f = offset - s * d  # Q(x) − (p + s d)
            # Newton's step [a b −d] (δx, δy, δs) = −f, by Cramer's rule
            cross = dr.cross(b, -d)
            det = dr.dot(a, cross)
            ok = dr.abs(det) > 1e-12
            det = dr.select(ok, det, 1.0)
            du = dr.dot(-f, cross) / det
            dv = dr.dot(a, dr.cross(-f, -d)) / det
            ds = dr.dot(a, dr.cross(b, -f)) / det
            x = dr.select(ok, x + du, x)
            y = dr.select(ok, y + dv, y)
            s = dr.select(ok, s + ds, s)
        limit = MAX_PARALLAX_STEPS * spacing  # grazing rays: the move capped
        mx, my = x - rest.x, y - rest.y
        scale = dr.minimum(1.0, limit / dr.maximum(dr.sqrt(mx * mx + my * my), 1e-12))
        return mi.Point2f(rest.x + scale * mx, rest.y + scale * my)

    def foam_at(self, si, active=True):
        """Fresh-foam weight [-] of a hit: B of the foam grid at its rest position, drawn as lace.

        B bilinear in (ring, angle) on the polar grid (between the centre and the first
        ring linear in r; beyond the last ring the far mean), as
        :func:`oceanrender.surface.open_sea.polar_grid_sample`; then the weight
        clip((B − L)/ε + ½, 0, 1) with L the lace tile (uniform on [0, 1)) at the rest
        position and ε = :data:`LACE_EDGE`: foam covers the fraction B of the surface on
        average, a full sheet where B → 1 and a lace of thin lines where B is small.
        """
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        cx, cy, r_in, log_q, r_out, outside, lace_size = self.foam_params
        rest = mi.Point2f(si.uv.x, si.uv.y)  # relative to the origin, like the grid's centre
        dx, dy = rest.x - cx, rest.y - cy
        r = dr.sqrt(dx * dx + dy * dy)
        rings, segments = self.foam_rings, self.foam_segments
        j = dr.log(dr.maximum(r, 1e-9) / r_in) / log_q
        a = dr.atan2(dy, dx) * (segments / (2 * math.pi))
        a = a - segments * dr.floor(a / segments)
        i0f = dr.floor(a)
        fa = a - i0f
        i0 = dr.minimum(mi.UInt32(i0f), segments - 1)
        i1 = dr.select(i0 + 1 >= segments, 0, i0 + 1)
        j0f = dr.clip(dr.floor(j), 0.0, rings - 1.0)
        fj = dr.clip(j - j0f, 0.0, 1.0)
        j0 = mi.UInt32(j0f)
        j1 = dr.minimum(j0 + 1, rings - 1)

        def value(jj, ii):
            return dr.gather(mi.Float, self.foam_fresh, 1 + jj * segments + ii, active)

        inner = dr.lerp(value(j0, i0), value(j0, i1), fa)
        outer = dr.lerp(value(j1, i0), value(j1, i1), fa)
        fresh = dr.lerp(inner, outer, fj)
        centre = dr.gather(mi.Float, self.foam_fresh, mi.UInt32(0), active)
        fresh = dr.select(r < r_in, dr.lerp(centre, fresh, r / r_in), fresh)
        fresh = dr.select(r > r_out * (1 + 1e-6), outside, fresh)
        if self.join:  # the sea's whitecaps where the body carries the sea, plus its own white water
            _, scale, offset = self.join_at(si, active & self.on_top(si))
            fresh = scale * fresh + offset
        weight = lace_weight(fresh, rest.x + self.origin.x, rest.y + self.origin.y, self.lace, self.lace_n, lace_size,
                             active)
        return dr.select(self.on_top(si), weight, 0.0)

    def _area_at(self, si, active, parallax=False, spacing=None):
        """(N of :meth:`area_normal` at the hit's footprint, shading spacing Δ [m], on_top) of a hit
        (``spacing``: Δ [m] given instead of the camera's footprint, e.g. a light ray's spacing)."""
        import mitsuba as mi  # noqa: PLC0415

        top = mi.Bool(active) & self.on_top(si)
        spacing = self.spacing(si) if spacing is None else mi.Float(spacing)
        rest = mi.Point2f(si.uv.x, si.uv.y) + self.origin
        tau = self.join_at(si, top)[0] if self.join else None  # one attribute read for the whole hit
        if parallax:
            rest = self.parallax(si, rest, spacing, top, tau)
        fields = self.fields_at(rest, spacing, top)
        if self.join:
            return self._joined_area(si, fields, top, tau), spacing, top
        return self.area_normal(*fields), spacing, top

    def _joined_area(self, si, fields, top, tau):
        """The vector area per unit rest area [-] of a joined body's hit (:class:`JoinShading`).

        Slope s = s_body + τ_s (s_fields − s_sea) (s of the body's interpolated vertex normal, of
        the fields' normal at the footprint, of the sea's own interpolated vertex normal), and
        the area element det(I + τ_s (J − I)) of the sea's horizontal displacement scaled as the
        body scales its short waves: (−s_x, −s_y, 1) times it (``tau``: τ_s at the hit). With τ_s = 1
        and s_body = s_sea it is :meth:`area_normal` of the fields exactly.
        """
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        sea = si.shape.eval_attribute_3(SEA_NORMAL_ATTRIBUTE, si, top)
        sea = mi.Vector3f(sea[0], sea[1], sea[2])

        def slope(n):
            z = dr.maximum(n.z, MIN_NORMAL_Z * dr.norm(n))
            return -n.x / z, -n.y / z

        fx, fy = slope(self.area_normal(*fields))
        bx, by = slope(si.sh_frame.n)
        vx, vy = slope(sea)
        sx, sy = bx + tau * (fx - vx), by + tau * (fy - vy)
        _, _, xx, yy, xy = fields
        det = dr.maximum((1.0 + tau * xx) * (1.0 + tau * yy) - tau * tau * xy * xy, MIN_JACOBIAN)
        return mi.Vector3f(-sx * det, -sy * det, det)

    def normal(self, si, active=True):
        """(unit normal [world], Beckmann α [-], on_top) at a hit from the fields at its footprint."""
        import drjit as dr  # noqa: PLC0415

        area, spacing, top = self._area_at(si, active)
        return dr.normalize(area), self.alpha_at(spacing), top

    @staticmethod
    def area_normal(sx, sy, xx, yy, xy):
        """∂p/∂x₀ × ∂p/∂y₀ of p = (x₀ + λD_x, y₀ + λD_y, η): the surface's vector area per unit rest area [-]."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        jxx, jyy = 1.0 + xx, 1.0 + yy
        det = dr.maximum(jxx * jyy - xy * xy, MIN_JACOBIAN)
        return mi.Vector3f(xy * sy - jyy * sx, xy * sx - jxx * sy, det)

    def shading_frame(self, si, active=True, parallax=False, spacing=None):
        """(unit normal [world], visible-area weight [-], on_top) of a hit: :meth:`normal` and the ratio of
        the fields' projected area to the mesh's (``spacing``: Δ [m] instead of the camera's footprint).

        A ray meets the mesh with a density per unit rest area ∝ ω_i·N_g (N_g = ∂p/∂u × ∂p/∂v of
        the triangle, the texture coordinates being rest positions), while the surface the fields
        describe shows each rest element with its own projected area max(0, ω_i·N) (N of
        :meth:`area_normal`; facets turned away are hidden). The weight
        w = max(0, ω_i·N) / ω_i·N_g (signs taken on the side the ray comes from) turns the
        mesh's sampling into the fields' visible normals: its mean over a pixel is 1 where the two
        surfaces share their long waves (same vector area, Heitz 2014, Eq. 2), facets facing the ray
        count more and hidden ones not at all. Capped at :data:`MAX_AREA_WEIGHT`.

        With ``parallax`` (the camera's hit: :meth:`parallax`) the weight is 1: the hit is on the
        fine surface where its ray meets it. The area weight varies at the pixel's own scale and so
        paints foreshortening as brightness (docs/pixel_detail.md: 1.5–3.8× brute force's luminance
        power above 0.3 cycles px⁻¹ on camera hits), and without masking it brightens grazing views
        (+62 % just below the default frame's horizon); at the camera's hit parallax does both as shape.
        """
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        area, _, top = self._area_at(si, active, parallax, spacing)
        wi = si.to_world(si.wi)
        mesh = dr.dot(wi, dr.cross(si.dp_du, si.dp_dv))
        side = dr.select(mesh >= 0, 1.0, -1.0)
        if parallax:
            # The hit is on the fine surface, sampled as the ray meets it: weight 1. Where the Newton
            # steps end on a facet turned away from the ray (it crossed a crest it grazes: 23 % of the
            # hits just below the horizon of the default frame, < 1 % in the lower half of the frame), the ray
            # meets that crest's near side, which the fine surface does not resolve: the mesh's normal is taken.
            hidden = top & (dr.dot(wi, area) * side <= 0)
            area = dr.select(hidden, mi.Vector3f(si.sh_frame.n), area)
            weight = mi.Float(1.0)
        else:
            weight = dr.maximum(dr.dot(wi, area) * side, 0.0) / dr.maximum(dr.abs(mesh), 1e-12)
            weight = dr.select(top, dr.minimum(weight, MAX_AREA_WEIGHT), 1.0)
        return dr.normalize(area), weight, top


_CLASSES: dict[tuple[str, str], type] = {}


def _classes() -> tuple[type, type, type, type]:
    """(:class:`SeaSurfaceBSDF`, :class:`SeaRoughness`, :class:`SeaFoam`, :class:`LaceFoam`) of the active variant."""
    import mitsuba as mi  # noqa: PLC0415

    key = (mi.variant(), "classes")
    if key not in _CLASSES:
        _CLASSES[key] = _define_classes()
    return _CLASSES[key]


def _define_classes() -> tuple[type, type, type, type]:
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    class _ScalarTexture(mi.Texture):
        """A one-channel texture defined by ``compute`` (the spectrum is that value at every λ).

        :class:`SeaSurfaceBSDF` evaluates it once per hit and sets :attr:`current` while its
        nested BSDF is traced at that hit, so the nested BSDF's several reads of it (each of
        ``sample``, ``eval``, ``pdf``) are that one value, not each its own evaluation.
        """

        #: The value at the hit whose BSDF is being traced, or None (then :meth:`compute`).
        current = None

        def eval_1(self, si, active=True):
            return self.compute(si, active) if self.current is None else self.current

        def eval(self, si, active=True):
            return mi.UnpolarizedSpectrum(self.eval_1(si, active))

        def to_string(self):
            return f"{type(self).__name__}[]"

    class SeaRoughness(_ScalarTexture):
        """Beckmann α [-] of a water hit: the slopes its footprint does not resolve (:meth:`SeaShading.alpha_at`).

        Off the upper surface (skirt, bottom) the texture ``fallback`` (the vertex α or a constant).
        """

        def attach(self, shading: SeaShading, fallback) -> "SeaRoughness":
            self.shading, self.fallback = shading, fallback
            return self

        def compute(self, si, active=True):
            alpha = self.shading.alpha_at(self.shading.spacing(si))
            return dr.select(self.shading.on_top(si), alpha, self.fallback.eval_1(si, active))

        def mean(self):
            return float(np.mean(np.asarray(self.shading.alpha)))

    class SeaFoam(_ScalarTexture):
        """Fresh-foam weight [-] of a water hit from the foam's field-resolution grid (:meth:`SeaShading.foam_at`)."""

        def attach(self, shading: SeaShading) -> "SeaFoam":
            self.shading = shading
            return self

        def compute(self, si, active=True):
            return self.shading.foam_at(si, active)

        def mean(self):
            return float(np.mean(np.asarray(self.shading.foam_fresh)))

    class LaceFoam(_ScalarTexture):
        """Fresh-foam weight [-] of a mesh whose foam is per vertex (the coast's cells, or no foam grid):
        the interpolated B drawn as lace (:func:`lace_weight`) at the hit's horizontal world position."""

        def attach(self, nested, lace, size: float) -> "LaceFoam":
            self.nested, self.n, self.size = nested, int(lace.shape[0]), float(size)
            self.lace = jit_floats(lace)
            dr.make_opaque(self.lace)
            return self

        def compute(self, si, active=True):
            return lace_weight(self.nested.eval_1(si, active), si.p.x, si.p.y, self.lace, self.n, self.size, active)

        def mean(self):
            return float(self.nested.mean())

    class SeaSurfaceBSDF(mi.BSDF):
        """The water surface's BSDF in the shading frame of the sea's fields at each hit.

        Wraps ``nested`` (the surface's ``roughdielectric``, or its ``blendbsdf`` with foam)
        as Mitsuba's ``normalmap`` does, with the normal of :meth:`SeaShading.shading_frame` in
        world space, and scales its values (not its densities) by that method's visible-area
        weight, so the normals a pixel sees are the fields' visible ones. A sampled or
        evaluated direction must lie on the side of the *geometric* surface that its lobe
        implies (reflection: the side of ω_i; transmission: the other), else the value is 0:
        light cannot leak through the mesh (a real surface would send such a ray into the
        next wave; docs/pixel_detail.md measures what is lost).
        """

        #: The split integrator treats it as the dielectric it wraps (:mod:`.integrator`).
        wraps_dielectric = True

        def __init__(self, props):
            super().__init__(props)
            self.nested = None
            self.shading = None

        def attach(self, nested, shading: SeaShading, textures=()) -> "SeaSurfaceBSDF":
            """``textures``: the :class:`_ScalarTexture` objects inside ``nested``, evaluated once per hit."""
            self.nested, self.shading, self.textures = nested, shading, tuple(textures)
            self.m_flags = nested.flags()
            self.m_components = [nested.flags(i) for i in range(nested.component_count())]
            return self

        def _perturbed(self, si, active, parallax=False, branch=False):
            """(the hit with the fields' shading frame, visible-area weight, the textures' values) at ``si``.

            ``branch``: evaluated in a symbolic branch, only in packets where some lane is
            ``active`` (a path's hits, most of which are not on the water)."""

            def evaluate(si, active):
                n, weight, _ = self.shading.shading_frame(si, active, parallax)
                return n, weight, [texture.compute(si, active) for texture in self.textures]

            active = mi.Bool(active)
            if branch:
                n, weight, values = dr.if_stmt(
                    (si, active), active, evaluate,
                    lambda si, active: (mi.Vector3f(0.0, 0.0, 1.0), mi.Float(1.0),
                                        [mi.Float(0.0) for _ in self.textures]))
            else:
                n, weight, values = evaluate(si, active)
            top = active & self.shading.on_top(si)
            perturbed = mi.SurfaceInteraction3f(si)
            frame = mi.Frame3f(n)
            perturbed.sh_frame = mi.Frame3f(dr.select(top, frame.s, si.sh_frame.s),
                                            dr.select(top, frame.t, si.sh_frame.t),
                                            dr.select(top, frame.n, si.sh_frame.n))
            perturbed.wi = perturbed.to_local(si.to_world(si.wi))
            return perturbed, weight, values

        def _traced(self, values, call):
            """``call()`` (a method of the nested BSDF) with the textures' values at the hit set."""
            for texture, value in zip(self.textures, values):
                texture.current = value
            try:
                return call()
            finally:
                for texture in self.textures:
                    texture.current = None

        def prepared(self, si, active=True, parallax=True, branch=False):
            """This BSDF at hit ``si`` with its shading frame evaluated once: an object with the
            methods ``sample``, ``eval``, ``pdf``, ``eval_pdf`` of a BSDF at that hit (the
            ``split`` integrator's camera hit calls four of them on the same hit, with ``parallax``;
            a path's later hits on the surface three, without: :func:`~.underwater.trace_path`)."""
            return _Prepared(self, si, *self._perturbed(si, active, parallax, branch))

        def _sample(self, ctx, si, perturbed, area, values, sample1, sample2, active):
            bs, weight = self._traced(values, lambda: self.nested.sample(ctx, perturbed, sample1, sample2, active))
            wo_world = perturbed.to_world(bs.wo)
            bs.wo = si.to_local(wo_world)
            return bs, dr.select(self._consistent(si, perturbed, wo_world), weight * area, 0.0)

        def _eval(self, ctx, si, perturbed, area, values, wo, active):
            wo_world = si.to_world(wo)
            value = self._traced(values, lambda: self.nested.eval(ctx, perturbed, perturbed.to_local(wo_world),
                                                                  active))
            return dr.select(self._consistent(si, perturbed, wo_world), value * area, 0.0)

        def _pdf(self, ctx, si, perturbed, values, wo, active):
            wo_world = si.to_world(wo)
            value = self._traced(values, lambda: self.nested.pdf(ctx, perturbed, perturbed.to_local(wo_world), active))
            return dr.select(self._consistent(si, perturbed, wo_world), value, 0.0)

        def _eval_pdf(self, ctx, si, perturbed, area, values, wo, active):
            wo_world = si.to_world(wo)
            value, pdf = self._traced(values, lambda: self.nested.eval_pdf(ctx, perturbed,
                                                                           perturbed.to_local(wo_world), active))
            ok = self._consistent(si, perturbed, wo_world)
            return dr.select(ok, value * area, 0.0), dr.select(ok, pdf, 0.0)

        def sample(self, ctx, si, sample1, sample2, active=True):
            return self._sample(ctx, si, *self._perturbed(si, active), sample1, sample2, active)

        def eval(self, ctx, si, wo, active=True):
            return self._eval(ctx, si, *self._perturbed(si, active), wo, active)

        def pdf(self, ctx, si, wo, active=True):
            perturbed, _, values = self._perturbed(si, active)
            return self._pdf(ctx, si, perturbed, values, wo, active)

        def eval_pdf(self, ctx, si, wo, active=True):
            return self._eval_pdf(ctx, si, *self._perturbed(si, active), wo, active)

        @staticmethod
        def _consistent(si, perturbed, wo_world):
            """Reflection (same side of the shading frame) must also be reflection about the geometric
            surface, and transmission transmission."""
            geometric = dr.dot(si.to_world(si.wi), si.n) * dr.dot(wo_world, si.n)
            shading = mi.Frame3f.cos_theta(perturbed.wi) * dr.dot(wo_world, perturbed.sh_frame.n)
            return geometric * shading > 0

        def eval_diffuse_reflectance(self, si, active=True):
            return self.nested.eval_diffuse_reflectance(si, active)

        def traverse(self, callback):
            pass

        def to_string(self):
            return f"SeaSurfaceBSDF[nested={self.nested}]"

    class _Prepared:
        """:meth:`SeaSurfaceBSDF.prepared`: the BSDF's methods at one hit, its shading frame computed once."""

        def __init__(self, bsdf, si, perturbed, area, values):
            self.bsdf, self.si, self.perturbed, self.area, self.values = bsdf, si, perturbed, area, values

        def flags(self):
            return self.bsdf.flags()

        def sample(self, ctx, si, sample1, sample2, active=True):
            return self.bsdf._sample(ctx, si, self.perturbed, self.area, self.values, sample1, sample2, active)

        def eval(self, ctx, si, wo, active=True):
            return self.bsdf._eval(ctx, si, self.perturbed, self.area, self.values, wo, active)

        def pdf(self, ctx, si, wo, active=True):
            return self.bsdf._pdf(ctx, si, self.perturbed, self.values, wo, active)

        def eval_pdf(self, ctx, si, wo, active=True):
            return self.bsdf._eval_pdf(ctx, si, self.perturbed, self.area, self.values, wo, active)

    return SeaSurfaceBSDF, SeaRoughness, SeaFoam, LaceFoam


def sea_foam(shading: SeaShading):
    """The foam weight texture of the surface's ``blendbsdf``: :class:`SeaFoam`."""
    import mitsuba as mi  # noqa: PLC0415

    return _classes()[2](mi.Properties()).attach(shading)


def lace_foam(nested: dict, lace, size: float):
    """A foam weight texture: ``nested`` (B per vertex, a texture dict) drawn as lace (:class:`LaceFoam`)."""
    import mitsuba as mi  # noqa: PLC0415

    return _classes()[3](mi.Properties()).attach(mi.load_dict(nested), lace, size)


def sea_roughness(shading: SeaShading, fallback: dict):
    """The α texture of the surface BSDF: :class:`SeaRoughness` over ``fallback`` (a texture dict)."""
    import mitsuba as mi  # noqa: PLC0415

    roughness_class = _classes()[1]
    return roughness_class(mi.Properties()).attach(shading, mi.load_dict(fallback))


def _textures_in(tree) -> list:
    """The field-shading textures (:class:`SeaRoughness`, :class:`SeaFoam`, :class:`LaceFoam`) in a BSDF dict."""
    found = []
    for value in tree.values():
        if isinstance(value, dict):
            found += _textures_in(value)
        elif hasattr(value, "compute") and hasattr(value, "current"):
            found.append(value)
    return found


def sea_surface(nested: dict, shading: SeaShading):
    """The water surface's BSDF ``nested`` (a dict, objects allowed inside) shaded from the sea's fields."""
    import mitsuba as mi  # noqa: PLC0415

    surface_class = _classes()[0]
    return surface_class(mi.Properties()).attach(mi.load_dict(nested), shading, _textures_in(nested))
