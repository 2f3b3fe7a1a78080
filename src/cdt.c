/* SPDX-License-Identifier: MIT */
/*
 * cdt.c - constraints: the constrained Delaunay triangulation kept beside
 * the diagram (vor_cdt.h; docs/design/constraints.md).
 *
 * Inserting a constraint a-b, one piece at a time (a piece ends at the
 * first site exactly on the segment):
 *
 *   1. walk from a along the segment: the triangles it crosses form the
 *      cavity, bounded by an upper chain (a, u1 .. up, e) on the left of
 *      a -> e and a lower one (a, l1 .. lq, e) on the right, and the
 *      triangles outside each chain edge are noted;
 *   2. each chain with the segment is a pseudo-polygon, triangulated by
 *      Anglada's rule: over the base x-y, the chain vertex c whose circle
 *      through x and y holds no other chain vertex between them, then
 *      x..c and c..y the same way (an explicit stack, no recursion);
 *   3. the new triangles take the cavity's slots, so that every home slot
 *      among them still holds a triangle of its site (mesh.h).
 *
 * Step 3 always succeeds. The cavity's m + 1 slots include the home slots
 * of a set H of its vertices, |H| <= m + 1 = p + q, the number of new
 * triangles. In one triangulated polygon any set of k vertices, k at most
 * its triangle count, touches at least k triangles (the triangles missing
 * them have all corners among the other n - k vertices, at most n - k - 2
 * of them), so by Hall's theorem the demand can be met; a and e, in both
 * polygons, go to the one with room. Down the recursion, the triangle
 * (x, y, c) serves x, y or c, and the other demanded corners go to the
 * sub-polygon that has room (assign, below): with s1 and s2 the rooms of
 * x..c and c..y, the demanded corners number at most s1 + s2 + 1.
 */
#include "cdt.h"
#include "crossing.h"
#include "dynamic.h"
#include "mesh.h"
#include "multiword.h"
#include "perturbation.h"
#include "predicates.h"

typedef char vor__cdt_header_check[(sizeof(struct vor__cdt) <= VOR_CDT_HEADER_BYTES) ? 1 : -1];

/* ------------------------------------------------------------------ */
/* The edge table                                                      */

/* Entry of edge a-b, or the empty entry where it would go. */
static uint32_t edge_place(const struct vor__cdt *c, vor_index_t u, vor_index_t v)
{
    uint32_t i = vor__cdt_home(c, u, v);
    for (uint32_t probes = 0; probes < c->edge_slots; probes++) {
        const vor__cdt_edge_t *e = &c->edges[i];
        if ((e->u == VOR__NONE) || ((e->u == u) && (e->v == v))) {
            break;
        }
        i = ((i + 1u) == c->edge_slots) ? 0u : (i + 1u);
    }
    return i;
}

/* Adds `count` constraints through edge a-b (the caller checked room). */
static void edge_add(struct vor__cdt *c, vor_index_t a, vor_index_t b, uint32_t count)
{
    vor_index_t u = (a < b) ? a : b;
    vor_index_t v = (a < b) ? b : a;
    vor__cdt_edge_t *e = &c->edges[edge_place(c, u, v)];
    if (e->u == VOR__NONE) {
        e->u = u;
        e->v = v;
        e->count = 0;
        c->edge_count++;
    }
    e->count += count;
}

/* Empties entry i, moving later entries of its probe run back so that
 * every entry stays reachable from its home (no tombstones). */
static void edge_remove(struct vor__cdt *c, uint32_t removed)
{
    uint32_t hole = removed;
    uint32_t i = removed;
    for (uint32_t probes = 0; probes < c->edge_slots; probes++) {
        i = ((i + 1u) == c->edge_slots) ? 0u : (i + 1u);
        vor__cdt_edge_t *e = &c->edges[i];
        if (e->u == VOR__NONE) {
            break;
        }
        uint32_t home = vor__cdt_home(c, e->u, e->v);
        /* e may fill the hole unless its home lies cyclically in (hole, i] */
        bool stays = (hole <= i) ? ((hole < home) && (home <= i)) : ((hole < home) || (home <= i));
        if (!stays) { /* field by field: a structure copy may be a memcpy call */
            c->edges[hole].u = e->u;
            c->edges[hole].v = e->v;
            c->edges[hole].count = e->count;
            hole = i;
        }
    }
    c->edges[hole].u = VOR__NONE;
    c->edge_count--;
}

/* ------------------------------------------------------------------ */
/* Mesh helpers                                                        */

/* ------------------------------------------------------------------ */
/* Vertices: sites and crossings                                       */

static bool is_crossing(const struct vor__cdt *c, vor_index_t v)
{
    return (v >= c->first_crossing) && (v != VOR__INFINITE);
}

/* Vertex v (finite) in homogeneous coordinates (crossing.h). */
static void hpoint_of(const struct vor__cdt *c, vor_index_t v, vor__hpoint_t *h)
{
    const vor_point_t *s = c->mesh.sites;
    if (!is_crossing(c, v)) {
        vor__hpoint_site(h, s[v]);
        return;
    }
    const vor_index_t *q = &c->crossings[4u * (v - c->first_crossing)];
    (void)vor__hpoint_crossing(h, s[q[0]], s[q[1]], s[q[2]], s[q[3]]);
}

/* The exact orientation of finite vertices a, b, p (0 on a line). */
static int exact_orient(const struct vor__cdt *c, vor_index_t a, vor_index_t b, vor_index_t p)
{
    if (!is_crossing(c, a) && !is_crossing(c, b) && !is_crossing(c, p)) {
        const vor_point_t *s = c->mesh.sites;
        return vor__orient2d_exact(&s[a], &s[b], &s[p], NULL);
    }
    vor__hpoint_t h[3];
    hpoint_of(c, a, &h[0]);
    hpoint_of(c, b, &h[1]);
    hpoint_of(c, p, &h[2]);
    return vor__orient_h(&h[0], &h[1], &h[2]);
}

/* The perturbed orientation (never 0) and incircle test of vertices of
 * the mesh: the diagram's own predicates for sites, the crossing ones'
 * else (with the same injected faults in test builds). */
static int orient(struct vor__cdt *c, vor_index_t a, vor_index_t b, vor_index_t p)
{
    if (!is_crossing(c, a) && !is_crossing(c, b) && !is_crossing(c, p)) {
        return vor__orient(&c->mesh, a, b, p);
    }
    vor__hpoint_t h[3];
    const vor__hpoint_t *v[3];
    uint32_t ids[3] = {a, b, p};
    for (unsigned k = 0; k < 3u; k++) {
        hpoint_of(c, (vor_index_t)ids[k], &h[k]);
        v[k] = &h[k];
    }
    return vor__with_faults(&c->mesh, vor__orient_h_sos(v, ids));
}

static int incircle(struct vor__cdt *c, vor_index_t a, vor_index_t b, vor_index_t q,
                    vor_index_t p)
{
    if (!is_crossing(c, a) && !is_crossing(c, b) && !is_crossing(c, q) && !is_crossing(c, p)) {
        return vor__incircle(&c->mesh, a, b, q, p);
    }
    vor__hpoint_t h[4];
    const vor__hpoint_t *v[4];
    uint32_t ids[4] = {a, b, q, p};
    for (unsigned k = 0; k < 4u; k++) {
        hpoint_of(c, (vor_index_t)ids[k], &h[k]);
        v[k] = &h[k];
    }
    return vor__with_faults(&c->mesh, vor__incircle_h_sos(v, ids));
}

bool vor__cdt_conflicts(struct vor__cdt *c, vor_index_t v0, vor_index_t v1, vor_index_t v2,
                        uint32_t p)
{
    vor_index_t q = (vor_index_t)p;
    if (v0 == VOR__INFINITE) {
        return orient(c, v1, v2, q) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return orient(c, v2, v0, q) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return orient(c, v0, v1, q) > 0;
    }
    return incircle(c, v0, v1, v2, q) > 0;
}

/* The removal's predicates on the mesh (vor_t cdt_predicate; dynamic.c):
 * the mesh is the first member of its struct vor__cdt. */
static int mesh_predicate(vor_t *mesh, const uint32_t *ids, unsigned count)
{
    struct vor__cdt *c = (struct vor__cdt *)(void *)mesh;
    return (count == 3u) ? orient(c, (vor_index_t)ids[0], (vor_index_t)ids[1], (vor_index_t)ids[2])
                         : incircle(c, (vor_index_t)ids[0], (vor_index_t)ids[1],
                                    (vor_index_t)ids[2], (vor_index_t)ids[3]);
}

/* For finite vertices on one line: does m lie strictly between p and q?
 * Then p -> m and m -> q step as p -> q does on each axis. */
static bool between(const struct vor__cdt *c, vor_index_t p, vor_index_t m, vor_index_t q)
{
    if (!is_crossing(c, p) && !is_crossing(c, m) && !is_crossing(c, q)) {
        const vor_point_t *s = c->mesh.sites;
        return vor__strictly_between(&s[p], &s[m], &s[q]);
    }
    vor__hpoint_t h[3];
    hpoint_of(c, p, &h[0]);
    hpoint_of(c, m, &h[1]);
    hpoint_of(c, q, &h[2]);
    bool inside = true;
    for (unsigned axis = 0; axis < 2u; axis++) {
        int way = vor__compare_h(&h[2], &h[0], axis);
        inside = inside && (vor__compare_h(&h[1], &h[0], axis) == way) &&
                 (vor__compare_h(&h[2], &h[1], axis) == way);
    }
    return inside;
}

/* Does vertex p lie exactly inside the segment of finite vertices u-v? */
static bool splits(const struct vor__cdt *c, vor_index_t u, vor_index_t v, vor_index_t p)
{
    return (exact_orient(c, u, v, p) == 0) && between(c, u, p, v);
}

/* Index of the corner of t that is neither u nor v (3 if none). */
static unsigned third_corner(const vor__tri_t *t, vor_index_t u, vor_index_t v)
{
    for (unsigned k = 0; k < 3u; k++) {
        vor_index_t w = vor__vertex(t, k);
        if ((w != u) && (w != v)) {
            return k;
        }
    }
    return 3u;
}

/* In triangle `slot`, the link across its edge u-v becomes `to`. */
static void link_across(vor__tri_t *tri, vor_index_t slot, vor_index_t u, vor_index_t v,
                        vor_index_t to)
{
    unsigned k = third_corner(&tri[slot], u, v);
    if (k != 3u) {
        tri[slot].n[k] = to;
    }
}

/* The triangle of the constrained mesh m that holds site p (not in m yet),
 * by the straight walk from site `from`: it works on any triangulation,
 * where the Delaunay walk may circle. Ties are broken by the perturbation,
 * so the segment from -> p never runs along an edge. */
static vor_index_t locate(struct vor__cdt *c, vor_index_t from, uint32_t p)
{
    const vor_t *m = &c->mesh;
    const vor__tri_t *tri = m->triangles;
    vor_index_t q = (vor_index_t)p;
    /* the star triangle (from, x, y) whose corner at `from` holds p */
    vor_index_t slot = from;
    vor_index_t ghost = VOR__NONE;
    vor_index_t r = VOR__INFINITE;
    vor_index_t l = VOR__INFINITE;
    for (uint32_t left = m->vertex_count + 1u; left > 0u; left--) {
        const vor__tri_t *t = &tri[slot];
        unsigned i = vor__vertex_index(t, from);
        if (i == 3u) {
            return slot; /* a broken mesh only */
        }
        vor_index_t x = vor__vertex(t, vor__next(i));
        vor_index_t y = vor__vertex(t, vor__prev(i));
        if ((x == VOR__INFINITE) || (y == VOR__INFINITE)) {
            if (vor__cdt_conflicts(c, vor__vertex(t, 0), vor__vertex(t, 1), vor__vertex(t, 2), p)) {
                ghost = slot;
            }
        } else if ((orient(c, from, x, q) > 0) && (orient(c, from, y, q) < 0)) {
            if (orient(c, x, y, q) > 0) {
                return slot;
            }
            r = x;
            l = y;
            slot = t->n[i];
            break;
        } else {
            /* p is not in this corner */
        }
        slot = t->n[vor__prev(i)];
        if (slot == from) {
            return ghost; /* p outside the hull, seen from a hull edge at `from` */
        }
    }
    /* cross edges r-l (r right of from -> p, l left) until p's triangle */
    for (uint32_t step = vor__triangle_count(m->vertex_count); step > 0u; step--) {
        const vor__tri_t *t = &tri[slot];
        unsigned k = third_corner(t, r, l);
        vor_index_t w = (k == 3u) ? VOR__INFINITE : vor__vertex(t, k);
        if (w == VOR__INFINITE) {
            return slot; /* p beyond the hull edge r-l */
        }
        if ((orient(c, r, w, q) > 0) && (orient(c, w, l, q) > 0)) {
            return slot;
        }
        bool w_left = orient(c, from, q, w) > 0;
        unsigned out = vor__vertex_index(t, w_left ? l : r);
        l = w_left ? w : l;
        r = w_left ? r : w;
        slot = t->n[(out == 3u) ? 0u : out];
    }
    return slot; /* only if the predicates lie */
}

/* The constrained mesh's slot of d's slot s: d's packed slots follow its
 * max_sites home slots, the mesh's its max_sites + max_crossings. */
static vor_index_t mesh_slot(const struct vor__cdt *c, vor_index_t s)
{
    return (s < c->first_crossing) ? s : (vor_index_t)(s + c->max_crossings);
}

/* Makes the constrained mesh d's Delaunay triangulation: its triangles,
 * the packed ones moved up past the crossings' home slots; no
 * constraint, no crossing. */
static void copy_delaunay(struct vor__cdt *c, const vor_t *d)
{
    vor_t *m = &c->mesh;
    m->vertex_count = d->vertex_count;
    m->last_site = d->last_site;
    m->low = d->low;
    m->high = d->high;
    for (uint32_t s = 0; s < m->max_sites; s++) { /* every id unused first */
        vor__tri_fresh(&m->triangles[s]);
        m->triangles[s].n[0] = VOR__NONE;
    }
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *from = &d->triangles[s];
        vor__tri_t *to = &m->triangles[mesh_slot(c, (vor_index_t)s)];
        vor_index_t v[3];
        vor__vertices(from, v);
        vor__tri_fresh(to);
        vor__tri_set(to, v[0], v[1], v[2], mesh_slot(c, from->n[0]), mesh_slot(c, from->n[1]),
                     mesh_slot(c, from->n[2]));
    }
    for (uint32_t i = 0; i < c->edge_slots; i++) {
        c->edges[i].u = VOR__NONE;
    }
    for (uint32_t i = 0; i < c->max_crossings; i++) {
        c->crossings[4u * i] = VOR__NONE;
    }
    c->edge_count = 0;
    c->crossing_count = 0;
    c->domain = false;
}

int vor_cdt_attach(vor_t *d, void *mem, size_t bytes, const vor_cdt_limits_t *limits)
{
    if ((d == NULL) || (mem == NULL) || (limits == NULL) || (limits->edges == 0u) ||
        (limits->crossings > (VOR_MAX_SITES - d->max_sites)) ||
        (limits->edges > (3u * (d->max_sites + limits->crossings))) ||
        (limits->cut > ((2u * (d->max_sites + limits->crossings)) + 2u))) {
        return VOR_ERR_ARG;
    }
    if (((uintptr_t)mem % VOR_CDT_ALIGN) != 0u) {
        return VOR_ERR_ALIGN;
    }
    if (bytes < VOR_CDT_BYTES(d->max_sites, limits->edges, limits->crossings, limits->cut)) {
        return VOR_ERR_NOMEM;
    }
    struct vor__cdt *c = (struct vor__cdt *)mem;
    uint8_t *at = (uint8_t *)mem + VOR_CDT_HEADER_BYTES;
    vor_t *m = &c->mesh;
    c->first_crossing = d->max_sites;
    c->max_crossings = limits->crossings;
    m->sites = d->sites;
    m->triangles = (vor__tri_t *)(void *)at;
    m->max_sites = d->max_sites + limits->crossings;
    m->site_count = m->max_sites;
    at += (size_t)vor__triangle_count(m->max_sites) * sizeof(vor__tri_t);
    m->buckets = NULL;
    m->bucket_columns = 0;
    m->bucket_rows = 0;
    m->bucket_scale = 0;
    m->bucket_rebuild_at = 0;
    m->bucket_origin = d->low;
    m->revision = 0;
    m->free_site = 0;
#if VOR_STATS
    vor__stats_clear(&m->stats);
#endif
#ifdef VOR_FAULT_INJECTION
    m->fault_rate = d->fault_rate;
    m->fault_state = d->fault_state | 1u;
#endif
    m->motion = NULL;
    m->motion_epoch = 0;
    m->motion_update = NULL;
    m->cdt = NULL;
    m->cdt_update = NULL;
    m->cdt_predicate = mesh_predicate;
    c->edges = (vor__cdt_edge_t *)(void *)at;
    c->edge_slots = 2u * limits->edges;
    c->max_edges = limits->edges;
    at += (size_t)c->edge_slots * sizeof(vor__cdt_edge_t);
    c->crossings = (vor_index_t *)(void *)at;
    at += (size_t)limits->crossings * VOR_CDT_CROSSING_BYTES;
    c->scratch = (vor_index_t *)(void *)at;
    c->max_cut = limits->cut;
    at += 13u * ((size_t)limits->cut + 4u) * sizeof(vor_index_t);
    c->levels = at;
    copy_delaunay(c, d);
    d->cdt = c;
    d->cdt_update = vor__cdt_update;
    return VOR_OK;
}

int vor_cdt_crossing(const vor_t *d, uint32_t id, uint32_t sites[4])
{
    if ((d == NULL) || (d->cdt == NULL) || (sites == NULL)) {
        return VOR_ERR_ARG;
    }
    const struct vor__cdt *c = d->cdt;
    if ((id < c->first_crossing) || ((id - c->first_crossing) >= c->max_crossings) ||
        (c->crossings[4u * (id - c->first_crossing)] == VOR__NONE)) {
        return VOR_ERR_ARG;
    }
    for (unsigned k = 0; k < 4u; k++) {
        sites[k] = c->crossings[(4u * (id - c->first_crossing)) + k];
    }
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Sites                                                               */

/* The edge of triangle t other than u-v (VOR__NONE, VOR__NONE for none)
 * that holds p strictly inside, exactly: its ends in *a, *b. */
static unsigned edge_through(const struct vor__cdt *c, const vor__tri_t *t, vor_index_t u,
                             vor_index_t v, vor_index_t p, vor_index_t *a, vor_index_t *b)
{
    for (unsigned k = 0; k < 3u; k++) {
        vor_index_t x = vor__vertex(t, vor__next(k));
        vor_index_t y = vor__vertex(t, vor__prev(k));
        bool same = ((x == u) && (y == v)) || ((x == v) && (y == u));
        if (!same && (x != VOR__INFINITE) && (y != VOR__INFINITE) &&
            splits(c, x, y, p)) {
            *a = x;
            *b = y;
            return k;
        }
    }
    return 3u;
}

/* The entry of the constrained edge that holds site p (not in the mesh
 * yet) exactly inside, its ends in *su, *sv; edge_slots if none. The
 * edges holding p inside all lie on one line, and the triangles on them
 * form a path: the triangle holding the perturbed p (`root`), flat
 * triangles on the line (two such edges each), and at each end a
 * triangle with one (or a triangle at infinity). It is walked both ways
 * from root. There is at most one constrained edge on it: no constrained
 * edge holds a site inside. */
static uint32_t find_split(const struct vor__cdt *c, vor_index_t root, uint32_t p,
                           vor_index_t *su, vor_index_t *sv)
{
    const vor_t *m = &c->mesh;
    const vor__tri_t *tri = m->triangles;
    *su = VOR__NONE;
    *sv = VOR__NONE;
    if (c->edge_count == 0u) {
        return c->edge_slots;
    }
    vor_index_t start = root;
    unsigned inf = vor__vertex_index(&tri[root], VOR__INFINITE);
    if (inf != 3u) {
        /* p outside the hull, or on its line: the perturbed p may see any
         * hull edge on that line; the one holding p starts the path */
        for (unsigned way = 0; (way < 2u) && (start == root); way++) {
            vor_index_t at = root;
            for (uint32_t left = m->vertex_count; left > 0u; left--) {
                const vor__tri_t *g = &tri[at];
                unsigned i = vor__vertex_index(g, VOR__INFINITE);
                vor_index_t a = (i == 3u) ? VOR__INFINITE : vor__vertex(g, vor__next(i));
                vor_index_t b = (i == 3u) ? VOR__INFINITE : vor__vertex(g, vor__prev(i));
                if ((a == VOR__INFINITE) || (b == VOR__INFINITE) || (exact_orient(c, a, b, (vor_index_t)p) != 0)) {
                    break;
                }
                if (splits(c, a, b, (vor_index_t)p)) {
                    start = at;
                    break;
                }
                at = g->n[(way == 0u) ? vor__next(i) : vor__prev(i)];
            }
        }
    }
    vor_index_t first_a = VOR__NONE;
    vor_index_t first_b = VOR__NONE;
    for (unsigned way = 0; way < 2u; way++) {
        vor_index_t a;
        vor_index_t b;
        unsigned k = edge_through(c, &tri[start], first_a, first_b, (vor_index_t)p, &a, &b);
        if (k == 3u) {
            break;
        }
        first_a = a;
        first_b = b;
        vor_index_t at = tri[start].n[k];
        for (uint32_t left = vor__triangle_count(m->vertex_count); left > 0u; left--) {
            uint32_t e = vor__cdt_find(c, a, b);
            if (e != c->edge_slots) {
                *su = a;
                *sv = b;
                return e;
            }
            vor_index_t x;
            vor_index_t y;
            unsigned j = edge_through(c, &tri[at], a, b, (vor_index_t)p, &x, &y);
            if (j == 3u) {
                break;
            }
            at = tri[at].n[j];
            a = x;
            b = y;
        }
    }
    return c->edge_slots;
}

/* Has site p a constrained edge? */
static bool ends_constraint(const struct vor__cdt *c, uint32_t p)
{
    vor_neighbour_iter_t it;
    uint32_t n;
    uint32_t third;
    vor__fan_begin(&it, &c->mesh, p);
    while ((c->edge_count > 0u) && vor__fan_next(&it, &n, &third)) {
        if (vor__cdt_constrained(c, (vor_index_t)p, (vor_index_t)n)) {
            return true;
        }
    }
    return false;
}

/* The crossing vertex of triangle `root` at exactly site p's point, or
 * VOR__NONE. (The perturbed p lies in a triangle of that vertex's: they
 * cover a neighbourhood of it.) */
static vor_index_t crossing_at(const struct vor__cdt *c, vor_index_t root, vor_index_t p)
{
    vor_index_t v[3];
    vor__vertices(&c->mesh.triangles[root], v);
    vor__hpoint_t h;
    hpoint_of(c, p, &h);
    for (unsigned k = 0; (k < 3u) && (c->crossing_count > 0u); k++) {
        if (is_crossing(c, v[k])) {
            vor__hpoint_t x;
            hpoint_of(c, v[k], &x);
            if ((vor__compare_h(&x, &h, 0) == 0) && (vor__compare_h(&x, &h, 1) == 0)) {
                return v[k];
            }
        }
    }
    return VOR__NONE;
}

/* Site p, inserted exactly at crossing vertex x, takes its place: every
 * triangle of x names p instead, x's home triangle moves to p's (empty)
 * home slot, and x's constrained edges become p's. No predicate: the
 * triangulation is the same. */
static void take_over(struct vor__cdt *c, vor_index_t x, vor_index_t p)
{
    vor_t *m = &c->mesh;
    vor__tri_t *tri = m->triangles;
    vor_index_t slot = x;
    for (uint32_t left = m->vertex_count + 1u; left > 0u; left--) {
        vor__tri_t *t = &tri[slot];
        unsigned i = vor__vertex_index(t, x);
        if (i == 3u) {
            break; /* a broken mesh only */
        }
        vor_index_t next = t->n[vor__prev(i)];
        vor_index_t v[3];
        vor__vertices(t, v);
        v[i] = p;
        vor__tri_set(t, v[0], v[1], v[2], t->n[0], t->n[1], t->n[2]);
        slot = next;
        if (slot == x) {
            break;
        }
    }
    vor_index_t v[3];
    vor__vertices(&tri[x], v);
    vor__tri_fresh(&tri[p]);
    vor__tri_set(&tri[p], v[0], v[1], v[2], tri[x].n[0], tri[x].n[1], tri[x].n[2]);
    for (unsigned k = 0; k < 3u; k++) {
        vor__tri_t *o = &tri[tri[p].n[k]];
        unsigned j = vor__neighbour_index(o, x);
        if (j != 3u) {
            o->n[j] = p;
        }
    }
    vor__tri_fresh(&tri[x]);
    tri[x].n[0] = VOR__NONE;
    vor_neighbour_iter_t it;
    uint32_t n;
    uint32_t third;
    vor__fan_begin(&it, m, p);
    while (vor__fan_next(&it, &n, &third)) {
        uint32_t e = vor__cdt_find(c, x, (vor_index_t)n);
        if (e != c->edge_slots) {
            uint32_t count = c->edges[e].count;
            edge_remove(c, e);
            edge_add(c, p, (vor_index_t)n, count);
        }
    }
    c->crossings[4u * (x - c->first_crossing)] = VOR__NONE;
    c->crossing_count--;
}

/* Places vertex p (a site, d->sites[p] its point, or a crossing) in the
 * constrained mesh, walking to it from vertex `near`; a constrained edge
 * holding p exactly is split, and a crossing vertex at p's point gives p
 * its place. */
static void insert_vertex(struct vor__cdt *c, uint32_t p, vor_index_t near)
{
    vor_t *m = &c->mesh;
    if (m->vertex_count == 1u) {
        vor__make_edge(m, m->last_site, p);
    } else if (m->vertex_count >= 2u) {
        vor_index_t root = locate(c, near, p);
        vor_index_t x = is_crossing(c, (vor_index_t)p) ? VOR__NONE : crossing_at(c, root, (vor_index_t)p);
        if (x != VOR__NONE) {
            take_over(c, x, (vor_index_t)p);
            m->last_site = p;
            return;
        }
        vor_index_t su;
        vor_index_t sv;
        uint32_t split = find_split(c, root, p, &su, &sv);
        uint32_t count = 0;
        if (split != c->edge_slots) {
            count = c->edges[split].count;
            edge_remove(c, split);
        }
        vor__insert_at_constrained(m, root, p, c);
        if (count != 0u) {
            edge_add(c, su, (vor_index_t)p, count);
            edge_add(c, (vor_index_t)p, sv, count);
        }
    } else {
        /* the first site: no triangle */
    }
    m->vertex_count++;
    m->last_site = is_crossing(c, (vor_index_t)p) ? m->last_site : p;
}

/* Does site p (its coordinates in d->sites[p]) lie exactly inside a
 * constrained edge that does not end at p? A scan of the table, which
 * reads no triangle: p may still be in the mesh at another place (a
 * move's check), and runs only when the table is full. */
static bool on_constrained_edge(const struct vor__cdt *c, uint32_t p)
{
    for (uint32_t i = 0; i < c->edge_slots; i++) {
        vor_index_t u = c->edges[i].u;
        vor_index_t v = c->edges[i].v;
        if ((u != VOR__NONE) && (u != p) && (v != p) && splits(c, u, v, (vor_index_t)p)) {
            return true;
        }
    }
    return false;
}

int vor__cdt_update(vor_t *d, uint32_t p, unsigned event)
{
    struct vor__cdt *c = d->cdt;
    vor_t *m = &c->mesh;
    int err = VOR_OK;
    if (event == VOR__CDT_CHECK_INSERT) {
        /* a split adds one edge */
        if ((c->edge_count >= c->max_edges) && on_constrained_edge(c, p)) {
            err = VOR_ERR_NOMEM;
        }
    } else if (event == VOR__CDT_INSERTED) {
        insert_vertex(c, p, (vor_index_t)m->last_site);
    } else if ((event == VOR__CDT_REMOVE) || (event == VOR__CDT_CHECK_REMOVE)) {
        if (ends_constraint(c, p)) {
            err = VOR_ERR_CONSTRAINED;
        } else if (event == VOR__CDT_REMOVE) {
            m->last_site = vor__unlink_site(m, p);
        } else {
            /* the check alone */
        }
    } else {
        copy_delaunay(c, d);
    }
    /* the marks stay unless the triangulation changed (a refused removal
     * changes nothing) */
    c->domain = c->domain && ((event == VOR__CDT_CHECK_INSERT) || (event == VOR__CDT_CHECK_REMOVE) ||
                              (err != VOR_OK));
    m->low = d->low;
    m->high = d->high;
    return err;
}

/* ------------------------------------------------------------------ */
/* Constraints                                                         */

/* The scratch arrays of one piece's cavity: the chains, the triangles
 * outside their edges, the cavity's slots, and the stack. */
typedef struct {
    vor_index_t *upper;       /* upper[0] = from .. upper[nu - 1] = end */
    vor_index_t *upper_out;   /* upper_out[i]: outside upper[i]-upper[i+1] */
    vor_index_t *lower;
    vor_index_t *lower_out;
    vor_index_t *slots;       /* the cavity's slots */
    vor_index_t *side;        /* a spike edge's new triangle, by chain position */
    vor_index_t *side_link;   /* and its link index there */
    vor_index_t *demands;     /* demanded positions before each position */
    vor_index_t *stack;       /* 4 entries a pending sub-polygon */
    uint32_t nu;
    uint32_t nl;
    uint32_t cut;
} cavity_t;

static void cavity_init(cavity_t *cv, const struct vor__cdt *c)
{
    size_t n = (size_t)c->max_cut + 2u;
    cv->upper = c->scratch;
    cv->upper_out = cv->upper + n;
    cv->lower = cv->upper_out + n;
    cv->lower_out = cv->lower + n;
    cv->slots = cv->lower_out + n;
    cv->side = cv->slots + n;
    cv->side_link = cv->side + n;
    cv->demands = cv->side_link + n;
    cv->stack = cv->demands + n;
    cv->nu = 0;
    cv->nl = 0;
    cv->cut = 0;
}

/* The first step of the piece from `from` toward b: either a neighbour
 * exactly on the segment (returned, *slot VOR__NONE), or the star
 * triangle whose corner the segment leaves through (*slot; returns
 * VOR__NONE). */
static vor_index_t first_step(const struct vor__cdt *c, vor_index_t from, vor_index_t b,
                              vor_index_t *slot_out)
{
    const vor_t *m = &c->mesh;
    const vor__tri_t *tri = m->triangles;
    vor_index_t slot = from;
    vor_index_t on_line = VOR__NONE;
    *slot_out = VOR__NONE;
    for (uint32_t left = m->vertex_count + 1u; left > 0u; left--) {
        const vor__tri_t *t = &tri[slot];
        unsigned i = vor__vertex_index(t, from);
        if (i == 3u) {
            break; /* a broken mesh only */
        }
        vor_index_t x = vor__vertex(t, vor__next(i));
        vor_index_t y = vor__vertex(t, vor__prev(i));
        if ((x != VOR__INFINITE) && (exact_orient(c, from, b, x) == 0) &&
            ((x == b) || between(c, from, x, b))) {
            /* the nearest such neighbour (flat hull triangles may give two) */
            if ((on_line == VOR__NONE) || between(c, from, x, on_line)) {
                on_line = x;
            }
        } else if ((x != VOR__INFINITE) && (y != VOR__INFINITE) &&
                   (exact_orient(c, from, x, b) > 0) && (exact_orient(c, from, y, b) < 0)) {
            *slot_out = slot;
        } else {
            /* not this corner */
        }
        slot = t->n[vor__prev(i)];
        if (slot == from) {
            break;
        }
    }
    if (on_line != VOR__NONE) {
        *slot_out = VOR__NONE;
    }
    return on_line;
}

/* Walks the cavity of the piece from `from` toward b, whose first
 * triangle is `slot`, and returns the piece's end: b or the first vertex
 * exactly on the segment. Recording (`record`), it fills cv, and stops at
 * a constrained edge it would cross: VOR__NONE, the edge in crossed[].
 * Checking, it walks on through constrained edges, counting them in
 * *crossings, and returns VOR__NONE when a stretch between two of them
 * (or the piece's ends) crosses more than max_cut - 2 triangles before
 * its end (the triangle holding the piece's end vertex is entered after
 * the last check: such a stretch may cross max_cut - 1): a crossing
 * vertex inserted at each end of a stretch adds at most one triangle
 * there (the segment meets its star in one triangle), so the recorded
 * cavities then stay within max_cut. */
static vor_index_t walk_cavity(const struct vor__cdt *c, cavity_t *cv, vor_index_t from,
                               vor_index_t b, vor_index_t slot, bool record,
                               uint32_t *crossings, vor_index_t crossed[2])
{
    const vor_t *m = &c->mesh;
    const vor__tri_t *tri = m->triangles;
    const vor__tri_t *t = &tri[slot];
    unsigned i = vor__vertex_index(t, from);
    vor_index_t r = vor__vertex(t, vor__next(i)); /* right of from -> b */
    vor_index_t l = vor__vertex(t, vor__prev(i)); /* left */
    uint32_t limit = record ? c->max_cut : ((c->max_cut >= 2u) ? (c->max_cut - 2u) : 0u);
    uint32_t stretch = 1;
    crossed[0] = VOR__NONE;
    crossed[1] = VOR__NONE;
    cv->cut = 1;
    if (record) {
        cv->upper[0] = from;
        cv->upper[1] = l;
        cv->upper_out[0] = t->n[vor__next(i)];
        cv->lower[0] = from;
        cv->lower[1] = r;
        cv->lower_out[0] = t->n[vor__prev(i)];
        cv->slots[0] = slot;
        cv->nu = 2;
        cv->nl = 2;
    }
    vor_index_t at = t->n[i];
    for (uint32_t steps = vor__triangle_count(m->vertex_count); steps > 0u; steps--) {
        if (stretch > limit) {
            return VOR__NONE;
        }
        if (vor__cdt_constrained(c, r, l)) {
            if (record) {
                crossed[0] = r;
                crossed[1] = l;
                return VOR__NONE;
            }
            *crossings += 1u;
            stretch = 0;
        }
        const vor__tri_t *f = &tri[at];
        unsigned k = third_corner(f, r, l);
        if (k == 3u) {
            return VOR__NONE; /* a broken mesh only */
        }
        vor_index_t w = vor__vertex(f, k);
        unsigned ir = vor__vertex_index(f, r);
        unsigned il = vor__vertex_index(f, l);
        if (record) {
            cv->slots[cv->cut] = at;
        }
        cv->cut++;
        stretch++;
        int side = (w == b) ? 0 : exact_orient(c, from, b, w);
        if (side == 0) { /* the piece ends at w */
            if (record) {
                cv->upper_out[cv->nu - 1u] = f->n[ir];
                cv->upper[cv->nu] = w;
                cv->nu++;
                cv->lower_out[cv->nl - 1u] = f->n[il];
                cv->lower[cv->nl] = w;
                cv->nl++;
            }
            return w;
        }
        if (side > 0) { /* w above: the upper chain grows, l-w crossed no more */
            if (record) {
                cv->upper_out[cv->nu - 1u] = f->n[ir];
                cv->upper[cv->nu] = w;
                cv->nu++;
            }
            at = f->n[il];
            l = w;
        } else {
            if (record) {
                cv->lower_out[cv->nl - 1u] = f->n[il];
                cv->lower[cv->nl] = w;
                cv->nl++;
            }
            at = f->n[ir];
            r = w;
        }
    }
    return VOR__NONE; /* a broken mesh only */
}

/* Does site v still need a triangle in its home slot (a cavity slot)? */
static bool needs_home(const vor_t *m, vor_index_t v)
{
    return (v < m->max_sites) && vor__marked(&m->triangles[v]);
}

/* The positions of chain[0 .. n) that demand a home, counted: demands[i]
 * is their number before position i. A vertex whose home slot is in the
 * cavity demands it at its first position only (a spike's base appears
 * twice), and the ends not at all: they are placed by fill_cavity. */
static void count_demands(const vor_t *m, const vor_index_t *chain, uint32_t n,
                          vor_index_t *demands)
{
    uint32_t count = 0;
    for (uint32_t i = 0; i < n; i++) {
        demands[i] = (vor_index_t)count;
        bool first = (i > 0u) && ((i + 1u) < n);
        for (uint32_t j = 0; j < i; j++) {
            first = first && (chain[j] != chain[i]);
        }
        count += (first && needs_home(m, chain[i])) ? 1u : 0u;
    }
}

/* Demanded positions strictly between lo and hi. */
static uint32_t demand(const vor_index_t *demands, uint32_t lo, uint32_t hi)
{
    return (uint32_t)demands[hi] - (uint32_t)demands[lo + 1u];
}

/* Triangulates the pseudo-polygon of chain[0 .. n) (left of chain[0] ->
 * chain[n - 1]) by Anglada's rule, the triangle on the base linked to
 * `parent` (its link n[2] set when parent is VOR__NONE later by the
 * caller); need_first and need_last say whether the base's ends take a
 * home from it. Returns the slot of the triangle on the base. `packed`
 * lists the cavity's free packed slots (*free_count of them). */
static vor_index_t triangulate(struct vor__cdt *c, const vor_index_t *chain,
                               const vor_index_t *outside, uint32_t n, cavity_t *cv,
                               bool need_first, bool need_last, vor_index_t parent,
                               uint32_t *free_count)
{
    vor__tri_t *tri = c->mesh.triangles;
    vor_index_t *stack = cv->stack;
    const vor_index_t *packed = cv->slots;
    vor_index_t root = VOR__NONE;
    uint32_t depth = 0;
    stack[0] = 0;
    stack[1] = (vor_index_t)(n - 1u);
    uint32_t flags = (need_first ? 1u : 0u) | (need_last ? 2u : 0u) | (2u << 2);
    stack[2] = (vor_index_t)flags;
    stack[3] = parent;
    depth = 1;
    while (depth > 0u) {
        depth--;
        vor_index_t *e = &stack[4u * depth];
        uint32_t lo = e[0];
        uint32_t hi = e[1];
        bool need_lo = (e[2] & 1u) != 0u;
        bool need_hi = (e[2] & 2u) != 0u;
        unsigned link = (unsigned)(e[2] >> 2) & 3u;
        vor_index_t up = e[3];
        if (hi == (lo + 1u)) { /* a chain edge: the triangle outside it */
            vor_index_t o = outside[lo];
            if (o == VOR__NONE) { /* a spike: linked to its other side later */
                cv->side[lo] = up;
                cv->side_link[lo] = (vor_index_t)link;
                continue;
            }
            if (up != VOR__NONE) {
                tri[up].n[link] = o;
            }
            link_across(tri, o, chain[lo], chain[hi], up);
            continue;
        }
        /* the apex: the chain vertex whose circle over the base is empty.
         * No vertex meets itself: a spike's tip, which comes right after
         * its base, lies inside the base's circle (docs/design/
         * constraints.md), so the base is never the apex when its second
         * place comes, nor an end of a range that holds its spike. */
        uint32_t apex = hi;
        for (uint32_t v = lo + 1u; v < hi; v++) {
            if ((apex == hi) || (incircle(c, chain[lo], chain[hi], chain[apex], chain[v]) > 0)) {
                apex = v;
            }
        }
        uint32_t room1 = (apex - lo - 1u) - demand(cv->demands, lo, apex);
        uint32_t room2 = (hi - apex - 1u) - demand(cv->demands, apex, hi);
        bool need_apex = cv->demands[apex + 1u] != cv->demands[apex];
        /* which demanded corner this triangle serves (file comment) */
        vor_index_t served = VOR__NONE;
        if (need_lo && (room1 == 0u)) {
            served = chain[lo];
            need_lo = false;
        } else if (need_hi && (room2 == 0u)) {
            served = chain[hi];
            need_hi = false;
        } else if (need_apex) {
            served = chain[apex];
            need_apex = false;
        } else if (need_lo) {
            served = chain[lo];
            need_lo = false;
        } else if (need_hi) {
            served = chain[hi];
            need_hi = false;
        } else {
            /* no demand here */
        }
        bool apex_first = need_apex && (room1 > (need_lo ? 1u : 0u));
        bool apex_second = need_apex && !apex_first;
        vor_index_t slot;
        if (served != VOR__NONE) {
            slot = served;
        } else {
            (*free_count)--;
            slot = packed[*free_count];
        }
        vor__tri_set(&tri[slot], chain[lo], chain[hi], chain[apex], VOR__NONE, VOR__NONE, up);
        if (served != VOR__NONE) {
            vor__set_mark(&tri[slot], false);
        }
        if (up != VOR__NONE) {
            tri[up].n[link] = slot;
        }
        root = (root == VOR__NONE) ? slot : root;
        /* x..apex across (apex, x): link 1; apex..y across (y, apex): link 0 */
        vor_index_t *p1 = &stack[4u * depth];
        p1[0] = (vor_index_t)lo;
        p1[1] = (vor_index_t)apex;
        uint32_t flags1 = (need_lo ? 1u : 0u) | (apex_first ? 2u : 0u) | (1u << 2);
        p1[2] = (vor_index_t)flags1;
        p1[3] = slot;
        vor_index_t *p2 = &stack[4u * (depth + 1u)];
        p2[0] = (vor_index_t)apex;
        p2[1] = (vor_index_t)hi;
        uint32_t flags2 = (apex_second ? 1u : 0u) | (need_hi ? 2u : 0u);
        p2[2] = (vor_index_t)flags2;
        p2[3] = slot;
        depth += 2u;
    }
    return root;
}

/* Links the two new triangles on each spike edge of a chain: position i
 * (chain[i] -> chain[i + 1]) and the position j running back along it. */
static void link_spikes(vor__tri_t *tri, const vor_index_t *chain, const vor_index_t *outside,
                        uint32_t n, const cavity_t *cv)
{
    for (uint32_t i = 0; (i + 1u) < n; i++) {
        if (outside[i] != VOR__NONE) {
            continue;
        }
        for (uint32_t j = 0; (j + 1u) < n; j++) {
            if ((j != i) && (chain[j] == chain[i + 1u]) && (chain[j + 1u] == chain[i])) {
                tri[cv->side[i]].n[cv->side_link[i]] = cv->side[j];
            }
        }
    }
}

/* Retriangulates the cavity cv of the piece from -> end (step 2, 3). */
static void fill_cavity(struct vor__cdt *c, cavity_t *cv)
{
    vor_t *m = &c->mesh;
    vor__tri_t *tri = m->triangles;
    /* a chain edge with the cavity on both sides is a spike (a vertex
     * whose every triangle the segment crosses hangs from it) */
    for (uint32_t i = 0; (i + 1u) < cv->nu; i++) {
        for (uint32_t k = 0; k < cv->cut; k++) {
            cv->upper_out[i] = (cv->upper_out[i] == cv->slots[k]) ? VOR__NONE : cv->upper_out[i];
        }
    }
    for (uint32_t i = 0; (i + 1u) < cv->nl; i++) {
        for (uint32_t k = 0; k < cv->cut; k++) {
            cv->lower_out[i] = (cv->lower_out[i] == cv->slots[k]) ? VOR__NONE : cv->lower_out[i];
        }
    }
    /* mark the home slots among the cavity's; list its packed slots */
    uint32_t packed = 0;
    for (uint32_t i = 0; i < cv->cut; i++) {
        vor_index_t s = cv->slots[i];
        if (s < m->max_sites) {
            vor__set_mark(&tri[s], true);
        } else {
            cv->slots[packed] = s;
            packed++;
        }
    }
    /* the lower chain reversed, so that it lies left of its base too */
    for (uint32_t i = 0; i < (cv->nl / 2u); i++) {
        uint32_t j = cv->nl - 1u - i;
        vor_index_t v = cv->lower[i];
        cv->lower[i] = cv->lower[j];
        cv->lower[j] = v;
    }
    for (uint32_t i = 0; i < ((cv->nl - 1u) / 2u); i++) {
        uint32_t j = cv->nl - 2u - i;
        vor_index_t o = cv->lower_out[i];
        cv->lower_out[i] = cv->lower_out[j];
        cv->lower_out[j] = o;
    }
    /* the ends go to the polygon with room */
    vor_index_t from = cv->upper[0];
    vor_index_t end = cv->upper[cv->nu - 1u];
    count_demands(m, cv->upper, cv->nu, cv->demands);
    uint32_t room_up = (cv->nu - 2u) - demand(cv->demands, 0, cv->nu - 1u);
    bool from_up = needs_home(m, from) && (room_up > 0u);
    room_up -= from_up ? 1u : 0u;
    bool end_up = needs_home(m, end) && (room_up > 0u);
    bool from_down = needs_home(m, from) && !from_up;
    bool end_down = needs_home(m, end) && !end_up;
    vor_index_t top = triangulate(c, cv->upper, cv->upper_out, cv->nu, cv, from_up, end_up,
                                  VOR__NONE, &packed);
    link_spikes(tri, cv->upper, cv->upper_out, cv->nu, cv);
    count_demands(m, cv->lower, cv->nl, cv->demands);
    vor_index_t bottom = triangulate(c, cv->lower, cv->lower_out, cv->nl, cv, end_down,
                                     from_down, top, &packed);
    link_spikes(tri, cv->lower, cv->lower_out, cv->nl, cv);
    tri[top].n[2] = bottom;
    VOR_ASSERT(packed == 0u);
}

/* The constrained neighbour of vertex `at` that continues the line from
 * `prev` through `at` beyond it, or VOR__NONE. */
static vor_index_t run_next(const struct vor__cdt *c, vor_index_t prev, vor_index_t at)
{
    vor_neighbour_iter_t it;
    uint32_t w;
    uint32_t third;
    vor__fan_begin(&it, &c->mesh, at);
    while (vor__fan_next(&it, &w, &third)) {
        if ((w != prev) && vor__cdt_constrained(c, at, (vor_index_t)w) &&
            (exact_orient(c, prev, at, (vor_index_t)w) == 0) &&
            between(c, prev, at, (vor_index_t)w)) {
            return (vor_index_t)w;
        }
    }
    return VOR__NONE;
}

/* Two sites on the line of constrained edge u-v, *la and *lb: from each
 * end outward along the constrained edges on that line, the first site
 * (u or v when it is one). Every constraint ends at sites, so each way
 * reaches one, and no site whose constrained edges hold it can leave. */
static void run_line(const struct vor__cdt *c, vor_index_t u, vor_index_t v, vor_index_t *la,
                     vor_index_t *lb)
{
    vor_index_t ends[2];
    for (unsigned way = 0; way < 2u; way++) {
        vor_index_t prev = (way == 0u) ? v : u;
        vor_index_t at = (way == 0u) ? u : v;
        for (uint32_t left = c->max_crossings; (left > 0u) && is_crossing(c, at); left--) {
            vor_index_t next = run_next(c, prev, at);
            if (next == VOR__NONE) {
                break; /* a broken mesh only */
            }
            prev = at;
            at = next;
        }
        ends[way] = at;
    }
    *la = ends[0];
    *lb = ends[1];
}

/* A free crossing id, holding the lines a-b and c-d (the caller checked
 * room). */
static vor_index_t new_crossing(struct vor__cdt *c, vor_index_t a, vor_index_t b, vor_index_t p,
                                vor_index_t q)
{
    uint32_t i = 0;
    while (((i + 1u) < c->max_crossings) && (c->crossings[4u * i] != VOR__NONE)) {
        i++;
    }
    vor_index_t *e = &c->crossings[4u * i];
    e[0] = a;
    e[1] = b;
    e[2] = p;
    e[3] = q;
    c->crossing_count++;
    return (vor_index_t)(c->first_crossing + i);
}

int vor_constrain(vor_t *d, uint32_t a, uint32_t b)
{
    if ((d == NULL) || (d->cdt == NULL) || !vor__site_in_mesh(d, a) || !vor__site_in_mesh(d, b)) {
        return VOR_ERR_ARG;
    }
    if (a == b) {
        return VOR_OK;
    }
    struct vor__cdt *c = d->cdt;
    vor_t *m = &c->mesh;
    cavity_t cv;
    cavity_init(&cv, c);
    /* first the whole segment is walked, nothing changed: its cuts
     * checked, the new edges and crossings counted (a crossing splits the
     * edge it crosses and adds a piece) */
    uint32_t added = 0;
    uint32_t crossings = 0;
    vor_index_t from = (vor_index_t)a;
    for (uint32_t pieces = 0; (from != b) && (pieces < m->vertex_count); pieces++) {
        vor_index_t slot;
        vor_index_t next = first_step(c, from, (vor_index_t)b, &slot);
        if (next == VOR__NONE) {
            if (slot == VOR__NONE) {
                return VOR_ERR_ARG; /* a broken mesh only */
            }
            uint32_t k = 0;
            vor_index_t crossed[2];
            next = walk_cavity(c, &cv, from, (vor_index_t)b, slot, false, &k, crossed);
            if (next == VOR__NONE) {
                return VOR_ERR_NOMEM;
            }
            crossings += k;
            added += (2u * k) + 1u;
        } else {
            added += vor__cdt_constrained(c, from, next) ? 0u : 1u;
        }
        from = next;
    }
    if (((c->edge_count + added) > c->max_edges) ||
        ((c->crossing_count + crossings) > c->max_crossings)) {
        return VOR_ERR_NOMEM;
    }
    c->domain = false;
    /* then piece by piece: a constrained edge in the way gets its crossing
     * vertex (which splits it) and the piece ends there */
    from = (vor_index_t)a;
    uint32_t bound = m->max_sites + crossings + 1u;
    for (uint32_t steps = 0; (from != b) && (steps < bound); steps++) {
        vor_index_t slot;
        vor_index_t next = first_step(c, from, (vor_index_t)b, &slot);
        if (next == VOR__NONE) {
            uint32_t k = 0;
            vor_index_t crossed[2];
            next = walk_cavity(c, &cv, from, (vor_index_t)b, slot, true, &k, crossed);
            if (next == VOR__NONE) {
                vor_index_t la;
                vor_index_t lb;
                run_line(c, crossed[0], crossed[1], &la, &lb);
                vor_index_t x = new_crossing(c, (vor_index_t)a, (vor_index_t)b, la, lb);
                insert_vertex(c, x, from); /* x is on the edge the cut from `from` ends at */
                continue;
            }
            fill_cavity(c, &cv);
        }
        edge_add(c, from, next, 1u);
        from = next;
    }
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Removing constraints                                                */

/* The slot of the triangle holding edge u -> v counterclockwise, its
 * third corner's index in *corner; VOR__NONE when u-v is no edge. */
static vor_index_t edge_slot(const vor_t *m, vor_index_t u, vor_index_t v, unsigned *corner)
{
    vor_index_t slot = u;
    for (uint32_t left = m->vertex_count + 1u; (left > 0u) && !vor__slot_empty(&m->triangles[u]);
         left--) {
        const vor__tri_t *t = &m->triangles[slot];
        unsigned i = vor__vertex_index(t, u);
        if (i == 3u) {
            break; /* a broken mesh only */
        }
        if (vor__vertex(t, vor__next(i)) == v) {
            *corner = vor__prev(i);
            return slot;
        }
        slot = t->n[vor__prev(i)];
        if (slot == u) {
            break;
        }
    }
    return VOR__NONE;
}

/* Flips the edge opposite corner i of the triangle in `slot` (the two
 * triangles on it form a convex quadrilateral). */
static void flip_edge(vor_t *m, vor_index_t slot, unsigned i)
{
    vor__tri_t *tri = m->triangles;
    vor__tri_t *t = &tri[slot];
    vor_index_t v[3];
    vor__vertices(t, v);
    vor_index_t p = v[i];
    vor_index_t x = v[vor__next(i)];
    vor_index_t y = v[vor__prev(i)];
    vor_index_t u_slot = t->n[i];
    const vor__tri_t *u = &tri[u_slot];
    unsigned k = third_corner(u, x, y);
    (void)vor__flip_core(m, slot, u_slot, p, x, y, vor__vertex(u, k), t->n[vor__next(i)],
                         t->n[vor__prev(i)], u->n[vor__next(k)], u->n[vor__prev(k)]);
}

/* Lawson's flips back to the constrained Delaunay triangulation. */
typedef struct {
    vor_index_t *edges; /* pairs of vertices to test */
    uint32_t count;
    uint32_t room;      /* pairs */
    bool lost;          /* some did not fit: a sweep of every edge follows */
    uint64_t flips;     /* in this run */
} lawson_t;

/* An empty stack over the whole scratch: 13 (max_cut + 4) indices, as
 * vor_cdt_attach laid it out. One stack for the flips and the domain's
 * flood, so both read its room from here (set field by field: a struct
 * returned or assigned whole is a memcpy call at -O0). */
static void lawson_begin(struct vor__cdt *c, lawson_t *w)
{
    w->edges = c->scratch;
    w->count = 0;
    w->room = (13u * (c->max_cut + 4u)) / 2u;
    w->lost = false;
    w->flips = 0;
}

static void lawson_push(lawson_t *w, vor_index_t u, vor_index_t v)
{
    if (w->count < w->room) {
        w->edges[2u * w->count] = u;
        w->edges[(2u * w->count) + 1u] = v;
        w->count++;
    } else {
        w->lost = true;
    }
}

/* Flips edge u-v when it is no constrained edge, no hull edge, and its far
 * vertex lies in its circle; then its four outer edges are to test. */
static bool lawson_test(struct vor__cdt *c, lawson_t *w, vor_index_t u, vor_index_t v)
{
    vor_t *m = &c->mesh;
    unsigned k;
    if ((u == VOR__INFINITE) || (v == VOR__INFINITE)) {
        return false; /* a hull edge's spoke: never flipped */
    }
    vor_index_t slot = edge_slot(m, u, v, &k);
    if ((slot == VOR__NONE) || vor__cdt_constrained(c, u, v)) {
        return false;
    }
    const vor__tri_t *t = &m->triangles[slot];
    vor_index_t p = vor__vertex(t, k);
    const vor__tri_t *o = &m->triangles[t->n[k]];
    vor_index_t q = vor__vertex(o, third_corner(o, u, v));
    if ((p == VOR__INFINITE) || (q == VOR__INFINITE) || (incircle(c, u, v, p, q) <= 0)) {
        return false;
    }
    flip_edge(m, slot, k);
    w->flips++;
    lawson_push(w, u, q);
    lawson_push(w, q, v);
    lawson_push(w, v, p);
    lawson_push(w, p, u);
    return true;
}

/* Runs the flips. A flip lowers the lifted surface, so an edge flipped
 * away never comes back (Lawson): at most one flip per pair of vertices,
 * fewer than v^2. A good share of the pairs can be needed (a constraint
 * taken off between two long arcs of sites: docs/design/constraints.md);
 * the bound only stops lying predicates (fault injection). When the
 * stack overflowed, sweeps over every edge finish the work. */
static void lawson_run(struct vor__cdt *c, lawson_t *w)
{
    vor_t *m = &c->mesh;
    uint64_t bound = vor__mul_u32(m->vertex_count, m->vertex_count);
    w->flips = 0;
    while ((w->count > 0u) && (w->flips < bound)) {
        w->count--;
        (void)lawson_test(c, w, w->edges[2u * w->count], w->edges[(2u * w->count) + 1u]);
    }
    bool changed = w->lost;
    while (changed && (w->flips < bound)) {
        changed = false;
        uint32_t end = vor__used_slots_end(m);
        for (uint32_t s = vor__next_used_slot(m, 0); s < end; s = vor__next_used_slot(m, s + 1u)) {
            vor_index_t v[3];
            vor__vertices(&m->triangles[s], v);
            for (unsigned k = 0; k < 3u; k++) {
                w->count = 0;
                if (lawson_test(c, w, v[vor__next(k)], v[vor__prev(k)])) {
                    changed = true;
                    break; /* the triangle changed */
                }
            }
        }
    }
    w->count = 0;
}

/* Removes crossing vertex x, whose constrained edges u-x and x-v now lie
 * on one line: x's other spokes are flipped away, one side at a time
 * (the spoke to the vertex farthest from line u-v always can be: the
 * segment between its ring neighbours crosses the spoke), until x has
 * four neighbours u, s, v, t; then its four triangles become (u, s, v)
 * and (v, t, u), u-v constrained as u-x and x-v were, and every edge the
 * flips made is left to Lawson's flips. Home slots: (u, s, v) goes to
 * s's home if it is one of the four slots, (v, t, u) to t's; the fourth
 * slot besides x's is freed, refilled as a removal's is (dynamic.c). */
static void remove_crossing(struct vor__cdt *c, vor_index_t x, lawson_t *w)
{
    vor_t *m = &c->mesh;
    vor__tri_t *tri = m->triangles;
    vor_index_t u = VOR__NONE;
    vor_index_t v = VOR__NONE;
    vor_neighbour_iter_t it;
    uint32_t n;
    uint32_t third;
    vor__fan_begin(&it, m, x);
    while (vor__fan_next(&it, &n, &third)) {
        if (vor__cdt_constrained(c, x, (vor_index_t)n)) {
            v = (u == VOR__NONE) ? v : (vor_index_t)n;
            u = (u == VOR__NONE) ? (vor_index_t)n : u;
        }
    }
    uint32_t count = c->edges[vor__cdt_find(c, u, x)].count;
    /* flip spokes until the degree is 4 */
    for (uint32_t left = m->vertex_count; left > 0u; left--) {
        uint32_t degree = 0;
        bool flipped = false;
        vor_index_t slot = x;
        for (uint32_t k = m->vertex_count + 1u; (k > 0u) && !flipped; k--) {
            /* star triangle (x, a, b) and the next, (x, b, e): spoke x-b */
            const vor__tri_t *t = &tri[slot];
            unsigned i = vor__vertex_index(t, x);
            vor_index_t a = vor__vertex(t, vor__next(i));
            vor_index_t b = vor__vertex(t, vor__prev(i));
            vor_index_t next = t->n[vor__next(i)];
            const vor__tri_t *nt = &tri[next];
            vor_index_t e = vor__vertex(nt, vor__prev(vor__vertex_index(nt, x)));
            degree++;
            /* b alone on its side would leave x on a flat (u, x, v) */
            bool alone = ((a == u) && (e == v)) || ((a == v) && (e == u));
            if ((b != u) && (b != v) && !alone && (orient(c, x, a, e) > 0) &&
                (orient(c, a, b, e) > 0)) {
                flip_edge(m, next, vor__prev(vor__vertex_index(nt, x)));
                lawson_push(w, a, e);
                flipped = true;
            }
            slot = next;
            if (slot == x) {
                break;
            }
        }
        if (!flipped) {
            VOR_ASSERT(degree == 4u);
            break;
        }
    }
    /* the four triangles (x, u, s), (x, s, v), (x, v, t), (x, t, u) */
    vor_index_t slots[4];
    vor_index_t ring[4];
    vor_index_t outer[4];
    unsigned start = 0;
    vor_index_t slot = x;
    for (unsigned k = 0; k < 4u; k++) {
        const vor__tri_t *t = &tri[slot];
        unsigned i = vor__vertex_index(t, x);
        slots[k] = slot;
        ring[k] = vor__vertex(t, vor__next(i));
        outer[k] = t->n[i]; /* across ring[k] - ring[k + 1] */
        start = (ring[k] == u) ? k : start;
        slot = t->n[vor__next(i)]; /* across x - ring[k + 1]: counterclockwise */
    }
    vor_index_t r[4];
    vor_index_t o[4];
    vor_index_t sl[4];
    for (unsigned k = 0; k < 4u; k++) {
        r[k] = ring[(start + k) & 3u];
        o[k] = outer[(start + k) & 3u];
        sl[k] = slots[(start + k) & 3u];
    }
    vor_index_t s = r[1];
    vor_index_t t = r[3];
    /* (u, s, v) to s's home if among the slots, (v, t, u) to t's; the
     * others to homes of u or v first, packed slots last */
    vor_index_t a_slot = VOR__NONE;
    vor_index_t b_slot = VOR__NONE;
    for (unsigned k = 0; k < 4u; k++) {
        a_slot = ((sl[k] == s) && (s < m->max_sites)) ? sl[k] : a_slot;
        b_slot = ((sl[k] == t) && (t < m->max_sites)) ? sl[k] : b_slot;
    }
    for (unsigned pass = 0; pass < 2u; pass++) {
        for (unsigned k = 0; k < 4u; k++) {
            vor_index_t q = sl[k];
            bool home = (q == u) || (q == v);
            bool free = (q != x) && (q != a_slot) && (q != b_slot) && ((pass == 1u) || home);
            if (free && (a_slot == VOR__NONE)) {
                a_slot = q;
            } else if (free && (b_slot == VOR__NONE)) {
                b_slot = q;
            } else {
                /* taken, or left for later */
            }
        }
    }
    vor_index_t freed = VOR__NONE;
    for (unsigned k = 0; k < 4u; k++) {
        freed = ((sl[k] != x) && (sl[k] != a_slot) && (sl[k] != b_slot)) ? sl[k] : freed;
    }
    /* by edges, not by old links: an outer triangle on two ring edges (a
     * ring vertex of degree 3) may already link to a_slot or b_slot */
    vor__relink_before(tri, o[0], r[0], a_slot);
    vor__relink_before(tri, o[1], r[1], a_slot);
    vor__relink_before(tri, o[2], r[2], b_slot);
    vor__relink_before(tri, o[3], r[3], b_slot);
    vor__tri_set(&tri[a_slot], u, s, v, o[1], b_slot, o[0]);
    vor__tri_set(&tri[b_slot], v, t, u, o[3], a_slot, o[2]);
    vor__tri_fresh(&tri[x]);
    tri[x].n[0] = VOR__NONE;
    vor_index_t last = (vor_index_t)(m->max_sites + m->vertex_count - 3u);
    if (freed < m->max_sites) { /* a home of u or v: refilled from its stars */
        vor__rehome(m, freed, a_slot, last); /* (u, s, v) holds u and v */
    } else if (freed != last) {
        vor__move_triangle(tri, last, freed);
    } else {
        /* the last packed slot: nothing to move */
    }
    m->vertex_count--;
    edge_remove(c, vor__cdt_find(c, u, x));
    edge_remove(c, vor__cdt_find(c, x, v));
    edge_add(c, u, v, count);
    c->crossings[4u * (x - c->first_crossing)] = VOR__NONE;
    c->crossing_count--;
    lawson_push(w, u, s);
    lawson_push(w, s, v);
    lawson_push(w, v, t);
    lawson_push(w, t, u);
}

/* The lines through crossing vertex x: how many distinct lines its
 * constrained edges lie on (up to 2 counted), and two sites of each of
 * the first two in sites[0..4). */
static unsigned crossing_lines(const struct vor__cdt *c, vor_index_t x, vor_index_t sites[4])
{
    vor_index_t first = VOR__NONE;
    unsigned lines = 0;
    vor_neighbour_iter_t it;
    uint32_t n;
    uint32_t third;
    vor__fan_begin(&it, &c->mesh, x);
    while ((lines < 2u) && vor__fan_next(&it, &n, &third)) {
        if (!vor__cdt_constrained(c, x, (vor_index_t)n)) {
            continue;
        }
        if (first == VOR__NONE) {
            first = (vor_index_t)n;
            run_line(c, x, first, &sites[0], &sites[1]);
            lines = 1;
        } else if (exact_orient(c, first, x, (vor_index_t)n) != 0) {
            run_line(c, x, (vor_index_t)n, &sites[2], &sites[3]);
            lines = 2;
        } else {
            /* on the first line */
        }
    }
    return lines;
}

int vor_unconstrain(vor_t *d, uint32_t a, uint32_t b)
{
    if ((d == NULL) || (d->cdt == NULL) || !vor__site_in_mesh(d, a) || !vor__site_in_mesh(d, b)) {
        return VOR_ERR_ARG;
    }
    struct vor__cdt *c = d->cdt;
    vor_t *m = &c->mesh;
    /* every piece from a to b must be a constrained edge */
    vor_index_t from = (vor_index_t)a;
    for (uint32_t pieces = 0; (from != b) && (pieces < m->vertex_count); pieces++) {
        vor_index_t slot;
        vor_index_t next = first_step(c, from, (vor_index_t)b, &slot);
        if ((next == VOR__NONE) || !vor__cdt_constrained(c, from, next)) {
            return VOR_ERR_ARG;
        }
        from = next;
    }
    if (from != b) {
        return VOR_ERR_ARG; /* a == b's point: never two sites */
    }
    c->domain = false;
    /* one constraint less on each piece; the freed edges are tested */
    lawson_t w;
    lawson_begin(c, &w);
    from = (vor_index_t)a;
    for (uint32_t pieces = 0; (from != b) && (pieces < m->vertex_count); pieces++) {
        vor_index_t slot;
        vor_index_t next = first_step(c, from, (vor_index_t)b, &slot);
        uint32_t e = vor__cdt_find(c, from, next);
        c->edges[e].count--;
        if (c->edges[e].count == 0u) {
            edge_remove(c, e);
            lawson_push(&w, from, next);
        }
        from = next;
    }
    lawson_run(c, &w);
    /* crossing vertices left on one line go; the others are defined
     * again by sites of their lines that still hold constraints */
    for (uint32_t i = 0; i < c->max_crossings; i++) {
        vor_index_t *q = &c->crossings[4u * i];
        if (q[0] == VOR__NONE) {
            continue;
        }
        vor_index_t x = (vor_index_t)(c->first_crossing + i);
        vor_index_t sites[4];
        if (crossing_lines(c, x, sites) < 2u) {
            remove_crossing(c, x, &w);
            lawson_run(c, &w);
        } else {
            for (unsigned k = 0; k < 4u; k++) {
                q[k] = sites[k];
            }
        }
    }
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* The domain                                                          */

#define LEVEL_UNKNOWN 0xFFu
#define LEVEL_PENDING 0x80u /* a level reached across a constraint, not final */
#define LEVEL_MAX 126u

/* Triangle s of level `level`: its unconstrained neighbours join the
 * level (stacked in w when it is given), those across an edge under k
 * constraints wait at level + k. Returns whether a neighbour changed. */
static bool spread(struct vor__cdt *c, lawson_t *w, vor_index_t s, uint32_t level)
{
    const vor__tri_t *tri = c->mesh.triangles;
    uint8_t *lv = c->levels;
    bool changed = false;
    vor_index_t v[3];
    vor__vertices(&tri[s], v);
    for (unsigned k = 0; k < 3u; k++) {
        vor_index_t a = v[vor__next(k)];
        vor_index_t b = v[vor__prev(k)];
        vor_index_t u = tri[s].n[k];
        uint32_t e = ((a == VOR__INFINITE) || (b == VOR__INFINITE)) ? c->edge_slots
                                                                   : vor__cdt_find(c, a, b);
        uint32_t to = (e == c->edge_slots) ? level : (level + c->edges[e].count);
        to = (to > LEVEL_MAX) ? LEVEL_MAX : to;
        uint32_t now = lv[u];
        bool open = (now == LEVEL_UNKNOWN) ||
                    (((now & LEVEL_PENDING) != 0u) && ((now & ~LEVEL_PENDING) > to));
        if (open) {
            lv[u] = (uint8_t)((to == level) ? level : (to | LEVEL_PENDING));
            changed = true;
            if ((to == level) && (w != NULL)) {
                lawson_push(w, u, u);
            }
        }
    }
    return changed;
}

/* Floods the level-`level` region from the triangles stacked in w; when
 * the stack overflowed, sweeps over the level's triangles finish it. */
static void flood(struct vor__cdt *c, lawson_t *w, uint32_t level)
{
    const vor_t *m = &c->mesh;
    while (w->count > 0u) {
        w->count--;
        (void)spread(c, w, w->edges[2u * w->count], level);
    }
    bool changed = w->lost;
    w->lost = false;
    while (changed) {
        changed = false;
        uint32_t end = vor__used_slots_end(m);
        for (uint32_t s = vor__next_used_slot(m, 0); s < end; s = vor__next_used_slot(m, s + 1u)) {
            if (c->levels[s] == level) {
                changed = spread(c, NULL, (vor_index_t)s, level) || changed;
            }
        }
    }
}

int vor_cdt_domain(vor_t *d)
{
    if ((d == NULL) || (d->cdt == NULL)) {
        return VOR_ERR_ARG;
    }
    struct vor__cdt *c = d->cdt;
    const vor_t *m = &c->mesh;
    uint8_t *lv = c->levels;
    /* below two vertices the slots hold no triangle (stale contents) */
    uint32_t end = (m->vertex_count >= 2u) ? vor__used_slots_end(m) : 0u;
    lawson_t w;
    lawson_begin(c, &w);
    for (uint32_t s = 0; s < end; s++) {
        lv[s] = LEVEL_UNKNOWN;
    }
    for (uint32_t s = vor__next_used_slot(m, 0); s < end; s = vor__next_used_slot(m, s + 1u)) {
        if (vor__vertex_index(&m->triangles[s], VOR__INFINITE) != 3u) { /* outside: level 0 */
            lv[s] = 0;
            lawson_push(&w, (vor_index_t)s, (vor_index_t)s);
        }
    }
    for (uint32_t level = 0; level <= LEVEL_MAX; level++) {
        if (level > 0u) { /* the pending triangles of this level start it */
            bool waiting = false; /* a triangle pending (above this level) or unreached */
            for (uint32_t s = vor__next_used_slot(m, 0); s < end; s = vor__next_used_slot(m, s + 1u)) {
                waiting = waiting || ((lv[s] & LEVEL_PENDING) != 0u);
                if (lv[s] == (level | LEVEL_PENDING)) {
                    lv[s] = (uint8_t)level;
                    lawson_push(&w, (vor_index_t)s, (vor_index_t)s);
                }
            }
            if (!waiting) {
                break; /* every triangle has its level */
            }
        }
        flood(c, &w, level);
    }
    c->domain = true;
    return VOR_OK;
}

int vor_cdt_inside_begin(vor_cdt_triangle_iter_t *it, const vor_t *d)
{
    int err = vor_cdt_triangles_begin(it, d);
    if ((err == VOR_OK) && !d->cdt->domain) {
        it->d = NULL;
        err = VOR_ERR_ARG;
    }
    if (err == VOR_OK) {
        it->inside = true;
    }
    return err;
}

/* ------------------------------------------------------------------ */
/* Output                                                              */

int vor_cdt_triangles_begin(vor_cdt_triangle_iter_t *it, const vor_t *d)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    it->d = ((d != NULL) && (d->cdt != NULL)) ? d : NULL;
    it->slot = 0;
    it->inside = false;
    return (it->d != NULL) ? VOR_OK : VOR_ERR_ARG;
}

int vor_cdt_triangles_next(vor_cdt_triangle_iter_t *it, uint32_t ids[3])
{
    if ((it == NULL) || (it->d == NULL) || (ids == NULL)) {
        return 0;
    }
    const struct vor__cdt *c = it->d->cdt;
    const vor_t *m = &c->mesh;
    if (m->vertex_count < 2u) {
        return 0;
    }
    uint32_t end = vor__used_slots_end(m);
    for (uint32_t s = vor__next_used_slot(m, it->slot); s < end; s = vor__next_used_slot(m, s + 1u)) {
        vor_index_t w[3];
        vor__vertices(&m->triangles[s], w);
        /* of nonzero area: as vor_triangles_next reports the Delaunay ones */
        bool wanted = !it->inside || (c->domain && ((c->levels[s] & 1u) != 0u));
        if (wanted && (w[0] != VOR__INFINITE) && (w[1] != VOR__INFINITE) &&
            (w[2] != VOR__INFINITE) && (exact_orient(c, w[0], w[1], w[2]) != 0)) {
            ids[0] = w[0];
            ids[1] = w[1];
            ids[2] = w[2];
            it->slot = s + 1u;
            return 1;
        }
    }
    it->slot = end;
    return 0;
}

int vor_cdt_edges_begin(vor_cdt_edge_iter_t *it, const vor_t *d)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    it->d = ((d != NULL) && (d->cdt != NULL)) ? d : NULL;
    it->entry = 0;
    return (it->d != NULL) ? VOR_OK : VOR_ERR_ARG;
}

int vor_cdt_edges_next(vor_cdt_edge_iter_t *it, uint32_t *a, uint32_t *b)
{
    if ((it == NULL) || (it->d == NULL) || (a == NULL) || (b == NULL)) {
        return 0;
    }
    const struct vor__cdt *c = it->d->cdt;
    for (uint32_t i = it->entry; i < c->edge_slots; i++) {
        if (c->edges[i].u != VOR__NONE) {
            *a = c->edges[i].u;
            *b = c->edges[i].v;
            it->entry = i + 1u;
            return 1;
        }
    }
    it->entry = c->edge_slots;
    return 0;
}
