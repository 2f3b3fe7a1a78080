/* SPDX-License-Identifier: MIT */
/*
 * geometry.c - the Voronoi diagram's geometry, read from the Delaunay mesh:
 * vertices (circumcentres), edges, the convex hull and cells clipped to a
 * box; and the power diagram's cells, read from the regular triangulation
 * (vor_power.h) by the same code with weighted bisectors. Read-only, like
 * queries.c.
 *
 * The geometry is that of the true Voronoi diagram of the distinct sites,
 * while the mesh is the Delaunay triangulation under the symbolic
 * perturbation. The two differ only where sites are degenerate, and each
 * difference is decided from the mesh with exact predicates:
 *   - cocircular sites: several triangles share one circumcentre, and the
 *     edges between them have length 0 (incircle = 0): skipped;
 *   - collinear sites on the hull: triangles of zero area, whose
 *     circumcentre is at infinity, and edges joining two of those sites
 *     past a third between them, whose Voronoi edge is empty.
 * docs/design/geometry.md has the proofs.
 *
 * Arithmetic (as in Sugihara's textbook: translate to one of the sites
 * first, here so that the widths stay small). Around a site s, coordinates are
 * taken relative to s and doubled, so that every line of a cell has integer
 * coefficients: a line is a x + b y = c, its half-plane a x + b y <= c.
 *   bisector of s and n (e = n - s):  a = e.x, b = e.y, c = |e|^2
 *       |a|, |b| <= 2^32 - 1 (differences of int32), 0 <= c < 2^65
 *   power bisector, weights ws, wn:   c = |e|^2 + ws - wn, |c| < 2^66
 *       (|q - s|^2 - ws <= |q - n|^2 - wn, doubled: e.q' <= c)
 *   box side, e.g. x >= x0:           a = -1, b = 0, c = -2 (x0 - s.x)
 *       |c| < 2^33
 * Two lines meet at (x / w, y / w) with w = a1 b2 - a2 b1 (|w| < 2^65),
 * x = c1 b2 - c2 b1 and y = a1 c2 - a2 c1 (|x|, |y| < 2 2^66 2^32 = 2^99).
 * A point is inside a third line's half-plane when a x + b y - c w <= 0
 * (w > 0): |a x|, |b y| < 2^131, |c w| < 2^131, the sum < 2^133. Every
 * value therefore fits in 160-bit two's complement (GEO_LIMBS), and each
 * decision is the exact sign of a 3x3 determinant of line coefficients.
 */
#include "vor_power.h"

#include "bucket_grid.h"
#include "mesh.h"
#include "multiword.h"
#include "perturbation.h"
#include "predicates.h"
#include "walk.h"

#define GEO_LIMBS VOR__LIMBS(160u)
#define U64_LIMBS VOR__LIMBS(64u)

/* A line a x + b y = c in a site's doubled frame. */
typedef struct vor__line {
    int64_t a;
    int64_t b;
    vor__limb c[GEO_LIMBS];
} geo_line_t;

/* A point (x / w, y / w), w > 0, in the same frame. */
typedef struct geo_point {
    vor__limb x[GEO_LIMBS];
    vor__limb y[GEO_LIMBS];
    vor__limb w[GEO_LIMBS];
} geo_point_t;

/* r = x * k over GEO_LIMBS, exact when the product fits: |k| goes into
 * limbs as a non-negative number, x is two's complement at full width. */
static void mul_i64(vor__limb *r, const vor__limb *x, int64_t k)
{
    uint64_t m = (k < 0) ? 0u - (uint64_t)k : (uint64_t)k;
    vor__limb limbs[U64_LIMBS];
    vor__mw_from_u64(limbs, U64_LIMBS, m);
    vor__mw_mul(r, GEO_LIMBS, x, GEO_LIMBS, limbs, U64_LIMBS);
    if (k < 0) {
        vor__mw_neg(r, GEO_LIMBS);
    }
}

/* r = a * b over GEO_LIMBS for int64 a, b with |a b| < 2^159. */
static void mul_i64_i64(vor__limb *r, int64_t a, int64_t b)
{
    vor__limb t[GEO_LIMBS];
    vor__mw_from_i64(t, GEO_LIMBS, a);
    mul_i64(r, t, b);
}

/* The bisector of s and n, the half-plane of points at least as close to
 * s as to n: 2 e.p <= |e|^2 for p relative to s, e.p' <= |e|^2 doubled. */
static void bisector(geo_line_t *l, const vor_point_t *s, const vor_point_t *n)
{
    int64_t ex = (int64_t)n->x - s->x;
    int64_t ey = (int64_t)n->y - s->y;
    uint32_t mx = vor__mw_magnitude(ex);
    uint32_t my = vor__mw_magnitude(ey);
    vor__limb t[GEO_LIMBS];
    l->a = ex;
    l->b = ey;
    vor__mw_from_u64(l->c, GEO_LIMBS, vor__mul_u32(mx, mx));
    vor__mw_from_u64(t, GEO_LIMBS, vor__mul_u32(my, my));
    vor__mw_add(l->c, t, GEO_LIMBS); /* < 2^65 */
}

/* r = |p - o|^2 (< 2^65). */
static void squared_distance(vor__limb *r, const vor_point_t *o, const vor_point_t *p)
{
    uint32_t mx = vor__mw_magnitude((int64_t)p->x - o->x);
    uint32_t my = vor__mw_magnitude((int64_t)p->y - o->y);
    vor__limb t[GEO_LIMBS];
    vor__mw_from_u64(r, GEO_LIMBS, vor__mul_u32(mx, mx));
    vor__mw_from_u64(t, GEO_LIMBS, vor__mul_u32(my, my));
    vor__mw_add(r, t, GEO_LIMBS);
}

/* The bisector of s and t in the doubled frame of origin o, the
 * half-plane of points at least as close to s as to t: for a point
 * o + q / 2, (t - s).q <= |t - o|^2 - |s - o|^2. |a|, |b| <= 2^32 - 1 and
 * |c| < 2^65, the bounds of the bisectors above; with o = s it is
 * bisector(s, t). */
static void pair_bisector(geo_line_t *l, const vor_point_t *o, const vor_point_t *s,
                          const vor_point_t *t)
{
    vor__limb u[GEO_LIMBS];
    l->a = (int64_t)t->x - s->x;
    l->b = (int64_t)t->y - s->y;
    squared_distance(l->c, o, t);
    squared_distance(u, o, s);
    vor__mw_sub(l->c, u, GEO_LIMBS);
}

/* The power bisector of s and n, weights ws and wn: the half-plane of
 * points whose power distance to s is at most that to n. Equal weights
 * give the bisector; others move it along e by (ws - wn) / 2|e|, so it
 * may hold no integer point. */
static void power_bisector(geo_line_t *l, const vor_point_t *s, const vor_point_t *n, int64_t ws,
                           int64_t wn)
{
    bisector(l, s, n);
    if (ws != wn) {
        vor__limb t[GEO_LIMBS];
        vor__mw_from_i64(t, GEO_LIMBS, ws);
        vor__mw_add(l->c, t, GEO_LIMBS);
        vor__mw_from_i64(t, GEO_LIMBS, wn);
        vor__mw_sub(l->c, t, GEO_LIMBS); /* |c| < 2^65 + 2^64 */
    }
}

/* Box sides in counterclockwise order, each with its outward normal:
 * 0 bottom (0, -1), 1 right (1, 0), 2 top (0, 1), 3 left (-1, 0). */
static void box_side(geo_line_t *l, const vor_box_t *box, const vor_point_t *s, unsigned side)
{
    int64_t distance; /* signed, along the outward normal */
    switch (side) {
    case 0:
        l->a = 0;
        l->b = -1;
        distance = (int64_t)s->y - box->y0;
        break;
    case 1:
        l->a = 1;
        l->b = 0;
        distance = (int64_t)box->x1 - s->x;
        break;
    case 2:
        l->a = 0;
        l->b = 1;
        distance = (int64_t)box->y1 - s->y;
        break;
    default:
        l->a = -1;
        l->b = 0;
        distance = (int64_t)s->x - box->x0;
        break;
    }
    /* doubled frame; a sum, as 2 * distance may become a 64-bit multiply
     * call on Cortex-M0 */
    int64_t c = distance + distance;
    vor__mw_from_i64(l->c, GEO_LIMBS, c); /* |c| < 2^33 */
}

/* Sign of a1 b2 - a2 b1: > 0 when moving along line 1 in its direction
 * (-b1, a1) (counterclockwise around the cell) increases line 2's
 * a x + b y, i.e. line 2 bounds line 1 from above. */
VOR__ALWAYS_INLINE int direction(const geo_line_t *l1, const geo_line_t *l2)
{
    return vor__compare_products(l1->a, l2->b, l2->a, l1->b);
}

/* The point where l1 and l2 meet; false when they are parallel. */
static bool intersect(geo_point_t *p, const geo_line_t *l1, const geo_line_t *l2)
{
    vor__limb t[GEO_LIMBS];
    mul_i64_i64(p->w, l1->a, l2->b);
    mul_i64_i64(t, l2->a, l1->b);
    vor__mw_sub(p->w, t, GEO_LIMBS);
    int sign = vor__mw_sign(p->w, GEO_LIMBS);
    if (sign == 0) {
        return false;
    }
    mul_i64(p->x, l1->c, l2->b);
    mul_i64(t, l2->c, l1->b);
    vor__mw_sub(p->x, t, GEO_LIMBS);
    mul_i64(p->y, l2->c, l1->a);
    mul_i64(t, l1->c, l2->a);
    vor__mw_sub(p->y, t, GEO_LIMBS);
    if (sign < 0) {
        vor__mw_neg(p->x, GEO_LIMBS);
        vor__mw_neg(p->y, GEO_LIMBS);
        vor__mw_neg(p->w, GEO_LIMBS);
    }
    return true;
}

/* Sign of a x + b y - c w: 1 when p is strictly outside l's half-plane,
 * 0 on the line, -1 strictly inside. */
static int side_of(const geo_line_t *l, const geo_point_t *p)
{
    vor__limb sum[GEO_LIMBS];
    vor__limb t[GEO_LIMBS];
    mul_i64(sum, p->x, l->a);
    mul_i64(t, p->y, l->b);
    vor__mw_add(sum, t, GEO_LIMBS);
    vor__mw_mul(t, GEO_LIMBS, l->c, GEO_LIMBS, p->w, GEO_LIMBS);
    vor__mw_sub(sum, t, GEO_LIMBS);
    return vor__mw_sign(sum, GEO_LIMBS);
}

/* side_of for a point of line `on`, taken from its coefficients alone:
 * the foot of the perpendicular from the origin, (a c, b c) / (a^2 + b^2)
 * (|a c|, |b c| < 2^98; 0 < w < 2^65). Only parallel lines need it, so
 * its cost is rare; a power bisector may hold no integer point at all. */
static int side_of_line(const geo_line_t *l, const geo_line_t *on)
{
    geo_point_t p;
    vor__limb t[GEO_LIMBS];
    mul_i64(p.x, on->c, on->a);
    mul_i64(p.y, on->c, on->b);
    mul_i64_i64(p.w, on->a, on->a);
    mul_i64_i64(t, on->b, on->b);
    vor__mw_add(p.w, t, GEO_LIMBS);
    return side_of(l, &p);
}

/* |rest| / step by shift and subtract (no divide instruction anywhere),
 * for step > 0 over n limbs, when the quotient is below 2^bits (bits <=
 * 64): *quotient = floor(|rest| / step), and *negative, *exact say whether
 * rest was negative and the division exact. Returns false, with only
 * *negative set, when the quotient is 2^bits or more. step must have
 * bits + 1 bits of headroom; rest and step are overwritten. */
static bool divide(vor__limb *rest, vor__limb *step, size_t n, unsigned bits,
                   uint64_t *quotient, bool *negative, bool *exact)
{
    bool below_zero = vor__mw_sign(rest, n) < 0;
    *negative = below_zero;
    if (below_zero) {
        vor__mw_neg(rest, n);
    }
    for (unsigned k = 0; k < bits; k++) {
        vor__mw_shl1(step, n);
    }
    if (vor__mw_compare(rest, step, n) >= 0) {
        return false;
    }
    uint64_t q = 0;
    for (unsigned k = 0; k < bits; k++) { /* quotient bits bits-1 .. 0 */
        vor__mw_shr1(step, n);
        q <<= 1;
        if (vor__mw_compare(rest, step, n) >= 0) {
            vor__mw_sub(rest, step, n);
            q |= 1u;
        }
    }
    *quotient = q;
    *exact = vor__mw_sign(rest, n) == 0;
    return true;
}

/* floor(rest / step) for step > 0 when |quotient| < 2^bits (bits < 63);
 * else a value of magnitude 2^bits or more. */
static int64_t floor_quotient(vor__limb *rest, vor__limb *step, size_t n, unsigned bits)
{
    uint64_t quotient;
    bool negative;
    bool exact;
    if (!divide(rest, step, n, bits, &quotient, &negative, &exact)) {
        int64_t saturated = (int64_t)vor__shl_u64(1u, bits);
        return negative ? (-saturated - 1) : saturated;
    }
    /* floor of a negative quotient: -ceil(|n| / d) */
    return negative ? -(int64_t)quotient - (exact ? 0 : 1) : (int64_t)quotient;
}

/* origin + q, saturated to int32; false when it had to be. */
static bool add_saturated(int32_t origin, int64_t q, int32_t *out)
{
    int64_t r = origin + q;
    if (r < INT32_MIN) {
        *out = INT32_MIN;
        return false;
    }
    if (r > INT32_MAX) {
        *out = INT32_MAX;
        return false;
    }
    *out = (int32_t)r;
    return true;
}

/* origin + floor(v / (2 w) + 1/2): the rounded coordinate of v / w in a
 * site's doubled frame, |v| < 2^99, 0 < w < 2^65. Returns false, with the
 * result saturated, when it is outside int32: if it fits in int32 after
 * adding origin, the quotient's magnitude is below 2^33, so 33 steps
 * decide it and a larger one is out of range. */
static bool round_coordinate(const vor__limb *v, const vor__limb *w, int32_t origin,
                             int32_t *out)
{
    vor__limb rest[GEO_LIMBS];
    vor__limb step[GEO_LIMBS];
    /* floor(v / 2w + 1/2) = floor((v + w) / 2w); |v + w| < 2^100 */
    for (size_t i = 0; i < GEO_LIMBS; i++) {
        rest[i] = v[i];
        step[i] = w[i];
    }
    vor__mw_add(rest, w, GEO_LIMBS);
    vor__mw_shl1(step, GEO_LIMBS); /* 2w 2^33 < 2^100 */
    return add_saturated(origin, floor_quotient(rest, step, GEO_LIMBS, 33u), out);
}

/* The rounded vertex of p (in the frame of `origin`). */
static void round_point(const geo_point_t *p, const vor_point_t *origin, vor_vertex_t *out)
{
    bool x_ok = round_coordinate(p->x, p->w, origin->x, &out->point.x);
    bool y_ok = round_coordinate(p->y, p->w, origin->y, &out->point.y);
    out->status = (x_ok && y_ok) ? VOR_VERTEX_IN_RANGE : VOR_VERTEX_OUT_OF_RANGE;
}

/* ------------------------------------------------------------------ */
/* Vertices                                                            */

/* vor_circumcentre of points in place (no copies); out not NULL. */
static void circumcentre(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                         vor_vertex_t *out)
{
    geo_line_t lb;
    geo_line_t lc;
    geo_point_t p;
    bisector(&lb, a, b);
    bisector(&lc, a, c);
    /* the bisectors of a with b and c are parallel exactly when a, b, c
     * are collinear (w = cross(b - a, c - a)) */
    if (!intersect(&p, &lb, &lc)) {
        out->point.x = 0;
        out->point.y = 0;
        out->status = VOR_VERTEX_AT_INFINITY;
        return;
    }
    round_point(&p, a, out);
}

int vor_circumcentre(vor_point_t a, vor_point_t b, vor_point_t c, vor_vertex_t *out)
{
    if (out == NULL) {
        return VOR_ERR_ARG;
    }
    circumcentre(&a, &b, &c, out);
    return VOR_OK;
}

int vor_voronoi_vertex(const vor_t *d, uint32_t a, uint32_t b, uint32_t c, vor_vertex_t *out)
{
    /* a removed site's or a duplicate's coordinates are no site's */
    if ((d == NULL) || (out == NULL) || !vor__site_in_mesh(d, a) || !vor__site_in_mesh(d, b) ||
        !vor__site_in_mesh(d, c)) {
        return VOR_ERR_ARG;
    }
    circumcentre(&d->sites[a], &d->sites[b], &d->sites[c], out);
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* The true Voronoi edge of a Delaunay edge                            */

/*
 * The Delaunay edge p -> q with r the third vertex of the triangle on its
 * right and l of the one on its left (VOR__INFINITE at the hull). Its
 * Voronoi edge runs along the bisector in direction (q - p) turned left,
 * from the circumcentre of (q, p, r) to that of (p, q, l). Returns false
 * when the true edge is empty or a single point; else sets *has_start and
 * *has_end, which say whether those ends are finite vertices.
 *   - r at infinity: nothing bounds the edge on that side.
 *   - r collinear with p, q (a zero-area triangle, on the hull): if r is
 *     between p and q, it is strictly closer than p and q on the whole
 *     bisector, so the edge is empty; otherwise it does not bound it.
 *   - r strictly right: the edge starts at the circumcentre.
 *   - both ends finite: they coincide exactly when p, q, r, l are
 *     cocircular (a zero-length edge of the perturbed mesh).
 * With weights (a power cell's edge, along the power bisector) the same
 * holds, the ends power vertices, but a zero-length edge is kept: the
 * trace writes its one point once.
 */
static bool true_edge(const vor_point_t *s, const int64_t *weights, uint32_t p, uint32_t q,
                      uint32_t r, uint32_t l, bool *has_start, bool *has_end)
{
    *has_start = false;
    *has_end = false;
    if (r != VOR__INFINITE) {
        int o = vor__orient2d_sign(&s[p], &s[q], &s[r]);
        VOR_ASSERT(o <= 0);
        if (o != 0) {
            *has_start = true;
        } else if (vor__strictly_between(&s[p], &s[r], &s[q])) {
            return false;
        } else {
            /* no other case */
        }
    }
    if (l != VOR__INFINITE) {
        int o = vor__orient2d_sign(&s[p], &s[q], &s[l]);
        VOR_ASSERT(o >= 0);
        if (o != 0) {
            *has_end = true;
        } else if (vor__strictly_between(&s[p], &s[l], &s[q])) {
            return false;
        } else {
            /* no other case */
        }
    }
    /* a power diagram's zero-length edges (four lifted sites on one
     * plane) are left to the cell trace, which writes a repeated exact
     * point once: the exact power test here would link the weighted
     * predicates into every firmware that draws Voronoi cells */
    if (*has_start && *has_end && (weights == NULL) &&
        vor__incircle_sign(&s[p], &s[q], &s[l], &s[r]) == 0) {
        return false;
    }
    return true;
}

/* The third vertex of triangle t besides p and q. */
static uint32_t third_vertex(const vor__tri_t *t, uint32_t p, uint32_t q)
{
    vor_index_t v[3];
    vor__vertices(t, v);
    for (unsigned i = 0; i < 2u; i++) {
        if ((v[i] != p) && (v[i] != q)) {
            return v[i];
        }
    }
    return v[2];
}

/* floor(v / 2) for the rounded midpoint (|v| <= 2^32 + 1): v + 2^33 is
 * non-negative and halved by an unsigned shift, as a shift of a negative is
 * implementation-defined and a 64-bit division may become a runtime call
 * (clang -Oz). */
static int32_t floor_half(int64_t v)
{
    uint64_t biased = (uint64_t)v + ((uint64_t)1 << 33);
    return (int32_t)((int64_t)(biased >> 1) - 4294967296 /* 2^32 */);
}

static void fill_edge(const vor_t *d, vor_edge_t *e, uint32_t p, uint32_t q, uint32_t r,
                      uint32_t l, bool has_start, bool has_end)
{
    const vor_point_t *s = d->sites;
    if (!has_start && has_end) { /* a ray starts at its vertex: turn it round */
        uint32_t t = p;
        p = q;
        q = t;
        r = l;
        has_start = true;
        has_end = false;
    }
    e->sites[0] = p;
    e->sites[1] = q;
    e->dx = -((int64_t)s[q].y - s[p].y);
    e->dy = (int64_t)s[q].x - s[p].x;
    e->to.point.x = 0;
    e->to.point.y = 0;
    e->to.status = VOR_VERTEX_AT_INFINITY;
    if (has_start) {
        circumcentre(&s[p], &s[q], &s[r], &e->from);
        if (has_end) {
            circumcentre(&s[p], &s[q], &s[l], &e->to);
        }
        e->kind = has_end ? VOR_EDGE_SEGMENT : VOR_EDGE_RAY;
    } else {
        e->kind = VOR_EDGE_LINE;
        e->from.point.x = floor_half((int64_t)s[p].x + s[q].x + 1);
        e->from.point.y = floor_half((int64_t)s[p].y + s[q].y + 1);
        e->from.status = VOR_VERTEX_IN_RANGE;
    }
}

/* vor__next_used_slot, out of line: two copies in the edge iterator would
 * cost more flash than the calls cost time. */
static VOR__NOINLINE uint32_t next_used_slot(const vor_t *d, uint32_t slot)
{
    return vor__next_used_slot(d, slot);
}

int vor_edges_begin(vor_edge_iter_t *it, const vor_t *d)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    it->d = d; /* NULL: closed */
    it->slot = 0;
    it->edge = 0;
    return (d != NULL) ? VOR_OK : VOR_ERR_ARG;
}

int vor_edges_next(vor_edge_iter_t *it, vor_edge_t *edge)
{
    /* a zeroed iterator, or one begun on no diagram, is at its end */
    if ((it == NULL) || (it->d == NULL) || (edge == NULL)) {
        return 0;
    }
    const vor_t *d = it->d;
    if (d->vertex_count < 2u) {
        return 0;
    }
    uint32_t end = vor__used_slots_end(d);
    /* each used slot once, each of its three edges once: ends at `end` */
    for (uint32_t slot = next_used_slot(d, it->slot); slot < end;
         slot = next_used_slot(d, slot + 1u)) {
        const vor__tri_t *t = &d->triangles[slot];
        vor_index_t v[3];
        vor__vertices(t, v);
        unsigned first = (slot == it->slot) ? it->edge : 0u;
        for (unsigned i = first; i < 3u; i++) {
            uint32_t p = v[vor__next(i)];
            uint32_t q = v[vor__prev(i)];
            uint32_t l = v[i];
            if (p == VOR__INFINITE || (q == VOR__INFINITE)) {
                continue;
            }
            uint32_t other = t->n[i];
            uint32_t r = third_vertex(&d->triangles[other], p, q);
            /* each edge once: from its finite side, or the smaller slot */
            bool ghost_here = l == VOR__INFINITE;
            bool ghost_there = r == VOR__INFINITE;
            if ((ghost_here != ghost_there) ? ghost_here : (other < slot)) {
                continue;
            }
            bool has_start;
            bool has_end;
            if (!true_edge(d->sites, NULL, p, q, r, l, &has_start, &has_end)) {
                continue;
            }
            fill_edge(d, edge, p, q, r, l, has_start, has_end);
            it->slot = slot;
            it->edge = i + 1u;
            return 1;
        }
    }
    it->slot = end;
    it->edge = 0;
    return 0;
}

/* ------------------------------------------------------------------ */
/* Convex hull                                                         */

/* The triangle at infinity in `slot` is (u, w, infinity) in counterclockwise
 * order, so the outside is left of u -> w and the hull runs w -> u
 * counterclockwise. The next hull edge's triangle (x, u, infinity) shares
 * the edge (u, infinity), opposite w. */
static void ghost_edge(const vor_t *d, uint32_t slot, uint32_t *w, uint32_t *u, uint32_t *next)
{
    const vor__tri_t *g = &d->triangles[slot];
    unsigned k = vor__vertex_index(g, VOR__INFINITE);
    *u = vor__vertex(g, vor__next(k));
    *w = vor__vertex(g, vor__prev(k));
    *next = g->n[vor__prev(k)];
}

/* The site with the smallest (y, x), by the walk (walk.h). A site that is
 * not the lowest has a lower neighbour in a triangulation: the direction
 * to the lowest site lies in one of its triangles. The walk starts at the
 * bucket grid's bottom row, below the middle of the box, a few steps from
 * the lowest site for uniform sites. */
static uint32_t lowest_site(const vor_t *d)
{
    uint32_t half_width = ((uint32_t)d->high.x - (uint32_t)d->low.x) >> 1;
    uint32_t middle_bits = (uint32_t)d->low.x + half_width;
    int32_t middle = (int32_t)middle_bits;
    vor__walk_t w;
    vor__walk_begin(&w, d, VOR__WALK_LOWEST);
    return vor__walk(&w, vor__grid_start(d, middle, d->low.y));
}

int vor_hull_begin(vor_hull_iter_t *it, const vor_t *d)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    it->d = d;
    it->left = 0;
    it->ghost = VOR__NONE;
    it->collinear = 0;
    it->site = 0;
    it->first = 0;
    if (d == NULL) {
        return VOR_ERR_ARG; /* left = 0: closed */
    }
    it->first = d->last_site;
    it->site = it->first;
    if (d->vertex_count < 2u) {
        it->left = d->vertex_count; /* one site: itself */
        return VOR_OK;
    }
    const vor_point_t *s = d->sites;
    uint32_t low = lowest_site(d);
    /* its hull edge low -> u: the triangle (u, low, infinity) of its fan,
     * found turning around it (fan size <= vertex_count) */
    uint32_t slot = low;
    for (uint32_t step = 0; step <= d->vertex_count; step++) {
        const vor__tri_t *t = &d->triangles[slot];
        unsigned i = vor__vertex_index(t, (vor_index_t)low);
        if (i == 3u) {
            return VOR_OK; /* only on a broken mesh */
        }
        if (vor__vertex(t, vor__next(i)) == VOR__INFINITE) {
            it->ghost = slot;
            break;
        }
        slot = t->n[vor__next(i)];
    }
    if (it->ghost == VOR__NONE) {
        return VOR_OK;
    }
    /* all sites are collinear exactly when the hull's corners are: one
     * turn around the hull (at most vertex_count edges) */
    uint32_t w;
    uint32_t u;
    uint32_t next;
    uint32_t g = it->ghost;
    ghost_edge(d, g, &w, &u, &next);
    uint32_t second = u;
    it->collinear = 1;
    for (uint32_t step = 0; (step < d->vertex_count) && it->collinear; step++) {
        ghost_edge(d, next, &w, &u, &next);
        if (vor__orient2d_sign(&s[low], &s[second], &s[u]) != 0) {
            it->collinear = 0;
        }
        if (next == g) {
            break;
        }
    }
    it->first = low;
    it->site = it->first;
    /* collinear: every site once, up the line; else back to the start */
    it->left = it->collinear ? d->vertex_count : (d->vertex_count + 1u);
    return VOR_OK;
}

int vor_hull_next(vor_hull_iter_t *it, uint32_t *site)
{
    /* a zeroed iterator, or one begun on no diagram, is at its end */
    if ((it == NULL) || (it->d == NULL) || (site == NULL)) {
        return 0;
    }
    const vor_t *d = it->d;
    if (it->left == 0u) {
        return 0;
    }
    *site = it->site;
    it->left--;
    if (it->ghost == VOR__NONE) {
        it->left = 0;
        return 1;
    }
    /* advance: along the hull edge w -> u, the next site between site and u
     * on the segment (a Delaunay neighbour: consecutive sites on a hull
     * edge have a Voronoi ray in common), else u and the next hull edge.
     * The neighbours are the true diagram's, so at most one lies strictly
     * inside the segment: of two, the nearer is strictly closer than site
     * and the farther on their whole bisector, which cuts them apart. */
    const vor_point_t *s = d->sites;
    uint32_t w;
    uint32_t u;
    uint32_t next;
    uint32_t n;
    uint32_t best = VOR__NONE;
    ghost_edge(d, it->ghost, &w, &u, &next);
    vor_neighbour_iter_t ni;
    (void)vor_neighbours_begin(&ni, d, it->site); /* a hull site: in the mesh */
    while (vor_neighbours_next(&ni, &n) != 0) {
        if ((n != u) && vor__orient2d_sign(&s[it->site], &s[u], &s[n]) == 0 &&
            vor__strictly_between(&s[it->site], &s[n], &s[u])) {
            best = n;
        }
    }
    if (best != VOR__NONE) {
        it->site = best;
    } else {
        it->site = u;
        it->ghost = next;
    }
    if (!it->collinear && (it->site == it->first)) {
        it->left = 0;
    }
    return 1;
}

/* ------------------------------------------------------------------ */
/* Cells                                                               */

/* Lines of a cell are named by a site id or a box side (BOX_LINE + k). */
#define BOX_LINE 0xFFFFFFF0u
#define NO_LINE 0xFFFFFFFFu

typedef struct cell {
    const vor_t *d;
    const int64_t *weights; /* a power diagram's, else NULL */
    uint32_t site;
    const vor_point_t *s; /* the site's point: the frame's origin */
    const vor_box_t *box;
    uint32_t start_slot; /* the fan triangle where the edges' angles begin */
    uint32_t degree;     /* Delaunay neighbours */
    /* each box side's part in the cell */
    uint32_t side_lo[4];
    uint32_t side_hi[4];
    bool side_empty[4];
} cell_t;

/* The half-plane of the cell's site against neighbour n. */
static void cell_bisector(const cell_t *c, uint32_t n, geo_line_t *l)
{
    if (c->weights == NULL) {
        bisector(l, c->s, &c->d->sites[n]);
    } else {
        power_bisector(l, c->s, &c->d->sites[n], c->weights[c->site], c->weights[n]);
    }
}

static void make_line(const cell_t *c, uint32_t name, geo_line_t *l)
{
    if (name >= BOX_LINE) {
        box_side(l, c->box, c->s, name - BOX_LINE);
    } else {
        cell_bisector(c, name, l);
    }
}

/* Angle classes of an outward normal e = n - s, counterclockwise from
 * (0, -1), the bottom side's normal: quadrant k begins at box side k's
 * normal. */
static unsigned quadrant(int64_t x, int64_t y)
{
    if ((x >= 0) && (y < 0)) {
        return 0;
    }
    if ((x > 0) && (y >= 0)) {
        return 1;
    }
    if ((x <= 0) && (y > 0)) {
        return 2;
    }
    return 3;
}

static unsigned quadrant_of(const cell_t *c, uint32_t n)
{
    const vor_point_t *p = &c->d->sites[n];
    return quadrant((int64_t)p->x - c->s->x, (int64_t)p->y - c->s->y);
}

/* Is the direction to neighbour a strictly before that to b, in angle
 * from (0, -1) counterclockwise? */
static bool angle_before(const cell_t *c, uint32_t a, uint32_t b)
{
    unsigned qa = quadrant_of(c, a);
    unsigned qb = quadrant_of(c, b);
    if (qa != qb) {
        return qa < qb;
    }
    /* within a quadrant (less than a half turn): b turns left of a */
    return vor__orient2d_sign(c->s, &c->d->sites[a], &c->d->sites[b]) > 0;
}

/* A step around the fan of c->site counterclockwise: the triangle at
 * `slot` is (site, x, y); the edge (site, y) comes next, with x on its
 * right and the next triangle's third vertex on its left. */
static void fan_triangle(const cell_t *c, uint32_t slot, uint32_t *x, uint32_t *y, uint32_t *next)
{
    const vor__tri_t *t = &c->d->triangles[slot];
    unsigned i = vor__vertex_index(t, (vor_index_t)c->site);
    VOR_ASSERT(i != 3u);
    *x = vor__vertex(t, vor__next(i));
    *y = vor__vertex(t, vor__prev(i));
    *next = t->n[vor__next(i)]; /* across (site, y) */
}

/* The fan's size, and where the angles of the edge normals wrap around:
 * around a site the neighbours come in counterclockwise order, so their
 * angles from (0, -1) rise except at one step (unless all are equal).
 * The walk from there meets the edges in the order of the box sides'
 * normals too. The fan closes within vertex_count steps on a valid mesh. */
VOR__NOINLINE static void find_start(cell_t *c)
{
    const vor_t *d = c->d;
    uint32_t slot = c->site;
    uint32_t x;
    uint32_t y;
    uint32_t next;
    uint32_t first = VOR__NONE;
    uint32_t first_slot = slot;
    uint32_t previous = VOR__NONE;
    c->start_slot = slot;
    c->degree = 0;
    bool found = false;
    for (uint32_t step = 0; step <= d->vertex_count; step++) {
        fan_triangle(c, slot, &x, &y, &next);
        if (y != VOR__INFINITE) {
            c->degree++;
            if (first == VOR__NONE) {
                first = y;
                first_slot = slot;
            } else if (!found && angle_before(c, y, previous)) {
                c->start_slot = slot;
                found = true;
            } else {
                /* no other case */
            }
            previous = y;
        }
        slot = next;
        if (slot == c->site) {
            break;
        }
    }
    if (!found) { /* the wrap is at the first neighbour, or nowhere */
        c->start_slot = first_slot;
    }
}

/* The part of box side k inside the cell: clipped by the half-plane of
 * every Delaunay neighbour (the cell is their intersection; neighbours of
 * the perturbed mesh that are no true neighbours add true, redundant
 * constraints). Along the side in its direction, a constraint bounds from
 * below or above (direction()), or is parallel. */
VOR__NOINLINE static void clip_side(cell_t *c, unsigned k)
{
    const vor_t *d = c->d;
    geo_line_t side;
    geo_line_t line;
    geo_point_t lo;
    geo_point_t hi;
    box_side(&side, c->box, c->s, k);
    c->side_lo[k] = BOX_LINE + ((k + 3u) & 3u);
    c->side_hi[k] = BOX_LINE + ((k + 1u) & 3u);
    c->side_empty[k] = false;
    make_line(c, c->side_lo[k], &line);
    (void)intersect(&lo, &side, &line);
    make_line(c, c->side_hi[k], &line);
    (void)intersect(&hi, &side, &line);
    if (d->vertex_count >= 2u) {
        uint32_t slot = c->site;
        uint32_t x;
        uint32_t y;
        uint32_t next;
        for (uint32_t step = 0; step <= d->vertex_count; step++) {
            fan_triangle(c, slot, &x, &y, &next);
            if (y != VOR__INFINITE) {
                cell_bisector(c, y, &line);
                int g = direction(&side, &line);
                if (g == 0) {
                    if (side_of_line(&line, &side) > 0) {
                        c->side_empty[k] = true;
                        return;
                    }
                } else if (g > 0) {
                    if (side_of(&line, &hi) > 0) {
                        c->side_hi[k] = y;
                        (void)intersect(&hi, &side, &line);
                    }
                } else if (side_of(&line, &lo) > 0) {
                    c->side_lo[k] = y;
                    (void)intersect(&lo, &side, &line);
                } else {
                    /* no other case */
                }
            }
            slot = next;
            if (slot == c->site) {
                break;
            }
        }
    }
    make_line(c, c->side_hi[k], &line);
    c->side_empty[k] = side_of(&line, &lo) > 0;
}

/* The output: distinct exact points in order, each compared with the
 * previous one (and the last with the first), rounded when confirmed. The
 * first two are held back so that a result of fewer than three (no area)
 * writes nothing. Three point buffers rotate, so nothing is copied. */
typedef struct centroid_sum centroid_sum_t;

typedef struct emitter {
    const cell_t *c;
    vor_point_t *out;     /* NULL: only count */
    centroid_sum_t *sum;  /* not NULL: vertices go to the centroid's sums */
    uint32_t count;
    vor_point_t held[2];
    geo_point_t pool[3];
    uint32_t names[3][2]; /* the two lines through each pooled point */
    /* pool indices, -1 while empty */
    int first;
    int last;
} emitter_t;

static bool same_point(const emitter_t *e, int a, const geo_point_t *p)
{
    geo_line_t l;
    make_line(e->c, e->names[a][0], &l);
    if (side_of(&l, p) != 0) {
        return false;
    }
    make_line(e->c, e->names[a][1], &l);
    return side_of(&l, p) == 0;
}

static void hold_vertex(centroid_sum_t *sum, const geo_point_t *p);

static void confirm(emitter_t *e, int index)
{
    if (e->sum != NULL) {
        hold_vertex(e->sum, &e->pool[index]);
        e->count++;
        return;
    }
    vor_vertex_t v;
    round_point(&e->pool[index], e->c->s, &v);
    VOR_ASSERT(v.status == VOR_VERTEX_IN_RANGE); /* inside the box */
    if (e->out != NULL) {
        if (e->count < 2u) {
            e->held[e->count].x = v.point.x;
            e->held[e->count].y = v.point.y;
        } else {
            if (e->count == 2u) {
                for (unsigned i = 0; i < 2u; i++) {
                    e->out[i].x = e->held[i].x;
                    e->out[i].y = e->held[i].y;
                }
            }
            e->out[e->count].x = v.point.x;
            e->out[e->count].y = v.point.y;
        }
    }
    e->count++;
}

/* The pool slot a new point may be computed into. */
static int scratch(const emitter_t *e)
{
    int i = 0;
    while ((i == e->first) || (i == e->last)) {
        i++;
    }
    return i;
}

/* The new point in pool[scratch(e)], on lines a and b. */
static void emit(emitter_t *e, uint32_t a, uint32_t b)
{
    int i = scratch(e);
    e->names[i][0] = a;
    e->names[i][1] = b;
    if ((e->last >= 0) && same_point(e, e->last, &e->pool[i])) {
        return;
    }
    if (e->first < 0) {
        e->last = i;
        e->first = e->last;
        return;
    }
    confirm(e, e->last);
    e->last = i;
}

VOR__NOINLINE static void emit_side(emitter_t *e, unsigned k)
{
    const cell_t *c = e->c;
    if (c->side_empty[k]) {
        return;
    }
    geo_line_t side;
    geo_line_t line;
    box_side(&side, c->box, c->s, k);
    make_line(c, c->side_lo[k], &line);
    (void)intersect(&e->pool[scratch(e)], &side, &line);
    emit(e, BOX_LINE + k, c->side_lo[k]);
}

/* The Voronoi edge with neighbour n (r: its start's third site, l: its
 * end's, NO_LINE for an unbounded end) clipped to the box; emits its
 * start if anything is left. */
VOR__NOINLINE static void emit_edge(emitter_t *e, uint32_t n, uint32_t r, uint32_t l)
{
    const cell_t *c = e->c;
    geo_line_t edge;
    geo_line_t line;
    geo_point_t hi;
    geo_point_t *lo = &e->pool[scratch(e)];
    uint32_t lo_name = NO_LINE;
    uint32_t hi_name = NO_LINE;
    uint32_t bounds[6] = {r, l, BOX_LINE, BOX_LINE + 1u, BOX_LINE + 2u, BOX_LINE + 3u};
    cell_bisector(c, n, &edge);
    for (unsigned k = 0; k < 6u; k++) {
        if (bounds[k] == NO_LINE) {
            continue;
        }
        make_line(c, bounds[k], &line);
        int g = direction(&edge, &line);
        if (g == 0) {
            if (side_of_line(&line, &edge) > 0) {
                return;
            }
        } else if (g > 0) {
            if ((hi_name == NO_LINE) || side_of(&line, &hi) > 0) {
                hi_name = bounds[k];
                (void)intersect(&hi, &edge, &line);
            }
        } else if ((lo_name == NO_LINE) || side_of(&line, lo) > 0) {
            lo_name = bounds[k];
            (void)intersect(lo, &edge, &line);
        } else {
            /* no other case */
        }
    }
    /* two opposite box sides are never both parallel to a line */
    VOR_ASSERT(lo_name != NO_LINE && hi_name != NO_LINE);
    if ((lo_name == NO_LINE) || (hi_name == NO_LINE)) {
        return;
    }
    make_line(c, hi_name, &line);
    if (side_of(&line, lo) > 0) {
        return; /* starts after it ends: outside the box */
    }
    emit(e, n, lo_name);
}

static void add_held_vertex(centroid_sum_t *sum);

/* One pass over the cell's boundary: the pieces of box sides and Voronoi
 * edges in the angular order of their outward normals, from (0, -1). That
 * is the order of a convex polygon's edges, and the first one's start is
 * the lowest vertex. Returns the number of vertices. A confirmed vertex
 * for the centroid is added here, not in confirm(): the sums' deep frames
 * then add to the trace's, not to the emitter's. */
static uint32_t trace(const cell_t *c, vor_point_t *out, centroid_sum_t *sum)
{
    const vor_t *d = c->d;
    emitter_t e;
    e.c = c;
    e.out = out;
    e.sum = sum;
    e.count = 0;
    e.first = -1;
    e.last = -1;
    unsigned next_side = 0;
    if (d->vertex_count >= 2u) {
        uint32_t slot = c->start_slot;
        uint32_t x;
        uint32_t y;
        uint32_t next;
        uint32_t z;
        uint32_t dummy;
        for (uint32_t step = 0; step <= d->vertex_count; step++) {
            fan_triangle(c, slot, &x, &y, &next);
            if (y != VOR__INFINITE) {
                fan_triangle(c, next, &dummy, &z, &dummy);
                for (unsigned q = quadrant_of(c, y); next_side <= q; next_side++) {
                    emit_side(&e, next_side);
                    add_held_vertex(sum);
                }
                bool has_start;
                bool has_end;
                if (true_edge(d->sites, c->weights, c->site, y, x, z, &has_start, &has_end)) {
                    emit_edge(&e, y, has_start ? x : NO_LINE, has_end ? z : NO_LINE);
                    add_held_vertex(sum);
                }
            }
            slot = next;
            if (slot == c->start_slot) {
                break;
            }
        }
    }
    for (; next_side < 4u; next_side++) {
        emit_side(&e, next_side);
        add_held_vertex(sum);
    }
    if ((e.last >= 0) && (e.last != e.first) && !same_point(&e, e.first, &e.pool[e.last])) {
        confirm(&e, e.last);
        add_held_vertex(sum);
    }
    return (e.count >= 3u) ? e.count : 0u;
}

static void begin_cell(cell_t *c, const vor_t *d, const int64_t *weights, uint32_t site,
                       const vor_box_t *box)
{
    c->d = d;
    c->weights = weights;
    c->site = site;
    c->s = &d->sites[site];
    c->box = box;
    c->start_slot = site;
    c->degree = 0;
    if (d->vertex_count >= 2u) {
        find_start(c);
    }
    for (unsigned k = 0; k < 4u; k++) {
        clip_side(c, k);
    }
}

/* The arguments every cell call checks the same way. */
static bool bad_box(const vor_box_t *box)
{
    return (box == NULL) || (box->x0 > box->x1) || (box->y0 > box->y1);
}

/* vor_cell of a site of the mesh (weights: a power diagram's, or NULL),
 * the arguments checked. */
static int cell_vertices(const vor_t *d, const int64_t *weights, uint32_t site,
                         const vor_box_t *box, vor_point_t *vertices, uint32_t capacity,
                         uint32_t *count)
{
    if ((box->x0 == box->x1) || (box->y0 == box->y1)) {
        *count = 0;
        return VOR_OK;
    }
    cell_t c;
    begin_cell(&c, d, weights, site, box);
    /* at most one vertex per neighbour and per box side: write at once
     * when that fits, else count first */
    if (capacity < (c.degree + 4u)) {
        uint32_t needed = trace(&c, NULL, NULL);
        if (needed > capacity) {
            *count = needed;
            return VOR_ERR_BUFFER;
        }
    }
    *count = trace(&c, vertices, NULL);
    return VOR_OK;
}

int vor_cell(const vor_t *d, uint32_t site, const vor_box_t *box, vor_point_t *vertices,
             uint32_t capacity, uint32_t *count)
{
    if ((d == NULL) || bad_box(box) || (count == NULL) || ((vertices == NULL) && (capacity > 0u)) ||
        !vor__site_in_mesh(d, site)) {
        return VOR_ERR_ARG;
    }
    return cell_vertices(d, NULL, site, box, vertices, capacity, count);
}

int vor_power_cell(const vor_power_t *pd, uint32_t site, const vor_box_t *box,
                   vor_point_t *vertices, uint32_t capacity, uint32_t *count)
{
    if ((pd == NULL) || bad_box(box) || (count == NULL) || ((vertices == NULL) && (capacity > 0u))) {
        return VOR_ERR_ARG;
    }
    int hidden = vor_power_hidden(pd, site);
    if (hidden < 0) {
        return hidden;
    }
    if (hidden != 0) { /* an empty cell */
        *count = 0;
        return VOR_OK;
    }
    return cell_vertices(&pd->mesh, pd->weights, site, box, vertices, capacity, count);
}

int vor_cells_begin(vor_cell_iter_t *it, const vor_t *d, const vor_box_t *box)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    it->next_site = 0;
    it->error = VOR_OK;
    it->box.x0 = 0;
    it->box.y0 = 0;
    it->box.x1 = 0;
    it->box.y1 = 0;
    if ((d == NULL) || bad_box(box)) {
        it->d = NULL; /* closed */
        it->error = VOR_ERR_ARG;
        return VOR_ERR_ARG;
    }
    it->d = d;
    it->box.x0 = box->x0;
    it->box.y0 = box->y0;
    it->box.x1 = box->x1;
    it->box.y1 = box->y1;
    return VOR_OK;
}

int vor_cells_next(vor_cell_iter_t *it, uint32_t *site, vor_point_t *vertices, uint32_t capacity,
                   uint32_t *count)
{
    if ((it == NULL) || (it->d == NULL)) {
        return 0; /* a zeroed iterator, or a closed one */
    }
    const vor_t *d = it->d;
    if ((site == NULL) || (count == NULL) || ((vertices == NULL) && (capacity > 0u))) {
        it->error = VOR_ERR_ARG;
        return 0;
    }
    while ((it->next_site < d->site_count) && !vor__site_in_mesh(d, it->next_site)) {
        it->next_site++;
    }
    if (it->next_site >= d->site_count) {
        it->error = VOR_OK;
        return 0;
    }
    *site = it->next_site;
    /* the box was checked by begin, and the site is in the mesh: only
     * VOR_ERR_BUFFER can come back, and the iterator stays on the cell */
    it->error = vor_cell(d, it->next_site, &it->box, vertices, capacity, count);
    if (it->error != VOR_OK) {
        return 0;
    }
    it->next_site++;
    return 1;
}

int vor_cells_error(const vor_cell_iter_t *it)
{
    return (it != NULL) ? it->error : VOR_ERR_ARG;
}

/* ------------------------------------------------------------------ */
/* Area and centroid of a clipped cell                                 */

/*
 * The cell's exact vertices v_i = (x_i, y_i) / w_i in the site's doubled
 * frame (0 < w_i < 2^65, |x_i|, |y_i| < 2^99, power cells included), with
 * v_k = v_0, give by the shoelace formula
 *   twice the area  A = sum c_i / (w_i w_{i+1}),
 *   the moments     M = sum (v_i + v_{i+1}) c_i / (w_i w_{i+1}),
 * c_i = x_i y_{i+1} - x_{i+1} y_i, and the centroid M / 3A. Each term is
 * a fraction T_i / (w_i w_{i+1})^2: for A, T = c w_i w_{i+1} (|c| < 2^199,
 * so |T| < 2^329); for M.x, T = c (x_i w_{i+1} + x_{i+1} w_i) (< 2^364);
 * M.y alike. TERM_LIMBS (384 bits) holds them.
 *
 * The sums are kept over the common denominator Q_k = prod_{m=0..k} w_m^2
 * (w_0 twice: the last term closes the polygon): term i is added by
 * N <- N w_{i+1}^2 + T_i Q_{i-1}, so only Q_{i-1} and Q_i are kept. No
 * reduction is needed as the result is rounded from N_M / N_A, where Q
 * cancels. Widths: Q_j < 2^(130 (j + 1)). Every vertex is in the box, so
 * its coordinates in the doubled frame are below 2^33 in magnitude, each
 * term's value below 2^101, and a partial sum of j < 2^32 terms below
 * 2^133: |N| < Q_j 2^133. sum_limbs(j), 130 j + 288 bits, holds every
 * number of step j, with room for the final divisions (6 N_A 2^34 and
 * 8 Q 2^64 are below Q 2^105). The arithmetic runs at the width the
 * values fill (at most that bound), so the cost is O(k^2) limb products
 * for k vertices, less for narrow denominators.
 */
#define TERM_LIMBS VOR__LIMBS(384u)
#define SUM_NUMBERS 6u /* N_A, N_X, N_Y, Q_{i-1}, Q_i and a spare */

struct centroid_sum {
    vor__limb *area;
    vor__limb *x;
    vor__limb *y;          /* N_A, N_X, N_Y over the denominator */
    vor__limb *before;
    vor__limb *denominator;  /* Q_{i-1}, Q_i */
    vor__limb *spare;
    size_t width;                     /* live limbs of every number */
    uint32_t vertices;
    bool held;                        /* a confirmed vertex waits in `next` */
    geo_point_t first;
    geo_point_t previous;
    geo_point_t next;
};

/* Limbs of step j's numbers, for j <= MAX_SUM_VERTICES (130 j < 2^32). */
#define MAX_SUM_VERTICES ((uint32_t)1 << 24)
static size_t sum_limbs(uint32_t j)
{
    return (((size_t)j * 130u) + 288u + VOR__LIMB_WIDTH - 1u) / VOR__LIMB_WIDTH;
}

/* k <= MAX_SUM_VERTICES for every cell: both counts scratch_fits is
 * given (the neighbours met plus 4, and trace's vertices, at most one per
 * box side, one per fan step and the closing one) are at most
 * vertex_count + 5, and vertex_count <= max_sites <= VOR_MAX_SITES. */
typedef char vor__sum_vertices_check[((VOR_MAX_SITES + 5u) <= MAX_SUM_VERTICES) ? 1 : -1];

/* Does scratch of `bytes` hold the sums of a cell of k vertices? Then
 * *stride = the limbs of each number. */
static bool scratch_fits(size_t bytes, uint32_t k, size_t *stride)
{
    VOR_ASSERT(k <= MAX_SUM_VERTICES);
    size_t limbs = sum_limbs(k);
    if (limbs * SUM_NUMBERS * sizeof(vor__limb) > bytes) {
        return false;
    }
    *stride = limbs;
    return true;
}

/* r[from .. to) = the sign of r[0 .. from): two's complement widened. */
static void widen(vor__limb *r, size_t from, size_t to)
{
    vor__limb fill = (vor__mw_sign(r, from) < 0) ? (vor__limb)~(vor__limb)0 : 0u;
    for (size_t i = from; i < to; i++) {
        r[i] = fill;
    }
}

/* Every number of the sums at `width` limbs, where they all fit. */
static void widen_sums(centroid_sum_t *sum, size_t width)
{
    vor__limb *numbers[5] = {sum->area, sum->x, sum->y, sum->before, sum->denominator};
    for (unsigned i = 0; i < 5u; i++) {
        widen(numbers[i], sum->width, width);
    }
    sum->width = width;
}

/* r = a b over TERM_LIMBS for two's complement a (na limbs) and b (nb
 * limbs), at most FACTOR_LIMBS each, through their magnitudes: the
 * toolkit's product is exact for operands narrower than the result only
 * when they are non-negative. */
#define FACTOR_LIMBS VOR__LIMBS(224u) /* |c| < 2^199, the widest factor */
static void term_product(vor__limb *r, const vor__limb *a, size_t na, const vor__limb *b,
                         size_t nb)
{
    vor__limb ma[FACTOR_LIMBS];
    vor__limb mb[FACTOR_LIMBS];
    bool a_negative = vor__mw_sign(a, na) < 0;
    bool b_negative = vor__mw_sign(b, nb) < 0;
    for (size_t i = 0; i < na; i++) {
        ma[i] = a[i];
    }
    for (size_t i = 0; i < nb; i++) {
        mb[i] = b[i];
    }
    if (a_negative) {
        vor__mw_neg(ma, na);
    }
    if (b_negative) {
        vor__mw_neg(mb, nb);
    }
    vor__mw_mul(r, TERM_LIMBS, ma, na, mb, nb);
    if (a_negative != b_negative) {
        vor__mw_neg(r, TERM_LIMBS);
    }
}

/* The fewest limbs that hold a (n limbs, two's complement) with its sign. */
static size_t significant(const vor__limb *a, size_t n)
{
    vor__limb fill = (vor__mw_sign(a, n) < 0) ? (vor__limb)~(vor__limb)0 : 0u;
    size_t m = n;
    while ((m > 1u) && (a[m - 1u] == fill) && (a[m - 2u] >> (VOR__LIMB_WIDTH - 1u)) == (fill & 1u)) {
        m--;
    }
    return m;
}

/* n = n w^2 + t before, at the sum's width; t is signed, before >= 0 and
 * fills before_limbs, w^2 square_limbs. The non-negative factors are
 * passed at their own widths, so the products cost what the numbers
 * hold, not what the bound allows. */
static void accumulate(centroid_sum_t *sum, vor__limb *n, const vor__limb *t,
                       const vor__limb *square, size_t square_limbs, size_t before_limbs)
{
    size_t width = sum->width;
    vor__limb magnitude[TERM_LIMBS];
    vor__mw_mul(sum->spare, width, n, width, square, square_limbs);
    bool negative = vor__mw_sign(t, TERM_LIMBS) < 0;
    for (size_t i = 0; i < TERM_LIMBS; i++) {
        magnitude[i] = t[i];
    }
    if (negative) {
        vor__mw_neg(magnitude, TERM_LIMBS);
    }
    vor__mw_mul(n, width, sum->before, before_limbs, magnitude,
                significant(magnitude, TERM_LIMBS));
    if (negative) {
        vor__mw_neg(n, width);
    }
    vor__mw_add(n, sum->spare, width);
}

/* The shoelace term of the edge p -> q. */
VOR__NOINLINE static void add_edge(centroid_sum_t *sum, const geo_point_t *p,
                                   const geo_point_t *q)
{
    vor__limb cross[TERM_LIMBS];
    vor__limb t[TERM_LIMBS];
    vor__limb u[TERM_LIMBS];
    vor__limb term[TERM_LIMBS];
    vor__limb square[GEO_LIMBS];
    term_product(cross, p->x, GEO_LIMBS, q->y, GEO_LIMBS);
    term_product(t, q->x, GEO_LIMBS, p->y, GEO_LIMBS);
    vor__mw_sub(cross, t, TERM_LIMBS);
    vor__mw_mul(square, GEO_LIMBS, q->w, GEO_LIMBS, q->w, GEO_LIMBS); /* < 2^130 */

    /* the width this step needs, from the numbers' actual sizes (the
     * sums' N w^2 + T Q_{i-1}, the denominator's Q_i w^2), capped by the
     * bound SUM_BITS, where every value fits whatever the estimate says */
    size_t square_limbs = significant(square, GEO_LIMBS);
    size_t before_limbs = significant(sum->before, sum->width);
    size_t denominator_limbs = significant(sum->denominator, sum->width);
    size_t widest = denominator_limbs;
    vor__limb *sums[3] = {sum->area, sum->x, sum->y};
    for (unsigned i = 0; i < 3u; i++) {
        size_t limbs = significant(sums[i], sum->width);
        widest = (limbs > widest) ? limbs : widest;
    }
    widest = (before_limbs + TERM_LIMBS > (widest + square_limbs)) ? before_limbs + TERM_LIMBS
                                                                 : (widest + square_limbs);
    size_t width = sum_limbs(sum->vertices);
    width = ((widest + 1u) < width) ? (widest + 1u) : width;
    widen_sums(sum, width);

    /* t and u below 2^165, the cross product below 2^199 */
    term_product(u, p->w, GEO_LIMBS, q->w, GEO_LIMBS);
    term_product(term, cross, FACTOR_LIMBS, u, FACTOR_LIMBS);
    accumulate(sum, sum->area, term, square, square_limbs, before_limbs);
    term_product(t, p->x, GEO_LIMBS, q->w, GEO_LIMBS);
    term_product(u, q->x, GEO_LIMBS, p->w, GEO_LIMBS);
    vor__mw_add(t, u, TERM_LIMBS);
    term_product(term, cross, FACTOR_LIMBS, t, FACTOR_LIMBS);
    accumulate(sum, sum->x, term, square, square_limbs, before_limbs);
    term_product(t, p->y, GEO_LIMBS, q->w, GEO_LIMBS);
    term_product(u, q->y, GEO_LIMBS, p->w, GEO_LIMBS);
    vor__mw_add(t, u, TERM_LIMBS);
    term_product(term, cross, FACTOR_LIMBS, t, FACTOR_LIMBS);
    accumulate(sum, sum->y, term, square, square_limbs, before_limbs);

    /* Q_{i+1} = Q_i w_{i+1}^2; the buffers rotate instead of copying */
    vor__mw_mul(sum->spare, width, sum->denominator, denominator_limbs, square, square_limbs);
    vor__limb *free_buffer = sum->before;
    sum->before = sum->denominator;
    sum->denominator = sum->spare;
    sum->spare = free_buffer;
}

static void copy_point(geo_point_t *to, const geo_point_t *from)
{
    for (size_t i = 0; i < GEO_LIMBS; i++) {
        to->x[i] = from->x[i];
        to->y[i] = from->y[i];
        to->w[i] = from->w[i];
    }
}

/* A confirmed vertex, kept until the trace adds it. */
static void hold_vertex(centroid_sum_t *sum, const geo_point_t *p)
{
    copy_point(&sum->next, p);
    sum->held = true;
}

/* The emitter's confirmed vertices, in order. */
VOR__ALWAYS_INLINE void add_vertex(centroid_sum_t *sum, const geo_point_t *p)
{
    if (sum->vertices == 0u) {
        copy_point(&sum->first, p);
        /* Q_{-1} = 1, Q_0 = w_0^2, the sums 0 */
        sum->width = sum_limbs(0);
        vor__mw_from_u64(sum->before, sum->width, 1u);
        vor__mw_from_u64(sum->denominator, sum->width, 0u);
        vor__mw_mul(sum->denominator, sum->width, p->w, GEO_LIMBS, p->w, GEO_LIMBS);
        vor__mw_from_u64(sum->area, sum->width, 0u);
        vor__mw_from_u64(sum->x, sum->width, 0u);
        vor__mw_from_u64(sum->y, sum->width, 0u);
    } else {
        add_edge(sum, &sum->previous, p);
    }
    copy_point(&sum->previous, p);
    sum->vertices++;
}

/* Field by field: a structure assignment may become a memcpy call. */
static void write_centroid(vor_centroid_t *out, const vor_centroid_t *from)
{
    out->point.x = from->point.x;
    out->point.y = from->point.y;
    out->area = from->area;
    out->vertices = from->vertices;
}

static void add_held_vertex(centroid_sum_t *sum)
{
    if ((sum != NULL) && sum->held) {
        sum->held = false;
        add_vertex(sum, &sum->next);
    }
}

static int32_t clamp(int32_t v, int32_t low, int32_t high)
{
    return (v < low) ? low : (v > high) ? high : v;
}

/* The limbs a division of the wide sums needs: with m limbs, step 2^bits
 * < 2^(L (m - 1)). A rest (>= 0) with a limb set at m - 1 or above gives
 * a quotient too large: then n, and divide() says so. */
static size_t division_width(const vor__limb *rest, const vor__limb *step, size_t n,
                             unsigned bits)
{
    size_t m = n;
    while ((m > 1u) && (step[m - 1u] == 0u)) {
        m--;
    }
    m += VOR__LIMBS((size_t)bits) + 1u;
    if ((m >= n) || vor__mw_sign(rest, n) < 0) {
        return n;
    }
    for (size_t i = m - 1u; i < n; i++) {
        if (rest[i] != 0u) {
            return n;
        }
    }
    return m;
}

/* s + floor(n / (6 N_A) + 1/2) = s + floor((n + 3 N_A) / 6 N_A): the
 * rounded centroid coordinate, n / 3 N_A in the doubled frame. */
static int32_t round_centroid(centroid_sum_t *sum, vor__limb *n, int32_t origin)
{
    size_t width = sum->width;
    for (size_t i = 0; i < width; i++) {
        sum->spare[i] = sum->area[i];
    }
    vor__mw_add(sum->spare, sum->area, width);
    vor__mw_add(sum->spare, sum->area, width); /* 3 N_A */
    vor__mw_add(n, sum->spare, width);
    vor__mw_shl1(sum->spare, width); /* 6 N_A */
    int32_t result;
    /* magnitudes: a negative n is as wide as its negation */
    bool negative = vor__mw_sign(n, width) < 0;
    if (negative) {
        vor__mw_neg(n, width);
    }
    size_t m = division_width(n, sum->spare, width, 33u);
    if (negative) {
        vor__mw_neg(n, m);
    }
    bool in_range = add_saturated(origin, floor_quotient(n, sum->spare, m, 33u), &result);
    VOR_ASSERT(in_range); /* the centroid is in the cell, so in the box */
    (void)in_range;
    return result;
}

/* The scratch, aligned for limbs: its first limb, and *usable its bytes
 * from there. */
VOR__ALWAYS_INLINE vor__limb *align_scratch(void *scratch, size_t scratch_bytes, size_t *usable)
{
    size_t skip = (size_t)(0u - (uintptr_t)scratch) & (sizeof(vor__limb) - 1u);
    *usable = (scratch_bytes > skip) ? (scratch_bytes - skip) : 0u;
    return (vor__limb *)(void *)((unsigned char *)scratch + skip);
}

/* Empty sums over six numbers of `stride` limbs from `limbs`. */
VOR__ALWAYS_INLINE void begin_sums(centroid_sum_t *sum, vor__limb *limbs, size_t stride)
{
    sum->area = limbs;
    sum->x = limbs + stride;
    sum->y = limbs + (2u * stride);
    sum->before = limbs + (3u * stride);
    sum->denominator = limbs + (4u * stride);
    sum->spare = limbs + (5u * stride);
    sum->width = 0;
    sum->vertices = 0;
    sum->held = false;
}

/* The closed boundary's sums after `steps` of them, rounded once into
 * result (the site s is the frame's origin): false, with result
 * untouched, when the area is not positive. */
VOR__ALWAYS_INLINE bool round_sums(centroid_sum_t *sum, uint32_t steps, const vor_point_t *s,
                                   vor_centroid_t *result)
{
    widen_sums(sum, sum_limbs(steps)); /* the bound's room for the divisions */
    if (vor__mw_sign(sum->area, sum->width) <= 0) {
        return false; /* distinct vertices, but all on one line */
    }
    result->point.x = round_centroid(sum, sum->x, s->x);
    result->point.y = round_centroid(sum, sum->y, s->y);
    /* the area is N_A / 8 Q in the doubled frame (a factor 4 for the
     * scale, 2 for "twice"): floor((N_A + 4 Q) / 8 Q), below 2^64 */
    size_t width = sum->width;
    for (size_t i = 0; i < width; i++) {
        sum->spare[i] = sum->denominator[i];
    }
    vor__mw_shl1(sum->spare, width);
    vor__mw_shl1(sum->spare, width);
    vor__mw_add(sum->area, sum->spare, width);
    vor__mw_shl1(sum->spare, width);
    uint64_t area;
    bool negative;
    bool exact;
    bool fits = divide(sum->area, sum->spare, division_width(sum->area, sum->spare, width, 64u),
                       64u, &area, &negative, &exact);
    VOR_ASSERT(fits && !negative);
    result->area = fits ? area : UINT64_MAX;
    return true;
}

/* vor_cell_centroid of a site of the mesh (weights: a power diagram's,
 * or NULL), the arguments checked; hidden: a power diagram's hidden site,
 * whose cell is empty. */
static int cell_centroid(const vor_t *d, const int64_t *weights, uint32_t site, bool hidden,
                         const vor_box_t *box, void *scratch, size_t scratch_bytes,
                         vor_centroid_t *out)
{
    const vor_point_t *s = &d->sites[site];
    vor_centroid_t result;
    /* no area: the point of the box nearest the site */
    result.point.x = clamp(s->x, box->x0, box->x1);
    result.point.y = clamp(s->y, box->y0, box->y1);
    result.area = 0;
    result.vertices = 0;
    if (hidden || (box->x0 == box->x1) || (box->y0 == box->y1)) {
        write_centroid(out, &result);
        return VOR_OK;
    }
    cell_t c;
    begin_cell(&c, d, weights, site, box);
    /* the scratch, aligned for limbs; VOR_CENTROID_SCRATCH_BYTES has room */
    size_t usable;
    vor__limb *limbs = align_scratch(scratch, scratch_bytes, &usable);
    size_t stride;
    /* at most one vertex per neighbour and per box side: count first only
     * when the scratch might be too small */
    if (!scratch_fits(usable, c.degree + 4u, &stride)) {
        uint32_t needed = trace(&c, NULL, NULL);
        if (needed == 0u) {
            write_centroid(out, &result);
            return VOR_OK;
        }
        if (!scratch_fits(usable, needed, &stride)) {
            out->vertices = needed;
            return VOR_ERR_BUFFER;
        }
    }
    centroid_sum_t sum;
    begin_sums(&sum, limbs, stride);
    uint32_t count = trace(&c, NULL, &sum);
    if (count == 0u) {
        write_centroid(out, &result);
        return VOR_OK;
    }
    add_edge(&sum, &sum.previous, &sum.first);
    if (!round_sums(&sum, count, s, &result)) {
        write_centroid(out, &result);
        return VOR_OK;
    }
    result.vertices = count;
    write_centroid(out, &result);
    return VOR_OK;
}

int vor_cell_centroid(const vor_t *d, uint32_t site, const vor_box_t *box, void *scratch,
                      size_t scratch_bytes, vor_centroid_t *out)
{
    if ((d == NULL) || bad_box(box) || (out == NULL) || ((scratch == NULL) && (scratch_bytes > 0u)) ||
        !vor__site_in_mesh(d, site)) {
        return VOR_ERR_ARG;
    }
    return cell_centroid(d, NULL, site, false, box, scratch, scratch_bytes, out);
}

int vor_power_cell_centroid(const vor_power_t *pd, uint32_t site, const vor_box_t *box,
                            void *scratch, size_t scratch_bytes, vor_centroid_t *out)
{
    if ((pd == NULL) || bad_box(box) || (out == NULL) ||
        ((scratch == NULL) && (scratch_bytes > 0u))) {
        return VOR_ERR_ARG;
    }
    int hidden = vor_power_hidden(pd, site);
    if (hidden < 0) {
        return hidden;
    }
    return cell_centroid(&pd->mesh, pd->weights, site, hidden != 0, box, scratch, scratch_bytes,
                         out);
}

/* ------------------------------------------------------------------ */
/* Cells clipped to a simple polygon                                   */

/*
 * The room is a simple polygon and the cell the intersection of the
 * half-planes of the site's bisectors. The pieces are found by clipping
 * the room by one half-plane at a time, every piece a simple polygon
 * kept as the cyclic list of its edges' lines ("names": a neighbour's
 * id for its bisector, ROOM_LINE + i for room edge i, counterclockwise);
 * vertex i is where lines i - 1 and i meet, so consecutive lines are
 * never parallel and no vertex is a straight angle. Cutting a piece by a
 * line L keeps the runs of its boundary strictly inside L's half-plane
 * (chains: they enter where an edge goes from on-or-outside to strictly
 * inside, exit where one goes back), and joins each exit to an entry
 * along L: sorted along L in its direction (the half-plane on the left),
 * the crossings pair as (exit, entry), (exit, entry), ... Two crossings
 * at one point are a vertex on L whose two edges go strictly inside: a
 * convex vertex touches L from inside (exit first: a zero-length join,
 * the piece goes on through the vertex), a reflex one pinches the piece
 * in two there (entry first). Everything is one of the 3x3 determinants
 * of the cells above (side_of, direction), with the room's lines
 * a = dy, b = -dx, c < 2^66 in the same doubled frame, so the same
 * 160-bit bounds hold. docs/design/geometry.md has the argument.
 */
#define ROOM_LINE 0x80000000u
#define CLIP_EXIT 0u
#define CLIP_ENTRY 1u
#define CLIP_SAME 0x80000000u /* a chain's join to the next has length 0 */

typedef struct vor__clip_frame {
    cell_t cell; /* d, site, s: the bisectors and their frame */
    const vor_point_t *room;
    uint32_t room_count;
    bool reversed;
    /* order K: the set's K sites, then its `others` other neighbours;
     * line (j << shift) | i is the bisector of set[i] and other j, which
     * pair_line computes. NULL for order 1, whose lines are named by
     * the neighbour alone. */
    const uint32_t *set;
    uint32_t order;
    uint32_t others;
    uint32_t shift;
    vor__pair_line_fn *pair_line;
} clip_frame_t;

/* The room's vertex i in counterclockwise order. */
static const vor_point_t *room_point(const clip_frame_t *f, uint32_t i)
{
    return &f->room[f->reversed ? (f->room_count - 1u - i) : i];
}

/* The line of room edge i (counterclockwise, the room on its left): its
 * outward normal (dy, -dx), through the edge's start. */
static void room_line(const clip_frame_t *f, uint32_t i, geo_line_t *l)
{
    const vor_point_t *p = room_point(f, i);
    const vor_point_t *q = room_point(f, (i + 1u == f->room_count) ? 0u : (i + 1u));
    const vor_point_t *s = f->cell.s;
    int64_t dx = (int64_t)q->x - p->x;
    int64_t dy = (int64_t)q->y - p->y;
    int64_t px = (int64_t)p->x - s->x;
    int64_t py = (int64_t)p->y - s->y;
    vor__limb t[GEO_LIMBS];
    l->a = dy;
    l->b = -dx;
    mul_i64_i64(l->c, dy, px + px); /* |c| < 2 2^32 2^33 = 2^66 */
    mul_i64_i64(t, -dx, py + py);
    vor__mw_add(l->c, t, GEO_LIMBS);
}

static void clip_line(const clip_frame_t *f, uint32_t name, geo_line_t *l)
{
    if (name >= ROOM_LINE) {
        room_line(f, name - ROOM_LINE, l);
    } else if (f->pair_line == NULL) {
        cell_bisector(&f->cell, name, l);
    } else {
        f->pair_line(f, name, l);
    }
}

/* The vertex where lines a and b meet (never parallel in a piece). */
static void clip_vertex(const clip_frame_t *f, uint32_t a, uint32_t b, geo_point_t *p)
{
    geo_line_t la;
    geo_line_t lb;
    clip_line(f, a, &la);
    clip_line(f, b, &lb);
    bool met = intersect(p, &la, &lb);
    VOR_ASSERT(met);
    (void)met;
}

/* Do the intervals between a and b and between c and e meet? */
static bool spans_meet(int32_t a, int32_t b, int32_t c, int32_t e)
{
    int32_t lo1 = (a < b) ? a : b;
    int32_t hi1 = (a < b) ? b : a;
    int32_t lo2 = (c < e) ? c : e;
    int32_t hi2 = (c < e) ? e : c;
    return (lo1 <= hi2) && (lo2 <= hi1);
}

/* Is the room simple? Exact orientations of its int32 vertices: no
 * zero-length edge, consecutive edges not folding back, other edges
 * disjoint. Then the lowest vertex (smallest y, then x) is a strict
 * corner whose turn gives the orientation: *clockwise. */
static bool segments_meet(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                          const vor_point_t *e)
{
    int o1 = vor__orient2d_sign(a, b, c);
    int o2 = vor__orient2d_sign(a, b, e);
    int o3 = vor__orient2d_sign(c, e, a);
    int o4 = vor__orient2d_sign(c, e, b);
    if ((o1 * o2 > 0) || (o3 * o4 > 0)) {
        return false;
    }
    if ((o1 != 0) || (o2 != 0)) {
        return true; /* a proper crossing, or an end on the other segment */
    }
    /* all four collinear: they meet when both their x and y spans do */
    return spans_meet(a->x, b->x, c->x, e->x) && spans_meet(a->y, b->y, c->y, e->y);
}

static bool same_vertex(const vor_point_t *a, const vor_point_t *b)
{
    return (a->x == b->x) && (a->y == b->y);
}

static int check_room(const vor_point_t *room, uint32_t m, bool *clockwise, uint32_t *low)
{
    uint32_t lowest = 0;
    for (uint32_t i = 0; i < m; i++) {
        const vor_point_t *p = &room[i];
        const vor_point_t *q = &room[(i + 1u == m) ? 0u : (i + 1u)];
        const vor_point_t *r = &room[(i + 2u >= m) ? (i + 2u - m) : (i + 2u)];
        if (same_vertex(p, q)) {
            return VOR_ERR_POLYGON;
        }
        /* q between p and r folds back when p, q, r are collinear and
         * the edges point opposite ways */
        if ((vor__orient2d_sign(p, q, r) == 0) &&
            (vor__compare_products((int64_t)q->x - p->x, (int64_t)r->x - q->x,
                                   (int64_t)p->y - q->y, (int64_t)r->y - q->y) < 0)) {
            return VOR_ERR_POLYGON;
        }
        /* edges i and j >= i + 2, except the last with the first */
        for (uint32_t j = i + 2u; j < m; j++) {
            if ((i == 0u) && (j + 1u == m)) {
                continue;
            }
            if (segments_meet(p, q, &room[j], &room[(j + 1u == m) ? 0u : (j + 1u)])) {
                return VOR_ERR_POLYGON;
            }
        }
        if ((p->y < room[lowest].y) || ((p->y == room[lowest].y) && (p->x < room[lowest].x))) {
            lowest = i;
        }
    }
    const vor_point_t *before = &room[(lowest == 0u) ? (m - 1u) : (lowest - 1u)];
    const vor_point_t *after = &room[(lowest + 1u == m) ? 0u : (lowest + 1u)];
    int turn = vor__orient2d_sign(before, &room[lowest], after);
    VOR_ASSERT(turn != 0);
    *clockwise = turn < 0;
    *low = lowest;
    return VOR_OK;
}

/* The working memory of a clipping, all in the caller's scratch: pieces
 * as line lists with their ends, read from one list and written to the
 * other; per piece being cut, its vertices' sides and its chains. */
typedef struct clip_work {
    const clip_frame_t *f;
    uint32_t capacity; /* lines of every list: VOR_CLIP_MAX_VERTICES */
    uint32_t *in;
    uint32_t *in_ends;
    uint32_t in_pieces;
    uint32_t *out;
    uint32_t *out_ends;
    uint32_t out_count;
    uint32_t out_pieces;
    uint32_t *sides;  /* [capacity], then the final pieces' starts */
    uint32_t *events; /* [capacity], then the final pieces' counts */
    uint32_t *first;  /* [capacity / 2 + 1] each: a chain's entry edge, */
    uint32_t *last;   /* its exit edge, */
    uint32_t *next;   /* the chain its exit joins (| CLIP_SAME) */
} clip_work_t;

/* The layout below takes 4 v + 5 (v / 2 + 1) words for lists of v
 * lines, below the 7 v + 8 of VOR_CLIP_SCRATCH_BYTES (the
 * bound v on the lines is proved in docs/design/geometry.md). */

static void emit_line(clip_work_t *w, uint32_t name)
{
    VOR_ASSERT(w->out_count < w->capacity);
    w->out[w->out_count] = name;
    w->out_count++;
}

static void end_piece(clip_work_t *w)
{
    VOR_ASSERT(w->out_pieces < ((w->capacity / 2u) + 1u));
    w->out_ends[w->out_pieces] = w->out_count;
    w->out_pieces++;
}

/* Is the crossing of event b (on line L) after that of a along L's
 * direction? Ties (one vertex, two crossings) put an exit first at a
 * convex vertex and an entry first at a reflex one. */
static bool event_after(const clip_work_t *w, const uint32_t *lines, const geo_line_t *line,
                        uint32_t a, uint32_t b)
{
    const clip_frame_t *f = w->f;
    uint32_t ca = a >> 1u;
    uint32_t cb = b >> 1u;
    uint32_t ea = ((a & 1u) == CLIP_ENTRY) ? w->first[ca] : w->last[ca];
    uint32_t eb = ((b & 1u) == CLIP_ENTRY) ? w->first[cb] : w->last[cb];
    geo_line_t la;
    geo_line_t lb;
    geo_point_t p;
    clip_line(f, lines[ea], &la);
    clip_line(f, lines[eb], &lb);
    (void)intersect(&p, line, &lb);
    /* along L, la's a x + b y grows when direction(L, la) > 0, and is 0
     * at a's crossing */
    int s = side_of(&la, &p) * direction(line, &la);
    if (s != 0) {
        return s > 0;
    }
    /* one vertex: the exit's edge ends where the entry's begins */
    const geo_line_t *in_edge = ((a & 1u) == CLIP_EXIT) ? &la : &lb;
    const geo_line_t *out_edge = ((a & 1u) == CLIP_EXIT) ? &lb : &la;
    bool convex = direction(in_edge, out_edge) > 0;
    return ((a & 1u) == CLIP_EXIT) == convex;
}

/* The piece lines[0 .. r) cut by the half-plane of line `name`, its
 * pieces appended to the output. */
static void clip_piece(clip_work_t *w, const uint32_t *lines, uint32_t r, uint32_t name)
{
    const clip_frame_t *f = w->f;
    geo_line_t line;
    geo_point_t p;
    clip_line(f, name, &line);
    uint32_t inside = 0;
    for (uint32_t i = 0; i < r; i++) {
        clip_vertex(f, lines[(i == 0u) ? (r - 1u) : (i - 1u)], lines[i], &p);
        w->sides[i] = 0u;
        if (side_of(&line, &p) < 0) {
            w->sides[i] = 1u; /* strictly inside */
            inside++;
        }
    }
    if (inside == 0u) {
        return; /* on or outside the line: nothing left (no area) */
    }
    if (inside == r) {
        for (uint32_t i = 0; i < r; i++) {
            emit_line(w, lines[i]);
        }
        end_piece(w);
        return;
    }
    /* the chains, from the first entry edge round: edge i goes from
     * vertex i to vertex i + 1 */
    uint32_t start = 0;
    while ((w->sides[start] != 0u) || (w->sides[(start + 1u == r) ? 0u : (start + 1u)] == 0u)) {
        start++; /* some vertex is inside and some not: an entry exists */
    }
    uint32_t chains = 0;
    for (uint32_t k = 0; k < r; k++) {
        uint32_t i = (start + k >= r) ? (start + k - r) : (start + k);
        uint32_t from = w->sides[i];
        uint32_t to = w->sides[(i + 1u == r) ? 0u : (i + 1u)];
        if ((from == 0u) && (to != 0u)) {
            w->first[chains] = i;
        } else if ((from != 0u) && (to == 0u)) {
            w->last[chains] = i;
            w->events[2u * chains] = (2u * chains) + CLIP_EXIT;
            w->events[(2u * chains) + 1u] = (2u * chains) + CLIP_ENTRY;
            chains++;
        } else {
            /* inside a chain, or outside */
        }
    }
    /* sort the crossings along the line (insertion: few of them) */
    uint32_t n = 2u * chains;
    for (uint32_t i = 1; i < n; i++) {
        uint32_t e = w->events[i];
        uint32_t j = i;
        while ((j > 0u) && event_after(w, lines, &line, e, w->events[j - 1u])) {
            w->events[j] = w->events[j - 1u];
            j--;
        }
        w->events[j] = e;
    }
    /* pair them: exit 2t joins entry 2t + 1; a join of length 0 is one
     * vertex, which takes no line */
    for (uint32_t t = 0; t < n; t += 2u) {
        uint32_t exit = w->events[t];
        uint32_t entry = w->events[t + 1u];
        VOR_ASSERT(((exit & 1u) == CLIP_EXIT) && ((entry & 1u) == CLIP_ENTRY));
        geo_line_t le;
        geo_line_t lx;
        clip_line(f, lines[w->last[exit >> 1u]], &lx);
        clip_line(f, lines[w->first[entry >> 1u]], &le);
        (void)intersect(&p, &line, &le);
        w->next[exit >> 1u] = (entry >> 1u) | ((side_of(&lx, &p) == 0) ? CLIP_SAME : 0u);
    }
    /* each cycle of chains is a piece: their lines, and the line between */
    for (uint32_t c = 0; c < chains; c++) {
        if (w->first[c] == NO_LINE) {
            continue;
        }
        uint32_t k = c;
        do {
            uint32_t i = w->first[k];
            uint32_t end = w->last[k];
            emit_line(w, lines[i]);
            while (i != end) {
                i = (i + 1u == r) ? 0u : (i + 1u);
                emit_line(w, lines[i]);
            }
            w->first[k] = NO_LINE;
            if ((w->next[k] & CLIP_SAME) == 0u) {
                emit_line(w, name);
            }
            k = w->next[k] & ~CLIP_SAME;
        } while (k != c);
        end_piece(w);
    }
}

static void swap_lists(clip_work_t *w);

/* Cut every piece of the input list by line `name`; the output becomes
 * the input. */
static void clip_all(clip_work_t *w, uint32_t name)
{
    w->out_count = 0;
    w->out_pieces = 0;
    uint32_t from = 0;
    for (uint32_t k = 0; k < w->in_pieces; k++) {
        clip_piece(w, w->in + from, w->in_ends[k] - from, name);
        from = w->in_ends[k];
    }
    swap_lists(w);
}

/* The output becomes the input. */
static void swap_lists(clip_work_t *w)
{
    uint32_t *t = w->in;
    w->in = w->out;
    w->out = t;
    t = w->in_ends;
    w->in_ends = w->out_ends;
    w->out_ends = t;
    w->in_pieces = w->out_pieces;
}

/* Signs of p.y - q.y, then p.x - q.x, exactly: the products y_p w_q go
 * to 384 bits. */
static int compare_vertices(const geo_point_t *p, const geo_point_t *q)
{
    vor__limb a[TERM_LIMBS];
    vor__limb b[TERM_LIMBS];
    term_product(a, p->y, GEO_LIMBS, q->w, GEO_LIMBS);
    term_product(b, q->y, GEO_LIMBS, p->w, GEO_LIMBS);
    vor__mw_sub(a, b, TERM_LIMBS);
    int s = vor__mw_sign(a, TERM_LIMBS);
    if (s != 0) {
        return s;
    }
    term_product(a, p->x, GEO_LIMBS, q->w, GEO_LIMBS);
    term_product(b, q->x, GEO_LIMBS, p->w, GEO_LIMBS);
    vor__mw_sub(a, b, TERM_LIMBS);
    return vor__mw_sign(a, TERM_LIMBS);
}

static void reverse_lines(uint32_t *lines, uint32_t from, uint32_t to)
{
    while ((from + 1u) < to) {
        to--;
        uint32_t t = lines[from];
        lines[from] = lines[to];
        lines[to] = t;
        from++;
    }
}

/* A piece's lines rotated so that its lowest vertex comes first. */
static void lowest_first(const clip_frame_t *f, uint32_t *lines, uint32_t r)
{
    uint32_t best = 0;
    geo_point_t p;
    geo_point_t low;
    clip_vertex(f, lines[r - 1u], lines[0], &low);
    for (uint32_t i = 1; i < r; i++) {
        clip_vertex(f, lines[i - 1u], lines[i], &p);
        if (compare_vertices(&p, &low) < 0) {
            copy_point(&low, &p);
            best = i;
        }
    }
    reverse_lines(lines, 0, best);
    reverse_lines(lines, best, r);
    reverse_lines(lines, 0, r);
}

/* The neighbours' bisectors, once each, around the site's fan (it closes
 * within vertex_count steps on a valid mesh). */
static uint32_t site_degree(const cell_t *c)
{
    uint32_t degree = 0;
    if (c->d->vertex_count >= 2u) {
        uint32_t slot = c->site;
        uint32_t x;
        uint32_t y;
        uint32_t next;
        for (uint32_t step = 0; step <= c->d->vertex_count; step++) {
            fan_triangle(c, slot, &x, &y, &next);
            degree += (y != VOR__INFINITE) ? 1u : 0u;
            slot = next;
            if (slot == c->site) {
                break;
            }
        }
    }
    return degree;
}

static void close_clip(vor_clip_t *clip, int error)
{
    clip->d = NULL;
    clip->room = NULL;
    clip->room_count = 0;
    clip->reversed = 0;
    clip->site = 0;
    clip->lines = NULL;
    clip->start = NULL;
    clip->count = NULL;
    clip->pieces = 0;
    clip->next_piece = 0;
    clip->error = error;
    clip->set = NULL;
    clip->order = 0;
    clip->others = 0;
    clip->shift = 0;
    clip->pair_line = NULL;
    clip->needed = 0;
}

static void begin_frame(clip_frame_t *f, const vor_t *d, uint32_t site, const vor_point_t *room,
                        uint32_t m, bool reversed)
{
    f->cell.d = d;
    f->cell.weights = NULL;
    f->cell.site = site;
    f->cell.s = &d->sites[site];
    f->cell.box = NULL;
    f->room = room;
    f->room_count = m;
    f->reversed = reversed;
    f->set = NULL;
    f->order = 1;
    f->others = 0;
    f->shift = 0;
    f->pair_line = NULL;
}

/* The frame of a begun iterator. */
static void frame_of(clip_frame_t *f, const vor_clip_t *clip)
{
    begin_frame(f, clip->d, clip->site, clip->room, clip->room_count, clip->reversed != 0u);
    f->set = clip->set;
    f->order = clip->order;
    f->others = clip->others;
    f->shift = clip->shift;
    f->pair_line = clip->pair_line;
}

/* The work lists laid out in words[] for lines of `capacity` (the layout
 * below takes 4 v + 5 (v / 2 + 1) words for v = capacity), and the room,
 * its straight angles dropped, as the one piece to cut. */
static void start_work(clip_work_t *w, const clip_frame_t *f, uint32_t *words, uint32_t capacity)
{
    /* pieces of 3 lines at least, chains of 2: half the lines bound both
     * (a shift: no division helper on ARMv6-M) */
    uint32_t pieces = (capacity / 2u) + 1u;
    uint32_t chains = pieces;
    uint32_t m = f->room_count;
    w->f = f;
    w->capacity = capacity;
    w->in = words;
    w->out = words + capacity;
    w->in_ends = words + (2u * capacity);
    w->out_ends = w->in_ends + pieces;
    w->sides = w->out_ends + pieces;
    w->events = w->sides + capacity;
    w->first = w->events + capacity;
    w->last = w->first + chains;
    w->next = w->last + chains;
    /* edge i's line is dropped when edge i + 1 goes on along it */
    w->out_count = 0;
    w->out_pieces = 0;
    for (uint32_t i = 0; i < m; i++) {
        const vor_point_t *p = room_point(f, i);
        const vor_point_t *q = room_point(f, (i + 1u == m) ? 0u : (i + 1u));
        const vor_point_t *r = room_point(f, (i + 2u >= m) ? (i + 2u - m) : (i + 2u));
        if (vor__orient2d_sign(p, q, r) != 0) {
            emit_line(w, ROOM_LINE + i);
        }
    }
    end_piece(w);
    swap_lists(w);
}

/* Each piece from its lowest vertex, the pieces by them (selection over
 * the pieces' starts and counts, kept in sides and events), and the
 * iterator over them. */
static void finish_clip(vor_clip_t *clip, clip_work_t *w, const clip_frame_t *f)
{
    uint32_t *starts = w->sides;
    uint32_t *counts = w->events;
    uint32_t from = 0;
    for (uint32_t k = 0; k < w->in_pieces; k++) {
        starts[k] = from;
        counts[k] = w->in_ends[k] - from;
        from = w->in_ends[k];
    }
    for (uint32_t k = 0; k < w->in_pieces; k++) {
        lowest_first(f, w->in + starts[k], counts[k]);
    }
    for (uint32_t k = 0; (k + 1u) < w->in_pieces; k++) {
        geo_point_t best;
        geo_point_t p;
        uint32_t at = k;
        clip_vertex(f, w->in[starts[k] + counts[k] - 1u], w->in[starts[k]], &best);
        for (uint32_t j = k + 1u; j < w->in_pieces; j++) {
            clip_vertex(f, w->in[starts[j] + counts[j] - 1u], w->in[starts[j]], &p);
            if (compare_vertices(&p, &best) < 0) {
                copy_point(&best, &p);
                at = j;
            }
        }
        uint32_t t = starts[k];
        starts[k] = starts[at];
        starts[at] = t;
        t = counts[k];
        counts[k] = counts[at];
        counts[at] = t;
    }
    clip->d = f->cell.d;
    clip->room = f->room;
    clip->room_count = f->room_count;
    clip->reversed = 0u;
    if (f->reversed) {
        clip->reversed = 1u;
    }
    clip->site = f->cell.site;
    clip->lines = w->in;
    clip->start = starts;
    clip->count = counts;
    clip->pieces = w->in_pieces;
    clip->next_piece = 0;
    clip->error = VOR_OK;
    clip->set = f->set;
    clip->order = f->order;
    clip->others = f->others;
    clip->shift = f->shift;
    clip->pair_line = f->pair_line;
    clip->needed = 0;
}

/* The scratch's first word-aligned byte (the sizes' 36 bytes cover it). */
static uint32_t *scratch_words(void *scratch)
{
    size_t skip = (size_t)(0u - (uintptr_t)scratch) & 3u;
    return (uint32_t *)(void *)((unsigned char *)scratch + skip);
}

/* VOR_ERR_BUFFER with the bytes needed (saturated). */
static int too_small(vor_clip_t *clip, uint64_t needed)
{
    close_clip(clip, VOR_ERR_BUFFER);
    clip->needed = (needed > (uint64_t)SIZE_MAX) ? SIZE_MAX : (size_t)needed;
    return VOR_ERR_BUFFER;
}

int vor_clip_begin(vor_clip_t *clip, const vor_t *d, uint32_t site, const vor_point_t *room,
                   uint32_t m, void *scratch, size_t scratch_bytes)
{
    if (clip == NULL) {
        return VOR_ERR_ARG;
    }
    if ((d == NULL) || (room == NULL) || (m < 3u) || (m > VOR_CLIP_MAX_ROOM) ||
        ((scratch == NULL) && (scratch_bytes > 0u)) || !vor__site_in_mesh(d, site)) {
        close_clip(clip, VOR_ERR_ARG);
        return VOR_ERR_ARG;
    }
    bool clockwise = false;
    uint32_t lowest = 0;
    int error = check_room(room, m, &clockwise, &lowest);
    if (error != VOR_OK) {
        close_clip(clip, error);
        return error;
    }
    clip_frame_t f;
    begin_frame(&f, d, site, room, m, clockwise);
    uint32_t degree = site_degree(&f.cell);

    /* the macro is the contract; its 36 bytes cover the alignment */
    uint32_t sites = degree + 1u; /* the site and its neighbours */
    uint32_t capacity = VOR_CLIP_MAX_VERTICES(m, sites);
    if (scratch_bytes < VOR_CLIP_SCRATCH_BYTES(m, sites)) {
        return too_small(clip, VOR_CLIP_SCRATCH_BYTES(m, sites));
    }
    clip_work_t w;
    start_work(&w, &f, scratch_words(scratch), capacity);
    /* cut by every neighbour's half-plane, around the fan */
    if (d->vertex_count >= 2u) {
        uint32_t slot = site;
        uint32_t x;
        uint32_t y;
        uint32_t next;
        for (uint32_t step = 0; (step <= d->vertex_count) && (w.in_pieces > 0u); step++) {
            fan_triangle(&f.cell, slot, &x, &y, &next);
            if (y != VOR__INFINITE) {
                clip_all(&w, y);
            }
            slot = next;
            if (slot == site) {
                break;
            }
        }
    }
    finish_clip(clip, &w, &f);
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Order-K cells clipped to a simple polygon                          */

/*
 * The cell of a set S is the intersection of the half-planes of the
 * bisectors of s in S and t outside. Only the sites next to S in the
 * Delaunay triangulation matter: the cell is the intersection over s of
 * s's cell among the sites outside S and s, bounded by s's Delaunay
 * neighbours there, and taking a site out of a Delaunay triangulation
 * joins only its own neighbours, so removing S - s one site at a time
 * gives s no neighbour outside the neighbours of S. With c such "other"
 * sites, k c pair lines cut the room, named (j << shift) | i, and every
 * line keeps the bounds of "Arithmetic" in the frame of S's first site:
 * the same 160-bit code cuts, orders and reports the pieces.
 * docs/design/geometry.md has the argument and the walk.
 */

static bool in_list(const uint32_t *list, uint32_t count, uint32_t id)
{
    for (uint32_t i = 0; i < count; i++) {
        if (list[i] == id) {
            return true;
        }
    }
    return false;
}

/* Is y a neighbour of one of set[0 .. i)? */
static bool next_to_earlier(const vor_t *d, uint32_t y, const uint32_t *set, uint32_t i)
{
    bool found = false;
    if (i > 0u) {
        vor_neighbour_iter_t ni;
        uint32_t z;
        (void)vor_neighbours_begin(&ni, d, y); /* a neighbour: in the mesh */
        while ((vor_neighbours_next(&ni, &z) != 0) && !found) {
            found = in_list(set, i, z);
        }
    }
    return found;
}

/* The set's other neighbours, each once (at the first of the set it is
 * next to): their count, and when out is not NULL the ids in out[]. */
static uint32_t set_neighbours(const vor_t *d, const uint32_t *set, uint32_t k, uint32_t *out)
{
    uint32_t count = 0;
    for (uint32_t i = 0; i < k; i++) {
        vor_neighbour_iter_t ni;
        uint32_t y;
        (void)vor_neighbours_begin(&ni, d, set[i]); /* checked: in the mesh */
        while (vor_neighbours_next(&ni, &y) != 0) {
            if (!in_list(set, k, y) && !next_to_earlier(d, y, set, i)) {
                if (out != NULL) {
                    out[count] = y;
                }
                count++;
            }
        }
    }
    return count;
}

/* VOR_OK when set[0 .. k) are k distinct sites of the mesh, 0 < k <
 * distinct sites, k <= VOR_ORDER_MAX. */
static int check_set(const vor_t *d, const uint32_t *set, uint32_t k)
{
    if ((d == NULL) || (set == NULL) || (k == 0u) || (k > VOR_ORDER_MAX) ||
        (k >= d->vertex_count)) {
        return VOR_ERR_ARG;
    }
    for (uint32_t i = 0; i < k; i++) {
        if (!vor__site_in_mesh(d, set[i]) || in_list(set, i, set[i])) {
            return VOR_ERR_ARG;
        }
    }
    return VOR_OK;
}

/* Sorts ids[0 .. k) increasing (insertion: k is small). */
static void sort_ids(uint32_t *ids, uint32_t k)
{
    for (uint32_t i = 1; i < k; i++) {
        uint32_t v = ids[i];
        uint32_t j = i;
        while ((j > 0u) && (ids[j - 1u] > v)) {
            ids[j] = ids[j - 1u];
            j--;
        }
        ids[j] = v;
    }
}

/* Line (j << shift) | i of an order-K frame: the bisector of set[i] and
 * other j. Reached only through the frame's pointer, which
 * vor_order_cell_begin sets, so that a firmware clipping order-1 cells
 * links none of it. */
static void pair_line(const clip_frame_t *f, uint32_t name, geo_line_t *l)
{
    const vor_point_t *p = f->cell.d->sites;
    uint32_t i = name & ((1u << f->shift) - 1u);
    uint32_t j = name >> f->shift;
    pair_bisector(l, f->cell.s, &p[f->set[i]], &p[f->set[f->order + j]]);
}

/* The order-k cell of a checked set in a checked room, into the scratch:
 * the set sorted, its other neighbours, k spare words (*spare, for the
 * walk), then the work lists. */
static int order_cell(vor_clip_t *clip, const vor_t *d, const uint32_t *set, uint32_t k,
                      const vor_point_t *room, uint32_t m, bool clockwise, void *scratch,
                      size_t scratch_bytes, uint32_t **spare)
{
    uint32_t others = set_neighbours(d, set, k, NULL);
    /* k <= 2^10, others < 2^21: the lines are below 2^31, the capacity
     * below 2^32 */
    uint32_t lines = (uint32_t)vor__mul_u32(k, others);
    uint32_t capacity = VOR_CLIP_MAX_VERTICES(m, lines + 1u);
    uint32_t set_words = (2u * k) + others;
    uint64_t needed = vor__mul_u32(28u, capacity) + 36u + vor__mul_u32(4u, set_words);
    if ((uint64_t)scratch_bytes < needed) {
        return too_small(clip, needed);
    }
    uint32_t *words = scratch_words(scratch);
    for (uint32_t i = 0; i < k; i++) {
        words[i] = set[i];
    }
    sort_ids(words, k);
    (void)set_neighbours(d, words, k, words + k);
    if (spare != NULL) {
        *spare = words + k + others;
    }
    clip_frame_t f;
    begin_frame(&f, d, words[0], room, m, clockwise);
    f.set = words;
    f.order = k;
    f.others = others;
    f.shift = vor__mw_bit_length32(k - 1u);
    f.pair_line = pair_line;
    clip_work_t w;
    start_work(&w, &f, words + (2u * k) + others, capacity);
    for (uint32_t j = 0; (j < others) && (w.in_pieces > 0u); j++) {
        for (uint32_t i = 0; (i < k) && (w.in_pieces > 0u); i++) {
            clip_all(&w, (j << f.shift) | i);
        }
    }
    finish_clip(clip, &w, &f);
    return VOR_OK;
}

int vor_order_cell_begin(vor_clip_t *clip, const vor_t *d, const uint32_t *set, uint32_t k,
                         const vor_point_t *room, uint32_t m, void *scratch,
                         size_t scratch_bytes)
{
    if (clip == NULL) {
        return VOR_ERR_ARG;
    }
    int error = check_set(d, set, k);
    if ((room == NULL) || (m < 3u) || (m > VOR_CLIP_MAX_ROOM) ||
        ((scratch == NULL) && (scratch_bytes > 0u))) {
        error = VOR_ERR_ARG;
    }
    bool clockwise = false;
    uint32_t lowest = 0;
    if (error == VOR_OK) {
        error = check_room(room, m, &clockwise, &lowest);
    }
    if (error != VOR_OK) {
        close_clip(clip, error);
        return error;
    }
    return order_cell(clip, d, set, k, room, m, clockwise, scratch, scratch_bytes, NULL);
}

/* ------------------------------------------------------------------ */
/* The walk over a room's order-K cells                                */

/* Sign of a.b for |a| < 2^32, |b| < 2^34 (in GEO_LIMBS). */
static int dot_sign(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    vor__limb r[GEO_LIMBS];
    vor__limb t[GEO_LIMBS];
    mul_i64_i64(r, ax, bx);
    mul_i64_i64(t, ay, by);
    vor__mw_add(r, t, GEO_LIMBS);
    return vor__mw_sign(r, GEO_LIMBS);
}

/* Is site a nearer than site b to p = v + e u + e^2 u' (u' = u turned a
 * quarter counterclockwise) for every small enough e > 0? |p - a|^2 -
 * |p - b|^2 = (|v - a|^2 - |v - b|^2) + 2 e (b - a).u + 2 e^2 (b - a).u':
 * its first nonzero term's sign. Distinct sites always differ. */
static bool nearer_at(const vor_point_t *v, int64_t ux, int64_t uy, const vor_point_t *a,
                      const vor_point_t *b)
{
    int s = vor__closer_sign(v, a, b, NULL);
    int64_t ex = (int64_t)b->x - a->x;
    int64_t ey = (int64_t)b->y - a->y;
    if (s == 0) {
        s = dot_sign(ex, ey, ux, uy);
    }
    if (s == 0) {
        s = dot_sign(ex, ey, -uy, ux);
    }
    return s < 0;
}

/* The k sites nearest a point just inside the room's lowest corner v
 * (which is convex), along u = (before - v) + (after - v), strictly
 * inside its angle: that point lies in no bisector, so its cell meets
 * the room in an area. k rounds of a scan, each for the nearest site
 * beyond the last one taken; the ids sorted. */
static void corner_sites(const vor_t *d, const vor_point_t *room, uint32_t m, uint32_t lowest,
                         uint32_t k, uint32_t *out)
{
    const vor_point_t *v = &room[lowest];
    const vor_point_t *before = &room[(lowest == 0u) ? (m - 1u) : (lowest - 1u)];
    const vor_point_t *after = &room[(lowest + 1u == m) ? 0u : (lowest + 1u)];
    int64_t ux = ((int64_t)before->x - v->x) + ((int64_t)after->x - v->x);
    int64_t uy = ((int64_t)before->y - v->y) + ((int64_t)after->y - v->y);
    const vor_point_t *p = d->sites;
    for (uint32_t r = 0; r < k; r++) {
        uint32_t best = VOR__NONE;
        for (uint32_t x = 0; x < d->site_count; x++) {
            if (!vor__site_in_mesh(d, x) ||
                ((r > 0u) && !nearer_at(v, ux, uy, &p[out[r - 1u]], &p[x]))) {
                continue; /* a duplicate's id, or taken */
            }
            if ((best == VOR__NONE) || nearer_at(v, ux, uy, &p[x], &p[best])) {
                best = x;
            }
        }
        out[r] = best; /* k < distinct sites: one is left */
    }
    sort_ids(out, k);
}

static void close_walk(vor_order_iter_t *it, int error)
{
    it->d = NULL;
    it->room = NULL;
    it->room_count = 0;
    it->reversed = 0;
    it->order = 0;
    it->sets = NULL;
    it->index = NULL;
    it->max_sets = 0;
    it->met = 0;
    it->done = 0;
    it->scratch = NULL;
    it->scratch_bytes = 0;
    it->needed = 0;
    it->error = error;
}

int vor_order_cells_begin(vor_order_iter_t *it, const vor_t *d, uint32_t k,
                          const vor_point_t *room, uint32_t m, uint32_t *sets,
                          uint32_t max_sets, void *scratch, size_t scratch_bytes)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    int error = VOR_OK;
    if ((d == NULL) || (k == 0u) || (k > VOR_ORDER_MAX) || (k >= d->vertex_count) ||
        (room == NULL) || (m < 3u) || (m > VOR_CLIP_MAX_ROOM) ||
        ((sets == NULL) && (max_sets > 0u)) || ((scratch == NULL) && (scratch_bytes > 0u))) {
        error = VOR_ERR_ARG;
    }
    bool clockwise = false;
    uint32_t lowest = 0;
    if (error == VOR_OK) {
        error = check_room(room, m, &clockwise, &lowest);
    }
    if ((error == VOR_OK) && (max_sets == 0u)) {
        error = VOR_ERR_BUFFER;
    }
    if (error != VOR_OK) {
        close_walk(it, error);
        return error;
    }
    it->d = d;
    it->room = room;
    it->room_count = m;
    it->reversed = 0u;
    if (clockwise) {
        it->reversed = 1u;
    }
    it->order = k;
    it->sets = sets;
    it->index = sets + ((size_t)max_sets * k);
    it->max_sets = max_sets;
    corner_sites(d, room, m, lowest, k, sets);
    it->index[0] = 0;
    it->met = 1;
    it->done = 0;
    it->scratch = scratch;
    it->scratch_bytes = scratch_bytes;
    it->needed = 0;
    it->error = VOR_OK;
    return VOR_OK;
}

/* The set across the piece edge on the bisector of set[i] and other j
 * (name (j << shift) | i) into across[0 .. k), sorted: set[i] swapped
 * for other j. Only that pair ties along the edge: a second pair (s, t)
 * on the same line would give, at every point of the edge, |p - set[i]|
 * <= |p - t| = |p - s| <= |p - other j| = |p - set[i]|, so the line
 * would also be the bisector of set[i] and s, and s would be the mirror
 * image of set[i], other j, which is not in the set. Every other pair
 * is strictly on its side inside the edge (a line crossing it would cut
 * the cell), so just across it the K nearest are the set swapped. */
static void set_across(const clip_frame_t *f, uint32_t name, uint32_t *across)
{
    uint32_t i = name & ((1u << f->shift) - 1u);
    uint32_t j = name >> f->shift;
    for (uint32_t h = 0; h < f->order; h++) {
        across[h] = f->set[h];
    }
    across[i] = f->set[f->order + j];
    sort_ids(across, f->order);
}

/* Sign of a - b, sets of k ids compared from the first. */
static int compare_sets(const uint32_t *a, const uint32_t *b, uint32_t k)
{
    for (uint32_t i = 0; i < k; i++) {
        if (a[i] != b[i]) {
            return (a[i] < b[i]) ? -1 : 1;
        }
    }
    return 0;
}

/* The set met before, or added to the store (false when it is full). */
static bool meet(vor_order_iter_t *it, const uint32_t *set)
{
    uint32_t k = it->order;
    uint32_t lo = 0;
    uint32_t hi = it->met;
    while (lo < hi) { /* binary search over the increasing index */
        uint32_t mid = lo + ((hi - lo) >> 1);
        int c = compare_sets(it->sets + ((size_t)it->index[mid] * k), set, k);
        if (c == 0) {
            return true;
        }
        if (c < 0) {
            lo = mid + 1u;
        } else {
            hi = mid;
        }
    }
    if (it->met == it->max_sets) {
        return false;
    }
    uint32_t *to = it->sets + ((size_t)it->met * k);
    for (uint32_t i = 0; i < k; i++) {
        to[i] = set[i];
    }
    for (uint32_t i = it->met; i > lo; i--) {
        it->index[i] = it->index[i - 1u];
    }
    it->index[lo] = it->met;
    it->met++;
    return true;
}

/* The cells across every bisector edge of the cell's pieces, met. */
static bool meet_neighbours(vor_order_iter_t *it, const vor_clip_t *clip, uint32_t *spare)
{
    clip_frame_t f;
    frame_of(&f, clip);
    for (uint32_t k = 0; k < clip->pieces; k++) {
        const uint32_t *lines = clip->lines + clip->start[k];
        for (uint32_t i = 0; i < clip->count[k]; i++) {
            if (lines[i] >= ROOM_LINE) {
                continue;
            }
            set_across(&f, lines[i], spare);
            if (!meet(it, spare)) {
                return false;
            }
        }
    }
    return true;
}

/* *to = *from, field by field (a structure assignment may become a call
 * to memcpy, which a freestanding library does not have). */
static void copy_clip(vor_clip_t *to, const vor_clip_t *from)
{
    to->d = from->d;
    to->room = from->room;
    to->room_count = from->room_count;
    to->reversed = from->reversed;
    to->site = from->site;
    to->lines = from->lines;
    to->start = from->start;
    to->count = from->count;
    to->pieces = from->pieces;
    to->next_piece = from->next_piece;
    to->error = from->error;
    to->set = from->set;
    to->order = from->order;
    to->others = from->others;
    to->shift = from->shift;
    to->pair_line = from->pair_line;
    to->needed = from->needed;
}

int vor_order_cells_next(vor_order_iter_t *it, uint32_t *set, vor_clip_t *clip)
{
    if ((it == NULL) || (it->d == NULL)) {
        return 0;
    }
    if ((set == NULL) || (clip == NULL)) {
        it->error = VOR_ERR_ARG;
        return 0;
    }
    uint32_t k = it->order;
    /* each round computes one set met, and met <= max_sets */
    while (it->done < it->met) {
        const uint32_t *s = it->sets + ((size_t)it->done * k);
        vor_clip_t cell;
        uint32_t *spare = NULL;
        int error = order_cell(&cell, it->d, s, k, it->room, it->room_count, it->reversed != 0u,
                               it->scratch, it->scratch_bytes, &spare);
        if (error != VOR_OK) {
            it->needed = cell.needed;
            it->error = error;
            return 0;
        }
        if (cell.pieces == 0u) {
            it->done++; /* met across a room edge: outside the room */
            continue;
        }
        if (!meet_neighbours(it, &cell, spare)) {
            it->error = VOR_ERR_BUFFER;
            return 0;
        }
        for (uint32_t i = 0; i < k; i++) {
            set[i] = s[i];
        }
        copy_clip(clip, &cell);
        it->done++;
        it->error = VOR_OK;
        return 1;
    }
    it->error = VOR_OK;
    return 0;
}

int vor_order_cells_error(const vor_order_iter_t *it)
{
    return (it != NULL) ? it->error : VOR_ERR_ARG;
}

/* |a| over n limbs, two's complement, into magnitude; a's sign. */
static int magnitude_of(vor__limb *r, const vor__limb *a, size_t n)
{
    int sign = vor__mw_sign(a, n);
    for (size_t i = 0; i < n; i++) {
        r[i] = a[i];
    }
    if (sign < 0) {
        vor__mw_neg(r, n);
    }
    return sign;
}

static bool is_even(const vor__limb *a)
{
    return (a[0] & 1u) == 0u;
}

/* x / w, y / w in lowest terms: divided by their greatest common divisor,
 * found by Stein's binary algorithm (shifts and subtractions only; at
 * most 2 x 160 steps), w > 0. */
static void lowest_terms(vor__limb *x, vor__limb *y, vor__limb *w)
{
    vor__limb g[GEO_LIMBS];
    vor__limb u[GEO_LIMBS];
    vor__limb mx[GEO_LIMBS];
    vor__limb my[GEO_LIMBS];
    int sx = magnitude_of(mx, x, GEO_LIMBS);
    int sy = magnitude_of(my, y, GEO_LIMBS);
    /* gcd(w, |x|, |y|): g = gcd(w, |x|), then gcd(g, |y|); gcd(a, 0) = a */
    vor__limb *others[2] = {mx, my};
    for (size_t i = 0; i < GEO_LIMBS; i++) {
        g[i] = w[i];
    }
    for (unsigned k = 0; k < 2u; k++) {
        for (size_t i = 0; i < GEO_LIMBS; i++) {
            u[i] = others[k][i];
        }
        if (vor__mw_sign(u, GEO_LIMBS) == 0) {
            continue;
        }
        unsigned shift = 0;
        while (is_even(g) && is_even(u)) {
            vor__mw_shr1(g, GEO_LIMBS);
            vor__mw_shr1(u, GEO_LIMBS);
            shift++;
        }
        while (is_even(g)) {
            vor__mw_shr1(g, GEO_LIMBS);
        }
        /* g odd; each round halves u at least once (bounded by its bits) */
        while (vor__mw_sign(u, GEO_LIMBS) != 0) {
            while (is_even(u)) {
                vor__mw_shr1(u, GEO_LIMBS);
            }
            if (vor__mw_compare(g, u, GEO_LIMBS) > 0) {
                vor__limb t;
                for (size_t i = 0; i < GEO_LIMBS; i++) {
                    t = g[i];
                    g[i] = u[i];
                    u[i] = t;
                }
            }
            vor__mw_sub(u, g, GEO_LIMBS);
        }
        for (unsigned i = 0; i < shift; i++) {
            vor__mw_shl1(g, GEO_LIMBS);
        }
    }
    /* divide all three by g (exact: the quotients fit 128 bits) */
    vor__limb *numbers[3] = {mx, my, w};
    for (unsigned k = 0; k < 3u; k++) {
        vor__limb step[GEO_LIMBS];
        for (size_t i = 0; i < GEO_LIMBS; i++) {
            step[i] = g[i];
        }
        /* shift the divisor up past the number (below 2^101: at most
         * 101 shifts, within the 160 bits), then subtract down */
        unsigned shifts = 0;
        while (vor__mw_compare(step, numbers[k], GEO_LIMBS) <= 0) {
            vor__mw_shl1(step, GEO_LIMBS);
            shifts++;
        }
        vor__limb q[GEO_LIMBS];
        vor__mw_from_u64(q, GEO_LIMBS, 0u);
        for (unsigned i = 0; i <= shifts; i++) {
            vor__mw_shl1(q, GEO_LIMBS);
            if (vor__mw_compare(numbers[k], step, GEO_LIMBS) >= 0) {
                vor__mw_sub(numbers[k], step, GEO_LIMBS);
                q[0] |= 1u;
            }
            vor__mw_shr1(step, GEO_LIMBS);
        }
        for (size_t i = 0; i < GEO_LIMBS; i++) {
            numbers[k][i] = q[i];
        }
    }
    for (size_t i = 0; i < GEO_LIMBS; i++) {
        x[i] = mx[i];
        y[i] = my[i];
    }
    if (sx < 0) {
        vor__mw_neg(x, GEO_LIMBS);
    }
    if (sy < 0) {
        vor__mw_neg(y, GEO_LIMBS);
    }
}

/* The low 128 bits of a as four 32-bit limbs, least significant first. */
static void export_number(uint32_t *out, const vor__limb *a)
{
    for (unsigned i = 0; i < VOR_EXACT_LIMBS; i++) {
        unsigned bit = 32u * i;
        out[i] = (uint32_t)(a[bit / VOR__LIMB_WIDTH] >> (bit % VOR__LIMB_WIDTH));
    }
}

/* A piece's vertex: exact in absolute coordinates, (x + 2 w s.x) / 2w
 * from the site's doubled frame, in lowest terms, and rounded. */
static void exact_vertex(const clip_frame_t *f, uint32_t a, uint32_t b, vor_exact_point_t *out)
{
    geo_point_t p;
    vor_vertex_t rounded;
    vor__limb t[GEO_LIMBS];
    const vor_point_t *s = f->cell.s;
    clip_vertex(f, a, b, &p);
    round_point(&p, s, &rounded);
    VOR_ASSERT(rounded.status == VOR_VERTEX_IN_RANGE); /* in the room */
    vor__mw_shl1(p.w, GEO_LIMBS); /* 2w < 2^66 */
    mul_i64(t, p.w, s->x);        /* < 2^97 */
    vor__mw_add(p.x, t, GEO_LIMBS);
    mul_i64(t, p.w, s->y);
    vor__mw_add(p.y, t, GEO_LIMBS);
    lowest_terms(p.x, p.y, p.w);
    out->point.x = rounded.point.x;
    out->point.y = rounded.point.y;
    export_number(out->x, p.x);
    export_number(out->y, p.y);
    export_number(out->w, p.w);
}

int vor_clip_next(vor_clip_t *clip, vor_exact_point_t *vertices, uint32_t capacity,
                  uint32_t *count)
{
    if ((clip == NULL) || (clip->d == NULL)) {
        return 0; /* a zeroed iterator, or a closed one */
    }
    if ((count == NULL) || ((vertices == NULL) && (capacity > 0u))) {
        clip->error = VOR_ERR_ARG;
        return 0;
    }
    if (clip->next_piece >= clip->pieces) {
        clip->error = VOR_OK;
        return 0;
    }
    uint32_t k = clip->next_piece;
    uint32_t r = clip->count[k];
    *count = r;
    if (r > capacity) {
        clip->error = VOR_ERR_BUFFER;
        return 0;
    }
    clip_frame_t f;
    frame_of(&f, clip);
    const uint32_t *lines = clip->lines + clip->start[k];
    for (uint32_t i = 0; i < r; i++) {
        exact_vertex(&f, lines[(i == 0u) ? (r - 1u) : (i - 1u)], lines[i], &vertices[i]);
    }
    clip->error = VOR_OK;
    clip->next_piece++;
    return 1;
}

int vor_clip_error(const vor_clip_t *clip)
{
    return (clip != NULL) ? clip->error : VOR_ERR_ARG;
}

/* One piece's boundary into the sums, a closed loop. A loop after the
 * first begins with a zero term that brings its first vertex's w^2 into
 * the denominator (add_edge of a point to itself), so that loops add up;
 * sum->vertices then counts the terms (one step of the width bound each:
 * a first loop of k vertices takes k, a later one k + 1). */
static void add_piece(centroid_sum_t *sum, const clip_frame_t *f, const uint32_t *lines,
                      uint32_t r)
{
    bool first_loop = sum->vertices == 0u;
    geo_point_t p;
    uint32_t i = 0;
    do { /* a piece has 3 lines at least: the first and last are set here */
        clip_vertex(f, lines[(i == 0u) ? (r - 1u) : (i - 1u)], lines[i], &p);
        if (first_loop) {
            add_vertex(sum, &p);
        } else {
            sum->vertices++;
            add_edge(sum, (i == 0u) ? &p : &sum->previous, &p);
            if (i == 0u) {
                copy_point(&sum->first, &p);
            }
            copy_point(&sum->previous, &p);
        }
        i++;
    } while (i < r);
    if (!first_loop) {
        sum->vertices++;
    }
    add_edge(sum, &sum->previous, &sum->first);
}

int vor_clip_centroid(const vor_clip_t *clip, uint32_t piece, void *scratch,
                      size_t scratch_bytes, vor_centroid_t *out)
{
    if ((clip == NULL) || (clip->d == NULL) || (out == NULL) ||
        ((scratch == NULL) && (scratch_bytes > 0u)) ||
        ((piece != VOR_CLIP_WHOLE) && (piece >= clip->pieces))) {
        return VOR_ERR_ARG;
    }
    uint32_t from = (piece == VOR_CLIP_WHOLE) ? 0u : piece;
    uint32_t to = (piece == VOR_CLIP_WHOLE) ? clip->pieces : (piece + 1u);
    uint32_t vertices = 0;
    uint32_t steps = 0;
    for (uint32_t k = from; k < to; k++) {
        vertices += clip->count[k];
        steps += clip->count[k] + ((k > from) ? 1u : 0u);
    }
    const vor_point_t *s = &clip->d->sites[clip->site];
    vor_centroid_t result;
    result.point.x = s->x;
    result.point.y = s->y;
    result.area = 0;
    result.vertices = 0;
    if (vertices == 0u) {
        write_centroid(out, &result);
        return VOR_OK;
    }
    size_t usable;
    size_t stride;
    vor__limb *limbs = align_scratch(scratch, scratch_bytes, &usable);
    if (!scratch_fits(usable, steps, &stride)) {
        out->vertices = steps;
        return VOR_ERR_BUFFER;
    }
    clip_frame_t f;
    frame_of(&f, clip);
    centroid_sum_t sum;
    begin_sums(&sum, limbs, stride);
    for (uint32_t k = from; k < to; k++) {
        add_piece(&sum, &f, clip->lines + clip->start[k], clip->count[k]);
    }
    bool positive = round_sums(&sum, sum.vertices, s, &result);
    VOR_ASSERT(positive); /* every piece has a positive area */
    (void)positive;
    result.vertices = vertices;
    write_centroid(out, &result);
    return VOR_OK;
}
