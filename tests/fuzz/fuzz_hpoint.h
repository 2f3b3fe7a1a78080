/* SPDX-License-Identifier: MIT */
/*
 * fuzz_hpoint.h - exact predicates on points with rational coordinates
 * (X / W, Y / W): the crossing vertices of vor_cdt.h and the centroids of
 * triangles on them, for the API harness's check of the constrained
 * triangulation. Written apart from the library's src/crossing.c, so the
 * harness is an independent reference, on fuzz_common.h's integers. The
 * largest value is the incircle determinant of four crossing vertices
 * (|X|, |Y| < 2^98, 0 < W < 2^66, rows (X W, Y W, X^2 + Y^2, W^2)):
 * 24 terms below 2^654, well inside their 767 bits. Host-only,
 * header-only.
 */
#ifndef VOR_FUZZ_HPOINT_H
#define VOR_FUZZ_HPOINT_H

#include <stdint.h>

#include "fuzz_common.h"

/* A point (x / w, y / w) with w > 0. */
typedef struct {
    fuzz_big_t x, y, w;
} fuzz_hpoint_t;

static inline fuzz_hpoint_t fuzz_hpoint_site(vor_point_t p)
{
    fuzz_hpoint_t h = {fuzz_big_from(p.x), fuzz_big_from(p.y), fuzz_big_from(1)};
    return h;
}

/* The crossing of lines a-b and c-d by vor_cdt.h's formula (W = (b - a) x
 * (d - c), T = (c - a) x (d - c), X = a.x W + (b.x - a.x) T, Y alike);
 * 0 when the lines are parallel. */
static inline int fuzz_hpoint_crossing(fuzz_hpoint_t *h, vor_point_t a, vor_point_t b,
                                       vor_point_t c, vor_point_t d)
{
    __int128 abx = (int64_t)b.x - a.x, aby = (int64_t)b.y - a.y;
    __int128 cdx = (int64_t)d.x - c.x, cdy = (int64_t)d.y - c.y;
    __int128 acx = (int64_t)c.x - a.x, acy = (int64_t)c.y - a.y;
    __int128 w = abx * cdy - aby * cdx;
    __int128 t = acx * cdy - acy * cdx;
    if (w == 0)
        return 0;
    fuzz_big_t W = fuzz_big_from(w), T = fuzz_big_from(t);
    h->x = fuzz_big_add(fuzz_big_mul(fuzz_big_from(a.x), W), fuzz_big_mul(fuzz_big_from(abx), T));
    h->y = fuzz_big_add(fuzz_big_mul(fuzz_big_from(a.y), W), fuzz_big_mul(fuzz_big_from(aby), T));
    h->w = W;
    if (w < 0) {
        h->x = fuzz_big_negate(h->x);
        h->y = fuzz_big_negate(h->y);
        h->w = fuzz_big_negate(h->w);
    }
    return 1;
}

/* The centroid of three points. */
static inline fuzz_hpoint_t fuzz_hpoint_centroid(const fuzz_hpoint_t *a, const fuzz_hpoint_t *b,
                                                 const fuzz_hpoint_t *c)
{
    fuzz_big_t bc = fuzz_big_mul(b->w, c->w), ac = fuzz_big_mul(a->w, c->w);
    fuzz_big_t ab = fuzz_big_mul(a->w, b->w);
    fuzz_hpoint_t g;
    g.x = fuzz_big_add(fuzz_big_add(fuzz_big_mul(a->x, bc), fuzz_big_mul(b->x, ac)),
                       fuzz_big_mul(c->x, ab));
    g.y = fuzz_big_add(fuzz_big_add(fuzz_big_mul(a->y, bc), fuzz_big_mul(b->y, ac)),
                       fuzz_big_mul(c->y, ab));
    g.w = fuzz_big_mul(fuzz_big_from(3), fuzz_big_mul(a->w, bc));
    return g;
}

/* The sign of p.axis - q.axis (axis 0: x, 1: y). */
static inline int fuzz_hpoint_compare(const fuzz_hpoint_t *p, const fuzz_hpoint_t *q, int axis)
{
    return axis == 0 ? fuzz_big_sign(fuzz_big_cross(p->x, q->w, q->x, p->w))
                     : fuzz_big_sign(fuzz_big_cross(p->y, q->w, q->y, p->w));
}

static inline int fuzz_hpoint_same(const fuzz_hpoint_t *p, const fuzz_hpoint_t *q)
{
    return fuzz_hpoint_compare(p, q, 0) == 0 && fuzz_hpoint_compare(p, q, 1) == 0;
}

/* Is m strictly between p and q (three points on a line)? */
static inline int fuzz_hpoint_between(const fuzz_hpoint_t *p, const fuzz_hpoint_t *m,
                                      const fuzz_hpoint_t *q)
{
    int moved = 0;
    for (int axis = 0; axis < 2; axis++) {
        int way = fuzz_hpoint_compare(q, p, axis);
        if (fuzz_hpoint_compare(m, p, axis) != way || fuzz_hpoint_compare(q, m, axis) != way)
            return 0;
        moved |= way != 0;
    }
    return moved;
}

/* Orientation of a, b, c: the 3 x 3 determinant of rows (x, y, w). */
static inline int fuzz_hpoint_orient(const fuzz_hpoint_t *a, const fuzz_hpoint_t *b,
                                     const fuzz_hpoint_t *c)
{
    fuzz_big_t det = fuzz_big_mul(a->x, fuzz_big_cross(b->y, c->w, c->y, b->w));
    det = fuzz_big_sub(det, fuzz_big_mul(a->y, fuzz_big_cross(b->x, c->w, c->x, b->w)));
    det = fuzz_big_add(det, fuzz_big_mul(a->w, fuzz_big_cross(b->x, c->y, c->x, b->y)));
    return fuzz_big_sign(det);
}

/* Positive when d lies inside the circle through a, b, c
 * (counterclockwise): the 4 x 4 determinant of rows (x w, y w, x^2 + y^2,
 * w^2), expanded along its first two columns. */
static inline int fuzz_hpoint_incircle(const fuzz_hpoint_t *a, const fuzz_hpoint_t *b,
                                       const fuzz_hpoint_t *c, const fuzz_hpoint_t *d)
{
    const fuzz_hpoint_t *p[4] = {a, b, c, d};
    fuzz_big_t m[4][4];
    for (int i = 0; i < 4; i++) {
        m[i][0] = fuzz_big_mul(p[i]->x, p[i]->w);
        m[i][1] = fuzz_big_mul(p[i]->y, p[i]->w);
        m[i][2] = fuzz_big_add(fuzz_big_mul(p[i]->x, p[i]->x), fuzz_big_mul(p[i]->y, p[i]->y));
        m[i][3] = fuzz_big_mul(p[i]->w, p[i]->w);
    }
    /* rows {i, j} of columns 0, 1 against the other two rows of 2, 3;
     * the sign of the pair is (-1)^(i + j + 1) */
    static const int pairs[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                    {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    fuzz_big_t det = fuzz_big_from(0);
    for (int k = 0; k < 6; k++) {
        int i = pairs[k][0], j = pairs[k][1], r = pairs[k][2], s = pairs[k][3];
        fuzz_big_t term = fuzz_big_mul(fuzz_big_cross(m[i][0], m[j][1], m[j][0], m[i][1]),
                                       fuzz_big_cross(m[r][2], m[s][3], m[s][2], m[r][3]));
        det = (i + j) % 2 ? fuzz_big_add(det, term) : fuzz_big_sub(det, term);
    }
    return fuzz_big_sign(det);
}

#endif
