"""The sea's three forms side by side (issue 23): wind, sea-state partitions, spectrum file.

Run: ``.venv/bin/python benchmarks/bench_sea_states.py``.

For scenes/open_ocean.toml (wind, Elfouhaily), scenes/swell_crossing.toml (two partitions) and
scenes/measured_sea.toml (SWAN file, wavespectra), in one run: reading and building the spectrum
(file included), the amplitudes of the 4 × 1024² cascades (Ψ on every lattice) and one frame's fields
of all cascades (best of 3), with each scene's Hs, Tp and mean direction. Prints lines for BENCHMARKS.md.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    from oceanrender.io.spectrum_files import _read
    from oceanrender.scene import load_scene
    from oceanrender.waves.sea import SeaSurface, directional_spectrum, sea_description

    print(f"load average {os.getloadavg()[0]:.1f}")
    rows = []
    for name in ("open_ocean", "swell_crossing", "measured_sea"):
        scene = load_scene(ROOT / "scenes" / f"{name}.toml")
        _read.cache_clear()  # the file is read again: its cost is counted
        tic = time.perf_counter()
        spectrum = directional_spectrum(scene.ocean)
        build = time.perf_counter() - tic
        tic = time.perf_counter()
        sea = SeaSurface(scene.ocean)
        for cascade in sea.cascades.cascades:
            cascade.synthesis  # Ψ on the lattice, amplitudes, precomputation
        amplitudes = time.perf_counter() - tic
        frames = []
        for t in (0.0, 0.5, 1.0):
            tic = time.perf_counter()
            for cascade in sea.cascades.cascades:
                cascade.fields(t)
            frames.append(time.perf_counter() - tic)
        d = sea_description(scene.ocean, spectrum)
        rows.append((name, d["form"], build, amplitudes, min(frames), d))
    base = rows[0][3]
    for name, form, build, amplitudes, frame, d in rows:
        print(f"{name} ({form}): spectrum {build * 1e3:.0f} ms; 4 x 1024² amplitudes {amplitudes:.2f} s "
              f"({amplitudes / base:.2f}x the wind form); one frame of all cascades {frame:.2f} s; "
              f"Hs {d['significant_wave_height_m']:.3f} m, Tp {d['peak_period_s']:.2f} s, "
              f"mean direction {d['mean_direction_deg']:.1f} deg")


if __name__ == "__main__":
    main()
