/* SPDX-License-Identifier: MIT */
/* bench/size/clip.c - build, plus cells clipped to a polygon room: the
 * pieces of every site's cell in an L-shaped room and their centroids
 * (what a coverage controller in a non-convex room calls). */
#include "common.h"

static vor_point_t points[SIZE_SITES];
static uint32_t clip_scratch[VOR_CLIP_SCRATCH_BYTES(SIZE_L_ROOM, SIZE_SITES) / 4u + 1u];
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
    for (uint32_t s = 0; s < SIZE_SITES; s++) {
        vor_clip_t clip;
        if (vor_clip_begin(&clip, &d, s, room, SIZE_L_ROOM, clip_scratch, sizeof clip_scratch) !=
            VOR_OK) {
            continue;
        }
        while (vor_clip_next(&clip, piece, VOR_CLIP_MAX_VERTICES(SIZE_L_ROOM, SIZE_SITES),
                             &count) > 0) {
            acc += (int)count;
        }
        vor_centroid_t centroid;
        acc |= vor_clip_centroid(&clip, VOR_CLIP_WHOLE, centroid_scratch, sizeof centroid_scratch,
                                 &centroid);
        acc |= vor_clip_error(&clip);
    }
    return acc;
}
