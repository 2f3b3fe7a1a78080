/* SPDX-License-Identifier: MIT */
/*
 * nearest_k.c - the harness of `make prove` for vor_nearest_k over the
 * small concrete diagrams of far_sites.h: every query point anywhere in
 * int32, every hint anywhere in uint32 (each site's id in turn, then any
 * other value), each count k from 0 to beyond the
 * sites (and any k with NULL output), every pointer NULL or not.
 */
#include "far_sites.h"
#include "inputs.h"

static int nearest(const vor_t *d)
{
    uint32_t found;
    uint32_t list[N + 1u];
    int r = 0;

    r |= vor_nearest_k(Frama_C_nondet_ptr((void *)d, NULL), any_point(), any_u32(), any_u32(),
                       NULL, &found);
    r |= vor_nearest_k(d, any_point(), any_u32(), 1u, list, NULL);
    /* each count in turn, a count beyond the sites included (how many
     * entries of list[] are written depends on it), from each hint */
    /*@ loop unroll N + 2; */
    for (uint32_t k = 0; k <= N + 1u; k++) {
        /*@ loop unroll N + 1; */
        for (uint32_t h = 0; h <= N; h++) {
            r |= vor_nearest_k(d, any_point(), id_or_any(h, N), k, list, &found);
        }
    }
    return r;
}

int main(void)
{
    vor_t d;
    int r = 0;

    if (far_sites_init(&d) != VOR_OK) {
        return 1;
    }
    /* an empty diagram, three collinear sites, then all of them */
    r |= nearest(&d);
    r |= vor_build(&d, collinear, 3u, NULL, NULL);
    r |= nearest(&d);
    r |= vor_build(&d, points, N, NULL, NULL);
    r |= nearest(&d);
    return r;
}
