"""The coast rendered with the DG scheme beside the default finite-volume scheme (issue 44, item 4).

Reads frame 0 of ``coastal_beach`` and ``coastal_bay`` rendered twice — the scenes as shipped (scheme
"kinetic", order 2, MC) and with ``[coastal] scheme = "dg"``, ``limiter = "minmod"``, ``cfl = 0.3`` — and
their stored fields, and writes docs/images/dg_coastal_renders.png (rows: scenes; columns: finite volume,
DG) and docs/data/dg_coastal_renders.md: per scene the RMS and largest difference of the surface η [m]
over cells wet in both, the wet area of each [m²], and the mean CIE ΔE00 between the two PNGs
(colour-science; it includes the Monte Carlo noise of two independent 32-spp renders, so it bounds the
scheme's effect on the picture from above).

Make the renders first (scene copies named ``<scene>_fv`` and ``<scene>_dg`` under one output folder)::

    oceanrender render SCENES/coastal_beach_dg.toml --frames 0:1     # and _fv, and the bay's

Usage: ``.venv/bin/python scripts/dg_coastal_renders.py OUTPUT_FOLDER``.
"""

from __future__ import annotations

import argparse
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SCENES = ("coastal_beach", "coastal_bay")
LABELS = {"fv": "finite volume (kinetic, MUSCL + Heun, MC: as shipped)", "dg": "DG P1 (minmod), cfl 0.3"}


def surface_difference(folder: pathlib.Path, scene: str) -> tuple[float, float, float, float]:
    """(RMS, largest |Δη| [m] over cells wet in both, wet area FV, wet area DG [m²]) at frame 0."""
    from oceanrender.coastal.simulation import read_frame_fields

    fields = {k: read_frame_fields(folder / f"{scene}_{k}" / "coastal", 0) for k in ("fv", "dg")}
    area = float(fields["fv"]["dx"] * fields["fv"]["dy"])
    wet = {k: f["h"] > 0.002 for k, f in fields.items()}
    both = wet["fv"] & wet["dg"]
    diff = (fields["fv"]["h"] + fields["fv"]["bed"]) - (fields["dg"]["h"] + fields["dg"]["bed"])
    return (float(np.sqrt(np.mean(diff[both] ** 2))), float(np.abs(diff[both]).max()),
            float(wet["fv"].sum() * area), float(wet["dg"].sum() * area))


def delta_e(a: np.ndarray, b: np.ndarray) -> float:
    """Mean CIE ΔE00 between two sRGB images (uint8)."""
    import colour

    lab = [colour.XYZ_to_Lab(colour.sRGB_to_XYZ(image[..., :3] / 255.0)) for image in (a, b)]
    return float(np.mean(colour.delta_E(lab[0], lab[1], method="CIE 2000")))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path)
    args = parser.parse_args()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from PIL import Image

    fig, axes = plt.subplots(len(SCENES), 2, figsize=(10, 2.9 * len(SCENES)), dpi=110)
    rows = ["| scene | RMS Δη over cells wet in both [m] | largest |Δη| [m] | wet area FV / DG [m²] | mean ΔE00 of "
            "the frames (incl. noise) |", "|---|---:|---:|---:|---:|"]
    for r, scene in enumerate(SCENES):
        images = {k: np.asarray(Image.open(args.folder / f"{scene}_{k}" / "frame_0000.png")) for k in ("fv", "dg")}
        for c, kind in enumerate(("fv", "dg")):
            ax = axes[r, c]
            ax.imshow(images[kind])
            ax.set_title(f"{scene}: {LABELS[kind]}", fontsize=8)
            ax.axis("off")
        rms, largest, wet_fv, wet_dg = surface_difference(args.folder, scene)
        rows.append(f"| {scene} | {rms:.4f} | {largest:.3f} | {wet_fv:.0f} / {wet_dg:.0f} | "
                    f"{delta_e(images['fv'], images['dg']):.2f} |")
    fig.tight_layout()
    out = ROOT / "docs" / "images" / "dg_coastal_renders.png"
    fig.savefig(out, bbox_inches="tight")
    table = "Frame 0, 320 × 180 px, 32 spp (scripts/dg_coastal_renders.py)\n\n" + "\n".join(rows) + "\n"
    (ROOT / "docs" / "data" / "dg_coastal_renders.md").write_text(table)
    print(table)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
