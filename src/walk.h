/* SPDX-License-Identifier: MIT */
/*
 * walk.h - the greedy neighbour walk, private to the library (the
 * starting-point search of Ohya, Iri and Murota): from a site, move to a
 * mesh neighbour that comes strictly before it in a goal's order, until
 * none does. The goals:
 *
 *   VOR__WALK_POINT   a site nearest to a query point, exactly, noting a
 *                     tie among the last site's neighbours (queries.c);
 *   VOR__WALK_LOWEST  the site with the smallest (y, x) (geometry.c).
 *
 * Why a site with no neighbour before it is the goal's first site: a site
 * that is not nearest has a strictly closer Delaunay neighbour (queries.c),
 * one that is not lowest a lower one (geometry.c). The walk steps over
 * mesh neighbours, a superset of the Delaunay ones, so this holds on the
 * perturbed mesh too.
 *
 * Termination, for every goal: each move goes to a site strictly before
 * the current one in a strict total order on the sites, so no site is
 * visited twice and there are fewer than vertex_count moves; that bound
 * is kept even if a predicate lies (fault injection), and each turn
 * around a site ends within vertex_count + 1 triangles even on a broken
 * mesh.
 *
 * Inline, with the goal a constant at each call, so that each caller gets
 * the walk specialised to its order, as fast as its own copy was.
 */
#ifndef VOR_WALK_H
#define VOR_WALK_H

#include <stdbool.h>

#include "mesh.h"
#include "multiword.h"
#include "perturbation.h"
#include "predicates.h"
#include "vor.h"

enum vor__walk_goal { VOR__WALK_POINT, VOR__WALK_LOWEST };

typedef struct {
    const vor_t *d;
    enum vor__walk_goal goal;
    const vor_point_t *q; /* VOR__WALK_POINT: the query */
    bool narrow;          /* VOR__WALK_POINT: vor__walk_is_narrow */
    bool tie;             /* out: a neighbour of the end is as close as it */
} vor__walk_t;

/* A walk toward `goal` on d, its other fields cleared for the caller to
 * set. Field by field: an initializer could become a memset call. */
static inline void vor__walk_begin(vor__walk_t *w, const vor_t *d, enum vor__walk_goal goal)
{
    w->d = d;
    w->goal = goal;
    w->q = NULL;
    w->narrow = false;
    w->tie = false;
}

/* Can the walk toward query (x, y) compare distances in int64 alone? Yes
 * when the sites' box spans less than 2^30 on each axis and every site s
 * has q - s in int32: then for a neighbour n of s, with d = n - s and
 * e = q - s,
 *     |q - n|^2 - |q - s|^2 = |d|^2 - e.(2d),
 * where |d|^2 < 2^61 and |e.(2d)| < 2 * 2^31 * 2^31 = 2^63: both int64,
 * compared without subtracting. */
static inline bool vor__walk_is_narrow(const vor_t *d, int32_t x, int32_t y)
{
    const int64_t reach = INT32_MAX;
    return (uint32_t)d->high.x - (uint32_t)d->low.x < ((uint32_t)1 << 30) &&
           (uint32_t)d->high.y - (uint32_t)d->low.y < ((uint32_t)1 << 30) &&
           ((int64_t)x - d->high.x) >= -reach && ((int64_t)x - d->low.x) <= reach &&
           ((int64_t)y - d->high.y) >= -reach && ((int64_t)y - d->low.y) <= reach;
}

/* Sign of |q - n|^2 - |q - s|^2 in the narrow case above (e = q - s). */
static inline int vor__narrow_closer(int32_t ex, int32_t ey, const vor_point_t *s,
                                     const vor_point_t *n)
{
    /* |.| < 2^30 */
    int32_t dx = n->x - s->x;
    int32_t dy = n->y - s->y;
    int64_t square = vor__mul_i32(dx, dx) + vor__mul_i32(dy, dy);
    int64_t twice_dot = vor__mul_i32(ex, 2 * dx) + vor__mul_i32(ey, 2 * dy);
    return (square < twice_dot) ? -1 : (square > twice_dot) ? 1 : 0;
}

/* Where neighbour n stands against site `best` in the goal's order: < 0
 * before it, 0 as close (VOR__WALK_POINT only), > 0 after it. A query
 * walk compares with the current site only (at, with e = q - at when
 * narrow): it moves at the first closer neighbour, so best is that site. */
static inline int vor__walk_compare(vor__walk_t *w, const vor_point_t *s, uint32_t n,
                                    uint32_t best, const vor_point_t *at, int32_t ex,
                                    int32_t ey)
{
    if (w->goal == VOR__WALK_POINT) {
        return w->narrow ? vor__narrow_closer(ex, ey, at, &s[n])
                         : vor__closer_sign(w->q, &s[n], at, NULL);
    }
    return ((s[n].y < s[best].y) || ((s[n].y == s[best].y) && (s[n].x < s[best].x))) ? -1 : 1;
}

/* The walk from site `from` (in the mesh, which has two or more sites);
 * returns where it ends. A query walk moves at the first neighbour
 * closer than the current site, so that its comparisons are all against
 * that site, whose offset to q is computed once a move; the walk to the
 * lowest site moves to the lowest neighbour. The neighbours come in fan
 * order from the site's home slot. */
static inline uint32_t vor__walk(vor__walk_t *w, uint32_t from)
{
    const vor_t *d = w->d;
    const vor_point_t *s = d->sites;
    const vor__tri_t *tri = d->triangles;
    uint32_t site = from;
    for (uint32_t moves = 0; moves < d->vertex_count; moves++) {
        const vor_point_t *at = &s[site];
        bool offset = (w->goal == VOR__WALK_POINT) && w->narrow;
        int32_t ex = offset ? (w->q->x - at->x) : 0;
        int32_t ey = offset ? (w->q->y - at->y) : 0;
        uint32_t slot = site;
        uint32_t best = site;
        w->tie = false;
        for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
            const vor__tri_t *t = &tri[slot];
            unsigned i = vor__vertex_index(t, (vor_index_t)site);
            if (i == 3u) {
                break; /* only on a broken mesh */
            }
            vor_index_t n = vor__vertex(t, vor__next(i));
            slot = t->n[vor__prev(i)];
            if (n != VOR__INFINITE) {
                int c = vor__walk_compare(w, s, n, best, at, ex, ey);
                if ((c < 0) && (w->goal == VOR__WALK_POINT)) {
                    best = n;
                    break;
                }
                best = (c < 0) ? n : best;
                w->tie = w->tie || (c == 0);
            }
            if (slot == site) {
                break;
            }
        }
        if (best == site) {
            break;
        }
        site = best;
    }
    return site;
}

#endif
