/* SPDX-License-Identifier: MIT */
/*
 * predicates.h - the exact predicates' hot paths, private to the library.
 *
 * The narrow tiers are inline here so that the mesh code evaluates the
 * common case without a call; the wider tiers and the perturbation stay
 * out of line in predicates.c, which also defines the public functions on
 * top of these. See predicates.c for the bounds behind every tier.
 */
#ifndef VOR_PREDICATES_H
#define VOR_PREDICATES_H

#include "multiword.h"
#include "vor.h"

/* Counts one evaluation in the caller's counters, if it keeps any: only
 * in a VOR_STATS build (vor_config.h). Otherwise no counter exists and
 * stats is NULL everywhere, so the count and its test compile to nothing. */
#if VOR_STATS
#define VOR__COUNT(stats, counter)                                             \
    do {                                                                       \
        if ((stats) != NULL) {                                                 \
            (stats)->counter++;                                                \
        }                                                                      \
    } while (0)
#define VOR__STATS_OF(d) (&(d)->stats)

#else
#define VOR__COUNT(stats, counter) ((void)(stats))
#define VOR__STATS_OF(d) ((vor_stats_t *)NULL)
#endif

/* Out-of-line tiers (predicates.c). */
int vor__compare_products(int64_t a, int64_t b, int64_t c, int64_t d);
/* bound: the OR of vor__mw_bound over d (below 2^31), which the caller
 * computed to choose the tier; the mid tier's filter sizes its cut by it. */
int vor__incircle_mid(const int64_t d[6], uint64_t bound);
int vor__incircle_wide(const int64_t d[6]);

/* Bit length of the exact |orient2d| and |incircle| determinants (0 for
 * 0): how far the sites may move before the sign can change (motion.c).
 * The determinants are those of vor_orient2d and vor_incircle, whose
 * magnitude does not depend on the order of the points. */
unsigned vor__orient2d_bits(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c);
unsigned vor__incircle_bits(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                            const vor_point_t *dp);

/* The public predicates on points in place (no copies), uncounted. */
int vor__orient2d_sign(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c);
int vor__incircle_sign(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                       const vor_point_t *d);
int vor__closer_sign(const vor_point_t *q, const vor_point_t *a, const vor_point_t *b,
                     vor_stats_t *stats);

/* The power test (vor_power_test) of points in place, w their weights in
 * order (a, b, c, d), counted in stats; and the power distance comparison
 * (vor_power_closer). Equal weights take the incircle's (closer's) tiers
 * and counters. */
int vor__power_exact(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                     const vor_point_t *dp, const int64_t w[4], vor_stats_t *stats);
int vor__power_closer_sign(const vor_point_t *q, const vor_point_t *a, int64_t wa,
                           const vor_point_t *b, int64_t wb, vor_stats_t *stats);

/* The perturbed decisions, for exact signs already known to be 0. */
int vor__orient2d_perturbed(const vor_point_t *sites, uint32_t i, uint32_t j,
                            uint32_t k, vor_stats_t *stats);
int vor__incircle_perturbed(const vor_point_t *sites, uint32_t i, uint32_t j,
                            uint32_t k, uint32_t l, vor_stats_t *stats);
int vor__power_perturbed(const vor_point_t *sites, const int64_t *weights, uint32_t i,
                         uint32_t j, uint32_t k, uint32_t l, vor_stats_t *stats);

VOR__INLINE int vor__orient2d_exact(const vor_point_t *a, const vor_point_t *b,
                                    const vor_point_t *c, vor_stats_t *stats)
{
    int64_t acx = (int64_t)a->x - c->x;
    int64_t acy = (int64_t)a->y - c->y;
    int64_t bcx = (int64_t)b->x - c->x;
    int64_t bcy = (int64_t)b->y - c->y;
    uint64_t m = vor__mw_bound(acx) | vor__mw_bound(acy) | vor__mw_bound(bcx) |
                 vor__mw_bound(bcy);
    if (m < 0x80000000u) {
        /* the differences fit int32, |products| <= 2^62 and their
         * difference is below 2^63 */
        VOR__COUNT(stats, orient2d[VOR_TIER_NARROW]);
        int64_t det = vor__mul_i32((int32_t)acx, (int32_t)bcy) -
                      vor__mul_i32((int32_t)acy, (int32_t)bcx);
        return vor__mw_sign64(det);
    }
    VOR__COUNT(stats, orient2d[VOR_TIER_WIDE]);
    return vor__compare_products(acx, bcy, acy, bcx);
}

/* The incircle determinant of d (a - d, b - d, c - d as x, y pairs) when
 * every d lies in [-2^14, 2^14 - 1]: lifts and |crosses| <= 2^29 fit
 * int32, the three products <= 2^58 and their sum < 2^60 fit int64. */
VOR__INLINE int64_t vor__incircle_narrow(const int32_t d[6])
{
    int32_t ax = d[0];
    int32_t ay = d[1];
    int32_t bx = d[2];
    int32_t by = d[3];
    int32_t cx = d[4];
    int32_t cy = d[5];
    int32_t la = (ax * ax) + (ay * ay);
    int32_t lb = (bx * bx) + (by * by);
    int32_t lc = (cx * cx) + (cy * cy);
    return vor__mul_i32(la, (bx * cy) - (by * cx)) + vor__mul_i32(lb, (cx * ay) - (cy * ax)) +
           vor__mul_i32(lc, (ax * by) - (ay * bx));
}

/* max(|x|, |y|) + 1 of a difference pair (x, y), |x|, |y| <= 2^14. */
VOR__INLINE uint32_t vor__point_size(const int32_t xy[2])
{
    uint32_t x = (uint32_t)vor__mw_magnitude(xy[0]);
    uint32_t y = (uint32_t)vor__mw_magnitude(xy[1]);
    return ((x > y) ? x : y) + 1u;
}

/* The mid incircle filter's second, finer error bound (32-bit limbs,
 * predicates.c incircle_filter), for the determinants its first bound
 * leaves (about one in ten on uniform sites). The filter takes each
 * difference d = 2^s d' + r, 0 <= r < 2^s, |d'| <= 2^14. With a, b, c the
 * vor__point_size of the three points d', a monomial of lift(a) cross(b,
 * c) is at most a^2 b c in magnitude and its error at most the sum of the
 * partial derivatives at (a, b, c), 2abc + a^2 (b + c) (they only grow
 * toward that corner; the + 1 of a size holds the mean value's point),
 * times 2^4s; four monomials a term, so
 *   |P(d) - 2^4s P(d')| <= 2^4s 4 (6abc + a^2 (b + c) + b^2 (c + a) + c^2 (a + b)),
 * below 2^4s 48 (2^14 + 1)^3 < 2^4s 2^48, and |P(d')| above that bound
 * decides. Here, not in predicates.c, so that the tests hold it to that
 * contract (test_predicates.c, check_point_bound). */
VOR__INLINE uint64_t vor__incircle_point_bound(const int32_t shifted[6])
{
    uint32_t a = vor__point_size(&shifted[0]);
    uint32_t b = vor__point_size(&shifted[2]);
    uint32_t c = vor__point_size(&shifted[4]);
    uint64_t sum = vor__mul_u32(a * b, 6u * c) + vor__mul_u32(a * a, b + c) +
                   vor__mul_u32(b * b, c + a) + vor__mul_u32(c * c, a + b);
    return sum << 2;
}

/* The bounds of the six differences d (vor__mw_bound). The caller ORs
 * them in its own scope to pick the tier: an analyser then narrows each
 * bound by the test of that OR (not through a returned value). */
VOR__INLINE void vor__incircle_bounds(uint64_t b[6], const int64_t d[6])
{
    b[0] = vor__mw_bound(d[0]);
    b[1] = vor__mw_bound(d[1]);
    b[2] = vor__mw_bound(d[2]);
    b[3] = vor__mw_bound(d[3]);
    b[4] = vor__mw_bound(d[4]);
    b[5] = vor__mw_bound(d[5]);
}

/* The narrow tier's determinant, of the differences d taken back from
 * their bounds b (vor__mw_unbound) once the OR of b is below 2^14. */
VOR__INLINE int64_t vor__incircle_narrow_of(const uint64_t b[6], const int64_t d[6])
{
    int32_t n[6] = {vor__mw_unbound(b[0], d[0]), vor__mw_unbound(b[1], d[1]),
                    vor__mw_unbound(b[2], d[2]), vor__mw_unbound(b[3], d[3]),
                    vor__mw_unbound(b[4], d[4]), vor__mw_unbound(b[5], d[5])};
    return vor__incircle_narrow(n);
}

VOR__INLINE int vor__incircle_exact(const vor_point_t *a, const vor_point_t *b,
                                    const vor_point_t *c, const vor_point_t *dp,
                                    vor_stats_t *stats)
{
    int64_t d[6] = {(int64_t)a->x - dp->x, (int64_t)a->y - dp->y,
                    (int64_t)b->x - dp->x, (int64_t)b->y - dp->y,
                    (int64_t)c->x - dp->x, (int64_t)c->y - dp->y};
    uint64_t bounds[6];
    vor__incircle_bounds(bounds, d);
    uint64_t m = bounds[0] | bounds[1] | bounds[2] | bounds[3] | bounds[4] | bounds[5];
    if (m < ((uint32_t)1 << 14)) {
        VOR__COUNT(stats, incircle[VOR_TIER_NARROW]);
        return vor__mw_sign64(vor__incircle_narrow_of(bounds, d));
    }
    if (m < 0x80000000u) {
        VOR__COUNT(stats, incircle[VOR_TIER_MID]);
        return vor__incircle_mid(d, m);
    }
    VOR__COUNT(stats, incircle[VOR_TIER_WIDE]);
    return vor__incircle_wide(d);
}

#endif
