#include "analysis/mesh/triangulate_polygon.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <stdexcept>

#include "core/point_in_loops.hpp"

namespace cadnurbs {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// 1 inside, 0 outside, for every finite face. Faces joined by unconstrained edges form regions between
// loop sides, each inside or outside as a whole; the project's one even-odd test (core/point_in_loops)
// decides each region at the centroid of its largest triangle. (Counting constraint crossings alone
// fails where two loops share a side, which CGAL keeps as one constraint: a hole touching its outer
// loop along a tiny edge, as in KiCad's LED domes, was left in.)
void mark_inside(Cdt& cdt, const PointInLoops& region) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Cdt::Face_handle> largest;  // per region
  std::vector<double> largest_area;
  for (auto start = cdt.finite_faces_begin(); start != cdt.finite_faces_end(); ++start) {
    if (start->info() != -1) continue;
    const int id = static_cast<int>(largest.size());
    largest.push_back(start);
    largest_area.push_back(-1);
    std::vector<Cdt::Face_handle> stack{start};
    start->info() = id;
    while (!stack.empty()) {
      const auto f = stack.back();
      stack.pop_back();
      const double area = std::abs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
      if (area > largest_area[id]) largest_area[id] = area, largest[id] = f;
      for (int i = 0; i < 3; ++i) {
        const auto n = f->neighbor(i);
        if (n->info() != -1 || cdt.is_infinite(n) || cdt.is_constrained(Cdt::Edge(f, i))) continue;
        n->info() = id;
        stack.push_back(n);
      }
    }
  }
  std::vector<int> inside(largest.size());
  for (size_t id = 0; id < largest.size(); ++id) {
    const auto c = CGAL::centroid(largest[id]->vertex(0)->point(), largest[id]->vertex(1)->point(),
                                  largest[id]->vertex(2)->point());
    inside[id] = region.inside(Eigen::Vector2d(c.x(), c.y())) ? 1 : 0;
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) f->info() = inside[f->info()];
}

}  // namespace

PlanarTriangulation triangulate_polygon(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                                        const std::vector<Eigen::Vector2d>& interior_points) {
  Cdt cdt;
  PlanarTriangulation out;
  // A vertex that already exists keeps its first index; a new one takes the point's index.
  auto add = [&](const Eigen::Vector2d& p) {
    const auto before = cdt.number_of_vertices();
    auto v = cdt.insert(Kernel::Point_2(p.x(), p.y()));
    if (cdt.number_of_vertices() > before) v->info() = static_cast<int>(out.points.size());
    out.points.push_back(p);
    return v;
  };
  for (const auto& loop : loops) {
    if (loop.size() < 3) throw std::runtime_error("triangulate_polygon: a loop has fewer than 3 points");
    std::vector<Cdt::Vertex_handle> handles;
    for (const auto& p : loop) handles.push_back(add(p));
    for (size_t i = 0; i < handles.size(); ++i) {
      auto a = handles[i], b = handles[(i + 1) % handles.size()];
      if (a != b) cdt.insert_constraint(a, b);
    }
  }
  // Crossing loop edges create vertices the loop points above did not name.
  const int known = static_cast<int>(out.points.size());
  std::vector<Cdt::Vertex_handle> named;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) named.push_back(v);
  for (auto v : named) {
    const auto& p = v->point();
    const int i = v->info();
    if (i < 0 || i >= known || out.points[i] != Eigen::Vector2d(p.x(), p.y())) {
      v->info() = static_cast<int>(out.points.size());
      out.points.emplace_back(p.x(), p.y());
    }
  }
  for (const auto& p : interior_points) add(p);
  mark_inside(cdt, PointInLoops(loops));
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() == 1) out.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return out;
}

}  // namespace cadnurbs
