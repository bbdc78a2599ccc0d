#!/usr/bin/env python3
"""Independent Monte Carlo check of the binary-mixture shear-viscosity collision integrals.

Run:   /usr/bin/python3 docs/methods/derivations/viscosity_mc_check.py [--batches 32] [--nper 1000000] [--seed 20240611]
       (needs numpy and the granmc binary, default build/bin/granmc (run from the repository root), override with GRANMC=/path/to/granmc;
       about 2 minutes of one core with the default 32 batches of 1e6 samples = 3.2e7 samples per integral;
       --batches 16 halves it)

What it checks (docs/methods/derivations/viscosity.md sec. 6 "Binary mixtures", kernel/theory/mixture_viscosity.cpp,
kernel/theory/mixture_hcs.cpp), dilute gas (phi = 0), mu = m1/m2 = 4, delta = n1/n2 = 1,
omega = sigma1/sigma2 in {0.5, 1, 2}, alpha in {1, 0.8, 0.7}:

  * the shear collision integrals l1 (f_i^(1) against f_j^(0)) and l2 (f_i^(0) against f_j^(1)), coefficient
    by coefficient in the cumulants a2, for all four ordered pairs (i, j);
  * the energy moments behind the partial cooling rates zeta_i (and, as a bonus, the fourth moments behind
    the a2_i conditions);
  * the HSS condition zeta_1 = zeta_2 at the gamma = T1/T2 printed by `granmc theory`;
  * the assembled first-Sonine eta_1, eta_2, eta and eta(alpha)/eta(alpha = 1) (Gaussian thermostat, r = 1;
    cooling state r = 1/2 as an extra), against `granmc theory` and a Python transcription of
    mixture_viscosity.cpp.

Nothing here uses the project's formulas for the MC numbers.  The only inputs taken from the project are
gamma and a2_i (from `granmc theory` on a scene without [shear]); the closed forms are re-evaluated in
Python (functions closed_*) ONLY for the comparison columns, and granmc's eta_over_eta_elastic is read from
`granmc theory` on the same scene with [shear].

Monte Carlo, straight from the Boltzmann collision rule (000 eqs. 2, 14).  For the ordered pair (i, j):
v1 ~ N(0, theta_i), v2 ~ N(0, theta_j) (theta = T/m, normalised Maxwellians phi_i, phi_j), sig uniform on the
unit sphere, g = v1 - v2, v1' = v1 - mu_ji (1 + alpha)(g.sig) sig, mu_ji = m_j/(m_i + m_j).  The collision
integral of a function psi over the pair, per n_i n_j sigma_ij^2,

    K[psi] = int dv1 dv2 dsig Theta(g.sig)(g.sig) phi_i phi_j W [psi(v1') - psi(v1)]
           = 4 pi E[Theta(g.sig)(g.sig) W dpsi] = 2 pi E[|g.sig| W dpsi]

(last form: v1' is invariant under sig -> -sig, so the two hemispheres contribute equally; no sample is
wasted).  The first-Sonine weights W = 1 + a S2(x), S2(x) = x^2/2 - 5x/2 + 15/8, x = v^2/(2 theta), are
applied as importance weights: each power of a_i, a_j is estimated separately (S2(x1), S2(x2) multiply the
integrand), so the comparison is per coefficient.

Shear balance (derived here, independently of viscosity.md).  f_i^(1) = -(m_i eta_i a / T_i^2) phi_i V_x V_y
for the shear u_x = a y gives P_i,xy = -eta_i a.  The m_i V_x V_y moment of the kinetic equation with the
Gaussian thermostat (1/2) zeta d/dV.(V f) (moment -zeta P_xy) and streaming n_i T_i a gives
    n_i T_i a + r zeta eta_i a = sum_j int m_i V_x V_y J_ij[f_i^(1), f_j^(0)] + J_ij[f_i^(0), f_j^(1)]
with r = 1 (HSS; the cooling state d_t P = -(zeta/2) P gives r = 1/2).  With
    I1_ij = K[psi = v1x v1y] with weight v1x v1y W_j(v2)     (f_i^(1) x f_j^(0))
    I2_ij = K[psi = v1x v1y] with weight v2x v2y W_i(v1)     (f_i^(0) x f_j^(1))
(averaged over the three off-diagonal planes xy, yz, zx for variance reduction), the right side is
-a [sum_j n_j s_ij^2 I1_ij / theta_i^2] eta_i - a sum_j n_i s_ij^2 (m_i/m_j) I2_ij / theta_j^2 eta_j,
(s_ij = (sigma_i + sigma_j)/2), i.e. the 2x2 system
    sum_j (C_ij - r zeta delta_ij) eta_j = n_i T_i,
    C_ij = delta_ij sum_k (-n_k s_ik^2 I1_ik / theta_i^2) - n_i s_ij^2 (m_i/m_j) I2_ij / theta_j^2.
Relation to the project's notation: L1 = m_i s^5 l1 = (m_i/5) 4 pi E[Theta (g.sig) W_j (D(v1'):D(v1) - D:D)]
and D:D/5 = 2 (V_x V_y)^2 in the isotropic average, so the closed form of I1 is s^5 l1 / 2 (I2: s^5 l2 / 2).
Partial cooling rates: zeta_i = -(m_i / (3 T_i)) sum_j n_j s_ij^2 K2_ij, K2 = K[|v1|^2] with W_i W_j;
total zeta = energy loss rate / ((3/2) n T) = sum_i n_i T_i zeta_i / sum_i n_i T_i.  Like the theory, the
zeta used in the viscosity is first order in a2 (the a_i a_j term is estimated and reported, not used).

Errors: the samples are split in batches; every derived quantity (eta, ratios, zeta_1 - zeta_2) gets a
jackknife error over the batches.  All states use the same random numbers, so ratios are correlated
estimates.  "z" columns are (MC - closed form) / sigma_MC; the +- columns are 2 sigma.  Because every state
uses the same draw, the z of all eta rows move together: with the default seed the whole eta table sits about
+2.5 sigma (+0.1 to +0.3 %) high, including the elastic HCB anchor, which involves no project formula at all;
seeds 7, 11 and 12 give -1.6 to +0.1 sigma, and 30 independent small runs confirmed that the jackknife errors
match the actual run-to-run scatter.
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

GRANMC = os.environ.get("GRANMC", "build/bin/granmc")
MU, DELTA = 4.0, 1.0
OMEGAS = (0.5, 1.0, 2.0)
ALPHAS = (1.0, 0.8, 0.7)
MASS = (MU, 1.0)
DENS = (0.5 * DELTA, 0.5)  # n1 = delta n2; only ratios matter for the dilute gas
SQ2PI = math.sqrt(2 * math.pi)
PAIRS = ((0, 0), (0, 1), (1, 0), (1, 1))
# accumulators per ordered pair: I1 a^0, I1 a_j, I2 a^0, I2 a_i, K2 {1, a_i, a_j, a_i a_j}, K4 {same}
ACC = ["I1", "I1_aj", "I2", "I2_ai", "K2", "K2_ai", "K2_aj", "K2_aiaj", "K4", "K4_ai", "K4_aj", "K4_aiaj"]
NACC = len(ACC)


# ----------------------------------------------------------------------------------------------------------
# granmc theory: gamma, a2_i and eta(alpha)/eta(1)
# ----------------------------------------------------------------------------------------------------------
SCENE = """[run]
method = "dsmc"
seed = 1
replicas = 1
t_end = 1.0
dt = 0.004
samples = 10

[[species]]
name = "one"
mass = {m1}
diameter = {s1}
density = {n1}
particles = 1000

[[species]]
name = "two"
mass = 1.0
diameter = 1.0
density = {n2}
particles = 1000

[collision]
kernel = "hard-sphere"
restitution = {alpha}

[thermostat]
kind = "gaussian"
zeta = "cooling-rate"
"""


def granmc_theory(omega, alpha, tmpdir):
    out = {}
    for shear in (False, True):
        text = SCENE.format(m1=MU, s1=omega, n1=DENS[0], n2=DENS[1], alpha=alpha)
        if shear:
            text += "\n[shear]\nrate = 0.25\n"
        path = os.path.join(tmpdir, f"scene_w{omega}_a{alpha}_{int(shear)}.toml")
        with open(path, "w") as fh:
            fh.write(text)
        res = json.loads(subprocess.run([GRANMC, "theory", path], check=True, capture_output=True, text=True).stdout)
        if shear:
            out["eta_ratio"] = res["viscosity"]["first_sonine"]["eta_over_eta_elastic"]
        else:
            mix = res.get("mixture", {})
            out["gamma"] = mix.get("temperature_ratio_sonine", 1.0)
            out["a2"] = tuple(mix.get("a2_sonine", (0.0, 0.0)))
    if alpha == 1.0:  # elastic: equilibrium, gamma = 1, a2 = 0 exactly
        out["gamma"], out["a2"] = 1.0, (0.0, 0.0)
    return out


# ----------------------------------------------------------------------------------------------------------
# Monte Carlo
# ----------------------------------------------------------------------------------------------------------
def S2(x):
    return 0.5 * x * x - 2.5 * x + 1.875


def offdiag(v):
    return np.stack([v[:, 0] * v[:, 1], v[:, 1] * v[:, 2], v[:, 2] * v[:, 0]], axis=1)


def temperatures(gamma):
    x1 = DENS[0] / (DENS[0] + DENS[1])
    T2 = 1.0 / (x1 * gamma + 1.0 - x1)  # mixture temperature x1 T1 + x2 T2 = 1
    return (gamma * T2, T2)


def mc_batch(Z1, Z2, S, s21, s22, T, alpha):
    """Batch means of the 12 accumulators for the four ordered pairs at temperatures T: array (4, NACC)."""
    out = np.empty((4, NACC))
    for p, (i, j) in enumerate(PAIRS):
        thi, thj = T[i] / MASS[i], T[j] / MASS[j]
        b = MASS[j] / (MASS[i] + MASS[j]) * (1.0 + alpha)
        v1 = math.sqrt(thi) * Z1
        v2 = math.sqrt(thj) * Z2
        gs = np.einsum("ij,ij->i", v1 - v2, S)
        w = 2.0 * math.pi * np.abs(gs)
        v1p = v1 - (b * gs)[:, None] * S
        q1 = offdiag(v1)
        dq = offdiag(v1p) - q1
        I1 = w * np.einsum("ij,ij->i", q1, dq) / 3.0
        I2 = w * np.einsum("ij,ij->i", offdiag(v2), dq) / 3.0
        e1 = np.einsum("ij,ij->i", v1, v1)
        e1p = np.einsum("ij,ij->i", v1p, v1p)
        d2 = w * (e1p - e1)
        d4 = w * (e1p * e1p - e1 * e1)
        Si, Sj = s21, s22  # S2 at v1 (species i) and at v2 (species j), both functions of the standard normals
        vals = [I1.mean(), (I1 * Sj).mean(), I2.mean(), (I2 * Si).mean()]
        for d in (d2, d4):
            dSi = d * Si
            vals += [d.mean(), dSi.mean(), (d * Sj).mean(), (dSi * Sj).mean()]
        out[p] = vals
    return out


def run_mc(states, nbatch, nper, seed):
    """states: list of (gamma, alpha).  Returns batch means, shape (nbatch, nstates, 4, NACC)."""
    rng = np.random.default_rng(seed)
    res = np.empty((nbatch, len(states), 4, NACC))
    t0 = time.time()
    for bi in range(nbatch):
        Z1 = rng.standard_normal((nper, 3))
        Z2 = rng.standard_normal((nper, 3))
        S = rng.standard_normal((nper, 3))
        S /= np.linalg.norm(S, axis=1)[:, None]
        s21 = S2(0.5 * np.einsum("ij,ij->i", Z1, Z1))
        s22 = S2(0.5 * np.einsum("ij,ij->i", Z2, Z2))
        for k, (gamma, alpha) in enumerate(states):
            res[bi, k] = mc_batch(Z1, Z2, S, s21, s22, temperatures(gamma), alpha)
        if bi == 0:
            print(f"# batch 1/{nbatch} took {time.time() - t0:.1f} s", file=sys.stderr, flush=True)
    return res


def jackknife(batches, func):
    """Mean estimate and standard error of func(mean over batches) by leave-one-out jackknife."""
    nb = batches.shape[0]
    full = np.asarray(func(batches.mean(axis=0)), dtype=float)
    tot = batches.sum(axis=0)
    loo = np.array([np.asarray(func((tot - batches[b]) / (nb - 1)), dtype=float) for b in range(nb)])
    err = np.sqrt((nb - 1) / nb * ((loo - loo.mean(axis=0)) ** 2).sum(axis=0))
    return full, err


# ----------------------------------------------------------------------------------------------------------
# Quantities built from the MC integrals (own code)
# ----------------------------------------------------------------------------------------------------------
def sig_ij(omega, i, j):
    d = (omega, 1.0)
    return 0.5 * (d[i] + d[j])


def mc_zetas(A, omega, T, a, bilinear=False):
    """Partial cooling rates zeta_i and total zeta from the K2 accumulators A (4, NACC)."""
    K = ACC.index("K2")
    z = []
    for i in range(2):
        acc = 0.0
        for p, (ii, j) in enumerate(PAIRS):
            if ii != i:
                continue
            k2 = A[p, K] + a[i] * A[p, K + 1] + a[j] * A[p, K + 2] + (a[i] * a[j] * A[p, K + 3] if bilinear else 0.0)
            acc += DENS[j] * sig_ij(omega, i, j) ** 2 * k2
        z.append(-MASS[i] / (3.0 * T[i]) * acc)
    ztot = (DENS[0] * T[0] * z[0] + DENS[1] * T[1] * z[1]) / (DENS[0] * T[0] + DENS[1] * T[1])
    return z[0], z[1], ztot


def mc_eta(A, omega, T, a, r):
    """eta_1, eta_2 from the MC integrals: sum_j (C_ij - r zeta delta_ij) eta_j = n_i T_i."""
    th = (T[0] / MASS[0], T[1] / MASS[1])
    C = np.zeros((2, 2))
    for p, (i, j) in enumerate(PAIRS):
        I1 = A[p, 0] + a[j] * A[p, 1]
        I2 = A[p, 2] + a[i] * A[p, 3]
        s2 = sig_ij(omega, i, j) ** 2
        C[i, i] -= DENS[j] * s2 * I1 / th[i] ** 2
        C[i, j] -= DENS[i] * s2 * (MASS[i] / MASS[j]) * I2 / th[j] ** 2
    zeta = mc_zetas(A, omega, T, a)[2]
    eta = np.linalg.solve(C - r * zeta * np.eye(2), np.array([DENS[0] * T[0], DENS[1] * T[1]]))
    return eta


# ----------------------------------------------------------------------------------------------------------
# Closed forms of the project, re-evaluated in Python (comparison only): mixture_viscosity.cpp, mixture_hcs.cpp
# ----------------------------------------------------------------------------------------------------------
def pair_geom(T, i, j, alpha):
    thi, thj = T[i] / MASS[i], T[j] / MASS[j]
    s2 = thi + thj
    return math.sqrt(s2), thi / s2, thj / s2, MASS[j] / (MASS[i] + MASS[j]) * (1 + alpha)


def closed_integrals(T, i, j, alpha):
    """Closed-form values of the 12 accumulators for the pair (i, j) (per coefficient of a_i, a_j)."""
    s, u, v, b = pair_geom(T, i, j, alpha)
    c = -SQ2PI / 15 * b
    I1 = s**5 / 2 * c * u * u * 8 * (10 + 2 * u - 3 * b)            # l1 = c u^2 [8(10+2u-3b) + a_j v^2 (3b+6u-10)]
    I1a = s**5 / 2 * c * u * u * v * v * (3 * b + 6 * u - 10)
    I2 = s**5 / 2 * c * v * v * 8 * (2 * u - 3 * b)                # l2 = c v^2 [8(2u-3b) + a_i u^2 (3b+6u-8)]
    I2a = s**5 / 2 * c * v * v * u * u * (3 * b + 6 * u - 8)
    d = 2 * u - b
    P2 = (-2 * b * d, b * u * u * (3 * b + 2 * u - 8) / 4, b * v * v * (3 * b + 2 * u) / 4,
          3 * b * u * u * v * v * (3 * b + 10 * u - 8) / 32)
    b2, b3, u2, u3 = b * b, b**3, u * u, u**3
    P4 = (-4 * b * d * (2 * b2 - 4 * b * u + u2 + 5 * u),
          -b * u2 * (-30 * b3 + 24 * b2 * u + 96 * b2 + 9 * b * u2 - 87 * b * u - 132 * b + 6 * u3 - 34 * u2
                     + 128 * u + 80) / 2,
          -b * v * v * (-30 * b3 + 24 * b2 * u + 9 * b * u2 - 15 * b * u + 6 * u3 - 10 * u2) / 2,
          -b * u2 * v * v * (30 * b3 + 72 * b2 * u - 96 * b2 + 135 * b * u2 - 261 * b * u + 132 * b + 210 * u3
                             - 510 * u2 + 384 * u - 80) / 16)
    return np.array([I1, I1a, I2, I2a] + [2 * SQ2PI * s**3 * x for x in P2] + [2 * SQ2PI * s**5 * x for x in P4])


def closed_all(T, alpha):
    return np.array([closed_integrals(T, i, j, alpha) for (i, j) in PAIRS])


def closed_eta(omega, T, a, alpha, r):
    """Python transcription of mixture_shear_viscosity (phi = 0): eta_1^k, eta_2^k; zeta = zeta_1 (linear)."""
    A = closed_all(T, alpha)
    th = (T[0] / MASS[0], T[1] / MASS[1])
    tau = np.zeros((2, 2))
    for i in range(2):
        for j in range(2):
            s, u, v, b = pair_geom(T, i, j, alpha)
            w = sig_ij(omega, i, j) ** 2
            l1 = -SQ2PI / 15 * b * u * u * (8 * (10 + 2 * u - 3 * b) + a[j] * v * v * (3 * b + 6 * u - 10))
            l2 = -SQ2PI / 15 * b * v * v * (8 * (2 * u - 3 * b) + a[i] * u * u * (3 * b + 6 * u - 8))
            tau[i, i] -= DENS[j] * w * s**5 * l1 / (2 * th[i] ** 2)
            tau[i, j] -= DENS[i] * w * MASS[i] * s**5 * l2 / (2 * MASS[j] * th[j] ** 2)
    zeta = mc_zetas(A, omega, T, a)[0]  # closed-form K2 fed into the same zeta_1 formula = partial_cooling_rate
    return np.linalg.solve(tau - r * zeta * np.eye(2), np.array([DENS[0] * T[0], DENS[1] * T[1]]))


def hcb_elastic(omega):
    """Elastic dilute binary mixture, T = 1, first Chapman-Cowling approximation for rigid spheres
    (Hirschfelder, Curtiss & Bird 1954, eqs. 8.2-22 to 8.2-25 with A* = 1), written out here from the book:
    eta = x^T H^-1 x, [eta_ij] = (5/16) sqrt(2 pi m_i m_j T/(m_i + m_j)) / (pi sigma_ij^2),
    H_ii = x_i^2/[eta_i] + 2 x_i x_k/[eta_ik] m_i m_k/(m_i + m_k)^2 (5/3 + m_k/m_i),
    H_ik = -2 x_i x_k/[eta_ik] m_i m_k/(m_i + m_k)^2 (5/3 - 1)."""
    x = np.array(DENS) / sum(DENS)
    e = lambda i, j: 5 / 16 * math.sqrt(2 * math.pi * MASS[i] * MASS[j] / (MASS[i] + MASS[j])) / (
        math.pi * sig_ij(omega, i, j) ** 2)
    H = np.zeros((2, 2))
    for i in range(2):
        k = 1 - i
        f = MASS[i] * MASS[k] / (MASS[i] + MASS[k]) ** 2
        H[i, i] = x[i] ** 2 / e(i, i) + 2 * x[i] * x[k] / e(i, k) * f * (5 / 3 + MASS[k] / MASS[i])
        H[i, k] = -2 * x[i] * x[k] / e(i, k) * f * (5 / 3 - 1)
    return float(x @ np.linalg.solve(H, x))


# ----------------------------------------------------------------------------------------------------------
def fmt(x, e):
    return f"{x:+.5f} +- {2 * e:.5f}"


def zscore(x, e, ref):
    return (x - ref) / e if e > 0 else float("nan")


def main():
    nbatch, nper, seed = 32, 1_000_000, 20240611
    if "--nper" in sys.argv[1:]:
        nper = int(sys.argv[sys.argv.index("--nper") + 1])
    args = sys.argv[1:]
    if "--batches" in args:
        nbatch = int(args[args.index("--batches") + 1])
    if "--seed" in args:
        seed = int(args[args.index("--seed") + 1])

    with tempfile.TemporaryDirectory(dir="/tmp") as tmpdir:
        theory = {(w, al): granmc_theory(w, al, tmpdir) for w in OMEGAS for al in ALPHAS}

    # distinct states (gamma, alpha): alpha = 1 is the same state (gamma = 1) for every omega
    keys = [(1.0, 1.0)] + [(w, al) for w in OMEGAS for al in ALPHAS if al != 1.0]
    states = [(theory[k]["gamma"], k[1]) for k in keys]
    state_of = {(w, al): (0 if al == 1.0 else keys.index((w, al))) for w in OMEGAS for al in ALPHAS}

    print(f"# Monte Carlo: {nbatch} batches x {nper:.0e} samples per integral, seed {seed}; "
          f"mu = {MU}, delta = {DELTA}, phi = 0; granmc = {GRANMC}")
    print("# state from granmc theory:")
    for w in OMEGAS:
        for al in ALPHAS:
            t = theory[(w, al)]
            print(f"#   omega {w:3.1f} alpha {al:3.1f}: gamma = {t['gamma']:.6f}, a2 = ({t['a2'][0]:+.6f}, "
                  f"{t['a2'][1]:+.6f}), granmc eta/eta(1) = {t['eta_ratio']:.6f}")
    t0 = time.time()
    R = run_mc(states, nbatch, nper, seed)
    print(f"# MC time {time.time() - t0:.0f} s")

    # ---------------- 1. per-integral comparison ----------------
    print("\n## 1. Collision integrals per ordered pair (i, j) = (species, partner), species 1 = heavy (m = 4)")
    print("##    I1: f_i^(1) x f_j^(0) = s^5 l1/2;  I2: f_i^(0) x f_j^(1) = s^5 l2/2;  K2, K4: energy and v^4 "
          "moments (2 sqrt(2pi) s^(p+1) P_p)")
    print("##    closed form = Python re-evaluation of the formulas in mixture_viscosity.cpp / mixture_hcs.cpp")
    allz = []
    detail = {(0.5, 0.7)}
    for k, key in enumerate(keys):
        gamma, al = states[k]
        T = temperatures(gamma)
        ref = closed_all(T, al)
        mean = R[:, k].mean(axis=0)
        err = R[:, k].std(axis=0, ddof=1) / math.sqrt(nbatch)
        z = (mean - ref) / err
        allz.append(z.ravel())
        if key in detail:
            print(f"\n### omega = {key[0]}, alpha = {al}, gamma = {gamma:.6f}, T = ({T[0]:.6f}, {T[1]:.6f})")
            print("| pair (i,j) | integral | MC +- 2 sigma | closed form | z (sigma) |")
            print("|---|---|---|---|---|")
            for p, (i, j) in enumerate(PAIRS):
                for c, name in enumerate(ACC):
                    print(f"| ({i + 1},{j + 1}) | {name} | {fmt(mean[p, c], err[p, c])} | {ref[p, c]:+.5f} | "
                          f"{z[p, c]:+.2f} |")
    allz = np.concatenate(allz)
    fin = np.isfinite(allz)
    print(f"\nAll {len(keys)} states x 4 pairs x {NACC} coefficients = {fin.sum()} comparisons: "
          f"max |z| = {np.abs(allz[fin]).max():.2f}, mean z^2 = {np.mean(allz[fin] ** 2):.2f} (expect ~1)")
    for k, key in enumerate(keys):
        gamma, al = states[k]
        ref = closed_all(temperatures(gamma), al)
        mean = R[:, k].mean(axis=0)
        err = R[:, k].std(axis=0, ddof=1) / math.sqrt(nbatch)
        zz = ((mean - ref) / err)[:, :4]
        label = "alpha=1.0 (gamma = 1, every omega)" if al == 1.0 else f"omega={key[0]:3.1f} alpha={al:3.1f}"
        print(f"  state {label}: shear integrals I1, I1_aj, I2, I2_ai max |z| = "
              f"{np.abs(zz).max():.2f};  all 12: max |z| = {np.abs((mean - ref) / err).max():.2f}")

    # ---------------- 2. cooling rates and the HSS condition ----------------
    print("\n## 2. Cooling rates at the granmc state (first order in a2 as in the theory)")
    print("| omega | alpha | zeta_1 MC | zeta_2 MC | zeta_1 - zeta_2 MC | (z1-z2)/zeta | zeta MC (total) | "
          "zeta closed (zeta_1) | z |")
    print("|---|---|---|---|---|---|---|---|---|")
    for k, key in enumerate(keys):
        if key[1] == 1.0:
            continue
        w = key[0]
        gamma, al = states[k]
        T = temperatures(gamma)
        a = theory[key]["a2"]
        B = R[:, k]
        (z1, z2, zt), (e1, e2, et) = jackknife(B, lambda A: mc_zetas(A, w, T, a))
        dz, edz = jackknife(B, lambda A: mc_zetas(A, w, T, a)[0] - mc_zetas(A, w, T, a)[1])
        rz, erz = jackknife(B, lambda A: (mc_zetas(A, w, T, a)[0] - mc_zetas(A, w, T, a)[1]) / mc_zetas(A, w, T, a)[2])
        zc = mc_zetas(closed_all(T, al), w, T, a)[0]
        print(f"| {w} | {al} | {fmt(z1, e1)} | {fmt(z2, e2)} | {fmt(dz, edz)} | {fmt(rz, erz)} | {fmt(zt, et)} | "
              f"{zc:+.5f} | {zscore(zt, et, zc):+.2f} |")
    # gamma implied by MC at omega = 0.5, alpha = 0.7: shift needed to make zeta_1 = zeta_2
    key = (0.5, 0.7)
    k = keys.index(key)
    gamma, al = states[k]
    a = theory[key]["a2"]
    T = temperatures(gamma)
    dz, edz = jackknife(R[:, k], lambda A: mc_zetas(A, 0.5, T, a)[0] - mc_zetas(A, 0.5, T, a)[1])
    h = 1e-4

    def dzc(g):
        Tg = temperatures(g)
        z = mc_zetas(closed_all(Tg, al), 0.5, Tg, a)
        return z[0] - z[1]
    slope = (dzc(gamma * (1 + h)) - dzc(gamma * (1 - h))) / (2 * h)  # d(zeta_1 - zeta_2)/d ln gamma
    print(f"\nomega = 0.5, alpha = 0.7: granmc gamma = {gamma:.6f}; MC zeta_1 - zeta_2 = {fmt(dz, edz)}; "
          f"d(zeta_1 - zeta_2)/d ln gamma (closed form, a2 fixed) = {slope:+.4f}\n  => MC-implied relative shift of "
          f"gamma: {-dz / slope:+.5f} +- {2 * edz / abs(slope):.5f} (2 sigma)")
    zb = mc_zetas(R[:, k].mean(axis=0), 0.5, T, a, bilinear=True)
    zl = mc_zetas(R[:, k].mean(axis=0), 0.5, T, a, bilinear=False)
    print(f"  a_1 a_2 term (dropped in the theory): zeta_1 {zb[0] - zl[0]:+.2e}, zeta_2 {zb[1] - zl[1]:+.2e}")
    # fourth-moment (a2) conditions, linearised as in mixture_hcs: E_i = sum_j n_j s^2 [K4 - 10 theta_i (1+a_i) K2]

    def a2_from(A, Tq):
        E0 = np.zeros(2)
        E = np.zeros((2, 2))
        for p, (i, j) in enumerate(PAIRS):
            wgt = DENS[j] * sig_ij(0.5, i, j) ** 2
            thi = Tq[i] / MASS[i]
            K2, K4 = A[p, 4:8], A[p, 8:12]
            E0[i] += wgt * (K4[0] - 10 * thi * K2[0])
            E[i, i] += wgt * (K4[1] - 10 * thi * (K2[1] + K2[0]))
            E[i, j] += wgt * (K4[2] - 10 * thi * K2[2])
        return np.linalg.solve(E, -E0)
    aa, ea = jackknife(R[:, k], lambda A: a2_from(A, T))
    ac = a2_from(closed_all(T, al), T)
    print(f"  a2 from the MC fourth moments at granmc gamma: a2_1 = {fmt(aa[0], ea[0])}, a2_2 = {fmt(aa[1], ea[1])}; "
          f"closed form {ac[0]:+.5f}, {ac[1]:+.5f}; granmc {a[0]:+.5f}, {a[1]:+.5f}")

    # ---------------- 3. viscosity ----------------
    print("\n## 3. First-Sonine shear viscosity, Gaussian thermostat (r = 1), T = x1 T1 + x2 T2 = 1, n1 = n2 = 0.5, "
          "m2 = sigma2 = 1")
    print("| omega | alpha | eta_1 MC | eta_1 closed | eta_2 MC | eta_2 closed | eta MC | eta closed | z(eta) | "
          "eta/eta(1) MC | closed (py) | granmc | z(ratio) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    rows, hcb, pydiff = [], {}, 0.0
    for r in (1.0, 0.5):
        for w in OMEGAS:
            k1 = state_of[(w, 1.0)]
            for al in ALPHAS:
                k = state_of[(w, al)]
                gamma = states[k][0]
                T = temperatures(gamma)
                a = theory[(w, al)]["a2"]

                def f(Am, w=w, T=T, a=a, k=k, k1=k1):
                    e = mc_eta(Am[k], w, T, a, r)
                    e1 = mc_eta(Am[k1], w, (1.0, 1.0), (0.0, 0.0), r)
                    return [e[0], e[1], e.sum(), e.sum() / e1.sum()]
                (m1, m2, mt, mr), (s1, s2, st, sr) = jackknife(R, f)
                c = closed_eta(w, T, a, al, r)
                c1 = closed_eta(w, (1.0, 1.0), (0.0, 0.0), 1.0, r)
                cr = c.sum() / c1.sum()
                g = theory[(w, al)]["eta_ratio"] if r == 1.0 else float("nan")
                rows.append((r, w, al, mr, sr, cr))
                if r == 1.0:
                    zr = f"{zscore(mr, sr, g):+.2f}" if al != 1.0 else "-"
                    print(f"| {w} | {al} | {fmt(m1, s1)} | {c[0]:.5f} | {fmt(m2, s2)} | {c[1]:.5f} | {fmt(mt, st)} | "
                          f"{c.sum():.5f} | {zscore(mt, st, c.sum()):+.2f} | {fmt(mr, sr)} | {cr:.5f} | {g:.5f} | "
                          f"{zr} |")
                    pydiff = max(pydiff, abs(cr - g))
                    if al == 1.0:
                        hcb[w] = (mt, st, hcb_elastic(w))
    print(f"\nPython transcription of mixture_viscosity.cpp vs granmc theory, eta/eta(1): max |diff| = {pydiff:.1e}")
    print("Elastic anchor, independent of the project: eta(alpha = 1) MC vs Hirschfelder-Curtiss-Bird first "
          "approximation (rigid spheres)")
    for w, (mt, st, h) in hcb.items():
        print(f"  omega {w}: MC {fmt(mt, st)}, HCB {h:.5f}, z = {zscore(mt, st, h):+.2f}")
    print("\nCooling-state reference (r = 1/2), eta/eta(1): MC vs Python closed form")
    print("| omega | alpha | MC | closed (py) | z |")
    print("|---|---|---|---|---|")
    for (r, w, al, mr, sr, cr) in rows:
        if r == 0.5 and al != 1.0:
            print(f"| {w} | {al} | {fmt(mr, sr)} | {cr:.5f} | {zscore(mr, sr, cr):+.2f} |")

    # ---------------- 4. sensitivity of the closed form to the state (context for the DSMC gap) ----------------
    print("\n## 4. Sensitivity of the closed-form eta/eta(1) (r = 1) to the homogeneous state (Python closed forms)")
    c1 = {w: closed_eta(w, (1.0, 1.0), (0.0, 0.0), 1.0, 1.0).sum() for w in OMEGAS}
    for w, al in ((0.5, 0.8), (0.5, 0.7)):
        gamma = theory[(w, al)]["gamma"]
        a = theory[(w, al)]["a2"]

        def ratio(g, aa):
            return closed_eta(w, temperatures(g), aa, al, 1.0).sum() / c1[w]
        base = ratio(gamma, a)
        dln = (math.log(ratio(gamma * 1.01, a)) - math.log(ratio(gamma / 1.01, a))) / (2 * math.log(1.01))
        print(f"  omega {w} alpha {al}: {base:.5f}; d ln(eta/eta1)/d ln gamma = {dln:+.3f}; with a2 = 0: "
              f"{ratio(gamma, (0.0, 0.0)):.5f}; at gamma = 1: {ratio(1.0, a):.5f}")


if __name__ == "__main__":
    main()
