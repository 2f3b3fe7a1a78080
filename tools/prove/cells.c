/* SPDX-License-Identifier: MIT */
/*
 * cells.c - the harness of `make prove` for the cells clipped to a box:
 * vor_cells_begin, vor_cells_next, vor_cells_error (and through them
 * vor_cell). The diagrams are small and concrete, and so are the boxes
 * (one around the sites, one inside the cocircular ones, the whole int32
 * plane, a flat one and an inverted one): with any box corner, the exact
 * divisions that round each vertex keep hundreds of states. Every
 * capacity up to what a cell needs, and every pointer the header allows
 * to be NULL, NULL or not.
 */
#include <__fc_builtin.h>

#include "far_sites.h"

static int iterate(const vor_t *d)
{
    vor_cell_iter_t ci;
    vor_point_t vertices[VOR_CELL_MAX_VERTICES(N)];
    uint32_t site, count;
    int r = 0;
    /*@ loop unroll BOXES; */
    for (unsigned b = 0; b < BOXES; b++) {
        r |= vor_cells_begin(&ci, Frama_C_nondet_ptr((void *)d, NULL),
                             Frama_C_nondet_ptr((void *)&boxes[b], NULL));
        while (
            vor_cells_next(&ci, Frama_C_nondet_ptr(&site, NULL), Frama_C_nondet_ptr(vertices, NULL),
                           Frama_C_unsigned_int_interval(0u, VOR_CELL_MAX_VERTICES(N)), &count)) {
        }
        r |= vor_cells_error(Frama_C_nondet_ptr(&ci, NULL));
    }
    return r;
}

int main(void)
{
    vor_t d;
    int r = 0;
    d.revision = Frama_C_unsigned_int_interval(0u, UINT32_MAX);
    if (vor_init(&d, arena, sizeof arena, N) != VOR_OK) {
        return 1;
    }
    r |= iterate(&d);
    r |= vor_build(&d, points, 1u, NULL, NULL);
    r |= iterate(&d);
    r |= vor_build(&d, collinear, 3u, NULL, NULL);
    r |= iterate(&d);
    r |= vor_build(&d, points, N, NULL, NULL);
    r |= iterate(&d);
    return r;
}
