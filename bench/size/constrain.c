/* SPDX-License-Identifier: MIT */
/* bench/size/constrain.c - the batch build and constraints: vor_build,
 * vor_cdt_attach and vor_constrain (crossing segments included), as a
 * firmware that walls off parts of its map does. */
#include "common.h"
#include "vor_cdt.h"

#define SIZE_EDGES (3u * SIZE_SITES)
#define SIZE_CROSSINGS SIZE_SITES
#define SIZE_CUT ((2u * (SIZE_SITES + SIZE_CROSSINGS)) + 2u)

static vor_point_t points[SIZE_SITES];

SIZE_ARENA(size_arena);
static uint8_t size_walls[VOR_CDT_BYTES(SIZE_SITES, SIZE_EDGES, SIZE_CROSSINGS, SIZE_CUT)]
    __attribute__((aligned(VOR_CDT_ALIGN)));

int main(void)
{
    vor_t d;
    vor_cdt_limits_t limits = {SIZE_EDGES, SIZE_CROSSINGS, SIZE_CUT};
    size_points(points);
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    acc |= vor_build(&d, points, SIZE_SITES, NULL, NULL);
    acc |= vor_cdt_attach(&d, size_walls, sizeof size_walls, &limits);
    acc |= vor_constrain(&d, (uint32_t)size_x(2), (uint32_t)size_y(2));
    return acc;
}
