/* SPDX-License-Identifier: MIT */
/*
 * cdt.h - the constrained triangulation's state, private to the library:
 * a second mesh of the diagram's sites in the caller's constraint memory
 * (vor_cdt_attach), and the table of its constrained edges. The mesh is a
 * vor_t of its own that shares the diagram's coordinates, so the mesh
 * code (mesh.h, incremental.c) runs on it unchanged; only the insertion's
 * flips ask the table first (vor__cdt_constrained).
 */
#ifndef VOR_CDT_PRIVATE_H
#define VOR_CDT_PRIVATE_H

#include <stdbool.h>

#include "mesh.h"
#include "multiword.h"
#include "vor.h"
#include "vor_cdt.h"

/* A constrained edge u < v and the number of constraints through it; u
 * is VOR__NONE in an empty entry. */
typedef struct vor__cdt_edge {
    vor_index_t u;
    vor_index_t v;
    uint32_t count;
} vor__cdt_edge_t;

typedef char vor__cdt_edge_size_check[(sizeof(vor__cdt_edge_t) == VOR_CDT_EDGE_BYTES) ? 1 : -1];

/* The constrained triangulation's mesh is a vor_t whose vertex ids are the
 * diagram's site ids, 0 .. first_crossing - 1 (its max_sites), and the
 * crossing vertices' from first_crossing on, each with a home slot: the
 * mesh's own max_sites is first_crossing + max_crossings, and its
 * site_count that too, unused ids having empty home slots. */
struct vor__cdt {
    vor_t mesh;                /* the constrained triangulation (first: cdt.c casts) */
    vor__cdt_edge_t *edges;    /* [edge_slots], open addressing */
    uint32_t edge_slots;       /* 2 max_edges: the table at most half full */
    uint32_t edge_count;
    uint32_t max_edges;
    vor_index_t *crossings;    /* [4 max_crossings]: the sites a, b, c, d of
                                  crossing first_crossing + i; VOR__NONE in
                                  crossings[4 i] when id is free */
    uint32_t first_crossing;
    uint32_t max_crossings;
    uint32_t crossing_count;
    vor_index_t *scratch;      /* [13 (max_cut + 4)], one piece's cavity */
    uint32_t max_cut;
    uint8_t *levels;           /* [triangle slots]: the domain's nesting levels */
    bool domain;               /* levels hold the current triangulation's */
};

/* The first slot to probe for edge u-v (u < v): a multiplicative hash
 * mapped onto the table by a multiply (no division). */
static inline uint32_t vor__cdt_home(const struct vor__cdt *c, vor_index_t u, vor_index_t v)
{
    uint32_t h = ((uint32_t)u * 0x9E3779B1u) ^ ((uint32_t)v * 0x85EBCA77u);
    h ^= h >> 15;
    return (uint32_t)(vor__mul_u32(h, c->edge_slots) >> 32);
}

/* The entry of edge a-b (either order), or edge_slots when absent. */
static inline uint32_t vor__cdt_find(const struct vor__cdt *c, vor_index_t a, vor_index_t b)
{
    vor_index_t u = (a < b) ? a : b;
    vor_index_t v = (a < b) ? b : a;
    uint32_t i = vor__cdt_home(c, u, v);
    for (uint32_t probes = 0; probes < c->edge_slots; probes++) {
        const vor__cdt_edge_t *e = &c->edges[i];
        if (e->u == VOR__NONE) {
            break;
        }
        if ((e->u == u) && (e->v == v)) {
            return i;
        }
        i = ((i + 1u) == c->edge_slots) ? 0u : (i + 1u);
    }
    return c->edge_slots;
}

/* Is the mesh edge a-b constrained? (The insertion's flips never cross one.) */
static inline bool vor__cdt_constrained(const struct vor__cdt *c, vor_index_t a, vor_index_t b)
{
    return vor__cdt_find(c, a, b) != c->edge_slots;
}

/* The upkeep vor_cdt_attach stores in d (d->cdt_update), for the events
 * of mesh.h (VOR__CDT_*). */
int vor__cdt_update(vor_t *d, uint32_t p, unsigned event);

/* Places vertex p of the constrained triangulation from triangle `root`,
 * which holds it, never flipping a constrained edge (incremental.c). */
void vor__insert_at_constrained(vor_t *mesh, vor_index_t root, uint32_t p,
                                struct vor__cdt *c);

/* Does the triangle (v0, v1, v2) of the constrained mesh (a triangle at
 * infinity too) conflict with vertex p, under the perturbation? As
 * vor__conflicts, for vertices that may be crossings (cdt.c). */
bool vor__cdt_conflicts(struct vor__cdt *c, vor_index_t v0, vor_index_t v1, vor_index_t v2,
                        uint32_t p);

#endif
