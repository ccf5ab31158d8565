"""How the four-flux coefficients from the phase function change the baked T0 LUT (issue 19, item 3).

For each preset scene, the T0 table (Eq. 21: the water-leaving colour over a black bottom
at depth h) is baked twice with the scene's own light and adaptation state: with today's
fixed closure (μ_d = 0.83, μ_u = 0.40) and with the coefficients from the medium's phase
function and the refracted sun (``oceanrender.optics.streams``). Printed: T0's spectral radiance
(``upwelling_radiance``) at h = ∞ and 450/550/650 nm (new/old) and ΔE2000 between the two T0 colours at h = 2 m, 10 m and ∞.

Usage: ``.venv/bin/python scripts/lut_change.py`` (writes ``docs/data/lut_change.md``).
"""

from __future__ import annotations

import dataclasses
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SCENES = ("clear_open_ocean", "green_coastal", "turbid_estuary")


def main() -> int:
    from oceanrender.pipeline import vision_for_scene
    from oceanrender.realtime.bake import BakeSettings, measure_scene_light, water_column
    from oceanrender.realtime.compare import delta_E_2000
    from oceanrender.realtime.luts import VisionState, upwelling_radiance
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene

    activate_variant("auto")
    depths = np.array([2.0, 10.0, np.inf])
    lines = ["| scene | T0's radiance at h = ∞, new/old, at 450, 550, 650 nm | ΔE2000 of T0 at h = 2 m, 10 m, ∞ |", "|---|---|---|"]
    for name in SCENES:
        scene = load_scene(ROOT / "scenes" / f"{name}.toml")
        settings = BakeSettings()
        light = measure_scene_light(scene, settings)
        new = water_column(scene, light)
        old = dataclasses.replace(new, phase=None)
        phi = VisionState(vision_for_scene(scene), light.white_XYZ, 0.18 * float(light.white_XYZ[1]))
        up_new, _ = upwelling_radiance(new, depths)
        up_old, _ = upwelling_radiance(old, depths)
        wl = new.wavelengths
        ratio = [float(np.interp(w, wl, up_new[-1]) / np.interp(w, wl, up_old[-1])) for w in (450.0, 550.0, 650.0)]
        colours = {}
        for key, column in (("new", new), ("old", old)):
            colours[key] = np.array([phi.spectra(u, wl) for u in upwelling_radiance(column, depths)[0]])
        dE = delta_E_2000(np.clip(colours["new"], 0, 1), np.clip(colours["old"], 0, 1))
        lines.append(f"| {name} | {ratio[0]:.3f}, {ratio[1]:.3f}, {ratio[2]:.3f} | "
                     f"{dE[0]:.2f}, {dE[1]:.2f}, {dE[2]:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    (ROOT / "docs" / "data" / "lut_change.md").write_text(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
