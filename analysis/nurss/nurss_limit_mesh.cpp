#include "analysis/nurss/nurss_limit_mesh.hpp"

#include <algorithm>
#include <map>

#include "analysis/nurss/nurss_face_point.hpp"
#include "analysis/nurss/refine_nurss.hpp"

namespace cadnurbs {

namespace {

// Twice a triangle's area below this fraction of its longest side squared: a sliver of points on one line.
constexpr double kSliver = 1e-10;

void add_polygon(NurssTriangles& out, const std::vector<int>& ring, int label) {
  const auto& p = out.mesh.positions;
  auto add = [&](int a, int b, int c) {
    const double longest = std::max({(p[b] - p[a]).norm(), (p[c] - p[b]).norm(), (p[a] - p[c]).norm()});
    if ((p[b] - p[a]).cross(p[c] - p[a]).norm() <= kSliver * longest * longest) return;
    out.mesh.triangles.push_back({a, b, c});
    out.triangle_labels.push_back(label);
  };
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
  // One vertex per distinct face point: faces between the two copies a zero interval leaves have
  // coinciding face points.
  std::vector<int> vertex_of_face(mesh.face_count());
  std::map<std::array<double, 3>, int> vertex_at;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d p = euclidean(nurss_face_point(mesh, NurssFaceId(f)));
    const auto [it, fresh] = vertex_at.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, out.mesh.positions.size());
    if (fresh) out.mesh.positions.push_back(p);
    vertex_of_face[f] = it->second;
  }
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const auto ring = mesh.ring_of_faces(NurssVertexId(v));
    if (!ring) continue;
    std::vector<int> polygon;
    for (NurssFaceId f : *ring) polygon.push_back(vertex_of_face[f.value]);
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
