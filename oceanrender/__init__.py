"""oceanrender: an offline, physically based, spectral renderer for the sea.

Units everywhere: lengths in m, time in s, wavelengths in nm, coefficients in m⁻¹,
radiance in W m⁻² sr⁻¹ nm⁻¹ (spectral) and luminance in cd m⁻².
"""

__version__ = "0.1.0"
