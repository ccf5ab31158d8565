"""Grading a shader (issue 22): the GLSL shader on the software rasteriser beside the numpy model, per frame.

Run: ``.venv/bin/python benchmarks/bench_shader.py REFERENCE_DIR [REFERENCE_DIR ...]`` on reference sets
written by ``oceanrender reference`` (docs/realtime.md).

Per set, in one run: the issue's numbers beside their references — the shipped shader against the
path-traced reference, beside the numpy model's own figure, the copy with a wrong Fresnel factor (the
LUT looked up at 1 − μ) and the reference's noise floor — then the shipped shader's image of each frame (textures uploaded, drawn, read back;
best and median of 5), the numpy model of the same frame with the same ripples (best and median
of 3), their ratio, the agreement between the two (ΔE2000 over the water pixels), and one whole
grading with its γ fit (``validate_shader``: every frame, ΔE maps, ~35 shader runs of the fit).
Prints lines to paste into BENCHMARKS.md.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

from bench_optics import timed  # noqa: E402 (a sibling script: benchmarks/ is on sys.path)

#: The deliberately broken copy of docs/realtime.md (scripts/shader_validation_sheet.py makes the same).
FRESNEL_LINE = "clamp(mu, 0.0, 1.0)).r, 0.0, 1.0);  // FRESNEL LOOKUP"
WRONG_FRESNEL_LINE = "clamp(1.0 - mu, 0.0, 1.0)).r, 0.0, 1.0);  // BROKEN"


def main() -> None:
    from oceanrender.realtime.glsl import GLContext, shipped_shader
    from oceanrender.realtime.validate import ShaderRunner, read_reference_set, validate_shader

    context = GLContext()
    print(f"OpenGL: {context.renderer}; load average {os.getloadavg()[0]:.1f}")
    for folder in map(Path, sys.argv[1:]):
        references = read_reference_set(folder)
        runner = ShaderRunner(context, shipped_shader().read_text(), "water.frag", references.luts, 1.0)
        view = references.views[0]
        height, width = view.gbuffer.shape
        gamma = references.luts.gamma
        runner.image(view, gamma)  # warm-up: llvmpipe compiles the shader on first draw
        shader_best, shader_median = timed(lambda: runner.image(view, gamma), repeats=5)
        model_best, model_median = timed(lambda: runner.model(view, gamma), repeats=3)
        tic = time.perf_counter()
        grade = validate_shader(runner, references)
        whole = time.perf_counter() - tic
        source = shipped_shader().read_text()
        wrong = ShaderRunner(context, source.replace(FRESNEL_LINE, WRONG_FRESNEL_LINE), "wrong", references.luts, 1.0)
        broken = validate_shader(wrong, references, fit_grid=3)
        wrong.release()
        noise = (references.report.get("reference_noise") or {}).get("water", {}).get("mean", float("nan"))
        print(f"{references.report['scene']}: water dE2000 vs reference: shipped shader {grade.before.mean:.2f}, "
              f"numpy model {grade.model_vs_reference.mean:.2f}, wrong-Fresnel copy {broken.before.mean:.2f} "
              f"(clearly worse: {broken.before.mean > grade.before.mean + 1.0}); reference two-seed noise {noise:.2f}; "
              f"shader vs numpy model {grade.shader_vs_model.mean:.4f} (issue: <= 0.5)")
        print(f"{references.report['scene']} ({folder}), {width}x{height}, {len(references.views)} frame(s): "
              f"shader image best {shader_best * 1e3:.0f} ms, median {shader_median * 1e3:.0f} ms; numpy model best "
              f"{model_best * 1e3:.0f} ms, median {model_median * 1e3:.0f} ms (numpy / shader {model_best / shader_best:.1f}x); "
              f"shader vs model water dE2000 mean {grade.shader_vs_model.mean:.4f}, max {grade.shader_vs_model.max:.3f}; "
              f"whole grading with gamma fit {whole:.1f} s")
        runner.release()
    context.release()


if __name__ == "__main__":
    main()
