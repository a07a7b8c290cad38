#include "analysis/nurss/refine_nurss.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/nurss/nurss_face_point.hpp"

namespace cadnurbs {

namespace {

// 1 + 2 cos(2π m / n), with cos snapped to its exact value where that is 0 or ±1/2 or ±1, so that a
// regular quad's rule has exact zeros where the tensor product has them.
double ring_weight(int m, int n) {
  double c = std::cos(2 * std::numbers::pi * m / n);
  for (double exact : {-1.0, -0.5, 0.0, 0.5, 1.0})
    if (std::abs(c - exact) < 1e-14) c = exact;
  return 1 + 2 * c;
}

// New vertices of face f, homogeneous.
std::vector<Eigen::Vector4d> face_corner_points(const NurssMesh& mesh, NurssFaceId f) {
  const auto& p = mesh.corners(f);
  const int n = static_cast<int>(p.size());
  const std::vector<double> c = nurss_corner_factors(mesh, f);
  double sum = 0;
  for (double ck : c) sum += ck;
  std::vector<Eigen::Vector4d> x(n);
  for (int k = 0; k < n; ++k) x[k] = mesh.homogeneous(p[k]);
  const Eigen::Vector4d v = nurss_face_point(mesh, f, c);
  std::vector<Eigen::Vector4d> out(n);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector4d ring = -n * x[i];
    for (int j = 0; j < n; ++j) ring += ring_weight(i - j, n) * x[j];
    out[i] = (x[i] + v) / 2 + (c[(i + 2) % n] + c[((i - 2) % n + n) % n]) / (8 * sum) * ring;
  }
  return out;
}

}  // namespace

NurssMesh refine_nurss(const NurssMesh& mesh) {
  validate(mesh, "NURSS mesh");
  const int faces = mesh.face_count();
  std::vector<int> offset(faces + 1, 0);
  for (int f = 0; f < faces; ++f) offset[f + 1] = offset[f] + static_cast<int>(mesh.corners(NurssFaceId(f)).size());

  NurssMesh out;
  for (int f = 0; f < faces; ++f)
    for (const Eigen::Vector4d& h : face_corner_points(mesh, NurssFaceId(f))) out.add_vertex(euclidean(h), h.w());

  // The corner of face f at vertex v, as a new vertex.
  auto corner_at = [&](NurssFaceId f, NurssVertexId v) { return NurssVertexId(offset[f.value] + mesh.corner_index(f, v)); };

  // F-faces.
  for (int f = 0; f < faces; ++f) {
    std::vector<NurssVertexId> corners;
    for (int k = offset[f]; k < offset[f + 1]; ++k) corners.emplace_back(k);
    out.add_face(corners, mesh.label(NurssFaceId(f)));
  }
  // E-faces: edge a-b with face f having a→b and face g having b→a.
  for (int e = 0; e < mesh.edge_count(); ++e) {
    const NurssEdge& edge = mesh.edge(NurssEdgeId(e));
    const NurssVertexId a = edge.ends[0], b = edge.ends[1];
    const auto f = mesh.face_with_side(a, b), g = mesh.face_with_side(b, a);
    if (!f || !g) continue;
    out.add_face({corner_at(*f, b), corner_at(*f, a), corner_at(*g, a), corner_at(*g, b)},
                 mesh.largest_label({*f, *g}));
  }
  // V-faces.
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const auto ring = mesh.ring_of_faces(NurssVertexId(v));
    if (!ring) continue;
    std::vector<NurssVertexId> corners;
    for (NurssFaceId f : *ring) corners.push_back(corner_at(f, NurssVertexId(v)));
    out.add_face(corners, mesh.largest_label(*ring));
  }

  // Intervals: P'_i holds d(P_i → P_{i+1})/2 toward P'_{i+1} and across P_{i-1}P_i, d(P_i → P_{i-1})/2 toward
  // P'_{i-1} and across P_iP_{i+1}.
  for (int f = 0; f < faces; ++f) {
    const auto& c = mesh.corners(NurssFaceId(f));
    const int n = static_cast<int>(c.size());
    for (int i = 0; i < n; ++i) {
      const NurssVertexId p = c[i], next = c[(i + 1) % n], prev = c[(i + n - 1) % n];
      const NurssVertexId me(offset[f] + i);
      const double along_next = mesh.interval(p, next) / 2, along_prev = mesh.interval(p, prev) / 2;
      out.set_interval(me, NurssVertexId(offset[f] + (i + 1) % n), along_next);
      out.set_interval(me, NurssVertexId(offset[f] + (i + n - 1) % n), along_prev);
      if (const auto across_next = mesh.face_with_side(next, p))  // the face across P_i P_{i+1}
        out.set_interval(me, corner_at(*across_next, p), along_prev);
      if (const auto across_prev = mesh.face_with_side(p, prev))  // the face across P_{i-1} P_i
        out.set_interval(me, corner_at(*across_prev, p), along_next);
    }
  }
  return out;
}

NurssMesh refine_nurss(const NurssMesh& mesh, int levels) {
  NurssMesh m = mesh;
  for (int l = 0; l < levels; ++l) m = refine_nurss(m);
  return m;
}

}  // namespace cadnurbs
