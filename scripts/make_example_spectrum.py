"""Write the example directional spectrum file ``scenes/sea_states/bimodal.swn`` (SWAN ASCII, read by wavespectra).

Run from the repository root: ``.venv/bin/python scripts/make_example_spectrum.py``.

A bimodal sea as a buoy or a wave model would report it, built with wavespectra's own
constructors (an implementation independent of this project's spectra), at two sites and
three hourly times:

* wind sea: JONSWAP, Hs 1.2 m, Tp 5.5 s, γ 3.3, coming from 250° (WSW), Cartwright
  cos-2s spreading of directional width 30°;
* swell: JONSWAP, Hs 1.0 m, Tp 12 s, γ 6, coming from 160° (SSE), width 12°.

Site 1 is the same sea 20 % higher. The swell grows by 10 % an hour. Frequencies 0.04–0.6 Hz
(log-spaced, 36, as SWAN and WAVEWATCH III space them), directions every 10°. Units in the
file: E [m² Hz⁻¹ deg⁻¹], directions nautical (coming from, clockwise from north), as SWAN
writes them. ``oceanrender`` turns them into directions of travel counter-clockwise from +x
(east): the wind sea travels towards 250° − 180° = 70° nautical, i.e. θ = 20°; the swell towards
340° nautical, θ = 110°.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr
from wavespectra.construct.direction import cartwright
from wavespectra.construct.frequency import jonswap

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "scenes" / "sea_states" / "bimodal.swn"

FREQUENCIES = np.geomspace(0.04, 0.6, 36)  # [Hz]
DIRECTIONS = np.arange(0.0, 360.0, 10.0)  # nautical, coming from [deg]
TIMES = np.array(["2026-03-14T06:00", "2026-03-14T07:00", "2026-03-14T08:00"], dtype="datetime64[s]")
SITES = {"lon": np.array([-9.50, -9.40]), "lat": np.array([38.60, 38.65]), "scale": np.array([1.0, 1.2])}


def bimodal(hour: int, scale: float) -> xr.DataArray:
    """E(f, θ) [m² Hz⁻¹ deg⁻¹] of the wind sea plus the swell (module docstring)."""
    wind = jonswap(FREQUENCIES, fp=1 / 5.5, gamma=3.3, hs=1.2 * scale) * cartwright(DIRECTIONS, dm=250.0, dspr=30.0)
    swell = (jonswap(FREQUENCIES, fp=1 / 12.0, gamma=6.0, hs=1.0 * scale * 1.1**hour)
             * cartwright(DIRECTIONS, dm=160.0, dspr=12.0))
    return (wind + swell).transpose("freq", "dir")


def main() -> None:
    data = np.stack([np.stack([bimodal(h, s).values for s in SITES["scale"]]) for h in range(len(TIMES))])
    efth = xr.DataArray(data, dims=("time", "site", "freq", "dir"),
                        coords={"time": TIMES, "site": [0, 1], "freq": FREQUENCIES, "dir": DIRECTIONS}, name="efth")
    dataset = efth.to_dataset()
    dataset["lon"] = (("site",), SITES["lon"])
    dataset["lat"] = (("site",), SITES["lat"])
    OUT.parent.mkdir(parents=True, exist_ok=True)
    dataset.spec.to_swan(str(OUT), id="oceanrender example: bimodal sea (scripts/make_example_spectrum.py)")
    back = dataset.spec.hs().values
    print(f"wrote {OUT} ({OUT.stat().st_size} bytes); Hs per time and site [m]: {np.round(back, 3).tolist()}")


if __name__ == "__main__":
    main()
