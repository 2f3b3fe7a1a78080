#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""compare_cdt.py - `vor cdt` against CGAL's constrained Delaunay
triangulation with exact intersections (tests/reference/cgal_cdt.cpp), on
random inputs: sites over the full int32 range with crossing constraints,
small grids with constraints along and across their lines, near-parallel
crossing pairs, and many constraints through one point.

Crossing vertices are compared by their exact points (both tools in lowest
terms), so the two numberings need not agree. Where the input has no four
cocircular points the constrained Delaunay triangulation is unique and the
triangles must match exactly; on grids and the symmetric star (ties, which
the perturbation and CGAL break differently) the constrained edges, the
vertices and the number of triangles must. Prints failures and ends with
"N passed, N failed"; exit status 1 if anything failed.

Usage: compare_cdt.py VOR CGAL_CDT [CASES] (tests/reference/reference_run.py)
"""
from reference_run import run

MIN, MAX = -2**31, 2**31 - 1


def normalise(text):
    """vor cdt's lines with crossing ids replaced by x:XN/YN/W names,
    each triangle rotated to its least name, as cgal_cdt prints them."""
    names = {}
    lines = text.splitlines()
    for line in lines:
        f = line.split()
        if f[0] == "s":
            names[f[1]] = f"x:{f[6]}/{f[7]}/{f[8]}"
    out = set()
    for line in lines:
        f = line.split()
        if f[0] == "t":
            t = [names.get(v, v) for v in f[1:]]
            k = t.index(min(t))
            out.add("t " + " ".join(t[k:] + t[:k]))
        elif f[0] == "c":
            a, b = sorted(names.get(v, v) for v in f[1:])
            out.add(f"c {a} {b}")
    return out


def case_input(rng, kind):
    if kind == 0:  # full range, generic
        n = rng.randint(4, 60)
        sites = [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(n)]
        pairs = [(rng.randrange(n), rng.randrange(n)) for _ in range(rng.randint(1, 12))]
    elif kind == 1:  # a small grid: ties, constraints along its lines
        w = rng.randint(3, 7)
        sites = [(x, y) for y in range(w) for x in range(w)]
        n = len(sites)
        pairs = [(rng.randrange(n), rng.randrange(n)) for _ in range(rng.randint(1, 10))]
        pairs += [(0, w - 1), (0, n - w), (0, n - 1)]
    elif kind == 2:  # near-parallel crossing pairs, long
        sites, pairs = [], []
        for _ in range(rng.randint(1, 6)):
            a = (rng.randint(MIN // 2, 0), rng.randint(MIN // 2, MAX // 2))
            b = (rng.randint(0, MAX // 2), rng.randint(MIN // 2, MAX // 2))
            d = rng.randint(1, 5)
            c = (a[0], a[1] + d)
            e = (b[0], b[1] - d)
            k = len(sites)
            sites += [a, b, c, e]
            pairs += [(k, k + 1), (k + 2, k + 3)]
        sites += [(rng.randint(MIN // 2, MAX // 2), rng.randint(MIN // 2, MAX // 2)) for _ in range(10)]
    else:  # a star of constraints through one point that is no site
        r = rng.randint(1, 2**20)
        ring = [(5, 0), (4, 3), (3, 4), (0, 5), (-3, 4), (-4, 3), (-5, 0), (-4, -3), (-3, -4), (0, -5),
                (3, -4), (4, -3)]
        sites = [(2 * r * x + 1, 2 * r * y + 1) for x, y in ring]
        sites += [(rng.randint(-10 * r, 10 * r), rng.randint(-10 * r, 10 * r)) for _ in range(8)]
        pairs = [(i, i + 6) for i in range(6)] + [(rng.randrange(20), rng.randrange(20)) for _ in range(3)]
    return sites, pairs


def case(ctx, number):
    kind = number % 4
    sites, pairs = case_input(ctx.rng, kind)
    sp, cp = ctx.write("s", sites), ctx.write("c", pairs)
    v, g = ctx.vor("cdt", sp, cp), ctx.cgal(sp, cp)
    ctx.check(v.returncode == 0 and g.returncode == 0,
              f"case {number}: vor {v.returncode} {v.stderr!r}, cgal {g.returncode} {g.stderr!r}")
    if v.returncode or g.returncode:
        return
    ours, theirs = normalise(v.stdout), set(g.stdout.splitlines())
    if kind in (1, 3):  # ties (a grid, a symmetric star): constraints, vertices, count
        oc = {l for l in ours if l.startswith("c ")}
        tc = {l for l in theirs if l.startswith("c ")}
        ov = {w for l in ours if l.startswith("t ") for w in l.split()[1:]}
        tv = {w for l in theirs if l.startswith("t ") for w in l.split()[1:]}
        same = oc == tc and ov == tv and len(ours) == len(theirs)
    else:
        same = ours == theirs
    ctx.check(same, f"case {number} (kind {kind}): {len(ours ^ theirs)} lines differ, "
                    f"e.g. {sorted(ours ^ theirs)[:4]}")


run(1000, 25, case)
