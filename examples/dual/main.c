/* SPDX-License-Identifier: MIT */
/*
 * examples/dual - vor_build_dc_forked on the two Cortex-M33 cores of
 * QEMU's mps2-an521 board (`make dual`): core 0 builds one half of the
 * diagram and the merge, core 1 the other half, through the fork/join
 * hook of fork_join_an521.c (Arm's MHU as the doorbell between the cores).
 *
 * For each size, on uniform random sites over the whole int32 range:
 *   1. vor_build_dc on core 0 alone: the one-core instructions;
 *   2. vor_build_dc_forked with the hook measuring: the fork waits while
 *      core 1 builds its half, then core 0 builds its own, so each half is
 *      counted on its own core while the other sleeps in wfi (under
 *      -icount the two cores share one clock). The critical path of a
 *      parallel run is what runs before the fork, the longer half, and
 *      the merge after the join;
 *   3. vor_build_dc_forked with the cores running at the same time.
 * Both forked diagrams must be byte for byte the one-core diagram (home
 * slots of every id, the packed extra slots, the sites, the bucket grid,
 * the counts, duplicate_of), and valid; each forked build must have used
 * the hook once, and core 1 must have run the work. Prints a table and
 * ends with "N passed, N failed"; speedups are reported, never checked.
 */
#include "example_io.h"
#include "fork_join_an521.h"
#include "port.h"
#include "vor.h"

#define MAX_SITES 20000u


static const uint32_t sizes[] = {100u, 300u, 1000u, 3000u, 10000u, 20000u};
#define SIZES (sizeof sizes / sizeof sizes[0])

static vor_point_t points[MAX_SITES];
static uint32_t dup_one[MAX_SITES], dup_two[MAX_SITES];
static uint8_t arena_one[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t arena_two[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));

/* Both arenas start with the same bytes, so that whatever a build leaves
 * unwritten compares equal too. */
static void fill(uint8_t *to, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        to[i] = (uint8_t)(i * 131u + 7u);
    }
}

static bool same_bytes(const void *a, const void *b, size_t n)
{
    const uint8_t *x = a, *y = b;
    for (size_t i = 0; i < n; i++) {
        if (x[i] != y[i]) {
            return false;
        }
    }
    return true;
}

/* Everything a build writes that a later call reads (as
 * tests/test_fork_join.c compares it). */
static bool same_diagram(const vor_t *a, const vor_t *b, uint32_t n)
{
    const uint8_t *ta = (const uint8_t *)a->triangles, *tb = (const uint8_t *)b->triangles;
    uint32_t extras = (a->vertex_count >= 2u) ? a->vertex_count - 2u : 0u;
    size_t from = (size_t)a->max_sites * VOR_TRIANGLE_BYTES;
    return a->vertex_count == b->vertex_count && a->site_count == b->site_count &&
           a->last_site == b->last_site &&
           same_bytes(ta, tb, (size_t)n * VOR_TRIANGLE_BYTES) &&
           same_bytes(ta + from, tb + from, (size_t)extras * VOR_TRIANGLE_BYTES) &&
           same_bytes(a->sites, b->sites, (size_t)n * sizeof(vor_point_t)) &&
           a->bucket_columns == b->bucket_columns && a->bucket_rows == b->bucket_rows &&
           a->bucket_scale == b->bucket_scale && a->bucket_origin.x == b->bucket_origin.x &&
           a->bucket_origin.y == b->bucket_origin.y && a->low.x == b->low.x &&
           a->low.y == b->low.y && a->high.x == b->high.x && a->high.y == b->high.y &&
           same_bytes(a->buckets, b->buckets,
                      (size_t)a->bucket_columns * a->bucket_rows * sizeof(vor_index_t)) &&
           same_bytes(dup_one, dup_two, (size_t)n * sizeof(uint32_t));
}

static void print_padded(uint64_t value, unsigned width)
{
    unsigned digits = 1u;
    for (uint64_t v = value; v >= 10u; v /= 10u) {
        digits++;
    }
    for (; digits < width; digits++) {
        example_print(" ");
    }
    example_print_uint(value);
}

/* a / b with two decimals, rounded. */
static void print_ratio(uint64_t a, uint64_t b)
{
    uint64_t hundredths = (b == 0u) ? 0u : (a * 100u + b / 2u) / b;
    example_print_uint(hundredths / 100u);
    example_print(".");
    example_print(hundredths % 100u < 10u ? "0" : "");
    example_print_uint(hundredths % 100u);
}

/* One forked build into arena_two; true when it succeeded, used the hook
 * once, core 1 ran the work, and the diagram is the one-core one. */
static bool build_forked(vor_t *two, const vor_t *one, uint32_t n, const vor_build_options_t *o,
                         an521_fork_join_t *state, uint64_t *began, uint64_t *ended)
{
    vor_fork_join_t hook = {an521_fork, an521_join, state};
    uint32_t runs = an521_core1_runs();
    vor_violation_t violation;
    bool ok;

    fill(arena_two, sizeof arena_two);
    ok = vor_init(two, arena_two, sizeof arena_two, MAX_SITES) == VOR_OK;
    *began = vor_port_counter();
    ok = ok && vor_build_dc_forked(two, points, n, o, dup_two, &hook) == VOR_OK;
    *ended = vor_port_counter();
    example_check(ok, "vor_build_dc_forked");
    example_check(state->forks == 1u && state->joins == 1u, "the hook forked and joined once");
    example_check(an521_core1_runs() == runs + 1u, "core 1 ran the work");
    ok = ok && same_diagram(one, two, n);
    example_check(ok, "identical to the one-core build");
    example_check(vor_validate(two, &violation) == VOR_OK, "vor_validate");
    return ok && state->forks == 1u && an521_core1_runs() == runs + 1u;
}

int main(void)
{
    static vor_t one, two;
    vor_build_options_t options = {0};
    uint32_t seed = 20261129u;

    vor_port_init();
    /* The fork costs a mailbox write and a doorbell here, not a thread:
     * fork from the library's lowest threshold on. */
    options.fork_min_sites = 8u;
    example_print("vor_build_dc_forked on mps2-an521, two Cortex-M33 (instructions)\n");
    example_print("  sites   before fork    core 1 half    core 0 half     merge   critical path"
                  "   one core  speedup  identical\n");
    for (uint32_t s = 0; s < SIZES; s++) {
        uint32_t n = sizes[s];
        uint64_t t0, t1, began, ended, single, before, half1, half0, merge, critical;
        an521_fork_join_t measured = {0}, parallel = {0};
        bool identical;

        for (uint32_t i = 0; i < n; i++) {
            points[i].x = (int32_t)example_random(&seed);
            points[i].y = (int32_t)example_random(&seed);
        }
        fill(arena_one, sizeof arena_one);
        example_check(vor_init(&one, arena_one, sizeof arena_one, MAX_SITES) == VOR_OK, "vor_init");
        t0 = vor_port_counter();
        example_check(vor_build_dc(&one, points, n, &options, dup_one) == VOR_OK, "vor_build_dc");
        t1 = vor_port_counter();

        single = t1 - t0;

        measured.measure = 1u;
        identical = build_forked(&two, &one, n, &options, &measured, &began, &ended);
        before = measured.at_fork - began;
        half1 = measured.at_core1_done - measured.at_fork;
        half0 = measured.at_join - measured.at_core1_done;
        merge = ended - measured.at_join;
        critical = before + (half1 > half0 ? half1 : half0) + merge;
        /* The same build with the hook as a firmware uses it: fork
         * returns at once and both cores build. (QEMU runs its cores in
         * turns, so the order of their steps differs from the measured
         * run's, never the result.) */
        identical = build_forked(&two, &one, n, &options, &parallel, &t0, &t1) && identical;
        print_padded(n, 7u);
        print_padded(before, 14u);
        print_padded(half1, 15u);
        print_padded(half0, 15u);
        print_padded(merge, 10u);
        print_padded(critical, 16u);
        print_padded(single, 11u);
        example_print("    ");
        print_ratio(single, critical);
        example_print(identical ? "x   yes\n" : "x   NO\n");
    }
    example_print("core 1 stack used: ");
    example_print_uint(an521_core1_stack_used());
    example_print(" bytes\n");
    return example_print_tally();
}
