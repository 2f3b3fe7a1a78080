/* SPDX-License-Identifier: MIT */
/*
 * raster.c - the harness of `make prove` for vor_raster and
 * vor_raster_euclid: every metric with each output kind and method, on a
 * small frame (W x H pixels in bands of BAND rows, so that a band seam
 * and a partial last band are crossed) over small site sets of each
 * shape, and every bad argument the header lists with any value.
 */
#include <__fc_builtin.h>

#include "vor_raster.h"

#define W 4u
#define H 3u
#define BAND 2u
#define SITES 3u
#define POINTS 6u

/* point sites; for SEGMENT the first two pairs; for the point sets
 * (HAUSDORFF, POLYGON, POLYLINE) a point, a segment and a triangle */
static const vor_point_t points[POINTS] = {{0, 0}, {3, 1}, {1, 2}, {-2, 5}, {6, -1}, {2, 7}};
static const uint32_t offsets[SITES + 1u] = {0, 1, 3, 6};
static const int32_t mult[SITES] = {1, 2, 3};
static const int32_t add[SITES] = {0, -1, 5};
static const uint16_t palette565[SITES] = {0x001F, 0x07E0, 0xF800};
static const uint32_t palette888[SITES] = {0x0000FF, 0x00FF00, 0xFF0000};

static uint32_t band[BAND * W];
static uint64_t work[(VOR_RASTER_WORK_BYTES(SITES, W) + 7u) / 8u];
static uint32_t areas[SITES];

/* the caller's flush: goes on or asks to stop, either way */
static int flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)user;
    (void)first_row;
    (void)rows;
    (void)pixels;
    return Frama_C_nondet(0, 1);
}

static int render(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                  const vor_raster_output_t *out, const vor_raster_options_t *options)
{
    return vor_raster(frame, sites, out, options, work, sizeof work);
}

int main(void)
{
    vor_raster_frame_t frame = {-1, -2, 2, 3, W, H};
    vor_raster_sites_t sites = {0};
    vor_raster_output_t out = {0};
    vor_raster_options_t options = {0};
    int r = 0;

    sites.points = points;
    sites.count = SITES;
    sites.mult_weights = mult;
    sites.add_weights = add;
    sites.offsets = offsets;
    sites.lp_exponent = 3u;
    sites.form_a = 2;
    sites.form_b = -1;
    sites.form_c = 3;
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = BAND;
    out.flush = flush;
    out.palette565 = palette565;
    out.palette888 = palette888;
    out.areas = Frama_C_nondet_ptr(areas, NULL);

    /* every kind with every method, Euclidean sites, both entry points */
    /*@ loop unroll 7; */
    for (int k = 0; k < 7; k++) {
        out.kind = (enum vor_raster_kind)k;
        /*@ loop unroll 2; */
        for (int m = 0; m < 2; m++) {
            options.method = (enum vor_raster_method)m;
            r |= render(&frame, &sites, &out, &options);
            r |= vor_raster_euclid(&frame, &sites, &out, Frama_C_nondet_ptr(&options, NULL), work,
                                   sizeof work);
        }
    }
    /* every metric with every method, labels and distances */
    /*@ loop unroll 13; */
    for (int metric = 0; metric < 13; metric++) {
        sites.metric = (enum vor_metric)metric;
        /*@ loop unroll 2; */
        for (int m = 0; m < 2; m++) {
            options.method = (enum vor_raster_method)m;
            out.kind = VOR_RASTER_LABEL8;
            r |= render(&frame, &sites, &out, &options);
            out.kind = VOR_RASTER_DISTANCE;
            r |= render(&frame, &sites, &out, &options);
        }
    }
    return r;
}
