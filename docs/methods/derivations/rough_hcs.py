#!/usr/bin/env python3
"""Energy production rates of inelastic rough hard spheres (d = 3) and disks (d = 2) in the Maxwellian
approximation, the cooling state's temperature ratio theta = T_rot / T_tr, and the steady theta under white
noise acting on translation only.  Derivation: docs/methods/derivations/rough-hcs.md.

Run with /usr/bin/python3 (needs sympy and numpy): `rough_hcs.py` prints the rates (exact, from the moments
below) and a table of theta and the reduced cooling rate; `--mc` checks the per-collision energy changes by
Monte Carlo with the explicit collision rule.

Collision rule (equal masses m, diameter sigma, moment of inertia I = kappa m sigma^2 / 4, normal restitution
alpha, tangential restitution beta in [-1, 1]; Huthmann and Zippelius, Phys. Rev. E 56 (1997) R6275):
sigma-hat points from particle 1 to particle 2, g = v1 - v2 with g.sigma > 0, and the relative velocity of
the contact points is g_c = g + (sigma/2) (w1 + w2) x sigma-hat.  Its normal part is reversed with alpha, its
tangential part g_t with beta:  J = -m (1 + alpha)/2 (g.sigma) sigma-hat - m b g_t is the impulse on 1,
b = (1 + beta) kappa / (2 (1 + kappa)), and v1' = v1 + J/m, v2' = v2 - J/m,
w1' = w1 + (sigma/2) sigma-hat x J / I, w2' = w2 + (sigma/2) sigma-hat x J / I.
beta = -1 is the smooth gas (b = 0); alpha = beta = 1 conserves the total energy.

Per collision, with W = (sigma/2)(w1 + w2), w_t = W x sigma-hat and g_perp = g - (g.sigma) sigma-hat:
  dK_tr  = J.g + |J|^2 / m,            dK_rot = J.w_t + |J_t|^2 / (kappa m).
Averaged over collisions (rate Theta(g.sigma) (g.sigma), Maxwellian translation at T and rotation at T_r,
independent): <(g.sigma)^2> = 4 T/m, <|g_perp|^2> = 2 (d-1) T/m, <|w_t|^2> = 2 (d-1) T_r / (kappa m),
<g_perp.w_t> = 0 (computed below), so
  <dK_tr>  = -(1 - alpha^2) T + 2 (d-1) [-b T + b^2 (T + T_r/kappa)],
  <dK_rot> = 2 (d-1) (b/kappa) [-T_r + b (T + T_r/kappa)].
Each particle takes part in nu collisions per unit time, nu = S_d/... the smooth gas's (4 sqrt(pi) n sigma^2 chi
sqrt(T/m) for spheres, 2 sqrt(pi) n sigma chi sqrt(T/m) for disks), and T = 2 K_tr / d, T_r = 2 K_rot / d_r
per particle, d_r = d (d - 1) / 2 rotational degrees of freedom (3, or 1 for disks):
  dT/dt   = (nu / d)   <dK_tr>,       dT_r/dt = (nu / d_r) <dK_rot>.
The cooling state has zeta_tr = zeta_rot (both temperatures decay at one rate): a quadratic in theta.
White noise on translation only has dT_r/dt = 0: theta = b kappa / (kappa - b), whatever alpha.
"""
import sys

import numpy as np
import sympy as sp


def collision_averages(d):
    """<(g.sigma)^2>, <|g_perp|^2> over collisions, in units of T/m, and <|w_t|^2> in T_r/(kappa m)."""
    th, x = sp.symbols("theta x", positive=True)
    # angle theta between g-hat and sigma-hat: measure sin(theta) d theta (sphere) or d theta (circle),
    # weight cos(theta) (the rate), theta in (0, pi/2) (both halves of the circle alike)
    measure = sp.sin(th) if d == 3 else sp.Integer(1)
    norm = sp.integrate(sp.cos(th) * measure, (th, 0, sp.pi / 2))
    cos2 = sp.integrate(sp.cos(th) ** 3 * measure, (th, 0, sp.pi / 2)) / norm
    sin2 = 1 - cos2
    # |g| with weight |g| (the rate): g has d Gaussian components of variance 2T/m; chi_d moments of x = |g|
    pdf = x ** (d - 1) * sp.exp(-x**2 / 4)  # variance 2 per component (T/m = 1)
    g3 = sp.integrate(x**3 * pdf, (x, 0, sp.oo)) / sp.integrate(x * pdf, (x, 0, sp.oo))
    # W = (sigma/2)(w1 + w2): each rotational component has variance 2 T_r / (kappa m) (I <w_c^2> = T_r);
    # |W x sigma-hat|^2 keeps the d - 1 components perpendicular to sigma-hat (spheres 2 of 3; a disk's
    # spin along z is always perpendicular to sigma-hat in the plane)
    wt2 = 2 * (d - 1)
    return sp.simplify(cos2 * g3), sp.simplify(sin2 * g3), sp.Integer(wt2)


def rates(d):
    al, b, k, T, Tr = sp.symbols("alpha b kappa T T_r", positive=True)
    n2, perp2, wt2 = collision_averages(d)
    A = (1 + al) / 2  # J_n = -m A (g.sigma) sigma-hat
    # dK_tr = J.g + |J|^2/m with J = -m A (g.sigma) s - m b (g_perp + w_t); m = 1
    dk_tr = -A * n2 * T + A**2 * n2 * T - b * perp2 * T + b**2 * (perp2 * T + wt2 * Tr / k)
    dk_rot = -b * wt2 * Tr / k + b**2 * (perp2 * T + wt2 * Tr / k) / k
    return sp.simplify(sp.expand(dk_tr)), sp.simplify(sp.expand(dk_rot)), (al, b, k, T, Tr)


def theta_hcs(d, alpha, beta, kappa):
    """theta of the cooling state and zeta / nu (Maxwellian approximation)."""
    b = (1 + beta) * kappa / (2 * (1 + kappa))
    dr = d * (d - 1) // 2
    c = 2 * (d - 1)
    # zeta_tr / nu = [(1 - alpha^2) + c (b - b^2 (1 + theta/kappa))] / d
    # zeta_rot / nu = c (b/kappa) [1 - b (1/theta + 1/kappa)] / dr; equal -> quadratic in theta
    # multiply by theta: (q2 theta^2 + q1 theta + q0) = 0
    q2 = -c * b * b / (kappa * d)
    q1 = ((1 - alpha**2) + c * (b - b * b)) / d - c * (b / kappa) * (1 - b / kappa) / dr
    q0 = c * b * b / (kappa * dr)
    if b == 0:
        return 0.0, (1 - alpha**2) / d
    disc = q1 * q1 - 4 * q2 * q0
    theta = (-q1 - np.sqrt(disc)) / (2 * q2)  # q2 < 0 < q0: one positive root
    zeta = ((1 - alpha**2) + c * (b - b * b * (1 + theta / kappa))) / d
    return theta, zeta


def theta_white_noise(beta, kappa):
    b = (1 + beta) * kappa / (2 * (1 + kappa))
    return b * kappa / (kappa - b)


def monte_carlo(d, alpha, beta, kappa, T=1.0, Tr=0.7, n=4_000_000, seed=1):
    """<dK_tr>, <dK_rot> per collision (and their standard errors) from the explicit rule."""
    rng = np.random.default_rng(seed)
    m, sigma = 1.0, 1.0
    inertia = kappa * m * sigma**2 / 4
    v1 = rng.normal(0, np.sqrt(T / m), (n, 3))
    v2 = rng.normal(0, np.sqrt(T / m), (n, 3))
    w1 = rng.normal(0, np.sqrt(Tr / inertia), (n, 3))
    w2 = rng.normal(0, np.sqrt(Tr / inertia), (n, 3))
    s = rng.normal(size=(n, 3))
    if d == 2:
        v1[:, 2] = v2[:, 2] = s[:, 2] = 0.0
        w1[:, :2] = w2[:, :2] = 0.0
    s /= np.linalg.norm(s, axis=1)[:, None]
    g = v1 - v2
    gs = np.einsum("ij,ij->i", g, s)
    # rate Theta(g.sigma) (g.sigma) as a weight on uniform sigma-hat
    weight = np.where(gs > 0, gs, 0.0)
    W = 0.5 * sigma * (w1 + w2)
    gc = g + np.cross(W, s)
    gt = gc - gs[:, None] * s
    b = (1 + beta) * kappa / (2 * (1 + kappa))
    J = -m * (1 + alpha) / 2 * gs[:, None] * s - m * b * gt
    v1n, v2n = v1 + J / m, v2 - J / m
    dw = 0.5 * sigma * np.cross(s, J) / inertia
    w1n, w2n = w1 + dw, w2 + dw
    dk_tr = 0.5 * m * (np.sum(v1n**2 + v2n**2, axis=1) - np.sum(v1**2 + v2**2, axis=1))
    dk_rot = 0.5 * inertia * (np.sum(w1n**2 + w2n**2, axis=1) - np.sum(w1**2 + w2**2, axis=1))
    out = []
    for x in (dk_tr, dk_rot):
        mean = np.sum(weight * x) / np.sum(weight)
        # delta-method standard error of a ratio of means
        r = weight * (x - mean)
        se = np.sqrt(np.mean(r**2) / n) / np.mean(weight)
        out.append((mean, se))
    return out


def main():
    for d in (3, 2):
        dk_tr, dk_rot, (al, b, k, T, Tr) = rates(d)
        print(f"d = {d}: <dK_tr> = {dk_tr}")
        print(f"       <dK_rot> = {dk_rot}")
    print()
    print("theta = T_rot/T_tr of the cooling state, zeta/nu (Maxwellian approximation), white-noise theta")
    print(" d  alpha   beta  kappa   theta_hcs     zeta/nu       theta_wn")
    for d, kappa in ((3, 0.4), (2, 0.5)):
        for alpha in (1.0, 0.9, 0.7):
            for beta in (-1.0, -0.5, 0.0, 0.5, 1.0):
                th, z = theta_hcs(d, alpha, beta, kappa)
                print(f" {d}  {alpha:4.2f}  {beta:5.2f}  {kappa:4.2f}  {th:.10f}  {z:.10f}  "
                      f"{theta_white_noise(beta, kappa):.10f}")
    if "--mc" in sys.argv:
        print()
        print("Monte Carlo of the rule against the rates (T = 1, T_r = 0.7): (measured - exact) / standard error")
        for d, kappa in ((3, 0.4), (2, 0.5)):
            dk_tr, dk_rot, (al, b, k, T, Tr) = rates(d)
            for alpha, beta in ((0.8, -1.0), (0.8, 0.3), (1.0, 1.0), (0.5, 0.8)):
                bb = (1 + beta) * kappa / (2 * (1 + kappa))
                subs = {al: alpha, b: bb, k: kappa, T: 1.0, Tr: 0.7}
                exact = (float(dk_tr.subs(subs)), float(dk_rot.subs(subs)))
                (mt, st), (mr, sr) = monte_carlo(d, alpha, beta, kappa)
                zt = (mt - exact[0]) / st if st > 0 else 0.0
                zr = (mr - exact[1]) / sr if sr > 0 else 0.0
                print(f" d = {d} alpha = {alpha} beta = {beta}: dK_tr {mt:+.5f} (exact {exact[0]:+.5f}, {zt:+.2f} se)"
                      f"  dK_rot {mr:+.5f} (exact {exact[1]:+.5f}, {zr:+.2f} se)")


if __name__ == "__main__":
    main()
