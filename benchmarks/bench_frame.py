"""Time per frame of the default scene at preview settings, split by stage.

Run: ``make bench`` (or ``.venv/bin/python benchmarks/bench_frame.py [SCENE] [--frames N]``).
Renders into a temporary folder (nothing in outputs/ is touched) and prints a
Markdown table for BENCHMARKS.md: seconds per frame for geometry, scene
update, render, vision and write, the non-render share, and samples per second.
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
    parser.add_argument("scene", nargs="?", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--frames", type=int, default=3, help="frames to time (after one warm-up frame)")
    parser.add_argument("--no-foam", action="store_true", help="time with [foam] enabled = false")
    parser.add_argument("--patch", action="store_true", help="time with [mesh] kind = 'patch' (one FFT patch)")
    args = parser.parse_args()
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")

    from oceanrender.scene import load_scene, with_overrides
    from oceanrender.pipeline import STAGES, Sequence, frame_paths
    from oceanrender.runtime.variants import activate_variant

    runtime = activate_variant(load_scene(args.scene).render.variant)
    scene = load_scene(args.scene)
    scene = with_overrides(scene, foam={"enabled": False} if args.no_foam else {},
                           mesh={"kind": "patch"} if args.patch else {})
    tic = time.perf_counter()
    sequence = Sequence(scene, runtime.variant)
    setup = time.perf_counter() - tic
    width, height = sequence.resolution
    with tempfile.TemporaryDirectory() as tmp:
        warm = {s: 0.0 for s in STAGES}
        tic = time.perf_counter()
        sequence.render_frame(0, frame_paths(tmp, 0), warm)  # JIT compilation happens here
        first = time.perf_counter() - tic
        seconds = {s: 0.0 for s in STAGES}
        for frame in range(1, args.frames + 1):
            sequence.render_frame(frame, frame_paths(tmp, frame), seconds)
    per_frame = {s: v / args.frames for s, v in seconds.items()}
    total = sum(per_frame.values())
    samples = width * height * sequence.spp
    print(f"# {Path(args.scene).name}: {width}x{height}, {sequence.spp} spp, variant {runtime.variant}, "
          f"ocean {scene.ocean.cascades} x {scene.ocean.resolution}², mesh {scene.mesh.kind} "
          f"({sequence.body.vertex_count} vertices), foam {'on' if scene.foam.enabled else 'off'}, "
          f"integrator {scene.render.integrator}, {platform.processor() or platform.machine()}")
    print(f"setup (scene load, adapting white) {setup:.2f} s; first frame incl. JIT {first:.2f} s")
    print()
    print("| stage | s / frame | share |")
    print("|---|---:|---:|")
    for stage in STAGES:
        print(f"| {stage} | {per_frame[stage]:.3f} | {100 * per_frame[stage] / total:.1f} % |")
    print(f"| **total** | **{total:.3f}** | 100 % |")
    print()
    print(f"non-render share: {100 * (total - per_frame['render']) / total:.2f} % of frame time")
    print(f"render throughput: {samples / per_frame['render'] / 1e6:.3f} M samples/s "
          f"({samples} samples per frame, mean of {args.frames} frames)")


if __name__ == "__main__":
    main()
