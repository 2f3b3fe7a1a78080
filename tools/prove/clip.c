/* SPDX-License-Identifier: MIT */
/*
 * clip.c - the harness of `make prove` for vor_clip_begin, vor_clip_next,
 * vor_clip_error and vor_clip_centroid: every site of each small concrete
 * diagram of far_sites.h clipped to each room (an L around the sites, a
 * U whose arms cut cells in two, a triangle over the whole int32 plane),
 * each piece read with a buffer too small and then one large enough, its
 * centroid and the whole's; a room that crosses itself; then any other
 * id, any scratch size below what the call needs, and each pointer the
 * header allows to be NULL, NULL in turn. Each call has concrete
 * arguments but for those, so that EVA follows each clipping exactly.
 */
#include <__fc_builtin.h>

#include "far_sites.h"

#define ROOMS 3u
#define MOST_ROOM 8u
static const uint32_t room_sizes[ROOMS] = {6u, 8u, 3u};
static const vor_point_t rooms[ROOMS][MOST_ROOM] = {
    {{-5, -5}, {15, -5}, {15, 5}, {5, 5}, {5, 15}, {-5, 15}},
    {{-5, -5}, {15, -5}, {15, 15}, {8, 15}, {8, 2}, {2, 2}, {2, 15}, {-5, 15}},
    {{INT32_MIN, INT32_MIN}, {INT32_MAX, INT32_MIN}, {INT32_MIN, INT32_MAX}},
};
static const vor_point_t bowtie[4] = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};

/* The scratches at fixed addresses (far_sites.h): the pieces', then the
 * sums' past them. */
#define CLIP_BYTES VOR_CLIP_SCRATCH_BYTES(MOST_ROOM, N)
#define SUMS_BYTES VOR_CLIP_CENTROID_SCRATCH_BYTES(MOST_ROOM, N)
#define clip_scratch FIXED_SCRATCH
#define sums ((uint64_t *)0x18000u)

static vor_exact_point_t piece[VOR_CLIP_MAX_VERTICES(MOST_ROOM, N)];

static int pieces_of(vor_clip_t *clip)
{
    uint32_t count = 0;
    vor_centroid_t c;
    int r = 0;
    uint32_t k = 0;
    /* a piece has 3 vertices at least: 2 never fit, and the iterator
     * stays; then the piece with room enough */
    /*@ loop unroll VOR_CLIP_MAX_VERTICES(MOST_ROOM, N); */
    while ((vor_clip_next(clip, piece, 2u, &count) == 0) &&
           (vor_clip_error(clip) == VOR_ERR_BUFFER) &&
           (vor_clip_next(clip, piece, VOR_CLIP_MAX_VERTICES(MOST_ROOM, N), &count) == 1)) {
        r |= vor_clip_centroid(clip, k, sums, SUMS_BYTES, &c);
        k++;
    }
    r |= vor_clip_centroid(clip, VOR_CLIP_WHOLE, sums, SUMS_BYTES, &c);
    r |= vor_clip_centroid(clip, VOR_CLIP_WHOLE, sums, Frama_C_unsigned_int_interval(0u, 7u), &c);
    return r | vor_clip_error(clip);
}

static int clips(const vor_t *d)
{
    vor_clip_t clip;
    vor_centroid_t c;
    uint32_t count;
    int r = 0;
    /* EVA follows each vertex's exact gcd, bit by bit: a few cells per
     * shape (the first site in the L, the U's arms cutting a cell, the
     * far site in the int32 plane) keep the run within minutes */
    if (vor_clip_begin(&clip, d, 0u, rooms[0], room_sizes[0], clip_scratch, CLIP_BYTES) == VOR_OK) {
        r |= pieces_of(&clip);
    }
    if (vor_clip_begin(&clip, d, (d->site_count > 1u) ? 1u : 0u, rooms[1], room_sizes[1], clip_scratch,
                       CLIP_BYTES) == VOR_OK) {
        r |= pieces_of(&clip);
    }
    if (vor_clip_begin(&clip, d, d->site_count - 1u, rooms[2], room_sizes[2], clip_scratch,
                       CLIP_BYTES) == VOR_OK) {
        r |= pieces_of(&clip);
    }
    r |= vor_clip_begin(&clip, d, 0u, bowtie, 4u, clip_scratch, CLIP_BYTES);
    r |= vor_clip_next(&clip, piece, 4u, &count);
    r |= vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, SUMS_BYTES, &c);
    /* any other id, a short or misaligned scratch, and each NULL the
     * header lists, one at a time */
    r |= vor_clip_begin(&clip, d, Frama_C_unsigned_int_interval(N, UINT32_MAX), rooms[0], 6u,
                        clip_scratch, CLIP_BYTES);
    r |= vor_clip_begin(&clip, d, 0u, rooms[0], 6u, clip_scratch,
                        Frama_C_unsigned_int_interval(0u, 64u));
    r |= vor_clip_begin(&clip, d, 0u, rooms[0], 6u, (unsigned char *)clip_scratch + 1,
                        CLIP_BYTES - 1u);
    r |= vor_clip_begin(&clip, d, 0u, rooms[0], Frama_C_unsigned_int_interval(0u, 2u),
                        clip_scratch, CLIP_BYTES);
    r |= vor_clip_begin(NULL, d, 0u, rooms[0], 6u, clip_scratch, CLIP_BYTES);
    r |= vor_clip_begin(&clip, NULL, 0u, rooms[0], 6u, clip_scratch, CLIP_BYTES);
    r |= vor_clip_begin(&clip, d, 0u, NULL, 6u, clip_scratch, CLIP_BYTES);
    r |= vor_clip_begin(&clip, d, 0u, rooms[0], 6u, NULL, CLIP_BYTES);
    r |= vor_clip_begin(&clip, d, 0u, rooms[0], 6u, clip_scratch, CLIP_BYTES);
    r |= vor_clip_next(NULL, piece, 4u, &count);
    r |= vor_clip_next(&clip, NULL, 4u, &count);
    r |= vor_clip_next(&clip, piece, 4u, NULL);
    r |= vor_clip_error(NULL);
    r |= vor_clip_centroid(NULL, 0u, sums, SUMS_BYTES, &c);
    r |= vor_clip_centroid(&clip, 0u, sums, SUMS_BYTES, NULL);
    r |= vor_clip_centroid(&clip, 0u, NULL, SUMS_BYTES, &c);
    r |= vor_clip_centroid(&clip, Frama_C_unsigned_int_interval(1u, UINT32_MAX - 1u), sums,
                           SUMS_BYTES, &c);
    return r;
}

int main(void)
{
    return far_sites_each(0u, false, N, clips);
}
