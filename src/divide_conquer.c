/* SPDX-License-Identifier: MIT */
/*
 * divide_conquer.c - the divide-and-conquer builder (Guibas and Stolfi,
 * Lee and Schachter), made unbreakable by numerical error with Oishi and
 * Sugihara's topological guards (Oishi and Sugihara, sections 3-4).
 *
 * It works on the same triangle mesh as the incremental builder (mesh.h):
 * a sub-triangulation of two or more sites is a closed triangulation of
 * the sphere, its hull closed by ghost triangles (a, b, inf), and every
 * step of a merge is an edge flip in a closed triangulation, so the
 * structure is a valid triangulation of the sphere after every step,
 * whatever the predicates answer:
 *
 *   1. the lower common tangent (l0, r0) of F (left) and S (right) is
 *      found on the hulls, from the rightmost site of F and the leftmost
 *      of S (Oishi and Sugihara, section 4.1), guarded by C4 and C5;
 *   2. glue: the two spheres are joined at the vertex at infinity by two
 *      new triangles, the lower ghost (r0, l0, inf) and the "cap"
 *      (l0, r0, inf) over the base edge (l0, r0). The ghosts of both hulls
 *      plus the cap now form one fan around infinity; the hull chains
 *      between the cap and the lower ghost are the pocket still to fill;
 *   3. zipper (Oishi and Sugihara, section 3.2, fig. 3.1), with base (l, r) = the
 *      cap's finite edge:
 *        - deleting the F-F edge (l, c1) is the flip of (l, c1) between
 *          the pocket ghost (c1, l, inf) and the F triangle (l, c1, c2):
 *          it becomes the edge (c2, inf), and the F triangle two ghosts;
 *        - drawing the next F-S edge (c1, r) is the flip of the cap with
 *          the pocket ghost (c1, l, inf): it gives the cross triangle
 *          (l, r, c1) and the new cap (c1, r, inf); the S side mirrors it.
 *      The merge ends when no candidate is valid: the cap is then the
 *      upper tangent's ghost. A merge creates exactly two triangles (the
 *      count goes from 2vF - 2 + 2vS - 2 to 2(vF + vS) - 2); flips reuse
 *      their two slots.
 *
 * Guards (never triggered with exact arithmetic; with wrong signs they
 * keep the structure a triangulation of the sphere whose edges are
 * F-F, S-S, F-S or to infinity, with no parallel edges):
 *   C1 connectivity: a deletion is a flip, so the endpoints of a deleted
 *      edge stay joined through c2 and no deletion can disconnect the
 *      graph: C1 holds by construction and needs no test.
 *   C2 crossing: an F-F edge of a finished cross triangle (its two ends
 *      joined to one S site by drawn F-S edges) is never deleted: the
 *      triangle beyond the candidate edge must be F-F-F (its far vertex
 *      c2 in F). (docs/design/divide-and-conquer.md, "Guards": why not "both ends have F-S edges".)
 *   C3 parallel edges: an F-S edge that exists already is never drawn
 *      (a walk around one endpoint); if both candidates fail, the merge
 *      ends.
 *   C4 search range: the tangent search moves the F end clockwise from the
 *      rightmost site of F (R1) no further than the leftmost (L1), and the
 *      S end counterclockwise from L2 no further than R2.
 *   C5 no backtracking: the F end only ever moves clockwise, the S end
 *      counterclockwise.
 * and two guards the triangle representation needs beyond them:
 *   T1 the triangle beyond a deleted edge is finite (a two-site F has
 *      ghosts on both sides of its edge): covered by the test of C2.
 *   T2 (no vertex twice on the hull): if the zipper would stop before
 *      either end of the base has moved, l0 (or r0) would be on the fan
 *      around infinity twice; that end is advanced once regardless (C3
 *      still applies, and the first move of an end can never break it).
 * Termination even when the predicates lie: every deletion turns one
 * F-F-F or S-S-S triangle into ghosts (there are fewer than 2v), every
 * advance turns one ghost into a cross triangle, and cross triangles are
 * never flipped again; so a merge makes fewer than 2v deletions and
 * 4v + hull advances.
 *
 * Memory: nothing beyond the arena. The sorted site order lives at the
 * top of the triangle slots and is read front to back while triangles
 * fill the slots from below (see start()); the recursion is an
 * explicit stack of O(log n) frames.
 *
 * Two cores: vor_build_dc_forked builds the two halves of the top-level
 * merge on two cores through the caller's fork/join hook, each in its own
 * region of slots, then merges them on the calling core (build_forked).
 */
#include "bucket_grid.h"
#include "insertion_order.h"
#include "mesh.h"
#include "multiword.h"
#include "perturbation.h"

/* ------------------------------------------------------------------ */
/* Orders                                                              */

/* Lexicographic order (x, y): after duplicates are removed it is the x
 * order of the plane turned by an infinitesimal angle, so the two halves
 * of a split are separated by a line and the leftmost site of a set is a
 * hull vertex even when many sites share an x. */
static inline bool lex_less(const vor_point_t *s, vor_index_t a, vor_index_t b)
{
    return (s[a].x < s[b].x) || ((s[a].x == s[b].x) && (s[a].y < s[b].y));
}

/* The same turned by 90 degrees, (x', y') = (-y, x): top to bottom, for
 * vertical merges (Oishi and Sugihara, section 3.2: "rotate the algorithm"). */
static inline bool lex_less_rotated(const vor_point_t *s, vor_index_t a, vor_index_t b)
{
    return (s[a].y > s[b].y) || ((s[a].y == s[b].y) && (s[a].x < s[b].x));
}

/* Axis 0: lex_less; axis 1: lex_less_rotated. */
static inline bool axis_less(const vor_point_t *s, vor_index_t a, vor_index_t b, unsigned axis)
{
    return (axis == 0u) ? lex_less(s, a, b) : lex_less_rotated(s, a, b);
}

/* ------------------------------------------------------------------ */
/* Parts and the builder's state                                       */

/* A finished sub-triangulation (a "part") is named by one index, so the
 * explicit recursion stacks hold one or two words a level:
 *   VOR__NONE        no sites (an empty quadtree bucket);
 *   an empty slot    one site, whose home slot it is (single() empties it:
 *                    a lone site has no triangle, its home slot is free);
 *   any other slot   one of its ghost triangles. Slots of other parts never
 *                    change during a merge, so the ghost stays one; and a
 *                    merge returns its lower ghost, which its zipper never
 *                    flips (the pocket beyond it would need a far vertex on
 *                    the other side).
 * Its extreme sites are read off its hull when it is merged
 * (hull_extremes), not stored. */
typedef struct {
    vor_t *d;
    vor__tri_t *tri;
    vor_stats_t *stats; /* d's, or a forked worker's own (VOR_STATS; else NULL) */
    uint32_t *duplicate_of; /* vor_build's, or NULL */
    uint32_t next_extra; /* the next unused extra slot */
    uint32_t distinct;   /* distinct sites built so far */
    vor_index_t last;    /* the last of them */
    unsigned axis;       /* this merge's order: F before S on it */
    /* Which side of this merge a site is on, exactly (guard C2 relies on
     * it), by one of two rules:
     *   by_line false: F = the sites before `split` on the axis (the
     *     x-split: split = the least site of S);
     *   by_line true: F = the sites whose coordinate (x on axis 0, y on
     *     axis 1) is below `line`, or at or above it if f_above (quadtree
     *     merges: the children are separated by a grid line). */
    bool by_line;
    bool f_above;
    vor_index_t split;
    int64_t line;
    unsigned k;          /* the quadtree's grid: 2^k x 2^k buckets over */
    vor__grid_square_t *square; /* this square (vor__grid_z), the entry
                                   point's: both workers read it */
    uint32_t bound;      /* step bound for walks around a vertex */
} builder_t;

/* The perturbed predicates, counted in the builder's own stats: a worker
 * of vor_build_dc_forked writes no counter the other core writes. */
static inline int orient(const builder_t *b, vor_index_t p, vor_index_t q, vor_index_t r)
{
    return vor__orient_counted(b->d, b->stats, p, q, r);
}

static inline int incircle(const builder_t *b, vor_index_t p, vor_index_t q, vor_index_t r,
                           vor_index_t t)
{
    return vor__incircle_counted(b->d, b->stats, p, q, r, t);
}

static inline bool in_f_finite(const builder_t *b, vor_index_t v)
{
    if (b->by_line) {
        const vor_point_t *p = &b->d->sites[v];
        return ((int64_t)((b->axis == 0u) ? p->x : p->y) < b->line) != b->f_above;
    }
    return axis_less(b->d->sites, v, b->split, b->axis);
}

static inline bool in_f(const builder_t *b, vor_index_t v)
{
    return v != VOR__INFINITE && in_f_finite(b, v);
}

/* One site as a part: its home slot, emptied. */
static vor_index_t single(builder_t *b, vor_index_t s)
{
    vor__tri_fresh(&b->tri[s]);
    b->tri[s].n[0] = VOR__NONE;
    return s;
}

static bool is_single(const builder_t *b, vor_index_t part)
{
    return vor__slot_empty(&b->tri[part]);
}

/* Index of x among decoded vertices v, or 3. */
static inline unsigned find(const vor_index_t v[3], vor_index_t x)
{
    return (v[0] == x) ? 0u : (v[1] == x) ? 1u : (v[2] == x) ? 2u : 3u;
}

/* The vertex among decoded vertices v that is neither a nor c. */
static inline vor_index_t third(const vor_index_t v[3], vor_index_t a, vor_index_t c)
{
    return ((v[0] != a) && (v[0] != c)) ? v[0] : ((v[1] != a) && (v[1] != c)) ? v[1] : v[2];
}

static bool is_home(const builder_t *b, vor_index_t slot, vor_index_t v)
{
    return (slot == v) && (v < b->d->max_sites);
}

/* Flips the edge opposite vertex i1 of the triangle in slot s1 = (a, b, c)
 * (its vertices decoded in tv) with its neighbour (c, b, e): they become
 * T1 = (a, b, e) and T2 = (a, e, c), in the two slots chosen so that each
 * home slot still holds a triangle of its site (incremental.c's flip, with
 * infinity allowed anywhere). Returns T1's slot in *t1 and T2's in *t2.
 * Each triangle is decoded once: the packed vertex words are the builder's
 * main cost after the predicates. */
static inline void flip(builder_t *b, vor_index_t s1, const vor_index_t tv[3], unsigned i1,
                        vor_index_t *t1, vor_index_t *t2)
{
    vor__tri_t *tri = b->tri;
    vor__tri_t *t = &tri[s1];
    vor_index_t a = tv[i1];
    vor_index_t bb = tv[vor__next(i1)];
    vor_index_t c = tv[vor__prev(i1)];
    vor_index_t s2 = t->n[i1];
    vor_index_t nab = t->n[vor__prev(i1)];
    vor_index_t nca = t->n[vor__next(i1)];
    vor__tri_t *u = &tri[s2];
    vor_index_t uv[3];
    vor__vertices(u, uv);
    unsigned ib = find(uv, bb);
    ib = (ib == 3u) ? 0u : ib; /* always found: the two share the edge */
    vor_index_t e = uv[vor__next(ib)];
    vor_index_t nbe = u->n[vor__prev(ib)];
    vor_index_t nec = u->n[ib];
    vor_index_t x1 = s1;
    vor_index_t x2 = s2;
    if (is_home(b, s1, c) || is_home(b, s2, bb)) {
        x1 = s2;
        x2 = s1;
    }
    vor__relink_before(tri, nab, a, x1);
    vor__relink_before(tri, nbe, bb, x1);
    vor__relink_before(tri, nec, e, x2);
    vor__relink_before(tri, nca, c, x2);
    vor__tri_set(&tri[x1], a, bb, e, nbe, x2, nab);
    vor__tri_set(&tri[x2], a, e, c, nec, nca, x1);
    *t1 = x1;
    *t2 = x2;
}

/* Is q a neighbour of site p? A walk around p from its home slot (C3;
 * Oishi and Sugihara, section 3.3: one endpoint's edges). */
static bool has_edge(const builder_t *b, vor_index_t p, vor_index_t q)
{
    vor_index_t slot = p;
    for (uint32_t step = 0; step < b->bound; step++) {
        const vor__tri_t *t = &b->tri[slot];
        vor_index_t v[3];
        vor__vertices(t, v);
        unsigned i = find(v, p);
        if (i == 3u) {
            return true; /* only on a corrupted mesh: refuse the edge */
        }
        if ((v[vor__next(i)] == q) || v[vor__prev(i)] == q) {
            return true;
        }
        slot = t->n[vor__next(i)];
        if (slot == p) {
            break;
        }
    }
    return false;
}

/* C3 for the F-S edge (p, q) of the current merge. Every F-S edge drawn so
 * far has both ends marked (each end of the base is marked when it becomes
 * one, and F-S edges are only ever drawn as the base), so an unmarked p
 * has none and needs no walk: with exact predicates the candidates are
 * never marked, and the check costs one bit. */
static bool joined(const builder_t *b, vor_index_t p, vor_index_t q)
{
    return vor__marked(&b->tri[p]) && has_edge(b, p, q);
}

/* Writes a fresh triangle into an unused slot (clearing what scratch data
 * left in its mark bit). */
static void put(vor__tri_t *tri, vor_index_t slot, vor_index_t v0, vor_index_t v1,
                vor_index_t v2, vor_index_t n0, vor_index_t n1, vor_index_t n2)
{
    vor__tri_fresh(&tri[slot]);
    vor__tri_set(&tri[slot], v0, v1, v2, n0, n1, n2);
}

/* The least and greatest hull sites of a part on an axis, the ghosts
 * (site, w, inf) at them, and the hull's length: one walk around the fan
 * of ghosts at infinity from the part's ghost g (at most v ghosts; the
 * bound only matters on a corrupted mesh). Only coordinates are compared,
 * exactly. With exact predicates the least and greatest sites of the part
 * are hull sites, so these are its extremes (the tangent search starts
 * there, Oishi and Sugihara, section 4.1); if earlier signs lied they are still hull
 * sites, which is all the search and guards C4 and C5 need. */
typedef struct {
    vor_index_t least;
    vor_index_t least_ghost;
    vor_index_t most;
    vor_index_t most_ghost;
    uint32_t length;
} extremes_t;

static void hull_extremes(const builder_t *b, vor_index_t g, unsigned axis, extremes_t *e)
{
    const vor__tri_t *tri = b->tri;
    const vor_point_t *s = b->d->sites;
    vor_index_t v[3];
    vor__vertices(&tri[g], v);
    unsigned i = find(v, VOR__INFINITE);
    i = (i == 3u) ? 2u : i; /* never: a part's ghost is a ghost */
    vor_index_t a = v[vor__next(i)];
    e->most = a;
    e->least = e->most;
    e->most_ghost = g;
    e->least_ghost = e->most_ghost;
    e->length = 1;
    /* the next ghost (w, x, inf) lies across (w, inf) from (a, w, inf) */
    vor_index_t slot = tri[g].n[vor__next(i)];
    while ((slot != g) && (e->length < b->bound)) {
        const vor__tri_t *t = &tri[slot];
        vor__vertices(t, v);
        i = find(v, VOR__INFINITE);
        if (i == 3u) {
            break; /* only on a corrupted mesh */
        }
        a = v[vor__next(i)];
        if (axis_less(s, a, e->least, axis)) {
            e->least = a;
            e->least_ghost = slot;
        } else if (axis_less(s, e->most, a, axis)) {
            e->most = a;
            e->most_ghost = slot;
        } else {
            /* no other case */
        }
        e->length++;
        slot = t->n[vor__next(i)];
    }
}

/* ------------------------------------------------------------------ */
/* Merge                                                               */

/* The lower common tangent (l, r) of F and S and the ghosts at its ends,
 * (l, w, inf) in F and (u, r, inf) in S (VOR__NONE for a single site). */
typedef struct {
    vor_index_t l;
    vor_index_t r;
    vor_index_t g1;
    vor_index_t g2;
} tangent_t;

/* Step 1 (Oishi and Sugihara, section 4): the lower common tangent of F
 * and S, from R1 (F's greatest site) and L2 (S's least). */
static void lower_tangent(builder_t *b, vor_index_t f, vor_index_t s, bool f_single,
                          bool s_single, tangent_t *t)
{
    vor__tri_t *tri = b->tri;
    vor_index_t v[3];
    vor_index_t l = f;
    vor_index_t r = s;
    vor_index_t l_stop = f;
    vor_index_t r_stop = s;
    vor_index_t g1 = VOR__NONE;
    vor_index_t g2 = VOR__NONE;
    uint32_t f_hull = 1;
    uint32_t s_hull = 1;
    extremes_t e;
    if (!f_single) {
        hull_extremes(b, f, b->axis, &e);
        l = e.most; /* R1 */
        g1 = e.most_ghost;
        l_stop = e.least; /* L1 */
        f_hull = e.length;
    }
    if (!s_single) {
        hull_extremes(b, s, b->axis, &e);
        r = e.least; /* L2 */
        r_stop = e.most; /* R2 */
        s_hull = e.length;
        /* (r, w, inf) -> the ghost before it, (u, r, inf), across (inf, r) */
        vor_index_t h = e.least_ghost;
        vor__vertices(&tri[h], v);
        g2 = tri[h].n[vor__next(find(v, r))];
    }
    uint32_t moves1 = 0;
    uint32_t moves2 = 0;
    for (;;) {
        /* C4: the F end stays between R1 and L1 (clockwise), the S end
         * between L2 and R2 (counterclockwise); C5: no move back. The
         * move counts bound the walks if the hulls are not convex. */
        if (g1 != VOR__NONE && (l != l_stop) && (moves1 < f_hull)) {
            vor__vertices(&tri[g1], v);
            unsigned i = find(v, l);
            vor_index_t w = v[vor__next(i)];
            if (orient(b, l, r, w) < 0) {
                g1 = tri[g1].n[i];
                l = w;
                moves1++;
                continue;
            }
        }
        if (g2 != VOR__NONE && (r != r_stop) && (moves2 < s_hull)) {
            vor__vertices(&tri[g2], v);
            unsigned i = find(v, r);
            vor_index_t u = v[vor__prev(i)];
            if (orient(b, l, r, u) < 0) {
                g2 = tri[g2].n[i];
                r = u;
                moves2++;
                continue;
            }
        }
        break;
    }
    t->l = l;
    t->r = r;
    t->g1 = g1;
    t->g2 = g2;
}

/* Step 2, glue: the lower ghost (r0, l0, inf) and the cap (l0, r0, inf)
 * join the two spheres at infinity. Returns the lower ghost's slot; *cap
 * is the cap's. */
static vor_index_t glue(builder_t *b, const tangent_t *t, bool f_single, bool s_single,
                        vor_index_t *cap_slot)
{
    vor__tri_t *tri = b->tri;
    vor_index_t v[3];
    vor_index_t l0 = t->l;
    vor_index_t r0 = t->r;
    vor_index_t ga = t->g1;
    vor_index_t gb = VOR__NONE;
    vor_index_t ha = VOR__NONE;
    vor_index_t hb = t->g2;
    if (ga != VOR__NONE) { /* (u, l0, inf), across (inf, l0) from (l0, w, inf) */
        vor__vertices(&tri[ga], v);
        gb = tri[ga].n[vor__next(find(v, l0))];
    }
    if (hb != VOR__NONE) { /* (r0, w, inf), across (r0, inf) from (u, r0, inf) */
        vor__vertices(&tri[hb], v);
        ha = tri[hb].n[vor__prev(find(v, r0))];
    }
    vor_index_t lower;
    vor_index_t cap;
    if (f_single) {
        lower = l0; /* the single site's home slot */
    } else if (s_single) {
        lower = r0;
    } else {
        lower = (vor_index_t)b->next_extra;
        b->next_extra++;
    }
    cap = (vor_index_t)b->next_extra;
    b->next_extra++;
    put(tri, lower, r0, l0, VOR__INFINITE, (ga != VOR__NONE) ? ga : cap,
        (hb != VOR__NONE) ? hb : cap, cap);
    put(tri, cap, l0, r0, VOR__INFINITE, (ha != VOR__NONE) ? ha : lower,
        (gb != VOR__NONE) ? gb : lower, lower);
    if (ga != VOR__NONE) {
        vor__relink_before(tri, ga, l0, lower);
        vor__relink_before(tri, gb, VOR__INFINITE, cap);
    }
    if (hb != VOR__NONE) {
        vor__relink_before(tri, hb, VOR__INFINITE, lower);
        vor__relink_before(tri, ha, r0, cap);
    }
    /* the base's ends are marked (joined()); both home slots hold
     * triangles now */
    vor__set_mark(&tri[l0], true);
    vor__set_mark(&tri[r0], true);
    *cap_slot = cap;
    return lower;
}

/* Is v a site on the given side of the merge (F: left true, S: false)? */
static inline bool on_side(const builder_t *b, vor_index_t v, bool left)
{
    return v != VOR__INFINITE && in_f_finite(b, v) == left;
}

/* One side's deletions in the zipper, the two sides mirrored. The pocket
 * ghost at `pocket` is (c1, l, inf) on the left, (r, e1, inf) on the
 * right; its candidate c1 (e1) is valid when it is on its side and above
 * the base (l, r), already known when still_valid. While it is, the edge
 * (l, c1) ((r, e1)) is deleted if the triangle beyond it has its far
 * vertex c2 on the same side (C2 and T1) inside the circle through l, r
 * and the candidate: a flip, after which c2 is the candidate. Returns the
 * last candidate; *valid tells whether it is valid. At most one deletion
 * per F-F-F (S-S-S) triangle: bounded with the merge. */
VOR__ALWAYS_INLINE vor_index_t delete_side(builder_t *b, vor_index_t pocket_in, bool left,
                                           vor_index_t l, vor_index_t r, bool still_valid_in,
                                           bool *valid)
{
    vor_index_t pocket = pocket_in;
    bool still_valid = still_valid_in;
    vor__tri_t *tri = b->tri;
    vor_index_t pv[3];
    vor_index_t v[3];
    vor__vertices(&tri[pocket], pv);
    unsigned inf = find(pv, VOR__INFINITE); /* found: the cap's edge */
    VOR_ASSERT(inf < 3u);
    vor_index_t c1 = left ? pv[vor__next(inf)] : pv[vor__prev(inf)];
    for (;;) {
        *valid = on_side(b, c1, left) && (still_valid || orient(b, l, r, c1) > 0);
        still_valid = false;
        if (!*valid) {
            return c1;
        }
        vor__vertices(&tri[tri[pocket].n[inf]], v);
        vor_index_t c2 = third(v, left ? l : r, c1);
        if (!on_side(b, c2, left) || incircle(b, l, r, c1, c2) <= 0) {
            return c1;
        }
        vor_index_t x1;
        vor_index_t x2;
        flip(b, pocket, pv, inf, &x1, &x2);
        /* the next pocket ghost: x2 = (inf, c2, l), or x1 = (inf, r, c2) */
        pocket = left ? x2 : x1;
        pv[0] = VOR__INFINITE;
        pv[1] = left ? c2 : r;
        pv[2] = left ? l : c2;
        inf = 0;
        c1 = c2;
    }
}

/* Step 3, the zipper, bottom to top (Oishi and Sugihara, section 3.2,
 * fig. 3.1), from the base (l0, r0) under the cap. Bounded by the counts
 * in the header comment; `steps_left` is a last resort. Returns the
 * number of advances (cross triangles made). */
static uint32_t zipper(builder_t *b, vor_index_t l0, vor_index_t r0, vor_index_t cap_in)
{
    vor_index_t cap = cap_in;
    vor__tri_t *tri = b->tri;
    vor_index_t l = l0;
    vor_index_t r = r0;
    /* The cap (l, r, inf) is always written by put() or flip() in a
     * known rotation: cv holds its vertices, with l at cv[il] and r at
     * cv[ir]; the F pocket ghost lies across (l, inf), the S one across
     * (inf, r). */
    vor_index_t cv[3] = {l0, r0, VOR__INFINITE};
    unsigned il = 0;
    unsigned ir = 1;
    bool l_moved = false;
    bool r_moved = false;
    /* A candidate that stayed while the other side advanced by the circle
     * test is still above the new base, exactly: were the S candidate e
     * below (c, r) after the base (l, r) moved to (c, r), it would lie in
     * the triangle (l, r, c), which its circle contains, or beyond (c, l),
     * where the segment (r, e) crosses (l, c) and no line could separate
     * F from S (mirrored for F). Its test is skipped. */
    bool l_still_valid = false;
    bool r_still_valid = false;
    uint32_t steps_left = (4u * b->bound) + 16u;
    uint32_t advances = 0;
    while (steps_left-- > 0u) {
        /* the candidates above the base */
        bool lvalid;
        bool rvalid;
        vor_index_t c1 = delete_side(b, tri[cap].n[ir], true, l, r, l_still_valid, &lvalid);
        vor_index_t e1 = delete_side(b, tri[cap].n[il], false, l, r, r_still_valid, &rvalid);
        /* the next F-S edge: (c1, r) or (l, e1), whichever keeps the
         * other candidate outside its triangle's circle (the deletions on
         * one side leave the other side's candidate as it was) */
        bool circle_left = lvalid && rvalid && incircle(b, l, r, c1, e1) < 0;
        bool circle_right = lvalid && rvalid && !circle_left;
        bool left = lvalid && (!rvalid || circle_left);
        bool right = rvalid && !left;
        /* C3: never a parallel edge; then the other candidate, if valid */
        if (left && joined(b, c1, r)) {
            left = false;
            right = rvalid && !joined(b, e1, l);
        } else if (right && joined(b, e1, l)) {
            right = false;
            left = lvalid && !joined(b, c1, r);
        } else {
            /* no other case */
        }
        if (!left && !right) {
            /* T2: each end moves at least once (never needed when the
             * signs are right) */
            if (!l_moved && on_side(b, c1, true) && !joined(b, c1, r)) {
                left = true;
            } else if (!r_moved && on_side(b, e1, false) && !joined(b, e1, l)) {
                right = true;
            } else {
                break;
            }
        }
        r_still_valid = left && circle_left;
        l_still_valid = right && circle_right;
        vor_index_t x1;
        vor_index_t x2;
        if (left) { /* cap (l, r, inf) + (c1, l, inf) -> (r, inf, c1) + (r, c1, l) */
            flip(b, cap, cv, ir, &x1, &x2);
            cap = x1;
            l = c1;
            cv[0] = r;
            cv[1] = VOR__INFINITE;
            cv[2] = l;
            il = 2;
            ir = 0;
            l_moved = true;
        } else { /* cap + (r, e1, inf) -> (l, r, e1) + (l, e1, inf) */
            flip(b, cap, cv, il, &x1, &x2);
            cap = x2;
            r = e1;
            cv[0] = l;
            cv[1] = r;
            cv[2] = VOR__INFINITE;
            il = 0;
            ir = 1;
            r_moved = true;
        }
        vor__set_mark(&tri[left ? l : r], true);
        advances++;
    }
    return advances;
}

/* After the zipper: clears the marks. The base's ends were the vertices of the
 * strip of cross triangles from (l0, r0) up to the cap. Cross triangles
 * are never flipped (deletions flip F-F-F and S-S-S triangles, advances
 * the cap), so the strip is intact: from base (l, r) the triangle above
 * is (l, r, c), and the next base is (c, r) if c is in F, else (l, c).
 * One step per advance. */
static void clear_marks(builder_t *b, vor_index_t lower, vor_index_t l0, vor_index_t r0,
                        uint32_t advances)
{
    vor__tri_t *tri = b->tri;
    vor_index_t v[3];
    vor_index_t l = l0;
    vor_index_t r = r0;
    vor__set_mark(&tri[l], false);
    vor__set_mark(&tri[r], false);
    vor__vertices(&tri[lower], v);
    vor_index_t t = tri[lower].n[find(v, VOR__INFINITE)];
    for (uint32_t k = 0; k < advances; k++) {
        vor__vertices(&tri[t], v);
        vor_index_t c = third(v, l, r);
        if (c == VOR__INFINITE) {
            break;
        }
        vor__set_mark(&tri[c], false);
        if (in_f(b, c)) { /* across (c, r), opposite l */
            t = tri[t].n[find(v, l)];
            l = c;
        } else {
            t = tri[t].n[find(v, r)];
            r = c;
        }
    }
}

/* Merges the parts F and S (every site of F before every site of S on
 * `axis`; b->by_line, split etc. set for in_f), neither empty, into one;
 * returns it (its lower ghost): steps 1 to 3 of the header comment, then
 * the marks cleared. */
static vor_index_t merge(builder_t *b, vor_index_t f, vor_index_t s, unsigned axis)
{
    b->axis = axis;
    bool f_single = is_single(b, f);
    bool s_single = is_single(b, s);
    if (f_single && s_single) {
        vor__make_edge(b->d, f, s);
        return f;
    }
    tangent_t t;
    lower_tangent(b, f, s, f_single, s_single, &t);
    vor_index_t cap;
    vor_index_t lower = glue(b, &t, f_single, s_single, &cap);
    uint32_t advances = zipper(b, t.l, t.r, cap);
    clear_marks(b, lower, t.l, t.r, advances);
    return lower;
}

/* ------------------------------------------------------------------ */
/* The builders                                                        */

/* Pending parts of the x-split, the least site of each for in_f. */
struct pending {
    vor_index_t part;
    vor_index_t least;
};

/* Three sites as a part: the triangle (p, q, r) or (p, r, q), whichever
 * the orientation test calls counterclockwise, and its three ghosts
 * (Guibas and Stolfi's base case: whatever the sign, a closed
 * triangulation of the sphere). The ghost (y, x, inf) behind the hull
 * edge (x, y) takes x's home slot, the finite triangle an extra slot.
 * Returns p's slot, a ghost. */
static vor_index_t triangle(builder_t *b, vor_index_t p, vor_index_t q_in, vor_index_t r_in)
{
    vor_index_t q = q_in;
    vor_index_t r = r_in;
    vor__tri_t *tri = b->tri;
    if (orient(b, p, q, r) < 0) {
        vor_index_t swap = q;
        q = r;
        r = swap;
    }
    vor_index_t t = (vor_index_t)b->next_extra;
    b->next_extra++;
    put(tri, t, p, q, r, q, r, p);
    put(tri, p, q, p, VOR__INFINITE, r, q, t);
    put(tri, q, r, q, VOR__INFINITE, p, r, t);
    put(tri, r, p, r, VOR__INFINITE, q, p, t);
    return p;
}

/* The classical x-split of the sorted sites order[0, v), v >= 1: a merge
 * of two halves, the recursion unrolled into a binary counter (Oishi and
 * Sugihara, section 3.2, horizontal merges only). The sites enter left to right in
 * leaves of three (two at the end if needed: 3 + 1 is 2 + 2; a lone site
 * only when v = 1), built directly; after the i-th leaf (1-based) the two
 * top parts are merged once for every trailing zero bit of i (equal
 * sizes, 2^j leaves each), and the rest right to left at the end. The
 * stack then holds one part per set bit of i plus one, i < VOR_MAX_SITES /
 * 3: at most 15 with 16-bit ids, 22 with 32-bit ids. */
#define SPLIT_STACK ((VOR_INDEX_BITS == 16) ? 15u : 22u)

/* The size of the x-split's next leaf when `left` sites remain. */
static inline uint32_t leaf_size(uint32_t left)
{
    return ((left <= 2u) || (left == 4u)) ? ((left == 1u) ? 1u : 2u) : 3u;
}

VOR__NOINLINE static vor_index_t build_split(builder_t *b, const vor_index_t *order, uint32_t v)
{
    VOR_ASSERT(v > 0u);
    struct pending stack[SPLIT_STACK];
    unsigned top = 0;
    uint32_t pos = 0;
    for (uint32_t i = 0; (pos < v) || (top > 1u); i++) {
        if (pos < v) {
            VOR_ASSERT(top < SPLIT_STACK);
            uint32_t size = leaf_size(v - pos);
            const vor_index_t *leaf = order + pos;
            if (size == 1u) {
                stack[top].part = single(b, leaf[0]);
            } else if (size == 2u) {
                vor__make_edge(b->d, leaf[0], leaf[1]);
                stack[top].part = leaf[0];
            } else {
                stack[top].part = triangle(b, leaf[0], leaf[1], leaf[2]);
            }
            pos += size;
            stack[top].least = leaf[0];
            top++;
        }
        /* merge pairs of equal size; once every leaf is in, all pairs */
        for (uint32_t c = i + 1u; (top > 1u) && ((pos == v) || (c & 1u) == 0u); c >>= 1) {
            b->by_line = false;
            b->split = stack[top - 1u].least;
            stack[top - 2u].part = merge(b, stack[top - 2u].part, stack[top - 1u].part, 0);
            top--;
        }
    }
    return stack[0].part;
}

/* For the lexicographically sorted ids[0, count) (equal points adjacent,
 * the first occurrence first): reports the duplicates, empties their home
 * slots, and moves the distinct ids to the front, keeping their order.
 * Returns their number. */
VOR__ALWAYS_INLINE uint32_t keep_distinct(builder_t *b, vor_index_t *ids, uint32_t count)
{
    const vor_point_t *p = b->d->sites;
    uint32_t m = 0;
    for (uint32_t i = 0; i < count; i++) {
        vor_index_t s = ids[i];
        vor_index_t first = (m > 0u) ? ids[m - 1u] : s;
        if ((m > 0u) && (p[s].x == p[first].x) && (p[s].y == p[first].y)) {
            vor__tri_fresh(&b->tri[s]); /* a duplicate's home slot stays empty */
            b->tri[s].n[0] = VOR__NONE;
        } else {
            ids[m] = s;
            m++;
            first = s;
        }
        if (b->duplicate_of != NULL) {
            b->duplicate_of[s] = first;
        }
    }
    return m;
}

/* Sorts the sites ids[0, count), count >= 1, drops the duplicates and
 * counts the rest as built (the last of them too); returns their number. */
VOR__ALWAYS_INLINE uint32_t sort_distinct(builder_t *b, vor_index_t *ids, uint32_t count)
{
    if (count > 1u) {
        vor__sort_ids(b->d->sites, ids, count, VOR__SORT_LEX);
    }
    uint32_t m = keep_distinct(b, ids, count);
    b->distinct += m;
    b->last = ids[m - 1u];
    return m;
}

/* Sorts the sites ids[0, count), drops the duplicates and builds the
 * rest by the x-split; returns the part (VOR__NONE if count is 0). */
static vor_index_t build_sites(builder_t *b, vor_index_t *ids, uint32_t count)
{
    if (count == 0u) {
        return VOR__NONE;
    }
    return build_split(b, ids, sort_distinct(b, ids, count));
}

/* F and S merged on an axis (in_f set up by the caller), either possibly
 * empty (VOR__NONE). */
static vor_index_t combine(builder_t *b, vor_index_t f, vor_index_t s, unsigned axis)
{
    if (f == VOR__NONE) {
        return s;
    }
    if (s == VOR__NONE) {
        return f;
    }
    return merge(b, f, s, axis);
}

/* A bucket of more than CROWDED sites (a cluster) is not built by the
 * x-split, which would cut it into thin strips, but by its own quadtree,
 * subdivided where the sites are: the quadtree order down to squares of at
 * most CROWDED sites, at most CROWDED_LEVELS levels deep (then the
 * x-split, which is correct at any size). */
#define CROWDED 8u
#define CROWDED_LEVELS 20u

/* Moves the ids[0, count) whose coordinate (x on axis 0, y on axis 1) is
 * below `line` to the front; returns their number. */
static uint32_t partition_below(const vor_point_t *p, vor_index_t *ids, uint32_t count,
                                unsigned axis, int64_t line)
{
    uint32_t i = 0;
    uint32_t j = count;
    while (i < j) {
        const vor_point_t *q = &p[ids[i]];
        if ((int64_t)((axis == 0u) ? q->x : q->y) < line) {
            i++;
        } else {
            j--;
            vor_index_t swap = ids[i];
            ids[i] = ids[j];
            ids[j] = swap;
        }
    }
    return i;
}

/* Is site q in the square with corner (ox, oy) and side 2^s? */
static inline bool in_square(const vor_point_t *q, int64_t ox, int64_t oy, unsigned s)
{
    int64_t dx = (int64_t)q->x - ox;
    int64_t dy = (int64_t)q->y - oy;
    return vor__shr_u64((uint64_t)dx | (uint64_t)dy, s) == 0u;
}

/* Builds the crowded bucket ids[0, count) (count > CROWDED): over the
 * bounding square of its sites, a square of more than CROWDED sites is
 * split in four (its ids partitioned in place: bottom left, bottom right,
 * top left, top right, so each child is a run) and its children are
 * merged like the grid's; smaller squares are built by build_sites. The
 * squares are visited depth first; each level holds its child index, the
 * finished bottom pair (or first child) and the third child. */
VOR__NOINLINE static vor_index_t build_crowded(builder_t *b, vor_index_t *ids, uint32_t count)
{
    const vor_point_t *p = b->d->sites;
    int64_t ox = p[ids[0]].x;
    int64_t oy = p[ids[0]].y;
    int64_t hx = ox;
    int64_t hy = oy;
    for (uint32_t i = 1; i < count; i++) {
        const vor_point_t *q = &p[ids[i]];
        ox = (q->x < ox) ? q->x : ox;
        oy = (q->y < oy) ? q->y : oy;
        hx = (q->x > hx) ? q->x : hx;
        hy = (q->y > hy) ? q->y : hy;
    }
    uint64_t span = (uint64_t)(((hx - ox) > (hy - oy)) ? (hx - ox) : (hy - oy));
    unsigned s = 0; /* the current square: corner (ox, oy), side 2^s */
    while (vor__shr_u64(span, s) != 0u) {
        s++;
    }
    vor_index_t bottom[CROWDED_LEVELS];
    vor_index_t third_child[CROWDED_LEVELS];
    uint8_t child[CROWDED_LEVELS];
    unsigned level = 0;
    uint32_t pos = 0;
    for (;;) {
        uint32_t end = pos;
        while ((end < count) && in_square(&p[ids[end]], ox, oy, s)) {
            end++;
        }
        if (((end - pos) > CROWDED) && (s > 0u) && ((level + 1u) < CROWDED_LEVELS)) {
            /* split it and go on with its first child */
            s--;
            int64_t side = (int64_t)vor__shl_u64(1u, s);
            uint32_t lower = partition_below(p, ids + pos, end - pos, 1, oy + side);
            (void)partition_below(p, ids + pos, lower, 0, ox + side);
            (void)partition_below(p, ids + pos + lower, end - pos - lower, 0, ox + side);
            level++;
            child[level] = 0;
            continue;
        }
        vor_index_t part = build_sites(b, ids + pos, end - pos);
        pos = end;
        /* the square is finished: on to its next sibling, merging the
         * parent (and further up) when it was the last child */
        for (;;) {
            if (level == 0u) {
                return part;
            }
            int64_t side = (int64_t)vor__shl_u64(1u, s);
            unsigned c = child[level];
            if ((c == 0u) || (c == 2u)) {
                if (c == 0u) {
                    bottom[level] = part;
                } else {
                    third_child[level] = part;
                }
                ox += side;
                break;
            }
            /* right child: F left of its left edge */
            b->by_line = true;
            b->f_above = false;
            b->line = ox;
            if (c == 1u) {
                bottom[level] = combine(b, bottom[level], part, 0);
                ox -= side;
                oy += side;
                break;
            }
            vor_index_t top = combine(b, third_child[level], part, 0);
            /* top over bottom: F from its lower edge up */
            b->by_line = true;
            b->f_above = true;
            b->line = oy;
            part = combine(b, top, bottom[level], 1);
            ox -= side;
            oy -= side;
            s++;
            level--;
        }
        child[level]++;
    }
}

/* Katajainen and Koppinen's bucket merging in quadtree order (Oishi and
 * Sugihara, sections 1, 3.1): two to eight sites a bucket, each bucket built by the
 * x-split (or, when crowded, by build_crowded), then every square of four
 * merged from its children: bottom pair and top pair horizontally, then
 * the two halves vertically (the horizontal merge turned by 90 degrees).
 * ids[0, n) are grouped by bucket in Z order (group_by_bucket); each
 * bucket is sorted just before it is built. The buckets are visited in Z
 * order, a base-4 counter: at each level the finished bottom pair (or its
 * first child) and the third child wait, two words a level. */
/* levels 0..k with 4^k <= 2n <= 2 VOR_MAX_SITES (group_by_bucket): k <= 7
 * with 16-bit ids, k <= 10 with 32-bit ids */
#define QUADTREE_LEVELS ((VOR_INDEX_BITS == 16) ? 8u : 11u)

/* The least coordinate (x on axis 0, y on axis 1) in grid column (row)
 * `index` or beyond: (c - x0) 2^k / 2^shift >= index iff
 * c - x0 >= ceil(index 2^shift / 2^k); index <= 2^12, shift <= 32. */
static int64_t grid_line(const builder_t *b, uint32_t index, unsigned axis)
{
    unsigned k = b->k;
    uint64_t offset = vor__shr_u64(vor__shl_u64(index, b->square->shift) + ((1u << k) - 1u), k);
    return ((axis == 0u) ? b->square->x0 : b->square->y0) + (int64_t)offset;
}

/* Top over bottom, the square's two halves (it starts at cell z0, its
 * children have side 2^side_log cells): F = the top, rows from the
 * middle on. */
VOR__ALWAYS_INLINE vor_index_t merge_vertical(builder_t *b, vor_index_t top, vor_index_t bottom,
                                              uint32_t z0, unsigned side_log)
{
    b->by_line = true;
    b->f_above = true;
    b->line = grid_line(b, vor__compact_bits(z0 >> 1) + (1u << side_log), 1);
    return combine(b, top, bottom, 1);
}

/* Builds the buckets [from_cell, to_cell) in Z order, their ids grouped in
 * ids[0, n): all of them [0, 4^k), returning the root; or one half of the
 * grid for vor_build_dc_forked: the bottom half [0, 4^k / 2), returning
 * the bottom pair's merge of the top square, or the top half [4^k / 2,
 * 4^k), returning its top pair's merge (merged with a bottom pair of
 * VOR__NONE, i.e. not at all). */
VOR__NOINLINE static vor_index_t build_quadtree(builder_t *b, vor_index_t *ids, uint32_t n,
                                                uint32_t from_cell, uint32_t to_cell)
{
    vor_t *d = b->d;
    unsigned k = b->k;
    uint32_t cells = 1u << (2u * k);
    vor_index_t bottom[QUADTREE_LEVELS];
    vor_index_t third_child[QUADTREE_LEVELS];
    vor_index_t root = VOR__NONE;
    bottom[1] = VOR__NONE; /* the top half alone has no bottom pair */
    uint32_t pos = 0;
    for (uint32_t c = from_cell; c < to_cell; c++) {
        uint32_t end = pos;
        while ((end < n) && vor__grid_z(d, ids[end], k, b->square) == c) {
            end++;
        }
        /* sites are numbered in input order, so the next buckets' sites
         * and home slots lie anywhere in the arena */
        for (uint32_t ahead = end; VOR__PREFETCHING && (ahead < (end + 4u)) && ((ahead + 12u) < n);
             ahead++) {
            VOR__PREFETCH(&d->sites[ids[ahead + 12u]]);
            VOR__PREFETCH(&b->tri[ids[ahead + 12u]]);
        }
        /* each bucket is sorted and built while its sites are in the cache */
        vor_index_t part = ((end - pos) > CROWDED) ? build_crowded(b, ids + pos, end - pos)
                                                 : build_sites(b, ids + pos, end - pos);
        pos = end;
        /* the children of one square are the squares of side 2^(k -
         * level) cells in it; the one just finished is child number
         * `child` of its parent, which starts at cell z0 */
        for (unsigned level = k;; level--) {
            if (level == 0u) {
                root = part;
                break;
            }
            unsigned side_log = k - level;
            uint32_t z0 = (c >> ((2u * side_log) + 2u)) << ((2u * side_log) + 2u);
            unsigned child = (c >> (2u * side_log)) & 3u;
            if (child == 0u) {
                bottom[level] = part;
                break;
            }
            if (child == 2u) {
                third_child[level] = part;
                break;
            }
            /* left and right children: F left of the middle column */
            b->by_line = true;
            b->f_above = false;
            b->line = grid_line(b, vor__compact_bits(z0) + (1u << side_log), 0);
            if (child == 1u) {
                bottom[level] = combine(b, bottom[level], part, 0);
                break;
            }
            vor_index_t top = combine(b, third_child[level], part, 0);
            part = merge_vertical(b, top, bottom[level], z0, side_log);
        }
    }
    return (to_cell == cells) ? root : bottom[1];
}

/* The number of cells of the 2^k x 2^k grid over the square that the
 * sites' bounding box meets: columns times rows, at most 4^k. */
static uint32_t box_cells(const vor_t *d, const vor__grid_square_t *square, unsigned k)
{
    uint32_t columns = vor__grid_cell(d->high.x, square->x0, k, square->shift) -
                       vor__grid_cell(d->low.x, square->x0, k, square->shift) + 1u;
    uint32_t rows = vor__grid_cell(d->high.y, square->y0, k, square->shift) -
                    vor__grid_cell(d->low.y, square->y0, k, square->shift) + 1u;
    return columns * rows;
}

/* Groups the ids[0, n) of the sites by quadtree bucket (n >= 8): the grid
 * sort into 4^k buckets, of which the C that the bounding box meets hold
 * two to eight sites on average, n / 8 < C <= n / 2 (C grows at most
 * fourfold a level). Counting the box's cells rather than the square's
 * keeps the buckets that small when the box fills only part of its
 * power-of-two square: a span of 2^32 / 3 fills 45 % of it, and counted
 * by the square its buckets held 8.5 sites on average, which took as many
 * instructions but 5-8 % more time at 10^6 sites. Sets b->k and
 * b->square. Its counters lie right below ids: 4^k + 1 <= 2 n + 1
 * entries, which with the n ids fit in the max_sites - 2 >= n - 2 slots
 * above the home slots, 5 or 6 ids a slot (4^k + 1 + n <= 5 (n - 2) for
 * n >= 8), and are free until the build starts. Out of line: its frame is
 * not on the merges' stack. */
VOR__NOINLINE static void group_by_bucket(builder_t *b, vor_index_t *ids, uint32_t n)
{
    vor__grid_square(b->d, true, b->square);
    while ((b->k + 1u) < QUADTREE_LEVELS &&
           vor__shl_u64(box_cells(b->d, b->square, b->k), 3u) <= n &&
           vor__shl_u64(1u, 2u * (b->k + 1u)) <= (2u * (uint64_t)n)) {
        b->k++;
    }
    vor__grid_sort(b->d, n, b->k, b->square, VOR__CELL_Z, ids - ((1u << (2u * b->k)) + 1u), ids);
}

/* ------------------------------------------------------------------ */
/* The entry points                                                    */

/* A builder for d's n sites, counting into stats, its extras from
 * next_extra on. Field by field: no structure copies (memcpy). */
static void builder_init(builder_t *b, vor_t *d, uint32_t n, uint32_t *duplicate_of,
                         vor_stats_t *stats, uint32_t next_extra,
                         vor__grid_square_t *square)
{
    b->d = d;
    b->tri = d->triangles;
    b->stats = stats;
    b->duplicate_of = duplicate_of;
    b->next_extra = next_extra;
    b->distinct = 0;
    b->last = 0;
    b->axis = 0;
    b->by_line = false;
    b->f_above = false;
    b->split = 0;
    b->line = 0;
    b->k = 0;
    b->square = square;
    b->bound = (2u * n) + 2u;
}

/* What both entry points do first: the checks and vor__build_start (a
 * negative error or VOR_OK: done), then the builder and the place of the
 * site ids. The site ids at the top of the triangle slots, read front to
 * back while triangles fill the slots from below: once the first i ids
 * are read, at most i - 2 extra slots are in use (one fewer per duplicate
 * among them), and the n - i ids still to be read fit above them because
 * an id is smaller than a triangle. For max_sites >= 3 they start above
 * the home slots (a two-slot mesh is read first). Each bucket (or, for
 * the x-split, the whole array) is sorted in place and its distinct ids
 * moved to its front before it is built. */
VOR__ALWAYS_INLINE int start(builder_t *b, vor_t *d, const vor_point_t *points, uint32_t n,
                             enum vor_dc_split split, uint32_t *duplicate_of,
                             vor__grid_square_t *square, vor_index_t **ids)
{
    if ((split != VOR_DC_QUADTREE) && (split != VOR_DC_XSPLIT)) {
        return VOR_ERR_ARG;
    }
    int status = vor__build_start(d, points, n, duplicate_of);
    if (status != VOR__BUILD_MESH) {
        return status;
    }
    builder_init(b, d, n, duplicate_of, VOR__STATS_OF(d), d->max_sites, square);
    vor_index_t *base = (vor_index_t *)(void *)d->triangles;
    size_t entries = (size_t)vor__triangle_count(d->max_sites) * sizeof(vor__tri_t) /
                     sizeof(vor_index_t);
    *ids = base + entries - n;
    return VOR__BUILD_MESH;
}

/* The ids 0 .. n - 1 in ids[0, n), for the x-split. */
static void all_ids(vor_index_t *ids, uint32_t n)
{
    for (uint32_t s = 0; s < n; s++) {
        ids[s] = (vor_index_t)s;
    }
}

/* The whole build on the calling core. */
VOR__ALWAYS_INLINE void build_all(builder_t *b, vor_index_t *ids, uint32_t n,
                                  enum vor_dc_split split)
{
    if ((split == VOR_DC_QUADTREE) && (n >= 8u)) {
        group_by_bucket(b, ids, n);
        (void)build_quadtree(b, ids, n, 0, 1u << (2u * b->k));
    } else {
        all_ids(ids, n);
        (void)build_sites(b, ids, n);
    }
}

VOR__ALWAYS_INLINE void finish(const builder_t *b)
{
    vor_t *d = b->d;
    d->vertex_count = b->distinct;
    d->last_site = b->last;
    vor__grid_rebuild(d);
    if (d->cdt_update != NULL) {
        (void)d->cdt_update(d, VOR_NO_HINT, VOR__CDT_REBUILT);
    }
}


/* ------------------------------------------------------------------ */
/* Two cores (vor_build_dc_forked)                                     */

/* One half of a forked build: its own builder and predicate counters, its
 * ids, and what it built. The quadtree halves are cell ranges; to_cell 0
 * marks an x-split half (its distinct sorted ids, leaves of the x-split). */
typedef struct {
    builder_t b;
#if VOR_STATS
    vor_stats_t stats;
#endif
    vor_index_t *ids;
    uint32_t count;
    uint32_t from_cell;
    uint32_t to_cell;
    vor_index_t part;
} half_t;

/* The work handed to the hook: builds one half. */
static void build_half(void *arg)
{
    half_t *h = (half_t *)arg;
    h->part = (h->to_cell != 0u)
                  ? build_quadtree(&h->b, h->ids, h->count, h->from_cell, h->to_cell)
                  : build_split(&h->b, h->ids, h->count);
}

#if VOR_STATS
/* Counters add modulo 2^32, as one build's would have wrapped. */
static void stats_add(vor_stats_t *to, const vor_stats_t *from)
{
    for (unsigned t = 0; t < (unsigned)VOR_TIERS; t++) {
        to->orient2d[t] += from->orient2d[t];
        to->incircle[t] += from->incircle[t];
        to->closer[t] += from->closer[t];
    }
    to->orient2d_perturbed += from->orient2d_perturbed;
    to->incircle_perturbed += from->incircle_perturbed;
    to->closer_perturbed += from->closer_perturbed;
    to->power += from->power;
    to->power_perturbed += from->power_perturbed;
}
#define HALF_STATS(x) (&(x)->stats)
#else
#define HALF_STATS(x) ((vor_stats_t *)NULL)
#endif

/* The x-split of m sorted distinct sites ends with the merge of its first
 * 2^j leaves and the rest, 2^j < leaves <= 2^(j + 1) (build_split: the
 * binary counter's highest bit, or the two halves when the count is a
 * power of two). Returns the first part's number of sites. */
static uint32_t xsplit_first_part(uint32_t m)
{
    uint32_t leaves = 0;
    for (uint32_t pos = 0; pos < m; leaves++) {
        pos += leaf_size(m - pos);
    }
    uint32_t first = 1;
    while ((2u * first) < leaves) {
        first *= 2u;
    }
    uint32_t sites = 0;
    for (uint32_t leaf = 0; leaf < first; leaf++) {
        sites += leaf_size(m - sites);
    }
    return sites;
}

/* The number of ids[0, n) (grouped in Z order) in the bottom half of the
 * grid, cells below `half`: a binary search. */
static uint32_t quadtree_first_part(const builder_t *b, const vor_index_t *ids, uint32_t n,
                                    uint32_t half)
{
    uint32_t low = 0;
    uint32_t high = n;
    while (low < high) {
        uint32_t mid = low + ((high - low) >> 1);
        if (vor__grid_z(b->d, ids[mid], b->k, b->square) < half) {
            low = mid + 1u;
        } else {
            high = mid;
        }
    }
    return low;
}

/* Moves the second half's extras, tri[from, from + count), down by gap
 * slots onto the end of the first half's, and every link into them with
 * them: those of the second half's home slots and of its extras (the
 * first half's triangles link none of them). All home slots of the sites
 * [0, n) are looked at: the first half's have no such link, duplicates'
 * are empty. */
static void close_gap(vor__tri_t *tri, uint32_t n, uint32_t from, uint32_t count, uint32_t gap)
{
    for (uint32_t slot = 0; slot < (n + count); slot++) {
        uint32_t at = (slot < n) ? slot : (from + (slot - n));
        vor__tri_t *t = &tri[(slot < n) ? at : (at - gap)];
        if (slot >= n) { /* field by field: no memmove */
            const vor__tri_t *old = &tri[at];
            for (unsigned i = 0; i < sizeof t->v / sizeof t->v[0]; i++) {
                t->v[i] = old->v[i];
            }
            for (unsigned i = 0; i < 3u; i++) {
                t->n[i] = old->n[i];
            }
        } else if (vor__slot_empty(t)) {
            continue;
        } else {
            /* no other case */
        }
        for (unsigned i = 0; i < 3u; i++) {
            if (((uint32_t)t->n[i] - from) < count) {
                t->n[i] = (vor_index_t)(t->n[i] - gap);
            }
        }
    }
}

/* the quadtree needs 8 sites (group_by_bucket) before it can fork */
#define FORK_MIN_SITES_LEAST 8u
typedef char vor__fork_min_check[(VOR_DC_FORK_MIN_SITES_DEFAULT >= FORK_MIN_SITES_LEAST) ? 1 : -1];

/* a triangle is a whole number of ids (12 = 6 x 2 or 20 = 5 x 4 bytes) */
typedef char vor__ids_per_triangle_check[(sizeof(vor__tri_t) % sizeof(vor_index_t) == 0u) ? 1 : -1];

/*
 * The two halves on two cores: the first (A: the bottom half of the grid,
 * or the x-split's first part) through the hook, the second (B) on the
 * calling core, then the last merge here. Every slot either writes is its
 * own (docs/design/divide-and-conquer.md, "Two cores"): A's and B's sites are disjoint, so
 * are their home slots, marks and duplicate_of entries; each counts into
 * its own stats; and the extra slots and ids are split into two regions
 * in which the sequential invariant of start() holds:
 *   A: extras from max_sites, its nA ids moved to end where B's extras
 *      begin, at slot E = max_sites + nA - 2. A region whose ids end at
 *      the start of slot X and whose extras start at slot S holds the
 *      invariant iff S + (its ids) - 2 <= X: writing extra S + e needs
 *      e + 3 ids read, and the unread ids need (ids - e - 3) id sizes,
 *      less than the same number of slots. For A it is an equality; its
 *      ids start above the home slots when nA (T - I) >= 2 T (T, I the
 *      sizes of a triangle and an id), which nA >= 3 gives.
 *   B: extras from E, its nB = n - nA ids (mB after the x-split's
 *      deduplication) where they are, at the top: E + nB - 2 =
 *      max_sites + n - 4 <= 2 max_sites - 2.
 * Moving A's ids moves them down (their new end, E slots, is at or below
 * the old one: nA T + nB I <= n T <= max_sites T), so a forward copy is
 * safe. The sequential build allocates A's extras, then B's, then the
 * last merge's two; here B's start nA - 2 - (A's extras) slots later when
 * A had duplicates, and close_gap moves them down. Slot numbers decide
 * nothing in a merge (only whether a slot is a home slot), so the mesh is
 * then the sequential one byte for byte.
 */
VOR__NOINLINE static void build_forked(builder_t *b, vor_index_t *ids, uint32_t n,
                                       enum vor_dc_split split, const vor_fork_join_t *hook)
{
    vor_t *d = b->d;
    uint32_t count = n;
    uint32_t n_a;
    uint32_t cells = 0;
    if (split == VOR_DC_QUADTREE) {
        group_by_bucket(b, ids, n);
        cells = 1u << (2u * b->k);
        n_a = quadtree_first_part(b, ids, n, cells >> 1);
    } else {
        all_ids(ids, n);
        count = sort_distinct(b, ids, n);
        n_a = xsplit_first_part(count);
    }
    if ((n_a < 3u) || (count - n_a) < 3u) { /* one side (nearly) empty: no fork */
        if (split == VOR_DC_QUADTREE) {
            (void)build_quadtree(b, ids, n, 0, cells);
        } else {
            (void)build_split(b, ids, count);
        }
        return;
    }
    uint32_t gap_end = d->max_sites + n_a - 2u; /* E: B's first extra */
    vor_index_t *ids_a =
        (vor_index_t *)(void *)b->tri + (size_t)gap_end * (sizeof(vor__tri_t) / sizeof(vor_index_t)) - n_a;
    for (uint32_t i = 0; i < n_a; i++) {
        ids_a[i] = ids[i];
    }
    vor_index_t b_least = ids[n_a]; /* B's least site: the last merge's split */
    half_t half[2];
    for (unsigned h = 0; h < 2u; h++) {
        half_t *x = &half[h];
#if VOR_STATS
        vor__stats_clear(&x->stats);
#endif
        builder_init(&x->b, d, n, b->duplicate_of, HALF_STATS(x), (h == 0u) ? d->max_sites : gap_end,
                     b->square);
        x->b.k = b->k;
        x->ids = (h == 0u) ? ids_a : (ids + n_a);
        x->count = (h == 0u) ? n_a : (count - n_a);
        x->from_cell = (h == 0u) ? 0u : (cells >> 1);
        x->to_cell = (h == 0u) ? (cells >> 1) : cells;
        x->part = VOR__NONE;
    }
    half_t *a = &half[0];
    half_t *s = &half[1];
    /* A on the other core if the hook can; B here meanwhile */
    bool forked = hook->fork(hook->context, build_half, a) == 0;
    build_half(s);
    if (forked) {
        hook->join(hook->context);
    } else {
        build_half(a);
    }
    uint32_t used_b = s->b.next_extra - gap_end;
    uint32_t gap = gap_end - a->b.next_extra;
    if (gap > 0u) {
        close_gap(b->tri, n, gap_end, used_b, gap);
        if (((uint32_t)s->part - gap_end) < used_b) { /* B's part is one of its ghosts */
            s->part = (vor_index_t)(s->part - gap);
        }
    }
    b->next_extra = a->b.next_extra + used_b;
    b->distinct += a->b.distinct + s->b.distinct;
    b->last = (s->b.distinct > 0u) ? s->b.last : b->last; /* the x-split's is set */
#if VOR_STATS
    stats_add(b->stats, &a->stats);
    stats_add(b->stats, &s->stats);
#endif
    if (split == VOR_DC_QUADTREE) {
        (void)merge_vertical(b, s->part, a->part, 0, b->k - 1u);
    } else {
        b->by_line = false;
        b->split = b_least;
        (void)combine(b, a->part, s->part, 0);
    }
}

/* Both entry points: the build on the calling core, or through the hook
 * when there is one and the build is large enough to fork. Inline, so that
 * vor_build_dc's constant NULL hook leaves build_forked out of a firmware
 * that calls only vor_build_dc. */
VOR__ALWAYS_INLINE int build_dc(vor_t *d, const vor_point_t *points, uint32_t n,
                                const vor_build_options_t *options, uint32_t *duplicate_of,
                                const vor_fork_join_t *hook)
{
    enum vor_dc_split split = (options != NULL) ? options->split : VOR_DC_QUADTREE;
    builder_t b;
    vor__grid_square_t square;
    vor_index_t *ids;
    int status = start(&b, d, points, n, split, duplicate_of, &square, &ids);
    if (status != VOR__BUILD_MESH) {
        return status;
    }
    bool faults = false;
#ifdef VOR_FAULT_INJECTION
    faults = d->fault_rate != 0u; /* one fault sequence: one core */
#endif
    uint32_t fork_min = VOR_DC_FORK_MIN_SITES_DEFAULT;
    if ((hook != NULL) && (options != NULL) && (options->fork_min_sites != 0u)) {
        fork_min = (options->fork_min_sites > FORK_MIN_SITES_LEAST) ? options->fork_min_sites
                                                                    : FORK_MIN_SITES_LEAST;
    }
    if ((hook == NULL) || (n < fork_min) || faults) {
        build_all(&b, ids, n, split);
    } else {
        build_forked(&b, ids, n, split, hook);
    }
    finish(&b);
    return VOR_OK;
}

int vor_build_dc(vor_t *d, const vor_point_t *points, uint32_t n,
                 const vor_build_options_t *options, uint32_t *duplicate_of)
{
    return build_dc(d, points, n, options, duplicate_of, NULL);
}

int vor_build_dc_forked(vor_t *d, const vor_point_t *points, uint32_t n,
                        const vor_build_options_t *options, uint32_t *duplicate_of,
                        const vor_fork_join_t *hook)
{
    if ((hook != NULL) && ((hook->fork == NULL) || (hook->join == NULL))) {
        return VOR_ERR_ARG;
    }
    return build_dc(d, points, n, options, duplicate_of, hook);
}
