#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Tests of the host command-line tool build/host/vor (and of
examples/contours, build/host/example-contours beside it).

Expected answers come from Python's big integers, independently of the C
code. Prints failures and ends with "N passed, N failed"; exit status 1 if
anything failed. Usage: tests/cli/test_cli.py path/to/vor
"""
import os
import random
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exact_plane import (boundary_coordinates, clip_half_plane, laplace_inside,  # noqa: E402
                         polygon_area2, sibson_inside)

VOR = sys.argv[1] if len(sys.argv) > 1 else "build/host/vor"
MIN, MAX = -2**31, 2**31 - 1
passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"FAIL {what}")


def sign(v):
    return (v > 0) - (v < 0)


def orient(a, b, c):
    return sign((a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]))


def incircle(a, b, c, d):
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    (ax, ay), (bx, by), (cx, cy) = rows
    la, lb, lc = ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy
    return sign(la * (bx * cy - by * cx) + lb * (cx * ay - cy * ax) + lc * (ax * by - ay * bx))


def run(args, text):
    return subprocess.run([VOR] + args, input=text, capture_output=True, text=True)


def predicates_cases(rng):
    lines, expected = [], []
    for n in range(600):
        small = n % 3 == 0
        coord = (lambda: rng.randint(-3, 3)) if small else (lambda: rng.choice([MIN, MAX, rng.randint(MIN, MAX)]))
        if n % 2:
            pts = [(coord(), coord()) for _ in range(3)]
            lines.append("o " + " ".join(f"{x} {y}" for x, y in pts))
            expected.append(orient(*pts))
        else:
            pts = [(coord(), coord()) for _ in range(4)]
            lines.append("c " + " ".join(f"{x} {y}" for x, y in pts))
            expected.append(incircle(*pts))
        if n % 50 == 0:
            lines.append("")
            lines.append("# a comment line")
    return lines, expected


def brute_delaunay(pts):
    """Empty-circumcircle triangles of points in general position, each
    counterclockwise and rotated to its smallest index."""
    n, out = len(pts), set()
    for i in range(n):
        for j in range(i + 1, n):
            for k in range(j + 1, n):
                o = orient(pts[i], pts[j], pts[k])
                assert o != 0, "test set not in general position"
                a, b, c = (i, j, k) if o > 0 else (i, k, j)
                inside = [incircle(pts[a], pts[b], pts[c], pts[l]) for l in range(n) if l not in (i, j, k)]
                assert 0 not in inside, "test set not in general position"
                if all(v < 0 for v in inside):
                    out.add((a, b, c))
    return out


def delaunay_cases(rng):
    # random full-range sets: exact predicates decide everything
    for n in (3, 4, 7, 15, 30):
        pts = [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(n)]
        text = "# random\n" + "\n".join(f"{x} {y}" for x, y in pts) + "\n"
        r = run(["delaunay", "-"], text)
        check(r.returncode == 0, f"delaunay n={n}: status {r.returncode} {r.stderr}")
        got = set()
        for line in r.stdout.splitlines():
            f = line.split()
            check(f[0] == "t" and len(f) == 4, f"delaunay n={n}: line {line!r}")
            got.add(tuple(int(v) for v in f[1:]))
        check(got == brute_delaunay(pts), f"delaunay n={n}: {len(got)} triangles differ from brute force")
        lines = r.stdout.splitlines()
        check(lines == sorted(lines, key=lambda l: tuple(int(v) for v in l.split()[1:])),
              f"delaunay n={n}: output not sorted")
    # duplicates: "d i j" for a repeated site, j its first occurrence
    pts = [(0, 0), (100, 0), (0, 100), (100, 0), (0, 0), (100, 100)]
    r = run(["delaunay", "-"], "\n".join(f"{x} {y}" for x, y in pts) + "\n")
    dups = [l for l in r.stdout.splitlines() if l.startswith("d ")]
    check(dups == ["d 3 1", "d 4 0"], f"duplicates: {dups}")
    tris = [l for l in r.stdout.splitlines() if l.startswith("t ")]
    check(len(tris) == 2, f"square with duplicates: {tris}")
    # --stats on stderr, output unchanged
    r2 = run(["delaunay", "--stats", "-"], "\n".join(f"{x} {y}" for x, y in pts) + "\n")
    check(r2.stdout == r.stdout, "--stats changed stdout")
    check(r2.stderr.startswith("sites=6 triangles=2 bytes=") and "seconds=" in r2.stderr
          and "incircle narrow=" in r2.stderr, f"--stats line: {r2.stderr!r}")
    # collinear sites: no triangle (the true triangulation, not the
    # perturbed mesh's zero-area ones)
    r = run(["delaunay", "-"], "".join(f"{3 * t} {5 * t}\n" for t in range(6)))
    tris = [l for l in r.stdout.splitlines() if l.startswith("t ")]
    check(r.returncode == 0 and tris == [], f"collinear: {tris}")
    # grids: 2n - h - 2 counterclockwise triangles of nonzero area (h the
    # sites on the hull's boundary) whose areas add up to the hull's
    for cols, rows in ((2, 3), (4, 4), (7, 5)):
        pts = [(1000 * x, 1000 * y) for y in range(rows) for x in range(cols)]
        r = run(["delaunay", "-"], "".join(f"{x} {y}\n" for x, y in pts))
        tris = [tuple(int(v) for v in l.split()[1:]) for l in r.stdout.splitlines()]
        n, h = cols * rows, 2 * (cols + rows) - 4
        areas = [(pts[b][0] - pts[a][0]) * (pts[c][1] - pts[a][1]) -
                 (pts[b][1] - pts[a][1]) * (pts[c][0] - pts[a][0]) for a, b, c in tris]
        check(r.returncode == 0 and len(tris) == 2 * n - h - 2 and min(areas) > 0 and
              sum(areas) == 2 * 1000 ** 2 * (cols - 1) * (rows - 1),
              f"{cols} x {rows} grid: {len(tris)} triangles, areas {areas}")
    # bad input
    for text, line in (("0 0\n1 2 3\n", 2), ("0 0\n\n1 x\n", 3), ("2147483648 0\n", 1)):
        r = run(["delaunay", "-"], text)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: <stdin>:{line}: "),
              f"delaunay bad input {text!r}: {r.returncode} {r.stderr!r}")
    r = run(["delaunay", "/no/such/file"], "")
    check(r.returncode == 2 and r.stdout == "", "missing file: status 2")
    # --algo: every builder prints the same triangles and duplicates as the
    # default one, checked against brute force above (small range: many
    # duplicates, collinear and cocircular sites)
    for n in (3, 9, 40, 300):
        pts = [(rng.randint(-20, 20), rng.randint(-20, 20)) for _ in range(n)]
        text = "\n".join(f"{x} {y}" for x, y in pts) + "\n"
        ref = run(["delaunay", "-"], text)
        check(ref.returncode == 0 and ref.stdout.startswith("t "), f"delaunay n={n}: {ref.stderr}")
        for algo in ("incremental", "dc", "dc-quadtree"):
            r = run(["delaunay", f"--algo={algo}", "-"], text)
            check(r.returncode == 0 and r.stdout == ref.stdout,
                  f"--algo={algo} n={n}: output differs from the default build")
    r = run(["delaunay", "--algo=sweep", "-"], "0 0\n")
    check(r.returncode == 2 and "usage" in r.stderr, f"unknown --algo: {r.returncode}")


def nearest_cases(rng, tmp):
    """vor nearest against brute force: exact squared distances, ties to
    the smaller index, duplicates answered by their first occurrence."""
    import os
    sets = {
        "random": [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(300)],
        "grid": [(x * 10, y * 10) for x in range(12) for y in range(12)],
        "duplicates": [(rng.randint(0, 5) * 7, rng.randint(0, 5) * 7) for _ in range(120)],
        "collinear": [(3 * t, 5 * t) for t in (rng.randint(-50, 50) for _ in range(60))],
    }
    for name, sites in sets.items():
        queries = [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(50)]
        lo_x, hi_x = min(x for x, _ in sites), max(x for x, _ in sites)
        lo_y, hi_y = min(y for _, y in sites), max(y for _, y in sites)
        queries += [(rng.randint(lo_x - 3, hi_x + 3), rng.randint(lo_y - 3, hi_y + 3)) for _ in range(250)]
        queries += [(x + 5, y + 5) for x, y in sites[:40]] + sites[:20]
        sp, qp = os.path.join(tmp, name + ".sites"), os.path.join(tmp, name + ".queries")
        with open(sp, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in sites))
        with open(qp, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in queries))
        r = run(["nearest", sp, qp], "")
        check(r.returncode == 0, f"nearest {name}: status {r.returncode} {r.stderr}")
        got = r.stdout.split()
        check(len(got) == len(queries), f"nearest {name}: {len(got)} answers for {len(queries)}")
        wrong = 0
        for (qx, qy), g in zip(queries, got):
            best = min(range(len(sites)), key=lambda i: ((sites[i][0] - qx) ** 2 + (sites[i][1] - qy) ** 2, i))
            wrong += int(g) != best
        check(wrong == 0, f"nearest {name}: {wrong} of {len(queries)} answers differ from brute force")
        # the k nearest: distinct sites (first occurrences) by (distance, index)
        k = 7
        r = run(["nearest", f"--k={k}", sp, qp], "")
        lines = r.stdout.splitlines()
        check(r.returncode == 0 and len(lines) == len(queries), f"nearest --k {name}: {r.returncode} {r.stderr}")
        first = {}
        for i, p in enumerate(sites):
            first.setdefault(p, i)
        distinct = sorted(first.values())
        wrong = 0
        for (qx, qy), line in zip(queries, lines):
            ranked = sorted(distinct, key=lambda i: ((sites[i][0] - qx) ** 2 + (sites[i][1] - qy) ** 2, i))
            wrong += [int(v) for v in line.split()] != ranked[:k]
        check(wrong == 0, f"nearest --k={k} {name}: {wrong} of {len(queries)} lists differ from brute force")
    with open(os.path.join(tmp, "bad"), "w") as f:
        f.write("1 2\n3\n")
    r = run(["nearest", os.path.join(tmp, "grid.sites"), os.path.join(tmp, "bad")], "")
    check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: {os.path.join(tmp, 'bad')}:2: "),
          f"nearest bad query line: {r.returncode} {r.stderr!r}")


def locate_within_cases(rng, tmp):
    """vor locate against the triangles of vor delaunay, each tested with
    exact orientations and the documented tie rule (the query moved up by
    e, right by e^4); vor within against exact squared distances."""
    import os

    def orient(a, b, q):
        d = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])
        if d == 0:
            d = b[0] - a[0]
        if d == 0:
            d = a[1] - b[1]
        return d

    sets = {
        "random": [(rng.randint(-400, 400) * 2, rng.randint(-400, 400) * 2) for _ in range(150)],
        "grid": [(x * 10, y * 10) for x in range(10) for y in range(10)],
        "duplicates": [(rng.randint(0, 5) * 8, rng.randint(0, 5) * 8) for _ in range(60)],
        "collinear": [(3 * t, 5 * t) for t in (rng.randint(-50, 50) for _ in range(30))],
        "wide": [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(60)],
        "two": [(0, 0), (5, 5)],
    }
    for name, sites in sets.items():
        lo_x, hi_x = min(x for x, _ in sites), max(x for x, _ in sites)
        lo_y, hi_y = min(y for _, y in sites), max(y for _, y in sites)
        queries = [(rng.randint(lo_x - 3, hi_x + 3), rng.randint(lo_y - 3, hi_y + 3)) for _ in range(150)]
        queries += sites[:30] + [((a[0] + b[0]) // 2, (a[1] + b[1]) // 2) for a, b in zip(sites, sites[1:40])]
        queries += [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(20)]
        sp, qp = os.path.join(tmp, name + ".lsites"), os.path.join(tmp, name + ".lqueries")
        with open(sp, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in sites))
        with open(qp, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in queries))
        triangles = [tuple(int(v) for v in line.split()[1:]) for line in run(["delaunay", sp], "").stdout.splitlines()]
        r = run(["locate", sp, qp], "")
        lines = r.stdout.splitlines()
        check(r.returncode == 0 and len(lines) == len(queries), f"locate {name}: {r.returncode} {r.stderr}")
        wrong = 0
        for q, line in zip(queries, lines):
            holding = [t for t in triangles
                       if all(orient(sites[t[k]], sites[t[(k + 1) % 3]], q) > 0 for k in range(3))]
            want = "outside" if not holding else "t %d %d %d" % holding[0]
            wrong += len(holding) > 1 or line != want
        check(wrong == 0, f"locate {name}: {wrong} of {len(queries)} answers differ from brute force")
        first = {}
        for i, p in enumerate(sites):
            first.setdefault(p, i)
        for r2 in (0, 100, 12345, 2**62):
            r = run(["within", "--r2", str(r2), sp, qp], "")
            lines = r.stdout.split("\n")[:-1]
            check(r.returncode == 0 and len(lines) == len(queries), f"within {name}: {r.returncode} {r.stderr}")
            wrong = 0
            for (qx, qy), line in zip(queries, lines):
                want = sorted(i for i in first.values() if (sites[i][0] - qx) ** 2 + (sites[i][1] - qy) ** 2 <= r2)
                wrong += [int(v) for v in line.split()] != want or (not want and line != "")
            check(wrong == 0, f"within --r2 {r2} {name}: {wrong} of {len(queries)} lines differ from brute force")
    sp = os.path.join(tmp, "grid.lsites")
    for args, reason in ((["within", sp, sp], "--r2"), (["within", "--r2", "-1", sp, sp], "'-1'"),
                         (["within", "--r2", "x", sp, sp], "'x'"), (["locate", sp], "missing QUERIES"),
                         (["locate", "--r2", "1", sp, sp], "unknown option '--r2'"),
                         (["within", "--r2", "9223372036854775808", sp, sp], "9223372036854775808")):
        r = run(args, "")
        check(r.returncode == 2 and r.stdout == "" and reason in r.stderr, f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}")
    # --scale: coordinates times S, R2 times S^2
    r = run(["within", "--r2", "0.25", "--scale", "10", "-", sp], "0 0\n0.5 0\n")
    check(r.returncode == 0 and r.stdout == "0 1\n" + "\n" * 99, f"within --scale: {r.returncode} {r.stdout[:20]!r} {r.stderr!r}")
    with open(os.path.join(tmp, "lbad"), "w") as f:
        f.write("1 2\n3\n")
    r = run(["locate", sp, os.path.join(tmp, "lbad")], "")
    check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: {os.path.join(tmp, 'lbad')}:2: "),
          f"locate bad query line: {r.returncode} {r.stderr!r}")


def raster_cases(rng, tmp):
    """vor raster --labels against a Python brute force: exact squared
    distances in big integers, ties to the smaller index."""
    import os
    import struct
    cases = []
    for n in range(8):
        w, h = rng.randint(1, 23), rng.randint(1, 19)
        ox, oy = rng.randint(-40, 40), rng.randint(-40, 40)
        sx, sy = rng.randint(1, 4), rng.randint(1, 4)
        k = rng.randint(1, 30)
        sites = [(ox + rng.randint(-10, w * sx + 10), oy + rng.randint(-10, h * sy + 10)) for _ in range(k)]
        cases.append((f"random{n}", w, h, ox, oy, sx, sy, sites, rng.choice([1, 3, 16])))
    lattice = [(x, y) for y in range(0, 21, 4) for x in range(0, 21, 4)][::-1]
    cases.append(("lattice-ties", 21, 21, 0, 0, 1, 1, lattice + lattice[:5], 4))
    huge = [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(12)] + [(MAX, MIN), (MIN, MAX)]
    cases.append(("huge", 9, 7, MIN, MIN, 2**29 - 1, 2**29 + 7, huge, 2))
    for name, w, h, ox, oy, sx, sy, sites, band in cases:
        sp = os.path.join(tmp, name + ".sites")
        with open(sp, "w") as f:
            f.write("# sites\n\n" + "".join(f"{x} {y}\n" for x, y in sites))
        out = os.path.join(tmp, name + ".raw")
        r = run(["raster", "--size", str(w), str(h), "--origin", str(ox), str(oy), "--step", str(sx), str(sy),
                 "--band", str(band), sp, "--labels", out], "")
        check(r.returncode == 0, f"raster {name}: status {r.returncode} {r.stderr}")
        if r.returncode != 0:
            continue
        data = open(out, "rb").read()
        check(len(data) == 4 * w * h, f"raster {name}: {len(data)} bytes for {w}x{h}")
        got = struct.unpack(f"<{w * h}I", data[:4 * w * h]) if len(data) >= 4 * w * h else ()
        wrong = 0
        for j in range(h):
            for i in range(w):
                qx, qy = ox + i * sx, oy + j * sy
                d = [(x - qx) ** 2 + (y - qy) ** 2 for x, y in sites]
                want = d.index(min(d))
                wrong += got[j * w + i] != want if got else 1
        check(wrong == 0, f"raster {name}: {wrong} of {w * h} labels differ from brute force")
    # bad input: status 2 and the line number
    bp = os.path.join(tmp, "bad.sites")
    with open(bp, "w") as f:
        f.write("1 2\n\n3\n")
    r = run(["raster", "--size", "4", "4", "--origin", "0", "0", "--step", "1", "1", bp, "--labels",
             os.path.join(tmp, "bad.raw")], "")
    check(r.returncode == 2 and r.stderr.startswith(f"error: {bp}:3: "), f"raster bad line: {r.returncode} {r.stderr!r}")
    for args in (["--size", "0", "4"], ["--size", "4", "4", "--step", "0", "1"], ["--size", "4", "4", "--origin", "2147483647", "0"]):
        r = run(["raster"] + args + [os.path.join(tmp, "huge.sites"), "--labels", os.path.join(tmp, "x.raw")], "")
        check(r.returncode == 2 and r.stderr.startswith("error: "), f"raster bad frame {args}: {r.returncode} {r.stderr!r}")
    png = os.path.join(tmp, "out.png")
    r = run(["raster", "--size", "30", "20", "--origin", "0", "0", "--step", "1", "1",
             os.path.join(tmp, "lattice-ties.sites"), "--png", png], "")
    check(r.returncode == 0 and open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n", f"raster --png: {r.returncode} {r.stderr!r}")
def nearest_k_cases(rng, tmp):
    """vor raster --nearest K: --labels against a Python ranking (the keys
    of metric_nearest, sorted with the index breaking ties), K past the
    site count padded with 4294967295; --png against the k-sets: black
    where the right or lower neighbour's k-set differs, else the mean of
    the members' colours in RGB565, widened back to 8 bits."""
    import functools
    import os
    import struct
    metrics = [("euclid", None, "euclid"), ("l1", None, "l1"), ("linf", None, "linf"),
               ("lp", 3, "lp:3"), ("ellip", (3, -1, 2), "ellip:3,-1,2"), ("mult", None, "mult"),
               ("add", None, "add"), ("comp", None, "comp"), ("farthest", None, "farthest"),
               ("power", None, "power")]

    def ranking(metric, param, sites, q):
        key_metric = "farthest" if metric == "euclid" else metric
        keys = []
        for k, site in enumerate(sites):
            # euclid ranks as farthest's negated key; the rest as metric_nearest
            kk = metric_key(key_metric, param, site, q)
            keys.append((-kk if metric == "euclid" else kk, k))
        if metric in ("mult", "add", "comp"):
            def cmp(a, b):
                c = weighted_compare(a[0], b[0])
                return c if c != 0 else (a[1] > b[1]) - (a[1] < b[1])
            keys.sort(key=functools.cmp_to_key(cmp))
        else:
            keys.sort()
        return [k for _, k in keys]

    for metric, param, arg in metrics:
        w, h = rng.randint(3, 17), rng.randint(2, 13)
        ox, oy, sx, sy = rng.randint(-20, 20), rng.randint(-20, 20), rng.randint(1, 3), rng.randint(1, 3)
        sites = []
        for k in range(rng.randint(2, 9)):
            p = (ox + rng.randint(-6, w * sx + 6), oy + rng.randint(-6, h * sy + 6))
            if metric == "mult":
                p += (rng.randint(1, 3),)
            elif metric == "add":
                p += (rng.randint(-4, 4),)
            elif metric == "comp":
                p += (rng.randint(1, 3), rng.randint(-4, 4))
            elif metric == "power":
                p += (rng.randint(-40, 40),)
            sites.append(p)
        sites.append(sites[0])  # a coincident pair: ranked by index
        sp = os.path.join(tmp, f"k-{metric}.sites")
        with open(sp, "w") as f:
            f.write("".join(" ".join(str(v) for v in site) + "\n" for site in sites))
        ranks = [[ranking(metric, param, sites, (ox + i * sx, oy + j * sy)) for i in range(w)] for j in range(h)]
        for kk in (1, 2, 3, len(sites) + 1):
            out = os.path.join(tmp, f"k-{metric}-{kk}.raw")
            r = run(["raster", "--size", str(w), str(h), "--origin", str(ox), str(oy), "--step", str(sx),
                     str(sy), "--metric", arg, "--nearest", str(kk), "--band", str(rng.choice([1, 4, 16])),
                     sp, "--labels", out], "")
            check(r.returncode == 0, f"raster --nearest {kk} {metric}: status {r.returncode} {r.stderr}")
            if r.returncode != 0:
                continue
            data = open(out, "rb").read()
            check(len(data) == 4 * w * h * kk, f"raster --nearest {kk} {metric}: {len(data)} bytes")
            got = struct.unpack(f"<{w * h * kk}I", data) if len(data) == 4 * w * h * kk else None
            wrong = 0
            for j in range(h):
                for i in range(w):
                    want = (ranks[j][i] + [2**32 - 1] * kk)[:kk]
                    p = (j * w + i) * kk
                    wrong += got is None or list(got[p:p + kk]) != want
            check(wrong == 0, f"raster --nearest {kk} {metric}: {wrong} of {w * h} pixels differ")
        # the k-set picture, y down
        kk = 2
        png = os.path.join(tmp, f"k-{metric}.png")
        r = run(["raster", "--size", str(w), str(h), "--origin", str(ox), str(oy), "--step", str(sx), str(sy),
                 "--metric", arg, "--nearest", str(kk), sp, "--png", png, "--y-down"], "")
        check(r.returncode == 0, f"raster --nearest --png {metric}: {r.returncode} {r.stderr!r}")
        if r.returncode != 0:
            continue
        picture = read_png(png)
        sets = [[sorted(ranks[j][i][:kk]) for i in range(w)] for j in range(h)]
        wrong = 0
        for j in range(h):
            for i in range(w):
                edge = (i + 1 < w and sets[j][i + 1] != sets[j][i]) or (j + 1 < h and sets[j + 1][i] != sets[j][i])
                if edge:
                    want = (0, 0, 0)
                else:
                    cs = [draw_colour(s) for s in sets[j][i]]
                    r5 = sum(c[0] >> 3 for c in cs) // len(cs)
                    g6 = sum(c[1] >> 2 for c in cs) // len(cs)
                    b5 = sum(c[2] >> 3 for c in cs) // len(cs)
                    want = ((r5 * 255 + 15) // 31, (g6 * 255 + 31) // 63, (b5 * 255 + 15) // 31)
                wrong += picture[j][i] != want
        check(wrong == 0, f"raster --nearest --png {metric}: {wrong} of {w * h} pixels differ")
    # bad K: status 2
    for bad in ("0", "17", "x"):
        r = run(["raster", "--size", "4", "4", "--nearest", bad, os.path.join(tmp, "k-l1.sites"), "--labels",
                 os.path.join(tmp, "bad.raw")], "")
        check(r.returncode == 2 and r.stderr.startswith("error: --nearest"), f"raster --nearest {bad}: {r.returncode} {r.stderr!r}")


def brute_cell(sites, i, box):
    """Cell of sites[i] in the box, exactly: the box clipped by the closed
    half-plane |p - s|^2 <= |p - n|^2 of every other distinct site n, with
    coinciding vertices merged; [] when no area is left. Rotated to start
    at the lowest vertex (smallest y, then x). Sites (x, y, w) are weighted:
    power distances |p - s|^2 - w, and a heavier site at s's point empties
    s's cell."""
    from fractions import Fraction as F
    x0, y0, x1, y1 = (F(v) for v in box)
    poly = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    sx, sy, sw = (tuple(sites[i]) + (0,))[:3]
    for j, n in enumerate(sites):
        nx, ny, nw = (tuple(n) + (0,))[:3]
        if (nx, ny) == (sx, sy):
            if nw > sw:
                return []
        elif poly:
            poly = clip_half_plane(poly, 2 * (nx - sx), 2 * (ny - sy),
                                   nx * nx + ny * ny - sx * sx - sy * sy + sw - nw)
    merged = []
    for p in poly:
        if not merged or merged[-1] != p:
            merged.append(p)
    while len(merged) > 1 and merged[0] == merged[-1]:
        merged.pop()
    if len(merged) < 3 or polygon_area2(merged) == 0:
        return []
    start = min(range(len(merged)), key=lambda k: (merged[k][1], merged[k][0]))
    return merged[start:] + merged[:start]


def brute_sibson(sites, q):
    """Sibson coordinates {site index: Fraction} of q among distinct
    sites by exact clipping (tools/exact_plane.py): q's cell with q added,
    the part of it nearer each site than every other site, over the
    whole; at a site, on the hull's boundary and outside it as
    boundary_coordinates says."""
    done, coordinates = boundary_coordinates(sites, q)
    return coordinates if done else sibson_inside(sites, q)


def check_interpolate(rng, tmp, name, flags, config, brute):
    """vor interpolate FLAGS on the valued sites of config, at one site,
    a midpoint and 12 random points around them, against brute's
    coordinates. Returns the output lines."""
    import os
    first = {}
    for x, y, v in config:
        first.setdefault((x, y), v)
    sites = list(first)
    xs = [p[0] for p in sites]
    ys = [p[1] for p in sites]
    queries = [sites[0], ((sites[0][0] + sites[-1][0]) // 2, (sites[0][1] + sites[-1][1]) // 2)]
    for _ in range(12):
        queries.append((rng.randint(min(xs) - 1, max(xs) + 1), rng.randint(min(ys) - 1, max(ys) + 1)))
    site_path = os.path.join(tmp, f"{name}.txt")
    with open(site_path, "w") as f:
        f.write("".join(f"{x} {y} {v}\n" for x, y, v in config))
    r = run(["interpolate"] + flags + [site_path, "-"], "".join(f"{x} {y}\n" for x, y in queries))
    lines = r.stdout.splitlines()
    check(r.returncode == 0 and len(lines) == len(queries), f"interpolate {name}: {r.returncode} {r.stderr!r}")
    for q, line in zip(queries, lines):
        ref = brute(sites, q)
        if ref is None:
            check(line == f"q {q[0]} {q[1]} outside", f"interpolate {name} {q}: {line!r}, expected outside")
            continue
        value = sum(lam * first[sites[i]] for i, lam in ref.items())
        want = f"q {q[0]} {q[1]} {round_half_away(value)} {value.numerator} {value.denominator}"
        check(line == want, f"interpolate {name} {q}: {line!r}, expected {want!r}")
    return lines


def valued_configs(rng):
    """The valued site sets (x, y, value) of the interpolate sections: a
    square, a grid with random values, cocircular sites around a centre
    site, collinear hull sites, all collinear, a duplicate, and 8 random
    sets, small to full-range."""
    configs = [
        [(0, 0, 0), (4, 0, 40), (4, 4, 80), (0, 4, 40)],
        [(x, y, rng.randint(-100, 100)) for y in range(0, 9, 4) for x in range(0, 9, 4)],
        [(5, 0, 1), (3, 4, 2), (0, 5, 3), (-4, 3, 4), (-5, 0, 5), (-3, -4, 6), (0, -5, 7), (4, -3, 8),
         (0, 0, -9)],  # cocircular around a centre site
        [(0, 0, 0), (3, 0, 7), (6, 0, -7), (9, 0, 100), (4, 5, 5), (0, 6, 6), (9, 6, 9)],
        [(0, 0, 1), (2, 1, 2), (4, 2, 3)],  # collinear
        [(0, 0, 5), (10, 0, 6), (0, 10, 7), (0, 0, 99)],  # a duplicate keeps its first value
    ]
    for _ in range(8):
        r = rng.choice([8, 1000, 2**31 - 1])
        configs.append([(rng.randint(-r, r), rng.randint(-r, r), rng.randint(-2**31, 2**31 - 1))
                        for _ in range(rng.randint(3, 10))])
    return configs


def interpolate_cases(rng, tmp):
    """vor interpolate against brute_sibson: the exact value in lowest
    terms and its rounding, halves away from zero; outside lines."""
    import os
    configs = valued_configs(rng)
    for k, config in enumerate(configs):
        check_interpolate(rng, tmp, f"interp{k}", [], config, brute_sibson)
    r = run(["interpolate", "-"], "0 0 1\n")
    check(r.returncode == 2 and "missing QUERIES" in r.stderr, f"interpolate usage: {r.stderr!r}")
    r = run(["interpolate", "-", os.path.join(tmp, "interp0.txt")], "0 0\n")
    check(r.returncode == 2 and r.stderr.startswith("error: <stdin>:1: "), f"interpolate bad site: {r.stderr!r}")


def brute_laplace(sites, q):
    """Laplace coordinates {site index: Fraction} of q among distinct
    sites (tools/exact_plane.py): the length of the edge of q's cell (q
    added, exactly) that faces each site over the site's distance from q,
    normalised; at a site, on the hull's boundary and outside it as
    boundary_coordinates says."""
    done, coordinates = boundary_coordinates(sites, q)
    return coordinates if done else laplace_inside(sites, q)


def laplace_cases(tmp):
    """vor interpolate --laplace against brute_laplace (its own random
    generator: the other sections' cases stay as they were). Laplace's
    interpolant differs from Sibson's somewhere, so the flag is seen."""
    rng = random.Random(2612)
    configs = valued_configs(rng)
    differ = 0
    for k, config in enumerate(configs):
        state = rng.getstate()
        lines = check_interpolate(rng, tmp, f"laplace{k}", ["--laplace"], config, brute_laplace)
        rng.setstate(state)  # the same queries over Sibson's coordinates
        differ += sum(a != b for a, b in zip(lines, check_interpolate(rng, tmp, f"sibson{k}", [], config,
                                                                    brute_sibson)))
    check(differ > 10, f"interpolate --laplace: only {differ} answers differ from Sibson's")
    r = run(["interpolate", "--laplace", "-"], "0 0 1\n")
    check(r.returncode == 2 and "missing QUERIES" in r.stderr and "--laplace" in r.stderr,
          f"interpolate --laplace usage: {r.stderr!r}")
    r = run(["interpolate", "--laplace=1", "-", "-"], "")
    check(r.returncode == 2 and r.stdout == "", f"interpolate --laplace=1: {r.returncode} {r.stderr!r}")


def round_half_up(v):
    import math
    from fractions import Fraction as F
    return math.floor(v + F(1, 2))


def cells_cases(rng, tmp):
    """vor cells against brute-force clipping with exact rationals: the
    rounded vertices equal vor's, and the exact cells tile the box (their
    areas add up to the box's exactly)."""
    import os
    big = 2**31 - 1
    sets = [
        ("random", [(rng.randint(-1000, 1000), rng.randint(-1000, 1000)) for _ in range(40)], (-1200, -900, 1100, 1300)),
        ("random full range", [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(30)], (MIN, MIN, MAX, MAX)),
        ("random partial box", [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(30)],
         (-2**30, -2**29, 2**30 + 12345, 2**30)),
        ("grid", [(x * 10, y * 10) for x in range(7) for y in range(6)] + [(20, 30), (0, 0)], (-5, -7, 55, 45)),
        ("grid on bisectors", [(x * 10, y * 10) for x in range(5) for y in range(5)], (5, 5, 35, 25)),
        ("circle", [(x * 7, y * 7) for x in range(-25, 26) for y in range(-25, 26) if x * x + y * y == 625],
         (-200, -300, 250, 180)),
        ("collinear", [(3 * t, -5 * t + 2) for t in (rng.randint(-40, 40) for _ in range(25))], (-150, -200, 130, 220)),
        ("collinear big", [(t * 2**24, t * 2**23 - 7) for t in (rng.randint(-127, 127) for _ in range(15))],
         (MIN, MIN, MAX, MAX)),
        ("hull collinear", [(x, 0) for x in range(0, 50, 7)] + [(rng.randint(0, 49), rng.randint(1, 40)) for _ in range(12)],
         (-10, -10, 60, 50)),
        ("corners", [(MIN, MIN), (MAX, MIN), (MIN, MAX), (MAX, MAX), (0, 0), (1, -1), (MAX, 0)], (MIN, MIN, MAX, MAX)),
        ("two sites", [(3, 4), (-7, 11)], (-20, -20, 20, 20)),
        ("one site", [(5, 5), (5, 5)], (0, 0, 3, 9)),
        ("far from the box", [(1000, 1000), (1010, 1000), (1000, 1020)], (0, 0, 10, 10)),
        ("zero width", [(0, 0), (10, 0)], (5, -5, 5, 5)),
    ]
    for name, sites, box in sets:
        path = os.path.join(tmp, "cells.sites")
        with open(path, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in sites))
        r = run(["cells", "--box", *map(str, box), path], "")
        check(r.returncode == 0, f"cells {name}: status {r.returncode} {r.stderr}")
        first = {}
        for k, p in enumerate(sites):
            first.setdefault(p, k)
        distinct = [k for k, p in enumerate(sites) if first[p] == k]
        unique = [sites[k] for k in distinct]
        lines = r.stdout.splitlines()
        check(len(lines) == len(distinct), f"cells {name}: {len(lines)} lines for {len(distinct)} sites")
        area2, wrong = 0, 0
        for k, line in zip(distinct, lines):
            cell = brute_cell(unique, unique.index(sites[k]), box)
            area2 += polygon_area2(cell) if cell else 0
            expected = [k, len(cell)] + [round_half_up(c) for p in cell for c in p]
            got = line.split()
            if got[0] != "c" or [int(v) for v in got[1:]] != expected:
                wrong += 1
                if wrong <= 2:
                    check(False, f"cells {name}: {line!r}, brute force {expected}")
        check(wrong == 0, f"cells {name}: {wrong} of {len(distinct)} cells differ from brute force")
        box_area2 = 2 * (box[2] - box[0]) * (box[3] - box[1])
        check(area2 == box_area2, f"cells {name}: areas add up to {area2}/2, the box has {box_area2}/2")
    # bad input: nothing on stdout, status 2
    path = os.path.join(tmp, "cells.sites")
    with open(path, "w") as f:
        f.write("0 0\n1 1\n2\n")
    r = run(["cells", "--box", "0", "0", "9", "9", path], "")
    check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: {path}:3: "),
          f"cells bad site line: {r.returncode} {r.stderr!r}")
    for args in (["--box", "5", "0", "4", "9", "-"], ["--box", "0", "0", "9", "x", "-"],
                 ["--box", "0", "0", "9", "2147483648", "-"], ["--box", "0", "0", "9", "-"], ["-"]):
        r = run(["cells", *args], "0 0\n")
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith("error: "),
              f"cells {args}: {r.returncode} {r.stderr!r}")


def polygon_where(poly, q):
    """1 strictly inside, 0 on the boundary, -1 outside (winding number)."""
    winding = 0
    for k in range(len(poly)):
        a, b = poly[k], poly[(k + 1) % len(poly)]
        o = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])
        if o == 0 and min(a[0], b[0]) <= q[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= q[1] <= max(a[1], b[1]):
            return 0
        if a[1] <= q[1] < b[1] and o > 0:
            winding += 1
        elif b[1] <= q[1] < a[1] and o < 0:
            winding -= 1
    return 1 if winding else -1


def clip_cases(rng, tmp):
    """vor cells --clip POLY [--exact] against exact checks in Fractions:
    the exact pieces (lowest terms, w > 0) round to the printed ones, are
    counterclockwise from their lowest vertex, lie in their site's closed
    cell and the closed room, their areas add up to the room's exactly,
    and random points strictly inside the room lie in a piece of their
    nearest site; a box as a polygon gives --box's cells, --box --exact
    rounds to --box; bad polygons and arguments exit 2 with nothing on
    stdout."""
    import math
    import os
    from fractions import Fraction as F
    rooms = {
        "L": [(0, 0), (60, 0), (60, 30), (30, 30), (30, 60), (0, 60)],
        "U": [(0, 0), (60, 0), (60, 60), (40, 60), (40, 20), (20, 20), (20, 60), (0, 60)],
        "comb": [(0, 0), (60, 0), (60, 60), (50, 10), (40, 60), (30, 10), (20, 60), (10, 10), (0, 60)],
        "clockwise star": [(30, 0), (20, 20), (0, 25), (15, 40), (10, 60), (30, 48), (50, 60), (45, 40),
                           (60, 25), (40, 20)],
        "collinear edges": [(0, 0), (20, 0), (40, 0), (60, 0), (60, 30), (60, 60), (0, 60), (0, 30)],
        "wide": [(-2**31, -2**31), (2**31 - 1, -2**31), (2**31 - 1, 2**31 - 1), (0, 0), (-2**31, 2**31 - 1)],
    }
    site_sets = [
        ("random", lambda: [(rng.randint(-10, 70), rng.randint(-10, 70)) for _ in range(12)]),
        ("grid", lambda: [(10 + 20 * i, 10 + 20 * j) for i in range(3) for j in range(3)]),
        ("diagonal", lambda: [(5 + 10 * t, 5 + 10 * t) for t in range(6)] + [(25, 25)]),
        ("full range", lambda: [(rng.randint(MIN, MAX), rng.randint(MIN, MAX)) for _ in range(10)]),
    ]

    poly_path = os.path.join(tmp, "room.poly")
    sites_path = os.path.join(tmp, "clip.sites")
    for room_name, room in rooms.items():
        with open(poly_path, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in room))
        room_area2 = abs(polygon_area2(room))
        xs, ys = [p[0] for p in room], [p[1] for p in room]
        for set_name, make in site_sets:
            if (room_name == "wide") != (set_name == "full range"):
                continue
            sites = make()
            with open(sites_path, "w") as f:
                f.write("".join(f"{x} {y}\n" for x, y in sites))
            what = f"cells --clip {room_name} {set_name}"
            rounded = run(["cells", "--clip", poly_path, sites_path], "")
            exact = run(["cells", "--clip", poly_path, "--exact", sites_path], "")
            check(rounded.returncode == 0 and exact.returncode == 0, f"{what}: {rounded.stderr!r} {exact.stderr!r}")
            distinct = []
            for p in sites:
                if p not in distinct:
                    distinct.append(p)
            total, pieces, wrong = F(0), {}, 0
            for line, eline in zip(rounded.stdout.splitlines(), exact.stdout.splitlines()):
                got, egot = [int(v) for v in line.split()[1:]], [int(v) for v in eline.split()[1:]]
                i, m = got[0], got[1]
                if m == 0:
                    continue
                nums = egot[2:]
                poly = [(F(nums[3 * k], nums[3 * k + 2]), F(nums[3 * k + 1], nums[3 * k + 2])) for k in range(m)]
                ok = (egot[:2] == [i, m] and len(nums) == 3 * m and
                      all(nums[3 * k + 2] > 0 and math.gcd(math.gcd(nums[3 * k], nums[3 * k + 1]), nums[3 * k + 2]) == 1
                          for k in range(m)) and
                      got[2:] == [round_half_up(c) for p in poly for c in p] and
                      polygon_area2(poly) > 0 and
                      all((poly[0][1], poly[0][0]) < (p[1], p[0]) for p in poly[1:]))
                s = sites[i]
                for p in poly:
                    ok = ok and polygon_where(room, p) >= 0
                    for n in distinct:
                        ok = ok and 2 * (n[0] - s[0]) * p[0] + 2 * (n[1] - s[1]) * p[1] <= \
                            n[0] ** 2 + n[1] ** 2 - s[0] ** 2 - s[1] ** 2
                if not ok:
                    wrong += 1
                    if wrong <= 2:
                        check(False, f"{what}: piece {line!r} / {eline!r} is wrong")
                total += polygon_area2(poly)
                pieces.setdefault(s, []).append(poly)
            check(wrong == 0, f"{what}: {wrong} wrong pieces")
            check(total == room_area2, f"{what}: areas add up to {total}/2, the room has {room_area2}/2")
            for _ in range(60 if set_name != "full range" else 0):
                q = (rng.randint(min(xs), max(xs)), rng.randint(min(ys), max(ys)))
                if polygon_where(room, q) != 1:
                    continue
                best = min((q[0] - n[0]) ** 2 + (q[1] - n[1]) ** 2 for n in distinct)
                near = [n for n in distinct if (q[0] - n[0]) ** 2 + (q[1] - n[1]) ** 2 == best]
                check(any(polygon_where(poly, q) >= 0 for n in near for poly in pieces.get(n, [])),
                      f"{what}: {q} in no piece of its nearest site")
    # a box as a polygon: --box's cells; --box --exact rounds to --box
    for _ in range(4):
        sites = [(rng.randint(-50, 50), rng.randint(-50, 50)) for _ in range(15)]
        box = (-40, -30, 45, 35)
        with open(sites_path, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in sites))
        with open(poly_path, "w") as f:
            f.write(f"{box[0]} {box[1]}\n{box[2]} {box[1]}\n{box[2]} {box[3]}\n{box[0]} {box[3]}\n")
        a = run(["cells", "--box", *map(str, box), sites_path], "")
        b = run(["cells", "--clip", poly_path, sites_path], "")
        e = run(["cells", "--box", *map(str, box), "--exact", sites_path], "")
        check(a.returncode == 0 and a.stdout == b.stdout, f"cells --clip of a box: {b.stdout!r} vs {a.stdout!r}")
        rounded_e = []
        for line in e.stdout.splitlines():
            v = [int(t) for t in line.split()[1:]]
            rounded_e.append(" ".join(["c", str(v[0]), str(v[1])] +
                                      [str(round_half_up(F(v[2 + 3 * k + c], v[4 + 3 * k]))) for k in range(v[1])
                                       for c in (0, 1)]))
        check(rounded_e == a.stdout.splitlines(), f"cells --box --exact does not round to --box")
    r = run(["cells", "--box", "0", "5", "9", "5", "--exact", "-"], "1 1\n3 3\n")
    check(r.returncode == 0 and r.stdout == "c 0 0\nc 1 0\n", f"cells --exact of a flat box: {r.stdout!r}")
    # bad polygons and arguments
    for name, poly in (("bowtie", [(0, 0), (10, 10), (10, 0), (0, 10)]),
                       ("repeated", [(0, 0), (10, 0), (10, 0), (0, 10)]),
                       ("touching", [(0, 0), (40, 0), (40, 40), (30, 40), (20, 0), (10, 40), (0, 40)]),
                       ("collinear", [(0, 0), (10, 0), (20, 0)])):
        with open(poly_path, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in poly))
        r = run(["cells", "--clip", poly_path, "-"], "1 1\n5 5\n")
        check(r.returncode == 2 and r.stdout == "" and "not simple" in r.stderr,
              f"cells --clip {name}: {r.returncode} {r.stderr!r}")
    with open(poly_path, "w") as f:
        f.write("0 0\n10 0\n")
    for args in (["--clip", poly_path, "-"], ["--clip", os.path.join(tmp, "missing.poly"), "-"],
                 ["--box", "0", "0", "9", "9", "--clip", poly_path, "-"], ["--exact", "-"],
                 ["--clip", poly_path]):
        r = run(["cells", *args], "0 0\n")
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith("error: "),
              f"cells {args}: {r.returncode} {r.stderr!r}")


def order_cells_cases(rng, tmp):
    """vor cells --order K against a brute force in Fractions: every set
    increasing and printed in increasing order, each set's pieces round to
    the --exact ones and lie in the closed room and in the closed order-K
    cell of their set (every site of the set at least as close as every
    other site, by the bisectors' exact inequalities), their areas add up
    to the room's exactly, random points of the room lie in a piece of
    their brute-force K nearest sites (ties to the smaller index); --order
    1 is the "c" output; bad orders exit 2 with nothing on stdout."""
    import os
    from fractions import Fraction as F
    rooms = {
        "box": [(0, 0), (60, 0), (60, 60), (0, 60)],
        "L": [(0, 0), (60, 0), (60, 30), (30, 30), (30, 60), (0, 60)],
        "U": [(0, 0), (60, 0), (60, 60), (40, 60), (40, 20), (20, 20), (20, 60), (0, 60)],
        "clockwise comb": [(0, 60), (10, 10), (20, 60), (30, 10), (40, 60), (50, 10), (60, 60), (60, 0), (0, 0)],
    }
    site_sets = [
        ("random", lambda: [(rng.randint(-10, 70), rng.randint(-10, 70)) for _ in range(9)]),
        ("grid", lambda: [(10 + 20 * i, 10 + 20 * j) for i in range(3) for j in range(3)]),
        ("ring", lambda: [(30, 30), (35, 30), (33, 34), (30, 35), (27, 34), (25, 30), (27, 26), (30, 25), (33, 26)]),
        ("collinear", lambda: [(5 + 12 * t, 30) for t in range(5)] + [(5, 30)]),
    ]

    poly_path = os.path.join(tmp, "order.poly")
    sites_path = os.path.join(tmp, "order.sites")
    for room_name, room in rooms.items():
        with open(poly_path, "w") as f:
            f.write("".join(f"{x} {y}\n" for x, y in room))
        room_area2 = abs(polygon_area2(room))
        xs, ys = [p[0] for p in room], [p[1] for p in room]
        for set_name, make in site_sets:
            sites = make()
            with open(sites_path, "w") as f:
                f.write("".join(f"{x} {y}\n" for x, y in sites))
            first = {}
            for i, p in enumerate(sites):
                first.setdefault(p, i)
            ids = sorted(first.values())
            for k in (2, 3, len(ids) - 1):
                what = f"cells --clip {room_name} --order {k} {set_name}"
                rounded = run(["cells", "--clip", poly_path, "--order", str(k), sites_path], "")
                exact = run(["cells", "--clip", poly_path, "--order", str(k), "--exact", sites_path], "")
                check(rounded.returncode == 0 and exact.returncode == 0, f"{what}: {rounded.stderr!r} {exact.stderr!r}")
                total, pieces, wrong, previous = F(0), {}, 0, None
                for line, eline in zip(rounded.stdout.splitlines(), exact.stdout.splitlines()):
                    got, egot = line.split(), [int(v) for v in eline.split()[1:]]
                    v = [int(t) for t in got[1:]]
                    group = tuple(v[1:1 + k])
                    m = v[1 + k]
                    nums = egot[2 + k:]
                    poly = [(F(nums[3 * j], nums[3 * j + 2]), F(nums[3 * j + 1], nums[3 * j + 2])) for j in range(m)]
                    ok = (got[0] == "o" and eline.startswith("o ") and v[0] == k and egot[:2 + k] == v[:2 + k] and
                          list(group) == sorted(set(group)) and all(g in ids for g in group) and
                          (previous is None or previous <= group) and len(nums) == 3 * m and
                          v[2 + k:] == [round_half_up(c) for p in poly for c in p] and polygon_area2(poly) > 0)
                    previous = group
                    for p in poly:
                        ok = ok and polygon_where(room, p) >= 0
                        for i in group:
                            s = sites[i]
                            for j in ids:
                                if j in group:
                                    continue
                                n = sites[j]
                                ok = ok and 2 * (n[0] - s[0]) * p[0] + 2 * (n[1] - s[1]) * p[1] <= \
                                    n[0] ** 2 + n[1] ** 2 - s[0] ** 2 - s[1] ** 2
                    if not ok:
                        wrong += 1
                        if wrong <= 2:
                            check(False, f"{what}: piece {line!r} / {eline!r} is wrong")
                    total += polygon_area2(poly)
                    pieces.setdefault(group, []).append(poly)
                check(wrong == 0, f"{what}: {wrong} wrong pieces")
                check(total == room_area2, f"{what}: areas add up to {total}/2, the room has {room_area2}/2")
                for _ in range(40):
                    q = (rng.randint(min(xs), max(xs)), rng.randint(min(ys), max(ys)))
                    if polygon_where(room, q) != 1:
                        continue
                    near = tuple(sorted(sorted(ids, key=lambda i: ((q[0] - sites[i][0]) ** 2 +
                                                                   (q[1] - sites[i][1]) ** 2, i))[:k]))
                    check(any(polygon_where(poly, q) >= 0 for poly in pieces.get(near, [])),
                          f"{what}: {q} in no piece of its {k} nearest sites {near}")
            one = run(["cells", "--clip", poly_path, "--order", "1", sites_path], "")
            plain = run(["cells", "--clip", poly_path, sites_path], "")
            check(one.returncode == 0 and one.stdout == plain.stdout, f"--order 1 differs from the c lines")
    # a box room, a flat box
    r = run(["cells", "--box", "0", "-10", "40", "10", "--order", "2", "-"], "0 0\n20 0\n40 0\n")
    check(r.returncode == 0 and r.stdout == "o 2 0 1 4 0 -10 20 -10 20 10 0 10\no 2 1 2 4 20 -10 40 -10 40 10 20 10\n",
          f"cells --box --order 2: {r.stdout!r}")
    r = run(["cells", "--box", "0", "5", "9", "5", "--order", "2", "-"], "1 1\n3 3\n5 5\n")
    check(r.returncode == 0 and r.stdout == "", f"cells --order 2 of a flat box: {r.stdout!r}")
    for args in (["--order", "0"], ["--order", "3"], ["--order", "x"], ["--order", "1025"], ["--order"]):
        r = run(["cells", "--box", "0", "0", "9", "9", *args, "-"], "0 0\n5 5\n7 1\n0 0\n")
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith("error: "),
              f"cells {args}: {r.returncode} {r.stderr!r}")


def weighted_compare(a, b):
    """Exact order of sqrt(D)/w1 - w2 for a = (D, w1, w2), b likewise:
    brackets of sqrt(D * 4^t) with growing t (equality only when the
    weights' terms cancel or both roots are integers)."""
    from fractions import Fraction
    from math import isqrt
    (da, w1a, w2a), (db, w1b, w2b) = a, b
    if w2a == w2b and da * w1b * w1b == db * w1a * w1a:
        return 0
    ra, rb = isqrt(da), isqrt(db)
    if ra * ra == da and rb * rb == db:
        return sign(Fraction(ra, w1a) - w2a - Fraction(rb, w1b) + w2b)
    t = 0
    while True:
        sa, sb = isqrt(da << (2 * t)), isqrt(db << (2 * t))
        lo_a, hi_a = Fraction(sa, w1a) - (w2a << t), Fraction(sa + 1, w1a) - (w2a << t)
        lo_b, hi_b = Fraction(sb, w1b) - (w2b << t), Fraction(sb + 1, w1b) - (w2b << t)
        if hi_a <= lo_b:
            return -1
        if hi_b <= lo_a:
            return 1
        t += 8


def segment_square(q, a, b):
    """Squared distance from q to segment a-b, through the clamped
    parameter of the nearest point (a Fraction)."""
    from fractions import Fraction
    ex, ey = b[0] - a[0], b[1] - a[1]
    length = ex * ex + ey * ey
    t = Fraction(0) if length == 0 else min(max(Fraction((q[0] - a[0]) * ex + (q[1] - a[1]) * ey, length), 0), 1)
    px, py = a[0] + t * ex, a[1] + t * ey
    return (q[0] - px) ** 2 + (q[1] - py) ** 2


def polygon_square(q, poly):
    """0 inside (nonzero winding number, counted on a ray towards +x) or on
    the boundary, else the squared distance to the nearest edge."""
    k = len(poly)
    if k >= 3:
        winding = 0
        for i in range(k):
            a, b = poly[i], poly[(i + 1) % k]
            if a[1] <= q[1] < b[1] and orient(a, b, q) > 0:
                winding += 1
            elif b[1] <= q[1] < a[1] and orient(a, b, q) < 0:
                winding -= 1
        if winding != 0:
            return 0
    edges = [(poly[0], poly[0])] if k == 1 else [(poly[i], poly[(i + 1) % k]) for i in range(k if k >= 3 else 1)]
    return min(segment_square(q, a, b) for a, b in edges)


def metric_key(metric, param, site, q):
    """The exact image of site's distance at q under metric (mult, add,
    comp: a tuple for weighted_compare; farthest: negated)."""
    if metric in ("l1", "linf", "lp", "ellip", "farthest", "mult", "add", "comp", "power"):
        dx, dy = abs(site[0] - q[0]), abs(site[1] - q[1])
    if metric == "power":  # the power distance, an exact Python integer
        return dx * dx + dy * dy - site[2]
    if metric == "l1":
        return dx + dy
    if metric == "linf":
        return max(dx, dy)
    if metric == "lp":
        return dx ** param + dy ** param
    if metric == "ellip":
        a, b, c = param
        sx, sy = q[0] - site[0], q[1] - site[1]
        return a * sx * sx + 2 * b * sx * sy + c * sy * sy
    if metric == "farthest":
        return -(dx * dx + dy * dy)
    if metric == "hausdorff":
        return max((x - q[0]) ** 2 + (y - q[1]) ** 2 for x, y in site)
    if metric == "segment":
        return segment_square(q, site[0], site[1])
    if metric == "polygon":
        return polygon_square(q, site)
    if metric == "polyline":
        pts = site[1:]
        edges = [(pts[0], pts[0])] if len(pts) == 1 else list(zip(pts, pts[1:]))
        return min(segment_square(q, a, b) for a, b in edges) / (site[0] * site[0])
    d = dx * dx + dy * dy
    return (d, site[2] if metric != "add" else 1, site[-1] if metric != "mult" else 0)


def metric_nearest(metric, param, sites, q):
    """Index of the first-ranked site at q (ties: the smaller index)."""
    def key(site):
        return metric_key(metric, param, site, q)
    best = 0
    best_key = key(sites[0])
    for k in range(1, len(sites)):
        kk = key(sites[k])
        better = weighted_compare(kk, best_key) < 0 if metric in ("mult", "add", "comp") else kk < best_key
        if better:
            best, best_key = k, kk
    return best


def raster_metric_cases(rng, tmp):
    """vor raster --metric M --labels against metric_nearest, for every
    metric: random sites, sites on pixel centres with ties, and bad input."""
    import os
    import struct
    def site_line(metric, site):
        if metric in ("hausdorff", "polygon"):
            return " ".join(f"{x} {y}" for x, y in site)
        if metric == "polyline":
            return f"{site[0]} " + " ".join(f"{x} {y}" for x, y in site[1:])
        if metric == "segment":
            return f"{site[0][0]} {site[0][1]} {site[1][0]} {site[1][1]}"
        return " ".join(str(v) for v in site)
    metrics = [("l1", None, "l1"), ("linf", None, "linf"), ("lp", 3, "lp:3"), ("lp", 8, "lp:8"),
               ("ellip", (3, -1, 2), "ellip:3,-1,2"), ("mult", None, "mult"), ("add", None, "add"),
               ("comp", None, "comp"), ("farthest", None, "farthest"), ("hausdorff", None, "hausdorff"),
               ("segment", None, "segment"), ("polygon", None, "polygon"),
               ("polyline", None, "polyline"), ("power", None, "power")]
    main_rng = rng
    for metric, param, arg in metrics:
        # power draws from its own generator: the later cases keep their inputs
        rng = random.Random(26) if metric == "power" else main_rng
        for n in range(3):
            w, h = rng.randint(1, 21), rng.randint(1, 19)
            ox, oy, sx, sy = rng.randint(-20, 20), rng.randint(-20, 20), rng.randint(1, 3), rng.randint(1, 3)
            def pt(on_centre):
                if on_centre:
                    return (ox + sx * rng.randint(0, w - 1), oy + sy * rng.randint(0, h - 1))
                return (ox + rng.randint(-8, w * sx + 8), oy + rng.randint(-8, h * sy + 8))
            sites = []
            for k in range(rng.randint(1, 14)):
                p = pt(n == 1)
                if metric == "mult":
                    sites.append(p + (rng.randint(1, 3),))
                elif metric == "add":
                    sites.append(p + (rng.randint(-4, 4) if n != 1 else 5 * (k % 2),))
                elif metric == "comp":
                    sites.append(p + (rng.randint(1, 3), rng.randint(-4, 4)))
                elif metric == "power":  # n = 2: heavy weights that hide sites
                    sites.append(p + (rng.randint(-40, 40) if n != 2 else rng.randint(-300, 300) * (1 + 9 * (k == 0)),))
                elif metric == "segment":
                    sites.append((p, pt(n == 1) if k % 3 else p))
                elif metric == "polyline":
                    sites.append([rng.randint(1, 4), p] + [(p[0] + rng.randint(-6, 6), p[1] + rng.randint(-6, 6)) for _ in range(rng.randint(0, 4))])
                elif metric in ("hausdorff", "polygon"):
                    sites.append([p] + [(p[0] + rng.randint(-6, 6), p[1] + rng.randint(-6, 6)) for _ in range(rng.randint(0, 4))])
                else:
                    sites.append(p)
            if n == 1 and len(sites) > 1:
                sites.append(sites[0])  # a duplicate: never owns a pixel
            name = f"{metric}{param if param is not None else ''}-{n}"
            sp = os.path.join(tmp, name + ".sites")
            with open(sp, "w") as f:
                f.write("# " + name + "\n" + "".join(site_line(metric, s) + "\n" for s in sites))
            out = os.path.join(tmp, name + ".raw")
            r = run(["raster", "--size", str(w), str(h), "--origin", str(ox), str(oy), "--step", str(sx), str(sy),
                     "--metric", arg, "--band", str(rng.choice([1, 5, 16])), sp, "--labels", out], "")
            check(r.returncode == 0, f"raster {name}: status {r.returncode} {r.stderr}")
            if r.returncode != 0:
                continue
            data = open(out, "rb").read()
            got = struct.unpack(f"<{w * h}I", data) if len(data) == 4 * w * h else None
            check(got is not None, f"raster {name}: {len(data)} bytes for {w}x{h}")
            wrong = 0
            for j in range(h):
                for i in range(w):
                    want = metric_nearest(metric, param, sites, (ox + i * sx, oy + j * sy))
                    wrong += got is None or got[j * w + i] != want
            check(wrong == 0, f"raster {name}: {wrong} of {w * h} labels differ from brute force")
    # bad site lines and metric arguments: status 2 and the line number
    bad = [("mult", "1 2 3\n4 5 0\n", 2), ("mult", "1 2\n", 1), ("comp", "# c\n1 2 3\n", 2),
           ("comp", "1 2 -1 5\n", 1), ("add", "1 2 3 4\n", 1), ("segment", "1 2 3\n", 1),
           ("polygon", "1 2 3 4\n5 6 7\n", 2), ("hausdorff", "\n\n1 2 x\n", 3), ("l1", "1 2 3\n", 1),
           ("polyline", "2 1 2 3 4\n0 5 6\n", 2), ("polyline", "1 1 2 3\n", 1),
           ("power", "1 2 3\n1 2\n", 2), ("power", "1 2 3.5\n", 1), ("power", "1 2 3 4\n", 1),
           ("power", "0 0 9223372036854775808\n", 1)]
    for metric, text, line in bad:
        bp = os.path.join(tmp, "bad.sites")
        with open(bp, "w") as f:
            f.write(text)
        r = run(["raster", "--size", "4", "4", "--metric", metric, bp, "--labels", os.path.join(tmp, "bad.raw")], "")
        check(r.returncode == 2 and r.stderr.startswith(f"error: {bp}:{line}: "),
              f"raster --metric {metric} bad line {text!r}: {r.returncode} {r.stderr!r}")
    # power: int64 weights at both ends, and --scale S multiplies them by S^2
    for text, scale, want in (("0 0 -9223372036854775808\n3 0 9223372036854775807\n", None, [1, 1, 1, 1]),
                              ("0 0 9223372036854775807\n3 0 9223372036854775807\n", None, [0, 0, 1, 1]),
                              ("0 0 0\n0.3 0 0.03\n", "10", [0, 0, 1, 1]),  # w 3: x = 1 ties, to 0
                              ("0 0 0\n0.3 0 0.035\n", "10", [0, 1, 1, 1])):  # 3.5 rounds away to 4
        pp = os.path.join(tmp, "power-scale.sites")
        with open(pp, "w") as f:
            f.write(text)
        args = ["raster", "--size", "4", "1", "--metric", "power", pp, "--labels", os.path.join(tmp, "power.raw")]
        r = run(args + (["--scale", scale] if scale else []), "")
        got = list(struct.unpack("<4I", open(os.path.join(tmp, "power.raw"), "rb").read())) if r.returncode == 0 else None
        check(got == want, f"raster --metric power {text!r} --scale {scale}: {got}, want {want} ({r.stderr!r})")
    rng = random.Random(27)
    # power --png: every pixel the colour of its brute-force site, black on
    # the boundaries (a label unlike the right or lower neighbour's)
    w, h = 24, 16
    sites = [(rng.randint(-4, 28), rng.randint(-4, 20), rng.randint(-60, 60)) for _ in range(9)] + [(12, 8, 900)]
    pp, png = os.path.join(tmp, "power-png.sites"), os.path.join(tmp, "power.png")
    with open(pp, "w") as f:
        f.write("".join(f"{x} {y} {wt}\n" for x, y, wt in sites))
    r = run(["raster", "--size", str(w), str(h), "--metric", "power", pp, "--png", png, "--y-down"], "")
    check(r.returncode == 0, f"raster --metric power --png: {r.returncode} {r.stderr!r}")
    if r.returncode == 0:
        picture = read_png(png)
        labels = [[metric_nearest("power", None, sites, (i, j)) for i in range(w)] for j in range(h)]
        wrong = 0
        for j in range(h):
            for i in range(w):
                edge = (i + 1 < w and labels[j][i + 1] != labels[j][i]) or (j + 1 < h and labels[j + 1][i] != labels[j][i])
                wrong += tuple(picture[j][i]) != ((0, 0, 0) if edge else draw_colour(labels[j][i]))
        check(wrong == 0, f"raster --metric power --png: {wrong} of {w * h} pixels unlike the brute force")
    rng = main_rng
    for arg in ("lp:0", "lp:9", "lp:x", "ellip:1,2,3", "ellip:0,0,1", "ellip:1,2", "manhattan"):
        r = run(["raster", "--size", "4", "4", "--metric", arg, os.path.join(tmp, "l1-0.sites"), "--labels",
                 os.path.join(tmp, "bad.raw")], "")
        check(r.returncode == 2 and r.stderr.startswith("error: --metric"), f"raster --metric {arg}: {r.returncode} {r.stderr!r}")


def contour_labels(contours, frame, alpha):
    """examples/contours' pairwise rule (its top comment), brute force with
    exact fractions: per step i = 1 .. alpha - 1, the label grid."""
    (ox, oy, sx, sy, w, h) = frame
    cs = [pts for _, pts in sorted(contours, key=lambda c: c[0])]
    n = len(cs)
    def sq(q, pts):
        edges = [(pts[0], pts[0])] if len(pts) == 1 else list(zip(pts, pts[1:]))
        return min(segment_square(q, a, b) for a, b in edges)
    def closed(pts):
        return len(pts) >= 4 and pts[0] == pts[-1]
    def inside(pts, q):
        winding = 0
        for a, b in zip(pts, pts[1:]):
            if a[1] <= q[1] < b[1] and orient(a, b, q) > 0:
                winding += 1
            elif b[1] <= q[1] < a[1] and orient(a, b, q) < 0:
                winding -= 1
        return winding != 0
    grids = [[[0] * w for _ in range(h)] for _ in range(alpha - 1)]
    for y in range(h):
        for x in range(w):
            q = (ox + x * sx, oy + y * sy)
            d = [sq(q, c) for c in cs]
            k = min(range(n), key=lambda t: (d[t], t))
            lower, upper = k > 0, k + 1 < n
            if closed(cs[k]):
                side = inside(cs[k], q)
                tl = lower and inside(cs[k], cs[k - 1][0]) == side
                tu = upper and inside(cs[k], cs[k + 1][0]) == side
                if not tl and not tu and lower and upper:
                    tl = tu = True
                lower, upper = tl, tu
            if lower and upper:
                lower, upper = d[k - 1] <= d[k + 1], d[k - 1] > d[k + 1]
            j = k - 1 if lower else k if upper else None
            for i in range(1, alpha):
                if j is None:
                    grids[i - 1][y][x] = k
                else:
                    # c_j (weight i) wins ties against c_(j+1) (weight alpha - i)
                    grids[i - 1][y][x] = j if d[j] * (alpha - i) ** 2 <= d[j + 1] * i * i else j + 1
    return grids


def contours_cases(rng, tmp):
    """examples/contours --labels against contour_labels: the sample on a
    coarse frame, random nested rings with an open contour, two hills."""
    import os
    example = os.path.join(os.path.dirname(VOR), "example-contours")
    def ring(cx, cy, r, m):
        pts = [(cx + round(r * [1, 0, -1, 0][t % 4] + rng.randint(-1, 1)),
                cy + round(r * [0, 1, 0, -1][t % 4] + rng.randint(-1, 1))) for t in range(m)]
        return pts + [pts[0]]
    sample = []
    for line in open("examples/contours/sample.txt"):
        f = line.split()
        if not f or f[0].startswith("#"):
            continue
        if f[0] == "contour":
            sample.append((int(f[1]), []))
        else:
            sample[-1][1].append((int(f[0]), int(f[1])))
    cases = [("sample", sample, (4, 4, 8, 8, 32, 32), 4)]
    for t in range(3):
        cx, cy = rng.randint(14, 20), rng.randint(12, 16)
        cs = [(30, ring(cx, cy, 10, 4)), (40, ring(cx + 1, cy, 6, 4)), (50, ring(cx, cy + 1, 2, 4)),
              (20, [(0, 26), (5, 29), (9, 31)])]
        if t == 2:  # non-nested: two hills inside one ring, and a point summit
            cs = [(10, ring(17, 15, 14, 4)), (20, ring(10, 15, 4, 4)), (30, ring(25, 15, 4, 4)), (40, [(25, 15)])]
        cases.append((f"rings{t}", cs, (0, 0, 1, 1, 34, 32), 3 + t))
    for name, cs, frame, alpha in cases:
        cp = os.path.join(tmp, name + ".contours")
        with open(cp, "w") as f:
            for height, pts in cs:
                f.write(f"contour {height}\n" + "".join(f"{x} {y}\n" for x, y in pts))
        lp, pp = os.path.join(tmp, name + ".labels"), os.path.join(tmp, name + ".png")
        (ox, oy, sx, sy, w, h) = frame
        r = subprocess.run([example, cp, pp, "--size", str(w), str(h), "--origin", str(ox), str(oy),
                            "--step", str(sx), str(sy), "--alpha", str(alpha), "--labels", lp],
                           capture_output=True, text=True)
        check(r.returncode == 0, f"contours {name}: status {r.returncode} {r.stderr}")
        if r.returncode != 0:
            continue
        check(open(pp, "rb").read(8) == b"\x89PNG\r\n\x1a\n", f"contours {name}: not a PNG")
        got, grid = [], None
        for line in open(lp):
            if line.startswith("step"):
                grid = []
                got.append(grid)
            else:
                grid.append([int(v) for v in line.split()])
        want = contour_labels(cs, frame, alpha)
        check(len(got) == alpha - 1, f"contours {name}: {len(got)} steps for alpha {alpha}")
        for i, (g, e) in enumerate(zip(got, want)):
            wrong = sum(g[y][x] != e[y][x] for y in range(h) for x in range(w)) if len(g) == h else w * h
            check(wrong == 0, f"contours {name} step {i + 1}: {wrong} of {w * h} labels differ from brute force")
            # the intermediate contour exists: some label changes inside a pair
            edges = sum(e[y][x] != e[y][x + 1] for y in range(h) for x in range(w - 1))
            check(edges > 0, f"contours {name} step {i + 1}: no boundary to compare")
    bp = os.path.join(tmp, "bad.contours")
    for text in ("1 2\n", "contour 5\n1 2\ncontour 6\n1 x\n", "contour 5\n1 2\n"):
        with open(bp, "w") as f:
            f.write(text)
        r = subprocess.run([example, bp, os.path.join(tmp, "bad.png")], capture_output=True, text=True)
        check(r.returncode == 2 and r.stderr.startswith("error: "), f"contours bad input {text!r}: {r.returncode} {r.stderr!r}")


def read_png(path):
    """The RGB pixels of an 8-bit RGB or RGBA PNG (rows top first), decoded
    with zlib alone: enough for rsvg-convert's output."""
    import struct
    import zlib
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            w, h, depth, colour_type, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour_type in (2, 6) and interlace == 0, "unsupported PNG"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    bpp = 3 if colour_type == 2 else 4
    raw, stride = zlib.decompress(idat), w * bpp
    rows, prev = [], bytearray(stride)
    for r in range(h):
        f, line = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[i * bpp:i * bpp + 3]) for i in range(w)])
        prev = line
    return rows


def draw_colour(site):
    # the palette of tools/cli/draw.c, written from its documentation
    c = site * 2654435761 % 2**21
    return (128 + (c & 127), 128 + ((c >> 7) & 127), 128 + (c >> 14))


def draw_cells(svg_path):
    """The filled cell paths of a `vor draw` SVG as (fill, [vertices])."""
    import xml.etree.ElementTree as ET
    ns = "{http://www.w3.org/2000/svg}"
    cells = []
    for path in ET.parse(svg_path).getroot().iter(ns + "path"):
        if path.get("fill", "none") != "none":
            numbers = [int(v) for v in path.get("d").replace("M", " ").replace("L", " ").replace("Z", " ").split()]
            cells.append((path.get("fill"), list(zip(numbers[0::2], numbers[1::2]))))
    return cells


def draw_cases(rng, tmp):
    """vor draw: the SVG parses (xmllint), its cells are `vor cells`'
    vertices, and rendered by rsvg-convert the colour at every pixel centre
    well inside a cell is the colour of the site `vor raster --labels`
    gives for that centre, in a frame whose pixel centres are the SVG's."""
    import os
    import shutil
    import struct
    if not (shutil.which("xmllint") and shutil.which("rsvg-convert")):
        check(False, "draw: xmllint and rsvg-convert are needed (tools/install-deps.sh svg)")
        return
    sites = [(rng.randint(0, 1000), rng.randint(0, 800)) for _ in range(40)]
    sites += [sites[3], sites[17]]  # duplicates: drawn once, under the first id
    path = os.path.join(tmp, "draw.sites")
    with open(path, "w") as f:
        f.write("".join(f"{x} {y}\n" for x, y in sites))
    # pixel (i, row r) of the picture covers x0 + [i, i+1] * step, y1 - [r, r+1] * step
    w, h, step = 110, 90, 10
    x0, y0 = -37, -52
    box = (x0, y0, x0 + w * step, y0 + h * step)
    svg, png = os.path.join(tmp, "draw.svg"), os.path.join(tmp, "draw.png")
    r = run(["draw", "--box", *map(str, box), "--size", str(w), str(h), path, "-o", svg], "")
    check(r.returncode == 0 and r.stdout == "", f"draw: status {r.returncode} {r.stderr!r}")
    lint = subprocess.run(["xmllint", "--noout", svg], capture_output=True, text=True)
    check(lint.returncode == 0 and lint.stderr == "", f"draw: xmllint {lint.returncode} {lint.stderr!r}")
    r = run(["cells", "--box", *map(str, box), path], "")
    expected = []
    for line in r.stdout.splitlines():
        v = [int(t) for t in line.split()[1:]]
        if v[1] > 0:
            expected.append(("#%02x%02x%02x" % draw_colour(v[0]), list(zip(v[2::2], v[3::2]))))
    check(draw_cells(svg) == expected, f"draw: the cell paths differ from vor cells ({len(expected)} cells)")
    # the black edges: every side of a cell that is not on the box, once
    import xml.etree.ElementTree as ET
    ns = "{http://www.w3.org/2000/svg}"
    edges = [tuple(tuple(int(v) for v in end.split()) for end in piece.split("L"))
             for p in ET.parse(svg).getroot().iter(ns + "path") if p.get("stroke") == "#000"
             for piece in p.get("d").split("M")[1:]]
    on_box = lambda p, q: (p[0] == q[0] and p[0] in (box[0], box[2])) or (p[1] == q[1] and p[1] in (box[1], box[3]))
    sides = {frozenset((c[k], c[(k + 1) % len(c)])) for _, c in expected for k in range(len(c))
             if c[k] != c[(k + 1) % len(c)] and not on_box(c[k], c[(k + 1) % len(c)])}
    check(len(edges) == len(sides) and {frozenset(e) for e in edges} == sides,
          f"draw: {len(edges)} edges drawn, {len(sides)} cell sides off the box")
    labels_path = os.path.join(tmp, "draw.raw")
    r = run(["raster", "--size", str(w), str(h), "--origin", str(x0 + step // 2), str(y0 + step // 2),
             "--step", str(step), str(step), path, "--labels", labels_path], "")
    check(r.returncode == 0, f"draw: raster status {r.returncode} {r.stderr!r}")
    labels = struct.unpack(f"<{w * h}I", open(labels_path, "rb").read())
    r = subprocess.run(["rsvg-convert", svg, "-o", png], capture_output=True, text=True)
    check(r.returncode == 0, f"draw: rsvg-convert {r.returncode} {r.stderr!r}")
    pixels = read_png(png)
    check(len(pixels) == h and len(pixels[0]) == w, f"draw: rendered {len(pixels[0])}x{len(pixels)}, asked {w}x{h}")
    # well inside: 3 pixels from every other cell (edges are 1 pixel wide
    # and anti-aliased) and 4 from every site (dots of radius 1.5 pixels)
    margin = 3 * step
    checked = wrong = 0
    for j in range(h):
        for i in range(w):
            q = (x0 + step // 2 + i * step, y0 + step // 2 + j * step)
            a = sites[labels[j * w + i]]
            da = (q[0] - a[0]) ** 2 + (q[1] - a[1]) ** 2
            if min((q[0] - s[0]) ** 2 + (q[1] - s[1]) ** 2 for s in sites) < (4 * step) ** 2:
                continue
            # distance to the bisector with b is (db - da) / (2 |b - a|)
            if any(s != a and ((q[0] - s[0]) ** 2 + (q[1] - s[1]) ** 2 - da) ** 2 <
                   4 * margin ** 2 * ((s[0] - a[0]) ** 2 + (s[1] - a[1]) ** 2) for s in sites):
                continue
            checked += 1
            if pixels[h - 1 - j][i] != draw_colour(labels[j * w + i]):
                wrong += 1
                if wrong <= 3:
                    check(False, f"draw: pixel {i},{h - 1 - j} is {pixels[h - 1 - j][i]}, "
                                 f"site {labels[j * w + i]}'s colour is {draw_colour(labels[j * w + i])}")
    check(checked > w * h // 3, f"draw: only {checked} of {w * h} pixels well inside cells")
    check(wrong == 0, f"draw: {wrong} of {checked} pixel colours differ from the raster's sites")
    # a dump in the firmware's format gives the same cells
    dump = os.path.join(tmp, "draw.cells")
    with open(dump, "w") as f:
        f.write("box %d %d %d %d\n" % box + "".join(f"s {x} {y}\n" for x, y in sites[:40]))
        f.write(run(["cells", "--box", *map(str, box), path], "").stdout)
    svg_dump = os.path.join(tmp, "dump.svg")
    r = run(["draw", "--cells", dump, "--size", str(w), str(h), "-o", svg_dump], "")
    check(r.returncode == 0 and draw_cells(svg_dump) == expected, f"draw --cells: {r.returncode} {r.stderr!r}")
    # the options: one label a distinct site, 2n - h - 2 triangles
    r = run(["draw", "--triangles", "--ids", "--hull", path, "-o", svg], "")
    lint = subprocess.run(["xmllint", "--noout", svg], capture_output=True, text=True)
    check(r.returncode == 0 and lint.returncode == 0, f"draw --triangles --ids --hull: {r.returncode} {lint.stderr!r}")
    root = ET.parse(svg).getroot()
    texts = sorted(int(t.text) for t in root.iter(ns + "text"))
    check(texts == list(range(40)), f"draw --ids: labels {texts}")
    strokes = {p.get("stroke"): p.get("d") for p in root.iter(ns + "path") if p.get("fill") == "none"}
    # the hull's sides, each "Mx yLx y", from each hull site to the next
    sides = [[tuple(int(v) for v in end.split()) for end in piece.split("L")]
             for piece in strokes.get("#d01010", "").split("M")[1:]]
    hull_points = [side[0] for side in sides]
    check(all(sides[k - 1][1] == sides[k][0] for k in range(len(sides))), f"draw --hull: sides {sides} do not close")
    check(len(hull_points) >= 3 and all(orient(hull_points[k - 2], hull_points[k - 1], hull_points[k]) >= 0
                                        for k in range(len(hull_points))) and
          all(orient(hull_points[k - 1], hull_points[k], s) >= 0 for k in range(len(hull_points)) for s in sites),
          f"draw --hull: {hull_points} is not the convex hull, counterclockwise")
    triangles = strokes.get("#1f4fbf", "").count("Z")
    check(triangles == 2 * 40 - len(hull_points) - 2, f"draw --triangles: {triangles} triangles, hull {len(hull_points)}")
    # more pieces than one path holds (libxml2's 10 MB attribute limit):
    # split into several paths, still every triangle once
    many = os.path.join(tmp, "many.sites")
    with open(many, "w") as f:
        f.write("".join(f"{rng.randint(MIN, MAX)} {rng.randint(MIN, MAX)}\n" for _ in range(3000)))
    r = run(["draw", "--triangles", many, "-o", svg], "")
    lint = subprocess.run(["xmllint", "--noout", svg], capture_output=True, text=True)
    check(r.returncode == 0 and lint.returncode == 0, f"draw 3000 sites: {r.returncode} {lint.stderr!r}")
    paths = [p.get("d") for p in ET.parse(svg).getroot().iter(ns + "path") if p.get("stroke") == "#1f4fbf"]
    triangles = run(["delaunay", many], "").stdout.count("t ")
    check(len(paths) > 1 and sum(d.count("Z") for d in paths) == triangles,
          f"draw 3000 sites: {len(paths)} paths, {sum(d.count('Z') for d in paths)} of {triangles} triangles")
    # errors: status 2, nothing written
    out = os.path.join(tmp, "never.svg")
    for args in (["--box", "5", "0", "5", "9", path, "-o", out], [path], [path, "-o", out, "--size", "0", "5"],
                 ["--bogus", path, "-o", out], ["--cells", path, "-o", out]):
        r = run(["draw", *args], "")
        check(r.returncode == 2 and r.stderr.startswith("error: ") and not os.path.exists(out),
              f"draw {args}: {r.returncode} {r.stderr!r}")
    r = run(["draw", path, "-o", os.path.join(tmp, "no-such-dir", "x.svg")], "")
    check(r.returncode == 2 and "no-such-dir" in r.stderr, f"draw to a missing directory: {r.returncode} {r.stderr!r}")


def picture_cases(tmp):
    """vor draw and vor raster --png show the same sites the same way: y up,
    site i in draw_colour(i) in both, at the same pixels (the raster's pixel
    centres are the picture's); --y-down turns both upside down; --dots
    blackens the raster's pixels within 1.5 pixels of each site."""
    import os
    import shutil
    if not shutil.which("rsvg-convert"):
        check(False, "pictures: rsvg-convert is needed (tools/install-deps.sh svg)")
        return
    sites = [(200, 650), (800, 600), (500, 150)]  # site 0 high and left, site 2 low
    path = os.path.join(tmp, "pictures.sites")
    with open(path, "w") as f:
        f.write("".join(f"{x} {y}\n" for x, y in sites))
    w, h = 100, 80
    pictures = {}
    for flip in ([], ["--y-down"]):
        svg, drawn, raster = (os.path.join(tmp, "pictures" + "".join(flip) + e) for e in (".svg", "-draw.png", "-raster.png"))
        r = run(["draw", *flip, "--box", "0", "0", "1000", "800", "--size", str(w), str(h), path, "-o", svg], "")
        r2 = subprocess.run(["rsvg-convert", svg, "-o", drawn], capture_output=True, text=True)
        r3 = run(["raster", *flip, "--size", str(w), str(h), "--origin", "5", "5", "--step", "10", "10", path, "--png", raster], "")
        check(r.returncode == 0 and r2.returncode == 0 and r3.returncode == 0,
              f"pictures {flip}: {r.stderr!r} {r2.stderr!r} {r3.stderr!r}")
        if r.returncode == 0 and r2.returncode == 0 and r3.returncode == 0:
            pictures[bool(flip)] = (read_png(drawn), read_png(raster))
    # 3.5 pixels up and right of each site, well inside its cell: the
    # point (x + 35, y + 35) is raster pixel ((x + 30) / 10, (y + 30) / 10)
    for down, (drawn, raster) in pictures.items():
        for k, (x, y) in enumerate(sites):
            i, j = (x + 30) // 10, (y + 30) // 10
            row = j if down else h - 1 - j
            for name, picture in (("draw", drawn), ("raster", raster)):
                check(picture[row][i] == draw_colour(k), f"pictures: {name}{' --y-down' * down} shows {picture[row][i]} "
                      f"at site {k}'s pixel ({i}, row {row}), expected {draw_colour(k)}")
        same = sum(drawn[r][i] == raster[r][i] for r in range(h) for i in range(w))
        check(same > 0.95 * w * h, f"pictures{' --y-down' * down}: draw and raster agree on only {same} of {w * h} pixels")
    if False not in pictures:
        return
    raster = pictures[False][1]
    # site 0 (the highest y) fills the top left corner, site 2 the bottom middle
    check(raster[2][2] == draw_colour(0) and raster[h - 3][w // 2] == draw_colour(2),
          f"pictures: raster --png is not y up: {raster[2][2]} {raster[h - 3][w // 2]}")
    if True in pictures:
        check(pictures[True][1][::-1] == raster, "pictures: raster --y-down is not raster upside down")
    dotted = os.path.join(tmp, "pictures-dots.png")
    r = run(["raster", "--dots", "--size", str(w), str(h), "--origin", "5", "5", "--step", "10", "10", path, "--png", dotted], "")
    check(r.returncode == 0, f"raster --dots: {r.returncode} {r.stderr!r}")
    if r.returncode == 0:
        dots = read_png(dotted)
        # site (x, y) is at pixel ((x - 5) / 10, (y - 5) / 10) = (u + 0.5, v + 0.5)
        want = {(h - 1 - (y - 5) // 10 - dr, (x - 5) // 10 + di) for x, y in sites for di in (0, 1) for dr in (0, 1)}
        changed = {(r, i) for r in range(h) for i in range(w) if dots[r][i] != raster[r][i]}
        check(changed == want and all(dots[r][i] == (0, 0, 0) for r, i in want),
              f"raster --dots: changed pixels {sorted(changed)}, expected {sorted(want)}")
    r = run(["raster", "--dots", "--size", "2", "2", path, "--labels", os.path.join(tmp, "x.raw")], "")
    check(r.returncode == 2 and "--png" in r.stderr, f"raster --dots --labels: {r.returncode} {r.stderr!r}")


def option_cases(rng, tmp):
    """One option parser for every command: "--name V1 V2" and
    "--name=V1,V2" give the same output, options and files in any order;
    a missing value, a value of a flag and an unknown option are errors."""
    import os
    sp, qp = os.path.join(tmp, "opt.sites"), os.path.join(tmp, "opt.queries")
    pts = [(rng.randint(0, 1000), rng.randint(0, 1000)) for _ in range(30)]
    with open(sp, "w") as f:
        f.write("".join(f"{x} {y}\n" for x, y in pts))
    with open(qp, "w") as f:
        f.write("".join(f"{rng.randint(0, 1000)} {rng.randint(0, 1000)}\n" for _ in range(20)))
    ops = "i 0 0\ni 10 0\nr 0\ni 5 5\nn 1 1\nt\n"
    out = [os.path.join(tmp, f"opt{k}") for k in range(2)]
    # (spaced arguments, '=' arguments); {out} is replaced by each output file
    pairs = [
        (["nearest", "--k", "3", sp, qp], ["nearest", sp, "--k=3", qp]),
        (["delaunay", "--order", "input", "--algo", "dc", sp], ["delaunay", sp, "--algo=dc", "--order=input"]),
        (["delaunay", "--scale", "0.5", sp], ["delaunay", "--scale=0.5", sp]),
        (["cells", "--box", "-10", "-20", "900", "1000", sp], ["cells", sp, "--box=-10,-20,900,1000"]),
        (["ops", "--capacity", "2", "-"], ["ops", "-", "--capacity=2"]),
        (["raster", "--size", "23", "17", "--origin", "-5", "7", "--step", "40", "60", "--metric", "ellip:2,1,3",
          "--band", "3", sp, "--labels", "{out}"],
         ["raster", "--size=23,17", "--origin=-5,7", "--step=40,60", "--metric=ellip:2,1,3", "--band=3", sp, "--labels={out}"]),
        (["raster", "--size", "23", "17", "--dots", sp, "--png", "{out}"], ["raster", "--size=23,17", "--dots", "--png={out}", sp]),
        (["draw", "--box", "0", "0", "1000", "900", "--size", "50", "40", "--ids", sp, "-o", "{out}"],
         ["draw", "-o", "{out}", "--size=50,40", sp, "--ids", "--box=0,0,1000,900"]),
    ]
    for spaced, joined in pairs:
        results = []
        for k, args in enumerate((spaced, joined)):
            if os.path.exists(out[k]):
                os.remove(out[k])
            r = run([a.replace("{out}", out[k]) for a in args], ops)
            written = open(out[k], "rb").read() if os.path.exists(out[k]) else None
            results.append((r.returncode, r.stdout, written))
            check(r.returncode == 0 and (r.stdout != "" or written), f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}")
        check(results[0] == results[1], f"vor {' '.join(spaced)} and {' '.join(joined)} differ")
    dump = os.path.join(tmp, "opt.cells")
    with open(dump, "w") as f:
        f.write("box 0 0 1000 1000\n" + run(["cells", "--box", "0", "0", "1000", "1000", sp], "").stdout)
    r, r2 = run(["draw", "--cells", dump, "-o", "-"], ""), run(["draw", "--cells=" + dump, "-o", "-"], "")
    check(r.returncode == 0 and r.stdout.startswith("<?xml") and r2.stdout == r.stdout, f"draw --cells=: {r2.returncode} {r2.stderr!r}")
    # errors: usage, status 2, nothing written
    for args, reason in ((["nearest", sp, qp, "--k"], "missing value after '--k'"),
                         (["nearest", "--k=", sp, qp], "--k"),
                         (["delaunay", "--stats=1", sp], "takes no value"),
                         (["delaunay", "--order=bogus", sp], "'bogus'"),
                         (["cells", "--box=0,0,9", sp], "expected 4 comma-separated values in '--box=0,0,9'"),
                         (["cells", sp, "--box", "0", "0", "9"], "missing value after '--box'"),
                         (["raster", "--size=4", sp, "--labels", out[0]], "'--size=4'"),
                         (["draw", "-o=x.svg", sp], "unknown option '-o=x.svg'"),
                         (["ops", "--capacity", "-1", "-"], "--capacity"),
                         (["predicates", "--scale"], "missing value after '--scale'"),
                         (["predicates", "--frobnicate=1"], "unknown option '--frobnicate=1'")):
        if os.path.exists(out[0]):
            os.remove(out[0])
        r = run(args, ops)
        check(r.returncode == 2 and r.stdout == "" and reason in r.stderr and f"usage: vor {args[0]}" in r.stderr
              and not os.path.exists(out[0]), f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}")


def version_cases():
    # The expected string is read from the header's three numeric macros,
    # so a STRING that disagrees with MAJOR/MINOR/PATCH fails too.
    import os
    import re
    header = open(os.path.join(os.path.dirname(__file__), "..", "..", "include", "vor.h")).read()
    parts = [re.search(rf"#define VOR_VERSION_{p} (\d+)\b", header) for p in ("MAJOR", "MINOR", "PATCH")]
    check(all(parts), "vor.h defines VOR_VERSION_MAJOR, _MINOR and _PATCH")
    if all(parts):
        expected = "vor " + ".".join(m.group(1) for m in parts) + "\n"
        r = run(["--version"], "")
        check(r.returncode == 0 and r.stdout == expected and r.stderr == "",
              f"--version: {r.returncode} {r.stdout!r}, expected {expected!r}")


COMMANDS = ("predicates", "delaunay", "nearest", "raster", "cells", "draw", "ops", "cdt", "power", "interpolate",
            "locate", "within")


def help_cases(tmp):
    """--help and vor COMMAND --help on stdout with status 0; each help's
    example, run in a shell, prints what the help says it prints."""
    import os
    for args in (["--help"], ["help"], ["-h"]):
        r = run(args, "")
        check(r.returncode == 0 and r.stderr == "" and all(c in r.stdout for c in COMMANDS)
              and "x,y" in r.stdout and "--scale" in r.stdout, f"vor {args[0]}: {r.returncode} {r.stderr!r}")
    env = dict(os.environ, PATH=os.path.dirname(os.path.abspath(VOR)) + os.pathsep + os.environ["PATH"])
    for command in COMMANDS:
        for args in ([command, "--help"], ["help", command], [command, "-", "--help"]):
            r = run(args, "")
            check(r.returncode == 0 and r.stderr == "" and r.stdout.startswith(f"usage: vor {command}")
                  and "input:" in r.stdout and "output:" in r.stdout and "example:" in r.stdout,
                  f"vor {' '.join(args)}: {r.returncode} {r.stdout[:60]!r} {r.stderr!r}")
        # the example: "  $ command" lines, each followed by its output
        lines = run([command, "--help"], "").stdout.split("example:\n", 1)[-1].splitlines()
        steps = []
        for line in lines:
            if line.startswith("  $ "):
                steps.append([line[4:], []])
            elif steps:
                steps[-1][1].append(line[2:])
        check(len(steps) > 0, f"vor {command} --help: no example")
        for shell, expected in steps:
            r = subprocess.run(shell, shell=True, cwd=tmp, env=env, capture_output=True, text=True)
            got = [l.split() for l in r.stdout.splitlines()]
            check(r.returncode == 0 and got == [l.split() for l in expected],
                  f"vor {command} --help example {shell!r}: {r.returncode} {r.stdout!r} {r.stderr!r}")
    r = run(["bogus"], "")
    check(r.returncode == 2 and r.stdout == "" and "unknown command 'bogus'" in r.stderr and "vor --help" in r.stderr,
          f"vor bogus: {r.returncode} {r.stderr!r}")
    r = run(["help", "bogus"], "")
    check(r.returncode == 2 and r.stdout == "" and "unknown command 'bogus'" in r.stderr, f"vor help bogus: {r.stderr!r}")
    r = run(["--bogus"], "")
    check(r.returncode == 2 and r.stdout == "" and "unknown option '--bogus'" in r.stderr, f"vor --bogus: {r.stderr!r}")
    r = run([], "")
    check(r.returncode == 2 and r.stdout == "" and "usage: vor COMMAND" in r.stderr, f"vor: {r.returncode} {r.stderr!r}")
    # an unknown option is named, with the command's usage
    for args in (["predicates", "--frobnicate"], ["delaunay", "--frobnicate", "-"], ["nearest", "--frobnicate", "-", "-"],
                 ["cells", "--box", "0", "0", "1", "1", "--frobnicate", "-"],
                 ["draw", "--frobnicate", "-", "-o", os.path.join(tmp, "x.svg")],
                 ["raster", "--size", "2", "2", "--frobnicate", "-", "--labels", os.path.join(tmp, "x.raw")]):
        r = run(args, "0 0\n")
        check(r.returncode == 2 and r.stdout == "" and "unknown option '--frobnicate'" in r.stderr
              and f"usage: vor {args[0]}" in r.stderr, f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}")
    r = run(["raster", "--size", "2", "2", "-", "--labels"], "0 0\n")
    check(r.returncode == 2 and "missing value after '--labels'" in r.stderr, f"raster --labels without a path: {r.stderr!r}")
    r = run(["delaunay", "--scale"], "0 0\n")
    check(r.returncode == 2 and "--scale" in r.stderr, f"--scale without S: {r.stderr!r}")
    for bad in ("0", "-1", "x", "1.5.2", ""):
        r = run(["delaunay", "--scale", bad, "-"], "0 0\n")
        check(r.returncode == 2 and r.stdout == "" and f"--scale" in r.stderr and f"'{bad}'" in r.stderr,
              f"--scale {bad!r}: {r.returncode} {r.stderr!r}")


def file_error_cases(tmp):
    """Files that cannot be read or written: status 2, the path and the
    system's reason, nothing on stdout, an existing output untouched."""
    import errno
    import os
    sites = os.path.join(tmp, "fe.sites")
    with open(sites, "w") as f:
        f.write("0 0\n5 1\n2 7\n")
    missing, not_dir = os.path.join(tmp, "no-such-file"), os.path.join(sites, "x")
    for path, code in ((tmp, errno.EISDIR), (missing, errno.ENOENT), (not_dir, errno.ENOTDIR)):
        for args in (["delaunay", path], ["nearest", path, sites], ["nearest", sites, path],
                     ["cells", "--box", "0", "0", "9", "9", path],
                     ["raster", "--size", "3", "3", path, "--labels", os.path.join(tmp, "fe.raw")]):
            r = run(args, "")
            want = f"error: {path}: {os.strerror(code)}\n"
            check(r.returncode == 2 and r.stdout == "" and r.stderr == want,
                  f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}, expected {want!r}")
    # a NUL byte is an error on its line, not a silently dropped line
    for text, line in (("0 0\n1\x002\n3 3\n", 2), ("\x00\n", 1), ("0 0\n# c\x00\n", 2)):
        r = run(["delaunay", "-"], text)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: <stdin>:{line}: NUL byte"),
              f"NUL in {text!r}: {r.returncode} {r.stderr!r}")
    # empty inputs: 0 sites, no output (delaunay, cells), no queries (nearest)
    empty = os.path.join(tmp, "empty")
    open(empty, "w").close()
    for args in (["delaunay", empty], ["cells", "--box", "0", "0", "1", "1", empty], ["nearest", sites, empty],
                 ["nearest", empty, empty], ["delaunay", "-"]):
        r = run(args, "# only a comment\n\n")
        check(r.returncode == 0 and r.stdout == "" and r.stderr == "", f"empty: vor {' '.join(args)}: {r.returncode} {r.stderr!r}")
    r = run(["nearest", empty, sites], "")
    check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: {empty}: no sites"), f"nearest with no sites: {r.stderr!r}")
    r = run(["raster", "--size", "2", "2", empty, "--labels", os.path.join(tmp, "fe.raw")], "")
    check(r.returncode == 2 and r.stderr.startswith(f"error: {empty}: no sites"), f"raster with no sites: {r.stderr!r}")
    # outputs: a failing run leaves an existing output as it was and no
    # temporary file behind; an unwritable path names the path and reason
    out = os.path.join(tmp, "keep.raw")
    bad_sites = os.path.join(tmp, "fe-bad.sites")
    with open(bad_sites, "w") as f:
        f.write("0 0\n1 x\n")
    for kind in ("--labels", "--png"):
        with open(out, "w") as f:
            f.write("keep")
        before = sorted(os.listdir(tmp))
        r = run(["raster", "--size", "3", "3", bad_sites, kind, out], "")
        check(r.returncode == 2 and open(out).read() == "keep" and sorted(os.listdir(tmp)) == before,
              f"raster {kind} with a bad site line: {r.returncode}, output changed or a temporary file left")
        for path, code in ((os.path.join(missing, "out"), errno.ENOENT), (tmp, errno.EISDIR),
                           (os.path.join(not_dir), errno.ENOTDIR)):
            r = run(["raster", "--size", "3", "3", sites, kind, path], "")
            want = f"error: {path}: {os.strerror(code)}\n"
            check(r.returncode == 2 and r.stderr == want, f"raster {kind} {path}: {r.returncode} {r.stderr!r}, expected {want!r}")
        check(sorted(os.listdir(tmp)) == before, f"raster {kind}: a temporary file was left behind")
        r = run(["raster", "--size", "3", "3", sites, kind, out], "")
        check(r.returncode == 0 and open(out, "rb").read() != b"keep" and sorted(os.listdir(tmp)) == before
              and (os.stat(out).st_mode & 0o777) == 0o666 & ~current_umask(),
              f"raster {kind} over an existing file: {r.returncode} {r.stderr!r} mode {oct(os.stat(out).st_mode)}")
    # standard output on a full device, and an input without permission
    if os.path.exists("/dev/full"):
        with open("/dev/full", "w") as full:
            r = subprocess.run([VOR, "delaunay", sites], stdout=full, capture_output=False,
                               stderr=subprocess.PIPE, text=True)
        want = f"error: <stdout>: {os.strerror(errno.ENOSPC)}\n"
        check(r.returncode == 2 and r.stderr == want, f"stdout on /dev/full: {r.returncode} {r.stderr!r}")
    if os.geteuid() != 0:  # root reads any file
        locked = os.path.join(tmp, "locked.sites")
        with open(locked, "w") as f:
            f.write("0 0\n")
        os.chmod(locked, 0)
        r = run(["delaunay", locked], "")
        check(r.returncode == 2 and r.stderr == f"error: {locked}: {os.strerror(errno.EACCES)}\n",
              f"unreadable file: {r.returncode} {r.stderr!r}")
        os.remove(locked)
    # a frame outside int32 is explained, not a bare library error number
    r = run(["raster", "--size", "4", "4", "--origin", "2147483647", "0", sites, "--labels", out], "")
    check(r.returncode == 2 and "(2147483650, 3)" in r.stderr and "int32" in r.stderr and "error -1" not in r.stderr,
          f"raster --origin 2147483647: {r.stderr!r}")


def error_name_cases():
    """No library error is reachable through the checked arguments, so the
    table behind "error: CALL: VOR_ERR_X: meaning" is checked against the
    header: every code of enum vor_error has its name and a meaning."""
    import os
    import re
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    header = open(os.path.join(root, "include", "vor.h")).read()
    source = open(os.path.join(root, "tools", "cli", "cli.c")).read()
    names = re.findall(r"^\s*(VOR_ERR_[A-Z_]+) = -\d+", header, re.M)
    check(len(names) >= 9, f"vor.h: only {len(names)} error codes found")
    for name in names:
        check(re.search(rf'case {name}: return "{name}: [a-z]', source) is not None,
              f"tools/cli/cli.c: cli_error_text does not name {name}")


def current_umask():
    import os
    mask = os.umask(0)
    os.umask(mask)
    return mask


def round_half_away(v):
    """v rounded to the nearest integer, ties away from zero."""
    import math
    from fractions import Fraction as F
    n = math.floor(abs(v) + F(1, 2))
    return n if v >= 0 else -n


def decimal_text(v):
    """An exact decimal string of the fraction v (its denominator 2^a 5^b)."""
    import decimal
    with decimal.localcontext() as ctx:
        ctx.prec = 200
        ctx.traps[decimal.Inexact] = True
        return str(decimal.Decimal(v.numerator) / decimal.Decimal(v.denominator))


def input_cases(rng, tmp):
    """CSV input and --scale: the same answers as the integer form, and
    scaled values equal to Python's exact rounding of the fraction."""
    import os
    from fractions import Fraction as F
    pts = [(rng.randint(-10**6, 10**6), rng.randint(-10**6, 10**6)) for _ in range(60)]
    plain = "".join(f"{x} {y}\n" for x, y in pts)
    ref = run(["delaunay", "-"], plain)
    check(ref.returncode == 0 and ref.stdout.startswith("t "), f"delaunay reference: {ref.stderr!r}")
    forms = {
        "csv": "".join(f"{x},{y}\n" for x, y in pts),
        "csv header": "x,y\n" + "".join(f"{x},{y}\n" for x, y in pts),
        "quoted header, blanks, CRLF": '"x", "y"\r\n' + "".join(f" {x} ,\t{y}\r\n" for x, y in pts),
        "comment then header": "# exported\nlon,lat\n" + "".join(f"{x},{y}\n" for x, y in pts),
    }
    for name, text in forms.items():
        r = run(["delaunay", "-"], text)
        check(r.returncode == 0 and r.stdout == ref.stdout, f"delaunay {name}: {r.returncode} {r.stderr!r}")
    sp, qp = os.path.join(tmp, "in.sites"), os.path.join(tmp, "in.queries")
    queries = [(rng.randint(-10**6, 10**6), rng.randint(-10**6, 10**6)) for _ in range(40)]
    with open(sp, "w") as f:
        f.write(forms["csv header"])
    with open(qp, "w") as f:
        f.write("qx,qy\n" + "".join(f"{x},{y}\n" for x, y in queries))
    r = run(["nearest", "--k=3", sp, qp], "")
    want = [sorted(range(len(pts)), key=lambda i: ((pts[i][0] - qx) ** 2 + (pts[i][1] - qy) ** 2, i))[:3] for qx, qy in queries]
    check(r.returncode == 0 and [[int(v) for v in l.split()] for l in r.stdout.splitlines()] == want,
          f"nearest CSV: {r.returncode} {r.stderr!r}")
    r = run(["cells", "--box", "-1000000", "-1000000", "1000000", "1000000", sp], "")
    r2 = run(["cells", "--box", "-1000000", "-1000000", "1000000", "1000000", "-"], plain)
    check(r.returncode == 0 and r.stdout == r2.stdout and r.stdout != "", f"cells CSV: {r.returncode} {r.stderr!r}")
    r = run(["raster", "--size", "5", "4", "--metric", "add", "-", "--labels", os.path.join(tmp, "csv.raw")], "x,y,w\n1,1,2\n4,3,0\n")
    r2 = run(["raster", "--size", "5", "4", "--metric", "add", "-", "--labels", os.path.join(tmp, "plain.raw")], "1 1 2\n4 3 0\n")
    check(r.returncode == 0 and r2.returncode == 0 and open(os.path.join(tmp, "csv.raw"), "rb").read()
          == open(os.path.join(tmp, "plain.raw"), "rb").read(), f"raster CSV: {r.stderr!r} {r2.stderr!r}")
    r = run(["predicates"], "o,0,0,1,0,0,1\nc, 0, 0, 2, 0, 0, 2, 2, 2\n")
    check(r.returncode == 0 and r.stdout == "1\n0\n", f"predicates CSV: {r.returncode} {r.stdout!r} {r.stderr!r}")
    # malformed CSV, and a header anywhere but first, name their line
    for text, line, reason in (("0,0\n1,,2\n", 2, "CSV field 2 is empty"), ("0,0\n1,2,\n", 2, "CSV field 3 is empty"),
                               ("x,y\n0,0\nx,y\n", 3, "'x'"), ("0,0\n1 2,3\n", 2, "blank"),
                               ("x y\n0 0\n", 1, "'x'"), ("0,0\n1;2\n", 2, "'1;2'"), ("0,0,0\n", 1, "too many fields")):
        r = run(["delaunay", "-"], text)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: <stdin>:{line}: ") and reason in r.stderr,
              f"delaunay {text!r}: {r.returncode} {r.stderr!r}")
    # --scale: each line compares the scaled x of a with the line x = E of
    # b and c (E from exact fractions, given as E/S so that it scales back
    # to E): orient2d is 0 exactly when vor's value equals E
    scales = ["1", "1000", "0.5", "2.5", "0.001", "64", "1e6", "0.125", "1E-2", "3.2", "+4", "0.0000390625"]
    fixed = ["0.5", "-0.5", "2.5", "-2.5", "1.49999999999999999999", "-1.5000000000000000000000001", "0", "-0",
             ".5", "7.", "1e0", "-3E+2", "0.000", "00012.3400"]
    for scale in scales:
        values = list(fixed)
        for _ in range(80):
            digits = "".join(rng.choice("0123456789") for _ in range(rng.randint(0, 9)))
            fraction = "".join(rng.choice("0123456789") for _ in range(rng.randint(0, 14)))
            text = (digits or "0") + ("." + fraction if fraction else "")
            if rng.random() < 0.3:
                text += rng.choice("eE") + rng.choice(["", "+", "-"]) + str(rng.randint(0, 4))
            values.append(rng.choice(["", "-", "+"]) + text)
        S = F(scale)
        lines, expected_error = [], None
        for v in values:
            e = round_half_away(F(v) * S)
            if not MIN <= e <= MAX:
                continue
            back, unit = decimal_text(F(e) / S), decimal_text(1 / S)
            lines.append(f"o {v} 0 {back} {unit} {back} -{unit}")
        r = run(["predicates", "--scale", scale], "\n".join(lines) + "\n")
        got = r.stdout.split()
        wrong = sum(g != "0" for g in got)
        check(r.returncode == 0 and len(got) == len(lines) and wrong == 0,
              f"--scale {scale}: {r.returncode} {r.stderr!r}, {wrong} of {len(lines)} values differ from exact rounding")
    # the int32 boundary after scaling, with the line of the bad value
    for scale, value, ok in (("1", "2147483647.4999999", True), ("1", "2147483647.5", False),
                             ("1", "-2147483648.4999", True), ("1", "-2147483648.5", False),
                             ("1000", "2147483.6474999", True), ("1000", "2147483.6475", False),
                             ("0.001", "2147483647499.99", True), ("1e9", "3", False), ("1", "1e10", False),
                             ("1", "1e-100000000", True), ("1", "4e100000000", False)):
        r = run(["delaunay", "--scale", scale, "-"], f"0 0\n# c\n1 {value}\n")
        if ok:
            check(r.returncode == 0, f"--scale {scale} {value}: {r.returncode} {r.stderr!r}")
        else:
            check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith("error: <stdin>:3: out of int32 range")
                  and f"'{value}'" in r.stderr, f"--scale {scale} {value}: {r.returncode} {r.stderr!r}")
    for bad in ("1.2.3", "1e", "--1", ".", "1x", "e5"):
        r = run(["delaunay", "--scale", "10", "-"], f"0 0\n{bad} 1\n")
        check(r.returncode == 2 and r.stderr.startswith(f"error: <stdin>:2: not a decimal number: '{bad}'"),
              f"--scale 10 {bad!r}: {r.returncode} {r.stderr!r}")
    r = run(["delaunay", "-"], "0 0\n1.5 2\n")
    check(r.returncode == 2 and "--scale" in r.stderr, f"a decimal without --scale suggests it: {r.stderr!r}")
    # every command reads scaled points: the same answers as the integers
    scaled = "".join(f"{decimal_text(F(x, 1000))},{decimal_text(F(y, 1000))}\n" for x, y in pts)
    r = run(["delaunay", "--scale", "1000", "-"], "x,y\n" + scaled)
    check(r.returncode == 0 and r.stdout == ref.stdout, f"delaunay --scale: {r.returncode} {r.stderr!r}")
    cells_ref = run(["cells", "--box", "-1000000", "-1000000", "1000000", "1000000", "-"], plain).stdout
    r = run(["cells", "--scale", "1000", "--box", "-1000000", "-1000000", "1000000", "1000000", "-"], scaled)
    check(r.returncode == 0 and r.stdout == cells_ref, f"cells --scale: {r.returncode} {r.stderr!r}")
    # the queries (integers in qp) are scaled too: 1000 times farther out
    r = run(["nearest", "--scale", "1000", "-", qp], scaled)
    want = [min(range(len(pts)), key=lambda i: ((pts[i][0] - 1000 * qx) ** 2 + (pts[i][1] - 1000 * qy) ** 2, i))
            for qx, qy in queries]
    check(r.returncode == 0 and [int(v) for v in r.stdout.split()] == want, f"nearest --scale: {r.returncode} {r.stderr!r}")
    r = run(["raster", "--size", "5", "4", "--metric", "add", "--scale", "10", "-", "--labels", os.path.join(tmp, "csv.raw")],
            "0.1,0.1,0.2\n0.4,0.3,0\n")
    check(r.returncode == 0 and open(os.path.join(tmp, "csv.raw"), "rb").read() == open(os.path.join(tmp, "plain.raw"), "rb").read(),
          f"raster --scale: {r.returncode} {r.stderr!r}")

def ops_cases(rng):
    """vor ops against a Python model of the dynamic diagram: live sites by
    id, the most recently freed id reused first (as vor.h documents), nearest by
    exact distance with ties to the smaller id, and brute-force triangles
    of sites in general position (full-range random coordinates)."""
    for trial in range(6):
        live, free, fresh = {}, [], 0  # free: the most recently freed id last
        lines, expected = [], []
        for step in range(60):
            op = rng.choice("iiiirmmnt") if live else "i"
            if op == "i":
                if live and rng.random() < 0.15:
                    x, y = live[rng.choice(sorted(live))]
                else:
                    x, y = rng.randint(MIN, MAX), rng.randint(MIN, MAX)
                lines.append(f"i {x} {y}")
                same = [k for k, p in live.items() if p == (x, y)]
                if same:
                    expected.append(f"d {same[0]}")
                else:
                    if free:
                        new = free.pop()
                    else:
                        new, fresh = fresh, fresh + 1
                    live[new] = (x, y)
                    expected.append(str(new))
            elif op == "r":
                k = rng.choice(sorted(live))
                lines.append(f"r {k}")
                del live[k]
                free.append(k)
                expected.append("ok")
            elif op == "m":
                k = rng.choice(sorted(live))
                if rng.random() < 0.2 and len(live) > 1:
                    x, y = live[rng.choice([j for j in sorted(live) if j != k])]
                else:
                    x, y = rng.randint(MIN, MAX), rng.randint(MIN, MAX)
                lines.append(f"m {k} {x} {y}")
                same = [j for j, p in live.items() if p == (x, y) and j != k]
                if same:
                    expected.append(f"d {same[0]}")
                else:
                    live[k] = (x, y)
                    expected.append("ok")
            elif op == "n":
                x, y = rng.randint(MIN, MAX), rng.randint(MIN, MAX)
                lines.append(f"n {x} {y}")
                expected.append(str(min(live, key=lambda j: ((live[j][0] - x) ** 2 + (live[j][1] - y) ** 2, j))))
            else:
                lines.append("t")
                ids = sorted(live)
                tris = brute_delaunay([live[j] for j in ids]) if len(ids) >= 3 else set()
                mapped = sorted(tuple(ids[v] for v in t) for t in tris)
                rotated = []
                for t in mapped:
                    m = t.index(min(t))
                    rotated.append(t[m:] + t[:m])
                expected.extend(f"t {a} {b} {c}" for a, b, c in sorted(rotated))
                expected.append("end")
        r = run(["ops", "-"], "\n".join(lines) + "\n")
        check(r.returncode == 0, f"ops trial {trial}: status {r.returncode} {r.stderr.strip()}")
        check(r.stdout.splitlines() == expected, f"ops trial {trial}: output differs from the model")
    # errors: the line, the reason, nothing on stdout
    for text, line, reason in (("i 0 0\nr 5\n", 2, "unknown site id"),
                               ("i 0 0\nm 3 1 1\n", 2, "unknown site id"),
                               ("i 0 0\ni 1 1\ni 2 2\n", 3, "full"),
                               ("n 0 0\n", 1, "no sites"),
                               ("i 0\n", 1, ""),
                               ("x 1 2\n", 1, "expected")):
        args = ["ops", "--capacity", "2", "-"] if reason == "full" else ["ops", "-"]
        r = run(args, text)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: <stdin>:{line}: ")
              and reason in r.stderr, f"ops bad input {text!r}: {r.returncode} {r.stderr!r}")

    # a header is skipped only when it cannot be an operation: a CSV first
    # line is read like any other, and a mixed one is an error on its line
    r = run(["ops", "-"], "i,0,0\ni,10,0\ni,0,10\nn,9,1\n")
    check(r.returncode == 0 and r.stdout == "0\n1\n2\n1\n", f"ops CSV first line: {r.returncode} {r.stdout!r} {r.stderr!r}")
    r = run(["ops", "-"], "op,x,y\ni,0,0\nn,1,1\n")
    check(r.returncode == 0 and r.stdout == "0\n0\n", f"ops header: {r.returncode} {r.stdout!r} {r.stderr!r}")
    for text, line in (("i 0,0\n", 1), ("i,0,0\ni 0,0\n", 2), ("# c\nn,x,1\n", 2), ("i,0,0\nop,x,y\n", 2)):
        r = run(["ops", "-"], text)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: <stdin>:{line}: "),
              f"ops {text!r}: {r.returncode} {r.stdout!r} {r.stderr!r}")

    # --scale: coordinates of i, m and n scaled as every command's are
    # (ids are not), so a script in decimal units gives the integer run's output
    from fractions import Fraction as F
    script, scaled = [], []
    for step in range(80):
        op = rng.choice("iiimn") if step > 3 else "i"
        x, y = rng.randint(-10**6, 10**6), rng.randint(-10**6, 10**6)
        k = rng.randint(0, 3)
        dx, dy = decimal_text(F(x, 1000)), decimal_text(F(y, 1000))
        script.append({"i": f"i {x} {y}", "m": f"m {k} {x} {y}", "n": f"n {x} {y}"}[op])
        scaled.append({"i": f"i,{dx},{dy}", "m": f"m {k} {dx} {dy}", "n": f"n {dx} {dy}"}[op])
    script.append("t")
    scaled.append("t")
    ref = run(["ops", "-"], "\n".join(script) + "\n")
    r = run(["ops", "--scale", "1000", "-"], "\n".join(scaled) + "\n")
    check(ref.returncode == 0 and "t " in ref.stdout and r.returncode == 0 and r.stdout == ref.stdout,
          f"ops --scale: {ref.returncode} {r.returncode} {r.stderr!r}")
    r = run(["ops", "--scale", "2.5", "-"], "i 0.2 -0.2\ni 0.6 0.2\nn 0.4 0\nn 0.61 0.2\nm 1 0.2 -0.2\n")
    check(r.returncode == 0 and r.stdout == "0\n1\n0\n1\nd 0\n", f"ops --scale 2.5: {r.returncode} {r.stdout!r} {r.stderr!r}")
    r = run(["ops", "--scale", "10", "-"], "i 1 1\nr 0.0\n")
    check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith("error: <stdin>:2: not a decimal integer"),
          f"ops --scale: an id stays an integer: {r.returncode} {r.stderr!r}")


def header_cases(tmp):
    """The same header rule for every input: a first CSV line is a header
    only when no field of it is a number, so no record is dropped."""
    import os
    pts = "0,0\n10,0\n0,10\n"
    ref = run(["delaunay", "-"], pts).stdout
    for text in ("x,y\n" + pts, '"x" , Y\n' + pts, "# c\n\nlon,lat\n" + pts):
        r = run(["delaunay", "-"], text)
        check(r.returncode == 0 and r.stdout == ref, f"header {text!r}: {r.returncode} {r.stderr!r}")
    for text, line in (("x,0\n" + pts, 1), ("0,y\n" + pts, 1), ("x,,y\n" + pts, 1), ("x y\n" + pts, 1)):
        r = run(["delaunay", "-"], text)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: <stdin>:{line}: "),
              f"not a header {text!r}: {r.returncode} {r.stderr!r}")
    # a UTF-8 byte-order mark opening a file or stdin is dropped, before a
    # header or a record; anywhere else it is an error on its line
    sp = os.path.join(tmp, "bom.sites")
    for text in ("\ufeffx,y\n" + pts, "\ufeff" + pts, "\ufeff0 0\n10 0\n0 10\n", "\ufeff\n# c\n" + pts):
        with open(sp, "w", encoding="utf-8") as f:
            f.write(text)
        for args in (["delaunay", "-"], ["delaunay", sp]):
            r = run(args, text)
            check(r.returncode == 0 and r.stdout == ref, f"byte-order mark {args} {text!r}: {r.returncode} {r.stderr!r}")
    r = run(["ops", "-"], "\ufeffi 0 0\nn 1 1\n")
    check(r.returncode == 0 and r.stdout == "0\n0\n", f"ops byte-order mark: {r.returncode} {r.stdout!r} {r.stderr!r}")
    r = run(["predicates"], "\ufeffo 0 0 1 0 0 1\n")
    check(r.returncode == 0 and r.stdout == "1\n", f"predicates byte-order mark: {r.returncode} {r.stdout!r} {r.stderr!r}")
    r = run(["delaunay", "-"], "0 0\n\ufeff10 0\n")
    check(r.returncode == 2 and r.stderr.startswith("error: <stdin>:2: "), f"byte-order mark on line 2: {r.returncode} {r.stderr!r}")
    r = run(["predicates"], "op,ax,ay,bx,by,cx,cy\no,0,0,1,0,0,1\n")
    check(r.returncode == 0 and r.stdout == "1\n", f"predicates header: {r.returncode} {r.stdout!r} {r.stderr!r}")


def hull_size(pts):
    """Points on the convex hull's boundary, collinear ones included."""
    pts = sorted(set(pts))
    if len(pts) < 3:
        return len(pts)

    def chain(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and orient(out[-2], out[-1], p) < 0:
                out.pop()
            out.append(p)
        return out
    lower, upper = chain(pts), chain(reversed(pts))
    return len(lower) + len(upper) - 2


def on_open_segment(a, b, p):
    """Is p (Fractions) strictly inside segment a-b?"""
    if (b[0] - a[0]) * (p[1] - a[1]) != (b[1] - a[1]) * (p[0] - a[0]):
        return False
    t = (p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1])
    return 0 < t < (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2


def check_cdt_output(sites, pairs, out, domain, what):
    """vor cdt's output against the definition: crossing vertices exactly
    where two constraints cross off the sites, counterclockwise triangles
    covering the hull, every edge that is no constraint locally Delaunay
    (exact rationals), the constrained edges the constraints' pieces, and
    with --domain the inside flipping across odd edges only."""
    from fractions import Fraction as F
    from math import gcd
    first = {}
    point = {}
    for i, p in enumerate(sites):
        first.setdefault(p, i)
        point[i] = (F(p[0]), F(p[1]))
    distinct = [i for i, p in enumerate(sites) if first[p] == i]
    cons = [(first[sites[a]], first[sites[b]]) for a, b in pairs if first[sites[a]] != first[sites[b]]]
    lines = out.split("\n")[:-1]
    ok = True
    n = len(sites)
    crossings = [l.split() for l in lines if l.startswith("s ")]
    tris = [tuple(map(int, l.split()[1:])) for l in lines if l.startswith("t ")]
    edges = set(tuple(map(int, l.split()[1:])) for l in lines if l.startswith("c "))
    for k, c in enumerate(crossings):
        cid, a, b, c2, d2, x, y, w = map(int, c[1:])
        ok &= cid == n + k and w > 0 and gcd(gcd(abs(x), abs(y)), w) == 1
        p = (F(x, w), F(y, w))
        ok &= on_open_segment(point[a], point[b], p) and on_open_segment(point[c2], point[d2], p)
        ok &= (a, b) in cons and (c2, d2) in cons
        ok &= all(p != point[i] for i in distinct) and all(p != point[j] for j in point if j >= n)
        point[cid] = p
    # every crossing of two constraints off the sites has its vertex
    for i in range(len(cons)):
        for j in range(i):
            a, b = (point[v] for v in cons[i])
            c, d = (point[v] for v in cons[j])
            den = (b[0] - a[0]) * (d[1] - c[1]) - (b[1] - a[1]) * (d[0] - c[0])
            if den == 0:
                continue
            t = ((c[0] - a[0]) * (d[1] - c[1]) - (c[1] - a[1]) * (d[0] - c[0])) / den
            p = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
            if on_open_segment(a, b, p) and on_open_segment(c, d, p) and \
                    all(p != point[v] for v in distinct):
                ok &= any(point[v] == p for v in point if v >= n)
    # the pieces
    pieces = set()
    for a, b in cons:
        on = sorted((v for v in point if v not in (a, b) and (v >= n or first[sites[v]] == v)
                     and on_open_segment(point[a], point[b], point[v])),
                    key=lambda v: abs(point[v][0] - point[a][0]) + abs(point[v][1] - point[a][1]))
        chain = [a] + on + [b]
        pieces |= {(min(u, v), max(u, v)) for u, v in zip(chain, chain[1:])}
    ok &= edges == pieces
    # triangles
    half = {}
    for t in tris:
        if len(t) != 3 or orient(*(point[v] for v in t)) <= 0:
            ok = False
            continue
        for k in range(3):
            half.setdefault((t[k], t[(k + 1) % 3]), t[(k + 2) % 3])
    for (u, v), w in half.items():
        z = half.get((v, u))
        if z is not None and (min(u, v), max(u, v)) not in edges:
            ok &= incircle(point[u], point[v], point[w], point[z]) <= 0
    if not domain:
        h = hull_size([sites[i] for i in distinct])
        expected = 2 * (len(distinct) + len(crossings)) - h - 2 if len(tris) else 0
        ok &= len(tris) == expected
    check(ok, f"vor cdt {what}: output does not satisfy the definition")
    return tris, edges, point


def cdt_cases(rng, tmp):
    """vor cdt on random sites and crossing constraints, grids with
    constraints along their lines, a polygon with a hole (--domain, checked
    by parity), and its errors."""
    import os
    from fractions import Fraction as F
    for case in range(24):
        span = (6, 1000, 2**31 - 1)[case % 3]
        n = rng.randint(3, 40)
        sites = [(rng.randint(-span, span) if span < MAX else rng.randint(MIN, MAX),
                  rng.randint(-span, span) if span < MAX else rng.randint(MIN, MAX)) for _ in range(n)]
        pairs = [(rng.randrange(n), rng.randrange(n)) for _ in range(rng.randint(0, 10))]
        sp, cp = os.path.join(tmp, "s.txt"), os.path.join(tmp, "c.txt")
        open(sp, "w").write("".join(f"{x} {y}\n" for x, y in sites))
        open(cp, "w").write("".join(f"{a} {b}\n" for a, b in pairs))
        r = run(["cdt", sp, cp], "")
        check(r.returncode == 0 and r.stderr == "", f"vor cdt case {case}: {r.returncode} {r.stderr!r}")
        if r.returncode == 0:
            check_cdt_output(sites, pairs, r.stdout, False, f"case {case}")
    # full-range sites whose crossing's s line once named no constraint:
    # the tool's own check that the point lies on a constraint overflowed
    # 128 bits (its products reach 2^131)
    sites = [
        (-1409958251, -966569112), (-94912888, 1626741058), (1713753823, 953058984), (2114128344, 33806560),
        (481998206, 896494184), (47345682, -477804654), (2054298827, -18553515), (-1247455157, 1597016486),
        (888270844, -1940102144), (-71489056, 1895462587), (-328963085, -765662083), (1047602485, 63429302),
        (-2067841113, -1998818340), (-289063547, -1439693884), (1301079743, 1087529875),
        (-707845983, 128565954), (-1553020534, 295678144), (-616975479, -936999918),
        (-994666154, 1478541201), (-1156398636, 1228411541), (1329983873, 2026714104),
        (318230221, 1874246647), (-1211059701, 1658994022), (-1528619729, 2125834683),
        (-1067560038, -1939102901), (-1853286192, -1430852883), (451603214, -640894243),
        (-1822560003, -1961319774), (-1159934071, -1146474538), (-1258540961, 1604302606),
        (985367830, -752618110), (1352743448, 557939545), (2144584273, 570689844), (-1183618859, 814129115),
        (1941585915, 1706082330)
    ]
    pairs = [(23, 30), (23, 3), (27, 33), (26, 33), (9, 16), (12, 22), (8, 9), (23, 17), (5, 13), (32, 34)]
    open(sp, "w").write("".join(f"{x} {y}\n" for x, y in sites))
    open(cp, "w").write("".join(f"{a} {b}\n" for a, b in pairs))
    r = run(["cdt", sp, cp], "")
    check(r.returncode == 0, f"vor cdt full range: {r.returncode} {r.stderr!r}")
    check_cdt_output(sites, pairs, r.stdout, False, "full range")
    # a square with a square hole and a triangle inside the hole: --domain
    sites = [(0, 0), (100, 0), (100, 100), (0, 100), (30, 30), (70, 30), (70, 70), (30, 70),
             (40, 40), (60, 40), (50, 60), (10, 50), (50, 10), (85, 85), (50, 50), (120, 50)]
    pairs = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (8, 9), (9, 10), (10, 8)]
    open(sp, "w").write("".join(f"{x} {y}\n" for x, y in sites))
    open(cp, "w").write("# walls\n" + "".join(f"{a} {b}\n" for a, b in pairs) + "\n3 3\n")
    r = run(["cdt", "--domain", sp, cp], "")
    check(r.returncode == 0, f"vor cdt --domain: {r.returncode} {r.stderr!r}")
    inside, edges, point = check_cdt_output(sites, pairs, r.stdout, True, "--domain")
    full, _, _ = check_cdt_output(sites, pairs, run(["cdt", sp, cp], "").stdout, False, "walls")
    # the inside by a ray from each triangle's centroid: crossings of the walls
    def parity(t):
        cx = sum(point[v][0] for v in t) / 3
        cy = sum(point[v][1] for v in t) / 3
        count = 0
        for a, b in pairs:
            (ax, ay), (bx, by) = point[a], point[b]
            if (ay > cy) != (by > cy):
                x = ax + (cy - ay) * (bx - ax) / (by - ay)
                count += x > cx
        return count % 2
    check(set(inside) == {t for t in full if parity(t)}, "vor cdt --domain: not the even-odd inside")
    check(len(inside) > 0 and len(inside) < len(full), "vor cdt --domain: nothing or everything inside")
    # vor draw of the walls: their crossing vertices as squares, the inside shaded
    svg = os.path.join(tmp, "walls.svg")
    open(cp, "a").write("11 13\n")  # a wall across the hole's square: two crossings
    r = run(["draw", "--constraints", cp, "--domain", sp, "-o", svg], "")
    text = open(svg).read() if r.returncode == 0 else ""
    crossings = sum(1 for l in run(["cdt", sp, cp], "").stdout.splitlines() if l.startswith("s "))
    check(r.returncode == 0 and crossings == 2 and text.count("<rect x=") == crossings and "fill-opacity" in text
          and 'stroke="#202020"' in text, f"vor draw --constraints: {r.returncode} {r.stderr!r}")
    r = run(["draw", "--domain", sp, "-o", svg], "")
    check(r.returncode == 2 and "--domain needs --constraints" in r.stderr, f"draw --domain alone: {r.stderr!r}")
    # errors: a missing site names the file and line; status 2, nothing out
    open(cp, "w").write("0 1\n\n1 16\n")
    r = run(["cdt", sp, cp], "")
    check(r.returncode == 2 and r.stdout == "" and f"{cp}:3:" in r.stderr and "no site 16" in r.stderr,
          f"vor cdt missing site: {r.returncode} {r.stderr!r}")
    open(cp, "w").write("0 x\n")
    r = run(["cdt", sp, cp], "")
    check(r.returncode == 2 and f"{cp}:1:" in r.stderr, f"vor cdt bad id: {r.stderr!r}")
    open(cp, "w").write("0 1 2\n")
    r = run(["cdt", sp, cp], "")
    check(r.returncode == 2 and f"{cp}:1:" in r.stderr, f"vor cdt three ids: {r.stderr!r}")
    # a repeated site is its first: the constraint from a site to its repeat is ignored
    open(sp, "w").write("0 0\n10 0\n0 10\n0 0\n")
    open(cp, "w").write("0 3\n3 1\n")
    r = run(["cdt", sp, cp], "")
    check(r.returncode == 0 and r.stdout.splitlines()[-1] == "c 0 1" and "c 0 3" not in r.stdout,
          f"vor cdt repeated site: {r.stdout!r}")

def power_test(a, b, c, d):
    """The sign of weighted site d's lifted point (x, y, x^2 + y^2 - w)
    against the plane of counterclockwise a, b, c: positive below it."""
    rows = [(p[0] - d[0], p[1] - d[1], (p[0] - d[0]) ** 2 + (p[1] - d[1]) ** 2 - (p[2] - d[2])) for p in (a, b, c)]
    (ax, ay, la), (bx, by, lb), (cx, cy, lc) = rows
    return sign(la * (bx * cy - by * cx) + lb * (cx * ay - cy * ax) + lc * (ax * by - ay * bx))


def hull_area2(pts):
    """Twice the area of the convex hull of pts (exact)."""
    pts = sorted(set(pts))
    if len(pts) < 3:
        return 0

    def chain(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and orient(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]
    ring = chain(pts) + chain(reversed(pts))
    return sum(ring[i][0] * ring[(i + 1) % len(ring)][1] - ring[(i + 1) % len(ring)][0] * ring[i][1]
               for i in range(len(ring)))


def line_status(sites, ids, s):
    """All sites on one line: 1 when site s's lifted point is strictly above
    the lower chain of the others (a heavier site at its point, or a chord
    of sites on either side below it), -1 when it is a strict corner of the
    chain, 0 when it lies on the chain without being a corner."""
    vertical = len({sites[i][0] for i in ids}) == 1
    key = (lambda p: p[1]) if vertical else (lambda p: p[0])

    def lift(p):
        return p[0] ** 2 + p[1] ** 2 - p[2]
    ps, status = sites[s], -1
    for a in ids:
        if a == s:
            continue
        if sites[a][:2] == ps[:2]:
            if sites[a][2] > ps[2]:
                return 1
            continue
        for b in ids:
            ta, ts, tb = key(sites[a]), key(ps), key(sites[b])
            if ta < ts < tb:
                above = (tb - ta) * lift(ps) - (tb - ts) * lift(sites[a]) - (ts - ta) * lift(sites[b])
                if above > 0:
                    return 1
                if above == 0:
                    status = 0
    return status


def power_reference(sites):
    """The regular triangulation by brute force over the lifted sites: the
    ccw triples with no other site's lifted point strictly below their
    plane. Returns (first occurrences, those triples, unique): unique is
    False when a lifted site lies on such a triple's plane without being
    one of its corners (four or more coplanar: not unique)."""
    first = {}
    dup = [first.setdefault(s, i) for i, s in enumerate(sites)]
    ids = [i for i in range(len(sites)) if dup[i] == i]
    faces, unique = set(), True
    for x in range(len(ids)):
        for y in range(x + 1, len(ids)):
            for z in range(y + 1, len(ids)):
                i, j, k = ids[x], ids[y], ids[z]
                o = orient(sites[i], sites[j], sites[k])
                if o == 0:
                    continue
                a, b, c = (i, j, k) if o > 0 else (i, k, j)
                signs = [power_test(sites[a], sites[b], sites[c], sites[l]) for l in ids if l not in (i, j, k)]
                if all(v <= 0 for v in signs):
                    faces.add((a, b, c))
                    unique = unique and 0 not in signs
    return dup, ids, faces, unique


def check_power_output(sites, out, what):
    """vor power's output for sites against the brute force: exactly its
    triangles and hidden sites where the triangulation is unique; its
    invariants where it is not; the duplicates and the line order always."""
    dup, ids, faces, unique = power_reference(sites)
    lines = out.splitlines()
    tris = [tuple(int(v) for v in l.split()[1:]) for l in lines if l.startswith("t ")]
    hidden = [int(l.split()[1]) for l in lines if l.startswith("h ")]
    dups = [tuple(int(v) for v in l.split()[1:]) for l in lines if l.startswith("d ")]
    kinds = [l.split()[0] for l in lines]
    ok = (kinds == sorted(kinds, key="thd".index) and all(len(t) == 3 for t in tris) and all(len(d) == 2 for d in dups)
          and len(tris) + len(hidden) + len(dups) == len(lines))
    check(ok, f"vor power {what}: malformed output {out!r}")
    if not ok:
        return
    check(tris == sorted(tris) and all(t[0] == min(t) for t in tris) and hidden == sorted(set(hidden)),
          f"vor power {what}: lines not sorted, or not from the smallest id")
    check(dups == [(i, dup[i]) for i in range(len(sites)) if dup[i] != i], f"vor power {what}: duplicates {dups}")
    area = hull_area2([s[:2] for s in sites])
    if unique and area > 0:
        want_hidden = sorted(set(ids) - {v for t in faces for v in t})
        want = sorted(tuple(t[k:] + t[:k]) for t in faces for k in range(3) if t[k] == min(t))
        check(tris == want and hidden == want_hidden,
              f"vor power {what}: {tris} hidden {hidden}, brute force {want} hidden {want_hidden}; sites {sites}")
        return
    # not unique (or on a line): the invariants of any regular triangulation
    hid, corner, bad = set(hidden), {v for t in tris for v in t}, []
    if hid - set(ids) or hid & corner:
        bad.append("a hidden site that is a duplicate or a corner")
    if corner - set(ids):
        bad.append("a corner that is a duplicate")
    # the edges cut at the sites inside them: a vertex whose cell has no
    # area may sit inside an edge (its flat triangle is not printed)
    points = {sites[l][:2] for l in ids}

    def pieces(a, b):
        inner = sorted((p for p in points if p not in (a, b) and orient(a, b, p) == 0 and
                        (p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1]) > 0 and
                        (p[0] - b[0]) * (a[0] - b[0]) + (p[1] - b[1]) * (a[1] - b[1]) > 0),
                       key=lambda p: (p[0] - a[0]) ** 2 + (p[1] - a[1]) ** 2)
        chain = [a] + inner + [b]
        return list(zip(chain, chain[1:]))
    edges = [e for t in tris for k in range(3) for e in pieces(sites[t[k]][:2], sites[t[(k + 1) % 3]][:2])]
    for t in tris:
        a, b, c = (sites[v] for v in t)
        if orient(a, b, c) <= 0:
            bad.append(f"{t} not ccw of nonzero area")
        if any(power_test(a, b, c, sites[l]) > 0 for l in ids):
            bad.append(f"a site below the plane of {t}")
    if len(set(edges)) != len(edges):
        bad.append("an edge used twice the same way")
    for u, v in edges:
        if (v, u) not in edges and any(orient(u, v, sites[l]) < 0 for l in ids):
            bad.append(f"the unpaired edge {u} {v} inside the hull")
    if sum(orient2 for orient2 in ((sites[b][0] - sites[a][0]) * (sites[c][1] - sites[a][1]) -
                                   (sites[b][1] - sites[a][1]) * (sites[c][0] - sites[a][0]) for a, b, c in tris)) != area:
        bad.append("the triangles do not cover the hull")

    def under(s):  # the triangles whose closed projection holds site s
        return [t for t in tris if all(orient(sites[t[k]], sites[t[(k + 1) % 3]], sites[s]) >= 0 for k in range(3))]
    for s in ids:
        if area == 0:
            status = line_status(sites, ids, s)
            if (status == 1 and s not in hid) or (status == -1 and s in hid):
                bad.append(f"site {s} on the line: status {status}, hidden {s in hid}")
        elif s in hid and not any(power_test(*(sites[v] for v in t), sites[s]) <= 0 for t in under(s)):
            bad.append(f"hidden site {s} outside the triangles or below them")
        elif s not in hid and s not in corner and not any(power_test(*(sites[v] for v in t), sites[s]) == 0 for t in under(s)):
            bad.append(f"site {s} in no triangle, not hidden, its lifted point off the surface (a cell with area)")
    check(not bad, f"vor power {what}: {bad[:3]}; sites {sites}; output {out!r}")


def power_cases(tmp):
    """vor power on random small sets (ties from small coordinates and
    weights, sites at one point, lines) and full-range ones, against the
    brute force above; CSV, --scale, malformed input and usage errors.
    Its own generator: the sets, and so the count of degenerate ones
    checked below, do not move with the other sections."""
    import os
    rng = random.Random(1128)
    degenerate = 0
    for case in range(160):
        kind = case % 4
        n = rng.randint(0, 12) if kind >= 2 else rng.randint(5, 12)
        sites = []
        for _ in range(n):
            if kind == 3:  # generic: full int32 coordinates, full int64 weights
                s = (rng.randint(MIN, MAX), rng.randint(MIN, MAX), rng.randint(-2**63, 2**63 - 1))
            elif kind == 2:  # on a line, weights small
                t = rng.randint(-4, 4)
                s = (3 * t, -2 * t + 1, rng.randint(-20, 20))
            elif kind == 1:  # a small grid, small weights: ties, sites at one point
                s = (rng.randint(-3, 3), rng.randint(-3, 3), rng.randint(-4, 4))
            else:  # a smaller grid, mostly equal weights: cocircular sites
                s = (rng.randint(-2, 2), rng.randint(-2, 2), rng.choice((0, 0, 0, 0, 1)))
            if sites and rng.random() < 0.2:  # an earlier point, same or other weight
                p = rng.choice(sites)
                s = p if rng.random() < 0.5 else (p[0], p[1], s[2])
            sites.append(s)
        r = run(["power", "-"], "".join(f"{x} {y} {w}\n" for x, y, w in sites))
        check(r.returncode == 0 and r.stderr == "", f"vor power case {case}: {r.returncode} {r.stderr!r}")
        if r.returncode == 0:
            check_power_output(sites, r.stdout, f"case {case}")
            degenerate += not power_reference(sites)[3]
    check(degenerate >= 10, f"vor power: only {degenerate} sets where the triangulation is not unique")
    # the extremes of the ranges, and sites at one point
    sites = [(MIN, MIN, -2**63), (MAX, MIN, 2**63 - 1), (MIN, MAX, 0), (MAX, MAX, -1), (0, 0, 2**63 - 1),
             (0, 0, -2**63), (1, -1, 2**62)]
    r = run(["power", "-"], "".join(f"{x} {y} {w}\n" for x, y, w in sites))
    check(r.returncode == 0, f"vor power extremes: {r.returncode} {r.stderr!r}")
    check_power_output(sites, r.stdout, "extremes")
    r = run(["power", "-"], "5 5 1\n5 5 3\n5 5 3\n5 5 -2\n")
    check(r.returncode == 0 and r.stdout == "h 0\nh 3\nd 2 1\n", f"vor power one point: {r.stdout!r}")
    # the same sites as CSV (with a header), and scaled (the weights by S^2)
    sites = [(rng.randint(-50, 50), rng.randint(-50, 50), rng.randint(-400, 400)) for _ in range(12)]
    ref = run(["power", "-"], "".join(f"{x} {y} {w}\n" for x, y, w in sites))
    check(ref.returncode == 0 and ref.stdout.startswith("t "), f"vor power reference: {ref.stderr!r}")
    for args, text in ((["power", "-"], "x,y,w\n" + "".join(f"{x},{y},{w}\n" for x, y, w in sites)),
                       (["power", "-"], "# c\n\n" + "".join(f" {x} ,\t{y}, {w}\r\n" for x, y, w in sites)),
                       (["power", "--scale", "10", "-"], "".join(f"{x / 10} {y / 10} {w / 100}\n" for x, y, w in sites)),
                       (["power", "--scale=0.5", "-"], "".join(f"{2 * x},{2 * y},{4 * w}\n" for x, y, w in sites))):
        r = run(args, text)
        check(r.returncode == 0 and r.stdout == ref.stdout, f"vor {' '.join(args)} {text[:20]!r}: {r.returncode} {r.stderr!r}")
    sp = os.path.join(tmp, "power.sites")
    with open(sp, "w") as f:
        f.write("".join(f"{x} {y} {w}\n" for x, y, w in sites))
    r = run(["power", sp], "")
    check(r.returncode == 0 and r.stdout == ref.stdout, f"vor power FILE: {r.returncode} {r.stderr!r}")
    # malformed input: status 2, its line, nothing on stdout
    for text, line, reason in (("0 0 0\n1 1 x\n", 2, "not a decimal integer"), ("0 0\n", 1, "missing weight"),
                               ("0 0 1.5\n", 1, "not a decimal integer"),
                               ("0 0 9223372036854775808\n", 1, "out of int64 range"),
                               ("0 0 -9223372036854775809\n", 1, "out of int64 range"),
                               ("0 0 99999999999999999999\n", 1, "out of int64 range"),
                               ("1 2 3\n0 0 0 0\n", 2, "too many fields"), ("0,0,0,0\n", 1, "too many fields"),
                               ("0,0,\n", 1, "CSV field 3 is empty"), ("2147483648 0 0\n", 1, "out of int32 range"),
                               ("0 0 0\n# c\n1 2 3 # x\n", 3, "too many fields")):
        r = run(["power", "-"], text)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: <stdin>:{line}: ") and reason in r.stderr,
              f"vor power {text!r}: {r.returncode} {r.stderr!r}")
    for text in ("0 0 9223372036854775807\n", "0 0 -9223372036854775808\n", "0 0 +5\n", "0 0 -0\n"):
        r = run(["power", "-"], text)
        check(r.returncode == 0 and r.stdout == "", f"vor power {text!r}: {r.returncode} {r.stderr!r}")
    # a decimal weight: an error that sends the user to --scale, which
    # scales weights by S^2; with it, rounded to the nearest, ties away
    r = run(["power", "-"], "0 0 1.5\n")
    check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith("error: <stdin>:1: ") and "'1.5'" in r.stderr
          and "--scale" in r.stderr, f"vor power: a decimal weight: {r.returncode} {r.stderr!r}")
    r = run(["power", "--scale", "10", "-"], "0 0 0.015\n0 0 0.025\n0 0 -0.025\n0 0 0.02\n")
    check(r.returncode == 0 and r.stdout == "h 0\nh 2\nd 3 0\n",
          f"vor power --scale 10: weights 1.5, 2.5, -2.5, 2 round to 2, 3, -3, 2: {r.returncode} {r.stdout!r}")
    r = run(["power", "-"], "0 0 0\n0.5 1 0\n")
    check(r.returncode == 2 and "--scale" in r.stderr, f"vor power: a decimal coordinate suggests --scale: {r.stderr!r}")
    # usage errors
    for args, reason in ((["power"], "missing SITES"), (["power", "-", sp], "unexpected argument"),
                         (["power", "--scale"], "missing value after '--scale'"),
                         (["power", "--frobnicate", "-"], "unknown option '--frobnicate'")):
        r = run(args, "0 0 0\n")
        check(r.returncode == 2 and r.stdout == "" and reason in r.stderr and "usage: vor power" in r.stderr,
              f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}")
    r = run(["power", "--scale", "0", "-"], "0 0 0\n")
    check(r.returncode == 2 and r.stdout == "" and "--scale" in r.stderr and "'0'" in r.stderr,
          f"vor power --scale 0: {r.returncode} {r.stderr!r}")
    for args in (["power", os.path.join(tmp, "no-such-file")], ["power", tmp]):
        r = run(args, "")
        check(r.returncode == 2 and r.stdout == "" and r.stderr.startswith(f"error: {args[1]}: "),
              f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}")
    r = run(["power", "-"], "# nothing\n\n")
    check(r.returncode == 0 and r.stdout == "" and r.stderr == "", f"vor power of no sites: {r.returncode} {r.stderr!r}")


def power_draw_cases(tmp):
    """vor draw --power: the SVG parses, its cells are the brute-force power
    cells (exact clipping with Fractions) rounded once, a circle of radius
    sqrt(w) for each site of positive weight, a ring for each hidden site
    (as vor power lists them), and --triangles draws vor power's triangles.
    Its own generator, so the other sections' inputs do not move."""
    import os
    import shutil
    import xml.etree.ElementTree as ET
    if not shutil.which("xmllint"):
        check(False, "draw --power: xmllint is needed (tools/install-deps.sh svg)")
        return
    ns = "{http://www.w3.org/2000/svg}"
    rng = random.Random(2611)
    for case in range(12):
        n = rng.randint(1, 30)
        sites = [(rng.randint(0, 1000), rng.randint(0, 800), rng.randint(-5000, 20000)) for _ in range(n)]
        if case % 3 == 0:  # a grid with weights linear in the position: ties everywhere
            sites = [(100 * (k % 5), 100 * (k // 5), 7 * (k % 5) - 3 * (k // 5)) for k in range(n)]
        if n > 3:  # the same point with another weight, and a duplicate
            sites += [(sites[1][0], sites[1][1], sites[1][2] + rng.choice((-900, 900))), sites[2]]
        box = (rng.randint(-100, 300), rng.randint(-100, 300), rng.randint(400, 1100), rng.randint(400, 900))
        path, svg = os.path.join(tmp, "power-draw.sites"), os.path.join(tmp, "power-draw.svg")
        with open(path, "w") as f:
            f.write("".join(f"{x} {y} {w}\n" for x, y, w in sites))
        r = run(["draw", "--power", "--triangles", "--box", *map(str, box), path, "-o", svg], "")
        check(r.returncode == 0 and r.stdout == "", f"draw --power case {case}: {r.returncode} {r.stderr!r}")
        if r.returncode != 0:
            continue
        lint = subprocess.run(["xmllint", "--noout", svg], capture_output=True, text=True)
        check(lint.returncode == 0 and lint.stderr == "", f"draw --power case {case}: xmllint {lint.stderr!r}")
        first = {}
        for k, site in enumerate(sites):
            first.setdefault(site, k)
        expected = []
        for k, site in enumerate(sites):
            cell = brute_cell(sites, k, box) if first[site] == k else []
            if cell:
                expected.append(("#%02x%02x%02x" % draw_colour(k),
                                 [(round_half_up(x), round_half_up(y)) for x, y in cell]))
        check(draw_cells(svg) == expected, f"draw --power case {case}: the cells differ from the brute force; "
                                           f"sites {sites} box {box}")
        ref = run(["power", path], "").stdout.splitlines()
        hidden = {int(l.split()[1]) for l in ref if l.startswith("h ")}
        root = ET.parse(svg).getroot()
        rings = {(int(c.get("cx")), int(c.get("cy"))) for g in root.iter(ns + "g") if g.get("fill") == "#fff"
                 for c in g.iter(ns + "circle")}
        circles = sorted((int(c.get("cx")), int(c.get("cy")), round(float(c.get("r")) ** 2))
                         for g in root.iter(ns + "g") if g.get("fill") == "none" for c in g.iter(ns + "circle"))
        check(rings == {sites[k][:2] for k in hidden},
              f"draw --power case {case}: rings at {sorted(rings)}, hidden {sorted(hidden)}")
        check(circles == sorted(s for k, s in enumerate(sites) if first[s] == k and s[2] > 0),
              f"draw --power case {case}: circles {circles}")
        triangles = [d for p in root.iter(ns + "path") if p.get("stroke") == "#1f4fbf" for d in p.get("d").split("Z") if d]
        check(len(triangles) == sum(l.startswith("t ") for l in ref),
              f"draw --power case {case}: {len(triangles)} triangles drawn, vor power gives "
              f"{sum(l.startswith('t ') for l in ref)}")
    for args, reason in ((["draw", "--power", "--hull", "-", "-o", "-"], "no hull"),
                         (["draw", "--power", "--cells", "-", "-o", "-"], "power")):
        r = run(args, "0 0 0\n")
        check(r.returncode == 2 and r.stdout == "" and reason in r.stderr, f"vor {' '.join(args)}: {r.returncode} {r.stderr!r}")


def main():
    rng = random.Random(5)
    lines, expected = predicates_cases(rng)
    r = run(["predicates"], "\n".join(lines) + "\n")
    got = r.stdout.split()
    check(r.returncode == 0, f"predicates exit status {r.returncode}: {r.stderr.strip()}")
    check(len(got) == len(expected), f"predicates printed {len(got)} lines for {len(expected)} cases")
    zeros = 0
    for k, (g, e) in enumerate(zip(got, expected)):
        check(g == str(e), f"predicates case {k}: printed {g}, expected {e}")
        zeros += e == 0
    check(zeros > 20, f"only {zeros} degenerate cases were generated")

    # malformed input: status 2, the right line number, nothing on stdout
    bad = [
        ("o 0 0 1 0 0 1\no 1 2 3\n", 2, "missing coordinate"),
        ("# c\n\nc 0 0 1 0 0 1 1 1 9\n", 3, "too many fields"),
        ("o 0 0 1 0 0 2147483648\n", 1, "out of int32 range"),
        ("o 0 0 1 0 0 -2147483649\n", 1, "out of int32 range"),
        ("o 0 0 1 0 0 1x\n", 1, "not a decimal integer"),
        ("x 1 2\n", 1, "expected 'o' or 'c'"),
    ]
    for text, line, reason in bad:
        r = run(["predicates"], text)
        check(r.returncode == 2, f"bad input {text!r}: exit {r.returncode}, expected 2")
        check(r.stdout == "", f"bad input {text!r}: stdout {r.stdout!r}, expected nothing")
        check(r.stderr.startswith(f"error: <stdin>:{line}: ") and reason in r.stderr,
              f"bad input {text!r}: stderr {r.stderr!r}")
    r = run(["predicates"], "o -2147483648 -2147483648 0 0 2147483647 2147483647\n")
    check(r.stdout == "0\n", f"full-range collinear: {r.stdout!r}")
    delaunay_cases(rng)
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        nearest_cases(rng, tmp)
        locate_within_cases(rng, tmp)
        raster_cases(rng, tmp)
        cells_cases(rng, tmp)
        clip_cases(random.Random(2715), tmp)
        order_cells_cases(random.Random(2716), tmp)
        raster_metric_cases(rng, tmp)
        nearest_k_cases(random.Random(27), tmp)
        contours_cases(rng, tmp)
        help_cases(tmp)
        file_error_cases(tmp)
        input_cases(rng, tmp)
        draw_cases(rng, tmp)
        picture_cases(tmp)
        header_cases(tmp)
        option_cases(rng, tmp)
        cdt_cases(rng, tmp)
        power_cases(tmp)
        power_draw_cases(tmp)
        interpolate_cases(rng, tmp)
        laplace_cases(tmp)
    version_cases()
    error_name_cases()
    ops_cases(rng)

    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
