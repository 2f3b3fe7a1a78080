/* SPDX-License-Identifier: MIT */
/*
 * power.c - weighted sites (vor_power.h): the regular triangulation, dual
 * of the power diagram, on the diagram's mesh (docs/design/power.md).
 *
 * Lift site i to (x, y, x^2 + y^2 - w_i): the regular triangulation is
 * the lower hull of the lifted sites seen from below, and a site whose
 * lifted point lies above that hull is hidden. Inserting site p
 * (Edelsbrunner and Shah, "Incremental topological flipping works for
 * regular triangulations", 1996):
 *
 *   1. locate p's triangle; if p's lifted point is not below the
 *      triangle's lifted plane (the power test), p is hidden: done;
 *   2. split the triangle into three around p;
 *   3. walk around p's star. The edge x-y of star triangle (p, x, y) with
 *      its neighbour (y, x, c) is not locally regular when the power test
 *      puts p below the lifted plane of (y, x, c). Then
 *        - if p, x, c, y is convex, flip x-y to p-c (2-2 flip);
 *        - if it is reflex at y and y has only the neighbours p, x, c,
 *          merge y's three triangles into (p, x, c): y is hidden (3-1
 *          flip); the same at x;
 *        - else leave the edge for later.
 *      The walk ends after a whole turn without a flip. Edelsbrunner and
 *      Shah show that while an edge of the star is not locally regular
 *      one of them can be flipped, so the star ends regular.
 *
 * Topological guard: a 2-2 flip whose far vertex c is already on the star
 * is refused (marks, as in incremental.c), so no flip can put an edge
 * into the mesh twice, whatever the predicates answer. Every flip turns
 * a triangle off the star into star triangles and none goes the other
 * way, so the walk ends within the triangle count even if they lie.
 *
 * A hidden site keeps its id; its empty home slot links the hidden ids'
 * list: n[0] VOR__NONE (empty), n[1] the next hidden id plus one (0: the
 * end), n[2] HIDDEN. A duplicate's slot holds its twin in n[1] and
 * DUPLICATE in n[2].
 */
#include "bucket_grid.h"
#include "dynamic.h"
#include "incremental.h"
#include "insertion_order.h"
#include "mesh.h"
#include "perturbation.h"
#include "predicates.h"
#include "vor_power.h"

/* what an empty home slot's n[2] says about its id */
#define DUPLICATE ((vor_index_t)0u)
#define HIDDEN ((vor_index_t)1u)
#define PENDING ((vor_index_t)2u) /* vor_power_build: to be placed last */

/* place's outcomes besides VOR_OK (a vertex) and VOR_ERR_DUPLICATE */
#define PLACED_HIDDEN 1

/* ------------------------------------------------------------------ */
/* Predicates                                                          */

/* The perturbed power test of site p against the counterclockwise finite
 * (a, b, c): positive when p's lifted point is below their plane. *tie
 * becomes true when the exact test is 0. */
static int power_test(vor_power_t *pd, vor_index_t a, vor_index_t b, vor_index_t c, uint32_t p,
                      bool *tie)
{
    vor_t *d = &pd->mesh;
    const vor_point_t *s = d->sites;
    const int64_t *w = pd->weights;
    const int64_t ws[4] = {w[a], w[b], w[c], w[p]};
    int sign = vor__power_exact(&s[a], &s[b], &s[c], &s[p], ws, VOR__STATS_OF(d));
    if (sign == 0) {
        *tie = true;
        sign = vor__power_perturbed(s, w, a, b, c, p, VOR__STATS_OF(d));
    }
    return vor__with_faults(d, sign);
}

/* Is triangle (v0, v1, v2) not locally regular once p is in: p below its
 * lifted plane, or for a triangle at infinity, beyond its hull edge? */
static bool conflicts(vor_power_t *pd, vor_index_t v0, vor_index_t v1, vor_index_t v2,
                      uint32_t p, bool *tie)
{
    vor_t *d = &pd->mesh;
    if (v0 == VOR__INFINITE) {
        return vor__orient_tie(d, VOR__STATS_OF(d), v1, v2, p, tie) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return vor__orient_tie(d, VOR__STATS_OF(d), v2, v0, p, tie) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return vor__orient_tie(d, VOR__STATS_OF(d), v0, v1, p, tie) > 0;
    }
    return power_test(pd, v0, v1, v2, p, tie) > 0;
}

/* The removal's predicates (dynamic.c) on this mesh: the orientation,
 * and for four vertices the power test in place of the incircle. */
static int removal_predicate(vor_t *mesh, const uint32_t *ids, unsigned count)
{
    vor_power_t *pd = (vor_power_t *)(void *)mesh; /* the first member */
    bool tie = false;
    if (count == 3u) {
        return vor__orient(mesh, ids[0], ids[1], ids[2]);
    }
    return power_test(pd, (vor_index_t)ids[0], (vor_index_t)ids[1], (vor_index_t)ids[2], ids[3],
                      &tie);
}

static bool same_point(const vor_point_t *a, const vor_point_t *b)
{
    return (a->x == b->x) && (a->y == b->y);
}

/* Sites a, b, s on one line, s strictly between: the exact sign of s's
 * lifted point against the segment of a's and b's (positive below, 0 on
 * it). The power test with a point c off the line, whose weight does not
 * matter: on the line, the plane through a', b' and c' is the segment's
 * line. */
static int lifted_side(const vor_power_t *pd, uint32_t a, uint32_t b, uint32_t s)
{
    const vor_point_t *site = pd->mesh.sites;
    vor_point_t c = site[a];
    bool vertical = site[a].x == site[b].x;
    if (vertical) {
        c.x = (c.x < INT32_MAX) ? (c.x + 1) : (c.x - 1);
    } else {
        c.y = (c.y < INT32_MAX) ? (c.y + 1) : (c.y - 1);
    }
    const int64_t w[4] = {pd->weights[a], pd->weights[b], 0, pd->weights[s]};
    int power = vor__power_exact(&site[a], &site[b], &c, &site[s], w, NULL);
    return (vor__orient2d_sign(&site[a], &site[b], &c) > 0) ? power : -power;
}

/* ------------------------------------------------------------------ */
/* Hidden sites                                                        */

static void empty_slot(vor_power_t *pd, uint32_t id, vor_index_t link, vor_index_t kind)
{
    vor__tri_t *t = &pd->mesh.triangles[id];
    vor__tri_fresh(t);
    t->n[0] = VOR__NONE;
    t->n[1] = link;
    t->n[2] = kind;
}

/* Puts id h on the hidden list (its home slot is free: h is no vertex). */
static void hide(vor_power_t *pd, uint32_t h)
{
    empty_slot(pd, h, (vor_index_t)pd->first_hidden, HIDDEN);
    pd->first_hidden = h + 1u;
    pd->hidden_count++;
}

/* Takes vertex y, of degree three with the star's p, out of the mesh:
 * its triangles (y, nb[i], nb[i + 1]) in slots sl[i] merge into one. */
static void hide_vertex(vor_power_t *pd, vor_index_t y, const vor_index_t nb[3],
                        const vor_index_t sl[3], bool *infinity_marked)
{
    vor_t *d = &pd->mesh;
    vor__mark_site(d, y, false, infinity_marked);
    vor__merge_three(d, y, nb, sl);
    d->vertex_count--;
    hide(pd, y);
    d->last_site = (d->last_site == y) ? nb[0] : d->last_site;
}

/* Marks the vertices of p's star, `star` triangles from p's home slot. */
static void mark_star(vor_t *d, vor_index_t p, uint32_t star, bool on, bool *infinity_marked)
{
    vor_index_t slot = p;
    for (uint32_t k = 0; k < star; k++) {
        vor__mark_site(d, vor__vertex(&d->triangles[slot], 1), on, infinity_marked);
        slot = d->triangles[slot].n[1];
    }
}

/* ------------------------------------------------------------------ */
/* Insertion                                                           */

/* What to do with the edge x-y of star triangle (p, x, y) whose
 * neighbour (y, x, c) conflicts with p. */
enum shape { CONVEX, REFLEX_AT_Y, REFLEX_AT_X };

/* *flat becomes true when an exact orientation is 0: a flip would then
 * make a triangle of no area. */
static enum shape quad_shape(vor_t *d, vor_index_t p, vor_index_t x, vor_index_t y, vor_index_t c,
                             bool *flat)
{
    const vor_point_t *s = d->sites;
    if ((x == VOR__INFINITE) || (y == VOR__INFINITE) || (c == VOR__INFINITE)) {
        /* a hull edge: p is beyond it, and c-p crosses x-y; the flip's
         * finite triangle, if any, is (p, x, c) or (p, c, y) */
        vor_index_t u = (x == VOR__INFINITE) ? c : x;
        vor_index_t v = (x == VOR__INFINITE) ? y : c;
        *flat = *flat || ((c != VOR__INFINITE) && (u != VOR__INFINITE) && (v != VOR__INFINITE) &&
                          (vor__orient2d_sign(&s[p], &s[u], &s[v]) == 0));
        return CONVEX;
    }
    if (vor__orient_tie(d, VOR__STATS_OF(d), p, c, y, flat) < 0) {
        return REFLEX_AT_Y;
    }
    return (vor__orient_tie(d, VOR__STATS_OF(d), p, x, c, flat) < 0) ? REFLEX_AT_X : CONVEX;
}

/* Inserts vertex p into the triangle in slot `root` (p below its lifted
 * plane, or beyond its hull edge) and flips its star regular. Returns
 * whether a flip may have left a star triangle of no area (an exact
 * orientation of 0 in a 2-2 flip, or a 3-1 flip); the split leaves one
 * only where p is on a line of the root's edges. */
static bool insert_at(vor_power_t *pd, vor_index_t root, uint32_t p)
{
    bool flat = false;
    vor_t *d = &pd->mesh;
    vor__tri_t *tri = d->triangles;
    vor_index_t sp = (vor_index_t)p;
    (void)vor__split_triangle(d, root, p);
    d->vertex_count++;
    bool infinity_marked = false;
    uint32_t star = 3;
    mark_star(d, sp, star, true, &infinity_marked);

    /* one turn without a flip ends it; every flip uses up a triangle off
     * the star, so the loop ends even if the predicates lie */
    vor_index_t slot = sp;
    uint32_t refused = 0;
    while (refused < star) {
        vor__tri_t *t = &tri[slot];
        /* t = (p, x, y), u = (y, x, c) */
        vor_index_t tv[3];
        vor_index_t uv[3];
        vor__vertices(t, tv);
        vor__vertices(&tri[t->n[0]], uv);
        unsigned ix = vor__vertex_index(&tri[t->n[0]], tv[1]);
        bool tie = false;
        if ((ix == 3u) || !conflicts(pd, uv[0], uv[1], uv[2], p, &tie)) {
            refused++; /* regular (or a corrupted mesh: never index past it) */
            slot = t->n[1];
            continue;
        }
        unsigned apex = vor__next(ix);
        vor_index_t x = tv[1];
        vor_index_t y = tv[2];
        vor_index_t c = uv[apex];
        bool tie_in_shape = false;
        enum shape shape = quad_shape(d, sp, x, y, c, &tie_in_shape);
        vor_index_t next = t->n[1]; /* (p, y, z) */
        vor_index_t prev = t->n[2]; /* (p, z, x) */
        if ((shape == CONVEX) && !vor__site_marked(d, c, infinity_marked)) {
            flat = flat || tie_in_shape;
            slot = vor__star_flip(d, slot, sp, x, y, apex, c);
            vor__mark_site(d, c, true, &infinity_marked);
            star++;
        } else if ((shape == REFLEX_AT_Y) && (vor__vertex(&tri[next], 2) == c)) {
            const vor_index_t nb[3] = {sp, x, c};
            const vor_index_t sl[3] = {slot, t->n[0], next};
            hide_vertex(pd, y, nb, sl, &infinity_marked);
            flat = true;
            star--;
            slot = sp;
        } else if ((shape == REFLEX_AT_X) && (vor__vertex(&tri[prev], 1) == c)) {
            const vor_index_t nb[3] = {sp, c, y};
            const vor_index_t sl[3] = {prev, t->n[0], slot};
            hide_vertex(pd, x, nb, sl, &infinity_marked);
            flat = true;
            star--;
            slot = sp;
        } else {
            refused++;
            slot = t->n[1];
            continue;
        }
        refused = 0;
        /* a merge may move triangles and their marks: mark the star again */
        mark_star(d, sp, star, true, &infinity_marked);
    }
    mark_star(d, sp, star, false, &infinity_marked);
    return flat;
}

/* ------------------------------------------------------------------ */
/* Where the perturbation must not decide: the hull, collinear sites    */

/* Takes vertex y out of the mesh (the removal's ears, with the power
 * test) and hides it. */
static void unlink_hidden(vor_power_t *pd, uint32_t y)
{
    vor_t *d = &pd->mesh;
    uint32_t other = vor__unlink_vertex(d, y);
    pd->flats = true; /* the ears may be flat */
    hide(pd, y);
    d->last_site = (d->last_site == y) ? other : d->last_site;
}

/* Does vertex v have a triangle of nonzero area? Its fan from its home
 * slot, with the exact orientation. */
static bool has_area(const vor_t *d, vor_index_t v)
{
    const vor__tri_t *tri = d->triangles;
    const vor_point_t *s = d->sites;
    vor_index_t slot = v;
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        const vor__tri_t *t = &tri[slot];
        unsigned i = vor__vertex_index(t, v);
        if (i == 3u) {
            return true; /* only on a corrupted mesh: leave the vertex */
        }
        vor_index_t x = vor__vertex(t, vor__next(i));
        vor_index_t y = vor__vertex(t, vor__prev(i));
        if ((x != VOR__INFINITE) && (y != VOR__INFINITE) &&
            (vor__orient2d_sign(&s[v], &s[x], &s[y]) > 0)) {
            return true;
        }
        slot = t->n[vor__next(i)];
        if (slot == v) {
            break;
        }
    }
    return false;
}

/* Is a finite triangle of p's star flat (p on the line of two of its
 * neighbours)? The star from p's home slot. */
static bool star_flat(const vor_t *d, vor_index_t p)
{
    const vor_point_t *s = d->sites;
    vor_index_t slot = p;
    for (uint32_t left = d->vertex_count + 1u; left > 0u; left--) {
        const vor__tri_t *t = &d->triangles[slot];
        unsigned i = vor__vertex_index(t, p);
        if (i == 3u) {
            return false; /* only on a corrupted mesh */
        }
        vor_index_t x = vor__vertex(t, vor__next(i));
        vor_index_t y = vor__vertex(t, vor__prev(i));
        if ((x != VOR__INFINITE) && (y != VOR__INFINITE) &&
            (vor__orient2d_sign(&s[p], &s[x], &s[y]) == 0)) {
            return true;
        }
        slot = t->n[vor__next(i)];
        if (slot == p) {
            break;
        }
    }
    return false;
}

/* Is s strictly between a and b on their line (s on it)? Along x, or
 * along y for a vertical line. */
static bool between(const vor_point_t *site, vor_index_t a, vor_index_t s, vor_index_t b)
{
    int32_t lo = site[a].x;
    int32_t hi = site[b].x;
    int32_t at = site[s].x;
    if (lo == hi) {
        lo = site[a].y;
        hi = site[b].y;
        at = site[s].y;
    }
    return ((lo < at) && (at < hi)) || ((hi < at) && (at < lo));
}

/* Is the triangle in `slot` finite with nonzero area (a true one)? */
static bool true_triangle(const vor_t *d, vor_index_t slot)
{
    vor_index_t v[3];
    vor__vertices(&d->triangles[slot], v);
    return (v[0] != VOR__INFINITE) && (v[1] != VOR__INFINITE) && (v[2] != VOR__INFINITE) &&
           (vor__orient2d_sign(&d->sites[v[0]], &d->sites[v[1]], &d->sites[v[2]]) > 0);
}

/* A T-junction at triangle `slot` (finite): a vertex inside an edge of a
 * true triangle, held there by a flat one across it; VOR__NONE if none.
 * Either t is flat with a vertex inside the edge of its other two and a
 * true triangle across that edge, or t is true with such a flat one
 * across an edge. */
static vor_index_t junction(const vor_t *d, vor_index_t slot)
{
    const vor__tri_t *t = &d->triangles[slot];
    bool flat = !true_triangle(d, slot);
    vor_index_t v[3];
    vor__vertices(t, v);
    for (unsigned i = 0; i < 3u; i++) {
        vor_index_t a = v[vor__next(i)];
        vor_index_t b = v[vor__prev(i)];
        vor_index_t across = t->n[i];
        if (flat) {
            if (between(d->sites, a, v[i], b) && true_triangle(d, across)) {
                return v[i];
            }
        } else {
            const vor__tri_t *u = &d->triangles[across];
            vor_index_t apex = vor__vertex(u, vor__next(vor__vertex_index(u, a)));
            if ((apex != VOR__INFINITE) && !true_triangle(d, across) &&
                between(d->sites, a, apex, b)) {
                return apex;
            }
        }
    }
    return VOR__NONE;
}

/* After vertex p went in, in a mesh with area where flat triangles may
 * be (insert_vertex). Two kinds of vertex have a power cell of no area
 * or an empty one, and are hidden:
 *   - one whose triangles are all flat (a cell with area has a triangle
 *     of the true triangulation at each corner): the perturbation keeps
 *     it only as a sliver at infinity;
 *   - one inside an edge of a true triangle, with a flat triangle across
 *     that edge (a T-junction): its lifted point lies on the lifted edge
 *     (the edge is locally regular), and kept it would leave the true
 *     triangles meeting it on one side only.
 * A vertex becomes one only at p's star: its last true triangle goes to a
 * flat one of the star, or a true triangle of the star comes across the
 * flat one that holds it. Hiding one changes only flat triangles there.
 * Hides p or the vertices so at its star; returns whether p was. */
static bool settle_star(vor_power_t *pd, vor_index_t p)
{
    vor_t *d = &pd->mesh;
    /* p's star, again after each vertex hidden (that changes the star) */
    for (uint32_t round = d->vertex_count; round > 0u; round--) {
        vor_index_t found = VOR__NONE;
        bool flat = false;
        vor_index_t slot = p;
        for (uint32_t left = d->vertex_count + 1u; (left > 0u) && (found == VOR__NONE); left--) {
            const vor__tri_t *t = &d->triangles[slot];
            unsigned i = vor__vertex_index(t, p);
            if (i == 3u) {
                return false; /* only on a corrupted mesh */
            }
            vor_index_t b = vor__vertex(t, vor__next(i));
            vor_index_t c = vor__vertex(t, vor__prev(i));
            if ((b != VOR__INFINITE) && (c != VOR__INFINITE)) {
                /* a vertex loses its last true triangle to a flat one */
                bool true_one = true_triangle(d, slot);
                flat = flat || !true_one;
                if (!true_one && !has_area(d, b)) {
                    found = b;
                } else if (!true_one && !has_area(d, c)) {
                    found = c;
                } else {
                    found = junction(d, slot);
                }
            }
            slot = t->n[vor__next(i)];
            if (slot == p) {
                break;
            }
        }
        if ((found == VOR__NONE) && flat && !has_area(d, p)) {
            found = p;
        }
        if (found == VOR__NONE) {
            break;
        }
        unlink_hidden(pd, found);
        if (found == p) {
            return true;
        }
    }
    return false;
}

/* While every vertex is on one line the triangles are flat and the power
 * test of four collinear sites is 0: the perturbation would decide which
 * are hidden. The diagram is one-dimensional then, and is kept exactly:
 * the vertices are the lower chain of the lifted sites along the line. */

/* With every vertex on one line (two at least): a vertex other than the
 * last site, which with it gives the line (a corner of its home slot's
 * triangle: every triangle has two finite corners). */
static uint32_t line_mate(const vor_t *d)
{
    vor_index_t u[3];
    vor__vertices(&d->triangles[d->last_site], u);
    uint32_t mate = u[2];
    for (unsigned i = 0; i < 2u; i++) {
        mate = ((u[i] != d->last_site) && (u[i] != VOR__INFINITE)) ? u[i] : mate;
    }
    return mate;
}

/* The vertex nearest to site p along the line (key: x, or y for a
 * vertical line), below it (`below`) or above, other than `skip`;
 * VOR__NONE if none: a look at every id. */
static uint32_t line_neighbour(const vor_power_t *pd, uint32_t p, bool vertical, bool below)
{
    const vor_t *d = &pd->mesh;
    const vor_point_t *s = d->sites;
    int32_t at = vertical ? s[p].y : s[p].x;
    uint32_t best = VOR__NONE;
    int32_t best_key = 0;
    for (uint32_t v = 0; v < d->site_count; v++) {
        if ((v == p) || !vor__site_in_mesh(d, v)) {
            continue;
        }
        int32_t key = vertical ? s[v].y : s[v].x;
        bool side = below ? (key < at) : (key > at);
        if (side && ((best == VOR__NONE) || (below ? (key > best_key) : (key < best_key)))) {
            best = v;
            best_key = key;
        }
    }
    return best;
}

/* p is in, on the line: hides the vertices beside it that its lifted
 * point now lies below the chain under, on each side. */
static void settle_line(vor_power_t *pd, uint32_t p, bool vertical)
{
    for (unsigned k = 0; k < 2u; k++) {
        bool below = k == 0u;
        for (uint32_t left = pd->mesh.vertex_count; left > 0u; left--) {
            uint32_t b = line_neighbour(pd, p, vertical, below);
            uint32_t a = (b != VOR__NONE) ? line_neighbour(pd, b, vertical, below) : VOR__NONE;
            if ((a == VOR__NONE) || (lifted_side(pd, a, p, b) >= 0)) {
                break;
            }
            unlink_hidden(pd, b);
        }
    }
}

static bool same_site(const vor_power_t *pd, uint32_t a, uint32_t b)
{
    const vor_point_t *s = pd->mesh.sites;
    return (s[a].x == s[b].x) && (s[a].y == s[b].y) && (pd->weights[a] == pd->weights[b]);
}

/* The smallest id below `ids` of a site (vertex or hidden) with the same
 * point and weight as site p, VOR__NONE if none: a look at every id. */
static uint32_t find_twin(const vor_power_t *pd, uint32_t p, uint32_t ids)
{
    for (uint32_t v = 0; v < ids; v++) {
        if ((v != p) && (vor_power_hidden(pd, v) >= 0) && same_site(pd, v, p)) {
            return v;
        }
    }
    return VOR__NONE;
}

/* The hidden site with the same point and weight as site p, VOR__NONE
 * if none: a look at the hidden list. */
static uint32_t find_hidden_twin(const vor_power_t *pd, uint32_t p)
{
    uint32_t h = pd->first_hidden;
    for (uint32_t left = pd->hidden_count; (left > 0u) && (h != 0u); left--) {
        if (same_site(pd, h - 1u, p)) {
            return h - 1u;
        }
        h = pd->mesh.triangles[h - 1u].n[1];
    }
    return VOR__NONE;
}

/* A vertex at the point of site p with another weight, VOR__NONE if
 * none: a look at every id. */
static uint32_t find_at(const vor_power_t *pd, uint32_t p, uint32_t ids)
{
    const vor_point_t *s = pd->mesh.sites;
    for (uint32_t v = 0; v < ids; v++) {
        if ((v != p) && vor__site_in_mesh(&pd->mesh, v) && same_point(&s[v], &s[p])) {
            return v;
        }
    }
    return VOR__NONE;
}

/* Inserts vertex p into the triangle in slot `root` (`on_line`: p on a
 * line of its edges), then hides `under` (a lighter vertex at p's point,
 * VOR__NONE if none) and the slivers p leaves (settle_star). Returns
 * PLACED_HIDDEN when p itself ends hidden, else VOR_OK. */
static int insert_vertex(vor_power_t *pd, vor_index_t root, uint32_t p, uint32_t under,
                         bool on_line)
{
    vor_t *d = &pd->mesh;
    bool flat = insert_at(pd, root, p) || on_line;
    d->last_site = p;
    if ((under != VOR__NONE) && vor__site_in_mesh(d, under)) {
        unlink_hidden(pd, under); /* farther everywhere, by a constant */
    }
    pd->flats = pd->flats || (flat && star_flat(d, (vor_index_t)p));
    if (!pd->area || !pd->flats) {
        return VOR_OK;
    }
    return settle_star(pd, (vor_index_t)p) ? PLACED_HIDDEN : VOR_OK;
}

/* The one-dimensional case (every vertex on one line, p on it too). */
static int place_on_line(vor_power_t *pd, uint32_t p, bool vertical, vor_index_t root,
                         uint32_t under)
{
    const int64_t *w = pd->weights;
    if ((under != VOR__NONE) && (w[p] < w[under])) {
        hide(pd, p);
        return PLACED_HIDDEN;
    }
    uint32_t lo = line_neighbour(pd, p, vertical, true);
    uint32_t hi = line_neighbour(pd, p, vertical, false);
    if ((under == VOR__NONE) && (lo != VOR__NONE) && (hi != VOR__NONE) &&
        (lifted_side(pd, lo, hi, p) < 0)) {
        hide(pd, p); /* above the chain between its neighbours */
        return PLACED_HIDDEN;
    }
    (void)insert_vertex(pd, root, p, under, true);
    settle_line(pd, p, vertical);
    return VOR_OK;
}

/* Places site p (its point and weight stored, not counted yet): makes it
 * a vertex (VOR_OK), hidden (PLACED_HIDDEN), or finds its twin, a site
 * with the same point and weight (VOR_ERR_DUPLICATE, nothing changed).
 * The search starts at `start` (the last site if that is no vertex);
 * `twins`: ids below it may hold a twin of p or a vertex at its point
 * (0: none can). */
static int place(vor_power_t *pd, uint32_t p, uint32_t start_in, uint32_t twins, uint32_t *twin)
{
    vor_t *d = &pd->mesh;
    const int64_t *w = pd->weights;
    const vor_point_t *s = d->sites;
    if (d->vertex_count == 0u) {
        d->vertex_count = 1;
        d->last_site = p;
        return VOR_OK;
    }
    if (d->vertex_count == 1u) {
        uint32_t v = d->last_site;
        if (!same_point(&s[v], &s[p])) {
            vor__make_edge(d, v, p);
            d->vertex_count = 2;
        } else if (w[p] == w[v]) {
            *twin = v;
            return VOR_ERR_DUPLICATE;
        } else if (w[p] < w[v]) {
            uint32_t found = find_twin(pd, p, twins); /* a hidden twin */
            if (found != VOR__NONE) {
                *twin = found;
                return VOR_ERR_DUPLICATE;
            }
            hide(pd, p);
            return PLACED_HIDDEN;
        } else {
            hide(pd, v); /* p takes its place: nearer everywhere by w[p] - w[v] */
        }
        d->last_site = p;
        return VOR_OK;
    }
    uint32_t start = ((start_in != p) && (start_in < d->site_count) && vor__site_in_mesh(d, start_in))
                         ? start_in
                         : d->last_site;
    bool on_line;
    vor_index_t root = vor__locate(d, (vor_index_t)start, p, &on_line);
    vor_index_t v[3];
    vor__vertices(&d->triangles[root], v);
    uint32_t found = VOR__NONE;
    uint32_t under = VOR__NONE;
    for (unsigned corner = 0; corner < 3u; corner++) {
        vor_index_t c = v[corner];
        if ((c != VOR__INFINITE) && same_point(&s[c], &s[p])) {
            found = (w[c] == w[p]) ? c : found;
            under = (w[c] != w[p]) ? c : under;
        }
    }
    bool tie = false;
    bool hidden = (v[0] != VOR__INFINITE) && (v[1] != VOR__INFINITE) &&
                  (v[2] != VOR__INFINITE) && (power_test(pd, v[0], v[1], v[2], p, &tie) < 0);
    bool outside = (v[0] == VOR__INFINITE) || (v[1] == VOR__INFINITE) ||
                   (v[2] == VOR__INFINITE);
    if ((found == VOR__NONE) && (twins > 0u)) {
        /* A twin vertex elsewhere: its lifted point is on the surface, so
         * p's power test ties, or p is on the hull's boundary. A hidden
         * twin is on or above the surface: p ties or is hidden. */
        if (tie || (outside && on_line)) {
            found = find_twin(pd, p, twins);
        } else if (hidden || (under != VOR__NONE)) {
            found = find_hidden_twin(pd, p);
        } else {
            /* no twin */
        }
    }
    if (found != VOR__NONE) {
        *twin = found;
        return VOR_ERR_DUPLICATE;
    }
    if (!pd->area) {
        uint32_t a = d->last_site;
        uint32_t b = line_mate(d);
        if (vor__orient2d_sign(&s[a], &s[b], &s[p]) == 0) {
            /* a vertex at p (the line's cost: every id is looked at) */
            under = (under != VOR__NONE) ? under : find_at(pd, p, d->site_count);
            return place_on_line(pd, p, s[a].x == s[b].x, root, under);
        }
        pd->area = true; /* p off the line: its triangles have area */
        hidden = false;  /* a new hull vertex */
        /* three vertices or more on the line hold flat triangles, and
         * those beyond the line from p stay */
        pd->flats = pd->flats || (d->vertex_count >= 3u);
    }
    if (hidden || ((under != VOR__NONE) && (w[p] < w[under]))) {
        hide(pd, p);
        return PLACED_HIDDEN;
    }
    return insert_vertex(pd, root, p, under, on_line);
}

/* After site p was placed (`placed`: VOR_OK, a vertex, or
 * PLACED_HIDDEN), `vertices` and `hidden` the counts before: the vertices
 * hidden since leave the bucket grid (the newest entries of the hidden
 * list; p, when hidden, was never in it), and a new vertex enters it and
 * the box. Two vertices stay when there were two: a hidden one leaves a
 * heavier one at its point or hides under two others. */
static void grid_upkeep(vor_power_t *pd, uint32_t p, int placed, uint32_t vertices,
                        uint32_t hidden)
{
    vor_t *d = &pd->mesh;
    if (vertices >= 2u) {
        uint32_t h = pd->first_hidden;
        for (uint32_t k = hidden; (k < pd->hidden_count) && (h != 0u); k++) {
            if ((h - 1u) != p) {
                vor__grid_forget(d, h - 1u, d->last_site);
            }
            h = d->triangles[h - 1u].n[1];
        }
    }
    if (placed == VOR_OK) {
        vor__box_add(d, &d->sites[p], d->vertex_count == 1u);
        if (d->vertex_count >= 2u) {
            vor__grid_add(d, p);
        }
    }
}

/* ------------------------------------------------------------------ */
/* Removal                                                             */

/* Takes hidden site h off the hidden list: a look along it. */
static void unhide(vor_power_t *pd, uint32_t h)
{
    vor__tri_t *tri = pd->mesh.triangles;
    vor_index_t next = tri[h].n[1];
    if (pd->first_hidden == (h + 1u)) {
        pd->first_hidden = next;
    } else {
        uint32_t k = pd->first_hidden;
        for (uint32_t left = pd->hidden_count; (left > 0u) && (k != 0u); left--) {
            if (tri[k - 1u].n[1] == (h + 1u)) {
                tri[k - 1u].n[1] = next;
                break;
            }
            k = tri[k - 1u].n[1];
        }
    }
    pd->hidden_count--;
}

static bool in_box(const vor_point_t *p, const vor_point_t *lo, const vor_point_t *hi)
{
    return (lo->x <= p->x) && (p->x <= hi->x) && (lo->y <= p->y) && (p->y <= hi->y);
}

static void widen(vor_point_t *lo, vor_point_t *hi, const vor_point_t *p)
{
    lo->x = (p->x < lo->x) ? p->x : lo->x;
    lo->y = (p->y < lo->y) ? p->y : lo->y;
    hi->x = (p->x > hi->x) ? p->x : hi->x;
    hi->y = (p->y > hi->y) ? p->y : hi->y;
}

/* Moves the hidden sites in the closed box lo..hi off the hidden list to
 * a list of their own (tag PENDING, the same links); returns its first
 * id plus one (0: none). A look along the hidden list. */
static uint32_t take_hidden_in(vor_power_t *pd, const vor_point_t *lo, const vor_point_t *hi)
{
    vor__tri_t *tri = pd->mesh.triangles;
    const vor_point_t *s = pd->mesh.sites;
    uint32_t pending = 0;
    uint32_t kept = 0; /* the last entry left on the list, plus one (0: none) */
    uint32_t h = pd->first_hidden;
    for (uint32_t left = pd->hidden_count; (left > 0u) && (h != 0u); left--) {
        uint32_t id = h - 1u;
        uint32_t next = tri[id].n[1];
        if (in_box(&s[id], lo, hi)) {
            if (kept == 0u) {
                pd->first_hidden = next;
            } else {
                tri[kept - 1u].n[1] = (vor_index_t)next;
            }
            empty_slot(pd, id, (vor_index_t)pending, PENDING);
            pending = h;
            pd->hidden_count--;
        } else {
            kept = h;
        }
        h = next;
    }
    return pending;
}

/* A removal collects up to this many of the vertex's neighbours on the
 * stack, for the checks after it; a larger star (rare) checks every
 * vertex instead. */
#define RING_MAX 16u

/* After a vertex left a mesh with area: is a triangle of area left? The
 * hull's corners all stay when the vertex was not on the hull (a corner
 * off the line of the others would be one); else a neighbour with a
 * triangle of area tells, and failing that a look at every id for a
 * vertex off the line of two. */
static bool keeps_area(const vor_power_t *pd, const vor_index_t *ring, uint32_t count, bool hull)
{
    const vor_t *d = &pd->mesh;
    if (d->vertex_count < 3u) {
        return false;
    }
    if (!hull) {
        return true;
    }
    for (uint32_t i = 0; (i < count) && (i < RING_MAX); i++) {
        if (vor__site_in_mesh(d, ring[i]) && has_area(d, ring[i])) {
            return true;
        }
    }
    const vor_point_t *s = d->sites;
    uint32_t a = d->last_site;
    uint32_t b = line_mate(d);
    for (uint32_t v = 0; v < d->site_count; v++) {
        if (vor__site_in_mesh(d, v) && (vor__orient2d_sign(&s[a], &s[b], &s[v]) != 0)) {
            return true;
        }
    }
    return false;
}

/* After a vertex left a mesh that keeps area: its ears may be flat, and
 * a flat ear may leave a T-junction (a vertex with all its triangles
 * flat has a cell of no area, which may stay). Every new triangle has
 * its corners among the former neighbours in ring[0..count): their stars
 * are settled as an insertion's is (every vertex's when the ring did not
 * fit). */
static void settle_ring(vor_power_t *pd, const vor_index_t *ring, uint32_t count)
{
    vor_t *d = &pd->mesh;
    bool all = count > RING_MAX;
    for (uint32_t i = 0; (i < count) && !all && !pd->flats; i++) {
        pd->flats = vor__site_in_mesh(d, ring[i]) && star_flat(d, ring[i]);
    }
    pd->flats = pd->flats || all;
    if (!pd->flats) {
        return;
    }
    uint32_t end = all ? d->site_count : count;
    for (uint32_t i = 0; i < end; i++) {
        uint32_t v = all ? i : ring[i];
        if (vor__site_in_mesh(d, v)) {
            uint32_t hidden = pd->hidden_count;
            (void)settle_star(pd, (vor_index_t)v);
            grid_upkeep(pd, VOR__NONE, PLACED_HIDDEN, d->vertex_count, hidden);
        }
    }
}

/* Removes vertex v. The lifted surface changes only over v's star, where
 * it rises to the lower hull of the neighbours: the hidden sites there
 * are the only ones that may come out, and those in the box of v and
 * its neighbours (a superset; on a line, of v and its neighbours along
 * it) are taken off the hidden list, v is unlinked (the removal's ears
 * with the power test), and each is placed again by the insertion,
 * which hides it or makes it a vertex exactly. */
static void remove_vertex(vor_power_t *pd, uint32_t v)
{
    vor_t *d = &pd->mesh;
    const vor_point_t *s = d->sites;
    vor_point_t lo = s[v];
    vor_point_t hi = s[v];
    vor_index_t ring[RING_MAX];
    uint32_t count = 0;
    bool hull = false;
    if ((d->vertex_count >= 2u) && pd->area) {
        vor_neighbour_iter_t it;
        uint32_t n = v;
        uint32_t third = v;
        vor__fan_begin(&it, d, v);
        while (vor__fan_next(&it, &n, &third)) {
            widen(&lo, &hi, &s[n]);
            hull = hull || (third == VOR__INFINITE);
            if (count < RING_MAX) {
                ring[count] = (vor_index_t)n;
            }
            count++;
        }
    } else if (d->vertex_count >= 2u) {
        uint32_t a = (d->last_site != v) ? d->last_site : line_mate(d);
        uint32_t b = (d->last_site != v) ? line_mate(d) : d->last_site;
        bool vertical = s[a].x == s[b].x;
        for (unsigned k = 0; k < 2u; k++) {
            uint32_t u = line_neighbour(pd, v, vertical, k == 0u);
            if (u != VOR__NONE) {
                widen(&lo, &hi, &s[u]);
            }
        }
    } else {
        /* one vertex: the hidden sites are at its point */
    }
    uint32_t pending = take_hidden_in(pd, &lo, &hi);
    vor__unlinked(d, v, vor__unlink_site(d, v));
    if (pd->area) {
        pd->area = keeps_area(pd, ring, count, hull);
        if (pd->area) {
            settle_ring(pd, ring, count);
        }
    }
    uint32_t twin = VOR__NONE;
    for (uint32_t left = d->site_count; (left > 0u) && (pending != 0u); left--) {
        uint32_t c = pending - 1u;
        pending = d->triangles[c].n[1];
        uint32_t vertices = d->vertex_count;
        uint32_t hidden = pd->hidden_count;
        /* no twins: the sites are distinct, so place only hides or adds.
         * Only lying predicates (fault injection) can have let a twin in
         * and find it now: c stays a site, hidden. */
        int placed = place(pd, c, d->last_site, 0, &twin);
        if (placed == VOR_ERR_DUPLICATE) {
            hide(pd, c);
            placed = PLACED_HIDDEN;
        }
        grid_upkeep(pd, c, placed, vertices, hidden);
    }
}

/* The power distance of q to site a against site b's: negative when a is
 * strictly nearer; of equal ones, the smaller id first. */
static bool nearer(const vor_power_t *pd, const vor_point_t *q, uint32_t a, uint32_t b)
{
    const vor_point_t *s = pd->mesh.sites;
    int c = vor__power_closer_sign(q, &s[a], pd->weights[a], &s[b], pd->weights[b], NULL);
    return (c < 0) || ((c == 0) && (a < b));
}

/* ------------------------------------------------------------------ */
/* Public calls                                                        */

int vor_power_init_checked(vor_power_t *pd, void *arena, size_t arena_bytes,
                           uint32_t max_sites, uint32_t config)
{
    if (config != VOR_CONFIG_FINGERPRINT) {
        return VOR_ERR_CONFIG;
    }
    if ((pd == NULL) || (arena == NULL) || (max_sites == 0u) || (max_sites > VOR_MAX_SITES)) {
        return VOR_ERR_ARG;
    }
    if (((uintptr_t)arena % VOR_POWER_ARENA_ALIGN) != 0u) {
        return VOR_ERR_ALIGN;
    }
    if (arena_bytes < VOR_POWER_ARENA_BYTES(max_sites)) {
        return VOR_ERR_NOMEM;
    }
    /* the weights first: 8-byte entries keep the diagram's arena aligned */
    int64_t *weights = (int64_t *)arena;
    int err = vor_init(&pd->mesh, weights + max_sites,
                       arena_bytes - ((size_t)max_sites * sizeof(int64_t)), max_sites);
    if (err == VOR_OK) {
        pd->weights = weights;
        pd->hidden_count = 0;
        pd->first_hidden = 0;
        pd->area = false;
        pd->flats = false;
        /* the removal's ears (dynamic.c) with the power test */
        pd->mesh.cdt_predicate = removal_predicate;
    }
    return err;
}

int vor_power_insert(vor_power_t *pd, vor_point_t point, int64_t w, uint32_t *site)
{
    if (pd == NULL) {
        return VOR_ERR_ARG;
    }
    vor_t *d = &pd->mesh;
    bool reused = d->free_site != 0u; /* a removed site's id, as vor_insert */
    uint32_t p = reused ? (d->free_site - 1u) : d->site_count;
    if (p >= d->max_sites) {
        /* no free slot to place it in: only tell a duplicate */
        for (uint32_t v = 0; v < d->site_count; v++) {
            if ((vor_power_hidden(pd, v) >= 0) && (d->sites[v].x == point.x) &&
                (d->sites[v].y == point.y) && (pd->weights[v] == w)) {
                if (site != NULL) {
                    *site = v;
                }
                return VOR_ERR_DUPLICATE;
            }
        }
        return VOR_ERR_FULL;
    }
    vor_point_t saved_point = d->sites[p];
    int64_t saved_weight = pd->weights[p];
    uint32_t saved_free = d->free_site;
    vor__tally_t tally;
    vor__tally_save(&tally, d);
    d->sites[p] = point;
    pd->weights[p] = w;
    uint32_t vertices = d->vertex_count;
    uint32_t hidden = pd->hidden_count;
    uint32_t twin = VOR__NONE;
    vor__take_free_id(d); /* p's home slot holds the list's link */
    int placed = place(pd, p, d->last_site, d->site_count, &twin);
    if (placed == VOR_ERR_DUPLICATE) {
        d->sites[p] = saved_point;
        pd->weights[p] = saved_weight;
        d->free_site = saved_free;
        vor__tally_restore(d, &tally);
        if (site != NULL) {
            *site = twin;
        }
        return VOR_ERR_DUPLICATE;
    }
    d->site_count += reused ? 0u : 1u;
    grid_upkeep(pd, p, placed, vertices, hidden);
    if (site != NULL) {
        *site = p;
    }
    return VOR_OK;
}

int vor_power_build(vor_power_t *pd, const vor_point_t *points, const int64_t *weights,
                    uint32_t n, uint32_t *duplicate_of)
{
    if ((pd == NULL) || (((points == NULL) || (weights == NULL)) && (n > 0u))) {
        return VOR_ERR_ARG;
    }
    vor_t *d = &pd->mesh;
    if (n > d->max_sites) {
        return VOR_ERR_FULL;
    }
    for (uint32_t i = 0; i < n; i++) {
        pd->weights[i] = weights[i];
    }
    pd->hidden_count = 0;
    pd->first_hidden = 0;
    pd->area = false;
    pd->flats = false;
    int status = vor__build_start(d, points, n, duplicate_of);
    if (status != VOR__BUILD_MESH) {
        return status;
    }
    /* the plan of vor_build (incremental.c): at the very end of the
     * triangle slots, which fill from below and never reach an entry
     * still to be read */
    vor_index_t *base = (vor_index_t *)(void *)d->triangles;
    size_t entries = (size_t)vor__triangle_count(d->max_sites) * sizeof(vor__tri_t) /
                     sizeof(vor_index_t);
    vor_index_t *plan = base + entries - (2u * (size_t)n);
    uint32_t distinct = vor__plan(d, n, VOR_ORDER_QUADTREE, base, plan, NULL);
    vor_index_t few[16];
    if (n < 8u) { /* so few slots that the plan may share words with home slots */
        for (uint32_t i = 0; i < 16u; i++) {
            few[i] = (i < (2u * n)) ? plan[i] : (vor_index_t)0;
        }
        plan = few;
    }
    /* the first three sites off one line, if any three are: then only a
     * set on one line meets the one-dimensional case, which looks at
     * every id. The searches of the sites moved start at the last site. */
    const vor_point_t *pt = d->sites;
    uint32_t third = 2;
    while ((third < distinct) &&
           (vor__orient2d_sign(&pt[plan[0]], &pt[plan[2]], &pt[plan[2u * third]]) == 0)) {
        third++;
    }
    if ((third > 2u) && (third < distinct)) {
        vor_index_t moved = plan[4];
        plan[4] = plan[2u * third];
        plan[2u * third] = moved;
        for (uint32_t i = 2; i <= third; i++) {
            plan[(2u * i) + 1u] = VOR__NONE;
        }
    }
    /* every home slot empty until its site is placed: the one-dimensional
     * case and the search for a twin look at every id */
    for (uint32_t i = 0; i < n; i++) {
        empty_slot(pd, i, 0, DUPLICATE);
    }
    uint32_t twin = VOR__NONE;
    for (uint32_t i = 0; i < n; i++) {
        vor_index_t s = plan[2u * i];
        vor_index_t from = plan[(2u * i) + 1u];
        if (i >= distinct) {
            /* a point met before: placed once the plan is read */
            empty_slot(pd, s, from, PENDING);
        } else {
            /* distinct points: no twins */
            (void)place(pd, s, (from == VOR__NONE) ? d->last_site : from, 0, &twin);
        }
    }
    /* the points met before, at their first occurrence: a twin, hidden
     * under a larger weight, or a vertex that hides the lighter ones */
    for (uint32_t s = 0; s < n; s++) {
        const vor__tri_t *t = &d->triangles[s];
        uint32_t kept = s;
        if (vor__slot_empty(t) && (t->n[2] == PENDING) && (s != d->last_site)) {
            if (place(pd, s, t->n[1], n, &twin) == VOR_ERR_DUPLICATE) {
                empty_slot(pd, s, (vor_index_t)twin, DUPLICATE);
                kept = twin;
            }
        }
        if (duplicate_of != NULL) {
            duplicate_of[s] = kept;
        }
    }
    vor__grid_rebuild(d);
    return VOR_OK;
}

int vor_power_hidden(const vor_power_t *pd, uint32_t site)
{
    if ((pd == NULL) || (site >= pd->mesh.site_count)) {
        return VOR_ERR_ARG;
    }
    const vor_t *d = &pd->mesh;
    if (vor__site_in_mesh(d, site)) {
        return 0;
    }
    if (d->max_sites < 2u) {
        return VOR_ERR_ARG; /* no slots: the one id is free */
    }
    const vor__tri_t *t = &d->triangles[site];
    return (vor__slot_empty(t) && (t->n[2] == HIDDEN)) ? 1 : VOR_ERR_ARG;
}

int vor_power_remove(vor_power_t *pd, uint32_t site)
{
    int hidden = vor_power_hidden(pd, site);
    if (hidden < 0) {
        return VOR_ERR_ARG;
    }
    vor_t *d = &pd->mesh;
    if (hidden == 1) {
        /* the surface does not change: only the id goes */
        unhide(pd, site);
        vor__free_id(d, site);
    } else {
        remove_vertex(pd, site);
    }
    return VOR_OK;
}

int vor_power_move(vor_power_t *pd, uint32_t site, vor_point_t p, int64_t w, uint32_t *existing)
{
    if (vor_power_hidden(pd, site) < 0) {
        return VOR_ERR_ARG;
    }
    const vor_t *d = &pd->mesh;
    const vor_point_t *s = d->sites;
    if (same_point(&s[site], &p) && (pd->weights[site] == w)) {
        return VOR_OK;
    }
    /* a twin at the new place, before anything changes: a look at every
     * id (the smallest one) */
    for (uint32_t v = 0; v < d->site_count; v++) {
        if ((v != site) && same_point(&s[v], &p) && (pd->weights[v] == w) &&
            (vor_power_hidden(pd, v) >= 0)) {
            if (existing != NULL) {
                *existing = v;
            }
            return VOR_ERR_DUPLICATE;
        }
    }
    /* removed, its id at the head of the free list, which the insertion
     * takes: the same id, and no duplicate or full diagram to refuse it */
    (void)vor_power_remove(pd, site);
    uint32_t id = site;
    int err = vor_power_insert(pd, p, w, &id);
    VOR_ASSERT((err == VOR_OK) && (id == site));
    return err;
}

/*
 * The power distance of q to site i is |q|^2 + (h_i - 2 q.p_i), h_i =
 * |p_i|^2 - w_i the lifted height: a linear function of the lifted point,
 * increasing upwards. Over the convex hull of the sites, the lower surface
 * F is convex and piecewise linear on the triangulation, so g(x) = F(x) -
 * 2 q.x is convex, and at each vertex it is that vertex's power distance
 * less |q|^2. A vertex v that is not least: the segment from v to a least
 * one stays in the hull, and g falls along it from v; it leaves v along an
 * edge or into a triangle of area of v's star, on which g is linear, so
 * another corner of that edge or triangle, a neighbour of v, is strictly
 * nearer. The walk from neighbour to strictly nearer neighbour ends, each
 * vertex seen at most once, at a least vertex. The least vertices are a
 * face of the lower hull, which the triangulation covers: when there are
 * several, the one found has a neighbour as near, and then every vertex is
 * looked at for the smallest id (O(n), on ties only). A hidden site is
 * never strictly nearer than every vertex (its lifted point is on or above
 * the surface) but can tie: the hidden list is looked at (O(hidden)).
 * While every vertex is on one line (no triangle of area) the mesh's flat
 * triangles do not carry that argument: every vertex is looked at.
 */
int vor_power_nearest(const vor_power_t *pd, vor_point_t q, uint32_t hint, uint32_t *site)
{
    if ((pd == NULL) || (site == NULL)) {
        return VOR_ERR_ARG;
    }
    const vor_t *d = &pd->mesh;
    if (d->vertex_count == 0u) {
        return VOR_ERR_EMPTY;
    }
    if ((hint != VOR_NO_HINT) && (vor_power_hidden(pd, hint) < 0)) {
        return VOR_ERR_ARG;
    }
    uint32_t best = d->last_site;
    if ((hint != VOR_NO_HINT) && vor__site_in_mesh(d, hint)) {
        best = hint;
    } else if (d->vertex_count >= 2u) {
        best = vor__grid_start(d, q.x, q.y); /* also for a hidden hint */
    } else {
        /* the only vertex */
    }
    bool tie = !pd->area;
    for (uint32_t steps = 0; (steps < d->vertex_count) && pd->area; steps++) {
        vor_neighbour_iter_t it;
        uint32_t n = best;
        uint32_t third = best;
        uint32_t next = best;
        tie = false;
        /* (For Frama-C's EVA: one state per vertex walked from, so that
         * its fan's slots are not merged with another's.) */
        /*@ split best; */
        vor__fan_begin(&it, d, best);
        while (vor__fan_next(&it, &n, &third)) {
            int c = vor__power_closer_sign(&q, &d->sites[n], pd->weights[n], &d->sites[best],
                                           pd->weights[best], NULL);
            tie = tie || (c == 0);
            next = ((c < 0) && nearer(pd, &q, n, next)) ? n : next;
        }
        if (next == best) {
            break;
        }
        best = next;
    }
    for (uint32_t v = 0; tie && (v < d->site_count); v++) {
        best = (vor__site_in_mesh(d, v) && nearer(pd, &q, v, best)) ? v : best;
    }
    uint32_t h = pd->first_hidden;
    for (uint32_t left = pd->hidden_count; (left > 0u) && (h != 0u); left--) {
        if (nearer(pd, &q, h - 1u, best)) {
            best = h - 1u;
        }
        h = d->triangles[h - 1u].n[1];
    }
    *site = best;
    return VOR_OK;
}

int vor_power_hidden_begin(vor_power_hidden_iter_t *it, const vor_power_t *pd)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    it->pd = pd;
    it->next = (pd != NULL) ? pd->first_hidden : 0u;
    return (pd != NULL) ? VOR_OK : VOR_ERR_ARG;
}

int vor_power_hidden_next(vor_power_hidden_iter_t *it, uint32_t *site)
{
    if ((it == NULL) || (it->pd == NULL) || (site == NULL) || (it->next == 0u)) {
        return 0;
    }
    const vor_t *d = &it->pd->mesh;
    uint32_t h = it->next - 1u;
    if ((h >= d->site_count) || (d->max_sites < 2u)) {
        it->next = 0; /* only on a corrupted object */
        return 0;
    }
    *site = h;
    it->next = d->triangles[h].n[1];
    return 1;
}

int vor_power_triangles_begin(vor_triangle_iter_t *it, const vor_power_t *pd)
{
    return vor_triangles_begin(it, (pd != NULL) ? &pd->mesh : NULL);
}

static int violation(vor_violation_t *out, enum vor_check check, uint32_t triangle,
                     uint32_t site)
{
    if (out != NULL) {
        out->check = check;
        out->triangle = triangle;
        out->site = site;
    }
    return VOR_ERR_INVALID;
}

/* Every finite triangle counterclockwise and every edge locally regular
 * (no neighbour's far vertex below a triangle's lifted plane, none beyond
 * a hull edge), by the perturbed predicates, uncounted. */
static int check_regular(const vor_power_t *pd, vor_violation_t *out)
{
    const vor_t *d = &pd->mesh;
    const vor_point_t *s = d->sites;
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t slot = vor__next_used_slot(d, 0); slot < end;
         slot = vor__next_used_slot(d, slot + 1u)) {
        const vor__tri_t *t = &tri[slot];
        vor_index_t v[3];
        vor__vertices(t, v);
        unsigned infinite = vor__vertex_index(t, VOR__INFINITE);
        if ((infinite == 3u) && (vor_orient2d_sos(s, v[0], v[1], v[2]) < 0)) {
            return violation(out, VOR_CHECK_ORIENTATION, slot, v[0]);
        }
        for (unsigned i = 0; i < 3u; i++) {
            const vor__tri_t *o = &tri[t->n[i]];
            vor_index_t apex = vor__vertex(o, vor__next(vor__vertex_index(o, v[vor__next(i)])));
            if ((apex == VOR__INFINITE) || (vor__vertex_index(t, apex) != 3u)) {
                continue; /* two sites: both triangles have the same vertices */
            }
            bool conflict = (infinite != 3u)
                                ? (vor_orient2d_sos(s, v[vor__next(infinite)],
                                                    v[vor__prev(infinite)], apex) > 0)
                                : (vor_power_test_sos(s, pd->weights, v[0], v[1], v[2], apex) > 0);
            if (conflict) {
                return violation(out, VOR_CHECK_DELAUNAY, slot, apex);
            }
        }
    }
    return VOR_OK;
}

/* The same while every vertex is on one line (no triangle of area): h on
 * the line, at a vertex no lighter than it or between two vertices with
 * its lifted point on or above their chain (a look at every vertex). */
static bool hidden_on_line(const vor_power_t *pd, uint32_t h)
{
    const vor_t *d = &pd->mesh;
    const vor_point_t *s = d->sites;
    uint32_t a = d->last_site;
    uint32_t at = find_at(pd, h, d->site_count);
    if (at != VOR__NONE) {
        return pd->weights[at] >= pd->weights[h];
    }
    if (d->vertex_count < 2u) {
        return false; /* one vertex: only a site at its point is hidden */
    }
    uint32_t b = line_mate(d);
    if (vor__orient2d_sign(&s[a], &s[b], &s[h]) != 0) {
        return false;
    }
    bool vertical = s[a].x == s[b].x;
    uint32_t lo = line_neighbour(pd, h, vertical, true);
    uint32_t hi = line_neighbour(pd, h, vertical, false);
    return (lo != VOR__NONE) && (hi != VOR__NONE) && (lifted_side(pd, lo, hi, h) <= 0);
}

/* Is hidden site h on or above the lifted surface? The triangle under it
 * by a walk with the perturbed orientation (read-only), then the exact
 * power test; outside the hull only on its boundary's line. */
static bool hidden_above(const vor_power_t *pd, uint32_t h)
{
    const vor_t *d = &pd->mesh;
    const vor_point_t *s = d->sites;
    const vor__tri_t *tri = d->triangles;
    vor_index_t slot = (vor_index_t)d->last_site;
    uint32_t limit = vor__triangle_count(d->vertex_count) + 1u;
    for (uint32_t step = 0; step < limit; step++) {
        const vor__tri_t *t = &tri[slot];
        vor_index_t v[3];
        vor__vertices(t, v);
        unsigned out = 3u;
        unsigned infinite = vor__vertex_index(t, VOR__INFINITE);
        for (unsigned i = 0; (i < 3u) && (out == 3u); i++) {
            vor_index_t a = v[vor__next(i)];
            vor_index_t b = v[vor__prev(i)];
            if ((a != VOR__INFINITE) && (b != VOR__INFINITE) &&
                (vor_orient2d_sos(s, a, b, h) < 0)) {
                out = i;
            }
        }
        if (out != 3u) {
            slot = t->n[out];
        } else if (infinite != 3u) {
            /* beyond the hull edge: allowed only exactly on its line */
            return vor_orient2d(s[v[vor__next(infinite)]], s[v[vor__prev(infinite)]], s[h]) == 0;
        } else {
            const int64_t w[4] = {pd->weights[v[0]], pd->weights[v[1]], pd->weights[v[2]],
                                  pd->weights[h]};
            return vor_power_test(s[v[0]], w[0], s[v[1]], w[1], s[v[2]], w[2], s[h], w[3]) <= 0;
        }
    }
    return false; /* the walk did not end: a broken mesh */
}

int vor_power_validate(const vor_power_t *pd, vor_violation_t *out)
{
    if (pd == NULL) {
        return VOR_ERR_ARG;
    }
    const vor_t *d = &pd->mesh;
    int err = vor__validate_topology(d, out);
    if ((err == VOR_OK) && (d->vertex_count >= 2u)) {
        err = check_regular(pd, out);
    }
    uint32_t seen = 0;
    for (uint32_t h = pd->first_hidden; (err == VOR_OK) && (h != 0u); seen++) {
        uint32_t site = h - 1u;
        if ((seen >= pd->hidden_count) || (site >= d->site_count) ||
            (vor_power_hidden(pd, site) != 1) ||
            !(pd->area ? hidden_above(pd, site) : hidden_on_line(pd, site))) {
            err = violation(out, VOR_CHECK_DELAUNAY, 0, site);
        } else {
            h = d->triangles[site].n[1];
        }
    }
    if ((err == VOR_OK) && (seen != pd->hidden_count)) {
        err = violation(out, VOR_CHECK_COUNTS, 0, seen);
    }
    return err;
}
