/* SPDX-License-Identifier: MIT */
/*
 * bench/interpolate.c - cost of natural-neighbour interpolation per query,
 * on any port: vor_interpolate (Sibson) and vor_interpolate_laplace, and
 * the coordinates alone (vor_sibson, vor_laplace).
 *
 * 1,000 and 10,000 sites uniform over the full int32 range (a fixed
 * generator, the same on every target, as bench/power.c), values uniform
 * in [-10^6, 10^6], and QUERIES query points uniform in the middle square
 * [-3/4 2^31, 3/4 2^31)^2, inside the hull of these sites; every call
 * starts from VOR_NO_HINT (the bucket grid's site), as for unrelated
 * queries. Each call is counted on its own; the counter's own reads (two
 * consecutive reads, averaged) are taken off. Prints per size
 *
 *   bench CALL N COST UNIT       mean per query of CALL over all queries
 *   bench CALL-k6 N COST UNIT    the same over the queries with 6 neighbours
 *   bench neighbours N MEAN K6 Q mean natural neighbours (one decimal), the
 *                                queries with 6 and all the queries
 *
 * CALL: sibson, laplace, interpolate, interpolate-laplace. COST is the
 * vor_port_counter() delta with one decimal (instructions under QEMU
 * -icount on targets, nanoseconds on the host). Checks outside the
 * counted part: every call returns VOR_OK with the same neighbours as
 * vor_sibson, both coordinates' weights add up to their denominator, and
 * both rounded values lie between the smallest and the largest value of
 * the neighbours. "bench valid ok" ends a good run. tools/peer-bench/run.sh
 * collects the lines for docs/benchmarks.md.
 */
#include "test.h"
#include "vor.h"

#define MAX_SITES 10000u
#define QUERIES 300u
#define MAX_K 24u

static vor_point_t points[MAX_SITES];
static int32_t values[MAX_SITES];
static uint8_t arena[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(MAX_K)];
static vor_t diagram;

enum call { SIBSON, LAPLACE, INTERPOLATE, INTERPOLATE_LAPLACE, CALLS };
static const char *const call_name[CALLS] = {"sibson", "laplace", "interpolate",
                                             "interpolate-laplace"};

static void report(const char *name, const char *suffix, uint32_t n, uint64_t spent,
                   uint32_t count)
{
    uint64_t tenths = (count == 0u) ? 0u : ((spent * 10u) + (count / 2u)) / count;
    test_printf("bench %s%s %u %u.%u %s\n", name, suffix, (unsigned)n, (unsigned)(tenths / 10u),
                (unsigned)(tenths % 10u), vor_port_counter_unit);
}

/* sum of the k weights == the denominator (limbs 32-bit words each) */
static bool adds_up(const vor_coordinates_t *c)
{
    uint32_t limbs = c->limbs;
    uint64_t carry = 0;
    bool ok = limbs <= 64u;
    for (uint32_t w = 0; ok && (w < limbs); w++) {
        uint64_t s = carry;
        for (uint32_t i = 0; i < c->count; i++) {
            s += c->weights[(size_t)i * limbs + w];
        }
        ok = (uint32_t)s == c->denominator[w];
        carry = s >> 32;
    }
    return ok && (carry == 0u);
}

/* The neighbours' smallest and largest values. */
static void value_range(const vor_coordinates_t *c, int32_t *lo, int32_t *hi)
{
    *lo = INT32_MAX;
    *hi = INT32_MIN;
    for (uint32_t i = 0; i < c->count; i++) {
        int32_t v = values[c->sites[i]];
        *lo = (v < *lo) ? v : *lo;
        *hi = (v > *hi) ? v : *hi;
    }
}

static bool run(uint32_t n, uint64_t idle)
{
    test_rng_t rng;
    test_rng_seed(&rng, 0x9017u + n);
    for (uint32_t i = 0; i < n; i++) {
        points[i].x = (int32_t)test_rng_u32(&rng);
        points[i].y = (int32_t)test_rng_u32(&rng);
        values[i] = test_rng_range(&rng, -1000000, 1000000);
    }
    bool ok = (vor_init(&diagram, arena, sizeof arena, n) == VOR_OK) &&
              (vor_build(&diagram, points, n, NULL, NULL) == VOR_OK);
    uint64_t spent[CALLS] = {0}, spent6[CALLS] = {0};
    uint32_t neighbours = 0, with6 = 0;
    const int32_t reach = 1610612736; /* 3/4 of 2^31 */
    for (uint32_t j = 0; ok && (j < QUERIES); j++) {
        vor_point_t q = {test_rng_range(&rng, -reach, reach - 1),
                         test_rng_range(&rng, -reach, reach - 1)};
        uint64_t cost[CALLS];
        vor_coordinates_t c;
        vor_interpolation_t v;
        int32_t lo;
        int32_t hi;

        uint64_t start = vor_port_counter();
        int err = vor_laplace(&diagram, q, VOR_NO_HINT, scratch, sizeof scratch, &c);
        cost[LAPLACE] = vor_port_counter() - start;
        ok &= (err == VOR_OK) && adds_up(&c);
        uint32_t k = c.count;

        start = vor_port_counter();
        err = vor_sibson(&diagram, q, VOR_NO_HINT, scratch, sizeof scratch, &c);
        cost[SIBSON] = vor_port_counter() - start;
        ok &= (err == VOR_OK) && adds_up(&c) && (c.count == k) && (k >= 3u);
        value_range(&c, &lo, &hi);

        start = vor_port_counter();
        err = vor_interpolate(&diagram, values, q, VOR_NO_HINT, scratch, sizeof scratch, &v);
        cost[INTERPOLATE] = vor_port_counter() - start;
        ok &= (err == VOR_OK) && (v.neighbours == k) && (v.value >= lo) && (v.value <= hi);

        start = vor_port_counter();
        err = vor_interpolate_laplace(&diagram, values, q, VOR_NO_HINT, scratch, sizeof scratch,
                                      &v);
        cost[INTERPOLATE_LAPLACE] = vor_port_counter() - start;
        ok &= (err == VOR_OK) && (v.neighbours == k) && (v.value >= lo) && (v.value <= hi);

        neighbours += k;
        with6 += (k == 6u) ? 1u : 0u;
        for (unsigned i = 0; i < CALLS; i++) {
            uint64_t net = (cost[i] > idle) ? (cost[i] - idle) : 0u;
            spent[i] += net;
            spent6[i] += (k == 6u) ? net : 0u;
        }
        if (!ok) {
            test_printf("bench %u sites: query (%d, %d) failed (error %d, %u neighbours)\n",
                        (unsigned)n, (int)q.x, (int)q.y, err, (unsigned)k);
        }
    }
    for (unsigned i = 0; i < CALLS; i++) {
        report(call_name[i], "", n, spent[i], QUERIES);
        report(call_name[i], "-k6", n, spent6[i], with6);
    }
    uint32_t tenths = ((neighbours * 10u) + (QUERIES / 2u)) / QUERIES;
    test_printf("bench neighbours %u %u.%u %u %u\n", (unsigned)n, (unsigned)(tenths / 10u),
                (unsigned)(tenths % 10u), (unsigned)with6, (unsigned)QUERIES);
    return ok;
}

int main(void)
{
    vor_port_init();
    /* what two consecutive counter reads cost by themselves */
    uint64_t idle = 0;
    for (unsigned i = 0; i < 64u; i++) {
        uint64_t start = vor_port_counter();
        idle += vor_port_counter() - start;
    }
    idle /= 64u;
    bool ok = run(1000u, idle);
    ok &= run(MAX_SITES, idle);
    if (ok) {
        test_printf("bench valid ok\n");
    }
    return ok ? 0 : 1;
}
