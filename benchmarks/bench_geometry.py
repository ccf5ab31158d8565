"""Geometry time per frame of the default scene: this tree against an earlier revision, in one run.

Run: ``.venv/bin/python benchmarks/bench_geometry.py [--before REV] [--frames N]``.
Times ``WaterBody(scene).frame(t)`` (sea sampling on the radial mesh, foam
history, closed body) for N frames after one warm-up frame, alternating
between this tree and ``REV`` (default e24db91, before the wavenumber filter of
issue 14) checked out in a temporary git worktree, each with the scene file of
its own revision; prints seconds per frame for each and their ratio.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

TIMER = r"""
import json, sys, time
sys.path.insert(0, sys.argv[1])
from oceanrender.scene import load_scene
try:
    from oceanrender.surface.open_sea import WaterBody
except ImportError:
    from oceanrender.geometry.open_sea import WaterBody
scene = load_scene(sys.argv[1] + "/scenes/open_ocean.toml")
tic = time.perf_counter(); body = WaterBody(scene); body.frame(0.0); first = time.perf_counter() - tic
times = []
for i in range(int(sys.argv[2])):
    tic = time.perf_counter(); body.frame((i + 1) / 24); times.append(time.perf_counter() - tic)
print(json.dumps({"first": first, "per_frame": sorted(times)[len(times) // 2], "vertices": int(body.vertex_count)}))
"""


def time_tree(tree: Path, frames: int) -> dict:
    out = subprocess.run([str(ROOT / ".venv" / "bin" / "python"), "-c", TIMER, str(tree), str(frames)],
                         check=True, capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", default="e24db91")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--rounds", type=int, default=2, help="alternations of before/after")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        old = Path(tmp) / "before"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(old), args.before],
                       check=True, capture_output=True)
        try:
            results = {"before": [], "after": []}
            for _ in range(args.rounds):
                results["before"].append(time_tree(old, args.frames))
                results["after"].append(time_tree(ROOT, args.frames))
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(old)], capture_output=True)
    print("| tree | vertices | first frame [s] | median frame [s] |\n|---|---:|---:|---:|")
    for name, runs in results.items():
        best = min(runs, key=lambda r: r["per_frame"])
        print(f"| {name} ({args.before if name == 'before' else 'this tree'}) | {best['vertices']} | "
              f"{best['first']:.2f} | {best['per_frame']:.3f} |")
    ratio = min(r["per_frame"] for r in results["after"]) / min(r["per_frame"] for r in results["before"])
    print(f"\nafter / before: {ratio:.2f}")


if __name__ == "__main__":
    main()
