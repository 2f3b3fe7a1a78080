/* SPDX-License-Identifier: MIT */
/*
 * cells.c - the harness of `make prove` for the cells clipped to a box:
 * vor_cells_begin, vor_cells_next, vor_cells_error and vor_cell. The
 * diagrams are small and concrete, and so are the boxes (one around the
 * sites, one inside the cocircular ones, the whole int32 plane, a flat
 * one and an inverted one): with any box corner, the exact divisions that
 * round each vertex keep hundreds of states. Each call is made with
 * concrete arguments, one at a time (unrolled), so that EVA follows each
 * cell's trace exactly: every capacity from 0 to what a cell needs, every
 * site id and any other id, and each pointer the header allows to be
 * NULL, NULL in turn.
 */
#include <__fc_builtin.h>

#include "far_sites.h"

#define CAP VOR_CELL_MAX_VERTICES(N)

static int iterate(const vor_t *d)
{
    vor_cell_iter_t ci;
    vor_point_t vertices[CAP];
    uint32_t site, count;
    int r = 0;
    /*@ loop unroll BOXES; */
    for (unsigned b = 0; b < BOXES; b++) {
        /* each capacity, up to one beyond what any cell needs */
        /*@ loop unroll CAP + 1; */
        for (uint32_t capacity = 0; capacity <= CAP; capacity++) {
            r |= vor_cells_begin(&ci, d, &boxes[b]);
            while (vor_cells_next(&ci, &site, (capacity > 0u) ? vertices : NULL, capacity,
                                  &count)) {
            }
            r |= vor_cells_error(&ci);
        }
        /* every id, then any other: vor_cell itself */
        /*@ loop unroll N; */
        for (uint32_t s = 0; s < N; s++) {
            r |= vor_cell(d, s, &boxes[b], vertices, CAP, &count);
        }
        r |= vor_cell(d, Frama_C_unsigned_int_interval(N, UINT32_MAX), &boxes[b], vertices, CAP,
                      &count);
    }
    /* each NULL the header lists, one at a time */
    r |= vor_cells_begin(NULL, d, &boxes[0]);
    r |= vor_cells_begin(&ci, NULL, &boxes[0]);
    r |= vor_cells_next(&ci, &site, vertices, CAP, &count);
    r |= vor_cells_begin(&ci, d, NULL);
    r |= vor_cells_begin(&ci, d, &boxes[0]);
    r |= vor_cells_next(NULL, &site, vertices, CAP, &count);
    r |= vor_cells_next(&ci, NULL, vertices, CAP, &count);
    r |= vor_cells_next(&ci, &site, vertices, CAP, NULL);
    r |= vor_cells_next(&ci, &site, NULL, 1u, &count);
    r |= vor_cells_error(NULL);
    r |= vor_cell(NULL, 0u, &boxes[0], vertices, CAP, &count);
    r |= vor_cell(d, 0u, NULL, vertices, CAP, &count);
    r |= vor_cell(d, 0u, &boxes[0], NULL, 1u, &count);
    r |= vor_cell(d, 0u, &boxes[0], vertices, CAP, NULL);
    return r;
}

int main(void)
{
    return far_sites_each(Frama_C_unsigned_int_interval(0u, UINT32_MAX), true, N, iterate);
}
