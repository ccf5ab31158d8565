"""Reading the project's spectral tables in ``spectra/``.

Each table is a CSV whose ``#`` header names its units and source, followed by
one column-name line; the first column is the wavelength [nm].
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: Folder of the project's spectral tables (``spectra/`` at the repository root).
SPECTRA_DIR = Path(__file__).resolve().parents[2] / "spectra"

#: Largest spectral table accepted [bytes] (the project's are below 100 kB).
MAX_TABLE_BYTES = 16 << 20

#: The wavelength range every rendered spectrum must cover [nm] (CIE 1931 CMFs).
VISIBLE_RANGE_NM = (360.0, 830.0)


class SpectralDataError(ValueError):
    """A spectral table that is missing, malformed or too short in wavelength."""


@dataclass(frozen=True)
class SpectralTable:
    """A wavelength-indexed table.

    Attributes
    ----------
    wavelengths : ndarray
        Strictly increasing wavelengths [nm].
    columns : dict of str to ndarray
        The other columns, by name (units in the file's header).
    header : str
        The provenance header of the file.
    """

    wavelengths: np.ndarray
    columns: dict[str, np.ndarray]
    header: str

    def at(self, name: str, wavelengths: np.ndarray) -> np.ndarray:
        """Column ``name`` linearly interpolated at ``wavelengths`` [nm].

        Refuses wavelengths outside the table: no silent extrapolation.
        """
        wavelengths = np.asarray(wavelengths, dtype=float)
        lo, hi = self.wavelengths[0], self.wavelengths[-1]
        if wavelengths.size and (wavelengths.min() < lo or wavelengths.max() > hi):
            raise SpectralDataError(
                f"wavelengths {wavelengths.min():g}-{wavelengths.max():g} nm outside the table's {lo:g}-{hi:g} nm"
            )
        return np.interp(wavelengths, self.wavelengths, self.columns[name])


def read_spectral_table(path: str | Path, required: tuple[str, ...] = (), cover: tuple[float, float] = VISIBLE_RANGE_NM) -> SpectralTable:
    """Read a table from ``spectra/`` (or any path) and check it.

    Parameters
    ----------
    path : str or Path
        A file name inside ``spectra/`` or a path.
    required : tuple of str
        Column names that must be present.
    cover : (float, float)
        Wavelength range [nm] the table must span.
    """
    from ..io.paths import PathProblem, check_input_file  # noqa: PLC0415

    path = Path(path)
    if not path.is_absolute() and len(path.parts) == 1:
        path = SPECTRA_DIR / path  # a bare name is one of the project's tables
    try:
        path = check_input_file(path, MAX_TABLE_BYTES)
        lines = path.read_bytes().decode("utf-8").splitlines()
    except (PathProblem, OSError, UnicodeDecodeError) as exc:
        reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else exc
        if isinstance(exc, UnicodeDecodeError):
            reason = f"not UTF-8 text (byte {exc.start})"
        raise SpectralDataError(f"{str(path)[:300]}: cannot read spectral table ({reason})") from None
    header = [line[1:].strip() for line in lines if line.startswith("#")]
    if len(header) < 2:
        raise SpectralDataError(f"{path}: a spectral table needs a '#' header with units and source")
    names = header[-1].split(",")
    try:
        data = np.loadtxt(lines, delimiter=",", comments="#", ndmin=2)  # the checked bytes, not a second read
    except (ValueError, IndexError) as exc:
        raise SpectralDataError(f"{path}: malformed numbers ({exc})") from None
    if data.shape[1] != len(names):
        raise SpectralDataError(f"{path}: {data.shape[1]} columns but the header names {len(names)}")
    wavelengths = data[:, 0]
    if np.any(np.diff(wavelengths) <= 0) or not np.all(np.isfinite(data)):
        raise SpectralDataError(f"{path}: wavelengths must increase strictly and all values be finite")
    if wavelengths[0] > cover[0] or wavelengths[-1] < cover[1]:
        raise SpectralDataError(
            f"{path}: covers {wavelengths[0]:g}-{wavelengths[-1]:g} nm, expected at least {cover[0]:g}-{cover[1]:g} nm"
        )
    columns = {name: data[:, i] for i, name in enumerate(names[1:], start=1)}
    missing = [name for name in required if name not in columns]
    if missing:
        raise SpectralDataError(f"{path}: missing column(s) {', '.join(missing)}; has {', '.join(columns)}")
    return SpectralTable(wavelengths=wavelengths, columns=columns, header="\n".join(header[:-1]))


def read_reflectance_table(path: str | Path) -> SpectralTable:
    """A reflectance spectrum [-] (column ``reflectance``, each value in [0, 1]) over 360-830 nm [nm].

    The same table format as ``spectra/`` (a ``#`` header with units and source, then
    ``wavelength_nm,reflectance``), e.g. an object's ``albedo_spectrum``.
    """
    table = read_spectral_table(path, required=("reflectance",))
    r = table.columns["reflectance"]
    if not (np.all(r >= 0) and np.all(r <= 1)):
        raise SpectralDataError(f"{path}: reflectance must lie in [0, 1] at every wavelength, got {r.min():g} to "
                                f"{r.max():g}")
    return table
