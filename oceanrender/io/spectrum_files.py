"""Directional wave spectra E(f, θ) from buoy and wave-model files, read with wavespectra.

wavespectra (MetOcean Solutions; PyPI, optional extra ``spectra``) reads
the formats people hold measured and forecast spectra in — SWAN ASCII,
WAVEWATCH III, ERA5, NDBC, Octopus, WWM, netCDF and more — into one xarray
layout: ``efth`` [m² Hz⁻¹ deg⁻¹] over ``freq`` [Hz] and ``dir`` [deg], in
the nautical convention (the direction the waves come *from*, clockwise from
north). This module picks one time and one site and returns the spectrum in
the project's frame: directions of travel, counter-clockwise from +x (east),
in radians, and E per radian:

    θ_to = 270° − θ_from  (waves from the west, 270°, travel east, θ_to = 0)
    E(f, θ_to) [m² Hz⁻¹ rad⁻¹] = efth(f, θ_from) [m² Hz⁻¹ deg⁻¹] · 180/π

References
----------
.. [1] wavespectra, https://github.com/wavespectra/wavespectra (v4.9), the
   ``read_*`` functions and the attribute conventions of ``wavespectra.core.attributes``.
.. [2] L. H. Holthuijsen, Waves in Oceanic and Coastal Waters, Cambridge
   University Press, 2007, §3.5 (the directional spectrum E(f, θ), nautical convention).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .messages import quoted

__all__ = ["FileSpectrum", "read_spectrum_file", "READERS", "reader_for"]

#: ``[ocean] spectrum_format`` → wavespectra reader.
READERS = {"swan": "read_swan", "ww3": "read_ww3", "netcdf": "read_netcdf", "octopus": "read_octopus",
           "ncswan": "read_ncswan", "era5": "read_era5", "wwm": "read_wwm", "json": "read_json"}

#: File name endings → format for ``spectrum_format = "auto"``.
SUFFIXES = {(".spc", ".spec", ".swn", ".sp2", ".spc.gz", ".swn.gz"): "swan", (".csv", ".oct"): "octopus",
            (".json",): "json", (".nc", ".nc4", ".cdf"): "netcdf"}


@dataclass(frozen=True, eq=False)
class FileSpectrum:
    """One directional spectrum from a file, in the project's frame.

    Attributes
    ----------
    frequency : ndarray (F,)        Frequencies f [Hz], increasing.
    direction : ndarray (D,)        Directions of travel θ, counter-clockwise from +x, increasing in [0, 2π) [rad].
    density : ndarray (F, D)        E(f, θ) [m² Hz⁻¹ rad⁻¹].
    time : str                      The time picked (ISO 8601), or "" for a file without times.
    site : int                      The site picked [-].
    sites : int                     Sites in the file [-].
    source : str                    File, format and what wavespectra reported.
    """

    frequency: NDArray[np.float64]
    direction: NDArray[np.float64]
    density: NDArray[np.float64]
    time: str
    site: int
    sites: int
    source: str


def reader_for(path: str | Path, spectrum_format: str) -> str:
    """The ``spectrum_format`` of a file: as given, or from its name for ``"auto"`` (ValueError if unknown)."""
    if spectrum_format != "auto":
        return spectrum_format
    name = Path(path).name.lower()
    for suffixes, fmt in SUFFIXES.items():
        if name.endswith(suffixes):
            return fmt
    raise ValueError(f"cannot tell the format from the name {quoted(Path(path).name)}; set spectrum_format "
                     f"({', '.join(READERS)})")


def _as_time_site_freq_dir(efth):
    """efth with dims (time, site, freq, dir): other dims (site, lat, lon, ...) stacked into ``site``."""
    data = efth
    if "time" not in data.dims:
        data = data.expand_dims(time=[np.datetime64("NaT")])
    rest = [d for d in data.dims if d not in ("time", "freq", "dir")]
    if not rest:
        data = data.expand_dims(site=[0])
    elif rest != ["site"]:
        data = data.stack(site=rest)
    return data.transpose("time", "site", "freq", "dir")


@lru_cache(maxsize=8)
def _read(path: str, mtime: float, spectrum_format: str, time: str | None, site: int) -> FileSpectrum:
    try:
        import wavespectra  # noqa: PLC0415
    except ImportError:
        raise ValueError("reading spectrum files needs wavespectra: pip install 'oceanrender[spectra]' "
                         "(make setup installs it)") from None
    fmt = reader_for(path, spectrum_format)
    reader = getattr(wavespectra, READERS[fmt])
    try:
        dataset = reader(path)
    except Exception as exc:  # noqa: BLE001 (every reader failure means the same to the user)
        raise ValueError(f"wavespectra.{READERS[fmt]} cannot read it ({exc.__class__.__name__}: "
                         f"{str(exc).splitlines()[0] if str(exc) else ''})") from None
    if "efth" not in dataset or not {"freq", "dir"} <= set(dataset["efth"].dims):
        raise ValueError("no 2-D spectrum efth(freq, dir) in it (a 1-D spectrum has no directions)")
    efth = _as_time_site_freq_dir(dataset["efth"])
    times = efth["time"].values
    if time is None:
        index = 0
    else:
        try:
            wanted = np.datetime64(time).astype(times.dtype)
        except ValueError:
            raise ValueError(f"spectrum_time {quoted(time)} is not an ISO 8601 time") from None
        matches = np.flatnonzero(times == wanted)
        if matches.size == 0:
            shown = ", ".join(str(t)[:19] for t in times[:4]) + (" ..." if len(times) > 4 else "")
            raise ValueError(f"spectrum_time {quoted(time)} is not in the file (it has {len(times)} times: {shown})")
        index = int(matches[0])
    sites = int(efth.sizes["site"])
    if site >= sites:
        raise ValueError(f"spectrum_site {site} is not in the file (it has {sites} site(s): 0 to {sites - 1})")
    values = np.asarray(efth.isel(time=index, site=site).values, dtype=np.float64)  # (freq, dir) [m² Hz⁻¹ deg⁻¹]
    frequency = np.asarray(efth["freq"].values, dtype=np.float64)
    direction_from = np.asarray(efth["dir"].values, dtype=np.float64)
    if values.ndim != 2 or frequency.size < 3 or direction_from.size < 4:
        raise ValueError(f"needs at least 3 frequencies and 4 directions, got {frequency.size} and "
                         f"{direction_from.size}")
    if not np.all(np.isfinite(values)) or np.any(values < 0):
        raise ValueError("the spectrum has negative or non-finite values")
    if not np.any(values > 0):
        raise ValueError("the spectrum is zero everywhere at that time and site")
    # Nautical "from", clockwise from north → "towards", counter-clockwise from east (module docstring).
    direction = np.mod(np.radians(270.0 - direction_from), 2.0 * math.pi)
    order_f, order_d = np.argsort(frequency), np.argsort(direction)
    density = values[order_f][:, order_d] * (180.0 / math.pi)
    when = "" if np.isnat(times[index]) else str(np.datetime_as_string(times[index], unit="s"))
    return FileSpectrum(frequency[order_f], direction[order_d], density, when, int(site), sites,
                        f"{path} ({fmt}, wavespectra {wavespectra.__version__})")


def read_spectrum_file(path: str | Path, spectrum_format: str = "auto", time: str | None = None, site: int = 0
                       ) -> FileSpectrum:
    """Read E(f, θ) at ``time`` (ISO 8601; default the first) and ``site`` (index) from a spectrum file.

    Raises
    ------
    ValueError
        One line: an unreadable file, a format wavespectra cannot read, a
        time or site not in the file, a spectrum without directions, or
        negative or non-finite values.
    """
    path = Path(path)
    if not path.is_file():
        raise ValueError("no such file")
    return _read(str(path.resolve()), path.stat().st_mtime, spectrum_format, time, int(site))
