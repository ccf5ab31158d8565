"""The USD stage of ``oceanrender geometry --usd`` read back with pxr: metres, Z up, frames, points, camera, sun."""

import math

import numpy as np
import pytest
from pxr import Usd, UsdGeom, UsdLux

from oceanrender.cli import main
from oceanrender.render.scene import sun_direction
from oceanrender.scene import load_scene
from oceanrender.waves.sea import SeaSurface

from ..tolerances import ROUNDOFF32
from tests.scenes import small_sea_text


def _scene_file(tmp_path, extra=""):
    path = tmp_path / "usd.toml"
    path.write_text(small_sea_text('name = "usd"\n[output]\nframes = [2, 5]\nfps = 10.0\n[ocean]\nresolution = 64\ncascades = 2\n'
                    '[camera]\nposition = [3.0, -4.0, 6.0]\ntarget = [3.0, 20.0, 0.0]\nfov = 50.0\n'
                    '[sun]\nelevation = 30.0\nazimuth = 120.0\n' + extra))
    return path


def test_the_stage_round_trips(tmp_path):
    scene_path, usd = _scene_file(tmp_path), tmp_path / "sea.usda"
    assert main(["geometry", str(scene_path), "--usd", str(usd), "--usd-extent", "60", "--usd-points", "16"]) == 0
    stage = Usd.Stage.Open(str(usd))
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0 and UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert (stage.GetStartTimeCode(), stage.GetEndTimeCode(), stage.GetTimeCodesPerSecond()) == (2, 4, 10.0)
    mesh = UsdGeom.Mesh(stage.GetPrimAtPath("/World/Sea"))
    points = mesh.GetPointsAttr()
    assert points.GetTimeSamples() == [2.0, 3.0, 4.0]
    assert len(mesh.GetFaceVertexCountsAttr().Get()) == 15 * 15  # same quads every frame
    # A point's height is the sea's at its rest point: the grid is 60 m wide, centred under the camera.
    scene = load_scene(scene_path)
    sea = SeaSurface(scene.ocean)
    axis = np.linspace(-30.0, 30.0, 16)
    x0, y0 = 3.0 + axis[5], -4.0 + axis[9]
    index = 9 * 16 + 5
    for frame in (2, 4):
        p = np.array(points.Get(frame))[index]
        expected = sea.sample(np.array([x0]), np.array([y0]), frame / 10.0, np.array([4.0])).displacement[0]
        # float32 storage: ~1e-4 of the coordinates' scale (tens of metres), ROUNDOFF32 relative
        np.testing.assert_allclose(p, [x0 + expected[0], y0 + expected[1], expected[2]], atol=ROUNDOFF32 * 30)
        normals = np.array(mesh.GetNormalsAttr().Get(frame))
        np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=ROUNDOFF32)
    # The camera sits where the scene puts it, looking at the target; its focal length gives the fov.
    camera = UsdGeom.Camera(stage.GetPrimAtPath("/World/Camera"))
    matrix = np.array(camera.ComputeLocalToWorldTransform(3))
    np.testing.assert_allclose(matrix[3, :3], [3.0, -4.0, 6.0], atol=1e-9)
    forward = -matrix[2, :3]  # USD cameras look along −Z
    np.testing.assert_allclose(forward, np.array([0.0, 24.0, -6.0]) / math.hypot(24.0, 6.0), atol=1e-9)
    fov = 2 * math.degrees(math.atan(0.5 * camera.GetHorizontalApertureAttr().Get() / camera.GetFocalLengthAttr().Get(3)))
    assert fov == pytest.approx(50.0)
    # The sun light shines along −(direction to the sun).
    sun = UsdLux.DistantLight(stage.GetPrimAtPath("/World/Sun"))
    sun_matrix = np.array(sun.ComputeLocalToWorldTransform(3))
    np.testing.assert_allclose(sun_matrix[2, :3], sun_direction(30.0, 120.0), atol=1e-9)


@pytest.mark.parametrize("argv, expected", [
    (["--usd", "sea.obj"], "--usd: expected a file ending in .usda, .usdc, .usd"),
    (["--usd", "sea.usda", "--usd-points", "1"], "--usd-points: expected 2 to 4096"),
    (["--usd", "sea.usda", "--usd-extent", "-5"], "--usd-extent: expected a width > 0"),
    ([], "give --out DIR (wave maps), --usd FILE (USD stage), or both"),
])
def test_bad_usd_options_are_one_line_exit_2(tmp_path, capsys, argv, expected):
    argv = [str(tmp_path / a) if a.endswith((".obj", ".usda")) else a for a in argv]
    assert main(["geometry", str(_scene_file(tmp_path)), *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert expected in err and "\n" not in err
