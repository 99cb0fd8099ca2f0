#!/usr/bin/env python3
"""Where Lipton's bond-based law first localises under a homogeneous strain (docs/peridynamics.md,
"Localisation under uniform tension").

Strain eps diag(1, -k) (tension along x, k = -eps_yy / eps_xx). The continuum tangent of the pair
law is C_ijkl = int c e_i e_j e_k e_l over the bonds, with a bond's tangent c ~ J(rho) rho^2
exp(-x) (1 - 2 x), x = a rho s^2, s = cos^2 t - k sin^2 t, a = beta delta eps^2 (a shortened bond,
s < 0, under the linear law in compression: c ~ J rho^2). A band with normal n can form once the
acoustic tensor Q_ik(n) = C_ijkl n_j n_l = int c (e.n)^2 e_i e_k is singular (Rice 1976). For each
k the script raises a in steps of 0.05 until det Q(n) <= 0 for some n (in steps of 2 degrees)
and prints that a and the angle of n from the tension axis (the band then runs at that angle from
the perpendicular to the tension).
Linear J = 12 (1 - rho); pure Python, about a minute.
"""
import math

NR, NT = 40, 180
BONDS = []
for i in range(NR):
    rho = (i + 0.5) / NR
    for j in range(NT):
        t = (j + 0.5) * 2. * math.pi / NT
        BONDS.append((rho, 12. * (1. - rho) * rho * rho, math.cos(t), math.sin(t)))


def det_q(a, k, psi):
    """det Q(n) / det Q_linear(n), n at psi from the tension axis (Q_linear: every bond linear)."""
    n0, n1 = math.cos(psi), math.sin(psi)
    q11 = q22 = q12 = l11 = l22 = l12 = 0.
    for rho, w, c, s_ in BONDS:
        s = c * c - k * s_ * s_
        x = a * rho * s * s
        tangent = w * (math.exp(-x) * (1. - 2. * x) if s > 0. else 1.)
        en2 = (c * n0 + s_ * n1) ** 2
        q11 += tangent * en2 * c * c
        q22 += tangent * en2 * s_ * s_
        q12 += tangent * en2 * c * s_
        l11 += w * en2 * c * c
        l22 += w * en2 * s_ * s_
        l12 += w * en2 * c * s_
    return (q11 * q22 - q12 * q12) / (l11 * l22 - l12 * l12)


for k in (0., 1. / 3., 1., 5. / 3.):
    for step in range(1, 80):
        a = 0.05 * step
        d, psi = min((det_q(a, k, math.radians(p)), p) for p in range(0, 91, 2))
        if d <= 0.:
            print(f"k = {k:.3f}: det Q first vanishes at a = {a:.2f}, n at {psi} degrees from the tension axis",
                  flush=True)
            break
