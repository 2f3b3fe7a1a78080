/* SPDX-License-Identifier: MIT */
// tools/peer-bench/power.cpp - `make bench-power`, host part: the regular
// triangulation of weighted sites (the dual of their power diagram), vor
// (vor_power_build, vor_power_insert) against CGAL's
// Regular_triangulation_2 with Exact_predicates_inexact_constructions_kernel
// (Epick), on the same weighted sites in one process run.
//
//   power-host [--sizes N,N,..] [--reps R] [--insert-max N] [--no-mem]
//              [--out FILE]
//   power-host --mem LIB KIND N     (internal: one memory measurement)
//
// Sites: n distinct points uniform over the full int32 range (splitmix64
// seeded by n; a repeated point is drawn again), the same points for both
// kinds of weights. With s^2 = 2^64 / n the squared spacing of the sites:
//
//   light   weights uniform in [0, s^2 / 100): few sites hidden;
//   heavy   weights uniform in [0, s^2): a good share hidden.
//
// Every weight is an integer below 2^53, so CGAL's doubles hold the
// same input exactly (the program refuses sizes where they would not:
// below 2,048 sites for the heavy kind).
//
// Each library builds the triangulation twice per repetition:
//
//   build      vor: malloc of VOR_POWER_ARENA_BYTES(n), vor_power_init,
//              vor_power_build; CGAL: construct, insert(begin, end) (which
//              sorts the points spatially first);
//   insert     one site after another in input order, which for these
//              independent uniform sites is a random (shuffled) order: vor:
//              vor_power_init and vor_power_insert per site (its walk starts
//              at the last inserted site); CGAL: insert(p) per site (its walk
//              starts at a fixed face). Up to --insert-max sites (default
//              10^5: in random order both walks are O(sqrt n) a site, and at
//              10^6 a run takes minutes).
//
// Sizes default to 10^5 and 10^6. The libraries take turns within each of R
// repetitions (default 5) and the median is reported, with ratios CGAL / vor
// (above 1: vor is faster). Times are the thread's CPU time (cpu_s), not wall
// time: the machine is shared. Allocation and page faults are timed;
// destruction and input generation (the conversion to CGAL's weighted points
// included) are not.
//
// Memory: each library's build runs once more in a fresh child process
// (--mem), which generates the same input, resets its peak-RSS mark
// (writing 5 to /proc/self/clear_refs), builds and reports VmHWM minus the
// RSS before the build, and the peak of live heap bytes (global operator
// new/delete and vor's arena malloc, by malloc_usable_size), as
// tools/peer-bench/delaunay.cpp does. vor's own figure is its arena,
// VOR_POWER_ARENA_BYTES(n) / n, everything it uses.
//
// Checks, outside the timed part, on the first repetition: vor_power_validate
// passes after the build and after the insertions; the finite triangles
// (vor_power_triangles_begin; CGAL's number_of_faces), the hidden sites
// (vor_power_hidden_begin; CGAL's number_of_hidden_vertices) and the
// vertices (n less the hidden; CGAL's number_of_vertices) of all four
// triangulations agree: on these inputs in general position the regular
// triangulation is unique. A failed check marks the row and makes the exit
// status 1.

#include "vor.h"
#include "vor_power.h"

#include "bench_common.hpp"
#include "bench_memory.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_set>
#include <vector>

// ------------------------------------------------------------------ inputs

enum kind { LIGHT, HEAVY, KINDS };
static const char *const kind_name[KINDS] = {"light", "heavy"};
static const char *const kind_label[KINDS] = {"uniform int32, weights < s^2 / 100",
                                              "uniform int32, weights < s^2"};

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Rt = CGAL::Regular_triangulation_2<K>;
using Wp = K::Weighted_point_2;

struct input {
    std::vector<vor_point_t> points;
    std::vector<int64_t> weights;
    std::vector<Wp> cgal;
};

// The weights' bound for n sites: s^2 = 2^64 / n, a hundredth of it for the
// light kind.
static uint64_t weight_bound(kind k, uint32_t n)
{
    double s2 = 18446744073709551616.0 / (double)n;
    return (uint64_t)(k == LIGHT ? s2 / 100.0 : s2);
}

static input make_input(kind k, uint32_t n)
{
    uint64_t bound = weight_bound(k, n);
    if (bound > (1ull << 53)) {
        die("weights above 2^53 (too few sites): CGAL's doubles would round them");
    }
    input in;
    splitmix64 r{0x9017ull * 1000003u + n};
    std::unordered_set<uint64_t> seen;
    in.points.reserve(n);
    while (in.points.size() < n) {
        uint64_t v = r.next();
        if (seen.insert(v).second) {
            in.points.push_back({(int32_t)(uint32_t)(v >> 32), (int32_t)(uint32_t)v});
        }
    }
    splitmix64 rw{0x3E16ull * 1000003u + n * 2u + (uint32_t)k};
    in.weights.resize(n);
    in.cgal.reserve(n);
    for (uint32_t i = 0; i < n; i++) {
        in.weights[i] = (int64_t)(rw.next() % bound);
        in.cgal.push_back(Wp(K::Point_2(in.points[i].x, in.points[i].y),
                             (double)in.weights[i]));
    }
    return in;
}

// ---------------------------------------------------------------- the runs

// What a triangulation holds, for the checks.
struct counts {
    long long triangles = -1, hidden = -1, vertices = -1;
};

struct timing {
    double s = -1; // seconds
    counts c;
    std::string note;
};

static void vor_counts(const vor_power_t &pd, uint32_t n, timing &t)
{
    if (vor_power_validate(&pd, nullptr) != VOR_OK) {
        t.note = "vor_power_validate failed";
    }
    vor_triangle_iter_t it;
    uint32_t ids[3];
    t.c.triangles = 0;
    vor_power_triangles_begin(&it, &pd);
    while (vor_triangles_next(&it, ids) == 1) {
        t.c.triangles++;
    }
    vor_power_hidden_iter_t h;
    uint32_t id;
    t.c.hidden = 0;
    vor_power_hidden_begin(&h, &pd);
    while (vor_power_hidden_next(&h, &id) == 1) {
        t.c.hidden++;
    }
    t.c.vertices = (long long)n - t.c.hidden;
}

// vor_power_build (insert == false) or vor_power_insert per site.
static timing run_vor(const input &in, bool insert, bool check)
{
    timing t;
    uint32_t n = (uint32_t)in.points.size();
    size_t bytes = VOR_POWER_ARENA_BYTES(n);
    double t0 = cpu_s();
    void *arena = counted_malloc(bytes); // malloc aligns to 16
    vor_power_t pd;
    if (arena == nullptr || vor_power_init(&pd, arena, bytes, n) != VOR_OK) {
        die("vor_power_init failed");
    }
    if (!insert) {
        if (vor_power_build(&pd, in.points.data(), in.weights.data(), n, nullptr) != VOR_OK) {
            die("vor_power_build failed");
        }
    } else {
        for (uint32_t i = 0; i < n; i++) {
            if (vor_power_insert(&pd, in.points[i], in.weights[i], nullptr) != VOR_OK) {
                die("vor_power_insert failed");
            }
        }
    }
    t.s = cpu_s() - t0;
    if (check) {
        vor_counts(pd, n, t);
    }
    counted_free(arena);
    return t;
}

static timing run_cgal(const input &in, bool insert, bool check)
{
    timing t;
    double t0 = cpu_s();
    Rt *rt = new Rt;
    if (!insert) {
        rt->insert(in.cgal.begin(), in.cgal.end()); // spatially sorted
    } else {
        for (const Wp &p : in.cgal) {
            rt->insert(p);
        }
    }
    t.s = cpu_s() - t0;
    if (check) {
        t.c.triangles = (long long)rt->number_of_faces();
        t.c.hidden = (long long)rt->number_of_hidden_vertices();
        t.c.vertices = (long long)rt->number_of_vertices();
        if (!rt->is_valid()) {
            t.note = "CGAL is_valid failed";
        }
    }
    delete rt;
    return t;
}

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
    bool is_cgal = std::strcmp(lib, "cgal") == 0;
    if (!is_cgal && std::strcmp(lib, "vor") != 0) {
        die("unknown library (vor or cgal)");
    }
    input in = make_input((kind)k, n);
    mem_child child = mem_child_start();
    if (is_cgal) {
        Rt *rt = new Rt; // kept: its memory must stay in use until the end
        rt->insert(in.cgal.begin(), in.cgal.end());
        std::printf("check %zu\n", rt->number_of_faces());
    } else {
        size_t bytes = VOR_POWER_ARENA_BYTES(n);
        void *arena = counted_malloc(bytes);
        static vor_power_t pd;
        if (arena == nullptr || vor_power_init(&pd, arena, bytes, n) != VOR_OK ||
            vor_power_build(&pd, in.points.data(), in.weights.data(), n, nullptr) != VOR_OK) {
            die("vor_power_build failed");
        }
        std::printf("check %u\n", pd.hidden_count);
    }
    mem_child_finish(child);
}

static std::string self_exe;

static mem_result measure_memory(const char *lib, kind k, uint32_t n)
{
    return measure_memory(self_exe, std::string(lib) + " " + kind_name[k] + " " +
                                        std::to_string(n));
}

// ------------------------------------------------------------------- main

// One library's runs of one mode: their times, the first run's counts.
struct column {
    const char *name;
    std::vector<double> s;
    counts c;
    std::string note;
    bool ran = false;

    explicit column(const char *what) : name(what) {}

    void add(const timing &t)
    {
        if (!ran) {
            c = t.c;
            note = t.note;
            ran = true;
        }
        s.push_back(t.s);
    }
};

static std::string ratio(double peer, double ours)
{
    return (peer < 0 || ours <= 0) ? "-" : fmt("%.2f", peer / ours);
}

int main(int argc, char **argv)
{
    bench_program = "power-host";
    self_exe = argv[0];
    if (argc == 5 && std::strcmp(argv[1], "--mem") == 0) {
        return mem_main(argv[2], argv[3], parse_sizes(argv[4], 2048, 2000000)[0]);
    }
    std::vector<uint32_t> sizes = {100000, 1000000};
    uint32_t reps = 5, insert_max = 100000;
    bool mem = true;
    const char *out_path = nullptr;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--sizes" && i + 1 < argc) {
            sizes = parse_sizes(argv[++i], 2048, 2000000);
        } else if (a == "--reps" && i + 1 < argc) {
            reps = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--insert-max" && i + 1 < argc) {
            insert_max = (uint32_t)std::strtoul(argv[++i], nullptr, 10);
        } else if (a == "--no-mem") {
            mem = false;
        } else if (a == "--out" && i + 1 < argc) {
            out_path = argv[++i];
        } else {
            usage("[--sizes N,N,..] [--reps R] [--insert-max N] [--no-mem] [--out FILE]");
        }
    }
    if (reps == 0) {
        die("--reps must be positive");
    }

    std::string summary =
        md_head({"weights", "n", "hidden", "vor build ms", "CGAL build ms", "build CGAL/vor",
                 "vor insert ms", "CGAL insert ms", "insert CGAL/vor", "vor B/site",
                 "CGAL B/site", "checks"});
    std::string detail = md_head({"weights", "n", "library", "mode", "ms", "ns / site",
                                  "finite triangles", "hidden", "vertices", "checks"});
    std::string memory = md_head({"weights", "n", "vor arena", "vor RSS", "vor heap",
                                  "CGAL RSS", "CGAL heap"});
    bool all_ok = true;
    for (uint32_t n : sizes) {
        for (kind k : {LIGHT, HEAVY}) {
            input in = make_input(k, n);
            bool insert = n <= insert_max;
            std::vector<column> cols = {column("vor"), column("CGAL")};
            std::vector<column> ins = {column("vor"), column("CGAL")};
            for (uint32_t rep = 0; rep < reps; rep++) {
                bool check = rep == 0;
                cols[0].add(run_vor(in, false, check));
                cols[1].add(run_cgal(in, false, check));
                if (insert) {
                    ins[0].add(run_vor(in, true, check));
                    ins[1].add(run_cgal(in, true, check));
                }
                std::fprintf(stderr, "%s n=%u rep %u done\n", kind_name[k], n, rep + 1);
            }

            // every triangulation against vor's build
            const counts &v = cols[0].c;
            std::string bad;
            auto compare = [&](const column &col, const char *mode) {
                if (!col.note.empty()) {
                    bad += std::string(bad.empty() ? "" : "; ") + col.note;
                }
                auto one = [&](const char *what, long long theirs, long long ours) {
                    if (theirs != ours) {
                        bad += std::string(bad.empty() ? "" : "; ") + col.name + " " + mode +
                               " " + what + " " + std::to_string(theirs) + " vs " +
                               std::to_string(ours);
                    }
                };
                one("triangles", col.c.triangles, v.triangles);
                one("hidden", col.c.hidden, v.hidden);
                one("vertices", col.c.vertices, v.vertices);
            };
            compare(cols[0], "build");
            compare(cols[1], "build");
            if (insert) {
                compare(ins[0], "insert");
                compare(ins[1], "insert");
            }
            bool row_ok = bad.empty();
            all_ok &= row_ok;
            std::string checks = row_ok ? "ok" : "**" + bad + "**";

            mem_result vm, cm;
            if (mem) {
                vm = measure_memory("vor", k, n);
                cm = measure_memory("cgal", k, n);
                if (vm.rss < 0 || cm.rss < 0) {
                    all_ok = false;
                    checks += " (memory child failed)";
                }
            }
            double arena = (double)VOR_POWER_ARENA_BYTES(n);

            double vb = median(cols[0].s), cb = median(cols[1].s);
            double vi = insert ? median(ins[0].s) : -1, ci = insert ? median(ins[1].s) : -1;
            std::string hidden = with_commas((uint64_t)std::max(0LL, v.hidden)) + " (" +
                                 fmt("%.1f", 100.0 * (double)v.hidden / n) + " %)";
            summary += md_row({kind_label[k], with_commas(n), hidden, fmt("%.1f", vb * 1e3),
                               fmt("%.1f", cb * 1e3), ratio(cb, vb), fmt("%.1f", vi * 1e3),
                               fmt("%.1f", ci * 1e3), ratio(ci, vi), per_site(arena, n),
                               per_site(cm.rss, n), checks}) +
                       "\n";
            auto detail_row = [&](const column &col, const char *mode) {
                double s = median(col.s);
                detail += md_row({kind_name[k], with_commas(n), col.name, mode,
                                  fmt("%.1f", s * 1e3), fmt("%.0f", s * 1e9 / n),
                                  with_commas((uint64_t)std::max(0LL, col.c.triangles)),
                                  with_commas((uint64_t)std::max(0LL, col.c.hidden)),
                                  with_commas((uint64_t)std::max(0LL, col.c.vertices)),
                                  col.note.empty() ? "ok" : col.note}) +
                          "\n";
            };
            detail_row(cols[0], "build");
            detail_row(cols[1], "build (range insert)");
            if (insert) {
                detail_row(ins[0], "insert, one by one");
                detail_row(ins[1], "insert, one by one");
            }
            memory += md_row({kind_name[k], with_commas(n), per_site(arena, n),
                              per_site(vm.rss, n), per_site(vm.heap, n), per_site(cm.rss, n),
                              per_site(cm.heap, n)}) +
                      "\n";
        }
    }
    std::string text =
        summary + "\n(median of " + std::to_string(reps) +
        " repetitions of the thread's CPU time; ratios above 1: vor is faster; \"insert\" "
        "one site at a time in random order, up to " +
        with_commas(insert_max) + " sites; vor B/site = VOR_POWER_ARENA_BYTES(n) / n; CGAL "
        "B/site = peak RSS growth of its build in a fresh process)\n\nEach run (medians, ms; "
        "counts of the first repetition):\n\n" +
        detail;
    if (mem) {
        text += "\nMemory detail, bytes per site: vor arena = VOR_POWER_ARENA_BYTES(n) / n; "
                "RSS = peak RSS growth during the build in a fresh process; heap = peak live "
                "heap bytes (malloc_usable_size).\n\n" +
                memory;
    }
    publish(text, out_path);
    return all_ok ? 0 : 1;
}
