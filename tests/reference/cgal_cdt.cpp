/* SPDX-License-Identifier: MIT */
// tests/reference/cgal_cdt.cpp - the reference for `vor cdt`: CGAL's
// Constrained_Delaunay_triangulation_2 with exact constructions and exact
// intersections (Epeck, Exact_intersections_tag), on the same input files,
// printed in `vor cdt`'s format with every crossing vertex named by its
// exact point, "x:XN/YN/W" in lowest terms, instead of an id (the two
// libraries number crossings in different orders). Host tests only
// (tests/reference/compare_cdt.py); the library never depends on CGAL.
//
//   cgal-cdt SITES CONSTRAINTS
#define CGAL_NO_CDT_2_WARNING /* exact intersections are the point here */
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gmpxx.h>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_with_info_2<long, K> Vb;
typedef CGAL::Constrained_triangulation_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_intersections_tag> Cdt;

static std::vector<std::vector<long>> read_numbers(const char *path)
{
    std::ifstream in(path);
    std::vector<std::vector<long>> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        std::istringstream s(line);
        std::vector<long> row;
        long v;
        while (s >> v) {
            row.push_back(v);
        }
        if (!row.empty()) {
            rows.push_back(row);
        }
    }
    return rows;
}

static mpq_class exact_value(const K::FT &v)
{
    return mpq_class(CGAL::exact(v).backend().data()); // boost gmp_rational: an mpq_t
}

static std::string name(Cdt::Vertex_handle v)
{
    if (v->info() >= 0) {
        return std::to_string(v->info());
    }
    mpq_class x = exact_value(v->point().x()), y = exact_value(v->point().y());
    mpz_class w = lcm(mpz_class(x.get_den()), mpz_class(y.get_den()));
    mpz_class xn = x.get_num() * (w / x.get_den()), yn = y.get_num() * (w / y.get_den());
    return "x:" + xn.get_str() + "/" + yn.get_str() + "/" + w.get_str();
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::cerr << "usage: cgal-cdt SITES CONSTRAINTS\n";
        return 2;
    }
    auto sites = read_numbers(argv[1]);
    auto pairs = read_numbers(argv[2]);
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handle;
    std::map<std::pair<long, long>, long> first;
    for (size_t i = 0; i < sites.size(); i++) {
        Cdt::Vertex_handle v = cdt.insert(K::Point_2(sites[i][0], sites[i][1]));
        auto key = std::make_pair(sites[i][0], sites[i][1]);
        if (first.find(key) == first.end()) {
            first[key] = (long)i;
            v->info() = (long)i;
        }
        handle.push_back(v);
    }
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        auto key = std::make_pair((long)CGAL::to_double(v->point().x()), (long)CGAL::to_double(v->point().y()));
        v->info() = first.count(key) ? first[key] : -1;
    }
    for (auto &p : pairs) {
        if (handle[p[0]] != handle[p[1]]) {
            cdt.insert_constraint(handle[p[0]], handle[p[1]]);
        }
    }
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        bool site = false;
        for (size_t i = 0; i < handle.size(); i++) {
            site = site || (handle[i] == Cdt::Vertex_handle(v));
        }
        if (!site) {
            v->info() = -1;
        }
    }
    std::vector<std::string> lines;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        std::array<std::string, 3> t = {name(f->vertex(0)), name(f->vertex(1)), name(f->vertex(2))};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        lines.push_back("t " + t[0] + " " + t[1] + " " + t[2]);
        for (int k = 0; k < 3; k++) {
            if (f->is_constrained(k)) {
                std::string a = name(f->vertex((k + 1) % 3)), b = name(f->vertex((k + 2) % 3));
                lines.push_back("c " + std::min(a, b) + " " + std::max(a, b));
            }
        }
    }
    std::sort(lines.begin(), lines.end());
    lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    for (auto &l : lines) {
        std::cout << l << "\n";
    }
    return 0;
}
