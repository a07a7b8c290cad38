// The driver of sew_faces: the scene prepared, then the faces of each group through the steps of the
// header, each in its own file under analysis/sewing/.
#include "analysis/sewing/sew_faces.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "analysis/sewing/boundary_pieces.hpp"
#include "analysis/sewing/model_vertices.hpp"
#include "analysis/sewing/piece_matching.hpp"
#include "analysis/sewing/sewing_faces.hpp"
#include "core/flatten_transforms.hpp"
#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

using sewing::Piece;
using sewing::SewFace;

// Steps 1-6 on the faces `members` (one group); their loops are rebuilt from the pieces.
void sew_group(std::vector<SewFace>& faces, const std::vector<int>& members, const SewingTolerance& tolerance,
               SewingReport& report) {
  std::vector<Piece> pieces = sewing::cut_into_pieces(faces, members);
  for (auto& p : pieces) sewing::sample_piece(p, *faces[p.face].surface, tolerance.first);
  const std::vector<Eigen::Vector3d> vertices = sewing::find_model_vertices(pieces, tolerance.first);
  pieces = sewing::cut_at_vertices(pieces, faces, vertices, tolerance.first, report);

  UnionFind edges = sewing::match_pieces(pieces, faces, tolerance.first);
  sewing::match_open_pieces(pieces, faces, tolerance, edges, report);

  const std::vector<int> edge_of = sewing::split_by_solid(pieces, faces, edges);
  std::vector<int> uses(pieces.size(), 0), first_use(pieces.size(), -1), edge_id(pieces.size(), -1);
  for (size_t i = 0; i < pieces.size(); ++i)
    if (uses[edge_of[i]]++ == 0) first_use[edge_of[i]] = static_cast<int>(i);
  for (size_t i = 0; i < pieces.size(); ++i) {
    Piece& p = pieces[i];
    const int e = edge_of[i];
    if (p.is_point) {
      ++report.point_pieces;
    } else if (uses[e] < 2) {
      ++report.open_pieces;
      for (size_t k = 1; k < p.points.size(); ++k) report.open_length += (p.points[k] - p.points[k - 1]).norm();
    } else {
      if (edge_id[e] < 0) edge_id[e] = static_cast<int>(report.shared_edges++);
      const int first = first_use[e];
      p.edge = {edge_id[e],
                first != static_cast<int>(i) && sewing::runs_against(pieces[first], p, *faces[p.face].surface)};
      ++report.sewn_pieces;
    }
  }
  report.pieces += static_cast<long>(pieces.size());

  // The loops again, from their pieces (in loop order: pieces were made and cut in order).
  for (const int f : members)
    for (auto& loop : faces[f].trimmed->loops) loop = {};
  for (auto& p : pieces) {
    TrimLoop& loop = faces[p.face].trimmed->loops[p.loop];
    loop.segments.push_back(std::move(p.segment));
    loop.edges.push_back(p.edge);
  }
}

}  // namespace

SewingTolerance sewing_tolerance(double bounding_box_diagonal, double max_deviation) {
  const double largest = 0.25 * max_deviation;
  return {std::min(1e-5 * bounding_box_diagonal, largest), largest};
}

Scene sew_faces(const Scene& scene, const SewingTolerance& tolerance, SewingReport* report_out) {
  if (!(tolerance.first > 0) || !std::isfinite(tolerance.first) || !(tolerance.largest >= tolerance.first) ||
      !std::isfinite(tolerance.largest))
    throw std::invalid_argument(
        "sew_faces: the tolerances must be positive numbers, the largest at least the first, not " +
        std::to_string(tolerance.first) + " and " + std::to_string(tolerance.largest));
  SewingReport report;
  Scene out = flatten_transforms(scene);
  sewing::polygons_as_faces(out.root, tolerance.first, report);
  std::vector<SewFace> faces;
  int groups = 1;  // group 0: faces under no named node
  sewing::collect_faces(out.root, 0, groups, faces);
  report.faces = static_cast<int>(faces.size());
  std::vector<std::vector<int>> members(groups);
  for (size_t f = 0; f < faces.size(); ++f) members[faces[f].group].push_back(static_cast<int>(f));
  for (const auto& group : members)
    if (!group.empty()) sew_group(faces, group, tolerance, report);
  if (report_out) *report_out = report;
  return out;
}

}  // namespace cadnurbs
