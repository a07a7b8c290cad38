#include "analysis/compaction/compact_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "analysis/compaction/instance_repeated_parts.hpp"
#include "analysis/compaction/join_straight_trim_runs.hpp"
#include "core/knot_removal.hpp"
#include "analysis/compaction/planar_face_polygons.hpp"
#include "analysis/mesh/weld_polygon_meshes.hpp"
#include "analysis/knots/whole_number_knots.hpp"

namespace cadnurbs {

namespace {

// The loop is the domain's boundary: one straight polyline through the four corners.
bool is_domain_boundary(const TrimLoop& loop, const NurbsSurface& s, double uv_tolerance) {
  if (loop.segments.size() != 1) return false;
  const auto* polyline = std::get_if<Polyline2D>(&loop.segments[0]);
  if (!polyline) return false;
  std::vector<Eigen::Vector2d> points = without_collinear_points(polyline->points, uv_tolerance);
  if (points.size() > 1 && (points.front() - points.back()).norm() <= uv_tolerance) points.pop_back();
  if (points.size() != 4) return false;
  const Eigen::Vector2d corners[4] = {
      {s.u_start(), s.v_start()}, {s.u_end(), s.v_start()}, {s.u_end(), s.v_end()}, {s.u_start(), s.v_end()}};
  for (const auto& corner : corners) {
    bool found = false;
    for (const auto& p : points) found = found || (p - corner).norm() <= uv_tolerance;
    if (!found) return false;
  }
  return true;
}

class Compactor {
 public:
  Compactor(double tolerance, CompactReport& report) : tau_(tolerance), report_(report) {}

  void node(SceneNode& node) {
    std::vector<Shape> kept;
    // Unnamed planar faces by colour (no colour: the node's), in first-seen order.
    std::vector<std::pair<std::optional<Colour>, std::vector<PolygonMesh>>> planar;
    for (auto& shape : node.shapes) {
      if (auto* face = std::get_if<TrimmedSurface>(&shape.geometry)) {
        if (auto polygons = planar_face_polygons(*face, tau_)) {
          ++report_.planar_faces;
          if (!shape.name.empty()) {
            shape.geometry = std::move(*polygons);
            kept.push_back(std::move(shape));
            ++report_.polygon_meshes;
            continue;
          }
          auto group = std::find_if(planar.begin(), planar.end(), [&](const auto& g) { return g.first == shape.colour; });
          if (group == planar.end()) group = planar.insert(planar.end(), {shape.colour, {}});
          group->second.push_back(std::move(*polygons));
          continue;
        }
        compact_face(*face);
      } else if (auto* curve = std::get_if<NurbsCurve>(&shape.geometry)) {
        report_.reparametrised += use_whole_number_knots(*curve);
      }
      kept.push_back(std::move(shape));
    }
    std::vector<Shape> shapes;
    for (auto& [colour, meshes] : planar) {
      Shape shape;
      shape.geometry = weld_polygon_meshes(meshes, 0.25 * tau_);
      shape.colour = colour;
      shape.source_type = "Plane";
      shape.source_entity = std::to_string(meshes.size()) + " planar faces";
      shapes.push_back(std::move(shape));
      ++report_.polygon_meshes;
    }
    for (auto& shape : kept) shapes.push_back(std::move(shape));
    node.shapes = std::move(shapes);
    for (auto& child : node.children) this->node(child);
  }

 private:
  void compact_face(TrimmedSurface& face) {
    const double uv_tolerance = trim_parameter_tolerance(face.surface, tau_);
    // Knot removal may move a trim by τ/4 in 3D (2.5 x the trimming precision of τ/10), the written
    // digits by τ/20 more.
    for (auto& loop : face.loops)
      for (auto& segment : loop.segments)
        if (auto* curve = std::get_if<NurbsCurve>(&segment)) {
          int removed = 0;
          *curve = remove_knots(*curve, 2.5 * uv_tolerance, &removed);
          report_.knots_removed += removed;
        }
    for (auto& loop : face.loops) loop = join_straight_trim_runs(loop, uv_tolerance, &report_.straight_runs);
    if (face.loops.size() == 1 && is_domain_boundary(face.loops[0], face.surface, uv_tolerance)) {
      face.loops.clear();
      ++report_.untrimmed;
    }
    report_.reparametrised += use_whole_number_knots(face, tau_);
  }

  double tau_;
  CompactReport& report_;
};

}  // namespace

int instance_repeats(SceneNode& node, double tolerance) {
  const int parts = instance_repeated_parts(node, 0.25 * tolerance);
  // Faces that become polygons are merged into face sets instead.
  return parts + instance_repeated_faces(node, 0.25 * tolerance, [&](const Shape& shape) {
           return !planar_face_polygons(std::get<TrimmedSurface>(shape.geometry), tolerance);
         });
}

Scene compact_scene(const Scene& scene, double tolerance, CompactReport* report) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("compact_scene: the tolerance must be a positive number");
  CompactReport local;
  CompactReport& r = report ? *report : local;
  Scene out = scene;
  r.instanced += instance_repeats(out.root, tolerance);
  Compactor(tolerance, r).node(out.root);
  return out;
}

}  // namespace cadnurbs
