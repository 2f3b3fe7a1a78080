/* SPDX-License-Identifier: MIT */
/* bench/size/move.c - insertion, vor_move and nearest-site queries, with
 * no motion cache attached (vor_motion_attach is never called): moving
 * sites, as a firmware that tracks robots without a cache does. */
#include "common.h"

SIZE_ARENA(size_arena);

int main(void)
{
    vor_t d;
    uint32_t site = 0;
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        acc |= vor_insert(&d, (vor_point_t){size_x(i), size_y(i)}, &site);
    }
    acc |= vor_move(&d, site, (vor_point_t){size_x(1), size_y(0)}, &site);
    acc |= vor_nearest(&d, (vor_point_t){size_x(0), size_y(1)}, VOR_NO_HINT, &site);
    return acc + (int)site;
}
