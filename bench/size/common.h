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

#endif
