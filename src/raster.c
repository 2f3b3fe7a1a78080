/* SPDX-License-Identifier: MIT */
/*
 * raster.c - the raster core, what every raster entry point shares
 * whatever its metric: the checks and set-up of a request, and the band
 * writer, which turns each row's runs of labels into pixels of the output
 * kind and hands out full bands. Teramoto renders the discrete Voronoi
 * diagram (section 2.2, Definition 2.2) with distance cones in a Z-buffer;
 * here the same diagram is computed exactly, one row at a time, so that
 * only a band of rows ever needs memory. The rows come from the metric
 * families (raster_euclid.c, raster_metrics.c).
 */
#include "raster.h"

#include "multiword.h"

/* -------------------------------------------------------------- output */

/* px[from .. to) = value, four pixels per step (the hot loop of RGB565
 * output: a run is usually tens of pixels). */
static void fill16(uint16_t *px, uint32_t from, uint32_t to, uint16_t value)
{
    uint32_t i = from;
    for (; (i + 4u) <= to; i += 4u) {
        px[i] = value;
        px[i + 1u] = value;
        px[i + 2u] = value;
        px[i + 3u] = value;
    }
    for (; i < to; i++) {
        px[i] = value;
    }
}

/* The pixels of a row (runs) in one output kind. */
typedef void run_writer_t(const vor_raster_output_t *out, const vor__run_t *runs, uint32_t count,
                          void *dst);

static void write_label8(const vor_raster_output_t *out, const vor__run_t *runs, uint32_t count,
                         void *dst)
{
    (void)out;
    uint8_t *px = dst;
    uint32_t i = 0;
    for (uint32_t r = 0; r < count; r++) {
        uint8_t label = (uint8_t)runs[r].site;
        for (; i < runs[r].end; i++) {
            px[i] = label;
        }
    }
}

/* LABEL16 and RGB565: a run's value is its site, or the site's colour. */
static void write_16(const vor_raster_output_t *out, const vor__run_t *runs, uint32_t count,
                     void *dst)
{
    const uint16_t *palette = (out->kind == VOR_RASTER_RGB565) ? out->palette565 : NULL;
    uint16_t *px = dst;
    uint32_t i = 0;
    for (uint32_t r = 0; r < count; r++) {
        uint32_t site = runs[r].site;
        fill16(px, i, runs[r].end, (palette != NULL) ? palette[site] : (uint16_t)site);
        i = runs[r].end;
    }
}

static void write_label32(const vor_raster_output_t *out, const vor__run_t *runs, uint32_t count,
                          void *dst)
{
    (void)out;
    uint32_t *px = dst;
    uint32_t i = 0;
    for (uint32_t r = 0; r < count; r++) {
        for (; i < runs[r].end; i++) {
            px[i] = runs[r].site;
        }
    }
}

static void write_rgb888(const vor_raster_output_t *out, const vor__run_t *runs, uint32_t count,
                         void *dst)
{
    uint8_t *px = dst;
    uint32_t i = 0;
    for (uint32_t r = 0; r < count; r++) {
        uint32_t colour = out->palette888[runs[r].site];
        uint8_t red = (uint8_t)(colour >> 16);
        uint8_t green = (uint8_t)(colour >> 8);
        uint8_t 
                blue = (uint8_t)colour;
        for (; i < runs[r].end; i++) {
            px[3u * i] = red;
            px[(3u * i) + 1u] = green;
            px[(3u * i) + 2u] = blue;
        }
    }
}

/* BOUNDARY: 1 where the right or the lower neighbour has another site.
 * below: the runs of the next row (NULL on the last row). */
static void write_boundary(uint32_t width, const vor__run_t *runs, uint32_t count,
                           const vor__run_t *below, uint32_t below_count, uint8_t *px)
{
    uint32_t i;
    for (i = 0; i < width; i++) {
        px[i] = 0;
    }
    /* right neighbour: the last pixel of every run but the final one */
    for (uint32_t r = 0; (r + 1u) < count; r++) {
        px[runs[r].end - 1u] = 1;
    }
    /* lower neighbour: walk both rows' runs together */
    if (below != NULL) {
        uint32_t r = 0;
        uint32_t s = 0;
        i = 0;
        while (i < width) { /* each step ends a run of one row */
            uint32_t end = (runs[r].end < below[s].end) ? runs[r].end : below[s].end;
            if (runs[r].site != below[s].site) {
                for (; i < end; i++) {
                    px[i] = 1;
                }
            }
            i = end;
            if ((runs[r].end == end) && (r + 1u) < count) {
                r++;
            }
            if ((below[s].end == end) && (s + 1u) < below_count) {
                s++;
            }
        }
    }
}

/* Writes a row (runs) into dst in the output's kind, except DISTANCE,
 * NEAREST and KSETS (the kinds after BOUNDARY), which the entry point
 * writes (it knows the metric, the ranks and the k-sets). below: the runs of
 * the next row (BOUNDARY only; NULL on the last row). The writer comes
 * from a table: a switch on the kind, or a chain of == tests, which
 * compilers turn into one, is a case table, and GCC for ARMv6-M at -Os
 * reads those through libgcc (__gnu_thumb1_case_*), outside the library. */
static void write_row(const vor_raster_output_t *out, uint32_t width, const vor__run_t *runs,
                      uint32_t count, const vor__run_t *below, uint32_t below_count, void *dst)
{
    static run_writer_t *const writers[] = {
        [VOR_RASTER_LABEL8] = write_label8,   [VOR_RASTER_LABEL16] = write_16,
        [VOR_RASTER_LABEL32] = write_label32, [VOR_RASTER_RGB565] = write_16,
        [VOR_RASTER_RGB888] = write_rgb888,
    };
    if (out->kind == VOR_RASTER_BOUNDARY) {
        write_boundary(width, runs, count, below, below_count, dst);
    } else if (out->kind < VOR_RASTER_DISTANCE) {
        writers[out->kind](out, runs, count, dst);
    } else {
        /* no other case */
    }
}

/* ---------------------------------------------------------------- bands */

void vor__bands_begin(vor__bands_t *b, const vor_raster_frame_t *frame, uint32_t sites,
                      const vor_raster_output_t *out, vor__run_t *const rows[2], size_t row_bytes)
{
    if (out->areas != NULL) {
        for (uint32_t k = 0; k < sites; k++) {
            out->areas[k] = 0;
        }
    }
    b->out = out;
    b->width = frame->width;
    b->height = frame->height;
    b->row_bytes = row_bytes;
    b->rows[0] = rows[0];
    b->rows[1] = rows[1];
    b->counts[0] = 0;
    b->counts[1] = 0;
    b->cur = 0;
    b->next = 0;
    b->written = 0;
    b->band_first = 0;
    b->flush_first = 0;
    b->hold = out->kind == VOR_RASTER_BOUNDARY;
}

uint32_t vor__bands_put(vor__bands_t *b, uint32_t count)
{
    const vor_raster_output_t *out = b->out;
    const uint32_t j = b->next;
    uint8_t *band = out->band;
    if (j < b->height) {
        const vor__run_t *runs = b->rows[b->cur];
        b->counts[b->cur] = count;
        if (out->areas != NULL) {
            uint32_t start = 0;
            for (uint32_t r = 0; r < count; r++) {
                out->areas[runs[r].site] += runs[r].end - start;
                start = runs[r].end;
            }
        }
    }
    if (b->hold != 0) {
        /* row j - 1 is written now that the row below it is known */
        uint32_t held = b->cur ^ 1u;
        if (j > 0u) {
            write_row(out, b->width, b->rows[held], b->counts[held],
                      (j < b->height) ? b->rows[b->cur] : NULL, count,
                      band + (size_t)(j - 1u - b->band_first) * b->row_bytes);
            b->written = j;
        }
        b->cur = held;
    } else if (j < b->height) {
        write_row(out, b->width, b->rows[b->cur], count, NULL, 0,
                  band + (size_t)(j - b->band_first) * b->row_bytes);
        b->written = j + 1u;
    } else {
        /* no other case */
    }
    b->next = j + 1u;
    uint32_t rows = b->written - b->band_first;
    if ((rows == out->band_rows) || ((b->written == b->height) && (rows > 0u))) {
        b->flush_first = b->band_first;
        b->band_first = b->written;
        return rows;
    }
    return 0;
}

/* -------------------------------------------------------------- checks */

int vor__raster_frame_ok(const vor_raster_frame_t *f)
{
    if ((f->width == 0u) || (f->height == 0u) || (f->step_x <= 0) || (f->step_y <= 0) ||
        (f->width > 0x7FFFFFFFu) || (f->height > 0x7FFFFFFFu)) {
        return 0;
    }
    /* the last centre must be an int32 point: (w - 1) step < 2^62 here */
    int64_t last_x = f->origin_x + vor__offset(f->width - 1u, f->step_x);
    int64_t last_y = f->origin_y + vor__offset(f->height - 1u, f->step_y);
    return (last_x <= INT32_MAX) && (last_y <= INT32_MAX);
}

int vor__raster_band_check(uint32_t width, size_t pixel_bytes, size_t band_bytes,
                           uint32_t band_rows, size_t *row_bytes)
{
    if (width > 0x07FFFFFFu) {
        return VOR_ERR_ARG; /* the sizes below (and the work's) must not overflow */
    }
    size_t bytes = (size_t)width * pixel_bytes; /* below 2^29 */
    if ((uint64_t)band_bytes < vor__mul_u32((uint32_t)bytes, band_rows)) {
        return VOR_ERR_NOMEM;
    }
    *row_bytes = bytes;
    return VOR_OK;
}

int vor__raster_check(vor__raster_t *r, const vor_raster_frame_t *frame,
                      const vor_raster_sites_t *sites, const vor_raster_output_t *out,
                      const vor_raster_options_t *options, void *work, size_t work_bytes)
{
    return vor__raster_check_order(r, frame, sites, out, options, work, work_bytes, 0u);
}

void vor__raster_start(vor__raster_t *r)
{
    vor__bands_begin(&r->bands, r->frame, r->sites->count, r->out, r->rows, r->row_bytes);
}
