/* SPDX-License-Identifier: MIT */
/*
 * fuzz_raster.c - libFuzzer harness: random frames (origins and steps near
 * the int32 limits, some with centres outside int32), every metric and
 * output kind, both methods, band heights from 1 to past the frame, band
 * and work buffers exactly as large as documented or too small or
 * misaligned, flushes that stop the render; vor_raster, vor_raster_euclid
 * and vor_raster_nearest (K from 0 to past its largest, the k-order kinds
 * too). Valid renders are compared pixel by pixel (and the areas) with
 * the brute-force reference of tests/raster_reference.c (for K: a
 * selection of the ranks by ref_rank_compare); a call that fails before
 * the first pixel must write nothing: no band byte, no area, no flush.
 */
#include <string.h>

#include "fuzz_common.h"
#include "raster_reference.h"
#include "vor_raster.h"

#define MOST_SITES 8u
#define MOST_POINTS 24u
#define MOST_SIDE 24u

#define MOST_K VOR_RASTER_MAX_NEAREST

static uint8_t band[MOST_SIDE * (MOST_SIDE + 2u) * 4u * MOST_K + 8u];
static uint64_t work[VOR_RASTER_NEAREST_WORK_BYTES(MOST_SITES, MOST_SIDE, MOST_K) / 8u + 2u];
static uint32_t frame_pixels[MOST_SIDE * MOST_SIDE * MOST_K];
static uint32_t ranks[MOST_SIDE * MOST_SIDE * MOST_K];

typedef struct {
    const vor_raster_frame_t *frame;
    enum vor_raster_kind kind;
    uint32_t values; /* values a pixel: K for NEAREST, else 1 */
    uint32_t next_row;
    uint32_t stop_after; /* flushes until a nonzero return; 0: never */
    uint32_t flushes;
    int bad;
} capture_t;

static uint32_t pixel_value(enum vor_raster_kind kind, const uint8_t *p)
{
    switch (kind) {
    case VOR_RASTER_LABEL8:
    case VOR_RASTER_BOUNDARY:
        return p[0];
    case VOR_RASTER_LABEL16:
    case VOR_RASTER_RGB565:
    case VOR_RASTER_KSETS: {
        uint16_t v;
        memcpy(&v, p, 2);
        return v;
    }
    case VOR_RASTER_RGB888:
        return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
    default: {
        uint32_t v;
        memcpy(&v, p, 4);
        return v;
    }
    }
}

static int capture_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    capture_t *c = user;
    uint32_t w = c->frame->width * c->values;
    uint32_t bytes = c->kind == VOR_RASTER_NEAREST ? 4u : VOR_RASTER_NEAREST_PIXEL_BYTES(c->kind, 1u);
    if (first_row != c->next_row || rows == 0 || first_row + rows > c->frame->height)
        c->bad = 1;
    else
        for (uint32_t p = 0; p < rows * w; p++)
            frame_pixels[first_row * w + p] = pixel_value(c->kind, (const uint8_t *)pixels + p * bytes);
    c->next_row = first_row + rows;
    c->flushes++;
    return c->stop_after && c->flushes == c->stop_after ? 1234 : 0;
}

static int32_t draw_origin(fuzz_reader_t *r)
{
    uint8_t b = fuzz_u8(r);
    if (!(b & 1u))
        return (int8_t)fuzz_u8(r);
    int64_t corner = fuzz_corner(fuzz_u8(r));
    return fuzz_saturate(corner - (int8_t)fuzz_u8(r) % 32 * (b & 2u ? 1 : -1));
}

static int32_t draw_step(fuzz_reader_t *r)
{
    uint8_t b = fuzz_u8(r);
    if (b < 16)
        return (int32_t)b - 2; /* zero and negative steps too */
    return b < 200 ? (int32_t)(b % 7u) + 1 : (int32_t)(fuzz_u32(r) >> (b % 8u));
}

static int frame_valid(const vor_raster_frame_t *f)
{
    if (f->width == 0 || f->height == 0 || f->step_x <= 0 || f->step_y <= 0)
        return 0;
    int64_t last_x = f->origin_x + (int64_t)(f->width - 1u) * f->step_x;
    int64_t last_y = f->origin_y + (int64_t)(f->height - 1u) * f->step_y;
    return last_x <= INT32_MAX && last_y <= INT32_MAX;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_reader_t r = {data, size, 0};
    vor_point_t previous = {0, 0}, points[MOST_POINTS];
    int32_t mult[MOST_SITES], add[MOST_SITES];
    int64_t power[MOST_SITES];
    uint32_t offsets[MOST_SITES + 1u], areas[MOST_SITES];
    uint16_t palette565[MOST_SITES];
    uint32_t palette888[MOST_SITES];

    vor_raster_frame_t frame;
    frame.origin_x = draw_origin(&r);
    frame.origin_y = draw_origin(&r);
    frame.step_x = draw_step(&r);
    frame.step_y = draw_step(&r);
    frame.width = fuzz_u8(&r) % (MOST_SIDE + 1u);
    frame.height = fuzz_u8(&r) % (MOST_SIDE + 1u);

    vor_raster_sites_t sites = {0};
    uint8_t metric = fuzz_u8(&r);
    sites.metric = (enum vor_metric)(metric % 15u); /* 14: unknown */
    sites.count = fuzz_u8(&r) % (MOST_SITES + 1u);
    uint32_t npoints = sites.metric == VOR_METRIC_SEGMENT ? 2u * sites.count : sites.count;
    int grouped = sites.metric == VOR_METRIC_HAUSDORFF || sites.metric == VOR_METRIC_POLYGON ||
                  sites.metric == VOR_METRIC_POLYLINE;
    offsets[0] = 0;
    for (uint32_t k = 0; k < sites.count; k++) {
        offsets[k + 1u] = offsets[k] + (grouped ? 1u + fuzz_u8(&r) % 3u : 1u);
        mult[k] = 1 + (int32_t)(fuzz_u8(&r) % 5u);
        add[k] = (int8_t)fuzz_u8(&r) * (metric & 0x40u ? 1 << 20 : 1);
        /* power weights: small, or anywhere in int64 (the ends included) */
        uint8_t pick = fuzz_u8(&r);
        power[k] = pick < 128u  ? (int8_t)fuzz_u8(&r) * (int64_t)(pick % 64u + 1u)
                   : pick < 192u ? (int64_t)((uint64_t)fuzz_u32(&r) << 32 | fuzz_u32(&r))
                   : pick < 224u ? INT64_MIN + fuzz_u8(&r)
                                 : INT64_MAX - fuzz_u8(&r);
        palette565[k] = (uint16_t)(0x1111u * (k + 1u));
        palette888[k] = 0x010203u * (k + 1u);
    }
    if (grouped)
        npoints = offsets[sites.count];
    for (uint32_t i = 0; i < npoints; i++)
        points[i] = fuzz_point(&r, &previous);
    sites.points = points;
    sites.mult_weights = mult;
    sites.add_weights = add;
    sites.power_weights = power;
    sites.offsets = offsets;
    sites.lp_exponent = fuzz_u8(&r) % 10u; /* 0 and 9: out of range */
    sites.form_a = (int8_t)fuzz_u8(&r);
    sites.form_b = (int8_t)fuzz_u8(&r);
    sites.form_c = (int8_t)fuzz_u8(&r);
    if (sites.metric == VOR_METRIC_POLYLINE && (metric & 0x80u))
        sites.mult_weights = NULL;
    if (sites.metric == VOR_METRIC_POWER && (metric & 0x80u))
        sites.power_weights = NULL; /* power needs its weights */
    if (metric & 0x20u && sites.count)
        mult[0] = (int32_t)(fuzz_u8(&r) % 2u); /* 0: a weight below 1 */

    vor_raster_output_t out = {0};
    uint8_t how = fuzz_u8(&r);
    uint8_t memory = fuzz_u8(&r);
    int euclid_entry = (memory & 4u) != 0;
    int nearest_entry = !euclid_entry && (memory & 8u) != 0;
    uint32_t nk = fuzz_u8(&r) % (MOST_K + 2u); /* K; 0 and MOST_K + 1: out of range */
    /* 7 NEAREST and 8 KSETS: vor_raster_nearest's; 9: unknown */
    out.kind = (enum vor_raster_kind)(how % 10u);
    vor_raster_options_t options = {(enum vor_raster_method)((how >> 4) % 3u), 0xF00Du}; /* 2: unknown */
    out.band_rows = fuzz_u8(&r) % (MOST_SIDE + 3u);
    uint32_t pixel_bytes = nearest_entry ? (uint32_t)VOR_RASTER_NEAREST_PIXEL_BYTES(out.kind, nk)
                                         : VOR_RASTER_PIXEL_BYTES(out.kind);
    size_t band_needed = (size_t)out.band_rows * frame.width * pixel_bytes;
    out.band = band;
    out.band_bytes = band_needed - (how & 0x40u && band_needed ? 1u : 0u);
    out.palette565 = (memory & 0x10u) ? NULL : palette565; /* KSETS needs it */
    out.palette888 = palette888;
    out.areas = areas;
    uint32_t values = nearest_entry && out.kind == VOR_RASTER_NEAREST ? nk : 1u;
    capture_t capture = {&frame, out.kind, values, 0, fuzz_u8(&r) % 4u, 0, 0};
    out.flush = capture_flush;
    out.user = &capture;
    size_t work_bytes = (nearest_entry ? VOR_RASTER_NEAREST_WORK_BYTES(sites.count, frame.width, nk)
                                       : VOR_RASTER_WORK_BYTES(sites.count, frame.width)) -
                        (memory & 1u);
    uint8_t *work_at = (uint8_t *)work + (memory & 2u ? 4u : 0u);

    /* What the header promises an error for, checked here independently. */
    int params = sites.metric <= VOR_METRIC_POWER;
    if (sites.metric == VOR_METRIC_POWER)
        params = sites.power_weights != NULL;
    if (sites.metric == VOR_METRIC_LP)
        params = sites.lp_exponent >= 1u && sites.lp_exponent <= 8u;
    if (sites.metric == VOR_METRIC_ELLIPTIC)
        params = sites.form_a > 0 &&
                 (int64_t)sites.form_a * sites.form_c > (int64_t)sites.form_b * sites.form_b;
    if ((sites.metric == VOR_METRIC_MULT || sites.metric == VOR_METRIC_COMPOUND ||
         (sites.metric == VOR_METRIC_POLYLINE && sites.mult_weights)) && sites.count)
        for (uint32_t k = 0; k < sites.count; k++)
            params &= mult[k] >= 1;
    int kind_ok = nearest_entry ? nk >= 1u && nk <= MOST_K && out.kind <= VOR_RASTER_KSETS
                                : out.kind <= VOR_RASTER_DISTANCE;
    int palette_ok = !((out.kind == VOR_RASTER_RGB565 || out.kind == VOR_RASTER_KSETS) &&
                       out.palette565 == NULL);
    int valid = params && frame_valid(&frame) && kind_ok && palette_ok &&
                options.method <= VOR_RASTER_BRUTE && out.band_rows >= 1u &&
                !(out.kind == VOR_RASTER_LABEL8 && sites.count > 256u) &&
                (!euclid_entry || sites.metric == VOR_METRIC_EUCLID);
    int sized = sites.count && !(how & 0x40u) && !(memory & 3u);

    memset(band, 0x5a, sizeof band);
    memset(areas, 0x5a, sizeof areas);
    int result = nearest_entry ? vor_raster_nearest(&frame, &sites, nk, &out, &options, work_at,
                                                    work_bytes)
                 : (euclid_entry ? vor_raster_euclid : vor_raster)(&frame, &sites, &out, &options,
                                                                   work_at, work_bytes);
    if (!valid || !sized) {
        FUZZ_REQUIRE(result != VOR_OK, "raster: an invalid request succeeded");
        if (result < 0) {
            for (size_t i = 0; i < sizeof band; i++)
                FUZZ_REQUIRE(band[i] == 0x5a, "raster: failure wrote the band");
            for (uint32_t k = 0; k < MOST_SITES; k++)
                FUZZ_REQUIRE(areas[k] == 0x5a5a5a5au, "raster: failure wrote areas");
            FUZZ_REQUIRE(capture.flushes == 0, "raster: failure flushed");
        }
        return 0;
    }
    if (capture.stop_after && capture.flushes == capture.stop_after) {
        FUZZ_REQUIRE(result == VOR_ERR_STOPPED, "raster: a stopping flush gave no VOR_ERR_STOPPED");
        FUZZ_REQUIRE(!capture.bad, "raster: rows out of order");
        return 0;
    }
    FUZZ_REQUIRE(result == VOR_OK && !capture.bad && capture.next_row == frame.height,
                 "raster: a valid render failed or skipped rows");

    uint32_t w = frame.width, h = frame.height, labels[MOST_SIDE * MOST_SIDE];
    uint32_t counted[MOST_SITES] = {0};
    int undecided = 0;
    /* K' = min(K, count) ranks a pixel (1 for the other entries) */
    uint32_t ranked = !nearest_entry ? 1u : nk < sites.count ? nk : sites.count;
    for (uint32_t j = 0; j < h; j++)
        for (uint32_t i = 0; i < w; i++) {
            int32_t qx = ref_centre_x(&frame, i), qy = ref_centre_y(&frame, j);
            uint32_t *rank = &ranks[(j * w + i) * MOST_K];
            if (!nearest_entry) {
                rank[0] = ref_nearest_metric(&sites, qx, qy, &undecided);
            } else { /* per rank, the first best of the sites not ranked yet */
                uint32_t taken = 0;
                for (uint32_t q = 0; q < ranked; q++) {
                    uint32_t best = MOST_SITES;
                    for (uint32_t s = 0; s < sites.count; s++)
                        if (!(taken >> s & 1u) &&
                            (best == MOST_SITES || ref_rank_compare(&sites, s, best, qx, qy, &undecided) < 0))
                            best = s;
                    taken |= 1u << best;
                    rank[q] = best;
                }
            }
            labels[j * w + i] = rank[ranked - 1u];
            counted[labels[j * w + i]]++;
        }
    if (undecided)
        return 0; /* beyond the reference's precision: nothing to compare */
    if (out.kind == VOR_RASTER_NEAREST) {
        for (uint32_t p = 0; p < w * h; p++)
            for (uint32_t q = 0; q < nk; q++)
                FUZZ_REQUIRE(frame_pixels[p * nk + q] == (q < ranked ? ranks[p * MOST_K + q] : VOR_RASTER_NO_SITE),
                             "raster: a rank differs from the reference");
        for (uint32_t s = 0; s < sites.count; s++)
            FUZZ_REQUIRE(areas[s] == counted[s], "raster: an area differs from the reference");
        return 0;
    }
    for (uint32_t j = 0; j < h; j++)
        for (uint32_t i = 0; i < w; i++) {
            uint32_t label = labels[j * w + i], want = label;
            switch (out.kind) {
            case VOR_RASTER_RGB565: want = palette565[label]; break;
            case VOR_RASTER_RGB888: want = palette888[label]; break;
            case VOR_RASTER_BOUNDARY:
                want = (i + 1u < w && labels[j * w + i + 1u] != label) ||
                       (j + 1u < h && labels[(j + 1u) * w + i] != label);
                break;
            case VOR_RASTER_DISTANCE:
                want = ref_distance_metric(&sites, label, ref_centre_x(&frame, i),
                                           ref_centre_y(&frame, j));
                break;
            case VOR_RASTER_KSETS: { /* k-sets as bit sets of the sites */
                uint32_t here = 0, right = 0, below = 0, red = 0, green = 0, blue = 0;
                for (uint32_t q = 0; q < ranked; q++) {
                    uint32_t s = ranks[(j * w + i) * MOST_K + q];
                    here |= 1u << s;
                    red += palette565[s] >> 11;
                    green += palette565[s] >> 5 & 63u;
                    blue += palette565[s] & 31u;
                    if (i + 1u < w)
                        right |= 1u << ranks[(j * w + i + 1u) * MOST_K + q];
                    if (j + 1u < h)
                        below |= 1u << ranks[((j + 1u) * w + i) * MOST_K + q];
                }
                int edge = (i + 1u < w && right != here) || (j + 1u < h && below != here);
                /* the boundary colour of the options */
                want = edge ? 0xF00Du : (red / ranked) << 11 | (green / ranked) << 5 | blue / ranked;
                break;
            }
            default: break;
            }
            FUZZ_REQUIRE(frame_pixels[j * w + i] == want, "raster: a pixel differs from the reference");
        }
    for (uint32_t k = 0; k < sites.count; k++)
        FUZZ_REQUIRE(areas[k] == counted[k], "raster: an area differs from the reference");
    return 0;
}
