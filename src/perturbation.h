/* SPDX-License-Identifier: MIT */
/*
 * perturbation.h - the perturbation, private to the library: how the
 * builders ask the exact predicates (predicates.h) about mesh sites, with
 * ties broken by symbolic perturbation and, in test builds, injected
 * faults; and how every output hides the device again, reporting the true
 * diagram of the distinct sites (docs/design/queries.md, "What the iterators
 * report").
 */
#ifndef VOR_PERTURBATION_H
#define VOR_PERTURBATION_H

#include <stdbool.h>

#include "mesh.h"
#include "multiword.h"
#include "predicates.h"
#include "vor.h"

/* The perturbed predicates as the mesh calls them: site ids are the
 * perturbation's order, stats counts the tiers in a VOR_STATS build (the
 * diagram's counters, or a divide-and-conquer worker's own, so that two
 * cores never write the same counter; NULL otherwise), and the narrow
 * tiers are inlined. In fault injection builds (tests only) a sign is
 * flipped with probability d->fault_rate / 2^32. */
static inline int vor__with_faults(vor_t *d, int sign)
{
#ifdef VOR_FAULT_INJECTION
    if (d->fault_rate != 0u) {
        uint64_t x = d->fault_state;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        d->fault_state = x;
        return ((uint32_t)(x >> 32) < d->fault_rate) ? -sign : sign;
    }
#else
    (void)d;
#endif
    return sign;
}

/* The perturbed orientation of sites a, b, c of d; *tie becomes true when
 * their exact orientation is 0, so that the perturbation decided (the
 * walk learns from it that the point lies on an edge's line). */
static inline int vor__orient_tie(vor_t *d, vor_stats_t *stats, uint32_t a, uint32_t b,
                                  uint32_t c, bool *tie)
{
    const vor_point_t *s = d->sites;
    int sign = vor__orient2d_exact(&s[a], &s[b], &s[c], stats);
    if (sign == 0) {
        *tie = true;
        sign = vor__orient2d_perturbed(s, a, b, c, stats);
    }
    return vor__with_faults(d, sign);
}

static inline int vor__orient_counted(vor_t *d, vor_stats_t *stats, uint32_t a, uint32_t b,
                                      uint32_t c)
{
    bool tie = false;
    return vor__orient_tie(d, stats, a, b, c, &tie);
}

VOR__INLINE int vor__incircle_counted(vor_t *d, vor_stats_t *stats, uint32_t a, uint32_t b,
                                      uint32_t c, uint32_t p)
{
    const vor_point_t *s = d->sites;
    int sign = vor__incircle_exact(&s[a], &s[b], &s[c], &s[p], stats);
    if (sign == 0) {
        sign = vor__incircle_perturbed(s, a, b, c, p, stats);
    }
    return vor__with_faults(d, sign);
}

static inline int vor__orient(vor_t *d, uint32_t a, uint32_t b, uint32_t c)
{
    return vor__orient_counted(d, VOR__STATS_OF(d), a, b, c);
}

VOR__INLINE int vor__incircle(vor_t *d, uint32_t a, uint32_t b, uint32_t c, uint32_t p)
{
    return vor__incircle_counted(d, VOR__STATS_OF(d), a, b, c, p);
}

/* Does the triangle (v0, v1, v2) (finite or at infinity) conflict with
 * site p, i.e. is p strictly inside its circumcircle (for a hull triangle:
 * strictly outside its hull edge, left of a -> b in (a, b, inf))? The
 * Voronoi vertex it stands for would be deleted by p. */
static inline bool vor__conflicts(vor_t *d, vor_index_t v0, vor_index_t v1, vor_index_t v2,
                                  uint32_t p)
{
    if (v0 == VOR__INFINITE) {
        return vor__orient(d, v1, v2, p) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return vor__orient(d, v2, v0, p) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return vor__orient(d, v0, v1, p) > 0;
    }
    return vor__incircle(d, v0, v1, v2, p) > 0;
}

/* What a call that fails after evaluating predicates restores, so that
 * it changes nothing: the VOR_STATS counters and the fault generator's
 * state (test builds). Empty in a release build, where predicates write
 * nothing but their answers. */
typedef struct {
#if VOR_STATS
    vor_stats_t stats;
#endif
#ifdef VOR_FAULT_INJECTION
    uint64_t fault_state;
#endif
    char unused; /* C99 wants a member */
} vor__tally_t;

static inline void vor__tally_save(vor__tally_t *to, const vor_t *d)
{
#if VOR_STATS
    vor__stats_copy(&to->stats, &d->stats);
#endif
#ifdef VOR_FAULT_INJECTION
    to->fault_state = d->fault_state;
#endif
    to->unused = 0;
    (void)d;
}

static inline void vor__tally_restore(vor_t *d, const vor__tally_t *from)
{
#if VOR_STATS
    vor__stats_copy(&d->stats, &from->stats);
#endif
#ifdef VOR_FAULT_INJECTION
    d->fault_state = from->fault_state;
#endif
    (void)d;
    (void)from;
}

/* The orientation of sites a, b (distinct points) and a query point q
 * under the perturbation, q taking an index before every site's: q moves
 * to (q.x + e^4, q.y + e) for an infinitesimal e, far more than any site
 * moves, so a tie is decided by q's move alone,
 *     orient(a, b, q~) = orient(a, b, q) + (b.x - a.x) e - (b.y - a.y) e^4,
 * the sign of b.x - a.x, then of a.y - b.y. Never 0 for distinct a and b:
 * q~ lies on no line through two sites (vor_locate). Uncounted. */
static inline int vor__orient_query(const vor_point_t *a, const vor_point_t *b,
                                    const vor_point_t *q)
{
    int sign = vor__orient2d_exact(a, b, q, NULL);
    if (sign == 0) {
        sign = vor__mw_sign64((int64_t)b->x - a->x);
    }
    if (sign == 0) {
        sign = vor__mw_sign64((int64_t)a->y - b->y);
    }
    return sign;
}

/* ------------------------------------------------------------------ */
/* The true output                                                     */

/* What the iterators report is the true Delaunay triangulation of the
 * distinct sites, not the perturbed mesh (docs/design/queries.md, "What the
 * iterators report"): a finite triangle is reported exactly when its
 * three sites are not collinear (unperturbed). A flat triangle's perturbed
 * circumcircle is a half-plane in the limit, empty only on a side of a
 * hull line, so dropping those leaves a triangulation of the hull.
 * Of a triangle's decoded vertices v. */
VOR__SHARED_INLINE bool vor__reported_vertices(const vor_point_t *s, const vor_index_t v[3])
{
    return v[0] != VOR__INFINITE && (v[1] != VOR__INFINITE) && (v[2] != VOR__INFINITE) &&
           vor__orient2d_exact(&s[v[0]], &s[v[1]], &s[v[2]], NULL) != 0;
}

/* The same of the triangle t (its vertices decoded here). A caller that
 * goes on to use the vertices decodes them and asks
 * vor__reported_vertices, so that an analyser sees them finite. */
static inline bool vor__reported(const vor_point_t *s, const vor__tri_t *t)
{
    vor_index_t v[3];
    vor__vertices(t, v);
    return vor__reported_vertices(s, v);
}

/* For collinear a, m, b: does m lie strictly inside the segment ab? Then
 * the steps a -> m and m -> b point the way a -> b does, coordinate by
 * coordinate (no products needed). */
static inline bool vor__strictly_between(const vor_point_t *a, const vor_point_t *m,
                                         const vor_point_t *b)
{
    int sx = vor__mw_sign64((int64_t)b->x - a->x);
    int sy = vor__mw_sign64((int64_t)b->y - a->y);
    return (vor__mw_sign64((int64_t)m->x - a->x) == sx) && vor__mw_sign64((int64_t)m->y - a->y) == sy &&
           vor__mw_sign64((int64_t)b->x - m->x) == sx && vor__mw_sign64((int64_t)b->y - m->y) == sy;
}

/* Does site c (VOR__INFINITE for a triangle at infinity), the third vertex
 * of a triangle on the mesh edge a-b, lie exactly on the segment between
 * a and b? Then a and b are not Delaunay neighbours: c is strictly closer
 * than both on their whole bisector. */
static inline bool vor__splits_edge(const vor_point_t *s, uint32_t a, uint32_t b, uint32_t c)
{
    return c != VOR__INFINITE && vor__orient2d_exact(&s[a], &s[b], &s[c], NULL) == 0 &&
           vor__strictly_between(&s[a], &s[c], &s[b]);
}

/* Is the mesh edge a-b, between the triangles with third vertices c and e
 * (either may be VOR__INFINITE), an edge of the true triangulation, or on
 * all-collinear input a pair of sites adjacent along the line? When a
 * triangle on it is reported, yes. Otherwise both are flat or at infinity,
 * and a-b is a true edge unless one of them has its third vertex between
 * a and b: a site strictly between a and b but on neither triangle would
 * lie, under the perturbation, on one side of the edge, where the
 * triangle's circumcircle (a half-plane through a and b in the limit, or
 * the outside of the hull) contains the segment's neighbourhood. And a
 * reported triangle never sits beside a splitting one: its circumcircle
 * would hold the splitting site on its chord a-b. */
static inline bool vor__true_edge(const vor_point_t *s, uint32_t a, uint32_t b, uint32_t c,
                                  uint32_t e)
{
    if (c != VOR__INFINITE && vor__orient2d_exact(&s[a], &s[b], &s[c], NULL) != 0) {
        return true;
    }
    return !vor__splits_edge(s, a, b, c) && !vor__splits_edge(s, a, b, e);
}

/* The next mesh neighbour that is a true one (vor__true_edge): the
 * triangle just passed lies on one side of the edge, the fan's next (in
 * it->slot) on the other. What vor_neighbours_next reports. */
static inline bool vor__true_neighbour_next(vor_neighbour_iter_t *it, uint32_t *neighbour)
{
    const vor_t *d = it->d;
    uint32_t n;
    uint32_t third;
    while (vor__fan_next(it, &n, &third)) {
        const vor__tri_t *after = &d->triangles[it->slot];
        unsigned j = vor__vertex_index(after, (vor_index_t)it->site);
        uint32_t other = (j == 3u) ? VOR__INFINITE : vor__vertex(after, vor__next(j));
        if (vor__true_edge(d->sites, it->site, n, third, other)) {
            *neighbour = n;
            return true;
        }
    }
    return false;
}

#endif
