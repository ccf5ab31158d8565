"""Baking the real-time model's LUTs (issue 6 goal: T0 over 256 depths + T1 over 256 × 256, ≤ 2 s here).

Run: ``.venv/bin/python benchmarks/bench_luts.py [SCENE]`` (default ``scenes/coastal_beach.toml``).

The scene's sun and sky irradiance and adapting white are measured once with
Mitsuba (not timed: the same measurement serves every bake). Timed, best and
median of 10 runs: T0 + T1 over the 95 wavelengths 360–830 nm at 5 nm, i.e.
four-flux over 256 depths, the e^{−c l} attenuation over 256 path lengths, the
CIE 1931 integration and the vision operator Φ — and, for information, the
whole LUT set without the Mitsuba sky evaluation (Fresnel, sky map Φ, ripple
maps, albedo colours) and the sky evaluation itself. Prints one line to paste
into BENCHMARKS.md.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import numpy as np
from bench_optics import timed  # noqa: E402 (a sibling script: benchmarks/ is on sys.path)

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    from oceanrender.scene import load_scene, with_overrides
    from oceanrender.pipeline import vision_for_scene
    from oceanrender.realtime.bake import BakeSettings, bake_lut_set, measure_scene_light, water_column, lut_axes
    from oceanrender.realtime.luts import VisionState, bake_T0, bake_T1
    from oceanrender.realtime.sky import sky_radiance_spectra
    from oceanrender.realtime.luts import envmap_directions
    from oceanrender.runtime.variants import activate_variant

    path = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "scenes" / "coastal_beach.toml"
    runtime = activate_variant("auto")
    scene = with_overrides(load_scene(path), "benchmark", render={"white_spp": 256})
    settings = BakeSettings()
    light = measure_scene_light(scene, settings)
    column = water_column(scene, light)
    phi = VisionState(vision_for_scene(scene), light.white_XYZ, 4000.0)
    depth, path_axis, _ = lut_axes(settings)
    R0 = np.zeros_like(column.wavelengths)

    def T0_T1():
        bake_T0(column, phi, depth, R0)
        bake_T1(column, phi, depth, path_axis, R0)

    T0_T1()  # warm-up (colour-science tables, numpy)
    best, median = timed(T0_T1)
    whole_best, whole_median = timed(lambda: bake_lut_set(scene, light, 4000.0, "benchmark", settings), repeats=5)
    directions = envmap_directions(*settings.sky_size)
    sky_best, sky_median = timed(lambda: sky_radiance_spectra(scene.sun, directions, settings.wavelengths), repeats=3)
    load = os.getloadavg()[0]
    print(f"scene {scene.name}, {len(column.wavelengths)} wavelengths, variant {runtime.variant}, "
          f"load average {load:.1f}")
    print(f"T0 (256 depths) + T1 (256 x 256): best {best:.3f} s, median {median:.3f} s (goal <= 2 s)")
    print(f"whole LUT set without the sky evaluation: best {whole_best:.2f} s, median {whole_median:.2f} s")
    print(f"sky radiance 512 x 256 x 95 from Mitsuba's sunsky: best {sky_best:.2f} s, median {sky_median:.2f} s")
    print(f"| T0 + T1 bake, 95 wavelengths, 256 + 256 x 256 texels | {1e3 * best:.0f} | {1e3 * median:.0f} "
          f"| <= 2000 ms | (load {load:.1f}; whole set {whole_median:.2f} s, sky map {sky_median:.2f} s)")


if __name__ == "__main__":
    main()
