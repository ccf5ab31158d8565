"""Print the mean-square-slope table of docs/slope_budget.md.

Usage::

    .venv/bin/python scripts/slope_budget.py

For U₁₀ = 3, 5, 8, 10, 12 and 15 m s⁻¹ it integrates the slope spectrum k² Ψ of
each sea from k = 2π/(2560 m) to 2π/(1 mm), at a fetch of 50 km and fully
developed, for "JONSWAP 1973" with the Mitsuyasu (1975) spreading (the
package default) and for "Elfouhaily 1997", and prints them beside the
clean- and slick-surface fits of Cox & Munk (1954) as Markdown tables.
Everything it prints is computed here; nothing is read from files.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from oceanrender.waves.elfouhaily import (
    VON_KARMAN,
    friction_velocity_Elfouhaily1997,
    inverse_wave_age_Elfouhaily1997,
    mean_square_slope_Elfouhaily1997,
    peak_wavenumber_Elfouhaily1997,
    phase_speed_Elfouhaily1997,
)
from oceanrender.waves.wave_spectra import (
    GRAVITY,
    PIERSON_MOSKOWITZ_WIND_RATIO,
    DirectionalSpectrum,
    peak_frequency_PiersonMoskowitz1964,
)

WIND_SPEEDS = (3.0, 5.0, 8.0, 10.0, 12.0, 15.0)
"""Wind speeds U₁₀ of the table [m s⁻¹]."""

K_MIN = 2 * math.pi / 2560.0
"""Longest wave 2560 m [rad m⁻¹]."""

K_MAX = 2 * math.pi / 1e-3
"""Shortest wave 1 mm [rad m⁻¹]."""

FETCH = 50e3
"""Fetch of the fetch-limited columns [m]."""

ANEMOMETER_HEIGHT = 12.5
"""Height of Cox & Munk's wind measurements, 41 ft [m]."""

#: Cox & Munk (1954) regressions σ² = a + b W ± rms scatter, W [m s⁻¹] at 12.5 m:
#: (a, b, scatter) of the upwind, crosswind and total mean-square slope.
COX_MUNK_1954 = {
    "clean": {"upwind": (0.000, 3.16e-3, 0.004), "crosswind": (0.003, 1.92e-3, 0.002),
              "total": (0.003, 5.12e-3, 0.004)},
    "slick": {"upwind": (0.005, 0.78e-3, 0.002), "crosswind": (0.003, 0.84e-3, 0.002),
              "total": (0.008, 1.56e-3, 0.004)},
}


def cox_munk(wind_speed_12_5: float, surface: str, component: str) -> float:
    """Cox & Munk's (1954) fitted mean-square slope a + b W [-] at W = U(12.5 m) [m s⁻¹]."""
    a, b, _ = COX_MUNK_1954[surface][component]
    return a + b * wind_speed_12_5


def anemometer_wind(wind_speed_10: float, fetch: float) -> float:
    """U(12.5 m) = U₁₀ + (u*/κ) ln(12.5/10) on the log profile of the Elfouhaily sea [m s⁻¹]."""
    omega_c = inverse_wave_age_Elfouhaily1997(wind_speed_10, fetch, GRAVITY)
    c_p = phase_speed_Elfouhaily1997(peak_wavenumber_Elfouhaily1997(wind_speed_10, omega_c, GRAVITY), GRAVITY)
    u_star = friction_velocity_Elfouhaily1997(wind_speed_10, wind_speed_10 / c_p, GRAVITY)
    return float(wind_speed_10 + u_star / VON_KARMAN * math.log(ANEMOMETER_HEIGHT / 10.0))


def jonswap_full_fetch(wind_speed_10: float) -> float:
    """Fetch at which the JONSWAP peak reaches the Pierson–Moskowitz peak, x = g F/U₁₀² ≈ 1.7e4 [m]."""
    omega_pm = peak_frequency_PiersonMoskowitz1964(PIERSON_MOSKOWITZ_WIND_RATIO * wind_speed_10, g=GRAVITY)
    x_full = (22.0 / (float(omega_pm) * wind_speed_10 / GRAVITY)) ** 3  # ω_p U/g = 22 x^{-1/3}
    return x_full * wind_speed_10**2 / GRAVITY


def slope_components(spectrum, k_min: float, k_max: float, radial: int = 4097, angular: int = 720):
    """(⟨s_x²⟩, ⟨s_y²⟩) = ∫∫ (kx², ky²) Ψ dkx dky on a polar grid, wind along +x [-]."""
    ln_k = np.linspace(math.log(k_min), math.log(k_max), radial)
    theta = np.linspace(0.0, 2 * math.pi, angular, endpoint=False)
    k = np.exp(ln_k)[:, None]
    psi = spectrum(k * np.cos(theta), k * np.sin(theta))
    weight = 2 * math.pi / angular * k[:, 0] ** 4  # k² · k² d(ln k) dθ
    upwind = np.trapezoid((psi * np.cos(theta) ** 2).sum(axis=1) * weight, ln_k)
    crosswind = np.trapezoid((psi * np.sin(theta) ** 2).sum(axis=1) * weight, ln_k)
    return float(upwind), float(crosswind)


def budget() -> list[dict[str, float]]:
    """One row of mean-square slopes per wind speed [-]."""
    rows = []
    for U in WIND_SPEEDS:
        row = {"U10": U}
        for label, jonswap_fetch, elfouhaily_fetch in (("50 km", FETCH, FETCH),
                                                      ("full", jonswap_full_fetch(U), math.inf)):
            jonswap = DirectionalSpectrum("JONSWAP 1973", spreading="Mitsuyasu 1975", wind_speed=U,
                                          fetch=jonswap_fetch, g=GRAVITY)
            row[f"JONSWAP {label}"] = sum(slope_components(jonswap, K_MIN, K_MAX))
            slopes = mean_square_slope_Elfouhaily1997(U, elfouhaily_fetch, K_MIN, K_MAX, g=GRAVITY)
            row[f"Elfouhaily {label}"] = float(slopes.total)
            row[f"Elfouhaily {label} upwind"] = float(slopes.upwind)
            row[f"Elfouhaily {label} crosswind"] = float(slopes.crosswind)
        W = anemometer_wind(U, math.inf)
        row["W"] = W
        for surface in COX_MUNK_1954:
            for component in ("upwind", "crosswind", "total"):
                row[f"CM {surface} {component}"] = cox_munk(W, surface, component)
        rows.append(row)
    return rows


def markdown(rows: list[dict[str, float]]) -> str:
    """The two tables of docs/slope_budget.md."""
    lines = [
        "| U₁₀ [m/s] | JONSWAP 1973, 50 km | JONSWAP 1973, fully developed | Elfouhaily 1997, 50 km "
        "| Elfouhaily 1997, fully developed | Cox & Munk clean | Cox & Munk slick |",
        "|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(
            f"| {r['U10']:.0f} | {r['JONSWAP 50 km']:.4f} | {r['JONSWAP full']:.4f} | {r['Elfouhaily 50 km']:.4f} "
            f"| {r['Elfouhaily full']:.4f} | {r['CM clean total']:.4f} ± 0.004 | {r['CM slick total']:.4f} ± 0.004 |"
        )
    lines += [
        "",
        "| U₁₀ [m/s] | W(12.5 m) [m/s] | Elfouhaily upwind, 50 km / full | Cox & Munk clean upwind "
        "| Elfouhaily crosswind, 50 km / full | Cox & Munk clean crosswind |",
        "|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(
            f"| {r['U10']:.0f} | {r['W']:.2f} | {r['Elfouhaily 50 km upwind']:.4f} / {r['Elfouhaily full upwind']:.4f} "
            f"| {r['CM clean upwind']:.4f} ± 0.004 | {r['Elfouhaily 50 km crosswind']:.4f} / "
            f"{r['Elfouhaily full crosswind']:.4f} | {r['CM clean crosswind']:.4f} ± 0.002 |"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    """Parse (no options), compute, print."""
    argparse.ArgumentParser(description=__doc__.splitlines()[0]).parse_args(argv)
    print(markdown(budget()))


if __name__ == "__main__":
    main()
