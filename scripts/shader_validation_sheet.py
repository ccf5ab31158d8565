"""Grade the shipped shader and a copy with a wrong Fresnel factor on a reference set; lay out a sheet (docs/realtime.md).

Run from the repository root, on a reference set from ``oceanrender reference``::

    python scripts/shader_validation_sheet.py REFERENCE_DIR docs/images/shader_validation_NAME.png [FRAME]

Writes ``REFERENCE_DIR/shader_water`` and ``REFERENCE_DIR/shader_wrong_fresnel`` (the two
``validate-shader`` outputs, with their reports) and the sheet: the path-traced reference, the
shipped shader and its ΔE2000 map, the broken copy and its map, for one frame (default: the first).

The broken copy looks the Fresnel LUT up at 1 − μ instead of μ = cos θ (an angle/cosine mix-up):
the line marked ``FRESNEL LOOKUP`` in the shader, changed and nothing else.
"""

from __future__ import annotations

import json
import sys
import tempfile
from pathlib import Path

import imageio.v3 as iio
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from oceanrender.cli import main  # noqa: E402
from oceanrender.realtime.glsl import shipped_shader  # noqa: E402

FRESNEL_LINE = "clamp(mu, 0.0, 1.0)).r, 0.0, 1.0);  // FRESNEL LOOKUP"
WRONG_FRESNEL_LINE = "clamp(1.0 - mu, 0.0, 1.0)).r, 0.0, 1.0);  // BROKEN"


def sheet(reference: Path, out: Path, frame: int | None = None) -> None:
    source = shipped_shader().read_text()
    if source.count(FRESNEL_LINE) != 1:
        raise SystemExit("the shipped shader's Fresnel line has changed: update this script")
    with tempfile.TemporaryDirectory() as folder:
        wrong = Path(folder) / "wrong_fresnel.frag"
        wrong.write_text(source.replace(FRESNEL_LINE, WRONG_FRESNEL_LINE))
        outputs = {"shipped": reference / "shader_water", "wrong Fresnel": reference / "shader_wrong_fresnel"}
        assert main(["validate-shader", "shipped", "--reference", str(reference),
                     "--out", str(outputs["shipped"])]) == 0
        assert main(["validate-shader", str(wrong), "--reference", str(reference),
                     "--out", str(outputs["wrong Fresnel"])]) == 0
    reports = {name: json.loads((path / "report.json").read_text()) for name, path in outputs.items()}
    first = reports["shipped"]["frames"][0] if frame is None else frame
    stem = f"{first:04d}"
    panels = [("path-traced reference", iio.imread(reference / f"reference_{stem}.png"))]
    for name, path in outputs.items():
        total = reports[name]["totals_water"]["shader_vs_reference"]
        panels.append((f"{name} shader", iio.imread(path / f"shader_{stem}.png")))
        panels.append((f"{name}: dE2000 (0-20), water mean {total['mean']:.2f}",
                       iio.imread(path / f"delta_e_{stem}.png")))
    fig, axes = plt.subplots(1, 5, figsize=(20, 2.6))
    for ax, (title, image) in zip(axes, panels):
        ax.imshow(image)
        ax.set_title(title, fontsize=9)
        ax.axis("off")
    fig.suptitle(f"{reports['shipped']['scene']}, frame {first}: "
                 f"{reports['shipped']['resolution'][0]}x{reports['shipped']['resolution'][1]}, "
                 f"{reports['shipped']['spp']} spp{' denoised' if reports['shipped']['denoised'] else ''}",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=80)
    print(f"wrote {out}")


if __name__ == "__main__":
    sheet(Path(sys.argv[1]), Path(sys.argv[2]), int(sys.argv[3]) if len(sys.argv) > 3 else None)
