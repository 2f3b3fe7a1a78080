/* SPDX-License-Identifier: MIT */
/*
 * bench/size/common.h - what the feature-set firmwares of `make size`
 * share. Each program calls one set of public functions on inputs the
 * compiler cannot see through (volatile), so that the linker keeps exactly
 * what a firmware using that feature set keeps; tools/size-features.sh
 * sums the library's bytes in the linked image.
 */
#ifndef SIZE_COMMON_H
#define SIZE_COMMON_H

#include "vor.h"

#define SIZE_SITES 64u

/* The arena of a diagram of SIZE_SITES sites, for the programs that have one. */
#define SIZE_ARENA(name) \
    static uint8_t name[VOR_ARENA_BYTES(SIZE_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)))

static volatile int32_t size_input[2 * SIZE_SITES];

static inline int32_t size_x(uint32_t i) { return size_input[2u * i]; }
static inline int32_t size_y(uint32_t i) { return size_input[2u * i + 1u]; }

/* The SIZE_SITES sites of the input. */
static inline void size_points(vor_point_t *points)
{
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        points[i].x = size_x(i);
        points[i].y = size_y(i);
    }
}

/* An L-shaped room of SIZE_L_ROOM vertices, counterclockwise, in the box
 * (x0, y0) - (x1, y1) of the input's sites 2 and 3: the room the clipping
 * programs cut cells by. */
#define SIZE_L_ROOM 6u
static inline void size_l_room(vor_point_t *room)
{
    int32_t x0 = size_x(2), y0 = size_y(2), x1 = size_x(3), y1 = size_y(3);
    int32_t xs[SIZE_L_ROOM] = {x0, x1, x1, x1 / 2, x1 / 2, x0};
    int32_t ys[SIZE_L_ROOM] = {y0, y0, y1 / 2, y1 / 2, y1, y1};
    for (uint32_t i = 0; i < SIZE_L_ROOM; i++) {
        room[i].x = xs[i];
        room[i].y = ys[i];
    }
}

#endif
