"""Composition → IOPs → four-flux light field, 95 wavelengths × 256 depths (issue 4 goal: < 0.1 s here).

Run: ``.venv/bin/python benchmarks/bench_optics.py``. Prints the best and median of 20 runs for each
preset composition (a fresh :func:`composition_iops` each time: mineral tables are cached after the
first call, as in a render), and for the four-flux step alone.
"""

from __future__ import annotations

import time

import numpy as np

from oceanrender.optics.components import PRESETS, composition_iops
from oceanrender.optics.fourflux import four_flux


def timed(function, repeats: int = 20) -> tuple[float, float]:
    """(best, median) wall time of ``function()`` [s]."""
    times = []
    for _ in range(repeats):
        tic = time.perf_counter()
        function()
        times.append(time.perf_counter() - tic)
    return min(times), float(np.median(times))


def main() -> None:
    wavelengths = np.linspace(360, 830, 95)
    z = np.linspace(0, 40, 256)
    for name, composition in PRESETS.items():
        def chain():
            iops = composition_iops(composition, wavelengths)
            four_flux(iops.absorption, iops.backscattering, 1.0, 0.2, 30.0, 25.0, 0.25, z, b=iops.scattering)

        chain()  # warm the table caches
        best, median = timed(chain)
        print(f"{name}: composition → IOPs → four-flux, 95 λ × 256 z: best {1e3 * best:.1f} ms, "
              f"median {1e3 * median:.1f} ms (goal < 100 ms)")
    a = 0.01 + 0.6 * ((wavelengths - 360) / 470) ** 3
    bb = 0.002 * (wavelengths / 500) ** -4.32 + 0.001
    best, median = timed(lambda: four_flux(a, bb, 1.0, 0.2, 30.0, np.inf, 0.25, z))
    print(f"four-flux alone, deep water: best {1e3 * best:.1f} ms, median {1e3 * median:.1f} ms")


if __name__ == "__main__":
    main()
