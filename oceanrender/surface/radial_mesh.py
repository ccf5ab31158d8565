"""A camera-centred radial water body with a fixed triangulation.

The sea seen from a few metres needs centimetre detail under the camera and
kilometres of surface towards the horizon. A polar grid whose ring radii grow
geometrically does both with a fixed number of vertices: its cells stay
roughly square (Δr ≈ r·Δθ) and their size grows in proportion to the distance
from the centre, which is how a perspective camera's pixel footprint grows.
This is the idea of the dissertation's camera-following mesh with a fixed
triangulation (ch. 3): the topology never changes, only the vertices move with
the waves sampled at their rest positions.

The body is closed for Mitsuba's dielectric + medium: a top surface (centre
vertex + rings), a skirt below the outer ring down to ``depth``, and a flat
bottom fan. z up; lengths in m.

The horizon. Seen from a height h, a flat sea that ends at radius R leaves a
gap of atan(h/R) between its edge and the horizon (0° elevation), where the
sky model is black below the horizon: from 30 m, an 8 km mesh leaves 0.21°,
a dark line a pixel or two high. :func:`horizon_radius` puts one more, flat
ring far enough out that the gap is :data:`HORIZON_GAP_DEG` (a fraction of a
pixel at any usual resolution); the waves have faded into the surface
roughness long before (:mod:`oceanrender.waves.lod`), so this ring only
continues the sea's mean appearance. The Earth is flat here: the sky model
(Hosek & Wilkie 2012) is defined above 0° elevation only, so the sea meets it
there rather than at the geometric dip sqrt(2h/R_E) of a curved Earth.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray


@dataclass(frozen=True)
class RadialGrid:
    """Rest positions of the top surface: a centre vertex and ``rings`` rings.

    Parameters
    ----------
    center : (float, float)
        Horizontal centre (under the camera) [m].
    inner_radius : float
        Radius of the first ring [m].
    outer_radius : float
        Radius of the last ring [m].
    rings : int
        Number of rings [-] (≥ 2).
    segments : int
        Vertices per ring [-] (≥ 3).
    """

    center: tuple[float, float]
    inner_radius: float
    outer_radius: float
    rings: int
    segments: int

    def __post_init__(self) -> None:
        if not 0 < self.inner_radius < self.outer_radius:
            raise ValueError(f"radii must satisfy 0 < inner < outer [m], got {self.inner_radius}, {self.outer_radius}")
        if self.rings < 2 or self.segments < 3:
            raise ValueError(f"need rings ≥ 2 and segments ≥ 3, got {self.rings}, {self.segments}")

    @classmethod
    def square_cells(cls, center: tuple[float, float], inner_radius: float, outer_radius: float,
                     segments: int) -> "RadialGrid":
        """The grid whose ring ratio q makes cells square: q − 1 = 2π/segments."""
        ratio = 1.0 + 2.0 * np.pi / segments
        rings = int(np.ceil(np.log(outer_radius / inner_radius) / np.log(ratio))) + 1
        return cls(center, inner_radius, outer_radius, max(rings, 2), segments)

    @cached_property
    def radii(self) -> NDArray[np.float64]:
        """Ring radii r_j = r_in (r_out/r_in)^{j/(rings−1)} [m]."""
        return self.inner_radius * (self.outer_radius / self.inner_radius) ** np.linspace(0.0, 1.0, self.rings)

    @cached_property
    def points(self) -> NDArray[np.float64]:
        """Rest positions (V_top, 2) [m]: the centre, then ring by ring."""
        theta = 2.0 * np.pi * np.arange(self.segments) / self.segments
        ring = self.radii[:, None]
        xy = np.stack([ring * np.cos(theta), ring * np.sin(theta)], axis=-1).reshape(-1, 2)
        return np.vstack([[0.0, 0.0], xy]) + np.asarray(self.center, dtype=float)

    @cached_property
    def spacing(self) -> NDArray[np.float64]:
        """Local vertex spacing (V_top,) [m]: the larger of the radial and angular steps."""
        radial = np.gradient(self.radii)
        angular = 2.0 * np.pi * self.radii / self.segments
        per_ring = np.maximum(radial, angular)
        return np.concatenate([[self.inner_radius], np.repeat(per_ring, self.segments)])

    @property
    def top_vertex_count(self) -> int:
        return 1 + self.rings * self.segments


#: Largest angle between the horizon and the far edge of the sea, seen from the camera [deg]
#: (a 1280 px wide, 60° frame has 0.047° pixels).
HORIZON_GAP_DEG = 0.005


def horizon_radius(camera_height: float, outer_radius: float, segments: int) -> float:
    """Radius of the flat far ring [m]: h / (tan(gap) cos(π/segments)), at least twice ``outer_radius``.

    Parameters
    ----------
    camera_height : float   Height of the camera above the mean sea level [m] (≤ 0: under water).
    outer_radius : float    Radius of the last wave-carrying ring [m].
    segments : int          Vertices of the ring [-]: its edges' midpoints are cos(π/segments) nearer.
    """
    reach = max(camera_height, 0.0) / (np.tan(np.radians(HORIZON_GAP_DEG)) * np.cos(np.pi / segments))
    return float(max(2.0 * outer_radius, reach))


def radial_body_faces(rings: int, segments: int) -> NDArray[np.uint32]:
    """Triangles of the closed radial body, outward-facing (counter-clockwise seen from outside).

    Vertex layout: top centre (0), top rings (1 … rings·segments), skirt ring
    at the bottom (segments vertices), bottom centre (last).
    """
    s = segments
    j = np.arange(s)
    jn = (j + 1) % s
    faces = [np.stack([np.zeros(s, int), 1 + j, 1 + jn], axis=1)]  # centre fan, +z
    r = np.arange(rings - 1)[:, None]
    a = 1 + r * s + j  # ring r, segment j
    b = 1 + r * s + jn
    c = 1 + (r + 1) * s + j
    d = 1 + (r + 1) * s + jn
    faces.append(np.stack([a, c, d], axis=-1).reshape(-1, 3))
    faces.append(np.stack([a, d, b], axis=-1).reshape(-1, 3))
    top_outer = 1 + (rings - 1) * s + j
    top_outer_next = 1 + (rings - 1) * s + jn
    skirt = 1 + rings * s + j
    skirt_next = 1 + rings * s + jn
    faces.append(np.stack([top_outer, skirt, skirt_next], axis=1))  # outward (radial) walls
    faces.append(np.stack([top_outer, skirt_next, top_outer_next], axis=1))
    bottom = 1 + rings * s + s
    faces.append(np.stack([np.full(s, bottom), skirt_next, skirt], axis=1))  # −z
    return np.concatenate(faces).astype(np.uint32)


def radial_body_vertices(grid: RadialGrid, displacement: NDArray, normals: NDArray, depth: float,
                         far_radius: float | None = None) -> tuple[NDArray[np.float32], NDArray[np.float32]]:
    """Positions and normals of the closed body from the surface sampled at the rest points.

    With ``far_radius`` [m] a flat ring at that radius (z = 0, normals +z)
    follows the grid's rings: the faces are then those of ``grid.rings + 1`` rings.

    Parameters
    ----------
    grid : RadialGrid
    displacement : (V_top, 3) array
        (dx, dy, η) at ``grid.points`` [m].
    normals : (V_top, 3) array
        Unit normals of the displaced surface there.
    depth : float
        Depth of the flat bottom below z = 0 [m]; must clear the lowest trough.
    """
    top = np.column_stack([grid.points + displacement[:, :2], displacement[:, 2]])
    if not depth > 0 or -depth >= top[:, 2].min():
        raise ValueError(f"depth must be > 0 and below the deepest trough ({-top[:, 2].min():.3f} m), got {depth}")
    if far_radius is not None:
        theta = 2.0 * np.pi * np.arange(grid.segments) / grid.segments
        far = np.column_stack([far_radius * np.cos(theta) + grid.center[0], far_radius * np.sin(theta) + grid.center[1],
                               np.zeros(grid.segments)])
        top = np.vstack([top, far])
        normals = np.vstack([normals, np.tile([0.0, 0.0, 1.0], (grid.segments, 1))])
    outer = top[-grid.segments:]
    skirt = np.column_stack([outer[:, :2], np.full(grid.segments, -depth)])
    bottom = np.array([[*outer[:, :2].mean(axis=0), -depth]])
    positions = np.vstack([top, skirt, bottom]).astype(np.float32)
    down = np.tile([0.0, 0.0, -1.0], (grid.segments + 1, 1))
    return positions, np.vstack([normals, down]).astype(np.float32)
