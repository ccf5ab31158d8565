"""What issue 43's water data change in the numbers and the pictures (Bricaud 1998 a_φ, WOPP v3 a_w(T, S)).

Two steps, so that the code before the change can run the first one from its own tree:

``measure OUT.json``
    For each preset scene and the default scene: the water's a, b_b and the four-flux model's K_d and
    R(0⁻) (coefficients from the phase function) under the scene's sun and sky, as ``oceanrender
    optics`` computes them, at 400-700 nm; and the real-time T0 table at h = 2 m, 10 m and ∞ (the
    water-leaving colour over a black bottom, Eq. 21), in the scene's display colour.
    Uses only functions that exist before and after issue 43 (``realtime.bake``).
``compare BEFORE.json AFTER.json RENDERS_BEFORE RENDERS_AFTER``
    Prints and writes ``docs/data/water_colour_change.md``: the ratios after/before of a(440), K_d and
    R(0⁻) at 440/490/550/650 nm, ΔE2000 of T0, and of the rendered frames (``oceanrender render
    SCENE --frames 0:1 --spp 32 --resolution 320x180 --denoise`` into each renders folder): the mean
    colour of the lower half (the water) and the per-pixel median over it; and
    ``docs/images/water_colour_before_after.png`` (before | after, one row per scene).

Usage (issue 43's run; the "before" tree a ``git worktree`` of the commit before)::

    (cd BEFORE_TREE && PYTHONPATH=. /work/main/.venv/bin/python /work/main/scripts/water_colour_change.py measure /tmp/before.json)
    .venv/bin/python scripts/water_colour_change.py measure /tmp/after.json
    .venv/bin/python scripts/water_colour_change.py compare /tmp/before.json /tmp/after.json RB RA
"""

from __future__ import annotations

import json
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
SCENES = ("clear_open_ocean", "green_coastal", "turbid_estuary", "open_ocean")
WAVELENGTHS_NM = np.arange(400.0, 701.0, 5.0)
BANDS_NM = (440.0, 490.0, 550.0, 650.0)
T0_DEPTHS_M = (2.0, 10.0, np.inf)


def measure(out: pathlib.Path) -> None:
    import oceanrender
    from oceanrender.optics.report import scene_optics
    from oceanrender.optics.scene_water import water_ior, water_phase_table
    from oceanrender.pipeline import vision_for_scene
    from oceanrender.realtime.bake import BakeSettings, measure_scene_light, scene_iops, water_column
    from oceanrender.realtime.luts import VisionState, upwelling_radiance
    from oceanrender.render.irradiance import sky_irradiance_spectra
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene

    print(f"code from {pathlib.Path(oceanrender.__file__).parent}")
    activate_variant("auto")
    result = {}
    for name in SCENES:
        scene = load_scene(ROOT / "scenes" / f"{name}.toml")
        a, b, bb = scene_iops(scene, WAVELENGTHS_NM)
        direct, diffuse = sky_irradiance_spectra(scene.sun, WAVELENGTHS_NM, spp=scene.render.white_spp)
        report = scene_optics(a, b, bb, direct, diffuse, 90.0 - scene.sun.elevation, np.inf, np.array([0.0, 1.0]),
                              n_water=water_ior(scene), phase=water_phase_table(scene, WAVELENGTHS_NM))
        light = measure_scene_light(scene, BakeSettings())
        column = water_column(scene, light)
        phi = VisionState(vision_for_scene(scene), light.white_XYZ, 0.18 * float(light.white_XYZ[1]))
        up, _ = upwelling_radiance(column, np.array(T0_DEPTHS_M))
        t0 = [phi.spectra(u, column.wavelengths).tolist() for u in up]
        result[name] = {"a": a.tolist(), "bb": bb.tolist(), "K_d": report.light.K_d.tolist(),
                        "R": report.light.R.tolist(), "T0_rgb": t0}
        print(f"{name}: a(440) {np.interp(440, WAVELENGTHS_NM, a):.4f}, K_d(490) "
              f"{np.interp(490, WAVELENGTHS_NM, report.light.K_d):.4f}, R(440) {np.interp(440, WAVELENGTHS_NM, report.light.R):.4f}")
    out.write_text(json.dumps({"wavelengths_nm": WAVELENGTHS_NM.tolist(), "scenes": result}, indent=1) + "\n")


def _frame(folder: pathlib.Path, name: str) -> np.ndarray:
    """The frame's display image: sRGB-encoded values in [0, 1], (H, W, 3)."""
    from PIL import Image

    with Image.open(folder / name / "frame_0000.png") as image:
        return np.asarray(image.convert("RGB"), dtype=float) / 255.0


def compare(before_path: pathlib.Path, after_path: pathlib.Path, renders_before: pathlib.Path,
            renders_after: pathlib.Path) -> None:
    import colour
    from PIL import Image

    before, after = (json.loads(p.read_text()) for p in (before_path, after_path))
    wl = np.asarray(after["wavelengths_nm"])
    lines = ["| scene | a(440) after/before | K_d after/before at 440, 490, 550, 650 nm | R(0⁻) after/before at 440, 490, "
             "550, 650 nm | ΔE2000 of T0 at h = 2 m, 10 m, ∞ | ΔE2000 of the rendered water: mean colour; per-pixel median |",
             "|---|---|---|---|---|---|"]
    rows = []
    for name in SCENES:
        b, a = before["scenes"][name], after["scenes"][name]
        at = lambda d, key, w: float(np.interp(w, wl, d[key]))  # noqa: E731
        k = ", ".join(f"{at(a, 'K_d', w) / at(b, 'K_d', w):.3f}" for w in BANDS_NM)
        r = ", ".join(f"{at(a, 'R', w) / at(b, 'R', w):.3f}" for w in BANDS_NM)
        lab = lambda rgb: colour.XYZ_to_Lab(colour.sRGB_to_XYZ(np.clip(rgb, 0, None), apply_cctf_decoding=False))  # noqa: E731
        t0 = colour.delta_E(lab(np.array(b["T0_rgb"])), lab(np.array(a["T0_rgb"])), method="CIE 2000")
        img_b, img_a = _frame(renders_before, name), _frame(renders_after, name)
        half = slice(img_a.shape[0] // 2, None)
        srgb_lab = lambda s: colour.XYZ_to_Lab(colour.sRGB_to_XYZ(s))  # noqa: E731  (PNG: sRGB-encoded)
        lin = lambda s: colour.cctf_decoding(s, function="sRGB")  # noqa: E731
        mean_b = colour.cctf_encoding(lin(img_b[half]).reshape(-1, 3).mean(axis=0), function="sRGB")
        mean_a = colour.cctf_encoding(lin(img_a[half]).reshape(-1, 3).mean(axis=0), function="sRGB")
        dE_mean = float(colour.delta_E(srgb_lab(mean_b), srgb_lab(mean_a), method="CIE 2000"))
        dE_pix = float(np.median(colour.delta_E(srgb_lab(img_b[half]), srgb_lab(img_a[half]), method="CIE 2000")))
        lines.append(f"| {name} | {at(a, 'a', 440) / at(b, 'a', 440):.3f} | {k} | {r} | "
                     f"{t0[0]:.2f}, {t0[1]:.2f}, {t0[2]:.2f} | {dE_mean:.2f}; {dE_pix:.2f} |")
        rows.append(np.concatenate([img_b, np.ones((img_b.shape[0], 4, 3)), img_a], axis=1))
    text = "\n".join(lines) + "\n"
    print(text)
    (ROOT / "docs" / "data" / "water_colour_change.md").write_text(text)
    sheet = np.concatenate([np.concatenate([r, np.ones((4, r.shape[1], 3))], axis=0) for r in rows], axis=0)
    Image.fromarray((np.clip(sheet, 0, 1) * 255 + 0.5).astype(np.uint8)).save(
        ROOT / "docs" / "images" / "water_colour_before_after.png")


if __name__ == "__main__":
    if sys.argv[1] == "measure":
        measure(pathlib.Path(sys.argv[2]))
    elif sys.argv[1] == "compare":
        compare(*(pathlib.Path(p) for p in sys.argv[2:6]))
    else:
        raise SystemExit(__doc__)
