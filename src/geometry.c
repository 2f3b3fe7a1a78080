/*
 * geometry.c - the Voronoi diagram's geometry, read from the Delaunay mesh:
 * vertices (circumcentres), edges and the convex hull. Read-only, like
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
 * docs/design.md ("Voronoi geometry") has the proofs.
 *
 * Arithmetic (seed 003 section 2.1: translate to one of the sites first,
 * here so that the widths stay small). Around a site s, coordinates are
 * taken relative to s and doubled, so that every line of a cell has integer
 * coefficients: a line is a x + b y = c, its half-plane a x + b y <= c.
 *   bisector of s and n (e = n - s):  a = e.x, b = e.y, c = |e|^2
 *       |a|, |b| <= 2^32 - 1 (differences of int32), 0 <= c < 2^65
 *   box side, e.g. x >= x0:           a = -1, b = 0, c = -2 (x0 - s.x)
 *       |c| < 2^33
 * Two lines meet at (x / w, y / w) with w = a1 b2 - a2 b1 (|w| < 2^65),
 * x = c1 b2 - c2 b1 and y = a1 c2 - a2 c1 (|x|, |y| < 2 2^65 2^32 = 2^98).
 * A point is inside a third line's half-plane when a x + b y - c w <= 0
 * (w > 0): |a x|, |b y|, |c w| < 2^130, the sum < 2^132. Every value
 * therefore fits in 160-bit two's complement (GEO_LIMBS), and each
 * decision is the exact sign of a 3x3 determinant of line coefficients.
 */
#include "mesh.h"

#define GEO_LIMBS VOR__LIMBS(160)
#define U64_LIMBS VOR__LIMBS(64)

/* A line a x + b y = c in a site's doubled frame, with an integer point
 * (px, py) on it for the test of a parallel line. */
typedef struct geo_line {
    int64_t a, b;
    vor__limb c[GEO_LIMBS];
    int64_t px, py;
} geo_line_t;

/* A point (x / w, y / w), w > 0, in the same frame. */
typedef struct geo_point {
    vor__limb x[GEO_LIMBS];
    vor__limb y[GEO_LIMBS];
    vor__limb w[GEO_LIMBS];
} geo_point_t;

static inline uint32_t magnitude32(int64_t v)
{
    /* |v| <= 2^32 - 1 for a difference of two int32 */
    return (uint32_t)(v < 0 ? -v : v);
}

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
    int64_t ex = (int64_t)n->x - s->x, ey = (int64_t)n->y - s->y;
    uint32_t mx = magnitude32(ex), my = magnitude32(ey);
    vor__limb t[GEO_LIMBS];
    l->a = ex;
    l->b = ey;
    l->px = ex; /* the midpoint of s and n, doubled: e */
    l->py = ey;
    vor__mw_from_u64(l->c, GEO_LIMBS, vor__mul_u32(mx, mx));
    vor__mw_from_u64(t, GEO_LIMBS, vor__mul_u32(my, my));
    vor__mw_add(l->c, t, GEO_LIMBS); /* < 2^65 */
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

/* origin + floor(v / (2 w) + 1/2): the rounded coordinate of v / w in a
 * site's doubled frame, |v| < 2^98, 0 < w < 2^65. Returns false, with the
 * result saturated, when it is outside int32. The quotient is found by
 * shift and subtract (no divide instruction anywhere): if it fits in int32
 * after adding origin, its magnitude is below 2^33, so 33 steps decide it
 * and a larger one is out of range. */
static bool round_coordinate(const vor__limb *v, const vor__limb *w, int32_t origin,
                             int32_t *out)
{
    vor__limb rest[GEO_LIMBS], step[GEO_LIMBS];
    /* floor(v / 2w + 1/2) = floor((v + w) / 2w); |v + w| < 2^99 */
    for (size_t i = 0; i < GEO_LIMBS; i++) {
        rest[i] = v[i];
        step[i] = w[i];
    }
    vor__mw_add(rest, w, GEO_LIMBS);
    bool negative = vor__mw_sign(rest, GEO_LIMBS) < 0;
    if (negative) {
        vor__mw_neg(rest, GEO_LIMBS);
    }
    for (unsigned k = 0; k < 34u; k++) { /* 2w 2^33 < 2^99 */
        vor__mw_shl1(step, GEO_LIMBS);
    }
    int64_t q;
    if (vor__mw_compare(rest, step, GEO_LIMBS) >= 0) {
        q = negative ? -((int64_t)1 << 33) - 1 : ((int64_t)1 << 33); /* |q| >= 2^33 */
    } else {
        uint64_t quotient = 0;
        for (unsigned k = 0; k < 33u; k++) { /* quotient bits 32 .. 0 */
            vor__mw_shr1(step, GEO_LIMBS);
            quotient <<= 1;
            if (vor__mw_compare(rest, step, GEO_LIMBS) >= 0) {
                vor__mw_sub(rest, step, GEO_LIMBS);
                quotient |= 1u;
            }
        }
        bool exact = vor__mw_sign(rest, GEO_LIMBS) == 0;
        /* floor of a negative quotient: -ceil(|n| / d) */
        q = negative ? -(int64_t)quotient - (exact ? 0 : 1) : (int64_t)quotient;
    }
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

/* The rounded vertex of p (in the frame of `origin`). */
static void round_point(const geo_point_t *p, const vor_point_t *origin, vor_vertex_t *out)
{
    bool x_ok = round_coordinate(p->x, p->w, origin->x, &out->point.x);
    bool y_ok = round_coordinate(p->y, p->w, origin->y, &out->point.y);
    out->status = (x_ok && y_ok) ? VOR_VERTEX_IN_RANGE : VOR_VERTEX_OUT_OF_RANGE;
}

/* ------------------------------------------------------------------ */
/* Vertices                                                            */

int vor_circumcentre(const vor_point_t *a, const vor_point_t *b, const vor_point_t *c,
                     vor_vertex_t *out)
{
    if (a == NULL || b == NULL || c == NULL || out == NULL) {
        return VOR_ERR_ARG;
    }
    geo_line_t lb, lc;
    geo_point_t p;
    bisector(&lb, a, b);
    bisector(&lc, a, c);
    /* the bisectors of a with b and c are parallel exactly when a, b, c
     * are collinear (w = cross(b - a, c - a)) */
    if (!intersect(&p, &lb, &lc)) {
        out->point.x = 0;
        out->point.y = 0;
        out->status = VOR_VERTEX_AT_INFINITY;
        return VOR_OK;
    }
    round_point(&p, a, out);
    return VOR_OK;
}

int vor_voronoi_vertex(const vor_t *d, uint32_t a, uint32_t b, uint32_t c, vor_vertex_t *out)
{
    if (d == NULL || out == NULL || a >= d->site_count || b >= d->site_count ||
        c >= d->site_count) {
        return VOR_ERR_ARG;
    }
    return vor_circumcentre(&d->sites[a], &d->sites[b], &d->sites[c], out);
}

/* ------------------------------------------------------------------ */
/* The true Voronoi edge of a Delaunay edge                            */

static int sign64(int64_t v)
{
    return (v > 0) - (v < 0);
}

/* For collinear a, m, b: does m lie strictly inside the segment ab? Then
 * the steps a -> m and m -> b point the way a -> b does, coordinate by
 * coordinate (no products needed). */
static bool strictly_between(const vor_point_t *a, const vor_point_t *m, const vor_point_t *b)
{
    int sx = sign64((int64_t)b->x - a->x), sy = sign64((int64_t)b->y - a->y);
    return sign64((int64_t)m->x - a->x) == sx && sign64((int64_t)m->y - a->y) == sy &&
           sign64((int64_t)b->x - m->x) == sx && sign64((int64_t)b->y - m->y) == sy;
}

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
 */
static bool true_edge(const vor_point_t *s, uint32_t p, uint32_t q, uint32_t r, uint32_t l,
                      bool *has_start, bool *has_end)
{
    *has_start = false;
    *has_end = false;
    if (r != VOR__INFINITE) {
        int o = vor_orient2d(&s[p], &s[q], &s[r], NULL);
        VOR_ASSERT(o <= 0);
        if (o != 0) {
            *has_start = true;
        } else if (strictly_between(&s[p], &s[r], &s[q])) {
            return false;
        }
    }
    if (l != VOR__INFINITE) {
        int o = vor_orient2d(&s[p], &s[q], &s[l], NULL);
        VOR_ASSERT(o >= 0);
        if (o != 0) {
            *has_end = true;
        } else if (strictly_between(&s[p], &s[l], &s[q])) {
            return false;
        }
    }
    if (*has_start && *has_end && vor_incircle(&s[p], &s[q], &s[l], &s[r], NULL) == 0) {
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
        if (v[i] != p && v[i] != q) {
            return v[i];
        }
    }
    return v[2];
}

/* floor(v / 2) for the rounded midpoint, without a shift of a negative */
static int32_t floor_half(int64_t v)
{
    return (int32_t)((v - (int64_t)((uint64_t)v & 1u)) / 2);
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
        vor_circumcentre(&s[p], &s[q], &s[r], &e->from);
        if (has_end) {
            vor_circumcentre(&s[p], &s[q], &s[l], &e->to);
        }
        e->kind = has_end ? VOR_EDGE_SEGMENT : VOR_EDGE_RAY;
    } else {
        e->kind = VOR_EDGE_LINE;
        e->from.point.x = floor_half((int64_t)s[p].x + s[q].x + 1);
        e->from.point.y = floor_half((int64_t)s[p].y + s[q].y + 1);
        e->from.status = VOR_VERTEX_IN_RANGE;
    }
}

void vor_edges_begin(vor_edge_iter_t *it, const vor_t *d)
{
    it->d = d;
    it->slot = 0;
    it->edge = 0;
}

int vor_edges_next(vor_edge_iter_t *it, vor_edge_t *edge)
{
    const vor_t *d = it->d;
    if (d->vertex_count < 2u) {
        return 0;
    }
    uint32_t end = vor__used_slots_end(d);
    /* each used slot once, each of its three edges once: ends at `end` */
    for (uint32_t slot = vor__next_used_slot(d, it->slot); slot < end;
         slot = vor__next_used_slot(d, slot + 1u)) {
        const vor__tri_t *t = &d->triangles[slot];
        vor_index_t v[3];
        vor__vertices(t, v);
        unsigned first = (slot == it->slot) ? it->edge : 0u;
        for (unsigned i = first; i < 3u; i++) {
            uint32_t p = v[vor__next(i)], q = v[vor__prev(i)], l = v[i];
            if (p == VOR__INFINITE || q == VOR__INFINITE) {
                continue;
            }
            uint32_t other = t->n[i];
            uint32_t r = third_vertex(&d->triangles[other], p, q);
            /* each edge once: from its finite side, or the smaller slot */
            bool ghost_here = l == VOR__INFINITE, ghost_there = r == VOR__INFINITE;
            if (ghost_here != ghost_there ? ghost_here : other < slot) {
                continue;
            }
            bool has_start, has_end;
            if (!true_edge(d->sites, p, q, r, l, &has_start, &has_end)) {
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

static bool lower(const vor_point_t *a, const vor_point_t *b)
{
    return a->y < b->y || (a->y == b->y && a->x < b->x);
}

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

/* The site with the smallest (y, x): from any site, step to a lower
 * neighbour while there is one. In a triangulation a site that is not the
 * lowest has a lower neighbour (the direction to the lowest site lies in
 * one of its triangles), and each step is strictly lower, so this ends
 * within vertex_count steps at the lowest site. */
static uint32_t lowest_site(const vor_t *d)
{
    const vor_point_t *s = d->sites;
    uint32_t best = d->last_site;
    for (uint32_t step = 0; step < d->vertex_count; step++) {
        uint32_t from = best, n;
        vor_neighbour_iter_t it;
        vor_neighbours_begin(&it, d, from);
        while (vor_neighbours_next(&it, &n)) {
            if (lower(&s[n], &s[best])) {
                best = n;
            }
        }
        if (best == from) {
            break;
        }
    }
    return best;
}

void vor_hull_begin(vor_hull_iter_t *it, const vor_t *d)
{
    it->d = d;
    it->left = 0;
    it->ghost = VOR__NONE;
    it->collinear = 0;
    it->site = it->first = d->last_site;
    if (d->vertex_count < 2u) {
        it->left = d->vertex_count; /* one site: itself */
        return;
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
            return; /* only on a broken mesh */
        }
        if (vor__vertex(t, vor__next(i)) == VOR__INFINITE) {
            it->ghost = slot;
            break;
        }
        slot = t->n[vor__next(i)];
    }
    if (it->ghost == VOR__NONE) {
        return;
    }
    /* all sites are collinear exactly when the hull's corners are: one
     * turn around the hull (at most vertex_count edges) */
    uint32_t w, u, next, g = it->ghost;
    ghost_edge(d, g, &w, &u, &next);
    uint32_t second = u;
    it->collinear = 1;
    for (uint32_t step = 0; step < d->vertex_count && it->collinear; step++) {
        ghost_edge(d, next, &w, &u, &next);
        if (vor_orient2d(&s[low], &s[second], &s[u], NULL) != 0) {
            it->collinear = 0;
        }
        if (next == g) {
            break;
        }
    }
    it->site = it->first = low;
    /* collinear: every site once, up the line; else back to the start */
    it->left = it->collinear ? d->vertex_count : d->vertex_count + 1u;
}

int vor_hull_next(vor_hull_iter_t *it, uint32_t *site)
{
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
     * edge have a Voronoi ray in common), else u and the next hull edge */
    const vor_point_t *s = d->sites;
    uint32_t w, u, next, n, best = VOR__NONE;
    ghost_edge(d, it->ghost, &w, &u, &next);
    vor_neighbour_iter_t ni;
    vor_neighbours_begin(&ni, d, it->site);
    while (vor_neighbours_next(&ni, &n)) {
        if (n != u && vor_orient2d(&s[it->site], &s[u], &s[n], NULL) == 0 &&
            strictly_between(&s[it->site], &s[n], &s[u]) &&
            (best == VOR__NONE || strictly_between(&s[it->site], &s[n], &s[best]))) {
            best = n;
        }
    }
    if (best != VOR__NONE) {
        it->site = best;
    } else {
        it->site = u;
        it->ghost = next;
    }
    if (!it->collinear && it->site == it->first) {
        it->left = 0;
    }
    return 1;
}
