/* SPDX-License-Identifier: MIT */
/*
 * test_cdt.c - constraints (vor_cdt.h): the constrained triangulation
 * against an independent check of what it must be.
 *
 * The check reads only the public output (vor_cdt_triangles_next,
 * vor_cdt_edges_next, vor_cdt_crossing) and decides with exact
 * predicates: the sites' own (vor_orient2d, vor_incircle), and for
 * crossing vertices the homogeneous ones of src/crossing.h, which
 * predicates/crossing_vectors checks against exact rationals:
 *   - every triangle is counterclockwise, every edge is on one triangle
 *     each way at most, and there are as many triangles as the Delaunay
 *     triangulation of the sites has plus two a crossing vertex (a
 *     triangulation of the sites and the crossings, all inside the hull);
 *   - every edge on two triangles that is not constrained is locally
 *     Delaunay (the far vertex not strictly inside the circle), which
 *     makes it the constrained Delaunay triangulation;
 *   - every crossing vertex lies on its two lines and inside two of the
 *     test's constraints, no two at one point nor at a site, and every two
 *     constraints that cross at a point that is no site have one there;
 *   - the constrained edges are exactly the pieces of the test's
 *     constraints: each segment cut at every site and crossing vertex on
 *     it, found here by exact collinearity and sorted along it.
 */
#include "cdt.h"
#include "crossing.h"
#include "predicates.h"
#include "test.h"
#include "vor_cdt.h"

#define CDT_SITES 120u
#define CDT_CONSTRAINTS 80u
#define CDT_CROSSINGS 200u
#define CDT_VERTICES (CDT_SITES + CDT_CROSSINGS)
#define CDT_EDGES (3u * CDT_VERTICES)
#define CDT_CUT (2u * CDT_VERTICES + 2u)

static uint8_t arena[VOR_ARENA_BYTES(CDT_SITES)] __attribute__((aligned(8)));
static uint8_t memory[VOR_CDT_BYTES(CDT_SITES, CDT_EDGES, CDT_CROSSINGS, CDT_CUT)]
    __attribute__((aligned(8)));
static uint8_t saved_arena[sizeof arena];
static uint8_t saved_memory[sizeof memory];
static const vor_cdt_limits_t limits = {CDT_EDGES, CDT_CROSSINGS, CDT_CUT};

/* The test's own record: points by site id, and the constraints made. */
typedef struct {
    vor_point_t at[CDT_SITES];
    bool live[CDT_SITES];
    uint32_t a[CDT_CONSTRAINTS];
    uint32_t b[CDT_CONSTRAINTS];
    uint32_t constraints;
} model_t;

static model_t model;

/* Vertex v of d's constrained triangulation (a site, or a crossing id
 * from max_sites on) in homogeneous coordinates; false if v is neither. */
static bool vertex_of(const vor_t *d, uint32_t v, vor__hpoint_t *h)
{
    if (v < d->max_sites) {
        vor__hpoint_site(h, model.at[v]);
        return model.live[v];
    }
    uint32_t s[4];
    if (vor_cdt_crossing(d, v, s) != VOR_OK) {
        return false;
    }
    return vor__hpoint_crossing(h, model.at[s[0]], model.at[s[1]], model.at[s[2]],
                                model.at[s[3]]);
}

/* Is m strictly inside segment p-q (three collinear points)? */
static bool inside(const vor__hpoint_t *p, const vor__hpoint_t *m, const vor__hpoint_t *q)
{
    bool any = false;
    for (unsigned axis = 0; axis < 2u; axis++) {
        int way = vor__compare_h(q, p, axis);
        if ((vor__compare_h(m, p, axis) != way) || (vor__compare_h(q, m, axis) != way)) {
            return false;
        }
        any = any || (way != 0);
    }
    return any;
}

static bool same_point(const vor__hpoint_t *p, const vor__hpoint_t *q)
{
    return (vor__compare_h(p, q, 0) == 0) && (vor__compare_h(p, q, 1) == 0);
}

/* Is vertex h strictly inside constraint k's segment? */
static bool on_constraint(const vor__hpoint_t *h, uint32_t k)
{
    vor__hpoint_t a;
    vor__hpoint_t b;
    vor__hpoint_site(&a, model.at[model.a[k]]);
    vor__hpoint_site(&b, model.at[model.b[k]]);
    return (vor__orient_h(&a, &b, h) == 0) && inside(&a, h, &b);
}

/* An undirected edge as a sortable key, and the third vertex of the
 * triangle it came from, with its direction there. */
typedef struct {
    uint64_t key;
    uint32_t apex;
    uint32_t forward;
} half_edge_t;

static half_edge_t halves[6u * CDT_VERTICES];
static uint64_t got_keys[CDT_EDGES];
static uint64_t expected_keys[CDT_EDGES];
static uint32_t crossing_ids[CDT_CROSSINGS];
static vor__hpoint_t crossing_points[CDT_CROSSINGS];
static uint32_t on_ids[CDT_VERTICES];
static vor__hpoint_t on_points[CDT_VERTICES];

static uint64_t edge_key(uint32_t u, uint32_t v)
{
    return (u < v) ? (((uint64_t)u << 32) | v) : (((uint64_t)v << 32) | u);
}

static void sort_halves(half_edge_t *h, uint32_t n)
{
    for (uint32_t gap = n / 2u; gap > 0u; gap /= 2u) { /* shell sort */
        for (uint32_t i = gap; i < n; i++) {
            half_edge_t x = h[i];
            uint32_t j = i;
            while ((j >= gap) && (h[j - gap].key > x.key)) {
                h[j] = h[j - gap];
                j -= gap;
            }
            h[j] = x;
        }
    }
}

static void sort_keys(uint64_t *k, uint32_t n)
{
    for (uint32_t gap = n / 2u; gap > 0u; gap /= 2u) {
        for (uint32_t i = gap; i < n; i++) {
            uint64_t x = k[i];
            uint32_t j = i;
            while ((j >= gap) && (k[j - gap] > x)) {
                k[j] = k[j - gap];
                j -= gap;
            }
            k[j] = x;
        }
    }
}

static bool has_key(const uint64_t *k, uint32_t n, uint64_t key)
{
    uint32_t lo = 0;
    uint32_t hi = n;
    while (lo < hi) {
        uint32_t mid = lo + ((hi - lo) / 2u);
        if (k[mid] < key) {
            lo = mid + 1u;
        } else {
            hi = mid;
        }
    }
    return (lo < n) && (k[lo] == key);
}

/* The crossing vertices of d, with their points; their number. */
static uint32_t gather_crossings(const vor_t *d)
{
    uint32_t n = 0;
    for (uint32_t i = 0; (i < CDT_CROSSINGS) && (n < CDT_CROSSINGS); i++) {
        if (vertex_of(d, d->max_sites + i, &crossing_points[n])) {
            crossing_ids[n] = d->max_sites + i;
            n++;
        }
    }
    return n;
}

/* The pieces of constraint k: the vertices strictly inside it, sorted
 * along it, between its ends; added to keys[*n..] unless there. */
static void add_pieces(const vor_t *d, uint32_t k, uint32_t crossings, uint64_t *keys,
                       uint32_t *n)
{
    vor__hpoint_t a;
    vor__hpoint_site(&a, model.at[model.a[k]]);
    uint32_t count = 0;
    for (uint32_t i = 0; i < d->site_count; i++) {
        vor__hpoint_t h;
        vor__hpoint_site(&h, model.at[i]);
        if (model.live[i] && on_constraint(&h, k)) {
            on_ids[count] = i;
            on_points[count] = h;
            count++;
        }
    }
    for (uint32_t i = 0; i < crossings; i++) {
        if (on_constraint(&crossing_points[i], k)) {
            on_ids[count] = crossing_ids[i];
            on_points[count] = crossing_points[i];
            count++;
        }
    }
    /* insertion sort by distance from a: on a line, the coordinate that
     * changes orders it (x unless the segment is vertical) */
    vor__hpoint_t b;
    vor__hpoint_site(&b, model.at[model.b[k]]);
    unsigned axis = (vor__compare_h(&a, &b, 0) != 0) ? 0u : 1u;
    int way = vor__compare_h(&b, &a, axis);
    for (uint32_t i = 1; i < count; i++) {
        for (uint32_t j = i; (j > 0u) && (vor__compare_h(&on_points[j - 1u], &on_points[j], axis) == way); j--) {
            uint32_t id = on_ids[j];
            vor__hpoint_t h = on_points[j];
            on_ids[j] = on_ids[j - 1u];
            on_points[j] = on_points[j - 1u];
            on_ids[j - 1u] = id;
            on_points[j - 1u] = h;
        }
    }
    uint32_t from = model.a[k];
    for (uint32_t i = 0; i <= count; i++) {
        uint32_t to = (i < count) ? on_ids[i] : model.b[k];
        uint64_t key = edge_key(from, to);
        bool seen = false;
        for (uint32_t j = 0; (j < *n) && !seen; j++) {
            seen = keys[j] == key;
        }
        if (!seen && (*n < CDT_EDGES)) {
            keys[(*n)++] = key;
        }
        from = to;
    }
}

/* Do constraints j and k cross at a point that is no site? */
static bool cross_off_sites(const vor_t *d, uint32_t j, uint32_t k)
{
    vor_point_t a = model.at[model.a[j]];
    vor_point_t b = model.at[model.b[j]];
    vor_point_t c = model.at[model.a[k]];
    vor_point_t e = model.at[model.b[k]];
    if ((vor_orient2d(a, b, c) * vor_orient2d(a, b, e) >= 0) ||
        (vor_orient2d(c, e, a) * vor_orient2d(c, e, b) >= 0)) {
        return false;
    }
    vor__hpoint_t x;
    (void)vor__hpoint_crossing(&x, a, b, c, e);
    for (uint32_t i = 0; i < d->site_count; i++) {
        vor__hpoint_t h;
        vor__hpoint_site(&h, model.at[i]);
        if (model.live[i] && same_point(&h, &x)) {
            return false;
        }
    }
    return true;
}

/* The checks of the file comment; returns the number of violations. */
static unsigned long check_cdt(const vor_t *d)
{
    unsigned long bad = 0;
    uint32_t crossings = gather_crossings(d);
    /* crossing vertices: on their lines, in two constraints, distinct */
    for (uint32_t i = 0; i < crossings; i++) {
        uint32_t s[4];
        (void)vor_cdt_crossing(d, crossing_ids[i], s);
        vor__hpoint_t h[4];
        for (unsigned k = 0; k < 4u; k++) {
            vor__hpoint_site(&h[k], model.at[s[k]]);
        }
        bad += (vor__orient_h(&h[0], &h[1], &crossing_points[i]) == 0) ? 0u : 1u;
        bad += (vor__orient_h(&h[2], &h[3], &crossing_points[i]) == 0) ? 0u : 1u;
        uint32_t through = 0;
        for (uint32_t k = 0; k < model.constraints; k++) {
            through += on_constraint(&crossing_points[i], k) ? 1u : 0u;
        }
        bad += (through >= 2u) ? 0u : 1u;
        for (uint32_t j = 0; j < i; j++) {
            bad += same_point(&crossing_points[i], &crossing_points[j]) ? 1u : 0u;
        }
        for (uint32_t j = 0; j < d->site_count; j++) {
            vor__hpoint_t p;
            vor__hpoint_site(&p, model.at[j]);
            bad += (model.live[j] && same_point(&p, &crossing_points[i])) ? 1u : 0u;
        }
    }
    for (uint32_t j = 0; j < model.constraints; j++) {
        for (uint32_t k = 0; k < j; k++) {
            if (!cross_off_sites(d, j, k)) {
                continue;
            }
            bool found = false;
            for (uint32_t i = 0; (i < crossings) && !found; i++) {
                found = on_constraint(&crossing_points[i], j) && on_constraint(&crossing_points[i], k);
            }
            bad += found ? 0u : 1u;
        }
    }
    /* the triangles, as half-edges */
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    uint32_t triangles = 0;
    uint32_t nh = 0;
    (void)vor_cdt_triangles_begin(&it, d);
    while (vor_cdt_triangles_next(&it, ids) == 1) {
        triangles++;
        vor__hpoint_t h[3];
        bool known = true;
        for (unsigned k = 0; k < 3u; k++) {
            known = known && vertex_of(d, ids[k], &h[k]);
        }
        bad += (known && (vor__orient_h(&h[0], &h[1], &h[2]) > 0)) ? 0u : 1u;
        for (unsigned k = 0; (k < 3u) && (nh < sizeof halves / sizeof halves[0]); k++) {
            uint32_t u = ids[(k + 1u) % 3u];
            uint32_t v = ids[(k + 2u) % 3u];
            halves[nh].key = edge_key(u, v);
            halves[nh].apex = ids[k];
            halves[nh].forward = (u < v) ? 1u : 0u;
            nh++;
        }
    }
    vor_triangle_iter_t dt;
    uint32_t delaunay = 0;
    (void)vor_triangles_begin(&dt, d);
    while (vor_triangles_next(&dt, ids) == 1) {
        delaunay++;
    }
    bad += (triangles == delaunay + ((delaunay > 0u) ? 2u * crossings : 0u)) ? 0u : 1u;
    /* the constrained edges */
    uint32_t np = 0;
    vor_cdt_edge_iter_t e;
    uint32_t a;
    uint32_t b;
    (void)vor_cdt_edges_begin(&e, d);
    while ((vor_cdt_edges_next(&e, &a, &b) == 1) && (np < CDT_EDGES)) {
        got_keys[np++] = edge_key(a, b);
    }
    sort_keys(got_keys, np);
    sort_halves(halves, nh);
    /* each edge once each way at most; locally Delaunay unless constrained */
    for (uint32_t i = 0; i < nh;) {
        uint32_t j = i + 1u;
        while ((j < nh) && (halves[j].key == halves[i].key)) {
            j++;
        }
        if ((j - i > 2u) || ((j - i == 2u) && (halves[i].forward == halves[i + 1u].forward))) {
            bad++;
        } else if ((j - i == 2u) && !has_key(got_keys, np, halves[i].key)) {
            uint32_t u = (uint32_t)(halves[i].key >> 32);
            uint32_t v = (uint32_t)halves[i].key;
            vor__hpoint_t h[4];
            /* (u, v, w) counterclockwise when u -> v runs forward in w's triangle */
            (void)vertex_of(d, halves[i].forward ? u : v, &h[0]);
            (void)vertex_of(d, halves[i].forward ? v : u, &h[1]);
            (void)vertex_of(d, halves[i].apex, &h[2]);
            (void)vertex_of(d, halves[i + 1u].apex, &h[3]);
            bad += (vor__incircle_h(&h[0], &h[1], &h[2], &h[3]) > 0) ? 1u : 0u;
        } else {
            /* a hull edge, or a constrained one */
        }
        i = j;
    }
    /* the constrained edges are the constraints' pieces, each an edge */
    uint32_t ne = 0;
    for (uint32_t k = 0; k < model.constraints; k++) {
        add_pieces(d, k, crossings, expected_keys, &ne);
    }
    sort_keys(expected_keys, ne);
    bad += (ne == np) ? 0u : 1u;
    for (uint32_t i = 0; (i < ne) && (i < np); i++) {
        bad += (expected_keys[i] == got_keys[i]) ? 0u : 1u;
    }
    for (uint32_t i = 0; (triangles > 0u) && (i < np); i++) {
        bool found = false;
        for (uint32_t k = 0; (k < nh) && !found; k++) {
            found = halves[k].key == got_keys[i];
        }
        bad += found ? 0u : 1u;
    }
    return bad;
}

/* A point of the distribution `kind`: 0 a small grid (collinear and
 * cocircular sites everywhere), 1 a box of 2^20, 2 the full int32 range. */
static vor_point_t random_point(test_rng_t *rng, unsigned kind)
{
    vor_point_t p;
    if (kind == 0u) {
        p.x = test_rng_range(rng, -6, 6);
        p.y = test_rng_range(rng, -6, 6);
    } else if (kind == 1u) {
        p.x = test_rng_range(rng, -(1 << 19), (1 << 19) - 1);
        p.y = test_rng_range(rng, -(1 << 19), (1 << 19) - 1);
    } else {
        p.x = (int32_t)test_rng_u32(rng);
        p.y = (int32_t)test_rng_u32(rng);
    }
    return p;
}

/* Inserts a random point, noting it in the model. */
static int insert_random(vor_t *d, test_rng_t *rng, unsigned kind)
{
    vor_point_t p = random_point(rng, kind);
    uint32_t id;
    int err = vor_insert(d, p, &id);
    if (err == VOR_OK) {
        model.at[id] = p;
        model.live[id] = true;
    }
    return err;
}

static void model_clear(void)
{
    for (uint32_t i = 0; i < CDT_SITES; i++) {
        model.live[i] = false;
    }
    model.constraints = 0;
}

/* Does site s end a constrained edge? (From the public edge iterator.) */
static bool ends_constraint(const vor_t *d, uint32_t s)
{
    vor_cdt_edge_iter_t e;
    uint32_t a;
    uint32_t b;
    (void)vor_cdt_edges_begin(&e, d);
    while (vor_cdt_edges_next(&e, &a, &b) == 1) {
        if ((a == s) || (b == s)) {
            return true;
        }
    }
    return false;
}

/* Random constraints between random sites, each checked after. */
static void constrain_random(vor_t *d, test_rng_t *rng, uint32_t count, unsigned long *bad)
{
    for (uint32_t k = 0; (k < 4u * count) && (model.constraints < count); k++) {
        uint32_t a = test_rng_u32(rng) % d->site_count;
        uint32_t b = test_rng_u32(rng) % d->site_count;
        if (!model.live[a] || !model.live[b] || (a == b)) {
            continue;
        }
        int err = vor_constrain(d, a, b);
        *bad += (err == VOR_OK) ? 0u : 1u;
        if (err == VOR_OK) {
            model.a[model.constraints] = a;
            model.b[model.constraints] = b;
            model.constraints++;
            *bad += check_cdt(d);
        }
    }
}

/* Inserts a site at the first crossing vertex of d that lies on the
 * integer lattice (small coordinates: exact in int64), if any. */
static bool insert_at_crossing(vor_t *d)
{
    uint32_t crossings = gather_crossings(d);
    for (uint32_t i = 0; i < crossings; i++) {
        uint32_t s[4];
        (void)vor_cdt_crossing(d, crossing_ids[i], s);
        vor_point_t a = model.at[s[0]];
        vor_point_t b = model.at[s[1]];
        vor_point_t c = model.at[s[2]];
        vor_point_t e = model.at[s[3]];
        int64_t w = ((int64_t)b.x - a.x) * (e.y - c.y) - ((int64_t)b.y - a.y) * (e.x - c.x);
        int64_t t = ((int64_t)c.x - a.x) * (e.y - c.y) - ((int64_t)c.y - a.y) * (e.x - c.x);
        int64_t x = a.x * w + ((int64_t)b.x - a.x) * t;
        int64_t y = a.y * w + ((int64_t)b.y - a.y) * t;
        if ((w != 0) && (x % w == 0) && (y % w == 0)) {
            vor_point_t p = {(int32_t)(x / w), (int32_t)(y / w)};
            uint32_t id;
            if (vor_insert(d, p, &id) == VOR_OK) {
                model.at[id] = p;
                model.live[id] = true;
                return gather_crossings(d) == crossings - 1u;
            }
        }
    }
    return false;
}

/* Two new constraints crossing at a lattice point p that is no site:
 * sites at p +- (1, 2) and p +- (2, -1), the segments between them. */
static void plant_crossing(vor_t *d, test_rng_t *rng, unsigned long *bad)
{
    for (unsigned tries = 0; tries < 20u; tries++) {
        vor_point_t p = random_point(rng, 0u);
        bool taken = false;
        for (uint32_t i = 0; i < d->site_count; i++) {
            taken = taken || (model.live[i] && (model.at[i].x == p.x) && (model.at[i].y == p.y));
        }
        if (taken || (model.constraints + 2u > CDT_CONSTRAINTS)) {
            continue;
        }
        vor_point_t ends[4] = {{p.x + 1, p.y + 2}, {p.x - 1, p.y - 2}, {p.x + 2, p.y - 1},
                               {p.x - 2, p.y + 1}};
        uint32_t id[4];
        for (unsigned k = 0; k < 4u; k++) {
            int err = vor_insert(d, ends[k], &id[k]);
            if (err == VOR_OK) {
                model.at[id[k]] = ends[k];
                model.live[id[k]] = true;
            }
        }
        for (unsigned k = 0; k < 4u; k += 2u) {
            *bad += (vor_constrain(d, id[k], id[k + 1u]) == VOR_OK) ? 0u : 1u;
            model.a[model.constraints] = id[k];
            model.b[model.constraints] = id[k + 1u];
            model.constraints++;
        }
        *bad += check_cdt(d);
        return;
    }
}

/* Removes about half of the constraints, each checked after; and a
 * segment that is no constraint is refused, nothing changed. */
static void unconstrain_random(vor_t *d, test_rng_t *rng, unsigned long *bad)
{
    for (uint32_t k = 0; k < model.constraints;) {
        if ((test_rng_u32(rng) & 1u) == 0u) {
            k++;
            continue;
        }
        uint32_t a = model.a[k];
        uint32_t b = model.b[k];
        int err = (test_rng_u32(rng) & 1u) ? vor_unconstrain(d, a, b) : vor_unconstrain(d, b, a);
        *bad += (err == VOR_OK) ? 0u : 1u;
        model.constraints--;
        model.a[k] = model.a[model.constraints];
        model.b[k] = model.b[model.constraints];
        *bad += check_cdt(d);
    }
    /* a segment between two sites that is no constraint's */
    for (uint32_t tries = 0; tries < 10u; tries++) {
        uint32_t a = test_rng_u32(rng) % d->site_count;
        uint32_t b = test_rng_u32(rng) % d->site_count;
        if (!model.live[a] || !model.live[b] || (a == b)) {
            continue;
        }
        bool covered = false; /* every piece under some constraint? */
        vor__hpoint_t pa;
        vor__hpoint_t pb;
        vor__hpoint_site(&pa, model.at[a]);
        vor__hpoint_site(&pb, model.at[b]);
        for (uint32_t k = 0; k < model.constraints; k++) {
            covered = covered || (on_constraint(&pa, k) || (a == model.a[k]) || (a == model.b[k]));
        }
        if (covered) {
            continue;
        }
        test_copy_bytes(saved_memory, memory, sizeof memory);
        *bad += (vor_unconstrain(d, a, b) == VOR_ERR_ARG) ? 0u : 1u;
        *bad += test_same_bytes(saved_memory, memory, sizeof memory) ? 0u : 1u;
    }
}

/* Inserts the points, noting them. */
static void insert_all(vor_t *d, const vor_point_t *p, unsigned n)
{
    for (unsigned i = 0; i < n; i++) {
        uint32_t id;
        if (vor_insert(d, p[i], &id) == VOR_OK) {
            model.at[id] = p[i];
            model.live[id] = true;
        }
    }
}

/* A new scene: the model cleared, d a fresh diagram of CDT_SITES sites
 * with the points inserted and noted (insert_all). */
static void fresh(vor_t *d, const vor_point_t *points, unsigned n)
{
    model_clear();
    (void)vor_init(d, arena, sizeof arena, CDT_SITES);
    insert_all(d, points, n);
}

/* The constraints attached to d with limits *l, in the memory they take
 * (VOR_CDT_BYTES of d's sites and *l): 0 when that succeeds, else 1. */
static unsigned long attach(vor_t *d, const vor_cdt_limits_t *l)
{
    size_t bytes = VOR_CDT_BYTES(d->max_sites, l->edges, l->crossings, l->cut);
    return (vor_cdt_attach(d, memory, bytes, l) == VOR_OK) ? 0u : 1u;
}

/* A fresh scene of the points (fresh) with constraints attached (attach):
 * 0 when they attached, else 1. */
static unsigned long scene(vor_t *d, const vor_point_t *points, unsigned n,
                           const vor_cdt_limits_t *l)
{
    fresh(d, points, n);
    return attach(d, l);
}

/* A fresh scene of n random sites of the kind (insert_random) with
 * constraints attached (attach): 0 when they attached, else 1. */
static unsigned long random_scene(vor_t *d, test_rng_t *rng, uint32_t n, unsigned kind,
                                  const vor_cdt_limits_t *l)
{
    fresh(d, NULL, 0);
    for (uint32_t i = 0; i < n; i++) {
        (void)insert_random(d, rng, kind);
    }
    return attach(d, l);
}

/* Random sites, random constraints (crossing each other), then sites
 * inserted (some on the constraints: they split them), removed and moved
 * (the ends of constrained edges refused, nothing changed), each step
 * checked. */
static void check_random(unsigned kind, uint64_t seed)
{
    test_rng_t rng;
    test_rng_seed(&rng, seed);
    unsigned long bad = 0;
    unsigned long kept_ends = 0;
    unsigned long crossings = 0;
    unsigned long takeovers = 0;
    for (unsigned round = 0; round < 3u; round++) {
        vor_t d;
        fresh(&d, NULL, 0);
        uint32_t n = 30u + (test_rng_u32(&rng) % 60u);
        for (uint32_t i = 0; i < n; i++) {
            (void)insert_random(&d, &rng, kind);
            if (i == n / 2u) { /* attached to a diagram half built */
                bad += attach(&d, &limits);
            }
        }
        bad += check_cdt(&d);
        constrain_random(&d, &rng, 6u + (test_rng_u32(&rng) % 10u), &bad);
        if (kind == 0u) { /* two constraints crossing at a lattice point */
            plant_crossing(&d, &rng, &bad);
        }
        if (round == 1u) { /* half of them removed again */
            unconstrain_random(&d, &rng, &bad);
        }
        crossings += gather_crossings(&d);
        for (uint32_t k = 0; k < 30u; k++) {
            uint32_t s = test_rng_u32(&rng) % d.site_count;
            unsigned op = test_rng_u32(&rng) % 3u;
            if ((op == 0u) && (kind == 0u) && (k % 2u == 0u)) {
                takeovers += insert_at_crossing(&d) ? 1u : 0u;
            } else if (op == 0u) {
                (void)insert_random(&d, &rng, kind);
            } else if (model.live[s]) {
                bool ends = ends_constraint(&d, s);
                vor_point_t to = random_point(&rng, kind);
                bool stays = (to.x == model.at[s].x) && (to.y == model.at[s].y);
                test_copy_bytes(saved_arena, arena, sizeof arena);
                test_copy_bytes(saved_memory, memory, sizeof memory);
                uint32_t twin;
                int err = (op == 1u) ? vor_remove(&d, s) : vor_move(&d, s, to, &twin);
                if (ends && !stays) {
                    bool unchanged = test_same_bytes(saved_arena, arena, sizeof arena) &&
                                     test_same_bytes(saved_memory, memory, sizeof memory);
                    bad += (((err == VOR_ERR_CONSTRAINED) || (err == VOR_ERR_DUPLICATE)) &&
                            unchanged)
                               ? 0u
                               : 1u;
                    kept_ends++;
                } else if (err == VOR_OK) {
                    model.live[s] = (op == 2u);
                    model.at[s] = (op == 2u) ? to : model.at[s];
                } else {
                    bad += (err == VOR_ERR_DUPLICATE) ? 0u : 1u;
                }
            } else {
                /* a free id: nothing to do */
            }
            bad += check_cdt(&d);
        }
    }
    test_printf("cdt random (%u): %lu crossing vertices, %lu ends kept, %lu taken by sites\n",
                kind, crossings, kept_ends, takeovers);
    CHECK(bad == 0, "cdt random (%u): %lu violations", kind, bad);
    CHECK(crossings > 0u && kept_ends > 0u && ((kind != 0u) || (takeovers > 0u)),
          "cdt random (%u): crossings %lu, ends kept %lu, taken %lu", kind, crossings, kept_ends,
          takeovers);
}

/* The calls' documented errors, each leaving everything as it was. */
static void check_errors(void)
{
    vor_t d;
    fresh(&d, NULL, 0);
    vor_cdt_limits_t small = {4, 1, 4};
    vor_cdt_limits_t none = {0, 1, 4};
    CHECK(vor_constrain(&d, 0, 1) == VOR_ERR_ARG, "constrain without memory");
    CHECK(vor_cdt_attach(NULL, memory, sizeof memory, &small) == VOR_ERR_ARG, "attach to NULL");
    CHECK(vor_cdt_attach(&d, NULL, sizeof memory, &small) == VOR_ERR_ARG, "attach NULL memory");
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, NULL) == VOR_ERR_ARG, "attach no limits");
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, &none) == VOR_ERR_ARG, "attach no edges");
    CHECK(vor_cdt_attach(&d, memory + 1, sizeof memory - 1u, &small) == VOR_ERR_ALIGN,
          "attach misaligned");
    CHECK(vor_cdt_attach(&d, memory, VOR_CDT_BYTES(CDT_SITES, 4, 1, 4) - 1u, &small) ==
              VOR_ERR_NOMEM,
          "attach one byte short");
    CHECK(d.cdt == NULL, "a failed attach attached");
    /* a square with its centre, and two sites across its diagonals */
    static const vor_point_t square[] = {{0, 0},   {100, 0}, {100, 100}, {0, 100},
                                         {50, 50}, {20, 70}, {90, 30}};
    insert_all(&d, square, 7);
    /* a cut of no triangle: only the edges there are can be constrained */
    vor_cdt_limits_t uncut = {40, 4, 0};
    CHECK(vor_cdt_attach(&d, memory, VOR_CDT_BYTES(CDT_SITES, 40, 4, 0), &uncut) == VOR_OK,
          "attach with no cut");
    CHECK(vor_constrain(&d, 0, 99) == VOR_ERR_ARG, "constrain a free id");
    CHECK(vor_constrain(NULL, 0, 1) == VOR_ERR_ARG, "constrain NULL");
    CHECK(vor_constrain(&d, 2, 2) == VOR_OK, "constrain a site to itself");
    test_copy_bytes(saved_memory, memory, sizeof memory);
    unsigned too_long = 0;
    for (uint32_t a = 0; a < 7u; a++) {
        for (uint32_t b = a + 1u; b < 7u; b++) {
            int err = vor_constrain(&d, a, b);
            too_long += (err == VOR_ERR_NOMEM) ? 1u : 0u;
            CHECK((err == VOR_ERR_NOMEM) || (err == VOR_OK), "a cut too long: %d", err);
            CHECK(test_same_bytes(saved_memory, memory, sizeof memory) || (err == VOR_OK),
                  "a failing call changed the memory");
            test_copy_bytes(saved_memory, memory, sizeof memory);
        }
    }
    CHECK(too_long > 0u, "no segment crossed a triangle");
    /* room for 5 edges and one crossing */
    vor_cdt_limits_t few = {5, 1, (2u * (CDT_SITES + 1u)) + 2u};
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, &few) == VOR_OK, "attach again");
    CHECK(vor_constrain(&d, 0, 2) == VOR_OK, "constrain 0-2: 0-4, 4-2");
    CHECK(vor_constrain(&d, 1, 3) == VOR_OK, "constrain 1-3: meets 0-2 at the site 4");
    model.a[0] = 0;
    model.b[0] = 2;
    model.a[1] = 1;
    model.b[1] = 3;
    model.constraints = 2;
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation");
    test_copy_bytes(saved_memory, memory, sizeof memory);
    test_copy_bytes(saved_arena, arena, sizeof arena);
    /* 5-6 crosses 0-4 and 4-1 off any site: two crossings, 4 more edges */
    CHECK(vor_constrain(&d, 5, 6) == VOR_ERR_NOMEM, "two crossings where one fits");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory), "an overflow changed the memory");
    CHECK(vor_remove(&d, 4) == VOR_ERR_CONSTRAINED, "remove a constrained site");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory), "a refused removal changed it");
    vor_point_t away = {30, 60};
    CHECK(vor_move(&d, 0, away, NULL) == VOR_ERR_CONSTRAINED, "move a constrained site");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory) &&
              test_same_bytes(saved_arena, arena, sizeof arena),
          "a refused move changed the memory");
    /* a site landing on a constrained edge when the table is full */
    CHECK(vor_constrain(&d, 5, 0) == VOR_OK, "a fifth edge");
    model.a[2] = 5;
    model.b[2] = 0;
    model.constraints = 3;
    test_copy_bytes(saved_memory, memory, sizeof memory);
    test_copy_bytes(saved_arena, arena, sizeof arena);
    uint32_t id;
    vor_point_t on_edge = {25, 25};
    CHECK(vor_insert(&d, on_edge, &id) == VOR_ERR_NOMEM, "a split in a full table");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory) &&
              test_same_bytes(saved_arena, arena, sizeof arena),
          "a refused insertion changed the memory");
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation");
    /* a full table still takes a site off every constrained edge; the
     * change ends an inside iteration begun before it */
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    CHECK(vor_cdt_domain(&d) == VOR_OK && vor_cdt_inside_begin(&it, &d) == VOR_OK, "a domain");
    vor_point_t off_edges = {60, 20};
    insert_all(&d, &off_edges, 1);
    CHECK(model.live[7], "a site off the constrained edges in a full table");
    CHECK(vor_cdt_triangles_next(&it, ids) == 0, "inside triangles after a change");
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation");
    /* a free site moved onto a constrained edge of the full table */
    test_copy_bytes(saved_memory, memory, sizeof memory);
    test_copy_bytes(saved_arena, arena, sizeof arena);
    CHECK(vor_move(&d, 6, on_edge, NULL) == VOR_ERR_NOMEM &&
              test_same_bytes(saved_memory, memory, sizeof memory) &&
              test_same_bytes(saved_arena, arena, sizeof arena),
          "a move onto a constrained edge of a full table");
    /* a build starts the constrained triangulation again, unconstrained:
     * either builder, and a build of one site */
    CHECK(vor_build(&d, square, 7, NULL, NULL) == VOR_OK, "build");
    model.live[7] = false;
    model.constraints = 0;
    CHECK(!ends_constraint(&d, 4), "constraints after a build");
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation after a build");
    CHECK(vor_constrain(&d, 5, 6) == VOR_OK && vor_build_dc(&d, square, 7, NULL, NULL) == VOR_OK,
          "constrain, then build by divide and conquer");
    model.constraints = 0;
    CHECK(!ends_constraint(&d, 5) && check_cdt(&d) == 0u, "the constraints after vor_build_dc");
    CHECK(vor_build(&d, square, 1, NULL, NULL) == VOR_OK, "build one site");
    for (uint32_t i = 1; i < 7u; i++) {
        model.live[i] = false;
    }
    CHECK(d.cdt->mesh.vertex_count == 1u && check_cdt(&d) == 0u, "the constrained mesh of one site");
}

/* Constraints along the lines of a grid, through its sites, overlapping
 * and repeated, and its two diagonals crossing between sites. */
static void check_grid_lines(void)
{
    vor_t d;
    unsigned long bad = 0;
    fresh(&d, NULL, 0);
    for (int32_t y = 0; y < 8; y++) {
        for (int32_t x = 0; x < 8; x++) {
            vor_point_t p = {x * 3, y * 3};
            insert_all(&d, &p, 1);
        }
    }
    bad += attach(&d, &limits);
    static const uint32_t lines[][2] = {{0, 7},  {8, 15},  {0, 56},  {7, 63}, {0, 63},
                                        {2, 5},  {1, 6},   {56, 7},  {24, 31}, {27, 30},
                                        {3, 59}, {0, 63},  {16, 47}, {40, 23}};
    for (unsigned k = 0; k < sizeof lines / sizeof lines[0]; k++) {
        bad += (vor_constrain(&d, lines[k][0], lines[k][1]) == VOR_OK) ? 0u : 1u;
        model.a[model.constraints] = lines[k][0];
        model.b[model.constraints] = lines[k][1];
        model.constraints++;
        bad += check_cdt(&d);
    }
    uint32_t crossings = gather_crossings(&d);
    CHECK(bad == 0 && crossings > 0u, "cdt grid lines: %lu wrong, %u crossings", bad,
          (unsigned)crossings);
}

/* Many constraints through one point: a star of segments through the
 * centre of a ring, which is no site: one crossing vertex. */
static void check_star(void)
{
    vor_t d;
    unsigned long bad = 0;
    fresh(&d, NULL, 0);
    /* 12 lattice points of the circle of radius 5 k, around (1, 1) / 2 */
    static const int32_t ring[12][2] = {{5, 0},  {4, 3},  {3, 4},  {0, 5},  {-3, 4}, {-4, 3},
                                        {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    for (unsigned i = 0; i < 12u; i++) {
        vor_point_t p = {2 * 1000 * ring[i][0] + 1, 2 * 1000 * ring[i][1] + 1};
        insert_all(&d, &p, 1);
    }
    bad += attach(&d, &limits);
    for (uint32_t i = 0; i < 6u; i++) { /* opposite points: all through (1, 1) */
        bad += (vor_constrain(&d, i, i + 6u) == VOR_OK) ? 0u : 1u;
        model.a[model.constraints] = i;
        model.b[model.constraints] = i + 6u;
        model.constraints++;
        bad += check_cdt(&d);
    }
    uint32_t crossings = gather_crossings(&d);
    CHECK(bad == 0 && crossings == 1u, "cdt star: %lu wrong, %u crossings (1 expected)", bad,
          (unsigned)crossings);
    /* a site at the crossing takes its place, and ends 12 constrained edges */
    vor_point_t centre = {1, 1};
    insert_all(&d, &centre, 1);
    CHECK(gather_crossings(&d) == 0u && check_cdt(&d) == 0u, "a site at the crossing");
    CHECK(vor_remove(&d, 12) == VOR_ERR_CONSTRAINED, "the centre ends constraints");
}

/* How many of the test's constraints hold both u and v (ends included):
 * the constraints through edge u-v. */
static uint32_t constraints_through(const vor_t *d, uint32_t u, uint32_t v)
{
    vor__hpoint_t hu;
    vor__hpoint_t hv;
    (void)vertex_of(d, u, &hu);
    (void)vertex_of(d, v, &hv);
    uint32_t n = 0;
    for (uint32_t k = 0; k < model.constraints; k++) {
        bool eu = (u == model.a[k]) || (u == model.b[k]) || on_constraint(&hu, k);
        bool ev = (v == model.a[k]) || (v == model.b[k]) || on_constraint(&hv, k);
        n += (eu && ev) ? 1u : 0u;
    }
    return n;
}

/* The domain's triangles against the even-odd rule, locally: across every
 * edge the inside flips exactly when an odd number of the test's
 * constraints run along it, and beside the hull's outside it is that
 * number's parity (closed polygons make the rule path-independent). */
static unsigned long check_domain(const vor_t *d, uint32_t *inside_count)
{
    unsigned long bad = 0;
    static uint64_t inside_keys[2u * CDT_VERTICES];
    uint32_t ni = 0;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    bad += (vor_cdt_inside_begin(&it, d) == VOR_OK) ? 0u : 1u;
    while ((vor_cdt_triangles_next(&it, ids) == 1) && (ni < 2u * CDT_VERTICES)) {
        /* a triangle by its sorted corners */
        uint32_t lo = ids[0] < ids[1] ? ids[0] : ids[1];
        lo = lo < ids[2] ? lo : ids[2];
        uint32_t hi = ids[0] > ids[1] ? ids[0] : ids[1];
        hi = hi > ids[2] ? hi : ids[2];
        uint32_t mid = ids[0] + ids[1] + ids[2] - lo - hi;
        inside_keys[ni++] = ((uint64_t)lo << 42) | ((uint64_t)mid << 21) | hi;
    }
    *inside_count = ni;
    sort_keys(inside_keys, ni);
    uint32_t nh = 0;
    (void)vor_cdt_triangles_begin(&it, d);
    while (vor_cdt_triangles_next(&it, ids) == 1) {
        uint32_t lo = ids[0] < ids[1] ? ids[0] : ids[1];
        lo = lo < ids[2] ? lo : ids[2];
        uint32_t hi = ids[0] > ids[1] ? ids[0] : ids[1];
        hi = hi > ids[2] ? hi : ids[2];
        uint32_t mid = ids[0] + ids[1] + ids[2] - lo - hi;
        uint32_t in = has_key(inside_keys, ni, ((uint64_t)lo << 42) | ((uint64_t)mid << 21) | hi) ? 1u : 0u;
        for (unsigned k = 0; (k < 3u) && (nh < sizeof halves / sizeof halves[0]); k++) {
            halves[nh].key = edge_key(ids[(k + 1u) % 3u], ids[(k + 2u) % 3u]);
            halves[nh].apex = in; /* here: the triangle's inside bit */
            halves[nh].forward = 0;
            nh++;
        }
    }
    sort_halves(halves, nh);
    for (uint32_t i = 0; i < nh;) {
        uint32_t j = i + 1u;
        while ((j < nh) && (halves[j].key == halves[i].key)) {
            j++;
        }
        uint32_t odd = constraints_through(d, (uint32_t)(halves[i].key >> 32),
                                           (uint32_t)halves[i].key) & 1u;
        uint32_t other = (j - i == 2u) ? halves[i + 1u].apex : 0u; /* the outside */
        bad += ((halves[i].apex ^ other) == odd) ? 0u : 1u;
        i = j;
    }
    return bad;
}

/* Adds constraint a-b to the model and the diagram. */
static unsigned long add_constraint(vor_t *d, uint32_t a, uint32_t b)
{
    if (model.constraints == CDT_CONSTRAINTS) {
        return 1; /* the test's own table is full */
    }
    model.a[model.constraints] = a;
    model.b[model.constraints] = b;
    model.constraints++;
    return (vor_constrain(d, a, b) == VOR_OK) ? 0u : 1u;
}

/* Domains: nested squares (a hole with an island), overlapping squares
 * (their crossings become vertices, the overlap is outside by parity), a
 * square traced twice (outside again), and random star-shaped polygons,
 * with sites inside and outside them. */
static void check_domains(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 25);
    unsigned long bad = 0;
    uint32_t inside = 0;
    for (unsigned round = 0; round < 6u; round++) {
        vor_t d;
        fresh(&d, NULL, 0);
        /* 4 squares: (0..90), (20..70), (35..55), and (60..110) x (60..110) */
        static const int32_t squares[4][2] = {{0, 90}, {20, 70}, {35, 55}, {60, 110}};
        uint32_t corner[4][4];
        for (unsigned q = 0; q < 4u; q++) {
            int32_t lo = squares[q][0];
            int32_t hi = squares[q][1];
            vor_point_t c4[4] = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
            for (unsigned k = 0; k < 4u; k++) {
                (void)vor_insert(&d, c4[k], &corner[q][k]);
                model.at[corner[q][k]] = c4[k];
                model.live[corner[q][k]] = true;
            }
        }
        for (uint32_t i = 0; i < 30u; i++) {
            (void)insert_random(&d, &rng, 1u);
            vor_point_t p = {test_rng_range(&rng, -10, 120), test_rng_range(&rng, -10, 120)};
            insert_all(&d, &p, 1);
        }
        bad += attach(&d, &limits);
        unsigned count = (round % 2u == 0u) ? 4u : 3u;
        for (unsigned q = 0; q < count; q++) {
            for (unsigned k = 0; k < 4u; k++) {
                bad += add_constraint(&d, corner[q][k], corner[q][(k + 1u) & 3u]);
            }
        }
        if (round >= 2u) { /* the first square once more: its inside flips */
            for (unsigned k = 0; k < 4u; k++) {
                bad += add_constraint(&d, corner[0][k], corner[0][(k + 1u) & 3u]);
            }
        }
        if (round >= 4u) { /* a random star-shaped polygon around a site */
            uint32_t ring[8];
            uint32_t n = 0;
            for (uint32_t tries = 0; (tries < 50u) && (n < 8u); tries++) {
                uint32_t s = test_rng_u32(&rng) % d.site_count;
                bool fresh = model.live[s];
                for (uint32_t k = 0; k < n; k++) {
                    fresh = fresh && (ring[k] != s);
                }
                if (fresh) {
                    ring[n++] = s;
                }
            }
            /* sort by angle around the first: half-plane, then orientation */
            vor_point_t o = model.at[ring[0]];
            for (uint32_t i = 2; i < n; i++) {
                for (uint32_t j = i; j > 1u; j--) {
                    vor_point_t p = model.at[ring[j - 1u]];
                    vor_point_t q = model.at[ring[j]];
                    bool hp = (p.y > o.y) || ((p.y == o.y) && (p.x > o.x));
                    bool hq = (q.y > o.y) || ((q.y == o.y) && (q.x > o.x));
                    if ((hp == hq) ? (vor_orient2d(o, p, q) >= 0) : hp) {
                        break;
                    }
                    uint32_t t = ring[j];
                    ring[j] = ring[j - 1u];
                    ring[j - 1u] = t;
                }
            }
            for (uint32_t i = 1; i < n; i++) {
                bad += add_constraint(&d, ring[i], ring[(i + 1u < n) ? (i + 1u) : 1u]);
            }
        }
        bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
        uint32_t in;
        bad += check_domain(&d, &in);
        inside += in;
        bad += check_cdt(&d);
        /* a change clears the domain */
        (void)insert_random(&d, &rng, 1u);
        vor_cdt_triangle_iter_t it;
        bad += (vor_cdt_inside_begin(&it, &d) == VOR_ERR_ARG) ? 0u : 1u;
    }
    test_printf("cdt domains: %u inside triangles\n", (unsigned)inside);
    CHECK(bad == 0 && inside > 0u, "cdt domains: %lu wrong", bad);
    CHECK(vor_cdt_domain(NULL) == VOR_ERR_ARG, "vor_cdt_domain(NULL)");
}

/* A vertex every triangle of which the constraint crosses hangs into the
 * cavity from the chain (a spike): V = (0, -1) below the segment, its
 * neighbours W far below and sites above. */
static void check_spike(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{-100, 0}, {100, 0}, {0, -1},  {0, -50}, {-20, 5},
                                    {0, 5},    {20, 5},  {-60, 30}, {60, 30}, {0, 60},
                                    {-70, -40}, {70, -40}};
    bad += scene(&d, p, sizeof p / sizeof p[0], &limits);
    bad += add_constraint(&d, 0, 1);
    bad += check_cdt(&d);
    /* and a second one under it, through the spike's base */
    bad += add_constraint(&d, 10, 11);
    bad += check_cdt(&d);
    CHECK(bad == 0, "cdt spike: %lu wrong", bad);
}

/* Builds the small-scratch scenario with limits *l: a square and its
 * midline constrained among few sites, then sites crowding the midline. */
static unsigned long crowd(vor_t *d, const vor_cdt_limits_t *l)
{
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    unsigned long bad = 0;
    static const vor_point_t frame[] = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}, {500, 20},
                                        {500, 980}};
    bad += scene(d, frame, 6, l);
    for (unsigned k = 0; k < 4u; k++) {
        bad += add_constraint(d, k, (k + 1u) & 3u);
    }
    bad += add_constraint(d, 4, 5);
    for (uint32_t i = 0; i < 80u; i++) {
        vor_point_t q = {test_rng_range(&rng, 470, 530), test_rng_range(&rng, 30, 970)};
        insert_all(d, &q, 1);
    }
    return bad + check_cdt(d);
}

/* The domain's inside triangles, as sorted keys; their number. */
static uint32_t inside_keys_of(const vor_t *d, uint64_t *keys)
{
    uint32_t n = 0;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    (void)vor_cdt_inside_begin(&it, d);
    while ((vor_cdt_triangles_next(&it, ids) == 1) && (n < CDT_EDGES)) {
        unsigned lo = (ids[1] < ids[0]) ? 1u : 0u;
        lo = (ids[2] < ids[lo]) ? 2u : lo;
        keys[n++] = ((uint64_t)ids[lo] << 42) | ((uint64_t)ids[(lo + 1u) % 3u] << 21) |
                    ids[(lo + 2u) % 3u];
    }
    sort_keys(keys, n);
    return n;
}

/* Small scratch space: the domain's flood and Lawson's flips overflow
 * their stacks and finish by sweeps, with the results of a large one
 * (the same scenario built twice). Removing the crowded midline flips
 * many edges. */
static void check_small_scratch(void)
{
    unsigned long bad = 0;
    vor_t d;
    static const vor_cdt_limits_t large = {3u * (CDT_SITES + 8u), 8, 2u * (CDT_SITES + 8u) + 2u};
    static const vor_cdt_limits_t small = {3u * (CDT_SITES + 8u), 8, 6};
    static uint64_t first[CDT_EDGES]; /* check_cdt uses the other key arrays */
    static uint64_t second[CDT_EDGES];
    bad += crowd(&d, &large);
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    uint32_t n = inside_keys_of(&d, first);
    bad += crowd(&d, &small);
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    bad += (inside_keys_of(&d, second) == n) ? 0u : 1u;
    for (uint32_t i = 0; i < n; i++) {
        bad += (second[i] == first[i]) ? 0u : 1u;
    }
    bad += (n > 0u) ? 0u : 1u;
    /* the midline off: its crowd flips back to Delaunay */
    bad += (vor_unconstrain(&d, 5, 4) == VOR_OK) ? 0u : 1u;
    model.constraints--;
    bad += check_cdt(&d);
    CHECK(bad == 0, "cdt small scratch: %lu wrong", bad);
}

/* Stacks that overflow at once: 70 sites in convex position (70 triangles
 * at infinity seed the domain's flood) and a constraint through 50
 * collinear sites (49 pieces freed at once), with a scratch of 39 pairs. */
/* The bytes past the constraint memory a test gives (memory[from ..)):
 * filled before the attach, and counted afterwards if any changed, as
 * nothing may be written past the size given. */
static void canary_fill(size_t from)
{
    for (size_t i = from; i < sizeof memory; i++) {
        memory[i] = 0xA5u;
    }
}

static unsigned long canary_faults(size_t from)
{
    unsigned long bad = 0;
    for (size_t i = from; i < sizeof memory; i++) {
        bad += (memory[i] == 0xA5u) ? 0u : 1u;
    }
    return bad;
}

static void check_overflow(void)
{
    unsigned long bad = 0;
    vor_t d;
    fresh(&d, NULL, 0);
    for (int32_t i = 0; i < 70; i++) { /* on the parabola y = x^2 / 64 */
        vor_point_t p = {(i - 35) * 64, (i - 35) * (i - 35) * 64};
        insert_all(&d, &p, 1);
    }
    for (int32_t i = 0; i < 50; i++) {
        vor_point_t p = {-1225 + (i * 50), 30000};
        insert_all(&d, &p, 1);
    }
    static const vor_cdt_limits_t small = {3u * (CDT_SITES + 8u), 8, 2};
    const size_t bytes = VOR_CDT_BYTES(CDT_SITES, small.edges, 8, 2);
    canary_fill(bytes);
    bad += attach(&d, &small);
    for (unsigned k = 0; k < 70u; k++) { /* the hull, closed */
        bad += add_constraint(&d, k, (k + 1u) % 70u);
    }
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    uint32_t in;
    bad += check_domain(&d, &in);
    bad += add_constraint(&d, 70, 119); /* along the collinear sites' edges */
    bad += check_cdt(&d);
    bad += (vor_unconstrain(&d, 119, 70) == VOR_OK) ? 0u : 1u;
    model.constraints--;
    bad += check_cdt(&d) + canary_faults(bytes);
    CHECK(bad == 0 && in > 0u, "cdt overflow: %lu wrong", bad);
}

/* The edge table under churn: a small table (6 edges, 12 entries) takes
 * and gives back many different edges, so that its probes wrap around
 * and its removals shift entries back across the end. */
static void check_edge_table(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 31);
    unsigned long bad = 0;
    unsigned long kept = 0;
    vor_t d;
    static const vor_cdt_limits_t few = {6, 8, (2u * (CDT_SITES + 8u)) + 2u};
    bad += random_scene(&d, &rng, 60u, 1u, &few);
    for (uint32_t round = 0; round < 300u; round++) {
        /* an edge of the triangulation, constrained and let go again */
        vor_cdt_triangle_iter_t it;
        uint32_t ids[3];
        (void)vor_cdt_triangles_begin(&it, &d);
        uint32_t skip = test_rng_u32(&rng) % 40u;
        while ((vor_cdt_triangles_next(&it, ids) == 1) && (skip > 0u)) {
            skip--;
        }
        uint32_t k = test_rng_u32(&rng) % 3u;
        uint32_t a = ids[k];
        uint32_t b = ids[(k + 1u) % 3u];
        int err = vor_constrain(&d, a, b);
        if (err == VOR_OK) {
            model.a[model.constraints] = a;
            model.b[model.constraints] = b;
            model.constraints++;
            kept++;
        } else {
            bad += (err == VOR_ERR_NOMEM) ? 0u : 1u;
        }
        if ((model.constraints > 0u) && ((err != VOR_OK) || ((test_rng_u32(&rng) & 1u) != 0u))) {
            uint32_t j = test_rng_u32(&rng) % model.constraints;
            bad += (vor_unconstrain(&d, model.a[j], model.b[j]) == VOR_OK) ? 0u : 1u;
            model.constraints--;
            model.a[j] = model.a[model.constraints];
            model.b[j] = model.b[model.constraints];
        }
        if (round % 25u == 0u) {
            bad += check_cdt(&d);
        }
    }
    bad += check_cdt(&d);
    CHECK(bad == 0 && kept > 100u, "cdt edge table: %lu wrong, %lu kept", bad, kept);
}

/* Tables filled to their last entry: nine crossings in a table of nine
 * (the search for a free crossing id runs to the table's end), one
 * needing two more refused with nothing changed, and the three a removed
 * constraint frees used again. */
static void check_full_tables(void)
{
    vor_t d;
    unsigned long bad = 0;
    /* three horizontal and three vertical segments, sites 2k and 2k + 1 */
    static const vor_point_t ends[] = {{0, 10}, {100, 10}, {0, 50}, {100, 50}, {0, 90},  {100, 90},
                                       {10, 0}, {10, 100}, {50, 0}, {50, 100}, {90, 0}, {90, 100}};
    static const vor_cdt_limits_t nine = {60, 9, (2u * (CDT_SITES + 9u)) + 2u};
    bad += scene(&d, ends, 12, &nine);
    for (uint32_t k = 0; k < 6u; k++) {
        bad += add_constraint(&d, 2u * k, (2u * k) + 1u);
    }
    bad += check_cdt(&d);
    bad += (gather_crossings(&d) == 9u) ? 0u : 1u;
    /* (0, 10)-(100, 90) passes the crossing (50, 50) and makes two new ones */
    test_copy_bytes(saved_memory, memory, sizeof memory);
    test_copy_bytes(saved_arena, arena, sizeof arena);
    bad += (vor_constrain(&d, 0, 5) == VOR_ERR_NOMEM) ? 0u : 1u;
    bad += (test_same_bytes(saved_memory, memory, sizeof memory) &&
            test_same_bytes(saved_arena, arena, sizeof arena))
               ? 0u
               : 1u;
    /* y = 50 gone: its three crossings free, the diagonal takes three */
    bad += (vor_unconstrain(&d, 3, 2) == VOR_OK) ? 0u : 1u;
    model.a[1] = model.a[5];
    model.b[1] = model.b[5];
    model.constraints = 5;
    bad += (gather_crossings(&d) == 6u) ? 0u : 1u;
    bad += add_constraint(&d, 0, 5);
    bad += check_cdt(&d);
    bad += (gather_crossings(&d) == 9u) ? 0u : 1u;
    /* a site between crossings (50, 10) and (50, 50) on x = 50 */
    vor_point_t between_crossings = {50, 30};
    insert_all(&d, &between_crossings, 1);
    bad += check_cdt(&d);
    CHECK(bad == 0, "cdt full tables: %lu wrong", bad);
}

/* Lawson's flips past their stack: a constraint with rows of sites just
 * above and below it, inserted after it, so that the triangles on either
 * side are slivers; removed with a stack of 39 pairs, its Delaunay edges
 * across the line take far more flips than fit, and sweeps finish. */
static void check_lawson_sweeps(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t line[] = {{0, 0}, {10000, 0}, {5000, 3000}}; /* 0-1 an edge */
    fresh(&d, line, 3);
    static const vor_cdt_limits_t small = {3u * (CDT_SITES + 8u), 8, 2};
    const size_t bytes = VOR_CDT_BYTES(CDT_SITES, small.edges, 8, 2);
    canary_fill(bytes);
    bad += attach(&d, &small);
    bad += add_constraint(&d, 0, 1);
    for (int32_t i = 0; i < 100; i++) { /* alternately 3 above and 5 below */
        vor_point_t q = {37 + (i * 97), ((i & 1) != 0) ? 3 : -5};
        insert_all(&d, &q, 1);
    }
    bad += check_cdt(&d);
    bad += (vor_unconstrain(&d, 1, 0) == VOR_OK) ? 0u : 1u;
    model.constraints = 0;
    bad += check_cdt(&d) + canary_faults(bytes);
    CHECK(bad == 0, "cdt lawson sweeps: %lu wrong", bad);
}

/* The domain's flood past its stack: a constrained square filled with 110
 * random sites, flooded with a stack of 26 pairs (a cut of 0), which
 * loses triangles whose neighbours only the sweeps then reach (seed 28
 * does, often), and with a large one: the same inside either way. */
static void check_flood_sweeps(void)
{
    unsigned long bad = 0;
    vor_t d;
    static uint64_t first[CDT_EDGES];
    static uint64_t second[CDT_EDGES];
    static const vor_cdt_limits_t small = {3u * (CDT_SITES + 8u), 8, 0};
    static const vor_cdt_limits_t large = {3u * (CDT_SITES + 8u), 8, (2u * (CDT_SITES + 8u)) + 2u};
    uint32_t n[2] = {0, 0};
    for (unsigned round = 0; round < 2u; round++) {
        const vor_cdt_limits_t *l = (round == 0u) ? &large : &small;
        test_rng_t rng;
        test_rng_seed(&rng, 28);
        static const vor_point_t square[] = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
        fresh(&d, square, 4);
        const size_t bytes = VOR_CDT_BYTES(CDT_SITES, l->edges, l->crossings, l->cut);
        canary_fill(bytes);
        bad += attach(&d, l);
        for (uint32_t k = 0; k < 4u; k++) {
            bad += add_constraint(&d, k, (k + 1u) % 4u);
        }
        for (uint32_t i = 0; i < 110u; i++) {
            vor_point_t q = {test_rng_range(&rng, 1, 999), test_rng_range(&rng, 1, 999)};
            insert_all(&d, &q, 1);
        }
        bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
        uint32_t in;
        bad += check_domain(&d, &in) + canary_faults(bytes);
        n[round] = inside_keys_of(&d, (round == 0u) ? first : second);
    }
    bad += ((n[0] == n[1]) && (n[0] > 0u)) ? 0u : 1u;
    for (uint32_t i = 0; (i < n[0]) && (i < n[1]); i++) {
        bad += (first[i] == second[i]) ? 0u : 1u;
    }
    CHECK(bad == 0, "cdt flood sweeps: %lu wrong", bad);
}

/* Sites on constrained hull edges: a square with its sides constrained
 * corner to corner through three sites each, then a site inside each
 * side's pieces; the perturbed site may lie outside the hull, where the
 * split is found from the triangles at infinity along the side. */
static void check_hull_splits(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t corners[] = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
    fresh(&d, corners, 4);
    for (int32_t k = 1; k < 4; k++) { /* three sites on each side */
        vor_point_t side[] = {{250 * k, 0}, {1000, 250 * k}, {1000 - (250 * k), 1000}, {0, 1000 - (250 * k)}};
        insert_all(&d, side, 4);
    }
    bad += attach(&d, &limits);
    for (uint32_t k = 0; k < 4u; k++) {
        bad += add_constraint(&d, k, (k + 1u) & 3u);
    }
    bad += check_cdt(&d);
    for (int32_t k = 0; k < 4; k++) { /* one site in a piece of each side */
        int32_t at = 100 + (250 * k);
        vor_point_t side[] = {{at, 0}, {1000, at}, {1000 - at, 1000}, {0, 1000 - at}};
        for (unsigned j = 0; j < 4u; j++) {
            insert_all(&d, &side[j], 1);
            bad += check_cdt(&d);
        }
    }
    CHECK(bad == 0, "cdt hull splits: %lu wrong", bad);
}

/* A tangle: random constraints among few sites, crossing each other many
 * times, then all removed in random order, each step checked; crossing
 * vertices go while their neighbours are crossings too. */
static void check_tangle(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 41);
    unsigned long bad = 0;
    unsigned long crossings = 0;
    for (unsigned round = 0; round < 4u; round++) {
        vor_t d;
        bad += random_scene(&d, &rng, 30u, 1u, &limits);
        constrain_random(&d, &rng, 16u, &bad);
        crossings += gather_crossings(&d);
        while (model.constraints > 0u) {
            uint32_t k = test_rng_u32(&rng) % model.constraints;
            bad += (vor_unconstrain(&d, model.a[k], model.b[k]) == VOR_OK) ? 0u : 1u;
            model.constraints--;
            model.a[k] = model.a[model.constraints];
            model.b[k] = model.b[model.constraints];
            bad += check_cdt(&d);
        }
        bad += (gather_crossings(&d) == 0u) ? 0u : 1u;
    }
    test_printf("cdt tangle: %lu crossing vertices\n", crossings);
    CHECK(bad == 0 && crossings > 40u, "cdt tangle: %lu wrong, %lu crossings", bad, crossings);
}

/* Nesting levels past the cap: a triangle whose sides carry k
 * constraints each is inside when k is odd, and levels beyond 126 count
 * as 126 (vor_cdt.h): so for k = 125 inside, for 126 and 127 not. */
static void check_deep_nesting(void)
{
    unsigned long bad = 0;
    vor_t d;
    static const vor_point_t corners[] = {{0, 0}, {90, 10}, {30, 70}};
    for (uint32_t k = 125; k <= 127u; k++) {
        bad += scene(&d, corners, 3, &limits);
        for (uint32_t j = 0; j < k; j++) {
            for (uint32_t side = 0; side < 3u; side++) {
                bad += (vor_constrain(&d, side, (side + 1u) % 3u) == VOR_OK) ? 0u : 1u;
            }
        }
        bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
        vor_cdt_triangle_iter_t it;
        uint32_t ids[3];
        uint32_t inside = 0;
        (void)vor_cdt_inside_begin(&it, &d);
        while (vor_cdt_triangles_next(&it, ids) == 1) {
            inside++;
        }
        bad += (inside == ((k == 125u) ? 1u : 0u)) ? 0u : 1u;
    }
    CHECK(bad == 0, "cdt deep nesting: %lu wrong", bad);
}

/* The calls' argument checks. */
static void check_arguments(void)
{
    vor_t d;
    fresh(&d, NULL, 0);
    vor_cdt_triangle_iter_t it;
    vor_cdt_edge_iter_t e;
    uint32_t ids[3];
    uint32_t a;
    uint32_t b;
    uint32_t s[4];
    CHECK(vor_cdt_triangles_begin(NULL, &d) == VOR_ERR_ARG, "triangles_begin NULL");
    CHECK(vor_cdt_triangles_begin(&it, &d) == VOR_ERR_ARG, "triangles_begin without memory");
    CHECK(vor_cdt_triangles_next(&it, ids) == 0 && vor_cdt_triangles_next(NULL, ids) == 0,
          "triangles_next of a closed iterator");
    CHECK(vor_cdt_inside_begin(&it, &d) == VOR_ERR_ARG, "inside_begin without memory");
    CHECK(vor_cdt_edges_begin(NULL, &d) == VOR_ERR_ARG && vor_cdt_edges_begin(&e, &d) == VOR_ERR_ARG,
          "edges_begin NULL or without memory");
    CHECK(vor_cdt_edges_next(&e, &a, &b) == 0 && vor_cdt_edges_next(NULL, &a, &b) == 0,
          "edges_next of a closed iterator");
    CHECK(vor_cdt_crossing(&d, 0, s) == VOR_ERR_ARG && vor_cdt_crossing(NULL, 0, s) == VOR_ERR_ARG,
          "crossing without memory");
    CHECK(vor_unconstrain(&d, 0, 1) == VOR_ERR_ARG && vor_unconstrain(NULL, 0, 1) == VOR_ERR_ARG,
          "unconstrain without memory");
    CHECK(vor_cdt_domain(&d) == VOR_ERR_ARG, "domain without memory");
    /* limits beyond use, on an empty diagram */
    vor_cdt_limits_t too_many = {8, VOR_MAX_SITES, 8};
    vor_cdt_limits_t many_edges = {(3u * (CDT_SITES + 2u)) + 1u, 2, 8};
    vor_cdt_limits_t long_cut = {8, 2, (2u * (CDT_SITES + 2u)) + 3u};
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, &too_many) == VOR_ERR_ARG &&
              vor_cdt_attach(&d, memory, sizeof memory, &many_edges) == VOR_ERR_ARG &&
              vor_cdt_attach(&d, memory, sizeof memory, &long_cut) == VOR_ERR_ARG,
          "attach with limits beyond use");
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, &limits) == VOR_OK, "attach to no site");
    /* a diagram of one site: constraint memory of no triangle slot */
    static const vor_cdt_limits_t one_site = {1, 0, 0};
    CHECK(vor_init(&d, arena, sizeof arena, 1) == VOR_OK &&
              vor_cdt_attach(&d, memory, VOR_CDT_BYTES(1, 1, 0, 0), &one_site) == VOR_OK,
          "attach to a diagram of one site");
    vor_point_t lone = {3, 4};
    uint32_t lone_id;
    CHECK(vor_insert(&d, lone, &lone_id) == VOR_OK && vor_cdt_triangles_begin(&it, &d) == VOR_OK &&
              vor_cdt_triangles_next(&it, ids) == 0,
          "no triangle of one site");
    (void)vor_init(&d, arena, sizeof arena, CDT_SITES);
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, &limits) == VOR_OK, "attach to no site");
    vor_point_t first = {7, 7};
    insert_all(&d, &first, 1);
    CHECK(vor_remove(&d, 0) == VOR_OK && d.cdt->mesh.vertex_count == 0u, "the only site removed");
    (void)vor_init(&d, arena, sizeof arena, CDT_SITES);
    model_clear();
    /* one site attached, then a second: the meshes' first edge */
    vor_point_t one = {5, 5};
    insert_all(&d, &one, 1);
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, &limits) == VOR_OK, "attach to one site");
    CHECK(vor_cdt_triangles_begin(&it, &d) == VOR_OK && vor_cdt_triangles_next(&it, ids) == 0,
          "no triangle of one site");
    vor_point_t more[] = {{50, 5}, {20, 40}, {30, -20}};
    insert_all(&d, more, 3);
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation of four sites");
    CHECK(vor_cdt_triangles_next(&it, NULL) == 0 && vor_cdt_edges_next(&e, NULL, &b) == 0,
          "iterators with NULL outputs");
    CHECK(vor_cdt_crossing(&d, 4, NULL) == VOR_ERR_ARG && vor_cdt_crossing(&d, 3, s) == VOR_ERR_ARG &&
              vor_cdt_crossing(&d, CDT_SITES, s) == VOR_ERR_ARG &&
              vor_cdt_crossing(&d, CDT_SITES + CDT_CROSSINGS, s) == VOR_ERR_ARG,
          "crossing of no crossing id");
    CHECK(vor_cdt_triangles_begin(&it, NULL) == VOR_ERR_ARG &&
              vor_cdt_triangles_next(&it, ids) == 0 && vor_cdt_edges_begin(&e, NULL) == VOR_ERR_ARG,
          "iterators of no diagram");
    CHECK(vor_cdt_edges_begin(&e, &d) == VOR_OK && vor_cdt_edges_next(&e, &a, NULL) == 0 &&
              vor_cdt_edges_next(&e, NULL, &b) == 0,
          "edges_next with NULL outputs");
    CHECK(vor_constrain(&d, 99, 0) == VOR_ERR_ARG && vor_unconstrain(&d, 99, 0) == VOR_ERR_ARG,
          "constrain and unconstrain from a free id");
    CHECK(vor_unconstrain(&d, 0, 1) == VOR_ERR_ARG && vor_unconstrain(&d, 0, 99) == VOR_ERR_ARG &&
              vor_unconstrain(&d, 2, 2) == VOR_OK,
          "unconstrain no constraint, a free id; a site to itself does nothing");
    CHECK(add_constraint(&d, 0, 1) == 0u && vor_unconstrain(&d, 1, 0) == VOR_OK &&
              vor_unconstrain(&d, 0, 1) == VOR_ERR_ARG,
          "a constraint removed once, not twice");
}

static void check_links(void);
static void check_hull_line_splits(void);
static void check_dense(void);
static void check_full_table_overlap(void);
static void check_split_beside_crossing(void);
static void check_crossing_sos_as_sites(void);
static void check_fan_cut(void);
static void check_unconstrain_chains(void);
static void check_stale_scratch(void);
static void check_attach_state(void);
static void check_full_table_beyond(void);
static void check_marks_kept(void);
static void check_crossing_freed(void);
static void check_collinear_beyond(void);
static void check_zigzag_crossings(void);
static void check_fan_stretches(void);
static void check_crossing_line_sites(void);
static void check_tight_homes(void);
static void check_last_stretch(void);
static void check_open_domains(void);
static void check_domain_seeds(void);
static void check_flood_gateways(void);
static void check_nesting_past_cap(void);
static void check_domain_pending_slots(void);
static void check_unconstrain_domain(void);
static void check_stale_lawson_stack(void);
static void check_domain_one_site(void);
static void check_lawson_room(void);
static void check_crossing_redefined(void);
static void check_domain_all_seeds(void);
static void check_tiny_scenes(void);
static void check_first_packed_freed(void);
static void check_ring_of_three(void);

void test_cdt(void)
{
    TEST_CASE("arguments") check_arguments();
    TEST_CASE("spike") check_spike();
    TEST_CASE("small_scratch") check_small_scratch();
    TEST_CASE("overflow") check_overflow();
    TEST_CASE("edge_table") check_edge_table();
    TEST_CASE("full_tables") check_full_tables();
    TEST_CASE("lawson_sweeps") check_lawson_sweeps();
    TEST_CASE("flood_sweeps") check_flood_sweeps();
    TEST_CASE("hull_splits") check_hull_splits();
    TEST_CASE("tangle") check_tangle();
    TEST_CASE("deep_nesting") check_deep_nesting();
    TEST_CASE("domains") check_domains();
    TEST_CASE("errors") check_errors();
    TEST_CASE("grid_lines") check_grid_lines();
    TEST_CASE("star") check_star();
    TEST_CASE("random/grid") check_random(0, 11);
    TEST_CASE("random/box") check_random(1, 12);
    TEST_CASE("random/full_range") check_random(2, 13);
    TEST_CASE("links") check_links();
    TEST_CASE("hull_line_splits") check_hull_line_splits();
    TEST_CASE("dense") check_dense();
    TEST_CASE("full_table_overlap") check_full_table_overlap();
    TEST_CASE("split_beside_crossing") check_split_beside_crossing();
    TEST_CASE("crossing_sos_as_sites") check_crossing_sos_as_sites();
    TEST_CASE("fan_cut") check_fan_cut();
    TEST_CASE("unconstrain_chains") check_unconstrain_chains();
    TEST_CASE("stale_scratch") check_stale_scratch();
    TEST_CASE("attach_state") check_attach_state();
    TEST_CASE("full_table_beyond") check_full_table_beyond();
    TEST_CASE("marks_kept") check_marks_kept();
    TEST_CASE("crossing_freed") check_crossing_freed();
    TEST_CASE("collinear_beyond") check_collinear_beyond();
    TEST_CASE("zigzag_crossings") check_zigzag_crossings();
    TEST_CASE("fan_stretches") check_fan_stretches();
    TEST_CASE("crossing_line_sites") check_crossing_line_sites();
    TEST_CASE("tight_homes") check_tight_homes();
    TEST_CASE("last_stretch") check_last_stretch();
    TEST_CASE("open_domains") check_open_domains();
    TEST_CASE("domain_seeds") check_domain_seeds();
    TEST_CASE("flood_gateways") check_flood_gateways();
    TEST_CASE("nesting_past_cap") check_nesting_past_cap();
    TEST_CASE("domain_pending_slots") check_domain_pending_slots();
    TEST_CASE("unconstrain_domain") check_unconstrain_domain();
    TEST_CASE("stale_lawson_stack") check_stale_lawson_stack();
    TEST_CASE("domain_one_site") check_domain_one_site();
    TEST_CASE("lawson_room") check_lawson_room();
    TEST_CASE("crossing_redefined") check_crossing_redefined();
    TEST_CASE("domain_all_seeds") check_domain_all_seeds();
    TEST_CASE("ring_of_three") check_ring_of_three();
    TEST_CASE("tiny_scenes") check_tiny_scenes();
    TEST_CASE("first_packed_freed") check_first_packed_freed();
}

/* ------------------------------------------------------------------ */
/* Mutation testing's kills (tools/mutants.py): what the checks above do
 * not see, each against an invariant of its own. */

/* The constrained mesh's topology: every used slot holds three distinct
 * vertices, each neighbour link leads to a used slot holding the shared
 * edge the other way round and linking back, and every home slot in use
 * holds its own vertex. Returns the number of violations. */
static unsigned long mesh_link_faults(const vor_t *d)
{
    const vor_t *m = &d->cdt->mesh;
    const vor__tri_t *tri = m->triangles;
    unsigned long bad = 0;
    uint32_t end = vor__used_slots_end(m);
    for (uint32_t s = vor__next_used_slot(m, 0); s < end; s = vor__next_used_slot(m, s + 1u)) {
        vor_index_t v[3];
        vor__vertices(&tri[s], v);
        bad += ((v[0] != v[1]) && (v[1] != v[2]) && (v[2] != v[0])) ? 0u : 1u;
        bad += ((s >= m->max_sites) || (vor__vertex_index(&tri[s], (vor_index_t)s) != 3u)) ? 0u
                                                                                            : 1u;
        for (unsigned k = 0; k < 3u; k++) {
            vor_index_t u = tri[s].n[k];
            if ((u >= end) || vor__slot_empty(&tri[u])) {
                bad++;
                continue;
            }
            vor_index_t a = v[(k + 1u) % 3u];
            vor_index_t b = v[(k + 2u) % 3u];
            unsigned ia = vor__vertex_index(&tri[u], a);
            unsigned ib = vor__vertex_index(&tri[u], b);
            /* in u the edge runs b -> a, and u's link across it is s */
            bool reversed = (ia != 3u) && (ib != 3u) && (((ib + 1u) % 3u) == ia);
            bad += (reversed && (tri[u].n[(ia + 1u) % 3u] == s)) ? 0u : 1u;
        }
    }
    return bad;
}

/* The faults of d's constrained triangulation (check_cdt) and of its
 * mesh's links (mesh_link_faults), in all. */
static unsigned long mesh_faults(const vor_t *d)
{
    return check_cdt(d) + mesh_link_faults(d);
}

/* Constraints between random live sites (add_constraint), each checked
 * (mesh_faults), until the model holds want of them or tries picks of
 * two sites are made: the faults. */
static unsigned long add_random_constraints(vor_t *d, test_rng_t *rng, uint32_t tries,
                                            uint32_t want)
{
    unsigned long bad = 0;
    for (uint32_t k = 0; (k < tries) && (model.constraints < want); k++) {
        uint32_t a = test_rng_u32(rng) % d->site_count;
        uint32_t b = test_rng_u32(rng) % d->site_count;
        if (!model.live[a] || !model.live[b] || (a == b)) {
            continue;
        }
        bad += add_constraint(d, a, b);
        bad += mesh_faults(d);
    }
    return bad;
}

/* Random scenes as check_random's, the mesh's links checked after every
 * change: constraints crossing, sites taking crossings' places, half the
 * constraints removed (their crossing vertices too), sites removed. */
static void check_links(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 2025);
    unsigned long bad = 0;
    unsigned long takeovers = 0;
    for (unsigned round = 0; round < 6u; round++) {
        vor_t d;
        unsigned kind = round % 2u;
        bad += random_scene(&d, &rng, 40u, kind, &limits);
        bad += mesh_link_faults(&d);
        constrain_random(&d, &rng, 10u, &bad);
        bad += mesh_link_faults(&d);
        for (unsigned k = 0; k < 3u; k++) {
            plant_crossing(&d, &rng, &bad);
            bad += mesh_link_faults(&d);
        }
        for (unsigned k = 0; k < 4u; k++) {
            bool taken = insert_at_crossing(&d);
            takeovers += taken ? 1u : 0u;
            bad += mesh_link_faults(&d) + (taken ? check_cdt(&d) : 0u);
        }
        unconstrain_random(&d, &rng, &bad);
        bad += mesh_link_faults(&d);
        for (uint32_t k = 0; k < 20u; k++) {
            uint32_t s = test_rng_u32(&rng) % d.site_count;
            if ((k % 2u) == 0u) {
                (void)insert_random(&d, &rng, kind);
            } else if (model.live[s] && (vor_remove(&d, s) == VOR_OK)) {
                model.live[s] = false;
            } else {
                /* a free id, or a constraint's end */
            }
            bad += mesh_faults(&d);
        }
    }
    CHECK(bad == 0 && takeovers > 0u, "cdt links: %lu wrong, %lu crossings taken by sites", bad,
          takeovers);
}

/* A constraint along the hull's line, split by sites inserted exactly on
 * it: outside the hull the perturbed site may see a hull edge on that
 * line other than the one holding it. Sites on a line (the bottom, top
 * or left side of the hull) and a few beyond it, built by insertion or by
 * divide and conquer, every other site of the line removed again (a
 * removal's triangles at infinity have that vertex in any corner), the
 * whole line constrained, then the points between its sites inserted in
 * a shuffled order. */
static void check_hull_line_splits(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 4242);
    unsigned long bad = 0;
    for (unsigned round = 0; round < 12u; round++) {
        vor_t d;
        unsigned side = round % 3u;
        vor_point_t p[29];
        uint32_t duplicate_of[29];
        /* the line's sites; the rest of the hull on one side */
        for (int32_t i = 0; i <= 20; i++) {
            p[i] = (side == 2u) ? (vor_point_t){0, 2 * i} : (vor_point_t){2 * i, 0};
        }
        for (uint32_t i = 21; i < 29u; i++) {
            int32_t along = test_rng_range(&rng, 0, 40);
            int32_t away = test_rng_range(&rng, 3, 30);
            p[i] = (side == 2u) ? (vor_point_t){away, along}
                                : (vor_point_t){along, (side == 1u) ? -away : away};
        }
        fresh(&d, NULL, 0);
        int err = ((round % 2u) == 0u) ? vor_build(&d, p, 29, NULL, duplicate_of)
                                       : vor_build_dc(&d, p, 29, NULL, duplicate_of);
        bad += (err == VOR_OK) ? 0u : 1u;
        for (uint32_t i = 0; i < 29u; i++) {
            model.at[i] = p[i];
            model.live[i] = duplicate_of[i] == i;
        }
        bad += attach(&d, &limits);
        for (uint32_t i = 1; i < 20u; i += 2u) {
            bad += (vor_remove(&d, i) == VOR_OK) ? 0u : 1u;
            model.live[i] = false;
        }
        bad += add_constraint(&d, 0, 20);
        bad += check_cdt(&d);
        int32_t odd[10];
        for (int32_t i = 0; i < 10; i++) {
            odd[i] = (4 * i) + 1 + (int32_t)(test_rng_u32(&rng) % 3u);
        }
        for (uint32_t i = 9; i > 0u; i--) { /* shuffled */
            uint32_t j = test_rng_u32(&rng) % (i + 1u);
            int32_t t = odd[i];
            odd[i] = odd[j];
            odd[j] = t;
        }
        for (unsigned i = 0; i < 10u; i++) {
            vor_point_t q = (side == 2u) ? (vor_point_t){0, odd[i]} : (vor_point_t){odd[i], 0};
            insert_all(&d, &q, 1);
            bad += mesh_faults(&d);
        }
    }
    CHECK(bad == 0, "cdt hull line splits: %lu wrong", bad);
}

/* Many constraints among few sites, every one checked with the mesh's
 * links: long cavities whose chains hold many home slots, so that the
 * triangles' home slots are assigned in every way the rule allows. */
static void check_dense(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 777);
    unsigned long bad = 0;
    for (unsigned round = 0; round < 24u; round++) {
        vor_t d;
        unsigned kind = round % 2u;
        bad += random_scene(&d, &rng, 24u, kind, &limits);
        bad += add_random_constraints(&d, &rng, 200u, 24u);
    }
    CHECK(bad == 0, "cdt dense: %lu wrong", bad);
}

/* A full edge table takes a constraint along constrained edges only (it
 * adds none), and refuses one more piece: five sites on a line, their
 * four pieces filling a table of four edges. */
static void check_full_table_overlap(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0}, {10, 0}, {20, 0}, {30, 0}, {40, 0},
                                    {15, 25}, {25, -30}, {5, 40}};
    static const vor_cdt_limits_t four = {4, 1, (2u * (CDT_SITES + 1u)) + 2u};
    bad += scene(&d, p, sizeof p / sizeof p[0], &four);
    bad += add_constraint(&d, 0, 4);
    bad += add_constraint(&d, 4, 0); /* again, and parts of it */
    bad += add_constraint(&d, 1, 3);
    bad += add_constraint(&d, 2, 0);
    bad += mesh_faults(&d);
    test_copy_bytes(saved_memory, memory, sizeof memory);
    bad += (vor_constrain(&d, 5, 2) == VOR_ERR_NOMEM) ? 0u : 1u;
    bad += test_same_bytes(saved_memory, memory, sizeof memory) ? 0u : 1u;
    /* a table of one edge and no crossing takes a segment across
     * triangles: one piece, no crossing */
    static const vor_cdt_limits_t one = {1, 0, (2u * CDT_SITES) + 2u};
    bad += scene(&d, p, sizeof p / sizeof p[0], &one);
    bad += add_constraint(&d, 7, 6);
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt full table overlap: %lu wrong", bad);
}

/* Sites inserted exactly on the pieces between a site and a crossing
 * vertex: two constraints crossing at a lattice point that is no site,
 * with lattice points inside each of their four pieces. */
static void check_split_beside_crossing(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{2, 4}, {-2, -4}, {4, -2}, {-4, 2},
                                    {9, 9}, {-9, 9}, {-9, -9}, {9, -9}};
    bad += scene(&d, p, sizeof p / sizeof p[0], &limits);
    bad += add_constraint(&d, 0, 1);
    bad += add_constraint(&d, 2, 3);
    bad += check_cdt(&d);
    static const vor_point_t on[] = {{1, 2}, {-1, -2}, {2, -1}, {-2, 1}};
    for (unsigned i = 0; i < 4u; i++) {
        insert_all(&d, &on[i], 1);
        bad += mesh_faults(&d);
    }
    CHECK(bad == 0 && gather_crossings(&d) == 1u, "cdt split beside a crossing: %lu wrong", bad);
}

/* A sign test's vertex at lattice point p as a homogeneous point: the
 * site p itself, or (crossing) the crossing at p of two random lines
 * through it, whose W is 4 |u x w|: each of its rows is a positive
 * multiple of the site's. */
static void lattice_vertex(vor__hpoint_t *h, vor_point_t p, test_rng_t *rng, bool crossing)
{
    vor_point_t u;
    vor_point_t w;
    do {
        u = (vor_point_t){test_rng_range(rng, -3, 3), test_rng_range(rng, -3, 3)};
        w = (vor_point_t){test_rng_range(rng, -3, 3), test_rng_range(rng, -3, 3)};
    } while ((int64_t)u.x * w.y == (int64_t)u.y * w.x);
    vor_point_t a = {p.x + u.x, p.y + u.y};
    vor_point_t b = {p.x - u.x, p.y - u.y};
    vor_point_t c = {p.x + w.x, p.y + w.y};
    vor_point_t e = {p.x - w.x, p.y - w.y};
    if (!crossing || !vor__hpoint_crossing(h, a, b, c, e)) {
        vor__hpoint_site(h, p);
    }
}

/* The crossing predicates' perturbation (vor__orient_h_sos,
 * vor__incircle_h_sos) against the sites' own (predicates.c) on lattice
 * points: a crossing vertex at a site's point moves as a site of its
 * index, so each sign must be the sites' one. Cocircular and collinear
 * points on lattice circles and lines around random centres, each given
 * as a site or as a crossing of two lines through it, under random ids. */
static void check_crossing_sos_as_sites(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 1729);
    static const int32_t circle[12][2] = {{5, 0},  {4, 3},  {3, 4},  {0, 5},  {-3, 4}, {-4, 3},
                                          {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    vor_point_t table[32];
    unsigned long bad = 0;
    unsigned long ties = 0;
    for (uint32_t trial = 0; trial < 3000u; trial++) {
        int32_t cx = test_rng_range(&rng, -12, 12);
        int32_t cy = test_rng_range(&rng, -12, 12);
        /* collinear: an orientation test, or an incircle test of four
         * points on a line (whose deciding terms go deepest) */
        bool line = (trial % 3u) != 2u;
        bool flat = (trial % 3u) == 1u;
        unsigned count = (line && !flat) ? 3u : 4u;
        uint32_t ids[4];
        vor__hpoint_t h[4];
        const vor__hpoint_t *v[4];
        int32_t dx = test_rng_range(&rng, -2, 2);
        int32_t dy = (dx == 0) ? 1 : test_rng_range(&rng, -2, 2);
        for (unsigned k = 0; k < count; k++) {
            bool fresh;
            vor_point_t p;
            do { /* distinct ids, distinct points */
                ids[k] = test_rng_u32(&rng) % 32u;
                unsigned pick = test_rng_u32(&rng) % 12u;
                int32_t t = test_rng_range(&rng, -4, 4);
                p = line ? (vor_point_t){cx + (t * dx), cy + (t * dy)}
                         : (vor_point_t){cx + circle[pick][0], cy + circle[pick][1]};
                /* in one trial of four, points of an incircle test on
                 * earlier ones: the perturbation alone then decides, deep
                 * in its terms (two coincident pairs: two-row terms) */
                bool twin = (count == 4u) && (k > 0u) && ((trial % 4u) == 3u) &&
                            ((test_rng_u32(&rng) % 3u) == 0u);
                p = twin ? table[ids[test_rng_u32(&rng) % k]] : p;
                fresh = true;
                for (unsigned j = 0; j < k; j++) {
                    fresh = fresh && (ids[j] != ids[k]) &&
                            (twin || (table[ids[j]].x != p.x) || (table[ids[j]].y != p.y));
                }
            } while (!fresh);
            table[ids[k]] = p;
            lattice_vertex(&h[k], table[ids[k]], &rng, (test_rng_u32(&rng) & 1u) != 0u);
            v[k] = &h[k];
        }
        const vor_point_t *s = table;
        int want;
        int got;
        if (count == 3u) {
            want = vor__orient2d_exact(&s[ids[0]], &s[ids[1]], &s[ids[2]], NULL);
            want = (want != 0) ? want : vor__orient2d_perturbed(s, ids[0], ids[1], ids[2], NULL);
            got = vor__orient_h_sos(v, ids);
        } else {
            want = vor__incircle_exact(&s[ids[0]], &s[ids[1]], &s[ids[2]], &s[ids[3]], NULL);
            want = (want != 0) ? want
                               : vor__incircle_perturbed(s, ids[0], ids[1], ids[2], ids[3], NULL);
            got = vor__incircle_h_sos(v, ids);
        }
        ties += ((count == 3u) ? vor__orient_h(v[0], v[1], v[2]) : vor__incircle_h(v[0], v[1], v[2], v[3])) == 0
                    ? 1u
                    : 0u;
        bad += (got == want) ? 0u : 1u;
    }
    CHECK(bad == 0 && ties > 2000u, "cdt crossing perturbation as sites: %lu wrong, %lu ties", bad,
          ties);
}

/* The cut's limit at its edge: two long parallel constraints, a column
 * of sites just left of the middle between them, and a constraint across
 * both through the middle, whose piece between its two crossing vertices
 * crosses the fan of triangles from the column to the far ends. With
 * each cut from none up, each constraint is refused (nothing changed)
 * until its stretches fit, and made from then on. */
static void check_fan_cut(void)
{
    unsigned long bad = 0;
    unsigned before = 0;
    for (uint32_t cut = 0; cut <= 60u; cut++) {
        vor_t d;
        static const vor_point_t ends[] = {{-400, 0}, {400, 0}, {-400, 40}, {400, 40},
                                           {0, -30}, {0, 70}};
        fresh(&d, ends, sizeof ends / sizeof ends[0]);
        for (int32_t k = 1; k < 40; k++) {
            vor_point_t column = {-1, k};
            insert_all(&d, &column, 1);
        }
        vor_cdt_limits_t tight = {CDT_EDGES, CDT_CROSSINGS, cut};
        bad += attach(&d, &tight);
        static const uint32_t pairs[3][2] = {{0, 1}, {2, 3}, {4, 5}};
        unsigned made = 0;
        for (unsigned k = 0; k < 3u; k++) {
            int err = vor_constrain(&d, pairs[k][0], pairs[k][1]);
            if (err == VOR_OK) {
                model.a[model.constraints] = pairs[k][0];
                model.b[model.constraints] = pairs[k][1];
                model.constraints++;
                made |= 1u << k;
            }
            bad += ((err == VOR_OK) || (err == VOR_ERR_NOMEM)) ? 0u : 1u;
        }
        bad += mesh_faults(&d);
        bad += ((made & before) == before) ? 0u : 1u; /* once made, made with more room */
        before = made;
    }
    CHECK(bad == 0 && before == 7u, "cdt fan at the cut's limit: %lu wrong, %u made", bad, before);
}

/* A constraint taken off between two long arcs of sites, one above and
 * one below it, staggered: Lawson's flips from the two sides' fans to
 * the zigzag between the arcs flip pairs of sites one after another,
 * some 1,100 flips for 100 sites (far beyond 3 a vertex), all of which
 * must happen for the result to be Delaunay again. */
static void check_unconstrain_chains(void)
{
    unsigned long bad = 0;
    for (unsigned shape = 0; shape < 2u; shape++) {
        vor_t d;
        const int32_t width = 100000;
        const int32_t arcs = 50;
        static const vor_point_t ends[] = {{0, 0}, {100000, 0}};
        fresh(&d, ends, 2);
        for (int32_t i = 1; i < arcs; i++) {
            int64_t x = ((int64_t)width * i) / arcs;
            int64_t half = width / (2 * arcs);
            int64_t up = 1 + ((x * (width - x)) / ((int64_t)width * 4));
            int64_t down = (shape == 0u) ? up : 1 + ((x * (width - x)) / ((int64_t)width * 40));
            vor_point_t p[2] = {{(int32_t)x, (int32_t)up}, {(int32_t)(x + half), (int32_t)-down}};
            insert_all(&d, p, 2);
        }
        bad += attach(&d, &limits);
        bad += add_constraint(&d, 0, 1);
        bad += check_cdt(&d);
        bad += (vor_unconstrain(&d, 1, 0) == VOR_OK) ? 0u : 1u;
        model.constraints = 0;
        bad += mesh_faults(&d);
    }
    CHECK(bad == 0, "cdt constraint off between two arcs: %lu wrong", bad);
}

/* A cavity's scratch holds whatever earlier calls left there, and a call
 * must read only what it wrote. Two triangles across a segment (chains
 * a, u, b and a, l, b) with the scratch filled first as a longer piece
 * with spikes could have left it: every chain entry u or l, every
 * triangle outside an edge none (a spike's mark), every spike side a far
 * site's home triangle. The links and the triangulation stay whole. */
static void check_stale_scratch(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0}, {10, 0}, {5, 3}, {5, -3}, {500, 500}};
    bad += scene(&d, p, sizeof p / sizeof p[0], &limits);
    struct vor__cdt *c = d.cdt;
    size_t n = (size_t)c->max_cut + 2u; /* cavity_init's layout */
    for (size_t k = 0; k < n; k++) {
        c->scratch[k] = 2;                   /* upper: u */
        c->scratch[n + k] = VOR__NONE;       /* upper_out */
        c->scratch[(2u * n) + k] = 3;        /* lower: l */
        c->scratch[(3u * n) + k] = VOR__NONE; /* lower_out */
        c->scratch[(5u * n) + k] = 4;        /* side: the far site's home */
        c->scratch[(6u * n) + k] = (vor_index_t)(k % 3u);
    }
    bad += add_constraint(&d, 0, 1);
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt stale scratch: %lu wrong", bad);
}

/* Attach's checks and fresh state. Crossings up to the documented limit
 * (VOR_MAX_SITES vertices in all) pass the argument check and fail only
 * on the memory's size. A fresh attach has no domain marked, and its edge
 * table is at most half full (cdt.h: a probe for an absent edge meets an
 * empty entry soon). A free site id's slot holds no triangle even when
 * the memory held one there from an earlier attach. */
static void check_attach_state(void)
{
    vor_t d;
    unsigned long bad = 0;
    fresh(&d, NULL, 0);
    const vor_cdt_limits_t most = {8, VOR_MAX_SITES - CDT_SITES, 8};
    bad += (vor_cdt_attach(&d, memory, sizeof memory, &most) == VOR_ERR_NOMEM) ? 0u : 1u;
    static const vor_point_t p[] = {{0, 0}, {40, 0}, {20, 30}, {20, -30}, {60, 20}};
    insert_all(&d, p, 5);
    bad += attach(&d, &limits);
    vor_cdt_triangle_iter_t it;
    bad += (vor_cdt_inside_begin(&it, &d) == VOR_ERR_ARG) ? 0u : 1u;
    bad += ((2u * d.cdt->max_edges) <= d.cdt->edge_slots) ? 0u : 1u;
    /* the same sites, site 0 removed before attaching to the same memory */
    fresh(&d, p, 5);
    bad += (vor_remove(&d, 0) == VOR_OK) ? 0u : 1u;
    model.live[0] = false;
    bad += attach(&d, &limits);
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt attach state: %lu wrong", bad);
}

/* A full edge table refuses only a site that splits a constrained edge.
 * Here the pieces of (0, 0)-(10, 0) end at the crossing vertex (5, 0) of
 * (5, -5)-(5, 5): (12, 0), on their line beyond both, splits nothing and
 * goes in; (2, 0) splits a piece and is refused; (5, 0) takes the
 * crossing vertex's place, which splits nothing. */
static void check_full_table_beyond(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0}, {10, 0}, {5, -5}, {5, 5}};
    static const vor_cdt_limits_t four = {4, 1, (2u * (CDT_SITES + 1u)) + 2u};
    bad += scene(&d, p, 4, &four);
    bad += add_constraint(&d, 0, 1) + add_constraint(&d, 2, 3);
    bad += (d.cdt->edge_count == 4u) ? 0u : 1u; /* the table is full */
    vor_point_t beyond = {12, 0};
    uint32_t id;
    bad += (vor_insert(&d, beyond, &id) == VOR_OK) ? 0u : 1u;
    model.at[id] = beyond;
    model.live[id] = true;
    vor_point_t inside_piece = {2, 0};
    bad += (vor_insert(&d, inside_piece, &id) == VOR_ERR_NOMEM) ? 0u : 1u;
    vor_point_t at_crossing = {5, 0};
    bad += (vor_insert(&d, at_crossing, &id) == VOR_OK) ? 0u : 1u;
    model.at[id] = at_crossing;
    model.live[id] = true;
    bad += check_cdt(&d);
    CHECK(bad == 0, "cdt full table, sites on a line: %lu wrong", bad);
}

/* The domain's marks stay through a refused change and go with a made
 * one (vor_cdt.h): a square of four constraints fills a table of four,
 * so moving the free site inside onto a side is refused (VOR_ERR_NOMEM)
 * and the marks stay; removing that site clears them. */
static void check_marks_kept(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 7}};
    static const vor_cdt_limits_t four = {4, 1, (2u * (CDT_SITES + 1u)) + 2u};
    bad += scene(&d, p, 5, &four);
    for (uint32_t k = 0; k < 4u; k++) {
        bad += add_constraint(&d, k, (k + 1u) % 4u);
    }
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    vor_point_t on_side = {5, 0};
    vor_cdt_triangle_iter_t it;
    bad += (vor_move(&d, 4, on_side, NULL) == VOR_ERR_NOMEM) ? 0u : 1u;
    bad += (vor_cdt_inside_begin(&it, &d) == VOR_OK) ? 0u : 1u;
    bad += (vor_remove(&d, 4) == VOR_OK) ? 0u : 1u;
    model.live[4] = false;
    bad += (vor_cdt_inside_begin(&it, &d) == VOR_ERR_ARG) ? 0u : 1u;
    bad += check_cdt(&d);
    CHECK(bad == 0, "cdt marks kept and cleared: %lu wrong", bad);
}

/* A crossing vertex a site takes over frees its entry: in a table of one
 * crossing, (0, 0)-(10, 0) and (5, -5)-(5, 5) cross at (5, 0), a site
 * inserted there takes its place, and (0, 3)-(10, 3) may then cross
 * (5, 0)-(5, 5). A site ending the only constraint stays (removal
 * refused); one ending none goes. */
static void check_crossing_freed(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0}, {10, 0}, {5, -5}, {5, 5}, {0, 3}, {10, 3}, {30, 30}};
    static const vor_cdt_limits_t one = {40, 1, (2u * (CDT_SITES + 1u)) + 2u};
    bad += scene(&d, p, 7, &one);
    bad += add_constraint(&d, 0, 1);
    bad += (vor_remove(&d, 0) == VOR_ERR_CONSTRAINED) ? 0u : 1u;
    bad += (vor_remove(&d, 6) == VOR_OK) ? 0u : 1u;
    model.live[6] = false;
    bad += add_constraint(&d, 2, 3);
    bad += (gather_crossings(&d) == 1u) ? 0u : 1u;
    vor_point_t at_crossing = {5, 0};
    insert_all(&d, &at_crossing, 1);
    bad += (gather_crossings(&d) == 0u) ? 0u : 1u;
    bad += add_constraint(&d, 4, 5);
    bad += (gather_crossings(&d) == 1u) ? 0u : 1u;
    bad += check_cdt(&d);
    CHECK(bad == 0, "cdt crossing freed: %lu wrong", bad);
}

/* Sites all on one line with a constraint, and sites inserted on that
 * line beyond both ends: the search for a constrained edge holding the
 * new site walks the hull edges on its line, which here go all the way
 * round, and must stop (the site splits nothing). */
static void check_collinear_beyond(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0}, {10, 5}, {20, 10}};
    bad += scene(&d, p, 3, &limits);
    bad += add_constraint(&d, 0, 1);
    static const vor_point_t beyond[] = {{30, 15}, {-10, -5}};
    insert_all(&d, beyond, 2);
    bad += (d.site_count == 5u) ? 0u : 1u;
    bad += check_cdt(&d);
    CHECK(bad == 0, "cdt collinear, sites beyond: %lu wrong", bad);
}

/* A zigzag of seven joins between four sites above a-b and four below,
 * each crossing a-b at its own point, and a-b made across all of them:
 * with ten sites and exactly seven crossings of room, a-b's crossings are
 * all the room there is. Making it takes two steps a crossing (its
 * insertion, then the piece up to it), 15 in all, which the recording
 * pass's bound must allow (17 vertices of room). The joins are cut once each (14 edges) and a-b seven times
 * (8 edges): 22 edges fit a table of 22 and not one of 21, where a-b is
 * refused with nothing changed. A domain marked before a-b is no longer
 * one after it. zigzag() builds the sites, with a table of `edges`. */
static void zigzag(vor_t *d, uint32_t edges)
{
    model_clear();
    (void)vor_init(d, arena, sizeof arena, 10);
    static const vor_point_t p[] = {{-50, 0},   {150, 0},  {0, 100},  {10, -100}, {20, 100},
                                    {30, -100}, {40, 100}, {50, -100}, {60, 100}, {70, -100}};
    insert_all(d, p, sizeof p / sizeof p[0]);
    const vor_cdt_limits_t room = {edges, 7, (2u * 17u) + 2u};
    CHECK(attach(d, &room) == 0u, "cdt zigzag: attach");
}

static void check_zigzag_crossings(void)
{
    vor_t d;
    unsigned long bad = 0;
    zigzag(&d, 22);
    for (uint32_t s = 2; s < 9u; s++) {
        bad += add_constraint(&d, s, s + 1u);
    }
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    bad += add_constraint(&d, 0, 1);
    bad += mesh_faults(&d);
    vor_cdt_triangle_iter_t it;
    bad += (vor_cdt_inside_begin(&it, &d) == VOR_ERR_ARG) ? 0u : 1u;
    zigzag(&d, 21);
    for (uint32_t s = 2; s < 9u; s++) {
        bad += add_constraint(&d, s, s + 1u);
    }
    test_copy_bytes(saved_memory, memory, sizeof memory);
    bad += (vor_constrain(&d, 0, 1) == VOR_ERR_NOMEM) ? 0u : 1u;
    bad += test_same_bytes(saved_memory, memory, sizeof memory) ? 0u : 1u;
    bad += check_cdt(&d);
    CHECK(bad == 0 && gather_crossings(&d) == 0u, "cdt zigzag crossings: %lu wrong", bad);
}

/* The cut's limit, stretch by stretch (docs/design/constraints.md: each
 * stretch between two vertices or crossings is checked against cut - 2):
 * check_fan_cut's scene, two constraints along y = 0 and y = 40 and a
 * column of sites at x = -1 between them, with a second column below
 * y = 0, crossed by the segment x = 0 from below that column to (0, 70).
 * The triangles each stretch crosses are counted here from the
 * triangulation before it (those with corners on both sides of x = 0,
 * by the side of the two lines they lie on); with cuts around the larger
 * of the first two stretches (the third kept short), the segment is made
 * exactly when both fit within cut - 2. With a short column below the
 * middle stretch decides, with a long one (and a short one above) the
 * first. Returns 1 when the segment was made. */
static uint32_t fan_stretches(unsigned shape, uint32_t cut, uint32_t stretch[3])
{
    static const int32_t above[2] = {40, 20};
    static const int32_t below[2] = {3, 40};
    vor_t d;
    unsigned long bad = 0;
    const vor_point_t ends[] = {{-400, 0}, {400, 0}, {-400, 40}, {400, 40},
                                {0, -30 - below[shape]}, {0, 70}};
    fresh(&d, ends, sizeof ends / sizeof ends[0]);
    for (int32_t k = 1; k < above[shape]; k++) {
        vor_point_t column = {-1, k};
        insert_all(&d, &column, 1);
    }
    for (int32_t k = 1; k < below[shape]; k++) {
        vor_point_t column = {-1, -k};
        insert_all(&d, &column, 1);
    }
    vor_cdt_limits_t tight = {CDT_EDGES, CDT_CROSSINGS, cut};
    bad += attach(&d, &tight);
    bad += add_constraint(&d, 0, 1);
    bad += add_constraint(&d, 2, 3);
    stretch[0] = 0;
    stretch[1] = 0;
    stretch[2] = 0;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    (void)vor_cdt_triangles_begin(&it, &d);
    while (vor_cdt_triangles_next(&it, ids) == 1) {
        bool left = false;
        bool right = false;
        int32_t low = INT32_MAX;
        int32_t high = INT32_MIN;
        for (unsigned k = 0; k < 3u; k++) {
            vor_point_t q = model.at[ids[k]];
            left = left || (q.x < 0);
            right = right || (q.x > 0);
            low = (q.y < low) ? q.y : low;
            high = (q.y > high) ? q.y : high;
        }
        if (left && right) {
            stretch[(high <= 0) ? 0 : (low >= 40) ? 2 : 1]++;
        }
    }
    int err = vor_constrain(&d, 4, 5);
    bad += ((err == VOR_OK) || (err == VOR_ERR_NOMEM)) ? 0u : 1u;
    if (err == VOR_OK) {
        model.a[model.constraints] = 4;
        model.b[model.constraints] = 5;
        model.constraints++;
    }
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt fan stretches: %lu wrong", bad);
    return (err == VOR_OK) ? 1u : 0u;
}

static void check_fan_stretches(void)
{
    unsigned long bad = 0;
    for (unsigned shape = 0; shape < 2u; shape++) {
        uint32_t s[3];
        (void)fan_stretches(shape, CDT_CUT, s);
        uint32_t most = (s[0] > s[1]) ? s[0] : s[1];
        /* the intended stretch decides; the last one stays short */
        bad += ((s[shape] < most) && (s[2] + 4u < most)) ? 0u : 1u;
        for (uint32_t cut = most - 2u; cut <= most + 3u; cut++) {
            uint32_t fits = ((s[0] + 2u <= cut) && (s[1] + 2u <= cut) && (s[2] + 2u <= cut)) ? 1u
                                                                                          : 0u;
            bad += (fan_stretches(shape, cut, s) == fits) ? 0u : 1u;
        }
    }
    CHECK(bad == 0, "cdt fan stretches: %lu wrong", bad);
}

/* A crossing vertex's lines are given by the first sites along each
 * line's constrained edges, each way from it (docs/design/constraints.md,
 * "crossing vertex"): a segment S-T crossing P-Q, beyond which Q-R
 * continues P-Q's line, reports S, T, P and Q, not R. Once Q-R is taken
 * off and R removed, the crossing (defined again) still reports sites of
 * the diagram, and the triangulation is whole. */
static void check_crossing_line_sites(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0},  {10, 0},   {20, 0}, {5, 5},
                                    {5, -5}, {-10, 10}, {30, -10}};
    bad += scene(&d, p, sizeof p / sizeof p[0], &limits);
    bad += add_constraint(&d, 0, 1);
    bad += add_constraint(&d, 1, 2);
    bad += add_constraint(&d, 3, 4);
    uint32_t s[4];
    bad += (gather_crossings(&d) == 1u) ? 0u : 1u;
    bad += (vor_cdt_crossing(&d, crossing_ids[0], s) == VOR_OK) ? 0u : 1u;
    /* S-T's line (sites 3, 4), then P-Q's (0, 1), each either way round */
    bad += (((s[0] == 3u) && (s[1] == 4u)) || ((s[0] == 4u) && (s[1] == 3u))) ? 0u : 1u;
    bad += (((s[2] == 0u) && (s[3] == 1u)) || ((s[2] == 1u) && (s[3] == 0u))) ? 0u : 1u;
    bad += (vor_unconstrain(&d, 1, 2) == VOR_OK) ? 0u : 1u;
    model.a[1] = 3; /* the model keeps P-Q and S-T */
    model.b[1] = 4;
    model.constraints = 2;
    bad += (vor_remove(&d, 2) == VOR_OK) ? 0u : 1u;
    model.live[2] = false;
    bad += (gather_crossings(&d) == 1u) ? 0u : 1u;
    bad += (vor_cdt_crossing(&d, crossing_ids[0], s) == VOR_OK) ? 0u : 1u;
    for (unsigned k = 0; k < 4u; k++) {
        bad += ((s[k] < CDT_SITES) && model.live[s[k]]) ? 0u : 1u;
    }
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt crossing line sites: %lu wrong", bad);
}

/* Home slots where the rule has no slack: random sites in a box of
 * width 1000 and height 8, 60 or 1000 and random constraints across them,
 * whose long cavities hold many home slots, checked after each
 * constraint. Seeds 125 and 490 of this scene put a sub-polygon's room
 * at exactly what its demanded corners need, so that one corner sent the
 * wrong way leaves a home slot unserved (mutants of triangulate's room
 * rule crash or break the links there). */
static void check_tight_homes(void)
{
    static const uint32_t seeds[] = {125, 490};
    unsigned long bad = 0;
    for (unsigned s = 0; s < 2u; s++) {
        test_rng_t rng;
        test_rng_seed(&rng, seeds[s]);
        vor_t d;
        fresh(&d, NULL, 0);
        uint32_t n = 8u + (test_rng_u32(&rng) % 40u);
        unsigned kind = test_rng_u32(&rng) % 3u;
        int32_t height = (kind == 0u) ? 8 : (kind == 1u) ? 60 : 1000;
        for (uint32_t i = 0; i < n; i++) {
            vor_point_t q = {test_rng_range(&rng, 0, 1000), test_rng_range(&rng, 0, height)};
            uint32_t id;
            if (vor_insert(&d, q, &id) == VOR_OK) {
                model.at[id] = q;
                model.live[id] = true;
            }
        }
        bad += attach(&d, &limits);
        uint32_t want = 1u + (test_rng_u32(&rng) % 12u);
        bad += add_random_constraints(&d, &rng, 100u, want);
    }
    CHECK(bad == 0, "cdt tight homes: %lu wrong", bad);
}

/* A triangle by its sorted corners, as check_domain keys it. */
static uint64_t triangle_key(const uint32_t ids[3])
{
    uint32_t lo = (ids[0] < ids[1]) ? ids[0] : ids[1];
    lo = (lo < ids[2]) ? lo : ids[2];
    uint32_t hi = (ids[0] > ids[1]) ? ids[0] : ids[1];
    hi = (hi > ids[2]) ? hi : ids[2];
    uint32_t mid = ids[0] + ids[1] + ids[2] - lo - hi;
    return ((uint64_t)lo << 42) | ((uint64_t)mid << 21) | hi;
}

/* The domain against its definition by brute force, for any constraints
 * (open ones too, where check_domain's local rule does not hold): every
 * triangle's least level, relaxed across its edges until none lowers (an
 * edge under k of the test's constraints costs k, an edge of one listed
 * triangle borders the outside at level 0), capped at 126; a triangle is
 * inside exactly when that level is odd. Returns the triangles wrong. */
static unsigned long domain_faults(const vor_t *d)
{
    static uint64_t inside_keys[2u * CDT_VERTICES];
    static uint32_t least[2u * CDT_VERTICES];
    static bool reported[2u * CDT_VERTICES];
    const uint32_t unreached = 1u << 30;
    unsigned long bad = 0;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    uint32_t ni = 0;
    bad += (vor_cdt_inside_begin(&it, d) == VOR_OK) ? 0u : 1u;
    while ((vor_cdt_triangles_next(&it, ids) == 1) && (ni < 2u * CDT_VERTICES)) {
        inside_keys[ni++] = triangle_key(ids);
    }
    sort_keys(inside_keys, ni);
    uint32_t nt = 0;
    uint32_t nh = 0;
    (void)vor_cdt_triangles_begin(&it, d);
    while ((vor_cdt_triangles_next(&it, ids) == 1) && (nt < 2u * CDT_VERTICES)) {
        reported[nt] = has_key(inside_keys, ni, triangle_key(ids));
        least[nt] = unreached;
        for (unsigned k = 0; k < 3u; k++) {
            halves[nh].key = edge_key(ids[(k + 1u) % 3u], ids[(k + 2u) % 3u]);
            halves[nh].apex = nt; /* here: the triangle's number */
            nh++;
        }
        nt++;
    }
    sort_halves(halves, nh);
    for (uint32_t i = 0; i < nh; i++) { /* here: the edge's cost */
        halves[i].forward = constraints_through(d, (uint32_t)(halves[i].key >> 32),
                                                (uint32_t)halves[i].key);
    }
    bool lowered = true;
    while (lowered) {
        lowered = false;
        for (uint32_t i = 0; i < nh;) {
            uint32_t j = i + 1u;
            while ((j < nh) && (halves[j].key == halves[i].key)) {
                j++;
            }
            uint32_t cost = halves[i].forward;
            uint32_t a = halves[i].apex;
            uint32_t b = halves[j - 1u].apex;
            uint32_t from_a = (j - i == 1u) ? 0u : least[b]; /* a's other side */
            uint32_t from_b = least[a];
            if ((from_a < unreached) && (from_a + cost < least[a])) {
                least[a] = from_a + cost;
                lowered = true;
            }
            if ((j - i == 2u) && (from_b < unreached) && (from_b + cost < least[b])) {
                least[b] = from_b + cost;
                lowered = true;
            }
            bad += (j - i <= 2u) ? 0u : 1u;
            i = j;
        }
    }
    for (uint32_t t = 0; t < nt; t++) {
        uint32_t level = (least[t] > 126u) ? 126u : least[t];
        bad += (((level & 1u) != 0u) == reported[t]) ? 0u : 1u;
    }
    return bad;
}

/* Open constraints (random segments between random sites, some twice):
 * a triangle beside one is reached around its ends at a lower level than
 * across it, so a level first reached across a constraint must be
 * lowered later; the domain against the brute force. */
static void check_open_domains(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 41);
    unsigned long bad = 0;
    for (unsigned round = 0; round < 6u; round++) {
        vor_t d;
        fresh(&d, NULL, 0);
        for (uint32_t i = 0; i < 40u; i++) {
            vor_point_t p = {test_rng_range(&rng, 0, 1000), test_rng_range(&rng, 0, 1000)};
            insert_all(&d, &p, 1);
        }
        bad += attach(&d, &limits);
        for (uint32_t k = 0; k < 8u; k++) {
            uint32_t a = test_rng_u32(&rng) % d.site_count;
            uint32_t b = test_rng_u32(&rng) % d.site_count;
            if ((a != b) && model.live[a] && model.live[b]) {
                bad += add_constraint(&d, a, b);
                if ((k % 3u) == 0u) {
                    bad += add_constraint(&d, b, a);
                }
            }
        }
        bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
        bad += domain_faults(&d);
    }
    CHECK(bad == 0, "cdt open domains: %lu wrong", bad);
}

/* One triangle, two of its sides constrained, each choice of the free
 * one: the inside is reached at level 0 only across the free side's
 * triangle at infinity, whichever of the flood's seeds that is. */
static void check_domain_seeds(void)
{
    unsigned long bad = 0;
    static const vor_point_t corners[] = {{0, 0}, {90, 10}, {30, 70}};
    for (uint32_t free_side = 0; free_side < 3u; free_side++) {
        vor_t d;
        bad += scene(&d, corners, 3, &limits);
        for (uint32_t side = 0; side < 3u; side++) {
            if (side != free_side) {
                bad += add_constraint(&d, side, (side + 1u) % 3u);
            }
        }
        bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
        bad += domain_faults(&d);
    }
    CHECK(bad == 0, "cdt domain seeds: %lu wrong", bad);
}

/* The flood's sweeps doing all the work: 70 sites in convex position
 * with their hull constrained but for one side (each in turn), flooded
 * with a stack of 26 pairs (a cut of 0). The 70 triangles at infinity
 * overflow it at once, so when the free side's one is lost, the whole
 * inside is reached at level 0 only by the sweeps, through it, over
 * many passes. The sites are numbered from two starting points, so that
 * the first slot (site 0's home) holds another triangle. */
static void check_flood_gateways(void)
{
    unsigned long bad = 0;
    for (int32_t first = 0; first < 2; first++) {
        vor_t d;
        fresh(&d, NULL, 0);
        for (int32_t j = 0; j < 70; j++) { /* on the parabola y = x^2 / 64 */
            int32_t i = (j + first) % 70;
            vor_point_t p = {(i - 35) * 64, (i - 35) * (i - 35) * 64};
            insert_all(&d, &p, 1);
        }
        static const vor_cdt_limits_t small = {3u * (CDT_SITES + 8u), 8, 0};
        const size_t bytes = VOR_CDT_BYTES(CDT_SITES, small.edges, 8, 0);
        canary_fill(bytes);
        bad += attach(&d, &small);
        for (uint32_t k = 0; k < 70u; k++) {
            bad += add_constraint(&d, k, (k + 1u) % 70u);
        }
        for (uint32_t g = 0; g < 70u; g++) {
            bad += (vor_unconstrain(&d, g, (g + 1u) % 70u) == VOR_OK) ? 0u : 1u;
            model.a[g] = model.a[69]; /* the model without side g */
            model.b[g] = model.b[69];
            model.constraints = 69;
            bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
            bad += domain_faults(&d);
            model.a[69] = model.a[g];
            model.b[69] = model.b[g];
            model.a[g] = g;
            model.b[g] = (g + 1u) % 70u;
            model.constraints = 70;
            bad += (vor_constrain(&d, g, (g + 1u) % 70u) == VOR_OK) ? 0u : 1u;
        }
        bad += canary_faults(bytes);
    }
    CHECK(bad == 0, "cdt flood gateways: %lu wrong", bad);
}

/* Levels past 126 count as 126: a triangle constrained 126 times around
 * a smaller one constrained once, whose inside only the flood of level
 * 126 reaches (126 + 1 counts as 126): no triangle is inside. */
static void check_nesting_past_cap(void)
{
    unsigned long bad = 0;
    vor_t d;
    static const vor_point_t corners[] = {{0, 0},     {900, 0},   {450, 800},
                                          {400, 200}, {500, 200}, {450, 300}};
    bad += scene(&d, corners, 6, &limits);
    for (uint32_t j = 0; j < 126u; j++) {
        for (uint32_t side = 0; side < 3u; side++) {
            bad += (vor_constrain(&d, side, (side + 1u) % 3u) == VOR_OK) ? 0u : 1u;
        }
    }
    for (uint32_t side = 0; side < 3u; side++) {
        bad += (vor_constrain(&d, 3u + side, 3u + ((side + 1u) % 3u)) == VOR_OK) ? 0u : 1u;
    }
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    uint32_t inside = 0;
    (void)vor_cdt_inside_begin(&it, &d);
    while (vor_cdt_triangles_next(&it, ids) == 1) {
        inside++;
    }
    CHECK(bad == 0 && inside == 0u, "cdt nesting past the cap: %lu wrong, %u inside", bad,
          (unsigned)inside);
}

/* A level's first triangles are the pending ones, wherever they sit: a
 * hexagon around site 0 (whose home slot, the first, holds one of its
 * triangles), each triangle T = (0, i, i + 1) with its sides constrained
 * once and a neighbour U's two other sides three times, so that U's
 * least level (2, through T) is reached only from T. */
static void check_domain_pending_slots(void)
{
    unsigned long bad = 0;
    vor_t d;
    static const vor_point_t hexagon[] = {{0, 0},    {100, 0},  {50, 87}, {-50, 87},
                                          {-100, 0}, {-50, -87}, {50, -87}};
    for (uint32_t i = 1; i <= 6u; i++) {
        for (uint32_t way = 0; way < 2u; way++) {
            uint32_t j = (i % 6u) + 1u; /* T = (0, i, j) */
            /* U = (0, j, beyond) across 0-j, or (0, beyond, i) across 0-i */
            uint32_t shared = (way == 0u) ? j : i;
            uint32_t beyond = (way == 0u) ? ((j % 6u) + 1u) : (((i + 4u) % 6u) + 1u);
            bad += scene(&d, hexagon, 7, &limits);
            bad += add_constraint(&d, 0, i) + add_constraint(&d, 0, j) + add_constraint(&d, i, j);
            for (uint32_t times = 0; times < 3u; times++) {
                bad += add_constraint(&d, 0, beyond) + add_constraint(&d, shared, beyond);
            }
            bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
            bad += domain_faults(&d);
        }
    }
    CHECK(bad == 0, "cdt domain pending slots: %lu wrong", bad);
}

/* A constraint taken off clears the domain (the header: any change), and
 * the edge iterator refuses either output NULL while edges remain. */
static void check_unconstrain_domain(void)
{
    unsigned long bad = 0;
    vor_t d;
    static const vor_point_t square[] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}, {50, 50}};
    bad += scene(&d, square, 5, &limits);
    for (uint32_t k = 0; k < 4u; k++) {
        bad += add_constraint(&d, k, (k + 1u) % 4u);
    }
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    vor_cdt_edge_iter_t e;
    uint32_t a;
    uint32_t b;
    bad += (vor_cdt_edges_begin(&e, &d) == VOR_OK) ? 0u : 1u;
    bad += ((vor_cdt_edges_next(&e, NULL, &b) == 0) && (vor_cdt_edges_next(&e, &a, NULL) == 0))
               ? 0u
               : 1u;
    bad += (vor_unconstrain(&d, 1, 0) == VOR_OK) ? 0u : 1u;
    vor_cdt_triangle_iter_t it;
    bad += (vor_cdt_inside_begin(&it, &d) == VOR_ERR_ARG) ? 0u : 1u;
    CHECK(bad == 0, "cdt unconstrain and the domain: %lu wrong", bad);
}

/* Lawson's stack holds only what the call pushed: the scratch filled with
 * ids of no vertex, then a constraint along an edge (no cavity) made and
 * taken off again. */
static void check_stale_lawson_stack(void)
{
    vor_t d;
    unsigned long bad = 0;
    static const vor_point_t p[] = {{0, 0}, {10, 0}, {5, 3}, {5, -3}};
    bad += scene(&d, p, 4, &limits);
    struct vor__cdt *c = d.cdt;
    for (size_t k = 0; k < 13u * ((size_t)c->max_cut + 4u); k++) {
        c->scratch[k] = VOR__NONE;
    }
    bad += add_constraint(&d, 2, 3);
    bad += (vor_unconstrain(&d, 3, 2) == VOR_OK) ? 0u : 1u;
    model.constraints = 0;
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt stale lawson stack: %lu wrong", bad);
}

/* Below two sites the slots hold stale contents, which the domain must
 * not read: one site, every slot made to look like a triangle at
 * infinity with neighbours far past the mesh. */
static void check_domain_one_site(void)
{
    vor_t d;
    unsigned long bad = 0;
    vor_point_t lone = {3, 4};
    bad += scene(&d, &lone, 1, &limits);
    vor__tri_t *tri = d.cdt->mesh.triangles;
    for (uint32_t s = 0; s < vor__triangle_count(d.cdt->mesh.max_sites); s++) {
        uint8_t *corners = (uint8_t *)tri[s].v; /* all ones: the vertex at infinity */
        for (size_t k = 0; k < sizeof tri[s].v; k++) {
            corners[k] = 0xFFu;
        }
        for (unsigned k = 0; k < 3u; k++) {
            tri[s].n[k] = (vor_index_t)(VOR__NONE - 1u);
        }
    }
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    bad += (vor_cdt_inside_begin(&it, &d) == VOR_OK) ? 0u : 1u;
    bad += (vor_cdt_triangles_next(&it, ids) == 0) ? 0u : 1u;
    CHECK(bad == 0, "cdt domain of one site: %lu wrong", bad);
}

/* Lawson's stack at its room: 14 sites (so few triangle slots that the
 * domain's levels after the scratch take 26 bytes), a constraint with 11
 * sites in a band of 10 on either side of it, inserted after it, taken
 * off with a cut of 0 (26 pairs): the flips would stack 35 pairs, and
 * nothing may be written past the memory given. */
static void check_lawson_room(void)
{
    vor_t d;
    unsigned long bad = 0;
    model_clear();
    (void)vor_init(&d, arena, sizeof arena, 14);
    static const vor_point_t line[] = {{0, 0}, {10000, 0}, {5000, 3000}};
    insert_all(&d, line, 3);
    static const vor_cdt_limits_t small = {42, 0, 0};
    const size_t bytes = VOR_CDT_BYTES(14, small.edges, 0, 0);
    canary_fill(bytes);
    bad += attach(&d, &small);
    bad += add_constraint(&d, 0, 1);
    static const vor_point_t band[] = {{834, 10},  {7101, -6}, {9329, -2}, {3237, 8},
                                       {8228, -1}, {5532, 8},  {6538, 6},  {1894, -4},
                                       {8117, 1},  {893, -2},  {3026, -9}};
    insert_all(&d, band, 11);
    bad += check_cdt(&d);
    bad += (vor_unconstrain(&d, 1, 0) == VOR_OK) ? 0u : 1u;
    model.constraints = 0;
    bad += mesh_faults(&d) + canary_faults(bytes);
    CHECK(bad == 0, "cdt lawson room: %lu wrong", bad);
}

/* A crossing vertex on three constraints, one of its two defining ones
 * taken off: it is defined again by the other two, so that the sites of
 * the one taken off can go and their ids be used again elsewhere. */
static void check_crossing_redefined(void)
{
    vor_t d;
    unsigned long bad = 0;
    /* y = 50, x = 50 and the diagonal, all through (50, 50) */
    static const vor_point_t ends[] = {{0, 50}, {100, 50}, {50, 0}, {50, 100}, {0, 0}, {100, 100},
                                       {20, 80}, {80, 20}};
    bad += scene(&d, ends, 8, &limits);
    for (uint32_t k = 0; k < 3u; k++) {
        bad += add_constraint(&d, 2u * k, (2u * k) + 1u);
    }
    bad += check_cdt(&d);
    bad += (vor_unconstrain(&d, 0, 1) == VOR_OK) ? 0u : 1u;
    model.a[0] = model.a[2];
    model.b[0] = model.b[2];
    model.constraints = 2;
    bad += check_cdt(&d);
    bad += ((vor_remove(&d, 0) == VOR_OK) && (vor_remove(&d, 1) == VOR_OK)) ? 0u : 1u;
    model.live[0] = false;
    model.live[1] = false;
    static const vor_point_t elsewhere[] = {{10, 60}, {70, 95}};
    insert_all(&d, elsewhere, 2);
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt crossing redefined: %lu wrong", bad);
}

/* The flood starts from every triangle at infinity, wherever its slot:
 * seven sites whose triangles at infinity all sit in the second, fourth,
 * ... used slots (found by a search over slot layouts); without any
 * constraint every triangle is at level 0, outside. */
static void check_domain_all_seeds(void)
{
    vor_t d;
    unsigned long bad = 0;
    model_clear();
    (void)vor_init(&d, arena, sizeof arena, 7);
    static const vor_point_t p[] = {{933, 464}, {778, 23},  {822, 700}, {988, 594},
                                    {384, 515}, {851, 803}, {856, 296}};
    insert_all(&d, p, 7);
    static const vor_cdt_limits_t few = {21, 0, 16};
    bad += attach(&d, &few);
    bad += (vor_cdt_domain(&d) == VOR_OK) ? 0u : 1u;
    bad += domain_faults(&d);
    CHECK(bad == 0, "cdt domain from all seeds: %lu wrong", bad);
}

/* A stretch that ends at a vertex may cross cut - 1 triangles (vor_cdt.h,
 * VOR_ERR_NOMEM): no crossing vertex is made at its end. Segment a-b
 * along x = 0, with a column of sites at x = -1 beside it and one site
 * far right, crosses every triangle with corners on both sides of x = 0
 * (a and b are the hull's lowest and highest points on that line), T of
 * them, counted here from the triangulation before it: cut T refuses it
 * with nothing changed, cut T + 1 makes it. */
static uint32_t last_stretch(uint32_t cut, uint32_t *crossed)
{
    vor_t d;
    unsigned long bad = 0;
    const vor_point_t ends[] = {{0, -10}, {0, 100}, {400, 45}};
    fresh(&d, ends, sizeof ends / sizeof ends[0]);
    for (int32_t k = 1; k < 30; k++) {
        vor_point_t column = {-1, 3 * k};
        insert_all(&d, &column, 1);
    }
    vor_cdt_limits_t tight = {CDT_EDGES, CDT_CROSSINGS, cut};
    bad += attach(&d, &tight);
    *crossed = 0;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    (void)vor_cdt_triangles_begin(&it, &d);
    while (vor_cdt_triangles_next(&it, ids) == 1) {
        bool left = false;
        bool right = false;
        for (unsigned k = 0; k < 3u; k++) {
            left = left || (model.at[ids[k]].x < 0);
            right = right || (model.at[ids[k]].x > 0);
        }
        *crossed += (left && right) ? 1u : 0u;
    }
    test_copy_bytes(saved_memory, memory, sizeof memory);
    int err = vor_constrain(&d, 0, 1);
    bad += ((err == VOR_OK) || (err == VOR_ERR_NOMEM)) ? 0u : 1u;
    if (err == VOR_OK) {
        model.a[model.constraints] = 0;
        model.b[model.constraints] = 1;
        model.constraints++;
    } else {
        bad += test_same_bytes(saved_memory, memory, sizeof memory) ? 0u : 1u;
    }
    bad += mesh_faults(&d);
    CHECK(bad == 0, "cdt last stretch: %lu wrong", bad);
    return (err == VOR_OK) ? 1u : 0u;
}

static void check_last_stretch(void)
{
    uint32_t t;
    (void)last_stretch(CDT_CUT, &t);
    uint32_t again;
    unsigned long bad = (t > 20u) ? 0u : 1u; /* the column makes a long fan */
    bad += (last_stretch(t, &again) == 0u) ? 0u : 1u;
    bad += (last_stretch(t + 1u, &again) == 1u) ? 0u : 1u;
    bad += (again == t) ? 0u : 1u;
    CHECK(bad == 0, "cdt last stretch: %u triangles, %lu wrong", t, bad);
}

/* A crossing vertex taken off where a vertex of its ring is left with
 * three neighbours: constraints 2-4 and 5-0 (through site 3) cross at x,
 * and site 0's only other neighbours are sites 1 and 2, so triangle
 * (2, 1, 0) lies outside two of x's four ring edges, 1-0 and 0-2. Taking
 * 2-4 off removes x; the new triangles' links must follow the edges, not
 * the old slots (one of which a new triangle reuses): once they broke. */
static void check_ring_of_three(void)
{
    vor_t d;
    unsigned long bad = 0;
    for (unsigned order = 0; order < 2u; order++) {
        static const vor_point_t p[] = {{-3, -4}, {6, -3}, {-5, -5}, {-2, -1}, {5, 4}, {-1, 2}};
        bad += scene(&d, p, sizeof p / sizeof p[0], &limits);
        bad += add_constraint(&d, 2, 4);
        bad += add_constraint(&d, 5, 0);
        bad += mesh_faults(&d) + ((gather_crossings(&d) == 1u) ? 0u : 1u);
        int err = (order == 0u) ? vor_unconstrain(&d, 2, 4) : vor_unconstrain(&d, 4, 2);
        bad += (err == VOR_OK) ? 0u : 1u;
        model.a[0] = 5;
        model.b[0] = 0;
        model.constraints = 1;
        bad += mesh_faults(&d) + ((gather_crossings(&d) == 0u) ? 0u : 1u);
    }
    CHECK(bad == 0, "cdt crossing off beside a vertex of degree 3: %lu wrong", bad);
}

/* Few sites (4 to 7 on a small grid): a hull site is then often a
 * neighbour of every other vertex, so that the turn around it to an
 * edge's triangle (Lawson's test of an edge a removal freed) may meet
 * all of them, infinity included, and ring vertices of degree 3 are
 * common. Constraints among them, crossing each other, are taken off
 * again one by one in either direction, the triangulation and the mesh's
 * links checked after each. */
static void check_tiny_scenes(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 31337);
    unsigned long bad = 0;
    for (unsigned round = 0; round < 400u; round++) {
        vor_t d;
        uint32_t n = 4u + (test_rng_u32(&rng) % 4u);
        bad += random_scene(&d, &rng, n, 0u, &limits);
        constrain_random(&d, &rng, 1u + (test_rng_u32(&rng) % 4u), &bad);
        bad += mesh_link_faults(&d);
        while (model.constraints > 0u) {
            uint32_t k = test_rng_u32(&rng) % model.constraints;
            uint32_t a = model.a[k];
            uint32_t b = model.b[k];
            int err = ((test_rng_u32(&rng) & 1u) != 0u) ? vor_unconstrain(&d, a, b)
                                                        : vor_unconstrain(&d, b, a);
            bad += (err == VOR_OK) ? 0u : 1u;
            model.constraints--;
            model.a[k] = model.a[model.constraints];
            model.b[k] = model.b[model.constraints];
            bad += mesh_faults(&d);
        }
    }
    CHECK(bad == 0, "cdt tiny scenes: %lu wrong", bad);
}

/* A crossing vertex taken off whose freed slot is the first packed one
 * (the constrained mesh's max_sites), while (u, s, v) takes s's home: five
 * sites, constraints 4-0, 4-1 and 3-2 (which crosses 4-0), then 3-2 off.
 * Site 1's three triangles are then all in home slots, so that treating
 * the packed slot as a home to refill from a star finds nothing to move
 * and leaves the last packed triangle out of the mesh. The links and the
 * triangulation must stay whole. */
static void check_first_packed_freed(void)
{
    unsigned long bad = 0;
    for (unsigned order = 0; order < 2u; order++) {
        vor_t d;
        static const vor_point_t p[] = {{-4, 2}, {2, -1}, {-5, 5}, {2, -4}, {6, 0}};
        bad += scene(&d, p, sizeof p / sizeof p[0], &limits);
        bad += add_constraint(&d, 4, 0);
        bad += add_constraint(&d, 4, 1);
        bad += add_constraint(&d, 3, 2);
        bad += check_cdt(&d) + ((gather_crossings(&d) == 1u) ? 0u : 1u);
        int err = (order == 0u) ? vor_unconstrain(&d, 3, 2) : vor_unconstrain(&d, 2, 3);
        bad += (err == VOR_OK) ? 0u : 1u;
        model.constraints = 2;
        bad += mesh_faults(&d) + ((gather_crossings(&d) == 0u) ? 0u : 1u);
    }
    CHECK(bad == 0, "cdt crossing off freeing the first packed slot: %lu wrong", bad);
}
