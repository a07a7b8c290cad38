#include "analysis/triangulate_polygon.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <list>
#include <stdexcept>

#include "analysis/loop_sides.hpp"

namespace cadnurbs {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// Nesting level of every face: 0 outside, 1 inside an outer loop, 2 in a hole, ... (flood fill that
// crosses one loop side per level, loop_sides.hpp).
void mark_nesting(Cdt& cdt, const LoopSides<Cdt>& sides) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::list<Cdt::Edge> border;
  auto flood = [&](Cdt::Face_handle start, int level) {
    if (start->info() != -1) return;
    std::list<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      auto f = queue.front();
      queue.pop_front();
      if (f->info() != -1) continue;
      f->info() = level;
      for (int i = 0; i < 3; ++i) {
        auto n = f->neighbor(i);
        if (n->info() != -1) continue;
        if (sides.bounds(cdt, f, i)) border.emplace_back(f, i);
        else queue.push_back(n);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    const auto e = border.front();
    border.pop_front();
    auto n = e.first->neighbor(e.second);
    if (n->info() == -1) flood(n, e.first->info() + 1);
  }
}

}  // namespace

PlanarTriangulation triangulate_polygon(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                                        const std::vector<Eigen::Vector2d>& interior_points) {
  Cdt cdt;
  LoopSides<Cdt> sides;
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
      if (a != b) {
        cdt.insert_constraint(a, b);
        sides.add(a, b);
      }
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
  mark_nesting(cdt, sides);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1) out.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return out;
}

}  // namespace cadnurbs
