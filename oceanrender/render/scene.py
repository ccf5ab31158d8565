"""Small functions that return Mitsuba 3 scene-description dicts.

The scene is assembled in memory from these pieces (no XML). World frame:
z up, +x east, +y north; scene units are metres, so Mitsuba's "inverse scene
units" for medium coefficients are m⁻¹. Spectra are in nm.

Call these only after a variant is set (:func:`oceanrender.runtime.activate_variant`).
"""

from __future__ import annotations

import math

import colour
import numpy as np

from ..optics.water import MediumOptics, WaterIOPs
from ..scene import CameraSettings, SunSettings
from ..scene.motion import CameraPose, SunAngles

#: Name of the CIE 1931 2° observer in colour-science.
CIE1931 = "CIE 1931 2 Degree Standard Observer"

#: Wavelength range of the rendered spectrum and of the film [nm].
FILM_RANGE_NM = (360.0, 830.0)


def sun_direction(elevation_deg: float, azimuth_deg: float) -> np.ndarray:
    """Unit vector towards the sun, world frame (z up, +y north, +x east).

    Parameters
    ----------
    elevation_deg : float   Elevation above the horizon [deg].
    azimuth_deg : float     Azimuth clockwise from north [deg].
    """
    el, az = math.radians(elevation_deg), math.radians(azimuth_deg)
    return np.array([math.sin(az) * math.cos(el), math.cos(az) * math.cos(el), math.sin(el)])


def cmf_response_spectra(wavelength_range: tuple[float, float] = FILM_RANGE_NM) -> dict[str, list[tuple[float, float]]]:
    """The CIE 1931 2° colour-matching functions x̄, ȳ, z̄ as (λ [nm], value) lists."""
    cmfs = colour.MSDS_CMFS[CIE1931].copy().trim(colour.SpectralShape(*wavelength_range, 1))
    wavelengths = cmfs.wavelengths
    return {
        name: list(zip(wavelengths.tolist(), cmfs.values[:, i].tolist()))
        for i, name in enumerate(("X", "Y", "Z"))
    }


def spectral_band_edges(bands: int, wavelength_range: tuple[float, float] = FILM_RANGE_NM) -> np.ndarray:
    """Edges [nm] of ``bands`` equal-width bands over the film's range, shape (bands + 1,)."""
    if int(bands) != bands or bands < 1:
        raise ValueError(f"bands must be a positive integer, got {bands!r}")
    return np.linspace(wavelength_range[0], wavelength_range[1], int(bands) + 1)


def band_channel_name(index: int) -> str:
    """Film channel of band ``index``: lower-case, so it sorts after X, Y, Z (Mitsuba orders channels by name)."""
    return f"b{index:03d}"


#: Maximum luminous efficacy of radiation for photopic vision [lm W⁻¹] (CIE 2004 / SI definition of the candela).
K_M = 683.0


def xyz_film(width: int, height: int, bands: int = 0, crop: tuple[int, int, int, int] | None = None) -> dict:
    """``specfilm`` whose three channels are ∫L x̄ dλ, ∫L ȳ dλ, ∫L z̄ dλ (and optionally ``bands`` more).

    With ``bands`` > 0, channels ∫_{λ_i}^{λ_{i+1}} L dλ over equal bands of the
    film's range follow (box response functions; :func:`spectral_band_edges`),
    in W m⁻² sr⁻¹ — divide by the band width for the mean spectral radiance.

    With radiance L in W m⁻² sr⁻¹ nm⁻¹ each channel is in W m⁻² sr⁻¹ (CIE-
    weighted); multiply by K_m = 683 lm W⁻¹ for cd m⁻². Channel names sort as
    X, Y, Z, which is the order Mitsuba stores them in. float32 storage: the
    default float16 overflows on the sun. ``crop`` (x, y, width, height) [px] renders only that
    window of the image (Mitsuba's ``crop_offset_*``/``crop_*``).
    """
    film = {
        "type": "specfilm",
        "width": int(width),
        "height": int(height),
        "component_format": "float32",
        "rfilter": {"type": "box"},
    }
    if crop is not None:
        x, y, w, h = (int(v) for v in crop)
        if not (0 <= x and 0 <= y and w > 0 and h > 0 and x + w <= width and y + h <= height):
            raise ValueError(f"crop {crop} must lie inside the {width}×{height} image")
        film.update(crop_offset_x=x, crop_offset_y=y, crop_width=w, crop_height=h)
    for name, values in cmf_response_spectra().items():
        film[name] = {"type": "spectrum", "value": values}
    if bands:
        edges = spectral_band_edges(bands)
        step = 1e-3  # [nm]: the box's edges
        for i, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
            points = [(lo, 1.0), (hi - step, 1.0), (hi, 0.0)] if i < bands - 1 else [(lo, 1.0), (hi, 1.0)]
            if i > 0:
                points.insert(0, (lo - step, 0.0))
            film[band_channel_name(i)] = {"type": "spectrum", "value": [(float(w), float(v)) for w, v in points]}
    return film


def white_plane_meter(emitter: dict, film: dict, samples: int) -> dict:
    """Scene dict: a white Lambertian disk under ``emitter``, seen straight down by an n×n-pixel orthographic sensor.

    Every pixel takes one sample (n = ⌈√samples⌉, so n² ≥ ``samples``): the
    mean over the pixels of ``mi.render`` is the radiance L = E/π of the white
    plane (uniform over the 2 m × 2 m view of a 10 km disk; Lambert's law), E
    the horizontal irradiance of ``emitter``. One sample per pixel keeps the
    reading identical from process to process: drjit's LLVM backend adds the
    samples of one pixel in the order its threads finish, so a 1-pixel meter of
    the same samples differed between runs by up to 1e-6 relative (measured:
    6 processes, 3 to 4 different readings at 64 and 16384 samples), which
    made a resumed sequence's display colours differ from an uninterrupted one's
    in the last bits. ``film`` is a 1×1 film dict; its size is replaced.
    """
    import mitsuba as mi  # noqa: PLC0415

    side = max(1, math.isqrt(int(samples) - 1) + 1)
    return {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 2},
        "sensor": {
            "type": "orthographic",
            "to_world": mi.ScalarTransform4f().look_at(origin=[0.0, 0.0, 1.0], target=[0.0, 0.0, 0.0],
                                                       up=[0.0, 1.0, 0.0]),
            "film": {**film, "width": side, "height": side, "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": 1},
        },
        "sky": emitter,
        "ground": {
            "type": "disk",
            "to_world": mi.ScalarTransform4f().scale([1.0e4, 1.0e4, 1.0]),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 1.0}},
        },
    }


def meter_reading(film: np.ndarray) -> np.ndarray:
    """Mean over the pixels of a :func:`white_plane_meter` render, per channel (float64, fixed order)."""
    values = np.asarray(film, dtype=np.float64)
    return values.reshape(-1, values.shape[-1]).mean(axis=0)


def look_at_transform(position, target):
    """Camera-to-world transform looking from ``position`` at ``target`` (z up)."""
    import mitsuba as mi  # noqa: PLC0415

    forward = np.subtract(target, position, dtype=float)
    forward /= np.linalg.norm(forward)
    up = [0.0, 0.0, 1.0] if abs(forward[2]) < 0.999 else [0.0, 1.0, 0.0]
    return mi.ScalarTransform4f().look_at(origin=list(map(float, position)), target=list(map(float, target)), up=up)


def perspective_sensor(camera: CameraSettings, film: dict, spp: int, sampler: str = "independent") -> dict:
    """Pinhole ``perspective`` sensor; ``camera.fov`` is the horizontal field of view [deg].

    ``sampler`` is Mitsuba's sampler plugin (``[render] sampler``): ``independent`` draws every
    number of every sample on its own; ``multijitter`` (Kensler 2013, correlated multi-jittered
    sampling) stratifies each dimension of a pixel's samples, the sensor's wavelength sample and
    pixel position among them, so the four wavelengths of the pixel's samples cover the spectrum
    evenly (issue 42: 0.70x the error at equal samples on the default scene); ``orthogonal``
    (Jarosz et al. 2019) rounds the count up to a prime's square. Every sample is uniform on its own
    in all of them: the estimate stays unbiased.

    Clip distances [m]: 1 cm, and 10⁸ m, beyond the water body's far ring
    (:func:`oceanrender.surface.radial_mesh.horizon_radius`: 1.1·10⁷ m from 1 km up),
    which Mitsuba's default (10⁴ m) would cut off, showing the black sky below the horizon.
    """
    return {
        "type": "perspective",
        "fov": float(camera.fov),
        "fov_axis": "x",
        "near_clip": 0.01,
        "far_clip": 1.0e8,
        "to_world": look_at_transform(camera.position, camera.target),
        "film": film,
        "sampler": {"type": sampler, "sample_count": int(spp)},
    }


def sunsky_emitter(sun: SunSettings) -> dict:
    """Mitsuba's ``sunsky`` (Hosek & Wilkie 2012 sky, 2013 sun), radiance in W m⁻² sr⁻¹ nm⁻¹.

    Its emitter frame is z up, like the world frame here, so no ``to_world``.
    NOTE: its spectral data end at 720 nm; radiance is zero above.
    """
    return {
        "type": "sunsky",
        "sun_direction": sun_direction(sun.elevation, sun.azimuth).tolist(),
        "turbidity": float(sun.turbidity),
        "albedo": float(sun.ground_albedo),
        "sun_scale": float(sun.sun_scale),
        "sky_scale": float(sun.sky_scale),
    }


def irregular_spectrum(wavelengths: np.ndarray, values: np.ndarray) -> dict:
    """An ``irregular`` Mitsuba spectrum from arrays (λ in nm)."""
    return {
        "type": "irregular",
        "wavelengths": ", ".join(f"{w:.6g}" for w in wavelengths),
        "values": ", ".join(f"{v:.8g}" for v in values),
    }


def water_medium(optics: WaterIOPs | MediumOptics) -> dict:
    """Homogeneous medium from the water's IOPs (σ_t = a + b [m⁻¹], albedo b/c).

    The phase function is Mitsuba's ``rayleigh`` (3/16π)(1 + cos²θ): the
    shape of molecular scattering; pure water's own VSF has 0.835 cos²θ
    (Morel 1974) because of depolarisation — within 5 % of this in the
    forward/backward directions. With particles (:class:`MediumOptics`) the
    phase function is ``blendphase`` of that Rayleigh shape and a
    Henyey–Greenstein lobe, weighted by the particles' share of scattering; when
    the optics carry that share and g per wavelength (``*_spectrum``, as
    :func:`oceanrender.optics.components.composition_optics` gives them), the
    blend is :mod:`oceanrender.render.phase`'s, which follows both with λ.
    """
    if isinstance(optics, MediumOptics):
        iops, fraction, g = optics.iops, optics.particle_fraction, optics.particle_g
    else:
        iops, fraction, g = optics, 0.0, 0.0
    lo, hi = FILM_RANGE_NM
    if iops.wavelengths[0] > lo or iops.wavelengths[-1] < hi:
        raise ValueError(
            f"water IOPs cover {iops.wavelengths[0]:g}-{iops.wavelengths[-1]:g} nm; "
            f"the medium must be defined over {lo:g}-{hi:g} nm"
        )
    phase = {"type": "rayleigh"}
    spectral = isinstance(optics, MediumOptics) and optics.particle_fraction_spectrum is not None
    if isinstance(optics, MediumOptics) and optics.phase_table is not None:
        from .phase import TABULATED_PLUGIN  # noqa: PLC0415 (registered by water_mesh before loading)

        mu, table = optics.phase_table
        step = np.diff(iops.wavelengths)
        if not np.allclose(step, step[0]):
            raise ValueError("a tabulated phase function needs IOPs on a uniform wavelength grid")
        phase = {"type": TABULATED_PLUGIN, "wavelengths": f"{iops.wavelengths[0]:.9g},{step[0]:.9g},{iops.wavelengths.size}",
                 "mu": ",".join(f"{x:.17g}" for x in mu), "values": ",".join(f"{x:.9g}" for x in np.ravel(table))}
    elif spectral and np.any(optics.particle_fraction_spectrum > 0):
        from .phase import PHASE_PLUGIN  # noqa: PLC0415 (registered by water_mesh before loading)

        g_spectrum = optics.particle_g_spectrum if optics.particle_g_spectrum is not None else np.full_like(
            iops.wavelengths, g)
        phase = {"type": PHASE_PLUGIN,
                 "weight": irregular_spectrum(iops.wavelengths, optics.particle_fraction_spectrum),
                 "g": irregular_spectrum(iops.wavelengths, g_spectrum)}
    elif fraction > 0:
        phase = {"type": "blendphase", "weight": float(fraction), "phase1": phase,
                 "phase2": {"type": "hg", "g": float(g)}}
    return {
        "type": "homogeneous",
        "sigma_t": irregular_spectrum(iops.wavelengths, iops.attenuation),
        "albedo": irregular_spectrum(iops.wavelengths, iops.single_scattering_albedo),
        "phase": phase,
        "scale": 1.0,
    }


#: Below this Beckmann α the surface is treated as perfectly smooth [-].
SMOOTH_ALPHA = 1e-3


#: Name of the per-vertex Beckmann α attribute of the water mesh.
ROUGHNESS_ATTRIBUTE = "vertex_roughness"


def water_surface_bsdf(ior: float, alpha: float, per_vertex: bool = False) -> dict:
    """Air–water interface: smooth ``dielectric`` or ``roughdielectric`` (Beckmann α).

    Parameters
    ----------
    ior : float         Refractive index of water relative to air [-].
    alpha : float       Beckmann roughness of the unresolved slopes [-].
    per_vertex : bool   Read α per vertex from the mesh attribute :data:`ROUGHNESS_ATTRIBUTE`
                        (a ``mesh_attribute`` texture, interpolated over each triangle) instead.

    Notes
    -----
    A rough interface also lets Mitsuba's next-event estimation reach the sun
    from under water (a delta interface blocks it), which is what makes the
    sun's light scattered inside the water converge at low spp.
    """
    if per_vertex:
        return {"type": "roughdielectric", "distribution": "beckmann",
                "alpha": {"type": "mesh_attribute", "name": ROUGHNESS_ATTRIBUTE},
                "int_ior": float(ior), "ext_ior": 1.0}
    if alpha < SMOOTH_ALPHA:
        return {"type": "dielectric", "int_ior": float(ior), "ext_ior": 1.0}
    return {"type": "roughdielectric", "distribution": "beckmann", "alpha": float(alpha),
            "int_ior": float(ior), "ext_ior": 1.0}


def volumetric_integrator(kind: str, max_depth: int, sun=None, water_ior: float = 1.333,
                          sun_lobe_alpha: float = 0.2, in_water_clamp: float = 0.0, rr_depth: int = 5,
                          lobes: str = "both") -> dict:
    """``volpath``, ``volpathmis`` or ``split`` with Russian roulette after ``rr_depth`` vertices.

    ``split`` is :class:`oceanrender.render.integrator.SplitSurfaceIntegrator`:
    volpath that follows both Fresnel lobes at the camera's first water hit
    (registered here on first use). Given ``sun`` (unit vector towards it), it
    also samples the sunlight refracted into the water at every in-water vertex
    (:mod:`oceanrender.render.underwater`; ``water_ior`` [-], ``sun_lobe_alpha``
    the total rms slope of the surface [-]; ``in_water_clamp`` the firefly clamp of
    the in-water radiance per sample [W m⁻² sr⁻¹ nm⁻¹], 0 for none); ``lobes`` which
    lobes of the split vertex a sample returns (``split`` only, see
    :func:`oceanrender.render.integrator.split_integrator`).
    """
    if kind == "split":
        from .integrator import register, split_integrator  # noqa: PLC0415

        register()
        return split_integrator(int(max_depth), rr_depth=int(rr_depth), sun=sun, water_ior=water_ior,
                                sun_lobe_alpha=sun_lobe_alpha, in_water_clamp=in_water_clamp, lobes=lobes)
    if lobes != "both":
        raise ValueError(f"only the 'split' integrator has single-lobe passes, not {kind!r}")
    return {"type": kind, "max_depth": int(max_depth), "rr_depth": int(rr_depth)}


def apply_camera(params, pose: CameraPose, sensor: str = "sensor") -> None:
    """Move a loaded ``perspective`` sensor (``fov_axis = "x"``) to ``pose``, in place.

    ``params`` is ``mi.traverse(scene)``; ``sensor`` the sensor's key in the
    scene dict. Sets ``<sensor>.to_world`` (look-at, z up, as
    :func:`look_at_transform`) and ``<sensor>.x_fov``
    [deg], then ``params.update()``: no reload.
    """
    params[f"{sensor}.to_world"] = look_at_transform(pose.position, pose.target)
    params[f"{sensor}.x_fov"] = float(pose.fov)
    params.update()


def apply_sun(params, angles: SunAngles, emitter: str = "sky") -> None:
    """Point a loaded ``sunsky`` emitter's sun at ``angles``, in place (``<emitter>.sun_direction``).

    Raises
    ------
    ValueError
        The sun is not above the horizon (``sunsky`` is defined for elevation > 0).
    """
    if not angles.elevation > 0:
        raise ValueError(f"the sun must be above the horizon for sunsky, got elevation {angles.elevation:g} deg")
    import mitsuba as mi  # noqa: PLC0415

    params[f"{emitter}.sun_direction"] = mi.Vector3f(*sun_direction(angles.elevation, angles.azimuth).tolist())
    params.update()
