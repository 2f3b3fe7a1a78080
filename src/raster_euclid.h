/* SPDX-License-Identifier: MIT */
/*
 * raster_euclid.h - the Euclidean family of the raster (raster_euclid.c):
 * rows of Euclidean point sites, from the fast exact path or the
 * brute-force search, and their distance pixels. Private to the library.
 * It builds on the raster core's request (raster.h) and nothing else.
 */
#ifndef VOR_RASTER_EUCLID_H
#define VOR_RASTER_EUCLID_H

#include "raster.h"

/* The family's state: the frame and sites of the request, and the fast
 * path's arrays, which live in the work memory after the rows (n entries
 * per array). */
typedef struct vor__euclid {
    const vor_raster_frame_t *frame;
    const vor_point_t *points;
    uint32_t n;
    int fast;             /* the fast path; else the brute-force search */
    uint32_t *by_x;       /* site ids sorted by (x, id) */
    uint32_t *by_y;       /* site ids sorted by (y, id) */
    int32_t *sorted_x;    /* relative x of by_x[p] */
    int32_t *sorted_y;    /* relative y of by_x[p] */
    uint8_t *mark;        /* per site: candidate flags of this band and the next */
    uint32_t *cand;       /* the band's list: sites in (x, id) order (also scratch) */
    int64_t *val;         /* the list's lines, packed (also scratch: edge values) */
    int32_t *key;         /* scratch: edge envelope keys */
    uint32_t *stack;      /* scratch: edge envelope stack */
    uint32_t *left;       /* envelope of the left frame edge (positions in by_y) */
    uint32_t *right;      /* and of the right edge */
    uint32_t left_count, right_count;
    uint32_t left_next, right_next; /* first pieces that may meet the next band */
    uint32_t cand_count;
    uint32_t band_first, band_last; /* rows of the current culling band */
    uint32_t inside_next;           /* by_y position: first site not yet below the band */
    uint32_t quotient_bits;         /* 2^quotient_bits >= width */
    uint32_t reach_row;             /* the last row of the previous band ... */
    uint64_t reach_most;            /* ... and its largest squared distance to a site */
    int band_valid;
    int narrow;          /* tier: 1 narrow (< 2^14), 2 mid (< 2^19), 0 wide */
} vor__euclid_t;

/* Sets e up for the checked request r (Euclidean sites): the fast path
 * when r asks for it and its bit budget holds, else the brute force. */
void vor__euclid_prepare(vor__euclid_t *e, const vor__raster_t *r);

/* Runs of row j (rows requested in increasing order); returns their count. */
uint32_t vor__euclid_row(vor__euclid_t *e, uint32_t j, vor__run_t *runs);

/* The DISTANCE pixels of row j (its count runs): floor(|q - s|) of each
 * pixel's site, saturated at UINT32_MAX. */
void vor__euclid_distances(const vor__euclid_t *e, uint32_t j, const vor__run_t *runs,
                           uint32_t count, uint32_t *px);

#endif
