"""Peak memory of each stage against its size: the slopes behind ``oceanrender.checks``' memory estimates.

Each measurement runs in a fresh process: peak resident memory (``ru_maxrss``)
after the stage, minus the peak after the imports and a warm-up at a small size,
for two sizes; the slope [bytes per unit] is what the scene checks multiply by
the scene's size to refuse a run before it allocates. Units:

* ``fft``: FFT grid points summed over cascades (resolution² × cascades);
* ``mesh``: top vertices of the radial water body (1 + rings × segments), a whole 64² frame rendered
  (sampling every cascade, normals, foam, Mitsuba's buffers and its BVH);
* ``coastal``: shallow-water cells (nx × ny);
* ``render``: pixels of a whole frame at 1 spp (film, XYZ, vision model, files);
* ``samples``: Monte Carlo samples of one pass at 512² pixels (width × height × spp): the split
  integrator's paths run as loops inside one drjit kernel, so more samples should cost no memory.

Usage: ``.venv/bin/python benchmarks/bench_memory.py`` (about 2 minutes); the
printed table goes into BENCHMARKS.md.
"""

from __future__ import annotations

import json
import subprocess
import sys

CHILD = r"""
import json, resource, sys
from oceanrender.scene.settings import load_scene, with_overrides
kind, size = sys.argv[1], int(sys.argv[2])
scene = load_scene("scenes/open_ocean.toml")

def peak():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024

if kind == "fft":
    from oceanrender.waves.sea import SeaSurface
    import numpy as np
    def run(n):
        sea = SeaSurface(with_overrides(scene, ocean={"resolution": n, "cascades": 2}).ocean)
        sea.sample(np.zeros(4), np.zeros(4), 0.5)
    run(16); base = peak(); run(size); units = size * size * 2
elif kind == "mesh":
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.pipeline import Sequence
    activate_variant("llvm_ad_spectral")
    def run(s):
        seq = Sequence(with_overrides(scene, mesh={"segments": s}), "llvm_ad_spectral", spp=1, resolution=(64, 64))
        seq.compute_frame(0)
        return seq.body.grid_at(seq.time_of(0)).top_vertex_count
    run(16); base = peak(); units = run(size)
elif kind == "coastal":
    from oceanrender.coastal.simulation import solver_for_scene
    coast = load_scene("scenes/coastal_beach.toml")
    def run(n):
        solver, bed, state = solver_for_scene(with_overrides(coast, coastal={"cells": (n, n)}))
        solver.advance(state, state.t + 1e-3)
    run(16); base = peak(); run(size); units = size * size
elif kind == "render":
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.pipeline import Sequence
    activate_variant("llvm_ad_spectral")
    Sequence(scene, "llvm_ad_spectral", spp=1, resolution=(64, 64)).compute_frame(0); base = peak()
    Sequence(scene, "llvm_ad_spectral", spp=1, resolution=(size, size)).compute_frame(0); units = size * size
elif kind == "samples":
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.pipeline import Sequence
    activate_variant("llvm_ad_spectral")
    seq = Sequence(scene, "llvm_ad_spectral", spp=1, resolution=(512, 512))
    seq.renderer.render_xyz(1, 0); base = peak()
    seq.renderer.render_xyz(size, 0); units = 512 * 512 * size
print(json.dumps({"kind": kind, "size": size, "units": units, "bytes": peak() - base}))
"""


def measure(kind: str, size: int) -> dict:
    result = subprocess.run([sys.executable, "-c", CHILD, kind, str(size)], capture_output=True, text=True,
                            check=True)
    return json.loads(result.stdout.strip().splitlines()[-1])


def main() -> None:
    sizes = {"fft": (256, 1024), "mesh": (256, 1024), "coastal": (256, 1024), "render": (1024, 2048), "samples": (4, 64)}
    print("| stage | unit | small: units, MiB | large: units, MiB | slope [bytes/unit] |")
    print("|---|---|---|---|---|")
    for kind, (a, b) in sizes.items():
        small, large = measure(kind, a), measure(kind, b)
        slope = (large["bytes"] - small["bytes"]) / (large["units"] - small["units"])
        print(f"| {kind} | {large['units'] / b ** (2 if kind in ('fft', 'coastal', 'render') else 1):g}/size | "
              f"{small['units']}, {small['bytes'] / 2**20:.0f} | {large['units']}, {large['bytes'] / 2**20:.0f} | "
              f"{slope:.0f} |", flush=True)


if __name__ == "__main__":
    main()
