/* SPDX-License-Identifier: MIT */
/*
 * power_cells.c - the harness of `make prove` for the power cells:
 * vor_power_cell and vor_power_cell_centroid. The sites of far_sites.h
 * with concrete weights: the four cocircular ones with weights linear in
 * the position (their lifted points stay on one plane: the tie, and the
 * zero-length edge it leaves), then with unequal weights (the bisectors
 * moved off every integer point, the parallel-line test through their
 * foot), the duplicate of 0 heavier (0 hidden) and the far site with the
 * widest weights (its bisectors' c near 2^66); then three collinear sites
 * and one. Each site in each box of far_sites.h, every capacity from 0 to
 * what a cell needs, the centroid's scratch aligned at a fixed address
 * (prove.sh) and too small; any other id, and each pointer the header
 * allows to be NULL, NULL in turn. Concrete arguments, one call at a time
 * (unrolled), so that EVA follows each cell's trace and sums exactly.
 */
#include <__fc_builtin.h>

#include "far_sites.h"
#include "vor_power.h"

#define CAP VOR_CELL_MAX_VERTICES(N)
#define SCRATCH_BYTES VOR_CENTROID_SCRATCH_BYTES(CAP)
#define scratch FIXED_SCRATCH /* far_sites.h */

#define WEIGHTINGS 2u
static const int64_t weights[WEIGHTINGS][N] = {
    {0, 20, 40, 20, 0, INT64_MIN},
    {7, -30, 55, 0, 100, INT64_MAX},
};
static const int64_t line_weights[3] = {0, 50, -50};

static uint64_t power_arena[VOR_POWER_ARENA_BYTES(N) / 8u + 1u];

static int cells(const vor_power_t *pd)
{
    vor_point_t vertices[CAP];
    vor_centroid_t centroid;
    uint32_t count;
    int r = 0;
    /*@ loop unroll BOXES; */
    for (unsigned b = 0; b < BOXES; b++) {
        /*@ loop unroll N; */
        for (uint32_t s = 0; s < N; s++) {
            /* no room (count only), too little, enough */
            r |= vor_power_cell(pd, s, &boxes[b], NULL, 0u, &count);
            r |= vor_power_cell(pd, s, &boxes[b], vertices, 3u, &count);
            r |= vor_power_cell(pd, s, &boxes[b], vertices, CAP, &count);
            r |= vor_power_cell_centroid(pd, s, &boxes[b], scratch, SCRATCH_BYTES, &centroid);
            r |= vor_power_cell_centroid(pd, s, &boxes[b], scratch, 40u, &centroid);
        }
    }
    r |= vor_power_cell(pd, Frama_C_unsigned_int_interval(N, UINT32_MAX), &boxes[0], vertices, CAP,
                        &count);
    r |= vor_power_cell_centroid(pd, Frama_C_unsigned_int_interval(N, UINT32_MAX), &boxes[0],
                                 scratch, SCRATCH_BYTES, &centroid);
    r |= vor_power_cell(NULL, 0u, &boxes[0], vertices, CAP, &count);
    r |= vor_power_cell(pd, 0u, NULL, vertices, CAP, &count);
    r |= vor_power_cell(pd, 0u, &boxes[0], NULL, 1u, &count);
    r |= vor_power_cell(pd, 0u, &boxes[0], vertices, CAP, NULL);
    r |= vor_power_cell_centroid(NULL, 0u, &boxes[0], scratch, SCRATCH_BYTES, &centroid);
    r |= vor_power_cell_centroid(pd, 0u, NULL, scratch, SCRATCH_BYTES, &centroid);
    r |= vor_power_cell_centroid(pd, 0u, &boxes[0], NULL, SCRATCH_BYTES, &centroid);
    r |= vor_power_cell_centroid(pd, 0u, &boxes[0], scratch, SCRATCH_BYTES, NULL);
    return r;
}

int main(void)
{
    vor_power_t pd;
    int r = 0;
    pd.mesh.revision = 0u; /* vor_power_init reads it */
    if (vor_power_init(&pd, power_arena, sizeof power_arena, N) != VOR_OK) {
        return 1;
    }
    r |= cells(&pd); /* no site: every id refused */
    /*@ loop unroll WEIGHTINGS; */
    for (unsigned k = 0; k < WEIGHTINGS; k++) {
        r |= vor_power_build(&pd, points, weights[k], N, NULL);
        r |= cells(&pd);
    }
    r |= vor_power_build(&pd, collinear, line_weights, 3u, NULL);
    r |= cells(&pd);
    r |= vor_power_build(&pd, points, weights[0], 1u, NULL);
    r |= cells(&pd);
    return r;
}
