"""Files of the real-time path: LUTs (EXR + PNG + JSON), reference sets, reports.

Each LUT is three files with the same stem: ``NAME.exr`` (float32, the exact
texel values, one channel per texture channel, with a few header
attributes), ``NAME.png`` (an 8-bit preview, sRGB-encoded for colours,
linear otherwise) and ``NAME.json`` (axes, units, ranges, encodings and every
parameter, so a shader author can sample it without guessing). ``luts.json``
lists the set and holds the constants the shader needs besides the textures.
Every file is written atomically (:mod:`oceanrender.io.frames`).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from .. import __version__
from ..io.frames import atomic_path, read_exr, write_exr, write_png
from ..vision.display import encode_sRGB_8bit
from .bake import LUT_NAMES, LutSet
from .luts import Axis, Lut

__all__ = ["jsonable", "write_json", "read_json", "write_lut", "read_lut", "write_lut_set", "read_lut_set",
           "preview_8bit", "PREVIEW_ROWS", "read_gbuffer"]

#: A one-row LUT's PNG preview repeats its row this many times (the EXR has one row).
PREVIEW_ROWS = 32


def jsonable(value):
    """``value`` with numpy scalars/arrays as Python values and ±inf/NaN as strings (strict JSON)."""
    if isinstance(value, dict):
        return {str(k): jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [jsonable(v) for v in value]
    if isinstance(value, np.ndarray):
        return jsonable(value.tolist())
    if isinstance(value, (np.bool_, bool)):
        return bool(value)
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        value = float(value)
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return value
    return value


def write_json(path: str | Path, data: dict) -> None:
    """Write strict JSON (no NaN/Infinity literals), atomically."""
    text = json.dumps(jsonable(data), indent=2, allow_nan=False, ensure_ascii=False)
    with atomic_path(path, ".json") as tmp:
        tmp.write_text(text + "\n", encoding="utf-8")


def read_json(path: str | Path) -> dict:
    return json.loads(Path(path).read_text(encoding="utf-8"))


def preview_8bit(lut: Lut) -> np.ndarray:
    """The PNG preview of a LUT: (rows, columns, 3) uint8, one-row LUTs repeated to :data:`PREVIEW_ROWS` rows."""
    data = np.asarray(lut.data, dtype=np.float64)
    data = lut.preview_offset + lut.preview_scale * data
    if data.shape[-1] < 3:
        data = np.concatenate([data, np.zeros(data.shape[:-1] + (3 - data.shape[-1],))], axis=-1)
    if lut.preview == "sRGB":
        rgb8 = encode_sRGB_8bit(data)
    else:
        rgb8 = np.rint(np.clip(np.nan_to_num(data, nan=0.0, posinf=1.0, neginf=0.0), 0, 1) * 255).astype(np.uint8)
    if rgb8.shape[0] == 1:
        rgb8 = np.repeat(rgb8, PREVIEW_ROWS, axis=0)
    return rgb8


def _sidecar(lut: Lut) -> dict:
    rows, columns, channels = lut.data.shape
    finite = np.where(np.isfinite(lut.data), lut.data, np.nan)
    if lut.preview == "sRGB":
        png = "8-bit sRGB-encoded (IEC 61966-2-1 inverse EOTF) of clip(offset + scale * value, 0, 1)"
    else:
        png = "8-bit linear: code = round(255 * clip(offset + scale * value, 0, 1))"
    return {
        "name": lut.name,
        "oceanrender_version": __version__,
        "files": {"exr": f"{lut.name}.exr", "png": f"{lut.name}.png", "json": f"{lut.name}.json"},
        "quantity": lut.quantity,
        "size": {"width": columns, "height": rows, "channels": list(lut.channels)},
        "axes": {"u (columns, left to right)": None if lut.columns is None else lut.columns.describe(),
                 "v (rows, first row of the file = v 0)": None if lut.rows is None else lut.rows.describe("v")},
        "encoding": {"exr": "float32 per channel, linear (no transfer function): the values of 'quantity'",
                     "png": png, "png_offset": lut.preview_offset, "png_scale": lut.preview_scale,
                     "png_channels": list(lut.channels) + ["0"] * (3 - len(lut.channels)),
                     "png_rows_repeated": PREVIEW_ROWS if rows == 1 else 1},
        "value_range": {name: [float(np.nanmin(finite[..., i])), float(np.nanmax(finite[..., i]))]
                        for i, name in enumerate(lut.channels)},
        "parameters": lut.parameters,
    }


def write_lut(folder: str | Path, lut: Lut) -> list[Path]:
    """Write ``NAME.exr``, ``NAME.png`` and ``NAME.json`` into ``folder``; returns the paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    exr, png, sidecar = (folder / f"{lut.name}.{ext}" for ext in ("exr", "png", "json"))
    write_exr(exr, {name: lut.data[..., i] for i, name in enumerate(lut.channels)},
              {"lut": lut.name, "quantity": lut.quantity, "sidecar": sidecar.name})
    write_png(png, preview_8bit(lut))
    write_json(sidecar, _sidecar(lut))
    return [exr, png, sidecar]


def read_lut(folder: str | Path, name: str) -> Lut:
    """Read a LUT back from ``NAME.exr`` and ``NAME.json`` (inverse of :func:`write_lut`)."""
    folder = Path(folder)
    meta = read_json(folder / f"{name}.json")
    channels, _ = read_exr(folder / meta["files"]["exr"])
    names = tuple(meta["size"]["channels"])
    data = np.stack([channels[c] for c in names], axis=-1).astype(np.float32)
    axes = list(meta["axes"].values())
    encoding = meta["encoding"]
    return Lut(name=meta["name"], data=data, channels=names,
               columns=None if axes[0] is None else Axis.from_description(axes[0]),
               rows=None if axes[1] is None else Axis.from_description(axes[1]),
               quantity=meta["quantity"], preview="sRGB" if encoding["png"].startswith("8-bit sRGB") else "linear",
               parameters=meta["parameters"], preview_offset=float(encoding["png_offset"]),
               preview_scale=float(encoding["png_scale"]))


def write_lut_set(folder: str | Path, lut_set: LutSet) -> list[Path]:
    """Write every LUT of the set and ``luts.json`` (the list and the constants)."""
    written = []
    names = list(LUT_NAMES) + [name for name in lut_set.luts if name not in LUT_NAMES]  # + optional ones
    for name in names:
        written += write_lut(folder, lut_set.luts[name])
    index = Path(folder) / "luts.json"
    write_json(index, {"oceanrender_version": __version__, "luts": names,
                       "files": {name: f"{name}.json" for name in names}, "constants": lut_set.constants})
    return written + [index]


def read_lut_set(folder: str | Path) -> LutSet:
    """Read a LUT set written by :func:`write_lut_set`."""
    index = read_json(Path(folder) / "luts.json")
    return LutSet(luts={name: read_lut(folder, name) for name in index["luts"]}, constants=index["constants"])


# -- reference sets -------------------------------------------------------------------------------------------------

#: ΔE2000 at the top of the false-colour scale of the ΔE previews.
DELTA_E_PREVIEW_MAX = 20.0


def reference_paths(folder: str | Path, frame: int) -> dict[str, Path]:
    """The files of one frame of a reference set (see :func:`write_reference_frame`)."""
    folder = Path(folder)
    stem = f"{frame:04d}"
    names = {"reference_exr": f"reference_{stem}.exr", "reference_png": f"reference_{stem}.png",
             "realtime_exr": f"realtime_{stem}.exr", "realtime_png": f"realtime_{stem}.png",
             "fitted_exr": f"realtime_fitted_{stem}.exr", "fitted_png": f"realtime_fitted_{stem}.png",
             "delta_e_exr": f"delta_e_{stem}.exr", "delta_e_png": f"delta_e_{stem}.png",
             "delta_e_fitted_png": f"delta_e_fitted_{stem}.png",
             "gbuffer": f"gbuffer_{stem}.exr", "camera": f"camera_{stem}.json", "mesh": f"water_{stem}.ply"}
    return {key: folder / name for key, name in names.items()}


def read_reference_xyz(path: str | Path, expected: dict) -> np.ndarray | None:
    """The absolute XYZ of a reference EXR written earlier with the same ``expected`` metadata, else None."""
    path = Path(path)
    if not path.is_file():
        return None
    try:
        channels, meta = read_exr(path)
    except Exception:  # noqa: BLE001 (unreadable: render again)
        return None
    if any(str(meta.get(k)) != str(v) for k, v in expected.items()):
        return None
    return np.stack([channels[c] for c in "XYZ"], axis=-1).astype(np.float64)


def write_display_image(exr: Path, png: Path, rgb: np.ndarray, metadata: dict, xyz: np.ndarray | None = None,
                        display=None) -> None:
    """Linear sRGB as EXR channels R, G, B (with X, Y, Z when given) and an 8-bit sRGB PNG of ``display(rgb)``.

    ``display`` is Φ's display response (``VisionState.display``); None: the identity.
    """
    channels = {} if xyz is None else {name: xyz[..., i] for i, name in enumerate("XYZ")}
    channels.update({name: rgb[..., i] for i, name in enumerate("RGB")})
    write_exr(exr, channels, metadata)
    write_png(png, encode_sRGB_8bit(rgb if display is None else display(rgb)))


def delta_e_preview(delta_E: np.ndarray, top: float = DELTA_E_PREVIEW_MAX) -> np.ndarray:
    """False-colour (matplotlib 'magma') 8-bit image of a ΔE map over [0, top]."""
    import matplotlib  # noqa: PLC0415

    scaled = np.clip(np.nan_to_num(delta_E) / top, 0.0, 1.0)
    return np.rint(matplotlib.colormaps["magma"](scaled)[..., :3] * 255).astype(np.uint8)


def write_delta_e(exr: Path, png: Path, maps: dict[str, np.ndarray], water: np.ndarray, metadata: dict) -> None:
    """ΔE maps (one EXR channel each, plus the water mask) and a false-colour PNG of the first."""
    channels = {name: values for name, values in maps.items()}
    channels["water"] = water.astype(np.float32)
    write_exr(exr, channels, {**metadata, "png_scale": f"magma colour map, 0 to {DELTA_E_PREVIEW_MAX:g} dE2000"})
    write_png(png, delta_e_preview(next(iter(maps.values()))))


def write_delta_e_png(png: Path, delta_E: np.ndarray, top: float = DELTA_E_PREVIEW_MAX) -> None:
    write_png(png, delta_e_preview(delta_E, top))


def write_gbuffer(path: Path, gbuffer, metadata: dict) -> None:
    """The G-buffer channels (:meth:`~oceanrender.realtime.gbuffer.GBuffer.channels`) with their meanings."""
    from .gbuffer import CHANNEL_NOTES  # noqa: PLC0415

    notes = {f"channel {key}": value for key, value in CHANNEL_NOTES.items()}
    write_exr(path, gbuffer.channels(), {**metadata, **notes})


def read_gbuffer(path: str | Path):
    """A :class:`~oceanrender.realtime.gbuffer.GBuffer` back from its EXR (inverse of :func:`write_gbuffer`; float32 values)."""
    from .gbuffer import GBuffer  # noqa: PLC0415

    channels, _ = read_exr(path)

    def vector(prefix: str) -> np.ndarray:
        return np.stack([channels[f"{prefix}.{axis}"] for axis in "XYZ"], axis=-1).astype(np.float64)

    return GBuffer(kind=np.rint(channels["kind"]).astype(np.uint8), ray=vector("D"), position=vector("P"),
                   normal=vector("N"), geo_normal=vector("Ng"), distance=channels["distance"].astype(np.float64),
                   cos_view=channels["cos_view"].astype(np.float64), depth=channels["depth"].astype(np.float64),
                   path_length=channels["path_length"].astype(np.float64), refracted=vector("T"),
                   bottom_position=vector("Pb"), rock=channels["rock"].astype(np.float64),
                   roughness=channels["roughness"].astype(np.float64) if "roughness" in channels else None,
                   foam=channels["foam"].astype(np.float64) if "foam" in channels else None)


def write_water_mesh(path: Path, geometry, faces: np.ndarray, comments: dict) -> None:
    """The frame's closed water body (positions [m], vertex normals) as binary PLY."""
    from ..io.ply import write_ply  # noqa: PLC0415

    write_ply(path, geometry.positions, faces, geometry.normals, comments)


def _fmt(stats: dict) -> str:
    return f"{stats['mean']:.2f} | {stats['p95']:.2f} | {stats['max']:.2f}"


def report_markdown(report: dict) -> str:
    """The reference set's report as Markdown (the same content as ``report.json``)."""
    fit = report["gamma_fit"]
    lines = [f"# Real-time model vs path-traced reference: {report['scene']}", "",
             f"Frames {report['frames'][0]}:{report['frames'][1]}, "
             f"{report['resolution'][0]}x{report['resolution'][1]} px, "
             f"{report['spp']} spp{' (denoised, OIDN)' if report.get('denoised') else ''}, variant {report['variant']}. LUTs: `{report['luts']}`. "
             f"Adaptation L_wa = {report['adaptation_luminance_cd_m2']:.6g} cd/m² ({report['adaptation_source']}).",
             "", "CIEDE2000 between the display images (clipped linear sRGB → CIELAB, D65).", "",
             f"## γ of F^γ (Eq. 20), fitted over the water pixels of all frames: γ = {fit['gamma']:.4g}", "",
             "| pixels | γ | mean ΔE | p95 | max |", "|---|---|---|---|---|",
             f"| water, all frames | {fit['gamma_start']:.4g} (before) | {_fmt(fit['before'])} |",
             f"| water, all frames | {fit['gamma']:.4g} (after) | {_fmt(fit['after'])} |", "",
             "## Per frame", "",
             "| frame | pixels | before: mean | p95 | max | after: mean | p95 | max |",
             "|---|---|---|---|---|---|---|---|"]
    for entry in report["per_frame"]:
        for part in ("water", "all"):
            lines.append(f"| {entry['frame']} | {part} ({entry['before'][part]['pixels']}) | "
                         f"{_fmt(entry['before'][part])} | {_fmt(entry['after'][part])} |")
    noise = report.get("reference_noise")
    if noise:
        lines += ["", "## Noise of the reference",
                  f"ΔE2000 between two path-traced renders of frame {noise['frame']} with independent seeds "
                  f"(water pixels): mean {noise['water']['mean']:.2f}, p95 {noise['water']['p95']:.2f}, "
                  f"max {noise['water']['max']:.2f}. A reference's own noise contributes roughly 1/√2 of that to "
                  "every figure above."]
    lines += ["", "## Files", ""] + [f"* `{k}`: {v}" for k, v in report["files"].items()]
    return "\n".join(lines) + "\n"


def write_report(folder: str | Path, report: dict, markdown=None) -> list[Path]:
    """``report.json`` and ``report.md`` (``markdown(report)``; :func:`report_markdown` by default) of a report."""
    folder = Path(folder)
    json_path, md_path = folder / "report.json", folder / "report.md"
    write_json(json_path, report)
    with atomic_path(md_path, ".md") as tmp:
        tmp.write_text((markdown or report_markdown)(jsonable(report)), encoding="utf-8")
    return [json_path, md_path]


def write_camera_json(path: Path, camera, extra: dict) -> None:
    """The camera of a view (:meth:`~oceanrender.realtime.gbuffer.Camera.describe`) plus ``extra``."""
    write_json(path, {**extra, **camera.describe()})


def write_comparison(folder: str | Path, frame: int, reference_xyz: np.ndarray, comparison, gbuffer, camera,
                     geometry, faces: np.ndarray, metadata: dict) -> None:
    """A frame's reference, real-time image (at the LUTs' γ), G-buffer, camera and water mesh."""
    paths = reference_paths(folder, frame)
    meta = {**metadata, "adaptation_luminance_cd_m2": comparison.adaptation_luminance,
            "frame_log_average_cd_m2": comparison.frame_adaptation}
    write_display_image(paths["reference_exr"], paths["reference_png"], comparison.reference_rgb,
                        {**meta, "channels": "XYZ absolute [cd/m2 for Y]; RGB linear sRGB after the vision model's "
                                             "linear stage (the LUTs' adaptation state); PNG after its display "
                                             "response"}, reference_xyz, comparison.display)
    write_display_image(paths["realtime_exr"], paths["realtime_png"], comparison.realtime_rgb,
                        {**meta, "gamma": comparison.gamma,
                         "channels": "RGB linear sRGB before the display response (real-time model)"},
                        display=comparison.display)
    write_gbuffer(paths["gbuffer"], gbuffer, meta)
    write_camera_json(paths["camera"], camera, {"scene": metadata.get("scene"), "frame": frame,
                                                "time_s": metadata.get("time_s")})
    write_water_mesh(paths["mesh"], geometry, faces,
                     {"scene": metadata.get("scene"), "frame": frame, "units": "m, z up, +x east, +y north"})


def write_fitted(folder: str | Path, frame: int, before, after, metadata: dict) -> None:
    """The real-time image at the fitted γ and the ΔE maps before and after the fit."""
    paths = reference_paths(folder, frame)
    write_display_image(paths["fitted_exr"], paths["fitted_png"], after.realtime_rgb,
                        {**metadata, "gamma": after.gamma,
                         "channels": "RGB linear sRGB before the display response (real-time model, fitted gamma)"},
                        display=after.display)
    write_delta_e(paths["delta_e_exr"], paths["delta_e_png"], {"dE_before": before.delta_E, "dE_after": after.delta_E},
                  before.terms.water, {**metadata, "gamma_before": before.gamma, "gamma_after": after.gamma})
    write_delta_e_png(paths["delta_e_fitted_png"], after.delta_E)


# -- shader validation (``oceanrender validate-shader``) -----------------------------------------------------------

#: ΔE2000 at the top of the false-colour scale of the shader-vs-numpy-model maps (agreement is judged at 0.5).
DELTA_E_MODEL_PREVIEW_MAX = 2.0

#: What each file of a shader validation holds (copied into its report).
SHADER_REPORT_FILES = {
    "shader_NNNN.exr/png": "the shader's output: EXR RGB linear sRGB before the display response; PNG as displayed",
    "delta_e_NNNN.exr": "channels dE_reference (shader vs path-traced reference), dE_model (shader vs the numpy "
                        "model on the same G-buffer and LUTs) and water (mask)",
    "delta_e_NNNN.png": "dE2000 shader vs reference, magma colour map 0-20",
    "delta_e_model_NNNN.png": "dE2000 shader vs numpy model, magma colour map 0-2",
}


def write_shader_frame(folder: str | Path, grade, display, metadata: dict) -> None:
    """A graded frame's shader image, ΔE maps (EXR) and their previews."""
    folder = Path(folder)
    stem = f"{grade.frame:04d}"
    write_display_image(folder / f"shader_{stem}.exr", folder / f"shader_{stem}.png", grade.shader_rgb,
                        {**metadata, "channels": "RGB linear sRGB before the display response (the shader's output)"},
                        display=display)
    write_delta_e(folder / f"delta_e_{stem}.exr", folder / f"delta_e_{stem}.png",
                  {"dE_reference": grade.delta_E_reference, "dE_model": grade.delta_E_model}, grade.water, metadata)
    write_delta_e_png(folder / f"delta_e_model_{stem}.png", grade.delta_E_model, DELTA_E_MODEL_PREVIEW_MAX)


def shader_report(grade, references, shader: str, digest: str, renderer: str, strength: float) -> dict:
    """The JSON-ready report of a shader graded on a reference set."""
    ref = references.report
    per_frame = [{"frame": f.frame, **f.stats(), "worst_regions": f.regions} for f in grade.frames]
    return {
        "shader": shader, "shader_sha256": digest, "opengl": renderer, "oceanrender_version": __version__,
        "reference_set": str(references.folder), "luts": str(references.luts_folder), "scene": ref.get("scene"),
        "frames": ref.get("frames"), "resolution": ref.get("resolution"), "spp": ref.get("spp"),
        "denoised": bool(ref.get("denoised", False)), "ripple_strength": strength, "gamma": grade.gamma,
        "totals_water": {"shader_vs_reference": grade.before.describe(),
                         "numpy_model_vs_reference": grade.model_vs_reference.describe(),
                         "shader_vs_numpy_model": grade.shader_vs_model.describe()},
        "totals_all_pixels": {"shader_vs_reference": grade.all_vs_reference.describe()},
        "gamma_fit": {"gamma": grade.fitted_gamma, "gamma_start": grade.gamma, "before": grade.before.describe(),
                      "after": grade.after.describe(), "grid": [list(p) for p in grade.curve],
                      "shader_uses_gamma": grade.gamma_sensitive},
        "reference_noise": ref.get("reference_noise"), "per_frame": per_frame, "files": SHADER_REPORT_FILES,
    }


def shader_report_markdown(report: dict) -> str:
    """The shader report as Markdown (the content of ``report.json``)."""
    t, fit = report["totals_water"], report["gamma_fit"]
    noise = report.get("reference_noise")
    lines = [f"# Shader `{Path(report['shader']).name}` vs path-traced references: {report['scene']}", "",
             f"Reference set `{report['reference_set']}`: frames {report['frames'][0]}:{report['frames'][1]}, "
             f"{report['resolution'][0]}x{report['resolution'][1]} px, {report['spp']} spp"
             f"{' (denoised, OIDN)' if report['denoised'] else ''}. OpenGL: {report['opengl']}. "
             f"Ripple strength {report['ripple_strength']:g}, gamma {report['gamma']:.4g}. "
             f"Shader SHA-256 `{report['shader_sha256'][:16]}…`.", "",
             "CIEDE2000 between the images as displayed (the vision model's display response, clipped, CIELAB D65).",
             "", "## Water pixels, all frames", "", "| comparison | mean | p95 | max | pixels |", "|---|---|---|---|---|"]
    for label, key in (("shader vs reference", "shader_vs_reference"),
                       ("numpy model vs reference (baseline)", "numpy_model_vs_reference"),
                       ("shader vs numpy model (same inputs)", "shader_vs_numpy_model")):
        s = t[key]
        lines.append(f"| {label} | {s['mean']:.3f} | {s['p95']:.3f} | {s['max']:.3f} | {s['pixels']} |")
    if noise:
        w = noise["water"]
        lines += ["", f"Noise floor: two path-traced renders of frame {noise['frame']} with independent seeds"
                      f"{' (both denoised)' if noise.get('denoised') else ''} differ by mean {w['mean']:.2f}, p95 "
                      f"{w['p95']:.2f}, max {w['max']:.2f} (water). A reference's own error is about 1/√2 of that."]
    lines += ["", "## γ of F^γ (Eq. 20), fitted for this shader", ""]
    if fit["shader_uses_gamma"]:
        lines += ["| γ | mean | p95 | max |", "|---|---|---|---|",
                  f"| {fit['gamma_start']:.4g} (given) | {_fmt(fit['before'])} |",
                  f"| {fit['gamma']:.4g} (fitted) | {_fmt(fit['after'])} |"]
    else:
        lines.append("The shader's image does not change with `u_gamma`: no fit.")
    lines += ["", "## Per frame (water pixels)", "",
              "| frame | vs reference: mean | p95 | max | vs numpy model: mean | p95 | max | worst tile "
              "[x0, y0, x1, y1) px: mean dE, view angle, distance |", "|---|---|---|---|---|---|---|---|"]
    for entry in report["per_frame"]:
        worst = entry["worst_regions"][0] if entry["worst_regions"] else None
        where = "—" if worst is None else (
            f"{worst['rect_px']}: {worst['mean']:.1f}, "
            + (f"{worst['view_angle_deg']:.0f}°, {worst['distance_m']:.0f} m" if worst["distance_m"] else "sky"))
        model = entry["shader_vs_model"]["water"]
        lines.append(f"| {entry['frame']} | {_fmt(entry['shader_vs_reference']['water'])} | "
                     f"{model['mean']:.3f} | {model['p95']:.3f} | {model['max']:.3f} | {where} |")
    lines += ["", "## Files", ""] + [f"* `{k}`: {v}" for k, v in report["files"].items()]
    return "\n".join(lines) + "\n"


def write_shader_report(folder: str | Path, report: dict) -> list[Path]:
    """``report.json`` and ``report.md`` of a shader validation."""
    return write_report(folder, report, shader_report_markdown)
