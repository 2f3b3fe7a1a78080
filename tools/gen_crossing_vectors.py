#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""gen_crossing_vectors.py - test vectors for the predicates on crossing
vertices (src/crossing.c): orientation and incircle of vertices that are
sites or crossing points of two site-to-site segments, with their exact
sign and their sign under the symbolic perturbation.

Every expected sign comes from Python's exact rationals (fractions), the
crossing point from the two lines' equations, and the perturbed sign from
expanding the determinant as a polynomial in eps (the perturbation of
docs/design/predicates.md applied to each vertex's rational coordinates;
tools/gen_predicate_vectors.py's expansion). Nothing is shared with the C
code. Writes build/gen/crossing_vectors.c (layout:
tests/vectors/crossing_vectors.h).
"""
import argparse
import random
import sys
from fractions import Fraction

import gen_predicate_vectors as pv

INT32_MIN = -(1 << 31)
INT32_MAX = (1 << 31) - 1

OP_ORIENT2D = 0
OP_INCIRCLE = 1


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def crossing_point(a, b, c, d):
    """The point where line a-b meets line c-d (not parallel)."""
    w = cross(sub(b, a), sub(d, c))
    assert w != 0
    t = Fraction(cross(sub(c, a), sub(d, c)), w)
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))


def properly_cross(a, b, c, d):
    o1 = pv.sgn(cross(sub(b, a), sub(c, a)))
    o2 = pv.sgn(cross(sub(b, a), sub(d, a)))
    o3 = pv.sgn(cross(sub(d, c), sub(a, c)))
    o4 = pv.sgn(cross(sub(d, c), sub(b, c)))
    return o1 * o2 < 0 and o3 * o4 < 0


class Gen:
    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.cases = []

    def coord(self, span):
        lo = max(INT32_MIN, -span)
        hi = min(INT32_MAX, span)
        return self.rng.randint(lo, hi)

    def point(self, span):
        return (self.coord(span), self.coord(span))

    def segment_pair(self, span):
        """Two segments that cross properly, within [-span, span]^2."""
        while True:
            a, b, c, d = (self.point(span) for _ in range(4))
            if properly_cross(a, b, c, d):
                return (a, b, c, d)

    def through(self, p, span):
        """Two segments crossing exactly at the lattice point p."""
        while True:
            u = (self.rng.randint(1, span), self.rng.randint(-span, span))
            v = (self.rng.randint(-span, span), self.rng.randint(1, span))
            a, b = (p[0] - u[0], p[1] - u[1]), (p[0] + u[0], p[1] + u[1])
            c, d = (p[0] - v[0], p[1] - v[1]), (p[0] + v[0], p[1] + v[1])
            pts = (a, b, c, d)
            if cross(u, v) != 0 and pv.in_range(pts):
                return pts

    def add(self, op, vertices):
        """vertices: each ("site", p) or ("crossing", (a, b, c, d))."""
        n = 3 if op == OP_ORIENT2D else 4
        assert len(vertices) == n
        pts = []
        for kind, v in vertices:
            if kind == "site":
                pts.append((Fraction(v[0]), Fraction(v[1])))
            else:
                pts.append(crossing_point(*v))
        ranks = list(range(n))
        self.rng.shuffle(ranks)
        pop = pv.OP_ORIENT2D if op == OP_ORIENT2D else pv.OP_INCIRCLE
        exact = pv.exact_sign(pop, pts)
        perturbed = pv.perturbed_sign(pop, pts, ranks)
        self.cases.append((op, vertices, exact, perturbed, ranks))

    def vertex(self, span, crossing_share):
        if self.rng.random() < crossing_share:
            return ("crossing", self.segment_pair(span))
        return ("site", self.point(span))

    def generate(self, count):
        spans = [6, 1 << 10, 1 << 20, (1 << 31) - 1]
        for i in range(count):
            span = spans[i % len(spans)]
            family = (i // len(spans)) % 5
            if family <= 1:  # random: some vertices crossings, at least one
                for op in (OP_ORIENT2D, OP_INCIRCLE):
                    n = 3 if op == OP_ORIENT2D else 4
                    vs = [self.vertex(span, 0.5) for _ in range(n)]
                    if all(k == "site" for k, _ in vs):
                        vs[0] = ("crossing", self.segment_pair(span))
                    self.add(op, vs)
            elif family == 2:  # a crossing on the line of two sites (its own segment's ends)
                a, b, c, d = self.segment_pair(span)
                order = [("site", a), ("site", b), ("crossing", (a, b, c, d))]
                self.rng.shuffle(order)
                self.add(OP_ORIENT2D, order)
                self.add(OP_ORIENT2D, [("site", c), ("crossing", (a, b, c, d)), ("site", d)])
            elif family == 3:  # lattice points of a circle, some as crossings
                k = self.rng.randint(1, max(1, min(span, 1 << 26) // 5))
                ring = [(5, 0), (4, 3), (3, 4), (0, 5), (-3, 4), (-4, 3), (-5, 0), (-4, -3),
                        (-3, -4), (0, -5), (3, -4), (4, -3)]
                picks = self.rng.sample(ring, 4)
                vs = []
                for j, (x, y) in enumerate(picks):
                    p = (k * x, k * y)
                    if j % 2 == 0 or self.rng.random() < 0.5:
                        vs.append(("crossing", self.through(p, min(span, 1 << 24) if span > 6 else 6)))
                    else:
                        vs.append(("site", p))
                self.add(OP_INCIRCLE, vs)
                self.add(OP_ORIENT2D, vs[:3])
            else:  # collinear: crossings through lattice points of one line
                u = (self.rng.randint(-3, 3), self.rng.randint(-3, 3))
                if u == (0, 0):
                    u = (1, 2)
                k = self.rng.randint(1, max(1, min(span, 1 << 24) // 8))
                vs = []
                for j in range(4):
                    p = (u[0] * k * (j - 1), u[1] * k * (j - 1))
                    lim = min(span, 1 << 24) if span > 6 else 6
                    vs.append(("crossing", self.through(p, lim)) if j != 1 else ("site", p))
                self.add(OP_ORIENT2D, vs[:3])
                # four on one line: the incircle's first terms vanish too
                self.add(OP_INCIRCLE, vs)
                # an axis-parallel line: more terms vanish
                a = [("crossing", self.through((0, k * j), lim)) if j % 2 else ("site", (0, k * j))
                     for j in range(4)]
                self.add(OP_ORIENT2D, a[:3])
                self.add(OP_INCIRCLE, a)
        return self.cases


def c_vertex(kind, v):
    if kind == "site":
        vals = [v[0], v[1], 0, 0, 0, 0, 0, 0]
    else:
        vals = [c for p in v for c in p]
    return "{" + ", ".join(pv.c_int(x) for x in vals) + "}"


def render(cases, seed):
    out = ["/* SPDX-License-Identifier: MIT */",
           "/* Generated by tools/gen_crossing_vectors.py --seed %d: do not edit. */" % seed,
           '#include "crossing_vectors.h"', "",
           "const struct crossing_vector crossing_vectors[] = {"]
    for op, vs, exact, perturbed, ranks in cases:
        crossing = sum(1 << k for k, (kind, _) in enumerate(vs) if kind == "crossing")
        rk = sum(r << (2 * k) for k, r in enumerate(ranks))
        verts = [c_vertex(k, v) for k, v in vs]
        while len(verts) < 4:
            verts.append("{0, 0, 0, 0, 0, 0, 0, 0}")
        out.append("    {{%s}, %d, %d, %d, %d, %d}," % (", ".join(verts), crossing, op, exact,
                                                     perturbed, rk))
    out.append("};")
    out.append("const size_t crossing_vector_count = sizeof crossing_vectors / sizeof crossing_vectors[0];")
    return "\n".join(out) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--seed", type=int, default=25)
    ap.add_argument("--count", type=int, default=400)
    args = ap.parse_args(argv)
    cases = Gen(args.seed).generate(args.count)
    zeros = sum(1 for c in cases if c[2] == 0)
    assert zeros > len(cases) // 5, zeros
    with open(args.out, "w") as f:
        f.write(render(cases, args.seed))
    print("crossing vectors: %d cases, %d exact zeros" % (len(cases), zeros), file=sys.stderr)


if __name__ == "__main__":
    main()
