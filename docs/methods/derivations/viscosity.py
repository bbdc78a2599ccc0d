#!/usr/bin/env python3
"""First-Sonine Navier-Stokes shear viscosity of inelastic hard spheres (d = 3, Enskog equation, uniform chi):
every collision integral that enters 003's eta^k and eta, evaluated exactly and compared with 003's closed
forms; then the same for a binary mixture with unequal partial temperatures (000 Figs. 7-12), with its limits.
Derivation: docs/methods/derivations/viscosity.md.  Code: kernel/theory/viscosity.*, kernel/theory/mixture_viscosity.*.

Run with /usr/bin/python3 (needs sympy, numpy; imports mixture_hcs.py from this directory).
    python3 viscosity.py            symbolic derivation, comparison with 003, mixture checks (about 25 s)
    python3 viscosity.py --tables   the same and the tables of the note (about 25 s)
    python3 viscosity.py --quad     independent quadrature in the original velocities (about 90 s)

One species.  Units m = T = 1 (theta = T/m = 1), one-particle densities normalised to one.  Reference
distribution (HCS, first Sonine): f0(V) = fM(V) W0(V), W0 = 1 + a2 S2(V^2/2), fM = (2 pi)^(-3/2) exp(-V^2/2).
Navier-Stokes shear part (003): f1(V) = c fM(V) D(V):E, D(V) = V V - V^2 I/3, E the traceless symmetric
shear rate (the antisymmetric part of grad u drops out of every symmetric traceless moment by isotropy).

Pair coordinates for equal masses and temperatures: G = (V1 + V2)/2 ~ N(0, 1/2), g = V1 - V2 ~ N(0, 2) per
component, independent, unit Jacobian.  Every integrand below, after contraction of the free tensor indices
with the traceless-symmetric projector, is a rotation scalar in (G, g, sig), so int dsig = 4 pi x (value at
sig = z); with the factor Theta(g_z) the g_z integral runs over the half line.  An isotropic rank-4 map
X_ab = T_abkl E_kl between traceless symmetric tensors is X = lambda E with lambda = T_abkl Delta_abkl / 5
(Delta the traceless-symmetric projector, trace 5), which is how each tensor integral becomes one number.
"""
import math
import os
import sys
from math import factorial

import sympy as sp
from sympy.polys.domains import QQ
from sympy.polys.rings import ring

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mixture_hcs as mh  # noqa: E402  (pair coordinates of the mixture, docs/methods/derivations/mixture-hcs.md)

R, Gx, Gy, Gz, gx, gy, gz, AL, A2 = ring("Gx,Gy,Gz,gx,gy,gz,alpha,a2", QQ)
alpha, a2 = sp.symbols("alpha a2")
sqrt_pi = sp.sqrt(sp.pi)


def dfact(n):  # n!! for odd n, (-1)!! = 1
    r = 1
    while n > 1:
        r *= n
        n -= 2
    return r


def S2(x):
    return QQ(1, 2) * x**2 - QQ(5, 2) * x + QQ(15, 8)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


G = (Gx, Gy, Gz)
g = (gx, gy, gz)
V1 = tuple(Gi + gi * QQ(1, 2) for Gi, gi in zip(G, g))
V2 = tuple(Gi - gi * QQ(1, 2) for Gi, gi in zip(G, g))
b = (1 + AL) * QQ(1, 2)                       # V1' = V1 - (1+alpha)/2 (sig.g) sig, sig = z  (000 eq. 14)
V1p = (V1[0], V1[1], V1[2] - b * gz)


def W0(V):
    return 1 + A2 * S2(dot(V, V) * QQ(1, 2))


def grad_f0(V):
    """d f0 / dV_l = fM(V) w_l(V):  w_l = V_l [-(1 + a2 S2(x)) + a2 S2'(x)],  x = V^2/2."""
    x = dot(V, V) * QQ(1, 2)
    s = -(1 + A2 * S2(x)) + A2 * (x - QQ(5, 2))
    return tuple(Vl * s for Vl in V)


def DD(V, W):
    """D(V):D(W) = (V.W)^2 - V^2 W^2 / 3."""
    return dot(V, W) ** 2 - dot(V, V) * dot(W, W) * QQ(1, 3)


def zDw(V, w):
    """z . D(V) . w = V_z (V.w) - V^2 w_z / 3  (= TS(z w) : D(V))."""
    return V[2] * dot(V, w) - dot(V, V) * w[2] * QQ(1, 3)


def expect(poly):
    """E[Theta(g_z) poly] for G ~ N(0, 1/2), g ~ N(0, 2): returns (rational part, coefficient of 1/sqrt(pi)) as
    sympy expressions in alpha, a2.  Half-line moments of g_z ~ N(0, 2): r = 2m+1 -> 4^m m!/sqrt(pi),
    r = 2m -> 2^m (2m-1)!!/2."""
    rat, irr = {}, {}
    for e, c in poly.terms():
        if any(k % 2 for k in e[:5]):
            continue
        val = QQ(c)
        for k in e[:3]:
            val *= dfact(k - 1) * QQ(1, 2) ** (k // 2)
        for k in e[3:5]:
            val *= dfact(k - 1) * 2 ** (k // 2)
        r = e[5]
        key = e[6:]
        if r % 2:
            m = (r - 1) // 2
            irr[key] = irr.get(key, 0) + val * 4**m * factorial(m)
        else:
            m = r // 2
            rat[key] = rat.get(key, 0) + val * QQ(2**m * dfact(2 * m - 1), 2)
    to = lambda d: sp.expand(sum(sp.Rational(int(v.numerator), int(v.denominator)) * alpha**k[0] * a2**k[1]
                                 for k, v in d.items()))
    return to(rat), to(irr)


def integral(poly):
    """int dV1 dV2 dsig Theta(sig.g) (...) fM fM = 4 pi E[Theta(g_z) poly] (sig = z)."""
    rat, irr = expect(poly)
    return sp.expand(4 * sp.pi * (rat + irr / sqrt_pi))


def linear(expr):
    """Drop a2^2 and higher (the first-Sonine linearisation)."""
    p = sp.Poly(sp.expand(expr), a2)
    return sp.expand(sum(cf * a2**k[0] for k, cf in p.terms() if k[0] <= 1))


def report(name, got, want):
    diff = sp.simplify(got - want)
    print(f"{name}:\n    derived  {sp.factor(got)}\n    003/lit. {sp.factor(want)}\n    difference {diff}")
    return diff == 0


def main():
    ok = True
    c0 = 2 * a2                                          # 003: c0 = 2 a2 (c = 6<V^4>/5<V^2>^2 - 2)
    # eta0 = (5/16) sqrt(1/pi) (sigma = 1), nu0 = n T / eta0 = 16 sqrt(pi)/5 (n = sigma = 1): reduced rates.
    nu0 = 16 * sqrt_pi / 5

    # (1) Cooling rate zeta = -(1/3) n sigma^2 chi int (V1'^2 - V1^2) Theta (sig.g) f0 f0.
    zeta = -sp.Rational(1, 3) * integral(gz * W0(V1) * W0(V2) * (dot(V1p, V1p) - dot(V1, V1)))
    zeta_star = linear(zeta / nu0)
    ok &= report("zeta* (first Sonine, linear in a2)", zeta_star,
                 sp.Rational(5, 12) * (1 - alpha**2) * (1 + sp.Rational(3, 32) * c0))

    # (2) nu_eta: int D(V1) [J[f0, f1] + J[f1, f0]] = -nu_eta P1, P1 = 2 c E.
    d1 = lambda W: DD(V1p, W) - DD(V1, W)
    lam_a = integral(gz * W0(V1) * d1(V2)) / 5          # f0 at V1, f1 at V2
    lam_b = integral(gz * W0(V2) * d1(V1)) / 5          # f1 at V1, f0 at V2
    nu_eta_star = sp.expand(-(lam_a + lam_b) / 2 / nu0)  # exactly linear in a2 (f1 carries no a2)
    ok &= report("nu_eta*", nu_eta_star,
                 (1 - (1 - alpha)**2 / 4) * (1 - c0 / 64))

    # 003's denominator: (1/384)(1+alpha)[16(13 - alpha) - 3(4 - 3 alpha) c0] = nu_eta* - zeta*/2 (chi = 1)
    ok &= report("nu_eta* - zeta*/2 vs 003 denominator", linear(nu_eta_star - zeta_star / 2),
                 (1 + alpha) * (16 * (13 - alpha) - 3 * (4 - 3 * alpha) * c0) / 384)
    # Gaussian thermostat (000's HSS): nu_eta* - zeta*.
    print("nu_eta* - zeta* (Gaussian thermostat, HSS):", sp.factor(linear(nu_eta_star - zeta_star)))
    ok &= report("nu_eta* - zeta* vs (1+alpha)/384 [64(2+alpha) - (3/2)(13 - 11 alpha) c0]",
                 linear(nu_eta_star - zeta_star),
                 (1 + alpha) * (64 * (2 + alpha) - sp.Rational(3, 2) * (13 - 11 * alpha) * c0) / 384)

    # (3) First-order (gradient) part of the Enskog collision moment, Y = int D(V1) J^(1)[f0, f0]:
    #     Y_ab = -n^2 sigma^3 chi int Theta (sig.g) f0(V1) sig_k E_kl d_l f0(V2) [D_ab(V1') - D_ab(V1)],
    #     Y = -2 n T y E  =>  y = -(n sigma^3 chi / 2) lambda_J = -(3/pi) phi chi lambda_J.
    w2 = grad_f0(V2)
    lam_J = -integral(gz * W0(V1) * (zDw(V1p, w2) - zDw(V1, w2))) / 5
    y = sp.expand(-3 / sp.pi * lam_J)                   # per phi chi
    print("y / (phi chi), exact in a2:", sp.factor(y))
    ok &= report("y / (phi chi) (kinetic numerator 1 + y)", linear(y),
                 -sp.Rational(2, 5) * (1 + alpha) * (1 - 3 * alpha))

    # (4) Collisional transfer of f0 f1 (000 eq. 18 / Enskog flux, first order through f1):
    #     P^c_ab = ((1+alpha)/4) sigma^3 chi int Theta (sig.g)^2 sig_a sig_b [f0(1) f1(2) + f1(1) f0(2)],
    #     eta^c1 = eta^k (1+alpha) n sigma^3 chi (lam_t1 + lam_t2) / 8 = eta^k (1+alpha) phi chi (3/(4 pi))(lam_t1+lam_t2).
    Dzz = lambda V: V[2] ** 2 - dot(V, V) * QQ(1, 3)
    lam_t = (integral(gz**2 * W0(V1) * Dzz(V2)) + integral(gz**2 * W0(V2) * Dzz(V1))) / 5
    t = sp.expand(3 / (4 * sp.pi) * lam_t)            # eta^c1 = eta^k (1+alpha) phi chi t
    print("collisional transfer of f1, per eta^k (1+alpha) phi chi, exact in a2:", sp.factor(t))
    ok &= report("  at a2 = 0", t.subs(a2, 0), sp.Rational(4, 5))

    # (5) Collisional transfer of f0 f0 across the gradient of u:
    #     P^c = ((1+alpha)/4) sigma^4 chi n^2 (1/2) [lam_c1 - lam_c2] E,
    #     lam_c1 = (1/5) int Theta (sig.g)^2 (2/3) w_z(V1) W0(V2), lam_c2 = same with 1 <-> 2.
    #     eta^c0 = -((1+alpha)/16) n^2 sigma^4 chi (lam_c1 - lam_c2); in units of eta0 phi^2 chi (1+alpha):
    #     n^2 sigma^4 = 36 phi^2 / pi^2, eta0 = 5/(16 sqrt(pi)).
    w1 = grad_f0(V1)
    lam_c1 = integral(gz**2 * QQ(2, 3) * w1[2] * W0(V2)) / 5
    lam_c2 = integral(gz**2 * QQ(2, 3) * w2[2] * W0(V1)) / 5
    eta_c0 = sp.expand(-(lam_c1 - lam_c2) / 16 * 36 / sp.pi**2 / (5 / (16 * sqrt_pi)))
    print("eta^c0 / (eta0 phi^2 chi (1+alpha)), exact in a2:", sp.factor(eta_c0))
    ok &= report("eta^c0 / (eta0 phi^2 chi (1+alpha)) linear in a2", linear(eta_c0),
                 sp.Rational(384, 25) / sp.pi * (1 - c0 / 32))

    print("ALL CHECKS PASSED" if ok else "SOME CHECKS FAILED")
    return ok


def quadrature_check(al=0.6, a=0.3):
    """Independent deterministic quadrature of every integral above at one point (alpha, a2), in the ORIGINAL
    velocities V1, V2 (no polynomial expansion, no pair moments): sig = z (isotropy), the x and y components of
    V1, V2 by 4D Gauss-Hermite (polynomial integrand: exact), the z components through (G_z, g_z) with g_z > 0
    (Gauss-Hermite in G_z, Gauss-Legendre on 0 < g_z < 20).  Compared with the exact symbolic values (full
    dependence on a2, not linearised)."""
    import numpy as np
    from numpy.polynomial.hermite_e import hermegauss
    from numpy.polynomial.legendre import leggauss
    xh, wh = hermegauss(10)                     # weight exp(-x^2/2)
    wh = wh / np.sqrt(2 * np.pi)                # -> expectation over N(0, 1)
    xl, wl = leggauss(60)
    gzs, wgz = 10 * (xl + 1), 10 * wl
    Gz = xh / np.sqrt(2)                        # G_z ~ N(0, 1/2)
    # grids
    X1, X2, Y1, Y2, GZ, GGZ = np.meshgrid(xh, xh, xh, xh, Gz, gzs, indexing="ij")
    W = (wh[:, None, None, None, None, None] * wh[None, :, None, None, None, None] * wh[None, None, :, None, None, None]
         * wh[None, None, None, :, None, None] * wh[None, None, None, None, :, None]
         * (wgz * np.exp(-gzs**2 / 4) / np.sqrt(4 * np.pi))[None, None, None, None, None, :])
    N1 = np.stack([X1, Y1, GZ + GGZ / 2], -1).reshape(-1, 3)
    N2 = np.stack([X2, Y2, GZ - GGZ / 2], -1).reshape(-1, 3)
    W = W.reshape(-1)
    gzv = N1[:, 2] - N2[:, 2]
    N1p = N1.copy()
    N1p[:, 2] -= (1 + al) / 2 * gzv
    sq = lambda V: np.einsum("ij,ij->i", V, V)
    S2n = lambda x: x * x / 2 - 2.5 * x + 15 / 8
    W0n = lambda V: 1 + a * S2n(sq(V) / 2)
    wn = lambda V: V * (-(1 + a * S2n(sq(V) / 2)) + a * (sq(V) / 2 - 2.5))[:, None]
    DDn = lambda V, U: np.einsum("ij,ij->i", V, U) ** 2 - sq(V) * sq(U) / 3
    zDwn = lambda V, w: V[:, 2] * np.einsum("ij,ij->i", V, w) - sq(V) * w[:, 2] / 3
    Dzzn = lambda V: V[:, 2] ** 2 - sq(V) / 3
    I = lambda f: 4 * np.pi * np.sum(W * f)
    num = {
        "zeta": I(gzv * W0n(N1) * W0n(N2) * (sq(N1p) - sq(N1))),
        "lam_a": I(gzv * W0n(N1) * (DDn(N1p, N2) - DDn(N1, N2))),
        "lam_b": I(gzv * W0n(N2) * (DDn(N1p, N1) - DDn(N1, N1))),
        "lam_J": I(gzv * W0n(N1) * (zDwn(N1p, wn(N2)) - zDwn(N1, wn(N2)))),
        "lam_t": I(gzv**2 * (W0n(N1) * Dzzn(N2) + W0n(N2) * Dzzn(N1))),
        "lam_c": I(gzv**2 * (2 / 3) * (wn(N1)[:, 2] * W0n(N2) - wn(N2)[:, 2] * W0n(N1))),
    }
    w1, w2 = grad_f0(V1), grad_f0(V2)
    sym = {
        "zeta": integral(gz * W0(V1) * W0(V2) * (dot(V1p, V1p) - dot(V1, V1))),
        "lam_a": integral(gz * W0(V1) * (DD(V1p, V2) - DD(V1, V2))),
        "lam_b": integral(gz * W0(V2) * (DD(V1p, V1) - DD(V1, V1))),
        "lam_J": integral(gz * W0(V1) * (zDw(V1p, w2) - zDw(V1, w2))),
        "lam_t": integral(gz**2 * (W0(V1) * (V2[2]**2 - dot(V2, V2) * QQ(1, 3))
                                   + W0(V2) * (V1[2]**2 - dot(V1, V1) * QQ(1, 3)))),
        "lam_c": integral(gz**2 * QQ(2, 3) * (w1[2] * W0(V2) - w2[2] * W0(V1))),
    }
    ok = True
    for k in num:
        exact = float(sym[k].subs({alpha: sp.Rational(al).limit_denominator(1000), a2: sp.Rational(a).limit_denominator(1000)}))
        rel = abs(num[k] - exact) / max(abs(exact), 1e-300)
        ok &= rel < 1e-10 or abs(num[k] - exact) < 1e-12
        print(f"{k:6s} quadrature {num[k]: .12e}   symbolic {exact: .12e}   rel. diff {rel:.1e}")
    print("QUADRATURE AGREES" if ok else "QUADRATURE DISAGREES")
    return ok


# ---------------------------------------------------------------------------------------------------------
# Binary mixture (Enskog, uniform chi_ij), species i, j with their own temperatures T_i (HCS or HSS)
# ---------------------------------------------------------------------------------------------------------
# Pair coordinates of docs/methods/derivations/mixture-hcs.md (imported from mixture_hcs.py): in units of
# s = sqrt(theta_i + theta_j), v1 = G + u g, v2 = G - (1-u) g, G ~ N(0, u(1-u)), g ~ N(0, 1) independent,
# u = theta_i / s^2, v1' = v1 - b (sig.g) sig with b = mu_ji (1 + alpha_ij), x1 = v1^2/(2 theta_i) = |v1|^2 w1 / 2,
# w1 = 1/u, w2 = 1/(1-u).  f_i0 = n_i phi_i W_i, W_i = 1 + a_i S2(x1); d f_i0 / dv = n_i phi_i w_i(v),
# w_i = (v / theta_i)[-(1 + a_i S2) + a_i S2'], i.e. s w_i = v-hat w1 [...]; f_i1 = n_i A_i phi_i D(v):E.
MU, MB, MAI, MAJ = mh.u, mh.b, mh.ai, mh.aj


def mexpect(poly):
    """4 pi E[Theta(g_z) poly] over the pair coordinates (units of s): sympy expression in u, b, a_i, a_j.
    Half-line moments of g_z ~ N(0, 1): z^(2m+1) -> 2^m m!/sqrt(2 pi), z^(2m) -> (2m-1)!!/2."""
    out = 0
    for e, c in poly.terms():
        if any(k % 2 for k in e[:5]):
            continue
        val = sp.Rational(int(c.numerator), int(c.denominator))
        for k in e[:3]:
            val *= dfact(k - 1) * (MU * (1 - MU)) ** (k // 2)
        for k in e[3:5]:
            val *= dfact(k - 1)
        r = e[5]
        if r % 2:
            m = (r - 1) // 2
            val *= sp.Integer(2**m * factorial(m)) / sp.sqrt(2 * sp.pi)
        else:
            val *= sp.Rational(dfact(r - 1), 2)
        uu, w1, w2, bb, aii, ajj = e[6:]
        out += val * MU**uu * (1 / MU) ** w1 * (1 / (1 - MU)) ** w2 * MB**bb * MAI**aii * MAJ**ajj
    return sp.factor(sp.cancel(sp.together(4 * sp.pi * out)))


def mixture_coefficients():
    """The seven pair functions (all per n_i n_j; s = s_ij):
       L1 = m_i s^5 l1, L2 = m_i s^5 l2    Boltzmann part, f_i1 x f_j0 and f_i0 x f_j1 (moment m_i D(v1))
       Lambda_J = m_i s^2 lJ               Enskog gradient source, f_i0 x grad f_j0
       T_a = s^4 ta, T_b = s^4 tb          collisional transfer of f_j1 (at v2) and of f_i1 (at v1)
       Lambda_c1 = s c1, Lambda_c2 = s c2  collisional transfer across grad u, grad at v1 or at v2."""
    v1, v2, v1p = mh.v1, mh.v2, mh.v1p
    Wi = 1 + mh.AI * mh.S2(mh.x1)
    Wj = 1 + mh.AJ * mh.S2(mh.x2)
    wi = tuple(c * mh.W1 * (-(1 + mh.AI * mh.S2(mh.x1)) + mh.AI * (mh.x1 - QQ(5, 2))) for c in v1)
    wj = tuple(c * mh.W2 * (-(1 + mh.AJ * mh.S2(mh.x2)) + mh.AJ * (mh.x2 - QQ(5, 2))) for c in v2)
    gzr = mh.gz
    Dzz = lambda V: V[2] ** 2 - dot(V, V) * QQ(1, 3)
    return {
        "l1": mexpect(gzr * Wj * (DD(v1p, v1) - DD(v1, v1))) / 5,
        "l2": mexpect(gzr * Wi * (DD(v1p, v2) - DD(v1, v2))) / 5,
        "lJ": -mexpect(gzr * Wi * (zDw(v1p, wj) - zDw(v1, wj))) / 5,
        "ta": mexpect(gzr**2 * Wi * Dzz(v2)) / 5,
        "tb": mexpect(gzr**2 * Dzz(v1) * Wj) / 5,
        # linearised in (a_i, a_j) as 003's (1 - c0/32): the a_i a_j term is dropped
        "c1": linear_a(mexpect(gzr**2 * QQ(2, 3) * wi[2] * Wj) / 5),
        "c2": linear_a(mexpect(gzr**2 * QQ(2, 3) * Wi * wj[2]) / 5),
    }


def linear_a(expr):
    p = sp.Poly(sp.expand(expr), MAI, MAJ)
    return sp.factor(sum(cf * MAI**k[0] * MAJ**k[1] for k, cf in p.terms() if k[0] + k[1] <= 1))


def print_mixture_coefficients(C):
    for k, v in C.items():
        p = sp.Poly(sp.expand(v), MAI, MAJ)
        print(f"{k}:")
        for mon, cf in sorted(p.terms()):
            print(f"    a_i^{mon[0]} a_j^{mon[1]}:  {sp.factor(cf)}")


class Pair:
    """Numeric pair data for (i, j) at temperatures T."""

    def __init__(self, m, T, i, j, alpha_):
        th = [T[0] / m[0], T[1] / m[1]]
        self.s = math.sqrt(th[i] + th[j])
        self.u = th[i] / (th[i] + th[j])
        self.b = m[j] / (m[i] + m[j]) * (1 + alpha_)
        self.theta_i = th[i]


def mixture_viscosity(NUMC, m, sig, n, nE, chi, alpha_, T, a, zeta, r):
    """Assembly (docs/methods/derivations/viscosity.md): returns (eta^k_i list, eta^c1, eta^c0).  n: number densities of the
    Boltzmann part (only their ratio matters); nE: the densities in the Enskog terms (x_i n with
    n = 6 phi / (pi sum_k x_k sigma_k^3); zero when dilute).  r = 1/2 (cooling) or 1 (Gaussian thermostat);
    T = (T_1, T_2) the partial temperatures; a = (a_1, a_2); zeta the cooling rate at the densities n."""
    import numpy as np
    th = [T[0] / m[0], T[1] / m[1]]
    val = lambda key, p, i, j: NUMC[key](p.u, p.b, a[i], a[j])
    tau = np.zeros((2, 2))
    rhs = np.zeros(2)
    for i in range(2):
        rhs[i] = n[i] * T[i]
        for j in range(2):
            p = Pair(m, T, i, j, alpha_)
            sij = 0.5 * (sig[i] + sig[j])
            L1 = m[i] * p.s**5 * val("l1", p, i, j)
            L2 = m[i] * p.s**5 * val("l2", p, i, j)
            tau[i, i] -= n[j] * sij**2 * chi[i][j] * L1 / (2 * m[i] * th[i] ** 2)
            tau[i, j] -= n[i] * sij**2 * chi[i][j] * L2 / (2 * m[j] * th[j] ** 2)
            rhs[i] -= 0.5 * n[i] * nE[j] * sij**3 * chi[i][j] * m[i] * p.s**2 * val("lJ", p, i, j)
    eta_k = np.linalg.solve(tau - r * zeta * np.eye(2), rhs)
    B = [-eta_k[i] / (m[i] * th[i] ** 2) for i in range(2)]          # n_i A_i
    c1 = c0 = 0.0
    for i in range(2):
        for j in range(2):
            p = Pair(m, T, i, j, alpha_)
            sij = 0.5 * (sig[i] + sig[j])
            mij = m[i] * m[j] / (m[i] + m[j])
            pre = mij * (1 + alpha_) * sij**3 * chi[i][j]
            c1 -= 0.25 * pre * p.s**4 * (nE[i] * B[j] * val("ta", p, i, j) + nE[j] * B[i] * val("tb", p, i, j))
            c0 -= 0.125 * pre * nE[i] * nE[j] * sij * p.s * (val("c1", p, i, j) - val("c2", p, i, j))
    return list(eta_k), c1, c0


def enskog_densities(sig, n, phi):
    x = [n[0] / sum(n), n[1] / sum(n)]
    ntot = 6 * phi / (math.pi * (x[0] * sig[0] ** 3 + x[1] * sig[1] ** 3))
    return [x[0] * ntot, x[1] * ntot]


def numeric_coefficients(C):
    return {k: sp.lambdify((MU, MB, MAI, MAJ), v, "math") for k, v in C.items()}


def monodisperse_total(al, phi, chi, r):
    """003's closed forms with r = 1/2, and the Gaussian-thermostat variant r = 1 (the C++ shear_viscosity)."""
    c0 = 2 * mh.vne(al)
    nu = chi * (1 - (1 - al) ** 2 / 4) * (1 - c0 / 64)
    z = 5 / 12 * chi * (1 - al * al) * (1 + 3 * c0 / 32)
    ek = (1 - 0.4 * phi * chi * (1 + al) * (1 - 3 * al)) / (nu - r * z)
    return ek, ek * (1 + 0.8 * phi * chi * (1 + al)) + 384 / (25 * math.pi) * phi**2 * chi * (1 + al) * (1 - c0 / 32)


def hcb_elastic(m, sig, n):
    """Elastic dilute binary mixture, first approximation (Hirschfelder, Curtiss & Bird 1954, eqs. 8.2-22 to
    8.2-25; rigid spheres: A* = 1, Omega^(2,2)* = 1), T = 1."""
    x = [n[0] / sum(n), n[1] / sum(n)]
    eij = lambda i, j: 5 / 16 * math.sqrt(2 * math.pi * m[i] * m[j] / (m[i] + m[j])) / (math.pi * (0.5 * (sig[i] + sig[j])) ** 2)
    H = [[0.0, 0.0], [0.0, 0.0]]
    for i in range(2):
        k = 1 - i
        f = m[i] * m[k] / (m[i] + m[k]) ** 2
        H[i][i] = x[i] ** 2 / eij(i, i) + 2 * x[i] * x[k] / eij(i, k) * f * (5 / 3 + m[k] / m[i])
        H[i][k] = -2 * x[i] * x[k] / eij(i, k) * f * (5 / 3 - 1)
    d = H[0][0] * H[1][1] - H[0][1] * H[1][0]
    y0 = (x[0] * H[1][1] - H[0][1] * x[1]) / d
    y1 = (H[0][0] * x[1] - H[1][0] * x[0]) / d
    return x[0] * y0 + x[1] * y1


def mixture_state(NUM, mu, omega, delta, al, phi, order):
    """gamma, a_i, zeta (T_2 = 1) from mixture_hcs.py; chi_ij Carnahan-Starling (000 eq. 3)."""
    mix = mh.Mixture(mu, omega, delta, al, phi)
    g, a = mh.hcs(NUM, mix, order)
    z, _ = mh.zeta_and_residual(NUM, mix, [g, 1.0], a, "linear")
    return mix, g, a, z[0]


def mixture_eta(NUM, NUMC, mu, omega, delta, al, phi, order="linear", r=1.0):
    """eta^k and eta at the mixture temperature T = x_1 T_1 + x_2 T_2 = 1."""
    mix, g, a, z = mixture_state(NUM, mu, omega, delta, al, phi, order)
    x1 = delta / (1 + delta)
    T2 = 1 / (x1 * g + 1 - x1)
    T = [g * T2, T2]
    # zeta scales as sqrt(T): the value at T_2 = 1 times sqrt(T2)
    nE = enskog_densities(mix.sig, mix.n, phi)
    ek, c1, c0 = mixture_viscosity(NUMC, mix.m, mix.sig, mix.n, nE, mix.chi, al, T, a, z * math.sqrt(T2), r)
    return sum(ek), sum(ek) + c1 + c0, (ek, c1, c0)


def mixture_checks(C, NUMC):
    import random
    ok = True
    # (a) identical species, symbolic: u = 1/2, b = (1+alpha)/2, a_i = a_j.
    sub = {MU: sp.Rational(1, 2), MB: (1 + alpha) / 2, MAI: a2, MAJ: a2}
    mono = {k: sp.expand(v.subs(sub)) for k, v in C.items()}
    # one species, m = T = 1: s^2 = 2; l1 + l2 per 2^(5/2) = (lambda_b + lambda_a)/... compare with the one-species
    # integrals (pair coordinates of the one-species part are G, g with g ~ N(0, 2): the same integrals).
    d1 = lambda W: DD(V1p, W) - DD(V1, W)
    lam_a = integral(gz * W0(V1) * d1(V2)) / 5
    lam_b = integral(gz * W0(V2) * d1(V1)) / 5
    s2 = sp.Integer(2)
    ok &= report("mixture l1 + l2 at identical species (x s^5) vs one-species lambda_b + lambda_a",
                 sp.expand((mono["l1"] + mono["l2"]) * s2 ** sp.Rational(5, 2)), sp.expand(lam_a + lam_b))
    # (b) identical species, numeric assembly (random n_1/n_2, phi, alpha) against the closed forms.
    NUM = mh.make_numeric(*DERIVED_P2P4)
    random.seed(5)
    worst = 0.0
    for _ in range(6):
        al, phi, delta = random.uniform(0.2, 1.0), random.uniform(0.0, 0.45), random.uniform(0.1, 10)
        for rr in (0.5, 1.0):
            ek, e, _ = mixture_eta(NUM, NUMC, 1.0, 1.0, delta, al, phi, "linear", rr)
            chi = (1 - phi / 2) / (1 - phi) ** 3
            eta0 = 5 / (16 * math.sqrt(math.pi))
            mk, mt = monodisperse_total(al, phi, chi, rr)
            worst = max(worst, abs(ek / eta0 / mk - 1), abs(e / eta0 / mt - 1))
    print(f"identical species, assembled mixture vs one-species closed forms: worst rel. diff {worst:.1e}")
    ok &= worst < 1e-12
    # (c) elastic dilute, equal temperatures: Hirschfelder-Curtiss-Bird.
    worst = 0.0
    for _ in range(20):
        m = [random.uniform(0.05, 20), random.uniform(0.05, 20)]
        sig = [random.uniform(0.2, 5), random.uniform(0.2, 5)]
        n = [random.uniform(0.05, 5), random.uniform(0.05, 5)]
        ek, c1, c0 = mixture_viscosity(NUMC, m, sig, n, [0, 0], [[1, 1], [1, 1]], 1.0, [1.0, 1.0], [0, 0], 0.0, 1.0)
        worst = max(worst, abs(sum(ek) / hcb_elastic(m, sig, n) - 1))
    print(f"elastic dilute vs Hirschfelder-Curtiss-Bird 8.2-22: worst rel. diff {worst:.1e}")
    ok &= worst < 1e-12
    # (d) elastic Enskog, gradient term vs (3/5) kappa, kappa = (4/9) sum_ij n_i n_j sigma_ij^4 chi_ij sqrt(2 pi m_ij T)
    #     (the one-species kappa = (4/9) n^2 sigma^4 chi sqrt(pi m T) with m_ij -> m/2).
    worst = 0.0
    for _ in range(20):
        m = [random.uniform(0.05, 20), random.uniform(0.05, 20)]
        sig = [random.uniform(0.2, 5), random.uniform(0.2, 5)]
        n = [random.uniform(0.05, 5), random.uniform(0.05, 5)]
        chi = [[random.uniform(1, 3), 0], [0, random.uniform(1, 3)]]
        chi[0][1] = chi[1][0] = random.uniform(1, 3)
        _, _, c0 = mixture_viscosity(NUMC, m, sig, n, n, chi, 1.0, [1.0, 1.0], [0, 0], 0.0, 1.0)
        kappa = 4 / 9 * sum(n[i] * n[j] * (0.5 * (sig[i] + sig[j])) ** 4 * chi[i][j] *
                            math.sqrt(2 * math.pi * m[i] * m[j] / (m[i] + m[j])) for i in range(2) for j in range(2))
        worst = max(worst, abs(c0 / (0.6 * kappa) - 1))
    print(f"elastic Enskog gradient term vs (3/5) kappa: worst rel. diff {worst:.1e}")
    ok &= worst < 1e-12
    # (e) elastic Enskog mixture, equal temperatures: Thorne's theory as in Hirschfelder, Curtiss & Bird sec. 9.3,
    #     eta = sum_ij y_i (H^chi)^-1_ij y_j + (3/5) kappa, y_i = x_i [1 + (8 pi/15) sum_j n_j mu_ji sigma_ij^3 chi_ij],
    #     H^chi the dilute H of (c) with each 1/eta_ij multiplied by chi_ij.
    worst = 0.0
    for _ in range(20):
        m = [random.uniform(0.05, 20), random.uniform(0.05, 20)]
        sig = [random.uniform(0.2, 5), random.uniform(0.2, 5)]
        n = [random.uniform(0.01, 0.3), random.uniform(0.01, 0.3)]
        chi = [[random.uniform(1, 3), 0], [0, random.uniform(1, 3)]]
        chi[0][1] = chi[1][0] = random.uniform(1, 3)
        ek, c1, c0 = mixture_viscosity(NUMC, m, sig, n, n, chi, 1.0, [1.0, 1.0], [0, 0], 0.0, 1.0)
        x = [n[0] / sum(n), n[1] / sum(n)]
        sij = lambda i, j: 0.5 * (sig[i] + sig[j])
        y = [x[i] * (1 + 8 * math.pi / 15 * sum(n[j] * m[j] / (m[i] + m[j]) * sij(i, j) ** 3 * chi[i][j] for j in range(2)))
             for i in range(2)]
        eij = lambda i, j: 5 / 16 * math.sqrt(2 * math.pi * m[i] * m[j] / (m[i] + m[j])) / (math.pi * sij(i, j) ** 2) / chi[i][j]
        H = [[0.0, 0.0], [0.0, 0.0]]
        for i in range(2):
            k = 1 - i
            f = m[i] * m[k] / (m[i] + m[k]) ** 2
            H[i][i] = x[i] ** 2 / eij(i, i) + 2 * x[i] * x[k] / eij(i, k) * f * (5 / 3 + m[k] / m[i])
            H[i][k] = -2 * x[i] * x[k] / eij(i, k) * f * (5 / 3 - 1)
        d = H[0][0] * H[1][1] - H[0][1] * H[1][0]
        z0 = (y[0] * H[1][1] - H[0][1] * y[1]) / d
        z1 = (H[0][0] * y[1] - H[1][0] * y[0]) / d
        kappa = 4 / 9 * sum(n[i] * n[j] * sij(i, j) ** 4 * chi[i][j] * math.sqrt(2 * math.pi * m[i] * m[j] / (m[i] + m[j]))
                            for i in range(2) for j in range(2))
        worst = max(worst, abs((sum(ek) + c1 + c0) / (y[0] * z0 + y[1] * z1 + 0.6 * kappa) - 1))
    print(f"elastic Enskog mixture vs Thorne (HCB sec. 9.3): worst rel. diff {worst:.1e}")
    ok &= worst < 1e-12
    # (f) the transfer integrands of (i, j) and (j, i) are one integral: ta(u) = tb(1 - u) with a_i <-> a_j,
    #     c1(u) = -c2(1 - u) with a_i <-> a_j.
    swap = lambda e: e.subs({MU: 1 - MU, MAI: MAJ, MAJ: MAI}, simultaneous=True)
    ok &= report("ta(u) - tb(1-u) [swapped labels]", sp.simplify(C["ta"] - swap(C["tb"])), 0)
    ok &= report("c1(u) + c2(1-u) [swapped labels]", sp.simplify(C["c1"] + swap(C["c2"])), 0)
    return ok


def mixture_quadrature(C, points=((2.0, 1.0, 1.3, 1.0, 0.7, 0.2, -0.1), (1.0, 10.0, 0.2, 1.0, 0.5, 0.05, 0.3),
                                  (5.0, 0.5, 3.0, 0.4, 0.0, -0.2, 0.1))):
    """Independent quadrature in the ORIGINAL velocities (v1 ~ N(0, theta_i), v2 ~ N(0, theta_j)), sig = z:
    x, y components by 4D Gauss-Hermite, (v2z, g_z = v1z - v2z > 0) by a Gauss-Legendre product rule on a box.
    Each point is (m_i, m_j, T_i, T_j, alpha, a_i, a_j)."""
    import numpy as np
    from numpy.polynomial.hermite_e import hermegauss
    from numpy.polynomial.legendre import leggauss
    NUMC = numeric_coefficients(C)
    ok = True
    xh, wh = hermegauss(10)
    wh = wh / np.sqrt(2 * np.pi)
    xl, wl = leggauss(90)
    for (mi, mj, Ti, Tj, al, ai_, aj_) in points:
        thi, thj = Ti / mi, Tj / mj
        s = math.sqrt(thi + thj)
        b_ = mj / (mi + mj) * (1 + al)
        L = 14 * max(math.sqrt(thi), math.sqrt(thj))
        v2zs, w2z = L * xl, L * wl
        gzs, wgz = L * (xl + 1), L * wl
        X1, Y1, X2, Y2 = np.meshgrid(xh * math.sqrt(thi), xh * math.sqrt(thi), xh * math.sqrt(thj), xh * math.sqrt(thj), indexing="ij")
        Wxy = np.einsum("a,b,c,d->abcd", wh, wh, wh, wh).reshape(-1)
        X1, Y1, X2, Y2 = X1.reshape(-1), Y1.reshape(-1), X2.reshape(-1), Y2.reshape(-1)
        phi = lambda v, th: np.exp(-v * v / (2 * th)) / math.sqrt(2 * math.pi * th)
        S2n = lambda x: x * x / 2 - 2.5 * x + 15 / 8
        acc = dict.fromkeys(C, 0.0)
        for v2z, wv in zip(v2zs, w2z):
            for gzv, wg in zip(gzs, wgz):
                v1z = v2z + gzv
                w = Wxy * wv * wg * phi(v1z, thi) * phi(v2z, thj)
                V1 = np.stack([X1, Y1, np.full_like(X1, v1z)], -1)
                V2 = np.stack([X2, Y2, np.full_like(X2, v2z)], -1)
                V1p = V1.copy()
                V1p[:, 2] -= b_ * gzv
                sq = lambda V: np.einsum("ij,ij->i", V, V)
                x1n, x2n = sq(V1) / (2 * thi), sq(V2) / (2 * thj)
                Wi_, Wj_ = 1 + ai_ * S2n(x1n), 1 + aj_ * S2n(x2n)
                wi_ = V1 / thi * (-(1 + ai_ * S2n(x1n)) + ai_ * (x1n - 2.5))[:, None]
                wj_ = V2 / thj * (-(1 + aj_ * S2n(x2n)) + aj_ * (x2n - 2.5))[:, None]
                DDn = lambda V, U: np.einsum("ij,ij->i", V, U) ** 2 - sq(V) * sq(U) / 3
                zD = lambda V, ww: V[:, 2] * np.einsum("ij,ij->i", V, ww) - sq(V) * ww[:, 2] / 3
                Dz = lambda V: V[:, 2] ** 2 - sq(V) / 3
                f = 4 * np.pi / 5
                acc["l1"] += f * np.sum(w * gzv * Wj_ * (DDn(V1p, V1) - DDn(V1, V1)))
                acc["l2"] += f * np.sum(w * gzv * Wi_ * (DDn(V1p, V2) - DDn(V1, V2)))
                acc["lJ"] -= f * np.sum(w * gzv * Wi_ * (zD(V1p, wj_) - zD(V1, wj_)))
                acc["ta"] += f * np.sum(w * gzv**2 * Wi_ * Dz(V2))
                acc["tb"] += f * np.sum(w * gzv**2 * Dz(V1) * Wj_)
                # linear in (a_i, a_j), as the closed forms: drop the a_i a_j product
                wi0, wj0 = -V1[:, 2] / thi, -V2[:, 2] / thj
                acc["c1"] += f * np.sum(w * gzv**2 * (2 / 3) * (wi_[:, 2] + wi0 * (Wj_ - 1)))
                acc["c2"] += f * np.sum(w * gzv**2 * (2 / 3) * (wj_[:, 2] + wj0 * (Wi_ - 1)))
        u_ = thi / s**2
        scale = {"l1": s**5, "l2": s**5, "lJ": s**2, "ta": s**4, "tb": s**4, "c1": s, "c2": s}
        for k in C:
            exact = NUMC[k](u_, b_, ai_, aj_) * scale[k]
            rel = abs(acc[k] - exact) / max(abs(exact), 1e-300)
            ok &= rel < 1e-9
            print(f"({mi}, {mj}, {Ti}, {Tj}, {al}, {ai_}, {aj_}) {k}: quadrature {acc[k]: .12e}  closed form {exact: .12e}  rel {rel:.1e}")
    print("MIXTURE QUADRATURE AGREES" if ok else "MIXTURE QUADRATURE DISAGREES")
    return ok


def mixture_tables(NUM, NUMC):
    """Tables of docs/methods/derivations/viscosity.md: 000 Figs. 6-12 (Gaussian thermostat, the HSS of 000)."""
    f5 = mh.f5
    print("\n### Fig. 6: one species, phi = 0\n")
    print("| alpha | c0 = 2 a2 | eta/eta0 HCS (a) | eta/eta0 HSS (b) |")
    print("|---|---|---|---|")
    for al in [0.5, 0.6, 0.7, 0.8, 0.9, 1.0]:
        print(f"| {al:.1f} | {f5(2 * mh.vne(al))} | {f5(monodisperse_total(al, 0, 1, 0.5)[1])} | "
              f"{f5(monodisperse_total(al, 0, 1, 1.0)[1])} |")

    def ratio(mu, omega, delta, al, phi=0.0, order="linear"):
        return mixture_eta(NUM, NUMC, mu, omega, delta, al, phi, order)[1] / mixture_eta(NUM, NUMC, mu, omega, delta, 1.0, phi)[1]

    def star(mu, omega, delta, al, phi, order="linear"):
        ek, e, _ = mixture_eta(NUM, NUMC, mu, omega, delta, al, phi, order)
        v0 = math.sqrt(2 * (mu + 1) / mu)
        f = math.sqrt(math.pi) * (0.5 * (omega + 1)) ** 2 * v0
        return f * ek, f * e

    for title, key, values, fixed in (
            ("Fig. 7: eta(alpha)/eta0 vs mu, omega = delta = 1, phi = 0", "mu", [0.25, 0.5, 1, 2, 4, 6, 8, 10], {}),
            ("Fig. 8: eta(alpha)/eta0 vs omega, mu = 4, delta = 1, phi = 0", "omega", [0.5, 1, 1.5, 2, 2.5, 3], {}),
            ("Fig. 9: eta(alpha)/eta0 vs delta, mu = 4, omega = 1, phi = 0", "delta", [0.1, 0.25, 0.5, 1, 2, 4, 10], {})):
        print(f"\n### {title} (first-Sonine state; in brackets: Maxwellian state, a_i = 0 and Maxwellian gamma)\n")
        print(f"| {key} | alpha = 0.9 | alpha = 0.8 | alpha = 0.7 |")
        print("|---|---|---|---|")
        for v in values:
            p = {"mu": 4.0, "omega": 1.0, "delta": 1.0} if key != "mu" else {"mu": 1.0, "omega": 1.0, "delta": 1.0}
            p[key] = float(v)
            cells = [f"{f5(ratio(p['mu'], p['omega'], p['delta'], al))} ({f5(ratio(p['mu'], p['omega'], p['delta'], al, 0.0, 'maxwell'))})"
                     for al in (0.9, 0.8, 0.7)]
            print(f"| {v} | " + " | ".join(cells) + " |")
    print("\n### Figs. 10-11: eta^k* and eta* vs phi, mu = 4, omega = delta = 1\n")
    print("| phi | eta^k* 0.9 | eta^k* 0.8 | eta^k* 0.7 | eta* 0.9 | eta* 0.8 | eta* 0.7 | eta* 1.0 |")
    print("|---|---|---|---|---|---|---|---|")
    for phi in [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]:
        r = [star(4.0, 1.0, 1.0, al, phi) for al in (0.9, 0.8, 0.7, 1.0)]
        print(f"| {phi:.1f} | " + " | ".join(f5(x[0]) for x in r[:3]) + " | " + " | ".join(f5(x[1]) for x in r) + " |")
    print("\n### Fig. 12: eta* vs mu, omega = delta = 1, phi = 0.2\n")
    print("| mu | alpha = 0.9 | alpha = 0.8 | alpha = 0.7 | alpha = 1 |")
    print("|---|---|---|---|---|")
    for mu in [0.25, 0.5, 1, 2, 4, 6, 8, 10]:
        print(f"| {mu} | " + " | ".join(f5(star(float(mu), 1.0, 1.0, al, 0.2)[1]) for al in (0.9, 0.8, 0.7, 1.0)) + " |")


DERIVED_P2P4 = None


def mixture_main(tables=False):
    global DERIVED_P2P4
    import contextlib
    import io
    with contextlib.redirect_stdout(io.StringIO()):
        P2, P4, _ = mh.derive()
    DERIVED_P2P4 = (P2, P4)
    C = mixture_coefficients()
    print_mixture_coefficients(C)
    NUMC = numeric_coefficients(C)
    ok = mixture_checks(C, NUMC)
    print("MIXTURE CHECKS PASSED" if ok else "MIXTURE CHECKS FAILED")
    if tables:
        mixture_tables(mh.make_numeric(P2, P4), NUMC)
    return ok


if __name__ == "__main__":
    if "--quad" in sys.argv:
        ok = quadrature_check()
        ok &= mixture_quadrature(mixture_coefficients())
        sys.exit(0 if ok else 1)
    ok = main()
    ok &= mixture_main(tables="--tables" in sys.argv)
    sys.exit(0 if ok else 1)
