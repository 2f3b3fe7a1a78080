/* SPDX-License-Identifier: MIT */
/* bench/size/geometry.c - build and nearest, plus the Voronoi geometry:
 * clipped cells, their centroids and edges. */
#include "common.h"

static vor_point_t points[SIZE_SITES];
static vor_point_t cell[VOR_CELL_MAX_VERTICES(SIZE_SITES)];
static uint8_t centroid_scratch[VOR_CENTROID_SCRATCH_BYTES(16)];

SIZE_ARENA(size_arena);

int main(void)
{
    vor_t d;
    uint32_t site = 0, count = 0;
    size_points(points);
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    acc |= vor_build(&d, points, SIZE_SITES, NULL, NULL);
    acc |= vor_nearest(&d, (vor_point_t){size_x(0), size_y(1)}, VOR_NO_HINT, &site);
    vor_box_t box = {size_x(2), size_y(2), size_x(3), size_y(3)};
    vor_cell_iter_t cells;
    vor_cells_begin(&cells, &d, &box);
    while (vor_cells_next(&cells, &site, cell, VOR_CELL_MAX_VERTICES(SIZE_SITES), &count) > 0) {
        acc += (int)count;
    }
    vor_centroid_t centroid;
    acc |= vor_cell_centroid(&d, site, &box, centroid_scratch, sizeof centroid_scratch, &centroid);
    vor_edge_iter_t edges;
    vor_edge_t edge;
    vor_edges_begin(&edges, &d);
    while (vor_edges_next(&edges, &edge) > 0) {
        acc++;
    }
    return acc;
}
