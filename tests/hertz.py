"""Hertz's and Mindlin's closed forms for a sphere on a flat (and Hertz's for a
cylinder's line contact), as the 3D tests
read them (Johnson, Contact Mechanics 4.2 and 7.2): written once here so that
every test compares against the same formulas, not against the program's
own (scripts/plot_hertz.py has its own, checked against these)."""
import math

import numpy as np


def plane_strain_modulus(E1, nu1, E2, nu2):
    """E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)."""
    return 1 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)


def peak(P, a):
    """p0 = 3 P / (2 pi a^2): the peak pressure of the force P over a disc of radius a."""
    return 3 * P / (2 * math.pi * a * a)


def sphere(P, Es, R=1.0):
    """The contact radius a = (3 P R / (4 E*))^(1/3) and the peak pressure p0."""
    a = (3 * P * R / (4 * Es)) ** (1 / 3)
    return a, peak(P, a)


def line(P1, Es, R=1.0):
    """A cylinder's line contact under a load P1 per unit length (Johnson 4.3):
    the half-width b = sqrt(4 P1 R / (pi E*)) and the peak p0 = 2 P1 / (pi b)."""
    b = math.sqrt(4 * P1 * R / (math.pi * Es))
    return b, 2 * P1 / (math.pi * b)


def moment_radius(rows):
    """a from the nodal pressures' second moment, sqrt(5/2 sum p A r^2 / sum p
    A) (2 a^2 / 5 for Hertz's profile), from a pair's contact_nodes rows (X, Y,
    Z, p, A), r the distance from the z axis."""
    w = sum(r[3] * r[4] for r in rows)
    return math.sqrt(2.5 * sum(r[3] * r[4] * (r[0] ** 2 + r[1] ** 2) for r in rows) / w)


def mindlin_shear(r, a, c, p0, mu):
    """Cattaneo-Mindlin's tangential traction along Q at radius r: mu p0/a
    (sqrt(a^2 - r^2) - sqrt(c^2 - r^2)), each root 0 outside its disc."""
    return mu * p0 / a * (np.sqrt(np.maximum(a * a - r * r, 0)) - np.sqrt(np.maximum(c * c - r * r, 0)))
