/* SPDX-License-Identifier: MIT */
// tests/reference/cgal_interpolate.cpp - the reference for vor_sibson,
// vor_laplace, vor_interpolate and vor_interpolate_laplace: CGAL's
// Delaunay_triangulation_2 with exact constructions (Epeck, whose numbers
// are exact rationals), on the same input files. Host tests only
// (tests/reference/compare_interpolate.py); the library never depends on
// CGAL.
//
//   cgal-interpolate SITES QUERIES
//
// SITES: "x y value" lines (a repeated point keeps its first line's id and
// value); QUERIES: "x y" lines. For each query four lines:
//   s X Y ID:NUM/DEN ...   CGAL::natural_neighbor_coordinates_2 (Sibson),
//                          each coordinate divided by CGAL's norm
//   l X Y ID:NUM/DEN ...   Laplace's coordinates (below)
//   S X Y NUM/DEN          CGAL::linear_interpolation over the Sibson ones
//   L X Y NUM/DEN          the same sum over the Laplace ones
// each "X Y outside" when CGAL answers that q is outside the convex hull,
// or "X Y none" when the sites do not span the plane (CGAL's functions
// require a triangulation of dimension 2). Numbers are CGAL's exact
// rationals, printed by GMP in lowest terms.
//
// CGAL 5.5 has Laplace (non-Sibsonian) coordinates in 3D only
// (laplace_natural_neighbor_coordinates_3). In 2D they are built here from
// their definition with CGAL's exact objects: CGAL's conflict zone of q
// (get_boundary_of_conflicts, the same one natural_neighbor_coordinates_2
// walks), and for each site v on its boundary, with prev and next its
// neighbours on the boundary, the edge of q's cell facing v runs from
// circumcenter(prev, v, q) to circumcenter(v, q, next); it is
// perpendicular to q - v, so its length over |q - v| is the rational
// |e . perp(q - v)| / |q - v|^2. At a site and on a hull edge, where CGAL
// answers without a conflict zone, Laplace's coordinates are CGAL's
// Sibson ones (both are the linear interpolation there).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/interpolation_functions.h>
#include <CGAL/natural_neighbor_coordinates_2.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <list>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
typedef K::FT FT;
typedef K::Point_2 Point;
typedef CGAL::Triangulation_vertex_base_with_info_2<std::pair<long, long>, K> Vb; /* id, value */
typedef CGAL::Triangulation_data_structure_2<Vb> Tds;
typedef CGAL::Delaunay_triangulation_2<K, Tds> Dt;
typedef Dt::Vertex_handle Vertex;
typedef std::vector<std::pair<Vertex, FT>> Coordinates;

/* natural_neighbor_coordinates_2's output functor: keeps the vertex. */
struct Keep_vertex {
    typedef std::pair<Vertex, FT> argument_type;
    typedef std::pair<Vertex, FT> result_type;
    result_type operator()(const argument_type &a) const { return a; }
};

/* linear_interpolation's value functor: the site's value. */
struct Site_value {
    typedef std::pair<FT, bool> result_type;
    result_type operator()(const Vertex &v) const { return std::make_pair(FT(v->info().second), true); }
};

static void print_coordinates(char tag, const Point &q, const Coordinates &c, const FT &norm)
{
    std::cout << tag << " " << q.x().exact() << " " << q.y().exact();
    for (auto &e : c) {
        FT w = e.second / norm;
        std::cout << " " << e.first->info().first << ":" << w.exact();
    }
    std::cout << "\n";
}

static void print_value(char tag, const Point &q, const Coordinates &c, const FT &norm)
{
    FT v = CGAL::linear_interpolation(c.begin(), c.end(), norm, Site_value());
    std::cout << tag << " " << q.x().exact() << " " << q.y().exact() << " " << v.exact() << "\n";
}

/* Laplace's coordinates of q strictly inside the hull, not a site, from
 * CGAL's conflict zone (see the top). */
static FT laplace(const Dt &dt, const Point &q, Coordinates &out)
{
    Dt::Locate_type lt;
    int li;
    Dt::Face_handle f = dt.locate(q, lt, li);
    std::list<Dt::Edge> hole;
    dt.get_boundary_of_conflicts(q, std::back_inserter(hole), f);
    std::vector<Vertex> ring;
    for (auto &e : hole) {
        ring.push_back(e.first->vertex(dt.cw(e.second)));
    }
    size_t n = ring.size();
    FT sum(0);
    for (size_t i = 0; i < n; i++) {
        Vertex prev = ring[(i + n - 1) % n], v = ring[i], next = ring[(i + 1) % n];
        Point a = CGAL::circumcenter(prev->point(), v->point(), q);
        Point b = CGAL::circumcenter(v->point(), next->point(), q);
        K::Vector_2 e = b - a, d = q - v->point();
        if (e * d != 0) {
            std::cerr << "cgal-interpolate: an edge of q's cell is not perpendicular to q - v\n";
            std::exit(1);
        }
        FT t = (e.y() * d.x() - e.x() * d.y()) / d.squared_length();
        if (t < 0) {
            t = -t;
        }
        if (t != 0) {
            out.push_back(std::make_pair(v, t));
            sum += t;
        }
    }
    return sum;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::cerr << "usage: cgal-interpolate SITES QUERIES\n";
        return 2;
    }
    Dt dt;
    std::ifstream sites(argv[1]), queries(argv[2]);
    std::string line;
    long id = 0;
    while (std::getline(sites, line)) {
        std::istringstream s(line);
        long x, y, value;
        if (line.empty() || line[0] == '#' || !(s >> x >> y >> value)) {
            continue;
        }
        size_t before = dt.number_of_vertices();
        Vertex v = dt.insert(Point(x, y));
        if (dt.number_of_vertices() != before) {
            v->info() = std::make_pair(id, value);
        }
        id++;
    }
    while (std::getline(queries, line)) {
        std::istringstream s(line);
        long x, y;
        if (line.empty() || line[0] == '#' || !(s >> x >> y)) {
            continue;
        }
        Point q(x, y);
        if (dt.dimension() < 2) {
            std::cout << "s " << x << " " << y << " none\nl " << x << " " << y << " none\n"
                      << "S " << x << " " << y << " none\nL " << x << " " << y << " none\n";
            continue;
        }
        Coordinates sibson;
        auto r = CGAL::natural_neighbor_coordinates_2(dt, q, std::back_inserter(sibson), Keep_vertex());
        if (!r.third) {
            std::cout << "s " << x << " " << y << " outside\nl " << x << " " << y << " outside\n"
                      << "S " << x << " " << y << " outside\nL " << x << " " << y << " outside\n";
            continue;
        }
        Dt::Locate_type lt;
        int li;
        Dt::Face_handle f = dt.locate(q, lt, li);
        Coordinates lap;
        FT lap_norm = r.second;
        if (lt == Dt::VERTEX || (lt == Dt::EDGE && (dt.is_infinite(f) || dt.is_infinite(f->neighbor(li))))) {
            lap = sibson;
        } else {
            lap_norm = laplace(dt, q, lap);
        }
        print_coordinates('s', q, sibson, r.second);
        print_coordinates('l', q, lap, lap_norm);
        print_value('S', q, sibson, r.second);
        print_value('L', q, lap, lap_norm);
    }
    return 0;
}
