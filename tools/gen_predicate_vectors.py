#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Generate the predicate test vectors (build/gen/predicate_vectors.c).

This is an independent oracle for vor's exact predicates: every expected sign
is computed here with Python's unbounded integers, without looking at the C
code or at any hand-derived list of perturbation terms.

    python3 tools/gen_predicate_vectors.py --out build/gen/predicate_vectors.c [--seed N]
    python3 tools/gen_predicate_vectors.py --selftest

Conventions (tests/vectors/predicate_vectors.h holds the emitted layout):

* orient2d(a, b, c)    = sign det [[ax ay 1] [bx by 1] [cx cy 1]]
                         (> 0 when a, b, c turn counterclockwise).
* incircle(a, b, c, d) = sign det of the rows (x, y, x^2 + y^2, 1) for
                         a, b, c, d (> 0 when d is inside the circle through
                         the counterclockwise a, b, c).
* closer(q, a, b)      = sign (|q - a|^2 - |q - b|^2); never perturbed.
* power(a, b, c, d)    = sign det of the rows (x, y, x^2 + y^2 - w, 1) of
                         the weighted points (the power test; incircle when
                         the weights are equal).
* power_closer(q, a, b) = sign ((|q - a|^2 - wa) - (|q - b|^2 - wb)), with
                         q's weight unused; never perturbed.
* Symbolic perturbation: the site of rank r (0..3) moves to
      (x + eps^(4*16^r), y + eps^(16^r)),  eps -> 0+,
  the lifted coordinate is recomputed from the moved x and y (the weights
  stay), and the
  perturbed sign is the sign of the coefficient of the lowest power of eps
  in the expanded determinant.  Rank 0 has the largest perturbation.
* ranks field: rank of the k-th point in call order is (ranks >> 2k) & 3.

Python 3.11 standard library only; the output is a pure function of --seed.
"""

import argparse
import itertools
import math
import os
import random
import sys
import time

INT32_MIN = -(1 << 31)
INT32_MAX = (1 << 31) - 1

OP_ORIENT2D, OP_INCIRCLE, OP_CLOSER = 0, 1, 2
OP_NAMES = ["PV_ORIENT2D", "PV_INCIRCLE", "PV_CLOSER"]
NPOINTS = {OP_ORIENT2D: 3, OP_INCIRCLE: 4, OP_CLOSER: 3}

FAMILY_NAMES = ["PF_RANDOM_FULL", "PF_RANDOM_SMALL", "PF_RANDOM_MID",
                "PF_COLLINEAR", "PF_COCIRCULAR", "PF_OFF_BY_ONE",
                "PF_CORNERS", "PF_PERTURBED", "PF_TIER_EDGE"]
(PF_RANDOM_FULL, PF_RANDOM_SMALL, PF_RANDOM_MID, PF_COLLINEAR, PF_COCIRCULAR,
 PF_OFF_BY_ONE, PF_CORNERS, PF_PERTURBED, PF_TIER_EDGE) = range(len(FAMILY_NAMES))

DEFAULT_SEED = 1

# How many cases of each (op, family).  Totals: orient2d 4392 (35%),
# incircle 5656 (45%), closer 2552 (20%); PF_PERTURBED = 1770 cases,
# PF_TIER_EDGE = 600 (generated last, so the other families' cases do not
# depend on it; its counts are multiples of the 8 TIER_CLASSES).
# The PF_PERTURBED counts are multiples of the per-configuration fan-out
# (6 rank permutations for orient2d; 24 or 4 for incircle, see below).
PLAN = {
    OP_ORIENT2D: {PF_RANDOM_FULL: 600, PF_RANDOM_SMALL: 700, PF_RANDOM_MID: 400,
                  PF_COLLINEAR: 600, PF_COCIRCULAR: 300, PF_OFF_BY_ONE: 400,
                  PF_CORNERS: 390, PF_PERTURBED: 810, PF_TIER_EDGE: 192},
    OP_INCIRCLE: {PF_RANDOM_FULL: 700, PF_RANDOM_SMALL: 800, PF_RANDOM_MID: 500,
                  PF_COLLINEAR: 600, PF_COCIRCULAR: 900, PF_OFF_BY_ONE: 600,
                  PF_CORNERS: 340, PF_PERTURBED: 960, PF_TIER_EDGE: 256},
    OP_CLOSER: {PF_RANDOM_FULL: 400, PF_RANDOM_SMALL: 400, PF_RANDOM_MID: 300,
                PF_COLLINEAR: 500, PF_COCIRCULAR: 200, PF_OFF_BY_ONE: 300,
                PF_CORNERS: 300, PF_TIER_EDGE: 152},
}

CORNER_VALUES = [INT32_MIN, INT32_MIN + 1, INT32_MIN + 2, -2, -1, 0, 1, 2,
                 INT32_MAX - 2, INT32_MAX - 1, INT32_MAX]


def sgn(v):
    return (v > 0) - (v < 0)


def in_range(pts):
    return all(INT32_MIN <= c <= INT32_MAX for p in pts for c in p)


# ---------------------------------------------------------------------------
# Exact (unperturbed) predicates: literal determinants, Leibniz formula.

def _perm_parity(perm):
    inv = sum(1 for i in range(len(perm)) for j in range(i + 1, len(perm))
              if perm[i] > perm[j])
    return -1 if inv & 1 else 1


PERMS = {n: [(p, _perm_parity(p)) for p in itertools.permutations(range(n))]
         for n in (3, 4)}


def det_leibniz(m):
    n = len(m)
    total = 0
    for perm, s in PERMS[n]:
        prod = s
        for i in range(n):
            prod *= m[i][perm[i]]
        total += prod
    return total


def exact_sign(op, pts):
    if op == OP_ORIENT2D:
        return sgn(det_leibniz([[x, y, 1] for x, y in pts]))
    if op == OP_INCIRCLE:
        return sgn(det_leibniz([[x, y, x * x + y * y, 1] for x, y in pts]))
    (qx, qy), (ax, ay), (bx, by) = pts
    return sgn((qx - ax) ** 2 + (qy - ay) ** 2 - (qx - bx) ** 2 - (qy - by) ** 2)


# ---------------------------------------------------------------------------
# Symbolic perturbation by explicit polynomial expansion in eps.
#
# A matrix entry is a list of terms (exponent, coefficient, factor) where
# factor names the perturbation quantity the term carries: None for the
# unperturbed part, else (rank, kind) with kind one of dy, dy^2, dx, dx^2,
# i.e. eps^(16^r), eps^(2*16^r), eps^(4*16^r), eps^(8*16^r).  These are the
# four bits of nibble r, so an exponent spells out which factors a monomial
# carries; the expansion asserts that (no two different factor sets share
# an exponent), which is what makes "lowest exponent" well defined.

def _perturbed_row(op, pt, rank, weight=0):
    x, y = pt
    e_dy = 16 ** rank
    e_dx = 4 * 16 ** rank
    col_x = [(0, x, None), (e_dx, 1, (rank, "dx"))]
    col_y = [(0, y, None), (e_dy, 1, (rank, "dy"))]
    one = [(0, 1, None)]
    if op == OP_ORIENT2D:
        return [col_x, col_y, one]
    # (x + dx)^2 + (y + dy)^2 = x^2 + y^2 + 2x dx + dx^2 + 2y dy + dy^2
    lift = [(0, x * x + y * y - weight, None),
            (e_dx, 2 * x, (rank, "dx")), (2 * e_dx, 1, (rank, "dx^2")),
            (e_dy, 2 * y, (rank, "dy")), (2 * e_dy, 1, (rank, "dy^2"))]
    return [col_x, col_y, lift, one]


def perturbed_poly(op, pts, ranks, weights=None):
    """The perturbed determinant as {exponent of eps: integer coefficient};
    weights (the power test) go into the lifted coordinate."""
    assert op in (OP_ORIENT2D, OP_INCIRCLE)
    n = NPOINTS[op]
    assert len(pts) == n and sorted(ranks) == list(range(n))
    weights = weights or [0] * n
    rows = [_perturbed_row(op, p, r, w) for p, r, w in zip(pts, ranks, weights)]
    poly = {}
    factors_of = {}
    for perm, psign in PERMS[n]:
        for combo in itertools.product(*(rows[i][perm[i]] for i in range(n))):
            exp = 0
            coef = psign
            factors = []
            for e, c, f in combo:
                exp += e
                coef *= c
                if f is not None:
                    factors.append(f)
            # Every row contributes at most one factor and rows have distinct
            # ranks, so the factor set must be a function of the exponent.
            key = tuple(sorted(factors))
            assert factors_of.setdefault(exp, key) == key, (exp, key)
            poly[exp] = poly.get(exp, 0) + coef
    return poly


def perturbed_sign(op, pts, ranks, weights=None):
    poly = perturbed_poly(op, pts, ranks, weights)
    nonzero = [e for e, c in poly.items() if c != 0]
    assert nonzero, ("perturbed determinant vanishes identically", op, pts, ranks)
    return sgn(poly[min(nonzero)])


# ---------------------------------------------------------------------------
# Second, independent perturbation oracle (used only by --selftest).
#
# Choice: substitute a concrete eps and evaluate the determinant exactly,
# with a different determinant algorithm (Laplace expansion) and no
# polynomial bookkeeping.  The true exponents (up to 8*16^3) would need
# numbers with millions of bits, so each rank's exponents are remapped
# order-preservingly: dy -> 7^r, dy^2 -> 2*7^r, dx -> 3*7^r, dx^2 -> 6*7^r
# (still consistent: dy^2 = (dy)^2, dx^2 = (dx)^2).  A monomial carries at
# most one factor per rank, so both the true and the remapped exponents are
# positional numbers with per-rank digit order 0 < dy < dy^2 < dx < dx^2
# (true: digits 0,1,2,4,8 in base 16; remapped: 0,1,2,3,6 in base 7; in both
# the digit maximum is below the base, so comparison is lexicographic from
# rank 3 down).  Hence the lowest monomial and its coefficient are the same.
# With eps = 2^-k and C >= sum |coefficients|, choosing 2^k > C makes the
# lowest monomial dominate the rest (remapped exponents are integers, so the
# others carry at least one more factor of eps), so sign(det) at that eps is
# the perturbed sign.  Rows are scaled by 2^(k*6*7^r) to stay in integers.

def _det_laplace(m, rows_order):
    """Determinant by cofactor expansion; rows_order lists the rows to expand
    along first (largest numbers first keeps the big multiplications few)."""
    n = len(m)
    if n == 1:
        return m[0][0]
    r = rows_order[0]
    rest = [i for i in range(n) if i != r]
    sub_order = [rest.index(i) for i in rows_order[1:]]
    total = 0
    for j in range(n):
        if m[r][j] == 0:
            continue
        minor = [[m[i][c] for c in range(n) if c != j] for i in rest]
        cof = _det_laplace(minor, sub_order)
        total += (-1) ** (r + j) * m[r][j] * cof
    return total


def concrete_perturbed_sign(op, pts, ranks, weights=None):
    n = NPOINTS[op]
    weights = weights or [0] * n
    bound = 1
    for (x, y), w in zip(pts, weights):  # permanent <= product of row sums
        row = abs(x) + 1 + abs(y) + 1 + 1
        if op == OP_INCIRCLE:
            row += abs(x * x + y * y - w) + 2 * abs(x) + 1 + 2 * abs(y) + 1
        bound *= row
    k = bound.bit_length() + 1
    m = []
    for (x, y), r, w in zip(pts, ranks, weights):
        b = 7 ** r
        a = 3 * b
        top = 2 * a
        scale = 1 << (k * top)
        ex = 1 << (k * (top - a))       # eps^a     * scale
        ey = 1 << (k * (top - b))       # eps^b     * scale
        ex2 = 1                         # eps^(2a)  * scale
        ey2 = 1 << (k * (top - 2 * b))  # eps^(2b)  * scale
        px = x * scale + ex
        py = y * scale + ey
        if op == OP_ORIENT2D:
            m.append([px, py, scale])
        else:
            lift = (x * x + y * y - w) * scale + 2 * x * ex + ex2 + 2 * y * ey + ey2
            m.append([px, py, lift, scale])
    order = sorted(range(n), key=lambda i: -ranks[i])
    value = _det_laplace(m, order)
    assert value != 0
    return sgn(value)


# ---------------------------------------------------------------------------
# Gaussian integers: lattice points on x^2 + y^2 = n from n's factorisation.

def _gmul(z, w):
    return (z[0] * w[0] - z[1] * w[1], z[0] * w[1] + z[1] * w[0])


def _gpow(z, e):
    r = (1, 0)
    for _ in range(e):
        r = _gmul(r, z)
    return r


def _two_squares_prime(p):
    """(x, y) with x^2 + y^2 = p for a prime p = 1 mod 4 (Hermite-Serret)."""
    assert p % 4 == 1
    for c in range(2, p):
        t = pow(c, (p - 1) // 4, p)
        if t * t % p == p - 1:
            break
    a, b = p, t
    while b * b > p:
        a, b = b, a % b
    y = math.isqrt(p - b * b)
    assert b * b + y * y == p
    return (b, y)


class Circle:
    """Lattice points of X^2 + Y^2 = n, n given factorised.  half=True means
    n = 2 mod 4, every (X, Y) is odd/odd and the points used are
    ((X + 1) / 2, (Y + 1) / 2): a circle with a half-integer centre."""

    def __init__(self, factors, half=False):
        self.factors = dict(factors)
        self.n = math.prod(p ** e for p, e in factors.items())
        self.half = half
        self.gauss = {}
        for p, e in factors.items():
            if p % 4 == 3:
                assert e % 2 == 0, "p = 3 mod 4 needs an even exponent"
            elif p % 4 == 1:
                self.gauss[p] = _two_squares_prime(p)
        if half:
            assert self.n % 4 == 2

    def point(self, rng):
        """A uniformly random unit times a random split of each prime p = 1
        mod 4 between pi and conj(pi): by unique factorisation in Z[i] this
        reaches every lattice point of the circle."""
        z = (1, 0)
        for p, e in sorted(self.factors.items()):
            if p == 2:
                z = _gmul(z, _gpow((1, 1), e))
            elif p % 4 == 3:
                z = (z[0] * p ** (e // 2), z[1] * p ** (e // 2))
            else:
                pi = self.gauss[p]
                j = rng.randint(0, e)
                z = _gmul(z, _gmul(_gpow(pi, j), _gpow((pi[0], -pi[1]), e - j)))
        z = _gmul(z, _gpow((0, 1), rng.randrange(4)))
        assert z[0] ** 2 + z[1] ** 2 == self.n
        if self.half:
            assert z[0] % 2 == 1 and z[1] % 2 == 1
            return ((z[0] + 1) // 2, (z[1] + 1) // 2)
        return z


# R = 2*5*11*13*17*29*37*41 = 1069469830 < 2^30: 4 * 5^6 = 62500 lattice points.
CIRCLES_BIG = [
    Circle({2: 2, 5: 2, 11: 2, 13: 2, 17: 2, 29: 2, 37: 2, 41: 2}),
    # non-square n ~ 2^59.8 (radius ~ 2^29.9), 3 * 2^10 * 4 lattice points
    Circle({2: 1, 5: 2, 13: 1, 17: 1, 29: 1, 37: 1, 41: 1, 53: 1, 61: 1,
            73: 1, 89: 1, 97: 1}),
    # half-integer centre, N ~ 2^61.3 (radius ~ 2^29.7)
    Circle({2: 1, 3: 2, 5: 2, 13: 1, 17: 1, 29: 1, 37: 1, 41: 1, 53: 1,
            61: 1, 73: 1, 89: 1}, half=True),
]
CIRCLES_SMALL = [
    Circle({2: 1}, half=True),          # the unit square
    Circle({2: 1}),                     # (+-1, +-1)
    Circle({5: 1}),
    Circle({5: 2}),
    Circle({5: 1, 13: 1}),
    Circle({2: 1, 5: 1, 13: 1}, half=True),
    Circle({5: 2, 13: 2}),              # R = 65
    Circle({5: 1, 13: 1, 17: 1, 29: 1, 37: 1}),
    Circle({5: 2, 13: 2, 17: 2, 29: 2}),  # R = 32045
    Circle({2: 1, 5: 1, 13: 1, 17: 1, 29: 1, 37: 1, 41: 1}, half=True),
    Circle({5: 2, 13: 2, 17: 2, 29: 2, 37: 2, 41: 2}),  # R = 48612265
]


# ---------------------------------------------------------------------------
# PF_TIER_EDGE helpers.
#
# src/predicates.c picks an integer width from the magnitudes of the
# coordinate differences to one reference point (c for orient2d, d for
# incircle, q for closer), measured as bound(v) = v for v >= 0, -v - 1 for
# v < 0 (so bound(v) < 2^k exactly when v lies in [-2^k, 2^k - 1]).  The
# family's cases fall in classes that fix the largest bound exactly, at each
# side of the tier limits 2^14 (incircle narrow), 2^30 (incircle mid) and
# 2^31 (orient2d and closer narrow), plus 2^15 (where the incircle narrow
# arithmetic would first overflow) and the extremes above 2^31:
#
#   ("in", k)   largest bound 2^k - 1: differences -2^k or 2^k - 1 occur
#   ("out", k)  largest bound 2^k: differences 2^k or -2^k - 1 occur
#   ("ext", 32) largest bound above 2^31 (differences up to 2^32 - 1)
#
# Only the choice of the configurations looks at the tiers; every expected
# sign still comes from exact_sign() and perturbed_sign().

L32 = (1 << 32) - 1  # the largest difference of two int32 coordinates

TIER_CLASSES = [("in", 14), ("out", 14), ("in", 15), ("in", 30), ("out", 30),
                ("in", 31), ("out", 31), ("ext", 32)]


def tier_bound(v):
    return -v - 1 if v < 0 else v


def reference_diffs(op, pts):
    """Differences to the reference point, in call order of the others."""
    if op == OP_ORIENT2D:
        ref, others = pts[2], pts[:2]
    elif op == OP_INCIRCLE:
        ref, others = pts[3], pts[:3]
    else:
        ref, others = pts[0], pts[1:]
    return [(x - ref[0], y - ref[1]) for x, y in others]


def max_bound(op, pts):
    return max(tier_bound(c) for p in reference_diffs(op, pts) for c in p)


def class_meets(cls, m):
    """Whether m is the largest bound class cls asks for."""
    kind, k = cls
    if kind == "in":
        return m == (1 << k) - 1
    if kind == "out":
        return m == 1 << k
    return m > 1 << 31


def cross2(u, v):
    return u[0] * v[1] - u[1] * v[0]


def incircle_terms(rel):
    """The three terms lift(p) * cross(q, r) whose sum is the incircle
    determinant of rel = [a - d, b - d, c - d] (Laplace along the lifts)."""
    a, b, c = rel
    lift = [x * x + y * y for x, y in rel]
    return [lift[0] * cross2(b, c), lift[1] * cross2(c, a), lift[2] * cross2(a, b)]


def egcd(a, b):
    """(g, x, y) with a x + b y = g = gcd(a, b) >= 0."""
    x0, y0, x1, y1 = 1, 0, 0, 1
    while b:
        q = a // b
        a, b = b, a - q * b
        x0, x1 = x1, x0 - q * x1
        y0, y1 = y1, y0 - q * y1
    if a < 0:
        a, x0, y0 = -a, -x0, -y0
    return a, x0, y0


def factorize(n):
    """Trial division; meant for n up to about 2^33."""
    f = {}
    p = 2
    while p * p <= n:
        while n % p == 0:
            f[p] = f.get(p, 0) + 1
            n //= p
        p += 1 if p == 2 else 2
    if n > 1:
        f[n] = f.get(n, 0) + 1
    return f


# Circle radii R per class whose R^2 has many lattice points (R a product of
# primes 1 mod 4, times small factors) and for which R^2 - 1 = (R-1)(R+1) is
# a sum of two squares too.  All 2R + 1 fit the class: 2R < 2^14, 2^30, 2^31,
# 2^32 - 1.  A point d at squared distance R^2 +- 1 from the centre has power
# -+1, so the incircle determinant is -+orient2d(a, b, c) (up to sign) while
# its terms are near the class maximum.
TIER_CIRCLE_RADII = {("in", 14): 7395, ("in", 30): 517917699,
                     ("in", 31): 1063667305, ("ext", 32): 2129098881}


def _merge_factors(*fs):
    out = {}
    for f in fs:
        for p, e in f.items():
            out[p] = out.get(p, 0) + e
    return out


_TIER_CIRCLES = {}


def tier_circles(R):
    """(Circle of R^2, Circle of R^2 - 1), built once."""
    if R not in _TIER_CIRCLES:
        fr = factorize(R)
        on = Circle({p: 2 * e for p, e in fr.items()})
        inside = Circle(_merge_factors(factorize(R - 1), factorize(R + 1)))
        _TIER_CIRCLES[R] = (on, inside)
    return _TIER_CIRCLES[R]


# ---------------------------------------------------------------------------
# Case generation.

class Generator:
    def __init__(self, seed):
        self.rng = random.Random(seed)
        # The 5% self-check sample uses its own stream so that turning it
        # into a no-op would not change the emitted cases.
        self.check_rng = random.Random(seed * 7919 + 17)
        self.cases = []
        self.expansions = 0
        self.expansion_checks = 0

    # -- bookkeeping ------------------------------------------------------

    def add(self, op, pts, family, ranks=None):
        pts = [tuple(p) for p in pts]
        n = NPOINTS[op]
        assert len(pts) == n and in_range(pts), (op, pts)
        exact = exact_sign(op, pts)
        if op == OP_CLOSER:
            ranks = [0, 0, 0]
            perturbed = exact
        else:
            if ranks is None:
                ranks = self.rng.sample(range(n), n)
            if exact == 0:
                perturbed = perturbed_sign(op, pts, ranks)
                self.expansions += 1
            else:
                perturbed = exact
                if self.check_rng.random() < 0.05:
                    assert perturbed_sign(op, pts, ranks) == exact, (op, pts)
                    self.expansion_checks += 1
            assert perturbed != 0
        packed = 0
        for k, r in enumerate(ranks):
            packed |= r << (2 * k)
        xy = [c for p in pts for c in p] + [0] * (8 - 2 * n)
        self.cases.append((xy, op, exact, perturbed, packed, family))
        return exact

    # -- point helpers ----------------------------------------------------

    def coord(self):
        return self.rng.randint(INT32_MIN, INT32_MAX)

    def point(self):
        return (self.coord(), self.coord())

    def window_points(self, n, w):
        """n points with coordinate differences <= w - 1, anywhere in range;
        the base is sometimes pinned to an extreme of the int32 range."""
        bx, by = self.window_base(w), self.window_base(w)
        return [(bx + self.rng.randrange(w), by + self.rng.randrange(w))
                for _ in range(n)]

    def window_base(self, w):
        """Lowest coordinate of a window of width w that fits in int32."""
        u = self.rng.random()
        if u < 0.1:
            return INT32_MIN
        if u < 0.2:
            return INT32_MAX - (w - 1)
        return self.rng.randint(INT32_MIN, INT32_MAX - (w - 1))

    def translate_into_range(self, pts):
        """Translate pts by an integer vector so they fit in int32; a third
        of the time per axis the box touches INT32_MIN or INT32_MAX."""
        out = []
        shift = []
        for axis in (0, 1):
            lo = INT32_MIN - min(p[axis] for p in pts)
            hi = INT32_MAX - max(p[axis] for p in pts)
            assert lo <= hi, "configuration too wide for int32"
            u = self.rng.random()
            if u < 1 / 6:
                shift.append(lo)
            elif u < 1 / 3:
                shift.append(hi)
            else:
                shift.append(self.rng.randint(lo, hi))
        for p in pts:
            out.append((p[0] + shift[0], p[1] + shift[1]))
        return out

    def direction(self):
        """A random primitive (gcd-reduced) direction of random scale."""
        scale = self.rng.choice([2, 4, 1 << 10, 1 << 20, 1 << 30])
        while True:
            dx = self.rng.randint(-scale, scale)
            dy = self.rng.randint(-scale, scale)
            if self.rng.random() < 0.1:  # axis-parallel and diagonal lines
                dx, dy = self.rng.choice([(1, 0), (0, 1), (1, 1), (1, -1)])
            g = math.gcd(dx, dy)
            if g:
                return dx // g, dy // g

    @staticmethod
    def step_range(p, d):
        """Integers s with p + s*d inside int32 on both axes."""
        lo, hi = -(1 << 64), 1 << 64
        for c, dc in zip(p, d):
            if dc > 0:
                lo = max(lo, -((c - INT32_MIN) // dc))
                hi = min(hi, (INT32_MAX - c) // dc)
            elif dc < 0:
                lo = max(lo, -((INT32_MAX - c) // -dc))
                hi = min(hi, (c - INT32_MIN) // -dc)
        return lo, hi

    def line(self):
        """(p, d, lo, hi): a line through an int32 point with at least four
        distinct int32 points p + s*d, s in [lo, hi]."""
        while True:
            d = self.direction()
            if self.rng.random() < 0.2:
                p = (self.rng.choice(CORNER_VALUES), self.rng.choice(CORNER_VALUES))
            else:
                p = self.point()
            lo, hi = self.step_range(p, d)
            if hi - lo >= 3:
                return p, d, lo, hi

    def collinear_points(self, n, distinct=True):
        p, d, lo, hi = self.line()
        while True:
            steps = []
            for _ in range(n):
                u = self.rng.random()
                # endpoints put points on the int32 boundary
                s = lo if u < 0.1 else hi if u < 0.2 else self.rng.randint(lo, hi)
                steps.append(s)
            if not distinct or len(set(steps)) == n:
                break
        return [(p[0] + s * d[0], p[1] + s * d[1]) for s in steps]

    def near_line_point(self, line_pts):
        """A point just off the line through line_pts[0], line_pts[1]."""
        (ax, ay), (bx, by) = line_pts[0], line_pts[1]
        while True:
            t = self.rng.randint(-1024, 2048)  # position along the line / 1024
            x = ax + (bx - ax) * t // 1024 + self.rng.randint(-3, 3)
            y = ay + (by - ay) * t // 1024 + self.rng.randint(-3, 3)
            if INT32_MIN <= x <= INT32_MAX and INT32_MIN <= y <= INT32_MAX:
                return (x, y)

    def cocircular(self, n, big=None):
        """n distinct points on one lattice circle, translated into range.
        Returns (points, centre) where centre is None for half-integer
        centres."""
        if big is None:
            big = self.rng.random() < 0.6
        circle = self.rng.choice(CIRCLES_BIG if big else CIRCLES_SMALL)
        while True:
            raw = [circle.point(self.rng) for _ in range(n)]
            if len(set(raw)) == n:
                break
        if circle.half:
            return self.translate_into_range(raw), None
        moved = self.translate_into_range(raw + [(0, 0)])
        return moved[:n], moved[n]

    def equidistant(self):
        """(q, a, b) with |q - a| = |q - b| exactly."""
        while True:
            if self.rng.random() < 0.5:
                # a, b anywhere with a = b mod 2, q on the perpendicular
                # bisector: q = (a + b) / 2 + t * perp(b - a) / g.
                a = self.point()
                b = self.point()
                b = tuple(bc if (bc - ac) % 2 == 0 else
                          (bc - 1 if bc > INT32_MIN else bc + 1)
                          for ac, bc in zip(a, b))
                if a == b:
                    continue
                m = ((a[0] + b[0]) // 2, (a[1] + b[1]) // 2)
                g = math.gcd(b[0] - a[0], b[1] - a[1])
                w = (-(b[1] - a[1]) // g, (b[0] - a[0]) // g)
                lo, hi = self.step_range(m, w)
                u = self.rng.random()
                t = lo if u < 0.1 else hi if u < 0.2 else self.rng.randint(lo, hi)
                q = (m[0] + t * w[0], m[1] + t * w[1])
            else:
                # a - q = z1 z2, b - q = z1 conj(z2) in Z[i]: equal norms.
                q = self.point() if self.rng.random() < 0.8 else (
                    self.rng.choice(CORNER_VALUES), self.rng.choice(CORNER_VALUES))
                s1 = 1 << self.rng.randint(0, 16)
                s2 = 1 << self.rng.randint(0, 15)
                z1 = (self.rng.randint(-s1, s1), self.rng.randint(-s1, s1))
                z2 = (self.rng.randint(-s2, s2), self.rng.randint(-s2, s2))
                u = _gmul(z1, z2)
                v = _gmul(z1, (z2[0], -z2[1]))
                a = (q[0] + u[0], q[1] + u[1])
                b = (q[0] + v[0], q[1] + v[1])
            if in_range([q, a, b]):
                return [q, a, b]

    def off_by_one(self, pts):
        """Move one coordinate of one point by +-1, staying in range."""
        pts = [list(p) for p in pts]
        i = self.rng.randrange(len(pts))
        axis = self.rng.randrange(2)
        delta = self.rng.choice([-1, 1])
        if not INT32_MIN <= pts[i][axis] + delta <= INT32_MAX:
            delta = -delta
        pts[i][axis] += delta
        return [tuple(p) for p in pts]

    # -- families ---------------------------------------------------------

    def gen_random_full(self, op, count):
        for _ in range(count):
            self.add(op, [self.point() for _ in range(NPOINTS[op])], PF_RANDOM_FULL)

    def gen_random_small(self, op, count):
        for i in range(count):
            # a quarter in a 4x4 window (differences in [-3, 3]) so that
            # degeneracies happen naturally; the rest up to 2^13.
            w = 4 if i % 4 == 0 else 1 << self.rng.randint(3, 13)
            self.add(op, self.window_points(NPOINTS[op], w), PF_RANDOM_SMALL)

    def gen_random_mid(self, op, count):
        for i in range(count):
            w = 1 << 29 if i % 3 else 1 << self.rng.randint(14, 29)
            self.add(op, self.window_points(NPOINTS[op], w), PF_RANDOM_MID)

    def gen_collinear(self, op, count):
        for i in range(count):
            if op == OP_ORIENT2D:
                pts = self.collinear_points(3)
            elif op == OP_INCIRCLE:
                if i % 2 == 0:
                    pts = self.collinear_points(4)
                else:  # three collinear, one off the line (far or near)
                    pts = self.collinear_points(3)
                    off = self.point() if i % 4 == 1 else self.near_line_point(pts)
                    pts.insert(self.rng.randrange(4), off)
            else:
                pts = self.equidistant()
            self.add(op, pts, PF_COLLINEAR)

    def gen_cocircular(self, op, count):
        for _ in range(count):
            if op == OP_CLOSER:
                while True:
                    (a, b), centre = self.cocircular(2)
                    if centre is not None:
                        break
                pts = [centre, a, b]
            else:
                pts, _ = self.cocircular(4)
                if op == OP_ORIENT2D:
                    pts = pts[:3]
            self.add(op, pts, PF_COCIRCULAR)

    def degenerate_source(self, op):
        if op == OP_ORIENT2D:
            return self.collinear_points(3)
        if op == OP_INCIRCLE:
            if self.rng.random() < 0.5:
                return self.collinear_points(4)
            return self.cocircular(4)[0]
        return self.equidistant()

    def gen_off_by_one(self, op, count):
        for _ in range(count):
            for _attempt in range(50):
                pts = self.off_by_one(self.degenerate_source(op))
                if exact_sign(op, pts) != 0:
                    break
            self.add(op, pts, PF_OFF_BY_ONE)

    def gen_corners(self, op, count):
        for i in range(count):
            # Every other case draws from a random 3-value subset, which makes
            # duplicates and degenerate configurations much more frequent.
            values = CORNER_VALUES if i % 2 else self.rng.sample(CORNER_VALUES, 3)
            pts = [(self.rng.choice(values), self.rng.choice(values))
                   for _ in range(NPOINTS[op])]
            self.add(op, pts, PF_CORNERS)

    # PF_PERTURBED: degenerate on purpose; every configuration is emitted
    # under several rank permutations (orient2d: all 6; incircle: all 24 for
    # every fifth configuration, 4 distinct random ones otherwise).

    def any_point(self):
        u = self.rng.random()
        if u < 0.4:
            return self.point()
        if u < 0.6:
            return (self.rng.choice(CORNER_VALUES), self.rng.choice(CORNER_VALUES))
        return (self.rng.randint(-4, 4), self.rng.randint(-4, 4))

    def duplicated(self, n):
        """n points following a random set partition with a repeated block."""
        while True:
            labels = [self.rng.randrange(n) for _ in range(n)]
            if len(set(labels)) < n:
                break
        if self.rng.random() < 0.3:  # the distinct points collinear too
            line = self.collinear_points(n)
            return [line[k] for k in labels]
        if self.rng.random() < 0.3:  # close together
            base = self.window_points(n, 4)
            return [base[k] for k in labels]
        pool = [self.any_point() for _ in range(n)]
        return [pool[k] for k in labels]

    def grid(self, n):
        """n points of a 3x3 grid (unit or huge spacing) with exact == 0."""
        op = OP_ORIENT2D if n == 3 else OP_INCIRCLE
        if self.rng.random() < 0.2:
            step = (1 << 31) - 1  # {INT32_MIN, -1, INT32_MAX - 1}
            ox = oy = INT32_MIN
        else:
            step = self.rng.choice([1, 1, 1, 2, 1000])
            ox = self.window_base(2 * step + 1)
            oy = self.window_base(2 * step + 1)
        while True:
            pts = [(ox + step * self.rng.randrange(3), oy + step * self.rng.randrange(3))
                   for _ in range(n)]
            if exact_sign(op, pts) == 0:
                return pts

    def perturbed_config(self, op, i):
        n = NPOINTS[op]
        kind = i % 4
        if kind == 0:
            return self.duplicated(n)
        if kind == 1:
            return self.grid(n)
        if op == OP_ORIENT2D:
            return self.collinear_points(3, distinct=kind == 2)
        if kind == 2:
            return self.cocircular(4)[0]
        # collinear quadruple, possibly with repeated points
        return self.collinear_points(4, distinct=self.rng.random() < 0.5)

    def gen_perturbed(self, op, count):
        n = NPOINTS[op]
        all_ranks = [list(p) for p in itertools.permutations(range(n))]
        made = 0
        i = 0
        while made < count:
            pts = self.perturbed_config(op, i)
            assert exact_sign(op, pts) == 0
            if op == OP_ORIENT2D or i % 5 == 0:
                rank_sets = all_ranks
            else:
                rank_sets = self.rng.sample(all_ranks, 4)
            rank_sets = rank_sets[:count - made]
            for ranks in rank_sets:
                self.add(op, pts, PF_PERTURBED, ranks)
            made += len(rank_sets)
            i += 1

    # PF_TIER_EDGE: the largest differences each tier of src/predicates.c
    # admits and the smallest it must refuse (see TIER_CLASSES), arranged so
    # that products, lifts and cross products are near their largest for
    # the class: points at the corners and edges of the box of allowed
    # differences, the reference point (c, d or q) at the origin.  Cases
    # cycle through the classes; within a class through the constructions of
    # the op, and each construction's variants, the first time each variant
    # comes up with no jitter at all (the exact box corners).

    TIER_KINDS = {OP_ORIENT2D: ["max", "max", "zero", "pm1", "bare", "max"],
                  OP_INCIRCLE: ["max", "max", "zero", "near", "max", "bare", "zero", "near"],
                  OP_CLOSER: ["near", "zero", "pm1", "bare"]}
    TIER_VARIANTS = {"max": 4, "zero": 4, "pm1": 2, "near": 4, "bare": 1}

    def tier_box(self, cls, interior=False, corner=False):
        """Per axis (lo, hi): the differences class cls allows; interior
        keeps the reference point off the sides of an ext box, corner puts
        it at a corner of the int32 square."""
        kind, k = cls
        if kind == "in":
            return [(-(1 << k), (1 << k) - 1)] * 2
        if kind == "out" and k < 31:
            return [(-(1 << k) - 1, 1 << k)] * 2
        if kind == "out":  # int32 spans at most 2^32 - 1: one end short
            return [self.rng.choice([(-(1 << 31) - 1, (1 << 31) - 2),
                                     (-(1 << 31) + 1, 1 << 31)]) for _ in range(2)]
        box = []  # ext: the reference point anywhere in a 2^32 - 1 box
        for _ in range(2):
            # on this axis s = 0 or L32 puts it at a side of the box
            u = self.rng.uniform(0.6 if interior else 0, 0.6 if corner else 1)
            if u < 0.3:
                s = 0
            elif u < 0.6:
                s = L32
            elif u < 0.8:
                s = self.rng.randint(L32 // 8, 3 * L32 // 8)
            else:
                s = self.rng.randint(5 * L32 // 8, 7 * L32 // 8)
            box.append((-s, L32 - s))
        return box

    @staticmethod
    def tier_edges(cls, axis_box):
        """The values of one axis of the box whose bound is the class's."""
        kind, k = cls
        lo, hi = axis_box
        if kind == "in":
            vals = (-(1 << k), (1 << k) - 1)
        elif kind == "out":
            vals = (-(1 << k) - 1, 1 << k)
        else:
            vals = tuple(v for v in (lo, hi) if tier_bound(v) > 1 << 31)
        return [v for v in vals if lo <= v <= hi]

    def tier_jitter(self, k, pure):
        """How far a box coordinate moves inwards: mostly not at all."""
        u = self.rng.random()
        if pure or u < 0.5:
            return 0
        if u < 0.8:
            return self.rng.randint(1, 3)
        return self.rng.randint(4, 1 << (k - 10))

    def tier_value(self, axis_box, label, k, pure):
        """label 0: the low end, 2: the high end, 1: the middle half."""
        lo, hi = axis_box
        if label == 0:
            return lo + self.tier_jitter(k, pure)
        if label == 2:
            return hi - self.tier_jitter(k, pure)
        if pure:
            return (lo + hi) // 2
        q = (hi - lo) // 4
        return self.rng.randint(lo + q, hi - q)

    def tier_point(self, box, labels, k, pure):
        return tuple(self.tier_value(box[a], labels[a], k, pure) for a in (0, 1))

    @staticmethod
    def in_box(box, p):
        return all(box[a][0] <= p[a] <= box[a][1] for a in (0, 1))

    @staticmethod
    def rotate_labels(labels, r):
        """Labels turned by r quarter turns about the middle of the box."""
        for _ in range(r):
            labels = [(2 - ly, lx) for lx, ly in labels]
        return labels

    # -- orient2d: u = a - c, v = b - c ---------------------------------------

    def tier_orient_max(self, box, k, pure, variant):
        corners = [(0, 0), (2, 0), (2, 2), (0, 2)]
        i = self.rng.randrange(4)
        if variant == 0:    # adjacent corners: the products' signs differ
            pair = [corners[i], corners[(i + 1) % 4]]
        elif variant == 1:  # opposite corners: nearly collinear with c
            pair = [corners[i], corners[(i + 2) % 4]]
        elif variant == 2:  # a corner and the middle of a far edge
            pair = [corners[i], self.rng.choice([(1, 2 - corners[i][1]),
                                                 (2 - corners[i][0], 1)])]
        else:
            grid = [(x, y) for x in range(3) for y in range(3) if (x, y) != (1, 1)]
            pair = self.rng.sample(grid, 2)
        return [self.tier_point(box, lab, k, pure) for lab in pair]

    def tier_orient_zero(self, box, cls, k, pure, variant):
        """u and v on one line through c, as far out as the box allows."""
        if variant == 3 and cls in (("out", 31), ("ext", 32)):
            variant = self.rng.randrange(3)  # a - b would span over 2^32 - 1
        if variant == 3:  # c is the midpoint of a and b
            u = self.tier_point(box, (self.rng.choice([0, 2]), self.rng.choice([0, 2])),
                                k, pure)
            v = (-u[0], -u[1])
            return [u, v] if self.in_box(box, v) else None
        # towards the far corner of the box, when c is not in its middle
        far = [1 if hi + lo > 0 else -1 if hi + lo < 0 else self.rng.choice([-1, 1])
               for lo, hi in box]
        if variant == 0:
            w = (far[0], far[1]) if self.rng.random() < 0.75 else (far[0], -far[1])
        elif variant == 1:
            w = self.rng.choice([(1, 0), (0, 1)])
        else:  # a power of two on one axis: its multiples reach +-2^k
            i = self.rng.randint(1, k - 2)
            o = self.rng.randrange(1, 1 << i, 2)
            w = (1 << i, o) if self.rng.random() < 0.5 else (o, 1 << i)
            w = (w[0] * far[0], w[1] * far[1])
        mlo, mhi = -(1 << 40), 1 << 40
        for a in (0, 1):
            lo, hi = box[a]
            if w[a] > 0:
                mlo, mhi = max(mlo, -(-lo // w[a])), min(mhi, hi // w[a])
            elif w[a] < 0:
                mlo, mhi = max(mlo, -(hi // -w[a])), min(mhi, (-lo) // -w[a])
        if mhi - mlo < 2:
            return None
        m1 = mlo if self.rng.random() < 0.5 else mhi
        m2 = mlo + mhi - m1  # the other end, unless c is at an end
        u = self.rng.random()
        if m2 == 0 or (not pure and u < 0.5):
            # next to m1 (products near their largest), or anywhere
            near = pure or u < 0.75
            m2 = m1 - sgn(m1) * self.rng.randint(1, 3) if near else self.rng.randint(mlo, mhi)
        if m1 == m2 or m1 == 0 or m2 == 0:
            return None
        return [(m1 * w[0], m1 * w[1]), (m2 * w[0], m2 * w[1])]

    def tier_orient_pm1(self, box, cls, k, pure, variant):
        """cross(u, v) = +-1: u has a coordinate at the class's edge, v is
        on the lattice line next to the line through c and a, where its
        products with u are largest; variant 0 keeps the best of 16 u."""
        ea = self.rng.randrange(2)
        edges = self.tier_edges(cls, box[ea])
        if not edges:
            return None
        target = self.rng.choice([-1, 1])
        best = None
        for _ in range(16 if variant == 0 or pure else 1):
            found = self.tier_orient_pm1_try(box, ea, edges, k, target,
                                             variant == 0 or pure)
            if found is not None:
                size = min(abs(found[0][0] * found[1][1]), abs(found[0][1] * found[1][0]))
                if best is None or size > best[0]:
                    best = (size, found)
        return None if best is None else best[1]

    def tier_orient_pm1_try(self, box, ea, edges, k, target, far):
        """One u, the other coordinate near an end of the box (far: the
        end further from c); None if u is not primitive."""
        oa = 1 - ea
        u = [0, 0]
        u[ea] = self.rng.choice(edges)
        lo, hi = box[oa]
        span = 1 << (k - 6)
        low_end = -lo > hi if far else self.rng.random() < 0.5
        u[oa] = lo + self.rng.randint(0, span) if low_end else hi - self.rng.randint(0, span)
        g, x, y = egcd(u[0], -u[1])
        if g != 1:
            return None
        v0 = (y * target, x * target)  # u0 * v0y - u1 * v0x = target
        klo, khi = -(1 << 40), 1 << 40
        for a in (0, 1):
            alo, ahi = box[a][0] - v0[a], box[a][1] - v0[a]
            if u[a] > 0:
                klo, khi = max(klo, -(-alo // u[a])), min(khi, ahi // u[a])
            elif u[a] < 0:
                klo, khi = max(klo, -(ahi // -u[a])), min(khi, (-alo) // -u[a])
            elif not alo <= 0 <= ahi:
                return None
        if klo > khi:
            return None

        def size(kk):
            v = (v0[0] + kk * u[0], v0[1] + kk * u[1])
            return min(abs(u[0] * v[1]), abs(u[1] * v[0]))
        kk = max(range(klo, min(khi, klo + 8) + 1), key=size)  # the largest products
        v = (v0[0] + kk * u[0], v0[1] + kk * u[1])
        assert cross2(u, v) == target
        return [tuple(u), v]

    # -- incircle: a - d, b - d, c - d ----------------------------------------

    def tier_incircle_max(self, box, k, pure, variant):
        """d inside a triangle spanned by box corners and edges: the three
        terms share a sign (with three corners, d lies on or next to the
        diagonal and one term is about 0: the largest determinant)."""
        corners = [(0, 0), (2, 0), (2, 2), (0, 2)]
        if variant == 0:
            labels = self.rng.sample(corners, 3)
        elif variant == 1:
            labels = self.rotate_labels([(0, 0), (2, 0), (1, 2)], self.rng.randrange(4))
        elif variant == 2:
            labels = self.rotate_labels([(0, 0), (2, 1), (1, 2)], self.rng.randrange(4))
        else:
            labels = self.rotate_labels([(0, 0), (2, self.rng.randrange(3)),
                                         (self.rng.randrange(3), 2)], self.rng.randrange(4))
        rel = [self.tier_point(box, lab, k, pure) for lab in labels]
        if all(lo < 0 < hi for lo, hi in box):
            signs = {sgn(t) for t in incircle_terms(rel)}
            if variant == 0:
                if {-1, 1} <= signs:
                    return None
            elif len(signs) != 1 or 0 in signs:
                return None
        return rel

    def tier_incircle_zero(self, box, k, pure, variant):
        """Cocircular through d, symmetric: a rectangle, an isosceles
        trapezoid, or a trapezoid symmetric about a diagonal line."""
        X = self.tier_value(box[0], self.rng.choice([0, 2]), k, pure)
        Y = self.tier_value(box[1], self.rng.choice([0, 2]), k, pure)
        if variant == 0:
            return [(X, 0), (X, Y), (0, Y)]
        if variant == 1:  # symmetric about x = X / 2
            lo, hi = box[0]
            dlo, dhi = max(lo, X - hi), min(hi, X - lo)
            delta = self.rng.choice([dlo, dhi, self.rng.randint(dlo, dhi)])
            rel = [(X, 0), (delta, Y), (X - delta, Y)]
            if self.rng.random() < 0.5 and box[0] == box[1]:
                rel = [(y, x) for x, y in rel]
            return rel
        # symmetric about y = x + s (variant 2) or y = -x + s (variant 3);
        # class ("in", 15) wants (-2^15, -2^15), which only the second
        # mirror can pair with another point of the box
        diagonal = variant == 2 and k != 15

        def mirror(p, s):
            return (p[1] - s, p[0] + s) if diagonal else (s - p[1], s - p[0])
        a = (X, Y)
        for _ in range(20):
            s = self.rng.randint(-(1 << k), 1 << k)
            if self.rng.random() < 0.3:
                s = self.rng.choice([-1, 0, 1]) + (X - Y if variant == 2 else 0)
            rel = [a, mirror(a, s), mirror((0, 0), s)]
            if all(self.in_box(box, p) for p in rel):
                return rel
        return None

    def tier_incircle_near(self, box, cls, k, pure, variant):
        if variant % 2 == 0 or cls not in TIER_CIRCLE_RADII:
            # a symmetric cocircular case with one coordinate moved by 1
            rel = self.tier_incircle_zero(box, k, pure, self.rng.randrange(4))
            if rel is None:
                return None
            rel = [list(p) for p in rel]
            i, a = self.rng.randrange(3), self.rng.randrange(2)
            step = self.rng.choice([-1, 1])
            if not box[a][0] <= rel[i][a] + step <= box[a][1]:
                step = -step
            rel[i][a] += step
            rel = [tuple(p) for p in rel]
            return rel if sum(incircle_terms(rel)) != 0 else None
        return self.tier_incircle_power(cls, variant)

    def tier_incircle_power(self, cls, variant):
        """a, b, c on a lattice circle of radius R about O, d at squared
        distance R^2 + 1 (variant 1) or R^2 - 1 (variant 3) from O."""
        R = TIER_CIRCLE_RADII[cls]
        on, inside = tier_circles(R)
        if variant == 1:
            r = _gmul((R, self.rng.choice([-1, 1])), _gpow((0, 1), self.rng.randrange(4)))
        else:
            r = inside.point(self.rng)
        pool = {on.point(self.rng) for _ in range(24)}
        pool.discard(r)
        pool = sorted(pool)
        if self.rng.random() < 0.5:  # a, b, c close together, opposite d
            pool.sort(key=lambda p: (p[0] + r[0]) ** 2 + (p[1] + r[1]) ** 2)
            abc = pool[:3]
        else:
            abc = self.rng.sample(pool, 3)
        return [(x - r[0], y - r[1]) for x, y in abc]

    # -- closer: a - q, b - q -------------------------------------------------

    SYMMETRIES = [lambda p: (p[1], p[0]), lambda p: (-p[0], p[1]),
                  lambda p: (p[0], -p[1]), lambda p: (-p[1], p[0]),
                  lambda p: (p[1], -p[0]), lambda p: (-p[0], -p[1])]

    def tier_closer_mirror(self, box, k, pure, exact):
        """B the image of A under a symmetry of the square (|A| = |B|),
        then (exact False) moved by a few units: near-ties."""
        labels = (self.rng.choice([0, 1, 2, 2]), self.rng.choice([0, 2]))
        if self.rng.random() < 0.5:
            labels = labels[::-1]
        A = self.tier_point(box, labels, k, pure)
        B = self.rng.choice(self.SYMMETRIES)(A)
        if not exact:
            while True:
                dx, dy = self.rng.randint(-3, 3), self.rng.randint(-3, 3)
                if dx or dy:
                    break
            B = (B[0] + dx, B[1] + dy)
        if A == B or not self.in_box(box, B):
            return None
        return [A, B]

    def tier_closer_edge_pair(self, box, cls, k, target, pure):
        """A = (e, t), B = (e', t') (or transposed), e at the class's edge,
        e' = e moved inwards by 1..3: e^2 - e'^2 + t^2 - t'^2 = target."""
        ea = self.rng.randrange(2)
        edges = self.tier_edges(cls, box[ea])
        if not edges:
            return None
        e = self.rng.choice(edges)
        delta = self.rng.choice([1, 1, 2, 3])
        e2 = e - delta if e > 0 else e + delta
        n = e * e - e2 * e2 - target  # t'^2 - t^2, positive
        assert n > 0
        # n = f g with f = t' - t, g = t' + t of one parity
        fs = [f for f in range(1, min(4096, math.isqrt(n)) + 1)
              if n % f == 0 and (f - n // f) % 2 == 0]
        lo, hi = box[1 - ea]
        fits = []
        for f in fs:
            g = n // f
            t2, t = (g + f) // 2, (g - f) // 2
            for s2 in (-1, 1):
                for s in (-1, 1):
                    if lo <= s2 * t2 <= hi and lo <= s * t <= hi:
                        fits.append((t, s * t, s2 * t2))
        if not fits:
            return None
        if pure or self.rng.random() < 0.5:  # the largest t that fits
            best = max(f[0] for f in fits)
            fits = [f for f in fits if f[0] == best]
        _, t, t2 = self.rng.choice(fits)
        A, B = [e, t], [e2, t2]
        if ea == 1:
            A, B = A[::-1], B[::-1]
        return [tuple(A), tuple(B)]

    def tier_closer_corner_pm1(self, box, k, target):
        """|A|^2 - |B|^2 = (A - B).(A + B) = target with A, B near a box
        corner: w = A - B short and nearly perpendicular to the corner
        direction, z = A + B on the lattice line w.z = target."""
        margin = 1 << self.rng.randint((k + 1) // 2 + 3, (k + 1) // 2 + 6)
        P = tuple(box[a][0] + margin if self.rng.random() < 0.5 else box[a][1] - margin
                  for a in (0, 1))
        size = math.isqrt(P[0] ** 2 + P[1] ** 2) + 1
        scale = 8 * size // margin + 1
        wx = -P[1] * scale // size + self.rng.randint(-2, 2)
        wy = P[0] * scale // size + self.rng.randint(-2, 2)
        g, x, y = egcd(wx, wy)
        if g != 1 or (wx + wy) % 2 == 0:
            return None
        z0 = (x * target, y * target)
        p = (-wy, wx)
        kk = ((2 * P[0] - z0[0]) * p[0] + (2 * P[1] - z0[1]) * p[1]) // (wx * wx + wy * wy)
        for dk in (0, 1, -1, 2, -2):
            z = (z0[0] + (kk + dk) * p[0], z0[1] + (kk + dk) * p[1])
            if (z[0] - wx) % 2 == 0 and (z[1] - wy) % 2 == 0:
                break
        else:
            return None
        A = ((z[0] + wx) // 2, (z[1] + wy) // 2)
        B = ((z[0] - wx) // 2, (z[1] - wy) // 2)
        if not (self.in_box(box, A) and self.in_box(box, B)):
            return None
        assert A[0] ** 2 + A[1] ** 2 - B[0] ** 2 - B[1] ** 2 == target
        return [A, B]

    # -- all ops --------------------------------------------------------------

    def tier_bare(self, op, box, cls, pure):
        """Every difference 0, -1 or at the class's edge (bound 0 or the
        class's): a bitwise OR of the bounds then equals the largest one.
        Where the edge is 2^31 or -2^31 - 1, the differences wrapped to
        int32 (2^31 -> -2^31, -2^31 - 1 -> 2^31 - 1) give the opposite
        sign for many such cases; the pure ones are picked to be among
        them: orient2d (0, -1), (E, 0); incircle (0, -1), (0, E'), (E, 0);
        closer (E, 0), (0, E') with E = -E' - 1 (the edges of a closer
        case lie on different sides, and its two big differences on
        different axes, whenever the box allows)."""
        if op == OP_CLOSER and cls == ("out", 31):
            box = self.rng.sample([(-(1 << 31) - 1, (1 << 31) - 2),
                                   (-(1 << 31) + 1, 1 << 31)], 2)
        edges = [self.tier_edges(cls, box[a]) for a in (0, 1)]
        if op == OP_CLOSER:
            E = self.rng.choice(edges[0])
            opposite = [v for v in edges[1] if (v < 0) != (E < 0)]
            E2 = self.rng.choice(opposite or edges[1])
            if pure or self.rng.random() < 0.5:
                small = [0, 0] if pure else [self.rng.choice([0, -1]) for _ in range(2)]
                small = [s if box[1 - a][0] <= s else 0 for a, s in enumerate(small)]
                return [(E, small[0]), (small[1], E2)]
        elif pure and cls != ("in", 15):
            E, E2 = self.rng.choice(edges[0]), self.rng.choice(edges[1])
            if op == OP_ORIENT2D:
                return [(0, -1), (E, 0)] if box[1][0] < 0 else [(0, 1), (E, 0)]
            if box[1][0] < 0:
                return [(0, -1), (0, E2), (E, 0)]
        values = [[v for v in [0, -1] + edges[a] if box[a][0] <= v <= box[a][1]]
                  for a in (0, 1)]
        n = NPOINTS[op] - 1
        return [(self.rng.choice(values[0]), self.rng.choice(values[1]))
                for _ in range(n)]

    # -- driver -----------------------------------------------------------

    def tier_relative(self, op, cls, kind, variant, pure):
        """The points other than the reference, relative to it, or None."""
        interior = op == OP_INCIRCLE and kind == "max" and variant > 0
        corner = pure and (op != OP_INCIRCLE or (kind == "max" and variant == 0))
        box = self.tier_box(cls, interior, corner)
        k = cls[1]
        if kind == "bare":
            return self.tier_bare(op, box, cls, pure)
        if op == OP_ORIENT2D:
            if kind == "max":
                return self.tier_orient_max(box, k, pure, variant)
            if kind == "zero":
                return self.tier_orient_zero(box, cls, k, pure, variant)
            return self.tier_orient_pm1(box, cls, k, pure, variant)
        if op == OP_INCIRCLE:
            if kind == "max":
                return self.tier_incircle_max(box, k, pure, variant)
            if kind == "zero":
                return self.tier_incircle_zero(box, k, pure, variant)
            return self.tier_incircle_near(box, cls, k, pure, variant)
        if kind == "near":
            return self.tier_closer_mirror(box, k, pure, exact=False)
        if kind == "zero":
            if variant % 2 == 0:
                return self.tier_closer_mirror(box, k, pure, exact=True)
            return self.tier_closer_edge_pair(box, cls, k, 0, pure)
        target = self.rng.choice([-1, 1])
        if variant == 0:
            return self.tier_closer_edge_pair(box, cls, k, target, pure)
        return self.tier_closer_corner_pm1(box, k, target)

    def tier_case(self, op, cls, kind, variant, pure):
        # the power-of-a-point incircle cases and the closer +-1 cases near
        # a corner lie inside the class's box, not on its edge
        exact_class = not ((op == OP_INCIRCLE and kind == "near" and variant % 2 == 1
                            and cls in TIER_CIRCLE_RADII)
                           or (op == OP_CLOSER and kind == "pm1" and variant == 1))
        for _attempt in range(1000):
            rel = self.tier_relative(op, cls, kind, variant, pure)
            if rel is None or (0, 0) in rel:
                continue
            spans = [max(0, *(p[a] for p in rel)) - min(0, *(p[a] for p in rel))
                     for a in (0, 1)]
            assert max(spans) <= L32, (op, cls, kind, variant, rel)
            if exact_class and not class_meets(cls, max(tier_bound(c) for p in rel for c in p)):
                continue
            if op == OP_INCIRCLE and cls == ("in", 15) and (-(1 << 15), -(1 << 15)) not in rel:
                continue  # lift 2^31: the first that int32 cannot hold
            self.rng.shuffle(rel)
            pts = self.translate_into_range([(0, 0)] + rel)
            ref, others = pts[0], pts[1:]
            return [ref] + others if op == OP_CLOSER else others + [ref]
        raise AssertionError(("no tier-edge case", op, cls, kind, variant))

    def gen_tier_edge(self, op, count):
        kinds = self.TIER_KINDS[op]
        for i in range(count):
            cls = TIER_CLASSES[i % len(TIER_CLASSES)]
            n = i // len(TIER_CLASSES)
            kind = kinds[n % len(kinds)]
            # occurrence of this kind within the class
            m = sum(1 for j in range(n) if kinds[j % len(kinds)] == kind)
            variants = self.TIER_VARIANTS[kind]
            pts = self.tier_case(op, cls, kind, m % variants, m < variants)
            self.add(op, pts, PF_TIER_EDGE)

    def generate(self):
        runners = {PF_RANDOM_FULL: self.gen_random_full,
                   PF_RANDOM_SMALL: self.gen_random_small,
                   PF_RANDOM_MID: self.gen_random_mid,
                   PF_COLLINEAR: self.gen_collinear,
                   PF_COCIRCULAR: self.gen_cocircular,
                   PF_OFF_BY_ONE: self.gen_off_by_one,
                   PF_CORNERS: self.gen_corners,
                   PF_PERTURBED: self.gen_perturbed,
                   PF_TIER_EDGE: self.gen_tier_edge}
        for family in range(len(FAMILY_NAMES)):
            for op in (OP_ORIENT2D, OP_INCIRCLE, OP_CLOSER):
                count = PLAN[op].get(family, 0)
                if count:
                    runners[family](op, count)
        return self.cases


# ---------------------------------------------------------------------------
# The power test and the power distance (weighted points): a table of their
# own (struct power_vector), from a generator of their own seed, so that the
# cases above do not depend on it.

INT64_MIN = -(1 << 63)
INT64_MAX = (1 << 63) - 1
WEIGHT_CORNERS = [INT64_MIN, INT64_MIN + 1, -(1 << 62), -1, 0, 1, 1 << 62,
                  INT64_MAX - 1, INT64_MAX]
POWER_OPS = ["PW_TEST", "PW_CLOSER"]
PW_TEST, PW_CLOSER = range(len(POWER_OPS))
POWER_FAMILY_NAMES = ["PWF_RANDOM_FULL", "PWF_RANDOM_SMALL", "PWF_RANDOM_MID",
                      "PWF_EQUAL_WEIGHTS", "PWF_TIED", "PWF_OFF_BY_ONE", "PWF_CORNERS"]
(PWF_RANDOM_FULL, PWF_RANDOM_SMALL, PWF_RANDOM_MID, PWF_EQUAL_WEIGHTS, PWF_TIED,
 PWF_OFF_BY_ONE, PWF_CORNERS) = range(len(POWER_FAMILY_NAMES))
POWER_PLAN = {
    PW_TEST: {PWF_RANDOM_FULL: 400, PWF_RANDOM_SMALL: 500, PWF_RANDOM_MID: 300,
              PWF_EQUAL_WEIGHTS: 400, PWF_TIED: 960, PWF_OFF_BY_ONE: 300, PWF_CORNERS: 300},
    PW_CLOSER: {PWF_RANDOM_FULL: 300, PWF_RANDOM_SMALL: 300, PWF_RANDOM_MID: 200,
                PWF_EQUAL_WEIGHTS: 100, PWF_TIED: 300, PWF_OFF_BY_ONE: 100, PWF_CORNERS: 300},
}


def power_rows(pts, weights):
    return [[x, y, x * x + y * y - w, 1] for (x, y), w in zip(pts, weights)]


def power_exact_sign(op, pts, weights):
    if op == PW_TEST:
        return sgn(det_leibniz(power_rows(pts, weights)))
    (qx, qy), (ax, ay), (bx, by) = pts
    return sgn((qx - ax) ** 2 + (qy - ay) ** 2 - weights[1]
               - (qx - bx) ** 2 - (qy - by) ** 2 + weights[2])


def in_int64(weights):
    return all(INT64_MIN <= w <= INT64_MAX for w in weights)


class PowerGenerator(Generator):
    def __init__(self, seed):
        Generator.__init__(self, seed * 31 + 5)

    def add_power(self, op, pts, weights, family, ranks=None):
        pts = [tuple(p) for p in pts]
        n = 4 if op == PW_TEST else 3
        assert len(pts) == n and len(weights) == n and in_range(pts) and in_int64(weights)
        exact = power_exact_sign(op, pts, weights)
        if op == PW_CLOSER:
            ranks = [0, 0, 0]
            perturbed = exact
        else:
            if ranks is None:
                ranks = self.rng.sample(range(4), 4)
            if exact == 0:
                perturbed = perturbed_sign(OP_INCIRCLE, pts, ranks, weights)
                self.expansions += 1
            else:
                perturbed = exact
                if self.check_rng.random() < 0.05:
                    assert perturbed_sign(OP_INCIRCLE, pts, ranks, weights) == exact
                    self.expansion_checks += 1
        packed = 0
        for k, r in enumerate(ranks):
            packed |= r << (2 * k)
        xy = [c for p in pts for c in p] + [0] * (8 - 2 * n)
        self.cases.append((xy, list(weights) + [0] * (4 - n), op, exact, perturbed, packed,
                           family))

    def weight(self, bits):
        return self.rng.randint(-(1 << bits), (1 << bits) - 1)

    def radius_weight(self):
        """A squared int32 radius: the weights a user gives most."""
        r = self.rng.randint(0, INT32_MAX)
        return r * r

    def unimodular(self):
        """Two integer vectors u, v with u x v = +-1: the identity's rows
        after random shears and a swap, small enough to stay near."""
        u, v = [1, 0], [0, 1]
        for _ in range(self.rng.randint(1, 4)):
            k = self.rng.randint(-3, 3)
            if self.rng.random() < 0.5:
                u = [u[0] + k * v[0], u[1] + k * v[1]]
            else:
                v = [v[0] + k * u[0], v[1] + k * u[1]]
        if self.rng.random() < 0.5:
            u, v = v, u
        assert abs(cross2(u, v)) == 1
        return u, v

    def tied_test(self):
        """Four weighted points on the power test's zero set: three points
        of a unimodular lattice triangle (orientation +-1, so the
        determinant moves by exactly 1 a unit of the fourth point's weight)
        and the fourth's weight solved for; or four collinear points with
        any weights; or a weighted point twice."""
        u = self.rng.random()
        if u < 0.15:
            pts = self.collinear_points(4, distinct=self.rng.random() < 0.5)
            return pts, [self.weight(self.rng.choice([4, 40, 62])) for _ in range(4)]
        if u < 0.3:
            pts = [self.any_point() for _ in range(3)]
            weights = [self.weight(self.rng.choice([4, 40, 62])) for _ in range(3)]
            k = self.rng.randrange(3)
            pts.append(pts[k])
            weights.append(weights[k])
        else:
            while True:
                spread = self.rng.choice([4, 1 << 10, 1 << 14])
                a = self.window_points(1, 1 << 20)[0]
                e, f = self.unimodular()
                d = (a[0] + self.rng.randint(-spread, spread),
                     a[1] + self.rng.randint(-spread, spread))
                pts = [a, (a[0] + e[0], a[1] + e[1]), (a[0] + f[0], a[1] + f[1]), d]
                if not in_range(pts):
                    continue
                bits = self.rng.choice([4, 20, 40])
                weights = [self.weight(bits) for _ in range(3)] + [0]
                d0 = det_leibniz(power_rows(pts, weights))
                weights[3] = 1
                slope = det_leibniz(power_rows(pts, weights)) - d0
                assert abs(slope) == 1
                weights[3] = -d0 * slope
                if in_int64(weights):
                    break
        order = self.rng.sample(range(4), 4)
        pts = [pts[i] for i in order]
        weights = [weights[i] for i in order]
        assert power_exact_sign(PW_TEST, pts, weights) == 0
        return pts, weights

    def tied_closer(self):
        while True:
            u = self.rng.random()
            if u < 0.5:
                pts = [self.point() for _ in range(3)]
            else:
                pts = self.window_points(3, 1 << self.rng.randint(2, 20))
            (qx, qy), (ax, ay), (bx, by) = pts
            wa = self.weight(self.rng.choice([8, 40, 60]))
            wb = wa - ((qx - ax) ** 2 + (qy - ay) ** 2) + (qx - bx) ** 2 + (qy - by) ** 2
            weights = [self.weight(8), wa, wb]
            if in_int64(weights):
                return pts, weights

    def generate_power(self):
        for op in (PW_TEST, PW_CLOSER):
            n = 4 if op == PW_TEST else 3
            plan = POWER_PLAN[op]
            for _ in range(plan[PWF_RANDOM_FULL]):
                pts = [self.point() for _ in range(n)]
                if self.rng.random() < 0.5:
                    weights = [self.weight(63) for _ in range(n)]
                else:
                    weights = [self.radius_weight() for _ in range(n)]
                self.add_power(op, pts, weights, PWF_RANDOM_FULL)
            for i in range(plan[PWF_RANDOM_SMALL]):
                pts = self.window_points(n, 4 if i % 2 == 0 else 1 << self.rng.randint(3, 13))
                self.add_power(op, pts, [self.weight(3 if i % 2 == 0 else 20) for _ in range(n)],
                               PWF_RANDOM_SMALL)
            for _ in range(plan[PWF_RANDOM_MID]):
                pts = self.window_points(n, 1 << self.rng.randint(14, 30))
                self.add_power(op, pts, [self.weight(self.rng.randint(20, 61)) for _ in range(n)],
                               PWF_RANDOM_MID)
            for i in range(plan[PWF_EQUAL_WEIGHTS]):
                if op == PW_TEST:
                    pts = self.degenerate_source(OP_INCIRCLE) if i % 2 else \
                        [self.point() for _ in range(4)]
                else:
                    pts = self.equidistant() if i % 2 else [self.point() for _ in range(3)]
                w = self.rng.choice(WEIGHT_CORNERS + [self.weight(63)])
                self.add_power(op, pts, [w] * n, PWF_EQUAL_WEIGHTS)
            made = 0
            while made < plan[PWF_TIED]:
                if op == PW_CLOSER:
                    pts, weights = self.tied_closer()
                    self.add_power(op, pts, weights, PWF_TIED)
                    made += 1
                    continue
                pts, weights = self.tied_test()
                all_ranks = [list(r) for r in itertools.permutations(range(4))]
                rank_sets = self.rng.sample(all_ranks, 4)[:plan[PWF_TIED] - made]
                for ranks in rank_sets:
                    self.add_power(op, pts, weights, PWF_TIED, ranks)
                made += len(rank_sets)
            for _ in range(plan[PWF_OFF_BY_ONE]):
                # a tie with one weight moved by one: the smallest nonzero
                # determinant (1 in the lattice triangles) or difference
                while True:
                    pts, weights = self.tied_test() if op == PW_TEST else self.tied_closer()
                    k = self.rng.randrange(1, n) if op == PW_CLOSER else self.rng.randrange(n)
                    weights[k] += self.rng.choice([-1, 1])
                    if in_int64(weights) and power_exact_sign(op, pts, weights) != 0:
                        break
                self.add_power(op, pts, weights, PWF_OFF_BY_ONE)
            for i in range(plan[PWF_CORNERS]):
                values = CORNER_VALUES if i % 2 else self.rng.sample(CORNER_VALUES, 3)
                pts = [(self.rng.choice(values), self.rng.choice(values)) for _ in range(n)]
                wvalues = WEIGHT_CORNERS if i % 3 else self.rng.sample(WEIGHT_CORNERS, 2)
                self.add_power(op, pts, [self.rng.choice(wvalues) for _ in range(n)],
                               PWF_CORNERS)
        return self.cases


def c_int64(v):
    if v == INT64_MIN:
        return "INT64_MIN"
    return "INT64_C(%d)" % v


def render_power(cases):
    out = ["const struct power_vector power_vectors[] = {\n"]
    for xy, weights, op, exact, perturbed, ranks, family in cases:
        out.append("    {{%s}, {%s}, %s, %d, %d, 0x%02x, %s},\n" % (
            ", ".join(c_int(v) for v in xy), ", ".join(c_int64(w) for w in weights),
            POWER_OPS[op], exact, perturbed, ranks, POWER_FAMILY_NAMES[family]))
    out.append("};\n\n")
    out.append("const size_t power_vector_count =\n"
               "    sizeof power_vectors / sizeof power_vectors[0];\n")
    return "".join(out)


def check_power_coverage(cases):
    zeros = {PW_TEST: 0, PW_CLOSER: 0}
    families = set()
    for _, _, op, exact, _, _, family in cases:
        zeros[op] += exact == 0
        families.add((op, family))
    assert zeros[PW_TEST] >= 900 and zeros[PW_CLOSER] >= 300, zeros
    assert len(families) == 2 * len(POWER_FAMILY_NAMES)


# ---------------------------------------------------------------------------
# Output.

def c_int(v):
    return "INT32_MIN" if v == INT32_MIN else str(v)


def render(cases, power_cases, command, seed):
    out = []
    out.append("/*\n")
    out.append(" * Generated by: %s\n" % command)
    out.append(" * (seed %d)\n" % seed)
    out.append(" * do not edit: change tools/gen_predicate_vectors.py and rerun.\n")
    out.append(" * %d predicate test vectors; expected signs computed with Python\n"
               " * big integers, perturbed signs by expanding the perturbed\n"
               " * determinant in eps (see the generator's docstring).\n" % len(cases))
    out.append(" */\n")
    out.append('#include "predicate_vectors.h"\n\n')
    out.append("const struct predicate_vector predicate_vectors[] = {\n")
    for xy, op, exact, perturbed, ranks, family in cases:
        out.append("    {{%s}, %s, %d, %d, 0x%02x, %s},\n" % (
            ", ".join(c_int(v) for v in xy), OP_NAMES[op], exact, perturbed,
            ranks, FAMILY_NAMES[family]))
    out.append("};\n\n")
    out.append("const size_t predicate_vector_count =\n"
               "    sizeof predicate_vectors / sizeof predicate_vectors[0];\n\n")
    out.append(render_power(power_cases))
    return "".join(out)


def summarize(cases):
    by = {}
    zeros = {}
    for _, op, exact, _, _, family in cases:
        by[(op, family)] = by.get((op, family), 0) + 1
        if exact == 0:
            zeros[op] = zeros.get(op, 0) + 1
    lines = ["%-14s" % "" + "".join("%12s" % n[3:] for n in OP_NAMES) + "%8s" % "total"]
    for f, name in enumerate(FAMILY_NAMES):
        row = [by.get((op, f), 0) for op in range(3)]
        lines.append("%-14s" % name[3:] + "".join("%12d" % c for c in row)
                     + "%8d" % sum(row))
    tot = [sum(by.get((op, f), 0) for f in range(len(FAMILY_NAMES))) for op in range(3)]
    lines.append("%-14s" % "total" + "".join("%12d" % c for c in tot) + "%8d" % sum(tot))
    lines.append("%-14s" % "exact == 0" + "".join("%12d" % zeros.get(op, 0)
                                                 for op in range(3)))
    return "\n".join(lines), tot, zeros


def check_coverage(cases):
    _, tot, zeros = summarize(cases)
    assert sum(tot) >= 10000
    for op in (OP_ORIENT2D, OP_INCIRCLE):
        assert zeros.get(op, 0) >= 0.2 * tot[op], "too few exact zeros"
        used = {c[4] for c in cases if c[1] == op}
        assert len(used) == math.factorial(NPOINTS[op]), "rank permutation missing"
    assert sum(1 for c in cases if c[5] == PF_PERTURBED) >= 1500
    extreme_zero = [c for c in cases if c[2] == 0 and c[1] != OP_CLOSER
                    and any(v in (INT32_MIN, INT32_MAX) for v in c[0])]
    assert extreme_zero, "no exact zero at the int32 extremes"


def tier_edge_facts(cases):
    """Measure what PF_TIER_EDGE reaches: counts of cases per largest
    bound, and the largest intermediate values of each predicate."""
    facts = {"bound": {}, "zeros_at": {}, "shared": {}, "in15_corner": 0,
             "incircle_det": 0, "mid_cross_det": 0, "lift_65": 0,
             "incircle_cancel": 0, "orient_narrow_det": 0,
             "orient_pm1_narrow": 0, "orient_pm1_wide": 0, "orient_zero_wide": 0,
             "closer_narrow_sum": 0, "closer_pm1_narrow": 0, "closer_pm1_wide": 0,
             "closer_zero_wide": 0}

    def bump(key, sub):
        facts[key][sub] = facts[key].get(sub, 0) + 1

    for xy, op, exact, _, _, family in cases:
        if family != PF_TIER_EDGE:
            continue
        pts = [(xy[2 * k], xy[2 * k + 1]) for k in range(NPOINTS[op])]
        rel = reference_diffs(op, pts)
        m = max_bound(op, pts)
        cls = next((c for c in TIER_CLASSES if class_meets(c, m)), None)
        bump("bound", (op, cls))
        if exact == 0:
            bump("zeros_at", (op, cls))
        if op == OP_INCIRCLE:
            terms = incircle_terms(rel)
            det = abs(sum(terms))
            assert sgn(sum(terms)) == exact
            if len({sgn(t) for t in terms}) == 1 and terms[0] != 0:
                bump("shared", cls)
            if cls == ("in", 15) and (-(1 << 15), -(1 << 15)) in rel:
                facts["in15_corner"] += 1
            facts["incircle_det"] = max(facts["incircle_det"], det)
            crosses = [abs(cross2(p, q)) for p, q in itertools.combinations(rel, 2)]
            if (1 << 30) <= m < (1 << 31) and max(crosses) > 1 << 62:
                facts["mid_cross_det"] = max(facts["mid_cross_det"], det)
            if max(x * x + y * y for x, y in rel) >= 1 << 64:
                facts["lift_65"] += 1
            if 0 < det <= 1 << 64 and max(abs(t) for t in terms) >= 1 << 120:
                facts["incircle_cancel"] += 1
        elif op == OP_ORIENT2D:
            (ux, uy), (vx, vy) = rel
            det = ux * vy - uy * vx
            products = max(abs(ux * vy), abs(uy * vx))
            if m < 1 << 31:
                facts["orient_narrow_det"] = max(facts["orient_narrow_det"], abs(det))
            # the largest product of a +-1 case per tier, of a 0 case above
            key = None
            if abs(det) == 1:
                key = "orient_pm1_narrow" if m < 1 << 31 else "orient_pm1_wide"
            elif det == 0 and m >= 1 << 31:
                key = "orient_zero_wide"
            if key:
                facts[key] = max(facts[key], products)
        else:
            sums = [x * x + y * y for x, y in rel]
            diff = sums[0] - sums[1]
            if m < 1 << 31:
                facts["closer_narrow_sum"] = max(facts["closer_narrow_sum"], *sums)
            key = None
            if abs(diff) == 1:
                key = "closer_pm1_narrow" if m < 1 << 31 else "closer_pm1_wide"
            elif diff == 0 and m >= 1 << 31:
                key = "closer_zero_wide"
            if key:
                facts[key] = max(facts[key], min(sums))
    return facts


def check_tier_edge(cases):
    """Proof that PF_TIER_EDGE hits the tier limits: asserts on the cases
    themselves (run on every generated table)."""
    f = tier_edge_facts(cases)
    for op, least in ((OP_ORIENT2D, 20), (OP_INCIRCLE, 24), (OP_CLOSER, 15)):
        for cls in TIER_CLASSES:  # largest bound exactly 2^30 - 1, 2^30, 2^31 - 1, ...
            assert f["bound"].get((op, cls), 0) >= least, ("tier edge", op, cls)
            assert f["zeros_at"].get((op, cls), 0) >= 3, ("tier edge zeros", op, cls)
    for cls in TIER_CLASSES:  # three terms of one sign: the sum is largest
        assert f["shared"].get(cls, 0) >= 9, cls
    assert f["in15_corner"] >= 20  # a lift of 2^31, the first int32 cannot hold
    # Four points in a box of side L have |incircle| <= L^4 / 2 or so (three
    # corners and d at the centre; a numerical search found nothing
    # larger), so with L = 2^32 - 1 the determinant stays below 2^127: ask
    # for that maximum to within a factor 1 - 2^-29.
    assert f["incircle_det"] >= (1 << 127) - (1 << 98)
    # bound in [2^30, 2^31), a cross product above 2^62, |det| above 2^126:
    # what the mid tier would hold if its limit were 2^31
    assert f["mid_cross_det"] > 1 << 126
    assert f["lift_65"] >= 5  # lifts of 65 bits in the wide tier
    assert f["incircle_cancel"] >= 4  # terms >= 2^120 summing to <= 2^64
    # orient2d: narrow-tier products up to 2^62 whose difference nears 2^63;
    # +-1 and 0 with the largest products each tier allows
    assert f["orient_narrow_det"] >= (1 << 63) - (1 << 33)
    assert f["orient_pm1_narrow"] >= 3 << 60 and f["orient_pm1_wide"] >= 1 << 63
    assert f["orient_zero_wide"] >= 3 << 62
    # closer: narrow-tier sums reaching 2^63; +-1 and 0 with sums near 2^63
    # in the narrow tier and above 2^64 (a 65th bit) in the wide one
    assert f["closer_narrow_sum"] >= (1 << 63) - (1 << 33)
    assert f["closer_pm1_narrow"] >= (1 << 63) - (1 << 58)
    assert f["closer_pm1_wide"] >= 1 << 64
    assert f["closer_zero_wide"] >= (1 << 65) - (1 << 36)
    return f


# ---------------------------------------------------------------------------
# --selftest

def selftest():
    O, I, C = OP_ORIENT2D, OP_INCIRCLE, OP_CLOSER
    # Hand-known exact signs.
    assert exact_sign(O, [(0, 0), (1, 0), (0, 1)]) == 1
    assert exact_sign(O, [(0, 0), (0, 1), (1, 0)]) == -1
    assert exact_sign(O, [(0, 0), (1, 1), (2, 2)]) == 0
    assert exact_sign(I, [(0, 0), (1, 0), (0, 1), (1, 1)]) == 0   # on circle
    assert exact_sign(I, [(0, 0), (2, 0), (0, 2), (1, 1)]) == 1   # inside
    assert exact_sign(I, [(0, 0), (2, 0), (0, 2), (3, 3)]) == -1  # outside
    assert exact_sign(I, [(0, 0), (0, 2), (2, 0), (1, 1)]) == -1  # clockwise abc
    assert exact_sign(C, [(0, 0), (1, 0), (2, 0)]) == -1          # a closer
    assert exact_sign(C, [(0, 0), (3, 4), (5, 0)]) == 0
    big = INT32_MAX
    assert exact_sign(O, [(INT32_MIN, INT32_MIN), (big, INT32_MIN), (big, big)]) == 1
    assert exact_sign(O, [(INT32_MIN, INT32_MIN), (0, 0), (big, big)]) == 0
    assert exact_sign(O, [(INT32_MIN, INT32_MIN), (-1, -1), (big, big)]) == 0
    # Hand-derived perturbed signs.  (0,0),(1,0),(2,0): the largest
    # perturbation is the y of the rank-0 point; its coefficient in the
    # determinant is cx - bx when a has rank 0 (+) and ax - cx when b has
    # rank 0 (-).
    assert perturbed_sign(O, [(0, 0), (1, 0), (2, 0)], [0, 1, 2]) == 1
    assert perturbed_sign(O, [(0, 0), (1, 0), (2, 0)], [1, 0, 2]) == -1
    # a = (0, delta) makes (1, 1) lie strictly inside the circle a, b, c.
    assert perturbed_sign(I, [(0, 0), (1, 0), (0, 1), (1, 1)], [0, 1, 2, 3]) == 1
    # The eps^0 coefficient is the unperturbed determinant.
    poly = perturbed_poly(O, [(0, 0), (1, 0), (0, 1)], [0, 1, 2])
    assert poly[0] == 1

    # Alternative exact formulas (translated, Shewchuk style) on random cases.
    rng = random.Random(12345)
    for _ in range(2000):
        pts = [(rng.randint(INT32_MIN, INT32_MAX), rng.randint(INT32_MIN, INT32_MAX))
               for _ in range(4)]
        (ax, ay), (bx, by), (cx, cy), (dx, dy) = pts
        o = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        assert exact_sign(O, pts[:3]) == sgn(o)
        rows = [(px - dx, py - dy) for px, py in pts[:3]]
        rows = [(u, v, u * u + v * v) for u, v in rows]
        assert exact_sign(I, pts) == sgn(det_leibniz([list(r) for r in rows]))

    # Perturbation: expansion vs concrete eps on degenerate cases.
    gen = Generator(4242)
    cases = []
    for op in (O, I):
        gen.cases = []
        gen.gen_perturbed(op, 240)
        gen.gen_corners(op, 200)
        gen.gen_random_small(op, 200)
        cases += [c for c in gen.cases if c[2] == 0]
    # keep ~200 degenerate cases, spread over the sources
    step = max(1, len(cases) // 200)
    checked = 0
    for xy, op, exact, perturbed, packed, family in cases[::step]:
        n = NPOINTS[op]
        pts = [(xy[2 * k], xy[2 * k + 1]) for k in range(n)]
        ranks = [(packed >> (2 * k)) & 3 for k in range(n)]
        assert concrete_perturbed_sign(op, pts, ranks) == perturbed, (op, pts, ranks)
        checked += 1
    # And the concrete method on the hand-derived cases.
    assert concrete_perturbed_sign(O, [(0, 0), (1, 0), (2, 0)], [1, 0, 2]) == -1
    assert concrete_perturbed_sign(I, [(0, 0), (1, 0), (0, 1), (1, 1)], [0, 1, 2, 3]) == 1

    # PF_TIER_EDGE from another seed: it reaches the tier limits too, and its
    # degenerate cases (differences up to 2^32 - 1) agree with the
    # concrete-eps oracle.
    gen = Generator(4242)
    gen.cases = []
    for op in (O, I, C):
        gen.gen_tier_edge(op, PLAN[op][PF_TIER_EDGE])
    check_tier_edge(gen.cases)
    edge_checked = 0
    for xy, op, exact, perturbed, packed, family in gen.cases:
        if exact == 0 and op != C:
            n = NPOINTS[op]
            pts = [(xy[2 * k], xy[2 * k + 1]) for k in range(n)]
            ranks = [(packed >> (2 * k)) & 3 for k in range(n)]
            assert concrete_perturbed_sign(op, pts, ranks) == perturbed, (op, pts, ranks)
            edge_checked += 1
    # The power test: hand-known signs, equal weights as incircle, and its
    # tied cases' perturbed signs against the concrete-eps oracle.
    P = PW_TEST
    unit = [(0, 0), (2, 0), (0, 2), (1, 1)]
    assert power_exact_sign(P, unit, [0, 0, 0, 0]) == 1          # inside
    assert power_exact_sign(P, unit, [0, 0, 0, -2]) == 0         # orthogonal
    assert power_exact_sign(P, unit, [0, 0, 0, -3]) == -1        # too light
    assert power_exact_sign(P, unit, [5, 5, 5, 5]) == 1          # a common shift
    assert power_exact_sign(PW_CLOSER, [(0, 0), (1, 0), (3, 0)], [0, 0, 8]) == 0
    power_gen = PowerGenerator(4242)
    power_checked = 0
    for case in power_gen.generate_power():
        xy, weights, op, exact, perturbed, packed, family = case
        if op != P:
            continue
        pts = [(xy[2 * k], xy[2 * k + 1]) for k in range(4)]
        if family == PWF_EQUAL_WEIGHTS:
            assert exact == exact_sign(I, pts)
        if exact == 0 and power_checked < 150:
            ranks = [(packed >> (2 * k)) & 3 for k in range(4)]
            assert concrete_perturbed_sign(I, pts, ranks, weights) == perturbed
            power_checked += 1
    print("selftest ok: %d degenerate cases (%d at the tier edges, %d power tests) agree "
          "with the concrete-eps oracle" % (checked + edge_checked + power_checked,
                                           edge_checked, power_checked))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", help="C file to write")
    ap.add_argument("--seed", type=int, default=DEFAULT_SEED)
    ap.add_argument("--selftest", action="store_true",
                    help="check the oracle on known cases and exit")
    ap.add_argument("--stats", action="store_true",
                    help="print case counts per op and family")
    args = ap.parse_args(argv)
    if args.selftest:
        selftest()
        if not args.out:
            return 0
    if not args.out:
        ap.error("--out is required")
    t0 = time.perf_counter()
    gen = Generator(args.seed)
    cases = gen.generate()
    check_coverage(cases)
    facts = check_tier_edge(cases)
    # Echo the command as given (--seed only if it was passed) so the header
    # names exactly what produced the file; the seed is recorded either way.
    command = "python3 tools/gen_predicate_vectors.py --out %s" % args.out
    if args.seed != DEFAULT_SEED or any(a.startswith("--seed") for a in
                                        (argv if argv is not None else sys.argv[1:])):
        command += " --seed %d" % args.seed
    power = PowerGenerator(args.seed)
    power_cases = power.generate_power()
    check_power_coverage(power_cases)
    text = render(cases, power_cases, command, args.seed)
    d = os.path.dirname(args.out)
    if d:
        os.makedirs(d, exist_ok=True)
    tmp = args.out + ".tmp"
    with open(tmp, "w", newline="\n") as f:
        f.write(text)
    os.replace(tmp, args.out)
    if args.stats:
        print(summarize(cases)[0])
        print("expansions: %d degenerate, %d nondegenerate self-checks; %.2f s"
              % (gen.expansions, gen.expansion_checks, time.perf_counter() - t0))
        print("tier edge: |incircle| up to 2^%.9f, mid-bound 2^%.9f; orient2d "
              "narrow |det| 2^%.9f; closer narrow sum 2^%.9f" % tuple(
                  math.log2(facts[key]) for key in ("incircle_det", "mid_cross_det",
                                                    "orient_narrow_det",
                                                    "closer_narrow_sum")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
