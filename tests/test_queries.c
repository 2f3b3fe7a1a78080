/* SPDX-License-Identifier: MIT */
/*
 * test_queries.c - nearest-site queries and neighbour iteration against
 * brute force: exact squared distances in 64-bit integers over every site,
 * ties to the smallest id, duplicates answered by their first occurrence.
 */
#include "test.h"
#include "vor.h"

#define QUERY_SITES 1200u

#define KMAX 64u /* the largest k asked */

static vor_point_t sites[QUERY_SITES];
static uint32_t first_of[QUERY_SITES];
static uint8_t arena[VOR_ARENA_BYTES(QUERY_SITES)] __attribute__((aligned(8)));

/* |q - p|^2 exactly: differences up to 2^32 - 1, so compare as unsigned
 * 65-bit values (a 64-bit sum plus a carry). */
static int compare_distance(vor_point_t q, vor_point_t a, vor_point_t b)
{
    uint64_t da[2] = {0, 0}, db[2] = {0, 0};
    int64_t d[4] = {(int64_t)a.x - q.x, (int64_t)a.y - q.y, (int64_t)b.x - q.x,
                    (int64_t)b.y - q.y};
    for (int k = 0; k < 4; k++) {
        uint64_t m = (uint64_t)(d[k] < 0 ? -d[k] : d[k]);
        uint64_t sq = m * m; /* m < 2^32 */
        uint64_t *acc = (k < 2) ? da : db;
        acc[0] += sq;
        acc[1] += (acc[0] < sq) ? 1u : 0u;
    }
    if (da[1] != db[1]) {
        return (da[1] < db[1]) ? -1 : 1;
    }
    return (da[0] < db[0]) ? -1 : (da[0] > db[0]) ? 1 : 0;
}

static uint32_t brute_nearest(uint32_t n, vor_point_t q)
{
    uint32_t best = VOR_NO_HINT;
    for (uint32_t i = 0; i < n; i++) {
        if (first_of[i] == i &&
            (best == VOR_NO_HINT || compare_distance(q, sites[i], sites[best]) < 0)) {
            best = i; /* strictly closer only: ties keep the smaller id */
        }
    }
    return best;
}

/* Is site a before site b in the k-nearest order: closer, or as close
 * and a smaller id? */
static bool ranks_before(vor_point_t q, uint32_t a, uint32_t b)
{
    int c = compare_distance(q, sites[a], sites[b]);
    return c < 0 || (c == 0 && a < b);
}

/* vor_nearest_k against a selection over all sites, k from 1 to 16 and
 * one more than there are sites. */
static unsigned check_k_nearest(const vor_t *d, uint32_t n, vor_point_t q, uint32_t k,
                                uint32_t hint)
{
    uint32_t got[KMAX], expect[KMAX], found = 0, count = 0;
    if (vor_nearest_k(d, q, hint, k, got, &found) != VOR_OK) {
        return 1;
    }
    while (count < k) { /* the next site after expect[count - 1] */
        uint32_t pick = VOR_NO_HINT;
        for (uint32_t i = 0; i < n; i++) {
            bool after = count == 0u || ranks_before(q, expect[count - 1u], i);
            if (first_of[i] == i && after && (pick == VOR_NO_HINT || ranks_before(q, i, pick))) {
                pick = i;
            }
        }
        if (pick == VOR_NO_HINT) {
            break;
        }
        expect[count++] = pick;
    }
    unsigned wrong = (found != count) ? 1u : 0u;
    for (uint32_t i = 0; i < count && i < found; i++) {
        wrong += (got[i] != expect[i]) ? 1u : 0u;
    }
    return wrong;
}

static void check_set(const char *name, uint32_t n, test_rng_t *rng, const vor_point_t *extra,
                      uint32_t extras)
{
    vor_t d;
    CHECK(vor_init(&d, arena, sizeof arena, QUERY_SITES) == VOR_OK, "init");
    CHECK(vor_build(&d, sites, n, NULL, first_of) == VOR_OK, "%s: build", name);
    unsigned wrong = 0, queries = 0;
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t k = 0; k < 400u + extras; k++) {
        vor_point_t q;
        if (k < extras) {
            q = extra[k];
        } else if (k % 4u == 0u) { /* near a site */
            q = sites[test_rng_u32(rng) % n];
            q.x += test_rng_range(rng, -2, 2);
            q.y += test_rng_range(rng, -2, 2);
        } else if (k % 4u == 1u) { /* anywhere, far outside too */
            q.x = (int32_t)test_rng_u32(rng);
            q.y = (int32_t)test_rng_u32(rng);
        } else { /* between two sites: on bisectors when coordinates allow */
            vor_point_t a = sites[test_rng_u32(rng) % n], b = sites[test_rng_u32(rng) % n];
            q.x = (int32_t)(((int64_t)a.x + b.x) / 2);
            q.y = (int32_t)(((int64_t)a.y + b.y) / 2);
        }
        /* alternate hints: the previous answer, none, a random site */
        uint32_t h = (k % 3u == 0u) ? hint : (k % 3u == 1u) ? VOR_NO_HINT
                                                             : first_of[test_rng_u32(rng) % n];
        uint32_t got = VOR_NO_HINT;
        int err = vor_nearest(&d, q, h, &got);
        uint32_t expect = brute_nearest(n, q);
        queries++;
        if (err != VOR_OK || got != expect) {
            wrong++;
            if (wrong <= 3u) {
                CHECK(false, "%s: nearest(%d, %d) = %u (err %d), brute force %u", name, q.x, q.y,
                      got, err, expect);
            }
        }
        if (k % 4u == 0u || k < extras) {
            uint32_t want = (k < extras) ? KMAX : 1u + k % 16u;
            unsigned bad = check_k_nearest(&d, n, q, want, h);
            CHECK(bad == 0, "%s: %u-nearest of (%d, %d): %u wrong", name, want, q.x, q.y, bad);
        }
        hint = got;
    }
    CHECK(wrong == 0, "%s: %u of %u nearest queries wrong", name, wrong, queries);

    /* a tracker on a random walk through the sites' box, steps of 1/64 of
     * it, some crossing cells, some staying */
    int64_t low_x = sites[0].x, high_x = sites[0].x, low_y = sites[0].y, high_y = sites[0].y;
    for (uint32_t i = 0; i < n; i++) {
        low_x = (sites[i].x < low_x) ? sites[i].x : low_x;
        high_x = (sites[i].x > high_x) ? sites[i].x : high_x;
        low_y = (sites[i].y < low_y) ? sites[i].y : low_y;
        high_y = (sites[i].y > high_y) ? sites[i].y : high_y;
    }
    int32_t step_x = (int32_t)((high_x - low_x) / 64 + 1), step_y = (int32_t)((high_y - low_y) / 64 + 1);
    vor_tracker_t tracker;
    vor_tracker_begin(&tracker, &d);
    int64_t x = sites[0].x, y = sites[0].y;
    unsigned tracked_wrong = 0;
    for (uint32_t k = 0; k < 300u; k++) {
        x += test_rng_range(rng, -step_x, step_x) / ((k % 3u == 0u) ? 1 : 16);
        y += test_rng_range(rng, -step_y, step_y) / ((k % 3u == 0u) ? 1 : 16);
        x = (x < low_x) ? low_x : (x > high_x) ? high_x : x;
        y = (y < low_y) ? low_y : (y > high_y) ? high_y : y;
        vor_point_t q = {(int32_t)x, (int32_t)y};
        uint32_t got = VOR_NO_HINT;
        if (k % 50u == 0u) { /* a grid centre or circle centre: a tie */
            q = (extras > 0u) ? extra[k % extras] : q;
        }
        if (vor_track(&tracker, q, &got) != VOR_OK || got != brute_nearest(n, q)) {
            tracked_wrong++;
        }
    }
    CHECK(tracked_wrong == 0, "%s: %u of 300 tracked queries wrong", name, tracked_wrong);
    vor_violation_t violation;
    CHECK(vor_validate(&d, &violation) == VOR_OK, "%s: validate: check %d", name,
          (int)violation.check);

    /* neighbours are symmetric, and every edge is seen twice */
    uint32_t seen = 0, asymmetric = 0;
    for (uint32_t s = 0; s < n; s++) {
        vor_neighbour_iter_t it, back;
        uint32_t t, u;
        vor_neighbours_begin(&it, &d, s);
        while (vor_neighbours_next(&it, &t)) {
            seen++;
            bool found = false;
            vor_neighbours_begin(&back, &d, t);
            while (vor_neighbours_next(&back, &u)) {
                found |= u == s;
            }
            asymmetric += found ? 0u : 1u;
        }
    }
    vor_memory_t m;
    vor_memory(&d, &m);
    uint32_t hull = 0; /* finite edges = 3 (v+1) - 6 - hull edges at infinity */
    vor_triangle_iter_t ti;
    uint32_t ids[3];
    uint32_t finite = 0;
    vor_triangles_begin(&ti, &d);
    while (vor_triangles_next(&ti, ids)) {
        finite++;
    }
    hull = m.triangles - finite;
    uint32_t edges = (d.vertex_count >= 2u) ? (3u * m.triangles / 2u - hull) : 0u;
    CHECK(asymmetric == 0 && seen == 2u * edges, "%s: %u asymmetric neighbours, %u of %u edges",
          name, asymmetric, seen / 2u, edges);
}

static void uniform_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    /* uniform, full range */
    for (uint32_t i = 0; i < QUERY_SITES; i++) {
        sites[i].x = (int32_t)test_rng_u32(&rng);
        sites[i].y = (int32_t)test_rng_u32(&rng);
    }
    vor_point_t corners[4] = {{INT32_MIN, INT32_MIN}, {INT32_MAX, INT32_MIN},
                              {INT32_MIN, INT32_MAX}, {INT32_MAX, INT32_MAX}};
    check_set("uniform", QUERY_SITES, &rng, corners, 4);
}

static void grid_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    /* a grid: cell centres are equidistant from four sites */
    vor_point_t centres[64];
    for (uint32_t i = 0; i < 30u * 30u; i++) {
        sites[i].x = (int32_t)(i % 30u) * 10;
        sites[i].y = (int32_t)(i / 30u) * 10;
    }
    for (uint32_t k = 0; k < 64u; k++) {
        centres[k].x = (int32_t)(k % 8u) * 30 + 5;
        centres[k].y = (int32_t)(k / 8u) * 30 + 5;
    }
    check_set("grid", 900, &rng, centres, 64);
}

static void circle_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    /* a circle around the origin: the centre ties with every site */
    uint32_t n = 0;
    for (int32_t x = -25; x <= 25; x++) {
        for (int32_t y = -25; y <= 25; y++) {
            if (x * x + y * y == 625 && n < QUERY_SITES) {
                sites[n].x = x * 1000;
                sites[n].y = y * 1000;
                n++;
            }
        }
    }
    /* shuffle so that the smallest id is not the first one around */
    for (uint32_t i = n; i > 1u; i--) {
        uint32_t j = test_rng_u32(&rng) % i;
        vor_point_t t = sites[i - 1u];
        sites[i - 1u] = sites[j];
        sites[j] = t;
    }
    vor_point_t origin[1] = {{0, 0}};
    check_set("circle", n, &rng, origin, 1);
}

static void collinear_set(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    vor_point_t origin[1] = {{0, 0}};
    /* collinear sites, duplicates among them */
    for (uint32_t i = 0; i < 300u; i++) {
        int32_t t = test_rng_range(&rng, -200, 200);
        sites[i].x = 5 * t;
        sites[i].y = 2 * t;
    }
    check_set("collinear with duplicates", 300, &rng, origin, 1);
}

static void errors(void)
{
    /* errors */
    vor_t d;
    uint32_t got;
    CHECK(vor_init(&d, arena, sizeof arena, 10) == VOR_OK, "init");
    CHECK(vor_nearest(&d, (vor_point_t){0, 0}, VOR_NO_HINT, &got) == VOR_ERR_EMPTY, "empty diagram");
    CHECK(vor_insert(&d, (vor_point_t){7, 7}, NULL) == VOR_OK, "insert");
    CHECK(vor_nearest(&d, (vor_point_t){0, 0}, VOR_NO_HINT, &got) == VOR_OK && got == 0, "one site");
    CHECK(vor_nearest(&d, (vor_point_t){0, 0}, 5, &got) == VOR_ERR_ARG, "hint out of range");
    CHECK(vor_nearest(&d, (vor_point_t){0, 0}, 0, NULL) == VOR_ERR_ARG, "NULL result");
    uint32_t list[3] = {9, 9, 9}, found = 9;
    CHECK(vor_nearest_k(&d, (vor_point_t){0, 0}, VOR_NO_HINT, 3, list, &found) == VOR_OK && found == 1 &&
              list[0] == 0 && list[1] == 9,
          "k-nearest of one site");
    CHECK(vor_nearest_k(&d, (vor_point_t){0, 0}, VOR_NO_HINT, 0, NULL, &found) == VOR_OK && found == 0,
          "0-nearest");
    CHECK(vor_nearest_k(&d, (vor_point_t){0, 0}, VOR_NO_HINT, 3, list, NULL) == VOR_ERR_ARG, "NULL found");
    CHECK(vor_nearest_k(&d, (vor_point_t){0, 0}, 4, 3, list, &found) == VOR_ERR_ARG, "k-nearest bad hint");

    vor_tracker_t tracker;
    static vor_tracker_t zeroed; /* never begun: no diagram */
    CHECK(vor_tracker_begin(&zeroed, NULL) == VOR_ERR_ARG && zeroed.d == NULL,
          "tracker begun without a diagram");
    CHECK(vor_track(&zeroed, (vor_point_t){0, 0}, &got) == VOR_ERR_ARG, "tracker without a diagram");
    CHECK(vor_tracker_begin(&tracker, &d) == VOR_OK, "tracker begin");
    CHECK(vor_track(&tracker, (vor_point_t){0, 0}, NULL) == VOR_ERR_ARG, "tracker, NULL result");
    CHECK(vor_track(NULL, (vor_point_t){0, 0}, &got) == VOR_ERR_ARG, "NULL tracker");
}

static void inserts(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 77);
    vor_t d;
    uint32_t got;
    vor_tracker_t tracker;
    /* sites inserted one by one: the bucket grid is redrawn as they double,
     * cold queries start from it, and a tracker notices every insertion */
    CHECK(vor_init(&d, arena, sizeof arena, QUERY_SITES) == VOR_OK, "init");
    vor_tracker_begin(&tracker, &d);
    CHECK(vor_track(&tracker, (vor_point_t){0, 0}, &got) == VOR_ERR_EMPTY, "tracker on an empty diagram");
    for (uint32_t i = 0; i < 700u; i++) {
        sites[i].x = test_rng_range(&rng, -5000, 5000) + (int32_t)i * 50;
        sites[i].y = test_rng_range(&rng, -5000, 5000);
        first_of[i] = i;
        /* the tracker stands where the next site lands: the cell it caches
         * there is out of date after the insertion */
        vor_point_t here = {sites[i].x + 1, sites[i].y};
        CHECK(i == 0u || vor_track(&tracker, here, &got) == VOR_OK, "track");
        CHECK(vor_insert(&d, sites[i], NULL) == VOR_OK, "insert %u", i);
        if ((i & (i + 1u)) == 0u || i % 97u == 0u) { /* around each redraw */
            CHECK(vor_validate(&d, NULL) == VOR_OK, "grid after %u inserts", i + 1u);
            vor_point_t q = {test_rng_range(&rng, -6000, 40000), test_rng_range(&rng, -6000, 6000)};
            CHECK(vor_nearest(&d, q, VOR_NO_HINT, &got) == VOR_OK &&
                      got == brute_nearest(i + 1u, q),
                  "cold query after %u inserts", i + 1u);
        }
        CHECK(vor_track(&tracker, here, &got) == VOR_OK &&
                  got == brute_nearest(i + 1u, here),
              "tracker after %u inserts", i + 1u);
    }

    /* a tracker begun before vor_init of the same vor_t and arena, which
     * is then rebuilt with the revision count it had: the cell it cached
     * belongs to the old diagram and must not answer for the new one */
    for (uint32_t shift = 0; shift <= 100u; shift += 100u) {
        CHECK(vor_init(&d, arena, sizeof arena, QUERY_SITES) == VOR_OK, "init %u", shift);
        for (uint32_t i = 0; i < 9u; i++) { /* a 3 x 3 grid, moved right by shift */
            sites[i].x = (int32_t)(i % 3u * 100u + shift);
            sites[i].y = (int32_t)(i / 3u * 100u);
            first_of[i] = i;
        }
        CHECK(vor_build(&d, sites, 9, NULL, NULL) == VOR_OK, "build %u", shift);
        if (shift == 0u) {
            CHECK(vor_tracker_begin(&tracker, &d) == VOR_OK, "tracker begin");
        }
        vor_point_t q = {101, 100}; /* the centre site's, then the left one's */
        got = VOR_NO_HINT;
        int rc = vor_track(&tracker, q, &got);
        CHECK(rc == VOR_OK && got == brute_nearest(9, q),
              "tracker across vor_init, grid moved by %u: rc %d, site %u, brute force %u", shift,
              rc, got, brute_nearest(9, q));
    }
}

/* Boxes a walk cannot take in int64 alone: sites spanning 2^30 or more
 * on one axis only, and a small box at a corner of the range queried
 * from the far corners (more than 2^31 away). */
static void strip_sets(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 78);
    vor_point_t far[6] = {{INT32_MIN, INT32_MIN}, {INT32_MAX, INT32_MIN}, {INT32_MIN, INT32_MAX},
                          {INT32_MAX, INT32_MAX}, {INT32_MIN, 0},          {0, INT32_MIN}};
    for (uint32_t i = 0; i < 300u; i++) {
        sites[i].x = test_rng_range(&rng, 0, 999);
        sites[i].y = (int32_t)test_rng_u32(&rng);
    }
    check_set("tall strip", 300, &rng, far, 6);
    for (uint32_t i = 0; i < 300u; i++) {
        sites[i].x = (int32_t)test_rng_u32(&rng);
        sites[i].y = test_rng_range(&rng, 0, 999);
    }
    check_set("wide strip", 300, &rng, far, 6);
    for (uint32_t i = 0; i < 300u; i++) {
        sites[i].x = INT32_MAX - test_rng_range(&rng, 0, 1000000);
        sites[i].y = INT32_MAX - test_rng_range(&rng, 0, 1000000);
    }
    check_set("small box at the top corner", 300, &rng, far, 6);
    for (uint32_t i = 0; i < 300u; i++) {
        sites[i].x = INT32_MIN + test_rng_range(&rng, 0, 1000000);
        sites[i].y = INT32_MIN + test_rng_range(&rng, 0, 1000000);
    }
    check_set("small box at the bottom corner", 300, &rng, far, 6);
}

void test_queries(void)
{
    TEST_CASE("uniform") uniform_set();
    TEST_CASE("grid") grid_set();
    TEST_CASE("circle") circle_set();
    TEST_CASE("collinear") collinear_set();
    TEST_CASE("errors") errors();
    TEST_CASE("inserts") inserts();
    TEST_CASE("strips") strip_sets();
}
