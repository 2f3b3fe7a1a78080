/*
 * raster.h - what the band driver (raster.c) and the row producers share.
 * Private to the library.
 *
 * A row of labels travels as runs: run k covers pixels [end of run k-1,
 * end of run k) and belongs to one site. Consecutive runs have different
 * sites, so a row of width W has at most W runs.
 */
#ifndef VOR_RASTER_PRIVATE_H
#define VOR_RASTER_PRIVATE_H

#include "vor_raster.h"

#include "multiword.h"

typedef struct vor__run {
    uint32_t end;  /* one past the last pixel of the run */
    uint32_t site;
} vor__run_t;

/* Adds pixel i, labelled site, to the row's runs (count of them so far):
 * it extends the last run when the label repeats. Returns the new count. */
static inline uint32_t vor__run_push(vor__run_t *runs, uint32_t count, uint32_t i, uint32_t site)
{
    if (count > 0u && runs[count - 1u].site == site) {
        runs[count - 1u].end = i + 1u;
        return count;
    }
    runs[count].end = i + 1u;
    runs[count].site = site;
    return count + 1u;
}

/* The fast Euclidean producer (raster_euclid.c): its state lives in the
 * caller's work memory (n entries per array). */
typedef struct vor__euclid {
    const vor_point_t *points;
    uint32_t n;
    uint32_t width, height;
    int32_t step_x, step_y;
    int32_t origin_x, origin_y;
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

/* i * step for a pixel index i < 2^31 and a step in (0, 2^31): below
 * 2^62, and without a 64-bit multiply call on Cortex-M0. */
static inline int64_t vor__offset(uint32_t i, int32_t step)
{
    return (int64_t)vor__mul_u32(i, (uint32_t)step);
}

/* Rows per culling band of the fast path. */
#define VOR__CULL_ROWS 16u

/* True when the fast path's bit budget holds: every site within 2^29 of
 * the first pixel centre, (width - 1) * step_x and (height - 1) * step_y
 * below 2^29. */
int vor__euclid_fits(const vor_raster_frame_t *frame, const vor_point_t *points, uint32_t n);

/* Sorts the sites and envelopes the frame's left and right edges. The
 * arrays of e must be set; frame checked; vor__euclid_fits true. */
void vor__euclid_prepare(vor__euclid_t *e);

/* Runs of row j (rows requested in increasing order); returns their count. */
uint32_t vor__euclid_row(vor__euclid_t *e, uint32_t j, vor__run_t *runs);

/* The other metrics (raster_metrics.c): exact per-metric comparisons,
 * the brute-force search, and the culling of sites per tile. */
typedef struct vor__metric {
    const vor_raster_sites_t *sites;
    enum vor_metric metric;
    uint32_t n;
    uint32_t width, height;
    int32_t origin_x, origin_y, step_x, step_y;
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
 * offsets); else VOR_ERR_ARG. Reads every site once. */
int vor__metric_check(const vor_raster_sites_t *sites);

/* Sets m up for frame (checked) and sites (checked by vor__metric_check),
 * with pool_words words of culling memory (at least 2 count + 2). */
void vor__metric_prepare(vor__metric_t *m, const vor_raster_frame_t *frame,
                         const vor_raster_sites_t *sites, int brute, uint32_t *pool,
                         size_t pool_words);

/* Runs of row j (rows requested in increasing order); returns their count. */
uint32_t vor__metric_row(vor__metric_t *m, uint32_t j, vor__run_t *runs);

/* The VOR_RASTER_DISTANCE value of site `site` at the pixel centre
 * (qx, qy): the floor of its distance under m's metric, saturated (ADD
 * and COMPOUND: an int32 bit pattern); vor_raster.h, OUTPUT KINDS. */
uint32_t vor__metric_distance(const vor__metric_t *m, uint32_t site, int32_t qx, int32_t qy);

#endif
