"""`oceanrender validate-shader` end to end: tiny path-traced reference sets of a beach and of the open sea,
the shipped GLSL shader and a copy with a wrong Fresnel factor, on the software rasteriser."""

import contextlib
import io
import json

import numpy as np
import pytest

from oceanrender.cli import main
from oceanrender.io.frames import read_exr
from oceanrender.realtime.glsl import GLContext, shipped_shader
from oceanrender.realtime.validate import ShaderRunner, read_reference_set, validate_shader

from . import TINY_COASTAL
from tests.scenes import small_sea_text

pytestmark = [pytest.mark.render, pytest.mark.slow]  # every test grades a shader on rendered references

#: The deliberate bug: the Fresnel LUT looked up at 1 − μ instead of μ = cos θ (an angle/cosine mix-up).
FRESNEL_LINE = "clamp(mu, 0.0, 1.0)).r, 0.0, 1.0);  // FRESNEL LOOKUP"
WRONG_FRESNEL_LINE = "clamp(1.0 - mu, 0.0, 1.0)).r, 0.0, 1.0);  // BROKEN"


def wrong_fresnel_source() -> str:
    source = shipped_shader().read_text()
    assert source.count(FRESNEL_LINE) == 1
    return source.replace(FRESNEL_LINE, WRONG_FRESNEL_LINE)


SCENES = {
    "beach": "[output]\nframes = [0, 2]\nfps = 10.0\nresolution = [32, 18]\nspp = 16\n"
             "[render]\nwhite_spp = 64\nmax_depth = 6\n"
             "[camera]\nposition = [0.0, -1.5, 1.2]\ntarget = [0.0, 6.0, -0.3]\n[coastal]\n"
             + "".join(f"{k} = {list(v) if isinstance(v, list) else v}\n" for k, v in TINY_COASTAL.items()),
    # A low camera looking towards the horizon: Fresnel weights from 0.02 to 1 across the frame.
    "sea": "[output]\nframes = [0, 1]\nresolution = [32, 18]\nspp = 32\n"
           "[ocean]\nresolution = 16\npatch_size = 40.0\n[render]\nwhite_spp = 64\nmax_depth = 6\n"
           "[camera]\nposition = [0.0, 0.0, 4.0]\ntarget = [0.0, 100.0, -6.0]\nfov = 60.0\n",
}


def run(argv) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main([str(a) for a in argv])
    return status, out.getvalue(), err.getvalue()


@pytest.fixture(scope="module")
def reference_sets(variant, tmp_path_factory):
    folder = tmp_path_factory.mktemp("validate")
    sets = {}
    for name, text in SCENES.items():
        scene = folder / f"{name}.toml"
        scene.write_text(small_sea_text(text + f"\n[vision]\nadaptation_luminance = 3000.0\n"))
        out = folder / f"{name}_ref"
        status, _, err = run(["reference", scene, "--out", out, "--variant", variant])
        assert status == 0, err
        sets[name] = out
    wrong = folder / "wrong_fresnel.frag"
    wrong.write_text(wrong_fresnel_source())
    return sets, wrong


@pytest.mark.parametrize("name", ["beach", "sea"])
def test_shipped_shader_matches_the_numpy_model(reference_sets, name):
    """Issue threshold: ≤ 0.5 ΔE00 mean between the GLSL shader and the numpy model on the same inputs.

    With ripples at 3× their strength, so that the LEAN terms, the tilted normals and the
    seafloor drift are exercised at every water pixel, not only where a pixel resolves them.
    """
    from dataclasses import replace

    sets, _ = reference_sets
    references = read_reference_set(sets[name])
    # The same views with foam on the water (a random coverage field): the foam blend is checked too.
    rng = np.random.default_rng(7)
    foamy = replace(references, views=[replace(v, gbuffer=replace(v.gbuffer, foam=rng.uniform(0, 1, v.gbuffer.shape)))
                                       for v in references.views])
    context = GLContext()
    try:
        for strength, refs in ((0.0, references), (1.0, references), (3.0, references), (1.0, foamy)):
            runner = ShaderRunner(context, shipped_shader().read_text(), "water.frag", refs.luts, strength)
            grade = validate_shader(runner, refs, fit_grid=5)
            assert grade.shader_vs_model.mean <= 0.5
            # Both are float arithmetic of the same formulas and texels: what remains is float32 vs float64 and the
            # rasteriser's fixed-point filter weights, two orders of magnitude below the threshold.
            assert grade.shader_vs_model.mean < 0.05 and grade.shader_vs_model.p95 < 0.2
            for frame in grade.frames:
                assert np.all(np.isfinite(frame.shader_rgb))
    finally:
        context.release()


@pytest.mark.parametrize("name", ["beach", "sea"])
def test_validate_shader_grades_shipped_better_than_a_wrong_fresnel(reference_sets, name, tmp_path):
    sets, wrong = reference_sets
    grades = {}
    for label, fragment in (("shipped", "shipped"), ("wrong", wrong)):
        out = tmp_path / label
        status, text, err = run(["validate-shader", fragment, "--reference", sets[name], "--out", out])
        assert status == 0, err
        assert "water dE2000 vs reference" in text
        report = json.loads((out / "report.json").read_text())
        grades[label] = report
        assert report["scene"] and report["opengl"] and len(report["shader_sha256"]) == 64
        assert [entry["frame"] for entry in report["per_frame"]] == list(range(*report["frames"]))
        for entry in report["per_frame"]:
            stem = f"{entry['frame']:04d}"
            for file in (f"shader_{stem}.exr", f"shader_{stem}.png", f"delta_e_{stem}.exr", f"delta_e_{stem}.png",
                         f"delta_e_model_{stem}.png"):
                assert (out / file).is_file()
            channels, _ = read_exr(out / f"delta_e_{stem}.exr")
            assert {"dE_reference", "dE_model", "water"} <= set(channels)
            assert entry["worst_regions"][0]["mean"] >= entry["shader_vs_reference"]["all"]["mean"]
        fit = report["gamma_fit"]
        assert fit["shader_uses_gamma"] and fit["after"]["mean"] <= fit["before"]["mean"] + 1e-9
        assert "## γ of F^γ" in (out / "report.md").read_text()
    shipped = grades["shipped"]["totals_water"]
    broken = grades["wrong"]["totals_water"]
    # The same G-buffers and LUTs: only the Fresnel factor differs. "Clearly worse": at least 1 ΔE00 more
    # on average, and the broken shader is far from the numpy model while the shipped one is not.
    assert broken["shader_vs_reference"]["mean"] > shipped["shader_vs_reference"]["mean"] + 1.0
    assert broken["shader_vs_numpy_model"]["mean"] > 1.0 > 0.05 > shipped["shader_vs_numpy_model"]["mean"]


def test_a_shader_that_does_not_compile_is_exit_2_with_one_line_per_error(reference_sets, tmp_path):
    sets, _ = reference_sets
    bad = tmp_path / "bad.frag"
    source = shipped_shader().read_text().splitlines()
    line = next(i for i, text in enumerate(source) if "float Fc = pow(F, u_gamma);" in text)
    source[line] = source[line].replace("pow(F, u_gamma)", "pow(F, u_gamma_typo)")
    bad.write_text("\n".join(source) + "\n")
    status, _, err = run(["validate-shader", bad, "--reference", sets["beach"], "--out", tmp_path / "out"])
    assert status == 2
    lines = err.strip().splitlines()
    assert lines[0].startswith(f"{bad}:{line + 1}:") and "u_gamma_typo" in lines[0]
    assert lines[-1] == f"oceanrender: error: {bad}: {len(lines) - 1} GLSL error(s)"
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("argv, message", [
    (["validate-shader", "{missing}", "--reference", "{ref}"], "FRAGMENT {missing}: cannot read it"),
    (["validate-shader", "shipped", "--reference", "{nowhere}"], "no report.json"),
    (["validate-shader", "shipped", "--reference", "{ref}", "--ripples", "-1"], "--ripples: expected"),
    (["validate-shader", "shipped", "--reference", "{ref}", "--gamma", "0"], "--gamma: expected"),
])
def test_bad_input_is_one_line_exit_2(reference_sets, tmp_path, argv, message):
    sets, _ = reference_sets
    names = {"missing": tmp_path / "none.frag", "ref": sets["beach"], "nowhere": tmp_path / "nothing"}
    status, _, err = run([a.format(**names) for a in argv])
    assert status == 2
    assert err.count("\n") == 1 and message.format(**names) in err


def test_the_seafloor_map_lies_where_the_terrain_meshs_rock_is(reference_sets):
    """The shader looks the floor up in `lut_seafloor` at world (x, y): where the G-buffer's refracted rays meet the
    terrain, the map must give the rock coverage Mitsuba interpolated from the mesh's vertices there."""
    from oceanrender.realtime.model import sample_lut_2d

    sets, _ = reference_sets
    references = read_reference_set(sets["beach"])
    floor = references.luts["seafloor"]
    rock, looked_up = [], []
    for view in references.views:
        g = view.gbuffer
        hit = (g.kind == 1) & np.isfinite(g.path_length)
        rock.append(g.rock[hit])
        looked_up.append(sample_lut_2d(floor, g.bottom_position[hit][:, 0], g.bottom_position[hit][:, 1])[:, 0])
    rock, looked_up = np.concatenate(rock), np.concatenate(looked_up)
    assert rock.size > 100 and 0.02 < np.mean(rock > 0.5) < 0.6  # some rock and some sand is seen
    # Bilinear on the cell grid vs barycentric on the mesh's triangles of the same vertices: they differ inside a
    # cell by a fraction of the coverage's change across it; the mean difference stays well below it.
    assert np.mean(np.abs(looked_up - rock)) < 0.05
    assert np.corrcoef(rock, looked_up)[0, 1] > 0.95
