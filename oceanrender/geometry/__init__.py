"""Sea-surface geometry: wave spectra, Tessendorf's FFT ocean and the water-body mesh.

Units: lengths in m, time in s, wavenumbers in rad m⁻¹, angular frequencies in
rad s⁻¹; z up, x east, y north; angles in radians counter-clockwise from +x.
"""

from .fft_ocean import (
    FFTOcean,
    OceanFields,
    OceanGrid,
    elevation_variance,
    initial_amplitudes,
    negate_wavenumber,
    ocean_fields,
    time_amplitudes,
)
from .mesh import (
    signed_volume,
    water_body_face_count,
    water_body_faces,
    water_body_vertex_count,
    water_body_vertices,
)
from .spectra import (
    GRAVITY,
    PHILLIPS_ALPHA,
    SPECTRA,
    dispersion_relation,
    elevation_variance_Phillips2001,
    significant_wave_height_Phillips2001,
    spectrum_Phillips2001,
    wave_spectrum,
)

__all__ = [
    "GRAVITY",
    "PHILLIPS_ALPHA",
    "SPECTRA",
    "spectrum_Phillips2001",
    "elevation_variance_Phillips2001",
    "significant_wave_height_Phillips2001",
    "dispersion_relation",
    "wave_spectrum",
    "OceanGrid",
    "OceanFields",
    "FFTOcean",
    "initial_amplitudes",
    "elevation_variance",
    "negate_wavenumber",
    "time_amplitudes",
    "ocean_fields",
    "water_body_vertex_count",
    "water_body_face_count",
    "water_body_faces",
    "water_body_vertices",
    "signed_volume",
]
