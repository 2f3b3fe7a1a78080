/* SPDX-License-Identifier: MIT */
/*
 * test_true_output.c - the iterators report the true Delaunay
 * triangulation of the distinct sites, not the perturbed mesh.
 *
 * Every diagram is built by every builder (incremental in quadtree and
 * input order, both divide-and-conquer builders) and by vor_insert in a
 * random order, and checked against references computed here:
 *   - a monotone-chain hull that keeps collinear hull sites: h, its twice
 *     area, which sites are on it, and whether all sites are collinear;
 *   - the triangle count 2n - h - 2 (none when all sites are collinear),
 *     every triangle counterclockwise with positive twice area, the twice
 *     areas summing to the hull's (128-bit, exact up to the int32 corners);
 *   - for small sets, every reported triangle's circle empty, and brute
 *     force: every triple of nonzero area with no site strictly inside its
 *     circle, and every pair of sites whose Voronoi cells share a point;
 *   - neighbours: each site's degree from the triangles (plus one on the
 *     hull), the pairs joined by a reported triangle, and on all-collinear
 *     input the adjacent sites along the line.
 * The exact predicates used here (vor_orient2d, vor_incircle) are checked
 * against the generator's table in test_predicates.c.
 */
#include "test.h"
#include "vor.h"

#define MAX_SITES 1100u
#define SMALL_SITES 10u  /* brute force over all triples and quadruples */
#define EMPTY_SITES 90u  /* every reported circle checked against every site */
#define MATRIX_SITES 64u /* neighbour pairs compared one by one */

static vor_point_t input[MAX_SITES], shuffled[MAX_SITES];
static uint32_t duplicate_of[MAX_SITES];
static uint8_t arena[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(8)));

/* ------------------------------------------------------------------ */
/* 128-bit two's complement, for twice areas of int32 points            */

typedef struct {
    uint64_t lo, hi;
} wide_t;

static wide_t wide_add(wide_t a, wide_t b)
{
    wide_t r = {a.lo + b.lo, a.hi + b.hi};
    r.hi += (r.lo < a.lo) ? 1u : 0u;
    return r;
}

static wide_t wide_neg(wide_t a)
{
    wide_t r = {~a.lo + 1u, ~a.hi};
    r.hi += (r.lo == 0u) ? 1u : 0u;
    return r;
}

static int wide_sign(wide_t a)
{
    if ((a.hi >> 63) != 0u) {
        return -1;
    }
    return (a.hi != 0u || a.lo != 0u) ? 1 : 0;
}

static bool wide_equal(wide_t a, wide_t b)
{
    return a.lo == b.lo && a.hi == b.hi;
}

/* a * b for |a|, |b| < 2^33, by 32-bit halves */
static wide_t wide_mul(int64_t a, int64_t b)
{
    bool negative = (a < 0) != (b < 0);
    uint64_t x = (a < 0) ? 0u - (uint64_t)a : (uint64_t)a;
    uint64_t y = (b < 0) ? 0u - (uint64_t)b : (uint64_t)b;
    uint64_t x0 = x & 0xFFFFFFFFu, x1 = x >> 32, y0 = y & 0xFFFFFFFFu, y1 = y >> 32;
    wide_t low = {x0 * y0, 0}, middle = {(x0 * y1 + x1 * y0) << 32, (x0 * y1 + x1 * y0) >> 32};
    wide_t r = wide_add(low, middle);
    r.hi += x1 * y1;
    return negative ? wide_neg(r) : r;
}

/* Twice the signed area of (a, b, c): positive when counterclockwise. */
static wide_t twice_area(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c)
{
    int64_t bx = (int64_t)b->x - a->x, by = (int64_t)b->y - a->y;
    int64_t cx = (int64_t)c->x - a->x, cy = (int64_t)c->y - a->y;
    return wide_add(wide_mul(bx, cy), wide_neg(wide_mul(by, cx)));
}

static int turn(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c)
{
    return wide_sign(twice_area(a, b, c));
}

/* ------------------------------------------------------------------ */
/* The reference hull                                                  */

typedef struct {
    uint32_t ids[MAX_SITES]; /* the distinct sites */
    uint32_t n;
    uint32_t chain[2u * MAX_SITES + 2u];
    uint32_t h;            /* sites on the hull boundary, collinear ones kept */
    bool collinear;        /* all sites on one line (or fewer than 3) */
    wide_t twice_area;     /* of the hull */
    bool on_hull[MAX_SITES];
    uint32_t first, last;  /* lexicographic extremes */
} reference_t;

static reference_t ref;

static bool lex_less(const vor_point_t *a, const vor_point_t *b)
{
    return a->x < b->x || (a->x == b->x && a->y < b->y);
}

/* heapsort of ids by their points, lexicographically */
static void sift(const vor_point_t *s, uint32_t *ids, uint32_t root, uint32_t n)
{
    for (uint32_t child = 2u * root + 1u; child < n; child = 2u * root + 1u) {
        if (child + 1u < n && lex_less(&s[ids[child]], &s[ids[child + 1u]])) {
            child++;
        }
        if (!lex_less(&s[ids[root]], &s[ids[child]])) {
            return;
        }
        uint32_t t = ids[root];
        ids[root] = ids[child];
        ids[child] = t;
        root = child;
    }
}

static void sort_ids(const vor_point_t *s, uint32_t *ids, uint32_t n)
{
    for (uint32_t i = n / 2u; i-- > 0u;) {
        sift(s, ids, i, n);
    }
    for (uint32_t end = n; end-- > 1u;) {
        uint32_t t = ids[0];
        ids[0] = ids[end];
        ids[end] = t;
        sift(s, ids, 0, end);
    }
}

/* Andrew's monotone chain, popping only right turns so that sites on a
 * hull edge stay on the chain. */
static void make_reference(const vor_t *d, const uint32_t *dup)
{
    const vor_point_t *s = d->sites;
    ref.n = 0;
    for (uint32_t i = 0; i < d->site_count; i++) {
        ref.on_hull[i] = false;
        if (dup == NULL || dup[i] == i) {
            ref.ids[ref.n++] = i;
        }
    }
    sort_ids(s, ref.ids, ref.n);
    ref.collinear = true;
    for (uint32_t i = 2; i < ref.n; i++) {
        ref.collinear &= turn(&s[ref.ids[0]], &s[ref.ids[1]], &s[ref.ids[i]]) == 0;
    }
    ref.h = 0;
    ref.twice_area = (wide_t){0, 0};
    ref.first = ref.ids[0];
    ref.last = ref.ids[ref.n - 1u];
    if (ref.collinear) {
        return;
    }
    uint32_t k = 0;
    for (uint32_t i = 0; i < ref.n; i++) { /* lower chain */
        while (k >= 2u && turn(&s[ref.chain[k - 2u]], &s[ref.chain[k - 1u]], &s[ref.ids[i]]) < 0) {
            k--;
        }
        ref.chain[k++] = ref.ids[i];
    }
    uint32_t lower = k + 1u;
    for (uint32_t i = ref.n - 1u; i-- > 0u;) { /* upper chain */
        while (k >= lower && turn(&s[ref.chain[k - 2u]], &s[ref.chain[k - 1u]], &s[ref.ids[i]]) < 0) {
            k--;
        }
        ref.chain[k++] = ref.ids[i];
    }
    ref.h = k - 1u; /* the first site closes the chain */
    for (uint32_t i = 0; i < ref.h; i++) {
        ref.on_hull[ref.chain[i]] = true;
    }
    for (uint32_t i = 1; i + 1u < ref.h; i++) {
        ref.twice_area = wide_add(ref.twice_area,
                                  twice_area(&s[ref.chain[0]], &s[ref.chain[i]], &s[ref.chain[i + 1u]]));
    }
}

/* ------------------------------------------------------------------ */
/* Checks of one diagram                                               */

static uint32_t triangles_at[MAX_SITES];
static uint64_t joined[MATRIX_SITES]; /* bit j of row i: a triangle has edge i-j */

/* A distinct site's id: below count, and not a duplicate's. */
static bool is_site(const uint32_t *dup, uint32_t id, uint32_t count)
{
    return id < count && (dup == NULL || dup[id] == id);
}

/* No site strictly inside the circle of counterclockwise (a, b, c). */
static bool empty_circle(const vor_t *d, uint32_t a, uint32_t b, uint32_t c)
{
    const vor_point_t *s = d->sites;
    for (uint32_t i = 0; i < ref.n; i++) {
        if (vor_incircle(s[a], s[b], s[c], s[ref.ids[i]]) > 0) {
            return false;
        }
    }
    return true;
}

/* Brute force over the distinct sites: the triangles (triples of nonzero
 * area with an empty circle); whether four sites are cocircular; and the
 * pairs whose Voronoi cells share a point, counted (an empty circle
 * through both, or, on all-collinear input, nothing strictly between). */
typedef struct {
    uint32_t triangles, touching_pairs;
    bool cocircular;
    uint64_t touching[SMALL_SITES]; /* by position in ref.ids */
} brute_t;

static bool strictly_between(const vor_point_t *a, const vor_point_t *m, const vor_point_t *b)
{
    int64_t abx = (int64_t)b->x - a->x, aby = (int64_t)b->y - a->y;
    int64_t amx = (int64_t)m->x - a->x, amy = (int64_t)m->y - a->y;
    /* collinear, and 0 < (m - a).(b - a) < |b - a|^2, by coordinates */
    bool inside_x = (abx > 0) ? (amx > 0 && amx < abx) : (abx < 0) ? (amx < 0 && amx > abx) : amx == 0;
    bool inside_y = (aby > 0) ? (amy > 0 && amy < aby) : (aby < 0) ? (amy < 0 && amy > aby) : amy == 0;
    return turn(a, m, b) == 0 && inside_x && inside_y;
}

static void brute_force(const vor_t *d, brute_t *b)
{
    const vor_point_t *s = d->sites;
    const uint32_t *id = ref.ids;
    uint32_t n = ref.n;
    b->triangles = b->touching_pairs = 0;
    b->cocircular = false;
    for (uint32_t i = 0; i < n; i++) {
        b->touching[i] = 0;
    }
    for (uint32_t i = 0; i < n; i++) {
        for (uint32_t j = i + 1u; j < n; j++) {
            for (uint32_t k = j + 1u; k < n; k++) {
                int o = turn(&s[id[i]], &s[id[j]], &s[id[k]]);
                if (o == 0) {
                    continue;
                }
                uint32_t a = id[i], bb = (o > 0) ? id[j] : id[k], c = (o > 0) ? id[k] : id[j];
                bool empty = true;
                for (uint32_t l = 0; l < n; l++) {
                    int in = vor_incircle(s[a], s[bb], s[c], s[id[l]]);
                    empty &= in <= 0;
                    b->cocircular |= in == 0 && l != i && l != j && l != k;
                }
                if (empty) {
                    b->triangles++;
                    b->touching[i] |= (1ull << j) | (1ull << k);
                    b->touching[j] |= (1ull << i) | (1ull << k);
                    b->touching[k] |= (1ull << i) | (1ull << j);
                }
            }
        }
    }
    if (ref.collinear) {
        for (uint32_t i = 0; i < n; i++) {
            for (uint32_t j = 0; j < n; j++) {
                bool between = false;
                for (uint32_t m = 0; m < n && i != j; m++) {
                    between |= strictly_between(&s[id[i]], &s[id[m]], &s[id[j]]);
                }
                if (i != j && !between) {
                    b->touching[i] |= 1ull << j;
                }
            }
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        for (uint32_t j = i + 1u; j < n; j++) {
            b->touching_pairs += (uint32_t)((b->touching[i] >> j) & 1u);
        }
    }
}

/* Position of site id in ref.ids (small sets only). */
static uint32_t position(uint32_t id)
{
    uint32_t i = 0;
    while (i < ref.n && ref.ids[i] != id) {
        i++;
    }
    return i;
}

static unsigned failures_shown;

/* A set is named by a description and two numbers (sizes, a direction). */
static void check_diagram(const vor_t *d, const uint32_t *dup, const char *set, int32_t a,
                          int32_t b, const char *how)
{
    const vor_point_t *s = d->sites;
    unsigned long failed_before = test_failures();
    CHECK(vor_validate(d, NULL) == VOR_OK, "%s [%d %d], %s: vor_validate", set, (int)a, (int)b, how);
    make_reference(d, dup);
    bool matrix = d->site_count <= MATRIX_SITES;
    for (uint32_t i = 0; i < d->site_count; i++) {
        triangles_at[i] = 0;
        if (i < MATRIX_SITES) {
            joined[i] = 0;
        }
    }

    /* triangles */
    vor_triangle_iter_t it;
    uint32_t t[3], count = 0, bad = 0, not_empty = 0;
    wide_t area = {0, 0};
    vor_triangles_begin(&it, d);
    while (vor_triangles_next(&it, t)) {
        count++;
        if (!is_site(dup, t[0], d->site_count) || !is_site(dup, t[1], d->site_count) ||
            !is_site(dup, t[2], d->site_count) || t[0] == t[1] || t[1] == t[2] ||
            t[2] == t[0]) {
            bad++;
            continue;
        }
        wide_t twice = twice_area(&s[t[0]], &s[t[1]], &s[t[2]]);
        bad += (wide_sign(twice) <= 0) ? 1u : 0u;
        area = wide_add(area, twice);
        for (unsigned k = 0; k < 3u; k++) {
            uint32_t from = t[k], to = t[(k + 1u) % 3u];
            triangles_at[from]++;
            if (matrix) {
                joined[from] |= 1ull << to;
                joined[to] |= 1ull << from;
            }
        }
        if (ref.n <= EMPTY_SITES && !empty_circle(d, t[0], t[1], t[2])) {
            not_empty++;
        }
    }
    uint32_t expected = ref.collinear ? 0u : 2u * ref.n - ref.h - 2u;
    CHECK(count == expected, "%s [%d %d], %s: %u triangles, expected 2n - h - 2 = %u (n %u, h %u%s)", set, (int)a, (int)b,
          how, count, expected, ref.n, ref.h, ref.collinear ? ", collinear" : "");
    CHECK(bad == 0u, "%s [%d %d], %s: %u triangles with a bad id or not of positive area", set, (int)a, (int)b, how, bad);
    CHECK(wide_equal(area, ref.twice_area), "%s [%d %d], %s: the triangles do not cover the hull", set, (int)a, (int)b, how);
    CHECK(not_empty == 0u, "%s [%d %d], %s: %u triangles with a site inside their circle", set, (int)a, (int)b, how,
          not_empty);

    /* neighbours */
    uint32_t wrong_degree = 0, wrong_pair = 0, n;
    for (uint32_t site = 0; site < d->site_count; site++) {
        vor_neighbour_iter_t ni;
        uint32_t degree = 0;
        uint64_t seen = 0;
        vor_neighbours_begin(&ni, d, site);
        while (vor_neighbours_next(&ni, &n) && degree <= d->site_count) {
            degree++;
            if (!is_site(dup, n, d->site_count) || n == site) {
                wrong_pair++;
                continue;
            }
            if (matrix) {
                wrong_pair += ((seen >> n) & 1u) != 0u; /* reported twice */
                seen |= 1ull << n;
                if (ref.collinear) {
                    for (uint32_t m = 0; m < ref.n; m++) {
                        wrong_pair += strictly_between(&s[site], &s[ref.ids[m]], &s[n]) ? 1u : 0u;
                    }
                }
            }
        }
        uint32_t want;
        if (!is_site(dup, site, d->site_count) || ref.n < 2u) {
            want = 0;
        } else if (ref.collinear) {
            want = (site == ref.first || site == ref.last) ? 1u : 2u;
        } else {
            want = triangles_at[site] + (ref.on_hull[site] ? 1u : 0u);
        }
        wrong_degree += (degree != want) ? 1u : 0u;
        if (matrix && !ref.collinear) {
            wrong_pair += (seen != joined[site]) ? 1u : 0u;
        }
    }
    CHECK(wrong_degree == 0u, "%s [%d %d], %s: %u sites with a wrong number of neighbours", set, (int)a, (int)b, how,
          wrong_degree);
    CHECK(wrong_pair == 0u, "%s [%d %d], %s: %u wrong neighbours", set, (int)a, (int)b, how, wrong_pair);

    /* brute force */
    if (ref.n <= SMALL_SITES) {
        brute_t brute;
        brute_force(d, &brute);
        /* with four cocircular sites any of their diagonals is Delaunay:
         * the checks above (empty circles, count, area) decide then */
        CHECK(brute.cocircular || brute.triangles == count, "%s [%d %d], %s: %u triangles, brute force %u", set,
              how, count, brute.triangles);
        uint32_t pairs = 0, outside = 0;
        for (uint32_t site = 0; site < d->site_count; site++) {
            vor_neighbour_iter_t ni;
            vor_neighbours_begin(&ni, d, site);
            while (vor_neighbours_next(&ni, &n) && pairs <= d->site_count * d->site_count) {
                uint32_t i = position(site), j = position(n);
                pairs += (site < n) ? 1u : 0u;
                outside += (i >= ref.n || j >= ref.n || ((brute.touching[i] >> j) & 1u) == 0u) ? 1u : 0u;
            }
        }
        CHECK(outside == 0u && (brute.cocircular || pairs == brute.touching_pairs),
              "%s [%d %d], %s: %u neighbour pairs (%u whose cells do not touch), brute force %u", set, (int)a, (int)b, how,
              pairs, outside, brute.touching_pairs);
    }
    if (test_failures() != failed_before && failures_shown++ < 3u) {
        for (uint32_t i = 0; i < d->site_count && i < 40u; i++) {
            test_printf("    site %u: %d %d\n", i, (int)s[i].x, (int)s[i].y);
        }
    }
}

/* ------------------------------------------------------------------ */
/* Every builder                                                       */

static void check_set(const char *set, int32_t a, int32_t b, uint32_t n, test_rng_t *rng)
{
    /* vor_build in both orders, vor_build_dc with both splits */
    static const struct {
        const char *name;
        bool dc;
        vor_build_options_t options;
    } builders[] = {
        {"incremental", false, {VOR_ORDER_QUADTREE, VOR_DC_QUADTREE, 0}},
        {"incremental, input order", false, {VOR_ORDER_INPUT, VOR_DC_QUADTREE, 0}},
        {"divide and conquer", true, {VOR_ORDER_QUADTREE, VOR_DC_XSPLIT, 0}},
        {"divide and conquer, quadtree", true, {VOR_ORDER_QUADTREE, VOR_DC_QUADTREE, 0}},
    };
    vor_t d;
    for (unsigned k = 0; k < sizeof builders / sizeof builders[0]; k++) {
        CHECK(vor_init(&d, arena, sizeof arena, MAX_SITES) == VOR_OK, "init");
        int err = builders[k].dc
                      ? vor_build_dc(&d, input, n, &builders[k].options, duplicate_of)
                      : vor_build(&d, input, n, &builders[k].options, duplicate_of);
        CHECK(err == VOR_OK, "%s [%d %d], %s: build", set, (int)a, (int)b, builders[k].name);
        check_diagram(&d, duplicate_of, set, a, b, builders[k].name);
    }
    /* vor_insert in a random order: ids follow the order of insertion */
    for (uint32_t i = 0; i < n; i++) {
        shuffled[i] = input[i];
    }
    for (uint32_t i = n; i > 1u; i--) {
        uint32_t j = test_rng_u32(rng) % i;
        vor_point_t p = shuffled[i - 1u];
        shuffled[i - 1u] = shuffled[j];
        shuffled[j] = p;
    }
    CHECK(vor_init(&d, arena, sizeof arena, MAX_SITES) == VOR_OK, "init");
    bool inserted = true;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t id;
        int err = vor_insert(&d, shuffled[i], &id);
        inserted &= err == VOR_OK || err == VOR_ERR_DUPLICATE;
    }
    CHECK(inserted, "%s [%d %d]: vor_insert", set, (int)a, (int)b);
    check_diagram(&d, NULL, set, a, b, "vor_insert, random order");
}

/* ------------------------------------------------------------------ */
/* Point sets                                                          */

/* n points base + t (dx, dy), t from t0 in steps of 0 (a duplicate) to 3. */
static uint32_t line(int32_t bx, int32_t by, int32_t dx, int32_t dy, int32_t t0, uint32_t n,
                     test_rng_t *rng)
{
    int64_t t = t0;
    for (uint32_t i = 0; i < n; i++) {
        input[i].x = (int32_t)(bx + t * dx);
        input[i].y = (int32_t)(by + t * dy);
        t += (int64_t)(test_rng_u32(rng) % 4u); /* 0: a duplicate */
    }
    return n;
}

static void check_lines(test_rng_t *rng)
{
    /* directions of many slopes, magnitudes from 1 to the int32 corners */
    static const int32_t directions[][2] = {
        {1, 0}, {0, 1}, {1, 1}, {1, -1}, {3, 5}, {-7, 2}, {1000, 1}, {1, -999},
        {65535, 65536}, {-46341, 46340}, {1 << 20, 3}, {7, 1 << 24},
    };
    for (unsigned k = 0; k < sizeof directions / sizeof directions[0]; k++) {
        int32_t dx = directions[k][0], dy = directions[k][1];
        int64_t ax = (dx < 0) ? -(int64_t)dx : dx, ay = (dy < 0) ? -(int64_t)dy : dy;
        int64_t big = (ax > ay) ? ax : ay;
        uint32_t n = 3u + test_rng_u32(rng) % 40u;
        /* steps of up to 3 a point: a line through the origin spans at
         * most 3 n + 3 steps, when they fit in int32 */
        if (big * (int64_t)(3u * n + 3u) <= INT32_MAX) {
            line(0, 0, dx, dy, -(int32_t)(3u * n / 2u), n, rng);
            check_set("line through 0 of direction", dx, dy, n, rng);
        }
        /* from an int32 corner inwards: the largest magnitudes */
        int64_t steps = ((int64_t)UINT32_MAX) / big;
        uint32_t m = (steps < 60) ? (uint32_t)(steps / 3 + 1) : 20u;
        if (m >= 2u) {
            int32_t bx = (dx > 0) ? INT32_MIN : INT32_MAX, by = (dy > 0) ? INT32_MIN : INT32_MAX;
            line(bx, by, dx, dy, 0, m, rng);
            check_set("line from an int32 corner of direction", dx, dy, m, rng);
            /* plus the two corners next to the base, at least one off
             * the line: its sites on a hull edge or inside */
            input[m] = (vor_point_t){~bx, by};
            input[m + 1u] = (vor_point_t){bx, ~by};
            check_set("line from a corner and 2 sites off it, direction", dx, dy, m + 2u, rng);
        }
    }
    /* the two diagonals of the int32 square, end to end */
    input[0] = (vor_point_t){INT32_MIN, INT32_MIN};
    input[1] = (vor_point_t){INT32_MAX, INT32_MAX};
    input[2] = (vor_point_t){0, 0};
    input[3] = (vor_point_t){-1, -1};
    input[4] = (vor_point_t){INT32_MAX - 1, INT32_MAX - 1};
    check_set("the int32 diagonal", 0, 0, 5, rng);
    input[5] = (vor_point_t){INT32_MIN, INT32_MAX};
    input[6] = (vor_point_t){INT32_MAX, INT32_MIN};
    check_set("both int32 diagonals", 0, 0, 7, rng);
}

/* A cols x rows grid of the given spacing from origin, each point kept
 * with probability keep / 8. Returns the number kept. */
static uint32_t grid(int32_t ox, int32_t oy, int32_t spacing, uint32_t cols, uint32_t rows,
                     uint32_t keep, test_rng_t *rng)
{
    uint32_t n = 0;
    for (uint32_t r = 0; r < rows; r++) {
        for (uint32_t c = 0; c < cols; c++) {
            if (test_rng_u32(rng) % 8u < keep) {
                input[n].x = (int32_t)(ox + (int64_t)c * spacing);
                input[n].y = (int32_t)(oy + (int64_t)r * spacing);
                n++;
            }
        }
    }
    return n;
}

static void check_grids(test_rng_t *rng)
{
    static const uint32_t sides[][2] = {{2, 3}, {3, 3}, {4, 4}, {1, 7}, {9, 5}, {12, 12}, {30, 30}};
    for (unsigned g = 0; g < sizeof sides / sizeof sides[0]; g++) {
        uint32_t cols = sides[g][0], rows = sides[g][1];
        uint32_t side = (cols > rows) ? cols : rows;
        /* 2^30 / sqrt(n) for the square grids: the spacing of n sites
         * spread over 2^30 */
        int32_t spacings[4] = {1, 1000, 1 << 20, (int32_t)((1u << 30) / side)};
        for (unsigned k = 0; k < 4u; k++) {
            int32_t spacing = spacings[k];
            int32_t ox = -(int32_t)((int64_t)spacing * (cols / 2u)), oy = 7 - (int32_t)rows;
            uint32_t n = grid(ox, oy, spacing, cols, rows, 8u, rng);
            check_set("grid (spacing, 100 columns + rows)", spacing, (int32_t)(100u * cols + rows), n,
                      rng);
            n = grid(ox, oy, spacing, cols, rows, 6u, rng);
            check_set("grid with holes (spacing, 100 columns + rows)", spacing,
                      (int32_t)(100u * cols + rows), n, rng);
        }
    }
    /* at the int32 corners: the largest spacing that fits */
    uint32_t n = grid(INT32_MIN, INT32_MIN, (int32_t)(UINT32_MAX / 5u), 6, 6, 8u, rng);
    check_set("grid over the whole int32 square", 6, 6, n, rng);
    /* a grid with every point twice */
    n = grid(-5, -5, 3, 5, 5, 8u, rng);
    for (uint32_t i = 0; i < n; i++) {
        input[n + i] = input[(i * 7u) % n];
    }
    check_set("grid with every point twice", 5, 5, 2u * n, rng);
}

static void check_random(test_rng_t *rng)
{
    static const uint32_t sizes[] = {3, 4, 5, 7, 10, 40, 300};
    for (unsigned round = 0; round < 3u; round++) {
        for (unsigned k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            uint32_t n = sizes[k];
            for (uint32_t i = 0; i < n; i++) { /* 16-bit, often small ranges */
                int32_t range = (round == 0u) ? 32767 : (round == 1u) ? 3 : 100;
                input[i].x = test_rng_range(rng, -range - 1, range);
                input[i].y = test_rng_range(rng, -range - 1, range);
            }
            check_set("16-bit random, points and round", (int32_t)n, (int32_t)round, n, rng);
        }
    }
}

/* Lattice points on circles: x^2 + y^2 = 25 (12 points), = 5^2 13^2
 * scaled, with and without the centre and points inside and outside. */
static void check_cocircular(test_rng_t *rng)
{
    static const int32_t on5[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                       {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    static const int32_t scales[] = {1, 1000, 1 << 20, 400000000};
    for (unsigned k = 0; k < sizeof scales / sizeof scales[0]; k++) {
        int32_t scale = scales[k];
        for (unsigned extra = 0; extra < 3u; extra++) {
            uint32_t n = 0;
            for (unsigned i = 0; i < 12u; i++) {
                if (extra != 2u || i % 3u != 0u) {
                    input[n].x = on5[i][0] * scale;
                    input[n].y = on5[i][1] * scale;
                    n++;
                }
            }
            if (extra == 1u) {
                input[n++] = (vor_point_t){0, 0};
            }
            if (extra == 2u) { /* the two circles' lattice points, crossing */
                input[n++] = (vor_point_t){5 * scale, 5 * scale};
                input[n++] = (vor_point_t){(int32_t)(scale / 2), -(int32_t)(scale / 3)};
            }
            check_set("circle of radius 5, scale and variant", scale, (int32_t)extra, n, rng);
        }
    }
    /* concentric squares and a regular octagon's lattice version */
    uint32_t n = 0;
    for (int32_t r = 1; r <= 6; r++) {
        input[n++] = (vor_point_t){r, r};
        input[n++] = (vor_point_t){-r, r};
        input[n++] = (vor_point_t){-r, -r};
        input[n++] = (vor_point_t){r, -r};
    }
    check_set("concentric squares", 6, 0, n, rng);
}

void test_true_output(void)
{
    test_rng_t rng;
    TEST_CASE("lines") check_lines(test_rng_seed(&rng, 2026));
    TEST_CASE("grids") check_grids(test_rng_seed(&rng, 2026));
    TEST_CASE("random") check_random(test_rng_seed(&rng, 2026));
    TEST_CASE("cocircular") check_cocircular(test_rng_seed(&rng, 2026));
}
