"""Whitecap foam coverage from the folding of the choppy surface, with temporal decay.

Tessendorf [1] notes that the Jacobian J of the choppy horizontal map turns
negative where the surface folds over, at the crests that would break; Dupuy
and Bruneton [2] turn a threshold on J into whitecap coverage. Foam outlives the
breaking that made it: a whitecap patch fades roughly exponentially, with an
e-folding time of a few seconds (3.85 s in sea water after Monahan [3]; 0.5–8 s
observed by Callaghan et al. [4]).

Here the foam coverage F ∈ [0, 1] of each surface point obeys

    dF/dt = s(J) (1 − F) − F / τ,     s(J) = G max(J_c − J, 0),

production where the surface is compressed below the threshold J_c (G [s⁻¹]
is the gain), saturating at full coverage, and exponential decay with
e-folding time τ [s]. :func:`foam_step` integrates it exactly over a step with
J held fixed, so the result does not depend on the frame rate when J is
constant and to first order in dt when it varies, and stays in [0, 1].

The coverage lives on the undisplaced FFT grid: a grid point follows a water
parcel (Lagrangian coordinates), so foam moves with the horizontal
displacement when the fields are drawn on the displaced mesh, and the foam a
breaking crest leaves behind stays with the water while the crest runs on:
a trail along the direction the waves travel (downwind), fresh at the crest
and older behind it.

Two stages (Monahan & Lu 1990: stage A, the actively breaking crest; stage B,
the decaying foam patch). Besides the coverage F, :func:`two_stage_foam_step`
carries the *fresh* coverage B, foam weighted by exp(−age/τ_f), the age
counted from the last breaking over it: breaking makes clear water and old
foam fresh, and B decays faster, at 1/τ + 1/τ_f, so B ≤ F and B/F is the
mean of exp(−age/τ_f) over the foam present. The renderer gives foam the
reflectance of fresh foam on the fraction B of the surface: a patch's
reflectance falls as exp(−age/τ_f) (Koepke 1984, his exponential decay of a
whitecap's reflectance) while it still counts as whitecap (F).

Breaking criterion (:func:`crest_acceleration_threshold`). For deep-water
linear waves the horizontal displacement's divergence is the vertical
acceleration over g (Tessendorf's D = −iλ k/|k| h), so J − 1 ≈ λ a_z / g, and
J < J_c is the crest-acceleration criterion of Longuet-Higgins (1963) and
Srokosz (1986), a_z < −α g, with α = (1 − J_c)/λ. The mesh carries only the
waves longer than a few vertex spacings; the criterion is applied to the whole
sea's acceleration by rescaling α by the rms of the carried waves over the rms
of all (for a Gaussian sea the exceedance fraction is then the whole sea's).
Whole-sea slopes grow with the wind (Cox & Munk 1954), so the breaking
fraction does too, with no wind-dependent constant.

References
----------
.. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes,
   section "Choppy waves" (the Jacobian as a fold and whitecap indicator).
.. [2] J. Dupuy and E. Bruneton, "Real-time Animation and Rendering of Ocean
   Whitecaps", SIGGRAPH Asia 2012 Technical Briefs, 2012.
.. [3] E. C. Monahan, "Oceanic whitecaps", J. Phys. Oceanogr. 1(2), 139–144, 1971.
.. [4] A. H. Callaghan, G. B. Deane, M. D. Stokes and B. Ward, "Observed
   variation in the decay time of oceanic whitecap foam", J. Geophys. Res.
   117, C09015, 2012.
.. [5] E. C. Monahan and I. G. O'Muircheartaigh, "Optimal power-law
   description of oceanic whitecap coverage dependence on wind speed",
   J. Phys. Oceanogr. 10(12), 2094–2099, 1980.
.. [6] E. C. Monahan and M. Lu, "Acoustically relevant bubble assemblages and
   their dependence on meteorological parameters", IEEE J. Oceanic Eng.
   15(4), 340–349, 1990 (whitecap stages A and B).
.. [7] M. S. Longuet-Higgins, "The generation of capillary waves by steep
   gravity waves", J. Fluid Mech. 16, 138–159, 1963 (crest acceleration −g/2
   of the limiting Stokes wave); M. A. Srokosz, "On the probability of wave
   breaking in deep water", J. Phys. Oceanogr. 16, 382–385, 1986.
.. [8] P. Koepke, "Effective reflectance of oceanic whitecaps", Appl. Opt.
   23(11), 1816–1824, 1984, doi:10.1364/AO.23.001816.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "lace_tile_Perlin1985",
    "FOAM_DECAY_TIME_SEAWATER",
    "whitecap_fraction_MonahanOMuircheartaigh1980",
    "crest_acceleration_threshold",
    "foam_production_rate",
    "foam_step",
    "two_stage_foam_step",
    "FoamAccumulator",
]

FOAM_DECAY_TIME_SEAWATER: float = 3.85
"""e-folding time of whitecap foam in sea water, Monahan (1971) [s]."""


def whitecap_fraction_MonahanOMuircheartaigh1980(wind_speed_10: ArrayLike) -> NDArray[np.floating]:
    """Fraction W of the sea surface covered by whitecaps [-], Monahan & O'Muircheartaigh (1980).

    W = 3.84·10⁻⁶ U₁₀^3.41 (their Eq. 5, the optimal power law; 0.46 % at
    8 m s⁻¹, 1.8 % at 12, 4.9 % at 16).

    Parameters
    ----------
    wind_speed_10 : array_like
        Wind speed 10 m above the sea, U₁₀ ≥ 0 [m s⁻¹].

    Returns
    -------
    ndarray
        W [-] (a fraction, not per cent).

    References
    ----------
    .. [1] E. C. Monahan and I. G. O'Muircheartaigh, J. Phys. Oceanogr. 10(12),
       2094–2099, 1980.
    """
    wind = np.asarray(wind_speed_10, dtype=np.float64)
    return 3.84e-6 * wind**3.41  # Eq. 5 of [1]


def crest_acceleration_threshold(alpha: float, choppiness: ArrayLike, resolved_slope_variance: ArrayLike,
                                 total_slope_variance: float) -> NDArray[np.floating]:
    """Jacobian J_c below which a crest breaks: a_z < −α g for the whole sea, seen on the carried waves [-].

    J_c = 1 − λ α √(m_r / m_t)

    Parameters
    ----------
    alpha : float
        Breaking crest acceleration α, in units of g [-] (0.5 for the
        limiting Stokes wave, Longuet-Higgins 1963).
    choppiness : array_like
        λ of the horizontal displacement [-].
    resolved_slope_variance : array_like
        Mean-square slope m_r of the waves the Jacobian is computed from [-].
    total_slope_variance : float
        Mean-square slope m_t of all the sea's waves [-].

    Returns
    -------
    ndarray
        J_c [-].

    Notes
    -----
    In deep water J − 1 = λ ∇·D ≈ λ a_z/g to first order (Tessendorf 2001,
    D = −i k/|k| h; a_z = −g|k| h for each mode), and the variance of a_z/g
    is the mean-square slope (Srokosz 1986). The whole sea's acceleration
    exceeds α g on the fraction ½ erfc(α/√(2 m_t)) of the surface; the
    carried waves' does on the same fraction when their threshold is
    α √(m_r/m_t) (Gaussian statistics). The foam is placed where the carried
    crests are most extreme: the waves the mesh lacks decide how much breaks,
    the resolved crests where.
    """
    resolved = np.asarray(resolved_slope_variance, dtype=np.float64)
    total = float(total_slope_variance)
    if not (np.all(np.isfinite(resolved)) and np.isfinite(total) and total >= 0 and np.all(resolved >= 0)):
        raise ValueError(f"slope variances must be finite and ≥ 0, got m_r = {resolved!r:.80}, m_t = {total!r}")
    # NOTE: a sea without slopes (m_t = 0, e.g. a wind of 1e-9 m/s underflows) breaks nowhere whatever the
    # ratio; the carried waves are then all of it (ratio 1), never 0/0. m_r ≤ m_t, so the ratio is in [0, 1].
    ratio = np.sqrt(np.clip(resolved / total, 0.0, 1.0)) if total > 0 else np.ones_like(resolved)
    return 1.0 - np.asarray(choppiness, dtype=np.float64) * alpha * ratio  # a_z = −α g √(m_r/m_t), J ≈ 1 + λ a_z/g


def foam_production_rate(jacobian: ArrayLike, threshold: float, gain: float) -> NDArray[np.floating]:
    """Foam production rate s = G max(J_c − J, 0) [s⁻¹].

    Parameters
    ----------
    jacobian : array_like
        Jacobian J of the horizontal map [-]; J < 0 where the surface folds.
    threshold : float
        J_c below which foam forms [-]; 0 makes foam only where the surface folds.
    gain : float
        G, production rate per unit of J_c − J [s⁻¹].

    Returns
    -------
    ndarray
        s ≥ 0 [s⁻¹].
    """
    jacobian = np.asarray(jacobian)
    return gain * np.maximum(np.asarray(threshold, jacobian.dtype) - jacobian, 0)


def foam_step(
    previous: ArrayLike, jacobian: ArrayLike, dt: float, threshold: float, decay_time: float, gain: float
) -> NDArray[np.floating]:
    """Foam coverage after a step of dt seconds with the Jacobian held fixed [-].

    Parameters
    ----------
    previous : array_like
        Coverage F at the start of the step, in [0, 1] [-].
    jacobian : array_like
        Jacobian J of the horizontal map during the step (broadcast with
        ``previous``) [-].
    dt : float
        Step length ≥ 0 [s].
    threshold : float
        J_c: foam forms where J < J_c [-].
    decay_time : float
        e-folding time τ > 0 of the foam [s]; ``np.inf`` for foam that never fades.
    gain : float
        G ≥ 0, production rate per unit of J_c − J [s⁻¹].

    Returns
    -------
    ndarray
        F(t + dt) in [0, 1] [-].

    Notes
    -----
    With s = G max(J_c − J, 0) and a = s + 1/τ, dF/dt = s (1 − F) − F/τ has
    the exact solution

        F(t + dt) = F_eq + (F(t) − F_eq) e^{−a dt},   F_eq = s / a,

    a convex combination of F(t) ∈ [0, 1] and F_eq ∈ [0, 1], hence in [0, 1].
    Without folding (s = 0) it is the pure decay F e^{−dt/τ} of [3]; two steps
    of dt/2 equal one of dt exactly for constant J.

    References
    ----------
    .. [1] J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 Course Notes.
    .. [2] J. Dupuy and E. Bruneton, SIGGRAPH Asia 2012 Technical Briefs.
    .. [3] E. C. Monahan, J. Phys. Oceanogr. 1(2), 139–144, 1971.
    """
    if not dt >= 0:
        raise ValueError(f"dt must be ≥ 0 [s], got {dt!r}")
    if not decay_time > 0:
        raise ValueError(f"decay_time must be > 0 [s], got {decay_time!r}")
    if not gain >= 0:
        raise ValueError(f"gain must be ≥ 0 [s⁻¹], got {gain!r}")
    previous = np.asarray(previous)
    production = foam_production_rate(jacobian, threshold, gain)
    rate = production + 1.0 / decay_time  # a = s + 1/τ
    with np.errstate(invalid="ignore", divide="ignore"):
        equilibrium = np.where(rate > 0, production / rate, 0.0)  # F_eq = s/a
    decay = np.exp(-rate * dt)
    coverage = equilibrium + (previous - equilibrium) * decay  # exact solution over dt
    return np.clip(coverage, 0.0, 1.0).astype(np.result_type(previous, production), copy=False)


def two_stage_foam_step(coverage: ArrayLike, fresh: ArrayLike, jacobian: ArrayLike, dt: float, threshold: ArrayLike,
                        decay_time: float, fresh_decay_time: float,
                        gain: float) -> tuple[NDArray[np.floating], NDArray[np.floating]]:
    """Whitecap coverage F and fresh-foam coverage B after a step of dt seconds, J held fixed [-].

    dF/dt = s (1 − F) − F/τ,    dB/dt = s (1 − B) − B (1/τ + 1/τ_f),

    s = G max(J_c − J, 0): breaking covers clear water with foam and makes
    the foam already there fresh again; B is the foam weighted by
    exp(−age/τ_f), its age counted from the last breaking over it.

    Parameters
    ----------
    coverage, fresh : array_like
        F and B at the start of the step, 0 ≤ B ≤ F ≤ 1 [-].
    jacobian : array_like
        J during the step [-].
    dt : float
        Step length ≥ 0 [s].
    threshold : array_like
        J_c [-] (broadcast with ``jacobian``).
    decay_time : float
        τ > 0, e-folding time of the whitecap coverage [s].
    fresh_decay_time : float
        τ_f > 0, e-folding time of a patch's reflectance beyond its
        coverage's [s] (``np.inf``: B = F).
    gain : float
        G ≥ 0 [s⁻¹].

    Returns
    -------
    (F, B) : tuple of ndarray
        At t + dt, 0 ≤ B ≤ F ≤ 1 [-].

    Notes
    -----
    Both are linear with constant coefficients over the step, so each has
    the exact solution X(t) = X_eq + (X₀ − X_eq) e^{−rt}: F with r = s + 1/τ,
    F_eq = s/r (:func:`foam_step`); B with r = s + 1/τ + 1/τ_f, B_eq = s/r.
    D = F − B obeys D' = −(s + 1/τ) D + B/τ_f ≥ −(s + 1/τ) D, so B ≤ F holds.
    Under steady breaking B → s/(s + 1/τ + 1/τ_f): the actively breaking
    crest is fresh foam (Monahan & Lu's stage A); once breaking stops B/F
    falls as e^{−t/τ_f} (stage B).
    """
    if not dt >= 0:
        raise ValueError(f"dt must be ≥ 0 [s], got {dt!r}")
    if not (decay_time > 0 and fresh_decay_time > 0):
        raise ValueError(f"decay times must be > 0 [s], got {decay_time!r}, {fresh_decay_time!r}")
    if not gain >= 0:
        raise ValueError(f"gain must be ≥ 0 [s⁻¹], got {gain!r}")
    coverage = np.asarray(coverage, dtype=np.float64)
    fresh = np.asarray(fresh, dtype=np.float64)
    s = gain * np.maximum(np.asarray(threshold, dtype=np.float64) - np.asarray(jacobian, dtype=np.float64), 0.0)
    rate_f = s + 1.0 / decay_time
    rate_b = rate_f + 1.0 / fresh_decay_time
    new_coverage = s / rate_f + (coverage - s / rate_f) * np.exp(-rate_f * dt)  # exact, F_eq = s/(s + 1/τ)
    new_fresh = s / rate_b + (fresh - s / rate_b) * np.exp(-rate_b * dt)  # exact, B_eq = s/(s + 1/τ + 1/τ_f)
    new_coverage = np.clip(new_coverage, 0.0, 1.0)
    return new_coverage, np.clip(new_fresh, 0.0, new_coverage)


@dataclass
class FoamAccumulator:
    """Foam coverage carried from frame to frame; its whole state is (coverage, time).

    Parameters
    ----------
    threshold : float, optional
        J_c: foam forms where J < J_c [-]; 0 (default) means only where the surface folds.
    decay_time : float, optional
        e-folding time τ of the foam [s]; Monahan's sea-water value by default.
    gain : float, optional
        G, production rate per unit of J_c − J [s⁻¹].
    coverage : ndarray or None
        Coverage F on the FFT grid [-]; ``None`` until the first frame (then zero).
    time : float or None
        Time of ``coverage`` [s].

    Notes
    -----
    A sequence renderer that resumes at frame n either restores the state it
    saved (:meth:`state`, :meth:`from_state`) or re-runs the accumulation from
    an earlier frame: foam older than a few τ has faded, so starting 5 τ
    earlier reproduces the coverage to within e⁻⁵ < 1 %. For a sequence that
    loops with period T (``loop_period`` of the FFT ocean), accumulate over
    one period before the first frame: the foam then loops too, to within
    e^{−T/τ}.

    Examples
    --------
    >>> foam = FoamAccumulator(gain=2.0)
    >>> j = np.array([[-0.5, 1.0]])
    >>> foam.advance(j, 0.0).tolist()
    [[0.0, 0.0]]
    >>> bool(foam.advance(j, 1.0)[0, 0] > 0.5)
    True
    """

    threshold: float = 0.0
    decay_time: float = FOAM_DECAY_TIME_SEAWATER
    gain: float = 1.0
    coverage: NDArray[np.floating] | None = field(default=None, repr=False)
    time: float | None = None

    def __post_init__(self) -> None:
        if not self.decay_time > 0:
            raise ValueError(f"decay_time must be > 0 [s], got {self.decay_time!r}")
        if not self.gain >= 0:
            raise ValueError(f"gain must be ≥ 0 [s⁻¹], got {self.gain!r}")

    def advance(self, jacobian: ArrayLike, t: float) -> NDArray[np.floating]:
        """Step the coverage to time t with the Jacobian of that frame; returns the new coverage [-].

        The first call starts from no foam at time t. Steps backwards in time
        are refused.
        """
        jacobian = np.asarray(jacobian)
        if self.coverage is None or self.time is None:
            self.coverage, self.time = np.zeros(jacobian.shape, jacobian.dtype), float(t)
            return self.coverage
        if t < self.time:
            raise ValueError(f"foam cannot step back in time from {self.time} s to {t} s")
        # NOTE: the new frame's J is held over the step (backward Euler in the source):
        # foam appears in the frame whose surface folds, not one frame later.
        self.coverage = foam_step(self.coverage, jacobian, t - self.time, self.threshold, self.decay_time,
                                  self.gain)
        self.time = float(t)
        return self.coverage

    def state(self) -> dict[str, object]:
        """Everything needed to resume: parameters, coverage array and time."""
        return {"threshold": self.threshold, "decay_time": self.decay_time, "gain": self.gain,
                "coverage": None if self.coverage is None else self.coverage.copy(), "time": self.time}

    @classmethod
    def from_state(cls, state: dict[str, object]) -> FoamAccumulator:
        """The accumulator saved by :meth:`state`."""
        coverage = state.get("coverage")
        return cls(threshold=float(state["threshold"]), decay_time=float(state["decay_time"]),
                   gain=float(state["gain"]), coverage=None if coverage is None else np.array(coverage),
                   time=None if state.get("time") is None else float(state["time"]))


def lace_tile_Perlin1985(size: float, resolution: int, scale: float, stretch: float, direction: float,
                         seed: int) -> NDArray[np.float32]:
    """A periodic tile of foam lace: the magnitude of a band-pass Gaussian field, rank-mapped to uniform [-].

    |G| of a zero-mean Gaussian random field G is 0 along G's zero contours, a network
    of thin, curved, connected lines (Perlin's "turbulence", the sum of |noise|,
    Perlin 1985, §5). G here has the power spectrum exp(−(ln(k'/k₀))²/(2·0.35²)) in
    the stretched wavenumber k' = √((k_∥ s)² + k_⊥²), k₀ = 2π/``scale`` (one octave wide,
    log-normal), so its lines are ``stretch`` times longer along ``direction`` (the wind:
    trailing foam is drawn out downwind) than across. Mapped through its own empirical
    distribution (ranks / texel count) the tile L is uniform on [0, 1): foam drawn where
    L < B covers on average the fraction B of the surface (the fresh-foam coverage of
    :func:`two_stage_foam_step` keeps its mean), a full sheet where B → 1 and, as B falls,
    the lace along G's zero lines (the look of decaying whitecaps, Monahan's stage B).

    Parameters
    ----------
    size : float        Side of the periodic tile [m].
    resolution : int    Texels per side [-].
    scale : float       Wavelength 2π/k₀ of the field's spectral peak [m]: the lace's mesh is about half of it.
    stretch : float     Elongation of the lines along ``direction`` (≥ 1) [-].
    direction : float   Direction of elongation, counter-clockwise from +x [rad].
    seed : int          Seed of the field.

    Returns
    -------
    (resolution, resolution) float32, rows along y; texel (i, j) at ((i + ½), (j + ½)) size/resolution.

    References
    ----------
    .. [1] K. Perlin, "An image synthesizer," Proc. SIGGRAPH '85, 287–296, doi:10.1145/325165.325247.
    """
    rng = np.random.default_rng(seed)
    k = 2.0 * np.pi * np.fft.fftfreq(resolution, d=size / resolution)
    kx, ky = np.meshgrid(k, k)
    along = kx * np.cos(direction) + ky * np.sin(direction)
    across = -kx * np.sin(direction) + ky * np.cos(direction)
    stretched = np.hypot(along * stretch, across)
    peak = 2.0 * np.pi / scale
    amplitude = np.exp(-np.log(np.maximum(stretched, 1e-12) / peak) ** 2 / (4.0 * 0.35**2))
    amplitude[0, 0] = 0.0
    noise = rng.standard_normal((resolution, resolution)) + 1j * rng.standard_normal((resolution, resolution))
    field = np.abs(np.real(np.fft.ifft2(noise * amplitude)))
    ranks = np.empty(field.size)
    ranks[np.argsort(field.ravel(), kind="stable")] = (np.arange(field.size) + 0.5) / field.size
    return ranks.reshape(resolution, resolution).astype(np.float32)
