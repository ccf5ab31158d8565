"""Time per frame of the FFT ocean against the bare FFTs it needs, memory per grid point, FFT libraries.

Run: ``.venv/bin/python benchmarks/bench_fft.py [--sizes 256 512 1024 2048] [--repeats 15]``.
Prints Markdown tables for BENCHMARKS.md:

1. per grid size N: the bare transforms a frame needs (4 in-place complex
   inverse FFTs of N × N, single precision, same library and threads), the
   full frame (:meth:`FFTOcean.fields`: height, displacement, slopes, normals,
   Jacobian), their ratio, and memory;
2. the FFT libraries on the same 4 transforms at 1024² (and 8 real c2r ones,
   the alternative packing), plus the numpy engine for the pointwise work.

Bare and full runs alternate within one process, so both see the same load;
the tables give medians (and minima) over the repeats. Memory: the peak of
``tracemalloc`` while one frame is computed (numpy arrays, the returned fields
included; the few row buffers of the compiled loops and the FFT library's
scratch are not traced), the bytes of the returned arrays, and the bytes of
the time-independent state (amplitudes, index). "full frame" drops each
result, so the synthesis recycles its arrays; "fresh arrays" keeps the
previous frame alive, so every frame allocates (and the kernel zeroes) them.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
import tracemalloc

import numpy as np
import scipy.fft

from oceanrender.waves.fft_ocean import ENGINES, FFT_BACKENDS, FFTOcean, OceanGrid


def _forward_ducc0(spectra, workers):
    import ducc0  # noqa: PLC0415

    ducc0.fft.c2c(spectra, axes=(-2, -1), forward=True, inorm=2, out=spectra, nthreads=workers)


def _forward_scipy(spectra, workers):
    spectra[...] = scipy.fft.fft2(spectra, norm="forward", workers=workers, overwrite_x=True)


def _forward_numpy(spectra, workers):
    spectra[...] = np.fft.fft2(spectra, norm="forward")


#: Normalised forward transforms, the inverses of :data:`FFT_BACKENDS`.
FORWARD = {"ducc0": _forward_ducc0, "scipy": _forward_scipy, "numpy": _forward_numpy}


def timings(functions: dict[str, callable], repeats: int) -> dict[str, np.ndarray]:
    """Milliseconds per call of each function, calls interleaved, one warm-up each."""
    for function in functions.values():
        function()
    times = {name: [] for name in functions}
    for _ in range(repeats):
        for name, function in functions.items():
            tic = time.perf_counter()
            function()
            times[name].append(1e3 * (time.perf_counter() - tic))
    return {name: np.array(values) for name, values in times.items()}


def ocean(n: int, workers: int, engine: str = "auto", dtype=np.float32) -> FFTOcean:
    """A choppy 10 m/s Phillips sea on a 1 km patch (the workload does not depend on it)."""
    return FFTOcean(OceanGrid(n, 1000.0), 10.0, 0.3, seed=1, choppiness=1.0, dtype=dtype, workers=workers,
                    engine=engine)


def frame_memory(sea: FFTOcean, t: float) -> tuple[float, float]:
    """(tracemalloc peak, bytes of the returned arrays) of one frame, per grid point [B]."""
    sea.synthesis  # noqa: B018 - build the time-independent state outside the measurement
    tracemalloc.start()
    fields = sea.fields(t)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    arrays = {id(a.base if a.base is not None else a): (a.base if a.base is not None else a)
              for a in (fields.height, fields.slope_x, fields.displacement_y, fields.jacobian_xx,
                        fields.jacobian, fields.normals)}
    points = sea.grid.resolution**2
    return peak / points, sum(a.nbytes for a in arrays.values()) / points


def frame_table(sizes: list[int], repeats: int, workers: int) -> None:
    print("| N | bare FFTs [ms] | full frame [ms] | ratio | full, fresh arrays [ms] | peak [B/pt] | "
          "fields [B/pt] | state [B/pt] | library, engine |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for n in sizes:
        sea = ocean(n, workers)
        synthesis = sea.synthesis
        rng = np.random.default_rng(0)
        pairs = [(rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n))).astype(np.complex64)
                 for _ in range(4)]
        inverse, forward = FFT_BACKENDS[synthesis.backend], FORWARD[synthesis.backend]
        t = iter(np.arange(0.0, 1e6, 0.04))
        kept = []

        def bare_pair():
            # NOTE: an inverse and a normalised forward transform per array, so the
            # values stay bounded (repeated unnormalised transforms overflow);
            # the bare cost of a frame's 4 inverse transforms is half of this.
            for pair in pairs:
                inverse(pair, synthesis.workers)
                forward(pair, synthesis.workers)

        keeper = ocean(n, workers)

        def keep():  # a caller that holds on to the previous frame: new arrays every time
            kept[:] = [keeper.fields(next(t))]

        result = timings({"bare": bare_pair, "full": lambda: sea.fields(next(t)), "keep": keep}, repeats)
        result["bare"] = result["bare"] / 2
        bare_ms = np.median(result["bare"])
        peak, fields = frame_memory(ocean(n, workers), 1.0)  # a first frame: all arrays new
        held = synthesis.nbytes / n**2
        full, fresh = np.median(result["full"]), np.median(result["keep"])
        print(f"| {n} | {bare_ms:.1f} (min {result['bare'].min():.1f}) | {full:.1f} (min {result['full'].min():.1f})"
              f" | {full / bare_ms:.2f} | {fresh:.1f} | {peak:.0f} | {fields:.0f} | {held:.0f} | "
              f"{synthesis.backend} ×{synthesis.workers}, {synthesis.engine} |")


def library_table(n: int, repeats: int, workers: int) -> None:
    rng = np.random.default_rng(0)
    packed = [(rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n))).astype(np.complex64) for _ in range(4)]
    half = (rng.standard_normal((8, n, n // 2 + 1)) + 1j * rng.standard_normal((8, n, n // 2 + 1))).astype(np.complex64)
    functions = {}
    for threads in sorted({1, workers}):
        functions[f"scipy.fft, workers={threads}"] = (
            lambda w=threads: [scipy.fft.ifft2(a, norm="forward", workers=w) for a in packed],
            lambda w=threads: scipy.fft.irfft2(half, s=(n, n), norm="forward", workers=w))
    functions["numpy.fft"] = (lambda: [np.fft.ifft2(a, norm="forward") for a in packed],
                              lambda: np.fft.irfft2(half, s=(n, n), norm="forward"))
    try:
        import ducc0

        out = np.empty((8, n, n), np.float32)
        results = [np.empty_like(a) for a in packed]
        for threads in sorted({1, workers}):
            functions[f"ducc0 {ducc0.__version__}, nthreads={threads}"] = (
                lambda w=threads: [ducc0.fft.c2c(a, axes=(0, 1), forward=False, out=b, nthreads=w)
                                   for a, b in zip(packed, results)],
                lambda w=threads: ducc0.fft.c2r(half, axes=(1, 2), lastsize=n, forward=False, out=out, nthreads=w))
    except ImportError:
        print("(ducc0 not installed)")
    try:
        import pyfftw

        for threads in sorted({1, workers}):
            source = pyfftw.empty_aligned((4, n, n), np.complex64)
            source[:] = np.stack(packed)
            plan = pyfftw.FFTW(source, source, axes=(1, 2), direction="FFTW_BACKWARD", flags=("FFTW_MEASURE",),
                               threads=threads, normalise_idft=False)
            half_in = pyfftw.empty_aligned(half.shape, np.complex64)
            real_out = pyfftw.empty_aligned((8, n, n), np.float32)
            real_plan = pyfftw.FFTW(half_in, real_out, axes=(1, 2), direction="FFTW_BACKWARD",
                                    flags=("FFTW_MEASURE", "FFTW_DESTROY_INPUT"), threads=threads,
                                    normalise_idft=False)

            def c2r(p=real_plan, a=half_in):
                a[:] = half  # FFTW's multi-dimensional c2r destroys its input
                p()

            functions[f"pyfftw {pyfftw.__version__} (FFTW_MEASURE), threads={threads}"] = (plan, c2r)
    except ImportError:
        print("(pyfftw not installed)")
    complex_times = timings({name: pair[0] for name, pair in functions.items()}, repeats)
    real_times = timings({name: pair[1] for name, pair in functions.items()}, repeats)
    print(f"| library ({n}², single precision) | 4 complex ifft2 [ms] | 8 real irfft2 [ms] |")
    print("|---|---:|---:|")
    for name in functions:
        print(f"| {name} | {np.median(complex_times[name]):.1f} (min {complex_times[name].min():.1f}) | "
              f"{np.median(real_times[name]):.1f} (min {real_times[name].min():.1f}) |")


def engine_table(n: int, repeats: int, workers: int) -> None:
    print(f"| engine ({n}², float32) | full frame [ms] |")
    print("|---|---:|")
    t = iter(np.arange(0.0, 1e6, 0.04))
    seas = {engine: ocean(n, workers, engine) for engine in ENGINES}
    result = timings({engine: (lambda s=sea: s.fields(next(t))) for engine, sea in seas.items()}, repeats)
    for engine, values in result.items():
        print(f"| {engine} | {np.median(values):.1f} (min {values.min():.1f}) |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[256, 512, 1024, 2048])
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--workers", type=int, default=None, help="threads (default: all CPUs of this process)")
    parser.add_argument("--library-size", type=int, default=1024)
    args = parser.parse_args()
    workers = args.workers or len(os.sched_getaffinity(0))
    print(f"# FFT ocean, float32, {workers} threads, {platform.processor() or platform.machine()}, "
          f"load average {os.getloadavg()[0]:.2f} at start; medians of {args.repeats}")
    print()
    frame_table(args.sizes, args.repeats, workers)
    print()
    library_table(args.library_size, args.repeats, workers)
    print()
    engine_table(args.library_size, args.repeats, workers)
    print(f"\nload average {os.getloadavg()[0]:.2f} at end")


if __name__ == "__main__":
    main()
