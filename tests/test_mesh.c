/* SPDX-License-Identifier: MIT */
/*
 * test_mesh.c - the incremental builder and the diagram object.
 *
 * Independent references: a brute-force Delaunay triangulation (every
 * triple of nonzero area whose perturbed circumcircle holds no other site:
 * the triangles the iterator reports) for small sets;
 * vor_validate's invariants after every operation; and the uniqueness of
 * the perturbed Delaunay triangulation, so that the batch build in both
 * orders and one-by-one insertion must give the same triangles.
 */
#include "insertion_order.h" /* white-box: vor__sort_ids, for its worst case */
#include "mesh.h" /* white-box: the triangle layout, for the corrupted diagrams */
#include "test.h"
#include "vor.h"

#define BIG_SITES 3000u

static vor_point_t points[BIG_SITES];
static uint32_t duplicate_of[BIG_SITES];
static uint8_t arena_a[VOR_ARENA_BYTES(BIG_SITES)] __attribute__((aligned(8)));
static uint8_t arena_b[VOR_ARENA_BYTES(BIG_SITES)] __attribute__((aligned(8)));
static uint8_t snapshot[VOR_ARENA_BYTES(64)] __attribute__((aligned(8)));

/* ------------------------------------------------------------------ */
/* Triangle sets                                                       */

/* Brute force: (i, j, k) of nonzero area, counterclockwise, with no site
 * inside its perturbed circle. */
static test_fingerprint_t brute_force(const vor_point_t *sites, uint32_t n,
                                 const uint32_t *dup)
{
    test_fingerprint_t f = {0, 0, 0};
    for (uint32_t i = 0; i < n; i++) {
        for (uint32_t j = i + 1; j < n; j++) {
            for (uint32_t k = j + 1; k < n; k++) {
                if (dup[i] != i || dup[j] != j || dup[k] != k ||
                    vor_orient2d(sites[i], sites[j], sites[k]) == 0) {
                    continue;
                }
                uint32_t ids[3] = {i, j, k};
                if (vor_orient2d_sos(sites, i, j, k) < 0) {
                    ids[1] = k;
                    ids[2] = j;
                }
                bool empty = true;
                for (uint32_t l = 0; l < n && empty; l++) {
                    if (l != i && l != j && l != k && dup[l] == l) {
                        empty = vor_incircle_sos(sites, ids[0], ids[1], ids[2], l) < 0;
                    }
                }
                if (empty) {
                    test_fingerprint_add(&f, ids);
                }
            }
        }
    }
    return f;
}

static bool validate_ok(const vor_t *d, const char *what)
{
    vor_violation_t v = {VOR_CHECK_COUNTS, 0, 0};
    int err = vor_validate(d, &v);
    return CHECK(err == VOR_OK, "%s: validate %d: check %u, triangle %u, site %u", what, err,
                 (unsigned)v.check, v.triangle, v.site);
}

/* ------------------------------------------------------------------ */
/* Point sets                                                          */

enum family {
    F_UNIFORM_FULL, F_UNIFORM_SMALL, F_TINY, F_GRID, F_LINE, F_CIRCLE,
    F_CLUSTER, F_DUPLICATES, F_CORNERS, F_FAMILIES
};
static const char *const family_names[F_FAMILIES] = {
    "uniform full range", "uniform 16-bit", "tiny window", "grid", "line",
    "circle R=5^13", "cluster", "heavy duplicates", "int32 corners"};

/* Lattice points on x^2 + y^2 = (5^13)^2: (2+i)^a (2-i)^(26-a) and their
 * rotations by i, R = 1,220,703,125 (about 2^30.2). Returns the count. */
static uint32_t circle_points(vor_point_t *out, uint32_t max)
{
    uint32_t n = 0;
    for (unsigned a = 0; a <= 26u && n < max; a++) {
        int64_t re = 1, im = 0;
        for (unsigned k = 0; k < 26u; k++) {
            int64_t sign = (k < a) ? 1 : -1; /* 2 + i or 2 - i */
            int64_t r2 = 2 * re - sign * im, i2 = 2 * im + sign * re;
            re = r2;
            im = i2;
        }
        for (unsigned rot = 0; rot < 4u && n < max; rot++) {
            int64_t t = re;
            re = -im;
            im = t;
            vor_point_t p = {(int32_t)re, (int32_t)im};
            bool seen = false;
            for (uint32_t e = 0; e < n; e++) {
                seen |= out[e].x == p.x && out[e].y == p.y;
            }
            if (!seen) {
                out[n++] = p;
            }
        }
    }
    return n;
}

/* Approximately normal with sigma ~ 3 (sum of uniforms). */
static int32_t cluster_offset(test_rng_t *rng)
{
    int32_t s = 0;
    for (int k = 0; k < 6; k++) {
        s += test_rng_range(rng, -5, 5);
    }
    return s / 2;
}

static uint32_t make_family(enum family f, uint32_t n, test_rng_t *rng, vor_point_t *out)
{
    static const int32_t corners[] = {INT32_MIN, INT32_MIN + 1, -1, 0, 1,
                                      INT32_MAX - 1, INT32_MAX};
    uint32_t side = 1;
    while ((side + 1u) * (side + 1u) <= n) {
        side++;
    }
    switch (f) {
    case F_CIRCLE:
        return circle_points(out, n);
    case F_GRID:
        n = side * side;
        break;
    default:
        break;
    }
    int32_t cx = test_rng_range(rng, -1000000, 1000000), cy = test_rng_range(rng, -1000000, 1000000);
    for (uint32_t i = 0; i < n; i++) {
        vor_point_t p = {0, 0};
        switch (f) {
        case F_UNIFORM_FULL:
            p.x = (int32_t)test_rng_u32(rng);
            p.y = (int32_t)test_rng_u32(rng);
            break;
        case F_UNIFORM_SMALL:
            p.x = test_rng_range(rng, -32768, 32767);
            p.y = test_rng_range(rng, -32768, 32767);
            break;
        case F_TINY:
            p.x = test_rng_range(rng, -4, 4);
            p.y = test_rng_range(rng, -4, 4);
            break;
        case F_GRID:
            p.x = (int32_t)(i % side) * 1000 - 500000;
            p.y = (int32_t)(i / side) * 1000 + 7;
            break;
        case F_LINE: {
            int32_t t = test_rng_range(rng, -100000, 100000);
            p.x = 3 * t + 17;
            p.y = -7 * t + 5;
            break;
        }
        case F_CLUSTER:
            p.x = cx + cluster_offset(rng);
            p.y = cy + cluster_offset(rng);
            break;
        case F_DUPLICATES:
            p.x = test_rng_range(rng, 0, 5) * 1000003;
            p.y = test_rng_range(rng, 0, 4) * -999983;
            break;
        case F_CORNERS:
        default:
            p.x = corners[test_rng_u32(rng) % 7u];
            p.y = corners[test_rng_u32(rng) % 7u];
            break;
        }
        out[i] = p;
    }
    return n;
}

/* ------------------------------------------------------------------ */
/* Tests                                                               */

static void check_init(void)
{
    vor_t d;
    static uint8_t small[VOR_ARENA_BYTES(10) + 8] __attribute__((aligned(8)));
    CHECK(vor_init(NULL, small, sizeof small, 10) == VOR_ERR_ARG, "init NULL diagram");
    CHECK(vor_init(&d, NULL, sizeof small, 10) == VOR_ERR_ARG, "init NULL arena");
    CHECK(vor_init(&d, small, sizeof small, 0) == VOR_ERR_ARG, "init 0 sites");
    CHECK(vor_init(&d, small, sizeof small, VOR_MAX_SITES + 1u) == VOR_ERR_ARG,
          "init too many sites");
    CHECK(vor_init(&d, small + 1, sizeof small - 1, 10) == VOR_ERR_ALIGN, "init misaligned");
    CHECK(vor_init(&d, small, VOR_ARENA_BYTES(10) - 1u, 10) == VOR_ERR_NOMEM,
          "init one byte short");
    /* init never writes the arena */
    for (size_t i = 0; i < sizeof small; i++) {
        small[i] = (uint8_t)(i * 7u + 3u);
    }
    CHECK(vor_init(&d, small, VOR_ARENA_BYTES(10), 10) == VOR_OK, "init exact size");
    bool untouched = true;
    for (size_t i = 0; i < sizeof small; i++) {
        untouched &= small[i] == (uint8_t)(i * 7u + 3u);
    }
    CHECK(untouched, "init wrote the arena");
    CHECK(VOR_ARENA_BYTES(500) ==
              500u * 8u + 998u * VOR_TRIANGLE_BYTES +
                  (500u + VOR_SITES_PER_BUCKET - 1u) / VOR_SITES_PER_BUCKET * sizeof(vor_index_t),
          "VOR_ARENA_BYTES follows Euler's count, plus one bucket per %u sites",
          (unsigned)VOR_SITES_PER_BUCKET);
}

/* 0 to 3 sites, by insertion and by build */
static void check_tiny(void)
{
    vor_t d;
    static const vor_point_t three[3] = {{0, 0}, {10, 0}, {0, 10}};
    for (uint32_t n = 0; n <= 3u; n++) {
        CHECK(vor_init(&d, arena_a, VOR_ARENA_BYTES(3), 3) == VOR_OK, "init 3");
        CHECK(vor_build(&d, three, n, NULL, duplicate_of) == VOR_OK, "build %u sites", n);
        test_fingerprint_t f = test_fingerprint_of(&d, NULL);
        CHECK(f.count == (n == 3u ? 1u : 0u), "%u sites: %u triangles", n, f.count);
        validate_ok(&d, "tiny build");
        vor_memory_t m;
        CHECK(vor_memory(&d, &m) == VOR_OK && m.sites == n &&
                  m.triangles == (n >= 2u ? 2u * n - 2u : 0u),
              "memory of %u sites: %u triangles", n, m.triangles);
        /* the rest inserted one by one: a build of one site or none
         * leaves the bucket grid to be drawn at the second site */
        for (uint32_t k = n; k < 3u; k++) {
            CHECK(vor_insert(&d, three[k], NULL) == VOR_OK, "%u built, insert %u", n, k);
            validate_ok(&d, "tiny build and insertions");
        }
    }
    /* one site: a second identical one is a duplicate */
    CHECK(vor_init(&d, arena_a, VOR_ARENA_BYTES(3), 3) == VOR_OK, "init");
    uint32_t id = 99;
    CHECK(vor_insert(&d, (vor_point_t){5, 5}, &id) == VOR_OK && id == 0, "first insert");
    CHECK(vor_insert(&d, (vor_point_t){5, 5}, &id) == VOR_ERR_DUPLICATE && id == 0, "duplicate of one site");
    CHECK(vor_insert(&d, (vor_point_t){6, 5}, &id) == VOR_OK && id == 1, "second site");
    validate_ok(&d, "two sites");
    CHECK(vor_insert(&d, (vor_point_t){5, 5}, &id) == VOR_ERR_DUPLICATE && id == 0, "duplicate of two");
    CHECK(vor_insert(&d, (vor_point_t){7, 5}, &id) == VOR_OK && id == 2, "third site, collinear");
    validate_ok(&d, "three collinear sites");
    CHECK(test_fingerprint_of(&d, NULL).count == 0u, "three collinear sites: no triangle");
    CHECK(vor_insert(&d, (vor_point_t){8, 5}, &id) == VOR_ERR_FULL, "full");
}

/* An insertion's predicates, counted (vor_stats) against what the
 * algorithm must evaluate on a layout where the count follows from the
 * geometry: site p strictly inside the Delaunay triangle (a, b, c), no
 * three sites collinear, each edge of abc with a finite triangle beyond
 * whose circle does not hold p. The walk finds abc without an exact zero,
 * so the insertion takes no nearest-site walk (no vor_closer), and the
 * pass around p refuses each of the star's three edges once: exactly
 * three incircle tests (an infinite triangle beyond would be an
 * orientation), no flip. The premises are checked by brute force. */
static void check_insertion_counts(void)
{
    static const vor_point_t six[6] = {{0, 0},     {2000, 0},    {1000, 1732},
                                       {1000, -4000}, {4964, 2866}, {-2964, 2866}};
    const vor_point_t p = {1001, 577};
    /* the triangles beyond edges ab, bc, ca: (a, b, 3), (b, c, 4), (c, a, 5) */
    static const uint32_t beyond[3][3] = {{1, 0, 3}, {2, 1, 4}, {0, 2, 5}};
    bool premises = true;
    for (uint32_t t = 0; t < 4u; t++) {
        uint32_t ids[3] = {0, 1, 2};
        if (t > 0u) {
            for (uint32_t k = 0; k < 3u; k++) {
                ids[k] = beyond[t - 1u][k];
            }
        }
        premises = premises && vor_orient2d(six[ids[0]], six[ids[1]], six[ids[2]]) > 0;
        for (uint32_t l = 0; l < 6u; l++) {
            if (l != ids[0] && l != ids[1] && l != ids[2]) {
                premises = premises && vor_incircle(six[ids[0]], six[ids[1]], six[ids[2]],
                                                    six[l]) < 0;
            }
        }
        /* p inside abc, outside each triangle beyond */
        premises = premises && ((t == 0u) ? vor_orient2d(six[ids[0]], six[ids[1]], p) > 0 &&
                                                vor_orient2d(six[ids[1]], six[ids[2]], p) > 0 &&
                                                vor_orient2d(six[ids[2]], six[ids[0]], p) > 0
                                          : vor_incircle(six[ids[0]], six[ids[1]], six[ids[2]],
                                                         p) < 0);
    }
    for (uint32_t i = 0; i < 6u; i++) {
        for (uint32_t j = i + 1u; j < 6u; j++) {
            for (uint32_t k = j + 1u; k < 6u; k++) {
                premises = premises && vor_orient2d(six[i], six[j], six[k]) != 0;
            }
            premises = premises && vor_orient2d(six[i], six[j], p) != 0;
        }
    }
    CHECK(premises, "insertion counts: the layout is not as described");
    vor_t d;
    vor_stats_t before, after;
    /* from each site's neighbourhood: the walk's start does not matter */
    for (uint32_t hint = 0; hint < 6u; hint++) {
        CHECK(vor_init(&d, arena_a, VOR_ARENA_BYTES(7), 7) == VOR_OK &&
                  vor_build(&d, six, 6, NULL, duplicate_of) == VOR_OK,
              "insertion counts: build");
        if (vor_stats(&d, &before) != VOR_OK) {
            return; /* a library without VOR_STATS: no count to compare */
        }
        uint32_t id = 0;
        CHECK(vor_insert_near(&d, p, hint, &id) == VOR_OK && id == 6u, "insertion counts: insert");
        vor_stats(&d, &after);
        uint32_t incircle = 0, closer = 0;
        for (unsigned t = 0; t < VOR_TIERS; t++) {
            incircle += after.incircle[t] - before.incircle[t];
            closer += after.closer[t] - before.closer[t];
        }
        incircle += after.incircle_perturbed - before.incircle_perturbed;
        closer += after.closer_perturbed - before.closer_perturbed;
        CHECK(incircle == 3u && closer == 0u,
              "insertion counts from site %u: %u incircle tests, %u closer (want 3, 0)", hint,
              incircle, closer);
        validate_ok(&d, "insertion counts");
    }
}

/* Small random sets against brute force, validating after every insert. */
static void check_brute_force(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 11);
    vor_point_t sites[16];
    uint32_t dup[16];
    for (unsigned round = 0; round < 60u; round++) {
        uint32_t n = 3u + round % 14u;
        int32_t range = (round % 3u == 0u) ? 2 : (round % 3u == 1u) ? 1000 : INT32_MAX;
        vor_t d;
        CHECK(vor_init(&d, arena_a, VOR_ARENA_BYTES(16), 16) == VOR_OK, "init");
        uint32_t inserted = 0;
        bool valid = true;
        for (uint32_t i = 0; i < n; i++) {
            int32_t x = test_rng_range(&rng, -range, range);
            int32_t y = test_rng_range(&rng, -range, range);
            uint32_t id;
            int err = vor_insert(&d, (vor_point_t){x, y}, &id);
            if (err == VOR_OK) {
                sites[inserted] = (vor_point_t){x, y};
                dup[inserted] = inserted;
                inserted++;
            } else {
                CHECK(err == VOR_ERR_DUPLICATE && d.sites[id].x == x && d.sites[id].y == y,
                      "round %u: insert %d", round, err);
            }
            valid &= validate_ok(&d, "brute-force round");
        }
        test_fingerprint_t expect = brute_force(sites, inserted, dup);
        CHECK(valid && test_same_fingerprint(test_fingerprint_of(&d, NULL), expect),
              "round %u (%u sites, range %d): %u triangles, brute force %u", round, inserted,
              range, test_fingerprint_of(&d, NULL).count, expect.count);
    }
}

/* Every family: build (quadtree and input order) and one-by-one insertion
 * give the same triangulation, and it is valid. */
static void check_families(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 23);
    static const uint32_t sizes[] = {40, 700, BIG_SITES};
    for (unsigned f = 0; f < F_FAMILIES; f++) {
        for (unsigned s = 0; s < 3u; s++) {
            uint32_t n = make_family((enum family)f, sizes[s], &rng, points);
            vor_t a, b, c;
            CHECK(vor_init(&a, arena_a, sizeof arena_a, BIG_SITES) == VOR_OK, "init");
            CHECK(vor_init(&b, arena_b, sizeof arena_b, BIG_SITES) == VOR_OK, "init");
            CHECK(vor_build(&a, points, n, NULL, duplicate_of) == VOR_OK, "build");
            bool ok = validate_ok(&a, family_names[f]);
            uint32_t distinct = 0;
            bool dup_ok = true;
            for (uint32_t i = 0; i < n; i++) {
                uint32_t first = duplicate_of[i];
                distinct += (first == i) ? 1u : 0u;
                dup_ok &= first <= i && points[first].x == points[i].x &&
                          points[first].y == points[i].y && duplicate_of[first] == first;
            }
            CHECK(dup_ok && a.vertex_count == distinct, "%s: duplicates reported wrongly",
                  family_names[f]);
            test_fingerprint_t quadtree = test_fingerprint_of(&a, NULL);
            /* unique sites: the triangulation has 2v - 2 - h triangles */
            CHECK(quadtree.count + 2u <= 2u * distinct || distinct < 3u,
                  "%s: %u triangles for %u sites", family_names[f], quadtree.count, distinct);

            vor_build_options_t input = {VOR_ORDER_INPUT, VOR_DC_QUADTREE, 0};
            CHECK(vor_build(&b, points, n, &input, NULL) == VOR_OK, "build in input order");
            test_fingerprint_t in_input_order = test_fingerprint_of(&b, NULL);
            ok &= validate_ok(&b, "input order") && test_same_fingerprint(in_input_order, quadtree);

            /* divide and conquer, both splits: the same triangles, the
             * same duplicates */
            for (unsigned split = VOR_DC_QUADTREE; split <= VOR_DC_XSPLIT; split++) {
                static uint32_t dc_duplicate_of[BIG_SITES];
                CHECK(vor_build_dc(&b, points, n, TEST_SPLIT(split), dc_duplicate_of) ==
                          VOR_OK,
                      "build d&c");
                bool same_dups = b.vertex_count == a.vertex_count;
                for (uint32_t i = 0; i < n; i++) {
                    same_dups &= dc_duplicate_of[i] == duplicate_of[i];
                }
                test_fingerprint_t dcf = test_fingerprint_of(&b, NULL);
                CHECK(validate_ok(&b, split == VOR_DC_XSPLIT ? "d&c" : "d&c quadtree") &&
                          same_dups && test_same_fingerprint(dcf, quadtree),
                      "%s, %u sites: d&c split %u differs (%u / %u triangles)",
                      family_names[f], n, split, dcf.count, quadtree.count);
            }

            /* one by one, skipping duplicates: ids shift, so map them back */
            CHECK(vor_init(&c, arena_b, sizeof arena_b, BIG_SITES) == VOR_OK, "init");
            test_fingerprint_t one_by_one = {0, 0, 0};
            if (s < 2u) { /* the big sets are covered by the two builds */
                static uint32_t id_to_point[BIG_SITES];
                for (uint32_t i = 0; i < n; i++) {
                    uint32_t id;
                    int err = vor_insert(&c, points[i], &id);
                    if (err == VOR_OK) {
                        id_to_point[id] = i;
                    }
                }
                ok &= validate_ok(&c, "one by one");
                vor_triangle_iter_t it;
                uint32_t ids[3];
                vor_triangles_begin(&it, &c);
                while (vor_triangles_next(&it, ids)) {
                    uint32_t mapped[3] = {id_to_point[ids[0]], id_to_point[ids[1]],
                                          id_to_point[ids[2]]};
                    test_fingerprint_add(&one_by_one, mapped);
                }
                /* ids keep their order, so the perturbation is the same */
                ok &= test_same_fingerprint(one_by_one, quadtree);
            }
            CHECK(ok, "%s, %u sites: builds disagree (%u / %u / %u triangles)",
                  family_names[f], n, quadtree.count, in_input_order.count, one_by_one.count);
        }
    }
}

/* Memory: every site costs at most the documented bytes. */
static void check_memory(void)
{
    vor_t d;
    vor_memory_t m;
    test_rng_t rng;
    test_rng_seed(&rng, 5);
    uint32_t n = make_family(F_UNIFORM_FULL, BIG_SITES, &rng, points);
    CHECK(vor_init(&d, arena_a, sizeof arena_a, BIG_SITES) == VOR_OK, "init");
    CHECK(vor_build(&d, points, n, NULL, NULL) == VOR_OK, "build");
    CHECK(vor_memory(&d, &m) == VOR_OK, "memory");
    /* issue 3's mesh budget, plus the bucket grid: one id per
     * VOR_SITES_PER_BUCKET sites */
    uint32_t limit = ((VOR_INDEX_BITS == 16) ? 3200u : 4800u) +
                     (uint32_t)((100u * sizeof(vor_index_t) + VOR_SITES_PER_BUCKET - 1u) /
                                VOR_SITES_PER_BUCKET);
    CHECK(m.bytes_per_site_x100 <= limit && m.used_bytes <= m.arena_bytes,
          "%u.%02u bytes per site", m.bytes_per_site_x100 / 100u, m.bytes_per_site_x100 % 100u);
    test_printf("mesh: %u.%02u bytes per site (%u-bit indices)\n", m.bytes_per_site_x100 / 100u,
                m.bytes_per_site_x100 % 100u, (unsigned)VOR_INDEX_BITS);
}

/* Failing calls change nothing: the diagram object and every arena byte
 * are compared before and after, at every step until the diagram is full
 * (littlefs runs its tests with the power cut at every write). */
static bool unchanged(const vor_t *d, const vor_t *before, size_t bytes)
{
    const uint8_t *a = (const uint8_t *)d, *b = (const uint8_t *)before;
    for (size_t i = 0; i < sizeof *d; i++) {
        if (a[i] != b[i]) {
            return false;
        }
    }
    for (size_t i = 0; i < bytes; i++) {
        if (arena_a[i] != snapshot[i]) {
            return false;
        }
    }
    return true;
}

static void check_failures_change_nothing(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 41);
    unsigned bad = 0, tried = 0;
    for (uint32_t max = 1; max <= 40u; max++) {
        vor_t d;
        size_t bytes = VOR_ARENA_BYTES(max);
        CHECK(vor_init(&d, arena_a, bytes, max) == VOR_OK, "init %u", max);
        for (uint32_t step = 0; step <= max; step++) {
            vor_t before = d;
            for (size_t i = 0; i < bytes; i++) {
                snapshot[i] = arena_a[i];
            }
            /* a duplicate of an existing site, or any point when full */
            int32_t x = test_rng_range(&rng, -3, 3), y = test_rng_range(&rng, -3, 3);
            if (step > 0u && step % 2u == 0u) {
                uint32_t k = test_rng_u32(&rng) % d.site_count;
                x = d.sites[k].x;
                y = d.sites[k].y;
            }
            uint32_t id;
            int err = vor_insert(&d, (vor_point_t){x, y}, &id);
            if (err != VOR_OK) {
                tried++;
                bad += unchanged(&d, &before, bytes) ? 0u : 1u;
                bad += (err == VOR_ERR_FULL || err == VOR_ERR_DUPLICATE) ? 0u : 1u;
            } else if (!validate_ok(&d, "capacity steps")) {
                bad++;
            }
            /* a failing build: more points than room */
            before = d;
            for (size_t i = 0; i < bytes; i++) {
                snapshot[i] = arena_a[i];
            }
            err = vor_build(&d, points, max + 1u, NULL, NULL);
            tried++;
            bad += (err == VOR_ERR_FULL && unchanged(&d, &before, bytes)) ? 0u : 1u;
            err = vor_build_dc(&d, points, max + 1u, NULL, NULL);
            tried++;
            bad += (err == VOR_ERR_FULL && unchanged(&d, &before, bytes)) ? 0u : 1u;
        }
        /* bad arguments */
        vor_t before = d;
        CHECK(vor_insert_near(&d, (vor_point_t){1, 1}, d.site_count + 5u, NULL) == VOR_ERR_ARG ||
                  d.site_count == max,
              "bad hint accepted");
        vor_build_options_t weird = {(enum vor_order)7, VOR_DC_QUADTREE, 0};
        CHECK(vor_build(&d, points, 1, &weird, NULL) == VOR_ERR_ARG &&
                  unchanged(&d, &before, 0),
              "unknown order accepted");
        CHECK(vor_build_dc(&d, points, 1, TEST_SPLIT(2), NULL) == VOR_ERR_ARG &&
                  unchanged(&d, &before, 0),
              "unknown split accepted");
    }
    CHECK(bad == 0 && tried > 60u, "%u of %u failing calls changed the diagram", bad, tried);
}

/* vor_memory's figures, exactly: the documented sizes of the current
 * sites, the 2v - 2 triangle slots of v >= 2 sites in the mesh and the
 * bucket grid (columns x rows ids once the mesh has two sites), and the
 * bytes per site in hundredths rounded to nearest, here by the compiler's
 * own 64-bit division; and vor_init's and vor_build's argument limits at
 * their edges (the mutation tests showed them unchecked). */
static void check_memory_figures(void)
{
    /* every size to 40 (each rounding of the hundredths), and larger */
    static const uint32_t larger[] = {50, 333, 3000};
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    for (unsigned k = 0; k < 41u + sizeof larger / sizeof larger[0]; k++) {
        uint32_t n = (k <= 40u) ? k : larger[k - 41u], max = n + 5u;
        vor_t d;
        vor_memory_t m;
        for (uint32_t i = 0; i < n; i++) {
            points[i].x = test_rng_range(&rng, -100000, 100000);
            points[i].y = test_rng_range(&rng, -100000, 100000);
        }
        if (max > BIG_SITES) {
            max = BIG_SITES;
        }
        CHECK(vor_init(&d, arena_a, VOR_ARENA_BYTES(max), max) == VOR_OK &&
                  vor_build(&d, points, n, NULL, NULL) == VOR_OK &&
                  vor_memory(&d, &m) == VOR_OK,
              "build %u", n);
        uint32_t triangles = (n >= 2u) ? 2u * n - 2u : 0u;
        uint32_t buckets = (n >= 2u) ? d.bucket_columns * d.bucket_rows : 0u;
        uint64_t used = (uint64_t)n * sizeof(vor_point_t) +
                        (uint64_t)triangles * VOR_TRIANGLE_BYTES +
                        (uint64_t)buckets * sizeof(vor_index_t);
        uint64_t x100 = (n == 0u) ? 0u : (used * 100u + n / 2u) / n;
        CHECK(m.arena_bytes == VOR_ARENA_BYTES(max) && m.sites == n && m.triangles == triangles &&
                  m.used_bytes == used && m.bytes_per_site_x100 == x100,
              "memory of %u sites: %u bytes, %u per site x100 (want %u, %u)", n,
              (unsigned)m.used_bytes, m.bytes_per_site_x100, (unsigned)used, (unsigned)x100);
        CHECK(n < 2u || buckets > 0u, "%u sites: a bucket grid", n);
    }
    /* the limits of the arguments */
    vor_t d;
    uint32_t dup[1] = {UINT32_MAX};
    CHECK(vor_init(&d, arena_a, 64u, VOR_MAX_SITES) == VOR_ERR_NOMEM &&
              vor_init(&d, arena_a, 64u, VOR_MAX_SITES + 1u) == VOR_ERR_ARG,
          "vor_init at VOR_MAX_SITES");
    CHECK(vor_init(&d, arena_a, VOR_ARENA_BYTES(4), 4) == VOR_OK &&
              vor_build(&d, NULL, 0, NULL, NULL) == VOR_OK && d.site_count == 0u &&
              vor_build(&d, NULL, 1, NULL, NULL) == VOR_ERR_ARG,
          "vor_build with no points");
    points[0].x = 7;
    points[0].y = -7;
    CHECK(vor_build(&d, points, 1, NULL, dup) == VOR_OK && dup[0] == 0u && d.site_count == 1u,
          "vor_build of one site: duplicate_of[0] = %u", dup[0]);
    dup[0] = UINT32_MAX;
    CHECK(vor_build(&d, points, 0, NULL, dup) == VOR_OK && dup[0] == UINT32_MAX,
          "vor_build of no site writes no duplicate_of");
    /* rebuilt with one site or none after a grid was drawn: no grid counts */
    for (uint32_t n = 0; n < 2u; n++) {
        vor_memory_t m;
        CHECK(vor_init(&d, arena_a, VOR_ARENA_BYTES(64), 64) == VOR_OK &&
                  vor_build(&d, points, 64, NULL, NULL) == VOR_OK &&
                  vor_build(&d, points, n, NULL, NULL) == VOR_OK && vor_memory(&d, &m) == VOR_OK &&
                  m.used_bytes == n * sizeof(vor_point_t) && m.triangles == 0u,
              "rebuilt with %u sites: %u bytes used", n, (unsigned)m.used_bytes);
    }
}

/* ------------------------------------------------------------------ */
/* vor_validate on corrupted diagrams                                  */

#define CORRUPT_SITES 40u
#define CORRUPT_DUPLICATE 7u /* a copy of site 0: its home slot stays empty */

static uint8_t corrupt_arena[VOR_ARENA_BYTES(CORRUPT_SITES)] __attribute__((aligned(8)));
static uint8_t pristine_arena[sizeof corrupt_arena], corrupted_arena[sizeof corrupt_arena];
static vor_t corrupt, pristine;

/* The first of sites[0 .. i] at p. */
static uint32_t site_index(const vor_point_t *sites, uint32_t i, vor_point_t p)
{
    uint32_t j = 0;
    while (sites[j].x != p.x || sites[j].y != p.y) {
        j++;
    }
    return (j < i) ? j : i;
}

/* The diagram back to the valid one built below. */
static void restore(void)
{
    test_copy_bytes(corrupt_arena, pristine_arena, sizeof corrupt_arena);
    corrupt = pristine;
}

/* vor_validate must name `check` for the corruption just made, with and
 * without a violation record, and read only: the arena and the diagram
 * stay as the corruption left them. */
static void expect_violation(enum vor_check check, const char *what)
{
    vor_t before = corrupt;
    test_copy_bytes(corrupted_arena, corrupt_arena, sizeof corrupt_arena);
    vor_violation_t v = {VOR_CHECK_TRUE_OUTPUT, 77, 77};
    int err = vor_validate(&corrupt, &v);
    CHECK(err == VOR_ERR_INVALID && v.check == check && vor_validate(&corrupt, NULL) == err &&
              test_same_bytes(corrupted_arena, corrupt_arena, sizeof corrupt_arena) &&
              test_same_bytes(&before, &corrupt, sizeof corrupt),
          "%s: vor_validate %d, check %d (expected %d)", what, err, (int)v.check, (int)check);
    restore();
}

/* Rewrites one vertex (k) or one neighbour link (k - 3) of a slot. */
static void set_field(uint32_t slot, unsigned k, vor_index_t value)
{
    vor__tri_t *t = &corrupt.triangles[slot];
    vor_index_t v[3], n[3] = {t->n[0], t->n[1], t->n[2]};
    vor__vertices(t, v);
    if (k < 3u) {
        v[k] = value;
    } else {
        n[k - 3u] = value;
    }
    vor__tri_set(t, v[0], v[1], v[2], n[0], n[1], n[2]);
}

/* The first used slot at or after `from` whose triangle has (or lacks,
 * with has false) vertex a, and b when b is not VOR__NONE. */
static uint32_t find_slot(uint32_t from, vor_index_t a, bool has, vor_index_t b)
{
    uint32_t end = vor__used_slots_end(&corrupt);
    for (uint32_t s = vor__next_used_slot(&corrupt, from); s < end;
         s = vor__next_used_slot(&corrupt, s + 1u)) {
        const vor__tri_t *t = &corrupt.triangles[s];
        bool with_a = vor__vertex_index(t, a) != 3u;
        if (with_a == has && (b == VOR__NONE || vor__vertex_index(t, b) == 3u)) {
            return s;
        }
    }
    return VOR__NONE;
}

/* One corruption per test of vor_validate (each passes the tests before
 * it): counts, vertices, neighbour links, fans, the box and the buckets,
 * then geometry on four sites whose coordinates are moved. */
static void check_corrupted(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 0xBAD);
    vor_point_t sites[CORRUPT_SITES];
    for (uint32_t i = 0; i < CORRUPT_SITES; i++) {
        do { /* distinct, but for the one copy */
            sites[i].x = test_rng_range(&rng, -5000, 5000);
            sites[i].y = test_rng_range(&rng, -5000, 5000);
        } while (i != CORRUPT_DUPLICATE && site_index(sites, i, sites[i]) != i);
    }
    sites[CORRUPT_DUPLICATE] = sites[0];
    CHECK(vor_init(&corrupt, corrupt_arena, sizeof corrupt_arena, CORRUPT_SITES) == VOR_OK &&
              vor_build(&corrupt, sites, CORRUPT_SITES, NULL, NULL) == VOR_OK &&
              vor_validate(&corrupt, NULL) == VOR_OK &&
              corrupt.vertex_count == CORRUPT_SITES - 1u &&
              vor__slot_empty(&corrupt.triangles[CORRUPT_DUPLICATE]),
          "the valid diagram");
    pristine = corrupt;
    test_copy_bytes(pristine_arena, corrupt_arena, sizeof corrupt_arena);
    const uint32_t packed = corrupt.max_sites, end = vor__used_slots_end(&corrupt);

    corrupt.vertex_count = corrupt.site_count + 1u;
    expect_violation(VOR_CHECK_COUNTS, "more vertices than sites");
    corrupt.site_count = corrupt.max_sites + 1u;
    expect_violation(VOR_CHECK_COUNTS, "more sites than room");
    corrupt.vertex_count--;
    expect_violation(VOR_CHECK_COUNTS, "a vertex fewer");

    set_field(packed, 0, (vor_index_t)corrupt.site_count);
    expect_violation(VOR_CHECK_VERTICES, "a vertex past the sites");
    set_field(packed, 1, CORRUPT_DUPLICATE);
    expect_violation(VOR_CHECK_VERTICES, "a duplicate's id as a vertex");
    for (unsigned k = 0; k < 3u; k++) { /* vertex k made equal to the next */
        set_field(packed, k, vor__vertex(&corrupt.triangles[packed], vor__next(k)));
        expect_violation(VOR_CHECK_VERTICES, "two equal vertices");
    }

    set_field(packed, 4, VOR__NONE);
    expect_violation(VOR_CHECK_NEIGHBOURS, "no neighbour");
    set_field(packed, 4, CORRUPT_DUPLICATE);
    expect_violation(VOR_CHECK_NEIGHBOURS, "an empty slot as neighbour");
    set_field(packed, 4, (vor_index_t)end);
    expect_violation(VOR_CHECK_NEIGHBOURS, "a slot past the used ones as neighbour");
    /* slot 0's edge opposite its vertex 0 runs a -> b */
    const vor__tri_t *t0 = &corrupt.triangles[0];
    vor_index_t a = vor__vertex(t0, 1), b = vor__vertex(t0, 2);
    set_field(0, 3, (vor_index_t)find_slot(0, a, false, VOR__NONE));
    expect_violation(VOR_CHECK_NEIGHBOURS, "a neighbour without the edge's first vertex");
    set_field(0, 3, (vor_index_t)find_slot(1, a, true, b));
    expect_violation(VOR_CHECK_NEIGHBOURS, "a neighbour without the edge's second vertex");
    set_field(0, 3, 0);
    expect_violation(VOR_CHECK_NEIGHBOURS, "a triangle its own neighbour");
    {
        /* the neighbour across a -> b links elsewhere across b -> a */
        uint32_t u = t0->n[0];
        const vor__tri_t *o = &corrupt.triangles[u];
        unsigned ia = vor__vertex_index(o, a);
        set_field(u, 3u + vor__next(ia), o->n[vor__prev(ia)]);
        expect_violation(VOR_CHECK_NEIGHBOURS, "a link that does not point back");
    }

    /* site 0's triangle and a packed one without site 0 trade slots, every
     * link following: the topology holds, but home slot 0 misses site 0 */
    uint32_t other = find_slot(packed, 0, false, VOR__NONE);
    vor__tri_t swap = corrupt.triangles[0];
    corrupt.triangles[0] = corrupt.triangles[other];
    corrupt.triangles[other] = swap;
    for (uint32_t s = vor__next_used_slot(&corrupt, 0); s < end;
         s = vor__next_used_slot(&corrupt, s + 1u)) {
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t n = corrupt.triangles[s].n[i];
            set_field(s, 3u + i, (n == 0u) ? (vor_index_t)other : (n == other) ? 0u : n);
        }
    }
    {
        /* reads on it end (the turn around site 0 finds it in no triangle) */
        vor_neighbour_iter_t it;
        uint32_t n = 77, near = 77;
        vor_neighbours_begin(&it, &corrupt, 0);
        CHECK(vor_neighbours_next(&it, &n) == 0 && n == 77u &&
                  vor_nearest(&corrupt, sites[1], 0, &near) == VOR_OK && near < CORRUPT_SITES,
              "reads on a home slot without its site end");
    }
    expect_violation(VOR_CHECK_SITES, "a home slot without its site");

    corrupt.low.x++;
    expect_violation(VOR_CHECK_BUCKETS, "a site left of the box");
    corrupt.high.x--;
    expect_violation(VOR_CHECK_BUCKETS, "a site right of the box");
    corrupt.low.y++;
    expect_violation(VOR_CHECK_BUCKETS, "a site below the box");
    corrupt.high.y--;
    expect_violation(VOR_CHECK_BUCKETS, "a site above the box");
    corrupt.bucket_columns = 0;
    expect_violation(VOR_CHECK_BUCKETS, "no buckets");
    corrupt.bucket_rows = VOR_BUCKETS(CORRUPT_SITES) + 1u;
    expect_violation(VOR_CHECK_BUCKETS, "more buckets than room");
    corrupt.buckets[0] = (vor_index_t)corrupt.site_count;
    expect_violation(VOR_CHECK_BUCKETS, "a bucket naming no site");
    corrupt.buckets[0] = CORRUPT_DUPLICATE;
    expect_violation(VOR_CHECK_BUCKETS, "a bucket naming a duplicate");

    /* geometry: the square-ish (0,0) (10,0) (10,10) (0,11) takes the
     * diagonal (0,0)-(10,10), as (0,11) lies outside the circle through
     * the other three (centre (5,5), 61 > 50); the fourth site moved to
     * (0,9) lies inside it (41 < 50), to (5,4) right of the diagonal */
    const vor_point_t four[4] = {{0, 0}, {10, 0}, {10, 10}, {0, 11}};
    CHECK(vor_init(&corrupt, corrupt_arena, sizeof corrupt_arena, CORRUPT_SITES) == VOR_OK &&
              vor_build(&corrupt, four, 4, NULL, NULL) == VOR_OK &&
              vor_validate(&corrupt, NULL) == VOR_OK,
          "four sites");
    pristine = corrupt;
    test_copy_bytes(pristine_arena, corrupt_arena, sizeof corrupt_arena);
    corrupt.sites[3] = (vor_point_t){0, 9};
    expect_violation(VOR_CHECK_DELAUNAY, "a site moved into a circle");
    corrupt.sites[3] = (vor_point_t){5, 4};
    expect_violation(VOR_CHECK_ORIENTATION, "a site moved across a diagonal");
}

/* ------------------------------------------------------------------ */
/* The sort's worst case                                               */

#define SORT_SITES 256u
#define GAS UINT32_MAX /* a value not decided yet */

static uint32_t sort_value[SORT_SITES], frozen, candidate;

/* McIlroy's adversary ("A killer adversary for quicksort", 1999): values
 * are decided only when a comparison needs them, each new one below all
 * undecided ones, and the one frozen is the likely pivot, so that every
 * partition splits off as little as it can. */
static bool adversary_less(uint32_t a, uint32_t b)
{
    if (sort_value[a] == GAS && sort_value[b] == GAS) {
        sort_value[(a == candidate) ? a : b] = frozen++;
    }
    if (sort_value[a] == GAS) {
        candidate = a;
    } else if (sort_value[b] == GAS) {
        candidate = b;
    }
    return sort_value[a] < sort_value[b];
}

static void swap_u32(uint32_t *ids, uint32_t i, uint32_t j)
{
    uint32_t t = ids[i];
    ids[i] = ids[j];
    ids[j] = t;
}

/* Plays the introsort's quicksort steps (src/insertion_order.c: median of
 * three, Hoare partition, the smaller part first) against the adversary on
 * ids 0 .. n - 1 until a range of 16 or more ids gets deeper than
 * 2 log2 n, where the sort turns to heapsort; then decides the values
 * still open. Returns whether that depth was reached: sites[i].x =
 * sort_value[i] is then an input that takes vor__sort_ids there. */
static bool play_adversary(uint32_t n)
{
    static uint32_t ids[SORT_SITES];
    struct range {
        uint32_t first, count, depth;
    } stack[64];
    unsigned top = 0, log2n = 0;
    bool deep = false;
    while ((1u << log2n) < n) {
        log2n++;
    }
    for (uint32_t i = 0; i < n; i++) {
        ids[i] = i;
        sort_value[i] = GAS;
    }
    frozen = candidate = 0;
    stack[top++] = (struct range){0, n, 0};
    while (top > 0u && !deep && top + 2u <= 64u) {
        struct range r = stack[--top];
        uint32_t *a = ids + r.first;
        if (r.count < 16u) {
            continue; /* insertion sort: within the range, the others unaffected */
        }
        if (r.depth > 2u * log2n) {
            deep = true;
            break;
        }
        uint32_t mid = r.count / 2u, last = r.count - 1u;
        if (adversary_less(a[mid], a[0])) {
            swap_u32(a, mid, 0);
        }
        if (adversary_less(a[last], a[0])) {
            swap_u32(a, last, 0);
        }
        if (adversary_less(a[last], a[mid])) {
            swap_u32(a, last, mid);
        }
        swap_u32(a, 0, mid);
        uint32_t pivot = a[0], i = 0, j = r.count;
        for (;;) {
            do {
                i++;
            } while (i < r.count && adversary_less(a[i], pivot));
            do {
                j--;
            } while (adversary_less(pivot, a[j]));
            if (i >= j) {
                break;
            }
            swap_u32(a, i, j);
        }
        swap_u32(a, 0, j);
        struct range left = {r.first, j, r.depth + 1u};
        struct range right = {r.first + j + 1u, r.count - j - 1u, r.depth + 1u};
        stack[top++] = (left.count > right.count) ? left : right;
        stack[top++] = (left.count > right.count) ? right : left;
    }
    for (uint32_t i = 0; i < n; i++) {
        sort_value[i] = (sort_value[i] == GAS) ? frozen++ : sort_value[i];
    }
    return deep;
}

/* The adversary's input, sorted by both keys: the values are 0 .. n - 1
 * (y = 0, so the Z-order is the x order too), so the k-th id must be the
 * one of value k. */
static void check_sort_worst_case(void)
{
    static vor_point_t sites[SORT_SITES];
    static vor_index_t ids[SORT_SITES];
    static const uint32_t sizes[3] = {64, 100, SORT_SITES};
    for (unsigned s = 0; s < 3u; s++) {
        uint32_t n = sizes[s];
        CHECK(play_adversary(n), "%u sites: the adversary did not get deep enough", n);
        for (unsigned key = 0; key < 2u; key++) {
            for (uint32_t i = 0; i < n; i++) {
                sites[i] = (vor_point_t){(int32_t)sort_value[i] - 1000, 0};
                ids[i] = (vor_index_t)i;
            }
            vor__sort_ids(sites, ids, n, (key == 0u) ? VOR__SORT_LEX : VOR__SORT_Z);
            unsigned bad = 0;
            for (uint32_t k = 0; k < n; k++) {
                bad += sort_value[ids[k]] != k;
            }
            CHECK(bad == 0, "%u sites, key %u: %u ids out of place", n, key, bad);
        }
    }
}

void test_mesh(void)
{
    TEST_CASE("init") check_init();
    TEST_CASE("tiny") check_tiny();
    TEST_CASE("insertion_counts") check_insertion_counts();
    TEST_CASE("brute_force") check_brute_force();
    TEST_CASE("families") check_families();
    TEST_CASE("memory") check_memory();
    TEST_CASE("failures_change_nothing") check_failures_change_nothing();
    TEST_CASE("memory_figures") check_memory_figures();
    TEST_CASE("corrupted") check_corrupted();
    TEST_CASE("sort_worst_case") check_sort_worst_case();
}
