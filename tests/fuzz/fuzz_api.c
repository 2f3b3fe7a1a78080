/* SPDX-License-Identifier: MIT */
/*
 * fuzz_api.c - libFuzzer harness: the fuzz bytes are a program of calls on
 * one small diagram (arenas that run out, both index widths: built with
 * -DVOR_INDEX_BITS=16 and 32): builds, inserts, removes, moves, queries,
 * iterators, the two-core builder through a one-thread hook, field frames
 * (vor_field_raster, each pixel against vor_interpolate), Voronoi
 * vertices, the memory figures and the counters. After every call
 * vor_validate must pass; every failing call must leave the vor_t and the
 * arena byte-for-byte unchanged; answers are
 * checked against a model kept here (the sites by id, each duplicate's
 * first occurrence, the freed ids) and brute force with exact wide-integer
 * distances; on small sets the triangles are checked for empty
 * circumcircles, positive area and the count 2n - h - 2; cell centroids
 * against vor_cell and their box; cells clipped to random rooms (simple
 * or not, by brute force; a box room's one piece is vor_cell's cell).
 * Diagrams of odd capacity carry a motion
 * cache (vor_motion_attach), whose bytes a failing call must not change
 * either.
 *
 * Constraints (vor_cdt.h) join the program: attaching constraint memory
 * (also with bad limits, short or misaligned memory), vor_constrain,
 * vor_unconstrain, closed chains of constraints, sites inserted on
 * constraints and at crossings, vor_cdt_domain and the iterators, between
 * the dynamic calls. The model keeps the constraints as signed segments
 * (+1 a vor_constrain, -1 a vor_unconstrain, by their points): a point's
 * coverage is their sum over the segments through it. From it alone, with
 * exact rational arithmetic (fuzz_hpoint.h), the harness derives what the
 * library must hold: the crossing vertices (points off the sites where two
 * lines of positive coverage cross), the constrained edges (the pieces of
 * positive coverage between the vertices on each segment), the errors
 * each call must give (a table that would overflow, a constraint's end
 * removed or moved, a piece not constrained). After every call the
 * constrained triangulation read through the public calls must match:
 * its crossing vertices and constrained edges exactly, its triangles
 * counterclockwise, each edge used once each way, the unpaired ones the
 * hull's pieces, 2v - h - 2 of them, every unconstrained edge locally
 * Delaunay, no vertex inside a triangle's circumcircle visible from the
 * triangle's centroid (on small meshes), and the domain's triangles those
 * at odd nesting levels by a shortest-path flood over the triangles.
 *
 * Weighted sites (vor_power.h): an input whose first byte is POWER_MODE
 * or more is a program of its own on one vor_power_t (power_program):
 * inits, inserts, builds, removals, moves, nearest sites, bad arguments,
 * each followed by power_check,
 * which decides the regular triangulation's invariants by brute force
 * over the lifted sites with fuzz_power's 768-bit determinants, and checks
 * that the power cells tile the whole plane (power_check_cells).
 */
#include <string.h>

#include "fuzz_common.h"
#include "fuzz_hpoint.h"
#include "vor_cdt.h"
#include "vor_power.h"
#include "vor_raster.h"

#define MOST_SITES 24u
#define BUILD_POINTS (MOST_SITES + 4u) /* builds may ask for more than fit */

static uint8_t arena[VOR_ARENA_BYTES(MOST_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t arena_before[sizeof arena];
static uint8_t motion[VOR_MOTION_BYTES(MOST_SITES)] __attribute__((aligned(VOR_MOTION_ALIGN)));
static uint8_t motion_before[sizeof motion];

/* Constraint memory for every limit the harness draws. */
#define MOST_CROSSINGS 12u
#define MOST_VERTICES (MOST_SITES + MOST_CROSSINGS)
#define MOST_CDT_EDGES (3u * MOST_VERTICES)
#define MOST_CUT (2u * MOST_VERTICES + 2u)
#define MOST_ENTRIES 64u /* one a call at most: the program's length */
static uint8_t cdt_memory[VOR_CDT_BYTES(MOST_SITES, MOST_CDT_EDGES, MOST_CROSSINGS, MOST_CUT) + 8u]
    __attribute__((aligned(VOR_CDT_ALIGN)));
static uint8_t cdt_before[sizeof cdt_memory];

/* A constraint made (+1) or taken off (-1) along the segment a-b. */
typedef struct {
    vor_point_t a, b;
    int weight;
} entry_t;

typedef struct {
    vor_t d;
    uint32_t capacity;
    uint32_t count;                 /* ids handed out */
    vor_point_t point[MOST_SITES];  /* by id */
    uint32_t first[MOST_SITES];     /* the id of the first occurrence */
    uint8_t removed[MOST_SITES];    /* freed by vor_remove */
    uint32_t freed[MOST_SITES];     /* freed ids, the most recent last */
    uint32_t freed_count;
    vor_tracker_t tracker;
    int cdt_attached;
    vor_cdt_limits_t limits;
    entry_t entry[MOST_ENTRIES];
    uint32_t entries;
    int domain; /* vor_cdt_domain succeeded and nothing changed since */
} model_t;

static vor_t diagram_before;

static void snapshot(const model_t *m)
{
    memcpy(&diagram_before, &m->d, sizeof m->d);
    memcpy(arena_before, arena, sizeof arena);
    memcpy(motion_before, motion, sizeof motion);
    memcpy(cdt_before, cdt_memory, sizeof cdt_memory);
}

static int unchanged(const model_t *m)
{
    return memcmp(&diagram_before, &m->d, sizeof m->d) == 0 &&
           memcmp(arena_before, arena, sizeof arena) == 0 &&
           memcmp(motion_before, motion, sizeof motion) == 0 &&
           memcmp(cdt_before, cdt_memory, sizeof cdt_memory) == 0;
}

static int is_site(const model_t *m, uint32_t id)
{
    return id < m->count && m->first[id] == id && !m->removed[id];
}

/* The site at p, or m->count. */
static uint32_t site_at(const model_t *m, vor_point_t p)
{
    for (uint32_t i = 0; i < m->count; i++)
        if (is_site(m, i) && m->point[i].x == p.x && m->point[i].y == p.y)
            return i;
    return m->count;
}

static uint32_t first_occurrence(const model_t *m, vor_point_t p, uint32_t before)
{
    for (uint32_t i = 0; i < before; i++)
        if (m->point[i].x == p.x && m->point[i].y == p.y)
            return i;
    return before;
}

static uint32_t distinct_sites(const model_t *m)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < m->count; i++)
        n += is_site(m, i) ? 1u : 0u;
    return n;
}

/* ------------------------------------------------------------------ */
/* Constraints: what the model says the constrained triangulation holds */

/* Vertices by the model's numbering: sites by id, then the crossings the
 * model derives, MOST_SITES + k. */
#define MOST_EXPECTED_EDGES 256u

typedef struct {
    fuzz_hpoint_t point[MOST_SITES + MOST_CROSSINGS];
    uint32_t crossings;
    int too_many_crossings; /* more than MOST_CROSSINGS: no table holds them */
    uint32_t edge_u[MOST_EXPECTED_EDGES], edge_v[MOST_EXPECTED_EDGES]; /* u < v */
    uint32_t edge_cover[MOST_EXPECTED_EDGES];
    uint32_t edges;
    int too_many_edges;
} expected_t;

static expected_t expected; /* of the model after the last call */

static int entry_collinear(const entry_t *e, const entry_t *k)
{
    return fuzz_orient(e->a, e->b, k->a) == 0 && fuzz_orient(e->a, e->b, k->b) == 0;
}

/* Is p on the closed segment of entry k (a point of its line)? */
static int entry_holds(const entry_t *k, const fuzz_hpoint_t *p)
{
    fuzz_hpoint_t a = fuzz_hpoint_site(k->a), b = fuzz_hpoint_site(k->b);
    return fuzz_hpoint_same(p, &a) || fuzz_hpoint_same(p, &b) || fuzz_hpoint_between(&a, p, &b);
}

/* The coverage of the piece p-q (both on entry e's line): the weights of
 * the entries on that line whose segments hold it. */
static int piece_cover(const model_t *m, const entry_t *e, const fuzz_hpoint_t *p,
                       const fuzz_hpoint_t *q)
{
    int cover = 0;
    for (uint32_t k = 0; k < m->entries; k++)
        if (entry_collinear(e, &m->entry[k]) && entry_holds(&m->entry[k], p) &&
            entry_holds(&m->entry[k], q))
            cover += m->entry[k].weight;
    return cover;
}

/* The coverage at a point strictly inside entry e, no site. */
static int point_cover(const model_t *m, const entry_t *e, const fuzz_hpoint_t *p)
{
    return piece_cover(m, e, p, p);
}

static int is_site_point(const model_t *m, const expected_t *x, const fuzz_hpoint_t *p)
{
    for (uint32_t i = 0; i < m->count; i++)
        if (is_site(m, i) && fuzz_hpoint_same(p, &x->point[i]))
            return 1;
    return 0;
}

/* Vertices strictly inside segment a-b, sorted from a to b, into on[]. */
static uint32_t vertices_inside(const model_t *m, const expected_t *x, vor_point_t pa,
                                vor_point_t pb, uint32_t *on)
{
    fuzz_hpoint_t a = fuzz_hpoint_site(pa), b = fuzz_hpoint_site(pb);
    uint32_t n = 0;
    for (uint32_t v = 0; v < MOST_SITES + x->crossings; v++) {
        if (v < MOST_SITES && !is_site(m, v))
            continue;
        const fuzz_hpoint_t *p = &x->point[v];
        if (fuzz_hpoint_orient(&a, &b, p) == 0 && fuzz_hpoint_between(&a, p, &b))
            on[n++] = v;
    }
    int axis = fuzz_hpoint_compare(&a, &b, 0) != 0 ? 0 : 1;
    int way = fuzz_hpoint_compare(&b, &a, axis);
    for (uint32_t i = 1; i < n; i++)
        for (uint32_t j = i; j > 0 && fuzz_hpoint_compare(&x->point[on[j - 1]],
                                                          &x->point[on[j]], axis) == way; j--) {
            uint32_t t = on[j];
            on[j] = on[j - 1];
            on[j - 1] = t;
        }
    return n;
}

/* The crossings and constrained edges of the model's constraints. */
static void derive(const model_t *m, expected_t *x)
{
    for (uint32_t i = 0; i < m->count; i++)
        x->point[i] = fuzz_hpoint_site(m->point[i]);
    x->crossings = 0;
    x->too_many_crossings = 0;
    x->edges = 0;
    x->too_many_edges = 0;
    for (uint32_t i = 0; i < m->entries; i++) {
        const entry_t *e = &m->entry[i];
        for (uint32_t j = 0; j < i && e->weight > 0; j++) {
            const entry_t *f = &m->entry[j];
            /* interiors crossing at one point */
            if (f->weight < 0 || fuzz_orient(e->a, e->b, f->a) * fuzz_orient(e->a, e->b, f->b) >= 0 ||
                fuzz_orient(f->a, f->b, e->a) * fuzz_orient(f->a, f->b, e->b) >= 0)
                continue;
            fuzz_hpoint_t p;
            FUZZ_REQUIRE(fuzz_hpoint_crossing(&p, e->a, e->b, f->a, f->b), "harness: parallel crossing");
            if (is_site_point(m, x, &p) || point_cover(m, e, &p) <= 0 || point_cover(m, f, &p) <= 0)
                continue;
            int seen = 0;
            for (uint32_t k = 0; k < x->crossings && !seen; k++)
                seen = fuzz_hpoint_same(&p, &x->point[MOST_SITES + k]);
            if (seen)
                continue;
            if (x->crossings == MOST_CROSSINGS) {
                x->too_many_crossings = 1;
                return;
            }
            x->point[MOST_SITES + x->crossings++] = p;
        }
    }
    uint32_t on[MOST_SITES + MOST_CROSSINGS + 2];
    for (uint32_t i = 0; i < m->entries; i++) {
        const entry_t *e = &m->entry[i];
        if (e->weight < 0)
            continue;
        uint32_t n = vertices_inside(m, x, e->a, e->b, on + 1);
        on[0] = site_at(m, e->a);
        on[n + 1] = site_at(m, e->b);
        for (uint32_t k = 0; k <= n; k++) {
            uint32_t u = on[k] < on[k + 1] ? on[k] : on[k + 1];
            uint32_t v = on[k] < on[k + 1] ? on[k + 1] : on[k];
            int seen = 0;
            for (uint32_t j = 0; j < x->edges && !seen; j++)
                seen = x->edge_u[j] == u && x->edge_v[j] == v;
            int cover = seen ? 0 : piece_cover(m, e, &x->point[u], &x->point[v]);
            FUZZ_REQUIRE(cover >= 0, "harness: a piece taken off more often than made");
            if (cover == 0)
                continue;
            if (x->edges == MOST_EXPECTED_EDGES) {
                x->too_many_edges = 1;
                return;
            }
            x->edge_u[x->edges] = u;
            x->edge_v[x->edges] = v;
            x->edge_cover[x->edges] = (uint32_t)cover;
            x->edges++;
        }
    }
}

/* Does a constrained edge end at site s? */
static int ends_constraint(const expected_t *x, uint32_t s)
{
    for (uint32_t j = 0; j < x->edges; j++)
        if (x->edge_u[j] == s || x->edge_v[j] == s)
            return 1;
    return 0;
}

/* Does point p lie strictly inside a constrained edge? */
static int splits_edge(const expected_t *x, vor_point_t p)
{
    fuzz_hpoint_t h = fuzz_hpoint_site(p);
    for (uint32_t j = 0; j < x->edges; j++) {
        const fuzz_hpoint_t *u = &x->point[x->edge_u[j]], *v = &x->point[x->edge_v[j]];
        if (fuzz_hpoint_orient(u, v, &h) == 0 && fuzz_hpoint_between(u, &h, v))
            return 1;
    }
    return 0;
}

/* Must an insertion (or a move) of a site at p fail for the edge table? */
static int split_overflows(const model_t *m, vor_point_t p)
{
    return m->cdt_attached && expected.edges >= m->limits.edges && splits_edge(&expected, p);
}

/* A hint as a caller might pass it: none, a site, a duplicate, garbage. */
static uint32_t draw_hint(fuzz_reader_t *r, const model_t *m)
{
    uint8_t b = fuzz_u8(r);
    if (b < 64)
        return VOR_NO_HINT;
    if (b < 240)
        return m->count ? (uint32_t)b % m->count : b;
    return b == 255 ? 0x7fffffffu : (uint32_t)b;
}

static int hint_valid(const model_t *m, uint32_t hint)
{
    return hint == VOR_NO_HINT || is_site(m, hint);
}

/* Orders ids by exact distance to q, ties by id (insertion sort: small n). */
static uint32_t brute_order(const model_t *m, int32_t qx, int32_t qy, uint32_t *order)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < m->count; i++) {
        if (!is_site(m, i))
            continue;
        unsigned __int128 di = fuzz_distance2(qx, qy, m->point[i]);
        uint32_t at = n++;
        while (at > 0 && fuzz_distance2(qx, qy, m->point[order[at - 1]]) > di) {
            order[at] = order[at - 1];
            at--;
        }
        order[at] = i;
    }
    return n;
}

static void check_cdt(const model_t *m);

/* After every call: the invariants, the memory figures against the model,
 * and the counters (read-only: neither may change the diagram). */
static void check_valid(const model_t *m)
{
    vor_violation_t violation;
    FUZZ_REQUIRE(vor_validate(&m->d, &violation) == VOR_OK, "vor_validate failed");
    vor_memory_t memory;
    vor_stats_t stats;
    uint32_t n = distinct_sites(m);
    snapshot(m);
    FUZZ_REQUIRE(vor_memory(&m->d, &memory) == VOR_OK && memory.sites == m->count &&
                     memory.arena_bytes == VOR_ARENA_BYTES(m->capacity) &&
                     memory.triangles == (n >= 2u ? 2u * n - 2u : 0u) &&
                     memory.used_bytes <= memory.arena_bytes,
                 "memory: figures disagree with the model");
    FUZZ_REQUIRE(vor_stats(&m->d, &stats) == (VOR_STATS ? VOR_OK : VOR_ERR_ARG),
                 "stats: wrong result for this build");
    FUZZ_REQUIRE(vor_memory(&m->d, NULL) == VOR_ERR_ARG && vor_stats(&m->d, NULL) == VOR_ERR_ARG,
                 "memory, stats: NULL accepted");
    FUZZ_REQUIRE(unchanged(m), "memory or stats changed the diagram");
    if (m->cdt_attached)
        check_cdt(m);
}

/* The model after a successful build of points[0 .. n). */
static void model_build(model_t *m, const vor_point_t *points, uint32_t n,
                        const uint32_t *duplicate_of)
{
    m->count = 0;
    m->freed_count = 0;
    memset(m->removed, 0, sizeof m->removed);
    for (uint32_t i = 0; i < n; i++) {
        m->point[i] = points[i];
        m->first[i] = first_occurrence(m, points[i], i);
        m->count = i + 1;
        FUZZ_REQUIRE(duplicate_of[i] == m->first[i], "build: wrong duplicate_of");
    }
}

/* Fork hooks of vor_build_dc_forked on one thread: the "other core" runs
 * the work before fork returns, or there is none. */
static int fork_now(void *context, void (*work)(void *arg), void *arg)
{
    (void)context;
    work(arg);
    return 0;
}

static int fork_refuse(void *context, void (*work)(void *arg), void *arg)
{
    (void)context;
    (void)work;
    (void)arg;
    return 1;
}

static void join_now(void *context)
{
    (void)context;
}

static void op_build(fuzz_reader_t *r, model_t *m, vor_point_t *previous, int divide)
{
    vor_point_t points[BUILD_POINTS];
    uint32_t duplicate_of[BUILD_POINTS];
    uint32_t n = fuzz_u8(r) % (BUILD_POINTS + 1u);
    uint8_t how = fuzz_u8(r);
    for (uint32_t i = 0; i < n; i++)
        points[i] = fuzz_point(r, previous);
    snapshot(m);
    int result;
    if (divide && (how & 8u)) {
        /* the two-core builder through a hook that runs the work at once,
         * or refuses to fork (vor runs it itself); 8..15 sites or more */
        vor_build_options_t options = {VOR_ORDER_QUADTREE, (enum vor_dc_split)(how % 3u),
                                       (uint32_t)how >> 5};
        vor_fork_join_t hook = {(how & 16u) ? fork_refuse : fork_now, join_now, NULL};
        result = vor_build_dc_forked(&m->d, points, n, &options, duplicate_of, &hook);
    } else if (divide) {
        vor_build_options_t options = {VOR_ORDER_QUADTREE, (enum vor_dc_split)(how % 3u), 0};
        result = vor_build_dc(&m->d, points, n, &options, duplicate_of);
    } else {
        vor_build_options_t options = {(enum vor_order)(how % 3u), VOR_DC_QUADTREE, 0};
        result = vor_build(&m->d, points, n, (how & 4u) ? NULL : &options, duplicate_of);
    }
    int bad_mode = how % 3u == 2u && (divide || !(how & 4u));
    if (bad_mode || n > m->capacity) {
        /* either error may be reported first when both apply */
        FUZZ_REQUIRE(bad_mode ? result == VOR_ERR_ARG || (n > m->capacity && result == VOR_ERR_FULL)
                              : result == VOR_ERR_FULL,
                     "build: a bad request did not fail as documented");
        FUZZ_REQUIRE(unchanged(m), "build: failure changed the diagram");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "build failed");
    model_build(m, points, n, duplicate_of);
    m->entries = 0; /* the constrained triangulation starts again */
    m->domain = 0;
}

/* vor_insert (near: vor_insert_near from hint) of p, checked. */
static void insert_checked(model_t *m, vor_point_t p, int near, uint32_t hint)
{
    uint32_t id = 0xdeadbeefu;
    snapshot(m);
    int result = near ? vor_insert_near(&m->d, p, hint, &id)
                      : vor_insert(&m->d, p, &id);
    uint32_t first = site_at(m, p);
    if (near && !hint_valid(m, hint)) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG, "insert_near: a bad hint was accepted");
    } else if (first < m->count) {
        FUZZ_REQUIRE(result == VOR_ERR_DUPLICATE && id == first, "insert: duplicate missed");
    } else if (m->count == m->capacity && m->freed_count == 0) {
        FUZZ_REQUIRE(result == VOR_ERR_FULL, "insert: full diagram accepted a site");
    } else if (split_overflows(m, p)) {
        FUZZ_REQUIRE(result == VOR_ERR_NOMEM, "insert: a split beyond the edge table accepted");
    } else {
        /* the most recently freed id first */
        uint32_t expected_id = m->freed_count ? m->freed[--m->freed_count] : m->count++;
        FUZZ_REQUIRE(result == VOR_OK && id == expected_id, "insert failed or wrong id");
        m->point[id] = p;
        m->first[id] = id;
        m->removed[id] = 0;
        m->domain = 0;
        return;
    }
    FUZZ_REQUIRE(unchanged(m), "insert: failure changed the diagram");
}

static void op_insert(fuzz_reader_t *r, model_t *m, vor_point_t *previous, int near)
{
    vor_point_t p = fuzz_point(r, previous);
    uint32_t hint = near ? draw_hint(r, m) : VOR_NO_HINT;
    insert_checked(m, p, near, hint);
}

/* ------------------------------------------------------------------ */
/* Natural-neighbour coordinates (vor_sibson, vor_laplace, vor_interpolate) */

static __int128 orient128(vor_point_t a, vor_point_t b, vor_point_t c)
{
    return (__int128)((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) -
           (__int128)((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
}

/* q in the closed convex hull of the distinct sites, by brute force. */
static int brute_in_hull(const model_t *m, vor_point_t q)
{
    uint32_t s[MOST_SITES], n = 0;
    for (uint32_t i = 0; i < m->count; i++)
        if (is_site(m, i))
            s[n++] = i;
    if (n == 0)
        return 0;
    uint32_t far = 0; /* a site off the line of s[0] and s[1], if any */
    while (far < n && (n < 2 || orient128(m->point[s[0]], m->point[s[1]], m->point[s[far]]) == 0))
        far++;
    if (far == n) { /* collinear (or one site): on the segment */
        vor_point_t lo = m->point[s[0]], hi = lo;
        for (uint32_t i = 0; i < n; i++) {
            vor_point_t p = m->point[s[i]];
            if (p.x < lo.x || (p.x == lo.x && p.y < lo.y)) lo = p;
            if (p.x > hi.x || (p.x == hi.x && p.y > hi.y)) hi = p;
        }
        return orient128(lo, hi, q) == 0 &&
               (q.x > lo.x || (q.x == lo.x && q.y >= lo.y)) &&
               (q.x < hi.x || (q.x == hi.x && q.y <= hi.y));
    }
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = 0; j < n; j++) {
            vor_point_t a = m->point[s[i]], b = m->point[s[j]];
            if (i == j || orient128(a, b, q) >= 0)
                continue;
            uint32_t k = 0;
            while (k < n && orient128(a, b, m->point[s[k]]) >= 0)
                k++;
            if (k == n)
                return 0; /* a supporting line with q strictly outside */
        }
    return 1;
}

/* acc += w * v over `words` 32-bit words (two's complement), v signed
 * below 2^62 in magnitude, w non-negative of wn words. */
static void add_times(uint32_t *acc, size_t words, const uint32_t *w, size_t wn, int64_t v)
{
    uint64_t mag = v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
    uint32_t t[4 * MOST_SITES + 16];
    size_t tn = wn + 3;
    memset(t, 0, sizeof t);
    for (size_t h = 0; h < 2; h++) {
        uint32_t part = (uint32_t)(mag >> (32 * h));
        uint64_t carry = 0;
        for (size_t i = 0; i + h < tn; i++) {
            uint64_t x = (uint64_t)(i < wn ? w[i] : 0u) * part + t[i + h] + carry;
            t[i + h] = (uint32_t)x;
            carry = x >> 32;
        }
    }
    if (v < 0) { /* negate t over `words` */
        uint64_t carry = 1;
        for (size_t i = 0; i < words; i++) {
            uint64_t x = (uint64_t)(uint32_t)~(i < tn ? t[i] : 0u) + carry;
            t[i] = (uint32_t)x;
            carry = x >> 32;
        }
        tn = words;
    }
    uint64_t carry = 0;
    for (size_t i = 0; i < words; i++) {
        uint64_t x = (uint64_t)acc[i] + (i < tn ? t[i] : 0u) + carry;
        acc[i] = (uint32_t)x;
        carry = x >> 32;
    }
}

static int all_zero(const uint32_t *a, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] != 0u)
            return 0;
    return 1;
}

/* The coordinates of q (Sibson's or Laplace's) after a nearest query:
 * the diagram unchanged; the documented error for a bad hint, no sites,
 * a point outside the brute-force hull; inside, positive weights adding
 * up to the denominator and linear precision, exactly; a scratch one
 * byte short of the documented size refused with the count alone. */
static void check_natural(model_t *m, vor_point_t q, uint32_t hint, uint32_t sites, int laplace)
{
    static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(MOST_SITES)];
    vor_coordinates_t out, before;
    memset(&out, 0xa5, sizeof out);
    before = out;
    snapshot(m);
    int result = (laplace ? vor_laplace : vor_sibson)(&m->d, q, hint, scratch, sizeof scratch, &out);
    FUZZ_REQUIRE(unchanged(m), "sibson changed the diagram");
    if (!hint_valid(m, hint) || sites == 0) {
        /* as vor_nearest: a bad hint on an empty diagram may be either */
        FUZZ_REQUIRE((hint_valid(m, hint) ? result == VOR_ERR_EMPTY
                      : sites ? result == VOR_ERR_ARG
                              : (result == VOR_ERR_ARG || result == VOR_ERR_EMPTY)) &&
                         memcmp(&out, &before, sizeof out) == 0,
                     "sibson: bad hint or empty accepted, or wrote");
        return;
    }
    if (!brute_in_hull(m, q)) {
        FUZZ_REQUIRE(result == VOR_ERR_OUTSIDE && memcmp(&out, &before, sizeof out) == 0,
                     "sibson: a point outside the hull accepted, or wrote");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK && out.count >= 1 && out.count < MOST_SITES && out.limbs >= 1 &&
                     out.limbs < 4 * MOST_SITES + 8,
                 "sibson: a point in the hull refused");
    size_t words = out.limbs + 4;
    uint32_t sum[4 * MOST_SITES + 16], x[4 * MOST_SITES + 16], y[4 * MOST_SITES + 16];
    memset(sum, 0, sizeof sum);
    memset(x, 0, sizeof x);
    memset(y, 0, sizeof y);
    for (uint32_t i = 0; i < out.count; i++) {
        const uint32_t *w = out.weights + (size_t)i * out.limbs;
        FUZZ_REQUIRE(is_site(m, out.sites[i]) && !all_zero(w, out.limbs), "sibson: a bad neighbour");
        vor_point_t p = m->point[out.sites[i]];
        add_times(sum, words, w, out.limbs, 1);
        add_times(x, words, w, out.limbs, (int64_t)p.x - q.x);
        add_times(y, words, w, out.limbs, (int64_t)p.y - q.y);
    }
    add_times(sum, words, out.denominator, out.limbs, -1);
    FUZZ_REQUIRE(all_zero(sum, words), "sibson: the weights do not add up to the denominator");
    FUZZ_REQUIRE(all_zero(x, words) && all_zero(y, words), "sibson: no linear precision");
    uint32_t k = out.count;
    memset(&out, 0xa5, sizeof out);
    result = (laplace ? vor_laplace : vor_sibson)(&m->d, q, hint, scratch,
                                                  VOR_SIBSON_SCRATCH_BYTES(k) - 9u, &out);
    before.count = k;
    FUZZ_REQUIRE(result == VOR_ERR_NOMEM && memcmp(&out, &before, sizeof out) == 0,
                 "sibson: a short scratch accepted, or more than the count written");
}

/* Field frames' flush: the rows arrive in order into one frame. */
typedef struct {
    int32_t px[5 * 3];
    uint32_t next_row;
    uint32_t calls;
} field_sink_t;

static int field_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    field_sink_t *s = user;
    FUZZ_REQUIRE(first_row == s->next_row && rows >= 1 && rows <= 2 && first_row + rows <= 3,
                 "field: a band out of order");
    memcpy(s->px + first_row * 5u, pixels, (size_t)rows * 5u * sizeof(int32_t));
    s->next_row = first_row + rows;
    s->calls++;
    return 0;
}

/* A 5 x 3 field frame around q (steps and method from q's bits, no byte
 * read: the corpora keep their meaning), in bands of 2 rows: each pixel
 * what vor_interpolate (or its Laplace sibling) gives at its centre,
 * max_neighbours the most of them, the diagram unchanged; a frame past
 * int32 refused with nothing written; no sites: VOR_ERR_EMPTY. */
static void check_field(model_t *m, vor_point_t q, uint32_t sites)
{
    static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(MOST_SITES)];
    static int32_t values[MOST_SITES];
    for (uint32_t i = 0; i < MOST_SITES; i++)
        values[i] = (int32_t)(0x9E3779B9u * (i + 1u) + (uint32_t)q.x);
    int laplace = (q.y & 2) != 0;
    vor_raster_frame_t frame = {q.x, q.y, 1 + (q.x & 3), 1 + ((q.y >> 2) & 3), 5, 3};
    int64_t last_x = (int64_t)frame.origin_x + 4 * (int64_t)frame.step_x;
    int64_t last_y = (int64_t)frame.origin_y + 2 * (int64_t)frame.step_y;
    int32_t band[5 * 2];
    field_sink_t sink;
    memset(&sink, 0, sizeof sink);
    memset(band, 0xa5, sizeof band);
    uint32_t most = 0xdeadbeefu;
    vor_field_output_t out;
    memset(&out, 0, sizeof out);
    out.kind = VOR_FIELD_VALUE;
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = 2;
    out.flush = field_flush;
    out.user = &sink;
    out.outside = INT32_MIN;
    out.max_neighbours = &most;
    vor_field_options_t options = {laplace ? VOR_FIELD_LAPLACE : VOR_FIELD_SIBSON};
    snapshot(m);
    int result = vor_field_raster(&m->d, values, &frame, &out, &options, scratch, sizeof scratch);
    FUZZ_REQUIRE(unchanged(m), "field changed the diagram");
    if (last_x > INT32_MAX || last_y > INT32_MAX || sites == 0) {
        FUZZ_REQUIRE(result == (sites == 0 && last_x <= INT32_MAX && last_y <= INT32_MAX
                                    ? VOR_ERR_EMPTY : VOR_ERR_ARG) &&
                         sink.calls == 0 && most == 0xdeadbeefu,
                     "field: a bad frame or no sites accepted, or wrote");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK && sink.calls == 2 && sink.next_row == 3, "field: refused");
    uint32_t most_seen = 0;
    for (uint32_t j = 0; j < 3; j++)
        for (uint32_t i = 0; i < 5; i++) {
            vor_point_t p = {(int32_t)(frame.origin_x + (int32_t)i * frame.step_x),
                             (int32_t)(frame.origin_y + (int32_t)j * frame.step_y)};
            vor_interpolation_t v;
            int e = (laplace ? vor_interpolate_laplace : vor_interpolate)(
                &m->d, values, p, VOR_NO_HINT, scratch, sizeof scratch, &v);
            FUZZ_REQUIRE(e == VOR_OK || e == VOR_ERR_OUTSIDE, "field: interpolate failed");
            FUZZ_REQUIRE(sink.px[j * 5 + i] == (e == VOR_OK ? v.value : INT32_MIN),
                         "field: a pixel differs from vor_interpolate");
            if (e == VOR_OK && v.neighbours > most_seen)
                most_seen = v.neighbours;
        }
    FUZZ_REQUIRE(most == most_seen, "field: max_neighbours wrong");
}

/* vor_locate at q against every triangle the iterator lists, each
 * tested with exact orientations and the documented tie rule (q moved up
 * by e, then right by e^4); vor_within at q for r2 against the model's
 * exact distances. Neither reads fuzz bytes (the corpora keep their
 * meaning): r2 is the squared distance of the model's site `at` in q's
 * order, less one when `less`, or 0 and every uint64. */
static int tie_orient(vor_point_t a, vor_point_t b, vor_point_t q)
{
    int o = fuzz_orient(a, b, q);
    o = o ? o : (b.x > a.x) - (b.x < a.x);
    return o ? o : (a.y > b.y) - (a.y < b.y);
}

static void check_locate(model_t *m, vor_point_t q, uint32_t hint, uint32_t n)
{
    uint32_t ids[3] = {7u, 7u, 7u}, v[3], holding = 0, want[3] = {0, 0, 0};
    vor_triangle_iter_t it;
    FUZZ_REQUIRE(vor_triangles_begin(&it, &m->d) == VOR_OK, "locate: triangles_begin");
    while (vor_triangles_next(&it, v))
        if (tie_orient(m->point[v[0]], m->point[v[1]], q) > 0 &&
            tie_orient(m->point[v[1]], m->point[v[2]], q) > 0 &&
            tie_orient(m->point[v[2]], m->point[v[0]], q) > 0) {
            holding++;
            memcpy(want, v, sizeof want);
        }
    FUZZ_REQUIRE(holding <= 1u, "locate: two triangles hold the moved point");
    snapshot(m);
    int result = vor_locate(&m->d, q, hint, ids);
    FUZZ_REQUIRE(unchanged(m), "locate changed the diagram");
    if (!hint_valid(m, hint) || n == 0) {
        FUZZ_REQUIRE(result == (n == 0 && hint_valid(m, hint) ? VOR_ERR_EMPTY : VOR_ERR_ARG) ||
                         (n == 0 && result < 0),
                     "locate: bad hint or empty accepted");
        FUZZ_REQUIRE(ids[0] == 7u && ids[1] == 7u && ids[2] == 7u, "locate: wrote on an error");
        return;
    }
    if (holding == 0u) {
        FUZZ_REQUIRE(result == VOR_ERR_OUTSIDE && ids[0] == 7u, "locate: not outside, or wrote");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK && memcmp(ids, want, sizeof want) == 0, "locate: wrong triangle");
}

static void check_within(model_t *m, vor_point_t q, uint32_t hint, const uint32_t *order, uint32_t n,
                         uint32_t at, int less)
{
    uint64_t r2 = 0;
    if (at < n) {
        unsigned __int128 d2 = fuzz_distance2(q.x, q.y, m->point[order[at]]);
        r2 = d2 > UINT64_MAX ? UINT64_MAX : (uint64_t)d2;
        r2 -= (less && r2 > 0u && d2 <= UINT64_MAX) ? 1u : 0u;
    } else if (at == n) {
        r2 = UINT64_MAX;
    }
    uint32_t want[MOST_SITES], count = 0;
    for (uint32_t i = 0; i < m->count; i++)
        if (is_site(m, i) && fuzz_distance2(q.x, q.y, m->point[i]) <= r2)
            want[count++] = i;
    uint32_t got[MOST_SITES + 1u], found = 0xdeadbeefu;
    memset(got, 0xa5, sizeof got);
    snapshot(m);
    int result = vor_within(&m->d, q, r2, hint, got, MOST_SITES, &found);
    FUZZ_REQUIRE(unchanged(m), "within changed the diagram");
    if (!hint_valid(m, hint) || n == 0) {
        FUZZ_REQUIRE(result < 0 && found == 0xdeadbeefu && got[0] == 0xa5a5a5a5u,
                     "within: bad hint or empty accepted, or wrote");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK && found == count && got[count] == 0xa5a5a5a5u, "within: wrong count");
    FUZZ_REQUIRE(memcmp(got, want, count * sizeof got[0]) == 0, "within: wrong sites or order");
    if (count > 0u) {
        memset(got, 0xa5, sizeof got);
        found = 0;
        result = vor_within(&m->d, q, r2, hint, got, count - 1u, &found);
        FUZZ_REQUIRE(result == VOR_ERR_BUFFER && found == count && got[0] == 0xa5a5a5a5u && unchanged(m),
                     "within: a short buffer accepted, or written");
    }
}

static void op_nearest(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
    vor_point_t q = fuzz_point(r, previous);
    uint32_t hint = draw_hint(r, m);
    uint32_t order[MOST_SITES];
    uint32_t n = brute_order(m, q.x, q.y, order);
    uint32_t id = 0xdeadbeefu;
    check_natural(m, q, hint, n, (q.x & 1) != 0);
    check_field(m, q, n);
    check_locate(m, q, hint, n);
    check_within(m, q, hint, order, n, (uint32_t)q.y % (n + 2u), (q.x & 2) != 0);
    snapshot(m);
    int result = vor_nearest(&m->d, q, hint, &id);
    FUZZ_REQUIRE(unchanged(m), "nearest changed the diagram");
    if (!hint_valid(m, hint) || n == 0) {
        FUZZ_REQUIRE(result < 0 && id == 0xdeadbeefu, "nearest: bad hint or empty accepted");
        FUZZ_REQUIRE(hint_valid(m, hint) ? result == VOR_ERR_EMPTY
                     : n ? result == VOR_ERR_ARG : 1,
                     "nearest: wrong error");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK && id == order[0], "nearest: wrong site");
}

static void op_nearest_k(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
    vor_point_t q = fuzz_point(r, previous);
    uint32_t hint = draw_hint(r, m);
    uint32_t k = fuzz_u8(r) % (MOST_SITES + 3u);
    uint32_t order[MOST_SITES], got[MOST_SITES + 3u], found = 0xdeadbeefu;
    uint32_t n = brute_order(m, q.x, q.y, order);
    memset(got, 0xa5, sizeof got);
    snapshot(m);
    int result = vor_nearest_k(&m->d, q, hint, k, got, &found);
    FUZZ_REQUIRE(unchanged(m), "nearest_k changed the diagram");
    if (!hint_valid(m, hint) || n == 0) {
        FUZZ_REQUIRE(result < 0 && found == 0xdeadbeefu && got[0] == 0xa5a5a5a5u,
                     "nearest_k: bad hint or empty accepted, or wrote");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK && found == (k < n ? k : n), "nearest_k: wrong count");
    for (uint32_t i = 0; i < found; i++)
        FUZZ_REQUIRE(got[i] == order[i], "nearest_k: wrong site or order");
    for (uint32_t i = found; i < MOST_SITES + 3u; i++)
        FUZZ_REQUIRE(got[i] == 0xa5a5a5a5u, "nearest_k: wrote past found");
}

static void op_track(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
    uint32_t order[MOST_SITES];
    uint32_t steps = 1u + fuzz_u8(r) % 8u;
    for (uint32_t s = 0; s < steps; s++) {
        vor_point_t q = fuzz_point(r, previous);
        uint32_t n = brute_order(m, q.x, q.y, order);
        uint32_t id = 0xdeadbeefu;
        int result = vor_track(&m->tracker, q, &id);
        if (n == 0)
            FUZZ_REQUIRE(result == VOR_ERR_EMPTY && id == 0xdeadbeefu, "track on empty");
        else
            FUZZ_REQUIRE(result == VOR_OK && id == order[0], "track: wrong site");
    }
}

/* Boxes as callers get them wrong: inverted, empty, huge, ordinary. */
static vor_box_t draw_box(fuzz_reader_t *r, vor_point_t *previous)
{
    vor_point_t a = fuzz_point(r, previous), b = fuzz_point(r, previous);
    vor_box_t box = {a.x, a.y, b.x, b.y};
    switch (fuzz_u8(r) % 4u) {
    case 0: /* ordered */
        if (box.x0 > box.x1) {
            box.x0 = b.x;
            box.x1 = a.x;
        }
        if (box.y0 > box.y1) {
            box.y0 = b.y;
            box.y1 = a.y;
        }
        break;
    case 1:
        box = (vor_box_t){INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX};
        break;
    case 2:
        box.x1 = box.x0;
        break;
    default: /* as drawn: often inverted */
        break;
    }
    return box;
}

static void op_cells(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
    vor_box_t box = draw_box(r, previous);
    uint32_t capacity = fuzz_u8(r) % (VOR_CELL_MAX_VERTICES(MOST_SITES) + 1u);
    vor_point_t vertices[VOR_CELL_MAX_VERTICES(MOST_SITES)];
    int inverted = box.x0 > box.x1 || box.y0 > box.y1;
    vor_cell_iter_t it;
    uint32_t site, count, cells = 0, last = 0;
    int begun = vor_cells_begin(&it, &m->d, &box);
    FUZZ_REQUIRE(begun == (inverted ? VOR_ERR_ARG : VOR_OK), "cells: begin");
    /* next is 1 or 0, and a while over it ends: the guard only bounds
     * the retries with larger buffers */
    for (uint32_t guard = 0; guard < 2u * MOST_SITES + 2u; guard++) {
        int result = vor_cells_next(&it, &site, vertices, capacity, &count);
        FUZZ_REQUIRE(result == 0 || result == 1, "cells: next neither 1 nor 0");
        if (result == 0) {
            int why = vor_cells_error(&it);
            if (inverted) {
                FUZZ_REQUIRE(why == VOR_ERR_ARG, "cells: inverted box accepted");
                break;
            }
            if (why != VOR_ERR_BUFFER) {
                FUZZ_REQUIRE(why == VOR_OK, "cells: wrong reason to stop");
                break;
            }
            FUZZ_REQUIRE(count > capacity && count <= VOR_CELL_MAX_VERTICES(MOST_SITES) &&
                             is_site(m, site),
                         "cells: wrong size needed");
            capacity = count;
            continue;
        }
        FUZZ_REQUIRE(!inverted && is_site(m, site) && (cells == 0 || site > last),
                     "cells: wrong site");
        for (uint32_t i = 0; i < count; i++)
            FUZZ_REQUIRE(vertices[i].x >= box.x0 && vertices[i].x <= box.x1 &&
                             vertices[i].y >= box.y0 && vertices[i].y <= box.y1,
                         "cells: a vertex outside the box");
        last = site;
        cells++;
    }
    FUZZ_REQUIRE(inverted || cells == distinct_sites(m), "cells: not one cell per site");
}

/* vor_remove of a random id: a site, a duplicate's, a freed or unused one. */
static void op_remove(fuzz_reader_t *r, model_t *m)
{
    uint32_t id = draw_hint(r, m);
    snapshot(m);
    int result = vor_remove(&m->d, id);
    if (!is_site(m, id)) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && unchanged(m), "remove: a non-site accepted");
        return;
    }
    if (m->cdt_attached && ends_constraint(&expected, id)) {
        FUZZ_REQUIRE(result == VOR_ERR_CONSTRAINED && unchanged(m),
                     "remove: a constraint's end removed, or the refusal changed memory");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "remove failed");
    m->domain = 0;
    m->removed[id] = 1;
    m->freed[m->freed_count++] = id;
}

/* vor_move of a random id to a pattern point (often another site). */
static void op_move(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
    uint32_t id = draw_hint(r, m);
    vor_point_t p = fuzz_point(r, previous);
    if (fuzz_u8(r) < 64 && m->count) /* onto a site (maybe itself) */
        p = m->point[fuzz_u8(r) % m->count];
    uint32_t existing = 0xdeadbeefu, other = site_at(m, p);
    snapshot(m);
    int result = vor_move(&m->d, id, p, &existing);
    if (!is_site(m, id)) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && unchanged(m), "move: a non-site accepted");
        return;
    }
    if (other < m->count && other != id) {
        FUZZ_REQUIRE(result == VOR_ERR_DUPLICATE && existing == other && unchanged(m),
                     "move onto another site: not its duplicate, or changed the diagram");
        return;
    }
    if (other != id && m->cdt_attached && ends_constraint(&expected, id)) {
        FUZZ_REQUIRE(result == VOR_ERR_CONSTRAINED && unchanged(m),
                     "move: a constraint's end moved, or the refusal changed memory");
        return;
    }
    if (other != id && split_overflows(m, p)) {
        FUZZ_REQUIRE(result == VOR_ERR_NOMEM && unchanged(m),
                     "move: a split beyond the edge table accepted, or the refusal changed memory");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "move failed");
    m->point[id] = p;
    m->domain = m->domain && other == id; /* onto its own point: nothing changes */
}

/* vor_cell_centroid of a random id and box, with scratch exactly as large
 * as documented or smaller: checked against vor_cell's count and the box. */
static void op_centroid(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
    static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(MOST_SITES)) + 1u];
    vor_box_t box = draw_box(r, previous);
    uint32_t site = draw_hint(r, m);
    uint8_t how = fuzz_u8(r);
    vor_point_t vertices[VOR_CELL_MAX_VERTICES(MOST_SITES)];
    uint32_t count = 0;
    int cell = vor_cell(&m->d, site, &box, vertices, VOR_CELL_MAX_VERTICES(MOST_SITES), &count);
    size_t bytes = VOR_CENTROID_SCRATCH_BYTES(count) - (how & 1u);
    vor_centroid_t out, before;
    memset(&out, 0xa5, sizeof out);
    before = out;
    snapshot(m);
    int result = vor_cell_centroid(&m->d, site, &box, scratch + (how & 2u ? 1u : 0u),
                                   (how & 4u) ? sizeof scratch - 1u : bytes, &out);
    FUZZ_REQUIRE(unchanged(m), "centroid changed the diagram");
    if (box.x0 > box.x1 || box.y0 > box.y1 || !is_site(m, site)) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && cell == VOR_ERR_ARG &&
                         memcmp(&out, &before, sizeof out) == 0,
                     "centroid: a bad box or site accepted, or wrote");
        return;
    }
    FUZZ_REQUIRE(cell == VOR_OK, "cell failed where centroid must work");
    if (result == VOR_ERR_BUFFER) {
        /* a short scratch may still fit once aligned; the documented size must */
        before.vertices = count;
        FUZZ_REQUIRE(!(how & 4u) && (how & 1u) && memcmp(&out, &before, sizeof out) == 0,
                     "centroid: scratch of the documented size refused, or wrote more than k");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK && out.vertices == count, "centroid failed or miscounted");
    FUZZ_REQUIRE(out.point.x >= box.x0 && out.point.x <= box.x1 && out.point.y >= box.y0 &&
                     out.point.y <= box.y1,
                 "centroid: the point outside the box");
    /* a sliver cell's exact area may round to 0, never the other way */
    uint64_t box_area = (uint64_t)((int64_t)box.x1 - box.x0) * (uint64_t)((int64_t)box.y1 - box.y0);
    FUZZ_REQUIRE(count > 0 || out.area == 0, "centroid: an empty cell with area");
    FUZZ_REQUIRE(out.area <= box_area, "centroid: more area than the box");
    if (count == 0) {
        vor_point_t s = m->point[site];
        FUZZ_REQUIRE(out.point.x == (s.x < box.x0 ? box.x0 : s.x > box.x1 ? box.x1 : s.x) &&
                         out.point.y == (s.y < box.y0 ? box.y0 : s.y > box.y1 ? box.y1 : s.y),
                     "centroid: an empty cell's point is not the box point nearest the site");
    }
}

/* Is the room simple, by brute force over its edges (the harness's own
 * orientations)? */
static int room_is_simple(const vor_point_t *v, uint32_t m)
{
    for (uint32_t i = 0; i < m; i++) {
        vor_point_t a = v[i], b = v[(i + 1u) % m], c = v[(i + 2u) % m];
        if (a.x == b.x && a.y == b.y)
            return 0;
        /* consecutive edges folding back */
        if (fuzz_orient(a, b, c) == 0 &&
            (__int128)((int64_t)b.x - a.x) * ((int64_t)c.x - b.x) +
                    (__int128)((int64_t)b.y - a.y) * ((int64_t)c.y - b.y) <
                0)
            return 0;
        for (uint32_t j = i + 2u; j < m; j++) {
            if (i == 0u && j + 1u == m)
                continue;
            vor_point_t p = v[j], q = v[(j + 1u) % m];
            int o1 = fuzz_orient(a, b, p), o2 = fuzz_orient(a, b, q);
            int o3 = fuzz_orient(p, q, a), o4 = fuzz_orient(p, q, b);
            if (o1 * o2 > 0 || o3 * o4 > 0)
                continue;
            if (o1 != 0 || o2 != 0)
                return 0;
            /* collinear: do the spans meet? */
            int64_t lo1 = a.x < b.x ? a.x : b.x, hi1 = a.x < b.x ? b.x : a.x;
            int64_t lo2 = p.x < q.x ? p.x : q.x, hi2 = p.x < q.x ? q.x : p.x;
            int64_t ly1 = a.y < b.y ? a.y : b.y, hy1 = a.y < b.y ? b.y : a.y;
            int64_t ly2 = p.y < q.y ? p.y : q.y, hy2 = p.y < q.y ? q.y : p.y;
            if (lo1 <= hi2 && lo2 <= hi1 && ly1 <= hy2 && ly2 <= hy1)
                return 0;
        }
    }
    return 1;
}

/* The walk over the order-k cells of a simple room (no byte read: the
 * corpora keep their meaning): each set once, of k distinct sites
 * increasing, with pieces in the room's box, the single call giving the
 * same pieces, and the rounded areas adding up to the room's within
 * half a unit a piece; then the single call's errors for a bad set. */
static void op_order(model_t *m, const vor_point_t *room, uint32_t n, uint32_t k)
{
#define ORDER_ROOM_MOST 8u
#define ORDER_MOST_CELLS VOR_ORDER_MAX_CELLS(MOST_SITES, 3u)
    static uint32_t sets[VOR_ORDER_SETS_WORDS(ORDER_MOST_CELLS, 3u)];
    static uint32_t seen[ORDER_MOST_CELLS][3];
    static uint8_t scratch[VOR_ORDER_SCRATCH_BYTES(ORDER_ROOM_MOST, MOST_SITES, 3u)];
    static uint8_t single_scratch[sizeof scratch];
    static uint8_t before_scratch[sizeof scratch];
    static vor_exact_point_t piece[VOR_CLIP_MAX_VERTICES(ORDER_ROOM_MOST, MOST_SITES * 3u)];
    static vor_exact_point_t other[VOR_CLIP_MAX_VERTICES(ORDER_ROOM_MOST, MOST_SITES * 3u)];
    uint32_t capacity = VOR_CLIP_MAX_VERTICES(ORDER_ROOM_MOST, MOST_SITES * 3u);
    uint32_t distinct = 0;
    for (uint32_t i = 0; i < m->count; i++)
        distinct += is_site(m, i) ? 1u : 0u;
    vor_order_iter_t it;
    snapshot(m);
    int result = vor_order_cells_begin(&it, &m->d, k, room, n, sets, (uint32_t)ORDER_MOST_CELLS,
                                       scratch, sizeof scratch);
    if (k >= distinct) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && unchanged(m), "order: k >= the sites accepted");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "order: the walk failed to begin on a simple room");
    __int128 room_area2 = 0;
    for (uint32_t i = 0; i < n; i++) {
        vor_point_t a = room[i], b = room[(i + 1u) % n];
        room_area2 += (__int128)a.x * b.y - (__int128)b.x * a.y;
    }
    room_area2 = room_area2 < 0 ? -room_area2 : room_area2;
    int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
    for (uint32_t i = 0; i < n; i++) {
        x0 = room[i].x < x0 ? room[i].x : x0;
        x1 = room[i].x > x1 ? room[i].x : x1;
        y0 = room[i].y < y0 ? room[i].y : y0;
        y1 = room[i].y > y1 ? room[i].y : y1;
    }
    uint32_t set[3], cells = 0, all_pieces = 0;
    __int128 area2 = 0;
    vor_clip_t clip;
    while (vor_order_cells_next(&it, set, &clip)) {
        FUZZ_REQUIRE(cells < ORDER_MOST_CELLS && clip.pieces >= 1u, "order: too many cells, or empty");
        for (uint32_t i = 0; i < k; i++)
            FUZZ_REQUIRE(is_site(m, set[i]) && (i == 0u || set[i - 1u] < set[i]),
                         "order: a set not of increasing sites");
        for (uint32_t c = 0; c < cells; c++)
            FUZZ_REQUIRE(memcmp(seen[c], set, k * sizeof set[0]) != 0, "order: a set twice");
        memcpy(seen[cells], set, k * sizeof set[0]);
        cells++;
        vor_clip_t single;
        FUZZ_REQUIRE(vor_order_cell_begin(&single, &m->d, set, k, room, n, single_scratch,
                                          sizeof single_scratch) == VOR_OK &&
                         single.pieces == clip.pieces,
                     "order: the single call disagrees");
        uint32_t count, count2, pieces = 0;
        while (vor_clip_next(&clip, piece, capacity, &count)) {
            FUZZ_REQUIRE(vor_clip_next(&single, other, capacity, &count2) && count2 == count &&
                             memcmp(piece, other, count * sizeof piece[0]) == 0,
                         "order: a piece differs from the single call's");
            for (uint32_t i = 0; i < count; i++)
                FUZZ_REQUIRE(piece[i].point.x >= x0 && piece[i].point.x <= x1 &&
                                 piece[i].point.y >= y0 && piece[i].point.y <= y1,
                             "order: a vertex outside the room's box");
            static uint8_t sums[VOR_CENTROID_SCRATCH_BYTES(
                VOR_CLIP_MAX_VERTICES(ORDER_ROOM_MOST, MOST_SITES * 3u))];
            vor_centroid_t c;
            FUZZ_REQUIRE(vor_clip_centroid(&clip, pieces, sums, sizeof sums, &c) == VOR_OK,
                         "order: a piece's centroid failed");
            area2 += 2 * (__int128)c.area;
            pieces++;
        }
        all_pieces += pieces;
        FUZZ_REQUIRE(vor_clip_error(&clip) == VOR_OK && pieces == clip.pieces,
                     "order: the pieces stopped early");
    }
    FUZZ_REQUIRE(vor_order_cells_error(&it) == VOR_OK && unchanged(m), "order: the walk failed");
    __int128 gap = area2 - room_area2;
    FUZZ_REQUIRE(cells >= 1u && gap <= (__int128)all_pieces && -gap <= (__int128)all_pieces,
                 "order: the cells' areas do not add up to the room's");
    /* a set with an id twice, or not a site: nothing written */
    uint32_t bad_set[3] = {set[0], set[0], set[0]};
    memset(scratch, 0x5a, sizeof scratch);
    memcpy(before_scratch, scratch, sizeof scratch);
    FUZZ_REQUIRE(vor_order_cell_begin(&clip, &m->d, bad_set, k, room, n, scratch, sizeof scratch) ==
                         VOR_ERR_ARG &&
                     memcmp(scratch, before_scratch, sizeof scratch) == 0,
                 "order: a set with an id twice accepted, or the scratch written");
#undef ORDER_MOST_CELLS
#undef ORDER_ROOM_MOST
}

/* vor_clip_begin of a random id and room (often not simple; sometimes a
 * box, whose one piece must be vor_cell's cell), its pieces and centroids:
 * errors leave everything alone, pieces have 3 vertices or more, in the
 * room's bounding box, and a box's piece is the box cell vertex for
 * vertex. */
static void op_clip(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
#define CLIP_ROOM_MOST 8u
    static uint8_t scratch[VOR_CLIP_SCRATCH_BYTES(CLIP_ROOM_MOST, MOST_SITES)];
    static uint8_t before_scratch[sizeof scratch];
    static uint8_t sums[VOR_CLIP_CENTROID_SCRATCH_BYTES(CLIP_ROOM_MOST, MOST_SITES)];
    static vor_exact_point_t piece[VOR_CLIP_MAX_VERTICES(CLIP_ROOM_MOST, MOST_SITES)];
    vor_point_t room[CLIP_ROOM_MOST];
    uint8_t how = fuzz_u8(r);
    uint32_t n = 3u + (how % (CLIP_ROOM_MOST - 2u));
    int box_room = (how & 0x80u) != 0u;
    if (box_room) {
        vor_box_t box = draw_box(r, previous);
        n = 4;
        room[0] = (vor_point_t){box.x0, box.y0};
        room[1] = (vor_point_t){box.x1, box.y0};
        room[2] = (vor_point_t){box.x1, box.y1};
        room[3] = (vor_point_t){box.x0, box.y1};
    } else {
        for (uint32_t i = 0; i < n; i++)
            room[i] = fuzz_point(r, previous);
    }
    uint32_t site = draw_hint(r, m);
    vor_clip_t clip;
    memset(scratch, 0x5a, sizeof scratch);
    memcpy(before_scratch, scratch, sizeof scratch);
    snapshot(m);
    int result = vor_clip_begin(&clip, &m->d, site, room, n, scratch, sizeof scratch);
    FUZZ_REQUIRE(unchanged(m), "clip changed the diagram");
    int simple = room_is_simple(room, n);
    if (!is_site(m, site) || !simple) {
        FUZZ_REQUIRE(result == (!is_site(m, site) ? VOR_ERR_ARG : VOR_ERR_POLYGON) &&
                         vor_clip_error(&clip) == result &&
                         memcmp(scratch, before_scratch, sizeof scratch) == 0,
                     "clip: a bad site or room accepted, or the scratch written");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "clip failed on a simple room");
    int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
    for (uint32_t i = 0; i < n; i++) {
        x0 = room[i].x < x0 ? room[i].x : x0;
        x1 = room[i].x > x1 ? room[i].x : x1;
        y0 = room[i].y < y0 ? room[i].y : y0;
        y1 = room[i].y > y1 ? room[i].y : y1;
    }
    uint32_t count = 0, pieces = 0, total = 0;
    while (vor_clip_next(&clip, piece, VOR_CLIP_MAX_VERTICES(CLIP_ROOM_MOST, MOST_SITES), &count)) {
        FUZZ_REQUIRE(count >= 3u, "clip: a piece of fewer than 3 vertices");
        for (uint32_t i = 0; i < count; i++)
            FUZZ_REQUIRE(piece[i].point.x >= x0 && piece[i].point.x <= x1 &&
                             piece[i].point.y >= y0 && piece[i].point.y <= y1 &&
                             (int32_t)piece[i].w[VOR_EXACT_LIMBS - 1u] >= 0,
                         "clip: a vertex outside the room's box, or w < 0");
        vor_centroid_t c;
        FUZZ_REQUIRE(vor_clip_centroid(&clip, pieces, sums, sizeof sums, &c) == VOR_OK &&
                         c.vertices == count && c.point.x >= x0 && c.point.x <= x1 &&
                         c.point.y >= y0 && c.point.y <= y1,
                     "clip: a piece's centroid failed or outside the room's box");
        if (box_room) {
            /* the room's box: its corners in either orientation */
            vor_box_t box = {(int32_t)x0, (int32_t)y0, (int32_t)x1, (int32_t)y1};
            vor_point_t cell[VOR_CELL_MAX_VERTICES(MOST_SITES)];
            uint32_t k = 0;
            FUZZ_REQUIRE(vor_cell(&m->d, site, &box, cell, VOR_CELL_MAX_VERTICES(MOST_SITES), &k) ==
                                 VOR_OK &&
                             k == count && pieces == 0u,
                         "clip: a box room's piece is not the box cell");
            for (uint32_t i = 0; i < count; i++)
                FUZZ_REQUIRE(cell[i].x == piece[i].point.x && cell[i].y == piece[i].point.y,
                             "clip: a box room's vertex differs from the box cell's");
        }
        total += count;
        pieces++;
    }
    FUZZ_REQUIRE(vor_clip_error(&clip) == VOR_OK && pieces == clip.pieces,
                 "clip: the iterator stopped early");
    vor_centroid_t whole;
    FUZZ_REQUIRE(vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, sizeof sums, &whole) == VOR_OK &&
                     whole.vertices == total,
                 "clip: the whole centroid failed or miscounted");
    op_order(m, room, n, 2u + ((uint32_t)(how >> 3) & 1u));
#undef CLIP_ROOM_MOST
}

/* Hull sites counted by brute force: on the segment of a strict hull edge. */
static uint32_t brute_hull_sites(const model_t *m, int *collinear)
{
    uint32_t ids[MOST_SITES], n = 0, h = 0;
    for (uint32_t i = 0; i < m->count; i++)
        if (is_site(m, i))
            ids[n++] = i;
    *collinear = 1;
    for (uint32_t i = 2; i < n; i++)
        if (fuzz_orient(m->point[ids[0]], m->point[ids[1]], m->point[ids[i]]) != 0)
            *collinear = 0;
    if (*collinear)
        return n;
    for (uint32_t p = 0; p < n; p++) {
        int on = 0;
        for (uint32_t a = 0; a < n && !on; a++)
            for (uint32_t b = 0; b < n && !on; b++) {
                if (a == b)
                    continue;
                vor_point_t pa = m->point[ids[a]], pb = m->point[ids[b]];
                int left_all = 1;
                for (uint32_t c = 0; c < n; c++)
                    if (fuzz_orient(pa, pb, m->point[ids[c]]) < 0)
                        left_all = 0;
                vor_point_t pp = m->point[ids[p]];
                if (left_all && fuzz_orient(pa, pb, pp) == 0 &&
                    (__int128)((int64_t)pp.x - pa.x) * ((int64_t)pp.x - pb.x) <= 0 &&
                    (__int128)((int64_t)pp.y - pa.y) * ((int64_t)pp.y - pb.y) <= 0)
                    on = 1;
            }
        h += (uint32_t)on;
    }
    return h;
}

static void op_triangles(model_t *m)
{
    int collinear;
    uint32_t n = distinct_sites(m), h = brute_hull_sites(m, &collinear), ids[3];
    uint32_t triangles = 0;
    vor_triangle_iter_t it;
    FUZZ_REQUIRE(vor_triangles_begin(&it, &m->d) == VOR_OK, "triangles: begin");
    while (vor_triangles_next(&it, ids)) {
        FUZZ_REQUIRE(is_site(m, ids[0]) && is_site(m, ids[1]) && is_site(m, ids[2]),
                     "triangles: not a site");
        vor_point_t a = m->point[ids[0]], b = m->point[ids[1]], c = m->point[ids[2]];
        FUZZ_REQUIRE(fuzz_orient(a, b, c) > 0, "triangles: not of positive area, CCW");
        for (uint32_t i = 0; i < m->count; i++)
            FUZZ_REQUIRE(!is_site(m, i) || fuzz_incircle(a, b, c, m->point[i]) <= 0,
                         "triangles: a site inside a circumcircle");
        /* the Voronoi vertex of a triangle is its sites' circumcentre */
        vor_vertex_t vertex, direct;
        FUZZ_REQUIRE(vor_voronoi_vertex(&m->d, ids[0], ids[1], ids[2], &vertex) == VOR_OK &&
                         vor_circumcentre(a, b, c, &direct) == VOR_OK &&
                         vertex.status != VOR_VERTEX_AT_INFINITY &&
                         vertex.status == direct.status && vertex.point.x == direct.point.x &&
                         vertex.point.y == direct.point.y,
                     "voronoi_vertex: not the circumcentre of a triangle");
        FUZZ_REQUIRE(++triangles <= 2u * MOST_SITES, "triangles: endless");
    }
    /* ids that are no site: refused, *out unchanged */
    for (uint32_t i = 0; i <= m->count; i++) {
        if (is_site(m, i) || n < 2u)
            continue;
        vor_vertex_t out = {{7, 7}, VOR_VERTEX_IN_RANGE};
        uint32_t other = 0;
        while (!is_site(m, other))
            other++;
        FUZZ_REQUIRE(vor_voronoi_vertex(&m->d, other, i, other, &out) == VOR_ERR_ARG &&
                         out.point.x == 7 && out.point.y == 7,
                     "voronoi_vertex: a non-site accepted, or wrote");
    }
    FUZZ_REQUIRE(triangles == (collinear ? 0u : 2u * n - h - 2u), "triangles: not 2n - h - 2");

    /* the flat export: the iterator's triangles in its order, each
     * half-edge's twin the reversed pair (by a search of them all) */
    {
        uint32_t flat[3u * VOR_TRIANGLES_MAX(MOST_SITES) + 1u], twins[3u * VOR_TRIANGLES_MAX(MOST_SITES) + 1u];
        uint32_t count = 0xdeadbeefu, listed = 0;
        memset(flat, 0xa5, sizeof flat);
        memset(twins, 0xa5, sizeof twins);
        snapshot(m);
        if (triangles > 0u) {
            FUZZ_REQUIRE(vor_triangles_export(&m->d, flat, twins, triangles - 1u, &count) == VOR_ERR_BUFFER &&
                             count == triangles && flat[0] == 0xa5a5a5a5u && twins[0] == 0xa5a5a5a5u,
                         "export: a short buffer accepted, or written");
        }
        FUZZ_REQUIRE(vor_triangles_count(&m->d, &count) == VOR_OK && count == triangles &&
                         vor_triangles_export(&m->d, flat, twins, VOR_TRIANGLES_MAX(MOST_SITES), &count) == VOR_OK &&
                         count == triangles && unchanged(m) && flat[3u * triangles] == 0xa5a5a5a5u &&
                         twins[3u * triangles] == 0xa5a5a5a5u,
                     "export: refused, wrong count or wrote past");
        FUZZ_REQUIRE(vor_triangles_begin(&it, &m->d) == VOR_OK, "export: triangles_begin");
        while (vor_triangles_next(&it, ids)) {
            FUZZ_REQUIRE(memcmp(ids, &flat[3u * listed], sizeof ids) == 0, "export: not the iterator's triangle");
            listed++;
        }
        for (uint32_t e = 0; e < 3u * triangles; e++) {
            uint32_t from = flat[e], to = flat[e % 3u == 2u ? e - 2u : e + 1u], twin = VOR_HALFEDGE_NONE;
            for (uint32_t f = 0; f < 3u * triangles; f++)
                if (flat[f] == to && flat[f % 3u == 2u ? f - 2u : f + 1u] == from)
                    twin = f;
            FUZZ_REQUIRE(twins[e] == twin, "export: a wrong twin");
        }
    }

    uint32_t site, hull = 0;
    vor_hull_iter_t hi;
    FUZZ_REQUIRE(vor_hull_begin(&hi, &m->d) == VOR_OK, "hull: begin");
    while (vor_hull_next(&hi, &site)) {
        FUZZ_REQUIRE(is_site(m, site), "hull: not a site");
        FUZZ_REQUIRE(++hull <= MOST_SITES, "hull: endless");
    }
    FUZZ_REQUIRE(hull == h, "hull: wrong number of sites");
}

static void op_edges_neighbours(fuzz_reader_t *r, model_t *m)
{
    vor_edge_iter_t it;
    vor_edge_t edge;
    uint32_t edges = 0, neighbour;
    FUZZ_REQUIRE(vor_edges_begin(&it, &m->d) == VOR_OK, "edges: begin");
    while (vor_edges_next(&it, &edge)) {
        FUZZ_REQUIRE(is_site(m, edge.sites[0]) && is_site(m, edge.sites[1]) &&
                         edge.sites[0] != edge.sites[1],
                     "edges: not two sites");
        FUZZ_REQUIRE(++edges <= 3u * MOST_SITES, "edges: endless");
    }
    uint32_t site = m->count ? fuzz_u8(r) % (m->count + 1u) : fuzz_u8(r);
    vor_neighbour_iter_t ni;
    uint32_t seen = 0;
    FUZZ_REQUIRE(vor_neighbours_begin(&ni, &m->d, site) == (is_site(m, site) ? VOR_OK : VOR_ERR_ARG),
                 "neighbours: begin");
    while (vor_neighbours_next(&ni, &neighbour)) {
        FUZZ_REQUIRE(is_site(m, site) && is_site(m, neighbour) && neighbour != site,
                     "neighbours: not a site");
        FUZZ_REQUIRE(++seen <= MOST_SITES, "neighbours: endless");
    }
}

/* A failing init of the same vor_t (too small, misaligned, too many). */
static void op_bad_init(fuzz_reader_t *r, model_t *m)
{
    uint8_t how = fuzz_u8(r);
    snapshot(m);
    int result;
    vor_tracker_t tracker = m->tracker;
    if (how % 4u == 0u)
        result = vor_init(&m->d, arena, VOR_ARENA_BYTES(m->capacity) - 1u, m->capacity);
    else if (how % 4u == 1u)
        result = vor_init(&m->d, arena + 2, sizeof arena - 2u, 1);
    else if (how % 4u == 2u)
        result = vor_init(&m->d, arena, sizeof arena, VOR_MAX_SITES + 1u + how);
    else /* a library of other vor_config.h options */
        result = vor_init_checked(&m->d, arena, sizeof arena, 1, VOR_CONFIG_FINGERPRINT ^ how);
    FUZZ_REQUIRE(result < 0 && unchanged(m), "init: failure changed the diagram");
    FUZZ_REQUIRE(vor_tracker_begin_checked(&m->tracker, &m->d, VOR_CONFIG_FINGERPRINT ^ 1u) ==
                         VOR_ERR_CONFIG &&
                     memcmp(&tracker, &m->tracker, sizeof tracker) == 0,
                 "tracker_begin: another configuration accepted, or wrote");
}

/* ------------------------------------------------------------------ */
/* Constraints: the calls, and the check of the constrained triangulation */

#define NO_VERTEX 0xffffffffu
#define MOST_TRIANGLES (2u * MOST_VERTICES)

static uint32_t crossing_vertex[MOST_CROSSINGS]; /* library crossing k: the model's vertex */
static uint32_t triangle[MOST_TRIANGLES][3];     /* by the model's vertices */
static uint32_t triangle_ids[MOST_TRIANGLES][3]; /* as the library reports them */
static uint32_t twin[MOST_TRIANGLES][3];         /* across the edge opposite corner i */

/* The model's vertex of the library's vertex id, or NO_VERTEX. */
static uint32_t model_vertex(const model_t *m, uint32_t id)
{
    if (id < m->capacity)
        return is_site(m, id) ? id : NO_VERTEX;
    return id - m->capacity < MOST_CROSSINGS ? crossing_vertex[id - m->capacity] : NO_VERTEX;
}

static int vertex_orient(uint32_t a, uint32_t b, uint32_t c, const model_t *m)
{
    if (a < MOST_SITES && b < MOST_SITES && c < MOST_SITES)
        return fuzz_orient(m->point[a], m->point[b], m->point[c]);
    return fuzz_hpoint_orient(&expected.point[a], &expected.point[b], &expected.point[c]);
}

static int vertex_incircle(uint32_t a, uint32_t b, uint32_t c, uint32_t d, const model_t *m)
{
    if (a < MOST_SITES && b < MOST_SITES && c < MOST_SITES && d < MOST_SITES)
        return fuzz_incircle(m->point[a], m->point[b], m->point[c], m->point[d]);
    return fuzz_hpoint_incircle(&expected.point[a], &expected.point[b], &expected.point[c],
                                &expected.point[d]);
}

/* The entry of constrained edge u-v in `expected`, or expected.edges. */
static uint32_t expected_edge(uint32_t u, uint32_t v)
{
    uint32_t j = 0;
    while (j < expected.edges && !((expected.edge_u[j] == u && expected.edge_v[j] == v) ||
                                   (expected.edge_u[j] == v && expected.edge_v[j] == u)))
        j++;
    return j;
}

/* Does segment g-w meet a constrained edge anywhere but at w? */
static int hidden(const fuzz_hpoint_t *g, uint32_t w)
{
    const fuzz_hpoint_t *pw = &expected.point[w];
    for (uint32_t j = 0; j < expected.edges; j++) {
        const fuzz_hpoint_t *p = &expected.point[expected.edge_u[j]];
        const fuzz_hpoint_t *q = &expected.point[expected.edge_v[j]];
        int o1 = fuzz_hpoint_orient(p, q, g), o2 = fuzz_hpoint_orient(p, q, pw);
        if (o1 * o2 > 0)
            continue;
        int o3 = fuzz_hpoint_orient(g, pw, p), o4 = fuzz_hpoint_orient(g, pw, q);
        if (o3 * o4 > 0)
            continue;
        if (o1 == 0 && o2 == 0) { /* on one line: do the segments overlap short of w? */
            if (fuzz_hpoint_between(g, p, pw) || fuzz_hpoint_between(g, q, pw) ||
                fuzz_hpoint_between(p, g, q) || fuzz_hpoint_between(p, pw, q))
                return 1;
            continue;
        }
        if (o2 != 0) /* one point in common, and it is not w */
            return 1;
    }
    return 0;
}

/* The least number of constraints crossed from outside the hull to each
 * triangle (an edge under k constraints counts k; at most 126), by
 * relaxing over the triangles' adjacency. */
static void nesting_levels(uint32_t triangles, uint32_t *level)
{
    for (uint32_t k = 0; k < triangles; k++) {
        level[k] = 126u;
        for (unsigned i = 0; i < 3u; i++) {
            uint32_t j = expected_edge(triangle[k][(i + 1u) % 3u], triangle[k][(i + 2u) % 3u]);
            uint32_t cost = j < expected.edges ? expected.edge_cover[j] : 0u;
            if (twin[k][i] == NO_VERTEX && cost < level[k])
                level[k] = cost;
        }
    }
    for (int changed = 1; changed;) {
        changed = 0;
        for (uint32_t k = 0; k < triangles; k++)
            for (unsigned i = 0; i < 3u; i++) {
                uint32_t o = twin[k][i];
                if (o == NO_VERTEX)
                    continue;
                uint32_t j = expected_edge(triangle[k][(i + 1u) % 3u], triangle[k][(i + 2u) % 3u]);
                uint32_t to = level[k] + (j < expected.edges ? expected.edge_cover[j] : 0u);
                to = to > 126u ? 126u : to;
                if (to < level[o]) {
                    level[o] = to;
                    changed = 1;
                }
            }
    }
}

/* The crossing vertices: each a crossing the model makes, each once. */
static void check_crossings(const model_t *m)
{
    uint8_t matched[MOST_CROSSINGS] = {0};
    uint32_t found = 0;
    for (uint32_t k = 0; k < MOST_CROSSINGS; k++)
        crossing_vertex[k] = NO_VERTEX;
    for (uint32_t k = 0; k <= m->limits.crossings; k++) {
        uint32_t s[4];
        memset(s, 0xa5, sizeof s);
        int result = vor_cdt_crossing(&m->d, m->capacity + k, s);
        if (result != VOR_OK) {
            FUZZ_REQUIRE(result == VOR_ERR_ARG && s[0] == 0xa5a5a5a5u && s[3] == 0xa5a5a5a5u,
                         "cdt_crossing: wrong error, or wrote");
            continue;
        }
        FUZZ_REQUIRE(k < m->limits.crossings, "cdt_crossing: an id beyond the table");
        FUZZ_REQUIRE(is_site(m, s[0]) && is_site(m, s[1]) && is_site(m, s[2]) && is_site(m, s[3]),
                     "cdt_crossing: not four sites");
        fuzz_hpoint_t p;
        FUZZ_REQUIRE(fuzz_hpoint_crossing(&p, m->point[s[0]], m->point[s[1]], m->point[s[2]],
                                          m->point[s[3]]),
                     "cdt_crossing: parallel lines");
        uint32_t match = 0;
        while (match < expected.crossings &&
               !fuzz_hpoint_same(&p, &expected.point[MOST_SITES + match]))
            match++;
        FUZZ_REQUIRE(match < expected.crossings && !matched[match],
                     "cdt_crossing: a vertex where no two constraints cross, or two at one point");
        matched[match] = 1;
        crossing_vertex[k] = MOST_SITES + match;
        found++;
    }
    FUZZ_REQUIRE(found == expected.crossings, "cdt_crossing: a crossing of the constraints missing");
}

/* The constrained edges: exactly the pieces of positive coverage. */
static void check_edges(const model_t *m)
{
    uint8_t seen[MOST_EXPECTED_EDGES] = {0};
    uint32_t edges = 0, a, b;
    vor_cdt_edge_iter_t it;
    FUZZ_REQUIRE(vor_cdt_edges_begin(&it, &m->d) == VOR_OK, "cdt_edges: begin");
    while (vor_cdt_edges_next(&it, &a, &b)) {
        FUZZ_REQUIRE(++edges <= MOST_CDT_EDGES && a < b, "cdt_edges: endless, or not a < b");
        uint32_t j = expected_edge(model_vertex(m, a), model_vertex(m, b));
        FUZZ_REQUIRE(j < expected.edges && !seen[j],
                     "cdt_edges: an edge on no constraint, or reported twice");
        seen[j] = 1;
    }
    FUZZ_REQUIRE(edges == expected.edges, "cdt_edges: a piece of a constraint missing");
}

/* The triangles; their number. */
static uint32_t check_triangles(const model_t *m)
{
    uint32_t triangles = 0, ids[3];
    vor_cdt_triangle_iter_t it;
    FUZZ_REQUIRE(vor_cdt_triangles_begin(&it, &m->d) == VOR_OK, "cdt_triangles: begin");
    while (vor_cdt_triangles_next(&it, ids)) {
        FUZZ_REQUIRE(triangles < MOST_TRIANGLES, "cdt_triangles: endless");
        for (unsigned i = 0; i < 3u; i++) {
            triangle_ids[triangles][i] = ids[i];
            triangle[triangles][i] = model_vertex(m, ids[i]);
            FUZZ_REQUIRE(triangle[triangles][i] != NO_VERTEX, "cdt_triangles: not a vertex");
        }
        const uint32_t *t = triangle[triangles];
        FUZZ_REQUIRE(vertex_orient(t[0], t[1], t[2], m) > 0,
                     "cdt_triangles: not of positive area, counterclockwise");
        triangles++;
    }
    /* every edge once each way at most; twin: the triangle across */
    for (uint32_t k = 0; k < triangles; k++)
        for (unsigned i = 0; i < 3u; i++) {
            uint32_t u = triangle[k][(i + 1u) % 3u], v = triangle[k][(i + 2u) % 3u];
            twin[k][i] = NO_VERTEX;
            for (uint32_t o = 0; o < triangles; o++)
                for (unsigned j = 0; j < 3u; j++) {
                    uint32_t x = triangle[o][(j + 1u) % 3u], y = triangle[o][(j + 2u) % 3u];
                    FUZZ_REQUIRE(o == k || x != u || y != v, "cdt_triangles: an edge twice one way");
                    if (x == v && y == u)
                        twin[k][i] = o;
                }
        }
    return triangles;
}

/* The unpaired edges are the hull's pieces, counterclockwise (with the
 * triangles' orientation and pairing, the triangles then cover the hull
 * once), and Euler's count holds. */
static void check_cover(const model_t *m, uint32_t triangles)
{
    int collinear;
    uint32_t n = distinct_sites(m), h = brute_hull_sites(m, &collinear), unpaired = 0;
    if (collinear || n < 3u) {
        FUZZ_REQUIRE(triangles == 0, "cdt_triangles: triangles of collinear sites");
        return;
    }
    FUZZ_REQUIRE(triangles == 2u * (n + expected.crossings) - h - 2u,
                 "cdt_triangles: not 2v - h - 2");
    for (uint32_t k = 0; k < triangles; k++)
        for (unsigned i = 0; i < 3u; i++) {
            if (twin[k][i] != NO_VERTEX)
                continue;
            uint32_t u = triangle[k][(i + 1u) % 3u], v = triangle[k][(i + 2u) % 3u];
            FUZZ_REQUIRE(u < MOST_SITES && v < MOST_SITES, "cdt_triangles: a crossing on the hull");
            for (uint32_t w = 0; w < m->count; w++) {
                if (!is_site(m, w))
                    continue;
                int side = fuzz_orient(m->point[u], m->point[v], m->point[w]);
                FUZZ_REQUIRE(side > 0 || (side == 0 && !fuzz_hpoint_between(&expected.point[u],
                                                                             &expected.point[w],
                                                                             &expected.point[v])),
                             "cdt_triangles: an unpaired edge that is no hull piece");
            }
            unpaired++;
        }
    FUZZ_REQUIRE(unpaired == h, "cdt_triangles: the unpaired edges are not the hull");
    for (uint32_t j = 0; j < expected.edges; j++) {
        int found = 0;
        for (uint32_t k = 0; k < triangles && !found; k++)
            for (unsigned i = 0; i < 3u; i++)
                found |= (triangle[k][i] == expected.edge_u[j] &&
                          triangle[k][(i + 1u) % 3u] == expected.edge_v[j]) ||
                         (triangle[k][i] == expected.edge_v[j] &&
                          triangle[k][(i + 1u) % 3u] == expected.edge_u[j]);
        FUZZ_REQUIRE(found, "cdt: a constrained edge no triangle has");
    }
}

/* Constrained Delaunay: every unconstrained edge locally Delaunay; on
 * small meshes also, straight from the definition, no vertex inside a
 * triangle's circumcircle that its centroid sees (both hold exactly for
 * the constrained Delaunay triangulation under any tie-breaking). */
static void check_delaunay(const model_t *m, uint32_t triangles)
{
    for (uint32_t k = 0; k < triangles; k++)
        for (unsigned i = 0; i < 3u; i++) {
            uint32_t o = twin[k][i];
            if (o == NO_VERTEX || o < k ||
                expected_edge(triangle[k][(i + 1u) % 3u], triangle[k][(i + 2u) % 3u]) <
                    expected.edges)
                continue;
            uint32_t far = 0;
            for (unsigned j = 0; j < 3u; j++)
                far = twin[o][j] == k ? triangle[o][j] : far;
            const uint32_t *t = triangle[k];
            FUZZ_REQUIRE(vertex_incircle(t[0], t[1], t[2], far, m) <= 0,
                         "cdt: an unconstrained edge not locally Delaunay");
        }
    uint32_t vertices = distinct_sites(m) + expected.crossings;
    if (triangles * vertices * (expected.edges + 1u) > 24000u)
        return; /* the brute force's budget */
    for (uint32_t k = 0; k < triangles; k++) {
        const uint32_t *t = triangle[k];
        fuzz_hpoint_t g = fuzz_hpoint_centroid(&expected.point[t[0]], &expected.point[t[1]],
                                               &expected.point[t[2]]);
        for (uint32_t w = 0; w < MOST_SITES + expected.crossings; w++) {
            if ((w < MOST_SITES && !is_site(m, w)) || w == t[0] || w == t[1] || w == t[2])
                continue;
            if (vertex_incircle(t[0], t[1], t[2], w, m) > 0)
                FUZZ_REQUIRE(hidden(&g, w),
                             "cdt: a vertex in a triangle's circumcircle, visible from it");
        }
    }
}

/* The domain: vor_cdt_inside_begin refused unless marked since the last
 * change; else the triangles at odd nesting levels, in the order of all. */
static void check_domain(const model_t *m, uint32_t triangles)
{
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3] = {7, 7, 7};
    int result = vor_cdt_inside_begin(&it, &m->d);
    if (!m->domain) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && !vor_cdt_triangles_next(&it, ids) && ids[0] == 7,
                     "cdt_inside_begin: no domain marked, yet accepted");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "cdt_inside_begin: refused after vor_cdt_domain");
    uint32_t level[MOST_TRIANGLES];
    nesting_levels(triangles, level);
    uint32_t k = 0;
    while (vor_cdt_triangles_next(&it, ids)) {
        while (k < triangles && (triangle_ids[k][0] != ids[0] || triangle_ids[k][1] != ids[1] ||
                                 triangle_ids[k][2] != ids[2])) {
            FUZZ_REQUIRE(level[k] % 2u == 0u, "cdt_domain: an inside triangle left out");
            k++;
        }
        FUZZ_REQUIRE(k < triangles, "cdt_domain: a triangle not in the triangulation");
        FUZZ_REQUIRE(level[k] % 2u == 1u, "cdt_domain: an outside triangle reported inside");
        k++;
    }
    for (; k < triangles; k++)
        FUZZ_REQUIRE(level[k] % 2u == 0u, "cdt_domain: an inside triangle left out");
}

/* After every call with constraint memory attached. */
static void check_cdt(const model_t *m)
{
    derive(m, &expected);
    FUZZ_REQUIRE(!expected.too_many_crossings && !expected.too_many_edges &&
                     expected.crossings <= m->limits.crossings &&
                     expected.edges <= m->limits.edges,
                 "cdt: more crossings or constrained edges than the limits hold");
    check_crossings(m);
    check_edges(m);
    uint32_t triangles = check_triangles(m);
    check_cover(m, triangles);
    check_delaunay(m, triangles);
    check_domain(m, triangles);
}

/* A vertex id as a caller might pass it: mostly a site, else garbage. */
static uint32_t draw_site(fuzz_reader_t *r, const model_t *m)
{
    uint8_t b = fuzz_u8(r);
    if (b >= 248)
        return b == 255 ? 0x7fffffffu : m->capacity + (b & 3u); /* a crossing's id */
    return m->count ? (uint32_t)b % m->count : b;
}

static void op_cdt_attach(fuzz_reader_t *r, model_t *m)
{
    uint8_t how = fuzz_u8(r);
    vor_cdt_limits_t limits;
    limits.crossings = fuzz_u8(r) % (MOST_CROSSINGS + 1u);
    uint32_t roomy_cut = 2u * (m->capacity + limits.crossings) + 2u;
    limits.edges = fuzz_u8(r) % (MOST_CDT_EDGES + 1u);
    limits.cut = (how & 1u) ? roomy_cut : fuzz_u8(r) % (roomy_cut + 2u);
    int bad_limits = limits.edges == 0 || limits.edges > 3u * (m->capacity + limits.crossings) ||
                     limits.cut > roomy_cut;
    size_t bytes = VOR_CDT_BYTES(m->capacity, limits.edges, limits.crossings, limits.cut);
    snapshot(m);
    int result, expected_result = bad_limits ? VOR_ERR_ARG : VOR_OK;
    switch ((how >> 1) % 8u) {
    case 0:
        result = vor_cdt_attach(&m->d, cdt_memory, sizeof cdt_memory, NULL);
        expected_result = VOR_ERR_ARG;
        break;
    case 1:
        result = vor_cdt_attach(&m->d, NULL, bytes, &limits);
        expected_result = VOR_ERR_ARG;
        break;
    case 2:
        result = vor_cdt_attach(&m->d, cdt_memory + 2, bytes, &limits);
        expected_result = bad_limits ? VOR_ERR_ARG : VOR_ERR_ALIGN;
        break;
    case 3:
        result = vor_cdt_attach(&m->d, cdt_memory, bytes - 1u, &limits);
        expected_result = bad_limits ? VOR_ERR_ARG : VOR_ERR_NOMEM;
        break;
    default:
        result = vor_cdt_attach(&m->d, cdt_memory, bytes, &limits);
        break;
    }
    FUZZ_REQUIRE(result == expected_result, "cdt_attach: wrong result");
    if (result != VOR_OK) {
        FUZZ_REQUIRE(unchanged(m), "cdt_attach: failure changed memory");
        return;
    }
    m->cdt_attached = 1;
    m->limits = limits;
    m->entries = 0;
    m->domain = 0;
}

static void constrain_checked(model_t *m, uint32_t a, uint32_t b)
{
    snapshot(m);
    int result = vor_constrain(&m->d, a, b);
    if (!m->cdt_attached || !is_site(m, a) || !is_site(m, b) || a == b) {
        FUZZ_REQUIRE(result == (m->cdt_attached && a == b && is_site(m, a) ? VOR_OK : VOR_ERR_ARG) &&
                         unchanged(m),
                     "constrain: no memory, no site, or one site: wrong result, or changed memory");
        return;
    }
    static expected_t after;
    m->entry[m->entries++] = (entry_t){m->point[a], m->point[b], 1};
    derive(m, &after);
    int overflows = after.too_many_crossings || after.too_many_edges ||
                    after.crossings > m->limits.crossings || after.edges > m->limits.edges;
    int roomy_cut = m->limits.cut == 2u * (m->capacity + m->limits.crossings) + 2u;
    if (overflows)
        FUZZ_REQUIRE(result == VOR_ERR_NOMEM, "constrain: a table overflow accepted");
    else if (roomy_cut)
        FUZZ_REQUIRE(result == VOR_OK, "constrain: refused with room enough");
    else
        FUZZ_REQUIRE(result == VOR_OK || result == VOR_ERR_NOMEM, "constrain: wrong error");
    if (result != VOR_OK) {
        m->entries--;
        FUZZ_REQUIRE(unchanged(m), "constrain: failure changed memory");
        return;
    }
    m->domain = 0;
}

static void unconstrain_checked(model_t *m, uint32_t a, uint32_t b)
{
    snapshot(m);
    int result = vor_unconstrain(&m->d, a, b);
    if (!m->cdt_attached || !is_site(m, a) || !is_site(m, b)) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && unchanged(m), "unconstrain: no memory or no site");
        return;
    }
    uint32_t on[MOST_VERTICES + 2];
    uint32_t n = a == b ? 0 : vertices_inside(m, &expected, m->point[a], m->point[b], on + 1);
    on[0] = a;
    on[n + 1] = b;
    int constrained = 1;
    for (uint32_t k = 0; k <= n && a != b; k++)
        constrained &= expected_edge(on[k], on[k + 1]) < expected.edges;
    if (!constrained) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && unchanged(m),
                     "unconstrain: a piece not constrained, accepted or changed memory");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "unconstrain failed");
    if (a != b)
        m->entry[m->entries++] = (entry_t){m->point[a], m->point[b], -1};
    m->domain = 0;
}

static void op_constrain(fuzz_reader_t *r, model_t *m)
{
    uint32_t a = draw_site(r, m), b = draw_site(r, m);
    if (m->entries < MOST_ENTRIES)
        constrain_checked(m, a, b);
}

/* Often a constraint made before, either way round, maybe in part. */
static void op_unconstrain(fuzz_reader_t *r, model_t *m)
{
    uint8_t how = fuzz_u8(r);
    uint32_t a = draw_site(r, m), b = draw_site(r, m);
    if ((how & 1u) && m->entries) {
        const entry_t *e = &m->entry[how % m->entries];
        a = site_at(m, (how & 2u) ? e->a : e->b);
        b = (how & 4u) ? b : site_at(m, (how & 2u) ? e->b : e->a);
    }
    if (m->entries < MOST_ENTRIES)
        unconstrain_checked(m, a, b);
}

/* A closed chain of constraints (a polygon, often), each call checked. */
static void op_cdt_polygon(fuzz_reader_t *r, model_t *m)
{
    uint32_t corners = 3u + fuzz_u8(r) % 4u, id[6];
    for (uint32_t i = 0; i < corners; i++)
        id[i] = draw_site(r, m);
    for (uint32_t i = 0; i < corners && m->entries < MOST_ENTRIES; i++) {
        constrain_checked(m, id[i], id[(i + 1u) % corners]);
        check_valid(m);
    }
}

static void op_cdt_domain(model_t *m)
{
    snapshot(m);
    FUZZ_REQUIRE(vor_cdt_domain(NULL) == VOR_ERR_ARG, "cdt_domain: NULL accepted");
    int result = vor_cdt_domain(&m->d);
    if (!m->cdt_attached) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && unchanged(m), "cdt_domain: no memory, accepted");
        return;
    }
    FUZZ_REQUIRE(result == VOR_OK, "cdt_domain failed");
    m->domain = 1;
}

/* The read-only calls as callers get them wrong: NULLs, ids that are no
 * crossing, an iterator on a diagram without constraint memory. */
static void op_cdt_reads(fuzz_reader_t *r, model_t *m)
{
    vor_cdt_triangle_iter_t it;
    vor_cdt_edge_iter_t ei;
    uint32_t ids[3] = {7, 7, 7}, a = 7, b = 7, s[4] = {7, 7, 7, 7};
    uint32_t id = (fuzz_u8(r) & 1u) ? fuzz_u32(r) : m->capacity + fuzz_u8(r) % (MOST_CROSSINGS + 2u);
    int attached = m->cdt_attached ? VOR_OK : VOR_ERR_ARG;
    snapshot(m);
    FUZZ_REQUIRE(vor_cdt_triangles_begin(NULL, &m->d) == VOR_ERR_ARG &&
                     vor_cdt_edges_begin(NULL, &m->d) == VOR_ERR_ARG &&
                     vor_cdt_inside_begin(NULL, &m->d) == VOR_ERR_ARG,
                 "cdt iterators: a NULL iterator accepted");
    FUZZ_REQUIRE(vor_cdt_triangles_begin(&it, NULL) == VOR_ERR_ARG &&
                     !vor_cdt_triangles_next(&it, ids) && !vor_cdt_triangles_next(NULL, ids) &&
                     vor_cdt_edges_begin(&ei, NULL) == VOR_ERR_ARG &&
                     !vor_cdt_edges_next(&ei, &a, &b) && !vor_cdt_edges_next(NULL, &a, &b) &&
                     ids[0] == 7 && a == 7 && b == 7,
                 "cdt iterators: a NULL diagram accepted, or wrote");
    FUZZ_REQUIRE(vor_cdt_triangles_begin(&it, &m->d) == attached &&
                     !vor_cdt_triangles_next(&it, NULL) &&
                     vor_cdt_edges_begin(&ei, &m->d) == attached &&
                     !vor_cdt_edges_next(&ei, NULL, &b) && !vor_cdt_edges_next(&ei, &a, NULL) &&
                     a == 7 && b == 7,
                 "cdt iterators: begin without memory accepted, or NULL outputs written");
    if (!m->cdt_attached)
        FUZZ_REQUIRE(!vor_cdt_triangles_next(&it, ids) && !vor_cdt_edges_next(&ei, &a, &b) &&
                         ids[0] == 7 && a == 7,
                     "cdt iterators: items without memory");
    FUZZ_REQUIRE(vor_cdt_crossing(NULL, id, s) == VOR_ERR_ARG &&
                     vor_cdt_crossing(&m->d, id, NULL) == VOR_ERR_ARG && s[0] == 7,
                 "cdt_crossing: NULL accepted, or wrote");
    int crossing = m->cdt_attached && id >= m->capacity && id - m->capacity < MOST_CROSSINGS &&
                   crossing_vertex[id - m->capacity] != NO_VERTEX;
    int result = vor_cdt_crossing(&m->d, id, s);
    FUZZ_REQUIRE(crossing ? result == VOR_OK : result == VOR_ERR_ARG && s[0] == 7,
                 "cdt_crossing: wrong answer for an id");
    FUZZ_REQUIRE(unchanged(m), "cdt reads changed memory");
}

static uint64_t gcd64(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* A site inserted where constraints are: a lattice point inside a
 * constraint (it splits the edge there), or a crossing vertex's point
 * when it is one (the site takes its place). */
static void op_cdt_on_constraint(fuzz_reader_t *r, model_t *m)
{
    uint8_t how = fuzz_u8(r), pick = fuzz_u8(r), step = fuzz_u8(r);
    vor_point_t p;
    if ((how & 1u) && m->cdt_attached && expected.crossings) {
        const fuzz_hpoint_t *x = &expected.point[MOST_SITES + pick % expected.crossings];
        /* |X| < 2^98 and W < 2^66: two limbs hold them */
        __int128 X = (__int128)(((unsigned __int128)x->x.limb[1] << 64) | x->x.limb[0]);
        __int128 Y = (__int128)(((unsigned __int128)x->y.limb[1] << 64) | x->y.limb[0]);
        __int128 W = (__int128)(((unsigned __int128)x->w.limb[1] << 64) | x->w.limb[0]);
        if (X % W != 0 || Y % W != 0)
            return;
        p.x = (int32_t)(X / W);
        p.y = (int32_t)(Y / W);
    } else if (m->entries) {
        const entry_t *e = &m->entry[pick % m->entries];
        int64_t dx = (int64_t)e->b.x - e->a.x, dy = (int64_t)e->b.y - e->a.y;
        uint64_t g = gcd64((uint64_t)(dx < 0 ? -dx : dx), (uint64_t)(dy < 0 ? -dy : dy));
        if (g < 2u)
            return; /* no lattice point inside */
        int64_t t = 1 + (int64_t)(step % (g - 1u));
        p.x = (int32_t)(e->a.x + dx / (int64_t)g * t);
        p.y = (int32_t)(e->a.y + dy / (int64_t)g * t);
    } else {
        return;
    }
    insert_checked(m, p, (how & 2u) != 0, VOR_NO_HINT);
}

/* ------------------------------------------------------------------ */
/* Weighted sites (vor_power.h): a program of its own                  */

/* An input whose first byte is at least POWER_MODE drives a vor_power_t
 * instead of the vor_t (every committed input of the diagram's program
 * opens with a capacity byte below 0x18, so they keep their meaning). */
#define POWER_MODE 0xe0u
#define POWER_SLACK 16u /* arena bytes past the minimum an init may give */

static uint8_t power_arena[VOR_POWER_ARENA_BYTES(MOST_SITES) + POWER_SLACK]
    __attribute__((aligned(VOR_POWER_ARENA_ALIGN)));
static uint8_t power_arena_before[sizeof power_arena];

typedef struct {
    vor_power_t pd;
    uint32_t capacity;
    uint32_t count;                /* ids handed out */
    vor_point_t point[MOST_SITES]; /* by id */
    int64_t weight[MOST_SITES];
    uint32_t first[MOST_SITES]; /* the smallest id of the same point and weight;
                                   POWER_FREE for a removed id */
    uint32_t free_ids[MOST_SITES]; /* removed ids, most recent last */
    uint32_t free_count;
} power_model_t;

#define POWER_FREE 0xffffffffu

static vor_power_t power_before;

static void power_snapshot(const power_model_t *m)
{
    memcpy(&power_before, &m->pd, sizeof m->pd);
    memcpy(power_arena_before, power_arena, sizeof power_arena);
}

static int power_unchanged(const power_model_t *m)
{
    return memcmp(&power_before, &m->pd, sizeof m->pd) == 0 &&
           memcmp(power_arena_before, power_arena, sizeof power_arena) == 0;
}

static int power_is_site(const power_model_t *m, uint32_t id)
{
    return id < m->count && m->first[id] == id;
}

/* The first of ids [0, before) with point p and weight w, or before. */
static uint32_t power_twin(const vor_point_t *point, const int64_t *weight, uint32_t before,
                           vor_point_t p, int64_t w)
{
    for (uint32_t i = 0; i < before; i++)
        if (point[i].x == p.x && point[i].y == p.y && weight[i] == w)
            return i;
    return before;
}

/* Twice the signed area of a, b, c: exact (below 2^66). */
static __int128 power_cross(vor_point_t a, vor_point_t b, vor_point_t c)
{
    return (__int128)((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) -
           (__int128)((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
}

/* x^2 + y^2 - w, the lifted height (below 2^65 in magnitude). */
static __int128 power_lift(vor_point_t p, int64_t w)
{
    return (__int128)p.x * p.x + (__int128)p.y * p.y - w;
}

/* Twice the area of the convex hull of the sites (monotone chain). */
static __int128 power_hull_area2(const power_model_t *m)
{
    vor_point_t p[MOST_SITES], hull[2u * MOST_SITES + 1u];
    uint32_t n = 0, k = 0;
    for (uint32_t i = 0; i < m->count; i++) {
        if (!power_is_site(m, i))
            continue;
        uint32_t at = n++;
        vor_point_t q = m->point[i];
        while (at > 0 && (p[at - 1].x > q.x || (p[at - 1].x == q.x && p[at - 1].y > q.y))) {
            p[at] = p[at - 1];
            at--;
        }
        p[at] = q;
    }
    if (n < 3u)
        return 0;
    for (uint32_t i = 0; i < n; i++) {
        while (k >= 2u && power_cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
            k--;
        hull[k++] = p[i];
    }
    for (uint32_t i = n - 1u, t = k + 1u; i-- > 0;) {
        while (k >= t && power_cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
            k--;
        hull[k++] = p[i];
    }
    __int128 area2 = 0;
    for (uint32_t i = 0; i + 1u < k; i++)
        area2 += (__int128)hull[i].x * hull[i + 1].y - (__int128)hull[i + 1].x * hull[i].y;
    return area2;
}

/* Sites all on one line: is site s strictly above the lower chain of the
 * lifted sites (1), a corner strictly below it (-1), or on it (0)? A
 * heavier site at its point, or a chord of two sites on either side
 * strictly below it, puts it above. */
static int power_line_status(const power_model_t *m, uint32_t s)
{
    int vertical = 1;
    for (uint32_t i = 0; i < m->count; i++)
        vertical &= !power_is_site(m, i) || m->point[i].x == m->point[s].x;
    int status = -1;
    vor_point_t ps = m->point[s];
    int64_t ts = vertical ? ps.y : ps.x;
    __int128 ls = power_lift(ps, m->weight[s]);
    for (uint32_t a = 0; a < m->count; a++) {
        if (!power_is_site(m, a) || a == s)
            continue;
        int64_t ta = vertical ? m->point[a].y : m->point[a].x;
        if (ta == ts) {
            if (m->weight[a] > m->weight[s])
                return 1;
            continue;
        }
        for (uint32_t b = 0; b < m->count; b++) {
            int64_t tb = vertical ? m->point[b].y : m->point[b].x;
            if (!power_is_site(m, b) || !(ta < ts && ts < tb))
                continue;
            __int128 above = (__int128)(tb - ta) * ls -
                             ((__int128)(tb - ts) * power_lift(m->point[a], m->weight[a]) +
                              (__int128)(ts - ta) * power_lift(m->point[b], m->weight[b]));
            if (above > 0)
                return 1;
            if (above == 0)
                status = 0;
        }
    }
    return status;
}

static uint32_t power_triangle[2u * MOST_SITES][3];

/* Edge pieces: each triangle edge cut at the sites strictly inside it. */
#define MOST_PIECES (6u * MOST_SITES * MOST_SITES)
static vor_point_t power_piece[MOST_PIECES][2];

static int power_same_point(vor_point_t a, vor_point_t b)
{
    return a.x == b.x && a.y == b.y;
}

/* Appends the pieces of segment a-b (from a to b) after the first np. */
static uint32_t power_pieces(const power_model_t *m, vor_point_t a, vor_point_t b, uint32_t np)
{
    vor_point_t from = a;
    for (;;) { /* the nearest site strictly inside from-b, then on from it */
        vor_point_t next = b;
        for (uint32_t s = 0; s < m->count; s++) {
            vor_point_t p = m->point[s];
            if (m->first[s] == POWER_FREE || fuzz_orient(from, b, p) != 0 || power_same_point(p, from) || power_same_point(p, next))
                continue;
            /* strictly between from and next, on the line: closer to from */
            __int128 along = ((__int128)p.x - from.x) * ((__int128)next.x - from.x) +
                             ((__int128)p.y - from.y) * ((__int128)next.y - from.y);
            __int128 beyond = ((__int128)p.x - next.x) * ((__int128)from.x - next.x) +
                              ((__int128)p.y - next.y) * ((__int128)from.y - next.y);
            if (along > 0 && beyond > 0)
                next = p;
        }
        FUZZ_REQUIRE(np < MOST_PIECES, "harness: too many edge pieces");
        power_piece[np][0] = from;
        power_piece[np][1] = next;
        np++;
        if (power_same_point(next, b))
            return np;
        from = next;
    }
}

/* After every call: vor_power_validate; vor_power_hidden of every id and
 * the hidden iterator against each other and the model; the triangles
 * against brute force over the sites with exact wide integers: each
 * counterclockwise of nonzero area with vertices for corners, no site's
 * lifted point strictly below its plane (so each lies in a face of the
 * lower hull), each directed edge (cut at the sites inside it) once, the
 * unpaired ones on the hull's boundary and the areas adding up to the
 * hull's (so they cover it once);
 * a vertex in no triangle only with its lifted point on the surface (a
 * cell of no area: one strictly above is hidden); on one line, the sites
 * strictly above the lower chain hidden and its strict corners not. None
 * of it may change a byte. */
/* The power cells in the whole int32 plane: every site's (a hidden one's
 * empty), ids that are no site refused; the centroid's vertex count is
 * the cell's, and the cells' areas, each rounded once, add up to the
 * plane's within half a unit per cell (the exact areas tile it). */
static void power_check_cells(const power_model_t *m, const int *hidden)
{
    static vor_point_t poly[VOR_CELL_MAX_VERTICES(MOST_SITES)];
    static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(MOST_SITES))];
    const vor_box_t plane = {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX};
    __int128 total = 0, cells = 0;
    for (uint32_t i = 0; i < m->count + 2u; i++) {
        uint32_t count = 77;
        vor_centroid_t c;
        int r = vor_power_cell(&m->pd, i, &plane, poly, VOR_CELL_MAX_VERTICES(MOST_SITES), &count);
        if (!power_is_site(m, i)) {
            FUZZ_REQUIRE(r == VOR_ERR_ARG && count == 77, "power_cell: a duplicate's or unused id accepted");
            continue;
        }
        FUZZ_REQUIRE(r == VOR_OK && (hidden[i] == 0 || count == 0u), "power_cell failed, or a hidden site's cell");
        r = vor_power_cell_centroid(&m->pd, i, &plane, scratch, sizeof scratch, &c);
        FUZZ_REQUIRE(r == VOR_OK && c.vertices == count && (count > 0u || c.area == 0u),
                     "power_cell_centroid failed, or another cell than power_cell's");
        total += c.area;
        cells += (count > 0u) ? 1 : 0;
    }
    __int128 side = (__int128)UINT32_MAX, gap = total - side * side;
    FUZZ_REQUIRE(cells == 0 || 2 * (gap < 0 ? -gap : gap) <= cells,
                 "power cells: their areas do not tile the plane");
}

static void power_check(const power_model_t *m)
{
    vor_violation_t violation;
    power_snapshot(m);
    FUZZ_REQUIRE(vor_power_validate(&m->pd, &violation) == VOR_OK, "power_validate failed");
    int hidden[MOST_SITES] = {0};
    uint32_t hidden_count = 0;
    for (uint32_t i = 0; i < m->count + 2u; i++) {
        int h = vor_power_hidden(&m->pd, i);
        if (!power_is_site(m, i)) {
            FUZZ_REQUIRE(h == VOR_ERR_ARG, "power_hidden: a duplicate's or unused id accepted");
            continue;
        }
        FUZZ_REQUIRE(h == 0 || h == 1, "power_hidden: a site refused");
        hidden[i] = h;
        hidden_count += (uint32_t)h;
    }
    FUZZ_REQUIRE(vor_power_hidden(&m->pd, 0xffffffffu) == VOR_ERR_ARG &&
                     vor_power_hidden(&m->pd, VOR_MAX_SITES) == VOR_ERR_ARG,
                 "power_hidden: a huge id accepted");
    uint8_t listed[MOST_SITES] = {0};
    uint32_t id = 0, listed_count = 0;
    vor_power_hidden_iter_t hi;
    FUZZ_REQUIRE(vor_power_hidden_begin(&hi, &m->pd) == VOR_OK, "power_hidden_begin");
    while (vor_power_hidden_next(&hi, &id)) {
        FUZZ_REQUIRE(++listed_count <= MOST_SITES, "power hidden iterator: endless");
        FUZZ_REQUIRE(power_is_site(m, id) && hidden[id] == 1 && !listed[id],
                     "power hidden iterator: not a hidden site, or twice");
        listed[id] = 1;
    }
    FUZZ_REQUIRE(listed_count == hidden_count, "power hidden iterator: disagrees with power_hidden");
    FUZZ_REQUIRE(vor_power_hidden_next(&hi, &id) == 0, "power hidden iterator: past its end");

    uint32_t nt = 0, ids[3];
    uint8_t corner[MOST_SITES] = {0};
    __int128 area2 = 0;
    vor_triangle_iter_t ti;
    FUZZ_REQUIRE(vor_power_triangles_begin(&ti, &m->pd) == VOR_OK, "power_triangles_begin");
    while (vor_triangles_next(&ti, ids)) {
        FUZZ_REQUIRE(nt < 2u * MOST_SITES, "power triangles: endless");
        for (int k = 0; k < 3; k++) {
            FUZZ_REQUIRE(power_is_site(m, ids[k]) && hidden[ids[k]] == 0,
                         "power triangles: a corner that is no vertex");
            corner[ids[k]] = 1;
            power_triangle[nt][k] = ids[k];
        }
        vor_point_t a = m->point[ids[0]], b = m->point[ids[1]], c = m->point[ids[2]];
        int64_t wa = m->weight[ids[0]], wb = m->weight[ids[1]], wc = m->weight[ids[2]];
        __int128 twice = power_cross(a, b, c);
        FUZZ_REQUIRE(twice > 0, "power triangles: not counterclockwise of nonzero area");
        area2 += twice;
        for (uint32_t s = 0; s < m->count; s++)
            FUZZ_REQUIRE(!power_is_site(m, s) ||
                             fuzz_power(a, wa, b, wb, c, wc, m->point[s], m->weight[s]) <= 0,
                         "power triangles: a site's lifted point below a triangle's plane");
        nt++;
    }
    /* the triangles' edges cut at the sites inside them: a vertex whose
     * cell has no area may sit inside an edge, between two reported
     * triangles on one side and one on the other (its flat triangle is
     * not reported) */
    uint32_t np = 0;
    for (uint32_t t = 0; t < nt; t++)
        for (int e = 0; e < 3; e++)
            np = power_pieces(m, m->point[power_triangle[t][e]],
                              m->point[power_triangle[t][(e + 1) % 3]], np);
    for (uint32_t i = 0; i < np; i++) {
        uint32_t same = 0, reverse = 0;
        for (uint32_t j = 0; j < np; j++) {
            same += power_same_point(power_piece[j][0], power_piece[i][0]) &&
                    power_same_point(power_piece[j][1], power_piece[i][1]);
            reverse += power_same_point(power_piece[j][0], power_piece[i][1]) &&
                       power_same_point(power_piece[j][1], power_piece[i][0]);
        }
        FUZZ_REQUIRE(same == 1u, "power triangles: an edge used twice the same way");
        for (uint32_t s = 0; s < m->count && !reverse; s++)
            FUZZ_REQUIRE(!power_is_site(m, s) ||
                             fuzz_orient(power_piece[i][0], power_piece[i][1], m->point[s]) >= 0,
                         "power triangles: an unpaired edge inside the hull");
    }
    __int128 hull2 = power_hull_area2(m);
    FUZZ_REQUIRE(area2 == hull2, "power triangles: do not cover the hull once");
    for (uint32_t s = 0; s < m->count; s++) {
        if (!power_is_site(m, s))
            continue;
        if (hull2 == 0) {
            int status = power_line_status(m, s);
            FUZZ_REQUIRE(status != 1 || hidden[s] == 1, "power, on a line: a site above the chain kept");
            FUZZ_REQUIRE(status != -1 || hidden[s] == 0, "power, on a line: a corner of the chain hidden");
        } else if (!hidden[s] && !corner[s]) {
            int on = 0;
            for (uint32_t t = 0; t < nt && !on; t++) {
                const uint32_t *v = power_triangle[t];
                vor_point_t a = m->point[v[0]], b = m->point[v[1]], c = m->point[v[2]];
                vor_point_t p = m->point[s];
                on = fuzz_orient(a, b, p) >= 0 && fuzz_orient(b, c, p) >= 0 &&
                     fuzz_orient(c, a, p) >= 0 &&
                     fuzz_power(a, m->weight[v[0]], b, m->weight[v[1]], c, m->weight[v[2]], p,
                                m->weight[s]) == 0;
            }
            FUZZ_REQUIRE(on, "power: a vertex in no triangle, not on the lifted surface");
        }
    }
    power_check_cells(m, hidden);
    FUZZ_REQUIRE(power_unchanged(m), "power reads changed the object or the arena");
}

/* A weighted site as inputs make them: a pattern point and weight, or the
 * point of a site made before (`made`) with another weight (one of them
 * hides the other) or the same (a duplicate). */
static void draw_weighted(fuzz_reader_t *r, const vor_point_t *made, const int64_t *made_w,
                          uint32_t made_count, vor_point_t *previous, int64_t *previous_w,
                          vor_point_t *p, int64_t *w)
{
    uint8_t how = fuzz_u8(r);
    if (made_count > 0 && how >= 0xc0u) {
        uint32_t k = fuzz_u8(r) % made_count;
        *p = *previous = made[k];
        *previous_w = made_w[k];
        *w = how >= 0xf0u ? made_w[k] : fuzz_weight(r, previous_w);
        return;
    }
    *p = fuzz_point(r, previous);
    *w = fuzz_weight(r, previous_w);
}

/* The smallest site (not a duplicate's or removed id) with point p and
 * weight w, or m->count. */
static uint32_t power_site_twin(const power_model_t *m, vor_point_t p, int64_t w)
{
    for (uint32_t i = 0; i < m->count; i++)
        if (power_is_site(m, i) && m->point[i].x == p.x && m->point[i].y == p.y &&
            m->weight[i] == w)
            return i;
    return m->count;
}

/* vor_power_insert of p, w (id wanted or not), checked against the model:
 * the most recently removed id, else the next one. */
static void power_insert_checked(power_model_t *m, vor_point_t p, int64_t w, int want_id)
{
    uint32_t id = 0xdeadbeefu;
    power_snapshot(m);
    int result = vor_power_insert(&m->pd, p, w, want_id ? &id : NULL);
    uint32_t first = power_site_twin(m, p, w);
    if (first < m->count) {
        FUZZ_REQUIRE(result == VOR_ERR_DUPLICATE && (!want_id || id == first),
                     "power_insert: a duplicate missed, or the wrong twin");
        FUZZ_REQUIRE(power_unchanged(m), "power_insert: a duplicate changed the object");
    } else if (m->free_count == 0u && m->count == m->capacity) {
        FUZZ_REQUIRE(result == VOR_ERR_FULL && id == 0xdeadbeefu,
                     "power_insert: a full object accepted a site, or wrote its id");
        FUZZ_REQUIRE(power_unchanged(m), "power_insert: full, and changed the object");
    } else {
        uint32_t next = m->free_count > 0u ? m->free_ids[--m->free_count] : m->count++;
        FUZZ_REQUIRE(result == VOR_OK && (!want_id || id == next),
                     "power_insert failed, or not the most recently freed or next id");
        m->point[next] = p;
        m->weight[next] = w;
        m->first[next] = next;
    }
}

/* vor_power_remove of an id from the input (sites, removed, duplicates',
 * unused ones). */
static void op_power_remove(fuzz_reader_t *r, power_model_t *m)
{
    uint32_t id = fuzz_u8(r) % (m->count + 2u);
    power_snapshot(m);
    int result = vor_power_remove(&m->pd, id);
    if (power_is_site(m, id)) {
        FUZZ_REQUIRE(result == VOR_OK, "power_remove: a site refused");
        m->first[id] = POWER_FREE;
        m->free_ids[m->free_count++] = id;
    } else {
        FUZZ_REQUIRE(result == VOR_ERR_ARG, "power_remove: no site accepted");
        FUZZ_REQUIRE(power_unchanged(m), "power_remove: a failure changed the object");
    }
}

/* vor_power_move of an id from the input to a weighted site as inputs
 * make them (often a site's point: a duplicate, or the site itself). */
static void op_power_move(fuzz_reader_t *r, power_model_t *m, vor_point_t *previous,
                          int64_t *previous_w)
{
    uint32_t id = fuzz_u8(r) % (m->count + 2u), existing = 0xdeadbeefu;
    vor_point_t p;
    int64_t w;
    draw_weighted(r, m->point, m->weight, m->count, previous, previous_w, &p, &w);
    uint8_t want = fuzz_u8(r) & 1u;
    power_snapshot(m);
    int result = vor_power_move(&m->pd, id, p, w, want ? &existing : NULL);
    uint32_t same = power_site_twin(m, p, w);
    if (!power_is_site(m, id)) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && existing == 0xdeadbeefu,
                     "power_move: no site accepted");
        FUZZ_REQUIRE(power_unchanged(m), "power_move: a failure changed the object");
    } else if (same < m->count && same != id) {
        FUZZ_REQUIRE(result == VOR_ERR_DUPLICATE && (!want || existing == same),
                     "power_move: a duplicate missed, or the wrong twin");
        FUZZ_REQUIRE(power_unchanged(m), "power_move: a duplicate changed the object");
    } else {
        FUZZ_REQUIRE(result == VOR_OK && existing == 0xdeadbeefu, "power_move failed");
        FUZZ_REQUIRE(same != id || power_unchanged(m), "power_move: in place, and changed");
        m->point[id] = p;
        m->weight[id] = w;
    }
}

/* |q - p|^2 - w, exact (below 2^66 in magnitude). */
static __int128 power_distance(vor_point_t q, vor_point_t p, int64_t w)
{
    __int128 dx = (__int128)q.x - p.x, dy = (__int128)q.y - p.y;
    return dx * dx + dy * dy - w;
}

/* vor_power_nearest against a scan (ties: the smallest id), at a point
 * as inputs make them or a site's point, from a hint from the input. */
static void op_power_nearest(fuzz_reader_t *r, power_model_t *m, vor_point_t *previous)
{
    uint8_t how = fuzz_u8(r);
    vor_point_t q = fuzz_point(r, previous);
    if (m->count > 0u && how >= 0x80u)
        q = m->point[fuzz_u8(r) % m->count];
    uint32_t hint = (how & 1u) ? VOR_NO_HINT : fuzz_u8(r) % (m->count + 2u);
    uint32_t best = m->count;
    for (uint32_t i = 0; i < m->count; i++)
        if (power_is_site(m, i) &&
            (best == m->count || power_distance(q, m->point[i], m->weight[i]) <
                                     power_distance(q, m->point[best], m->weight[best])))
            best = i;
    uint32_t got = 0xdeadbeefu;
    power_snapshot(m);
    int result = vor_power_nearest(&m->pd, q, hint, &got);
    if (best == m->count) {
        FUZZ_REQUIRE(result == VOR_ERR_EMPTY && got == 0xdeadbeefu, "power_nearest: not empty");
    } else if (hint != VOR_NO_HINT && !power_is_site(m, hint)) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG && got == 0xdeadbeefu,
                     "power_nearest: a hint that is no site accepted");
    } else {
        FUZZ_REQUIRE(result == VOR_OK && got == best,
                     "power_nearest: not the nearest site of smallest id");
    }
    FUZZ_REQUIRE(power_unchanged(m), "power_nearest changed the object");
}

static void op_power_insert(fuzz_reader_t *r, power_model_t *m, vor_point_t *previous,
                            int64_t *previous_w)
{
    uint8_t flags = fuzz_u8(r);
    vor_point_t p;
    int64_t w;
    draw_weighted(r, m->point, m->weight, m->count, previous, previous_w, &p, &w);
    power_insert_checked(m, p, w, (flags & 1u) == 0);
}

/* A site on the line through two sites, a few steps along it: collinear
 * runs across the whole range, and 1-dimensional objects growing. */
static void op_power_on_line(fuzz_reader_t *r, power_model_t *m, int64_t *previous_w)
{
    uint8_t pick = fuzz_u8(r), other = fuzz_u8(r), step = fuzz_u8(r);
    if (m->count == 0)
        return;
    vor_point_t a = m->point[pick % m->count], b = m->point[other % m->count];
    int64_t k = (int8_t)step % 4;
    int64_t x = a.x + k * ((int64_t)b.x - a.x), y = a.y + k * ((int64_t)b.y - a.y);
    if (x < INT32_MIN || x > INT32_MAX || y < INT32_MIN || y > INT32_MAX)
        return;
    vor_point_t p = {(int32_t)x, (int32_t)y};
    power_insert_checked(m, p, fuzz_weight(r, previous_w), 1);
}

static void op_power_build(fuzz_reader_t *r, power_model_t *m, vor_point_t *previous,
                           int64_t *previous_w)
{
    vor_point_t points[BUILD_POINTS];
    int64_t weights[BUILD_POINTS];
    uint32_t duplicate_of[BUILD_POINTS], before[BUILD_POINTS];
    uint32_t n = fuzz_u8(r) % (BUILD_POINTS + 1u);
    uint8_t how = fuzz_u8(r);
    for (uint32_t i = 0; i < n; i++)
        draw_weighted(r, points, weights, i, previous, previous_w, &points[i], &weights[i]);
    memset(duplicate_of, 0xee, sizeof duplicate_of);
    memcpy(before, duplicate_of, sizeof before);
    const vor_point_t *pp = how % 8u == 0u ? NULL : points;
    const int64_t *pw = how % 8u == 1u ? NULL : weights;
    uint32_t *dup = (how & 8u) ? NULL : duplicate_of;
    power_snapshot(m);
    int result = vor_power_build(&m->pd, pp, pw, n, dup);
    if ((pp == NULL || pw == NULL) && n > 0u) {
        FUZZ_REQUIRE(result == VOR_ERR_ARG, "power_build: NULL points or weights accepted");
    } else if (n > m->capacity) {
        FUZZ_REQUIRE(result == VOR_ERR_FULL, "power_build: more points than room accepted");
    } else {
        FUZZ_REQUIRE(result == VOR_OK, "power_build failed");
        m->count = n;
        m->free_count = 0;
        for (uint32_t i = 0; i < n; i++) {
            m->point[i] = points[i];
            m->weight[i] = weights[i];
            m->first[i] = power_twin(points, weights, i, points[i], weights[i]);
            FUZZ_REQUIRE(dup == NULL || duplicate_of[i] == m->first[i],
                         "power_build: wrong duplicate_of");
        }
        return;
    }
    FUZZ_REQUIRE(power_unchanged(m) && memcmp(before, duplicate_of, sizeof before) == 0,
                 "power_build: a failure changed the object or wrote duplicate_of");
}

/* Inits: one that fails for each documented reason (nothing may change),
 * or a new one (capacity and arena size from the input). */
static void op_power_init(fuzz_reader_t *r, power_model_t *m)
{
    uint8_t how = fuzz_u8(r), size = fuzz_u8(r);
    uint32_t capacity = 1u + size % MOST_SITES;
    size_t bytes = VOR_POWER_ARENA_BYTES(capacity);
    int result, documented;
    power_snapshot(m);
    switch (how % 8u) {
    case 0:
        result = vor_power_init(&m->pd, power_arena, bytes - 1u - how / 8u % 8u, capacity);
        documented = VOR_ERR_NOMEM;
        break;
    case 1:
        result = vor_power_init(&m->pd, power_arena + 1u + how / 8u % 7u, bytes, capacity);
        documented = VOR_ERR_ALIGN;
        break;
    case 2:
        result = vor_power_init(&m->pd, power_arena, sizeof power_arena, 0);
        documented = VOR_ERR_ARG;
        break;
    case 3:
        result = vor_power_init(&m->pd, power_arena, sizeof power_arena, VOR_MAX_SITES + 1u + how);
        documented = VOR_ERR_ARG;
        break;
    case 4:
        result = vor_power_init(&m->pd, NULL, bytes, capacity);
        documented = VOR_ERR_ARG;
        break;
    case 5:
        result = vor_power_init_checked(&m->pd, power_arena, bytes, capacity,
                                        VOR_CONFIG_FINGERPRINT ^ (1u << (how / 8u)));
        documented = VOR_ERR_CONFIG;
        break;
    default:
        bytes += size / MOST_SITES % POWER_SLACK;
        FUZZ_REQUIRE(vor_power_init(&m->pd, power_arena, bytes, capacity) == VOR_OK,
                     "power_init failed");
        m->capacity = capacity;
        m->count = 0;
        m->free_count = 0;
        return;
    }
    FUZZ_REQUIRE(result == documented, "power_init: not the documented error");
    FUZZ_REQUIRE(power_unchanged(m), "power_init: a failure changed the object or the arena");
}

/* Every call with the arguments callers get wrong: NULLs, an iterator
 * whose begin failed, an object vor_power_init never saw (zeroed). */
static void op_power_bad_arguments(fuzz_reader_t *r, power_model_t *m, vor_point_t *previous,
                                   int64_t *previous_w)
{
    static vor_power_t zeroed;
    static const vor_power_t zero;
    vor_point_t p = fuzz_point(r, previous);
    int64_t w = fuzz_weight(r, previous_w);
    uint32_t id = 77, ids[3] = {77, 77, 77};
    vor_violation_t violation = {VOR_CHECK_COUNTS, 77, 77};
    vor_power_hidden_iter_t hi;
    vor_triangle_iter_t ti;
    power_snapshot(m);
    FUZZ_REQUIRE(vor_power_insert(NULL, p, w, &id) == VOR_ERR_ARG &&
                     vor_power_build(NULL, &p, &w, 1, &id) == VOR_ERR_ARG &&
                     vor_power_hidden(NULL, 0) == VOR_ERR_ARG &&
                     vor_power_validate(NULL, &violation) == VOR_ERR_ARG &&
                     vor_power_remove(NULL, 0) == VOR_ERR_ARG &&
                     vor_power_move(NULL, 0, p, w, &id) == VOR_ERR_ARG &&
                     vor_power_nearest(NULL, p, VOR_NO_HINT, &id) == VOR_ERR_ARG &&
                     vor_power_nearest(&m->pd, p, VOR_NO_HINT, NULL) == VOR_ERR_ARG &&
                     id == 77 &&
                     violation.triangle == 77,
                 "power: a NULL object accepted, or written through");
    FUZZ_REQUIRE(vor_power_hidden_begin(NULL, &m->pd) == VOR_ERR_ARG &&
                     vor_power_hidden_begin(&hi, NULL) == VOR_ERR_ARG &&
                     vor_power_hidden_next(&hi, &id) == 0 && vor_power_hidden_next(NULL, &id) == 0 &&
                     vor_power_hidden_begin(&hi, &m->pd) == VOR_OK &&
                     vor_power_hidden_next(&hi, NULL) == 0 && id == 77,
                 "power hidden iterator: NULLs accepted, or wrote");
    FUZZ_REQUIRE(vor_power_triangles_begin(NULL, &m->pd) == VOR_ERR_ARG &&
                     vor_power_triangles_begin(&ti, NULL) == VOR_ERR_ARG &&
                     vor_triangles_next(&ti, ids) == 0 &&
                     vor_power_triangles_begin(&ti, &m->pd) == VOR_OK &&
                     vor_triangles_next(&ti, NULL) == 0 && ids[0] == 77,
                 "power triangles: NULLs accepted, or wrote");
    FUZZ_REQUIRE(power_unchanged(m), "power: bad arguments changed the object");
    memset(&zeroed, 0, sizeof zeroed);
    FUZZ_REQUIRE(vor_power_insert(&zeroed, p, w, &id) == VOR_ERR_FULL &&
                     vor_power_build(&zeroed, &p, &w, 1, &id) == VOR_ERR_FULL &&
                     vor_power_hidden(&zeroed, 0) == VOR_ERR_ARG &&
                     vor_power_validate(&zeroed, NULL) == VOR_OK &&
                     vor_power_remove(&zeroed, 0) == VOR_ERR_ARG &&
                     vor_power_move(&zeroed, 0, p, w, &id) == VOR_ERR_ARG &&
                     vor_power_nearest(&zeroed, p, VOR_NO_HINT, &id) == VOR_ERR_EMPTY && id == 77,
                 "power: a zeroed object not empty and full");
    FUZZ_REQUIRE(vor_power_hidden_begin(&hi, &zeroed) == VOR_OK &&
                     vor_power_hidden_next(&hi, &id) == 0 &&
                     vor_power_triangles_begin(&ti, &zeroed) == VOR_OK &&
                     vor_triangles_next(&ti, ids) == 0 && id == 77 && ids[0] == 77,
                 "power: a zeroed object's iterators not empty");
    FUZZ_REQUIRE(memcmp(&zeroed, &zero, sizeof zero) == 0, "power: a zeroed object written");
}

/* The power program: a capacity and an arena size, then up to 64 calls,
 * each followed by power_check. */
static int power_program(fuzz_reader_t *r)
{
    static power_model_t m;
    vor_point_t previous = {0, 0};
    int64_t previous_w = 0;
    memset(&m, 0, sizeof m);
    (void)fuzz_u8(r); /* the mode */
    uint8_t size = fuzz_u8(r);
    m.capacity = 1u + size % MOST_SITES;
    FUZZ_REQUIRE(vor_power_init(&m.pd, power_arena,
                                VOR_POWER_ARENA_BYTES(m.capacity) + size / MOST_SITES % POWER_SLACK,
                                m.capacity) == VOR_OK,
                 "power_init failed");
    for (uint32_t ops = 0; ops < 64u && !fuzz_done(r); ops++) {
        switch (fuzz_u8(r) % 8u) {
        case 0:
        case 1:
        case 2: op_power_insert(r, &m, &previous, &previous_w); break;
        case 3: op_power_build(r, &m, &previous, &previous_w); break;
        case 4: op_power_on_line(r, &m, &previous_w); break;
        case 5: op_power_init(r, &m); break;
        case 6: op_power_bad_arguments(r, &m, &previous, &previous_w); break;
        default: /* removals, moves, the nearest site, or power_check alone */
            switch (fuzz_u8(r) % 4u) {
            case 0: op_power_remove(r, &m); break;
            case 1: op_power_move(r, &m, &previous, &previous_w); break;
            case 2: op_power_nearest(r, &m, &previous); break;
            default: break;
            }
            break;
        }
        power_check(&m);
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_reader_t r = {data, size, 0};
    if (size > 0 && data[0] >= POWER_MODE)
        return power_program(&r);
    static model_t m;
    vor_point_t previous = {0, 0};
    memset(&m, 0, sizeof m);
    m.capacity = 1u + fuzz_u8(&r) % MOST_SITES;
    FUZZ_REQUIRE(vor_init(&m.d, arena, VOR_ARENA_BYTES(m.capacity), m.capacity) == VOR_OK,
                 "init failed");
    FUZZ_REQUIRE(vor_tracker_begin(&m.tracker, &m.d) == VOR_OK, "tracker_begin failed");
    if (m.capacity % 2u == 1u) /* no byte read: the corpora keep their meaning */
        FUZZ_REQUIRE(vor_motion_attach(&m.d, motion, VOR_MOTION_BYTES(m.capacity)) == VOR_OK,
                     "motion_attach failed");
    for (uint32_t ops = 0; ops < 64u && !fuzz_done(&r); ops++) {
        uint8_t op = fuzz_u8(&r);
        if (op >= 0xe0u) { /* the constraints' calls: the other ops keep their bytes */
            switch (op & 7u) {
            case 0: op_cdt_attach(&r, &m); break;
            case 1:
            case 2: op_constrain(&r, &m); break;
            case 3: op_unconstrain(&r, &m); break;
            case 4: op_cdt_domain(&m); break;
            case 5: op_cdt_reads(&r, &m); break;
            case 6: op_cdt_polygon(&r, &m); break;
            default: op_cdt_on_constraint(&r, &m); break;
            }
            check_valid(&m);
            continue;
        }
        switch (op % 13u) {
        case 0: op_build(&r, &m, &previous, 0); break;
        case 1: op_build(&r, &m, &previous, 1); break;
        case 2: op_insert(&r, &m, &previous, 0); break;
        case 3: op_insert(&r, &m, &previous, 1); break;
        case 4: op_nearest(&r, &m, &previous); break;
        case 5: op_nearest_k(&r, &m, &previous); break;
        case 6: op_track(&r, &m, &previous); break;
        case 7: op_cells(&r, &m, &previous); break;
        case 8: op_triangles(&m); op_edges_neighbours(&r, &m); break;
        case 9: op_clip(&r, &m, &previous); break;
        case 10: op_centroid(&r, &m, &previous); break;
        case 11: op_remove(&r, &m); break;
        case 12: op_move(&r, &m, &previous); break;
        default: op_bad_init(&r, &m); break;
        }
        check_valid(&m);
    }
    return 0;
}
