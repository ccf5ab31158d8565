"""Mitsuba Monte Carlo light fields of deep water slabs over the grid of issue 19, item 3.

Runs :func:`oceanrender.render.slab.slab_light_field` for every valid cell of

    b_b/a ∈ {0.001, 0.01, 0.1, 1} × ω₀ = b/c ∈ {0.1, 0.5, 0.8, 0.95} × sun zenith in air {0°, 30°, 60°}

with a = 0.1 m⁻¹ and a Fournier–Forand phase function whose b_b/b = (b_b/a)(1 − ω₀)/ω₀
(Mobley et al. 2002 parameters). Cells whose b_b/b lies outside the Fournier–Forand fit
(0.0003–0.3) are not physical for a particle phase function and are left out (b_b/b would be
0.9 or more, or below 0.0003). The beam travels at the refracted angle of the sun
(n = 1.334); the slab's surface is index-matched (see the module docstring of
``oceanrender.render.slab``).

Depths: E_d is metered at z₁·{0.85, 1, 1.15} (z₁ the first optical depth of the discrete-
ordinate solution, ``oceanrender.optics.streams``, only to place the meters) and at 10 m, so
that the first optical depth (quadratic interpolation of ln E_d through the three) and the
0–10 m mean are read from the Monte Carlo numbers alone. Writes the raw Monte Carlo numbers
(with their standard errors) to ``docs/data/fourflux_slab_mc.json``; ``scripts/fourflux_agreement.py``
compares models with them.

Usage: ``.venv/bin/python scripts/fourflux_slab_mc.py [--spp N] [--passes K] [--out FILE]``
(~40 min at the defaults on 2 cores).
"""

from __future__ import annotations

import argparse
import json
import math
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

A_PER_M = 0.1
BB_OVER_A = (0.001, 0.01, 0.1, 1.0)
ALBEDOS = (0.1, 0.5, 0.8, 0.95)
SUN_ZENITHS_DEG = (0.0, 30.0, 60.0)
N_WATER = 1.334
DEPTH_FACTORS = (0.85, 1.0, 1.15)
MEAN_DEPTH_M = 10.0


def grid():
    """The valid cells: (b_b/a, ω₀, b_b/b)."""
    from oceanrender.optics.components import fournier_forand_bb_ratio

    lo = float(fournier_forand_bb_ratio(1.01 + 0.1542 * 0.0005, 3.0005))
    hi = float(fournier_forand_bb_ratio(1.01 + 0.1542 * 2.0, 5.0))
    cells = []
    for ratio in BB_OVER_A:
        for albedo in ALBEDOS:
            bb_over_b = ratio * (1.0 - albedo) / albedo
            if lo <= bb_over_b <= hi:
                cells.append((ratio, albedo, bb_over_b))
    return cells


def refracted_zenith_deg(zenith_deg: float) -> float:
    """Zenith angle in the water of a beam at ``zenith_deg`` in air (Snell) [deg]."""
    return math.degrees(math.asin(math.sin(math.radians(zenith_deg)) / N_WATER))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spp", type=int, default=50_000)
    parser.add_argument("--passes", type=int, default=4)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "docs" / "data" / "fourflux_slab_mc.json")
    args = parser.parse_args(argv)

    from oceanrender.optics.components import tabulated_fournier_forand
    from oceanrender.optics.streams import N_STREAMS, deep_layer, first_optical_depth, legendre_moments
    from oceanrender.render.slab import slab_light_field
    from oceanrender.runtime.variants import activate_variant

    info = activate_variant("auto")
    records = []
    start = time.time()
    for ratio, albedo, bb_over_b in grid():
        b = A_PER_M * albedo / (1.0 - albedo)
        bb = ratio * A_PER_M
        table = tabulated_fournier_forand(bb_over_b)
        for zenith in SUN_ZENITHS_DEG:
            theta_w = refracted_zenith_deg(zenith)
            layer = deep_layer(A_PER_M, b, legendre_moments(*table, 2 * N_STREAMS + 1), math.cos(math.radians(theta_w)))
            z1 = first_optical_depth(layer)
            depths = np.array([f * z1 for f in DEPTH_FACTORS] + [MEAN_DEPTH_M])
            light = slab_light_field(A_PER_M, b, table, theta_w, depths, spp=args.spp, passes=args.passes,
                                     seed=len(records) * 1000, spp_up=4 * args.spp)
            records.append({"bb_over_a": ratio, "albedo": albedo, "bb_over_b": bb_over_b, "a_per_m": A_PER_M,
                            "b_per_m": b, "bb_per_m": bb, "sun_zenith_deg": zenith, "zenith_in_water_deg": theta_w,
                            "z_m": depths.tolist(), "E_d": light.E_d.tolist(), "E_d_error": light.E_d_error.tolist(),
                            "E_u0": light.E_u0, "E_u0_error": light.E_u0_error, "E_d0": light.E_d0})
            print(f"{time.time() - start:7.0f} s  b_b/a {ratio:<6} ω₀ {albedo:<5} sun {zenith:>4}°  "
                  f"R {light.R:.4g} ± {light.E_u0_error / light.E_d0:.2g}  "
                  f"max rel. error of E_d {np.max(light.E_d_error / light.E_d):.3f}", flush=True)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    meta = {"generator": "scripts/fourflux_slab_mc.py", "variant": info.variant, "spp_per_pass": args.spp, "spp_per_pass_E_u": 4 * args.spp,
            "passes": args.passes, "estimator": "reciprocal radiance meter (oceanrender/render/slab.py)", "n_water": N_WATER,
            "date": time.strftime("%Y-%m-%d %H:%M"), "seconds": round(time.time() - start),
            "units": "irradiances per unit normal irradiance of the beam [-]; depths m; coefficients 1/m",
            "phase_function": "Fournier-Forand, Mobley et al. (2002) parameters, b_b/b as given"}
    args.out.write_text(json.dumps({"meta": meta, "records": records}, indent=1))
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
