"""The view of a frame as a shader sees it: camera, and a per-pixel G-buffer by ray casting.

A rasteriser shades each pixel at its centre; the G-buffer here is the same:
one ray per pixel centre from the pinhole camera of the scene (the formula of
:meth:`Camera.ray_directions`, which matches Mitsuba's ``perspective`` sensor —
tested), cast with ``mi.Scene.ray_intersect`` into the very scene the path
tracer renders. At a water hit two more rays are cast: the view ray refracted
by the surface normal (Snell's law) to the seafloor, giving the in-water path
length l and the seafloor point, and a vertical ray down to the seafloor,
giving the depth h of the water column under the surface point.

NOTE: Mitsuba's ``aov`` integrator gives position, normals and distance too,
but averaged over each pixel's box filter, which mixes surfaces at
silhouettes (the shoreline, the horizon); it is used in the tests to check
this camera against Mitsuba's, not as the G-buffer.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..optics.fresnel import refract
from ..render.buffers import jit_bools, jit_floats


__all__ = ["Camera", "camera_for_scene", "GBuffer", "trace_gbuffer", "KIND_SKY", "KIND_WATER", "KIND_LAND",
           "KIND_OTHER"]

#: Values of :attr:`GBuffer.kind`.
KIND_SKY, KIND_WATER, KIND_LAND, KIND_OTHER = 0, 1, 2, 3


@dataclass(frozen=True)
class Camera:
    """A pinhole camera in the world frame (z up, +x east, +y north; metres).

    Attributes
    ----------
    position : ndarray (3,)          Centre of projection [m].
    forward, right, up : ndarray (3,)  Orthonormal frame: viewing direction, image right, image up.
    fov_x : float                    Horizontal field of view [deg].
    width, height : int              Resolution [px].
    """

    position: NDArray[np.float64]
    forward: NDArray[np.float64]
    right: NDArray[np.float64]
    up: NDArray[np.float64]
    fov_x: float
    width: int
    height: int

    @property
    def fov_y(self) -> float:
        """Vertical field of view [deg]: tan(fov_y/2) = tan(fov_x/2) · height/width."""
        return math.degrees(2.0 * math.atan(math.tan(math.radians(self.fov_x) / 2.0) * self.height / self.width))

    def ray_directions(self) -> NDArray[np.float64]:
        """Unit directions (height, width, 3) of the rays through the pixel centres.

        d ∝ forward + x tan(fov_x/2) right + y tan(fov_y/2) up with
        x = 2(i + ½)/width − 1 (column i, left to right) and
        y = 1 − 2(j + ½)/height (row j, top to bottom).
        """
        tx = math.tan(math.radians(self.fov_x) / 2.0)
        ty = tx * self.height / self.width
        x = (2.0 * (np.arange(self.width) + 0.5) / self.width - 1.0) * tx
        y = (1.0 - 2.0 * (np.arange(self.height) + 0.5) / self.height) * ty
        d = self.forward + x[None, :, None] * self.right + y[:, None, None] * self.up
        return d / np.linalg.norm(d, axis=-1, keepdims=True)

    def to_world(self) -> NDArray[np.float64]:
        """4 × 4 camera-to-world matrix, columns (right, up, −forward, position) (OpenGL view convention)."""
        m = np.eye(4)
        m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = self.right, self.up, -self.forward, self.position
        return m

    def describe(self) -> dict[str, object]:
        """JSON-ready description for a shader author."""
        return {
            "position_m": self.position.tolist(), "forward": self.forward.tolist(), "right": self.right.tolist(),
            "up": self.up.tolist(), "fov_x_deg": self.fov_x, "fov_y_deg": self.fov_y,
            "resolution": [self.width, self.height], "projection": "pinhole (perspective)",
            "camera_to_world": self.to_world().tolist(),
            "camera_to_world_convention": "columns: right, up, -forward, position (OpenGL: the camera looks down -z)",
            "world_frame": "z up, +x east, +y north; metres",
            "pixel_rays": "pixel (i, j) (column i from the left, row j from the top) looks along "
                          "normalize(forward + x tan(fov_x/2) right + y tan(fov_y/2) up), "
                          "x = 2 (i + 0.5)/width - 1, y = 1 - 2 (j + 0.5)/height",
        }


def camera_for_scene(camera, resolution: tuple[int, int]) -> Camera:
    """The scene's ``[camera]`` (position, target, horizontal fov) at ``resolution`` (width, height).

    The frame is Mitsuba's ``look_at`` with up = +z (+y when looking straight
    up or down), as :func:`oceanrender.render.scene.look_at_transform` builds it.
    """
    position = np.asarray(camera.position, dtype=np.float64)
    forward = np.asarray(camera.target, dtype=np.float64) - position
    forward /= np.linalg.norm(forward)
    up_hint = np.array([0.0, 0.0, 1.0]) if abs(forward[2]) < 0.999 else np.array([0.0, 1.0, 0.0])
    right = np.cross(forward, up_hint)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    width, height = resolution
    return Camera(position, forward, right, up, float(camera.fov), int(width), int(height))


@dataclass(frozen=True, eq=False)
class GBuffer:
    """Per-pixel geometry of one frame; every array is (height, width) or (height, width, 3).

    Attributes
    ----------
    kind : ndarray uint8       0 sky (no hit), 1 water surface, 2 land (seafloor/beach seen directly), 3 other.
    ray : ndarray              Unit camera-ray direction [-].
    position : ndarray         First hit [m]; 0 for sky.
    normal : ndarray           Shading normal at the hit, facing the camera [-]; 0 for sky.
    geo_normal : ndarray       Geometric (face) normal at the hit [-]; 0 for sky.
    distance : ndarray         Camera to hit [m]; inf for sky.
    cos_view : ndarray         n · v, v the unit vector to the camera, in [0, 1] [-].
    depth : ndarray            Water pixels: vertical depth h from the surface point to the seafloor [m],
                               inf without a seafloor (open sea); 0 elsewhere.
    path_length : ndarray      Water pixels: length l of the refracted ray to the seafloor [m], inf without
                               a seafloor; 0 elsewhere.
    refracted : ndarray        Water pixels: unit refracted direction; 0 elsewhere.
    bottom_position : ndarray  Water pixels: where the refracted ray meets the seafloor [m]; 0 elsewhere.
    rock : ndarray             Rock coverage in [0, 1] of the seafloor point (water) or of the hit (land) [-].
    roughness : ndarray        Water pixels: Beckmann α of the surface BSDF at the hit, where the mesh carries
                               it per vertex (the camera-following mesh: coarser far away, rougher) [-];
                               0 elsewhere and where the surface has one α (the LUT set's).
    foam : ndarray             Water pixels: fresh-foam coverage B in [0, 1] at the hit (the mesh's per-vertex
                               foam, as the renderer's blend of water and Lambertian foam reads it) [-]; 0 elsewhere.
    """

    kind: NDArray[np.uint8]
    ray: NDArray[np.float64]
    position: NDArray[np.float64]
    normal: NDArray[np.float64]
    geo_normal: NDArray[np.float64]
    distance: NDArray[np.float64]
    cos_view: NDArray[np.float64]
    depth: NDArray[np.float64]
    path_length: NDArray[np.float64]
    refracted: NDArray[np.float64]
    bottom_position: NDArray[np.float64]
    rock: NDArray[np.float64]
    roughness: NDArray[np.float64] | None = None
    foam: NDArray[np.float64] | None = None

    def __post_init__(self) -> None:
        for name in ("roughness", "foam"):
            if getattr(self, name) is None:
                object.__setattr__(self, name, np.zeros(self.kind.shape))

    @property
    def shape(self) -> tuple[int, int]:
        return self.kind.shape

    @property
    def view_angle(self) -> NDArray[np.float64]:
        """Angle between the normal and the direction to the camera [deg]."""
        return np.degrees(np.arccos(np.clip(self.cos_view, 0.0, 1.0)))

    @property
    def has_bottom(self) -> NDArray[np.bool_]:
        """Water pixels whose refracted ray ends on the seafloor."""
        return (self.kind == KIND_WATER) & np.isfinite(self.path_length)

    def channels(self) -> dict[str, NDArray[np.float32]]:
        """EXR channels (``P.X`` …): see :data:`CHANNEL_NOTES`."""
        out: dict[str, NDArray] = {}
        for prefix, array in (("P", self.position), ("N", self.normal), ("Ng", self.geo_normal), ("D", self.ray),
                              ("T", self.refracted), ("Pb", self.bottom_position)):
            for i, axis in enumerate("XYZ"):
                out[f"{prefix}.{axis}"] = array[..., i]
        out.update({"distance": self.distance, "cos_view": self.cos_view, "view_angle": self.view_angle,
                    "depth": self.depth, "path_length": self.path_length, "rock": self.rock,
                    "roughness": self.roughness, "foam": self.foam, "kind": self.kind.astype(np.float32)})
        return {k: np.asarray(v, dtype=np.float32) for k, v in out.items()}


#: What each G-buffer EXR channel holds (written into its metadata and the reference report).
CHANNEL_NOTES = {
    "P.X/Y/Z": "world position of the first hit [m] (0 for sky)",
    "N.X/Y/Z": "shading normal (interpolated vertex normals), facing the camera [-]",
    "Ng.X/Y/Z": "geometric (triangle) normal [-]",
    "D.X/Y/Z": "unit camera-ray direction through the pixel centre [-]",
    "T.X/Y/Z": "water pixels: unit refracted direction (Snell, n = water ior) [-]",
    "Pb.X/Y/Z": "water pixels: where the refracted ray meets the seafloor [m]",
    "distance": "camera to first hit [m] (inf for sky)",
    "cos_view": "cosine of the view angle, n . v [-]",
    "view_angle": "angle between the normal and the direction to the camera [deg]",
    "depth": "water pixels: vertical depth h of the water column under the surface point [m] (inf: no seafloor)",
    "path_length": "water pixels: in-water length l of the refracted ray to the seafloor [m] (inf: no seafloor)",
    "rock": "rock coverage of the seafloor (water pixels: at the refracted hit; land: at the hit) [-]",
    "roughness": "water pixels: Beckmann alpha of the surface at the hit where the mesh carries it per vertex [-]; "
                 "0: the LUT set's surface_roughness_alpha",
    "foam": "water pixels: fresh-foam coverage of the surface at the hit [-] (0: none)",
    "kind": "0 sky, 1 water surface, 2 land (seafloor/beach seen directly), 3 other",
}


def _shape_index(shapes_ptr) -> NDArray[np.uint32]:
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    return np.array(dr.reinterpret_array(mi.UInt32, shapes_ptr))


def _vectors(a: NDArray):
    import mitsuba as mi  # noqa: PLC0415

    return mi.Vector3f(*(jit_floats(a[:, k]) for k in range(3)))


def _numpy3(v) -> NDArray[np.float64]:
    return np.array(v, dtype=np.float64).T.reshape(-1, 3)


def trace_gbuffer(scene, camera: Camera, n_water: float, water_id: str = "water", bottom_id: str | None = "terrain",
                  rock_attribute: str = "vertex_rock", roughness_attribute: str = "vertex_roughness",
                  foam_attribute: str = "vertex_foam") -> GBuffer:
    """Cast the camera's pixel-centre rays into a loaded Mitsuba scene and fill a :class:`GBuffer`.

    Parameters
    ----------
    scene : mitsuba.Scene
        The scene the path tracer renders (with the frame's water mesh).
    camera : Camera
        The view (:func:`camera_for_scene`).
    n_water : float
        Refractive index of the water [-].
    water_id : str
        Mitsuba id of the water body.
    bottom_id : str or None
        Mitsuba id of the seafloor/terrain shape; None or absent: no seafloor (open sea).
    rock_attribute : str
        Per-vertex rock coverage attribute of the seafloor mesh, if it has one.
    roughness_attribute, foam_attribute : str
        Per-vertex Beckmann α and fresh-foam coverage attributes of the water mesh, if it has them.
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    shapes = {shape.id(): shape for shape in scene.shapes()}
    if water_id not in shapes:
        raise ValueError(f"the scene has no shape {water_id!r} (has {', '.join(shapes)})")
    index = {name: int(_shape_index(mi.ShapePtr(shape))[0]) for name, shape in shapes.items()}
    bottom = shapes.get(bottom_id) if bottom_id else None

    H, W = camera.height, camera.width
    d = camera.ray_directions().reshape(-1, 3)
    origin = np.broadcast_to(camera.position, d.shape)
    si = scene.ray_intersect(mi.Ray3f(_vectors(np.asarray(origin)), _vectors(d)))
    dr.eval(si)  # one kernel for every field read below
    hit = _shape_index(si.shape)
    valid = np.array(si.is_valid())
    kind = np.full(len(d), KIND_SKY, np.uint8)
    kind[valid] = KIND_OTHER
    kind[valid & (hit == index[water_id])] = KIND_WATER
    if bottom is not None:
        kind[valid & (hit == index[bottom_id])] = KIND_LAND

    position = np.where(valid[:, None], _numpy3(si.p), 0.0)
    geo = np.where(valid[:, None], _numpy3(si.n), 0.0)
    shading = np.where(valid[:, None], _numpy3(si.sh_frame.n), 0.0)
    facing = np.sum(shading * -d, axis=-1) > 0
    shading = np.where(facing[:, None], shading, np.where(np.sum(geo * -d, axis=-1, keepdims=True) > 0, geo, -geo))
    distance = np.where(valid, np.array(si.t, dtype=np.float64), np.inf)
    cos_view = np.clip(np.sum(shading * -d, axis=-1), 0.0, 1.0)

    water = kind == KIND_WATER
    water_shape = shapes[water_id]

    def water_attribute(name: str, top: float) -> NDArray:
        if not (water.any() and water_shape.has_attribute(name)):
            return np.zeros(len(d))
        values = np.array(water_shape.eval_attribute_1(name, si, jit_bools(water)), dtype=np.float64)
        return np.where(water, np.clip(np.nan_to_num(values), 0.0, top), 0.0)

    roughness = water_attribute(roughness_attribute, np.inf)
    foam = water_attribute(foam_attribute, 1.0)
    refracted = np.where(water[:, None], refract(d, shading, 1.0 / n_water), 0.0)
    refracted = np.nan_to_num(refracted)
    depth = np.where(water, np.inf, 0.0)
    path = np.where(water, np.inf, 0.0)
    bottom_position = np.zeros_like(position)
    rock = np.zeros(len(d))
    if bottom is not None:
        has_attribute = bool(bottom.has_attribute(rock_attribute))

        def coverage(interaction, active: NDArray) -> NDArray:
            if not has_attribute or not active.any():
                return np.zeros(len(active))
            values = np.array(bottom.eval_attribute_1(rock_attribute, interaction, jit_bools(active)), dtype=np.float64)
            return np.where(active, np.clip(np.nan_to_num(values), 0.0, 1.0), 0.0)

        land = kind == KIND_LAND
        rock = coverage(si, land)
        # The refracted view ray to the seafloor (l) and the vertical ray (h), from just below the surface.
        si_b = scene.ray_intersect(si.spawn_ray(_vectors(np.where(water[:, None], refracted, d))))
        dr.eval(si_b)
        on_floor = water & np.array(si_b.is_valid()) & (_shape_index(si_b.shape) == index[bottom_id])
        path = np.where(on_floor, np.array(si_b.t, dtype=np.float64), path)
        bottom_position = np.where(on_floor[:, None], _numpy3(si_b.p), 0.0)
        rock = np.where(on_floor, coverage(si_b, on_floor), rock)
        down = np.broadcast_to(np.array([0.0, 0.0, -1.0]), d.shape)
        si_v = scene.ray_intersect(si.spawn_ray(_vectors(np.asarray(down))))
        dr.eval(si_v)
        below = water & np.array(si_v.is_valid()) & (_shape_index(si_v.shape) == index[bottom_id])
        depth = np.where(below, np.array(si_v.t, dtype=np.float64), depth)

    def image(a: NDArray) -> NDArray:
        return a.reshape((H, W) + a.shape[1:])

    return GBuffer(kind=image(kind), ray=image(d), position=image(position), normal=image(shading),
                   geo_normal=image(geo), distance=image(distance), cos_view=image(cos_view), depth=image(depth),
                   path_length=image(path), refracted=image(refracted), bottom_position=image(bottom_position),
                   rock=image(rock), roughness=image(roughness), foam=image(foam))
