"""The coastal domain inside the open sea: its frame, the sea's long waves, the terrain beyond it, the join.

A coastal scene with ``[coastal] waves = "open sea"`` puts the shallow-water
domain into the FFT sea that surrounds it to the horizon
(:class:`oceanrender.surface.coast_in_sea.CoastInSea`). This module holds the
pure pieces of that join (docs/coastal.md, "The coast inside the open sea"):

* :class:`DomainFrame` — where the grid lies: world = origin + R(θ) (ξ, ζ), with
  (ξ, ζ) the offsets from the grid's south-west corner along its axes [m] and θ
  the ``rotation`` counter-clockwise [deg].
* :class:`SeaModes` — the sea's *long* waves as the exact Fourier modes of its
  largest FFT cascade (same spectrum, same random amplitudes and phases, same
  ω(k), same time), evaluated by direct sums at any point. The solver's offshore
  side is driven by those that travel into the domain
  (:func:`incident_from_modes`); inside the domain they are what the solver
  replaces.
* :func:`terrain_height` — the bed inside the grid (bilinear in its cell
  centres) and its continuation outside: the edge profile carried on along the
  coast and landward, the sea floor deepening offshore to ``outer_depth``.
* :func:`blend_weight` — the weight w of the solver's surface: 1 inside, a C¹
  smoothstep to 0 over ``blend_width`` at the offshore and lateral sides, 0
  outside.
* :func:`depth_taper` — the saturation of waves that the solver does not carry
  in shallow water: their rms height is held at γ d (Thornton & Guza 1983).

Lengths in m, times in s, angles of directions counter-clockwise from +x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .boundaries import IncidentWave

#: Breaker index of the saturated surf zone on H_rms [-]: H_rms ≈ 0.42 d (Thornton & Guza 1983, J. Geophys.
#: Res. 88(C10) 5925–5938, doi:10.1029/JC088iC10p05925, their γ = 0.42 fitted at Torrey Pines and Soldiers Beach).
BREAKER_INDEX_RMS = 0.42

#: Largest k d of a long wave given to the solver [-]: tanh(kd)/(kd) ≥ 0.76, so its phase speed √(g d) in the
#: shallow-water equations is within 15 % of the linear-theory speed ω/k at the offshore depth.
LONG_WAVE_KD = 1.0

#: Fewest cells per wavelength of a long wave given to the solver [-].
CELLS_PER_WAVELENGTH = 8.0

#: Points evaluated per block of the direct mode sums (bounds the (points × modes) temporaries).
POINT_BLOCK = 16384

_INWARD = {"north": -0.5 * math.pi, "south": 0.5 * math.pi, "east": math.pi, "west": 0.0}
_OPPOSITE = {"north": "south", "south": "north", "east": "west", "west": "east"}


@dataclass(frozen=True)
class DomainFrame:
    """The coastal grid's placement in the world: world = origin + R(θ) (ξ, ζ).

    Parameters
    ----------
    origin : (float, float)   World (x, y) of the grid's south-west corner [m].
    rotation : float          θ, counter-clockwise from the world axes to the grid's [deg].
    size : (float, float)     Extent (Lx, Ly) along the grid's axes [m].
    """

    origin: tuple[float, float]
    rotation: float
    size: tuple[float, float]

    @property
    def cos_sin(self) -> tuple[float, float]:
        angle = math.radians(self.rotation)
        return math.cos(angle), math.sin(angle)

    def to_local(self, x: ArrayLike, y: ArrayLike) -> tuple[NDArray, NDArray]:
        """(ξ, ζ) [m] of world points (x, y) [m]: offsets from the south-west corner along the grid's axes."""
        c, s = self.cos_sin
        dx = np.asarray(x, float) - self.origin[0]
        dy = np.asarray(y, float) - self.origin[1]
        return c * dx + s * dy, -s * dx + c * dy

    def to_world(self, xi: ArrayLike, zeta: ArrayLike) -> tuple[NDArray, NDArray]:
        """World (x, y) [m] of grid offsets (ξ, ζ) [m]."""
        vx, vy = self.vector_to_world(xi, zeta)
        return vx + self.origin[0], vy + self.origin[1]

    def vector_to_world(self, vx: ArrayLike, vy: ArrayLike) -> tuple[NDArray, NDArray]:
        """A vector's world components from its components along the grid's axes."""
        c, s = self.cos_sin
        vx, vy = np.asarray(vx, float), np.asarray(vy, float)
        return c * vx - s * vy, s * vx + c * vy

    def vector_to_local(self, vx: ArrayLike, vy: ArrayLike) -> tuple[NDArray, NDArray]:
        """A world vector's components along the grid's axes."""
        c, s = self.cos_sin
        vx, vy = np.asarray(vx, float), np.asarray(vy, float)
        return c * vx + s * vy, -s * vx + c * vy


def domain_frame(coastal) -> DomainFrame:
    """The :class:`DomainFrame` of a ``[coastal]`` section."""
    return DomainFrame(tuple(coastal.origin), float(coastal.rotation), tuple(coastal.size))


@dataclass(frozen=True)
class SeaModes:
    """Linear waves η = Σ a_n cos(k_n·x − ω_n t + φ_n) in world coordinates, and their chop.

    Parameters
    ----------
    kx, ky : (N,) arrays    Wavenumber vectors [rad m⁻¹]; each wave travels along +k.
    amplitude : (N,) array  a_n [m].
    phase : (N,) array      φ_n relative to the world origin [rad].
    omega : (N,) array      ω_n [rad s⁻¹] (the sea's dispersion relation and loop quantisation).
    choppiness : float      λ of the horizontal displacement D = −λ Σ a k̂ sin(…) [-] (Tessendorf 2001, eq. 29;
                            toward the crests, as the FFT sea's own D and Gerstner's trochoid).
    patch_size : float      With every k on the lattice 2π n / L of this patch [m], :meth:`fields` may sum
                            the waves by an inverse FFT on a fine grid (0: direct sums only).
    """

    kx: NDArray[np.float64]
    ky: NDArray[np.float64]
    amplitude: NDArray[np.float64]
    phase: NDArray[np.float64]
    omega: NDArray[np.float64]
    choppiness: float = 0.0
    patch_size: float = 0.0

    @property
    def count(self) -> int:
        return int(self.kx.size)

    @property
    def variance(self) -> float:
        """Σ a²/2: the elevation variance the waves carry [m²]."""
        return float(np.sum(self.amplitude**2) / 2.0)

    def subset(self, keep: NDArray[np.bool_]) -> SeaModes:
        return SeaModes(self.kx[keep], self.ky[keep], self.amplitude[keep], self.phase[keep], self.omega[keep],
                        self.choppiness, self.patch_size)

    def _phase_at(self, t: float) -> NDArray[np.float64]:
        """φ_n − ω_n t [rad], ωt reduced to one cycle in float64 first (as the FFT sea does)."""
        cycles = self.omega * (t / (2.0 * math.pi))
        return self.phase - 2.0 * math.pi * (cycles - np.rint(cycles))

    def _multipliers(self) -> NDArray[np.complex128]:
        """Per mode, the multipliers of A e^{iθ} whose real parts are (η, Dx, Dy, ∂η/∂x, ∂η/∂y), shape (5, N)."""
        k = np.hypot(self.kx, self.ky)
        ux, uy = self.choppiness * self.kx / k, self.choppiness * self.ky / k
        one = np.ones(self.count)
        # Dx = Re(i λ k̂x A e^{iθ}) = −λ k̂x a sin θ (Tessendorf 2001, eq. 29, with the FFT sea's signs); ∇η = Re(i k A e^{iθ})
        return np.stack([one + 0j, 1j * ux, 1j * uy, 1j * self.kx, 1j * self.ky])

    def fft_size(self) -> int:
        """Points per side of the inverse FFT that sums the waves: ≥ 32 per shortest wavelength, a power of 2."""
        k_max = float(np.max(np.hypot(self.kx, self.ky)))
        needed = 32.0 * self.patch_size * k_max / (2.0 * math.pi)
        return int(2 ** math.ceil(math.log2(max(needed, 16.0))))

    def fields(self, x: ArrayLike, y: ArrayLike, t: float, method: str = "auto") -> NDArray[np.float64]:
        """(η, Dx, Dy, ∂η/∂x, ∂η/∂y) at world points (x, y) [m], time t [s]: shape (5, *x.shape) [m, m, m, -, -].

        ``method``: ``"direct"`` sums every mode at every point (blocks of
        :data:`POINT_BLOCK` points); ``"fft"`` (lattice modes only) sums them
        by one inverse FFT on a periodic grid of :meth:`fft_size` points per
        side over the patch and interpolates bilinearly, which at ≥ 32 points
        per wavelength keeps each wave's amplitude to within 1 − cos(π/32)
        ≈ 0.5 % (the midpoint of linear interpolation of a cosine);
        ``"auto"``: the FFT when there are more points than FFT cells / 64.
        """
        x, y = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float))
        shape = x.shape
        x, y = x.ravel(), y.ravel()
        if self.count == 0:
            return np.zeros((5, *shape))
        if method == "auto":
            method = "fft" if self.patch_size > 0 and x.size * self.count > self.fft_size() ** 2 * 4 else "direct"
        if method == "fft":
            return self._fft_fields(x, y, t).reshape(5, *shape)
        out = np.zeros((5, x.size))
        k = np.hypot(self.kx, self.ky)
        ux, uy = self.choppiness * self.kx / k, self.choppiness * self.ky / k
        base = self._phase_at(t)
        for start in range(0, x.size, POINT_BLOCK):
            stop = min(start + POINT_BLOCK, x.size)
            theta = np.outer(x[start:stop], self.kx) + np.outer(y[start:stop], self.ky) + base
            c, s = np.cos(theta), np.sin(theta)
            a_c, a_s = c * self.amplitude, s * self.amplitude
            out[0, start:stop] = a_c.sum(axis=1)
            out[1, start:stop] = -(a_s @ ux)  # −λ k̂ a sin θ: toward the crests (Tessendorf 2001, eq. 29)
            out[2, start:stop] = -(a_s @ uy)
            out[3, start:stop] = -(a_s @ self.kx)  # ∇η = −a k sin θ
            out[4, start:stop] = -(a_s @ self.ky)
        return out.reshape(5, *shape)

    def _fft_fields(self, x: NDArray, y: NDArray, t: float) -> NDArray[np.float64]:
        """:meth:`fields` by one inverse FFT of the lattice modes and bilinear interpolation (flat points)."""
        if not self.patch_size > 0:
            raise ValueError("the FFT sum needs the modes' patch_size")
        n = self.fft_size()
        dk = 2.0 * math.pi / self.patch_size
        ix, iy = np.rint(self.kx / dk).astype(np.int64), np.rint(self.ky / dk).astype(np.int64)
        if np.max(np.abs(self.kx - ix * dk)) > 1e-9 * dk or np.max(np.abs(self.ky - iy * dk)) > 1e-9 * dk:
            raise ValueError("the FFT sum needs every wavenumber on the patch's lattice")
        amplitude = self.amplitude * np.exp(1j * self._phase_at(t))  # A_n: η = Re Σ A_n e^{i k_n·x}
        spectra = np.zeros((5, n, n), np.complex128)
        np.add.at(spectra, (slice(None), iy % n, ix % n), self._multipliers() * amplitude)
        grids = (np.fft.ifft2(spectra) * (n * n)).real  # Σ c_k e^{i k·x} at x = (i, j) L / n
        cell = self.patch_size / n
        fx, fy = np.mod(x, self.patch_size) / cell, np.mod(y, self.patch_size) / cell
        i0, j0 = np.floor(fx).astype(np.int64) % n, np.floor(fy).astype(np.int64) % n
        tx, ty = fx - np.floor(fx), fy - np.floor(fy)
        i1, j1 = (i0 + 1) % n, (j0 + 1) % n
        return ((1 - ty) * ((1 - tx) * grids[:, j0, i0] + tx * grids[:, j0, i1])
                + ty * ((1 - tx) * grids[:, j1, i0] + tx * grids[:, j1, i1]))


def long_wave_cutoff(coastal, offshore_depth: float) -> float:
    """Largest wavenumber of the sea's waves that the solver takes [rad m⁻¹].

    k d ≤ :data:`LONG_WAVE_KD` at the offshore depth d [m] (the shallow-water
    equations carry every period at √(g d)) and at least
    :data:`CELLS_PER_WAVELENGTH` cells per wavelength.
    """
    dx, dy = coastal.spacing
    return min(LONG_WAVE_KD / offshore_depth, 2.0 * math.pi / (CELLS_PER_WAVELENGTH * max(dx, dy)))


def sea_long_modes(sea, k_max: float) -> SeaModes:
    """The modes of the sea's largest FFT cascade with 0 < |k| ≤ k_max [rad m⁻¹], as :class:`SeaModes`.

    Parameters
    ----------
    sea : oceanrender.waves.sea.SeaSurface
        An FFT sea (``model = "FFT"``).
    k_max : float
        Cut-off wavenumber [rad m⁻¹]; must lie inside the first cascade's band,
        or be infinite for all its modes (those of lattice cells that the band's
        top edge crosses included).

    Notes
    -----
    The FFT sea is η = Σ_k h̃(k, t) e^{ik·x} with h̃(k, t) = h̃₀(k) e^{−iωt} +
    conj h̃₀(−k) e^{iωt} (:func:`~oceanrender.waves.fft_ocean.time_amplitudes`),
    i.e. η = 2 Re Σ_k h̃₀(k) e^{i(k·x − ωt)} over all kept lattice modes: each
    mode is one wave along +k of amplitude 2|h̃₀(k)| and phase arg h̃₀(k). The
    cascade's amplitudes were drawn from Ψ/g to make up for the gain g of
    bilinear interpolation (:class:`~oceanrender.waves.lod.GainCompensated`);
    here they are multiplied by √g, the amplitude of the spectrum itself.
    """
    from ..waves.lod import bilinear_power_gain  # noqa: PLC0415

    if sea.cascades is None:
        raise ValueError("the coast inside the open sea needs the FFT sea ([ocean] model = 'FFT')")
    levels = sea.levels[0]
    if math.isfinite(k_max) and k_max > levels.band_top:
        raise ValueError(f"long waves up to k = {k_max:.4g} rad/m lie beyond the first cascade's band "
                         f"(top {levels.band_top:.4g} rad/m): raise [ocean] resolution or patch_size")
    ocean = levels.oceans[0]
    grid = ocean.grid
    keep = grid.mode_mask & (grid.k <= k_max) & (np.abs(ocean.h0) > 0)
    gain = bilinear_power_gain(grid.kx, grid.ky, grid.spacing)
    h0 = ocean.h0 * np.sqrt(gain)
    return SeaModes(
        kx=grid.kx[keep].astype(float), ky=grid.ky[keep].astype(float),
        amplitude=2.0 * np.abs(h0[keep]), phase=np.angle(h0[keep]), omega=ocean.omega[keep].astype(float),
        choppiness=float(ocean.choppiness), patch_size=float(grid.patch_size),
    )


def incident_from_modes(modes: SeaModes, frame: DomainFrame, side: str, spinup: float, still_level: float = 0.0,
                        ramp_time: float = 5.0) -> IncidentWave:
    """The solver's incident waves on ``side``: the modes that travel into the domain, in the grid's frame.

    A wave cos(k·X − ω t + φ) at world X = o + R ξ and scene time t = τ − spinup
    (τ the solver's clock) is cos(k_l·ξ − ω τ + φ + k·o + ω spinup), k_l = Rᵀ k:
    the phases move to the grid's corner and the solver's clock, so the side sees
    exactly the sea's long waves. The sea's own wavenumbers are kept (its phases
    along the side), ω is the sea's.
    """
    klx, kly = frame.vector_to_local(modes.kx, modes.ky)
    direction = np.arctan2(kly, klx)
    inward = np.cos(direction - _INWARD[side]) > 0.0
    if not np.any(inward):
        return IncidentWave.absorbing(still_level)
    phase = modes.phase + modes.kx * frame.origin[0] + modes.ky * frame.origin[1] + modes.omega * spinup
    phase = np.mod(phase, 2.0 * math.pi)
    k = np.hypot(modes.kx, modes.ky)
    return IncidentWave.from_components(
        amplitudes=modes.amplitude[inward], omegas=modes.omega[inward], directions_rad=direction[inward],
        phases=phase[inward], still_level=still_level, wavenumbers=k[inward], ramp_time=ramp_time)


def _smoothstep(s: NDArray) -> tuple[NDArray, NDArray]:
    """(S, dS/ds) of the C¹ smoothstep S = 3s² − 2s³ on s clipped to [0, 1]."""
    inside = (s > 0.0) & (s < 1.0)
    s = np.clip(s, 0.0, 1.0)
    return s * s * (3.0 - 2.0 * s), np.where(inside, 6.0 * s * (1.0 - s), 0.0)


def side_distances(frame: DomainFrame, xi: NDArray, zeta: NDArray) -> dict[str, tuple[NDArray, tuple[float, float]]]:
    """Per side: (distance inward from that side [m], its inward unit normal in the grid's frame)."""
    lx, ly = frame.size
    return {"west": (xi, (1.0, 0.0)), "east": (lx - xi, (-1.0, 0.0)),
            "south": (zeta, (0.0, 1.0)), "north": (ly - zeta, (0.0, -1.0))}


def blend_weight(frame: DomainFrame, offshore_side: str, width: float, x: ArrayLike, y: ArrayLike
                 ) -> tuple[NDArray, NDArray, NDArray]:
    """(w, ∂w/∂x, ∂w/∂y) at world points: the weight of the solver's surface [-, m⁻¹].

    w = Π_sides S(d_side / width) over the offshore side and the two lateral
    sides (S the C¹ smoothstep, d the distance inward from the side); 0 outside
    the grid. The landward side does not fade: there the grid ends on land.
    """
    xi, zeta = frame.to_local(x, y)
    distances = side_distances(frame, xi, zeta)
    fading = [side for side in distances if side != _OPPOSITE[offshore_side]]
    w = np.ones(xi.shape)
    gx, gy = np.zeros(xi.shape), np.zeros(xi.shape)
    factors = []
    for side in fading:
        d, normal = distances[side]
        value, slope = _smoothstep(d / width)
        factors.append((value, slope / width, normal))
    for value, _, _ in factors:
        w = w * value
    for i, (_, derivative, normal) in enumerate(factors):
        others = np.ones(xi.shape)
        for j, (value, _, _) in enumerate(factors):
            if j != i:
                others = others * value
        gx = gx + others * derivative * normal[0]
        gy = gy + others * derivative * normal[1]
    lx, ly = frame.size
    inside = (xi >= 0) & (xi <= lx) & (zeta >= 0) & (zeta <= ly)
    w = np.where(inside, w, 0.0)
    gx, gy = np.where(inside, gx, 0.0), np.where(inside, gy, 0.0)
    wx, wy = frame.vector_to_world(gx, gy)
    return w, wx, wy


def depth_taper(depth: ArrayLike, rms_height: float) -> tuple[NDArray, NDArray]:
    """(τ, dτ/dd): the factor on waves the solver does not carry, at still depth d [m] [-, m⁻¹].

    τ = tanh(γ d / H_rms) for d > 0, 0 on land, γ = :data:`BREAKER_INDEX_RMS`:
    in deep water the waves pass unchanged (τ → 1); as the depth falls their
    rms height τ H_rms approaches γ d, the saturated surf zone of Thornton &
    Guza (1983, eq. 21 with their γ). C∞ for d > 0.
    """
    d = np.asarray(depth, float)
    if rms_height <= 0:
        return (d > 0).astype(float), np.zeros(d.shape)
    z = np.maximum(d, 0.0) * (BREAKER_INDEX_RMS / rms_height)
    tau = np.tanh(z)
    return tau, np.where(d > 0, (1.0 - tau**2) * BREAKER_INDEX_RMS / rms_height, 0.0)


def _bilinear(field: NDArray, spacing: tuple[float, float], xi: NDArray, zeta: NDArray) -> NDArray:
    """Bilinear interpolation of a cell-centred (ny, nx) field at grid offsets (ξ, ζ), clamped at the edges."""
    ny, nx = field.shape
    fx = np.clip(xi / spacing[0] - 0.5, 0.0, nx - 1.0)
    fy = np.clip(zeta / spacing[1] - 0.5, 0.0, ny - 1.0)
    i0 = np.minimum(fx.astype(np.int64), nx - 2)
    j0 = np.minimum(fy.astype(np.int64), ny - 2)
    tx, ty = fx - i0, fy - j0
    return ((1 - ty) * ((1 - tx) * field[j0, i0] + tx * field[j0, i0 + 1])
            + ty * ((1 - tx) * field[j0 + 1, i0] + tx * field[j0 + 1, i0 + 1]))


def grid_sample(field: NDArray, frame: DomainFrame, spacing: tuple[float, float], x: ArrayLike, y: ArrayLike
                ) -> NDArray:
    """A cell-centred field of the grid at world points (bilinear; the edge values continued outside)."""
    xi, zeta = frame.to_local(x, y)
    return _bilinear(np.asarray(field, float), spacing, xi, zeta)


def terrain_height(bed: NDArray, frame: DomainFrame, spacing: tuple[float, float], offshore_side: str,
                   still_level: float, outer_slope: float, outer_depth: float, x: ArrayLike, y: ArrayLike
                   ) -> NDArray[np.float64]:
    """Terrain elevation z [m] at world points: the bed inside the grid, continued outside.

    Inside: bilinear in the cell centres. Outside, the nearest edge value
    continues (the beach's cross-shore profile along the coast, the land at
    its landward edge), and beyond the offshore side the floor deepens with
    ``outer_slope`` [-] per metre of distance from it, down to ``outer_depth``
    [m] below the still level (never rising: a deeper edge stays as it is).
    """
    xi, zeta = frame.to_local(x, y)
    z = _bilinear(np.asarray(bed, float), spacing, xi, zeta)
    distance, _ = side_distances(frame, xi, zeta)[offshore_side]
    beyond = np.maximum(-distance, 0.0)
    deeper = np.maximum(z - outer_slope * beyond, still_level - outer_depth)
    return np.minimum(z, deeper)
