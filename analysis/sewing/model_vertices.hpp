#pragma once
// Step 2 of sew_faces (see its header): the model vertices of a group, as classes of piece ends
// (internal to analysis/sewing/).
//
// In: sampled pieces (boundary_pieces) and a tolerance. Out: every piece's Piece::start and Piece::end, and
// one position per vertex: the first end of its class in the order piece 0's start, piece 0's end, piece
// 1's start, ... Vertex ids are 0, 1, ... in that order of first appearance.
// Piece ends closer than the tolerance are one vertex, transitively: a chain of ends each within the
// tolerance of the next is one vertex however long it is. No close pair is missed: the ends are hashed
// into cells of the tolerance's size (PointHashGrid), whose search covers every point within one cell.
#include <Eigen/Core>
#include <vector>

#include "analysis/sewing/boundary_pieces.hpp"

namespace cadnurbs::sewing {

// Gives every piece its end vertices; returns one position per vertex.
std::vector<Eigen::Vector3d> find_model_vertices(std::vector<Piece>& pieces, double tolerance);

}  // namespace cadnurbs::sewing
