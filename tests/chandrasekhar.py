"""Chandrasekhar's H-function of isotropic scattering: an independent closed form for the radiative-transfer tests."""

import numpy as np


def h_function(omega, mu, nodes=400, iterations=2000):
    """H(μ) for single-scattering albedo ω, by iterating H = 1/(1 − (ω/2) μ ∫₀¹ H(μ')/(μ + μ') dμ').

    Chandrasekhar (1960), Radiative Transfer, § 35; Gauss–Legendre on (0, 1). The plane albedo
    of a semi-infinite isotropic medium under a beam at μ₀ is 1 − H(μ₀) √(1 − ω) (§ 47), and its
    emergent radiance (ω F/4) μ₀/(μ + μ₀) H(μ) H(μ₀) (πF the beam's normal irradiance).
    """
    x, w = np.polynomial.legendre.leggauss(nodes)
    x, w = 0.5 * (x + 1.0), 0.5 * w
    H = np.ones_like(x)
    for _ in range(iterations):
        H = 1.0 / (1.0 - 0.5 * omega * x * np.sum(w * H / (x[:, None] + x[None, :]), axis=1))
    return 1.0 / (1.0 - 0.5 * omega * mu * np.sum(w * H / (mu + x)))
