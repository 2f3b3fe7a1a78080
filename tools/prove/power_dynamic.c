/* SPDX-License-Identifier: MIT */
/*
 * power_dynamic.c - the harness of `make prove` for the changes and the
 * query of a power diagram on concrete weighted sites: vor_power_remove,
 * vor_power_move and vor_power_nearest (power.c has them with their bad
 * arguments on an empty diagram, and everything else of vor_power.h).
 * One diagram of 8 sites, built afresh before each change so that each
 * change starts from it: removals of an inner vertex with three
 * neighbours, of one with five that un-hides a hidden site, of a hidden
 * site, of a hull vertex that un-hides a site at its own point, then of
 * every id in turn down to none (the hull, three vertices, the line, one
 * vertex); moves within a cell, across cells, onto another site's point
 * (heavier: it hides that site; equal: refused, with and without the id
 * back), onto itself, of a hidden site (it comes out) and of a weight
 * alone. The nearest site to any point of the int32 plane from each
 * site's id as hint (hidden ones included), from any other id and with
 * no hint: on the diagram, on the one left by the removal of the vertex
 * with five neighbours, on two vertices (no triangle of area: every
 * vertex looked at) and on one.
 * No -eva-slevel (prove.sh, as queries.c and nearest_k.c): the updates
 * are concrete, so EVA follows them exactly, and the nearest walk with
 * any point merges its states at its loops instead of keeping one per
 * path (with a slevel that reaches no loop, as power.c's, a run on a
 * concrete diagram had not ended after 20 minutes). The walk splits its
 * states by the vertex it walks from (`split best`, src/power.c), so
 * that the fans of two vertices are never merged into one (whose slots
 * EVA then widens past the triangles).
 */
#include <__fc_builtin.h>

#include "inputs.h"
#include "vor.h"
#include "vor_power.h"

/* The square 0 to 3 with equal weights; 4 at its centre, heavy (five
 * neighbours), hiding 5 beside it; 6 inside, with three neighbours; 7 at
 * 2's point and lighter, hidden. */
#define N 8u
static const vor_point_t points[N] = {{0, 0}, {10, 0}, {10, 10}, {0, 10},
                                      {5, 5}, {4, 5},  {7, 2},   {10, 10}};
static const int64_t weights[N] = {0, 0, 0, 0, 40, 0, 2, -5};

static uint64_t arena[VOR_POWER_ARENA_BYTES(N) / 8u + 1u];

/* The diagram again, whatever a change left. */
static void fresh(vor_power_t *pd)
{
    (void)vor_power_build(pd, points, weights, N, NULL);
}

/* The nearest site to any point from each id in turn (each site's, then
 * any other value: refused, or no hint), and with no hint. */
static void nearest_all(const vor_power_t *pd)
{
    uint32_t site;
    /*@ loop unroll N + 1; */
    for (uint32_t h = 0; h <= N; h++) {
        (void)vor_power_nearest(pd, any_point(), id_or_any(h, N), &site);
    }
    (void)vor_power_nearest(pd, any_point(), VOR_NO_HINT, &site);
}

int main(void)
{
    vor_power_t pd;
    uint32_t id;

    pd.mesh.revision = any_u32(); /* vor_power_init reads it */
    if (vor_power_init(&pd, arena, sizeof arena, N) != VOR_OK) {
        return 1;
    }
    fresh(&pd);
    nearest_all(&pd);

    /* removals: an inner vertex of three neighbours; one of five, which
     * un-hides 5; a hidden site; a hull vertex, which un-hides 7 at its
     * point */
    (void)vor_power_remove(&pd, 6u);
    fresh(&pd);
    (void)vor_power_remove(&pd, 4u);
    nearest_all(&pd);
    fresh(&pd);
    (void)vor_power_remove(&pd, 5u);
    fresh(&pd);
    (void)vor_power_remove(&pd, 2u);

    /* moves: within 6's cell; across to 3's side; onto 0's point,
     * heavier (0 hidden); onto 0 as it is (refused), with the id back
     * and without; onto itself; 5 heavier (out of hiding); 4 lighter */
    fresh(&pd);
    {
        vor_point_t within = {6, 2};
        vor_point_t across = {3, 8};
        (void)vor_power_move(&pd, 6u, within, 10, &id);
        fresh(&pd);
        (void)vor_power_move(&pd, 6u, across, weights[6], &id);
    }
    fresh(&pd);
    (void)vor_power_move(&pd, 6u, points[0], 10, &id);
    fresh(&pd);
    (void)vor_power_move(&pd, 6u, points[0], weights[0], &id);
    (void)vor_power_move(&pd, 6u, points[0], weights[0], NULL);
    (void)vor_power_move(&pd, 6u, points[6], weights[6], &id);
    (void)vor_power_move(&pd, 5u, points[5], 30, &id);
    fresh(&pd);
    (void)vor_power_move(&pd, 4u, points[4], 0, &id);

    /* every id removed in turn: hull vertices, down to three vertices,
     * two on a line, one, none */
    fresh(&pd);
    /*@ loop unroll N; */
    for (uint32_t s = 0; s < N; s++) {
        (void)vor_power_remove(&pd, s);
        if ((s == 5u) || (s == 6u)) {
            nearest_all(&pd); /* two vertices (no area), then one */
        }
    }
    return 0;
}
