/* SPDX-License-Identifier: MIT */
/*
 * queries.c - questions asked of a built diagram: its triangles and
 * neighbours, the nearest and k nearest sites, the tracker, and
 * vor_validate. Read-only: no query writes the diagram, so several threads
 * may query one diagram at once.
 *
 * Nearest site (the starting-point search of Ohya, Iri and Murota): from a
 * hint, step to a Delaunay neighbour strictly closer to the query, with
 * exact distance comparisons, until none is. That reaches the smallest
 * distance d: if a site s is not nearest, the segment from s to the query
 * leaves s's Voronoi cell through an edge, whose other site is a closer
 * Delaunay neighbour, or through a vertex, where every other site on that
 * vertex's circle is strictly closer (its chord from s makes an acute angle
 * with the segment), among them s's neighbours on the circle.
 *
 * Ties: all sites at distance d lie on a circle around the query with no
 * site inside, and two of them that are consecutive on the circle are
 * joined by an edge of every Delaunay triangulation. Walking that polygon
 * counterclockwise visits them all; the smallest index wins.
 */
#include "bucket_grid.h"
#include "mesh.h"
#include "multiword.h"
#include "perturbation.h"
#include "predicates.h"
#include "walk.h"

int vor_triangles_begin(vor_triangle_iter_t *it, const vor_t *d)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    it->d = d; /* NULL: closed */
    it->next_slot = 0;
    return (d != NULL) ? VOR_OK : VOR_ERR_ARG;
}

int vor_triangles_next(vor_triangle_iter_t *it, uint32_t ids[3])
{
    /* a zeroed iterator, or one begun on no diagram, is at its end */
    if ((it == NULL) || (it->d == NULL) || (ids == NULL)) {
        return 0;
    }
    const vor_t *d = it->d;
    if (d->vertex_count < 2u) {
        return 0;
    }
    uint32_t end = vor__used_slots_end(d);
    /* each used slot is visited once; the loop ends at `end` */
    for (uint32_t s = vor__next_used_slot(d, it->next_slot); s < end;
         s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &d->triangles[s];
        if (VOR__PREFETCHING && ((s + 4u) < end)) {
            /* the sites of a triangle ahead, fetched while this one's are
             * compared: site ids are input positions, anywhere in memory */
            vor_index_t ahead[3];
            vor__vertices(&d->triangles[s + 4u], ahead);
            for (unsigned k = 0; k < 3u; k++) {
                if (ahead[k] != VOR__INFINITE) {
                    VOR__PREFETCH(&d->sites[ahead[k]]);
                }
            }
        }
        if (vor__reported(d->sites, t)) {
            ids[0] = vor__vertex(t, 0);
            ids[1] = vor__vertex(t, 1);
            ids[2] = vor__vertex(t, 2);
            it->next_slot = s + 1u;
            return 1;
        }
    }
    it->next_slot = end;
    return 0;
}

int vor_neighbours_begin(vor_neighbour_iter_t *it, const vor_t *d, uint32_t site)
{
    if (it == NULL) {
        return VOR_ERR_ARG;
    }
    if ((d == NULL) || !vor__site_in_mesh(d, site)) {
        vor__fan_begin(it, NULL, site); /* closed */
        return VOR_ERR_ARG;
    }
    vor__fan_begin(it, d, site);
    return VOR_OK;
}

int vor_neighbours_next(vor_neighbour_iter_t *it, uint32_t *neighbour)
{
    /* a zeroed iterator, or one begun on no diagram, is at its end */
    if ((it == NULL) || (it->d == NULL) || (neighbour == NULL)) {
        return 0;
    }
    return vor__true_neighbour_next(it, neighbour) ? 1 : 0;
}

/* Is t before u going counterclockwise around q from `from` (all three on
 * one circle around q)? Angles in (0, pi) come before [pi, 2 pi). */
static bool before(const vor_t *d, const vor_point_t *q, uint32_t from, uint32_t t, uint32_t u)
{
    const vor_point_t *s = d->sites;
    bool t_first_half = vor__orient2d_sign(q, &s[from], &s[t]) > 0;
    bool u_first_half = vor__orient2d_sign(q, &s[from], &s[u]) > 0;
    if (t_first_half != u_first_half) {
        return t_first_half;
    }
    return vor__orient2d_sign(q, &s[t], &s[u]) > 0;
}

/* The site after `current` going counterclockwise around the empty circle
 * centred on q through `best` (the sites nearest to q, all neighbours of
 * their successors on the circle); `current` itself when it is alone. */
static uint32_t next_on_circle(const vor_t *d, const vor_point_t *q, uint32_t best,
                               uint32_t current)
{
    vor_neighbour_iter_t it;
    uint32_t n = current; /* set when the fan answers: said for the prover */
    uint32_t third;
    uint32_t next = current;
    vor__fan_begin(&it, d, current);
    while (vor__fan_next(&it, &n, &third)) {
        if ((vor__closer_sign(q, &d->sites[n], &d->sites[best], NULL) == 0) &&
            ((next == current) || before(d, q, current, n, next))) {
            next = n;
        }
    }
    return next;
}

/* Checks a query's diagram and hint; on success *start is where to begin. */
static int query_start(const vor_t *d, int32_t x, int32_t y, uint32_t hint, uint32_t *start)
{
    if (d->vertex_count == 0u) {
        return VOR_ERR_EMPTY;
    }
    if (hint == VOR_NO_HINT) {
        *start = (d->vertex_count >= 2u) ? vor__grid_start(d, x, y) : d->last_site;
        return VOR_OK;
    }
    if (!vor__site_in_mesh(d, hint)) {
        return VOR_ERR_ARG; /* not an id, or a duplicate's id: not in the mesh */
    }
    *start = hint;
    return VOR_OK;
}

/* The walk (walk.h) from site `from` to a site nearest to q; *tie is set
 * when another site at the same distance was seen among the last site's
 * neighbours. */
static uint32_t walk_to_nearest(const vor_t *d, const vor_point_t *q, uint32_t from, bool *tie)
{
    vor__walk_t w;
    vor__walk_begin(&w, d, VOR__WALK_POINT);
    w.q = q;
    w.narrow = vor__walk_is_narrow(d, q->x, q->y);
    uint32_t best = vor__walk(&w, from);
    *tie = w.tie;
    return best;
}

int vor_nearest(const vor_t *d, vor_point_t q, uint32_t hint, uint32_t *site)
{
    if ((d == NULL) || (site == NULL)) {
        return VOR_ERR_ARG;
    }
    uint32_t best;
    int err = query_start(d, q.x, q.y, hint, &best);
    if ((err != VOR_OK) || (d->vertex_count == 1u)) {
        if (err == VOR_OK) {
            *site = best; /* untouched on failure: not even rewritten */
        }
        return err;
    }
    bool tie = false;
    best = walk_to_nearest(d, &q, best, &tie);
    /* ties: around the empty circle through `best`, the smallest index.
     * Only when the last fan saw one: every site on that circle is a
     * neighbour of the next one around it, so a tie shows among best's
     * neighbours. The walk visits each circle site once. */
    uint32_t smallest = best;
    uint32_t current = tie ? next_on_circle(d, &q, best, best) : best;
    for (uint32_t steps = 0; (current != best) && (steps < d->vertex_count); steps++) {
        smallest = (current < smallest) ? current : smallest;
        current = next_on_circle(d, &q, best, current);
    }
    *site = smallest;
    return VOR_OK;
}

/* Is site a before site b in the order of the k nearest: strictly closer
 * to q, or as close and a smaller id? */
static bool ranks_before(const vor_t *d, const vor_point_t *q, uint32_t a, uint32_t b)
{
    int c = vor__closer_sign(q, &d->sites[a], &d->sites[b], NULL);
    return (c < 0) || ((c == 0) && (a < b));
}

static bool listed(const uint32_t *list, uint32_t count, uint32_t site)
{
    for (uint32_t i = 0; i < count; i++) {
        if (list[i] == site) {
            return true;
        }
    }
    return false;
}

/*
 * The k nearest sites in order. All sites at the smallest distance lie on
 * an empty circle around q and come first, by id, read off that circle.
 * Every later site p is a Delaunay neighbour of a site strictly closer to
 * q, hence of one already listed: shrink the disk around q through p
 * towards p, keeping p on its boundary, until its interior is empty. Its
 * circle then holds p and sites strictly inside the first disk, and p's
 * neighbours around that empty circle are Delaunay neighbours of p. So
 * the next site is the best unlisted neighbour of the listed ones.
 */
int vor_nearest_k(const vor_t *d, vor_point_t q, uint32_t hint, uint32_t k,
                  uint32_t *nearest, uint32_t *found)
{
    if ((d == NULL) || ((nearest == NULL) && (k > 0u)) || (found == NULL)) {
        return VOR_ERR_ARG;
    }
    uint32_t best;
    int err = query_start(d, q.x, q.y, hint, &best);
    if (err != VOR_OK) {
        return err;
    }
    if ((k == 0u) || (d->vertex_count == 1u)) {
        if (k > 0u) {
            nearest[0] = best;
        }
        *found = (k > 0u) ? 1u : 0u;
        return VOR_OK;
    }
    bool tie = false;
    best = walk_to_nearest(d, &q, best, &tie);

    /* the nearest circle, by id: each round walks it once for the smallest
     * id above the last one listed (at most vertex_count steps a round) */
    uint32_t count = 0;
    uint32_t last = 0;
    bool any = false;
    while (count < k) {
        uint32_t pick = VOR__NONE;
        uint32_t current = best;
        for (uint32_t steps = 0; steps <= d->vertex_count; steps++) {
            if ((!any || (current > last)) && (pick == VOR__NONE || (current < pick))) {
                pick = current;
            }
            current = tie ? next_on_circle(d, &q, best, current) : best;
            if (current == best) {
                break;
            }
        }
        if (pick == VOR__NONE) {
            break;
        }
        nearest[count++] = pick;
        last = pick;
        any = true;
    }

    /* then the best unlisted neighbour of a listed site, each round.
     * (For Frama-C's EVA: one state per count, so that it sees
     * nearest[0 .. count) written.) */
    /*@ split count; */
    while (count < k) {
        uint32_t pick = VOR__NONE;
        uint32_t n = 0; /* set when the fan answers: said for the prover */
        uint32_t third;
        for (uint32_t i = 0; i < count; i++) {
            vor_neighbour_iter_t it;
            vor__fan_begin(&it, d, nearest[i]);
            while (vor__fan_next(&it, &n, &third)) {
                if ((pick == VOR__NONE || ranks_before(d, &q, n, pick)) &&
                    !listed(nearest, count, n)) {
                    pick = n;
                }
            }
        }
        if (pick == VOR__NONE) {
            break; /* every site is listed */
        }
        nearest[count++] = pick;
    }
    *found = count;
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Point location (vor_locate)                                         */

/*
 * The reported triangle (vor__reported) holding q~, q moved by the
 * perturbation with an index before every site (vor__orient_query), or
 * VOR__NONE when q~ is outside the hull. q~ lies on no line through two
 * sites, so it is strictly inside one triangle of the true
 * triangulation, or strictly outside the hull. From site c (the nearest
 * to q, where the walk ends) the straight walk along the segment c -> q~:
 * the corner of a reported triangle at c that the segment leaves by,
 * then across the edges it crosses, until the triangle holds q~. The
 * segment runs through the hull while q~ is inside (convexity), so
 * meeting a triangle that is not reported (at infinity, or flat on a
 * hull line) means it left the hull: q~ is outside. No reported corner
 * at c holding the segment means the same: the reported corners at c
 * cover the hull's cone at c. Why from the nearest site: the segment
 * then stays in c's Voronoi cell, and crosses only Delaunay edges whose
 * triangles have q in their circle (a handful). Termination: each step
 * moves on along the segment, into a triangle not visited before, so at
 * most the triangle count of steps (a bound kept on a broken mesh).
 */
static vor_index_t locate_from(const vor_t *d, const vor_point_t *q, vor_index_t c)
{
    const vor_point_t *s = d->sites;
    const vor__tri_t *tri = d->triangles;
    vor__star_step_t star;
    vor__star_begin(d, c, &star);
    vor_index_t r = VOR__INFINITE; /* the crossed edge: r right of c -> q~, l left */
    vor_index_t l = VOR__INFINITE;
    vor_index_t slot = VOR__NONE;
    bool turning = true;
    for (uint32_t left = d->vertex_count + 1u; turning && (left > 0u); left--) {
        const vor__tri_t *t = &tri[star.slot];
        /* the corner (c, x, y) holds q~: left of c -> x, right of c -> y.
         * (x and y finite is part of reported; said for the analysers) */
        if ((star.x != VOR__INFINITE) && (star.y != VOR__INFINITE) && vor__reported(s, t) &&
            (vor__orient_query(&s[c], &s[star.x], q) > 0) &&
            (vor__orient_query(&s[star.y], &s[c], q) > 0)) {
            if (vor__orient_query(&s[star.x], &s[star.y], q) > 0) {
                return star.slot;
            }
            r = star.x;
            l = star.y;
            /* across x - y: opposite c, found as vor__star_look finds it */
            slot = t->n[(star.v[1] == c) ? 1u : (star.v[2] == c) ? 2u : 0u];
            break;
        }
        turning = vor__star_advance(d, c, &star);
    }
    if (slot == VOR__NONE) {
        return VOR__NONE; /* no corner holds it: outside the hull */
    }
    for (uint32_t left = vor__triangle_count(d->vertex_count); left > 0u; left--) {
        /* (l, r, w) counterclockwise, entered across l -> r */
        const vor__tri_t *t = &tri[slot];
        vor_index_t v[3];
        vor__vertices(t, v);
        unsigned k = ((v[0] != r) && (v[0] != l)) ? 0u : ((v[1] != r) && (v[1] != l)) ? 1u : 2u;
        vor_index_t w = v[k];
        /* (w finite is part of reported: said for the analysers) */
        if (!vor__reported_vertices(s, v) || (w == VOR__INFINITE)) {
            break; /* across a hull edge: q~ is outside */
        }
        if ((vor__orient_query(&s[r], &s[w], q) > 0) && (vor__orient_query(&s[w], &s[l], q) > 0)) {
            return slot;
        }
        /* w left of the segment (c, q~, w counterclockwise): out across
         * r - w, opposite l; else across w - l, opposite r */
        bool w_left = vor__orient_query(&s[w], &s[c], q) > 0;
        unsigned out = vor__vertex_index(t, w_left ? l : r);
        l = w_left ? w : l;
        r = w_left ? r : w;
        slot = t->n[(out == 3u) ? 0u : out];
    }
    return VOR__NONE; /* outside (or, on a broken mesh only, out of steps) */
}

int vor_locate(const vor_t *d, vor_point_t q, uint32_t hint, uint32_t ids[3])
{
    if ((d == NULL) || (ids == NULL)) {
        return VOR_ERR_ARG;
    }
    uint32_t start;
    int err = query_start(d, q.x, q.y, hint, &start);
    if (err != VOR_OK) {
        return err;
    }
    if (d->vertex_count < 3u) {
        return VOR_ERR_OUTSIDE; /* no triangle */
    }
    bool tie = false;
    uint32_t c = walk_to_nearest(d, &q, start, &tie);
    vor_index_t slot = locate_from(d, &q, (vor_index_t)c);
    if (slot == VOR__NONE) {
        return VOR_ERR_OUTSIDE;
    }
    vor_index_t v[3];
    vor__vertices(&d->triangles[slot], v);
    ids[0] = v[0];
    ids[1] = v[1];
    ids[2] = v[2];
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Sites within a distance (vor_within)                                */

/* Is |q - p|^2 <= r2, exactly? Each square is below 2^64 (differences
 * below 2^32), their sum below 2^65: a carry out means farther. */
static bool in_disc(const vor_point_t *q, const vor_point_t *p, uint64_t r2)
{
    uint32_t dx = vor__mw_magnitude((int64_t)q->x - p->x);
    uint32_t dy = vor__mw_magnitude((int64_t)q->y - p->y);
    uint64_t a = vor__mul_u32(dx, dx);
    uint64_t sum = a + vor__mul_u32(dy, dy);
    return (sum >= a) && (sum <= r2);
}

/* The search tree of vor_within: a site p farther from q than the
 * nearest sites has a mesh neighbour strictly closer to q (the shrinking
 * disc of vor_nearest_k), and its parent is its first neighbour in the
 * order of the k nearest (ranks_before); the nearest sites are the roots.
 * Is p a child of v: in the disc, not a root, and no neighbour of p
 * before v? */
static bool is_child(const vor_t *d, const vor_point_t *q, uint64_t r2, uint32_t best,
                     uint32_t v, uint32_t p)
{
    const vor_point_t *s = d->sites;
    if (!in_disc(q, &s[p], r2) || (vor__closer_sign(q, &s[p], &s[best], NULL) == 0) ||
        ranks_before(d, q, p, v)) {
        return false;
    }
    vor_neighbour_iter_t it;
    uint32_t n = 0; /* set when the fan answers: said for the prover */
    uint32_t third;
    vor__fan_begin(&it, d, p);
    while (vor__fan_next(&it, &n, &third)) {
        if (ranks_before(d, q, n, v)) {
            return false;
        }
    }
    return true;
}

/* The parent of p (not a root): its first neighbour in rank order. */
static uint32_t parent_of(const vor_t *d, const vor_point_t *q, uint32_t p)
{
    vor_neighbour_iter_t it;
    uint32_t n = 0;
    uint32_t third;
    uint32_t parent = p;
    vor__fan_begin(&it, d, p);
    while (vor__fan_next(&it, &n, &third)) {
        parent = ((parent == p) || ranks_before(d, q, n, parent)) ? n : parent;
    }
    return parent;
}

/* v's first child in its fan's order after neighbour `after` (VOR__NONE:
 * from the fan's start); VOR__NONE when there is none. */
static uint32_t next_child(const vor_t *d, const vor_point_t *q, uint64_t r2, uint32_t best,
                           uint32_t v, uint32_t after)
{
    vor_neighbour_iter_t it;
    uint32_t n = 0;
    uint32_t third;
    bool past = after == VOR__NONE;
    vor__fan_begin(&it, d, v);
    while (vor__fan_next(&it, &n, &third)) {
        if (past && is_child(d, q, r2, best, v, n)) {
            return n;
        }
        past = past || (n == after);
    }
    return VOR__NONE;
}

/*
 * The sites in the disc, by a depth-first walk of the search tree with
 * no stack: down to a node's first child; at a node without more
 * children, up to its parent and on to the parent's next child; at a
 * root, on to the next root around the nearest circle (vor_nearest's
 * walk). The disc's sites form a subtree of every root in the disc: a
 * site's parent is strictly closer to q, so in the disc too. Each site
 * is entered once and left once: at most 2 v + 1 steps, the bound kept
 * on a broken mesh. Writes the first `room` sites found to ids[] (none
 * when room is 0); returns how many there are.
 */
static uint32_t disc_walk(const vor_t *d, const vor_point_t *q, uint64_t r2, uint32_t best,
                          bool tie, uint32_t *ids, uint32_t room)
{
    if (!in_disc(q, &d->sites[best], r2)) {
        return 0;
    }
    uint32_t count = 1;
    if (room > 0u) {
        ids[0] = best;
    }
    uint32_t v = best;
    uint32_t from = VOR__NONE; /* the child of v just finished */
    for (uint32_t left = (2u * d->vertex_count) + 1u; left > 0u; left--) {
        uint32_t next = next_child(d, q, r2, best, v, from);
        if ((next == VOR__NONE) && (vor__closer_sign(q, &d->sites[v], &d->sites[best], NULL) == 0)) {
            next = tie ? next_on_circle(d, q, best, v) : best; /* the next root */
            if (next == best) {
                break;
            }
        }
        if (next == VOR__NONE) {
            from = v;
            v = parent_of(d, q, v);
            continue;
        }
        if (count < room) {
            ids[count] = next;
        }
        count++;
        v = next;
        from = VOR__NONE;
    }
    return count;
}

/* Moves a[root] down the max-heap a[0 .. n) to its place: each step at
 * least doubles root, so fewer than 32 steps. */
static void heap_sift(uint32_t *a, uint32_t root_in, uint32_t n)
{
    uint32_t root = root_in;
    uint32_t child = (2u * root) + 1u;
    while (child < n) {
        uint32_t pick = child;
        if (((child + 1u) < n) && (a[child + 1u] > a[child])) {
            pick = child + 1u;
        }
        if (a[root] >= a[pick]) {
            break;
        }
        uint32_t top = a[root];
        a[root] = a[pick];
        a[pick] = top;
        root = pick;
        child = (2u * root) + 1u;
    }
}

/* Heapsort of a[0 .. n), increasing: in place, O(n log n), no recursion
 * (the library has no libc). */
static void sort_increasing(uint32_t *a, uint32_t n)
{
    for (uint32_t i = n / 2u; i > 0u; i--) {
        heap_sift(a, i - 1u, n);
    }
    for (uint32_t end = n; end > 1u; end--) {
        uint32_t top = a[0];
        a[0] = a[end - 1u];
        a[end - 1u] = top;
        heap_sift(a, 0, end - 1u);
    }
}

int vor_within(const vor_t *d, vor_point_t q, uint64_t r2, uint32_t hint, uint32_t *ids,
               uint32_t capacity, uint32_t *count)
{
    if ((d == NULL) || (count == NULL) || ((ids == NULL) && (capacity > 0u))) {
        return VOR_ERR_ARG;
    }
    uint32_t best;
    int err = query_start(d, q.x, q.y, hint, &best);
    if (err != VOR_OK) {
        return err;
    }
    bool tie = false;
    if (d->vertex_count >= 2u) {
        best = walk_to_nearest(d, &q, best, &tie);
    }
    /* a capacity that holds every site takes one walk; a smaller one is
     * counted first, so that nothing is written when it is too small */
    uint32_t room = (capacity >= d->vertex_count) ? capacity : 0u;
    uint32_t needed = disc_walk(d, &q, r2, best, tie, ids, room);
    if (needed > capacity) {
        *count = needed;
        return VOR_ERR_BUFFER;
    }
    if (room == 0u) {
        (void)disc_walk(d, &q, r2, best, tie, ids, capacity);
    }
    sort_increasing(ids, needed);
    *count = needed;
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Flat export (vor_triangles_export)                                  */

/* The triangles vor_triangles_next lists: the reported ones among the
 * used slots, in increasing slot order. */
static uint32_t reported_count(const vor_t *d)
{
    uint32_t n = 0;
    if (d->vertex_count < 2u) {
        return 0; /* no triangle slots: a one-site arena may have none */
    }
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        n += vor__reported(d->sites, &d->triangles[s]) ? 1u : 0u;
    }
    return n;
}

int vor_triangles_count(const vor_t *d, uint32_t *count)
{
    if ((d == NULL) || (count == NULL)) {
        return VOR_ERR_ARG;
    }
    *count = reported_count(d);
    return VOR_OK;
}

/* The index of the triangle whose slot is `slot` among the n triangles
 * whose increasing slots are keys[0], keys[3], ..; VOR__NONE when none
 * (a triangle that is not reported). Binary search: O(log n). */
static uint32_t triangle_of_slot(const uint32_t *keys, uint32_t n, uint32_t slot)
{
    uint32_t low = 0;
    uint32_t high = n;
    while (low < high) { /* the range halves each step */
        uint32_t middle = low + ((high - low) / 2u);
        uint32_t key = keys[3u * middle];
        if (key == slot) {
            return middle;
        }
        if (key < slot) {
            low = middle + 1u;
        } else {
            high = middle;
        }
    }
    return VOR__NONE;
}

/*
 * The triangles in the iterator's order, then the twins. Without other
 * memory: triangles[3 t] first holds triangle t's slot (the slots
 * increase with t), which the twins' binary search reads; then each is
 * replaced by the triangle's vertices, which the mesh still holds.
 * Half-edge 3 t + k runs from vertex k to vertex k + 1 (mod 3) of
 * triangle t, the edge opposite vertex k + 2 in the mesh; its twin runs
 * back in the triangle across, at the index of that triangle's vertex
 * k + 1 (mod 3) of t.
 */
int vor_triangles_export(const vor_t *d, uint32_t *triangles, uint32_t *halfedges,
                         uint32_t capacity, uint32_t *count)
{
    if ((d == NULL) || (count == NULL) || ((triangles == NULL) && (capacity > 0u))) {
        return VOR_ERR_ARG;
    }
    uint32_t n = reported_count(d);
    if (n > capacity) {
        *count = n;
        return VOR_ERR_BUFFER;
    }
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    uint32_t t = 0;
    for (uint32_t s = (n > 0u) ? vor__next_used_slot(d, 0) : end; (s < end) && (t < n);
         s = vor__next_used_slot(d, s + 1u)) {
        if (vor__reported(d->sites, &tri[s])) {
            triangles[3u * t] = s;
            t++;
        }
    }
    for (uint32_t i = 0; (halfedges != NULL) && (i < n); i++) {
        const vor__tri_t *at = &tri[triangles[3u * i]];
        for (unsigned k = 0; k < 3u; k++) {
            vor_index_t across = at->n[vor__prev(k)];
            uint32_t j = triangle_of_slot(triangles, n, across);
            unsigned back = vor__vertex_index(&tri[across], vor__vertex(at, vor__next(k)));
            /* back < 3: the triangle across has the edge (a valid mesh) */
            halfedges[(3u * i) + k] = (j == VOR__NONE) ? VOR_HALFEDGE_NONE : ((3u * j) + back);
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        vor_index_t v[3];
        vor__vertices(&tri[triangles[3u * i]], v);
        triangles[3u * i] = v[0];
        triangles[(3u * i) + 1u] = v[1];
        triangles[(3u * i) + 2u] = v[2];
    }
    *count = n;
    return VOR_OK;
}

int vor_tracker_begin_checked(vor_tracker_t *tracker, const vor_t *d, uint32_t config)
{
    if (config != VOR_CONFIG_FINGERPRINT) {
        return VOR_ERR_CONFIG; /* *tracker may be smaller than this library's */
    }
    if ((tracker == NULL) || (d == NULL)) {
        return VOR_ERR_ARG;
    }
    tracker->d = d;
    tracker->revision = 0;
    tracker->site = VOR_NO_HINT;
    tracker->edges = 0;
    tracker->cached = 0;
    return VOR_OK;
}

/* Caches the cell of `site` as its bisector tests, when they are exact in
 * int64: for a neighbour n with d = n - s within 2^30 of s on each axis,
 * and a query q with e = q - s in int32, q is strictly closer to s than to
 * n exactly when |d|^2 > e.(2d) (bounds at vor__walk_is_narrow, walk.h). */
static void cache_cell(vor_tracker_t *tracker, uint32_t site)
{
    const vor_t *d = tracker->d;
    const vor_point_t *s = &d->sites[site];
    tracker->site = site;
    tracker->revision = d->revision;
    tracker->edges = 0;
    tracker->cached = 0;
    tracker->at.x = s->x;
    tracker->at.y = s->y;
    const int64_t reach = INT32_MAX;
    tracker->low.x = (int32_t)((s->x >= 0) ? (s->x - reach) : INT32_MIN);
    tracker->low.y = (int32_t)((s->y >= 0) ? (s->y - reach) : INT32_MIN);
    tracker->high.x = (int32_t)((s->x >= 0) ? INT32_MAX : (s->x + reach));
    tracker->high.y = (int32_t)((s->y >= 0) ? INT32_MAX : (s->y + reach));

    vor_neighbour_iter_t it;
    uint32_t n;
    uint32_t third;
    uint32_t edges = 0;
    vor__fan_begin(&it, d, site);
    while (vor__fan_next(&it, &n, &third)) {
        int64_t dx = (int64_t)d->sites[n].x - s->x;
        int64_t dy = (int64_t)d->sites[n].y - s->y;
        const int64_t limit = 1073741824; /* 2^30 */
        if ((edges == (uint32_t)VOR_TRACKER_EDGES) || (dx <= -limit) || (dx >= limit) || (dy <= -limit) ||
            (dy >= limit)) {
            return; /* not cached: vor_nearest answers */
        }
        /* the cell the point moves into next is one of these: its first
         * triangle (the neighbour's home slot) is fetched meanwhile */
        VOR__PREFETCH(&d->triangles[n]);
        tracker->neighbour[edges] = (vor_index_t)n;
        vor_tracker_edge_t *e = &tracker->edge[edges];
        edges++;
        e->twice_dx = (int32_t)(2 * dx);
        e->twice_dy = (int32_t)(2 * dy);
        e->square = vor__mul_i32((int32_t)dx, (int32_t)dx) + vor__mul_i32((int32_t)dy, (int32_t)dy);
    }
    tracker->edges = edges;
    tracker->cached = 1;
}

/* The point left the cached cell (or there is none): vor_nearest from the
 * last answer, and the new answer's cell cached. Out of line, so that the
 * cached path pays for no registers of it. */
static VOR__NOINLINE int track_by_walk(vor_tracker_t *tracker, int32_t x, int32_t y,
                                       uint32_t hint, uint32_t *site)
{
    const vor_t *d = tracker->d;
    bool current = (tracker->revision == d->revision) && (tracker->site != VOR_NO_HINT);
    uint32_t answer;
    vor_point_t q = {x, y};
    int err = vor_nearest(d, q, current ? hint : VOR_NO_HINT, &answer);
    if (err != VOR_OK) {
        return err;
    }
    cache_cell(tracker, answer);
    *site = answer;
    return VOR_OK;
}

int vor_track(vor_tracker_t *tracker, vor_point_t q, uint32_t *site)
{
    if ((tracker == NULL) || (tracker->d == NULL) || (site == NULL)) {
        return VOR_ERR_ARG;
    }
    int32_t x = q.x;
    int32_t y = q.y;
    if (tracker->cached && (tracker->revision == tracker->d->revision) &&
        (x >= tracker->low.x) && (x <= tracker->high.x) && (y >= tracker->low.y) &&
        (y <= tracker->high.y)) {
        int32_t ex = x - tracker->at.x;
        int32_t ey = y - tracker->at.y;
        const vor_tracker_edge_t *edge = tracker->edge;
        const vor_tracker_edge_t *end = edge + tracker->edges;
        /* strictly inside the cell: every neighbour strictly farther */
        while ((edge != end) &&
               (edge->square > vor__mul_i32(ex, edge->twice_dx) + vor__mul_i32(ey, edge->twice_dy))) {
            edge++;
        }
        if (edge == end) {
            *site = tracker->site;
            return VOR_OK;
        }
        /* the site across the edge is at least as close: the walk starts
         * there, and skips the fan of the cell just left */
        return track_by_walk(tracker, x, y, tracker->neighbour[edge - tracker->edge], site);
    }
    return track_by_walk(tracker, x, y, tracker->site, site);
}

/* ------------------------------------------------------------------ */
/* Validation: every invariant of the mesh (counts, vertices, neighbours,
 * fans, the bucket grid, orientation, the Delaunay property) and of what
 * the iterators report, checked with the exact predicates, uncounted, so
 * validation never changes the diagram (nor lies in fault injection
 * builds). */

/* vor__conflicts with the true predicates, uncounted. */
static bool exact_conflict(const vor_t *d, const vor__tri_t *t, uint32_t p)
{
    vor_index_t v0 = vor__vertex(t, 0);
    vor_index_t v1 = vor__vertex(t, 1);
    vor_index_t v2 = vor__vertex(t, 2);
    if (v0 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v1, v2, p) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v2, v0, p) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v0, v1, p) > 0;
    }
    return vor_incircle_sos(d->sites, v0, v1, v2, p) > 0;
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

static bool slot_in_use(const vor_t *d, uint32_t slot)
{
    if (slot < d->max_sites) {
        return (slot < d->site_count) && !vor__slot_empty(&d->triangles[slot]);
    }
    return slot < vor__used_slots_end(d);
}

/* The site's triangles around it from its home slot, counted; 0 when the
 * fan does not close within `limit` steps or leaves the site. */
static uint32_t fan_size(const vor_t *d, uint32_t start, vor_index_t site, uint32_t limit)
{
    uint32_t slot = start;
    uint32_t count = 0;
    do {
        const vor__tri_t *t = &d->triangles[slot];
        unsigned i = vor__vertex_index(t, site);
        if ((i == 3u) || (count == limit)) {
            return 0;
        }
        count++;
        slot = t->n[vor__next(i)]; /* across the edge (site, next-next): turn clockwise */
    } while (slot != start);
    return count;
}

/* The site after b on the boundary of the reported triangles, turning
 * clockwise around b from the reported triangle at `slot` that has the
 * boundary edge a -> b; VOR__INFINITE if the turn does not end within
 * vertex_count + 1 steps (only on a broken mesh). */
static uint32_t boundary_after(const vor_t *d, uint32_t slot_in, vor_index_t b)
{
    uint32_t slot = slot_in;
    for (uint32_t step = 0; step <= d->vertex_count; step++) {
        const vor__tri_t *t = &d->triangles[slot];
        unsigned j = vor__vertex_index(t, b);
        if (j == 3u) {
            break;
        }
        slot = t->n[vor__prev(j)]; /* across the edge b -> the vertex after b */
        if (!vor__reported(d->sites, &d->triangles[slot])) {
            return vor__vertex(t, vor__next(j));
        }
    }
    return VOR__INFINITE;
}

/* What the iterators report, against the counts of a triangulation of the
 * v distinct sites whose boundary is the convex hull through all h sites
 * on it (Euler: 2 v - h - 2 triangles, 3 t + h edge ends), or of a path
 * when all sites are collinear (no triangle, v - 1 edges). */
static int check_true_output(const vor_t *d, vor_violation_t *out)
{
    const vor_point_t *s = d->sites;
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    uint32_t reported = 0;
    uint32_t boundary = 0;
    for (uint32_t slot = vor__next_used_slot(d, 0); slot < end;
         slot = vor__next_used_slot(d, slot + 1u)) {
        const vor__tri_t *t = &tri[slot];
        if (!vor__reported(s, t)) {
            continue;
        }
        vor_index_t v[3];
        vor__vertices(t, v);
        if (vor__orient2d_sign(&s[v[0]], &s[v[1]], &s[v[2]]) <= 0) {
            return violation(out, VOR_CHECK_TRUE_OUTPUT, slot, v[0]);
        }
        reported++;
        for (unsigned i = 0; i < 3u; i++) {
            if (vor__reported(s, &tri[t->n[i]])) {
                continue;
            }
            /* a boundary edge a -> b: the boundary turns left (or goes
             * straight on, past a hull site) at b */
            vor_index_t a = v[vor__next(i)];
            vor_index_t b = v[vor__prev(i)];
            uint32_t c = boundary_after(d, slot, b);
            if (c == VOR__INFINITE || (c == a) || vor__orient2d_sign(&s[a], &s[b], &s[c]) < 0) {
                return violation(out, VOR_CHECK_TRUE_OUTPUT, slot, b);
            }
            boundary++;
        }
    }
    uint32_t v = d->vertex_count;
    if ((reported != 0u) && (reported + boundary + 2u) != (2u * v)) {
        return violation(out, VOR_CHECK_TRUE_OUTPUT, 0, v);
    }
    uint32_t ends = 0;
    for (uint32_t site = 0; site < d->site_count; site++) {
        if (vor__slot_empty(&tri[site])) {
            continue;
        }
        vor_neighbour_iter_t it;
        uint32_t n;
        uint32_t degree = 0;
        vor__fan_begin(&it, d, site);
        while (vor__true_neighbour_next(&it, &n)) {
            degree++;
        }
        if ((degree == 0u) || ((reported == 0u) && (degree > 2u))) {
            return violation(out, VOR_CHECK_TRUE_OUTPUT, site, site);
        }
        ends += degree;
    }
    if (ends != ((reported != 0u) ? ((3u * reported) + boundary) : (2u * (v - 1u)))) {
        return violation(out, VOR_CHECK_TRUE_OUTPUT, 0, v);
    }
    return VOR_OK;
}

/* Counts: the used slots are exactly 2v - 2 (none below two sites). The
 * packed extra slots are v - 2 by their definition (vor__used_slots_end),
 * so that holds when exactly v home slots are in use. */
static int check_counts(const vor_t *d, vor_violation_t *out)
{
    if ((d->vertex_count > d->site_count) || (d->site_count > d->max_sites)) {
        return violation(out, VOR_CHECK_COUNTS, 0, d->vertex_count);
    }
    if (d->vertex_count < 2u) {
        return VOR_OK;
    }
    uint32_t present = 0;
    for (uint32_t s = 0; s < d->site_count; s++) {
        present += vor__slot_empty(&d->triangles[s]) ? 0u : 1u;
    }
    if (present != d->vertex_count) {
        return violation(out, VOR_CHECK_COUNTS, 0, d->vertex_count);
    }
    return VOR_OK;
}

/* Vertices: sites in the mesh or infinity, three distinct. */
static int check_vertices(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t v = vor__vertex(t, i);
            if (v != VOR__INFINITE &&
                ((v >= d->site_count) || vor__slot_empty(&tri[v]))) {
                return violation(out, VOR_CHECK_VERTICES, s, v);
            }
        }
        if (vor__vertex(t, 0) == vor__vertex(t, 1) || vor__vertex(t, 1) == vor__vertex(t, 2) ||
            vor__vertex(t, 2) == vor__vertex(t, 0)) {
            return violation(out, VOR_CHECK_VERTICES, s, vor__vertex(t, 1));
        }
    }
    return VOR_OK;
}

/* Neighbours: in use, pointing back across the same edge. */
static int check_neighbours(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t u = t->n[i];
            vor_index_t a = vor__vertex(t, vor__next(i));
            vor_index_t b = vor__vertex(t, vor__prev(i));
            if (u == VOR__NONE || !slot_in_use(d, u)) {
                return violation(out, VOR_CHECK_NEIGHBOURS, s, a);
            }
            const vor__tri_t *o = &tri[u];
            unsigned ia = vor__vertex_index(o, a);
            unsigned ib = vor__vertex_index(o, b);
            /* in o the edge runs b -> a, and o's neighbour across it is t */
            if ((ia == 3u) || (ib == 3u) || vor__next(ib) != ia ||
                o->n[vor__next(ia)] != s) {
                return violation(out, VOR_CHECK_NEIGHBOURS, s, a);
            }
        }
    }
    return VOR_OK;
}

/* Sites: each site's home slot holds one of its triangles, and its
 * triangles form one fan; all fans together cover each triangle once per
 * corner. */
static int check_fans(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t triangles = vor__triangle_count(d->vertex_count);
    uint32_t end = vor__used_slots_end(d);
    uint32_t corners = 0;
    for (uint32_t s = 0; s < d->site_count; s++) {
        if (vor__slot_empty(&tri[s])) {
            continue;
        }
        uint32_t fan = fan_size(d, s, (vor_index_t)s, triangles);
        if (fan < 2u) {
            return violation(out, VOR_CHECK_SITES, s, s);
        }
        corners += fan;
    }
    uint32_t ghost = vor__next_used_slot(d, 0);
    while ((ghost < end) && !vor__is_ghost(&tri[ghost])) {
        ghost = vor__next_used_slot(d, ghost + 1u);
    }
    corners += (ghost < end) ? fan_size(d, ghost, VOR__INFINITE, triangles) : 0u;
    if (corners != (3u * triangles)) {
        return violation(out, VOR_CHECK_SITES, 0, VOR__INFINITE);
    }
    return VOR_OK;
}

/* The query index: a box around every site, buckets naming sites. */
static int check_buckets(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    for (uint32_t s = 0; s < d->site_count; s++) {
        const vor_point_t *p = &d->sites[s];
        if (!vor__slot_empty(&tri[s]) && ((p->x < d->low.x) || (p->x > d->high.x) ||
                                          (p->y < d->low.y) || (p->y > d->high.y))) {
            return violation(out, VOR_CHECK_BUCKETS, s, s);
        }
    }
    uint64_t buckets = vor__mul_u32(d->bucket_columns, d->bucket_rows);
    if ((buckets == 0u) || (buckets > VOR_BUCKETS(d->max_sites))) {
        return violation(out, VOR_CHECK_BUCKETS, 0, VOR__INFINITE);
    }
    for (uint32_t b = 0; b < (uint32_t)buckets; b++) {
        vor_index_t s = d->buckets[b];
        if ((s >= d->site_count) || vor__slot_empty(&tri[s])) {
            return violation(out, VOR_CHECK_BUCKETS, b, s);
        }
    }
    return VOR_OK;
}

/* Geometry: every finite triangle counterclockwise, and no neighbour's
 * far vertex in a triangle's circle, by the exact perturbed predicates,
 * uncounted, so validation never changes the diagram (nor lies in fault
 * injection builds). */
static int check_delaunay(const vor_t *d, vor_violation_t *out)
{
    const vor__tri_t *tri = d->triangles;
    uint32_t end = vor__used_slots_end(d);
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        if (!vor__is_ghost(t) &&
            vor_orient2d_sos(d->sites, vor__vertex(t, 0), vor__vertex(t, 1), vor__vertex(t, 2)) < 0) {
            return violation(out, VOR_CHECK_ORIENTATION, s, vor__vertex(t, 0));
        }
    }
    for (uint32_t s = vor__next_used_slot(d, 0); s < end; s = vor__next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            const vor__tri_t *o = &tri[t->n[i]];
            vor_index_t a = vor__vertex(t, vor__next(i));
            vor_index_t apex = vor__vertex(o, vor__next(vor__vertex_index(o, a)));
            if (apex == VOR__INFINITE || vor__vertex_index(t, apex) != 3u) {
                continue; /* infinity is never inside a circle; two sites:
                             both triangles have the same three vertices */
            }
            /* the neighbour's far vertex must not conflict with t */
            if (exact_conflict(d, t, apex)) {
                return violation(out, VOR_CHECK_DELAUNAY, s, apex);
            }
        }
    }
    return VOR_OK;
}

/* The checks in order, each relying on the ones before it (the fans on
 * the neighbours, the geometry on the fans, ...); the first failure is
 * reported. The topological ones are shared with vor_power_validate. */
int vor__validate_topology(const vor_t *d, vor_violation_t *out)
{
    int err = check_counts(d, out);
    if ((err != VOR_OK) || (d->vertex_count < 2u)) {
        return err;
    }
    err = check_vertices(d, out);
    err = (err == VOR_OK) ? check_neighbours(d, out) : err;
    err = (err == VOR_OK) ? check_fans(d, out) : err;
    return (err == VOR_OK) ? check_buckets(d, out) : err;
}

int vor_validate(const vor_t *d, vor_violation_t *out)
{
    if (d == NULL) {
        return VOR_ERR_ARG;
    }
    int err = vor__validate_topology(d, out);
    if ((err != VOR_OK) || (d->vertex_count < 2u)) {
        return err;
    }
    err = check_delaunay(d, out);
    return (err == VOR_OK) ? check_true_output(d, out) : err;
}
