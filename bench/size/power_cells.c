/* SPDX-License-Identifier: MIT */
/* bench/size/power_cells.c - the power program's calls (vor_power_build,
 * vor_power_insert, the hidden sites and the triangles) plus the power
 * cells: vor_power_cell and vor_power_cell_centroid, as a firmware that
 * runs capacity-constrained Lloyd steps does. */
#include "common.h"
#include "vor_power.h"

static vor_point_t points[SIZE_SITES];
static int64_t weights[SIZE_SITES];
static uint32_t ids[3];
static vor_point_t cell[VOR_CELL_MAX_VERTICES(SIZE_SITES)];
static uint8_t centroid_scratch[VOR_CENTROID_SCRATCH_BYTES(16)];

static uint8_t size_power_arena[VOR_POWER_ARENA_BYTES(SIZE_SITES)]
    __attribute__((aligned(VOR_POWER_ARENA_ALIGN)));

int main(void)
{
    vor_power_t pd;
    uint32_t site = 0, count = 0;
    size_points(points);
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        weights[i] = (int64_t)size_x(i) * size_y(i);
    }
    int acc = vor_power_init(&pd, size_power_arena, sizeof size_power_arena, SIZE_SITES);
    acc |= vor_power_build(&pd, points, weights, SIZE_SITES / 2u, NULL);
    acc |= vor_power_insert(&pd, (vor_point_t){size_x(1), size_y(1)}, size_x(2), &site);
    vor_power_hidden_iter_t hidden;
    vor_power_hidden_begin(&hidden, &pd);
    while (vor_power_hidden_next(&hidden, &site) > 0) {
        acc += vor_power_hidden(&pd, site);
    }
    vor_triangle_iter_t triangles;
    vor_power_triangles_begin(&triangles, &pd);
    while (vor_triangles_next(&triangles, ids) > 0) {
        acc++;
    }
    vor_box_t box = {size_x(2), size_y(2), size_x(3), size_y(3)};
    acc |= vor_power_cell(&pd, site, &box, cell, VOR_CELL_MAX_VERTICES(SIZE_SITES), &count);
    vor_centroid_t centroid;
    acc |= vor_power_cell_centroid(&pd, site, &box, centroid_scratch, sizeof centroid_scratch,
                                   &centroid);
    return acc + (int)count + centroid.point.x;
}
