/* SPDX-License-Identifier: MIT */
// tools/peer-bench/interpolate.cpp - `make bench-interpolate`, host part:
// natural-neighbour interpolation queries, vor (vor_interpolate: Sibson's
// coordinates; vor_interpolate_laplace: Laplace's) against CGAL's
// natural_neighbor_coordinates_2 followed by linear_interpolation (Sibson;
// CGAL 5.5 has no Laplace coordinates in 2D) on a Delaunay_triangulation_2,
// with Exact_predicates_inexact_constructions_kernel (Epick: what a CGAL
// user would take, double coordinates) and with
// Exact_predicates_exact_constructions_kernel (Epeck: exact, as vor), on
// the same sites and queries in one process run. Epick runs twice: on a
// plain Delaunay_triangulation_2, as CGAL's interpolation examples do, whose
// point location walks from an arbitrary face (O(sqrt n) a random query),
// and on a Triangulation_hierarchy_2, CGAL's O(log n) point location (vor
// locates with its bucket grid). Epeck runs on the hierarchy.
//
//   interpolate-host [--sizes N,N,..] [--queries Q] [--reps R] [--out FILE]
//
// Sites: n distinct points uniform over the full int32 range (splitmix64
// seeded by n, as tools/peer-bench/power.cpp), each with a value uniform in
// [-10^6, 10^6]; queries: Q points (default 10^5) uniform in the middle
// square [-3/4 2^31, 3/4 2^31)^2, inside the hull of these sites. Every
// query starts afresh: vor from VOR_NO_HINT (its bucket grid), CGAL from
// no face (its default). Per query the timed part is the whole
// interpolation, up to a number: vor_interpolate's rounded value; CGAL's
// coordinates into a reused vector, linear_interpolation with the values
// kept in the vertices, and (Epeck) to_double of the result. Building the
// triangulations and generating the inputs are not timed.
//
// Sizes default to 10^4 and 10^5. The five runs take turns within each of
// R repetitions (default 3) and the median is reported, as queries per
// second and as ratios CGAL time / vor time (above 1: vor is faster).
// Times are the thread's CPU time (cpu_s): the machine is shared.
//
// Checks, outside the timed part, on the first repetition: every vor call
// returns VOR_OK and every CGAL call answers inside; vor's and both CGAL
// Epick runs' numbers of natural neighbours agree on every query; for the
// first 2,000 queries vor's exact value (numerator / denominator) equals
// CGAL Epeck's exact value (its mpq), and for every query CGAL Epick's
// doubles are within 10^-3 of vor's exact value (the largest difference is
// reported). A failed check marks the row and makes the exit status 1.

#include "vor.h"

#include "bench_common.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/interpolation_functions.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/natural_neighbor_coordinates_2.h>

#include <gmpxx.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

// ------------------------------------------------------------------ inputs

struct input {
    std::vector<vor_point_t> points;
    std::vector<int32_t> values;
    std::vector<vor_point_t> queries;
};

static input make_input(uint32_t n, uint32_t queries)
{
    input in;
    splitmix64 r{0x9017ull * 1000003u + n};
    std::unordered_set<uint64_t> seen;
    while (in.points.size() < n) {
        uint64_t v = r.next();
        if (seen.insert(v).second) {
            in.points.push_back({(int32_t)(uint32_t)(v >> 32), (int32_t)(uint32_t)v});
            in.values.push_back((int32_t)(r.next() % 2000001u) - 1000000);
        }
    }
    splitmix64 rq{0x1D7Eull * 1000003u + n};
    const uint64_t reach = 3221225472u; // 3/2 of 2^31: [-3/4 2^31, 3/4 2^31)
    for (uint32_t i = 0; i < queries; i++) {
        int32_t x = (int32_t)((int64_t)(rq.next() % reach) - (int64_t)(reach / 2));
        int32_t y = (int32_t)((int64_t)(rq.next() % reach) - (int64_t)(reach / 2));
        in.queries.push_back({x, y});
    }
    return in;
}

// ------------------------------------------------------------------- CGAL

// A Delaunay triangulation of kernel K whose vertices keep their values,
// and one query: natural_neighbor_coordinates_2, then linear_interpolation.
// Plain, or (hierarchy) a Triangulation_hierarchy_2, CGAL's way to locate a
// point in O(log n) expected time.
template <class K, class Vb, class Dt> struct cgal_side {
    typedef typename Dt::Vertex_handle Vertex;
    typedef typename K::FT FT;
    typedef std::pair<Vertex, FT> Coordinate;

    struct keep_vertex { // natural_neighbor_coordinates_2's output functor
        typedef Coordinate argument_type;
        typedef Coordinate result_type;
        result_type operator()(const argument_type &a) const { return a; }
    };
    struct site_value { // linear_interpolation's value functor
        typedef std::pair<FT, bool> result_type;
        result_type operator()(const Vertex &v) const { return result_type(FT(v->info()), true); }
    };

    Dt dt;
    std::vector<Coordinate> coords;

    explicit cgal_side(const input &in)
    {
        // spatially sorted, as insert(begin, end) does, one by one to set the
        // values (Triangulation_hierarchy_2 takes no (point, info) range)
        std::vector<std::pair<typename K::Point_2, int32_t>> pts;
        for (size_t i = 0; i < in.points.size(); i++) {
            pts.push_back({typename K::Point_2(in.points[i].x, in.points[i].y), in.values[i]});
        }
        typedef CGAL::Spatial_sort_traits_adapter_2<
            K, CGAL::First_of_pair_property_map<std::pair<typename K::Point_2, int32_t>>>
            traits;
        CGAL::spatial_sort(pts.begin(), pts.end(), traits());
        typename Dt::Face_handle hint;
        for (const auto &p : pts) {
            Vertex v = dt.insert(p.first, hint);
            v->info() = p.second;
            hint = v->face();
        }
    }

    // false outside the hull; value and neighbours otherwise
    bool query(const vor_point_t &q, FT &value, size_t &neighbours)
    {
        coords.clear();
        auto r = CGAL::natural_neighbor_coordinates_2(dt, typename K::Point_2(q.x, q.y),
                                                      std::back_inserter(coords), keep_vertex());
        if (!r.third) {
            return false;
        }
        value = CGAL::linear_interpolation(coords.begin(), coords.end(), r.second, site_value());
        neighbours = coords.size();
        return true;
    }
};

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
template <class K> using info_vb = CGAL::Triangulation_vertex_base_with_info_2<int32_t, K>;
template <class K>
using plain_dt = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<info_vb<K>>>;
template <class K> using hierarchy_vb = CGAL::Triangulation_hierarchy_vertex_base_2<info_vb<K>>;
template <class K>
using hierarchy_dt = CGAL::Triangulation_hierarchy_2<
    CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<hierarchy_vb<K>>>>;
typedef cgal_side<Epick, info_vb<Epick>, plain_dt<Epick>> epick_side;
typedef cgal_side<Epeck, hierarchy_vb<Epeck>, hierarchy_dt<Epeck>> epeck_side;
typedef cgal_side<Epick, hierarchy_vb<Epick>, hierarchy_dt<Epick>> epick_hierarchy_side;

// -------------------------------------------------------------------- vor

struct vor_side {
    vor_t d;
    void *arena;
    std::vector<uint8_t> scratch;
    const int32_t *values;

    explicit vor_side(const input &in) : scratch(VOR_SIBSON_SCRATCH_BYTES(32)), values(in.values.data())
    {
        uint32_t n = (uint32_t)in.points.size();
        arena = std::malloc(VOR_ARENA_BYTES(n));
        if (arena == nullptr || vor_init(&d, arena, VOR_ARENA_BYTES(n), n) != VOR_OK ||
            vor_build(&d, in.points.data(), n, nullptr, nullptr) != VOR_OK) {
            die("vor_build failed");
        }
    }
    ~vor_side() { std::free(arena); }

    int query(const vor_point_t &q, bool laplace, vor_interpolation_t &v)
    {
        auto fn = laplace ? vor_interpolate_laplace : vor_interpolate;
        int err = fn(&d, values, q, VOR_NO_HINT, scratch.data(), scratch.size(), &v);
        if (err == VOR_ERR_NOMEM) {
            scratch.resize(VOR_SIBSON_SCRATCH_BYTES(v.neighbours));
            err = fn(&d, values, q, VOR_NO_HINT, scratch.data(), scratch.size(), &v);
        }
        return err;
    }
};

static mpq_class exact_of(const vor_interpolation_t &v)
{
    mpz_class num, den;
    mpz_import(num.get_mpz_t(), v.limbs, -1, 4, 0, 0, v.numerator);
    mpz_import(den.get_mpz_t(), v.limbs, -1, 4, 0, 0, v.denominator);
    mpq_class q(v.sign < 0 ? mpz_class(-num) : num, den);
    q.canonicalize();
    return q;
}

// ------------------------------------------------------------------- main

int main(int argc, char **argv)
{
    bench_program = "interpolate-host";
    std::vector<uint32_t> sizes = {10000, 100000};
    uint32_t queries = 100000, reps = 3;
    const char *out_path = nullptr;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--sizes" && i + 1 < argc) {
            sizes = parse_sizes(argv[++i], 1000, 2000000);
        } else if (a == "--queries" && i + 1 < argc) {
            queries = parse_sizes(argv[++i], 1, 10000000)[0];
        } else if (a == "--reps" && i + 1 < argc) {
            reps = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--out" && i + 1 < argc) {
            out_path = argv[++i];
        } else {
            usage("[--sizes N,N,..] [--queries Q] [--reps R] [--out FILE]");
        }
    }
    if (reps == 0) {
        die("--reps must be positive");
    }
    const uint32_t exact_checks = 2000;

    std::string table = md_head({"n", "queries", "neighbours", "vor Sibson q/s", "vor Laplace q/s",
                                 "CGAL Epick q/s", "CGAL Epick + hierarchy q/s", "CGAL Epeck + hierarchy q/s",
                                 "Epick / vor Sibson", "Epick + hierarchy / vor Sibson",
                                 "Epeck + hierarchy / vor Sibson", "Epick / vor Laplace",
                                 "Epick + hierarchy / vor Laplace", "Epick's largest error",
                                 "checks"});
    bool all_ok = true;
    for (uint32_t n : sizes) {
        input in = make_input(n, queries);
        vor_side vs(in);
        epick_side ek(in);
        epick_hierarchy_side eh(in);
        epeck_side ee(in);
        std::vector<double> t_sibson, t_laplace, t_epick, t_hierarchy, t_epeck;
        std::vector<int32_t> vor_value(queries);
        std::vector<uint32_t> vor_k(queries);
        std::vector<mpq_class> vor_exact(std::min(queries, exact_checks));
        std::vector<double> vor_double(queries);
        std::string bad;
        auto fail = [&](const std::string &what) {
            if (bad.size() < 200) {
                bad += std::string(bad.empty() ? "" : "; ") + what;
            }
        };
        double largest_error = 0, neighbours = 0;
        volatile double sink = 0;
        for (uint32_t rep = 0; rep < reps; rep++) {
            bool check = rep == 0;
            for (bool laplace : {false, true}) {
                double t0 = cpu_s();
                int64_t sum = 0;
                int errors = 0;
                for (uint32_t i = 0; i < queries; i++) {
                    vor_interpolation_t v;
                    errors += vs.query(in.queries[i], laplace, v) != VOR_OK;
                    sum += v.value;
                    if (check && !laplace) {
                        vor_value[i] = v.value;
                        vor_k[i] = v.neighbours;
                    }
                }
                (laplace ? t_laplace : t_sibson).push_back(cpu_s() - t0);
                sink = sink + (double)sum;
                if (errors != 0) {
                    fail("vor: " + std::to_string(errors) + " calls failed");
                }
            }
            if (check) { // vor's exact values, outside the clock
                for (uint32_t i = 0; i < queries; i++) {
                    vor_interpolation_t v;
                    vs.query(in.queries[i], false, v);
                    mpq_class e = exact_of(v);
                    vor_double[i] = e.get_d();
                    if (i < exact_checks) {
                        vor_exact[i] = e;
                    }
                    neighbours += v.neighbours;
                }
            }
            auto run_epick = [&](auto &side, std::vector<double> &times, const std::string &name) {
                double t0 = cpu_s(), sum = 0;
                int outside = 0;
                for (uint32_t i = 0; i < queries; i++) {
                    double value = 0;
                    size_t k = 0;
                    if (!side.query(in.queries[i], value, k)) {
                        outside++;
                        continue;
                    }
                    sum += value;
                    if (check) {
                        double e = std::fabs(value - vor_double[i]);
                        largest_error = std::max(largest_error, e);
                        if (k != vor_k[i]) {
                            fail(name + " neighbours differ at query " + std::to_string(i));
                        }
                    }
                }
                times.push_back(cpu_s() - t0);
                sink = sink + sum;
                if (outside != 0) {
                    fail(name + ": " + std::to_string(outside) + " queries outside");
                }
            };
            run_epick(ek, t_epick, "Epick");
            run_epick(eh, t_hierarchy, "Epick hierarchy");
            {
                double t0 = cpu_s(), sum = 0;
                int outside = 0;
                std::vector<epeck_side::FT> kept;
                for (uint32_t i = 0; i < queries; i++) {
                    epeck_side::FT value;
                    size_t k = 0;
                    if (!ee.query(in.queries[i], value, k)) {
                        outside++;
                        continue;
                    }
                    sum += CGAL::to_double(value);
                    if (check && i < exact_checks) {
                        kept.push_back(value);
                    }
                }
                t_epeck.push_back(cpu_s() - t0);
                sink = sink + sum;
                if (outside != 0) {
                    fail("Epeck: " + std::to_string(outside) + " queries outside");
                }
                for (size_t i = 0; i < kept.size(); i++) { // exact, outside the clock
                    std::ostringstream s;
                    s << kept[i].exact();
                    if (mpq_class(s.str()) != vor_exact[i]) {
                        fail("Epeck's exact value differs at query " + std::to_string(i));
                    }
                }
            }
            std::fprintf(stderr, "n=%u rep %u done\n", n, rep + 1);
        }
        if (largest_error > 1e-3) {
            fail("Epick's error above 10^-3");
        }
        bool ok = bad.empty();
        all_ok &= ok;
        double s = median(t_sibson), l = median(t_laplace), ek_t = median(t_epick),
               eh_t = median(t_hierarchy), ee_t = median(t_epeck);
        auto rate = [&](double t) { return with_commas((uint64_t)std::llround(queries / t)); };
        table += md_row({with_commas(n), with_commas(queries), fmt("%.2f", neighbours / queries),
                         rate(s), rate(l), rate(ek_t), rate(eh_t), rate(ee_t),
                         fmt("%.2f", ek_t / s), fmt("%.2f", eh_t / s), fmt("%.2f", ee_t / s),
                         fmt("%.2f", ek_t / l), fmt("%.2f", eh_t / l), fmt("%.1e", largest_error),
                         ok ? "ok" : "**" + bad + "**"}) +
                 "\n";
    }
    std::string text = table + "\n(median of " + std::to_string(reps) +
                       " repetitions of the thread's CPU time; ratios CGAL time / vor time, above "
                       "1: vor is faster; Epick's largest error: the largest difference between "
                       "CGAL Epick's double and vor's exact value; Epeck's exact values equal vor's "
                       "on the first " +
                       with_commas(exact_checks) + " queries)\n";
    publish(text, out_path);
    return all_ok ? 0 : 1;
}
