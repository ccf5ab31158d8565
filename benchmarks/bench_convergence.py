"""Time to quality in one call (issue 42): the error curve, its outliers and exponent, the pipeline's frame.

Run: ``python benchmarks/bench_convergence.py [--scene scenes/open_ocean.toml] [--size 320x180]
[--variant auto] [--spp 16,64,256,1024] [--reference-spp 4096] [--frames 3] [--out DIR]``
and, for arrays another machine wrote (a GPU run), ``python benchmarks/bench_convergence.py --grade DIR``
to add the denoised columns here (OIDN runs on the CPU; it does not travel to the GPU machine).
A GPU run at ``--size 1920x1080 --reference-spp 2048 --spp 64,256,1024`` fits one 6-minute call
(docs/time_to_quality.md gives the command that carries it there).

Method
------
* Frame 0 of the scene at ``--size``, the scene's own ``[render]`` settings (sampler, two passes).
* Reference: the mean of independent 64-spp frames (seeds 10 000 …), ``--reference-spp`` in all; its
  own error is ΔE00(A, B) / 2 of its two halves (noise-dominated: σ(A − B) = 2 σ(mean)).
* Curve: one frame per ``--spp`` value, as the mean of 64-spp frames (16: one 16-spp frame), seeds
  20 000 … (the mean of k independent n-spp frames of a box-filtered film is distributed as one
  k·n-spp frame, and a new spp value costs a JIT compilation). Seconds: the renders' wall time, warm.
* Errors: each image → the scene's vision model with the *reference's* adapting white and adaptation
  luminance → display sRGB → CIELAB → CIEDE2000 (colour-science) per pixel: mean, 95th percentile,
  share of pixels above 20; also less the reference's own error in quadrature ("noise").
* Exponent: the least-squares slope of log(noise) against log(spp) over the points from 64 to 1024
  spp; an unbiased estimator of finite variance gives −0.5.
* Denoised (``--denoise`` here or ``--grade``): OIDN colour only
  (:func:`oceanrender.render.denoise.denoise_XYZ`) and its measured bias (mean Y / the reference's).
* Pipeline: ``Sequence.compute_frame`` of frames 0 … ``--frames``−1 at the scene's spp and the same
  size, before anything else (as a fresh run: kernels compiled on first use, or read from Dr.Jit's
  cache on disk): seconds per stage, the first frame apart.
* ``--out``: ``reference.npy``, ``spp_<n>.npy`` (XYZ, float32, cd m⁻²), ``grading.npz`` (the adapting
  white, the adaptation luminance) and ``result.json``.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

#: ΔE00 above which a pixel is an outlier (issue 42) [-].
OUTLIER_DELTA_E = 20.0
#: spp of the frames the reference and the curve are built from [-].
CHUNK = 64


def noise_only(measured: float, reference_error: float) -> float:
    """An error less the reference's own, in quadrature (0 where the reference's is larger) [-]."""
    return float(np.sqrt(max(measured ** 2 - reference_error ** 2, 0.0)))


def fitted_exponent(spp: list[int], errors: list[float]) -> float:
    """Least-squares slope of log(error) against log(spp) [-] (−0.5 for a finite-variance estimator)."""
    x, y = np.log(np.asarray(spp, float)), np.log(np.maximum(np.asarray(errors, float), 1e-12))
    return float(np.polyfit(x, y, 1)[0])


def delta_e_stats(de: np.ndarray) -> dict[str, float]:
    """Mean, 95th percentile and the share above :data:`OUTLIER_DELTA_E` [%] of a ΔE00 map."""
    return {"mean": float(de.mean()), "p95": float(np.percentile(de, 95)),
            "above_20_pct": float(100.0 * np.mean(de > OUTLIER_DELTA_E))}


class Grading:
    """The scene's vision model with the reference's adapting white and adaptation luminance."""

    def __init__(self, vision, white: np.ndarray, adaptation: float, reference: np.ndarray):
        self.vision, self.white, self.adaptation = vision, np.asarray(white, float), float(adaptation)
        self.target = self.display(reference)

    def display(self, xyz: np.ndarray) -> np.ndarray:
        return self.vision.apply(xyz, self.white, self.adaptation)

    def delta_e(self, xyz: np.ndarray, against: np.ndarray | None = None) -> np.ndarray:
        from oceanrender.realtime.compare import delta_E_2000

        return delta_E_2000(self.display(xyz), self.target if against is None else self.display(against))


def mean_of_frames(renderer, spp: int, seed: int) -> tuple[np.ndarray, float, list[np.ndarray]]:
    """(mean XYZ of ``spp`` samples per pixel, render seconds, the frames) from 64-spp frames (16: one)."""
    chunk = CHUNK if spp >= CHUNK else spp
    frames, seconds = [], 0.0
    for i in range(max(1, spp // chunk)):
        tic = time.perf_counter()
        xyz, _ = renderer.render_xyz(chunk, seed=seed + i)
        seconds += time.perf_counter() - tic
        frames.append(xyz)
    return np.mean(frames, axis=0), seconds, frames


def pipeline_frames(scene, variant: str, count: int) -> dict:
    """Seconds per stage of ``count`` frames of a fresh sequence (``compute_frame``), the first apart."""
    from oceanrender.pipeline import Sequence

    tic = time.perf_counter()
    sequence = Sequence(scene, variant)
    setup = time.perf_counter() - tic
    frames = []
    for frame in range(count):
        tic = time.perf_counter()
        rendered = sequence.compute_frame(frame)
        total = time.perf_counter() - tic
        frames.append({"total": round(total, 2), **{k: round(v, 2) for k, v in rendered.seconds.items()}})
    return {"setup": round(setup, 2), "frames": frames}


def render_curve(args) -> dict:
    from oceanrender.pipeline import adaptation_luminance
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene, with_overrides
    from bench_quality import build_sequence

    width, height = (int(v) for v in args.size.split("x"))
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    pipeline = None
    if args.frames > 0:  # first, as a fresh run would: a later sequence in the process recompiles its kernels
        scene = with_overrides(load_scene(Path(args.scene)), output={"resolution": [width, height]},
                               render={} if args.variant == "auto" else {"variant": args.variant})
        pipeline = pipeline_frames(scene, activate_variant(scene.render.variant).variant, args.frames)
        print(json.dumps({"pipeline": pipeline}), flush=True)
    tic = time.perf_counter()
    scene, sequence, variant = build_sequence(Path(args.scene), None, width, height, args.variant, None)
    renderer = sequence.renderer
    sequence.point(0)
    renderer.update_water(sequence.geometry(0))
    result = {"scene": Path(args.scene).stem, "size": [width, height], "variant": variant,
              "sampler": scene.render.sampler, "setup_s": round(time.perf_counter() - tic, 1)}
    compile_s = 0.0
    for spp in sorted({min(s, CHUNK) for s in args.spp}):  # one warm-up per kernel (spp value)
        tic = time.perf_counter()
        renderer.render_xyz(spp, seed=1)
        compile_s += time.perf_counter() - tic
    result["warm_up_s"] = round(compile_s, 1)

    reference, seconds, frames = mean_of_frames(renderer, args.reference_spp, 10_000)
    half_a, half_b = np.mean(frames[0::2], axis=0), np.mean(frames[1::2], axis=0)
    adaptation = adaptation_luminance(scene, reference, sequence.white_xyz)
    grading = Grading(sequence.vision, sequence.white_xyz, adaptation, reference)
    reference_error = float(grading.delta_e(half_a, half_b).mean() / 2.0)
    np.save(out / "reference.npy", reference.astype(np.float32))
    np.savez(out / "grading.npz", white=np.asarray(sequence.white_xyz, float), adaptation=adaptation)
    result.update(reference_spp=args.reference_spp, reference_s=round(seconds, 1),
                  reference_error=round(reference_error, 3))
    curve = []
    for spp in args.spp:
        image, seconds, _ = mean_of_frames(renderer, spp, 20_000 + 1000 * spp)
        np.save(out / f"spp_{spp}.npy", image.astype(np.float32))
        stats = delta_e_stats(grading.delta_e(image))
        curve.append({"spp": spp, "render_s": round(seconds, 2), **{k: round(v, 4) for k, v in stats.items()},
                      "noise": round(noise_only(stats["mean"], reference_error), 4),
                      "mean_Y_over_reference": round(float(image[..., 1].mean() / reference[..., 1].mean()), 5)})
        print(json.dumps(curve[-1]), flush=True)
    result["curve"] = curve
    if pipeline is not None:
        result["pipeline"] = pipeline
    return result


def grade_arrays(folder: Path, scene_path: Path, denoise: bool) -> dict:
    """Errors of the arrays in ``folder`` (noisy and, with ``denoise``, OIDN colour only) against its reference."""
    from oceanrender.pipeline import vision_for_scene
    from oceanrender.scene import load_scene

    reference = np.load(folder / "reference.npy").astype(np.float64)
    saved = np.load(folder / "grading.npz")
    grading = Grading(vision_for_scene(load_scene(scene_path)), saved["white"], float(saved["adaptation"]),
                      reference)
    rows = []
    for path in sorted(folder.glob("spp_*.npy"), key=lambda p: int(p.stem.split("_")[1])):
        image = np.load(path).astype(np.float64)
        row = {"spp": int(path.stem.split("_")[1]), **{k: round(v, 4) for k, v in
                                                        delta_e_stats(grading.delta_e(image)).items()}}
        if denoise:
            from oceanrender.render.denoise import CHROMA_RADIUS_PX, denoise_frame

            for label, radius in (("denoised", 0), ("chroma", CHROMA_RADIUS_PX)):
                tic = time.perf_counter()
                clean = denoise_frame(image, radius)
                row[f"{label}_s"] = round(time.perf_counter() - tic, 2)
                row.update({f"{label}_{k}": round(v, 4) for k, v in delta_e_stats(grading.delta_e(clean)).items()})
                for c, name in enumerate("XYZ"):
                    row[f"{label}_mean_{name}_over_reference"] = round(
                        float(clean[..., c].mean() / reference[..., c].mean()), 5)
        rows.append(row)
    return {"graded": rows}


def summary(result: dict) -> dict:
    """The exponent of the noisy error over 64…1024 spp, raw and less the reference's own error."""
    points = [c for c in result.get("curve", []) if 64 <= c["spp"] <= 1024]
    if len(points) >= 2:
        spp = [c["spp"] for c in points]
        result["exponent_raw"] = round(fitted_exponent(spp, [c["mean"] for c in points]), 3)
        result["exponent_noise"] = round(fitted_exponent(spp, [c["noise"] for c in points]), 3)
    return result


def markdown(result: dict) -> str:
    graded = {row["spp"]: row for row in result.get("graded", [])}
    lines = [f"{result.get('scene', '')} {result.get('size', '')} {result.get('variant', '')}, sampler "
             f"{result.get('sampler', '')}; reference {result.get('reference_spp')} spp (own error "
             f"{result.get('reference_error')}); exponent {result.get('exponent_raw')} raw, "
             f"{result.get('exponent_noise')} less the reference's error", "",
             "| spp | render s | ΔE00 mean | p95 | > 20 | noise | OIDN mean / p95 | + chroma mean / p95 | "
             "+ chroma s | + chroma bias X, Y, Z |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    nan = float("nan")
    for c in result.get("curve", []):
        g = graded.get(c["spp"], {})
        bias = ", ".join(f"{100 * (g.get(f'chroma_mean_{n}_over_reference', nan) - 1):+.2f}" for n in "XYZ")
        lines.append(f"| {c['spp']} | {c['render_s']} | {c['mean']:.2f} | {c['p95']:.2f} | {c['above_20_pct']:.3f} % | "
                     f"{c['noise']:.2f} | {g.get('denoised_mean', nan):.2f} / {g.get('denoised_p95', nan):.2f} | "
                     f"{g.get('chroma_mean', nan):.2f} / {g.get('chroma_p95', nan):.2f} | "
                     f"{g.get('chroma_s', nan)} | {bias} % |")
    for i, frame in enumerate(result.get("pipeline", {}).get("frames", [])):
        lines.append(f"\nframe {i}: " + ", ".join(f"{k} {v} s" for k, v in frame.items()))
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--variant", default="auto")
    parser.add_argument("--spp", default="16,64,256,1024", type=lambda t: [int(v) for v in t.split(",")])
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--out", default=str(ROOT / "outputs" / "convergence"))
    parser.add_argument("--denoise", action="store_true", help="OIDN the curve's images here (needs pyoidn)")
    parser.add_argument("--grade", default=None, help="grade the arrays of an earlier run in this folder")
    args = parser.parse_args()
    if args.reference_spp % (2 * CHUNK) or any(s > CHUNK and s % CHUNK for s in args.spp):
        parser.error(f"--reference-spp must be a multiple of {2 * CHUNK}, --spp values above {CHUNK} of {CHUNK}")
    if args.grade:
        folder = Path(args.grade)
        result = json.loads((folder / "result.json").read_text())
        result.update(grade_arrays(folder, Path(args.scene), denoise=True))
    else:
        result = render_curve(args)
        if args.denoise:
            result.update(grade_arrays(Path(args.out), Path(args.scene), denoise=True))
        folder = Path(args.out)
    result = summary(result)
    (folder / "result.json").write_text(json.dumps(result, indent=1))
    print(markdown(result))


if __name__ == "__main__":
    main()
