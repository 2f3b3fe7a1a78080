#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""compare_interpolate.py - vor_sibson, vor_laplace, vor_interpolate and
vor_interpolate_laplace (tests/reference/vor_interpolate.c) against CGAL's
natural_neighbor_coordinates_2 and linear_interpolation with exact
constructions, and Laplace's coordinates built from CGAL's exact conflict
zone (tests/reference/cgal_interpolate.cpp).

Every coordinate is compared as an exact rational (vor's weight over its
denominator against CGAL's coordinate over its norm, both Fractions), and
so are the interpolated values (vor's numerator and denominator against
CGAL's sum of value * coordinate); vor's rounded value must be CGAL's
value rounded half away from zero. The site sets: uniform random (small,
medium and 2^29 wide), clustered near 2^30, spread over the whole int32
range with sites at its corners, integer grids (cocircular squares, where
the triangulation is not unique but the coordinates are), subsets of
lattice points on one circle with sites around it, collinear sites, and
one or two sites, with repeated points. The queries: random points in and
around the sites' box and near convex combinations of three sites, the
sites, lattice points on hull edges and just
outside them, midpoints of nearest-neighbour pairs (Delaunay edges), the
centres and circumcircle points of grid squares and rings, and far
outside. Where CGAL's functions do not apply (the sites do not span the
plane: collinear, one site) vor is checked against the documented answer,
the linear interpolation along the segment, computed here with Fractions.

Prints failures and ends with "N passed, N failed" (one check per query
and call: the coordinates of vor_sibson and vor_laplace, the values of
vor_interpolate and vor_interpolate_laplace) and the queries by kind of
answer and the coordinates compared; exit status 1 if anything failed.

Usage: compare_interpolate.py VOR_INTERPOLATE CGAL_INTERPOLATE [CASES]
       (tests/reference/reference_run.py)
"""
import atexit
from fractions import Fraction
from math import gcd

from reference_run import run

MIN, MAX = -2**31, 2**31 - 1
stats = {"queries": 0, "coordinates": 0, "outside": 0, "collinear": 0, "site": 0, "edge": 0,
         "inside": 0}
atexit.register(lambda: print("{queries} queries ({site} at a site, {edge} on a hull edge or "
                              "segment, {inside} inside, {outside} outside; {collinear} of them "
                              "against the segment formula), {coordinates} coordinates compared "
                              "exactly".format(**stats)))


def hull(points):
    """The convex hull, counterclockwise, without collinear points."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def half(seq):
        h = []
        for p in seq:
            while len(h) >= 2 and ((h[-1][0] - h[-2][0]) * (p[1] - h[-2][1]) -
                                   (h[-1][1] - h[-2][1]) * (p[0] - h[-2][0])) <= 0:
                h.pop()
            h.append(p)
        return h
    lower, upper = half(pts), half(reversed(pts))
    return lower[:-1] + upper[:-1]


def clamp(v):
    return max(MIN, min(MAX, v))


def lattice_circle(r2):
    """The integer points (x, y) with x^2 + y^2 = r2."""
    out = []
    r = int(r2 ** 0.5) + 1
    for x in range(-r, r + 1):
        y2 = r2 - x * x
        if y2 >= 0:
            y = int(y2 ** 0.5)
            while y * y > y2:
                y -= 1
            while (y + 1) * (y + 1) <= y2:
                y += 1
            if y * y == y2:
                out.extend({(x, y), (x, -y)})
    return out


def sites_of(rng, kind):
    """(points, extra queries) of one case."""
    if kind == 0:  # uniform, even coordinates (integer midpoints)
        half = rng.choice([50, 10**5, 2**29])
        n = rng.randint(3, 150)
        return [(2 * rng.randint(-half, half), 2 * rng.randint(-half, half)) for _ in range(n)], []
    if kind == 1:  # clustered near 2^30
        spread = 2 ** rng.choice([4, 12, 24, 28])
        cx, cy = 2**30 - spread, 2**30 - rng.randint(0, spread)
        n = rng.randint(3, 100)
        return [(cx + 2 * rng.randint(-spread // 2, spread // 2), cy + 2 * rng.randint(-spread // 2, spread // 2))
                for _ in range(n)], []
    if kind == 2:  # the whole int32 range, its corners among the sites
        n = rng.randint(3, 80)
        pts = [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(n)]
        pts += rng.sample([(MIN, MIN), (MAX, MIN), (MAX, MAX), (MIN, MAX)], rng.randint(1, 4))
        extra = [(MAX, MAX), (MIN, MIN), (MAX, 0), (0, MIN), (MAX - 1, MAX - 1), (MIN + 1, MIN + 1)]
        return pts, extra
    if kind == 3:  # a grid: cocircular squares
        s = rng.choice([2, 10, 1000, 2**20, 2**26])
        nx, ny = rng.randint(2, 8), rng.randint(2, 8)
        x0 = clamp(rng.choice([0, -5 * s, 2**30 - nx * s, MIN]))
        y0 = clamp(rng.choice([0, 3 * s, 2**30 - ny * s, MAX - ny * s]))
        pts = [(x0 + i * s, y0 + j * s) for i in range(nx) for j in range(ny)]
        if rng.random() < 0.3 and len(pts) > 4:
            pts = rng.sample(pts, len(pts) - rng.randint(1, len(pts) // 3))
        h = s // 2
        extra = []
        for i in range(nx):
            for j in range(ny):
                x, y = x0 + i * s, y0 + j * s
                extra += [(x + h, y + h), (x + h, y), (x, y + h)]
        if s == 10:  # on the circumcircles of the squares: (5 +- 7, 5 +- 1) about each corner
            for i in range(nx):
                for j in range(ny):
                    x, y = x0 + i * 10 + 5, y0 + j * 10 + 5
                    extra += [(x + a, y + b) for a, b in ((7, 1), (1, 7), (-7, 1), (-1, -7), (5, 5))]
        return pts, extra
    if kind == 4:  # lattice points of one circle, sites around it
        r2 = rng.choice([25, 65, 325, 5525])
        ring = lattice_circle(r2)
        scale = rng.choice([1, 3, 2**10, 2**20])
        cx, cy = rng.choice([(0, 0), (2**30 - 2**28, 2**30 - 2**28), (-2**29, 2**28)])
        chosen = rng.sample(ring, rng.randint(3, len(ring)))
        pts = [(cx + scale * x, cy + scale * y) for x, y in chosen]
        r = int(r2 ** 0.5) + 1
        for _ in range(rng.randint(0, 12)):
            a, b = rng.randint(-3 * r, 3 * r), rng.randint(-3 * r, 3 * r)
            if a * a + b * b > 2 * r2:
                pts.append((cx + scale * a, cy + scale * b))
        if rng.random() < 0.3:
            pts.append((cx, cy))
        extra = [(cx + scale * x, cy + scale * y) for x, y in ring] + [(cx, cy)]
        return pts, extra
    if kind == 5:  # collinear
        dx, dy = rng.choice([(1, 0), (0, 1), (1, 1), (3, -2), (2**20, 2**19)])
        ks = sorted(set(rng.randint(-40, 40) for _ in range(rng.randint(2, 12))))
        x0, y0 = rng.choice([(0, 0), (2**30, -2**29)])
        pts = [(x0 + k * dx, y0 + k * dy) for k in ks]
        extra = []
        for k in range(ks[0] - 2, ks[-1] + 3):
            extra += [(x0 + k * dx, y0 + k * dy), (x0 + k * dx + 1, y0 + k * dy)]
            if dx % 2 == 0 and dy % 2 == 0:
                extra.append((x0 + k * dx + dx // 2, y0 + k * dy + dy // 2))
        return pts, extra
    # one or two sites (and a triangle), with repeated points
    pts = [(rng.randint(-100, 100), rng.randint(-100, 100)) for _ in range(rng.randint(1, 3))]
    return pts, [p for p in pts] + [(0, 0), (pts[0][0] + 1, pts[0][1])]


def queries_of(rng, pts, extra):
    distinct = list(dict.fromkeys(pts))
    xs, ys = [p[0] for p in distinct], [p[1] for p in distinct]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    wx, wy = max(1, (x1 - x0) // 10), max(1, (y1 - y0) // 10)
    qs = [(clamp(rng.randint(x0 - wx, x1 + wx)), clamp(rng.randint(y0 - wy, y1 + wy))) for _ in range(60)]
    qs += rng.sample(distinct, min(len(distinct), 15))
    if len(distinct) >= 3:  # inside the hull: near convex combinations of three sites
        for _ in range(40):
            (ax, ay), (bx, by), (cx, cy) = rng.sample(distinct, 3)
            u, v, w = rng.random(), rng.random(), rng.random()
            t = u + v + w
            qs.append((round((u * ax + v * bx + w * cx) / t), round((u * ay + v * by + w * cy) / t)))
    h = hull(distinct)
    if len(h) >= 3:
        for i in range(len(h)):
            (ax, ay), (bx, by) = h[i], h[(i + 1) % len(h)]
            g = gcd(bx - ax, by - ay)
            sx, sy = (bx - ax) // g, (by - ay) // g
            for k in sorted({1, g // 2, g - 1, rng.randint(1, max(1, g - 1))}):
                if 0 < k < g:
                    px, py = ax + k * sx, ay + k * sy
                    qs.append((px, py))
                    # one step outward (to the right of the counterclockwise edge)
                    ox, oy = (1 if sy > 0 else -1 if sy < 0 else 0), (-1 if sx > 0 else 1 if sx < 0 else 0)
                    qs.append((clamp(px + ox), clamp(py + oy)))
    # midpoints of nearest-neighbour pairs: Delaunay edges
    for p in rng.sample(distinct, min(len(distinct), 12)):
        others = [o for o in distinct if o != p]
        if others:
            o = min(others, key=lambda o: (o[0] - p[0]) ** 2 + (o[1] - p[1]) ** 2)
            if (o[0] - p[0]) % 2 == 0 and (o[1] - p[1]) % 2 == 0:
                qs.append(((o[0] + p[0]) // 2, (o[1] + p[1]) // 2))
    qs += [(clamp(x0 - 3 * wx - 7), clamp(y1 + 5 * wy)), (MIN, MAX), (MAX, MIN)]
    qs += extra
    return list(dict.fromkeys((clamp(x), clamp(y)) for x, y in qs))


def parse(text):
    """{(tag, x, y): fields} of either tool's lines."""
    out = {}
    for line in text.splitlines():
        f = line.split()
        out[(f[0], int(f[1]), int(f[2]))] = f[3:]
    return out


def vor_coordinates(fields):
    if fields[0] in ("outside", "error"):
        return " ".join(fields)
    den = int(fields[0], 16)
    return {int(i.rstrip(":")): Fraction(int(w, 16), den) for i, w in zip(fields[1::2], fields[2::2])}


def cgal_coordinates(fields):
    if fields[0] in ("outside", "none"):
        return fields[0]
    return {int(a): Fraction(b) for a, b in (f.split(":") for f in fields)}


def vor_value(fields):
    if fields[0] in ("outside", "error"):
        return " ".join(fields)
    value, sign, num, den = int(fields[0]), int(fields[1]), int(fields[2], 16), int(fields[3], 16)
    return value, Fraction(sign * num, den), sign


def rounded(f):
    """f rounded to the nearest integer, halves away from zero."""
    a = abs(f)
    r = (a.numerator * 2 + a.denominator) // (2 * a.denominator)
    return -r if f < 0 else r


def segment(pts, q):
    """The documented answer where the sites do not span the plane: q a
    site, or on the segment between two neighbouring collinear sites."""
    first = {}
    for i, p in enumerate(pts):
        first.setdefault(p, i)
    if q in first:
        return {first[q]: Fraction(1)}
    ids = sorted(first.values(), key=lambda i: pts[i])
    for a, b in zip(ids, ids[1:]):
        (ax, ay), (bx, by) = pts[a], pts[b]
        cross = (bx - ax) * (q[1] - ay) - (by - ay) * (q[0] - ax)
        t = (q[0] - ax) * (bx - ax) + (q[1] - ay) * (by - ay)
        l2 = (bx - ax) ** 2 + (by - ay) ** 2
        if cross == 0 and 0 < t < l2:
            return {a: Fraction(l2 - t, l2), b: Fraction(t, l2)}
    return "outside"


def difference(got, ref):
    """What differs between two answers, briefly."""
    if isinstance(got, str) or isinstance(ref, str):
        return f"{got if isinstance(got, str) else 'coordinates'} but CGAL {ref if isinstance(ref, str) else 'coordinates'}"
    ids = sorted(set(got) | set(ref))
    return "; ".join(f"site {i}: {got.get(i)} but CGAL {ref.get(i)}" for i in ids if got.get(i) != ref.get(i))


def case(ctx, number):
    kind = number % 7
    pts, extra = sites_of(ctx.rng, kind)
    if ctx.rng.random() < 0.2:  # repeated points (with other values: the first one counts)
        pts += ctx.rng.sample(pts, min(len(pts), 3))
        ctx.rng.shuffle(pts)
    big = ctx.rng.random() < 0.5
    values = [ctx.rng.randint(MIN, MAX) if big else ctx.rng.randint(-1000, 1000) for _ in pts]
    queries = queries_of(ctx.rng, pts, extra)
    sites_path = ctx.write("sites", [(x, y, v) for (x, y), v in zip(pts, values)])
    queries_path = ctx.write("queries", queries)
    ours, theirs = ctx.vor(sites_path, queries_path), ctx.cgal(sites_path, queries_path)
    ctx.check(ours.returncode == 0 and ours.stderr == "",
              f"case {number}: vor-interpolate {ours.returncode} {ours.stderr!r}")
    ctx.check(theirs.returncode == 0 and theirs.stderr == "",
              f"case {number}: cgal-interpolate {theirs.returncode} {theirs.stderr!r}")
    a, b = parse(ours.stdout), parse(theirs.stdout)
    first = {}
    for i, p in enumerate(pts):
        first.setdefault(p, i)
    for qx, qy in queries:
        stats["queries"] += 1
        where = f"case {number} (kind {kind}, {len(first)} sites), q = ({qx}, {qy})"
        expected = {}
        for tag in "sl":
            ref = cgal_coordinates(b[(tag, qx, qy)])
            if ref == "none":
                ref = segment(pts, (qx, qy))
            expected[tag] = ref
            got = vor_coordinates(a[(tag, qx, qy)])
            if tag == "s":
                stats["outside" if ref == "outside" else ("site", "edge", "inside")[min(len(ref), 3) - 1]] += 1
                stats["collinear"] += 1 if b[(tag, qx, qy)][0] == "none" else 0
            if ref != "outside":
                stats["coordinates"] += len(ref)
            ctx.check(got == ref, f"{where}: {'vor_sibson' if tag == 's' else 'vor_laplace'} "
                                  f"{difference(got, ref)}")
        for tag, call in (("S", "vor_interpolate"), ("L", "vor_interpolate_laplace")):
            ref = expected[tag.lower()]
            if ref != "outside":
                ref = sum((values[i] * c for i, c in ref.items()), Fraction(0))
            got = vor_value(a[(tag, qx, qy)])
            if b[(tag, qx, qy)][0] not in ("none", "outside"):
                ctx.check(Fraction(b[(tag, qx, qy)][0]) == ref,
                          f"{where}: CGAL's linear_interpolation differs from its coordinates")
            if ref == "outside":
                ctx.check(got == "outside", f"{where}: {call} {got} but CGAL outside")
            else:
                ctx.check(got != "outside" and not isinstance(got, str) and got[1] == ref and
                          got[0] == rounded(ref) and got[2] == (ref > 0) - (ref < 0),
                          f"{where}: {call} {got} but CGAL {ref} (rounded {rounded(ref)})")


run(280, 27, case)
