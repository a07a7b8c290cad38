#pragma once
// The geometry records of a .cnb payload (docs/cnb.md, "Geometry"): each writer quantises and predicts,
// each reader refuses (PayloadError) what cannot be right and allocates only what the bytes left can hold.
#include <unordered_set>

#include "core/nurbs_curve.hpp"
#include "core/polygon_mesh.hpp"
#include "core/triangle_mesh.hpp"
#include "core/trimmed_surface.hpp"
#include "formats/cnb/cnb_mesh_copies.hpp"
#include "formats/cnb/cnb_mesh_period.hpp"
#include "formats/cnb/cnb_numbers.hpp"
#include "formats/cnb/cnb_quantisation.hpp"
#include "formats/cnb/cnb_stream.hpp"
#include "formats/cnb/cnb_vertex_values.hpp"

namespace cadnurbs::cnb {

// What coding a record depends on besides the record: the previous segment's edge number (scene-wide)
// and the raw knot vectors met so far. Writer and reader keep one each, updated in the same order.
struct CodingState {
  int previous_edge = -1;
  KnotCache knots;
  WeightCache weights;
  // Traversal-coded meshes: the values each axis has met, and the last new vertex (which predicts the
  // corners of a mesh's starting triangles), over all the meshes so far: parts of one part repeat them.
  VertexValues mesh_values;
  GridPoint last_mesh_vertex{0, 0, 0};
  bool trim_extrapolation = true;  // writer only: whether faces may take the extrapolating trim predictor
  bool piece_copies = true;        // writer only: whether mesh groups may code pieces as copies
  bool mesh_periods = true;        // writer only: whether traversal-coded meshes may take a period
  bool mesh_predictors = true;     // writer only: whether traversal-coded meshes name a predictor per vertex
  bool trim_knot_removal = true;   // writer only: whether trimming curves may lose their spare knots
  PeriodCache* periods = nullptr;  // writer only: periods found by earlier codings of the same meshes
  int periodic_meshes = 0;         // writer only: the traversal-coded meshes written with a period
  // Writer only: a traversal-coded mesh's new vertex may take, instead of its nearest grid point, any
  // within this many steps of it (the points' bound over the step) that codes cheaper against its
  // prediction; 0: the nearest. Never a vertex whose nearest grid point is in `locked_points` (points two
  // of the scene's points round to: shared, they must decode alike), nor one of a group with copies.
  double free_radius = 0;
  const std::unordered_set<GridPoint, GridPointHash>* locked_points = nullptr;
  long vertices_off_nearest = 0;  // writer only: new vertices written at another grid point than their nearest
  int traversal_meshes = 0;       // writer only: traversal-coded meshes written (a group's union counts once)
  // The format version being read or written: from 4 on, mesh symbols and vertex coordinates take the
  // contexts by previous symbol and by axis (cnb_stream.hpp).
  uint8_t version = format_version;
};

// A surface's net on the grid of step q, predicted along rows (each point from the one before it, u
// fastest) or across the net (parallelogram: P[i-1,j] + P[i,j-1] - P[i-1,j-1]), whichever leaves the
// smaller residuals. Returns true when the parallelogram was taken.
// Weights as `weights` says (cnb_quantisation.hpp: exact, rounded or factored).
bool write_surface(ByteWriter& out, const NurbsSurface& surface, double q, CodingState& state,
                   const WeightCoding& weights = {});
NurbsSurface read_surface(ByteReader& in, double q, CodingState& state);

// Trimming loops on the grid 2^exponent in (u,v), predicted from the previous point along the loop (or,
// within a segment, by extrapolating the two previous points, where the face's residuals get smaller and
// state.trim_extrapolation allows it); a segment's first point snapped onto the previous segment's last where they were within half a step
// (so closed loops stay closed). Edge numbers as differences from the previous segment's, scene-wide.
void write_trim_loops(ByteWriter& out, const std::vector<TrimLoop>& loops, int exponent, CodingState& state);
std::vector<TrimLoop> read_trim_loops(ByteReader& in, int exponent, CodingState& state);

// A 3D curve: order, knots, weights and points predicted from the previous point on the grid q.
void write_curve(ByteWriter& out, const NurbsCurve& curve, double q, CodingState& state);
NurbsCurve read_curve(ByteReader& in, double q, CodingState& state);

// Meshes: vertices predicted from the previous vertex on the grid q; indices as differences from the
// previous index; normals (triangle meshes) to 1/32767 per component.
void write_triangle_mesh(ByteWriter& out, const TriangleMesh& mesh, double q);
TriangleMesh read_triangle_mesh(ByteReader& in, double q);
// A triangle mesh without corner normals and without triangles that repeat a vertex, coded by a traversal
// (cnb_traversal_mesh_coding.cpp): decoded with the same triangles (same orientation) and vertices on the
// grid q, in the order the traversal meets them; vertices no triangle uses are not kept.
// With `members` (one per triangle, in [0, member_count)): the mesh is a group's union and each triangle's
// member is coded after it; the reader then fills `members` in decoded order.
bool traversal_codable(const TriangleMesh& mesh);
void write_traversal_mesh(ByteWriter& out, const TriangleMesh& mesh, double q, CodingState& state,
                          const std::vector<int>* members = nullptr);
TriangleMesh read_traversal_mesh(ByteReader& in, double q, CodingState& state, int member_count = 0,
                                 std::vector<int>* members = nullptr);
// Several traversal-codable meshes of one node coded as one (cnb_mesh_group_coding.cpp): their vertices
// on one grid point joined across meshes (never within one), so that meshes meeting along an edge (the
// colours of one body) share its vertices and are traversed together, and each triangle's mesh coded
// beside it. Decoded as the same meshes, each as read_traversal_mesh would decode it alone: the same
// triangles, vertices on the grid q in the order the group's traversal meets them. 2..max_group_meshes
// meshes; the reader refuses a mesh left without a triangle. From format version 5, pieces of a mesh that
// are copies of another of its pieces (find_group_copies) are left out of the traversal and follow it as
// records (shape kind 7); they decode after the mesh's other triangles. The reader refuses copies adding
// more than `number_room` numbers.
constexpr int max_group_meshes = 255;
void write_mesh_group(ByteWriter& out, const GroupCopies& group, double q, CodingState& state);
std::vector<TriangleMesh> read_mesh_group(ByteReader& in, int mesh_count, double q, CodingState& state,
                                          bool with_copies, size_t number_room);
void write_polygon_mesh(ByteWriter& out, const PolygonMesh& mesh, double q);
PolygonMesh read_polygon_mesh(ByteReader& in, double q);

}  // namespace cadnurbs::cnb
