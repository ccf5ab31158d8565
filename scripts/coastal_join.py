"""Measure the join of the coast and the open sea of a scene (docs/coastal.md, "The coast inside the open sea").

Usage: .venv/bin/python scripts/coastal_join.py SCENE STORE [FRAME ...]

SCENE has ``[coastal] waves = "open sea"``; STORE is its simulation store (``<out>/<name>/coastal``).
For each frame it prints, along the offshore side (201 points, the lateral blend zones excluded):

* the height and slope jumps between points 1 mm inside and 1 mm outside the grid (continuity);
* the rms and largest difference η_S − η_L the blend zone cross-fades (what the solver made of the
  sea's long waves at the side), against the long waves' rms height;
* the rms slope of the joined surface and of the FFT sea alone in bands of distance from the side
  (a seam would show as a spike or a step).

All lengths in m; slopes dimensionless.
"""

from __future__ import annotations

import sys

import numpy as np

from oceanrender.scene import load_scene
from oceanrender.surface.coast_in_sea import CoastInSea


def offshore_line(body: CoastInSea, distance: float, count: int = 201):
    """World points at ``distance`` [m] outside (> 0) or inside (< 0) the offshore side, off the lateral blends."""
    c, frame = body.coastal, body.domain
    lx, ly = frame.size
    along = np.linspace(c.blend_width, (lx if c.offshore_side in ("north", "south") else ly) - c.blend_width, count)
    across = {"north": ly + distance, "south": -distance, "east": lx + distance, "west": -distance}[c.offshore_side]
    if c.offshore_side in ("north", "south"):
        return frame.to_world(along, np.full(count, across))
    return frame.to_world(np.full(count, across), along)


def measure(body: CoastInSea, frame: int) -> dict[str, float]:
    t = frame / body.scene.output.fps
    x_in, y_in = offshore_line(body, -1e-3)
    x_out, y_out = offshore_line(body, 1e-3)
    d_in, s_in, _ = body.surface_at(x_in, y_in, t)
    d_out, s_out, _ = body.surface_at(x_out, y_out, t)
    out = {"height jump max [mm]": 1e3 * float(np.abs(d_in[:, 2] - d_out[:, 2]).max()),
           "slope jump max": float(np.abs(s_in - s_out).max())}
    mismatch, long = [], []
    for distance in np.linspace(-body.coastal.blend_width, 0.0, 9):
        x, y = offshore_line(body, distance)
        g = body.geometry(x, y)
        eta_l = body.modes.fields(x, y, t)[0]
        eta_s = body.solver_fields(t, x, y, g.terrain)[0]
        mismatch.append(eta_s - g.tau_l * eta_l)
        long.append(eta_l)
    mismatch, long = np.concatenate(mismatch), np.concatenate(long)
    out["blend: rms(η_S − η_L) [m]"] = float(np.sqrt(np.mean(mismatch**2)))
    out["blend: max|η_S − η_L| [m]"] = float(np.abs(mismatch).max())
    out["long waves rms [m]"] = float(np.sqrt(np.mean(long**2)))
    for lo, hi in ((-40, -20), (-20, -5), (-5, 5), (5, 20), (20, 40)):
        joined, sea = [], []
        for distance in np.linspace(lo, hi, 5):
            x, y = offshore_line(body, distance)
            joined.append(body.surface_at(x, y, t)[1])
            n = body.sea_body.sea.sample(x, y, t).normals
            sea.append(-n[:, :2] / n[:, 2:3])
        joined, sea = np.concatenate(joined), np.concatenate(sea)
        out[f"rms slope {lo:+d}..{hi:+d} m: joined / sea"] = (float(np.sqrt(np.mean(np.sum(joined**2, 1)))),
                                                            float(np.sqrt(np.mean(np.sum(sea**2, 1)))))
    return out


def main(argv: list[str]) -> int:
    if len(argv) < 2:
        print(__doc__)
        return 2
    scene = load_scene(argv[0])
    body = CoastInSea(scene, argv[1])
    frames = [int(f) for f in argv[2:]] or [scene.output.frames[0]]
    for frame in frames:
        print(f"frame {frame}")
        for key, value in measure(body, frame).items():
            shown = " / ".join(f"{v:.4g}" for v in value) if isinstance(value, tuple) else f"{value:.4g}"
            print(f"  {key}: {shown}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
