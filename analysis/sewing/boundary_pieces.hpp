#pragma once
// Steps 1 and 3 of sew_faces (see its header): the boundary pieces of a group's faces with their sampled
// 3D images, and their cuts at the model vertices of other faces (internal to analysis/sewing/).
//
// In: the faces of one group, prepared (sewing_faces: every face has loops). Out, step 1 (cut_into_pieces,
// then sample_piece on each): one Piece per NURBS trimming curve and per side of a polyline (zero-length
// sides dropped), in loop order, each with its 3D image sampled. Out, step 3 (cut_at_vertices): the same
// pieces, each cut where a model vertex (step 2) lies within the tolerance of its interior, in loop order.
// The cuts are exact (split_curve, or a polyline side split at the cut's point): every loop keeps its
// shape. Refuses to cut a piece whose image is a point (a pole), and skips a cut at a piece's own end
// vertices, at one of its (u,v) ends, or at a parameter already cut.
//
// Why no vertex near a piece is missed: the vertices considered lie in the box of the piece's samples
// widened by the tolerance plus half the longest sample spacing, since the curve may bulge past its
// samples; each is then projected on the curve itself (project_to_piece), not on its samples.
#include <Eigen/Core>
#include <compare>
#include <vector>

#include "analysis/eval/point_inversion.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/sewing/sewing_faces.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs::sewing {

// A model vertex of a group (model_vertices): an index into the vertex positions; -1 for none yet.
struct VertexId {
  int value = -1;
  bool operator==(const VertexId&) const = default;
  auto operator<=>(const VertexId&) const = default;
};

// One piece of a face's loop and its sampled 3D image.
struct Piece {
  int face = 0, loop = 0;
  TrimSegment segment;
  std::vector<double> ts;               // sample parameters on `segment`, ascending, its ends included
  std::vector<Eigen::Vector3d> points;  // the surface at segment_uv(ts[k])
  VertexId start, end;
  bool is_point = false;  // the whole image lies within the tolerance of its start
  TrimEdgeRef edge;
};

// Step 1: the loops of faces `members` cut into pieces, not yet sampled. NURBS trimming curves are pieces
// as they are; polylines are cut at every point, since the compact writer joins runs of straight edges
// into one polyline.
std::vector<Piece> cut_into_pieces(const std::vector<SewFace>& faces, const std::vector<int>& members);

// Samples the piece's 3D image on `surface` (its face's): 8 samples per knot span of the piece, and as many
// again per knot line of the surface that a sample interval crosses (a straight (u,v) side across a
// many-patch surface is one span long). Sets Piece::ts, Piece::points and Piece::is_point.
void sample_piece(Piece& piece, const SurfaceEvaluator& surface, double tolerance);

// Nearest point of the piece's 3D image to p, by Newton from the nearest point of its sample polygon
// (not the nearest sample: beside the shared start of a closed piece that may lie at the wrong end).
CurveProjection project_to_piece(const Piece& piece, const SurfaceEvaluator& surface, const Eigen::Vector3d& p);

// Step 3: the pieces again, every piece cut at the vertices (positions by VertexId) that lie within
// `tolerance` of its interior; the new pieces end at those vertices and are sampled again. Counts the
// cuts in SewingReport::cuts.
std::vector<Piece> cut_at_vertices(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces,
                                   const std::vector<Eigen::Vector3d>& vertices, double tolerance,
                                   SewingReport& report);

}  // namespace cadnurbs::sewing
