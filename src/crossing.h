/* SPDX-License-Identifier: MIT */
/*
 * crossing.h - exact predicates on the vertices of the constrained
 * triangulation, private to the library. A vertex is a site or the point
 * where two constraints cross: the crossing of lines a-b and c-d (sites)
 * held exactly, in homogeneous coordinates (X, Y, W), W > 0, the point
 * being (X / W, Y / W). Nothing is rounded: the predicates evaluate their
 * determinants in the multi-word toolkit (multiword.h), at widths bounded
 * below, and the perturbation (docs/design/predicates.md, "Symbolic
 * perturbation") moves a crossing vertex like a site of its own index.
 *
 * Widths, for sites in int32: a difference has 33 bits, W = (b - a) x
 * (d - c) at most 2^65 in magnitude (two products below 2^64), and a
 * crossing of two segments lies in their box, so |X| = |x| W <= 2^31 2^65
 * = 2^96. Two's complement in 128 bits holds each.
 */
#ifndef VOR_CROSSING_H
#define VOR_CROSSING_H

#include <stdbool.h>

#include "multiword.h"
#include "vor.h"

#define VOR__HPOINT_LIMBS VOR__LIMBS(128u)

typedef struct vor__hpoint {
    vor__limb x[VOR__HPOINT_LIMBS];
    vor__limb y[VOR__HPOINT_LIMBS];
    vor__limb w[VOR__HPOINT_LIMBS];
} vor__hpoint_t;

/* h = site p (W = 1). */
void vor__hpoint_site(vor__hpoint_t *h, vor_point_t p);

/* h = the point where line a-b meets line c-d; false (h unset) when they
 * are parallel. The caller's segments cross (|X| <= 2^96 above). */
bool vor__hpoint_crossing(vor__hpoint_t *h, vor_point_t a, vor_point_t b, vor_point_t c,
                          vor_point_t d);

/* The sign of the orientation of p, q, r (> 0 counterclockwise), and of
 * the incircle test of p, q, r, s (> 0: s inside the circle through the
 * counterclockwise p, q, r): exact, 0 on a tie. */
int vor__orient_h(const vor__hpoint_t *p, const vor__hpoint_t *q, const vor__hpoint_t *r);
int vor__incircle_h(const vor__hpoint_t *p, const vor__hpoint_t *q, const vor__hpoint_t *r,
                    const vor__hpoint_t *s);

/* The sign of p - q along axis 0 (x) or 1 (y). */
int vor__compare_h(const vor__hpoint_t *p, const vor__hpoint_t *q, unsigned axis);

/* The same under the symbolic perturbation, vertex k moved as the vertex
 * of index ids[k] (distinct): never 0. */
int vor__orient_h_sos(const vor__hpoint_t *const v[3], const uint32_t ids[3]);
int vor__incircle_h_sos(const vor__hpoint_t *const v[4], const uint32_t ids[4]);

#endif
