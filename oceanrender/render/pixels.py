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

from .buffers import jit_bools, jit_uints
from .scene import K_M, cmf_response_spectra

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

    def __init__(self, scene, integrator=None, lanes: int = LANES, sensor: int = 0):
        import mitsuba as mi  # noqa: PLC0415

        self.scene = scene
        self.integrator = integrator if integrator is not None else scene.integrator()
        self.sensor_index = int(sensor)
        self.sensor = scene.sensors()[self.sensor_index]
        film = self.sensor.film()
        # pixels are numbered in the film's crop window; positions are in the whole image
        self.width, self.height = (int(v) for v in film.crop_size())
        self.offset = tuple(int(v) for v in film.crop_offset())
        self.size = tuple(int(v) for v in film.size())
        self.lanes = int(lanes)
        self.sampler = self.sensor.sampler().clone()  # once: a new object per launch could recompile
        # The film's total response and one response per XYZ channel (specfilm's m_srf, m_srfs).
        self.total_response = self.sensor.film().sensor_response_function()
        spectra = cmf_response_spectra()
        self.responses = [mi.load_dict({"type": "spectrum", "value": spectra[k]}) for k in ("X", "Y", "Z")]

    def launch(self, pixels: np.ndarray, seed: int) -> np.ndarray:
        """XYZ [cd m⁻²] of one sample for each of up to ``lanes`` pixel indices → (N, 3)."""
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        n = pixels.size
        padded = np.zeros(self.lanes, dtype=np.uint32)
        padded[:n] = pixels
        active = jit_bools(np.arange(self.lanes) < n)
        index = jit_uints(padded)
        sampler = self.sampler
        sampler.seed(dr.opaque(mi.UInt32, int(seed) % (1 << 32)), self.lanes)
        x = mi.Float(index % self.width + self.offset[0])
        y = mi.Float(index // self.width + self.offset[1])
        position = mi.Point2f(x, y) + sampler.next_2d(active)  # box filter: uniform in the pixel
        wavelength_sample = sampler.next_1d(active)
        adjusted = position / mi.ScalarVector2f(*self.size)
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
            sums.add(pixels, self.launch(pixels, seed + k))
        return sums


def grid_shape(width: int, height: int, columns: int) -> tuple[int, int]:
    """(rows, columns) of a grid of ``columns`` blocks across a ``width`` × ``height`` image, rows in its
    aspect, at most one block per pixel each way."""
    columns = max(1, min(int(columns), int(width)))
    return max(1, min(int(round(columns * height / width)), int(height))), columns


def grid_edges(width: int, height: int, rows: int, columns: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixel edges of the grid's blocks: block (r, c) is columns [x_c, x_{c+1}) and rows [y_r, y_{r+1})."""
    return (np.arange(columns + 1) * int(width)) // columns, (np.arange(rows + 1) * int(height)) // rows


def grid_mean(image: np.ndarray, columns: int) -> np.ndarray:
    """Mean of an (H, W) image over each block of :func:`grid_shape`'s grid → (rows, columns)."""
    height, width = image.shape[:2]
    rows, columns = grid_shape(width, height, columns)
    edges_x, edges_y = grid_edges(width, height, rows, columns)
    sums = np.add.reduceat(np.add.reduceat(np.asarray(image, float), edges_y[:-1], axis=0), edges_x[:-1], axis=1)
    return sums / np.outer(np.diff(edges_y), np.diff(edges_x))


def block_slots(width: int, height: int, columns: int, samples: int, seed: int) -> tuple[np.ndarray, np.ndarray, tuple]:
    """Pixels of ``samples`` samples in each block of a grid over a ``width`` × ``height`` image.

    The grid has ``columns`` blocks across (at most one per pixel) and rows in the image's aspect, each
    block the pixels [⌊j W/c⌋, ⌊(j+1) W/c⌋) × ..., so a block is a fixed fraction of the view whatever
    the resolution. Each sample picks a pixel of its block uniformly (numpy's PCG64 seeded by ``seed``:
    the same slots in every process); :class:`PixelSampler` then draws its position uniformly in the
    pixel, so the samples are uniform over the block's area.

    Returns (pixel index y·W + x per sample, block index per sample, (rows, columns)).
    """
    rows, columns = grid_shape(width, height, columns)
    edges_x, edges_y = grid_edges(width, height, rows, columns)
    block = np.repeat(np.arange(rows * columns), int(samples))
    bx, by = block % columns, block // columns
    rng = np.random.Generator(np.random.PCG64(int(seed)))
    x = edges_x[bx] + np.floor(rng.random(block.size) * (edges_x[bx + 1] - edges_x[bx])).astype(np.int64)
    y = edges_y[by] + np.floor(rng.random(block.size) * (edges_y[by + 1] - edges_y[by])).astype(np.int64)
    return y * int(width) + x, block, (rows, columns)


def block_means(sampler: PixelSampler, pixels: np.ndarray, blocks: np.ndarray, shape: tuple, seed: int) -> np.ndarray:
    """Mean XYZ [cd m⁻²] of each block (rows, columns, 3) from one sample per slot (``pixels``, ``blocks``
    from :func:`block_slots`), rendered by ``sampler`` with seeds ``seed``, ``seed`` + 1, ... per launch."""
    n = shape[0] * shape[1]
    sums = np.zeros((n, 3))
    for k, start in enumerate(range(0, pixels.size, sampler.lanes)):
        xyz = sampler.launch(pixels[start:start + sampler.lanes].astype(np.uint32), seed + k)
        for c in range(3):
            sums[:, c] += np.bincount(blocks[start:start + sampler.lanes], weights=xyz[:, c], minlength=n)
    counts = np.bincount(blocks, minlength=n)
    return (sums / np.maximum(counts, 1)[:, None]).reshape(*shape, 3)
