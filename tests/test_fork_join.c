/* SPDX-License-Identifier: MIT */
/*
 * test_fork_join.c - vor_build_dc_forked against vor_build_dc. The hooks
 * here run on one core, in three ways: the work at once inside fork; the
 * work deferred to join, so that the calling core's half is built before
 * the forked one (the halves must not depend on each other); and a fork
 * that refuses, so that vor runs the work itself. For every input family
 * and both splits the forked diagram must be byte for byte the one
 * vor_build_dc makes in an arena filled the same way: the home slots of
 * all ids, the packed extra slots, the sites, the bucket grid, the counts,
 * last_site, duplicate_of and the sums of the predicate statistics; and
 * vor_validate must pass. Whether the hook is called at all follows from
 * how each input is made (its size against VOR_DC_FORK_MIN_SITES_DEFAULT, and
 * which halves of the grid it fills), never from the library.
 */
#include "test.h"
#include "vor.h"

#define FJ_SITES 3000u
typedef char fj_sites_check[(FJ_SITES > VOR_DC_FORK_MIN_SITES_DEFAULT + 1u) ? 1 : -1];

static vor_point_t points[FJ_SITES];
static uint32_t dup_seq[FJ_SITES], dup_fork[FJ_SITES];
static uint8_t arena_seq[VOR_ARENA_BYTES(FJ_SITES)] __attribute__((aligned(8)));
static uint8_t arena_fork[VOR_ARENA_BYTES(FJ_SITES)] __attribute__((aligned(8)));

enum hook_mode { HOOK_AT_ONCE, HOOK_AT_JOIN, HOOK_REFUSES, HOOK_MODES };
static const char *const mode_names[HOOK_MODES] = {"at once", "at join", "refusing"};

typedef struct {
    enum hook_mode mode;
    unsigned forks, joins, runs;
    void (*work)(void *arg); /* deferred to join */
    void *arg;
} test_hook_t;

static int hook_fork(void *context, void (*work)(void *arg), void *arg)
{
    test_hook_t *h = context;
    h->forks++;
    if (h->mode == HOOK_REFUSES) {
        return 1;
    }
    if (h->mode == HOOK_AT_ONCE) {
        h->runs++;
        work(arg);
    } else {
        h->work = work;
        h->arg = arg;
    }
    return 0;
}

static void hook_join(void *context)
{
    test_hook_t *h = context;
    h->joins++;
    if (h->work != NULL) {
        void (*work)(void *arg) = h->work;
        h->work = NULL;
        h->runs++;
        work(h->arg);
    }
}

enum family {
    F_DUPLICATES, /* 64 x 64 lattice points: duplicates in every half */
    F_UNIFORM,    /* the whole int32 range */
    F_GRID,       /* 32 columns, at least as many rows: cocircular everywhere */
    F_LINE,       /* all collinear, in both halves */
    F_CLUSTERS,   /* six tight clusters */
    F_FLAT,       /* a wide flat strip: the quadtree's midline cuts it lengthwise */
    F_TOP,        /* two sites in the bottom half of the grid, the rest on top */
    F_FAMILIES
};
static const char *const family_names[F_FAMILIES] = {"duplicates", "uniform", "grid", "line",
                                                     "clusters",   "flat",    "top"};

static void make_family(enum family f, uint32_t n, test_rng_t *rng)
{
    for (uint32_t i = 0; i < n; i++) {
        vor_point_t *p = &points[i];
        switch (f) {
        case F_DUPLICATES:
            p->x = test_rng_range(rng, 0, 63);
            p->y = test_rng_range(rng, 0, 63);
            break;
        case F_UNIFORM:
            p->x = (int32_t)test_rng_u32(rng);
            p->y = (int32_t)test_rng_u32(rng);
            break;
        case F_GRID:
            p->x = (int32_t)(i % 32u) * 7;
            p->y = (int32_t)(i / 32u) * 7;
            break;
        case F_LINE: /* on y = 2x, in two bunches at its ends */
            p->x = (int32_t)i + ((i < n / 2u) ? 0 : 500000);
            p->y = 2 * p->x;
            break;
        case F_CLUSTERS: {
            int32_t cx = (int32_t)(i % 6u) * 100000, cy = (int32_t)((i % 6u) * 37u % 5u) * 90000;
            p->x = cx + test_rng_range(rng, -200, 200) + test_rng_range(rng, -200, 200);
            p->y = cy + test_rng_range(rng, -200, 200) + test_rng_range(rng, -200, 200);
            break;
        }
        case F_FLAT:
            p->x = test_rng_range(rng, 0, 1000000);
            p->y = test_rng_range(rng, 0, 1000);
            break;
        case F_TOP:
        default:
            p->x = test_rng_range(rng, 0, 1000000);
            p->y = (i < 2u) ? (int32_t)i : test_rng_range(rng, 900000, 1000000);
            break;
        }
    }
}

static void fill(uint8_t *to, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        to[i] = (uint8_t)(i * 131u + 7u);
    }
}

static bool same_stats(const vor_t *da, const vor_t *db)
{
    vor_stats_t sa, sb;
    if (vor_stats(da, &sa) != VOR_OK || vor_stats(db, &sb) != VOR_OK) {
        return false;
    }
    const vor_stats_t *a = &sa, *b = &sb;
    bool same = a->orient2d_perturbed == b->orient2d_perturbed &&
                a->incircle_perturbed == b->incircle_perturbed &&
                a->closer_perturbed == b->closer_perturbed && a->power == b->power &&
                a->power_perturbed == b->power_perturbed;
    for (unsigned t = 0; t < VOR_TIERS; t++) {
        same &= a->orient2d[t] == b->orient2d[t] && a->incircle[t] == b->incircle[t] &&
                a->closer[t] == b->closer[t];
    }
    return same;
}

/* Everything a build writes that a later call reads, compared byte for
 * byte: home slots of every id (duplicates' included), the packed extra
 * slots, the sites, the grid and the counts. */
static const char *first_difference(const vor_t *a, const vor_t *b, uint32_t n)
{
    const uint8_t *ta = (const uint8_t *)a->triangles, *tb = (const uint8_t *)b->triangles;
    if (a->vertex_count != b->vertex_count || a->site_count != b->site_count) {
        return "counts";
    }
    if (a->last_site != b->last_site) {
        return "last_site";
    }
    if (!test_same_bytes(ta, tb, (size_t)n * VOR_TRIANGLE_BYTES)) {
        return "home slots";
    }
    uint32_t extras = (a->vertex_count >= 2u) ? a->vertex_count - 2u : 0u;
    size_t from = (size_t)a->max_sites * VOR_TRIANGLE_BYTES;
    if (!test_same_bytes(ta + from, tb + from, (size_t)extras * VOR_TRIANGLE_BYTES)) {
        return "extra slots";
    }
    if (!test_same_bytes(a->sites, b->sites, (size_t)n * sizeof(vor_point_t))) {
        return "sites";
    }
    if (a->bucket_columns != b->bucket_columns || a->bucket_rows != b->bucket_rows ||
        a->bucket_scale != b->bucket_scale || a->bucket_origin.x != b->bucket_origin.x ||
        a->bucket_origin.y != b->bucket_origin.y || a->low.x != b->low.x ||
        a->low.y != b->low.y || a->high.x != b->high.x || a->high.y != b->high.y ||
        !test_same_bytes(a->buckets, b->buckets,
                    (size_t)a->bucket_columns * a->bucket_rows * sizeof(vor_index_t))) {
        return "bucket grid";
    }
    if (!same_stats(a, b)) {
        return "predicate stats";
    }
    if (!test_same_bytes(dup_seq, dup_fork, (size_t)n * sizeof(uint32_t))) {
        return "duplicate_of";
    }
    return NULL;
}

/* Does the input give both halves at least three ids, so that the build
 * forks? From how the families are made: the quadtree's square is centred
 * on the sites' box, so its midline halves the box's height; F_TOP puts
 * two sites below it and the rest far above; the others fill both halves
 * by far (uniform in a box, or a grid, line, clusters or strip reaching
 * across the middle); the x-split's halves are always full (many distinct
 * sites). */
static bool expect_fork(enum family f, uint32_t n, enum vor_dc_split split)
{
    if (n < VOR_DC_FORK_MIN_SITES_DEFAULT) {
        return false;
    }
    return split == VOR_DC_XSPLIT || f != F_TOP;
}

static void check_family(enum family f, uint32_t n, test_rng_t *rng)
{
    make_family(f, n, rng);
    for (unsigned split = VOR_DC_QUADTREE; split <= VOR_DC_XSPLIT; split++) {
        vor_t seq;
        fill(arena_seq, sizeof arena_seq);
        CHECK(vor_init(&seq, arena_seq, sizeof arena_seq, FJ_SITES) == VOR_OK, "init");
        CHECK(vor_build_dc(&seq, points, n, TEST_SPLIT(split), dup_seq) == VOR_OK,
              "build_dc");
        for (unsigned m = 0; m < HOOK_MODES; m++) {
            test_hook_t h = {(enum hook_mode)m, 0, 0, 0, NULL, NULL};
            vor_fork_join_t hook = {hook_fork, hook_join, &h};
            vor_t d;
            fill(arena_fork, sizeof arena_fork);
            CHECK(vor_init(&d, arena_fork, sizeof arena_fork, FJ_SITES) == VOR_OK, "init");
            CHECK(vor_build_dc_forked(&d, points, n, TEST_SPLIT(split), dup_fork,
                                      &hook) == VOR_OK,
                  "build_dc_forked");
            const char *diff = first_difference(&seq, &d, n);
            vor_violation_t v;
            int valid = vor_validate(&d, &v);
            CHECK(diff == NULL && valid == VOR_OK,
                  "%s, %u sites, split %u, hook %s: %s differ, validate %d (check %u)",
                  family_names[f], n, split, mode_names[m], (diff != NULL) ? diff : "none",
                  valid, (unsigned)v.check);
            unsigned forks = expect_fork(f, n, (enum vor_dc_split)split) ? 1u : 0u;
            unsigned joins = (m == HOOK_REFUSES) ? 0u : forks;
            CHECK(h.forks == forks && h.joins == joins && h.runs == joins && h.work == NULL,
                  "%s, %u sites, split %u, hook %s: %u forks, %u joins, %u runs (want %u, %u)",
                  family_names[f], n, split, mode_names[m], h.forks, h.joins, h.runs, forks,
                  joins);
        }
    }
}

/* A hook NULL is vor_build_dc, whatever n. */
static void check_no_hook(test_rng_t *rng)
{
    make_family(F_DUPLICATES, FJ_SITES, rng);
    vor_t seq, d;
    fill(arena_seq, sizeof arena_seq);
    fill(arena_fork, sizeof arena_fork);
    CHECK(vor_init(&seq, arena_seq, sizeof arena_seq, FJ_SITES) == VOR_OK &&
              vor_init(&d, arena_fork, sizeof arena_fork, FJ_SITES) == VOR_OK,
          "init");
    CHECK(vor_build_dc(&seq, points, FJ_SITES, NULL, dup_seq) == VOR_OK &&
              vor_build_dc_forked(&d, points, FJ_SITES, NULL, dup_fork, NULL) ==
                  VOR_OK,
          "builds");
    const char *diff = first_difference(&seq, &d, FJ_SITES);
    CHECK(diff == NULL, "no hook: %s differ", (diff != NULL) ? diff : "none");
}

/* options->fork_min_sites moves the threshold: uniform sites fork from
 * exactly that many on, with vor_build_dc's result. */
static void check_fork_min(test_rng_t *rng)
{
    for (uint32_t n = 99; n <= 100u; n++) {
        make_family(F_UNIFORM, n, rng);
        vor_t seq, d;
        fill(arena_seq, sizeof arena_seq);
        fill(arena_fork, sizeof arena_fork);
        test_hook_t h = {HOOK_AT_ONCE, 0, 0, 0, NULL, NULL};
        vor_fork_join_t hook = {hook_fork, hook_join, &h};
        vor_build_options_t options = {VOR_ORDER_QUADTREE, VOR_DC_XSPLIT, 100};
        CHECK(vor_init(&seq, arena_seq, sizeof arena_seq, FJ_SITES) == VOR_OK &&
                  vor_init(&d, arena_fork, sizeof arena_fork, FJ_SITES) == VOR_OK,
              "init");
        CHECK(vor_build_dc(&seq, points, n, &options, dup_seq) == VOR_OK &&
                  vor_build_dc_forked(&d, points, n, &options, dup_fork, &hook) == VOR_OK,
              "builds");
        const char *diff = first_difference(&seq, &d, n);
        CHECK(diff == NULL && h.forks == (n >= 100u ? 1u : 0u),
              "fork_min_sites 100, %u sites: %s differ, %u forks", n,
              (diff != NULL) ? diff : "none", h.forks);
    }
}

/* The x-split over few distinct sites: 40 copies of 2 to 6 points on a
 * parabola, fork_min_sites 3 (which means 8). With fewer than 3 distinct
 * sites on a side (the first part takes 3 of 5 or 6, in leaves of 2 or 3)
 * there is nothing to fork, as for the quadtree's "top" family; the
 * diagram is vor_build_dc's either way. */
static void check_few_distinct(void)
{
    for (uint32_t distinct = 2; distinct <= 6u; distinct++) {
        for (uint32_t i = 0; i < 40u; i++) {
            points[i].x = (int32_t)(i % distinct) * 1000 + 7;
            points[i].y = (int32_t)((i % distinct) * (i % distinct)) * 300;
        }
        vor_t seq, d;
        fill(arena_seq, sizeof arena_seq);
        fill(arena_fork, sizeof arena_fork);
        test_hook_t h = {HOOK_AT_ONCE, 0, 0, 0, NULL, NULL};
        vor_fork_join_t hook = {hook_fork, hook_join, &h};
        vor_build_options_t options = {VOR_ORDER_QUADTREE, VOR_DC_XSPLIT, 3};
        CHECK(vor_init(&seq, arena_seq, sizeof arena_seq, FJ_SITES) == VOR_OK &&
                  vor_init(&d, arena_fork, sizeof arena_fork, FJ_SITES) == VOR_OK,
              "init");
        CHECK(vor_build_dc(&seq, points, 40, &options, dup_seq) == VOR_OK &&
                  vor_build_dc_forked(&d, points, 40, &options, dup_fork, &hook) == VOR_OK,
              "builds");
        const char *diff = first_difference(&seq, &d, 40);
        CHECK(diff == NULL && vor_validate(&d, NULL) == VOR_OK && d.vertex_count == distinct,
              "%u distinct sites: %s differ", distinct, (diff != NULL) ? diff : "none");
        CHECK(h.forks == ((distinct >= 6u) ? 1u : 0u), "%u distinct sites: %u forks", distinct,
              h.forks);
    }
}

void test_fork_join(void)
{
    test_rng_t rng;
    static const uint32_t sizes[] = {VOR_DC_FORK_MIN_SITES_DEFAULT - 1u,
                                     VOR_DC_FORK_MIN_SITES_DEFAULT,
                                     VOR_DC_FORK_MIN_SITES_DEFAULT + 1u, FJ_SITES};
    for (unsigned f = 0; f < F_FAMILIES; f++) {
        for (unsigned s = 0; s < 4u; s++) {
            /* every size for the random families, the threshold and the
             * largest for the others */
            if (f != F_DUPLICATES && f != F_UNIFORM && s != 1u && s != 3u) {
                continue;
            }
            TEST_CASE("family/%s/%u", family_names[f], sizes[s]) {
                check_family((enum family)f, sizes[s], test_rng_seed(&rng, 0xF0F0 + f * 4u + s));
            }
        }
    }
    TEST_CASE("no_hook") check_no_hook(test_rng_seed(&rng, 0xF0F0));
    TEST_CASE("fork_min") check_fork_min(test_rng_seed(&rng, 0xF0F1));
    TEST_CASE("few_distinct") check_few_distinct();
}
