"""A rendered frame of a sea-state scene beside a polar plot of its directional spectrum (docs/geometry.md).

Run from the repository root::

    python scripts/sea_state_figure.py scenes/swell_crossing.toml docs/images/sea_state_swell_crossing.png

Renders frame 0 (``--spp 256 --denoise``, the scene's resolution unless ``--resolution WxH`` follows) into a
temporary folder, evaluates the scene's spectrum as E(f, θ) [m² Hz⁻¹ rad⁻¹] (the same object the FFT
cascades sample) and draws it in polar form: angle = direction of travel on the map (north up, east right,
as the camera's world), radius = frequency [Hz]. The statistics in the title (Hs, Tp, mean direction) are
``oceanrender.waves.sea.sea_description``.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import imageio.v3 as iio
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from oceanrender.cli import main  # noqa: E402
from oceanrender.scene import load_scene  # noqa: E402
from oceanrender.waves.sea import directional_spectrum, sea_description  # noqa: E402
from oceanrender.waves.wave_spectra import dispersion_relation, group_velocity  # noqa: E402


def spectrum_E(spectrum, f: np.ndarray, theta: np.ndarray, depth: float, tension: float) -> np.ndarray:
    """E(f, θ) of any scene spectrum, from Ψ by Eq. 1 of oceanrender.waves.sea_state inverted [m² Hz⁻¹ rad⁻¹]."""
    from scipy.optimize import brentq

    k = np.array([brentq(lambda q: dispersion_relation(q, depth, 9.81, tension) - 2 * np.pi * fi, 1e-8, 1e4)
                  for fi in f])
    psi = spectrum(k[:, None] * np.cos(theta), k[:, None] * np.sin(theta))
    return psi * (2 * np.pi * k / group_velocity(k, depth, 9.81, tension))[:, None]


def figure(scene_path: Path, out: Path, resolution: str | None = None) -> None:
    scene = load_scene(scene_path)
    with tempfile.TemporaryDirectory() as folder:
        argv = ["render", str(scene_path), "--frames", "0:1", "--out", folder, "--spp", "256", "--denoise",
                "--no-progress"]
        if resolution:
            argv += ["--resolution", resolution]
        assert main(argv) == 0
        frame = iio.imread(Path(folder) / scene.name / "frame_0000.png")
    spectrum = directional_spectrum(scene.ocean)
    described = sea_description(scene.ocean, spectrum)
    f = np.linspace(0.03, 0.35, 160)
    theta = np.linspace(0, 2 * np.pi, 181)
    E = spectrum_E(spectrum, f, theta, scene.ocean.wave_depth, scene.ocean.surface_tension)
    fig = plt.figure(figsize=(15, 4.6))
    ax0 = fig.add_axes([0.0, 0.0, 0.68, 0.9])
    ax0.imshow(frame)
    ax0.axis("off")
    ax0.set_title(f"{scene.name}, frame 0 ({frame.shape[1]}x{frame.shape[0]}, 256 spp denoised); "
                  f"camera looking north", fontsize=10)
    ax1 = fig.add_axes([0.72, 0.08, 0.26, 0.78], projection="polar")
    ax1.set_theta_zero_location("E")  # θ = 0 towards +x (east), counter-clockwise: the project's convention
    mesh = ax1.pcolormesh(theta, f, E, shading="auto", cmap="viridis")
    ax1.set_rlabel_position(200)
    ax1.set_ylim(0, f[-1])
    ax1.set_xticks(np.radians([0, 90, 180, 270]), ["E", "N", "W", "S"])
    fig.colorbar(mesh, ax=ax1, fraction=0.05, pad=0.12, label="E(f, θ) [m² Hz⁻¹ rad⁻¹]")
    ax1.set_title(f"directions of travel; radius f [Hz]\nHs {described['significant_wave_height_m']:.2f} m, "
                  f"Tp {described['peak_period_s']:.1f} s, mean {described['mean_direction_deg']:.0f}°",
                  fontsize=9)
    fig.savefig(out, dpi=80)
    print(f"wrote {out}: {described}")


if __name__ == "__main__":
    figure(Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[4] if len(sys.argv) > 4 and sys.argv[3] == "--resolution"
           else None)
