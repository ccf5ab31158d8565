"""Issue 40: per-hit field shading against brute force, in a window of the near field.

For each case (a shipped scene, optionally at another wind speed) frame 0 is
rendered over one window of the 1280×720 image three ways, at equal spp and
with two seeds each:

* ``fields``: the radial mesh shaded from the sea's fields at every hit (the default);
* ``vertex``: the radial mesh with normals and α interpolated from its vertices (before);
* ``brute``: the reference. The radial mesh with a hole where the window's rays can meet
  the sea, filled by a patch of the same sea sampled with *every* wave of the cascades
  (no level filtering) at a spacing of at most half the pixel footprint in x and in y,
  per-vertex α of the waves beyond the cascades (the spectrum's part no geometry here
  carries), vertex-interpolated normals. Its geometry resolves everything below the pixel.

Foam is off in all three (the window compares the water's own shading).

Measured in the window (luminance Y [cd m⁻²] from absolute XYZ):

1. the radially averaged power spectrum of Y, as the *cross*-spectrum of the two seeds'
   renders (Re F₁F₂*: Monte Carlo noise, independent between seeds, averages out of it),
   per frequency bin up to the pixel Nyquist (0.5 cycles px⁻¹), against brute force;
2. ΔE00 of the window's mean colour (CIELAB of XYZ / Y_white, the scene's adapting white);
3. the count of glitter pixels, Y above the white plane's luminance (a sunlit white
   Lambertian sheet: a fixed luminance per unit solid angle), against brute force.

Writes docs/images/pixel_detail/<case>_{fields,vertex,brute}.png, the strip <case>.png (vertex |
fields | brute) and prints a JSON line per case.

Usage: python scripts/pixel_detail.py [--spp 256] [--cases default,default_4,glitter_4,glitter_12]
"""

from __future__ import annotations

import argparse
import json
import math
import time
import tomllib
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

#: case → (scene file, wind speed or None, crop (x, y, w, h) of the 1280×720 frame: near field, in the glitter)
CASES = {
    "default": ("scenes/open_ocean.toml", None, (832, 464, 256, 128)),
    "default_4": ("scenes/open_ocean.toml", 4.0, (832, 464, 256, 128)),
    "glitter_4": ("scenes/glitter_low_sun.toml", 4.0, (512, 400, 256, 128)),
    "glitter_12": ("scenes/glitter_low_sun.toml", 12.0, (512, 400, 256, 128)),
    # the default scene from other heights (camera z [m] after the "@"): crops for the eye
    "default@2": ("scenes/open_ocean.toml", None, (832, 464, 256, 128)),
    "default@30": ("scenes/open_ocean.toml", None, (832, 464, 256, 128)),
}

#: Most vertices of the brute-force patch (memory): beyond, its spacing grows (and is reported).
MAX_PATCH_VERTICES = 4_000_000

WIDTH, HEIGHT = 1280, 720


def scene_for(path: str, wind: float | None, height: float | None = None):
    """The case's scene at 1280×720, foam off, one frame (camera ``height`` [m] above the sea if given)."""
    from oceanrender.scene.settings import scene_from_dict  # noqa: PLC0415

    data = tomllib.loads((ROOT / path).read_text())
    data.setdefault("name", Path(path).stem)
    data["output"].update(resolution=[WIDTH, HEIGHT], frames=[0, 1])
    data["foam"] = {"enabled": False}
    if wind is not None:
        data["ocean"]["wind_speed"] = wind
    if height is not None:
        data["camera"]["position"][2] = height
    return scene_from_dict(data, path)


def crop_rays(scene, crop):
    """Origins and unit directions of the rays through the crop's corners and edge midpoints (z up)."""
    import mitsuba as mi  # noqa: PLC0415

    from oceanrender.render.scene import perspective_sensor, xyz_film  # noqa: PLC0415

    sensor = mi.load_dict(perspective_sensor(scene.camera, xyz_film(WIDTH, HEIGHT), 1))
    x, y, w, h = crop
    points = [(x + a * w, y + b * h) for a in np.linspace(0, 1, 5) for b in np.linspace(0, 1, 5)]
    rays = []
    for px, py in points:
        ray, _ = sensor.sample_ray(0.0, 0.5, mi.Point2f(float(px) / WIDTH, float(py) / HEIGHT), mi.Point2f(0.5, 0.5))
        o = np.array([ray.o.x, ray.o.y, ray.o.z], float).ravel()
        d = np.array([ray.d.x, ray.d.y, ray.d.z], float).ravel()
        rays.append((o, d))
    return rays


def brute_force_patch(body, t: float, scene, crop, sigma_eta: float):
    """(faces, FrameGeometry) of the reference: radial mesh with a hole, filled by a fine patch of every wave."""
    from oceanrender.render.sea_shading import pixel_angle  # noqa: PLC0415
    from oceanrender.surface.frame import FrameGeometry  # noqa: PLC0415

    angle = pixel_angle(scene.camera.fov, WIDTH)
    # the sea's surface lies between ±3.5 σ_η (but for 1 point in 10⁴); below the camera
    heights = min(3.5 * sigma_eta, 0.9 * scene.camera.position[2])
    xs, ys, spacing_x, spacing_y = [], [], [], []
    for o, d in crop_rays(scene, crop):
        for z in (-heights, 0.0, heights):
            s = (z - o[2]) / d[2]
            xs.append(o[0] + s * d[0])
            ys.append(o[1] + s * d[1])
        distance = -o[2] / d[2]
        footprint = distance * angle
        spacing_x.append(footprint / 2)
        spacing_y.append(footprint / abs(d[2]) / 2)
    margin = 1.5 + 3.0 * sigma_eta  # [m]: the choppy displacement
    x0, x1 = min(xs) - margin, max(xs) + margin
    y0, y1 = min(ys) - margin, max(ys) + margin
    # NOTE: the camera looks along ±y in the cases here, so x is across the view and y along it.
    sx, sy = min(spacing_x), min(spacing_y)
    grow = math.sqrt(max(1.0, (x1 - x0) / sx * (y1 - y0) / sy / MAX_PATCH_VERTICES))
    sx, sy = sx * grow, sy * grow
    nx, ny = int(math.ceil((x1 - x0) / sx)) + 1, int(math.ceil((y1 - y0) / sy)) + 1
    gx, gy = np.meshgrid(np.linspace(x0, x1, nx), np.linspace(y0, y1, ny))
    surface = body.sea.sample(gx.ravel(), gy.ravel(), t, None)
    rest = np.column_stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)])
    patch_positions = (rest + surface.displacement).astype(np.float32)
    patch_normals = surface.normals.astype(np.float32)
    index = np.arange(nx * ny).reshape(ny, nx)
    a, b, c, e = index[:-1, :-1].ravel(), index[:-1, 1:].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel()
    patch_faces = np.concatenate([np.column_stack([a, b, e]), np.column_stack([a, e, c])])  # counter-clockwise from above
    alpha = float(np.sqrt(body.sea.unresolved_slope_variance(None)))

    radial = body.frame(t)
    top = len(body.grid_at(t).points)
    rest_xy = body.grid_at(t).points
    faces = body.faces
    on_top = np.all(faces < top, axis=1)
    centroid = np.zeros((len(faces), 2))
    centroid[on_top] = rest_xy[faces[on_top]].mean(axis=1)
    cell = 2.0 * np.pi * np.hypot(centroid[:, 0], centroid[:, 1]) / body.radial.segments
    inside = on_top & (centroid[:, 0] > x0 + cell) & (centroid[:, 0] < x1 - cell) \
        & (centroid[:, 1] > y0 + cell) & (centroid[:, 1] < y1 - cell)
    kept = faces[~inside]
    offset = len(radial.positions)
    positions = np.vstack([radial.positions, patch_positions])
    normals = np.vstack([radial.normals, patch_normals])
    roughness = np.concatenate([radial.roughness, np.full(len(patch_positions), alpha, np.float32)])
    geometry = FrameGeometry(positions, normals, None, roughness)
    info = {"patch_vertices": int(nx * ny), "spacing_x_m": sx, "spacing_y_m": sy,
            "window_m": [x0, x1, y0, y1], "alpha_patch": alpha}
    return np.vstack([kept, patch_faces + offset]), geometry, info


def radial_spectrum(a: np.ndarray, b: np.ndarray, bins: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """Radially averaged cross-spectrum Re(F_a F_b*) of two images (mean removed, Hann window) per frequency bin.

    Returns (bin centres [cycles px⁻¹], power) over (0, 0.5]: the pixel Nyquist frequency.
    """
    h, w = a.shape
    window = np.outer(np.hanning(h), np.hanning(w))
    fa = np.fft.fft2((a - a.mean()) * window)
    fb = np.fft.fft2((b - b.mean()) * window)
    cross = np.real(fa * np.conj(fb))
    fy, fx = np.meshgrid(np.fft.fftfreq(h), np.fft.fftfreq(w), indexing="ij")
    radius = np.hypot(fx, fy)
    edges = np.linspace(0.0, 0.5, bins + 1)
    edges[0] = 2.0 / min(h, w)  # leave out the lowest frequencies (the window's own extent)
    power = np.array([cross[(radius >= lo) & (radius < hi)].mean() for lo, hi in zip(edges[:-1], edges[1:])])
    return 0.5 * (edges[:-1] + edges[1:]), power


def mean_lab(xyz: np.ndarray, white: np.ndarray) -> np.ndarray:
    """CIELAB of the window's mean XYZ, relative to the adapting white (Y_white = 100)."""
    import colour  # noqa: PLC0415

    mean = xyz.reshape(-1, 3).mean(axis=0)
    white_xy = colour.XYZ_to_xy(white)
    return colour.XYZ_to_Lab(mean / white[1], white_xy)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spp", type=int, default=256)
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--out", default=str(ROOT / "docs" / "images" / "pixel_detail"))
    parser.add_argument("--modes", default="fields,vertex", help="the shadings compared with brute force")
    args = parser.parse_args()
    import colour  # noqa: PLC0415
    import imageio.v3 as iio  # noqa: PLC0415

    from oceanrender.pipeline import Sequence  # noqa: PLC0415
    from oceanrender.render.renderer import WaterRenderer  # noqa: PLC0415
    from oceanrender.runtime.variants import activate_variant  # noqa: PLC0415
    from oceanrender.vision.brightness import adaptation_luminance_log_average  # noqa: PLC0415
    from oceanrender.vision.display import encode_sRGB_8bit  # noqa: PLC0415
    from oceanrender.waves.sea import elevation_std  # noqa: PLC0415

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for case in args.cases.split(","):
        path, wind, crop = CASES[case]
        height = float(case.split("@")[1]) if "@" in case else None
        scene = scene_for(path, wind, height)
        variant = activate_variant(scene.render.variant).variant
        tic = time.perf_counter()
        seq = Sequence(scene, variant, spp=args.spp)
        t = seq.time_of(0)
        geometry = seq.geometry(0)
        common = dict(roughness=seq.roughness, in_water_clamp=seq.in_water_clamp, sun_lobe_alpha=seq.sun_lobe_alpha,
                      spp=args.spp, crop=crop)
        faces_bf, geometry_bf, info = brute_force_patch(seq.body, t, scene, crop, elevation_std(scene.ocean))
        builds = {
            "fields": (seq.faces, geometry),
            "vertex": (seq.faces, replace(geometry, shading=None)),
            "brute": (faces_bf, geometry_bf),
        }
        builds = {mode: build for mode, build in builds.items() if mode in args.modes.split(",") + ["brute"]}
        renders = {}
        for mode, (faces, geo) in builds.items():
            renderer = WaterRenderer.build(scene, seq.iops, faces, geo, **common)
            start = time.perf_counter()
            seeds = (1, 2, 3, 4) if mode == "brute" else (1, 2)  # brute: two pairs, the estimate's own scatter
            renders[mode] = [renderer.render_xyz(args.spp, seed)[0] for seed in seeds]
            renders[mode + "_seconds"] = (time.perf_counter() - start) / len(seeds)
            del renderer
        white = np.asarray(seq.white_xyz, float)
        reference = renders["brute"]
        freq, p_ref = radial_spectrum(reference[0][..., 1], reference[1][..., 1])
        _, p_ref2 = radial_spectrum(reference[2][..., 1], reference[3][..., 1])
        floor = p_ref2 / p_ref  # the same reference from other seeds: how far the estimate itself scatters
        lab_ref = mean_lab(np.mean(reference, axis=0), white)
        threshold = white[1]  # the white plane's luminance [cd m⁻²]
        count_ref = np.mean([np.count_nonzero(r[..., 1] > threshold) for r in reference[:2]])
        adaptation = adaptation_luminance_log_average(np.mean(reference, axis=0)[..., 1])
        result = {"case": case, "scene": path, "wind_speed": wind or scene.ocean.wind_speed, "crop": crop,
                  "spp": args.spp, "setup_s": time.perf_counter() - tic, **info,
                  "glitter_threshold_cd_m2": threshold, "glitter_brute": count_ref,
                  "frequency_cy_px": freq.round(4).tolist(), "power_brute": p_ref.tolist(),
                  "power_ratio_brute_seeds": floor.round(3).tolist(),
                  "power_worst_brute_seeds": float(np.max(np.abs(floor - 1.0)))}
        images = {}
        for mode in builds:
            xyz = np.mean(renders[mode], axis=0)
            rgb = seq.vision.apply(xyz, white, adaptation)
            images[mode] = encode_sRGB_8bit(np.clip(rgb, 0, 1))
            iio.imwrite(out / f"{case}_{mode}.png", images[mode])
            result[f"seconds_{mode}"] = renders[mode + "_seconds"]
            result[f"mean_Y_{mode}"] = float(xyz[..., 1].mean())
            if mode == "brute":
                continue
            _, power = radial_spectrum(renders[mode][0][..., 1], renders[mode][1][..., 1])
            ratio = power / p_ref
            result[f"power_ratio_{mode}"] = ratio.round(3).tolist()
            result[f"power_worst_{mode}"] = float(np.max(np.abs(ratio - 1.0)))
            result[f"delta_E00_{mode}"] = float(colour.delta_E(mean_lab(xyz, white), lab_ref, method="CIE 2000"))
            count = np.mean([np.count_nonzero(r[..., 1] > threshold) for r in renders[mode]])
            result[f"glitter_{mode}"] = float(count)
            result[f"glitter_ratio_{mode}"] = float(count / count_ref) if count_ref else float("nan")
        # the strip of the docs: vertex | fields | brute, 4 px white between
        parts = [images[m] for m in ("vertex", "fields", "brute") if m in images]
        gap = np.full((parts[0].shape[0], 4, 3), 255, np.uint8)
        iio.imwrite(out / f"{case}.png", np.hstack([piece for part in parts for piece in (part, gap)][:-1]))
        print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
