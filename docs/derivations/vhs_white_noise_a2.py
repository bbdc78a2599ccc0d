#!/usr/bin/env python3
"""The first-Sonine steady a2 of 001's kernel B = rate |u|^lambda with e uniform on the sphere or circle (Maxwell,
VHS; collision rule 001 eq. 4) heated by white noise, in d dimensions, in closed form.  Derivation:
docs/derivations/vhs-white-noise-a2.md.

Run with /usr/bin/python3 (needs sympy).  Prints a2(alpha, lambda, d) and checks its two exact limits: lambda = 0
is the exact a2 of Maxwell pseudomolecules (docs/derivations/maxwell-white-noise-a2.md), and lambda = 1, d = 3 is
van Noije and Ernst's hard-sphere a2 (001's hard spheres scatter e uniformly: docs/physics.md).
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

# 001 eq. (4): u' = a u + b |u| e, a = (1 - alpha)/2, b = (1 + alpha)/2, G' = G; averaged over e uniform on
# S^(d-1): E mu = 0, E mu^2 = 1/d (mu = u-hat.e), E (G.e) = 0, E (G.e)^2 = |G|^2 / d.
a, b = (1 - alpha) / 2, (1 + alpha) / 2
u2_after = Y * (a**2 + b**2)  # E |u'|^2
u4_after = Y**2 * ((a**2 + b**2) ** 2 + 4 * a**2 * b**2 / d)  # E |u'|^4
Gu2_after = a**2 * Z + b**2 * Y * X / d  # E (G.u')^2
# |c1|^2 + |c2|^2 = 2 X + |u|^2 / 2;  |c1|^4 + |c2|^4 = 2 (X + |u|^2/4)^2 + 2 (G.u)^2
delta2 = (u2_after - Y) / 2
delta4 = 2 * (X**2 + X * u2_after / 2 + u4_after / 16 - (X + Y / 4) ** 2) + 2 * (Gu2_after - Z)


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
