#!/usr/bin/env python3
"""Exact collisional moments mu_2, mu_4, mu_6 of smooth inelastic hard spheres (d = 3) or hard disks
(d = 2) for the second-Sonine distribution F = phi(c) [1 + a2 S2(c^2) + a3 S3(c^2)], and the HCS Sonine
coefficients.

Run with /usr/bin/python3 (needs sympy): `sonine_hcs.py [--dimension 2]` (default 3), with `--quad` or
`--mc` for the independent checks of the moments.  Derivation: docs/methods/derivations/sonine-hcs.md.

    mu_p = -int dc c^p I[F,F]
         = -(1/2) int dc1 dc2 dsigma Theta(sigma.g) (sigma.g) F(c1) F(c2) [c1'^p + c2'^p - c1^p - c2^p],
    g = c1 - c2,  c1' = c1 - (1+alpha)/2 (sigma.g) sigma,  c2' = c2 + (1+alpha)/2 (sigma.g) sigma.

Centre-of-mass and relative coordinates G = (c1+c2)/2, g (unit Jacobian): phi(c1) phi(c2) =
pi^-d exp(-2 G^2 - g^2/2).  The integrand is rotation invariant, so the sigma integral is S_d (4 pi, or
2 pi for disks) times the integrand at sigma along the last axis z.  Then c1^2, c2^2 = G^2 +- G.g + g^2/4
and c1'^2, c2'^2 = G^2 +- G.g' + g'^2/4 with g' = g with g_z -> -alpha g_z.  What remains is a polynomial in
the 2d Cartesian components times Gaussians (g_z restricted to g_z > 0, with one extra power g_z), each
monomial integrated exactly:
    int x^(2k) exp(-2 x^2) dx  = sqrt(pi/2) (2k-1)!! / 4^k          (G components)
    int x^(2k) exp(-x^2/2) dx  = sqrt(2 pi) (2k-1)!!                 (the d - 1 transverse g components)
    int_0^inf z^(2m+1) exp(-z^2/2) dz = 2^m m!                        (g_z, incl. the factor sigma.g)
Collecting the constants, mu_p = -sqrt(2 pi) kappa_d * sum_monomials coeff * (product of the rational
parts), kappa_d = S_d pi^-d (pi/2)^(d/2) (2 pi)^((d-1)/2) / (2 sqrt(2 pi)): 1 for d = 3, 1/2 for d = 2.
The result is printed as mu_p / sqrt(2 pi) = polynomial in alpha, a2, a3 with rational coefficients.
The Sonine polynomials are the Laguerre polynomials L^(d/2-1)_2 and L^(d/2-1)_3 of c^2.
"""
import sys
import time
from fractions import Fraction
from math import factorial, pi

import sympy as sp
from sympy.polys.rings import ring
from sympy.polys.domains import QQ

D = int(sys.argv[sys.argv.index("--dimension") + 1]) if "--dimension" in sys.argv else 3
if D not in (2, 3):
    raise SystemExit("--dimension: 2 or 3")
# G_0 .. G_{d-1}, g_0 .. g_{d-1} (g_{d-1} along sigma), alpha, a2, a3
R, *GENS = ring(",".join([f"G{i}" for i in range(D)] + [f"g{i}" for i in range(D)] + ["al", "A2", "A3"]), QQ)
G, g, al, A2, A3 = GENS[:D], GENS[D:2 * D], GENS[2 * D], GENS[2 * D + 1], GENS[2 * D + 2]
KAPPA = {3: sp.Integer(1), 2: sp.Rational(1, 2)}[D]  # the docstring's kappa_d (checked in main)


def S2(x, d=D):  # L^(d/2-1)_2(x)
    return QQ(1, 2) * x**2 - QQ(d + 2, 2) * x + QQ(d * (d + 2), 8)


def S3(x, d=D):  # L^(d/2-1)_3(x)
    return -QQ(1, 6) * x**3 + QQ(d + 4, 4) * x**2 - QQ((d + 2) * (d + 4), 8) * x + QQ(d * (d + 2) * (d + 4), 48)


def dfact(n):  # (2k-1)!! with n = 2k-1, (-1)!! = 1
    r = 1
    while n > 1:
        r *= n
        n -= 2
    return r


G2 = sum(x**2 for x in G)
Gg = sum(x * y for x, y in zip(G, g))
g2 = sum(y**2 for y in g)
Ggp = Gg - (1 + al) * G[-1] * g[-1]  # g' = g with g_z -> -alpha g_z
gp2 = g2 - g[-1]**2 + al**2 * g[-1]**2
c1sq, c2sq = G2 + Gg + g2 / 4, G2 - Gg + g2 / 4
c1psq, c2psq = G2 + Ggp + gp2 / 4, G2 - Ggp + gp2 / 4


def gauss_integral(poly):
    """Map a ring element in (G, g, al, A2, A3) to sum over G,g monomials of coeff * moment (rational);
    returns a dict {(al_exp, a2_exp, a3_exp): Fraction}."""
    out = {}
    for mon, coeff in poly.terms():
        e = mon
        # parity: every Cartesian exponent must be even (g_z even as well; the weight carries g_z^1)
        if any(x % 2 for x in e[:2 * D]):
            continue
        val = Fraction(1)
        for k in e[:D]:
            val *= Fraction(dfact(k - 1), 4 ** (k // 2))
        for k in e[D:2 * D - 1]:
            val *= dfact(k - 1)
        m = e[2 * D - 1] // 2
        val *= (2**m) * factorial(m)
        key = e[2 * D:]
        out[key] = out.get(key, Fraction(0)) + Fraction(int(coeff.numerator), int(coeff.denominator)) * val
    return out


def collision_moment(p, maxdeg=2):
    """mu_p / sqrt(2 pi) as dict {(al, a2, a3): Fraction}; F F' product kept to total degree maxdeg in
    (a2, a3) (2 = exact)."""
    h = p // 2
    delta = c1psq**h + c2psq**h - c1sq**h - c2sq**h
    f1 = 1 + A2 * S2(c1sq) + A3 * S3(c1sq)
    f2 = 1 + A2 * S2(c2sq) + A3 * S3(c2sq)
    ff = f1 * f2
    res = {}
    # expand term by term in (a2, a3) to keep the intermediate polynomials small
    # group ff by its (A2, A3) exponent
    groups = {}
    for mon, coeff in ff.terms():
        key = mon[2 * D + 1:]
        if sum(key) > maxdeg:
            continue
        groups.setdefault(key, R(0))
        groups[key] += R({mon[:2 * D + 1] + (0, 0): coeff})
    kappa = Fraction(int(KAPPA.p), int(KAPPA.q))
    for key, part in groups.items():
        integ = gauss_integral(part * delta)
        for (ea, _, _), v in integ.items():
            k = (ea,) + key
            res[k] = res.get(k, Fraction(0)) - kappa * v
    return {k: v for k, v in res.items() if v != 0}


SURFACE = {3: 4 * pi, 2: 2 * pi}[D]  # S_d, the area of the unit sphere (circle)


def S2n(x):  # S2, numerically
    return 0.5 * x * x - (D + 2) / 2 * x + D * (D + 2) / 8


def S3n(x):  # S3, numerically
    return -x**3 / 6 + (D + 4) / 4 * x * x - (D + 2) * (D + 4) / 8 * x + D * (D + 2) * (D + 4) / 48


def monte_carlo_check(alpha_val, nsamp=40_000_000, batch=2_000_000, seed=1):
    """Independent check of every coefficient of mu_p (p = 2, 4, 6) by plain Monte Carlo: c1, c2 drawn
    from phi, sigma uniform on the sphere (no centre-of-mass coordinates, no symbolic algebra).
    mu_p coefficient of a2^i a3^j = -E[(S_d / 2) Theta(s.g) (s.g) w_ij(c1, c2) Delta_p]."""
    import numpy as np
    rng = np.random.default_rng(seed)
    keys = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]
    acc = {(p, k): [0.0, 0.0] for p in (2, 4, 6) for k in keys}
    n = 0
    while n < nsamp:
        c1 = rng.normal(scale=np.sqrt(0.5), size=(batch, D))
        c2 = rng.normal(scale=np.sqrt(0.5), size=(batch, D))
        s = rng.normal(size=(batch, D)); s /= np.linalg.norm(s, axis=1)[:, None]
        sg = np.einsum("ij,ij->i", s, c1 - c2)
        th = np.where(sg > 0, sg, 0.0)
        c1p = c1 - 0.5 * (1 + alpha_val) * sg[:, None] * s
        c2p = c2 + 0.5 * (1 + alpha_val) * sg[:, None] * s
        x1, x2 = (c1**2).sum(1), (c2**2).sum(1)
        y1, y2 = (c1p**2).sum(1), (c2p**2).sum(1)
        w = {(0, 0): 1.0, (1, 0): S2n(x1) + S2n(x2), (0, 1): S3n(x1) + S3n(x2), (2, 0): S2n(x1) * S2n(x2),
             (1, 1): S2n(x1) * S3n(x2) + S3n(x1) * S2n(x2), (0, 2): S3n(x1) * S3n(x2)}
        for p in (2, 4, 6):
            h = p // 2
            delta = y1**h + y2**h - x1**h - x2**h
            for k in keys:
                v = -0.5 * SURFACE * th * w[k] * delta / np.sqrt(2 * np.pi)
                acc[(p, k)][0] += v.sum(); acc[(p, k)][1] += (v * v).sum()
        n += batch
    out = {}
    for key, (s1, s2) in acc.items():
        m = s1 / n
        out[key] = (m, np.sqrt((s2 / n - m * m) / n))
    return out


def quadrature_check(alpha_val):
    """Independent deterministic check of every coefficient of mu_p: sigma = z (rotation invariance);
    the transverse components of c1 and c2 by Gauss-Hermite (12 nodes, exact to degree 23 per component),
    the z pair in (Gz, gz): Gz by Gauss-Hermite for the weight exp(-2 Gz^2), gz > 0 by 80-node
    Gauss-Legendre on [0, 14] (the integrand is a polynomial times exp(-gz^2/2)).  Returns
    {(p, (i, j)): mu_p coeff/sqrt(2pi)}."""
    import numpy as np
    xh, wh = np.polynomial.hermite.hermgauss(12)          # weight exp(-x^2)
    xl, wl = np.polynomial.legendre.leggauss(80)
    zg, wz = 7.0 * (xl + 1.0), 7.0 * wl                   # gz in [0, 14]
    Gz, wG = xh / np.sqrt(2.0), wh / np.sqrt(2.0)         # weight exp(-2 Gz^2)
    # the transverse grid: d - 1 components of c1, then d - 1 of c2
    n = 2 * (D - 1)
    X = np.stack(np.meshgrid(*[xh] * n, indexing="ij"), -1).reshape(-1, n)
    W = np.prod(np.stack(np.meshgrid(*[wh] * n, indexing="ij"), -1).reshape(-1, n), axis=1)
    t1 = (X[:, :D - 1]**2).sum(1)
    t2 = (X[:, D - 1:]**2).sum(1)
    keys = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]
    acc = {(p, k): 0.0 for p in (2, 4, 6) for k in keys}
    for G, wg in zip(Gz, wG):
        for g, wgz in zip(zg, wz):
            z1, z2 = G + g / 2, G - g / 2
            z1p, z2p = G - alpha_val * g / 2, G + alpha_val * g / 2
            x1, x2 = t1 + z1 * z1, t2 + z2 * z2
            y1, y2 = t1 + z1p * z1p, t2 + z2p * z2p
            w = {(0, 0): 1.0, (1, 0): S2n(x1) + S2n(x2), (0, 1): S3n(x1) + S3n(x2), (2, 0): S2n(x1) * S2n(x2),
                 (1, 1): S2n(x1) * S3n(x2) + S3n(x1) * S2n(x2), (0, 2): S3n(x1) * S3n(x2)}
            base = W * (wg * wgz * g * np.exp(-g * g / 2))
            for p in (2, 4, 6):
                h = p // 2
                delta = y1**h + y2**h - x1**h - x2**h
                for k in keys:
                    acc[(p, k)] += float(np.sum(base * w[k] * delta))
    # measure: -(1/2) * S_d * pi^-d * (dc1 dc2 = dG dg) ; transverse weights carry exp(-c^2)
    pref = -0.5 * SURFACE / np.pi**D / np.sqrt(2 * np.pi)
    return {k: pref * v for k, v in acc.items()}


alpha, a2, a3 = sp.symbols("alpha a2 a3")


def to_sympy(d):
    return sp.expand(sum(sp.Rational(v.numerator, v.denominator) * alpha**k[0] * a2**k[1] * a3**k[2]
                         for k, v in d.items()))


def main():
    t0 = time.time()
    # Sonine normalisation checks: <c^4>, <c^6> for F = phi (1 + a2 S2 + a3 S3)
    print(f"d = {D}")
    c = sp.symbols("c", positive=True)
    x = c**2
    d = sp.Integer(D)
    phi = sp.pi**(-d / 2) * sp.exp(-x)
    S2s = x**2 / 2 - (d + 2) / 2 * x + d * (d + 2) / 8
    S3s = -x**3 / 6 + (d + 4) / 4 * x**2 - (d + 2) * (d + 4) / 8 * x + d * (d + 2) * (d + 4) / 48
    surface = 2 * sp.pi**(d / 2) / sp.gamma(d / 2)
    kappa = surface * sp.pi**(-d) * (sp.pi / 2)**(d / 2) * (2 * sp.pi)**((d - 1) / 2) / (2 * sp.sqrt(2 * sp.pi))
    print("kappa_d =", sp.simplify(kappa), "  == KAPPA:", sp.simplify(kappa - KAPPA) == 0)
    F = phi * (1 + a2 * S2s + a3 * S3s)
    mom = lambda n: sp.simplify(sp.integrate(surface * c**(d - 1) * c**n * F, (c, 0, sp.oo)))
    print("<1>   =", mom(0))
    print("<c^2> =", mom(2))
    print("<c^4> =", sp.factor(mom(4)))
    print("<c^6> =", sp.factor(mom(6)))
    print("<c^8> =", sp.expand(mom(8)))

    mu = {}
    for p in (2, 4, 6):
        mu[p] = sp.collect(to_sympy(collision_moment(p)), [a2, a3])
        print(f"\nmu_{p}/sqrt(2 pi) =")
        poly = sp.Poly(mu[p], a2, a3)
        for mon, cf in sorted(poly.terms()):
            print(f"  a2^{mon[0]} a3^{mon[1]}:  {sp.factor(cf)}")
        sys.stdout.flush()
    print(f"(moments: {time.time() - t0:.1f} s)")

    # ---- HCS equations: mu_p = (p/d) mu_2 <c^p>
    c4 = d * (d + 2) / 4 * (1 + a2)
    c6 = d * (d + 2) * (d + 4) / 8 * (1 + 3 * a2 - a3)
    E4 = sp.expand(mu[4] - 4 / d * mu[2] * c4)
    E6 = sp.expand(mu[6] - 6 / d * mu[2] * c6)

    def lin(e, vars_):
        P = sp.Poly(e, *vars_)
        return sum(cf * sp.prod([v**k for v, k in zip(vars_, mon)]) for mon, cf in P.terms() if sum(mon) <= 1)

    # (0) linear first Sonine (van Noije & Ernst)
    E4_1 = E4.subs(a3, 0)
    l = sp.Poly(lin(E4_1, [a2]), a2)
    a2_lin = sp.factor(-l.coeff_monomial(1) / l.coeff_monomial(a2))
    vne = 16 * (1 - alpha) * (1 - 2 * alpha**2) / (9 + 24 * d - alpha * (41 - 8 * d) + 30 * alpha**2 * (1 - alpha))
    print("\nlinear first Sonine a2 =", a2_lin, "   == vNE:", sp.simplify(a2_lin - vne) == 0)

    # (1) nonlinear first Sonine: E4(a2, a3=0) = 0 exactly (cubic in a2)
    P1 = sp.Poly(E4_1, a2)
    print("\nnonlinear first-Sonine equation E4(a2)/sqrt(2pi), coefficients of a2^k:")
    for k in range(P1.degree(), -1, -1):
        print(f"  a2^{k}: {sp.factor(P1.coeff_monomial(a2**k))}")

    # (2) linear second Sonine
    L4 = sp.Poly(lin(E4, [a2, a3]), a2, a3)
    L6 = sp.Poly(lin(E6, [a2, a3]), a2, a3)
    print("\nlinear second-Sonine system  A_p + B_p a2 + C_p a3 = 0:")
    for name, L in (("p=4", L4), ("p=6", L6)):
        print(f"  {name}: A = {sp.factor(L.coeff_monomial(1))}")
        print(f"        B = {sp.factor(L.coeff_monomial(a2))}")
        print(f"        C = {sp.factor(L.coeff_monomial(a3))}")
    sol = sp.solve([L4.as_expr(), L6.as_expr()], [a2, a3], dict=True)[0]
    print("  a2 =", sp.factor(sol[a2]))
    print("  a3 =", sp.factor(sol[a3]))

    den = sp.Poly(sp.denom(sp.factor(sol[a2])), alpha)
    print("  real roots of the denominator:", [float(r) for r in sp.real_roots(den)], "(none in [0, 1] => regular)")

    # table
    print("\nalpha  a2_vNE      a2_NL1      a2_NL1q     a2_2S(lin)  a3_2S(lin)  a2_2S(NL)   a3_2S(NL)"
          "   zeta*/zeta*_M (2S lin)")
    P1q = sp.Poly(E4_1 - P1.coeff_monomial(a2**3) * a2**3, a2)   # drop the a2^3 term only
    # "ratio" variant: mu_p / mu_2 = (p/3) <c^p> linearised (differs from the E_p linearisation at O(a^2))
    t = sp.symbols("t")

    def linearise(e, vars_):
        return sp.series(e.subs({v: t * v for v in vars_}), t, 0, 2).removeO().subs(t, 1)
    R4 = mu[4] / mu[2] - 4 / d * c4
    R6 = mu[6] / mu[2] - 6 / d * c6
    ratio_rows = []
    for av in [sp.Rational(k, 10) for k in range(1, 10)]:
        alin = float(a2_lin.subs(alpha, av))

        def near_root(P):
            roots = sp.Poly(P.as_expr().subs(alpha, av), a2).nroots(n=30)
            real = [complex(r).real for r in roots if abs(complex(r).imag) < 1e-20]
            return min(real, key=lambda r: abs(r - alin)), sorted(real)
        anl, allr = near_root(P1)
        anq, _ = near_root(P1q)
        s2 = float(sol[a2].subs(alpha, av)); s3 = float(sol[a3].subs(alpha, av))
        nl = sp.nsolve([E4.subs(alpha, av), E6.subs(alpha, av)], [a2, a3], [s2, s3], prec=30)
        ratio = float((mu[2].subs({alpha: av, a2: s2, a3: s3}) / mu[2].subs({alpha: av, a2: 0, a3: 0})))
        print(f"{float(av):.1f}  {alin: .8f} {anl: .8f} {anq: .8f} {s2: .8f} {s3: .8f} {float(nl[0]): .8f}"
              f" {float(nl[1]): .8f} {ratio:.8f}   (cubic real roots: {', '.join(f'{r:.4g}' for r in allr)})")
        r1 = sp.solve(linearise(R4.subs({alpha: av, a3: 0}), [a2]), a2)[0]
        r2 = sp.solve([linearise(R4.subs(alpha, av), [a2, a3]), linearise(R6.subs(alpha, av), [a2, a3])], [a2, a3])
        ratio_rows.append((float(av), float(r1), float(r2[a2]), float(r2[a3])))
    print("\nratio-linearised variants:  alpha  a2_1S(ratio)  a2_2S(ratio)  a3_2S(ratio)")
    for row in ratio_rows:
        print(f"  {row[0]:.1f}  {row[1]: .8f}  {row[2]: .8f}  {row[3]: .8f}")


if __name__ == "__main__":
    if "--quad" in sys.argv:
        for av in [sp.Rational(k, 20) for k in (1, 4, 6, 9, 12, 16, 18, 20)]:
            q = quadrature_check(float(av))
            worst = 0.0
            for p in (2, 4, 6):
                exact = sp.Poly(to_sympy(collision_moment(p)).subs(alpha, av), a2, a3)
                for (i, j) in [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]:
                    ex = float(exact.coeff_monomial(a2**i * a3**j))
                    worst = max(worst, abs(q[(p, (i, j))] - ex))
                    print(f"alpha={float(av)} mu_{p} a2^{i} a3^{j}: exact {ex: .15f}"
                          f"  quadrature {q[(p, (i, j))]: .15f}")
            print(f"alpha={float(av)}: largest |quadrature - exact| = {worst:.2e}")
    elif "--mc" in sys.argv:
        for av in (sp.Rational(4, 5), sp.Rational(3, 10)):
            mcres = monte_carlo_check(float(av))
            worst = 0.0
            for p in (2, 4, 6):
                exact = sp.Poly(to_sympy(collision_moment(p)).subs(alpha, av), a2, a3)
                for (i, j) in [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]:
                    ex = float(exact.coeff_monomial(a2**i * a3**j))
                    m, e = mcres[(p, (i, j))]
                    worst = max(worst, abs(m - ex) / e)
                    print(f"alpha={float(av)} mu_{p} a2^{i} a3^{j}: exact {ex: .6f}  MC {m: .6f} +- {e:.6f}"
                          f"  z = {(m - ex) / e: .2f}")
            print(f"alpha={float(av)}: largest |z| = {worst:.2f}")
    else:
        main()
