/* SPDX-License-Identifier: MIT */
/*
 * test_cdt.c - constraints (vor_cdt.h): the constrained triangulation
 * against an independent check of what it must be.
 *
 * The check reads only the public output (vor_cdt_triangles_next,
 * vor_cdt_edges_next) and decides with exact predicates:
 *   - every triangle is counterclockwise, every edge is on one triangle
 *     each way at most, and there are as many triangles as the Delaunay
 *     triangulation of the same sites has (a triangulation of the same
 *     point set: 2n - h - 2);
 *   - every edge on two triangles that is not constrained is locally
 *     Delaunay: the far vertex is not strictly inside the circle (exact
 *     vor_incircle), which makes it the constrained Delaunay triangulation;
 *   - the constrained edges are exactly the pieces of the constraints the
 *     test made: each segment cut at every site on it, found here by exact
 *     collinearity, and each is an edge of a triangle;
 *   - vor_constrain refuses exactly the segments that cross a kept one at
 *     a point that is no site (exact orientations).
 */
#include "test.h"
#include "vor_cdt.h"

#define CDT_SITES 160u
#define CDT_CONSTRAINTS 96u
#define CDT_EDGES (3u * CDT_SITES)

static uint8_t arena[VOR_ARENA_BYTES(CDT_SITES)] __attribute__((aligned(8)));
static uint8_t memory[VOR_CDT_BYTES(CDT_SITES, CDT_EDGES, CDT_SITES)] __attribute__((aligned(8)));
static uint8_t saved_arena[sizeof arena];
static uint8_t saved_memory[sizeof memory];

/* The test's own record of the diagram: points by id, and the
 * constraints it made. */
typedef struct {
    vor_point_t at[CDT_SITES];
    bool live[CDT_SITES];
    uint32_t a[CDT_CONSTRAINTS];
    uint32_t b[CDT_CONSTRAINTS];
    uint32_t constraints;
} model_t;

static model_t model;

/* The sign of v. */
static int sign64(int64_t v)
{
    return (v > 0) - (v < 0);
}

/* Does site m lie strictly inside segment a-b? On the line, m is inside
 * when the steps a -> m and m -> b point as a -> b does on both axes. */
static bool strictly_inside(vor_point_t a, vor_point_t m, vor_point_t b)
{
    if (vor_orient2d(a, b, m) != 0) {
        return false;
    }
    int sx = sign64((int64_t)b.x - a.x);
    int sy = sign64((int64_t)b.y - a.y);
    return (sign64((int64_t)m.x - a.x) == sx) && (sign64((int64_t)b.x - m.x) == sx) &&
           (sign64((int64_t)m.y - a.y) == sy) && (sign64((int64_t)b.y - m.y) == sy) &&
           ((sx != 0) || (sy != 0));
}

/* |q - a| along a-b, for ordering collinear sites (the coordinate of
 * larger spread, so no product is needed). */
static int64_t along(vor_point_t a, vor_point_t b, vor_point_t q)
{
    int64_t dx = (int64_t)b.x - a.x;
    int64_t dy = (int64_t)b.y - a.y;
    int64_t ax = (dx < 0) ? -dx : dx;
    int64_t ay = (dy < 0) ? -dy : dy;
    return (ax >= ay) ? ((dx < 0) ? (a.x - (int64_t)q.x) : ((int64_t)q.x - a.x))
                      : ((dy < 0) ? (a.y - (int64_t)q.y) : ((int64_t)q.y - a.y));
}

/* Do segments a-b and c-d cross at a point that is not a site? Proper
 * crossings only: a site on the other segment splits it there instead. */
static bool crosses(const vor_t *d, vor_point_t a, vor_point_t b, vor_point_t c, vor_point_t e)
{
    int s1 = vor_orient2d(a, b, c);
    int s2 = vor_orient2d(a, b, e);
    int s3 = vor_orient2d(c, e, a);
    int s4 = vor_orient2d(c, e, b);
    if ((s1 * s2 >= 0) || (s3 * s4 >= 0)) {
        return false;
    }
    for (uint32_t i = 0; i < d->site_count; i++) {
        if (model.live[i] && strictly_inside(a, model.at[i], b) &&
            strictly_inside(c, model.at[i], e)) {
            return false; /* they meet at a site: both are split there */
        }
    }
    return true;
}

/* An undirected edge as a sortable key, and the third vertex of the
 * triangle it came from (top bits: its direction). */
typedef struct {
    uint64_t key;
    uint32_t apex;
    uint32_t forward;
} half_edge_t;

static half_edge_t halves[3u * 2u * CDT_SITES];
static uint32_t pieces_a[CDT_EDGES];
static uint32_t pieces_b[CDT_EDGES];
static uint64_t piece_keys[CDT_EDGES];
static uint64_t expected_keys[CDT_EDGES];

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
        uint32_t mid = lo + (hi - lo) / 2u;
        if (k[mid] < key) {
            lo = mid + 1u;
        } else {
            hi = mid;
        }
    }
    return (lo < n) && (k[lo] == key);
}

/* The pieces of every constraint the test made, as sorted keys. */
static uint32_t expected_pieces(const vor_t *d, uint64_t *keys)
{
    uint32_t n = 0;
    for (uint32_t c = 0; c < model.constraints; c++) {
        vor_point_t a = model.at[model.a[c]];
        vor_point_t b = model.at[model.b[c]];
        uint32_t from = model.a[c];
        /* the sites on the segment, nearest first, by repeated search */
        int64_t reached = 0;
        for (;;) {
            uint32_t next = model.b[c];
            int64_t best = along(a, b, b);
            for (uint32_t i = 0; i < d->site_count; i++) {
                if (model.live[i] && strictly_inside(a, model.at[i], b)) {
                    int64_t t = along(a, b, model.at[i]);
                    if ((t > reached) && (t < best)) {
                        best = t;
                        next = i;
                    }
                }
            }
            uint64_t key = edge_key(from, next);
            bool seen = false;
            for (uint32_t k = 0; k < n; k++) {
                seen = seen || (keys[k] == key);
            }
            if (!seen && (n < CDT_EDGES)) {
                keys[n++] = key;
            }
            if (next == model.b[c]) {
                break;
            }
            from = next;
            reached = best;
        }
    }
    sort_keys(keys, n);
    return n;
}

/* The checks of the file comment; returns the number of violations. */
static unsigned long check_cdt(const vor_t *d)
{
    unsigned long bad = 0;
    /* the triangles, as half-edges */
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    uint32_t triangles = 0;
    uint32_t nh = 0;
    (void)vor_cdt_triangles_begin(&it, d);
    while (vor_cdt_triangles_next(&it, ids) == 1) {
        triangles++;
        bad += (vor_orient2d(model.at[ids[0]], model.at[ids[1]], model.at[ids[2]]) > 0) ? 0u : 1u;
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
    bad += (triangles == delaunay) ? 0u : 1u;
    /* the constrained edges */
    uint32_t np = 0;
    vor_cdt_edge_iter_t e;
    uint32_t a;
    uint32_t b;
    (void)vor_cdt_edges_begin(&e, d);
    while ((vor_cdt_edges_next(&e, &a, &b) == 1) && (np < CDT_EDGES)) {
        pieces_a[np] = a;
        pieces_b[np] = b;
        np++;
    }
    uint64_t *got = piece_keys;
    for (uint32_t i = 0; i < np; i++) {
        got[i] = edge_key(pieces_a[i], pieces_b[i]);
    }
    sort_keys(got, np);
    sort_halves(halves, nh);
    /* each edge once each way at most; locally Delaunay unless constrained */
    for (uint32_t i = 0; i < nh;) {
        uint32_t j = i + 1u;
        while ((j < nh) && (halves[j].key == halves[i].key)) {
            j++;
        }
        if (j - i > 2u || ((j - i == 2u) && (halves[i].forward == halves[i + 1u].forward))) {
            bad++;
        } else if ((j - i == 2u) && !has_key(got, np, halves[i].key)) {
            uint32_t u = (uint32_t)(halves[i].key >> 32);
            uint32_t v = (uint32_t)halves[i].key;
            uint32_t w = halves[i].apex;
            uint32_t z = halves[i + 1u].apex;
            /* (u, v, w) counterclockwise when u -> v runs forward in w's triangle */
            vor_point_t p = model.at[halves[i].forward ? u : v];
            vor_point_t q = model.at[halves[i].forward ? v : u];
            bad += (vor_incircle(p, q, model.at[w], model.at[z]) > 0) ? 1u : 0u;
        } else {
            /* a hull edge, or a constrained one */
        }
        i = j;
    }
    /* the constrained edges are the constraints' pieces, each an edge */
    uint32_t ne = expected_pieces(d, expected_keys);
    bad += (ne == np) ? 0u : 1u;
    for (uint32_t i = 0; (i < ne) && (i < np); i++) {
        bad += (expected_keys[i] == got[i]) ? 0u : 1u;
    }
    for (uint32_t i = 0; (triangles > 0u) && (i < np); i++) {
        bool found = false;
        for (uint32_t k = 0; (k < nh) && !found; k++) {
            found = halves[k].key == got[i];
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

/* Random constraints between random sites: each accepted or refused as
 * the model says, and the whole checked after each. */
static void constrain_random(vor_t *d, test_rng_t *rng, uint32_t tries, unsigned long *bad,
                             unsigned long *refused)
{
    for (uint32_t k = 0; (k < tries) && (model.constraints < CDT_CONSTRAINTS); k++) {
        uint32_t a = test_rng_u32(rng) % d->site_count;
        uint32_t b = test_rng_u32(rng) % d->site_count;
        if (!model.live[a] || !model.live[b] || (a == b)) {
            continue;
        }
        bool cross = false;
        for (uint32_t c = 0; (c < model.constraints) && !cross; c++) {
            cross = crosses(d, model.at[a], model.at[b], model.at[model.a[c]],
                            model.at[model.b[c]]);
        }
        test_copy_bytes(saved_arena, arena, sizeof arena);
        test_copy_bytes(saved_memory, memory, sizeof memory);
        int err = vor_constrain(d, a, b);
        if (cross) {
            *bad += (err == VOR_ERR_CROSS) ? 0u : 1u;
            *bad += (test_same_bytes(saved_arena, arena, sizeof arena) &&
                     test_same_bytes(saved_memory, memory, sizeof memory))
                        ? 0u
                        : 1u;
            *refused += 1u;
            continue;
        }
        *bad += (err == VOR_OK) ? 0u : 1u;
        if (err == VOR_OK) {
            model.a[model.constraints] = a;
            model.b[model.constraints] = b;
            model.constraints++;
            *bad += check_cdt(d);
        }
    }
}

/* Random sites, random constraints, then sites inserted (some on the
 * constraints: they split them), removed and moved (the ends of
 * constrained edges refused, nothing changed), each step checked. */
static void check_random(unsigned kind, uint64_t seed)
{
    test_rng_t rng;
    test_rng_seed(&rng, seed);
    unsigned long bad = 0;
    unsigned long refused = 0;
    unsigned long kept_ends = 0;
    for (unsigned round = 0; round < 4u; round++) {
        vor_t d;
        model_clear();
        (void)vor_init(&d, arena, sizeof arena, CDT_SITES);
        uint32_t n = 30u + (test_rng_u32(&rng) % 70u);
        for (uint32_t i = 0; i < n; i++) {
            (void)insert_random(&d, &rng, kind);
            if (i == n / 2u) { /* attached to a diagram half built */
                bad += (vor_cdt_attach(&d, memory, sizeof memory, CDT_EDGES, CDT_SITES) == VOR_OK) ? 0u : 1u;
            }
        }
        bad += check_cdt(&d);
        constrain_random(&d, &rng, 60, &bad, &refused);
        for (uint32_t k = 0; k < 40u; k++) {
            uint32_t s = test_rng_u32(&rng) % d.site_count;
            unsigned op = test_rng_u32(&rng) % 3u;
            if (op == 0u) {
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
    test_printf("cdt random (%u): %lu constraints refused as crossing, %lu ends kept\n", kind,
                refused, kept_ends);
    CHECK(bad == 0, "cdt random (%u): %lu violations", kind, bad);
    CHECK(refused > 0u && kept_ends > 0u, "cdt random (%u): refused %lu, ends kept %lu", kind,
          refused, kept_ends);
}

/* The calls' documented errors, each leaving everything as it was. */
static void check_errors(void)
{
    vor_t d;
    model_clear();
    (void)vor_init(&d, arena, sizeof arena, CDT_SITES);
    CHECK(vor_constrain(&d, 0, 1) == VOR_ERR_ARG, "vor_constrain(&d, 0, 1) == VOR_ERR_ARG"); /* nothing attached */
    CHECK(vor_cdt_attach(NULL, memory, sizeof memory, 4, 4) == VOR_ERR_ARG, "vor_cdt_attach(NULL, memory, sizeof memory, 4, 4) == VOR_ERR_ARG");
    CHECK(vor_cdt_attach(&d, NULL, sizeof memory, 4, 4) == VOR_ERR_ARG, "vor_cdt_attach(&d, NULL, sizeof memory, 4, 4) == VOR_ERR_ARG");
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, 0, 4) == VOR_ERR_ARG, "vor_cdt_attach(&d, memory, sizeof memory, 0, 4) == VOR_ERR_ARG");
    CHECK(vor_cdt_attach(&d, memory + 1, sizeof memory - 1u, 4, 4) == VOR_ERR_ALIGN, "vor_cdt_attach(&d, memory + 1, sizeof memory - 1u, 4, 4) == VOR_ERR_ALIGN");
    CHECK(vor_cdt_attach(&d, memory, VOR_CDT_BYTES(CDT_SITES, 4, 4) - 1u, 4, 4) ==
            VOR_ERR_NOMEM, "vor_cdt_attach(&d, memory, VOR_CDT_BYTES(CDT_SITES, 4, 4) - 1u, 4, 4) ==             VOR_ERR_NOMEM");
    CHECK(d.cdt == NULL, "d.cdt == NULL");
    /* a square with its centre, and two sites across its diagonals */
    static const vor_point_t square[] = {{0, 0},   {100, 0}, {100, 100}, {0, 100},
                                         {50, 50}, {20, 70}, {90, 30}};
    for (unsigned i = 0; i < 7u; i++) {
        uint32_t id;
        (void)vor_insert(&d, square[i], &id);
        model.at[id] = square[i];
        model.live[id] = true;
    }
    /* a cut of no triangle: only the edges there are can be constrained */
    CHECK(vor_cdt_attach(&d, memory, VOR_CDT_BYTES(CDT_SITES, 40, 0), 40, 0) == VOR_OK, "attach with no cut");
    CHECK(vor_constrain(&d, 0, 99) == VOR_ERR_ARG, "vor_constrain(&d, 0, 99) == VOR_ERR_ARG");
    CHECK(vor_constrain(NULL, 0, 1) == VOR_ERR_ARG, "vor_constrain(NULL, 0, 1) == VOR_ERR_ARG");
    CHECK(vor_constrain(&d, 2, 2) == VOR_OK, "vor_constrain(&d, 2, 2) == VOR_OK");
    test_copy_bytes(saved_memory, memory, sizeof memory);
    unsigned too_long = 0; /* every segment that is no edge crosses a triangle */
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
    CHECK(vor_cdt_attach(&d, memory, sizeof memory, 4, CDT_SITES) == VOR_OK, "vor_cdt_attach(&d, memory, sizeof memory, 4, CDT_SITES) == VOR_OK");
    CHECK(vor_constrain(&d, 0, 2) == VOR_OK, "vor_constrain(&d, 0, 2) == VOR_OK"); /* 0-4, 4-2 */
    CHECK(vor_constrain(&d, 1, 3) == VOR_OK, "vor_constrain(&d, 1, 3) == VOR_OK"); /* meets it at the site 4 */
    model.a[0] = 0;
    model.b[0] = 2;
    model.a[1] = 1;
    model.b[1] = 3;
    model.constraints = 2;
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation");
    test_copy_bytes(saved_memory, memory, sizeof memory);
    test_copy_bytes(saved_arena, arena, sizeof arena);
    CHECK(vor_constrain(&d, 5, 6) == VOR_ERR_CROSS, "vor_constrain(&d, 5, 6) == VOR_ERR_CROSS");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory), "crossing changed the memory"); /* off any site */
    CHECK(vor_constrain(&d, 5, 0) == VOR_ERR_NOMEM, "vor_constrain(&d, 5, 0) == VOR_ERR_NOMEM");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory), "a full table changed the memory"); /* a fifth edge */
    CHECK(vor_remove(&d, 4) == VOR_ERR_CONSTRAINED, "vor_remove(&d, 4) == VOR_ERR_CONSTRAINED");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory), "a refused removal changed the memory");
    vor_point_t away = {30, 60};
    CHECK(vor_move(&d, 0, away, NULL) == VOR_ERR_CONSTRAINED, "vor_move(&d, 0, away, NULL) == VOR_ERR_CONSTRAINED");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory) &&
            test_same_bytes(saved_arena, arena, sizeof arena), "test_same_bytes(saved_memory, memory, sizeof memory) &&             test_same_bytes(saved_arena, arena, sizeof arena)");
    /* a site landing on a constrained edge when the table is full */
    uint32_t id;
    vor_point_t on_edge = {25, 25};
    CHECK(vor_insert(&d, on_edge, &id) == VOR_ERR_NOMEM, "vor_insert(&d, on_edge, &id) == VOR_ERR_NOMEM");
    CHECK(test_same_bytes(saved_memory, memory, sizeof memory) &&
            test_same_bytes(saved_arena, arena, sizeof arena), "test_same_bytes(saved_memory, memory, sizeof memory) &&             test_same_bytes(saved_arena, arena, sizeof arena)");
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation");
    /* a build starts the constrained triangulation again, unconstrained */
    CHECK(vor_build(&d, square, 7, NULL, NULL) == VOR_OK, "vor_build(&d, square, 7, NULL, NULL) == VOR_OK");
    model.constraints = 0;
    CHECK(!ends_constraint(&d, 4), "constraints after a build");
    CHECK(check_cdt(&d) == 0u, "the constrained triangulation");
}

/* Constraints along the lines of a grid, through its sites, overlapping
 * and repeated: every edge of a line becomes a constrained edge once. */
static void check_grid_lines(void)
{
    vor_t d;
    unsigned long bad = 0;
    model_clear();
    (void)vor_init(&d, arena, sizeof arena, CDT_SITES);
    for (int32_t y = 0; y < 8; y++) {
        for (int32_t x = 0; x < 8; x++) {
            vor_point_t p = {x * 3, y * 3};
            uint32_t id;
            (void)vor_insert(&d, p, &id);
            model.at[id] = p;
            model.live[id] = true;
        }
    }
    bad += (vor_cdt_attach(&d, memory, sizeof memory, CDT_EDGES, CDT_SITES) == VOR_OK) ? 0u : 1u;
    /* rows, columns, diagonals, and overlapping pieces of them */
    static const uint32_t lines[][2] = {{0, 7}, {8, 15}, {0, 56}, {7, 63}, {0, 63}, {2, 5},
                                        {1, 6}, {56, 63}, {24, 31}, {27, 30}, {3, 59}, {0, 63}};
    for (unsigned k = 0; k < sizeof lines / sizeof lines[0]; k++) {
        int err = vor_constrain(&d, lines[k][0], lines[k][1]);
        bad += (err == VOR_OK) ? 0u : 1u;
        model.a[model.constraints] = lines[k][0];
        model.b[model.constraints] = lines[k][1];
        model.constraints++;
        bad += check_cdt(&d);
    }
    CHECK(bad == 0, "cdt grid lines: %lu wrong", bad);
}

void test_cdt(void)
{
    TEST_CASE("errors") check_errors();
    TEST_CASE("grid_lines") check_grid_lines();
    TEST_CASE("random/grid") check_random(0, 11);
    TEST_CASE("random/box") check_random(1, 12);
    TEST_CASE("random/full_range") check_random(2, 13);
}
