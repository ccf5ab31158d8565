"""Issue 41, item 3: the noise of the in-water part of the default above-water view, against a reference.

The default scene's frames render in two passes (`render.in_water_fraction`): the light
reflected at the camera's first water hit, and the light from under the water (the
``transmission`` lobe), which carries the in-water sunlight. This renders frame 0 at the
given size: the reflected pass once at ``--reference-spp`` (shared by every comparison, so its
own noise cancels), the in-water pass once at ``--reference-spp`` as the reference, and at
each of ``--spp`` with ``--seeds`` seeds. Each noisy frame is reflected + in-water; its error is
ΔE00 per pixel against reflected + reference (CIELAB of XYZ over the scene's adapting white,
colour-science), and the relative RMS error of the in-water luminance. Prints one JSON line.

The reference's own noise is a floor under those errors (at 2048 spp its relative RMS is about
half the in-water luminance per pixel of this view), so each setting's noise alone is also given,
from pairs of its independent frames: ΔE00 between them over √2 and the RMS of their in-water
luminance difference over √2 (a proxy, ΔE00 not being linear, the same for every setting).

With ``--shaft-cell`` (> 0) the noisy frames are also rendered with the sun's beam in the volume
(``[render] shaft_cell``: docs/sunlight.md) at ``--shaft-spp``, against the same reference (the
path tracer alone), so its bias is part of its error; the JSON line then also holds the frame's
in-water mean luminance of each setting over the reference's.

Usage: python scripts/in_water_noise.py [--scene scenes/open_ocean.toml] [--size 320x180]
       [--spp 16,64] [--seeds 4] [--reference-spp 2048] [--shaft-cell 0.1 --shaft-spp 16,64]
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
    parser.add_argument("--shaft-cell", type=float, default=0.0)
    parser.add_argument("--reference-cache", default=None,
                        help="an .npz to keep the reference passes in (reused when it exists: same scene, size, spp)")
    parser.add_argument("--shaft-spp", default="16,64")
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
    cache = Path(args.reference_cache) if args.reference_cache else None
    key = f"{Path(args.scene).stem} {width}x{height} {args.reference_spp}"
    if cache is not None and cache.exists() and str(np.load(cache)["key"]) == key:
        reflected, reference = np.load(cache)["reflected"], np.load(cache)["reference"]
    else:
        reflected = xyz(render_passes(renderer.scene, args.reference_spp, 1_000_003))
        reference = xyz(render_passes(renderer.scene, args.reference_spp, 2_000_003, renderer.in_water))
        if cache is not None:
            np.savez_compressed(cache, key=key, reflected=reflected, reference=reference)
    reference_seconds = time.perf_counter() - tic

    def lab(values):
        return colour.XYZ_to_Lab(values / white[1], colour.XYZ_to_xy(white / white[1]))

    target = lab(reflected + reference)
    result = {"scene": Path(args.scene).stem, "size": [width, height], "reference_spp": args.reference_spp,
              "reference_seconds": round(reference_seconds, 1),
              "in_water_share_of_Y": float(reference[..., 1].mean() / (reflected + reference)[..., 1].mean())}
    def noisy(scene_renderer, spp_list, label):
        for spp in (int(s) for s in spp_list.split(",")):
            delta, rms, seconds, means, frames = [], [], [], [], []
            for seed in range(args.seeds):
                tic = time.perf_counter()
                frame = xyz(render_passes(scene_renderer.scene, spp, 17 + 7919 * seed, scene_renderer.in_water))
                seconds.append(time.perf_counter() - tic)
                frames.append(frame)
                delta.append(float(np.mean(colour.delta_E(target, lab(reflected + frame), method="CIE 2000"))))
                rms.append(float(np.sqrt(np.mean((frame[..., 1] - reference[..., 1]) ** 2)) / reference[..., 1].mean()))
                means.append(float(frame[..., 1].mean() / reference[..., 1].mean()))
            result[f"{label}spp_{spp}"] = {"delta_E00_mean": round(float(np.mean(delta)), 4),
                                           "delta_E00_seeds": [round(v, 4) for v in delta],
                                           "relative_rms_Y": round(float(np.mean(rms)), 4),
                                           "mean_Y_over_reference": round(float(np.mean(means)), 4),
                                           # the noise alone (the reference's own noise and the bias left out):
                                           # two independent frames of the same setting, ΔE00 between them / √2
                                           # and the RMS of their in-water luminance difference / √2 over the mean
                                           "delta_E00_between_seeds": round(float(np.mean([np.mean(colour.delta_E(
                                               lab(reflected + frames[i]), lab(reflected + frames[i + 1]),
                                               method="CIE 2000")) for i in range(0, len(frames) - 1, 2)])
                                               / np.sqrt(2.0)), 4),
                                           "relative_rms_Y_between_seeds": round(float(np.mean([np.sqrt(np.mean(
                                               (frames[i][..., 1] - frames[i + 1][..., 1]) ** 2) / 2.0)
                                               / reference[..., 1].mean() for i in range(0, len(frames) - 1, 2)])), 4),
                                           "seconds": round(float(np.mean(seconds)), 2)}

    noisy(renderer, args.spp, "")
    if args.shaft_cell > 0:
        beam_scene = with_overrides(scene, render={"shaft_cell": args.shaft_cell})
        beam_sequence = Sequence(beam_scene, runtime.variant)
        beam_sequence.point(0)
        beam_sequence.renderer.update_water(beam_sequence.geometry(0))
        result["shaft_cell"] = args.shaft_cell
        noisy(beam_sequence.renderer, args.shaft_spp, "beam_")
    print(json.dumps(result))


if __name__ == "__main__":
    main()
