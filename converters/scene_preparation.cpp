#include "converters/scene_preparation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "analysis/measure_deviation.hpp"
#include "analysis/scene_triangles.hpp"
#include "analysis/weld_exact.hpp"
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

namespace {

// The node tree with the trimmed surfaces only (what measure_deviation compares; fallen-back meshes
// are no face of either side).
SceneNode surfaces_only(const SceneNode& node) {
  SceneNode out = node;
  std::erase_if(out.shapes, [](const Shape& s) { return !std::holds_alternative<TrimmedSurface>(s.geometry); });
  for (auto& child : out.children) child = surfaces_only(child);
  return out;
}

void forget_edges(SceneNode& node) {
  for (auto& shape : node.shapes)
    if (auto* t = std::get_if<TrimmedSurface>(&shape.geometry))
      for (auto& loop : t->loops) loop.edges.clear();
  for (auto& child : node.children) forget_edges(child);
}

EdgeCounts sewn_open_edges(const Scene& scene, double diagonal, double deviation, double written_tolerance,
                           int& unshared) {
  Scene written = compact_scene(scene, written_tolerance);
  forget_edges(written.root);
  const Scene sewn = sew_faces(written, sewing_tolerance(diagonal, deviation));
  TessellationReport report;
  const TriangleMesh mesh = weld_exact(scene_triangles(tessellate_to_deviation(sewn, deviation, &report)));
  unshared = report.unshared_edge_uses;
  return count_boundary_edges(mesh);
}

}  // namespace

bool SimplifiedScene::watertight_kept() const {
  const bool closed_stays_closed = open_before.boundary > 0 || open_after.boundary == 0;
  const bool no_crack = open_after.boundary_length <= 1.01 * open_before.boundary_length + max_deviation;
  return unshared_after <= unshared_before && open_after.non_manifold <= open_before.non_manifold &&
         closed_stays_closed && no_crack;
}

SimplifiedScene simplified_scene(const Scene& scene, double max_deviation, double written_tolerance) {
  if (!(max_deviation > 0) || !std::isfinite(max_deviation))
    throw std::invalid_argument("simplified_scene: the deviation must be a positive number");
  SimplifiedScene out;
  out.max_deviation = max_deviation;
  const double diagonal = scene_bounding_box(scene).diagonal().norm();
  out.open_before = sewn_open_edges(scene, diagonal, max_deviation, written_tolerance, out.unshared_before);
  out.open_after = out.open_before;
  out.unshared_after = out.unshared_before;
  // Copies of a repeated part, simplified one by one, would lose different knots (a copy's parameters
  // may run the other way) and be written apart; placed as exact copies first, they stay equal.
  Scene instanced = scene;
  out.instanced = instance_repeats(instanced.root, written_tolerance);
  for (double move = kSimplifyShare * max_deviation; out.attempts < kSimplifyAttempts; move /= 8) {
    ++out.attempts;
    out.max_move = move;
    out.scene = simplify_scene(instanced, move, &out.knots);
    if (out.knots.knots_removed == 0) break;
    out.open_after = sewn_open_edges(out.scene, diagonal, max_deviation, written_tolerance, out.unshared_after);
    if (out.watertight_kept()) break;
  }
  if (out.knots.knots_removed > 0 && !out.watertight_kept()) {  // no move small enough kept the edges sewn
    const long points = out.knots.control_points_before;
    out.knots = SimplifyReport{};
    out.knots.control_points_before = out.knots.control_points_after = points;
  }
  if (out.knots.knots_removed == 0) {  // nothing moved: the input as it is, its mesh the same
    out.scene = scene;
    out.instanced = 0;
    out.max_move = 0;
    out.open_after = out.open_before;
    out.unshared_after = out.unshared_before;
    return out;
  }
  Scene before = scene, after = out.scene;
  before.root = surfaces_only(scene.root);
  after.root = surfaces_only(out.scene.root);
  if (out.knots.surfaces_changed > 0) {
    TessellationReport report;
    const TriangleMesh mesh = scene_triangles(tessellate_to_deviation(before, 0.25 * max_deviation, &report));
    out.mesh_deviation = report.certified_deviation;
    out.measured = measure_deviation(mesh, after).overall.max;
  }
  out.certified_deviation = std::max(out.measured + out.mesh_deviation, out.knots.curve_deviation);
  return out;
}

}  // namespace cadnurbs
