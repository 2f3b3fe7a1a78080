/* SPDX-License-Identifier: MIT */
/* counters.c - the library's predicate counters (VOR_STATS), summed for the
 * tests. Apart from harness.c, which the harness self-tests link without
 * the library. */
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
