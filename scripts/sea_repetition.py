"""How much the sea repeats: the height field's autocorrelation at lags from 2 peak wavelengths to 2 km.

Run: ``.venv/bin/python scripts/sea_repetition.py [SCENE ...] [--step M]``. For
each scene (default: the default and flyover scenes) prints the largest |ρ(τ)|
over lags 2 λ_p ≤ |τ| ≤ 2 km of its sea at t = 0 and ρ at each cascade's period
(:func:`oceanrender.waves.repetition.repetition`).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenes", nargs="*", default=[str(ROOT / "scenes" / "open_ocean.toml"),
                                                       str(ROOT / "scenes" / "open_ocean_flyover.toml")])
    parser.add_argument("--step", type=float, default=4.0, help="sample spacing [m]")
    args = parser.parse_args()
    from oceanrender.scene import load_scene
    from oceanrender.waves.repetition import repetition

    for path in args.scenes:
        result = repetition(load_scene(path).ocean, args.step)
        periods = ", ".join(f"{size:g} m: {rho:.3f}" for size, rho in result.at_periods.items())
        print(f"{Path(path).name}: peak wavelength {result.peak_wavelength:.1f} m, max |rho| over "
              f"2 lambda_p..2 km = {result.max_abs_rho:.3f} at lag {result.at_lag} m; rho at cascade periods: {periods}")


if __name__ == "__main__":
    main()
