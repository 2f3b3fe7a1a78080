/* SPDX-License-Identifier: MIT */
/* bench/size/order.c - build, plus the order-2 cells of an L-shaped room:
 * the walk over all of them, every piece read and each cell's centroid
 * (what a robot pair's coverage or a second-nearest map calls). */
#include "common.h"

#define ORDER 2u
static vor_point_t points[SIZE_SITES];
static uint32_t order_scratch[VOR_ORDER_SCRATCH_BYTES(SIZE_L_ROOM, SIZE_SITES, ORDER) / 4u + 1u];
static uint32_t sets[VOR_ORDER_SETS_WORDS(VOR_ORDER_MAX_CELLS(SIZE_SITES, ORDER), ORDER)];
static vor_exact_point_t piece[VOR_CLIP_MAX_VERTICES(SIZE_L_ROOM, SIZE_SITES)];
static uint8_t centroid_scratch[VOR_CENTROID_SCRATCH_BYTES(16)];

SIZE_ARENA(size_arena);

int main(void)
{
    vor_t d;
    uint32_t count = 0;
    size_points(points);
    int acc = vor_init(&d, size_arena, sizeof size_arena, SIZE_SITES);
    acc |= vor_build(&d, points, SIZE_SITES, NULL, NULL);
    vor_point_t room[SIZE_L_ROOM];
    size_l_room(room);
    vor_order_iter_t it;
    vor_clip_t clip;
    uint32_t set[ORDER];
    acc |= vor_order_cells_begin(&it, &d, ORDER, room, SIZE_L_ROOM, sets,
                                 (uint32_t)VOR_ORDER_MAX_CELLS(SIZE_SITES, ORDER), order_scratch,
                                 sizeof order_scratch);
    while (vor_order_cells_next(&it, set, &clip) > 0) {
        while (vor_clip_next(&clip, piece, VOR_CLIP_MAX_VERTICES(SIZE_L_ROOM, SIZE_SITES),
                             &count) > 0) {
            acc += (int)count;
        }
        vor_centroid_t centroid;
        acc |= vor_clip_centroid(&clip, VOR_CLIP_WHOLE, centroid_scratch, sizeof centroid_scratch,
                                 &centroid);
        acc += (int)set[0];
    }
    acc |= vor_order_cells_error(&it);
    return acc;
}
