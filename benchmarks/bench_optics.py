"""Four-flux light field for 95 wavelengths × 256 depths (issue 4 goal: < 0.1 s here).

Run: ``.venv/bin/python benchmarks/bench_optics.py``. Prints the best and median of 20 runs.
"""

from __future__ import annotations

import time

import numpy as np

from oceanrender.optics.fourflux import four_flux


def main() -> None:
    wavelengths = np.linspace(360, 830, 95)
    a = 0.01 + 0.6 * ((wavelengths - 360) / 470) ** 3  # a rising pure-water-like absorption [m⁻¹]
    bb = 0.002 * (wavelengths / 500) ** -4.32 + 0.001  # backscattering [m⁻¹]
    z = np.linspace(0, 40, 256)
    for depth in (25.0, np.inf):
        times = []
        for _ in range(20):
            tic = time.perf_counter()
            four_flux(a, bb, 1.0, 0.2, 30.0, depth, 0.25, z)
            times.append(time.perf_counter() - tic)
        print(f"four_flux 95 λ × 256 z, H = {depth:g} m: best {1e3 * min(times):.1f} ms, "
              f"median {1e3 * float(np.median(times)):.1f} ms (goal < 100 ms for composition → IOPs → four-flux)")


if __name__ == "__main__":
    main()
