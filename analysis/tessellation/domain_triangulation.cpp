#include "analysis/tessellation/domain_triangulation.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>

#include "analysis/tessellation/loop_sides.hpp"

namespace cadnurbs {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// CGAL leaves an int info uninitialised; vertices it creates itself (constraint crossings) must be
// recognisable as unnamed.
struct VertexId {
  int value = -1;
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexId, Kernel>;
using FaceBase =
    CGAL::Triangulation_face_base_with_info_2<int, Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

}  // namespace

struct DomainTriangulation::Impl {
  double su, sv;
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  std::vector<Eigen::Vector2d> uvs;
  LoopSides<Cdt> sides;  // how many loop sides run along each constraint (loop_sides.hpp)

  int add(Cdt::Vertex_handle v, const Eigen::Vector2d& uv) {
    v->info().value = static_cast<int>(handles.size());
    handles.push_back(v);
    uvs.push_back(uv);
    return v->info().value;
  }
  // Vertices CGAL created at constraint crossings have no id yet.
  void name_new_vertices() {
    if (cdt.number_of_vertices() == handles.size()) return;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if (v->info().value < 0) add(v, Eigen::Vector2d(v->point().x() / su, v->point().y() / sv));
  }
};

DomainTriangulation::DomainTriangulation(double scale_u, double scale_v) : impl_(std::make_unique<Impl>()) {
  impl_->su = scale_u;
  impl_->sv = scale_v;
}

DomainTriangulation::~DomainTriangulation() = default;

int DomainTriangulation::insert(const Eigen::Vector2d& uv, int near) {
  const auto before = impl_->cdt.number_of_vertices();
  // Points come in runs (loops, grid rows) or inside a known triangle (refinement): locating from a
  // nearby vertex walks a few triangles instead of across the whole domain.
  const auto& handles = impl_->handles;
  const Cdt::Face_handle hint = near >= 0 ? handles[near]->face() : handles.empty() ? Cdt::Face_handle() : handles.back()->face();
  auto v = impl_->cdt.insert(Kernel::Point_2(uv.x() * impl_->su, uv.y() * impl_->sv), hint);
  if (impl_->cdt.number_of_vertices() == before) return v->info().value;
  return impl_->add(v, uv);
}

void DomainTriangulation::insert_loop(const std::vector<int>& ids) {
  for (size_t i = 0; i < ids.size(); ++i) {
    const int a = ids[i], b = ids[(i + 1) % ids.size()];
    if (a != b) {
      impl_->cdt.insert_constraint(impl_->handles[a], impl_->handles[b]);
      impl_->sides.add(impl_->handles[a], impl_->handles[b]);
    }
    impl_->name_new_vertices();
  }
}

int DomainTriangulation::split_constrained_edge(int a, int b, const Eigen::Vector2d& uv) {
  Cdt::Face_handle f;
  int i;
  auto& cdt = impl_->cdt;
  if (cdt.is_edge(impl_->handles[a], impl_->handles[b], f, i)) cdt.remove_constrained_edge(f, i);
  const int m = insert(uv);
  cdt.insert_constraint(impl_->handles[a], impl_->handles[m]);
  cdt.insert_constraint(impl_->handles[m], impl_->handles[b]);
  impl_->sides.split(impl_->handles[a], impl_->handles[b], impl_->handles[m]);
  impl_->name_new_vertices();
  return m;
}

bool DomainTriangulation::is_constrained(int a, int b) const {
  Cdt::Face_handle f;
  int i;
  return impl_->cdt.is_edge(impl_->handles[a], impl_->handles[b], f, i) && impl_->cdt.is_constrained({f, i});
}

int DomainTriangulation::vertex_count() const { return static_cast<int>(impl_->handles.size()); }

const Eigen::Vector2d& DomainTriangulation::uv(int id) const { return impl_->uvs[id]; }

std::vector<std::array<int, 3>> DomainTriangulation::inside_triangles() const {
  Cdt& cdt = impl_->cdt;
  // Nesting level by flood fill: crossing a constrained edge goes one level deeper, unless an even
  // number of loop sides run along it (loop_sides.hpp).
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::deque<Cdt::Face_handle> next_level{cdt.infinite_face()};
  int level = 0;
  while (!next_level.empty()) {
    std::deque<Cdt::Face_handle> queue;
    for (auto f : next_level)
      if (f->info() == -1) queue.push_back(f);
    next_level.clear();
    for (auto f : queue) f->info() = -2;  // queued at this level
    while (!queue.empty()) {
      auto f = queue.front();
      queue.pop_front();
      f->info() = level;
      for (int i = 0; i < 3; ++i) {
        auto n = f->neighbor(i);
        if (n->info() != -1) continue;
        if (impl_->sides.bounds(cdt, f, i)) {
          next_level.push_back(n);
        } else {
          n->info() = -2;
          queue.push_back(n);
        }
      }
    }
    ++level;
  }
  std::vector<std::array<int, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1) out.push_back({f->vertex(0)->info().value, f->vertex(1)->info().value, f->vertex(2)->info().value});
  return out;
}

}  // namespace cadnurbs
