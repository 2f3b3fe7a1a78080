/* SPDX-License-Identifier: MIT */
/*
 * far_sites.h - the diagrams of the query harnesses of `make prove`
 * (queries.c, nearest_k.c, geometry.c, cells.c, centroid.c) and their
 * boxes.
 * 6 points, 5 sites: four cocircular (0 to 3, on the circle of centre
 * (5, 5)), a duplicate (4 repeats 0) and one far away (5), beyond the
 * tracker's 2^30 reach and where vertices round out of int32. Then three
 * collinear sites, one site and none: each shape the calls tell apart.
 * far_sites_init starts a harness's diagram. The boxes (cells.c,
 * centroid.c): one around the sites, one inside the cocircular ones, the
 * whole int32 plane, a flat one and an inverted one.
 */
#ifndef PROVE_FAR_SITES_H
#define PROVE_FAR_SITES_H

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

#define BOXES 5u
static const vor_box_t boxes[BOXES] = {{-20, -20, 30, 30},
                                       {2, 3, 8, 7},
                                       {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX},
                                       {5, 5, 5, 9},
                                       {1, 0, 0, 1}};

#endif
