"""Rendered near-field whitecap coverage against Monahan & O'Muircheartaigh (1980), at several winds.

"Showing foam": a camera pixel whose ray (through the pixel centre) meets the
top of the water mesh within ``--near`` metres (horizontal) of the camera,
where the mesh's interpolated whitecap coverage (the attribute
``vertex_foam`` of a ray-cast copy of the frame's mesh, read with Mitsuba's
``Shape.eval_attribute_1``) is at least ½. Coverage = showing-foam pixels /
near-field water pixels, pooled over the frame times and ocean seeds given.
It also reports the whitecaps' effective reflectance in Koepke's (1984)
sense, the foam's whole reflectance contribution over the coverage,
R_eff = albedo × Σ B / (showing-foam pixels), B the interpolated fresh-foam
coverage (the rendered foam weight) over all near-field pixels (Koepke:
0.22 ± 0.11), and the reflectance of the foam in the showing-foam pixels,
albedo × B/F.

Usage::

    .venv/bin/python scripts/whitecap_coverage.py [--scene scenes/open_ocean.toml] [--winds 8 12 16]
        [--times 4 6 8] [--seeds 1 2] [--resolution 320x180] [--near 100] [--foam KEY=VALUE ...]
        [--alphas A ...]   # the fit: coverage for several breaking_acceleration α, and the α meeting Monahan

Works on the code before issue 15 part 4 as well (it then reads the frame's
``foam``, the one coverage that code had). Prints one line per wind and a
table row for docs/whitecaps.md.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))


def monahan(wind: float) -> float:
    """W = 3.84e-6 U^3.41 [-] (Monahan & O'Muircheartaigh 1980, Eq. 5)."""
    return 3.84e-6 * wind**3.41


def parse_value(text: str):
    """A --foam value: bool, number or string."""
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    if text.lower() == "none":
        return None
    try:
        return float(text)
    except ValueError:
        return text


def ray_cast_foam(scene, geometry, faces, coverage, fresh, resolution, near):
    """(coverage, fresh) at the near-field water pixels, by a Mitsuba ray cast through the pixel centres."""
    import drjit as dr
    import mitsuba as mi

    from oceanrender.render.buffers import jit_floats
    from oceanrender.render.scene import perspective_sensor

    width, height = resolution
    props = mi.Properties()
    props["bsdf"] = mi.load_dict({"type": "diffuse"})
    mesh = mi.Mesh("water", len(geometry.positions), len(faces), props, has_vertex_normals=True)
    mesh.add_attribute("vertex_foam", 1, jit_floats(coverage))
    mesh.add_attribute("vertex_foam_fresh", 1, jit_floats(fresh))
    params = mi.traverse(mesh)
    params["vertex_positions"] = jit_floats(geometry.positions)
    params["vertex_normals"] = jit_floats(geometry.normals)
    params["faces"] = mi.UInt32(np.ascontiguousarray(faces, dtype=np.uint32).ravel())
    params.update()
    film = {"type": "hdrfilm", "width": width, "height": height}
    mscene = mi.load_dict({"type": "scene", "sensor": perspective_sensor(scene.camera, film, 1), "water": mesh})
    sensor = mscene.sensors()[0]
    index = dr.arange(mi.UInt32, width * height)
    pixel = mi.Vector2f((mi.Float(index % width) + 0.5) / width, (mi.Float(index // width) + 0.5) / height)
    ray, _ = sensor.sample_ray(0.0, 0.5, pixel, mi.Point2f(0.5, 0.5))
    si = mscene.ray_intersect(ray)
    valid = np.array(si.is_valid())
    point = np.array(si.p).reshape(3, -1)  # drjit arrays of 3-vectors convert to (3, N)
    up = np.array(si.n).reshape(3, -1)[2] > 0  # the top of the body, not its skirt or bottom
    foam = np.array(si.shape.eval_attribute_1("vertex_foam", si))
    foam_fresh = np.array(si.shape.eval_attribute_1("vertex_foam_fresh", si))
    point = point.T
    cam = np.asarray(scene.camera.position, float)
    distance = np.hypot(point[:, 0] - cam[0], point[:, 1] - cam[1])
    near_water = valid & up & (distance <= near)
    return foam[near_water], foam_fresh[near_water]


def measure(scene_path: str, wind: float, times, seeds, resolution, near, foam_overrides, alphas=(None,)) -> list:
    """One result dict per α of ``alphas`` (None: the scene's criterion), pooled over ``seeds`` and ``times``.

    The α values share each frame's Jacobian history (only the threshold changes).
    """
    from oceanrender.scene.settings import load_scene, with_overrides
    from oceanrender.surface.open_sea import WaterBody

    scene = load_scene(scene_path)
    showing = np.zeros(len(alphas), int)
    pixels = np.zeros(len(alphas), int)
    reflectance = [[] for _ in alphas]
    bright = np.zeros(len(alphas))  # Σ B over the near-field pixels
    per_frame = [[] for _ in alphas]  # each frame's pixel coverage (for the spread)
    area_cover = [[] for _ in alphas]  # vertex-area fraction with F ≥ ½ within the near field
    seconds = []
    for seed in seeds:
        settings = with_overrides(scene, ocean={"wind_speed": wind, "seed": int(seed)},
                                  foam={"enabled": True, **foam_overrides})
        body = WaterBody(settings)
        albedo = settings.foam.albedo
        for t in times:
            for i, alpha in enumerate(alphas):
                if alpha is not None:  # the criterion with another α: same Jacobians, another J_c
                    body.__dict__.pop("foam_threshold", None)
                    body.scene = with_overrides(settings, foam={"breaking_acceleration": float(alpha)})
                start = time.perf_counter()
                geometry = body.frame(float(t))
                if i == 0:
                    seconds.append(time.perf_counter() - start)
                if hasattr(body, "vertex_foam"):
                    coverage, fresh = body.vertex_foam(float(t), len(geometry.positions))
                else:  # the code before part 4: one coverage, a flat blend
                    coverage = fresh = geometry.foam
                foam, foam_fresh = ray_cast_foam(settings, geometry, body.faces, coverage, fresh, resolution, near)
                if hasattr(body, "foam_points") and body.spacing is not None:  # on the sea itself, not the pixels
                    x, y, _ = body.foam_points(float(t))
                    cx, cy = body.grid_at(float(t)).center
                    inside = np.hypot(x - cx, y - cy) <= near
                    cell = body.spacing[inside] ** 2  # a radial vertex's cell area ∝ its spacing²
                    area_cover[i].append(float(np.sum((coverage[: x.size][inside] >= 0.5) * cell) / cell.sum()))
                mask = foam >= 0.5
                per_frame[i].append(float(mask.mean()) if foam.size else 0.0)
                showing[i] += int(mask.sum())
                bright[i] += float(np.sum(foam_fresh))
                pixels[i] += foam.size
                if mask.any():
                    reflectance[i].append(albedo * foam_fresh[mask] / np.maximum(foam[mask], 1e-9))
    results = []
    for i, alpha in enumerate(alphas):
        coverage = showing[i] / max(pixels[i], 1)
        mean_r = float(np.mean(np.concatenate(reflectance[i]))) if reflectance[i] else float("nan")
        effective = albedo * bright[i] / max(showing[i], 1)
        results.append({"wind": wind, "alpha": alpha, "coverage": coverage, "monahan": monahan(wind),
                        "effective_reflectance": effective,
                        "area_coverage": float(np.mean(area_cover[i])) if area_cover[i] else float("nan"),
                        "frame_coverage": per_frame[i],
                        "ratio": coverage / monahan(wind), "pixels": int(pixels[i]), "showing": int(showing[i]),
                        "foam_reflectance": mean_r, "first_frame_s": seconds[0], "seconds": seconds})
    return results


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="scenes/open_ocean.toml")
    parser.add_argument("--winds", type=float, nargs="+", default=[8.0, 12.0, 16.0])
    parser.add_argument("--times", type=float, nargs="+", default=[4.0, 6.0, 8.0], help="frame times [s]")
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2], help="ocean seeds")
    parser.add_argument("--resolution", default="320x180")
    parser.add_argument("--near", type=float, default=100.0, help="near field: horizontal distance [m]")
    parser.add_argument("--foam", nargs="*", default=[], help="[foam] overrides KEY=VALUE")
    parser.add_argument("--alphas", type=float, nargs="*", help="breaking_acceleration values to try (the fit)")
    parser.add_argument("--variant", default="llvm_ad_spectral")
    parser.add_argument("--json", help="write the results here")
    args = parser.parse_args(argv)
    import mitsuba as mi

    mi.set_variant(args.variant)
    resolution = tuple(int(v) for v in args.resolution.lower().split("x"))
    overrides = dict(item.split("=", 1) for item in args.foam)
    overrides = {key: parse_value(value) for key, value in overrides.items()}
    results = []
    alphas = args.alphas or [None]
    for wind in args.winds:
        for r in measure(args.scene, wind, args.times, args.seeds, resolution, args.near, overrides, alphas):
            results.append(r)
            label = "" if r["alpha"] is None else f"alpha = {r['alpha']:.3f}: "
            spread = np.std(r["frame_coverage"]) / np.sqrt(len(r["frame_coverage"]))
            print(f"U10 = {wind:4.1f} m/s: {label}rendered near-field coverage {100 * r['coverage']:.3f} % "
                  f"(± {100 * spread:.3f} % standard error over {len(r['frame_coverage'])} frames; sea area with "
                  f"F ≥ 1/2: {100 * r['area_coverage']:.3f} %) "
                  f"({r['showing']} of {r['pixels']} px) vs Monahan {100 * r['monahan']:.2f} %: "
                  f"ratio {r['ratio']:.2f}; R_eff {r['effective_reflectance']:.3f}, foam reflectance "
                  f"{r['foam_reflectance']:.3f}; geometry first frame "
                  f"{r['first_frame_s']:.1f} s, later {np.mean(r['seconds'][1:]) if len(r['seconds']) > 1 else float('nan'):.2f} s",
                  flush=True)
        if args.alphas and len(alphas) > 1:  # the α that meets Monahan at this wind: log-linear interpolation
            rows = [r for r in results if r["wind"] == wind and r["coverage"] > 0]
            a = np.array([r["alpha"] for r in rows])
            c = np.log([r["ratio"] for r in rows])
            order = np.argsort(c)
            if len(rows) > 1 and c.min() <= 0 <= c.max():
                print(f"U10 = {wind:4.1f} m/s: coverage = Monahan at alpha = {np.interp(0.0, c[order], a[order]):.3f}")
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
