/* SPDX-License-Identifier: MIT */
/*
 * far_sites.h - the diagrams of the query harnesses of `make prove`
 * (queries.c, nearest_k.c, geometry.c, cells.c, centroid.c) and their
 * boxes.
 * 6 points, 5 sites: four cocircular (0 to 3, on the circle of centre
 * (5, 5)), a duplicate (4 repeats 0) and one far away (5), beyond the
 * tracker's 2^30 reach and where vertices round out of int32. Then three
 * collinear sites, one site and none: each shape the calls tell apart.
 * far_sites_init starts a harness's diagram, far_sites_each runs a
 * harness's calls on each shape, FIXED_SCRATCH is the scratch. The boxes (cells.c,
 * centroid.c): one around the sites, one inside the cocircular ones, the
 * whole int32 plane, a flat one and an inverted one.
 */
#ifndef PROVE_FAR_SITES_H
#define PROVE_FAR_SITES_H

#include <stdbool.h>

#include "inputs.h"
#include "vor.h"

#define N 6u
static const vor_point_t points[N] = {{0, 0},  {10, 0}, {10, 10},
                                      {0, 10}, {0, 0},  {INT32_MIN, INT32_MAX}};
static const vor_point_t collinear[3] = {{0, 0}, {10, 0}, {20, 0}};

static uint32_t arena[(VOR_ARENA_BYTES(N) + 3u) / 4u];

/* *d empty over the arena, whatever revision it held before (vor_init
 * reads it). */
static int far_sites_init(vor_t *d)
{
    d->revision = any_u32();
    return vor_init(d, arena, sizeof arena, N);
}

/* The scratch of the calls that take one (centroid.c, power_cells.c,
 * interpolate.c), at a fixed address that prove.sh declares valid
 * (-absolute-valid-range 0x10000-0x1FFFF): the call aligns it from its
 * address as an integer, which EVA knows for an absolute address only
 * (for a variable's, any value, and every sum's place with it). 0x10000
 * is aligned; 0x10001 to 0x10007 are not: every address's alignment. */
#define FIXED_SCRATCH ((uint64_t *)0x10000u)

/* The harness's calls, check, on a diagram over the arena (its revision
 * before vor_init: `revision`) with each shape in turn: no sites
 * (with_empty), one site, the three collinear ones, then the first `all`
 * points. The results or-ed; 1 when vor_init fails. */
static int far_sites_each(uint32_t revision, bool with_empty, uint32_t all,
                          int (*check)(const vor_t *d))
{
    vor_t d;
    int r = 0;
    d.revision = revision;
    if (vor_init(&d, arena, sizeof arena, N) != VOR_OK) {
        return 1;
    }
    if (with_empty) {
        r |= check(&d);
    }
    r |= vor_build(&d, points, 1u, NULL, NULL);
    r |= check(&d);
    r |= vor_build(&d, collinear, 3u, NULL, NULL);
    r |= check(&d);
    r |= vor_build(&d, points, all, NULL, NULL);
    r |= check(&d);
    return r;
}

#define BOXES 5u
static const vor_box_t boxes[BOXES] = {{-20, -20, 30, 30},
                                       {2, 3, 8, 7},
                                       {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX},
                                       {5, 5, 5, 9},
                                       {1, 0, 0, 1}};

#endif
