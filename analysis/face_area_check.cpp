#include "analysis/face_area_check.hpp"

#include <algorithm>
#include <map>

#include "analysis/surface_evaluator.hpp"
#include "analysis/trimmed_surface_area.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

double boundary_length(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  double length = 0;
  for (const auto& [edge, n] : uses)
    if (n == 1) length += (mesh.positions[edge.first] - mesh.positions[edge.second]).norm();
  return length;
}

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
  const double relative = out.area < 1 ? 0.005 : 0.001;
  out.allowance = std::max(relative * out.area, max_deviation * (boundary_length(mesh) + largest_curvature(face.surface) * out.area));
  return out;
}

}  // namespace cadnurbs
