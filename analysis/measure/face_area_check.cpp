#include "analysis/measure/face_area_check.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/measure/trimmed_surface_area.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

double largest_curvature(const NurbsSurface& surface) {
  const SurfaceEvaluator e(surface);
  auto samples = [](const std::vector<double>& knots) {
    const std::vector<double> breaks = distinct_knots(knots);
    const int per_span = std::max(2, std::min(8, 64 / std::max<int>(1, static_cast<int>(breaks.size()) - 1)));
    std::vector<double> out;
    for (size_t i = 0; i + 1 < breaks.size(); ++i)
      for (int k = 0; k < per_span; ++k) out.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * (k + 0.5) / per_span);
    return out;
  };
  double largest = 0;
  for (double v : samples(surface.v_knots))
    for (double u : samples(surface.u_knots)) {
      const SurfaceJet j = e.jet(u, v, 2);
      const Eigen::Vector3d n = j.su.cross(j.sv);
      const double area2 = n.squaredNorm();  // EG - F^2
      if (!(area2 > 1e-24 * j.su.squaredNorm() * j.sv.squaredNorm())) continue;  // a pole: no normal
      const Eigen::Vector3d un = n / std::sqrt(area2);
      const double E = j.su.dot(j.su), F = j.su.dot(j.sv), G = j.sv.dot(j.sv);
      const double L = un.dot(j.suu), M = un.dot(j.suv), N = un.dot(j.svv);
      // Principal curvatures: roots of (EG - F^2) k^2 - (EN + GL - 2FM) k + (LN - M^2) = 0.
      const double mean = (E * N + G * L - 2 * F * M) / (2 * area2), gauss = (L * N - M * M) / area2;
      const double root = std::sqrt(std::max(0.0, mean * mean - gauss));
      largest = std::max(largest, std::abs(mean) + root);
    }
  return largest;
}

FaceAreaCheck check_face_area(const TrimmedSurface& face, const TriangleMesh& mesh, double max_deviation) {
  FaceAreaCheck out;
  out.area = trimmed_surface_area(face, 1e-4);  // a tenth of the smallest allowance
  out.mesh_area = mesh_area(mesh);
  out.relative_limit = out.area < 1 ? 0.005 : 0.001;
  const double band = count_boundary_edges(mesh).boundary_length;
  out.allowance = std::max(out.relative_limit * out.area,
                           max_deviation * (band + largest_curvature(face.surface) * out.area));
  return out;
}

namespace {

void check_node(const SceneNode& exact, const SceneNode& meshed, double d, std::vector<SceneFaceAreaCheck>& out) {
  for (size_t i = 0; i < exact.shapes.size() && i < meshed.shapes.size(); ++i) {
    const auto* face = std::get_if<TrimmedSurface>(&exact.shapes[i].geometry);
    const auto* mesh = std::get_if<TriangleMesh>(&meshed.shapes[i].geometry);
    if (face && mesh) out.push_back({&exact.shapes[i], check_face_area(*face, *mesh, d)});
  }
  for (size_t i = 0; i < exact.children.size() && i < meshed.children.size(); ++i)
    check_node(exact.children[i], meshed.children[i], d, out);
}

}  // namespace

std::vector<SceneFaceAreaCheck> check_face_areas(const Scene& exact, const Scene& meshed, double max_deviation) {
  std::vector<SceneFaceAreaCheck> out;
  check_node(exact.root, meshed.root, max_deviation, out);
  return out;
}

}  // namespace cadnurbs
