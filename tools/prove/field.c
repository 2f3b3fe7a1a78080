/* SPDX-License-Identifier: MIT */
/*
 * field.c - the harness of `make prove` for vor_field_raster: on the
 * cheap diagrams of far_sites.h (no sites, one site, three collinear
 * sites: every pixel at a site, on the segment or outside, so that no
 * boundary walk of src/interpolate.c is entered: interpolate.c proves
 * the walk on its own), a W x H frame in bands of BAND rows (a seam and
 * a partial last band) of each kind and method, a flush that goes on or
 * stops, a scratch of any size up to enough (a pixel's VOR_ERR_NOMEM),
 * the RGB565 ramp over three ranges; then every bad argument the header
 * lists, each with any value that makes it one.
 */
#include <__fc_builtin.h>

#include "far_sites.h"
#include "vor_raster.h"

#define W 5u
#define H 3u
#define BAND 2u
#define SCRATCH_BYTES VOR_SIBSON_SCRATCH_BYTES(2)

static int32_t band[BAND * W];
static uint16_t ramp[256];
static const int32_t values[N] = {10, -20, 30, INT32_MIN, 99, INT32_MAX};
/* The scratch at a fixed address (prove.sh declares the range valid), as
 * in centroid.c: the interpolation aligns it from its address as an
 * integer. */
#define scratch ((uint8_t *)0x10000u)
static uint32_t most;

/* the caller's flush: goes on or asks to stop, either way */
static int flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)user;
    (void)first_row;
    (void)rows;
    (void)pixels;
    return Frama_C_nondet(0, 1);
}

static int frames(const vor_t *d, const vor_field_output_t *good)
{
    /* the pixels (0..4, 0) .. (0..4, 10): the collinear sites' segment,
     * sites at its ends and middle, and points off it */
    vor_raster_frame_t frame = {0, 0, 5, 5, W, H};
    vor_field_output_t out = *good;
    vor_field_options_t options = {VOR_FIELD_SIBSON};
    int r = 0;
    /* the ramp over concrete ranges (any range would split each pixel's
     * index 256 ways): a narrow one the values leave at both ends, one
     * inside them, the whole of int32 */
    static const int32_t lows[3] = {-1, -25, INT32_MIN};
    static const int32_t highs[3] = {1, 40, INT32_MAX};
    /*@ loop unroll 2; */
    for (unsigned method = 0; method < 2u; method++) {
        options.method = (enum vor_field_method)method;
        out.kind = VOR_FIELD_VALUE;
        r |= vor_field_raster(d, values, &frame, &out, &options, scratch, SCRATCH_BYTES);
        out.kind = VOR_FIELD_RGB565;
        /*@ loop unroll 3; */
        for (unsigned k = 0; k < 3u; k++) {
            out.low = lows[k];
            out.high = highs[k];
            r |= vor_field_raster(d, values, &frame, &out, &options, scratch, SCRATCH_BYTES);
        }
    }
    out.max_neighbours = NULL;
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch,
                          Frama_C_unsigned_int_interval(0u, SCRATCH_BYTES));
    return r;
}

/* every error the header lists, each with any value that makes it one:
 * only failures, so nothing is rendered */
static int bad_arguments(const vor_t *d, const vor_field_output_t *good)
{
    const vor_raster_frame_t frame = {0, 0, 5, 5, W, H};
    vor_raster_frame_t f = frame;
    vor_field_output_t out = *good;
    vor_field_options_t options = {VOR_FIELD_SIBSON};
    int r = 0;
    r |= vor_field_raster(NULL, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    r |= vor_field_raster(d, NULL, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    r |= vor_field_raster(d, values, NULL, &out, NULL, scratch, SCRATCH_BYTES);
    r |= vor_field_raster(d, values, &frame, NULL, NULL, scratch, SCRATCH_BYTES);
    r |= vor_field_raster(d, values, &frame, &out, NULL, NULL, Frama_C_unsigned_int_interval(1u, UINT32_MAX));
    options.method = (enum vor_field_method)Frama_C_interval(2, INT32_MAX);
    r |= vor_field_raster(d, values, &frame, &out, &options, scratch, SCRATCH_BYTES);
    f.step_x = Frama_C_interval(INT32_MIN, 0);
    r |= vor_field_raster(d, values, &f, &out, NULL, scratch, SCRATCH_BYTES);
    f = frame;
    f.height = 0;
    r |= vor_field_raster(d, values, &f, &out, NULL, scratch, SCRATCH_BYTES);
    f = frame;
    f.origin_y = Frama_C_interval(INT32_MAX - 9, INT32_MAX); /* the last row past int32 */
    r |= vor_field_raster(d, values, &f, &out, NULL, scratch, SCRATCH_BYTES);
    f = frame;
    f.width = Frama_C_unsigned_int_interval(0x08000000u, 0x7FFFFFFFu);
    f.origin_x = INT32_MIN;
    r |= vor_field_raster(d, values, &f, &out, NULL, scratch, SCRATCH_BYTES);
    out.band = NULL;
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    out = *good;
    out.flush = NULL;
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    out = *good;
    out.band_rows = 0;
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    out = *good;
    out.kind = (enum vor_field_kind)Frama_C_interval(2, INT32_MAX);
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    out = *good;
    out.kind = VOR_FIELD_RGB565;
    out.ramp565 = NULL;
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    out.ramp565 = ramp;
    out.high = Frama_C_interval(INT32_MIN, 0);
    out.low = Frama_C_interval(out.high, INT32_MAX);
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    out = *good;
    out.band_bytes = Frama_C_unsigned_int_interval(0u, (BAND * W * 4u) - 1u);
    r |= vor_field_raster(d, values, &frame, &out, NULL, scratch, SCRATCH_BYTES);
    return r;
}

int main(void)
{
    vor_t d;
    vor_field_output_t out = {0};
    out.kind = VOR_FIELD_VALUE;
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = BAND;
    out.flush = flush;
    out.outside = Frama_C_interval(INT32_MIN, INT32_MAX);
    out.ramp565 = ramp;
    out.low = 0;
    out.high = 255;
    out.max_neighbours = &most;
    int r = 0;
    if (far_sites_init(&d) != VOR_OK) {
        return 1;
    }
    r |= frames(&d, &out); /* no sites */
    r |= vor_build(&d, points, 1u, NULL, NULL);
    r |= frames(&d, &out);
    r |= vor_build(&d, collinear, 3u, NULL, NULL);
    r |= frames(&d, &out);
    r |= bad_arguments(&d, &out);
    return r;
}
