/* SPDX-License-Identifier: MIT */
/*
 * test_dynamic.c - removing and moving sites.
 *
 * Independent references: a model of the live sites kept here (positions,
 * which ids are live, the free ids in the documented reuse order), from
 * which every expected id and error follows; vor_validate's invariants;
 * and the uniqueness of the perturbed Delaunay triangulation: after every
 * operation the triangles must be those of a fresh vor_build of the live
 * sites in id order (the perturbation depends only on that order).
 * The rehoming tests lay the triangles out in their slots another legal
 * way (mesh.h), so that removal must search for home triangles. The
 * removal's predicate counts (vor_stats) against a model of the ear
 * order docs/design/dynamic.md states.
 */
#include "dynamic.h" /* white-box: vor__rehome and the slot layout, for the rehoming tests */
#include "test.h"
#include "vor.h"

#define DYN_SITES 40u

static uint8_t arena[VOR_ARENA_BYTES(DYN_SITES)] __attribute__((aligned(8)));
static uint8_t fresh_arena[VOR_ARENA_BYTES(DYN_SITES)] __attribute__((aligned(8)));
static uint8_t saved_arena[sizeof arena];

/* The model: what the diagram must hold. */
typedef struct {
    vor_point_t at[DYN_SITES];
    bool live[DYN_SITES];
    uint32_t handed_out;        /* ids 0 .. handed_out - 1 were given */
    uint32_t freed[DYN_SITES];  /* free ids, the most recent last */
    uint32_t free_count;
} model_t;

static uint32_t live_count(const model_t *m)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < m->handed_out; i++) {
        n += m->live[i] ? 1u : 0u;
    }
    return n;
}

static uint32_t site_at(const model_t *m, int32_t x, int32_t y)
{
    for (uint32_t i = 0; i < m->handed_out; i++) {
        if (m->live[i] && m->at[i].x == x && m->at[i].y == y) {
            return i;
        }
    }
    return VOR_NO_HINT;
}

/* Every operation's aftermath: valid, and the fresh build's triangles. */
static bool check_state(const vor_t *d, const model_t *m, const char *what, uint32_t step)
{
    vor_violation_t violation = {VOR_CHECK_COUNTS, 0, 0};
    int err = vor_validate(d, &violation);
    bool ok = CHECK(err == VOR_OK, "%s step %u: vor_validate %d (check %d, triangle %u, site %u)",
                    what, step, err, (int)violation.check, violation.triangle, violation.site);
    ok = CHECK(d->vertex_count == live_count(m), "%s step %u: %u sites, expected %u", what, step,
               d->vertex_count, live_count(m)) && ok;
    static vor_point_t points[DYN_SITES];
    static uint32_t id_of[DYN_SITES];
    uint32_t n = 0;
    for (uint32_t i = 0; i < m->handed_out; i++) {
        if (m->live[i]) {
            id_of[n] = i;
            points[n++] = m->at[i];
        }
    }
    vor_t fresh;
    vor_init(&fresh, fresh_arena, sizeof fresh_arena, DYN_SITES);
    CHECK(vor_build(&fresh, points, n, NULL, NULL) == VOR_OK, "%s step %u: fresh build", what,
          step);
    test_fingerprint_t got = test_fingerprint_of(d, NULL), want = test_fingerprint_of(&fresh, id_of);
    ok = CHECK(got.count == want.count && got.sum1 == want.sum1 && got.sum2 == want.sum2,
               "%s step %u: %u triangles, the fresh build has %u (or others)", what, step,
               got.count, want.count) && ok;
    return ok;
}

/* ------------------------------------------------------------------ */
/* Byte-for-byte unchanged after a failing call                        */

static vor_t saved;

static void save(const vor_t *d)
{
    const uint8_t *from = (const uint8_t *)d;
    uint8_t *to = (uint8_t *)&saved;
    for (size_t i = 0; i < sizeof saved; i++) {
        to[i] = from[i];
    }
    for (size_t i = 0; i < sizeof arena; i++) {
        saved_arena[i] = arena[i];
    }
}

static bool unchanged(const vor_t *d)
{
    const uint8_t *now = (const uint8_t *)d, *then = (const uint8_t *)&saved;
    for (size_t i = 0; i < sizeof saved; i++) {
        if (now[i] != then[i]) {
            return false;
        }
    }
    for (size_t i = 0; i < sizeof arena; i++) {
        if (arena[i] != saved_arena[i]) {
            return false;
        }
    }
    return true;
}

/* ------------------------------------------------------------------ */
/* Operations against the model                                        */

static void do_insert(vor_t *d, model_t *m, vor_point_t p, const char *what, uint32_t step)
{
    uint32_t twin = site_at(m, p.x, p.y), id = VOR_NO_HINT;
    bool full = m->free_count == 0u && m->handed_out == DYN_SITES;
    if (twin != VOR_NO_HINT || full) {
        save(d);
    }
    int err = vor_insert(d, p, &id);
    if (twin != VOR_NO_HINT) {
        CHECK(err == VOR_ERR_DUPLICATE && id == twin,
              "%s step %u: insert onto site %u gave %d, id %u", what, step, twin, err, id);
        CHECK(unchanged(d), "%s step %u: a duplicate insert changed the diagram", what, step);
        return;
    }
    if (full) {
        CHECK(err == VOR_ERR_FULL, "%s step %u: insert into a full diagram gave %d", what, step,
              err);
        CHECK(unchanged(d), "%s step %u: a full insert changed the diagram", what, step);
        return;
    }
    /* the most recently freed id first, then the next new one */
    uint32_t expected = (m->free_count > 0u) ? m->freed[--m->free_count] : m->handed_out++;
    CHECK(err == VOR_OK && id == expected, "%s step %u: insert gave %d, id %u, expected %u",
          what, step, err, id, expected);
    m->at[expected] = p;
    m->live[expected] = true;
}

static void do_remove(vor_t *d, model_t *m, uint32_t id, const char *what, uint32_t step)
{
    bool live = id < m->handed_out && m->live[id];
    if (!live) {
        save(d);
    }
    int err = vor_remove(d, id);
    if (!live) {
        CHECK(err == VOR_ERR_ARG, "%s step %u: removing non-site %u gave %d", what, step, id,
              err);
        CHECK(unchanged(d), "%s step %u: a failed remove changed the diagram", what, step);
        return;
    }
    CHECK(err == VOR_OK, "%s step %u: remove %u gave %d", what, step, id, err);
    m->live[id] = false;
    m->freed[m->free_count++] = id;
}

static void do_move(vor_t *d, model_t *m, uint32_t id, vor_point_t p, const char *what,
                    uint32_t step)
{
    bool live = id < m->handed_out && m->live[id];
    uint32_t twin = site_at(m, p.x, p.y), existing = VOR_NO_HINT;
    bool fails = !live || (twin != VOR_NO_HINT && twin != id);
    bool stays = live && twin == id;
    if (fails || stays) {
        save(d);
    }
    int err = vor_move(d, id, p, &existing);
    if (!live) {
        CHECK(err == VOR_ERR_ARG, "%s step %u: moving non-site %u gave %d", what, step, id, err);
    } else if (twin != VOR_NO_HINT && twin != id) {
        CHECK(err == VOR_ERR_DUPLICATE && existing == twin,
              "%s step %u: move of %u onto site %u gave %d, %u", what, step, id, twin, err,
              existing);
    } else {
        CHECK(err == VOR_OK, "%s step %u: move %u gave %d", what, step, id, err);
        m->at[id] = p;
    }
    if (fails || stays) {
        CHECK(unchanged(d), "%s step %u: a move that %s changed the diagram", what, step,
              fails ? "failed" : "stayed");
    }
}

/* ------------------------------------------------------------------ */
/* Random sequences                                                    */

enum shape { UNIFORM, GRID, LINE, CIRCLE, HEAPED, SHAPES };

/* Points of x^2 + y^2 = 25^2: twelve cocircular sites (and the centre
 * makes the set degenerate in another way). */
static const int8_t circle[13][2] = {{25, 0}, {0, 25},  {-25, 0}, {0, -25}, {7, 24},
                                     {-7, 24}, {24, -7}, {-24, -7}, {15, 20}, {-20, 15},
                                     {20, -15}, {-15, -20}, {0, 0}};

static vor_point_t random_point(test_rng_t *rng, enum shape shape)
{
    vor_point_t p = {0, 0};
    int32_t t;
    switch (shape) {
    case UNIFORM:
        p.x = test_rng_range(rng, -1000, 1000);
        p.y = test_rng_range(rng, -1000, 1000);
        break;
    case GRID:
        p.x = test_rng_range(rng, 0, 6) * 10;
        p.y = test_rng_range(rng, 0, 6) * 10;
        break;
    case LINE:
        t = test_rng_range(rng, -30, 30);
        p.x = 3 * t + 1;
        p.y = -2 * t;
        break;
    case CIRCLE:
        t = test_rng_range(rng, 0, 12);
        p.x = circle[t][0];
        p.y = circle[t][1];
        break;
    default: /* heaped: most points fall on a few */
        p.x = test_rng_range(rng, 0, 2);
        p.y = test_rng_range(rng, 0, 2);
        break;
    }
    return p;
}

static const char *const shape_names[SHAPES] = {"uniform", "grid", "line", "circle", "heaped"};

/* An empty diagram over the shared arena, and its model. */
static void begin_model(vor_t *d, model_t *m)
{
    vor_init(d, arena, sizeof arena, DYN_SITES);
    m->handed_out = 0;
    m->free_count = 0;
}

/* `count` insertions of uniform random points, each checked. */
static void insert_uniform(vor_t *d, model_t *m, test_rng_t *rng, uint32_t count, const char *what)
{
    for (uint32_t i = 0; i < count; i++) {
        do_insert(d, m, random_point(rng, UNIFORM), what, i);
    }
}

static uint32_t random_id(test_rng_t *rng, const model_t *m)
{
    /* mostly live sites, sometimes a free or unused id */
    uint32_t id = (uint32_t)test_rng_range(rng, 0, (int32_t)DYN_SITES);
    for (uint32_t tries = 0; tries < 8u && (id >= m->handed_out || !m->live[id]); tries++) {
        id = (uint32_t)test_rng_range(rng, 0, (int32_t)DYN_SITES);
    }
    return id;
}

/* The live site nearest (x, y), the smaller id on a tie (vor_nearest's
 * rule), by looking at every site. */
static uint32_t brute_nearest(const model_t *m, int32_t x, int32_t y)
{
    uint32_t best = VOR_NO_HINT;
    int64_t best_distance = 0;
    for (uint32_t i = 0; i < m->handed_out; i++) {
        int64_t dx = (int64_t)m->at[i].x - x, dy = (int64_t)m->at[i].y - y;
        int64_t distance = dx * dx + dy * dy;
        if (m->live[i] && (best == VOR_NO_HINT || distance < best_distance)) {
            best = i;
            best_distance = distance;
        }
    }
    return best;
}

/* Inserts, removals and moves that keep between none and four sites, so
 * that the diagram passes often through its smallest states (no site,
 * one, two, three: no triangles, an edge, one triangle), and moves land
 * on other sites too; after each step the state of check_state, each
 * site's neighbours (live other sites, none for a lone site) and
 * vor_nearest from a few points, against brute force. */
static void few_sites(uint64_t seed)
{
    static vor_t d;
    static model_t m;
    test_rng_t rng;
    test_rng_seed(&rng, seed);
    begin_model(&d, &m);
    uint32_t failures_before = (uint32_t)test_failures();
    for (uint32_t step = 0; step < 400u; step++) {
        uint32_t live = live_count(&m), r = test_rng_u32(&rng) % 8u, id = random_id(&rng, &m);
        uint32_t to = random_id(&rng, &m);
        if (live == 0u || (r < 3u && live < 4u)) {
            do_insert(&d, &m, random_point(&rng, UNIFORM), "few", step);
        } else if (r < 5u) {
            do_remove(&d, &m, id, "few", step);
        } else if (r < 6u) {
            do_move(&d, &m, id, random_point(&rng, UNIFORM), "few", step);
        } else if (r < 7u && id < m.handed_out) { /* a small step */
            vor_point_t p = m.at[id];
            p.x += test_rng_range(&rng, -300, 300);
            p.y += test_rng_range(&rng, -300, 300);
            do_move(&d, &m, id, p, "few", step);
        } else if (id < m.handed_out && to < m.handed_out) { /* onto another site */
            do_move(&d, &m, id, m.at[to], "few", step);
        }
        bool ok = check_state(&d, &m, "few", step);
        for (uint32_t i = 0; i < m.handed_out; i++) { /* neighbours: live others, none of one */
            vor_neighbour_iter_t it;
            uint32_t n = VOR_NO_HINT, count = 0;
            bool good = vor_neighbours_begin(&it, &d, i) == (m.live[i] ? VOR_OK : VOR_ERR_ARG);
            while (m.live[i] && vor_neighbours_next(&it, &n) == 1 && count <= DYN_SITES) {
                good = good && n < m.handed_out && m.live[n] && n != i;
                count++;
            }
            ok = CHECK(good && count < live_count(&m) + (m.live[i] ? 0u : 1u),
                       "few step %u: the neighbours of %u (%u of them)", step, i, count) &&
                 ok;
        }
        for (uint32_t k = 0; k < 3u && live_count(&m) > 0u; k++) {
            int32_t x = test_rng_range(&rng, -1200, 1200), y = test_rng_range(&rng, -1200, 1200);
            uint32_t got = VOR_NO_HINT;
            ok = CHECK(vor_nearest(&d, (vor_point_t){x, y}, VOR_NO_HINT, &got) == VOR_OK &&
                           got == brute_nearest(&m, x, y),
                       "few step %u: nearest to (%d, %d) %u, brute force %u", step, (int)x, (int)y,
                       got, brute_nearest(&m, x, y)) && ok;
        }
        if (!ok || test_failures() > failures_before + 4u) {
            return;
        }
    }
}

static void random_sequence(enum shape shape, uint64_t seed, uint32_t steps)
{
    static vor_t d;
    static model_t m;
    test_rng_t rng;
    test_rng_seed(&rng, seed);
    begin_model(&d, &m);
    const char *what = shape_names[shape];
    uint32_t failures_before = (uint32_t)test_failures();
    for (uint32_t step = 0; step < steps; step++) {
        uint32_t r = test_rng_u32(&rng) % 10u, id = random_id(&rng, &m);
        if (r < 4u || live_count(&m) < 3u) {
            do_insert(&d, &m, random_point(&rng, shape), what, step);
        } else if (r < 6u) {
            do_remove(&d, &m, id, what, step);
        } else if (r < 8u || shape != UNIFORM) {
            do_move(&d, &m, id, random_point(&rng, shape), what, step);
        } else if (r < 9u && id < m.handed_out) {
            /* a robot's small step: usually no triangle changes */
            vor_point_t p = m.at[id];
            p.x += test_rng_range(&rng, -4, 4);
            p.y += test_rng_range(&rng, -4, 4);
            do_move(&d, &m, id, p, what, step);
        } else if (id < m.handed_out) {
            /* to the hull, and back on a later step */
            vor_point_t p = m.at[id];
            p.x = (p.x > 0) ? p.x - 5000 : p.x + 5000;
            do_move(&d, &m, id, p, what, step);
        }
        if (!check_state(&d, &m, what, step) || test_failures() > failures_before + 4u) {
            return; /* the first failure tells; the rest would repeat it */
        }
    }
}

/* ------------------------------------------------------------------ */
/* Edge cases                                                          */

static void down_to_nothing(void)
{
    static vor_t d;
    static model_t m;
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    begin_model(&d, &m);
    for (uint32_t i = 0; i < 12u; i++) {
        do_insert(&d, &m, random_point(&rng, UNIFORM), "drain", i);
    }
    /* every site removed, so the counts pass through 3, 2, 1 and 0 */
    for (uint32_t i = 0; i < 12u; i++) {
        do_remove(&d, &m, (i * 5u) % 12u, "drain", 100u + i);
        check_state(&d, &m, "drain", 100u + i);
    }
    uint32_t nearest;
    CHECK(vor_nearest(&d, (vor_point_t){0, 0}, VOR_NO_HINT, &nearest) == VOR_ERR_EMPTY, "empty after removals");
    for (uint32_t i = 0; i < 14u; i++) { /* ids come back, then new ones */
        do_insert(&d, &m, random_point(&rng, UNIFORM), "refill", 200u + i);
        check_state(&d, &m, "refill", 200u + i);
    }
    do_remove(&d, &m, DYN_SITES + 3u, "refill", 300);
    CHECK(vor_remove(NULL, 0) == VOR_ERR_ARG, "vor_remove(NULL)");
    CHECK(vor_move(NULL, 0, (vor_point_t){0, 0}, NULL) == VOR_ERR_ARG, "vor_move(NULL)");

    /* one site of capacity one: its only id comes back */
    static uint8_t one[VOR_ARENA_BYTES(1)] __attribute__((aligned(8)));
    vor_t solo;
    uint32_t id = 9;
    vor_init(&solo, one, sizeof one, 1);
    CHECK(vor_insert(&solo, (vor_point_t){4, 5}, &id) == VOR_OK && id == 0, "solo insert");
    CHECK(vor_move(&solo, 0, (vor_point_t){6, 7}, NULL) == VOR_OK && solo.sites[0].x == 6, "solo move");
    CHECK(vor_remove(&solo, 0) == VOR_OK && solo.vertex_count == 0, "solo remove");
    CHECK(vor_remove(&solo, 0) == VOR_ERR_ARG, "solo remove twice");
    CHECK(vor_insert(&solo, (vor_point_t){1, 1}, &id) == VOR_OK && id == 0, "solo id reused");
    CHECK(vor_insert(&solo, (vor_point_t){2, 2}, &id) == VOR_ERR_FULL, "solo full");
}

/* ------------------------------------------------------------------ */
/* Large stars and home slots                                          */

/* ------------------------------------------------------------------ */
/* The cost of a removal                                               */

/* Every order of ears gives the same triangulation, so only the number
 * of predicates a removal evaluates tells one order from another. The
 * model here follows the order docs/design/dynamic.md states: p's
 * neighbours counterclockwise by exact angle (the vertex at infinity in a
 * hull site's gap), from the star triangle in p's home slot (the one
 * white-box read, mesh.h); above 16 neighbours ears by walking, each
 * against the others counterclockwise, each pass from the last cut's new
 * star triangle; then the arrays from there: ears from `from`, the other
 * neighbours at offsets 3, deg - 1, 4, deg - 2, .., a quadrilateral with
 * one ear test, and after a cut the scan resumes at the ear before the
 * new edge. Its signs are vor_orient2d_sos and vor_incircle_sos: the
 * same perturbation over the same ids. */
#define RING_MAX (DYN_SITES + 1u)
#define RING_INFINITE ((uint32_t)VOR__INFINITE)
#define RING_ARRAYS 16u /* STAR_MAX */

typedef struct {
    const vor_point_t *at;
    uint32_t nb[RING_MAX];
    uint32_t deg;
    uint32_t orient;
    uint32_t incircle;
} ring_t;

/* p's star as removal reads it: the mesh's triangles around p (home
 * slots of live sites, then the packed ones, mesh.h), chained
 * counterclockwise from the one in p's home slot. */
static bool ring_load(ring_t *r, const vor_t *d, const model_t *m, uint32_t p)
{
    uint32_t next[RING_MAX], prev[RING_MAX], count = 0;
    uint32_t slots = d->max_sites + d->vertex_count - 2u;
    r->at = m->at;
    r->orient = r->incircle = 0;
    for (uint32_t s = 0; s < slots; s++) {
        const vor__tri_t *t = &d->triangles[s];
        unsigned i = vor__vertex_index(t, (vor_index_t)p);
        if ((s >= d->max_sites || (s < m->handed_out && m->live[s])) && i < 3u &&
            count < RING_MAX) {
            next[count] = vor__vertex(t, vor__next(i));
            prev[count] = vor__vertex(t, vor__prev(i));
            count++;
        }
    }
    const vor__tri_t *home = &d->triangles[p];
    uint32_t at = vor__vertex(home, vor__next(vor__vertex_index(home, (vor_index_t)p)));
    for (r->deg = 0; r->deg < count; r->deg++) {
        uint32_t j = 0;
        while (j < count && next[j] != at) {
            j++;
        }
        if (!CHECK(j < count, "cost: the star of %u is broken at %u", p, at)) {
            return false;
        }
        r->nb[r->deg] = at;
        at = prev[j];
    }
    return CHECK(count >= 3u && at == r->nb[0], "cost: the star of %u (%u triangles) is open", p,
                 count);
}

/* Neighbour `first` to index 0, the order kept. */
static void ring_start_at(ring_t *r, uint32_t first)
{
    for (uint32_t turns = 0; turns < r->deg && r->nb[0] != first; turns++) {
        uint32_t head = r->nb[0];
        for (uint32_t k = 0; k + 1u < r->deg; k++) {
            r->nb[k] = r->nb[k + 1u];
        }
        r->nb[r->deg - 1u] = head;
    }
}

/* Is y in the perturbed circle of (a, b, c), or beyond its hull edge? */
static bool ring_conflicts(ring_t *r, uint32_t a, uint32_t b, uint32_t c, uint32_t y)
{
    const uint32_t hull[3][2] = {{b, c}, {c, a}, {a, b}};
    unsigned at = (a == RING_INFINITE) ? 0u : (b == RING_INFINITE) ? 1u : 2u;
    if (a != RING_INFINITE && b != RING_INFINITE && c != RING_INFINITE) {
        r->incircle++;
        return vor_incircle_sos(r->at, a, b, c, y) > 0;
    }
    r->orient++;
    return vor_orient2d_sos(r->at, hull[at][0], hull[at][1], y) > 0;
}

/* Is ear i a triangle of the result? The others in the arrays' order
 * (`alternate`) or counterclockwise (the walk). */
static bool ring_ear(ring_t *r, uint32_t i, bool alternate)
{
    uint32_t deg = r->deg;
    uint32_t a = r->nb[i], b = r->nb[(i + 1u) % deg], c = r->nb[(i + 2u) % deg];
    if (a != RING_INFINITE && b != RING_INFINITE && c != RING_INFINITE) {
        r->orient++;
        if (vor_orient2d_sos(r->at, a, b, c) < 0) {
            return false;
        }
    }
    for (uint32_t t = 0; t + 3u < deg; t++) {
        uint32_t offset = !alternate ? 3u + t : (t % 2u == 0u) ? 3u + t / 2u : deg - 1u - t / 2u;
        uint32_t y = r->nb[(i + offset) % deg];
        if (y != RING_INFINITE && ring_conflicts(r, a, b, c, y)) {
            return false;
        }
    }
    return true;
}

/* Cuts ear i (its middle neighbour leaves); returns the index of its
 * first neighbour after the cut. */
static uint32_t ring_cut(ring_t *r, uint32_t i)
{
    uint32_t j = (i + 1u) % r->deg;
    for (uint32_t k = j; k + 1u < r->deg; k++) {
        r->nb[k] = r->nb[k + 1u];
    }
    r->deg--;
    return (j == 0u) ? i - 1u : i;
}

/* The predicates the removal of the star in r evaluates, into r. */
static bool ring_remove(ring_t *r)
{
    uint32_t start = 0;
    while (r->deg > RING_ARRAYS) {
        uint32_t k = 0;
        while (k < r->deg && !ring_ear(r, (start + k) % r->deg, false)) {
            k++;
        }
        if (!CHECK(k < r->deg, "cost: a star of %u without an ear", r->deg)) {
            return false;
        }
        start = ring_cut(r, (start + k) % r->deg);
    }
    ring_start_at(r, r->nb[start]);
    uint32_t from = 0;
    while (r->deg > 3u) {
        uint32_t i = 0;
        if (r->deg == 4u) {
            i = ring_ear(r, 0, true) ? 0u : 1u;
        } else {
            uint32_t k = 0;
            while (k < r->deg && !ring_ear(r, (from + k) % r->deg, true)) {
                k++;
            }
            if (!CHECK(k < r->deg, "cost: a star of %u without an ear", r->deg)) {
                return false;
            }
            i = (from + k) % r->deg;
        }
        uint32_t at = ring_cut(r, i);
        from = (at == 0u) ? r->deg - 1u : at - 1u;
    }
    return true;
}

static uint32_t tier_sum(const uint32_t count[VOR_TIERS])
{
    return count[VOR_TIER_NARROW] + count[VOR_TIER_MID] + count[VOR_TIER_WIDE];
}

/* do_remove, with the predicates counted (vor_stats) against the model's. */
static bool remove_as_modelled(vor_t *d, model_t *m, uint32_t p, const char *what, uint32_t step)
{
    ring_t r;
    vor_stats_t before, after;
    bool mesh = d->vertex_count >= 4u;
    if (mesh && (!ring_load(&r, d, m, p) || !ring_remove(&r))) {
        return false;
    }
    CHECK(vor_stats(d, &before) == VOR_OK, "cost: no counters");
    do_remove(d, m, p, what, step);
    CHECK(vor_stats(d, &after) == VOR_OK, "cost: no counters");
    uint32_t orient = tier_sum(after.orient2d) - tier_sum(before.orient2d);
    uint32_t incircle = tier_sum(after.incircle) - tier_sum(before.incircle);
    uint32_t closer = tier_sum(after.closer) - tier_sum(before.closer);
    return CHECK(orient == (mesh ? r.orient : 0u) && incircle == (mesh ? r.incircle : 0u) &&
                     closer == 0u,
                 "%s step %u: removing %u took %u orientation, %u incircle and %u closer tests; "
                 "the model %u, %u and 0",
                 what, step, p, orient, incircle, closer, mesh ? r.orient : 0u,
                 mesh ? r.incircle : 0u);
}

/* Sets of each shape emptied in a random order, every removal's
 * predicates counted against the model (the rings above 16 neighbours
 * are big_star's). */
static void removal_cost(void)
{
    static vor_t d;
    static model_t m;
    static const enum shape shapes[3] = {UNIFORM, GRID, CIRCLE};
    for (uint32_t round = 0; round < 60u; round++) {
        test_rng_t rng;
        test_rng_seed(&rng, 7000u + round);
        begin_model(&d, &m);
        for (uint32_t i = 0; i < DYN_SITES; i++) {
            do_insert(&d, &m, random_point(&rng, shapes[round % 3u]), "cost", i);
        }
        for (uint32_t step = 0; live_count(&m) > 0u; step++) {
            uint32_t id = (uint32_t)test_rng_range(&rng, 0, (int32_t)m.handed_out - 1);
            while (!m.live[id]) {
                id = (id + 1u) % m.handed_out;
            }
            if (!remove_as_modelled(&d, &m, id, "cost", step)) {
                return;
            }
        }
        check_state(&d, &m, "cost", round);
    }
}

/* Diagrams filled to capacity in arenas of exactly VOR_ARENA_BYTES(n),
 * n = 4 and 5 (one or two buckets after the triangles), each site removed
 * and put back in turn against a fresh build: the last packed triangle,
 * which a removal moves, is then the arena's last slot, and a read past
 * it leaves the arena (the sanitizer suites see it). */
static void full_arenas(void)
{
    static uint8_t four[VOR_ARENA_BYTES(4)] __attribute__((aligned(8)));
    static uint8_t five[VOR_ARENA_BYTES(5)] __attribute__((aligned(8)));
    static vor_t d;
    static model_t m;
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    for (uint32_t round = 0; round < 40u; round++) {
        uint32_t n = 4u + round % 2u;
        vor_init(&d, (n == 4u) ? four : five, (n == 4u) ? sizeof four : sizeof five, n);
        m.handed_out = 0;
        m.free_count = 0;
        for (uint32_t i = 0; i < n; i++) {
            vor_point_t p;
            do {
                p = random_point(&rng, UNIFORM);
            } while (site_at(&m, p.x, p.y) != VOR_NO_HINT);
            do_insert(&d, &m, p, "full", i);
        }
        for (uint32_t i = 0; i < n; i++) {
            vor_point_t p = m.at[i];
            remove_as_modelled(&d, &m, i, "full", i);
            check_state(&d, &m, "full", i);
            do_insert(&d, &m, p, "full", i);
            check_state(&d, &m, "full", i);
        }
    }
}

/* Two or three sites moving across the whole bucket grid, with
 * insertions and removals between: the grid's runs must follow every
 * move (each site's entries one run through its own bucket), or a later
 * removal leaves entries naming the removed site, which vor_validate
 * rejects. */
static void grid_at_two_sites(void)
{
    static vor_t d;
    static model_t m;
    test_rng_t rng;
    test_rng_seed(&rng, 88);
    for (uint32_t round = 0; round < 300u; round++) {
        begin_model(&d, &m);
        do_insert(&d, &m, (vor_point_t){-1000, -1000}, "grid", round);
        do_insert(&d, &m, (vor_point_t){1000, 1000}, "grid", round);
        for (uint32_t step = 0; step < 12u; step++) {
            uint32_t live = live_count(&m), r = test_rng_u32(&rng) % 4u;
            uint32_t id = (uint32_t)test_rng_range(&rng, 0, (int32_t)m.handed_out - 1);
            while (!m.live[id]) {
                id = (id + 1u) % m.handed_out;
            }
            vor_point_t p = {test_rng_range(&rng, -1000, 1000), test_rng_range(&rng, -1000, 1000)};
            if (r < 2u || live == 1u) {
                do_move(&d, &m, id, p, "grid", step);
            } else if (r == 2u && live < 3u) {
                do_insert(&d, &m, p, "grid", step);
            } else {
                do_remove(&d, &m, id, "grid", step);
            }
            if (!check_state(&d, &m, "grid", round * 100u + step)) {
                return;
            }
        }
    }
}

/* The point at angle k 15 degrees and radius r around the origin (the
 * cosine and sine times 2^14, rounded). */
static vor_point_t ring_point(uint32_t k, int32_t r)
{
    static const int32_t c15[24] = {16384, 15826, 14189, 11585, 8192, 4240, 0, -4240,
                                    -8192, -11585, -14189, -15826, -16384, -15826, -14189,
                                    -11585, -8192, -4240, 0, 4240, 8192, 11585, 14189, 15826};
    vor_point_t p = {(c15[k % 24u] * r) / 16384, (c15[(k + 18u) % 24u] * r) / 16384};
    return p;
}

/* A fan: a site below 17 sites on one line, each of its triangles with
 * two neighbours of the line Delaunay (its circle meets the line only at
 * them), so its star holds every other site and the vertex at infinity:
 * a star above removal's arrays whose degree is the site count. */
static void fan(void)
{
    static vor_t d;
    static model_t m;
    begin_model(&d, &m);
    do_insert(&d, &m, (vor_point_t){0, 0}, "fan", 0);
    for (int32_t k = -8; k <= 8; k++) {
        do_insert(&d, &m, (vor_point_t){100 * k, 1000}, "fan", 1);
    }
    uint32_t degree = test_degree(&d, 0);
    CHECK(degree == 17u && d.vertex_count == 18u, "fan: the apex has %u neighbours of %u",
          degree, d.vertex_count - 1u);
    remove_as_modelled(&d, &m, 0, "fan", 2);
    check_state(&d, &m, "fan", 2);
}

/* A site inside a ring of 32 cocircular sites (x^2 + y^2 = 5525^2 has 180
 * lattice points; every sixth of the first quadrant's, turned four ways):
 * its star is larger than removal's arrays (STAR_MAX, dynamic.c), so the
 * first ears are cut by walking the mesh, each decided by the
 * perturbation; then the ring's sites go one by one. */
static void big_star(void)
{
    static vor_t d;
    static model_t m;
    begin_model(&d, &m);
    const int32_t r = 5525;
    uint32_t found = 0, step = 0;
    int32_t y = r;
    for (int32_t x = 0; x < r; x++) {
        while ((int64_t)y * y > (int64_t)r * r - (int64_t)x * x) {
            y--;
        }
        if ((int64_t)y * y == (int64_t)r * r - (int64_t)x * x && found++ % 6u == 0u) {
            const vor_point_t turns[4] = {{x, y}, {-y, x}, {-x, -y}, {y, -x}};
            for (unsigned k = 0; k < 4u; k++) {
                do_insert(&d, &m, turns[k], "ring", step++);
            }
        }
    }
    CHECK(found == 45u && m.handed_out == 32u, "ring: %u lattice points, %u sites", found,
          m.handed_out);
    do_insert(&d, &m, (vor_point_t){0, 0}, "ring", step++);
    uint32_t degree = test_degree(&d, 32);
    CHECK(degree == 32u, "ring: the centre has %u neighbours, expected 32", degree);
    remove_as_modelled(&d, &m, 32, "ring", step);
    check_state(&d, &m, "ring", step++);
    for (uint32_t i = 0; i < 32u; i++) {
        remove_as_modelled(&d, &m, (i * 7u) % 32u, "ring", step);
        check_state(&d, &m, "ring", step++);
    }
}

/* A ring of 24 sites around a centre, every third one pulled in to 96 %
 * of the radius so that it is a reflex corner of the centre's star (the
 * chord of its two neighbours passes at 96.6 %), yet still its
 * neighbour; the pattern turned by `turn` of the 24 places, so that the
 * walk that cuts stars above 16 neighbours meets a reflex candidate first
 * at some turn. The centre's removal against a fresh build. */
static void big_star_reflex(uint32_t turn)
{
    static vor_t d;
    static model_t m;
    begin_model(&d, &m);
    for (uint32_t k = 0; k < 24u; k++) {
        int32_t r = ((k + turn) % 3u == 0u) ? 960 : 1000;
        vor_point_t p = ring_point(k, r);
        do_insert(&d, &m, p, "reflex ring", k);
    }
    do_insert(&d, &m, (vor_point_t){1, 2}, "reflex ring", 24);
    uint32_t degree = test_degree(&d, 24);
    CHECK(degree == 24u, "reflex ring %u: the centre has %u neighbours, expected 24", turn, degree);
    remove_as_modelled(&d, &m, 24, "reflex ring", 25);
    check_state(&d, &m, "reflex ring", 25);
}

/* A site inside a ring of 24 sites at radii 1000 to 1059, none four on a
 * circle by construction (each radius differs): the large star's ears
 * are decided by the incircle tests themselves, not the perturbation.
 * The centre goes first, then the ring's sites in a scrambled order, each
 * step against a fresh build. */
static void big_star_irregular(void)
{
    static vor_t d;
    static model_t m;
    begin_model(&d, &m);
    uint32_t step = 0;
    for (uint32_t k = 0; k < 24u; k++) {
        int32_t r = 1000 + (int32_t)((k * 37u) % 60u);
        vor_point_t p = ring_point(k, r);
        do_insert(&d, &m, p, "irregular ring", step++);
    }
    do_insert(&d, &m, (vor_point_t){3, -2}, "irregular ring", step++);
    uint32_t degree = test_degree(&d, 24);
    CHECK(degree > 16u, "irregular ring: the centre has %u neighbours, expected more than 16",
          degree);
    remove_as_modelled(&d, &m, 24, "irregular ring", step);
    check_state(&d, &m, "irregular ring", step++);
    for (uint32_t i = 0; i < 24u; i++) {
        remove_as_modelled(&d, &m, (i * 5u) % 24u, "irregular ring", step);
        check_state(&d, &m, "irregular ring", step++);
    }
}

/* Moves the triangle in slot `from` to the unused slot `to`. */
static void move_slot(vor_t *d, vor_index_t from, vor_index_t to)
{
    vor__tri_t *tri = d->triangles;
    tri[to] = tri[from];
    for (unsigned i = 0; i < 3u; i++) {
        vor__tri_t *u = &tri[tri[to].n[i]];
        for (unsigned k = 0; k < 3u; k++) {
            u->n[k] = (u->n[k] == from) ? to : u->n[k];
        }
    }
}

static int64_t distance2(const vor_point_t *a, const vor_point_t *b)
{
    int64_t dx = (int64_t)a->x - b->x, dy = (int64_t)a->y - b->y;
    return dx * dx + dy * dy;
}

/* How near a triangle comes to site c: its nearest vertex's squared
 * distance, then its farthest's (by halves: distances are below 2^32). */
static uint64_t nearness(const vor_t *d, const vor__tri_t *t, vor_index_t c)
{
    vor_index_t v[3];
    vor__vertices(t, v);
    uint64_t nearest = UINT32_MAX, farthest = 0;
    for (unsigned i = 0; i < 3u; i++) {
        uint64_t e = (v[i] == VOR__INFINITE) ? UINT32_MAX : (uint64_t)distance2(&d->sites[v[i]], &d->sites[c]);
        nearest = (e < nearest) ? e : nearest;
        farthest = (e > farthest) ? e : farthest;
    }
    return (nearest << 32) | farthest;
}

/* Another legal layout: triangles in order of a key each take an owner
 * among their sites, by an augmenting path through the owners so far
 * when all are taken (a matching of sites to their triangles, grown in
 * key order); the triangles left over fill the packed slots. With no
 * generator the key is nearness to site c, a layout hostile to removal:
 * near c every triangle is a home, so a search for a packed slot from
 * there runs through other homes. With one, the key is random: any
 * legal layout can come out. */
static void relayout(vor_t *d, vor_index_t c, test_rng_t *rng)
{
    static vor__tri_t copy[2u * DYN_SITES];
    static vor_index_t to[2u * DYN_SITES], order[2u * DYN_SITES], owner[2u * DYN_SITES];
    static vor_index_t from[2u * DYN_SITES], queue[2u * DYN_SITES], home[DYN_SITES];
    static uint32_t seen[2u * DYN_SITES];
    static uint64_t key[2u * DYN_SITES];
    vor__tri_t *tri = d->triangles;
    uint32_t slots = d->max_sites + d->vertex_count - 2u, used = 0;
    for (uint32_t s = 0; s < slots; s++) {
        to[s] = VOR__NONE;
        owner[s] = VOR__NONE;
        seen[s] = 0;
        if (s < d->max_sites && (s >= d->site_count || vor__slot_empty(&tri[s]))) {
            continue; /* a free id's slot: no triangle */
        }
        key[s] = (rng != NULL) ? test_rng_u32(rng) : nearness(d, &tri[s], c);
        uint32_t j = used++; /* insertion sort by key */
        for (; j > 0u && key[order[j - 1u]] > key[s]; j--) {
            order[j] = order[j - 1u];
        }
        order[j] = (vor_index_t)s;
    }
    for (uint32_t s = 0; s < d->site_count; s++) {
        home[s] = VOR__NONE;
    }
    for (uint32_t i = 0; i < used; i++) {
        /* breadth first from triangle t through its sites' homes to a
         * site with none */
        vor_index_t t = order[i], free_site = VOR__NONE, last = VOR__NONE;
        uint32_t head = 0, tail = 0;
        queue[tail++] = t;
        seen[t] = i + 1u;
        while (head < tail && free_site == VOR__NONE) {
            vor_index_t x = queue[head++], v[3];
            vor__vertices(&tri[x], v);
            for (unsigned k = 0; k < 3u && free_site == VOR__NONE; k++) {
                if (v[k] == VOR__INFINITE) {
                    continue;
                }
                if (home[v[k]] == VOR__NONE) {
                    free_site = v[k];
                    last = x;
                } else if (seen[home[v[k]]] != i + 1u) {
                    seen[home[v[k]]] = i + 1u;
                    from[home[v[k]]] = x;
                    queue[tail++] = home[v[k]];
                }
            }
        }
        /* shift the owners along the path back to t */
        for (vor_index_t u = free_site, x = last; u != VOR__NONE;) {
            vor_index_t before = owner[x];
            owner[x] = u;
            home[u] = x;
            u = (x == t) ? VOR__NONE : before;
            x = from[x];
        }
    }
    uint32_t next = d->max_sites;
    for (uint32_t i = 0; i < used; i++) {
        vor_index_t s = order[i];
        to[s] = (owner[s] != VOR__NONE) ? owner[s] : (vor_index_t)next++;
    }
    for (uint32_t s = 0; s < slots; s++) {
        if (to[s] != VOR__NONE) {
            copy[to[s]] = tri[s];
            for (unsigned i = 0; i < 3u; i++) {
                copy[to[s]].n[i] = to[tri[s].n[i]];
            }
        }
    }
    for (uint32_t s = 0; s < slots; s++) {
        if (to[s] != VOR__NONE) {
            tri[to[s]] = copy[to[s]];
        }
    }
}

/* Home slots whose triangle changed, slot `except` aside. */
static uint32_t homes_changed(const vor_t *d, const vor__tri_t *before, vor_index_t except)
{
    uint32_t changed = 0;
    for (uint32_t s = 0; s < d->site_count; s++) {
        vor_index_t u[3], v[3];
        vor__vertices(&before[s], u);
        vor__vertices(&d->triangles[s], v);
        bool same = true;
        for (unsigned i = 0; i < 3u; i++) {
            same = same && (v[i] == u[0] || v[i] == u[1] || v[i] == u[2]);
        }
        changed += (s != except && !same) ? 1u : 0u;
    }
    return changed;
}

/* Removal's rehoming (vor__rehome): with the hostile layout around site
 * h, slot h is emptied the way a removal empties it (h's home triangle
 * goes to a neighbour r's home slot, r's to one packed slot too many),
 * then vor__rehome must refill it without changing a triangle; when h
 * has no triangle in a packed slot it searches through other homes,
 * which the test sees as other home slots changing. Then removals near
 * such layouts, checked against fresh builds. */
static void rehoming(void)
{
    static vor_t d;
    static model_t m;
    static vor__tri_t before[DYN_SITES];
    uint32_t searched = 0, runs = 0;
    for (uint64_t seed = 1; seed <= 200u; seed++) {
        test_rng_t rng;
        test_rng_seed(&rng, 9000u + seed);
        begin_model(&d, &m);
        insert_uniform(&d, &m, &rng, 4u + test_rng_u32(&rng) % (DYN_SITES - 4u), "rehome");
        vor_index_t h = (vor_index_t)(test_rng_u32(&rng) % d.site_count), r = VOR__NONE, v[3];
        if (d.vertex_count < 4u || !m.live[h]) {
            continue;
        }
        relayout(&d, h, NULL);
        vor__tri_t *tri = d.triangles;
        vor__vertices(&tri[h], v);
        for (unsigned i = 0; i < 3u; i++) {
            r = (v[i] != h && v[i] != VOR__INFINITE) ? v[i] : r;
        }
        test_fingerprint_t want = test_fingerprint_of(&d, NULL);
        vor_index_t extra = (vor_index_t)(d.max_sites + d.vertex_count - 2u);
        move_slot(&d, r, extra);
        move_slot(&d, h, r);
        for (uint32_t s = 0; s < d.site_count; s++) {
            before[s] = tri[s];
        }
        vor__rehome(&d, h, r, extra);
        runs++;
        searched += (homes_changed(&d, before, h) > 0u) ? 1u : 0u;
        vor_violation_t why = {VOR_CHECK_COUNTS, 0, 0};
        test_fingerprint_t got = test_fingerprint_of(&d, NULL);
        CHECK(vor_validate(&d, &why) == VOR_OK && test_same_fingerprint(got, want),
              "rehome seed %u: check %d, or the triangles changed", (unsigned)seed,
              (int)why.check);
        /* a removal beside the hostile layout */
        relayout(&d, h, NULL);
        do_remove(&d, &m, (test_rng_u32(&rng) % 2u == 0u) ? h : r, "rehome", 1000);
        check_state(&d, &m, "rehome", 1000);
    }
    /* the search beyond h's own triangles must have been needed */
    CHECK(runs > 100u && searched > 3u, "rehome: %u runs, %u searched other homes", runs,
          searched);
    test_printf("rehoming: %u hostile layouts, %u needed other sites' homes\n", runs, searched);
}

/* No home slot of a site keeps the search's visited mark. */
static bool marks_clear(const vor_t *d)
{
    bool clear = true;
    for (uint32_t s = 0; s < d->site_count; s++) {
        clear = clear && (vor__slot_empty(&d->triangles[s]) || !vor__marked(&d->triangles[s]));
    }
    return clear;
}

/* vor__rehome in small meshes under random legal layouts: slot h is
 * emptied along a random chain h = c0, c1, .., ck of sites (each c(i+1)
 * a vertex of c(i)'s home triangle; c(k)'s home triangle goes to the
 * extra packed slot, each c(i)'s to c(i+1)'s), so that any legal state
 * before a refill can come up, and with it both of the refill's cases:
 * a triangle of h packed, or none and one of c1's. The refill must change
 * no triangle, keep the layout legal (vor_validate) and leave no mark. */
static void rehome_search(void)
{
    static vor_t d;
    static vor_point_t points[DYN_SITES];
    static vor__tri_t before[DYN_SITES];
    uint32_t runs = 0, neighbours = 0;
    for (uint64_t seed = 1; seed <= 3000u; seed++) {
        test_rng_t rng;
        test_rng_seed(&rng, 7100u + seed);
        uint32_t n = 4u + test_rng_u32(&rng) % 10u;
        for (uint32_t i = 0; i < n; i++) {
            points[i] = (vor_point_t){test_rng_range(&rng, -40, 40), test_rng_range(&rng, -40, 40)};
        }
        vor_init(&d, arena, sizeof arena, DYN_SITES);
        (void)vor_build(&d, points, n, NULL, NULL);
        vor_index_t h = (vor_index_t)(test_rng_u32(&rng) % n);
        if (d.vertex_count < 4u || !vor__site_in_mesh(&d, h)) {
            continue;
        }
        relayout(&d, h, &rng);
        vor__tri_t *tri = d.triangles;
        test_fingerprint_t want = test_fingerprint_of(&d, NULL);
        vor_index_t extra = (vor_index_t)(d.max_sites + d.vertex_count - 2u);
        vor_index_t chain[6] = {h};
        uint32_t k = 1u + test_rng_u32(&rng) % 5u;
        for (uint32_t i = 0; i < k; i++) {
            vor_index_t v[3], fresh[3];
            unsigned count = 0;
            vor__vertices(&tri[chain[i]], v);
            for (unsigned j = 0; j < 3u; j++) {
                bool is_new = v[j] != VOR__INFINITE;
                for (uint32_t e = 0; e <= i; e++) {
                    is_new = is_new && v[j] != chain[e];
                }
                fresh[count] = v[j];
                count += is_new ? 1u : 0u;
            }
            if (count == 0u) {
                k = i;
                break;
            }
            chain[i + 1u] = fresh[test_rng_u32(&rng) % count];
        }
        move_slot(&d, chain[k], extra);
        for (uint32_t i = k; i > 0u; i--) {
            move_slot(&d, chain[i - 1u], chain[i]);
        }
        for (uint32_t s = 0; s < d.site_count; s++) {
            before[s] = tri[s];
        }
        vor__rehome(&d, h, chain[1], extra);
        runs++;
        neighbours += (homes_changed(&d, before, h) > 0u) ? 1u : 0u;
        vor_violation_t why = {VOR_CHECK_COUNTS, 0, 0};
        CHECK(vor_validate(&d, &why) == VOR_OK &&
                  test_same_fingerprint(test_fingerprint_of(&d, NULL), want) && marks_clear(&d),
              "rehome search seed %u: check %d, the triangles changed or a mark stayed",
              (unsigned)seed, (int)why.check);
    }
    /* both cases must have come up */
    CHECK(runs >= 2000u && neighbours >= 10u, "rehome search: %u runs, %u through a neighbour",
          runs, neighbours);
    test_printf("rehome search: %u refills, %u from a neighbour's star\n", runs, neighbours);
}

/* Duplicates' ids from vor_build stay reserved: not sites, never reused. */
static void build_duplicates(void)
{
    static vor_t d;
    static const vor_point_t points[6] = {{0, 0}, {10, 0}, {0, 0}, {0, 10}, {10, 10}, {10, 0}};
    vor_init(&d, arena, sizeof arena, DYN_SITES);
    CHECK(vor_build(&d, points, 6, NULL, NULL) == VOR_OK, "build with duplicates");
    save(&d);
    CHECK(vor_remove(&d, 2) == VOR_ERR_ARG && vor_move(&d, 5, (vor_point_t){1, 1}, NULL) == VOR_ERR_ARG &&
              unchanged(&d),
          "a duplicate's id is no site");
    uint32_t id = 0;
    CHECK(vor_remove(&d, 1) == VOR_OK && vor_insert(&d, (vor_point_t){3, 4}, &id) == VOR_OK && id == 1,
          "the freed id, not a duplicate's, comes back");
    CHECK(vor_insert(&d, (vor_point_t){4, 3}, &id) == VOR_OK && id == 6, "then a new id");
    CHECK(vor_validate(&d, NULL) == VOR_OK, "valid after reuse");
}

/* The tracker's answer for (x, y) is the brute-force nearest site;
 * *answer is set to it (VOR_NO_HINT when the call fails). */
static bool tracks(vor_tracker_t *robot, const model_t *m, int32_t x, int32_t y, uint32_t *answer,
                   const char *what, uint32_t step)
{
    *answer = VOR_NO_HINT;
    return CHECK(vor_track(robot, (vor_point_t){x, y}, answer) == VOR_OK &&
                     *answer == brute_nearest(m, x, y),
                 "%s %u: %u, brute force %u", what, step, *answer, brute_nearest(m, x, y));
}

/* A tracker whose answer was removed or moved recovers: its answers stay
 * those of a brute-force nearest site. */
static void trackers(void)
{
    static vor_t d;
    static model_t m;
    test_rng_t rng;
    test_rng_seed(&rng, 4242);
    begin_model(&d, &m);
    insert_uniform(&d, &m, &rng, 30u, "tracker");
    vor_tracker_t robot;
    vor_tracker_begin(&robot, &d);
    int32_t x = 0, y = 0;
    for (uint32_t step = 0; step < 60u; step++) {
        uint32_t answer;
        x += test_rng_range(&rng, -40, 40);
        y += test_rng_range(&rng, -40, 40);
        tracks(&robot, &m, x, y, &answer, "tracker step", step);
        if (step % 3u == 0u && live_count(&m) > 4u) {
            do_remove(&d, &m, answer, "tracker", step); /* its answer goes */
        } else if (step % 3u == 1u) {
            vor_point_t p = random_point(&rng, UNIFORM);
            do_move(&d, &m, answer, p, "tracker", step);
        } else {
            do_insert(&d, &m, random_point(&rng, UNIFORM), "tracker", step);
        }
    }
}

/* A tracker must see every change, also two in a row: with an answer
 * cached, a removal or a small move of another site, then an insertion
 * next to the query, then the same query again, against brute force. */
static void tracker_two_changes(void)
{
    static vor_t d;
    static model_t m;
    test_rng_t rng;
    test_rng_seed(&rng, 4343);
    begin_model(&d, &m);
    insert_uniform(&d, &m, &rng, 20u, "two changes");
    vor_tracker_t robot;
    vor_tracker_begin(&robot, &d);
    for (uint32_t round = 0; round < 45u; round++) {
        int32_t x = test_rng_range(&rng, -900, 900), y = test_rng_range(&rng, -900, 900);
        uint32_t answer, again;
        tracks(&robot, &m, x, y, &answer, "two changes round", round);
        uint32_t other = random_id(&rng, &m);
        for (uint32_t tries = 0; tries < 64u && (other == answer || other >= m.handed_out ||
                                                 !m.live[other]); tries++) {
            other = random_id(&rng, &m);
        }
        if (other != answer && other < m.handed_out && m.live[other]) {
            if (round % 3u != 2u) {
                do_remove(&d, &m, other, "two changes", round);
            } else { /* one unit: the triangles mostly stay */
                do_move(&d, &m, other, (vor_point_t){m.at[other].x + 1, m.at[other].y},
                        "two changes", round);
            }
        }
        do_insert(&d, &m, (vor_point_t){x + 1, y}, "two changes", round);
        tracks(&robot, &m, x, y, &again, "two changes, after, round", round);
    }
}

/* A diagram of one site, whose arena has no triangle slots to hold the
 * free list: its id is reused after a removal, and the bytes after the
 * arena (filled with a pattern) are never taken for an id nor written;
 * and one of two,
 * whose free list holds both ids. */
static void one_site(void)
{
    static uint8_t memory[VOR_ARENA_BYTES(1) + 64u] __attribute__((aligned(8)));
    for (size_t i = 0; i < sizeof memory; i++) {
        memory[i] = 0xA5u;
    }
    vor_t d;
    uint32_t id = UINT32_MAX, other = UINT32_MAX;
    CHECK(vor_init(&d, memory, VOR_ARENA_BYTES(1), 1) == VOR_OK &&
              vor_insert(&d, (vor_point_t){3, 4}, &id) == VOR_OK && id == 0u,
          "first site: id %u", id);
    for (int round = 0; round < 3; round++) {
        CHECK(vor_remove(&d, 0) == VOR_OK, "remove, round %d", round);
        id = UINT32_MAX;
        CHECK(vor_insert(&d, (vor_point_t){round, -round}, &id) == VOR_OK && id == 0u &&
                  vor_validate(&d, NULL) == VOR_OK,
              "insert after a removal, round %d: id %u", round, id);
        CHECK(vor_insert(&d, (vor_point_t){100, 100}, &other) == VOR_ERR_FULL,
              "a second site, round %d", round);
    }
    bool kept = true;
    for (size_t i = VOR_ARENA_BYTES(1); i < sizeof memory; i++) {
        kept = kept && memory[i] == 0xA5u;
    }
    CHECK(kept, "one site: a byte after the arena was written");
    /* room for two: both removed, both ids come back, the last freed
     * first (the list's link in the first one's home slot) */
    static uint8_t pair[VOR_ARENA_BYTES(2)] __attribute__((aligned(8)));
    CHECK(vor_init(&d, pair, sizeof pair, 2) == VOR_OK &&
              vor_insert(&d, (vor_point_t){3, 4}, NULL) == VOR_OK &&
              vor_insert(&d, (vor_point_t){5, 6}, NULL) == VOR_OK && vor_remove(&d, 0) == VOR_OK &&
              vor_remove(&d, 1) == VOR_OK,
          "two sites removed");
    id = other = UINT32_MAX;
    CHECK(vor_insert(&d, (vor_point_t){7, 8}, &id) == VOR_OK && id == 1u &&
              vor_insert(&d, (vor_point_t){9, 1}, &other) == VOR_OK && other == 0u &&
              vor_validate(&d, NULL) == VOR_OK,
          "the two ids again: %u, %u", id, other);
}

/* Two sites: vor_move tells a move onto the other site (a duplicate,
 * nothing changed) from moves that share only its x or only its y. And
 * the 24-bit change counter wraps to 1 on a diagram without a motion
 * cache too (white box: d.motion_epoch). */
static void two_sites(void)
{
    vor_t d;
    const vor_point_t two[2] = {{10, 20}, {-5, 7}};
    CHECK(vor_init(&d, arena, sizeof arena, DYN_SITES) == VOR_OK &&
              vor_build(&d, two, 2, NULL, NULL) == VOR_OK,
          "two sites");
    save(&d);
    uint32_t existing = 77;
    CHECK(vor_move(&d, 0, two[1], &existing) == VOR_ERR_DUPLICATE && existing == 1u &&
              unchanged(&d),
          "a move onto the other site");
    const vor_point_t to[2] = {{-5, 30}, {40, 7}}; /* the other's x, then its y */
    for (unsigned k = 0; k < 2u; k++) {
        uint32_t nearest = 77;
        CHECK(vor_move(&d, 0, to[k], NULL) == VOR_OK && vor_validate(&d, NULL) == VOR_OK &&
                  d.sites[0].x == to[k].x && d.sites[0].y == to[k].y &&
                  vor_nearest(&d, to[k], VOR_NO_HINT, &nearest) == VOR_OK && nearest == 0u,
              "a move sharing one coordinate with the other site (%u)", k);
    }
    d.motion_epoch = 0xFFFFFFu;
    uint32_t id = 77;
    CHECK(vor_insert(&d, (vor_point_t){100, 100}, &id) == VOR_OK && id == 2u &&
              d.motion_epoch == 1u && vor_validate(&d, NULL) == VOR_OK,
          "the change counter wraps to 1 without a cache (epoch %u)", d.motion_epoch);
}

void test_dynamic(void)
{
    for (unsigned shape = UNIFORM; shape < SHAPES; shape++) {
        for (uint64_t seed = 1; seed <= 2u; seed++) {
            TEST_CASE("random_sequence/%s/%u", shape_names[shape], (unsigned)seed) {
                random_sequence((enum shape)shape, seed * 1000u + shape, 150);
            }
        }
    }
    TEST_CASE("few_sites/1") few_sites(5151);
    TEST_CASE("few_sites/2") few_sites(5252);
    TEST_CASE("down_to_nothing") down_to_nothing();
    TEST_CASE("removal_cost") removal_cost();
    TEST_CASE("big_star") big_star();
    TEST_CASE("fan") fan();
    TEST_CASE("grid_at_two_sites") grid_at_two_sites();
    TEST_CASE("full_arenas") full_arenas();
    TEST_CASE("big_star_irregular") big_star_irregular();
    TEST_CASE("big_star_reflex") {
        for (uint32_t turn = 0; turn < 3u; turn++) {
            big_star_reflex(turn);
        }
    }
    TEST_CASE("rehoming") rehoming();
    TEST_CASE("rehome_search") rehome_search();
    TEST_CASE("build_duplicates") build_duplicates();
    TEST_CASE("trackers") trackers();
    TEST_CASE("tracker_two_changes") tracker_two_changes();
    TEST_CASE("one_site") one_site();
    TEST_CASE("two_sites") two_sites();
}
