/* SPDX-License-Identifier: MIT */
/*
 * interpolate.c - natural-neighbour (Sibson) coordinates and
 * interpolation, exact. Read-only, like queries.c and geometry.c.
 * docs/design/interpolation.md has the formulas and the proofs.
 *
 * The natural neighbours of q are found from the mesh with the exact,
 * unperturbed predicates: a triangle is "in conflict" with q when it is
 * a proper triangle (not at infinity, not flat) whose circumcircle holds
 * q strictly inside (incircle > 0). This is the conflict region of the
 * true diagram, whatever triangulation the perturbation chose:
 *   - sites that are cocircular share one circle, so the triangles the
 *     perturbation made of their polygon are all in conflict or none is,
 *     and their circumcentres are one point: the areas below do not
 *     depend on the diagonals chosen;
 *   - a circle through q (incircle = 0) is left out: its centre is then a
 *     vertex of q's new cell as well, so the pieces it would add have
 *     zero area. A site whose only contact with q's cell is such a point
 *     has weight 0 and is not listed.
 * So the coordinates are those of the true Voronoi diagram: one answer.
 *
 * q strictly inside the convex hull: the region is star-shaped from q
 * (walking from a conflict triangle toward q stays in conflict: the
 * triangulation is Delaunay, non-strictly, across every edge), every
 * vertex of it is on its boundary (a site with all its triangles in
 * conflict would have its whole cell, the site included, nearer to q),
 * and the nearest site is one of them (its cell loses area to q, and the
 * piece lost is a convex polygon with a Voronoi vertex of the site on
 * q's side). The boundary is walked counterclockwise around q: p_0 ..
 * p_{k-1}, and around each p_i the conflict triangles T_in .. T_out
 * between its two boundary edges. Then, with c_i the circumcentre of
 * (q, p_i, p_{i+1}) and C_T that of triangle T:
 *   q's new cell           the polygon c_0 .. c_{k-1} (counterclockwise)
 *   area taken from p_i    the polygon c_{i-1}, C_{T_in} .., C_{T_out}, c_i
 *                          (clockwise: the old cell's boundary backwards)
 * both by the shoelace formula over one common denominator, the product
 * D of the 2k - 2 points' denominators (k of the c_i, k - 2 triangles).
 * The walk meets the hull where a boundary edge has a triangle at
 * infinity or a flat one behind it: q strictly outside that edge is
 * outside the hull; on it, q is on the hull edge, where the coordinates
 * are linear along the edge.
 *
 * Arithmetic: points relative to q, P = (X, Y) / W with W > 0. A
 * circumcentre of (o, b, c) relative to o, with b' = b - o and c' = c - o
 * (|.| <= 2^32 - 1 a coordinate), is
 *   (|b'|^2 c'_y - |c'|^2 b'_y, |c'|^2 b'_x - |b'|^2 c'_x) / (2 b' x c')
 * and relative to q it adds (o - q) W: |X|, |Y| < 2^99 + 2^100 < 2^101,
 * 0 < W < 2^67, all in POINT_LIMBS (192 bits). A shoelace term
 * X_a Y_b - X_b Y_a is below 2^203 (CROSS_LIMBS), times the other 2k - 4
 * denominators below 2^(132 k - 61), and a sum of at most 2^32 of them
 * below 2^(132 k - 29): number_limbs(k), 132 k + 64 bits, holds every
 * number, the value's numerator (values below 2^31 in magnitude times
 * weights below 2^(132 k - 29), k < 2^21 of them) and the denominator
 * shifted 32 bits for the rounding division.
 */
#include "mesh.h"
#include "multiword.h"
#include "predicates.h"

#define POINT_LIMBS VOR__LIMBS(192u)
#define CROSS_LIMBS VOR__LIMBS(224u)
#define U64_LIMBS VOR__LIMBS(64u)

/* 64-bit words of one number for k neighbours (the macro's unit), for
 * k <= VOR_MAX_SITES < 2^22: below 2^24. */
static uint32_t number_words(uint32_t k)
{
    return ((k * 132u) + 127u) >> 6;
}

/* VOR_SIBSON_SCRATCH_BYTES(k) without the 8 bytes of alignment, in 64
 * bits so that no k overflows it, with 32 x 32-bit products (a 64-bit
 * multiply is a runtime call on Cortex-M0). */
static uint64_t scratch_needed(uint32_t k)
{
    return vor__mul_u32((k * 2u) + 5u, 8u * number_words(k)) + vor__mul_u32(k, 172u) + 4u;
}

/* The caller's scratch, cut up for k neighbours. */
typedef struct ip_space {
    vor__limb *numbers; /* weights [0, k), the denominator k, then temporaries */
    vor__limb *points;  /* (2k - 2) x (X, Y, W), POINT_LIMBS each */
    uint32_t *ids;      /* [k] the natural neighbours, counterclockwise */
    uint32_t *tags;     /* [2k] a point's triangle slot (c_i: none) */
    uint32_t *seq;      /* [3k] the conflict triangles' points around each p_i */
    uint32_t *start;    /* [k + 1] where p_{i+1}'s run in seq begins */
    uint32_t *out;      /* (k + 1) numbers of 2 words each 64 bits */
    size_t width;       /* limbs of a number */
    uint32_t k;
    uint32_t points_used;
    uint32_t seq_used;
    bool laplace;       /* Laplace's coordinates: no triangles recorded */
} ip_space_t;

#define NO_TAG 0xFFFFFFFFu

static vor__limb *number(const ip_space_t *sp, uint32_t i)
{
    return sp->numbers + ((size_t)i * sp->width);
}

static vor__limb *point_part(const ip_space_t *sp, uint32_t i, unsigned part)
{
    return sp->points + (((size_t)i * 3u) + part) * POINT_LIMBS;
}

/* Cuts scratch for k neighbours; false when it is too small. */
static bool cut_scratch(ip_space_t *sp, void *scratch, size_t bytes, uint32_t k)
{
    size_t skip = (size_t)(0u - (uintptr_t)scratch) & 7u;
    uint64_t usable = (bytes > skip) ? (uint64_t)(bytes - skip) : 0u;
    if ((scratch == NULL) || (scratch_needed(k) > usable)) {
        return false;
    }
    size_t words = number_words(k);
    unsigned char *base = (unsigned char *)scratch + skip;
    size_t points_at = ((size_t)k + 4u) * words * 8u;
    size_t out_at = points_at + ((size_t)k * 2u * 3u * 24u);
    size_t ids_at = out_at + (((size_t)k + 1u) * words * 8u);
    sp->width = words * (8u / sizeof(vor__limb));
    sp->k = k;
    sp->numbers = (vor__limb *)(void *)base;
    sp->points = (vor__limb *)(void *)(base + points_at);
    sp->out = (uint32_t *)(void *)(base + out_at);
    sp->ids = (uint32_t *)(void *)(base + ids_at);
    sp->tags = sp->ids + k;
    sp->seq = sp->tags + (2u * (size_t)k);
    sp->start = sp->seq + (3u * (size_t)k);
    sp->points_used = 0;
    sp->seq_used = 0;
    sp->laplace = false;
    return true;
}

/* ------------------------------------------------------------------ */
/* Exact arithmetic on the toolkit's numbers                          */

/* r = a b over nr limbs for two's complement a (na limbs) and b (nb
 * limbs), at most POINT_LIMBS each, through their magnitudes (the
 * toolkit's product is exact for narrower operands only when they are
 * non-negative). */
static void signed_product(vor__limb *r, size_t nr, const vor__limb *a, size_t na,
                           const vor__limb *b, size_t nb)
{
    vor__limb ma[POINT_LIMBS];
    vor__limb mb[POINT_LIMBS];
    bool a_negative = vor__mw_sign(a, na) < 0;
    bool b_negative = vor__mw_sign(b, nb) < 0;
    vor__mw_copy(ma, a, na);
    vor__mw_copy(mb, b, nb);
    if (a_negative) {
        vor__mw_neg(ma, na);
    }
    if (b_negative) {
        vor__mw_neg(mb, nb);
    }
    vor__mw_mul(r, nr, ma, na, mb, nb);
    if (a_negative != b_negative) {
        vor__mw_neg(r, nr);
    }
}

/* r = a k over POINT_LIMBS, for a >= 0 and |k| < 2^63. */
static void times_i64(vor__limb *r, const vor__limb *a, int64_t k)
{
    vor__limb m[U64_LIMBS];
    vor__mw_from_u64(m, U64_LIMBS, (k < 0) ? (0u - (uint64_t)k) : (uint64_t)k);
    vor__mw_mul(r, POINT_LIMBS, a, POINT_LIMBS, m, U64_LIMBS);
    if (k < 0) {
        vor__mw_neg(r, POINT_LIMBS);
    }
}

/* r = e.x f.x + e.y f.y over POINT_LIMBS for differences of int32
 * coordinates (|.| < 2^33, the sum below 2^67). */
static void dot(vor__limb *r, int64_t ex, int64_t ey, int64_t fx, int64_t fy)
{
    vor__limb a[POINT_LIMBS];
    vor__limb b[POINT_LIMBS];
    vor__limb t[POINT_LIMBS];
    vor__mw_from_i64(a, POINT_LIMBS, ex);
    vor__mw_from_i64(b, POINT_LIMBS, fx);
    signed_product(r, POINT_LIMBS, a, POINT_LIMBS, b, POINT_LIMBS);
    vor__mw_from_i64(a, POINT_LIMBS, ey);
    vor__mw_from_i64(b, POINT_LIMBS, fy);
    signed_product(t, POINT_LIMBS, a, POINT_LIMBS, b, POINT_LIMBS);
    vor__mw_add(r, t, POINT_LIMBS);
}

/* The circumcentre of (o, b, c), o b c not collinear, relative to q:
 * (X, Y) / W with W > 0 (the formula and bounds at the top). */
static void circumcentre(vor__limb *x, vor__limb *y, vor__limb *w, const vor_point_t *o,
                         const vor_point_t *b, const vor_point_t *c, const vor_point_t *q)
{
    int64_t bx = (int64_t)b->x - o->x;
    int64_t by = (int64_t)b->y - o->y;
    int64_t cx = (int64_t)c->x - o->x;
    int64_t cy = (int64_t)c->y - o->y;
    vor__limb nb[POINT_LIMBS];
    vor__limb nc[POINT_LIMBS];
    vor__limb t[POINT_LIMBS];
    dot(nb, bx, by, bx, by); /* |b'|^2 < 2^65 */
    dot(nc, cx, cy, cx, cy);
    times_i64(x, nb, cy);
    times_i64(t, nc, by);
    vor__mw_sub(x, t, POINT_LIMBS);
    times_i64(y, nc, bx);
    times_i64(t, nb, cx);
    vor__mw_sub(y, t, POINT_LIMBS);
    dot(w, bx, -by, cy, cx); /* b'x c'y - b'y c'x */
    vor__mw_shl1(w, POINT_LIMBS);
    if (vor__mw_sign(w, POINT_LIMBS) < 0) {
        vor__mw_neg(x, POINT_LIMBS);
        vor__mw_neg(y, POINT_LIMBS);
        vor__mw_neg(w, POINT_LIMBS);
    }
    /* relative to q: + (o - q) W */
    times_i64(t, w, (int64_t)o->x - q->x);
    vor__mw_add(x, t, POINT_LIMBS);
    times_i64(t, w, (int64_t)o->y - q->y);
    vor__mw_add(y, t, POINT_LIMBS);
}

/* ------------------------------------------------------------------ */
/* The conflict region                                                 */

/* A triangle at infinity, or a flat one (collinear sites on the hull):
 * no circle, and behind it the hull's boundary. */
static bool hull_side(const vor_t *d, vor_index_t slot)
{
    vor_index_t v[3];
    vor__vertices(&d->triangles[slot], v);
    if ((v[0] == VOR__INFINITE) || (v[1] == VOR__INFINITE) || (v[2] == VOR__INFINITE)) {
        return true;
    }
    return vor__orient2d_sign(&d->sites[v[0]], &d->sites[v[1]], &d->sites[v[2]]) == 0;
}

/* Is the triangle in slot a proper one whose circumcircle holds q
 * strictly inside? (exact, unperturbed: see the top) */
static bool in_conflict(const vor_t *d, vor_index_t slot, const vor_point_t *q)
{
    if (hull_side(d, slot)) {
        return false;
    }
    vor_index_t v[3];
    vor__vertices(&d->triangles[slot], v);
    /* a proper triangle's perturbed orientation is its true one: CCW */
    return vor__incircle_sign(&d->sites[v[0]], &d->sites[v[1]], &d->sites[v[2]], q) > 0;
}

/* The outcome of the boundary walk. */
enum ip_walk {
    WALK_INSIDE = 0,  /* q strictly inside the hull: k neighbours */
    WALK_OUTSIDE = 1, /* q strictly outside a hull edge */
    WALK_EDGE = 2,    /* q strictly inside hull edge (edge[0], edge[1]) */
    WALK_BROKEN = 3   /* the step bound ran out: only on a broken mesh */
};

/* Is p strictly between a and b, for p on the line ab? */
static bool between(const vor_point_t *p, const vor_point_t *a, const vor_point_t *b)
{
    return (vor__closer_sign(a, p, b, NULL) < 0) && (vor__closer_sign(b, p, a, NULL) < 0);
}

/* Records the circumcentre of triangle `slot` in p_{i+1}'s run (once per
 * triangle among the points). */
static void record_triangle(const vor_t *d, ip_space_t *sp, vor_index_t slot, const vor_point_t *q)
{
    uint32_t j = sp->k;
    while ((j < sp->points_used) && (sp->tags[j] != slot)) {
        j++;
    }
    if (j == sp->points_used) {
        if (j >= (2u * sp->k)) {
            return; /* only on a broken mesh: the walk reports it */
        }
        vor_index_t v[3];
        vor__vertices(&d->triangles[slot], v);
        circumcentre(point_part(sp, j, 0), point_part(sp, j, 1), point_part(sp, j, 2),
                     &d->sites[v[0]], &d->sites[v[1]], &d->sites[v[2]], q);
        sp->tags[j] = slot;
        sp->points_used++;
    }
    if (sp->seq_used < (3u * sp->k)) {
        sp->seq[sp->seq_used] = j;
        sp->seq_used++;
    }
}

/*
 * Walks the conflict region's boundary counterclockwise from edge
 * (u0, v0) of conflict triangle t0, counting its vertices in *k; with sp,
 * records them and each one's run of triangles. Around each vertex v the
 * turn goes clockwise from T_in (the triangle of the edge into v) across
 * conflict triangles to T_out, whose next edge (v, x) has no conflict
 * triangle behind it. Every boundary edge is visited once and each turn
 * stays in v's fan, so sum of degrees <= 6n steps bound it.
 */
static enum ip_walk walk_boundary(const vor_t *d, const vor_point_t *q, vor_index_t t0,
                                  vor_index_t u0, vor_index_t v0, ip_space_t *sp, uint32_t *k,
                                  uint32_t edge[2])
{
    const vor_point_t *s = d->sites;
    vor_index_t t = t0;
    vor_index_t u = u0;
    vor_index_t v = v0;
    uint32_t count = 0;
    uint32_t steps = (6u * d->vertex_count) + 6u;
    for (;;) {
        if (sp != NULL) {
            if (count >= sp->k) {
                return WALK_BROKEN;
            }
            sp->ids[count] = u;
            sp->start[count] = sp->seq_used;
        }
        count++;
        vor_index_t x;
        for (;;) {
            if (steps == 0u) {
                return WALK_BROKEN;
            }
            steps--;
            const vor__tri_t *tri = &d->triangles[t];
            unsigned iv = vor__vertex_index(tri, v);
            if (iv == 3u) {
                return WALK_BROKEN;
            }
            if ((sp != NULL) && !sp->laplace) {
                record_triangle(d, sp, t, q);
            }
            x = vor__vertex(tri, vor__next(iv));
            vor_index_t across = tri->n[vor__prev(iv)];
            if (in_conflict(d, across, q)) {
                t = across;
                continue;
            }
            if (hull_side(d, across)) {
                int side = vor__orient2d_sign(&s[v], &s[x], q);
                if (side < 0) {
                    return WALK_OUTSIDE;
                }
                if (side == 0) {
                    /* on the line, inside the circle: inside the edge.
                     * No site lies strictly between v and x: it would
                     * lie strictly inside the circle of the Delaunay
                     * triangle t, so q's neighbours are v and x. */
                    edge[0] = v;
                    edge[1] = x;
                    return WALK_EDGE;
                }
            }
            break;
        }
        u = v;
        v = x;
        if ((t == t0) && (u == u0)) {
            break;
        }
    }
    if (sp != NULL) {
        sp->start[count] = sp->seq_used;
    }
    *k = count;
    return WALK_INSIDE;
}

/* A conflict triangle around site c (the nearest site), and the boundary
 * edge (u, c) of the conflict region it leads to turning
 * counterclockwise around c. False when no triangle around c is in
 * conflict. */
static bool find_start(const vor_t *d, const vor_point_t *q, vor_index_t c, vor_index_t *t0,
                       vor_index_t *u0)
{
    vor_index_t slot = c;
    uint32_t left = d->vertex_count + 1u;
    bool found = false;
    while (left > 0u) { /* clockwise around c: at most its degree steps */
        left--;
        if (in_conflict(d, slot, q)) {
            found = true;
            break;
        }
        const vor__tri_t *tri = &d->triangles[slot];
        slot = tri->n[vor__prev(vor__vertex_index(tri, c))];
        if (slot == c) {
            return false;
        }
    }
    if (!found) {
        return false;
    }
    left = d->vertex_count + 1u;
    while (left > 0u) { /* counterclockwise to the region's edge */
        left--;
        const vor__tri_t *tri = &d->triangles[slot];
        unsigned i = vor__vertex_index(tri, c);
        vor_index_t next = tri->n[vor__next(i)];
        if (!in_conflict(d, next, q)) {
            *t0 = slot;
            *u0 = vor__vertex(tri, vor__prev(i));
            return true;
        }
        slot = next;
    }
    return false;
}

/* ------------------------------------------------------------------ */
/* The exact areas                                                     */

/* The product of every point's denominator but those of points a and b
 * (D / (W_a W_b)), in one of two temporaries; *used = its live limbs. */
static const vor__limb *product_except(const ip_space_t *sp, uint32_t a, uint32_t b, size_t *used)
{
    vor__limb *r = number(sp, sp->k + 1u);
    vor__limb *spare = number(sp, sp->k + 2u);
    size_t live = 1;
    vor__mw_from_u64(r, sp->width, 1u);
    for (uint32_t j = 0; j < sp->points_used; j++) {
        if ((j == a) || (j == b)) {
            continue;
        }
        vor__mw_mul(spare, sp->width, r, live, point_part(sp, j, 2), POINT_LIMBS);
        vor__limb *swap = r;
        r = spare;
        spare = swap;
        live = ((live + POINT_LIMBS) < sp->width) ? (live + POINT_LIMBS) : sp->width;
    }
    *used = live;
    return r;
}

/* number `target` += (X_a Y_b - X_b Y_a) D / (W_a W_b), or -= when
 * `backwards`: the shoelace term of the edge from point a to point b. */
static void add_edge(const ip_space_t *sp, uint32_t target, uint32_t a, uint32_t b, bool backwards)
{
    vor__limb cross[CROSS_LIMBS];
    vor__limb t[CROSS_LIMBS];
    if (a == b) {
        return; /* a point repeated: no area */
    }
    signed_product(cross, CROSS_LIMBS, point_part(sp, a, 0), POINT_LIMBS, point_part(sp, b, 1),
                   POINT_LIMBS);
    signed_product(t, CROSS_LIMBS, point_part(sp, b, 0), POINT_LIMBS, point_part(sp, a, 1),
                   POINT_LIMBS);
    vor__mw_sub(cross, t, CROSS_LIMBS);
    bool negative = vor__mw_sign(cross, CROSS_LIMBS) < 0;
    if (negative) {
        vor__mw_neg(cross, CROSS_LIMBS);
    }
    size_t used;
    const vor__limb *other = product_except(sp, a, b, &used);
    vor__limb *term = number(sp, sp->k + 3u);
    vor__mw_mul(term, sp->width, cross, CROSS_LIMBS, other, used);
    if (negative != backwards) {
        vor__mw_sub(number(sp, target), term, sp->width);
    } else {
        vor__mw_add(number(sp, target), term, sp->width);
    }
}

/* Sibson's weights of the k neighbours the walk recorded, and their sum
 * computed on its own: twice the areas over D (the top). */
static void sibson_areas(const vor_t *d, ip_space_t *sp, const vor_point_t *q)
{
    uint32_t k = sp->k;
    for (uint32_t i = 0; i < k; i++) {
        uint32_t next = ((i + 1u) == k) ? 0u : (i + 1u);
        circumcentre(point_part(sp, i, 0), point_part(sp, i, 1), point_part(sp, i, 2), q,
                     &d->sites[sp->ids[i]], &d->sites[sp->ids[next]], q);
        sp->tags[i] = NO_TAG;
    }
    for (uint32_t i = 0; i <= k; i++) {
        vor__mw_from_u64(number(sp, i), sp->width, 0u);
    }
    for (uint32_t i = 0; i < k; i++) { /* q's new cell, counterclockwise */
        add_edge(sp, k, i, ((i + 1u) == k) ? 0u : (i + 1u), false);
    }
    for (uint32_t i = 0; i < k; i++) { /* p_{i+1}'s loss, clockwise */
        uint32_t owner = ((i + 1u) == k) ? 0u : (i + 1u);
        uint32_t from = i;
        for (uint32_t j = sp->start[i]; j < sp->start[i + 1u]; j++) {
            add_edge(sp, owner, from, sp->seq[j], true);
            from = sp->seq[j];
        }
        add_edge(sp, owner, from, owner, true);
        add_edge(sp, owner, owner, i, true);
    }
}

/* number `target` += n D / (X_a X_b) (a == b: D / X_a), n signed of
 * POINT_LIMBS limbs, X_j the points' third parts. */
static void add_scaled(const ip_space_t *sp, uint32_t target, const vor__limb *n, uint32_t a,
                       uint32_t b)
{
    vor__limb magnitude[POINT_LIMBS];
    vor__mw_copy(magnitude, n, POINT_LIMBS);
    bool negative = vor__mw_sign(magnitude, POINT_LIMBS) < 0;
    if (negative) {
        vor__mw_neg(magnitude, POINT_LIMBS);
    }
    size_t used;
    const vor__limb *other = product_except(sp, a, b, &used);
    vor__limb *term = number(sp, sp->k + 3u);
    vor__mw_mul(term, sp->width, magnitude, POINT_LIMBS, other, used);
    if (negative) {
        vor__mw_sub(number(sp, target), term, sp->width);
    } else {
        vor__mw_add(number(sp, target), term, sp->width);
    }
}

/*
 * Laplace's (non-Sibsonian) weights of the k neighbours: the length of
 * q's cell edge facing p_i over |p_i - q|. With a_i = p_i - q and
 * X_i = a_i x a_{i+1} > 0, the cell's vertex c_i (circumcentre of q, p_i,
 * p_{i+1}) has a_i x c_i = |a_i|^2 (|a_{i+1}|^2 - a_i.a_{i+1}) / 2 X_i,
 * and the edge c_{i-1} c_i is perpendicular to a_i, turned
 * counterclockwise, so its length over |a_i| is a_i x (c_i - c_{i-1}) /
 * |a_i|^2:
 *   2 t_i = a_{i+1}.(a_{i+1} - a_i) / X_i + a_{i-1}.(a_{i-1} - a_i) / X_{i-1},
 * over the common denominator prod X_j (each X_j < 2^67, each numerator
 * below 2^68, so the sums fit the numbers far within Sibson's widths).
 * The denominator is the weights' sum: Laplace's coordinates are the
 * t_i normalised.
 */
static void laplace_weights(const vor_t *d, ip_space_t *sp, const vor_point_t *q)
{
    uint32_t k = sp->k;
    const vor_point_t *s = d->sites;
    for (uint32_t i = 0; i < k; i++) { /* X_i, as the "denominators" */
        const vor_point_t *a = &s[sp->ids[i]];
        const vor_point_t *b = &s[sp->ids[((i + 1u) == k) ? 0u : (i + 1u)]];
        dot(point_part(sp, i, 2), (int64_t)a->x - q->x, -((int64_t)a->y - q->y),
            (int64_t)b->y - q->y, (int64_t)b->x - q->x);
    }
    sp->points_used = k;
    for (uint32_t i = 0; i <= k; i++) {
        vor__mw_from_u64(number(sp, i), sp->width, 0u);
    }
    vor__limb n[POINT_LIMBS];
    for (uint32_t i = 0; i < k; i++) {
        uint32_t next = ((i + 1u) == k) ? 0u : (i + 1u);
        uint32_t before = ((i == 0u) ? k : i) - 1u;
        const vor_point_t *a = &s[sp->ids[i]];
        const vor_point_t *b = &s[sp->ids[next]];
        const vor_point_t *c = &s[sp->ids[before]];
        dot(n, (int64_t)b->x - q->x, (int64_t)b->y - q->y, (int64_t)b->x - a->x, (int64_t)b->y - a->y);
        add_scaled(sp, i, n, i, i);
        dot(n, (int64_t)c->x - q->x, (int64_t)c->y - q->y, (int64_t)c->x - a->x, (int64_t)c->y - a->y);
        add_scaled(sp, i, n, before, before);
    }
    for (uint32_t i = 0; i < k; i++) {
        vor__mw_add(number(sp, k), number(sp, i), sp->width);
    }
}

/* Number i = v, a non-negative value of POINT_LIMBS limbs. */
static void set_number(const ip_space_t *sp, uint32_t i, const vor__limb *v)
{
    vor__limb *r = number(sp, i);
    vor__mw_from_u64(r, sp->width, 0u);
    vor__mw_copy(r, v, POINT_LIMBS);
}

/* The limit on hull edge (a, b), q strictly inside it: weights
 * (b - q).(b - a) and (q - a).(b - a) over |b - a|^2, each below 2^67. */
static void edge_weights(const vor_t *d, const ip_space_t *sp, const vor_point_t *q,
                         const uint32_t edge[2])
{
    const vor_point_t *a = &d->sites[edge[0]];
    const vor_point_t *b = &d->sites[edge[1]];
    int64_t ex = (int64_t)b->x - a->x;
    int64_t ey = (int64_t)b->y - a->y;
    vor__limb t[POINT_LIMBS];
    sp->ids[0] = edge[0];
    sp->ids[1] = edge[1];
    dot(t, (int64_t)b->x - q->x, (int64_t)b->y - q->y, ex, ey);
    set_number(sp, 0, t);
    dot(t, (int64_t)q->x - a->x, (int64_t)q->y - a->y, ex, ey);
    set_number(sp, 1, t);
    dot(t, ex, ey, ex, ey);
    set_number(sp, 2, t);
}

/* 32-bit word w of a non-negative number (shifts, not divisions: a
 * division is a runtime call on Cortex-M0 without optimisation). */
static uint32_t word_of(const vor__limb *n, size_t w)
{
#if VOR_LIMB_BITS == 64
    return (uint32_t)(n[w >> 1] >> ((w & 1u) * 32u));
#else
    return (uint32_t)n[w];
#endif
}

/* The 32-bit words a non-negative number of `width` limbs fills (>= 1). */
static uint32_t words_of(const vor__limb *n, size_t width)
{
    size_t w = width * (VOR__LIMB_WIDTH / 32u);
    while ((w > 1u) && (word_of(n, w - 1u) == 0u)) {
        w--;
    }
    return (uint32_t)w;
}

/* Output number `slot` = the low `words` words of n. */
static const uint32_t *put_number(const ip_space_t *sp, uint32_t slot, const vor__limb *n,
                                  uint32_t words)
{
    uint32_t *r = sp->out + ((size_t)slot * words);
    for (uint32_t w = 0; w < words; w++) {
        r[w] = word_of(n, w);
    }
    return r;
}

/* The entry points' common part: their argument checks, then the
 * coordinates of q in the scratch, ids and numbers 0 .. k (the weights,
 * then the denominator). count is where VOR_ERR_NOMEM writes the k needed
 * (the caller's out->count or out->neighbours, nothing else of *out),
 * NULL when an output or the values are missing (VOR_ERR_ARG). */
static int coordinates(const vor_t *d, vor_point_t q, uint32_t hint, void *scratch,
                       size_t scratch_bytes, bool laplace, ip_space_t *sp, uint32_t *count)
{
    if ((d == NULL) || (count == NULL) || ((scratch == NULL) && (scratch_bytes > 0u))) {
        return VOR_ERR_ARG;
    }
    uint32_t c;
    int err = vor_nearest(d, q, hint, &c);
    if (err != VOR_OK) {
        return err;
    }
    const vor_point_t *s = d->sites;
    if ((s[c].x == q.x) && (s[c].y == q.y)) { /* at a site: its value */
        if (!cut_scratch(sp, scratch, scratch_bytes, 1u)) {
            *count = 1;
            return VOR_ERR_NOMEM;
        }
        sp->ids[0] = c;
        vor__mw_from_u64(number(sp, 0), sp->width, 1u);
        vor__mw_from_u64(number(sp, 1), sp->width, 1u);
        return VOR_OK;
    }
    if (d->vertex_count < 2u) {
        return VOR_ERR_OUTSIDE;
    }
    uint32_t edge[2];
    vor_index_t t0;
    vor_index_t u0;
    if (find_start(d, &q, (vor_index_t)c, &t0, &u0)) {
        uint32_t k = 0;
        enum ip_walk walk = walk_boundary(d, &q, t0, u0, (vor_index_t)c, NULL, &k, edge);
        if (walk == WALK_OUTSIDE) {
            return VOR_ERR_OUTSIDE;
        }
        if (walk == WALK_BROKEN) {
            return VOR_ERR_INVALID;
        }
        if (walk == WALK_INSIDE) {
            if (k < 3u) {
                return VOR_ERR_INVALID;
            }
            if (!cut_scratch(sp, scratch, scratch_bytes, k)) {
                *count = k;
                return VOR_ERR_NOMEM;
            }
            sp->points_used = k;
            sp->laplace = laplace;
            if (walk_boundary(d, &q, t0, u0, (vor_index_t)c, sp, &k, edge) != WALK_INSIDE) {
                return VOR_ERR_INVALID;
            }
            if (laplace) {
                laplace_weights(d, sp, &q);
            } else {
                sibson_areas(d, sp, &q);
            }
            return VOR_OK;
        }
    } else {
        /* no circle holds q: q is outside the hull, or the sites are
         * collinear and q is on their line between c and its neighbour
         * on q's side (the nearest such neighbour of c) */
        vor_neighbour_iter_t it;
        uint32_t n;
        uint32_t third;
        uint32_t best = VOR_NO_HINT;
        vor__fan_begin(&it, d, c);
        while (vor__fan_next(&it, &n, &third)) {
            if ((vor__orient2d_sign(&s[c], &s[n], &q) == 0) && between(&q, &s[c], &s[n]) &&
                ((best == VOR_NO_HINT) || (vor__closer_sign(&s[c], &s[n], &s[best], NULL) < 0))) {
                best = n;
            }
        }
        if (best == VOR_NO_HINT) {
            return VOR_ERR_OUTSIDE;
        }
        edge[0] = c;
        edge[1] = best;
    }
    if (!cut_scratch(sp, scratch, scratch_bytes, 2u)) {
        *count = 2;
        return VOR_ERR_NOMEM;
    }
    edge_weights(d, sp, &q, edge);
    return VOR_OK;
}

/* vor_sibson and vor_laplace: the coordinates, as 32-bit words. */
static int natural(const vor_t *d, vor_point_t q, uint32_t hint, void *scratch,
                   size_t scratch_bytes, bool laplace, vor_coordinates_t *out)
{
    ip_space_t sp;
    int err = coordinates(d, q, hint, scratch, scratch_bytes, laplace, &sp,
                          (out != NULL) ? &out->count : NULL);
    if (err != VOR_OK) {
        return err;
    }
    /* every weight is at most the denominator: its words bound them all */
    uint32_t words = words_of(number(&sp, sp.k), sp.width);
    const uint32_t *weights = sp.out;
    for (uint32_t i = 0; i < sp.k; i++) {
        (void)put_number(&sp, i, number(&sp, i), words);
    }
    out->denominator = put_number(&sp, sp.k, number(&sp, sp.k), words);
    out->weights = weights;
    out->sites = sp.ids;
    out->limbs = words;
    out->count = sp.k;
    return VOR_OK;
}

int vor_sibson(const vor_t *d, vor_point_t q, uint32_t hint, void *scratch, size_t scratch_bytes,
               vor_coordinates_t *out)
{
    return natural(d, q, hint, scratch, scratch_bytes, false, out);
}

int vor_laplace(const vor_t *d, vor_point_t q, uint32_t hint, void *scratch, size_t scratch_bytes,
                vor_coordinates_t *out)
{
    return natural(d, q, hint, scratch, scratch_bytes, true, out);
}

/* |rest| / step rounded to the nearest integer, halves away from zero,
 * for |rest| < 2^32 step: rest and step (> 0) are overwritten, with room
 * for step 2^32 in `width` limbs. */
static uint64_t rounded_quotient(vor__limb *rest, vor__limb *step, size_t width)
{
    for (unsigned i = 0; i < 32u; i++) {
        vor__mw_shl1(step, width);
    }
    uint64_t quotient = 0;
    for (unsigned i = 0; i < 32u; i++) { /* quotient bits 31 .. 0 */
        vor__mw_shr1(step, width);
        quotient <<= 1;
        if (vor__mw_compare(rest, step, width) >= 0) {
            vor__mw_sub(rest, step, width);
            quotient |= 1u;
        }
    }
    vor__mw_shl1(rest, width); /* 2 rest < 2 step: fits */
    return quotient + ((vor__mw_compare(rest, step, width) >= 0) ? 1u : 0u);
}

/* vor_interpolate and vor_interpolate_laplace. */
static int interpolate(const vor_t *d, const int32_t *values, vor_point_t q, uint32_t hint,
                       void *scratch, size_t scratch_bytes, bool laplace, vor_interpolation_t *out)
{
    ip_space_t sp;
    int err = coordinates(d, q, hint, scratch, scratch_bytes, laplace, &sp,
                          ((values != NULL) && (out != NULL)) ? &out->neighbours : NULL);
    if (err != VOR_OK) {
        return err;
    }
    size_t width = sp.width;
    vor__limb *sum = number(&sp, sp.k + 1u);
    vor__limb *t = number(&sp, sp.k + 2u);
    vor__limb m[U64_LIMBS];
    vor__mw_from_u64(sum, width, 0u);
    for (uint32_t i = 0; i < sp.k; i++) {
        int32_t v = values[sp.ids[i]];
        vor__mw_from_u64(m, U64_LIMBS, (v < 0) ? (0u - (uint64_t)(int64_t)v) : (uint64_t)v);
        vor__mw_mul(t, width, number(&sp, i), width, m, U64_LIMBS);
        if (v < 0) {
            vor__mw_sub(sum, t, width);
        } else {
            vor__mw_add(sum, t, width);
        }
    }
    int sign = vor__mw_sign(sum, width);
    if (sign < 0) {
        vor__mw_neg(sum, width);
    }
    vor__limb *rest = number(&sp, sp.k + 2u);
    vor__limb *step = number(&sp, sp.k + 3u);
    vor__mw_copy(rest, sum, width);
    vor__mw_copy(step, number(&sp, sp.k), width);
    uint64_t magnitude = rounded_quotient(rest, step, width);
    uint32_t words = words_of(sum, width);
    uint32_t d_words = words_of(number(&sp, sp.k), width);
    words = (d_words > words) ? d_words : words;
    out->numerator = put_number(&sp, 0, sum, words);
    out->denominator = put_number(&sp, 1, number(&sp, sp.k), words);
    out->limbs = words;
    out->sign = sign;
    out->neighbours = sp.k;
    out->value = (int32_t)((sign < 0) ? -(int64_t)magnitude : (int64_t)magnitude);
    return VOR_OK;
}

int vor_interpolate(const vor_t *d, const int32_t *values, vor_point_t q, uint32_t hint,
                    void *scratch, size_t scratch_bytes, vor_interpolation_t *out)
{
    return interpolate(d, values, q, hint, scratch, scratch_bytes, false, out);
}

int vor_interpolate_laplace(const vor_t *d, const int32_t *values, vor_point_t q, uint32_t hint,
                            void *scratch, size_t scratch_bytes, vor_interpolation_t *out)
{
    return interpolate(d, values, q, hint, scratch, scratch_bytes, true, out);
}
