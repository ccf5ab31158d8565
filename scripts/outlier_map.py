"""Issue 42, item 1: where the heavy tail of the default scene's estimator comes from.

Renders frame 0 of a scene (default ``scenes/open_ocean.toml``) at ``--size``: a reference of
each pass of a two-pass frame (the reflected pass and the in-water pass, ``--reference-spp`` each,
cached in ``--cache``), then ``--seeds`` noisy frames of ``--spp`` (the scene's own split: the in-water
pass at ``in_water_fraction`` of it). Each frame is graded as the pipeline's output is seen (the scene's
vision model with the reference's adapting white and adaptation luminance, CIEDE2000 of colour-science),
and so are the two hybrids that take one pass noisy and the other from the reference, which says which
pass carries the pixels above ΔE00 20.

It also renders ``--tail-seeds`` one-sample renders of each pass: per pixel, the samples are single
path values (box filter), so the share of a pixel's variance carried by its samples above 10× the
pixel's reference mean is measured directly, and the pixels where it is large are mapped.

Prints one JSON line; ``--images DIR`` writes PNGs (the ΔE00 map of one noisy frame, the pixels above 20
of each hybrid, and the tail's share of the variance per pass).

Usage: python scripts/outlier_map.py [--scene scenes/open_ocean.toml] [--size 160x90] [--spp 64]
       [--seeds 4] [--reference-spp 4096] [--tail-seeds 256] [--cache outputs/outliers/ref.npz]
       [--render KEY=VALUE ...] [--water KEY=VALUE ...] [--images DIR]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

#: ΔE00 above which a pixel is an outlier (the issue's threshold) [-].
OUTLIER_DELTA_E = 20.0
#: A sample is in the tail when it exceeds this multiple of its pixel's reference mean luminance [-].
TAIL_MULTIPLE = 10.0


def tail_share(samples: np.ndarray, mean: np.ndarray, multiple: float = TAIL_MULTIPLE) -> np.ndarray:
    """Share of each pixel's second moment about ``mean`` carried by samples above ``multiple`` × mean.

    ``samples`` (n, H, W) single-sample luminances, ``mean`` (H, W) the reference mean [any unit]. Returns
    (H, W) in [0, 1]; 0 where the pixel's second moment is 0.
    """
    deviation = (samples - mean) ** 2
    total = deviation.sum(axis=0)
    tail = np.where(samples > multiple * np.maximum(mean, 0.0), deviation, 0.0).sum(axis=0)
    return np.where(total > 0, tail / np.where(total > 0, total, 1.0), 0.0)


def parse_overrides(pairs: list[str]) -> dict:
    out = {}
    for pair in pairs:
        key, value = pair.split("=", 1)
        out[key] = json.loads(value) if value[:1] in "[{0123456789-.tf" else value
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--size", default="160x90")
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--in-water-spp", type=int, default=None, help="the in-water pass's spp (default: the scene's share)")
    parser.add_argument("--seeds", type=int, default=4)
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--tail-seeds", type=int, default=256)
    parser.add_argument("--cache", default=None)
    parser.add_argument("--render", nargs="*", default=[], help="[render] overrides KEY=VALUE (JSON values)")
    parser.add_argument("--water", nargs="*", default=[], help="[water] overrides KEY=VALUE (JSON values)")
    parser.add_argument("--images", default=None)
    args = parser.parse_args()

    from oceanrender.pipeline import Sequence, adaptation_luminance
    from oceanrender.realtime.compare import delta_E_2000
    from oceanrender.render.renderer import film_to_absolute_XYZ, render_passes
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene, with_overrides

    width, height = (int(v) for v in args.size.split("x"))
    scene = with_overrides(load_scene(Path(args.scene)), output={"resolution": [width, height]},
                           render=parse_overrides(args.render), water=parse_overrides(args.water))
    runtime = activate_variant(scene.render.variant)
    sequence = Sequence(scene, runtime.variant)
    renderer = sequence.renderer
    sequence.point(0)
    renderer.update_water(sequence.geometry(0))
    assert renderer.in_water is not None, "the scene renders in one pass"

    def xyz(film):
        return np.asarray(film_to_absolute_XYZ(film[..., :3]), float)

    def reflected(spp, seed):
        return xyz(render_passes(renderer.scene, spp, seed))

    def in_water(spp, seed):
        return xyz(render_passes(renderer.scene, spp, seed, renderer.in_water))

    tic = time.perf_counter()
    cache = Path(args.cache) if args.cache else None
    key = f"{Path(args.scene).stem} {width}x{height} {args.reference_spp} {sorted(parse_overrides(args.render).items())} {sorted(parse_overrides(args.water).items())}"
    if cache is not None and cache.exists() and str(np.load(cache)["key"]) == key:
        ref_r, ref_t = np.load(cache)["reflected"], np.load(cache)["in_water"]
    else:
        ref_r, ref_t = reflected(args.reference_spp, 1_000_003), in_water(args.reference_spp, 2_000_003)
        if cache is not None:
            cache.parent.mkdir(parents=True, exist_ok=True)
            np.savez_compressed(cache, key=key, reflected=ref_r, in_water=ref_t)
    reference_seconds = time.perf_counter() - tic
    reference = ref_r + ref_t
    white = sequence.white_xyz
    adaptation = adaptation_luminance(scene, reference, white)

    def display(image):
        return sequence.vision.apply(image, white, adaptation)

    target = display(reference)

    def grade(image):
        de = delta_E_2000(display(image), target)
        return de, {"mean": float(de.mean()), "p95": float(np.percentile(de, 95)),
                    "above_20_pct": float(100.0 * np.mean(de > OUTLIER_DELTA_E))}

    t_spp = args.in_water_spp or renderer.in_water_spp(args.spp)
    rows = {"frame": [], "noisy_reflected": [], "noisy_in_water": []}
    maps = None
    for seed in range(args.seeds):
        r, t = reflected(args.spp, 31 + 7919 * seed), in_water(t_spp, 57 + 7919 * seed)
        de, row = grade(r + t)
        rows["frame"].append(row)
        rows["noisy_reflected"].append(grade(r + ref_t)[1])
        de_t, row_t = grade(ref_r + t)
        rows["noisy_in_water"].append(row_t)
        if maps is None:
            maps = (de, grade(r + ref_t)[0], de_t)

    def mean_rows(items):
        return {k: round(float(np.mean([i[k] for i in items])), 4) for k in items[0]}

    result = {"scene": Path(args.scene).stem, "size": [width, height], "spp": args.spp, "in_water_spp": t_spp,
              "reference_spp": args.reference_spp, "reference_seconds": round(reference_seconds, 1),
              "render": parse_overrides(args.render), "water": parse_overrides(args.water),
              **{k: mean_rows(v) for k, v in rows.items()}}

    tails = {}
    if args.tail_seeds > 0:
        for name, render, ref in (("reflected", reflected, ref_r), ("in_water", in_water, ref_t)):
            samples = np.stack([render(1, 90_001 + 13 * s)[..., 1] for s in range(args.tail_seeds)])
            share = tail_share(samples, ref[..., 1])
            ratio = samples.max(axis=0) / np.maximum(ref[..., 1], 1e-12)
            tails[name] = share
            result[f"tail_{name}"] = {
                "variance_share_above_10x_mean": round(float(((samples - ref[..., 1]) ** 2 * (samples > TAIL_MULTIPLE
                                                   * ref[..., 1])).sum() / ((samples - ref[..., 1]) ** 2).sum()), 4),
                "pixels_tail_share_over_half_pct": round(float(100 * np.mean(share > 0.5)), 3),
                "max_sample_over_mean_p99": round(float(np.percentile(ratio, 99)), 1),
                "mean_Y": float(ref[..., 1].mean())}
    print(json.dumps(result))

    if args.images:
        from PIL import Image

        out = Path(args.images)
        out.mkdir(parents=True, exist_ok=True)

        def png(name, rgb):
            data = np.clip(rgb, 0, 1) ** (1 / 2.2)
            Image.fromarray((255 * data).astype(np.uint8)).resize((width * 4, height * 4), Image.NEAREST).save(
                out / f"{name}.png")

        png("reference", target)
        png("delta_e_frame", np.repeat((maps[0] / 20.0)[..., None], 3, axis=-1))
        for i, name in enumerate(("frame", "noisy_reflected", "noisy_in_water")):
            mark = target.copy()
            mark[maps[i] > OUTLIER_DELTA_E] = (1.0, 0.0, 1.0)
            png(f"above20_{name}", mark)
        for name, share in tails.items():
            png(f"tail_share_{name}", np.repeat(share[..., None], 3, axis=-1))


if __name__ == "__main__":
    main()
