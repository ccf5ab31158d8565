"""Renders of the default sea from several heights, and the horizon check.

Run: ``.venv/bin/python scripts/horizon_views.py [--spp N] [--resolution WxH] [--out DIR]``.
Renders ``scenes/open_ocean.toml`` frame 0 from 2 m, 30 m and 150 m (looking
down 4°, 8° and 12°) and, looking level, from 1 m, 30 m and 1 km, into
``--out`` (default docs/images/) as ``view_<h>m.png``/``horizon_<h>m.png``,
and prints for each level view the luminance of the rows at the horizon
(:func:`horizon_rows`): a gap line between the sea and the sky would show as
a row darker than both.
"""

from __future__ import annotations

import argparse
import math
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

VIEWS = {"view_2m": (2.0, 4.0), "view_30m": (30.0, 8.0), "view_150m": (150.0, 12.0),
         "horizon_1m": (1.0, 0.0), "horizon_30m": (30.0, 0.0), "horizon_1000m": (1000.0, 0.0)}


def camera(height: float, down_deg: float) -> dict:
    """Camera ``height`` [m] up at the origin looking north, ``down_deg`` below the horizontal [deg]."""
    reach = 1000.0
    return {"position": [0.0, 0.0, height],
            "target": [0.0, reach, height - reach * math.tan(math.radians(down_deg))]}


def horizon_rows(luminance: np.ndarray, half_height: int = 3) -> dict:
    """Mean luminance [cd m⁻²] of the rows around the centre row (the horizon of a level camera).

    Returns the centre rows' minimum against the mean of the ``half_height``
    rows just above (sky) and just below (sea): ``dip`` < 1 means a row darker
    than both sides, i.e. a gap line.
    """
    rows = luminance.mean(axis=1)
    c = len(rows) // 2
    sky = rows[c - 1 - half_height: c - 1].mean()
    sea = rows[c + 1: c + 1 + half_height].mean()
    centre = rows[c - 1: c + 1].min()
    return {"sky": float(sky), "sea": float(sea), "horizon_min": float(centre), "dip": float(centre / min(sky, sea))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spp", type=int, default=32)
    parser.add_argument("--resolution", default="480x270")
    parser.add_argument("--out", default=str(ROOT / "docs" / "images"))
    parser.add_argument("--only", nargs="*", default=list(VIEWS))
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "open_ocean.toml"))
    args = parser.parse_args()
    from oceanrender.io.frames import read_exr
    from oceanrender.pipeline import STAGES, Sequence, frame_paths
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene, with_overrides

    width, height = (int(v) for v in args.resolution.split("x"))
    base = load_scene(args.scene)
    runtime = activate_variant(base.render.variant)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for name in args.only:
        h, down = VIEWS[name]
        scene = with_overrides(base, camera=camera(h, down))
        sequence = Sequence(scene, runtime.variant, spp=args.spp, resolution=(width, height))
        with tempfile.TemporaryDirectory() as tmp:
            paths = frame_paths(tmp, 0)
            sequence.render_frame(0, paths, {s: 0.0 for s in STAGES})
            channels, _ = read_exr(paths.exr)
            (out / f"{name}.png").write_bytes(paths.png.read_bytes())
        line = f"{name}: camera {h:g} m, {down:g} deg down"
        if down == 0:
            rows = horizon_rows(channels["Y"])
            line += (f"; rows at the horizon: sky {rows['sky']:.0f}, sea {rows['sea']:.0f}, "
                     f"darkest centre row {rows['horizon_min']:.0f} cd/m2 (dip {rows['dip']:.3f})")
        print(line, flush=True)


if __name__ == "__main__":
    main()
