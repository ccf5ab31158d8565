"""Render passes (AOVs) of a frame, named as compositors expect: ``[output] passes``.

The depth pass is ``depth.Z``, Nuke's channel for it, because the frame's own ``X, Y, Z``
are CIE tristimulus values. Each pass is read from the camera's pixel-centre ray (one ray per pixel, through the
same Mitsuba sensor the frame is rendered with, so it lines up with the beauty pass):

| pass          | EXR channels            | what                                                          |
|---------------|-------------------------|---------------------------------------------------------------|
| ``"Z"``       | ``depth.Z``             | distance from the camera along the ray to the first surface [m]; :data:`FAR_Z` where it meets none (sky) |
| ``"N"``       | ``N.X``, ``N.Y``, ``N.Z`` | world shading normal at the first surface [-] (0 on the sky) |
| ``"P"``       | ``P.X``, ``P.Y``, ``P.Z`` | world position of the first surface [m] (0 on the sky)      |
| ``"water"``   | ``mask.water``          | 1 where the first surface is the water's, else 0               |
| ``"foam"``    | ``mask.foam``           | the fresh-foam coverage of the water surface there [0, 1]      |
| ``"objects"`` | ``mask.objects``        | 1 where the first surface is one of the ``[[objects]]``        |
| ``"water_path"`` | ``water_path``       | length of the ray's first stretch in the water [m]: from the surface it refracts through (or from the camera under the water) to the next surface; 0 where it never enters the water, :data:`FAR_Z` where nothing ends it |

World frame: x east, y north, z up, metres. Unfiltered (one sample at the pixel centre),
as compositors' ID and depth passes are.
"""

from __future__ import annotations

import numpy as np

from ..optics.fresnel import refract

__all__ = ["PASSES", "PASS_CHANNELS", "FAR_Z", "first_hit_passes"]

#: The passes ``[output] passes`` may name, and their EXR channels.
PASS_CHANNELS = {
    "Z": ("depth.Z",),  # NOTE: Nuke's name; a bare "Z" is the frame's CIE Z tristimulus channel
    "N": ("N.X", "N.Y", "N.Z"),
    "P": ("P.X", "P.Y", "P.Z"),
    "water": ("mask.water",),
    "foam": ("mask.foam",),
    "objects": ("mask.objects",),
    "water_path": ("water_path",),
}
PASSES = tuple(PASS_CHANNELS)
#: Distance written where a ray meets nothing [m] (finite, so compositors' depth tools keep working).
FAR_Z = 1.0e10


def _numpy3(v) -> np.ndarray:
    return np.stack([np.array(v.x, dtype=np.float64), np.array(v.y, dtype=np.float64),
                     np.array(v.z, dtype=np.float64)], -1)


def first_hit_passes(scene, passes, *, sensor: int = 0, water_id: str, object_ids=(), n_water: float,
                     camera_in_water: bool = False, foam_attribute: str | None = None) -> dict[str, np.ndarray]:
    """The EXR channels (H, W) float32 of ``passes`` (names of :data:`PASS_CHANNELS`) for a loaded scene.

    ``sensor``: index of the scene's sensor the frame is rendered with; ``water_id``, ``object_ids``:
    Mitsuba ids of the water body and the objects; ``n_water``: the water's refractive index [-];
    ``camera_in_water``: the camera is under the surface; ``foam_attribute``: the water mesh's
    per-vertex foam attribute, if it has one.
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    unknown = [p for p in passes if p not in PASS_CHANNELS]
    if unknown:
        raise ValueError(f"passes: unknown {', '.join(unknown)}; known: {', '.join(PASSES)}")
    camera = scene.sensors()[sensor]
    width, height = (int(v) for v in camera.film().crop_size())
    index = dr.arange(mi.UInt32, width * height)
    film = mi.Point2f((mi.Float(index % width) + 0.5) / width, (mi.Float(index // width) + 0.5) / height)
    ray, _ = camera.sample_ray(0.0, 0.5, film, mi.Point2f(0.5, 0.5))
    si = scene.ray_intersect(ray)
    shapes = {shape.id(): shape for shape in scene.shapes()}
    water = shapes[water_id]
    on_water = si.is_valid() & (si.shape == mi.ShapePtr(water))
    on_object = mi.Bool(False)
    for name in object_ids:
        on_object |= si.is_valid() & (si.shape == mi.ShapePtr(shapes[name]))
    dr.eval(si, on_water, on_object)
    valid = np.array(si.is_valid(), dtype=bool)
    shape = (height, width)
    out: dict[str, np.ndarray] = {}
    if "Z" in passes:
        out["depth.Z"] = np.where(valid, np.array(si.t, dtype=np.float64), FAR_Z)
    if "N" in passes:
        normal = np.where(valid[:, None], _numpy3(si.sh_frame.n), 0.0)
        out.update({f"N.{c}": normal[:, i] for i, c in enumerate("XYZ")})
    if "P" in passes:
        position = np.where(valid[:, None], _numpy3(si.p), 0.0)
        out.update({f"P.{c}": position[:, i] for i, c in enumerate("XYZ")})
    if "water" in passes:
        out["mask.water"] = np.array(on_water, dtype=np.float64)
    if "objects" in passes:
        out["mask.objects"] = np.array(on_object, dtype=np.float64)
    if "foam" in passes:
        foam = np.zeros(width * height)
        if foam_attribute is not None and water.has_attribute(foam_attribute):
            value = np.array(water.eval_attribute_1(foam_attribute, si, on_water), dtype=np.float64)
            foam = np.where(np.array(on_water, dtype=bool), np.clip(value, 0.0, 1.0), 0.0)
        out["mask.foam"] = foam
    if "water_path" in passes:
        out["water_path"] = _water_path(scene, ray, si, on_water, n_water, camera_in_water, valid)
    # NOTE: a mask of no shape (no objects) comes back as one lane: broadcast it to the pixels.
    return {name: np.broadcast_to(np.asarray(value, dtype=np.float32), (width * height,)).reshape(shape).copy()
            for name, value in out.items()}


def _water_path(scene, ray, si, on_water, n_water: float, camera_in_water: bool, valid: np.ndarray) -> np.ndarray:
    """Length of the first in-water stretch of each ray [m] (see the module table)."""
    import mitsuba as mi  # noqa: PLC0415

    if camera_in_water:  # the ray starts in the water and runs to the first surface
        return np.where(valid, np.array(si.t, dtype=np.float64), FAR_Z)
    # Refract through the water surface's shading normal (Snell, air -> water) and trace to the next surface;
    # where that would leave the water (a shading normal far from the facet's), through the facet's normal.
    d = _numpy3(ray.d)
    geometric = _facing(_numpy3(si.n), d)
    t = refract(d, _facing(_numpy3(si.sh_frame.n), d), 1.0 / n_water)
    wrong_side = np.sum(t * geometric, axis=-1) >= 0
    t[wrong_side] = refract(d[wrong_side], geometric[wrong_side], 1.0 / n_water)
    inside = mi.Ray3f(si.spawn_ray(mi.Vector3f(t[:, 0], t[:, 1], t[:, 2])))
    second = scene.ray_intersect(inside, on_water)
    hit = np.array(second.is_valid(), dtype=bool)
    length = np.where(hit, np.array(second.t, dtype=np.float64), FAR_Z)
    return np.where(np.array(on_water, dtype=bool), length, 0.0)


def _facing(normals: np.ndarray, d: np.ndarray) -> np.ndarray:
    """``normals`` turned to the side the rays ``d`` come from (d·n ≤ 0)."""
    return np.where((np.sum(normals * d, axis=-1) > 0)[:, None], -normals, normals)
