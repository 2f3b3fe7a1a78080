/* SPDX-License-Identifier: MIT */
/*
 * vor_config.h - build-time configuration of vor.
 *
 * Every option has a default here. Override any of them with -D on the
 * compiler command line, or put your overrides in a header of your own and
 * build with -DVOR_CONFIG_HEADER='"my_vor_config.h"'; that header is read
 * first, so whatever it defines wins.
 */
#ifndef VOR_CONFIG_H
#define VOR_CONFIG_H

#ifdef VOR_CONFIG_HEADER
#include VOR_CONFIG_HEADER
#endif

/* VOR_ASSERT(x): internal consistency checks. Off (compiled out) by
 * default; tests build with it mapped to a trap. It never guards against
 * bad caller input: that is reported with error codes. */
#ifndef VOR_ASSERT
#define VOR_ASSERT(x) ((void)0)
#endif

/* VOR_LIMB_BITS: the word of the multi-word integer arithmetic behind the
 * exact predicates. 64 where the compiler has a native 64x64->128 multiply
 * (unsigned __int128, e.g. x86-64 and AArch64 gcc/clang), else 32. Both give
 * identical results; 32 is always available. */
#ifndef VOR_LIMB_BITS
#if defined(__SIZEOF_INT128__)
#define VOR_LIMB_BITS 64
#else
#define VOR_LIMB_BITS 32
#endif
#endif

/* VOR_INDEX_BITS: width of site and triangle indices, 16 or 32. 16 for up
 * to 32,767 sites, 32 for up to 2,097,150 sites at about half as much
 * again per site (VOR_ARENA_BYTES; docs/porting.md and docs/benchmarks.md
 * have the bytes). Default: 16 on every machine, so that a host
 * simulation sizes its arena as the firmware does; host programs with
 * more sites define it as 32. */
#ifndef VOR_INDEX_BITS
#define VOR_INDEX_BITS 16
#endif

/* VOR_SITES_PER_BUCKET: the density of the bucket grid that starts
 * queries without a hint: VOR_BUCKETS(n) = ceil(n / VOR_SITES_PER_BUCKET)
 * site ids in the arena. Fewer sites per bucket: shorter walks for cold
 * queries, more memory (4 / VOR_SITES_PER_BUCKET bytes per site with
 * 32-bit ids, half that with 16-bit ones). A power of two keeps the
 * macro's division a shift. At 4, cold queries at 10^5 and 10^6 sites
 * keep pace with a kd-tree; 16 saves memory for walks about twice as long
 * (docs/benchmarks.md has both). */
#ifndef VOR_SITES_PER_BUCKET
#define VOR_SITES_PER_BUCKET 4u
#endif

/* VOR_TRACKER_EDGES: the most Voronoi edges a vor_tracker_t caches for
 * the cell it is in (16 bytes each). A cell with more edges is still
 * answered exactly, through vor_nearest, just not from the cache. Cells of
 * uniform sites have 6 edges on average and rarely more than 10. */
#ifndef VOR_TRACKER_EDGES
#define VOR_TRACKER_EDGES 12
#endif

/* VOR_STATS: 1 counts the predicate evaluations of every diagram by tier
 * (vor_stats_t in vor_t, read with vor_stats), for benchmarks and tests;
 * 0 (the default) has no counter in vor_t and none on any path. The
 * counters decide nothing; a call that fails restores them, as it
 * restores everything else. */
#ifndef VOR_STATS
#define VOR_STATS 0
#endif

/* VOR_FAULT_INJECTION: test builds only. The perturbed predicates that the
 * diagram uses return a wrong sign with a probability set per diagram
 * (vor_t's fault_rate), to show that the topology survives any
 * arithmetic. Never define it in a release build. */

/* The configuration contract. The options above that change a size or a
 * layout the application sees (VOR_INDEX_BITS: vor_index_t, the arena;
 * VOR_SITES_PER_BUCKET: VOR_ARENA_BYTES; VOR_TRACKER_EDGES:
 * vor_tracker_t; VOR_STATS and VOR_FAULT_INJECTION: fields of vor_t)
 * are packed into VOR_CONFIG_FINGERPRINT with the layout version of the
 * public structures. vor_init and vor_tracker_begin are inline wrappers
 * that hand the application's fingerprint to the library, which returns
 * VOR_ERR_CONFIG, touching nothing, when it was compiled with another.
 * VOR_ASSERT and VOR_LIMB_BITS change only the library's code: not part
 * of it. Bump VOR_LAYOUT_VERSION whenever a public structure changes. */
#define VOR_LAYOUT_VERSION 5u

#if VOR_SITES_PER_BUCKET < 1 || VOR_SITES_PER_BUCKET > 2047
#error "VOR_SITES_PER_BUCKET must be 1 .. 2047"
#endif
#if VOR_TRACKER_EDGES < 1 || VOR_TRACKER_EDGES > 2047
#error "VOR_TRACKER_EDGES must be 1 .. 2047"
#endif

#if VOR_STATS != 0 && VOR_STATS != 1
#error "VOR_STATS must be 0 or 1"
#endif

#ifdef VOR_FAULT_INJECTION
#define VOR__CONFIG_FAULTS 1u
#else
#define VOR__CONFIG_FAULTS 0u
#endif

/* One bit per choice, 11 bits per count (exact within the ranges above),
 * 7 bits of layout version:
 * two configurations have the same fingerprint only when they agree. */
#define VOR_CONFIG_FINGERPRINT                                                 \
    ((uint32_t)(((uint32_t)VOR_LAYOUT_VERSION << 25) |                         \
                ((uint32_t)((VOR_INDEX_BITS == 32) ? 1u : 0u) << 24) |         \
                ((uint32_t)VOR__CONFIG_FAULTS << 23) |                         \
                ((uint32_t)(VOR_STATS) << 22) |                                \
                ((uint32_t)(VOR_SITES_PER_BUCKET) << 11) |                     \
                (uint32_t)(VOR_TRACKER_EDGES)))

#endif
