"""
Light adaptation over time
==========================

The eye does not re-adapt instantly when the scene's luminance changes: after
a step it approaches the new state roughly exponentially. Durand and Dorsey
[1] model the adaptation luminance as a first-order low-pass (exponential
decay towards the current target) of the scene's luminance; Pattanaik et al.
[2] build the same kind of filters into their time-dependent model, with
separate fast (neural) and slow (bleaching) stages. For daylight scenes the
fast cone stage dominates, and this module keeps that one stage:

    dL_a/dt = (L_target − L_a) / τ        (on log luminance, see below)

-   :func:`adaptation_step_DurandDorsey2000`: one frame step of the filter.
-   :func:`adaptation_history_frames`: how many frames of history a frame's
    state depends on (after that many steps the initial state weighs < 2 %).
-   :func:`adapted_luminance`: the state after a sequence of targets, the eye
    starting adapted to the first.

A frame's state is a function of its own and the preceding frames' targets
only, over a window fixed by the frame number (:func:`adaptation_window`), so
frames stay independent tasks and a resumed run equals an uninterrupted one.

References
----------
.. [1] F. Durand and J. Dorsey, "Interactive tone mapping," in Proc.
   Eurographics Workshop on Rendering 2000, Springer, pp. 219–230, 2000.
   doi:10.1007/978-3-7091-6303-0_20
.. [2] S. N. Pattanaik, J. Tumblin, H. Yee and D. P. Greenberg, "Time-dependent
   visual adaptation for fast realistic image display," in Proc. SIGGRAPH
   2000, pp. 47–54, 2000. doi:10.1145/344779.344810
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "HISTORY_TIME_CONSTANTS",
    "adaptation_step_DurandDorsey2000",
    "adaptation_history_frames",
    "adaptation_window",
    "adapted_luminance",
]

#: Length of a frame's adaptation history in time constants [-]: the state the window starts from
#: weighs e⁻⁴ ≈ 1.8 % after it (and for a scene whose luminance was steady, nothing).
HISTORY_TIME_CONSTANTS = 4.0


def adaptation_step_DurandDorsey2000(previous: ArrayLike, target: ArrayLike, dt: float,
                                     time_constant: float) -> NDArray[np.float64]:
    """Adaptation luminance after a step of ``dt`` towards ``target`` [cd/m²].

    .. math:: \\ln L_a(t + Δt) = \\ln L_t + (\\ln L_a(t) − \\ln L_t)\\, e^{−Δt/τ}

    Parameters
    ----------
    previous : array_like
        Adaptation luminance :math:`L_a(t)` [cd/m²], > 0.
    target : array_like
        Luminance the eye adapts towards during the step, :math:`L_t` [cd/m²], > 0
        (e.g. the log-average of the view).
    dt : float
        Step [s], ≥ 0.
    time_constant : float
        τ [s], ≥ 0; 0 adapts at once.

    Returns
    -------
    numpy.ndarray
        :math:`L_a(t + Δt)` [cd/m²].

    Notes
    -----
    -   The exponential approach is that of [1] (and the fast stage of [2]),
        integrated exactly for a target held constant over the step, so two
        steps of Δt/2 equal one of Δt.
    -   It is applied to log luminance: adaptation acts on ratios (a step from
        100 to 1000 cd/m² and back is symmetric), and the geometric mean is
        what the log-average adaptation luminance already averages.

    References
    ----------
    .. [1] F. Durand and J. Dorsey, Proc. EGWR 2000, pp. 219–230.
    .. [2] S. N. Pattanaik et al., Proc. SIGGRAPH 2000, pp. 47–54.
    """
    if not (dt >= 0 and time_constant >= 0):
        raise ValueError(f"need dt ≥ 0 and time_constant ≥ 0 [s], got {dt!r}, {time_constant!r}")
    previous = np.asarray(previous, dtype=np.float64)
    target = np.asarray(target, dtype=np.float64)
    if not (np.all(previous > 0) and np.all(target > 0)):
        raise ValueError("adaptation luminances must be > 0 [cd/m²]")
    keep = math.exp(-dt / time_constant) if time_constant > 0 else 0.0  # e^{−Δt/τ}, [1]

    return np.exp(np.log(target) + (np.log(previous) - np.log(target)) * keep)


def adaptation_history_frames(time_constant: float, fps: float) -> int:
    """Frames of history a frame's adaptation state is computed from [-]: ⌈4 τ · fps⌉ (0 for τ = 0)."""
    if not (time_constant >= 0 and fps > 0 and math.isfinite(time_constant) and math.isfinite(fps)):
        raise ValueError(f"need a finite time_constant ≥ 0 [s] and fps > 0 [s⁻¹], got {time_constant!r}, {fps!r}")
    return int(math.ceil(HISTORY_TIME_CONSTANTS * time_constant * fps))


def adaptation_window(frame: int, time_constant: float, fps: float) -> range:
    """Frames whose targets decide ``frame``'s state: from max(0, frame − history) to ``frame``, inclusive."""
    return range(max(0, frame - adaptation_history_frames(time_constant, fps)), frame + 1)


def adapted_luminance(targets: ArrayLike, dt: float, time_constant: float) -> float:
    """State after the last of ``targets`` (one per frame, oldest first), adapted to the first at the start [cd/m²].

    Parameters
    ----------
    targets : array_like
        Target luminance of each frame of the window [cd/m²], > 0.
    dt : float
        Frame interval [s].
    time_constant : float
        τ [s].
    """
    targets = np.asarray(targets, dtype=np.float64).ravel()
    if targets.size == 0:
        raise ValueError("need at least one target luminance")
    state = targets[0]
    for target in targets[1:]:
        state = adaptation_step_DurandDorsey2000(state, target, dt, time_constant)

    return float(state)
