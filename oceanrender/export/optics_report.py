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


LIGHTFIELD_DECADES = 6
"""Decades of irradiance below the largest surface value that the light-field plot shows [-]."""


def lightfield_limits(z, E_d, E_u, decades: int = LIGHTFIELD_DECADES) -> tuple[float, float, float]:
    """(deepest z [m], smallest and largest irradiance [W m⁻² nm⁻¹]) of a readable light-field plot.

    The irradiance axis spans ``decades`` below the largest value of E_d and E_u (so
    turbid water, whose E_d falls by 1e-67 over the water column, is not squashed into
    one corner); the depth axis ends where every plotted E_d has fallen below that floor
    (or at the bottom of z). E_d, E_u: (n_λ, n_z) on the depths z [m], positive down.
    """
    z = np.asarray(z, dtype=float)
    E_d = np.atleast_2d(np.asarray(E_d, dtype=float))
    E_u = np.atleast_2d(np.asarray(E_u, dtype=float))
    finite = np.concatenate([E_d[np.isfinite(E_d)], E_u[np.isfinite(E_u)]])
    top = float(finite.max()) if finite.size and finite.max() > 0 else 1.0
    floor = top * 10.0 ** (-decades)
    above = np.any(np.nan_to_num(E_d, nan=0.0) >= floor, axis=0)
    deepest = float(z[np.nonzero(above)[0].max()]) if above.any() else float(z[-1])
    z_max = min(float(z[-1]), deepest * 1.05) if deepest > 0 else float(z[-1])
    return z_max, floor, 2.0 * top


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
    rows = [int(np.argmin(np.abs(optics.wavelengths - wavelength))) for wavelength in (450.0, 550.0, 650.0)]
    for i in rows:
        left.semilogx(optics.light.E_d[i], z, label=f"E_d {optics.wavelengths[i]:.0f} nm")
        left.semilogx(optics.light.E_u[i], z, "--", label=f"E_u {optics.wavelengths[i]:.0f} nm")
    z_max, x_lo, x_hi = lightfield_limits(z, optics.light.E_d[rows], optics.light.E_u[rows])
    left.set_xlim(x_lo, x_hi)
    left.set_ylim(z_max, 0.0)  # depth down
    left.set(xlabel="irradiance [W m⁻² nm⁻¹]", ylabel="depth z [m]",
             title=f"Four-flux irradiance profiles (to {LIGHTFIELD_DECADES} decades below the surface)")
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
