/* SPDX-License-Identifier: MIT */
/*
 * motion.c - the motion cache: small moves without predicates
 * (docs/design/dynamic.md, "Small moves").
 *
 * Each site may hold a box: its anchor (ax, ay) and an exponent e, the box
 * being |x - ax| <= 2^e, |y - ay| <= 2^e, stamped with the epoch of the
 * triangles it was computed for (motion.h). A site's entry is valid when
 * its stamp carries the current epoch and a box. The cache keeps
 *
 *   Invariant J: for every predicate of the current triangles (each finite
 *   triangle's orientation, each edge's incircle test with the far vertex,
 *   the hull's orientation tests: what star_still_delaunay in dynamic.c
 *   evaluates around each site) that involves a site with a valid entry,
 *   in every configuration where each such site lies anywhere in its box
 *   and every other site at its current position, the exact value keeps
 *   its current sign and is never zero.
 *
 * A never-zero exact value is its own perturbed sign, and the box product
 * is connected, so every configuration of it has the current triangles as
 * its perturbed Delaunay triangulation. Hence a site moving inside its box
 * (vor__motion_fast) changes no triangle. Nor can it land on a site q: q
 * and p would then be perturbed nearest neighbours, so an edge p-q with a
 * finite triangle on it (the mesh has three or more sites: only a
 * two-site mesh has no finite triangle), whose orientation is 0.
 *
 * J survives what happens to it:
 * - a fast move: the box product, J's domain, does not depend on where in
 *   its box a site currently is;
 * - voiding an entry (its box bits cleared): the domain shrinks;
 * - a move of p that keeps the triangles: only p's predicates change.
 *   vor__motion_update re-proves each of them with p at its new place and
 *   the other valid sites anywhere within 2^(e+1) of their current
 *   positions (which covers their boxes), voiding those sites' entries
 *   where that fails (a walk skipped when no site of p's star holds a
 *   box: nothing to re-prove), and then, if the backoff (below) chooses
 *   to, sizes p's box so that the bound for every predicate, p free too,
 *   stays below |P| / 4: the margin leaves room for
 *   the neighbours' own later moves, so that robots that all move every
 *   step do not void each other's boxes in turn. The bounds depend on the
 *   largest exponent only, so p may always take the others' largest one,
 *   already proven below |P|;
 * - a change of triangles: the epoch moves on and voids every entry.
 *
 * The bounds, powers of two from bit lengths only. A predicate's points
 * move at most 2^(e+1) each (e the largest exponent among its valid
 * sites), so a vector between two of them changes by at most 2^E per
 * coordinate, E = e + 2. Let |coordinates| of the vectors be < 2^m and
 * n = max(m, E).
 * - orient(a, b, c) = ux vy - uy vx with u = b - a, v = c - a: a product
 *   changes by |ux dvy| + |dux vy| + |dux dvy| <= 3 * 2^(n+E), the
 *   difference by 6 * 2^(n+E) < 2^(n+E+3).
 * - incircle relative to d, rows (x, y, z = x^2 + y^2) of a-d, b-d, c-d:
 *   |x|, |y| < 2^n move to < 2^(n+1); z < 2^(2n+1) changes by
 *   |2x dx + dx^2 + 2y dy + dy^2| <= 6 * 2^(n+E) <= 2^(2n+3), so z' <
 *   2^(2n+4). A product x y z changes by at most
 *   |dx| |y'| |z'| + |x| |dy| |z'| + |x| |y| |dz|
 *   <= 2^(3n+E+5) + 2^(3n+E+4) + 2^(3n+E+3) < 2^(3n+E+6), and the six of
 *   the determinant by < 2^(3n+E+9) <= 2^(3n+E+10).
 * The incircle bound is too crude for boxes of use (a Delaunay quad's |P|
 * is near 2^(4m - 6), leaving E about m - 16), so a first-order bound
 * replaces it. With h = 2^E <= 2^(m-3),
 * each of the six products x y z of the determinant, as a polynomial in
 * t (the points at t times their moves), has t^2, t^3, t^4 coefficients
 * of at most 12 M^2 h^2, 8 M h^3 <= M^2 h^2 and 2 h^4 <= M^2 h^2 / 32
 * (M = 2^m; z moves by t w + t^2 v with |w| <= 4 M h, |v| <= 2 h^2), so
 * beyond the first order the change is below 6 * 14 M^2 h^2 <
 * 2^(2m+2E+7). The first order is the gradient g of the determinant
 * z_a (b x c) + z_b (c x a) + z_c (a x b) times the moves:
 *   g_a = (2 a_x (b x c) - z_b c_y + z_c b_y, 2 a_y (b x c) + z_b c_x - z_c b_x)
 * and cyclically for b and c, bounded from int64 values (gradient_bits),
 * at most G h < 2^(Lg+E) for G below 2^Lg. Together: below
 * 2^(max(Lg+E, 2m+2E+7)+1). Either bound is a proof; the smaller one is
 * used.
 *
 * With |P| of bit length L (2^(L-1) <= |P|), a change bound 2^B keeps the
 * sign when B <= L - 2, and stays within |P| / 4 when B <= L - 3.
 */
#include "motion.h"

#include "mesh.h"
#include "multiword.h"
#include "predicates.h"

/* Largest box exponent the fast test handles (2r fits 32 bits). */
#define MAX_EXPONENT 30

static bool entry_valid(const vor_t *d, uint32_t site)
{
    uint32_t stamp = d->motion[site].stamp;
    return ((stamp >> 8) == d->motion_epoch) && (stamp & VOR__BOX_MASK) != 0u;
}

static void motion_update(vor_t *d, uint32_t p, const vor_point_t *from, uint32_t epoch);

int vor_motion_attach(vor_t *d, void *mem, size_t bytes)
{
    if ((d == NULL) || ((mem == NULL) && (bytes > 0u))) {
        return VOR_ERR_ARG;
    }
    if (mem == NULL) {
        d->motion = NULL;
        d->motion_update = NULL;
        return VOR_OK;
    }
    if (((uintptr_t)mem % VOR_MOTION_ALIGN) != 0u) {
        return VOR_ERR_ALIGN;
    }
    if (bytes < VOR_MOTION_BYTES(d->max_sites)) {
        return VOR_ERR_NOMEM;
    }
    struct vor__motion_entry *cache = (struct vor__motion_entry *)mem;
    for (uint32_t i = 0; i < d->max_sites; i++) {
        cache[i].x = 0;
        cache[i].y = 0;
        cache[i].stamp = 0; /* no box */
    }
    d->motion = cache;
    d->motion_update = motion_update; /* vor_move reaches the upkeep only so */
    return VOR_OK;
}

/* Exponent of the change bound of a predicate of `count` points (3: an
 * orientation, 4: an incircle test) whose vectors are < 2^m and move by
 * at most 2^E (the derivations above). */
static int change_bound(unsigned count, int m, int E)
{
    int n = (m > E) ? m : E;
    return (count == 3u) ? (n + E + 3) : ((3 * n) + E + 10);
}

/* The gradient is evaluated on vectors cut to GRADIENT_BITS bits: below
 * that, every product fits int64 (above). */
#define GRADIENT_BITS 18

/* An upper bound on the bit length of the incircle gradient's absolute
 * sum G for the vectors v (the three sites relative to the fourth, below
 * 2^m). Longer vectors are cut: u = 2^k u' + r with u' = sign(u) (|u| >> k),
 * |r| < 2^k, |2^k u'| <= |u| < 2^m. A monomial u v w of a component then
 * differs from 2^(3k) u' v' w' by r_u v w + 2^k u' r_v w + 2^k u' 2^k v' r_w,
 * below 3 * 2^(2m+k); a component has monomials of total weight 8
 * (2 a_x b_x c_y - 2 a_x b_y c_x - b_x^2 c_y - b_y^2 c_y + c_x^2 b_y +
 * c_y^2 b_y for g_ax), so G <= 2^(3k) G' + 6 * 8 * 3 * 2^(2m+k) <
 * 2^(3k) G' + 2^(2m+k+8), G' the sum for the cut vectors. */
static int gradient_bits(int64_t wide[3][2], int m)
{
    int k = (m > GRADIENT_BITS) ? (m - GRADIENT_BITS) : 0;
    int32_t v[3][2];
    for (unsigned r = 0; r < 3u; r++) {
        for (unsigned c = 0; c < 2u; c++) {
            uint32_t cut = (uint32_t)((wide[r][c] < 0) ? -wide[r][c] : wide[r][c]) >> (unsigned)k;
            v[r][c] = (wide[r][c] < 0) ? -(int32_t)cut : (int32_t)cut; /* cut < 2^18 */
        }
    }
    int64_t z[3];
    int64_t cross[3];
    for (unsigned r = 0; r < 3u; r++) {
        unsigned r1 = vor__next(r);
        unsigned r2 = vor__prev(r);
        z[r] = vor__mul_i32(v[r][0], v[r][0]) + vor__mul_i32(v[r][1], v[r][1]);
        /* the cross product of the two other rows: (b x c) for a */
        cross[r] = vor__mul_i32(v[r1][0], v[r2][1]) - vor__mul_i32(v[r1][1], v[r2][0]);
    }
    uint64_t sum = 0;
    for (unsigned r = 0; r < 3u; r++) {
        unsigned r1 = vor__next(r);
        unsigned r2 = vor__prev(r);
        int64_t gx = 2 * vor__mul_i64_i32(cross[r], v[r][0]) -
                     vor__mul_i64_i32(z[r1], v[r2][1]) + vor__mul_i64_i32(z[r2], v[r1][1]);
        int64_t gy = 2 * vor__mul_i64_i32(cross[r], v[r][1]) +
                     vor__mul_i64_i32(z[r1], v[r2][0]) - vor__mul_i64_i32(z[r2], v[r1][0]);
        sum += (uint64_t)((gx < 0) ? -gx : gx) + (uint64_t)((gy < 0) ? -gy : gy);
    }
    int bits = (int)vor__mw_bit_length(sum);
    if (k == 0) {
        return bits; /* exact */
    }
    int scaled = (3 * k) + bits;
    int cut_error = (2 * m) + k + 8;
    return ((scaled > cut_error) ? scaled : cut_error) + 1;
}

/* The first-order incircle bound's exponent for moves of 2^E (above), or
 * a value past any limit when it does not apply (E > m - 3). */
static int gradient_bound(int m, int Lg, int E)
{
    if (E > (m - 3)) {
        return 1000;
    }
    int first = Lg + E;
    int rest = (2 * m) + (2 * E) + 7;
    return ((first > rest) ? first : rest) + 1;
}

/* The largest E with gradient_bound(m, Lg, E) <= T (it increases with E).
 * The square term's E is floor((T - 8 - 2m) / 2); C's division truncates
 * toward zero instead, which differs only for a negative odd value, where
 * both are at most 0: then E - 2 < 0 and no box follows either way. */
static int gradient_motion(int m, int Lg, int T)
{
    int E = T - 1 - Lg;
    int square = (T - 8 - (2 * m)) / 2;
    E = (square < E) ? square : E;
    return ((m - 3) < E) ? (m - 3) : E;
}

/* The largest E whose change bound is at most 2^T (change_bound is
 * increasing in E): on the side E <= m the bound is linear in E with
 * slope 1; when that side's answer exceeds m, every E <= m fits and the
 * answer lies on the side E > m, where the bound is 2E + 3 (orient) or
 * 4E + 10 (incircle). Negative when none. */
static int largest_motion(unsigned count, int m, int T)
{
    if (count == 3u) {
        int low = T - 3 - m;
        return (low <= m) ? low : (T - 3) / 2;
    }
    int low = T - 10 - (3 * m);
    return (low <= m) ? low : (T - 10) / 4;
}

/* The smaller of the change bounds that apply (Lg < 0: the crude one). */
static int bound_of(unsigned count, int m, int Lg, int E)
{
    int crude = change_bound(count, m, E);
    int first_order = (Lg >= 0) ? gradient_bound(m, Lg, E) : crude;
    return (first_order < crude) ? first_order : crude;
}

/* One predicate of p's star on sites ids[0 .. count): re-proves it with p
 * at its place and the other valid sites free, voiding their entries if
 * that fails; returns the largest box exponent p may have for it (< 0:
 * none). With `sizing` false p gets no box anyway (an earlier predicate
 * said so): only the re-proof is needed, and none when no other site of
 * the predicate is free. The vectors are taken from ids[0] for an
 * orientation and from ids[3] for an incircle test, as in the
 * derivations. */
static int predicate_limit(vor_t *d, uint32_t p, const vor_index_t ids[4], unsigned count,
                           bool sizing)
{
    int others = -1; /* largest exponent among the other valid sites */
    for (unsigned k = 0; k < count; k++) {
        if ((ids[k] != p) && entry_valid(d, ids[k])) {
            uint32_t box = d->motion[ids[k]].stamp & VOR__BOX_MASK;
            int e = (int)box - 1;
            others = (e > others) ? e : others;
        }
    }
    if ((others < 0) && !sizing) {
        return -1;
    }
    VOR_ASSERT(count >= 3u); /* at most one vertex of a triangle is infinite */
    const vor_point_t *s = d->sites;
    unsigned b = (count == 3u) ? 0u : 3u;
    uint32_t spread = 0;
    int64_t v[3][2]; /* the vectors (all three set for an incircle test) */
    unsigned r = 0;
    for (unsigned k = 0; k < count; k++) {
        /* |difference| of two int32 fits uint32 */
        int64_t dx = (int64_t)s[ids[k]].x - s[ids[b]].x;
        int64_t dy = (int64_t)s[ids[k]].y - s[ids[b]].y;
        uint32_t ax = (uint32_t)((dx < 0) ? -dx : dx);
        uint32_t ay = (uint32_t)((dy < 0) ? -dy : dy);
        spread |= ax | ay; /* same bit length as the larger */
        if (k != b) {
            v[r][0] = dx;
            v[r][1] = dy;
            r++;
        }
    }
    int m = (int)vor__mw_bit_length32(spread);
    int L = (int)((count == 3u) ? vor__orient2d_bits(&s[ids[0]], &s[ids[1]], &s[ids[2]])
                                : vor__incircle_bits(&s[ids[0]], &s[ids[1]], &s[ids[2]],
                                                     &s[ids[3]]));
    int Lg = (count == 4u) ? gradient_bits(v, m) : -1; /* -1: an orientation */
    if ((others >= 0) && ((L < 2) || bound_of(count, m, Lg, others + 2) > (L - 2))) {
        /* the others may no longer move freely: fixed where they are,
         * their boxes sized again at their next slow moves */
        for (unsigned k = 0; k < count; k++) {
            if ((ids[k] != p) && entry_valid(d, ids[k])) {
                struct vor__motion_entry *e = &d->motion[ids[k]];
                e->stamp &= ~VOR__BOX_MASK;
                e->x = 0;
                e->y = 1;
            }
        }
        others = -1;
    }
    if (L < 3) {
        return -1; /* |P| < 4: no room (a zero P: its sign is the perturbation's) */
    }
    int E = largest_motion(count, m, L - 3);
    if (Lg >= 0) {
        int first_order = gradient_motion(m, Lg, L - 3);
        E = (first_order > E) ? first_order : E;
    }
    /* p's and the others' exponents e share one E = max e + 2: the bound
     * leaves a quarter of |P| when p's e is below E - 2, and p may share
     * the others' largest e, which the check above allowed, at no cost */
    if ((others + 2) > E) {
        return others;
    }
    return E - 2;
}

/* The predicate deciding whether site t lies in the circle of triangle
 * (v0, v1, v2) (vor__conflicts): an orientation for a triangle at
 * infinity, an incircle test otherwise. Returns p's limit for it. */
static int conflict_limit(vor_t *d, uint32_t p, const vor_index_t v[3], vor_index_t t,
                          bool sizing)
{
    vor_index_t ids[4];
    unsigned count = 0;
    for (unsigned k = 0; k < 3u; k++) {
        if (v[k] != VOR__INFINITE) {
            ids[count] = v[k];
            count++;
        }
    }
    ids[count] = t;
    count++;
    return predicate_limit(d, p, ids, count, sizing);
}

static int min_limit(int a, int b)
{
    return (a < b) ? a : b;
}

/* The largest exponent e <= limit whose box around c stays in int32
 * (the fast test's offsets then cannot wrap), < 0 when none. */
static int in_range(int limit_in, int32_t c)
{
    int limit = limit_in;
    /* distance to the nearer end of int32 */
    uint32_t room = (c < 0) ? (uint32_t)((int64_t)c - INT32_MIN) : (uint32_t)(INT32_MAX - c);
    while ((limit >= 0) && (1u << limit) > room) {
        limit--;
    }
    return limit;
}

/* Does a site of p's predicates other than p hold a box: one of p's
 * neighbours (each is the vertex after p in one triangle of the star) or
 * a far vertex across the star's outer edges? */
static bool star_boxed(const vor_t *d, uint32_t p)
{
    vor__star_step_t s;
    vor__star_begin(d, (vor_index_t)p, &s);
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        if ((s.x != VOR__INFINITE && entry_valid(d, s.x)) ||
            (s.far != VOR__INFINITE && entry_valid(d, s.far))) {
            return true;
        }
        if (!vor__star_advance(d, (vor_index_t)p, &s)) {
            break;
        }
    }
    return false;
}

/* The backoff. Sizing a box costs several slow moves and pays only if
 * the site then moves inside it; whether it will cannot be known, so the
 * past decides. A site's first slow move after the cache is attached
 * sizes nothing: a site moved once (a beacon set down, a one-off
 * correction) never pays; one that moves again is sized at its next slow
 * move, and stays a mover across changes of the triangles. A sizing was
 * wasted when the site leaves the box without having moved inside it (it
 * is still at the anchor), or when no box could hold another step as
 * long as the last one (steps larger than the boxes): the site's level
 * goes up (at most 5) and its next 2^level slow moves, counting the one
 * that found the box unused, size nothing. A box the site moved inside
 * resets the level; one voided by a change of the triangles before the
 * move tells nothing. Only whether p is sized depends on this: J holds
 * either way (a site without a box is fixed). size_now decides for p's
 * move from `from` (`epoch` the one before the move) and leaves p without
 * a box while its predicates are examined. */
#define MAX_LEVEL 5u

static bool size_now(struct vor__motion_entry *e, const vor_point_t *from, uint32_t epoch)
{
    uint32_t level = (e->stamp >> 5) & 7u;
    if ((e->stamp & VOR__BOX_MASK) != 0u) {
        /* a box voided by a change of the triangles before this move
         * tells nothing: the level stays */
        bool current = (e->stamp >> 8) == epoch;
        bool unused = current && (e->x == from->x) && (e->y == from->y);
        level = unused ? level + ((level < MAX_LEVEL) ? 1u : 0u) : current ? 0u : level;
        e->x = unused ? (int32_t)(1u << level) : 0;
        e->y = 1;
    }
    e->stamp = level << 5;
    if (e->y == 0) {
        e->y = 1;
        return false; /* the first slow move */
    }
    if (e->x > 0) {
        e->x--;
        return false;
    }
    return true;
}

/* vor__motion_update (motion.h) through d->motion_update. */
static void motion_update(vor_t *d, uint32_t p, const vor_point_t *from, uint32_t epoch)
{
    struct vor__motion_entry *entry = &d->motion[p];
    bool sizing = size_now(entry, from, epoch);
    if (d->vertex_count < 3u) {
        return; /* no finite triangle: the twin argument needs one */
    }
    if (!sizing && !star_boxed(d, p)) {
        return; /* p's predicates involve no other box: J holds for them */
    }
    /* p gets a box only if it holds another step as long as this one:
     * 2^need >= step, the larger coordinate distance (int32 differences
     * fit uint32 as magnitudes). Once a predicate limits p below need,
     * the rest are only re-proved for the other sites. */
    const vor_point_t *at = &d->sites[p];
    uint32_t dx = (at->x > from->x) ? (uint32_t)at->x - (uint32_t)from->x
                                    : (uint32_t)from->x - (uint32_t)at->x;
    uint32_t dy = (at->y > from->y) ? (uint32_t)at->y - (uint32_t)from->y
                                    : (uint32_t)from->y - (uint32_t)at->y;
    uint32_t step = (dx > dy) ? dx : dy;
    int need = (step <= 1u) ? 0 : (int)vor__mw_bit_length32(step - 1u);
    need = sizing ? need : (MAX_EXPONENT + 1);
    /* p's star as star_still_delaunay walks it (vor__star_step, mesh.h):
     * per triangle its orientation, the test across its far edge, the
     * test across the spoke to the next triangle. */
    int limit = MAX_EXPONENT;
    vor__star_step_t s;
    vor__star_begin(d, (vor_index_t)p, &s);
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        if (s.x != VOR__INFINITE && (s.y != VOR__INFINITE)) {
            const vor_index_t ids[4] = {(vor_index_t)p, s.x, s.y, 0};
            limit = min_limit(limit, predicate_limit(d, p, ids, 3u, limit >= need));
        }
        if (s.far != VOR__INFINITE) {
            limit = min_limit(limit, conflict_limit(d, p, s.v, s.far, limit >= need));
        }
        if (s.across != VOR__INFINITE) {
            limit = min_limit(limit, conflict_limit(d, p, s.v, s.across, limit >= need));
        }
        if (!vor__star_advance(d, (vor_index_t)p, &s)) {
            break;
        }
    }
    limit = in_range(in_range(limit, at->x), at->y);
    uint32_t level = entry->stamp;
    if (limit >= need) {
        entry->x = at->x;
        entry->y = at->y;
        entry->stamp = (d->motion_epoch << 8) | level | ((uint32_t)limit + 1u);
    } else if (sizing) {
        /* no box to hold such steps: the sizing was of no use */
        level = (level >> 5) + (((level >> 5) < MAX_LEVEL) ? 1u : 0u);
        uint32_t side = 1u << level;
        entry->x = (int32_t)side;
        entry->stamp = level << 5;
    } else {
        /* no other case */
    }
}
