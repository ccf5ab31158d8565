"""The sea's three forms side by side (issue 23): wind, sea-state partitions, spectrum file.

Run: ``.venv/bin/python benchmarks/bench_sea_states.py``.

For scenes/open_ocean.toml (wind, Elfouhaily), scenes/swell_crossing.toml (two partitions) and
scenes/measured_sea.toml (SWAN file, wavespectra), in one run: reading and building the spectrum
(file included), the amplitudes of the 4 × 1024² cascades (Ψ on every lattice) and one frame's fields
of all cascades (best of 3), with each scene's Hs, Tp and mean direction. Then the issue's check, generated
against input: the FFT sea of a Hs 2 m, Tp 8 s sea towards 35° and of the bimodal file (4 km patch, 1024²,
averaged over seeds), its Hs, Tp and mean direction beside the input's (the test's estimators,
tests/waves/test_sea_state.py). Prints lines for BENCHMARKS.md.
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


def generated_statistics() -> None:
    import math
    import sys

    sys.path.insert(0, str(ROOT))
    from oceanrender.io.spectrum_files import read_spectrum_file
    from oceanrender.waves.fft_ocean import OceanGrid
    from oceanrender.waves.sea_state import Partition, PartitionedSpectrum, TabulatedSpectrum
    from tests.waves.test_sea_state import direction_of, generated, peak_period

    grid = OceanGrid(1024, 4000.0)
    seas = {"Hs 2 m, Tp 8 s, towards 35 deg": PartitionedSpectrum(partitions=(
        Partition("JONSWAP 1973", hs=2.0, tp=8.0, direction=math.radians(35.0), spreading_s=15.0),))}
    table = read_spectrum_file(ROOT / "scenes" / "sea_states" / "bimodal.swn")
    seas["bimodal.swn, 06:00, site 0"] = TabulatedSpectrum(frequency=table.frequency, direction=table.direction,
                                                           table=table.density)
    import numpy as np
    import wavespectra

    file_tp = float(np.ravel(wavespectra.read_swan(str(ROOT / "scenes" / "sea_states" / "bimodal.swn")).spec.tp())[0])
    for name, sea in seas.items():
        variances, power = generated(sea, grid)
        hs = 4 * math.sqrt(float(sum(variances) / len(variances)))
        tp = peak_period(power, grid)
        expected = peak_period(sea(grid.kx, grid.ky), grid)  # the same estimator on E|h̃₀|² ∝ Ψ
        reference = f"wavespectra's tp() of the file {file_tp:.2f} s" if "bimodal" in name else "input"
        print(f"{name}: Hs generated {hs:.3f} m vs input {sea.significant_wave_height():.3f} m "
              f"({100 * (hs / sea.significant_wave_height() - 1):+.1f} %); Tp generated {tp:.2f} s vs input "
              f"{2 * math.pi / sea.peak_frequency:.2f} s (grid maximum) and {reference}; the estimator on the "
              f"expected power {expected:.2f} s ({100 * (tp / expected - 1):+.1f} %); mean direction generated "
              f"{math.degrees(direction_of(power, grid)):.1f} deg vs input {math.degrees(sea.mean_direction()):.1f} deg")


if __name__ == "__main__":
    generated_statistics()
    main()
