"""What every section of a scene file shares: :class:`SceneError`, the limits, the frozen model base
:class:`_Section`, the vector and interpolation types.

Part of :mod:`.settings` (which re-exports every name here); units and conventions there.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict


class SceneError(ValueError):
    """A scene file that cannot be used; the message is one line for the user."""


#: Largest sampler/wave seed: Mitsuba's samplers take a 32-bit unsigned seed.
SEED_MAX = (1 << 32) - 1
#: Most frames one run may hold (69 min at 24 fps): every frame is validated (camera path, sun) at load.
MAX_FRAME_COUNT = 100_000
#: Largest frame number [-] (frame files are numbered frame_NNNN with at least 4 digits).
MAX_FRAME = 10_000_000
#: Lowest sun elevation accepted [deg]: the sun's disc (0.53° wide) clear of the horizon.
MIN_SUN_ELEVATION = 0.5
#: Largest scene file accepted [bytes].
MAX_SCENE_BYTES = 1 << 20
#: Most bands of the spectral EXR [-]: 5 nm bands over 360–830 nm. Each band is a channel of Mitsuba's film, compiled
#: into every kernel: measured here (16×9 px, 1 spp, cold kernel cache) 6 s to render with 16 bands, 10 s with 96,
#: 18 s with 256, 41 s with 470 (0.86 GB), and a run with 470 was seen compiling for over 7 min on a loaded machine
#: (issue 39). Narrower bands carry nothing the renderer has: the sky's spectra are tabulated every 40 nm
#: (Hosek & Wilkie 2012) and the water's tables every 1–5 nm.
MAX_SPECTRAL_BANDS = 94
#: A scene name: a safe folder name (no "..", no hidden folder, no separator), at most 100 characters.
SAFE_NAME = r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}"


class _Section(BaseModel):
    # NOTE: allow_inf_nan=False: no NaN or infinity anywhere (vectors included) unless a field allows it.
    model_config = ConfigDict(extra="forbid", frozen=True, strict=False, allow_inf_nan=False)


Vec3 = tuple[float, float, float]


#: Interpolations of keyframed motion (see :mod:`oceanrender.scene.motion`).
Interpolation = Literal["monotone cubic", "Catmull-Rom"]
