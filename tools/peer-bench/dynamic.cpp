/* SPDX-License-Identifier: MIT */
// tools/peer-bench/dynamic.cpp - `make bench-dynamic`, host part: removing and
// moving sites of a Delaunay triangulation, vor (vor_remove, vor_move)
// against CGAL's Delaunay_triangulation_2 (remove, move), on the same
// sites and the same operations in one process run.
//
//   dynamic-host [--sizes N,N,..] [--ops K] [--reps R] [--only KIND] [--out FILE]
//
// Sites: n points uniform in [0, 2^25)^2 (splitmix64 seeded by n; exact
// doubles for CGAL), duplicates dropped. Three kinds of operations, each a
// fixed array of K (default 10,000) computed before any clock runs:
//
//   remove      min(K, n / 10) distinct random sites are removed (so that
//               the row measures removal from about n sites); for n up to
//               10,000 a second row, "remove all", removes every site, down
//               to an empty diagram;
//   small move  K random sites each move by up to 1/100 of the mean site
//               spacing 2^25 / sqrt(n) (a robot's step: nearly always no
//               triangle changes);
//   large move  K random sites each move to a uniform random point.
//
// Each library starts every kind from a fresh triangulation of the same
// sites (building is not timed) and runs the whole array; the best of R
// repetitions (default 3) is reported as nanoseconds per operation, with
// the ratio CGAL time / vor time (above 1: vor is faster). --only remove
// (small-move, large-move) runs one kind, for profiling. A move onto an
// existing site is skipped by both (vor: VOR_ERR_DUPLICATE; CGAL: move
// returns the other vertex), never counted. After each run the two agree
// on the number of vertices and faces (vor's true triangulation), and
// vor_validate passes; a mismatch marks the row and makes the exit status 1.

#include "vor.h"

#include "bench_common.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cgal_dt = CGAL::Delaunay_triangulation_2<Epick>;
using Cgal_vertex = Cgal_dt::Vertex_handle;

struct rng : splitmix64 {
    int32_t coordinate() { return (int32_t)(next() >> 39); } // [0, 2^25)
    uint32_t below(uint32_t n) { return (uint32_t)(next() % n); }
};

enum class kind { remove, small_move, large_move };

struct operation {
    uint32_t site;   // index into the site array
    vor_point_t to;  // moves only
};

static std::vector<vor_point_t> make_sites(uint32_t n)
{
    rng r{0xD1A5ull * 1000003u + n};
    std::set<std::pair<int32_t, int32_t>> seen;
    std::vector<vor_point_t> p;
    p.reserve(n);
    while (p.size() < n) {
        vor_point_t q = {r.coordinate(), r.coordinate()};
        if (seen.insert({q.x, q.y}).second) {
            p.push_back(q);
        }
    }
    return p;
}

static std::vector<operation> make_operations(const std::vector<vor_point_t> &sites, kind k,
                                              uint32_t count)
{
    uint32_t n = (uint32_t)sites.size();
    rng r{0x0B5ull * 1000003u + n * 3u + (uint32_t)k};
    std::vector<operation> ops;
    if (k == kind::remove) { // distinct sites: a partial shuffle
        std::vector<uint32_t> ids(n);
        for (uint32_t i = 0; i < n; i++) {
            ids[i] = i;
        }
        for (uint32_t i = 0; i < count && i < n; i++) {
            std::swap(ids[i], ids[i + r.below(n - i)]);
            ops.push_back({ids[i], {0, 0}});
        }
        return ops;
    }
    const int32_t reach = (int32_t)std::max(1.0, 33554432.0 / std::sqrt((double)n) / 100);
    for (uint32_t i = 0; i < count; i++) {
        operation op;
        op.site = r.below(n);
        if (k == kind::small_move) {
            const vor_point_t &s = sites[op.site];
            op.to.x = std::clamp(s.x + (int32_t)r.below(2u * (uint32_t)reach + 1u) - reach, 0,
                                 33554431);
            op.to.y = std::clamp(s.y + (int32_t)r.below(2u * (uint32_t)reach + 1u) - reach, 0,
                                 33554431);
        } else {
            op.to = {r.coordinate(), r.coordinate()};
        }
        ops.push_back(op);
    }
    return ops;
}

// -------------------------------------------------------------------- vor

struct vor_run {
    std::vector<uint8_t> arena;
    vor_t d;
};

static void build_vor(vor_run &v, const std::vector<vor_point_t> &sites)
{
    uint32_t n = (uint32_t)sites.size();
    v.arena.assign(VOR_ARENA_BYTES(n) + VOR_ARENA_ALIGN, 0);
    void *base = v.arena.data();
    size_t misalign = (uintptr_t)base % VOR_ARENA_ALIGN;
    base = v.arena.data() + (misalign ? VOR_ARENA_ALIGN - misalign : 0);
    if (vor_init(&v.d, base, VOR_ARENA_BYTES(n), n) != VOR_OK ||
        vor_build(&v.d, sites.data(), n, nullptr, nullptr) != VOR_OK) {
        die("vor_build failed");
    }
}

// Runs ops on vor (site i has id i); returns the seconds taken.
static double run_vor(vor_run &v, kind k, const std::vector<operation> &ops)
{
    double t0 = now_s();
    for (const operation &op : ops) {
        int err = (k == kind::remove) ? vor_remove(&v.d, op.site)
                                      : vor_move(&v.d, op.site, op.to, nullptr);
        if (err != VOR_OK && err != VOR_ERR_DUPLICATE) {
            die("vor_remove or vor_move failed");
        }
    }
    return now_s() - t0;
}

static uint32_t vor_faces(const vor_t *d)
{
    uint32_t count = 0, ids[3];
    vor_triangle_iter_t it;
    vor_triangles_begin(&it, d);
    while (vor_triangles_next(&it, ids)) {
        count++;
    }
    return count;
}

// ------------------------------------------------------------------- CGAL

static void build_cgal(Cgal_dt &dt, std::vector<Cgal_vertex> &handle,
                       const std::vector<vor_point_t> &sites)
{
    // one at a time along a spatial order (CGAL's own), keeping the handles
    std::vector<uint32_t> order(sites.size());
    for (uint32_t i = 0; i < order.size(); i++) {
        order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return sites[a].x != sites[b].x ? sites[a].x < sites[b].x : sites[a].y < sites[b].y;
    });
    handle.assign(sites.size(), Cgal_vertex());
    Cgal_dt::Face_handle hint;
    for (uint32_t i : order) {
        handle[i] = dt.insert(Epick::Point_2(sites[i].x, sites[i].y), hint);
        hint = handle[i]->face();
    }
}

static double run_cgal(Cgal_dt &dt, std::vector<Cgal_vertex> &handle, kind k,
                       const std::vector<operation> &ops)
{
    double t0 = now_s();
    for (const operation &op : ops) {
        if (k == kind::remove) {
            dt.remove(handle[op.site]);
        } else {
            Cgal_vertex v = dt.move(handle[op.site], Epick::Point_2(op.to.x, op.to.y));
            if (v == handle[op.site]) {
                continue; // moved; otherwise another vertex is there: skipped
            }
        }
    }
    return now_s() - t0;
}

// ------------------------------------------------------------------- main

int main(int argc, char **argv)
{
    bench_program = "dynamic-host";
    std::vector<uint32_t> sizes = {10000, 100000, 1000000};
    uint32_t ops_count = 10000, reps = 3;
    const char *out_path = nullptr;
    std::string only;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--sizes" && i + 1 < argc) {
            sizes = parse_sizes(argv[++i], 16, 2000000);
        } else if (a == "--ops" && i + 1 < argc) {
            ops_count = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--reps" && i + 1 < argc) {
            reps = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--only" && i + 1 < argc) {
            only = argv[++i];
        } else if (a == "--out" && i + 1 < argc) {
            out_path = argv[++i];
        } else {
            usage("[--sizes N,N,..] [--ops K] [--reps R] [--only KIND] [--out FILE]");
        }
    }
    if (ops_count == 0 || reps == 0) {
        die("--ops and --reps must be positive");
    }
    if (!only.empty() && only != "remove" && only != "small-move" && only != "large-move") {
        die("--only takes remove, small-move or large-move");
    }
    std::string table =
        "| operation | n | ops | vor ns/op | CGAL ns/op | CGAL/vor | checks |\n"
        "|---|---|---|---|---|---|---|\n";
    bool all_ok = true;
    const char *names[] = {"remove", "small move", "large move"};
    const char *options[] = {"remove", "small-move", "large-move"};
    for (uint32_t n : sizes) {
        std::vector<vor_point_t> sites = make_sites(n);
        // one row per kind; removals take at most a tenth of the sites, so
        // that a row measures removal from about n sites, and the smallest
        // diagrams also get a row that removes every site, down to none
        std::vector<std::pair<kind, uint32_t>> rows;
        for (kind k : {kind::remove, kind::small_move, kind::large_move}) {
            if (!only.empty() && only != options[(int)k]) {
                continue;
            }
            rows.push_back({k, k == kind::remove ? std::min(ops_count, n / 10u) : ops_count});
            if (k == kind::remove && n <= 10000u) {
                rows.push_back({k, n});
            }
        }
        for (const auto &[k, count] : rows) {
            std::vector<operation> ops = make_operations(sites, k, count);
            double best_vor = 1e30, best_cgal = 1e30;
            std::string checks = "ok";
            for (uint32_t rep = 0; rep < reps; rep++) {
                vor_run v;
                build_vor(v, sites);
                best_vor = std::min(best_vor, run_vor(v, k, ops));
                Cgal_dt dt;
                std::vector<Cgal_vertex> handle;
                build_cgal(dt, handle, sites);
                best_cgal = std::min(best_cgal, run_cgal(dt, handle, k, ops));
                if (rep == 0) {
                    vor_violation_t why;
                    if (vor_validate(&v.d, &why) != VOR_OK) {
                        checks = "vor_validate failed";
                    } else if (v.d.vertex_count != dt.number_of_vertices()) {
                        checks = "vertex counts differ";
                    } else if (vor_faces(&v.d) != dt.number_of_faces()) {
                        checks = "face counts differ";
                    }
                }
            }
            all_ok &= checks == "ok";
            double per_vor = best_vor * 1e9 / (double)ops.size();
            double per_cgal = best_cgal * 1e9 / (double)ops.size();
            char row[256];
            std::snprintf(row, sizeof row, "| %s | %s | %s | %s | %s | %s | %s |\n",
                          (k == kind::remove && count == n) ? "remove all" : names[(int)k],
                          with_commas(n).c_str(),
                          with_commas(ops.size()).c_str(), fmt("%.0f", per_vor).c_str(),
                          fmt("%.0f", per_cgal).c_str(), fmt("%.2f", per_cgal / per_vor).c_str(),
                          checks.c_str());
            table += row;
            std::fprintf(stderr, "%s", row);
        }
    }
    publish(table, out_path);
    return all_ok ? 0 : 1;
}
