"""Water composition → spectral IOPs: a(λ), b(λ), b_b(λ) [m⁻¹] per component and in total.

Components and their models
---------------------------
water           absorption a_w(T, S) of WOPP v3 (:func:`~oceanrender.optics.water.aw_WOPP3`) at
                the composition's temperature and salinity; scattering from
                ``spectra/pure_seawater.csv`` (Morel 1974 b_sw at 35 PSU) rescaled to the
                salinity by Morel's (1 + 0.3 S/37); b_b,w = b_w / 2 (symmetric VSF).
phytoplankton   absorption :func:`aph_Bricaud1998` (a_φ = A_φ Chl^E_φ, measured; default) or
                :func:`aph_HoepffnerSathyendranath1991` (Gaussian pigment bands, packaged in
                three size classes), chosen by ``phytoplankton_absorption``; scattering
                :func:`bp_LoiselMorel1998`; b_b = 0.01 b (:data:`PHYTOPLANKTON_BB_RATIO`).
cdom            :func:`ag_BricaudMorelPrieur1981`, no scattering.
soil, kaolinite, illite, calcite
                mass-specific a*, b*, b_b* [m² g⁻¹] from Mie theory, ``spectra/mineral_*.csv``
                (``spectra/make_mineral_iops.py``) times the concentration [g m⁻³].

The phase function of the mixture is described by the per-component b and b_b:
:func:`mixture_phase_function` adds the water's Rayleigh-like phase function to one
Fournier-Forand phase function per particle component, each fitted to that component's
backscattering ratio (:func:`fournier_forand_from_bb_ratio`);
:func:`henyey_greenstein_g_from_bb_ratio` gives the one-parameter alternative.
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from .tables import VISIBLE_RANGE_NM, SpectralDataError, read_spectral_table
from .water import (
    SALINITY_RANGE_PSU,
    TABLE_SALINITY_PSU,
    TEMPERATURE_RANGE_C,
    MediumOptics,
    WaterIOPs,
    aw_WOPP3,
    pure_seawater_iops,
    seawater_scattering_salinity_factor,
)

#: Backscattering ratio b_bp/b_p of phytoplankton-dominated particles [-]:
#: ≈ 0.01 for organic particles of low relative index (Twardowski et al. 2001,
#: J. Geophys. Res. 106(C7):14129; Ulloa, Sathyendranath & Platt 1994, Appl. Opt. 33:7070).
PHYTOPLANKTON_BB_RATIO = 0.01

#: Mineral components and their tables in ``spectra/``.
MINERAL_TABLES = MappingProxyType({
    "soil": "mineral_soil.csv",
    "kaolinite": "mineral_kaolinite.csv",
    "illite": "mineral_illite.csv",
    "calcite": "mineral_calcite.csv",
})

#: Models of phytoplankton absorption a_φ(λ, Chl) (``[composition] phytoplankton_absorption``); the first is
#: the default: Bricaud et al. (1998)'s measured power laws, or the Gaussian-band model this project had
#: until issue 43 (Hoepffner & Sathyendranath 1991 with packaging).
PHYTOPLANKTON_ABSORPTION_MODELS = ("Bricaud 1998", "Hoepffner-Sathyendranath 1991")

#: Morel (1974) depolarisation-derived anisotropy of pure-water scattering, β ∝ 1 + 0.835 cos²θ.
WATER_ANISOTROPY = 0.835


@dataclass(frozen=True)
class WaterComposition:
    """What the water holds. Every concentration must be ≥ 0.

    Attributes
    ----------
    temperature_c : float       Water temperature [°C], 0 to 40 (sets a_w, :func:`~oceanrender.optics.water.aw_WOPP3`).
    salinity_psu : float        Salinity [PSU], 0 to 40 (sets a_w and b_sw).
    chlorophyll_mg_m3 : float   Chlorophyll a [mg m⁻³].
    soil_g_m3 : float           Iron-oxide-bearing soil particles [g m⁻³].
    kaolinite_g_m3 : float      Kaolinite clay particles [g m⁻³].
    illite_g_m3 : float         Illite clay particles [g m⁻³].
    calcite_g_m3 : float        Calcite / limestone particles [g m⁻³].
    cdom_a440_per_m : float     CDOM absorption at 440 nm [m⁻¹].
    cdom_slope_per_nm : float   CDOM spectral slope S [nm⁻¹], 0.005 to 0.03.
    phytoplankton_absorption : str
        One of :data:`PHYTOPLANKTON_ABSORPTION_MODELS` (default Bricaud et al. 1998).
    """

    temperature_c: float = 20.0
    salinity_psu: float = 35.0
    chlorophyll_mg_m3: float = 0.0
    soil_g_m3: float = 0.0
    kaolinite_g_m3: float = 0.0
    illite_g_m3: float = 0.0
    calcite_g_m3: float = 0.0
    cdom_a440_per_m: float = 0.0
    cdom_slope_per_nm: float = 0.014
    phytoplankton_absorption: str = PHYTOPLANKTON_ABSORPTION_MODELS[0]

    def __post_init__(self) -> None:
        if self.phytoplankton_absorption not in PHYTOPLANKTON_ABSORPTION_MODELS:
            raise ValueError(f"phytoplankton_absorption: expected one of {', '.join(PHYTOPLANKTON_ABSORPTION_MODELS)}, "
                             f"got {self.phytoplankton_absorption!r}")
        for f in dataclasses.fields(self):
            if f.name == "phytoplankton_absorption":
                continue
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
                raise ValueError(f"{f.name}: must be a number, got {value!r}")
            if not np.isfinite(value):
                raise ValueError(f"{f.name}: must be finite, got {value!r}")
        for name in ("chlorophyll_mg_m3", "soil_g_m3", "kaolinite_g_m3", "illite_g_m3", "calcite_g_m3", "cdom_a440_per_m"):
            if getattr(self, name) < 0:
                raise ValueError(f"{name}: a concentration cannot be negative, got {getattr(self, name)!r}")
        _in_range(self, "temperature_c", *TEMPERATURE_RANGE_C)
        _in_range(self, "salinity_psu", *SALINITY_RANGE_PSU)
        _in_range(self, "cdom_slope_per_nm", 0.005, 0.03)

    @classmethod
    def from_mapping(cls, values: Mapping[str, float]) -> "WaterComposition":
        """Build from a mapping (e.g. a TOML table), refusing unknown keys by name."""
        known = [f.name for f in dataclasses.fields(cls)]
        unknown = [key for key in values if key not in known]
        if unknown:
            raise ValueError(f"unknown water component(s) {', '.join(map(repr, unknown))}; known: {', '.join(known)}")
        return cls(**values)


def _in_range(obj, name: str, lo: float, hi: float) -> None:
    value = getattr(obj, name)
    if not lo <= value <= hi:
        raise ValueError(f"{name}: {value!r} outside the supported {lo:g} to {hi:g}")


@dataclass(frozen=True)
class ComponentIOPs:
    """IOPs of one component [m⁻¹] on the result's wavelengths."""

    absorption: np.ndarray
    scattering: np.ndarray
    backscattering: np.ndarray

    @property
    def backscattering_ratio(self) -> np.ndarray:
        """b_b / b [-]; NaN where the component does not scatter."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(self.scattering > 0, self.backscattering / self.scattering, np.nan)


@dataclass(frozen=True)
class CompositionIOPs:
    """Spectral IOPs of a water body, per component and in total.

    Attributes
    ----------
    wavelengths : ndarray                Wavelengths [nm].
    composition : WaterComposition       What they were computed for.
    components : mapping of str to ComponentIOPs
        "water", "phytoplankton", "cdom", "soil", "kaolinite", "illite", "calcite".
    notes : tuple of str                 Model limitations that apply to this result.
    """

    wavelengths: np.ndarray
    composition: WaterComposition
    components: Mapping[str, ComponentIOPs]
    notes: tuple[str, ...] = ()

    @property
    def absorption(self) -> np.ndarray:
        """Total absorption coefficient a(λ) [m⁻¹]."""
        return sum(c.absorption for c in self.components.values())

    @property
    def scattering(self) -> np.ndarray:
        """Total scattering coefficient b(λ) [m⁻¹]."""
        return sum(c.scattering for c in self.components.values())

    @property
    def backscattering(self) -> np.ndarray:
        """Total backscattering coefficient b_b(λ) [m⁻¹]."""
        return sum(c.backscattering for c in self.components.values())

    @property
    def attenuation(self) -> np.ndarray:
        """c = a + b [m⁻¹]."""
        return self.absorption + self.scattering

    @property
    def backscattering_ratio(self) -> np.ndarray:
        """b_b / b of the mixture, water included [-]."""
        return self.backscattering / self.scattering

    @property
    def single_scattering_albedo(self) -> np.ndarray:
        """ω0 = b / c [-]."""
        return self.scattering / self.attenuation


# ----------------------------------------------------------------------------
# Phytoplankton
# ----------------------------------------------------------------------------

#: Chlorophyll a in vivo, unpackaged: Gaussian bands (centre [nm], σ [nm], peak a* [m² mg⁻¹]).
HS1991_CHLOROPHYLL_A_BANDS = (
    (384.0, 53.8, 0.037),
    (413.0, 21.3, 0.012),
    (435.0, 32.1, 0.039),
    (623.0, 35.0, 0.005),
    (676.0, 21.6, 0.020),
    (700.0, 33.5, 0.002),
)
#: Photosynthetic carotenoids, per mg of carotenoid (centre [nm], σ [nm], peak a* [m² mg⁻¹]).
HS1991_CAROTENOID_BANDS = ((490.0, 17.1, 0.0313), (532.0, 22.8, 0.0194))

#: Photosynthetic carotenoids per chlorophyll a [mg mg⁻¹]: total accessory pigments ≈ TChl a
#: on average (Trees et al. 2000, Limnol. Oceanogr. 45:1130); about half of them photosynthetic carotenoids.
CAROTENOID_TO_CHLOROPHYLL = 0.5

#: Intracellular chlorophyll c_i [mg m⁻³]: 2-10 kg m⁻³ for the cultures of Stramski, Bricaud &
#: Morel (2001) Appl. Opt. 40:2929, Table 1 (Chl per cell over cell volume), median ≈ 4 kg m⁻³.
INTRACELLULAR_CHLOROPHYLL_MG_M3 = 4.0e6

#: Effective cell diameters of pico-, nano- and microphytoplankton [m], the typical sizes of
#: those classes in Stramski et al. (2001) Table 1 (Synechococcus ≈ 1 µm; haptophytes and diatoms
#: 4-8 µm; Prorocentrum micans 28 µm) within Sieburth et al.'s (1978) 0.2-2-20-200 µm classes.
SIZE_CLASS_DIAMETERS_M = (1.0e-6, 5.0e-6, 25.0e-6)

#: Taper of the phytoplankton absorption beyond the Chl a red bands [nm]: 1 at 700 nm, 0 from 750 nm.
APH_TAPER_NM = (700.0, 750.0)


def size_classes_Brewin2010(chlorophyll_mg_m3):
    """Chlorophyll in pico-, nano- and microphytoplankton [mg m⁻³] (Brewin et al. 2010).

    C_p = C_p^m (1 − exp(−S_p C)), C_p,n = C_p,n^m (1 − exp(−S_p,n C)),
    C_n = C_p,n − C_p, C_m = C − C_p,n, with C_p^m = 0.107, S_p = 6.801,
    C_p,n^m = 1.057, S_p,n = 0.851.

    References
    ----------
    .. [1] Brewin, R. J. W. et al. (2010), "A three-component model of phytoplankton
       size class for the Atlantic Ocean", Ecol. Model. 221, 1472-1483.
    """
    c = np.asarray(chlorophyll_mg_m3, dtype=float)
    c_pn = 1.057 * (1.0 - np.exp(-0.851 * c))
    c_p = 0.107 * (1.0 - np.exp(-6.801 * c))
    return c_p, c_pn - c_p, c - c_pn


def packaging_MorelBricaud1981(rho_prime):
    """Package-effect factor Q*_a(ρ') [-] of homogeneous absorbing spheres.

    Q*_a = (3 / 2ρ') [1 + 2 e^−ρ' / ρ' + 2 (e^−ρ' − 1) / ρ'²], ρ' = a_cm D, the
    optical thickness of the cell's material across its diameter. Q*_a → 1 for ρ' → 0.

    References
    ----------
    .. [1] Morel, A. & Bricaud, A. (1981), "Theoretical results concerning light
       absorption in a discrete medium, and application to specific absorption of
       phytoplankton", Deep-Sea Res. 28A, 1375-1393.
    """
    r = np.asarray(rho_prime, dtype=float)
    small = r < 1e-3
    rs = np.where(small, 1.0, r)
    q = 1.5 / rs * (1.0 + 2.0 * np.exp(-rs) / rs + 2.0 * (np.exp(-rs) - 1.0) / rs**2)  # [1]
    return np.where(small, 1.0 - 0.375 * r, q)  # series for small ρ': 1 − 3ρ'/8


def aph_HoepffnerSathyendranath1991(wavelengths_nm, chlorophyll_mg_m3):
    """Phytoplankton absorption a_φ(λ) [m⁻¹] from Gaussian pigment bands with packaging.

    a_φ = Σ_k C_k a*_sol(λ) Q*_a(c_i D_k a*_sol(λ)) × taper(λ), where
    a*_sol = Σ Chl a bands + r Σ carotenoid bands (Gaussians of [1]), C_k the
    chlorophyll of the three size classes (:func:`size_classes_Brewin2010`),
    Q*_a the package effect (:func:`packaging_MorelBricaud1981`), c_i
    :data:`INTRACELLULAR_CHLOROPHYLL_MG_M3`, D_k :data:`SIZE_CLASS_DIAMETERS_M`,
    r :data:`CAROTENOID_TO_CHLOROPHYLL`.

    Parameters
    ----------
    wavelengths_nm : array_like    Wavelengths [nm], 360-830.
    chlorophyll_mg_m3 : float      Chlorophyll a [mg m⁻³], ≥ 0.

    Returns
    -------
    ndarray    a_φ(λ) [m⁻¹].

    Notes
    -----
    * The Gaussian parameters (centre, σ, peak) are those of [1] as tabulated,
      with that attribution, in the CSIRO EMS ecology library (Baird et al.
      2016, Environ. Model. Softw. 78:79); they were not re-read from the paper.
    * Extension outside 400-700 nm: below 400 nm the 384- and 413-nm Soret bands
      of [1] are used unchanged down to 360 nm; above 700 nm the sum is tapered
      by a raised cosine from 1 at 700 nm to 0 at 750 nm (the Chl a Q_y band
      ends near 730 nm; no phytoplankton absorption is modelled beyond 750 nm).
    * Against Bricaud et al. (1998) a_φ = A Chl^E (400-690 nm): median |ratio − 1|
      ≈ 0.05-0.25 for Chl 0.3-10 mg m⁻³; at 0.03-0.1 mg m⁻³ this model is
      ~35-55 % low at 440 nm (no photoprotective carotenoids or Chl b/c bands,
      which oligotrophic picoplankton are rich in). See the tests.

    References
    ----------
    .. [1] Hoepffner, N. & Sathyendranath, S. (1991), "Effect of pigment composition
       on absorption properties of phytoplankton", Mar. Ecol. Prog. Ser. 73, 11-23.
    .. [2] Morel, A. & Bricaud, A. (1981), Deep-Sea Res. 28A, 1375-1393.
    .. [3] Brewin, R. J. W. et al. (2010), Ecol. Model. 221, 1472-1483.
    """
    wl = np.asarray(wavelengths_nm, dtype=float)
    chl = float(chlorophyll_mg_m3)
    if chl < 0:
        raise ValueError(f"chlorophyll_mg_m3: a concentration cannot be negative, got {chl!r}")
    a_sol = _gaussians(HS1991_CHLOROPHYLL_A_BANDS, wl) + CAROTENOID_TO_CHLOROPHYLL * _gaussians(HS1991_CAROTENOID_BANDS, wl)
    a = np.zeros_like(wl)
    for c_k, d_k in zip(size_classes_Brewin2010(chl), SIZE_CLASS_DIAMETERS_M):
        a += c_k * a_sol * packaging_MorelBricaud1981(INTRACELLULAR_CHLOROPHYLL_MG_M3 * d_k * a_sol)
    return a * _red_taper(wl)


def _gaussians(bands, wl: np.ndarray) -> np.ndarray:
    return sum(peak * np.exp(-((wl - centre) ** 2) / (2.0 * sigma**2)) for centre, sigma, peak in bands)


def _red_taper(wl: np.ndarray) -> np.ndarray:
    lo, hi = APH_TAPER_NM
    t = np.clip((wl - lo) / (hi - lo), 0.0, 1.0)
    return 0.5 * (1.0 + np.cos(np.pi * t))


#: Bricaud et al. (1998) a_φ = A_φ Chl^E_φ table in ``spectra/`` (400-700 nm, 2 nm; see its header).
BRICAUD1998_TABLE = "aph_bricaud1998.csv"
#: Wavelengths the Bricaud et al. (1998) table spans [nm].
BRICAUD1998_RANGE_NM = (400.0, 700.0)


@functools.lru_cache(maxsize=1)
def _bricaud1998_table():
    return read_spectral_table(BRICAUD1998_TABLE, required=("A_phi_m2_per_mg", "E_phi"), cover=BRICAUD1998_RANGE_NM)


def aph_Bricaud1998(wavelengths_nm, chlorophyll_mg_m3):
    """Phytoplankton absorption a_φ(λ) = A_φ(λ) Chl^E_φ(λ) [m⁻¹] (Bricaud et al. 1998).

    The power laws Bricaud et al. fitted to 1166 spectra of oceanic (case 1) waters, Chl
    0.02-25 mg m⁻³, 400-700 nm (their Eq. 2 and Table 2, ``spectra/aph_bricaud1998.csv``),
    linearly interpolated between the table's 2 nm steps. Outside 400-700 nm, where they
    published nothing, the spectral shape of :func:`aph_HoepffnerSathyendranath1991` at the
    same Chl continues the curve from its end values: a_φ(λ) = a_φ(400) s(λ)/s(400) below
    400 nm and a_φ(700) s(λ)/s(700) above 700 nm, s the Gaussian-band model (which ends at
    0 from 750 nm).

    Parameters
    ----------
    wavelengths_nm : array_like    Wavelengths [nm], 360-830.
    chlorophyll_mg_m3 : float      Chlorophyll a [mg m⁻³], ≥ 0 (fitted for 0.02-25).

    Returns
    -------
    ndarray    a_φ(λ) [m⁻¹].

    References
    ----------
    .. [1] Bricaud, A., Morel, A., Babin, M., Allali, K. & Claustre, H. (1998), "Variations of
       light absorption by suspended particles with chlorophyll a concentration in oceanic
       (case 1) waters: analysis and implications for bio-optical models", J. Geophys. Res.
       103(C13), 31033-31044, doi:10.1029/98JC02712.
    """
    wl = np.asarray(wavelengths_nm, dtype=float)
    chl = float(chlorophyll_mg_m3)
    if chl < 0:
        raise ValueError(f"chlorophyll_mg_m3: a concentration cannot be negative, got {chl!r}")
    if chl == 0:
        return np.zeros_like(wl)
    table = _bricaud1998_table()
    lo, hi = BRICAUD1998_RANGE_NM

    def power_law(x):
        return table.at("A_phi_m2_per_mg", x) * chl ** table.at("E_phi", x)  # [1] Eq. 2

    inside = np.clip(wl, lo, hi)
    a = power_law(inside)
    if np.any((wl < lo) | (wl > hi)):
        shape = aph_HoepffnerSathyendranath1991(wl, chl)
        ends = aph_HoepffnerSathyendranath1991(np.array([lo, hi]), chl)
        a = np.where(wl < lo, a * shape / ends[0], np.where(wl > hi, a * shape / ends[1], a))
    return a


def phytoplankton_absorption(model: str, wavelengths_nm, chlorophyll_mg_m3) -> np.ndarray:
    """a_φ(λ) [m⁻¹] of the named model (:data:`PHYTOPLANKTON_ABSORPTION_MODELS`) at Chl [mg m⁻³]."""
    if model == "Bricaud 1998":
        return aph_Bricaud1998(wavelengths_nm, chlorophyll_mg_m3)
    if model == "Hoepffner-Sathyendranath 1991":
        return aph_HoepffnerSathyendranath1991(wavelengths_nm, chlorophyll_mg_m3)
    raise ValueError(f"phytoplankton_absorption: expected one of {', '.join(PHYTOPLANKTON_ABSORPTION_MODELS)}, "
                     f"got {model!r}")


def bp_LoiselMorel1998(wavelengths_nm, chlorophyll_mg_m3):
    """Particle scattering of Case 1 waters b_p(λ) [m⁻¹].

    b_p(660) = 0.347 Chl^0.766 with a λ⁻¹ spectral shape: b_p(λ) = b_p(660) (660/λ).

    Parameters
    ----------
    wavelengths_nm : array_like    Wavelengths [nm].
    chlorophyll_mg_m3 : float      Chlorophyll a [mg m⁻³].

    References
    ----------
    .. [1] Loisel, H. & Morel, A. (1998), "Light scattering and chlorophyll concentration
       in case 1 waters: a reexamination", Limnol. Oceanogr. 43, 847-858.
    """
    wl = np.asarray(wavelengths_nm, dtype=float)
    return 0.347 * float(chlorophyll_mg_m3) ** 0.766 * (660.0 / wl)  # [1]: b_p(660) = 0.347 Chl^0.766, λ⁻¹ shape


def ag_BricaudMorelPrieur1981(wavelengths_nm, a440_per_m, slope_per_nm=0.014):
    """CDOM absorption a_g(λ) = a_g(440) exp(−S (λ − 440)) [m⁻¹].

    Parameters
    ----------
    wavelengths_nm : array_like    Wavelengths [nm].
    a440_per_m : float             a_g(440) [m⁻¹].
    slope_per_nm : float           Spectral slope S [nm⁻¹] (0.014 typical, [1]).

    References
    ----------
    .. [1] Bricaud, A., Morel, A. & Prieur, L. (1981), "Absorption by dissolved organic
       matter of the sea (yellow substance) in the UV and visible domains",
       Limnol. Oceanogr. 26, 43-53.
    """
    wl = np.asarray(wavelengths_nm, dtype=float)
    return a440_per_m * np.exp(-slope_per_nm * (wl - 440.0))  # [1]


# ----------------------------------------------------------------------------
# Phase functions
# ----------------------------------------------------------------------------

def henyey_greenstein_bb_ratio(g):
    """Backscattered fraction of a Henyey-Greenstein phase function [-].

    B(g) = (1 − g)/(2g) [(1 + g)/√(1 + g²) − 1]  (integral of HG over θ > 90°).

    References
    ----------
    .. [1] Henyey, L. G. & Greenstein, J. L. (1941), Astrophys. J. 93, 70-83.
    """
    g = np.asarray(g, dtype=float)
    gs = np.where(np.abs(g) < 1e-6, 1e-6, g)
    return (1.0 - gs) / (2.0 * gs) * ((1.0 + gs) / np.sqrt(1.0 + gs**2) - 1.0)


def henyey_greenstein_g_from_bb_ratio(bb_ratio):
    """Asymmetry g of the Henyey-Greenstein phase function with backscattered fraction b_b/b [-].

    Inverts :func:`henyey_greenstein_bb_ratio` (monotonic) by bisection; b_b/b in (0, 0.5].
    """
    b = np.asarray(bb_ratio, dtype=float)
    if np.any(~np.isfinite(b)) or np.any((b <= 0) | (b > 0.5)):
        raise ValueError("bb_ratio: need 0 < b_b/b <= 0.5")
    lo, hi = np.zeros_like(b), np.full_like(b, 1.0 - 1e-12)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        too_forward = henyey_greenstein_bb_ratio(mid) < b
        hi = np.where(too_forward, mid, hi)
        lo = np.where(too_forward, lo, mid)
    return 0.5 * (lo + hi)


def _ff_delta(theta_rad, n):
    return 4.0 / (3.0 * (n - 1.0) ** 2) * np.sin(theta_rad / 2.0) ** 2


def fournier_forand_bb_ratio(n, mu):
    """Backscattered fraction of the Fournier-Forand phase function [-].

    B = 1 − [1 − δ90^(ν+1) − 0.5 (1 − δ90^ν)] / [(1 − δ90) δ90^ν],
    ν = (3 − μ)/2, δ90 = 4 sin²(45°) / (3 (n − 1)²).

    References
    ----------
    .. [1] Fournier, G. R. & Jonasz, M. (1999), "Computer-based underwater imaging
       analysis", Proc. SPIE 3761, 62-70.
    .. [2] Mobley, C. D., Sundman, L. K. & Boss, E. (2002), "Phase function effects
       on oceanic light fields", Appl. Opt. 41, 1035-1050.
    """
    nu = (3.0 - np.asarray(mu, dtype=float)) / 2.0
    d90 = _ff_delta(np.pi / 2.0, np.asarray(n, dtype=float))
    return 1.0 - (1.0 - d90 ** (nu + 1.0) - 0.5 * (1.0 - d90**nu)) / ((1.0 - d90) * d90**nu)


def fournier_forand_from_bb_ratio(bb_ratio):
    """Fournier-Forand parameters (n, μ) with backscattered fraction b_b/b.

    Follows Mobley et al. (2002): n and the Junge slope μ move together along
    n = 1.01 + 0.1542 (μ − 3), and μ is solved for so that B(n, μ) = b_b/b.
    Valid for b_b/b in about 0.0003-0.3 (μ in 3.0005-5).

    Returns
    -------
    n, mu : ndarray   Real relative index [-] and Junge slope [-].
    """
    b = np.asarray(bb_ratio, dtype=float)
    line = lambda mu: 1.01 + 0.1542 * (mu - 3.0)  # noqa: E731  (Mobley et al. 2002, Sec. 2)
    lo_mu, hi_mu = 3.0005, 5.0
    b_min, b_max = fournier_forand_bb_ratio(line(lo_mu), lo_mu), fournier_forand_bb_ratio(line(hi_mu), hi_mu)
    if np.any(~np.isfinite(b)) or np.any((b < b_min) | (b > b_max)):
        raise ValueError(f"bb_ratio: Fournier-Forand fit needs {b_min:.2g} <= b_b/b <= {b_max:.2g}")
    lo, hi = np.full_like(b, lo_mu), np.full_like(b, hi_mu)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        low_b = fournier_forand_bb_ratio(line(mid), mid) < b
        lo = np.where(low_b, mid, lo)
        hi = np.where(low_b, hi, mid)
    mu = 0.5 * (lo + hi)
    return line(mu), mu


def fournier_forand_phase_function(angles_deg, n, mu):
    """Fournier-Forand phase function p(θ) [sr⁻¹], 2π ∫ p dcosθ = 1 (Mobley et al. 2002, Sec. 2).

    ``n`` and ``mu`` broadcast against each other; the angle axis is last.
    """
    # NOTE: p diverges (integrably, as θ^(μ−5)) at θ = 0; θ below 1e-9 rad is evaluated at 1e-9 rad.
    theta = np.maximum(np.radians(np.asarray(angles_deg, dtype=float)), 1e-9)
    n = np.asarray(n, dtype=float)[..., None]
    nu = (3.0 - np.asarray(mu, dtype=float)[..., None]) / 2.0
    d = _ff_delta(theta, n)
    d180 = _ff_delta(np.pi, n)
    s2 = np.sin(theta / 2.0) ** 2
    first = (nu * (1 - d) - (1 - d**nu) + (d * (1 - d**nu) - nu * (1 - d)) / s2) / (4 * np.pi * (1 - d) ** 2 * d**nu)
    second = (1 - d180**nu) / (16 * np.pi * (d180 - 1) * d180**nu) * (3 * np.cos(theta) ** 2 - 1)
    return first + second


def pure_water_phase_function(angles_deg):
    """Phase function of pure (sea) water p(θ) = 3 (1 + 0.835 cos²θ) / (4π (3 + 0.835)) [sr⁻¹].

    References
    ----------
    .. [1] Morel, A. (1974), in Optical Aspects of Oceanography, Academic Press, 1-24.
    """
    c = np.cos(np.radians(np.asarray(angles_deg, dtype=float)))
    return 3.0 * (1.0 + WATER_ANISOTROPY * c**2) / (4.0 * np.pi * (3.0 + WATER_ANISOTROPY))


def mixture_phase_function(iops: CompositionIOPs, angles_deg, particle_phase: str = "Fournier-Forand") -> np.ndarray:
    """Phase function of the mixture p(λ, θ) [sr⁻¹], shape (n_λ, n_θ).

    p = [b_w p_w + Σ_k b_k p_FF(θ; b_b,k / b_k)] / b: pure water's phase
    function plus one Fournier-Forand phase function per scattering particle
    component, fitted to that component's backscattering ratio; with
    ``particle_phase = "Petzold"`` every particle component scatters as
    :func:`petzold_particle_phase`.
    """
    angles = np.asarray(angles_deg, dtype=float)
    total = np.zeros((iops.wavelengths.size, angles.size))
    for name, comp in iops.components.items():
        if not np.any(comp.scattering > 0):
            continue
        if name == "water":
            total += comp.scattering[:, None] * pure_water_phase_function(angles)[None, :]
            continue
        if particle_phase == "Petzold":
            total += comp.scattering[:, None] * petzold_particle_phase(angles)[None, :]
            continue
        n, mu = fournier_forand_from_bb_ratio(comp.backscattering_ratio)
        total += comp.scattering[:, None] * fournier_forand_phase_function(angles, n, mu)
    return total / iops.scattering[:, None]


# ----------------------------------------------------------------------------
# Composition → IOPs
# ----------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def _mineral_table(name: str):
    return read_spectral_table(MINERAL_TABLES[name], required=("a_star_m2_per_g", "b_star_m2_per_g", "bb_star_m2_per_g"))


@functools.lru_cache(maxsize=1)
def _water_table():
    return pure_seawater_iops()


def mineral_mass_specific_iops(name: str, wavelengths_nm) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """a*, b*, b_b* [m² g⁻¹] of mineral ``name`` from its table in ``spectra/``."""
    if name not in MINERAL_TABLES:
        raise KeyError(f"unknown mineral {name!r}; known: {', '.join(MINERAL_TABLES)}")
    table = _mineral_table(name)
    wl = np.asarray(wavelengths_nm, dtype=float)
    return tuple(table.at(col, wl) for col in ("a_star_m2_per_g", "b_star_m2_per_g", "bb_star_m2_per_g"))


def composition_iops(composition: WaterComposition, wavelengths_nm) -> CompositionIOPs:
    """Spectral IOPs [m⁻¹] of ``composition`` at ``wavelengths_nm`` (within 360-830 nm).

    Parameters
    ----------
    composition : WaterComposition   What the water holds.
    wavelengths_nm : array_like      Wavelengths [nm], inside 360-830 nm.

    Returns
    -------
    CompositionIOPs   a, b, b_b per component and in total [m⁻¹].
    """
    if not isinstance(composition, WaterComposition):
        raise TypeError(f"composition: expected a WaterComposition, got {type(composition).__name__}")
    wl = np.atleast_1d(np.asarray(wavelengths_nm, dtype=float))
    lo, hi = VISIBLE_RANGE_NM
    if wl.size == 0 or not np.all(np.isfinite(wl)) or wl.min() < lo or wl.max() > hi:
        raise SpectralDataError(f"wavelengths_nm: must lie within {lo:g}-{hi:g} nm, the range of the IOP data "
                                f"(got {np.nanmin(wl) if wl.size else 'none'}-{np.nanmax(wl) if wl.size else 'none'} nm); "
                                "no extrapolation")
    c = composition
    water = _water_table()
    salinity_factor = seawater_scattering_salinity_factor(c.salinity_psu, TABLE_SALINITY_PSU)  # Morel 1974
    b_w = np.interp(wl, water.wavelengths, water.scattering) * salinity_factor
    zero = np.zeros_like(wl)
    parts = {
        "water": ComponentIOPs(aw_WOPP3(wl, c.temperature_c, c.salinity_psu), b_w, 0.5 * b_w),
    }
    b_ph = bp_LoiselMorel1998(wl, c.chlorophyll_mg_m3)
    a_ph = phytoplankton_absorption(c.phytoplankton_absorption, wl, c.chlorophyll_mg_m3)
    parts["phytoplankton"] = ComponentIOPs(a_ph, b_ph, PHYTOPLANKTON_BB_RATIO * b_ph)
    parts["cdom"] = ComponentIOPs(ag_BricaudMorelPrieur1981(wl, c.cdom_a440_per_m, c.cdom_slope_per_nm), zero, zero)
    for name in MINERAL_TABLES:
        conc = getattr(c, f"{name}_g_m3")
        a_s, b_s, bb_s = mineral_mass_specific_iops(name, wl)
        parts[name] = ComponentIOPs(conc * a_s, conc * b_s, conc * bb_s)
    notes = (
        f"pure-water absorption a_w at {c.temperature_c:g} degC and {c.salinity_psu:g} PSU (WOPP v3, linear Psi_T, Psi_S)",
        f"phytoplankton absorption: {c.phytoplankton_absorption}"
        + (" (400-700 nm; outside, the Gaussian-band model's shape joined to its ends)"
           if c.phytoplankton_absorption == "Bricaud 1998" else "")
        + "; tapered to 0 between 700 and 750 nm",
    )
    return CompositionIOPs(wavelengths=wl, composition=c, components=MappingProxyType(parts), notes=notes)


# ----------------------------------------------------------------------------
# Presets
# ----------------------------------------------------------------------------

PRESETS = MappingProxyType({
    # Oligotrophic subtropical gyre: Chl ≈ 0.05 mg m⁻³ (surface Chl of the gyres is 0.02-0.1 mg m⁻³;
    # the clearest, South Pacific gyre, ≈ 0.02-0.03: Morel et al. 2007, Limnol. Oceanogr. 52:217);
    # CDOM a_g(440) ≈ 0.005 m⁻¹ (of order 1e-3 to 1e-2 m⁻¹ there, same source); no terrigenous minerals.
    "clear open ocean": WaterComposition(temperature_c=22.0, salinity_psu=36.0, chlorophyll_mg_m3=0.05,
                                         cdom_a440_per_m=0.005),
    # Productive shelf water: Chl ≈ 2 mg m⁻³; SPM ≈ 1.5 g m⁻³ with a clay-dominated mineral part
    # (COASTLOOC North Sea / English Channel stations: SPM 0.5-5 g m⁻³, Babin et al. 2003, JGR
    # 108:3211); a_g(440) ≈ 0.1 m⁻¹, S = 0.0176 nm⁻¹ (Babin et al. 2003 mean CDOM slope).
    "green coastal": WaterComposition(temperature_c=15.0, salinity_psu=33.0, chlorophyll_mg_m3=2.0,
                                      illite_g_m3=0.6, kaolinite_g_m3=0.3, soil_g_m3=0.2, calcite_g_m3=0.2,
                                      cdom_a440_per_m=0.1, cdom_slope_per_nm=0.0176),
    # River-influenced turbid estuary: SPM ≈ 30 g m⁻³ of iron-oxide-bearing soil and clays (turbidity
    # maxima of macrotidal estuaries such as the Gironde hold tens to thousands of g m⁻³; Doxaran et al.
    # 2009, Estuar. Coast. Shelf Sci. 81:321); Chl 5 mg m⁻³; a_g(440) ≈ 1 m⁻¹, typical of river plumes
    # (an assumption of this preset); brackish 15 PSU.
    "turbid brown estuary": WaterComposition(temperature_c=18.0, salinity_psu=15.0, chlorophyll_mg_m3=5.0,
                                             soil_g_m3=12.0, illite_g_m3=10.0, kaolinite_g_m3=6.0, calcite_g_m3=2.0,
                                             cdom_a440_per_m=1.0, cdom_slope_per_nm=0.0176),
})


def preset(name: str) -> WaterComposition:
    """The preset ``name``; refuses unknown names with the list of known ones."""
    try:
        return PRESETS[name]
    except KeyError:
        raise KeyError(f"unknown water preset {name!r}; known: {', '.join(PRESETS)}") from None


PARTICLE_PHASES = ("Henyey-Greenstein", "Fournier-Forand", "Petzold")
"""Particle phase functions of :func:`composition_optics` (the first is the default)."""

#: Scattering angles of the tabulated phase functions [deg]: 0, then 1e-5° to 180° log-spaced
#: (the Fournier–Forand peak grows as θ^(μ−5) towards 0; its value at 0 is taken at 1e-5°).
TABLE_ANGLES_DEG = np.concatenate([[0.0], np.geomspace(1e-5, 180.0, 1200)])


def _tabulate(phase_of_angles) -> tuple[np.ndarray, np.ndarray]:
    """(μ ascending from −1 to 1, p (..., M) [sr⁻¹]) of ``phase_of_angles(θ [deg])`` on :data:`TABLE_ANGLES_DEG`."""
    angles = TABLE_ANGLES_DEG.copy()
    angles[-1] = 180.0
    values = np.array(phase_of_angles(angles), dtype=float)
    values[..., 0] = values[..., 1]  # θ = 0: the value at the smallest tabulated angle (the peak is integrable)
    mu = np.cos(np.radians(angles))[::-1]
    mu[0], mu[-1] = -1.0, 1.0
    return mu, values[..., ::-1]


def tabulated_mixture_phase(iops: CompositionIOPs, particle_phase: str = "Fournier-Forand"
                            ) -> tuple[np.ndarray, np.ndarray]:
    """(μ ascending from −1 to 1, p (n_λ, M) [sr⁻¹]) of :func:`mixture_phase_function` on :data:`TABLE_ANGLES_DEG`."""
    return _tabulate(lambda angles: mixture_phase_function(iops, angles, particle_phase))


#: Petzold's (1972) three San Diego Harbor stations, whose mean is the "average particle" phase function.
PETZOLD_HARBOR_STATIONS = ("NUC 2200", "NUC 2240", "NUC 2040")


@functools.lru_cache(maxsize=1)
def _petzold_harbor_table() -> tuple[np.ndarray, np.ndarray]:
    """(θ [deg] from 1e-5 to 180, mean normalised phase function [sr⁻¹]) of :data:`PETZOLD_HARBOR_STATIONS`."""
    import jerlov  # noqa: PLC0415

    angles = TABLE_ANGLES_DEG[1:].copy()
    angles[-1] = 180.0
    mean = np.zeros(angles.size)
    for station in PETZOLD_HARBOR_STATIONS:
        vsf = jerlov.petzold_scattering(station)
        log_t, log_v = np.log(vsf.angles_deg), np.log(vsf.vsf)
        # below the first tabulated angle (0.1°) the report's own power-law extension: the log-log slope
        # of its first two values, integrable (−1.2 to −1.4 > −2)
        slope = (log_v[1] - log_v[0]) / (log_t[1] - log_t[0])
        beta = np.where(angles >= vsf.angles_deg[0], np.exp(np.interp(np.log(angles), log_t, log_v)),
                        vsf.vsf[0] * (angles / vsf.angles_deg[0]) ** slope)
        mu = np.cos(np.radians(angles))
        total = -2.0 * np.pi * np.trapezoid(beta, mu)  # b of the curve as tabulated here [m⁻¹]
        mean += beta / total / len(PETZOLD_HARBOR_STATIONS)
    return angles, mean


def petzold_particle_phase(angles_deg) -> np.ndarray:
    """Petzold's (1972) San Diego Harbor phase function p(θ) [sr⁻¹], the mean of three stations.

    Each station's measured volume scattering function (530 nm; the ``jerlov`` package's
    transcription) is extended below 0.1° by the power law of its first two values, normalised
    so that 2π ∫ p dcosθ = 1 on :data:`TABLE_ANGLES_DEG`, and the three are averaged: the
    "average particle" phase function of Mobley et al. (1993) and Mobley (1994, Table 3.10),
    used for particles at every wavelength (b_b/b = 0.019, not the composition's b_bp/b_p).
    Log-log interpolation between the report's 55 angles.

    References
    ----------
    .. [1] Petzold, T. J. (1972). Volume scattering functions for selected ocean waters.
       SIO Ref. 72-78, Scripps Institution of Oceanography.
    .. [2] Mobley, C. D. et al. (1993). Comparison of numerical models for computing underwater
       light fields. *Appl. Opt.* 32(36), 7484–7504. doi:10.1364/AO.32.007484
    """
    table_angles, table = _petzold_harbor_table()
    a = np.clip(np.asarray(angles_deg, dtype=float), table_angles[0], 180.0)
    return np.exp(np.interp(np.log(a), np.log(table_angles), np.log(table)))


def tabulated_fournier_forand(bb_ratio: float) -> tuple[np.ndarray, np.ndarray]:
    """(μ ascending from −1 to 1, p (M,) [sr⁻¹]) of the Fournier–Forand function with backscattered fraction b_b/b.

    Mobley et al. (2002) parameters (:func:`fournier_forand_from_bb_ratio`) on :data:`TABLE_ANGLES_DEG`.
    """
    n, mu = fournier_forand_from_bb_ratio(bb_ratio)
    return _tabulate(lambda angles: fournier_forand_phase_function(angles, n, mu))


def composition_optics(composition, wavelengths: np.ndarray | None = None,
                       particle_phase: str = PARTICLE_PHASES[0]) -> MediumOptics:
    """IOPs and phase model of a :class:`WaterComposition`.

    The phase function is a blend of the water's Rayleigh shape and one
    Henyey–Greenstein lobe for all particles, weighted by b_p(λ)/b(λ), with g(λ)
    fitted to the particles' b_bp(λ)/b_p(λ) at every wavelength (the
    ``*_spectrum`` fields, rendered by :mod:`oceanrender.render.phase`), so that the
    medium's b_b/b equals the composition's at every wavelength (issue 19). The
    scalar ``particle_fraction`` and ``particle_g`` are the 550 nm values (for the
    four-flux model and the LUTs). ``particle_phase = "Fournier-Forand"`` tabulates the
    mixture of water and one Fournier–Forand function per particle component, each with
    that component's b_b/b (Mobley et al. 2002), instead (``phase_table``); ``"Petzold"``
    tabulates water plus Petzold's measured San Diego Harbor function for all particles
    (:func:`petzold_particle_phase`; its own b_b/b).
    """
    if particle_phase not in PARTICLE_PHASES:
        raise ValueError(f"particle_phase must be one of {list(PARTICLE_PHASES)}, got {particle_phase!r}")
    wavelengths = np.arange(360.0, 831.0, 5.0) if wavelengths is None else np.asarray(wavelengths, float)
    result = composition_iops(composition, wavelengths)
    water = result.components["water"]
    b_total = np.interp(550.0, wavelengths, result.scattering)
    b_particles = b_total - np.interp(550.0, wavelengths, water.scattering)
    bb_particles = np.interp(550.0, wavelengths, result.backscattering - water.backscattering)
    fraction = float(np.clip(b_particles / b_total, 0.0, 1.0)) if b_total > 0 else 0.0
    g = float(henyey_greenstein_g_from_bb_ratio(bb_particles / b_particles)) if b_particles > 0 else 0.0
    fraction_spectrum, g_spectrum = _particle_phase_spectra(result.scattering, water.scattering,
                                                            result.backscattering - water.backscattering)
    iops = WaterIOPs(wavelengths=wavelengths, absorption=result.absorption, scattering=result.scattering,
                     source="composition: " + "; ".join(result.notes) if getattr(result, "notes", None) else "composition")
    table = None if particle_phase == "Henyey-Greenstein" else tabulated_mixture_phase(result, particle_phase)
    return MediumOptics(iops=iops, particle_fraction=fraction, particle_g=g,
                        particle_fraction_spectrum=fraction_spectrum, particle_g_spectrum=g_spectrum,
                        phase_table=table)


def _particle_phase_spectra(b, b_water, bb_particles):
    """(b_p/b, HG g of b_bp/b_p) per wavelength [-]; g = 0 where there are no particles.

    b, b_water [m⁻¹]: total and water scattering; bb_particles [m⁻¹]: the particles'
    backscattering. b_bp/b_p is clipped into HG's range (0, 0.5].
    """
    b_p = np.maximum(b - b_water, 0.0)
    fraction = np.clip(np.divide(b_p, b, out=np.zeros_like(b), where=b > 0), 0.0, 1.0)
    has = b_p > 0
    ratio = np.clip(np.divide(bb_particles, b_p, out=np.full_like(b, 0.5), where=has), 1e-9, 0.5)
    g = np.where(has, henyey_greenstein_g_from_bb_ratio(ratio), 0.0)
    return fraction, g


def _rayleigh_phase(angles_deg):
    """Rayleigh p(θ) = 3 (1 + cos²θ)/(16π) [sr⁻¹], the shape Mitsuba's ``rayleigh`` and the HG blend use."""
    c = np.cos(np.radians(np.asarray(angles_deg, dtype=float)))
    return 3.0 * (1.0 + c * c) / (16.0 * np.pi)


def _henyey_greenstein(angles_deg, g):
    """HG p(θ; g) = (1 − g²)/(4π (1 + g² − 2g cos θ)^{3/2}) [sr⁻¹] (Henyey & Greenstein 1941); g (...) broadcasts."""
    c = np.cos(np.radians(np.asarray(angles_deg, dtype=float)))
    g = np.asarray(g, dtype=float)[..., None]
    return (1.0 - g * g) / (4.0 * np.pi * (1.0 + g * g - 2.0 * g * c) ** 1.5)


def medium_phase_table(optics: WaterIOPs | MediumOptics, wavelengths_nm) -> tuple[np.ndarray, np.ndarray]:
    """The phase function the renderer gives the medium, tabulated: (μ (M,) from −1 to 1 [-], p (W, M) [sr⁻¹]).

    Pure water (:class:`WaterIOPs`): Mitsuba's ``rayleigh``. A :class:`MediumOptics`:
    its ``phase_table`` (the row of the nearest table wavelength, as
    :data:`oceanrender.render.phase.TABULATED_PLUGIN` looks it up), else the Rayleigh +
    HG blend with weight and g per wavelength (``oceanrender_water_phase``; the 550 nm
    values where no spectra are given, as Mitsuba's ``blendphase``). For the four-flux
    coefficients (:mod:`oceanrender.optics.streams`).
    """
    wl = np.atleast_1d(np.asarray(wavelengths_nm, dtype=float))
    if isinstance(optics, WaterIOPs):
        mu, p = _tabulate(_rayleigh_phase)
        return mu, np.broadcast_to(p, (wl.size, p.size)).copy()
    grid = optics.iops.wavelengths
    if optics.phase_table is not None:
        mu, table = optics.phase_table
        rows = np.clip(np.rint((wl - grid[0]) / (grid[1] - grid[0])).astype(int), 0, grid.size - 1)
        return np.asarray(mu, float), np.asarray(table, float)[rows]
    if optics.particle_fraction_spectrum is not None:
        w = np.interp(wl, grid, optics.particle_fraction_spectrum)
        g = np.interp(wl, grid, optics.particle_g_spectrum if optics.particle_g_spectrum is not None
                      else np.full(grid.size, optics.particle_g))
    else:
        w, g = np.full(wl.size, optics.particle_fraction), np.full(wl.size, optics.particle_g)
    return _tabulate(lambda angles: (1.0 - w[:, None]) * _rayleigh_phase(angles)[None, :]
                     + w[:, None] * _henyey_greenstein(angles, g))
