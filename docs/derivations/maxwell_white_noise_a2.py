#!/usr/bin/env python3
"""The exact steady a2 of Maxwell pseudomolecules heated by white noise (001's kernel B = rate, e uniform,
collision rule 001 eq. 4), in closed form.  Derivation: docs/derivations/maxwell-white-noise-a2.md.

Run with /usr/bin/python3 (needs sympy).  Prints a2(alpha) and checks it at alpha = 1/2 (2/23).
"""
import sympy as sp

alpha = sp.symbols("alpha")
a, b = (1 - alpha) / 4, (1 + alpha) / 4  # v' = c + a u + b |u| e, c = (v + w)/2, u = v - w
s = a**2 + b**2
half = sp.Rational(1, 2)
# |v'|^2 = X + Y, X = |c|^2 + s |u|^2 + 2 a c.u, Y = 2 b |u| (c + a u).e;  with p = |v|^2, q = |w|^2,
# r = v.w: X = x1 p + x2 q + x3 r
x1, x2, x3 = sp.Rational(1, 4) + s + a, sp.Rational(1, 4) + s - a, half - 2 * s
# |c + a u|^2 = y1 p + y2 q + y3 r
y1, y2, y3 = (half + a) ** 2, (half - a) ** 2, 2 * (sp.Rational(1, 4) - a**2)
# E over e: E Y = 0, E Y^2 = (4 b^2 / 3) |u|^2 |c + a u|^2.  E over v, w independent and isotropic:
# E p = m2, E p^2 = m4, E pq = m2^2, E r = E pr = 0, E r^2 = m2^2 / 3.
# E |v'|^4 = A m4 + B m2^2:
A = x1**2 + x2**2 + 4 * b**2 / 3 * (y1 + y2)
B = 2 * x1 * x2 + x3**2 / 3 + 4 * b**2 / 3 * ((y1 + y2) - 2 * y3 / 3)
# d m4/dt = 20 beta m2 + nu (E|v'|^4 - m4) = 0, with the steady m2 = 24 beta / (nu (1 - alpha^2)) from
# E |v'|^2 = m2 (3 + alpha^2) / 4 and d m2/dt = 6 beta - nu (1 - alpha^2) m2 / 4.
ratio = (B + sp.Rational(5, 6) * (1 - alpha**2)) / (1 - A)  # m4 / m2^2
a2 = sp.factor(sp.simplify(sp.Rational(3, 5) * ratio - 1))
print("a2(alpha) =", a2)
expected = 2 * (1 - alpha) ** 2 * (1 + alpha) / (13 - 9 * alpha + alpha**2 - alpha**3)
assert sp.simplify(a2 - expected) == 0
assert a2.subs(alpha, sp.Rational(1, 2)) == sp.Rational(2, 23)
print("a2(1/2) =", a2.subs(alpha, sp.Rational(1, 2)), "=", float(a2.subs(alpha, sp.Rational(1, 2))))
