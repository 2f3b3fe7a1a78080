/* SPDX-License-Identifier: MIT */
/*
 * mesh.c - the diagram object: arena layout, the first edge and the
 * start every builder shares, and memory figures. Topology only: the
 * builders (incremental.c, divide_conquer.c, dynamic.c) change the mesh
 * with the predicates, queries.c reads and validates it.
 */
#include "mesh.h"
#include "motion.h"

int vor_init_checked(vor_t *d, void *arena, size_t arena_bytes, uint32_t max_sites,
                     uint32_t config)
{
    if (config != VOR_CONFIG_FINGERPRINT) {
        return VOR_ERR_CONFIG; /* *d and the arena are laid out differently */
    }
    if ((d == NULL) || (arena == NULL) || (max_sites == 0u) || (max_sites > VOR_MAX_SITES)) {
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
    d->low.x = 0;
    d->low.y = 0;
    d->high.x = 0;
    d->high.y = 0;
    d->bucket_origin.x = 0;
    d->bucket_origin.y = 0;
    d->bucket_columns = 0;
    d->bucket_rows = 0;
    d->bucket_scale = 0;
    d->bucket_rebuild_at = 2;
    /* moved on, never reset: a tracker begun before this call must not
     * find its revision again after the rebuild. Read even from an
     * uninitialised *d: a uint32_t has no trap representation, and any
     * first value will do (no tracker can have seen a diagram there). */
    d->revision++;
    d->free_site = 0;
    d->motion = NULL; /* a cache is attached afterwards (vor_motion_attach) */
    d->motion_update = NULL;
    d->cdt = NULL; /* constraint memory is attached afterwards (vor_cdt_attach) */
    d->cdt_update = NULL;
    d->cdt_predicate = NULL;
    d->motion_epoch = 0;
#if VOR_STATS
    vor__stats_clear(&d->stats);
#endif
#ifdef VOR_FAULT_INJECTION
    d->fault_rate = 0;
    d->fault_state = 1;
#endif
    return VOR_OK;
}

/* ------------------------------------------------------------------ */
/* What the builders share                                             */

void vor__make_edge(vor_t *d, uint32_t a, uint32_t b)
{
    vor__tri_t *tri = d->triangles;
    vor_index_t sa = (vor_index_t)a;
    vor_index_t sb = (vor_index_t)b;
    /* fresh slots: clear any mark bits left by earlier contents */
    vor__tri_fresh(&tri[a]);
    vor__tri_fresh(&tri[b]);
    vor__tri_set(&tri[a], sa, sb, VOR__INFINITE, sb, sb, sb);
    vor__tri_set(&tri[b], sb, sa, VOR__INFINITE, sa, sa, sa);
}

int vor__build_start(vor_t *d, const vor_point_t *points, uint32_t n,
                     uint32_t *duplicate_of)
{
    if ((d == NULL) || ((points == NULL) && (n > 0u))) {
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
        if ((n == 1u) && (duplicate_of != NULL)) {
            duplicate_of[0] = 0;
        }
        if (d->cdt_update != NULL) {
            (void)d->cdt_update(d, VOR_NO_HINT, VOR__CDT_REBUILT);
        }
        return VOR_OK;
    }
    return VOR__BUILD_MESH;
}


/* ------------------------------------------------------------------ */
/* Memory                                                              */

/* numerator / denominator by shift and subtract: Cortex-M0 has no divide
 * instruction and the library calls no runtime routine. 64 steps, each
 * moving the numerator's top bit into the remainder and one quotient bit
 * in at the bottom (shifts by constants only: no shift routine either). */
static uint64_t divide(uint64_t numerator_in, uint64_t denominator)
{
    uint64_t numerator = numerator_in;
    uint64_t quotient = 0;
    uint64_t remainder = 0;
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

int vor_stats(const vor_t *d, vor_stats_t *out)
{
#if VOR_STATS
    if ((d == NULL) || (out == NULL)) {
        return VOR_ERR_ARG;
    }
    vor__stats_copy(out, &d->stats);
    return VOR_OK;
#else
    (void)d;
    (void)out;
    return VOR_ERR_ARG; /* no counters in this build */
#endif
}

int vor_memory(const vor_t *d, vor_memory_t *memory)
{
    if ((d == NULL) || (memory == NULL)) {
        return VOR_ERR_ARG;
    }
    uint32_t triangles = vor__triangle_count(d->vertex_count);
    memory->arena_bytes = VOR_ARENA_BYTES(d->max_sites);
    uint32_t buckets = (d->vertex_count >= 2u) ? (d->bucket_columns * d->bucket_rows) : 0u;
    memory->used_bytes = (size_t)d->site_count * sizeof(vor_point_t) +
                         (size_t)triangles * VOR_TRIANGLE_BYTES +
                         (size_t)buckets * sizeof(vor_index_t);
    memory->sites = d->site_count;
    memory->triangles = triangles;
    memory->bytes_per_site_x100 =
        (d->site_count == 0u)
            ? 0u
            : (uint32_t)divide((memory->used_bytes * 100u) + (d->site_count / 2u),
                               d->site_count); /* size_t: a native multiply */
    return VOR_OK;
}

