/* SPDX-License-Identifier: MIT */
/*
 * dynamic.c - removing and moving sites (docs/design.md, "Dynamic
 * diagrams").
 *
 * Removal: the triangles around p are replaced by a triangulation of the
 * polygon of p's neighbours (the vertex at infinity among them for a hull
 * site), cut off one ear at a time by flipping an edge of p's star
 * (Devillers, "On deletion in Delaunay triangulations", 2002): the ear
 * (a, b, c) of consecutive neighbours is a triangle of the result when it
 * turns left, p lies in its perturbed circle (it was one of the triangles
 * p's insertion deleted) and no other neighbour does. When three
 * neighbours are left, their triangles merge into one. Every predicate is
 * the perturbed one, so the result is the unique perturbed Delaunay
 * triangulation of the remaining sites: the one a fresh build gives.
 *
 * Topological guard: an ear is cut only when its new edge a-c is not an
 * edge already (else the mesh would hold it twice). Of two consecutive
 * ears at most one is blocked (two such edges would cross outside the
 * star), so a guarded ear always exists, and when the predicates lie and
 * no ear passes the geometric test the first guarded one is cut: every
 * pass removes one neighbour, so removal ends after degree - 3 cuts and
 * leaves a valid triangulation whatever the predicates answer.
 *
 * Memory: two triangles disappear. p's home slot empties; the other slot
 * freed must be a packed one, and the last packed triangle moves into it,
 * so the layout stays what vor_init set up (mesh.h).
 */
#include "bucket_grid.h"
#include "mesh.h"
#include "motion.h"
#include "perturbation.h"

static inline bool is_home(const vor_t *d, vor_index_t slot, vor_index_t v)
{
    return slot == v && v < d->max_sites;
}

/* In triangle `slot`, points the link that pointed at `from` at `to`. */
static void relink(vor__tri_t *tri, vor_index_t slot, vor_index_t from, vor_index_t to)
{
    vor__tri_t *t = &tri[slot];
    unsigned i = vor__neighbour_index(t, from);
    if (i != 3u) { /* always found in a valid mesh */
        t->n[i] = to;
    }
}

/* Moves the triangle in slot `from` to the unused slot `to` (meshes of
 * three or more sites: its neighbours are three distinct triangles). */
static void move_triangle(vor__tri_t *tri, vor_index_t from, vor_index_t to)
{
    vor__tri_t *f = &tri[from];
    vor_index_t v[3];
    vor__vertices(f, v);
    vor__tri_fresh(&tri[to]);
    vor__tri_set(&tri[to], v[0], v[1], v[2], f->n[0], f->n[1], f->n[2]);
    for (unsigned i = 0; i < 3u; i++) {
        relink(tri, tri[to].n[i], from, to);
    }
}

/* Index of vertex v in t, 0 when absent (only on a broken mesh): never
 * an index past the triangle. */
static unsigned corner(const vor__tri_t *t, vor_index_t v)
{
    unsigned i = vor__vertex_index(t, v);
    return (i == 3u) ? 0u : i;
}

/* The star of p: slot of the next triangle counterclockwise around p,
 * and the neighbours (p, x, y) of a star triangle. */
static vor_index_t star_next(const vor__tri_t *tri, vor_index_t slot, vor_index_t p)
{
    const vor__tri_t *t = &tri[slot];
    unsigned i = vor__vertex_index(t, p);
    return (i == 3u) ? slot : t->n[vor__next(i)]; /* absent only on a broken mesh */
}

static void star_edge(const vor__tri_t *tri, vor_index_t slot, vor_index_t p, vor_index_t *x,
                      vor_index_t *y)
{
    const vor__tri_t *t = &tri[slot];
    unsigned i = corner(t, p);
    *x = vor__vertex(t, vor__next(i));
    *y = vor__vertex(t, vor__prev(i));
}

/* Is a-b an edge of the mesh? Turns around whichever is finite, at most
 * once around (vertex_count + 1 triangles bound the turn). */
static bool is_edge(const vor_t *d, vor_index_t a, vor_index_t b)
{
    if (a == VOR__INFINITE) {
        a = b;
        b = VOR__INFINITE;
    }
    const vor__tri_t *tri = d->triangles;
    vor_index_t slot = a;
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        if (vor__vertex_index(&tri[slot], b) != 3u) {
            return true;
        }
        slot = star_next(tri, slot, a);
        if (slot == a) {
            break;
        }
    }
    return false;
}

/* Is the ear (a, b, c) of p's star, whose following triangle is at slot
 * `after`, a triangle of the triangulation without p? */
static bool is_delaunay_ear(vor_t *d, vor_index_t p, vor_index_t a, vor_index_t b,
                            vor_index_t c, vor_index_t after)
{
    if (a != VOR__INFINITE && b != VOR__INFINITE && c != VOR__INFINITE &&
        vor__orient(d, a, b, c) <= 0) {
        return false;
    }
    if (!vor__conflicts(d, a, b, c, p)) {
        return false;
    }
    /* the other neighbours: second vertices of the star triangles after
     * the ear's up to the one ending at a (degree - 3 of them) */
    const vor__tri_t *tri = d->triangles;
    vor_index_t slot = after, x, y;
    for (uint32_t left = d->vertex_count; left > 0u; left--) {
        star_edge(tri, slot, p, &x, &y);
        if (y == a) {
            break;
        }
        /* infinity lies in no circle of finite sites */
        if (y != VOR__INFINITE && vor__conflicts(d, a, b, c, y)) {
            return false;
        }
        slot = star_next(tri, slot, p);
    }
    return true;
}

/* Cuts the ear (a, b, c) off p's star: star triangles t1 = (p, a, b) in
 * slot s1 and t2 = (p, b, c) in s2 become the ear (a, b, c) and the star
 * triangle (p, a, c). Returns the latter's slot. */
static vor_index_t cut_ear(vor_t *d, vor_index_t p, vor_index_t s1, vor_index_t s2)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t a, b, c, unused;
    star_edge(tri, s1, p, &a, &b);
    star_edge(tri, s2, p, &unused, &c);
    const vor__tri_t *t1 = &tri[s1], *t2 = &tri[s2];
    unsigned i1 = corner(t1, p), i2 = corner(t2, p);
    vor_index_t outer1 = t1->n[i1], before = t1->n[vor__prev(i1)];
    vor_index_t outer2 = t2->n[i2], after = t2->n[vor__next(i2)];
    /* keep home slots home: the ear holds a, b, c, the star triangle p, a,
     * c; only b's slot must take the ear and only p's the star triangle,
     * and those cannot both ask for the same slot */
    vor_index_t ear = s1, star = s2;
    if (is_home(d, s1, p) || is_home(d, s2, b)) {
        ear = s2;
        star = s1;
    }
    relink(tri, outer1, s1, ear);
    relink(tri, outer2, s2, ear);
    relink(tri, before, s1, star);
    relink(tri, after, s2, star);
    vor__tri_set(&tri[ear], a, b, c, outer2, star, outer1);
    vor__tri_set(&tri[star], p, a, c, ear, after, before);
    return star;
}

/* Home slot `hole` of site h lost its triangle: fills it with another
 * triangle of h, from a packed slot when h has one there (which is then
 * returned, free); otherwise from the home slot of another of its
 * vertices r, which then needs one in turn: an augmenting path of the
 * matching of sites to their home triangles, searched greedily (no site
 * of the last eight steps is robbed again). Bounded by the site count;
 * the first step finds a packed triangle in the common case. */
static vor_index_t rehome(vor_t *d, vor_index_t h, vor_index_t hole, vor_index_t start)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t visited[8];
    uint32_t chain = 0;
    for (uint32_t step = 0; step < d->vertex_count; step++) {
        vor_index_t packed = VOR__NONE, other = VOR__NONE, slot = start;
        /* one turn around h, skipping the hole (it holds nothing yet) */
        for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
            if (slot >= d->max_sites) {
                packed = slot;
                break;
            }
            bool seen = false;
            for (uint32_t k = 0; k < chain; k++) {
                seen = seen || visited[k] == slot;
            }
            other = (other == VOR__NONE && slot != h && !seen) ? slot : other;
            slot = star_next(tri, slot, h);
            if (slot == start) {
                break;
            }
        }
        vor_index_t from = (packed != VOR__NONE) ? packed : other;
        if (from == VOR__NONE) {
            from = start; /* every candidate visited: any other triangle of h */
        }
        move_triangle(tri, from, hole);
        if (from >= d->max_sites) {
            return from;
        }
        if (chain < 8u) {
            visited[chain++] = h;
        }
        start = hole;
        hole = from;
        h = from; /* a home slot's index is its site */
    }
    return VOR__NONE;
}

/* Puts id p on the free list: d->free_site holds the most recent free id
 * plus one (0: none, so that a zeroed vor_t has no free id), and each
 * free id's home slot the same for the next one. */
static void free_id(vor_t *d, uint32_t p)
{
    if (d->max_sites >= 2u) { /* one site: no slots, and no other free id */
        vor__tri_t *t = &d->triangles[p];
        vor__tri_fresh(t);
        t->n[0] = VOR__NONE;
        t->n[1] = (vor_index_t)d->free_site;
        t->n[2] = VOR__NONE;
    }
    d->free_site = p + 1u;
}

/* Removes p (in the mesh, at least four sites) and returns a former
 * neighbour of it. */
static uint32_t remove_from_mesh(vor_t *d, vor_index_t p)
{
    vor__tri_t *tri = d->triangles;
    uint32_t degree = 0;
    vor_index_t slot = p;
    do {
        degree++;
        slot = star_next(tri, slot, p);
    } while (slot != p && degree <= d->vertex_count);

    vor_index_t s1 = p; /* the home slot stays in the star (cut_ear) */
    while (degree > 3u) {
        vor_index_t chosen = VOR__NONE, guarded = VOR__NONE;
        slot = s1;
        for (uint32_t k = 0; k < degree && chosen == VOR__NONE; k++) {
            vor_index_t s2 = star_next(tri, slot, p), a, b, c;
            star_edge(tri, slot, p, &a, &b);
            star_edge(tri, s2, p, &b, &c);
            if (!is_edge(d, a, c)) {
                guarded = (guarded == VOR__NONE) ? slot : guarded;
                if (is_delaunay_ear(d, p, a, b, c, star_next(tri, s2, p))) {
                    chosen = slot;
                }
            }
            slot = s2;
        }
        /* only lying predicates leave no ear: the first guarded one */
        chosen = (chosen != VOR__NONE) ? chosen : guarded;
        if (chosen == VOR__NONE) {
            break; /* a broken mesh only */
        }
        s1 = cut_ear(d, p, chosen, star_next(tri, chosen, p));
        degree--;
    }

    /* three triangles (p, a, b), (p, b, c), (p, c, a) merge into (a, b, c) */
    vor_index_t s2 = star_next(tri, s1, p), s3 = star_next(tri, s2, p), a, b, c;
    star_edge(tri, s1, p, &a, &b);
    star_edge(tri, s2, p, &b, &c);
    vor_index_t o1 = tri[s1].n[corner(&tri[s1], p)];
    vor_index_t o2 = tri[s2].n[corner(&tri[s2], p)];
    vor_index_t o3 = tri[s3].n[corner(&tri[s3], p)];
    /* the two slots besides p's home (p's home is one of the three) */
    vor_index_t x1 = (s1 == p) ? s2 : s1, x2 = (s3 == p) ? s2 : s3;
    vor_index_t keep = x2, freed = x1;
    if (x2 >= d->max_sites) {
        keep = x1;
        freed = x2;
    }
    relink(tri, o1, s1, keep);
    relink(tri, o2, s2, keep);
    relink(tri, o3, s3, keep);
    vor__tri_set(&tri[keep], a, b, c, o2, o3, o1);
    if (freed < d->max_sites) {
        /* both home slots of neighbours: the one not kept needs another
         * of its triangles, which frees a packed slot */
        freed = rehome(d, freed, freed, keep);
    }
    free_id(d, p);
    /* keep the extras packed: the last one fills the freed slot */
    vor_index_t last = (vor_index_t)(d->max_sites + d->vertex_count - 3u);
    if (freed != VOR__NONE && freed != last) {
        move_triangle(tri, last, freed);
    }
    return (a != VOR__INFINITE) ? a : b;
}

int vor_remove(vor_t *d, uint32_t site)
{
    if (d == NULL || !vor__site_in_mesh(d, site)) {
        return VOR_ERR_ARG;
    }
    vor__tri_t *tri = d->triangles;
    vor_index_t p = (vor_index_t)site;
    uint32_t other = site;
    if (d->vertex_count >= 4u) {
        other = remove_from_mesh(d, p);
    } else if (d->vertex_count == 3u) {
        /* two sites left: the two triangles at infinity of an edge */
        vor_index_t v[3];
        vor__vertices(&tri[p], v);
        unsigned i = corner(&tri[p], p);
        vor_index_t a = v[vor__next(i)], b = v[vor__prev(i)];
        if (a == VOR__INFINITE || b == VOR__INFINITE) {
            /* p's home holds a triangle at infinity; its finite triangle
             * is across the hull edge and holds both others */
            const vor__tri_t *f = &tri[tri[p].n[corner(&tri[p], VOR__INFINITE)]];
            i = corner(f, p);
            a = vor__vertex(f, vor__next(i));
            b = vor__vertex(f, vor__prev(i));
        }
        free_id(d, p);
        vor__make_edge(d, a, b);
        other = a;
    } else if (d->vertex_count == 2u) {
        const vor__tri_t *t = &tri[p];
        for (unsigned i = 0; i < 3u; i++) { /* the other finite vertex */
            vor_index_t v = vor__vertex(t, i);
            other = (v != p && v != VOR__INFINITE) ? v : other;
        }
        vor__tri_fresh(&tri[other]);
        tri[other].n[0] = VOR__NONE; /* one site has no triangles */
        free_id(d, p);
    } else {
        free_id(d, p);
    }
    d->vertex_count--;
    if (d->vertex_count < 2u) {
        d->bucket_rebuild_at = 2; /* the grid is redrawn with the second site */
    } else {
        vor__grid_forget(d, site, other);
    }
    d->last_site = (d->last_site == site) ? other : d->last_site;
    d->revision++;
    vor__topology_changed(d);
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Moving                                                              */

/* With p's coordinates already changed: is every triangle around p still
 * counterclockwise, and every edge of those triangles locally Delaunay?
 * Only they involve p, so then the mesh is the triangulation of the moved
 * sites. A triangle's neighbour across a spoke p-y is the next star
 * triangle; across the far edge, a triangle off the star. Also sets
 * *twin to a neighbour of p at p's new place (VOR__NONE: none): when the
 * answer is yes, a site there would be one, since a site and its twin are
 * each other's nearest (perturbed) sites, hence Delaunay neighbours. */
static bool star_still_delaunay(vor_t *d, vor_index_t p, vor_index_t *twin)
{
    vor__tri_t *tri = d->triangles;
    const vor_point_t *at = &d->sites[p];
    vor_index_t slot = p, v[3];
    vor__vertices(&tri[slot], v);
    *twin = VOR__NONE;
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        const vor__tri_t *t = &tri[slot];
        unsigned i = (v[1] == p) ? 1u : (v[2] == p) ? 2u : 0u;
        vor_index_t x = v[vor__next(i)], y = v[vor__prev(i)];
        if (x != VOR__INFINITE && d->sites[x].x == at->x && d->sites[x].y == at->y) {
            *twin = x;
        }
        if (x != VOR__INFINITE && y != VOR__INFINITE && vor__orient(d, p, x, y) <= 0) {
            return false;
        }
        const vor__tri_t *o = &tri[t->n[i]];
        vor_index_t far = vor__vertex(o, vor__next(corner(o, x)));
        if (far != VOR__INFINITE && vor__conflicts(d, v[0], v[1], v[2], far)) {
            return false;
        }
        /* the next triangle around p, (p, y, z): z across the spoke p-y */
        vor_index_t next = t->n[vor__next(i)], w[3];
        vor__vertices(&tri[next], w);
        unsigned j = (w[1] == p) ? 1u : (w[2] == p) ? 2u : 0u;
        vor_index_t z = w[vor__prev(j)];
        if (z != VOR__INFINITE && vor__conflicts(d, v[0], v[1], v[2], z)) {
            return false;
        }
        slot = next;
        if (slot == p) {
            break;
        }
        v[0] = w[0];
        v[1] = w[1];
        v[2] = w[2];
    }
    return true;
}

/* A site sharing a triangle with p (p in a mesh of two or more). */
static uint32_t any_neighbour(const vor_t *d, vor_index_t p)
{
    vor_index_t v[3], found = p;
    vor__vertices(&d->triangles[p], v);
    for (unsigned i = 0; i < 3u; i++) {
        found = (v[i] != p && v[i] != VOR__INFINITE) ? v[i] : found;
    }
    return found;
}

/* Site `site`, whose triangles stay the same, goes to (x, y): the box
 * grows to hold it, and a site that changed bucket moves its run of the
 * bucket grid. Should the site name every bucket, another site in the
 * mesh takes its runs: the last inserted one (always in the mesh), or a
 * neighbour when that is this site (a turn of the home triangle, kept
 * off the common path). */
static void move_in_place(vor_t *d, uint32_t site, int32_t x, int32_t y)
{
    vor_point_t *s = &d->sites[site], old = *s;
    s->x = x;
    s->y = y;
    vor__box_add(d, s, false);
    if (d->vertex_count >= 2u) {
        uint32_t fallback = d->last_site;
        if (fallback == site) {
            fallback = any_neighbour(d, (vor_index_t)site);
        }
        vor__grid_move(d, site, old, fallback);
    }
    d->revision++;
}

/* vor_move past the motion cache: proves the triangles unchanged, or
 * removes and inserts. Out of line, so that the fast path saves no more
 * registers and stack than it uses. */
static VOR__NOINLINE int move_checked(vor_t *d, uint32_t site, int32_t x, int32_t y,
                                      uint32_t *existing)
{
    vor_point_t *s = &d->sites[site];
    vor_point_t old = *s;
    uint32_t epoch = d->motion_epoch; /* for the cache's backoff */
    uint32_t twin = VOR__NONE;
    if (d->vertex_count == 2u) { /* the other site is the only neighbour */
        uint32_t other = any_neighbour(d, (vor_index_t)site);
        twin = (d->sites[other].x == x && d->sites[other].y == y) ? other : VOR__NONE;
    }
    /* the common small step first: the same triangles at the new place.
     * The tests count in the stats, restored if the move fails. */
    vor_predicate_stats_t saved_stats;
    vor__copy_stats(&saved_stats, &d->stats);
    s->x = x;
    s->y = y;
    vor_index_t star_twin = VOR__NONE;
    bool same_triangles = d->vertex_count <= 2u || star_still_delaunay(d, (vor_index_t)site,
                                                                       &star_twin);
    twin = (star_twin != VOR__NONE) ? star_twin : twin;
    *s = old;
    if (!same_triangles && d->vertex_count >= 3u) {
        /* a site at (x, y) is the nearest site to it (a read-only query
         * from the bucket grid) */
        uint32_t nearest;
        if (vor_nearest(d, x, y, VOR_NO_HINT, &nearest) == VOR_OK && d->sites[nearest].x == x &&
            d->sites[nearest].y == y) {
            twin = nearest;
        }
    }
    if (twin != VOR__NONE) {
        vor__copy_stats(&d->stats, &saved_stats);
        if (existing != NULL) {
            *existing = twin;
        }
        return VOR_ERR_DUPLICATE;
    }
    if (same_triangles) {
        move_in_place(d, site, x, y);
        vor__motion_update(d, site, old, epoch);
        return VOR_OK;
    }
    /* remove, then insert again under the same id (the free list's head),
     * from the bucket grid's site near the new place */
    vor_remove(d, site);
    uint32_t id;
    int err = vor_insert_near(d, x, y, VOR_NO_HINT, &id);
    if (err != VOR_OK) {
        /* only lying predicates (fault injection) find a twin the exact
         * query did not: the site goes back where it was */
        vor_insert_near(d, old.x, old.y, VOR_NO_HINT, &id);
    } else {
        vor__motion_update(d, site, old, epoch); /* a box in the new epoch */
    }
    return err;
}

int vor_move(vor_t *d, uint32_t site, int32_t x, int32_t y, uint32_t *existing)
{
    if (d == NULL || !vor__site_in_mesh(d, site)) {
        return VOR_ERR_ARG;
    }
    const vor_point_t *s = &d->sites[site];
    if (s->x == x && s->y == y) {
        return VOR_OK;
    }
    if (vor__motion_fast(d, site, x, y)) {
        /* inside the site's box: no triangle changes and no site is
         * there (invariant J, motion.c) */
        move_in_place(d, site, x, y);
        return VOR_OK;
    }
    return move_checked(d, site, x, y, existing);
}
