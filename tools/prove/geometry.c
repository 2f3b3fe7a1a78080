/* SPDX-License-Identifier: MIT */
/*
 * geometry.c - the harness of `make prove` for the Voronoi geometry:
 * vor_circumcentre, vor_voronoi_vertex, the edge and cell iterators,
 * vor_cell and vor_cell_centroid. The diagrams are small and concrete;
 * every point, box corner, id and capacity is anywhere in its type, and
 * every pointer the header allows to be NULL is NULL or not.
 */
#include <__fc_builtin.h>

#include "vor.h"

/* 6 points, 5 sites: four cocircular (0 to 3, on the circle of centre
 * (5, 5)), a duplicate (4 repeats 0) and one far away (5), beyond the
 * tracker's 2^30 reach and where vertices round out of int32. Then three
 * collinear sites, one site and none: each shape the calls tell apart. */
#define N 6u
static const vor_point_t points[N] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0},
                                      {INT32_MIN, INT32_MAX}};
static const vor_point_t collinear[3] = {{0, 0}, {10, 0}, {20, 0}};

static uint32_t arena[(VOR_ARENA_BYTES(N) + 3u) / 4u];
static uint64_t scratch[(VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(N)) + 7u) / 8u];

static uint32_t any_u32(void)
{
    return Frama_C_unsigned_int_interval(0u, UINT32_MAX);
}

/* a site id or anything else: in range most of the time, as a caller's */
static uint32_t any_id(void)
{
    return any_u32();
}

static vor_point_t any_point(void)
{
    vor_point_t p;
    p.x = Frama_C_interval(INT32_MIN, INT32_MAX);
    p.y = Frama_C_interval(INT32_MIN, INT32_MAX);
    return p;
}

static vor_box_t any_box(void)
{
    vor_box_t b;
    b.x0 = Frama_C_interval(INT32_MIN, INT32_MAX);
    b.y0 = Frama_C_interval(INT32_MIN, INT32_MAX);
    b.x1 = Frama_C_interval(INT32_MIN, INT32_MAX);
    b.y1 = Frama_C_interval(INT32_MIN, INT32_MAX);
    return b;
}

static int iterate(const vor_t *d)
{
    vor_triangle_iter_t ti;
    vor_vertex_t vertex;
    vor_edge_iter_t ei;
    vor_cell_iter_t ci;
    vor_edge_t edge;
    vor_box_t box = any_box();
    vor_point_t vertices[VOR_CELL_MAX_VERTICES(N)];
    uint32_t ids[3], site, count;
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
    r |= vor_cells_begin(NULL, d, &box);
    r |= vor_cells_begin(&ci, Frama_C_nondet_ptr((void *)d, NULL), Frama_C_nondet_ptr(&box, NULL));
    while (vor_cells_next(&ci, Frama_C_nondet_ptr(&site, NULL), Frama_C_nondet_ptr(vertices, NULL),
                          Frama_C_unsigned_int_interval(0u, VOR_CELL_MAX_VERTICES(N)), &count)) {
    }
    r |= vor_cells_error(Frama_C_nondet_ptr(&ci, NULL));
    r |= vor_edges_next(NULL, &edge) | vor_cells_next(NULL, &site, vertices, 0u, &count);
    return r;
}

static int geometry(const vor_t *d)
{
    vor_vertex_t vertex;
    vor_centroid_t centroid;
    vor_box_t box = any_box();
    vor_point_t vertices[VOR_CELL_MAX_VERTICES(N)];
    uint32_t count;
    int r = 0;

    r |= vor_circumcentre(any_point(), any_point(), any_point(), Frama_C_nondet_ptr(&vertex, NULL));
    r |= vor_voronoi_vertex(Frama_C_nondet_ptr((void *)d, NULL), any_id(), any_id(), any_id(),
                            Frama_C_nondet_ptr(&vertex, NULL));
    r |= vor_cell(Frama_C_nondet_ptr((void *)d, NULL), any_id(), Frama_C_nondet_ptr(&box, NULL),
                  Frama_C_nondet_ptr(vertices, NULL),
                  Frama_C_unsigned_int_interval(0u, VOR_CELL_MAX_VERTICES(N)),
                  Frama_C_nondet_ptr(&count, NULL));
    r |= vor_cell_centroid(Frama_C_nondet_ptr((void *)d, NULL), any_id(),
                           Frama_C_nondet_ptr(&box, NULL), Frama_C_nondet_ptr(scratch, NULL),
                           Frama_C_unsigned_int_interval(0u, sizeof scratch),
                           Frama_C_nondet_ptr(&centroid, NULL));
    return r;
}

int main(void)
{
    vor_t d;
    int r = 0;

    d.revision = any_u32();
    if (vor_init(&d, arena, sizeof arena, N) != VOR_OK) {
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
