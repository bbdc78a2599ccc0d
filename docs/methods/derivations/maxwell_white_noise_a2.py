#!/usr/bin/env python3
"""The exact steady a2 of Maxwell pseudomolecules heated by white noise (001's kernel B = rate, e uniform on the
sphere or circle, collision rule 001 eq. 4) in d dimensions, in closed form.  Derivation:
docs/methods/derivations/maxwell-white-noise-a2.md.

Run with /usr/bin/python3 (needs sympy).  Prints a2(alpha, d) and checks it for spheres (2/23 at alpha = 1/2)
and disks (18/167).
"""
import sympy as sp

alpha, d = sp.symbols("alpha d", positive=True)
a, b = (1 - alpha) / 4, (1 + alpha) / 4  # v' = c + a u + b |u| e, c = (v + w)/2, u = v - w
s = a**2 + b**2
half = sp.Rational(1, 2)
# |v'|^2 = X + Y, X = |c|^2 + s |u|^2 + 2 a c.u, Y = 2 b |u| (c + a u).e;  with p = |v|^2, q = |w|^2,
# r = v.w: X = x1 p + x2 q + x3 r
x1, x2, x3 = sp.Rational(1, 4) + s + a, sp.Rational(1, 4) + s - a, half - 2 * s
# |c + a u|^2 = y1 p + y2 q + y3 r
y1, y2, y3 = (half + a) ** 2, (half - a) ** 2, 2 * (sp.Rational(1, 4) - a**2)
# E over e uniform on the unit sphere of R^d: E Y = 0, E Y^2 = (4 b^2 / d) |u|^2 |c + a u|^2.  E over v, w
# independent and isotropic: E p = m2, E p^2 = m4, E pq = m2^2, E r = E pr = 0, E r^2 = m2^2 / d.
# E |v'|^4 = A m4 + B m2^2:
A = x1**2 + x2**2 + 4 * b**2 / d * (y1 + y2)
B = 2 * x1 * x2 + x3**2 / d + 4 * b**2 / d * ((y1 + y2) - 2 * y3 / d)
# d m4/dt = 4 (d + 2) beta m2 + nu (E|v'|^4 - m4) = 0 (Lap |v|^4 = 4 (d + 2) |v|^2), with the steady
# m2 = 8 d beta / (nu (1 - alpha^2)) from E |v'|^2 = m2 (3 + alpha^2) / 4 and d m2/dt = 2 d beta - nu (1 - alpha^2) m2 / 4.
ratio = (B + 4 * (d + 2) * (1 - alpha**2) / (8 * d)) / (1 - A)  # m4 / m2^2
a2 = sp.factor(sp.simplify(d / (d + 2) * ratio - 1))  # <|v|^4> = (d + 2)/d m2^2 (1 + a2)
print("a2(alpha, d) =", a2)
expected = (
    2 * (d + 1) * (1 - alpha) ** 2 * (1 + alpha)
    / (19 * d - 5 - (11 * d + 3) * alpha + (d + 1) * (alpha**2 - alpha**3))
)
assert sp.simplify(a2 - expected) == 0
spheres = sp.simplify(a2.subs(d, 3))
assert sp.simplify(spheres - 2 * (1 - alpha) ** 2 * (1 + alpha) / (13 - 9 * alpha + alpha**2 - alpha**3)) == 0
assert spheres.subs(alpha, half) == sp.Rational(2, 23)
disks = sp.simplify(a2.subs(d, 2))
assert sp.simplify(disks - 6 * (1 - alpha) ** 2 * (1 + alpha) / (33 - 25 * alpha + 3 * alpha**2 - 3 * alpha**3)) == 0
assert disks.subs(alpha, half) == sp.Rational(18, 167)
print("spheres: a2(1/2) =", spheres.subs(alpha, half), "=", float(spheres.subs(alpha, half)))
print("disks:   a2(1/2) =", disks.subs(alpha, half), "=", float(disks.subs(alpha, half)))
