#!/usr/bin/env python3
"""The first-Sonine steady a2 of 001's kernel B = rate |u|^lambda with e uniform on the sphere or circle (Maxwell,
VHS; collision rule 001 eq. 4) heated by white noise, in d dimensions, in closed form.  Derivation:
docs/methods/derivations/vhs-white-noise-a2.md.

Run with /usr/bin/python3 (needs sympy).  Prints a2(alpha, lambda, d) and checks its two exact limits: lambda = 0
is the exact a2 of Maxwell pseudomolecules (docs/methods/derivations/maxwell-white-noise-a2.md), and lambda = 1, d = 3 is
van Noije and Ernst's hard-sphere a2 (001's hard spheres scatter e uniformly: docs/methods/physics.md).  Then the second
Sonine approximation, linear in (a2, a3) as theory::second_sonine_linear does it for hard cores: a table, its
values at alpha = 1/2 as exact rationals, and its checks (lambda = 1, d = 3 is the hard spheres' linear second
Sonine of docs/methods/derivations/sonine-hcs.md, "White noise"; lambda = 0 keeps the exact a2).
"""
import sympy as sp

alpha, lam, d, a2 = sp.symbols("alpha lambda d a2")
X, Y, C = sp.symbols("X Y C", nonnegative=True)  # |G|^2, |u|^2, cos^2 of the angle between G and u

# Scaled velocities c = v / v0, v0 = sqrt(2 T / m), unit mass: F = phi (1 + a2 S2(c^2)), phi = pi^(-d/2) e^(-c^2).
# A pair c1 = G + u/2, c2 = G - u/2: phi(c1) phi(c2) ~ e^(-2 G^2 - u^2 / 2), so G and u are independent Gaussians
# with variances 1/4 and 1 per component.  With Z = (G.u)^2 = X Y C:
Z = X * Y * C
S2 = lambda x2, x4: x4 / 2 - (d + 2) * x2 / 2 + d * (d + 2) / 8  # S2(x) as a function of x and x^2
# S2(c1^2) + S2(c2^2): c1^2 + c2^2 = 2X + Y/2, c1^4 + c2^4 = 2 (X + Y/4)^2 + 2 Z
S = S2(2 * X + Y / 2, 2 * (X + Y / 4) ** 2 + 2 * Z) + d * (d + 2) / 8  # S2 sums two constants
# S3(x) = -x^3/6 + (d + 4) x^2/4 - (d + 2)(d + 4) x/8 + d (d + 2)(d + 4)/48, so <c^6> = (d (d+2) (d+4) / 8) (1 + 3 a2
# - a3); with Q = X + Y/4, c1^2 = Q + G.u, c2^2 = Q - G.u and c1^6 + c2^6 = 2 Q^3 + 6 Q Z:
Q = X + Y / 4
S3 = (-(2 * Q**3 + 6 * Q * Z) / 6 + (d + 4) * (2 * Q**2 + 2 * Z) / 4 - (d + 2) * (d + 4) * 2 * Q / 8
      + d * (d + 2) * (d + 4) / 24)

# 001 eq. (4): u' = a u + b |u| e, a = (1 - alpha)/2, b = (1 + alpha)/2, G' = G; averaged over e uniform on
# S^(d-1): E mu = 0, E mu^2 = 1/d (mu = u-hat.e), E (G.e) = 0, E (G.e)^2 = |G|^2 / d.
a, b = (1 - alpha) / 2, (1 + alpha) / 2
u2_after = Y * (a**2 + b**2)  # E |u'|^2
u4_after = Y**2 * ((a**2 + b**2) ** 2 + 4 * a**2 * b**2 / d)  # E |u'|^4
Gu2_after = a**2 * Z + b**2 * Y * X / d  # E (G.u')^2
# |c1|^2 + |c2|^2 = 2 X + |u|^2 / 2;  |c1|^4 + |c2|^4 = 2 (X + |u|^2/4)^2 + 2 (G.u)^2
delta2 = (u2_after - Y) / 2
delta4 = 2 * (X**2 + X * u2_after / 2 + u4_after / 16 - (X + Y / 4) ** 2) + 2 * (Gu2_after - Z)
# For the sixth moment also E |u'|^6 and E |u'|^2 (G.u')^2 (E mu^3 = 0, E mu Gamma = (G.u) / (|u| d), E mu Gamma^2 =
# 0 with Gamma = G.e), and c1'^6 + c2'^6 = 2 Q'^3 + 6 Q' Z' with Q' = X + |u'|^2 / 4, Z' = (G.u')^2:
s_ab = a**2 + b**2
u6_after = Y**3 * (s_ab**3 + 12 * s_ab * a**2 * b**2 / d)
u2Gu2_after = Y * (s_ab * a**2 * Z + s_ab * b**2 * Y * X / d + 4 * a**2 * b**2 * Z / d)
delta6 = (2 * (X**3 + 3 * X**2 * u2_after / 4 + 3 * X * u4_after / 16 + u6_after / 64)
          + 6 * (X * Gu2_after + u2Gu2_after / 4) - (2 * Q**3 + 6 * Q * Z))


def average(expr):
    """E over the pair, weighted by |u|^lambda, up to a factor common to every term: X^i Y^j C^k averages to
    E|G|^(2i) E|u|^(lambda + 2j) / E|u|^lambda E[cos^(2k)] with the rising factorials of the Gamma functions."""
    poly = sp.Poly(sp.expand(expr), X, Y, C)
    total = 0
    for (i, j, k), coefficient in poly.terms():
        g = sp.Rational(1, 2) ** i * sp.rf(d / 2, i)
        u = 2**j * sp.rf((d + lam) / 2, j)
        c = sp.rf(sp.Rational(1, 2), k) / sp.rf(d / 2, k)
        total += coefficient * g * u * c
    return sp.simplify(total)


def average_expanded(expr):
    """average() without the final simplification (the second Sonine's terms are larger)."""
    poly = sp.Poly(sp.expand(expr), X, Y, C)
    return sp.expand(sum(coefficient * sp.Rational(1, 2) ** i * sp.rf(d / 2, i) * 2**j * sp.rf((d + lam) / 2, j)
                         * sp.rf(sp.Rational(1, 2), k) / sp.rf(d / 2, k) for (i, j, k), coefficient in poly.terms()))


# Moments of the collision term, to first order in a2: A_p = -(1/2) E[|u|^lambda Delta_p (1 + a2 S)] (a common
# factor aside).  White noise: d/dt <|v|^(2p)> gains beta 2p (2p + d - 2) <|v|^(2p - 2)>, so the steady state has
# A_2 proportional to 2 d beta and A_4 to 4 (d + 2) beta <c^2> = 2 d (d + 2) beta: A_4 = (d + 2) A_2.
A2 = [average(-delta2 / 2), average(-delta2 * S / 2)]
A4 = [average(-delta4 / 2), average(-delta4 * S / 2)]
solution = sp.factor(sp.simplify(-(A4[0] - (d + 2) * A2[0]) / (A4[1] - (d + 2) * A2[1])))
print("a2(alpha, lambda, d) =", solution)
numerator, denominator = sp.fraction(solution)
print("numerator   =", sp.factor(numerator))
print("denominator =", sp.collect(sp.expand(denominator), [lam, d]))

maxwell = 2 * (d + 1) * (1 - alpha) ** 2 * (1 + alpha) / (
    19 * d - 5 - (11 * d + 3) * alpha + (d + 1) * (alpha**2 - alpha**3))
assert sp.simplify(solution.subs(lam, 0) - maxwell) == 0, "lambda = 0 is not the exact Maxwell a2"
hard_spheres = 16 * (1 - alpha) * (1 - 2 * alpha**2) / (241 - 177 * alpha + 30 * (1 - alpha) * alpha**2)
assert sp.simplify(solution.subs({lam: 1, d: 3}) - hard_spheres) == 0, "lambda = 1, d = 3 is not van Noije-Ernst"
print("checks: lambda = 0 gives the exact Maxwell a2; lambda = 1, d = 3 van Noije and Ernst's hard-sphere a2")
for dd in (3, 2):
    for ll in (sp.Rational(1, 4), sp.Rational(1, 2), 1):
        for aa in (sp.Rational(1, 10), sp.Rational(1, 2), sp.Rational(9, 10)):
            value = solution.subs({d: dd, lam: ll, alpha: aa})
            print(f"d = {dd}, lambda = {ll}, alpha = {aa}: a2 = {sp.nsimplify(value)} = {float(value):.6f}")

# The second Sonine, F = phi (1 + a2 S2 + a3 S3), linear in (a2, a3): A_p = A_p0 + a2 A_p2 + a3 A_p3 with
# A_pq = -(1/2) E[|u|^lambda Delta_p S_q-sum].  White noise adds to d/dt <|v|^6> the term beta 6 (d + 4) <|v|^4>, so
# A_6 = (3/4)(d + 2)(d + 4) A_2 (1 + a2), linearised (docs/methods/derivations/sonine-hcs.md, "White noise": E4, E6).
def moment_terms(delta):
    return [average_expanded(-delta / 2), average_expanded(-delta * S / 2), average_expanded(-delta * S3 / 2)]


M2, M4, M6 = moment_terms(delta2), moment_terms(delta4), moment_terms(delta6)
k6 = sp.Rational(3, 4) * (d + 2) * (d + 4)
E4 = [M4[q] - (d + 2) * M2[q] for q in range(3)]
E6 = [M6[0] - k6 * M2[0], M6[1] - k6 * (M2[1] + M2[0]), M6[2] - k6 * M2[2]]


def second_sonine(values):
    """(a2, a3) of the linear second Sonine at the given d, lambda, alpha (exact rationals), by Cramer's rule."""
    e4 = [sp.cancel(x.subs(values)) for x in E4]
    e6 = [sp.cancel(x.subs(values)) for x in E6]
    det = e4[1] * e6[2] - e4[2] * e6[1]
    return sp.cancel((e4[2] * e6[0] - e4[0] * e6[2]) / det), sp.cancel((e4[0] * e6[1] - e4[1] * e6[0]) / det)


# lambda = 1, d = 3: the hard spheres' linear second Sonine (docs/methods/derivations/sonine-hcs.md's table, 5 decimals).
for aa, (h2, h3) in ((sp.Rational(1, 10), (0.06154, -0.00791)), (sp.Rational(1, 2), (0.02492, -0.00332)),
                     (sp.Rational(4, 5), (-0.00938, -0.00321)), (sp.Rational(9, 10), (-0.01246, -0.00291))):
    v2, v3 = second_sonine({d: 3, lam: 1, alpha: aa})
    assert abs(float(v2) - h2) < 6e-6 and abs(float(v3) - h3) < 6e-6, (aa, float(v2), float(v3))
for aa in (sp.Rational(1, 10), sp.Rational(1, 2), sp.Rational(9, 10)):  # lambda = 0: a2 stays the exact one
    for dd in (2, 3):
        assert second_sonine({d: dd, lam: 0, alpha: aa})[0] == solution.subs({d: dd, lam: 0, alpha: aa})
print("checks: lambda = 1, d = 3 gives the hard spheres' linear second Sonine; lambda = 0 keeps the exact a2")
print("| d | lambda | alpha | a2 1S | a2 2S | a3 2S | a2 2S - a2 1S |")
print("|---|---|---|---|---|---|---|")
for dd in (2, 3):
    for ll in (sp.Rational(1, 2), 1):
        for aa in (sp.Rational(1, 10), sp.Rational(1, 2), sp.Rational(4, 5), sp.Rational(9, 10)):
            first = solution.subs({d: dd, lam: ll, alpha: aa})
            v2, v3 = second_sonine({d: dd, lam: ll, alpha: aa})
            print(f"| {dd} | {ll} | {aa} | {float(first):.5f} | {float(v2):.5f} | {float(v3):.5f} | "
                  f"{float(v2 - first):+.5f} |")
for dd in (2, 3):
    v2, v3 = second_sonine({d: dd, lam: sp.Rational(1, 2), alpha: sp.Rational(1, 2)})
    print(f"d = {dd}, lambda = 1/2, alpha = 1/2: a2 = {v2}, a3 = {v3}")
