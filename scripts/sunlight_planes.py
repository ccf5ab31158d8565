"""Issue 41: the sun's beam under a shipped scene's sea, on horizontal planes (docs/sunlight.md).

Light tracing (:mod:`oceanrender.surface.sunlight`): one sun ray per rest point of a square
window of the sea (every wave of the cascades, no level filtering), refracted at the
displaced surface's own normal, landed on planes below and splatted into square cells.
Writes docs/images/sunlight/<scene>_planes.png (one panel per depth, each scaled to its
own mean irradiance: white = 4× the mean) and prints per depth the mean irradiance over
the beam's irradiance on a horizontal plane above the water (the window is small against the
long waves, whose horizontal displacement spreads or gathers it locally: the energy check is on
a periodic patch, tests/surface/test_sunlight.py), the contrast (std / mean) and the brightest
cell.

Usage: python scripts/sunlight_planes.py [--scene scenes/open_ocean.toml] [--window 6] [--ray 0.004]
       [--refine 4] [--cell 0.01] [--depths 1,2,4,8] [--elevation DEG]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--window", type=float, default=6.0, help="side of the square window of planes [m]")
    parser.add_argument("--ray", type=float, default=0.004, help="rest spacing of the sun rays [m]")
    parser.add_argument("--cell", type=float, default=0.01, help="side of the irradiance cells [m]")
    parser.add_argument("--depths", default="1,2,4,8", help="depths of the planes below the mean level [m]")
    parser.add_argument("--refine", type=int, default=4, help="rays per ray spacing, in x and in y, inside each quad")
    parser.add_argument("--elevation", type=float, default=None, help="the sun's elevation [deg] (the scene's)")
    parser.add_argument("--out", default=str(ROOT / "docs" / "images" / "sunlight"))
    args = parser.parse_args()

    import imageio.v3 as iio

    from oceanrender.render.scene import sun_direction
    from oceanrender.scene import load_scene
    from oceanrender.surface.open_sea import WaterBody
    from oceanrender.surface.sunlight import facet_power, refined_plane_irradiance, refracted_beam

    scene = load_scene(Path(args.scene))
    elevation = scene.sun.elevation if args.elevation is None else args.elevation
    sun = sun_direction(elevation, scene.sun.azimuth)
    n_water = 1.34
    depths = np.array([float(d) for d in args.depths.split(",")])
    # rays from a window larger by how far the deepest plane's rays travel sideways (flat sea)
    tan_t = np.hypot(sun[0], sun[1]) / n_water / np.sqrt(1 - (np.hypot(sun[0], sun[1]) / n_water) ** 2)
    margin = depths.max() * tan_t + 0.5
    half = args.window / 2 + margin
    x0 = np.arange(-half, half, args.ray) + args.ray / 2
    xx, yy = np.meshgrid(x0, x0)
    centre = np.array(scene.camera.target[:2], float) if scene.camera.target is not None else np.zeros(2)
    sea = WaterBody(scene).sea
    t = 0.0
    surface = sea.sample(xx.ravel() + centre[0], yy.ravel() + centre[1], t, None)
    points = np.column_stack([xx.ravel() + surface.displacement[:, 0], yy.ravel() + surface.displacement[:, 1],
                              surface.displacement[:, 2]])
    normals = surface.normals
    area = normals * (surface.jacobian / normals[:, 2])[:, None]  # ∂p/∂x₀ × ∂p/∂y₀ = n det J / n_z
    directions, transmittance = refracted_beam(normals, sun, n_water)
    power = facet_power(area, sun, 1.0, args.ray**2) * transmittance
    # the beam's irradiance on a horizontal plane above the water (E_n = 1)
    above = sun[2]
    cells = int(round(args.window / args.cell))
    panels = []
    # each plane's window: under the rays' window, shifted with the refracted beam (flat sea)
    flat_d, _ = refracted_beam(np.array([[0.0, 0.0, 1.0]]), sun, n_water)
    for depth in depths:
        shift = flat_d[0, :2] * depth / -flat_d[0, 2]
        origin = (shift[0] - args.window / 2, shift[1] - args.window / 2)
        shape = xx.shape
        irradiance = refined_plane_irradiance(points.reshape(*shape, 3), directions.reshape(*shape, 3),
                                              power.reshape(shape), [-depth], origin, args.cell, (cells, cells),
                                              refine=args.refine)[0]
        print(f"depth {depth:g} m: mean {irradiance.mean() / above:.3f} of the irradiance above the water, "
              f"contrast (std/mean) {irradiance.std() / irradiance.mean():.3f}, "
              f"brightest cell {irradiance.max() / irradiance.mean():.1f}× the mean")
        panels.append(np.clip(irradiance / (4 * irradiance.mean()), 0, 1)[::-1])  # north up
    gap = np.ones((cells, max(4, cells // 60)))
    strip = np.concatenate(sum(([p, gap] for p in panels), [])[:-1], axis=1)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    name = out / f"{Path(args.scene).stem}_planes.png"
    iio.imwrite(name, (255 * strip ** (1 / 2.2)).astype(np.uint8))
    print(name)


if __name__ == "__main__":
    main()
