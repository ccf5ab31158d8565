"""Inherent optical properties (IOPs) of the water body.

Issue-2 scope: pure sea water only (absorption a_w and scattering b_sw from
``spectra/pure_seawater.csv``). Coefficients in m⁻¹, wavelengths in nm.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .tables import SpectralDataError, read_spectral_table


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


def pure_seawater_iops(table: str = "pure_seawater.csv") -> WaterIOPs:
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
