/* SPDX-License-Identifier: MIT */
/*
 * raster.h - the raster core (raster.c): the checks and set-up every
 * entry point shares, the rows of runs, the scan of the rows, and the
 * band writer that turns them into output pixels. Private to the library.
 *
 * The metric families (raster_euclid.c, raster_metrics.c) produce rows of
 * runs for the request set up here, and their entry points end with the
 * core's scan; the core knows nothing of distances.
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
VOR__ALWAYS_INLINE uint32_t vor__run_push(vor__run_t *runs, uint32_t count, uint32_t i, uint32_t site)
{
    if ((count > 0u) && (runs[count - 1u].site == site)) {
        runs[count - 1u].end = i + 1u;
        return count;
    }
    runs[count].end = i + 1u;
    runs[count].site = site;
    return count + 1u;
}

/* The band writer (raster.c). The scan (vor__raster_scan, below) has
 * the rows produced top down into vor__bands_runs (and, for DISTANCE,
 * their pixels at vor__bands_pixels) and hands each to
 * vor__bands_put_flush, then calls it once more with no row (the end);
 * each full band goes to the output's flush. BOUNDARY rows are written one row late, when
 * the row below is known. */
typedef struct vor__bands {
    const vor_raster_output_t *out;
    uint32_t width;
    uint32_t height;
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

/* Starts the rows of frame into out's band (rows: the two rows of runs;
 * zeroes out->areas[0 .. sites)). A producer that writes each row's
 * pixels itself at vor__bands_pixels (DISTANCE; the field frames of
 * field.c) puts rows of no runs; field.c's out has the kind
 * VOR_RASTER_DISTANCE, no areas and no rows of runs, so the writer only
 * counts its rows into bands and hands them to the flush. */
void vor__bands_begin(vor__bands_t *b, const vor_raster_frame_t *frame, uint32_t sites,
                      const vor_raster_output_t *out, vor__run_t *const rows[2], size_t row_bytes);

static inline vor__run_t *vor__bands_runs(const vor__bands_t *b)
{
    return b->rows[b->cur];
}

/* Where the next row's pixels go in the band (not for BOUNDARY). */
static inline void *vor__bands_pixels(const vor__bands_t *b)
{
    return (uint8_t *)b->out->band + (size_t)(b->next - b->band_first) * b->row_bytes;
}

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
 * takes it apart and divides the work memory (the two rows of runs at its
 * start, the family's state in the rest), the family makes its own checks
 * and prepares its state, and vor__raster_scan renders. */
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

/* Is every pixel centre of f an int32 point, with positive sizes and
 * steps? (nonzero: yes) */
int vor__raster_frame_ok(const vor_raster_frame_t *f);

/* The band of a frame width pixels wide, pixel_bytes (1 to 4) a pixel:
 * VOR_OK with the bytes of a row in *row_bytes when band_bytes hold
 * band_rows rows; VOR_ERR_ARG for width >= 2^27 (the sizes must not
 * overflow), VOR_ERR_NOMEM for a band too small (*row_bytes unchanged). */
int vor__raster_band_check(uint32_t width, size_t pixel_bytes, size_t band_bytes,
                           uint32_t band_rows, size_t *row_bytes);

/* Rounds an offset up to a multiple of 8 (the work memory's alignment). */
static inline size_t vor__align8(size_t x)
{
    return (x + 7u) & ~(size_t)7u;
}

/* The checks every entry point makes, all but the metric's own fields,
 * for nearest = 0 (vor_raster, vor_raster_euclid: the kinds of
 * VOR_RASTER_PIXEL_BYTES) or nearest = K >= 1 (vor_raster_nearest: K up
 * to VOR_RASTER_MAX_NEAREST, the kinds NEAREST and KSETS too, and the
 * work of VOR_RASTER_NEAREST_WORK_BYTES): VOR_OK with r filled in and the
 * work memory divided (nothing written there yet), or the error
 * vor_raster (vor_raster_nearest) documents. Forced inline, so that the
 * entry points with nearest = 0 compile no k-order branch at all. */
VOR__ALWAYS_INLINE int vor__raster_check_order(vor__raster_t *r, const vor_raster_frame_t *frame,
                                               const vor_raster_sites_t *sites,
                                               const vor_raster_output_t *out,
                                               const vor_raster_options_t *options, void *work,
                                               size_t work_bytes, uint32_t nearest)
{
    enum vor_raster_method method = (options != NULL) ? options->method : VOR_RASTER_FAST;
    if ((frame == NULL) || (sites == NULL) || (out == NULL) || (work == NULL) ||
        !vor__raster_frame_ok(frame)) {
        return VOR_ERR_ARG;
    }
    if (sites->count == 0u) {
        return VOR_ERR_EMPTY;
    }
    if ((sites->points == NULL) || (out->band == NULL) ||
        (out->flush == NULL) || (out->band_rows == 0u) ||
        ((method != VOR_RASTER_FAST) && (method != VOR_RASTER_BRUTE))) {
        return VOR_ERR_ARG;
    }
    const uint32_t n = sites->count;
    if ((nearest > VOR_RASTER_MAX_NEAREST) ||
        ((nearest != 0u) && (out->kind == VOR_RASTER_KSETS) && (out->palette565 == NULL))) {
        return VOR_ERR_ARG;
    }
    /* 0: an unknown kind (NEAREST and KSETS are known with nearest only) */
    const size_t pixel_bytes = (nearest != 0u) ? VOR_RASTER_NEAREST_PIXEL_BYTES(out->kind, nearest)
                                               : VOR_RASTER_PIXEL_BYTES(out->kind);
    if (pixel_bytes == 0u) {
        return VOR_ERR_ARG;
    }
    /* the sites a label tells apart, the palette a colour needs */
    if (((out->kind == VOR_RASTER_LABEL8) && (n > 256u)) ||
        ((out->kind == VOR_RASTER_LABEL16) && (n > 65536u)) ||
        ((out->kind == VOR_RASTER_RGB565) && (out->palette565 == NULL)) ||
        ((out->kind == VOR_RASTER_RGB888) && (out->palette888 == NULL))) {
        return VOR_ERR_ARG;
    }
    if (n > 0x07FFFFFFu) {
        return VOR_ERR_ARG; /* the work size below must not overflow */
    }
    size_t row_bytes = 0;
    int err = vor__raster_band_check(frame->width, pixel_bytes, out->band_bytes, out->band_rows,
                                     &row_bytes);
    if (err != VOR_OK) {
        return err;
    }
    /* nearest: VOR_RASTER_NEAREST_WORK_BYTES beyond VOR_RASTER_WORK_BYTES,
     * compared in 64 bits (below 2^35) */
    if ((work_bytes < VOR_RASTER_WORK_BYTES(n, frame->width)) ||
        ((nearest != 0u) &&
         ((uint64_t)(work_bytes - VOR_RASTER_WORK_BYTES(n, frame->width)) <
          (vor__mul_u32(nearest + 1u, 112u) + vor__mul_u32(frame->width, 8u * nearest))))) {
        return VOR_ERR_NOMEM;
    }
    if (((uintptr_t)work & (VOR_RASTER_WORK_ALIGN - 1u)) != 0u) {
        return VOR_ERR_ALIGN;
    }
    r->frame = frame;
    r->sites = sites;
    r->out = out;
    r->brute = method == VOR_RASTER_BRUTE;
    r->row_bytes = row_bytes;
    /* the two rows of runs first (16 width + 16 bytes at most), the
     * family's state after them (45 n or 48 n + 48 bytes; the k-order
     * arrays before it): together within the work macro */
    size_t rows8 = vor__align8((size_t)frame->width * sizeof(vor__run_t));
    r->rows[0] = (vor__run_t *)work;
    r->rows[1] = (vor__run_t *)(void *)((uint8_t *)work + rows8);
    r->rest = (uint8_t *)work + (2u * rows8);
    r->rest_bytes = work_bytes - (2u * rows8);
    return VOR_OK;
}

/* vor__raster_check_order with nearest = 0: the checks of vor_raster and
 * vor_raster_euclid. */
int vor__raster_check(vor__raster_t *r, const vor_raster_frame_t *frame,
                      const vor_raster_sites_t *sites, const vor_raster_output_t *out,
                      const vor_raster_options_t *options, void *work, size_t work_bytes);

/* Starts the bands of a checked request (zeroes out->areas): the first
 * write to the caller's memory, after every check (vor__raster_scan). */
void vor__raster_start(vor__raster_t *r);

/* A family's producers for vor__raster_scan: the runs of row j (rows in
 * increasing order) into runs, their count returned; and the DISTANCE
 * pixels of those runs. state is the family's own. */
typedef uint32_t vor__raster_row_fn(void *state, uint32_t j, vor__run_t *runs);
typedef void vor__raster_distances_fn(const void *state, uint32_t j, const vor__run_t *runs,
                                      uint32_t count, uint32_t *px);

/* The scan every entry point ends with: starts the bands, then takes the
 * rows top down from the family's producers into the band writer, and
 * hands each full band to the output's flush. VOR_OK, or VOR_ERR_STOPPED
 * when a flush returned nonzero. Forced inline with the family's own static producers:
 * the calls are then direct (no function pointer hides which family a
 * firmware links, and tools/stack-depth.py sees every call), the
 * producers inline into the entry point as the compiler sees fit, and the
 * caller's flush is called from the public entry point. */
VOR__ALWAYS_INLINE int vor__raster_scan(vor__raster_t *r, void *state, vor__raster_row_fn *row,
                                        vor__raster_distances_fn *distances)
{
    const uint32_t height = r->frame->height;
    vor__raster_start(r);
    for (uint32_t j = 0; j <= height; j++) { /* j = height: the end */
        uint32_t count = 0;
        if (j < height) {
            vor__run_t *runs = vor__bands_runs(&r->bands);
            count = row(state, j, runs);
            if (r->out->kind == VOR_RASTER_DISTANCE) {
                distances(state, j, runs, count, vor__bands_pixels(&r->bands));
            }
        }
        if (vor__bands_put_flush(&r->bands, count) != 0) {
            return VOR_ERR_STOPPED; /* the flush's own code stays the caller's */
        }
    }
    return VOR_OK;
}

/* i * step for a pixel index i < 2^31 and a step in (0, 2^31): below
 * 2^62, and without a 64-bit multiply call on Cortex-M0. */
static inline int64_t vor__offset(uint32_t i, int32_t step)
{
    return (int64_t)vor__mul_u32(i, (uint32_t)step);
}

#endif
