/* SPDX-License-Identifier: MIT */
/*
 * test_locate.c - the queries robots ask, against brute force:
 *   vor_locate            every triangle the iterator lists, tested with
 *                         the public perturbed orientation
 *                         (vor_orient2d_sos, the query at index 0 of a
 *                         copy of the sites, before every site): the
 *                         answer is the one triangle holding the moved
 *                         query, or VOR_ERR_OUTSIDE when none does;
 *   vor_within            every site's squared distance, exact (65-bit);
 *   vor_triangles_export  the iterator's triangles in order, and each
 *                         half-edge's twin found by a search of all
 *                         half-edges for the reversed pair.
 * Sets: uniform, grid (collinear and cocircular runs), a circle of
 * lattice points, collinear, 0 to 3 sites, duplicates, wide coordinates,
 * a diagram after removals. Queries at every site, on every edge
 * (midpoints: even coordinates), at centroids, random, outside.
 */
#include "test.h"
#include "vor.h"

#define LOCATE_SITES 160u
#define LOCATE_TRIANGLES VOR_TRIANGLES_MAX(LOCATE_SITES)

static vor_point_t sites[LOCATE_SITES];
static vor_point_t moved[LOCATE_SITES + 1u]; /* [0]: the query; [1 + i]: site i */
static uint32_t first_of[LOCATE_SITES];
static uint32_t listed[3u * LOCATE_TRIANGLES];
static uint32_t exported[3u * LOCATE_TRIANGLES];
static uint32_t halfedges[3u * LOCATE_TRIANGLES];
static uint32_t found[LOCATE_SITES + 1u];
static uint8_t arena[VOR_ARENA_BYTES(LOCATE_SITES)] __attribute__((aligned(8)));

/* The iterator's triangles into listed[]; returns how many. */
static uint32_t list_triangles(const vor_t *d)
{
    vor_triangle_iter_t it;
    uint32_t ids[3], t = 0;
    CHECK(vor_triangles_begin(&it, d) == VOR_OK, "triangles_begin");
    while (vor_triangles_next(&it, ids) && t < LOCATE_TRIANGLES) {
        listed[3u * t] = ids[0];
        listed[3u * t + 1u] = ids[1];
        listed[3u * t + 2u] = ids[2];
        t++;
    }
    return t;
}

/* The listed triangle holding q moved by the perturbation with q's
 * index before every site; LOCATE_TRIANGLES when none; *holding counts
 * the triangles that hold it (one at most in a triangulation). */
static uint32_t brute_locate(uint32_t n, uint32_t triangles, vor_point_t q, uint32_t *holding)
{
    moved[0] = q;
    for (uint32_t i = 0; i < n; i++) {
        moved[1u + i] = sites[i];
    }
    uint32_t answer = LOCATE_TRIANGLES;
    *holding = 0;
    for (uint32_t t = 0; t < triangles; t++) {
        const uint32_t *v = &listed[3u * t];
        if (vor_orient2d_sos(moved, 1u + v[0], 1u + v[1], 0) > 0 &&
            vor_orient2d_sos(moved, 1u + v[1], 1u + v[2], 0) > 0 &&
            vor_orient2d_sos(moved, 1u + v[2], 1u + v[0], 0) > 0) {
            answer = t;
            (*holding)++;
        }
    }
    return answer;
}

/* |q - p|^2 <= r2, exactly (differences below 2^32: 65-bit sums). */
static bool brute_in_disc(vor_point_t q, vor_point_t p, uint64_t r2)
{
    int64_t dx = (int64_t)q.x - p.x, dy = (int64_t)q.y - p.y;
    uint64_t mx = (uint64_t)(dx < 0 ? -dx : dx), my = (uint64_t)(dy < 0 ? -dy : dy);
    uint64_t a = mx * mx, sum = a + my * my;
    return sum >= a && sum <= r2;
}

/* |q - p|^2, saturated at UINT64_MAX. */
static uint64_t distance2(vor_point_t q, vor_point_t p)
{
    int64_t dx = (int64_t)q.x - p.x, dy = (int64_t)q.y - p.y;
    uint64_t mx = (uint64_t)(dx < 0 ? -dx : dx), my = (uint64_t)(dy < 0 ? -dy : dy);
    uint64_t a = mx * mx, sum = a + my * my;
    return (sum < a) ? UINT64_MAX : sum;
}

typedef struct {
    const char *name;
    uint32_t n;
    unsigned wrong;
} run_t;

/* vor_locate at q with a hint, against brute force. */
static void check_locate(run_t *r, const vor_t *d, uint32_t triangles, vor_point_t q, uint32_t hint)
{
    uint32_t holding;
    uint32_t expect = brute_locate(r->n, triangles, q, &holding);
    uint32_t ids[3] = {7u, 7u, 7u};
    int err = vor_locate(d, q, hint, ids);
    bool ok = holding <= 1u;
    if (expect == LOCATE_TRIANGLES) {
        ok = ok && err == (d->vertex_count == 0u ? VOR_ERR_EMPTY : VOR_ERR_OUTSIDE) && ids[0] == 7u &&
             ids[1] == 7u && ids[2] == 7u;
    } else {
        const uint32_t *v = &listed[3u * expect];
        ok = ok && err == VOR_OK && ids[0] == v[0] && ids[1] == v[1] && ids[2] == v[2];
    }
    if (!ok && r->wrong++ < 3u) {
        CHECK(false, "%s: locate(%d, %d) hint %u: err %d, %u %u %u; brute force %u of %u (%u hold)",
              r->name, q.x, q.y, hint, err, ids[0], ids[1], ids[2], expect, triangles, holding);
    }
}

/* vor_within at q for r2, against every site's distance; also with the
 * capacity one short (VOR_ERR_BUFFER, nothing written) and a capacity
 * below the site count (the counted path). */
static void check_within(run_t *r, const vor_t *d, vor_point_t q, uint64_t r2, uint32_t hint)
{
    uint32_t expect[LOCATE_SITES], count = 0;
    for (uint32_t i = 0; i < r->n; i++) {
        if (first_of[i] == i && brute_in_disc(q, sites[i], r2)) {
            expect[count++] = i; /* increasing */
        }
    }
    for (uint32_t i = 0; i <= LOCATE_SITES; i++) {
        found[i] = 0xA5A5A5A5u;
    }
    uint32_t got = 12345u;
    int err = vor_within(d, q, r2, hint, found, LOCATE_SITES, &got);
    bool ok = err == VOR_OK && got == count && found[count] == 0xA5A5A5A5u;
    for (uint32_t i = 0; ok && i < count; i++) {
        ok = found[i] == expect[i];
    }
    /* exactly the capacity needed, below the site count: counted first */
    uint32_t again = 0;
    found[count] = 0xA5A5A5A5u;
    ok = ok && vor_within(d, q, r2, VOR_NO_HINT, found, count, &again) == VOR_OK && again == count &&
         found[count] == 0xA5A5A5A5u;
    for (uint32_t i = 0; ok && i < count; i++) {
        ok = found[i] == expect[i];
    }
    if (count > 0u) {
        for (uint32_t i = 0; i < count; i++) {
            found[i] = 0xA5A5A5A5u;
        }
        uint32_t needed = 0;
        ok = ok && vor_within(d, q, r2, hint, found, count - 1u, &needed) == VOR_ERR_BUFFER &&
             needed == count && found[0] == 0xA5A5A5A5u && found[count - 1u] == 0xA5A5A5A5u;
    }
    if (!ok && r->wrong++ < 3u) {
        CHECK(false, "%s: within(%d, %d, r2 %u) err %d: %u sites, brute force %u", r->name, q.x, q.y,
              (unsigned)(r2 & 0xFFFFFFFFu), err, got, count);
    }
}

/* vor_triangles_export against the iterator and a brute-force twin
 * search; a buffer one short and halfedges NULL too. */
static void check_export(run_t *r, const vor_t *d, uint32_t triangles)
{
    uint32_t count = 99u;
    CHECK(vor_triangles_count(d, &count) == VOR_OK && count == triangles, "%s: count %u of %u",
          r->name, count, triangles);
    for (uint32_t i = 0; i < 3u * LOCATE_TRIANGLES; i++) {
        exported[i] = halfedges[i] = 0x5A5A5A5Au;
    }
    if (triangles > 0u) {
        count = 0;
        CHECK(vor_triangles_export(d, exported, halfedges, triangles - 1u, &count) == VOR_ERR_BUFFER &&
                  count == triangles && exported[0] == 0x5A5A5A5Au && halfedges[0] == 0x5A5A5A5Au,
              "%s: export one short", r->name);
    }
    count = 0;
    CHECK(vor_triangles_export(d, exported, halfedges, LOCATE_TRIANGLES, &count) == VOR_OK &&
              count == triangles,
          "%s: export %u of %u", r->name, count, triangles);
    unsigned bad = 0, none = 0;
    for (uint32_t e = 0; e < 3u * triangles; e++) {
        bad += (exported[e] != listed[e]) ? 1u : 0u;
        uint32_t from = listed[e], to = listed[(e % 3u == 2u) ? e - 2u : e + 1u];
        uint32_t twin = VOR_HALFEDGE_NONE;
        for (uint32_t f = 0; f < 3u * triangles; f++) {
            uint32_t ff = listed[f], ft = listed[(f % 3u == 2u) ? f - 2u : f + 1u];
            if (ff == to && ft == from) {
                bad += (twin != VOR_HALFEDGE_NONE) ? 1u : 0u; /* a second twin */
                twin = f;
            }
        }
        none += (twin == VOR_HALFEDGE_NONE) ? 1u : 0u;
        bad += (halfedges[e] != twin) ? 1u : 0u;
    }
    bad += (exported[3u * triangles] != 0x5A5A5A5Au || halfedges[3u * triangles] != 0x5A5A5A5Au) ? 1u : 0u;
    CHECK(bad == 0u, "%s: export: %u wrong entries (%u hull edges)", r->name, bad, none);
    /* the triangles alone */
    for (uint32_t i = 0; i < 3u * triangles; i++) {
        exported[i] = 0;
    }
    CHECK(vor_triangles_export(d, exported, NULL, triangles, &count) == VOR_OK && count == triangles &&
              test_same_bytes(exported, listed, 3u * triangles * sizeof(uint32_t)),
          "%s: export without halfedges", r->name);
}

/* Every check on d, built from sites[0 .. n) (or changed since): queries
 * at the sites, on the triangles' edges and at their centroids, random
 * ones in and around the box, with hints; within at distances of sites. */
static void check_diagram(const char *name, const vor_t *d, uint32_t n, test_rng_t *rng)
{
    run_t r = {name, n, 0};
    uint32_t triangles = list_triangles(d);
    CHECK(vor_validate(d, NULL) == VOR_OK, "%s: valid", name);
    check_export(&r, d, triangles);
    int64_t lx = 0, ly = 0, hx = 0, hy = 0;
    for (uint32_t i = 0; i < n; i++) {
        lx = (i == 0u || sites[i].x < lx) ? sites[i].x : lx;
        ly = (i == 0u || sites[i].y < ly) ? sites[i].y : ly;
        hx = (i == 0u || sites[i].x > hx) ? sites[i].x : hx;
        hy = (i == 0u || sites[i].y > hy) ? sites[i].y : hy;
    }
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t i = 0; i < n; i++) {
        if (first_of[i] != i) {
            continue;
        }
        vor_point_t q = sites[i];
        check_locate(&r, d, triangles, q, (i % 2u == 0u) ? VOR_NO_HINT : hint);
        vor_point_t e = sites[(i * 7u + 3u) % n];
        uint64_t r2 = distance2(q, e);
        check_within(&r, d, q, r2, hint);
        check_within(&r, d, q, r2 - (r2 > 0u ? 1u : 0u), VOR_NO_HINT);
        hint = i;
    }
    for (uint32_t t = 0; t < triangles; t++) {
        const uint32_t *v = &listed[3u * t];
        for (unsigned k = 0; k < 3u; k++) {
            vor_point_t a = sites[v[k]], b = sites[v[(k + 1u) % 3u]];
            vor_point_t m = {(int32_t)(((int64_t)a.x + b.x) / 2), (int32_t)(((int64_t)a.y + b.y) / 2)};
            check_locate(&r, d, triangles, m, (k == 0u) ? VOR_NO_HINT : v[k]);
        }
        vor_point_t c = {
            (int32_t)(((int64_t)sites[v[0]].x + sites[v[1]].x + sites[v[2]].x) / 3),
            (int32_t)(((int64_t)sites[v[0]].y + sites[v[1]].y + sites[v[2]].y) / 3)};
        check_locate(&r, d, triangles, c, VOR_NO_HINT);
    }
    if (n > 0u) { /* the origin: the circle set's centre, where every site ties */
        vor_point_t o = {0, 0};
        uint64_t r2 = distance2(o, sites[0]);
        check_locate(&r, d, triangles, o, VOR_NO_HINT);
        check_within(&r, d, o, r2, VOR_NO_HINT);
        check_within(&r, d, o, r2 - (r2 > 0u ? 1u : 0u), VOR_NO_HINT);
    }
    int64_t wx = hx - lx + 2, wy = hy - ly + 2;
    for (unsigned k = 0; k < 120u; k++) {
        vor_point_t q;
        if (k % 4u == 3u) { /* anywhere */
            q.x = (int32_t)test_rng_u32(rng);
            q.y = (int32_t)test_rng_u32(rng);
        } else { /* in the box and a margin around it */
            int64_t x = lx - wx / 4 + (int64_t)(test_rng_u32(rng) % (uint32_t)(wx + wx / 2));
            int64_t y = ly - wy / 4 + (int64_t)(test_rng_u32(rng) % (uint32_t)(wy + wy / 2));
            q.x = (int32_t)(x < INT32_MIN ? INT32_MIN : x > INT32_MAX ? INT32_MAX : x);
            q.y = (int32_t)(y < INT32_MIN ? INT32_MIN : y > INT32_MAX ? INT32_MAX : y);
        }
        uint32_t h = (n > 0u && k % 2u == 0u) ? first_of[test_rng_u32(rng) % n] : VOR_NO_HINT;
        h = (h < n) ? h : VOR_NO_HINT; /* a removed site: no hint */
        check_locate(&r, d, triangles, q, h);
        if (n > 0u) {
            uint64_t r2 = distance2(q, sites[test_rng_u32(rng) % n]);
            check_within(&r, d, q, r2, h);
            check_within(&r, d, q, (k % 8u == 0u) ? UINT64_MAX : (k % 8u == 1u) ? 0u : r2 / 3u, h);
        }
    }
    CHECK(r.wrong == 0u, "%s: %u wrong answers", name, r.wrong);
}

static void build_and_check(const char *name, uint32_t n, test_rng_t *rng)
{
    vor_t d;
    CHECK(vor_init(&d, arena, sizeof arena, LOCATE_SITES) == VOR_OK, "init");
    CHECK(vor_build(&d, sites, n, NULL, first_of) == VOR_OK, "%s: build", name);
    check_diagram(name, &d, n, rng);
}

static void uniform_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 27);
    for (uint32_t i = 0; i < LOCATE_SITES; i++) { /* even: edge midpoints are integers */
        sites[i].x = 2 * test_rng_range(&rng, -500, 500);
        sites[i].y = 2 * test_rng_range(&rng, -500, 500);
    }
    build_and_check("uniform", LOCATE_SITES, &rng);
}

static void grid_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 28);
    uint32_t n = 0;
    for (int32_t y = 0; y < 12; y++) {
        for (int32_t x = 0; x < 12; x++) {
            sites[n].x = 4 * x;
            sites[n].y = 4 * y;
            n++;
        }
    }
    sites[n].x = 8; /* duplicates */
    sites[n].y = 8;
    n++;
    sites[n].x = 0;
    sites[n].y = 44;
    n++;
    build_and_check("grid", n, &rng);
}

/* Lattice points of the circle x^2 + y^2 = 65^2 (cocircular), and its
 * centre. */
static void circle_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 29);
    uint32_t n = 0;
    for (int32_t x = -65; x <= 65; x++) {
        for (int32_t y = -65; y <= 65; y++) {
            if (x * x + y * y == 65 * 65 && n < LOCATE_SITES - 1u) {
                sites[n].x = 2 * x;
                sites[n].y = 2 * y;
                n++;
            }
        }
    }
    build_and_check("circle", n, &rng);
    sites[n].x = 0;
    sites[n].y = 0;
    build_and_check("circle and centre", n + 1u, &rng);
}

static void collinear_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 30);
    for (uint32_t i = 0; i < 40u; i++) {
        sites[i].x = (int32_t)(6u * ((i * 17u) % 40u));
        sites[i].y = (int32_t)(2u * ((i * 17u) % 40u)) - 30;
    }
    build_and_check("collinear", 40, &rng);
    /* one site off the line: triangles that all touch it */
    sites[40].x = 30;
    sites[40].y = 100;
    build_and_check("collinear and one", 41, &rng);
}

static void small_sets(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 31);
    const vor_point_t few[4] = {{0, 0}, {10, 0}, {0, 10}, {20, 0}};
    for (uint32_t n = 0; n <= 3u; n++) {
        for (uint32_t i = 0; i < n; i++) {
            sites[i] = few[i];
        }
        build_and_check((n == 0u) ? "no sites" : (n == 1u) ? "one site" : (n == 2u) ? "two sites" : "three sites", n,
                        &rng);
    }
    sites[2] = few[3];
    build_and_check("three collinear", 3, &rng);
}

/* Coordinates across the whole int32 range: wide tiers, 65-bit sums. */
static void wide_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 32);
    for (uint32_t i = 0; i < 60u; i++) {
        sites[i].x = (int32_t)(test_rng_u32(&rng) & ~1u);
        sites[i].y = (int32_t)(test_rng_u32(&rng) & ~1u);
    }
    sites[0].x = INT32_MIN;
    sites[0].y = INT32_MIN;
    sites[1].x = INT32_MAX - 1;
    sites[1].y = INT32_MAX - 1;
    sites[2].x = INT32_MIN;
    sites[2].y = INT32_MAX - 1;
    build_and_check("wide", 60, &rng);
}

/* After removals and a reinsertion: home slots left empty, ids reused. */
static void dynamic_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 33);
    for (uint32_t i = 0; i < 80u; i++) {
        sites[i].x = 2 * test_rng_range(&rng, -300, 300);
        sites[i].y = 2 * test_rng_range(&rng, -300, 300);
    }
    vor_t d;
    CHECK(vor_init(&d, arena, sizeof arena, LOCATE_SITES) == VOR_OK, "init");
    CHECK(vor_build(&d, sites, 80, NULL, first_of) == VOR_OK, "dynamic: build");
    for (uint32_t i = 0; i < 80u; i += 5u) {
        if (first_of[i] == i) {
            CHECK(vor_remove(&d, i) == VOR_OK, "dynamic: remove %u", i);
            first_of[i] = LOCATE_SITES; /* not a site */
        }
    }
    vor_point_t p = {1, 3};
    uint32_t id = 0;
    CHECK(vor_insert(&d, p, &id) == VOR_OK && id < 80u && first_of[id] == LOCATE_SITES,
          "dynamic: insert");
    sites[id] = p;
    first_of[id] = id;
    check_diagram("dynamic", &d, 80, &rng);
}

/* The perturbation's rule as documented: on an edge the triangle above
 * it, on a vertical edge the one right of it, at a site the corner
 * holding straight up; a bottom hull edge inside, a top one outside. */
static void documented_rule(void)
{
    const vor_point_t square[4] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    const vor_point_t centre = {5, 5};
    vor_t d;
    for (uint32_t i = 0; i < 4u; i++) {
        sites[i] = square[i];
    }
    sites[4] = centre;
    CHECK(vor_init(&d, arena, sizeof arena, LOCATE_SITES) == VOR_OK, "init");
    CHECK(vor_build(&d, sites, 5, NULL, NULL) == VOR_OK, "build");
    static const struct {
        vor_point_t q;
        int err;
        uint32_t a, b; /* two of the triangle's sites (the third is 4) */
    } cases[] = {
        {{5, 0}, VOR_OK, 0, 1},                /* bottom hull edge: inside */
        {{5, 10}, VOR_ERR_OUTSIDE, 0, 0},      /* top hull edge: outside */
        {{0, 5}, VOR_OK, 3, 0},                /* left hull edge: right of it */
        {{10, 5}, VOR_ERR_OUTSIDE, 0, 0},      /* right hull edge: outside */
        {{5, 5}, VOR_OK, 2, 3},                /* the centre: straight up */
        {{0, 0}, VOR_OK, 3, 0},                /* corner: up along the edge, right of it */
        {{10, 0}, VOR_ERR_OUTSIDE, 0, 0},      /* up along the right edge: outside */
        {{2, 2}, VOR_OK, 3, 0},                /* on the diagonal 0-4: above it */
        {{8, 2}, VOR_OK, 1, 2},                /* on the diagonal 1-4: above it */
        {{7, 7}, VOR_OK, 2, 3},                /* on the diagonal 2-4: above it */
    };
    for (unsigned k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        uint32_t ids[3] = {9u, 9u, 9u};
        int err = vor_locate(&d, cases[k].q, VOR_NO_HINT, ids);
        bool ok = err == cases[k].err;
        if (err == VOR_OK) {
            unsigned have = 0;
            for (unsigned i = 0; i < 3u; i++) {
                have += (ids[i] == cases[k].a || ids[i] == cases[k].b || ids[i] == 4u) ? 1u : 0u;
            }
            ok = ok && have == 3u && vor_orient2d(sites[ids[0]], sites[ids[1]], sites[ids[2]]) > 0;
        }
        CHECK(ok, "locate(%d, %d): err %d, %u %u %u", cases[k].q.x, cases[k].q.y, err, ids[0], ids[1],
              ids[2]);
    }
}

/* Bad arguments: an error, nothing written. */
static void errors(void)
{
    vor_t d;
    uint32_t ids[3] = {1u, 2u, 3u}, count = 77u, out[4] = {5u, 5u, 5u, 5u};
    vor_point_t q = {0, 0};
    CHECK(vor_init(&d, arena, sizeof arena, LOCATE_SITES) == VOR_OK, "init");
    CHECK(vor_locate(NULL, q, VOR_NO_HINT, ids) == VOR_ERR_ARG, "locate NULL d");
    CHECK(vor_locate(&d, q, VOR_NO_HINT, NULL) == VOR_ERR_ARG, "locate NULL ids");
    CHECK(vor_locate(&d, q, VOR_NO_HINT, ids) == VOR_ERR_EMPTY, "locate empty");
    CHECK(vor_within(&d, q, 5, VOR_NO_HINT, out, 4, &count) == VOR_ERR_EMPTY, "within empty");
    CHECK(vor_within(NULL, q, 5, VOR_NO_HINT, out, 4, &count) == VOR_ERR_ARG, "within NULL d");
    CHECK(vor_within(&d, q, 5, VOR_NO_HINT, out, 4, NULL) == VOR_ERR_ARG, "within NULL count");
    CHECK(vor_within(&d, q, 5, VOR_NO_HINT, NULL, 4, &count) == VOR_ERR_ARG, "within NULL ids");
    CHECK(vor_triangles_count(NULL, &count) == VOR_ERR_ARG, "count NULL d");
    CHECK(vor_triangles_count(&d, NULL) == VOR_ERR_ARG, "count NULL count");
    CHECK(vor_triangles_export(NULL, out, out, 1, &count) == VOR_ERR_ARG, "export NULL d");
    CHECK(vor_triangles_export(&d, out, out, 1, NULL) == VOR_ERR_ARG, "export NULL count");
    CHECK(vor_triangles_export(&d, NULL, out, 1, &count) == VOR_ERR_ARG, "export NULL triangles");
    CHECK(ids[0] == 1u && ids[1] == 2u && ids[2] == 3u && count == 77u && out[0] == 5u,
          "nothing written");
    CHECK(vor_triangles_export(&d, NULL, NULL, 0, &count) == VOR_OK && count == 0u, "export empty");
    count = 77u;
    const vor_point_t tri[4] = {{0, 0}, {4, 0}, {0, 4}, {0, 0}};
    uint32_t dup[4];
    CHECK(vor_build(&d, tri, 4, NULL, dup) == VOR_OK, "build");
    const uint32_t bad_hints[4] = {3u, 4u, LOCATE_SITES, VOR_NO_HINT - 1u}; /* 3: a duplicate's id */
    for (unsigned k = 0; k < 4u; k++) {
        CHECK(vor_locate(&d, q, bad_hints[k], ids) == VOR_ERR_ARG, "locate hint %u", bad_hints[k]);
        CHECK(vor_within(&d, q, 5, bad_hints[k], out, 4, &count) == VOR_ERR_ARG, "within hint %u",
              bad_hints[k]);
    }
    CHECK(ids[0] == 1u && ids[1] == 2u && ids[2] == 3u && count == 77u && out[0] == 5u,
          "nothing written");
    CHECK(vor_within(&d, q, 0, 1u, NULL, 0, &count) == VOR_ERR_BUFFER && count == 1u,
          "within: the count needed with no buffer");
    CHECK(vor_within(&d, q, 0, 1u, out, 1, &count) == VOR_OK && count == 1u && out[0] == 0u &&
              out[1] == 5u,
          "within r2 = 0 at a site");
    CHECK(vor_triangles_export(&d, NULL, NULL, 0, &count) == VOR_ERR_BUFFER && count == 1u,
          "export: the size with no arrays");
    /* a one-site arena has no triangle slots at all: nothing read there */
    static uint8_t tiny[VOR_ARENA_BYTES(1)] __attribute__((aligned(8)));
    vor_t one;
    vor_point_t p = {3, -4};
    CHECK(vor_init(&one, tiny, sizeof tiny, 1) == VOR_OK && vor_insert(&one, p, NULL) == VOR_OK,
          "one-site arena");
    count = 77u;
    out[0] = 5u;
    CHECK(vor_triangles_count(&one, &count) == VOR_OK && count == 0u &&
              vor_triangles_export(&one, out, out, 1, &count) == VOR_OK && count == 0u && out[0] == 5u &&
              vor_locate(&one, p, 0, ids) == VOR_ERR_OUTSIDE &&
              vor_within(&one, q, 25, VOR_NO_HINT, out, 1, &count) == VOR_OK && count == 1u && out[0] == 0u &&
              vor_within(&one, q, 24, 0, out, 1, &count) == VOR_OK && count == 0u,
          "one-site arena: no triangle, within 5 of the origin");
}

void test_locate(void)
{
    TEST_CASE("uniform") uniform_set();
    TEST_CASE("grid") grid_set();
    TEST_CASE("circle") circle_set();
    TEST_CASE("collinear") collinear_set();
    TEST_CASE("small") small_sets();
    TEST_CASE("wide") wide_set();
    TEST_CASE("dynamic") dynamic_set();
    TEST_CASE("rule") documented_rule();
    TEST_CASE("errors") errors();
}
