/* SPDX-License-Identifier: MIT */
/*
 * predicates.c - the harness of `make prove` for the exact predicates:
 * Frama-C's EVA runs main() with every coordinate anywhere in int32 and
 * every index anywhere in the array, so the analysis covers each call's
 * whole documented domain at once (no sampling). An alarm means some
 * input of that domain may reach undefined behaviour.
 */
#include <__fc_builtin.h>

#include "vor.h"

#include "inputs.h"

/* Enough sites for every order of the indices of vor_incircle_sos (four
 * distinct ones), plus room for equal indices (the rejected calls). */
#define SITES 5

static uint32_t any_index(void)
{
    return (uint32_t)Frama_C_interval(0, SITES - 1);
}

int main(void)
{
    vor_point_t a = any_point(), b = any_point(), c = any_point(), d = any_point();
    /* one by one, not in a loop, so EVA sees each site set */
    vor_point_t sites[SITES] = {any_point(), any_point(), any_point(), any_point(),
                                any_point()};
    int r = vor_orient2d(a, b, c);
    r |= vor_incircle(a, b, c, d);
    r |= vor_closer(a, b, c);
    r |= vor_orient2d_sos(sites, any_index(), any_index(), any_index());
    r |= vor_incircle_sos(sites, any_index(), any_index(), any_index(), any_index());
    r |= vor_closer_sos(sites, any_index(), any_index(), any_index());
    r |= vor_power_test(a, any_weight(), b, any_weight(), c, any_weight(), d, any_weight());
    r |= vor_power_closer(a, b, any_weight(), c, any_weight());
    int64_t weights[SITES] = {any_weight(), any_weight(), any_weight(), any_weight(),
                              any_weight()};
    r |= vor_power_test_sos(sites, weights, any_index(), any_index(), any_index(),
                            any_index());
    /* NULL is a documented bad argument: 0, no access */
    r |= vor_orient2d_sos(NULL, 0, 1, 2);
    r |= vor_incircle_sos(NULL, 0, 1, 2, 3);
    r |= vor_closer_sos(NULL, 0, 1, 2);
    r |= vor_power_test_sos(NULL, weights, 0, 1, 2, 3);
    r |= vor_power_test_sos(sites, NULL, 0, 1, 2, 3);
    return r;
}
