/* SPDX-License-Identifier: MIT */
/*
 * queries.c - the harness of `make prove` for the calls that read a
 * diagram's topology: vor_nearest, the tracker and the iterators over
 * triangles, neighbours and the hull (nearest_k.c has vor_nearest_k,
 * geometry.c the Voronoi geometry). The diagrams are small and concrete;
 * every query point is anywhere in int32, every hint and id anywhere in
 * uint32 (each site's id in turn, then any other value), and every
 * pointer the header allows to be NULL is NULL or not.
 */
#include "far_sites.h"
#include "inputs.h"

static int iterate(const vor_t *d)
{
    vor_triangle_iter_t ti;
    vor_neighbour_iter_t ni;
    vor_hull_iter_t hi;
    uint32_t ids[3], site;
    int r = 0;

    /* a NULL iterator: nothing done; a NULL diagram: the iterator closed */
    r |= vor_triangles_begin(NULL, d);
    r |= vor_triangles_begin(&ti, Frama_C_nondet_ptr((void *)d, NULL));
    while (vor_triangles_next(&ti, Frama_C_nondet_ptr(ids, NULL))) {
    }
    r |= vor_neighbours_begin(NULL, d, any_u32());
    r |= vor_neighbours_begin(&ni, NULL, any_u32());
    r |= vor_neighbours_next(&ni, &site);
    /* each site's neighbours, then any other id's */
    /*@ loop unroll N + 1; */
    for (uint32_t i = 0; i <= N; i++) {
        r |= vor_neighbours_begin(&ni, d, id_or_any(i, N));
        while (vor_neighbours_next(&ni, Frama_C_nondet_ptr(&site, NULL))) {
        }
    }
    r |= vor_hull_begin(NULL, d);
    r |= vor_hull_begin(&hi, Frama_C_nondet_ptr((void *)d, NULL));
    while (vor_hull_next(&hi, Frama_C_nondet_ptr(&site, NULL))) {
    }
    r |= vor_hull_next(NULL, &site);
    return r;
}

static int nearest(const vor_t *d)
{
    vor_tracker_t tracker;
    uint32_t site;
    int r = 0;

    r |= vor_nearest(NULL, any_point(), any_u32(), &site);
    r |= vor_nearest(d, any_point(), any_u32(), NULL);
    /* from each hint: each site's id, then any other value */
    /*@ loop unroll N + 1; */
    for (uint32_t h = 0; h <= N; h++) {
        r |= vor_nearest(d, any_point(), id_or_any(h, N), &site);
    }
    r |= vor_tracker_begin_checked(Frama_C_nondet_ptr(&tracker, NULL),
                                   Frama_C_nondet_ptr((void *)d, NULL), any_u32());
    if (vor_tracker_begin(&tracker, d) == VOR_OK) {
        r |= vor_track(&tracker, any_point(), &site); /* from anywhere */
    }
    /* from the cell cached at each answer (unrolled: a non-relational
     * analysis would mix one cell's bounds with another's position), on
     * to anywhere */
    /*@ loop unroll N; */
    for (uint32_t s = 0; s < N; s++) {
        if (vor_tracker_begin(&tracker, d) == VOR_OK &&
            vor_track(&tracker, points[s], &site) == VOR_OK) {
            r |= vor_track(&tracker, any_point(), Frama_C_nondet_ptr(&site, NULL));
        }
    }
    r |= vor_track(NULL, any_point(), &site);
    return r;
}

int main(void)
{
    vor_t d;
    int r = 0;

    if (far_sites_init(&d) != VOR_OK) {
        return 1;
    }
    /* an empty diagram, one site, then all of them */
    r |= nearest(&d);
    r |= iterate(&d);
    r |= vor_build(&d, points, 1u, NULL, NULL);
    r |= iterate(&d);
    r |= vor_build(&d, collinear, 3u, NULL, NULL);
    r |= nearest(&d);
    r |= iterate(&d);
    r |= vor_build(&d, points, N, NULL, NULL);
    r |= nearest(&d);
    r |= iterate(&d);
    return r;
}
