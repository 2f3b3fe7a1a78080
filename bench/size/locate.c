/* SPDX-License-Identifier: MIT */
/* bench/size/locate.c - the batch build and the queries robots ask: the
 * triangle holding a point (vor_locate), the sites within a distance
 * (vor_within) and the flat export (vor_triangles_export). */
#include "common.h"

static vor_point_t points[SIZE_SITES];
static uint32_t ids[SIZE_SITES];
static uint32_t triangles[3u * VOR_TRIANGLES_MAX(SIZE_SITES)];
static uint32_t halfedges[3u * VOR_TRIANGLES_MAX(SIZE_SITES)];

SIZE_ARENA(size_arena);

int main(void)
{
    vor_t d;
    uint32_t tri[3] = {0, 0, 0};
    uint32_t found = 0;
    uint32_t count = 0;
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        points[i].x = size_x(i);
        points[i].y = size_y(i);
    }
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    acc |= vor_build(&d, points, SIZE_SITES, NULL, NULL);
    vor_point_t q = {size_x(0), size_y(1)};
    acc |= vor_locate(&d, q, VOR_NO_HINT, tri);
    acc |= vor_within(&d, q, (uint64_t)(uint32_t)size_x(2), tri[0], ids, SIZE_SITES, &found);
    acc |= vor_triangles_export(&d, triangles, halfedges, VOR_TRIANGLES_MAX(SIZE_SITES), &count);
    return acc + (int)(tri[1] + found + count + ids[0] + halfedges[0]);
}
