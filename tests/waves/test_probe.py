"""Probing the sea at world points: height, water velocity and normal over time (oceanrender.waves.probe)."""

from pathlib import Path

import numpy as np
import pytest

from oceanrender.cli import PROBE_COLUMNS, main
from tests.scenes import scene_from_dict, small_sea_text
from oceanrender.waves.probe import probe_sea
from oceanrender.waves.sea import SeaSurface
from oceanrender.waves.wave_spectra import dispersion_relation

from ..tolerances import ROUNDOFF

SCENES = Path(__file__).resolve().parents[2] / "scenes"
POINTS_X, POINTS_Y = np.array([0.0, 7.3, -40.2]), np.array([0.0, -3.1, 12.9])
TIMES = np.array([0.0, 0.7, 3.1])


def _ocean(**ocean):
    return scene_from_dict({"name": "p", "ocean": {"resolution": 64, "cascades": 2, "wind_speed": 8.0, **ocean}}).ocean


def test_sum_of_sines_height_and_velocity_are_the_closed_form():
    # η = Σ a cos(k·x − ωt + φ) and ∂η/∂t = Σ a ω sin(k·x − ωt + φ); no horizontal displacement,
    # so the water at the surface moves vertically only (at this model's order).
    ocean = _ocean(model="sum of sines", wave_count=48)
    sea = SeaSurface(ocean)
    probe = probe_sea(sea, POINTS_X, POINTS_Y, TIMES)
    a = np.array([c.amplitude for c in sea.components])
    kx = np.array([c.wavenumber_x for c in sea.components])
    ky = np.array([c.wavenumber_y for c in sea.components])
    phi = np.array([c.phase for c in sea.components])
    omega = dispersion_relation(np.hypot(kx, ky), ocean.wave_depth)
    for i, t in enumerate(TIMES):
        theta = np.outer(POINTS_X, kx) + np.outer(POINTS_Y, ky) - omega * t + phi
        eta = (a * np.cos(theta)).sum(-1)
        w = (a * omega * np.sin(theta)).sum(-1)
        scale = np.abs(a).sum()
        np.testing.assert_allclose(probe.height[i], eta, atol=ROUNDOFF * scale)
        # Central difference over ±1 ms: truncation (δt ω)²/6 ≲ 1e-5 of a ω for these waves (ω ≲ 8 rad/s).
        np.testing.assert_allclose(probe.velocity[i, :, 2], w, atol=1e-5 * (a * omega).sum())
        np.testing.assert_allclose(probe.velocity[i, :, :2], 0.0, atol=ROUNDOFF * (a * omega).sum())
        # Normal of the closed form: (−∂η/∂x, −∂η/∂y, 1)/‖·‖.
        n = np.stack([(a * kx * np.sin(theta)).sum(-1), (a * ky * np.sin(theta)).sum(-1), np.ones(3)], -1)
        np.testing.assert_allclose(probe.normal[i], n / np.linalg.norm(n, axis=-1, keepdims=True), atol=ROUNDOFF)
    assert probe.converged.all()


def test_fft_probe_lands_on_the_displaced_sheet_and_is_reproducible():
    ocean = _ocean(choppiness=1.0)
    probe = probe_sea(SeaSurface(ocean), POINTS_X, POINTS_Y, TIMES)
    assert probe.converged.all()
    # The choppy sheet moves water horizontally too: |u| is of the order of |w| (deep-water orbits).
    assert np.abs(probe.velocity[..., :2]).max() > 0.2 * np.abs(probe.velocity[..., 2]).max() > 0
    # Every time is a pure function of the scene: another sea object, a subset of times -> the same bits
    # (what a Dask worker or a resumed run computes).
    again = probe_sea(SeaSurface(ocean), POINTS_X, POINTS_Y, TIMES[1:])
    np.testing.assert_array_equal(again.height, probe.height[1:])
    np.testing.assert_array_equal(again.velocity, probe.velocity[1:])
    np.testing.assert_array_equal(again.normal, probe.normal[1:])


def test_probe_refuses_bad_points():
    sea = SeaSurface(_ocean(model="sum of sines", wave_count=4))
    with pytest.raises(ValueError, match="x, y"):
        probe_sea(sea, [0.0, 1.0], [0.0], [0.0])
    with pytest.raises(ValueError, match="finite"):
        probe_sea(sea, [np.nan], [0.0], [0.0])


def _scene_file(tmp_path, extra=""):
    path = tmp_path / "probe.toml"
    path.write_text(small_sea_text('name = "probe"\n[output]\nframes = [0, 3]\n[ocean]\nresolution = 64\ncascades = 1\n' + extra))
    return path


def test_cli_probe_writes_one_row_per_frame_and_point(tmp_path, capsys):
    out = tmp_path / "probe.csv"
    assert main(["probe", str(_scene_file(tmp_path)), "--at", "1.5,-2", "--at", "0,0", "--frames", "1:3",
                 "--out", str(out)]) == 0
    lines = out.read_text().splitlines()
    assert lines[0].split(",") == list(PROBE_COLUMNS)
    rows = [line.split(",") for line in lines[1:]]
    assert [(r[0], r[2], r[3]) for r in rows] == [("1", "1.5", "-2.0"), ("1", "0.0", "0.0"),
                                                  ("2", "1.5", "-2.0"), ("2", "0.0", "0.0")]
    assert all(r[-2] == "true" for r in rows)
    assert main(["probe", str(_scene_file(tmp_path)), "--at", "0,0", "--frames", "0:1"]) == 0
    printed = capsys.readouterr().out.splitlines()
    assert len(printed) == 2 and printed[0].startswith("frame,time_s")


@pytest.mark.parametrize("argv_tail, expected", [
    (["--at", "1,2", "--frames", "3:1"], "[output] frames"),
])
def test_cli_probe_bad_input_is_one_line_exit_2(tmp_path, capsys, argv_tail, expected):
    assert main(["probe", str(_scene_file(tmp_path)), *argv_tail]) == 2
    err = capsys.readouterr().err.strip()
    assert expected in err and "\n" not in err


def test_cli_probe_refuses_a_coastal_scene_and_a_bad_point(tmp_path, capsys):
    assert main(["probe", str(SCENES / "coastal_beach.toml"), "--at", "0,0"]) == 2
    assert "[coastal]" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exit_info:  # argparse: exit status 2, one line naming --at
        main(["probe", str(_scene_file(tmp_path)), "--at", "1;2"])
    assert exit_info.value.code == 2
    assert "--at" in capsys.readouterr().err
