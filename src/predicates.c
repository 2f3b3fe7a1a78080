/* SPDX-License-Identifier: MIT */
/*
 * predicates.c - the exact geometric predicates and their symbolic
 * perturbation.
 *
 * Integer counterpart of the hybrid arithmetic of Kanda, sections 4-5: instead of a
 * floating-point filter with an error bound, each predicate measures the
 * magnitude of its coordinate differences and evaluates in the narrowest
 * integer width that cannot overflow for that magnitude. Every tier is
 * exact; the tiers differ only in cost. The bounds are derived next to
 * each tier.
 *
 * All coordinate differences of int32 values fit in 33 bits signed, so
 * their magnitudes fit in uint32_t: |d| <= 2^32 - 1.
 */
#include <stdbool.h>

#include "vor.h"

#include "multiword.h"
#include "predicates.h"

/* (k + 1) mod 3 without a division (Cortex-M0 has no divide instruction) */
static const unsigned char next_of[3] = {1, 2, 0};

/* Sign of a*b - c*d for |a|, |b|, |c|, |d| <= 2^32 - 1, without any value
 * wider than 64 bits: compare the products' signs, then their magnitudes. */
int vor__compare_products(int64_t a, int64_t b, int64_t c, int64_t d)
{
    int sp = vor__mw_sign64(a) * vor__mw_sign64(b);
    int sq = vor__mw_sign64(c) * vor__mw_sign64(d);
    if (sp != sq) {
        return (sp > sq) ? 1 : -1;
    }
    if (sp == 0) {
        return 0;
    }
    uint64_t mp = vor__mul_u32(vor__mw_magnitude(a), vor__mw_magnitude(b));
    uint64_t mq = vor__mul_u32(vor__mw_magnitude(c), vor__mw_magnitude(d));
    int by_magnitude = (mp > mq) - (mp < mq);
    return (sp > 0) ? by_magnitude : -by_magnitude;
}

/* ------------------------------------------------------------------ */
/* orient2d                                                            */

int vor__orient2d_sign(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c)
{
    return vor__orient2d_exact(a, b, c, NULL);
}

int vor_orient2d(vor_point_t a, vor_point_t b, vor_point_t c)
{
    return vor__orient2d_exact(&a, &b, &c, NULL);
}

/* ------------------------------------------------------------------ */
/* closer                                                              */

int vor_closer(vor_point_t q, vor_point_t a, vor_point_t b)
{
    return vor__closer_sign(&q, &a, &b, NULL);
}

int vor__closer_sign(const vor_point_t *q, const vor_point_t *a, const vor_point_t *b,
                     vor_stats_t *stats)
{
    int64_t ax = (int64_t)a->x - q->x;
    int64_t ay = (int64_t)a->y - q->y;
    int64_t bx = (int64_t)b->x - q->x;
    int64_t by = (int64_t)b->y - q->y;
    uint64_t m = vor__mw_bound(ax) | vor__mw_bound(ay) | vor__mw_bound(bx) | vor__mw_bound(by);
    if (m < 0x80000000u) {
        /* the differences fit int32: squares <= 2^62, sums of two <= 2^63
         * fit uint64 */
        VOR__COUNT(stats, closer[VOR_TIER_NARROW]);
        uint64_t da = (uint64_t)vor__mul_i32((int32_t)ax, (int32_t)ax) +
                      (uint64_t)vor__mul_i32((int32_t)ay, (int32_t)ay);
        uint64_t db = (uint64_t)vor__mul_i32((int32_t)bx, (int32_t)bx) +
                      (uint64_t)vor__mul_i32((int32_t)by, (int32_t)by);
        return (da > db) - (da < db);
    }
    /* squares < 2^64, sums of two < 2^65: keep the carry as a 65th bit */
    VOR__COUNT(stats, closer[VOR_TIER_WIDE]);
    uint64_t sa = vor__mul_u32(vor__mw_magnitude(ax), vor__mw_magnitude(ax));
    uint64_t da = sa + vor__mul_u32(vor__mw_magnitude(ay), vor__mw_magnitude(ay));
    unsigned ca = (da < sa) ? 1u : 0u;
    uint64_t sb = vor__mul_u32(vor__mw_magnitude(bx), vor__mw_magnitude(bx));
    uint64_t db = sb + vor__mul_u32(vor__mw_magnitude(by), vor__mw_magnitude(by));
    unsigned cb = (db < sb) ? 1u : 0u;
    if (ca != cb) {
        return (ca > cb) ? 1 : -1;
    }
    return (da > db) - (da < db);
}

/* ------------------------------------------------------------------ */
/* incircle                                                            */

/*
 * The mid and wide incircle tiers work on 64-bit words (two limbs with
 * 32-bit limbs). The determinant is a sum of three products of a lift
 * (>= 0) and a signed cross product, each factor below 2^65: a word plus
 * a 65th bit. Positive and negative products are summed apart, as 3-word
 * (192-bit) unsigned numbers, vor__mw_u192_t, and compared at the end: no
 * negation, and the sign only selects an accumulator, which compiles
 * without branches.
 */
/* Both sums zeroed word by word: an aggregate initializer of this size
 * becomes a memset call on some targets, and the library calls nothing. */
VOR__INLINE void clear_sums(vor__mw_u192_t sums[2])
{
    for (unsigned i = 0; i < 2u; i++) {
        sums[i].w[0] = 0u;
        sums[i].w[1] = 0u;
        sums[i].w[2] = 0u;
    }
}

/* Mid tier term, differences in int32 ([-2^31, 2^31 - 1]): the lift
 * <= 2^63 fits uint64, the cross product <= 2^63 - 2^31 fits int64 (its
 * two products cannot both reach 2^62 with opposite signs), the product of
 * the two < 2^126, and each sum of up to three such < 2^128: two words.
 * d[] holds a-d, b-d, c-d as x, y pairs; the term is lift(p) cross(u, v). */
VOR__INLINE void mid_term(vor__mw_u128_t sums[2], const int64_t d[6], unsigned p,
                          unsigned u, unsigned v)
{
    int32_t px = (int32_t)d[p];
    int32_t py = (int32_t)d[p + 1u];
    int32_t ux = (int32_t)d[u];
    int32_t uy = (int32_t)d[u + 1u];
    int32_t vx = (int32_t)d[v];
    int32_t vy = (int32_t)d[v + 1u];
    uint64_t lift = (uint64_t)vor__mul_i32(px, px) + (uint64_t)vor__mul_i32(py, py);
    int64_t cross = vor__mul_i32(ux, vy) - vor__mul_i32(uy, vx);
    bool negative = cross < 0;
    uint64_t magnitude_of_cross = negative ? 0u - (uint64_t)cross : (uint64_t)cross;
    vor__mw_u128_add_product(&sums[negative], lift, magnitude_of_cross);
}

/* x^2 + y^2 of differences below 2^32 in magnitude: below 2^65, a word
 * and its 65th bit (*high). */
VOR__ALWAYS_INLINE uint64_t wide_lift(int64_t x, int64_t y, uint64_t *high)
{
    uint64_t sx = vor__mul_u32(vor__mw_magnitude(x), vor__mw_magnitude(x));
    uint64_t lift = sx + vor__mul_u32(vor__mw_magnitude(y), vor__mw_magnitude(y));
    *high = (lift < sx) ? 1u : 0u;
    return lift;
}

/* ux vy - uy vx for entries below 2^32 in magnitude, as magnitude (a word
 * and its 65th bit, *high) and sign (returned: true when negative). The
 * cross product is (+-m1) + (+-m2) with m1, m2 < 2^64. */
VOR__INLINE bool wide_cross(int64_t ux, int64_t uy, int64_t vx, int64_t vy, uint64_t *low,
                            uint64_t *high)
{
    bool n1 = (ux < 0) != (vy < 0);
    bool n2 = (uy < 0) == (vx < 0);
    uint64_t m1 = vor__mul_u32(vor__mw_magnitude(ux), vor__mw_magnitude(vy));
    uint64_t m2 = vor__mul_u32(vor__mw_magnitude(uy), vor__mw_magnitude(vx));
    if (n1 == n2) { /* same signs: the magnitudes add, up to 65 bits */
        *low = m1 + m2;
        *high = (*low < m1) ? 1u : 0u;
        return n1;
    }
    bool second = m2 > m1; /* opposite signs: the larger magnitude wins */
    *low = second ? (m2 - m1) : (m1 - m2);
    *high = 0u;
    return second ? n2 : n1;
}

/* A cross product as wide_cross gives it: its sign and its magnitude, a
 * word and its 65th bit. */
typedef struct {
    uint64_t low;
    uint64_t high;
    bool negative;
} wide_cross_t;

/* Wide tier term, D < 2^32: the lift and |cross| < 2^65, the product
 * < 2^130; each of the two sums stays below 2^132. The cross product
 * goes back in *cross, for the power test's weight term (power_wide);
 * the incircle's (wide_sums) drops it, and inlined, its stores fold
 * away. */
VOR__INLINE void wide_term(vor__mw_u192_t sums[2], const int64_t d[6], unsigned p, unsigned u,
                           unsigned v, wide_cross_t *cross)
{
    uint64_t lift_high;
    uint64_t lift = wide_lift(d[p], d[p + 1u], &lift_high);
    cross->negative = wide_cross(d[u], d[u + 1u], d[v], d[v + 1u], &cross->low, &cross->high);
    vor__mw_u192_add_product(&sums[cross->negative], lift, lift_high, cross->low, cross->high);
}

/* The incircle's wide tier: its positive and negative sums of the three
 * terms, each row's lift times the cross product of the next two.
 * Inlined in both callers: out of line it costs a frame and a call more
 * at -Os. */
VOR__ALWAYS_INLINE void wide_sums(vor__mw_u192_t sums[2], const int64_t d[6])
{
    wide_cross_t cross; /* only the power test reads it */
    clear_sums(sums);
    wide_term(sums, d, 0, 2, 4, &cross);
    wide_term(sums, d, 2, 4, 0, &cross);
    wide_term(sums, d, 4, 0, 2, &cross);
}

/* ------------------------------------------------------------------ */
/* Power test and power distance                                       */
/*
 * The power test's rows are (x, y, x^2 + y^2 - w, 1); relative to the
 * fourth point and its weight, row r is (x, y, lift - dw, 0) with
 * dw = w_r - w_d, so the determinant is the incircle's three lift terms
 * plus three weight terms -dw cross(the other two rows). A weight
 * difference of two int64 is below 2^64 in magnitude, a cross product
 * below 2^65: each weight term is below 2^129 and goes to the sum of its
 * sign beside the lift terms (< 2^130): both sums stay below 2^133.
 */

/* *sums += -dw (cross as magnitude low + high 2^64 and sign), where
 * dw = w - base: the sum of the product's sign takes it. The difference
 * is taken modulo 2^64, exact as a magnitude below 2^64. */
VOR__INLINE void add_weight_term(vor__mw_u192_t sums[2], int64_t w, int64_t base,
                                 bool cross_negative, uint64_t low, uint64_t high)
{
    bool lighter = w < base; /* dw < 0 */
    uint64_t dw = lighter ? ((uint64_t)base - (uint64_t)w) : ((uint64_t)w - (uint64_t)base);
    /* -dw cross is negative when dw and cross have the same sign */
    vor__mw_u192_add_product(&sums[(cross_negative == lighter) ? 1u : 0u], dw, 0u, low, high);
}

/* The power test of the differences d (a - d, b - d, c - d as x, y pairs,
 * each below 2^32 in magnitude) and the weights w (a, b, c, d). */
static VOR__NOINLINE int power_wide(const int64_t d[6], const int64_t w[4])
{
    vor__mw_u192_t sums[2]; /* positive, negative */
    clear_sums(sums);
    for (unsigned r = 0; r < 3u; r++) {
        unsigned p = 2u * r;
        unsigned u = 2u * next_of[r];
        unsigned v = 2u * next_of[next_of[r]];
        wide_cross_t cross;
        wide_term(sums, d, p, u, v, &cross);
        add_weight_term(sums, w[r], w[3], cross.negative, cross.low, cross.high);
    }
    return vor__mw_u192_compare(&sums[0], &sums[1]);
}

int vor__power_exact(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                     const vor_point_t *dp, const int64_t w[4], vor_stats_t *stats)
{
    if ((w[0] == w[3]) && (w[1] == w[3]) && (w[2] == w[3])) {
        return vor__incircle_exact(a, b, c, dp, stats);
    }
    VOR__COUNT(stats, power);
    int64_t d[6] = {(int64_t)a->x - dp->x, (int64_t)a->y - dp->y,
                    (int64_t)b->x - dp->x, (int64_t)b->y - dp->y,
                    (int64_t)c->x - dp->x, (int64_t)c->y - dp->y};
    return power_wide(d, w);
}

int vor_power_test(vor_point_t a, int64_t wa, vor_point_t b, int64_t wb, vor_point_t c,
                   int64_t wc, vor_point_t d, int64_t wd)
{
    const int64_t w[4] = {wa, wb, wc, wd};
    return vor__power_exact(&a, &b, &c, &d, w, NULL);
}

/* (|q-a|^2 - wa) - (|q-b|^2 - wb) compared as |q-a|^2 + (wb + 2^63)
 * against |q-b|^2 + (wa + 2^63): squared distances below 2^65 (a word and
 * its 65th bit) plus a word, below 2^66 each: a word and a high part. */
int vor__power_closer_sign(const vor_point_t *q, const vor_point_t *a, int64_t wa,
                           const vor_point_t *b, int64_t wb, vor_stats_t *stats)
{
    if (wa == wb) {
        return vor__closer_sign(q, a, b, stats);
    }
    VOR__COUNT(stats, power);
    const uint64_t offset = (uint64_t)1 << 63;
    uint64_t a_high;
    uint64_t da = wide_lift((int64_t)a->x - q->x, (int64_t)a->y - q->y, &a_high);
    uint64_t b_high;
    uint64_t db = wide_lift((int64_t)b->x - q->x, (int64_t)b->y - q->y, &b_high);
    uint64_t left = da + ((uint64_t)wb ^ offset);
    a_high += (left < da) ? 1u : 0u;
    uint64_t right = db + ((uint64_t)wa ^ offset);
    b_high += (right < db) ? 1u : 0u;
    if (a_high != b_high) {
        return (a_high > b_high) ? 1 : -1;
    }
    return (left > right) - (left < right);
}

int vor_power_closer(vor_point_t q, vor_point_t a, int64_t wa, vor_point_t b, int64_t wb)
{
    return vor__power_closer_sign(&q, &a, wa, &b, wb, NULL);
}

/* The mid tier's filter (32-bit limbs, and not at -Os, where its 280
 * bytes on Cortex-M3 count for more than its speed). */
#if VOR_LIMB_BITS == 32 && !defined(__OPTIMIZE_SIZE__)
#define MID_FILTER 1
#else
#define MID_FILTER 0
#endif

#if MID_FILTER
/* floor(v / 2^(17 - t)) for v in [-2^(31 - t), 2^(31 - t) - 1], t <= 17:
 * v shifted left by t fits 32 bits, and its top 15 bits are taken (a
 * right shift of a negative value is implementation-defined, so only a
 * non-negative one is shifted; compilers emit one ASR). The result lies
 * in [-2^14, 2^14 - 1] whatever v and t: the filters' narrow evaluations
 * are bounded by this function alone, not by a relation between t and
 * the caller's OR of bounds, which an analyser does not keep. */
VOR__INLINE int32_t top_bits(int64_t v, unsigned t)
{
    uint32_t shifted = (uint32_t)v << t;
    int32_t w = (int32_t)shifted;
    return (w >= 0) ? ((w >> 17)) : ~((~w) >> 17);
}

/* With 32-bit limbs the mid tier's exact sums cost 2.6 times the narrow
 * tier (Cortex-M3), so the determinant P (12 monomials, each +-1 times a
 * product of four differences: lift x cross, 4 monomials a term) is first
 * taken of the differences shifted right by s until they fit 15 bits (s
 * from m, the OR of their bounds, which the caller chose the tier by):
 * d = 2^s d' + r, 0 <= r < 2^s, |d'| <= A = 2^14, exact in int64 by the
 * narrow tier. A product of four differences then differs from 2^4s times
 * that of the d' by at most 2^4s ((A + 1)^4 - A^4), so |P(d) - 2^4s P(d')|
 * <= 2^4s 12 (4 A^3 + 6 A^2 + 4 A + 1) < 2^4s (3 2^46 + 2^35), and when
 * |P(d')| is at least that bound its sign is P(d)'s; else a finer bound
 * from each point's size may decide (vor__incircle_point_bound). Returns
 * 0 when neither does (an exact zero among them: the exact sums then
 * decide). Straight-line code on 32-bit values: loops cost a Cortex-M3
 * more than they save. Out of line: inlined, the registers it needs are
 * saved and restored on every mid-tier call, which costs RISC-V more than
 * the call. */
static VOR__NOINLINE int incircle_filter(const int64_t d[6], uint32_t m)
{
    /* m in [2^14, 2^31) (the mid tier's): s = bits - 14 in [1, 17], and
     * the differences shifted left by t = 17 - s fit 32 bits */
    unsigned t = 31u - vor__mw_bit_length32(m);
    int32_t shifted[6] = {top_bits(d[0], t), top_bits(d[1], t), top_bits(d[2], t),
                          top_bits(d[3], t), top_bits(d[4], t), top_bits(d[5], t)};
    int64_t det = vor__incircle_narrow(shifted);
    const int64_t error = ((int64_t)3 << 46) + ((int64_t)1 << 35);
    if ((det >= error) || (det <= -error)) {
        return vor__mw_sign64(det);
    }
    uint64_t size = (uint64_t)((det < 0) ? -det : det);
    return (size > vor__incircle_point_bound(shifted)) ? vor__mw_sign64(det) : 0;
}
#endif

int vor__incircle_mid(const int64_t d[6], uint64_t bound)
{
#if MID_FILTER
    int filtered = incircle_filter(d, (uint32_t)bound);
    if (filtered != 0) {
        return filtered;
    }
#else
    (void)bound; /* only the filter sizes anything by it */
#endif
#if VOR_LIMB_BITS == 64
    /* With 64-bit limbs and every lift below 2^61, each |cross| is below
     * 2^61 too (|u x v| <= |u| |v|), the products below 2^122 and their sum
     * fits a signed double limb: one sum, no accumulator chosen per sign.
     * Lifts up to 2^63 (differences near 2^31) take the two sums below. */
    int32_t ax = (int32_t)d[0];
    int32_t ay = (int32_t)d[1];
    int32_t bx = (int32_t)d[2];
    int32_t by = (int32_t)d[3];
    int32_t cx = (int32_t)d[4];
    int32_t cy = (int32_t)d[5];
    uint64_t la = (uint64_t)vor__mul_i32(ax, ax) + (uint64_t)vor__mul_i32(ay, ay);
    uint64_t lb = (uint64_t)vor__mul_i32(bx, bx) + (uint64_t)vor__mul_i32(by, by);
    uint64_t lc = (uint64_t)vor__mul_i32(cx, cx) + (uint64_t)vor__mul_i32(cy, cy);
    if (((la | lb | lc) >> 61) == 0u) {
        return vor__mw_sign_of_products(
            (int64_t)la, vor__mul_i32(bx, cy) - vor__mul_i32(by, cx), (int64_t)lb,
            vor__mul_i32(cx, ay) - vor__mul_i32(cy, ax), (int64_t)lc,
            vor__mul_i32(ax, by) - vor__mul_i32(ay, bx));
    }
#endif
    vor__mw_u128_t sums[2]; /* positive, negative */
    /* field by field: a structure copy is a memcpy call on Cortex-M0 */
    sums[0].lo = 0u;
    sums[0].hi = 0u;
    sums[1].lo = 0u;
    sums[1].hi = 0u;
    mid_term(sums, d, 0, 2, 4);
    mid_term(sums, d, 2, 4, 0);
    mid_term(sums, d, 4, 0, 2);
    /* the low words compared without a branch (vor__mw_u128_compare
     * branches, which suits the raster's uses but not this one) */
    if (sums[0].hi != sums[1].hi) {
        return (sums[0].hi > sums[1].hi) ? 1 : -1;
    }
    return (sums[0].lo > sums[1].lo) - (sums[0].lo < sums[1].lo);
}

int vor__incircle_wide(const int64_t d[6])
{
    vor__mw_u192_t sums[2]; /* positive, negative */
    wide_sums(sums, d);
    return vor__mw_u192_compare(&sums[0], &sums[1]);
}

int vor__incircle_sign(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                       const vor_point_t *d)
{
    return vor__incircle_exact(a, b, c, d, NULL);
}

int vor_incircle(vor_point_t a, vor_point_t b, vor_point_t c, vor_point_t d)
{
    return vor__incircle_exact(&a, &b, &c, &d, NULL);
}

/* ------------------------------------------------------------------ */
/* Symbolic perturbation                                               */
/*
 * Site i moves to (x_i + dx_i, y_i + dy_i) with dy_i = eps^(16^i) and
 * dx_i = eps^(4 * 16^i). The predicate is the determinant of one row per
 * site: (x, y, 1) for orient2d, (x, y, x^2 + y^2, 1) for incircle. A row of
 * a moved site is the sum of the plain row and one row per perturbation
 * term:
 *
 *   ROW_POINT   (x, y, x^2+y^2, 1)   eps^0
 *   ROW_DY      (0, 1, 2y, 0)        eps^(16^i)      coefficient of dy
 *   ROW_SQUARE  (0, 0, 1, 0)         eps^(2*16^i)    coefficient of dy^2
 *   ROW_DX      (1, 0, 2x, 0)        eps^(4*16^i)    coefficient of dx
 *   (ROW_SQUARE again                eps^(8*16^i)    coefficient of dx^2)
 *
 * (orient2d rows stop at the second column and have no ROW_SQUARE). The
 * determinant is multilinear in rows, so the moved determinant is a sum
 * over one row kind per site; the term's eps exponent is the sum of the
 * chosen exponents. Those are distinct powers of two per site and per
 * kind, so no two terms share an exponent and the sign as eps -> 0 is the
 * sign of the first nonzero term in increasing exponent order. That order
 * is lexicographic in the row kinds, the largest index most significant,
 * kinds ordered as listed. The dx^2 term repeats the dy^2 term's row at a
 * larger exponent, so it can never be first and is skipped.
 *
 * The determinant is translation invariant term by term, so coordinates
 * are taken relative to the site with the largest index. That site keeps
 * ROW_POINT in every term examined (a term with ROW_DX, ROW_DY, ROW_SQUARE
 * on the other rows is +-1 and comes earlier), so its row is (0, ..., 0, 1)
 * and the determinant reduces to the minor of the others.
 */

enum row_kind { ROW_POINT, ROW_DY, ROW_SQUARE, ROW_DX, ROW_KINDS };

int vor_orient2d_sos(const vor_point_t *sites, uint32_t i, uint32_t j, uint32_t k)
{
    if ((sites == NULL) || (i == j) || (j == k) || (i == k)) {
        return 0; /* the only 0 it returns: no perturbation orders these */
    }
    int sign = vor__orient2d_exact(&sites[i], &sites[j], &sites[k], NULL);
    return (sign != 0) ? sign : vor__orient2d_perturbed(sites, i, j, k, NULL);
}

int vor__orient2d_perturbed(const vor_point_t *sites, uint32_t i, uint32_t j,
                            uint32_t k, vor_stats_t *stats)
{
    VOR__COUNT(stats, orient2d_perturbed);
    VOR_ASSERT(i != j && j != k && i != k);
    /* orient2d is invariant under rotation of its points: rotate the
     * largest index, the origin, to the last place, (u, v, w). The minor
     * is then det [[u - w], [v - w]], cofactor sign +1. */
    uint32_t u = i;
    uint32_t v = j;
    uint32_t w = k;
    if ((u > v) && (u > w)) { /* (j, k, i) */
        u = j;
        v = k;
        w = i;
    } else if (v > w) { /* (k, i, j) */
        u = k;
        v = i;
        w = j;
    } else {
        /* (i, j, k) already */
    }
    /* L: the rank-0 site (the smaller of u, v), H the other; s = +1 when
     * L is the minor's first row. The terms after the exact one (0), with
     * (L's kind, H's kind), kinds in the order ROW_POINT, ROW_DY, ROW_DX
     * and H's the more significant, all have a unit row (0, 1) or (1, 0):
     *   (DY, POINT): s (-xH)     (DX, POINT): s yH
     *   (POINT, DY): s xL        (DY, DY): 0 (equal rows)
     *   (DX, DY): s              (each coordinate relative to w)
     * No products, and no tiers: the first nonzero one is the sign. */
    bool l_first = u < v;
    const vor_point_t *low = &sites[l_first ? u : v];
    const vor_point_t *high = &sites[l_first ? v : u];
    const vor_point_t *origin = &sites[w];
    int sign = -vor__mw_sign64((int64_t)high->x - origin->x);
    if (sign == 0) {
        sign = vor__mw_sign64((int64_t)high->y - origin->y);
    }
    if (sign == 0) {
        sign = vor__mw_sign64((int64_t)low->x - origin->x);
    }
    if (sign == 0) {
        sign = 1;
    }
    return l_first ? sign : -sign;
}

/* Sign of the perturbation's term whose minor rows (x[r], y[r]: the
 * differences to the top site, |x|, |y| <= 2^32 - 1) have the kinds in
 * `kinds` (row r's in bits 2r and 2r + 1), at most one of them
 * ROW_SQUARE, expanded along the third column as the exact wide tier's
 * terms (wide_term). The first two columns hold x, y, 0 or 1, so a cross
 * product of two rows is a signed sum of two products below 2^64: a word
 * and a 65th bit. The third holds x^2 + y^2 < 2^65 (a word and a 65th
 * bit), 2x or 2y (< 2^33, taken as magnitude and sign) or 1. Each product
 * < 2^130 goes to the sum of its sign, three of them < 2^132 in 192 bits.
 * With weights (w: the rows' and the top site's, else NULL) a point row's
 * third entry is x^2 + y^2 - dw, and its weight term (below 2^129) joins
 * the sums as in the power test (power_wide). Two copies out of line
 * (term_sign, power_term_sign): the incircle's, in which w is NULL and
 * the weights' code folds away, so that a firmware without power
 * diagrams carries none of it; each serves every term the closed forms
 * do not decide, for every size of difference. */
VOR__ALWAYS_INLINE int term_sign_of(const int64_t x[3], const int64_t y[3], const int64_t *w,
                                    unsigned kinds)
{
    int64_t e[3][2];
    uint64_t c[3];
    uint64_t c_high[3];
    bool c_negative[3];
    enum row_kind kind[3];
    for (unsigned r = 0; r < 3u; r++) {
        unsigned packed = (kinds >> (2u * r)) & 3u;
        kind[r] = (enum row_kind)packed;
        e[r][0] = (kind[r] == ROW_POINT) ? x[r] : (kind[r] == ROW_DX) ? 1 : 0;
        e[r][1] = (kind[r] == ROW_POINT) ? y[r] : (kind[r] == ROW_DY) ? 1 : 0;
        uint64_t lift_high;
        uint64_t lift = wide_lift(x[r], y[r], &lift_high);
        int64_t halved = (kind[r] == ROW_DY) ? y[r] : x[r]; /* of 2y or 2x */
        uint64_t twice = 2u * (uint64_t)vor__mw_magnitude(halved);
        c[r] = (kind[r] == ROW_POINT) ? lift : (kind[r] == ROW_SQUARE) ? 1u : twice;
        c_high[r] = (kind[r] == ROW_POINT) ? lift_high : 0u;
        c_negative[r] = ((kind[r] == ROW_DY) || (kind[r] == ROW_DX)) && (halved < 0);
    }
    vor__mw_u192_t sums[2]; /* positive, negative */
    clear_sums(sums);
    for (unsigned r = 0; r < 3u; r++) {
        unsigned u = next_of[r];
        unsigned v = next_of[u];
        uint64_t low;
        uint64_t high;
        bool negative = wide_cross(e[u][0], e[u][1], e[v][0], e[v][1], &low, &high);
        vor__mw_u192_add_product(&sums[negative != c_negative[r]], c[r], c_high[r], low, high);
        if ((w != NULL) && (kind[r] == ROW_POINT)) {
            add_weight_term(sums, w[r], w[3], negative, low, high);
        }
    }
    return vor__mw_u192_compare(&sums[0], &sums[1]);
}

static VOR__NOINLINE int term_sign(const int64_t x[3], const int64_t y[3], unsigned kinds)
{
    return term_sign_of(x, y, NULL, kinds);
}

static VOR__NOINLINE int power_term_sign(const int64_t x[3], const int64_t y[3],
                                         const int64_t w[4], unsigned kinds)
{
    return term_sign_of(x, y, w, kinds);
}

int vor_incircle_sos(const vor_point_t *sites, uint32_t i, uint32_t j, uint32_t k,
                     uint32_t l)
{
    if ((sites == NULL) || (i == j) || (i == k) || (i == l) || (j == k) || (j == l) || (k == l)) {
        return 0; /* the only 0 it returns: no perturbation orders these */
    }
    int sign = vor__incircle_exact(&sites[i], &sites[j], &sites[k], &sites[l], NULL);
    return (sign != 0) ? sign : vor__incircle_perturbed(sites, i, j, k, l, NULL);
}

/* The first term of the perturbed incircle, 2 yL by_y - (xP zQ - zP xQ)
 * with z = x^2 + y^2 and by_y = xP yQ - yP xQ (vor__incircle_perturbed),
 * for entries |.| <= 2^14: z <= 2^29 in int32, every product <= 2^44,
 * |by_y| <= 2^29, the term below 2^46 in int64. */
VOR__INLINE int64_t first_term_narrow(int32_t yl, int32_t xp, int32_t yp, int32_t xq,
                                      int32_t yq, int64_t by_y)
{
    int32_t zp = (xp * xp) + (yp * yp);
    int32_t zq = (xq * xq) + (yq * yq);
    int64_t by_z = vor__mul_i32(xp, zq) - vor__mul_i32(zp, xq);
    return vor__mul_i64_i32(by_y, 2 * yl) - by_z;
}

/* The perturbed incircle's first two terms (vor__incircle_perturbed) of
 * the entries e = yL, xP, yP, xQ, yQ: the sign of the first nonzero one,
 * or 0, and then *next, the term from which the enumeration goes on: 3
 * when both are 0, 1 when the entries are too wide for the closed forms
 * here (beyond int32). The second term (t = 2) has L's row ROW_SQUARE
 * (0, 0, 1): along it, by_y itself (times the same (-1)^low), 0 only when
 * P, Q and the top site are collinear. */
VOR__INLINE int first_terms(const int64_t e[5], unsigned *next)
{
    /* the OR of the bounds tested in this scope, where an analyser
     * narrows each bound by the test (vor__mw_unbound) */
    uint64_t b[5] = {vor__mw_bound(e[0]), vor__mw_bound(e[1]), vor__mw_bound(e[2]),
                     vor__mw_bound(e[3]), vor__mw_bound(e[4])};
    uint64_t m = b[0] | b[1] | b[2] | b[3] | b[4];
    *next = 1u;
    if (m >= 0x80000000u) {
        return 0;
    }
    *next = 3u;
#if MID_FILTER
    /* As the exact mid tier's filter: the entries shifted right by s until
     * they fit 15 bits, d = 2^s d' + r, 0 <= r < 2^s, |d'| <= A = 2^14,
     * the first term of the d' exact in int64 (first_term_narrow). Its 6
     * monomials are products of three entries with coefficients 2, 2, 1,
     * 1, 1, 1, and such a product differs from 2^3s times that of the d'
     * by at most 2^3s ((A + 1)^3 - A^3), so the term differs from 2^3s
     * times the filtered one by at most 2^3s 8 (3 A^2 + 3 A + 1) < 2^3s
     * 2^33: from 2^33 on, its sign is the term's. Entries of 15 bits
     * (s = 0) give the exact terms. Nearly every tie on a lattice decides
     * here, a lattice square's term being near 2^42; the others take the
     * 192-bit sums (term_sign), which cost a Cortex-M0 less flash than
     * 128-bit ones for this term alone. */
    if (m < ((uint32_t)1 << 14)) { /* s = 0: the entries, from their bounds */
        int32_t f[5] = {vor__mw_unbound(b[0], e[0]), vor__mw_unbound(b[1], e[1]),
                        vor__mw_unbound(b[2], e[2]), vor__mw_unbound(b[3], e[3]),
                        vor__mw_unbound(b[4], e[4])};
        int64_t by_y = vor__mul_i32(f[1], f[4]) - vor__mul_i32(f[2], f[3]);
        int sign = vor__mw_sign64(first_term_narrow(f[0], f[1], f[2], f[3], f[4], by_y));
        return (sign != 0) ? sign : vor__mw_sign64(by_y);
    }
    /* t = 17 - s: the entries shifted left by t fit 32 bits (top_bits) */
    unsigned t = 31u - vor__mw_bit_length32((uint32_t)m);
    int32_t f[5] = {top_bits(e[0], t), top_bits(e[1], t), top_bits(e[2], t), top_bits(e[3], t),
                    top_bits(e[4], t)};
    int64_t by_y = vor__mul_i32(f[1], f[4]) - vor__mul_i32(f[2], f[3]);
    int64_t filtered = first_term_narrow(f[0], f[1], f[2], f[3], f[4], by_y);
    const int64_t error = (int64_t)1 << 33;
    bool decided = (filtered >= error) || (filtered <= -error);
    *next = decided ? 3u : 1u;
    return decided ? vor__mw_sign64(filtered) : 0;
#else
#if VOR_LIMB_BITS == 32
    /* 32-bit limbs at -Os: the closed form in int64 only */
    if (m >= ((uint32_t)1 << 14)) {
        *next = 1u;
        return 0;
    }
#endif
    /* the entries, from their bounds (below 2^14 at -Os, 2^31 here) */
    int32_t yl = vor__mw_unbound(b[0], e[0]);
    int32_t xp = vor__mw_unbound(b[1], e[1]);
    int32_t yp = vor__mw_unbound(b[2], e[2]);
    int32_t xq = vor__mw_unbound(b[3], e[3]);
    int32_t yq = vor__mw_unbound(b[4], e[4]);
    int64_t by_y = vor__mul_i32(xp, yq) - vor__mul_i32(yp, xq);
#if VOR_LIMB_BITS == 64
    /* |by_y| <= 2^63 - 2^31: the two products cannot both reach 2^62
     * with opposite signs. Beyond 15 bits, z <= 2^63 fits uint64, and the
     * first term's products are below 2^95, 2^94 and 2^94: one signed
     * 128-bit sum. */
    int sign;
    if (m < ((uint32_t)1 << 14)) {
        sign = vor__mw_sign64(first_term_narrow(yl, xp, yp, xq, yq, by_y));
    } else {
        uint64_t zp = (uint64_t)vor__mul_i32(xp, xp) + (uint64_t)vor__mul_i32(yp, yp);
        uint64_t zq = (uint64_t)vor__mul_i32(xq, xq) + (uint64_t)vor__mul_i32(yq, yq);
        vor__sdlimb det = (vor__sdlimb)by_y * (2 * (int64_t)yl) -
                          (vor__sdlimb)xp * (vor__sdlimb)zq + (vor__sdlimb)xq * (vor__sdlimb)zp;
        sign = (det > 0) ? 1 : ((det < 0) ? -1 : 0);
    }
#else
    int sign = vor__mw_sign64(first_term_narrow(yl, xp, yp, xq, yq, by_y));
#endif
    return (sign != 0) ? sign : vor__mw_sign64(by_y);
#endif
}

/* The site with the largest index of (i, j, k, l) is the origin: one
 * transposition moves it to the last place, negating the determinant
 * (returns true then). The other three, ids[], are then the rows of the
 * minor, whose sign is the determinant's (the cofactor of the (4, 4)
 * entry is +1). */
VOR__ALWAYS_INLINE bool move_top(uint32_t i, uint32_t j, uint32_t k, uint32_t l, uint32_t ids[3],
                          uint32_t *top)
{
    ids[0] = i;
    ids[1] = j;
    ids[2] = k;
    unsigned t = (j > i) ? 1u : 0u;
    t = (k > ids[t]) ? 2u : t;
    bool swapped = ids[t] > l;
    *top = swapped ? ids[t] : l;
    ids[t] = swapped ? l : ids[t];
    return swapped;
}

/* The perturbed incircle (weights NULL) or power test of sites i, j, k,
 * l from its term t = first on, the earlier ones known to be 0 (t = 1
 * when the differences are too wide for the first terms' closed forms):
 * -1 or 1. Out of line (later_terms, power_later_terms, as term_sign),
 * and the rows found and their differences computed again: rarely
 * reached, and its frame is not stacked on the first terms'
 * (first_two_terms). */
VOR__ALWAYS_INLINE int terms_from(const vor_point_t *sites, const int64_t *weights, uint32_t i,
                                  uint32_t j, uint32_t k, uint32_t l, unsigned first)
{
    uint32_t ids[3];
    uint32_t top;
    bool swapped = move_top(i, j, k, l, ids, &top);
    int64_t w[4]; /* the rows' weights and the top site's, when weighted */
    if (weights != NULL) {
        w[0] = weights[ids[0]];
        w[1] = weights[ids[1]];
        w[2] = weights[ids[2]];
        w[3] = weights[top];
    }
    int64_t x[3];
    int64_t y[3];
    unsigned shifts = 0; /* 2 rank(r) for row r, in bits 4r .. 4r + 3 */
    for (unsigned r = 0; r < 3u; r++) {
        x[r] = (int64_t)sites[ids[r]].x - sites[top].x;
        y[r] = (int64_t)sites[ids[r]].y - sites[top].y;
        unsigned rank = (ids[next_of[r]] < ids[r]) ? 1u : 0u;
        rank += (ids[next_of[next_of[r]]] < ids[r]) ? 1u : 0u;
        shifts |= (2u * rank) << (4u * r);
    }
    /* term t: digit r of t in base 4 is the kind of the rank-r site, the
     * rank-2 site most significant. t = 0 is the exact determinant (0);
     * t = 27 (ROW_DX, ROW_SQUARE, ROW_DY) is +-1, so the loop ends by then.
     * The rows' kinds go to term_sign packed, 2 bits a row. */
    int sign = 0;
    for (unsigned t = first; (t < 64u) && (sign == 0); t++) {
        unsigned kinds = 0;
        unsigned squares = 0;
        for (unsigned r = 0; r < 3u; r++) {
            unsigned kind = (t >> ((shifts >> (4u * r)) & 15u)) & 3u;
            kinds |= kind << (2u * r);
            squares += (kind == (unsigned)ROW_SQUARE) ? 1u : 0u;
        }
        if (squares < 2u) { /* else two equal rows: the term is 0 */
            sign = (weights == NULL) ? term_sign(x, y, kinds) : power_term_sign(x, y, w, kinds);
        }
    }
    VOR_ASSERT(sign != 0);
    return swapped ? -sign : sign;
}

static VOR__NOINLINE int later_terms(const vor_point_t *sites, uint32_t i, uint32_t j,
                                     uint32_t k, uint32_t l, unsigned first)
{
    return terms_from(sites, NULL, i, j, k, l, first);
}

static VOR__NOINLINE int power_later_terms(const vor_point_t *sites, const int64_t *weights,
                                           uint32_t i, uint32_t j, uint32_t k, uint32_t l)
{
    return terms_from(sites, weights, i, j, k, l, 1u);
}

/* The perturbed incircle of sites i, j, k, l by its first two terms: -1
 * or 1, or else 0 when the enumeration must go on from term 1 (the
 * differences are too wide for the closed forms) or 3 when it must go on
 * from term 3 (both terms are 0). Out of line, so that the later terms'
 * frame does not stack on this one's. */
static VOR__NOINLINE int first_two_terms(const vor_point_t *sites, uint32_t i, uint32_t j,
                                         uint32_t k, uint32_t l)
{
    uint32_t ids[3];
    uint32_t top;
    bool swapped = move_top(i, j, k, l, ids, &top);
    /* The first term (t = 1) nearly always decides: the smallest index's
     * row (at `low`, L) is ROW_DY (0, 1, 2y), the other two (P, Q, in row
     * order) are points. Along that row:
     *   det = (-1)^low (2 yL (xP yQ - yP xQ) - (xP zQ - zP xQ)),  z = x^2 + y^2,
     * in which only yL, xP, yP, xQ, yQ appear, so only their size picks
     * the width. Small ones (the usual degeneracy: grids, nearby
     * cocircular sites), |.| <= 2^14: int64 (first_term_narrow). In int32:
     * 128 bits with 64-bit limbs, a filter with 32-bit ones (first_terms).
     * Else term_sign's 192-bit sums, with the later terms. */
    /* L, P, Q */
    uint32_t il = ids[0];
    uint32_t ip = ids[1];
    uint32_t iq = ids[2];
    bool odd = false;                               /* low == 1 */
    if (ip < il) {                                  /* L = ids[1] */
        il = ids[1];
        ip = ids[0];
        odd = true;
    }
    if (iq < il) { /* L = ids[2]: P, Q = ids[0], ids[1] */
        il = ids[2];
        ip = ids[0];
        iq = ids[1];
        odd = false;
    }
    const vor_point_t *o = &sites[top];
    const vor_point_t *pl = &sites[il];
    const vor_point_t *pp = &sites[ip];
    const vor_point_t *pq = &sites[iq];
    int64_t e[5] = {(int64_t)pl->y - o->y, (int64_t)pp->x - o->x, (int64_t)pp->y - o->y,
                    (int64_t)pq->x - o->x, (int64_t)pq->y - o->y};
    unsigned next;
    int sign = first_terms(e, &next);
    if (sign == 0) {
        return (next == 1u) ? 0 : 3;
    }
    return (odd != swapped) ? -sign : sign;
}

int vor__incircle_perturbed(const vor_point_t *sites, uint32_t i, uint32_t j,
                            uint32_t k, uint32_t l, vor_stats_t *stats)
{
    VOR__COUNT(stats, incircle_perturbed);
    VOR_ASSERT(i != j && i != k && i != l && j != k && j != l && k != l);
    int sign = first_two_terms(sites, i, j, k, l);
    if ((sign == 1) || (sign == -1)) {
        return sign;
    }
    return later_terms(sites, i, j, k, l, (sign == 0) ? 1u : 3u);
}

/* The perturbed power test: the incircle's when the four weights are
 * equal (its rows are then the incircle's, the weights cancelling), else
 * every term from the first by term_sign: rare, and a closed form would
 * have to carry the weights. */
int vor__power_perturbed(const vor_point_t *sites, const int64_t *weights, uint32_t i,
                         uint32_t j, uint32_t k, uint32_t l, vor_stats_t *stats)
{
    int64_t wl = weights[l];
    if ((weights[i] == wl) && (weights[j] == wl) && (weights[k] == wl)) {
        return vor__incircle_perturbed(sites, i, j, k, l, stats);
    }
    VOR__COUNT(stats, power_perturbed);
    VOR_ASSERT(i != j && i != k && i != l && j != k && j != l && k != l);
    return power_later_terms(sites, weights, i, j, k, l);
}

int vor_power_test_sos(const vor_point_t *sites, const int64_t *weights, uint32_t i,
                       uint32_t j, uint32_t k, uint32_t l)
{
    if ((sites == NULL) || (weights == NULL) || (i == j) || (i == k) || (i == l) || (j == k) ||
        (j == l) || (k == l)) {
        return 0; /* the only 0 it returns: no perturbation orders these */
    }
    const int64_t w[4] = {weights[i], weights[j], weights[k], weights[l]};
    int sign = vor__power_exact(&sites[i], &sites[j], &sites[k], &sites[l], w, NULL);
    return (sign != 0) ? sign : vor__power_perturbed(sites, weights, i, j, k, l, NULL);
}

/*
 * vor_closer under the perturbation. With d_i the move of site i,
 *
 *   |q~ - a~|^2 - |q~ - b~|^2 = D + 2 (b - a).d_q - 2 (q - a).d_a
 *       + 2 (q - b).d_b + |d_a|^2 - |d_b|^2 - 2 d_q.d_a + 2 d_q.d_b
 *
 * (D the exact value), coordinate by coordinate. In increasing order of
 * eps exponents the first terms are those of the site L with the smallest
 * index: its dy term, its dy^2 term, its dx term, then the middle site M's
 * dy term and the product of M's and L's dy. If L is a or b, its dy^2
 * coefficient (+1 for a, -1 for b) ends the sequence; if L is q, its own
 * squares cancel, and M's dy product with L's (-2 for a, +2 for b) ends it.
 */
int vor_closer_sos(const vor_point_t *sites, uint32_t q, uint32_t a, uint32_t b)
{
    if ((sites == NULL) || (q == a) || (q == b) || (a == b)) {
        return 0; /* the only 0 it returns: no perturbation orders these */
    }
    const vor_point_t *pq = &sites[q];
    const vor_point_t *pa = &sites[a];
    const vor_point_t *pb = &sites[b];
    int sign = vor__closer_sign(pq, pa, pb, NULL);
    if (sign != 0) {
        return sign;
    }
    VOR_ASSERT(q != a && q != b && a != b);
    if ((a < q) || (b < q)) {
        bool a_first = a < b;
        /* L = a: -2 (qy - ay), then +1; L = b: 2 (qy - by), then -1 */
        int64_t coefficient = a_first ? ((int64_t)pa->y - pq->y) : (int64_t)pq->y - pb->y;
        sign = vor__mw_sign64(coefficient);
        return (sign != 0) ? sign : (a_first ? 1 : -1);
    }
    /* L = q: 2 (by - ay), 2 (bx - ax), then M's dy and the dy product */
    sign = vor__mw_sign64((int64_t)pb->y - pa->y);
    if (sign == 0) {
        sign = vor__mw_sign64((int64_t)pb->x - pa->x);
    }
    if (sign == 0) {
        bool a_middle = a < b;
        int64_t coefficient = a_middle ? ((int64_t)pa->y - pq->y) : (int64_t)pq->y - pb->y;
        sign = vor__mw_sign64(coefficient);
        if (sign == 0) {
            sign = a_middle ? -1 : 1;
        }
    }
    return sign;
}

/* ------------------------------------------------------------------ */
/* Magnitudes (the motion cache, motion.c)                             */

/* Bit length of |v| for a signed value of VOR__WIDE_LIMBS limbs (made
 * non-negative in place). */
static unsigned wide_bit_length(vor__limb *v)
{
    if (vor__mw_sign(v, VOR__WIDE_LIMBS) < 0) {
        vor__mw_neg(v, VOR__WIDE_LIMBS);
    }
    return vor__mw_bit_length_limbs(v, VOR__WIDE_LIMBS);
}

/* Bit length of |sums[0] - sums[1]|. */
static unsigned difference_bits(const vor__mw_u192_t sums[2])
{
    bool swap = vor__mw_u192_compare(&sums[0], &sums[1]) < 0;
    const vor__mw_u192_t *a = &sums[swap ? 1 : 0];
    const vor__mw_u192_t *b = &sums[swap ? 0 : 1];
    uint64_t borrow = 0;
    uint64_t w[3];
    for (unsigned i = 0; i < 3u; i++) {
        w[i] = a->w[i] - b->w[i] - borrow;
        borrow = ((a->w[i] < b->w[i]) || ((a->w[i] == b->w[i]) && (borrow != 0u))) ? 1u : 0u;
    }
    for (unsigned i = 3; i-- > 0;) {
        if (w[i] != 0u) {
            return (64u * i) + vor__mw_bit_length(w[i]);
        }
    }
    return 0;
}

unsigned vor__orient2d_bits(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c)
{
    int64_t acx = (int64_t)a->x - c->x;
    int64_t acy = (int64_t)a->y - c->y;
    int64_t bcx = (int64_t)b->x - c->x;
    int64_t bcy = (int64_t)b->y - c->y;
    if ((vor__mw_bound(acx) | vor__mw_bound(acy) | vor__mw_bound(bcx) | vor__mw_bound(bcy)) < 0x80000000u) {
        /* as the narrow tier: |det| < 2^63 */
        int64_t det = vor__mul_i32((int32_t)acx, (int32_t)bcy) -
                      vor__mul_i32((int32_t)acy, (int32_t)bcx);
        return vor__mw_bit_length((uint64_t)((det < 0) ? -det : det));
    }
    /* 33-bit differences: products < 2^66, det < 2^67 */
    vor__limb e[4][VOR__WIDE_LIMBS];
    vor__limb det[VOR__WIDE_LIMBS];
    vor__limb other[VOR__WIDE_LIMBS];
    vor__mw_from_i64(e[0], VOR__WIDE_LIMBS, acx);
    vor__mw_from_i64(e[1], VOR__WIDE_LIMBS, acy);
    vor__mw_from_i64(e[2], VOR__WIDE_LIMBS, bcx);
    vor__mw_from_i64(e[3], VOR__WIDE_LIMBS, bcy);
    /* 33-bit factors, products < 2^66: within VOR__WIDE_LIMBS */
    vor__mw_mul(det, VOR__WIDE_LIMBS, e[0], VOR__WIDE_LIMBS, e[3], VOR__WIDE_LIMBS);
    vor__mw_mul(other, VOR__WIDE_LIMBS, e[1], VOR__WIDE_LIMBS, e[2], VOR__WIDE_LIMBS);
    vor__mw_sub(det, other, VOR__WIDE_LIMBS);
    return wide_bit_length(det);
}

unsigned vor__incircle_bits(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                            const vor_point_t *dp)
{
    int64_t d[6] = {(int64_t)a->x - dp->x, (int64_t)a->y - dp->y,
                    (int64_t)b->x - dp->x, (int64_t)b->y - dp->y,
                    (int64_t)c->x - dp->x, (int64_t)c->y - dp->y};
    uint64_t bounds[6];
    vor__incircle_bounds(bounds, d);
    uint64_t m = bounds[0] | bounds[1] | bounds[2] | bounds[3] | bounds[4] | bounds[5];
    if (m < ((uint32_t)1 << 14)) { /* as the narrow tier: |det| < 2^60 */
        int64_t det = vor__incircle_narrow_of(bounds, d);
        return vor__mw_bit_length((uint64_t)((det < 0) ? -det : det));
    }
    /* the sign tiers' positive and negative sums; |det| is their
     * difference */
    if (m < 0x80000000u) {
        vor__mw_u128_t sums[2];
        /* field by field: a structure copy is a memcpy call on Cortex-M0 */
        sums[0].lo = 0u;
        sums[0].hi = 0u;
        sums[1].lo = 0u;
        sums[1].hi = 0u;
        mid_term(sums, d, 0, 2, 4);
        mid_term(sums, d, 2, 4, 0);
        mid_term(sums, d, 4, 0, 2);
        vor__mw_u192_t wide[2];
        for (unsigned k = 0; k < 2u; k++) {
            wide[k].w[0] = sums[k].lo;
            wide[k].w[1] = sums[k].hi;
            wide[k].w[2] = 0u;
        }
        return difference_bits(wide);
    }
    vor__mw_u192_t sums[2];
    wide_sums(sums, d);
    return difference_bits(sums);
}
