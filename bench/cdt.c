/* SPDX-License-Identifier: MIT */
/*
 * bench/cdt.c - cost of vor_constrain per constraint, on any port, beside
 * the build it starts from.
 *
 * 1,000 and 10,000 uniform sites in [0, 2^25)^2 (a fixed generator, the
 * same on every target) are built with vor_build, constraint memory is
 * attached (vor_cdt_attach), and one segment per cell of a grid of about
 * n / 10 square cells is constrained, in a shuffled order, as in
 * tools/peer-bench/cdt.cpp:
 *
 *   disjoint   two random sites of the cell (segments in disjoint cells
 *              never cross);
 *   crossing   a random site of the cell to a random site of one of its
 *              eight neighbours (they cross one another: crossing vertices).
 *
 * Each set starts from a fresh build. Prints per size
 *
 *   bench build N COST UNIT                 vor_init + vor_build, per site
 *   bench attach N COST UNIT                vor_cdt_attach, per site
 *   bench constrain-disjoint N COST UNIT    per vor_constrain, N segments
 *   bench constrain-crossing N COST UNIT    per vor_constrain, N segments
 *   bench crossings N C                     C crossing vertices of the N
 *   bench memory N BYTES                    the constraint memory attached
 *
 * where COST is the vor_port_counter() delta with one decimal
 * (instructions under QEMU -icount on targets, nanoseconds on the host)
 * and N is the count it is divided by. Checks outside the counted part:
 * vor_validate; the constrained triangulation has 2 C more triangles than
 * the Delaunay one of the sites (Euler: the same hull, C more vertices);
 * on the disjoint set the constrained edges are exactly the segments, and
 * on the crossing set their number is the segments' plus 2 C (every
 * crossing splits two of them). "bench valid ok" ends a good run.
 * tools/peer-bench/run.sh collects the lines for docs/benchmarks.md.
 */
#include "test.h"
#include "vor.h"
#include "vor_cdt.h"

#define MAX_SITES 10000u
#define SITES_PER_CELL 10u
#define MAX_SEGMENTS (MAX_SITES / SITES_PER_CELL)
/* Crossings up to four a segment; every piece of every segment an edge
 * entry; a segment crossing up to 512 triangles between two vertices on
 * it (these cross a few dozen). */
#define MAX_CROSSINGS (4u * MAX_SEGMENTS)
#define MAX_EDGES ((2u * MAX_SEGMENTS) + (2u * MAX_CROSSINGS) + 16u)
#define MAX_CUT 512u
#define SPAN (1 << 25)

static vor_point_t points[MAX_SITES];
static uint8_t arena[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static uint8_t walls[VOR_CDT_BYTES(MAX_SITES, MAX_EDGES, MAX_CROSSINGS, MAX_CUT)]
    __attribute__((aligned(VOR_CDT_ALIGN)));
static vor_t diagram;

/* Sites of each grid cell: cell_start[c] .. cell_start[c + 1] in by_cell. */
static uint32_t by_cell[MAX_SITES];
static uint32_t cell_start[MAX_SEGMENTS + 2u];
static uint32_t seg_a[MAX_SEGMENTS];
static uint32_t seg_b[MAX_SEGMENTS];
/* one bit a vertex id: the crossing vertices seen */
static uint32_t seen[(MAX_SITES + MAX_CROSSINGS + 31u) / 32u];

enum set { DISJOINT, CROSSING };

static uint32_t grid_side(uint32_t n)
{
    uint32_t side = 1;
    while ((side + 1u) * (side + 1u) * SITES_PER_CELL <= n) {
        side++;
    }
    return side;
}

static uint32_t cell_of(vor_point_t p, uint32_t side)
{
    uint32_t size = ((uint32_t)SPAN + side - 1u) / side;
    return ((uint32_t)p.y / size) * side + (uint32_t)p.x / size;
}

/* Counting sort of the sites by cell. */
static void sort_by_cell(uint32_t n, uint32_t side)
{
    uint32_t cells = side * side;
    for (uint32_t c = 0; c <= cells + 1u; c++) {
        cell_start[c] = 0;
    }
    for (uint32_t i = 0; i < n; i++) {
        cell_start[cell_of(points[i], side) + 2u]++;
    }
    for (uint32_t c = 2; c <= cells + 1u; c++) {
        cell_start[c] += cell_start[c - 1u];
    }
    for (uint32_t i = 0; i < n; i++) {
        by_cell[cell_start[cell_of(points[i], side) + 1u]++] = i;
    }
}

static uint32_t pick(test_rng_t *rng, uint32_t cell)
{
    uint32_t count = cell_start[cell + 1u] - cell_start[cell];
    return by_cell[cell_start[cell] + test_rng_u32(rng) % count];
}

/* One segment per cell (see the top comment), shuffled; returns their number. */
static uint32_t make_segments(test_rng_t *rng, uint32_t n, enum set set)
{
    uint32_t side = grid_side(n);
    sort_by_cell(n, side);
    uint32_t count = 0;
    for (uint32_t c = 0; c < side * side; c++) {
        uint32_t here = cell_start[c + 1u] - cell_start[c];
        if (set == DISJOINT) {
            if (here < 2u) {
                continue;
            }
            uint32_t i = test_rng_u32(rng) % here;
            uint32_t j = test_rng_u32(rng) % (here - 1u);
            seg_a[count] = by_cell[cell_start[c] + i];
            seg_b[count] = by_cell[cell_start[c] + j + ((j >= i) ? 1u : 0u)];
            count++;
            continue;
        }
        if (here == 0u) {
            continue;
        }
        int32_t cx = (int32_t)(c % side);
        int32_t cy = (int32_t)(c / side);
        int32_t nx;
        int32_t ny;
        do { /* a neighbour inside the grid, one of the eight */
            nx = cx + test_rng_range(rng, -1, 1);
            ny = cy + test_rng_range(rng, -1, 1);
        } while (((nx == cx) && (ny == cy)) || (nx < 0) || (ny < 0) || (nx >= (int32_t)side) ||
                 (ny >= (int32_t)side));
        uint32_t there = (uint32_t)ny * side + (uint32_t)nx;
        if (cell_start[there + 1u] != cell_start[there]) {
            seg_a[count] = pick(rng, c);
            seg_b[count] = pick(rng, there);
            count++;
        }
    }
    for (uint32_t i = count; i > 1u; i--) {
        uint32_t j = test_rng_u32(rng) % i;
        uint32_t a = seg_a[i - 1u];
        uint32_t b = seg_b[i - 1u];
        seg_a[i - 1u] = seg_a[j];
        seg_b[i - 1u] = seg_b[j];
        seg_a[j] = a;
        seg_b[j] = b;
    }
    return count;
}

static void report(const char *name, uint32_t count, uint64_t spent)
{
    uint64_t tenths = (spent * 10u + count / 2u) / count;
    test_printf("bench %s %u %u.%u %s\n", name, (unsigned)count, (unsigned)(tenths / 10u),
                (unsigned)(tenths % 10u), vor_port_counter_unit);
}

static uint32_t delaunay_triangles(void)
{
    vor_triangle_iter_t it;
    uint32_t ids[3];
    uint32_t count = 0;
    vor_triangles_begin(&it, &diagram);
    while (vor_triangles_next(&it, ids) != 0) {
        count++;
    }
    return count;
}

/* The checks of the top comment; *crossings gets C. */
static bool check(uint32_t n, enum set set, uint32_t segments, uint32_t *crossings)
{
    bool ok = vor_validate(&diagram, NULL) == VOR_OK;
    for (uint32_t w = 0; w < (MAX_SITES + MAX_CROSSINGS + 31u) / 32u; w++) {
        seen[w] = 0;
    }
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    uint32_t triangles = 0;
    *crossings = 0;
    ok &= vor_cdt_triangles_begin(&it, &diagram) == VOR_OK;
    while (vor_cdt_triangles_next(&it, ids) != 0) {
        triangles++;
        for (unsigned k = 0; k < 3u; k++) {
            uint32_t v = ids[k];
            if ((v >= n) && ((seen[v / 32u] >> (v % 32u)) & 1u) == 0u) {
                seen[v / 32u] |= 1u << (v % 32u);
                (*crossings)++;
            }
        }
    }
    ok &= triangles == delaunay_triangles() + 2u * *crossings;
    vor_cdt_edge_iter_t e;
    uint32_t a;
    uint32_t b;
    uint32_t edges = 0;
    ok &= vor_cdt_edges_begin(&e, &diagram) == VOR_OK;
    while (vor_cdt_edges_next(&e, &a, &b) != 0) {
        edges++;
        if (set == DISJOINT) {
            bool found = false;
            for (uint32_t s = 0; (s < segments) && !found; s++) {
                found = ((seg_a[s] == a) && (seg_b[s] == b)) || ((seg_a[s] == b) && (seg_b[s] == a));
            }
            ok &= found;
        }
    }
    ok &= edges == segments + 2u * *crossings;
    if (!ok) {
        test_printf("bench %u sites, %s set: check failed\n", (unsigned)n,
                    (set == DISJOINT) ? "disjoint" : "crossing");
    }
    return ok;
}

/* The limits for n sites: MAX_* scaled to their n / 10 segments. */
static vor_cdt_limits_t limits_for(uint32_t n)
{
    uint32_t segments = n / SITES_PER_CELL;
    vor_cdt_limits_t limits = {(2u * segments) + (8u * segments) + 16u, 4u * segments, MAX_CUT};
    return limits;
}

static size_t walls_bytes(uint32_t n)
{
    vor_cdt_limits_t limits = limits_for(n);
    return VOR_CDT_BYTES(n, limits.edges, limits.crossings, limits.cut);
}

/* Builds n sites and attaches constraint memory; reports both when `counted`. */
static bool build(uint32_t n, bool counted)
{
    vor_cdt_limits_t limits = limits_for(n);
    uint64_t start = vor_port_counter();
    bool ok = (vor_init(&diagram, arena, sizeof arena, n) == VOR_OK) &&
              (vor_build(&diagram, points, n, NULL, NULL) == VOR_OK);
    uint64_t built = vor_port_counter();
    ok = ok && (vor_cdt_attach(&diagram, walls, walls_bytes(n), &limits) == VOR_OK);
    uint64_t attached = vor_port_counter();
    if (counted) {
        report("build", n, built - start);
        report("attach", n, attached - built);
    }
    return ok;
}

static bool run(uint32_t n)
{
    test_rng_t rng;
    test_rng_seed(&rng, 0xCD7u + n);
    for (uint32_t i = 0; i < n; i++) {
        points[i].x = (int32_t)(test_rng_u32(&rng) >> 7);
        points[i].y = (int32_t)(test_rng_u32(&rng) >> 7);
    }
    bool ok = true;
    for (unsigned kind = DISJOINT; kind <= (unsigned)CROSSING; kind++) {
        enum set set = (kind == (unsigned)DISJOINT) ? DISJOINT : CROSSING;
        uint32_t segments = make_segments(&rng, n, set);
        ok &= build(n, set == DISJOINT);
        uint64_t start = vor_port_counter();
        for (uint32_t s = 0; s < segments; s++) {
            ok &= vor_constrain(&diagram, seg_a[s], seg_b[s]) == VOR_OK;
        }
        uint64_t spent = vor_port_counter() - start;
        report((set == DISJOINT) ? "constrain-disjoint" : "constrain-crossing", segments, spent);
        uint32_t crossings;
        ok &= check(n, set, segments, &crossings);
        if (set == CROSSING) {
            test_printf("bench crossings %u %u\n", (unsigned)segments, (unsigned)crossings);
            test_printf("bench memory %u %u\n", (unsigned)n, (unsigned)walls_bytes(n));
        }
    }
    return ok;
}

int main(void)
{
    vor_port_init();
    bool ok = run(1000u);
    ok &= run(MAX_SITES);
    if (ok) {
        test_printf("bench valid ok\n");
    }
    return ok ? 0 : 1;
}
