/* SPDX-License-Identifier: MIT */
/*
 * Predicate test vectors: the layout of the table that
 * tools/gen_predicate_vectors.py writes to build/gen/predicate_vectors.c.
 * The generator computes every expected sign with Python's big integers,
 * independently of the C code; the perturbed sign comes from expanding the
 * perturbed determinant as a polynomial in epsilon (docs/design/predicates.md).
 */
#ifndef VOR_TEST_PREDICATE_VECTORS_H
#define VOR_TEST_PREDICATE_VECTORS_H

#include <stddef.h>
#include <stdint.h>

enum predicate_op {
    PV_ORIENT2D = 0, /* points a, b, c: sign of det[[ax ay 1][bx by 1][cx cy 1]] */
    PV_INCIRCLE = 1, /* points a, b, c, d: sign of det rows (x, y, x^2+y^2, 1) */
    PV_CLOSER = 2    /* points q, a, b: sign of |q-a|^2 - |q-b|^2 */
};

struct predicate_vector {
    int32_t xy[8];     /* points in call order: (xy[0],xy[1]), (xy[2],xy[3]), ... */
    uint8_t op;        /* enum predicate_op */
    int8_t exact;      /* exact unperturbed sign: -1, 0 or 1 */
    int8_t perturbed;  /* sign under the symbolic perturbation (never 0 for
                          orient2d/incircle; equals exact for closer) */
    uint8_t ranks;     /* site index of the k-th point: (ranks >> 2k) & 3 */
    uint8_t family;    /* enum predicate_family: where the case came from */
};

enum predicate_family {
    PF_RANDOM_FULL, PF_RANDOM_SMALL, PF_RANDOM_MID, PF_COLLINEAR,
    PF_COCIRCULAR, PF_OFF_BY_ONE, PF_CORNERS, PF_PERTURBED,
    PF_TIER_EDGE, /* differences at the evaluation tiers' limits */
    PF_FAMILIES
};

extern const struct predicate_vector predicate_vectors[];
extern const size_t predicate_vector_count;

#endif
