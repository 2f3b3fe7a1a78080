/* SPDX-License-Identifier: MIT */
/*
 * field.c - field frames: the natural-neighbour interpolant of integer
 * site values (vor_interpolate, vor_interpolate_laplace) rendered over a
 * raster frame, band by band, through the raster core's band writer
 * (raster.h). docs/design/interpolation.md, "Field frames".
 *
 * Each pixel is one exact interpolation at its centre: no sampling, no
 * shortcut between pixels, so every pixel is what vor_interpolate gives
 * there. What neighbouring pixels share is the start of the search: each
 * pixel's nearest site (found with vor_nearest from the previous pixel's)
 * is a natural neighbour of it and the hint of the interpolation, so the
 * walk of vor_nearest is a step or two, whatever the frame.
 */
#include "raster.h"

#include <stdbool.h>

#include "multiword.h"

/* The bytes of a pixel of each field kind. */
static size_t field_pixel_bytes(enum vor_field_kind kind)
{
    return (kind == VOR_FIELD_VALUE) ? 4u : 2u;
}

/*
 * The colour index of a rounded value v on the ramp low .. high (low <
 * high): floor(256 (v - low) / (high - low + 1)), 0 below low and 255
 * above high. In [low, high] it is the largest c in 0 .. 255 with
 * c (high - low + 1) <= 256 (v - low), found bit by bit with exact 32 x 32
 * products (both sides below 2^40): no division, so no runtime helper on
 * a 32-bit target.
 */
static uint32_t ramp_index(int32_t v, int32_t low, int32_t high)
{
    if (v < low) {
        return 0u;
    }
    if (v > high) {
        return 255u;
    }
    uint32_t span = (uint32_t)high - (uint32_t)low; /* high - low, mod 2^32 exact */
    uint32_t offset = (uint32_t)v - (uint32_t)low; /* v - low, exact */
    uint64_t target = (uint64_t)offset << 8;
    uint32_t index = 0;
    for (uint32_t bit = 128u; bit != 0u; bit >>= 1) {
        uint32_t c = index | bit;
        if ((vor__mul_u32(c, span) + c) <= target) {
            index = c;
        }
    }
    return index;
}

/* One request, checked. */
typedef struct field {
    const vor_t *d;
    const int32_t *values;
    const vor_raster_frame_t *frame;
    const vor_field_output_t *out;
    bool laplace;
    void *scratch;
    size_t scratch_bytes;
    uint32_t hint;          /* the nearest site of the previous pixel */
    uint32_t row_hint;      /* that of the previous row's first pixel */
    uint32_t most;          /* natural neighbours of any pixel so far */
} field_t;

/* The pixels of row j into px: VOR_OK, or the error of a pixel (only
 * VOR_ERR_NOMEM on a valid diagram). */
static int field_row(field_t *f, uint32_t j, void *px)
{
    const vor_raster_frame_t *frame = f->frame;
    const vor_field_output_t *out = f->out;
    vor_point_t q;
    q.y = (int32_t)(frame->origin_y + vor__offset(j, frame->step_y));
    f->hint = f->row_hint;
    for (uint32_t i = 0; i < frame->width; i++) {
        q.x = (int32_t)(frame->origin_x + vor__offset(i, frame->step_x));
        /* a site of the mesh, or none at the first pixel: vor_nearest
         * cannot fail (d has sites), and its answer is a natural
         * neighbour of q, the interpolation's start */
        (void)vor_nearest(f->d, q, f->hint, &f->hint);
        if (i == 0u) {
            f->row_hint = f->hint;
        }
        vor_interpolation_t v;
        v.neighbours = 0;
        int err = f->laplace ? vor_interpolate_laplace(f->d, f->values, q, f->hint, f->scratch,
                                                       f->scratch_bytes, &v)
                             : vor_interpolate(f->d, f->values, q, f->hint, f->scratch,
                                               f->scratch_bytes, &v);
        f->most = (v.neighbours > f->most) ? v.neighbours : f->most;
        bool outside = err == VOR_ERR_OUTSIDE;
        if (!outside && (err != VOR_OK)) {
            return err; /* VOR_ERR_NOMEM: v.neighbours says how many */
        }
        if (out->kind == VOR_FIELD_VALUE) {
            ((int32_t *)px)[i] = outside ? out->outside : v.value;
        } else {
            ((uint16_t *)px)[i] =
                outside ? out->outside565 : out->ramp565[ramp_index(v.value, out->low, out->high)];
        }
    }
    return VOR_OK;
}

/* The argument checks, before anything is written: VOR_OK with the row's
 * bytes in *row_bytes, or the error vor_field_raster documents. */
static int field_check(const vor_t *d, const int32_t *values, const vor_raster_frame_t *frame,
                       const vor_field_output_t *out, const vor_field_options_t *options,
                       const void *scratch, size_t scratch_bytes, size_t *row_bytes)
{
    enum vor_field_method method = (options != NULL) ? options->method : VOR_FIELD_SIBSON;
    if ((d == NULL) || (values == NULL) || (frame == NULL) || (out == NULL) ||
        !vor__raster_frame_ok(frame) || (out->band == NULL) || (out->flush == NULL) ||
        (out->band_rows == 0u) || ((scratch == NULL) && (scratch_bytes > 0u)) ||
        ((method != VOR_FIELD_SIBSON) && (method != VOR_FIELD_LAPLACE))) {
        return VOR_ERR_ARG;
    }
    if (out->kind == VOR_FIELD_RGB565) {
        if ((out->ramp565 == NULL) || (out->low >= out->high)) {
            return VOR_ERR_ARG;
        }
    } else if (out->kind != VOR_FIELD_VALUE) {
        return VOR_ERR_ARG;
    } else {
        /* VALUE: every field read is valid */
    }
    if (d->vertex_count == 0u) {
        return VOR_ERR_EMPTY;
    }
    return vor__raster_band_check(frame->width, field_pixel_bytes(out->kind), out->band_bytes,
                                  out->band_rows, row_bytes);
}

int vor_field_raster(const vor_t *d, const int32_t *values, const vor_raster_frame_t *frame,
                     const vor_field_output_t *out, const vor_field_options_t *options,
                     void *scratch, size_t scratch_bytes)
{
    size_t row_bytes = 0;
    int err = field_check(d, values, frame, out, options, scratch, scratch_bytes, &row_bytes);
    if (err != VOR_OK) {
        return err;
    }
    field_t f;
    f.d = d;
    f.values = values;
    f.frame = frame;
    f.out = out;
    f.laplace = (options != NULL) && (options->method == VOR_FIELD_LAPLACE);
    f.scratch = scratch;
    f.scratch_bytes = scratch_bytes;
    f.hint = VOR_NO_HINT;
    f.row_hint = VOR_NO_HINT;
    f.most = 0;
    /* the band writer's output: the band and its flush; the rows come as
     * pixels written here, so the kind is one whose pixels the producer
     * writes (raster.h, vor__bands_begin) */
    vor_raster_output_t band_out; /* every field set: no memset call */
    band_out.kind = VOR_RASTER_DISTANCE;
    band_out.band = out->band;
    band_out.band_bytes = out->band_bytes;
    band_out.band_rows = out->band_rows;
    band_out.flush = out->flush;
    band_out.user = out->user;
    band_out.palette565 = NULL;
    band_out.palette888 = NULL;
    band_out.areas = NULL;
    vor__run_t *no_runs[2];
    no_runs[0] = NULL;
    no_runs[1] = NULL;
    vor__bands_t bands;
    vor__bands_begin(&bands, frame, 0u, &band_out, no_runs, row_bytes);
    for (uint32_t j = 0; (j <= frame->height) && (err == VOR_OK); j++) { /* j = height: the end */
        if (j < frame->height) {
            err = field_row(&f, j, vor__bands_pixels(&bands));
        }
        if ((err == VOR_OK) && (vor__bands_put_flush(&bands, 0u) != 0)) {
            err = VOR_ERR_STOPPED; /* the flush's own code stays the caller's */
        }
    }
    if (out->max_neighbours != NULL) {
        *out->max_neighbours = f.most;
    }
    return err;
}
