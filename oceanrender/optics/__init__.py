"""Water optics: spectral tables and inherent optical properties."""
