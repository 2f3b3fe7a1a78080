/* SPDX-License-Identifier: MIT */
/*
 * raster.h - the raster core (raster.c): the checks and set-up every
 * entry point shares, the rows of runs, and the band writer that turns
 * them into output pixels. Private to the library.
 *
 * The metric families (raster_euclid.h, raster_metrics.h) produce rows of
 * runs for the frame set up here; the core knows nothing of distances.
 * The entry points (raster_scan.c) tie a family to the core.
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

/* The band writer (raster.c). An entry point produces the rows top down
 * into vor__bands_runs (and, for DISTANCE, writes their pixels at
 * vor__bands_pixels itself) and hands each to vor__bands_put_flush,
 * then calls it once more with no row (the end); each full band goes to
 * the output's flush. BOUNDARY rows are written one row late, when
 * the row below is known. */
typedef struct vor__bands {
    const vor_raster_output_t *out;
    uint32_t width, height;
    size_t row_bytes;
    vor__run_t *rows[2];
    uint32_t counts[2];
    uint32_t cur;         /* rows[cur] receives the next row */
    uint32_t next;        /* the next row to receive */
    uint32_t written;     /* rows [0, written) are in bands */
    uint32_t band_first;  /* the first row of the band being filled */
    uint32_t flush_first; /* the first row of the band put returned */
    int hold;             /* BOUNDARY: a row waits for the one below */
} vor__bands_t;

static inline vor__run_t *vor__bands_runs(const vor__bands_t *b)
{
    return b->rows[b->cur];
}

/* Where the next row's pixels go in the band (not for BOUNDARY). */
void *vor__bands_pixels(const vor__bands_t *b);

/* Takes the next row (count runs; the end when all rows were put).
 * Returns the rows of a band to flush now, or 0. */
uint32_t vor__bands_put(vor__bands_t *b, uint32_t count);

/* vor__bands_put, then the output's flush when a band is full: 0 to go
 * on, or the flush's nonzero value. Forced inline, so that the caller's
 * callback is called from the public entry point (tools/stack-depth.py
 * counts its stack apart only there). */
VOR__ALWAYS_INLINE int vor__bands_put_flush(vor__bands_t *b, uint32_t count)
{
    uint32_t rows = vor__bands_put(b, count);
    if (rows == 0u) {
        return 0;
    }
    return b->out->flush(b->out->user, b->flush_first, rows, b->out->band);
}

/* One request, set up the same way for every metric: vor__raster_check
 * takes it apart, the family makes its own checks, vor__raster_start
 * carves the two rows of runs from the start of the work memory and
 * starts the bands; the family's state takes the rest. */
typedef struct vor__raster {
    const vor_raster_frame_t *frame; /* the caller's: read, never copied */
    const vor_raster_sites_t *sites;
    const vor_raster_output_t *out;
    int brute;           /* VOR_RASTER_BRUTE: every site at every pixel */
    size_t row_bytes;    /* of one output row */
    vor__run_t *rows[2]; /* at the start of the work memory */
    uint8_t *rest;       /* the work memory after the rows (8-aligned) ... */
    size_t rest_bytes;   /* ... and its size */
    vor__bands_t bands;
} vor__raster_t;

/* The checks every entry point makes, all but the metric's own fields:
 * VOR_OK with r filled in and the work memory divided (nothing written
 * there yet), or the error vor_raster documents. */
int vor__raster_check(vor__raster_t *r, const vor_raster_frame_t *frame,
                      const vor_raster_sites_t *sites, const vor_raster_output_t *out,
                      void *work, size_t work_bytes);

/* Starts the bands of a checked request (zeroes out->areas): the first
 * write to the caller's memory, after every check. */
void vor__raster_start(vor__raster_t *r);

/* i * step for a pixel index i < 2^31 and a step in (0, 2^31): below
 * 2^62, and without a 64-bit multiply call on Cortex-M0. */
static inline int64_t vor__offset(uint32_t i, int32_t step)
{
    return (int64_t)vor__mul_u32(i, (uint32_t)step);
}

#endif
