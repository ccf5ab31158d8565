"""The sequence runner: per-frame updates, resume, and the CLI end to end."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from oceanrender.cli import main
from oceanrender.io.frames import FRAME_CHANNELS, frame_is_complete, read_exr
from oceanrender.pipeline import Sequence, frame_paths, render_sequence
from oceanrender.render.renderer import WaterRenderer
from oceanrender.surface.frame import FrameGeometry
from tests.extras import needs_spectra
from tests.scenes import scene_from_dict, small_sea_text
from tests.tolerances import ROUNDOFF32

pytestmark = pytest.mark.render

ROOT = Path(__file__).resolve().parents[1]

TINY = {
    "output": {"resolution": [24, 16], "spp": 4, "frames": [0, 2]},
    "ocean": {"resolution": 16, "patch_size": 40.0},
    "render": {"white_spp": 64, "max_depth": 6},
}


def tiny_scene(**sections):
    data = {"name": "tiny", **{k: dict(v) for k, v in TINY.items()}}
    for key, values in sections.items():
        data[key] = {**data.get(key, {}), **values}
    return scene_from_dict(data)


def tiny_toml(tmp_path, frames=(0, 2), resolution=(24, 16), spp=4):
    path = tmp_path / "tiny.toml"
    path.write_text(small_sea_text(
        f"[output]\nframes = [{frames[0]}, {frames[1]}]\nresolution = [{resolution[0]}, {resolution[1]}]\nspp = {spp}\n"
        f"directory = '{tmp_path / 'out'}'\n"
        "[ocean]\nresolution = 16\npatch_size = 40.0\n[render]\nwhite_spp = 64\nmax_depth = 6\n"
    ))
    return path


@pytest.mark.slow
def test_per_frame_update_renders_like_a_fresh_load(variant):
    scene = tiny_scene()
    sequence = Sequence(scene, variant)  # loaded with frame 0's geometry
    later = sequence.geometry(7)  # a later frame: every vertex moves
    first = sequence.geometry(0)
    assert np.abs(later.positions - first.positions).max() > 0.01
    sequence.renderer.update_water(later)
    updated, _ = sequence.renderer.render_xyz(spp=4, seed=11)
    fresh = WaterRenderer.build(scene, sequence.iops, sequence.faces, later, roughness=sequence.roughness, spp=4,
                                sun_lobe_alpha=sequence.sun_lobe_alpha)
    reloaded, _ = fresh.render_xyz(spp=4, seed=11)
    # float32 films (pixels ≫ 0): the update rebuilds the acceleration structure in place, the
    # fresh load builds its own; the same vertices and seed agree to the last bits (observed: exactly).
    np.testing.assert_allclose(updated, reloaded, rtol=ROUNDOFF32)
    # ...and it is not trivially equal to the frame-0 image.
    sequence.renderer.update_water(first)
    other, _ = sequence.renderer.render_xyz(spp=4, seed=11)
    assert np.abs(other - updated).max() > 1.0


def test_sequence_writes_frames_with_metadata_and_resumes(variant, tmp_path):
    scene = tiny_scene()
    report = render_sequence(scene, tmp_path, variant)
    assert report.rendered == [0, 1] and report.skipped == []
    for frame in (0, 1):
        paths = frame_paths(tmp_path, frame)
        assert frame_is_complete(paths.exr, paths.png, (24, 16))
        channels, meta = read_exr(paths.exr)
        assert set(FRAME_CHANNELS) <= set(channels)
        assert meta["frame"] == frame and meta["scene"] == "tiny" and meta["variant"] == variant
        assert meta["time_s"] == pytest.approx(frame / 24.0)
        assert all(np.isfinite(channels[c]).all() for c in FRAME_CHANNELS)
        assert channels["Y"].mean() > 0
    stamp = frame_paths(tmp_path, 0).exr.stat().st_mtime_ns
    frame_paths(tmp_path, 1).png.write_bytes(b"\x89PNG broken")  # damaged frame: must be redone
    again = render_sequence(scene, tmp_path, variant)
    assert again.skipped == [0] and again.rendered == [1]
    assert frame_paths(tmp_path, 0).exr.stat().st_mtime_ns == stamp


def test_cli_tiny_render_end_to_end(tmp_path, capsys):
    scene = tiny_toml(tmp_path)
    assert main(["render", str(scene), "--no-progress"]) == 0
    out = capsys.readouterr().out
    assert "rendered 2 frame(s)" in out and "variant" in out
    assert sorted(p.name for p in (tmp_path / "out" / "tiny").iterdir()) == [
        "frame_0000.exr", "frame_0000.png", "frame_0001.exr", "frame_0001.png"]
    # Overrides from the command line: one more frame at another size goes to another folder.
    assert main(["render", str(scene), "--frames", "2:3", "--resolution", "12x8", "--spp", "2",
                 "--out", str(tmp_path / "o2"), "--no-progress"]) == 0
    assert frame_is_complete(tmp_path / "o2/tiny/frame_0002.exr", tmp_path / "o2/tiny/frame_0002.png", (12, 8))


@pytest.mark.slow
def test_cli_denoised_render_then_movie_and_contact_sheet(tmp_path, capsys):
    scene = tiny_toml(tmp_path, frames=(0, 3), resolution=(32, 18))
    assert main(["render", str(scene), "--denoise", "--no-progress"]) == 0
    folder = tmp_path / "out" / "tiny"
    channels, meta = read_exr(folder / "frame_0001.exr")
    assert meta["denoiser"].startswith("Intel Open Image Denoise") and np.all(np.isfinite(channels["Y"]))
    capsys.readouterr()
    assert main(["movie", str(folder)]) == 0
    assert "3 frames, 24 fps" in capsys.readouterr().out
    assert (folder / "tiny.mp4").stat().st_size > 0 and (folder / "contact_sheet.png").is_file()
    (folder / "frame_0001.png").unlink()
    assert main(["movie", str(folder)]) == 2
    assert "frame_0001.png" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["render", "no/such.toml"], "no/such.toml: cannot read scene file"),
        (["render", "{scene}", "--spp", "0"], "command line: [output] spp"),
        (["render", "{scene}", "--frames", "3:1"], "command line: [output] frames"),
        (["render", "{scene}", "--variant", "llvm_ad_rgb"], "[render] variant"),
        (["render", "{bad}"], "[ocean] wind_speed"),
    ],
)
def test_cli_user_errors_are_one_line_exit_2(tmp_path, capsys, args, message):
    bad = tmp_path / "bad.toml"
    bad.write_text("[ocean]\nwind_speed = -2\n")
    argv = [a.format(scene=tiny_toml(tmp_path), bad=bad) for a in args]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and "\n" not in err and "Traceback" not in err


@pytest.mark.slow
def test_killed_run_resumes_without_losing_frames(tmp_path):
    """SIGKILL at a seeded random frame, rerun: finished frames kept, the rest identical to an uninterrupted run.

    The kill lands once frame k's PNG exists, k drawn uniformly from 1…4 (seed
    ``OCEANRENDER_KILL_SEED``, default 17); the rerun must skip every complete
    frame, and every frame's EXR pixels and PNG must equal, bit for bit, those
    of an uninterrupted run of the same scene in another folder.
    """
    seed = int(os.environ.get("OCEANRENDER_KILL_SEED", "17"))
    kill_after = int(np.random.default_rng(seed).integers(1, 5))
    scene = tiny_toml(tmp_path, frames=(0, 6), resolution=(64, 36), spp=16)
    out, whole = tmp_path / "out" / "tiny", tmp_path / "whole"
    command = [sys.executable, "-m", "oceanrender", "render", str(scene), "--no-progress"]
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, cwd=ROOT)
    deadline = time.monotonic() + 240
    while not (out / f"frame_{kill_after:04d}.png").exists():
        assert proc.poll() is None, proc.stdout.read().decode()
        assert time.monotonic() < deadline, "no frame appeared"
        time.sleep(0.02)
    proc.send_signal(signal.SIGKILL)  # no clean-up handler can run
    proc.wait()
    done = [f for f in range(6) if frame_is_complete(out / f"frame_{f:04d}.exr", out / f"frame_{f:04d}.png", (64, 36))]
    assert kill_after + 1 <= len(done) < 6, f"the kill should land mid-sequence, had {done}"
    stamps = {f: (out / f"frame_{f:04d}.exr").stat().st_mtime_ns for f in done}
    result = subprocess.run(command, capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert result.returncode == 0, result.stderr
    assert f"skipped {len(done)} already complete" in result.stdout
    assert all((out / f"frame_{f:04d}.exr").stat().st_mtime_ns == stamps[f] for f in done)
    assert not list(out.glob(".frame_*")), "temporary files must not survive"
    result = subprocess.run(command + ["--out", str(whole)], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert result.returncode == 0, result.stderr
    for f in range(6):
        resumed, uninterrupted = frame_paths(out, f), frame_paths(whole / "tiny", f)
        assert frame_is_complete(resumed.exr, resumed.png, (64, 36))
        a, b = read_exr(resumed.exr)[0], read_exr(uninterrupted.exr)[0]
        assert a.keys() == b.keys() and all(np.array_equal(a[c], b[c]) for c in a), f"frame {f} differs"
        assert resumed.png.read_bytes() == uninterrupted.png.read_bytes(), f"frame {f}: PNG differs"


def test_cli_geometry_export(tmp_path, capsys):
    from oceanrender.export.wave_maps import read_frame_maps

    scene = tmp_path / "geo.toml"
    scene.write_text("[ocean]\nresolution = 16\npatch_size = 40.0\ncascades = 2\n")
    assert main(["geometry", str(scene), "--frames", "0:2", "--out", str(tmp_path / "g"), "--ply"]) == 0
    for cascade in (0, 1):
        folder = tmp_path / "g" / f"cascade_{cascade}"
        assert (folder / "geometry.json").is_file() and (folder / "mesh_0001.ply").is_file()
        maps = read_frame_maps(folder, 1)
        assert maps  # height, displacement, normal, Jacobian read back
    assert "wrote" in capsys.readouterr().out


def test_composition_builds_the_medium():
    from oceanrender.optics.scene_water import water_composition, water_optics
    from oceanrender.optics.water import MediumOptics
    from oceanrender.render.scene import water_medium

    pure = tiny_scene()
    assert water_composition(pure) is None
    coastal = scene_from_dict({"name": "c", "composition": {"preset": "green coastal", "chlorophyll_mg_m3": 2.5}})
    assert water_composition(coastal).chlorophyll_mg_m3 == 2.5  # explicit keys override the preset
    optics = water_optics(coastal)
    assert isinstance(optics, MediumOptics) and 0.5 < optics.particle_fraction <= 1 and 0.8 < optics.particle_g < 1
    medium = water_medium(optics)
    assert medium["phase"]["type"] == "oceanrender_water_phase"  # blend weight and g per wavelength
    # more stuff in the water: more attenuation than pure sea water at every wavelength
    pure_c = water_optics(pure).attenuation
    wl = optics.iops.wavelengths
    assert np.all(optics.iops.attenuation > np.interp(wl, water_optics(pure).wavelengths, pure_c))


def test_cli_refuses_a_bad_composition(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text("[composition]\nsoil_g_m3 = -1.0\n")
    assert main(["render", str(path)]) == 2
    assert "[composition] soil_g_m3" in capsys.readouterr().err


def test_cli_refuses_an_unknown_particle_phase(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text("[composition]\npreset = 'green coastal'\nparticle_phase = 'Kopelevich'\n")
    assert main(["render", str(path)]) == 2
    assert "[composition] particle_phase" in capsys.readouterr().err


def test_cli_optics_report(tmp_path, capsys):
    import json

    scene = tmp_path / "coastal.toml"
    scene.write_text("[composition]\npreset = 'green coastal'\n[render]\nwhite_spp = 64\n")
    assert main(["optics", str(scene), "--out", str(tmp_path / "o")]) == 0
    out = tmp_path / "o"
    table = np.loadtxt(out / "optics.csv", delimiter=",", comments="#")
    assert table.shape == (95, 11)
    wavelengths, reflectance = table[:, 0], table[:, 6]
    visible = wavelengths <= 700
    assert 500 <= wavelengths[visible][np.argmax(reflectance[visible])] <= 580  # green water reflects green
    document = json.loads((out / "lightfield.json").read_text())
    assert len(document["E_d"]) == 95 and len(document["z_m"]) == 101
    assert (out / "iops.png").stat().st_size > 1000 and (out / "lightfield.png").stat().st_size > 1000
    assert "K_d(550)" in capsys.readouterr().out


def test_adaptation_luminance_modes():
    from oceanrender.pipeline import GREY_CARD_REFLECTANCE, adaptation_luminance

    xyz = np.ones((4, 4, 3)) * 50.0
    white = np.array([9000.0, 10000.0, 11000.0])
    frame = scene_from_dict({"name": "adaptation", "vision": {"adaptation_luminance": "frame"}})
    daylight = scene_from_dict({"name": "adaptation", "vision": {"adaptation_luminance": "daylight"}})
    fixed = scene_from_dict({"name": "adaptation", "vision": {"adaptation_luminance": 123.0}})
    # The log-average of a uniform frame is its luminance (up to Ward's small δ).
    assert adaptation_luminance(frame, xyz) == pytest.approx(50.0, rel=1e-3)
    assert adaptation_luminance(daylight, xyz, white) == pytest.approx(GREY_CARD_REFLECTANCE * 10000.0)
    assert adaptation_luminance(fixed, xyz, white) == 123.0
    with pytest.raises(ValueError, match="daylight"):
        adaptation_luminance(daylight, xyz)


@pytest.mark.slow
def test_spectral_bands_integrate_a_constant_sky_and_are_written(variant, tmp_path):
    import mitsuba as mi

    from oceanrender.render.scene import band_channel_name, xyz_film

    # A constant environment of 1 W m⁻² sr⁻¹ nm⁻¹: each band's integral is its width.
    film = xyz_film(4, 4, bands=5)
    assert [k for k in film if k.startswith("b")] == [band_channel_name(i) for i in range(5)]
    scene = mi.load_dict({"type": "scene", "integrator": {"type": "path", "max_depth": 1},
                          "sensor": {"type": "perspective", "film": film,
                                     "sampler": {"type": "independent", "sample_count": 256}},
                          "sky": {"type": "constant", "radiance": {"type": "spectrum", "value": 1.0}}})
    image = np.array(mi.render(scene, seed=1))
    np.testing.assert_allclose(image[..., 3:].mean(axis=(0, 1)), (830.0 - 360.0) / 5, rtol=0.02)
    # Through the pipeline: frame_NNNN_spectral.exr with one channel per band, radiance per nm.
    render_sequence(tiny_scene(output={"spectral_bands": 4, "frames": [0, 1]}), tmp_path, variant)
    channels, meta = read_exr(tmp_path / "frame_0000_spectral.exr")
    assert sorted(channels) == ["360.0-477.5nm", "477.5-595.0nm", "595.0-712.5nm", "712.5-830.0nm"]
    assert meta["band_edges_nm"].split()[0] == "360.000"
    # Sunsky has no light above 720 nm; the blue-green bands of a daylight sea are lit.
    assert channels["477.5-595.0nm"].mean() > 10 * channels["712.5-830.0nm"].mean() >= 0


@pytest.mark.slow
def test_followed_adaptation_depends_on_the_frame_alone(variant):
    # The eye's state at frame 3 (τ = 0.05 s at 24 fps: a window of frames 0-3) from a run that rendered
    # frames 0-2 first equals that of a fresh run starting at frame 3 (a resumed run, or another Dask
    # worker), and is the filter of the meters of its window.
    from oceanrender.vision.temporal import adaptation_window, adapted_luminance

    scene = tiny_scene(vision={"adaptation_time": 0.05}, output={"frames": [0, 4]})
    run = Sequence(scene, variant)
    frames = [run.compute_frame(f) for f in range(4)]
    resumed = Sequence(scene, variant, first_frame=3)
    again = resumed.compute_frame(3)
    assert list(adaptation_window(3, 0.05, 24.0)) == [0, 1, 2, 3]
    expected = adapted_luminance([run.meter(f) for f in range(4)], 1 / 24, 0.05)
    # Meters are renders on several threads: equal to float32 round-off of the film, not bit for bit.
    assert frames[3].metadata["adaptation_luminance_cd_m2"] == pytest.approx(expected, rel=ROUNDOFF32)
    assert again.metadata["adaptation_luminance_cd_m2"] == pytest.approx(expected, rel=ROUNDOFF32)
    np.testing.assert_allclose(again.channels["R"], frames[3].channels["R"], rtol=1e-5, atol=1e-6)
    # The meter estimates the log-average over the blocks of its grid of the frame itself (32 samples per
    # block against the frame's 4 per pixel): within 10 %, the noise of blocks of 32 samples. (Per pixel, this
    # tiny noisy frame's log-average is 60× lower: black 4-spp pixels weigh ln δ.)
    from oceanrender.pipeline import METER_COLUMNS
    from oceanrender.render.pixels import grid_mean
    from oceanrender.vision.brightness import adaptation_luminance_log_average

    own = adaptation_luminance_log_average(grid_mean(frames[3].channels["Y"].astype(np.float64), METER_COLUMNS))
    assert run.meter(3) == pytest.approx(own, rel=0.1)
    assert "followed over time" in frames[3].metadata["adaptation"]


@pytest.mark.slow
def test_the_first_frame_runs_the_kernels_compiled_beside_its_sea(variant, monkeypatch):
    # A radial sea loads the scene with a calm stand-in of frame 0 (the same arrays, the sea at rest), and a
    # second thread compiles the frame's and the meter's kernels while the real frame 0 is computed. Frame 0
    # then compiles nothing: each of its large kernels (render passes, meter passes) is found in memory, not
    # compiled nor read from the disk cache (a kernel traced differently would be one or the other). And it
    # renders what a scene loaded with the real frame 0 renders.
    import drjit as dr

    scene = tiny_scene(mesh={"kind": "radial", "outer_radius": 300.0, "segments": 32},
                       ocean={"resolution": 16, "patch_size": 40.0, "cascades": 2})
    run = Sequence(scene, variant)
    assert run.body.frame_layout(0.0) is not None and run.follows_adaptation
    with dr.scoped_set_flag(dr.JitFlag.KernelHistory, True):
        dr.kernel_history()  # (emptied; the flag and the history are this thread's)
        frame = run.compute_frame(0)
        large = [k for k in dr.kernel_history() if k["type"] == dr.KernelType.JIT and k["operation_count"] > 10_000]
    assert len(large) >= 2  # the render's pass(es) and the meter's
    assert all(k["cache_hit"] and not k["cache_disk"] for k in large), [(k["cache_hit"], k["cache_disk"]) for k in large]
    monkeypatch.setattr(Sequence, "_stand_in", lambda self, frame: None)  # loaded with the real frame 0
    direct = Sequence(scene, variant).compute_frame(0)
    # float32 films: the same vertices and seed agree to the last bits (observed: exactly, every channel)
    for name in "XYZ":
        np.testing.assert_allclose(frame.channels[name], direct.channels[name], rtol=ROUNDOFF32)
    assert frame.metadata["adaptation_luminance_cd_m2"] == pytest.approx(
        direct.metadata["adaptation_luminance_cd_m2"], rel=ROUNDOFF32)


def test_zero_adaptation_time_adapts_each_frame_to_itself(variant):
    from oceanrender.vision.brightness import adaptation_luminance_log_average

    scene = tiny_scene(vision={"adaptation_time": 0.0})
    frame = Sequence(scene, variant).compute_frame(0)
    own = adaptation_luminance_log_average(frame.channels["Y"])
    assert frame.metadata["adaptation_luminance_cd_m2"] == pytest.approx(own, rel=ROUNDOFF32)
    assert frame.metadata["adaptation"] == "this frame's log-average luminance"
    assert frame.seconds["meter"] == 0.0


@pytest.mark.parametrize("ocean", [
    "hs = 1.5\ntp = 6.0\ndirection = 20.0\n[[ocean.partitions]]\nhs = 1.0\ntp = 12.0\ndirection = 110.0\n"
    "spreading_s = 40.0\n",
    pytest.param(f"spectrum_file = '{ROOT / 'scenes' / 'sea_states' / 'bimodal.swn'}'\n"
                 "spectrum_time = '2026-03-14T08:00:00'\nspectrum_site = 1\n", marks=needs_spectra),
])
def test_cli_geometry_export_of_measured_sea_states(tmp_path, capsys, ocean):
    """Issue 23 item 5: `oceanrender geometry` with the sea-state and the file forms; the sidecar says which."""
    import json

    scene = tmp_path / "sea.toml"
    scene.write_text("[ocean]\nresolution = 16\npatch_size = 400.0\ncascades = 1\n" + ocean)
    assert main(["geometry", str(scene), "--frames", "0:1", "--out", str(tmp_path / "g")]) == 0
    meta = json.loads((tmp_path / "g" / "cascade_0" / "geometry.json").read_text())
    sea = meta["parameters"]["ocean"]
    assert sea["form"] in ("sea state", "file")
    assert sea["significant_wave_height_m"] > 0.5 and sea["peak_period_s"] > 5.0
    assert "wrote" in capsys.readouterr().out


def test_a_non_finite_field_of_the_sea_stops_the_frame_naming_stage_and_keys():
    """Issue 39: a NaN in the foam was 'repaired' into a black sea; now the frame is refused in one line."""
    from oceanrender.pipeline import check_geometry
    from oceanrender.surface.frame import FrameError

    positions = np.zeros((4, 3), np.float32)
    normals = np.tile(np.float32([0, 0, 1]), (4, 1))
    good = FrameGeometry(positions, normals, np.zeros(4, np.float32))
    assert check_geometry(good, 3, 0.125) is good
    foam = np.float32([0.0, np.nan, 0.2, np.inf])
    with pytest.raises(FrameError, match=r"frame 3 \(t = 0.125 s\): stage geometry: 2 non-finite value\(s\) in the "
                                         r"water's foam, from the foam model: \[foam\]"):
        check_geometry(FrameGeometry(positions, normals, foam), 3, 0.125)


def test_more_repaired_pixels_than_a_small_share_fail_the_frame():
    from oceanrender.pipeline import REPAIR_SHARE, check_repaired
    from oceanrender.surface.frame import FrameError

    pixels = 1280 * 720
    check_repaired(int(REPAIR_SHARE * pixels), pixels, 0)  # a handful of NaN pixels: repaired, as before
    with pytest.raises(FrameError, match=r"frame 7: stage render: 922 of 921600 pixels came out non-finite"):
        check_repaired(int(REPAIR_SHARE * pixels) + 1, pixels, 7)
