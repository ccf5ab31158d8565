"""Sunlight inside the water: the sun's beam refracted through the sea's own surface and followed down.

The waves focus the sun: each facet of the surface refracts the beam by its own slope
(Snell's law), and where neighbouring facets send their light to the same place below,
the light concentrates — caustic networks on a seafloor, shafts in the water. This
module follows the beam by *light tracing*: a regular grid of sun rays, one per node of
the surface's rest grid, each carrying the power its facet intercepts (the sun's normal
irradiance times the facet's area seen from the sun, times Fresnel's transmittance),
refracted at the facet and landed on horizontal planes below, where the powers are
splatted into cells (bilinear weights). The irradiance of a cell is the power it
receives over its area: a histogram density estimate whose only bias is the cell size
(and the ray spacing, which must be finer), so it converges as both are refined (the
resolution parameters, named where they are used).

What is left out, stated: shadowing of one wave by another (the sun is taken high enough
that every facet facing it is lit) and the light the surface reflects back down after a
total internal reflection; the sun is a point (its 0.53° disk would soften caustics
deeper than a few metres, Lynch & Livingston 2001, §3.6).

References
----------
.. [1] M. Born and E. Wolf, *Principles of Optics*, 7th ed., Cambridge, 1999, §4.4
   (refraction at a spherical surface; the paraxial focal length n/((n − 1) κ) of a
   surface of curvature κ seen from the denser medium).
.. [2] D. K. Lynch and W. Livingston, *Color and Light in Nature*, 2nd ed., Cambridge,
   2001 (caustics under water).
.. [3] M. Pharr, W. Jakob and G. Humphreys, *Physically Based Rendering*, 4th ed., 2023,
   §9.3 (Snell's law in vector form) and §15.2 (light tracing).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..optics.fresnel import refract, transmittance_Fresnel

__all__ = ["refracted_beam", "facet_power", "plane_irradiance", "refined_plane_irradiance", "paraxial_focal_depth"]


def paraxial_focal_depth(amplitude: float, wavenumber: float, n_water: float) -> float:
    """Depth [m] below a crest of η = a cos kx at which a vertical beam first focuses.

    The crest is a refracting surface of curvature κ = a k² [m⁻¹] seen from the air; its
    paraxial focal length in the water is f = n / ((n − 1) κ) (Born & Wolf 1999, §4.4, the
    image distance of an object at infinity), n the water's index relative to air.
    Example: a 0.5 m wave of 1 cm amplitude, n = 1.34: f = 2.50 m.
    """
    return float(n_water) / ((float(n_water) - 1.0) * float(amplitude) * float(wavenumber) ** 2)


def refracted_beam(normals: ArrayLike, sun: ArrayLike, n_water: float) -> tuple[NDArray, NDArray]:
    """(unit directions of the refracted beam, Fresnel transmittance [-]) at facets of unit ``normals``.

    ``sun``: unit vector towards the sun (z up). The beam travels along −sun; a facet facing
    away from the sun (n·sun ≤ 0) transmits nothing (transmittance 0, direction straight down).
    Snell's law in vector form (Pharr et al. 2023, §9.3) with the relative index 1/n; the
    transmittance is Fresnel's for unpolarised light (:func:`~oceanrender.optics.fresnel.transmittance_Fresnel`).
    """
    n = np.asarray(normals, np.float64)
    s = np.asarray(sun, np.float64) / np.linalg.norm(sun)
    cos_i = np.sum(n * s, axis=-1)
    lit = cos_i > 0.0
    directions = refract(np.broadcast_to(-s, n.shape), n, 1.0 / float(n_water))
    directions = np.where(lit[..., None], directions, (0.0, 0.0, -1.0))
    transmittance = np.where(lit, transmittance_Fresnel(np.clip(cos_i, 0.0, 1.0), 1.0, float(n_water)), 0.0)
    return directions, transmittance


def facet_power(area_vectors: ArrayLike, sun: ArrayLike, normal_irradiance: float, rest_area: float) -> NDArray:
    """Power [W] (or W nm⁻¹) the sun's beam brings to each facet: E_n max(0, sun·N) A₀.

    ``area_vectors``: N = ∂p/∂x₀ × ∂p/∂y₀ of the displaced surface per unit rest area [-] (its
    length is the facet's area over its rest area ``rest_area`` [m²], its direction the
    normal); ``normal_irradiance`` E_n: the beam's irradiance on a plane facing the sun
    [W m⁻²]. Over a periodic patch Σ N A₀ = L² ẑ, so the facets facing the sun intercept
    E_n sun_z L² when none faces away: the beam's flux through the patch's horizontal area.
    """
    s = np.asarray(sun, np.float64) / np.linalg.norm(sun)
    projected = np.sum(np.asarray(area_vectors, np.float64) * s, axis=-1)
    return float(normal_irradiance) * np.maximum(projected, 0.0) * float(rest_area)


def plane_irradiance(points: ArrayLike, directions: ArrayLike, power: ArrayLike, depths: ArrayLike,
                     origin: tuple[float, float], cell: float, shape: tuple[int, int],
                     attenuation: float = 0.0, periodic: bool = True) -> NDArray[np.float64]:
    """Downward irradiance [W m⁻²] on horizontal planes at heights ``depths`` [m] (below the surface, z < η).

    Each ray starts at ``points`` (the facet, [m]) along unit ``directions`` (downward) with
    ``power`` [W]; it reaches the plane z after the path s = (z − p_z)/d_z [m], is attenuated
    by exp(−c s) (``attenuation`` c [m⁻¹], the beam attenuation a + b: what is scattered out of
    the beam is no longer in it — that light is the path tracer's, from the vertex where it
    scatters), and its power is shared bilinearly among the four cells around its landing
    point. Cells are ``cell`` [m] squares, ``shape`` (ny, nx), cell (i, j) centred at
    ``origin`` + ((j + ½) cell, (i + ½) cell); ``periodic``: the grid wraps (a periodic
    patch), else power landing outside is dropped. Returns (len(depths), ny, nx): the
    power per cell over the cell's area — a histogram estimate of the irradiance whose
    bias is the cell size (converges as the cell and the ray spacing are refined).
    """
    p = np.asarray(points, np.float64).reshape(-1, 3)
    d = np.asarray(directions, np.float64).reshape(-1, 3)
    w = np.asarray(power, np.float64).reshape(-1)
    down = d[:, 2] < 0.0
    p, d, w = p[down], d[:, :][down], w[down]
    ny, nx = int(shape[0]), int(shape[1])
    out = np.zeros((len(np.atleast_1d(depths)), ny, nx))
    for k, z in enumerate(np.atleast_1d(np.asarray(depths, np.float64))):
        s = (z - p[:, 2]) / d[:, 2]
        ok = s >= 0.0
        u = (p[ok, 0] + s[ok] * d[ok, 0] - origin[0]) / cell - 0.5
        v = (p[ok, 1] + s[ok] * d[ok, 1] - origin[1]) / cell - 0.5
        value = w[ok] * np.exp(-float(attenuation) * s[ok])
        j0, i0 = np.floor(u), np.floor(v)
        fu, fv = u - j0, v - i0
        j0, i0 = j0.astype(np.int64), i0.astype(np.int64)
        for dj, di, share in ((0, 0, (1 - fu) * (1 - fv)), (1, 0, fu * (1 - fv)),
                              (0, 1, (1 - fu) * fv), (1, 1, fu * fv)):
            jj, ii = j0 + dj, i0 + di
            if periodic:
                jj, ii = jj % nx, ii % ny
                keep = slice(None)
            else:
                keep = (jj >= 0) & (jj < nx) & (ii >= 0) & (ii < ny)
                jj, ii = jj[keep], ii[keep]
            out[k] += np.bincount(ii * nx + jj, weights=(value * share)[keep], minlength=nx * ny).reshape(ny, nx)
    return out / (float(cell) ** 2)


def refined_plane_irradiance(points: ArrayLike, directions: ArrayLike, power: ArrayLike, depths: ArrayLike,
                             origin: tuple[float, float], cell: float, shape: tuple[int, int],
                             attenuation: float = 0.0, refine: int = 4) -> NDArray[np.float64]:
    """:func:`plane_irradiance` of rays given on a regular rest grid, each grid quad refined into ``refine``²
    rays (not periodic: the window is open).

    ``points``, ``directions`` (ny, nx, 3) and ``power`` (ny, nx) at the grid's nodes [m, -, W], the
    power that of the node's rest cell. Where the waves focus, neighbouring rays part by more
    than a cell and a histogram of the nodes' rays alone shows them one by one (a hatching);
    inside each quad the surface is taken bilinear — positions and directions interpolated
    between its four nodes (directions renormalised), power density too — and sampled at
    ``refine``² stratified points, each with the quad's mean power density times its share
    of the quad (power/``refine``²). A resolution parameter like the cell: the estimate
    converges as the rays get denser than the cells wherever the light goes.
    """
    p = np.asarray(points, np.float64)
    d = np.asarray(directions, np.float64)
    w = np.asarray(power, np.float64)
    m = int(refine)
    out = None
    corners = ((slice(None, -1), slice(None, -1)), (slice(None, -1), slice(1, None)),
               (slice(1, None), slice(None, -1)), (slice(1, None), slice(1, None)))
    for a in range(m):
        fy = (a + 0.5) / m
        for b in range(m):
            fx = (b + 0.5) / m
            shares = ((1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy)
            sp = sum(s * p[c] for s, c in zip(shares, corners))
            sd = sum(s * d[c] for s, c in zip(shares, corners))
            sd /= np.linalg.norm(sd, axis=-1, keepdims=True)
            sw = sum(s * w[c] for s, c in zip(shares, corners)) / (m * m)
            part = plane_irradiance(sp, sd, sw, depths, origin, cell, shape, attenuation, periodic=False)
            out = part if out is None else out + part
    return out
