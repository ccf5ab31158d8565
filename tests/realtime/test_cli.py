"""`oceanrender bake-luts` and `oceanrender reference` end to end on a tiny coastal scene."""

import json

import numpy as np
import pytest

from oceanrender.cli import main
from oceanrender.io.frames import read_exr
from oceanrender.io.ply import read_ply
from oceanrender.realtime.bake import LUT_NAMES
from oceanrender.realtime.files import read_lut_set
from tests.tolerances import ROUNDOFF32

from . import TINY_COASTAL
from tests.scenes import small_sea_text

pytestmark = pytest.mark.render


def tiny_toml(folder):
    path = folder / "beach.toml"
    path.write_text(small_sea_text(
        "[output]\nframes = [0, 2]\nfps = 10.0\nresolution = [24, 16]\nspp = 2\n"
        f"directory = '{folder / 'out'}'\n[render]\nwhite_spp = 64\nmax_depth = 4\nintegrator = 'volpath'\n"
        "[camera]\nposition = [0.0, -1.0, 3.0]\ntarget = [0.0, 2.5, 0.0]\n[coastal]\n"
        + "".join(f"{k} = {list(v) if isinstance(v, list) else v}\n" for k, v in TINY_COASTAL.items())))
    return path


@pytest.fixture(scope="module")
def runs(variant, tmp_path_factory):
    folder = tmp_path_factory.mktemp("cli")
    scene = tiny_toml(folder)
    outputs = {}
    import contextlib
    import io

    for name, argv in (
        ("bake", ["bake-luts", str(scene), "--out", str(folder / "luts"), "--adaptation-luminance", "3000",
                  "--gamma", "0.8"]),
        ("reference", ["reference", str(scene), "--frames", "0:2", "--out", str(folder / "ref"),
                       "--luts", str(folder / "luts")]),
        ("again", ["reference", str(scene), "--frames", "0:2", "--out", str(folder / "ref"),
                   "--luts", str(folder / "luts")]),
    ):
        stream = io.StringIO()
        with contextlib.redirect_stdout(stream):
            outputs[name] = (main(argv), stream.getvalue())
    return folder, outputs


def test_bake_luts_writes_every_texture_with_its_sidecar(runs):
    folder, outputs = runs
    status, text = outputs["bake"]
    assert status == 0 and "L_wa = 3000 cd/m2 (given on the command line)" in text
    for name in LUT_NAMES:
        for ext in ("exr", "png", "json"):
            assert (folder / "luts" / f"{name}.{ext}").is_file()
    luts = read_lut_set(folder / "luts")
    assert luts.gamma == 0.8 and luts.constants["vision"]["adaptation_luminance_cd_m2"] == 3000.0
    # The EXR stores float32: the power is taken in float32 here, in float64 before the cast there.
    np.testing.assert_allclose(luts["fresnel"].data[0, :, 1], luts["fresnel"].data[0, :, 0] ** 0.8, rtol=ROUNDOFF32)
    assert luts["T1"].data.shape == (256, 256, 3) and luts["sky"].data.shape == (256, 512, 3)


def test_reference_set_files_and_report(runs):
    folder, outputs = runs
    status, text = outputs["reference"]
    assert status == 0 and "gamma fit over 2 frame(s)" in text
    ref = folder / "ref"
    report = json.loads((ref / "report.json").read_text())
    fit = report["gamma_fit"]
    assert fit["gamma_start"] == 0.8 and fit["after"]["mean"] <= fit["before"]["mean"]
    assert [entry["frame"] for entry in report["per_frame"]] == [0, 1]
    assert "mean ΔE" in (ref / "report.md").read_text()
    for frame in (0, 1):
        stem = f"{frame:04d}"
        channels, meta = read_exr(ref / f"reference_{stem}.exr")
        assert set("XYZRGB") <= set(channels) and meta["adaptation_luminance_cd_m2"] == 3000.0
        gbuffer, _ = read_exr(ref / f"gbuffer_{stem}.exr")
        assert {"P.X", "N.Z", "view_angle", "depth", "path_length", "kind"} <= set(gbuffer)
        assert gbuffer["kind"].shape == (16, 24)
        dE, _ = read_exr(ref / f"delta_e_{stem}.exr")
        assert np.all(np.isfinite(dE["dE_before"])) and dE["water"].sum() > 0
        camera = json.loads((ref / f"camera_{stem}.json").read_text())
        assert camera["resolution"] == [24, 16] and camera["position_m"] == [0.0, -1.0, 3.0]
        assert {"forward", "up", "right", "fov_x_deg", "fov_y_deg", "camera_to_world"} <= set(camera)
        mesh = read_ply(ref / f"water_{stem}.ply")
        assert len(mesh.faces) > 0 and mesh.normals is not None
        for name in ("reference", "realtime", "realtime_fitted", "delta_e", "delta_e_fitted"):
            assert (ref / f"{name}_{stem}.png").is_file()


def test_reference_reuses_stored_frames(runs):
    folder, outputs = runs
    status, text = outputs["again"]
    assert status == 0 and text.count("reused the stored reference") == 2
    first = json.loads((folder / "ref" / "report.json").read_text())
    assert first["gamma_fit"]["gamma"] > 0


def test_errors_are_one_line(runs, capsys, tmp_path):
    folder, _ = runs
    assert main(["reference", str(tiny_toml(tmp_path)), "--out", str(tmp_path / "x"), "--luts", str(tmp_path)]) == 2
    assert "no luts.json" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["bake-luts", str(folder / "beach.toml"), "--out", str(tmp_path), "--reference-albedo", "2,0"])
