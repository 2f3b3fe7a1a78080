/* SPDX-License-Identifier: MIT */
/* counters.c - what the tests count of the library: its predicate
 * counters (VOR_STATS), summed, and a site's neighbours. Apart from
 * harness.c, which the harness self-tests link without the library. */
#include "test.h"

uint32_t test_predicate_calls(const vor_t *d)
{
    vor_stats_t s;
    if (vor_stats(d, &s) != VOR_OK) {
        return UINT32_MAX; /* a library without VOR_STATS: no count to compare */
    }
    uint32_t n = s.orient2d_perturbed + s.incircle_perturbed + s.closer_perturbed + s.power +
                 s.power_perturbed;
    for (unsigned t = 0; t < VOR_TIERS; t++) {
        n += s.orient2d[t] + s.incircle[t] + s.closer[t];
    }
    return n;
}

uint32_t test_degree(const vor_t *d, uint32_t site)
{
    uint32_t degree = 0;
    uint32_t n;
    vor_neighbour_iter_t it;
    if (vor_neighbours_begin(&it, d, site) != VOR_OK) {
        return 0;
    }
    while (vor_neighbours_next(&it, &n) > 0) {
        degree++;
    }
    return degree;
}
