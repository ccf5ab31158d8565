"""The run-time estimate of ``oceanrender render``'s first line against the measured run, side by side.

Each shipped scene below renders ``FRAMES`` frames at ``RESOLUTION`` in a fresh
``oceanrender render`` process (the CLI exactly as a user runs it; kernels already
in drjit's cache, as on any second run). The first line's estimate
(``oceanrender.checks.time_estimate``) is set beside the wall time and the stage
times the run reports; the ratio measured / estimated is the estimate's error.
The per-sample constants of ``oceanrender/checks.py`` are fitted from the
render stage of these runs: seconds per sample of the camera's pass and per
expected in-water vertex of the in-water lobe (``--fit`` prints the fit).

Usage: ``.venv/bin/python benchmarks/bench_time_estimate.py [--fit]`` (about 6 minutes
on the 2-core machine); the table goes into BENCHMARKS.md, "Time estimate".
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
#: (scene, resolution, frames): six scenes at a small size, then `make render` as it is (the default scene).
RUNS = [(name, "160x90", "0:2") for name in ("open_ocean", "glitter_low_sun", "clear_open_ocean", "green_coastal",
                                            "turbid_estuary", "under_water")] + [("open_ocean", "320x180", "0:3")]


def run(scene: str, resolution: str, frames: str, out: Path) -> dict:
    """Wall time, the estimate and the reported stages of one render."""
    argv = [sys.executable, "-m", "oceanrender", "render", str(ROOT / "scenes" / f"{scene}.toml"),
            "--resolution", resolution, "--frames", frames, "--out", str(out), "--no-progress"]
    tic = time.perf_counter()
    done = subprocess.run(argv, capture_output=True, text=True, cwd=ROOT, check=True)
    wall = time.perf_counter() - tic
    lines = done.stdout.splitlines()
    estimate = re.search(r"estimated about (.+?) \(set-up (.+?), then (.+?) per frame\)", lines[0])
    stages = dict(re.findall(r"(\w+) ([0-9.]+) s", lines[-1].split("(setup", 1)[1]))
    setup = float(re.search(r"setup ([0-9.]+) s", lines[-1]).group(1))
    return {"wall": wall, "estimate": estimate.groups(), "setup": setup,
            **{k: float(v) for k, v in stages.items()}}


def seconds(text: str) -> float:
    value, unit = text.split()
    return float(value) * {"s": 1.0, "min": 60.0, "h": 3600.0, "days": 86400.0}[unit]


def main() -> None:
    sys.path.insert(0, str(ROOT))
    from oceanrender.checks import expected_water_vertices, time_estimate  # noqa: PLC0415
    from oceanrender.pipeline import meter_samples  # noqa: PLC0415
    from oceanrender.scene import load_scene, with_overrides  # noqa: PLC0415

    rows, fit = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for index, (name, resolution, frames) in enumerate(RUNS):
            width, height = map(int, resolution.split("x"))
            start, end = map(int, frames.split(":"))
            measured = run(name, resolution, frames, Path(tmp) / f"{index}")
            scene = with_overrides(load_scene(ROOT / "scenes" / f"{name}.toml"),
                                   output={"resolution": (width, height), "frames": (start, end)})
            estimate = time_estimate(scene, "llvm_ad_spectral", meter_samples(width, height))
            vertices = expected_water_vertices(scene)
            samples = width * height * scene.output.spp * (end - start)
            fraction = scene.render.in_water_fraction
            # Per-frame render seconds per sample = (a + b · fraction · vertices) / cores.
            cores = len(os.sched_getaffinity(0))
            calls = (end - start) * (2 if scene.render.in_water_fraction < 1 else 1)
            # Render stage = calls · c0 + samples · (a + b · fraction · vertices) / cores.
            fit.append((calls, samples / cores, samples / cores * fraction * vertices, measured["render"]))
            rows.append((name, resolution, frames, scene.output.spp, fraction, vertices, estimate.total,
                         measured["wall"], measured["render"], measured["meter"], measured["geometry"],
                         measured["setup"]))
    print(f"{len(os.sched_getaffinity(0))} cores, llvm_ad_spectral")
    print("| scene | size | frames | spp | in-water fraction | expected in-water vertices | estimated [s] | "
          "measured wall [s] | measured / estimated | render | meter | geometry | set-up |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, size, frames, spp, fraction, vertices, est, wall, render, meter, geometry, setup in rows:
        print(f"| {name} | {size} | {frames} | {spp} | {fraction:g} | {vertices:.1f} | {est:.0f} | {wall:.0f} | "
              f"{wall / est:.2f} | {render:.1f} | {meter:.1f} | {geometry:.1f} | {setup:.1f} |")
    if "--fit" in sys.argv:
        a = np.array(fit)
        (call, camera, water), *_ = np.linalg.lstsq(a[:, :3], a[:, 3], rcond=None)
        print(f"fit: SECONDS_PER_RENDER_CALL = {call:.3g}, SECONDS_PER_SAMPLE_CORE = {camera:.3g}, "
              f"SECONDS_PER_WATER_VERTEX_CORE = {water:.3g}")


if __name__ == "__main__":
    main()
