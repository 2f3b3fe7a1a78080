/* SPDX-License-Identifier: MIT */
/*
 * vor_power.h - weighted sites: the power diagram and its dual, the
 * regular triangulation, in an arena the caller provides.
 *
 * Site i is a point p_i with an int64 weight w_i; the power distance of a
 * point q to it is |q - p_i|^2 - w_i (a weight r^2 makes the site a circle
 * of radius r). The power cell of a site is where it is the nearest in
 * power distance; a site whose cell is empty is hidden: it is kept, with
 * its id, but it is not a vertex of the triangulation. Hidden is a normal
 * state, not an error: a heavy site can hide its light neighbours, and
 * an insertion can hide sites inserted before it.
 *
 *     // up to 500 weighted sites
 *     static uint8_t arena[VOR_POWER_ARENA_BYTES(500)]
 *         __attribute__((aligned(VOR_POWER_ARENA_ALIGN)));
 *     vor_power_t pd;
 *     vor_power_init(&pd, arena, sizeof arena, 500);
 *     uint32_t id;
 *     vor_power_insert(&pd, (vor_point_t){10, 20}, 900, &id); // r = 30
 *     vor_triangle_iter_t it;
 *     uint32_t ids[3];
 *     vor_power_triangles_begin(&it, &pd);
 *     while (vor_triangles_next(&it, ids)) { ... }  // counterclockwise
 *     vor_power_hidden_iter_t h;
 *     vor_power_hidden_begin(&h, &pd);
 *     while (vor_power_hidden_next(&h, &id)) { ... }
 *     // the power cell of id in a box, and its centroid (Lloyd)
 *     vor_box_t box = {0, 0, 1000, 1000};
 *     vor_point_t poly[VOR_CELL_MAX_VERTICES(500)];
 *     uint32_t m;
 *     vor_power_cell(&pd, id, &box, poly, VOR_CELL_MAX_VERTICES(500), &m);
 *     static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(500))];
 *     vor_centroid_t c;
 *     vor_power_cell_centroid(&pd, id, &box, scratch, sizeof scratch, &c);
 *     vor_power_move(&pd, id, (vor_point_t){12, 20}, 400, NULL); // same id
 *     vor_power_nearest(&pd, q, VOR_NO_HINT, &id); // least |q-p|^2 - w
 *     vor_power_remove(&pd, id);                   // id freed for reuse
 *
 * Exactness: every decision is an exact predicate of vor.h
 * (vor_power_test, vor_orient2d) over the whole int32 range of
 * coordinates and the whole int64 range of weights; ties are broken by
 * the symbolic perturbation of the sites (vor.h), which keeps the
 * weights. A site whose power cell is empty is always hidden and one
 * whose cell has area is always a vertex: where the perturbation alone
 * would keep an empty cell as a sliver at infinity (sites on the hull's
 * boundary, sites on one line), the exact answer is taken. Sites at the
 * same point: the largest weight is the vertex (the smallest id among
 * equal largest weights), every other weight there is hidden, since its
 * power distance is larger everywhere by a constant. Where four or more
 * lifted sites (x, y, x^2 + y^2 - w) lie on one plane, the triangulation
 * is not unique and the perturbation picks one; a site whose cell has no
 * area (its lifted point on the surface, not a corner of it) may be
 * either, and when it is a vertex it may be in no triangle (it then lies
 * on the hull's boundary). The triangle iterator reports, as for the
 * Delaunay triangulation, only triangles of nonzero area, and they form
 * a triangulation: every edge is on two of them or on the hull, never
 * with a vertex inside it.
 *
 * Errors, iterators and configuration follow vor.h.
 */
#ifndef VOR_POWER_H
#define VOR_POWER_H

#include <stdbool.h>

#include "vor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Arena bytes for up to n weighted sites (a constant expression): the
 * weights, then a diagram's arena (VOR_ARENA_BYTES). */
#define VOR_POWER_ARENA_BYTES(n) (((size_t)(n) * sizeof(int64_t)) + VOR_ARENA_BYTES(n))
/* The arena's alignment: the weights are int64_t. */
#define VOR_POWER_ARENA_ALIGN 8u

/* The power diagram object: owned by the caller, fields private. */
typedef struct vor_power {
    vor_t mesh;            /* the regular triangulation of the sites */
    int64_t *weights;      /* [max_sites], in the arena */
    uint32_t hidden_count; /* sites not in the triangulation (duplicates aside) */
    uint32_t first_hidden; /* the hidden ids' list: first id plus one, 0: none */
    bool area;             /* a triangle of nonzero area exists (not all collinear) */
    bool flats;            /* a triangle of zero area may exist (degenerate input) */
} vor_power_t;

/*
 * Prepares pd to hold up to max_sites weighted sites in arena.
 *   VOR_ERR_CONFIG the library was compiled with other vor_config.h
 *                  options than this file (checked first)
 *   VOR_ERR_ARG    pd or arena NULL, max_sites 0 or > VOR_MAX_SITES
 *   VOR_ERR_ALIGN  arena not aligned to VOR_POWER_ARENA_ALIGN
 *   VOR_ERR_NOMEM  arena_bytes < VOR_POWER_ARENA_BYTES(max_sites)
 * Writes only *pd, and nothing on failure. vor_power_init_checked is the
 * library's symbol: the inline vor_power_init passes it the
 * application's VOR_CONFIG_FINGERPRINT.
 */
int vor_power_init_checked(vor_power_t *pd, void *arena, size_t arena_bytes,
                           uint32_t max_sites, uint32_t config);
static inline int vor_power_init(vor_power_t *pd, void *arena, size_t arena_bytes,
                                 uint32_t max_sites)
{
    return vor_power_init_checked(pd, arena, arena_bytes, max_sites, VOR_CONFIG_FINGERPRINT);
}

/*
 * Adds the site p with weight w; its id goes to *site (may be NULL): the
 * most recently freed id (vor_power_remove) if there is one, else the
 * next unused. The site may be hidden at once (vor_power_hidden), and
 * it may hide sites that were vertices; the triangulation is afterwards
 * the regular triangulation of all the sites.
 *   VOR_ERR_ARG        pd NULL
 *   VOR_ERR_DUPLICATE  a site (a vertex or hidden) has the same point
 *                      and weight: its id goes to *site (the smallest
 *                      such id; also when full)
 *   VOR_ERR_FULL       max_sites ids are used
 * On failure nothing changes.
 * Cost: the walk from the last inserted site plus O(changed triangles);
 * telling a duplicate costs a look at the hidden sites when p is hidden,
 * and at every id when p's power test ties or p lies on the hull's line;
 * while every site so far is on one line, an insertion looks at every
 * id (the diagram is one-dimensional then).
 */
int vor_power_insert(vor_power_t *pd, vor_point_t p, int64_t w, uint32_t *site);

/*
 * Builds the regular triangulation of points[0..n) with weights[0..n),
 * replacing what pd held; ids are input positions. duplicate_of (may be
 * NULL) gets, for each i, the smallest id with the same point and weight
 * (i itself for all but duplicates).
 *   VOR_ERR_ARG   pd NULL, or points or weights NULL with n > 0
 *   VOR_ERR_FULL  n > max_sites (nothing changes)
 * Uses the arena's triangle space as scratch: no other memory. Cost:
 * expected O(n log n) for sites spread over a region (the insertion order
 * of vor_build, VOR_ORDER_QUADTREE); O(n^2) when every site is on one
 * line.
 */
int vor_power_build(vor_power_t *pd, const vor_point_t *points, const int64_t *weights,
                    uint32_t n, uint32_t *duplicate_of);

/*
 * Removes site `site`, a vertex or hidden; the triangulation is afterwards
 * the regular triangulation of the other sites, exactly as a fresh
 * insertion of them gives: the hidden sites whose power cells the removal
 * opens become vertices (a removed vertex's neighbourhood is the only
 * place where that can happen). The other sites keep their ids; `site`
 * becomes free, and the next vor_power_insert reuses the most recently
 * freed id (as vor_remove and vor_insert). Ids vor_power_build gave to
 * duplicates stay reserved: they are not sites.
 *   VOR_ERR_ARG  pd NULL, or site not a site (an unused or free id, a
 *                duplicate's id from vor_power_build)
 * On failure nothing changes.
 * Cost: a hidden site: a look along the hidden list. A vertex: the
 * removal's ears (vor_remove's, with the power test), a look along the
 * hidden list for those in the box of the vertex and its neighbours, and
 * an insertion of each of them; while every vertex is on one line (and
 * when a hull vertex leaves, its neighbours have no triangle of area) a
 * look at every id.
 */
int vor_power_remove(vor_power_t *pd, uint32_t site);

/*
 * Moves site `site` (a vertex or hidden) to the point p with weight w,
 * keeping its id: a removal and an insertion, whose result is the regular
 * triangulation of the sites as they are afterwards. Moving a site to its
 * own point and weight is VOR_OK and changes nothing.
 *   VOR_ERR_ARG        pd NULL, or site not a site (as vor_power_remove)
 *   VOR_ERR_DUPLICATE  another site has the point p and the weight w: its
 *                      id goes to *existing (may be NULL; the smallest)
 * On failure nothing changes.
 * Cost: a look at every id for a duplicate, then vor_power_remove's and
 * vor_power_insert's.
 */
int vor_power_move(vor_power_t *pd, uint32_t site, vor_point_t p, int64_t w,
                   uint32_t *existing);

/*
 * The site of least power distance |q - p|^2 - w to q, any int32 point,
 * exactly (vor_power_closer); of several as near, the smallest id. A
 * hidden site is never strictly nearer than every vertex but may tie, and
 * is then answered when its id is smaller. hint: a site to start from (the
 * previous answer; a hidden one starts from the bucket grid), or
 * VOR_NO_HINT (the bucket grid's site for q).
 *   VOR_ERR_ARG    pd or site NULL, hint neither VOR_NO_HINT nor a site
 *                  (an unused or free id, a duplicate's id)
 *   VOR_ERR_EMPTY  the diagram has no sites
 * On failure nothing is written.
 * Cost: a walk from vertex to strictly nearer neighbour, O(1) steps for a
 * hint near the answer; a look along the hidden list; a look at every id
 * when two vertices tie for the least, or every vertex is on one line.
 */
int vor_power_nearest(const vor_power_t *pd, vor_point_t q, uint32_t hint, uint32_t *site);

/*
 * 1 when `site` is hidden, 0 when it is a vertex of the triangulation.
 *   VOR_ERR_ARG  pd NULL, or site not an id handed out, a free id (removed),
 *                or a duplicate's
 */
int vor_power_hidden(const vor_power_t *pd, uint32_t site);

/* The hidden sites, most recently hidden first. */
typedef struct vor_power_hidden_iter {
    const vor_power_t *pd;
    uint32_t next; /* the next id plus one, 0: the end */
} vor_power_hidden_iter_t;

/*   VOR_ERR_ARG  it or pd NULL (the iterator then yields nothing) */
int vor_power_hidden_begin(vor_power_hidden_iter_t *it, const vor_power_t *pd);
/* 1 and the next hidden id in *site, or 0 at the end (and for a NULL
 * argument or an iterator whose begin failed). */
int vor_power_hidden_next(vor_power_hidden_iter_t *it, uint32_t *site);

/* The triangles of the regular triangulation, read with
 * vor_triangles_next (vor.h): counterclockwise, of nonzero area.
 *   VOR_ERR_ARG  it or pd NULL (the iterator then yields nothing) */
int vor_power_triangles_begin(vor_triangle_iter_t *it, const vor_power_t *pd);

/*
 * The power cell of `site` clipped to `box`, as vor_cell (vor.h) gives a
 * Voronoi cell: its vertices counterclockwise from the lowest (smallest
 * y, then smallest x) in vertices[0 .. *count), each computed exactly and
 * rounded once to the nearest integer point (halves toward +infinity),
 * exact coincidences written once; *count = 0 when the cell meets the box
 * in less than an area, for a box of zero width or height, and for a
 * hidden site (its cell is empty). A site's power cell need not contain
 * the site. VOR_CELL_MAX_VERTICES(n) vertices always suffice. Every
 * int32 coordinate and int64 weight: the vertices are exact rationals
 * of up to 99-bit numerators over 65-bit denominators.
 * Cost: O(neighbours of the site).
 *   VOR_ERR_ARG     pd, box or count NULL; vertices NULL with capacity >
 *                   0; box->x0 > box->x1 or box->y0 > box->y1; site not
 *                   an id handed out, or a duplicate's
 *   VOR_ERR_BUFFER  more than `capacity` vertices: *count = the number
 *                   needed, nothing written to vertices
 */
int vor_power_cell(const vor_power_t *pd, uint32_t site, const vor_box_t *box,
                   vor_point_t *vertices, uint32_t capacity, uint32_t *count);

/*
 * The area and centroid of the power cell of `site` clipped to `box`, as
 * vor_cell_centroid (vor.h) gives them for a Voronoi cell: exact, in the
 * caller's scratch (VOR_CENTROID_SCRATCH_BYTES(k) for k vertices, any
 * alignment), each rounded once: for capacity-constrained Lloyd
 * relaxation, move the site to out->point. A cell with no area in the
 * box, and a hidden site's, give area 0, vertices 0 and point = the point
 * of the box nearest the site.
 * Cost: O(neighbours + k^2) limb products for a cell of k vertices.
 *   VOR_ERR_ARG     pd, box or out NULL; scratch NULL with scratch_bytes
 *                   > 0; box->x0 > box->x1 or box->y0 > box->y1; site not
 *                   an id handed out, or a duplicate's
 *   VOR_ERR_BUFFER  the scratch cannot hold the sums of the cell's k
 *                   vertices: only out->vertices is written, with k
 */
int vor_power_cell_centroid(const vor_power_t *pd, uint32_t site, const vor_box_t *box,
                            void *scratch, size_t scratch_bytes, vor_centroid_t *out);

/*
 * Checks the regular triangulation's invariants (vor_validate's, with
 * the power test for local regularity), and that every hidden site lies
 * under the hull with its lifted point on or above the triangulation.
 *   VOR_ERR_ARG      pd NULL
 *   VOR_ERR_INVALID  an invariant is broken: *violation (may be NULL)
 *                    says which (vor.h)
 * Cost: O(n) predicates, and a walk for each hidden site.
 */
int vor_power_validate(const vor_power_t *pd, vor_violation_t *violation);

#ifdef __cplusplus
}
#endif

#endif
