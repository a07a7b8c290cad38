#pragma once
// Steps 4 to 6 of sew_faces (see its header): which boundary pieces of a group are one model edge
// (internal to analysis/sewing/).
//
// In: the group's pieces, cut (step 3) and with their end vertices (step 2), and the faces. Out: classes
// of pieces that are one edge, as a union-find over piece indices (steps 4 and 5), then one edge per piece
// with classes of more than two pieces split by solid (step 6).
//  4. match_pieces: pieces between the same two vertices are one edge when every interior sample of each
//     lies within the tolerance of the other's 3D image (project_to_piece). Both ways, since one piece
//     lying along the other does not keep the other from running off elsewhere between the same vertices.
//     Pieces whose image is a point (poles) match nothing.
//  5. match_open_pieces: the pieces still open repeat steps 2 and 4 among themselves at 10, 100, ... times
//     the first tolerance, up to the largest (no cuts). A piece that lies within such a width of its
//     start is a point at that width and takes no part. The largest bounds how far apart sewn pieces can
//     be (sewing_tolerance makes it D/4, so a sewn edge lies within D of both its faces).
//  6. split_by_solid: a class of more than two pieces is split by solid, a solid being the faces joined by
//     the classes of exactly two pieces; pieces the split leaves alone are paired one way with the other.
#include <vector>

#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/sewing/boundary_pieces.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/sewing/sewing_faces.hpp"
#include "core/union_find.hpp"

namespace cadnurbs::sewing {

// Whether b runs against a (both from one vertex to another, coinciding). For a closed piece (one vertex
// at both ends), from where b comes nearest to a's samples at a third and two thirds of the way.
bool runs_against(const Piece& a, const Piece& b, const SurfaceEvaluator& b_surface);

// Step 4: pieces between the same two vertices whose images coincide, as classes of a union-find.
UnionFind match_pieces(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces, double tolerance);

// Step 5: unites in `edges` the open pieces (each a class of its own) that match among themselves at a
// wider tolerance. Records the widest tolerance that matched in SewingReport::widest_gap.
void match_open_pieces(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces,
                       const SewingTolerance& tolerance, UnionFind& edges, SewingReport& report);

// Step 6: the edge of each piece (an index < pieces.size()). A class of more than two coinciding pieces is
// split by solid, a solid being the faces joined by the classes of exactly two pieces: two solids that touch
// along an edge (coincident faces of parts in an assembly) keep an edge each instead of one non-manifold one.
std::vector<int> split_by_solid(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces, UnionFind& edges);

}  // namespace cadnurbs::sewing
