/* SPDX-License-Identifier: MIT */
/*
 * incremental.h - what the incremental builder (incremental.c) offers the
 * rest of the library: placing a site in the mesh and inserting it.
 */
#ifndef VOR_INCREMENTAL_H
#define VOR_INCREMENTAL_H

#include <stdbool.h>

#include "mesh.h"

/* Places site p in the mesh: returns the slot of the triangle that contains
 * it (a hull triangle when p is outside the hull), walking from slot start.
 * *on_line is set when p lies exactly (unperturbed) on the line of one of
 * that triangle's edges, the only case where p may coincide with a site
 * that is not a vertex of the triangle. Bounded by the number of triangles
 * even if the predicates lie. */
vor_index_t vor__locate(vor_t *d, vor_index_t start, uint32_t p, bool *on_line);

/* Inserts site p (coordinates set, not yet in the mesh, v >= 2 sites
 * present) into the triangle at slot root that contains it. */
void vor__insert_at(vor_t *d, vor_index_t root, uint32_t p);

/* The insertion's first step: splits the triangle in slot `root` into
 * three around site p, which the vertex count does not count yet.
 * Returns the slot of the triangle (p, b, c), b and c the root's second
 * and third vertices; p's home slot holds another of the three. */
vor_index_t vor__split_triangle(vor_t *d, vor_index_t root, uint32_t p);

/* Takes the most recently freed id off the free list (vor__free_id,
 * dynamic.c): the id vor_insert and vor_power_insert hand out next is
 * d->free_site - 1 when free_site is not 0. */
void vor__take_free_id(vor_t *d);

#endif
