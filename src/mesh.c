/* SPDX-License-Identifier: MIT */
/*
 * mesh.c - the diagram object: arena layout, the predicates as the mesh
 * uses them, validation, memory figures and triangle iteration.
 * The builders (incremental.c) change the mesh; this file only reads it.
 */
#include "mesh.h"
#include "motion.h"

int vor_init_checked(vor_t *d, void *arena, size_t arena_bytes, uint32_t max_sites,
                     uint32_t config)
{
    if (config != VOR_CONFIG_FINGERPRINT) {
        return VOR_ERR_CONFIG; /* *d and the arena are laid out differently */
    }
    if (d == NULL || arena == NULL || max_sites == 0u || max_sites > VOR_MAX_SITES) {
        return VOR_ERR_ARG;
    }
    if (((uintptr_t)arena % VOR_ARENA_ALIGN) != 0u) {
        return VOR_ERR_ALIGN;
    }
    if (arena_bytes < VOR_ARENA_BYTES(max_sites)) {
        return VOR_ERR_NOMEM;
    }
    /* field by field: no structure copies, which can become memcpy calls */
    d->sites = (vor_point_t *)arena;
    /* the triangles follow the coordinates: 8-byte points keep them aligned */
    d->triangles = (vor__tri_t *)(void *)(d->sites + max_sites);
    /* the bucket grid follows the triangles (4-byte multiples) */
    d->buckets = (vor_index_t *)(void *)(d->triangles + vor__triangle_count(max_sites));
    d->max_sites = max_sites;
    d->site_count = 0;
    d->vertex_count = 0;
    d->last_site = 0;
    d->low.x = d->low.y = d->high.x = d->high.y = 0;
    d->bucket_origin.x = d->bucket_origin.y = 0;
    d->bucket_columns = d->bucket_rows = d->bucket_scale = 0;
    d->bucket_rebuild_at = 2;
    d->revision = 0;
    d->free_site = 0;
    d->motion = NULL; /* a cache is attached afterwards (vor_motion_attach) */
    d->motion_epoch = 0;
    vor_predicate_stats_t zero;
    for (unsigned t = 0; t < VOR_TIERS; t++) {
        zero.orient2d[t] = zero.incircle[t] = zero.closer[t] = 0;
    }
    zero.orient2d_perturbed = zero.incircle_perturbed = zero.closer_perturbed = 0;
#ifdef VOR_FAULT_INJECTION
    zero.fault_rate = 0;
    zero.fault_state = 1;
#endif
    vor__copy_stats(&d->stats, &zero);
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* Validation                                                          */

/* vor__conflicts with the true predicates, uncounted. */
void vor__make_edge(vor_t *d, uint32_t a, uint32_t b)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t sa = (vor_index_t)a, sb = (vor_index_t)b;
    /* fresh slots: clear any mark bits left by earlier contents */
    vor__tri_fresh(&tri[a]);
    vor__tri_fresh(&tri[b]);
    vor__tri_set(&tri[a], sa, sb, VOR__INFINITE, sb, sb, sb);
    vor__tri_set(&tri[b], sb, sa, VOR__INFINITE, sa, sa, sa);
}

int vor__build_start(vor_t *d, const vor_point_t *points, uint32_t n,
                     uint32_t *duplicate_of)
{
    if (d == NULL || (points == NULL && n > 0u)) {
        return VOR_ERR_ARG;
    }
    if (n > d->max_sites) {
        return VOR_ERR_FULL;
    }
    d->site_count = n;
    d->vertex_count = 0;
    d->last_site = 0;
    d->bucket_rebuild_at = 2; /* the grid of earlier sites is void */
    d->revision++;
    vor__topology_changed(d); /* the attached motion cache stays, emptied */
    d->free_site = 0; /* the ids are 0 .. n - 1 again */
    for (uint32_t s = 0; s < n; s++) {
        d->sites[s] = points[s];
        vor__box_add(d, &points[s], s == 0u);
    }
    if (n <= 1u) {
        d->vertex_count = n;
        if (n == 1u && duplicate_of != NULL) {
            duplicate_of[0] = 0;
        }
        return VOR_OK;
    }
    return VOR__BUILD_MESH;
}

static bool exact_conflict(const vor_t *d, const vor__tri_t *t, uint32_t p)
{
    vor_index_t v0 = vor__vertex(t, 0), v1 = vor__vertex(t, 1), v2 = vor__vertex(t, 2);
    if (v0 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v1, v2, p, NULL) > 0;
    }
    if (v1 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v2, v0, p, NULL) > 0;
    }
    if (v2 == VOR__INFINITE) {
        return vor_orient2d_sos(d->sites, v0, v1, p, NULL) > 0;
    }
    return vor_incircle_sos(d->sites, v0, v1, v2, p, NULL) > 0;
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

/* One past the last packed extra slot: v - 2 extras for v >= 2 sites. */
static uint32_t extra_end(const vor_t *d)
{
    return d->max_sites + ((d->vertex_count >= 2u) ? d->vertex_count - 2u : 0u);
}

/* Slots holding triangles: non-empty home slots of site ids, then the
 * packed extra slots. Returns the next used slot at or after `slot`, or
 * extra_end when none is left. */
static uint32_t next_used_slot(const vor_t *d, uint32_t slot)
{
    for (; slot < d->site_count; slot++) {
        if (!vor__slot_empty(&d->triangles[slot])) {
            return slot;
        }
    }
    if (slot < d->max_sites) {
        slot = d->max_sites;
    }
    uint32_t end = extra_end(d);
    return (slot < end) ? slot : end;
}

uint32_t vor__next_used_slot(const vor_t *d, uint32_t slot)
{
    return next_used_slot(d, slot);
}

uint32_t vor__used_slots_end(const vor_t *d)
{
    return extra_end(d);
}

static bool slot_in_use(const vor_t *d, uint32_t slot)
{
    if (slot < d->max_sites) {
        return slot < d->site_count && !vor__slot_empty(&d->triangles[slot]);
    }
    return slot < extra_end(d);
}

/* The site's triangles around it from its home slot, counted; 0 when the
 * fan does not close within `limit` steps or leaves the site. */
static uint32_t fan_size(const vor_t *d, uint32_t start, vor_index_t site, uint32_t limit)
{
    uint32_t slot = start, count = 0;
    do {
        const vor__tri_t *t = &d->triangles[slot];
        unsigned i = vor__vertex_index(t, site);
        if (i == 3u || count == limit) {
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
static uint32_t boundary_after(const vor_t *d, uint32_t slot, vor_index_t b)
{
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
    uint32_t end = extra_end(d), reported = 0, boundary = 0;
    for (uint32_t slot = next_used_slot(d, 0); slot < end; slot = next_used_slot(d, slot + 1u)) {
        const vor__tri_t *t = &tri[slot];
        if (!vor__reported(s, t)) {
            continue;
        }
        vor_index_t v[3];
        vor__vertices(t, v);
        if (vor_orient2d(&s[v[0]], &s[v[1]], &s[v[2]], NULL) <= 0) {
            return violation(out, VOR_CHECK_TRUE_OUTPUT, slot, v[0]);
        }
        reported++;
        for (unsigned i = 0; i < 3u; i++) {
            if (vor__reported(s, &tri[t->n[i]])) {
                continue;
            }
            /* a boundary edge a -> b: the boundary turns left (or goes
             * straight on, past a hull site) at b */
            vor_index_t a = v[vor__next(i)], b = v[vor__prev(i)];
            uint32_t c = boundary_after(d, slot, b);
            if (c == VOR__INFINITE || c == a || vor_orient2d(&s[a], &s[b], &s[c], NULL) < 0) {
                return violation(out, VOR_CHECK_TRUE_OUTPUT, slot, b);
            }
            boundary++;
        }
    }
    uint32_t v = d->vertex_count;
    if (reported != 0u && reported + boundary + 2u != 2u * v) {
        return violation(out, VOR_CHECK_TRUE_OUTPUT, 0, v);
    }
    uint32_t ends = 0;
    for (uint32_t site = 0; site < d->site_count; site++) {
        if (vor__slot_empty(&tri[site])) {
            continue;
        }
        vor_neighbour_iter_t it;
        uint32_t n, degree = 0;
        vor__fan_begin(&it, d, site);
        while (vor__true_neighbour_next(&it, &n)) {
            degree++;
        }
        if (degree == 0u || (reported == 0u && degree > 2u)) {
            return violation(out, VOR_CHECK_TRUE_OUTPUT, site, site);
        }
        ends += degree;
    }
    if (ends != ((reported != 0u) ? 3u * reported + boundary : 2u * (v - 1u))) {
        return violation(out, VOR_CHECK_TRUE_OUTPUT, 0, v);
    }
    return VOR_OK;
}

int vor_validate(const vor_t *d, vor_violation_t *out)
{
    if (d == NULL) {
        return VOR_ERR_ARG;
    }
    const vor__tri_t *tri = d->triangles;
    uint32_t triangles = vor__triangle_count(d->vertex_count);
    uint32_t end = extra_end(d);

    /* counts: the used slots are exactly 2v - 2 (none below two sites) */
    if (d->vertex_count > d->site_count || d->site_count > d->max_sites) {
        return violation(out, VOR_CHECK_COUNTS, 0, d->vertex_count);
    }
    if (d->vertex_count < 2u) {
        return VOR_OK;
    }
    uint32_t used = 0, present = 0;
    for (uint32_t s = 0; s < d->site_count; s++) {
        present += vor__slot_empty(&tri[s]) ? 0u : 1u;
    }
    used = present + (end - d->max_sites);
    if (used != triangles || present != d->vertex_count) {
        return violation(out, VOR_CHECK_COUNTS, 0, d->vertex_count);
    }

    /* vertices: sites in the mesh or infinity, three distinct */
    for (uint32_t s = next_used_slot(d, 0); s < end; s = next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t v = vor__vertex(t, i);
            if (v != VOR__INFINITE &&
                (v >= d->site_count || vor__slot_empty(&tri[v]))) {
                return violation(out, VOR_CHECK_VERTICES, s, v);
            }
        }
        if (vor__vertex(t, 0) == vor__vertex(t, 1) || vor__vertex(t, 1) == vor__vertex(t, 2) ||
            vor__vertex(t, 2) == vor__vertex(t, 0)) {
            return violation(out, VOR_CHECK_VERTICES, s, vor__vertex(t, 1));
        }
    }

    /* neighbours: in use, pointing back across the same edge */
    for (uint32_t s = next_used_slot(d, 0); s < end; s = next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        for (unsigned i = 0; i < 3u; i++) {
            vor_index_t u = t->n[i];
            vor_index_t a = vor__vertex(t, vor__next(i)), b = vor__vertex(t, vor__prev(i));
            if (u == VOR__NONE || !slot_in_use(d, u)) {
                return violation(out, VOR_CHECK_NEIGHBOURS, s, a);
            }
            const vor__tri_t *o = &tri[u];
            unsigned ia = vor__vertex_index(o, a), ib = vor__vertex_index(o, b);
            /* in o the edge runs b -> a, and o's neighbour across it is t */
            if (ia == 3u || ib == 3u || vor__next(ib) != ia ||
                o->n[vor__next(ia)] != s) {
                return violation(out, VOR_CHECK_NEIGHBOURS, s, a);
            }
        }
    }

    /* sites: each site's home slot holds one of its triangles, and its
     * triangles form one fan; all fans together cover each triangle once
     * per corner */
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
    uint32_t ghost = next_used_slot(d, 0);
    while (ghost < end && !vor__is_ghost(&tri[ghost])) {
        ghost = next_used_slot(d, ghost + 1u);
    }
    corners += (ghost < end) ? fan_size(d, ghost, VOR__INFINITE, triangles) : 0u;
    if (corners != 3u * triangles) {
        return violation(out, VOR_CHECK_SITES, 0, VOR__INFINITE);
    }

    /* the query index: a box around every site, buckets naming sites */
    for (uint32_t s = 0; s < d->site_count; s++) {
        const vor_point_t *p = &d->sites[s];
        if (!vor__slot_empty(&tri[s]) && (p->x < d->low.x || p->x > d->high.x ||
                                          p->y < d->low.y || p->y > d->high.y)) {
            return violation(out, VOR_CHECK_BUCKETS, s, s);
        }
    }
    uint64_t buckets = vor__mul_u32(d->bucket_columns, d->bucket_rows);
    if (buckets == 0u || buckets > VOR_BUCKETS(d->max_sites)) {
        return violation(out, VOR_CHECK_BUCKETS, 0, VOR__INFINITE);
    }
    for (uint32_t b = 0; b < (uint32_t)buckets; b++) {
        vor_index_t s = d->buckets[b];
        if (s >= d->site_count || vor__slot_empty(&tri[s])) {
            return violation(out, VOR_CHECK_BUCKETS, b, s);
        }
    }

    /* geometry: the exact perturbed predicates, uncounted, so validation
     * never changes the diagram (nor lies in fault injection builds) */
    for (uint32_t s = next_used_slot(d, 0); s < end; s = next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &tri[s];
        if (!vor__is_ghost(t) &&
            vor_orient2d_sos(d->sites, vor__vertex(t, 0), vor__vertex(t, 1), vor__vertex(t, 2),
                             NULL) < 0) {
            return violation(out, VOR_CHECK_ORIENTATION, s, vor__vertex(t, 0));
        }
    }
    for (uint32_t s = next_used_slot(d, 0); s < end; s = next_used_slot(d, s + 1u)) {
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
    return check_true_output(d, out);
}

/* ------------------------------------------------------------------ */
/* Memory and iteration                                                */

/* numerator / denominator by shift and subtract: Cortex-M0 has no divide
 * instruction and the library calls no runtime routine. 64 steps, each
 * moving the numerator's top bit into the remainder and one quotient bit
 * in at the bottom (shifts by constants only: no shift routine either). */
static uint64_t divide(uint64_t numerator, uint64_t denominator)
{
    uint64_t quotient = 0, remainder = 0;
    for (unsigned step = 0; step < 64u; step++) {
        remainder = (remainder << 1) | (numerator >> 63);
        numerator <<= 1;
        quotient <<= 1;
        if (remainder >= denominator) {
            remainder -= denominator;
            quotient |= 1u;
        }
    }
    return quotient;
}

int vor_memory(const vor_t *d, vor_memory_t *memory)
{
    if (d == NULL || memory == NULL) {
        return VOR_ERR_ARG;
    }
    uint32_t triangles = vor__triangle_count(d->vertex_count);
    memory->arena_bytes = VOR_ARENA_BYTES(d->max_sites);
    uint32_t buckets = (d->vertex_count >= 2u) ? d->bucket_columns * d->bucket_rows : 0u;
    memory->used_bytes = (size_t)d->site_count * sizeof(vor_point_t) +
                         (size_t)triangles * VOR_TRIANGLE_BYTES +
                         (size_t)buckets * sizeof(vor_index_t);
    memory->sites = d->site_count;
    memory->triangles = triangles;
    memory->bytes_per_site_x100 =
        (d->site_count == 0u)
            ? 0u
            : (uint32_t)divide(memory->used_bytes * 100u + d->site_count / 2u,
                               d->site_count); /* size_t: a native multiply */
    return VOR_OK;
}

void vor_triangles_begin(vor_triangle_iter_t *it, const vor_t *d)
{
    if (it == NULL) {
        return;
    }
    it->d = d;
    it->next_slot = 0;
}

int vor_triangles_next(vor_triangle_iter_t *it, uint32_t ids[3])
{
    /* a zeroed iterator, or one begun on no diagram, is at its end */
    if (it == NULL || it->d == NULL || ids == NULL) {
        return 0;
    }
    const vor_t *d = it->d;
    if (d->vertex_count < 2u) {
        return 0;
    }
    uint32_t end = extra_end(d);
    /* each used slot is visited once; the loop ends at `end` */
    for (uint32_t s = next_used_slot(d, it->next_slot); s < end;
         s = next_used_slot(d, s + 1u)) {
        const vor__tri_t *t = &d->triangles[s];
        if (s + 4u < end) {
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
