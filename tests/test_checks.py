"""What a run needs, checked before any work: tables, the sea against its water body, memory, output folders."""

from __future__ import annotations

import pytest

from oceanrender import checks
from oceanrender.scene import SceneError, with_overrides
from tests.scenes import scene_from_dict
from oceanrender.waves.sea import elevation_std

OCEAN = {"spectrum": "Pierson-Moskowitz 1964", "wind_speed": 10.0, "resolution": 64}


def scene(**sections):
    return scene_from_dict({"name": "c", "ocean": OCEAN, "mesh": {"kind": "radial", **sections.pop("mesh", {})},
                            **sections})


def test_the_vertex_count_is_the_radial_grid_s(variant):
    """mesh_vertices (no mesh built) against the top vertices of the water body the renderer gets."""
    from oceanrender.surface.open_sea import WaterBody

    for segments in (16, 48, 128):
        s = scene(mesh={"segments": segments}, foam={"enabled": False})
        body = WaterBody(s)
        body.frame(0.0)
        assert checks.mesh_vertices(s) == body.grid_at(0.0).top_vertex_count


def test_memory_estimate_adds_the_measured_costs():
    s = scene(output={"resolution": [200, 100]}, ocean={**OCEAN, "cascades": 2})
    items = {item.key: item.bytes for item in checks.memory_estimate(s)}
    assert items["[ocean] resolution"] == 64**2 * 2 * checks.BYTES_PER_FFT_POINT
    assert items["[mesh] segments"] == checks.mesh_vertices(s) * checks.BYTES_PER_MESH_VERTEX
    assert items["[output] resolution"] == 200 * 100 * (checks.BYTES_PER_PIXEL + 4 * s.output.spectral_bands)
    assert "[mesh] segments" not in {item.key for item in checks.memory_estimate(s, renders=False)}


@pytest.mark.parametrize(
    "sections, key",
    [
        ({"output": {"resolution": [16384, 16384]}}, "[output] resolution"),
        ({"ocean": {**OCEAN, "resolution": 8192, "cascades": 4}}, "[ocean] resolution"),
        ({"mesh": {"segments": 16384}}, "[mesh] segments"),
    ],
)
def test_runs_beyond_the_memory_are_refused_with_the_estimate(sections, key):
    with pytest.raises(SceneError, match=rf"scene.toml: {key.replace('[', '.').replace(']', '.')}: the run needs "
                                         r"about [0-9.]+ GiB .* more than the 12.8 GiB it may use here") as info:
        checks.check_memory(scene(**sections), "scene.toml", available=16 * checks.GiB)
    assert "\n" not in str(info.value)


def test_the_shipped_sizes_fit_a_16_gib_machine():
    checks.check_memory(scene(), "scene.toml", available=16 * checks.GiB)


def test_a_bottom_above_the_troughs_is_refused_and_a_camera_in_the_crests_is_not():
    sigma = elevation_std(scene().ocean)  # PM at 10 m/s: Hs ≈ 2.2 m, σ ≈ 0.55 m
    checks.check_sea(scene(water={"depth": 8.01 * sigma}), "s.toml")
    with pytest.raises(SceneError, match=r"\[water\] depth: .* above the deepest troughs of the sea; expected ≥"):
        checks.check_sea(scene(water={"depth": 7.9 * sigma}), "s.toml")
    # A camera in the crests, or under the water, renders from the side of the surface it is on, frame by frame.
    checks.check_sea(scene(camera={"position": [0, 0, 0.5 * sigma], "target": [0, 10, 0]}), "s.toml")
    checks.check_sea(scene(camera={"position": [0, 0, -3.0], "target": [0, 10, 0]}), "s.toml")



def test_a_binary_iop_table_is_refused(tmp_path):
    table = tmp_path / "iops.csv"
    table.write_bytes(bytes(range(256)) * 8)
    with pytest.raises(SceneError, match=r"\[water\] iop_table: "):
        checks.check_tables(with_overrides(scene(), water={"iop_table": str(table)}), "s.toml")


def test_the_output_check_probes_and_sizes(tmp_path):
    assert checks.check_output(tmp_path / "o", "s.toml", "--out") == tmp_path / "o"
    with pytest.raises(SceneError, match=r"s\.toml: --out: .*exists and is not a folder; expected a folder"):
        checks.check_output("/dev/null", "s.toml", "--out")
    s = scene(output={"resolution": [1000, 500]})
    assert checks.frame_bytes(s) == 1000 * 500 * (6 * 4 + 3 + 4 * s.output.spectral_bands) + 64 * 1024


def test_the_free_space_floors_follow_the_files_a_frame_writes():
    s = scene(ocean={**OCEAN, "cascades": 3})
    assert checks.geometry_frame_bytes(s) == 3 * 64**2 * 4 * 3 * 4 + checks.SLACK_BYTES  # 4 maps × RGB float32
    coast = scene_from_dict({"name": "c", "coastal": {"cells": [40, 30], "size": [8.0, 6.0]}})
    per_cell = 3 * 8 + 5 * 4  # the .npz's h, hu, hv (float64) and the EXR's five float32 channels
    assert checks.coastal_frame_bytes(coast) >= 40 * 30 * per_cell + checks.SLACK_BYTES


def test_an_object_reflectance_outside_0_1_is_refused_before_any_work(tmp_path):
    import trimesh

    trimesh.creation.box(extents=(1.0, 1.0, 1.0)).export(tmp_path / "box.ply")
    (tmp_path / "paint.csv").write_text("# bad paint\n# reflectance [-]\n# wavelength_nm,reflectance\n360,0.5\n830,1.5\n")
    s = scene(objects=[{"name": "b", "mesh": str(tmp_path / "box.ply"), "albedo_spectrum": str(tmp_path / "paint.csv")}])
    with pytest.raises(SceneError, match=r"\[\[objects\]\] b albedo_spectrum: .*reflectance must lie in \[0, 1\]"):
        checks.check_tables(s, "s.toml")


def test_the_time_estimate_grows_with_the_work_and_names_what_dominates():
    """Estimates from the measured unit costs (checks.SECONDS_PER_*): linear in samples, frames and cores."""
    base = scene(output={"resolution": [320, 180], "spp": 16, "frames": [0, 2]})
    one = checks.time_estimate(base, "llvm_ad_spectral", meter_samples=115200, cores=2)
    more = checks.time_estimate(with_overrides(base, output={"spp": 1 << 20}), "llvm_ad_spectral", 115200, cores=2)
    assert one.total == pytest.approx(one.setup + 2 * one.per_frame)
    assert more.per_frame > 1e4 * one.per_frame / 2 and more.key == "[output] spp"
    assert "h" in more.line() or "days" in more.line()
    wide = checks.time_estimate(base, "llvm_ad_spectral", 115200, cores=4)
    assert wide.per_frame < one.per_frame
    gpu = checks.time_estimate(base, "cuda_ad_spectral", 115200)
    assert gpu.per_frame < one.per_frame / 10


def test_turbid_water_is_estimated_slower_than_clear():
    """More scattering before absorption means more in-water vertices per path (1/(1 − ω₀), capped by max_depth)."""
    clear = scene()
    turbid = scene(composition={"preset": "turbid brown estuary"}, render={"max_depth": 64})
    assert checks.expected_water_vertices(clear) == pytest.approx(1.0, abs=0.1)
    assert checks.expected_water_vertices(turbid) > 5
    assert checks.expected_water_vertices(scene(composition={"preset": "turbid brown estuary"}, render={"max_depth": 3})) == 3
