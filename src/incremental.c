/* SPDX-License-Identifier: MIT */
/*
 * incremental.c - the topology-oriented incremental builder (Sugihara and
 * Iri; the insertion order of Ohya, Iri and Murota): dynamic insertion and the batch build.
 *
 * Inserting site p deletes the Voronoi vertices (Delaunay triangles) that
 * are closer to p than to their own sites and fills the hole with the
 * triangles around p. Here that is done in place, without a stack:
 *
 *   1. locate: walk to the triangle containing p; its Voronoi vertex is
 *      deleted first;
 *   2. split that triangle into three around p;
 *   3. walk once around p's star. Across each star edge lies a triangle u
 *      whose Voronoi vertex is a candidate for deletion: it is deleted,
 *      i.e. the edge is flipped so that u joins the star, only if
 *        (a) the deleted set stays a tree: u's far vertex c is not on the
 *            star yet (Sugihara and Iri's tree condition); and
 *        (b) the perturbed incircle puts p inside u's circle.
 *
 * Condition (a) is the topological guard: a flip whose far vertex is
 * already on the star would close a cycle of deleted Voronoi vertices (or
 * pinch the star), so it is never made, and every flip keeps a valid
 * triangulation of the sphere whatever the predicates answer. With exact
 * arithmetic the guard never refuses a flip that (b) accepts, and the
 * result is the unique Delaunay triangulation under the perturbation.
 *
 * Home slots: slot s always holds a triangle incident to site s (mesh.h);
 * the split and each flip choose which new triangle goes to which of the
 * slots they reuse so that this stays true.
 */
#include "bucket_grid.h"
#include "cdt.h"
#include "incremental.h"
#include "insertion_order.h"
#include "mesh.h"
#include "motion.h"
#include "multiword.h"
#include "perturbation.h"
#include "walk.h"

/* Is slot a home slot of site v (v may be infinity, which has none)? */
static inline bool is_home(const vor_t *d, vor_index_t slot, vor_index_t v)
{
    return (slot == v) && (v < d->max_sites);
}

/* ------------------------------------------------------------------ */
/* Locate                                                              */

vor_index_t vor__locate(vor_t *d, vor_index_t start, uint32_t p, bool *on_line)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t slot = start;
    /* With exact predicates the visibility walk in a Delaunay triangulation
     * never revisits a triangle (Edelsbrunner), so it ends within the
     * triangle count; the bound only matters if the predicates lie. */
    uint32_t limit = vor__triangle_count(d->vertex_count);
    unsigned first = 0;
    for (uint32_t step = 0; step <= limit; step++) {
        const vor__tri_t *t = &tri[slot];
        /* an exact zero among this triangle's tests: p is on an edge's line */
        bool tie = false;
        *on_line = false;
        unsigned infinite = vor__vertex_index(t, VOR__INFINITE);
        if (infinite != 3u) {
            /* outside the hull edge (a, b): found; else step inside */
            vor_index_t a = vor__vertex(t, vor__next(infinite));
            vor_index_t b = vor__vertex(t, vor__prev(infinite));
            if (vor__orient_tie(d, VOR__STATS_OF(d), a, b, p, &tie) > 0) {
                *on_line = tie;
                return slot;
            }
            slot = t->n[infinite];
            continue;
        }
        /* leave through the first edge with p strictly outside; starting
         * at a rotating edge keeps a lying predicate from pinning the walk */
        first = vor__next(first);
        unsigned i = first;
        bool moved = false;
        do {
            vor_index_t a = vor__vertex(t, vor__next(i));
            vor_index_t b = vor__vertex(t, vor__prev(i));
            if (vor__orient_tie(d, VOR__STATS_OF(d), a, b, p, &tie) < 0) {
                slot = t->n[i];
                moved = true;
                break;
            }
            i = vor__next(i);
        } while (i != first);
        if (!moved) {
            *on_line = tie;
            return slot;
        }
    }
    *on_line = true; /* only if the predicates lie: take the careful path */
    return slot;
}

/* ------------------------------------------------------------------ */
/* Updating the mesh                                                   */

/* In triangle `slot`, point the link that pointed at `from` at `to`. */
static void relink(vor__tri_t *tri, vor_index_t slot, vor_index_t from, vor_index_t to)
{
    vor__tri_t *t = &tri[slot];
    unsigned i = vor__neighbour_index(t, from);
    if (i != 3u) { /* always found in a valid mesh */
        t->n[i] = to;
    }
}


/* The insertion proper: split, then the star's pass. With constraint
 * memory (cdt not NULL: the constrained triangulation's own mesh) a
 * constrained edge is never flipped, which is Lawson's insertion into a
 * constrained Delaunay triangulation; the diagram's own insertions pass
 * NULL, and the test compiles away in them. */
/* Splits the triangle in slot `root` into three around p (not yet
 * counted in the vertex count). Returns the slot of (p, b, c), b and c
 * the root's second and third vertices; p's home slot holds another. */
VOR__ALWAYS_INLINE vor_index_t split(vor_t *d, vor_index_t root, uint32_t p)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t sp = (vor_index_t)p;
    vor__tri_t *r = &tri[root];
    vor_index_t a = vor__vertex(r, 0);
    vor_index_t b = vor__vertex(r, 1);
    vor_index_t c = vor__vertex(r, 2);
    vor_index_t na = r->n[0];
    vor_index_t nb = r->n[1];
    vor_index_t nc = r->n[2];

    /* split into A = (p, b, c), B = (p, c, a), C = (p, a, b) in the root's
     * slot, p's home slot and one new slot, the root's slot going to a
     * triangle that holds the site it is home to */
    vor_index_t extra = (vor_index_t)(d->max_sites + d->vertex_count - 2u);
    vor_index_t sa = root;
    vor_index_t sb = sp;
    vor_index_t sc = extra;
    if (is_home(d, root, a)) { /* A lacks a; C = (p, a, b) takes the slot */
        sa = extra;
        sc = root;
    }
    vor__tri_fresh(&tri[sp]);
    vor__tri_fresh(&tri[extra]);
    if (d->vertex_count == 2u) { /* the root's neighbour is one triangle */
        vor__relink_before(tri, na, b, sa);
        vor__relink_before(tri, nb, c, sb);
        vor__relink_before(tri, nc, a, sc);
    } else {
        relink(tri, na, root, sa);
        relink(tri, nb, root, sb);
        relink(tri, nc, root, sc);
    }
    vor__tri_set(&tri[sa], sp, b, c, na, sb, sc);
    vor__tri_set(&tri[sb], sp, c, a, nb, sc, sa);
    vor__tri_set(&tri[sc], sp, a, b, nc, sa, sb);
    return sa;
}

vor_index_t vor__split_triangle(vor_t *d, vor_index_t root, uint32_t p)
{
    return split(d, root, p);
}

VOR__ALWAYS_INLINE void insert_at(vor_t *d, vor_index_t root, uint32_t p,
                                     struct vor__cdt *cdt)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t sp = (vor_index_t)p;
    vor_index_t a = vor__vertex(&tri[root], 0);
    vor_index_t b = vor__vertex(&tri[root], 1);
    vor_index_t c = vor__vertex(&tri[root], 2);
    vor_index_t sa = split(d, root, p);

    /* guard (a) marks: the star's vertices */
    bool infinity_marked = false;
    vor__mark_site(d, a, true, &infinity_marked);
    vor__mark_site(d, b, true, &infinity_marked);
    vor__mark_site(d, c, true, &infinity_marked);

    /* one counterclockwise pass around p. A refused edge stays refused
     * (its far triangle is not in conflict, or its far vertex is marked,
     * and marks only accumulate), so the pass ends when as many edges in
     * a row were refused as the star has; every flip uses up a triangle
     * not on the star, so the loop ends even if the predicates lie. */
    vor_index_t slot = sa;
    uint32_t star = 3;
    uint32_t refused = 0;
    while (refused < star) {
        vor__tri_t *t = &tri[slot];
        /* t = (p, x, y), u = (y, x, c) */
        vor_index_t tv[3];
        vor_index_t uv[3];
        vor__vertices(t, tv);
        vor__vertices(&tri[t->n[0]], uv);
        unsigned ix = (uv[0] == tv[1]) ? 0u : (uv[1] == tv[1]) ? 1u : (uv[2] == tv[1]) ? 2u : 3u;
        if (ix == 3u) { /* only on a corrupted mesh: never index past it */
            refused++;
            slot = t->n[1];
            continue;
        }
        unsigned apex = vor__next(ix);
        vor_index_t far = uv[apex];
        bool flippable = (cdt == NULL) || !vor__cdt_constrained(cdt, tv[1], tv[2]);
        if (flippable && !vor__site_marked(d, far, infinity_marked) &&
            ((cdt == NULL) ? vor__conflicts(d, uv[0], uv[1], uv[2], p)
                           : vor__cdt_conflicts(cdt, uv[0], uv[1], uv[2], p))) {
            slot = vor__star_flip(d, slot, sp, tv[1], tv[2], apex, far);
            vor__mark_site(d, far, true, &infinity_marked);
            star++;
        } else {
            refused++;
            slot = t->n[1]; /* next counterclockwise: across (y, p) */
        }
    }
    /* clear the marks: each star vertex is v[1] of one star triangle */
    for (uint32_t k = 0; k < star; k++) {
        vor__mark_site(d, vor__vertex(&tri[slot], 1), false, &infinity_marked);
        slot = tri[slot].n[1];
    }
}

void vor__insert_at(vor_t *d, vor_index_t root, uint32_t p)
{
    insert_at(d, root, p, NULL);
}

void vor__insert_at_constrained(vor_t *mesh, vor_index_t root, uint32_t p,
                                struct vor__cdt *c)
{
    insert_at(mesh, root, p, c);
}

/* ------------------------------------------------------------------ */
/* Public insertion                                                    */

static bool same_point(const vor_point_t *a, const vor_point_t *b)
{
    return (a->x == b->x) && (a->y == b->y);
}

/* Takes the most recently freed id off the free list (vor_remove puts
 * them there, dynamic.c): d->free_site is that id plus one, 0 for none,
 * and the id's empty home slot holds the same for the next (one site has
 * no slots, and then no other free id). Here, not in dynamic.c, so that a
 * firmware that never removes links no removal code. */
void vor__take_free_id(vor_t *d)
{
    if (d->free_site != 0u) {
        uint32_t p = d->free_site - 1u;
        d->free_site = (d->max_sites >= 2u) ? d->triangles[p].n[1] : 0u;
    }
}

int vor_insert_near(vor_t *d, vor_point_t point, uint32_t hint, uint32_t *site)
{
    if ((d == NULL) || ((hint != VOR_NO_HINT) && !vor__site_in_mesh(d, hint))) {
        return VOR_ERR_ARG;
    }
    uint32_t start = hint;
    if (start == VOR_NO_HINT) { /* as vor_nearest: the bucket grid's site */
        start = (d->vertex_count >= 2u) ? vor__grid_start(d, point.x, point.y) : d->last_site;
    }
    bool reused = d->free_site != 0u; /* a removed site's id */
    if (!reused && (d->site_count >= d->max_sites)) {
        /* no free coordinates slot to locate from: a read-only query
         * tells a duplicate, which needs no slot, from a new site */
        uint32_t nearest;
        if ((vor_nearest(d, point, start, &nearest) == VOR_OK) &&
            same_point(&d->sites[nearest], &point)) {
            if (site != NULL) {
                *site = nearest;
            }
            return VOR_ERR_DUPLICATE;
        }
        return VOR_ERR_FULL;
    }
    uint32_t p = reused ? (d->free_site - 1u) : d->site_count;
    vor__tri_t *tri = d->triangles;

    if (d->vertex_count == 0u) {
        /* no triangle yet: with max_sites 1 the arena has no triangle
         * slots at all, so none is touched */
        vor__take_free_id(d);
        d->sites[p] = point;
    } else if (d->vertex_count == 1u) {
        if (same_point(&d->sites[d->last_site], &point)) {
            if (site != NULL) {
                *site = d->last_site;
            }
            return VOR_ERR_DUPLICATE;
        }
        vor__take_free_id(d);
        d->sites[p] = point;
        vor__make_edge(d, d->last_site, p);
    } else {
        /* find p's triangle first: a duplicate must change nothing, so the
         * coordinates slot (and in test builds the counters) are restored
         * in that case */
        vor_point_t saved_point = d->sites[p];
        vor__tally_t tally;
        vor__tally_save(&tally, d);
        d->sites[p] = point;
        bool on_line;
        vor_index_t root = vor__locate(d, (vor_index_t)start, p, &on_line);
        /* strictly inside its triangle (or strictly outside the hull) p can
         * only coincide with a vertex of it; on an edge line, degenerate
         * thin triangles can put its twin elsewhere: the nearest site (the
         * query's walk, which vor_insert_near links anyway for a full
         * diagram) is the twin if there is one, the only site at distance 0 */
        uint32_t twin = VOR__NONE;
        uint32_t corner = 0;
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t v = vor__vertex(&tri[root], i);
            if (v != VOR__INFINITE) {
                corner = v;
                twin = same_point(&d->sites[v], &point) ? v : twin;
            }
        }
        uint32_t nearest;
        if ((twin == VOR__NONE) && on_line && (vor_nearest(d, point, corner, &nearest) == VOR_OK) &&
            same_point(&d->sites[nearest], &point)) {
            twin = nearest;
        }
        if (twin != VOR__NONE) {
            d->sites[p] = saved_point;
            vor__tally_restore(d, &tally);
            if (site != NULL) {
                *site = twin;
            }
            return VOR_ERR_DUPLICATE;
        }
        if ((d->cdt_update != NULL) && (d->cdt_update(d, p, VOR__CDT_CHECK_INSERT) != VOR_OK)) {
            d->sites[p] = saved_point;
            vor__tally_restore(d, &tally);
            return VOR_ERR_NOMEM;
        }
        vor__take_free_id(d); /* p's home slot holds the list's link */
        vor__insert_at(d, root, p);
    }
    vor__box_add(d, &point, d->vertex_count == 0u);
    d->site_count += reused ? 0u : 1u;
    d->vertex_count++;
    d->last_site = p;
    d->revision++;
    vor__topology_changed(d);
    if (d->vertex_count >= 2u) {
        vor__grid_add(d, p);
    }
    if (d->cdt_update != NULL) {
        (void)d->cdt_update(d, p, VOR__CDT_INSERTED);
    }
    if (site != NULL) {
        *site = p;
    }
    return VOR_OK;
}

int vor_insert(vor_t *d, vor_point_t p, uint32_t *site)
{
    if (d == NULL) {
        return VOR_ERR_ARG;
    }
    /* the last inserted site, once there is one */
    return vor_insert_near(d, p, (d->vertex_count >= 1u) ? d->last_site : VOR_NO_HINT, site);
}

/* ------------------------------------------------------------------ */
/* Batch build                                                         */

int vor_build(vor_t *d, const vor_point_t *points, uint32_t n,
              const vor_build_options_t *options, uint32_t *duplicate_of)
{
    enum vor_order order = (options != NULL) ? options->order : VOR_ORDER_QUADTREE;
    if ((order != VOR_ORDER_QUADTREE) && (order != VOR_ORDER_INPUT)) {
        return VOR_ERR_ARG;
    }
    int status = vor__build_start(d, points, n, duplicate_of);
    if (status != VOR__BUILD_MESH) {
        return status;
    }
    /* scratch in the triangle slots, the plan at their very end: triangles
     * fill the slots from below and never reach a plan entry still to be
     * read (5 or 6 indices per triangle against 2 per remaining plan
     * entry; docs/design/incremental.md, "Batch build") */
    vor_index_t *base = (vor_index_t *)(void *)d->triangles;
    size_t entries = (size_t)vor__triangle_count(d->max_sites) * sizeof(vor__tri_t) /
                     sizeof(vor_index_t);
    vor_index_t *plan = base + entries - (2u * (size_t)n);
    uint32_t distinct = vor__plan(d, n, order, base, plan, duplicate_of);

    vor__tri_t *tri = d->triangles;
    for (uint32_t i = 0; i < n; i++) {
        vor_index_t s = plan[2u * i];
        vor_index_t from = plan[(2u * i) + 1u];
        if (VOR__PREFETCHING && ((i + 8u) < distinct)) { /* the memory of the insertion 8 ahead */
            vor_index_t ahead = plan[2u * (i + 8u)];
            vor_index_t ahead_from = plan[2u * (i + 8u) + 1u];
            VOR__PREFETCH(&d->sites[ahead]);
            VOR__PREFETCH(&tri[ahead]);
            if (ahead_from != VOR__NONE) {
                VOR__PREFETCH(&tri[ahead_from]);
                VOR__PREFETCH(&d->sites[ahead_from]);
            }
        }
        if (i >= distinct) { /* a duplicate: its home slot stays empty */
            vor__tri_fresh(&tri[s]);
            tri[s].n[0] = VOR__NONE;
            continue;
        }
        if (d->vertex_count == 1u) {
            vor__make_edge(d, d->last_site, s);
        } else if (d->vertex_count >= 2u) {
            vor_index_t start = (from == VOR__NONE) ? (vor_index_t)d->last_site : from;
            bool on_line;
            vor__insert_at(d, vor__locate(d, start, s, &on_line), s);
        } else {
            /* no other case */
        }
        d->vertex_count++;
        d->last_site = s;
    }
    vor__grid_rebuild(d);
    if (d->cdt_update != NULL) {
        (void)d->cdt_update(d, VOR_NO_HINT, VOR__CDT_REBUILT);
    }
    return VOR_OK;
}
