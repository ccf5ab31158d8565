"""Display figures of the vision model Φ on rendered frames: clipping per operator, and flicker.

    python scripts/vision_figures.py clipping DIR [DIR ...]    # frames rendered with the CLI
    python scripts/vision_figures.py flicker DIR               # a still camera's frame sequence

``clipping`` reads every ``*/frame_NNNN.exr`` under the folders (their XYZ,
adapting white and adaptation luminance), applies each brightness operator
with the frame's own adaptation state, and counts 8-bit display pixels that
reach 255 in any channel and in all three, over the pixels that are not a
direct view of the sun: pixels whose world luminance exceeds that of a white
Lambertian plane under the same sun and sky (Y > Y_white) are the sun disc,
the circumsolar sky and specular sparkles — nothing diffuse can be brighter
than that plane. It writes ``<frame>_<operator>.png`` beside nothing: PNGs go
to ``--png DIR`` when given.

``adaptation SCENE`` meters every frame of a scene (the pipeline's own
2-spp meter) and prints, per frame, the meter's log-average and the state the
eye reaches with the scene's ``adaptation_time`` (and what a per-frame
adaptation would give), e.g. for the flyover's turn towards the sun.

``flicker`` reports, for consecutive PNG frames, the relative change of the
mean display luminance (the mean of the sRGB-decoded Rec. 709 luminance).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from oceanrender.io.frames import read_exr, write_png
from oceanrender.vision.brightness import BRIGHTNESS_METHODS
from oceanrender.vision.display import encode_sRGB_8bit
from oceanrender.vision.model import VisionModel


def frame_state(meta: dict) -> tuple[np.ndarray, float]:
    """(adapting white XYZ [cd m⁻²], adaptation luminance [cd m⁻²]) recorded in a frame's EXR."""
    white = np.array([float(v) for v in str(meta["white_XYZ_cd_m2"]).split()])
    return white, float(meta["adaptation_luminance_cd_m2"])


def clipping(xyz: np.ndarray, white: np.ndarray, adaptation: float, model: VisionModel) -> dict:
    """Shares of non-sun pixels at 255 in any / all channels, of sun pixels, and the 8-bit image."""
    rgb8 = encode_sRGB_8bit(model.apply(xyz, white, adaptation))
    sun = xyz[..., 1] > white[1]
    rest = ~sun
    at_max = rgb8 == 255
    return {"any_channel_255": float(at_max.any(-1)[rest].mean()), "white_255": float(at_max.all(-1)[rest].mean()),
            "any_channel_255_all_pixels": float(at_max.any(-1).mean()),
            "sun_or_sparkle_pixels": float(sun.mean()), "rgb8": rgb8}


def cmd_clipping(args: argparse.Namespace) -> None:
    rows = []
    for folder in args.folders:
        for exr in sorted(Path(folder).glob("*/frame_*.exr")):
            if exr.name.endswith("_spectral.exr"):
                continue
            channels, meta = read_exr(exr)
            xyz = np.stack([channels[c] for c in "XYZ"], -1).astype(np.float64)
            white, adaptation = frame_state(meta)
            for name in BRIGHTNESS_METHODS:
                result = clipping(xyz, white, adaptation, VisionModel(brightness=name))
                rgb8 = result.pop("rgb8")
                rows.append({"scene": exr.parent.name, "frame": exr.stem, "operator": name, **result})
                if args.png:
                    out = Path(args.png) / f"{exr.parent.name}_{exr.stem}_{name.replace(' ', '_')}.png"
                    out.parent.mkdir(parents=True, exist_ok=True)
                    write_png(out, rgb8)
    print(f"{'scene':28s} {'operator':22s} {'any ch 255':>10s} {'white':>8s} {'sun px':>8s} {'any, all px':>11s}")
    for r in rows:
        print(f"{r['scene']:28s} {r['operator']:22s} {100 * r['any_channel_255']:9.2f}% "
              f"{100 * r['white_255']:7.2f}% {100 * r['sun_or_sparkle_pixels']:7.3f}% {100 * r['any_channel_255_all_pixels']:10.2f}%")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))


def display_luminance(png: Path) -> float:
    """Mean relative luminance of an 8-bit sRGB PNG (decoded to linear, Rec. 709 weights) [-]."""
    import imageio.v3 as iio  # noqa: PLC0415

    v = iio.imread(png)[..., :3].astype(np.float64) / 255.0
    linear = np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)  # IEC 61966-2-1
    return float((linear @ np.array([0.2126, 0.7152, 0.0722])).mean())


def cmd_flicker(args: argparse.Namespace) -> None:
    pngs = sorted(Path(args.folder).glob("frame_*.png"))
    means = np.array([display_luminance(p) for p in pngs])
    change = np.abs(np.diff(means)) / means[:-1]
    result = {"frames": len(pngs), "mean_display_luminance": means.tolist(),
              "max_change": float(change.max()), "mean_change": float(change.mean()),
              "p95_change": float(np.percentile(change, 95))}
    print(f"{args.folder}: {len(pngs)} frames, frame-to-frame change of mean display luminance: "
          f"mean {100 * result['mean_change']:.3f} %, p95 {100 * result['p95_change']:.3f} %, "
          f"max {100 * result['max_change']:.3f} %")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=1))


def cmd_adaptation(args: argparse.Namespace) -> None:
    from oceanrender.pipeline import Sequence  # noqa: PLC0415
    from oceanrender.runtime.variants import activate_variant  # noqa: PLC0415
    from oceanrender.scene.settings import load_scene, with_overrides  # noqa: PLC0415

    scene = load_scene(args.scene)
    if args.resolution:
        scene = with_overrides(scene, output={"resolution": [int(v) for v in args.resolution.split("x")]})
    runtime = activate_variant("auto")
    sequence = Sequence(scene, runtime.variant)
    frames = range(*scene.output.frames)
    rows = []
    for frame in frames:
        state, target = sequence.followed_adaptation(frame)
        rows.append({"frame": frame, "time_s": frame / scene.output.fps, "meter_cd_m2": target,
                     "adapted_cd_m2": state})
        print(f"{frame:4d} t={frame / scene.output.fps:6.3f} s  meter {target:10.1f}  adapted {state:10.1f} cd/m2  "
              f"(ratio {state / target:.3f})")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))


def cmd_sheet(args: argparse.Namespace) -> None:
    """A labelled grid of ``frame_0000.png`` of every scene folder under ``root`` (2 columns)."""
    from PIL import Image, ImageDraw, ImageFont  # noqa: PLC0415

    pngs = sorted(Path(args.root).glob(f"*/frame_{args.frame:04d}.png"))
    frames = [Image.open(p).convert("RGB") for p in pngs]
    w, h = frames[0].size
    label, margin, columns = 16, 4, 2
    rows = -(-len(frames) // columns)
    sheet = Image.new("RGB", (columns * (w + margin) + margin, rows * (h + label + margin) + margin), (24, 24, 24))
    draw = ImageDraw.Draw(sheet)
    font = ImageFont.load_default(size=12)
    for i, (png, frame) in enumerate(zip(pngs, frames)):
        x = margin + (i % columns) * (w + margin)
        y = margin + (i // columns) * (h + label + margin)
        sheet.paste(frame, (x, y))
        draw.text((x + 2, y + h + 1), png.parent.name, fill=(230, 230, 230), font=font)
    sheet.save(args.out)
    print(f"{args.out}: {len(frames)} scenes")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    c = sub.add_parser("clipping")
    c.add_argument("folders", nargs="+")
    c.add_argument("--png", help="write each frame under each operator as PNG here")
    c.add_argument("--json")
    f = sub.add_parser("flicker")
    f.add_argument("folder")
    f.add_argument("--json")
    a = sub.add_parser("adaptation")
    a.add_argument("scene")
    a.add_argument("--resolution", help="WxH of the meter renders (default: the scene's)")
    a.add_argument("--json")
    sh = sub.add_parser("sheet")
    sh.add_argument("root")
    sh.add_argument("out")
    sh.add_argument("--frame", type=int, default=0)
    args = parser.parse_args()
    {"sheet": cmd_sheet, "clipping": cmd_clipping, "flicker": cmd_flicker, "adaptation": cmd_adaptation}[args.command](args)


if __name__ == "__main__":
    main()
