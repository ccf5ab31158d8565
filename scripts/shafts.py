"""Issue 41: a scene's frame with the volume's beam planes off and on, side by side (docs/sunlight.md).

Renders frame ``--frame`` of the scene once per ``--cells`` value of ``[render] shaft_cell`` (0: the
path tracer alone) at the same size, spp and seed, through the scene's own vision model, and writes
the frames side by side to ``--out``; prints one JSON line per frame: the render's seconds, the
frame's mean luminance Y [cd m⁻²], and its pixel noise (the RMS of the difference from a 3×3 box
blur, over the mean: the speckle a noisy estimator leaves, which the shafts' streaks barely move).
The XYZ frames are kept in ``outputs/shafts/<name of --out>.npz`` for a later look.

With ``--converge``, per frame: the point its streaks converge to (the structure tensor's streak
directions, the point of least weighted-median misalignment) against the image point of the
refracted sun's antisolar direction — the shafts' vanishing point in perspective.

Usage: python scripts/shafts.py [--scene scenes/under_water.toml] [--cells 0,0.05] [--spp 64]
       [--size 320x180] [--frame 0] [--out docs/images/sunlight/shafts_under_water.png]
       [--set section.key=value ...] [--converge] [--key caustic_cell]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def speckle(y: np.ndarray) -> float:
    """RMS of Y minus its 3×3 box mean, over the mean of Y [-]."""
    from scipy.ndimage import uniform_filter

    return float(np.sqrt(np.mean((y - uniform_filter(y, 3, mode="nearest")) ** 2)) / y.mean())


def streak_field(y: np.ndarray, sigma: float = 2.0):
    """Per pixel: the unit direction (dx, dy) [px] along which log Y varies least (a streak's), and its
    weight λ₁ − λ₂ [-] (the structure tensor's eigenvalues: how strongly the pixel's neighbourhood is a
    streak rather than a blob or noise; Bigün & Granlund 1987). Rows go down the image."""
    from scipy.ndimage import gaussian_filter, sobel

    image = gaussian_filter(np.log(np.maximum(y, 1e-30)), 1.0)
    gx, gy = sobel(image, axis=1), sobel(image, axis=0)
    jxx, jxy, jyy = (gaussian_filter(g, sigma) for g in (gx * gx, gx * gy, gy * gy))
    half_trace, root = (jxx + jyy) / 2, np.sqrt(((jxx - jyy) / 2) ** 2 + jxy ** 2)
    # the eigenvector of the smaller eigenvalue (along the streak): (λ₂ − jyy, jxy) ∝ (jxy, λ₂ − jxx)
    small = half_trace - root
    dx, dy = jxy, small - jxx
    swap = np.hypot(dx, dy) < 1e-12 * (half_trace + 1e-30)
    dx, dy = np.where(swap, small - jyy, dx), np.where(swap, jxy, dy)
    norm = np.maximum(np.hypot(dx, dy), 1e-30)
    return dx / norm, dy / norm, 2 * root


def vanishing_point(y: np.ndarray, mask: np.ndarray | None = None, sigma: float = 2.0) -> tuple[float, float]:
    """The point (column, row) [px] the streaks of ``y`` point at: the least-squares meeting point of the
    lines through each pixel along its streak direction, each weighted by its streak strength."""
    dx, dy, weight = streak_field(y, sigma)
    rows, columns = np.indices(y.shape, dtype=float)
    if mask is not None:
        weight = weight * mask
    nx, ny = -dy, dx  # the normal of each line
    a = np.array([[np.sum(weight * nx * nx), np.sum(weight * nx * ny)],
                  [np.sum(weight * nx * ny), np.sum(weight * ny * ny)]])
    b = np.array([np.sum(weight * nx * (nx * columns + ny * rows)), np.sum(weight * ny * (nx * columns + ny * rows))])
    column, row = np.linalg.solve(a, b)
    return float(column), float(row)


def _misalignment(dx, dy, weight, point) -> float:
    """Weighted median angle [deg] between the streaks (dx, dy) [px] and the lines from their pixels to ``point``."""
    rows, columns = np.indices(dx.shape, dtype=float)
    tx, ty = point[0] - columns, point[1] - rows
    cosine = np.abs(dx * tx + dy * ty) / np.maximum(np.hypot(tx, ty), 1e-9)
    angle = np.degrees(np.arccos(np.clip(cosine, 0.0, 1.0))).ravel()
    order = np.argsort(angle)
    cumulative = np.cumsum(weight.ravel()[order])
    return float(angle[order][np.searchsorted(cumulative, 0.5 * cumulative[-1])])


def streak_misalignment(y: np.ndarray, point, mask: np.ndarray | None = None, sigma: float = 2.0) -> float:
    """Weighted median angle [deg] between each pixel's streak and the line from it to ``point`` (column,
    row) [px]: 0 where every streak points there; 45° for streaks of random directions."""
    dx, dy, weight = streak_field(y, sigma)
    return _misalignment(dx, dy, weight if mask is None else weight * mask, point)


def most_aligned_point(y: np.ndarray, mask: np.ndarray | None = None, sigma: float = 2.0, step: float = 4.0):
    """The point (column, row) [px] of the image (a grid of ``step`` px, then 1 px around the best) at which
    :func:`streak_misalignment` is smallest — a median, robust to the noise's random streaks that pull the
    least-squares :func:`vanishing_point` towards the centre of the weights — and that smallest angle [deg]."""
    dx, dy, weight = streak_field(y, sigma)
    weight = weight if mask is None else weight * mask

    def misalignment(point):
        return _misalignment(dx, dy, weight, point)

    height, width = y.shape
    best = min(((c, r) for c in np.arange(0, width, step) for r in np.arange(0, height, step)), key=misalignment)
    fine = [(best[0] + a, best[1] + b) for a in np.arange(-step, step + 1) for b in np.arange(-step, step + 1)]
    best = min(fine, key=misalignment)
    return (float(best[0]), float(best[1])), misalignment(best)


def image_point(camera, direction, size) -> tuple[float, float]:
    """(column, row) [px] at which the perspective camera (horizontal ``camera.fov``, z up) sees ``direction``."""
    width, height = size
    forward = np.asarray(camera.target, float) - np.asarray(camera.position, float)
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    d = np.asarray(direction, float)
    x, y = d @ right / (d @ forward), d @ up / (d @ forward)
    tan_half = np.tan(np.radians(camera.fov) / 2)
    return float((x / tan_half + 1) / 2 * width - 0.5), float((1 - y / tan_half * width / height) / 2 * height - 0.5)


def converge(scene, frames: dict, size) -> None:
    """Print, per frame, the point its streaks converge to (:func:`most_aligned_point`, Y after a 3×3 median,
    streaks over 8 px) and the image point of the refracted sun's antisolar direction (flat sea, Snell)."""
    from scipy.ndimage import median_filter

    from oceanrender.render.scene import sun_direction
    from oceanrender.render.sun_beam import flat_beam_shear

    shear = np.array(flat_beam_shear(sun_direction(scene.sun.elevation, scene.sun.azimuth), 1.34))
    beam = np.array([shear[0], shear[1], 1.0]) * -1.0  # d_xy/d_z = shear, d_z < 0
    expected = image_point(scene.camera, beam / np.linalg.norm(beam), size)
    focal = size[0] / 2 / np.tan(np.radians(scene.camera.fov) / 2)
    for name, xyz in frames.items():
        y = median_filter(np.asarray(xyz[..., 1], float), 3)
        point, angle = most_aligned_point(y, None, 8.0)
        miss = float(np.hypot(point[0] - expected[0], point[1] - expected[1]))
        centre = streak_misalignment(y, ((size[0] - 1) / 2, (size[1] - 1) / 2), None, 8.0)
        print(json.dumps({"frame": name, "antisolar_px": [round(v, 1) for v in expected], "converge_px": point,
                          "miss_px": round(miss, 1), "miss_deg": round(float(np.degrees(np.arctan(miss / focal))), 2),
                          "median_misalignment_deg": round(angle, 1),
                          "towards_centre_deg": round(centre, 1)}), flush=True)


def parse_value(text: str):
    try:
        return json.loads(text)
    except json.JSONDecodeError:
        return text


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "under_water.toml"))
    parser.add_argument("--cells", default="0,0.05", help="values of --key [m], 0: off")
    parser.add_argument("--key", default="shaft_cell", help="the [render] key --cells sets (shaft_cell, caustic_cell)")
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--frame", type=int, default=0)
    parser.add_argument("--set", action="append", default=[], help="section.key=value (JSON value)")
    parser.add_argument("--converge", action="store_true",
                        help="where the frames' streaks converge, against the refracted sun's antisolar point")
    parser.add_argument("--out", default=str(ROOT / "docs" / "images" / "sunlight" / "shafts_under_water.png"))
    args = parser.parse_args()

    import imageio.v3 as iio

    from oceanrender.pipeline import Sequence, SequenceReport, simulate_coastal
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene, with_overrides

    width, height = (int(v) for v in args.size.split("x"))
    extra: dict[str, dict] = {}
    for item in args.set:
        key, value = item.split("=", 1)
        section, name = key.split(".", 1)
        extra.setdefault(section, {})[name] = parse_value(value)
    panels, frames = [], {}
    for cell in (float(c) for c in args.cells.split(",")):
        render = {**extra.get("render", {}), args.key: cell}
        scene = with_overrides(load_scene(Path(args.scene)), "shafts.py",
                               **{**extra, "render": render,
                                  "output": {**extra.get("output", {}), "resolution": [width, height],
                                             "spp": args.spp}})
        store = None
        if scene.coastal is not None:  # the coast's simulation, run once (kept under outputs/shafts/)
            store = simulate_coastal(scene, ROOT / "outputs" / "shafts" / Path(args.scene).stem, [args.frame],
                                     SequenceReport("shafts.py"))
        sequence = Sequence(scene, activate_variant(scene.render.variant).variant, coastal_store=store)
        tic = time.perf_counter()
        rendered = sequence.compute_frame(args.frame)
        seconds = time.perf_counter() - tic
        y = np.asarray(rendered.channels["Y"], float)
        frames[f"cell_{cell:g}"] = np.stack([rendered.channels[c] for c in "XYZ"], -1)
        panels.append(rendered.rgb8)
        print(json.dumps({args.key: cell, "seconds": round(seconds, 1),
                          "render_seconds": round(rendered.seconds["render"], 1), "mean_Y": round(float(y.mean()), 4),
                          "speckle": round(speckle(y), 4)}), flush=True)
    if args.converge:
        converge(scene, frames, (width, height))
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    gap = np.full((panels[0].shape[0], 4, 3), 255, np.uint8)
    row = [panels[0]]
    for panel in panels[1:]:
        row += [gap, panel]
    iio.imwrite(out, np.concatenate(row, axis=1))
    kept = ROOT / "outputs" / "shafts" / out.with_suffix(".npz").name  # (outputs/ is not committed)
    kept.parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(kept, **frames)


if __name__ == "__main__":
    main()
