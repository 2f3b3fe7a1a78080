/*
 * bench/raster.c - speed of vor_raster, on any port.
 *
 * Renders frames of uniform random sites (a fixed generator: the same
 * sites on every target) and prints one line per case:
 *
 *   bench raster METRIC W H N fast F brute B ratio R UNIT
 *
 * F and B are the cost per pixel of the fast path and of the brute-force
 * path (VOR_RASTER_BRUTE, every site at every pixel): instructions per
 * pixel under QEMU -icount on targets, and megapixels per second on the
 * host (best of a few runs). R = how many times faster the fast path is.
 * Targets render 320x240 RGB565 in 16-row bands; the host also renders
 * 1920x1080. METRIC euclid-mm is the frame of make demo: sites in
 * millimetres on a 100 m floor, 312 x 416 mm per pixel (coordinates up to
 * 10^5, the fast path's mid tier). The brute path is timed on the first 16 rows only (its cost
 * per pixel does not depend on the row). Every fast frame is checked
 * against the brute-force frame on those rows; "bench valid ok" ends a
 * good run. tools/bench/raster.sh turns the lines into docs/benchmarks.md.
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

static vor_point_t points[MAX_SITES];
static uint16_t palette[MAX_SITES];
static uint16_t band[BAND_ROWS * MAX_WIDTH];
static uint16_t first_band[BAND_ROWS * MAX_WIDTH];
static uint8_t work[VOR_RASTER_WORK_BYTES(MAX_SITES, MAX_WIDTH)]
    __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));

typedef struct sink {
    uint32_t checksum;
    uint32_t stop_rows; /* stop after this many rows (0: never) */
    int keep_first;     /* copy the first band to first_band */
    uint32_t mismatches;
    uint32_t width;
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
            for (uint32_t k = 0; k < rows * s->width; k++) {
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

static uint64_t render(const vor_raster_frame_t *f, uint32_t n, enum vor_raster_method method,
                       sink_t *s)
{
    vor_raster_frame_t frame = *f;
    vor_raster_sites_t sites = {VOR_METRIC_EUCLID, points, n};
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_RGB565;
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = BAND_ROWS;
    out.flush = flush;
    out.user = s;
    out.palette565 = palette;
    out.method = method;
    uint64_t start = vor_port_counter();
    __asm__ volatile("" ::: "memory");
    int err = vor_raster(&frame, &sites, &out, work, sizeof work);
    __asm__ volatile("" ::: "memory");
    uint64_t spent = vor_port_counter() - start;
    return (err == VOR_OK || (err == 1 && s->stop_rows != 0u)) ? spent : 0u;
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

/* millimetres: true for the demo's frame (w x h pixels over a 100 m
 * floor), false for one unit per pixel */
static bool run(uint32_t w, uint32_t h, uint32_t n, bool millimetres)
{
    const int host = vor_port_counter_unit[0] == 'n';
    const unsigned runs = host ? HOST_RUNS : 1u;
    vor_raster_frame_t frame = {0, 0, 1, 1, w, h};
    if (millimetres) {
        frame.origin_x = -49844;
        frame.origin_y = -49792;
        frame.step_x = 312;
        frame.step_y = 416;
    }
    test_rng_t rng;
    test_rng_seed(&rng, 7000u + n);
    for (uint32_t k = 0; k < n; k++) {
        if (millimetres) {
            points[k].x = test_rng_range(&rng, -50000, 49999);
            points[k].y = test_rng_range(&rng, -50000, 49999);
        } else {
            points[k].x = test_rng_range(&rng, 0, (int32_t)w - 1);
            points[k].y = test_rng_range(&rng, 0, (int32_t)h - 1);
        }
        palette[k] = (uint16_t)(k * 2654435761u >> 16);
    }
    uint64_t fast = UINT64_MAX, brute = UINT64_MAX;
    sink_t s = {0, BAND_ROWS, 1, 0, w};
    for (unsigned r = 0; r < runs; r++) {
        uint64_t spent = render(&frame, n, VOR_RASTER_BRUTE, &s);
        brute = spent < brute ? spent : brute;
    }
    s.keep_first = 0;
    s.stop_rows = 0;
    for (unsigned r = 0; r < runs; r++) {
        uint64_t spent = render(&frame, n, VOR_RASTER_FAST, &s);
        fast = spent < fast ? spent : fast;
    }
    uint64_t fast_px = (uint64_t)w * h, brute_px = (uint64_t)w * BAND_ROWS;
    bool ok = fast != 0u && brute != 0u && s.mismatches == 0u;
    test_printf("bench raster %s %u %u %u", millimetres ? "euclid-mm" : "euclid", (unsigned)w,
                (unsigned)h, (unsigned)n);
    print_cost("fast", fast, fast_px, host);
    print_cost("brute", brute, brute_px, host);
    /* ratio of the per-pixel costs, one decimal */
    uint64_t ratio10 = (fast == 0u) ? 0u : (brute * fast_px * 10u) / (fast * brute_px);
    test_printf(" ratio %lu.%lu %s%s\n", (unsigned long)(ratio10 / 10u),
                (unsigned long)(ratio10 % 10u), host ? "Mpx/s" : "instructions/px",
                ok ? "" : " FAILED");
    return ok;
}

int main(void)
{
    vor_port_init();
    static const uint32_t sizes[] = {16u, 256u, MAX_SITES};
    bool ok = true;
    for (unsigned i = 0; i < 3u; i++) {
        ok &= run(320, 240, sizes[i], false);
    }
    ok &= run(320, 240, 256, true);
#ifdef BENCH_HOST_FRAMES
    for (unsigned i = 0; i < 3u; i++) {
        ok &= run(1920, 1080, sizes[i], false);
    }
#endif
    test_printf("bench valid %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
