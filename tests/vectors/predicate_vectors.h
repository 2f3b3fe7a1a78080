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

/* The power test and the power distance, on weighted points. */
enum power_op {
    PW_TEST = 0,  /* a, b, c, d: sign of det rows (x, y, x^2 + y^2 - w, 1) */
    PW_CLOSER = 1 /* q, a, b: sign of (|q-a|^2 - wa) - (|q-b|^2 - wb) */
};

enum power_family {
    PWF_RANDOM_FULL, PWF_RANDOM_SMALL, PWF_RANDOM_MID,
    PWF_EQUAL_WEIGHTS, /* the power test is the incircle test */
    PWF_TIED,          /* exactly 0 by construction */
    PWF_OFF_BY_ONE,    /* a tie with one weight moved by one */
    PWF_CORNERS,       /* int32 and int64 extremes */
    PWF_FAMILIES
};

struct power_vector {
    int32_t xy[8];    /* points in call order, as predicate_vector's */
    int64_t w[4];     /* their weights (PW_CLOSER: q's unused) */
    uint8_t op;       /* enum power_op */
    int8_t exact;     /* exact sign */
    int8_t perturbed; /* PW_TEST: the perturbed sign; PW_CLOSER: exact */
    uint8_t ranks;    /* site index of the k-th point: (ranks >> 2k) & 3 */
    uint8_t family;   /* enum power_family */
};

extern const struct power_vector power_vectors[];
extern const size_t power_vector_count;

#endif
