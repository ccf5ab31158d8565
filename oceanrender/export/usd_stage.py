"""The animated sea as a USD stage (``oceanrender geometry SCENE --usd FILE``), for Blender, Houdini, Nuke.

One stage (Pixar's USD through ``usd-core``: ``.usda`` text, ``.usdc``/``.usd`` binary)
holding, in metres with Z up (``metersPerUnit = 1``, ``upAxis = "Z"``) and one time code
per frame (``timeCodesPerSecond`` = the scene's fps):

* ``/World/Sea``: the water surface around the camera as a grid of quads, the same
  topology every frame; its points (rest point + choppy displacement, height above the
  still level) and vertex normals are time-sampled per frame. Waves finer than the grid
  are filtered out (the sea's own level-of-detail, :mod:`oceanrender.waves.lod`), so the
  grid does not alias; moving objects' wakes are included.
* ``/World/Camera``: the scene's camera (its path, if animated): a ``UsdGeom.Camera``
  with the horizontal field of view as a 36 mm aperture and its focal length.
* ``/World/Sun``: a ``UsdLux.DistantLight`` pointing along the sunlight (0.53° wide),
  time-sampled if the sun moves; its intensity is not calibrated (the renderer's sun is
  ``sunsky``'s): the direction is what it carries, with the elevation and azimuth as
  ``oceanrender:`` attributes.
* ``/World/Objects/<name>``: each ``[[objects]]`` mesh with its points posed per frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..scene import Scene

__all__ = ["USD_SUFFIXES", "SeaGrid", "sea_grid", "write_usd_stage"]

#: File suffixes USD writes (text, binary crate, either).
USD_SUFFIXES = (".usda", ".usdc", ".usd")
#: Horizontal film aperture of the exported camera [mm] (a full-frame 35 mm still camera).
APERTURE_MM = 36.0


@dataclass(frozen=True)
class SeaGrid:
    """A square grid of rest points (N, N) centred at ``centre`` [m], ``extent`` wide [m]."""

    centre: tuple[float, float]
    extent: float
    points: int

    @property
    def spacing(self) -> float:
        return self.extent / (self.points - 1)

    def rest_points(self) -> tuple[NDArray, NDArray]:
        """x, y (N², ) of the grid, row by row [m]."""
        axis = np.linspace(-0.5 * self.extent, 0.5 * self.extent, self.points)
        x, y = np.meshgrid(self.centre[0] + axis, self.centre[1] + axis, indexing="xy")
        return x.ravel(), y.ravel()

    def quads(self) -> NDArray[np.int64]:
        """(Q, 4) vertex indices of the quads, counter-clockwise seen from above."""
        n = self.points
        i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="xy")
        a = (j * n + i).ravel()
        return np.stack([a, a + 1, a + n + 1, a + n], -1)


def sea_grid(scene: Scene, extent: float, points: int) -> SeaGrid:
    """The exported grid: ``extent`` [m] wide with ``points`` per side, centred under the camera at the first frame."""
    if not (math.isfinite(extent) and extent > 0):
        raise ValueError(f"extent: expected a width > 0 [m], got {extent!r}")
    if not 2 <= int(points) <= 4096:
        raise ValueError(f"points: expected 2 to 4096 per side, got {points!r}")
    from ..scene.motion import camera_motion, static_camera_pose  # noqa: PLC0415

    path = camera_motion(scene)
    start = scene.output.frames[0] / scene.output.fps
    position = path.at(start).position if path is not None else static_camera_pose(scene).position
    return SeaGrid((float(position[0]), float(position[1])), float(extent), int(points))


def _look_at_matrix(position, target):
    """USD (row-vector) matrix of a camera at ``position`` looking at ``target``, z up: −Z forward, +Y up."""
    from pxr import Gf  # noqa: PLC0415

    p, t = np.asarray(position, float), np.asarray(target, float)
    back = p - t
    back /= np.linalg.norm(back)
    up_world = np.array([0.0, 0.0, 1.0]) if abs(back[2]) < 0.999 else np.array([0.0, 1.0, 0.0])
    right = np.cross(up_world, back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    return Gf.Matrix4d(*right, 0.0, *up, 0.0, *back, 0.0, *p, 1.0)


def _sun_matrix(direction):
    """Rotation whose local +Z is ``direction`` (towards the sun): a DistantLight shines along local −Z."""
    from pxr import Gf  # noqa: PLC0415

    z = np.asarray(direction, float) / np.linalg.norm(direction)
    helper = np.array([0.0, 0.0, 1.0]) if abs(z[2]) < 0.999 else np.array([1.0, 0.0, 0.0])
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    return Gf.Matrix4d(*x, 0.0, *y, 0.0, *z, 0.0, 0.0, 0.0, 0.0, 1.0)


def write_usd_stage(scene: Scene, path: str | Path, grid: SeaGrid, frames: range) -> dict[str, int]:
    """Write the animated stage (module docstring) for ``frames`` to ``path``; counts of what it holds."""
    from pxr import Sdf, Usd, UsdGeom, UsdLux, Vt  # noqa: PLC0415

    from ..io.frames import atomic_path  # noqa: PLC0415
    from ..render.scene import sun_direction  # noqa: PLC0415
    from ..scene.motion import camera_motion, static_camera_pose, sun_motion  # noqa: PLC0415
    from ..surface.objects import SceneObjects, scene_sea  # noqa: PLC0415

    path = Path(path)
    fps = scene.output.fps
    sea = scene_sea(scene)
    objects = SceneObjects(scene, sea)
    camera_path, sun_path = camera_motion(scene), sun_motion(scene)
    x, y = grid.rest_points()
    spacing = np.full(x.shape, grid.spacing)
    with atomic_path(path, path.suffix) as tmp:
        stage = Usd.Stage.CreateNew(str(tmp))
        UsdGeom.SetStageMetersPerUnit(stage, 1.0)
        UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
        stage.SetTimeCodesPerSecond(fps)
        stage.SetFramesPerSecond(fps)
        stage.SetStartTimeCode(frames.start)
        stage.SetEndTimeCode(frames.stop - 1)
        world = UsdGeom.Xform.Define(stage, "/World")
        stage.SetDefaultPrim(world.GetPrim())

        mesh = UsdGeom.Mesh.Define(stage, "/World/Sea")
        quads = grid.quads()
        mesh.CreateFaceVertexCountsAttr(Vt.IntArray([4] * len(quads)))
        mesh.CreateFaceVertexIndicesAttr(Vt.IntArray(quads.ravel().tolist()))
        mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
        mesh.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
        points_attr, normals_attr = mesh.CreatePointsAttr(), mesh.CreateNormalsAttr()
        camera = UsdGeom.Camera.Define(stage, "/World/Camera")
        camera.CreateHorizontalApertureAttr(APERTURE_MM)
        camera_xform = camera.AddTransformOp()
        focal = camera.CreateFocalLengthAttr()
        camera.CreateClippingRangeAttr().Set((0.01, 1.0e7))
        sun = UsdLux.DistantLight.Define(stage, "/World/Sun")
        sun.CreateAngleAttr(0.53)
        sun_xform = sun.AddTransformOp()
        elevation_attr = sun.GetPrim().CreateAttribute("oceanrender:sun_elevation_deg", Sdf.ValueTypeNames.Double)
        azimuth_attr = sun.GetPrim().CreateAttribute("oceanrender:sun_azimuth_deg", Sdf.ValueTypeNames.Double)
        object_meshes = {}
        for obj, object_mesh in objects.items:
            prim = UsdGeom.Mesh.Define(stage, f"/World/Objects/{obj.name}")
            prim.CreateFaceVertexCountsAttr(Vt.IntArray([3] * len(object_mesh.faces)))
            prim.CreateFaceVertexIndicesAttr(Vt.IntArray(object_mesh.faces.ravel().tolist()))
            prim.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
            object_meshes[obj.name] = prim.CreatePointsAttr()

        for frame in frames:
            t = frame / fps
            surface = sea.sample(x, y, t, spacing)
            d = surface.displacement
            points = np.stack([x + d[:, 0], y + d[:, 1], d[:, 2]], -1)
            points_attr.Set(Vt.Vec3fArray.FromNumpy(points.astype(np.float32)), frame)
            normals_attr.Set(Vt.Vec3fArray.FromNumpy(surface.normals.astype(np.float32)), frame)
            pose = camera_path.at(t) if camera_path is not None else static_camera_pose(scene)
            camera_xform.Set(_look_at_matrix(pose.position, pose.target), frame)
            focal.Set(0.5 * APERTURE_MM / math.tan(math.radians(0.5 * pose.fov)), frame)
            angles = sun_path.at(t) if sun_path is not None else None
            elevation = angles.elevation if angles is not None else scene.sun.elevation
            azimuth = angles.azimuth if angles is not None else scene.sun.azimuth
            sun_xform.Set(_sun_matrix(sun_direction(elevation, azimuth)), frame)
            elevation_attr.Set(float(elevation), frame)
            azimuth_attr.Set(float(azimuth), frame)
            for geometry in objects.frame(t):
                object_meshes[geometry.name].Set(Vt.Vec3fArray.FromNumpy(geometry.positions.astype(np.float32)),
                                                 frame)
        stage.GetRootLayer().Save()
    return {"frames": len(frames), "points": len(x), "quads": len(quads), "objects": len(object_meshes)}
