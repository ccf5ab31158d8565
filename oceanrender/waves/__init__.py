"""Waves: the sea surface as a function of (x, y, t), in physical units.

Wave spectra and directional spreading, dispersion, Tessendorf's FFT ocean and its
cascades, sums of sines and Gerstner waves, fractal detail, foam from folding, height
queries and the Beckmann roughness of the waves finer than a mesh. Fields and arrays
only: no meshes (``oceanrender.surface``), no light.

Units: lengths in m, time in s, wavenumbers in rad m⁻¹, angular frequencies in
rad s⁻¹; z up, x east, y north; angles in radians counter-clockwise from +x.
"""
