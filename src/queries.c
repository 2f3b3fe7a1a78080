/*
 * queries.c - questions asked of a built diagram. Read-only: no query
 * writes the diagram, so several threads may query one diagram at once.
 *
 * Nearest site (seed 003 section 2.3, the starting-point search): from a
 * hint, step to a Delaunay neighbour strictly closer to the query, with
 * exact distance comparisons, until none is. That reaches the smallest
 * distance d: if a site s is not nearest, the segment from s to the query
 * leaves s's Voronoi cell through an edge, whose other site is a closer
 * Delaunay neighbour, or through a vertex, where every other site on that
 * vertex's circle is strictly closer (its chord from s makes an acute angle
 * with the segment), among them s's neighbours on the circle.
 *
 * Ties: all sites at distance d lie on a circle around the query with no
 * site inside, and two of them that are consecutive on the circle are
 * joined by an edge of every Delaunay triangulation. Walking that polygon
 * counterclockwise visits them all; the smallest index wins.
 */
#include "mesh.h"

void vor_neighbours_begin(vor_neighbour_iter_t *it, const vor_t *d, uint32_t site)
{
    it->d = d;
    it->site = site;
    it->slot = site;
    /* no triangles: one site, or a duplicate's id */
    it->left = (d->vertex_count >= 2u && site < d->site_count &&
                !vor__slot_empty(&d->triangles[site]))
                   ? d->vertex_count + 1u
                   : 0u;
}

int vor_neighbours_next(vor_neighbour_iter_t *it, uint32_t *neighbour)
{
    const vor_t *d = it->d;
    /* turning around the site from its home slot: one neighbour per
     * triangle of its fan; `left` bounds the turn even on a broken mesh */
    while (it->left > 0u) {
        const vor__tri_t *t = &d->triangles[it->slot];
        unsigned i = vor__vertex_index(t, (vor_index_t)it->site);
        if (i == 3u) { /* not in this triangle: only on a broken mesh */
            it->left = 0;
            return 0;
        }
        vor_index_t n = vor__vertex(t, vor__next(i));
        it->slot = t->n[vor__prev(i)];
        it->left = (it->slot == it->site) ? 0u : it->left - 1u;
        if (n != VOR__INFINITE) {
            *neighbour = n;
            return 1;
        }
    }
    return 0;
}

/* Is t before u going counterclockwise around q from `from` (all three on
 * one circle around q)? Angles in (0, pi) come before [pi, 2 pi). */
static bool before(const vor_t *d, const vor_point_t *q, uint32_t from, uint32_t t, uint32_t u)
{
    const vor_point_t *s = d->sites;
    bool t_first_half = vor_orient2d(q, &s[from], &s[t], NULL) > 0;
    bool u_first_half = vor_orient2d(q, &s[from], &s[u], NULL) > 0;
    if (t_first_half != u_first_half) {
        return t_first_half;
    }
    return vor_orient2d(q, &s[t], &s[u], NULL) > 0;
}

int vor_nearest(const vor_t *d, int32_t x, int32_t y, uint32_t hint, uint32_t *site)
{
    if (d == NULL || site == NULL) {
        return VOR_ERR_ARG;
    }
    if (d->vertex_count == 0u) {
        return VOR_ERR_EMPTY;
    }
    if (hint == VOR_NO_HINT) {
        hint = d->last_site;
    }
    if (hint >= d->site_count) {
        return VOR_ERR_ARG;
    }
    if (d->vertex_count == 1u) {
        *site = d->last_site;
        return VOR_OK;
    }
    if (vor__slot_empty(&d->triangles[hint])) {
        return VOR_ERR_ARG; /* a duplicate's id: not in the mesh */
    }
    const vor_point_t q = {x, y};
    const vor_point_t *s = d->sites;

    /* greedy: each step strictly decreases the exact distance, so it ends
     * within vertex_count steps */
    vor_neighbour_iter_t it;
    uint32_t n, best = hint;
    bool tie = false; /* a neighbour of `best` as close as it */
    for (uint32_t step = 0; step < d->vertex_count; step++) {
        uint32_t from = best;
        tie = false;
        vor_neighbours_begin(&it, d, from);
        while (vor_neighbours_next(&it, &n)) {
            int c = vor_closer(&q, &s[n], &s[best], NULL);
            if (c < 0) {
                best = n;
                tie = false;
            } else if (c == 0) {
                tie = true;
            }
        }
        if (best == from) {
            break;
        }
    }

    /* ties: around the empty circle through `best`, smallest index. Only
     * when the last round saw one: every site on that circle is then a
     * neighbour of another, so a tie shows up among best's neighbours. */
    uint32_t smallest = best, current = best;
    for (uint32_t step = 0; tie && step < d->vertex_count; step++) {
        uint32_t next = VOR__NONE;
        vor_neighbours_begin(&it, d, current);
        while (vor_neighbours_next(&it, &n)) {
            if (vor_closer(&q, &s[n], &s[best], NULL) == 0 &&
                (next == VOR__NONE || before(d, &q, current, n, next))) {
                next = n;
            }
        }
        if (next == VOR__NONE || next == best) {
            break;
        }
        smallest = (next < smallest) ? next : smallest;
        current = next;
    }
    *site = smallest;
    return VOR_OK;
}
