"""Write scenes/coastal_bay_bed.npy: the bed of scenes/coastal_bay.toml, a sandy beach beside a cliffed headland.

Grid: 400 × 240 cells of 1 m (the scene's [coastal] cells and size), rows south → north,
columns west → east, cell (j, i) centred at grid coordinates x = −200 + i + ½, y = −40 + j + ½ [m]
(the scene's origin). Elevations in metres above the still level (float32).

* The beach: a plane 1:30 slope, z = −y / 30, down to the 6 m offshore depth (y = 180 m).
* The headland on the east: a plateau 22 m high whose cliffs (a C¹ smoothstep over 8 m of plan
  distance, up to ~65° steep) face west (x = 120 + y / 2) and north (y = 80 m), with a rock
  platform at its foot (2 m below the still level, sloping into the beach's bed).

Run: .venv/bin/python scripts/make_coastal_bay.py  (deterministic; no random numbers).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

NX, NY = 400, 240
X0, Y0 = -200.0, -40.0
CELL = 1.0
SLOPE = 1.0 / 30.0
OFFSHORE_DEPTH = 6.0
PLATEAU = 22.0
CLIFF_WIDTH = 8.0
PLATFORM_DEPTH = 2.0
PLATFORM_WIDTH = 25.0


def smoothstep(s: np.ndarray) -> np.ndarray:
    s = np.clip(s, 0.0, 1.0)
    return s * s * (3.0 - 2.0 * s)


def bed() -> np.ndarray:
    x = X0 + (np.arange(NX) + 0.5) * CELL
    y = Y0 + (np.arange(NY) + 0.5) * CELL
    xx, yy = np.meshgrid(x, y)
    beach = np.maximum(-SLOPE * yy, -OFFSHORE_DEPTH)
    # plan distance inside the headland (positive inside): the nearer of its west and north faces
    inside = np.minimum((xx - (120.0 + 0.5 * yy)) / np.hypot(1.0, 0.5), 80.0 - yy)
    platform = np.maximum(beach, -PLATFORM_DEPTH) * smoothstep(1.0 + inside / PLATFORM_WIDTH) \
        + beach * (1.0 - smoothstep(1.0 + inside / PLATFORM_WIDTH))
    cliff = smoothstep(inside / CLIFF_WIDTH)
    return (platform * (1.0 - cliff) + PLATEAU * cliff).astype(np.float32)


def main() -> None:
    out = Path(__file__).resolve().parents[1] / "scenes" / "coastal_bay_bed.npy"
    np.save(out, bed())
    print(f"wrote {out} ({NY} x {NX}, {bed().min():.2f} .. {bed().max():.2f} m)")


if __name__ == "__main__":
    main()
