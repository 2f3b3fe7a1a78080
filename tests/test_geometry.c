/* SPDX-License-Identifier: MIT */
/*
 * test_geometry.c - Voronoi vertices, edges, hull and cells against
 * independent references:
 *   - vertices: the seed's untranslated circumcentre formula (003 (2.1.4))
 *     in the test's own 256-bit integers, and the rounding rule checked as
 *     an exact inequality;
 *   - edges: brute force over every pair of sites, each bisector cut by
 *     every other site with exact predicates;
 *   - hull: brute force over every pair (a supporting line) and the
 *     order checked edge by edge;
 *   - cells: exact known polygons (grids, strips, crosses), and sample
 *     points of the box, each in the cell of its brute-force nearest site
 *     (exact winding numbers of the rounded polygons, with a margin that
 *     covers the rounding).
 * tests/cli/test_cli.py checks the exact area tiling with rationals.
 */
#include "test.h"
#include "vor.h"

#define GEO_SITES 48u
#define CELL_POOL 4096u
#ifndef GEO_DEGENERATE_ROUNDS
#define GEO_DEGENERATE_ROUNDS 40u
#endif

static vor_point_t sites[GEO_SITES];
static uint32_t first_of[GEO_SITES];
static uint8_t arena[VOR_ARENA_BYTES(GEO_SITES)] __attribute__((aligned(8)));

/* ------------------------------------------------------------------ */
/* 256-bit two's complement integers, for the reference formulas       */

#define BIG_LIMBS 8u
typedef struct {
    uint32_t v[BIG_LIMBS];
} big_t;

static big_t big_from(int64_t x)
{
    big_t r;
    uint64_t u = (uint64_t)x;
    for (unsigned i = 0; i < BIG_LIMBS; i++) {
        r.v[i] = (i == 0) ? (uint32_t)u : (i == 1) ? (uint32_t)(u >> 32) : (x < 0 ? ~0u : 0u);
    }
    return r;
}

static big_t big_add(big_t a, big_t b)
{
    uint64_t carry = 0;
    for (unsigned i = 0; i < BIG_LIMBS; i++) {
        uint64_t s = (uint64_t)a.v[i] + b.v[i] + carry;
        a.v[i] = (uint32_t)s;
        carry = s >> 32;
    }
    return a;
}

static big_t big_neg(big_t a)
{
    for (unsigned i = 0; i < BIG_LIMBS; i++) {
        a.v[i] = ~a.v[i];
    }
    return big_add(a, big_from(1));
}

static big_t big_sub(big_t a, big_t b)
{
    return big_add(a, big_neg(b));
}

static big_t big_mul(big_t a, big_t b)
{
    big_t r = big_from(0);
    for (unsigned i = 0; i < BIG_LIMBS; i++) {
        uint64_t carry = 0;
        for (unsigned j = 0; i + j < BIG_LIMBS; j++) {
            uint64_t t = (uint64_t)a.v[i] * b.v[j] + r.v[i + j] + carry;
            r.v[i + j] = (uint32_t)t;
            carry = t >> 32;
        }
    }
    return r;
}

static int big_sign(big_t a)
{
    if (a.v[BIG_LIMBS - 1] >> 31) {
        return -1;
    }
    for (unsigned i = 0; i < BIG_LIMBS; i++) {
        if (a.v[i] != 0) {
            return 1;
        }
    }
    return 0;
}

static int big_compare(big_t a, big_t b)
{
    return big_sign(big_sub(a, b));
}

/* det [[1 a1 a2] [1 b1 b2] [1 c1 c2]] of raw entries */
static big_t det3(big_t a1, big_t a2, big_t b1, big_t b2, big_t c1, big_t c2)
{
    big_t r = big_sub(big_mul(b1, c2), big_mul(c1, b2));
    r = big_sub(r, big_sub(big_mul(a1, c2), big_mul(c1, a2)));
    return big_add(r, big_sub(big_mul(a1, b2), big_mul(b1, a2)));
}

/* Expected rounding of the coordinate num / den (den > 0) to
 * floor(v + 1/2): -1 below int32, 1 above, else 0 with *value. Here
 * num / den = 2v, the form of the seed's formula. */
static int expected_round(big_t twice_num, big_t den, int32_t *value)
{
    /* v + 1/2 >= 2^31  <=>  2v >= 2^32 - 1 */
    if (big_compare(twice_num, big_mul(big_from(4294967295ll), den)) >= 0) {
        return 1;
    }
    /* v + 1/2 < -2^31  <=>  2v < -2^32 - 1 */
    if (big_compare(twice_num, big_mul(big_from(-4294967297ll), den)) < 0) {
        return -1;
    }
    /* binary search for X with (2X - 1) den <= 2v den < (2X + 1) den */
    int64_t lo = INT32_MIN, hi = INT32_MAX;
    while (lo < hi) {
        int64_t mid = lo + (hi - lo + 1) / 2;
        if (big_compare(big_mul(big_from(2 * mid - 1), den), twice_num) <= 0) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    *value = (int32_t)lo;
    return 0;
}

/* The circumcentre by the seed's formula (2.1.4), (-B / 2A, C / 2A) with
 * A, B, C 3x3 determinants of the raw coordinates, checked against
 * vor_circumcentre: the rounding inequality, or the flag. */
static bool check_circumcentre(vor_point_t a, vor_point_t b, vor_point_t c, const char *what)
{
    vor_vertex_t got;
    int err = vor_circumcentre(a, b, c, &got);
    const vor_point_t *p[3] = {&a, &b, &c};
    big_t x[3], y[3], l[3];
    for (unsigned i = 0; i < 3; i++) {
        x[i] = big_from(p[i]->x);
        y[i] = big_from(p[i]->y);
        l[i] = big_add(big_mul(x[i], x[i]), big_mul(y[i], y[i]));
    }
    big_t A = det3(x[0], y[0], x[1], y[1], x[2], y[2]);
    big_t B = det3(y[0], l[0], y[1], l[1], y[2], l[2]);
    big_t C = det3(x[0], l[0], x[1], l[1], x[2], l[2]);
    if (big_sign(A) == 0) {
        return CHECK(err == VOR_OK && got.status == VOR_VERTEX_AT_INFINITY,
                     "%s: collinear (%d,%d) (%d,%d) (%d,%d): status %d", what, a.x, a.y, b.x, b.y,
                     c.x, c.y, (int)got.status);
    }
    if (big_sign(A) < 0) {
        A = big_neg(A);
        B = big_neg(B);
        C = big_neg(C);
    }
    /* 2 cx = -B / A, 2 cy = C / A */
    int32_t ex = 0, ey = 0;
    int rx = expected_round(big_neg(B), A, &ex);
    int ry = expected_round(C, A, &ey);
    bool ok = err == VOR_OK;
    if (rx == 0 && ry == 0) {
        ok = ok && got.status == VOR_VERTEX_IN_RANGE && got.point.x == ex && got.point.y == ey;
    } else {
        ok = ok && got.status == VOR_VERTEX_OUT_OF_RANGE;
        ok = ok && got.point.x == (rx > 0 ? INT32_MAX : rx < 0 ? INT32_MIN : ex);
        ok = ok && got.point.y == (ry > 0 ? INT32_MAX : ry < 0 ? INT32_MIN : ey);
    }
    return CHECK(ok, "%s: circumcentre of (%d,%d) (%d,%d) (%d,%d): got (%d,%d) status %d, "
                     "expected (%d,%d) range %d %d",
                 what, a.x, a.y, b.x, b.y, c.x, c.y, got.point.x, got.point.y, (int)got.status, ex,
                 ey, rx, ry);
}

static void test_vertices(test_rng_t *rng)
{
    unsigned failures = 0;
    for (unsigned k = 0; k < 1500u && failures < 5u; k++) {
        vor_point_t p[3];
        unsigned family = k % 6u;
        for (unsigned i = 0; i < 3; i++) {
            switch (family) {
            case 0: /* anywhere */
                p[i].x = (int32_t)test_rng_u32(rng);
                p[i].y = (int32_t)test_rng_u32(rng);
                break;
            case 1: /* small: halves of .5 are frequent */
                p[i].x = test_rng_range(rng, -4, 4);
                p[i].y = test_rng_range(rng, -4, 4);
                break;
            case 2: /* nearly collinear, far out: vertices out of range */
                p[i].x = (int32_t)test_rng_u32(rng);
                p[i].y = (int32_t)(p[i].x / 2 + test_rng_range(rng, -1, 1));
                break;
            case 3: /* corners of the range */
                p[i].x = (test_rng_u32(rng) & 1u) ? INT32_MAX - test_rng_range(rng, 0, 2)
                                                  : INT32_MIN + test_rng_range(rng, 0, 2);
                p[i].y = (test_rng_u32(rng) & 1u) ? INT32_MAX - test_rng_range(rng, 0, 2)
                                                  : INT32_MIN + test_rng_range(rng, 0, 2);
                break;
            case 4: /* a small triangle far from the origin */
                p[i].x = 2000000000 + test_rng_range(rng, -1000, 1000);
                p[i].y = -2000000000 + test_rng_range(rng, -1000, 1000);
                break;
            default: /* exactly collinear */
                p[i].x = 3 * test_rng_range(rng, -100000, 100000);
                p[i].y = -7 * (p[i].x / 3) + 11;
                break;
            }
        }
        failures += check_circumcentre(p[0], p[1], p[2], "random") ? 0u : 1u;
    }
    /* exact halves round up (toward +infinity): (0,0) (1,0) (0,1) -> (1/2, 1/2) */
    vor_point_t a = {0, 0}, b = {1, 0}, c = {0, 1};
    vor_vertex_t v;
    CHECK(vor_circumcentre(a, b, c, &v) == VOR_OK && v.point.x == 1 && v.point.y == 1 &&
              v.status == VOR_VERTEX_IN_RANGE,
          "(1/2, 1/2) rounds to (1, 1): (%d, %d)", v.point.x, v.point.y);
    a.x = -1; /* (-1,0) (0,0)... centre (-1/2, 1/2) */
    b.x = 0;
    c.x = -1;
    CHECK(vor_circumcentre(a, b, c, &v) == VOR_OK && v.point.x == 0 && v.point.y == 1,
          "(-1/2, 1/2) rounds to (0, 1): (%d, %d)", v.point.x, v.point.y);
    CHECK(vor_circumcentre(a, b, c, NULL) == VOR_ERR_ARG, "NULL result");
    vor_point_t far1 = {INT32_MIN, INT32_MIN}, far2 = {INT32_MAX, INT32_MIN + 1},
                far3 = {INT32_MAX, INT32_MIN};
    check_circumcentre(far1, far2, far3, "thin, out of range");
}

/* ------------------------------------------------------------------ */
/* Edges                                                               */

static bool strictly_inside(vor_point_t a, vor_point_t m, vor_point_t b)
{
    /* m on segment ab (collinear), not an end: by coordinates */
    int64_t lo_x = a.x < b.x ? a.x : b.x, hi_x = a.x < b.x ? b.x : a.x;
    int64_t lo_y = a.y < b.y ? a.y : b.y, hi_y = a.y < b.y ? b.y : a.y;
    bool ends = (m.x == a.x && m.y == a.y) || (m.x == b.x && m.y == b.y);
    return !ends && m.x >= lo_x && m.x <= hi_x && m.y >= lo_y && m.y <= hi_y;
}

static int orient(uint32_t a, uint32_t b, uint32_t c)
{
    return vor_orient2d(sites[a], sites[b], sites[c]);
}

static bool same_vertex(vor_vertex_t a, vor_vertex_t b)
{
    return a.status == b.status && a.point.x == b.point.x && a.point.y == b.point.y;
}

/* The brute-force Voronoi edge of sites p, q: the bisector, cut by every
 * other site r: on the left of p -> q, the edge ends where the circle
 * through p, q grows over r (the first such r: incircle); on the right it
 * starts at the last. Returns false when nothing of positive length is
 * left. The edge is put in the library's orientation. */
static bool brute_edge(uint32_t n, uint32_t p, uint32_t q, vor_edge_t *e)
{
    uint32_t lo = GEO_SITES, hi = GEO_SITES;
    for (uint32_t r = 0; r < n; r++) {
        if (first_of[r] != r || r == p || r == q) {
            continue;
        }
        int o = orient(p, q, r);
        if (o == 0) {
            if (strictly_inside(sites[p], sites[r], sites[q])) {
                return false;
            }
        } else if (o > 0) {
            if (hi == GEO_SITES || vor_incircle(sites[p], sites[q], sites[hi], sites[r]) > 0) {
                hi = r;
            }
        } else if (lo == GEO_SITES ||
                   vor_incircle(sites[q], sites[p], sites[lo], sites[r]) > 0) {
            lo = r;
        }
    }
    if (lo != GEO_SITES && hi != GEO_SITES &&
        vor_incircle(sites[p], sites[q], sites[hi], sites[lo]) >= 0) {
        return false; /* empty or a single point */
    }
    if (lo == GEO_SITES && hi != GEO_SITES) { /* a ray from its end: turn round */
        uint32_t t = p;
        p = q;
        q = t;
        lo = hi;
        hi = GEO_SITES;
    }
    e->sites[0] = p;
    e->sites[1] = q;
    e->dx = -((int64_t)sites[q].y - sites[p].y);
    e->dy = (int64_t)sites[q].x - sites[p].x;
    e->to.status = VOR_VERTEX_AT_INFINITY;
    e->to.point.x = e->to.point.y = 0;
    if (lo == GEO_SITES) {
        e->kind = VOR_EDGE_LINE;
        /* floor((p + q) / 2 + 1/2), computed with a plain division */
        int64_t sx = (int64_t)sites[p].x + sites[q].x + 1, sy = (int64_t)sites[p].y + sites[q].y + 1;
        e->from.point.x = (int32_t)((sx >= 0) ? sx / 2 : -((-sx + 1) / 2));
        e->from.point.y = (int32_t)((sy >= 0) ? sy / 2 : -((-sy + 1) / 2));
        e->from.status = VOR_VERTEX_IN_RANGE;
        return true;
    }
    vor_circumcentre(sites[p], sites[q], sites[lo], &e->from);
    if (hi != GEO_SITES) {
        e->kind = VOR_EDGE_SEGMENT;
        vor_circumcentre(sites[p], sites[q], sites[hi], &e->to);
    } else {
        e->kind = VOR_EDGE_RAY;
    }
    return true;
}

/* Segments and lines in the order sites[0] < sites[1]. */
static void normalise_edge(vor_edge_t *e)
{
    if (e->kind != VOR_EDGE_RAY && e->sites[0] > e->sites[1]) {
        uint32_t t = e->sites[0];
        e->sites[0] = e->sites[1];
        e->sites[1] = t;
        e->dx = -e->dx;
        e->dy = -e->dy;
        if (e->kind == VOR_EDGE_SEGMENT) {
            vor_vertex_t v = e->from;
            e->from = e->to;
            e->to = v;
        }
    }
}

static bool same_edge(const vor_edge_t *a, const vor_edge_t *b)
{
    return a->sites[0] == b->sites[0] && a->sites[1] == b->sites[1] && a->kind == b->kind &&
           same_vertex(a->from, b->from) && same_vertex(a->to, b->to) && a->dx == b->dx &&
           a->dy == b->dy;
}

static void check_edges(const vor_t *d, uint32_t n, const char *name)
{
    static vor_edge_t expected[3u * GEO_SITES];
    static bool matched[3u * GEO_SITES];
    uint32_t count = 0;
    for (uint32_t p = 0; p < n; p++) {
        for (uint32_t q = p + 1u; q < n; q++) {
            if (first_of[p] == p && first_of[q] == q && count < 3u * GEO_SITES &&
                brute_edge(n, p, q, &expected[count])) {
                normalise_edge(&expected[count]);
                matched[count] = false;
                count++;
            }
        }
    }
    vor_edge_iter_t it;
    vor_edge_t e;
    uint32_t got = 0, wrong = 0;
    vor_edges_begin(&it, d);
    while (vor_edges_next(&it, &e)) {
        got++;
        bool direction_ok = e.dx == -((int64_t)sites[e.sites[1]].y - sites[e.sites[0]].y) &&
                            e.dy == (int64_t)sites[e.sites[1]].x - sites[e.sites[0]].x;
        normalise_edge(&e);
        bool found = false;
        for (uint32_t k = 0; k < count && !found; k++) {
            if (!matched[k] && same_edge(&e, &expected[k])) {
                matched[k] = found = true;
            }
        }
        if (!found || !direction_ok) {
            wrong++;
            if (wrong <= 2u) {
                CHECK(false, "%s: edge %u-%u kind %d from (%d,%d)/%d to (%d,%d)/%d not brute force",
                      name, e.sites[0], e.sites[1], (int)e.kind, e.from.point.x, e.from.point.y,
                      (int)e.from.status, e.to.point.x, e.to.point.y, (int)e.to.status);
            }
        }
    }
    CHECK(wrong == 0 && got == count, "%s: %u edges, %u expected, %u wrong", name, got, count,
          wrong);
}

/* ------------------------------------------------------------------ */
/* Hull                                                                */

static bool lower_point(vor_point_t a, vor_point_t b)
{
    return a.y < b.y || (a.y == b.y && a.x < b.x);
}

static void check_hull(const vor_t *d, uint32_t n, const char *name)
{
    /* brute force: s is on the boundary when it lies on a segment ab with
     * every site on one closed side of line ab */
    static bool on_hull[GEO_SITES];
    uint32_t expected = 0, distinct = 0;
    bool all_collinear = true;
    uint32_t any_a = GEO_SITES, any_b = GEO_SITES;
    for (uint32_t i = 0; i < n; i++) {
        on_hull[i] = false;
        if (first_of[i] != i) {
            continue;
        }
        distinct++;
        if (any_a == GEO_SITES) {
            any_a = i;
        } else if (any_b == GEO_SITES) {
            any_b = i;
        } else if (orient(any_a, any_b, i) != 0) {
            all_collinear = false;
        }
    }
    for (uint32_t a = 0; a < n; a++) {
        for (uint32_t b = 0; b < n; b++) {
            if (a == b || first_of[a] != a || first_of[b] != b) {
                continue;
            }
            bool supporting = true;
            for (uint32_t x = 0; x < n && supporting; x++) {
                supporting = first_of[x] != x || orient(a, b, x) >= 0;
            }
            for (uint32_t s = 0; s < n && supporting; s++) {
                if (first_of[s] == s && (s == a || s == b ||
                                         (orient(a, b, s) == 0 && strictly_inside(sites[a], sites[s], sites[b])))) {
                    on_hull[s] = true;
                }
            }
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        expected += on_hull[i] ? 1u : 0u;
    }
    if (distinct == 1u) {
        expected = 1u;
        on_hull[any_a] = true;
    }
    vor_hull_iter_t it;
    uint32_t s, count = 0, previous = GEO_SITES, first = GEO_SITES, bad = 0;
    static bool seen[GEO_SITES];
    for (uint32_t i = 0; i < n; i++) {
        seen[i] = false;
    }
    vor_hull_begin(&it, d);
    while (vor_hull_next(&it, &s) && count <= n) {
        count++;
        if (s >= n || !on_hull[s] || seen[s]) {
            bad++;
            continue;
        }
        seen[s] = true;
        if (first == GEO_SITES) {
            first = s;
            for (uint32_t i = 0; i < n; i++) { /* starts at the lowest */
                bad += (first_of[i] == i && lower_point(sites[i], sites[s])) ? 1u : 0u;
            }
        } else {
            /* consecutive: no site strictly between; turning left
             * (everything on the left of or on previous -> s) */
            for (uint32_t x = 0; x < n; x++) {
                if (first_of[x] != x) {
                    continue;
                }
                int o = orient(previous, s, x);
                bad += (!all_collinear && o < 0) ? 1u : 0u;
                bad += (o == 0 && strictly_inside(sites[previous], sites[x], sites[s])) ? 1u : 0u;
            }
        }
        previous = s;
    }
    if (!all_collinear && count > 1u) { /* closing edge */
        for (uint32_t x = 0; x < n; x++) {
            if (first_of[x] == x) {
                int o = orient(previous, first, x);
                bad += (o < 0 || (o == 0 && strictly_inside(sites[previous], sites[x], sites[first])))
                           ? 1u
                           : 0u;
            }
        }
    }
    CHECK(bad == 0 && count == expected, "%s: hull of %u sites, %u expected, %u wrong", name,
          count, expected, bad);
}

/* ------------------------------------------------------------------ */
/* Cells                                                               */

static vor_point_t pool[CELL_POOL];
static uint32_t cell_start[GEO_SITES + 1u], cell_count[GEO_SITES];

/* Winding number of the polygon around p (not on it), by crossings. */
static int winding(const vor_point_t *v, uint32_t m, vor_point_t p)
{
    int w = 0;
    for (uint32_t i = 0; i < m; i++) {
        vor_point_t a = v[i], b = v[(i + 1u == m) ? 0u : i + 1u];
        int64_t cross = ((int64_t)b.x - a.x) * ((int64_t)p.y - a.y) -
                        ((int64_t)p.x - a.x) * ((int64_t)b.y - a.y);
        if (a.y <= p.y && b.y > p.y && cross > 0) {
            w++;
        } else if (a.y > p.y && b.y <= p.y && cross < 0) {
            w--;
        }
    }
    return w;
}

static int64_t distance2(vor_point_t a, vor_point_t b)
{
    int64_t dx = (int64_t)a.x - b.x, dy = (int64_t)a.y - b.y;
    return dx * dx + dy * dy;
}

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* Every cell of the box; then sample points at least 1 from the box's
 * boundary and from every bisector they are near: such a point is at
 * least 1 from its nearest site's cell boundary, the rounded polygons are
 * within sqrt(2)/2 of the exact ones, so its winding number is exactly 1
 * in its nearest site's rounded cell and 0 in every other. Coordinates
 * stay below 2^29 here so that the squares fit int64. */
static void check_cells(const vor_t *d, uint32_t n, vor_box_t box, const char *name)
{
    uint32_t used = 0, wrong = 0;
    for (uint32_t i = 0; i < n; i++) {
        cell_start[i] = used;
        cell_count[i] = 0;
        if (first_of[i] != i) {
            uint32_t c;
            CHECK(vor_cell(d, i, &box, pool, 4, &c) == VOR_ERR_ARG, "%s: a duplicate's cell", name);
            continue;
        }
        uint32_t c = 0;
        int err = vor_cell(d, i, &box, pool + used, CELL_POOL - used, &c);
        if (!CHECK(err == VOR_OK && c <= VOR_CELL_MAX_VERTICES(n), "%s: cell %u: %d, %u vertices",
                   name, i, err, c)) {
            return;
        }
        cell_count[i] = c;
        for (uint32_t k = 0; k < c; k++) {
            vor_point_t v = pool[used + k];
            wrong += (v.x < box.x0 || v.x > box.x1 || v.y < box.y0 || v.y > box.y1) ? 1u : 0u;
            /* starts at the lowest: rounding keeps y's order weakly */
            wrong += (v.y < pool[used].y) ? 1u : 0u;
        }
        used += c;
    }
    CHECK(wrong == 0, "%s: %u cell vertices outside the box or before the lowest", name, wrong);
    /* sample points */
    uint32_t samples = 0, misplaced = 0;
    for (uint32_t gx = 0; gx <= 16u; gx++) {
        for (uint32_t gy = 0; gy <= 16u; gy++) {
            vor_point_t p;
            p.x = (int32_t)(box.x0 + 1 + (((int64_t)box.x1 - box.x0 - 2) * gx) / 16);
            p.y = (int32_t)(box.y0 + 1 + (((int64_t)box.y1 - box.y0 - 2) * gy) / 16);
            uint32_t best = GEO_SITES;
            for (uint32_t i = 0; i < n; i++) {
                if (first_of[i] == i && (best == GEO_SITES || distance2(p, sites[i]) < distance2(p, sites[best]))) {
                    best = i;
                }
            }
            bool margin = true;
            for (uint32_t i = 0; i < n && margin; i++) {
                if (first_of[i] == i && i != best) {
                    /* distance to the bisector >= 1 when the difference of
                     * squared distances is >= 2 |s_i - s_best| (L1 bounds it) */
                    int64_t diff = distance2(p, sites[i]) - distance2(p, sites[best]);
                    margin = diff >= 2 * (abs64((int64_t)sites[i].x - sites[best].x) +
                                          abs64((int64_t)sites[i].y - sites[best].y));
                }
            }
            if (!margin) {
                continue;
            }
            samples++;
            for (uint32_t i = 0; i < n; i++) {
                if (first_of[i] == i) {
                    int w = winding(pool + cell_start[i], cell_count[i], p);
                    if (w != (i == best ? 1 : 0)) {
                        misplaced++;
                        if (misplaced <= 2u) {
                            CHECK(false, "%s: (%d,%d), nearest %u, winds %d in cell %u", name, p.x,
                                  p.y, best, w, i);
                        }
                    }
                }
            }
        }
    }
    CHECK(misplaced == 0 && samples > 100u, "%s: %u of %u sample points misplaced", name,
          misplaced, samples);
}

/* One site's cell equals the given polygon exactly. */
static void expect_cell(const vor_t *d, uint32_t site, vor_box_t box, const vor_point_t *want,
                        uint32_t m, const char *name)
{
    vor_point_t got[16];
    uint32_t c = 99;
    int err = vor_cell(d, site, &box, got, 16, &c);
    bool ok = err == VOR_OK && c == m;
    for (uint32_t k = 0; ok && k < m; k++) {
        ok = got[k].x == want[k].x && got[k].y == want[k].y;
    }
    CHECK(ok, "%s: cell %u: err %d, %u vertices (%d,%d) (%d,%d) (%d,%d) ..., expected %u", name,
          site, err, c, got[0].x, got[0].y, got[1].x, got[1].y, got[2].x, got[2].y, m);
}

static bool build(vor_t *d, uint32_t n)
{
    return CHECK(vor_init(d, arena, sizeof arena, GEO_SITES) == VOR_OK &&
                     vor_build(d, sites, n, NULL, first_of) == VOR_OK,
                 "build %u sites", n);
}

static void check_all(uint32_t n, vor_box_t box, const char *name)
{
    vor_t d;
    if (!build(&d, n)) {
        return;
    }
    check_edges(&d, n, name);
    check_hull(&d, n, name);
    check_cells(&d, n, box, name);
    /* the cell iterator gives the same cells */
    vor_cell_iter_t it;
    uint32_t site, count, cells = 0, differ = 0;
    vor_point_t buffer[GEO_SITES + 4u];
    vor_cells_begin(&it, &d, &box);
    int r;
    while ((r = vor_cells_next(&it, &site, buffer, GEO_SITES + 4u, &count)) == 1) {
        cells++;
        differ += (site >= n || first_of[site] != site || count != cell_count[site]) ? 1u : 0u;
        for (uint32_t k = 0; k < count && differ == 0; k++) {
            vor_point_t want = pool[cell_start[site] + k];
            differ += (buffer[k].x != want.x || buffer[k].y != want.y) ? 1u : 0u;
        }
    }
    uint32_t distinct = 0;
    for (uint32_t i = 0; i < n; i++) {
        distinct += (first_of[i] == i) ? 1u : 0u;
    }
    CHECK(r == 0 && cells == distinct && differ == 0, "%s: cell iterator: %d, %u cells of %u, %u differ",
          name, r, cells, distinct, differ);
}

static void test_sets(test_rng_t *rng)
{
    vor_box_t box = {-(1 << 21), -(1 << 21), 1 << 21, 1 << 21};
    for (unsigned round = 0; round < 6u; round++) {
        uint32_t n = 3u + round * 8u;
        for (uint32_t i = 0; i < n; i++) {
            sites[i].x = test_rng_range(rng, -(1 << 20), 1 << 20);
            sites[i].y = test_rng_range(rng, -(1 << 20), 1 << 20);
        }
        check_all(n, box, "random");
    }
    /* small degenerate sets, scaled: lattices (cocircular), lines
     * (collinear, also along the hull), circles, duplicates */
    for (unsigned round = 0; round < GEO_DEGENERATE_ROUNDS; round++) {
        uint32_t n = 2u + test_rng_u32(rng) % 16u;
        int32_t a = test_rng_range(rng, -3, 3), b = test_rng_range(rng, -3, 3);
        static const int32_t circle[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                              {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
        for (uint32_t i = 0; i < n; i++) {
            int32_t t = test_rng_range(rng, -5, 5);
            uint32_t c = test_rng_u32(rng) % 12u;
            switch (round % 4u) {
            case 0:
                sites[i].x = test_rng_range(rng, -4, 4);
                sites[i].y = test_rng_range(rng, -4, 4);
                break;
            case 1:
                sites[i].x = a * t + ((test_rng_u32(rng) % 4u == 0u) ? 1 : 0);
                sites[i].y = b * t;
                break;
            case 2:
                sites[i].x = circle[c][0];
                sites[i].y = circle[c][1];
                break;
            default:
                sites[i].x = test_rng_range(rng, 0, 6);
                sites[i].y = (test_rng_u32(rng) % 2u == 0u) ? 0 : test_rng_range(rng, 0, 3);
                break;
            }
            sites[i].x *= 1000;
            sites[i].y *= 1000;
        }
        vor_box_t b2 = {test_rng_range(rng, -9000, -1000), test_rng_range(rng, -9000, -1000),
                        test_rng_range(rng, 1000, 9000), test_rng_range(rng, 1000, 9000)};
        check_all(n, b2, "degenerate");
    }
    /* a grid: cocircular squares, duplicates */
    for (uint32_t i = 0; i < 36u; i++) {
        sites[i].x = (int32_t)(i % 6u) * 1000 - 2500;
        sites[i].y = (int32_t)(i / 6u) * 1000 - 2500;
    }
    for (uint32_t i = 36; i < 40u; i++) {
        sites[i] = sites[test_rng_u32(rng) % 36u];
    }
    vor_box_t grid_box = {-4000, -3500, 3100, 3000};
    check_all(40, grid_box, "grid");
    /* a grid whose cells are all inside the box: exact squares */
    {
        vor_t d;
        for (uint32_t i = 0; i < 25u; i++) {
            sites[i].x = (int32_t)(i % 5u) * 10;
            sites[i].y = (int32_t)(i / 5u) * 10;
        }
        if (build(&d, 25)) {
            vor_box_t b = {-5, -5, 45, 45};
            for (uint32_t i = 0; i < 25u; i++) {
                int32_t x = sites[i].x, y = sites[i].y;
                vor_point_t square[4] = {{x - 5, y - 5}, {x + 5, y - 5}, {x + 5, y + 5}, {x - 5, y + 5}};
                expect_cell(&d, i, b, square, 4, "grid squares");
            }
            /* a box along bisectors: the cells beyond it touch it in segments */
            vor_box_t inner = {5, 5, 15, 15};
            vor_point_t middle[4] = {{5, 5}, {15, 5}, {15, 15}, {5, 15}};
            expect_cell(&d, 6, inner, middle, 4, "box on bisectors");
            for (uint32_t i = 0; i < 25u; i++) {
                uint32_t c = 99;
                CHECK(i == 6u || (vor_cell(&d, i, &inner, NULL, 0, &c) == VOR_OK && c == 0u),
                      "box on bisectors: cell %u has %u vertices", i, c);
            }
        }
    }
    /* collinear with duplicates: strips */
    for (uint32_t i = 0; i < 20u; i++) {
        int32_t t = test_rng_range(rng, -50, 50);
        sites[i].x = 7 * t;
        sites[i].y = -3 * t + 5;
    }
    vor_box_t line_box = {-400, -200, 400, 200};
    check_all(20, line_box, "collinear");
    {
        vor_t d;
        sites[0].x = 0, sites[0].y = 0;
        sites[1].x = 10, sites[1].y = 0;
        sites[2].x = 30, sites[2].y = 0;
        if (build(&d, 3)) {
            vor_box_t b = {-10, -10, 50, 10};
            vor_point_t s0[4] = {{-10, -10}, {5, -10}, {5, 10}, {-10, 10}};
            vor_point_t s1[4] = {{5, -10}, {20, -10}, {20, 10}, {5, 10}};
            vor_point_t s2[4] = {{20, -10}, {50, -10}, {50, 10}, {20, 10}};
            expect_cell(&d, 0, b, s0, 4, "strips");
            expect_cell(&d, 1, b, s1, 4, "strips");
            expect_cell(&d, 2, b, s2, 4, "strips");
            vor_edge_iter_t it;
            vor_edge_t e;
            uint32_t lines = 0;
            vor_edges_begin(&it, &d);
            while (vor_edges_next(&it, &e)) {
                lines += (e.kind == VOR_EDGE_LINE) ? 1u : 100u;
            }
            CHECK(lines == 2u, "strips: two line edges (%u)", lines);
        }
    }
    /* a cross of four cocircular sites: four rays from the origin */
    {
        vor_t d;
        vor_point_t cross[4] = {{10, 0}, {0, 10}, {-10, 0}, {0, -10}};
        for (uint32_t i = 0; i < 4u; i++) {
            sites[i] = cross[i];
        }
        if (build(&d, 4)) {
            vor_box_t b = {-20, -20, 20, 20};
            vor_point_t east[3] = {{20, -20}, {20, 20}, {0, 0}};
            vor_point_t south[3] = {{-20, -20}, {20, -20}, {0, 0}};
            expect_cell(&d, 0, b, east, 3, "cross");
            expect_cell(&d, 3, b, south, 3, "cross");
            check_all(4, b, "cross");
        }
    }
    /* sites on a circle: every Voronoi edge is a ray from its centre */
    {
        uint32_t n = 0;
        for (int32_t x = -25; x <= 25 && n < GEO_SITES; x++) {
            for (int32_t y = -25; y <= 25 && n < GEO_SITES; y++) {
                if (x * x + y * y == 625) {
                    sites[n].x = x * 40;
                    sites[n].y = y * 40;
                    n++;
                }
            }
        }
        vor_box_t b = {-3000, -2000, 2500, 3000};
        check_all(n, b, "circle");
    }
    /* huge coordinates: vertices far outside int32 */
    {
        vor_point_t huge[6] = {{INT32_MIN, INT32_MIN}, {INT32_MAX, INT32_MIN},
                               {INT32_MIN, INT32_MAX}, {INT32_MAX, INT32_MAX - 1},
                               {0, INT32_MIN + 1},     {1, INT32_MIN}};
        for (uint32_t i = 0; i < 6u; i++) {
            sites[i] = huge[i];
        }
        vor_t d;
        if (build(&d, 6)) {
            check_edges(&d, 6, "huge");
            check_hull(&d, 6, "huge");
            vor_box_t full = {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX};
            uint32_t c, total = 0;
            vor_point_t buffer[16];
            bool ok = true;
            for (uint32_t i = 0; i < 6u; i++) {
                ok = ok && vor_cell(&d, i, &full, buffer, 16, &c) == VOR_OK && c >= 3u;
                total += c;
            }
            CHECK(ok, "huge: every cell has an area in the full box (%u vertices)", total);
            vor_edge_iter_t it;
            vor_edge_t e;
            uint32_t out = 0;
            vor_edges_begin(&it, &d);
            while (vor_edges_next(&it, &e)) {
                out += (e.from.status == VOR_VERTEX_OUT_OF_RANGE ||
                        e.to.status == VOR_VERTEX_OUT_OF_RANGE) ? 1u : 0u;
            }
            CHECK(out > 0u, "huge: some vertex is out of range and flagged");
        }
    }
}

/* ------------------------------------------------------------------ */
/* Small diagrams and errors                                           */

static void test_errors(void)
{
    vor_t d;
    vor_box_t box = {0, 0, 100, 100};
    vor_point_t buffer[8];
    uint32_t c, s;
    CHECK(vor_init(&d, arena, sizeof arena, GEO_SITES) == VOR_OK, "init");
    /* no sites: nothing anywhere */
    vor_edge_iter_t ei;
    vor_edge_t e;
    vor_edges_begin(&ei, &d);
    CHECK(vor_edges_next(&ei, &e) == 0, "no sites: no edges");
    vor_hull_iter_t hi;
    vor_hull_begin(&hi, &d);
    CHECK(vor_hull_next(&hi, &s) == 0, "no sites: no hull");
    CHECK(vor_cell(&d, 0, &box, buffer, 8, &c) == VOR_ERR_ARG, "no sites: no cell");
    /* one site (and its duplicate): its cell is the box, no edges, the
     * hull is itself */
    vor_point_t points[4] = {{40, 60}, {40, 60}, {60, 40}, {90, 95}};
    CHECK(vor_build(&d, points, 2, NULL, NULL) == VOR_OK, "build one site");
    vor_point_t whole[4] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    expect_cell(&d, 0, box, whole, 4, "one site");
    vor_edges_begin(&ei, &d);
    CHECK(vor_edges_next(&ei, &e) == 0, "one site: no edges");
    vor_hull_begin(&hi, &d);
    CHECK(vor_hull_next(&hi, &s) == 1 && s == 0 && vor_hull_next(&hi, &s) == 0, "one site: hull");
    /* two sites: a line and two half-planes */
    CHECK(vor_build(&d, points, 3, NULL, NULL) == VOR_OK, "build two sites");
    vor_edges_begin(&ei, &d);
    CHECK(vor_edges_next(&ei, &e) == 1 && e.kind == VOR_EDGE_LINE && e.from.point.x == 50 &&
              e.from.point.y == 50 && vor_edges_next(&ei, &e) == 0,
          "two sites: one line");
    vor_point_t upper[3] = {{0, 0}, {100, 100}, {0, 100}};
    expect_cell(&d, 0, box, upper, 3, "two sites");
    uint32_t order[2], k = 0;
    vor_hull_begin(&hi, &d);
    while (k < 2u && vor_hull_next(&hi, &order[k])) {
        k++;
    }
    CHECK(k == 2u && order[0] == 2u && order[1] == 0u && vor_hull_next(&hi, &s) == 0,
          "two sites: hull from the lowest");
    CHECK(vor_build(&d, points, 4, NULL, NULL) == VOR_OK, "build three sites");
    /* arguments */
    vor_box_t bad = {10, 0, 9, 100}, thin = {10, 0, 10, 100}, away = {1000, 1000, 2000, 2000};
    CHECK(vor_cell(&d, 0, &bad, buffer, 8, &c) == VOR_ERR_ARG, "x0 > x1");
    CHECK(vor_cell(&d, 0, &thin, buffer, 8, &c) == VOR_OK && c == 0, "zero-width box");
    CHECK(vor_cell(&d, 0, &away, buffer, 8, &c) == VOR_OK && c == 0, "cell misses the box");
    CHECK(vor_cell(&d, 1, &box, buffer, 8, &c) == VOR_ERR_ARG, "a duplicate's id");
    CHECK(vor_cell(&d, 9, &box, buffer, 8, &c) == VOR_ERR_ARG, "an unknown id");
    CHECK(vor_cell(NULL, 0, &box, buffer, 8, &c) == VOR_ERR_ARG, "NULL diagram");
    CHECK(vor_cell(&d, 0, NULL, buffer, 8, &c) == VOR_ERR_ARG, "NULL box");
    CHECK(vor_cell(&d, 0, &box, buffer, 8, NULL) == VOR_ERR_ARG, "NULL count");
    CHECK(vor_cell(&d, 0, &box, NULL, 8, &c) == VOR_ERR_ARG, "NULL buffer");
    /* capacity: the count needed, nothing written */
    uint32_t needed = 0;
    CHECK(vor_cell(&d, 0, &box, NULL, 0, &needed) == VOR_ERR_BUFFER && needed >= 3u,
          "capacity 0: the count needed (%u)", needed);
    for (uint32_t i = 0; i < 8u; i++) {
        buffer[i].x = buffer[i].y = 12345;
    }
    c = 0;
    bool untouched = true;
    CHECK(vor_cell(&d, 0, &box, buffer, needed - 1u, &c) == VOR_ERR_BUFFER && c == needed,
          "capacity one short");
    for (uint32_t i = 0; i < 8u; i++) {
        untouched = untouched && buffer[i].x == 12345 && buffer[i].y == 12345;
    }
    CHECK(untouched, "capacity one short: nothing written");
    CHECK(vor_cell(&d, 0, &box, buffer, needed, &c) == VOR_OK && c == needed, "exact capacity");
    /* the cell iterator: a short buffer stops it on the site, a retry goes on */
    vor_cell_iter_t it;
    CHECK(vor_cells_begin(&it, &d, &box) == VOR_OK, "iterator: begin");
    CHECK(vor_cells_next(&it, &s, buffer, 2, &c) == 0 && vor_cells_error(&it) == VOR_ERR_BUFFER &&
              s == 0 && c == needed,
          "iterator: short buffer");
    CHECK(vor_cells_next(&it, &s, buffer, 8, &c) == 1 && s == 0, "iterator: retry");
    CHECK(vor_cells_next(&it, &s, buffer, 8, &c) == 1 && s == 2, "iterator: skips the duplicate");
    CHECK(vor_cells_next(&it, &s, buffer, 8, &c) == 1 && s == 3, "iterator: last");
    CHECK(vor_cells_next(&it, &s, buffer, 8, &c) == 0 && vor_cells_error(&it) == VOR_OK,
          "iterator: end");
    CHECK(vor_cells_begin(&it, &d, &bad) == VOR_ERR_ARG &&
              vor_cells_next(&it, &s, buffer, 8, &c) == 0 && vor_cells_error(&it) == VOR_ERR_ARG,
          "iterator: bad box");
    vor_vertex_t v;
    CHECK(vor_voronoi_vertex(&d, 0, 2, 3, &v) == VOR_OK && v.status == VOR_VERTEX_IN_RANGE,
          "vertex of three sites");
    CHECK(vor_voronoi_vertex(&d, 0, 2, 4, &v) == VOR_ERR_ARG, "vertex of an unknown id");
    /* ids that are no site of the mesh are refused, as every other call
     * refuses them, and *out keeps what it held */
    const vor_vertex_t mark = {{12345, -12345}, VOR_VERTEX_OUT_OF_RANGE};
    v = mark;
    CHECK(vor_voronoi_vertex(&d, 0, 1, 2, &v) == VOR_ERR_ARG && v.point.x == mark.point.x &&
              v.point.y == mark.point.y && v.status == mark.status,
          "vertex with a duplicate's id");
    v = mark;
    CHECK(vor_voronoi_vertex(&d, 2, 3, 1, &v) == VOR_ERR_ARG && v.point.x == mark.point.x,
          "vertex with a duplicate's id last");
    CHECK(vor_remove(&d, 3) == VOR_OK, "remove site 3");
    v = mark;
    CHECK(vor_voronoi_vertex(&d, 0, 2, 3, &v) == VOR_ERR_ARG && v.point.x == mark.point.x &&
              v.point.y == mark.point.y && v.status == mark.status,
          "vertex with a removed id");
}

/* Hulls with many sites along each edge: the border of a k x k lattice
 * square (or of a triangle's lattice, its slanted side too), a few sites
 * inside, ids shuffled, so that the perturbation leaves runs of sites on
 * a hull edge inside the perturbed hull (the iterator must still list
 * them, in order). */
static void test_hull_borders(test_rng_t *rng)
{
    vor_box_t box = {-(1 << 20), -(1 << 20), 1 << 20, 1 << 20};
    for (unsigned round = 0; round < 12u; round++) {
        int32_t k = 3 + (int32_t)(round % 6u);
        bool triangle = round >= 6u;
        uint32_t n = 0;
        for (int32_t y = 0; y <= k; y++) {
            for (int32_t x = 0; x <= k; x++) {
                bool border = triangle ? (y == 0 || x == 0 || x + y == k)
                                       : (x == 0 || y == 0 || x == k || y == k);
                bool inside = triangle ? (x + y <= k) : true;
                if (inside && (border || test_rng_u32(rng) % 8u == 0u) && n < GEO_SITES) {
                    sites[n].x = x * 1000 - 2000;
                    sites[n].y = y * 1000 + 500;
                    n++;
                }
            }
        }
        for (uint32_t i = n; i > 1u; i--) {
            uint32_t j = test_rng_u32(rng) % i;
            vor_point_t t = sites[i - 1u];
            sites[i - 1u] = sites[j];
            sites[j] = t;
        }
        check_all(n, box, triangle ? "lattice triangle border" : "lattice square border");
    }
}

void test_geometry(void)
{
    test_rng_t rng;
    TEST_CASE("vertices") test_vertices(test_rng_seed(&rng, 4242));
    TEST_CASE("errors") test_errors();
    TEST_CASE("sets") test_sets(test_rng_seed(&rng, 4242));
    TEST_CASE("hull_borders") test_hull_borders(test_rng_seed(&rng, 4243));
}
