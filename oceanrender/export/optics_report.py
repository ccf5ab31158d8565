"""Writing the optics report: CSV and JSON tables and matplotlib plots, atomically."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ..io.frames import atomic_path
from ..optics.report import SceneOptics


def _finite_or_none(values) -> list:
    """Nested lists with NaN/inf as None (JSON null): e.g. R = 0/0 above 720 nm, where sunsky has no light."""
    array = np.asarray(values, dtype=float)
    return np.where(np.isfinite(array), array, None).tolist()


def write_optics_report(out_dir: str | Path, optics: SceneOptics, metadata: dict) -> list[Path]:
    """Write ``optics.csv``, ``lightfield.json``, ``iops.png`` and ``lightfield.png`` into ``out_dir``."""
    out_dir = Path(out_dir)
    light = optics.light
    columns = {
        "wavelength_nm": optics.wavelengths, "a_per_m": optics.absorption, "b_per_m": optics.scattering,
        "bb_per_m": optics.backscattering, "c_per_m": optics.attenuation, "Kd_per_m": light.K_d,
        "R_0minus": light.R, "E_upwell_0minus_W_m2_nm": light.E_upwell, "E_bottom_W_m2_nm": light.E_bottom,
        "E_sun_direct_normal_W_m2_nm": optics.direct_normal_irradiance, "E_sky_W_m2_nm": optics.diffuse_irradiance,
    }
    table = np.column_stack([np.broadcast_to(v, optics.wavelengths.shape) for v in columns.values()])
    written = []
    path = out_dir / "optics.csv"
    with atomic_path(path, ".csv") as tmp:
        header = "\n".join([f"oceanrender optics of scene {metadata.get('scene')}: units in the column names",
                            "four-flux model: oceanrender/optics/fourflux.py; sun and sky: Mitsuba sunsky (0 above 720 nm)",
                            ",".join(columns)])
        np.savetxt(tmp, table, delimiter=",", fmt="%.6g", header=header, comments="# ")
    written.append(path)
    path = out_dir / "lightfield.json"
    document = {
        **metadata,
        "units": {"wavelength": "nm", "z": "m, positive down", "irradiance": "W m-2 nm-1", "coefficients": "m-1"},
        "wavelengths_nm": optics.wavelengths.tolist(), "z_m": np.asarray(light.z).tolist(),
        "sun_zenith_deg": optics.sun_zenith, "depth_m": optics.depth if np.isfinite(optics.depth) else "inf",
        "E_d": _finite_or_none(light.E_d), "E_u": _finite_or_none(light.E_u),
        "K_d": _finite_or_none(light.K_d), "R_0minus": _finite_or_none(light.R),
    }
    with atomic_path(path, ".json") as tmp:
        tmp.write_text(json.dumps(document, indent=1, allow_nan=False, default=float))
    written.append(path)
    written += _plots(out_dir, optics)
    return written


def _plots(out_dir: Path, optics: SceneOptics) -> list[Path]:
    import matplotlib  # noqa: PLC0415

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: PLC0415

    written = []
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for values, label in ((optics.absorption, "a"), (optics.scattering, "b"), (optics.backscattering, "b_b"),
                          (optics.attenuation, "c"), (optics.light.K_d, "K_d")):
        ax.semilogy(optics.wavelengths, values, label=label)
    ax.set(xlabel="wavelength [nm]", ylabel="coefficient [m⁻¹]", title="Inherent optical properties and K_d")
    ax.legend()
    ax.grid(alpha=0.3)
    path = out_dir / "iops.png"
    with atomic_path(path, ".png") as tmp:
        fig.savefig(tmp, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    written.append(path)

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    z = np.asarray(optics.light.z)
    for wavelength in (450.0, 550.0, 650.0):
        i = int(np.argmin(np.abs(optics.wavelengths - wavelength)))
        left.semilogx(optics.light.E_d[i], z, label=f"E_d {optics.wavelengths[i]:.0f} nm")
        left.semilogx(optics.light.E_u[i], z, "--", label=f"E_u {optics.wavelengths[i]:.0f} nm")
    left.invert_yaxis()
    left.set(xlabel="irradiance [W m⁻² nm⁻¹]", ylabel="depth z [m]", title="Four-flux irradiance profiles")
    left.legend(fontsize=7)
    right.plot(optics.wavelengths, optics.light.R, label="R(0⁻) = E_u/E_d")
    right.set(xlabel="wavelength [nm]", ylabel="irradiance reflectance [-]", title="Reflectance below the surface")
    right.grid(alpha=0.3)
    path = out_dir / "lightfield.png"
    with atomic_path(path, ".png") as tmp:
        fig.savefig(tmp, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    written.append(path)
    return written
