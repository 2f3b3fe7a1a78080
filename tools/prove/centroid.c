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

/* The scratch at a fixed address (far_sites.h): 0x10001 to 0x10003 skip
 * 3 to 1 bytes, with 32-bit limbs. */
#define SCRATCH_BYTES VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(N))
#define scratch FIXED_SCRATCH

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
    return far_sites_each(0u, false, N, centroids);
}
