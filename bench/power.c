/* SPDX-License-Identifier: MIT */
/*
 * bench/power.c - cost of the regular triangulation of weighted sites (the
 * dual of their power diagram) per site, on any port: vor_power_build, and
 * vor_power_insert one site after another.
 *
 * 1,000 and 10,000 points uniform over the full int32 range (a
 * fixed generator, the same on every target), with two kinds of weights,
 * as in tools/peer-bench/power.cpp; s^2 = 2^64 / n is the squared spacing
 * of the sites:
 *
 *   light   weights uniform in [0, s^2 / 100): few sites hidden;
 *   heavy   weights uniform in [0, s^2): a good share hidden.
 *
 * The insertions go in input order, which for these independent uniform
 * sites is a random order. Prints per size and kind
 *
 *   bench build-KIND N COST UNIT    vor_power_init + vor_power_build, per site
 *   bench insert-KIND N COST UNIT   vor_power_init + N vor_power_insert, per site
 *   bench hidden-KIND N H           H of the N sites hidden
 *   bench memory N BYTES            VOR_POWER_ARENA_BYTES(N)
 *
 * where COST is the vor_port_counter() delta with one decimal
 * (instructions under QEMU -icount on targets, nanoseconds on the host)
 * and N is the count it is divided by. Checks outside the counted part:
 * vor_power_validate after the build and after the insertions, and both
 * have the same number of finite triangles (vor_power_triangles_begin) and
 * of hidden sites (vor_power_hidden_begin): on sites in general position
 * the regular triangulation is unique. "bench valid ok" ends a good run.
 * tools/peer-bench/run.sh collects the lines for docs/benchmarks.md.
 */
#include "test.h"
#include "vor.h"
#include "vor_power.h"

#define MAX_SITES 10000u

static vor_point_t points[MAX_SITES];
static int64_t weights[MAX_SITES];
static uint8_t arena[VOR_POWER_ARENA_BYTES(MAX_SITES)]
    __attribute__((aligned(VOR_POWER_ARENA_ALIGN)));
static vor_power_t diagram;

enum kind { LIGHT, HEAVY };

static void report(const char *name, const char *kind, uint32_t count, uint64_t spent)
{
    uint64_t tenths = (spent * 10u + count / 2u) / count;
    test_printf("bench %s-%s %u %u.%u %s\n", name, kind, (unsigned)count,
                (unsigned)(tenths / 10u), (unsigned)(tenths % 10u), vor_port_counter_unit);
}

static uint64_t rng_u64(test_rng_t *rng)
{
    uint64_t high = test_rng_u32(rng);
    return (high << 32) | test_rng_u32(rng);
}

/* n points and their weights of the given kind. Two of the points are
 * equal with probability below n^2 / 2^65 (none here); the builds would
 * agree on them anyway (the lighter hidden, the same weight a duplicate). */
static void make_sites(uint32_t n, enum kind kind)
{
    test_rng_t rng;
    test_rng_seed(&rng, 0x9017u + n);
    for (uint32_t i = 0; i < n; i++) {
        points[i].x = (int32_t)test_rng_u32(&rng);
        points[i].y = (int32_t)test_rng_u32(&rng);
    }
    uint64_t bound = UINT64_MAX / n; /* s^2 */
    if (kind == LIGHT) {
        bound /= 100u;
    }
    test_rng_seed(&rng, 0x3E16u + (2u * n) + (uint32_t)kind);
    for (uint32_t i = 0; i < n; i++) {
        weights[i] = (int64_t)(rng_u64(&rng) % bound);
    }
}

/* vor_power_validate, and the finite triangles and hidden sites counted. */
static bool count(uint32_t *triangles, uint32_t *hidden)
{
    bool ok = vor_power_validate(&diagram, NULL) == VOR_OK;
    vor_triangle_iter_t it;
    uint32_t ids[3];
    *triangles = 0;
    ok &= vor_power_triangles_begin(&it, &diagram) == VOR_OK;
    while (vor_triangles_next(&it, ids) != 0) {
        (*triangles)++;
    }
    vor_power_hidden_iter_t h;
    uint32_t id;
    *hidden = 0;
    ok &= vor_power_hidden_begin(&h, &diagram) == VOR_OK;
    while (vor_power_hidden_next(&h, &id) != 0) {
        (*hidden)++;
    }
    return ok;
}

static bool run(uint32_t n, enum kind kind)
{
    const char *name = (kind == LIGHT) ? "light" : "heavy";
    make_sites(n, kind);

    uint64_t start = vor_port_counter();
    bool ok = (vor_power_init(&diagram, arena, sizeof arena, n) == VOR_OK) &&
              (vor_power_build(&diagram, points, weights, n, NULL) == VOR_OK);
    uint64_t spent = vor_port_counter() - start;
    report("build", name, n, spent);
    uint32_t built_triangles;
    uint32_t built_hidden;
    ok &= count(&built_triangles, &built_hidden);

    start = vor_port_counter();
    ok &= vor_power_init(&diagram, arena, sizeof arena, n) == VOR_OK;
    for (uint32_t i = 0; i < n; i++) {
        ok &= vor_power_insert(&diagram, points[i], weights[i], NULL) == VOR_OK;
    }
    spent = vor_port_counter() - start;
    report("insert", name, n, spent);
    uint32_t triangles;
    uint32_t hidden;
    ok &= count(&triangles, &hidden);
    ok &= (triangles == built_triangles) && (hidden == built_hidden);
    test_printf("bench hidden-%s %u %u\n", name, (unsigned)n, (unsigned)hidden);
    if (!ok) {
        test_printf("bench %u sites, %s weights: check failed (build: %u triangles, %u hidden; "
                    "insert: %u, %u)\n",
                    (unsigned)n, name, (unsigned)built_triangles, (unsigned)built_hidden,
                    (unsigned)triangles, (unsigned)hidden);
    }
    return ok;
}

int main(void)
{
    vor_port_init();
    bool ok = true;
    static const uint32_t sizes[] = {1000u, MAX_SITES};
    for (unsigned i = 0; i < 2u; i++) {
        ok &= run(sizes[i], LIGHT);
        ok &= run(sizes[i], HEAVY);
        test_printf("bench memory %u %u\n", (unsigned)sizes[i],
                    (unsigned)VOR_POWER_ARENA_BYTES(sizes[i]));
    }
    if (ok) {
        test_printf("bench valid ok\n");
    }
    return ok ? 0 : 1;
}
