"""The Mitsuba scene of a sequence: loaded once, geometry updated per frame.

Per frame only the water mesh's vertex positions and normals change, through
``mi.traverse(scene)`` + ``update()``; the scene is never reloaded.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TypeVar

import numpy as np

from ..optics.foam import foam_spectral_factor_Frouin1996
from ..optics.scene_water import water_ior
from ..optics.seafloor import linear_reflectance
from ..optics.water import MediumOptics, WaterIOPs
from ..scene import Scene
from ..scene.motion import CameraPose, SunAngles
from ..surface.frame import FrameGeometry, Terrain
from .buffers import jit_floats, jit_uints
from .environment import sky_emitters
from .objects import object_id, object_mesh, update_object_positions
from .scene import (
    K_M,
    FILM_RANGE_NM,
    ROUGHNESS_ATTRIBUTE,
    SMOOTH_ALPHA,
    apply_camera,
    apply_sun,
    irregular_spectrum,
    meter_reading,
    perspective_sensor,
    sun_direction,
    volumetric_integrator,
    water_medium,
    water_surface_bsdf,
    white_plane_meter,
    xyz_film,
)

T = TypeVar("T")


#: Identifier of the water body in the Mitsuba scene.
WATER_ID = "water"


def film_to_absolute_XYZ(film: np.ndarray) -> np.ndarray:
    """Absolute XYZ [cd m⁻² for Y] from specfilm channels ∫L x̄ dλ etc. [W m⁻² sr⁻¹].

    Y = K_m ∫ L(λ) ȳ(λ) dλ (CIE 015:2018 Eq. 7.1 with K_m = 683 lm W⁻¹).
    """
    return K_M * np.asarray(film, dtype=np.float64)


def in_water_seed(seed: int) -> int:
    """Sampler seed of a two-pass frame's in-water pass: ``seed`` offset by 0x6A09E667, far from the frame seeds (seed + frame)."""
    return (int(seed) + 0x6A09E667) % (1 << 32)


#: Most Monte Carlo samples (pixels × spp) of one ``mi.render`` call: drjit indexes a pass's samples
#: with 32 bits, so a pass beyond 2³² crashes Mitsuba; larger frames render in several passes.
MAX_SAMPLES_PER_PASS = 1 << 30


def sample_passes(pixels: int, spp: int, seed: int, cap: int = MAX_SAMPLES_PER_PASS) -> list[tuple[int, int]]:
    """Split ``spp`` samples per pixel into passes of at most ``cap`` samples: [(spp_i, seed_i), ...].

    The first pass keeps ``seed`` (a frame that fits one pass renders as before);
    pass i > 0 takes seed + i·0x9E3779B9 (mod 2³², the golden-ratio increment),
    far from the per-frame seeds seed + frame. The spp of the passes sum to ``spp``.
    """
    per_pass = max(1, cap // max(1, int(pixels)))
    count = -(-int(spp) // per_pass)
    sizes = [int(spp) // count + (1 if i < int(spp) % count else 0) for i in range(count)]
    return [(size, (int(seed) + i * 0x9E3779B9) % (1 << 32)) for i, size in enumerate(sizes)]


def render_passes(scene, spp: int, seed: int, integrator=None, sensor: int = 0) -> np.ndarray:
    """Mean film of ``spp`` samples per pixel rendered in :func:`sample_passes` passes (H, W, C), by the
    scene's sensor number ``sensor``."""
    import mitsuba as mi  # noqa: PLC0415

    width, height = scene.sensors()[sensor].film().crop_size()
    total = None
    for size, pass_seed in sample_passes(int(width) * int(height), spp, seed):
        film = np.array(mi.render(scene, integrator=integrator, seed=pass_seed, spp=size, sensor=sensor),
                        dtype=np.float64)
        total = film * size if total is None else total + film * size
    return total / int(spp)


def repair_non_finite(image: np.ndarray) -> tuple[np.ndarray, int]:
    """Replace non-finite pixels by the mean of their finite 3×3 neighbours.

    Returns the repaired (H, W, C) image and how many pixels were repaired.
    NOTE: Mitsuba's volpath occasionally returns NaN in a handful of pixels
    for media inside dielectrics (../shared/NOTES.md); a frame is never
    written with NaN in it.
    """
    bad = ~np.all(np.isfinite(image), axis=-1)
    count = int(bad.sum())
    if count == 0:
        return image, 0
    from scipy.ndimage import uniform_filter  # noqa: PLC0415

    good = (~bad).astype(np.float64)
    clean = np.where(bad[..., None], 0.0, image)
    weight = uniform_filter(good, size=3, mode="nearest")
    sums = np.stack([uniform_filter(clean[..., c], size=3, mode="nearest") for c in range(image.shape[-1])], axis=-1)
    fill = np.where(weight[..., None] > 0, sums / np.maximum(weight[..., None], 1e-12), 0.0)
    return np.where(bad[..., None], fill, image), count


#: Name of the per-vertex foam attribute of the water mesh: the fraction of the surface that reflects like
#: fresh foam [-] (``FrameGeometry.foam``; the fresh-foam coverage B of the open sea, the white water of the coast).
FOAM_ATTRIBUTE = "vertex_foam"


def load_water_medium(medium: dict):
    """The water's medium (:func:`~oceanrender.render.scene.water_medium`) as a loaded Mitsuba object,
    to be shared by the water body (its interior) and a camera under the water (its sensor's medium)."""
    import mitsuba as mi  # noqa: PLC0415

    from .phase import register, register_tabulated  # noqa: PLC0415

    register()  # the water's spectral phase functions (water_medium)
    register_tabulated()
    return mi.load_dict(medium)


def join_attributes(geometry: FrameGeometry) -> dict:
    """The per-vertex attributes of a joined body's field shading (:class:`~oceanrender.surface.frame.JoinShading`):
    {name: flat float buffer}, empty for a body that is the sea (:mod:`.sea_shading`)."""
    from .sea_shading import JOIN_ATTRIBUTE, SEA_NORMAL_ATTRIBUTE, SEA_POSITION_ATTRIBUTE  # noqa: PLC0415

    join = None if geometry.shading is None else geometry.shading.join
    if join is None:
        return {}
    factors = np.column_stack([join.short_taper, join.foam_scale, join.foam_offset])
    return {SEA_NORMAL_ATTRIBUTE: jit_floats(join.sea_normals), SEA_POSITION_ATTRIBUTE: jit_floats(join.sea_positions),
            JOIN_ATTRIBUTE: jit_floats(factors)}


def water_mesh(faces: np.ndarray, geometry: FrameGeometry, bsdf: dict, medium=None):
    """The water body as a Mitsuba mesh (id :data:`WATER_ID`) with ``bsdf`` and, if given, an interior medium
    (a dict of :func:`~oceanrender.render.scene.water_medium`, or the object :func:`load_water_medium` made)."""
    import mitsuba as mi  # noqa: PLC0415

    props = mi.Properties()
    props["bsdf"] = mi.load_dict(bsdf) if isinstance(bsdf, dict) else bsdf
    if medium is not None:
        props["interior"] = load_water_medium(medium) if isinstance(medium, dict) else medium
    mesh = mi.Mesh(WATER_ID, len(geometry.positions), len(faces), props, has_vertex_normals=True,
                   has_vertex_texcoords=geometry.shading is not None)
    if geometry.foam is not None:
        mesh.add_attribute(FOAM_ATTRIBUTE, 1, jit_floats(geometry.foam))
    if geometry.roughness is not None:
        mesh.add_attribute(ROUGHNESS_ATTRIBUTE, 1, jit_floats(geometry.roughness))
    for name, values in join_attributes(geometry).items():
        mesh.add_attribute(name, 3, values)
    params = mi.traverse(mesh)
    params["vertex_positions"] = jit_floats(geometry.positions)
    params["vertex_normals"] = jit_floats(geometry.normals)
    if geometry.shading is not None:
        params["vertex_texcoords"] = jit_floats(geometry.shading.texcoords)
    params["faces"] = jit_uints(faces)
    params.update()
    return mesh


def field_shaded_surface(geometry: FrameGeometry, ior: float, roughness: float, foam_albedo: float | None,
                         shading, lace=None):
    """The water surface BSDF shaded from the sea's fields at every hit (:mod:`.sea_shading`).

    ``roughdielectric`` whose α is :class:`~.sea_shading.SeaRoughness` (the footprint's
    unresolved slopes; off the upper surface the vertex α, or ``roughness``), blended with
    foam when ``foam_albedo`` is given (the foam grid's, or the vertices' drawn as ``lace``, a
    (tile, size [m]) pair), inside :class:`~.sea_shading.SeaSurfaceBSDF`.
    """
    from .sea_shading import lace_foam, sea_foam, sea_roughness, sea_surface  # noqa: PLC0415

    fallback = ({"type": "mesh_attribute", "name": ROUGHNESS_ATTRIBUTE} if geometry.roughness is not None
                else {"type": "uniform", "value": max(float(roughness), SMOOTH_ALPHA)})
    surface = {"type": "roughdielectric", "distribution": "beckmann", "alpha": sea_roughness(shading, fallback),
               "int_ior": float(ior), "ext_ior": 1.0}
    if foam_albedo is not None:
        surface = foamy_surface_bsdf(surface, foam_albedo)
        if getattr(shading, "foam_layout", None) is not None:  # the foam's field-resolution grid
            surface["weight"] = sea_foam(shading)
        elif lace is not None:
            surface["weight"] = lace_foam(surface["weight"], *lace)
    return sea_surface(surface, shading)


def surface_foam_weight(geometry: FrameGeometry, shading):
    """The fresh-foam weight [-] of the water's surface at a hit ``(si, active)``, as its BSDF blends the opaque
    foam (:func:`foamy_surface_bsdf`, :func:`field_shaded_surface`): the foam grid's (fields), or the vertices'
    drawn as lace or as they are; None without foam. For light traced through the surface (the sun's maps)."""
    if geometry.foam is None:
        return None
    if getattr(shading, "foam_layout", None) is not None:
        return shading.foam_at
    from .sea_shading import lace_weight  # noqa: PLC0415

    lace = geometry.foam_lace
    tile = None if lace is None else jit_floats(lace[0])

    def weight(si, active=True):
        fresh = si.shape.eval_attribute_1(FOAM_ATTRIBUTE, si, active)
        if lace is None:
            return fresh
        return lace_weight(fresh, si.p.x, si.p.y, tile, int(lace[0].shape[0]), float(lace[1]), active)

    return weight


#: Shapes a vertical ray from the camera passes before it gives up looking for the water's surface.
MAX_SHAPES_ABOVE_CAMERA = 16

#: Key of the camera in the water's medium (the scene's second sensor; the first is ``"sensor"``).
UNDERWATER_SENSOR = "sensor_underwater"

#: Id of the terrain mesh in the Mitsuba scene.
TERRAIN_ID = "terrain"

#: Name of the per-vertex rock coverage attribute of the terrain mesh.
ROCK_ATTRIBUTE = "vertex_rock"


def linear_albedo_spectrum(at_400_700: tuple[float, float]) -> dict:
    """An ``irregular`` reflectance spectrum over the film's range, linear through its 400 and 700 nm values."""
    wavelengths = np.array([FILM_RANGE_NM[0], 400.0, 700.0, FILM_RANGE_NM[1]])
    return irregular_spectrum(wavelengths, linear_reflectance(wavelengths, at_400_700))


def terrain_shape(terrain: Terrain):
    """The seafloor and beach as a Mitsuba mesh: Lambertian sand blended with rock by per-vertex coverage.

    It has no medium of its own: inside the water body, rays that reach it
    stay in the water. Reflectances [-] are linear in wavelength through their
    400 and 700 nm values (:func:`~oceanrender.optics.seafloor.linear_reflectance`).
    """
    import mitsuba as mi  # noqa: PLC0415

    props = mi.Properties()
    props["bsdf"] = mi.load_dict({
        "type": "blendbsdf",
        "weight": {"type": "mesh_attribute", "name": ROCK_ATTRIBUTE},
        "bsdf_0": {"type": "diffuse", "reflectance": linear_albedo_spectrum(terrain.sand_albedo)},
        "bsdf_1": {"type": "diffuse", "reflectance": linear_albedo_spectrum(terrain.rock_albedo)},
    })
    mesh = mi.Mesh(TERRAIN_ID, len(terrain.positions), len(terrain.faces), props, has_vertex_normals=True)
    mesh.add_attribute(ROCK_ATTRIBUTE, 1, jit_floats(terrain.rock))
    params = mi.traverse(mesh)
    params["vertex_positions"] = jit_floats(terrain.positions)
    params["vertex_normals"] = jit_floats(terrain.normals)
    params["faces"] = jit_uints(terrain.faces)
    params.update()
    return mesh


def object_shapes(settings: Scene, objects) -> dict:
    """The scene-dict entries of the posed ``objects`` (by name, with their settings' materials)."""
    by_name = {o.name: o for o in settings.objects}
    return {object_id(g.name): object_mesh(by_name[g.name], g.positions, g.faces, g.uv) for g in objects}


#: Id of the open sea's optional seafloor; its height above the water body's bottom face [m] (beyond
#: Mitsuba's ray offset, ~1e-4 (1 + |p|) m, at the depths of a scene).
SEAFLOOR_ID = "seafloor"
#: Reflectance of the open sea's bottom when the scene gives no ``bottom_albedo`` [-]: deep water, where the
#: light that passes the body's depth is lost (what the water below it would return is left out: at 50 m in the
#: default scene's clear water that is 13 % of the in-water pass's Z, docs/time_to_quality.md; give a deeper body).
DEEP_WATER_ALBEDO = 0.0
SEAFLOOR_LIFT_M = 0.02


def seafloor_shapes(settings: Scene, geometry: FrameGeometry) -> dict:
    """``{"seafloor": rectangle}``: the open sea's flat bottom, or none (a coast has its terrain).

    With ``[water] bottom_albedo`` A it is a Lambertian floor of reflectance A. Without, the sea is
    deep: the water goes on below the body, so light that reaches its bottom does not come back
    (reflectance 0; :data:`DEEP_WATER_ALBEDO`). The body's bottom face itself must not be what the
    light meets there: it is water against vacuum, a mirror by total internal reflection for the
    rays that refraction sends down at 40–49° from the vertical, which doubled the in-water light of
    the default view and carried its heavy tail of sun samples (docs/time_to_quality.md, issue 42).

    A ``rectangle`` (intersected in its own frame, so exact however large) just above the
    water body's bottom face, spanning the body's bottom (from the first frame's vertices,
    99 % of it). No medium: rays reach it in the water and stay there.
    """
    if settings.coastal is not None:
        return {}
    albedo = settings.water.bottom_albedo
    albedo = DEEP_WATER_ALBEDO if albedo is None else albedo
    import mitsuba as mi  # noqa: PLC0415

    depth = settings.water.depth
    bottom = geometry.positions[geometry.positions[:, 2] <= -depth + 1e-3 * (1.0 + depth)]
    lo, hi = bottom[:, :2].min(axis=0), bottom[:, :2].max(axis=0)
    centre, half = 0.5 * (lo + hi), 0.495 * (hi - lo)
    to_world = mi.ScalarTransform4f().translate([float(centre[0]), float(centre[1]), -depth + SEAFLOOR_LIFT_M]) \
        @ mi.ScalarTransform4f().scale([float(half[0]), float(half[1]), 1.0])
    return {SEAFLOOR_ID: {"type": "rectangle", "to_world": to_world,
                          "bsdf": {"type": "diffuse", "reflectance": {"type": "uniform", "value": float(albedo)}}}}


def terrain_shapes(terrain: Terrain | None) -> dict:
    """The scene-dict entries of a body's terrain: ``{"terrain": mesh}``, or none (open sea)."""
    return {} if terrain is None else {TERRAIN_ID: terrain_shape(terrain)}


def update_water_parameters(params, geometry: FrameGeometry) -> None:
    """Write a frame's vertex positions [m], normals, foam and roughness into a loaded scene's water mesh."""
    params[f"{WATER_ID}.vertex_positions"] = jit_floats(geometry.positions)
    params[f"{WATER_ID}.vertex_normals"] = jit_floats(geometry.normals)
    if geometry.foam is not None:
        params[f"{WATER_ID}.{FOAM_ATTRIBUTE}"] = jit_floats(geometry.foam)
    if geometry.roughness is not None:
        params[f"{WATER_ID}.{ROUGHNESS_ATTRIBUTE}"] = jit_floats(geometry.roughness)
    if geometry.shading is not None:
        params[f"{WATER_ID}.vertex_texcoords"] = jit_floats(geometry.shading.texcoords)
    for name, values in join_attributes(geometry).items():
        params[f"{WATER_ID}.{name}"] = values
    params.update()


def foam_reflectance_spectrum(albedo: float) -> dict:
    """Fresh foam's reflectance [-] as an ``irregular`` spectrum over the film's range.

    ``albedo`` in the visible (Whitlock et al. 1982: 0.55) times the decrease
    towards the near infrared of Frouin et al. (1996)
    (:func:`~oceanrender.optics.foam.foam_spectral_factor_Frouin1996`).
    """
    wavelengths = np.array([FILM_RANGE_NM[0], 555.0, 700.0, FILM_RANGE_NM[1]])
    return irregular_spectrum(wavelengths, float(albedo) * foam_spectral_factor_Frouin1996(wavelengths))


def foamy_surface_bsdf(surface: dict, albedo: float) -> dict:
    """The water surface with a Lambertian layer of fresh foam on the fraction ``vertex_foam`` of it.

    ``vertex_foam`` (per vertex, interpolated over each triangle by a
    ``mesh_attribute`` texture) is the fresh-foam coverage B of
    :meth:`oceanrender.surface.open_sea.WaterBody.vertex_foam`: a whitecap of
    coverage F and age a reflects like fresh foam on the fraction
    F e^{−a/τ_f} of its area, the exponential decay of a whitecap's
    reflectance (Koepke 1984), and like water on the rest. ``albedo`` is
    fresh foam's visible reflectance [-] (:func:`foam_reflectance_spectrum`).

    NOTE: the linear coverage model of whitecaps (Koepke 1984; Frouin et al.
    1996): an opaque Lambertian layer over part of the surface, the water
    (its ``surface`` BSDF) over the rest; the foam's own bubbles' light
    into the water below it is left out.
    """
    return {
        "type": "blendbsdf",
        "weight": {"type": "mesh_attribute", "name": FOAM_ATTRIBUTE},
        "bsdf_0": surface,
        "bsdf_1": {"type": "diffuse", "reflectance": foam_reflectance_spectrum(albedo)},
    }


@dataclass
class WaterRenderer:
    """A loaded Mitsuba scene: sun and sky, camera, closed water body.

    Build it with :meth:`build`; then per frame :meth:`update_water` and
    :meth:`render_xyz`.
    """

    scene: object
    params: object
    resolution: tuple[int, int]
    bands: int = 0
    #: The last render's spectral bands (H, W, bands), band integrals ∫L dλ [W m⁻² sr⁻¹], or None.
    last_bands: np.ndarray | None = None
    #: Two-pass frames (``render.in_water_fraction`` < 1): the ``split`` integrator of the in-water pass
    #: (``lobes="transmission"``; the scene's own then has ``lobes="reflection"``), else None.
    in_water: object | None = None
    #: Samples per pixel of the in-water pass as a fraction of the frame's spp [-].
    in_water_fraction: float = 1.0
    #: Where the camera is [m] (the pinhole), for :meth:`camera_in_water`.
    camera_position: np.ndarray | None = None
    #: Whether the last frame :meth:`render_xyz` rendered had its camera under the water.
    last_camera_in_water: bool = False
    #: Refractive index of the water [-] and the Mitsuba ids of the objects, for :meth:`passes`.
    n_water: float = 1.333
    object_ids: tuple[str, ...] = ()
    #: The sea's shading fields on the device (:class:`~.sea_shading.SeaShading`), or None (vertex shading).
    shading: object | None = None
    #: The sun's beam on the open sea's floor (:class:`~.sun_beam.FloorCaustics`, ``[render] caustic_cell``), or None.
    floor_caustics: object | None = None
    #: The sun's beam in the water's volume (:class:`~.sun_beam.VolumeBeam`, ``[render] shaft_cell``), or None.
    volume_beam: object | None = None
    #: The scene's ``[sun]`` (its spectrum, measured per direction, for :attr:`floor_caustics`).
    sun_settings: object | None = None
    #: The sun's (elevation, azimuth) [deg] last set by :meth:`point_sun`, or None (the scene's).
    sun_angles: tuple[float, float] | None = None
    #: (shading fields, (camera, sun)) the floor's map was last traced for (:meth:`update_caustics`).
    caustics_for: tuple | None = None
    #: sensor → the :class:`~.pixels.PixelSampler` of each pass (:meth:`block_xyz`), made on first use.
    pixel_samplers: dict = field(default_factory=dict)
    #: The geometry :meth:`update_water` last loaded (None: the one :meth:`build` loaded, or none).
    water: FrameGeometry | None = None

    @classmethod
    def build(cls, settings: Scene, iops: WaterIOPs | MediumOptics, faces: np.ndarray, geometry: FrameGeometry,
              roughness: float = 0.0, spp: int | None = None, resolution: tuple[int, int] | None = None,
              sun_lobe_alpha: float | None = None, terrain: Terrain | None = None,
              in_water_clamp: float = 0.0, objects: tuple = (),
              crop: tuple[int, int, int, int] | None = None) -> "WaterRenderer":
        """Load the scene once (vertex count and faces are then fixed).

        ``roughness`` is the Beckmann α of the water surface [-] (unused
        when ``geometry.roughness`` gives one per vertex);
        ``sun_lobe_alpha`` the total rms slope of the surface [-], which turns
        on the in-water sun sampling of the ``split`` integrator (when the
        scene's ``render.sun_sampling`` allows it); ``objects`` the ``[[objects]]``
        posed at the first frame (:class:`~oceanrender.surface.objects.ObjectGeometry`); ``crop``
        (x, y, width, height) [px] renders only that window of the frame (:func:`~.scene.xyz_film`).
        """
        import mitsuba as mi  # noqa: PLC0415

        width, height = resolution or settings.output.resolution
        shading = None
        if geometry.shading is not None:
            from .sea_shading import SeaShading, pixel_angle  # noqa: PLC0415

            shading = SeaShading(geometry.shading, settings.camera.position, pixel_angle(settings.camera.fov, width))
            bsdf = field_shaded_surface(geometry, water_ior(settings), roughness,
                                        settings.foam.albedo if geometry.foam is not None else None, shading,
                                        geometry.foam_lace if geometry.foam is not None else None)
        else:
            bsdf = water_surface_bsdf(water_ior(settings), roughness, per_vertex=geometry.roughness is not None)
            if geometry.foam is not None:
                bsdf = foamy_surface_bsdf(bsdf, settings.foam.albedo)
                if geometry.foam_lace is not None:  # the coast's cells: their foam drawn as lace
                    from .sea_shading import lace_foam  # noqa: PLC0415

                    bsdf["weight"] = lace_foam(bsdf["weight"], *geometry.foam_lace)
        medium = load_water_medium(water_medium(iops))
        mesh = water_mesh(faces, geometry, bsdf, medium)
        sun_sampling = {}
        has_sun = settings.environment is None or settings.environment.sun  # a map alone has no sun to sample
        if settings.render.sun_sampling and sun_lobe_alpha is not None and has_sun:
            sun_sampling = {"sun": sun_direction(settings.sun.elevation, settings.sun.azimuth),
                            "water_ior": water_ior(settings), "sun_lobe_alpha": float(sun_lobe_alpha),
                            "in_water_clamp": float(in_water_clamp)}
        render = settings.render
        two_pass = render.integrator == "split" and render.in_water_fraction < 1.0
        integrator = {"kind": render.integrator, "max_depth": render.max_depth, "rr_depth": render.roulette_depth,
                      **sun_sampling}
        in_water = mi.load_dict(volumetric_integrator(**integrator, lobes="transmission")) if two_pass else None
        sensor = perspective_sensor(settings.camera, xyz_film(width, height, settings.output.spectral_bands, crop),
                                    spp or settings.output.spp, render.sampler)
        scene = mi.load_dict({
            "type": "scene",
            "integrator": volumetric_integrator(**integrator, lobes="reflection" if two_pass else "both"),
            "sensor": sensor,
            # NOTE: the same camera in the water's medium; a frame whose camera is under the surface renders
            # with it (camera_in_water), so its rays start in the water.
            UNDERWATER_SENSOR: {**sensor, "medium": medium},
            **sky_emitters(settings),
            WATER_ID: mesh,
            **terrain_shapes(terrain),
            **seafloor_shapes(settings, geometry),
            **object_shapes(settings, objects),
        })
        renderer = cls(scene=scene, params=mi.traverse(scene), resolution=(width, height),
                       bands=settings.output.spectral_bands, in_water=in_water,
                       in_water_fraction=render.in_water_fraction if two_pass else 1.0,
                       camera_position=np.asarray(settings.camera.position, float), n_water=water_ior(settings),
                       object_ids=tuple(object_id(o.name) for o in objects), shading=shading,
                       sun_settings=settings.sun)
        import drjit as dr  # noqa: PLC0415

        # the sun's beam traced into maps: the split integrator's in-water tracer (JIT variants); the open sea's
        # floor and volume from the sea's fields, a terrain's by casting rays through the body (fields or not)
        if sun_sampling and render.integrator == "split" and dr.is_jit_v(mi.Float):
            from .sun_beam import SHAFT_PLANE_STEP, FloorCaustics, TerrainCaustics, VolumeBeam  # noqa: PLC0415

            shapes = {shape.id(): shape for shape in scene.shapes()}
            floor = shapes.get(SEAFLOOR_ID)
            if render.caustic_cell > 0 and terrain is not None:
                deepest = -float(np.min(terrain.positions[:, 2]))
                renderer.floor_caustics = TerrainCaustics(
                    scene, shapes[WATER_ID], [shapes[k] for k in (TERRAIN_ID, SEAFLOOR_ID) if k in shapes],
                    render.caustic_cell, render.caustic_window, water_ior(settings),
                    min(render.shaft_depth, deepest), foam=surface_foam_weight(geometry, shading),
                    alpha=roughness)
            elif render.caustic_cell > 0 and floor is not None and shading is not None and settings.water.bottom_albedo:
                renderer.floor_caustics = FloorCaustics(floor, -settings.water.depth + SEAFLOOR_LIFT_M,
                                                        render.caustic_cell, render.caustic_window,
                                                        water_ior(settings))
            if render.shaft_cell > 0 and shading is not None:
                renderer.volume_beam = VolumeBeam(render.shaft_cell, SHAFT_PLANE_STEP, render.caustic_window,
                                                  min(render.shaft_depth, settings.water.depth), water_ior(settings))
            for integrator in renderer.integrators():
                integrator.floor_caustics, integrator.volume_beam = renderer.floor_caustics, renderer.volume_beam
        renderer.update_caustics(geometry)
        return renderer

    def integrators(self) -> list:
        """The Mitsuba integrators a frame uses: the scene's, then the in-water pass's (two-pass frames)."""
        return [self.scene.integrator()] + ([self.in_water] if self.in_water is not None else [])

    def in_water_spp(self, spp: int) -> int:
        """Samples per pixel of the in-water pass of a ``spp`` frame: max(1, round(fraction × spp)) [-]."""
        return max(1, round(self.in_water_fraction * int(spp)))

    def point_camera(self, position, target, fov: float) -> None:
        """Move the camera to ``position`` looking at ``target`` [m], horizontal ``fov`` [deg], in place."""
        pose = CameraPose(np.asarray(position, float), np.asarray(target, float), float(fov))
        apply_camera(self.params, pose, sensor="sensor")
        apply_camera(self.params, pose, sensor=UNDERWATER_SENSOR)
        self.camera_position = pose.position
        if self.shading is not None:
            from .sea_shading import pixel_angle  # noqa: PLC0415

            self.shading.set_camera(pose.position)
            self.shading.set_pixel_angle(pixel_angle(pose.fov, self.resolution[0]))

    def camera_in_water(self) -> bool:
        """Whether the camera's pinhole is inside the water body of the current frame.

        Decided on the frame's own mesh: a ray from the pinhole straight up meets the water
        body's surface from inside (its outward normal along the ray) exactly when the
        pinhole is under the water — the surface that is rendered, not a model of it.
        """
        import mitsuba as mi  # noqa: PLC0415

        if self.camera_position is None:
            return False
        water = next(shape for shape in self.scene.shapes() if shape.id() == WATER_ID)
        jit = mi.variant().startswith(("llvm", "cuda"))
        ray = mi.Ray3f(mi.Point3f(*(float(v) for v in self.camera_position)), mi.Vector3f(0.0, 0.0, 1.0))
        for _ in range(MAX_SHAPES_ABOVE_CAMERA):  # past other shapes (a hull, rock) to the water's first hit
            si = self.scene.ray_intersect(ray)
            if not bool(np.array(si.is_valid(), dtype=bool).ravel()[0]):
                return False
            on_water = (si.shape == mi.ShapePtr(water)) if jit else (si.shape is water)
            if bool(np.array(on_water, dtype=bool).ravel()[0]):
                return bool(np.array(si.n.z, dtype=float).ravel()[0] > 0)  # outward normal: leaving the water
            ray = si.spawn_ray(ray.d)
        return False

    def point_sun(self, elevation: float, azimuth: float) -> None:
        """Move the sun of the sky and of the ``split`` integrator's in-water sampling [deg], in place.

        Neither reloads the scene nor recompiles: ``sunsky``'s direction is a
        scene parameter, and the integrator holds its sun as an opaque value.
        """
        apply_sun(self.params, SunAngles(float(elevation), float(azimuth)), emitter="sky")
        self.sun_angles = (float(elevation), float(azimuth))
        for integrator in self.integrators():
            if getattr(integrator, "sun", None) is not None:
                integrator.set_sun(sun_direction(float(elevation), float(azimuth)))

    def set_in_water_clamp(self, value: float) -> None:
        """Set the ``split`` integrator's in-water clamp [W m⁻² sr⁻¹ nm⁻¹] when it has one (else nothing)."""
        for integrator in self.integrators():
            if getattr(integrator, "clamps", False):
                integrator.set_in_water_clamp(float(value))

    def passes(self, names: tuple[str, ...]) -> dict[str, np.ndarray]:
        """The render passes ``names`` of the frame last rendered, as EXR channels (:mod:`.passes`)."""
        from .passes import first_hit_passes  # noqa: PLC0415

        return first_hit_passes(self.scene, names, sensor=1 if self.last_camera_in_water else 0, water_id=WATER_ID,
                                object_ids=self.object_ids, n_water=self.n_water,
                                camera_in_water=self.last_camera_in_water, foam_attribute=FOAM_ATTRIBUTE)

    def update_objects(self, objects) -> None:
        """Move the ``[[objects]]`` to their poses of a frame (:class:`~oceanrender.surface.objects.ObjectGeometry`)."""
        if not objects:
            return
        for geometry in objects:
            update_object_positions(self.params, geometry.name, geometry.positions)
        self.params.update()

    def update_water(self, geometry: FrameGeometry, floor_map: bool = True) -> None:
        """Replace the water mesh's vertex positions [m], unit normals and foam in place (and the sea's
        shading fields). ``floor_map`` False: the floor's map is left out of the next renders (the path
        tracer lights the floor alone, unbiased: the meter's quick renders of other frames need no map)."""
        if geometry is not self.water:  # (the meter's reading of the frame just rendered: its water is loaded)
            update_water_parameters(self.params, geometry)
            if self.shading is not None and geometry.shading is not None:
                self.shading.update(geometry.shading)
            self.water = geometry
        if not floor_map and self.floor_caustics is not None:
            self.floor_caustics.leave_out()
            self.caustics_for = None
            if self.volume_beam is None:
                return
        self.update_caustics(geometry, floor_map)

    def update_caustics(self, geometry: FrameGeometry, floor_map: bool = True) -> None:
        """Trace the sun's beam onto the floor's map (unless not ``floor_map``) and the volume's planes for a frame
        (after the shading fields and the sun are set)."""
        maps = [m for m in (self.floor_caustics if floor_map else None, self.volume_beam) if m is not None]
        if not maps:
            return
        from .environment import SUN_WAVELENGTHS_NM, sun_normal_irradiance  # noqa: PLC0415

        # the meter's render and the frame's both load the same geometry: one map for both
        key = (tuple(np.asarray(self.camera_position, float)), self.sun_angles)
        frame = geometry.shading if geometry.shading is not None else geometry  # (a coast without fields)
        last = self.caustics_for
        if last is not None and last[0] is frame and last[1] == key:
            return
        self.caustics_for = (frame, key) if floor_map else None
        sun = self.sun_settings
        if self.sun_angles is not None:
            sun = sun.model_copy(update={"elevation": self.sun_angles[0], "azimuth": self.sun_angles[1]})
        for beam_map in maps:
            beam_map.update(self.shading, sun_direction(sun.elevation, sun.azimuth), sun_normal_irradiance(sun),
                            SUN_WAVELENGTHS_NM, self.camera_position[:2])

    def render_film(self, spp: int, seed: int, sensor: int) -> np.ndarray:
        """The mean film (H, W, C) of a frame of ``spp`` samples seen by ``sensor`` (0: the air's, 1: the water's):
        the rest, plus the in-water pass for a camera in the air (:meth:`render_xyz`)."""
        film = render_passes(self.scene, int(spp), int(seed), sensor=sensor)
        if self.in_water is not None and sensor == 0:  # under the water nothing is split: one pass is the frame
            film = film + render_passes(self.scene, self.in_water_spp(spp), in_water_seed(seed), self.in_water)
        return film

    def render_xyz(self, spp: int, seed: int) -> tuple[np.ndarray, int]:
        """Render one frame → (absolute XYZ (H, W, 3) [cd m⁻²], repaired pixel count).

        A two-pass frame adds the in-water pass (:meth:`in_water_spp` samples, its own
        seed stream) to the rest (``spp``): the film values are per-pixel means, and the two
        passes estimate disjoint parts of each sample's radiance, so their sum is unbiased.
        """
        self.last_camera_in_water = self.camera_in_water()
        film = self.render_film(spp, seed, 1 if self.last_camera_in_water else 0)
        if self.bands:
            self.last_bands = repair_non_finite(np.asarray(film[..., 3:], dtype=np.float64))[0]
        return repair_non_finite(film_to_absolute_XYZ(film[..., :3]))

    def prepare_blocks(self) -> None:
        """Make :meth:`block_xyz`'s samplers for both sensors now (JIT variants; else nothing)."""
        import mitsuba as mi  # noqa: PLC0415

        if mi.variant().startswith(("llvm", "cuda")):
            for sensor in (0, 1):
                _block_samplers(self, sensor)

    def compile_kernels(self, spp: int | None, blocks: bool = True) -> None:
        """Compile the kernels of a frame of ``spp`` samples (:meth:`render_xyz`; None: not those) and, with
        ``blocks``, of the meter (:meth:`block_xyz`), for the sensor the camera is in now, rendering next to
        nothing: the frame's passes with every water triangle collapsed to a point (no ray meets the water),
        then the meter's launches with all lanes masked off. JIT variants; else nothing.

        The water is left collapsed: load the frame's with :meth:`update_water` next. (Not put back: measured,
        the same vertices loaded again after others render a few pixels differently, so a frame's water is
        loaded once, after.)

        A kernel's code depends on the scene's structure, not on its values: compiled while the scene holds a
        stand-in for its first water body, these are the kernels the real frame runs.
        """
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        if not mi.variant().startswith(("llvm", "cuda")):
            return
        sensor = 1 if self.camera_in_water() else 0
        if spp is not None:
            key = f"{WATER_ID}.vertex_positions"
            self.params[key] = dr.zeros(mi.Float, dr.width(self.params[key]))
            self.params.update()
            self.water = None  # (what update_water loaded is gone: the next one loads again)
            self.render_film(spp, 0, sensor)
        if blocks:
            for sampler in _block_samplers(self, sensor):
                sampler.launch(np.zeros(0, dtype=np.uint32), seed=0)

    def compile_kernels_beside(self, work: Callable[[], T], spp: int | None, blocks: bool = True) -> T:
        """``work()`` in this thread while another runs :meth:`compile_kernels` (``spp``, ``blocks``); its result.

        ``work`` must not touch Mitsuba or Dr.Jit (the other thread traces the scene); numpy work
        overlaps, as LLVM compiles with Python's lock released (BENCHMARKS.md). Dr.Jit's flags
        are per thread: the compiling thread takes this one's (``PacketOps`` off,
        :func:`~oceanrender.runtime.variants.steady_kernels`), so its kernels are the ones this
        thread will run. An error of either is raised, after both have finished. The water is then
        collapsed (:meth:`compile_kernels`): load the frame's next.
        """
        from concurrent.futures import ThreadPoolExecutor  # noqa: PLC0415

        flags = jit_flags()

        def compile_here():
            import drjit as dr  # noqa: PLC0415

            for flag, value in flags.items():
                if dr.flag(flag) != value:
                    dr.set_flag(flag, value)
            self.compile_kernels(spp, blocks)

        with ThreadPoolExecutor(max_workers=1, thread_name_prefix="compile-kernels") as pool:
            compiling = pool.submit(compile_here)
            try:
                result = work()
            finally:
                error = compiling.exception()  # waits: the scene is this thread's again only after it
        if error is not None:
            raise error
        return result

    def block_xyz(self, columns: int, samples: int, seed: int) -> np.ndarray:
        """Mean XYZ [cd m⁻²] of the blocks of a grid over the view ((rows, columns, 3)): ``samples`` samples per
        block and pass, at uniform positions in it (:func:`~.pixels.block_slots`), both passes of a frame.

        Rendered by :class:`~.pixels.PixelSampler`: a fixed number of lanes per launch and an opaque
        seed, so every call runs the same compiled kernel per pass whatever the frame (a ``mi.render``
        with fewer samples than the frame's would compile its own). Unbiased for each block.
        """
        import mitsuba as mi  # noqa: PLC0415

        from .pixels import block_means, block_slots  # noqa: PLC0415

        if not mi.variant().startswith(("llvm", "cuda")):
            raise NotImplementedError("block_xyz needs a JIT variant (llvm_* or cuda_*)")
        sensor = 1 if self.camera_in_water() else 0
        width, height = self.resolution
        pixels, blocks, shape = block_slots(width, height, columns, samples, seed)
        samplers = _block_samplers(self, sensor)
        total = block_means(samplers[0], pixels, blocks, shape, seed)
        for sampler in samplers[1:]:  # the in-water pass: its own seed stream, as render_xyz
            total = total + block_means(sampler, pixels, blocks, shape, in_water_seed(seed))
        return total


def jit_flags() -> dict:
    """This thread's Dr.Jit flags (``JitFlag`` → bool): a new thread starts from the defaults, not from these."""
    import drjit as dr  # noqa: PLC0415

    return {flag: bool(dr.flag(flag)) for name, flag in dr.JitFlag.__members__.items() if name != "Default"}


def _block_samplers(renderer: "WaterRenderer", sensor: int) -> list:
    """The :class:`~.pixels.PixelSampler` of each pass of ``renderer``'s frames seen by ``sensor`` (made once)."""
    from .pixels import PixelSampler  # noqa: PLC0415

    cache = renderer.pixel_samplers
    if sensor not in cache:
        integrators = [renderer.scene.integrator()]
        if renderer.in_water is not None and sensor == 0:  # under the water nothing is split: one pass
            integrators.append(renderer.in_water)
        cache[sensor] = [PixelSampler(renderer.scene, integrator, sensor=sensor) for integrator in integrators]
    return cache[sensor]


class WhiteMeter:
    """A white Lambertian plane under the scene's sun and sky, loaded once, to measure the adapting white.

    The radiance of a perfectly white Lambertian plane is L = E/π, with E the
    horizontal spectral irradiance of sun + sky (Lambert's cosine law), so
    :meth:`measure` gives the adapting white of the vision model in the same
    spectra and units as the frames. It is measured by an orthographic sensor
    looking straight down at a large white ``diffuse`` disk under the same
    ``sunsky`` emitter (key ``"sky"``), one sample per pixel
    (:func:`~oceanrender.render.scene.white_plane_meter`: identical readings in
    every process), with next-event estimation (``path``, one bounce). :meth:`point_sun` moves the sun in place, so a moving sun
    costs one small render per frame, not a scene load (and its compilation).
    """

    def __init__(self, settings: Scene, spp: int | None = None):
        import mitsuba as mi  # noqa: PLC0415

        emitters = sky_emitters(settings)  # sunsky, or an environment map (and its sun)
        meter = white_plane_meter(emitters.pop("sky"), xyz_film(1, 1), int(spp or settings.render.white_spp))
        self.scene = mi.load_dict({**meter, **emitters})
        self.params = mi.traverse(self.scene)

    def point_sun(self, elevation: float, azimuth: float) -> None:
        """Move the sun to ``elevation`` (> 0) and ``azimuth`` clockwise from north [deg], in place."""
        apply_sun(self.params, SunAngles(float(elevation), float(azimuth)), emitter="sky")

    def measure(self, seed: int = 0) -> np.ndarray:
        """XYZ [cd m⁻²] of the white plane under the current sun and sky."""
        import mitsuba as mi  # noqa: PLC0415

        return film_to_absolute_XYZ(meter_reading(mi.render(self.scene, seed=int(seed)))).reshape(3)


def adapting_white_XYZ(settings: Scene, spp: int | None = None, seed: int = 0) -> np.ndarray:
    """XYZ [cd m⁻²] of a white Lambertian surface lit by the scene's sun and sky (:class:`WhiteMeter`)."""
    return WhiteMeter(settings, spp).measure(seed)
