/* SPDX-License-Identifier: MIT */
/*
 * dynamic.c - removing and moving sites (docs/design/dynamic.md).
 *
 * Removal: the triangles around p are replaced by a triangulation of the
 * polygon of p's neighbours (the vertex at infinity among them for a hull
 * site), cut off one ear at a time by flipping an edge of p's star
 * (Devillers, "On deletion in Delaunay triangulations", 2002): the ear
 * (a, b, c) of consecutive neighbours is a triangle of the result when it
 * turns left and no other neighbour lies in its perturbed circle (that p
 * does follows). When three neighbours are left, their triangles merge
 * into one. Every predicate is the perturbed one, so the result is the
 * unique perturbed Delaunay triangulation of the remaining sites: the one
 * a fresh build gives. The star is walked once into small arrays and the
 * ears are tested from them; a star too large for them is cut down first
 * by walking the mesh.
 *
 * Topological guard: an ear is cut only when its new edge a-c is not an
 * edge already (else the mesh would hold it twice). Of two consecutive
 * ears at most one is blocked (two such edges would cross outside the
 * star), so a guarded ear always exists, and when the predicates lie and
 * no ear passes the geometric test the first guarded one is cut: every
 * pass removes one neighbour, so removal ends after degree - 3 cuts and
 * leaves a valid triangulation whatever the predicates answer. Only lying
 * predicates can make the guard block an ear (TOPOLOGY_GUARD), so it is
 * compiled where they can lie: the fault-injection builds.
 *
 * Memory: two triangles disappear. p's home slot empties; the other slot
 * freed must be a packed one, and the last packed triangle moves into it,
 * so the layout stays what vor_init set up (mesh.h). When the other slot
 * is a neighbour's home, vor__rehome finds that neighbour another
 * triangle, provably within its star or one neighbour's (see there).
 */
#include "bucket_grid.h"
#include "cdt.h"
#include "dynamic.h"
#include "mesh.h"
#include "motion.h"
#include "perturbation.h"

static inline bool is_home(const vor_t *d, vor_index_t slot, vor_index_t v)
{
    return (slot == v) && (v < d->max_sites);
}

/* The removal's predicates. On the constrained triangulation's own mesh
 * (cdt.c), whose vertices may be crossing points, they go through its
 * cdt_predicate; on a diagram (cdt_predicate NULL) straight to the sites'. */
static int star_orient(vor_t *d, vor_index_t a, vor_index_t b, vor_index_t c)
{
    if (d->cdt_predicate != NULL) {
        uint32_t ids[3] = {a, b, c};
        return d->cdt_predicate(d, ids, 3u);
    }
    return vor__orient(d, a, b, c);
}

static int star_incircle(vor_t *d, vor_index_t a, vor_index_t b, vor_index_t c, vor_index_t y)
{
    if (d->cdt_predicate != NULL) {
        uint32_t ids[4] = {a, b, c, y};
        return d->cdt_predicate(d, ids, 4u);
    }
    return vor__incircle(d, a, b, c, y);
}

/* vor__conflicts through the two above. */
static bool star_conflicts(vor_t *d, vor_index_t v0, vor_index_t v1, vor_index_t v2,
                           vor_index_t y)
{
    if (v0 == VOR__INFINITE) {
        return star_orient(d, v1, v2, y) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return star_orient(d, v2, v0, y) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return star_orient(d, v0, v1, y) > 0;
    }
    return star_incircle(d, v0, v1, v2, y) > 0;
}

/* In triangle `slot`, points the link that pointed at `from` at `to`. */
static void relink(vor__tri_t *tri, vor_index_t slot, vor_index_t from, vor_index_t to)
{
    vor__tri_t *t = &tri[slot];
    unsigned i = vor__neighbour_index(t, from);
    if (i != 3u) { /* always found in a valid mesh */
        t->n[i] = to;
    }
}

void vor__move_triangle(vor__tri_t *tri, vor_index_t from, vor_index_t to)
{
    vor__tri_t *f = &tri[from];
    vor_index_t v[3];
    vor__vertices(f, v);
    vor__tri_fresh(&tri[to]);
    vor__tri_set(&tri[to], v[0], v[1], v[2], f->n[0], f->n[1], f->n[2]);
    for (unsigned i = 0; i < 3u; i++) {
        relink(tri, tri[to].n[i], from, to);
    }
}

/* Index of vertex v in t, 0 when absent (only on a broken mesh): never
 * an index past the triangle. */
static unsigned corner(const vor__tri_t *t, vor_index_t v)
{
    unsigned i = vor__vertex_index(t, v);
    return (i == 3u) ? 0u : i;
}

/* The star of p: slot of the next triangle counterclockwise around p,
 * and the neighbours (p, x, y) of a star triangle. */
static vor_index_t star_next(const vor__tri_t *tri, vor_index_t slot, vor_index_t p)
{
    const vor__tri_t *t = &tri[slot];
    unsigned i = vor__vertex_index(t, p);
    return (i == 3u) ? slot : t->n[vor__next(i)]; /* absent only on a broken mesh */
}

static void star_edge(const vor__tri_t *tri, vor_index_t slot, vor_index_t p, vor_index_t *x,
                      vor_index_t *y)
{
    const vor__tri_t *t = &tri[slot];
    unsigned i = corner(t, p);
    *x = vor__vertex(t, vor__next(i));
    *y = vor__vertex(t, vor__prev(i));
}

/* Is a-b an edge of the mesh? Turns clockwise around the finite site a
 * from its triangle in slot `start` (not b's) to the one in slot `stop`
 * (not b's either, and not read), at most once around (vertex_count + 1
 * triangles bound the turn); one read of each triangle's vertices. */
static bool is_edge(const vor_t *d, vor_index_t a, vor_index_t b, vor_index_t start,
                    vor_index_t stop)
{
    const vor__tri_t *tri = d->triangles;
    vor_index_t slot = start;
    vor_index_t v[3];
    vor__vertices(&tri[slot], v);
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        /* clockwise: from a star triangle (p, a, b) across a-b first,
         * into the triangle the star walk prefetched */
        unsigned i = (v[1] == a) ? 1u : (v[2] == a) ? 2u : 0u;
        slot = tri[slot].n[vor__prev(i)];
        if (slot == stop) {
            break;
        }
        vor__vertices(&tri[slot], v);
        if ((v[0] == b) || (v[1] == b) || (v[2] == b)) {
            return true;
        }
    }
    return false;
}

/* Does the topological guard block the new edge a-c, because it is an
 * edge already? It turns around a from the star triangle in slot a_from
 * to the one in a_to (is_edge), or around c from c_from to c_to when a is
 * the vertex at infinity.
 * With exact signs it never blocks: before a removal the mesh is then the
 * perturbed Delaunay triangulation, an ear that passes the tests is a
 * triangle of the result (Devillers 2002, lemma 1) and the triangles off
 * the star stay in it, so a-c being an edge off the star as well would
 * put two edges a-c in one triangulation. The library's signs are exact;
 * only fault injection (tests/faults) makes them lie, so only those builds
 * turn (the turns, at random arena addresses, were a third of a removal's
 * time at 10^6 sites). */
#ifdef VOR_FAULT_INJECTION
#define TOPOLOGY_GUARD true
#else
#define TOPOLOGY_GUARD false
#endif

static bool guard_blocks(const vor_t *d, vor_index_t a, vor_index_t c, vor_index_t a_from,
                         vor_index_t a_to, vor_index_t c_from, vor_index_t c_to)
{
    if (!TOPOLOGY_GUARD) {
        return false;
    }
    return (a != VOR__INFINITE) ? is_edge(d, a, c, a_from, a_to) : is_edge(d, c, a, c_from, c_to);
}

/* Is the ear (a, b, c) of p's star, whose following triangle is at slot
 * `after`, a triangle of the triangulation without p? The test of
 * star_ear_ok, walking the mesh (for stars beyond the arrays). */
static bool is_delaunay_ear(vor_t *d, vor_index_t p, vor_index_t a, vor_index_t b,
                            vor_index_t c, vor_index_t after)
{
    if (a != VOR__INFINITE && (b != VOR__INFINITE) && (c != VOR__INFINITE) &&
        star_orient(d, a, b, c) <= 0) {
        return false;
    }
    /* the other neighbours: second vertices of the star triangles after
     * the ear's up to the one ending at a (degree - 3 of them) */
    const vor__tri_t *tri = d->triangles;
    vor_index_t slot = after;
    vor_index_t x;
    vor_index_t y;
    for (uint32_t left = d->vertex_count; left > 0u; left--) {
        star_edge(tri, slot, p, &x, &y);
        if (y == a) {
            break;
        }
        /* infinity lies in no circle of finite sites */
        if (y != VOR__INFINITE && star_conflicts(d, a, b, c, y)) {
            return false;
        }
        slot = star_next(tri, slot, p);
    }
    return true;
}

/* Cuts the ear (a, b, c) off p's star: star triangles t1 = (p, a, b) in
 * slot s1 and t2 = (p, b, c) in s2 become the ear (a, b, c) and the star
 * triangle (p, a, c). Returns the latter's slot. */
static vor_index_t cut_ear(vor_t *d, vor_index_t p, vor_index_t s1, vor_index_t s2)
{
    vor__tri_t *tri = d->triangles;
    const vor__tri_t *t1 = &tri[s1];
    const vor__tri_t *t2 = &tri[s2];
    vor_index_t v1[3];
    vor_index_t v2[3];
    vor__vertices(t1, v1);
    vor__vertices(t2, v2);
    unsigned i1 = (v1[1] == p) ? 1u : (v1[2] == p) ? 2u : 0u;
    unsigned i2 = (v2[1] == p) ? 1u : (v2[2] == p) ? 2u : 0u;
    vor_index_t a = v1[vor__next(i1)];
    vor_index_t b = v1[vor__prev(i1)];
    vor_index_t c = v2[vor__prev(i2)];
    vor_index_t outer1 = t1->n[i1];
    vor_index_t before = t1->n[vor__prev(i1)];
    vor_index_t outer2 = t2->n[i2];
    vor_index_t after = t2->n[vor__next(i2)];
    /* keep home slots home: the ear holds a, b, c, the star triangle p, a,
     * c; p's slot must take the star triangle and b's the ear (never both
     * asked of one slot). Otherwise a packed slot goes to the star, so
     * that home slots settle in ears and fewer reach the final merge,
     * which keeps only one of the last three slots. */
    vor_index_t ear = s1;
    vor_index_t star = s2;
    if (!is_home(d, s2, p) && !is_home(d, s1, b) &&
        (is_home(d, s1, p) || is_home(d, s2, b) || (s2 < d->max_sites))) {
        ear = s2;
        star = s1;
    }
    /* only the links into the slot that changed role move (one of the
     * two triangles beyond the star is not touched) */
    if (ear == s1) {
        relink(tri, outer2, s2, ear);
        relink(tri, before, s1, star);
    } else {
        relink(tri, outer1, s1, ear);
        relink(tri, after, s2, star);
    }
    vor__tri_set(&tri[ear], a, b, c, outer2, star, outer1);
    vor__tri_set(&tri[star], p, a, c, ear, after, before);
    return star;
}

/* The first packed slot (max_sites or above) of v's star, turning from
 * slot `first` (which holds a triangle of v); VOR__NONE if none. */
static vor_index_t packed_in_star(const vor_t *d, vor_index_t v, vor_index_t first)
{
    vor_index_t slot = first;
    vor_index_t packed = VOR__NONE;
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        if (slot >= d->max_sites) {
            packed = slot;
            break;
        }
        slot = star_next(d->triangles, slot, v);
        if (slot == first) {
            break;
        }
    }
    return packed;
}

/* Home slot h of site h is empty (removal merged its triangle away),
 * `start` holds another triangle of h, and the packed triangles run up to
 * slot `last`, one too many. Fills slot h with a triangle of h, which
 * empties a packed slot, and moves the triangle in `last` into it.
 *
 * Why a look at two stars always finds one. A home slot (below max_sites)
 * holds a triangle of its own site, so distinct home slots hold
 * triangles of distinct sites. If no triangle of h is in a packed slot,
 * h's k triangles fill the home slots of k distinct neighbours of h; h
 * has k neighbours, infinity among them at the hull, and infinity has no
 * home, so h is inside the hull and every neighbour's home holds a
 * triangle of h. Take such a neighbour c, whose home slot is `start`: two
 * of c's m triangles hold h, and the other m - 2 can only be in the home
 * slots of their corners other than c (c's holds a triangle of h), h
 * (empty), and a and b, the third corners of the two triangles on edge
 * h-c (their homes hold triangles of h too): m - 3 sites at most. So one
 * of c's triangles is in a packed slot P. Slot h takes c's home triangle
 * (a triangle of h), slot c takes P's (a triangle of c), P the last. */
void vor__rehome(vor_t *d, vor_index_t h, vor_index_t start, vor_index_t last)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t packed = packed_in_star(d, h, start);
    if (packed == VOR__NONE) {
        packed = packed_in_star(d, start, start);
        if (packed == VOR__NONE) {
            return; /* a broken mesh only */
        }
        vor__move_triangle(tri, start, h);
        vor__move_triangle(tri, packed, start);
    } else {
        vor__move_triangle(tri, packed, h);
    }
    if (packed != last) {
        vor__move_triangle(tri, last, packed);
    }
}

void vor__merge_three(vor_t *d, vor_index_t p, const vor_index_t nb[3], const vor_index_t sl[3])
{
    vor__tri_t *tri = d->triangles;
    /* three triangles (p, a, b), (p, b, c), (p, c, a) merge into (a, b, c) */
    vor_index_t a = nb[0];
    vor_index_t b = nb[1];
    vor_index_t c = nb[2];
    vor_index_t s1 = sl[0];
    vor_index_t s2 = sl[1];
    vor_index_t s3 = sl[2];
    vor_index_t o1 = tri[s1].n[corner(&tri[s1], p)];
    vor_index_t o2 = tri[s2].n[corner(&tri[s2], p)];
    vor_index_t o3 = tri[s3].n[corner(&tri[s3], p)];
    /* the two slots besides p's home (p's home is one of the three) */
    vor_index_t x1 = (s1 == p) ? s2 : s1;
    vor_index_t x2 = (s3 == p) ? s2 : s3;
    vor_index_t keep = x2;
    vor_index_t freed = x1;
    if (x2 >= d->max_sites) {
        keep = x1;
        freed = x2;
    }
    relink(tri, o1, s1, keep);
    relink(tri, o2, s2, keep);
    relink(tri, o3, s3, keep);
    vor__tri_set(&tri[keep], a, b, c, o2, o3, o1);
    /* keep the extras packed: the last one fills the freed slot */
    vor_index_t last = (vor_index_t)(d->max_sites + d->vertex_count - 3u);
    if (freed < d->max_sites) {
        /* both home slots of neighbours: the one not kept needs another
         * of its triangles, which frees a packed slot */
        vor__rehome(d, freed, keep, last);
    } else if (freed != last) {
        vor__move_triangle(tri, last, freed);
    } else {
        /* no other case */
    }
}

/* Puts id p on the free list: d->free_site holds the most recent free id
 * plus one (0: none, so that a zeroed vor_t has no free id), and each
 * free id's home slot the same for the next one. */
void vor__free_id(vor_t *d, uint32_t p)
{
    if (d->max_sites >= 2u) { /* one site: no slots, and no other free id */
        vor__tri_t *t = &d->triangles[p];
        vor__tri_fresh(t);
        t->n[0] = VOR__NONE;
        t->n[1] = (vor_index_t)d->free_site;
        t->n[2] = VOR__NONE;
    }
    d->free_site = p + 1u;
}

/* Up to this degree the star is walked once into two small arrays and the
 * ears are tested from them; a larger star (rare: a site inside a ring of
 * many others) is first cut down to it by walking the mesh. 16 covers
 * nearly every site of a random set (mean degree 6) at 128 bytes of stack. */
#define STAR_MAX 16u

/* The star of p as arrays: neighbour nb[i] and the slot sl[i] of the star
 * triangle (p, nb[i], nb[i + 1]), counterclockwise, indices mod deg. */
typedef struct {
    vor_index_t nb[STAR_MAX];
    vor_index_t sl[STAR_MAX];
    uint32_t deg;
} star_t;

static inline uint32_t wrap(uint32_t i, uint32_t deg)
{
    return (i >= deg) ? (i - deg) : i; /* i < 2 deg */
}

/* Is the ear (nb[i], nb[i + 1], nb[i + 2]) a triangle of the triangulation
 * without p? It is when it turns left and no other neighbour lies in its
 * perturbed circle: then it is a Delaunay triangle of p's neighbours inside
 * the star, hence of the remaining sites (Devillers 2002, lemma 1). That p
 * lies in the circle follows, so it is not tested. The neighbours next to
 * the ear come first: they are the likeliest inside. */
static bool star_ear_ok(vor_t *d, const star_t *st, uint32_t i)
{
    uint32_t deg = st->deg;
    vor_index_t a = st->nb[i];
    vor_index_t b = st->nb[wrap(i + 1u, deg)];
    vor_index_t c = st->nb[wrap(i + 2u, deg)];
    bool finite = a != VOR__INFINITE && (b != VOR__INFINITE) && (c != VOR__INFINITE);
    if (finite && star_orient(d, a, b, c) <= 0) {
        return false;
    }
    /* a hull ear (a vertex at infinity) is a hull edge u -> w, and a site
     * beyond it is in its "circle" (vor__conflicts) */
    vor_index_t u = (a == VOR__INFINITE) ? b : (b == VOR__INFINITE) ? c : a;
    vor_index_t w = (a == VOR__INFINITE) ? c : (b == VOR__INFINITE) ? a : b;
    /* the other deg - 3 neighbours at offsets 3, deg - 1, 4, deg - 2, ..
     * from the ear's first; one call site each for the two tests keeps
     * the stack frame small */
    for (uint32_t t = 0; (t + 3u) < deg; t++) {
        vor_index_t y = st->nb[wrap(i + ((t & 1u) ? (deg - 1u - (t / 2u)) : (3u + (t / 2u))), deg)];
        if (y == VOR__INFINITE) {
            continue; /* infinity lies in no circle of finite sites */
        }
        if (finite ? (star_incircle(d, a, b, c, y) > 0) : star_orient(d, u, w, y) > 0) {
            return false;
        }
    }
    return true;
}

/* The topological guard for ear i: its new edge is not an edge already.
 * The turn is around a finite end, over its triangles off the star: a's
 * from (p, a, b) to (p, z, a), or c's from (p, c, d) to (p, b, c). */
static bool star_guarded(const vor_t *d, const star_t *st, uint32_t i)
{
    uint32_t deg = st->deg;
    return !guard_blocks(d, st->nb[i], st->nb[wrap(i + 2u, deg)], st->sl[i],
                         st->sl[wrap(i + deg - 1u, deg)], st->sl[wrap(i + 2u, deg)],
                         st->sl[wrap(i + 1u, deg)]);
}

/* Walks p's star from slot `start` into the arrays (degree + 1 steps at
 * most), asking the cache early for what the ear tests and the guard
 * read next: the neighbours' coordinates and the triangles beyond the
 * star. False when the star has more than STAR_MAX triangles. */
static bool star_load(const vor_t *d, vor_index_t p, vor_index_t start, star_t *st)
{
    const vor__tri_t *tri = d->triangles;
    vor_index_t slot = start;
    st->deg = 0;
    do {
        if (st->deg == STAR_MAX) {
            return false;
        }
        const vor__tri_t *t = &tri[slot];
        vor_index_t v[3];
        vor__vertices(t, v);
        unsigned i = (v[1] == p) ? 1u : (v[2] == p) ? 2u : 0u;
        vor_index_t x = v[vor__next(i)];
        if (x != VOR__INFINITE) {
            VOR__PREFETCH(&d->sites[x]);
        }
        VOR__PREFETCH(&tri[t->n[i]]);
        st->nb[st->deg] = x;
        st->sl[st->deg] = slot;
        st->deg++;
        slot = t->n[vor__next(i)]; /* star_next */
    } while (slot != start);
    return true;
}

/* Cuts ear i off the star (arrays and mesh): b = nb[i + 1] leaves.
 * Returns the index of the ear before the new edge: it and the next one
 * are the ears that changed. */
static uint32_t star_cut(vor_t *d, vor_index_t p, star_t *st, uint32_t i)
{
    uint32_t j = wrap(i + 1u, st->deg);
    st->sl[i] = cut_ear(d, p, st->sl[i], st->sl[j]);
    for (uint32_t k = j; (k + 1u) < st->deg; k++) {
        st->nb[k] = st->nb[k + 1u];
        st->sl[k] = st->sl[k + 1u];
    }
    st->deg--;
    uint32_t at = (j == 0u) ? (i - 1u) : i; /* the new star triangle */
    return (at == 0u) ? (st->deg - 1u) : (at - 1u);
}

/* The ear of a star of four or more to cut: the first Delaunay ear from
 * `from` whose new edge is not one already (the topological guard, tested
 * only for ears that pass: it walks a star). A quadrilateral needs one ear
 * test: if ear 0's diagonal is not the Delaunay one, the other is. When
 * lying predicates pass no guarded ear, the first guarded one (one of two
 * consecutive ears is). STAR_MAX: only on a broken mesh. */
static uint32_t star_choose(vor_t *d, const star_t *st, uint32_t from)
{
    uint32_t deg = st->deg;
    if (deg == 4u) {
        uint32_t i = star_ear_ok(d, st, 0) ? 0u : 1u;
        return star_guarded(d, st, i) ? i : (1u - i);
    }
    for (uint32_t k = 0; k < deg; k++) {
        uint32_t i = wrap(from + k, deg);
        if (star_ear_ok(d, st, i) && star_guarded(d, st, i)) {
            return i;
        }
    }
    for (uint32_t i = 0; i < deg; i++) {
        if (star_guarded(d, st, i)) {
            return i;
        }
    }
    return STAR_MAX;
}

/* Removes p (in the mesh, at least four sites) and returns a former
 * neighbour of it. */
static uint32_t remove_from_mesh(vor_t *d, vor_index_t p)
{
    vor__tri_t *tri = d->triangles;
    star_t st;
    vor_index_t s1 = p; /* the home slot stays in the star (cut_ear) */
    /* the last packed triangle fills a freed slot at the end: its cache
     * line and, once it is in, its neighbours' are fetched meanwhile */
    const vor__tri_t *tail = &tri[d->max_sites + d->vertex_count - 3u];
    VOR__PREFETCH(tail);
    if (!star_load(d, p, s1, &st)) {
        /* a large star: ears by walking, until the arrays can hold it */
        uint32_t degree = 0;
        vor_index_t slot = p;
        do {
            degree++;
            slot = star_next(tri, slot, p);
        } while ((slot != p) && (degree <= d->vertex_count));
        while (degree > STAR_MAX) {
            vor_index_t chosen = VOR__NONE;
            vor_index_t guarded = VOR__NONE;
            slot = s1;
            for (uint32_t k = 0; (k < degree) && (chosen == VOR__NONE); k++) {
                vor_index_t s2 = star_next(tri, slot, p);
                vor_index_t a;
                vor_index_t b;
                vor_index_t c;
                star_edge(tri, slot, p, &a, &b);
                star_edge(tri, s2, p, &b, &c);
                if (!guard_blocks(d, a, c, slot, slot, s2, s2)) {
                    guarded = (guarded == VOR__NONE) ? slot : guarded;
                    if (is_delaunay_ear(d, p, a, b, c, star_next(tri, s2, p))) {
                        chosen = slot;
                    }
                }
                slot = s2;
            }
            /* only lying predicates leave no ear: the first guarded one */
            chosen = (chosen != VOR__NONE) ? chosen : guarded;
            if (chosen == VOR__NONE) {
                break; /* a broken mesh only */
            }
            s1 = cut_ear(d, p, chosen, star_next(tri, chosen, p));
            degree--;
        }
        (void)star_load(d, p, s1, &st);
    }
    for (unsigned k = 0; VOR__PREFETCHING && (k < 3u); k++) {
        VOR__PREFETCH(&tri[tail->n[k]]);
    }
    /* each cut removes one neighbour: deg - 3 cuts */
    uint32_t from = 0;
    while (st.deg > 3u) {
        uint32_t i = star_choose(d, &st, from);
        if (i == STAR_MAX) {
            break; /* a broken mesh only */
        }
        from = star_cut(d, p, &st, i);
    }

    VOR_ASSERT(st.deg == 3u); /* every vertex has at least three neighbours */
    if (st.deg == 3u) { /* fewer: a broken mesh only, left alone rather than read past */
        vor__merge_three(d, p, st.nb, st.sl);
    }
    vor_index_t a = st.nb[0];
    vor_index_t b = st.nb[1];
    return (a != VOR__INFINITE) ? a : b;
}

uint32_t vor__unlink_vertex(vor_t *d, uint32_t site)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t p = (vor_index_t)site;
    uint32_t other = site;
    if (d->vertex_count >= 4u) {
        other = remove_from_mesh(d, p);
    } else if (d->vertex_count == 3u) {
        /* two sites left: the two triangles at infinity of an edge */
        vor_index_t v[3];
        vor__vertices(&tri[p], v);
        unsigned i = corner(&tri[p], p);
        vor_index_t a = v[vor__next(i)];
        vor_index_t b = v[vor__prev(i)];
        if (a == VOR__INFINITE || (b == VOR__INFINITE)) {
            /* p's home holds a triangle at infinity; its finite triangle
             * is across the hull edge and holds both others */
            const vor__tri_t *f = &tri[tri[p].n[corner(&tri[p], VOR__INFINITE)]];
            i = corner(f, p);
            a = vor__vertex(f, vor__next(i));
            b = vor__vertex(f, vor__prev(i));
        }
        vor__make_edge(d, a, b);
        other = a;
    } else if (d->vertex_count == 2u) {
        /* two sites are vor__make_edge's edge: p's home holds (p, other,
         * infinity). The other's slot is not read while it is the only
         * site (vor__site_in_mesh: the last site), and the next site's
         * vor__make_edge rewrites it. */
        other = vor__vertex(&tri[p], 1);
    } else {
        /* one site: no triangles */
    }
    d->vertex_count--;
    return other;
}

uint32_t vor__unlink_site(vor_t *d, uint32_t site)
{
    uint32_t other = vor__unlink_vertex(d, site);
    vor__free_id(d, site);
    return other;
}

void vor__unlinked(vor_t *d, uint32_t site, uint32_t other)
{
    if (d->vertex_count < 2u) {
        d->bucket_rebuild_at = 2; /* the grid is redrawn with the second site */
    } else {
        vor__grid_forget(d, site, other);
    }
    d->last_site = (d->last_site == site) ? other : d->last_site;
    d->revision++;
    vor__topology_changed(d);
}

int vor_remove(vor_t *d, uint32_t site)
{
    if ((d == NULL) || !vor__site_in_mesh(d, site)) {
        return VOR_ERR_ARG;
    }
    if (d->cdt_update != NULL) { /* a constraint's end stays */
        int err = d->cdt_update(d, site, VOR__CDT_REMOVE);
        if (err != VOR_OK) {
            return err;
        }
    }
    vor__unlinked(d, site, vor__unlink_site(d, site));
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Moving                                                              */

/* With p's coordinates already changed: is every triangle around p still
 * counterclockwise, and every edge of those triangles locally Delaunay?
 * Only they involve p, so then the mesh is the triangulation of the moved
 * sites. A triangle's neighbour across a spoke p-y is the next star
 * triangle; across the far edge, a triangle off the star. Also sets
 * *twin to a neighbour of p at p's new place (VOR__NONE: none): when the
 * answer is yes, a site there would be one, since a site and its twin are
 * each other's nearest (perturbed) sites, hence Delaunay neighbours. */
static bool star_still_delaunay(vor_t *d, vor_index_t p, vor_index_t *twin)
{
    const vor_point_t *at = &d->sites[p];
    vor__star_step_t s;
    vor__star_begin(d, p, &s);
    *twin = VOR__NONE;
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        if (s.x != VOR__INFINITE && (d->sites[s.x].x == at->x) && (d->sites[s.x].y == at->y)) {
            *twin = s.x;
        }
        if (s.x != VOR__INFINITE && (s.y != VOR__INFINITE) && vor__orient(d, p, s.x, s.y) <= 0) {
            return false;
        }
        if (s.far != VOR__INFINITE && vor__conflicts(d, s.v[0], s.v[1], s.v[2], s.far)) {
            return false;
        }
        if (s.across != VOR__INFINITE && vor__conflicts(d, s.v[0], s.v[1], s.v[2], s.across)) {
            return false;
        }
        if (!vor__star_advance(d, p, &s)) {
            break;
        }
    }
    return true;
}

/* A site sharing a triangle with p (p in a mesh of two or more). */
static uint32_t any_neighbour(const vor_t *d, vor_index_t p)
{
    vor_index_t v[3];
    vor_index_t found = p;
    vor__vertices(&d->triangles[p], v);
    for (unsigned i = 0; i < 3u; i++) {
        found = ((v[i] != p) && (v[i] != VOR__INFINITE)) ? v[i] : found;
    }
    return found;
}

/* Site `site`, whose triangles stay the same, goes to (x, y): the box
 * grows to hold it, and a site that changed bucket moves its run of the
 * bucket grid. Should the site name every bucket, another site in the
 * mesh takes its runs: the last inserted one (always in the mesh), or a
 * neighbour when that is this site (a turn of the home triangle, kept
 * off the common path). */
static void move_in_place(vor_t *d, uint32_t site, int32_t x, int32_t y)
{
    vor_point_t *s = &d->sites[site];
    vor_point_t old = *s;
    s->x = x;
    s->y = y;
    vor__box_add(d, s, false);
    if (d->vertex_count >= 2u) {
        uint32_t fallback = d->last_site;
        if (fallback == site) {
            fallback = any_neighbour(d, (vor_index_t)site);
        }
        vor__grid_move(d, site, old, fallback);
    }
    d->revision++;
}

/* vor_move past the motion cache: proves the triangles unchanged, or
 * removes and inserts. Out of line, so that the fast path saves no more
 * registers and stack than it uses. */
static VOR__NOINLINE int move_checked(vor_t *d, uint32_t site, int32_t x, int32_t y,
                                      uint32_t *existing)
{
    vor_point_t *s = &d->sites[site];
    vor_point_t old = *s;
    uint32_t epoch = d->motion_epoch; /* for the cache's backoff */
    uint32_t twin = VOR__NONE;
    if (d->vertex_count == 2u) { /* the other site is the only neighbour */
        uint32_t other = any_neighbour(d, (vor_index_t)site);
        twin = ((d->sites[other].x == x) && (d->sites[other].y == y)) ? other : VOR__NONE;
    }
    /* the common small step first: the same triangles at the new place.
     * In test builds the tests count, restored if the move fails. */
    vor__tally_t tally;
    vor__tally_save(&tally, d);
    s->x = x;
    s->y = y;
    vor_index_t star_twin = VOR__NONE;
    bool same_triangles = (d->vertex_count <= 2u) || star_still_delaunay(d, (vor_index_t)site,
                                                                       &star_twin);
    twin = (star_twin != VOR__NONE) ? star_twin : twin;
    *s = old;
    if (!same_triangles && (d->vertex_count >= 3u)) {
        /* a site at (x, y) is the nearest site to it (a read-only query
         * from the bucket grid) */
        uint32_t nearest;
        vor_point_t q = {x, y};
        if ((vor_nearest(d, q, VOR_NO_HINT, &nearest) == VOR_OK) && (d->sites[nearest].x == x) &&
            (d->sites[nearest].y == y)) {
            twin = nearest;
        }
    }
    if (twin != VOR__NONE) {
        vor__tally_restore(d, &tally);
        if (existing != NULL) {
            *existing = twin;
        }
        return VOR_ERR_DUPLICATE;
    }
    if (same_triangles) {
        move_in_place(d, site, x, y);
        vor__motion_update(d, site, &old, epoch);
        return VOR_OK;
    }
    /* remove, then insert again under the same id (the free list's head),
     * from the bucket grid's site near the new place */
    (void)vor_remove(d, site);
    uint32_t id;
    vor_point_t to = {x, y};
    int err = vor_insert_near(d, to, VOR_NO_HINT, &id);
    if (err != VOR_OK) {
        /* only lying predicates (fault injection) find a twin the exact
         * query did not: the site goes back where it was */
        (void)vor_insert_near(d, old, VOR_NO_HINT, &id);
    } else {
        vor__motion_update(d, site, &old, epoch); /* a box in the new epoch */
    }
    return err;
}

/* vor_move on the diagram alone: the motion cache's fast path, else the
 * full check (site in the mesh, p elsewhere). */
static int move_diagram(vor_t *d, uint32_t site, vor_point_t p, uint32_t *existing)
{
    if (vor__motion_fast(d, site, p.x, p.y)) {
        /* inside the site's box: no triangle changes and no site is
         * there (invariant J, motion.c) */
        move_in_place(d, site, p.x, p.y);
        return VOR_OK;
    }
    return move_checked(d, site, p.x, p.y, existing);
}

/* vor_move with constraint memory: every refusal is found before
 * anything changes: a twin at the new place (the query is read-only), a
 * constraint ending at the site, a full edge table where the new place
 * splits a constrained edge. Then the constrained mesh loses the site,
 * the diagram moves it with the upkeep off, and the constrained mesh
 * takes it at the new place. */
static VOR__NOINLINE int move_constrained(vor_t *d, uint32_t site, vor_point_t p,
                                          uint32_t *existing)
{
    uint32_t nearest;
    if ((vor_nearest(d, p, VOR_NO_HINT, &nearest) == VOR_OK) && (d->sites[nearest].x == p.x) &&
        (d->sites[nearest].y == p.y)) {
        if (existing != NULL) {
            *existing = nearest;
        }
        return VOR_ERR_DUPLICATE;
    }
    int (*update)(vor_t *, uint32_t, unsigned) = d->cdt_update;
    int err = update(d, site, VOR__CDT_CHECK_REMOVE);
    if (err != VOR_OK) {
        return err;
    }
    vor_point_t old = d->sites[site];
    d->sites[site] = p;
    err = update(d, site, VOR__CDT_CHECK_INSERT);
    d->sites[site] = old;
    if (err != VOR_OK) {
        return err;
    }
    (void)update(d, site, VOR__CDT_REMOVE);
    d->cdt_update = NULL;
    err = move_diagram(d, site, p, existing);
    d->cdt_update = update;
    (void)update(d, site, VOR__CDT_INSERTED);
    return err;
}

int vor_move(vor_t *d, uint32_t site, vor_point_t p, uint32_t *existing)
{
    if ((d == NULL) || !vor__site_in_mesh(d, site)) {
        return VOR_ERR_ARG;
    }
    const vor_point_t *s = &d->sites[site];
    if ((s->x == p.x) && (s->y == p.y)) {
        return VOR_OK;
    }
    if (d->cdt_update != NULL) {
        return move_constrained(d, site, p, existing);
    }
    return move_diagram(d, site, p, existing);
}
