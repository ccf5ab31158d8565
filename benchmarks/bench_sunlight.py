"""Issue 41: the cost of the sun's beam maps per frame, side by side with the path tracer alone.

Run: ``.venv/bin/python benchmarks/bench_sunlight.py [--size 64x36 --spp 4 --frames 2]`` (the floor's map),
``.venv/bin/python benchmarks/bench_sunlight.py --volume [--size 320x180 --spp 32 --frames 1]`` (the volume's),
``.venv/bin/python benchmarks/bench_sunlight.py --coast [--size 320x180 --spp 16 --frames 2]`` (the coast's terrain).

In one process, a scene with the map at its cell and with it off (0: the path tracer's connections
alone): ``scenes/under_water_floor.toml`` and ``[render] caustic_cell`` 0.02 m, or with ``--volume``
``scenes/under_water_shafts.toml`` and ``shaft_cell`` 0.05 m (the planes, and the beam read along
every in-water segment: a cost of the render itself, so measured at the scene's own size), or with
``--coast`` ``scenes/coastal_beach.toml`` and ``caustic_cell`` 0.02 m (the terrain's map, rays cast
through the coast's mesh; its simulation run first, kept in ``outputs/bench_sunlight/``). A sequence
is built, frame 0 computed once (JIT, the sun's spectrum), then frames 1..N timed. The map is built
lazily, in the render kernel's first pass, so its cost shows in the render column. Prints a Markdown
table for BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import platform
import time
import tomllib
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="64x36")
    parser.add_argument("--spp", type=int, default=4)
    parser.add_argument("--frames", type=int, default=2)
    parser.add_argument("--volume", action="store_true", help="the volume's planes (under_water_shafts) instead")
    parser.add_argument("--coast", action="store_true", help="the terrain's map (coastal_beach) instead")
    args = parser.parse_args()
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")

    from oceanrender.pipeline import Sequence, SequenceReport, simulate_coastal
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene.settings import scene_from_dict

    path = ROOT / "scenes" / ("under_water_shafts.toml" if args.volume else
                              "coastal_beach.toml" if args.coast else "under_water_floor.toml")
    key, on = ("shaft_cell", 0.05) if args.volume else ("caustic_cell", 0.02)
    width, height = (int(v) for v in args.size.split("x"))
    rows = {}
    for cell in (on, 0.0):
        data = tomllib.loads(path.read_text())
        data.setdefault("name", path.stem)
        data["render"][key] = cell
        data["output"].update(resolution=[width, height], spp=args.spp)
        scene = scene_from_dict(data, str(path))
        runtime = activate_variant(scene.render.variant)
        store = None
        if scene.coastal is not None:
            store = simulate_coastal(scene, ROOT / "outputs" / "bench_sunlight", list(range(args.frames + 1)),
                                     SequenceReport(runtime.variant))
        sequence = Sequence(scene, runtime.variant, coastal_store=store)
        tic = time.perf_counter()
        sequence.compute_frame(0)
        first = time.perf_counter() - tic
        totals = {}
        tic = time.perf_counter()
        for frame in range(1, args.frames + 1):
            for stage, seconds in sequence.compute_frame(frame).seconds.items():
                totals[stage] = totals.get(stage, 0.0) + seconds
        wall = (time.perf_counter() - tic) / args.frames
        rows[cell] = (first, {k: v / args.frames for k, v in totals.items()}, wall)
    print(f"# {path.stem}: {width}x{height}, {args.spp} spp, variant {runtime.variant}, "
          f"{platform.processor() or platform.machine()}; {args.frames} frames timed per mode after one warm-up")
    print()
    print(f"| {key} [m] | first frame [s] | geometry [s/frame] | update [s/frame] | render [s/frame] | frame, wall [s] |")
    print("|---:|---:|---:|---:|---:|---:|")
    for cell, (first, per, wall) in rows.items():
        print(f"| {cell:g} | {first:.1f} | {per.get('geometry', 0):.2f} | {per.get('update', 0):.2f} "
              f"| {per.get('render', 0):.2f} | {wall:.2f} |")
    print()
    print(f"the map's cost per frame: {rows[on][2] - rows[0.0][2]:.2f} s ({rows[on][2] / rows[0.0][2]:.2f}x)")


if __name__ == "__main__":
    main()
