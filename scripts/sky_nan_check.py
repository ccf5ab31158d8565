"""Repeat the real-time sky evaluation many times on a loaded machine and count non-finite results (issue 45).

Mitsuba 3.9.1's ``sunsky`` reads past the end of its tables at exactly 720 nm and multiplies what it finds
there by zero (docs/realtime.md, "Non-finite sky radiance"). Whether that memory holds a NaN depends on
drjit's memory pool and on the SIMD width: on this 16-wide (AVX-512) machine the positions past the end are
written with finite values, on an 8-wide (AVX2) target they keep what freed buffers held. So this script
makes the failing conditions on purpose:

* ``--width 8``: drjit-core's LLVM target set to an 8-wide AVX2 CPU (through its C entry point
  ``jit_llvm_set_target``, before the first kernel; the native width otherwise);
* before each evaluation, buffers filled with NaN are evaluated and freed, as a render leaves its pool;
* ``--hogs N`` busy processes beside it (the machine under load).

Each evaluation is ``realtime.sky.sky_radiance_spectra`` on a 256 × 128 sky map at the 95 report wavelengths
(360–830 nm), either as shipped (``--mode fixed``: 720 nm moved one float32 step below) or with the guard
switched off (``--mode unguarded``: the wavelengths passed as they are, as before the fix). Prints how many
evaluations had a non-finite value, and at which wavelengths.

Usage: ``.venv/bin/python scripts/sky_nan_check.py --mode unguarded --width 8 --count 200 --hogs 2``
"""

from __future__ import annotations

import argparse
import ctypes
import multiprocessing
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def _hog(seconds: float) -> None:
    end = time.time() + seconds
    x = 0
    while time.time() < end:
        for i in range(100_000):
            x += i * i


def _set_width_8(dr) -> None:
    """drjit-core's LLVM target: an 8-wide AVX2 CPU (haswell), before any kernel is compiled."""
    core = ctypes.CDLL(str(pathlib.Path(dr.__file__).parent / "libdrjit-core.so"))
    core._Z19jit_llvm_set_targetPKcS0_j(b"haswell", b"+avx,+avx2,+fma,+sse4.2,+f16c,+bmi,+bmi2,+popcnt,+lzcnt",
                                         ctypes.c_uint32(8))


def _leave_nan_in_the_pool(dr, mi, rng) -> None:
    """Evaluate and free buffers of 16 … 32k floats holding NaN, as a render leaves drjit's memory pool."""
    kept = []
    for p in range(4, 16):
        values = np.full(2**p, np.nan, dtype=np.float32)
        for _ in range(3):
            buffer = mi.Float(values) * 2.0
            dr.eval(buffer)
            kept.append(buffer)
    dr.sync_thread()
    del kept
    dr.sync_thread()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", choices=("fixed", "unguarded"), default="fixed")
    parser.add_argument("--width", type=int, choices=(8, 0), default=0, help="8, or 0 for the native width")
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--hogs", type=int, default=2)
    args = parser.parse_args()

    from oceanrender.runtime.variants import activate_variant

    activate_variant("llvm_ad_spectral")
    import drjit as dr
    import mitsuba as mi

    if args.width == 8:
        _set_width_8(dr)
    from oceanrender.optics.report import REPORT_WAVELENGTHS
    from oceanrender.realtime import sky
    from oceanrender.realtime.luts import envmap_directions
    from oceanrender.scene.settings import SunSettings

    if args.mode == "unguarded":
        sky.sunsky_wavelengths = lambda w: np.asarray(w, dtype=np.float32)  # the evaluation before the fix
    hogs = [multiprocessing.Process(target=_hog, args=(3600.0,), daemon=True) for _ in range(args.hogs)]
    for hog in hogs:
        hog.start()
    directions = envmap_directions(256, 128)
    rng = np.random.default_rng(0)
    bad, where = 0, set()
    start = time.perf_counter()
    try:
        for _ in range(args.count):
            _leave_nan_in_the_pool(dr, mi, rng)
            try:
                radiance = sky.sky_radiance_spectra(SunSettings(), directions, REPORT_WAVELENGTHS)
            except RuntimeError:
                bad += 1
                where.add("raised")
                continue
            finite = np.isfinite(radiance.reshape(-1, len(REPORT_WAVELENGTHS)))
            if not finite.all():
                bad += 1
                where.update(float(w) for w in REPORT_WAVELENGTHS[~finite.all(axis=0)])
    finally:
        for hog in hogs:
            hog.terminate()
    print(f"mode {args.mode}, width {args.width or 'native'}, {args.hogs} busy processes: {bad} of {args.count} "
          f"evaluations non-finite{' at ' + ', '.join(map(str, sorted(where, key=str))) if where else ''} "
          f"({time.perf_counter() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
