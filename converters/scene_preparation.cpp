#include "converters/scene_preparation.hpp"

#include <algorithm>
#include <cmath>

#include "core/bounding_box.hpp"

namespace cadnurbs {

double written_tolerance(const Scene& scene, int significant_digits) {
  const auto box = scene_bounding_box(scene);
  const double diagonal = box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-300);
  if (significant_digits <= 0) return 1e-6 * diagonal;
  const double largest = box.isEmpty() ? 1.0 : std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  return 0.5 * std::pow(10.0, 1 - significant_digits) * std::max(largest, 1e-300);
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
