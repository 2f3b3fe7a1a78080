# SPDX-License-Identifier: MIT
"""exact_plane.py - exact plane geometry over fractions.Fraction for the
brute-force references written apart from the library: the vectors of
tools/gen_interpolate_vectors.py and the checks of tests/cli/test_cli.py
(which puts tools/ on its import path).

Polygons are lists of (x, y) vertices, counterclockwise; half-planes are
a x + b y <= c. Natural-neighbour coordinates here are those of a point q
strictly inside the hull of distinct sites: q's cell in the diagram with
q added is bounded there (a huge box cut by the bisectors of q with every
site); boundary_coordinates answers sites, hull edges and points outside.
"""
from fractions import Fraction as F

BIG = F(2) ** 130  # far beyond any vertex of a bounded cell of int32 sites


def orient(a, b, c):
    """Twice the signed area of the triangle abc: > 0 counterclockwise."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def boundary_coordinates(sites, q):
    """(True, coordinates) when q is a site, on the boundary of the
    distinct sites' hull or outside it: that site; the limit on the
    boundary, linear between the sites around q on the hull line; None
    outside. (False, None) strictly inside."""
    if q in sites:
        return True, {sites.index(q): F(1)}
    for A in sites:
        for B in sites:
            if A == B or any(orient(A, B, c) < 0 for c in sites):
                continue
            side = orient(A, B, q)
            if side < 0:
                return True, None
            if side == 0:
                d = (B[0] - A[0], B[1] - A[1])
                t = lambda p: (p[0] - A[0]) * d[0] + (p[1] - A[1]) * d[1]
                line = [p for p in sites if orient(A, B, p) == 0]
                lo = [p for p in line if t(p) < t(q)]
                hi = [p for p in line if t(p) > t(q)]
                if not lo or not hi:
                    return True, None
                a, b = max(lo, key=t), min(hi, key=t)
                e = (b[0] - a[0], b[1] - a[1])
                la = F((b[0] - q[0]) * e[0] + (b[1] - q[1]) * e[1], e[0] ** 2 + e[1] ** 2)
                return True, {sites.index(a): la, sites.index(b): 1 - la}
    if len(sites) < 3:
        return True, None  # collinear: answered by the hull-line test above
    return False, None


def clip_half_plane(poly, a, b, c):
    """Sutherland-Hodgman: the part of the convex polygon with a x + b y <= c."""
    out = []
    for k in range(len(poly)):
        p, q = poly[k], poly[(k + 1) % len(poly)]
        fp, fq = a * p[0] + b * p[1] - c, a * q[0] + b * q[1] - c
        if fp <= 0:
            out.append(p)
        if (fp < 0 < fq) or (fq < 0 < fp):
            t = fp / (fp - fq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def polygon_area2(poly):
    """Twice the signed area (shoelace)."""
    return sum(poly[k][0] * poly[(k + 1) % len(poly)][1] - poly[(k + 1) % len(poly)][0] * poly[k][1]
               for k in range(len(poly)))


def nearer(p, o):
    """The half-plane (a, b, c) of the points at least as near p as o."""
    return (2 * (o[0] - p[0]), 2 * (o[1] - p[1]), o[0] ** 2 + o[1] ** 2 - p[0] ** 2 - p[1] ** 2)


def new_site_cell(sites, q):
    """q's cell with q added to the sites (bounded for q inside the hull)."""
    cell = [(-BIG, -BIG), (BIG, -BIG), (BIG, BIG), (-BIG, BIG)]
    for s in sites:
        cell = clip_half_plane(cell, *nearer(q, s))
    return cell


def sibson_inside(sites, q):
    """Sibson's coordinates {site index: Fraction} of q strictly inside
    the hull: the part of q's cell nearer each site than every other site,
    over the whole cell."""
    cell = new_site_cell(sites, q)
    total = polygon_area2(cell)
    out = {}
    for i, p in enumerate(sites):
        piece = cell
        for j, o in enumerate(sites):
            if piece and j != i:
                piece = clip_half_plane(piece, *nearer(p, o))
        if piece and polygon_area2(piece) != 0:
            out[i] = polygon_area2(piece) / total
    return out


def laplace_inside(sites, q):
    """Laplace's coordinates {site index: Fraction} of q strictly inside
    the hull: for each edge v -> w of q's cell (counterclockwise), on the
    bisector of q and site p, |edge| / |p - q| = (p - q) x (w - v) /
    |p - q|^2 (the edge is perpendicular to p - q), normalised; sites
    whose edge has no length are left out."""
    cell = new_site_cell(sites, q)
    t = {}
    for j, v in enumerate(cell):
        w = cell[(j + 1) % len(cell)]
        for i, p in enumerate(sites):
            on = lambda z: (z[0] - p[0]) ** 2 + (z[1] - p[1]) ** 2 == (z[0] - q[0]) ** 2 + (z[1] - q[1]) ** 2
            if v != w and on(v) and on(w):
                a = (p[0] - q[0], p[1] - q[1])
                t[i] = t.get(i, 0) + F(a[0] * (w[1] - v[1]) - a[1] * (w[0] - v[0]), a[0] ** 2 + a[1] ** 2)
    total = sum(t.values())
    return {i: x / total for i, x in t.items() if x != 0}
