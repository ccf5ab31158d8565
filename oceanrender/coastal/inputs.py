"""Boundary inputs of a coastal simulation from the scene: incident waves and side conditions.

Pure functions of :class:`~oceanrender.scene.settings.CoastalSettings` (and the
[ocean] spectrum for spectral waves). The arrays a coastal scene names or
defines — bathymetry, initial surface, rock cover — are read, built and checked
in :mod:`oceanrender.scene.arrays` when the scene is loaded, before any work.

Conventions: arrays (ny, nx), rows south → north, columns west → east; cell
(j, i) centred at origin + ((i + ½) dx, (j + ½) dy); lengths in m.
"""

from __future__ import annotations

import numpy as np

from .boundaries import Boundaries, IncidentWave, Transmissive, Wall

_SIDE_NORMAL_IN = {"north": -np.pi / 2, "south": np.pi / 2, "east": np.pi, "west": 0.0}


def incident_waves(coastal, ocean=None, g: float = 9.81) -> IncidentWave:
    """The waves entering through ``offshore_side`` [m, s, rad], in the grid's frame.

    'train': one linear wave of height ``wave_height`` (amplitude H/2) and period
    ``wave_period`` travelling along ``wave_direction``. 'spectrum': ``wave_count``
    components drawn from the [ocean] directional spectrum Ψ(k) [m⁴] with
    amplitudes √(2 Ψ Δk²) (as the sum-of-sines sea), keeping those that travel
    into the domain; ω from the linear dispersion relation at the offshore
    depth. 'open sea': the long waves of the scene's FFT sea itself, its exact
    modes up to :func:`~.embedding.long_wave_cutoff` that travel into the
    domain, with the sea's phases at the sea's time (t = τ − spinup).
    'none': an absorbing side at the still level. A smooth start over two
    periods (or 5 s) avoids a shock at t = 0. Directions in the scene are
    world directions; with a ``rotation`` θ the solver sees them θ less.

    Parameters
    ----------
    coastal : CoastalSettings
    ocean : OceanSettings or None
        The scene's [ocean] section ('spectrum' and 'open sea').
    """
    if coastal.waves == "none":
        return IncidentWave.absorbing(coastal.still_level)
    if coastal.waves == "train":
        return IncidentWave.wave_train(coastal.wave_height / 2.0, coastal.wave_period,
                                       direction_deg=coastal.wave_direction - coastal.rotation,
                                       still_level=coastal.still_level, ramp_time=2.0 * coastal.wave_period)
    if ocean is None:
        raise ValueError(f"waves = {coastal.waves!r} needs the scene's [ocean] section")
    if coastal.waves == "open sea":
        from ..waves.sea import SeaSurface  # noqa: PLC0415
        from ..scene import arrays  # noqa: PLC0415
        from .embedding import domain_frame, incident_from_modes, long_wave_cutoff, sea_long_modes  # noqa: PLC0415

        depth = arrays.offshore_depth(coastal, arrays.bathymetry(coastal))
        modes = sea_long_modes(SeaSurface(ocean), long_wave_cutoff(coastal, depth))
        return incident_from_modes(modes, domain_frame(coastal), coastal.offshore_side, coastal.spinup,
                                   coastal.still_level)
    from ..waves.gerstner import wave_components_from_spectrum  # noqa: PLC0415
    from ..waves.sea import directional_spectrum  # noqa: PLC0415

    ocean_spectrum = directional_spectrum(ocean)
    dx, dy = coastal.spacing
    depth = coastal.offshore_depth
    # Band: from waves 4 domain sizes long to those 8 cells long (shorter ones are unresolved).
    k_min = 2.0 * np.pi / (4.0 * max(coastal.size))
    k_max = 2.0 * np.pi / (8.0 * max(dx, dy))
    components = wave_components_from_spectrum(ocean_spectrum, 4 * coastal.wave_count, coastal.seed, k_min, k_max)
    inward = _SIDE_NORMAL_IN[coastal.offshore_side]
    rotation = np.radians(coastal.rotation)
    kept = [c for c in components
            if np.cos(np.arctan2(c.wavenumber_y, c.wavenumber_x) - rotation - inward) > 0.2]
    kept = sorted(kept, key=lambda c: -c.amplitude)[: coastal.wave_count]
    if not kept:
        raise ValueError("the [ocean] spectrum has no waves travelling into the domain through the offshore side")
    k = np.array([np.hypot(c.wavenumber_x, c.wavenumber_y) for c in kept])
    omega = np.sqrt(g * k * np.tanh(k * depth))  # linear dispersion relation (e.g. Dean & Dalrymple 1991, Eq. 4.19)
    return IncidentWave.from_components(
        amplitudes=[c.amplitude for c in kept], omegas=omega,
        directions_rad=[np.arctan2(c.wavenumber_y, c.wavenumber_x) - rotation for c in kept],
        phases=[c.phase for c in kept], still_level=coastal.still_level, wavenumbers=k,
        ramp_time=5.0)


def boundaries(coastal, ocean=None) -> Boundaries:
    """Solver boundaries: incident waves on the offshore side, ``lateral`` beside it, a wall opposite."""
    opposite = {"north": "south", "south": "north", "east": "west", "west": "east"}[coastal.offshore_side]
    sides = {}
    for side in ("north", "south", "east", "west"):
        if side == coastal.offshore_side:
            sides[side] = incident_waves(coastal, ocean)
        elif side == opposite:
            sides[side] = Wall()
        else:
            sides[side] = Wall() if coastal.lateral == "wall" else Transmissive()
    return Boundaries(**sides)
