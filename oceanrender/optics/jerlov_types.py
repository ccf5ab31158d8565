"""Jerlov water types as measured IOPs (Williamson & Hollins 2022), for the renderer.

Jerlov classified sea water by its diffuse attenuation K_d(λ) (oceanic I–III,
coastal 1C–9C). Williamson & Hollins (2022) measured absorption and scattering
of waters so classified; the ``jerlov`` package ships their a(λ), b(λ) for
types IB, II, III, 1C, 3C and 5C on 300–800 nm (measured 412–715 nm, their
model outside). Those are the types offered here; I, IA, 7C and 9C have no
measured IOPs in that source and are refused rather than invented.

Extension to 830 nm (the film's range), stated and not silent: beyond 800 nm the
non-water absorption is held at its 800 nm value on top of pure water's
(a_w from ``spectra/pure_seawater.csv``), and the particle scattering follows
b_p ∝ λ⁻¹ from its 800 nm value. Backscattering: pure water's b_w/2 plus the
particles' b_p times Petzold's average-particle ratio 0.0183 (Mobley 1994,
Light and Water, Table 3.10), which also sets the Henyey–Greenstein g of the
particle phase-function lobe.

References
----------
.. [1] C. A. Williamson and R. C. Hollins, "Measured IOPs of Jerlov water
   types," Appl. Opt. 61(33), 9951–9961, 2022, doi:10.1364/AO.470464.
.. [2] N. G. Jerlov, Marine Optics, Elsevier, 1976.
.. [3] C. D. Mobley, Light and Water, Academic Press, 1994, Table 3.10.
"""

from __future__ import annotations

import csv
from importlib import resources

import numpy as np

from .tables import SpectralDataError
from .water import MediumOptics, WaterIOPs, pure_seawater_iops

#: Types with measured IOPs in Williamson & Hollins (2022).
JERLOV_TYPES = ("IB", "II", "III", "1C", "3C", "5C")

#: Particle backscattering ratio b_bp/b_p of Petzold's average particle [-] (Mobley 1994, Table 3.10).
PETZOLD_PARTICLE_BB_RATIO = 0.0183

#: Range of the published table [nm].
TABLE_RANGE_NM = (300.0, 800.0)


def _table(water_type: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(λ [nm], a [m⁻¹], b [m⁻¹]) of a type from the ``jerlov`` package's Williamson & Hollins table."""
    if water_type not in JERLOV_TYPES:
        raise KeyError(f"unknown Jerlov water type {water_type!r}; with measured IOPs: {', '.join(JERLOV_TYPES)}")
    with resources.files("jerlov").joinpath("data/williamson2022_iop.csv").open(encoding="utf-8") as f:
        rows = [r for r in csv.DictReader(f) if r["water_type"] == water_type]
    by = {q: sorted((float(r["wavelength_nm"]), float(r["value_per_m"])) for r in rows if r["quantity"] == q)
          for q in ("a", "b")}
    wl = np.array([w for w, _ in by["a"]])
    return wl, np.array([v for _, v in by["a"]]), np.interp(wl, *np.array(by["b"]).T)


def iops_WilliamsonHollins2022(water_type: str, wavelengths_nm) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """a, b, b_b [m⁻¹] of a Jerlov water type at ``wavelengths_nm`` (360–830 nm).

    Parameters
    ----------
    water_type : str          One of :data:`JERLOV_TYPES`.
    wavelengths_nm : array_like   [nm], within 360–830 (beyond 800 by the stated extension).

    Returns
    -------
    tuple of ndarray   absorption a, scattering b, backscattering b_b [m⁻¹].
    """
    wl = np.atleast_1d(np.asarray(wavelengths_nm, dtype=float))
    if wl.size == 0 or not np.all(np.isfinite(wl)) or wl.min() < 360.0 or wl.max() > 830.0:
        raise SpectralDataError("wavelengths_nm: Jerlov-type IOPs are defined on 360-830 nm, "
                                f"got {np.nanmin(wl)}-{np.nanmax(wl)} nm; no extrapolation beyond")
    table_wl, table_a, table_b = _table(water_type)
    water = pure_seawater_iops()
    a_w = np.interp(wl, water.wavelengths, water.absorption)
    b_w = np.interp(wl, water.wavelengths, water.scattering)
    end = TABLE_RANGE_NM[1]
    a_w_end = float(np.interp(end, water.wavelengths, water.absorption))
    b_w_end = float(np.interp(end, water.wavelengths, water.scattering))
    inside = wl <= end
    a = np.where(inside, np.interp(wl, table_wl, table_a), a_w + (table_a[-1] - a_w_end))
    b_p_end = max(table_b[-1] - b_w_end, 0.0)
    b = np.where(inside, np.interp(wl, table_wl, table_b), b_w + b_p_end * end / wl)  # b_p ∝ λ⁻¹ beyond 800 nm
    b_p = np.maximum(b - b_w, 0.0)
    bb = 0.5 * b_w + PETZOLD_PARTICLE_BB_RATIO * b_p
    return a, b, bb


def jerlov_type_optics(water_type: str, wavelengths: np.ndarray | None = None) -> MediumOptics:
    """The renderer's medium for a Jerlov water type: IOPs and the Rayleigh + HG phase blend.

    The blend weight b_p(λ)/b(λ) is given per wavelength (``particle_fraction_spectrum``),
    g is Petzold's particle b_bp/b_p at every wavelength; ``particle_fraction`` is the 550 nm value.
    """
    from .components import henyey_greenstein_g_from_bb_ratio  # noqa: PLC0415

    wavelengths = np.arange(360.0, 831.0, 5.0) if wavelengths is None else np.asarray(wavelengths, float)
    a, b, _ = iops_WilliamsonHollins2022(water_type, wavelengths)
    water = pure_seawater_iops()
    b_w550 = float(np.interp(550.0, water.wavelengths, water.scattering))
    b550 = float(np.interp(550.0, wavelengths, b))
    fraction = float(np.clip((b550 - b_w550) / b550, 0.0, 1.0))
    g = float(henyey_greenstein_g_from_bb_ratio(PETZOLD_PARTICLE_BB_RATIO))
    iops = WaterIOPs(wavelengths=wavelengths, absorption=a, scattering=b,
                     source=f"Jerlov type {water_type}: Williamson & Hollins (2022), doi:10.1364/AO.470464")
    b_w = np.interp(wavelengths, water.wavelengths, water.scattering)
    fraction_spectrum = np.clip(np.divide(b - b_w, b, out=np.zeros_like(b), where=b > 0), 0.0, 1.0)
    return MediumOptics(iops=iops, particle_fraction=fraction, particle_g=g,
                        particle_fraction_spectrum=fraction_spectrum, particle_g_spectrum=np.full_like(b, g))
