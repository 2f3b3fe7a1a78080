/*
 * vor.h - exact Voronoi diagrams and Delaunay triangulations for
 * microcontrollers. Freestanding C99: no malloc, no libc, no floating point,
 * no global state. All memory belongs to the caller.
 *
 * COORDINATES
 *   Sites are int32_t points over the whole range [INT32_MIN, INT32_MAX].
 *   Map fixed-point or float inputs to integers before calling vor
 *   ("integer reduction"): e.g. metres in Q16.16 are already int32.
 *
 * EXACT PREDICATES
 *   Every geometric decision in vor is one of three signs, computed exactly
 *   with multi-word integers:
 *
 *     vor_orient2d(a, b, c)     > 0  a, b, c turn counterclockwise
 *                               = 0  collinear
 *                               < 0  clockwise
 *     vor_incircle(a, b, c, d)  > 0  d inside the circle through a, b, c
 *                                    (a, b, c counterclockwise)
 *                               = 0  cocircular
 *     vor_closer(q, a, b)       sign of |q-a|^2 - |q-b|^2:
 *                               < 0  q is strictly closer to a than to b
 *
 *   Each call evaluates in the narrowest width that is provably exact for
 *   its operands (a "tier"): int64 when the coordinate differences are
 *   small, 128 bits for mid-size differences, and full multi-word width
 *   (133-bit results for incircle) otherwise. The widths are fixed by
 *   bounds, not by error estimates, so there is no fallback that could
 *   miss: every result is exact. Pass a vor_predicate_stats_t to count how
 *   often each tier ran, or NULL.
 *
 * SYMBOLIC PERTURBATION
 *   The _sos variants ("simulation of simplicity") never return 0. They take
 *   an array of sites and indices into it; site i is treated as if it were
 *   moved to
 *
 *       (x_i + eps^(4 * 16^i),  y_i + eps^(16^i))
 *
 *   for an infinitesimal eps > 0, and the sign of the moved configuration is
 *   returned. When the exact sign is not 0 the two agree. Otherwise the tie
 *   is broken by a fixed order on indices: a smaller index is moved further
 *   (it dominates), and y before x. Both predicates use the same moved
 *   points, so all their answers are consistent with one configuration in
 *   general position: collinear and cocircular inputs need no special case.
 *   Only the order of the indices matters, never their values.
 *   Identical points with different indices are separated too, but the
 *   diagram builders report them as duplicates instead of relying on it.
 *
 * COST (docs/benchmarks.md has the measured table)
 *   No call allocates, recurses or loops over data. A degenerate input to an
 *   _sos predicate evaluates at most 5 (orient2d) or 27 (incircle) small
 *   determinants; typical degeneracies are decided by the first one.
 *
 * CONFIGURATION: vor_config.h.  DESIGN: docs/design.md.  API: docs/api.md.
 */
#ifndef VOR_H
#define VOR_H

#include <stddef.h>
#include <stdint.h>

#include "vor_config.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A site or query point: integer coordinates over the full int32 range. */
typedef struct vor_point {
    int32_t x;
    int32_t y;
} vor_point_t;

/* The evaluation widths of the exact predicates, narrowest first. */
enum vor_tier {
    VOR_TIER_NARROW = 0, /* int64: small coordinate differences */
    VOR_TIER_MID = 1,    /* 128 bits (incircle only) */
    VOR_TIER_WIDE = 2,   /* full multi-word width */
    VOR_TIERS = 3
};

/* Per-tier call counters. Zero it before use; counters wrap modulo 2^32. */
typedef struct vor_predicate_stats {
    uint32_t orient2d[VOR_TIERS];
    uint32_t incircle[VOR_TIERS];
    uint32_t closer[VOR_TIERS];
    uint32_t orient2d_perturbed; /* _sos calls decided by the perturbation */
    uint32_t incircle_perturbed;
} vor_predicate_stats_t;

/*
 * Exact sign (-1, 0 or 1) of det[[ax ay 1][bx by 1][cx cy 1]]:
 * positive when a, b, c turn counterclockwise (x right, y up).
 * Tiers: narrow when every coordinate difference fits in int32, else wide.
 * stats may be NULL. Never fails.
 */
int vor_orient2d(const vor_point_t *a, const vor_point_t *b,
                 const vor_point_t *c, vor_predicate_stats_t *stats);

/*
 * Exact sign of det of the rows (x, y, x^2 + y^2, 1) of a, b, c, d:
 * positive when d lies inside the circle through a, b, c and a, b, c are
 * counterclockwise (negated when they are clockwise), 0 when cocircular.
 * Tiers, with D the largest |coordinate difference| to d: narrow for
 * D <= 2^14, mid for D <= 2^30, else wide (differences in [-2^k, 2^k - 1]
 * count as D <= 2^k). stats may be NULL. Never fails.
 */
int vor_incircle(const vor_point_t *a, const vor_point_t *b,
                 const vor_point_t *c, const vor_point_t *d,
                 vor_predicate_stats_t *stats);

/*
 * Exact sign of |q-a|^2 - |q-b|^2: -1 when q is strictly closer to a,
 * 1 when strictly closer to b, 0 on the bisector.
 * Tiers: narrow when every difference to q fits in int32, else wide.
 * stats may be NULL. Never fails.
 */
int vor_closer(const vor_point_t *q, const vor_point_t *a,
               const vor_point_t *b, vor_predicate_stats_t *stats);

/*
 * vor_orient2d of sites[i], sites[j], sites[k] under the symbolic
 * perturbation described at the top of this file: -1 or 1, never 0.
 * i, j, k must be distinct (indices order the perturbation).
 */
int vor_orient2d_sos(const vor_point_t *sites, uint32_t i, uint32_t j,
                     uint32_t k, vor_predicate_stats_t *stats);

/*
 * vor_incircle of sites[i], sites[j], sites[k], sites[l] under the
 * symbolic perturbation: -1 or 1, never 0. Indices must be distinct.
 */
int vor_incircle_sos(const vor_point_t *sites, uint32_t i, uint32_t j,
                     uint32_t k, uint32_t l, vor_predicate_stats_t *stats);

#ifdef __cplusplus
}
#endif

#endif
