/* SPDX-License-Identifier: MIT */
/*
 * bench/dynamic.c - cost of vor_remove and vor_move per operation, on any
 * port, beside the cost of an insertion.
 *
 * 1,000 uniform sites in [0, 2^25)^2 (a fixed generator, the same on every
 * target; mean spacing 2^25 / sqrt(1000), about 1.06 million) are
 * inserted one by one with vor_insert, then 200 of them are moved by a
 * small step (at most 10 units a coordinate: the robot's case, where no
 * triangle changes), 200 moved to random points, and 200 removed. Then,
 * with a motion cache attached (vor_motion_attach), 200 small moves again
 * (each site's first move since the attach, mostly); 20 sites taking 10
 * steps each of up to 1/100 of the spacing (10,600 units, far beyond
 * their boxes), without and then with the cache; and a robot control
 * loop: the sites rebuilt 32 times larger ([0, 2^30)^2, mean spacing
 * about 34 million), every site takes 20 steps of a random walk of at
 * most 3 units a coordinate, round by round. Prints per kind
 *
 *   bench insert N COST UNIT
 *   bench small-move N COST UNIT
 *   bench large-move N COST UNIT
 *   bench remove N COST UNIT
 *   bench small-move-cached N COST UNIT
 *   bench step-move N COST UNIT        the 1/100 spacing steps, no cache
 *   bench step-move-cached N COST UNIT the same kind of steps, cached
 *   bench robot-loop N COST UNIT       every move of the loop, first ones included
 *   bench fast-move N COST UNIT        the loop's moves that took the fast path
 *   bench fast-fraction N PERCENT %    N moves, PERCENT of them fast
 *
 * where COST is the vor_port_counter() delta per operation with one
 * decimal (instructions under QEMU -icount on targets, nanoseconds on the
 * host) and N the number of operations. A move is fast when it evaluated
 * no predicate (the diagram's stats); fast-move times each move alone and
 * subtracts the cost of reading the counter (measured beside it).
 * vor_validate checks the diagram after each kind, outside the timed part;
 * "bench valid ok" ends a good run. tools/peer-bench/run.sh collects the lines
 * for docs/benchmarks.md.
 */
#include "test.h"
#include "vor.h"

#define SITES 1000u
#define OPS 200u

static vor_point_t points[SITES];
static uint8_t arena[VOR_ARENA_BYTES(SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static vor_t diagram;
static uint8_t motion[VOR_MOTION_BYTES(SITES)] __attribute__((aligned(VOR_MOTION_ALIGN)));

#define ROUNDS 20u

/* The counter's delta of moving site[k] to to[k] for k < OPS; a move onto
 * another site (VOR_ERR_DUPLICATE) is a refusal, not a failure. */
static uint64_t timed_moves(const uint32_t *site, const vor_point_t *to, bool *ok)
{
    uint64_t start = vor_port_counter();
    for (uint32_t k = 0; k < OPS; k++) {
        int err = vor_move(&diagram, site[k], to[k], NULL);
        *ok &= err == VOR_OK || err == VOR_ERR_DUPLICATE;
    }
    return vor_port_counter() - start;
}

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

#define STEPPERS 20u
#define STEPS 10u

/* STEPPERS sites (in the mesh) take STEPS steps each of up to 10,600
 * units a coordinate, round by round, with the cache freshly attached or
 * detached; returns the time spent moving (*ok false if a move failed). */
static uint64_t repeated_steps(test_rng_t *rng, uint32_t inserted, bool cached, bool *ok)
{
    vor_motion_attach(&diagram, cached ? motion : NULL, cached ? sizeof motion : 0u);
    uint32_t site[STEPPERS];
    for (uint32_t k = 0; k < STEPPERS; k++) {
        do {
            site[k] = test_rng_u32(rng) % inserted;
        } while (vor_move(&diagram, site[k], diagram.sites[site[k]], NULL) != VOR_OK); /* a removed id */
    }
    uint64_t spent = 0;
    for (uint32_t step = 0; step < STEPS; step++) {
        for (uint32_t k = 0; k < STEPPERS; k++) {
            int32_t x = diagram.sites[site[k]].x + test_rng_range(rng, -10600, 10600);
            int32_t y = diagram.sites[site[k]].y + test_rng_range(rng, -10600, 10600);
            uint64_t start = vor_port_counter();
            int err = vor_move(&diagram, site[k], (vor_point_t){x, y}, NULL);
            spent += vor_port_counter() - start;
            *ok &= err == VOR_OK || err == VOR_ERR_DUPLICATE;
        }
    }
    return spent;
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
    uint64_t spent; /* apart: a counted call may clear ok too */

    uint32_t inserted = 0;
    uint64_t start = vor_port_counter();
    for (uint32_t i = 0; i < SITES; i++) {
        inserted += vor_insert(&diagram, points[i], NULL) == VOR_OK ? 1u : 0u;
    }
    ok &= report("insert", SITES, vor_port_counter() - start) && inserted > 0u;

    /* steps up to 10 units, 1/100,000 of the spacing */
    uint32_t site[OPS];
    vor_point_t to[OPS];
    for (uint32_t k = 0; k < OPS; k++) {
        site[k] = test_rng_u32(&rng) % inserted;
        to[k].x = diagram.sites[site[k]].x + (int32_t)(test_rng_u32(&rng) % 21u) - 10;
        to[k].y = diagram.sites[site[k]].y + (int32_t)(test_rng_u32(&rng) % 21u) - 10;
    }
    spent = timed_moves(site, to, &ok);
    ok &= report("small-move", OPS, spent);

    for (uint32_t k = 0; k < OPS; k++) {
        site[k] = test_rng_u32(&rng) % inserted;
        to[k].x = coordinate(&rng);
        to[k].y = coordinate(&rng);
    }
    spent = timed_moves(site, to, &ok);
    ok &= report("large-move", OPS, spent);

    /* distinct sites: every fifth id */
    start = vor_port_counter();
    for (uint32_t k = 0; k < OPS; k++) {
        ok &= vor_remove(&diagram, k * (inserted / OPS)) == VOR_OK;
    }
    ok &= report("remove", OPS, vor_port_counter() - start);

    /* the small moves again, with the cache */
    ok &= vor_motion_attach(&diagram, motion, sizeof motion) == VOR_OK;
    for (uint32_t k = 0; k < OPS; k++) {
        do {
            site[k] = test_rng_u32(&rng) % inserted;
        } while (vor_move(&diagram, site[k], diagram.sites[site[k]], NULL) != VOR_OK); /* a removed id */
        to[k].x = diagram.sites[site[k]].x + (int32_t)(test_rng_u32(&rng) % 21u) - 10;
        to[k].y = diagram.sites[site[k]].y + (int32_t)(test_rng_u32(&rng) % 21u) - 10;
    }
    spent = timed_moves(site, to, &ok);
    ok &= report("small-move-cached", OPS, spent);

    /* steps of up to 1/100 of the spacing, again and again: the boxes
     * (about 2^-12 of the spacing) never hold them */
    spent = repeated_steps(&rng, inserted, false, &ok);
    ok &= report("step-move", STEPPERS * STEPS, spent);
    spent = repeated_steps(&rng, inserted, true, &ok);
    ok &= report("step-move-cached", STEPPERS * STEPS, spent);

    /* the robot control loop, on the sites 32 times larger */
    for (uint32_t i = 0; i < SITES; i++) {
        points[i].x *= 32;
        points[i].y *= 32;
    }
    ok &= vor_build(&diagram, points, SITES, NULL, NULL) == VOR_OK;
    /* each move is timed alone: what reading the counter costs comes off */
    uint64_t reads = 0;
    for (uint32_t k = 0; k < SITES; k++) {
        start = vor_port_counter();
        reads += vor_port_counter() - start;
    }
    uint64_t loop = 0, fast_spent = 0;
    uint32_t fast = 0;
    for (uint32_t round = 0; round < ROUNDS; round++) {
        for (uint32_t i = 0; i < SITES; i++) {
            int32_t x = diagram.sites[i].x + test_rng_range(&rng, -3, 3);
            int32_t y = diagram.sites[i].y + test_rng_range(&rng, -3, 3);
            uint32_t calls = test_predicate_calls(&diagram);
            start = vor_port_counter();
            int err = vor_move(&diagram, i, (vor_point_t){x, y}, NULL);
            spent = vor_port_counter() - start;
            ok &= err == VOR_OK || err == VOR_ERR_DUPLICATE;
            loop += spent;
            if (test_predicate_calls(&diagram) == calls) {
                fast++;
                fast_spent += spent;
            }
        }
    }
    /* reads / SITES per read, rounded down: never more than was spent */
    ok &= report("robot-loop", SITES * ROUNDS, loop - reads * ROUNDS);
    ok &= fast > 0u && report("fast-move", fast, fast_spent - reads * fast / SITES);
    test_printf("bench fast-fraction %u %u.%u %%\n", (unsigned)(SITES * ROUNDS),
                (unsigned)(fast * 100u / (SITES * ROUNDS)),
                (unsigned)(fast * 1000u / (SITES * ROUNDS) % 10u));

    if (ok) {
        test_printf("bench valid ok\n");
    }
    return ok ? 0 : 1;
}
