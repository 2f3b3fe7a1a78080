#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""compare_power.py - `vor power` against CGAL's Regular_triangulation_2
with exact constructions (tests/reference/cgal_power.cpp), on random
weighted sites: over the full int32 range with weights up to 2^62 (many
sites hidden), within 2^30 with weights near 2^61, near one another with
small weights, and with repeated points of different weights (the
heaviest is the vertex). Coordinates and weights are drawn from wide
ranges, so no four lifted sites lie on one plane and the regular
triangulation is unique: the triangles and the hidden sites must match
exactly. Prints failures and ends with "N passed, N failed"; exit status 1
if anything failed.

Usage: compare_power.py VOR CGAL_POWER [CASES] (tests/reference/reference_run.py)
"""
from reference_run import run

MIN, MAX = -2**31, 2**31 - 1


def case_input(rng, kind):
    n = rng.randint(3, 120)
    if kind == 0:  # full range, weights up to 2^62
        return [(rng.randint(MIN, MAX), rng.randint(MIN, MAX), rng.randint(0, 2**62)) for _ in range(n)]
    if kind == 1:  # within 2^30, weights near 2^61
        return [(rng.randint(-2**30, 2**30), rng.randint(-2**30, 2**30),
                 2**61 + rng.randint(-2**60, 2**60)) for _ in range(n)]
    if kind == 2:  # near one another, negative weights too
        return [(rng.randint(-10**6, 10**6), rng.randint(-10**6, 10**6),
                 rng.randint(-10**11, 10**11)) for _ in range(n)]
    # repeated points with other weights, and exact repeats
    sites = [(rng.randint(-10**8, 10**8), rng.randint(-10**8, 10**8), rng.randint(0, 10**15))
             for _ in range(n)]
    for _ in range(rng.randint(1, n)):
        x, y, w = rng.choice(sites)
        sites.append((x, y, w if rng.random() < 0.3 else w + rng.randint(-10**14, 10**14)))
    rng.shuffle(sites)
    return sites


def case(ctx, number):
    kind = number % 4
    sites = case_input(ctx.rng, kind)
    path = ctx.write("sites", sites)
    ours, theirs = ctx.vor("power", path), ctx.cgal(path)
    ctx.check(ours.returncode == 0 and ours.stderr == "",
              f"case {number}: vor power {ours.returncode} {ours.stderr!r}")
    ctx.check(theirs.returncode == 0, f"case {number}: cgal-power {theirs.returncode} {theirs.stderr!r}")
    ours_lines = [l for l in ours.stdout.splitlines() if not l.startswith("d ")]
    dups = {}
    for line in ours.stdout.splitlines():
        if line.startswith("d "):
            _, i, j = line.split()
            dups[int(i)] = int(j)
    first = {}
    expected_dups = {}
    for i, s in enumerate(sites):
        if s in first:
            expected_dups[i] = first[s]
        else:
            first[s] = i
    ctx.check(dups == expected_dups, f"case {number} (kind {kind}): duplicates differ")
    same = ours_lines == theirs.stdout.splitlines()
    ctx.check(same, f"case {number} (kind {kind}): output differs from CGAL "
                    f"({len(ours_lines)} lines, CGAL {len(theirs.stdout.splitlines())})")
    hidden = sum(1 for l in ours_lines if l.startswith("h "))
    ctx.check(kind == 2 or hidden > 0 or len(sites) < 10 or kind == 3,
              f"case {number} (kind {kind}): no hidden site")


run(400, 26, case)
