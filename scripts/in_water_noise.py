"""Issue 41, item 3: the noise of the in-water part of the default above-water view, against a reference.

The default scene's frames render in two passes (`render.in_water_fraction`): the light
reflected at the camera's first water hit, and the light from under the water (the
``transmission`` lobe), which carries the in-water sunlight. This renders frame 0 at the
given size: the reflected pass once at ``--reference-spp`` (shared by every comparison, so its
own noise cancels), the in-water pass once at ``--reference-spp`` as the reference, and at
each of ``--spp`` with ``--seeds`` seeds. Each noisy frame is reflected + in-water; its error is
ΔE00 per pixel against reflected + reference (CIELAB of XYZ over the scene's adapting white,
colour-science), and the relative RMS error of the in-water luminance. Prints one JSON line.

Usage: python scripts/in_water_noise.py [--scene scenes/open_ocean.toml] [--size 320x180]
       [--spp 16,64] [--seeds 4] [--reference-spp 2048]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--spp", default="16,64")
    parser.add_argument("--seeds", type=int, default=4)
    parser.add_argument("--reference-spp", type=int, default=2048)
    args = parser.parse_args()

    import colour

    from oceanrender.pipeline import Sequence
    from oceanrender.render.renderer import film_to_absolute_XYZ, render_passes
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene, with_overrides

    width, height = (int(v) for v in args.size.split("x"))
    scene = with_overrides(load_scene(Path(args.scene)), output={"resolution": [width, height]})
    runtime = activate_variant(scene.render.variant)
    sequence = Sequence(scene, runtime.variant)
    renderer = sequence.renderer
    sequence.point(0)
    renderer.update_water(sequence.geometry(0))
    assert renderer.in_water is not None, "the scene renders in one pass: no in-water part of its own"
    white = np.asarray(sequence.white_xyz, float)

    def xyz(film):
        return np.asarray(film_to_absolute_XYZ(film[..., :3]), float)

    tic = time.perf_counter()
    reflected = xyz(render_passes(renderer.scene, args.reference_spp, 1_000_003))
    reference = xyz(render_passes(renderer.scene, args.reference_spp, 2_000_003, renderer.in_water))
    reference_seconds = time.perf_counter() - tic

    def lab(values):
        return colour.XYZ_to_Lab(values / white[1], colour.XYZ_to_xy(white / white[1]))

    target = lab(reflected + reference)
    result = {"scene": Path(args.scene).stem, "size": [width, height], "reference_spp": args.reference_spp,
              "reference_seconds": round(reference_seconds, 1),
              "in_water_share_of_Y": float(reference[..., 1].mean() / (reflected + reference)[..., 1].mean())}
    for spp in (int(s) for s in args.spp.split(",")):
        delta, rms, seconds = [], [], []
        for seed in range(args.seeds):
            tic = time.perf_counter()
            noisy = xyz(render_passes(renderer.scene, spp, 17 + 7919 * seed, renderer.in_water))
            seconds.append(time.perf_counter() - tic)
            delta.append(float(np.mean(colour.delta_E(target, lab(reflected + noisy), method="CIE 2000"))))
            rms.append(float(np.sqrt(np.mean((noisy[..., 1] - reference[..., 1]) ** 2)) / reference[..., 1].mean()))
        result[f"spp_{spp}"] = {"delta_E00_mean": round(float(np.mean(delta)), 4),
                                "delta_E00_seeds": [round(v, 4) for v in delta],
                                "relative_rms_Y": round(float(np.mean(rms)), 4),
                                "seconds": round(float(np.mean(seconds)), 2)}
    print(json.dumps(result))


if __name__ == "__main__":
    main()
