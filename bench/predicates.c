/* SPDX-License-Identifier: MIT */
/*
 * bench/predicates.c - cost of each predicate in each tier, on any port.
 *
 * Prints one line per row: "bench PREDICATE TIER COST UNIT", where COST is
 * the counter delta per call (nanoseconds on the host, instructions under
 * QEMU -icount on targets), including the call and the loop around it.
 * tools/bench-predicates.sh runs it on every port and builds the table of
 * docs/benchmarks.md. The inputs are generated here so that every call of
 * a row lands in that row's tier; the tier counters confirm it (the
 * library's counted evaluation, VOR_STATS, on the same inputs, untimed).
 */
#include "predicates.h"
#include "test.h"
#include "vor.h"

#ifndef BENCH_ROUNDS
#define BENCH_ROUNDS 4 /* passes over the inputs; the host build uses more */
#endif

#define INPUTS 256

static vor_point_t points[INPUTS][4];

/* Points whose differences lie within [-span, span] (span < 2^31),
 * anywhere in the int32 range; span 0 means differences beyond 2^31. */
static void make_inputs(test_rng_t *rng, int32_t span)
{
    for (unsigned n = 0; n < INPUTS; n++) {
        int32_t base_x = test_rng_range(rng, INT32_MIN / 2, INT32_MAX / 2);
        int32_t base_y = test_rng_range(rng, INT32_MIN / 2, INT32_MAX / 2);
        for (unsigned k = 0; k < 4; k++) {
            if (span == 0) {
                points[n][k].x = (int32_t)test_rng_u32(rng);
                points[n][k].y = (int32_t)test_rng_u32(rng);
                /* opposite ends of the x range: differences beyond 2^31,
                 * so every predicate needs its wide tier */
                if (k == 0 || k == 2) {
                    points[n][k].x = (k == 0) ? INT32_MAX - (points[n][k].x & 0xFFFF)
                                              : INT32_MIN + (points[n][k].x & 0xFFFF);
                }
            } else {
                points[n][k].x = base_x + test_rng_range(rng, -span / 2, span / 2);
                points[n][k].y = base_y + test_rng_range(rng, -span / 2, span / 2);
            }
        }
    }
}

/* Cocircular quadruples on x^2 + y^2 = (5 scale)^2, the inputs the
 * perturbation decides; their first three points become collinear for
 * orient2d when `collinear` is set. */
static void make_degenerate(test_rng_t *rng, int32_t scale, bool collinear)
{
    static const int32_t circle[8][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5},
                                         {-3, 4}, {-4, -3}, {0, -5}, {3, -4}};
    for (unsigned n = 0; n < INPUTS; n++) {
        int32_t cx = test_rng_range(rng, -1000, 1000);
        int32_t cy = test_rng_range(rng, -1000, 1000);
        unsigned first = test_rng_u32(rng) % 5u;
        for (unsigned k = 0; k < 4; k++) {
            points[n][k].x = cx + scale * circle[first + k][0];
            points[n][k].y = cy + scale * circle[first + k][1];
        }
        if (collinear) {
            points[n][2].x = 2 * points[n][1].x - points[n][0].x;
            points[n][2].y = 2 * points[n][1].y - points[n][0].y;
        }
    }
}

enum which { ORIENT2D, INCIRCLE, CLOSER, ORIENT2D_SOS, INCIRCLE_SOS };

static volatile int sink; /* keeps results alive */

/* The row's inputs once more through the library's counted evaluation,
 * so that stats shows which tier (or the perturbation) decided each. */
static void count_tiers(enum which which, vor_stats_t *stats)
{
    int acc = 0;
    for (unsigned n = 0; n < INPUTS; n++) {
        const vor_point_t *p = points[n];
        int sign;
        switch (which) {
        case ORIENT2D:
            acc += vor__orient2d_exact(&p[0], &p[1], &p[2], stats);
            break;
        case INCIRCLE:
            acc += vor__incircle_exact(&p[0], &p[1], &p[2], &p[3], stats);
            break;
        case CLOSER:
            acc += vor__closer_sign(&p[0], &p[1], &p[2], stats);
            break;
        case ORIENT2D_SOS:
            sign = vor__orient2d_exact(&p[0], &p[1], &p[2], stats);
            acc += (sign != 0) ? sign : vor__orient2d_perturbed(p, 0, 1, 2, stats);
            break;
        case INCIRCLE_SOS:
            sign = vor__incircle_exact(&p[0], &p[1], &p[2], &p[3], stats);
            acc += (sign != 0) ? sign : vor__incircle_perturbed(p, 0, 1, 2, 3, stats);
            break;
        }
    }
    sink = acc;
}

static void run(const char *name, const char *tier, enum which which, vor_stats_t *stats)
{
    count_tiers(which, stats);
    int acc = 0;
    uint64_t start = vor_port_counter();
    for (unsigned round = 0; round < BENCH_ROUNDS; round++) {
        for (unsigned n = 0; n < INPUTS; n++) {
            const vor_point_t *p = points[n];
            switch (which) {
            case ORIENT2D:
                acc += vor_orient2d(p[0], p[1], p[2]);
                break;
            case INCIRCLE:
                acc += vor_incircle(p[0], p[1], p[2], p[3]);
                break;
            case CLOSER:
                acc += vor_closer(p[0], p[1], p[2]);
                break;
            case ORIENT2D_SOS:
                acc += vor_orient2d_sos(p, 0, 1, 2);
                break;
            case INCIRCLE_SOS:
                acc += vor_incircle_sos(p, 0, 1, 2, 3);
                break;
            }
        }
    }
    uint64_t spent = vor_port_counter() - start;
    sink = acc;
    uint32_t calls = BENCH_ROUNDS * INPUTS;
    /* per call, with one decimal */
    uint64_t tenths = (spent * 10u + calls / 2u) / calls;
    test_printf("bench %s %s %lu.%lu %s\n", name, tier, (unsigned long)(tenths / 10u),
                (unsigned long)(tenths % 10u), vor_port_counter_unit);
}

int main(void)
{
    vor_port_init();
    test_rng_t rng;
    test_rng_seed(&rng, 2024);
    vor_stats_t stats = {0};
    static const struct {
        const char *tier;
        int32_t span;
    } tiers[] = {{"narrow", 1 << 13}, {"mid", 1 << 29}, {"wide", 0}};
    for (unsigned t = 0; t < 3; t++) {
        make_inputs(&rng, tiers[t].span);
        if (t != VOR_TIER_MID) { /* orient2d and closer have no mid tier */
            run("orient2d", tiers[t].tier, ORIENT2D, &stats);
            run("closer", tiers[t].tier, CLOSER, &stats);
        }
        run("incircle", tiers[t].tier, INCIRCLE, &stats);
    }
    vor_stats_t degenerate = {0};
    make_degenerate(&rng, 1 << 20, true);
    run("orient2d_sos", "collinear", ORIENT2D_SOS, &degenerate);
    make_degenerate(&rng, 1 << 10, false); /* differences below 2^14 */
    run("incircle_sos", "cocircular-small", INCIRCLE_SOS, &degenerate);
    make_degenerate(&rng, 1 << 20, false);
    run("incircle_sos", "cocircular-large", INCIRCLE_SOS, &degenerate);
    /* every timed call landed in the tier its row names */
    uint32_t per_row = INPUTS;
    bool tiers_ok = true;
    for (unsigned t = 0; t < VOR_TIERS; t++) {
        tiers_ok &= stats.incircle[t] == per_row;
        tiers_ok &= stats.orient2d[t] == ((t == VOR_TIER_MID) ? 0u : per_row);
        tiers_ok &= stats.closer[t] == ((t == VOR_TIER_MID) ? 0u : per_row);
    }
    tiers_ok &= degenerate.orient2d_perturbed == per_row &&
                degenerate.incircle_perturbed == 2u * per_row;
    test_printf("bench tiers %s\n", tiers_ok ? "ok" : "MISMATCH");
    return tiers_ok ? 0 : 1;
}
