/* SPDX-License-Identifier: MIT */
/*
 * test_clip.c - vor_clip_begin, vor_clip_next, vor_clip_centroid: Voronoi
 * cells clipped to simple polygons (rooms), against independent checks
 * in the test's own wide integers (tests/wide.h):
 *   - every piece is a proper polygon: at least 3 vertices in lowest
 *     terms, w > 0, consecutive vertices distinct, no straight angle,
 *     counterclockwise (positive shoelace area), from its lowest vertex,
 *     the pieces in the order of their lowest vertices;
 *   - every vertex is exactly in the closed cell (every bisector
 *     half-plane against every other site) and the closed room, every
 *     edge lies exactly on one line: a bisector of the site with another
 *     site, or a room edge; every vertex is rounded as floor(v + 1/2);
 *   - tiling: the directed edges of all pieces of all cells, compared as
 *     exact (canonical) points, cancel in opposite pairs except those on
 *     the room's boundary, which run along each room edge in the room's
 *     counterclockwise direction and chain from its start to its end; so
 *     the exact areas add up to the room's shoelace area exactly (each
 *     edge's cross term cancels or adds up to the room edge's);
 *   - random integer points strictly inside the room land in a piece of
 *     their nearest site (point in polygon by winding number, exact), and
 *     strictly inside no piece of a farther site;
 *   - areas and centroids (each piece and the whole) against the
 *     shoelace over the product of the denominators, the rounding checked
 *     as exact inequalities;
 *   - degenerate sites (grids with cocircular sites on room edges and
 *     corners, collinear sites, one site, duplicates), rooms with
 *     collinear edges, a U cutting cells in two, room corners pinching
 *     cells, both orientations;
 *   - bad rooms (crossing, touching, overlapping, folding back, repeated
 *     vertices, all collinear) and every argument error: nothing written.
 */
#include "test.h"
#include "vor.h"

#define WIDE_LIMBS 64u
#include "wide.h"

#define CLIP_SITES 16u
#define CLIP_ROOM 12u
#define CLIP_VERTICES VOR_CLIP_MAX_VERTICES(CLIP_ROOM, CLIP_SITES)
#define CLIP_EDGES 900u

static vor_point_t sites[CLIP_SITES];
static uint32_t first_of[CLIP_SITES];
static uint8_t arena[VOR_ARENA_BYTES(CLIP_SITES)] __attribute__((aligned(8)));
static uint8_t scratch[VOR_CLIP_SCRATCH_BYTES(CLIP_ROOM, CLIP_SITES) + 4u];
static uint8_t sums[VOR_CLIP_CENTROID_SCRATCH_BYTES(CLIP_ROOM, CLIP_SITES) + 8u];
static vor_exact_point_t piece[CLIP_VERTICES];

/* An exact point in the test's integers. */
typedef struct {
    wide_t x, y, w;
} exact_t;

/* Every directed edge of every piece, for the tiling, as the library
 * gives them (canonical: equal points have equal numbers). */
static vor_exact_point_t edge_from[CLIP_EDGES];
static vor_exact_point_t edge_to[CLIP_EDGES];
static bool edge_used[CLIP_EDGES];
static uint32_t edges;

/* A piece's vertices, kept for the point tests: per site, per piece. */
#define KEPT_PIECES 160u
static vor_exact_point_t kept[CLIP_EDGES];
static uint32_t kept_site[KEPT_PIECES];
static uint32_t kept_start[KEPT_PIECES];
static uint32_t kept_count[KEPT_PIECES];
static uint32_t kept_pieces;

static void to_exact(exact_t *e, const vor_exact_point_t *v)
{
    /* the limbs are two's complement: widen the sign */
    wide_words(&e->x, v->x, VOR_EXACT_LIMBS);
    wide_words(&e->y, v->y, VOR_EXACT_LIMBS);
    wide_words(&e->w, v->w, VOR_EXACT_LIMBS);
    wide_t *n[2] = {&e->x, &e->y};
    for (unsigned k = 0; k < 2u; k++) {
        if ((n[k]->v[VOR_EXACT_LIMBS - 1u] >> 31) != 0u) {
            for (unsigned i = VOR_EXACT_LIMBS; i < WIDE_LIMBS; i++) {
                n[k]->v[i] = 0xFFFFFFFFu;
            }
        }
    }
}

static bool same_exact(const exact_t *a, const exact_t *b)
{
    return wide_equal(&a->x, &b->x) && wide_equal(&a->y, &b->y) && wide_equal(&a->w, &b->w);
}

/* Equal exact points, as the library gives them (in lowest terms). */
static bool same_vertex(const vor_exact_point_t *a, const vor_exact_point_t *b)
{
    return test_same_bytes(a->x, b->x, sizeof a->x) && test_same_bytes(a->y, b->y, sizeof a->y) &&
           test_same_bytes(a->w, b->w, sizeof a->w);
}

/* An integer point in the library's exact form: (x, y, 1). */
static void vertex_of(vor_exact_point_t *e, vor_point_t p)
{
    e->point = p;
    for (unsigned i = 0; i < VOR_EXACT_LIMBS; i++) {
        e->x[i] = (i == 0u) ? (uint32_t)p.x : ((p.x < 0) ? 0xFFFFFFFFu : 0u);
        e->y[i] = (i == 0u) ? (uint32_t)p.y : ((p.y < 0) ? 0xFFFFFFFFu : 0u);
        e->w[i] = (i == 0u) ? 1u : 0u;
    }
}

/* Is r = floor(num / den + 1/2), for den > 0? */
static bool rounds_to(const wide_t *num, const wide_t *den, int64_t r)
{
    wide_t twice, low, high;
    wide_mul_i64(&twice, num, 2);
    wide_mul_i64(&low, den, 2 * r - 1);
    wide_mul_i64(&high, den, 2 * r + 1);
    return wide_compare(&low, &twice) <= 0 && wide_compare(&twice, &high) < 0;
}

/* Sign of a x + b y - c for the rational point p and integers a, b, c:
 * of a X + b Y - c W. */
static int line_side(const exact_t *p, int64_t a, int64_t b, int64_t c)
{
    wide_t s, t;
    wide_mul_i64(&s, &p->x, a);
    wide_mul_i64(&t, &p->y, b);
    wide_add(&s, &t);
    wide_mul_i64(&t, &p->w, c);
    wide_sub(&s, &t);
    wide_t zero;
    wide_set(&zero, 0);
    return wide_compare(&s, &zero);
}

/* Sign of the cross product (q - p) x (r - p) of three rational points:
 * of the determinant with rows (X, Y, W), which is that times
 * W_p W_q W_r > 0. */
static int turn(const exact_t *p, const exact_t *q, const exact_t *r)
{
    wide_t a, b, s, zero;
    wide_mul(&a, &q->y, &r->w);
    wide_mul(&b, &r->y, &q->w);
    wide_sub(&a, &b);
    wide_mul(&s, &p->x, &a);
    wide_mul(&a, &p->y, &r->w);
    wide_mul(&b, &r->y, &p->w);
    wide_sub(&a, &b);
    wide_mul(&a, &q->x, &a);
    wide_sub(&s, &a);
    wide_mul(&a, &p->y, &q->w);
    wide_mul(&b, &q->y, &p->w);
    wide_sub(&a, &b);
    wide_mul(&a, &r->x, &a);
    wide_add(&s, &a);
    wide_set(&zero, 0);
    return wide_compare(&s, &zero);
}

static void from_point(exact_t *e, vor_point_t p)
{
    wide_set(&e->x, p.x);
    wide_set(&e->y, p.y);
    wide_set(&e->w, 1);
}

/* Signs of p.y - q.y, then p.x - q.x. */
static int compare_low(const exact_t *p, const exact_t *q)
{
    wide_t a, b;
    wide_mul(&a, &p->y, &q->w);
    wide_mul(&b, &q->y, &p->w);
    int c = wide_compare(&a, &b);
    if (c != 0) {
        return c;
    }
    wide_mul(&a, &p->x, &q->w);
    wide_mul(&b, &q->x, &p->w);
    return wide_compare(&a, &b);
}

/* A partial check of lowest terms: no prime up to 97 divides x, y and w. */
static bool coprime3(const wide_t *x, const wide_t *y, const wide_t *w)
{
    /* no common factor: no prime p <= 97 divides all three, and no
     * common factor 2 (a cheap, partial check of lowest terms) */
    static const uint32_t primes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53,
                                      59, 61, 67, 71, 73, 79, 83, 89, 97};
    const wide_t *n[3] = {x, y, w};
    for (unsigned k = 0; k < sizeof primes / sizeof primes[0]; k++) {
        bool all = true;
        for (unsigned i = 0; i < 3u && all; i++) {
            /* |n| mod p from the limbs, most significant first */
            wide_t m = *n[i];
            if (wide_negative(&m)) {
                wide_neg(&m);
            }
            uint64_t r = 0;
            for (unsigned l = WIDE_LIMBS; l-- > 0;) {
                r = ((r << 32) | m.v[l]) % primes[k];
            }
            all = (r == 0u);
        }
        if (all) {
            return false;
        }
    }
    return true;
}

/* ------------------------------------------------------------------ */
/* Rooms                                                               */

typedef struct {
    const char *name;
    uint32_t m;
    vor_point_t v[CLIP_ROOM];
} room_t;

static const room_t rooms[] = {
    {"square", 4, {{0, 0}, {60, 0}, {60, 60}, {0, 60}}},
    {"L", 6, {{0, 0}, {60, 0}, {60, 30}, {30, 30}, {30, 60}, {0, 60}}},
    {"U", 8, {{0, 0}, {60, 0}, {60, 60}, {40, 60}, {40, 20}, {20, 20}, {20, 60}, {0, 60}}},
    {"collinear", 8, {{0, 0}, {20, 0}, {40, 0}, {60, 0}, {60, 30}, {60, 60}, {0, 60}, {0, 30}}},
    {"comb", 9, {{0, 0}, {60, 0}, {60, 60}, {50, 10}, {40, 60}, {30, 10}, {20, 60}, {10, 10},
                 {0, 60}}},
    {"star", 10, {{30, 0}, {40, 20}, {60, 25}, {45, 40}, {50, 60}, {30, 48}, {10, 60}, {15, 40},
                  {0, 25}, {20, 20}}},
    {"clockwise_L", 6, {{0, 0}, {0, 60}, {30, 60}, {30, 30}, {60, 30}, {60, 0}}},
    {"triangle", 3, {{-5, -3}, {67, 11}, {21, 58}}},
    {"C", 8, {{0, 60}, {0, 0}, {60, 0}, {60, 20}, {40, 20}, {40, 40}, {60, 40}, {60, 60}}},
    {"square_last_lowest", 4, {{60, 0}, {60, 60}, {0, 60}, {0, 0}}},
    {"zigzag", 12, {{0, 0}, {10, 5}, {20, 0}, {30, 5}, {40, 0}, {50, 5}, {60, 0}, {60, 60},
                    {40, 50}, {30, 60}, {20, 50}, {0, 60}}},
};
#define ROOMS (sizeof rooms / sizeof rooms[0])

/* The room's vertex i counterclockwise. */
static vor_point_t room_ccw(const room_t *r, uint32_t i)
{
    bool cw = (r->name[0] == 'c') && (r->name[1] == 'l');
    return r->v[cw ? (r->m - 1u - i) : i];
}

/* Is q strictly inside the room, on its boundary (0), or outside (-1)?
 * Winding number with integer orientations. */
static int in_room(const room_t *r, vor_point_t q)
{
    int winding = 0;
    for (uint32_t i = 0; i < r->m; i++) {
        vor_point_t a = r->v[i], b = r->v[(i + 1u) % r->m];
        int o = vor_orient2d(a, b, q);
        if (o == 0 && ((int64_t)q.x - a.x) * ((int64_t)q.x - b.x) <= 0 &&
            ((int64_t)q.y - a.y) * ((int64_t)q.y - b.y) <= 0) {
            return 0;
        }
        if (a.y <= q.y) {
            winding += (b.y > q.y && o > 0) ? 1 : 0;
        } else {
            winding -= (b.y <= q.y && o < 0) ? 1 : 0;
        }
    }
    return (winding != 0) ? 1 : -1;
}

/* q against a kept piece: 1 strictly inside, 0 on its boundary, -1 out. */
static int in_piece(uint32_t k, vor_point_t q)
{
    static exact_t e, pa, pb;
    static wide_t s, t, lo, hi;
    from_point(&e, q);
    int winding = 0;
    const vor_exact_point_t *v = kept + kept_start[k];
    uint32_t r = kept_count[k];
    for (uint32_t i = 0; i < r; i++) {
        to_exact(&pa, &v[i]);
        to_exact(&pb, &v[(i + 1u) % r]);
        const exact_t *a = &pa, *b = &pb;
        int o = turn(a, b, &e);
        if (o == 0) {
            /* on the segment: between the ends in x and y */
            bool between = true;
            const wide_t *ca[2] = {&a->x, &a->y}, *cb[2] = {&b->x, &b->y};
            int32_t cq[2] = {q.x, q.y};
            for (unsigned c = 0; c < 2u; c++) {
                wide_mul_i64(&lo, &a->w, cq[c]);
                wide_mul_i64(&hi, &b->w, cq[c]);
                int sa = wide_compare(ca[c], &lo); /* sign of a - q */
                int sb = wide_compare(cb[c], &hi);
                between = between && (sa * sb <= 0);
            }
            if (between) {
                return 0;
            }
        }
        /* crossing rule by y alone */
        wide_mul_i64(&s, &a->w, q.y);
        wide_mul_i64(&t, &b->w, q.y);
        bool a_below = wide_compare(&a->y, &s) <= 0;
        bool b_below = wide_compare(&b->y, &t) <= 0;
        if (a_below) {
            winding += (!b_below && o > 0) ? 1 : 0;
        } else {
            winding -= (b_below && o < 0) ? 1 : 0;
        }
    }
    return (winding != 0) ? 1 : -1;
}

/* ------------------------------------------------------------------ */
/* Checks                                                              */

static bool build(vor_t *d, uint32_t n)
{
    return CHECK(vor_init(d, arena, sizeof arena, CLIP_SITES) == VOR_OK &&
                     vor_build(d, sites, n, NULL, first_of) == VOR_OK,
                 "build of %u sites", n);
}

/* Does the edge a -> b lie on a bisector of site s with another site, or
 * on a room edge? */
static bool edge_on_a_line(const room_t *r, uint32_t s, uint32_t n, const exact_t *a,
                           const exact_t *b)
{
    for (uint32_t t = 0; t < n; t++) {
        vor_point_t p = sites[s], o = sites[t];
        if (p.x == o.x && p.y == o.y) {
            continue;
        }
        /* 2 (o - p).q = |o|^2 - |p|^2 */
        int64_t ca = 2 * ((int64_t)o.x - p.x), cb = 2 * ((int64_t)o.y - p.y);
        int64_t cc = (int64_t)o.x * o.x + (int64_t)o.y * o.y - (int64_t)p.x * p.x -
                     (int64_t)p.y * p.y;
        if (line_side(a, ca, cb, cc) == 0 && line_side(b, ca, cb, cc) == 0) {
            return true;
        }
    }
    for (uint32_t i = 0; i < r->m; i++) {
        static exact_t u, v;
        from_point(&u, r->v[i]);
        from_point(&v, r->v[(i + 1u) % r->m]);
        if (turn(&u, &v, a) == 0 && turn(&u, &v, b) == 0) {
            return true;
        }
    }
    return false;
}

/* Is p in the closed cell of s? */
static bool in_cell(uint32_t s, uint32_t n, const exact_t *p)
{
    for (uint32_t t = 0; t < n; t++) {
        vor_point_t a = sites[s], o = sites[t];
        int64_t ca = 2 * ((int64_t)o.x - a.x), cb = 2 * ((int64_t)o.y - a.y);
        int64_t cc = (int64_t)o.x * o.x + (int64_t)o.y * o.y - (int64_t)a.x * a.x -
                     (int64_t)a.y * a.y;
        if (line_side(p, ca, cb, cc) > 0) {
            return false;
        }
    }
    return true;
}

/* Is p in the closed room? */
static bool in_closed_room(const room_t *r, const exact_t *p)
{
    int winding = 0;
    for (uint32_t i = 0; i < r->m; i++) {
        static exact_t a, b;
        vor_point_t pa = room_ccw(r, i), pb = room_ccw(r, (i + 1u) % r->m);
        from_point(&a, pa);
        from_point(&b, pb);
        int o = turn(&a, &b, p);
        if (o == 0) {
            wide_t lo, hi;
            bool between = true;
            int32_t ea[2] = {pa.x, pa.y}, eb[2] = {pb.x, pb.y};
            const wide_t *c[2] = {&p->x, &p->y};
            for (unsigned k = 0; k < 2u; k++) {
                wide_mul_i64(&lo, &p->w, ea[k]);
                wide_mul_i64(&hi, &p->w, eb[k]);
                between = between && (wide_compare(c[k], &lo) * wide_compare(c[k], &hi) <= 0);
            }
            if (between) {
                return true;
            }
        }
        wide_t s, t;
        wide_mul_i64(&s, &p->w, pa.y);
        wide_mul_i64(&t, &p->w, pb.y);
        bool a_below = wide_compare(&s, &p->y) <= 0;
        bool b_below = wide_compare(&t, &p->y) <= 0;
        if (a_below) {
            winding += (!b_below && o > 0) ? 1 : 0;
        } else {
            winding -= (b_below && o < 0) ? 1 : 0;
        }
    }
    return winding != 0;
}

/* Shoelace sums over a running denominator D, the product of the w of
 * every vertex added: twice the area is area2 / D, the moments mx / D^2
 * and my / D^2, so several pieces add up (centroid = moment / 3 area2). */
typedef struct {
    wide_t area2;
    wide_t mx, my;
    wide_t den;
} shoelace_t;

static void shoelace_begin(shoelace_t *s)
{
    wide_set(&s->area2, 0);
    wide_set(&s->mx, 0);
    wide_set(&s->my, 0);
    wide_set(&s->den, 1);
}

static void shoelace_add(shoelace_t *s, const exact_t *v, uint32_t k)
{
    static wide_t prod, t, u, cross, others, old2;
    wide_set(&prod, 1);
    for (uint32_t i = 0; i < k; i++) {
        wide_mul(&prod, &prod, &v[i].w);
    }
    /* the earlier sums over D' = D prod */
    wide_mul(&s->area2, &s->area2, &prod);
    wide_mul(&t, &prod, &prod);
    wide_mul(&s->mx, &s->mx, &t);
    wide_mul(&s->my, &s->my, &t);
    wide_mul(&old2, &s->den, &s->den);
    for (uint32_t i = 0; i < k; i++) {
        const exact_t *p = &v[i], *q = &v[(i + 1u) % k];
        /* others = prod / (w_p w_q) */
        wide_set(&others, 1);
        for (uint32_t l = 0; l < k; l++) {
            if (l != i && l != (i + 1u) % k) {
                wide_mul(&others, &others, &v[l].w);
            }
        }
        /* cross / (w_p w_q), with cross = X_p Y_q - X_q Y_p */
        wide_mul(&cross, &p->x, &q->y);
        wide_mul(&u, &q->x, &p->y);
        wide_sub(&cross, &u);
        wide_mul(&t, &cross, &others);
        wide_mul(&t, &t, &s->den);
        wide_add(&s->area2, &t);
        /* (x_p + x_q) cross / (w_p w_q) = (X_p w_q + X_q w_p) cross / (w_p w_q)^2 */
        wide_mul(&cross, &cross, &others);
        wide_mul(&cross, &cross, &others);
        wide_mul(&cross, &cross, &old2);
        wide_mul(&t, &p->x, &q->w);
        wide_mul(&u, &q->x, &p->w);
        wide_add(&t, &u);
        wide_mul(&t, &t, &cross);
        wide_add(&s->mx, &t);
        wide_mul(&t, &p->y, &q->w);
        wide_mul(&u, &q->y, &p->w);
        wide_add(&t, &u);
        wide_mul(&t, &t, &cross);
        wide_add(&s->my, &t);
    }
    wide_mul(&s->den, &s->den, &prod);
}

/* The library's centroid against the sums: area = floor(area2 / 2D + 1/2),
 * point = floor(moment / (3 area2 D) + 1/2). */
static bool centroid_matches(const shoelace_t *s, const vor_centroid_t *c)
{
    static wide_t den, three;
    wide_mul_i64(&den, &s->den, 2);
    if (!rounds_to(&s->area2, &den, (int64_t)c->area)) {
        return false;
    }
    wide_mul(&three, &s->area2, &s->den);
    wide_mul_i64(&three, &three, 3);
    return rounds_to(&s->mx, &three, c->point.x) && rounds_to(&s->my, &three, c->point.y);
}

/* ------------------------------------------------------------------ */
/* One diagram in one room                                             */

/* Every piece of every site checked, the edges and pieces kept. */
static void check_pieces(const vor_t *d, const room_t *r, uint32_t n, const char *name)
{
    static exact_t v[CLIP_VERTICES];
    static shoelace_t whole, one;
    edges = 0;
    kept_pieces = 0;
    for (uint32_t s = 0; s < n; s++) {
        vor_clip_t clip;
        int err = vor_clip_begin(&clip, d, s, r->v, r->m, scratch, sizeof scratch);
        if (first_of[s] != s) {
            CHECK(err == VOR_ERR_ARG && vor_clip_error(&clip) == VOR_ERR_ARG,
                  "%s: duplicate %u: error %d", name, s, err);
            continue;
        }
        if (!CHECK(err == VOR_OK, "%s: site %u: begin error %d", name, s, err)) {
            continue;
        }
        shoelace_begin(&whole);
        uint32_t count = 0, pieces = 0, total = 0;
        exact_t previous_low;
        while (vor_clip_next(&clip, piece, CLIP_VERTICES, &count)) {
            bool ok = CHECK(count >= 3u && count <= CLIP_VERTICES, "%s: site %u piece %u: %u vertices",
                            name, s, pieces, count);
            for (uint32_t i = 0; ok && i < count; i++) {
                to_exact(&v[i], &piece[i]);
                wide_t zero;
                wide_set(&zero, 0);
                ok = CHECK(wide_compare(&v[i].w, &zero) > 0 && coprime3(&v[i].x, &v[i].y, &v[i].w),
                           "%s: site %u piece %u vertex %u: w <= 0 or not in lowest terms", name,
                           s, pieces, i) &&
                     CHECK(rounds_to(&v[i].x, &v[i].w, piece[i].point.x) &&
                               rounds_to(&v[i].y, &v[i].w, piece[i].point.y),
                           "%s: site %u piece %u vertex %u: rounded to (%d, %d) wrongly", name, s,
                           pieces, i, piece[i].point.x, piece[i].point.y) &&
                     CHECK(in_cell(s, n, &v[i]) && in_closed_room(r, &v[i]),
                           "%s: site %u piece %u vertex %u (%d, %d): outside the cell or room",
                           name, s, pieces, i, piece[i].point.x, piece[i].point.y);
            }
            for (uint32_t i = 0; ok && i < count; i++) {
                const exact_t *a = &v[i], *b = &v[(i + 1u) % count], *c = &v[(i + 2u) % count];
                ok = CHECK(!same_exact(a, b) && turn(a, b, c) != 0,
                           "%s: site %u piece %u: vertex %u repeated or a straight angle", name, s,
                           pieces, (i + 1u) % count) &&
                     CHECK(edge_on_a_line(r, s, n, a, b),
                           "%s: site %u piece %u: edge %u on no bisector or room edge", name, s,
                           pieces, i) &&
                     CHECK(i == 0u || compare_low(&v[0], &v[i]) < 0,
                           "%s: site %u piece %u: vertex %u lower than the first", name, s, pieces,
                           i);
            }
            if (ok && pieces > 0u) {
                CHECK(compare_low(&previous_low, &v[0]) < 0,
                      "%s: site %u: piece %u out of order", name, s, pieces);
            }
            if (ok) {
                previous_low = v[0];
                shoelace_begin(&one);
                shoelace_add(&one, v, count);
                shoelace_add(&whole, v, count);
                wide_t zero;
                wide_set(&zero, 0);
                vor_centroid_t c;
                int e = vor_clip_centroid(&clip, pieces, sums, sizeof sums, &c);
                CHECK(wide_compare(&one.area2, &zero) > 0, "%s: site %u piece %u: area <= 0",
                      name, s, pieces);
                CHECK(e == VOR_OK && c.vertices == count && centroid_matches(&one, &c),
                      "%s: site %u piece %u: centroid error %d, area %u, (%d, %d)", name, s,
                      pieces, e, (unsigned)c.area, c.point.x, c.point.y);
                /* keep the edges and the piece */
                if (CHECK(edges + count <= CLIP_EDGES && kept_pieces < KEPT_PIECES,
                          "%s: too many edges to keep", name)) {
                    kept_site[kept_pieces] = s;
                    kept_start[kept_pieces] = edges;
                    kept_count[kept_pieces] = count;
                    kept_pieces++;
                    for (uint32_t i = 0; i < count; i++) {
                        kept[edges] = piece[i];
                        edge_from[edges] = piece[i];
                        edge_to[edges] = piece[(i + 1u) % count];
                        edge_used[edges] = false;
                        edges++;
                    }
                }
            }
            total += count;
            pieces++;
        }
        CHECK(vor_clip_error(&clip) == VOR_OK && pieces == clip.pieces,
              "%s: site %u: iterator error %d after %u of %u pieces", name, s,
              vor_clip_error(&clip), pieces, clip.pieces);
        vor_centroid_t c;
        int e = vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, sizeof sums, &c);
        if (pieces == 0u) {
            CHECK(e == VOR_OK && c.area == 0 && c.vertices == 0 && c.point.x == sites[s].x &&
                      c.point.y == sites[s].y,
                  "%s: site %u: no pieces, whole centroid error %d", name, s, e);
        } else {
            CHECK(e == VOR_OK && c.vertices == total && centroid_matches(&whole, &c),
                  "%s: site %u: whole centroid error %d, area %u, (%d, %d)", name, s, e,
                  (unsigned)c.area, c.point.x, c.point.y);
        }
    }
}

/* Is c on the segment a b, strictly between its ends? */
static bool strictly_between(const vor_exact_point_t *va, const vor_exact_point_t *vb,
                             const vor_exact_point_t *vc)
{
    static exact_t ea, eb, ec;
    static wide_t u, v;
    if (same_vertex(va, vc) || same_vertex(vb, vc)) {
        return false;
    }
    to_exact(&ea, va);
    to_exact(&eb, vb);
    to_exact(&ec, vc);
    const exact_t *a = &ea, *b = &eb, *c = &ec;
    if (turn(a, b, c) != 0) {
        return false;
    }
    const wide_t *ca[2] = {&a->x, &a->y}, *cb[2] = {&b->x, &b->y}, *cc[2] = {&c->x, &c->y};
    for (unsigned k = 0; k < 2u; k++) {
        wide_mul(&u, cc[k], &a->w);
        wide_mul(&v, ca[k], &c->w);
        int sa = wide_compare(&u, &v); /* sign of c - a */
        wide_mul(&u, cc[k], &b->w);
        wide_mul(&v, cb[k], &c->w);
        int sb = wide_compare(&u, &v); /* sign of c - b */
        if (sa * sb > 0) {
            return false;
        }
    }
    return true;
}

/* Edges that run back along each other cancel. */
static void cancel_edges(void)
{
    for (uint32_t i = 0; i < edges; i++) {
        for (uint32_t j = i + 1u; j < edges && !edge_used[i]; j++) {
            if (!edge_used[j] && same_vertex(&edge_from[i], &edge_to[j]) &&
                same_vertex(&edge_to[i], &edge_from[j])) {
                edge_used[i] = true;
                edge_used[j] = true;
            }
        }
    }
}

/* The tiling: interior edges cancel, the rest chain along the room. An
 * edge of one cell may run straight through a corner of the cells on
 * its other side (a room corner on the bisector): the edges left after
 * a first cancellation are split at the ends of the others on them,
 * then cancel again. */
static void check_tiling(const room_t *r, const char *name)
{
    static vor_exact_point_t corner[CLIP_ROOM];
    static exact_t a, b, c;
    cancel_edges();
    for (uint32_t i = 0; i < edges; i++) {
        for (uint32_t j = 0; j < edges && !edge_used[i]; j++) {
            if (edge_used[j] || j == i) {
                continue;
            }
            const vor_exact_point_t *ends[2] = {&edge_from[j], &edge_to[j]};
            for (unsigned k = 0; k < 2u; k++) {
                if (strictly_between(&edge_from[i], &edge_to[i], ends[k]) &&
                    CHECK(edges < CLIP_EDGES, "%s: too many edges to split", name)) {
                    edge_from[edges] = *ends[k];
                    edge_to[edges] = edge_to[i];
                    edge_used[edges] = false;
                    edges++;
                    edge_to[i] = *ends[k];
                }
            }
        }
    }
    cancel_edges();
    /* the room's corners (straight angles dropped), counterclockwise */
    uint32_t corners = 0;
    for (uint32_t i = 0; i < r->m; i++) {
        from_point(&a, room_ccw(r, (i + r->m - 1u) % r->m));
        from_point(&b, room_ccw(r, i));
        from_point(&c, room_ccw(r, (i + 1u) % r->m));
        if (turn(&a, &b, &c) != 0) {
            vertex_of(&corner[corners++], room_ccw(r, i));
        }
    }
    bool ok = true;
    for (uint32_t k = 0; k < corners && ok; k++) {
        const vor_exact_point_t *end = &corner[(k + 1u) % corners];
        to_exact(&a, &corner[k]);
        to_exact(&b, end);
        vor_exact_point_t at = corner[k];
        uint32_t steps = 0;
        while (ok && !same_vertex(&at, end)) {
            uint32_t found = edges;
            for (uint32_t i = 0; i < edges && found == edges; i++) {
                if (!edge_used[i] && same_vertex(&edge_from[i], &at)) {
                    to_exact(&c, &edge_to[i]);
                    found = (turn(&a, &b, &c) == 0) ? i : edges;
                }
            }
            ok = CHECK(found < edges && steps < edges,
                       "%s: room edge %u is not covered from its start to its end", name, k);
            if (ok) {
                edge_used[found] = true;
                at = edge_to[found];
                steps++;
            }
        }
    }
    for (uint32_t i = 0; i < edges && ok; i++) {
        ok = CHECK(edge_used[i], "%s: edge %u neither cancels nor runs along the room", name, i);
    }
}

/* Random integer points: in a piece of their nearest site, strictly
 * inside none of a farther one's, and strictly inside none outside the
 * room. */
static void check_points(const room_t *r, uint32_t n, test_rng_t *rng, uint32_t samples,
                         const char *name)
{
    int32_t x0 = r->v[0].x, x1 = x0, y0 = r->v[0].y, y1 = y0;
    for (uint32_t i = 1; i < r->m; i++) {
        x0 = (r->v[i].x < x0) ? r->v[i].x : x0;
        x1 = (r->v[i].x > x1) ? r->v[i].x : x1;
        y0 = (r->v[i].y < y0) ? r->v[i].y : y0;
        y1 = (r->v[i].y > y1) ? r->v[i].y : y1;
    }
    for (uint32_t k = 0; k < samples; k++) {
        vor_point_t q = {test_rng_range(rng, x0 - 2, x1 + 2), test_rng_range(rng, y0 - 2, y1 + 2)};
        int where = in_room(r, q);
        int64_t best = INT64_MAX;
        for (uint32_t s = 0; s < n; s++) {
            int64_t dx = (int64_t)q.x - sites[s].x, dy = (int64_t)q.y - sites[s].y;
            best = (dx * dx + dy * dy < best) ? dx * dx + dy * dy : best;
        }
        bool in_nearest = false, wrong = false;
        for (uint32_t p = 0; p < kept_pieces; p++) {
            vor_point_t s = sites[kept_site[p]];
            int64_t dx = (int64_t)q.x - s.x, dy = (int64_t)q.y - s.y;
            int at = in_piece(p, q);
            if (dx * dx + dy * dy == best) {
                in_nearest = in_nearest || (at >= 0);
            } else {
                wrong = wrong || (at > 0);
            }
            wrong = wrong || ((where < 0) && (at > 0));
        }
        CHECK(!wrong && (where <= 0 || in_nearest),
              "%s: point (%d, %d) (room %d): in a farther site's piece or not in its own", name,
              q.x, q.y, where);
    }
}

static void check_room_case(const room_t *r, uint32_t n, test_rng_t *rng, const char *name)
{
    vor_t d;
    if (!build(&d, n)) {
        return;
    }
    check_pieces(&d, r, n, name);
    check_tiling(r, name);
    check_points(r, n, rng, 150u, name);
}

/* ------------------------------------------------------------------ */
/* Cases                                                               */

static void random_sites(test_rng_t *rng, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        sites[i].x = test_rng_range(rng, -10, 70);
        sites[i].y = test_rng_range(rng, -10, 70);
    }
}

static void grid_sites(uint32_t columns, uint32_t rows, int32_t x0, int32_t y0, int32_t step)
{
    for (uint32_t j = 0; j < rows; j++) {
        for (uint32_t i = 0; i < columns; i++) {
            sites[j * columns + i].x = x0 + (int32_t)i * step;
            sites[j * columns + i].y = y0 + (int32_t)j * step;
        }
    }
}

static void test_random(test_rng_t *rng)
{
    for (uint32_t k = 0; k < ROOMS; k++) {
        for (uint32_t round = 0; round < 2u; round++) {
            uint32_t n = 3u + (test_rng_u32(rng) % (CLIP_SITES - 3u));
            random_sites(rng, n);
            check_room_case(&rooms[k], n, rng, rooms[k].name);
        }
    }
}

/* Grids whose bisectors run along room edges and through room corners
 * (cocircular sites: Voronoi vertices of degree 4 on the room). */
static void test_grids(test_rng_t *rng)
{
    for (uint32_t k = 0; k < ROOMS; k++) {
        grid_sites(2, 2, 15, 15, 30); /* bisectors x = 30, y = 30 */
        check_room_case(&rooms[k], 4, rng, rooms[k].name);
        grid_sites(3, 3, 10, 10, 20); /* x, y = 20, 40 */
        check_room_case(&rooms[k], 9, rng, rooms[k].name);
        grid_sites(4, 4, 0, 0, 20); /* sites on room corners and edges */
        check_room_case(&rooms[k], 16, rng, rooms[k].name);
    }
}

static void test_collinear(test_rng_t *rng)
{
    for (uint32_t k = 0; k < ROOMS; k++) {
        for (uint32_t i = 0; i < 6u; i++) {
            sites[i].x = 5 + 10 * (int32_t)i;
            sites[i].y = 5 + 10 * (int32_t)i;
        }
        check_room_case(&rooms[k], 6, rng, rooms[k].name);
        for (uint32_t i = 0; i < 3u; i++) {
            sites[i].x = 10 + 20 * (int32_t)i;
            sites[i].y = 30;
        }
        check_room_case(&rooms[k], 3, rng, rooms[k].name);
    }
}

static void test_few(test_rng_t *rng)
{
    for (uint32_t k = 0; k < ROOMS; k++) {
        sites[0] = (vor_point_t){30, 30};
        check_room_case(&rooms[k], 1, rng, rooms[k].name); /* the room itself */
        sites[1] = (vor_point_t){200, -100};
        check_room_case(&rooms[k], 2, rng, rooms[k].name);
        /* duplicates */
        sites[0] = (vor_point_t){20, 20};
        sites[1] = (vor_point_t){40, 35};
        sites[2] = (vor_point_t){20, 20};
        sites[3] = (vor_point_t){40, 35};
        check_room_case(&rooms[k], 4, rng, rooms[k].name);
    }
}

/* Eight sites on a circle around a ninth. */
static void test_cocircular(test_rng_t *rng)
{
    static const vor_point_t ring[9] = {{30, 30}, {35, 30}, {33, 34}, {30, 35}, {27, 34},
                                        {25, 30}, {27, 26}, {30, 25}, {33, 26}};
    for (uint32_t k = 0; k < ROOMS; k++) {
        for (uint32_t i = 0; i < 9u; i++) {
            sites[i] = ring[i];
        }
        check_room_case(&rooms[k], 9, rng, rooms[k].name);
    }
}

/* Rooms that cut one cell into pieces: the U's arms, and the L's reflex
 * corner on a bisector pinching a cell in two pieces sharing the corner. */
static void test_split(test_rng_t *rng)
{
    vor_t d;
    vor_clip_t clip;
    uint32_t count;
    /* U: the site above the notch owns the tops of both arms */
    sites[0] = (vor_point_t){30, 70};
    sites[1] = (vor_point_t){30, 0};
    if (build(&d, 2)) {
        CHECK(vor_clip_begin(&clip, &d, 0, rooms[2].v, rooms[2].m, scratch, sizeof scratch) ==
                      VOR_OK &&
                  clip.pieces == 2u,
              "U: %u pieces, 2 expected", clip.pieces);
        CHECK(vor_clip_next(&clip, piece, CLIP_VERTICES, &count) && count == 4u &&
                  piece[0].point.x == 0 && piece[0].point.y == 35 && piece[1].point.x == 20 &&
                  piece[1].point.y == 35 && piece[2].point.x == 20 && piece[2].point.y == 60,
              "U: the first piece is not the left arm's top");
        CHECK(vor_clip_next(&clip, piece, CLIP_VERTICES, &count) && count == 4u &&
                  piece[0].point.x == 40 && piece[0].point.y == 35,
              "U: the second piece is not the right arm's top");
        check_room_case(&rooms[2], 2, rng, "U_two");
    }
    /* L: the bisector x + y = 60 through the reflex corner (30, 30) */
    sites[0] = (vor_point_t){20, 20};
    sites[1] = (vor_point_t){40, 40};
    if (build(&d, 2)) {
        CHECK(vor_clip_begin(&clip, &d, 1, rooms[1].v, rooms[1].m, scratch, sizeof scratch) ==
                      VOR_OK &&
                  clip.pieces == 2u,
              "L pinch: %u pieces, 2 expected", clip.pieces);
        /* (60, 0), (60, 30), (30, 30) and (30, 30), (30, 60), (0, 60) */
        CHECK(vor_clip_next(&clip, piece, CLIP_VERTICES, &count) && count == 3u &&
                  piece[0].point.x == 60 && piece[0].point.y == 0 && piece[2].point.x == 30 &&
                  piece[2].point.y == 30,
              "L pinch: the lower piece is wrong");
        CHECK(vor_clip_next(&clip, piece, CLIP_VERTICES, &count) && count == 3u &&
                  piece[0].point.x == 30 && piece[0].point.y == 30 && piece[1].point.x == 30 &&
                  piece[1].point.y == 60,
              "L pinch: the upper piece is wrong");
        CHECK(!vor_clip_next(&clip, piece, CLIP_VERTICES, &count) &&
                  vor_clip_error(&clip) == VOR_OK,
              "L pinch: a third piece");
    }
}

/* Both orientations of a room give the same pieces. */
static void test_orientation(test_rng_t *rng)
{
    static vor_exact_point_t other[CLIP_VERTICES];
    vor_t d;
    random_sites(rng, 10);
    if (!build(&d, 10)) {
        return;
    }
    for (uint32_t s = 0; s < 10u; s++) {
        vor_clip_t a, b;
        uint32_t ca, cb;
        bool same = vor_clip_begin(&a, &d, s, rooms[1].v, rooms[1].m, scratch, sizeof scratch) ==
                    VOR_OK;
        static uint8_t scratch2[sizeof scratch];
        same = same && vor_clip_begin(&b, &d, s, rooms[6].v, rooms[6].m, scratch2,
                                      sizeof scratch2) == VOR_OK;
        same = same && a.pieces == b.pieces;
        while (same && vor_clip_next(&a, piece, CLIP_VERTICES, &ca)) {
            same = vor_clip_next(&b, other, CLIP_VERTICES, &cb) && ca == cb &&
                   test_same_bytes(piece, other, ca * sizeof piece[0]);
        }
        CHECK(same, "site %u: the clockwise L gives other pieces", s);
    }
}

/* A room's vertices far apart: int32 extremes, exact and rounded. */
static void test_wide(test_rng_t *rng)
{
    static const vor_point_t big[4] = {{INT32_MIN, INT32_MIN},
                                       {INT32_MAX, INT32_MIN},
                                       {INT32_MAX, INT32_MAX},
                                       {INT32_MIN, INT32_MAX}};
    vor_t d;
    for (uint32_t k = 0; k < 4u; k++) {
        for (uint32_t i = 0; i < 8u; i++) {
            sites[i].x = (int32_t)test_rng_u32(rng);
            sites[i].y = (int32_t)test_rng_u32(rng);
        }
        if (!build(&d, 8)) {
            return;
        }
        /* the exact areas of the cells add up to the room's: checked by
         * the edges cancelling and chaining along the room */
        static room_t room;
        room.name = "wide";
        room.m = 4;
        for (uint32_t i = 0; i < 4u; i++) {
            room.v[i] = big[i];
        }
        edges = 0;
        kept_pieces = 0;
        for (uint32_t s = 0; s < 8u; s++) {
            vor_clip_t clip;
            uint32_t count;
            bool ok = CHECK(vor_clip_begin(&clip, &d, s, big, 4, scratch, sizeof scratch) ==
                                    VOR_OK &&
                                clip.pieces == 1u,
                            "wide: site %u", s);
            while (ok && vor_clip_next(&clip, piece, CLIP_VERTICES, &count)) {
                for (uint32_t i = 0; i < count && edges < CLIP_EDGES; i++) {
                    static exact_t e;
                    edge_from[edges] = piece[i];
                    edge_to[edges] = piece[(i + 1u) % count];
                    edge_used[edges] = false;
                    to_exact(&e, &piece[i]);
                    CHECK(in_cell(s, 8, &e) && rounds_to(&e.x, &e.w, piece[i].point.x) &&
                              rounds_to(&e.y, &e.w, piece[i].point.y),
                          "wide: site %u vertex %u", s, i);
                    edges++;
                }
            }
        }
        check_tiling(&room, "wide");
    }
}

/* ------------------------------------------------------------------ */
/* Errors                                                              */

static const room_t bad_rooms[] = {
    {"bowtie", 4, {{0, 0}, {10, 10}, {10, 0}, {0, 10}}},
    {"touching", 7, {{0, 0}, {40, 0}, {40, 40}, {30, 40}, {20, 0}, {10, 40}, {0, 40}}},
    {"overlap", 5, {{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 0}}},
    {"fold", 4, {{0, 0}, {20, 0}, {20, 20}, {20, 10}}},
    {"fold_closing", 4, {{0, 0}, {20, 0}, {20, 20}, {0, 20}}}, /* replaced below */
    {"repeated", 4, {{0, 0}, {20, 0}, {20, 0}, {0, 20}}},
    {"repeated_closing", 4, {{0, 0}, {20, 0}, {0, 20}, {0, 0}}},
    {"collinear3", 3, {{0, 0}, {20, 0}, {10, 0}}},
    {"collinear4", 4, {{0, 0}, {10, 0}, {20, 0}, {30, 0}}},
    {"figure8", 6, {{0, 0}, {20, 0}, {10, 10}, {20, 20}, {0, 20}, {10, 10}}},
    {"vertical_overlap", 7, {{0, 0}, {10, 0}, {10, 20}, {20, 20}, {20, 30}, {10, 30}, {10, 10}}},
    {"repeated3", 3, {{0, 0}, {20, 0}, {20, 0}}},
};

static void test_bad_rooms(void)
{
    vor_t d;
    sites[0] = (vor_point_t){5, 5};
    sites[1] = (vor_point_t){15, 8};
    if (!build(&d, 2)) {
        return;
    }
    for (uint32_t k = 0; k < sizeof bad_rooms / sizeof bad_rooms[0]; k++) {
        room_t r = bad_rooms[k];
        if (k == 4u) { /* the last edge folds back over the first */
            r.v[3] = (vor_point_t){30, 0};
            r.v[2] = (vor_point_t){10, 10};
        }
        for (uint32_t i = 0; i < sizeof scratch; i++) {
            scratch[i] = 0xA5;
        }
        vor_clip_t clip;
        uint32_t count = 77;
        int err = vor_clip_begin(&clip, &d, 0, r.v, r.m, scratch, sizeof scratch);
        bool untouched = true;
        for (uint32_t i = 0; i < sizeof scratch; i++) {
            untouched = untouched && scratch[i] == 0xA5;
        }
        CHECK(err == VOR_ERR_POLYGON && untouched && vor_clip_error(&clip) == VOR_ERR_POLYGON &&
                  !vor_clip_next(&clip, piece, CLIP_VERTICES, &count) && count == 77u,
              "%s: error %d, scratch %s", r.name, err, untouched ? "untouched" : "written");
    }
}

static void test_errors(void)
{
    vor_t d;
    vor_clip_t clip;
    uint32_t count;
    vor_centroid_t c;
    const room_t *L = &rooms[1];
    sites[0] = (vor_point_t){10, 10};
    sites[1] = (vor_point_t){50, 10};
    sites[2] = (vor_point_t){10, 10};
    sites[3] = (vor_point_t){10, 50};
    if (!build(&d, 4)) {
        return;
    }
    for (uint32_t i = 0; i < sizeof scratch; i++) {
        scratch[i] = 0x5A;
    }
    int bad[9];
    bad[0] = vor_clip_begin(NULL, &d, 0, L->v, L->m, scratch, sizeof scratch);
    bad[1] = vor_clip_begin(&clip, NULL, 0, L->v, L->m, scratch, sizeof scratch);
    bad[2] = vor_clip_begin(&clip, &d, 0, NULL, L->m, scratch, sizeof scratch);
    bad[3] = vor_clip_begin(&clip, &d, 0, L->v, 2, scratch, sizeof scratch);
    bad[4] = vor_clip_begin(&clip, &d, 0, L->v, VOR_CLIP_MAX_ROOM + 1u, scratch, sizeof scratch);
    bad[5] = vor_clip_begin(&clip, &d, 0, L->v, L->m, NULL, sizeof scratch);
    bad[6] = vor_clip_begin(&clip, &d, 2, L->v, L->m, scratch, sizeof scratch); /* duplicate */
    bad[7] = vor_clip_begin(&clip, &d, 4, L->v, L->m, scratch, sizeof scratch); /* unknown */
    bad[8] = vor_clip_begin(&clip, &d, 0, L->v, L->m, NULL, 0); /* too small */
    bool untouched = true;
    for (uint32_t i = 0; i < sizeof scratch; i++) {
        untouched = untouched && scratch[i] == 0x5A;
    }
    CHECK(bad[0] == VOR_ERR_ARG && bad[1] == VOR_ERR_ARG && bad[2] == VOR_ERR_ARG &&
              bad[3] == VOR_ERR_ARG && bad[4] == VOR_ERR_ARG && bad[5] == VOR_ERR_ARG &&
              bad[6] == VOR_ERR_ARG && bad[7] == VOR_ERR_ARG && bad[8] == VOR_ERR_BUFFER &&
              untouched,
          "begin errors: %d %d %d %d %d %d %d %d %d", bad[0], bad[1], bad[2], bad[3], bad[4],
          bad[5], bad[6], bad[7], bad[8]);
    CHECK(vor_clip_error(&clip) == VOR_ERR_BUFFER && !vor_clip_next(&clip, piece, 9, &count) &&
              vor_clip_error(NULL) == VOR_ERR_ARG && !vor_clip_next(NULL, piece, 9, &count) &&
              vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, sizeof sums, &c) == VOR_ERR_ARG,
          "a closed iterator");
    /* the scratch the site needs: 2 neighbours here */
    size_t need = VOR_CLIP_SCRATCH_BYTES(L->m, 3);
    CHECK(vor_clip_begin(&clip, &d, 0, L->v, L->m, scratch, need - 1u) == VOR_ERR_BUFFER &&
              clip.needed == need &&
              vor_clip_begin(&clip, &d, 0, L->v, L->m, NULL, 0) == VOR_ERR_BUFFER &&
              vor_clip_begin(&clip, &d, 0, L->v, L->m, scratch + 1, need) == VOR_OK &&
              vor_clip_begin(&clip, &d, 0, L->v, L->m, scratch, need) == VOR_OK,
          "scratch sizes");
    /* next: bad outputs, a buffer too small (nothing written, resumes) */
    CHECK(!vor_clip_next(&clip, piece, 9, NULL) && vor_clip_error(&clip) == VOR_ERR_ARG &&
              !vor_clip_next(&clip, NULL, 9, &count) && vor_clip_error(&clip) == VOR_ERR_ARG,
          "next: bad outputs");
    piece[0].point.x = 1234;
    count = 0;
    CHECK(!vor_clip_next(&clip, piece, 2, &count) && vor_clip_error(&clip) == VOR_ERR_BUFFER &&
              count >= 3u && piece[0].point.x == 1234 &&
              !vor_clip_next(&clip, NULL, 0, &count) && vor_clip_error(&clip) == VOR_ERR_BUFFER,
          "next: a buffer too small");
    uint32_t needed = count;
    CHECK(vor_clip_next(&clip, piece, needed, &count) && count == needed &&
              vor_clip_error(&clip) == VOR_OK &&
              !vor_clip_next(&clip, piece, CLIP_VERTICES, &count) &&
              vor_clip_error(&clip) == VOR_OK,
          "next: resumed after VOR_ERR_BUFFER");
    /* centroid errors */
    vor_centroid_t keep = {{7, 8}, 9, 10};
    c = keep;
    int e[6];
    e[0] = vor_clip_centroid(NULL, 0, sums, sizeof sums, &c);
    e[1] = vor_clip_centroid(&clip, 0, sums, sizeof sums, NULL);
    e[2] = vor_clip_centroid(&clip, 1, sums, sizeof sums, &c);
    e[3] = vor_clip_centroid(&clip, 0, NULL, sizeof sums, &c);
    CHECK(e[0] == VOR_ERR_ARG && e[1] == VOR_ERR_ARG && e[2] == VOR_ERR_ARG &&
              e[3] == VOR_ERR_ARG && test_same_bytes(&c, &keep, sizeof c),
          "centroid: bad arguments %d %d %d %d", e[0], e[1], e[2], e[3]);
    e[4] = vor_clip_centroid(&clip, 0, sums, 10, &c);
    CHECK(e[4] == VOR_ERR_BUFFER && c.vertices == needed && c.area == 9u && c.point.x == 7,
          "centroid: a scratch too small: %d, k %u", e[4], c.vertices);
    e[5] = vor_clip_centroid(&clip, 0, sums + 3, VOR_CENTROID_SCRATCH_BYTES(needed), &c);
    CHECK(e[5] == VOR_OK && c.vertices == needed && c.area > 0u,
          "centroid: VOR_CENTROID_SCRATCH_BYTES(k), unaligned: %d", e[5]);
    /* a cell outside the room: no pieces */
    static const vor_point_t corner_room[3] = {{0, 0}, {8, 0}, {0, 8}};
    CHECK(vor_clip_begin(&clip, &d, 1, corner_room, 3, scratch, sizeof scratch) == VOR_OK &&
              clip.pieces == 0u && !vor_clip_next(&clip, piece, CLIP_VERTICES, &count) &&
              vor_clip_error(&clip) == VOR_OK &&
              vor_clip_centroid(&clip, VOR_CLIP_WHOLE, NULL, 0, &c) == VOR_OK && c.area == 0u &&
              c.vertices == 0u && c.point.x == 50 && c.point.y == 10 &&
              vor_clip_centroid(&clip, 0, sums, sizeof sums, &c) == VOR_ERR_ARG,
          "a cell outside the room");
    /* the whole's scratch counts the vertices and the pieces after the first */
    sites[0] = (vor_point_t){30, 70};
    sites[1] = (vor_point_t){30, 0};
    if (build(&d, 2) &&
        CHECK(vor_clip_begin(&clip, &d, 0, rooms[2].v, rooms[2].m, scratch, sizeof scratch) ==
                  VOR_OK, "U")) {
        CHECK(vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, VOR_CENTROID_SCRATCH_BYTES(8),
                                &c) == VOR_ERR_BUFFER &&
                  c.vertices == 9u &&
                  vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, VOR_CENTROID_SCRATCH_BYTES(9),
                                    &c) == VOR_OK &&
                  c.vertices == 8u && c.area == 2u * 20u * 25u && c.point.x == 30 &&
                  c.point.y == 48,
              "U: whole centroid %u vertices, area %u, (%d, %d)", c.vertices, (unsigned)c.area,
              c.point.x, c.point.y);
    }
}

void test_clip(void)
{
    test_rng_t rng;
    TEST_CASE("errors") test_errors();
    TEST_CASE("bad_rooms") test_bad_rooms();
    TEST_CASE("split") test_split(test_rng_seed(&rng, 0xC11F0008u));
    TEST_CASE("few") test_few(test_rng_seed(&rng, 0xC11F0001u));
    TEST_CASE("grids") test_grids(test_rng_seed(&rng, 0xC11F0002u));
    TEST_CASE("collinear") test_collinear(test_rng_seed(&rng, 0xC11F0003u));
    TEST_CASE("cocircular") test_cocircular(test_rng_seed(&rng, 0xC11F0004u));
    TEST_CASE("orientation") test_orientation(test_rng_seed(&rng, 0xC11F0005u));
    TEST_CASE("random") test_random(test_rng_seed(&rng, 0xC11F0006u));
    TEST_CASE("wide") test_wide(test_rng_seed(&rng, 0xC11F0007u));
}

/* ================================================================== */
/* Order-K cells (vor_order_cell_begin, vor_order_cells_*)             */
/*
 * Against the same independent checks: every vertex exactly in the
 * closed order-K cell of its set (every half-plane of s in the set
 * against t outside, over all sites, brute force) and in the closed
 * room, every edge on such a bisector or a room edge, rounding, lowest
 * terms, counterclockwise, centroids against the shoelace; the tiling of
 * the room by the pieces of all the walk's cells (edges cancelling and
 * chaining along the room: the exact areas add up to the room's); every
 * set met once, increasing, at most VOR_ORDER_MAX_CELLS; the single-cell
 * call giving the walk's pieces for the set in any order; random integer
 * points in a piece of their brute-force K nearest sites (ties to the
 * smaller index) and strictly inside no piece of another set; order 1
 * against vor_clip_begin; errors leaving everything unchanged.
 */

#define ORDER_MAX_K 8u
#define ORDER_SITES 10u
#define ORDER_CELLS VOR_ORDER_MAX_CELLS(ORDER_SITES, ORDER_SITES / 2u)
static uint32_t order_sets[VOR_ORDER_SETS_WORDS(ORDER_CELLS, ORDER_MAX_K + 1u)];
static uint8_t order_scratch[VOR_ORDER_SCRATCH_BYTES(CLIP_ROOM, CLIP_SITES, CLIP_SITES / 2u) + 4u];
static uint8_t order_scratch2[sizeof order_scratch];
static uint32_t kept_set[KEPT_PIECES][ORDER_MAX_K];

/* Is p in the closed order-k cell of set[0 .. k)? */
static bool in_order_cell(const uint32_t *set, uint32_t k, uint32_t n, const exact_t *p)
{
    for (uint32_t t = 0; t < n; t++) {
        bool inside = false;
        for (uint32_t i = 0; i < k; i++) {
            inside = inside || (sites[set[i]].x == sites[t].x && sites[set[i]].y == sites[t].y);
        }
        for (uint32_t i = 0; i < k && !inside; i++) {
            vor_point_t a = sites[set[i]], o = sites[t];
            int64_t ca = 2 * ((int64_t)o.x - a.x), cb = 2 * ((int64_t)o.y - a.y);
            int64_t cc = (int64_t)o.x * o.x + (int64_t)o.y * o.y - (int64_t)a.x * a.x -
                         (int64_t)a.y * a.y;
            if (line_side(p, ca, cb, cc) > 0) {
                return false;
            }
        }
    }
    return true;
}

/* Does the edge a -> b lie on a bisector of a site of the set with a site
 * outside, or on a room edge? */
static bool edge_on_order_line(const room_t *r, const uint32_t *set, uint32_t k, uint32_t n,
                               const exact_t *a, const exact_t *b)
{
    for (uint32_t i = 0; i < k; i++) {
        for (uint32_t t = 0; t < n; t++) {
            vor_point_t p = sites[set[i]], o = sites[t];
            if (p.x == o.x && p.y == o.y) {
                continue;
            }
            int64_t ca = 2 * ((int64_t)o.x - p.x), cb = 2 * ((int64_t)o.y - p.y);
            int64_t cc = (int64_t)o.x * o.x + (int64_t)o.y * o.y - (int64_t)p.x * p.x -
                         (int64_t)p.y * p.y;
            if (line_side(a, ca, cb, cc) == 0 && line_side(b, ca, cb, cc) == 0) {
                return true;
            }
        }
    }
    return edge_on_a_line(r, set[0], 0, a, b);
}

/* The k nearest distinct sites of q, ties to the smaller index, sorted. */
static void brute_nearest(vor_point_t q, uint32_t n, uint32_t k, uint32_t *out, bool *tie)
{
    static int64_t dist[CLIP_SITES];
    static bool taken[CLIP_SITES];
    for (uint32_t s = 0; s < n; s++) {
        int64_t dx = (int64_t)q.x - sites[s].x, dy = (int64_t)q.y - sites[s].y;
        dist[s] = dx * dx + dy * dy;
        taken[s] = first_of[s] != s;
    }
    int64_t last = 0;
    for (uint32_t r = 0; r < k; r++) {
        uint32_t best = n;
        for (uint32_t s = 0; s < n; s++) {
            if (!taken[s] && (best == n || dist[s] < dist[best])) {
                best = s;
            }
        }
        taken[best] = true;
        out[r] = best;
        last = dist[best];
    }
    /* a tie between the k-th and the (k+1)-th: q is on a cell boundary */
    *tie = false;
    for (uint32_t s = 0; s < n; s++) {
        *tie = *tie || (!taken[s] && dist[s] == last);
    }
    for (uint32_t i = 1; i < k; i++) {
        for (uint32_t j = i; j > 0u && out[j - 1u] > out[j]; j--) {
            uint32_t t = out[j];
            out[j] = out[j - 1u];
            out[j - 1u] = t;
        }
    }
}

/* Random integer points: in a piece of their K nearest sites' cell, and
 * strictly inside no piece of another set (nor any outside the room). */
static void check_order_points(const room_t *r, uint32_t n, uint32_t k, test_rng_t *rng,
                               uint32_t samples, const char *name)
{
    int32_t x0 = r->v[0].x, x1 = x0, y0 = r->v[0].y, y1 = y0;
    for (uint32_t i = 1; i < r->m; i++) {
        x0 = (r->v[i].x < x0) ? r->v[i].x : x0;
        x1 = (r->v[i].x > x1) ? r->v[i].x : x1;
        y0 = (r->v[i].y < y0) ? r->v[i].y : y0;
        y1 = (r->v[i].y > y1) ? r->v[i].y : y1;
    }
    for (uint32_t sample = 0; sample < samples; sample++) {
        vor_point_t q = {test_rng_range(rng, x0 - 2, x1 + 2), test_rng_range(rng, y0 - 2, y1 + 2)};
        int where = in_room(r, q);
        uint32_t near[ORDER_MAX_K];
        bool tie;
        brute_nearest(q, n, k, near, &tie);
        bool in_own = false, wrong = false;
        for (uint32_t p = 0; p < kept_pieces; p++) {
            bool own = test_same_bytes(kept_set[p], near, k * sizeof near[0]);
            int at = in_piece(p, q);
            if (own) {
                in_own = in_own || (at >= 0);
            } else {
                wrong = wrong || (at > 0);
            }
            wrong = wrong || ((where < 0) && (at > 0)) || (tie && at > 0);
        }
        CHECK(!wrong && (where <= 0 || in_own),
              "%s k %u: point (%d, %d) (room %d): in another set's piece or not in its own", name,
              k, q.x, q.y, where);
    }
}

/* The walk's cells in one room: every check above. */
static void check_order_case(const room_t *r, uint32_t n, uint32_t k, test_rng_t *rng,
                             const char *name)
{
    static exact_t v[CLIP_VERTICES];
    static shoelace_t one;
    static vor_exact_point_t other[CLIP_VERTICES];
    vor_t d;
    if (!build(&d, n)) {
        return;
    }
    uint32_t distinct = 0;
    for (uint32_t s = 0; s < n; s++) {
        distinct += (first_of[s] == s) ? 1u : 0u;
    }
    edges = 0;
    kept_pieces = 0;
    vor_order_iter_t it;
    vor_clip_t clip;
    uint32_t set[ORDER_MAX_K];
    uint32_t cells = 0;
    int err = vor_order_cells_begin(&it, &d, k, r->v, r->m, order_sets, ORDER_CELLS,
                                    order_scratch, sizeof order_scratch);
    if (!CHECK(err == VOR_OK, "%s k %u: begin error %d", name, k, err)) {
        return;
    }
    while (vor_order_cells_next(&it, set, &clip)) {
        bool ok = CHECK(clip.pieces >= 1u, "%s k %u: an empty cell", name, k);
        for (uint32_t i = 0; ok && i < k; i++) {
            ok = CHECK(first_of[set[i]] == set[i] && (i == 0u || set[i - 1u] < set[i]),
                       "%s k %u: set not increasing distinct sites", name, k);
        }
        /* the same set from the single call, given backwards */
        uint32_t backwards[ORDER_MAX_K];
        for (uint32_t i = 0; i < k; i++) {
            backwards[i] = set[k - 1u - i];
        }
        vor_clip_t single;
        ok = ok && CHECK(vor_order_cell_begin(&single, &d, backwards, k, r->v, r->m,
                                              order_scratch2, sizeof order_scratch2) == VOR_OK &&
                             single.pieces == clip.pieces,
                         "%s k %u: the single call disagrees on the pieces", name, k);
        uint32_t count = 0, pieces = 0;
        while (ok && vor_clip_next(&clip, piece, CLIP_VERTICES, &count)) {
            uint32_t count2 = 0;
            ok = CHECK(vor_clip_next(&single, other, CLIP_VERTICES, &count2) && count2 == count &&
                           test_same_bytes(piece, other, count * sizeof piece[0]),
                       "%s k %u: piece %u differs from the single call's", name, k, pieces) &&
                 CHECK(count >= 3u, "%s k %u: %u vertices", name, k, count);
            for (uint32_t i = 0; ok && i < count; i++) {
                to_exact(&v[i], &piece[i]);
                wide_t zero;
                wide_set(&zero, 0);
                ok = CHECK(wide_compare(&v[i].w, &zero) > 0 &&
                               coprime3(&v[i].x, &v[i].y, &v[i].w) &&
                               rounds_to(&v[i].x, &v[i].w, piece[i].point.x) &&
                               rounds_to(&v[i].y, &v[i].w, piece[i].point.y),
                           "%s k %u: vertex %u: w, lowest terms or rounding", name, k, i) &&
                     CHECK(in_order_cell(set, k, n, &v[i]) && in_closed_room(r, &v[i]),
                           "%s k %u: vertex %u (%d, %d) outside the cell or room", name, k, i,
                           piece[i].point.x, piece[i].point.y);
            }
            for (uint32_t i = 0; ok && i < count; i++) {
                const exact_t *a = &v[i], *b = &v[(i + 1u) % count], *c = &v[(i + 2u) % count];
                ok = CHECK(!same_exact(a, b) && turn(a, b, c) != 0 &&
                               edge_on_order_line(r, set, k, n, a, b) &&
                               (i == 0u || compare_low(&v[0], &v[i]) < 0),
                           "%s k %u: piece %u edge %u", name, k, pieces, i);
            }
            if (ok) {
                shoelace_begin(&one);
                shoelace_add(&one, v, count);
                vor_centroid_t c;
                wide_t zero;
                wide_set(&zero, 0);
                int e = vor_clip_centroid(&clip, pieces, sums, sizeof sums, &c);
                CHECK(wide_compare(&one.area2, &zero) > 0 && e == VOR_OK && c.vertices == count &&
                          centroid_matches(&one, &c),
                      "%s k %u: piece %u: area or centroid", name, k, pieces);
                if (CHECK(edges + count <= CLIP_EDGES && kept_pieces < KEPT_PIECES,
                          "%s: too many edges to keep", name)) {
                    for (uint32_t i = 0; i < k; i++) {
                        kept_set[kept_pieces][i] = set[i];
                    }
                    kept_start[kept_pieces] = edges;
                    kept_count[kept_pieces] = count;
                    kept_pieces++;
                    for (uint32_t i = 0; i < count; i++) {
                        kept[edges] = piece[i];
                        edge_from[edges] = piece[i];
                        edge_to[edges] = piece[(i + 1u) % count];
                        edge_used[edges] = false;
                        edges++;
                    }
                }
            }
            pieces++;
        }
        CHECK(vor_clip_error(&clip) == VOR_OK && pieces == clip.pieces,
              "%s k %u: pieces %u of %u", name, k, pieces, clip.pieces);
        cells++;
    }
    CHECK(vor_order_cells_error(&it) == VOR_OK && it.met <= VOR_ORDER_MAX_CELLS(distinct, k),
          "%s k %u: walk error %d, %u sets met", name, k, vor_order_cells_error(&it), it.met);
    /* every set once: the yielded ones are distinct (sorted index) */
    for (uint32_t a = 0; a < kept_pieces; a++) {
        for (uint32_t b = a + 1u; b < kept_pieces; b++) {
            /* pieces of one cell are consecutive */
            bool same = test_same_bytes(kept_set[a], kept_set[b], k * sizeof set[0]);
            bool between = true;
            for (uint32_t c = a + 1u; c < b && between; c++) {
                between = test_same_bytes(kept_set[a], kept_set[c], k * sizeof set[0]);
            }
            CHECK(!same || between, "%s k %u: a set yielded twice", name, k);
        }
    }
    check_tiling(r, name);
    check_order_points(r, n, k, rng, 60u, name);
    (void)cells;
}

/* Order 1: vor_clip_begin's pieces, the walk's sets every site meeting
 * the room. */
static void check_order_one(const room_t *r, uint32_t n, const char *name)
{
    static vor_exact_point_t other[CLIP_VERTICES];
    vor_t d;
    if (!build(&d, n)) {
        return;
    }
    for (uint32_t s = 0; s < n; s++) {
        if (first_of[s] != s) {
            continue;
        }
        vor_clip_t a, b;
        uint32_t ca, cb;
        bool same = vor_clip_begin(&a, &d, s, r->v, r->m, scratch, sizeof scratch) == VOR_OK &&
                    vor_order_cell_begin(&b, &d, &s, 1, r->v, r->m, order_scratch,
                                         sizeof order_scratch) == VOR_OK &&
                    a.pieces == b.pieces;
        while (same && vor_clip_next(&a, piece, CLIP_VERTICES, &ca)) {
            same = vor_clip_next(&b, other, CLIP_VERTICES, &cb) && ca == cb &&
                   test_same_bytes(piece, other, ca * sizeof piece[0]);
        }
        CHECK(same, "%s: site %u: order 1 differs from vor_clip_begin", name, s);
    }
}

static void order_cases(const room_t *r, uint32_t n, test_rng_t *rng, const char *name)
{
    uint32_t distinct = 0;
    for (uint32_t s = 0; s < n; s++) {
        distinct += 1u;
        for (uint32_t t = 0; t < s; t++) {
            if (sites[s].x == sites[t].x && sites[s].y == sites[t].y) {
                distinct -= 1u;
                break;
            }
        }
    }
    check_order_one(r, n, name);
    for (uint32_t k = 1; k < distinct && k <= ORDER_MAX_K; k++) {
        if (k <= 3u || k + 1u == distinct) {
            check_order_case(r, n, k, rng, name);
        }
    }
}

static void test_order_random(test_rng_t *rng)
{
    for (uint32_t k = 0; k < ROOMS; k++) {
        uint32_t n = 3u + (test_rng_u32(rng) % (ORDER_SITES - 2u));
        random_sites(rng, n);
        order_cases(&rooms[k], n, rng, rooms[k].name);
    }
}

/* Grids (cocircular sites, coinciding bisectors: x = 30 is the bisector
 * of two pairs), a ring with its centre, collinear sites, duplicates. */
static void test_order_degenerate(test_rng_t *rng)
{
    static const vor_point_t ring[9] = {{30, 30}, {35, 30}, {33, 34}, {30, 35}, {27, 34},
                                        {25, 30}, {27, 26}, {30, 25}, {33, 26}};
    static const uint32_t some[4] = {0, 1, 2, 8};
    for (uint32_t j = 0; j < 4u; j++) {
        const room_t *r = &rooms[some[j]];
        grid_sites(2, 2, 15, 15, 30);
        order_cases(r, 4, rng, "grid2");
        grid_sites(3, 3, 10, 10, 20);
        order_cases(r, 9, rng, "grid3");
        for (uint32_t i = 0; i < 9u; i++) {
            sites[i] = ring[i];
        }
        order_cases(r, 9, rng, "ring");
        for (uint32_t i = 0; i < 5u; i++) {
            sites[i].x = 5 + 12 * (int32_t)i;
            sites[i].y = 30;
        }
        order_cases(r, 5, rng, "collinear");
        /* two pairs mirrored in one line: x = 30 bounds S = {0, 1} */
        sites[0] = (vor_point_t){20, 20};
        sites[1] = (vor_point_t){20, 40};
        sites[2] = (vor_point_t){40, 20};
        sites[3] = (vor_point_t){40, 40};
        sites[4] = (vor_point_t){20, 20};
        sites[5] = (vor_point_t){90, 30};
        order_cases(r, 6, rng, "mirrored");
    }
    /* a band across x = 30 where only the cells of {0, 1} and {2, 3}
     * meet: the walk crosses there by swapping both pairs at once */
    static const room_t band = {"band", 4, {{22, 26}, {38, 26}, {38, 34}, {22, 34}}};
    sites[0] = (vor_point_t){20, 20};
    sites[1] = (vor_point_t){20, 40};
    sites[2] = (vor_point_t){40, 20};
    sites[3] = (vor_point_t){40, 40};
    sites[4] = (vor_point_t){90, 30};
    order_cases(&band, 5, rng, "band");
    /* collinear room edges */
    random_sites(rng, 7);
    order_cases(&rooms[3], 7, rng, "collinear_room");
}

static void test_order_errors(void)
{
    vor_t d;
    vor_clip_t clip;
    const room_t *L = &rooms[1];
    sites[0] = (vor_point_t){10, 10};
    sites[1] = (vor_point_t){50, 10};
    sites[2] = (vor_point_t){10, 10};
    sites[3] = (vor_point_t){10, 50};
    sites[4] = (vor_point_t){40, 45};
    if (!build(&d, 5)) {
        return;
    }
    for (uint32_t i = 0; i < sizeof order_scratch; i++) {
        order_scratch[i] = 0x5A;
    }
    static const vor_point_t bowtie[4] = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
    const uint32_t good[2] = {0, 3}, dup[2] = {3, 3}, dupsite[2] = {0, 2}, unknown[2] = {0, 5},
                   four[4] = {0, 1, 3, 4};
    int bad[14];
    size_t bytes = sizeof order_scratch;
    uint8_t *sc = order_scratch;
    bad[0] = vor_order_cell_begin(NULL, &d, good, 2, L->v, L->m, sc, bytes);
    bad[1] = vor_order_cell_begin(&clip, NULL, good, 2, L->v, L->m, sc, bytes);
    bad[2] = vor_order_cell_begin(&clip, &d, NULL, 2, L->v, L->m, sc, bytes);
    bad[3] = vor_order_cell_begin(&clip, &d, good, 0, L->v, L->m, sc, bytes);
    bad[4] = vor_order_cell_begin(&clip, &d, four, 4, L->v, L->m, sc, bytes); /* k = n */
    bad[5] = vor_order_cell_begin(&clip, &d, dup, 2, L->v, L->m, sc, bytes);
    bad[6] = vor_order_cell_begin(&clip, &d, dupsite, 2, L->v, L->m, sc, bytes);
    bad[7] = vor_order_cell_begin(&clip, &d, unknown, 2, L->v, L->m, sc, bytes);
    bad[8] = vor_order_cell_begin(&clip, &d, good, 2, NULL, L->m, sc, bytes);
    bad[9] = vor_order_cell_begin(&clip, &d, good, 2, L->v, 2, sc, bytes);
    bad[10] = vor_order_cell_begin(&clip, &d, good, 2, L->v, L->m, NULL, bytes);
    bad[11] = vor_order_cell_begin(&clip, &d, good, 2, bowtie, 4, sc, bytes);
    bad[12] = vor_order_cell_begin(&clip, &d, good, 2, L->v, L->m, sc, 100);
    size_t needed = clip.needed;
    bad[13] = vor_order_cell_begin(&clip, &d, good, VOR_ORDER_MAX + 1u, L->v, L->m, sc, bytes);
    bool untouched = true;
    for (uint32_t i = 0; i < sizeof order_scratch; i++) {
        untouched = untouched && order_scratch[i] == 0x5A;
    }
    CHECK(bad[0] == VOR_ERR_ARG && bad[1] == VOR_ERR_ARG && bad[2] == VOR_ERR_ARG &&
              bad[3] == VOR_ERR_ARG && bad[4] == VOR_ERR_ARG && bad[5] == VOR_ERR_ARG &&
              bad[6] == VOR_ERR_ARG && bad[7] == VOR_ERR_ARG && bad[8] == VOR_ERR_ARG &&
              bad[9] == VOR_ERR_ARG && bad[10] == VOR_ERR_ARG && bad[11] == VOR_ERR_POLYGON &&
              bad[12] == VOR_ERR_BUFFER && bad[13] == VOR_ERR_ARG && untouched &&
              vor_clip_error(&clip) == VOR_ERR_ARG,
          "order begin errors: %d %d %d %d %d %d %d %d %d %d %d %d %d %d", bad[0], bad[1], bad[2],
          bad[3], bad[4], bad[5], bad[6], bad[7], bad[8], bad[9], bad[10], bad[11], bad[12],
          bad[13]);
    /* the size reported is the size needed, at any alignment */
    CHECK(needed > 100u && needed <= VOR_ORDER_SCRATCH_BYTES(L->m, 4, 2) &&
              vor_order_cell_begin(&clip, &d, good, 2, L->v, L->m, sc, needed - 1u) ==
                  VOR_ERR_BUFFER &&
              clip.needed == needed &&
              vor_order_cell_begin(&clip, &d, good, 2, L->v, L->m, sc + 1, needed) == VOR_OK &&
              clip.needed == 0u &&
              vor_order_cell_begin(&clip, &d, good, 2, L->v, L->m, sc + 3, needed) == VOR_OK,
          "order scratch: needed %u", (unsigned)needed);
    /* more edges than a room may have; no scratch at all */
    CHECK(vor_order_cell_begin(&clip, &d, good, 2, L->v, VOR_CLIP_MAX_ROOM + 1u, sc, bytes) ==
                  VOR_ERR_ARG &&
              vor_order_cell_begin(&clip, &d, good, 2, L->v, L->m, NULL, 0) == VOR_ERR_BUFFER &&
              clip.needed == needed,
          "order: a room too large, no scratch");
    /* the walk */
    vor_order_iter_t it;
    uint32_t set[2] = {77, 78};
    static uint32_t few_sets[VOR_ORDER_SETS_WORDS(2, 2)];
    int w[9];
    w[0] = vor_order_cells_begin(NULL, &d, 2, L->v, L->m, order_sets, 4, sc, bytes);
    w[1] = vor_order_cells_begin(&it, NULL, 2, L->v, L->m, order_sets, 4, sc, bytes);
    w[2] = vor_order_cells_begin(&it, &d, 0, L->v, L->m, order_sets, 4, sc, bytes);
    w[3] = vor_order_cells_begin(&it, &d, 4, L->v, L->m, order_sets, 4, sc, bytes);
    w[4] = vor_order_cells_begin(&it, &d, 2, NULL, L->m, order_sets, 4, sc, bytes);
    w[5] = vor_order_cells_begin(&it, &d, 2, L->v, L->m, NULL, 4, sc, bytes);
    w[6] = vor_order_cells_begin(&it, &d, 2, L->v, L->m, order_sets, 4, NULL, bytes);
    w[7] = vor_order_cells_begin(&it, &d, 2, bowtie, 4, order_sets, 4, sc, bytes);
    w[8] = vor_order_cells_begin(&it, &d, 2, L->v, L->m, order_sets, 0, sc, bytes);
    CHECK(w[0] == VOR_ERR_ARG && w[1] == VOR_ERR_ARG && w[2] == VOR_ERR_ARG &&
              w[3] == VOR_ERR_ARG && w[4] == VOR_ERR_ARG && w[5] == VOR_ERR_ARG &&
              w[6] == VOR_ERR_ARG && w[7] == VOR_ERR_POLYGON && w[8] == VOR_ERR_BUFFER &&
              vor_order_cells_error(&it) == VOR_ERR_BUFFER &&
              !vor_order_cells_next(&it, set, &clip) && vor_order_cells_error(NULL) == VOR_ERR_ARG &&
              !vor_order_cells_next(NULL, set, &clip) && set[0] == 77u,
          "walk begin errors: %d %d %d %d %d %d %d %d %d", w[0], w[1], w[2], w[3], w[4], w[5],
          w[6], w[7], w[8]);
    uint32_t none_set[2] = {88, 89};
    CHECK(vor_order_cells_begin(&it, &d, VOR_ORDER_MAX + 1u, L->v, L->m, order_sets, 4, sc,
                                bytes) == VOR_ERR_ARG &&
              vor_order_cells_begin(&it, &d, 2, L->v, VOR_CLIP_MAX_ROOM + 1u, order_sets, 4, sc,
                                    bytes) == VOR_ERR_ARG &&
              vor_order_cells_begin(&it, &d, 2, L->v, L->m, NULL, 0, sc, bytes) ==
                  VOR_ERR_BUFFER &&
              vor_order_cells_begin(&it, &d, 2, L->v, L->m, order_sets, 4, NULL, 0) == VOR_OK &&
              !vor_order_cells_next(&it, none_set, &clip) &&
              vor_order_cells_error(&it) == VOR_ERR_BUFFER && it.needed > 0u && none_set[0] == 88u,
          "walk: K too large, a room too large, no store, no scratch");
    /* bad outputs; a store too small; a scratch too small */
    CHECK(vor_order_cells_begin(&it, &d, 2, L->v, L->m, order_sets, 4, sc, bytes) == VOR_OK &&
              !vor_order_cells_next(&it, NULL, &clip) && vor_order_cells_error(&it) == VOR_ERR_ARG &&
              !vor_order_cells_next(&it, set, NULL) && vor_order_cells_error(&it) == VOR_ERR_ARG &&
              set[0] == 77u,
          "walk: bad outputs");
    uint32_t yielded = 0;
    bool began = vor_order_cells_begin(&it, &d, 2, L->v, L->m, few_sets, 1, sc, bytes) == VOR_OK;
    while (began && vor_order_cells_next(&it, set, &clip)) {
        yielded++;
    }
    CHECK(began && vor_order_cells_error(&it) == VOR_ERR_BUFFER && yielded == 0u,
          "walk: a store of one set: %d after %u", vor_order_cells_error(&it), yielded);
    began = vor_order_cells_begin(&it, &d, 2, L->v, L->m, order_sets, 4, sc, 100) == VOR_OK;
    CHECK(began && !vor_order_cells_next(&it, set, &clip) &&
              vor_order_cells_error(&it) == VOR_ERR_BUFFER && it.needed > 100u && set[0] == 77u,
          "walk: a scratch too small: %d, needed %u", vor_order_cells_error(&it),
          (unsigned)it.needed);
}

void test_order(void)
{
    test_rng_t rng;
    TEST_CASE("errors") test_order_errors();
    TEST_CASE("degenerate") test_order_degenerate(test_rng_seed(&rng, 0x0DE20001u));
    TEST_CASE("random") test_order_random(test_rng_seed(&rng, 0x0DE20002u));
}
