/* SPDX-License-Identifier: MIT */
/*
 * test_centroid.c - vor_cell_centroid against independent references:
 *   - small coordinates: the cell found by brute force (every pair of
 *     lines among the box sides and the bisectors with every other site,
 *     kept when it satisfies every half-plane), sorted around its lowest
 *     vertex, and its area and centroid by the shoelace formula over the
 *     product of all denominators, in the test's own 2048-bit integers;
 *     the rounding is checked as exact inequalities;
 *   - grids up to the int32 limits: rectangular cells whose area and
 *     centre follow from the grid's spacing in int64;
 *   - wide coordinates: the same cells moved by an integer vector (equal
 *     results, moved) and turned half round (equal areas, centroids
 *     negated up to a half), each with other denominators;
 *   - the rounded areas of all cells add up to the box's area within
 *     half a unit per cell;
 *   - bad arguments, a scratch too small, any alignment.
 * The power cells (vor_power_cell, vor_power_cell_centroid; "power_*"
 * cases) against the same brute force with weighted bisectors: random
 * weights (hidden sites among them), equal weights, one point with
 * several weights, collinear sites, and grids whose weights are a linear
 * function of the position (every four cocircular sites then stay tied)
 * or random;
 * each cell's rounded vertices against the brute force's exact corners,
 * its area and centroid, and the tiling of the box.
 */
#include "test.h"
#include "vor.h"
#include "vor_power.h"

#define WIDE_LIMBS 64u
#include "wide.h"

#define CEN_SITES 16u
#define CEN_MAX_VERTICES VOR_CELL_MAX_VERTICES(CEN_SITES)

static vor_point_t sites[CEN_SITES];
static uint32_t first_of[CEN_SITES];
static uint8_t arena[VOR_ARENA_BYTES(CEN_SITES)] __attribute__((aligned(8)));
static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(CEN_MAX_VERTICES) + 8u];
/* The power cases' weights, and their arena; NULL weights: Voronoi cells. */
static int64_t weights[CEN_SITES];
static const int64_t *cell_weights;
static uint8_t power_arena[VOR_POWER_ARENA_BYTES(CEN_SITES)] __attribute__((aligned(8)));

/* ------------------------------------------------------------------ */
/* 2048-bit two's complement integers (tests/wide.h)                   */

/* Is r = floor(num / den + 1/2), i.e. (2r - 1) den <= 2 num < (2r + 1) den,
 * for den > 0? */
static bool rounds_to(const wide_t *num, const wide_t *den, int64_t r)
{
    wide_t twice, low, high;
    wide_mul_i64(&twice, num, 2);
    wide_mul_i64(&low, den, 2 * r - 1);
    wide_mul_i64(&high, den, 2 * r + 1);
    return wide_compare(&low, &twice) <= 0 && wide_compare(&twice, &high) < 0;
}

/* ------------------------------------------------------------------ */
/* The brute-force cell, for coordinates below 2^10 in magnitude       */

/* Half-plane a x + b y <= c. */
typedef struct {
    int64_t a, b, c;
} half_plane_t;

/* The point (x / w, y / w), w > 0. */
typedef struct {
    int64_t x, y, w;
} rational_point_t;

#define MAX_PLANES (CEN_SITES + 4u)
#define MAX_CORNERS 40u

static uint32_t half_planes(uint32_t site, uint32_t n, vor_box_t box, half_plane_t *h)
{
    uint32_t m = 0;
    h[m++] = (half_plane_t){-1, 0, -(int64_t)box.x0};
    h[m++] = (half_plane_t){1, 0, box.x1};
    h[m++] = (half_plane_t){0, -1, -(int64_t)box.y0};
    h[m++] = (half_plane_t){0, 1, box.y1};
    const vor_point_t s = sites[site];
    for (uint32_t t = 0; t < n; t++) {
        const vor_point_t o = sites[t];
        /* |p - s|^2 - ws <= |p - o|^2 - wo (weights 0 without them) */
        int64_t shift = (cell_weights != NULL) ? cell_weights[site] - cell_weights[t] : 0;
        if (o.x == s.x && o.y == s.y && shift >= 0) {
            continue; /* itself, a duplicate, or a lighter site at its point */
        }
        /* a heavier site at its point: 0 <= shift < 0, nowhere */
        h[m++] = (half_plane_t){2 * ((int64_t)o.x - s.x), 2 * ((int64_t)o.y - s.y),
                                (int64_t)o.x * o.x + (int64_t)o.y * o.y -
                                    (int64_t)s.x * s.x - (int64_t)s.y * s.y + shift};
    }
    return m;
}

/* (qa - p) x (qb - p) for rational points, times p.w^2 qa.w qb.w > 0. */
static int orientation(rational_point_t p, rational_point_t qa, rational_point_t qb)
{
    wide_t ax, ay, bx, by, t, u;
    wide_set(&ax, qa.x * p.w - p.x * qa.w);
    wide_set(&ay, qa.y * p.w - p.y * qa.w);
    wide_set(&bx, qb.x * p.w - p.x * qb.w);
    wide_set(&by, qb.y * p.w - p.y * qb.w);
    wide_mul(&t, &ax, &by);
    wide_mul(&u, &ay, &bx);
    return wide_compare(&t, &u);
}

/* The cell's corners, counterclockwise from the lowest; their number. */
static uint32_t brute_cell(uint32_t site, uint32_t n, vor_box_t box, rational_point_t *corner)
{
    half_plane_t h[MAX_PLANES];
    uint32_t m = half_planes(site, n, box, h), k = 0;
    for (uint32_t i = 0; i < m; i++) {
        for (uint32_t j = i + 1; j < m; j++) {
            int64_t w = h[i].a * h[j].b - h[j].a * h[i].b;
            if (w == 0) {
                continue;
            }
            rational_point_t p = {h[i].c * h[j].b - h[j].c * h[i].b,
                                  h[i].a * h[j].c - h[j].a * h[i].c, w};
            if (w < 0) {
                p.x = -p.x;
                p.y = -p.y;
                p.w = -p.w;
            }
            bool inside = true;
            for (uint32_t l = 0; l < m && inside; l++) {
                inside = h[l].a * p.x + h[l].b * p.y <= h[l].c * p.w;
            }
            for (uint32_t l = 0; l < k && inside; l++) {
                inside = !(corner[l].x * p.w == p.x * corner[l].w &&
                           corner[l].y * p.w == p.y * corner[l].w);
            }
            if (inside && CHECK(k < MAX_CORNERS, "brute cell: too many corners")) {
                corner[k++] = p;
            }
        }
    }
    /* lowest first, then the rest by angle around it (all within a half
     * turn, no three corners of a convex polygon collinear) */
    for (uint32_t i = 1; i < k; i++) {
        int64_t dy = corner[i].y * corner[0].w - corner[0].y * corner[i].w;
        int64_t dx = corner[i].x * corner[0].w - corner[0].x * corner[i].w;
        if (dy < 0 || (dy == 0 && dx < 0)) {
            rational_point_t t = corner[0];
            corner[0] = corner[i];
            corner[i] = t;
        }
    }
    for (uint32_t i = 1; i < k; i++) {
        for (uint32_t j = i + 1; j < k; j++) {
            if (orientation(corner[0], corner[i], corner[j]) < 0) {
                rational_point_t t = corner[i];
                corner[i] = corner[j];
                corner[j] = t;
            }
        }
    }
    return k;
}

/* Shoelace over W = prod w_i: twice the area is area2 / W^2, the moments
 * moment_x / W^2, moment_y / W^2 (centroid = moment / 3 area2). */
static void shoelace(const rational_point_t *v, uint32_t k, wide_t *area2, wide_t *moment_x,
                     wide_t *moment_y, wide_t *w_squared)
{
    wide_t t, u, others;
    wide_set(area2, 0);
    wide_set(moment_x, 0);
    wide_set(moment_y, 0);
    wide_set(w_squared, 1);
    for (uint32_t i = 0; i < k; i++) {
        wide_mul_i64(w_squared, w_squared, v[i].w);
        wide_mul_i64(w_squared, w_squared, v[i].w);
    }
    for (uint32_t i = 0; i < k; i++) {
        uint32_t j = (i + 1u) % k;
        rational_point_t p = v[i], q = v[j];
        /* (W / (w_i w_j))^2 */
        wide_set(&others, 1);
        for (uint32_t l = 0; l < k; l++) {
            if (l != i && l != j) {
                wide_mul_i64(&others, &others, v[l].w);
            }
        }
        wide_mul(&others, &others, &others);
        /* |x|, |y| < 2^35: the products need more than 64 bits */
        wide_t cross, c2, a, b;
        wide_set(&a, p.x);
        wide_set(&b, q.y);
        wide_mul(&cross, &a, &b);
        wide_set(&a, -q.x);
        wide_set(&b, p.y);
        wide_mul(&c2, &a, &b);
        wide_add(&cross, &c2);
        wide_mul(&t, &cross, &others);
        wide_mul_i64(&u, &t, p.w * q.w);
        wide_add(area2, &u);
        wide_mul_i64(&u, &t, p.x * q.w + q.x * p.w);
        wide_add(moment_x, &u);
        wide_mul_i64(&u, &t, p.y * q.w + q.y * p.w);
        wide_add(moment_y, &u);
    }
}

static int32_t clamp32(int32_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* A power cell's rounded vertices against the brute force's corners. */
static void check_power_vertices(const vor_power_t *pd, uint32_t site, vor_box_t box,
                                 const rational_point_t *corner, uint32_t k, const char *name)
{
    vor_point_t got[CEN_MAX_VERTICES];
    uint32_t count = 0;
    int err = vor_power_cell(pd, site, &box, got, CEN_MAX_VERTICES, &count);
    uint32_t expected = (k >= 3u) ? k : 0u;
    bool same = (err == VOR_OK) && (count == expected);
    for (uint32_t i = 0; same && i < count; i++) {
        wide_t x, y, w;
        wide_set(&x, corner[i].x);
        wide_set(&y, corner[i].y);
        wide_set(&w, corner[i].w);
        same = rounds_to(&x, &w, got[i].x) && rounds_to(&y, &w, got[i].y);
    }
    CHECK(same, "%s: power cell %u: error %d, %u vertices (brute force %u)", name, site, err,
          count, expected);
}

/* One cell against the brute force (a power cell when pd is not NULL);
 * returns its rounded area. */
static uint64_t check_cell(const vor_t *d, const vor_power_t *pd, uint32_t site, uint32_t n,
                           vor_box_t box, const char *name)
{
    rational_point_t corner[MAX_CORNERS];
    uint32_t k = brute_cell(site, n, box, corner);
    vor_centroid_t got;
    int err;
    if (pd != NULL) {
        check_power_vertices(pd, site, box, corner, k, name);
        err = vor_power_cell_centroid(pd, site, &box, scratch, sizeof scratch, &got);
    } else {
        err = vor_cell_centroid(d, site, &box, scratch, sizeof scratch, &got);
    }
    if (!CHECK(err == VOR_OK, "%s: site %u: error %d", name, site, err)) {
        return 0;
    }
    if (k < 3u) {
        CHECK(got.area == 0 && got.vertices == 0 &&
                  got.point.x == clamp32(sites[site].x, box.x0, box.x1) &&
                  got.point.y == clamp32(sites[site].y, box.y0, box.y1),
              "%s: site %u: no area expected, got area %u, %u vertices, (%d, %d)", name, site,
              (unsigned)got.area, got.vertices, got.point.x, got.point.y);
        return got.area;
    }
    wide_t area2, mx, my, w2, three_area2, twice_w2;
    shoelace(corner, k, &area2, &mx, &my, &w2);
    wide_mul_i64(&three_area2, &area2, 3);
    wide_mul_i64(&twice_w2, &w2, 2);
    CHECK(got.vertices == k && rounds_to(&area2, &twice_w2, (int64_t)got.area) &&
              rounds_to(&mx, &three_area2, got.point.x) && rounds_to(&my, &three_area2, got.point.y),
          "%s: site %u: %u vertices (brute force %u), area %u, centroid (%d, %d)", name, site,
          got.vertices, k, (unsigned)got.area, got.point.x, got.point.y);
    return got.area;
}

static bool build(vor_t *d, uint32_t n)
{
    return CHECK(vor_init(d, arena, sizeof arena, CEN_SITES) == VOR_OK &&
                     vor_build(d, sites, n, NULL, first_of) == VOR_OK,
                 "build %u sites", n);
}

static bool build_power(vor_power_t *pd, uint32_t n)
{
    return CHECK(vor_power_init(pd, power_arena, sizeof power_arena, CEN_SITES) == VOR_OK &&
                     vor_power_build(pd, sites, weights, n, first_of) == VOR_OK,
                 "power build %u sites", n);
}

/* Every cell of sites[0 .. n) (power cells with weights[], when power). */
static void check_all_cells(uint32_t n, vor_box_t box, bool power, const char *name)
{
    vor_t d;
    vor_power_t pd;
    cell_weights = power ? weights : NULL;
    if (power ? !build_power(&pd, n) : !build(&d, n)) {
        return;
    }
    uint64_t total = 0, cells = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (first_of[i] == i) {
            total += check_cell(&d, power ? &pd : NULL, i, n, box, name);
            cells++;
        }
    }
    /* the exact areas tile the box; each rounded one is within 1/2 */
    uint64_t box_area = (uint64_t)((int64_t)box.x1 - box.x0) * (uint64_t)((int64_t)box.y1 - box.y0);
    uint64_t gap = (total > box_area) ? total - box_area : box_area - total;
    CHECK(2u * gap <= cells, "%s: areas add up to %u, box %u", name, (unsigned)total,
          (unsigned)box_area);
}

static void check_all(uint32_t n, vor_box_t box, const char *name)
{
    check_all_cells(n, box, false, name);
}

static void test_brute_force(test_rng_t *rng)
{
    for (unsigned round = 0; round < 60u; round++) {
        uint32_t n = 1u + test_rng_u32(rng) % CEN_SITES;
        unsigned kind = round % 4u;
        int32_t spread = (kind == 3u) ? 6 : 1000;
        for (uint32_t i = 0; i < n; i++) {
            switch (kind) {
            case 0: /* uniform */
                sites[i].x = test_rng_range(rng, -spread, spread);
                sites[i].y = test_rng_range(rng, -spread, spread);
                break;
            case 1: /* collinear, with repeats */
                sites[i].x = test_rng_range(rng, -20, 20) * 40;
                sites[i].y = sites[i].x / 2 + 7;
                break;
            case 2: /* a grid: cocircular fours */
                sites[i].x = (int32_t)(i % 4u) * 300 - 450;
                sites[i].y = (int32_t)(i / 4u) * 300 - 450;
                break;
            default: /* a small cluster, many duplicates */
                sites[i].x = test_rng_range(rng, -spread, spread);
                sites[i].y = test_rng_range(rng, -spread, spread);
                break;
            }
        }
        /* boxes around all sites, inside the cluster, or away from it */
        int32_t x0 = test_rng_range(rng, -1000, 900), y0 = test_rng_range(rng, -1000, 900);
        int32_t size = (round % 3u == 0u) ? 1000 : (round % 3u == 1u) ? 9 : 300;
        vor_box_t box = {x0, y0, x0 + test_rng_range(rng, 1, size), y0 + test_rng_range(rng, 1, size)};
        if (round % 5u == 0u) {
            box = (vor_box_t){-1000, -1000, 1000, 1000};
        }
        check_all(n, box, (kind == 0u) ? "uniform" : (kind == 1u) ? "collinear" : (kind == 2u) ? "grid" : "cluster");
    }
}

/* ------------------------------------------------------------------ */
/* Grids up to the int32 limits: rectangular cells                     */

/* The part [lo, hi] of the box's [b0, b1] nearer to the grid line at
 * `at` (spacing `step`, first and last unbounded outside); false when
 * it has no length. */
static bool grid_span(int64_t at, int64_t step, bool first, bool last, int64_t b0, int64_t b1,
                      int64_t *lo, int64_t *hi)
{
    *lo = first ? b0 : (at - step / 2 > b0 ? at - step / 2 : b0);
    *hi = last ? b1 : (at + step / 2 < b1 ? at + step / 2 : b1);
    return *lo < *hi;
}

/* floor((lo + hi) / 2 + 1/2) without overflow or a negative shift */
static int32_t rounded_middle(int64_t lo, int64_t hi)
{
    int64_t sum = lo + hi + 1; /* floor(sum / 2) */
    return (int32_t)((sum - ((sum % 2 + 2) % 2)) / 2);
}

static void check_grid(uint32_t nx, uint32_t ny, int32_t x0, int32_t y0, int32_t step,
                       vor_box_t box, const char *name)
{
    uint32_t n = nx * ny;
    for (uint32_t i = 0; i < n; i++) {
        sites[i].x = (int32_t)((int64_t)x0 + (int64_t)(i % nx) * step);
        sites[i].y = (int32_t)((int64_t)y0 + (int64_t)(i / nx) * step);
    }
    vor_t d;
    if (!build(&d, n)) {
        return;
    }
    uint32_t wrong = 0;
    for (uint32_t i = 0; i < n; i++) {
        int64_t xl, xh, yl, yh;
        bool has_x = grid_span(sites[i].x, step, i % nx == 0u, i % nx == nx - 1u, box.x0, box.x1, &xl, &xh);
        bool has_y = grid_span(sites[i].y, step, i / nx == 0u, i / nx == ny - 1u, box.y0, box.y1, &yl, &yh);
        vor_centroid_t got;
        int err = vor_cell_centroid(&d, i, &box, scratch, sizeof scratch, &got);
        bool ok;
        if (has_x && has_y) {
            ok = err == VOR_OK && got.area == (uint64_t)(xh - xl) * (uint64_t)(yh - yl) &&
                 got.point.x == rounded_middle(xl, xh) && got.point.y == rounded_middle(yl, yh) &&
                 got.vertices == 4u;
        } else {
            ok = err == VOR_OK && got.area == 0 && got.vertices == 0 &&
                 got.point.x == clamp32(sites[i].x, box.x0, box.x1) &&
                 got.point.y == clamp32(sites[i].y, box.y0, box.y1);
        }
        if (!ok && wrong++ == 0u) {
            CHECK(false, "%s: site %u: err %d, area %u/%u, centroid (%d, %d), %u vertices", name,
                  i, err, (unsigned)(got.area >> 32), (unsigned)got.area, got.point.x,
                  got.point.y, got.vertices);
        }
    }
    CHECK(wrong == 0, "%s: %u cells wrong", name, wrong);
}

static void test_grids(test_rng_t *rng)
{
    vor_box_t all = {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX};
    /* one site: the whole int32 plane, area (2^32 - 1)^2 */
    check_grid(1, 1, 5, -7, 2, all, "one site, whole plane");
    check_grid(4, 4, -(3 << 29), -(3 << 29), 1 << 30, all, "huge grid, whole plane");
    check_grid(4, 1, INT32_MIN, 0, 1 << 30, all, "huge strips");
    check_grid(3, 3, 0, 0, 10, (vor_box_t){-3, 4, 25, 17}, "small grid");
    check_grid(3, 3, 0, 0, 10, (vor_box_t){1, 1, 4, 3}, "box inside one cell");
    check_grid(3, 3, 0, 0, 10, (vor_box_t){5, 5, 15, 15}, "box on cell corners");
    check_grid(3, 3, 0, 0, 10, (vor_box_t){100, 100, 103, 101}, "box away from sites");
    for (unsigned round = 0; round < 20u; round++) {
        int32_t step = 2 * test_rng_range(rng, 1, 1 << 26);
        int32_t x = test_rng_range(rng, INT32_MIN / 2, INT32_MAX / 2);
        int32_t y = test_rng_range(rng, INT32_MIN / 2, INT32_MAX / 2);
        int32_t bx = test_rng_range(rng, INT32_MIN, INT32_MAX - 1);
        int32_t by = test_rng_range(rng, INT32_MIN, INT32_MAX - 1);
        vor_box_t box = {bx, by, test_rng_range(rng, bx + 1, INT32_MAX),
                         test_rng_range(rng, by + 1, INT32_MAX)};
        if (round % 2u == 0u) { /* around the grid, odd widths: halves */
            box = (vor_box_t){x - test_rng_range(rng, 0, step), y - test_rng_range(rng, 0, step),
                              x + 3 * step + test_rng_range(rng, 0, step),
                              y + 2 * step + test_rng_range(rng, 0, step)};
        }
        check_grid(4, 3, x, y, step, box, "random grid");
    }
}

/* ------------------------------------------------------------------ */
/* Wide coordinates: exact invariances                                 */

/* The cells of n sites with wide coordinates, against the same sites and
 * box moved by (dx, dy) (the rounding commutes with an integer shift:
 * equal results, shifted) and turned half round, (x, y) -> (-x, -y) (the
 * same area; the centroid negated, up to one unit where the exact value
 * is a half). Every product of denominators differs between the three. */
static void check_invariances(uint32_t n, vor_box_t box, int32_t dx, int32_t dy, const char *name)
{
    static vor_centroid_t first[CEN_SITES];
    static vor_point_t original[CEN_SITES];
    vor_t d;
    for (uint32_t i = 0; i < n; i++) {
        original[i] = sites[i];
    }
    if (!build(&d, n)) {
        return;
    }
    uint32_t wrong = 0;
    for (uint32_t i = 0; i < n; i++) {
        first[i].vertices = 0;
        if (first_of[i] == i &&
            vor_cell_centroid(&d, i, &box, scratch, sizeof scratch, &first[i]) != VOR_OK) {
            wrong++;
        }
    }
    for (unsigned turn = 0; turn < 2u; turn++) {
        vor_box_t moved = box;
        for (uint32_t i = 0; i < n; i++) {
            sites[i].x = turn ? -original[i].x : original[i].x + dx;
            sites[i].y = turn ? -original[i].y : original[i].y + dy;
        }
        if (turn) {
            moved = (vor_box_t){-box.x1, -box.y1, -box.x0, -box.y0};
        } else {
            moved = (vor_box_t){box.x0 + dx, box.y0 + dy, box.x1 + dx, box.y1 + dy};
        }
        if (!build(&d, n)) {
            return;
        }
        for (uint32_t i = 0; i < n; i++) {
            vor_centroid_t got;
            if (first_of[i] != i) {
                continue;
            }
            int err = vor_cell_centroid(&d, i, &moved, scratch, sizeof scratch, &got);
            const vor_centroid_t *want = &first[i];
            bool ok = err == VOR_OK && got.area == want->area && got.vertices == want->vertices;
            if (turn == 0u) {
                ok = ok && got.point.x == want->point.x + dx && got.point.y == want->point.y + dy;
            } else if (want->area > 0u) {
                int64_t sx = (int64_t)got.point.x + want->point.x;
                int64_t sy = (int64_t)got.point.y + want->point.y;
                ok = ok && sx >= 0 && sx <= 1 && sy >= 0 && sy <= 1;
            }
            if (!ok && wrong++ == 0u) {
                CHECK(false, "%s: site %u, %s: err %d, (%d, %d) area %u, first (%d, %d) area %u",
                      name, i, turn ? "turned" : "moved", err, got.point.x, got.point.y,
                      (unsigned)got.area, want->point.x, want->point.y, (unsigned)want->area);
            }
        }
        for (uint32_t i = 0; i < n; i++) {
            sites[i] = original[i];
        }
    }
    CHECK(wrong == 0, "%s: %u cells differ", name, wrong);
}

static void test_wide(test_rng_t *rng)
{
    const int32_t half = INT32_MAX / 2;
    for (unsigned round = 0; round < 12u; round++) {
        uint32_t n = 3u + test_rng_u32(rng) % (CEN_SITES - 2u);
        for (uint32_t i = 0; i < n; i++) {
            sites[i].x = test_rng_range(rng, -half, half);
            sites[i].y = test_rng_range(rng, -half, half);
        }
        if (round % 3u == 2u) { /* nearly collinear: wide circumcentres */
            for (uint32_t i = 0; i < n; i++) {
                sites[i].y = sites[i].x / 3 + test_rng_range(rng, -2, 2);
            }
        }
        int32_t x0 = test_rng_range(rng, -half, half - 2), y0 = test_rng_range(rng, -half, half - 2);
        vor_box_t box = {x0, y0, test_rng_range(rng, x0 + 1, half), test_rng_range(rng, y0 + 1, half)};
        if (round % 2u == 0u) {
            box = (vor_box_t){-half, -half, half, half};
        }
        check_invariances(n, box, test_rng_range(rng, -half, half), test_rng_range(rng, -half, half),
                          (round % 3u == 2u) ? "wide, nearly collinear" : "wide");
    }
}

/* ------------------------------------------------------------------ */
/* Errors and the scratch                                              */

static bool same_centroid(const vor_centroid_t *a, const vor_centroid_t *b)
{
    return a->point.x == b->point.x && a->point.y == b->point.y && a->area == b->area &&
           a->vertices == b->vertices;
}

static void test_errors(void)
{
    for (uint32_t i = 0; i < 9u; i++) { /* a 3 x 3 grid with one duplicate */
        sites[i].x = (int32_t)(i % 3u) * 10;
        sites[i].y = (int32_t)(i / 3u) * 10;
    }
    sites[9] = sites[4];
    vor_t d;
    if (!build(&d, 10)) {
        return;
    }
    vor_box_t box = {-5, -5, 25, 25}, inverted = {5, 0, 4, 10};
    const vor_centroid_t sentinel = {{12345, -678}, 99, 77};
    vor_centroid_t out = sentinel;
    int errors[8] = {
        vor_cell_centroid(NULL, 0, &box, scratch, sizeof scratch, &out),
        vor_cell_centroid(&d, 0, NULL, scratch, sizeof scratch, &out),
        vor_cell_centroid(&d, 0, &box, scratch, sizeof scratch, NULL),
        vor_cell_centroid(&d, 0, &box, NULL, 10, &out),
        vor_cell_centroid(&d, 0, &inverted, scratch, sizeof scratch, &out),
        vor_cell_centroid(&d, 10, &box, scratch, sizeof scratch, &out),
        vor_cell_centroid(&d, 9, &box, scratch, sizeof scratch, &out), /* a duplicate's id */
        vor_cell_centroid(&d, UINT32_MAX, &box, scratch, sizeof scratch, &out),
    };
    for (unsigned i = 0; i < 8u; i++) {
        CHECK(errors[i] == VOR_ERR_ARG, "bad argument %u: %d", i, errors[i]);
    }
    CHECK(same_centroid(&out, &sentinel), "a failed call wrote its output");

    /* the middle cell is the square [5, 15]^2 with 4 vertices; too little
     * scratch says so and writes only the count */
    vor_centroid_t want;
    CHECK(vor_cell_centroid(&d, 4, &box, scratch, sizeof scratch, &want) == VOR_OK &&
              want.point.x == 10 && want.point.y == 10 && want.area == 100 && want.vertices == 4,
          "middle square: (%d, %d), area %u, %u vertices", want.point.x, want.point.y,
          (unsigned)want.area, want.vertices);
    size_t enough = VOR_CENTROID_SCRATCH_BYTES(4);
    int err = vor_cell_centroid(&d, 4, &box, scratch, enough - 9u, &out);
    CHECK(err == VOR_ERR_BUFFER && out.vertices == 4 && out.point.x == sentinel.point.x &&
              out.point.y == sentinel.point.y && out.area == sentinel.area,
          "small scratch: %d, %u vertices", err, out.vertices);
    err = vor_cell_centroid(&d, 4, &box, NULL, 0, &out);
    CHECK(err == VOR_ERR_BUFFER && out.vertices == 4, "no scratch: %d", err);
    /* exactly enough, at every alignment */
    for (size_t offset = 0; offset < 8u; offset++) {
        out = sentinel;
        err = vor_cell_centroid(&d, 4, &box, scratch + offset, enough, &out);
        CHECK(err == VOR_OK && same_centroid(&out, &want), "scratch at offset %u: %d",
              (unsigned)offset, err);
    }
    /* no area: a zero-width box, a box touching the cell in a segment;
     * no scratch is needed */
    vor_box_t flat = {-100, 3, 100, 3}, touching = {5, -5, 20, 25};
    err = vor_cell_centroid(&d, 4, &flat, NULL, 0, &out);
    CHECK(err == VOR_OK && out.area == 0 && out.vertices == 0 && out.point.x == 10 &&
              out.point.y == 3,
          "flat box: %d, area %u, (%d, %d)", err, (unsigned)out.area, out.point.x, out.point.y);
    err = vor_cell_centroid(&d, 0, &touching, NULL, 0, &out);
    CHECK(err == VOR_OK && out.area == 0 && out.vertices == 0 && out.point.x == 5 &&
              out.point.y == 0,
          "touching box: %d, area %u, (%d, %d)", err, (unsigned)out.area, out.point.x,
          out.point.y);
}

/* Boxes of no area on either axis, the site inside or beside them: no
 * scratch is needed, the answer is the box's point nearest the site. */
static void test_flat_boxes(void)
{
    for (uint32_t i = 0; i < 9u; i++) { /* a 3 x 3 grid */
        sites[i].x = (int32_t)(i % 3u) * 10;
        sites[i].y = (int32_t)(i / 3u) * 10;
    }
    vor_t d;
    if (!build(&d, 9)) {
        return;
    }
    /* site 4 = (10, 10) */
    const vor_box_t boxes[4] = {{3, -100, 3, 100}, {3, 20, 3, 100}, {-100, 3, 100, 3}, {7, 7, 7, 7}};
    const vor_point_t want[4] = {{3, 10}, {3, 20}, {10, 3}, {7, 7}};
    for (unsigned k = 0; k < 4u; k++) {
        vor_centroid_t out = {{12345, -678}, 99, 77};
        int err = vor_cell_centroid(&d, 4, &boxes[k], NULL, 0, &out);
        CHECK(err == VOR_OK && out.area == 0 && out.vertices == 0 && out.point.x == want[k].x &&
                  out.point.y == want[k].y,
              "flat box %u: %d, area %u, (%d, %d)", k, err, (unsigned)out.area, out.point.x,
              out.point.y);
    }
}

/* ------------------------------------------------------------------ */
/* Power cells                                                         */

/* A box around the sites, inside them, or away from them. */
static vor_box_t random_box(test_rng_t *rng)
{
    uint32_t kind = test_rng_u32(rng) % 12u;
    int32_t x0 = test_rng_range(rng, -1000, 900), y0 = test_rng_range(rng, -1000, 900);
    int32_t size = (kind % 3u == 0u) ? 1000 : (kind % 3u == 1u) ? 9 : 300;
    vor_box_t box = {x0, y0, x0 + test_rng_range(rng, 1, size), y0 + test_rng_range(rng, 1, size)};
    if (kind % 4u == 0u) {
        box = (vor_box_t){-1000, -1000, 1000, 1000};
    }
    return box;
}

static void test_power_brute_force(test_rng_t *rng)
{
    static const char *const names[5] = {"power_random", "power_equal", "power_one_point",
                                         "power_collinear", "power_grid"};
    for (unsigned round = 0; round < 300u; round++) {
        uint32_t n = 1u + test_rng_u32(rng) % CEN_SITES;
        unsigned kind = round % 5u;
        /* a linear weight function keeps a grid's cocircular fours tied */
        int64_t gx = test_rng_range(rng, -300, 300), gy = test_rng_range(rng, -300, 300);
        int64_t g0 = test_rng_range(rng, -90000, 90000);
        for (uint32_t i = 0; i < n; i++) {
            sites[i].x = test_rng_range(rng, -1000, 1000);
            sites[i].y = test_rng_range(rng, -1000, 1000);
            weights[i] = test_rng_range(rng, -(1 << 20), 1 << 20);
            switch (kind) {
            case 0: /* random weights: some sites hidden */
                break;
            case 1: /* equal weights: the Voronoi cells */
                weights[i] = 12345;
                break;
            case 2: /* a few points, each with several weights (and repeats) */
                sites[i] = sites[test_rng_u32(rng) % (i + 1u)];
                weights[i] = test_rng_range(rng, 0, 4) * 250000;
                break;
            case 3: /* on one line */
                sites[i].x = test_rng_range(rng, -20, 20) * 40;
                sites[i].y = sites[i].x / 2 + 7;
                break;
            default: /* a grid: weights linear in the position (ties), or not */
                sites[i].x = (int32_t)(i % 4u) * 300 - 450;
                sites[i].y = (int32_t)(i / 4u) * 300 - 450;
                weights[i] = (round % 2u == 0u) ? gx * sites[i].x + gy * sites[i].y + g0
                                                : test_rng_range(rng, -30000, 30000);
                break;
            }
        }
        check_all_cells(n, random_box(rng), true, names[kind]);
    }
}

/* The power calls' arguments: errors change nothing; a hidden site's cell
 * is empty. */
static void test_power_errors(void)
{
    vor_power_t pd;
    vor_box_t box = {-100, -100, 100, 100}, bad = {1, 0, 0, 1};
    vor_point_t poly[8] = {{77, 77}};
    uint32_t count = 99;
    vor_centroid_t out = {{5, 6}, 7, 8};
    sites[0] = (vor_point_t){0, 0};
    sites[1] = (vor_point_t){10, 0};
    sites[2] = (vor_point_t){0, 10};
    sites[3] = (vor_point_t){1, 1};
    weights[0] = weights[1] = weights[2] = 0;
    weights[3] = -1000; /* hidden */
    if (!build_power(&pd, 4)) {
        return;
    }
    CHECK(vor_power_hidden(&pd, 3) == 1, "site 3 hidden");
    CHECK(vor_power_cell(NULL, 0, &box, poly, 8, &count) == VOR_ERR_ARG &&
              vor_power_cell(&pd, 0, NULL, poly, 8, &count) == VOR_ERR_ARG &&
              vor_power_cell(&pd, 0, &bad, poly, 8, &count) == VOR_ERR_ARG &&
              vor_power_cell(&pd, 0, &box, NULL, 8, &count) == VOR_ERR_ARG &&
              vor_power_cell(&pd, 0, &box, poly, 8, NULL) == VOR_ERR_ARG &&
              vor_power_cell(&pd, 4, &box, poly, 8, &count) == VOR_ERR_ARG &&
              count == 99 && poly[0].x == 77,
          "power cell: bad arguments");
    CHECK(vor_power_cell(&pd, 0, &box, poly, 2, &count) == VOR_ERR_BUFFER && count == 4 &&
              poly[0].x == 77,
          "power cell: a small buffer (count %u)", count);
    count = 99;
    CHECK(vor_power_cell(&pd, 0, &box, NULL, 0, &count) == VOR_ERR_BUFFER && count == 4,
          "power cell: no buffer, the count only (count %u)", count);
    CHECK(vor_power_cell(&pd, 3, &box, poly, 8, &count) == VOR_OK && count == 0,
          "power cell: hidden site (count %u)", count);
    CHECK(vor_power_cell_centroid(NULL, 0, &box, scratch, sizeof scratch, &out) == VOR_ERR_ARG &&
              vor_power_cell_centroid(&pd, 0, NULL, scratch, sizeof scratch, &out) == VOR_ERR_ARG &&
              vor_power_cell_centroid(&pd, 0, &bad, scratch, sizeof scratch, &out) == VOR_ERR_ARG &&
              vor_power_cell_centroid(&pd, 0, &box, NULL, 8, &out) == VOR_ERR_ARG &&
              vor_power_cell_centroid(&pd, 0, &box, scratch, sizeof scratch, NULL) ==
                  VOR_ERR_ARG &&
              vor_power_cell_centroid(&pd, 4, &box, scratch, sizeof scratch, &out) ==
                  VOR_ERR_ARG &&
              out.area == 7 && out.vertices == 8,
          "power centroid: bad arguments");
    CHECK(vor_power_cell_centroid(&pd, 0, &box, scratch, 8, &out) == VOR_ERR_BUFFER &&
              out.vertices == 4 && out.area == 7,
          "power centroid: a small scratch (%u vertices)", out.vertices);
    out.vertices = 8;
    CHECK(vor_power_cell_centroid(&pd, 0, &box, NULL, 0, &out) == VOR_ERR_BUFFER &&
              out.vertices == 4 && out.area == 7,
          "power centroid: no scratch (%u vertices)", out.vertices);
    CHECK(vor_power_cell_centroid(&pd, 3, &box, scratch, sizeof scratch, &out) == VOR_OK &&
              out.area == 0 && out.vertices == 0 && out.point.x == 1 && out.point.y == 1,
          "power centroid: hidden site");
}

void test_centroid(void)
{
    test_rng_t rng;
    TEST_CASE("errors") test_errors();
    TEST_CASE("grids") test_grids(test_rng_seed(&rng, 0xCE27701Du));
    TEST_CASE("wide") test_wide(test_rng_seed(&rng, 0xCE27701Du));
    TEST_CASE("brute_force") test_brute_force(test_rng_seed(&rng, 0xCE27701Du));
    TEST_CASE("flat_boxes") test_flat_boxes();
    TEST_CASE("power_errors") test_power_errors();
    TEST_CASE("power_brute_force") test_power_brute_force(test_rng_seed(&rng, 0x90E7CE11u));
}
