/* SPDX-License-Identifier: MIT */
/*
 * mesh.h - the triangle mesh behind the diagram, private to the library:
 * its topology only (layout, accessors, home slots, fans). It knows no
 * coordinates' geometry: the predicates the builders test it with are in
 * perturbation.h, which builds on this header, never the other way.
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

#include "multiword.h"
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
 * coordinates and home slots lie anywhere in the arena. Only where it can
 * help: with GCC or clang, and not on the microcontroller cores (Arm's
 * M profile, 32-bit RISC-V), which read RAM in a cycle or two and would
 * only pay the hint's instructions (a Cortex-M3 executes PLD). Code that
 * exists only to prefetch tests VOR__PREFETCHING, so that it compiles
 * away there. */
#if defined(__GNUC__) && !(defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M') &&      \
    !(defined(__riscv) && __riscv_xlen == 32)
#define VOR__PREFETCHING 1
#define VOR__PREFETCH(address) __builtin_prefetch(address)
#else
#define VOR__PREFETCHING 0
#define VOR__PREFETCH(address) ((void)(address))
#endif

/* (i + 1) mod 3 and (i + 2) mod 3 without a division. ">= 2" rather
 * than "== 2": the result is then provably below 3 even for the "not
 * found" index 3 of vor__vertex_index, which keeps gcc -O3's array-bounds
 * analysis quiet at no cost (one compare either way). */
static inline unsigned vor__next(unsigned i)
{
    return (i >= 2u) ? 0u : (i + 1u);
}
static inline unsigned vor__prev(unsigned i)
{
    return (i == 0u) ? 2u : (i - 1u);
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
    uint32_t w0 = t->v[0];
    uint32_t w1 = t->v[1];
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
    return (d->vertex_count >= 2u) && !vor__slot_empty(&d->triangles[site]);
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
    unsigned i = (v[1] == a) ? 1u : 0u;
    i |= (v[2] == a) ? 2u : 0u;
    VOR_ASSERT(i < 3u); /* a triangle's three vertices differ */
    if (v[i] == a) { /* always in a valid mesh */
        t->n[vor__next(i)] = to;
    }
}

/* Writes a whole triangle into slot t, keeping the slot's site mark. */
static inline void vor__tri_set(vor__tri_t *t, vor_index_t v0, vor_index_t v1,
                                vor_index_t v2, vor_index_t n0, vor_index_t n1,
                                vor_index_t n2);

/* In triangle `slot`, points the link that pointed at `from` at `to`. */
static inline void vor__relink(vor__tri_t *tri, vor_index_t slot, vor_index_t from,
                               vor_index_t to)
{
    vor__tri_t *t = &tri[slot];
    unsigned i = (t->n[0] == from) ? 0u : (t->n[1] == from) ? 1u : (t->n[2] == from) ? 2u : 3u;
    if (i != 3u) { /* always found in a valid mesh */
        t->n[i] = to;
    }
}

/* The edge flip: triangle (p, x, y) in slot t_slot and its neighbour
 * across x-y, (y, x, c) in u_slot, become (p, x, c) and (p, c, y). The
 * outer links: nx across p-y... named by the edge they cross: t's across
 * y-p (nx) and p-x (ny), u's across x-c and c-y. Home slots stay home:
 * (p, x, c) holds x, (p, c, y) holds y, both p and c, so the two slots go
 * where their sites are. Four distinct outer triangles (meshes of four or
 * more vertices). Returns the slot of (p, x, c). */
static inline vor_index_t vor__flip_core(vor_t *d, vor_index_t t_slot, vor_index_t u_slot,
                                         vor_index_t p, vor_index_t x, vor_index_t y,
                                         vor_index_t c, vor_index_t nx, vor_index_t ny,
                                         vor_index_t across_xc, vor_index_t across_cy)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t s1 = t_slot;
    vor_index_t s2 = u_slot;
    if (((t_slot == y) && (y < d->max_sites)) || ((u_slot == x) && (x < d->max_sites))) {
        s1 = u_slot;
        s2 = t_slot;
    }
    vor__relink(tri, across_xc, u_slot, s1);
    vor__relink(tri, across_cy, u_slot, s2);
    vor__relink(tri, ny, t_slot, s1);
    vor__relink(tri, nx, t_slot, s2);
    vor__tri_set(&tri[s1], p, x, c, across_xc, s2, ny);
    vor__tri_set(&tri[s2], p, c, y, across_cy, nx, s1);
    return s1;
}

/* A site's transient mark, infinity's kept by the caller: the insertions'
 * marks on the vertices of the new site's star (incremental.c, power.c). */
static inline bool vor__site_marked(const vor_t *d, vor_index_t v, bool infinity_marked)
{
    return (v == VOR__INFINITE) ? infinity_marked : vor__marked(&d->triangles[v]);
}

static inline void vor__mark_site(vor_t *d, vor_index_t v, bool on, bool *infinity_marked)
{
    if (v == VOR__INFINITE) {
        *infinity_marked = on;
    } else {
        vor__set_mark(&d->triangles[v], on);
    }
}

/* Flips the edge opposite p in star triangle `x_slot` = (p, x, y) with
 * its neighbour (y, x, c): the triangles become (p, x, c) and (p, c, y).
 * Returns the slot of (p, x, c). `apex` is c's index in the neighbour. */
static inline vor_index_t vor__star_flip(vor_t *d, vor_index_t x_slot, vor_index_t p, vor_index_t x,
                        vor_index_t y, unsigned apex, vor_index_t c)
{
    vor__tri_t *tri = d->triangles;
    vor__tri_t *t = &tri[x_slot];
    vor_index_t y_slot = t->n[0];
    vor__tri_t *u = &tri[y_slot];
    /* the star has at least three vertices besides p when flips happen:
     * four distinct outer triangles */
    return vor__flip_core(d, x_slot, y_slot, p, x, y, c, t->n[1], t->n[2], u->n[vor__next(apex)],
                          u->n[vor__prev(apex)]);
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
    it->left = ((d != NULL) && (d->vertex_count >= 2u) && (site < d->site_count) &&
                !vor__slot_empty(&d->triangles[site]))
                   ? (d->vertex_count + 1u)
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
        it->left = (it->slot == it->site) ? 0u : (it->left - 1u);
        if (n != VOR__INFINITE) {
            *neighbour = n;
            return true;
        }
    }
    return false;
}

/* Slots holding triangles, in increasing order: the non-empty home slots
 * of site ids, then the packed extra slots (the validator, the triangle
 * iterator and geometry.c walk them). vor__used_slots_end is one past the
 * last extra slot (v - 2 extras for v >= 2 sites); vor__next_used_slot is
 * the next used slot at or after `slot`, or that end when none is left. */
VOR__SHARED_INLINE uint32_t vor__used_slots_end(const vor_t *d)
{
    return d->max_sites + ((d->vertex_count >= 2u) ? (d->vertex_count - 2u) : 0u);
}

static inline uint32_t vor__next_used_slot(const vor_t *d, uint32_t slot_in)
{
    uint32_t slot = slot_in;
    for (; slot < d->site_count; slot++) {
        if (!vor__slot_empty(&d->triangles[slot])) {
            return slot;
        }
    }
    if (slot < d->max_sites) {
        slot = d->max_sites;
    }
    uint32_t end = vor__used_slots_end(d);
    return (slot < end) ? slot : end;
}

/* Slots in use for v sites in the mesh: 2v - 2 for v >= 2, else 0. */
static inline uint32_t vor__triangle_count(uint32_t vertices)
{
    return (vertices >= 2u) ? ((2u * vertices) - 2u) : 0u;
}

/* The constrained triangulation's upkeep (d->cdt_update, cdt.c), called
 * by the diagram's calls at these events of site p:
 *   VOR__CDT_CHECK_INSERT  before p (its coordinates in d->sites[p])
 *                          enters d: VOR_ERR_NOMEM when splitting a
 *                          constrained edge would overfill the table,
 *                          else VOR_OK; changes nothing
 *   VOR__CDT_INSERTED      p is in d's mesh: into the constrained one too
 *   VOR__CDT_REMOVE        p is about to leave d: VOR_ERR_CONSTRAINED when
 *                          a constrained edge ends at p (nothing changes),
 *                          else p leaves the constrained mesh
 *   VOR__CDT_CHECK_REMOVE  VOR__CDT_REMOVE's check alone; changes nothing
 *   VOR__CDT_REBUILT       d was built anew: the constrained mesh becomes
 *                          its Delaunay triangulation, without constraints */
#define VOR__CDT_CHECK_INSERT 0u
#define VOR__CDT_INSERTED 1u
#define VOR__CDT_REMOVE 2u
#define VOR__CDT_REBUILT 3u
#define VOR__CDT_CHECK_REMOVE 4u

/* The first two sites: two triangles at infinity sharing the edge ab
 * (mesh.c). */
void vor__make_edge(vor_t *d, uint32_t a, uint32_t b);

/* vor_validate's topological checks (queries.c), up to the bucket grid:
 * VOR_OK or VOR_ERR_INVALID with the first violation in *out (may be
 * NULL); vor_power_validate adds its own geometric ones. */
int vor__validate_topology(const vor_t *d, vor_violation_t *out);

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
        d->high.x = p->x;
        d->low.x = d->high.x;
        d->high.y = p->y;
        d->low.y = d->high.y;
        return;
    }
    d->low.x = (p->x < d->low.x) ? p->x : d->low.x;
    d->low.y = (p->y < d->low.y) ? p->y : d->low.y;
    d->high.x = (p->x > d->high.x) ? p->x : d->high.x;
    d->high.y = (p->y > d->high.y) ? p->y : d->high.y;
}

/* A turn around site p's star, one triangle at a step, with the vertices
 * of the tests that involve p besides the triangle's own orientation:
 * `far` across its far edge x-y, `across` across its spoke p-y (the third
 * vertex of the next star triangle, counterclockwise). vor_move's check
 * (dynamic.c) and the motion cache (motion.c) walk the same predicates
 * with it. Each triangle's vertices are decoded once. */
typedef struct vor__star_step {
    vor_index_t slot;
    vor_index_t v[3];  /* the star triangle and its vertices, as stored */
    vor_index_t x;
    vor_index_t y;        /* p's neighbours in it, counterclockwise */
    vor_index_t far;
    vor_index_t across;
    vor_index_t next;
    vor_index_t w[3];  /* the next star triangle and its vertices */
} vor__star_step_t;

static inline void vor__star_look(const vor_t *d, vor_index_t p, vor__star_step_t *s)
{
    const vor__tri_t *tri = d->triangles;
    const vor__tri_t *t = &tri[s->slot];
    unsigned i = (s->v[1] == p) ? 1u : (s->v[2] == p) ? 2u : 0u;
    s->x = s->v[vor__next(i)];
    s->y = s->v[vor__prev(i)];
    const vor__tri_t *o = &tri[t->n[i]];
    unsigned k = vor__vertex_index(o, s->x);
    s->far = vor__vertex(o, vor__next((k == 3u) ? 0u : k));
    s->next = t->n[vor__next(i)];
    vor__vertices(&tri[s->next], s->w);
    unsigned j = (s->w[1] == p) ? 1u : (s->w[2] == p) ? 2u : 0u;
    s->across = s->w[vor__prev(j)];
}

/* The star triangle in p's home slot (p in a mesh of three or more). */
static inline void vor__star_begin(const vor_t *d, vor_index_t p, vor__star_step_t *s)
{
    s->slot = p;
    vor__vertices(&d->triangles[p], s->v);
    vor__star_look(d, p, s);
}

/* The next star triangle; false when the turn is back at p's home slot,
 * after p's degree (at most vertex_count) steps: callers bound their
 * loops by vertex_count + 1 as well, against a broken mesh. */
static inline bool vor__star_advance(const vor_t *d, vor_index_t p, vor__star_step_t *s)
{
    s->slot = s->next;
    if (s->slot == p) {
        return false;
    }
    s->v[0] = s->w[0];
    s->v[1] = s->w[1];
    s->v[2] = s->w[2];
    vor__star_look(d, p, s);
    return true;
}

#if VOR_STATS
/* The counters vor_t keeps in a VOR_STATS build (vor_init clears them,
 * vor_stats reads them, failing calls restore them), copied and cleared
 * field by field: a structure assignment of this size becomes a memcpy
 * call on some targets. */
static inline void vor__stats_copy(vor_stats_t *to, const vor_stats_t *from)
{
    for (unsigned t = 0; t < (unsigned)VOR_TIERS; t++) {
        to->orient2d[t] = from->orient2d[t];
        to->incircle[t] = from->incircle[t];
        to->closer[t] = from->closer[t];
    }
    to->orient2d_perturbed = from->orient2d_perturbed;
    to->incircle_perturbed = from->incircle_perturbed;
    to->closer_perturbed = from->closer_perturbed;
    to->power = from->power;
    to->power_perturbed = from->power_perturbed;
}

static inline void vor__stats_clear(vor_stats_t *s)
{
    for (unsigned t = 0; t < (unsigned)VOR_TIERS; t++) {
        s->orient2d[t] = 0;
        s->incircle[t] = 0;
        s->closer[t] = 0;
    }
    s->orient2d_perturbed = 0;
    s->incircle_perturbed = 0;
    s->closer_perturbed = 0;
    s->power = 0;
    s->power_perturbed = 0;
}
#endif

#endif
