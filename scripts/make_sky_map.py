"""Write ``scenes/maps/sunsky_e35_t3.exr``: an equirectangular map of Mitsuba's ``sunsky`` sky (no sun).

Run from the repository root::

    python scripts/make_sky_map.py

Made here from the Hosek & Wilkie (2012) sky model as Mitsuba 3.9.1's ``sunsky`` evaluates it
(turbidity 3, ground albedo 0.1, sun at 35° elevation and azimuth 30° — the sun of
``scenes/environment.toml`` — sky only, ``sun_scale = 0``): so it is CC0 with the repository,
with nothing to attribute. 256 × 128 pixels, the top row the zenith, column u at azimuth
360° u clockwise from north. Each pixel: the sky's spectral radiance at 360–720 nm (5 nm;
``sunsky`` is zero above), integrated with the CIE 1931 2° observer (colour-science) into XYZ,
converted to linear sRGB, divided by the luminance Mitsuba gives an RGB of (1, 1, 1) — so that
a ``scale`` of 1 reproduces the sky's absolute luminance. Below the horizon: the sky model's
value there (its ground).
"""

from __future__ import annotations

from pathlib import Path

import colour
import drjit as dr
import mitsuba as mi
import numpy as np

OUT = Path(__file__).resolve().parents[1] / "scenes" / "maps" / "sunsky_e35_t3.exr"
WIDTH, HEIGHT = 256, 128
WAVELENGTHS = np.arange(360.0, 831.0, 5.0)


def directions() -> np.ndarray:
    """World directions (H·W, 3) of the pixel centres (z up; column u at azimuth 360° u clockwise from north)."""
    u = (np.arange(WIDTH) + 0.5) / WIDTH
    v = (np.arange(HEIGHT) + 0.5) / HEIGHT
    azimuth, zenith = np.meshgrid(2 * np.pi * u, np.pi * v)
    return np.stack([np.sin(zenith) * np.sin(azimuth), np.sin(zenith) * np.cos(azimuth), np.cos(zenith)], -1).reshape(-1, 3)


def emitter_spectra(emitter, d: np.ndarray) -> np.ndarray:
    """Radiance (N, len(WAVELENGTHS)) of an infinite emitter towards directions d [W m⁻² sr⁻¹ nm⁻¹]."""
    si = dr.zeros(mi.SurfaceInteraction3f, len(d))
    si.wi = mi.Vector3f(*(mi.Float(-d[:, i].astype(np.float32)) for i in range(3)))
    out = np.zeros((len(d), len(WAVELENGTHS)))
    for start in range(0, len(WAVELENGTHS), 4):
        chunk = list(WAVELENGTHS[start:start + 4]) + [WAVELENGTHS[-1]] * (4 - len(WAVELENGTHS[start:start + 4]))
        si.wavelengths = mi.Spectrum(*(mi.Float(np.full(len(d), w, np.float32)) for w in chunk))
        value = np.stack([np.array(c, dtype=np.float64) for c in emitter.eval(si)], -1)  # (N, 4)
        n = min(4, len(WAVELENGTHS) - start)
        out[:, start:start + n] = value[:, :n]
    return out


def xyz(spectra: np.ndarray) -> np.ndarray:
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(360, 830, 5)).values  # (W, 3)
    return 683.0 * spectra @ cmfs * 5.0  # absolute, Y in cd m⁻²


def main() -> None:
    mi.set_variant("llvm_ad_spectral")
    sky = mi.load_dict({"type": "sunsky", "turbidity": 3.0, "albedo": 0.1, "sun_scale": 0.0,
                        "sun_direction": [np.cos(np.radians(35)) * np.sin(np.radians(30)),
                                          np.cos(np.radians(35)) * np.cos(np.radians(30)), np.sin(np.radians(35))]})
    XYZ = xyz(emitter_spectra(sky, directions()))
    white = mi.load_dict({"type": "constant", "radiance": {"type": "rgb", "value": [1.0, 1.0, 1.0]}})
    white_Y = float(xyz(emitter_spectra(white, np.array([[0.0, 0.0, 1.0]])))[0, 1])
    rgb = colour.XYZ_to_RGB(XYZ / white_Y, colour.RGB_COLOURSPACES["sRGB"], apply_cctf_encoding=False)
    rgb = np.clip(rgb, 0.0, None).reshape(HEIGHT, WIDTH, 3).astype(np.float32)  # out-of-gamut blue: clipped at 0
    OUT.parent.mkdir(parents=True, exist_ok=True)
    mi.Bitmap(rgb, pixel_format=mi.Bitmap.PixelFormat.RGB).write(str(OUT))
    print(f"wrote {OUT}: {WIDTH} x {HEIGHT}, luminance {XYZ[:, 1].min():.4g}-{XYZ[:, 1].max():.4g} cd/m2; "
          f"RGB (1,1,1) in Mitsuba = {white_Y:.4g} cd/m2")


if __name__ == "__main__":
    main()
