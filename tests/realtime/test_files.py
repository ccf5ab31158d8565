"""LUT files: data, axes and metadata survive the round trip through EXR, PNG and JSON."""

import json

import imageio.v3 as iio
import numpy as np
import pytest

from oceanrender.realtime.bake import LUT_NAMES

#: The synthetic set is coastal: it carries the optional seafloor map too.
NAMES = LUT_NAMES + ("seafloor",)
from oceanrender.realtime.files import PREVIEW_ROWS, jsonable, read_lut_set, write_lut_set
from oceanrender.realtime.model import sample_lut_1d, sample_lut_2d

from . import SMALL, synthetic_lut_set


@pytest.fixture(scope="module")
def baked():
    return synthetic_lut_set()


@pytest.fixture(scope="module")
def folder(baked, tmp_path_factory):
    path = tmp_path_factory.mktemp("luts")
    write_lut_set(path, baked)
    return path


def strict_json(path):
    def refuse(constant):
        raise ValueError(f"non-standard JSON constant {constant}")

    return json.loads(path.read_text(encoding="utf-8"), parse_constant=refuse)


def test_every_lut_round_trips_bit_for_bit_with_its_axes(baked, folder):
    again = read_lut_set(folder)
    assert set(again.luts) == set(NAMES)
    for name in NAMES:
        a, b = baked[name], again[name]
        np.testing.assert_array_equal(a.data, b.data)  # exact: a float32 EXR round trip
        assert a.channels == b.channels and a.columns == b.columns and a.rows == b.rows
        assert a.quantity == b.quantity and a.preview == b.preview
        assert (a.preview_offset, a.preview_scale) == (b.preview_offset, b.preview_scale)
        assert json.loads(json.dumps(jsonable(a.parameters))) == b.parameters
    assert again.n_water == baked.n_water and again.gamma == baked.gamma
    np.testing.assert_allclose(again.rgb("sun_irradiance_rgb"), baked.rgb("sun_irradiance_rgb"))
    # A texture read back samples like the baked one, from its own axes (exact: same data, axes, code).
    h = np.array([0.0, 0.3, 2.0, 17.0, np.inf])
    np.testing.assert_array_equal(sample_lut_1d(again["T0"], h), sample_lut_1d(baked["T0"], h))
    np.testing.assert_array_equal(sample_lut_2d(again["T1"], h[::-1], h), sample_lut_2d(baked["T1"], h[::-1], h))


def test_sidecars_state_axes_units_ranges_and_encodings(baked, folder):
    for name in NAMES:
        meta = strict_json(folder / f"{name}.json")
        lut = baked[name]
        assert meta["size"] == {"width": lut.data.shape[1], "height": lut.data.shape[0], "channels": list(lut.channels)}
        assert set(meta["encoding"]) >= {"exr", "png", "png_offset", "png_scale"}
        for i, channel in enumerate(lut.channels):
            lo, hi = meta["value_range"][channel]
            assert lo == pytest.approx(float(lut.data[..., i].min()))
            assert hi == pytest.approx(float(lut.data[..., i].max()))
        assert "vision" in meta["parameters"] and meta["parameters"]["vision"]["adaptation_luminance_cd_m2"] == 2000.0
    t1 = strict_json(folder / "T1.json")
    u, v = t1["axes"].values()
    assert (u["symbol"], u["unit"], u["mapping"], u["range"]) == ("l", "m", "rational", [0.0, "inf"])
    assert (v["symbol"], v["unit"], v["scale"]) == ("h", "m", SMALL.depth_scale)
    assert strict_json(folder / "T0.json")["encoding"]["png"].startswith("8-bit sRGB")
    assert strict_json(folder / "fresnel.json")["encoding"]["png"].startswith("8-bit linear")
    index = strict_json(folder / "luts.json")
    assert index["luts"] == list(NAMES) and "reference_albedo_rgb" in index["constants"]
    floor = strict_json(folder / "seafloor.json")["axes"]
    assert [(a["symbol"], a["unit"], a["mapping"]) for a in floor.values()] == [("x", "m", "linear"),
                                                                                ("y", "m", "linear")]


def test_png_previews_have_the_documented_encoding(baked, folder):
    t0 = iio.imread(folder / "T0.png")
    assert t0.shape == (PREVIEW_ROWS, SMALL.depth_texels, 3) and t0.dtype == np.uint8
    fresnel = iio.imread(folder / "fresnel.png")
    F = baked["fresnel"].data[0, :, 0]
    # Exact: integer codes from the documented encoding, written with this same arithmetic.
    np.testing.assert_array_equal(fresnel[0, :, 0], np.rint(np.clip(F, 0, 1) * 255))  # linear, not sRGB
    normals = iio.imread(folder / "ripple_normals.png")
    n = baked["ripple_normals"].data
    np.testing.assert_array_equal(normals, np.rint(np.clip(0.5 + 0.5 * n, 0, 1) * 255))
    sky = iio.imread(folder / "sky.png")
    assert sky.shape == (SMALL.sky_size[1], SMALL.sky_size[0], 3)
    assert sky[-1].max() == 0 and sky[0].min() > 0  # black below the horizon, lit above
