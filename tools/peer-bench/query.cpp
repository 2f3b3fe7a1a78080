/* SPDX-License-Identifier: MIT */
// tools/peer-bench/query.cpp - `make bench-query`, host part: nearest-site
// queries of vor against nanoflann's kd-tree and CGAL's
// Delaunay_triangulation_2::nearest_vertex, on the same sites and the same
// queries in one process run.
//
//   query-host [--sizes N,N,..] [--reps R] [--min-time S] [--coherent Q]
//              [--random Q] [--step F] [--leaf L] [--morton] [--out FILE]
//
// Sites: n points uniform in [0, 2^25)^2 (splitmix64 seeded by n), in the
// order generated (--morton: sorted in Z-order first, for every library).
// Two kinds of queries, each a fixed array computed before any clock runs:
//
//   coherent  a smooth random walk through the square: every step is F
//             times the mean site spacing 2^25 / sqrt(n) long (default
//             0.1), the heading turns by up to 0.1 radian a step, and the
//             walk bounces off the sides. vor follows it twice: with a
//             vor_tracker_t (its way for a moving point), and with
//             vor_nearest hinted by the previous answer. CGAL is hinted
//             with a face of the previous answer's vertex; a kd-tree has
//             nothing to be hinted with, so nanoflann searches from its
//             root every time.
//   random    uniform in the square. vor gets VOR_NO_HINT, CGAL no face.
//
// For each size and kind it prints one Markdown table row: queries per
// second of each library, from its best repetition, and the ratios peer
// time / vor time (above 1: vor is faster). The libraries take turns, each
// running the whole query array once a turn: at least R times (default 3),
// and more, up to 100, until it has spent S seconds (default 0.25) in all,
// so that fast rows are timed over more than a few milliseconds. Building
// the structures is not timed. Defaults: 10^6 coherent and 10^4 random
// queries a row.
//
// Exactness: every library decides with exact squared distances.
//   vor        exact integer predicates (include/vor.h).
//   nanoflann  L2_Simple_Adaptor over doubles (read from vor's int32 array).
//              Coordinates below 2^25 make every value its search computes
//              an integer below 2^53, so exact in double: differences below
//              2^25, squares below 2^50, a point's squared distance below
//              2^51, and the bound it keeps for a subtree (two squared
//              differences, plus one more while it is updated) below 2^52.
//              Its one float step, `mindistsq * epsError <= worstDist()`
//              with epsError = 1.0f, is exact. (An int64 metric would also
//              be exact, but nanoflann 1.4's middle split then always cuts
//              along x: its tolerance 0.00001 becomes 0 and no other axis
//              can win, so the tree degenerates into slabs and a query costs
//              10x more at 10^6 sites.)
//   CGAL       Epick, whose predicates are exact; its coordinates are
//              exact doubles.
// After the timing, every answer's squared distance (int64, exact) is
// compared with that of vor's answer; 100 queries per row are also checked
// against brute force. Any mismatch is counted in the row and makes the
// exit status 1.

#include "vor.h"

#include "bench_common.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

static const double SIDE = 33554432.0; // 2^25: sites and queries in [0, 2^25)
static const unsigned MAX_REPS = 100;

struct rng : splitmix64 {
    int32_t coordinate() { return (int32_t)(next() >> 39); } // [0, 2^25)
    double unit() { return (double)(next() >> 11) * 0x1p-53; } // [0, 1)
};

// count points uniform in [0, 2^25)^2 from the generator seeded by seed.
static std::vector<vor_point_t> uniform_points(uint64_t seed, uint32_t count)
{
    rng r{seed};
    std::vector<vor_point_t> p(count);
    for (auto &q : p) {
        q.x = r.coordinate();
        q.y = r.coordinate();
    }
    return p;
}

static std::vector<vor_point_t> make_sites(uint32_t n)
{
    return uniform_points(0x51735ull * 1000003u + n, n);
}

// Morton (Z-order) key of a point in [0, 2^25)^2: its coordinates' bits
// interleaved.
static uint64_t morton(const vor_point_t &p)
{
    uint64_t key = 0;
    for (unsigned bit = 0; bit < 25; bit++) {
        key |= (uint64_t)(((uint32_t)p.x >> bit) & 1u) << (2 * bit);
        key |= (uint64_t)(((uint32_t)p.y >> bit) & 1u) << (2 * bit + 1);
    }
    return key;
}

static void sort_morton(std::vector<vor_point_t> &p)
{
    std::sort(p.begin(), p.end(), [](const vor_point_t &a, const vor_point_t &b) {
        return morton(a) < morton(b);
    });
}

static std::vector<vor_point_t> make_random_queries(uint32_t n, uint32_t count)
{
    return uniform_points(0x4A11D0ull * 1000003u + n, count);
}

// The walk: fixed step length, heading turning by up to 0.1 radian a
// step, reflected at the sides of [0, SIDE - 1]^2.
static std::vector<vor_point_t> make_trajectory(uint32_t n, uint32_t count, double step_fraction)
{
    rng r{0x7EA1ull * 1000003u + n};
    const double step = step_fraction * SIDE / std::sqrt((double)n), high = SIDE - 1;
    double x = SIDE / 2, y = SIDE / 2, heading = 2 * M_PI * r.unit();
    std::vector<vor_point_t> q(count);
    for (auto &p : q) {
        heading += 0.2 * (r.unit() - 0.5);
        x += step * std::cos(heading);
        y += step * std::sin(heading);
        if (x < 0 || x > high) { // step << SIDE: one reflection is enough
            x = (x < 0) ? -x : 2 * high - x;
            heading = M_PI - heading;
        }
        if (y < 0 || y > high) {
            y = (y < 0) ? -y : 2 * high - y;
            heading = -heading;
        }
        p.x = (int32_t)std::lround(x);
        p.y = (int32_t)std::lround(y);
    }
    return q;
}

static int64_t distance2(const vor_point_t &q, int64_t x, int64_t y)
{
    int64_t dx = q.x - x, dy = q.y - y; // |d| < 2^25: exact, sum < 2^51
    return dx * dx + dy * dy;
}

static int64_t distance2(const vor_point_t &q, const vor_point_t &s)
{
    return distance2(q, s.x, s.y);
}

// ---------------------------------------------------------------- libraries

// nanoflann reads the coordinates from the same array as vor, as doubles.
struct site_cloud {
    const std::vector<vor_point_t> *sites;
    size_t kdtree_get_point_count() const { return sites->size(); }
    double kdtree_get_pt(uint32_t i, size_t dim) const
    {
        const vor_point_t &p = (*sites)[i];
        return dim == 0 ? p.x : p.y;
    }
    template <class Bbox> bool kdtree_get_bbox(Bbox &) const { return false; }
};

using Kd_metric = nanoflann::L2_Simple_Adaptor<double, site_cloud, double, uint32_t>;
using Kd_tree = nanoflann::KDTreeSingleIndexAdaptor<Kd_metric, site_cloud, 2, uint32_t>;

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cgal_dt = CGAL::Delaunay_triangulation_2<Epick>;
using Cgal_vertex = Cgal_dt::Vertex_handle;

// The timed loops. Each stores its answers, read only after the clock stops.

// How vor is asked: a tracker following the query (vor_track), vor_nearest
// hinted with the previous answer, or vor_nearest without a hint.
enum class vor_way { tracked, hinted, cold };

static double run_vor(const vor_t *d, const std::vector<vor_point_t> &q, vor_way way,
                      std::vector<uint32_t> &answer)
{
    uint32_t hint = VOR_NO_HINT, site = 0;
    vor_tracker_t tracker;
    int failed = vor_tracker_begin(&tracker, d);
    double t0 = now_s();
    if (way == vor_way::tracked) {
        for (size_t i = 0; i < q.size(); i++) {
            failed |= vor_track(&tracker, q[i], &site);
            answer[i] = site;
        }
    } else {
        for (size_t i = 0; i < q.size(); i++) {
            failed |= vor_nearest(d, q[i], hint, &site);
            answer[i] = site;
            hint = (way == vor_way::hinted) ? site : VOR_NO_HINT;
        }
    }
    double t = now_s() - t0;
    if (failed != VOR_OK) {
        die("vor query failed");
    }
    return t;
}

static double run_nanoflann(const Kd_tree &tree, const std::vector<double> &q,
                            std::vector<uint32_t> &answer)
{
    const nanoflann::SearchParams params; // eps 0: exact
    double t0 = now_s();
    for (size_t i = 0; i < answer.size(); i++) {
        uint32_t index = 0;
        double dist = 0;
        nanoflann::KNNResultSet<double, uint32_t> result(1);
        result.init(&index, &dist);
        tree.findNeighbors(result, &q[2 * i], params);
        answer[i] = index;
    }
    return now_s() - t0;
}

static double run_cgal(const Cgal_dt &dt, const std::vector<Epick::Point_2> &q, bool hinted,
                       std::vector<Cgal_vertex> &answer)
{
    Cgal_dt::Face_handle hint; // none yet
    double t0 = now_s();
    for (size_t i = 0; i < q.size(); i++) {
        Cgal_vertex v = dt.nearest_vertex(q[i], hint);
        answer[i] = v;
        if (hinted) {
            hint = v->face();
        }
    }
    return now_s() - t0;
}

// -------------------------------------------------------------------- rows

struct row {
    const char *kind = "";
    vor_way way = vor_way::cold;
    uint32_t n = 0, queries = 0;
    double vor_s = 1e300, nanoflann_s = 1e300, cgal_s = 1e300; // best time
    uint64_t nanoflann_wrong = 0, cgal_wrong = 0, brute_wrong = 0;
    uint32_t brute_checked = 0;
    uint32_t changes = 0; // queries whose answer differs from the previous one
    unsigned vor_reps = 0;
    uint64_t mismatches() const { return nanoflann_wrong + cgal_wrong + brute_wrong; }
};

struct structures {
    const std::vector<vor_point_t> *sites;
    const vor_t *vor;
    const Kd_tree *tree;
    const Cgal_dt *dt;
};

static row run_row(const char *kind, vor_way way, const structures &s,
                   const std::vector<vor_point_t> &q, unsigned reps, double min_time)
{
    row r;
    r.kind = kind;
    r.way = way;
    r.n = (uint32_t)s.sites->size();
    r.queries = (uint32_t)q.size();
    std::vector<double> q_nanoflann(2 * q.size());
    std::vector<Epick::Point_2> q_cgal;
    q_cgal.reserve(q.size());
    for (size_t i = 0; i < q.size(); i++) {
        q_nanoflann[2 * i] = q[i].x;
        q_nanoflann[2 * i + 1] = q[i].y;
        q_cgal.emplace_back((double)q[i].x, (double)q[i].y); // exact: |x| < 2^53
    }
    std::vector<uint32_t> vor_answer(q.size()), nanoflann_answer(q.size());
    std::vector<Cgal_vertex> cgal_answer(q.size());
    // The libraries take turns; each drops out once it has had its
    // repetitions and its time.
    double total[3] = {0, 0, 0};
    for (unsigned rep = 0; rep < MAX_REPS; rep++) {
        bool more[3];
        for (int lib = 0; lib < 3; lib++) {
            more[lib] = rep < reps || total[lib] < min_time;
        }
        if (!more[0] && !more[1] && !more[2]) {
            break;
        }
        if (more[0]) {
            double t = run_vor(s.vor, q, way, vor_answer);
            r.vor_s = std::min(r.vor_s, t);
            total[0] += t;
            r.vor_reps = rep + 1;
        }
        if (more[1]) {
            double t = run_nanoflann(*s.tree, q_nanoflann, nanoflann_answer);
            r.nanoflann_s = std::min(r.nanoflann_s, t);
            total[1] += t;
        }
        if (more[2]) {
            double t = run_cgal(*s.dt, q_cgal, way != vor_way::cold, cgal_answer);
            r.cgal_s = std::min(r.cgal_s, t);
            total[2] += t;
        }
    }

    const std::vector<vor_point_t> &sites = *s.sites;
    for (size_t i = 0; i < q.size(); i++) {
        int64_t d = distance2(q[i], sites[vor_answer[i]]);
        r.nanoflann_wrong += distance2(q[i], sites[nanoflann_answer[i]]) != d;
        const Epick::Point_2 &c = cgal_answer[i]->point();
        r.cgal_wrong += distance2(q[i], (int64_t)c.x(), (int64_t)c.y()) != d;
        r.changes += i > 0 && vor_answer[i] != vor_answer[i - 1];
    }
    size_t stride = std::max<size_t>(1, q.size() / 100);
    for (size_t i = 0; i < q.size(); i += stride) {
        int64_t best = INT64_MAX;
        for (const vor_point_t &p : sites) {
            best = std::min(best, distance2(q[i], p));
        }
        r.brute_checked++;
        r.brute_wrong += distance2(q[i], sites[vor_answer[i]]) != best;
    }
    return r;
}

// ------------------------------------------------------------------- table

// Millions of queries per second, three significant digits.
static std::string mqps(const row &r, double seconds)
{
    return fmt("%#.3g", r.queries / seconds / 1e6);
}

// Two decimals, or three significant digits below 0.1.
static std::string ratio(double v)
{
    return fmt(v < 0.1 ? "%#.3g" : "%.2f", v);
}

static std::string table(const std::vector<row> &rows)
{
    std::string t;
    t += "| queries | sites | vor Mq/s | nanoflann Mq/s | CGAL Mq/s | nanoflann/vor | "
         "CGAL/vor | mismatches |\n";
    t += "|---|---|---|---|---|---|---|---|\n";
    for (const row &r : rows) {
        t += std::string("| ") + r.kind + " | " + with_commas(r.n) + " | " + mqps(r, r.vor_s) +
             " | " + mqps(r, r.nanoflann_s) + " | " + mqps(r, r.cgal_s) + " | " +
             ratio(r.nanoflann_s / r.vor_s) + " | " + ratio(r.cgal_s / r.vor_s) +
             " | " + (r.mismatches() == 0 ? "0" : "**" + with_commas(r.mismatches()) + "**") +
             " |\n";
    }
    return t;
}

// The host targets of issue 4, judged on this run's rows.
static std::string targets(const std::vector<row> &rows)
{
    double coherent_min = 1e300, random_min = 1e300;
    for (const row &r : rows) {
        double ratio = r.nanoflann_s / r.vor_s;
        if (r.way != vor_way::hinted) { /* the tracker is vor's way for a moving point */
            double &m = (r.way == vor_way::tracked) ? coherent_min : random_min;
            m = std::min(m, ratio);
        }
    }
    std::string t;
    t += "| target | measured (smallest nanoflann/vor over the sizes) | status |\n";
    t += "|---|---|---|\n";
    t += "| coherent queries >= 3x faster than nanoflann | " + ratio(coherent_min) + " | " +
         (coherent_min >= 3 ? "met" : "**not met**") + " |\n";
    t += "| random queries no slower than nanoflann | " + ratio(random_min) + " | " +
         (random_min >= 1 ? "met" : "**not met**") + " |\n";
    return t;
}

static uint32_t parse_count(const char *s)
{
    char *end;
    unsigned long v = std::strtoul(s, &end, 10);
    if (end == s || *end != '\0' || v < 1 || v > 100000000ul) {
        die("bad query count");
    }
    return (uint32_t)v;
}

int main(int argc, char **argv)
{
    bench_program = "query-host";
    std::vector<uint32_t> sizes = {1000, 10000, 100000, 1000000};
    unsigned reps = 3;
    double min_time = 0.25;
    uint32_t coherent_count = 1000000, random_count = 10000;
    double step_fraction = 0.1;
    size_t leaf = 10;
    const char *out = nullptr;
    bool sorted = false;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--sizes" && i + 1 < argc) {
            sizes = parse_sizes(argv[++i], 2, VOR_MAX_SITES);
        } else if (a == "--reps" && i + 1 < argc) {
            reps = parse_count(argv[++i]);
        } else if (a == "--min-time" && i + 1 < argc) {
            min_time = std::strtod(argv[++i], nullptr);
        } else if (a == "--coherent" && i + 1 < argc) {
            coherent_count = parse_count(argv[++i]);
        } else if (a == "--random" && i + 1 < argc) {
            random_count = parse_count(argv[++i]);
        } else if (a == "--step" && i + 1 < argc) {
            step_fraction = std::strtod(argv[++i], nullptr);
            if (!(step_fraction > 0 && step_fraction <= 1)) {
                die("bad --step (a fraction of the site spacing, in (0, 1])");
            }
        } else if (a == "--leaf" && i + 1 < argc) {
            leaf = parse_count(argv[++i]);
        } else if (a == "--morton") {
            sorted = true;
        } else if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else {
            usage("[--sizes N,N,..] [--reps R] [--min-time S] [--coherent Q] [--random Q] "
                  "[--step F] [--leaf L] [--morton] [--out FILE]");
        }
    }

    std::vector<row> rows;
    for (uint32_t n : sizes) {
        std::vector<vor_point_t> sites = make_sites(n);
        if (sorted) {
            sort_morton(sites);
        }

        size_t bytes = VOR_ARENA_BYTES(n);
        void *arena = std::malloc(bytes);
        vor_t d;
        if (arena == nullptr || vor_init(&d, arena, bytes, n) != VOR_OK ||
            vor_build(&d, sites.data(), n, nullptr, nullptr) != VOR_OK) {
            die("vor_build failed");
        }
        site_cloud cloud{&sites};
        Kd_tree tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(leaf));
        tree.buildIndex();
        Cgal_dt dt;
        std::vector<Epick::Point_2> cgal_sites;
        cgal_sites.reserve(n);
        for (const auto &p : sites) {
            cgal_sites.emplace_back((double)p.x, (double)p.y);
        }
        dt.insert(cgal_sites.begin(), cgal_sites.end());

        structures s{&sites, &d, &tree, &dt};
        std::vector<vor_point_t> trajectory = make_trajectory(n, coherent_count, step_fraction);
        rows.push_back(run_row("coherent, vor_track", vor_way::tracked, s, trajectory, reps,
                               min_time));
        rows.push_back(run_row("coherent, vor_nearest hinted", vor_way::hinted, s, trajectory,
                               reps, min_time));
        rows.push_back(run_row("random, vor_nearest no hint", vor_way::cold, s,
                               make_random_queries(n, random_count), reps, min_time));
        for (size_t i = rows.size() - 3; i < rows.size(); i++) {
            const row &r = rows[i];
            std::fprintf(stderr,
                         "bench: %-28s %8u sites %8u queries x %3u  ns/query: vor %8.1f  "
                         "nanoflann %8.1f  CGAL %8.1f\n"
                         "       answer changed on %.3f of queries; wrong: nanoflann %llu, CGAL "
                         "%llu, vor vs brute force %llu of %u\n",
                         r.kind, n, r.queries, r.vor_reps, r.vor_s / r.queries * 1e9,
                         r.nanoflann_s / r.queries * 1e9, r.cgal_s / r.queries * 1e9,
                         (double)r.changes / r.queries, (unsigned long long)r.nanoflann_wrong,
                         (unsigned long long)r.cgal_wrong, (unsigned long long)r.brute_wrong,
                         r.brute_checked);
        }
        std::free(arena);
    }
    std::stable_sort(rows.begin(), rows.end(), [](const row &a, const row &b) {
        return a.way != b.way ? a.way < b.way : a.n < b.n;
    });

    bool ok = true;
    for (const row &r : rows) {
        ok &= r.mismatches() == 0;
    }
    std::string text = table(rows) + "\nTargets on the host (issue 4):\n\n" + targets(rows);
    publish(text, out);
    if (!ok) {
        std::fprintf(stderr, "query-host: answers disagree (see the mismatches column)\n");
    }
    return ok ? 0 : 1;
}
