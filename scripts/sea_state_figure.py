"""A rendered frame of a sea-state scene beside a polar plot of its directional spectrum (docs/geometry.md).

Run from the repository root::

    python scripts/sea_state_figure.py scenes/swell_crossing.toml docs/images/sea_state_swell_crossing.png \
        [--resolution WxH] [--frame PNG]

Renders frame 0 (or takes the rendered ``--frame PNG``) (``--spp 256 --denoise``, the scene's resolution unless ``--resolution WxH`` follows) into a
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


def figure(scene_path: Path, out: Path, resolution: str | None = None, frame_png: Path | None = None) -> None:
    scene = load_scene(scene_path)
    if frame_png is not None:
        frame = iio.imread(frame_png)
    else:
        with tempfile.TemporaryDirectory() as folder:
            argv = ["render", str(scene_path), "--frames", "0:1", "--out", folder, "--spp", "256", "--denoise",
                    "--no-progress"]
            if resolution:
                argv += ["--resolution", resolution]
            assert main(argv) == 0
            frame = iio.imread(Path(folder) / scene.name / "frame_0000.png")
            iio.imwrite(Path(tempfile.gettempdir()) / f"{out.stem}_frame.png", frame)  # for --frame
    spectrum = directional_spectrum(scene.ocean)
    described = sea_description(scene.ocean, spectrum)
    f = np.linspace(0.03, 0.35, 160)
    theta = np.linspace(0, 2 * np.pi, 181)
    E = spectrum_E(spectrum, f, theta, scene.ocean.wave_depth, scene.ocean.surface_tension)
    fig = plt.figure(figsize=(15.5, 4.6))
    ax0 = fig.add_axes([0.0, 0.0, 0.66, 0.9])
    ax0.imshow(frame)
    ax0.axis("off")
    ax0.set_title(f"{scene.name}, frame 0 ({frame.shape[1]}x{frame.shape[0]}, 256 spp denoised); "
                  f"camera looking north", fontsize=10)
    ax1 = fig.add_axes([0.675, 0.08, 0.25, 0.78], projection="polar")
    ax1.set_theta_zero_location("E")  # θ = 0 towards +x (east), counter-clockwise: the project's convention
    # Log colours over three decades: a narrow swell peak and a broad wind sea both show.
    top = float(E.max())
    norm = matplotlib.colors.LogNorm(vmin=top * 1e-3, vmax=top)
    mesh = ax1.pcolormesh(theta, f, np.clip(E, top * 1e-3, None), shading="auto", cmap="viridis", norm=norm)
    ax1.set_rlabel_position(225)
    ax1.set_ylim(0, f[-1])
    ax1.set_yticks([0.1, 0.2, 0.3], ["0.1", "0.2", "0.3 Hz"], fontsize=7)
    ax1.set_xticks(np.radians([0, 90, 180, 270]), ["E", "N", "W", "S"])
    bar = fig.add_axes([0.935, 0.12, 0.012, 0.7])
    fig.colorbar(mesh, cax=bar, label="E(f, θ) [m² Hz⁻¹ rad⁻¹], log")
    ax1.set_title(f"directions of travel; radius f [Hz]\nHs {described['significant_wave_height_m']:.2f} m, "
                  f"Tp {described['peak_period_s']:.1f} s, mean {described['mean_direction_deg']:.0f}°",
                  fontsize=9)
    fig.savefig(out, dpi=80)
    print(f"wrote {out}: {described}")


if __name__ == "__main__":
    options = dict(zip(sys.argv[3::2], sys.argv[4::2]))
    figure(Path(sys.argv[1]), Path(sys.argv[2]), options.get("--resolution"),
           Path(options["--frame"]) if "--frame" in options else None)
