"""In-water sun sampling: the refracted-sun lobe's density, and single scattering of sunlight.

The single-scattering test renders a deep pool of isotropically scattering
water under the sun alone (sky scale 0), seen straight down through a nearly
flat surface, with paths limited to one scattering event; the radiance has a
closed form (below). Mitsuba's ``volpath`` cannot produce this image at all at
a usable sample count (the sun is reached only when a path happens to leave
within the sun's 0.5° disc), so the closed form is the reference.
"""

import numpy as np
import pytest

from oceanrender.optics.fresnel import refracted_cosine, transmittance_Fresnel
from oceanrender.render.integrator import register, split_integrator
from oceanrender.render.scene import look_at_transform, xyz_film
from oceanrender.render.underwater import cox_munk_mean_square_slope
from tests.tolerances import ROUNDOFF32

N_WATER = 1.333
#: Unit vector towards the sun, 40° above the horizon.
SUN = (0.0, -float(np.cos(np.radians(40.0))), float(np.sin(np.radians(40.0))))


def test_cox_munk_slope_variance():
    # Cox & Munk (1954): 0.003 + 5.12e-3 U; at 10 m/s 0.0542.
    assert cox_munk_mean_square_slope(10.0) == pytest.approx(0.0542)
    with pytest.raises(ValueError, match="wind_speed"):
        cox_munk_mean_square_slope(-1.0)


@pytest.mark.parametrize("alpha", [0.05, 0.3])
def test_sun_lobe_density_integrates_to_one_and_matches_its_samples(variant, alpha):
    import mitsuba as mi

    from oceanrender.render.underwater import sun_lobe_functions

    sample, pdf = sun_lobe_functions()
    n = 400_000
    rng = np.random.default_rng(7)
    u = mi.Point2f(rng.random(n), rng.random(n))
    sun = mi.Vector3f(*[float(c) for c in SUN])
    d, p = sample(u, sun, N_WATER, alpha)
    d_np, p_np = np.array(d), np.array(p)
    valid = p_np > 0
    assert valid.mean() > 0.97
    # Directions point up, into the surface; the density evaluated at a sample is the sample's.
    assert np.all(d_np[2, valid] > 0)
    # Two float32 formulas for one density (the sampler's Jacobian, the direct evaluation):
    # 2e-3 relative; the far tails (down to 1e-5 of the peak) relative to the peak.
    np.testing.assert_allclose(np.array(pdf(d, sun, N_WATER, alpha))[valid], p_np[valid], rtol=2e-3,
                               atol=ROUNDOFF32 * p_np[valid].max())
    # ∫ q dω over the upper hemisphere by uniform-hemisphere Monte Carlo: the mass of
    # the facets that refract the sun (all but the few facing away from it).
    m = 4_000_000
    w = mi.warp.square_to_uniform_hemisphere(mi.Point2f(rng.random(m), rng.random(m)))
    values = np.array(pdf(w, sun, N_WATER, alpha)) * 2.0 * np.pi
    standard_error = values.std() / np.sqrt(m)
    assert abs(values.mean() - valid.mean()) < 4.0 * standard_error + 0.005, (values.mean(), standard_error)
    # The lobe is centred on the direction of the sunlight refracted by a flat surface.
    cos_t = refracted_cosine(np.sin(np.radians(40.0)), 1.0, N_WATER)
    mean_d = d_np[:, valid].mean(axis=1)
    assert mean_d[2] / np.linalg.norm(mean_d) == pytest.approx(cos_t, abs=0.02 + alpha / 5)


def pool_scene(max_depth, spp, clamp=0.0):
    """Deep pool (σ_t = 2 m⁻¹, albedo 0.3, isotropic), sun only, camera 1 m up looking straight down."""
    import mitsuba as mi

    register()
    return mi.load_dict({
        "type": "scene",
        "integrator": split_integrator(max_depth, 5, sun=SUN, water_ior=N_WATER, sun_lobe_alpha=0.02,
                                       in_water_clamp=clamp),
        "sensor": {"type": "perspective", "fov": 20.0, "fov_axis": "x",
                   "to_world": look_at_transform((0.0, 0.0, 1.0), (0.0, 0.0, 0.0)),
                   "film": xyz_film(16, 16), "sampler": {"type": "independent", "sample_count": spp}},
        "sky": {"type": "sunsky", "sun_direction": list(SUN), "turbidity": 3.0, "sky_scale": 0.0},
        "pool": {"type": "cube",
                 "to_world": mi.ScalarTransform4f().translate([0.0, 0.0, -10.0]).scale([200.0, 200.0, 10.0]),
                 "bsdf": {"type": "roughdielectric", "distribution": "beckmann", "alpha": 0.02,
                          "int_ior": N_WATER, "ext_ior": 1.0},
                 "interior": {"type": "homogeneous", "sigma_t": 2.0, "albedo": 0.3,
                              "phase": {"type": "isotropic"}}},
    })


def white_plane_scene(spp):
    """A white Lambertian plane under the same sun, seen straight down: L = E cosθ_z / π."""
    import mitsuba as mi

    return mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 2},
        "sensor": {"type": "perspective", "fov": 20.0, "fov_axis": "x",
                   "to_world": look_at_transform((0.0, 0.0, 1.0), (0.0, 0.0, 0.0)),
                   "film": xyz_film(16, 16), "sampler": {"type": "independent", "sample_count": spp}},
        "sky": {"type": "sunsky", "sun_direction": list(SUN), "turbidity": 3.0, "sky_scale": 0.0},
        "ground": {"type": "rectangle", "to_world": mi.ScalarTransform4f().scale([100.0, 100.0, 1.0]),
                   "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 1.0}}},
    })


@pytest.mark.render
def test_single_scattering_of_sunlight_matches_the_closed_form(variant):
    import mitsuba as mi

    # Paths: camera → surface (1) → one scattering event (2) → surface (3) → sun.
    water = pool_scene(max_depth=3, spp=256)
    white = white_plane_scene(spp=64)
    Y_water = np.array(mi.render(water, seed=1))[..., 1].mean()
    Y_white = np.array(mi.render(white, seed=1))[..., 1].mean()

    # Perpendicular solar irradiance through ȳ from the white plane: E⊥ = π L / cos θ_z.
    cos_z = SUN[2]
    E_perp = np.pi * Y_white / cos_z
    # Below a flat surface the beam travels at θ_t with perpendicular irradiance
    # E_w = E⊥ T(θ_i) cos θ_i / cos θ_t (the flux through the horizontal is conserved).
    cos_t = float(refracted_cosine(cos_z, 1.0, N_WATER))
    E_w = E_perp * float(transmittance_Fresnel(cos_z, 1.0, N_WATER)) * cos_z / cos_t
    # Single scattering seen straight up from just below the surface, infinitely deep water:
    # L(0⁻) = ∫₀^∞ σ_s p E_w e^{−σ_t z / cos θ_t} e^{−σ_t z} dz = σ_s p E_w / (σ_t (1 + 1/cos θ_t)),
    # p = 1/4π; above the surface L = L(0⁻) T(0) / n² (radiance across an interface, Walter et al. 2007).
    sigma_t, albedo = 2.0, 0.3
    L_below = albedo * sigma_t / (4.0 * np.pi) * E_w / (sigma_t * (1.0 + 1.0 / cos_t))
    expected = L_below * float(transmittance_Fresnel(1.0, N_WATER, 1.0)) / N_WATER**2
    # Tolerance: Monte Carlo (~1 %) and the surface's 0.02 roughness.
    print(f"single scattering: rendered {Y_water:.6g}, closed form {expected:.6g}, ratio {Y_water / expected:.4f}")
    assert Y_water == pytest.approx(expected, rel=0.04)


@pytest.mark.slow
@pytest.mark.render
def test_in_water_clamp_bounds_the_samples_and_is_inert_when_high(variant):
    import mitsuba as mi

    plain, high, low = (pool_scene(3, 16, clamp) for clamp in (0.0, 1e9, 1e-4))
    images = [np.array(mi.render(scene, seed=3))[..., 1] for scene in (plain, high, low)]
    # An inert clamp is still a different float32 kernel: last bits only (pixels > 0).
    np.testing.assert_allclose(images[1], images[0], rtol=ROUNDOFF32)
    # Clamped to 1e-4 W m⁻² sr⁻¹ nm⁻¹ per sample and wavelength: Y ≤ 1e-4 · ∫ȳ · T(0)/n² < 0.011.
    assert images[2].max() < 1e-4 * 106.857 and images[2].mean() < 0.05 * images[0].mean()
    with pytest.raises(ValueError, match="in_water_clamp"):
        split_integrator(3, 5, sun=SUN, in_water_clamp=-1.0)


#: Extinction per channel of the hero-wavelength unit test [m⁻¹]: a 60-fold spread, as sea water's.
CHANNEL_SIGMA_T = (0.05, 0.3, 1.0, 3.0)


def test_hero_free_flight_update_is_unbiased_and_bounded(variant):
    import drjit as dr
    import mitsuba as mi

    from oceanrender.render.underwater import hero_free_flight_update

    if dr.size_v(mi.Spectrum) != len(CHANNEL_SIGMA_T):
        pytest.skip("needs a 4-channel spectral variant")
    # Paths of k flights of length ℓ through a homogeneous medium, each flight sampled on the
    # path's hero channel h (uniform); a path contributes where every flight passes (the
    # track-length estimator of the transmittance T_i = e^{−σ_i k ℓ}).
    n, k, length = 400_000, 3, 1.0
    rng = np.random.default_rng(11)
    sigma = np.array(CHANNEL_SIGMA_T)
    hero = rng.integers(0, 4, n)
    passes = np.all(rng.exponential(1.0 / sigma[hero][:, None], (n, k)) > length, axis=1)
    tr = mi.Spectrum(*[float(np.exp(-s * length)) for s in sigma])
    weight, ratio = mi.Spectrum(1.0), mi.Spectrum(1.0)
    per_flight = mi.Spectrum(1.0)
    for _ in range(k):
        weight, ratio = hero_free_flight_update(weight, ratio, tr, tr)
        per_flight, _ = hero_free_flight_update(per_flight, mi.Spectrum(1.0), tr, tr)
    # Every path has the same flights, so the weights are one value per channel.
    w = np.array([dr.ravel(weight[c])[0] for c in range(4)])
    w_flight = np.array([dr.ravel(per_flight[c])[0] for c in range(4)])
    expected = np.exp(-sigma * k * length)
    estimate = passes[:, None] * w[None, :]
    se = estimate.std(axis=0) / np.sqrt(n)
    # Unbiased in every channel (balance heuristic over the path densities, Wilkie et al. 2014).
    assert np.all(np.abs(estimate.mean(axis=0) - expected) < 4.0 * se + ROUNDOFF32 * expected), (
        estimate.mean(axis=0), expected, se)
    # Each channel weighted at most C = 4 times as strongly as if it had been sampled itself.
    assert np.all(w <= 4.0 * (1.0 + ROUNDOFF32))
    # The scheme it replaced, each flight weighted by the mean of its own densities while every
    # flight is sampled on the same channel: biased for k > 1 (here +125 % in every channel:
    # mean_h Π ≠ Π mean), and its weights exceed the bound C (they grow like C^k).
    old = passes[:, None] * w_flight[None, :]
    assert np.all(old.mean(axis=0) > expected + 10.0 * se), (old.mean(axis=0), expected)
    assert w_flight.max() > 4.0


def deep_pool_scene(sigma_t, spp):
    """A deep, wide pool (albedo 0.8, σ_t(λ) ≥ 1 m⁻¹: 20 optical depths) under sun and sky, seen from 2 m."""
    import mitsuba as mi

    register()
    return mi.load_dict({
        "type": "scene",
        "integrator": split_integrator(64, 5, sun=SUN, water_ior=N_WATER, sun_lobe_alpha=0.1),
        "sensor": {"type": "perspective", "fov": 40.0, "fov_axis": "x",
                   "to_world": look_at_transform((0.0, 0.0, 2.0), (0.0, 2.0, 0.0)),
                   "film": xyz_film(16, 16), "sampler": {"type": "independent", "sample_count": spp}},
        "sky": {"type": "sunsky", "sun_direction": list(SUN), "turbidity": 3.0},
        "pool": {"type": "cube",
                 "to_world": mi.ScalarTransform4f().translate([0.0, 0.0, -10.0]).scale([100.0, 100.0, 10.0]),
                 "bsdf": {"type": "roughdielectric", "distribution": "beckmann", "alpha": 0.1,
                          "int_ior": N_WATER, "ext_ior": 1.0},
                 "interior": {"type": "homogeneous", "albedo": 0.8,
                              "sigma_t": {"type": "irregular", "wavelengths": "360, 830",
                                          "values": f"{sigma_t[0]}, {sigma_t[1]}"}}},
    })


@pytest.mark.slow
@pytest.mark.render
def test_a_deep_medium_looks_the_same_whatever_its_extinction_spectrum(variant):
    import mitsuba as mi

    # With a constant albedo, the radiance leaving an optically semi-infinite medium depends
    # on its optical depths alone (the radiative transfer equation in τ = σ_t z): a pool whose
    # σ_t rises from 1 to 8 m⁻¹ over the spectrum (sea water's shape: clear in the violet)
    # must look like one with σ_t = 1 m⁻¹ everywhere. The per-flight channel weighting this
    # replaced made it +5 % brighter and +20 % bluer (Z), with 20× the standard error.
    spp, seeds = 32, 4
    films = {}
    for name, sigma_t in {"grey": (1.0, 1.0), "chromatic": (1.0, 8.0)}.items():
        scene = deep_pool_scene(sigma_t, spp)
        films[name] = np.stack([np.array(mi.render(scene, seed=s)) for s in range(seeds)])
    means, errors = {}, {}
    for name, film in films.items():
        pixels = film.reshape(seeds, -1, 3)
        means[name] = pixels.mean(axis=(0, 1))
        errors[name] = np.sqrt(pixels.var(axis=0, ddof=1).sum(axis=0) / seeds) / pixels.shape[1]
    z = (means["chromatic"] - means["grey"]) / np.hypot(errors["chromatic"], errors["grey"])
    # |z| < 4: see Z_MAX in test_integrator.py (3 comparisons, false alarm < 2e-4).
    assert np.all(np.abs(z) < 4.0), (z, means, errors)
    # The test sees a bias of 3 %.
    assert np.all(4.0 * np.hypot(errors["chromatic"], errors["grey"]) < 0.03 * means["grey"]), errors
    # No spectral fireflies: the chromatic medium's noise is the grey one's (measured 0.9×).
    assert np.all(errors["chromatic"] < 2.0 * errors["grey"]), errors
