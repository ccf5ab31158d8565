"""Render frame 0 of a scene with every render pass and lay the passes out as a contact sheet (docs/passes.md).

Run from the repository root::

    python scripts/passes_contact_sheet.py scenes/boat.toml docs/images/passes_contact_sheet.png

The frame goes to a temporary folder; the sheet shows the beauty pass (the PNG), Z on a
log scale, N as 0.5 + 0.5 n, P.z, the three masks and the in-water path length (log).
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import imageio.v3 as iio
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from oceanrender.cli import main  # noqa: E402
from oceanrender.io.frames import read_exr  # noqa: E402
from oceanrender.render.passes import PASSES  # noqa: E402
from oceanrender.scene import load_scene  # noqa: E402


def sheet(scene_path: Path, out: Path) -> None:
    scene = load_scene(scene_path)
    with tempfile.TemporaryDirectory() as folder:
        toml = Path(folder) / "scene.toml"
        text = scene_path.read_text().replace("[output]\n", f'[output]\npasses = {list(PASSES)!r}\n'.replace("'", '"'), 1)
        text = text.replace('mesh = "meshes/', f'mesh = "{scene_path.parent.resolve()}/meshes/')
        toml.write_text(text)
        assert main(["render", str(toml), "--frames", "0:1", "--out", folder, "--spp", "32", "--denoise",
                     "--no-progress"]) == 0
        channels, _ = read_exr(Path(folder) / scene.name / "frame_0000.exr")
        beauty = iio.imread(Path(folder) / scene.name / "frame_0000.png")
    panels = [
        ("beauty (PNG)", beauty, None),
        ("depth.Z [m], log10", np.log10(np.clip(channels["depth.Z"], 0.1, 1e10)), "viridis"),
        ("N (0.5 + 0.5 n)", np.clip(0.5 + 0.5 * np.stack([channels[f"N.{c}"] for c in "XYZ"], -1), 0, 1), None),
        ("P.Z [m]", channels["P.Z"], "coolwarm"),
        ("mask.water", channels["mask.water"], "gray"),
        ("mask.foam", channels["mask.foam"], "gray"),
        ("mask.objects", channels["mask.objects"], "gray"),
        ("water_path [m], log10", np.log10(np.clip(channels["water_path"], 0.1, 1e10)), "magma"),
    ]
    fig, axes = plt.subplots(2, 4, figsize=(16, 5.2))
    for ax, (title, image, cmap) in zip(axes.ravel(), panels):
        shown = ax.imshow(image, cmap=cmap)
        if cmap is not None and title not in ("mask.water", "mask.objects"):
            fig.colorbar(shown, ax=ax, fraction=0.03)
        ax.set_title(title)
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(out, dpi=80)
    print(f"wrote {out}")


if __name__ == "__main__":
    sheet(Path(sys.argv[1]), Path(sys.argv[2]))
