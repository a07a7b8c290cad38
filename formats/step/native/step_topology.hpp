#pragma once
// STEP's B-rep topology (ISO 10303-42: faces, bounds, loops, oriented edges, edges, vertices) read into
// plain structures: each EDGE_CURVE once, numbered, with its trimmed 3D curve; each face with its surface
// and its bounds as chains of edge uses.
// The vertices trim their edge's curve, so they must lie on it: the curve is cut at the points nearest
// them and its ends moved onto them. Files keep vertices within their edges' tolerance, not on the curve:
// up to 1e-3 of the curve's size plus 1e-3 mm is taken as that tolerance; a vertex farther off, up to 1e-3
// of the file's size (cartesian_points_size, the default deviation's share), is moved onto too and
// said (StepEdge::vertex_moved).
// Refuses (OutsideNativeSubset naming the entity): a vertex farther from its edge's curve than both; an
// edge whose vertices run against its curve's sense; topology types outside the subset.
#include <Eigen/Core>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/nurbs_curve.hpp"
#include "formats/step/native/step_geometry.hpp"

namespace cadnurbs::step {

struct StepEdge {
  EntityId entity = part21::none;
  StepCurve curve;
  Eigen::Vector3d start, end;  // the vertices' points
  NurbsCurve path;             // the edge's 3D curve from start to end (clamped; exactly through both)
  double vertex_moved = 0;     // > 0: how far (mm) an end was moved onto its vertex, beyond the edge's tolerance
};

struct EdgeUse {
  int edge = 0;         // index into the reader's edges (the scene-wide edge number)
  bool forward = true;  // runs from the edge's start to its end
};

struct StepBound {
  std::vector<EdgeUse> uses;  // in loop order, the bound's orientation applied
  bool outer = false;         // FACE_OUTER_BOUND
  EntityId entity = part21::none;
};

struct StepFace {
  EntityId entity = part21::none;
  EntityId surface_entity = part21::none;
  StepSurface surface;
  bool same_sense = true;  // false: the face's normal is against the surface's
  std::vector<StepBound> bounds;  // VERTEX_LOOPs (a point) left out
};

class TopologyReader {
 public:
  explicit TopologyReader(const StepContext& context) : context_(context) {}

  StepFace face(EntityId advanced_face);
  // The faces of a CLOSED_SHELL, OPEN_SHELL or ORIENTED_CLOSED_SHELL, in the shell's order.
  std::vector<EntityId> shell_faces(EntityId shell) const;

  const std::vector<StepEdge>& edges() const { return edges_; }

 private:
  int edge(EntityId edge_curve);

  const StepContext& context_;
  std::vector<StepEdge> edges_;
  std::unordered_map<EntityId, int> edge_index_;
  std::optional<double> points_size_;  // cartesian_points_size, once a vertex needs it
};

}  // namespace cadnurbs::step
