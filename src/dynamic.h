/* SPDX-License-Identifier: MIT */
/*
 * dynamic.h - removing and moving sites (dynamic.c), private to the
 * library: what the tests reach directly.
 */
#ifndef VOR_DYNAMIC_H
#define VOR_DYNAMIC_H

#include "mesh.h"

/* Removal's last step: home slot h lost its triangle and `start` holds
 * another of h's; the packed slots run to `last`, one triangle too many.
 * Refills slot h and packs the slots again (the proof is in dynamic.c). */
void vor__rehome(vor_t *d, vor_index_t h, vor_index_t start, vor_index_t last);

/* Moves the triangle in slot `from` to the unused slot `to` (meshes of
 * three or more sites: its neighbours are three distinct triangles). */
void vor__move_triangle(vor__tri_t *tri, vor_index_t from, vor_index_t to);

/* The last step of a removal, and the 3-1 flip of a regular
 * triangulation (power.c): vertex p has degree three, its triangles
 * (p, nb[i], nb[i + 1]) in slots sl[i] (indices mod 3, counterclockwise,
 * p's home slot among them) merge into (nb[0], nb[1], nb[2]), and the
 * slots are packed again. Meshes of four or more vertices; the vertex
 * count still counts p, whose home slot is left to the caller. */
void vor__merge_three(vor_t *d, vor_index_t p, const vor_index_t nb[3], const vor_index_t sl[3]);

/* Takes site `site` (in the mesh) out of d's mesh, its home slot left
 * to the caller (power.c keeps the id, as a hidden site's); the vertex
 * count drops by one. Returns a former neighbour of it (itself when it
 * was the only site). */
uint32_t vor__unlink_vertex(vor_t *d, uint32_t site);

/* Takes site `site` (in the mesh) out of d's mesh and frees its id; the
 * vertex count drops by one. Returns a former neighbour of it (itself
 * when it was the only site). The bucket grid, the last site and the
 * revision are the caller's (vor_remove; the constrained mesh, cdt.c). */
uint32_t vor__unlink_site(vor_t *d, uint32_t site);

/* Puts id p on the free list (vor_insert takes the most recent first);
 * its home slot (p no vertex) links the list. */
void vor__free_id(vor_t *d, uint32_t p);

/* The upkeep once vertex `site` left the mesh (vor__unlink_vertex gave
 * `other`): the bucket grid forgets it, the last site moves off it, the
 * revision and the motion cache's epoch change (vor_remove,
 * vor_power_remove). */
void vor__unlinked(vor_t *d, uint32_t site, uint32_t other);

#endif
