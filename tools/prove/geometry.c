/* SPDX-License-Identifier: MIT */
/*
 * geometry.c - the harness of `make prove` for the Voronoi vertices and
 * edges: vor_circumcentre, vor_voronoi_vertex and the edge iterator
 * (cells.c has the cells, centroid.c the centroids). The diagrams are
 * small and concrete; every point and id is anywhere in its type, and
 * every pointer the header allows to be NULL is NULL or not.
 */
#include "far_sites.h"
#include "inputs.h"

/* a site id or anything else: in range most of the time, as a caller's */
static uint32_t any_id(void)
{
    return any_u32();
}

static int iterate(const vor_t *d)
{
    vor_triangle_iter_t ti;
    vor_vertex_t vertex;
    vor_edge_iter_t ei;
    vor_edge_t edge;
    uint32_t ids[3];
    int r = 0;

    /* a NULL iterator: nothing done; a NULL diagram: the iterator closed */
    r |= vor_triangles_begin(&ti, d);
    while (vor_triangles_next(&ti, ids)) {
        r |= vor_voronoi_vertex(d, ids[0], ids[1], ids[2], &vertex);
    }
    r |= vor_edges_begin(NULL, d);
    r |= vor_edges_begin(&ei, Frama_C_nondet_ptr((void *)d, NULL));
    while (vor_edges_next(&ei, Frama_C_nondet_ptr(&edge, NULL))) {
    }
    r |= vor_edges_next(NULL, &edge);
    return r;
}

static int geometry(const vor_t *d)
{
    vor_vertex_t vertex;
    int r = 0;

    r |= vor_circumcentre(any_point(), any_point(), any_point(), Frama_C_nondet_ptr(&vertex, NULL));
    r |= vor_voronoi_vertex(Frama_C_nondet_ptr((void *)d, NULL), any_id(), any_id(), any_id(),
                            Frama_C_nondet_ptr(&vertex, NULL));
    return r;
}

int main(void)
{
    vor_t d;
    int r = 0;

    if (far_sites_init(&d) != VOR_OK) {
        return 1;
    }
    /* an empty diagram, one site, collinear sites, then all of them */
    r |= iterate(&d);
    r |= vor_build(&d, points, 1u, NULL, NULL);
    r |= iterate(&d);
    r |= geometry(&d);
    r |= vor_build(&d, collinear, 3u, NULL, NULL);
    r |= iterate(&d);
    r |= geometry(&d);
    r |= vor_build(&d, points, N, NULL, NULL);
    r |= iterate(&d);
    r |= geometry(&d);
    return r;
}
