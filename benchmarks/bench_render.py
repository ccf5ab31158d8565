"""Render time per frame of the split integrator: this tree against an earlier revision, in one run.

Run: ``.venv/bin/python benchmarks/bench_render.py [--before REV] [--frames N] [--rounds R]``.
Issue 15's goal: the hero-wavelength path tracer (``render/underwater.py``
``trace_path``) at no more than 1.2x the time per frame of the per-flight
estimator it replaced. Both trees render the *same* scene: the default scene
file of ``REV`` (f7b6cf2 by default: sun 40°, 8 m/s) with foam off (the foam
keys changed between the revisions), frame 0 at 160×90, 24 spp. After a warm-up
render (JIT compilation) it times ``render_xyz`` N times per tree, alternating
trees R times, and prints the median seconds per frame and their ratio.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

TIMER = r"""
import json, sys, time, tomllib
sys.path.insert(0, sys.argv[1])
from oceanrender.scene import scene_from_dict
from oceanrender.pipeline import Sequence
from oceanrender.runtime.variants import activate_variant
data = tomllib.loads(open(sys.argv[3]).read())
data["name"] = "open_ocean"
data["foam"] = {"enabled": False}
data.pop("vision", None)
variant = activate_variant("auto").variant
sequence = Sequence(scene_from_dict(data), variant, spp=24, resolution=(160, 90))
sequence.renderer.render_xyz(24, seed=0)
times = []
for i in range(int(sys.argv[2])):
    tic = time.perf_counter(); sequence.renderer.render_xyz(24, seed=i + 1); times.append(time.perf_counter() - tic)
print(json.dumps({"per_frame": sorted(times)[len(times) // 2]}))
"""


def time_tree(tree: Path, frames: int, scene: Path) -> float:
    out = subprocess.run([str(ROOT / ".venv" / "bin" / "python"), "-c", TIMER, str(tree), str(frames), str(scene)],
                         check=True, capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])["per_frame"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", default="f7b6cf2")
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--rounds", type=int, default=1, help="alternations of before/after")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        old = Path(tmp) / "before"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(old), args.before],
                       check=True, capture_output=True)
        scene = old / "scenes" / "open_ocean.toml"
        try:
            results = {"before": [], "after": []}
            for _ in range(args.rounds):
                results["before"].append(time_tree(old, args.frames, scene))
                results["after"].append(time_tree(ROOT, args.frames, scene))
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(old)], capture_output=True)
    before, after = min(results["before"]), min(results["after"])
    print(f"render_xyz, 160x90, 24 spp: before ({args.before}) {before:.2f} s/frame, after {after:.2f} s/frame, "
          f"ratio {after / before:.2f} (goal <= 1.2)")
    print(json.dumps(results))


if __name__ == "__main__":
    main()
