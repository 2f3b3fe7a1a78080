/* SPDX-License-Identifier: MIT */
// tools/peer-bench/delaunay.cpp - `make bench`, host part: the Delaunay build of
// vor against CGAL Delaunay_triangulation_2 (Epick, range insert) and Boost
// Polygon construct_voronoi, on identical inputs in one process run.
//
//   delaunay-host [--sizes N,N,..] [--reps R] [--input-order-max N]
//                 [--out FILE] [--no-mem] [--scaling-reps R] [--scaling-csv FILE]
//   delaunay-host --mem LIB KIND N     (internal: one memory measurement)
//
// For every input kind (make_input) and size it prints one Markdown table
// row: the best of R
// wall-clock times of each library (the libraries take turns within each
// repetition; vor's incremental build and both divide-and-conquer
// variants, the quadtree's on 2 threads too), their ratios, and bytes per
// site. Then a table of time per site for uniform n = 2^7 ... 2^20 (scaling(); --scaling-reps 0 skips it),
// also written as CSV for tools/peer-bench/plot_scaling.py. Input generation and the
// conversion to each library's point type are not timed; allocation of the
// structure and its page faults are (vor: malloc of VOR_ARENA_BYTES(n),
// vor_init, vor_build; CGAL: construct and range-insert; Boost: construct
// the diagram and construct_voronoi); destruction is not.
//
// Memory: each library runs once more in a fresh child process
// (--mem), which generates the same input, resets its peak-RSS mark
// (writing 5 to /proc/self/clear_refs), runs the library and reports
// VmHWM minus the RSS just before the run, and the peak of live heap bytes
// (global operator new/delete and vor's arena malloc, counted with
// malloc_usable_size).
//
// A second table sets vor beside delaunay32 (1 and 2 threads) and
// jc_voronoi when their sources are there (see "peers" below), with vor's
// divide and conquer (quadtree) on 2 threads: vor_build_dc_forked with a
// std::thread fork/join hook (the library itself stays single-threaded).
//
// Light correctness checks on every row: vor_validate passes; vor's
// distinct sites equal CGAL's number_of_vertices() and Boost's cells; vor's
// finite triangles of nonzero area equal CGAL's number_of_faces() and
// delaunay32's triangles; and for
// inputs with no four cocircular sites (uniform full-range) Boost's Voronoi
// vertices too.
// A failed check marks the row and makes the exit status 1.

#include "vor.h"

#include "bench_common.hpp"
#include "bench_memory.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <boost/polygon/voronoi.hpp>

#ifdef VOR_BENCH_DELAUNAY32
#include <delaunay32/delaunay.hpp>
#endif
#ifdef VOR_BENCH_JCV
#include "jcv_peer.h"
#include <sys/wait.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

// ------------------------------------------------------------------ inputs

// uniform-d32: uniform within a third of the int32 range, inside
// delaunay32's exact span (1,940,470,527); grid-wide: the grid spread over
// 2^30 whatever n, so that its cocircular ties need wide arithmetic;
// field-mm: uniform on the millimetre lattice of a 100 m x 100 m field (a
// robot's map: small coordinates, a few duplicates at 10^6).
enum kind { UNIFORM, D32_SPAN, U16, GRID, GRID_WIDE, FIELD_MM, CLUSTERED, KINDS };
static const char *const kind_name[KINDS] = {"uniform",   "uniform-d32", "u16",      "grid",
                                             "grid-wide", "field-mm",    "clustered"};
static const char *const kind_label[KINDS] = {
    "uniform int32", "uniform, span / 3", "uniform 16-bit",      "grid, spacing 1,000",
    "grid, spacing 2^30 / sqrt n", "field, mm on 100 m", "clustered"};

struct rng : splitmix64 {
    double unit() { return (double)((next() >> 11) + 1) * 0x1p-53; } // (0, 1]
    uint64_t below(uint64_t m) { return next() % m; }
};

static const int32_t GRID_SPACING = 1000;
static const int32_t D32_HALF_SPAN = (int32_t)(((int64_t)1 << 32) / 6); // span 2^32 / 3
static const uint32_t FIELD_SIDE_MM = 100000;                           // 100 m
static const unsigned CLUSTERS = 300;
static const double CLUSTER_SIGMA = 300.0;
static const int32_t CLUSTER_SPREAD = 1 << 24; // centres in [-2^24, 2^24]

// Deterministic: the same kind and n give the same points in every process.
static std::vector<vor_point_t> make_input(kind k, uint32_t n)
{
    rng r{0x5EEDull * 1000003u + (uint64_t)k * 7919u + n};
    std::vector<vor_point_t> p(n);
    switch (k) {
    case UNIFORM:
        for (auto &q : p) {
            uint64_t v = r.next();
            q.x = (int32_t)(uint32_t)v;
            q.y = (int32_t)(uint32_t)(v >> 32);
        }
        break;
    case D32_SPAN:
        for (auto &q : p) {
            q.x = (int32_t)((int64_t)r.below(2u * (uint64_t)D32_HALF_SPAN) - D32_HALF_SPAN);
            q.y = (int32_t)((int64_t)r.below(2u * (uint64_t)D32_HALF_SPAN) - D32_HALF_SPAN);
        }
        break;
    case FIELD_MM:
        for (auto &q : p) {
            q.x = (int32_t)r.below(FIELD_SIDE_MM);
            q.y = (int32_t)r.below(FIELD_SIDE_MM);
        }
        break;
    case U16:
        for (auto &q : p) {
            uint64_t v = r.next();
            q.x = (int16_t)(uint16_t)v;
            q.y = (int16_t)(uint16_t)(v >> 16);
        }
        break;
    case GRID:
    case GRID_WIDE: { // first n points of a ceil(sqrt n)^2 lattice, shuffled
        uint32_t side = (uint32_t)std::ceil(std::sqrt((double)n));
        int32_t spacing = (k == GRID) ? GRID_SPACING : (int32_t)((1u << 30) / side);
        for (uint32_t i = 0; i < n; i++) {
            p[i].x = ((int32_t)(i % side) - (int32_t)(side / 2)) * spacing;
            p[i].y = ((int32_t)(i / side) - (int32_t)(side / 2)) * spacing;
        }
        for (uint32_t i = n; i > 1; i--) {
            std::swap(p[i - 1], p[r.below(i)]);
        }
        break;
    }
    case CLUSTERED: {
        std::vector<vor_point_t> centre(CLUSTERS);
        for (auto &c : centre) {
            c.x = (int32_t)((int64_t)r.below(2u * CLUSTER_SPREAD + 1) - CLUSTER_SPREAD);
            c.y = (int32_t)((int64_t)r.below(2u * CLUSTER_SPREAD + 1) - CLUSTER_SPREAD);
        }
        for (auto &q : p) { // a random cluster each, Box-Muller offsets
            const vor_point_t &c = centre[r.below(CLUSTERS)];
            double radius = CLUSTER_SIGMA * std::sqrt(-2.0 * std::log(r.unit()));
            double angle = 2.0 * M_PI * r.unit();
            q.x = c.x + (int32_t)std::lround(radius * std::cos(angle));
            q.y = c.y + (int32_t)std::lround(radius * std::sin(angle));
        }
        break;
    }
    default:
        break;
    }
    return p;
}

// --------------------------------------------------------------- libraries

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cgal_dt = CGAL::Delaunay_triangulation_2<Epick>;
using Boost_point = boost::polygon::point_data<int32_t>;
using Boost_vd = boost::polygon::voronoi_diagram<double>;

struct inputs {
    std::vector<vor_point_t> vor;
    std::vector<Epick::Point_2> cgal;
    std::vector<Boost_point> boost;
};

static void convert(inputs &in, bool cgal, bool boost)
{
    if (cgal) {
        in.cgal.reserve(in.vor.size());
        for (const auto &q : in.vor) {
            in.cgal.emplace_back((double)q.x, (double)q.y); // exact: |x| < 2^53
        }
    }
    if (boost) {
        in.boost.reserve(in.vor.size());
        for (const auto &q : in.vor) {
            in.boost.emplace_back(q.x, q.y);
        }
    }
}

struct vor_run {
    void *arena = nullptr;
    vor_t d;
    ~vor_run() { counted_free(arena); }
};

static double now_ms() { return 1e3 * now_s(); }

// vor_build in an order, or vor_build_dc with a split.
enum vor_builder { VOR_INCREMENTAL, VOR_DC_X, VOR_DC_Q, VOR_DC_Q2 };

// vor_build_dc_forked's hook with std::thread: fork starts the work on a
// new thread (thread creation is timed, as delaunay32's is), join waits
// for it (std::thread::join gives the happens-before the hook needs). The
// library itself stays single-threaded.
static int thread_fork(void *context, void (*work)(void *arg), void *arg)
{
    std::thread *worker = static_cast<std::thread *>(context);
    try {
        *worker = std::thread(work, arg);
    } catch (...) {
        return 1; // no thread: vor runs the work itself
    }
    return 0;
}

static void thread_join(void *context)
{
    static_cast<std::thread *>(context)->join();
}

static void build_vor(vor_run &v, const std::vector<vor_point_t> &p, enum vor_order order,
                      enum vor_builder builder = VOR_INCREMENTAL)
{
    uint32_t n = (uint32_t)p.size();
    size_t bytes = VOR_ARENA_BYTES(n);
    v.arena = counted_malloc(bytes);
    if (v.arena == nullptr) {
        die("out of memory");
    }
    vor_build_options_t opt = {};
    opt.order = order;
    opt.split = (builder == VOR_DC_X) ? VOR_DC_XSPLIT : VOR_DC_QUADTREE;
    if (vor_init(&v.d, v.arena, bytes, n) != VOR_OK) {
        die("vor_init failed");
    }
    std::thread worker;
    vor_fork_join_t hook = {thread_fork, thread_join, &worker};
    int err = (builder == VOR_INCREMENTAL)
                  ? vor_build(&v.d, p.data(), n, &opt, nullptr)
                  : vor_build_dc_forked(&v.d, p.data(), n, &opt, nullptr,
                                        builder == VOR_DC_Q2 ? &hook : nullptr);
    if (err != VOR_OK) {
        die("vor_build failed");
    }
}

// ------------------------------------------------------------------ peers

// delaunay32 (exact int32, divide and conquer, optional threads) and
// jc_voronoi (float Fortune sweep), built from ../shared/peers when it is
// there: tools/peer-bench/bench.mk then defines VOR_BENCH_DELAUNAY32 and
// VOR_BENCH_JCV. Their rows say "skipped" otherwise.
struct peer_result {
    double ms = -1;      // one build, -1: not measured
    long long count = -1; // delaunay32: triangles; jc_voronoi: sites kept
    double heap = -1;    // jc_voronoi: peak heap bytes
    std::string note;    // why there is no figure
};

#ifdef VOR_BENCH_DELAUNAY32
static std::vector<delaunay32::Point> d32_points(const std::vector<vor_point_t> &p)
{
    std::vector<delaunay32::Point> out(p.size());
    for (size_t i = 0; i < p.size(); i++) {
        out[i].x = p[i].x;
        out[i].y = p[i].y;
    }
    return out;
}

// Construction, set_points and triangulate are timed (as CGAL's
// construction and insert are); destruction is not. delaunay32 refuses
// inputs whose span is beyond its exact range (it throws).
static peer_result run_delaunay32(const std::vector<delaunay32::Point> &points, size_t threads)
{
    peer_result r;
    try {
        double t0 = now_ms();
        delaunay32::Triangulator t;
        delaunay32::TriangulationOptions options;
        options.thread_count = threads;
        t.set_options(options);
        t.set_points(points);
        delaunay32::TriangulationResult result = t.triangulate();
        r.ms = now_ms() - t0;
        r.count = (long long)result.triangles.size();
        if (result.report.actual_thread_count != threads) {
            r.note = "ran on " + std::to_string(result.report.actual_thread_count) + " thread(s)";
        }
    } catch (const std::exception &) {
        r.ms = -1;
        r.note = "refused";
    }
    return r;
}
#endif

#ifdef VOR_BENCH_JCV
// In a child process: a float sweep may crash or loop on inputs float
// cannot hold exactly, and the table must survive that. The child times
// the build alone (the conversion to float is not timed) and reports
// "ms sites peak-heap-bytes" through a pipe.
static peer_result run_jcv(const std::vector<vor_point_t> &p)
{
    peer_result r;
    std::vector<float> xy(2 * p.size());
    for (size_t i = 0; i < p.size(); i++) {
        xy[2 * i] = (float)p[i].x;
        xy[2 * i + 1] = (float)p[i].y;
    }
    int fd[2];
    if (pipe(fd) != 0) {
        r.note = "no pipe";
        return r;
    }
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        alarm(300);
        jcv_peer_heap heap = {0, 0};
        double t0 = now_ms();
        int sites = jcv_peer_build(xy.data(), (int)p.size(), &heap);
        double ms = now_ms() - t0;
        char line[128];
        int len = std::snprintf(line, sizeof line, "%.3f %d %zu\n", ms, sites, heap.peak);
        ssize_t written = write(fd[1], line, (size_t)len);
        _exit(written == len ? 0 : 1);
    }
    close(fd[1]);
    char line[128] = {0};
    size_t got = 0;
    while (pid > 0 && got < sizeof line - 1) {
        ssize_t k = read(fd[0], line + got, sizeof line - 1 - got);
        if (k <= 0) {
            break;
        }
        got += (size_t)k;
    }
    close(fd[0]);
    int status = 0;
    double heap = -1;
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0 ||
        std::sscanf(line, "%lf %lld %lf", &r.ms, &r.count, &heap) != 3) {
        r.ms = -1;
        r.note = "failed";
        return r;
    }
    r.heap = heap;
    return r;
}
#endif

// -------------------------------------------------------- memory (--mem)

static int mem_main(const char *lib, const char *kind_arg, uint32_t n)
{
    int k = 0;
    while (k < KINDS && std::strcmp(kind_name[k], kind_arg) != 0) {
        k++;
    }
    if (k == KINDS) {
        die("unknown input kind");
    }
    inputs in;
    in.vor = make_input((kind)k, n);
    bool is_cgal = std::strcmp(lib, "cgal") == 0, is_boost = std::strcmp(lib, "boost") == 0;
    bool is_d32 = std::strcmp(lib, "delaunay32") == 0;
    if (!is_cgal && !is_boost && !is_d32 && std::strcmp(lib, "vor") != 0) {
        die("unknown library (vor, cgal, boost or delaunay32)");
    }
    convert(in, is_cgal, is_boost);
#ifdef VOR_BENCH_DELAUNAY32
    std::vector<delaunay32::Point> d32 = is_d32 ? d32_points(in.vor)
                                                : std::vector<delaunay32::Point>();
#else
    if (is_d32) {
        die("delaunay32 not built in");
    }
#endif
    mem_child child = mem_child_start();
    if (is_cgal) {
        Cgal_dt *dt = new Cgal_dt;
        dt->insert(in.cgal.begin(), in.cgal.end());
        std::printf("check %zu\n", dt->number_of_faces());
    } else if (is_boost) {
        Boost_vd *vd = new Boost_vd;
        boost::polygon::construct_voronoi(in.boost.begin(), in.boost.end(), vd);
        std::printf("check %zu\n", vd->num_cells());
#ifdef VOR_BENCH_DELAUNAY32
    } else if (is_d32) { // one thread: the peak of its serial build
        static peer_result kept;
        kept = run_delaunay32(d32, 1);
        std::printf("check %lld\n", kept.count);
#endif
    } else {
        static vor_run v; // kept: its memory must stay in use until the end
        build_vor(v, in.vor, VOR_ORDER_QUADTREE);
        std::printf("check %u\n", v.d.vertex_count);
    }
    mem_child_finish(child);
}

static std::string self_exe;

static mem_result measure_memory(const char *lib, kind k, uint32_t n)
{
    return measure_memory(self_exe, std::string(lib) + " " + kind_name[k] + " " +
                                        std::to_string(n));
}

// ------------------------------------------------------------- the table

struct row {
    std::string input;
    uint32_t n = 0;
    uint32_t distinct = 0;
    double vor_ms = 1e300, cgal_ms = 1e300, boost_ms = 1e300, vor_input_ms = -1;
    double dc_ms = 1e300, dcq_ms = 1e300; // vor's divide and conquer: x-split, quadtree
    double dcq2_ms = 1e300;               // the quadtree on 2 threads (vor_build_dc_forked)
    double vor_arena = 0;
    mem_result vor_mem, cgal_mem, boost_mem, d32_mem;
    peer_result d32_one, d32_two, jcv; // best of the repetitions
    std::string check = "ok";
    uint32_t flat = 0;            // vor's zero-area triangles
    vor_stats_t stats{}; // of vor's first build
};

static std::string table(const std::vector<row> &rows)
{
    std::string t = md_head({"input", "n", "vor ms", "CGAL ms", "Boost ms", "CGAL/vor",
                             "Boost/vor", "vor B/site", "CGAL B/site", "Boost B/site",
                             "vor input-order ms", "vor D&C ms", "vor D&C quadtree ms"});
    for (const row &r : rows) {
        t += md_row({r.input, with_commas(r.n), fmt("%.2f", r.vor_ms), fmt("%.2f", r.cgal_ms),
                     fmt("%.2f", r.boost_ms), fmt("%.2f", r.cgal_ms / r.vor_ms),
                     fmt("%.2f", r.boost_ms / r.vor_ms), per_site(r.vor_arena, r.n),
                     per_site(r.cgal_mem.rss, r.n), per_site(r.boost_mem.rss, r.n),
                     fmt("%.2f", r.vor_input_ms), fmt("%.2f", r.dc_ms), fmt("%.2f", r.dcq_ms)});
        if (r.check != "ok") {
            t += " **check: " + r.check + "**";
        }
        t += "\n";
    }
    return t;
}

static std::string memory_table(const std::vector<row> &rows)
{
    std::string t = md_head({"input", "n", "distinct", "vor arena", "vor RSS", "vor heap",
                             "CGAL RSS", "CGAL heap", "Boost RSS", "Boost heap"});
    for (const row &r : rows) {
        t += md_row({r.input, with_commas(r.n), with_commas(r.distinct),
                     per_site(r.vor_arena, r.n), per_site(r.vor_mem.rss, r.n),
                     per_site(r.vor_mem.heap, r.n), per_site(r.cgal_mem.rss, r.n),
                     per_site(r.cgal_mem.heap, r.n), per_site(r.boost_mem.rss, r.n),
                     per_site(r.boost_mem.heap, r.n)}) +
             "\n";
    }
    return t;
}

static void add_check(row &r, bool ok, const std::string &what)
{
    if (!ok) {
        r.check = (r.check == "ok") ? what : r.check + ", " + what;
    }
}

// A peer's figure: its time, or why there is none.
static std::string peer_ms(const peer_result &p)
{
    if (p.ms < 0) {
        return p.note.empty() ? "skipped" : p.note;
    }
    return fmt("%.2f", p.ms) + (p.note.empty() ? "" : " (" + p.note + ")");
}

static std::string peer_ratio(const peer_result &p, double vor_ms)
{
    return p.ms < 0 ? "-" : fmt("%.2f", p.ms / vor_ms);
}

static void keep_best(peer_result &best, const peer_result &now)
{
    if (best.ms < 0 || (now.ms >= 0 && now.ms < best.ms)) {
        best = now;
    }
}

static std::string peer_table(const std::vector<row> &rows)
{
    std::string t = md_head({"input", "n", "vor ms", "vor 2 threads ms", "delaunay32 1 thread ms",
                             "delaunay32 2 threads ms", "jc_voronoi ms", "d32 1t/vor",
                             "d32 2t/vor", "d32 2t / vor 2t", "jcv/vor", "vor B/site",
                             "d32 heap B/site", "jcv heap B/site"});
    for (const row &r : rows) {
        t += md_row({r.input, with_commas(r.n), fmt("%.2f", r.vor_ms), fmt("%.2f", r.dcq2_ms),
                     peer_ms(r.d32_one), peer_ms(r.d32_two), peer_ms(r.jcv),
                     peer_ratio(r.d32_one, r.vor_ms), peer_ratio(r.d32_two, r.vor_ms),
                     peer_ratio(r.d32_two, r.dcq2_ms), peer_ratio(r.jcv, r.vor_ms),
                     per_site(r.vor_arena, r.n), per_site(r.d32_mem.heap, r.n),
                     per_site(r.jcv.heap, r.n)}) +
             "\n";
    }
    return t;
}

static row run_row(kind k, uint32_t n, unsigned reps, uint32_t input_order_max, bool mem)
{
    row r;
    r.input = kind_label[k];
    r.n = n;
    inputs in;
    in.vor = make_input(k, n);
    convert(in, true, true);
#ifdef VOR_BENCH_DELAUNAY32
    std::vector<delaunay32::Point> d32 = d32_points(in.vor);
#else
    r.d32_one.note = r.d32_two.note = "skipped";
#endif
#ifndef VOR_BENCH_JCV
    r.jcv.note = "skipped";
#endif

    size_t cgal_faces = 0, cgal_vertices = 0, boost_cells = 0, boost_vertices = 0;
    uint32_t vor_triangles = 0;
    bool vor_valid = true;
    for (unsigned rep = 0; rep < reps; rep++) {
        { // vor, default (quadtree) order
            vor_run v;
            double t0 = now_ms();
            build_vor(v, in.vor, VOR_ORDER_QUADTREE);
            r.vor_ms = std::min(r.vor_ms, now_ms() - t0);
            if (rep == 0) {
                vor_valid = vor_validate(&v.d, nullptr) == VOR_OK;
                r.distinct = v.d.vertex_count;
                vor_triangle_iter_t it;
                uint32_t ids[3];
                vor_triangles_begin(&it, &v.d);
                while (vor_triangles_next(&it, ids)) {
                    // the iterator reports the true triangulation: none of
                    // the perturbed mesh's zero-area triangles on the hull
                    const vor_point_t *s = v.d.sites;
                    if (vor_orient2d(s[ids[0]], s[ids[1]], s[ids[2]]) != 0) {
                        vor_triangles++;
                    } else {
                        r.flat++;
                    }
                }
                add_check(r, r.flat == 0, "vor zero-area triangles");
                vor_stats(&v.d, &r.stats);
                vor_memory_t m;
                vor_memory(&v.d, &m);
                r.vor_arena = (double)m.arena_bytes;
            }
        }
        for (int algo = 0; algo < 3; algo++) { // vor, divide and conquer
            vor_run v;
            enum vor_builder a = (algo == 0) ? VOR_DC_X : (algo == 1) ? VOR_DC_Q : VOR_DC_Q2;
            double t0 = now_ms();
            build_vor(v, in.vor, VOR_ORDER_QUADTREE, a);
            double &best = (algo == 0) ? r.dc_ms : (algo == 1) ? r.dcq_ms : r.dcq2_ms;
            best = std::min(best, now_ms() - t0);
            if (rep == 0) { // the same mesh as the incremental build's
                add_check(r, vor_validate(&v.d, nullptr) == VOR_OK, "D&C vor_validate");
                add_check(r, v.d.vertex_count == r.distinct, "D&C sites");
                uint32_t count = 0, ids[3];
                vor_triangle_iter_t it;
                vor_triangles_begin(&it, &v.d);
                while (vor_triangles_next(&it, ids)) {
                    count++;
                }
                add_check(r, count == vor_triangles + r.flat, "D&C triangles");
            }
        }
        {
            double t0 = now_ms();
            Cgal_dt *dt = new Cgal_dt;
            dt->insert(in.cgal.begin(), in.cgal.end());
            r.cgal_ms = std::min(r.cgal_ms, now_ms() - t0);
            cgal_faces = dt->number_of_faces();
            cgal_vertices = dt->number_of_vertices();
            delete dt;
        }
        {
            double t0 = now_ms();
            Boost_vd *vd = new Boost_vd;
            boost::polygon::construct_voronoi(in.boost.begin(), in.boost.end(), vd);
            r.boost_ms = std::min(r.boost_ms, now_ms() - t0);
            boost_cells = vd->num_cells();
            boost_vertices = vd->num_vertices();
            delete vd;
        }
#ifdef VOR_BENCH_DELAUNAY32
        keep_best(r.d32_one, run_delaunay32(d32, 1));
        keep_best(r.d32_two, run_delaunay32(d32, 2));
#endif
#ifdef VOR_BENCH_JCV
        keep_best(r.jcv, run_jcv(in.vor));
#endif
    }
    // delaunay32's triangles: those of a triangulation of the distinct
    // sites, as many as vor's true ones (2 v - 2 - hull sites)
    for (const peer_result *p : {&r.d32_one, &r.d32_two}) {
        add_check(r, p->ms < 0 || p->count == (long long)vor_triangles, "triangles vs delaunay32");
    }
    if (n <= input_order_max) { // once: slow by design, and its walks dominate
        vor_run v;
        double t0 = now_ms();
        build_vor(v, in.vor, VOR_ORDER_INPUT);
        r.vor_input_ms = now_ms() - t0;
        add_check(r, v.d.vertex_count == r.distinct, "input order sites");
    }
    add_check(r, vor_valid, "vor_validate");
    add_check(r, r.distinct == cgal_vertices, "sites vs CGAL");
    add_check(r, r.distinct == boost_cells, "sites vs Boost");
    add_check(r, vor_triangles == cgal_faces, "triangles vs CGAL");
    if (k == UNIFORM) {
        add_check(r, vor_triangles == boost_vertices, "triangles vs Boost");
    }
    if (mem) {
        r.vor_mem = measure_memory("vor", k, n);
        r.cgal_mem = measure_memory("cgal", k, n);
        r.boost_mem = measure_memory("boost", k, n);
        add_check(r, r.vor_mem.rss >= 0 && r.cgal_mem.rss >= 0 && r.boost_mem.rss >= 0,
                  "memory child");
#ifdef VOR_BENCH_DELAUNAY32
        if (r.d32_one.ms >= 0) {
            r.d32_mem = measure_memory("delaunay32", k, n);
        }
#endif
    }
    return r;
}

// ------------------------------------------------ scaling (time per site)

// Uniform full-range sites, n = 2^7 ... 2^20 (the axes of seed 000's
// Fig. 5.1): the best over `reps` rounds of each library's mean build time
// per site, where a round repeats the build until 20 ms have been timed
// (small n) and times each build alone (allocation and build, as in the
// main table; destruction is not timed). The libraries take turns within a
// round. Writes a Markdown table and, if csv is set, "log2n,library,ns".
static const char *const scaling_libs[] = {"vor incremental", "vor D&C", "vor D&C quadtree",
                                           "CGAL", "Boost"};
enum { SCALING_LIBS = 5 };

static double time_one(int lib, const inputs &in)
{
    double t0 = now_ms(), ms;
    if (lib < 3) {
        vor_run v;
        enum vor_builder a = (lib == 0)   ? VOR_INCREMENTAL
                             : (lib == 1) ? VOR_DC_X
                                          : VOR_DC_Q;
        build_vor(v, in.vor, VOR_ORDER_QUADTREE, a);
        ms = now_ms() - t0;
    } else if (lib == 3) {
        Cgal_dt *dt = new Cgal_dt;
        dt->insert(in.cgal.begin(), in.cgal.end());
        ms = now_ms() - t0;
        delete dt;
    } else {
        Boost_vd *vd = new Boost_vd;
        boost::polygon::construct_voronoi(in.boost.begin(), in.boost.end(), vd);
        ms = now_ms() - t0;
        delete vd;
    }
    return ms;
}

static std::string scaling(unsigned reps, const char *csv)
{
    std::string t = "| log2 n | n |";
    for (const char *name : scaling_libs) {
        t += std::string(" ") + name + " ns/site |";
    }
    t += "\n|---|---|";
    for (int lib = 0; lib < SCALING_LIBS; lib++) {
        t += "---|";
    }
    t += "\n";
    std::string lines = "log2n,library,ns_per_site\n";
    for (unsigned l = 7; l <= 20; l++) {
        uint32_t n = 1u << l;
        inputs in;
        in.vor = make_input(UNIFORM, n);
        convert(in, true, true);
        double best[SCALING_LIBS];
        for (double &b : best) {
            b = 1e300;
        }
        for (unsigned rep = 0; rep < reps; rep++) {
            for (int lib = 0; lib < SCALING_LIBS; lib++) {
                double total = 0;
                unsigned count = 0;
                while (count == 0 || total < 20.0) {
                    total += time_one(lib, in);
                    count++;
                }
                best[lib] = std::min(best[lib], total * 1e6 / count / n);
            }
        }
        t += "| " + std::to_string(l) + " | " + with_commas(n) + " |";
        for (int lib = 0; lib < SCALING_LIBS; lib++) {
            t += " " + fmt("%.0f", best[lib]) + " |";
            lines += std::to_string(l) + "," + scaling_libs[lib] + "," + fmt("%.1f", best[lib]) +
                     "\n";
        }
        t += "\n";
        std::fprintf(stderr, "scaling: 2^%u done\n", l);
    }
    if (csv != nullptr) {
        FILE *f = std::fopen(csv, "w");
        if (f == nullptr || std::fputs(lines.c_str(), f) < 0 || std::fclose(f) != 0) {
            die("cannot write --scaling-csv file");
        }
    }
    return t;
}

int main(int argc, char **argv)
{
    bench_program = "delaunay-host";
    char exe[4096];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    self_exe = (len > 0) ? std::string(exe, (size_t)len) : std::string(argv[0]);

    if (argc == 5 && std::strcmp(argv[1], "--mem") == 0) {
        return mem_main(argv[2], argv[3], (uint32_t)std::strtoul(argv[4], nullptr, 10));
    }
    std::vector<uint32_t> sizes = {10000, 100000, 1000000};
    unsigned reps = 3;
    uint32_t input_order_max = 100000; // input order is O(n^1.5): 10^6 takes a minute
    const char *out = nullptr, *scaling_csv = nullptr;
    bool mem = true;
    unsigned scaling_reps = 2; // 0: no scaling table
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--sizes" && i + 1 < argc) {
            sizes = parse_sizes(argv[++i], 2, 100000000ul);
        } else if (a == "--reps" && i + 1 < argc) {
            reps = (unsigned)std::max(1l, std::strtol(argv[++i], nullptr, 10));
        } else if (a == "--input-order-max" && i + 1 < argc) {
            input_order_max = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else if (a == "--no-mem") {
            mem = false;
        } else if (a == "--scaling-reps" && i + 1 < argc) {
            scaling_reps = (unsigned)std::max(0l, std::strtol(argv[++i], nullptr, 10));
        } else if (a == "--scaling-csv" && i + 1 < argc) {
            scaling_csv = argv[++i];
        } else {
            usage("[--sizes N,N,..] [--reps R] [--input-order-max N] [--out FILE] [--no-mem] "
                  "[--scaling-reps R] [--scaling-csv FILE]");
        }
    }

    std::vector<row> rows;
    bool ok = true;
    for (uint32_t n : sizes) {
        for (int k = 0; k < KINDS; k++) {
            rows.push_back(run_row((kind)k, n, reps, input_order_max, mem));
            const row &r = rows.back();
            ok &= r.check == "ok";
            const vor_stats_t &st = r.stats;
            std::fprintf(stderr,
                         "bench: %-14s %8u  vor %9.2f  CGAL %9.2f  Boost %9.2f ms  %s\n"
                         "       per site: orient2d %.1f (%.1f perturbed), incircle narrow "
                         "%.1f mid %.1f wide %.1f (%.1f perturbed); flat triangles %u\n",
                         r.input.c_str(), n, r.vor_ms, r.cgal_ms, r.boost_ms, r.check.c_str(),
                         (double)(st.orient2d[0] + st.orient2d[1] + st.orient2d[2]) / n,
                         (double)st.orient2d_perturbed / n, (double)st.incircle[0] / n,
                         (double)st.incircle[1] / n, (double)st.incircle[2] / n,
                         (double)st.incircle_perturbed / n, r.flat);
        }
    }
    std::string text = table(rows);
    text += "\nExact integer and embeddable peers, the same inputs in the same run (best of " +
            std::to_string(reps) + "; ratios above 1: vor is faster; heap: peak live bytes)";
#if !defined(VOR_BENCH_DELAUNAY32) || !defined(VOR_BENCH_JCV)
    text += "; skipped: peer sources not found (../shared/peers, or PEERS=DIR)";
#endif
    text += ":\n\n" + peer_table(rows);
    if (mem) {
        text += "\nMemory detail, bytes per site: vor arena = VOR_ARENA_BYTES(n) / n; RSS = "
                "peak RSS growth during the build in a fresh process; heap = peak live "
                "heap bytes (malloc_usable_size).\n\n" +
                memory_table(rows);
    }
    if (scaling_reps > 0) {
        text += "\nTime per site against n, uniform full-range int32 sites (best of " +
                std::to_string(scaling_reps) + " rounds):\n\n" + scaling(scaling_reps, scaling_csv);
    }
    publish(text, out);
    if (!ok) {
        std::fprintf(stderr, "delaunay-host: a correctness check failed (see the table)\n");
    }
    return ok ? 0 : 1;
}
