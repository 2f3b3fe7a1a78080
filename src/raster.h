/* SPDX-License-Identifier: MIT */
/*
 * raster.h - what the band writer (raster.c), the entry points and the
 * row producers share.
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

/* The checks every entry point makes (raster.c), all but the metric's
 * own fields: VOR_OK with the bytes of one output row in *row_bytes, or
 * the error vor_raster documents. */
int vor__raster_check(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                      const vor_raster_output_t *out, const void *work, size_t work_bytes,
                      size_t *row_bytes);

/* Two rows of runs at the start of the work memory; returns the bytes
 * they take (8-aligned). */
size_t vor__raster_rows(const vor_raster_frame_t *frame, void *work, vor__run_t *rows[2]);

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

/* Starts the rows of frame; zeroes out->areas[0 .. sites). */
void vor__bands_begin(vor__bands_t *b, const vor_raster_frame_t *frame, uint32_t sites,
                      const vor_raster_output_t *out, vor__run_t *const rows[2], size_t row_bytes);

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

/* Sets e up for frame and the n points: sorts the sites and envelopes
 * the frame's left and right edges. The arrays of e must be set; frame
 * checked; vor__euclid_fits true. */
void vor__euclid_prepare(vor__euclid_t *e, const vor_raster_frame_t *frame,
                         const vor_point_t *points, uint32_t n);

/* Runs of row j (rows requested in increasing order); returns their count. */
uint32_t vor__euclid_row(vor__euclid_t *e, uint32_t j, vor__run_t *runs);

#endif
