/* SPDX-License-Identifier: MIT */
/*
 * raster_metrics.h - the raster's family of other metrics
 * (raster_metrics.c): L1, L-infinity, Lp, elliptic, weighted,
 * farthest-point, Hausdorff, segments, polygons and polylines. Each pixel
 * takes the site of smallest distance (largest for the farthest-point
 * diagram) by exact comparisons, with sites culled per tile. Private to
 * the library; it builds on the raster core's request (raster.h).
 */
#ifndef VOR_RASTER_METRICS_H
#define VOR_RASTER_METRICS_H

#include "raster.h"

/* The family's state: the frame and sites of the request, the widths of
 * its exact comparisons, and the culling of sites per tile. */
typedef struct vor__metric {
    const vor_raster_frame_t *frame;
    const vor_raster_sites_t *sites;
    enum vor_metric metric;
    uint32_t n;
    uint32_t limbs;      /* limbs of the wide comparisons of this frame */
    int lp_narrow;       /* LP: every sum below 2^128 */
    uint64_t det;        /* ELLIPTIC: a c - b^2 */
    uint32_t trace;      /* ELLIPTIC: a + c */
    int brute;           /* every site at every pixel, no culling */
    uint32_t *pool;      /* culling: the block list, then the tile lists */
    size_t pool_words;
    uint32_t tile_width; /* columns per tile (a power of two, >= 16) */
    uint32_t tiles;
    uint32_t band_first; /* rows of the current culling band */
    int band_valid;
} vor__metric_t;

/* VOR_OK when the metric's fields are usable (weights, exponent, form,
 * offsets); else VOR_ERR_ARG. Reads every site once. sites: past
 * vor__raster_check, not Euclidean. */
int vor__metric_check(const vor_raster_sites_t *sites);

/* Sets m up for the checked request r (its sites past vor__metric_check):
 * the comparison widths from the span of sites and frame, and the tiles;
 * the culling pool is the work memory after the rows. */
void vor__metric_prepare(vor__metric_t *m, const vor__raster_t *r);

/* Runs of row j (rows requested in increasing order); returns their count. */
uint32_t vor__metric_row(vor__metric_t *m, uint32_t j, vor__run_t *runs);

/* The DISTANCE pixels of row j (its count runs): the floor of each
 * pixel's own site's distance, from the key that ranked it, saturated
 * (ADD and COMPOUND: an int32 bit pattern); vor_raster.h, OUTPUT KINDS. */
void vor__metric_distances(const vor__metric_t *m, uint32_t j, const vor__run_t *runs,
                           uint32_t count, uint32_t *px);

#endif
