/* SPDX-License-Identifier: MIT */
/*
 * bench/raster.c - speed of vor_raster, on any port, for every metric.
 *
 * Renders frames of uniform random sites (a fixed generator: the same
 * sites on every target) and prints one line per case:
 *
 *   bench raster METRIC W H N fast F brute B ratio R UNIT
 *
 * F and B are the cost per pixel of the fast path (the Euclidean
 * envelopes, or per-tile culling for the other metrics) and of the
 * brute-force path (VOR_RASTER_BRUTE, every site at every pixel with the
 * same exact comparison): instructions per pixel under QEMU -icount on
 * targets, and megapixels per second on the host (best of a few runs).
 * R = how many times faster the fast path is. The host renders 320x240
 * and 1920x1080 with 16, 256 and 4,096 sites for every metric; targets
 * render 320x240, Euclidean sites at every count and the other metrics at
 * 16 and 256 sites. METRIC euclid-mm is the frame of make demo: 256
 * Euclidean sites in millimetres on a 100 m floor, 312 x 416 mm per pixel
 * (coordinates up to 10^5, the fast path's mid tier). The brute path is timed on the first 16 rows (the
 * first row only at 4,096 sites; its cost per pixel does not depend on
 * the row), and every fast frame is checked against the brute-force
 * frame on those rows; "bench valid ok" ends a good run.
 * tools/peer-bench/raster.sh turns the lines into docs/benchmarks.md.
 *
 * vor_raster_nearest (the K nearest sites, VOR_RASTER_NEAREST in 16-row
 * bands, the fast path) prints
 *
 *   bench korder METRIC W H N k K fast F UNIT
 *
 * for Euclidean and L1 sites, 16 and 256 of them, K = 1, 2, 4 and 8, on
 * 320x240 (targets and host).
 *
 * Sites of the other metrics: weights mult 1..4, add 0..s/4, compound
 * w1 1..4 and w2 0..s/8 (s: the mean site spacing); the form (2, 1, 3);
 * p = 3; Hausdorff sets of 3 points, segments and polygons (3 to 5
 * vertices, convex or not) within s/2 of their random centre; power
 * weights 0..s^2/4 (radii up to s/2, some sites hidden).
 */
#include "test.h"
#include "vor_raster.h"

#define MAX_SITES 4096u
#if defined(__SIZEOF_POINTER__) && __SIZEOF_POINTER__ > 4
#define BENCH_HOST_FRAMES 1
#define MAX_WIDTH 1920u
#else
#define MAX_WIDTH 320u
#endif
#define BAND_ROWS 16u
#define HOST_RUNS 5u

#define MAX_POINTS (5u * MAX_SITES)

static vor_point_t points[MAX_POINTS];
static int32_t mult_weights[MAX_SITES], add_weights[MAX_SITES];
static int64_t power_weights[MAX_SITES];
static uint32_t offsets[MAX_SITES + 1u];
static uint16_t palette[MAX_SITES];
static uint16_t band[BAND_ROWS * MAX_WIDTH];
static uint16_t first_band[BAND_ROWS * MAX_WIDTH];
static uint8_t work[VOR_RASTER_WORK_BYTES(MAX_SITES, MAX_WIDTH)]
    __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));
#define KORDER_MOST 8u
#define KORDER_WIDTH 320u
#define KORDER_SITES 256u
static uint32_t korder_band[BAND_ROWS * KORDER_WIDTH * KORDER_MOST];
static uint8_t korder_work[VOR_RASTER_NEAREST_WORK_BYTES(KORDER_SITES, KORDER_WIDTH, KORDER_MOST)]
    __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));

typedef struct sink {
    uint32_t checksum;
    uint32_t stop_rows; /* stop after this many rows (0: never) */
    int keep_first;     /* copy the first band to first_band */
    uint32_t mismatches;
    uint32_t width;
    uint32_t check_rows; /* rows of first_band to compare */
} sink_t;

static int flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    sink_t *s = user;
    const uint16_t *px = pixels;
    if (first_row == 0u) {
        if (s->keep_first) {
            for (uint32_t k = 0; k < rows * s->width; k++) {
                first_band[k] = px[k];
            }
        } else {
            for (uint32_t k = 0; k < s->check_rows * s->width; k++) {
                s->mismatches += first_band[k] != px[k];
            }
        }
    }
    s->checksum += px[0];
    if (s->stop_rows != 0u && first_row + rows >= s->stop_rows) {
        return 1;
    }
    return 0;
}

static uint64_t render(const vor_raster_sites_t *sites, const vor_raster_frame_t *frame,
                       enum vor_raster_method method, sink_t *s)
{
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_RGB565;
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = s->stop_rows != 0u ? s->stop_rows : BAND_ROWS;
    out.flush = flush;
    out.user = s;
    out.palette565 = palette;
    vor_raster_options_t options = {method, 0};
    uint64_t start = vor_port_counter();
    __asm__ volatile("" ::: "memory");
    int err = vor_raster(frame, sites, &out, &options, work, sizeof work);
    __asm__ volatile("" ::: "memory");
    uint64_t spent = vor_port_counter() - start;
    return (err == VOR_OK || (err == VOR_ERR_STOPPED && s->stop_rows != 0u)) ? spent : 0u;
}

static void print_cost(const char *label, uint64_t spent, uint64_t pixels, int host)
{
    if (host) { /* megapixels per second = pixels / ns * 1000, two decimals */
        uint64_t centi = spent == 0u ? 0u : (pixels * 100000u + spent / 2u) / spent;
        test_printf(" %s %lu.%02lu", label, (unsigned long)(centi / 100u),
                    (unsigned long)(centi % 100u));
    } else { /* instructions per pixel, one decimal */
        uint64_t tenths = (spent * 10u + pixels / 2u) / pixels;
        test_printf(" %s %lu.%lu", label, (unsigned long)(tenths / 10u),
                    (unsigned long)(tenths % 10u));
    }
}

static const char *const metric_names[] = {"euclid", "l1",       "linf",      "lp3",
                                           "ellip",  "mult",     "add",       "comp",
                                           "farthest", "hausdorff", "segment", "polygon",
                                           "polyline", "power"};

/* The sites of one case: n sites of the metric over a w x h frame (in
 * millimetres: over the demo's 100 m floor). */
static vor_raster_sites_t make_sites(enum vor_metric metric, uint32_t w, uint32_t h, uint32_t n,
                                     bool millimetres)
{
    test_rng_t rng;
    test_rng_seed(&rng, 7000u + n);
    /* the mean spacing s = sqrt(w h / n), by search (no float) */
    int32_t spacing = 1;
    while ((uint64_t)(spacing + 1) * (uint64_t)(spacing + 1) * n <= (uint64_t)w * h) {
        spacing++;
    }
    int32_t radius = spacing / 2 > 1 ? spacing / 2 : 1;
    uint32_t at = 0;
    for (uint32_t k = 0; k < n; k++) {
        int32_t x = millimetres ? test_rng_range(&rng, -50000, 49999)
                                : test_rng_range(&rng, 0, (int32_t)w - 1);
        int32_t y = millimetres ? test_rng_range(&rng, -50000, 49999)
                                : test_rng_range(&rng, 0, (int32_t)h - 1);
        palette[k] = (uint16_t)(k * 2654435761u >> 16);
        mult_weights[k] = 1 + test_rng_range(&rng, 0, 3);
        add_weights[k] = test_rng_range(&rng, 0, spacing / 4);
        if (metric == VOR_METRIC_COMPOUND) {
            add_weights[k] = test_rng_range(&rng, 0, spacing / 8);
        }
        if (metric == VOR_METRIC_POWER) {
            power_weights[k] = test_rng_range(&rng, 0, spacing * spacing / 4);
        }
        offsets[k] = at;
        uint32_t size = metric == VOR_METRIC_HAUSDORFF   ? 3u
                        : metric == VOR_METRIC_SEGMENT ? 2u
                        : metric == VOR_METRIC_POLYGON ? 3u + (uint32_t)test_rng_range(&rng, 0, 2)
                                                       : 1u;
        for (uint32_t i = 0; i < size; i++) {
            points[at].x = x + (size > 1u ? test_rng_range(&rng, -radius, radius) : 0);
            points[at].y = y + (size > 1u ? test_rng_range(&rng, -radius, radius) : 0);
            at++;
        }
    }
    offsets[n] = at;
    vor_raster_sites_t sites = {0};
    sites.metric = metric;
    sites.points = points;
    sites.count = n;
    sites.mult_weights = mult_weights;
    sites.add_weights = add_weights;
    sites.power_weights = power_weights;
    sites.offsets = offsets;
    sites.lp_exponent = 3;
    sites.form_a = 2;
    sites.form_b = 1;
    sites.form_c = 3;
    return sites;
}

static bool run(enum vor_metric metric, uint32_t w, uint32_t h, uint32_t n, bool millimetres)
{
    const int host = vor_port_counter_unit[0] == 'n';
    vor_raster_sites_t sites = make_sites(metric, w, h, n, millimetres);
    vor_raster_frame_t frame = {0, 0, 1, 1, w, h};
    if (millimetres) {
        frame.origin_x = -49844;
        frame.origin_y = -49792;
        frame.step_x = 312;
        frame.step_y = 416;
    }
    /* best of 5 on the host; of 2 for the slow large frames */
    const unsigned runs = !host ? 1u : (metric != VOR_METRIC_EUCLID && w > 320u) ? 2u : HOST_RUNS;
    const uint32_t brute_rows = n >= MAX_SITES && metric != VOR_METRIC_EUCLID ? 1u : BAND_ROWS;
    uint64_t fast = UINT64_MAX, brute = UINT64_MAX;
    sink_t s = {0, brute_rows, 1, 0, w, brute_rows};
    for (unsigned r = 0; r < runs; r++) {
        uint64_t spent = render(&sites, &frame, VOR_RASTER_BRUTE, &s);
        brute = spent < brute ? spent : brute;
    }
    s.keep_first = 0;
    s.stop_rows = 0;
    s.check_rows = brute_rows;
    for (unsigned r = 0; r < runs; r++) {
        uint64_t spent = render(&sites, &frame, VOR_RASTER_FAST, &s);
        fast = spent < fast ? spent : fast;
    }
    uint64_t fast_px = (uint64_t)w * h, brute_px = (uint64_t)w * brute_rows;
    bool ok = fast != 0u && brute != 0u && s.mismatches == 0u;
    test_printf("bench raster %s%s %u %u %u", metric_names[metric], millimetres ? "-mm" : "",
                (unsigned)w, (unsigned)h, (unsigned)n);
    print_cost("fast", fast, fast_px, host);
    print_cost("brute", brute, brute_px, host);
    /* ratio of the per-pixel costs, one decimal */
    uint64_t ratio10 = (fast == 0u) ? 0u : (brute * fast_px * 10u) / (fast * brute_px);
    test_printf(" ratio %lu.%lu %s%s\n", (unsigned long)(ratio10 / 10u),
                (unsigned long)(ratio10 % 10u), host ? "Mpx/s" : "instructions/px",
                ok ? "" : " FAILED");
    return ok;
}

static int korder_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)first_row;
    (void)rows;
    *(uint32_t *)user += ((const uint32_t *)pixels)[0];
    return 0;
}

/* vor_raster_nearest, K = k, the fast path: the cost per pixel. */
static bool run_korder(enum vor_metric metric, uint32_t n, uint32_t k)
{
    const int host = vor_port_counter_unit[0] == 'n';
    const uint32_t w = KORDER_WIDTH, h = 240u;
    vor_raster_sites_t sites = make_sites(metric, w, h, n, false);
    vor_raster_frame_t frame = {0, 0, 1, 1, w, h};
    uint32_t checksum = 0;
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_NEAREST;
    out.band = korder_band;
    out.band_bytes = sizeof korder_band;
    out.band_rows = BAND_ROWS;
    out.flush = korder_flush;
    out.user = &checksum;
    uint64_t best = UINT64_MAX;
    int err = VOR_OK;
    for (unsigned r = 0; r < (host ? HOST_RUNS : 1u); r++) {
        uint64_t start = vor_port_counter();
        __asm__ volatile("" ::: "memory");
        err |= vor_raster_nearest(&frame, &sites, k, &out, NULL, korder_work, sizeof korder_work);
        __asm__ volatile("" ::: "memory");
        uint64_t spent = vor_port_counter() - start;
        best = spent < best ? spent : best;
    }
    test_printf("bench korder %s %u %u %u k %u", metric_names[metric], (unsigned)w, (unsigned)h,
                (unsigned)n, (unsigned)k);
    print_cost("fast", best, (uint64_t)w * h, host);
    test_printf(" %s%s\n", host ? "Mpx/s" : "instructions/px", err == VOR_OK ? "" : " FAILED");
    return err == VOR_OK;
}

int main(void)
{
    vor_port_init();
    static const uint32_t sizes[] = {16u, 256u, MAX_SITES};
    bool ok = true;
    /* every metric but the polylines (examples/contours has their use) */
    for (int metric = VOR_METRIC_EUCLID; metric <= VOR_METRIC_POWER; metric++) {
        if (metric == VOR_METRIC_POLYLINE) {
            continue;
        }
        for (unsigned i = 0; i < 3u; i++) {
#ifndef BENCH_HOST_FRAMES
            if (metric != VOR_METRIC_EUCLID && sizes[i] > 256u) {
                continue; /* targets: the other metrics up to 256 sites */
            }
#endif
            ok &= run((enum vor_metric)metric, 320, 240, sizes[i], false);
        }
        if (metric == VOR_METRIC_EUCLID) {
            ok &= run(VOR_METRIC_EUCLID, 320, 240, 256, true); /* the demo's frame */
        }
#ifdef BENCH_HOST_FRAMES
        for (unsigned i = 0; i < 3u; i++) {
            ok &= run((enum vor_metric)metric, 1920, 1080, sizes[i], false);
        }
#endif
    }
    static const enum vor_metric korder_metrics[2] = {VOR_METRIC_EUCLID, VOR_METRIC_L1};
    static const uint32_t korder_ks[4] = {1u, 2u, 4u, KORDER_MOST};
    for (unsigned m = 0; m < 2u; m++) {
        for (uint32_t n = 16u; n <= KORDER_SITES; n *= 16u) {
            for (unsigned q = 0; q < 4u; q++) {
                ok &= run_korder(korder_metrics[m], n, korder_ks[q]);
            }
        }
    }
    test_printf("bench valid %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
