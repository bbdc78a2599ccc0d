#!/usr/bin/env python3
"""Homogeneous cooling state (HCS) of a binary mixture of smooth inelastic hard spheres, d = 3, Enskog
equation with uniform chi_ij: exact collisional moments of the first-Sonine distributions and the
temperature ratio gamma = T_1/T_2 and cumulants a2_i (c_i = 2 a2_i of paper 000) in the Maxwellian and
the linear first-Sonine approximations.

Run with /usr/bin/python3 (needs sympy, numpy, scipy).  Derivation: docs/methods/derivations/mixture-hcs.md.
    python3 mixture_hcs.py           symbolic derivation, exact checks, tables (about 6 s)
    python3 mixture_hcs.py --quad    independent deterministic quadrature of every coefficient
    python3 mixture_hcs.py --mc      independent Monte Carlo of every coefficient (about 2 min)

Species i has f_i(v) = n_i phi_i(v) [1 + a_i S2(v^2 / (2 theta_i))], theta_i = T_i / m_i,
phi_i = (2 pi theta_i)^(-3/2) exp(-v^2 / (2 theta_i)), S2(x) = x^2/2 - 5x/2 + 15/8; then
<v^2>_i = 3 theta_i, <v^4>_i = 15 theta_i^2 (1 + a_i).

The collisional moment of species i due to j (000 eq. 2 with uniform chi_ij):

    int dv v^p J_ij = n_i n_j sigma_ij^2 chi_ij Psi_p^ij,
    Psi_p^ij = int dv1 dv2 dsig Theta(sig.g) (sig.g) phi_i(v1) phi_j(v2) [1 + a_i S2(x1)] [1 + a_j S2(x2)]
               (|v1'|^p - |v1|^p),          v1' = v1 - mu_ji (1 + alpha_ij) (sig.g) sig,  g = v1 - v2.

Decorrelated coordinates (the point of the calculation).  v1 ~ N(0, theta_i), v2 ~ N(0, theta_j)
independently.  The mass centre mu_ij v1 + mu_ji v2 has covariance (T_i - T_j)/(m_i + m_j) with g per
component, so the one-component trick does not factorise when T_i != T_j.  The pair
    g = v1 - v2 ~ N(0, s^2),   G = (theta_j v1 + theta_i v2) / s^2 ~ N(0, theta_i theta_j / s^2),
    s^2 = theta_i + theta_j,
IS independent (Cov(G, g) = (theta_j theta_i - theta_i theta_j)/s^2 = 0), with unit Jacobian and
    v1 = G + u g,  v2 = G - (1 - u) g,   u = theta_i / s^2.
In units of s: G-hat ~ N(0, u (1 - u)), g-hat ~ N(0, 1).  The integrand is isotropic, so the sig integral is
4 pi times the integrand at sig = z (g_z > 0).  v1' depends on mu_ji and alpha_ij only through
    b = mu_ji (1 + alpha_ij).
Everything is then a polynomial in the six Cartesian components (coefficients polynomial in u, b, 1/u,
1/(1-u), a_i, a_j) times independent Gaussians:
    <G_x^(2k)> = (2k-1)!! (u (1-u))^k,  <g_x^(2k)> = (2k-1)!!,  int_0^inf z^(2m+1) N(0,1)(z) dz = 2^m m!/sqrt(2 pi),
so  Psi_p = (4 pi / sqrt(2 pi)) s^(p+1) P_p = 2 sqrt(2 pi) s^(p+1) P_p(u, b; a_i, a_j),
with P_p a polynomial, exactly bilinear in (a_i, a_j) (no truncation).
"""
import os
import sys
import time
from math import factorial

import sympy as sp
from sympy.polys.domains import QQ
from sympy.polys.rings import ring

R, Gx, Gy, Gz, gx, gy, gz, U, W1, W2, B, AI, AJ = ring("Gx,Gy,Gz,gx,gy,gz,u,w1,w2,b,ai,aj", QQ)
u, b, ai, aj, alpha = sp.symbols("u b a_i a_j alpha")
w1s, w2s = sp.symbols("w1 w2")  # stand for 1/u and 1/(1-u) inside the ring


# --dimension 2: hard disks (docs/methods/derivations/mixture-hcs.md, "Disks"): two Cartesian components (x, z), the
# sigma integral 2 pi times the integrand at sigma = z, S2 = L^(d/2-1)_2.
DIM = 2 if "--dimension" in sys.argv and sys.argv[sys.argv.index("--dimension") + 1] == "2" else 3
SPHERE = 4 if DIM == 3 else 2  # |S^(d-1)| / pi
F4 = 2 * (DIM + 2)             # <v^4>_i / (theta_i <v^2>_i) = 2 (d + 2) (1 + a_i): 10 spheres, 8 disks


def S2(x):  # L^(d/2-1)_2(x)
    return QQ(1, 2) * x**2 - QQ(DIM + 2, 2) * x + QQ(DIM * (DIM + 2), 8)


def dfact(n):  # (n)!! for odd n, (-1)!! = 1
    r = 1
    while n > 1:
        r *= n
        n -= 2
    return r


if DIM == 3:
    v1 = (Gx + U * gx, Gy + U * gy, Gz + U * gz)
    v2 = (Gx - (1 - U) * gx, Gy - (1 - U) * gy, Gz - (1 - U) * gz)
else:  # disks: the plane (x, z)
    v1 = (Gx + U * gx, Gz + U * gz)
    v2 = (Gx - (1 - U) * gx, Gz - (1 - U) * gz)
v1p = v1[:-1] + (v1[-1] - B * gz,)            # sig = z
sq = lambda v: sum(c**2 for c in v)
x1 = sq(v1) * W1 * QQ(1, 2)                    # v1^2 / (2 theta_i) in units of s^2: |v1-hat|^2 / (2u)
x2 = sq(v2) * W2 * QQ(1, 2)                    # v2^2 / (2 theta_j): |v2-hat|^2 / (2(1-u))
WEIGHT = (1 + AI * S2(x1)) * (1 + AJ * S2(x2))


def gauss_moment(poly):
    """sqrt(2 pi) E[Theta(g_z) g_z poly] for G-hat ~ N(0, u(1-u)), g-hat ~ N(0, 1), i.e. the sum over
    monomials of coeff x (G, g_x, g_y moments) x sqrt(2 pi) int_0^inf g_z^(e5+1) N(0,1) dg_z.  Since
    Psi_p = 4 pi s^(p+1) E[Theta(g_z) g_z W Delta_p] = 2 sqrt(2 pi) s^(p+1) P_p, P_p = gauss_moment(W Delta_p).
    Half-line moments: sqrt(2 pi) int_0^inf z^n N(0,1) dz = 2^m m! for n = 2m + 1.  Monomials with e5 odd
    (n even, which would bring a different constant) cannot survive: the integrand is even under
    (G, g) -> (-G, -g), so e5 odd needs an odd power of G_z or g_x or g_y, which averages to zero.  They are
    collected in GAUSS_ODD_RESIDUE and asserted absent."""
    out = R(0)
    for e, c in poly.terms():
        if any(k % 2 for k in e[:5]):
            continue
        val = R(c)
        for k in e[:3]:
            val *= dfact(k - 1) * (U * (1 - U)) ** (k // 2)
        for k in e[3:5]:
            val *= dfact(k - 1)
        n = e[5] + 1
        if n % 2 == 1:
            m = (n - 1) // 2
            val *= 2**m * factorial(m)
            out += R({(0,) * 6 + e[6:]: 1}) * val
        else:
            GAUSS_ODD_RESIDUE.append((e, c))
    return out


GAUSS_ODD_RESIDUE = []


def to_sympy(poly):
    """Ring element in (u, w1, w2, b, ai, aj) -> sympy rational expression in u, b, a_i, a_j."""
    expr = poly.as_expr()
    expr = expr.subs({sp.Symbol("w1"): 1 / u, sp.Symbol("w2"): 1 / (1 - u), sp.Symbol("u"): u, sp.Symbol("b"): b,
                      sp.Symbol("ai"): ai, sp.Symbol("aj"): aj})
    return sp.cancel(sp.together(expr))


def pair_moment(p):
    """P_p(u, b; a_i, a_j) with Psi_p = 2 sqrt(2 pi) s^(p+1) P_p."""
    h = p // 2
    delta = sq(v1p) ** h - sq(v1) ** h
    return to_sympy(gauss_moment(WEIGHT * delta))


def collision_q():
    """Q with int dv1 dv2 dsig Theta (sig.g)^3 f_i f_j / (n_i n_j) = 2 sqrt(2 pi) s^3 Q (energy-loss check)."""
    return to_sympy(gauss_moment(WEIGHT * gz**2))


def coeffs(P):
    """{(k, l): coefficient of a_i^k a_j^l} (factored)."""
    poly = sp.Poly(sp.expand(P), ai, aj)
    return {mon: sp.factor(cf) for mon, cf in poly.terms()}


# ---------------------------------------------------------------------------------------------------
# Numerical HCS solution (mirrors kernel/theory/mixture_hcs.cpp; used for the tables)
# ---------------------------------------------------------------------------------------------------
import math

import numpy as np


def make_numeric(P2, P4):
    f = {}
    for name, P in (("P2", P2), ("P4", P4)):
        c = coeffs(P)
        f[name] = {k: sp.lambdify((u, b), c.get(k, 0), "math") for k in [(0, 0), (1, 0), (0, 1), (1, 1)]}
    return f


def cs_chi(phi, x, sigma, i, j):
    """Carnahan-Starling chi_ij, 000 eq. 3, as kernel/collide/enskog_chi.cpp."""
    s2 = sum(xk * sk**2 for xk, sk in zip(x, sigma))
    s3 = sum(xk * sk**3 for xk, sk in zip(x, sigma))
    hat = phi * s2 / s3
    sij = 0.5 * (sigma[i] + sigma[j])
    a = hat * sigma[i] * sigma[j] / sij
    q = 1 - phi
    return 1 / q + 1.5 * a / q**2 + 0.5 * a * a / q**3


class Mixture:
    def __init__(self, mu, omega, delta, alpha_, phi=0.0):
        self.m = [mu, 1.0]
        self.sig = [omega, 1.0]
        self.n = [delta, 1.0]
        self.alpha = alpha_
        x = [delta / (1 + delta), 1 / (1 + delta)]
        self.chi = [[cs_chi(phi, x, self.sig, i, j) if phi > 0 else 1.0 for j in range(2)] for i in range(2)]


def pair_data(mix, i, j, T):
    th = [T[0] / mix.m[0], T[1] / mix.m[1]]
    s2 = th[i] + th[j]
    uu = th[i] / s2
    bb = mix.m[j] / (mix.m[i] + mix.m[j]) * (1 + mix.alpha)
    sij = 0.5 * (mix.sig[i] + mix.sig[j])
    w = mix.n[j] * sij ** (DIM - 1) * mix.chi[i][j]
    return uu, bb, math.sqrt(s2), w


def zeta_and_residual(NUM, mix, T, a, order="linear"):
    """Partial cooling rates zeta_i and fourth-moment residuals E_i (both divided by common constants):
         zeta_i = -(SPHERE sqrt(2 pi) / (2 d)) sum_j n_j sigma_ij^(d-1) chi_ij s_ij P2^ij / u_ij,
         E_i    = sum_j n_j sigma_ij^(d-1) chi_ij s_ij^5 [P4^ij - 2 (d + 2) u_ij (1 + a_i) P2^ij]
       (spheres: 2 sqrt(2 pi) / 3 and 10 u_ij).
    order = 'linear': zeta to first order in a, E_i linearised in a; 'exact': no linearisation."""
    z = [0.0, 0.0]
    E = [0.0, 0.0]
    for i in range(2):
        for j in range(2):
            uu, bb, s, w = pair_data(mix, i, j, T)
            p2 = {k: NUM["P2"][k](uu, bb) for k in NUM["P2"]}
            p4 = {k: NUM["P4"][k](uu, bb) for k in NUM["P4"]}
            ai_, aj_ = a[i], a[j]
            if order == "linear":
                P2v = p2[(0, 0)] + p2[(1, 0)] * ai_ + p2[(0, 1)] * aj_
                P4v = p4[(0, 0)] + p4[(1, 0)] * ai_ + p4[(0, 1)] * aj_
                ev = P4v - F4 * uu * (p2[(0, 0)] * (1 + ai_) + p2[(1, 0)] * ai_ + p2[(0, 1)] * aj_)
            else:
                P2v = p2[(0, 0)] + p2[(1, 0)] * ai_ + p2[(0, 1)] * aj_ + p2[(1, 1)] * ai_ * aj_
                P4v = p4[(0, 0)] + p4[(1, 0)] * ai_ + p4[(0, 1)] * aj_ + p4[(1, 1)] * ai_ * aj_
                ev = P4v - F4 * uu * (1 + ai_) * P2v
            z[i] += -(SPHERE * math.sqrt(2 * math.pi) / (2 * DIM)) * w * s * P2v / uu
            E[i] += w * s**5 * ev
    return z, E


def solve_a(NUM, mix, gamma, order="linear"):
    T = [gamma, 1.0]
    if order == "maxwell":
        return [0.0, 0.0]
    # the linear system (exact for 'linear'); Newton on top for 'exact'
    e0 = np.array(zeta_and_residual(NUM, mix, T, [0, 0], "linear")[1])
    M = np.zeros((2, 2))
    for k in range(2):
        a = [0.0, 0.0]
        a[k] = 1.0
        M[:, k] = np.array(zeta_and_residual(NUM, mix, T, a, "linear")[1]) - e0
    a = np.linalg.solve(M, -e0)
    if order == "exact":
        for _ in range(50):
            r = np.array(zeta_and_residual(NUM, mix, T, list(a), "exact")[1])
            J = np.zeros((2, 2))
            for k in range(2):
                d = np.zeros(2)
                d[k] = 1e-7
                J[:, k] = (np.array(zeta_and_residual(NUM, mix, T, list(a + d), "exact")[1]) - r) / 1e-7
            step = np.linalg.solve(J, -r)
            a = a + step
            if np.max(np.abs(step)) < 1e-14:
                break
    return list(a)


def gamma_root(NUM, mix, order="linear", x0=0.0):
    def f(x):
        g = math.exp(x)
        a = solve_a(NUM, mix, g, order)
        z, _ = zeta_and_residual(NUM, mix, [g, 1.0], a, "exact" if order == "exact" else "linear")
        return z[0] - z[1]
    # sign change nearest to x0 (as the C++ code: outward search, then bisection); x0 = 0 for the Maxwellian
    # ratio, log gamma_Maxwell for the linear Sonine one, log gamma_linear for the exact-bilinear variant
    f0 = f(x0)
    if f0 == 0.0:
        return math.exp(x0)
    lo = hi = x0
    flo = fhi = f0
    d = 0.01
    while True:
        nlo, nhi = x0 - d, x0 + d
        fnlo, fnhi = f(nlo), f(nhi)
        if (fnhi > 0) != (fhi > 0):
            a_, b_, fa = hi, nhi, fhi
            break
        if (fnlo > 0) != (flo > 0):
            a_, b_, fa = nlo, lo, fnlo
            break
        lo, hi, flo, fhi = nlo, nhi, fnlo, fnhi
        d *= 1.5
    for _ in range(200):
        mid = 0.5 * (a_ + b_)
        if mid in (a_, b_):
            break
        fm = f(mid)
        if (fm > 0) == (fa > 0):
            a_, fa = mid, fm
        else:
            b_ = mid
    return math.exp(0.5 * (a_ + b_))


def hcs(NUM, mix, order="linear"):
    gm = gamma_root(NUM, mix, "maxwell")
    if order == "maxwell":
        return gm, [0.0, 0.0]
    g = gamma_root(NUM, mix, "linear", math.log(gm))
    if order == "exact":
        g = gamma_root(NUM, mix, "exact", math.log(g))
    return g, solve_a(NUM, mix, g, order)


def vne(al):
    return 16 * (1 - al) * (1 - 2 * al**2) / (81 - 17 * al + 30 * al**2 * (1 - al))


def f5(x):
    """5-decimal string without a negative zero."""
    return f"{round(x, 5) + 0.0:.5f}"


def tables(NUM):
    hdr = "| alpha | gamma Maxwell | gamma Sonine | c_1 | c_2 | gamma exact-bilinear | c_1 exact-bilinear | c_2 exact-bilinear |"
    sep = "|---|---|---|---|---|---|---|---|"

    def row(mix, al):
        gm, _ = hcs(NUM, mix, "maxwell")
        gs, a = hcs(NUM, mix, "linear")
        ge, ae = hcs(NUM, mix, "exact")
        return (f"| {al:.2f} | {f5(gm)} | {f5(gs)} | {f5(2 * a[0])} | {f5(2 * a[1])} | {f5(ge)} | "
                f"{f5(2 * ae[0])} | {f5(2 * ae[1])} |")

    alphas = [0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95, 1.0]
    print("\n### Fig. 1: mu = 2, omega = 1, delta = 1, phi = 0 (one component: c = 2 a2_vNE)\n")
    print("| alpha | gamma Maxwell | gamma Sonine | c_1 | c_2 | c one-component | gamma exact-bilinear | c_1 exact-bilinear | c_2 exact-bilinear |")
    print("|---|---|---|---|---|---|---|---|---|")
    for al in alphas:
        mix = Mixture(2, 1, 1, al)
        r = row(mix, al).split("|")
        print("|" + "|".join(r[1:6]) + f"| {f5(2 * vne(al))} |" + "|".join(r[6:]))
    for mu in (0.1, 2, 10):
        print(f"\n### Fig. 3: omega = 1, delta = 2, phi = 0, mu = {mu}\n")
        print(hdr)
        print(sep)
        for al in alphas:
            print(row(Mixture(mu, 1, 2, al), al))
    for de in (0.25, 1, 4):
        print(f"\n### Fig. 4: mu = 4, omega = 1, phi = 0, delta = {de}\n")
        print(hdr)
        print(sep)
        for al in alphas:
            print(row(Mixture(4, 1, de, al), al))
    for al in (0.6, 0.8):
        print(f"\n### Fig. 5: mu = omega = 2, delta = 1/2, alpha = {al} (chi_ij Carnahan-Starling)\n")
        print("| phi | chi_11 | chi_12 | chi_22 | gamma Maxwell | gamma Sonine | gamma(phi)/gamma(0) Maxwell | "
              "gamma(phi)/gamma(0) Sonine | c_1 | c_2 |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        g0m, _ = hcs(NUM, Mixture(2, 2, 0.5, al), "maxwell")
        g0s, _ = hcs(NUM, Mixture(2, 2, 0.5, al), "linear")
        for phi in (0.0, 0.1, 0.2, 0.3, 0.4, 0.5):
            mix = Mixture(2, 2, 0.5, al, phi)
            gm, _ = hcs(NUM, mix, "maxwell")
            gs, a = hcs(NUM, mix, "linear")
            c = mix.chi
            print(f"| {phi:.1f} | {f5(c[0][0])} | {f5(c[0][1])} | {f5(c[1][1])} | {f5(gm)} | {f5(gs)} | "
                  f"{f5(gm / g0m)} | {f5(gs / g0s)} | {f5(2 * a[0])} | {f5(2 * a[1])} |")


def tables_disks(NUM):
    """The dilute curves of `make fig-mixture-disks` (000 Fig. 3 in the plane): Maxwellian and first-Sonine gamma."""
    alphas = [0.5, 0.6, 0.7, 0.8, 0.9, 0.95]
    print("\n### Disks, delta = 2, phi = 0\n")
    print("| curve | alpha | gamma Maxwell | gamma Sonine | c_1 | c_2 |")
    print("|---|---|---|---|---|---|")
    for name, mu, omega in (("mu = 1/10", 0.1, 1), ("mu = 2", 2, 1), ("mu = 10", 10, 1), ("mu = 10, omega = 2", 10, 2)):
        for al in alphas:
            mix = Mixture(mu, omega, 2, al)
            gm, _ = hcs(NUM, mix, "maxwell")
            gs, a = hcs(NUM, mix, "linear")
            print(f"| {name} | {al} | {f5(gm)} | {f5(gs)} | {f5(2 * a[0])} | {f5(2 * a[1])} |")


# ---------------------------------------------------------------------------------------------------
# Independent numerical checks of the collisional moments (no G, g decomposition, no symbolic algebra)
# ---------------------------------------------------------------------------------------------------
CHECK_POINTS = [  # (m_i, m_j, T_i, T_j, alpha)
    (2.0, 1.0, 1.3, 1.0, 0.7),
    (1.0, 10.0, 0.2, 1.0, 0.5),
    (5.0, 0.5, 3.0, 0.4, 0.0),
    (1.0, 1.0, 1.0, 1.0, 0.8),
]
KEYS = [(0, 0), (1, 0), (0, 1), (1, 1)]


def exact_psi(NUM, mi, mj, Ti, Tj, al):
    """Psi_p^ij coefficients {(p, key): value} from the closed forms."""
    thi, thj = Ti / mi, Tj / mj
    s2 = thi + thj
    uu, bb = thi / s2, mj / (mi + mj) * (1 + al)
    out = {}
    for p, name in ((2, "P2"), (4, "P4")):
        for k in KEYS:
            out[(p, k)] = SPHERE / 2 * math.sqrt(2 * math.pi) * s2 ** ((p + 1) / 2) * NUM[name][k](uu, bb)
    return out


def s2n(x):
    return 0.5 * x * x - (DIM + 2) / 2 * x + DIM * (DIM + 2) / 8


def quadrature_psi(mi, mj, Ti, Tj, al, n_lag=12, n_ang=64, n_rad=160, rmax=16.0):
    """Deterministic quadrature in the ORIGINAL velocities with sig = z:
    transverse parts v_perp^2 = 2 theta t, t ~ Exp(1) (Gauss-Laguerre, exact for polynomials);
    (v1z, v2z) = (sqrt(theta_i) r cos t, sqrt(theta_j) r sin t) with the half-plane v1z > v2z as an angular
    interval (Gauss-Legendre), r by Gauss-Legendre on [0, rmax]."""
    thi, thj = Ti / mi, Tj / mj
    bb = mj / (mi + mj) * (1 + al)
    tl, wl = np.polynomial.laguerre.laggauss(n_lag)
    xa, wa = np.polynomial.legendre.leggauss(n_ang)
    xr, wr = np.polynomial.legendre.leggauss(n_rad)
    beta = math.atan2(math.sqrt(thj), math.sqrt(thi))
    lo, hi = -math.pi / 2 - beta, math.pi / 2 - beta
    ang = 0.5 * (hi - lo) * xa + 0.5 * (hi + lo)
    wang = 0.5 * (hi - lo) * wa
    r = 0.5 * rmax * (xr + 1)
    wrr = 0.5 * rmax * wr
    T1, T2, A, RR = np.meshgrid(tl, tl, ang, r, indexing="ij")
    Wt = np.einsum("a,b,c,d->abcd", wl, wl, wang, wrr)
    v1z = math.sqrt(thi) * RR * np.cos(A)
    v2z = math.sqrt(thj) * RR * np.sin(A)
    gzv = v1z - v2z
    p1 = 2 * thi * T1
    p2 = 2 * thj * T2
    x1 = (p1 + v1z**2) / (2 * thi)
    x2 = (p2 + v2z**2) / (2 * thj)
    y1 = p1 + (v1z - bb * gzv) ** 2
    base = Wt * RR * np.exp(-RR**2 / 2) / (2 * math.pi) * 4 * math.pi * gzv
    w = {(0, 0): 1.0, (1, 0): s2n(x1), (0, 1): s2n(x2), (1, 1): s2n(x1) * s2n(x2)}
    out = {}
    for p in (2, 4):
        h = p // 2
        d = y1**h - (p1 + v1z**2) ** h
        for k in KEYS:
            out[(p, k)] = float(np.sum(base * w[k] * d))
    return out


def mc_psi(mi, mj, Ti, Tj, al, nsamp=20_000_000, batch=2_000_000, seed=7):
    """Plain Monte Carlo: v1 ~ N(0, T_i/m_i), v2 ~ N(0, T_j/m_j), sig uniform on the sphere (circle for disks)."""
    rng = np.random.default_rng(seed)
    thi, thj = Ti / mi, Tj / mj
    bb = mj / (mi + mj) * (1 + al)
    acc = {(p, k): [0.0, 0.0] for p in (2, 4) for k in KEYS}
    n = 0
    while n < nsamp:
        c1 = rng.normal(scale=math.sqrt(thi), size=(batch, DIM))
        c2 = rng.normal(scale=math.sqrt(thj), size=(batch, DIM))
        s = rng.normal(size=(batch, DIM))
        s /= np.linalg.norm(s, axis=1)[:, None]
        sg = np.einsum("ij,ij->i", s, c1 - c2)
        th = np.where(sg > 0, sg, 0.0)
        c1p = c1 - bb * sg[:, None] * s
        x1 = (c1**2).sum(1)
        y1 = (c1p**2).sum(1)
        w = {(0, 0): 1.0, (1, 0): s2n(x1 / (2 * thi)), (0, 1): s2n((c2**2).sum(1) / (2 * thj))}
        w[(1, 1)] = w[(1, 0)] * w[(0, 1)]
        for p in (2, 4):
            h = p // 2
            d = y1**h - x1**h
            for k in KEYS:
                v = SPHERE * math.pi * th * w[k] * d
                acc[(p, k)][0] += float(v.sum())
                acc[(p, k)][1] += float((v * v).sum())
        n += batch
    out = {}
    for key, (s1, s2) in acc.items():
        m = s1 / n
        out[key] = (m, math.sqrt(max(s2 / n - m * m, 0.0) / n))
    return out


# ---------------------------------------------------------------------------------------------------
def derive():
    t0 = time.time()
    P2, P4, Q = pair_moment(2), pair_moment(4), collision_q()
    assert not GAUSS_ODD_RESIDUE, "monomials with odd g_z power survived"
    print(f"(moments: {time.time() - t0:.1f} s)")
    for name, P in (("P2", P2), ("P4", P4), ("Q", Q)):
        print(f"\n{name}(u, b; a_i, a_j):")
        for mon, cf in sorted(coeffs(P).items()):
            print(f"  a_i^{mon[0]} a_j^{mon[1]}:  {cf}")
    return P2, P4, Q


def checks(P2, P4, Q):
    print("\n---- exact checks")
    if DIM == 3:
        checks_spheres(P2)
    checks_any_dimension(P2, P4, Q)


def checks_spheres(P2):
    # (1) Sonine normalisation of species i
    th, v, a = sp.symbols("theta v a", positive=True)
    x = v**2 / (2 * th)
    f = (2 * sp.pi * th) ** sp.Rational(-3, 2) * sp.exp(-x) * (1 + a * (x**2 / 2 - sp.Rational(5, 2) * x + sp.Rational(15, 8)))
    mom = lambda k: sp.simplify(sp.integrate(4 * sp.pi * v**2 * v**k * f, (v, 0, sp.oo)))
    print("<1> =", mom(0), "  <v^2> =", mom(2), "  <v^4> =", sp.factor(mom(4)))

    # (2) Maxwellian zeta_i reproduces the closed form of the brief (per partner j)
    mi, mj, Ti, Tj, al = sp.symbols("m_i m_j T_i T_j alpha", positive=True)
    thi, thj = Ti / mi, Tj / mj
    s2 = thi + thj
    M = mi + mj
    sub = {u: thi / s2, b: mj / M * (1 + al)}
    # zeta_i^(j) / (n_j sigma_ij^2 chi_ij) = -(2 sqrt(2 pi)/3) s P2 / u
    z_ours = -(2 * sp.sqrt(2 * sp.pi) / 3) * sp.sqrt(s2) * P2.subs({ai: 0, aj: 0}).subs(sub) / sub[u]
    z_brief = (8 * sp.sqrt(2 * sp.pi) / 3) * (mi * mj / M) * (1 + al) * s2 ** sp.Rational(3, 2) / Ti * (
        (Ti - Tj) / (M * s2) + mj / M * (1 - al) / 2)
    print("Maxwell zeta_i == brief's formula:", sp.simplify(z_ours - z_brief) == 0)
    m_, T_, n_ = sp.symbols("m T n", positive=True)
    one = sp.simplify(z_brief.subs({mi: m_, mj: m_, Ti: T_, Tj: T_}))
    print("  one species: zeta / (n sigma^2 chi) =", one,
          "  == (4 sqrt(pi)/3)(1-alpha^2) sqrt(T/m):",
          sp.simplify(one - 4 * sp.sqrt(sp.pi) / 3 * (1 - al**2) * sp.sqrt(T_ / m_)) == 0)


def checks_any_dimension(P2, P4, Q):
    mi, mj, al = sp.symbols("m_i m_j alpha", positive=True)
    M = mi + mj
    # (3) elastic, equal temperatures: Maxwellians are collision invariants for every p
    eq = {u: mj / M, b: 2 * mj / M}
    print("alpha = 1, T_i = T_j: P2 = P4 = 0:",
          sp.simplify(P2.subs({ai: 0, aj: 0}).subs(eq)) == 0, sp.simplify(P4.subs({ai: 0, aj: 0}).subs(eq)) == 0)

    # (4) pair energy balance for any (u, b, alpha, a_i, a_j):
    #     m_i Psi_2^ij + m_j Psi_2^ji = -(1 - alpha^2) m_ij int Theta (sig.g)^3 f_i f_j,
    #     Psi_2^ji = P2(1 - u, b'; a_j, a_i),  b' = mu_ij (1 + alpha) = (1 + alpha) - b,  m_j/m_i = b/b'.
    bp = (1 + alpha) - b
    P2ji = P2.subs({u: 1 - u, b: bp, ai: aj, aj: ai}, simultaneous=True)
    Qji = Q.subs({u: 1 - u, ai: aj, aj: ai}, simultaneous=True)
    lhs = P2 + (b / bp) * P2ji
    rhs = -(1 - alpha) * b * Q      # (1 - alpha^2) mu_ji = (1 - alpha) b
    print("pair energy balance (exact in a_i, a_j, alpha):", sp.simplify(lhs - rhs) == 0,
          "   Q symmetric under i <-> j:", sp.simplify(Q - Qji) == 0)

    # (5) one component: u = 1/2, b = (1 + alpha)/2, a_i = a_j = a  ->  mu_p of sonine_hcs.py (a3 = 0, run in
    #     the same dimension): mu_p / sqrt(2 pi) = -(SPHERE / 2) P_p   (Psi_p = (SPHERE / 2) sqrt(2 pi) s^(p+1) P_p,
    #     s = v0 = 1 in the units of mu_p)
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import sonine_hcs as one_comp
    a2s, a3s = one_comp.a2, one_comp.a3
    for p, P in ((2, P2), (4, P4)):
        mu_p = one_comp.to_sympy(one_comp.collision_moment(p)).subs(a3s, 0)
        mine = -sp.Rational(SPHERE, 2) * P.subs({u: sp.Rational(1, 2), b: (1 + one_comp.alpha) / 2, ai: a2s, aj: a2s})
        print(f"one component: -{SPHERE // 2} P{p} == mu_{p} of sonine_hcs.py (incl. a2^2):", sp.expand(mine - mu_p) == 0)

    # (6) identical species, any densities: the linearised HCS system gives a_1 = a_2 = van Noije-Ernst
    n1, n2, a1, a2 = sp.symbols("n1 n2 a1 a2", positive=True)
    half = {u: sp.Rational(1, 2), b: (1 + alpha) / 2}
    c2 = {k: v.subs(half) for k, v in coeffs(P2).items()}
    c4 = {k: v.subs(half) for k, v in coeffs(P4).items()}
    def Elin(own, other):  # pair contribution, linearised
        return (c4[(0, 0)] + c4[(1, 0)] * own + c4[(0, 1)] * other
                - (DIM + 2) * (c2[(0, 0)] * (1 + own) + c2[(1, 0)] * own + c2[(0, 1)] * other))
    E1 = n1 * Elin(a1, a1) + n2 * Elin(a1, a2)
    E2 = n2 * Elin(a2, a2) + n1 * Elin(a2, a1)
    sol = sp.solve([E1, E2], [a1, a2], dict=True)[0]
    vne_ = 16 * (1 - alpha) * (1 - 2 * alpha**2) / (9 + 24 * DIM - alpha * (41 - 8 * DIM) + 30 * alpha**2 * (1 - alpha))
    print("identical species, any n1, n2: a1 = a2 = vNE:",
          sp.simplify(sol[a1] - vne_) == 0, sp.simplify(sol[a2] - vne_) == 0)

    # (7) linearised fourth-moment coefficients Q^ij (printed for the note / C++)
    print(f"\nLinearised E_i pair term  P4 - {F4} u (1 + a_i) P2  ->  e0 + ei a_i + ej a_j:")
    cc2, cc4 = coeffs(P2), coeffs(P4)
    e0 = sp.factor(cc4[(0, 0)] - F4 * u * cc2[(0, 0)])
    ei = sp.factor(cc4[(1, 0)] - F4 * u * (cc2[(1, 0)] + cc2[(0, 0)]))
    ej = sp.factor(cc4[(0, 1)] - F4 * u * cc2[(0, 1)])
    print("  e0 =", e0)
    print("  ei =", ei)
    print("  ej =", ej)
    print("\nExpanded coefficients (for the C++ code):")
    for name, cc in (("P2", cc2), ("P4", cc4)):
        for k in KEYS:
            print(f"  {name}{k}: {sp.expand(cc.get(k, 0))}")


def main():
    P2, P4, Q = derive()
    if "--quad" in sys.argv and DIM == 2:
        raise SystemExit("--quad integrates over the sphere only; use --mc for disks")
    if "--quad" in sys.argv or "--mc" in sys.argv:
        NUM = make_numeric(P2, P4)
        worst = 0.0
        for idx, pt in enumerate(CHECK_POINTS):
            ex = exact_psi(NUM, *pt)
            if "--quad" in sys.argv:
                q = quadrature_psi(*pt)
                for key in sorted(ex):
                    rel = abs(q[key] - ex[key]) / max(1.0, abs(ex[key]))
                    worst = max(worst, rel)
                    print(f"{pt} Psi_{key[0]} a_i^{key[1][0]} a_j^{key[1][1]}: exact {ex[key]: .14e}"
                          f"  quadrature {q[key]: .14e}")
            else:
                mc = mc_psi(*pt, seed=7 + idx)
                for key in sorted(ex):
                    m, e = mc[key]
                    z = (m - ex[key]) / e
                    worst = max(worst, abs(z))
                    print(f"{pt} Psi_{key[0]} a_i^{key[1][0]} a_j^{key[1][1]}: exact {ex[key]: .6f}"
                          f"  MC {m: .6f} +- {e:.6f}  z = {z: .2f}")
        print("largest", "|quadrature - exact| / max(1, |exact|)" if "--quad" in sys.argv else "|z|", "=",
              f"{worst:.2e}")
        return
    checks(P2, P4, Q)
    NUM = make_numeric(P2, P4)
    # numbers for the C++ tests
    print("\n---- reference values")
    for args in ((2, 1, 1, 0.5), (2, 1, 1, 0.8), (10, 1, 2, 0.5), (0.1, 1, 2, 0.7), (4, 1, 0.25, 0.6),
                 (1000, 1, 1, 0.0), (0.001, 1, 1, 0.0)):
        mix = Mixture(*args)
        gm, _ = hcs(NUM, mix, "maxwell")
        gs, a = hcs(NUM, mix, "linear")
        print(f"mu, omega, delta, alpha = {args}: gamma_M = {gm:.15g}, gamma_S = {gs:.15g},"
              f" a2 = ({a[0]:.15g}, {a[1]:.15g})")
    # exact collisional moments for tests/test_mixture_hcs.cpp (CollisionalMomentsFromExactDerivation)
    masses, temps, al_, avals = [2, 1], [sp.Rational(13, 10), 1], sp.Rational(7, 10), [sp.Rational(3, 10), sp.Rational(-1, 5)]
    for i, j in ((0, 1), (1, 0), (0, 0)):
        thi, thj = sp.Rational(temps[i]) / masses[i], sp.Rational(temps[j]) / masses[j]
        sub = {u: thi / (thi + thj), b: sp.Rational(masses[j], masses[i] + masses[j]) * (1 + al_), ai: avals[i], aj: avals[j]}
        for p, P in ((2, P2), (4, P4)):
            val = sp.Rational(SPHERE, 2) * sp.sqrt(2 * sp.pi) * (thi + thj) ** sp.Rational(p + 1, 2) * P.subs(sub)
            print(f"Psi_{p}^({i}{j}) at m = (2, 1), T = (1.3, 1), alpha = 0.7, a2 = (0.3, -0.2): {sp.N(val, 17)}")
    if DIM == 3:
        tables(NUM)
    else:
        tables_disks(NUM)


if __name__ == "__main__":
    main()
