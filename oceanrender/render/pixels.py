"""Samples for chosen pixels: the renderer behind adaptive sampling (issue 16).

``mi.render`` gives every pixel the same number of samples. :class:`PixelSampler`
renders a list of sample slots, each naming its pixel, through the scene's own
sensor and integrator, and accumulates them per pixel on the host: so a pass
can give each pixel its own count. A sample is made as Mitsuba's
``SamplingIntegrator::render_sample`` makes it (``src/render/integrator.cpp``,
Mitsuba 3.9.1): a uniform position in the pixel (box filter), a wavelength
sample, the sensor's ray, ``integrator.sample``; and it is developed into the
film's channels as ``specfilm`` does (``src/films/specfilm.cpp``,
``prepare_sample``): the radiance at the sample's wavelengths times the ray's
weight, divided by the film's total response, dotted with each channel's
response and averaged over the wavelengths. So a uniform pass has the
expectation of ``mi.render`` (tested). Ray differentials are left unscaled
(no texture here is filtered by them).

Every launch has the same number of lanes (:data:`LANES`; unused lanes are
masked off): a new wavefront size would compile a new kernel, and the seed is an
opaque value, so all passes of a sequence run one compiled kernel per integrator.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .renderer import K_M
from .scene import cmf_response_spectra

#: Sample slots per kernel launch [-]: one compiled kernel for every pass (2¹⁷, ≈ 0.4 s here).
LANES = 1 << 17


@dataclass
class PixelSums:
    """Per-pixel sums of XYZ [cd m⁻²] and sample counts, in two independent halves A and B.

    Samples alternate between the halves per pixel, so ``A/nA`` and ``B/nB``
    are independent estimates of each pixel; their difference measures its noise.
    """

    width: int
    height: int
    sums: np.ndarray = field(init=False)    # (2, H·W, 3) float64
    counts: np.ndarray = field(init=False)  # (2, H·W) int64

    def __post_init__(self):
        self.sums = np.zeros((2, self.width * self.height, 3))
        self.counts = np.zeros((2, self.width * self.height), dtype=np.int64)

    def add(self, pixels: np.ndarray, xyz: np.ndarray) -> None:
        """Add samples ``xyz`` (N, 3) of ``pixels`` (N,), alternating halves per pixel's running count."""
        n = self.width * self.height
        # The k-th new sample of a pixel goes to half (count_so_far + k) mod 2.
        order = np.argsort(pixels, kind="stable")
        sorted_pixels = pixels[order]
        starts = np.searchsorted(sorted_pixels, sorted_pixels, side="left")
        rank = np.empty_like(order)
        rank[order] = np.arange(order.size) - starts
        half = (self.counts.sum(axis=0)[pixels] + rank) % 2
        for h in (0, 1):
            sel = half == h
            self.counts[h] += np.bincount(pixels[sel], minlength=n)
            for c in range(3):
                self.sums[h, :, c] += np.bincount(pixels[sel], weights=xyz[sel, c], minlength=n)

    def image(self) -> np.ndarray:
        """Mean XYZ per pixel (H, W, 3) [cd m⁻²] (pixels without samples: 0)."""
        total = self.counts.sum(axis=0)
        return (self.sums.sum(axis=0) / np.maximum(total, 1)[:, None]).reshape(self.height, self.width, 3)

    def halves(self) -> tuple[np.ndarray, np.ndarray]:
        """The two independent half estimates (H, W, 3) [cd m⁻²]."""
        a, b = (self.sums[h] / np.maximum(self.counts[h], 1)[:, None] for h in (0, 1))
        return a.reshape(self.height, self.width, 3), b.reshape(self.height, self.width, 3)

    def per_pixel_counts(self) -> np.ndarray:
        """Samples per pixel (H, W) [-]."""
        return self.counts.sum(axis=0).reshape(self.height, self.width)


class PixelSampler:
    """Renders sample slots of chosen pixels with a loaded scene's sensor and an integrator (JIT variants)."""

    def __init__(self, scene, integrator=None, lanes: int = LANES):
        import mitsuba as mi  # noqa: PLC0415

        self.scene = scene
        self.integrator = integrator if integrator is not None else scene.integrator()
        self.sensor = scene.sensors()[0]
        self.width, self.height = (int(v) for v in self.sensor.film().crop_size())
        self.lanes = int(lanes)
        self.sampler = self.sensor.sampler().clone()  # once: a new object per launch could recompile
        # The film's total response and one response per XYZ channel (specfilm's m_srf, m_srfs).
        self.total_response = self.sensor.film().sensor_response_function()
        spectra = cmf_response_spectra()
        self.responses = [mi.load_dict({"type": "spectrum", "value": spectra[k]}) for k in ("X", "Y", "Z")]

    def _launch(self, pixels: np.ndarray, seed: int) -> np.ndarray:
        """XYZ [cd m⁻²] of one sample for each of up to ``lanes`` pixel indices → (N, 3)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        n = pixels.size
        padded = np.zeros(self.lanes, dtype=np.uint32)
        padded[:n] = pixels
        active = mi.Bool(np.arange(self.lanes) < n)
        index = mi.UInt32(padded)
        sampler = self.sampler
        sampler.seed(dr.opaque(mi.UInt32, int(seed) % (1 << 32)), self.lanes)
        x = mi.Float(index % self.width)
        y = mi.Float(index // self.width)
        position = mi.Point2f(x, y) + sampler.next_2d(active)  # box filter: uniform in the pixel
        wavelength_sample = sampler.next_1d(active)
        adjusted = position / mi.ScalarVector2f(self.width, self.height)
        ray, weight = self.sensor.sample_ray_differential(0.0, wavelength_sample, adjusted, mi.Point2f(0.5),
                                                          active)
        radiance, _, _ = self.integrator.sample(self.scene, sampler, ray, None, active)
        si = dr.zeros(mi.SurfaceInteraction3f)
        si.wavelengths = ray.wavelengths
        total = self.total_response.eval(si)
        values = weight * radiance * dr.select(total != 0.0, dr.rcp(total), 1.0)
        channels = []
        for response in self.responses:
            weights = response.eval(si)
            channels.append(sum(weights[i] * values[i] for i in range(len(values))) / len(values))
        dr.eval(*channels)  # one kernel for all three (each np.array() alone would trace the path again)
        out = np.stack([np.array(c) for c in channels], axis=-1)[:n]
        return K_M * out.astype(np.float64)

    def render(self, counts: np.ndarray, seed: int, into: PixelSums | None = None) -> PixelSums:
        """Add ``counts`` (H, W) samples per pixel [-] to ``into`` (a new :class:`PixelSums` if None).

        Launch k uses seed ``seed + k``: give passes disjoint seed ranges.
        """
        sums = into if into is not None else PixelSums(self.width, self.height)
        flat = np.asarray(counts, dtype=np.int64).reshape(-1)
        slots = np.repeat(np.arange(flat.size, dtype=np.int64), flat)
        for k, start in enumerate(range(0, slots.size, self.lanes)):
            pixels = slots[start:start + self.lanes]
            sums.add(pixels, self._launch(pixels, seed + k))
        return sums
