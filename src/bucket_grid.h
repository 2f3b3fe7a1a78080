/* SPDX-License-Identifier: MIT */
/*
 * bucket_grid.h - the bucket grid (bucket_grid.c), private to the library:
 * a coarse grid over the sites' box whose buckets each name a site inside
 * or near them, where walks (queries, insertions without a hint) start.
 */
#ifndef VOR_BUCKET_GRID_H
#define VOR_BUCKET_GRID_H

#include "vor.h"

/* The bucket grid (bucket_grid.c), for meshes of two or more sites:
 * vor__grid_rebuild draws it over the bounding box and fills it;
 * vor__grid_add records a site just inserted (and redraws the grid when
 * the site count has doubled); vor__grid_start is a site near (x, y). */
void vor__grid_rebuild(vor_t *d);
void vor__grid_add(vor_t *d, uint32_t site);
uint32_t vor__grid_start(const vor_t *d, int32_t x, int32_t y);
/* Site `site` (coordinates still those the grid knows) leaves the grid:
 * its entries go to a neighbouring run's site, or to `fallback` (a site
 * in the mesh) when it named every bucket. */
void vor__grid_forget(vor_t *d, uint32_t site, uint32_t fallback);
/* Site `site`, now at its new coordinates, was at `from`. */
void vor__grid_move(vor_t *d, uint32_t site, vor_point_t from, uint32_t fallback);

#endif
