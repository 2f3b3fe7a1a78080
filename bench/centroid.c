/* SPDX-License-Identifier: MIT */
/*
 * bench/centroid.c - cost of vor_cell_centroid per cell, on any port.
 *
 * 64 and 1,000 uniform random sites (a fixed generator, the same on every
 * target) in the box [0, 2^20)^2, the arena of a Lloyd relaxation; every
 * site's cell clipped to that box. Prints per row
 *
 *   bench centroid N COST UNIT VERTICES   vor_cell_centroid, per cell
 *   bench cell N COST UNIT VERTICES       vor_cell, per cell, for scale
 *
 * where COST is the vor_port_counter() delta over all N cells divided by
 * N, with one decimal: instructions under QEMU -icount on targets (one
 * run: the count is repeatable), nanoseconds on the host (best of 5
 * runs); VERTICES is the mean vertex count, in tenths. "bench valid ok"
 * ends a good run (every call returned VOR_OK with a positive area).
 */
#include "test.h"
#include "vor.h"

#define MAX_SITES 1000u
#define HOST_RUNS 5u
#define BOX_SIDE (1 << 20)

static vor_point_t points[MAX_SITES];
static uint8_t arena[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(32)];
static vor_point_t polygon[VOR_CELL_MAX_VERTICES(MAX_SITES)];
static vor_t diagram;

/* The counter delta over every cell, or 0 on an error; *vertices their sum. */
static uint64_t all_cells(uint32_t n, bool centroid, uint32_t *vertices)
{
    vor_box_t box = {0, 0, BOX_SIDE, BOX_SIDE};
    uint32_t sum = 0;
    bool ok = true;
    uint64_t start = vor_port_counter();
    for (uint32_t i = 0; i < n; i++) {
        if (centroid) {
            vor_centroid_t c;
            ok &= vor_cell_centroid(&diagram, i, &box, scratch, sizeof scratch, &c) == VOR_OK &&
                  c.area > 0u;
            sum += c.vertices;
        } else {
            uint32_t count = 0;
            ok &= vor_cell(&diagram, i, &box, polygon, VOR_CELL_MAX_VERTICES(MAX_SITES), &count) ==
                  VOR_OK;
            sum += count;
        }
    }
    uint64_t cost = vor_port_counter() - start;
    *vertices = sum;
    return ok ? cost : 0u;
}

static bool row(const char *name, uint32_t n, bool centroid)
{
    bool host = vor_port_counter_unit[0] == 'n';
    uint64_t best = 0;
    uint32_t vertices = 0;
    for (unsigned run = 0; run < (host ? HOST_RUNS : 1u); run++) {
        uint64_t cost = all_cells(n, centroid, &vertices);
        if (cost == 0u) {
            return false;
        }
        best = (run == 0u || cost < best) ? cost : best;
    }
    uint64_t tenths = (best * 10u + n / 2u) / n;
    uint32_t mean_vertices = (vertices * 10u + n / 2u) / n;
    test_printf("bench %s %u %u.%u %s %u.%u\n", name, n, (unsigned)(tenths / 10u),
                (unsigned)(tenths % 10u), vor_port_counter_unit, mean_vertices / 10u,
                mean_vertices % 10u);
    return true;
}

int main(void)
{
    vor_port_init();
    bool ok = true;
    const uint32_t sizes[2] = {64u, MAX_SITES};
    for (unsigned s = 0; s < 2u; s++) {
        uint32_t n = sizes[s];
        test_rng_t rng;
        test_rng_seed(&rng, 2026u + n);
        for (uint32_t i = 0; i < n; i++) {
            points[i].x = (int32_t)(test_rng_u32(&rng) % BOX_SIDE);
            points[i].y = (int32_t)(test_rng_u32(&rng) % BOX_SIDE);
        }
        ok &= vor_init(&diagram, arena, sizeof arena, n) == VOR_OK &&
              vor_build(&diagram, points, n, NULL, NULL) == VOR_OK;
        ok = ok && row("centroid", n, true) && row("cell", n, false);
    }
    test_printf("bench valid %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
