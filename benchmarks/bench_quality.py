"""Time to quality: seconds and samples per pixel → ΔE00 against a high-spp reference (issue 16).

Run: ``.venv/bin/python benchmarks/bench_quality.py [--scenes open_ocean,coastal_beach,turbid_estuary]
[--resolution 320x180] [--reference-spp 1024] [--max-spp 256] [--hd-spp 64] [--hd-reference-spp 1024]
[--variant auto]`` (BENCHMARKS.md gives the arguments of the recorded runs and their times;
``--variant cuda_ad_spectral`` runs the same curves on a GPU). Prints Markdown tables, each scene's as
soon as it is done.

Method
------
* Per scene (frame 0, ``--resolution``) four settings in the same run, on the same geometry:
  **tuned** (the scene file's ``[render]``; for the default scene two passes with the in-water lobe at
  ``in_water_fraction`` of the samples), **adaptive** (the tuned integrators rendered by
  :func:`oceanrender.render.adaptive.render_adaptive`, a quarter of the budget uniform first),
  **before** (``split`` as it was before issue 16: one pass, ``in_water_fraction = 1``,
  ``roulette_depth = 5``; left out where the scene file has those settings) and plain Mitsuba
  **volpath** (``roulette_depth = 5``).
* Reference: the scene file's settings without the in-water clamp (:data:`REFERENCE`), at
  ``--reference-spp`` (× :data:`REFERENCE_SHARE` per scene), as the mean of independent 64-spp renders
  (seeds 10 000 … and 20 000 …). All settings but a clamped one estimate the same image without bias
  (tested in ``tests/render/test_integrator.py``), so one reference serves all. Its own error is
  estimated from its two halves: ≈ ΔE00(A, B) / 2 for noise-dominated differences (σ of A − B is
  2× that of the mean of A and B).
* Estimates at 16, 32 … ``--max-spp`` spp, built as means of independent 16- or 64-spp renders (the
  mean of k independent n-spp renders of a box-filtered film is distributed as one k·n-spp render, and
  every new spp value costs Mitsuba a JIT compilation). Time = the wall time of those renders, measured
  warm (one render per chunk size first, for the compilation), + OIDN's time for the denoised columns.
* Error: each image → Φ (the scene's vision model, issue 15) with the **reference's** adapting white and
  adaptation luminance → linear display sRGB → clipped to the display → CIELAB (D65) → CIEDE2000
  (colour-science) against the reference, per pixel; mean and 95th percentile over all pixels and over
  the pixels whose reference is not clipped (all display channels < 1); and mean Y / the reference's.
* Denoised: OIDN ``RT`` colour only, and with the first hit's albedo and normal
  (:class:`~oceanrender.render.denoise.FeatureRenderer`, its own 16-spp render, timed).
* Time to a given error: log–log interpolation along each curve; beyond a curve's end, the noisy
  curves are extended with the Monte-Carlo law ΔE ∝ t^(−1/2) from their last point.
* 1280×720: an unbiased 1280×720 reference (``--hd-reference-spp``) and one frame of the first scene as
  the pipeline makes it (tuned, ``--hd-spp``, OIDN), timed, with its errors also given less the
  reference's own (in quadrature).
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

#: Integrator settings compared, as ``[render]`` overrides of the scene file (None: the file's own).
#: "adaptive" is the tuned setting rendered by :func:`oceanrender.render.adaptive.render_adaptive`.
SETTINGS = {
    "tuned": None,
    "adaptive": None,
    "before": {"integrator": "split", "in_water_fraction": 1.0, "roulette_depth": 5},
    "volpath": {"integrator": "volpath", "in_water_fraction": 1.0, "roulette_depth": 5},
}

#: Chunk sizes of the renders the estimates are built from [spp].
CHUNKS = (16, 64)

#: The reference: the scene file's settings without the (biased) in-water clamp.
REFERENCE = {"in_water_clamp": 0.0}

#: Reference spp as a fraction of ``--reference-spp`` per scene: the turbid estuary costs ~10× per sample,
#: the coastal scene converges ~2× faster than the open sea.
REFERENCE_SHARE = {"turbid_estuary": 0.25, "coastal_beach": 0.5}

#: Per-pixel ΔE00 the adaptive passes aim at: below what any budget here reaches, so the budget decides
#: how many samples are spent and the error estimates decide where.
ADAPTIVE_TARGET = 0.5


def chunked_render(renderer, spp: int, seed: int) -> tuple[np.ndarray, float]:
    """Mean of independent renders of 16 or 64 spp totalling ``spp`` → (XYZ image, render seconds)."""
    chunk = 64 if spp >= 64 else 16
    total, seconds = None, 0.0
    for i in range(spp // chunk):
        tic = time.perf_counter()
        xyz, _ = renderer.render_xyz(chunk, seed=seed + i)
        seconds += time.perf_counter() - tic
        total = xyz if total is None else total + xyz
    return total / (spp // chunk), seconds


def build_sequence(scene_path: Path, overrides, width: int, height: int, variant_request: str, store: Path | None):
    from oceanrender.pipeline import Sequence
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene.settings import load_scene, with_overrides

    scene = load_scene(scene_path)
    render = dict(overrides or {})
    if variant_request != "auto":
        render["variant"] = variant_request
    scene = with_overrides(scene, output={"resolution": [width, height]}, render=render)
    variant = activate_variant(scene.render.variant).variant
    return scene, Sequence(scene, variant, coastal_store=store), variant


def coastal_store_for(scene_path: Path, workdir: Path) -> Path | None:
    """Run a coastal scene's simulation to frame 0 into ``workdir`` (None for the open sea)."""
    from oceanrender.coastal.simulation import run_simulation
    from oceanrender.scene.settings import load_scene

    scene = load_scene(scene_path)
    if scene.coastal is None:
        return None
    store = workdir / f"{scene_path.stem}_coastal"
    run_simulation(scene, store, (0, 1))
    return store


class Grader:
    """ΔE00 of images against the reference after Φ with the reference's white and adaptation."""

    def __init__(self, sequence, scene, reference: np.ndarray):
        from oceanrender.pipeline import adaptation_luminance

        self.vision, self.white = sequence.vision, sequence.white_xyz
        self.adaptation = adaptation_luminance(scene, reference, self.white)
        self.reference_rgb = self.display(reference)
        self.unclipped = np.all(self.reference_rgb < 1.0, axis=-1)

    def display(self, xyz: np.ndarray) -> np.ndarray:
        return self.vision.apply(xyz, self.white, self.adaptation)

    def errors(self, xyz: np.ndarray, against: np.ndarray | None = None) -> dict[str, float]:
        from oceanrender.realtime.compare import delta_E_2000

        base = self.reference_rgb if against is None else self.display(against)
        de = delta_E_2000(self.display(xyz), base)
        clear = de[self.unclipped] if self.unclipped.any() else np.array([np.nan])
        return {"mean": float(de.mean()), "p95": float(np.percentile(de, 95)),
                "mean_unclipped": float(clear.mean()), "p95_unclipped": float(np.percentile(clear, 95))}


def time_to_error(seconds: np.ndarray, errors: np.ndarray, target: float, extend: bool) -> float | None:
    """Seconds at which a curve reaches ``target`` (log–log interpolation; ``extend``: t^(−1/2) law beyond)."""
    for i, e in enumerate(errors):
        if e <= target:
            if i == 0:
                return float(seconds[0]) if e == target or not extend else \
                    float(seconds[0] * (e / target) ** 2)
            x0, x1, y0, y1 = np.log(seconds[i - 1]), np.log(seconds[i]), np.log(errors[i - 1]), np.log(e)
            return float(np.exp(x0 + (np.log(target) - y0) * (x1 - x0) / (y1 - y0)))
    if not extend:
        return None
    return float(seconds[-1] * (errors[-1] / target) ** 2)


def denoise_timed(xyz, features=None) -> tuple[np.ndarray, float]:
    from oceanrender.render.denoise import denoise_XYZ

    tic = time.perf_counter()
    out = denoise_XYZ(xyz) if features is None else denoise_XYZ(xyz, features.albedo, features.normal)
    return out, time.perf_counter() - tic


def adaptive_estimate(sequence, grader_of, budget: int, seed: int, samplers) -> tuple[np.ndarray, float, list]:
    """An adaptive frame of mean ``budget`` spp (a quarter of it uniform first) → (XYZ, seconds, pass history)."""
    from oceanrender.realtime.compare import delta_E_2000
    from oceanrender.render.adaptive import render_adaptive

    def error_of(a, b):  # ΔE00(A, B) / 2 ≈ the error of their mean, noise-dominated (module docstring)
        grader = grader_of(0.5 * (a + b))  # the frame's own white and adaptation, as the pipeline has them
        return 0.5 * delta_E_2000(grader.display(a), grader.display(b))

    tic = time.perf_counter()
    result = render_adaptive(samplers, error_of, ADAPTIVE_TARGET, initial_spp=max(4, budget // 4),
                             budget_spp=budget, seed=seed)
    return result.image(), time.perf_counter() - tic, result.history


def study_scene(scene_path: Path, args, workdir: Path) -> dict:
    from oceanrender.render.denoise import FeatureRenderer
    from oceanrender.render.pixels import PixelSampler
    from oceanrender.scene.settings import load_scene

    width, height = args.width, args.height
    store = coastal_store_for(scene_path, workdir)
    ladder = [s for s in (16, 32, 64, 128, 256, 512, 1024) if s <= args.max_spp]
    result = {"scene": scene_path.stem, "curves": {}, "throughput": {}}
    own = load_scene(scene_path).render

    # ---- Reference: unbiased (the scene's settings without the clamp).
    tic = time.perf_counter()
    scene, sequence, variant = build_sequence(scene_path, REFERENCE, width, height, args.variant, store)
    sequence.renderer.render_xyz(64, seed=99_999)
    half = int(args.reference_spp * REFERENCE_SHARE.get(scene_path.stem, 1.0)) // 128 * 64
    ref_a, _ = chunked_render(sequence.renderer, half, seed=10_000)
    ref_b, _ = chunked_render(sequence.renderer, half, seed=20_000)
    reference = 0.5 * (ref_a + ref_b)
    grader = Grader(sequence, scene, reference)
    result.update(reference_noise={k: v / 2 for k, v in grader.errors(ref_a, against=ref_b).items()},
                  reference_s=time.perf_counter() - tic, reference_spp=2 * half,
                  unclipped_fraction=float(grader.unclipped.mean()), render=own, variant=variant)
    features = FeatureRenderer.build(scene, sequence.faces, sequence.geometry(0), terrain=sequence.body.terrain())
    features.render(seed=0)
    tic = time.perf_counter()
    features = features.render(seed=1)
    result["feature_s"] = time.perf_counter() - tic
    del sequence

    for name, overrides in SETTINGS.items():
        if name == "before" and own.integrator == "split" and own.in_water_fraction == 1.0 \
                and own.roulette_depth == 5 and own.in_water_clamp == 0.0:
            continue  # the scene file's settings are the pre-issue-16 ones: "tuned" is "before"
        tic = time.perf_counter()
        scene, sequence, variant = build_sequence(scene_path, overrides, width, height, args.variant, store)
        renderer = sequence.renderer
        if name == "adaptive":
            samplers = [(PixelSampler(renderer.scene), 1.0)]
            if renderer.in_water is not None:
                samplers.append((PixelSampler(renderer.scene, renderer.in_water), renderer.in_water_fraction))
            for sampler, _ in samplers:  # compilation, outside the timings
                sampler.render(np.full((height, width), 1), seed=99_999)

            def grader_of(image, sequence=sequence, scene=scene):
                return Grader(sequence, scene, image)
        else:
            for chunk in CHUNKS:  # JIT compilation of both chunk sizes, outside the timings
                renderer.render_xyz(chunk, seed=99_999)
        setup = time.perf_counter() - tic
        rows = []
        for spp in ladder:
            history = None
            if name == "adaptive":
                image, seconds, history = adaptive_estimate(sequence, grader_of, spp, 100 * spp, samplers)
            else:
                image, seconds = chunked_render(renderer, spp, seed=100 * spp)
            plain, t_plain = denoise_timed(image)
            guided, t_guided = denoise_timed(image, features)
            rows.append({"spp": spp, "s": seconds, "s_plain": seconds + t_plain,
                         "s_guided": seconds + t_guided + result["feature_s"],
                         "noisy": grader.errors(image), "plain": grader.errors(plain),
                         "guided": grader.errors(guided), "history": history,
                         "level": float(image[..., 1].mean() / reference[..., 1].mean()),
                         "level_plain": float(plain[..., 1].mean() / reference[..., 1].mean())})
            print(f"  {scene_path.stem} {name} {spp} spp: {seconds:.1f} s, ΔE00 noisy {rows[-1]['noisy']['mean']:.2f}, "
                  f"OIDN {rows[-1]['plain']['mean']:.2f}", flush=True)
        last = rows[-1]
        result["throughput"][name] = width * height * last["spp"] / last["s"] / 1e6
        result["curves"][name] = {"rows": rows, "setup_s": setup}
    return result


def hd_frame(scene_path: Path, args, workdir: Path) -> dict:
    """1280×720: an unbiased reference, and one frame as the pipeline makes it (tuned, ``--hd-spp``, OIDN)."""
    from oceanrender.render.denoise import FeatureRenderer

    store = coastal_store_for(scene_path, workdir)
    scene, reference_sequence, _ = build_sequence(scene_path, REFERENCE, 1280, 720, args.variant, store)
    renderer = reference_sequence.renderer
    renderer.render_xyz(64, seed=99_999)
    tic = time.perf_counter()
    half = args.hd_reference_spp // 128 * 64
    ref_a, _ = chunked_render(renderer, half, seed=30_000)
    ref_b, _ = chunked_render(renderer, half, seed=40_000)
    reference = 0.5 * (ref_a + ref_b)
    reference_s = time.perf_counter() - tic
    grader = Grader(reference_sequence, scene, reference)
    del reference_sequence, renderer

    tic = time.perf_counter()
    scene, sequence, _ = build_sequence(scene_path, None, 1280, 720, args.variant, store)
    sequence.renderer.render_xyz(args.hd_spp, seed=1)  # compilation + a first frame
    features = FeatureRenderer.build(scene, sequence.faces, sequence.geometry(0), terrain=sequence.body.terrain())
    features.render(seed=0)
    first_s = time.perf_counter() - tic
    tic = time.perf_counter()
    frame, _ = sequence.renderer.render_xyz(args.hd_spp, seed=2)
    seconds = time.perf_counter() - tic
    plain, t_plain = denoise_timed(frame)
    tic = time.perf_counter()
    guide = features.render(seed=1)
    t_features = time.perf_counter() - tic
    guided, t_guided = denoise_timed(frame, guide)
    return {"spp": args.hd_spp, "reference_spp": 2 * half, "reference_s": reference_s, "first_s": first_s,
            "s": seconds, "denoise_s": t_plain, "guided_s": t_guided + t_features,
            "reference_noise": {k: v / 2 for k, v in grader.errors(ref_a, against=ref_b).items()},
            "unclipped_fraction": float(grader.unclipped.mean()),
            "noisy": grader.errors(frame), "plain": grader.errors(plain), "guided": grader.errors(guided),
            "level": float(frame[..., 1].mean() / reference[..., 1].mean()),
            "level_plain": float(plain[..., 1].mean() / reference[..., 1].mean())}


def corrected(measured: float, reference_error: float) -> float:
    """An error against a noisy reference less the reference's own, in quadrature (independent errors)."""
    return float(np.sqrt(max(measured**2 - reference_error**2, 0.0)))


def print_hd(hd: dict, name: str) -> None:
    noise = hd["reference_noise"]
    print(f"\n### 1280×720, {name}, tuned settings, {hd['spp']} spp\n")
    print(f"Reference {hd['reference_spp']} spp unclamped ({hd['reference_s']:.0f} s), its own error ≈ mean ΔE00 "
          f"{noise['mean']:.2f} ({noise['mean_unclipped']:.2f} unclipped); unclipped pixels "
          f"{100 * hd['unclipped_fraction']:.0f} %. Set-up of the frame's sequence (scene, white, compilation, "
          f"first frame, feature scene): {hd['first_s']:.0f} s.\n")
    print("| image | s | ΔE00 mean / p95 | unclipped mean / p95 | mean, less the reference's error "
          "(quadrature) | mean Y / ref |")
    print("|---|---:|---:|---:|---:|---:|")
    for key, label, extra, level in (("noisy", "noisy", 0.0, hd["level"]),
                                     ("plain", "OIDN colour", hd["denoise_s"], hd["level_plain"]),
                                     ("guided", "OIDN + albedo, normal", hd["guided_s"], float("nan"))):
        e = hd[key]
        print(f"| {label} | {hd['s'] + extra:.1f} | {e['mean']:.2f} / {e['p95']:.2f} | "
              f"{e['mean_unclipped']:.2f} / {e['p95_unclipped']:.2f} | "
              f"{corrected(e['mean'], noise['mean']):.2f} (unclipped {corrected(e['mean_unclipped'], noise['mean_unclipped']):.2f})"
              f" | {level:.4f} |")
    print(f"\nThroughput {1280 * 720 * hd['spp'] / hd['s'] / 1e6:.3f} M samples/s.")


def print_scene(result: dict, targets: list[float]) -> None:
    print(f"\n### {result['scene']} (variant {result['variant']}; "
          f"render settings tuned: in_water_fraction {result['render'].in_water_fraction:g}, "
          f"roulette_depth {result['render'].roulette_depth}, in_water_clamp {result['render'].in_water_clamp:g})\n")
    noise = result["reference_noise"]
    print(f"Reference {result['reference_spp']} spp, unclamped, {result['reference_s']:.0f} s; its own error ≈ mean ΔE00 {noise['mean']:.2f} "
          f"({noise['mean_unclipped']:.2f} unclipped); unclipped pixels {100 * result['unclipped_fraction']:.0f} %; "
          f"feature render {result['feature_s']:.2f} s.\n")
    print("| setting | spp | s | ΔE00 mean / p95, noisy | OIDN colour | OIDN + albedo, normal | "
          "unclipped: noisy | unclipped: OIDN colour | unclipped: OIDN + aux | mean Y / ref, noisy / OIDN |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, curve in result["curves"].items():
        for r in curve["rows"]:
            cells = [f"{r[k]['mean']:.2f} / {r[k]['p95']:.2f}" for k in ("noisy", "plain", "guided")]
            cells += [f"{r[k]['mean_unclipped']:.2f} / {r[k]['p95_unclipped']:.2f}" for k in ("noisy", "plain", "guided")]
            print(f"| {name} | {r['spp']} | {r['s']:.2f} | " + " | ".join(cells) + f" | {r['level']:.4f} / {r['level_plain']:.4f} |")
    print("\nThroughput (largest estimate): " + ", ".join(
        f"{k} {v:.3f} M samples/s" for k, v in result["throughput"].items())
        + (f"; tuned / before {result['throughput']['tuned'] / result['throughput']['before']:.2f}×"
           if "before" in result["throughput"] else "; tuned = before (the scene keeps the one-pass settings)"))
    print("\nTime to a mean ΔE00 over all pixels [s] (noisy curves extended by t^(−1/2); '–': not reached)\n")
    print("| target | " + " | ".join(f"{n} noisy | {n} OIDN | {n} OIDN + aux" for n in result["curves"])
          + " | volpath / ours, noisy | volpath / ours, best denoised |")
    print("|---:|" + "---:|" * (3 * len(result["curves"]) + 2))
    for target in targets:
        cells, best = [], {}
        for name, curve in result["curves"].items():
            rows = curve["rows"]
            for key, skey, extend in (("noisy", "s", True), ("plain", "s_plain", False),
                                      ("guided", "s_guided", False)):
                t = time_to_error(np.array([r[skey] for r in rows]), np.array([r[key]["mean"] for r in rows]),
                                  target, extend)
                cells.append("–" if t is None else f"{t:.1f}")
                best[(name, key)] = t
        ratios = []
        for keys in (("noisy",), ("plain", "guided")):
            def fastest(name):
                ts = [best[(name, k)] for k in keys if best[(name, k)] is not None]
                return min(ts) if ts else None
            ours = [t for t in (fastest(n) for n in ("tuned", "adaptive") if n in result["curves"]) if t]
            tv, tt = fastest("volpath"), (min(ours) if ours else None)
            ratios.append(f"{tv / tt:.1f}×" if tv and tt else ("> " + f"{result['curves']['volpath']['rows'][-1]['s'] / tt:.1f}×" if tt else "–"))
        print(f"| {target:g} | " + " | ".join(cells) + " | " + " | ".join(ratios) + " |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", default="open_ocean,coastal_beach,turbid_estuary")
    parser.add_argument("--resolution", default="320x180", help="WxH of the error study [px]")
    parser.add_argument("--reference-spp", type=int, default=1024, help="multiple of 128")
    parser.add_argument("--max-spp", type=int, default=256)
    parser.add_argument("--hd-spp", type=int, default=64, help="spp of the measured 1280x720 frame (0: none)")
    parser.add_argument("--hd-reference-spp", type=int, default=1024, help="its reference (multiple of 128)")
    parser.add_argument("--targets", default="3,2,1.5,1")
    parser.add_argument("--variant", default="auto", help="'auto' or a spectral variant, e.g. cuda_ad_spectral")
    args = parser.parse_args()
    args.width, args.height = (int(v) for v in args.resolution.lower().split("x"))
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")
    targets = [float(v) for v in args.targets.split(",")]
    print(f"# bench_quality at {args.resolution}, reference {args.reference_spp} spp, {os.cpu_count()} CPUs "
          f"({platform.processor() or platform.machine()}), {time.strftime('%Y-%m-%d')}", flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        workdir = Path(tmp)
        scenes = [ROOT / "scenes" / f"{name}.toml" for name in args.scenes.split(",")]
        for path in scenes:  # each scene's tables as soon as it is done
            print_scene(study_scene(path, args, workdir), targets)
            sys.stdout.flush()
        if args.hd_spp:
            print_hd(hd_frame(scenes[0], args, workdir), scenes[0].stem)


if __name__ == "__main__":
    main()
