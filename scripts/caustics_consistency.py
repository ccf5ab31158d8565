"""Issue 41: a frame's water with the sun's beam traced onto the floor, against the path tracer alone.

Renders frame 0 of ``--scene`` at ``--size``, ``--seeds`` times at ``--spp`` (seeds 0, 1, ...), once
with ``[render] caustic_cell = 0`` (the unbiased path tracer) and once per ``--cells`` value (the
floor's or the terrain's map, docs/sunlight.md). Per seed: the mean luminance Y [cd m⁻²] over the
pixels whose camera ray meets the water's upper surface first (what is seen through the water). Prints
one JSON line per setting: the mean over seeds, its ratio to the path tracer's and the ratio's
standard error from the seeds' spread (both settings' spreads, independent seeds).

Usage: python scripts/caustics_consistency.py [--scene scenes/coastal_beach.toml] [--size 80x45]
       [--spp 64] [--seeds 24] [--cells 0.02] [--set section.key=value ...]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def water_pixels(renderer, size) -> np.ndarray:
    """(H, W) bool: pixels whose centre's camera ray meets the water's upper surface first."""
    from oceanrender.render.renderer import WATER_ID
    from oceanrender.render.sun_beam import camera_water_hits

    water = next(shape for shape in renderer.scene.shapes() if shape.id() == WATER_ID)
    return camera_water_hits(renderer.scene, water, *size)[0]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "coastal_beach.toml"))
    parser.add_argument("--size", default="80x45")
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--seeds", type=int, default=24)
    parser.add_argument("--cells", default="0.02", help="caustic_cell values [m] beside 0 (the path tracer alone)")
    parser.add_argument("--set", action="append", default=[], help="section.key=value (JSON value)")
    args = parser.parse_args()

    from oceanrender.pipeline import Sequence, SequenceReport, simulate_coastal
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene, with_overrides

    size = tuple(int(v) for v in args.size.split("x"))
    extra: dict[str, dict] = {}
    for item in args.set:
        key, value = item.split("=", 1)
        section, name = key.split(".", 1)
        try:
            extra.setdefault(section, {})[name] = json.loads(value)
        except json.JSONDecodeError:
            extra.setdefault(section, {})[name] = value
    means, mask = {}, None
    for cell in [0.0] + [float(c) for c in args.cells.split(",")]:
        scene = with_overrides(load_scene(Path(args.scene)), "caustics_consistency.py",
                               **{**extra, "render": {**extra.get("render", {}), "caustic_cell": cell},
                                  "output": {**extra.get("output", {}), "resolution": list(size)}})
        store = None
        if scene.coastal is not None:
            store = simulate_coastal(scene, ROOT / "outputs" / "shafts" / Path(args.scene).stem, [0],
                                     SequenceReport("caustics_consistency.py"))
        sequence = Sequence(scene, activate_variant(scene.render.variant).variant, coastal_store=store)
        sequence.point(0)
        sequence.renderer.update_water(sequence.geometry(0))
        if mask is None:
            mask = water_pixels(sequence.renderer, size)
        tic = time.perf_counter()
        values = []
        for seed in range(args.seeds):
            xyz, _ = sequence.renderer.render_xyz(args.spp, seed)
            values.append(float(np.mean(xyz[..., 1][mask])))
        means[cell] = np.array(values)
        line = {"caustic_cell": cell, "water_pixels": int(mask.sum()), "mean_Y": round(float(means[cell].mean()), 3),
                "seconds_per_frame": round((time.perf_counter() - tic) / args.seeds, 2)}
        if cell > 0:
            base, own = means[0.0], means[cell]
            ratio = own.mean() / base.mean()
            error = ratio * np.sqrt(own.var(ddof=1) / own.size / own.mean() ** 2
                                    + base.var(ddof=1) / base.size / base.mean() ** 2)
            line.update({"ratio": round(float(ratio), 5), "ratio_sigma": round(float(error), 5)})
        print(json.dumps(line), flush=True)


if __name__ == "__main__":
    main()
