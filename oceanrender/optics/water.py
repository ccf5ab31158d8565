"""Inherent optical properties (IOPs) of the water body.

Pure sea water: absorption a_w and scattering b_sw from ``spectra/pure_seawater.csv``,
the absorption of pure water at any temperature and salinity (WOPP v3,
:func:`aw_WOPP3`), the salinity change of b_sw, and the refractive index n(λ, T, S).
Coefficients in m⁻¹, wavelengths in nm, temperature in °C, salinity in PSU.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from .tables import SpectralDataError, read_spectral_table


#: Wavelength at which the water's single refractive index is taken [nm]: the middle of the
#: visible; n varies by ±0.3 % over 400-700 nm (dispersion is not rendered).
IOR_WAVELENGTH_NM = 550.0

#: Refractive index of water when neither it nor the temperature or salinity is given [-]:
#: fresh water at 20 °C and 589 nm (Mitsuba's ``"water"``).
DEFAULT_IOR = 1.333

#: The default pure-water table in ``spectra/`` and its salinity [PSU] (see its header).
PURE_SEAWATER_TABLE = "pure_seawater.csv"
TABLE_SALINITY_PSU = 35.0

#: Ranges accepted for the water's state: temperature [°C] and salinity [PSU]. The state sets the
#: absorption of pure water (:func:`aw_WOPP3`), whose linear Ψ_T, Ψ_S model is used here for natural
#: waters from 0 to 40 °C and 0 to 40 PSU (docs/optics.md, "Pure-water absorption against temperature and
#: salinity", says which part of that range was measured and what the rest extrapolates); the index and
#: b_sw accept the same range.
TEMPERATURE_RANGE_C = (0.0, 40.0)
SALINITY_RANGE_PSU = (0.0, 40.0)
#: Temperature and salinity taken for the one of the two left out [°C, PSU].
DEFAULT_TEMPERATURE_C = 20.0
DEFAULT_SALINITY_PSU = 35.0


def _check_state(temperature_c: float, salinity_psu: float) -> tuple[float, float]:
    t, s = float(temperature_c), float(salinity_psu)
    for name, value, (lo, hi), unit in (("temperature_c", t, TEMPERATURE_RANGE_C, "°C"),
                                        ("salinity_psu", s, SALINITY_RANGE_PSU, "PSU")):
        if not lo <= value <= hi:
            raise ValueError(f"{name}: expected {lo:g} to {hi:g} {unit}, got {value!r}")
    return t, s


def seawater_refractive_index(wavelength_nm, temperature_c: float = DEFAULT_TEMPERATURE_C,
                              salinity_psu: float = DEFAULT_SALINITY_PSU) -> np.ndarray:
    """Real refractive index of sea water n(λ, T, S) [-] (Quan & Fry 1995).

    n = n0 + (n1 + n2 T + n3 T²) S + n4 T² + (n5 + n6 S + n7 T)/λ + n8/λ² + n9/λ³,
    λ in nm, T in °C, S in PSU, with n0 = 1.31405, n1 = 1.779e-4, n2 = −1.05e-6,
    n3 = 1.6e-8, n4 = −2.02e-6, n5 = 15.868, n6 = 0.01155, n7 = −0.00423,
    n8 = −4382, n9 = 1.1455e6 — the paper's one fitted equation, to the data of
    Austin & Halikas (1976), 400-700 nm, 0-30 °C, 0-35 PSU.

    Parameters
    ----------
    wavelength_nm : array_like   Vacuum wavelength [nm], 360-830 (the fit's range is 400-700).
    temperature_c : float        Temperature [°C], 0 to 40 (beyond 30: extrapolated).
    salinity_psu : float         Salinity [PSU], 0 to 40 (beyond 35: extrapolated).

    Returns
    -------
    ndarray   n [-], at 1 atm.

    Notes
    -----
    Against Daimon & Masumura (2007) distilled water at 19-24 °C the fit is 3.3-3.7e-4
    lower at every wavelength (their absolute scale differs from Austin & Halikas'); the
    dispersion and the temperature change agree within 3e-5 (``tests/optics/test_water.py``).

    References
    ----------
    .. [1] Quan, X. & Fry, E. S. (1995), "Empirical equation for the index of refraction
       of seawater", Appl. Opt. 34, 3477-3480, doi:10.1364/AO.34.003477.
    """
    t, s = _check_state(temperature_c, salinity_psu)
    wl = np.asarray(wavelength_nm, dtype=float)
    if not np.all((wl >= 360.0) & (wl <= 830.0)):
        raise ValueError(f"wavelength_nm: expected 360 to 830 nm, got {np.min(wl):g} to {np.max(wl):g}")
    return (1.31405 + (1.779e-4 - 1.05e-6 * t + 1.6e-8 * t * t) * s - 2.02e-6 * t * t  # [1]
            + (15.868 + 0.01155 * s - 0.00423 * t) / wl - 4382.0 / wl**2 + 1.1455e6 / wl**3)


#: WOPP v3 table of pure-water absorption at 20 °C, 0 PSU and its Ψ_S, Ψ_T in ``spectra/`` (see its header).
WOPP_TABLE = "pure_water_wopp_v3.csv"
#: Reference state of the WOPP table's a_w: 20 °C, 0 PSU.
WOPP_REFERENCE_TEMPERATURE_C = 20.0


@functools.lru_cache(maxsize=1)
def _wopp_table():
    return read_spectral_table(WOPP_TABLE, required=("a_w_20C_0PSU_per_m", "psi_S_per_m_per_PSU", "psi_T_per_m_per_C"))


def aw_WOPP3(wavelengths_nm, temperature_c: float = WOPP_REFERENCE_TEMPERATURE_C,
             salinity_psu: float = 0.0) -> np.ndarray:
    """Absorption of pure water a_w(λ, T, S) [m⁻¹] (WOPP v3).

    a_w(T, S) = a_w(20 °C, 0 PSU) + Ψ_T (T − 20 °C) + Ψ_S S, linear in T and S, with the
    WOPP v3 tables (Röttgers, HZG, 2016): a_w of Mason, Cone & Fry (2016, Table 2) below
    510 nm and of the WOPP compilation above, Ψ_T and Ψ_S of Röttgers, McKee & Utschig (2014).
    Linear interpolation between the table's 2 nm steps.

    Parameters
    ----------
    wavelengths_nm : array_like   Wavelengths [nm], 350 to 900.
    temperature_c : float         Water temperature [°C], :data:`TEMPERATURE_RANGE_C`.
    salinity_psu : float          Salinity [PSU], :data:`SALINITY_RANGE_PSU`.

    Returns
    -------
    ndarray   a_w [m⁻¹].

    References
    ----------
    .. [1] Röttgers, R., McKee, D. & Utschig, C. (2014), "Temperature and salinity correction
       coefficients for light absorption by water in the visible to infrared spectral region",
       Opt. Express 22, 25093-25108, doi:10.1364/OE.22.025093.
    .. [2] Mason, J. D., Cone, M. T. & Fry, E. S. (2016), "Ultraviolet (250-550 nm) absorption
       spectrum of pure water", Appl. Opt. 55, 7163-7172, doi:10.1364/AO.55.007163.
    """
    t, s = _check_state(temperature_c, salinity_psu)
    table = _wopp_table()
    wl = np.asarray(wavelengths_nm, dtype=float)
    return (table.at("a_w_20C_0PSU_per_m", wl) + table.at("psi_T_per_m_per_C", wl) * (t - WOPP_REFERENCE_TEMPERATURE_C)
            + table.at("psi_S_per_m_per_PSU", wl) * s)  # [1]


def seawater_scattering_salinity_factor(salinity_psu: float, table_salinity_psu: float) -> float:
    """b_sw(S) / b_sw(S_table) [-]: molecular scattering of sea water against salinity.

    b_sw ∝ 1 + 0.3 S / 37 (Morel 1974: sea water of 35-39 PSU scatters 30 % more than
    pure water), the form ``jerlov.pure_water_scattering`` uses. S in PSU.

    References
    ----------
    .. [1] Morel, A. (1974), "Optical properties of pure water and pure sea water", in
       Optical Aspects of Oceanography, Academic Press, pp. 1-24.
    """
    _check_state(DEFAULT_TEMPERATURE_C, salinity_psu)
    _check_state(DEFAULT_TEMPERATURE_C, table_salinity_psu)
    return (1.0 + 0.3 * salinity_psu / 37.0) / (1.0 + 0.3 * table_salinity_psu / 37.0)  # [1]


@dataclass(frozen=True)
class WaterIOPs:
    """Spectral absorption and scattering of a homogeneous water body.

    Attributes
    ----------
    wavelengths : ndarray   Wavelengths [nm].
    absorption : ndarray    Absorption coefficient a(λ) [m⁻¹].
    scattering : ndarray    Scattering coefficient b(λ) [m⁻¹].
    source : str            Provenance (the table's header).
    """

    wavelengths: np.ndarray
    absorption: np.ndarray
    scattering: np.ndarray
    source: str

    @property
    def attenuation(self) -> np.ndarray:
        """Beam attenuation c = a + b [m⁻¹]."""
        return self.absorption + self.scattering

    @property
    def single_scattering_albedo(self) -> np.ndarray:
        """ω0 = b / c [-], in [0, 1]."""
        return self.scattering / self.attenuation


#: Largest absorption or scattering coefficient accepted in a table [m⁻¹]: a hundred times the
#: attenuation of very turbid estuaries (order 100 m⁻¹); the bound refuses nonsense, not water.
MAX_IOP_PER_M = 1.0e4


def check_iop_values(table: str, absorption: np.ndarray, scattering: np.ndarray) -> None:
    """Refuse a, b that no water has: a > 0 (all water absorbs), b ≥ 0, both ≤ :data:`MAX_IOP_PER_M` [m⁻¹]."""
    if not (np.all(absorption > 0) and np.all(absorption <= MAX_IOP_PER_M)):
        raise SpectralDataError(f"{table}: a_per_m must lie in (0, {MAX_IOP_PER_M:g}] m⁻¹ at every wavelength "
                                f"(water always absorbs), got {absorption.min():g} to {absorption.max():g}")
    if not (np.all(scattering >= 0) and np.all(scattering <= MAX_IOP_PER_M)):
        raise SpectralDataError(f"{table}: b_per_m must lie in [0, {MAX_IOP_PER_M:g}] m⁻¹ at every wavelength, "
                                f"got {scattering.min():g} to {scattering.max():g}")


def pure_seawater_iops(table: str = PURE_SEAWATER_TABLE) -> WaterIOPs:
    """IOPs of pure sea water from a table in ``spectra/`` [m⁻¹].

    The default table is Williamson & Hollins (2022) absorption with
    Morel (1974) scattering; see its header and ``spectra/make_pure_seawater.py``.
    """
    data = read_spectral_table(table, required=("a_per_m", "b_per_m"))
    check_iop_values(table, data.columns["a_per_m"], data.columns["b_per_m"])
    return WaterIOPs(
        wavelengths=data.wavelengths,
        absorption=data.columns["a_per_m"],
        scattering=data.columns["b_per_m"],
        source=data.header,
    )


@dataclass(frozen=True)
class MediumOptics:
    """What the renderer needs of the water: spectral IOPs and a phase-function model.

    Attributes
    ----------
    iops : WaterIOPs
        a(λ), b(λ) [m⁻¹].
    particle_fraction : float
        Share of the scattering due to particles at 550 nm, b_p/b [-]; the rest is
        molecular (Rayleigh-shaped) scattering by the water itself.
    particle_g : float
        Henyey–Greenstein asymmetry g [-] of the particles, fitted to their
        backscattering ratio b_bp/b_p at 550 nm.
    particle_fraction_spectrum, particle_g_spectrum : ndarray or None
        The same two at every wavelength of ``iops`` [-] (b_p(λ)/b(λ), and g(λ) fitted
        to b_bp(λ)/b_p(λ)); when given, the renderer's phase function follows them
        (:mod:`oceanrender.render.phase`) and b_b/b of the render equals the
        composition's at every wavelength. None: the 550 nm values at all wavelengths.
    phase_table : (mu, p) or None
        A tabulated phase function of the whole water instead of the Rayleigh + HG blend:
        cosines mu (M,) from −1 to 1 [-] and p (n_λ, M) [sr⁻¹] at the wavelengths of
        ``iops`` (a 5 nm grid), e.g. Fournier–Forand per particle component.
    """

    iops: WaterIOPs
    particle_fraction: float = 0.0
    particle_g: float = 0.0
    particle_fraction_spectrum: np.ndarray | None = None
    particle_g_spectrum: np.ndarray | None = None
    phase_table: tuple[np.ndarray, np.ndarray] | None = None

    def __post_init__(self) -> None:
        n = self.iops.wavelengths.size
        for name in ("particle_fraction_spectrum", "particle_g_spectrum"):
            value = getattr(self, name)
            if value is None:
                continue
            value = np.asarray(value, dtype=float)
            if value.shape != (n,) or not np.all(np.isfinite(value)):
                raise ValueError(f"MediumOptics.{name}: need {n} finite values (one per wavelength of iops)")
            object.__setattr__(self, name, value)
        if self.particle_fraction_spectrum is not None and np.any(
                (self.particle_fraction_spectrum < 0) | (self.particle_fraction_spectrum > 1)):
            raise ValueError("MediumOptics.particle_fraction_spectrum: need 0 ≤ b_p/b ≤ 1")
        if self.particle_g_spectrum is not None and np.any(np.abs(self.particle_g_spectrum) >= 1):
            raise ValueError("MediumOptics.particle_g_spectrum: need |g| < 1")
