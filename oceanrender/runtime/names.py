"""The Mitsuba variants oceanrender supports, by name only (no Mitsuba import: the scene checks use it)."""

#: Order of preference of the spectral variants: GPU, CPU JIT. These are the only ones supported; the
#: scalar variants lack the vectorised drjit arrays the split integrator and the mesh updates use.
SPECTRAL_VARIANTS = ("cuda_ad_spectral", "llvm_ad_spectral")
