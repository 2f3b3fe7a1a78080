/* SPDX-License-Identifier: MIT */
/*
 * raster_metrics.c - the raster's family of other metrics, all but
 * Euclidean point sites (raster_euclid.c): L1, L-infinity, Lp, elliptic,
 * weighted (multiplicative, additive, compound), farthest-point, Hausdorff
 * point sets, segments, filled polygons, multiplicatively weighted
 * polylines and power diagrams (Teramoto: section 2.3 defines the
 * generalised diagrams, chapter 5 the distances). Each pixel takes the site of smallest
 * distance (largest for the farthest-point diagram), ties to the smaller
 * index: Definition 2.2 with another distance.
 *
 * To rank sites, distances are never computed, only compared, each
 * through a "key" that holds an exact integer (or rational) image of the
 * distance, and one exact comparison per metric (key_compare).
 * docs/design/raster-metrics.md, "Other metrics", derives each comparison and its width.
 * Only the DISTANCE output turns the winning key into the floor of the
 * distance (metric_distance, "Distance output").
 *
 * Culling: the frame is cut into tiles of 16 rows by tile_width columns.
 * For a tile R and a site, bounds() gives a key no larger than the site's
 * key at any pixel of R (its best case) and one no smaller (its worst
 * case). A site whose best case is strictly worse than some site's worst
 * case is strictly farther than that site at every pixel of R, so it can
 * be neither nearest nor tied for nearest there, and is skipped. Blocks
 * of 8 tiles are culled from all sites first, and their tiles from the
 * block's survivors, so a band costs O(n) bounds per block.
 */
#include <stdbool.h>

#include "raster.h"

#include "multiword.h"

/* A set of metrics, as bits: every dispatch on the metric tests a set
 * (IN) in an if-chain. A switch on the metric, or a chain of == tests,
 * which compilers turn into one, becomes a case table with four cases or
 * more, and GCC for ARMv6-M at -Os reads those through libgcc
 * (__gnu_thumb1_case_*): the library must call nothing outside itself.
 * Per site and per tile, the chains are compiled away: the key, the
 * comparison and the bounds are instances for one metric's constant bit,
 * picked once per frame from a table (metric_ops). */
#define METRIC(name) ((uint32_t)1 << (uint32_t)VOR_METRIC_##name)
#define IN(bit, set) (((bit) & (set)) != 0u)
/* the metrics whose keys are rationals (rank_key_t) */
#define RATIONAL_METRICS (METRIC(ELLIPTIC) | METRIC(SEGMENT) | METRIC(POLYGON) | METRIC(POLYLINE))

/* Rows per culling tile. */
#define TILE_ROWS 16u

struct key;
struct rect;

/* The family's state: the frame and sites of the request, the widths of
 * its exact comparisons, and the culling of sites per tile. */
typedef struct metric {
    const vor_raster_frame_t *frame;
    /* frame's: read per pixel, kept beside m's other fields */
    int32_t origin_x;
    int32_t step_x;
    const vor_raster_sites_t *sites;
    enum vor_metric metric;
    uint32_t metric_bit; /* 1 << metric, tested against METRIC() sets */
    /* the metric's key, comparison and bounds (metric_ops) */
    void (*key)(const struct metric *m, uint32_t site, int32_t qx, int32_t qy, struct key *k);
    int (*compare)(const struct metric *m, const struct key *a, const struct key *b);
    void (*bounds)(const struct metric *m, uint32_t site, const struct rect *r, int worst,
                   struct key *k);
    uint32_t n;
    uint32_t limbs;      /* limbs of the wide comparisons of this frame */
    int lp_narrow;       /* LP: every sum below 2^128 */
    uint64_t det;        /* ELLIPTIC: a c - b^2 */
    uint32_t trace;      /* ELLIPTIC: a + c */
    int brute;           /* every site at every pixel, no culling */
    uint32_t *pool;      /* culling: the block list, then the tile lists */
    size_t pool_words;
    uint32_t tile_width; /* columns per tile (a power of two, >= 16) */
    uint32_t tiles;
    uint32_t band_first; /* rows of the current culling band */
    int band_valid;
} metric_t;

/* -------------------------------------------------------------- widths */

/* *r = ax^2 + ay^2 < 2^65. */
VOR__ALWAYS_INLINE void square_sum(vor__mw_u128_t *r, uint32_t ax, uint32_t ay)
{
    uint64_t x2 = vor__mul_u32(ax, ax);
    uint64_t sum = x2 + vor__mul_u32(ay, ay);
    r->lo = sum;
    r->hi = (sum < x2) ? 1u : 0u; /* the carry */
}

/* Widest comparison: the compound weights' squares, 318 bits (below). */
#define MAX_LIMBS VOR__LIMBS(320u)
/* Lp sums: |dx|^8 + |dy|^8 < 2^257. */
#define LP_LIMBS VOR__LIMBS(258u)

/* ------------------------------------------------------------ keys */

/*
 * The exact image of one site's distance at one point. Which fields hold
 * it depends on the metric:
 *   L1, LINF, HAUSDORFF, FARTHEST   num = the distance (L1, LINF) or its
 *                                    square (the others)
 *   LP                               num = |dx|^p + |dy|^p (lp_narrow), else wide
 *   MULT, ADD, COMPOUND              num = squared Euclidean distance,
 *                                    w1, w2 = the site's weights
 *   POWER                            num = D - w + (2^63 - 1) (power_bias):
 *                                    the power distance, made unsigned
 *   ELLIPTIC, SEGMENT, POLYGON,      the rational (squared ? num^2 : num) / den
 *   POLYLINE                         (POLYLINE: den includes the weight^2)
 */
typedef struct key {
    vor__mw_u128_t num;
    vor__mw_u128_t den;
    int squared;
    int32_t w1;
    int32_t w2;
    vor__limb wide[LP_LIMBS];
} rank_key_t;

/* Makes k the integer k->num: denominator 1, not squared. The callers
 * write k->num in place (no 128-bit value is copied as a whole: see
 * multiword.h). */
VOR__ALWAYS_INLINE void set_unit_denominator(rank_key_t *k)
{
    vor__mw_u128_set(&k->den, 1);
    k->squared = 0;
}

/* *r = x^p for x^p < 2^128. */
VOR__ALWAYS_INLINE void power128(vor__mw_u128_t *r, uint32_t x, uint32_t p)
{
    vor__mw_u128_set(r, x);
    for (uint32_t i = 1; i < p; i++) {
        vor__mw_u128_mul64(r, r, x);
    }
}

/* r[0..n) = x^p (n limbs hold it). */
static void power_limbs(vor__limb *r, size_t n, uint32_t x, uint32_t p)
{
    vor__limb base[1] = {x};
    vor__limb product[LP_LIMBS];
    vor__mw_from_u64(r, n, x);
    for (uint32_t i = 1; i < p; i++) {
        vor__mw_mul(product, n, r, n, base, 1);
        vor__mw_copy(r, product, n);
    }
}

/* The power distance D - w for an int64 weight w, biased by 2^63 - 1 so
 * that it is unsigned: D - w + (2^63 - 1) = D + bias, where
 * bias = (2^63 - 1) - w lies in [0, 2^64) for every int64 w, computed
 * modulo 2^64 (exact, since the true value is in range). The key
 * D + bias < 2^65 + 2^64 keeps the order of the power distances, so the
 * keys compare as plain 128-bit integers (docs/design/raster-metrics.md,
 * "Power diagrams"). */
VOR__ALWAYS_INLINE uint64_t power_bias(int64_t w)
{
    return (uint64_t)INT64_MAX - (uint64_t)w;
}

/* The key of a point site at offsets of magnitude (ax, ay): every metric
 * whose distance grows with |dx| and with |dy| (POWER: for a fixed
 * weight). */
VOR__ALWAYS_INLINE void point_key(const metric_t *m, uint32_t bit, uint32_t site, uint32_t ax,
                                  uint32_t ay, rank_key_t *k)
{
    const vor_raster_sites_t *s = m->sites;
    if (IN(bit, METRIC(L1))) {
        vor__mw_u128_set(&k->num, (uint64_t)ax + ay);
    } else if (IN(bit, METRIC(LINF))) {
        vor__mw_u128_set(&k->num, (ax > ay) ? ax : ay);
    } else if (IN(bit, METRIC(LP))) {
        if (m->lp_narrow != 0) {
            vor__mw_u128_t x_power;
            vor__mw_u128_t y_power;
            power128(&x_power, ax, s->lp_exponent);
            power128(&y_power, ay, s->lp_exponent);
            vor__mw_u128_add(&k->num, &x_power, &y_power);
        } else {
            vor__limb other[LP_LIMBS];
            power_limbs(k->wide, m->limbs, ax, s->lp_exponent);
            power_limbs(other, m->limbs, ay, s->lp_exponent);
            vor__mw_add(k->wide, other, m->limbs);
        }
    } else { /* MULT, ADD, COMPOUND, FARTHEST, HAUSDORFF, POWER */
        square_sum(&k->num, ax, ay);
        if (IN(bit, METRIC(POWER))) {
            vor__mw_u128_t bias;
            vor__mw_u128_set(&bias, power_bias(s->power_weights[site]));
            vor__mw_u128_add(&k->num, &k->num, &bias);
        }
        if (IN(bit, METRIC(MULT) | METRIC(COMPOUND))) {
            k->w1 = s->mult_weights[site];
        }
        if (IN(bit, METRIC(ADD) | METRIC(COMPOUND))) {
            k->w2 = s->add_weights[site];
        }
    }
}

/* *r = a dx^2 + 2 b dx dy + c dy^2 for |dx|, |dy| < 2^32: each term is
 * below 2^96 and the form is positive definite, so every step fits 128
 * bits. Summed in a local, which stays in registers, and stored once. */
VOR__ALWAYS_INLINE void elliptic_form(vor__mw_u128_t *r, const vor_raster_sites_t *s, int64_t dx,
                                      int64_t dy)
{
    uint32_t ax = vor__mw_magnitude(dx);
    uint32_t ay = vor__mw_magnitude(dy);
    vor__mw_u128_t sum;
    vor__mw_u128_t term;
    vor__mw_u128_mul(&sum, vor__mul_u32(ax, ax), (uint32_t)s->form_a);
    vor__mw_u128_mul(&term, vor__mul_u32(ay, ay), (uint32_t)s->form_c);
    vor__mw_u128_add(&sum, &sum, &term);
    if ((s->form_b != 0) && (ax != 0u) && (ay != 0u)) {
        /* |b| < 2^31 since b^2 < a c < 2^62 */
        vor__mw_u128_mul(&term, vor__mul_u32(ax, ay), 2u * vor__mw_magnitude(s->form_b));
        if ((s->form_b < 0) != ((dx < 0) != (dy < 0))) {
            vor__mw_u128_sub(&sum, &sum, &term);
        } else {
            vor__mw_u128_add(&sum, &sum, &term);
        }
    }
    vor__mw_u128_copy(r, &sum);
}

/* The squared distance from q to the segment a-b, as the rational key
 * (squared ? num^2 : num) / den: the projection of q onto the segment's
 * line falls before a (then |q - a|^2), after b (|q - b|^2), or between
 * (cross^2 / |b - a|^2, cross = (q - a) x (b - a)). */
static void segment_key(const vor_point_t *a, const vor_point_t *b, int32_t qx, int32_t qy,
                        rank_key_t *k)
{
    int64_t ex = (int64_t)b->x - a->x;
    int64_t ey = (int64_t)b->y - a->y;
    int64_t ux = (int64_t)qx - a->x;
    int64_t uy = (int64_t)qy - a->y;
    vor__mw_u128_t length;
    square_sum(&length, vor__mw_magnitude(ex), vor__mw_magnitude(ey));
    vor__mw_s128_t along;
    vor__mw_s128_t term;
    vor__mw_s128_product(&along, ux, ex);
    vor__mw_s128_product(&term, uy, ey);
    vor__mw_s128_add(&along, &along, &term);
    if (vor__mw_u128_is_zero(&length) || along.neg || vor__mw_u128_is_zero(&along.mag)) {
        square_sum(&k->num, vor__mw_magnitude(ux), vor__mw_magnitude(uy));
        set_unit_denominator(k);
        return;
    }
    if (vor__mw_u128_compare(&along.mag, &length) >= 0) {
        square_sum(&k->num, vor__mw_magnitude((int64_t)qx - b->x), vor__mw_magnitude((int64_t)qy - b->y));
        set_unit_denominator(k);
        return;
    }
    vor__mw_s128_t cross;
    vor__mw_s128_product(&cross, uy, ex);
    cross.neg = !cross.neg && !vor__mw_u128_is_zero(&cross.mag);
    vor__mw_s128_product(&term, ux, ey);
    vor__mw_s128_add(&cross, &term, &cross);
    vor__mw_u128_copy(&k->num, &cross.mag); /* |cross| < 2^65 */
    vor__mw_u128_copy(&k->den, &length);    /* < 2^65 */
    k->squared = 1;
}

/* (squared ? num^2 : num) / den compared exactly: a / b < c / d iff
 * a d < c b (denominators >= 1). Numerators are below 2^130, denominators
 * below 2^65 (segments, polygons), 2^127 (weighted polylines: 2^65 times
 * a squared weight below 2^62) or 2^32 (elliptic bounds), so the cross
 * products stay below 2^257. */
static int rational_compare(const rank_key_t *a, const rank_key_t *b)
{
    bool a_unit = !a->squared && (a->den.lo == 1u) && (a->den.hi == 0u);
    bool b_unit = !b->squared && (b->den.lo == 1u) && (b->den.hi == 0u);
    if (a_unit && b_unit) {
        return vor__mw_u128_compare(&a->num, &b->num);
    }
    bool a_small = (a->den.hi == 0u) && (a->num.hi == 0u) && (!a->squared || ((a->num.lo >> 32) == 0u));
    bool b_small = (b->den.hi == 0u) && (b->num.hi == 0u) && (!b->squared || ((b->num.lo >> 32) == 0u));
    if (a_small && b_small) { /* numerators and denominators below 2^64 */
        uint64_t an = a->squared ? vor__mul_u32((uint32_t)a->num.lo, (uint32_t)a->num.lo) : a->num.lo;
        uint64_t bn = b->squared ? vor__mul_u32((uint32_t)b->num.lo, (uint32_t)b->num.lo) : b->num.lo;
        vor__mw_u128_t left;
        vor__mw_u128_t right;
        vor__mw_u128_mul(&left, an, b->den.lo);
        vor__mw_u128_mul(&right, bn, a->den.lo);
        return vor__mw_u128_compare(&left, &right);
    }
    enum { NUM = VOR__LIMBS(128u), SQUARE = VOR__LIMBS(192u), CROSS = VOR__LIMBS(258u) };
    vor__limb num[NUM];
    vor__limb square[SQUARE];
    vor__limb den[NUM];
    vor__limb left[CROSS];
    vor__limb right[CROSS];
    vor__mw_from_u128(num, NUM, &a->num);
    if (a->squared != 0) {
        vor__mw_mul(square, SQUARE, num, NUM, num, NUM);
    } else {
        vor__mw_from_u128(square, SQUARE, &a->num);
    }
    vor__mw_from_u128(den, NUM, &b->den);
    vor__mw_mul(left, CROSS, square, SQUARE, den, NUM);
    vor__mw_from_u128(num, NUM, &b->num);
    if (b->squared != 0) {
        vor__mw_mul(square, SQUARE, num, NUM, num, NUM);
    } else {
        vor__mw_from_u128(square, SQUARE, &b->num);
    }
    vor__mw_from_u128(den, NUM, &a->den);
    vor__mw_mul(right, CROSS, square, SQUARE, den, NUM);
    return vor__mw_compare(left, right, CROSS);
}

/*
 * Sign of (sqrt(A) - sqrt(B)) - delta for A, B >= 0: the additively
 * weighted comparison (docs/design/raster-metrics.md, "Additive weights"). With
 * delta >= 0 it is the sign of E - 2 delta sqrt(B), E = A - B - delta^2;
 * with delta = -g < 0, the sign of 2 g sqrt(A) - F, F = B - A - g^2. Both
 * sides are squared only when they are known non-negative. n limbs hold
 * E^2, F^2, 4 delta^2 A and 4 delta^2 B (the caller's bound) and the sign
 * of E and F.
 */
static int additive_sign(size_t n, const vor__mw_u128_t *big_a, const vor__mw_u128_t *big_b,
                         const vor__mw_s128_t *delta)
{
    if (vor__mw_u128_is_zero(&delta->mag) != 0) {
        return vor__mw_u128_compare(big_a, big_b);
    }
    vor__limb a[MAX_LIMBS];
    vor__limb b[MAX_LIMBS];
    vor__limb d[MAX_LIMBS];
    vor__limb d2[MAX_LIMBS];
    vor__limb e[MAX_LIMBS];
    vor__limb product[MAX_LIMBS];
    vor__limb left[MAX_LIMBS];
    vor__limb right[MAX_LIMBS];
    vor__mw_from_u128(a, n, big_a);
    vor__mw_from_u128(b, n, big_b);
    vor__mw_from_u128(d, n, &delta->mag);
    vor__mw_mul(d2, n, d, n, d, n);
    if (!delta->neg) {
        vor__mw_copy(e, a, n);
        vor__mw_sub(e, b, n);
        vor__mw_sub(e, d2, n);
        int sign = vor__mw_sign(e, n);
        if (sign < 0) {
            return -1; /* E < 0 <= 2 delta sqrt(B) */
        }
        if (sign == 0) {
            return vor__mw_u128_is_zero(big_b) ? 0 : -1;
        }
        vor__mw_mul(left, n, e, n, e, n);
        vor__mw_mul(product, n, d2, n, b, n);
        vor__mw_times4(right, product, n);
        return vor__mw_compare(left, right, n);
    }
    vor__mw_copy(e, b, n);
    vor__mw_sub(e, a, n);
    vor__mw_sub(e, d2, n);
    int sign = vor__mw_sign(e, n);
    if (sign < 0) {
        return 1; /* 2 g sqrt(A) >= 0 > F */
    }
    if (sign == 0) {
        return vor__mw_u128_is_zero(big_a) ? 0 : 1;
    }
    vor__mw_mul(product, n, d2, n, a, n);
    vor__mw_times4(left, product, n);
    vor__mw_mul(right, n, e, n, e, n);
    return vor__mw_compare(left, right, n);
}

/* Negative when key a ranks before key b (nearer; farther for FARTHEST),
 * 0 when they tie. */
VOR__ALWAYS_INLINE int key_compare(const metric_t *m, uint32_t bit, const rank_key_t *a,
                                   const rank_key_t *b)
{
    if (IN(bit, METRIC(LP))) {
        if (!m->lp_narrow) {
            return vor__mw_compare(a->wide, b->wide, m->limbs);
        }
        return vor__mw_u128_compare(&a->num, &b->num);
    } else if (IN(bit, METRIC(FARTHEST))) {
        return vor__mw_u128_compare(&b->num, &a->num);
    } else if (IN(bit, RATIONAL_METRICS)) {
        return rational_compare(a, b);
    } else if (IN(bit, METRIC(MULT))) {
        /* sqrt(A) / wa < sqrt(B) / wb iff A wb^2 < B wa^2: below 2^65 * 2^62 */
        uint64_t wa2 = vor__mul_u32((uint32_t)a->w1, (uint32_t)a->w1);
        uint64_t wb2 = vor__mul_u32((uint32_t)b->w1, (uint32_t)b->w1);
        vor__mw_u128_t left;
        vor__mw_u128_t right;
        vor__mw_u128_mul64(&left, &a->num, wb2);
        vor__mw_u128_mul64(&right, &b->num, wa2);
        return vor__mw_u128_compare(&left, &right);
    } else if (IN(bit, METRIC(ADD))) {
        vor__mw_s128_t delta; /* wa - wb, below 2^32 */
        int64_t diff = (int64_t)a->w2 - b->w2;
        vor__mw_u128_set(&delta.mag, (diff < 0) ? (uint64_t)-diff : (uint64_t)diff);
        delta.neg = diff < 0;
        return additive_sign(m->limbs, &a->num, &b->num, &delta);
    } else if (IN(bit, METRIC(COMPOUND))) {
        /* sqrt(A)/wa1 - wa2 vs sqrt(B)/wb1 - wb2, times wa1 wb1 > 0:
         * sqrt(A wb1^2) - sqrt(B wa1^2) vs (wa2 - wb2) wa1 wb1 */
        uint64_t wa2 = vor__mul_u32((uint32_t)a->w1, (uint32_t)a->w1);
        uint64_t wb2 = vor__mul_u32((uint32_t)b->w1, (uint32_t)b->w1);
        int64_t diff = (int64_t)a->w2 - b->w2;
        vor__mw_s128_t delta;
        vor__mw_u128_mul(&delta.mag, (diff < 0) ? (uint64_t)-diff : (uint64_t)diff,
                         vor__mul_u32((uint32_t)a->w1, (uint32_t)b->w1));
        delta.neg = diff < 0;
        vor__mw_u128_t big_a;
        vor__mw_u128_t big_b;
        vor__mw_u128_mul64(&big_a, &a->num, wb2);
        vor__mw_u128_mul64(&big_b, &b->num, wa2);
        return additive_sign(m->limbs, &big_a, &big_b, &delta);
    } else { /* L1, LINF, HAUSDORFF, POWER (biased) */
        return vor__mw_u128_compare(&a->num, &b->num);
    }
}

/* Nonzero winding number of the closed polygon p[0..count) around q
 * (q not on its boundary; on the boundary the distance is 0 anyway). */
static int winds_around(const vor_point_t *p, uint32_t count, const vor_point_t *q)
{
    int64_t winding = 0;
    for (uint32_t i = 0; i < count; i++) {
        const vor_point_t *a = &p[i];
        const vor_point_t *b = &p[((i + 1u) == count) ? 0u : (i + 1u)];
        if (a->y <= q->y) {
            if ((b->y > q->y) && vor_orient2d(*a, *b, *q) > 0) {
                winding++; /* an upward edge with q on its left */
            }
        } else if ((b->y <= q->y) && vor_orient2d(*a, *b, *q) < 0) {
            winding--; /* a downward edge with q on its right */
        } else {
            /* no other case */
        }
    }
    return winding != 0;
}

/* k = edge when edge is smaller, member by member: no structure copy
 * (memcpy on Cortex-M0). */
static void keep_smaller(rank_key_t *k, const rank_key_t *edge)
{
    if (rational_compare(edge, k) < 0) {
        vor__mw_u128_copy(&k->num, &edge->num);
        vor__mw_u128_copy(&k->den, &edge->den);
        k->squared = edge->squared;
    }
}

/* The squared weight of polyline site `site` (1 without weights): below
 * 2^62. */
static uint64_t polyline_weight2(const vor_raster_sites_t *s, uint32_t site)
{
    if (s->mult_weights == NULL) {
        return 1u;
    }
    uint32_t w = (uint32_t)s->mult_weights[site];
    return vor__mul_u32(w, w);
}

/* The key of site `site` at the pixel centre (qx, qy). */
VOR__ALWAYS_INLINE void site_key(const metric_t *m, uint32_t bit, uint32_t site, int32_t qx,
                                 int32_t qy, rank_key_t *k)
{
    const vor_raster_sites_t *s = m->sites;
    if (IN(bit, METRIC(ELLIPTIC))) {
        const vor_point_t *p = &s->points[site];
        elliptic_form(&k->num, s, (int64_t)qx - p->x, (int64_t)qy - p->y);
        set_unit_denominator(k);
    } else if (IN(bit, METRIC(HAUSDORFF))) {
        vor__mw_u128_t far;
        vor__mw_u128_t d;
        vor__mw_u128_set(&far, 0);
        for (uint32_t i = s->offsets[site]; i < s->offsets[site + 1u]; i++) {
            square_sum(&d, vor__mw_magnitude((int64_t)qx - s->points[i].x),
                       vor__mw_magnitude((int64_t)qy - s->points[i].y));
            if (vor__mw_u128_compare(&d, &far) > 0) {
                vor__mw_u128_copy(&far, &d);
            }
        }
        vor__mw_u128_copy(&k->num, &far);
    } else if (IN(bit, METRIC(SEGMENT))) {
        segment_key(&s->points[2u * site], &s->points[(2u * site) + 1u], qx, qy, k);
    } else if (IN(bit, METRIC(POLYGON))) {
        const vor_point_t *p = &s->points[s->offsets[site]];
        uint32_t count = s->offsets[site + 1u] - s->offsets[site];
        vor_point_t q;
        q.x = qx;
        q.y = qy;
        if ((count >= 3u) && winds_around(p, count, &q)) {
            vor__mw_u128_set(&k->num, 0);
            set_unit_denominator(k);
            return;
        }
        segment_key(&p[0], &p[(count > 1u) ? 1u : 0u], qx, qy, k);
        rank_key_t edge;
        for (uint32_t i = 1; (count >= 3u) && (i < count); i++) {
            segment_key(&p[i], &p[((i + 1u) == count) ? 0u : (i + 1u)], qx, qy, &edge);
            keep_smaller(k, &edge);
        }
    } else if (IN(bit, METRIC(POLYLINE))) {
        /* the smallest segment key (unweighted: one weight per site), then
         * divided by w^2: the denominator stays below 2^65 * 2^62 */
        const vor_point_t *p = &s->points[s->offsets[site]];
        uint32_t count = s->offsets[site + 1u] - s->offsets[site];
        segment_key(&p[0], &p[(count > 1u) ? 1u : 0u], qx, qy, k);
        rank_key_t edge;
        for (uint32_t i = 1; (i + 1u) < count; i++) {
            segment_key(&p[i], &p[i + 1u], qx, qy, &edge);
            keep_smaller(k, &edge);
        }
        vor__mw_u128_mul64(&k->den, &k->den, polyline_weight2(s, site));
    } else {
        const vor_point_t *p = &s->points[site];
        point_key(m, bit, site, vor__mw_magnitude((int64_t)qx - p->x), vor__mw_magnitude((int64_t)qy - p->y), k);
    }
}

/* --------------------------------------------------------- distances */

/*
 * VOR_RASTER_DISTANCE (vor_raster.h, OUTPUT KINDS): the floor of the
 * pixel's own site's distance, from the same key that ranked it, so the
 * value is the distance that decided the label. Every root and quotient
 * is an integer one, by these identities (r, w integers, w >= 1, X >= 0):
 *   floor(sqrt(X))            = isqrt(floor(X))       (r^2 <= X iff r^2 <= floor(X))
 *   floor(sqrt(X / D))        = isqrt(floor(X / D))   (the same, D > 0)
 *   floor(sqrt(A) / w)        = floor(isqrt(A) / w)   (r w <= sqrt(A) iff r w <= isqrt(A))
 *   floor(v - w)              = floor(v) - w
 * docs/design/raster-metrics.md, "Distance output", has the bounds.
 */

/* floor(sqrt(x)) (< 2^64) by the bit-by-bit method: bit runs over the
 * even powers of two down from 2^126, two places a step, so at most 64
 * steps; root + bit < 2^128 throughout. Constant shifts only (no shift
 * call on Cortex-M0). */
static uint64_t isqrt128(const vor__mw_u128_t *value)
{
    vor__mw_u128_t x;
    vor__mw_u128_t root;
    vor__mw_u128_t bit;
    vor__mw_u128_t trial;
    vor__mw_u128_copy(&x, value);
    vor__mw_u128_set(&root, 0);
    bit.lo = 0;
    bit.hi = (uint64_t)1 << 62;
    while (vor__mw_u128_compare(&bit, &x) > 0) {
        vor__mw_u128_shr(&bit, &bit, 2u);
    }
    while (!vor__mw_u128_is_zero(&bit)) {
        vor__mw_u128_add(&trial, &root, &bit);
        vor__mw_u128_shr(&root, &root, 1u);
        if (vor__mw_u128_compare(&x, &trial) >= 0) {
            vor__mw_u128_sub(&x, &x, &trial);
            vor__mw_u128_add(&root, &root, &bit);
        }
        vor__mw_u128_shr(&bit, &bit, 2u);
    }
    return root.lo;
}

/* floor(a / d) for d >= 1, by shift and subtract (no divider on
 * Cortex-M0): 64 steps, the remainder stays below 2 d < 2^33. */
static uint64_t divide_u64(uint64_t a_in, uint32_t d)
{
    uint64_t a = a_in;
    uint64_t quotient = 0;
    uint64_t rest = 0;
    for (int step = 0; step < 64; step++) {
        rest = (rest << 1) | (a >> 63);
        a <<= 1;
        quotient <<= 1;
        if (rest >= d) {
            rest -= d;
            quotient |= 1u;
        }
    }
    return quotient;
}

/* Limbs of the rational distances: numerators below 2^130, denominators
 * below 2^127, so a remainder shifted once stays below 2^128. */
#define DIV_LIMBS VOR__LIMBS(192u)

/* q = floor(a / d) over DIV_LIMBS limbs, d >= 1 and below 2^127: long
 * division bit by bit from a's top limb (at most 192 steps). */
static void mw_divide(vor__limb *q, const vor__limb *a, const vor__limb *d)
{
    vor__limb rest[DIV_LIMBS];
    for (size_t i = 0; i < DIV_LIMBS; i++) {
        rest[i] = 0;
        q[i] = 0;
    }
    size_t top = DIV_LIMBS;
    while ((top > 0u) && (a[top - 1u] == 0u)) {
        top--;
    }
    for (size_t i = top; i-- > 0u;) {
        for (uint32_t bit = VOR__LIMB_WIDTH; bit-- > 0u;) {
            vor__mw_shl1(rest, DIV_LIMBS);
            rest[0] |= (a[i] >> bit) & 1u;
            if (vor__mw_compare(rest, d, DIV_LIMBS) >= 0) {
                vor__mw_sub(rest, d, DIV_LIMBS);
                q[i] |= (vor__limb)1 << bit;
            }
        }
    }
}

VOR__ALWAYS_INLINE uint32_t saturate_u32(uint64_t v)
{
    return (v > 0xFFFFFFFFu) ? 0xFFFFFFFFu : (uint32_t)v;
}

/* v - w as an int32 bit pattern, saturated at INT32_MAX: v < 2^34 and
 * w >= -2^31, so v - w < 2^35; w < 2^31 keeps it above -2^31. Subtracted
 * in uint64_t (the same instructions), whose wrap needs no bound on v. */
VOR__ALWAYS_INLINE uint32_t signed_distance(uint64_t v, int32_t w)
{
    uint64_t difference = v - (uint64_t)(int64_t)w;
    int64_t d = (int64_t)difference;
    return (d > INT32_MAX) ? (uint32_t)INT32_MAX : (uint32_t)d;
}

/* floor((ax^p + ay^p)^(1/p)) (the key's sum), saturated: the root is
 * >= 2^32 iff the sum is >= 2^(32 p). Otherwise bisection on the root
 * keeps lo^p <= sum < hi^p from lo = max(ax, ay) and hi = min(ax + ay + 1,
 * 2^32) ((ax + ay + 1)^p > ax^p + ay^p); the bracket halves each step, so
 * at most 33 steps, each one power below 2^256. */
VOR__ALWAYS_INLINE uint32_t lp_distance(const metric_t *m, const rank_key_t *k, uint32_t ax,
                                        uint32_t ay)
{
    uint32_t p = m->sites->lp_exponent;
    vor__limb sum[LP_LIMBS];
    vor__limb power[LP_LIMBS];
    if (m->lp_narrow != 0) {
        vor__mw_from_u128(sum, LP_LIMBS, &k->num);
    } else {
        for (size_t i = 0; i < LP_LIMBS; i++) {
            sum[i] = (i < m->limbs) ? k->wide[i] : 0u;
        }
    }
    for (size_t i = 0; i < LP_LIMBS; i++) {
        power[i] = 0;
    }
    uint32_t bit = 32u * p; /* power = 2^(32 p) */
    power[bit / VOR__LIMB_WIDTH] = (vor__limb)1 << (bit % VOR__LIMB_WIDTH);
    if (vor__mw_compare(sum, power, LP_LIMBS) >= 0) {
        return 0xFFFFFFFFu;
    }
    uint64_t lo = (ax > ay) ? ax : ay;
    uint64_t hi = (uint64_t)ax + ay + 1u;
    hi = hi > ((uint64_t)1 << 32) ? ((uint64_t)1 << 32) : hi;
    while ((hi - lo) > 1u) {
        uint32_t mid = (uint32_t)(lo + ((hi - lo) >> 1));
        power_limbs(power, LP_LIMBS, mid, p);
        if (vor__mw_compare(power, sum, LP_LIMBS) <= 0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return (uint32_t)lo;
}

/* floor(sqrt((squared ? num^2 : num) / den)) of a rational key: the
 * squared distance's floor, then its integer root. The true squared
 * distance is below 2^65 (at most a vertex's), so the root saturates only
 * from 2^64 on. */
VOR__ALWAYS_INLINE uint32_t rational_distance(const rank_key_t *k)
{
    if (!k->squared && (k->den.lo == 1u) && (k->den.hi == 0u)) {
        return saturate_u32(isqrt128(&k->num));
    }
    vor__limb num[DIV_LIMBS];
    vor__limb x[DIV_LIMBS];
    vor__limb den[DIV_LIMBS];
    vor__limb q[DIV_LIMBS];
    vor__mw_from_u128(num, DIV_LIMBS, &k->num);
    if (k->squared != 0) {
        vor__mw_mul(x, DIV_LIMBS, num, DIV_LIMBS, num, DIV_LIMBS); /* < 2^130 */
    } else {
        vor__mw_copy(x, num, DIV_LIMBS);
    }
    vor__mw_from_u128(den, DIV_LIMBS, &k->den);
    mw_divide(q, x, den);
    vor__mw_u128_t quotient;
    vor__mw_to_u128(&quotient, q);
    return saturate_u32(isqrt128(&quotient));
}

/* The power distance D - w of a POWER key (num = D - w + (2^63 - 1),
 * below 2^66) as an int32 bit pattern, clamped to [INT32_MIN, INT32_MAX]:
 * no rounding, it is an integer. num >= 2^64 puts it above
 * 2^64 - 2^63 + 1 > INT32_MAX; below, one subtraction either way. */
VOR__ALWAYS_INLINE uint32_t power_distance(const rank_key_t *k)
{
    const uint64_t bias = (uint64_t)INT64_MAX;
    if (k->num.hi != 0u) {
        return (uint32_t)INT32_MAX;
    }
    if (k->num.lo >= bias) { /* 0 <= D - w <= 2^63 */
        uint64_t value = k->num.lo - bias;
        return (value > (uint64_t)INT32_MAX) ? (uint32_t)INT32_MAX : (uint32_t)value;
    }
    uint64_t below = bias - k->num.lo; /* D - w = -below < 0 */
    return (below >= ((uint64_t)1 << 31)) ? (uint32_t)INT32_MIN : (uint32_t)((uint64_t)0 - below);
}

/* The VOR_RASTER_DISTANCE value of site `site` at the pixel centre
 * (qx, qy): the floor of its distance under m's metric, saturated (ADD,
 * COMPOUND and POWER: an int32 bit pattern); vor_raster.h, OUTPUT KINDS. */
VOR__ALWAYS_INLINE uint32_t metric_distance(const metric_t *m, uint32_t site, int32_t qx, int32_t qy)
{
    rank_key_t k;
    m->key(m, site, qx, qy, &k);
    const vor_raster_sites_t *s = m->sites;
    if (IN(m->metric_bit, METRIC(L1) | METRIC(LINF))) { /* L1: ax + ay < 2^33; LINF: < 2^32 */
        return saturate_u32(k.num.lo);
    } else if (IN(m->metric_bit, METRIC(LP))) {
        const vor_point_t *p = &s->points[site];
        return lp_distance(m, &k, vor__mw_magnitude((int64_t)qx - p->x), vor__mw_magnitude((int64_t)qy - p->y));
    } else if (IN(m->metric_bit, METRIC(MULT))) { /* isqrt(A) < 2^33 */
        return saturate_u32(divide_u64(isqrt128(&k.num), (uint32_t)k.w1));
    } else if (IN(m->metric_bit, METRIC(ADD))) {
        return signed_distance(isqrt128(&k.num), k.w2);
    } else if (IN(m->metric_bit, METRIC(COMPOUND))) {
        return signed_distance(divide_u64(isqrt128(&k.num), (uint32_t)k.w1), k.w2);
    } else if (IN(m->metric_bit, RATIONAL_METRICS)) {
        return rational_distance(&k);
    } else if (IN(m->metric_bit, METRIC(POWER))) {
        return power_distance(&k);
    } else { /* FARTHEST, HAUSDORFF: the squared distance */
        return saturate_u32(isqrt128(&k.num));
    }
}

/* ------------------------------------------------------------ bounds */

/* A rectangle of pixel centres, corners included. */
typedef struct rect {
    int32_t x0;
    int32_t x1;
    int32_t y0;
    int32_t y1;
} rect_t;

/* Distance from v to [lo, hi], and to the farther end. */
static uint32_t gap(int32_t v, int32_t lo, int32_t hi)
{
    return (v < lo) ? (uint32_t)lo - (uint32_t)v : (v > hi) ? (uint32_t)v - (uint32_t)hi : 0u;
}

static uint32_t reach(int32_t v, int32_t lo, int32_t hi)
{
    uint32_t a = vor__mw_magnitude((int64_t)v - lo);
    uint32_t b = vor__mw_magnitude((int64_t)v - hi);
    return (a > b) ? a : b;
}

/* Distance between the intervals [lo1, hi1] and [lo2, hi2]. */
static uint32_t interval_gap(int32_t lo1, int32_t hi1, int32_t lo2, int32_t hi2)
{
    return (lo1 > hi2) ? (uint32_t)lo1 - (uint32_t)hi2 : (lo2 > hi1) ? (uint32_t)lo2 - (uint32_t)hi1 : 0u;
}

/* *d = the squared distance from p to the farthest corner of r. */
VOR__ALWAYS_INLINE void farthest_corner(vor__mw_u128_t *d, const vor_point_t *p, const rect_t *r)
{
    square_sum(d, reach(p->x, r->x0, r->x1), reach(p->y, r->y0, r->y1));
}

/*
 * A key bounding the site's key over every pixel centre of r: its best
 * case (worst == 0: ranks no later than the site at any pixel of r) or
 * its worst case (ranks no earlier). The arguments, per metric:
 *   monotone point metrics: the distance grows with |dx| and |dy|, so the
 *     nearest point of r (per axis) and the farthest corner bound it;
 *   ELLIPTIC: the form is convex, so its largest value on r is at a
 *     corner; below, Q(v) >= (ac - b^2) / (a + c) |v|^2 (the smaller
 *     eigenvalue is det / larger >= det / trace);
 *   HAUSDORFF: the largest of the points' bounds;
 *   SEGMENT, POLYGON: the site lies in its bounding box, so the gap
 *     between that box and r is a lower bound; the distance to one of its
 *     points (an end, the first vertex) an upper one;
 *   POLYLINE: the same bounding-box gap below, the nearest vertex's
 *     farthest corner above, both divided by the site's w^2.
 */
VOR__ALWAYS_INLINE void bounds(const metric_t *m, uint32_t bit, uint32_t site, const rect_t *r,
                               int worst, rank_key_t *k)
{
    const vor_raster_sites_t *s = m->sites;
    if (IN(bit, METRIC(ELLIPTIC))) {
        const vor_point_t *p = &s->points[site];
        if (!worst) {
            vor__mw_u128_t near;
            square_sum(&near, gap(p->x, r->x0, r->x1), gap(p->y, r->y0, r->y1));
            vor__mw_u128_mul64(&k->num, &near, m->det); /* < 2^65 * 2^62 */
            vor__mw_u128_set(&k->den, m->trace);
            k->squared = 0;
            return;
        }
        vor__mw_u128_t top;
        vor__mw_u128_t q;
        vor__mw_u128_set(&top, 0);
        for (int corner = 0; corner < 4; corner++) {
            int32_t x = (corner & 1) ? r->x1 : r->x0;
            int32_t y = (corner & 2) ? r->y1 : r->y0;
            elliptic_form(&q, s, (int64_t)x - p->x, (int64_t)y - p->y);
            if (vor__mw_u128_compare(&q, &top) > 0) {
                vor__mw_u128_copy(&top, &q);
            }
        }
        vor__mw_u128_copy(&k->num, &top);
        set_unit_denominator(k);
    } else if (IN(bit, METRIC(HAUSDORFF))) {
        vor__mw_u128_t top;
        vor__mw_u128_t d;
        vor__mw_u128_set(&top, 0);
        for (uint32_t i = s->offsets[site]; i < s->offsets[site + 1u]; i++) {
            const vor_point_t *p = &s->points[i];
            if (worst != 0) {
                farthest_corner(&d, p, r);
            } else {
                square_sum(&d, gap(p->x, r->x0, r->x1), gap(p->y, r->y0, r->y1));
            }
            if (vor__mw_u128_compare(&d, &top) > 0) {
                vor__mw_u128_copy(&top, &d);
            }
        }
        vor__mw_u128_copy(&k->num, &top);
    } else if (IN(bit, METRIC(SEGMENT) | METRIC(POLYGON) | METRIC(POLYLINE))) {
        const vor_point_t *p;
        uint32_t count;
        if (IN(bit, METRIC(SEGMENT))) {
            p = &s->points[2u * site];
            count = 2;
        } else {
            p = &s->points[s->offsets[site]];
            count = s->offsets[site + 1u] - s->offsets[site];
        }
        if (worst != 0) {
            vor__mw_u128_t d;
            vor__mw_u128_t other;
            farthest_corner(&d, &p[0], r);
            uint32_t reached = IN(bit, METRIC(SEGMENT))    ? 2u
                               : IN(bit, METRIC(POLYLINE)) ? count
                                                           : 1u;
            for (uint32_t i = 1; i < reached; i++) {
                farthest_corner(&other, &p[i], r);
                if (vor__mw_u128_compare(&other, &d) < 0) {
                    vor__mw_u128_copy(&d, &other);
                }
            }
            vor__mw_u128_copy(&k->num, &d);
            set_unit_denominator(k);
            if (IN(bit, METRIC(POLYLINE))) {
                vor__mw_u128_set(&k->den, polyline_weight2(s, site));
            }
            return;
        }
        int32_t x0 = p[0].x;
        int32_t x1 = p[0].x;
        int32_t y0 = p[0].y;
        int32_t y1 = p[0].y;
        for (uint32_t i = 1; i < count; i++) {
            x0 = (p[i].x < x0) ? p[i].x : x0;
            x1 = (p[i].x > x1) ? p[i].x : x1;
            y0 = (p[i].y < y0) ? p[i].y : y0;
            y1 = (p[i].y > y1) ? p[i].y : y1;
        }
        square_sum(&k->num, interval_gap(x0, x1, r->x0, r->x1), interval_gap(y0, y1, r->y0, r->y1));
        set_unit_denominator(k);
        if (IN(bit, METRIC(POLYLINE))) {
            vor__mw_u128_set(&k->den, polyline_weight2(s, site));
        }
    } else {
        const vor_point_t *p = &s->points[site];
        /* FARTHEST ranks larger distances first: its best case is far */
        bool far = IN(bit, METRIC(FARTHEST)) ? (worst == 0) : (worst != 0);
        if (far) {
            point_key(m, bit, site, reach(p->x, r->x0, r->x1), reach(p->y, r->y0, r->y1), k);
        } else {
            point_key(m, bit, site, gap(p->x, r->x0, r->x1), gap(p->y, r->y0, r->y1), k);
        }
    }
}

/* One metric's key, comparison and bounds: site_key, key_compare and
 * bounds for its constant bit, every test on the metric decided at compile
 * time. */
#define METRIC_OPS(name)                                                       \
    static void key_##name(const metric_t *m, uint32_t site, int32_t qx, int32_t qy, \
                           rank_key_t *k)                                      \
    {                                                                          \
        site_key(m, METRIC(name), site, qx, qy, k);                            \
    }                                                                          \
    static int compare_##name(const metric_t *m, const rank_key_t *a, const rank_key_t *b) \
    {                                                                          \
        return key_compare(m, METRIC(name), a, b);                             \
    }                                                                          \
    static void bounds_##name(const metric_t *m, uint32_t site, const rect_t *r, int worst, \
                              rank_key_t *k)                                   \
    {                                                                          \
        bounds(m, METRIC(name), site, r, worst, k);                            \
    }
METRIC_OPS(L1)
METRIC_OPS(LINF)
METRIC_OPS(LP)
METRIC_OPS(ELLIPTIC)
METRIC_OPS(MULT)
METRIC_OPS(ADD)
METRIC_OPS(COMPOUND)
METRIC_OPS(FARTHEST)
METRIC_OPS(HAUSDORFF)
METRIC_OPS(SEGMENT)
METRIC_OPS(POLYGON)
METRIC_OPS(POLYLINE)
METRIC_OPS(POWER)
/* EUCLID: the generic point key (the squared distance) and its plain
 * comparison, as FARTHEST's reversed; vor_raster_nearest's only (vor_raster
 * hands Euclidean frames to raster_euclid.c). */
METRIC_OPS(EUCLID)

typedef struct metric_ops {
    void (*key)(const metric_t *m, uint32_t site, int32_t qx, int32_t qy, rank_key_t *k);
    int (*compare)(const metric_t *m, const rank_key_t *a, const rank_key_t *b);
    void (*bounds)(const metric_t *m, uint32_t site, const rect_t *r, int worst, rank_key_t *k);
} metric_ops_t;

/* Indexed by metric (EUCLID has its own family, raster_euclid.c). */
static const metric_ops_t metric_ops[] = {
#define METRIC_ENTRY(name) [VOR_METRIC_##name] = {key_##name, compare_##name, bounds_##name}
    METRIC_ENTRY(L1),       METRIC_ENTRY(LINF),     METRIC_ENTRY(LP),
    METRIC_ENTRY(ELLIPTIC), METRIC_ENTRY(MULT),     METRIC_ENTRY(ADD),
    METRIC_ENTRY(COMPOUND), METRIC_ENTRY(FARTHEST), METRIC_ENTRY(HAUSDORFF),
    METRIC_ENTRY(SEGMENT),  METRIC_ENTRY(POLYGON),  METRIC_ENTRY(POLYLINE),
    METRIC_ENTRY(POWER),
#undef METRIC_ENTRY
};

/* ----------------------------------------------------------- culling */

#define ALL_SITES 0xFFFFFFFFu
#define TILES_PER_BLOCK 8u

/* ------------------------------------------------------------- ranks */

/*
 * The K best of a stream of offered sites (vor_raster_nearest): the kept
 * ones in rank order, a later offer ranking before an earlier one only
 * when strictly better, so that offers in index order break ties to the
 * smaller index. The keys live in the work memory, K + 1 slots: slot[r]
 * holds the key of rank r < kept, slot[kept] is the free one the next
 * offer's key is made in; an insertion moves slot numbers and sites, never
 * a key.
 */
typedef struct ranks {
    uint32_t k;       /* K */
    uint32_t ranked;  /* K' = min(K, sites): the ranks every pixel gets */
    uint32_t kept;    /* ranked so far, <= k */
    rank_key_t *keys; /* [k + 1] */
    uint32_t *slot;   /* [k + 1], a permutation of 0 .. k */
    uint32_t *site;   /* [k + 1]: the site of rank r */
    uint32_t *labels; /* NEAREST: the pixels of the row being made, else NULL */
    uint32_t *sets;   /* KSETS: the k-sets of the row being made, else NULL */
} ranks_t;

/* The bytes of a rank: its key, slot and site (VOR_RASTER_NEAREST_WORK_BYTES
 * counts 112). */
typedef char vor__rank_size_check[((sizeof(rank_key_t) + 8u) <= 112u) ? 1 : -1];

/* The key slot of the next offer. */
static rank_key_t *ranks_free(const ranks_t *ko)
{
    return &ko->keys[ko->slot[ko->kept]];
}

/* Offers site, its key made in the free slot (ranks_free): it takes rank
 * r when it ranks strictly before the kept site of rank r and not before
 * that of r - 1, and r < K; the K-th then drops out when K were kept. */
static void ranks_offer(const metric_t *m, ranks_t *ko, uint32_t site)
{
    const uint32_t free_slot = ko->slot[ko->kept];
    const rank_key_t *key = &ko->keys[free_slot];
    uint32_t at = ko->kept;
    while ((at > 0u) && (m->compare(m, key, &ko->keys[ko->slot[at - 1u]]) < 0)) {
        at--;
    }
    if (at == ko->k) {
        return; /* not before the K-th */
    }
    for (uint32_t q = ko->kept; q > at; q--) {
        ko->slot[q] = ko->slot[q - 1u];
        ko->site[q] = ko->site[q - 1u];
    }
    ko->slot[at] = free_slot;
    ko->site[at] = site;
    if (ko->kept < ko->k) {
        ko->kept++;
    }
}

/* The sites of list[0..count) (NULL: sites 0..count-1) that can rank
 * within K at some pixel of r, in index order, into out; returns their
 * number, or ALL_SITES when more than capacity survive. K sites whose
 * worst cases are at most the K-th smallest worst case W rank no later
 * than W at every pixel of r; a site whose best case is strictly later
 * than W is strictly behind each of them there, so it is never within K
 * (select_sites is the case K = 1). Fewer than K sites: all can. */
static uint32_t select_ranked(const metric_t *m, ranks_t *ko, const rect_t *r,
                              const uint32_t *list, uint32_t count, uint32_t *out,
                              size_t capacity)
{
    ko->kept = 0;
    for (uint32_t c = 0; c < count; c++) {
        uint32_t site = (list != NULL) ? list[c] : c;
        m->bounds(m, site, r, 1, ranks_free(ko));
        ranks_offer(m, ko, site);
    }
    const rank_key_t *bar = (ko->kept == ko->k) ? &ko->keys[ko->slot[ko->k - 1u]] : NULL;
    rank_key_t *best_case = ranks_free(ko);
    uint32_t kept = 0;
    for (uint32_t c = 0; c < count; c++) {
        uint32_t site = (list != NULL) ? list[c] : c;
        bool can = true;
        if (bar != NULL) {
            m->bounds(m, site, r, 0, best_case);
            can = m->compare(m, best_case, bar) <= 0;
        }
        if (can) {
            if (kept == capacity) {
                return ALL_SITES;
            }
            out[kept] = site;
            kept++;
        }
    }
    return kept;
}

/* The sites of list[0..count) (NULL: sites 0..count-1) that can rank
 * first (alone or tied) at some pixel of r, in index order, into out;
 * returns their number, or ALL_SITES when more than capacity survive. */
static uint32_t select_sites(const metric_t *m, const rect_t *r, const uint32_t *list,
                             uint32_t count, uint32_t *out, size_t capacity)
{
    rank_key_t keys[2];
    rank_key_t best_case;
    uint32_t slot = 0;
    m->bounds(m, (list != NULL) ? list[0] : 0u, r, 1, &keys[0]);
    for (uint32_t c = 1; c < count; c++) {
        m->bounds(m, (list != NULL) ? list[c] : c, r, 1, &keys[slot ^ 1u]);
        if (m->compare(m, &keys[slot ^ 1u], &keys[slot]) < 0) {
            slot ^= 1u;
        }
    }
    /* keys[slot]: the best worst case, reached at every pixel of r */
    uint32_t kept = 0;
    for (uint32_t c = 0; c < count; c++) {
        uint32_t site = (list != NULL) ? list[c] : c;
        m->bounds(m, site, r, 0, &best_case);
        if (m->compare(m, &best_case, &keys[slot]) <= 0) {
            if (kept == capacity) {
                return ALL_SITES;
            }
            out[kept] = site;
            kept++;
        }
    }
    return kept;
}

static rect_t columns_rect(const metric_t *m, uint32_t first, uint32_t last, int32_t y0,
                           int32_t y1)
{
    rect_t r;
    r.x0 = (int32_t)(m->frame->origin_x + vor__offset(first, m->frame->step_x));
    r.x1 = (int32_t)(m->frame->origin_x + vor__offset(last, m->frame->step_x));
    r.y0 = y0;
    r.y1 = y1;
    return r;
}

/* Fills the pool with the tile lists of the band starting at band_first:
 * per tile, a count (or ALL_SITES) and that many site ids: the sites that
 * can rank first there (ko NULL), or within K (ko's; select_ranked).
 * Forced inline, so that vor_raster's instance has no k-order branch. */
VOR__ALWAYS_INLINE void cull_with(metric_t *m, ranks_t *ko)
{
    uint32_t last_row = m->band_first + TILE_ROWS - 1u;
    if (last_row >= m->frame->height) {
        last_row = m->frame->height - 1u;
    }
    int32_t y0 = (int32_t)(m->frame->origin_y + vor__offset(m->band_first, m->frame->step_y));
    int32_t y1 = (int32_t)(m->frame->origin_y + vor__offset(last_row, m->frame->step_y));
    uint32_t *block = m->pool;
    uint32_t *lists = m->pool + m->n;
    size_t room = m->pool_words - m->n; /* >= tiles (prepare) */
    size_t at = 0;
    uint32_t tile = 0;
    uint32_t block_columns = m->tile_width * TILES_PER_BLOCK;
    for (uint32_t first = 0; first < m->frame->width; first += block_columns) {
        uint32_t end = ((m->frame->width - first) > block_columns) ? (first + block_columns) : m->frame->width;
        rect_t r = columns_rect(m, first, end - 1u, y0, y1);
        uint32_t block_count = (ko == NULL) ? select_sites(m, &r, NULL, m->n, block, m->n)
                                            : select_ranked(m, ko, &r, NULL, m->n, block, m->n);
        for (uint32_t column = first; column < end; column += m->tile_width) {
            uint32_t tile_end = ((end - column) > m->tile_width) ? (column + m->tile_width) : end;
            rect_t t = columns_rect(m, column, tile_end - 1u, y0, y1);
            size_t later = m->tiles - tile - 1u; /* one word kept for each later tile */
            size_t capacity = room - at - 1u - later;
            uint32_t kept =
                (ko == NULL)
                    ? select_sites(m, &t, block, block_count, lists + at + 1u, capacity)
                    : select_ranked(m, ko, &t, block, block_count, lists + at + 1u, capacity);
            lists[at] = kept;
            at += 1u + ((kept == ALL_SITES) ? 0u : kept);
            tile++;
        }
    }
}

static void cull_band(metric_t *m)
{
    cull_with(m, NULL);
}

static void cull_ranked(metric_t *m, ranks_t *ko)
{
    cull_with(m, ko);
}

/* The first-ranked site at (qx, qy) among list[0..count) (NULL: all),
 * which is in increasing index order: a later site takes over only when
 * strictly better, so ties stay with the smaller index. */
static uint32_t nearest(const metric_t *m, const uint32_t *list, uint32_t count, int32_t qx,
                        int32_t qy)
{
    rank_key_t keys[2];
    uint32_t slot = 0;
    uint32_t best = (list != NULL) ? list[0] : 0u;
    m->key(m, best, qx, qy, &keys[0]);
    for (uint32_t c = 1; c < count; c++) {
        uint32_t site = (list != NULL) ? list[c] : c;
        m->key(m, site, qx, qy, &keys[slot ^ 1u]);
        if (m->compare(m, &keys[slot ^ 1u], &keys[slot]) < 0) {
            slot ^= 1u;
            best = site;
        }
    }
    return best;
}

/* Ranks the sites of list[0..count) (NULL: all; in increasing index
 * order) at pixel i of row qy, the one at (qx, qy), into ko: its NEAREST
 * labels and its k-set (sorted by index) are written where ko says.
 * Returns the K'-th ranked site, the pixel's label. */
static uint32_t rank_pixel(const metric_t *m, ranks_t *ko, const uint32_t *list, uint32_t count,
                           int32_t qx, int32_t qy, uint32_t i)
{
    ko->kept = 0;
    for (uint32_t c = 0; c < count; c++) {
        uint32_t site = (list != NULL) ? list[c] : c;
        m->key(m, site, qx, qy, ranks_free(ko));
        ranks_offer(m, ko, site);
    }
    /* ko->kept == ko->ranked: the culling keeps the K' ranked sites */
    if (ko->labels != NULL) {
        uint32_t *px = ko->labels + ((size_t)i * ko->k);
        for (uint32_t r = 0; r < ko->k; r++) {
            px[r] = (r < ko->kept) ? ko->site[r] : VOR_RASTER_NO_SITE;
        }
    }
    if (ko->sets != NULL) {
        uint32_t *set = ko->sets + ((size_t)i * ko->ranked);
        for (uint32_t r = 0; r < ko->kept; r++) { /* insertion by index */
            uint32_t at = r;
            while ((at > 0u) && (set[at - 1u] > ko->site[r])) {
                set[at] = set[at - 1u];
                at--;
            }
            set[at] = ko->site[r];
        }
    }
    return ko->site[ko->kept - 1u];
}

/* The runs of row j: each pixel's nearest site (ko NULL), or its K'-th
 * ranked (ko's: rank_pixel). Forced inline, so that vor_raster's
 * instance has no k-order branch. */
VOR__ALWAYS_INLINE uint32_t scan_row(metric_t *m, ranks_t *ko, uint32_t j, vor__run_t *runs)
{
    if (!m->brute && (!m->band_valid || (j >= (m->band_first + TILE_ROWS)))) {
        m->band_first = j - (j % TILE_ROWS);
        m->band_valid = 1;
        if (ko == NULL) {
            cull_band(m);
        } else {
            cull_ranked(m, ko);
        }
    }
    const uint32_t width = m->frame->width;
    int32_t qy = (int32_t)(m->frame->origin_y + vor__offset(j, m->frame->step_y));
    const uint32_t *lists = m->pool + m->n;
    size_t at = 0;
    uint32_t count = 0;
    uint32_t span = m->brute ? width : m->tile_width;
    for (uint32_t first = 0; first < width; first += span) {
        uint32_t end = ((width - first) > span) ? (first + span) : width;
        const uint32_t *list = NULL;
        uint32_t candidates = m->n;
        if (!m->brute) {
            if (lists[at] != ALL_SITES) {
                list = lists + at + 1u;
                candidates = lists[at];
            }
            at += 1u + ((list != NULL) ? candidates : 0u);
        }
        for (uint32_t i = first; i < end; i++) {
            int32_t qx = (int32_t)(m->origin_x + vor__offset(i, m->step_x));
            uint32_t site = (ko == NULL) ? nearest(m, list, candidates, qx, qy)
                                         : rank_pixel(m, ko, list, candidates, qx, qy, i);
            count = vor__run_push(runs, count, i, site);
        }
    }
    return count;
}

/* The family's producers for the scan (vor__raster_row_fn,
 * vor__raster_distances_fn). */
static uint32_t row(void *state, uint32_t j, vor__run_t *runs)
{
    return scan_row(state, NULL, j, runs);
}

/* ------------------------------------------------------------ set up */

/* VOR_OK when the metric's fields are usable (weights, exponent, form,
 * offsets); else VOR_ERR_ARG. Reads every site once. */
VOR__ALWAYS_INLINE int metric_check(const vor_raster_sites_t *s)
{
    if ((unsigned)s->metric > (unsigned)VOR_METRIC_POWER) {
        return VOR_ERR_ARG;
    }
    const uint32_t bit = (uint32_t)1 << (uint32_t)s->metric;
    if (IN(bit, METRIC(L1) | METRIC(LINF) | METRIC(FARTHEST) | METRIC(SEGMENT))) {
        return VOR_OK;
    } else if (IN(bit, METRIC(POWER))) {
        return (s->power_weights != NULL) ? VOR_OK : VOR_ERR_ARG; /* any int64 */
    } else if (IN(bit, METRIC(LP))) {
        return ((s->lp_exponent >= 1u) && (s->lp_exponent <= 8u)) ? VOR_OK : VOR_ERR_ARG;
    } else if (IN(bit, METRIC(ELLIPTIC))) {
        /* positive definite: a > 0 and a c - b^2 > 0 (each product < 2^62) */
        return (s->form_a > 0) &&
                       vor__mul_i32(s->form_a, s->form_c) > vor__mul_i32(s->form_b, s->form_b)
                   ? VOR_OK
                   : VOR_ERR_ARG;
    } else if (IN(bit, METRIC(MULT) | METRIC(ADD) | METRIC(COMPOUND))) {
        if (((s->metric != VOR_METRIC_ADD) && (s->mult_weights == NULL)) ||
            ((s->metric != VOR_METRIC_MULT) && (s->add_weights == NULL))) {
            return VOR_ERR_ARG;
        }
        for (uint32_t k = 0; (s->metric != VOR_METRIC_ADD) && (k < s->count); k++) {
            if (s->mult_weights[k] < 1) {
                return VOR_ERR_ARG;
            }
        }
        return VOR_OK;
    } else if (IN(bit, METRIC(HAUSDORFF) | METRIC(POLYGON) | METRIC(POLYLINE))) {
        if (s->offsets == NULL) {
            return VOR_ERR_ARG;
        }
        for (uint32_t k = 0; k < s->count; k++) {
            if (s->offsets[k] >= s->offsets[k + 1u]) {
                return VOR_ERR_ARG; /* every site has a point */
            }
            if ((s->metric == VOR_METRIC_POLYLINE) && (s->mult_weights != NULL) &&
                (s->mult_weights[k] < 1)) {
                return VOR_ERR_ARG;
            }
        }
        return VOR_OK;
    } else {
        return VOR_ERR_ARG;
    }
}

/* Widens [lo, hi] to hold v. */
static void widen(int32_t v, int32_t *lo, int32_t *hi)
{
    *lo = (v < *lo) ? v : *lo;
    *hi = (v > *hi) ? v : *hi;
}

/* Limbs holding the additive comparison of square roots of values below
 * 2^a_bits with a weight term below 2^delta_bits: E^2 < 2^(2 a_bits),
 * 4 delta^2 B < 2^(2 + 2 delta_bits + a_bits), plus a sign bit. E, F in
 * signed form (below 2^(max(a_bits, 2 delta_bits) + 1)) fit in the
 * second bound's bits already. */
static uint32_t additive_limbs(uint32_t a_bits, uint32_t delta_bits)
{
    uint32_t bits = 2u * a_bits;
    if ((2u + (2u * delta_bits) + a_bits) > bits) {
        bits = 2u + (2u * delta_bits) + a_bits;
    }
    return (bits + 1u + VOR__LIMB_WIDTH - 1u) / VOR__LIMB_WIDTH;
}

/* Sets m up for the checked request r (its sites past metric_check): the
 * comparison widths from the span of sites and frame, and the tiles. */
VOR__ALWAYS_INLINE void prepare(metric_t *m, const vor__raster_t *r)
{
    const vor_raster_frame_t *frame = r->frame;
    const vor_raster_sites_t *s = r->sites;
    /* the culling pool: the work memory after the rows, at least 12 n + 14
     * words (the macro's 48 n + 64 bytes, less the rows and alignment) */
    const size_t pool_words = r->rest_bytes / sizeof(uint32_t);
    m->frame = frame;
    m->origin_x = frame->origin_x;
    m->step_x = frame->step_x;
    m->sites = s;
    m->metric = s->metric;
    m->metric_bit = (uint32_t)1 << (uint32_t)s->metric;
    m->key = metric_ops[s->metric].key;
    m->compare = metric_ops[s->metric].compare;
    m->bounds = metric_ops[s->metric].bounds;
    m->n = s->count;
    m->brute = r->brute;
    m->pool = (uint32_t *)(void *)r->rest;
    m->pool_words = pool_words;
    m->band_valid = 0;
    m->band_first = 0;
    m->limbs = 1;
    m->lp_narrow = 1;
    m->det = 0;
    m->trace = 0;

    /* span: the largest coordinate difference between any two of the
     * site points and pixel centres (< 2^32); it sets the widths */
    int32_t x0 = frame->origin_x;
    int32_t y0 = frame->origin_y;
    int32_t x1 = (int32_t)(frame->origin_x + vor__offset(frame->width - 1u, frame->step_x));
    int32_t y1 = (int32_t)(frame->origin_y + vor__offset(frame->height - 1u, frame->step_y));
    uint32_t first = 0;
    uint32_t end = s->count;
    if (s->metric == VOR_METRIC_SEGMENT) {
        end = 2u * s->count;
    }
    for (uint32_t k = 0; k < s->count; k++) {
        if ((s->metric == VOR_METRIC_HAUSDORFF) || (s->metric == VOR_METRIC_POLYGON) ||
            (s->metric == VOR_METRIC_POLYLINE)) {
            first = s->offsets[k];
            end = s->offsets[k + 1u];
        } else if (k > 0u) {
            break; /* the points are one array: walked once below */
        } else {
            /* no other case */
        }
        for (uint32_t i = first; i < end; i++) {
            widen(s->points[i].x, &x0, &x1);
            widen(s->points[i].y, &y0, &y1);
        }
    }
    int64_t width = (int64_t)x1 - x0; /* >= 0 */
    int64_t height = (int64_t)y1 - y0;
    uint64_t span_x = (uint64_t)width;
    uint64_t span_y = (uint64_t)height;
    uint32_t span_bits = vor__mw_bit_length((span_x > span_y) ? span_x : span_y); /* <= 32 */

    if (IN(m->metric_bit, METRIC(LP))) {
        uint32_t bits = (s->lp_exponent * span_bits) + 1u; /* |dx|^p + |dy|^p < 2^bits */
        m->lp_narrow = bits <= 128u;
        m->limbs = (bits + VOR__LIMB_WIDTH - 1u) / VOR__LIMB_WIDTH;
    } else if (IN(m->metric_bit, METRIC(ELLIPTIC))) {
        int64_t det = vor__mul_i32(s->form_a, s->form_c) - vor__mul_i32(s->form_b, s->form_b);
        m->det = (uint64_t)det; /* > 0, checked by metric_check */
        m->trace = (uint32_t)s->form_a + (uint32_t)s->form_c; /* < 2^32 */
    } else if (IN(m->metric_bit, METRIC(ADD) | METRIC(COMPOUND))) {
        int32_t lo = s->add_weights[0];
        int32_t hi = s->add_weights[0];
        int32_t heaviest = 1;
        for (uint32_t k = 0; k < s->count; k++) {
            widen(s->add_weights[k], &lo, &hi);
            if ((s->metric == VOR_METRIC_COMPOUND) && (s->mult_weights[k] > heaviest)) {
                heaviest = s->mult_weights[k];
            }
        }
        /* squared distances < 2^(2 span_bits + 1); weight differences
         * < 2^delta_bits; COMPOUND multiplies by the w1 products */
        uint32_t a_bits = (2u * span_bits) + 1u;
        int64_t delta = (int64_t)hi - lo; /* >= 0 */
        uint32_t delta_bits = vor__mw_bit_length((uint64_t)delta);
        if (s->metric == VOR_METRIC_COMPOUND) {
            uint32_t w_bits = vor__mw_bit_length((uint32_t)heaviest);
            a_bits += 2u * w_bits;
            delta_bits += 2u * w_bits;
        }
        m->limbs = additive_limbs(a_bits, delta_bits);
    } else {
        /* no other case */
    }

    /* tiles: 16 columns, wider when the pool could not hold one count
     * word per tile after the block list */
    uint32_t shift = 4;
    while ((size_t)((frame->width + (1u << shift) - 1u) >> shift) > (pool_words - m->n)) {
        shift++;
    }
    m->tile_width = 1u << shift;
    m->tiles = (frame->width + m->tile_width - 1u) >> shift;
}

/* ----------------------------------------------------- distance pixels */

/* The floor of each pixel's own site's distance under m's metric. */
VOR__ALWAYS_INLINE void distances(const void *state, uint32_t j, const vor__run_t *runs,
                                  uint32_t count, uint32_t *px)
{
    const metric_t *m = state;
    int32_t qy = (int32_t)(m->frame->origin_y + vor__offset(j, m->frame->step_y));
    uint32_t i = 0;
    for (uint32_t r = 0; r < count; r++) {
        for (; i < runs[r].end; i++) {
            int32_t qx = (int32_t)(m->origin_x + vor__offset(i, m->step_x));
            px[i] = metric_distance(m, runs[r].site, qx, qy);
        }
    }
}

/* ------------------------------------------------------- entry point */

int vor_raster(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
               const vor_raster_output_t *out, const vor_raster_options_t *options,
               void *work, size_t work_bytes)
{
    if ((sites != NULL) && (sites->metric == VOR_METRIC_EUCLID)) {
        return vor_raster_euclid(frame, sites, out, options, work, work_bytes);
    }
    vor__raster_t r;
    int status = vor__raster_check(&r, frame, sites, out, options, work, work_bytes);
    if (status != VOR_OK) {
        return status;
    }
    VOR_ASSERT(sites != NULL); /* vor__raster_check rejects NULL */
    if (metric_check(sites) != VOR_OK) {
        return VOR_ERR_ARG;
    }
    metric_t m;
    prepare(&m, &r);
    return vor__raster_scan(&r, &m, row, distances);
}

/* ------------------------------------------------------- k-order frames */

/* floor(s / d) = (s ceil(2^16 / d)) >> 16 for d = 1 .. 16 and s < 2^10:
 * the error s (d ceil(2^16 / d) - 2^16) / (d 2^16) < s 15 / (d 2^16) is
 * below 1 / d, so the floor holds (no divider on Cortex-M0). */
static const uint32_t reciprocal16[VOR_RASTER_MAX_NEAREST + 1u] = {
    0u,    65536u, 32768u, 21846u, 16384u, 13108u, 10923u, 9363u, 8192u,
    7282u, 6554u,  5958u,  5462u,  5042u,  4682u,  4370u,  4096u,
};

/* The KSETS colour of a k-set of d sites: per channel, the mean of their
 * palette colours, rounded down. */
static uint16_t kset_colour(const uint16_t *palette, const uint32_t *set, uint32_t d)
{
    uint32_t red = 0;
    uint32_t green = 0;
    uint32_t blue = 0;
    for (uint32_t r = 0; r < d; r++) {
        uint32_t c = palette[set[r]];
        red += c >> 11;
        green += (c >> 5) & 0x3Fu;
        blue += c & 0x1Fu;
    }
    red = (red * reciprocal16[d]) >> 16;
    green = (green * reciprocal16[d]) >> 16;
    blue = (blue * reciprocal16[d]) >> 16;
    return (uint16_t)((red << 11) | (green << 5) | blue);
}

/* Do the sets a[0..d) and b[0..d) (sorted) differ? */
static bool sets_differ(const uint32_t *a, const uint32_t *b, uint32_t d)
{
    for (uint32_t r = 0; r < d; r++) {
        if (a[r] != b[r]) {
            return true;
        }
    }
    return false;
}

/* The KSETS pixels of a row from its k-sets (row) and the next row's
 * (below; NULL for the last row), d sites each; boundary: the colour of
 * a pixel whose right or lower neighbour has another k-set. */
static void write_ksets(const vor_raster_output_t *out, uint16_t boundary, uint32_t width,
                        uint32_t d, const uint32_t *row_sets, const uint32_t *below, uint16_t *px)
{
    for (uint32_t i = 0; i < width; i++) {
        const uint32_t *set = row_sets + ((size_t)i * d);
        bool edge = ((i + 1u) < width) && sets_differ(set, set + d, d);
        if (!edge && (below != NULL)) {
            edge = sets_differ(set, below + ((size_t)i * d), d);
        }
        px[i] = edge ? boundary : kset_colour(out->palette565, set, d);
    }
}

int vor_raster_nearest(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                       uint32_t k, const vor_raster_output_t *out,
                       const vor_raster_options_t *options, void *work, size_t work_bytes)
{
    if (k == 0u) {
        return VOR_ERR_ARG;
    }
    vor__raster_t r;
    int status = vor__raster_check_order(&r, frame, sites, out, options, work, work_bytes, k);
    if (status != VOR_OK) {
        return status;
    }
    VOR_ASSERT((sites != NULL) && (out != NULL)); /* rejected by the check */
    if ((sites->metric != VOR_METRIC_EUCLID) && (metric_check(sites) != VOR_OK)) {
        return VOR_ERR_ARG;
    }
    /* the ranks and the two rows of k-sets before the family's pool
     * (within VOR_RASTER_NEAREST_WORK_BYTES, less VOR_RASTER_WORK_BYTES) */
    const uint32_t width = r.frame->width;
    ranks_t ko;
    uint32_t *sets[2];
    ko.k = k;
    ko.ranked = (k < sites->count) ? k : sites->count;
    ko.kept = 0;
    ko.keys = (rank_key_t *)(void *)r.rest;
    ko.slot = (uint32_t *)(void *)(r.rest + (((size_t)k + 1u) * sizeof(rank_key_t)));
    ko.site = ko.slot + k + 1u;
    sets[0] = ko.site + k + 1u;
    sets[1] = sets[0] + ((size_t)width * ko.ranked);
    size_t used = vor__align8((((size_t)k + 1u) * (sizeof(rank_key_t) + 8u)) +
                              ((size_t)width * ko.ranked * 8u));
    r.rest += used;
    r.rest_bytes -= used;
    for (uint32_t q = 0; q <= k; q++) {
        ko.slot[q] = q;
    }
    ko.labels = NULL;
    ko.sets = NULL;
    metric_t m;
    prepare(&m, &r);
    if (sites->metric == VOR_METRIC_EUCLID) {
        m.key = key_EUCLID;
        m.compare = compare_EUCLID;
        m.bounds = bounds_EUCLID;
    }
    /* the scan (vor__raster_scan's), with the rows of k-order kinds:
     * NEAREST rows written in place, KSETS rows one row late, when the
     * k-sets of the row below are known */
    const enum vor_raster_kind kind = out->kind;
    vor__raster_start(&r);
    if (kind == VOR_RASTER_KSETS) {
        r.bands.hold = 1;
    }
    for (uint32_t j = 0; j <= r.frame->height; j++) { /* j = height: the end */
        uint32_t count = 0;
        if (j < r.frame->height) {
            vor__run_t *runs = vor__bands_runs(&r.bands);
            ko.labels = (kind == VOR_RASTER_NEAREST) ? (uint32_t *)vor__bands_pixels(&r.bands) : NULL;
            ko.sets = (kind == VOR_RASTER_KSETS) ? sets[j & 1u] : NULL;
            count = scan_row(&m, &ko, j, runs);
            if (kind == VOR_RASTER_DISTANCE) {
                distances(&m, j, runs, count, vor__bands_pixels(&r.bands));
            }
        }
        if ((kind == VOR_RASTER_KSETS) && (j > 0u)) {
            uint8_t *row_px = (uint8_t *)out->band + ((size_t)(j - 1u - r.bands.band_first) * r.row_bytes);
            write_ksets(out, (options != NULL) ? options->boundary565 : 0u, width, ko.ranked,
                        sets[(j - 1u) & 1u],
                        (j < r.frame->height) ? sets[j & 1u] : NULL, (uint16_t *)(void *)row_px);
        }
        if (vor__bands_put_flush(&r.bands, count) != 0) {
            return VOR_ERR_STOPPED;
        }
    }
    return VOR_OK;
}
