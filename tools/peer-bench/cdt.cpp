/* SPDX-License-Identifier: MIT */
// tools/peer-bench/cdt.cpp - `make bench-cdt`, host part: constrained
// Delaunay triangulations, vor (vor_build, vor_cdt_attach, vor_constrain)
// against CGAL's Constrained_Delaunay_triangulation_2, artem-ogre's CDT
// and delaunay32, on the same sites and segments in one process run.
//
//   cdt-host [--sizes N,N,..] [--reps R] [--only SET] [--crossing-max N]
//            [--out FILE]
//
// Sites: n points uniform in [0, 2^30)^2 (splitmix64 seeded by n),
// duplicates dropped; every library's coordinates are these integers
// (exact doubles for CGAL and CDT). The plane is cut into a grid of about
// n / 10 square cells, and each set has one segment per cell, in a shuffled
// order:
//
//   disjoint   two random sites of the cell: segments in disjoint convex
//              cells never cross;
//   crossing   a random site of the cell to a random site of one of its
//              eight neighbours: segments about one to two cells long that
//              cross one another, each crossing a new vertex.
//
// Each library builds the triangulation of the sites (timed as "build":
// vor_init, vor_build and vor_cdt_attach; CGAL's range insert with the
// vertex handles collected; CDT's insertVertices), then inserts the
// segments one after another ("constrain": vor_constrain per segment,
// CGAL's insert_constraint per segment, CDT's insertEdges on the whole
// set). Sizes default to 10^4, 10^5 and 10^6; the crossing set runs only
// up to --crossing-max sites (default 10^5: vor takes minutes a run at
// 10^6). The libraries take turns within each of R repetitions (default 5;
// at least 21 up to 10^4 sites, where a run takes a millisecond and the
// other jobs of a shared machine show) and the median is reported, with
// ratios peer / vor (above 1: vor is faster). Times are the thread's CPU
// time (cpu_s), not wall time. Allocation and page faults are timed;
// destruction is not.
//
// The peers and their modes: CGAL with exact predicates and no
// intersection support (Epick, No_constraint_intersection_tag) on the
// disjoint set, and exact constructions with exact intersections (Epeck,
// Exact_intersections_tag) on both; CDT in its plain mode (DontCheck: the
// caller promises no crossings) on the disjoint set and in the mode that
// resolves crossings (TryResolve: a crossing becomes a vertex at a rounded
// floating-point point) on both. delaunay32 takes points and constraints
// in one triangulate() call: its constrain time is that call's minus the
// same call without constraints, on the disjoint set; it refuses crossing
// constraints (it throws), which the crossing row records.
//
// Checks on every row: vor_validate passes; vor's, CGAL's and CDT's
// triangles, vertices (sites and crossings) and constrained edges (the
// pieces between vertices) agree, and delaunay32's triangles with vor's;
// a failed check marks the row and makes the exit status 1.

#include "vor.h"
#include "vor_cdt.h"

#include "bench_common.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#ifdef VOR_BENCH_CDT
#include <CDT.h>
#endif
#ifdef VOR_BENCH_DELAUNAY32
#include <delaunay32/delaunay.hpp>
#endif

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

static const int32_t SPAN = 1 << 30;
static const uint32_t SITES_PER_CELL = 10;

struct rng : splitmix64 {
    int32_t coordinate() { return (int32_t)(next() >> 34); } // [0, 2^30)
    uint32_t below(uint32_t n) { return (uint32_t)(next() % n); }
};

struct segment {
    uint32_t a, b; // site indices
};

enum set_kind { DISJOINT, CROSSING };
static const char *const set_name[] = {"disjoint", "crossing"};

static std::vector<vor_point_t> make_sites(uint32_t n)
{
    rng r{0xCD7ull * 1000003u + n};
    std::unordered_set<uint64_t> seen;
    std::vector<vor_point_t> p;
    p.reserve(n);
    while (p.size() < n) {
        vor_point_t q = {r.coordinate(), r.coordinate()};
        if (seen.insert(((uint64_t)(uint32_t)q.x << 32) | (uint32_t)q.y).second) {
            p.push_back(q);
        }
    }
    return p;
}

// One segment per grid cell (see the top comment), shuffled.
static std::vector<segment> make_segments(const std::vector<vor_point_t> &sites, set_kind k)
{
    uint32_t n = (uint32_t)sites.size();
    uint32_t side = 1;
    while ((uint64_t)(side + 1) * (side + 1) * SITES_PER_CELL <= n) {
        side++;
    }
    const int64_t cell_size = ((int64_t)SPAN + side - 1) / side;
    std::vector<std::vector<uint32_t>> cell((size_t)side * side);
    for (uint32_t i = 0; i < n; i++) {
        size_t cx = (size_t)(sites[i].x / cell_size), cy = (size_t)(sites[i].y / cell_size);
        cell[cy * side + cx].push_back(i);
    }
    rng r{0x5E6ull * 1000003u + n * 2u + (uint32_t)k};
    std::vector<segment> segs;
    for (uint32_t cy = 0; cy < side; cy++) {
        for (uint32_t cx = 0; cx < side; cx++) {
            const std::vector<uint32_t> &here = cell[(size_t)cy * side + cx];
            if (k == DISJOINT) {
                if (here.size() < 2) {
                    continue;
                }
                uint32_t i = r.below((uint32_t)here.size());
                uint32_t j = r.below((uint32_t)here.size() - 1);
                segs.push_back({here[i], here[j + (j >= i ? 1u : 0u)]});
                continue;
            }
            if (here.empty()) {
                continue;
            }
            int nx, ny;
            do { // a neighbour inside the grid, one of the eight
                nx = (int)cx + (int)r.below(3) - 1;
                ny = (int)cy + (int)r.below(3) - 1;
            } while ((nx == (int)cx && ny == (int)cy) || nx < 0 || ny < 0 || nx >= (int)side ||
                     ny >= (int)side);
            const std::vector<uint32_t> &there = cell[(size_t)ny * side + (size_t)nx];
            if (!there.empty()) {
                segs.push_back({here[r.below((uint32_t)here.size())],
                                there[r.below((uint32_t)there.size())]});
            }
        }
    }
    for (size_t i = segs.size(); i > 1; i--) {
        std::swap(segs[i - 1], segs[r.below((uint32_t)i)]);
    }
    return segs;
}

// What a library's triangulation holds after the constraints, for the checks.
struct counts {
    long long triangles = -1, vertices = -1, constrained = -1;
};

struct timing {
    double build = -1, constrain = -1; // seconds
    counts c;
    std::string note;
};

// -------------------------------------------------------------------- vor

// Constraint memory limits: crossings up to four a segment on the crossing
// set (none on the disjoint one), every piece of every segment an edge
// entry, and a segment crossing at most 4,096 triangles between two of its
// vertices (the segments here cross a few dozen).
static vor_cdt_limits_t vor_limits(uint32_t segments, set_kind k)
{
    vor_cdt_limits_t limits;
    limits.crossings = (k == CROSSING) ? 4u * segments : 0u;
    limits.edges = 2u * segments + 2u * limits.crossings + 16u;
    limits.cut = 4096u;
    return limits;
}

static void *aligned_block(std::vector<uint8_t> &store, size_t bytes, size_t align)
{
    store.assign(bytes + align, 0);
    uintptr_t base = (uintptr_t)store.data();
    return store.data() + ((align - base % align) % align);
}

static timing run_vor(const std::vector<vor_point_t> &sites, const std::vector<segment> &segs,
                      set_kind k, bool check)
{
    timing t;
    uint32_t n = (uint32_t)sites.size();
    vor_cdt_limits_t limits = vor_limits((uint32_t)segs.size(), k);
    size_t cdt_bytes = VOR_CDT_BYTES(n, limits.edges, limits.crossings, limits.cut);
    double t0 = cpu_s();
    std::vector<uint8_t> arena_store, cdt_store;
    void *arena = aligned_block(arena_store, VOR_ARENA_BYTES(n), VOR_ARENA_ALIGN);
    void *cdt = aligned_block(cdt_store, cdt_bytes, VOR_CDT_ALIGN);
    vor_t d;
    if (vor_init(&d, arena, VOR_ARENA_BYTES(n), n) != VOR_OK ||
        vor_build(&d, sites.data(), n, nullptr, nullptr) != VOR_OK ||
        vor_cdt_attach(&d, cdt, cdt_bytes, &limits) != VOR_OK) {
        die("vor_build or vor_cdt_attach failed");
    }
    double t1 = cpu_s();
    for (const segment &s : segs) {
        int err = vor_constrain(&d, s.a, s.b);
        if (err != VOR_OK) {
            std::fprintf(stderr, "vor_constrain(%u, %u): %d\n", s.a, s.b, err);
            die("vor_constrain failed (a limit too small?)");
        }
    }
    double t2 = cpu_s();
    t.build = t1 - t0;
    t.constrain = t2 - t1;
    if (check) {
        if (vor_validate(&d, nullptr) != VOR_OK) {
            t.note = "vor_validate failed";
        }
        vor_cdt_triangle_iter_t it;
        uint32_t ids[3];
        std::unordered_set<uint32_t> vertices;
        t.c.triangles = 0;
        vor_cdt_triangles_begin(&it, &d);
        while (vor_cdt_triangles_next(&it, ids) == 1) {
            t.c.triangles++;
            vertices.insert(ids, ids + 3);
        }
        t.c.vertices = (long long)vertices.size();
        vor_cdt_edge_iter_t e;
        uint32_t a, b;
        t.c.constrained = 0;
        vor_cdt_edges_begin(&e, &d);
        while (vor_cdt_edges_next(&e, &a, &b) == 1) {
            t.c.constrained++;
        }
    }
    return t;
}

// ------------------------------------------------------------------- CGAL

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

template <class K, class Itag> struct cgal_types {
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
    using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, Itag>;
};

template <class K, class Itag>
static timing run_cgal(const std::vector<vor_point_t> &sites, const std::vector<segment> &segs,
                       bool check)
{
    using Cdt = typename cgal_types<K, Itag>::Cdt;
    timing t;
    std::vector<std::pair<typename K::Point_2, uint32_t>> in;
    in.reserve(sites.size());
    for (uint32_t i = 0; i < sites.size(); i++) {
        in.push_back({typename K::Point_2(sites[i].x, sites[i].y), i});
    }
    double t0 = cpu_s();
    Cdt cdt;
    cdt.insert(in.begin(), in.end()); // spatially sorted, with info
    std::vector<typename Cdt::Vertex_handle> handle(sites.size());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        handle[v->info()] = v;
    }
    double t1 = cpu_s();
    for (const segment &s : segs) {
        cdt.insert_constraint(handle[s.a], handle[s.b]);
    }
    double t2 = cpu_s();
    t.build = t1 - t0;
    t.constrain = t2 - t1;
    if (check) {
        t.c.triangles = (long long)cdt.number_of_faces();
        t.c.vertices = (long long)cdt.number_of_vertices();
        t.c.constrained = 0;
        for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
            t.c.constrained += cdt.is_constrained(*e) ? 1 : 0;
        }
    }
    return t;
}

// ----------------------------------------------------------- CDT (artem-ogre)

#ifdef VOR_BENCH_CDT
static timing run_cdt(const std::vector<vor_point_t> &sites, const std::vector<segment> &segs,
                      CDT::IntersectingConstraintEdges::Enum mode, bool check)
{
    timing t;
    std::vector<CDT::V2d<double>> points(sites.size());
    for (size_t i = 0; i < sites.size(); i++) {
        points[i] = CDT::V2d<double>(sites[i].x, sites[i].y);
    }
    std::vector<CDT::Edge> edges;
    edges.reserve(segs.size());
    for (const segment &s : segs) {
        edges.push_back(CDT::Edge(s.a, s.b));
    }
    double t0 = cpu_s();
    CDT::Triangulation<double> cdt(CDT::VertexInsertionOrder::Auto, mode, 0.0);
    cdt.insertVertices(points);
    double t1 = cpu_s();
    cdt.insertEdges(edges);
    double t2 = cpu_s();
    t.build = t1 - t0;
    t.constrain = t2 - t1;
    if (check) {
        cdt.eraseSuperTriangle();
        t.c.triangles = (long long)cdt.triangles.size();
        t.c.vertices = (long long)cdt.vertices.size();
        t.c.constrained = (long long)cdt.fixedEdges.size();
    }
    return t;
}
#endif

// ------------------------------------------------------------- delaunay32

#ifdef VOR_BENCH_DELAUNAY32
// build: triangulate() without constraints; constrain: with them, less
// that. Crossing constraints throw: the note says so.
static timing run_delaunay32(const std::vector<vor_point_t> &sites,
                             const std::vector<segment> &segs, bool check)
{
    timing t;
    std::vector<delaunay32::Point> points(sites.size());
    for (size_t i = 0; i < sites.size(); i++) {
        points[i] = {sites[i].x, sites[i].y};
    }
    std::vector<delaunay32::Constraint> constraints(segs.size());
    for (size_t i = 0; i < segs.size(); i++) {
        constraints[i] = {segs[i].a, segs[i].b};
    }
    double t0 = cpu_s();
    {
        delaunay32::Triangulator plain;
        plain.set_points(points);
        plain.triangulate();
    }
    double t1 = cpu_s();
    delaunay32::Triangulator tri;
    tri.set_points(points);
    tri.set_constraints(constraints);
    delaunay32::TriangulationResult result;
    try {
        result = tri.triangulate();
    } catch (const std::exception &e) {
        t.note = std::string("refused: ") + e.what();
        return t;
    }
    double t2 = cpu_s();
    t.build = t1 - t0;
    t.constrain = (t2 - t1) - (t1 - t0);
    if (check) {
        t.c.triangles = (long long)result.triangles.size();
    }
    return t;
}
#endif

// ------------------------------------------------------------------- main

// One library's column of a row: its runs, its checks' counts, its note.
struct column {
    const char *name;
    std::vector<double> build, constrain;
    counts c;
    std::string note;
    bool ran = false;

    explicit column(const char *library) : name(library) {}

    void add(const timing &t)
    {
        if (!ran) {
            c = t.c;
            note = t.note;
            ran = true;
        }
        build.push_back(t.build);
        constrain.push_back(t.constrain);
    }
};

int main(int argc, char **argv)
{
    bench_program = "cdt-host";
    std::vector<uint32_t> sizes = {10000, 100000, 1000000};
    uint32_t reps = 5, crossing_max = 100000;
    const char *out_path = nullptr;
    std::string only;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--sizes" && i + 1 < argc) {
            sizes = parse_sizes(argv[++i], 100, 2000000);
        } else if (a == "--reps" && i + 1 < argc) {
            reps = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--only" && i + 1 < argc) {
            only = argv[++i];
        } else if (a == "--crossing-max" && i + 1 < argc) {
            crossing_max = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--out" && i + 1 < argc) {
            out_path = argv[++i];
        } else {
            usage("[--sizes N,N,..] [--reps R] [--only disjoint|crossing] [--crossing-max N] "
                  "[--out FILE]");
        }
    }
    if (reps == 0) {
        die("--reps must be positive");
    }
    if (!only.empty() && only != "disjoint" && only != "crossing") {
        die("--only takes disjoint or crossing");
    }

    std::string detail = md_head({"set", "n", "segments", "crossings", "library", "build ms",
                                  "constrain ms", "ns / segment", "total ms", "checks"});
    std::string summary = md_head({"set", "n", "segments", "vor ns / segment", "peer",
                                   "peer ns / segment", "constrain peer/vor", "total peer/vor"});
    bool all_ok = true;
    for (uint32_t n : sizes) {
        std::vector<vor_point_t> sites = make_sites(n);
        for (set_kind k : {DISJOINT, CROSSING}) {
            if ((!only.empty() && only != set_name[k]) || (k == CROSSING && n > crossing_max)) {
                continue;
            }
            std::vector<segment> segs = make_segments(sites, k);
            std::vector<column> cols;
            cols.emplace_back("vor");
            if (k == DISJOINT) {
                cols.emplace_back("CGAL Epick, no intersections");
            }
            cols.emplace_back("CGAL Epeck, exact intersections");
#ifdef VOR_BENCH_CDT
            if (k == DISJOINT) {
                cols.emplace_back("CDT, DontCheck");
            }
            cols.emplace_back("CDT, TryResolve");
#else
            cols.emplace_back("CDT");
            cols.back().note = "skipped: peer sources not found";
#endif
            cols.emplace_back("delaunay32");
#ifndef VOR_BENCH_DELAUNAY32
            cols.back().note = "skipped: peer sources not found";
#endif
            uint32_t row_reps = (n <= 10000u) ? std::max(reps, 21u) : reps;
            for (uint32_t rep = 0; rep < row_reps; rep++) {
                bool check = rep == 0;
                for (column &col : cols) {
                    std::string name = col.name;
                    if (name == "vor") {
                        col.add(run_vor(sites, segs, k, check));
                    } else if (name == "CGAL Epick, no intersections") {
                        col.add(run_cgal<Epick, CGAL::No_constraint_intersection_tag>(sites, segs,
                                                                                     check));
                    } else if (name == "CGAL Epeck, exact intersections") {
                        col.add(run_cgal<Epeck, CGAL::Exact_intersections_tag>(sites, segs, check));
#ifdef VOR_BENCH_CDT
                    } else if (name == "CDT, DontCheck") {
                        col.add(run_cdt(sites, segs, CDT::IntersectingConstraintEdges::DontCheck,
                                        check));
                    } else if (name == "CDT, TryResolve") {
                        col.add(run_cdt(sites, segs, CDT::IntersectingConstraintEdges::TryResolve,
                                        check));
#endif
#ifdef VOR_BENCH_DELAUNAY32
                    } else if (name == "delaunay32" && (rep == 0 || col.note.empty())) {
                        col.add(run_delaunay32(sites, segs, check));
#endif
                    }
                }
                std::fprintf(stderr, "%s n=%u rep %u done\n", set_name[k], n, rep + 1);
            }

            // checks against vor's counts
            const column &v = cols[0];
            bool row_ok = v.note.empty();
            for (column &col : cols) {
                if (&col == &v || !col.ran || !col.note.empty()) {
                    continue;
                }
                std::string bad;
                auto compare = [&](const char *what, long long theirs, long long ours) {
                    if (theirs >= 0 && theirs != ours) {
                        bad += std::string(bad.empty() ? "" : ", ") + what + " " +
                               std::to_string(theirs) + " vs " + std::to_string(ours);
                    }
                };
                compare("triangles", col.c.triangles, v.c.triangles);
                compare("vertices", col.c.vertices, v.c.vertices);
                compare("constrained edges", col.c.constrained, v.c.constrained);
                if (!bad.empty() && k == CROSSING && std::string(col.name).rfind("CDT", 0) == 0) {
                    // CDT rounds each crossing to a double point: a count
                    // apart from the exact ones is its answer, reported only
                    col.note = "rounded crossings: " + bad + " (vor, CGAL)";
                } else if (!bad.empty()) {
                    col.note = "differs from vor: " + bad;
                    row_ok = false;
                }
            }
            all_ok &= row_ok;

            long long crossings = v.c.vertices - (long long)n;
            double vor_constrain = median(v.constrain), vor_total = vor_constrain + median(v.build);
            for (const column &col : cols) {
                double b = median(col.build), c = median(col.constrain);
                double total = (b < 0 || c < 0) ? -1 : b + c;
                std::string checks = col.note.empty() ? "ok" : col.note;
                if (&col == &v && col.note.empty()) {
                    checks = "ok (vor_validate)";
                }
                detail += md_row({set_name[k], with_commas(n), with_commas(segs.size()),
                                  with_commas((uint64_t)std::max(0LL, crossings)), col.name,
                                  fmt("%.1f", b * 1e3), fmt("%.1f", c * 1e3),
                                  fmt("%.0f", c * 1e9 / (double)segs.size()),
                                  fmt("%.1f", total * 1e3), checks}) +
                          "\n";
                if (&col == &v) {
                    continue;
                }
                summary += md_row({set_name[k], with_commas(n), with_commas(segs.size()),
                                   fmt("%.0f", vor_constrain * 1e9 / (double)segs.size()),
                                   col.name, c < 0 ? checks : fmt("%.0f", c * 1e9 / (double)segs.size()),
                                   fmt("%.2f", c < 0 ? -1 : c / vor_constrain),
                                   fmt("%.2f", total < 0 ? -1 : total / vor_total)}) +
                           "\n";
            }
        }
    }
    publish(summary + "\n" + detail, out_path);
    return all_ok ? 0 : 1;
}
