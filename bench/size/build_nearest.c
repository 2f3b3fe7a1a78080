/* SPDX-License-Identifier: MIT */
/* bench/size/build_nearest.c - the batch build (incremental, quadtree
 * order) and nearest-site queries. */
#include "common.h"

static vor_point_t points[SIZE_SITES];

SIZE_ARENA(size_arena);

int main(void)
{
    vor_t d;
    uint32_t site = 0;
    size_points(points);
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    acc |= vor_build(&d, points, SIZE_SITES, NULL, NULL);
    acc |= vor_nearest(&d, (vor_point_t){size_x(0), size_y(1)}, VOR_NO_HINT, &site);
    return acc + (int)site;
}
