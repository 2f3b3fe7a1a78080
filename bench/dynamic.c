/* SPDX-License-Identifier: MIT */
/*
 * bench/dynamic.c - cost of vor_remove and vor_move per operation, on any
 * port, beside the cost of an insertion.
 *
 * 1,000 uniform sites in [0, 2^25)^2 (a fixed generator, the same on every
 * target) are inserted one by one with vor_insert, then 200 of them are
 * moved by a small step (at most 1/100 of the mean spacing: the robot's
 * case, where no triangle changes), 200 moved to random points, and 200
 * removed. Prints per kind
 *
 *   bench insert N COST UNIT
 *   bench small-move N COST UNIT
 *   bench large-move N COST UNIT
 *   bench remove N COST UNIT
 *
 * where COST is the vor_port_counter() delta per operation with one
 * decimal (instructions under QEMU -icount on targets, nanoseconds on the
 * host) and N the number of operations. vor_validate checks the diagram
 * after each kind, outside the timed part; "bench valid ok" ends a good
 * run. tools/bench/run.sh collects the lines for docs/benchmarks.md.
 */
#include "test.h"
#include "vor.h"

#define SITES 1000u
#define OPS 200u

static vor_point_t points[SITES];
static uint8_t arena[VOR_ARENA_BYTES(SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static vor_t diagram;

static int32_t coordinate(test_rng_t *rng)
{
    return (int32_t)(test_rng_u32(rng) >> 7); /* [0, 2^25) */
}

/* Prints one row; false (and a message) when the diagram went wrong. */
static bool report(const char *name, uint32_t count, uint64_t spent)
{
    uint64_t tenths = (spent * 10u + count / 2u) / count;
    test_printf("bench %s %u %u.%u %s\n", name, (unsigned)count, (unsigned)(tenths / 10u),
                (unsigned)(tenths % 10u), vor_port_counter_unit);
    if (vor_validate(&diagram, NULL) != VOR_OK) {
        test_printf("bench %s: vor_validate failed\n", name);
        return false;
    }
    return true;
}

int main(void)
{
    vor_port_init();
    test_rng_t rng;
    test_rng_seed(&rng, 0xD1A5u);
    for (uint32_t i = 0; i < SITES; i++) {
        points[i].x = coordinate(&rng);
        points[i].y = coordinate(&rng);
    }
    if (vor_init(&diagram, arena, sizeof arena, SITES) != VOR_OK) {
        test_printf("bench: vor_init failed\n");
        return 1;
    }
    bool ok = true;

    uint32_t inserted = 0;
    uint64_t start = vor_port_counter();
    for (uint32_t i = 0; i < SITES; i++) {
        inserted += vor_insert(&diagram, points[i].x, points[i].y, NULL) == VOR_OK ? 1u : 0u;
    }
    ok &= report("insert", SITES, vor_port_counter() - start) && inserted > 0u;

    /* the mean spacing is 2^25 / sqrt(1000), about 1,061: steps up to 10 */
    uint32_t site[OPS];
    vor_point_t to[OPS];
    for (uint32_t k = 0; k < OPS; k++) {
        site[k] = test_rng_u32(&rng) % inserted;
        to[k].x = diagram.sites[site[k]].x + (int32_t)(test_rng_u32(&rng) % 21u) - 10;
        to[k].y = diagram.sites[site[k]].y + (int32_t)(test_rng_u32(&rng) % 21u) - 10;
    }
    start = vor_port_counter();
    for (uint32_t k = 0; k < OPS; k++) {
        int err = vor_move(&diagram, site[k], to[k].x, to[k].y, NULL);
        ok &= err == VOR_OK || err == VOR_ERR_DUPLICATE;
    }
    ok &= report("small-move", OPS, vor_port_counter() - start);

    for (uint32_t k = 0; k < OPS; k++) {
        site[k] = test_rng_u32(&rng) % inserted;
        to[k].x = coordinate(&rng);
        to[k].y = coordinate(&rng);
    }
    start = vor_port_counter();
    for (uint32_t k = 0; k < OPS; k++) {
        int err = vor_move(&diagram, site[k], to[k].x, to[k].y, NULL);
        ok &= err == VOR_OK || err == VOR_ERR_DUPLICATE;
    }
    ok &= report("large-move", OPS, vor_port_counter() - start);

    /* distinct sites: every fifth id */
    start = vor_port_counter();
    for (uint32_t k = 0; k < OPS; k++) {
        ok &= vor_remove(&diagram, k * (inserted / OPS)) == VOR_OK;
    }
    ok &= report("remove", OPS, vor_port_counter() - start);

    if (ok) {
        test_printf("bench valid ok\n");
    }
    return ok ? 0 : 1;
}
