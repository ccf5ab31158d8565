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
displacement when the fields are drawn on the displaced mesh.

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
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["FOAM_DECAY_TIME_SEAWATER", "foam_production_rate", "foam_step", "FoamAccumulator"]

FOAM_DECAY_TIME_SEAWATER: float = 3.85
"""e-folding time of whitecap foam in sea water, Monahan (1971) [s]."""


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
