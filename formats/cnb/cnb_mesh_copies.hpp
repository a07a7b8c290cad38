#pragma once
// Copies in a mesh group (docs/cnb.md, "Mesh group", format version 5 on): a piece of one of the group's
// meshes (its triangles joined through shared vertices) that is another piece of the same mesh turned by
// one of the 48 signed permutations of the axes and moved by whole grid steps is coded as a record (the
// source piece, the turn, the move) instead of in the group's traversal. The pins, pads and leads of a
// part are such pieces: a QFN-40's pads are 40 pieces of 16 triangles, and 39 of them are copies.
//
// Pieces are named by their place among the mesh's pieces left in the traversal, ordered by their grid
// points (each piece's points sorted, the lists compared lexicographically), which writer and reader both
// compute from the geometry alone: the traversal's order of triangles does not enter. The writer keeps
// no copy in a mesh where two such pieces have the same points.
//
// In: meshes and their vertices on the grid q. Out: the meshes without their copies and the records; the
// reader appends each copy's vertices and triangles to its mesh. A turn with determinant -1 (a mirror)
// maps a triangle (a, b, c) to (a', c', b'), so the copy faces outwards as its source does. A copy's
// vertices are the grid points of the piece it stands for and its triangles cover the same surface, so
// the decoded mesh keeps the bound of the mesh written.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/triangle_mesh.hpp"
#include "formats/cnb/cnb_stream.hpp"
#include "formats/cnb/cnb_vertex_values.hpp"

namespace cadnurbs::cnb {

constexpr int turn_count = 48;  // signed permutations: 6 orders of the axes times 8 sign choices

// Turn r (0 <= r < 48; 0 is the identity) of p: component k is +-p[order[k]], order r / 8, signs r % 8.
GridPoint turned(int turn, const GridPoint& p);
// Whether turn r is a mirror (determinant -1).
bool turn_mirrors(int turn);

// One copy: piece `source` of mesh `member` (its place among that mesh's pieces left in the traversal),
// turned by `turn`, then moved by `move` grid steps.
struct PieceCopy {
  int member = 0;
  int source = 0;
  int turn = 0;
  GridPoint move{0, 0, 0};
};

struct GroupCopies {
  std::vector<TriangleMesh> kept;  // each mesh without the pieces that are copies (same vertices)
  std::vector<PieceCopy> copies;   // in the order the writer found them
};

// The copies among the pieces of each mesh (vertices rounded to the grid q): a piece is a copy when an
// earlier piece of its mesh that is not a copy maps onto it by a turn and a move, vertex by vertex (each
// onto a distinct vertex), and its triangles cover the same surface: they land on the piece's triangles
// as oriented cycles (preferred), or on the same planar regions (a flat face cut along another diagonal;
// the copy then decodes with its source's triangles). The lowest such turn is taken. Only the first 16
// earlier pieces with the same counts and box sides are tried. Pieces of fewer than `smallest_piece`
// triangles are never copies.
GroupCopies find_group_copies(const std::vector<const TriangleMesh*>& meshes, double q, size_t smallest_piece = 2);

// Records: runs of copies of one source by one turn (a varuint count of runs; per run its member, source,
// turn and copies, then each copy's move as the difference from a prediction by the moves before it in
// the run, the moves in lexicographic order).
void write_piece_copies(ByteWriter& out, const std::vector<PieceCopy>& copies);
// Reads the records and appends each copy to its mesh (the group's meshes as the union decoded them,
// vertices on the grid q). Refuses (PayloadError, at the offending field) more copies than bytes left, a
// mesh outside the group, a source beyond the mesh's pieces, a turn above 47, a coordinate beyond 2^52
// steps, and copies adding more than `number_room` numbers (3 per vertex and per triangle).
void read_piece_copies(ByteReader& in, std::vector<TriangleMesh>& meshes, double q, size_t number_room);

}  // namespace cadnurbs::cnb
