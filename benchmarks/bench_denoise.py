"""Samples per pixel needed for a given error, with and without OIDN denoising; the denoiser's cost.

Run: ``.venv/bin/python benchmarks/bench_denoise.py [SCENE] [--resolution 160x90] [--reference-spp 1024]``
(about 10–15 min on 2 cores at the defaults). Prints Markdown tables.

Method
------
* Scene: ``scenes/open_ocean.toml`` (split integrator, sun sampling, foam,
  radial mesh) at ``--resolution``, frame 0.
* Reference: the mean of ``reference_spp / 64`` independent 64 spp renders
  (seeds 1000…), i.e. ``reference_spp`` samples per pixel.
* Estimates at 1, 2, 4 … ``--max-spp`` spp, from other seeds, built as means
  of independent 1, 8 or 64 spp renders (with a box pixel filter, the mean of
  k independent n-spp renders is distributed as one k·n-spp render; and each
  new spp value would cost Mitsuba a new JIT compilation of ~30 s here).
* Each estimate is compared noisy, denoised from colour alone, and denoised
  with albedo + normal features (:class:`FeatureRenderer`, 16 spp).
* Errors: relMSE of luminance, mean over pixels of (Y − Y_ref)²/(Y_ref² + ε)
  with both images divided by the reference's mean luminance and ε = 0.01
  (Rousselle, Knaus & Zwicker 2011, doi:10.1145/2070781.2024193), after
  dropping the 0.1 % of pixels with the largest error (caustic fireflies
  otherwise decide it; the untrimmed value is printed too); and the RMS
  difference of the final 8-bit sRGB frames [code values] after the vision
  model with the reference's adapting white and adaptation luminance.
* spp needed for a target error: interpolated log–log within the ladder
  ("> max" when never reached); for noisy renders also from a fit of
  relMSE = a/spp (unbiased Monte Carlo), which extrapolates. The
  reference's own noise adds ≈ a/reference_spp to every relMSE: printed.
* Cost at 320×180: OIDN ``RT`` filter (quality "high", CPU device) on a
  320×180 frame, with and without features (median of 7 after one warm-up
  call), and the 16 spp feature render at 320×180.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

#: ε of the relative MSE (images scaled to mean luminance 1).
EPSILON = 1e-2

#: Fraction of pixels with the largest error left out of the trimmed relMSE [-].
TRIM = 1e-3


def rel_mse(image: np.ndarray, reference: np.ndarray, eps: float = EPSILON, trim: float = TRIM) -> float:
    """relMSE of luminance (channel 1 of XYZ) [-], both divided by the reference's mean luminance.

    The ``trim`` fraction of pixels with the largest error is left out.
    """
    scale = reference[..., 1].mean()
    y, r = image[..., 1] / scale, reference[..., 1] / scale
    errors = np.sort(((y - r) ** 2 / (r**2 + eps)).ravel())
    return float(errors[: errors.size - int(np.ceil(trim * errors.size))].mean())


def mean_of_renders(renderer, spp_total: int, chunk: int, seed: int) -> np.ndarray:
    """Mean of spp_total/chunk independent renders of ``chunk`` spp (seeds seed, seed+1, …)."""
    count = spp_total // chunk
    total = None
    for i in range(count):
        xyz, _ = renderer.render_xyz(chunk, seed=seed + i)
        total = xyz if total is None else total + xyz
    return total / count


def spp_for_noisy(spp: np.ndarray, errors: np.ndarray, target: float) -> float:
    """spp at which an unbiased estimate reaches ``target``, from a least-squares fit of error = a/spp."""
    a = float(np.exp(np.mean(np.log(errors * spp))))
    return a / target


def spp_for_curve(spp: np.ndarray, errors: np.ndarray, target: float) -> float | None:
    """spp where a measured curve first falls to ``target`` (log–log interpolation); None if never."""
    for i, e in enumerate(errors):
        if e <= target:
            if i == 0:
                return float(spp[0])
            x0, x1, y0, y1 = np.log(spp[i - 1]), np.log(spp[i]), np.log(errors[i - 1]), np.log(e)
            return float(np.exp(x0 + (np.log(target) - y0) * (x1 - x0) / (y1 - y0)))
    return None


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", nargs="?", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--resolution", default="160x90", help="WxH of the error study [px]")
    parser.add_argument("--reference-spp", type=int, default=1024, help="multiple of 64")
    parser.add_argument("--max-spp", type=int, default=128, help="largest estimate (power of 2)")
    parser.add_argument("--targets", default="0.03,0.01,0.003", help="relMSE targets to report spp for")
    parser.add_argument("--targets-8bit", default="15,10,8", help="sRGB RMSE targets [code values]")
    parser.add_argument("--save", default=None, help="write the reference, estimates and features to this .npz")
    args = parser.parse_args()
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")

    from oceanrender.scene import load_scene, with_overrides
    from oceanrender.pipeline import Sequence, adaptation_luminance
    from oceanrender.render.denoise import FeatureRenderer, denoise_XYZ
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.vision.display import encode_sRGB_8bit

    width, height = (int(v) for v in args.resolution.lower().split("x"))
    runtime = activate_variant(load_scene(args.scene).render.variant)
    scene = with_overrides(load_scene(args.scene), output={"resolution": [width, height]})
    tic = time.perf_counter()
    sequence = Sequence(scene, runtime.variant)
    geometry = sequence.geometry(0)
    features = FeatureRenderer.build(scene, sequence.faces, geometry).render(seed=0)
    print(f"# bench_denoise: {Path(args.scene).name} at {width}x{height}, integrator {scene.render.integrator}, "
          f"variant {runtime.variant}, {os.cpu_count()} CPUs ({platform.processor() or platform.machine()})")
    print(f"setup {time.perf_counter() - tic:.1f} s", flush=True)

    tic = time.perf_counter()
    reference = mean_of_renders(sequence.renderer, args.reference_spp, 64, seed=1000)
    print(f"reference {args.reference_spp} spp: {time.perf_counter() - tic:.0f} s", flush=True)
    white = sequence.white_xyz
    adaptation = adaptation_luminance(scene, reference, white)
    ref8 = encode_sRGB_8bit(sequence.vision.apply(reference, white, adaptation)).astype(float)

    def display_rmse(xyz):
        out8 = encode_sRGB_8bit(sequence.vision.apply(xyz, white, adaptation)).astype(float)
        return float(np.sqrt(np.mean((out8 - ref8) ** 2)))

    ladder = [2**k for k in range(int(np.log2(args.max_spp)) + 1)]
    rows, estimates = [], {}
    for spp in ladder:
        chunk = 64 if spp >= 64 else (8 if spp >= 8 else 1)
        tic = time.perf_counter()
        noisy = mean_of_renders(sequence.renderer, spp, chunk, seed=10 * spp)
        render_s = time.perf_counter() - tic
        estimates[f"noisy_{spp}"] = noisy
        plain = denoise_XYZ(noisy)
        guided = denoise_XYZ(noisy, features.albedo, features.normal)
        rows.append({
            "spp": spp, "render_s": render_s,
            "noisy": rel_mse(noisy, reference), "plain": rel_mse(plain, reference),
            "guided": rel_mse(guided, reference), "noisy_all": rel_mse(noisy, reference, trim=0.0),
            "plain_all": rel_mse(plain, reference, trim=0.0),
            "noisy8": display_rmse(noisy), "plain8": display_rmse(plain), "guided8": display_rmse(guided),
            "level": float(guided[..., 1].mean() / reference[..., 1].mean()),
        })
        print(f"  {spp} spp done ({render_s:.0f} s)", flush=True)

    if args.save:
        np.savez_compressed(args.save, reference=reference, albedo=features.albedo, normal=features.normal,
                            white=white, adaptation=adaptation, **estimates)
    spp = np.array([r["spp"] for r in rows], dtype=float)
    noisy = np.array([r["noisy"] for r in rows])
    floor = float(np.exp(np.mean(np.log(noisy * spp)))) / args.reference_spp
    print()
    print(f"Errors against the {args.reference_spp} spp reference (reference noise floor ≈ {floor:.2g} relMSE)")
    print()
    print("| spp | relMSE noisy | relMSE OIDN | relMSE OIDN + albedo, normal | relMSE untrimmed noisy / OIDN | "
          "sRGB RMSE noisy | sRGB RMSE OIDN | sRGB RMSE OIDN + aux | mean Y OIDN+aux / ref |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['spp']} | {r['noisy']:.3g} | {r['plain']:.3g} | {r['guided']:.3g} | "
              f"{r['noisy_all']:.3g} / {r['plain_all']:.3g} | {r['noisy8']:.2f} | {r['plain8']:.2f} | "
              f"{r['guided8']:.2f} | {r['level']:.3f} |")

    def needed(key, target):
        value = spp_for_curve(spp, np.array([r[key] for r in rows]), target)
        return f"{value:.1f}" if value is not None else f"> {int(spp[-1])}"

    print()
    print("spp needed to reach a target (log–log interpolation within the ladder)")
    print()
    print("| target | noisy | noisy, fit a/spp | OIDN | OIDN + albedo, normal |")
    print("|---|---:|---:|---:|---:|")
    for target in (float(v) for v in args.targets.split(",")):
        print(f"| relMSE {target:g} | {needed('noisy', target)} | {spp_for_noisy(spp, noisy, target):.0f} | "
              f"{needed('plain', target)} | {needed('guided', target)} |")
    for target in (float(v) for v in args.targets_8bit.split(",")):
        print(f"| sRGB RMSE {target:g} | {needed('noisy8', target)} | – | {needed('plain8', target)} | "
              f"{needed('guided8', target)} |")

    # --- cost at 320×180 -------------------------------------------------------------------
    big = with_overrides(scene, output={"resolution": [320, 180]})
    feature_renderer = FeatureRenderer.build(big, sequence.faces, geometry)
    feature_renderer.render(seed=0)  # JIT compilation
    tic = time.perf_counter()
    big_features = feature_renderer.render(seed=1)
    feature_s = time.perf_counter() - tic
    if (2 * height, 2 * width) == (180, 320):  # a real noisy frame, pixel-doubled to 320×180
        frame = np.repeat(np.repeat(mean_of_renders(sequence.renderer, 4, 1, seed=5), 2, axis=0), 2, axis=1)
    else:  # OIDN's cost does not depend on the content: any noisy HDR frame will do
        frame = np.abs(np.random.default_rng(0).normal(1e3, 3e2, (180, 320, 3)))
    timings = {}
    for name, extra in (("colour only", ()), ("+ albedo, normal", (big_features.albedo, big_features.normal))):
        denoise_XYZ(frame, *extra)
        runs = []
        for _ in range(7):
            tic = time.perf_counter()
            denoise_XYZ(frame, *extra)
            runs.append(time.perf_counter() - tic)
        timings[name] = float(np.median(runs))
    print()
    print("Cost per 320×180 frame (median of 7)")
    print()
    print("| step | s / frame |")
    print("|---|---:|")
    for name, seconds in timings.items():
        print(f"| OIDN RT filter, {name} | {seconds:.3f} |")
    print(f"| feature render (aov, 16 spp) | {feature_s:.3f} |")
    if 64 in ladder:
        print(f"| for scale: one {width}x{height} colour render at 64 spp | {rows[ladder.index(64)]['render_s']:.1f} |")

if __name__ == "__main__":
    main()
