/* SPDX-License-Identifier: MIT */
/*
 * centroid.c - the harness of `make prove` for vor_cell_centroid: every
 * site of each small concrete diagram in each box of cells.c, with the
 * scratch VOR_CENTROID_SCRATCH_BYTES gives (aligned) and with a misaligned
 * one too small; site 0 in the first box at every other alignment; then
 * any other id, any scratch size below one limb and each pointer the
 * header allows to be NULL, NULL in turn. Each call has concrete
 * arguments but for those (unrolled), so that EVA follows each cell's
 * trace and sums exactly.
 */
#include <__fc_builtin.h>

#include "far_sites.h"

/* The scratch at a fixed address (prove.sh declares the range valid):
 * the call aligns it from its address as an integer, which EVA knows for
 * an absolute address only (for a variable's, any value, and every sum's
 * place with it). 0x10000 is aligned; 0x10001 to 0x10003 are not (3 to
 * 1 bytes skipped, with 32-bit limbs): every address's alignment. */
#define SCRATCH_BYTES VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(N))
#define scratch ((uint64_t *)0x10000u)

static int centroids(const vor_t *d)
{
    vor_centroid_t centroid;
    int r = 0;
    /*@ loop unroll BOXES; */
    for (unsigned b = 0; b < BOXES; b++) {
        /*@ loop unroll N; */
        for (uint32_t s = 0; s < N; s++) {
            r |= vor_cell_centroid(d, s, &boxes[b], scratch, SCRATCH_BYTES, &centroid);
            r |= vor_cell_centroid(d, s, &boxes[b], (unsigned char *)scratch + 1, 40u, &centroid);
        }
    }
    /* every other alignment (1 to 3 bytes past a limb's), with room */
    /*@ loop unroll 3; */
    for (unsigned a = 1; a < 4u; a++) {
        r |= vor_cell_centroid(d, 0u, &boxes[0], (unsigned char *)scratch + a, SCRATCH_BYTES - a,
                               &centroid);
    }
    /* any other id, any scratch size below one limb, and each NULL the
     * header lists, one at a time */
    r |= vor_cell_centroid(d, Frama_C_unsigned_int_interval(N, UINT32_MAX), &boxes[0], scratch,
                           SCRATCH_BYTES, &centroid);
    r |= vor_cell_centroid(d, 0u, &boxes[0], scratch, Frama_C_unsigned_int_interval(0u, 7u),
                           &centroid);
    r |= vor_cell_centroid(NULL, 0u, &boxes[0], scratch, SCRATCH_BYTES, &centroid);
    r |= vor_cell_centroid(d, 0u, NULL, scratch, SCRATCH_BYTES, &centroid);
    r |= vor_cell_centroid(d, 0u, &boxes[0], NULL, SCRATCH_BYTES, &centroid);
    r |= vor_cell_centroid(d, 0u, &boxes[0], NULL, 0u, &centroid);
    r |= vor_cell_centroid(d, 0u, &boxes[0], scratch, SCRATCH_BYTES, NULL);
    return r;
}

int main(void)
{
    vor_t d;
    int r = 0;
    d.revision = 0u;
    if (vor_init(&d, arena, sizeof arena, N) != VOR_OK) {
        return 1;
    }
    r |= vor_build(&d, points, 1u, NULL, NULL);
    r |= centroids(&d);
    r |= vor_build(&d, collinear, 3u, NULL, NULL);
    r |= centroids(&d);
    r |= vor_build(&d, points, N, NULL, NULL);
    r |= centroids(&d);
    return r;
}
