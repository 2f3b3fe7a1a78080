/* SPDX-License-Identifier: MIT */
/*
 * bench/delaunay.c - cost of vor_build per inserted site, on any port.
 *
 * Builds the Delaunay triangulation of 1,000 and 10,000 uniform random
 * full-range int32 sites (a fixed generator, the same sites on every
 * target) in a static arena, and prints per row
 *
 *   bench build N COST UNIT          default (quadtree) insertion order
 *   bench build-input N COST UNIT    VOR_ORDER_INPUT, as a baseline
 *   bench build-dc N COST UNIT       vor_build_dc, VOR_DC_XSPLIT
 *   bench build-dc-quadtree N COST UNIT   vor_build_dc, VOR_DC_QUADTREE
 *
 * where COST is the vor_port_counter() delta of one vor_init + vor_build
 * divided by N, with one decimal: instructions under QEMU -icount on
 * targets (one run: the count is repeatable), nanoseconds on the host
 * (best of 5 runs). vor_validate checks each result outside the timed
 * part; "bench valid ok" ends a good run. tools/peer-bench/run.sh collects the
 * lines for docs/benchmarks.md.
 */
#include "test.h"
#include "vor.h"

#define MAX_SITES 10000u
#define HOST_RUNS 5u

static vor_point_t points[MAX_SITES];
static uint8_t arena[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static vor_t diagram;

static void make_points(uint32_t n)
{
    test_rng_t rng;
    test_rng_seed(&rng, 2026u + n);
    for (uint32_t i = 0; i < n; i++) {
        points[i].x = (int32_t)test_rng_u32(&rng);
        points[i].y = (int32_t)test_rng_u32(&rng);
    }
}

/* vor_build in an order, or vor_build_dc with a split. */
enum builder { INCREMENTAL, DC_XSPLIT, DC_QUADTREE };

/* The counter delta of one build, or 0 on an error. */
static uint64_t build(uint32_t n, enum vor_order order, enum builder builder)
{
    vor_build_options_t options = {order, (builder == DC_XSPLIT) ? VOR_DC_XSPLIT : VOR_DC_QUADTREE,
                                   0};
    uint64_t start = vor_port_counter();
    if (vor_init(&diagram, arena, sizeof arena, n) != VOR_OK) {
        return 0u;
    }
    int err = (builder == INCREMENTAL) ? vor_build(&diagram, points, n, &options, NULL)
              : vor_build_dc(&diagram, points, n, &options, NULL);
    if (err != VOR_OK) {
        return 0u;
    }
    return vor_port_counter() - start;
}

static bool run(const char *name, uint32_t n, enum vor_order order, enum builder builder)
{
    /* the host's counter is wall time: keep the best of a few runs */
    unsigned runs = (vor_port_counter_unit[0] == 'n') ? HOST_RUNS : 1u;
    uint64_t best = UINT64_MAX;
    for (unsigned r = 0; r < runs; r++) {
        uint64_t spent = build(n, order, builder);
        if (spent == 0u || vor_validate(&diagram, NULL) != VOR_OK ||
            diagram.vertex_count != n) {
            test_printf("bench %s %u FAILED\n", name, (unsigned)n);
            return false;
        }
        best = (spent < best) ? spent : best;
    }
    uint64_t tenths = (best * 10u + n / 2u) / n;
    test_printf("bench %s %u %lu.%lu %s\n", name, (unsigned)n, (unsigned long)(tenths / 10u),
                (unsigned long)(tenths % 10u), vor_port_counter_unit);
    return true;
}

int main(void)
{
    vor_port_init();
    static const uint32_t sizes[] = {1000u, MAX_SITES};
    bool ok = true;
    for (unsigned i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        make_points(sizes[i]);
        ok &= run("build", sizes[i], VOR_ORDER_QUADTREE, INCREMENTAL);
        ok &= run("build-input", sizes[i], VOR_ORDER_INPUT, INCREMENTAL);
        ok &= run("build-dc", sizes[i], VOR_ORDER_QUADTREE, DC_XSPLIT);
        ok &= run("build-dc-quadtree", sizes[i], VOR_ORDER_QUADTREE, DC_QUADTREE);
    }
    test_printf("bench valid %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
