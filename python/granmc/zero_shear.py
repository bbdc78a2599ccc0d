"""The Navier-Stokes limit of a sheared steady state: eta at a* -> 0 from runs at several shear rates.

Uniform shear flow is non-Newtonian: eta*(a*) = eta*_NS + c a*^2 + O(a*^4) (the stress is odd in a, so eta is
even). A run's reduced shear rate a* is its mean over the viscosity window; the fit is weighted least squares
of eta against a*^2 over the rates, and the intercept is the Navier-Stokes value. Used by granmc.figures
(`[figure.zero_shear]`) and drivers/shear_rate_extrapolation.py.
"""
import numpy as np


def window_mean_shear_rate(viscosity):
    """Mean reduced shear rate a* over the samples of the viscosity window (the last half), from a summary's
    viscosity block."""
    a = np.asarray(viscosity["reduced_shear_rate"]["mean"], dtype=float)
    return float(np.mean(a[len(a) // 2:]))


def fit_intercept(a_star, eta, sigma):
    """Weighted least squares eta = b0 + b1 a*^2; returns (b0, standard error of b0, b1)."""
    x = np.asarray(a_star) ** 2
    A = np.vstack([np.ones_like(x), x]).T
    w = 1.0 / np.asarray(sigma) ** 2
    cov = np.linalg.inv(A.T @ (A * w[:, None]))
    b = cov @ A.T @ (w * np.asarray(eta))
    return float(b[0]), float(np.sqrt(cov[0, 0])), float(b[1])
