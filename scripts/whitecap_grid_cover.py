"""Whitecap cover on the foam's own grid (issue 40) against Monahan & O'Muircheartaigh (1980).

With field shading the whitecaps are accumulated on a polar grid of their own
(:attr:`oceanrender.surface.open_sea.WaterBody.foam_grid`). This measures, per wind,
the share of the sea's *area* within ``--near`` m of the camera (grid cells ∝ spacing²)
whose whitecap coverage F is ≥ ½ — the measure of docs/whitecaps.md, free of perspective —
and the area mean of F (the cover the lace draws: foam shows on the fraction F of the
surface on average), pooled over frame times and ocean seeds, against Monahan's
W = 3.84·10⁻⁶ U₁₀^3.41.

Usage: python scripts/whitecap_grid_cover.py [--winds 8 12 16] [--times 4 6 8] [--seeds 1 2] [--near 100]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--winds", type=float, nargs="+", default=[8.0, 12.0, 16.0])
    parser.add_argument("--times", type=float, nargs="+", default=[4.0, 6.0, 8.0])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--near", type=float, default=100.0)
    args = parser.parse_args()

    from oceanrender.scene import load_scene, with_overrides
    from oceanrender.surface.open_sea import WaterBody

    base = load_scene(ROOT / "scenes" / "open_ocean.toml")
    for wind in args.winds:
        above, mean_f, area_total = 0.0, 0.0, 0.0
        for seed in args.seeds:
            body = WaterBody(with_overrides(base, ocean={"wind_speed": wind, "seed": seed}))
            for t in args.times:
                coverage, _ = body.foam_state(t)
                grid = body.foam_grid_at(t)
                x, y = grid.points.T
                near = np.hypot(x - grid.center[0], y - grid.center[1]) <= args.near
                area = grid.spacing[near] ** 2
                above += float(np.sum(area * (coverage[near] >= 0.5)))
                mean_f += float(np.sum(area * coverage[near]))
                area_total += float(np.sum(area))
        monahan = 3.84e-6 * wind**3.41
        print(json.dumps({"wind": wind, "monahan": monahan, "area_F_half": above / area_total,
                          "ratio_F_half": above / area_total / monahan, "mean_F": mean_f / area_total,
                          "ratio_mean_F": mean_f / area_total / monahan, "frames": len(args.times) * len(args.seeds)}),
              flush=True)


if __name__ == "__main__":
    main()
