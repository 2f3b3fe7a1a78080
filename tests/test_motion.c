/* SPDX-License-Identifier: MIT */
/*
 * test_motion.c - the motion cache (vor_motion_attach): small moves that
 * skip the predicates must give exactly the triangles they would without.
 *
 * Independent references: after every move, vor_validate; the triangles
 * of a fresh vor_build of the current sites (the perturbed triangulation
 * is unique); and a twin diagram without a cache that takes the same
 * moves. A move counts as fast when it evaluated no predicate (the
 * diagram's stats did not change; every other successful move evaluates
 * at least one on meshes of three or more sites), and a fast move must
 * leave the twin's triangles as they were. White box: boxes against the
 * derivation in src/motion.c's head comment, computed here by trying
 * each exponent (orient_box, incircle_box), and every cache entry after
 * a slow move against a model of the upkeep built on them.
 */
#include "mesh.h" /* white box: the star around a site, for the upkeep model */
#include "motion.h"
#include "predicates.h" /* white box: the exact magnitudes, vor__incircle_bits */
#include "test.h"
#include "vor.h"

#define MOTION_SITES 48u

static uint8_t arena[VOR_ARENA_BYTES(MOTION_SITES)] __attribute__((aligned(8)));
static uint8_t twin_arena[VOR_ARENA_BYTES(MOTION_SITES)] __attribute__((aligned(8)));
static uint8_t fresh_arena[VOR_ARENA_BYTES(MOTION_SITES)] __attribute__((aligned(8)));
/* one spare byte for the misaligned attach */
static uint8_t cache[VOR_MOTION_BYTES(MOTION_SITES) + 4u] __attribute__((aligned(8)));
static vor_t with, without;
static vor_point_t at[MOTION_SITES];

/* d holds exactly the triangulation of at[0 .. n) (ids = indices). */
static bool exact(const vor_t *d, uint32_t n, const char *what, uint32_t step)
{
    vor_violation_t violation = {VOR_CHECK_COUNTS, 0, 0};
    int err = vor_validate(d, &violation);
    bool ok = CHECK(err == VOR_OK, "%s step %u: vor_validate %d (check %d)", what, step, err,
                    (int)violation.check);
    vor_t fresh;
    vor_init(&fresh, fresh_arena, sizeof fresh_arena, MOTION_SITES);
    ok = CHECK(vor_build(&fresh, at, n, NULL, NULL) == VOR_OK, "%s step %u: fresh build", what,
               step) && ok;
    ok = CHECK(test_same_fingerprint(test_fingerprint_of(d, NULL),
                                     test_fingerprint_of(&fresh, NULL)),
               "%s step %u: not the fresh build's triangles", what, step) && ok;
    return ok;
}

/* Both diagrams built from at[0 .. n), the cache attached to `with`. */
static void start(uint32_t n)
{
    vor_init(&with, arena, sizeof arena, MOTION_SITES);
    vor_init(&without, twin_arena, sizeof twin_arena, MOTION_SITES);
    CHECK(vor_motion_attach(&with, cache, VOR_MOTION_BYTES(MOTION_SITES)) == VOR_OK, "attach");
    CHECK(vor_build(&with, at, n, NULL, NULL) == VOR_OK, "build");
    CHECK(vor_build(&without, at, n, NULL, NULL) == VOR_OK, "build the twin");
}

static uint32_t site_at(uint32_t n, vor_point_t p)
{
    for (uint32_t i = 0; i < n; i++) {
        if (at[i].x == p.x && at[i].y == p.y) {
            return i;
        }
    }
    return VOR_NO_HINT;
}

/* Moves site i to p in both diagrams and checks everything; returns
 * whether the move with the cache was fast, or false on failure. */
static bool move(uint32_t n, uint32_t i, vor_point_t p, const char *what, uint32_t step)
{
    uint32_t twin = site_at(n, p), calls = test_predicate_calls(&with), existing = VOR_NO_HINT;
    test_fingerprint_t before = test_fingerprint_of(&without, NULL);
    int err = vor_move(&with, i, p, &existing);
    int twin_err = vor_move(&without, i, p, NULL);
    if (twin != VOR_NO_HINT && twin != i) {
        CHECK(err == VOR_ERR_DUPLICATE && existing == twin && twin_err == err,
              "%s step %u: move onto site %u gave %d", what, step, twin, err);
        return false;
    }
    CHECK(err == VOR_OK && twin_err == VOR_OK, "%s step %u: move gave %d, %d", what, step, err,
          twin_err);
    at[i] = p;
    bool fast = twin != i && test_predicate_calls(&with) == calls;
    if (fast) {
        CHECK(test_same_fingerprint(before, test_fingerprint_of(&without, NULL)),
              "%s step %u: a fast move of %u changed triangles", what, step, i);
    }
    CHECK(test_same_fingerprint(test_fingerprint_of(&with, NULL),
                                test_fingerprint_of(&without, NULL)),
          "%s step %u: the cache changed the triangles", what, step);
    exact(&with, n, what, step);
    return fast;
}

static vor_point_t offset(vor_point_t p, int32_t dx, int32_t dy)
{
    vor_point_t q = {p.x + dx, p.y + dy};
    return q;
}

/* Random walks; `scale` bounds a step (0: a mix from 1 to 4,096). */
static uint32_t walk(uint64_t seed, uint32_t n, int32_t spread, int32_t lattice, int32_t scale,
                     uint32_t steps, const char *what)
{
    test_rng_t rng;
    test_rng_seed(&rng, seed);
    for (uint32_t i = 0; i < n; i++) {
        do {
            at[i].x = test_rng_range(&rng, 0, spread) * lattice;
            at[i].y = test_rng_range(&rng, 0, spread) * lattice;
        } while (site_at(i, at[i]) != VOR_NO_HINT);
    }
    start(n);
    uint32_t fast = 0;
    unsigned long failures = test_failures();
    for (uint32_t step = 0; step < steps && test_failures() == failures; step++) {
        uint32_t i = test_rng_u32(&rng) % n;
        int32_t s = scale;
        if (s == 0) {
            static const int32_t scales[8] = {1, 1, 1, 2, 4, 16, 256, 4096};
            s = scales[test_rng_u32(&rng) % 8u];
        }
        vor_point_t p = offset(at[i], test_rng_range(&rng, -s, s), test_rng_range(&rng, -s, s));
        fast += move(n, i, p, what, step) ? 1u : 0u;
    }
    return fast;
}

/* Site `mover` walks in unit steps along (dx, dy) from `from` through a
 * configuration where its triangles change; the crossing must be slow. */
static void crossing(uint32_t n, uint32_t mover, vor_point_t from, int32_t dx, int32_t dy,
                     uint32_t steps, const char *what)
{
    at[mover] = from;
    start(n);
    uint32_t changes = 0;
    for (uint32_t step = 0; step < steps; step++) {
        test_fingerprint_t before = test_fingerprint_of(&without, NULL);
        move(n, mover, offset(at[mover], dx, dy), what, step);
        changes += test_same_fingerprint(before, test_fingerprint_of(&without, NULL)) ? 0u : 1u;
    }
    CHECK(changes > 0u, "%s: the walk changed no triangle (a test that cannot fail)", what);
}

/* Invariant J at its extremes: every site with a box jumps to a random
 * corner of it, round after round; each jump must be fast (J covers every
 * such configuration at once, so nothing is voided) and exact. The boxes
 * are read from the cache (white box: src/motion.h). */
static void corners(uint64_t seed, uint32_t n, int32_t spread, int32_t jitter, uint32_t min_boxed,
                    const char *what)
{
    test_rng_t rng;
    test_rng_seed(&rng, seed);
    for (uint32_t i = 0; i < n; i++) {
        do { /* a circle of radius spread / 2, moved off it by up to jitter */
            int32_t k = test_rng_range(&rng, 0, 7);
            static const int32_t unit[8][2] = {{1000, 0}, {707, 707},   {0, 1000},  {-707, 707},
                                               {-1000, 0}, {-707, -707}, {0, -1000}, {707, -707}};
            int32_t r = spread / 2000 + test_rng_range(&rng, 0, (int32_t)i);
            at[i].x = unit[k][0] * r + test_rng_range(&rng, -jitter, jitter) +
                      (int32_t)(i / 8u) * spread / 3;
            at[i].y = unit[k][1] * r + test_rng_range(&rng, -jitter, jitter);
        } while (site_at(i, at[i]) != VOR_NO_HINT);
    }
    start(n);
    for (uint32_t round = 0; round < 3u; round++) { /* boxes for most sites */
        for (uint32_t i = 0; i < n; i++) {
            move(n, i, offset(at[i], 1, -1), what, i);
        }
    }
    uint32_t boxed = 0, jumps = 0;
    unsigned long failures = test_failures();
    for (uint32_t round = 0; round < 6u && test_failures() == failures; round++) {
        for (uint32_t i = 0; i < n; i++) {
            const struct vor__motion_entry *e = &with.motion[i];
            if ((e->stamp >> 8) != with.motion_epoch || (e->stamp & VOR__BOX_MASK) == 0u) {
                continue;
            }
            int32_t r = (int32_t)(1u << ((e->stamp & VOR__BOX_MASK) - 1u));
            vor_point_t corner = {e->x + ((test_rng_u32(&rng) & 1u) ? r : -r),
                                  e->y + ((test_rng_u32(&rng) & 1u) ? r : -r)};
            if (site_at(n, corner) != VOR_NO_HINT) {
                continue; /* its own place already */
            }
            boxed += (round == 0u) ? 1u : 0u;
            jumps++;
            CHECK(move(n, i, corner, what, round), "%s: a jump inside the box of %u was slow",
                  what, i);
        }
    }
    CHECK(boxed >= min_boxed, "%s: only %u of %u sites have a box", what, boxed, n);
    CHECK(jumps > 0u, "%s: no jump", what);
}

static void degenerate_walks(void)
{
    /* a square (0,0) (1000,0) (1000,1000) (0,1000) and a frame around:
     * site 3 walks through the square's circle at (0, 1000) */
    static const vor_point_t square[8] = {{0, 0},       {1000, 0},   {1000, 1000}, {0, 1000},
                                          {-900, -900}, {1900, -900}, {1900, 1900}, {-900, 1900}};
    for (uint32_t i = 0; i < 8u; i++) {
        at[i] = square[i];
    }
    crossing(8, 3, offset(square[3], -20, 0), 1, 0, 40, "cocircular crossing");
    for (uint32_t i = 0; i < 8u; i++) {
        at[i] = square[i];
    }
    /* along the circle's normal at (0, 1000): in and out */
    crossing(8, 3, offset(square[3], 0, -15), 0, 1, 30, "cocircular normal");
    /* the hull: site 1 of (0,0) (500,0) (1000,0) crosses the hull line */
    static const vor_point_t hull[6] = {{0, 0},     {500, 12},  {1000, 0},
                                        {500, 300}, {300, 600}, {800, 500}};
    for (uint32_t i = 0; i < 6u; i++) {
        at[i] = hull[i];
    }
    crossing(6, 1, hull[1], 0, -1, 25, "hull crossing");
    /* three sites only, through collinearity */
    static const vor_point_t three[3] = {{0, 0}, {100, 7}, {200, 0}};
    for (uint32_t i = 0; i < 3u; i++) {
        at[i] = three[i];
    }
    crossing(3, 1, three[1], 0, -1, 14, "three sites collinear");
}

static uint8_t saved_arena[sizeof arena], saved_cache[sizeof cache];
static vor_t saved;

static void save(void)
{
    test_copy_bytes(&saved, &with, sizeof saved);
    test_copy_bytes(saved_arena, arena, sizeof arena);
    test_copy_bytes(saved_cache, cache, sizeof cache);
}

static bool unchanged(void)
{
    return test_same_bytes(&saved, &with, sizeof saved) &&
           test_same_bytes(saved_arena, arena, sizeof arena) &&
           test_same_bytes(saved_cache, cache, sizeof cache);
}

/* Tiny steps of every site until each has a box. */
static void settle(uint32_t n)
{
    for (uint32_t round = 0; round < 3u; round++) {
        for (uint32_t i = 0; i < n; i++) {
            move(n, i, offset(at[i], (round % 2u == 0u) ? 1 : -1, 0), "settle", i);
        }
    }
}

static void api_safety(void)
{
    vor_init(&with, arena, sizeof arena, MOTION_SITES);
    save();
    CHECK(vor_motion_attach(NULL, cache, sizeof cache) == VOR_ERR_ARG, "attach to NULL");
    CHECK(vor_motion_attach(&with, NULL, 12) == VOR_ERR_ARG &&
              vor_motion_attach(&with, NULL, 1) == VOR_ERR_ARG,
          "attach NULL memory");
    CHECK(vor_motion_attach(&with, cache + 1, VOR_MOTION_BYTES(MOTION_SITES)) == VOR_ERR_ALIGN,
          "attach misaligned memory");
    CHECK(vor_motion_attach(&with, cache, VOR_MOTION_BYTES(MOTION_SITES) - 1u) == VOR_ERR_NOMEM,
          "attach too little memory");
    CHECK(vor_motion_attach(&with, cache, 0) == VOR_ERR_NOMEM, "attach no memory");
    CHECK(unchanged(), "a failing attach changed something");
    CHECK(vor_motion_attach(&with, NULL, 0) == VOR_OK, "detach without a cache");
    CHECK(vor_move(NULL, 0, (vor_point_t){1, 1}, NULL) == VOR_ERR_ARG, "move in NULL");

    /* the attach writes its entries and not a byte past them */
    for (size_t i = VOR_MOTION_BYTES(MOTION_SITES); i < sizeof cache; i++) {
        cache[i] = 0xA5u;
    }
    CHECK(vor_motion_attach(&with, cache, VOR_MOTION_BYTES(MOTION_SITES)) == VOR_OK &&
              cache[VOR_MOTION_BYTES(MOTION_SITES)] == 0xA5u &&
              cache[sizeof cache - 1u] == 0xA5u,
          "the attach wrote past its memory");
    /* attached to an empty diagram, then filled one site at a time */
    CHECK(vor_motion_attach(&with, cache, sizeof cache) == VOR_OK, "attach to an empty diagram");
    vor_init(&without, twin_arena, sizeof twin_arena, MOTION_SITES);
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    uint32_t n = 0;
    for (; n < 20u; n++) {
        do {
            at[n].x = test_rng_range(&rng, 0, 5000000);
            at[n].y = test_rng_range(&rng, 0, 5000000);
        } while (site_at(n, at[n]) != VOR_NO_HINT);
        CHECK(vor_insert(&with, at[n], NULL) == VOR_OK, "insert %u", n);
        CHECK(vor_insert(&without, at[n], NULL) == VOR_OK, "insert %u", n);
        if (n >= 1u) { /* moves in meshes of 2 .. 20 sites */
            move(n + 1u, n - 1u, offset(at[n - 1u], 1, 1), "filling", n);
        }
    }
    settle(n);
    /* with boxes everywhere: failing calls change nothing, cache included */
    save();
    CHECK(vor_move(&with, 3, at[5], NULL) == VOR_ERR_DUPLICATE, "move onto a site");
    CHECK(vor_move(&with, MOTION_SITES - 1u, (vor_point_t){0, 0}, NULL) == VOR_ERR_ARG, "move an unused id");
    CHECK(vor_insert(&with, at[7], NULL) == VOR_ERR_DUPLICATE, "insert a duplicate");
    CHECK(vor_remove(&with, MOTION_SITES - 1u) == VOR_ERR_ARG, "remove an unused id");
    CHECK(vor_motion_attach(&with, cache + 1, sizeof cache - 1u) == VOR_ERR_ALIGN,
          "re-attach misaligned");
    CHECK(unchanged(), "a failing call changed the diagram or the cache");
    CHECK(move(n, 4, offset(at[4], 1, 0), "boxed", 0), "a tiny move with a box was slow");

    /* every change of triangles voids the boxes: the next tiny move is
     * checked in full */
    at[n] = (vor_point_t){2500000, 2600000};
    CHECK(vor_insert(&with, at[n], NULL) == VOR_OK, "insert");
    CHECK(vor_insert(&without, at[n], NULL) == VOR_OK, "insert");
    n++;
    CHECK(!move(n, 4, offset(at[4], -1, 0), "after insert", 0), "fast move after an insert");
    settle(n);
    n--;
    CHECK(vor_remove(&with, n) == VOR_OK && vor_remove(&without, n) == VOR_OK, "remove");
    CHECK(!move(n, 4, offset(at[4], 1, 0), "after remove", 0), "fast move after a removal");
    settle(n);
    CHECK(vor_build(&with, at, n, NULL, NULL) == VOR_OK, "rebuild");
    CHECK(vor_build(&without, at, n, NULL, NULL) == VOR_OK, "rebuild");
    CHECK(!move(n, 4, offset(at[4], -1, 0), "after build", 0), "fast move after a build");
    settle(n);
    CHECK(move(n, 4, offset(at[4], 1, 0), "build keeps", 0), "vor_build dropped the cache");
    CHECK(vor_build_dc(&with, at, n, TEST_SPLIT(VOR_DC_XSPLIT), NULL) == VOR_OK, "d&c rebuild");
    CHECK(!move(n, 4, offset(at[4], -1, 0), "after d&c build", 0), "fast move after a build");

    /* the 24-bit epoch wraps: stamps of 2^24 changes ago must not look
     * current, so the wrap clears them all (white box: the entry layout
     * of src/motion.h) */
    settle(n);
    with.motion_epoch = 0xFFFFFFu;
    settle(n);
    CHECK(vor_remove(&with, n - 1u) == VOR_OK && vor_remove(&without, n - 1u) == VOR_OK,
          "remove");
    n--;
    bool cleared = with.motion_epoch == 1u;
    for (uint32_t i = 0; i < MOTION_SITES; i++) {
        cleared = cleared && with.motion[i].stamp == 0u;
    }
    CHECK(cleared, "the epoch's wrap left stamps (epoch %u)", with.motion_epoch);
    CHECK(!move(n, 4, offset(at[4], 1, 0), "after the wrap", 0), "fast move after the wrap");

    /* detached: never fast; the memory is the caller's again */
    CHECK(vor_motion_attach(&with, NULL, 0) == VOR_OK, "detach");
    for (size_t i = 0; i < sizeof cache; i++) {
        cache[i] = 0xA5;
    }
    for (uint32_t i = 0; i < n; i++) {
        CHECK(!move(n, i, offset(at[i], 1, 0), "detached", i), "fast move without a cache");
    }
    /* re-attached memory starts empty whatever it held */
    CHECK(vor_motion_attach(&with, cache, sizeof cache) == VOR_OK, "re-attach");
    CHECK(!move(n, 2, offset(at[2], 1, 0), "re-attached", 0), "fast move from garbage");
    /* vor_init drops the attachment */
    vor_init(&with, arena, sizeof arena, MOTION_SITES);
    CHECK(with.motion == NULL, "vor_init kept a cache");
}

/* Does site i hold a box of the current triangles? (white box) */
static bool boxed(uint32_t i)
{
    const struct vor__motion_entry *e = &with.motion[i];
    return (e->stamp >> 8) == with.motion_epoch && (e->stamp & VOR__BOX_MASK) != 0u;
}

/* The backoff (src/motion.c): which slow moves size a box. */
static void backoff(void)
{
    uint32_t n = MOTION_SITES, i = 5;
    walk(21, n, 1000000, 1, 1, 0, "backoff");
    CHECK(!move(n, i, offset(at[i], 1, 0), "backoff", 0) && !boxed(i),
          "the first slow move since the attach sized a box");
    CHECK(!move(n, i, offset(at[i], -1, 0), "backoff", 1) && boxed(i),
          "the second slow move sized no box");
    /* boxes left unused: the next 2^level slow moves (the one leaving
     * included) size nothing, the level going up to 5 */
    for (uint32_t level = 1; level <= 6u && boxed(i); level++) {
        int32_t r = (int32_t)(1u << ((with.motion[i].stamp & VOR__BOX_MASK) - 1u));
        int32_t jump = (level % 2u == 1u) ? 2 * r + 1 : -2 * r - 1;
        CHECK(!move(n, i, offset(at[i], jump, 0), "backoff", level) && !boxed(i),
              "level %u: a jump out of the box sized one", level);
        uint32_t unsized = 1;
        while (unsized <= 64u && !boxed(i)) {
            move(n, i, offset(at[i], (unsized % 2u == 1u) ? 1 : -1, 0), "backoff", level);
            unsized += boxed(i) ? 0u : 1u;
        }
        CHECK(unsized == (1u << ((level < 5u) ? level : 5u)),
              "level %u: %u slow moves without sizing", level, unsized);
    }
    /* a box the site moves inside resets the level: the slow move
     * leaving it (a step of r, from 1 past the anchor) sizes again */
    CHECK(move(n, i, offset(at[i], 1, 0), "backoff", 7), "a step inside the box was slow");
    int32_t r = (int32_t)(1u << ((with.motion[i].stamp & VOR__BOX_MASK) - 1u));
    CHECK(!move(n, i, offset(at[i], r, 0), "backoff", 8) && boxed(i),
          "a used box's successor was not sized");
    CHECK(((with.motion[i].stamp >> 5) & 7u) == 0u, "a used box left the level at %u",
          (with.motion[i].stamp >> 5) & 7u);
    /* steps of 2^13 (the spacing about 144,000, the boxes about 2^-12 of
     * it) no box holds: each sizing raises the level, and the next
     * 2^level slow moves size nothing (the entry's counters), the level
     * going up to 5 and staying there */
    uint32_t j = 9;
    move(n, j, offset(at[j], 8192, 0), "big steps", 0); /* the first: no sizing */
    for (uint32_t round = 1; round <= 6u; round++) {
        uint32_t level = (round < 5u) ? round : 5u;
        int32_t sign = (round % 2u == 1u) ? -1 : 1;
        move(n, j, offset(at[j], sign * 8192, 0), "big steps", round);
        const struct vor__motion_entry *e = &with.motion[j];
        CHECK(!boxed(j) && ((e->stamp >> 5) & 7u) == level && e->x == (int32_t)(1u << level),
              "big steps: round %u, entry %x %d", round, e->stamp, e->x);
        for (uint32_t k = 0; k < (1u << level); k++) {
            move(n, j, offset(at[j], (k % 2u == 0u) ? sign * 8192 : -sign * 8192, 0), "big steps",
                 round);
        }
        CHECK(e->x == 0 && ((e->stamp >> 5) & 7u) == level,
              "big steps: round %u after the skipped moves, entry %x %d", round, e->stamp, e->x);
    }
}

/* Sites over the whole int32 range, four of them a few units from its
 * corners, taking tiny steps: predicates whose differences take 33 bits
 * and boxes cut short by the end of the range. */
static void full_range(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 21);
    const uint32_t n = 24;
    static const vor_point_t corner[4] = {{INT32_MIN + 2, INT32_MIN + 2},
                                          {INT32_MAX - 2, INT32_MIN + 5},
                                          {INT32_MIN + 3, INT32_MAX - 2},
                                          {INT32_MAX - 3, INT32_MAX - 4}};
    for (uint32_t i = 0; i < n; i++) {
        do {
            at[i].x = (int32_t)test_rng_u32(&rng);
            at[i].y = (int32_t)test_rng_u32(&rng);
            at[i] = (i < 4u) ? corner[i] : at[i];
        } while (site_at(i, at[i]) != VOR_NO_HINT);
    }
    start(n);
    unsigned long failures = test_failures();
    uint32_t fast = 0, steps = 400;
    for (uint32_t step = 0; step < steps && test_failures() == failures; step++) {
        uint32_t i = (step % 2u == 0u) ? step / 2u % 4u : test_rng_u32(&rng) % n;
        int64_t x = (int64_t)at[i].x + test_rng_range(&rng, -2, 2);
        int64_t y = (int64_t)at[i].y + test_rng_range(&rng, -2, 2);
        vor_point_t p = {(int32_t)((x < INT32_MIN) ? INT32_MIN : (x > INT32_MAX) ? INT32_MAX : x),
                         (int32_t)((y < INT32_MIN) ? INT32_MIN : (y > INT32_MAX) ? INT32_MAX : y)};
        fast += move(n, i, p, "full range", step) ? 1u : 0u;
    }
    CHECK(fast > 0u, "full range: no fast move (a test that cannot fail)");
}

/* A site's first slow move sizes no box of its own (the backoff), yet
 * its star's other boxes must be proven again: site 1 moves into the box
 * of its neighbour 0 without changing a triangle (the ring lies far from
 * their bisector), after which no jump of 0 to a corner of its box may
 * be fast, each crossing a line through site 1 (white box: the box read
 * from the cache). */
static void neighbour_moves_in(void)
{
    const uint32_t n = 9;
    static const vor_point_t ring[7] = {{1000000, 0},       {623490, 781831},   {-222521, 974928},
                                        {-900969, 433884},  {-900969, -433884}, {-222521, -974928},
                                        {623490, -781831}};
    at[0] = (vor_point_t){0, 0};
    at[1] = (vor_point_t){3000, 0};
    for (uint32_t k = 0; k < 7u; k++) {
        at[2u + k] = ring[k];
    }
    start(n);
    for (uint32_t k = 0; k < 4u; k++) {
        move(n, 0, offset(at[0], (k % 2u == 0u) ? 1 : -1, 0), "neighbour settles", k);
    }
    if (!CHECK(boxed(0), "neighbour: site 0 has no box (a test that cannot fail)")) {
        return;
    }
    const struct vor__motion_entry *e = &with.motion[0];
    int32_t r = (int32_t)(1u << ((e->stamp & VOR__BOX_MASK) - 1u));
    vor_point_t anchor = {e->x, e->y};
    vor_point_t inside = offset(anchor, r / 2 + 1, 0);
    CHECK(r >= 2 && site_at(n, inside) == VOR_NO_HINT, "neighbour: box of %d", (int)r);
    test_fingerprint_t before = test_fingerprint_of(&with, NULL);
    move(n, 1, inside, "neighbour moves in", 0);
    CHECK(test_same_fingerprint(before, test_fingerprint_of(&with, NULL)),
          "neighbour: the move changed triangles (a test that cannot fail)");
    static const int32_t sign[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (uint32_t k = 0; k < 4u; k++) {
        vor_point_t corner = offset(anchor, sign[k][0] * r, sign[k][1] * r);
        CHECK(!move(n, 0, corner, "neighbour: a corner", k),
              "neighbour: a jump of site 0 to (%d, %d) was fast", corner.x, corner.y);
        move(n, 0, anchor, "neighbour: back", k);
    }
}

/* A box near the end of the int32 range is cut to the largest power of
 * two that keeps it inside (so that the fast test's offsets cannot
 * wrap), and no smaller: site 0 lies `room` units from INT32_MAX, its
 * neighbours a million away, so its predicates alone would allow a far
 * larger box; 2^e <= room < 2^(e+1), and no box at all with no room
 * (white box: the box read from the cache). Rooms of 100, a power of two
 * and 0: the cut's both edges. */
static void box_at_range_end(int32_t room_wanted)
{
    test_rng_t rng;
    test_rng_seed(&rng, 31);
    const uint32_t n = 10;
    at[0] = (vor_point_t){INT32_MAX - room_wanted, 0};
    for (uint32_t i = 1; i < n; i++) {
        do {
            at[i].x = INT32_MAX - test_rng_range(&rng, 1000000, 4000000);
            at[i].y = test_rng_range(&rng, -2000000, 2000000);
        } while (site_at(i, at[i]) != VOR_NO_HINT);
    }
    start(n);
    for (uint32_t k = 0; k < 4u; k++) { /* down and back: it ends where it began */
        move(n, 0, offset(at[0], (k % 2u == 0u) ? -1 : 1, 0), "range end settles", k);
    }
    if (room_wanted == 0) {
        CHECK(!boxed(0), "range end: a box for a site at INT32_MAX");
        return;
    }
    if (!CHECK(boxed(0), "range end: site 0 has no box (a test that cannot fail)")) {
        return;
    }
    const struct vor__motion_entry *e = &with.motion[0];
    uint32_t exponent = (e->stamp & VOR__BOX_MASK) - 1u;
    uint32_t room = (uint32_t)(INT32_MAX - e->x);
    CHECK(room == (uint32_t)room_wanted && (1u << exponent) <= room && (2u << exponent) > room,
          "range end: box 2^%u at %u from the end", exponent, room);
}

/* Bit length of v: the least k with v < 2^k. */
static int bit_length(uint64_t v)
{
    int k = 0;
    while (k < 64 && (v >> k) != 0u) {
        k++;
    }
    return k;
}

/* The box of a three-site diagram, whose predicates are all the one
 * orientation (its triangle's and the hull's, whichever site they are
 * taken from), against the derivation in src/motion.c: with |P| of bit
 * length L, vectors below 2^m from every site, moves within 2^E, E = e + 2,
 * the bound 2^(max(m, E) + E + 3) must stay at or below 2^(L - 3); the
 * box has the largest such e >= 0, found here by trying each (white box:
 * the box read from the cache). */
static void triangle_boxes(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 41);
    uint32_t tried = 0, boxes = 0;
    for (uint32_t round = 0; round < 400u && tried < 60u; round++) {
        int32_t span = 1 << test_rng_range(&rng, 4, 20);
        for (uint32_t i = 0; i < 3u; i++) {
            at[i].x = test_rng_range(&rng, 0, span);
            at[i].y = test_rng_range(&rng, 0, span);
        }
        int64_t ux = (int64_t)at[1].x - at[0].x, uy = (int64_t)at[1].y - at[0].y;
        int64_t vx = (int64_t)at[2].x - at[0].x, vy = (int64_t)at[2].y - at[0].y;
        int64_t det = ux * vy - uy * vx;
        /* the same m from each site: every predicate has the same bound */
        int m[3];
        for (uint32_t b = 0; b < 3u; b++) {
            uint32_t spread = 0;
            for (uint32_t k = 0; k < 3u; k++) {
                int64_t dx = (int64_t)at[k].x - at[b].x, dy = (int64_t)at[k].y - at[b].y;
                spread |= (uint32_t)(dx < 0 ? -dx : dx) | (uint32_t)(dy < 0 ? -dy : dy);
            }
            m[b] = bit_length(spread);
        }
        if (det == 0 || m[0] != m[1] || m[1] != m[2]) {
            continue;
        }
        tried++;
        int L = bit_length((uint64_t)(det < 0 ? -det : det)), want = -1;
        for (int e = 0; e <= 30; e++) {
            int E = e + 2, n = (m[0] > E) ? m[0] : E;
            want = (L >= 3 && n + E + 3 <= L - 3) ? e : want;
        }
        start(3);
        move(3, 0, offset(at[0], 1, 0), "triangle box", round);
        move(3, 0, offset(at[0], -1, 0), "triangle box", round); /* sizes the box */
        const struct vor__motion_entry *e = &with.motion[0];
        int got = boxed(0) ? (int)(e->stamp & VOR__BOX_MASK) - 1 : -1;
        boxes += (want >= 0) ? 1u : 0u;
        CHECK(got == want, "triangle (%d, %d) (%d, %d) (%d, %d): box 2^%d, want 2^%d (L %d, m %d)",
              at[0].x, at[0].y, at[1].x, at[1].y, at[2].x, at[2].y, got, want, L, m[0]);
    }
    CHECK(tried >= 60u && boxes >= 20u, "triangle boxes: %u triangles, %u boxes", tried, boxes);
}

/* The derivation's incircle box (src/motion.c, the head comment) for a
 * predicate whose vectors from its base are v[0..3), |P| of bit length L:
 * with moves within 2^E, the crude bound 2^(3 max(m, E) + E + 10) and,
 * for E <= m - 3, the first-order one 2^(max(Lg + E, 2m + 2E + 7) + 1),
 * Lg the bit length bound of the gradient's absolute sum G: exact for
 * vectors below 2^18, else from the vectors cut by k = m - 18 bits,
 * max(3k + bits(G'), 2m + k + 8) + 1. The largest E whose smaller bound
 * stays at or below 2^(L - 3), found by trying each; the box is 2^(E - 2)
 * (-1: none). *which tells the bound that decided (0: crude, 1: the
 * first-order term, 2: its square term, 3: E = m - 3), *cut whether the
 * vectors were cut (1) and the cut's error term made Lg (2). */
static int incircle_terms(int64_t v[3][2], int *m_out, int *cut)
{
    uint64_t spread = 0;
    for (unsigned r = 0; r < 3u; r++) {
        for (unsigned c = 0; c < 2u; c++) {
            spread |= (uint64_t)(v[r][c] < 0 ? -v[r][c] : v[r][c]);
        }
    }
    int m = bit_length(spread), k = (m > 18) ? m - 18 : 0;
    int64_t w[3][2], z[3], cross[3];
    for (unsigned r = 0; r < 3u; r++) {
        for (unsigned c = 0; c < 2u; c++) {
            int64_t a = (v[r][c] < 0 ? -v[r][c] : v[r][c]) >> k;
            w[r][c] = (v[r][c] < 0) ? -a : a;
        }
        z[r] = w[r][0] * w[r][0] + w[r][1] * w[r][1];
    }
    for (unsigned r = 0; r < 3u; r++) {
        unsigned r1 = (r + 1u) % 3u, r2 = (r + 2u) % 3u;
        cross[r] = w[r1][0] * w[r2][1] - w[r1][1] * w[r2][0];
    }
    uint64_t G = 0;
    for (unsigned r = 0; r < 3u; r++) { /* g_a and cyclically */
        unsigned r1 = (r + 1u) % 3u, r2 = (r + 2u) % 3u;
        int64_t gx = 2 * w[r][0] * cross[r] - z[r1] * w[r2][1] + z[r2] * w[r1][1];
        int64_t gy = 2 * w[r][1] * cross[r] + z[r1] * w[r2][0] - z[r2] * w[r1][0];
        G += (uint64_t)(gx < 0 ? -gx : gx) + (uint64_t)(gy < 0 ? -gy : gy);
    }
    int Lg = bit_length(G);
    *cut = (k == 0) ? 0 : (3 * k + Lg <= 2 * m + k + 8) ? 2 : 1;
    if (k > 0) {
        Lg = ((3 * k + Lg > 2 * m + k + 8) ? 3 * k + Lg : 2 * m + k + 8) + 1;
    }
    *m_out = m;
    return Lg;
}

/* The smaller of the two incircle bounds' exponents for moves of 2^E. */
static int incircle_bound(int m, int Lg, int E)
{
    int n = (m > E) ? m : E;
    int crude = 3 * n + E + 10;
    int first = ((Lg + E > 2 * m + 2 * E + 7) ? Lg + E : 2 * m + 2 * E + 7) + 1;
    return (E <= m - 3 && first < crude) ? first : crude;
}

static int incircle_box(int64_t v[3][2], int L, int *which, int *cut)
{
    int m;
    int Lg = incircle_terms(v, &m, cut);
    int best = -100, T = L - 3;
    *which = -1;
    for (int E = -60; E <= 40 && L >= 3; E++) {
        int n = (m > E) ? m : E;
        int crude = 3 * n + E + 10;
        int first = (Lg + E > 2 * m + 2 * E + 7) ? Lg + E : 2 * m + 2 * E + 7;
        bool first_ok = E <= m - 3 && first + 1 <= T;
        if (crude <= T || first_ok) {
            best = E; /* what stops E + 1: */
            *which = (crude <= T && !first_ok) ? 0 : (Lg + E + 2 > T) ? 1
                     : (2 * m + 2 * E + 10 > T) ? 2 : 3;
        }
    }
    return (best - 2 >= 0) ? best - 2 : -1;
}

/* The orientation box (as triangle_boxes) of a, b, c from base a. */
static int orient_box(vor_point_t a, vor_point_t b, vor_point_t c)
{
    uint32_t spread = 0;
    const vor_point_t *p[3] = {&a, &b, &c};
    for (unsigned k = 0; k < 3u; k++) {
        int64_t dx = (int64_t)p[k]->x - a.x, dy = (int64_t)p[k]->y - a.y;
        spread |= (uint32_t)(dx < 0 ? -dx : dx) | (uint32_t)(dy < 0 ? -dy : dy);
    }
    int m = bit_length(spread), want = -1;
    int L = (int)vor__orient2d_bits(&a, &b, &c);
    for (int e = 0; e <= 30; e++) {
        int E = e + 2, n = (m > E) ? m : E;
        want = (L >= 3 && n + E + 3 <= L - 3) ? e : want;
    }
    return want;
}

/* The box of site q in a convex quad a, c, b, q (diagonal a-b), against
 * the derivation: q's predicates are the orientations of triples with q
 * and the incircle test of its triangle (a, b, q) with the far vertex c,
 * whose vectors are taken from c. The quads are chosen so that an
 * orientation never limits q (checked: every orientation of a triple with
 * q, from each base, allows more), so the box is the incircle test's.
 * The radius spans 2^5 to 2^26 and q's distance to the circle 1 to 16R, so
 * that each term of the first-order bound decides in turn (its square
 * term for vectors below 2^18 and q about R away); and tails, q
 * up to 2^28 away from a, b, c within 2^17, whose gradient is small, so
 * that the cut's error term makes Lg; with vectors below and beyond the
 * gradient's 18 bits (white box: the box read from the cache). */
static void quad_boxes(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 43);
    uint32_t tried = 0, decided[4] = {0, 0, 0, 0}, cut = 0, cut_decided = 0;
    for (uint32_t round = 0; round < 12000u && tried < 300u; round++) {
        int32_t R = (int32_t)1 << test_rng_range(&rng, 5, 26);
        int32_t j = R / 8;
        int32_t h = (int32_t)1 << test_rng_range(&rng, 0, bit_length((uint64_t)R) + 2);
        h += test_rng_range(&rng, 0, h);
        if (round % 4u == 2u) { /* small vectors, q about R from the circle: the square term */
            R >>= (R > (1 << 14)) ? 12 : 0;
            j = R / 8;
            h = R / 4 + test_rng_range(&rng, 0, 2 * R);
        }
        vor_point_t a = {-R + test_rng_range(&rng, -j, j), test_rng_range(&rng, -j, j)};
        vor_point_t b = {R + test_rng_range(&rng, -j, j), test_rng_range(&rng, -j, j)};
        vor_point_t c = {test_rng_range(&rng, -j, j), -R + test_rng_range(&rng, 0, R / 2)};
        vor_point_t q = {test_rng_range(&rng, -j, j), R + h};
        if (round % 2u == 1u) { /* a tail: q far from a small a, b, c */
            int32_t F = (int32_t)1 << test_rng_range(&rng, 20, 28);
            R = (int32_t)1 << test_rng_range(&rng, 8, 16);
            j = R / 8;
            a = (vor_point_t){-R + test_rng_range(&rng, -j, j), test_rng_range(&rng, -j, j)};
            b = (vor_point_t){R + test_rng_range(&rng, -j, j), test_rng_range(&rng, -j, j)};
            c = (vor_point_t){test_rng_range(&rng, -j, j), -test_rng_range(&rng, 1, R)};
            q = (vor_point_t){test_rng_range(&rng, -F / 4, F / 4), F};
        }
        /* convex, diagonal a-b: q left of a->b, c right; c outside (b, a, q)'s circle */
        if (vor_orient2d(a, b, q) <= 0 || vor_orient2d(a, b, c) >= 0 ||
            vor_orient2d(c, q, a) * vor_orient2d(c, q, b) >= 0 || vor_incircle(a, b, q, c) >= 0) {
            continue;
        }
        int64_t v[3][2] = {{(int64_t)a.x - c.x, (int64_t)a.y - c.y},
                           {(int64_t)b.x - c.x, (int64_t)b.y - c.y},
                           {(int64_t)q.x - c.x, (int64_t)q.y - c.y}};
        int which;
        int cut_by;
        int want = incircle_box(v, (int)vor__incircle_bits(&a, &b, &q, &c), &which, &cut_by);
        const vor_point_t tri[3][2] = {{a, b}, {b, c}, {c, a}};
        int least = 100;
        for (uint32_t t = 0; t < 3u; t++) {
            int o[3] = {orient_box(q, tri[t][0], tri[t][1]), orient_box(tri[t][0], tri[t][1], q),
                        orient_box(tri[t][1], q, tri[t][0])};
            for (uint32_t k = 0; k < 3u; k++) {
                least = (o[k] < least) ? o[k] : least;
            }
        }
        if (want < 0 || least <= want) {
            continue; /* no box, or an orientation may decide */
        }
        tried++;
        decided[which]++;
        cut += (cut_by > 0) ? 1u : 0u;
        cut_decided += (cut_by == 2) ? 1u : 0u;
        at[0] = a;
        at[1] = b;
        at[2] = c;
        at[3] = q;
        start(4);
        move(4, 3, offset(at[3], 1, 0), "quad box", round);
        move(4, 3, offset(at[3], -1, 0), "quad box", round); /* sizes the box */
        const struct vor__motion_entry *e = &with.motion[3];
        int got = boxed(3) ? (int)(e->stamp & VOR__BOX_MASK) - 1 : -1;
        CHECK(got == want, "quad (%d, %d) (%d, %d) (%d, %d) (%d, %d): box 2^%d, want 2^%d (bound %d)",
              a.x, a.y, b.x, b.y, c.x, c.y, q.x, q.y, got, want, which);
    }
    test_printf("quad boxes: %u quads, decided by the crude bound %u, the first order %u, its "
                "square term %u, m - 3 %u; %u with cut vectors, %u sized by the cut's "
                "error\n",
                tried, decided[0], decided[1], decided[2], decided[3], cut, cut_decided);
    CHECK(tried >= 300u && decided[1] >= 10u && decided[2] >= 3u && cut >= 10u &&
              cut_decided >= 5u,
          "quad boxes: %u quads (crude %u, first order %u, square %u, m - 3 %u, cut %u, by its "
          "error %u)",
          tried, decided[0], decided[1], decided[2], decided[3], cut, cut_decided);
}

/* ------------------------------------------------------------------ */
/* The upkeep of a slow move, against a model (white box)              */

/* The model of what a slow move of an interior site p that keeps the
 * triangles does to the cache (src/motion.c, the head comment): p's
 * predicates as star_still_delaunay evaluates them (per star triangle
 * (p, x, y), counterclockwise from the one in p's home slot: its
 * orientation, the incircle test with the far vertex across x-y, the one
 * with the next neighbour z), each re-proved for the other valid sites
 * free within 2^(e + 1) (E the largest e + 2), voiding them all where
 * the bound exceeds |P| / 4 (bit lengths: bound > L - 2, or L < 2); and,
 * when the move sizes p, p's box: per predicate the largest e the
 * derivation allows (orient_box, incircle_box), or the others' largest
 * e when that is larger (a box they were proven with), the least over
 * the predicates, if it holds a step as long as this one. Sites within
 * 2^20 of the origin: every box is far from the ends of int32. */

/* p's neighbours counterclockwise from the star triangle in its home
 * slot (mesh.h: the one white-box read of the layout); 0 if p is on the
 * hull. */
static uint32_t interior_star(const vor_t *d, uint32_t n, uint32_t p, uint32_t nb[])
{
    uint32_t next[MOTION_SITES], prev[MOTION_SITES], count = 0;
    for (uint32_t s = 0; s < d->max_sites + n - 2u; s++) {
        const vor__tri_t *t = &d->triangles[s];
        unsigned i = vor__vertex_index(t, (vor_index_t)p);
        if ((s < n || s >= d->max_sites) && i < 3u && count < MOTION_SITES) {
            next[count] = vor__vertex(t, vor__next(i));
            prev[count] = vor__vertex(t, vor__prev(i));
            count++;
        }
    }
    const vor__tri_t *home = &d->triangles[p];
    uint32_t v = vor__vertex(home, vor__next(vor__vertex_index(home, (vor_index_t)p)));
    for (uint32_t k = 0; k < count; k++) {
        uint32_t j = 0;
        while (j < count && next[j] != v) {
            j++;
        }
        if (j == count || v == (uint32_t)VOR__INFINITE) {
            return 0;
        }
        nb[k] = v;
        v = prev[j];
    }
    return count;
}

/* The third vertex of the triangle on x-y that is not p's. */
static uint32_t far_vertex(const vor_t *d, uint32_t n, uint32_t p, uint32_t x, uint32_t y)
{
    for (uint32_t s = 0; s < d->max_sites + n - 2u; s++) {
        const vor__tri_t *t = &d->triangles[s];
        if ((s < n || s >= d->max_sites) && vor__vertex_index(t, (vor_index_t)x) < 3u &&
            vor__vertex_index(t, (vor_index_t)y) < 3u && vor__vertex_index(t, (vor_index_t)p) == 3u) {
            uint32_t v[3] = {vor__vertex(t, 0), vor__vertex(t, 1), vor__vertex(t, 2)};
            return (v[0] != x && v[0] != y) ? v[0] : (v[1] != x && v[1] != y) ? v[1] : v[2];
        }
    }
    return (uint32_t)VOR__INFINITE;
}

static bool model_valid(const struct vor__motion_entry *e, uint32_t epoch)
{
    return (e->stamp >> 8) == epoch && (e->stamp & VOR__BOX_MASK) != 0u;
}

/* One predicate of p (an orientation of ids[0 .. 3) from p = ids[0], or
 * the incircle test of ids[0 .. 3) with ids[3], vectors from ids[3]):
 * the re-proof, and p's limit (-1: none). *voids counts voidings. */
static int model_predicate(struct vor__motion_entry *c, uint32_t epoch, uint32_t p,
                           const uint32_t ids[4], unsigned count, bool sizing, uint32_t *voids)
{
    int others = -1;
    for (unsigned k = 0; k < count; k++) {
        if (ids[k] != p && model_valid(&c[ids[k]], epoch)) {
            int e = (int)(c[ids[k]].stamp & VOR__BOX_MASK) - 1;
            others = (e > others) ? e : others;
        }
    }
    if (others < 0 && !sizing) {
        return -1;
    }
    int L, box, bound, E = others + 2;
    if (count == 3u) {
        L = (int)vor__orient2d_bits(&at[ids[0]], &at[ids[1]], &at[ids[2]]);
        box = orient_box(at[ids[0]], at[ids[1]], at[ids[2]]);
        uint32_t spread = 0;
        for (unsigned k = 1; k < 3u; k++) {
            int64_t dx = (int64_t)at[ids[k]].x - at[ids[0]].x;
            int64_t dy = (int64_t)at[ids[k]].y - at[ids[0]].y;
            spread |= (uint32_t)(dx < 0 ? -dx : dx) | (uint32_t)(dy < 0 ? -dy : dy);
        }
        int m = bit_length(spread), n = (m > E) ? m : E;
        bound = n + E + 3;
    } else {
        int64_t v[3][2];
        for (unsigned r = 0; r < 3u; r++) {
            v[r][0] = (int64_t)at[ids[r]].x - at[ids[3]].x;
            v[r][1] = (int64_t)at[ids[r]].y - at[ids[3]].y;
        }
        L = (int)vor__incircle_bits(&at[ids[0]], &at[ids[1]], &at[ids[2]], &at[ids[3]]);
        int which, cut, m;
        box = incircle_box(v, L, &which, &cut);
        int Lg = incircle_terms(v, &m, &cut);
        bound = incircle_bound(m, Lg, E);
    }
    if (others >= 0 && (L < 2 || bound > L - 2)) {
        for (unsigned k = 0; k < count; k++) {
            if (ids[k] != p && model_valid(&c[ids[k]], epoch)) {
                c[ids[k]].stamp &= ~VOR__BOX_MASK;
                c[ids[k]].x = 0;
                c[ids[k]].y = 1;
                (*voids)++;
            }
        }
        others = -1;
    }
    if (L < 3) {
        return -1;
    }
    return (others >= 0 && others > box) ? others : box;
}

/* The cache after p's slow move from `from` (at[] holds the new place),
 * p's entry due to size (sizing) or at its first slow move; its star nb. */
static void model_update(struct vor__motion_entry *c, uint32_t epoch, uint32_t p,
                         vor_point_t from, bool sizing, const uint32_t nb[], uint32_t deg,
                         uint32_t n, uint32_t *voids)
{
    uint32_t level = (c[p].stamp >> 5) & 7u;
    c[p].stamp = level << 5;
    c[p].y = 1;
    uint32_t dx = (uint32_t)(at[p].x > from.x ? at[p].x - from.x : from.x - at[p].x);
    uint32_t dy = (uint32_t)(at[p].y > from.y ? at[p].y - from.y : from.y - at[p].y);
    uint32_t step = (dx > dy) ? dx : dy;
    int need = 0;
    while (((uint64_t)1 << need) < step) { /* the least 2^need >= step */
        need++;
    }
    int limit = 30;
    for (uint32_t k = 0; k < deg; k++) {
        uint32_t x = nb[k], y = nb[(k + 1u) % deg], z = nb[(k + 2u) % deg];
        uint32_t far = far_vertex(&with, n, p, x, y);
        const uint32_t tri[4] = {p, x, y, far}, turn[4] = {p, x, y, z};
        int l = model_predicate(c, epoch, p, tri, 3u, sizing && limit >= need, voids);
        limit = (l < limit) ? l : limit;
        if (far != (uint32_t)VOR__INFINITE) {
            l = model_predicate(c, epoch, p, tri, 4u, sizing && limit >= need, voids);
            limit = (l < limit) ? l : limit;
        }
        l = model_predicate(c, epoch, p, turn, 4u, sizing && limit >= need, voids);
        limit = (l < limit) ? l : limit;
    }
    if (sizing && limit >= need) {
        c[p].x = at[p].x;
        c[p].y = at[p].y;
        c[p].stamp = (epoch << 8) | (level << 5) | (uint32_t)(limit + 1);
    } else if (sizing) {
        level += (level < 5u) ? 1u : 0u;
        c[p].x = (int32_t)(1u << level);
        c[p].stamp = level << 5;
    }
}

/* Random small diagrams, an interior site p moved by a step that keeps
 * the triangles, with boxes planted around it: valid ones of random
 * sizes (most of them larger than the derivation would give, so that
 * the re-proof has something to void), stale ones (an older epoch) and
 * current entries without a box counting down their backoff, which the
 * move must leave alone; p due to size its box or at its first slow
 * move. Every entry afterwards must be the model's. */
static void slow_move_upkeep(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 47);
    static struct vor__motion_entry model[MOTION_SITES];
    uint32_t tried = 0, voids = 0, kept = 0, sized = 0, unsized = 0;
    for (uint32_t round = 0; round < 20000u && tried < 1500u; round++) {
        uint32_t n = 5u + test_rng_u32(&rng) % 8u;
        int bits = test_rng_range(&rng, 2, 20);
        int32_t span = (int32_t)1 << bits;
        for (uint32_t i = 0; i < n; i++) {
            do {
                at[i].x = test_rng_range(&rng, 0, span);
                at[i].y = test_rng_range(&rng, 0, span);
            } while (site_at(i, at[i]) != VOR_NO_HINT);
        }
        start(n);
        uint32_t p = test_rng_u32(&rng) % n, nb[MOTION_SITES];
        uint32_t deg = interior_star(&with, n, p, nb);
        if (deg == 0u) {
            continue;
        }
        uint32_t epoch = with.motion_epoch;
        for (uint32_t i = 0; i < n; i++) {
            struct vor__motion_entry *e = &with.motion[i];
            uint32_t kind = test_rng_u32(&rng) % 8u;
            int most = (kind < 2u) ? bits + 2 : (bits > 12) ? bits - 12 : 0;
            uint32_t size = 1u + (uint32_t)test_rng_range(&rng, 0, most);
            e->x = at[i].x;
            e->y = at[i].y;
            e->stamp = (kind < 4u) ? ((epoch << 8) | ((kind & 1u) << 6) | size) /* valid */
                       : (kind == 4u) ? ((((epoch - 1u) & VOR__EPOCH_MASK) << 8) | size) /* stale */
                       : (kind == 5u) ? ((epoch << 8) | (2u << 5))                   /* waiting */
                                      : 0u;                                          /* none */
            if (kind == 5u) {
                e->x = 3;
                e->y = 1;
            }
        }
        bool sizing = test_rng_u32(&rng) % 2u == 0u;
        with.motion[p].x = 0;
        with.motion[p].y = sizing ? 1 : 0;
        with.motion[p].stamp = 0;
        for (uint32_t i = 0; i < n; i++) {
            model[i] = with.motion[i];
        }
        vor_point_t from = at[p];
        int32_t reach = (int32_t)1 << test_rng_range(&rng, 0, (bits > 4) ? bits - 4 : 0);
        vor_point_t to = offset(from, test_rng_range(&rng, -reach, reach),
                                test_rng_range(&rng, -reach, reach));
        if (site_at(n, to) != VOR_NO_HINT) {
            continue;
        }
        move(n, p, to, "upkeep", round);
        if (with.motion_epoch != epoch) {
            continue; /* the triangles changed: every entry void */
        }
        tried++;
        uint32_t before = voids;
        model_update(model, epoch, p, from, sizing, nb, deg, n, &voids);
        kept += (voids == before) ? 1u : 0u;
        sized += (sizing && (model[p].stamp & VOR__BOX_MASK) != 0u) ? 1u : 0u;
        unsized += (sizing && (model[p].stamp & VOR__BOX_MASK) == 0u) ? 1u : 0u;
        for (uint32_t i = 0; i < n; i++) {
            const struct vor__motion_entry *e = &with.motion[i];
            if (!CHECK(e->x == model[i].x && e->y == model[i].y && e->stamp == model[i].stamp,
                       "upkeep %u: site %u of %u (p %u, %s) entry (%d, %d, %x), the model's "
                       "(%d, %d, %x)",
                       round, i, n, p, sizing ? "sizing" : "first move", e->x, e->y, e->stamp,
                       model[i].x, model[i].y, model[i].stamp)) {
                return;
            }
        }
    }
    test_printf("slow move upkeep: %u moves, %u voidings, %u moves voiding none, p sized %u "
                "times, %u times not\n",
                tried, voids, kept, sized, unsized);
    CHECK(tried >= 1500u && voids >= 1000u && kept >= 150u && sized >= 100u && unsized >= 300u,
          "upkeep: %u moves, %u voidings, %u none, %u sized, %u not", tried, voids, kept, sized,
          unsized);
}

/* One or two sites have no finite triangle, so no box (the twin
 * argument in src/motion.c needs one): slow moves size nothing. Also a
 * diagram of at most one site, whose arena (exactly VOR_ARENA_BYTES(1))
 * has no triangle slot for the upkeep to read. */
static void few_sites(void)
{
    at[0] = (vor_point_t){0, 0};
    at[1] = (vor_point_t){1000000, 0};
    for (uint32_t n = 1; n <= 2u; n++) {
        start(n);
        for (uint32_t step = 0; step < 6u; step++) {
            uint32_t i = step % n;
            move(n, i, offset(at[i], (step < 2u) ? 1 : -1, 0), "few sites", step);
        }
        /* and no sizing was tried, so the backoff stays at its start */
        CHECK(!boxed(0) && !boxed(1) && with.motion[0].stamp == 0u && with.motion[0].x == 0 &&
                  with.motion[n - 1u].stamp == 0u && with.motion[n - 1u].x == 0,
              "%u sites: entries (%d, %x) (%d, %x)", n, with.motion[0].x, with.motion[0].stamp,
              with.motion[1].x, with.motion[1].stamp);
    }
    static uint8_t one_arena[VOR_ARENA_BYTES(1)] __attribute__((aligned(8)));
    static uint8_t one_cache[VOR_MOTION_BYTES(1)] __attribute__((aligned(8)));
    vor_t one;
    uint32_t id = 1;
    bool ok = vor_init(&one, one_arena, sizeof one_arena, 1) == VOR_OK &&
              vor_motion_attach(&one, one_cache, sizeof one_cache) == VOR_OK &&
              vor_insert(&one, (vor_point_t){5, 5}, &id) == VOR_OK && id == 0u;
    for (int32_t step = 1; step <= 4; step++) {
        ok = ok && vor_move(&one, 0, (vor_point_t){5 + step, 5}, NULL) == VOR_OK;
    }
    CHECK(ok && (one.motion[0].stamp & VOR__BOX_MASK) == 0u && one.sites[0].x == 9,
          "one site of one: moves %s, stamp %x", ok ? "done" : "failed", one.motion[0].stamp);
}

/* A hull site whose hull test across its hull edge p-y has |P| below 4:
 * y lies 1 / 2,000,001 of the way off the line from p to x (|P| = 1 at
 * p = (0, 0), 2 at (1, 0)), q makes the triangles fat. p's orientation
 * and incircle tests allow a box; the hull test allows none, so p,
 * sized at its second slow move, gets none. */
static void hull_sliver(void)
{
    at[0] = (vor_point_t){1, 0};        /* p */
    at[1] = (vor_point_t){1000000, 1};  /* y */
    at[2] = (vor_point_t){2000001, 2};  /* x */
    at[3] = (vor_point_t){1000000, -1000000};
    start(4);
    uint32_t epoch = with.motion_epoch;
    move(4, 0, (vor_point_t){0, 0}, "hull sliver", 0);
    move(4, 0, (vor_point_t){1, 0}, "hull sliver", 1); /* sizes */
    CHECK(with.motion_epoch == epoch && !boxed(0) && ((with.motion[0].stamp >> 5) & 7u) == 1u,
          "hull sliver: epoch %u of %u, entry %x", with.motion_epoch, epoch, with.motion[0].stamp);
}

/* A hull site p adjacent to every other site: its star has as many
 * triangles as the mesh has sites, and the walks over it (star_boxed's
 * and the upkeep's) must reach the last. a, b, c lie on a circle of
 * radius 10^6; p, 1 below the middle of chord a-c and deep inside the
 * circle, takes the diagonal to b. Its one tight predicate is the
 * orientation of (p, a, c), |P| = 2 or 4, tested across the hull edge
 * p-a; every other predicate allows a box. For each of the 24 orders of
 * ids (each lays the star out from another home triangle):
 * - p sized at its second slow move gets no box;
 * - a box planted far too large on a neighbour q is voided by p's first
 *   slow move (every predicate with q fails). */
static void hull_star(void)
{
    const vor_point_t a = {-1000000, -1}, c = {1000000, 1}, b = {0, 1000000}, p = {1, 0};
    const vor_point_t four[4] = {a, b, c, p};
    uint32_t checked = 0;
    for (uint32_t order = 0; order < 24u; order++) {
        uint32_t id[4] = {0, 1, 2, 3}, rest = order;
        for (uint32_t k = 0; k < 4u; k++) { /* the order-th permutation */
            uint32_t pick = k + rest % (4u - k), t = id[k];
            rest /= 4u - k;
            id[k] = id[pick];
            id[pick] = t;
        }
        for (uint32_t q = 0; q < 4u; q++) { /* q == 3: p sized */
            for (uint32_t k = 0; k < 4u; k++) {
                at[id[k]] = four[k];
            }
            start(4);
            uint32_t epoch = with.motion_epoch;
            if (q < 3u) {
                struct vor__motion_entry *e = &with.motion[id[q]];
                e->x = at[id[q]].x;
                e->y = at[id[q]].y;
                e->stamp = (epoch << 8) | 26u; /* 2^25 */
            }
            move(4, id[3], offset(p, 1, 0), "hull star", order);
            if (q == 3u) {
                move(4, id[3], p, "hull star", order);
            }
            if (!CHECK(with.motion_epoch == epoch, "hull star %u: the triangles changed", order)) {
                return;
            }
            CHECK(q == 3u ? !boxed(id[3]) : !boxed(id[q]),
                  "hull star, ids %u %u %u %u: %s", id[0], id[1], id[2], id[3],
                  q == 3u ? "p took a box" : "a box too large kept");
            checked++;
        }
    }
    CHECK(checked == 96u, "hull star: %u cases", checked);
}

/* A move that brings a line close to a boxed site must void its box:
 * site 1 moves so that the line of sites 0 and 1 passes just inside the
 * reach of site 2's box (|P| at least 2^(m + e), well below what the
 * derivation allows for the box, 2^(m + e + 6)); the jump of site 2 to the
 * corner across the line must then be slow and exact. Site 2 starts
 * `below` under the line's midpoint: 16384 gives it a box of 2^6, 200 one
 * of 2^0. */
static void line_comes_close(int32_t below)
{
    const int32_t B = 65535; /* vectors of m = 16 bits */
    at[0] = (vor_point_t){0, 0};
    at[1] = (vor_point_t){B, B};
    at[2] = (vor_point_t){32768, 32768 - below};
    start(3);
    move(3, 2, offset(at[2], 1, 0), "line settles", 0);
    move(3, 2, offset(at[2], -1, 0), "line settles", 1);
    if (!CHECK(boxed(2), "line: site 2 has no box (a test that cannot fail)")) {
        return;
    }
    const struct vor__motion_entry *e = &with.motion[2];
    int exponent = (int)(e->stamp & VOR__BOX_MASK) - 1;
    int32_t r = (int32_t)(1u << exponent);
    vor_point_t q = {e->x, e->y}, corner = offset(q, -r, r);
    int64_t reach = (int64_t)1 << (16 + exponent);
    int32_t s = 0;
    for (; s < B; s++) { /* site 1 lowered by s */
        vor_point_t b = {B, B - s};
        int64_t ux = b.x, uy = b.y;
        int64_t P = ux * q.y - uy * q.x; /* orient(site 0, b, q), site 0 at the origin */
        if ((P < 0 ? -P : P) < reach) {
            break; /* no such place */
        }
        if (vor_orient2d(at[0], b, corner) != vor_orient2d(at[0], b, q)) {
            break;
        }
    }
    vor_point_t b = {B, B - s};
    CHECK(s < B && vor_orient2d(at[0], b, corner) != vor_orient2d(at[0], b, q) &&
              exponent == ((below > 1000) ? 6 : 0),
          "line: box 2^%d, no place for site 1", exponent);
    move(3, 1, b, "line comes close", 0);
    CHECK(!move(3, 2, corner, "line: the corner across", 0),
          "line: the jump of site 2 across the line was fast");
    /* site 1 lowered by s + 1 - 2^j instead, close to far: site 2's box is
     * kept exactly when the orientation's bound for moves of 2^(e + 2),
     * 2^(max(m, E) + E + 3), stays at or below 2^(L - 2) (the one
     * predicate of three sites, from whichever base: the cases where
     * the bases disagree, or the line passes site 2, are skipped) */
    uint32_t kept = 0, voided = 0;
    for (int j = 0; j < 16; j++) {
        at[0] = (vor_point_t){0, 0};
        at[1] = (vor_point_t){B, B};
        at[2] = (vor_point_t){32768, 32768 - below};
        start(3);
        move(3, 2, offset(at[2], 1, 0), "line settles", 0);
        move(3, 2, offset(at[2], -1, 0), "line settles", 1);
        int E = (int)(e->stamp & VOR__BOX_MASK) + 1; /* e + 2 */
        if (s - (1 << j) + 1 < 0) {
            break;
        }
        vor_point_t low = {B, B - (s - (1 << j) + 1)};
        int side = vor_orient2d(at[0], at[1], at[2]);
        move(3, 1, low, "line lowered", (uint32_t)j);
        /* past site 2 the triangle turns: a new epoch voids every box */
        int keep = (vor_orient2d(at[0], at[1], at[2]) != side) ? 2 : -1;
        for (uint32_t k = 0; k < 3u && keep != 2; k++) {
            vor_point_t o = at[k], u = at[(k + 1u) % 3u], w = at[(k + 2u) % 3u];
            uint32_t spread = 0;
            for (uint32_t i = 0; i < 3u; i++) {
                int64_t dx = (int64_t)at[i].x - o.x, dy = (int64_t)at[i].y - o.y;
                spread |= (uint32_t)(dx < 0 ? -dx : dx) | (uint32_t)(dy < 0 ? -dy : dy);
            }
            int m = bit_length(spread), n = (m > E) ? m : E;
            int L = (int)vor__orient2d_bits(&o, &u, &w);
            int here = (L >= 2 && n + E + 3 <= L - 2) ? 1 : 0;
            keep = (keep == -1 || keep == here) ? here : 2;
        }
        if (keep != 2) {
            kept += (keep == 1) ? 1u : 0u;
            voided += (keep == 0) ? 1u : 0u;
            CHECK(boxed(2) == (keep == 1), "line lowered by 2^%d: box of site 2 %s, the bound %s it",
                  j, boxed(2) ? "kept" : "voided", (keep == 1) ? "keeps" : "voids");
        }
    }
    CHECK(kept > 0u && voided > 0u, "line: %u boxes kept, %u voided (a test that cannot fail)",
          kept, voided);
}

/* The incircle test's counterpart of line_comes_close: site 2 moves up so
 * that the circle through sites 0, 1, 2 comes within 64 heights of site
 * 3, which holds a box (and to heights 2^j below those); at each height
 * every corner jump of site 3 must be exact (a box the circle now reaches
 * must have been voided by site 2's move, the far vertex's re-proof), and
 * the box must be kept exactly when the derivation's bound allows it. With the circle's radius R near
 * 2^25 and a small box, the first-order term decides the re-proof. */
static void circle_comes_close(int32_t R, int32_t h)
{
    const vor_point_t a = {-R, 0}, b = {R, 0}, q0 = {0, R + h};
    /* the first height of site 2 whose circle holds site 3 (b, a, c
     * counterclockwise: > 0 inside) */
    int32_t reach = 0;
    while (reach < R && vor_incircle(b, a, (vor_point_t){0, -R + reach}, q0) < 0) {
        reach++;
    }
    uint32_t crossing = 0, reproved = 0, voided = 0;
    for (int32_t i = 0; i < 64 + 24; i++) {
        /* the 64 heights below reach, then farther ones, where boxes stay */
        int32_t t = (i < 64) ? reach - 64 + i : reach - 64 - ((int32_t)1 << (i - 64));
        if (t < -R / 2) {
            break;
        }
        at[0] = a;
        at[1] = b;
        at[2] = (vor_point_t){0, -R};
        at[3] = q0;
        start(4);
        move(4, 3, offset(at[3], 1, 0), "circle settles", 0);
        move(4, 3, offset(at[3], -1, 0), "circle settles", 1);
        if (!CHECK(boxed(3), "circle: site 3 has no box (a test that cannot fail)")) {
            return;
        }
        const struct vor__motion_entry *e = &with.motion[3];
        int32_t r = (int32_t)(1u << ((e->stamp & VOR__BOX_MASK) - 1u));
        vor_point_t q = {e->x, e->y}, c = {0, -R + t};
        int E = (int)(e->stamp & VOR__BOX_MASK) + 1; /* e + 2 */
        move(4, 2, c, "circle comes close", (uint32_t)t);
        /* site 2's move re-proves site 3's box for the incircle test with
         * site 3 the far vertex (vectors from it) and the orientations of
         * triples with both: kept exactly when every bound for moves of
         * 2^(e + 2) stays at or below 2^(L - 2), here decided by the
         * incircle test (the orientations' bounds, from every base, are
         * checked to allow it) */
        int64_t v[3][2] = {{(int64_t)a.x - q.x, (int64_t)a.y - q.y},
                           {(int64_t)b.x - q.x, (int64_t)b.y - q.y},
                           {(int64_t)c.x - q.x, (int64_t)c.y - q.y}};
        int m, cut;
        int Lg = incircle_terms(v, &m, &cut), L = (int)vor__incircle_bits(&a, &b, &c, &q);
        bool kept = L >= 2 && incircle_bound(m, Lg, E) <= L - 2;
        bool orientations = true;
        const vor_point_t other[2] = {a, b};
        for (uint32_t k = 0; k < 2u; k++) {
            const vor_point_t tri[3] = {q, c, other[k]};
            for (uint32_t base = 0; base < 3u; base++) {
                vor_point_t o = tri[base], u = tri[(base + 1u) % 3u], w = tri[(base + 2u) % 3u];
                uint32_t spread = 0;
                for (uint32_t j = 0; j < 3u; j++) {
                    int64_t dx = (int64_t)tri[j].x - o.x, dy = (int64_t)tri[j].y - o.y;
                    spread |= (uint32_t)(dx < 0 ? -dx : dx) | (uint32_t)(dy < 0 ? -dy : dy);
                }
                int mo = bit_length(spread), n = (mo > E) ? mo : E;
                int Lo = (int)vor__orient2d_bits(&o, &u, &w);
                orientations = orientations && Lo >= 2 && n + E + 3 <= Lo - 2;
            }
        }
        if (orientations) {
            reproved++;
            voided += kept ? 0u : 1u;
            CHECK(boxed(3) == kept, "circle at height %d: box of site 3 %s, the bound %s it", t,
                  boxed(3) ? "kept" : "voided", kept ? "keeps" : "voids");
        }
        static const int32_t sign[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
        unsigned long failures = test_failures();
        for (uint32_t k = 0; k < 4u && test_failures() == failures; k++) {
            vor_point_t corner = offset(q, sign[k][0] * r, sign[k][1] * r);
            crossing += (vor_incircle(b, a, c, corner) >= 0) ? 1u : 0u;
            move(4, 3, corner, "circle: a corner", (uint32_t)t);
            move(4, 3, q, "circle: back", (uint32_t)t);
        }
        if (test_failures() != failures) {
            break;
        }
    }
    CHECK(reach > 64 && reach < R && crossing > 0u && reproved >= 32u && voided > 0u &&
              voided < reproved,
          "circle: reached at %d, %u corners inside, %u boxes re-proved, %u voided (a test "
          "that cannot fail)",
          reach, crossing, reproved, voided);
}

void test_motion(void)
{
    /* tiny steps (1/10,000 of the spacing, about 144,000, or less) on
     * uniform sites: mostly fast, the first two moves of each site aside
     * (the backoff sizes no box at a site's first slow move) */
    TEST_CASE("uniform_steps") {
        uint32_t steps = 600;
        uint32_t fast = walk(11, MOTION_SITES, 1000000, 1, 14, steps, "uniform tiny steps");
        CHECK(fast * 2u > steps - 2u * MOTION_SITES, "tiny steps: %u of %u moves fast", fast,
              steps);
        uint32_t unit = walk(12, MOTION_SITES, 1000000, 1, 1, steps, "uniform unit steps");
        CHECK(unit * 4u > steps * 3u, "unit steps: %u of %u moves fast", unit, steps);
        test_printf("motion cache: %u of %u tiny steps fast, %u of %u unit steps\n", fast,
                    steps, unit, steps);
    }
    /* steps from tiny to large, some changing triangles */
    TEST_CASE("mixed_steps") {
        walk(13, MOTION_SITES, 20000, 1, 0, 400, "uniform mixed steps");
        walk(14, 40, 100, 1, 0, 300, "crowded mixed steps");
    }
    /* grids: collinear and cocircular sites everywhere */
    TEST_CASE("grids") {
        uint32_t grid = walk(15, 36, 7, 4096, 1, 300, "grid unit steps");
        walk(16, 36, 7, 16, 0, 300, "grid mixed steps");
        walk(17, 30, 5, 3, 1, 300, "dense grid");
        /* on a grid every quad is cocircular: boxes only once the walk has
         * broken the ties */
        CHECK(grid > 0u, "grid: no fast move (a test that cannot fail)");
    }
    /* sites near circles: the predicates' magnitudes are small, the
     * boxes tight */
    TEST_CASE("corners") {
        corners(18, MOTION_SITES, 4000000, 50, 16, "corners, near circles");
        corners(19, MOTION_SITES, 400000000, 3, 1, "corners, nearly cocircular");
        corners(20, MOTION_SITES, 40000, 0, 24, "corners, small coordinates");
    }
    TEST_CASE("degenerate_walks") degenerate_walks();
    TEST_CASE("backoff") backoff();
    TEST_CASE("api_safety") api_safety();
    TEST_CASE("full_range") full_range();
    TEST_CASE("neighbour_moves_in") neighbour_moves_in();
    TEST_CASE("box_at_range_end") {
        box_at_range_end(100);
        box_at_range_end(64);
        box_at_range_end(0);
    }
    TEST_CASE("triangle_boxes") triangle_boxes();
    TEST_CASE("quad_boxes") quad_boxes();
    TEST_CASE("slow_move_upkeep") slow_move_upkeep();
    TEST_CASE("few_sites") few_sites();
    TEST_CASE("hull_star") hull_star();
    TEST_CASE("hull_sliver") hull_sliver();
    TEST_CASE("line_comes_close") {
        line_comes_close(16384);
        line_comes_close(200);
    }
    TEST_CASE("circle_comes_close") {
        circle_comes_close(30000, 3000);
        circle_comes_close(3000, 2000); /* q's box large: the square term decides */
        circle_comes_close(30720000, 1000);
        circle_comes_close(30720000, 6000);
    }
}
