#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Generates tests/vectors/interpolate_vectors.h: natural-neighbour
coordinates (Sibson's and Laplace's) by brute force, independently of
src/interpolate.c.

Each query point's coordinates come from exact rational clipping with
fractions.Fraction: q's cell in the diagram with q added (a huge box cut
by the bisectors of q with every site), then the area it takes from site
i (that cell cut by the bisectors of site i with every other site), over
the whole cell's area. On the hull's boundary the coordinates are the
limit there, linear along the edge; at a site, that site alone; outside
the hull, none.

With --field it writes tests/vectors/field_vectors.h instead: whole
field frames (vor_field_raster), each pixel the value at its centre of
the same brute-force coordinates, rounded once (halves away from zero),
or FV_OUTSIDE outside the hull.

Usage: python3 tools/gen_interpolate_vectors.py > tests/vectors/interpolate_vectors.h
       python3 tools/gen_interpolate_vectors.py --field > tests/vectors/field_vectors.h
"""
import sys
import random
from fractions import Fraction as F

BIG = F(2) ** 130  # far beyond any vertex of a bounded cell of int32 sites


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def clip(poly, a, b, c):
    """poly cut to a x + b y <= c."""
    out = []
    for i, p in enumerate(poly):
        r = poly[(i + 1) % len(poly)]
        fp = a * p[0] + b * p[1] - c
        fr = a * r[0] + b * r[1] - c
        if fp <= 0:
            out.append(p)
        if (fp < 0 < fr) or (fr < 0 < fp):
            t = fp / (fp - fr)
            out.append((p[0] + t * (r[0] - p[0]), p[1] + t * (r[1] - p[1])))
    return out


def area2(poly):
    return sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
               for i in range(len(poly)))


def nearer(p, o):
    """The half-plane of points at least as near p as o."""
    return (2 * (o[0] - p[0]), 2 * (o[1] - p[1]), o[0] ** 2 + o[1] ** 2 - p[0] ** 2 - p[1] ** 2)


def hull_edge_around(sites, q):
    """The two sites around q on the hull's boundary, or None."""
    for A in sites:
        for B in sites:
            if A == B or orient(A, B, q) != 0 or any(orient(A, B, c) < 0 for c in sites):
                continue
            d = (B[0] - A[0], B[1] - A[1])
            t = lambda p: (p[0] - A[0]) * d[0] + (p[1] - A[1]) * d[1]
            line = [p for p in sites if orient(A, B, p) == 0]
            lo = [p for p in line if t(p) < t(q)]
            hi = [p for p in line if t(p) > t(q)]
            if lo and hi:
                return max(lo, key=t), min(hi, key=t)
    return None


def natural(sites, q):
    """{site index: Fraction} for distinct sites, or None outside the hull."""
    if q in sites:
        return {sites.index(q): F(1)}
    edge = hull_edge_around(sites, q)
    if edge is not None:
        A, B = edge
        d = (B[0] - A[0], B[1] - A[1])
        la = F((B[0] - q[0]) * d[0] + (B[1] - q[1]) * d[1], d[0] ** 2 + d[1] ** 2)
        return {sites.index(A): la, sites.index(B): 1 - la}
    if len(sites) < 3 or all(orient(sites[0], sites[1], c) == 0 for c in sites):
        return None
    for A in sites:
        for B in sites:
            if A != B and orient(A, B, q) < 0 and all(orient(A, B, c) >= 0 for c in sites):
                return None
    cell = [(-BIG, -BIG), (BIG, -BIG), (BIG, BIG), (-BIG, BIG)]
    for s in sites:
        cell = clip(cell, *nearer(q, s))
    total = area2(cell)
    out = {}
    for i, p in enumerate(sites):
        piece = cell
        for j, o in enumerate(sites):
            if piece and j != i:
                piece = clip(piece, *nearer(p, o))
        if piece and area2(piece) != 0:
            out[i] = area2(piece) / total
    return out


def laplace(sites, q):
    """Laplace's coordinates of q strictly inside the hull: for each edge
    of q's cell (counterclockwise, v -> w), on the bisector of q and site
    p, |edge| / |p - q| = (p - q) x (w - v) / |p - q|^2, normalised."""
    cell = [(-BIG, -BIG), (BIG, -BIG), (BIG, BIG), (-BIG, BIG)]
    for s in sites:
        cell = clip(cell, *nearer(q, s))
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


def natural_laplace(sites, q):
    """natural() with Laplace's coordinates where q is strictly inside."""
    ref = natural(sites, q)
    if ref is None or q in sites or hull_edge_around(sites, q) is not None:
        return ref
    return laplace(sites, q)


def words(v):
    out = []
    while True:
        out.append(v & 0xFFFFFFFF)
        v >>= 32
        if v == 0:
            return out


def main():
    rng = random.Random(26)
    configs = []
    # cocircular: the square, the square with its centre, a 3x3 grid
    configs.append([(0, 0), (4, 0), (4, 4), (0, 4)])
    configs.append([(0, 0), (4, 0), (4, 4), (0, 4), (2, 2)])
    configs.append([(x, y) for y in range(0, 9, 4) for x in range(0, 9, 4)])
    # eight points of one circle (x^2 + y^2 = 25) and its centre
    configs.append([(5, 0), (3, 4), (0, 5), (-4, 3), (-5, 0), (-3, -4), (0, -5), (4, -3)])
    configs.append([(5, 0), (3, 4), (0, 5), (-4, 3), (-5, 0), (-3, -4), (0, -5), (4, -3), (0, 0)])
    # collinear hull sites
    configs.append([(0, 0), (3, 0), (6, 0), (9, 0), (4, 5), (0, 6), (9, 6)])
    for _ in range(6):
        n = rng.randint(3, 9)
        configs.append(list({(rng.randint(-9, 9), rng.randint(-9, 9)) for _ in range(n)}))
    for _ in range(2):  # wide coordinates
        n = rng.randint(4, 7)
        configs.append(list({(rng.randint(-2**31, 2**31 - 1), rng.randint(-2**31, 2**31 - 1))
                             for _ in range(n)}))
    print("/* SPDX-License-Identifier: MIT */")
    print("/* Generated by: python3 tools/gen_interpolate_vectors.py > tests/vectors/interpolate_vectors.h")
    print(" * Sibson coordinates by exact rational clipping (fractions.Fraction). */")
    print("#ifndef INTERPOLATE_VECTORS_H\n#define INTERPOLATE_VECTORS_H\n#include <stdint.h>\n#include \"vor.h\"\n")
    print("typedef struct { uint32_t site; uint32_t num_words; uint32_t den_words; const uint32_t *num; const uint32_t *den; } ipv_weight_t;")
    print("typedef struct { uint32_t config; vor_point_t q; int outside; uint32_t count; const ipv_weight_t *weights; const ipv_weight_t *laplace; } ipv_query_t;")
    print("typedef struct { uint32_t n; const vor_point_t *sites; } ipv_config_t;\n")
    queries = []
    for ci, sites in enumerate(configs):
        print(f"static const vor_point_t ipv_sites_{ci}[] = {{" +
              ", ".join(f"{{{x}, {y}}}" for x, y in sites) + "};")
        xs = [p[0] for p in sites]
        ys = [p[1] for p in sites]
        qs = [sites[0]]
        a, b = sites[0], sites[-1]
        qs.append(((a[0] + b[0]) // 2, (a[1] + b[1]) // 2))
        for _ in range(7):
            qs.append((rng.randint(min(xs) - 1, max(xs) + 1), rng.randint(min(ys) - 1, max(ys) + 1)))
        for q in qs:
            queries.append((ci, q, natural(sites, q), natural_laplace(sites, q)))
    print(f"static const ipv_config_t ipv_configs[] = {{" +
          ", ".join(f"{{{len(s)}u, ipv_sites_{i}}}" for i, s in enumerate(configs)) + "};")
    for qi, (ci, q, ref, lap) in enumerate(queries):
        if not ref:
            continue
        for name, table in (("w", ref), ("l", lap)):
            for site, lam in sorted(table.items()):
                print(f"static const uint32_t ipv_{name}n_{qi}_{site}[] = {{" +
                      ", ".join(f"0x{w:08x}u" for w in words(lam.numerator)) + "};")
                print(f"static const uint32_t ipv_{name}d_{qi}_{site}[] = {{" +
                      ", ".join(f"0x{w:08x}u" for w in words(lam.denominator)) + "};")
            print(f"static const ipv_weight_t ipv_{name}_{qi}[] = {{" + ", ".join(
                f"{{{site}u, {len(words(lam.numerator))}u, {len(words(lam.denominator))}u, "
                f"ipv_{name}n_{qi}_{site}, ipv_{name}d_{qi}_{site}}}"
                for site, lam in sorted(table.items())) + "};")
    print("static const ipv_query_t ipv_queries[] = {")
    for qi, (ci, q, ref, lap) in enumerate(queries):
        if ref:
            print(f"    {{{ci}u, {{{q[0]}, {q[1]}}}, 0, {len(ref)}u, ipv_w_{qi}, ipv_l_{qi}}},")
        else:
            print(f"    {{{ci}u, {{{q[0]}, {q[1]}}}, 1, 0u, 0, 0}},")
    print("};\n#endif")


def rounded(x):
    """x rounded to an integer, halves away from zero."""
    m = (abs(x) * 2 + 1) // 2
    return m if x >= 0 else -m


FV_OUTSIDE = -2147483647 - 1


def field_frames():
    """(name, sites, values, (origin_x, origin_y, step_x, step_y, width, height)):
    every frame 20 x 12, partly outside the hull."""
    rng = random.Random(2611)
    frames = []
    sites = list(dict.fromkeys((rng.randint(-8, 8), rng.randint(-5, 5)) for _ in range(9)))
    frames.append(("random", sites, [rng.randint(-1000, 1000) for _ in sites], (-10, -6, 1, 1, 20, 12)))
    # a cocircular grid (squares of four sites: ties); odd differences
    # give halves on the edges and at the squares' centres
    grid = [(x, y) for y in range(0, 9, 4) for x in range(0, 13, 4)]
    gv = [3, -8, 17, 0, -5, 100, -31, 6, 1, -2, 55, -77]
    frames.append(("grid", grid, gv, (-2, -1, 1, 1, 20, 12)))
    # collinear sites: only the pixels on their segment are inside
    line = [(0, 0), (4, 2), (12, 6), (-6, -3), (8, 4)]
    frames.append(("line", line, [0, 41, -17, 9, 1000], (-8, -4, 1, 1, 20, 12)))
    # steps > 1, wider coordinates, values near the int32 ends
    wide = list(dict.fromkeys((rng.randint(-60, 60), rng.randint(-50, 50)) for _ in range(11)))
    frames.append(("steps", wide, [rng.randint(-2**30, 2**30) for _ in wide], (-55, -43, 5, 7, 20, 12)))
    # a hull of collinear sides and a site inside
    hull = [(0, 0), (3, 0), (6, 0), (9, 0), (4, 5), (0, 6), (9, 6), (0, 3)]
    frames.append(("hull", hull, [10, -20, 30, -40, 50, -60, 70, 81], (-3, -2, 1, 1, 20, 12)))
    return frames


def field_value(sites, values, q, coordinates):
    """(the rounded value or FV_OUTSIDE, the natural neighbours: 0 outside)."""
    lam = coordinates(sites, q)
    if lam is None:
        return FV_OUTSIDE, 0
    return rounded(sum(values[i] * w for i, w in lam.items())), len(lam)


def field_main():
    print("/* SPDX-License-Identifier: MIT */")
    print("/* Generated by: python3 tools/gen_interpolate_vectors.py --field > tests/vectors/field_vectors.h")
    print(" * Field frames: each pixel the Sibson (and Laplace) interpolant at its centre from")
    print(" * coordinates by exact rational clipping (fractions.Fraction), rounded once, halves")
    print(" * away from zero; FV_OUTSIDE outside the hull. */")
    print("#ifndef FIELD_VECTORS_H\n#define FIELD_VECTORS_H\n#include <stdint.h>\n#include \"vor_raster.h\"\n")
    print("#define FV_OUTSIDE (-2147483647 - 1)")
    print("typedef struct { const char *name; uint32_t n; const vor_point_t *sites; const int32_t *values;")
    print("                 vor_raster_frame_t frame; const int32_t *sibson; const int32_t *laplace;")
    print("                 const uint8_t *sibson_count; const uint8_t *laplace_count; } fv_frame_t;\n")
    frames = field_frames()
    for fi, (name, sites, values, fr) in enumerate(frames):
        ox, oy, sx, sy, w, h = fr
        print(f"static const vor_point_t fv_sites_{fi}[] = {{" + ", ".join(f"{{{x}, {y}}}" for x, y in sites) + "};")
        print(f"static const int32_t fv_values_{fi}[] = {{" + ", ".join(str(v) for v in values) + "};")
        for tag, fn in (("sibson", natural), ("laplace", natural_laplace)):
            got = [field_value(sites, values, (ox + i * sx, oy + j * sy), fn) for j in range(h) for i in range(w)]
            px = [v for v, _ in got]
            print(f"static const int32_t fv_{tag}_{fi}[] = {{")
            for j in range(h):
                print("    " + ", ".join("FV_OUTSIDE" if v == FV_OUTSIDE else str(v) for v in px[j * w:(j + 1) * w]) + ",")
            print("};")
            print(f"static const uint8_t fv_{tag}_count_{fi}[] = {{" + ", ".join(str(k) for _, k in got) + "};")
    print("static const fv_frame_t fv_frames[] = {")
    for fi, (name, sites, values, fr) in enumerate(frames):
        print(f"    {{\"{name}\", {len(sites)}u, fv_sites_{fi}, fv_values_{fi}, "
              f"{{{fr[0]}, {fr[1]}, {fr[2]}, {fr[3]}, {fr[4]}u, {fr[5]}u}}, fv_sibson_{fi}, fv_laplace_{fi}, "
              f"fv_sibson_count_{fi}, fv_laplace_count_{fi}}},")
    print("};\n#endif")


if __name__ == "__main__":
    if sys.argv[1:] == ["--field"]:
        field_main()
    else:
        main()
