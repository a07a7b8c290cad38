#include "analysis/nurss/nurss_limit_mesh.hpp"


#include "analysis/nurss/nurss_face_point.hpp"
#include "analysis/nurss/refine_nurss.hpp"

namespace cadnurbs {

namespace {

void add_polygon(NurssTriangles& out, const std::vector<int>& ring, int label) {
  auto add = [&](int a, int b, int c) {
    out.mesh.triangles.push_back({a, b, c});
    out.triangle_labels.push_back(label);
  };
  const auto& p = out.mesh.positions;
  if (ring.size() == 4) {
    if ((p[ring[0]] - p[ring[2]]).norm() <= (p[ring[1]] - p[ring[3]]).norm()) {
      add(ring[0], ring[1], ring[2]);
      add(ring[0], ring[2], ring[3]);
    } else {
      add(ring[0], ring[1], ring[3]);
      add(ring[1], ring[2], ring[3]);
    }
    return;
  }
  for (size_t k = 1; k + 1 < ring.size(); ++k) add(ring[0], ring[k], ring[k + 1]);
}

}  // namespace

NurssTriangles nurss_face_point_mesh(const NurssMesh& mesh) {
  validate(mesh, "NURSS mesh");
  NurssTriangles out;
  for (int f = 0; f < mesh.face_count(); ++f) out.mesh.positions.push_back(euclidean(nurss_face_point(mesh, NurssFaceId(f))));
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const auto ring = mesh.ring_of_faces(NurssVertexId(v));
    if (!ring) continue;
    std::vector<int> polygon;
    for (NurssFaceId f : *ring) polygon.push_back(f.value);
    add_polygon(out, polygon, mesh.largest_label(*ring));
  }
  return out;
}

NurssTriangles nurss_limit_mesh(const NurssMesh& mesh, int levels) {
  return nurss_face_point_mesh(refine_nurss(mesh, levels));
}

TriangleMesh nurss_triangles_with_label(const NurssTriangles& triangles, int label) {
  TriangleMesh out;
  std::vector<int> new_index(triangles.mesh.positions.size(), -1);
  for (size_t t = 0; t < triangles.mesh.triangles.size(); ++t) {
    if (triangles.triangle_labels[t] != label) continue;
    std::array<int, 3> tri;
    for (int k = 0; k < 3; ++k) {
      int& v = new_index[triangles.mesh.triangles[t][k]];
      if (v < 0) {
        v = static_cast<int>(out.positions.size());
        out.positions.push_back(triangles.mesh.positions[triangles.mesh.triangles[t][k]]);
      }
      tri[k] = v;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

NurssTriangles nurss_control_triangles(const NurssMesh& mesh) {
  NurssTriangles out;
  out.mesh.positions = mesh.positions();
  for (int f = 0; f < mesh.face_count(); ++f) {
    const auto& c = mesh.corners(NurssFaceId(f));
    for (size_t k = 1; k + 1 < c.size(); ++k) {
      out.mesh.triangles.push_back({c[0].value, c[k].value, c[k + 1].value});
      out.triangle_labels.push_back(mesh.label(NurssFaceId(f)));
    }
  }
  return out;
}

}  // namespace cadnurbs
