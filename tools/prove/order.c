/* SPDX-License-Identifier: MIT */
/*
 * order.c - the harness of `make prove` for vor_order_cell_begin,
 * vor_order_cells_begin, vor_order_cells_next and vor_order_cells_error:
 * on each small concrete diagram of far_sites.h, the walk over the
 * order-2 cells of an L room around the sites (each cell's pieces read
 * and its centroid taken), the single call for a set given backwards;
 * then a room that crosses itself, a store of one set, a scratch too
 * small, any order and id that is no site, any scratch size below what
 * the call needs,
 * and each pointer the header allows to be NULL, NULL in turn. Each call
 * has concrete arguments but for those, so that EVA follows each
 * clipping and each step of the walk exactly.
 */
#include <__fc_builtin.h>

#include "far_sites.h"

#define MOST_ROOM 6u
static const vor_point_t room[MOST_ROOM] = {{-5, -5}, {15, -5}, {15, 5}, {5, 5}, {5, 15}, {-5, 15}};
static const vor_point_t bowtie[4] = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};

/* The scratches at fixed addresses (far_sites.h): the cell's, then the
 * sums' past it. */
#define ORDER_BYTES VOR_ORDER_SCRATCH_BYTES(MOST_ROOM, N, 2u)
#define SUMS_BYTES VOR_CLIP_CENTROID_SCRATCH_BYTES(MOST_ROOM, 2u * N)
#define order_scratch FIXED_SCRATCH
#define sums ((uint64_t *)0x18000u)
#define MOST_SETS VOR_ORDER_MAX_CELLS(N, 2u)

static uint32_t sets[VOR_ORDER_SETS_WORDS(MOST_SETS, 2u)];
static vor_exact_point_t piece[VOR_CLIP_MAX_VERTICES(MOST_ROOM, 2u * N)];

static int pieces_of(vor_clip_t *clip)
{
    uint32_t count = 0;
    vor_centroid_t c;
    int r = 0;
    uint32_t k = 0;
    /*@ loop unroll VOR_CLIP_MAX_VERTICES(MOST_ROOM, 2u * N); */
    while (vor_clip_next(clip, piece, VOR_CLIP_MAX_VERTICES(MOST_ROOM, 2u * N), &count) == 1) {
        r |= vor_clip_centroid(clip, k, sums, SUMS_BYTES, &c);
        k++;
    }
    r |= vor_clip_centroid(clip, VOR_CLIP_WHOLE, sums, SUMS_BYTES, &c);
    return r | vor_clip_error(clip);
}

static int orders(const vor_t *d)
{
    vor_order_iter_t it;
    vor_clip_t clip;
    uint32_t set[2] = {0u, 1u};
    int r = 0;
    if (vor_order_cells_begin(&it, d, 2u, room, MOST_ROOM, sets, (uint32_t)MOST_SETS,
                              order_scratch, ORDER_BYTES) == VOR_OK) {
        /*@ loop unroll MOST_SETS; */
        while (vor_order_cells_next(&it, set, &clip) == 1) {
            r |= pieces_of(&clip);
        }
        r |= vor_order_cells_error(&it);
        /* the last set met, given backwards, in the single call */
        uint32_t backwards[2] = {set[1], set[0]};
        if (vor_order_cell_begin(&clip, d, backwards, 2u, room, MOST_ROOM, order_scratch,
                                 ORDER_BYTES) == VOR_OK) {
            r |= pieces_of(&clip);
        }
    }
    /* errors: a bad room, a store of one set, a scratch too small, any
     * order, any id, any short scratch, each NULL */
    r |= vor_order_cells_begin(&it, d, 2u, bowtie, 4u, sets, (uint32_t)MOST_SETS, order_scratch,
                               ORDER_BYTES);
    r |= vor_order_cells_next(&it, set, &clip);
    if (vor_order_cells_begin(&it, d, 2u, room, MOST_ROOM, sets, 1u, order_scratch, ORDER_BYTES) ==
        VOR_OK) {
        /*@ loop unroll 2; */
        while (vor_order_cells_next(&it, set, &clip) == 1) {
        }
        r |= vor_order_cells_error(&it);
    }
    if (vor_order_cells_begin(&it, d, 2u, room, MOST_ROOM, sets, (uint32_t)MOST_SETS,
                              order_scratch, Frama_C_unsigned_int_interval(0u, 64u)) == VOR_OK) {
        r |= vor_order_cells_next(&it, set, &clip);
    }
    r |= vor_order_cells_begin(&it, d, 0u, room, MOST_ROOM, sets, (uint32_t)MOST_SETS,
                               order_scratch, ORDER_BYTES);
    r |= vor_order_cells_begin(&it, d, Frama_C_unsigned_int_interval(N - 1u, UINT32_MAX), room,
                               MOST_ROOM, sets, (uint32_t)MOST_SETS, order_scratch, ORDER_BYTES);
    r |= vor_order_cells_begin(NULL, d, 2u, room, MOST_ROOM, sets, 4u, order_scratch, ORDER_BYTES);
    r |= vor_order_cells_begin(&it, NULL, 2u, room, MOST_ROOM, sets, 4u, order_scratch, ORDER_BYTES);
    r |= vor_order_cells_begin(&it, d, 2u, NULL, MOST_ROOM, sets, 4u, order_scratch, ORDER_BYTES);
    r |= vor_order_cells_begin(&it, d, 2u, room, MOST_ROOM, NULL, 4u, order_scratch, ORDER_BYTES);
    r |= vor_order_cells_begin(&it, d, 2u, room, MOST_ROOM, sets, 4u, NULL, ORDER_BYTES);
    r |= vor_order_cells_next(NULL, set, &clip);
    r |= vor_order_cells_next(&it, NULL, &clip);
    r |= vor_order_cells_next(&it, set, NULL);
    r |= vor_order_cells_error(NULL);
    /* ids and orders only where they are errors: a valid value among
     * them would merge with the others and blur the clipping */
    uint32_t any[2] = {0u, Frama_C_unsigned_int_interval(N, UINT32_MAX)};
    r |= vor_order_cell_begin(&clip, d, any, 2u, room, MOST_ROOM, order_scratch, ORDER_BYTES);
    uint32_t first[2] = {0u, 1u};
    r |= vor_order_cell_begin(&clip, d, first, Frama_C_unsigned_int_interval(N - 1u, UINT32_MAX), room,
                              MOST_ROOM, order_scratch, ORDER_BYTES);
    r |= vor_order_cell_begin(&clip, d, first, 2u, room, MOST_ROOM, order_scratch,
                              Frama_C_unsigned_int_interval(0u, 64u));
    r |= vor_order_cell_begin(&clip, d, first, 2u, room, MOST_ROOM,
                              (unsigned char *)order_scratch + 1, ORDER_BYTES - 1u);
    r |= vor_order_cell_begin(&clip, d, first, 2u, bowtie, 4u, order_scratch, ORDER_BYTES);
    r |= vor_order_cell_begin(NULL, d, first, 2u, room, MOST_ROOM, order_scratch, ORDER_BYTES);
    r |= vor_order_cell_begin(&clip, NULL, first, 2u, room, MOST_ROOM, order_scratch, ORDER_BYTES);
    r |= vor_order_cell_begin(&clip, d, NULL, 2u, room, MOST_ROOM, order_scratch, ORDER_BYTES);
    r |= vor_order_cell_begin(&clip, d, first, 2u, NULL, MOST_ROOM, order_scratch, ORDER_BYTES);
    r |= vor_order_cell_begin(&clip, d, first, 2u, room, MOST_ROOM, NULL, ORDER_BYTES);
    return r;
}

int main(void)
{
    return far_sites_each(0u, false, N, orders);
}
