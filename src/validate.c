/* SPDX-License-Identifier: MIT */
/*
 * validate.c - vor_validate: every invariant of the mesh (counts, vertices,
 * neighbours, fans, the bucket grid, orientation, the Delaunay property)
 * and of what the iterators report, checked with the exact predicates,
 * uncounted, so validation never changes the diagram (nor lies in fault
 * injection builds). Read-only.
 */
#include "mesh.h"
#include "multiword.h"
#include "perturbation.h"

/* vor__conflicts with the true predicates, uncounted. */
static bool exact_conflict(const vor_t *d, const vor__tri_t *t, uint32_t p)
{
    vor_index_t v0 = vor__vertex(t, 0), v1 = vor__vertex(t, 1), v2 = vor__vertex(t, 2);
    if (v0 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v1, v2, p, NULL) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v2, v0, p, NULL) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v0, v1, p, NULL) > 0;
    }
    return vor_incircle_sos(d->sites, v0, v1, v2, p, NULL) > 0;
}

static int violation(vor_violation_t *out, enum vor_check check, uint32_t triangle,
                     uint32_t site)
{
    if (out != NULL) {
        out->check = check;
        out->triangle = triangle;
        out->site = site;
    }
    return VOR_ERR_INVALID;
}

static bool slot_in_use(const vor_t *d, uint32_t slot)
{
    if (slot < d->max_sites) {
        return slot < d->site_count && !vor__slot_empty(&d->triangles[slot]);
    }
    return slot < vor__used_slots_end(d);
}

/* The site's triangles around it from its home slot, counted; 0 when the
 * fan does not close within `limit` steps or leaves the site. */
static uint32_t fan_size(const vor_t *d, uint32_t start, vor_index_t site, uint32_t limit)
{
    uint32_t slot = start, count = 0;
    do {
        const vor__tri_t *t = &d->triangles[slot];
        unsigned i = vor__vertex_index(t, site);
        if (i == 3u || count == limit) {
            return 0;
        }
        count++;
        slot = t->n[vor__next(i)]; /* across the edge (site, next-next): turn clockwise */
    } while (slot != start);
    return count;
}

/* The site after b on the boundary of the reported triangles, turning
 * clockwise around b from the reported triangle at `slot` that has the
 * boundary edge a -> b; VOR__INFINITE if the turn does not end within
 * vertex_count + 1 steps (only on a broken mesh). */
static uint32_t boundary_after(const vor_t *d, uint32_t slot, vor_index_t b)
{
    for (uint32_t step = 0; step <= d->vertex_count; step++) {
        const vor__tri_t *t = &d->triangles[slot];
        unsigned j = vor__vertex_index(t, b);
        if (j == 3u) {
            break;
        }
        slot = t->n[vor__prev(j)]; /* across the edge b -> the vertex after b */
        if (!vor__reported(d->sites, &d->triangles[slot])) {
            return vor__vertex(t, vor__next(j));
        }
    }
    return VOR__INFINITE;
}

/* What the iterators report, against the counts of a triangulation of the
 * v distinct sites whose boundary is the convex hull through all h sites
 * on it (Euler: 2 v - h - 2 triangles, 3 t + h edge ends), or of a path
 * when all sites are collinear (no triangle, v - 1 edges). */
static int check_true_output(const vor_t *d, vor_violation_t *out)
{
    const vor_point_t *s = d->sites;
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d), reported = 0, boundary = 0;
    for (uint32_t slot = vor__next_used_slot(d, 0); slot < end;
         slot = vor__next_used_slot(d, slot + 1u)) {
        const vor__tri_t *t = &tri[slot];
        if (!vor__reported(s, t)) {
            continue;
        }
        vor_index_t v[3];
        vor__vertices(t, v);
        if (vor_orient2d(&s[v[0]], &s[v[1]], &s[v[2]], NULL) <= 0) {
            return violation(out, VOR_CHECK_TRUE_OUTPUT, slot, v[0]);
        }
        reported++;
        for (unsigned i = 0; i < 3u; i++) {
            if (vor__reported(s, &tri[t->n[i]])) {
                continue;
            }
            /* a boundary edge a -> b: the boundary turns left (or goes
             * straight on, past a hull site) at b */
            vor_index_t a = v[vor__next(i)], b = v[vor__prev(i)];
            uint32_t c = boundary_after(d, slot, b);
            if (c == VOR__INFINITE || c == a || vor_orient2d(&s[a], &s[b], &s[c], NULL) < 0) {
                return violation(out, VOR_CHECK_TRUE_OUTPUT, slot, b);
            }
            boundary++;
        }
    }
    uint32_t v = d->vertex_count;
    if (reported != 0u && reported + boundary + 2u != 2u * v) {
        return violation(out, VOR_CHECK_TRUE_OUTPUT, 0, v);
    }
    uint32_t ends = 0;
    for (uint32_t site = 0; site < d->site_count; site++) {
        if (vor__slot_empty(&tri[site])) {
            continue;
        }
        vor_neighbour_iter_t it;
        uint32_t n, degree = 0;
        vor__fan_begin(&it, d, site);
        while (vor__true_neighbour_next(&it, &n)) {
            degree++;
        }
        if (degree == 0u || (reported == 0u && degree > 2u)) {
            return violation(out, VOR_CHECK_TRUE_OUTPUT, site, site);
        }
        ends += degree;
    }
    if (ends != ((reported != 0u) ? 3u * reported + boundary : 2u * (v - 1u))) {
        return violation(out, VOR_CHECK_TRUE_OUTPUT, 0, v);
    }
    return VOR_OK;
}

/* Counts: the used slots are exactly 2v - 2 (none below two sites). */
static int check_counts(const vor_t *d, vor_violation_t *out)
{
    if (d->vertex_count > d->site_count || d->site_count > d->max_sites) {
        return violation(out, VOR_CHECK_COUNTS, 0, d->vertex_count);
    }
    if (d->vertex_count < 2u) {
        return VOR_OK;
    }
    uint32_t present = 0;
    for (uint32_t s = 0; s < d->site_count; s++) {
        present += vor__slot_empty(&d->triangles[s]) ? 0u : 1u;
    }
    uint32_t used = present + (vor__used_slots_end(d) - d->max_sites);
    if (used != vor__triangle_count(d->vertex_count) || present != d->vertex_count) {
        return violation(out, VOR_CHECK_COUNTS, 0, d->vertex_count);
    }
    return VOR_OK;
}

/* Vertices: sites in the mesh or infinity, three distinct. */
static int check_vertices(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t v = vor__vertex(t, i);
            if (v != VOR__INFINITE &&
                (v >= d->site_count || vor__slot_empty(&tri[v]))) {
                return violation(out, VOR_CHECK_VERTICES, s, v);
            }
        }
        if (vor__vertex(t, 0) == vor__vertex(t, 1) || vor__vertex(t, 1) == vor__vertex(t, 2) ||
            vor__vertex(t, 2) == vor__vertex(t, 0)) {
            return violation(out, VOR_CHECK_VERTICES, s, vor__vertex(t, 1));
        }
    }
    return VOR_OK;
}

/* Neighbours: in use, pointing back across the same edge. */
static int check_neighbours(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t u = t->n[i];
            vor_index_t a = vor__vertex(t, vor__next(i)), b = vor__vertex(t, vor__prev(i));
            if (u == VOR__NONE || !slot_in_use(d, u)) {
                return violation(out, VOR_CHECK_NEIGHBOURS, s, a);
            }
            const vor__tri_t *o = &tri[u];
            unsigned ia = vor__vertex_index(o, a), ib = vor__vertex_index(o, b);
            /* in o the edge runs b -> a, and o's neighbour across it is t */
            if (ia == 3u || ib == 3u || vor__next(ib) != ia ||
                o->n[vor__next(ia)] != s) {
                return violation(out, VOR_CHECK_NEIGHBOURS, s, a);
            }
        }
    }
    return VOR_OK;
}

/* Sites: each site's home slot holds one of its triangles, and its
 * triangles form one fan; all fans together cover each triangle once per
 * corner. */
static int check_fans(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t triangles = vor__triangle_count(d->vertex_count);
    uint32_t end = vor__used_slots_end(d);
    uint32_t corners = 0;
    for (uint32_t s = 0; s < d->site_count; s++) {
        if (vor__slot_empty(&tri[s])) {
            continue;
        }
        uint32_t fan = fan_size(d, s, (vor_index_t)s, triangles);
        if (fan < 2u) {
            return violation(out, VOR_CHECK_SITES, s, s);
        }
        corners += fan;
    }
    uint32_t ghost = vor__next_used_slot(d, 0);
    while (ghost < end && !vor__is_ghost(&tri[ghost])) {
        ghost = vor__next_used_slot(d, ghost + 1u);
    }
    corners += (ghost < end) ? fan_size(d, ghost, VOR__INFINITE, triangles) : 0u;
    if (corners != 3u * triangles) {
        return violation(out, VOR_CHECK_SITES, 0, VOR__INFINITE);
    }
    return VOR_OK;
}

/* The query index: a box around every site, buckets naming sites. */
static int check_buckets(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    for (uint32_t s = 0; s < d->site_count; s++) {
        const vor_point_t *p = &d->sites[s];
        if (!vor__slot_empty(&tri[s]) && (p->x < d->low.x || p->x > d->high.x ||
                                          p->y < d->low.y || p->y > d->high.y)) {
            return violation(out, VOR_CHECK_BUCKETS, s, s);
        }
    }
    uint64_t buckets = vor__mul_u32(d->bucket_columns, d->bucket_rows);
    if (buckets == 0u || buckets > VOR_BUCKETS(d->max_sites)) {
        return violation(out, VOR_CHECK_BUCKETS, 0, VOR__INFINITE);
    }
    for (uint32_t b = 0; b < (uint32_t)buckets; b++) {
        vor_index_t s = d->buckets[b];
        if (s >= d->site_count || vor__slot_empty(&tri[s])) {
            return violation(out, VOR_CHECK_BUCKETS, b, s);
        }
    }
    return VOR_OK;
}

/* Geometry: every finite triangle counterclockwise, and no neighbour's
 * far vertex in a triangle's circle, by the exact perturbed predicates,
 * uncounted, so validation never changes the diagram (nor lies in fault
 * injection builds). */
static int check_delaunay(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        if (!vor__is_ghost(t) &&
            vor_orient2d_sos(d->sites, vor__vertex(t, 0), vor__vertex(t, 1), vor__vertex(t, 2),
                             NULL) < 0) {
            return violation(out, VOR_CHECK_ORIENTATION, s, vor__vertex(t, 0));
        }
    }
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            const vor__tri_t *o = &tri[t->n[i]];
            vor_index_t a = vor__vertex(t, vor__next(i));
            vor_index_t apex = vor__vertex(o, vor__next(vor__vertex_index(o, a)));
            if (apex == VOR__INFINITE || vor__vertex_index(t, apex) != 3u) {
                continue; /* infinity is never inside a circle; two sites:
                             both triangles have the same three vertices */
            }
            /* the neighbour's far vertex must not conflict with t */
            if (exact_conflict(d, t, apex)) {
                return violation(out, VOR_CHECK_DELAUNAY, s, apex);
            }
        }
    }
    return VOR_OK;
}

/* The checks in order, each relying on the ones before it (the fans on
 * the neighbours, the geometry on the fans, ...); the first failure is
 * reported. */
int vor_validate(const vor_t *d, vor_violation_t *out)
{
    if (d == NULL) {
        return VOR_ERR_ARG;
    }
    int err = check_counts(d, out);
    if (err != VOR_OK || d->vertex_count < 2u) {
        return err;
    }
    err = check_vertices(d, out);
    err = (err == VOR_OK) ? check_neighbours(d, out) : err;
    err = (err == VOR_OK) ? check_fans(d, out) : err;
    err = (err == VOR_OK) ? check_buckets(d, out) : err;
    err = (err == VOR_OK) ? check_delaunay(d, out) : err;
    return (err == VOR_OK) ? check_true_output(d, out) : err;
}
