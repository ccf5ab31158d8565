"""Issue 40: the cost of shading every water hit from the sea's fields, side by side with vertex shading.

Run: ``.venv/bin/python benchmarks/bench_pixel_detail.py [--width 1280 --height 720 --frames 2]``.

The default scene at the given size and its own spp (24), in one process: for each
``[render] surface_shading`` ("vertex", the shading before issue 40, and "fields")
a sequence is built, frame 0 rendered once (JIT compilation, the foam's history),
then frames 1..N timed. Prints a Markdown table for BENCHMARKS.md: per-frame seconds
of geometry (the fields and foam grid included) and render, and the ratio fields / vertex.
"""

from __future__ import annotations

import argparse
import platform
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=720)
    parser.add_argument("--frames", type=int, default=2, help="frames timed per mode, after one warm-up frame")
    args = parser.parse_args()
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")

    from oceanrender.pipeline import STAGES, Sequence, frame_paths
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene, with_overrides

    base = load_scene(ROOT / "scenes" / "open_ocean.toml")
    runtime = activate_variant(base.render.variant)
    rows = {}
    for mode in ("vertex", "fields"):
        scene = with_overrides(base, render={"surface_shading": mode},
                               output={"resolution": [args.width, args.height]})
        tic = time.perf_counter()
        sequence = Sequence(scene, runtime.variant)
        setup = time.perf_counter() - tic
        with tempfile.TemporaryDirectory() as tmp:
            warm = {s: 0.0 for s in STAGES}
            tic = time.perf_counter()
            sequence.render_frame(0, frame_paths(tmp, 0), warm)
            first = time.perf_counter() - tic
            seconds = {s: 0.0 for s in STAGES}
            tic = time.perf_counter()
            for frame in range(1, args.frames + 1):
                sequence.render_frame(frame, frame_paths(tmp, frame), seconds)
            wall = (time.perf_counter() - tic) / args.frames
        rows[mode] = (setup, first, {s: v / args.frames for s, v in seconds.items()}, wall)
        del sequence
    print(f"# open_ocean: {args.width}x{args.height}, {base.output.spp} spp, variant {runtime.variant}, "
          f"{platform.processor() or platform.machine()}; {args.frames} frames timed per mode after one warm-up")
    print()
    print("| surface_shading | set-up [s] | first frame (JIT, foam history) [s] | meter (with the frame's geometry) "
          "[s/frame] | geometry [s/frame] | update [s/frame] | render [s/frame] | vision, files [s/frame] "
          "| frame, wall [s] |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for mode, (setup, first, per, wall) in rows.items():
        rest = per["denoise"] + per["vision"] + per["write"]
        print(f"| {mode} | {setup:.1f} | {first:.1f} | {per['meter']:.2f} | {per['geometry']:.2f} "
              f"| {per['update']:.2f} | {per['render']:.2f} | {rest:.2f} | {wall:.2f} |")
    ratio = rows["fields"][3] / rows["vertex"][3]
    print()
    print(f"fields / vertex, wall per frame: **{ratio:.2f}×** (goal ≤ 1.3×); render alone: "
          f"{rows['fields'][2]['render'] / rows['vertex'][2]['render']:.2f}×")


if __name__ == "__main__":
    main()
