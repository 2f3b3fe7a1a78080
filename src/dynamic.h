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

/* Takes site `site` (in the mesh) out of d's mesh and frees its id; the
 * vertex count drops by one. Returns a former neighbour of it (itself
 * when it was the only site). The bucket grid, the last site and the
 * revision are the caller's (vor_remove; the constrained mesh, cdt.c). */
uint32_t vor__unlink_site(vor_t *d, uint32_t site);

#endif
