/* SPDX-License-Identifier: MIT */
/*
 * mesh.h - the triangle mesh behind the diagram, private to the library.
 *
 * Triangles live in one array of 2 max_sites - 2 slots (Euler's count with
 * a vertex at infinity closing the hull):
 *
 *   slots [0, max_sites)              home slots: slot s always holds a
 *                                     triangle incident to site s, which is
 *                                     how a site finds its triangles, at no
 *                                     memory cost (empty while s is not in
 *                                     the mesh; a removed id's empty slot
 *                                     links the free ids' list, dynamic.c)
 *   slots [max_sites, max_sites+v-2)  the remaining v - 2 triangles of a
 *                                     mesh of v sites, packed
 *
 * A triangle's vertices are counterclockwise (under the perturbation);
 * neighbour i lies across the edge opposite vertex i. A spare bit of home
 * slot s is a transient mark on site s, kept by every write to the slot
 * (vor__tri_set): insertion uses it for Sugihara and Iri's topological guard.
 */
#ifndef VOR_MESH_H
#define VOR_MESH_H

#include <stdbool.h>

#include "predicates.h"
#include "vor.h"

/* A triangle: three vertices and three neighbour slots. With 16-bit
 * indices the vertices are three uint16_t; with 32-bit indices they are
 * packed 21 bits each into two words (20 bytes a triangle instead of 24,
 * so 48 bytes per site with the coordinates; up to 2^21 - 2 sites). The
 * slot's site mark is the top bit of the vertex words. Only the accessors
 * below look inside. */
struct vor__triangle {
#if VOR_INDEX_BITS == 16
    vor_index_t v[3];
#else
    uint32_t v[2];
#endif
    vor_index_t n[3];
};
typedef struct vor__triangle vor__tri_t;

/* the arena size macro in vor.h must match the layout */
typedef char vor__triangle_size_check[(sizeof(vor__tri_t) == VOR_TRIANGLE_BYTES) ? 1 : -1];

#if VOR_INDEX_BITS == 16
#define VOR__INFINITE ((vor_index_t)0x7FFFu) /* the vertex at infinity */
#define VOR__MARK_BIT 0x8000u                /* in v[0] */
#else
#define VOR__INFINITE ((vor_index_t)0x1FFFFFu)
#define VOR__MARK_BIT 0x80000000u            /* in v[1] */
#endif
#define VOR__NONE ((vor_index_t)~(vor_index_t)0) /* no neighbour: empty slot */

/* A hint to the cache: site ids are input positions, so the next sites'
 * coordinates and home slots lie anywhere in the arena (no effect without
 * GCC or clang, and none on cores without a cache). */
#if defined(__GNUC__)
#define VOR__PREFETCH(address) __builtin_prefetch(address)
#else
#define VOR__PREFETCH(address) ((void)(address))
#endif

/* (i + 1) mod 3 and (i + 2) mod 3 without a division. ">= 2" rather
 * than "== 2": the result is then provably below 3 even for the "not
 * found" index 3 of vor__vertex_index, which keeps gcc -O3's array-bounds
 * analysis quiet at no cost (one compare either way). */
static inline unsigned vor__next(unsigned i)
{
    return (i >= 2u) ? 0u : i + 1u;
}
static inline unsigned vor__prev(unsigned i)
{
    return (i == 0u) ? 2u : i - 1u;
}

static inline vor_index_t vor__vertex(const vor__tri_t *t, unsigned i)
{
#if VOR_INDEX_BITS == 16
    return (vor_index_t)(t->v[i] & 0x7FFFu);
#else
    return (i == 0u)   ? (t->v[0] & 0x1FFFFFu)
           : (i == 1u) ? ((t->v[0] >> 21) | ((t->v[1] & 0x3FFu) << 11))
                       : ((t->v[1] >> 10) & 0x1FFFFFu);
#endif
}

/* All three vertices at once (one read of the packed words). */
static inline void vor__vertices(const vor__tri_t *t, vor_index_t v[3])
{
#if VOR_INDEX_BITS == 16
    v[0] = (vor_index_t)(t->v[0] & 0x7FFFu);
    v[1] = t->v[1];
    v[2] = t->v[2];
#else
    uint32_t w0 = t->v[0], w1 = t->v[1];
    v[0] = w0 & 0x1FFFFFu;
    v[1] = (w0 >> 21) | ((w1 & 0x3FFu) << 11);
    v[2] = (w1 >> 10) & 0x1FFFFFu;
#endif
}

/* The transient site mark of a home slot (incremental.c). */
static inline bool vor__marked(const vor__tri_t *t)
{
#if VOR_INDEX_BITS == 16
    return (t->v[0] & VOR__MARK_BIT) != 0u;
#else
    return (t->v[1] & VOR__MARK_BIT) != 0u;
#endif
}

static inline void vor__set_mark(vor__tri_t *t, bool on)
{
#if VOR_INDEX_BITS == 16
    t->v[0] = (vor_index_t)(on ? (t->v[0] | VOR__MARK_BIT) : (t->v[0] & ~VOR__MARK_BIT));
#else
    t->v[1] = on ? (t->v[1] | VOR__MARK_BIT) : (t->v[1] & ~VOR__MARK_BIT);
#endif
}

static inline bool vor__slot_empty(const vor__tri_t *t)
{
    return t->n[0] == VOR__NONE;
}

/* Is `site` a site of the mesh (an id handed out, not a duplicate's)? A
 * mesh of one vertex has no triangles: its only site is the last one. */
static inline bool vor__site_in_mesh(const vor_t *d, uint32_t site)
{
    if (site >= d->site_count) {
        return false;
    }
    if (d->vertex_count == 1u) {
        return site == d->last_site;
    }
    return d->vertex_count >= 2u && !vor__slot_empty(&d->triangles[site]);
}

/* In triangle `slot`, points the link across its edge that ends at
 * vertex a (x -> a, x the vertex before a) at `to`, which runs that edge
 * a -> x. By vertices, not by the old link: a two-site mesh's two
 * triangles are each other's neighbour across all three edges. a's
 * position is data, so it is found without a branch on it. */
static inline void vor__relink_before(vor__tri_t *tri, vor_index_t slot, vor_index_t a,
                                      vor_index_t to)
{
    vor__tri_t *t = &tri[slot];
    vor_index_t v[3];
    vor__vertices(t, v);
    unsigned i = (unsigned)(v[1] == a) | ((unsigned)(v[2] == a) << 1);
    if (v[i] == a) { /* always in a valid mesh */
        t->n[vor__next(i)] = to;
    }
}

/* Writes a whole triangle into slot t, keeping the slot's site mark. */
static inline void vor__tri_set(vor__tri_t *t, vor_index_t v0, vor_index_t v1,
                                vor_index_t v2, vor_index_t n0, vor_index_t n1,
                                vor_index_t n2)
{
#if VOR_INDEX_BITS == 16
    t->v[0] = (vor_index_t)((t->v[0] & VOR__MARK_BIT) | v0);
    t->v[1] = v1;
    t->v[2] = v2;
#else
    t->v[0] = v0 | (v1 << 21);
    t->v[1] = (t->v[1] & VOR__MARK_BIT) | (v1 >> 11) | (v2 << 10);
#endif
    t->n[0] = n0;
    t->n[1] = n1;
    t->n[2] = n2;
}

/* A slot about to get its first triangle: clears whatever mark bit its
 * earlier contents (scratch space, an old triangle) left. */
static inline void vor__tri_fresh(vor__tri_t *t)
{
    vor__set_mark(t, false);
}

static inline bool vor__is_ghost(const vor__tri_t *t)
{
    return vor__vertex(t, 0) == VOR__INFINITE || vor__vertex(t, 1) == VOR__INFINITE ||
           vor__vertex(t, 2) == VOR__INFINITE;
}

/* What the iterators report is the true Delaunay triangulation of the
 * distinct sites, not the perturbed mesh (docs/design.md, "What the
 * iterators report"): a finite triangle is reported exactly when its
 * three sites are not collinear (unperturbed). A flat triangle's perturbed
 * circumcircle is a half-plane in the limit, empty only on a side of a
 * hull line, so dropping those leaves a triangulation of the hull. */
static inline bool vor__reported(const vor_point_t *s, const vor__tri_t *t)
{
    vor_index_t v[3];
    vor__vertices(t, v);
    return v[0] != VOR__INFINITE && v[1] != VOR__INFINITE && v[2] != VOR__INFINITE &&
           vor__orient2d_exact(&s[v[0]], &s[v[1]], &s[v[2]], NULL) != 0;
}

static inline int vor__sign64(int64_t v)
{
    return (v > 0) - (v < 0);
}

/* For collinear a, m, b: does m lie strictly inside the segment ab? Then
 * the steps a -> m and m -> b point the way a -> b does, coordinate by
 * coordinate (no products needed). */
static inline bool vor__strictly_between(const vor_point_t *a, const vor_point_t *m,
                                         const vor_point_t *b)
{
    int sx = vor__sign64((int64_t)b->x - a->x), sy = vor__sign64((int64_t)b->y - a->y);
    return vor__sign64((int64_t)m->x - a->x) == sx && vor__sign64((int64_t)m->y - a->y) == sy &&
           vor__sign64((int64_t)b->x - m->x) == sx && vor__sign64((int64_t)b->y - m->y) == sy;
}

/* Does site c (VOR__INFINITE for a triangle at infinity), the third vertex
 * of a triangle on the mesh edge a-b, lie exactly on the segment between
 * a and b? Then a and b are not Delaunay neighbours: c is strictly closer
 * than both on their whole bisector. */
static inline bool vor__splits_edge(const vor_point_t *s, uint32_t a, uint32_t b, uint32_t c)
{
    return c != VOR__INFINITE && vor__orient2d_exact(&s[a], &s[b], &s[c], NULL) == 0 &&
           vor__strictly_between(&s[a], &s[c], &s[b]);
}

/* Is the mesh edge a-b, between the triangles with third vertices c and e
 * (either may be VOR__INFINITE), an edge of the true triangulation, or on
 * all-collinear input a pair of sites adjacent along the line? When a
 * triangle on it is reported, yes. Otherwise both are flat or at infinity,
 * and a-b is a true edge unless one of them has its third vertex between
 * a and b: a site strictly between a and b but on neither triangle would
 * lie, under the perturbation, on one side of the edge, where the
 * triangle's circumcircle (a half-plane through a and b in the limit, or
 * the outside of the hull) contains the segment's neighbourhood. And a
 * reported triangle never sits beside a splitting one: its circumcircle
 * would hold the splitting site on its chord a-b. */
static inline bool vor__true_edge(const vor_point_t *s, uint32_t a, uint32_t b, uint32_t c,
                                  uint32_t e)
{
    if (c != VOR__INFINITE && vor__orient2d_exact(&s[a], &s[b], &s[c], NULL) != 0) {
        return true;
    }
    return !vor__splits_edge(s, a, b, c) && !vor__splits_edge(s, a, b, e);
}

/* Index (0..2) of neighbour `slot` in t's neighbour list; 3 if absent. */
static inline unsigned vor__neighbour_index(const vor__tri_t *t, vor_index_t slot)
{
    return (t->n[0] == slot) ? 0u : (t->n[1] == slot) ? 1u : (t->n[2] == slot) ? 2u : 3u;
}

/* Index of vertex v in t; 3 if absent. */
static inline unsigned vor__vertex_index(const vor__tri_t *t, vor_index_t v)
{
    return (vor__vertex(t, 0) == v)   ? 0u
           : (vor__vertex(t, 1) == v) ? 1u
           : (vor__vertex(t, 2) == v) ? 2u
                                      : 3u;
}

/* Field by field: a structure assignment of this size becomes a memcpy
 * call on some targets, and the library calls nothing outside itself. */
static inline void vor__copy_stats(vor_predicate_stats_t *to,
                                   const vor_predicate_stats_t *from)
{
    for (unsigned t = 0; t < VOR_TIERS; t++) {
        to->orient2d[t] = from->orient2d[t];
        to->incircle[t] = from->incircle[t];
        to->closer[t] = from->closer[t];
    }
    to->orient2d_perturbed = from->orient2d_perturbed;
    to->incircle_perturbed = from->incircle_perturbed;
    to->closer_perturbed = from->closer_perturbed;
#ifdef VOR_FAULT_INJECTION
    to->fault_rate = from->fault_rate;
    to->fault_state = from->fault_state;
#endif
}

/* The mesh neighbours of a site, turning around it from its home slot:
 * one per triangle of its fan, flat triangles included. The builders and
 * the queries walk these (their proofs hold on the perturbed triangulation,
 * and they pay no extra predicate); vor_neighbours_next reports the true
 * ones among them. `left` bounds the turn even on a broken mesh. Sets *third to the third vertex of the triangle after the edge. */
static inline void vor__fan_begin(vor_neighbour_iter_t *it, const vor_t *d, uint32_t site)
{
    it->d = d;
    it->site = site;
    it->slot = site;
    /* no triangles: one site, or a duplicate's id */
    it->left = (d != NULL && d->vertex_count >= 2u && site < d->site_count &&
                !vor__slot_empty(&d->triangles[site]))
                   ? d->vertex_count + 1u
                   : 0u;
}

static inline bool vor__fan_next(vor_neighbour_iter_t *it, uint32_t *neighbour, uint32_t *third)
{
    const vor_t *d = it->d;
    while (it->left > 0u) {
        const vor__tri_t *t = &d->triangles[it->slot];
        unsigned i = vor__vertex_index(t, (vor_index_t)it->site);
        if (i == 3u) { /* not in this triangle: only on a broken mesh */
            it->left = 0;
            return false;
        }
        vor_index_t n = vor__vertex(t, vor__next(i));
        *third = vor__vertex(t, vor__prev(i));
        it->slot = t->n[vor__prev(i)];
        it->left = (it->slot == it->site) ? 0u : it->left - 1u;
        if (n != VOR__INFINITE) {
            *neighbour = n;
            return true;
        }
    }
    return false;
}

/* The next mesh neighbour that is a true one (vor__true_edge): the
 * triangle just passed lies on one side of the edge, the fan's next (in
 * it->slot) on the other. What vor_neighbours_next reports. */
static inline bool vor__true_neighbour_next(vor_neighbour_iter_t *it, uint32_t *neighbour)
{
    const vor_t *d = it->d;
    uint32_t n, third;
    while (vor__fan_next(it, &n, &third)) {
        const vor__tri_t *after = &d->triangles[it->slot];
        unsigned j = vor__vertex_index(after, (vor_index_t)it->site);
        uint32_t other = (j == 3u) ? VOR__INFINITE : vor__vertex(after, vor__next(j));
        if (vor__true_edge(d->sites, it->site, n, third, other)) {
            *neighbour = n;
            return true;
        }
    }
    return false;
}

/* Used triangle slots in increasing order (geometry.c walks them like the
 * triangle iterator): the next used slot at or after `slot`, or
 * vor__used_slots_end(d) when none is left. */
uint32_t vor__next_used_slot(const vor_t *d, uint32_t slot);
uint32_t vor__used_slots_end(const vor_t *d);

/* Slots in use for v sites in the mesh: 2v - 2 for v >= 2, else 0. */
static inline uint32_t vor__triangle_count(uint32_t vertices)
{
    return (vertices >= 2u) ? 2u * vertices - 2u : 0u;
}

/* The perturbed predicates as the mesh calls them: site ids are the
 * perturbation's order, the diagram's stats count the tiers, and the
 * narrow tiers are inlined. In fault injection builds (tests only) a sign
 * is flipped with probability fault_rate / 2^32. */
static inline int vor__with_faults(vor_t *d, int sign)
{
#ifdef VOR_FAULT_INJECTION
    if (d->stats.fault_rate != 0u) {
        uint64_t x = d->stats.fault_state;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        d->stats.fault_state = x;
        return ((uint32_t)(x >> 32) < d->stats.fault_rate) ? -sign : sign;
    }
#else
    (void)d;
#endif
    return sign;
}

static inline int vor__orient(vor_t *d, uint32_t a, uint32_t b, uint32_t c)
{
    const vor_point_t *s = d->sites;
    int sign = vor__orient2d_exact(&s[a], &s[b], &s[c], &d->stats);
    if (sign == 0) {
        sign = vor__orient2d_perturbed(s, a, b, c, &d->stats);
    }
    return vor__with_faults(d, sign);
}

VOR__INLINE int vor__incircle(vor_t *d, uint32_t a, uint32_t b, uint32_t c, uint32_t p)
{
    const vor_point_t *s = d->sites;
    int sign = vor__incircle_exact(&s[a], &s[b], &s[c], &s[p], &d->stats);
    if (sign == 0) {
        sign = vor__incircle_perturbed(s, a, b, c, p, &d->stats);
    }
    return vor__with_faults(d, sign);
}

static inline int vor__closer(vor_t *d, uint32_t p, uint32_t a, uint32_t b)
{
    return vor__with_faults(d, vor_closer_sos(d->sites, p, a, b, &d->stats));
}

/* Does the triangle (v0, v1, v2) (finite or at infinity) conflict with
 * site p, i.e. is p strictly inside its circumcircle (for a hull triangle:
 * strictly outside its hull edge, left of a -> b in (a, b, inf))? The
 * Voronoi vertex it stands for would be deleted by p. */
static inline bool vor__conflicts(vor_t *d, vor_index_t v0, vor_index_t v1, vor_index_t v2,
                                  uint32_t p)
{
    if (v0 == VOR__INFINITE) {
        return vor__orient(d, v1, v2, p) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return vor__orient(d, v2, v0, p) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return vor__orient(d, v0, v1, p) > 0;
    }
    return vor__incircle(d, v0, v1, v2, p) > 0;
}

/* Places site p in the mesh: returns the slot of the triangle that contains
 * it (a hull triangle when p is outside the hull), walking from slot start.
 * *on_line is set when p lies exactly (unperturbed) on the line of one of
 * that triangle's edges, the only case where p may coincide with a site
 * that is not a vertex of the triangle. Bounded by the number of triangles
 * even if the predicates lie. */
vor_index_t vor__locate(vor_t *d, vor_index_t start, uint32_t p, bool *on_line);

/* The site nearest to point p (not in the mesh) under the perturbation,
 * by a greedy walk over Delaunay neighbours from site `from` (the
 * starting-point search of Ohya, Iri and Murota). */
uint32_t vor__nearest_site(vor_t *d, uint32_t from, uint32_t p);

/* Inserts site p (coordinates set, not yet in the mesh, v >= 2 sites
 * present) into the triangle at slot root that contains it. */
void vor__insert_at(vor_t *d, vor_index_t root, uint32_t p);

/* The first two sites: two triangles at infinity sharing the edge ab
 * (mesh.c). */
void vor__make_edge(vor_t *d, uint32_t a, uint32_t b);

/* What every builder does first (mesh.c): checks d, points and n, then
 * replaces d's contents by the n sites, copied, with their bounding box.
 * Returns a negative error (nothing changed), VOR_OK when n <= 1 (done),
 * or VOR__BUILD_MESH: the builder must now mesh sites 0 .. n - 1. */
#define VOR__BUILD_MESH 1
int vor__build_start(vor_t *d, const vor_point_t *points, uint32_t n,
                     uint32_t *duplicate_of);

/* Grows the sites' bounding box to hold p (the first site sets it). */
static inline void vor__box_add(vor_t *d, const vor_point_t *p, bool first)
{
    if (first) {
        d->low.x = d->high.x = p->x;
        d->low.y = d->high.y = p->y;
        return;
    }
    d->low.x = (p->x < d->low.x) ? p->x : d->low.x;
    d->low.y = (p->y < d->low.y) ? p->y : d->low.y;
    d->high.x = (p->x > d->high.x) ? p->x : d->high.x;
    d->high.y = (p->y > d->high.y) ? p->y : d->high.y;
}

/* The bucket grid (bucket_grid.c), for meshes of two or more sites:
 * vor__grid_rebuild draws it over the bounding box and fills it;
 * vor__grid_add records a site just inserted (and redraws the grid when
 * the site count has doubled); vor__grid_start is a site near (x, y). */
void vor__grid_rebuild(vor_t *d);
void vor__grid_add(vor_t *d, uint32_t site);
uint32_t vor__grid_start(const vor_t *d, int32_t x, int32_t y);
/* Site `site` (coordinates still those the grid knows) leaves the grid:
 * its entries go to a neighbouring run's site, or to `fallback` (a site
 * in the mesh) when it named every bucket. */
void vor__grid_forget(vor_t *d, uint32_t site, uint32_t fallback);
/* Site `site`, now at its new coordinates, was at `from`. */
void vor__grid_move(vor_t *d, uint32_t site, vor_point_t from, uint32_t fallback);

/* Removal's last step (dynamic.c): home slot h lost its triangle and
 * `start` holds another of h's; the packed slots run to `last`, one
 * triangle too many. Refills slot h and packs the slots again. */
void vor__rehome(vor_t *d, vor_index_t h, vor_index_t start, vor_index_t last);

/* vor_build's plan (insertion_order.c): for the n sites already copied
 * into d->sites, writes plan[2i] = the i-th site to insert and plan[2i+1]
 * = the site its search starts from (VOR__NONE: the previous one); the
 * duplicates come last, with their first occurrence. Returns
 * the number of distinct sites. Writes duplicate_of[] if not NULL. Uses
 * scratch[0 .. 6n + 2) for n >= 8; scratch and plan must not overlap. */
uint32_t vor__plan(const vor_t *d, uint32_t n, enum vor_order order,
                   vor_index_t *scratch, vor_index_t *plan, uint32_t *duplicate_of);

/* The column (row) of coordinate c in a 2^k x 2^k grid over a square of
 * side 2^shift from low: floor((c - low) 2^k / 2^shift), for low <= c and
 * c - low < 2^shift (k <= 12, shift <= 32). c - low < 2^32, so this is one
 * 32-bit shift, by shift - k or, in a square smaller than the grid, left
 * by k - shift: no 64-bit shift, which is a runtime call on some targets. */
static inline uint32_t vor__grid_cell(int32_t c, int32_t low, unsigned k, unsigned shift)
{
    uint32_t offset = (uint32_t)((int64_t)c - low);
    if (shift < k) {
        return offset << (k - shift); /* < 2^k */
    }
    return (shift - k < 32u) ? offset >> (shift - k) : 0u;
}

/* Introsort of ids[0..n) by a strict total order on site ids, ids breaking
 * ties: Z-order for the plan, lexicographic (x, y) for the divide-and-conquer
 * builder. O(n log n) worst case, in place, a stack of 34 ranges
 * (insertion_order.c). A key, not a function pointer, keeps the call graph
 * static (make size). */
enum vor__sort_key { VOR__SORT_Z, VOR__SORT_LEX };
void vor__sort_ids(const vor_point_t *sites, vor_index_t *ids, uint32_t n,
                   enum vor__sort_key key);


#endif

