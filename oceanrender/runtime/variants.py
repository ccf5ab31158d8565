"""Choosing and activating the Mitsuba variant at run time.

Mitsuba's JIT variants need a backend: ``cuda_*`` a working NVIDIA driver,
``llvm_*`` a libLLVM that drjit can drive. drjit 1.5's LLVM backend aborts the
whole process (``LLVM ERROR: Cannot select: ... fminimum``) with Debian's
libLLVM 14 and 15, so a variant is only trusted after a tiny render has
succeeded in a *child* process; the verdict is cached per machine
configuration. The scalar variants are not offered: the split integrator and
the per-frame mesh updates use vectorised drjit arrays, which only the JIT
backends have, so ``scalar_spectral`` fails on the shipped scenes.

Nothing here runs at import time: the CLI (or a test) calls
:func:`activate_variant` once.
"""

from __future__ import annotations

import glob
import json
import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from .names import SPECTRAL_VARIANTS  # order of preference [1]: GPU, CPU JIT; the only ones supported

#: Why a scalar variant is refused (one line, for the user).
SCALAR_REFUSAL = ("is not supported: the renderer needs a JIT backend (cuda_ad_spectral with an NVIDIA driver, or "
                  "llvm_ad_spectral with libLLVM ≥ 16: apt-get install libllvm19)")

#: Oldest LLVM major version that drjit 1.5 was seen to drive correctly here.
MIN_LLVM_MAJOR = 16

_LLVM_GLOBS = (
    "/usr/lib/x86_64-linux-gnu/libLLVM*.so*",
    "/usr/lib/aarch64-linux-gnu/libLLVM*.so*",
    "/usr/lib/llvm-*/lib/libLLVM*.so*",
    "/usr/lib64/libLLVM*.so*",
    "/usr/local/lib/libLLVM*.so*",
)

_PROBE = r"""
import sys
import mitsuba as mi
mi.set_variant(sys.argv[1])
scene = mi.load_dict({
    "type": "scene",
    "integrator": {"type": "path", "max_depth": 2},
    "sensor": {"type": "perspective",
               "film": {"type": "hdrfilm", "width": 4, "height": 4},
               "sampler": {"type": "independent", "sample_count": 2}},
    "emitter": {"type": "constant"},
    "shape": {"type": "sphere", "to_world": mi.ScalarTransform4f().translate([0, 0, 3])},
})
value = float(mi.render(scene).numpy().mean())
assert value == value, "NaN"
print("OK")
"""


class VariantError(RuntimeError):
    """No requested Mitsuba variant can run on this machine."""


@dataclass(frozen=True)
class RuntimeInfo:
    """The activated Mitsuba variant and how it was chosen.

    Attributes
    ----------
    variant : str
        The Mitsuba variant in use, e.g. ``"llvm_ad_spectral"``.
    llvm_library : str or None
        Path of the libLLVM given to drjit (``DRJIT_LIBLLVM_PATH``), if any.
    tried : tuple of (str, str)
        Each variant tried before and including the chosen one, with the reason
        it was rejected or ``"ok"``.
    """

    variant: str
    llvm_library: str | None
    tried: tuple[tuple[str, str], ...]


def _llvm_major(path: str) -> int | None:
    match = re.search(r"libLLVM[-.]?(\d+)", os.path.basename(path))
    return int(match.group(1)) if match else None


def find_llvm_library() -> str | None:
    """Return the newest libLLVM (major ≥ 16) on this machine, or None.

    An explicit ``DRJIT_LIBLLVM_PATH`` in the environment wins. Otherwise the
    system library folders are searched, then a libLLVM shipped inside an
    installed Python package (e.g. ``karellen-llvm-core``).
    """
    explicit = os.environ.get("DRJIT_LIBLLVM_PATH")
    if explicit:
        return explicit
    candidates = [p for pattern in _LLVM_GLOBS for p in glob.glob(pattern)]
    for site in sys.path:
        if site and os.path.isdir(site):
            candidates += glob.glob(os.path.join(site, "*", "**", "libLLVM*.so*"), recursive=True)
    usable = [
        (major, path)
        for path in candidates
        if (major := _llvm_major(path)) is not None and major >= MIN_LLVM_MAJOR and os.path.isfile(path)
    ]
    if not usable:
        return None
    return max(usable)[1]


def cuda_driver_present() -> bool:
    """Whether an NVIDIA driver library (libcuda) can be found."""
    import ctypes.util  # noqa: PLC0415

    return ctypes.util.find_library("cuda") is not None or os.path.exists("/dev/nvidiactl")


def _cache_path() -> Path:
    root = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(root) / "oceanrender" / "variant-probe.json"


def _cache_key(variant: str, llvm: str | None) -> str:
    import mitsuba  # noqa: PLC0415 (import only here: never at module import)

    return f"{variant}|{mitsuba.__version__}|{llvm}|{sys.executable}"


def probe_variant(variant: str, llvm: str | None, timeout: float = 120.0) -> str:
    """Render 4×4 pixels with ``variant`` in a child process.

    Returns ``"ok"`` or a one-line reason for the failure. A crash of the
    child (LLVM abort, missing driver) cannot take the caller down.
    """
    env = dict(os.environ)
    if llvm:
        env["DRJIT_LIBLLVM_PATH"] = llvm
    try:
        proc = subprocess.run(
            [sys.executable, "-c", _PROBE, variant],
            env=env, capture_output=True, text=True, timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return f"probe timed out after {timeout:.0f} s"
    if proc.returncode == 0 and proc.stdout.strip().endswith("OK"):
        return "ok"
    lines = [line for line in (proc.stderr or proc.stdout).strip().splitlines() if line.strip()]
    return lines[-1][:200] if lines else f"exit code {proc.returncode}"


def probe_variant_cached(variant: str, llvm: str | None) -> str:
    """:func:`probe_variant` with a per-machine cache of successful probes."""
    path = _cache_path()
    key = _cache_key(variant, llvm)
    try:
        cache = json.loads(path.read_text())
    except (OSError, ValueError):
        cache = {}
    if cache.get(key) == "ok":
        return "ok"
    verdict = probe_variant(variant, llvm)
    if verdict == "ok":
        cache[key] = "ok"
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(".tmp")
            tmp.write_text(json.dumps(cache, indent=1))
            os.replace(tmp, path)
        except OSError:
            pass  # NOTE: a read-only home only costs a re-probe next time.
    return verdict


def candidate_variants(requested: str = "auto") -> tuple[str, ...]:
    """Variants to try, in order, for a requested name ("auto" or a variant)."""
    if requested == "auto":
        return SPECTRAL_VARIANTS
    return (requested,)


def steady_kernels() -> None:
    """Turn off Dr.Jit's packet memory operations, so a frame's kernels do not change with its buffers.

    With ``JitFlag.PacketOps`` Dr.Jit may read a gather of adjacent values (the mesh's
    two texture coordinates of a vertex) as one packet, and whether it does varied between
    two uploads of same-sized buffers (measured: 2 of 6 re-uploads of a mesh's texture
    coordinates gave the other kernel). The sea's field shading uploads its rest positions as
    texture coordinates every frame, so the render kernel changed at random between frames
    and was compiled again (26 s at 720p; a flaky no-recompile test). Without packets every
    frame's kernel is the same; the render time did not change measurably.
    """
    import drjit as dr  # noqa: PLC0415

    dr.set_flag(dr.JitFlag.PacketOps, False)


def activate_variant(requested: str = "auto") -> RuntimeInfo:
    """Pick, verify and activate the Mitsuba variant.

    Parameters
    ----------
    requested : str
        ``"auto"`` (cuda_ad_spectral, then llvm_ad_spectral) or one of
        :data:`SPECTRAL_VARIANTS`, which is then required.

    Returns
    -------
    RuntimeInfo

    Raises
    ------
    VariantError
        When no candidate works (for a forced variant: when it does not).
    """
    import mitsuba as mi  # noqa: PLC0415

    known = mi.variants()
    if requested != "auto" and requested not in known:
        raise VariantError(f"unknown Mitsuba variant {requested!r}; expected 'auto' or one of {', '.join(known)}")
    if requested != "auto" and requested not in SPECTRAL_VARIANTS:
        raise VariantError(f"variant {requested!r} {SCALAR_REFUSAL}" if requested.startswith("scalar") else
                           f"variant {requested!r} is not supported; expected 'auto' or one of "
                           f"{', '.join(SPECTRAL_VARIANTS)}")
    llvm = find_llvm_library()
    tried: list[tuple[str, str]] = []
    for variant in candidate_variants(requested):
        if variant.startswith("cuda") and not cuda_driver_present():
            verdict = "no NVIDIA driver (libcuda) found"
        elif variant.startswith("llvm") and llvm is None:
            verdict = f"no libLLVM ≥ {MIN_LLVM_MAJOR} found (apt-get install libllvm19)"
        else:
            verdict = probe_variant_cached(variant, llvm)
        tried.append((variant, verdict))
        if verdict != "ok":
            continue
        if variant.startswith("llvm") and llvm:
            os.environ["DRJIT_LIBLLVM_PATH"] = llvm
        mi.set_variant(variant)
        steady_kernels()
        return RuntimeInfo(variant=variant, llvm_library=llvm if variant.startswith("llvm") else None, tried=tuple(tried))
    raise VariantError("no usable Mitsuba variant: " + "; ".join(f"{v}: {why}" for v, why in tried))
