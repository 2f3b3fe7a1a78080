/* SPDX-License-Identifier: MIT */
/* bench/size/insert_nearest.c - incremental insertion and nearest-site
 * queries: the smallest useful firmware. */
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
    acc |= vor_nearest(&d, (vor_point_t){size_x(0), size_y(1)}, VOR_NO_HINT, &site);
    return acc + (int)site;
}
