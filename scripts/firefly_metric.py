"""Spectral fireflies of the default scene: the share of water pixels far from a converged reference.

Run: ``.venv/bin/python scripts/firefly_metric.py [--seeds 1 2 3 4] [--brightness NAME] [--label NAME]``.

Renders frame 0 of ``scenes/open_ocean.toml`` at 160×90: once a 4096-spp
reference (cached as ``outputs/fireflies/reference_*.exr`` and re-used; its
seeds are distinct from the test renders'), then 24-spp renders with several
seeds. For each test render it reports

* the **firefly share**: water pixels (the camera ray through the pixel centre
  first hits the water surface, found by a Mitsuba ray cast) whose CIEDE2000
  difference to the reference exceeds 20, over all water pixels [-];
* the seconds per frame of the render (``render_xyz``, JIT compilation excluded
  by a warm-up render);
* the image mean of X, Y, Z over the water pixels against the reference's, as a
  z-score (the test's bias check; standard errors from the spread of the seeds
  and of the reference's passes).

ΔE00 is computed on what a viewer sees: both images go through the same vision
model Φ (default ``vision_for_scene(scene)``, ``--brightness`` overrides its
brightness operator) with the **reference's** adapting white and adaptation
luminance, then linear sRGB → XYZ (D65) → CIELAB (D65) → ΔE00 (colour-science,
``colour.delta_E(..., method="CIE 2000")``). A table goes to stdout and the numbers
to ``outputs/fireflies/<label>.json``; ``--images DIR`` also writes small PNGs
(reference, one test render, its ΔE00 > 20 pixels in magenta).
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if importlib.util.find_spec("oceanrender") is None:
    sys.path.insert(0, str(ROOT))

#: ΔE00 above which a pixel counts as a firefly (the issue's threshold) [-].
FIREFLY_DELTA_E = 20.0


# ---------------------------------------------------------------------------------------------
# The metric: pure functions of arrays.


def linear_sRGB_to_Lab(rgb: np.ndarray) -> np.ndarray:
    """CIELAB (D65 white, Y_n = 1) of linear display sRGB (1 = display white), shape (..., 3)."""
    import colour  # noqa: PLC0415

    space = colour.RGB_COLOURSPACES["sRGB"]
    XYZ = np.einsum("ij,...j->...i", space.matrix_RGB_to_XYZ, np.asarray(rgb, dtype=np.float64))
    return colour.XYZ_to_Lab(XYZ, space.whitepoint)


def delta_E00_map(rgb: np.ndarray, rgb_reference: np.ndarray) -> np.ndarray:
    """Per-pixel CIEDE2000 between two linear sRGB images (H, W, 3) [-]."""
    import colour  # noqa: PLC0415

    return colour.delta_E(linear_sRGB_to_Lab(rgb), linear_sRGB_to_Lab(rgb_reference), method="CIE 2000")


def firefly_share(delta_e: np.ndarray, mask: np.ndarray, threshold: float = FIREFLY_DELTA_E) -> float:
    """Share of the pixels in ``mask`` whose ΔE00 exceeds ``threshold`` [-] (non-finite ΔE counts as a firefly)."""
    values = np.asarray(delta_e)[np.asarray(mask, bool)]
    if values.size == 0:
        raise ValueError("the mask selects no pixel")
    return float(np.mean(~(values <= threshold)))


def mean_z_score(means: np.ndarray, reference_passes: np.ndarray) -> np.ndarray:
    """z of the mean of independent renders' image means against a reference built from independent passes.

    ``means``: (K, C) image means of K test renders; ``reference_passes``: (P, C) image means of
    the P equal passes the reference averages. Each standard error is the spread of its
    renders over √count, so z ~ N(0, 1) for an unbiased pair (K, P large enough).
    """
    means, passes = np.asarray(means, float), np.asarray(reference_passes, float)
    se = np.hypot(means.std(axis=0, ddof=1) / np.sqrt(len(means)), passes.std(axis=0, ddof=1) / np.sqrt(len(passes)))
    return (means.mean(axis=0) - passes.mean(axis=0)) / se


# ---------------------------------------------------------------------------------------------
# Rendering.


def water_pixel_mask(mitsuba_scene, resolution: tuple[int, int], shape_id: str) -> np.ndarray:
    """(H, W) bool: the camera ray through the pixel centre first hits the shape ``shape_id``."""
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    width, height = resolution
    sensor = mitsuba_scene.sensors()[0]
    x, y = np.meshgrid((np.arange(width) + 0.5) / width, (np.arange(height) + 0.5) / height)
    n = width * height
    ray, _ = sensor.sample_ray(mi.Float(np.zeros(n)), mi.Float(np.full(n, 0.5)),
                               mi.Point2f(x.ravel(), y.ravel()), mi.Point2f(np.full(n, 0.5), np.full(n, 0.5)))
    si = mitsuba_scene.ray_intersect(ray)
    target = [s for s in mitsuba_scene.shapes() if s.id() == shape_id]
    if not target:
        raise ValueError(f"no shape with id {shape_id!r} in the scene")
    hit = si.is_valid() & (si.shape == mi.ShapePtr(target[0]))
    dr.eval(hit)
    return np.array(hit, dtype=bool).reshape(height, width)


def render_reference(renderer, spp: int, pass_spp: int, seed: int, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(mean XYZ (H, W, 3) [cd m⁻²], per-pass water means (P, 3)) of ``spp // pass_spp`` passes of ``pass_spp``."""
    passes = max(spp // pass_spp, 1)
    total, means = 0.0, []
    for k in range(passes):
        xyz, _ = renderer.render_xyz(pass_spp, seed=seed + k)
        total = total + xyz
        means.append(xyz[mask].mean(axis=0))
        print(f"  reference pass {k + 1}/{passes}", file=sys.stderr, flush=True)
    return total / passes, np.array(means)


def load_or_render_reference(path: Path, renderer, args, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray, dict]:
    from oceanrender.io.frames import read_exr, write_exr  # noqa: PLC0415

    if path.exists() and not args.rerender_reference:
        channels, metadata = read_exr(path)
        xyz = np.stack([channels[c] for c in "XYZ"], axis=-1).astype(np.float64)
        passes = np.array(json.loads(metadata["pass_water_means"]), dtype=float)
        return xyz, passes, metadata
    tic, sources = time.perf_counter(), integrator_fingerprint()
    xyz, passes = render_reference(renderer, args.reference_spp, args.reference_pass_spp, args.reference_seed, mask)
    metadata = {"spp": args.reference_spp, "pass_spp": args.reference_pass_spp, "seed": args.reference_seed,
                "seconds": round(time.perf_counter() - tic, 1), "pass_water_means": json.dumps(passes.tolist()),
                "integrator_sources": sources}
    path.parent.mkdir(parents=True, exist_ok=True)
    write_exr(path, {c: xyz[..., i] for i, c in enumerate("XYZ")}, metadata)
    return xyz, passes, metadata


def integrator_fingerprint() -> str:
    """sha256 (first 12 hex digits) of the render sources the light transport depends on."""
    import hashlib  # noqa: PLC0415

    import oceanrender.render.integrator as integrator  # noqa: PLC0415
    import oceanrender.render.underwater as underwater  # noqa: PLC0415

    digest = hashlib.sha256()
    for module in (integrator, underwater):
        digest.update(Path(module.__file__).read_bytes())
    return digest.hexdigest()[:12]


def parse_resolution(text: str) -> tuple[int, int]:
    width, height = (int(v) for v in text.lower().split("x"))
    return width, height


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--frame", type=int, default=0)
    parser.add_argument("--resolution", type=parse_resolution, default=(160, 90), help="WxH")
    parser.add_argument("--spp", type=int, default=24)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4])
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--reference-pass-spp", type=int, default=128)
    parser.add_argument("--reference-seed", type=int, default=1_000_000,
                        help="first seed of the reference's passes (distinct from --seeds)")
    parser.add_argument("--rerender-reference", action="store_true")
    parser.add_argument("--reference-sources", default=None,
                        help="use the reference rendered by these integrator sources (fingerprint) instead")
    parser.add_argument("--brightness", default=None,
                        help="brightness operator of the vision model (default: the scene's)")
    parser.add_argument("--threshold", type=float, default=FIREFLY_DELTA_E)
    parser.add_argument("--label", default="current", help="name of the JSON written to --out")
    parser.add_argument("--out", default=str(ROOT / "outputs" / "fireflies"))
    parser.add_argument("--images", default=None, help="folder for PNGs: reference, first test render, its fireflies")
    parser.add_argument("--variant", default="auto")
    args = parser.parse_args(argv)
    if set(args.seeds) & set(range(args.reference_seed, args.reference_seed + args.reference_spp)):
        parser.error("--seeds must be distinct from the reference's seeds")

    from oceanrender.pipeline import Sequence, adaptation_luminance, vision_for_scene  # noqa: PLC0415
    from oceanrender.render.renderer import WATER_ID  # noqa: PLC0415
    from oceanrender.runtime.variants import activate_variant  # noqa: PLC0415
    from oceanrender.scene.settings import load_scene  # noqa: PLC0415
    from oceanrender.vision.model import VisionModel  # noqa: PLC0415

    scene = load_scene(args.scene)
    vision = vision_for_scene(scene)
    if args.brightness is not None:
        vision = VisionModel(brightness=args.brightness, chromatic_transform=vision.chromatic_transform,
                             display_max_luminance=vision.display_max_luminance)
    variant = activate_variant(args.variant).variant
    seq = Sequence(scene, variant, spp=args.spp, resolution=args.resolution, first_frame=args.frame)
    seq.point(args.frame)
    seq.renderer.update_water(seq.geometry(args.frame))
    mask = water_pixel_mask(seq.renderer.scene, args.resolution, WATER_ID)

    width, height = args.resolution
    out = Path(args.out)
    # NOTE: named by the light-transport sources too: a changed integrator renders a new
    # reference, a changed vision model re-uses it.
    ref_path = out / (f"reference_{scene.name}_f{args.frame}_{width}x{height}_{args.reference_spp}spp"
                      f"_seed{args.reference_seed}_{args.reference_sources or integrator_fingerprint()}.exr")
    ref_xyz, ref_passes, ref_meta = load_or_render_reference(ref_path, seq.renderer, args, mask)
    white = seq.white_xyz
    L_a = adaptation_luminance(scene, ref_xyz, white)
    ref_rgb = vision.apply(ref_xyz, white, L_a)

    seq.renderer.render_xyz(args.spp, seed=args.reference_seed - 1)  # warm-up: JIT compilation
    rows, means, first = [], [], None
    for seed in args.seeds:
        tic, cpu = time.perf_counter(), time.process_time()
        xyz, repaired = seq.renderer.render_xyz(args.spp, seed=seed)
        seconds, cpu = time.perf_counter() - tic, time.process_time() - cpu
        delta_e = delta_E00_map(vision.apply(xyz, white, L_a), ref_rgb)
        share = firefly_share(delta_e, mask, args.threshold)
        means.append(xyz[mask].mean(axis=0))
        rows.append({"seed": seed, "firefly_share": share, "fireflies": int(round(share * mask.sum())),
                     "seconds": seconds, "cpu_seconds": cpu, "repaired": repaired,
                     "median_delta_E00": float(np.median(delta_e[mask])),
                     "water_mean_Y": float(means[-1][1])})
        first = first if first is not None else (xyz, delta_e)
    z = mean_z_score(np.array(means), ref_passes)

    shares = np.array([r["firefly_share"] for r in rows])
    seconds = np.array([r["seconds"] for r in rows])
    cpu_seconds = np.array([r["cpu_seconds"] for r in rows])
    print(f"{scene.name} frame {args.frame}, {width}x{height}, {args.spp} spp, {variant}, vision "
          f"{vision.brightness}/{vision.chromatic_transform}; water pixels {int(mask.sum())} of {mask.size}; "
          f"reference {ref_meta['spp']} spp (sources {ref_meta.get('integrator_sources', '?')})")
    print(f"{'seed':>6} {'ΔE00>' + format(args.threshold, 'g'):>10} {'share %':>9} {'median ΔE':>10} "
          f"{'Y water':>10} {'s/frame':>8} {'CPU s':>8}")
    for r in rows:
        print(f"{r['seed']:>6} {r['fireflies']:>10} {100 * r['firefly_share']:>9.3f} {r['median_delta_E00']:>10.2f} "
              f"{r['water_mean_Y']:>10.1f} {r['seconds']:>8.2f} {r['cpu_seconds']:>8.2f}")
    print(f"{'mean':>6} {shares.mean() * mask.sum():>10.1f} {100 * shares.mean():>9.3f} "
          f"{np.mean([r['median_delta_E00'] for r in rows]):>10.2f} {np.mean(means, axis=0)[1]:>10.1f} "
          f"{seconds.mean():>8.2f} {cpu_seconds.mean():>8.2f}")
    print(f"reference water mean Y {ref_passes.mean(axis=0)[1]:.1f}; z of the mean (X, Y, Z) against it: "
          + ", ".join(f"{v:+.2f}" for v in z))

    report = {"scene": scene.name, "frame": args.frame, "resolution": [width, height], "spp": args.spp,
              "variant": variant, "vision": {"brightness": vision.brightness,
                                             "chromatic_transform": vision.chromatic_transform},
              "threshold_delta_E00": args.threshold, "water_pixels": int(mask.sum()),
              "integrator_sources": integrator_fingerprint(),
              "reference": {"path": str(ref_path), "spp": int(ref_meta["spp"]),
                            "integrator_sources": ref_meta.get("integrator_sources"),
                            "water_mean_XYZ": ref_passes.mean(axis=0).tolist()},
              "adaptation_luminance": L_a, "white_XYZ": np.asarray(white).tolist(),
              "renders": rows, "firefly_share_mean": float(shares.mean()),
              "seconds_per_frame_mean": float(seconds.mean()),
              "cpu_seconds_per_frame_mean": float(cpu_seconds.mean()),
              "water_mean_XYZ": np.mean(means, axis=0).tolist(),
              "z_mean_XYZ": z.tolist()}
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{args.label}.json").write_text(json.dumps(report, indent=2))
    if args.images:
        write_images(Path(args.images), args.label, vision, white, L_a, ref_xyz, first, mask, args.threshold)
    return 0


def write_images(folder: Path, label: str, vision, white, L_a, ref_xyz, first, mask, threshold) -> None:
    """PNGs: the reference, the first test render and its fireflies (magenta where ΔE00 > threshold), 2× upscaled."""
    from oceanrender.io.frames import write_png  # noqa: PLC0415
    from oceanrender.vision.display import encode_sRGB_8bit  # noqa: PLC0415

    xyz, delta_e = first
    folder.mkdir(parents=True, exist_ok=True)
    test = encode_sRGB_8bit(vision.apply(xyz, white, L_a))
    marked = test.copy()
    marked[mask & ~(delta_e <= threshold)] = (255, 0, 255)

    def up(image):
        return np.repeat(np.repeat(image, 2, axis=0), 2, axis=1)

    write_png(folder / "fireflies_reference.png", up(encode_sRGB_8bit(vision.apply(ref_xyz, white, L_a))))
    write_png(folder / f"fireflies_{label}.png", up(test))
    write_png(folder / f"fireflies_{label}_marked.png", up(marked))


if __name__ == "__main__":
    sys.exit(main())
