/* SPDX-License-Identifier: MIT */
/*
 * diagram.c - the harness of `make prove` for the calls that make and
 * change a diagram: vor_init(_checked), vor_memory, vor_stats,
 * vor_motion_attach, the three builders, vor_validate, vor_insert(_near),
 * vor_remove and vor_move. Every bad argument the header lists is passed
 * with any value (sizes, counts, ids and options anywhere in their type);
 * the diagrams themselves are small and concrete (the sites below), so
 * EVA follows the mesh exactly, and the changes are made with any id.
 */
#include <__fc_builtin.h>

#include "vor.h"

#include "inputs.h"

/* 6 points, 5 sites: four cocircular (0 to 3, on the circle of centre
 * (5, 5)), a duplicate (4 repeats 0) and one collinear with 0 and 1 (5):
 * every degenerate case of the predicates' perturbation. Larger diagrams
 * make EVA merge the builders' loop iterations, and the mesh indices it
 * then reads turn imprecise (alarms and minutes of states). */
#define N 6u
static const vor_point_t points[N] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {20, 0}};

static uint32_t arena[(VOR_ARENA_BYTES(N) + 3u) / 4u];
static uint32_t cache[VOR_MOTION_BYTES(N) / 4u];

/* the caller's fork: runs the work itself or declines, either way */
static int fork_here(void *context, void (*work)(void *arg), void *arg)
{
    (void)context;
    if (Frama_C_nondet(0, 1)) {
        work(arg);
        return 0;
    }
    return 1;
}

static void join_here(void *context)
{
    (void)context;
}

/* each builder over points[0 .. n) for every n up to N, with each
 * option value (a bad one included) and duplicate_of given or not */
static int build_all(vor_t *d)
{
    vor_build_options_t options = {0};
    vor_fork_join_t hook = {fork_here, join_here, NULL};
    uint32_t dup[N];
    int r = 0;

    /* the failing counts and pointers, with any value */
    r |= vor_build(d, points, Frama_C_unsigned_int_interval(N + 1u, UINT32_MAX), NULL, dup);
    r |= vor_build(d, NULL, Frama_C_unsigned_int_interval(1u, UINT32_MAX), NULL, dup);
    r |= vor_build_dc(d, points, Frama_C_unsigned_int_interval(N + 1u, UINT32_MAX), NULL, dup);
    r |= vor_build_dc(d, NULL, Frama_C_unsigned_int_interval(1u, UINT32_MAX), NULL, dup);
    r |= vor_build_dc_forked(d, points, Frama_C_unsigned_int_interval(N + 1u, UINT32_MAX), NULL,
                             dup, &hook);
    r |= vor_build(NULL, points, N, NULL, dup);
    r |= vor_build_dc(NULL, points, N, NULL, dup);
    r |= vor_build_dc_forked(NULL, points, N, NULL, dup, &hook);
    options.order = (enum vor_order)Frama_C_interval(2, INT32_MAX);
    options.split = (enum vor_dc_split)Frama_C_interval(2, INT32_MAX);
    r |= vor_build(d, points, N, &options, dup);
    r |= vor_build_dc(d, points, N, &options, dup);
    r |= vor_build_dc_forked(d, points, N, &options, dup, &hook);
    /* one count and option at a time (unrolled): EVA follows each mesh */
    /*@ loop unroll N + 1; */
    for (uint32_t n = 0; n <= N; n++) {
        /*@ loop unroll 2; */
        for (int v = 0; v < 2; v++) {
            options.order = (enum vor_order)v;
            options.split = (enum vor_dc_split)v;
            options.fork_min_sites = any_u32();
            r |= vor_build(d, (n == 0u) ? Frama_C_nondet_ptr((void *)points, NULL) : points, n,
                           &options, Frama_C_nondet_ptr(dup, NULL));
            r |= vor_validate(d, NULL);
            r |= vor_build_dc(d, points, n, &options, Frama_C_nondet_ptr(dup, NULL));
            r |= vor_validate(d, NULL);
            r |= vor_build_dc_forked(d, points, n, &options, Frama_C_nondet_ptr(dup, NULL),
                                     Frama_C_nondet_ptr(&hook, NULL));
            r |= vor_validate(d, NULL);
        }
    }
    return r;
}

/* the dynamic updates on the diagram of points[], each site in turn and
 * any other id, with and without a motion cache */
static int update_all(vor_t *d)
{
    vor_violation_t violation;
    uint32_t id;
    int r = 0;

    r |= vor_remove(d, Frama_C_unsigned_int_interval(N, UINT32_MAX));
    r |= vor_move(d, Frama_C_unsigned_int_interval(N, UINT32_MAX), points[5], &id);
    r |= vor_insert_near(d, points[5], Frama_C_unsigned_int_interval(N, UINT32_MAX - 1u), &id);
    r |= vor_remove(NULL, 0u) | vor_move(NULL, 0u, points[0], &id);
    r |= vor_insert(NULL, points[0], &id) | vor_insert_near(NULL, points[0], 0u, &id);
    /*@ loop unroll N; */
    for (uint32_t s = 0; s < N; s++) {
        /* a small step, onto another site, far away, back */
        vor_point_t step = {points[s].x + 1, points[s].y + 2};
        vor_point_t far = {-30, 40};
        r |= vor_move(d, s, step, Frama_C_nondet_ptr(&id, NULL));
        r |= vor_move(d, s, points[(s + 1u) % N], Frama_C_nondet_ptr(&id, NULL));
        r |= vor_move(d, s, far, &id);
        r |= vor_move(d, s, points[s], &id);
        r |= vor_validate(d, &violation);
        /* out and in again: the freed id comes back */
        r |= vor_remove(d, s);
        r |= vor_validate(d, &violation);
        r |= vor_insert_near(d, points[s], (s == 0u) ? VOR_NO_HINT : 0u,
                             Frama_C_nondet_ptr(&id, NULL));
        r |= vor_insert(d, points[s], &id); /* a duplicate now */
        r |= vor_validate(d, &violation);
    }
    return r;
}

int main(void)
{
    vor_t d, e;
    vor_memory_t memory;
    vor_stats_t stats;
    vor_violation_t violation;
    uint32_t id;
    int r;

    /* a caller's vor_t: whatever its revision holds (vor_init reads it) */
    e.revision = any_u32();
    d.revision = any_u32();

    /* every argument of vor_init_checked anywhere (e is not used after) */
    r = vor_init_checked(Frama_C_nondet_ptr(&e, NULL), Frama_C_nondet_ptr(arena, NULL),
                         any_u32(), any_u32(), any_u32());
    r |= vor_memory(NULL, &memory);
    r |= vor_stats(NULL, &stats);
    r |= vor_validate(NULL, &violation);

    if (vor_init(&d, arena, sizeof arena, N) != VOR_OK) {
        return 1;
    }
    r |= vor_memory(&d, Frama_C_nondet_ptr(&memory, NULL));
    r |= vor_stats(&d, Frama_C_nondet_ptr(&stats, NULL));
    r |= vor_motion_attach(Frama_C_nondet_ptr(&d, NULL), Frama_C_nondet_ptr(cache, NULL),
                           any_u32());
    r |= vor_motion_attach(&d, NULL, 0u); /* detached: the analysis knows it */
    /* the inserts one by one into the empty diagram, then every update
     * without a cache and with one */
    /*@ loop unroll N; */
    for (uint32_t s = 0; s < N; s++) {
        r |= vor_insert(&d, points[s], &id);
    }
    r |= vor_validate(&d, &violation);
    r |= update_all(&d);
    r |= vor_motion_attach(&d, cache, sizeof cache);
    r |= update_all(&d);
    r |= build_all(&d);
    r |= vor_memory(&d, &memory);
    r |= vor_motion_attach(&d, NULL, 0u);
    return r;
}
