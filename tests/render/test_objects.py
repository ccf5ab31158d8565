"""Objects in the renderer: every material loads, a box crossing the surface is seen from above and below."""

import numpy as np
import pytest
import trimesh

from oceanrender.cli import main
from oceanrender.io.frames import read_exr
from oceanrender.scene import OBJECT_MATERIALS
from tests.scenes import scene_from_dict, small_sea_text


@pytest.mark.parametrize("material", OBJECT_MATERIALS)
def test_every_material_is_a_mitsuba_bsdf(material, tmp_path):
    import mitsuba as mi

    from oceanrender.render.objects import object_bsdf, object_mesh
    from oceanrender.runtime.variants import activate_variant

    activate_variant("auto")
    box = trimesh.creation.box(extents=(1.0, 1.0, 1.0))
    box.export(tmp_path / "box.ply")
    obj = scene_from_dict({"name": "m", "objects": [{"name": "b", "mesh": str(tmp_path / "box.ply"),
                                                     "material": material}]}).objects[0]
    assert mi.load_dict(object_bsdf(obj)) is not None
    mesh = object_mesh(obj, np.asarray(box.vertices), np.asarray(box.faces), None)
    assert mesh.face_count() == 12


def _render(tmp_path, name, camera, with_box):
    box = trimesh.creation.box(extents=(2.0, 2.0, 2.0))  # centred on the still level: half under water
    box.export(tmp_path / "box.ply")
    objects = ('[[objects]]\nname = "box"\nmesh = "box.ply"\nposition = [0.0, 6.0, 0.0]\n'
               'material = "diffuse"\nalbedo = [0.9, 0.1, 0.05]\n') if with_box else ""
    path = tmp_path / f"{name}.toml"
    path.write_text(small_sea_text(f'name = "{name}"\n[output]\nframes = [0, 1]\nresolution = [48, 32]\nspp = 16\n'
                    f'directory = "{tmp_path / "out"}"\n[ocean]\nwind_speed = 2.0\nresolution = 64\n'
                    f'[sun]\nelevation = 60.0\nazimuth = 180.0\n{camera}\n{objects}'))
    assert main(["render", str(path), "--no-progress"]) == 0
    channels, meta = read_exr(tmp_path / "out" / name / "frame_0000.exr")
    return np.stack([channels[c] for c in "XYZ"], -1), meta


@pytest.mark.slow
def test_a_box_across_the_surface_is_seen_from_above_and_below(tmp_path):
    above = '[camera]\nposition = [0.0, 0.0, 2.5]\ntarget = [0.0, 6.0, 0.5]\nfov = 50.0'
    below = '[camera]\nposition = [0.0, 0.0, -1.5]\ntarget = [0.0, 6.0, -0.5]\nfov = 50.0'
    for camera, name in ((above, "above"), (below, "below")):
        with_box, meta = _render(tmp_path, f"{name}_box", camera, True)
        without, _ = _render(tmp_path, f"{name}_none", camera, False)
        assert int(meta["repaired_pixels"]) == 0 and np.all(np.isfinite(with_box))
        centre = (slice(10, 22), slice(18, 30))  # the box fills the middle of the frame
        # A red box against blue water: in the middle, X (reddish) against Z (bluish) rises well above
        # the plain sea's; 16 spp noise moves the ratio by a few %, the box by a factor > 1.5.
        ratio_box = with_box[centre][..., 0].mean() / with_box[centre][..., 2].mean()
        ratio_sea = without[centre][..., 0].mean() / without[centre][..., 2].mean()
        assert ratio_box > 1.5 * ratio_sea, (name, ratio_box, ratio_sea)


def test_a_measured_albedo_spectrum_is_used_as_it_is(tmp_path):
    import mitsuba as mi

    from oceanrender.render.objects import object_bsdf
    from oceanrender.runtime.variants import activate_variant

    activate_variant("auto")
    trimesh.creation.box(extents=(1.0, 1.0, 1.0)).export(tmp_path / "box.ply")
    wl = np.arange(360.0, 831.0, 10.0)
    r = 0.05 + 0.8 * (wl > 600)  # a red paint: dark below 600 nm, bright above
    (tmp_path / "paint.csv").write_text("# test paint\n# reflectance [-]\n# wavelength_nm,reflectance\n"
                                        + "".join(f"{w:g},{v:g}\n" for w, v in zip(wl, r)))
    obj = scene_from_dict({"name": "m", "objects": [{"name": "b", "mesh": str(tmp_path / "box.ply"),
                                                     "albedo_spectrum": str(tmp_path / "paint.csv")}]}).objects[0]
    bsdf = mi.load_dict(object_bsdf(obj))
    si = mi.SurfaceInteraction3f()
    si.wi = mi.Vector3f(0, 0, 1)
    si.wavelengths = mi.Spectrum([450.0, 550.0, 650.0, 700.0])
    ctx = mi.BSDFContext()
    value = np.array(bsdf.eval(ctx, si, mi.Vector3f(0, 0, 1))).ravel() * np.pi  # Lambert: f = R/π at normal
    np.testing.assert_allclose(value, [0.05, 0.05, 0.85, 0.85], rtol=1e-5)  # float32 evaluation
