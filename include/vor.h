/* SPDX-License-Identifier: MIT */
/*
 * vor.h - exact Voronoi diagrams and Delaunay triangulations for
 * microcontrollers. Freestanding C99: no malloc, no libc, no floating point,
 * no global state. All memory belongs to the caller.
 *
 * COORDINATES
 *   Sites are int32_t points over the whole range [INT32_MIN, INT32_MAX].
 *   Map fixed-point or float inputs to integers before calling vor
 *   ("integer reduction"): e.g. metres in Q16.16 are already int32.
 *
 * EXACT PREDICATES
 *   Every geometric decision in vor is one of these signs, computed exactly
 *   with multi-word integers. Points are passed by value (vor_point_t), as
 *   in every call of the library, so no answer can stand for an error:
 *
 *     vor_orient2d(a, b, c)     > 0  a, b, c turn counterclockwise
 *                               = 0  collinear
 *                               < 0  clockwise
 *     vor_incircle(a, b, c, d)  > 0  d inside the circle through a, b, c
 *                                    (a, b, c counterclockwise)
 *                               = 0  cocircular
 *     vor_closer(q, a, b)       sign of |q-a|^2 - |q-b|^2:
 *                               < 0  q is strictly closer to a than to b
 *
 *   and for weighted points (an int64 weight w each, the power diagram's:
 *   the power distance of q to (p, w) is |q-p|^2 - w):
 *
 *     vor_power_test(a, wa, .., d, wd)  > 0  d conflicts with a, b, c
 *                               (the incircle test with each x^2 + y^2
 *                               less its weight; equal weights: incircle)
 *     vor_power_closer(q, a, wa, b, wb) sign of (|q-a|^2 - wa)
 *                               - (|q-b|^2 - wb)
 *
 *   Each call evaluates in the narrowest width that is provably exact for
 *   its operands (a "tier"): int64 when the coordinate differences are
 *   small, 128-bit products when they fit int32, and full multi-word width
 *   (133-bit results for incircle) otherwise. The widths are fixed by
 *   bounds, not by error estimates, so there is no fallback that could
 *   miss: every result is exact. A build with VOR_STATS (vor_config.h;
 *   benchmarks and tests) counts the tiers a diagram's calls ran, read
 *   with vor_stats.
 *
 * SYMBOLIC PERTURBATION
 *   The _sos variants ("simulation of simplicity") never return 0 for valid
 *   arguments. They take an array of sites and indices into it; site i is
 *   treated as if it were moved to
 *
 *       (x_i + eps^(4 * 16^i),  y_i + eps^(16^i))
 *
 *   for an infinitesimal eps > 0, and the sign of the moved configuration is
 *   returned. When the exact sign is not 0 the two agree. Otherwise the tie
 *   is broken by a fixed order on indices: a smaller index is moved further
 *   (it dominates), and y before x. Both predicates use the same moved
 *   points, so all their answers are consistent with one configuration in
 *   general position: collinear and cocircular inputs need no special case.
 *   vor_power_test_sos moves the sites the same way and keeps the weights.
 *   Only the order of the indices matters, never their values.
 *   Identical points with different indices are separated too, but the
 *   diagram builders report them as duplicates instead of relying on it.
 *   Since 0 is never an answer, it is the _sos calls' one error value (a
 *   NULL array, two equal indices).
 *
 * THE DIAGRAM
 *   A vor_t holds the Delaunay triangulation of its sites (the dual of
 *   their Voronoi diagram) in one arena the caller provides:
 *
 *       static uint8_t arena[VOR_ARENA_BYTES(500)]    // 4-aligned
 *           __attribute__((aligned(4)));
 *       vor_t d;
 *       vor_init(&d, arena, sizeof arena, 500);       // or VOR_ERR_*
 *       vor_build(&d, points, n, NULL, duplicate_of); // site i = points[i]
 *       vor_point_t p = {x, y};
 *       vor_insert(&d, p, &id);                       // one more site
 *       vor_move(&d, id, p2, NULL);                   // same id, new place
 *       vor_motion_attach(&d, cache, sizeof cache);   // cheap small moves
 *       vor_remove(&d, id);                           // id freed for reuse
 *       vor_nearest(&d, q, VOR_NO_HINT, &id);         // exact, ties to smaller id
 *       vor_nearest_k(&d, q, hint, k, ids, &found);   // k nearest, in order
 *       vor_locate(&d, q, hint, tri);                 // the triangle holding q
 *                                                     // (or VOR_ERR_OUTSIDE)
 *       vor_within(&d, q, r2, hint, ids, cap, &m);    // sites within r2, by id
 *       vor_triangles_export(&d, t, twins, cap, &m);  // delaunator's flat arrays
 *
 *       vor_tracker_t robot;                          // a moving query point:
 *       vor_tracker_begin(&robot, &d);                // caches its current cell
 *       vor_track(&robot, r, &id);                    // a few multiplies a cell edge
 *
 *   THE CONVENTIONS, the same for every call:
 *   - Points are vor_point_t values; ids are uint32_t; outputs go through
 *     pointers given last.
 *   - Every call returns VOR_OK or a negative enum vor_error, and a failing
 *     call changes nothing.
 *   - Options are a const pointer to an options struct (vor_build_options_t,
 *     vor_raster_options_t): NULL, or a zero-initialised struct, means the
 *     defaults, and a field added later keeps the old behaviour at 0.
 *   - Iterators: x_begin returns VOR_OK or VOR_ERR_ARG (the iterator is
 *     then closed); x_next returns 1 with an item or 0 at the end, never an
 *     error, so `while (x_next(&it, ...))` always ends. The cell iterator
 *     keeps why it stopped: vor_cells_error.
 *
 *   Nothing is allocated: VOR_ARENA_BYTES(n) is the whole memory of n
 *   sites (Euler: 2n - 2 triangles), a compile-time constant, the same on
 *   a 64-bit host as on a microcontroller (16-bit ids unless
 *   VOR_INDEX_BITS says 32). Insertion is Sugihara and Iri's
 *   topology-oriented update: the structure stays a valid triangulation
 *   whatever the arithmetic does, and with these exact predicates it is
 *   the unique Delaunay triangulation under the perturbation. vor_validate checks every
 *   invariant. The iterators list the true Delaunay triangulation of the
 *   distinct sites, not that perturbed mesh: 2n - h - 2 triangles, none of
 *   zero area (none at all for collinear sites), and neighbours whose
 *   cells touch. A query without a hint starts from a coarse bucket grid
 *   kept in the arena (one site id per VOR_SITES_PER_BUCKET sites), so
 *   it takes O(1) expected steps on uniform sites.
 *   vor_remove and vor_move keep the diagram exactly that of the current
 *   sites (the triangles a fresh build of them in id order gives) and the
 *   same topological guarantee (removal's edge guard, which exact signs
 *   provably never need, is compiled only where signs can be made to lie:
 *   the fault-injection test builds); removed ids are reused, most
 *   recently freed first. Across a change: a vor_tracker_t sees d->revision move
 *   and searches afresh (from the bucket grid, never from a stale site);
 *   a hint must be a site still in the mesh (else VOR_ERR_ARG); iterators
 *   must not outlive a change (begin them again).
 *
 * VORONOI GEOMETRY
 *   The geometry of the true Voronoi diagram of the distinct sites is read
 *   from the mesh, exactly: vertices are circumcentres computed as
 *   multi-word rationals and rounded only on output (to the nearest
 *   integer, halves toward +infinity; outside int32 flagged, never
 *   wrapped); degenerate sites give no zero-length edges.
 *
 *       vor_edges_begin(&ei, &d);                    // segments, rays, lines
 *       while (vor_edges_next(&ei, &edge)) { ... }
 *       vor_box_t box = {0, 0, 1000, 1000};
 *       vor_cell(&d, id, &box, poly, VOR_CELL_MAX_VERTICES(500), &m);
 *       vor_hull_begin(&hi, &d);                     // hull sites, CCW
 *
 *   A cell is clipped to the caller's box, counterclockwise, into the
 *   caller's buffer (VOR_ERR_BUFFER and the size needed when it is too
 *   small: nothing is written). For Lloyd relaxation, a clipped cell's
 *   area and centroid, exact and rounded once, in caller scratch:
 *
 *       static uint8_t scratch[VOR_CENTROID_SCRATCH_BYTES(32)];
 *       vor_cell_centroid(&d, id, &box, scratch, sizeof scratch, &c);
 *
 *   Rooms that are not boxes: a cell clipped to any simple polygon, its
 *   pieces (a non-convex room can cut a cell in several) with exact
 *   rational vertices, and their area and centroid (vor_clip_begin,
 *   vor_clip_next, vor_clip_centroid; VOR_ERR_POLYGON for a room that
 *   crosses itself). Order-K cells (the points whose K nearest sites are
 *   a given set) clipped the same way, and a walk over all the order-K
 *   cells of a room, which tile it (vor_order_cell_begin,
 *   vor_order_cells_begin, vor_order_cells_next).
 *
 * NATURAL-NEIGHBOUR INTERPOLATION
 *   Sibson's coordinates of a point q (the areas its cell would take from
 *   its natural neighbours' cells) and Laplace's (edge length over
 *   distance), exact rationals over one denominator, and the interpolant
 *   of int32 site values, exact and rounded once (halves away from zero):
 *
 *       static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(16)];
 *       vor_interpolate(&d, values, q, VOR_NO_HINT, scratch, sizeof scratch, &v);
 *       vor_sibson(&d, q, hint, scratch, sizeof scratch, &coordinates);
 *
 *   At a site its value, on a hull edge the linear interpolation of its
 *   ends, outside the hull VOR_ERR_OUTSIDE; cocircular sites give the one
 *   true answer.
 *
 * COST
 *   No predicate allocates, recurses or loops over data. A degenerate input
 *   to an _sos predicate evaluates at most 5 (orient2d) or 27 (incircle)
 *   small determinants; typical degeneracies are decided by the first one.
 *   Building n uniform sites takes expected O(n) time. docs/benchmarks.md
 *   has the measured times and instruction counts.
 *
 * FLASH
 *   A firmware linked with --gc-sections keeps only what it calls. The
 *   divide-and-conquer builder is its own entry point, vor_build_dc, so
 *   vor_build does not pull it in; the geometry (edges, cells, hull) and
 *   the interpolation (vor_sibson, vor_laplace, vor_interpolate) are
 *   linked only when called. vor_build_dc_forked runs it on two cores
 *   through a caller's fork/join hook (pthreads, or a dual-core
 *   microcontroller's second core): the library itself stays
 *   single-threaded. docs/benchmarks.md, "Code size and stack", has the
 *   bytes of each feature set.
 *
 * CONFIGURATION: vor_config.h.  DESIGN: docs/design.md.  API: docs/api.md.
 */
#ifndef VOR_H
#define VOR_H

#include <stddef.h>
#include <stdint.h>

#include "vor_config.h"

/* The library's version (semantic versioning; CHANGELOG.md says what each
 * release changed). The three numbers are the one place that sets it:
 * VOR_VERSION_STRING is made from them, and the CMake package, the
 * manifests' check and the CLI's --version read them from here.
 * docs/api.md, "Compatibility", says what a minor and a major release may
 * change. */
#define VOR_VERSION_MAJOR 1
#define VOR_VERSION_MINOR 0
#define VOR_VERSION_PATCH 0
#define VOR__STRINGIFY(x) #x
#define VOR__VERSION_TEXT(major, minor, patch) \
    VOR__STRINGIFY(major) "." VOR__STRINGIFY(minor) "." VOR__STRINGIFY(patch)
#define VOR_VERSION_STRING \
    VOR__VERSION_TEXT(VOR_VERSION_MAJOR, VOR_VERSION_MINOR, VOR_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

/* A site or query point: integer coordinates over the full int32 range. */
typedef struct vor_point {
    int32_t x;
    int32_t y;
} vor_point_t;

/* The evaluation widths of the exact predicates, narrowest first. */
enum vor_tier {
    VOR_TIER_NARROW = 0, /* int64: small coordinate differences */
    VOR_TIER_MID = 1,    /* 128 bits (incircle only) */
    VOR_TIER_WIDE = 2,   /* full multi-word width */
    VOR_TIERS = 3
};

/* Per-tier predicate counters of a diagram, in builds with VOR_STATS
 * (vor_config.h; benchmarks and tests): read them with vor_stats. They
 * count every evaluation the diagram's successful calls make (a failing
 * call restores them, as it restores everything else; they wrap modulo
 * 2^32) and decide nothing: no result depends on them. */
typedef struct vor_stats {
    uint32_t orient2d[VOR_TIERS];
    uint32_t incircle[VOR_TIERS];
    uint32_t closer[VOR_TIERS];
    uint32_t orient2d_perturbed; /* perturbed calls decided by the perturbation */
    uint32_t incircle_perturbed;
    uint32_t closer_perturbed;  /* stays 0: no diagram call compares distances
                                   under the perturbation (kept: the layout) */
    uint32_t power;           /* power tests and comparisons of unequal weights */
    uint32_t power_perturbed; /* of those, the ties the perturbation decided */
} vor_stats_t;

/*
 * Exact sign (-1, 0 or 1) of det[[ax ay 1][bx by 1][cx cy 1]]:
 * positive when a, b, c turn counterclockwise (x right, y up).
 * Tiers: narrow when every coordinate difference fits in int32, else wide.
 * Never fails.
 */
int vor_orient2d(vor_point_t a, vor_point_t b, vor_point_t c);

/*
 * Exact sign of det of the rows (x, y, x^2 + y^2, 1) of a, b, c, d:
 * positive when d lies inside the circle through a, b, c and a, b, c are
 * counterclockwise (negated when they are clockwise), 0 when cocircular.
 * Tiers, by the coordinate differences to d: narrow when they lie in
 * [-2^14, 2^14 - 1], mid when they fit int32, else wide. Never fails.
 */
int vor_incircle(vor_point_t a, vor_point_t b, vor_point_t c, vor_point_t d);

/*
 * Exact sign of |q-a|^2 - |q-b|^2: -1 when q is strictly closer to a,
 * 1 when strictly closer to b, 0 on the bisector.
 * Tiers: narrow when every difference to q fits in int32, else wide.
 * Never fails.
 */
int vor_closer(vor_point_t q, vor_point_t a, vor_point_t b);

/*
 * vor_orient2d of sites[i], sites[j], sites[k] under the symbolic
 * perturbation described at the top of this file: -1 or 1, never 0.
 * i, j, k must be distinct (indices order the perturbation) and index
 * sites[]: 0, which is never an answer, means a bad argument: sites NULL
 * or two indices equal (an index past the array cannot be detected).
 */
int vor_orient2d_sos(const vor_point_t *sites, uint32_t i, uint32_t j, uint32_t k);

/*
 * vor_incircle of sites[i], sites[j], sites[k], sites[l] under the
 * symbolic perturbation: -1 or 1. Indices must be distinct: 0 (a bad
 * argument) when sites is NULL or two are equal.
 */
int vor_incircle_sos(const vor_point_t *sites, uint32_t i, uint32_t j, uint32_t k,
                     uint32_t l);

/*
 * vor_closer of sites[q], sites[a], sites[b] under the symbolic
 * perturbation: -1 (q~ closer to a~) or 1. Distinct indices: 0 (a bad
 * argument) when sites is NULL or two are equal. Used to find the site
 * nearest to a point that coincides with one.
 */
int vor_closer_sos(const vor_point_t *sites, uint32_t q, uint32_t a, uint32_t b);

/*
 * Power test: the exact sign of det of the rows (x, y, x^2 + y^2 - w, 1)
 * of the weighted points (a, wa), (b, wb), (c, wc), (d, wd): positive when
 * d is in conflict with the counterclockwise a, b, c (its power distance
 * to their orthogonal circle, |d - z|^2 - wd - r^2, is negative: the
 * triangle is not a triangle of the power diagram's dual once d is in),
 * negated for clockwise a, b, c, 0 when tied. With equal weights it is
 * vor_incircle. Every int32 coordinate and every int64 weight, exact:
 * equal weights take vor_incircle's tiers, others 192-bit sums. Adding
 * one constant to all four weights keeps the sign. Never fails.
 */
int vor_power_test(vor_point_t a, int64_t wa, vor_point_t b, int64_t wb, vor_point_t c,
                   int64_t wc, vor_point_t d, int64_t wd);

/*
 * vor_power_test of sites[i], .., sites[l] with weights[i], .., weights[l]
 * under the symbolic perturbation (the sites move as for vor_incircle_sos;
 * weights stay): -1 or 1. Distinct indices: 0 (a bad argument) when sites
 * or weights is NULL or two indices are equal.
 */
int vor_power_test_sos(const vor_point_t *sites, const int64_t *weights, uint32_t i,
                       uint32_t j, uint32_t k, uint32_t l);

/*
 * Exact sign of (|q-a|^2 - wa) - (|q-b|^2 - wb): -1 when q is strictly
 * closer to (a, wa) in power distance, 1 when strictly closer to (b, wb),
 * 0 when tied. Every int32 coordinate and int64 weight. Never fails.
 */
int vor_power_closer(vor_point_t q, vor_point_t a, int64_t wa, vor_point_t b, int64_t wb);


/* ================================================================== */
/* The diagram: Delaunay triangulation / Voronoi diagram in an arena  */
/* ================================================================== */

/* Errors: every call returns VOR_OK (0) or one of these, and a failing
 * call changes nothing (the diagram and arena are exactly as before). */
enum vor_error {
    VOR_OK = 0,
    VOR_ERR_ARG = -1,       /* a NULL pointer, an out-of-range value */
    VOR_ERR_NOMEM = -2,     /* the arena is smaller than VOR_ARENA_BYTES */
    VOR_ERR_ALIGN = -3,     /* the arena is not VOR_ARENA_ALIGN-aligned */
    VOR_ERR_FULL = -4,      /* max_sites sites are in the diagram already */
    VOR_ERR_DUPLICATE = -5, /* the point is a site already (its id is returned) */
    VOR_ERR_INVALID = -6,   /* vor_validate found a broken invariant */
    VOR_ERR_EMPTY = -7,     /* a query on a diagram without sites */
    VOR_ERR_BUFFER = -8,    /* the caller's buffer is too small (the size needed is returned) */
    VOR_ERR_CONFIG = -9,    /* library and application were compiled with different
                               vor_config.h options (VOR_CONFIG_FINGERPRINT) */
    VOR_ERR_STOPPED = -10,  /* vor_raster: the caller's flush asked to stop */
    VOR_ERR_CONSTRAINED = -11, /* vor_remove, vor_move: the site ends a constrained edge */
    VOR_ERR_OUTSIDE = -12,    /* vor_locate, vor_sibson, vor_interpolate: the point is
                                 outside the convex hull of the sites */
    VOR_ERR_POLYGON = -13     /* vor_clip_begin, vor_order_cell(s)_begin: the room is
                                 not a simple polygon */
};

#if VOR_INDEX_BITS == 16
typedef uint16_t vor_index_t;
#define VOR_MAX_SITES 32767u
#elif VOR_INDEX_BITS == 32
typedef uint32_t vor_index_t;
#define VOR_MAX_SITES 2097150u /* vertex ids are packed in 21 bits */
#else
#error "VOR_INDEX_BITS must be 16 or 32"
#endif

/* One triangle of the mesh: three vertices counterclockwise and the three
 * neighbours, neighbour i across the edge opposite vertex i. A vertex is a
 * site index or the vertex at infinity that closes the convex hull. 12
 * bytes with 16-bit indices; 20 with 32-bit ones (vertices packed in 21
 * bits each, neighbours in 32). */
#define VOR_TRIANGLE_BYTES ((VOR_INDEX_BITS == 16) ? 12u : 20u)

/* Buckets of the coarse grid that finds a starting site for a query
 * without a hint: one site id per VOR_SITES_PER_BUCKET sites (vor_config.h),
 * a constant expression. */
#define VOR_BUCKETS(n)                                                         \
    (((size_t)(n) + (VOR_SITES_PER_BUCKET - 1u)) / VOR_SITES_PER_BUCKET)

/* Arena bytes for a diagram of up to n sites (a constant expression):
 * the coordinates, one triangle for each of the 2n - 2 triangles a
 * triangulation of n sites has once the hull is closed by a vertex at
 * infinity (Euler's formula), and the bucket grid.
 * No other memory is used, and vor_build takes its scratch space from the
 * same arena. */
#define VOR_ARENA_BYTES(n)                                                     \
    (((size_t)(n) * sizeof(vor_point_t)) +                                     \
     ((((n) >= 2u) ? ((2u * (size_t)(n)) - 2u) : 0u) * VOR_TRIANGLE_BYTES) +   \
     (VOR_BUCKETS(n) * sizeof(vor_index_t)))

/* The arena's required alignment (a static uint8_t array needs
 * _Alignas(4) or __attribute__((aligned(4))); malloc's is enough). */
#define VOR_ARENA_ALIGN 4u

struct vor__triangle;
struct vor__motion_entry;
struct vor__cdt;

/* The diagram object: owned by the caller, fields private. */
typedef struct vor {
    vor_point_t *sites;                /* [max_sites], in the arena */
    struct vor__triangle *triangles;   /* [2 max_sites - 2], in the arena */
    uint32_t max_sites;
    uint32_t site_count;   /* site ids handed out: 0 .. site_count - 1 */
    uint32_t vertex_count; /* of those, the ones in the mesh (not duplicates) */
    uint32_t last_site;    /* where the next search starts by default */
    /* bounding box of the sites in the mesh */
    vor_point_t low;
    vor_point_t high;
    /* The bucket grid (queries without a hint start at the site of the
     * query's bucket): square buckets of side 2^32 / bucket_scale from
     * bucket_origin, bucket_columns x bucket_rows of them, row by row. */
    vor_index_t *buckets;  /* [VOR_BUCKETS(max_sites)], in the arena */
    vor_point_t bucket_origin;
    uint32_t bucket_columns;
    uint32_t bucket_rows;
    uint32_t bucket_scale;
    uint32_t bucket_rebuild_at; /* site count at which the grid is redrawn */
    uint32_t revision;     /* counts the changes: trackers notice them */
    uint32_t free_site;    /* the most recently freed id plus one (0: none),
                              head of the free ids' list, threaded through
                              their empty home slots */
#if VOR_STATS
    vor_stats_t stats;     /* predicate tiers of every call on it (vor_stats) */
#endif
#ifdef VOR_FAULT_INJECTION
    /* test builds: the perturbed predicates answer a wrong sign with
     * probability fault_rate / 2^32, drawn from fault_state (nonzero) */
    uint32_t fault_rate;
    uint64_t fault_state;
#endif
    /* The motion cache (vor_motion_attach), NULL when none, and the
     * 24-bit count of triangle changes its entries are stamped with. */
    struct vor__motion_entry *motion;
    uint32_t motion_epoch;
    /* The cache's upkeep after a slow vor_move, stored by
     * vor_motion_attach (NULL when none): reached only through this
     * pointer, so a firmware that attaches no cache links none of it. */
    void (*motion_update)(struct vor *d, uint32_t site, const vor_point_t *from, uint32_t epoch);
    /* The constrained triangulation (vor_cdt_attach, vor_cdt.h), NULL
     * when none, and its upkeep (src/cdt.h, the events), stored by the
     * attach so that a firmware without constraints links none of it. */
    struct vor__cdt *cdt;
    int (*cdt_update)(struct vor *d, uint32_t site, unsigned event);
    /* Set in the constrained triangulation's own mesh only (cdt.c): the
     * perturbed orientation (count 3) or incircle test (count 4) of
     * vertices that may be crossings, for the removal it shares. */
    int (*cdt_predicate)(struct vor *mesh, const uint32_t *ids, unsigned count);
} vor_t;

/*
 * Prepares d to hold up to max_sites sites in arena.
 *   VOR_ERR_CONFIG the library was compiled with other vor_config.h
 *                  options than this file (checked first)
 *   VOR_ERR_ARG    d or arena NULL, max_sites 0 or > VOR_MAX_SITES
 *   VOR_ERR_ALIGN  arena not aligned to VOR_ARENA_ALIGN
 *   VOR_ERR_NOMEM  arena_bytes < VOR_ARENA_BYTES(max_sites)
 * Writes only *d (never the arena), and nothing on failure. The arena
 * must stay valid and untouched by the caller while d is in use.
 * Reads one field of *d, d->revision, whatever it holds (uninitialised
 * memory is fine): the count moves on from it instead of restarting, so a
 * tracker begun on d before this call never answers for the new diagram
 * (it searches afresh, see vor_track). No design that reads nothing can
 * tell a rebuilt diagram from the old one at a tracker's cost.
 * vor_init_checked is the library's symbol: the inline vor_init passes
 * it the application's VOR_CONFIG_FINGERPRINT.
 */
int vor_init_checked(vor_t *d, void *arena, size_t arena_bytes, uint32_t max_sites,
                     uint32_t config);
static inline int vor_init(vor_t *d, void *arena, size_t arena_bytes, uint32_t max_sites)
{
    return vor_init_checked(d, arena, arena_bytes, max_sites, VOR_CONFIG_FINGERPRINT);
}

/*
 * Adds the site p; its id goes to *site (may be NULL): the most
 * recently freed id (vor_remove) if there is one, else the next unused. The search for its place starts at the last inserted site;
 * vor_insert_near starts at site `hint` instead (a site in the mesh, or
 * VOR_NO_HINT: the bucket grid's site near p, as vor_nearest).
 *   VOR_ERR_ARG        d NULL, or hint neither VOR_NO_HINT nor a site in
 *                      the mesh (an unused id, a duplicate's id)
 *   VOR_ERR_DUPLICATE  p is a site already: its id goes to *site
 *                      (also when the diagram is full)
 *   VOR_ERR_FULL       max_sites ids are used
 *   VOR_ERR_NOMEM      constraint memory is attached (vor_cdt.h), p lies
 *                      inside a constrained edge and the edge table has
 *                      no room for its split
 * On failure the diagram (and the constraint memory) is unchanged.
 * Cost: the walk from the hint plus O(changed triangles), O(1) expected for
 * a nearby hint; no recursion, no memory beyond the arena.
 */
int vor_insert(vor_t *d, vor_point_t p, uint32_t *site);
int vor_insert_near(vor_t *d, vor_point_t p, uint32_t hint, uint32_t *site);

/*
 * Removes site `site` from the diagram. The result is exactly the diagram
 * of the remaining sites: the triangles a fresh build of them in id order
 * gives (the perturbation breaks ties by id order). The other sites keep
 * their ids; `site` becomes free, and the next vor_insert reuses the most
 * recently freed id (ids beyond the free ones are handed out after them).
 * Ids vor_build gave to duplicates stay reserved: they are not sites.
 *   VOR_ERR_ARG          d NULL, or site not a site in the mesh (an
 *                        unused or free id, a duplicate's id from vor_build)
 *   VOR_ERR_CONSTRAINED  constraint memory is attached (vor_cdt.h) and a
 *                        constrained edge ends at site
 * On failure the diagram (and the constraint memory) is unchanged. The bounding box (vor_t low, high)
 * may stay larger than the remaining sites' box.
 * Cost: O(degree^3) predicates in the worst case, 13 on average on
 * uniform sites (degree 6), plus the removed site's run of the bucket
 * grid (a few entries on uniform sites).
 */
int vor_remove(vor_t *d, uint32_t site);

/*
 * Moves site `site` to p, keeping its id. When the triangles around
 * it stay counterclockwise and Delaunay (the common small step) only its
 * coordinates change; otherwise it is removed and inserted again. Either
 * way the result is the diagram a fresh build gives. Moving a site onto
 * its own position is VOR_OK and changes nothing.
 *   VOR_ERR_ARG        d NULL, or site not a site in the mesh (as for
 *                      vor_remove)
 *   VOR_ERR_DUPLICATE  p is another site: its id goes to *existing
 *                      (may be NULL)
 *   VOR_ERR_CONSTRAINED  constraint memory is attached (vor_cdt.h) and a
 *                      constrained edge ends at site
 *   VOR_ERR_NOMEM      constraint memory is attached, p lies inside a
 *                      constrained edge and the edge table has no room
 *                      for its split
 * On failure the diagram, the motion cache and the constraint memory are
 * unchanged.
 * Cost: with a motion cache attached (vor_motion_attach), a move inside
 * the site's box only stores the coordinates and evaluates no predicate.
 * Otherwise the predicates of the site's star (about 18 on uniform sites)
 * prove the triangles unchanged (with a cache, sizing the site's new box
 * costs more, which a backoff skips at a site's first such move and after
 * boxes of no use), or it costs a removal and an insertion.
 * docs/benchmarks.md has the instruction counts of each path.
 */
int vor_move(vor_t *d, uint32_t site, vor_point_t p, uint32_t *existing);

/*
 * The motion cache: optional caller memory that makes small moves cheap.
 * Per site it keeps a box around the site's position (its anchor) in
 * which the site may move, with every other site anywhere in its own box,
 * without any triangle changing; a vor_move that stays in the site's box
 * then only stores the coordinates, with no predicate at all (docs/design/dynamic.md,
 * "Small moves"). A move outside the box, or of a site without one, is
 * checked in full and may give the site a new box: not at its first such
 * move since the attach (a site moved once never pays for a box), nor
 * for a while after its box went unused or could not hold its step. Any change of the
 * triangles (vor_insert, vor_remove, vor_build, vor_build_dc, a move that
 * changes triangles) voids every box at O(1) cost.
 *
 *     static uint8_t cache[VOR_MOTION_BYTES(500)] __attribute__((aligned(4)));
 *     vor_motion_attach(&d, cache, sizeof cache);  // after vor_init
 *
 * VOR_MOTION_BYTES(n) is a constant expression: 12 bytes a site, apart
 * from the arena (VOR_ARENA_BYTES does not change). vor_move reaches the
 * cache's code only through what vor_motion_attach stores in d, so a
 * firmware that never attaches a cache links none of it.
 */
#define VOR_MOTION_ENTRY_BYTES 12u
#define VOR_MOTION_BYTES(n) ((size_t)(n) * VOR_MOTION_ENTRY_BYTES)
#define VOR_MOTION_ALIGN 4u

/*
 * Attaches the motion cache mem[0 .. bytes) to d (initialised with
 * vor_init), replacing any attached one; mem NULL with bytes 0 detaches
 * it. The cache starts empty (every site without a box). vor_build and
 * vor_build_dc keep the attachment (emptied); vor_init drops it. The
 * memory must stay valid and untouched by the caller while attached.
 *   VOR_ERR_ARG    d NULL, or mem NULL with bytes > 0
 *   VOR_ERR_ALIGN  mem not aligned to VOR_MOTION_ALIGN
 *   VOR_ERR_NOMEM  bytes < VOR_MOTION_BYTES(max_sites of d)
 * On failure nothing changes (d keeps its cache, mem is not written).
 * Cost: O(max_sites) to empty the memory.
 */
int vor_motion_attach(vor_t *d, void *mem, size_t bytes);

/* The order in which vor_build inserts the sites. */
enum vor_order {
    VOR_ORDER_QUADTREE = 0, /* Ohya, Iri and Murota's bucket order */
    VOR_ORDER_INPUT = 1     /* as given (a baseline for benchmarks) */
};

/* How vor_build_dc and vor_build_dc_forked split the sites. */
enum vor_dc_split {
    VOR_DC_QUADTREE = 0, /* buckets merged in quadtree order (Katajainen and
                            Koppinen): expected O(n) for uniform points */
    VOR_DC_XSPLIT = 1    /* the classical halving by x, O(n log n) */
};

/* The options of the builders, shared by vor_build, vor_build_dc and
 * vor_build_dc_forked (each reads the fields it uses). A NULL pointer or a
 * zero-initialised struct means the defaults, and so does 0 in any field:
 *
 *     vor_build_options_t o = {0};
 *     o.split = VOR_DC_XSPLIT;
 *     vor_build_dc(&d, points, n, &o, NULL);
 */
typedef struct vor_build_options {
    enum vor_order order;     /* vor_build: VOR_ORDER_QUADTREE by default */
    enum vor_dc_split split;  /* vor_build_dc(_forked): VOR_DC_QUADTREE by default */
    uint32_t fork_min_sites;  /* vor_build_dc_forked: the hook is used only from
                                 this many sites on (0: VOR_DC_FORK_MIN_SITES_DEFAULT;
                                 any value below 8 means 8) */
} vor_build_options_t;

/* vor_build_dc_forked's fork_min_sites when the option is 0: below it,
 * starting the other core costs more than it saves and the build runs on
 * the calling core alone (the result is the same either way). Measured
 * with pthreads on the host (docs/benchmarks.md, "Two cores"); a cheaper
 * fork (a core already waiting, as on a dual-core microcontroller) may
 * take a lower one. */
#define VOR_DC_FORK_MIN_SITES_DEFAULT 1024u

/*
 * Replaces the contents of d by the diagram of points[0 .. n), by Sugihara
 * and Iri's topology-oriented insertion: site i is points[i]. A point
 * equal to an earlier one is not a separate site: duplicate_of[i] (if the
 * array is given, n entries) receives the id of its first occurrence, and
 * i for every other site. options may be NULL (the defaults); only its
 * order is read.
 *   VOR_ERR_ARG  d NULL, points NULL with n > 0, an unknown order
 *   VOR_ERR_FULL n > max_sites
 * Expected O(n) time for uniform points; scratch space comes from the
 * arena's unused part, nothing else is touched. Links no code of the
 * divide-and-conquer builder.
 */
int vor_build(vor_t *d, const vor_point_t *points, uint32_t n,
              const vor_build_options_t *options, uint32_t *duplicate_of);

/*
 * vor_build by divide and conquer with Oishi and Sugihara's topological
 * guards: the same result in the same structure (the perturbed Delaunay
 * triangulation is unique), so every other call works on either. No
 * memory beyond the arena and no recursion (an explicit stack of
 * O(log n) frames on the C stack; docs/design/divide-and-conquer.md).
 * A separate entry point so that a firmware using only vor_build does not
 * link this builder, nor this one the two-core code. options may be NULL
 * (the defaults); only its split is read.
 *   VOR_ERR_ARG  d NULL, points NULL with n > 0, an unknown split
 *   VOR_ERR_FULL n > max_sites
 */
int vor_build_dc(vor_t *d, const vor_point_t *points, uint32_t n,
                 const vor_build_options_t *options, uint32_t *duplicate_of);

/* A way to run work on another core, supplied by the caller: vor itself
 * stays single-threaded and freestanding (docs/api.md has a pthreads and
 * an RP2040 version).
 *   fork  starts work(arg) on another core and returns 0, or returns
 *         nonzero if it cannot (vor then runs work(arg) itself);
 *   join  returns once the work of the last successful fork has finished,
 *         with everything it wrote visible to the calling core (a
 *         happens-before edge, as pthread_join gives).
 * work runs exactly once, and must be able to use as much stack as
 * vor_build_dc (docs/benchmarks.md, "Code size and stack"). */
typedef struct vor_fork_join {
    int (*fork)(void *context, void (*work)(void *arg), void *arg);
    void (*join)(void *context);
    void *context; /* passed to both */
} vor_fork_join_t;

/*
 * vor_build_dc on two cores: from options->fork_min_sites sites on, one half
 * of the sites (the bottom half of the quadtree, whose square is centred
 * on the sites' box so that sites spread over it split about evenly, or
 * the first part of the x-split) is built through hook->fork while the
 * calling core builds the other, and the calling core merges them after
 * hook->join. The result is byte for byte vor_build_dc's, including
 * the VOR_STATS counters' sums (docs/design/divide-and-conquer.md, "Two cores"). hook NULL:
 * vor_build_dc. options: its split and fork_min_sites, NULL for the defaults.
 * Meanwhile the other core touches only d's arena, points already copied
 * into it, and duplicate_of; the caller must not use d, its arena or
 * duplicate_of until the call returns.
 *   VOR_ERR_ARG  d NULL, points NULL with n > 0, an unknown split, a hook
 *                whose fork or join is NULL
 *   VOR_ERR_FULL n > max_sites
 * On failure nothing changes and the hook is not called. Fault injection
 * builds (tests only) with a nonzero fault rate build on one core.
 */
int vor_build_dc_forked(vor_t *d, const vor_point_t *points, uint32_t n,
                        const vor_build_options_t *options, uint32_t *duplicate_of,
                        const vor_fork_join_t *hook);

/* What vor_validate checks, in this order; the first failure is reported. */
enum vor_check {
    VOR_CHECK_COUNTS,      /* 2 v - 2 triangles for v sites in the mesh */
    VOR_CHECK_VERTICES,    /* every vertex a valid site or infinity, distinct */
    VOR_CHECK_NEIGHBOURS,  /* neighbour links symmetric, edges shared */
    VOR_CHECK_SITES,       /* every site present, its triangles one fan */
    VOR_CHECK_BUCKETS,     /* the bounding box holds every site, and every
                              bucket of the grid names a site in the mesh */
    VOR_CHECK_ORIENTATION, /* every finite triangle counterclockwise */
    VOR_CHECK_DELAUNAY,    /* every edge locally Delaunay (and a convex hull) */
    VOR_CHECK_TRUE_OUTPUT  /* the iterators report the true triangulation:
                              2 v - h - 2 triangles of nonzero area, CCW,
                              bounded by a convex polygon through the h hull
                              sites; none and a path of neighbours when all
                              sites are collinear; neighbours = its edges */
};

typedef struct vor_violation {
    enum vor_check check; /* the first check that failed */
    uint32_t triangle;    /* the triangle slot where it failed */
    uint32_t site;        /* the site involved, where there is one */
} vor_violation_t;

/*
 * Checks every invariant of the mesh: returns VOR_OK, or VOR_ERR_INVALID
 * with the first violation in *violation (may be NULL); VOR_ERR_ARG if d
 * is NULL. The first four checks are topological and hold even when the
 * arithmetic is wrong; the last three hold with exact arithmetic. O(n),
 * read-only (its predicate calls are not counted in the VOR_STATS counters).
 */
int vor_validate(const vor_t *d, vor_violation_t *violation);

typedef struct vor_memory {
    size_t arena_bytes;    /* VOR_ARENA_BYTES(max_sites) */
    size_t used_bytes;     /* what the current sites and triangles occupy */
    uint32_t sites;        /* ids in use */
    uint32_t triangles;    /* triangles, including those at infinity */
    uint32_t bytes_per_site_x100; /* used_bytes / sites, in hundredths
                                     (exact while used_bytes < SIZE_MAX / 100) */
} vor_memory_t;

/* Memory figures of d. VOR_ERR_ARG if d or memory is NULL. */
int vor_memory(const vor_t *d, vor_memory_t *memory);

/*
 * The predicate counters of d (vor_stats_t) into *out, in a build with
 * VOR_STATS (vor_config.h): benchmarks and tests. Without it there are no
 * counters: VOR_ERR_ARG, nothing written.
 *   VOR_ERR_ARG  d or out NULL, or the library built without VOR_STATS
 */
int vor_stats(const vor_t *d, vor_stats_t *out);

/* ITERATORS (triangles, neighbours, edges, hull, cells): the state lives
 * in a struct on the caller's stack, and every one works the same way:
 *
 *     vor_triangle_iter_t it;
 *     if (vor_triangles_begin(&it, &d) == VOR_OK) {
 *         while (vor_triangles_next(&it, ids)) { ... }
 *     }
 *
 * x_begin returns VOR_OK, or VOR_ERR_ARG (d NULL, a site not in the mesh,
 * a NULL or inverted box) and leaves a non-NULL iterator closed; with a
 * NULL iterator it returns VOR_ERR_ARG and does nothing. x_next returns 1
 * with the next item, or 0 at the end, never an error: a closed iterator
 * (also a zero-initialised one, or one that reported its end), a NULL
 * iterator or output gives 0 and writes nothing, so a `while` over next
 * always ends. The cell iterator, whose buffer can be too small, keeps why
 * it stopped (vor_cells_error). An iterator must not outlive a change of
 * its diagram. */

/* Iterator over the triangles of the true Delaunay triangulation of the
 * distinct sites (state on the caller's stack): each as three site ids,
 * counterclockwise, of positive area. They cover the convex hull, with
 * every site on a hull edge a vertex: 2n - h - 2 triangles for n distinct
 * sites, h of them on the hull's boundary; none when all sites are
 * collinear. Cocircular ties are broken by the perturbation, the same way
 * by every builder. Cost: one exact orientation test a triangle. */
typedef struct vor_triangle_iter {
    const vor_t *d;
    uint32_t next_slot;
} vor_triangle_iter_t;

int vor_triangles_begin(vor_triangle_iter_t *it, const vor_t *d);
/* Returns 1 and fills ids[3] while triangles remain, then 0. */
int vor_triangles_next(vor_triangle_iter_t *it, uint32_t ids[3]);

/* Iterator over the neighbours of one site, turning around it: its edges
 * in the triangulation above, i.e. the sites whose Voronoi cells share an
 * edge with its cell, plus the diagonals the triangulation picked where
 * cocircular sites' cells meet in one point. With all sites collinear,
 * the nearest site on each side along the line; nothing in a diagram of
 * one site. begin: VOR_ERR_ARG for a site not in the mesh (unknown, or a
 * duplicate's id). Cost: O(its mesh neighbours),
 * one or two exact orientation tests each. */
typedef struct vor_neighbour_iter {
    const vor_t *d;
    uint32_t site;
    uint32_t slot;
    uint32_t left;
} vor_neighbour_iter_t;

int vor_neighbours_begin(vor_neighbour_iter_t *it, const vor_t *d, uint32_t site);
/* Returns 1 and sets *neighbour while neighbours remain, then 0. */
int vor_neighbours_next(vor_neighbour_iter_t *it, uint32_t *neighbour);

/* ================================================================== */
/* Voronoi geometry (read-only: safe from several threads)            */
/* ================================================================== */

/*
 * The geometry is that of the true Voronoi diagram of the distinct sites,
 * computed exactly (multi-word rationals) and rounded only on output: a
 * coordinate v becomes floor(v + 1/2), the nearest integer with halves
 * toward +infinity. docs/design/geometry.md has the widths.
 */

/* What a rounded vertex is. */
enum vor_vertex_status {
    VOR_VERTEX_IN_RANGE = 0,    /* point is the rounded exact vertex */
    VOR_VERTEX_OUT_OF_RANGE = 1, /* a rounded coordinate is outside int32: that
                                    coordinate is saturated to INT32_MIN or
                                    INT32_MAX (never wrapped), the other is
                                    rounded if it fits */
    VOR_VERTEX_AT_INFINITY = 2  /* collinear sites: no vertex; point is (0, 0) */
};

typedef struct vor_vertex {
    vor_point_t point;
    enum vor_vertex_status status;
} vor_vertex_t;

/*
 * The centre of the circle through a, b, c (their Voronoi vertex), rounded
 * as above; AT_INFINITY when they are collinear (or two coincide).
 *   VOR_ERR_ARG  out NULL
 */
int vor_circumcentre(vor_point_t a, vor_point_t b, vor_point_t c, vor_vertex_t *out);

/*
 * vor_circumcentre of sites a, b, c of d (e.g. a triangle from
 * vor_triangles_next).
 *   VOR_ERR_ARG  d or out NULL, an id that is no site in the mesh (an
 *                unused or removed id, a duplicate's id)
 * On failure *out is unchanged.
 */
int vor_voronoi_vertex(const vor_t *d, uint32_t a, uint32_t b, uint32_t c,
                       vor_vertex_t *out);

enum vor_edge_kind {
    VOR_EDGE_SEGMENT = 0, /* from `from` to `to` */
    VOR_EDGE_RAY = 1,     /* from `from` in direction (dx, dy), without end */
    VOR_EDGE_LINE = 2     /* the whole bisector: through `from` (the rounded
                             midpoint of the sites), direction (dx, dy) */
};

/* One edge of the Voronoi diagram: the part of the bisector of two sites
 * that is nearer to them than to any other site. Walking it from `from`
 * in direction (dx, dy), the cell of sites[0] is on the left and the cell
 * of sites[1] on the right. (dx, dy) is exact: sites[1] - sites[0] turned
 * a quarter counterclockwise. `to` is AT_INFINITY except for segments. */
typedef struct vor_edge {
    uint32_t sites[2];
    enum vor_edge_kind kind;
    vor_vertex_t from;
    vor_vertex_t to;
    int64_t dx;
    int64_t dy;
} vor_edge_t;

/* Iterator over the edges of the Voronoi diagram: each edge of positive
 * length exactly once (cocircular sites give no zero-length edges). With
 * all sites collinear the edges are parallel lines; with one site, none.
 * Two exact endpoints of a segment may round to the same point. */
typedef struct vor_edge_iter {
    const vor_t *d;
    uint32_t slot;
    uint32_t edge;
} vor_edge_iter_t;

int vor_edges_begin(vor_edge_iter_t *it, const vor_t *d);
/* Returns 1 and fills *edge while edges remain, then 0. */
int vor_edges_next(vor_edge_iter_t *it, vor_edge_t *edge);

/* Iterator over the sites on the boundary of the convex hull,
 * counterclockwise, each once, starting at the lowest one (smallest y,
 * then smallest x). Sites in the middle of a hull edge are included: their
 * cells are unbounded too. All sites collinear: every site, in order along
 * the line from the lowest end; one site: that site. */
typedef struct vor_hull_iter {
    const vor_t *d;
    uint32_t ghost; /* the current hull edge's triangle at infinity */
    uint32_t site;  /* the next site to return */
    uint32_t first;
    uint32_t left;  /* at most this many sites remain */
    uint32_t collinear;
} vor_hull_iter_t;

int vor_hull_begin(vor_hull_iter_t *it, const vor_t *d);
/* Returns 1 and sets *site while hull sites remain, then 0. */
int vor_hull_next(vor_hull_iter_t *it, uint32_t *site);

/* A closed axis-aligned box [x0, x1] x [y0, y1]. */
typedef struct vor_box {
    int32_t x0;
    int32_t y0;
    int32_t x1;
    int32_t y1;
} vor_box_t;

/* Most vertices a clipped cell of a diagram of n sites can have (a
 * constant expression for static buffers): one per neighbour and four. */
#define VOR_CELL_MAX_VERTICES(n) ((uint32_t)(n) + 3u)

/*
 * The Voronoi cell of `site` clipped to `box`: its vertices,
 * counterclockwise, starting at the lowest (smallest y, then smallest x),
 * go to vertices[0 .. *count). Computed exactly and rounded on output, so
 * every vertex lies in the box; vertices that coincide exactly are written
 * once (distinct ones may round to the same point). A cell that meets the
 * box in less than an area (nothing, a point, a segment) gives *count = 0,
 * as does any box of zero width or height. With all sites collinear cells
 * are strips; with one site, the cell is the whole box.
 * Cost: O(neighbours of the site).
 *   VOR_ERR_ARG     d, box or count NULL; vertices NULL with capacity > 0;
 *                   box->x0 > box->x1 or box->y0 > box->y1; site not a
 *                   site in the mesh (unknown, or a duplicate's id)
 *   VOR_ERR_BUFFER  more than `capacity` vertices: *count = the number
 *                   needed, nothing written to vertices
 */
int vor_cell(const vor_t *d, uint32_t site, const vor_box_t *box,
             vor_point_t *vertices, uint32_t capacity, uint32_t *count);

/* Iterator over the clipped cells of every site in the mesh (duplicates'
 * ids are skipped), in increasing id order:
 *
 *     vor_cells_begin(&ci, &d, &box);               // VOR_ERR_ARG: box NULL
 *     while (vor_cells_next(&ci, &id, poly, cap, &m)) { ... }  // or inverted
 *     if (vor_cells_error(&ci) == VOR_ERR_BUFFER) { ... }  // m vertices needed
 */
typedef struct vor_cell_iter {
    const vor_t *d;
    vor_box_t box;
    uint32_t next_site;
    int error; /* why next returned 0 (vor_cells_error) */
} vor_cell_iter_t;

int vor_cells_begin(vor_cell_iter_t *it, const vor_t *d, const vor_box_t *box);
/* Returns 1 with the next cell (as vor_cell) in *site, vertices[0 ..
 * *count); 0 at the end, and 0 when it cannot give the next cell, with
 * the reason kept for vor_cells_error: the cell has more than `capacity`
 * vertices (*site and the needed *count are set, nothing is written to
 * vertices, and the iterator stays on that cell, so that next with a
 * large enough buffer resumes there), or site or count is NULL, or
 * vertices NULL with capacity > 0 (nothing written). */
int vor_cells_next(vor_cell_iter_t *it, uint32_t *site, vor_point_t *vertices,
                   uint32_t capacity, uint32_t *count);
/* Why the last vor_cells_next returned 0: VOR_OK at the end of the cells
 * (and before the first next), VOR_ERR_BUFFER at a cell that did not fit,
 * VOR_ERR_ARG for bad outputs or a closed iterator (a failed begin, a
 * NULL it). */
int vor_cells_error(const vor_cell_iter_t *it);

/* Bytes of scratch vor_cell_centroid needs for a cell of up to
 * max_vertices vertices (a constant expression): six integers of
 * 130 max_vertices + 288 bits, and 8 bytes for alignment. For any cell of
 * a diagram of n sites: VOR_CENTROID_SCRATCH_BYTES(VOR_CELL_MAX_VERTICES(n)). */
#define VOR_CENTROID_SCRATCH_BYTES(max_vertices)                              \
    ((size_t)48u * (((size_t)(max_vertices) * 130u + 288u + 63u) / 64u) + 8u)

/* The area and centroid of a clipped cell, each rounded once from its
 * exact rational value: v becomes floor(v + 1/2), the nearest integer with
 * halves toward +infinity (as vor_cell's vertices). */
typedef struct vor_centroid {
    vor_point_t point; /* the centroid, always in the box */
    uint64_t area;     /* the area, in squared coordinate units (< 2^64) */
    uint32_t vertices; /* the cell's vertices, as vor_cell counts them */
} vor_centroid_t;

/*
 * The area and centroid of the Voronoi cell of `site` clipped to `box`
 * (the polygon vor_cell gives, before rounding): for Lloyd relaxation,
 * move the site to out->point. Computed from the exact vertices as exact
 * rationals in the caller's scratch (any alignment; its contents are
 * undefined after the call) and rounded once. A cell that meets the box
 * in less than an area, or a box of zero width or height, gives area 0,
 * vertices 0 and point = the point of the box nearest the site.
 * Cost: O(neighbours + k^2) limb products for a cell of k vertices.
 *   VOR_ERR_ARG     d, box or out NULL; scratch NULL with scratch_bytes > 0;
 *                   box->x0 > box->x1 or box->y0 > box->y1; site not a
 *                   site in the mesh (unknown, or a duplicate's id)
 *   VOR_ERR_BUFFER  the scratch, once aligned, cannot hold the sums of the
 *                   cell's k vertices (never when scratch_bytes >=
 *                   VOR_CENTROID_SCRATCH_BYTES(k); an aligned scratch
 *                   may do with up to 8 bytes less): only out->vertices
 *                   is written, with k
 */
int vor_cell_centroid(const vor_t *d, uint32_t site, const vor_box_t *box,
                      void *scratch, size_t scratch_bytes, vor_centroid_t *out);

/* ------------------------------------------------------------------ */
/* Cells clipped to a simple polygon (a room that need not be a box)  */
/*
 *     static vor_point_t room[6] = {{0,0}, {60,0}, {60,30}, {30,30},
 *                                   {30,60}, {0,60}};          // an L
 *     static uint32_t scratch[VOR_CLIP_SCRATCH_BYTES(6, N) / 4];
 *     vor_clip_t clip;
 *     vor_clip_begin(&clip, &d, id, room, 6, scratch, sizeof scratch);
 *     while (vor_clip_next(&clip, piece, cap, &m)) { ... }  // CCW pieces
 *     vor_clip_centroid(&clip, VOR_CLIP_WHOLE, sums, sizeof sums, &c);
 *
 * A room is a simple polygon: m >= 3 int32 vertices in order, either
 * orientation, no zero-length edge, no two edges meeting except
 * consecutive ones at their common vertex (collinear consecutive edges
 * are fine: the vertex between them is no corner and is not reported).
 * A non-convex room can cut one cell into several pieces; each is
 * reported on its own, counterclockwise, from its lowest vertex
 * (smallest y, then smallest x), the pieces in the order of their lowest
 * vertices. Pieces have positive area, distinct corners and no straight
 * angles, whatever touches what (room corners on cell edges, room edges
 * along cell edges, cell vertices on room edges). Two pieces may share a
 * corner (a room corner on a cell edge can pinch the cell in two).
 * The clipping is done with the exact lines of the cell (bisectors) and
 * of the room; an order-K cell, also an intersection of bisectors'
 * half-planes, is clipped by the same code.
 */

/* A vertex of a clipped cell, exact: (x / w, y / w) with w > 0, each
 * number VOR_EXACT_LIMBS 32-bit limbs, least significant first, two's
 * complement (|x|, |y| < 2^101, 0 < w < 2^67), in lowest terms; and
 * `point`, the same vertex rounded once as vor_cell's vertices are (v
 * becomes floor(v + 1/2)). */
#define VOR_EXACT_LIMBS 4u
typedef struct vor_exact_point {
    vor_point_t point;
    uint32_t x[VOR_EXACT_LIMBS];
    uint32_t y[VOR_EXACT_LIMBS];
    uint32_t w[VOR_EXACT_LIMBS];
} vor_exact_point_t;

/* Most room vertices vor_clip_begin takes (2^24). */
#define VOR_CLIP_MAX_ROOM 16777216u

/* Most vertices the pieces of one cell of a diagram of n sites clipped to
 * a room of m vertices have together (so also the most one piece has): a
 * constant expression. Every piece has 3 at least. */
#define VOR_CLIP_MAX_VERTICES(m, n) ((4u * (uint32_t)(m)) + (uint32_t)(n) + 3u)

/* Bytes of scratch vor_clip_begin needs for a room of m vertices and a
 * diagram of n sites (max_sites is enough; a constant expression; any
 * alignment): 7 words a
 * vertex of VOR_CLIP_MAX_VERTICES(m, n), 4m + n + 3, and 36 bytes. It holds the
 * pieces while the iterator reads them. */
#define VOR_CLIP_SCRATCH_BYTES(m, n)                                           \
    (((size_t)28u * ((4u * (size_t)(m)) + (size_t)(n) + 3u)) + 36u)

/* Bytes of scratch vor_clip_centroid needs for any piece, or the whole
 * clipped cell, of a room of m vertices in a diagram of n sites (a
 * constant expression). */
#define VOR_CLIP_CENTROID_SCRATCH_BYTES(m, n)                                  \
    VOR_CENTROID_SCRATCH_BYTES(2u * VOR_CLIP_MAX_VERTICES(m, n))

/* The pieces of a clipped cell, kept in the caller's scratch: fields are
 * private except `pieces`, how many there are (0: the cell does not meet
 * the room in an area). Valid while the diagram, the room and the scratch
 * are unchanged. */
struct vor__clip_frame;
struct vor__line;
typedef void vor__pair_line_fn(const struct vor__clip_frame *f, uint32_t name,
                               struct vor__line *line);
typedef struct vor_clip {
    const vor_t *d;          /* NULL: closed (a failed begin) */
    const vor_point_t *room;
    uint32_t room_count;
    uint32_t reversed;       /* 1: the room is clockwise */
    uint32_t site;
    const uint32_t *lines;   /* the pieces' edges, as line names */
    const uint32_t *start;   /* [pieces] first line of each piece */
    const uint32_t *count;   /* [pieces] lines of each piece */
    uint32_t pieces;         /* the pieces, once begun */
    uint32_t next_piece;
    int error;               /* why next returned 0 (vor_clip_error) */
    const uint32_t *set;     /* order K (vor_order_cell_begin): its K sites,
                                increasing, then the others met; else NULL */
    uint32_t order;          /* K */
    uint32_t others;
    uint32_t shift;          /* a pair's line name: (other << shift) | i */
    vor__pair_line_fn *pair_line; /* order K: a pair's line, else NULL
                                (stored by the order-K begin, so that a
                                firmware without it links none of it) */
    size_t needed;           /* after VOR_ERR_BUFFER from a begin: the
                                scratch bytes it needs (else 0) */
} vor_clip_t;

/*
 * The Voronoi cell of `site` clipped to the room room[0 .. m), computed
 * exactly into the caller's scratch (its contents are the iterator's
 * until the pieces have been read). The room array must stay unchanged
 * while the pieces are read. Cost: O(m^2) orientation tests to check the
 * room, then O((m + k) k) exact line tests for a site of k neighbours
 * (fewer when the cell is small), O(p^2 + v) to order p pieces of v
 * vertices.
 *   VOR_ERR_ARG      clip, d or room NULL; m < 3 or m > VOR_CLIP_MAX_ROOM;
 *                    scratch NULL with scratch_bytes > 0; site not a site
 *                    in the mesh (unknown, or a duplicate's id)
 *   VOR_ERR_POLYGON  the room is not simple: a zero-length edge, two
 *                    edges that cross, touch or overlap (consecutive
 *                    edges folding back on each other), all vertices on
 *                    one line
 *   VOR_ERR_BUFFER   scratch_bytes < VOR_CLIP_SCRATCH_BYTES(m, k + 1)
 *                    for the site's k Delaunay neighbours (never with
 *                    VOR_CLIP_SCRATCH_BYTES(m, n) for n sites);
 *                    clip->needed is then that size
 * On failure the iterator is closed (next returns 0, error the reason)
 * and nothing else is written.
 */
int vor_clip_begin(vor_clip_t *clip, const vor_t *d, uint32_t site, const vor_point_t *room,
                   uint32_t m, void *scratch, size_t scratch_bytes);
/* Returns 1 with the next piece's vertices in vertices[0 .. *count),
 * counterclockwise from the lowest; 0 at the end, and 0 when it cannot
 * give the next piece, with the reason kept for vor_clip_error: more
 * than `capacity` vertices (*count = the number needed, nothing written
 * to vertices, the iterator stays on that piece), count NULL or vertices
 * NULL with capacity > 0 (nothing written), a closed iterator. */
int vor_clip_next(vor_clip_t *clip, vor_exact_point_t *vertices, uint32_t capacity,
                  uint32_t *count);
/* Why the last vor_clip_next returned 0: VOR_OK at the end (and before
 * the first next), VOR_ERR_BUFFER at a piece that did not fit,
 * VOR_ERR_ARG for bad outputs, and a failed begin's error (VOR_ERR_ARG
 * for a NULL clip). */
int vor_clip_error(const vor_clip_t *clip);

/* vor_clip_centroid's piece for the whole clipped cell. */
#define VOR_CLIP_WHOLE 0xFFFFFFFFu

/*
 * The area and centroid of piece `piece` (0 .. clip->pieces - 1, in the
 * iterator's order) or of all of them together (VOR_CLIP_WHOLE), exact
 * and rounded once as vor_cell_centroid's: for Lloyd relaxation in a
 * room. out->vertices is the vertices counted (all pieces' for the
 * whole). The centroid of a non-convex region may lie outside it. When
 * there are no pieces, VOR_CLIP_WHOLE gives area 0, vertices 0 and the
 * site as the point. Scratch: any alignment, contents undefined after
 * the call, VOR_CENTROID_SCRATCH_BYTES(k) bytes with k = the piece's
 * vertices (the whole: the vertices of all pieces, plus one for each
 * piece after the first).
 * The iterator is not moved. Cost: O(k^2) limb products.
 *   VOR_ERR_ARG     clip or out NULL, a closed iterator, piece neither
 *                   VOR_CLIP_WHOLE nor below clip->pieces, scratch NULL
 *                   with scratch_bytes > 0
 *   VOR_ERR_BUFFER  the scratch is too small: only out->vertices is
 *                   written, with that k
 */
int vor_clip_centroid(const vor_clip_t *clip, uint32_t piece, void *scratch,
                      size_t scratch_bytes, vor_centroid_t *out);

/* ------------------------------------------------------------------ */
/* Order-K cells clipped to a simple polygon                          */
/*
 *     static const uint32_t pair[2] = {3, 7};                // K = 2
 *     static uint32_t scratch[VOR_ORDER_SCRATCH_BYTES(6, N, 2) / 4];
 *     vor_order_cell_begin(&clip, &d, pair, 2, room, 6, scratch, sizeof scratch);
 *     while (vor_clip_next(&clip, piece, cap, &m)) { ... }  // CCW pieces
 *
 *     // every non-empty order-K cell of the room: they tile it
 *     static uint32_t sets[VOR_ORDER_SETS_WORDS(VOR_ORDER_MAX_CELLS(N, 2), 2)];
 *     vor_order_iter_t it;
 *     uint32_t set[2];
 *     vor_order_cells_begin(&it, &d, 2, room, 6, sets, VOR_ORDER_MAX_CELLS(N, 2),
 *                           scratch, sizeof scratch);
 *     while (vor_order_cells_next(&it, set, &clip)) {
 *         while (vor_clip_next(&clip, piece, cap, &m)) { ... }
 *     }
 *
 * The order-K cell of a set S of K distinct sites is the closed region
 * of the points whose K nearest sites are S: the points at least as
 * close to every site of S as to every other site (the intersection of
 * the half-planes of the bisectors of s in S and t not in S). Cells are
 * closed, so a point where the K-th and (K+1)-th nearest sites are at
 * the same distance lies on the boundary of every cell that tie allows:
 * in particular in the cell of the K sites vor_raster_nearest labels it
 * with (ties to the smaller index) when given the distinct sites.
 * Duplicates count once: the sites are the distinct ones, named by the
 * ids in the mesh. Where more than K + 1 sites are equally far, a cell
 * the tie allows may be a point or a segment only, which the walk (cells
 * with an area) does not visit. The cells with
 * an area tile the room. Pieces, vertices, areas and centroids are those
 * of vor_clip_begin (vor_clip_next, vor_clip_centroid), exact; order 1
 * gives vor_clip_begin's pieces.
 */

/* Most K the order-K calls take. */
#define VOR_ORDER_MAX 1024u

/* Bytes of scratch vor_order_cell_begin needs for a room of m vertices,
 * n distinct sites (or more: the bytes grow with n, so max_sites is
 * enough) and order k (a constant expression, 1 <= k < n; any
 * alignment): the pieces of up to k (n - k) bisectors' cuts, as
 * VOR_CLIP_SCRATCH_BYTES, and n + k words for the sites. A set whose K
 * sites have c other Delaunay neighbours needs only
 * VOR_CLIP_SCRATCH_BYTES(m, k c + 1) + 4 (2 k + c) bytes (clip->needed
 * after VOR_ERR_BUFFER): typically c is near 2 k + 4. */
#define VOR_ORDER_SCRATCH_BYTES(m, n, k)                                       \
    (VOR_CLIP_SCRATCH_BYTES((m), ((size_t)(k) * ((size_t)(n) - (size_t)(k))) + 1u) + \
     ((size_t)4u * ((size_t)(n) + (size_t)(k))))

/*
 * The order-K cell of the k sites set[0 .. k) (any order) clipped to the
 * room room[0 .. m) (a simple polygon, as vor_clip_begin's), computed
 * exactly into the caller's scratch: read its pieces with vor_clip_next
 * and their area and centroid with vor_clip_centroid (whose point, when
 * there are no pieces, is the set's site of the smallest id). The set
 * and room arrays may change after the call; the diagram, the room and
 * the scratch must not while the pieces are read. Cost: O(m^2)
 * orientation tests to check the room, O(k^2 d^2) neighbour steps for
 * k sites of d neighbours each, then O((m + k c) k c) exact line tests
 * for the k c half-planes of the set and its c other neighbours.
 *   VOR_ERR_ARG      clip, d, set or room NULL; k == 0, k > VOR_ORDER_MAX
 *                    or k >= the number of distinct sites; an id not a
 *                    site in the mesh (unknown, or a duplicate's id); an
 *                    id twice; m < 3 or m > VOR_CLIP_MAX_ROOM; scratch
 *                    NULL with scratch_bytes > 0
 *   VOR_ERR_POLYGON  the room is not simple (as vor_clip_begin)
 *   VOR_ERR_BUFFER   the scratch is smaller than the set needs (never
 *                    with VOR_ORDER_SCRATCH_BYTES(m, n, k) for n distinct
 *                    sites): clip->needed is then that size
 * On failure the iterator is closed (next returns 0, error the reason)
 * and nothing else is written.
 */
int vor_order_cell_begin(vor_clip_t *clip, const vor_t *d, const uint32_t *set, uint32_t k,
                         const vor_point_t *room, uint32_t m, void *scratch,
                         size_t scratch_bytes);

/* Most order-k cells of n distinct sites, 1 <= k < n (a constant
 * expression): 2 k n - k^2 - n + 1, Lee's bound for sites in general
 * position (D. T. Lee, "On k-nearest neighbor Voronoi diagrams in the
 * plane", IEEE Trans. Computers, 1982), which holds for any sites: a
 * cell with an area keeps one under a small enough perturbation. */
#define VOR_ORDER_MAX_CELLS(n, k)                                              \
    ((((size_t)2u * (size_t)(k) * (size_t)(n)) - ((size_t)(k) * (size_t)(k))) - \
     (size_t)(n) + 1u)

/* Words of the store vor_order_cells_begin keeps the k-sets met in, for
 * up to `cells` of them (a constant expression): k + 1 a set. */
#define VOR_ORDER_SETS_WORDS(cells, k) ((size_t)(cells) * ((size_t)(k) + 1u))

/* A walk over the non-empty order-K cells of a room, its state on the
 * caller's stack and in the caller's memory: fields are private except
 * `met` (the k-sets met so far) and `needed` (see next). */
typedef struct vor_order_iter {
    const vor_t *d;          /* NULL: closed (a failed begin) */
    const vor_point_t *room;
    uint32_t room_count;
    uint32_t reversed;       /* 1: the room is clockwise */
    uint32_t order;          /* K */
    uint32_t *sets;          /* [max_sets] k-sets met, K ids each, in order */
    uint32_t *index;         /* [max_sets] those sets in increasing order */
    uint32_t max_sets;
    uint32_t met;            /* sets met */
    uint32_t done;           /* sets whose cells were computed */
    void *scratch;           /* one cell's, as vor_order_cell_begin's */
    size_t scratch_bytes;
    size_t needed;           /* after VOR_ERR_BUFFER for a cell: its bytes */
    int error;               /* why next returned 0 (vor_order_cells_error) */
} vor_order_iter_t;

/*
 * Begins a walk over every order-k cell that meets the room room[0 .. m)
 * in an area (a simple polygon, as vor_clip_begin's): they tile the
 * room. The walk starts from the k sites nearest a point just inside
 * the room's lowest corner and crosses every piece edge that lies on a
 * bisector: a cell of set S across its edge on the bisector of s in S
 * and t outside is the cell of S - s + t (no other pair ties along an
 * edge, even where bisectors coincide). The k-sets met are kept in sets[0 ..
 * VOR_ORDER_SETS_WORDS(max_sets, k)), which belongs to the walk until it
 * ends (no recursion, no other memory); the scratch holds the current
 * cell (VOR_ORDER_SCRATCH_BYTES(m, n, k) for n distinct sites always
 * does). max_sets = VOR_ORDER_MAX_CELLS(n, k) never runs out; a smaller
 * store may (next gives VOR_ERR_BUFFER). Cost: begin O(m^2 + n k)
 * exact tests; each cell as vor_order_cell_begin's, and O(log M) set
 * comparisons for each of its edges (M sets met).
 *   VOR_ERR_ARG      it, d or room NULL; k == 0, k > VOR_ORDER_MAX or
 *                    k >= the number of distinct sites; m < 3 or
 *                    m > VOR_CLIP_MAX_ROOM; sets NULL with max_sets > 0;
 *                    scratch NULL with scratch_bytes > 0
 *   VOR_ERR_POLYGON  the room is not simple
 *   VOR_ERR_BUFFER   max_sets == 0
 * On failure the iterator is closed and nothing else is written.
 */
int vor_order_cells_begin(vor_order_iter_t *it, const vor_t *d, uint32_t k,
                          const vor_point_t *room, uint32_t m, uint32_t *sets,
                          uint32_t max_sets, void *scratch, size_t scratch_bytes);
/* Returns 1 with the next non-empty cell: its k sites in set[0 .. k),
 * increasing, and *clip begun on it (pieces >= 1; read as from
 * vor_order_cell_begin, valid until the next call). Each k-set comes
 * once. Returns 0 at the end, and 0 when it cannot go on, with the
 * reason kept for vor_order_cells_error: set or clip NULL (nothing
 * written), the scratch too small for the next cell (it->needed is the
 * bytes that cell needs) or the store of sets full: VOR_ERR_BUFFER,
 * after which the walk stays where it is (begin again with more). */
int vor_order_cells_next(vor_order_iter_t *it, uint32_t *set, vor_clip_t *clip);
/* Why the last vor_order_cells_next returned 0: VOR_OK at the end (and
 * before the first next), VOR_ERR_ARG for bad outputs, VOR_ERR_BUFFER,
 * and a failed begin's error (VOR_ERR_ARG for a NULL it). */
int vor_order_cells_error(const vor_order_iter_t *it);

/* ================================================================== */
/* Natural-neighbour interpolation (src/interpolate.c)                */
/* ================================================================== */

/* Bytes of scratch vor_sibson and vor_interpolate need for a point with
 * up to k natural neighbours (a constant expression): k + 4 numbers of
 * 132 k + 64 bits and k + 1 output numbers of the same width, the 2k - 2
 * exact Voronoi vertices involved (3 x 192 bits each), 7k + 1 indices,
 * and 8 bytes for alignment. A point has at most n - 1 natural
 * neighbours in a diagram of n sites, typically about 6 (k = 6: 2.9 KB,
 * k = 16: 13 KB). docs/design/interpolation.md derives the widths. */
#define VOR_SIBSON_SCRATCH_BYTES(k)                                            \
    (((((size_t)(k) * 2u) + 5u) * 8u * ((((size_t)(k) * 132u) + 127u) / 64u)) + \
     ((size_t)(k) * 172u) + 12u)

/* Exact natural-neighbour coordinates of a point q: the sites q's
 * Voronoi cell would border if q were inserted, and for each its
 * coordinate weight_i / denominator (Sibson: the area q's cell takes
 * from the site's; Laplace: the length of the cell's edge facing the
 * site over the site's distance, normalised). Every number is a
 * non-negative integer of `limbs` 32-bit limbs, least significant first,
 * in the caller's scratch (valid until the scratch is reused). The
 * weights are positive and add up to the denominator exactly; with the
 * sites p_i, sum weight_i p_i = denominator q exactly (linear precision).
 * They are over one common denominator, not reduced. */
typedef struct vor_coordinates {
    uint32_t count;              /* natural neighbours (VOR_ERR_NOMEM: needed k) */
    uint32_t limbs;              /* 32-bit limbs of each number below */
    const uint32_t *sites;       /* [count] their ids, counterclockwise around q */
    const uint32_t *weights;     /* [count * limbs]: weight i at weights + i * limbs */
    const uint32_t *denominator; /* [limbs], > 0 */
} vor_coordinates_t;

/*
 * The Sibson coordinates of q (any int32 point) with respect to the true
 * Voronoi diagram of the distinct sites of d, exact. Cocircular sites
 * (where the triangulation is not unique) give the one true answer: the
 * areas are those of the true diagram, whatever the perturbation chose.
 *   q strictly inside the convex hull: its natural neighbours, each with
 *     the area its cell loses to q's (k >= 3 of them);
 *   q a site: that site alone, weight 1 of 1;
 *   q on the hull's boundary between two sites a and b (all sites
 *     collinear: on the segment between two neighbouring sites): the
 *     limit of the coordinates there, linear along the edge: a and b
 *     with weights (b - q).(b - a) and (q - a).(b - a) over |b - a|^2.
 * hint as for vor_nearest. Scratch: any alignment, contents undefined
 * after the call, VOR_SIBSON_SCRATCH_BYTES(k) bytes for k neighbours.
 * Cost: O(k) exact predicates to find the neighbours and O(k^3) limb
 * products for the exact areas.
 *   VOR_ERR_ARG      d or out NULL, scratch NULL with scratch_bytes > 0, a
 *                    bad hint (as vor_nearest)
 *   VOR_ERR_EMPTY    the diagram has no sites
 *   VOR_ERR_OUTSIDE  q is outside the convex hull of the sites (with all
 *                    sites collinear: not on their segment)
 *   VOR_ERR_NOMEM    scratch_bytes < VOR_SIBSON_SCRATCH_BYTES(k): only
 *                    out->count is written, with k
 * On any other failure *out is unchanged.
 */
int vor_sibson(const vor_t *d, vor_point_t q, uint32_t hint, void *scratch,
               size_t scratch_bytes, vor_coordinates_t *out);

/*
 * Laplace's (non-Sibsonian) coordinates of q, exact: for each natural
 * neighbour p_i, the length of the edge of q's cell facing it over
 * |q - p_i| (a rational number: the edge is perpendicular to q - p_i),
 * normalised. The same neighbours, special cases (site, hull edge,
 * outside), invariants (positive, adding up to the denominator, linear
 * precision), scratch and errors as vor_sibson, for O(k^2) limb products
 * instead of O(k^3), and numbers half as wide: the cheaper sibling for a
 * small microcontroller. The interpolant is continuous, but not smooth
 * (C0) at the sites' circles, unlike Sibson's.
 */
int vor_laplace(const vor_t *d, vor_point_t q, uint32_t hint, void *scratch,
                size_t scratch_bytes, vor_coordinates_t *out);

/* The Sibson interpolant of integer site values at a point: the exact
 * value numerator / denominator (sign and magnitude, 32-bit limbs least
 * significant first, in the caller's scratch) and the value rounded once,
 * halves away from zero. It lies between the smallest and the largest
 * value of the natural neighbours, so it always fits int32. */
typedef struct vor_interpolation {
    int32_t value;               /* the exact value rounded, halves away from zero */
    int32_t sign;                /* of the exact value: -1, 0 or 1 */
    uint32_t neighbours;         /* natural neighbours (VOR_ERR_NOMEM: needed k) */
    uint32_t limbs;              /* 32-bit limbs of numerator and denominator */
    const uint32_t *numerator;   /* [limbs], |numerator| */
    const uint32_t *denominator; /* [limbs], > 0 */
} vor_interpolation_t;

/*
 * sum_i values[site_i] lambda_i over q's Sibson coordinates (vor_sibson):
 * at a site its value, on a hull edge the linear interpolation of the
 * edge's ends, and a C1 surface elsewhere inside the hull. values is
 * indexed by site id (a duplicate's entry is not read: its first
 * occurrence is the site). Scratch and cost as vor_sibson.
 *   VOR_ERR_ARG, VOR_ERR_EMPTY, VOR_ERR_OUTSIDE as vor_sibson; also
 *                    values NULL
 *   VOR_ERR_NOMEM    as vor_sibson: only out->neighbours is written
 * On any other failure *out is unchanged.
 */
int vor_interpolate(const vor_t *d, const int32_t *values, vor_point_t q, uint32_t hint,
                    void *scratch, size_t scratch_bytes, vor_interpolation_t *out);

/* vor_interpolate over Laplace's coordinates (vor_laplace): the same
 * value at sites and along hull edges, errors and rounding. */
int vor_interpolate_laplace(const vor_t *d, const int32_t *values, vor_point_t q, uint32_t hint,
                            void *scratch, size_t scratch_bytes, vor_interpolation_t *out);

/* ================================================================== */
/* Queries (read-only: safe from several threads on one diagram)      */
/* ================================================================== */

#define VOR_NO_HINT 0xFFFFFFFFu

/*
 * The site nearest to q, any int32 point, by exact distance; of
 * several at the same distance, the smallest id. hint: a site to start
 * from (the previous answer, for a moving query), or VOR_NO_HINT (the
 * site the bucket grid holds for q's bucket). A duplicate is never answered: its first occurrence
 * is the site. Cost: O(steps from the hint x neighbours), O(1) for a hint
 * near the answer.
 *   VOR_ERR_ARG    d or site NULL, hint neither VOR_NO_HINT nor a site
 *                  in the mesh (an unused id, a duplicate's id)
 *   VOR_ERR_EMPTY  the diagram has no sites
 * On failure nothing is written.
 */
int vor_nearest(const vor_t *d, vor_point_t q, uint32_t hint, uint32_t *site);

/*
 * The k sites nearest to q, nearest first, by exact distance and, at
 * equal distances, smaller id first, into nearest[0 .. k). *found receives
 * min(k, number of sites): duplicates are not sites, their first
 * occurrences are. hint as for vor_nearest. Cost: the walk of vor_nearest,
 * then O(k^2) neighbour visits (each listed site's neighbours are scanned
 * for the next one); no memory beyond nearest[].
 *   VOR_ERR_ARG    d or found NULL, nearest NULL with k > 0, a bad hint
 *   VOR_ERR_EMPTY  the diagram has no sites
 * On failure nothing is written.
 */
int vor_nearest_k(const vor_t *d, vor_point_t q, uint32_t hint, uint32_t k,
                  uint32_t *nearest, uint32_t *found);

/*
 * The triangle holding q, any int32 point: the triangle of the true
 * Delaunay triangulation (one vor_triangles_next lists, its vertices in
 * the same order, counterclockwise) that contains q, exactly, into
 * ids[0 .. 3). A point on an edge or at a vertex is in several closed
 * triangles: the answer is the one that holds q moved by the library's
 * symbolic perturbation with an index before every site, to
 * (q.x + e^4, q.y + e) for an infinitesimal e > 0 (straight up, then a
 * far smaller step right), which lies on no line through two sites. So
 * the triangles and the outside of the hull split the plane into
 * half-open pieces, and every point has one answer:
 *   on an edge (not vertical)  the triangle above it;
 *   on a vertical edge         the triangle to its right;
 *   at a site                  the triangle whose corner there holds the
 *                              direction straight up (the one right of it
 *                              when an edge goes straight up);
 *   on the hull's boundary     that triangle when the hull lies above the
 *                              point (right of it on a vertical hull
 *                              edge), else VOR_ERR_OUTSIDE: a top or left
 *                              hull edge is outside, a bottom or right one
 *                              inside.
 * hint as for vor_nearest. Cost: vor_nearest's walk to the site c nearest
 * to q, then the triangles the segment from c to q crosses (a handful:
 * those whose circle holds q); no memory beyond ids[].
 *   VOR_ERR_ARG      d or ids NULL, a bad hint (as vor_nearest)
 *   VOR_ERR_EMPTY    the diagram has no sites
 *   VOR_ERR_OUTSIDE  q is outside the hull in the sense above; always
 *                    with fewer than 3 distinct sites or all collinear
 *                    (there is no triangle)
 * On failure nothing is written.
 */
int vor_locate(const vor_t *d, vor_point_t q, uint32_t hint, uint32_t ids[3]);

/*
 * Every site within squared distance r2 of q (|q - site|^2 <= r2, exact
 * for every int32 point and every uint64_t r2), their ids in increasing
 * order into ids[0 .. *count). Found by walking the mesh from the site
 * nearest to q (vor_nearest's walk), never by a scan of all sites: the
 * sites in a disc around q form a connected set in the Delaunay graph
 * together with the nearest site (each one has a Delaunay neighbour
 * strictly closer to q, as vor_nearest_k uses), so a walk over the
 * neighbours of the sites found, staying in the disc, finds them all.
 * Duplicates are not sites: their first occurrences are. hint as for
 * vor_nearest. Cost: O(m d^2) exact distance comparisons for m sites
 * found of degree d, twice when capacity is below the diagram's site
 * count (the sites are counted first); no memory beyond ids[] (the
 * walk keeps no list: each site's place in its search tree is
 * recomputed from its neighbours).
 *   VOR_ERR_ARG     d or count NULL, ids NULL with capacity > 0, a bad
 *                   hint (as vor_nearest)
 *   VOR_ERR_EMPTY   the diagram has no sites
 *   VOR_ERR_BUFFER  more than `capacity` sites are within r2: *count
 *                   receives how many, nothing is written to ids
 *                   (a capacity of the diagram's max_sites always
 *                   holds them)
 * On any other failure nothing is written.
 */
int vor_within(const vor_t *d, vor_point_t q, uint64_t r2, uint32_t hint, uint32_t *ids,
               uint32_t capacity, uint32_t *count);

/*
 * FLAT EXPORT of the triangulation for host and GPU code, in the
 * convention of delaunator: for T triangles,
 *   triangles[3 t .. 3 t + 2]  triangle t's site ids, counterclockwise:
 *                              the triangles vor_triangles_next lists, in
 *                              its order, each as it lists it;
 *   halfedges[e]               for the half-edge e = 3 t + k, which runs
 *                              from triangles[e] to triangles[3 t + (k + 1)
 *                              mod 3], the index of its twin (the same
 *                              edge run the other way in the triangle
 *                              across), or VOR_HALFEDGE_NONE on the hull.
 * Both arrays are 3 T uint32_t; T is at most VOR_TRIANGLES_MAX(n) for a
 * diagram of up to n sites (2 n - 5 for n >= 3, a constant expression),
 * and vor_triangles_count gives the current T.
 */
#define VOR_HALFEDGE_NONE 0xFFFFFFFFu
#define VOR_TRIANGLES_MAX(n) (((uint32_t)(n) >= 3u) ? ((2u * (uint32_t)(n)) - 5u) : 0u)

/*
 * The number of triangles vor_triangles_next lists for d, into *count.
 * Cost: one exact orientation test a triangle.
 *   VOR_ERR_ARG  d or count NULL (nothing written)
 */
int vor_triangles_count(const vor_t *d, uint32_t *count);

/*
 * The T triangles of d and their adjacency into triangles[0 .. 3 T) and
 * halfedges[0 .. 3 T) (the convention above); halfedges may be NULL (the
 * triangles alone). capacity: the triangles each array has room for (3
 * capacity entries). *count receives T. Cost: O(T log T), no memory
 * beyond the two arrays.
 *   VOR_ERR_ARG     d or count NULL, triangles NULL with capacity > 0
 *   VOR_ERR_BUFFER  T > capacity: *count receives T, nothing is written
 *                   to the arrays
 * On any other failure nothing is written.
 */
int vor_triangles_export(const vor_t *d, uint32_t *triangles, uint32_t *halfedges,
                         uint32_t capacity, uint32_t *count);

/*
 * A tracker follows a moving query point, such as a robot: it keeps the
 * last answer's Voronoi cell as a few bisector tests (VOR_TRACKER_EDGES at
 * most), so while the point stays in that cell an answer costs a
 * multiply-accumulate pair per edge, with no walk through the mesh. When
 * the point leaves the cell, or the diagram changed, it asks vor_nearest
 * with the last answer as the hint and caches the new cell. Answers are
 * exactly those of vor_nearest. The tracker belongs to the caller (its
 * size is a constant expression of VOR_TRACKER_EDGES); the diagram is
 * only read, so any number of trackers may follow one diagram at once.
 */
typedef struct vor_tracker_edge {
    /* 2 (neighbour - site), |.| < 2^31 */
    int32_t twice_dx;
    int32_t twice_dy;
    int64_t square;             /* |neighbour - site|^2 < 2^61 */
} vor_tracker_edge_t;

typedef struct vor_tracker {
    const vor_t *d;
    uint32_t revision;  /* d->revision when the cell was cached */
    uint32_t site;      /* the last answer; VOR_NO_HINT before the first */
    uint32_t edges;     /* the cached cell's edges, when cached */
    int cached;         /* 1: the cell below is the site's whole cell */
    vor_point_t at;     /* the site's coordinates */
    /* where the int64 tests are exact (q - at fits int32) */
    vor_point_t low;
    vor_point_t high;
    vor_tracker_edge_t edge[VOR_TRACKER_EDGES];
    vor_index_t neighbour[VOR_TRACKER_EDGES]; /* the site across each edge */
} vor_tracker_t;

/* Starts a tracker on diagram d (no answer yet, nothing cached). A
 * tracker stays valid across every change to d, vor_init of the same
 * vor_t included: d->revision never repeats a value the tracker cached
 * (vor_init moves it on too), so after any change vor_track searches
 * afresh and answers for the current diagram.
 *   VOR_ERR_CONFIG the library was compiled with another VOR_TRACKER_EDGES
 *                  (or other vor_config.h options) than this file
 *   VOR_ERR_ARG    tracker or d NULL
 * On failure *tracker is unchanged. vor_tracker_begin_checked is the
 * library's symbol, called with the application's VOR_CONFIG_FINGERPRINT. */
int vor_tracker_begin_checked(vor_tracker_t *tracker, const vor_t *d, uint32_t config);
static inline int vor_tracker_begin(vor_tracker_t *tracker, const vor_t *d)
{
    return vor_tracker_begin_checked(tracker, d, VOR_CONFIG_FINGERPRINT);
}

/*
 * The site nearest to q as vor_nearest answers it (exact, ties to
 * the smaller id), starting from the tracker's last answer. Cost: a
 * multiply pair per cached edge while q stays in the last answer's
 * cell; otherwise vor_nearest from the last answer, plus caching the new
 * cell (its edges are exact in int64 when the cell's neighbours lie within
 * 2^30 of its site on each axis; otherwise nothing is cached).
 *   VOR_ERR_ARG    tracker, its diagram or site NULL
 *   VOR_ERR_EMPTY  the diagram has no sites
 * On failure the tracker is unchanged.
 */
int vor_track(vor_tracker_t *tracker, vor_point_t q, uint32_t *site);

#ifdef __cplusplus
}
#endif

#endif
