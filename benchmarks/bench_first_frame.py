"""``make render`` on a cold kernel cache: when its first frame is written, with the kernels compiled beside the sea
and without, side by side.

Each run is ``oceanrender render scenes/open_ocean.toml`` (the default scene, as ``make render`` runs it) in a
fresh process whose home is an empty folder: Dr.Jit's kernel cache (``~/.drjit``), numba's cache and the
variant's probe verdict all start empty, as on a machine's first run. ``beside``: the code as it is — the scene
loads with a calm stand-in of frame 0 and a second thread compiles the frame's and the meter's kernels while
frame 0's sea is computed (``Sequence._first_geometry``). ``in turn``: the same code with the stand-in turned off
(``Sequence._stand_in`` returns None), so the sea is computed first and each kernel compiles when first run, as
before issue 45. The two alternate, ``REPEATS`` times each; the ratio is taken on the medians.

Usage: ``.venv/bin/python benchmarks/bench_first_frame.py`` (about 4 minutes on the 2-core machine, nothing else
running); the table goes into BENCHMARKS.md, "The two commands on a fresh machine".
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "open_ocean.toml"
REPEATS = 2

#: The CLI as ``make render`` runs it, the stand-in optionally turned off first.
LAUNCH = """
import sys
if sys.argv[1] == "in turn":
    from oceanrender.pipeline import Sequence
    Sequence._stand_in = lambda self, frame: None
from oceanrender.cli import main
sys.argv = ["oceanrender", "render", sys.argv[2], "--out", sys.argv[3], "--no-progress"]
sys.exit(main())
"""


def run(mode: str) -> tuple[float, list[float]]:
    """(wall time of the command, seconds from its start to each frame's PNG) [s], on an empty home."""
    with tempfile.TemporaryDirectory() as home:
        out = Path(home) / "out"
        env = {**os.environ, "HOME": home, "NUMBA_CACHE_DIR": str(Path(home) / "numba")}
        start = time.time()
        subprocess.run([sys.executable, "-c", LAUNCH, mode, str(SCENE), str(out)], cwd=ROOT, env=env, check=True,
                       capture_output=True)
        wall = time.time() - start
        frames = sorted((out / "open_ocean").glob("frame_*.png"))
        return wall, [f.stat().st_mtime - start for f in frames]


def main() -> None:
    results: dict[str, list[tuple[float, list[float]]]] = {"in turn": [], "beside": []}
    for _ in range(REPEATS):
        for mode in results:
            results[mode].append(run(mode))
    print("| kernels compiled | first frame written [s] | command [s] | frames 1, 2 after it [s] |")
    print("|---|---:|---:|---|")
    medians = {}
    for mode, runs in results.items():
        first = float(np.median([r[1][0] for r in runs]))
        wall = float(np.median([r[0] for r in runs]))
        later = [round(float(np.median([r[1][k] - r[1][k - 1] for r in runs])), 1) for k in (1, 2)]
        medians[mode] = first
        print(f"| {mode} | {first:.1f} ({', '.join(f'{r[1][0]:.1f}' for r in runs)}) | {wall:.1f} | {later} |")
    print(f"\nfirst frame, beside / in turn: {medians['beside'] / medians['in turn']:.2f}")


if __name__ == "__main__":
    main()
