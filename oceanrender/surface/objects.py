"""The scene's ``[[objects]]`` per frame: their meshes posed in the world, and the wakes they leave.

An object's pose at time t: its origin moves along its heading at its speed from
``position`` (at t = 0); its attitude is heading, then pitch (bow up), then roll
(starboard down), R = R_z(heading) R_y(−pitch) R_x(roll) in the mesh frame (x forward,
y left, z up). A floating object takes heave, pitch and roll from the sea
(:func:`~oceanrender.waves.floating.floating_pose`); a moving one that reaches into the
water leaves a Kelvin wake (:mod:`oceanrender.waves.wakes`), added to the sea the
water body is built from. Everything is a function of t alone.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..io.meshes import TriangleMesh, read_mesh
from ..scene import ObjectSettings, Scene
from ..waves.floating import floating_pose, footprint
from ..waves.sea import SeaSurface
from ..waves.wakes import ShipWake, ship_wake, submerged_source

__all__ = ["ObjectGeometry", "SceneObjects", "attitude_matrix", "object_centre", "scene_sea", "scene_wakes"]

#: Finest wave a floating hull feels, as a fraction of its waterline length [-]: shorter waves average out.
FLOAT_SPACING_FRACTION = 0.125


@dataclass(frozen=True)
class ObjectGeometry:
    """One object at one time: vertex positions (V, 3) [m] in the world and its faces (F, 3)."""

    name: str
    positions: NDArray[np.float64]
    faces: NDArray[np.int64]
    uv: NDArray[np.float64] | None


def attitude_matrix(heading_deg: float, pitch_deg: float, roll_deg: float) -> NDArray[np.float64]:
    """Rotation from the mesh frame (x forward, y left, z up) to the world (x east, y north, z up) [-]."""
    h, p, r = (math.radians(v) for v in (heading_deg, pitch_deg, roll_deg))
    yaw = np.array([[math.sin(h), -math.cos(h), 0.0], [math.cos(h), math.sin(h), 0.0], [0.0, 0.0, 1.0]])
    pitch = np.array([[math.cos(p), 0.0, -math.sin(p)], [0.0, 1.0, 0.0], [math.sin(p), 0.0, math.cos(p)]])
    roll = np.array([[1.0, 0.0, 0.0], [0.0, math.cos(r), -math.sin(r)], [0.0, math.sin(r), math.cos(r)]])
    return yaw @ pitch @ roll


@functools.lru_cache(maxsize=64)
def _mesh(path: str) -> TriangleMesh:
    """An object's mesh, read once per process (the wakes and the posed objects both need it)."""
    return read_mesh(path)


def object_centre(obj: ObjectSettings):
    """t [s] → (x, y) of the object's origin [m]: ``position`` at t = 0, moving along the heading at ``speed``."""
    h = math.radians(obj.heading)
    start = np.array(obj.position[:2], dtype=float)
    velocity = obj.speed * np.array([math.sin(h), math.cos(h)])
    return lambda t: start + velocity * float(t)


def scene_wakes(scene: Scene) -> tuple[ShipWake, ...]:
    """The Kelvin wakes of the scene's moving objects that reach into the water (``wake = true``, speed > 0)."""
    wakes = []
    for obj in scene.objects:
        if not obj.wake or obj.speed <= 0:
            continue
        source = submerged_source(obj.scale * _mesh(obj.mesh).vertices, -obj.position[2])
        if source is not None:
            wakes.append(ship_wake(source, obj.speed, scene.ocean.wave_depth, obj.heading, object_centre(obj)))
    return tuple(wakes)


def _hull_footprint(obj: ObjectSettings, mesh: TriangleMesh) -> tuple[NDArray, float]:
    """(sample points (P, 2) over the submerged part's footprint [m], the finest wave it feels [m])."""
    vertices = obj.scale * mesh.vertices
    below = vertices[vertices[:, 2] < -obj.position[2]]
    lo, hi = below[:, :2].min(axis=0), below[:, :2].max(axis=0)
    return footprint((lo[0], hi[0]), (lo[1], hi[1])), FLOAT_SPACING_FRACTION * float(hi[0] - lo[0])


def scene_sea(scene: Scene) -> SeaSurface:
    """The scene's open sea with the wakes of its moving objects: what the water body, probes and exports read."""
    return SeaSurface(scene.ocean, scene_wakes(scene))


class SceneObjects:
    """The scene's objects, read once; :meth:`frame` poses them at a time."""

    def __init__(self, scene: Scene, sea: SeaSurface | None):
        self.items: list[tuple[ObjectSettings, TriangleMesh]] = [(o, _mesh(o.mesh)) for o in scene.objects]
        self.sea = sea
        self._hulls = {o.name: _hull_footprint(o, m) for o, m in self.items if o.floating}
        self._last: tuple[float, list[ObjectGeometry]] | None = None  # a frame is posed once (meter, render)

    def pose(self, obj: ObjectSettings, mesh: TriangleMesh, t: float) -> tuple[NDArray, NDArray]:
        """(rotation (3, 3), translation (3,) [m]) of ``obj`` at time t [s]."""
        centre = object_centre(obj)
        z, pitch, roll = obj.position[2], obj.pitch, obj.roll
        if obj.floating and self.sea is not None:
            points, spacing = self._hulls[obj.name]
            state = floating_pose(self.sea, points, centre, obj.heading, t, obj.response_time, spacing)
            z, pitch, roll = obj.position[2] + state.heave, state.pitch, state.roll
        return attitude_matrix(obj.heading, pitch, roll), np.array([*centre(t), z])

    def frame(self, t: float) -> list[ObjectGeometry]:
        """Every object posed at time t [s]."""
        if self._last is not None and self._last[0] == t:
            return self._last[1]
        out = []
        for obj, mesh in self.items:
            rotation, translation = self.pose(obj, mesh, t)
            positions = (obj.scale * mesh.vertices) @ rotation.T + translation
            out.append(ObjectGeometry(obj.name, positions, mesh.faces, mesh.uv))
        self._last = (t, out)
        return out
