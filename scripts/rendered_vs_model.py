"""Rendered water-leaving radiance of a flat, deep sea against the four-flux model (issue 19, item 4).

For each preset scene (clear open ocean, green coastal, turbid estuary) the renderer's own
medium, sun and sky and integrator, with paths of up to 256 vertices (the scene's own depth
where larger; clear_open_ocean's 12 loses 10 % of its 400 nm light), render L_w at nadir
(``oceanrender.render.flat_sea``), and the four-flux model gives
L_w = L_u(0⁻) (1 − F(0))/n² with

* today's fixed closure (μ_d = 0.83, μ_u = 0.40, Q = π, r̄_wa = 0.475), and
* the coefficients from the medium's phase function and the refracted sun, with Q and the
  surface's reflection of the upwelling from the same discrete-ordinate solution
  (``oceanrender.optics.streams``),

both under the sun and sky irradiance of the same ``sunsky`` (``sky_irradiance_spectra``).
Writes ``docs/data/rendered_vs_model.md`` and ``docs/images/rendered_vs_model.png``.

Usage: ``.venv/bin/python scripts/rendered_vs_model.py [--spp N] [--passes K]``.
"""

from __future__ import annotations

import argparse
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SCENES = ("clear_open_ocean", "green_coastal", "turbid_estuary")
WAVELENGTHS = np.arange(400.0, 701.0, 25.0)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spp", type=int, default=1 << 16)
    parser.add_argument("--passes", type=int, default=4)
    parser.add_argument("--scenes", nargs="*", default=list(SCENES))
    parser.add_argument("--no-write", action="store_true")
    parser.add_argument("--max-depth", type=int, default=256,
                        help="path depth of the renders, at least the scene's (clear_open_ocean's 12 loses 10 %% at 400 nm)")
    args = parser.parse_args(argv)

    from oceanrender.optics.report import nadir_water_leaving
    from oceanrender.optics.scene_water import water_ior, water_optics
    from oceanrender.render.flat_sea import flat_sea_radiance
    from oceanrender.render.irradiance import sky_irradiance_spectra
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene import load_scene

    info = activate_variant("auto")
    lines = ["| scene | λ [nm] | rendered L_w [mW m⁻² sr⁻¹ nm⁻¹] | ± | today | new | Q new [sr] |", "|---|---|---|---|---|---|---|"]
    results = {}
    for name in args.scenes:
        scene = load_scene(ROOT / "scenes" / f"{name}.toml")
        depth = max(scene.render.max_depth, args.max_depth)
        scene = scene.model_copy(update={"render": scene.render.model_copy(update={"max_depth": depth})})
        optics = water_optics(scene)
        start = time.time()
        rendered = flat_sea_radiance(scene, optics, WAVELENGTHS, spp=args.spp, passes=args.passes)
        seconds = time.time() - start
        # NOTE: 2^18 samples: at the scene's white_spp (1024) these band irradiances carry ±5-10 % noise
        direct, diffuse = sky_irradiance_spectra(scene.sun, WAVELENGTHS, spp=1 << 18)
        old, new, co = nadir_water_leaving(optics, WAVELENGTHS, direct, diffuse, 90.0 - scene.sun.elevation,
                                           water_ior(scene))
        results[name] = (rendered, old, new)
        for i, w in enumerate(WAVELENGTHS):
            L = rendered.water_leaving[i]
            lines.append(f"| {name} | {w:.0f} | {1e3 * L:.4g} | {100 * rendered.water_leaving_error[i] / L:.1f} % "
                         f"| {100 * (old[i] / L - 1):+.1f} % | {100 * (new[i] / L - 1):+.1f} % | {co.Q[i]:.2f} |")
        worst_old = np.max(np.abs(old / rendered.water_leaving - 1))
        worst_new = np.max(np.abs(new / rendered.water_leaving - 1))
        print(f"{name}: {seconds:.0f} s render; largest |model/render − 1| today {100 * worst_old:.1f} %, "
              f"new {100 * worst_new:.1f} %; noise ≤ {100 * np.max(rendered.water_leaving_error / rendered.water_leaving):.1f} %",
              flush=True)
    header = (f"Flat deep sea, nadir, {args.spp} paths × {args.passes} passes per scene, max_depth ≥ {args.max_depth} "
              f"({info.variant}, "
              f"{time.strftime('%Y-%m-%d %H:%M')}); errors: model/render − 1; ± one standard error of the render.")
    text = "\n".join([header, ""] + lines) + "\n"
    print(text)
    if not args.no_write:
        (ROOT / "docs" / "data" / "rendered_vs_model.md").write_text(text)
        plot(results, ROOT / "docs" / "images" / "rendered_vs_model.png")
    return 0


def plot(results, path: pathlib.Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(results), figsize=(4.3 * len(results), 3.8))
    for ax, (name, (rendered, old, new)) in zip(np.atleast_1d(axes), results.items()):
        wl = rendered.wavelengths
        ax.errorbar(wl, 1e3 * rendered.water_leaving, yerr=2e3 * rendered.water_leaving_error, fmt="ko", ms=4,
                    label="rendered (±2σ)")
        ax.plot(wl, 1e3 * old, "r--", label="four-flux, today")
        ax.plot(wl, 1e3 * new, "b-", label="four-flux, from the phase function")
        ax.set_title(name.replace("_", " "))
        if name == "clear_open_ocean":  # its red is two decades below its blue
            ax.set_yscale("log")
        ax.set_xlabel("wavelength [nm]")
        ax.grid(alpha=0.3)
    np.atleast_1d(axes)[0].set_ylabel("L_w at nadir [mW m⁻² sr⁻¹ nm⁻¹]")
    np.atleast_1d(axes)[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    raise SystemExit(main())
