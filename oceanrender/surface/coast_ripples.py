"""The wind sea's short waves on an isolated coast's surface, shaded from fields (issue 41).

The shallow-water solver carries its own waves (the incident train, the bores) on cells of
side Δ_c; the scene's ``[ocean]`` wind sea reaches the coast's surface only as the roughness of
the waves its cells cannot carry, k > k_c = π/Δ_c (:func:`~.bodies.surface_roughness`). Drawn
as fields, that same band of the spectrum — Ψ(k) for |k| ≥ k_c, nothing below
(:class:`~oceanrender.waves.cascades.BandLimitedSpectrum`) — becomes resolved ripples wherever
a hit's footprint Δ resolves them, and the Beckmann α of the rest: resolved and unresolved slopes
of the band add up to the same roughness at every Δ (Bruneton, Neyret & Holzschuch 2010, Eq. 4),
so the surface's mean look is kept while the ripples — and the caustic network they focus on the
sand (:class:`~oceanrender.render.sun_beam.TerrainCaustics`) — appear.

They join the body's own surface as the open sea joins a coast inside it
(:class:`~.frame.JoinShading`, docs/pixel_detail.md): the slope at a hit is
s = s_body + τ_s (s_fields − s_sea) with s_sea = 0 (the body's mesh carries none of the band: the
sea's own normal is the vertical, its position the rest point on the still level), τ_s the depth
taper of :func:`~oceanrender.coastal.embedding.depth_taper` with the band's own H_rms (≈ 1 wherever
the water is deeper than a few millimetres), 0 where dry.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..coastal.embedding import depth_taper
from ..waves.cascades import BandLimitedSpectrum
from ..waves.sea import SeaSurface, directional_spectrum
from .frame import JoinShading, ShadingFields
from .open_sea import SHADING_SPACINGS, shading_cascades

__all__ = ["CoastRipples", "ripple_spectrum"]


def ripple_spectrum(spectrum, cell: float) -> BandLimitedSpectrum:
    """Ψ(kx, ky) [m⁴] of the waves a grid of cells ``cell`` [m] does not carry: |k| ≥ π/cell, zero below."""
    return BandLimitedSpectrum(spectrum, math.pi / float(cell), math.inf)


class CoastRipples:
    """The band of the wind sea finer than the solver's cells, as shading fields of the coast's surface.

    Parameters
    ----------
    scene : Scene       Its ``[ocean]`` (an FFT sea: the cascades, the spectrum) and ``[coastal]``.
    cell : float        The solver's finest cell Δ_c [m]: the band starts at k_c = π/Δ_c.
    origin : (x, y)     Rest position [m] of texture coordinate (0, 0): near the coast (float32's millimetres).
    """

    def __init__(self, scene, cell: float, origin: tuple[float, float]):
        self.scene = scene
        self.sea = SeaSurface(scene.ocean, spectrum=ripple_spectrum(directional_spectrum(scene.ocean), cell))
        self.origin = (float(origin[0]), float(origin[1]))
        #: Beckmann α [-] at :data:`SHADING_SPACINGS`: the band's slopes its fields leave out at each Δ
        self.alpha = np.sqrt(self.sea.unresolved_slope_variance(SHADING_SPACINGS))
        #: H_rms = √8 σ of the band [m] (Rayleigh), for the depth taper
        self.rms_height = math.sqrt(8.0 * max(float(self.sea.cascades.elevation_variance), 0.0))

    @property
    def resolves_any(self) -> bool:
        """Whether the cascades carry any of the band (their resolved slope variance > 0): else it is all roughness."""
        return float(np.sum(self.sea.resolved_variance(None)[1])) > 0.0

    def fields(self, t: float, positions: NDArray, top: int, depth: NDArray, wet: NDArray) -> ShadingFields:
        """The frame's :class:`~.frame.ShadingFields` at t [s] for a body of ``positions`` [m] whose first
        ``top`` vertices are its surface, at still depths ``depth`` [m], ``wet`` where the solver has water."""
        count = len(positions)
        coords = np.zeros((count, 2), np.float32)
        coords[:top] = positions[:top, :2] - np.asarray(self.origin)
        sea_normals = np.zeros((count, 3), np.float32)
        sea_normals[:, 2] = 1.0
        sea_positions = np.zeros((count, 3), np.float32)
        sea_positions[:top, :2] = positions[:top, :2]
        tau = np.zeros(count, np.float32)
        tau[:top] = np.where(wet, depth_taper(depth, self.rms_height)[0], 0.0)
        zeros = np.zeros(count, np.float32)
        join = JoinShading(sea_normals, sea_positions, tau, zeros, zeros)
        return ShadingFields(shading_cascades(self.sea, t), SHADING_SPACINGS, self.alpha, self.origin, coords,
                             None, join)
