/* SPDX-License-Identifier: MIT */
/*
 * Crossing-vertex predicate vectors: the layout of the table that
 * tools/gen_crossing_vectors.py writes to build/gen/crossing_vectors.c.
 * The generator computes every expected sign with Python's exact
 * rationals, independently of the C code; the perturbed sign comes from
 * expanding the perturbed determinant as a polynomial in epsilon.
 */
#ifndef VOR_TEST_CROSSING_VECTORS_H
#define VOR_TEST_CROSSING_VECTORS_H

#include <stddef.h>
#include <stdint.h>

struct crossing_vector {
    /* vertex k: a site (xy[k][0], xy[k][1]), or when bit k of `crossing`
     * is set the crossing of line (xy[k][0..1])-(xy[k][2..3]) with line
     * (xy[k][4..5])-(xy[k][6..7]) */
    int32_t xy[4][8];
    uint8_t crossing;
    uint8_t op;       /* 0: orientation of vertices 0..2; 1: incircle of 0..3 */
    int8_t exact;     /* exact sign: -1, 0 or 1 */
    int8_t perturbed; /* sign under the perturbation: never 0 */
    uint8_t ranks;    /* the index rank of vertex k: (ranks >> 2k) & 3 */
};

extern const struct crossing_vector crossing_vectors[];
extern const size_t crossing_vector_count;

#endif
