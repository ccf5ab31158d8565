"""Write the example meshes of ``scenes/boat.toml``: a small motor boat and a mooring buoy (PLY).

Run from the repository root::

    python scripts/make_boat.py

Both are made here (no third-party model, so no licence to track); the repository's
licence covers them. Frame of each mesh: x forward (the bow), y to the left, z up, metres,
origin on the still waterline.

* ``scenes/meshes/boat.ply``: 12 m long, 4 m beam, 0.8 m draft, 1.2 m freeboard; the hull is
  the convex hull of 13 cross sections (a fine bow, a full stern), with a 4.2 × 2.6 × 1.6 m
  cabin on the deck: two closed surfaces.
* ``scenes/meshes/buoy.ply``: a sphere of 0.6 m radius (an icosphere, 3 subdivisions).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh

OUT = Path(__file__).resolve().parents[1] / "scenes" / "meshes"
LENGTH, BEAM, DRAFT, FREEBOARD = 12.0, 4.0, 0.8, 1.2


def hull() -> trimesh.Trimesh:
    """Convex hull of cross sections x ∈ [−L/2, L/2] [m]: half-beam and keel depth taper to the bow."""
    points = []
    for x in np.linspace(-LENGTH / 2, LENGTH / 2, 13):
        t = (x + LENGTH / 2) / LENGTH  # 0 at the stern, 1 at the bow
        half = 0.5 * BEAM * (1.0 - max(t - 0.55, 0.0) ** 1.6 / 0.45**1.6 * 0.97)
        keel = DRAFT * (1.0 - 0.6 * max(t - 0.7, 0.0) / 0.3)
        sheer = FREEBOARD + 0.35 * max(t - 0.6, 0.0) / 0.4  # the deck rises towards the bow
        for y, z in ((half, sheer), (0.85 * half, 0.0), (0.45 * half, -0.8 * keel), (0.0, -keel)):
            points += [(x, y, z), (x, -y, z)]
    return trimesh.convex.convex_hull(np.array(points))


def cabin() -> trimesh.Trimesh:
    box = trimesh.creation.box(extents=(4.2, 2.6, 1.6))
    box.apply_translation((-1.2, 0.0, FREEBOARD + 0.8 - 0.05))
    return box


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    boat = trimesh.util.concatenate([hull(), cabin()])
    boat.export(OUT / "boat.ply")
    trimesh.creation.icosphere(subdivisions=3, radius=0.6).export(OUT / "buoy.ply")
    print(f"wrote {OUT / 'boat.ply'} ({len(boat.faces)} triangles) and {OUT / 'buoy.ply'}")


if __name__ == "__main__":
    main()
