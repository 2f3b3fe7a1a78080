/* SPDX-License-Identifier: MIT */
/*
 * large.c - the harness of `make prove` for the paths that need more
 * sites than the small diagrams have: the builders' quadtree paths (8
 * sites or more), a crowded bucket (a cluster of more than 8 sites), the
 * forked build's halves (the first with a duplicate), the removal of a
 * site with more than 16 neighbours, and the motion cache's sizing of
 * boxes for incircle tests.
 * The 39 points are concrete (a site with 20 neighbours around it, a
 * cluster of 10, 7 scattered and a duplicate), so that EVA follows each
 * build exactly.
 */
#include "large_sites.h"

static uint32_t cache[VOR_MOTION_BYTES(LN) / 4u];

/* the caller's fork: runs the work itself */
static int fork_here(void *context, void (*work)(void *arg), void *arg)
{
    (void)context;
    work(arg);
    return 0;
}

static void join_here(void *context)
{
    (void)context;
}

int main(void)
{
    vor_t d;
    vor_build_options_t options = {0};
    vor_fork_join_t hook = {fork_here, join_here, NULL};
    vor_violation_t violation;
    uint32_t id;
    int r = 0;

    d.revision = 0u;
    if (vor_init(&d, large_arena, sizeof large_arena, LN) != VOR_OK) {
        return 1;
    }
    /* each builder with each option (unrolled: one concrete state each) */
    /*@ loop unroll 2; */
    for (int v = 0; v < 2; v++) {
        options.order = (enum vor_order)v;
        options.split = (enum vor_dc_split)v;
        options.fork_min_sites = 8u;
        r |= vor_build(&d, large_sites, LN, &options, NULL);
        r |= vor_build_dc(&d, large_sites, LN, &options, NULL);
        r |= vor_build_dc_forked(&d, large_sites, LN, &options, NULL, &hook);
    }
    r |= vor_validate(&d, &violation);
    /* the centre of the star (20 neighbours) out and in again */
    r |= vor_remove(&d, 0u);
    r |= vor_validate(&d, &violation);
    r |= vor_insert(&d, large_sites[0], &id);
    /* moves with a motion cache over sites 2^10 apart or more (room for
     * boxes beside the incircle tests' crude bounds): each site's second
     * slow move sizes its box, next to neighbours already boxed (from the
     * second site on), and the third moves inside it */
    r |= vor_build(&d, motion_sites, MN, NULL, NULL);
    r |= vor_motion_attach(&d, cache, sizeof cache);
    /*@ loop unroll 3; */
    for (int32_t k = 1; k <= 3; k++) {
        /*@ loop unroll MN; */
        for (uint32_t s = 0; s < MN; s++) {
            vor_point_t step = {motion_sites[s].x + 3 * k, motion_sites[s].y - 2 * k};
            r |= vor_move(&d, s, step, &id);
        }
    }
    r |= vor_validate(&d, &violation);
    return r;
}
