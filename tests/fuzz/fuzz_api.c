/* SPDX-License-Identifier: MIT */
/*
 * fuzz_api.c - libFuzzer harness: the fuzz bytes are a program of calls on
 * one small diagram (arenas that run out, both index widths: built with
 * -DVOR_INDEX_BITS=16 and 32): builds, inserts, removes, moves, queries,
 * iterators, the two-core builder through a one-thread hook, Voronoi
 * vertices, the memory figures and the counters. After every call
 * vor_validate must pass; every failing call must leave the vor_t and the
 * arena byte-for-byte unchanged; answers are
 * checked against a model kept here (the sites by id, each duplicate's
 * first occurrence, the freed ids) and brute force with exact wide-integer
 * distances; on small sets the triangles are checked for empty
 * circumcircles, positive area and the count 2n - h - 2; cell centroids
 * against vor_cell and their box. Diagrams of odd capacity carry a motion
 * cache (vor_motion_attach), whose bytes a failing call must not change
 * either.
 */
#include <string.h>

#include "fuzz_common.h"

#define MOST_SITES 24u
#define BUILD_POINTS (MOST_SITES + 4u) /* builds may ask for more than fit */

static uint8_t arena[VOR_ARENA_BYTES(MOST_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t arena_before[sizeof arena];
static uint8_t motion[VOR_MOTION_BYTES(MOST_SITES)] __attribute__((aligned(VOR_MOTION_ALIGN)));
static uint8_t motion_before[sizeof motion];

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
} model_t;

static vor_t diagram_before;

static void snapshot(const model_t *m)
{
    memcpy(&diagram_before, &m->d, sizeof m->d);
    memcpy(arena_before, arena, sizeof arena);
    memcpy(motion_before, motion, sizeof motion);
}

static int unchanged(const model_t *m)
{
    return memcmp(&diagram_before, &m->d, sizeof m->d) == 0 &&
           memcmp(arena_before, arena, sizeof arena) == 0 &&
           memcmp(motion_before, motion, sizeof motion) == 0;
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
}

static void op_insert(fuzz_reader_t *r, model_t *m, vor_point_t *previous, int near)
{
    vor_point_t p = fuzz_point(r, previous);
    uint32_t hint = near ? draw_hint(r, m) : VOR_NO_HINT;
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
    } else {
        /* the most recently freed id first */
        uint32_t expected = m->freed_count ? m->freed[--m->freed_count] : m->count++;
        FUZZ_REQUIRE(result == VOR_OK && id == expected, "insert failed or wrong id");
        m->point[id] = p;
        m->first[id] = id;
        m->removed[id] = 0;
        return;
    }
    FUZZ_REQUIRE(unchanged(m), "insert: failure changed the diagram");
}

static void op_nearest(fuzz_reader_t *r, model_t *m, vor_point_t *previous)
{
    vor_point_t q = fuzz_point(r, previous);
    uint32_t hint = draw_hint(r, m);
    uint32_t order[MOST_SITES];
    uint32_t n = brute_order(m, q.x, q.y, order);
    uint32_t id = 0xdeadbeefu;
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
    FUZZ_REQUIRE(result == VOR_OK, "remove failed");
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
    FUZZ_REQUIRE(result == VOR_OK, "move failed");
    m->point[id] = p;
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

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_reader_t r = {data, size, 0};
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
        switch (fuzz_u8(&r) % 13u) {
        case 0: op_build(&r, &m, &previous, 0); break;
        case 1: op_build(&r, &m, &previous, 1); break;
        case 2: op_insert(&r, &m, &previous, 0); break;
        case 3: op_insert(&r, &m, &previous, 1); break;
        case 4: op_nearest(&r, &m, &previous); break;
        case 5: op_nearest_k(&r, &m, &previous); break;
        case 6: op_track(&r, &m, &previous); break;
        case 7: op_cells(&r, &m, &previous); break;
        case 8: op_triangles(&m); op_edges_neighbours(&r, &m); break;
        case 10: op_centroid(&r, &m, &previous); break;
        case 11: op_remove(&r, &m); break;
        case 12: op_move(&r, &m, &previous); break;
        default: op_bad_init(&r, &m); break;
        }
        check_valid(&m);
    }
    return 0;
}
