"""Named tolerances for the test suite, each relative to the scale of the quantity it checks.

A comparison that depends on the last bits of a float64 result changes between numpy,
scipy and OpenBLAS builds (summation order, SIMD paths, libm), so no test may ask for
more than these. An absolute tolerance is always written as a multiple of the
quantity's own scale (its maximum, its mean, or a physical reference value), never as
a bare number far below that scale.
"""

import numpy as np

#: Machine epsilon of float64 [1].
EPS64 = float(np.finfo(np.float64).eps)

#: One float64 formula evaluated by two code paths, or checked against an equivalent
#: closed form [relative to the quantity's scale]: ~4500 ulp, room for sums of 10³–10⁴
#: terms and for different libm/SIMD/BLAS paths, still 10⁴× below anything physical.
ROUNDOFF = 1e-12

#: As ROUNDOFF for results stored or computed in float32 [relative to the scale]:
#: ~800 ulp of float32 (eps 1.19e-7).
ROUNDOFF32 = 1e-4

#: Closed forms evaluated by numerical quadrature or root finding in float64
#: [relative]: the integrators' own error targets are 1e-8…1e-10.
QUADRATURE = 1e-6
