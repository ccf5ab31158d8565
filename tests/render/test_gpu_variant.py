"""The GPU variant renders the same frames as the CPU one, statistically (issue 16).

``cuda_ad_spectral`` and ``llvm_ad_spectral`` run the same integrators on other
hardware with other random streams and other rounding, so their frames are two
independent Monte-Carlo estimates of one image: compared by a Z-test on block
means, not value for value. Skipped where no CUDA device is present (the
project's own machine has none); ``benchmarks/bench_quality.py --variant
cuda_ad_spectral`` runs the time-to-quality curves there.

Each variant renders in its own Python process (a Mitsuba variant is chosen
once per process here, see ``oceanrender.runtime.variants``).
"""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

pytestmark = pytest.mark.render

ROOT = Path(__file__).resolve().parents[2]

#: Largest accepted |z| per block: 24 blocks × 3 channels, each unbiased pair exceeds 4.5 with
#: probability 7e-6, so the whole comparison falsely fails with probability < 1e-3.
Z_MAX = 4.5

#: Seeds (independent renders) per variant, spp per render, image size [px], block size [px].
SEEDS, SPP, SIZE, BLOCK = 8, 32, (48, 32), 8


def cuda_present() -> bool:
    """Whether Dr.Jit finds a CUDA device (asked in a child process: it initialises the driver)."""
    probe = "import drjit as dr, sys; sys.exit(0 if dr.has_backend(dr.JitBackend.CUDA) else 1)"
    try:
        return subprocess.run([sys.executable, "-c", probe], capture_output=True, timeout=120).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


def render_blocks(variant: str) -> tuple[np.ndarray, np.ndarray]:
    """In this process: the default scene's frame 0, ``SEEDS`` renders → (block means, standard errors) of XYZ."""
    from oceanrender.pipeline import Sequence
    from oceanrender.runtime.variants import activate_variant
    from oceanrender.scene.settings import load_scene, with_overrides

    scene = with_overrides(load_scene(ROOT / "scenes" / "open_ocean.toml"),
                           output={"resolution": list(SIZE)}, render={"variant": variant})
    sequence = Sequence(scene, activate_variant(scene.render.variant).variant, spp=SPP)
    films = np.stack([sequence.renderer.render_xyz(SPP, seed=s)[0] for s in range(SEEDS)])
    k, h, w, c = films.shape
    blocks = films.reshape(k, h // BLOCK, BLOCK, w // BLOCK, BLOCK, c)
    # Pixels are independent (box filter), seeds are independent renders.
    mean = blocks.mean(axis=(0, 2, 4))
    se = np.sqrt(blocks.var(axis=0, ddof=1).sum(axis=(1, 3)) / k) / BLOCK**2
    return mean, se


def blocks_in_child(variant: str) -> tuple[np.ndarray, np.ndarray]:
    out = subprocess.run([sys.executable, __file__, variant], capture_output=True, text=True, cwd=ROOT,
                         timeout=1800, check=True).stdout
    data = json.loads(out.strip().splitlines()[-1])
    return np.array(data["mean"]), np.array(data["se"])


@pytest.mark.skipif(not cuda_present(), reason="no CUDA device on this machine")
def test_cuda_frames_equal_llvm_frames_statistically():
    gpu_mean, gpu_se = blocks_in_child("cuda_ad_spectral")
    cpu_mean, cpu_se = blocks_in_child("llvm_ad_spectral")
    combined = np.hypot(gpu_se, cpu_se)
    z = (gpu_mean - cpu_mean) / combined
    assert np.all(np.abs(z) < Z_MAX), f"largest |z| {np.abs(z).max():.2f}"
    # Sensitivity: a 5 % difference of a block would be seen in most blocks.
    assert np.median(Z_MAX * combined / cpu_mean) < 0.05


if __name__ == "__main__":
    block_mean, block_se = render_blocks(sys.argv[1])
    print(json.dumps({"mean": block_mean.tolist(), "se": block_se.tolist()}))
