"""K_d of the Jerlov types from Solonenko & Mobley's (2015) a, b against their HydroLight K_d^H (issue 43, item 4).

For Jerlov I, II, III, 1C, 5C and 9C at 400-600 nm (25 nm steps; 5C has no a beyond 575 nm):

1. the four-flux model with coefficients from the phase function (``oceanrender.optics.jerlov_kd.kd_four_flux``)
   and its fixed closure of before issue 19 (``kd_four_flux_fixed``), and the exact transport
   (discrete ordinates, ``kd_transport``), under :class:`~oceanrender.optics.jerlov_kd.KdConditions`;
2. what each condition does: the exact transport from the set-up of issue 19's comparison (sun overhead,
   no sky, an index-matched top, K_d over the first optical depth) to the conditions of the comparison,
   one change at a time, and the literal "10 scattering lengths" (6 for III) of the package's caveat;
3. the Mitsuba Monte Carlo slab under a level dielectric surface lit by the sun and two rings of sky
   (``oceanrender.render.slab.slab_kd``) at 400, 450, 500, 550, 600 nm.

Writes ``docs/data/kd_hydrolight.json`` (every number), ``docs/data/kd_hydrolight.md`` (the tables) and
``docs/images/kd_hydrolight.png`` (model/K_d^H against wavelength, one panel per type).

Usage: ``.venv/bin/python scripts/kd_hydrolight.py [--spp N] [--passes K] [--no-mc] [--plot-only]``
(~3 min on 2 cores; ``--plot-only`` redraws the figure from the JSON).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

WAVELENGTHS_NM = np.arange(400.0, 601.0, 25.0)
MC_WAVELENGTHS_NM = (400.0, 450.0, 500.0, 550.0, 600.0)
SKY_NODES_MC = 2


def steps():
    """The exact transport's conditions, one change at a time (label, KdConditions, scattering lengths of III)."""
    from oceanrender.optics.jerlov_kd import KdConditions

    before = KdConditions(sun_zenith_deg=0.0, sky_fraction=0.0, layer_m=None, level_surface=False,
                          water_rayleigh=False)
    out = [("issue 19's slab: sun overhead, no sky, index-matched top, first optical depth, all of b Petzold's", before)]
    out.append(("+ a level surface (Fresnel, internal reflection)", dataclasses.replace(before, level_surface=True)))
    out.append(("+ the water molecules' scattering (Morel) split from b", dataclasses.replace(out[-1][1], water_rayleigh=True)))
    out.append(("+ sun 30° from the zenith", dataclasses.replace(out[-1][1], sun_zenith_deg=30.0)))
    out.append(("+ 15 % sky (uniform)", dataclasses.replace(out[-1][1], sky_fraction=0.15)))
    out.append(("+ K_d over 0-10 m (the comparison's conditions)", dataclasses.replace(out[-1][1], layer_m=10.0)))
    out.append(("instead: K_d over 10 scattering lengths (6 for III), the package's wording",
                dataclasses.replace(out[-1][1], scattering_lengths=10.0)))
    for zenith in (0.0, 60.0):
        out.append((f"instead: sun {zenith:.0f}° (0-10 m, 15 % sky)", dataclasses.replace(out[5][1], sun_zenith_deg=zenith)))
    return out


def model_tables():
    from oceanrender.optics.jerlov_kd import (HYDROLIGHT_TYPES, KdConditions, kd_four_flux, kd_four_flux_fixed,
                                              kd_transport, solonenko2015_water)

    conditions = KdConditions()
    rows, sensitivity = {}, []
    water = {t: solonenko2015_water(t, WAVELENGTHS_NM) for t in HYDROLIGHT_TYPES}
    for t, (a, b, b_w, kd_h) in water.items():
        ok = np.isfinite(a) & np.isfinite(kd_h)
        rows[t] = {"wavelength_nm": WAVELENGTHS_NM[ok].tolist(), "a": a[ok].tolist(), "b": b[ok].tolist(),
                   "b_w": b_w[ok].tolist(), "Kd_hydrolight": kd_h[ok].tolist(),
                   "four_flux": kd_four_flux(a[ok], b[ok], b_w[ok], conditions).tolist(),
                   "four_flux_fixed": kd_four_flux_fixed(a[ok], b[ok], b_w[ok], conditions).tolist(),
                   "transport": kd_transport(a[ok], b[ok], b_w[ok], conditions).tolist()}
    for label, cond in steps():
        ratios = []
        for t, (a, b, b_w, kd_h) in water.items():
            ok = np.isfinite(a) & np.isfinite(kd_h)
            c = dataclasses.replace(cond, scattering_lengths=6.0) if (cond.scattering_lengths and t == "III") else cond
            ratios.append(kd_transport(a[ok], b[ok], b_w[ok], c) / kd_h[ok])
        r = np.concatenate(ratios)
        per_type = {t: [float(x.min()), float(x.max())] for t, x in zip(water, ratios)}
        sensitivity.append({"step": label, "min": float(r.min()), "max": float(r.max()),
                            "worst": float(np.abs(r - 1).max()), "per_type": per_type})
    return conditions, rows, sensitivity


def monte_carlo(conditions, spp: int, passes: int):
    from oceanrender.optics.jerlov_kd import (HYDROLIGHT_TYPES, hydrolight_phase, kd_transport, solonenko2015_water,
                                              surface_beams)
    from oceanrender.render.slab import slab_kd
    from oceanrender.runtime.variants import activate_variant

    activate_variant("auto")
    zeniths, weights = surface_beams(conditions, SKY_NODES_MC)
    out = {}
    for t in HYDROLIGHT_TYPES:
        a, b, b_w, kd_h = solonenko2015_water(t, MC_WAVELENGTHS_NM)
        mu, p = hydrolight_phase(b, b_w, conditions.water_rayleigh)
        cells = []
        for i, wl in enumerate(MC_WAVELENGTHS_NM):
            if not (np.isfinite(a[i]) and np.isfinite(kd_h[i])):
                continue
            start = time.time()
            r = slab_kd(float(a[i]), float(b[i]), (mu, p[i]), zeniths, weights, conditions.layer_m, conditions.n_water,
                        spp=spp, passes=passes, seed=int(wl))
            transport = float(kd_transport(a[i:i + 1], b[i:i + 1], b_w[i:i + 1], conditions)[0])
            cells.append({"wavelength_nm": wl, "K": r.K, "K_error": r.K_error, "Kd_hydrolight": float(kd_h[i]),
                          "transport": transport, "seconds": time.time() - start})
            print(f"  MC {t} {wl:.0f} nm: K {r.K:.4f} ± {r.K_error:.4f}, K_d^H {kd_h[i]:.4f}, "
                  f"ratio {r.K / kd_h[i]:.3f}, transport/MC {transport / r.K:.3f} ({time.time() - start:.1f} s)", flush=True)
        out[t] = cells
    return out


def markdown(conditions, rows, sensitivity, mc) -> str:
    lines = [f"Conditions: {conditions}", "",
             "| type | λ [nm] | K_d^H [m⁻¹] | four-flux / K_d^H | fixed closure (before) / K_d^H | exact transport / K_d^H |"
             + (" Monte Carlo / K_d^H (±1σ) |" if mc else ""),
             "|---|---|---|---|---|---|" + ("---|" if mc else "")]
    for t, r in rows.items():
        mc_cells = {c["wavelength_nm"]: c for c in mc.get(t, [])} if mc else {}
        for j, wl in enumerate(r["wavelength_nm"]):
            kh = r["Kd_hydrolight"][j]
            cell = (f"| {t} | {wl:.0f} | {kh:.4g} | {r['four_flux'][j] / kh:.3f} | {r['four_flux_fixed'][j] / kh:.3f} | "
                    f"{r['transport'][j] / kh:.3f} |")
            if mc:
                c = mc_cells.get(wl)
                cell += f" {c['K'] / kh:.3f} ± {c['K_error'] / kh:.3f} |" if c else " |"
            lines.append(cell)
    lines += ["", "| exact transport under | min / K_d^H | max / K_d^H | largest \\|ratio − 1\\| |", "|---|---|---|---|"]
    for s in sensitivity:
        lines.append(f"| {s['step']} | {s['min']:.3f} | {s['max']:.3f} | {100 * s['worst']:.1f} % |")
    return "\n".join(lines) + "\n"


def plot(data: dict, out: pathlib.Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 3, figsize=(11, 6.2), sharex=True, sharey=True)
    for ax, (t, r) in zip(axes.ravel(), data["models"].items()):
        wl, kh = np.array(r["wavelength_nm"]), np.array(r["Kd_hydrolight"])
        ax.axhspan(0.85, 1.15, color="0.92")
        ax.axhspan(0.90, 1.10, color="0.85")
        ax.plot(wl, np.array(r["four_flux_fixed"]) / kh, "s:", color="tab:red", label="four-flux, fixed closure (before)")
        ax.plot(wl, np.array(r["four_flux"]) / kh, "o-", color="tab:blue", label="four-flux, coefficients from the phase function")
        ax.plot(wl, np.array(r["transport"]) / kh, "-", color="k", label="exact transport (discrete ordinates)")
        cells = data["monte_carlo"].get(t, [])
        if cells:
            ax.errorbar([c["wavelength_nm"] for c in cells], [c["K"] / c["Kd_hydrolight"] for c in cells],
                        yerr=[2 * c["K_error"] / c["Kd_hydrolight"] for c in cells], fmt="D", color="tab:green",
                        label="Mitsuba Monte Carlo slab (±2σ)")
        ax.axhline(1.0, color="0.5", lw=0.8)
        ax.set_title(f"Jerlov {t}")
        ax.set_ylim(0.5, 1.2)
    for ax in axes[1]:
        ax.set_xlabel("wavelength [nm]")
    for ax in axes[:, 0]:
        ax.set_ylabel("K_d / HydroLight's K_d^H")
    axes[0, 0].legend(fontsize=7, loc="lower right")
    fig.suptitle("K_d over 0-10 m, sun 30°, 15 % sky, level surface; shaded: ±10 %, ±15 %", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spp", type=int, default=4096)
    parser.add_argument("--passes", type=int, default=3)
    parser.add_argument("--no-mc", action="store_true")
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()
    figure = ROOT / "docs" / "images" / "kd_hydrolight.png"
    if args.plot_only:
        plot(json.loads((ROOT / "docs" / "data" / "kd_hydrolight.json").read_text()), figure)
        return 0
    conditions, rows, sensitivity = model_tables()
    for s in sensitivity:
        print(f"{s['step']}: {s['min']:.3f}-{s['max']:.3f} (worst {100 * s['worst']:.1f} %)")
    for name in ("four_flux", "four_flux_fixed", "transport"):
        r = np.concatenate([np.array(v[name]) / np.array(v["Kd_hydrolight"]) for v in rows.values()])
        print(f"{name}: {r.min():.3f}-{r.max():.3f} of K_d^H (worst {100 * np.abs(r - 1).max():.1f} %)")
    mc = {} if args.no_mc else monte_carlo(conditions, args.spp, args.passes)
    if mc:
        r = np.array([c["K"] / c["Kd_hydrolight"] for cells in mc.values() for c in cells])
        print(f"Monte Carlo: {r.min():.3f}-{r.max():.3f} of K_d^H (worst {100 * np.abs(r - 1).max():.1f} %)")
    data = {"conditions": dataclasses.asdict(conditions), "models": rows, "sensitivity": sensitivity,
            "monte_carlo": mc, "monte_carlo_settings": {"spp": args.spp, "passes": args.passes,
                                                        "sky_nodes": SKY_NODES_MC}}
    out = ROOT / "docs" / "data"
    (out / "kd_hydrolight.json").write_text(json.dumps(data, indent=1) + "\n")
    (out / "kd_hydrolight.md").write_text(markdown(conditions, rows, sensitivity, mc))
    plot(data, figure)
    print(f"wrote {out / 'kd_hydrolight.json'}, kd_hydrolight.md and {figure}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
