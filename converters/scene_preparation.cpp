#include "converters/scene_preparation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/bounding_box.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

double written_tolerance(const Scene& scene, int significant_digits) {
  const auto box = scene_bounding_box(scene);
  const double diagonal = box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-300);
  if (significant_digits <= 0) return 1e-6 * diagonal;
  const double largest = box.isEmpty() ? 1.0 : std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  return 0.5 * std::pow(10.0, 1 - significant_digits) * std::max(largest, 1e-300);
}

namespace {

double checked_box_diagonal(const Eigen::AlignedBox3d& box, const std::string& in) {
  if (box.isEmpty()) return 0.0;
  if (!box.min().allFinite() || !box.max().allFinite())
    throw FileError(in + ": a coordinate is not finite once placed (a transform overflows)");
  const double largest = std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  if (largest > kLargestCoordinate) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", largest);
    throw FileError(in + ": the part's size is not finite in double precision (coordinates up to " + text +
                    "; squared lengths overflow beyond 1e+150): scale it down");
  }
  return box.diagonal().norm();
}

}  // namespace

double checked_diagonal(const Scene& scene, const std::string& in) {
  return checked_box_diagonal(scene_bounding_box(scene), in);
}

double checked_mesh_diagonal(const TriangleMesh& mesh, const std::string& in) {
  Eigen::AlignedBox3d box;
  for (const auto& p : mesh.positions) box.extend(p);
  const double diagonal = checked_box_diagonal(box, in);
  if (!(diagonal > 0)) throw FileError(in + ": all points coincide: every triangle is degenerate");
  return diagonal;
}

double default_deviation(double diagonal, const std::string& in) {
  if (!(diagonal > 0)) throw FileError(in + ": all points coincide: give --deviation");
  return 1e-3 * diagonal;
}

CertifiedMesh certified_mesh(const BrepTranslation& loaded, const Scene& scene, double max_deviation,
                             bool check_face_areas) {
  CertifiedMesh result;
  const SceneCounts counts = count_entities(scene);
  result.sewn = loaded.face_count == 0 && counts.surfaces + counts.polygon_meshes > 0;
  if (result.sewn) {
    result.sewing_tolerance = sewing_tolerance(scene_bounding_box(scene).diagonal().norm(), max_deviation);
    result.faces = sew_faces(scene, result.sewing_tolerance, &result.sewing);
  }
  result.meshes =
      tessellate_to_deviation(result.sewn ? result.faces : scene, max_deviation, &result.report, check_face_areas);
  return result;
}

}  // namespace cadnurbs
