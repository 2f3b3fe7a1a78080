/* SPDX-License-Identifier: MIT */
/*
 * raster.c - the harness of `make prove` for vor_raster,
 * vor_raster_euclid and vor_raster_nearest (K = 1, 2 and past the site
 * count, the k-order kinds): every metric with each output kind and method, on a
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
static const int64_t power[SITES] = {INT64_MIN, 4, INT64_MAX}; /* the ends of int64 */
static const uint16_t palette565[SITES] = {0x001F, 0x07E0, 0xF800};
static const uint32_t palette888[SITES] = {0x0000FF, 0x00FF00, 0xFF0000};

static uint32_t band[BAND * W];
static uint64_t work[(VOR_RASTER_WORK_BYTES(SITES, W) + 7u) / 8u];
static uint32_t areas[SITES];
#define KMOST (SITES + 1u) /* vor_raster_nearest's K past the site count */
static uint32_t kband[BAND * W * KMOST];
static uint64_t kwork[(VOR_RASTER_NEAREST_WORK_BYTES(SITES, W, KMOST) + 7u) / 8u];

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

/* every error the header lists, each with any value that makes it one:
 * only failures, so nothing is rendered */
static int bad_arguments(const vor_raster_frame_t *good, const vor_raster_sites_t *good_sites,
                         const vor_raster_output_t *good_out)
{
    vor_raster_frame_t frame = *good;
    vor_raster_sites_t sites = *good_sites;
    vor_raster_output_t out = *good_out;
    vor_raster_options_t options = {0};
    static const int32_t bad_weights[SITES] = {1, 0, -5};
    static const uint32_t bad_offsets[SITES + 1u] = {0, 2, 2, 6};
    int r = 0;

    sites.metric = VOR_METRIC_EUCLID;
    out.kind = VOR_RASTER_DISTANCE; /* 4 bytes a pixel: the band holds W */
    r |= vor_raster(NULL, &sites, &out, NULL, work, sizeof work);
    r |= vor_raster(&frame, NULL, &out, NULL, work, sizeof work);
    r |= vor_raster(&frame, &sites, NULL, NULL, work, sizeof work);
    r |= vor_raster(&frame, &sites, &out, NULL, NULL, sizeof work);
    r |= vor_raster_euclid(NULL, &sites, &out, NULL, work, sizeof work);
    /* any frame: wider than the band holds when it is a valid one */
    frame.origin_x = Frama_C_interval(INT32_MIN, INT32_MAX);
    frame.origin_y = Frama_C_interval(INT32_MIN, INT32_MAX);
    frame.step_x = Frama_C_interval(INT32_MIN, INT32_MAX);
    frame.step_y = Frama_C_interval(INT32_MIN, INT32_MAX);
    frame.width = Frama_C_unsigned_int_interval(W + 1u, UINT32_MAX);
    frame.height = Frama_C_unsigned_int_interval(0u, UINT32_MAX);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    r |= vor_raster_euclid(&frame, &sites, &out, NULL, work, sizeof work);
    frame.width = 0u;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    frame = *good;
    /* any size too small (EVA knows no addresses, so it takes both
     * outcomes of each alignment test: VOR_ERR_ALIGN is reached too) */
    r |= vor_raster(&frame, &sites, &out, NULL, work,
                    Frama_C_unsigned_int_interval(0u, VOR_RASTER_WORK_BYTES(SITES, W) - 1u));
    out.band_bytes = Frama_C_unsigned_int_interval(0u, BAND * W - 1u);
    out.kind = VOR_RASTER_LABEL8;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out.band_bytes = sizeof band;
    out.band_rows = 0u;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out.band_rows = BAND;
    out.flush = NULL;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out.flush = good_out->flush;
    out.band = NULL;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out.band = good_out->band;
    /* unknown kinds, methods and metrics, missing palettes */
    out.kind = (enum vor_raster_kind)Frama_C_interval(7, INT32_MAX);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out.kind = VOR_RASTER_RGB565;
    out.palette565 = NULL;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out.kind = VOR_RASTER_RGB888;
    out.palette888 = NULL;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out = *good_out;
    out.kind = VOR_RASTER_LABEL8;
    options.method = (enum vor_raster_method)Frama_C_interval(2, INT32_MAX);
    r |= vor_raster(&frame, &sites, &out, &options, work, sizeof work);
    sites.metric = (enum vor_metric)Frama_C_interval(14, INT32_MAX);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.metric = VOR_METRIC_L1;
    r |= vor_raster_euclid(&frame, &sites, &out, NULL, work, sizeof work);
    /* too many sites for 8 and 16-bit labels, none, no points */
    sites.count = Frama_C_unsigned_int_interval(257u, UINT32_MAX);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    out.kind = VOR_RASTER_LABEL16;
    sites.count = Frama_C_unsigned_int_interval(65537u, UINT32_MAX);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.count = 0u;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.count = SITES;
    sites.points = NULL;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.points = good_sites->points;
    /* each metric's own fields out of their range */
    sites.metric = VOR_METRIC_LP;
    sites.lp_exponent = Frama_C_nondet(0, Frama_C_unsigned_int_interval(9u, UINT32_MAX));
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.metric = VOR_METRIC_ELLIPTIC;
    sites.form_a = Frama_C_interval(INT32_MIN, 0);
    sites.form_b = Frama_C_interval(INT32_MIN, INT32_MAX);
    sites.form_c = Frama_C_interval(INT32_MIN, INT32_MAX);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.form_a = 2;
    sites.form_b = Frama_C_interval(2, 3);
    sites.form_c = 2;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.metric = (enum vor_metric)Frama_C_nondet(VOR_METRIC_MULT, VOR_METRIC_COMPOUND);
    sites.mult_weights = Frama_C_nondet_ptr((void *)bad_weights, NULL);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.metric = VOR_METRIC_ADD;
    sites.add_weights = NULL;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.metric = (enum vor_metric)Frama_C_nondet(VOR_METRIC_HAUSDORFF, VOR_METRIC_POLYLINE);
    sites.offsets = Frama_C_nondet_ptr((void *)bad_offsets, NULL);
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    sites.metric = VOR_METRIC_POWER;
    sites.power_weights = NULL;
    r |= vor_raster(&frame, &sites, &out, NULL, work, sizeof work);
    return r;
}

/* vor_raster_nearest: every metric, the k-order kinds and the K-th
 * label, K = 1, 2 and past the site count, both methods; then its own
 * bad arguments with any value (only failures). */
static int nearest(const vor_raster_frame_t *frame, const vor_raster_sites_t *good_sites,
                   const vor_raster_output_t *good_out)
{
    vor_raster_sites_t sites = *good_sites;
    vor_raster_output_t out = *good_out;
    vor_raster_options_t options = {0};
    static const enum vor_raster_kind kinds[3] = {VOR_RASTER_NEAREST, VOR_RASTER_KSETS,
                                                  VOR_RASTER_DISTANCE};
    static const uint32_t ks[3] = {1u, 2u, KMOST};
    int r = 0;
    out.band = kband;
    out.band_bytes = sizeof kband;
    /*@ loop unroll 14; */
    for (int metric = 0; metric < 14; metric++) {
        sites.metric = (enum vor_metric)metric;
        /*@ loop unroll 3; */
        for (int q = 0; q < 3; q++) {
            out.kind = kinds[q];
            options.method = (enum vor_raster_method)Frama_C_interval(0, 1);
            options.boundary565 = 0xFFFFu;
            r |= vor_raster_nearest(frame, &sites, ks[q], &out, &options, kwork, sizeof kwork);
        }
    }
    sites.metric = VOR_METRIC_EUCLID;
    out.kind = VOR_RASTER_BOUNDARY;
    r |= vor_raster_nearest(frame, &sites, 2u, &out, NULL, kwork, sizeof kwork);
    /* K out of range, KSETS without its palette, too small a band or
     * work, no sites */
    out.kind = VOR_RASTER_NEAREST;
    /* (0 and the interval apart: EVA would join them into one interval,
     * valid K included) */
    r |= vor_raster_nearest(frame, &sites, 0u, &out, NULL, kwork, sizeof kwork);
    r |= vor_raster_nearest(frame, &sites,
                            Frama_C_unsigned_int_interval(VOR_RASTER_MAX_NEAREST + 1u, UINT32_MAX),
                            &out, NULL, kwork, sizeof kwork);
    r |= vor_raster_nearest(NULL, &sites, 2u, &out, NULL, kwork, sizeof kwork);
    r |= vor_raster_nearest(frame, &sites, 2u, &out, NULL, kwork,
                            Frama_C_unsigned_int_interval(
                                0u, VOR_RASTER_NEAREST_WORK_BYTES(SITES, W, 2u) - 1u));
    out.band_bytes = Frama_C_unsigned_int_interval(0u, BAND * W * 4u * 2u - 1u);
    r |= vor_raster_nearest(frame, &sites, 2u, &out, NULL, kwork, sizeof kwork);
    out.band_bytes = sizeof kband;
    out.kind = (enum vor_raster_kind)Frama_C_interval(9, INT32_MAX);
    r |= vor_raster_nearest(frame, &sites, 2u, &out, NULL, kwork, sizeof kwork);
    out.kind = VOR_RASTER_KSETS;
    out.palette565 = NULL;
    r |= vor_raster_nearest(frame, &sites, 2u, &out, NULL, kwork, sizeof kwork);
    out.palette565 = good_out->palette565;
    sites.count = 0u;
    r |= vor_raster_nearest(frame, &sites, 2u, &out, NULL, kwork, sizeof kwork);
    return r;
}

int main(void)
{
    vor_raster_frame_t frame = {-1, -2, 2, 3, W, H};
    vor_raster_sites_t sites = {0};
    vor_raster_output_t out = {0};
    vor_raster_options_t options = {0};
    vor_point_t spread[SITES];
    int r = 0;

    sites.points = points;
    sites.count = SITES;
    sites.mult_weights = mult;
    sites.add_weights = add;
    sites.power_weights = power;
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
    /* Euclidean sites spread over the narrow (< 2^14), mid (< 2^19) and
     * wide tiers of vor_raster_euclid's envelopes, and beyond the 2^29
     * its fast method takes (the brute force then) */
    /*@ loop unroll 4; */
    for (int tier = 0; tier < 4; tier++) {
        static const int32_t scale[4] = {1 << 12, 1 << 17, 1 << 22, 1 << 28};
        vor_raster_frame_t wide = frame;
        /*@ loop unroll SITES; */
        for (uint32_t k = 0; k < SITES; k++) {
            spread[k].x = points[k].x * scale[tier];
            spread[k].y = points[k].y * (scale[tier] / 2);
        }
        wide.step_x = scale[tier] / 2;
        wide.step_y = scale[tier] / 4;
        sites.points = spread;
        /*@ loop unroll 2; */
        for (int m = 0; m < 2; m++) {
            options.method = (enum vor_raster_method)m;
            out.kind = VOR_RASTER_DISTANCE;
            r |= vor_raster_euclid(&wide, &sites, &out, &options, work, sizeof work);
            out.kind = VOR_RASTER_BOUNDARY;
            r |= vor_raster_euclid(&wide, &sites, &out, &options, work, sizeof work);
        }
    }
    sites.points = points;

    /* every metric with every method, labels and distances */
    /*@ loop unroll 14; */
    for (int metric = 0; metric < 14; metric++) {
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
    r |= nearest(&frame, &sites, &out);
    r |= bad_arguments(&frame, &sites, &out);
    return r;
}
