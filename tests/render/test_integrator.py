"""The split-surface integrator: same expectation as volpath, less noise, sky on misses.

Real renders of a tiny scene (24×16 px): three large water pools side by
side, with a smooth ``dielectric`` surface, a ``roughdielectric`` one
(Beckmann α = 0.085), and the rough one blended with 15 % white foam
(``blendbsdf``), each enclosing a homogeneous medium, under ``sunsky``, with
a black wall to the south that can put the pools in its shadow.

NOTE: all tests render the same three scenes with the same kernels: the
camera, the sun's direction and the medium's coefficients are changed in
place as opaque values. A changed literal (e.g. ``sky.sun_scale``) would
compile a new kernel, ~10 s for the split integrator on two CPU cores.
"""

import numpy as np
import pytest

from oceanrender.render.integrator import SPLIT_INTEGRATOR, register, split_integrator
from oceanrender.render.scene import look_at_transform, xyz_film
from tests.tolerances import ROUNDOFF32

pytestmark = pytest.mark.render

#: Largest accepted |z| of the difference of two image means, in combined standard errors.
#: With ~10³ degrees of freedom per standard error, |z| > 4 has probability 6e-5 per
#: comparison for an unbiased pair: 6 comparisons here give a false-alarm rate < 1e-3.
Z_MAX = 4.0

#: Sun towards the south-west, 40° high; the camera looks north (+y) or south.
SUN = [0.3, -0.72, 0.63]
#: Sun due south, 5° high: the wall's shadow covers the pools (no sunlight in the water).
LOW_SUN = [0.0, -0.99619, 0.08716]
#: Top and bottom of the black wall along y = −12 m [m]: its shadow under LOW_SUN reaches
#: y = 159 m, and it reaches below the pools' bottoms (there is no ground: sunlight
#: would otherwise come in under it).
WALL_TOP, WALL_BOTTOM = 15.0, -5.0
VOLPATH = {"type": "volpath", "max_depth": 12, "rr_depth": 5}

#: Camera 2 m above the water, 25° down: all water in view.
LOOK_NORTH = ((0.0, 0.0, 2.0), (0.0, 4.29, 0.0))
LOOK_SOUTH = ((0.0, 120.0, 2.0), (0.0, 115.71, 0.0))  # towards the sun: glints


#: Coverage of the foam blended into the third pool's surface [-].
FOAM = 0.15


def pool(x0, x1, bsdf, foam=0.0):
    """A 3 m deep box of water between x0 and x1 [m], y from −10 to 130 m, top at z = 0."""
    import mitsuba as mi

    surface = {"type": bsdf, "int_ior": 1.333, "ext_ior": 1.0}
    if bsdf == "roughdielectric":
        surface.update(distribution="beckmann", alpha=0.085)
    if foam:
        surface = {"type": "blendbsdf", "weight": foam, "bsdf_0": surface,
                   "bsdf_1": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 0.8}}}
    return {
        "type": "cube",
        "to_world": mi.ScalarTransform4f().translate([(x0 + x1) / 2, 60.0, -1.5]).scale([(x1 - x0) / 2, 70.0, 1.5]),
        "bsdf": surface,
        "interior": {"type": "homogeneous", "sigma_t": 0.3, "albedo": 0.8},
    }


def pools_scene(integrator, spp, sampler="independent"):
    """Smooth pool on the left, rough one in the middle, foamy one on the right, under sun and sky."""
    import mitsuba as mi

    register()
    return mi.load_dict({
        "type": "scene",
        "integrator": integrator,
        "sensor": {"type": "perspective", "fov": 60.0, "fov_axis": "x", "to_world": look_at_transform(*LOOK_NORTH),
                   "film": xyz_film(24, 16), "sampler": {"type": sampler, "sample_count": spp}},
        "sky": {"type": "sunsky", "sun_direction": SUN, "turbidity": 3.0},
        # NOTE: 1 cm gaps, so that neighbouring walls are not coplanar.
        "smooth": pool(-100.0, -1.5, "dielectric"),
        "rough": pool(-1.49, 1.49, "roughdielectric"),
        "foamy": pool(1.5, 100.0, "roughdielectric", foam=FOAM),
        "wall": {"type": "rectangle",
                 "to_world": mi.ScalarTransform4f().translate([0.0, -12.0, (WALL_TOP + WALL_BOTTOM) / 2])
                 .rotate([1.0, 0.0, 0.0], 90.0).scale([110.0, (WALL_TOP - WALL_BOTTOM) / 2, 1.0]),
                 "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 0.0}}},
    })


def configure(scene, camera, sun, albedo, sigma_t=0.3):
    """Move the camera and the sun (unit vector towards it), change the water, in place.

    ``sigma_t`` is the water's extinction coefficient [m⁻¹], ``albedo`` its
    single-scattering albedo [-]. They are set as opaque values: a Python
    float would become a literal of the kernel, compiled anew for each value.
    """
    import drjit as dr
    import mitsuba as mi

    params = mi.traverse(scene)
    params["sensor.to_world"] = look_at_transform(*camera)
    params["sky.sun_direction"] = mi.Vector3f(sun)
    for key in params.keys():
        if key.endswith("interior_medium.albedo.value.value"):
            params[key] = dr.opaque(mi.Float, albedo)
        if key.endswith("interior_medium.sigma_t.value.value"):
            params[key] = dr.opaque(mi.Float, sigma_t)
    params.update()


def renders(scene, seeds, spp):
    """(seeds, H, W, 3) films [W m⁻² sr⁻¹]."""
    import mitsuba as mi

    return np.stack([np.array(mi.render(scene, seed=int(s), spp=spp)) for s in seeds])


def image_mean_and_standard_error(films):
    """Mean over pixels and seeds of each channel, and its standard error.

    Pixels are independent (box filter: each sample lands in one pixel) and
    each seed is an independent render, so Var(image mean) = Σ_p Var_p / (P² K)
    with Var_p the per-pixel sample variance over the K seeds.
    """
    k = films.shape[0]
    pixels = films.reshape(k, -1, films.shape[-1])
    n_pixels = pixels.shape[1]
    mean = pixels.mean(axis=(0, 1))
    se = np.sqrt(pixels.var(axis=0, ddof=1).sum(axis=0) / k) / n_pixels
    return mean, se


def relative_noise(films):
    """rms over pixels of the difference of two renders / √2, over the mean luminance channel."""
    y = films[..., 1]
    return np.std((y[0] - y[1]) / np.sqrt(2.0)) / y.mean()


@pytest.fixture(scope="module")
def scenes(variant):
    import mitsuba as mi

    register()
    # NOTE: all scenes are loaded before the first render. Loading any Mitsuba object
    # (a scene, even a sampler) adds instances to the registries that the kernels'
    # virtual calls dispatch over, so every kernel compiled before is compiled again.
    return {
        "volpath": pools_scene(VOLPATH, 16),
        "split": pools_scene(split_integrator(12, 5), 16),
        "emitted": pools_scene({"type": "path", "max_depth": 1}, 4),  # directly seen radiance
        # A two-pass frame (render.in_water_fraction < 1), with Russian roulette from the
        # second vertex (render.roulette_depth = 2): the scene's integrator has every lobe but
        # the transmitted one, which the second integrator renders alone.
        "reflection": pools_scene(split_integrator(12, 2, lobes="reflection"), 16),
        "transmission": mi.load_dict(split_integrator(12, 2, lobes="transmission")),
        # the frames' sampler ([render] sampler): each dimension of a pixel's samples stratified
        "multijitter": pools_scene(split_integrator(12, 5), 16, sampler="multijitter"),
    }


def split_and_volpath(scenes):
    return {name: scenes[name] for name in ("volpath", "split")}


def two_pass_renders(scenes, seeds, spp, in_water_spp):
    """(reflection pass, transmission pass) films of the pools, as ``WaterRenderer`` makes them."""
    import mitsuba as mi

    scene = scenes["reflection"]
    transmitted = np.stack([np.array(mi.render(scene, integrator=scenes["transmission"], seed=int(s) + 7919,
                                               spp=in_water_spp)) for s in seeds])
    return renders(scene, seeds, spp), transmitted


@pytest.mark.parametrize(
    "camera, sun, albedo, sigma_t",
    [
        # Pools in the wall's shadow, bright scattering water: the transmitted lobe (η²
        # radiance scaling, continuation inside the medium) carries much of the image.
        # NOTE: sunlit scattering water makes rare, huge samples (in volpath as well).
        (LOOK_NORTH, LOW_SUN, 0.8, 0.3),
        # Towards the sun, opaque black water: glints through next-event estimation and
        # MIS with the reflection lobe (rough pools), a delta reflection (smooth pool).
        # NOTE: with clear water, sunlight reflected by the pools' bottoms into the
        # camera makes rare, huge samples (in volpath as well) that swamp the test.
        (LOOK_SOUTH, SUN, 0.0, 5.0),
    ],
    ids=["sky-scattering-water", "sun-glint"],
)
def test_split_has_the_same_expectation_as_volpath(scenes, camera, sun, albedo, sigma_t):
    means, errors = {}, {}
    for name, scene in split_and_volpath(scenes).items():
        configure(scene, camera, sun, albedo, sigma_t)
        means[name], errors[name] = image_mean_and_standard_error(renders(scene, seeds=range(4), spp=128))
    z = (means["split"] - means["volpath"]) / np.hypot(errors["split"], errors["volpath"])
    assert np.all(np.abs(z) < Z_MAX), f"z = {z}, means {means}, standard errors {errors}"
    # The test can see a bias of 2.5 %: Z_MAX standard errors are below that.
    assert np.all(Z_MAX * np.hypot(errors["split"], errors["volpath"]) < 0.025 * means["volpath"]), errors


def test_two_passes_with_early_roulette_have_the_expectation_of_one(scenes):
    # Pools in the shade, bright scattering water: the transmitted lobe carries much of the
    # image. The in-water pass gets a quarter of the samples (render.in_water_fraction 0.25)
    # and both passes roulette from the second vertex; their sum must estimate the image of
    # the one-pass split integrator with roulette after 5 (an independent estimator).
    for name in ("split", "reflection"):
        configure(scenes[name], LOOK_NORTH, LOW_SUN, albedo=0.8, sigma_t=0.3)
    one_mean, one_se = image_mean_and_standard_error(renders(scenes["split"], seeds=range(4), spp=128))
    reflected, transmitted = two_pass_renders(scenes, seeds=range(20, 24), spp=128, in_water_spp=32)
    r_mean, r_se = image_mean_and_standard_error(reflected)
    t_mean, t_se = image_mean_and_standard_error(transmitted)
    # The passes are independent renders (own seeds): their standard errors add in quadrature.
    two_se = np.hypot(r_se, t_se)
    z = (r_mean + t_mean - one_mean) / np.hypot(one_se, two_se)
    assert np.all(np.abs(z) < Z_MAX), f"z = {z}, one pass {one_mean} ± {one_se}, two {r_mean + t_mean} ± {two_se}"
    # Sensitivity: a bias of 2.5 % of the image would be seen; and the transmitted pass is a
    # sizeable part of it here (a test that left it out would fail).
    assert np.all(Z_MAX * np.hypot(one_se, two_se) < 0.025 * one_mean), (one_se, two_se)
    assert np.all(t_mean > 10 * Z_MAX * np.hypot(one_se, two_se)), (t_mean, one_se, two_se)


@pytest.mark.slow
def test_stratified_samples_keep_the_mean_and_lower_the_noise(scenes):
    # Towards the sun over the three pools (glints, reflected sky, scattering water): the split integrator
    # with Mitsuba's multijitter sampler (the frames' default) against the same integrator with independent
    # samples. Each of its samples is uniform on its own, so the image's mean must agree (Z-test); its
    # pixels' samples are stratified in every dimension (position, wavelength, lobes), so two of its
    # renders differ less than two independent ones: 0.76x here (mean over 4 pairs); 0.85 leaves room for noise.
    for name in ("split", "multijitter"):
        configure(scenes[name], LOOK_SOUTH, LOW_SUN, albedo=0.8)
    films = {name: renders(scenes[name], seeds=range(40, 48), spp=64) for name in ("split", "multijitter")}
    (m_i, se_i), (m_s, se_s) = (image_mean_and_standard_error(films[n]) for n in ("split", "multijitter"))
    z = (m_s - m_i) / np.hypot(se_i, se_s)
    assert np.all(np.abs(z) < Z_MAX), f"z = {z}, independent {m_i} ± {se_i}, multijitter {m_s} ± {se_s}"
    assert np.all(Z_MAX * np.hypot(se_i, se_s) < 0.025 * m_i), (se_i, se_s)  # a 2.5 % bias would be seen
    noise = {name: np.mean([relative_noise(films[name][i:i + 2]) for i in range(0, 8, 2)]) for name in films}
    assert noise["multijitter"] < 0.85 * noise["split"], noise


def test_split_reduces_the_noise_of_the_reflected_sky(scenes):
    # Pools in the shade, dark water: what the camera sees is mostly reflected sky,
    # which volpath estimates from the F ≈ 2-8 % of samples that choose reflection.
    noise = {}
    for name, scene in split_and_volpath(scenes).items():
        configure(scene, LOOK_NORTH, LOW_SUN, albedo=0.05)
        noise[name] = relative_noise(renders(scene, seeds=(11, 12), spp=16))
    assert noise["split"] < 0.5 * noise["volpath"], noise


@pytest.mark.slow
def test_a_ray_that_misses_the_water_returns_the_sky_radiance(scenes):
    # Looking up at the sky only. ``path`` with max_depth = 1 returns exactly the
    # radiance of the emitter a camera ray meets; the wavelengths and pixel
    # positions are drawn by the film before the integrator runs, so the images
    # agree to rounding. Every sample of the split integrator is volpath's here,
    # which draws the same random numbers: those images agree too.
    looking_up = ((0.0, 0.0, 2.0), (0.0, 3.0, 4.0))
    films = {}
    for name in ("volpath", "split", "emitted", "reflection"):
        configure(scenes[name], looking_up, SUN, albedo=0.8)
        films[name] = renders(scenes[name], seeds=(5,), spp=4)
    # The in-water pass of a two-pass frame adds nothing where no camera ray meets the water.
    assert np.all(two_pass_renders(scenes, seeds=(5,), spp=4, in_water_spp=1)[1] == 0.0)
    np.testing.assert_allclose(films["reflection"], films["emitted"], rtol=ROUNDOFF32)
    assert films["emitted"].min() > 0
    # float32 films from differently compiled kernels (FMA contraction may differ): pixels > 0.
    np.testing.assert_allclose(films["split"], films["emitted"], rtol=ROUNDOFF32)
    np.testing.assert_allclose(films["split"], films["volpath"], rtol=ROUNDOFF32)


def test_split_integrator_entry_and_registration(variant):
    import mitsuba as mi

    assert split_integrator(12) == {"type": SPLIT_INTEGRATOR, "max_depth": 12, "rr_depth": 5}
    register()
    register()  # idempotent
    integrator = mi.load_dict(split_integrator(7, 3))
    assert isinstance(integrator, mi.SamplingIntegrator)
    assert (integrator.max_depth, integrator.rr_depth) == (7, 3)
    with pytest.raises(ValueError):
        split_integrator(-2)
    with pytest.raises(ValueError):
        split_integrator(12, rr_depth=0)
    assert split_integrator(12, lobes="transmission")["lobes"] == "transmission"
    assert "lobes" not in split_integrator(12, lobes="both")
    with pytest.raises(ValueError, match="lobes"):
        split_integrator(12, lobes="refraction")
