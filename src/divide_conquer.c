/*
 * divide_conquer.c - the divide-and-conquer builder (Guibas and Stolfi,
 * Lee and Schachter), made unbreakable by numerical error with Oishi and
 * Sugihara's topological guards (seed 000 sections 3-4).
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
 *      of S (seed 000 section 4.1), guarded by C4 and C5;
 *   2. glue: the two spheres are joined at the vertex at infinity by two
 *      new triangles, the lower ghost (r0, l0, inf) and the "cap"
 *      (l0, r0, inf) over the base edge (l0, r0). The ghosts of both hulls
 *      plus the cap now form one fan around infinity; the hull chains
 *      between the cap and the lower ghost are the pocket still to fill;
 *   3. zipper (seed 000 section 3.2, fig. 3.1), with base (l, r) = the
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
 *      c2 in F). (docs/design.md: why not "both ends have F-S edges".)
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
 * fill the slots from below (see vor__build_dc); the recursion is an
 * explicit stack of O(log n) frames.
 */
#include "mesh.h"

/* ------------------------------------------------------------------ */
/* Orders                                                              */

/* Lexicographic order (x, y): after duplicates are removed it is the x
 * order of the plane turned by an infinitesimal angle, so the two halves
 * of a split are separated by a line and the leftmost site of a set is a
 * hull vertex even when many sites share an x. */
static bool lex_less(const vor_point_t *s, vor_index_t a, vor_index_t b)
{
    return s[a].x < s[b].x || (s[a].x == s[b].x && s[a].y < s[b].y);
}

/* The same turned by 90 degrees, (x', y') = (-y, x): top to bottom, for
 * vertical merges (seed 000 section 3.2: "rotate the algorithm"). */
static bool lex_less_rotated(const vor_point_t *s, vor_index_t a, vor_index_t b)
{
    return s[a].y > s[b].y || (s[a].y == s[b].y && s[a].x < s[b].x);
}

/* With ids breaking ties, for the sort (equal points adjacent, the first
 * occurrence first). */
static bool lex_less_id(const vor_point_t *s, vor_index_t a, vor_index_t b)
{
    if (s[a].x != s[b].x) {
        return s[a].x < s[b].x;
    }
    if (s[a].y != s[b].y) {
        return s[a].y < s[b].y;
    }
    return a < b;
}

/* ------------------------------------------------------------------ */
/* Components and the builder's state                                  */

/* A finished sub-triangulation: its size, its extreme sites in both
 * orders (axis 0: lex_less, axis 1: lex_less_rotated) and one of its
 * ghost triangles (count >= 2; a single site has no triangles). Slots of
 * other components never change during a merge, so the ghost stays. */
typedef struct {
    uint32_t count;
    vor_index_t first[2], last[2]; /* the least and greatest site per axis */
    vor_index_t ghost;
} component_t;

typedef struct {
    vor_t *d;
    vor__tri_t *tri;
    uint32_t next_extra; /* the next unused extra slot */
    bool (*less)(const vor_point_t *, vor_index_t, vor_index_t); /* this merge's axis */
    vor_index_t split;   /* the least site of S: v is in F iff v < split */
    uint32_t bound;      /* step bound for walks around a vertex */
} builder_t;

static bool in_f(const builder_t *b, vor_index_t v)
{
    return v != VOR__INFINITE && b->less(b->d->sites, v, b->split);
}

static bool in_s(const builder_t *b, vor_index_t v)
{
    return v != VOR__INFINITE && !b->less(b->d->sites, v, b->split);
}

/* The vertex of triangle t that is neither a nor c. */
static vor_index_t third(const vor__tri_t *t, vor_index_t a, vor_index_t c)
{
    vor_index_t v[3];
    vor__vertices(t, v);
    return (v[0] != a && v[0] != c) ? v[0] : (v[1] != a && v[1] != c) ? v[1] : v[2];
}

/* In triangle `slot`, point the link across the edge {a, b} at `to`. By
 * vertices, not by the old slot: a two-site mesh's triangles are each
 * other's neighbour across all three edges. */
static void relink_edge(vor__tri_t *tri, vor_index_t slot, vor_index_t a, vor_index_t b,
                        vor_index_t to)
{
    vor__tri_t *t = &tri[slot];
    for (unsigned i = 0; i < 3u; i++) {
        vor_index_t v = vor__vertex(t, i);
        if (v != a && v != b) {
            t->n[i] = to;
            return;
        }
    }
}

static bool is_home(const builder_t *b, vor_index_t slot, vor_index_t v)
{
    return slot == v && v < b->d->max_sites;
}

/* Flips the edge opposite vertex i1 of the triangle in slot s1 = (a, b, c)
 * with its neighbour (c, b, e): they become T1 = (a, b, e) and
 * T2 = (a, e, c), in the two slots chosen so that each home slot still
 * holds a triangle of its site (incremental.c's flip, with infinity
 * allowed anywhere). Returns T1's slot in *t1 and T2's in *t2. */
static void flip(builder_t *b, vor_index_t s1, unsigned i1, vor_index_t *t1, vor_index_t *t2)
{
    vor__tri_t *tri = b->tri;
    vor__tri_t *t = &tri[s1];
    vor_index_t a = vor__vertex(t, i1), bb = vor__vertex(t, vor__next(i1)),
                c = vor__vertex(t, vor__prev(i1));
    vor_index_t s2 = t->n[i1], nab = t->n[vor__prev(i1)], nca = t->n[vor__next(i1)];
    vor__tri_t *u = &tri[s2];
    unsigned ib = vor__vertex_index(u, bb);
    ib = (ib == 3u) ? 0u : ib; /* always found: the two share the edge */
    vor_index_t e = vor__vertex(u, vor__next(ib));
    vor_index_t nbe = u->n[vor__prev(ib)], nec = u->n[ib];
    vor_index_t x1 = s1, x2 = s2;
    if (is_home(b, s1, c) || is_home(b, s2, bb)) {
        x1 = s2;
        x2 = s1;
    }
    relink_edge(tri, nab, a, bb, x1);
    relink_edge(tri, nbe, bb, e, x1);
    relink_edge(tri, nec, e, c, x2);
    relink_edge(tri, nca, c, a, x2);
    vor__tri_set(&tri[x1], a, bb, e, nbe, x2, nab);
    vor__tri_set(&tri[x2], a, e, c, nec, nca, x1);
    *t1 = x1;
    *t2 = x2;
}

/* Is q a neighbour of site p? A walk around p from its home slot (C3;
 * seed 000 section 3.3: one endpoint's edges, O(1) on average). */
static bool has_edge(const builder_t *b, vor_index_t p, vor_index_t q)
{
    vor_index_t slot = p;
    for (uint32_t step = 0; step < b->bound; step++) {
        const vor__tri_t *t = &b->tri[slot];
        unsigned i = vor__vertex_index(t, p);
        if (i == 3u) {
            return true; /* only on a corrupted mesh: refuse the edge */
        }
        if (vor__vertex(t, vor__next(i)) == q || vor__vertex(t, vor__prev(i)) == q) {
            return true;
        }
        slot = t->n[vor__next(i)];
        if (slot == p) {
            break;
        }
    }
    return false;
}

/* The ghost (p, w, inf) at hull site p (w: p's clockwise neighbour on the
 * hull), by a walk around p; VOR__NONE if p is not on the hull. */
static vor_index_t ghost_after(const builder_t *b, vor_index_t p)
{
    vor_index_t slot = p;
    for (uint32_t step = 0; step < b->bound; step++) {
        const vor__tri_t *t = &b->tri[slot];
        unsigned i = vor__vertex_index(t, p);
        if (i == 3u) {
            return VOR__NONE;
        }
        if (vor__vertex(t, vor__prev(i)) == VOR__INFINITE) {
            return slot;
        }
        slot = t->n[vor__next(i)];
        if (slot == p) {
            break;
        }
    }
    return VOR__NONE;
}

/* Writes a fresh triangle into an unused slot (clearing what scratch data
 * left in its mark bit). */
static void put(vor__tri_t *tri, vor_index_t slot, vor_index_t v0, vor_index_t v1,
                vor_index_t v2, vor_index_t n0, vor_index_t n1, vor_index_t n2)
{
    vor__tri_fresh(&tri[slot]);
    vor__tri_set(&tri[slot], v0, v1, v2, n0, n1, n2);
}

/* ------------------------------------------------------------------ */
/* Merge                                                               */

/* Merges F and S (every site of F before every site of S on `axis`) into
 * *out. Both are marked on their hulls; so is the result. */
static void merge(builder_t *b, const component_t *f, const component_t *s, unsigned axis,
                  component_t *out)
{
    vor_t *d = b->d;
    vor__tri_t *tri = b->tri;
    b->less = (axis == 0u) ? lex_less : lex_less_rotated;
    b->split = s->first[axis];
    for (unsigned k = 0; k < 2u; k++) {
        bool (*order)(const vor_point_t *, vor_index_t, vor_index_t) =
            (k == 0u) ? lex_less : lex_less_rotated;
        out->first[k] = order(d->sites, f->first[k], s->first[k]) ? f->first[k] : s->first[k];
        out->last[k] = order(d->sites, f->last[k], s->last[k]) ? s->last[k] : f->last[k];
    }
    out->count = f->count + s->count;

    if (f->count == 1u && s->count == 1u) {
        vor_index_t a = f->first[0], c = s->first[0];
        vor__make_edge(d, a, c);
        out->ghost = a;
        return;
    }

    /* 1. lower common tangent (seed 000 section 4), from R1 and L2 */
    vor_index_t l = f->last[axis], r = s->first[axis];
    vor_index_t g1 = VOR__NONE, g2 = VOR__NONE; /* (l, w, inf) and (u, r, inf) */
    if (f->count >= 2u) {
        g1 = ghost_after(b, l);
        if (g1 == VOR__NONE) { /* only if earlier signs lied: any hull site */
            g1 = f->ghost;
            unsigned i = vor__vertex_index(&tri[g1], VOR__INFINITE);
            l = vor__vertex(&tri[g1], vor__next(i));
        }
    }
    if (s->count >= 2u) {
        vor_index_t h = ghost_after(b, r);
        if (h == VOR__NONE) {
            h = s->ghost;
            unsigned i = vor__vertex_index(&tri[h], VOR__INFINITE);
            r = vor__vertex(&tri[h], vor__next(i));
        }
        /* (r, w, inf) -> the ghost before it, (u, r, inf), across (inf, r) */
        unsigned i = vor__vertex_index(&tri[h], r);
        g2 = tri[h].n[vor__next(i)];
    }
    uint32_t moves1 = 0, moves2 = 0;
    for (;;) {
        /* C4: the F end stays between R1 and L1 (clockwise), the S end
         * between L2 and R2 (counterclockwise); C5: no move back. The
         * move counts bound the walks if the hulls are not convex. */
        if (g1 != VOR__NONE && l != f->first[axis] && moves1 < f->count) {
            unsigned i = vor__vertex_index(&tri[g1], l);
            vor_index_t w = vor__vertex(&tri[g1], vor__next(i));
            if (vor__orient(d, l, r, w) < 0) {
                g1 = tri[g1].n[i];
                l = w;
                moves1++;
                continue;
            }
        }
        if (g2 != VOR__NONE && r != s->last[axis] && moves2 < s->count) {
            unsigned i = vor__vertex_index(&tri[g2], r);
            vor_index_t u = vor__vertex(&tri[g2], vor__prev(i));
            if (vor__orient(d, l, r, u) < 0) {
                g2 = tri[g2].n[i];
                r = u;
                moves2++;
                continue;
            }
        }
        break;
    }
    vor_index_t l0 = l, r0 = r;

    /* 2. glue: the lower ghost (r0, l0, inf) and the cap (l0, r0, inf) */
    vor_index_t ga = g1, gb = VOR__NONE, ha = VOR__NONE, hb = g2;
    if (g1 != VOR__NONE) { /* (u, l0, inf), across (inf, l0) from (l0, w, inf) */
        unsigned i = vor__vertex_index(&tri[g1], l0);
        gb = tri[g1].n[vor__next(i)];
    }
    if (g2 != VOR__NONE) { /* (r0, w, inf), across (r0, inf) from (u, r0, inf) */
        unsigned i = vor__vertex_index(&tri[g2], r0);
        ha = tri[g2].n[vor__prev(i)];
    }
    vor_index_t lower, cap;
    if (f->count == 1u) {
        lower = l0; /* the single site's home slot */
    } else if (s->count == 1u) {
        lower = r0;
    } else {
        lower = (vor_index_t)b->next_extra++;
    }
    cap = (vor_index_t)b->next_extra++;
    put(tri, lower, r0, l0, VOR__INFINITE, (ga != VOR__NONE) ? ga : cap,
        (hb != VOR__NONE) ? hb : cap, cap);
    put(tri, cap, l0, r0, VOR__INFINITE, (ha != VOR__NONE) ? ha : lower,
        (gb != VOR__NONE) ? gb : lower, lower);
    if (ga != VOR__NONE) {
        relink_edge(tri, ga, l0, VOR__INFINITE, lower);
        relink_edge(tri, gb, l0, VOR__INFINITE, cap);
    }
    if (hb != VOR__NONE) {
        relink_edge(tri, hb, r0, VOR__INFINITE, lower);
        relink_edge(tri, ha, r0, VOR__INFINITE, cap);
    }

    /* 3. zipper, bottom to top (seed 000 section 3.2, fig. 3.1). Bounded
     * by the counts in the header comment; `steps` is a last resort. */
    bool l_moved = false, r_moved = false;
    uint32_t steps_left = 8u * out->count + 16u;
    while (steps_left-- > 0u) {
        /* left deletions: pocket ghost (c1, l, inf), F triangle (l, c1, c2) */
        vor_index_t c1, e1;
        for (;;) {
            vor_index_t pf = tri[cap].n[vor__vertex_index(&tri[cap], r)];
            c1 = third(&tri[pf], l, VOR__INFINITE);
            if (!in_f(b, c1) || vor__orient(d, l, r, c1) <= 0) {
                break;
            }
            unsigned at = vor__vertex_index(&tri[pf], VOR__INFINITE);
            vor_index_t c2 = third(&tri[tri[pf].n[at]], l, c1);
            /* C2 and T1: the triangle beyond is F-F-F */
            if (!in_f(b, c2) ||
                vor__incircle(d, l, r, c1, c2) <= 0) {
                break;
            }
            vor_index_t x1, x2;
            flip(b, pf, at, &x1, &x2);
        }
        /* right deletions: pocket ghost (r, d1, inf), S triangle (d1, r, d2) */
        for (;;) {
            vor_index_t ps = tri[cap].n[vor__vertex_index(&tri[cap], l)];
            e1 = third(&tri[ps], r, VOR__INFINITE);
            if (!in_s(b, e1) || vor__orient(d, l, r, e1) <= 0) {
                break;
            }
            unsigned at = vor__vertex_index(&tri[ps], VOR__INFINITE);
            vor_index_t e2 = third(&tri[tri[ps].n[at]], r, e1);
            if (!in_s(b, e2) ||
                vor__incircle(d, l, r, e1, e2) <= 0) {
                break;
            }
            vor_index_t x1, x2;
            flip(b, ps, at, &x1, &x2);
        }
        /* the next F-S edge: (c1, r) or (l, e1), whichever keeps the
         * other candidate outside its triangle's circle */
        bool lvalid = in_f(b, c1) && vor__orient(d, l, r, c1) > 0;
        bool rvalid = in_s(b, e1) && vor__orient(d, l, r, e1) > 0;
        bool left = lvalid && (!rvalid || vor__incircle(d, l, r, c1, e1) < 0);
        bool right = rvalid && !left;
        /* C3: never a parallel edge; then the other candidate, if valid */
        if (left && has_edge(b, c1, r)) {
            left = false;
            right = rvalid && !has_edge(b, e1, l);
        } else if (right && has_edge(b, e1, l)) {
            right = false;
            left = lvalid && !has_edge(b, c1, r);
        }
        if (!left && !right) {
            /* T2: each end moves at least once (never needed when the
             * signs are right) */
            if (!l_moved && in_f(b, c1) && !has_edge(b, c1, r)) {
                left = true;
            } else if (!r_moved && in_s(b, e1) && !has_edge(b, e1, l)) {
                right = true;
            } else {
                break;
            }
        }
        vor_index_t x1, x2;
        if (left) { /* cap (l, r, inf) + (c1, l, inf) -> (c1, r, inf) + (l, r, c1) */
            flip(b, cap, vor__vertex_index(&tri[cap], r), &x1, &x2);
            cap = x1;
            l = c1;
            l_moved = true;
        } else { /* cap + (r, e1, inf) -> (l, r, e1) + (l, e1, inf) */
            flip(b, cap, vor__vertex_index(&tri[cap], l), &x1, &x2);
            cap = x2;
            r = e1;
            r_moved = true;
        }
    }

    out->ghost = lower;
}

/* ------------------------------------------------------------------ */
/* The builders                                                        */

/* A range of sorted sites still to build (state 0), with its first half
 * built (1), or both (2). */
struct frame {
    uint32_t lo, hi;
    unsigned state;
};

/* Field by field: a structure assignment may become a memcpy call. */
static void copy_component(component_t *to, const component_t *from)
{
    to->count = from->count;
    for (unsigned k = 0; k < 2u; k++) {
        to->first[k] = from->first[k];
        to->last[k] = from->last[k];
    }
    to->ghost = from->ghost;
}

static void push_frame(struct frame *frames, unsigned *top, uint32_t lo, uint32_t hi)
{
    frames[*top].lo = lo;
    frames[*top].hi = hi;
    frames[*top].state = 0;
    (*top)++;
}

/* One site as a component (no triangles yet). */
static void single(component_t *c, vor_index_t s)
{
    c->count = 1;
    c->first[0] = c->last[0] = c->first[1] = c->last[1] = s;
    c->ghost = VOR__NONE;
}

/* The classical x-split: the sorted sites [0, v) halved down to single
 * sites, merged bottom-up (seed 000 section 3.2, horizontal merges only).
 * An explicit stack replaces the recursion: depth <= log2(v) + 1. */
static void build_split(builder_t *b, const vor_index_t *order, uint32_t v, component_t *out)
{
    struct frame frames[40];
    if (v == 0u) {
        out->count = 0;
        return;
    }
    component_t parts[40];
    unsigned top = 0, done = 0;
    push_frame(frames, &top, 0, v);
    while (top > 0u) {
        struct frame *f = &frames[top - 1u];
        uint32_t size = f->hi - f->lo;
        if (size == 1u) {
            single(&parts[done++], order[f->lo]);
            top--;
            continue;
        }
        uint32_t mid = f->lo + size / 2u;
        if (f->state == 0u) {
            f->state = 1;
            push_frame(frames, &top, f->lo, mid);
        } else if (f->state == 1u) {
            f->state = 2;
            push_frame(frames, &top, mid, f->hi);
        } else {
            component_t merged;
            merge(b, &parts[done - 2u], &parts[done - 1u], 0, &merged);
            done--;
            copy_component(&parts[done - 1u], &merged);
            top--;
        }
    }
    copy_component(out, &parts[0]);
}

/* F and S merged, either possibly empty. */
static void combine(builder_t *b, const component_t *f, const component_t *s, unsigned axis,
                    component_t *out)
{
    if (f->count == 0u) {
        copy_component(out, s);
    } else if (s->count == 0u) {
        copy_component(out, f);
    } else {
        component_t merged;
        merge(b, f, s, axis, &merged);
        copy_component(out, &merged);
    }
}

/* The bucket (cell) of a site in the 2^k x 2^k grid over the bounding
 * square, as a Z-order index: bit pairs (row bit, column bit) from the
 * top level down, so every quadtree square is a run of indices and a
 * square's four children come in the order bottom-left, bottom-right,
 * top-left, top-right. */
static uint32_t cell_of(const vor_t *d, vor_index_t s, unsigned k, unsigned shift)
{
    uint32_t cx = (uint32_t)((((uint64_t)((int64_t)d->sites[s].x - d->low.x)) << k) >> shift);
    uint32_t cy = (uint32_t)((((uint64_t)((int64_t)d->sites[s].y - d->low.y)) << k) >> shift);
    uint32_t z = 0;
    for (unsigned bit = 0; bit < k; bit++) {
        z |= ((cx >> bit) & 1u) << (2u * bit);
        z |= ((cy >> bit) & 1u) << (2u * bit + 1u);
    }
    return z;
}

/* Katajainen and Koppinen's bucket merging in quadtree order (seed 000
 * sections 1, 3.1): about two sites a bucket, each bucket built by the
 * x-split, then every square of four merged from its children: bottom
 * pair and top pair horizontally, then the two halves vertically (the
 * horizontal merge turned by 90 degrees). order[0, v) is lexicographic;
 * it is regrouped by bucket here (a stable counting sort, so each bucket
 * stays lexicographic) with scratch below it in the triangle slots. The
 * buckets are visited in Z order with one list of up to four finished
 * children per level, like the digits of a base-4 counter. */
static void build_quadtree(builder_t *b, vor_index_t *order, uint32_t v, vor_index_t *scratch,
                           component_t *out)
{
    vor_t *d = b->d;
    unsigned k = 0;
    while (k < 12u && (8ull << (2u * k)) <= v) {
        k++;
    }
    uint64_t span = (uint64_t)((int64_t)d->high.x - d->low.x);
    uint64_t span_y = (uint64_t)((int64_t)d->high.y - d->low.y);
    span = (span_y > span) ? span_y : span;
    unsigned shift = 0;
    while ((span >> shift) != 0u) {
        shift++;
    }
    uint32_t cells = 1u << (2u * k);
    vor_index_t *start = scratch;          /* [cells + 1], cells <= v / 2 */
    vor_index_t *grouped = scratch + cells + 1u; /* [v] */
    for (uint32_t c = 0; c <= cells; c++) {
        start[c] = 0;
    }
    for (uint32_t i = 0; i < v; i++) {
        start[cell_of(d, order[i], k, shift) + 1u]++;
    }
    for (uint32_t c = 0; c < cells; c++) {
        start[c + 1u] = (vor_index_t)(start[c + 1u] + start[c]);
    }
    for (uint32_t i = 0; i < v; i++) {
        uint32_t c = cell_of(d, order[i], k, shift);
        grouped[start[c]] = order[i];
        start[c]++;
    }
    for (uint32_t i = 0; i < v; i++) {
        order[i] = grouped[i];
    }
    /* from here on the scratch below the order may be overwritten */
    component_t children[13][4];
    unsigned filled[13];
    for (unsigned level = 0; level <= k; level++) {
        filled[level] = 0;
    }
    uint32_t pos = 0;
    for (uint32_t c = 0; c < cells; c++) {
        uint32_t end = pos;
        while (end < v && cell_of(d, order[end], k, shift) == c) {
            end++;
        }
        unsigned level = k;
        build_split(b, order + pos, end - pos, &children[level][filled[level]++]);
        pos = end;
        /* a full set of four children becomes one square a level up */
        while (level > 0u && filled[level] == 4u) {
            component_t bottom, top;
            component_t *q = children[level];
            combine(b, &q[0], &q[1], 0, &bottom);
            combine(b, &q[2], &q[3], 0, &top);
            filled[level] = 0;
            level--;
            combine(b, &top, &bottom, 1, &children[level][filled[level]++]);
        }
    }
    copy_component(out, &children[0][0]);
}

void vor__build_dc(vor_t *d, uint32_t n, enum vor_algorithm algorithm, uint32_t *duplicate_of)
{
    vor__tri_t *tri = d->triangles;
    /* the order at the top of the triangle slots: sorted in place, then the
     * distinct sites packed at the very end. It is read front to back while
     * merges fill extra slots from below: after the first i sites at most
     * i - 2 extras are used, and (v - i) index entries fit above them
     * because an index is smaller than a triangle; and it starts above the
     * home slots for max_sites >= 3 (a two-slot mesh is read first). */
    vor_index_t *base = (vor_index_t *)(void *)tri;
    size_t entries = (size_t)vor__triangle_count(d->max_sites) * sizeof(vor__tri_t) /
                     sizeof(vor_index_t);
    vor_index_t *ids = base + entries - n;
    for (uint32_t s = 0; s < n; s++) {
        ids[s] = (vor_index_t)s;
    }
    vor__sort_ids(d->sites, ids, n, lex_less_id);
    const vor_point_t *p = d->sites;
    /* duplicates: equal points are adjacent, the first occurrence first */
    vor_index_t head = ids[0];
    uint32_t v = 0;
    for (uint32_t i = 0; i < n; i++) {
        vor_index_t s = ids[i];
        if (i > 0u && p[s].x == p[head].x && p[s].y == p[head].y) {
            if (duplicate_of != NULL) {
                duplicate_of[s] = head;
            }
            vor__tri_fresh(&tri[s]); /* a duplicate's home slot stays empty */
            tri[s].n[0] = VOR__NONE;
        } else {
            head = s;
            v++;
            if (duplicate_of != NULL) {
                duplicate_of[s] = s;
            }
        }
    }
    /* pack the distinct ones at the end, back to front (in place) */
    uint32_t w = n;
    for (uint32_t i = n; i-- > 0u;) {
        vor_index_t s = ids[i];
        bool first = i == 0u || p[ids[i - 1u]].x != p[s].x || p[ids[i - 1u]].y != p[s].y;
        if (first) {
            ids[--w] = s;
        }
    }
    const vor_index_t *order = ids + w;

    builder_t b;
    b.d = d;
    b.tri = tri;
    b.next_extra = d->max_sites;
    b.less = lex_less;
    b.split = 0;
    b.bound = 2u * v + 2u;
    if (v == 1u) { /* as the incremental build leaves it */
        d->vertex_count = 1;
        d->last_site = order[0];
        vor__grid_rebuild(d);
        return;
    }
    vor_index_t last = order[v - 1u];
    component_t all;
    if (algorithm == VOR_ALGO_DC_QUADTREE && v >= 8u) {
        /* its scratch right below the order: above the home slots (a
         * duplicate's must stay empty) for v >= 8 (cells <= v / 2) */
        build_quadtree(&b, ids + w, v, ids + w - (v + v / 2u + 1u), &all);
    } else {
        build_split(&b, order, v, &all);
    }
    d->vertex_count = v;
    d->last_site = last;
    vor__grid_rebuild(d);
}
