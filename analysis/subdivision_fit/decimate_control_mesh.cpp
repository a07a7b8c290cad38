#include "analysis/subdivision_fit/decimate_control_mesh.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModHausdorffT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/subdivision_fit/turn_angle.hpp"

namespace cadnurbs {

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
  VertexAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

Eigen::Vector3d eig(const Mesh::Point& p) { return {p[0], p[1], p[2]}; }

// A half-edge collapse v0 -> v1 merges edge v0-vl into v1-vl (and v0-vr into v1-vr); OpenMesh keeps one
// edge of each pair, with its own status. This module passes a crease tag on to the survivor, so that a
// crease stays tagged along its whole course (a planar face's ears would otherwise cut it).
template <class MeshT>
class ModCreaseTagsT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ModCreaseTagsT, MeshT, CreaseTags);
  explicit ModCreaseTagsT(MeshT& mesh) : Base(mesh, true) {}
  float collapse_priority(const CollapseInfo&) override { return Base::LEGAL_COLLAPSE; }
  void preprocess_collapse(const CollapseInfo& ci) override {
    left_ = ci.vl.is_valid() && is_crease(ci.v0, ci.vl);
    right_ = ci.vr.is_valid() && is_crease(ci.v0, ci.vr);
  }
  void postprocess_collapse(const CollapseInfo& ci) override {
    if (left_) tag(ci.v1, ci.vl);
    if (right_) tag(ci.v1, ci.vr);
  }

 private:
  bool is_crease(typename Mesh::VertexHandle a, typename Mesh::VertexHandle b) {
    const auto h = Base::mesh().find_halfedge(a, b);
    return h.is_valid() && Base::mesh().status(Base::mesh().edge_handle(h)).feature();
  }
  void tag(typename Mesh::VertexHandle a, typename Mesh::VertexHandle b) {
    const auto h = Base::mesh().find_halfedge(a, b);
    if (h.is_valid()) Base::mesh().status(Base::mesh().edge_handle(h)).set_feature(true);
  }
  bool left_ = false, right_ = false;
};

}  // namespace

SubdivisionControlMesh decimate_control_mesh(const TriangleMesh& welded, int target_vertices, double sharp_angle,
                                      DecimationReport* report, const std::vector<int>& keep, double distance_guard) {
  if (target_vertices < 4) throw std::invalid_argument("decimate_control_mesh: the target must be 4 vertices or more");
  if (welded.triangles.empty()) throw std::invalid_argument("decimate_control_mesh: the mesh has no triangles");
  DecimationReport r;
  r.input_vertices = static_cast<int>(welded.positions.size());
  r.input_triangles = static_cast<int>(welded.triangles.size());

  Mesh mesh;
  omerr().disable();  // add_face's "complex vertex" notes: counted in skipped_triangles instead
  std::vector<Mesh::VertexHandle> handles;
  handles.reserve(welded.positions.size());
  for (const auto& p : welded.positions) handles.push_back(mesh.add_vertex(Mesh::Point(p.x(), p.y(), p.z())));
  for (const auto& t : welded.triangles) {
    const auto f = mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    if (!f.is_valid()) ++r.skipped_triangles;
  }
  mesh.update_face_normals();

  const bool keep_features = sharp_angle >= 0;
  OpenMesh::VPropHandleT<bool> turning_corner;  // a property: it follows the vertices through garbage collection
  mesh.add_property(turning_corner);
  for (const auto v : mesh.vertices()) mesh.property(turning_corner, v) = false;
  if (keep_features) {
    for (const auto e : mesh.edges()) {
      bool sharp = mesh.is_boundary(e);
      if (!sharp) {
        const auto n0 = mesh.normal(mesh.face_handle(mesh.halfedge_handle(e, 0)));
        const auto n1 = mesh.normal(mesh.face_handle(mesh.halfedge_handle(e, 1)));
        sharp = std::acos(std::clamp(OpenMesh::dot(n0, n1), -1.0, 1.0)) >= sharp_angle;
      }
      if (!sharp) continue;
      ++r.sharp_input_edges;
      mesh.status(e).set_feature(true);
      mesh.status(mesh.from_vertex_handle(mesh.halfedge_handle(e, 0))).set_feature(true);
      mesh.status(mesh.to_vertex_handle(mesh.halfedge_handle(e, 0))).set_feature(true);
    }
    for (const auto v : mesh.vertices()) {
      std::vector<Mesh::VertexHandle> ends;
      for (const auto e : mesh.ve_range(v))
        if (mesh.status(e).feature()) ends.push_back(mesh.from_vertex_handle(mesh.halfedge_handle(e, 0)) == v
                                                         ? mesh.to_vertex_handle(mesh.halfedge_handle(e, 0))
                                                         : mesh.from_vertex_handle(mesh.halfedge_handle(e, 0)));
      // Vertices with 3+ sharp edges are corners by themselves and the quadrics keep them where they
      // are (locking them too would stop the decimation early on coarse CAD tessellations, where
      // every hole's rim has many); a crease that turns sharply has to be locked to stay a corner.
      const bool corner =
          ends.size() == 2 && turn_angle(eig(mesh.point(ends[0])), eig(mesh.point(v)), eig(mesh.point(ends[1]))) >= sharp_angle;
      mesh.property(turning_corner, v) = corner;
      if (corner) {
        mesh.status(v).set_locked(true);
        ++r.locked_corners;
      }
    }
  }

  for (const int v : keep) {
    if (v < 0 || v >= static_cast<int>(handles.size()))
      throw std::invalid_argument("decimate_control_mesh: kept vertex " + std::to_string(v) + " is out of range");
    mesh.status(handles[v]).set_locked(true);
  }

  OpenMesh::Decimater::DecimaterT<Mesh> decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
  decimater.add(quadric);
  decimater.module(quadric).unset_max_err();
  OpenMesh::Decimater::ModNormalFlippingT<Mesh>::Handle flipping;
  ModCreaseTagsT<Mesh>::Handle crease_tags;
  if (keep_features) {
    decimater.add(crease_tags);
    decimater.add(flipping);
    decimater.module(flipping).set_max_normal_deviation(60.0);
  }
  OpenMesh::Decimater::ModHausdorffT<Mesh>::Handle hausdorff;
  if (distance_guard > 0) {
    decimater.add(hausdorff);
    decimater.module(hausdorff).set_tolerance(distance_guard);
  }
  decimater.initialize();
  decimater.decimate_to(target_vertices);
  mesh.garbage_collection();
  omerr().enable();

  SubdivisionControlMesh out;
  for (const auto v : mesh.vertices()) out.positions.push_back(eig(mesh.point(v)));
  for (const auto f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto v : mesh.fv_range(f)) t[k++] = v.idx();
    out.triangles.push_back(t);
  }
  if (keep_features) {
    for (const auto e : mesh.edges()) {
      if (!mesh.status(e).feature() || mesh.is_boundary(e)) continue;
      const int a = mesh.from_vertex_handle(mesh.halfedge_handle(e, 0)).idx();
      const int b = mesh.to_vertex_handle(mesh.halfedge_handle(e, 0)).idx();
      out.crease_edges.push_back({std::min(a, b), std::max(a, b)});
    }
    for (const auto v : mesh.vertices()) {
      if (!mesh.property(turning_corner, v)) continue;
      int sharp = 0;
      for (const auto e : mesh.ve_range(v)) sharp += mesh.status(e).feature() || mesh.is_boundary(e);
      if (sharp == 2) out.corner_vertices.push_back(v.idx());  // 3+ sharp edges make a corner by themselves
    }
  }
  if (report) *report = r;
  return out;
}

}  // namespace cadnurbs
