/* SPDX-License-Identifier: MIT */
// tests/reference/cgal_power.cpp - the reference for `vor power`: CGAL's
// Regular_triangulation_2 with exact constructions (Epeck, the weights
// exact rationals built from the int64 input), on the same input file,
// printed in `vor power`'s format: "t I J K" per finite triangle
// (counterclockwise, from its smallest id, sorted), "h I" per hidden
// site, sorted. A site with the point and weight of an earlier one is left
// out, as `vor power` reports it as a duplicate. Host tests only
// (tests/reference/compare_power.py); the library never depends on CGAL.
//
//   cgal-power SITES
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
typedef CGAL::Regular_triangulation_vertex_base_2<K> Rvb;
typedef CGAL::Triangulation_vertex_base_with_info_2<long, K, Rvb> Vb;
typedef CGAL::Regular_triangulation_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Regular_triangulation_2<K, Tds> Rt;

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::cerr << "usage: cgal-power SITES\n";
        return 2;
    }
    std::ifstream in(argv[1]);
    std::string line;
    std::set<std::tuple<long, long, long long>> seen;
    Rt rt;
    long id = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        std::istringstream s(line);
        long x, y;
        long long w;
        if (!(s >> x >> y >> w)) {
            continue;
        }
        long i = id++;
        if (!seen.insert(std::make_tuple(x, y, w)).second) {
            continue; /* a duplicate */
        }
        K::Weighted_point_2 p(K::Point_2(x, y), K::FT(K::FT::ET(w)));
        Rt::Vertex_handle v = rt.insert(p);
        if (v != Rt::Vertex_handle()) {
            v->info() = i;
        }
    }
    std::vector<std::array<long, 3>> triangles;
    for (auto f = rt.finite_faces_begin(); f != rt.finite_faces_end(); ++f) {
        std::array<long, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        triangles.push_back(t);
    }
    std::sort(triangles.begin(), triangles.end());
    std::vector<long> hidden;
    for (auto v = rt.hidden_vertices_begin(); v != rt.hidden_vertices_end(); ++v) {
        hidden.push_back(v->info());
    }
    std::sort(hidden.begin(), hidden.end());
    for (auto &t : triangles) {
        std::cout << "t " << t[0] << " " << t[1] << " " << t[2] << "\n";
    }
    for (long h : hidden) {
        std::cout << "h " << h << "\n";
    }
    return 0;
}
