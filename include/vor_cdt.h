/* SPDX-License-Identifier: MIT */
/*
 * vor_cdt.h - constraints: the constrained Delaunay triangulation of a
 * diagram's sites, kept beside the diagram in caller memory.
 *
 * The diagram (vor.h) stays the Delaunay triangulation and Voronoi diagram
 * of its sites, so every query of vor.h (nearest sites, cells, centroids,
 * the tracker, the motion cache) keeps answering for the sites alone.
 * Attaching constraint memory adds a second triangulation of the same
 * sites, kept up to date by every vor_insert; vor_constrain makes a
 * segment between two sites a chain of its edges, and the iterators here
 * read it: every edge that is not constrained is locally Delaunay.
 *
 *     // 500 sites, 512 constrained edges, 64 crossings, cuts of 1002
 *     static uint8_t walls[VOR_CDT_BYTES(500, 512, 64, 1002)]
 *         __attribute__((aligned(VOR_CDT_ALIGN)));
 *     static const vor_cdt_limits_t limits = {512, 64, 1002};
 *     vor_cdt_attach(&d, walls, sizeof walls, &limits);  // after vor_init
 *     vor_constrain(&d, door_left, corner);
 *     vor_cdt_triangle_iter_t it;
 *     uint32_t ids[3];                  // ids >= max_sites: crossings
 *     vor_cdt_triangles_begin(&it, &d);
 *     while (vor_cdt_triangles_next(&it, ids)) { ... }
 *
 * A constraint through a site is split there; collinear constraints that
 * overlap share their edges. The iterators follow vor.h's convention:
 * x_begin returns VOR_OK or VOR_ERR_ARG (it NULL, d NULL or without
 * constraint memory; the iterator then yields nothing), x_next returns 1
 * with an item or 0 at the end.
 */
#ifndef VOR_CDT_H
#define VOR_CDT_H

#include <stdbool.h>

#include "vor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A constrained edge's entry in the edge table: its two vertices and the
 * number of constraints through it. A crossing vertex's entry: the four
 * sites of its two lines. */
#define VOR_CDT_EDGE_BYTES ((2u * sizeof(vor_index_t)) + 4u)
#define VOR_CDT_CROSSING_BYTES (4u * sizeof(vor_index_t))

/* The part of the memory that holds the state (a constant, checked
 * against the library's layout when it is built). */
#define VOR_CDT_HEADER_BYTES (sizeof(vor_t) + (6u * sizeof(void *)) + (8u * sizeof(uint32_t)))

/* Bytes of constraint memory for a diagram of up to n sites (its
 * max_sites), up to `edges` constrained edges (a constraint counts one
 * edge for each piece the sites and crossings on it split it into), up to
 * `crossings` crossing vertices, and constraints crossing up to `cut`
 * triangles between two vertices on them (2n + 2 crossings always
 * suffices); a constant expression. */
#define VOR_CDT_BYTES(n, edges, crossings, cut)                                \
    ((size_t)VOR_CDT_HEADER_BYTES +                                            \
     (VOR__CDT_SLOTS((size_t)(n) + (crossings)) * (VOR_TRIANGLE_BYTES + 1u)) + \
     (2u * (size_t)(edges) * VOR_CDT_EDGE_BYTES) +                             \
     ((size_t)(crossings) * VOR_CDT_CROSSING_BYTES) +                          \
     (13u * ((size_t)(cut) + 4u) * sizeof(vor_index_t)) + 4u)
/* triangle slots of v vertices: 2 v - 2 */
#define VOR__CDT_SLOTS(v) (((v) >= 2u) ? ((2u * (v)) - 2u) : 0u)
#define VOR_CDT_ALIGN 4u

/* The limits vor_cdt_attach sizes the memory by (VOR_CDT_BYTES). */
typedef struct vor_cdt_limits {
    uint32_t edges;     /* constrained edges, at least 1 */
    uint32_t crossings; /* crossing vertices */
    uint32_t cut;       /* triangles a constraint crosses between two of its vertices */
} vor_cdt_limits_t;

/*
 * Attaches constraint memory mem[0 .. bytes) to d, sized by *limits. The
 * constrained triangulation starts as d's Delaunay triangulation, without
 * constraints.
 *   VOR_ERR_ARG    d, mem or limits NULL, limits->edges 0, or a limit
 *                  beyond use: crossings that with d's max_sites exceed
 *                  VOR_MAX_SITES vertices, more edges than 3 a vertex, a
 *                  cut beyond 2 a vertex + 2
 *   VOR_ERR_ALIGN  mem not aligned to VOR_CDT_ALIGN
 *   VOR_ERR_NOMEM  bytes < VOR_CDT_BYTES(max_sites of d, edges, crossings, cut)
 * On failure nothing changes. Cost: a copy of d's triangles.
 */
int vor_cdt_attach(vor_t *d, void *mem, size_t bytes, const vor_cdt_limits_t *limits);

/*
 * The crossing vertex `id` (ids from d's max_sites on, as the triangle
 * iterator reports them): the sites a, b, c, d of the two constraints'
 * lines a-b and c-d it lies on, in sites[0..4). Its exact coordinates are
 * X / W and Y / W for W = (b - a) x (d - c), X = a.x W + (b.x - a.x) T,
 * Y = a.y W + (b.y - a.y) T, T = (c - a) x (d - c).
 *   VOR_ERR_ARG  d or sites NULL, or id no crossing vertex of d
 */
int vor_cdt_crossing(const vor_t *d, uint32_t id, uint32_t sites[4]);

/*
 * Constrains the segment between sites a and b: afterwards it is a chain
 * of edges of the constrained triangulation, split at every site on it and
 * at every point where it crosses another constraint, which becomes a
 * crossing vertex held exactly (vor_cdt_crossing); a third constraint
 * through that point splits there too.
 * a == b (or the same point) does nothing.
 *   VOR_ERR_ARG    d NULL, no constraint memory attached, a or b not a
 *                  site in the diagram
 *   VOR_ERR_NOMEM  the edge table or the crossing table would overflow,
 *                  or the segment crosses more than limits->cut - 2
 *                  triangles between two consecutive points where it
 *                  meets a vertex or crosses a constraint (cut - 1 when
 *                  the second is a vertex): each crossing vertex made at
 *                  an end of such a stretch adds a triangle to it
 * On failure nothing changes.
 */
int vor_constrain(vor_t *d, uint32_t a, uint32_t b);

/*
 * Removes one constraint along the segment between sites a and b (either
 * order): every piece of it loses one of the constraints through it, and
 * the pieces left with none become plain edges again. A crossing vertex
 * left on one constraint's line disappears, the two pieces through it
 * joined; one on two or more stays. The triangulation is again the
 * constrained Delaunay one of what remains.
 *   VOR_ERR_ARG  d NULL, no constraint memory attached, a or b not a site
 *                in the diagram, or some piece of the segment from a to b
 *                not constrained (nothing changes)
 */
int vor_unconstrain(vor_t *d, uint32_t a, uint32_t b);

/* The triangles of the constrained triangulation, counterclockwise, of
 * nonzero area (as vor_triangles_next for the Delaunay one). */
typedef struct vor_cdt_triangle_iter {
    const vor_t *d;
    uint32_t slot;
    bool inside; /* only the domain's (vor_cdt_inside_begin) */
} vor_cdt_triangle_iter_t;

/*   VOR_ERR_ARG  it or d NULL, or no constraint memory attached */
int vor_cdt_triangles_begin(vor_cdt_triangle_iter_t *it, const vor_t *d);
/* 1 and the next triangle's vertex ids in ids, or 0 at the end (and for a
 * NULL argument or an iterator whose begin failed). */
int vor_cdt_triangles_next(vor_cdt_triangle_iter_t *it, uint32_t ids[3]);

/*
 * Marks the domain: the triangles inside the constraints by the even-odd
 * rule, as a polygon's inside without its holes, overlapping polygons by
 * parity. Flooding from the outside of the hull, a triangle's nesting
 * level is the least number of constraints crossed to reach it (an edge
 * under k constraints counts k); it is inside when that number is odd.
 * Levels beyond 126 count as 126. Any later change of the triangulation
 * (a site, a constraint) clears the marks.
 *   VOR_ERR_ARG  d NULL, or no constraint memory attached
 */
int vor_cdt_domain(vor_t *d);

/* The triangles inside the domain (vor_cdt_domain), as the iterator above.
 *   VOR_ERR_ARG  it or d NULL, no constraint memory, or no domain marked
 *                since the last change */
int vor_cdt_inside_begin(vor_cdt_triangle_iter_t *it, const vor_t *d);

/* The constrained edges, in no particular order. */
typedef struct vor_cdt_edge_iter {
    const vor_t *d;
    uint32_t entry;
} vor_cdt_edge_iter_t;

/*   VOR_ERR_ARG  it or d NULL, or no constraint memory attached */
int vor_cdt_edges_begin(vor_cdt_edge_iter_t *it, const vor_t *d);
/* 1 and the next constrained edge's vertex ids (a < b; crossings from
 * max_sites on), or 0 at the end (and for a NULL argument or an iterator
 * whose begin failed). */
int vor_cdt_edges_next(vor_cdt_edge_iter_t *it, uint32_t *a, uint32_t *b);

#ifdef __cplusplus
}
#endif

#endif
