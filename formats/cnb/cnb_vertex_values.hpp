#pragma once
// The coordinates of a traversal-coded mesh's vertices (docs/cnb.md, "Traversal-coded triangle mesh"),
// on the grid q, coded against a prediction. Each axis keeps the sorted values met so far; a coordinate
// equal to one of them is coded by its rank counted from where the prediction falls among them,
// otherwise by its difference from the prediction. CAD parts repeat few values per axis (the 539
// vertices of a DIP-10 tessellated within 0.005 mm take 71, 54 and 20), and the true value's rank lies
// near the prediction's, so a repeated value costs a few bits where a difference costs ten or more.
// Writer and reader update the tables in the same order; a table stops growing at value_table_limit
// values (so that a mesh of a million distinct values does not cost quadratic time).
//
// From format version 9 a listed value's rank is counted from the listed value nearest the prediction
// (the one below where it is strictly nearer than the one above, or where none is above), and the first
// byte of a rank or difference, and the axes byte, take contexts by whether the prediction is itself a
// listed value: where it is, the coordinate is mostly that value; where not, mostly a neighbour. Measured
// on the 226 DFN/QFN KiCad parts at 0.01 mm as version 9 first coded them (payloads 120,359 bytes, ideal
// code lengths of the same symbols): ranks in contexts by a listed prediction 117,794, counted from the
// nearest 117,188; the axes byte by whether all three predictions are listed -257 more (one context per
// pattern of the three: +481); differences by a listed prediction -164.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/triangle_mesh.hpp"
#include "formats/cnb/cnb_stream.hpp"

namespace cadnurbs::cnb {

using GridPoint = std::array<int64_t, 3>;

// Each vertex of `mesh` rounded to the grid q (on_grid per coordinate).
std::vector<GridPoint> grid_points(const TriangleMesh& mesh, double q);

constexpr size_t value_table_limit = 4096;

// How coordinates are coded, by format version: up to 3 each axis's first byte in its field's first context;
// 4 to 8 each axis in its own; from 9 also by whether the prediction is listed, ranks from the nearest.
enum class ValueCoding : uint8_t { shared_contexts, by_axis, by_listed_prediction };
ValueCoding value_coding(uint8_t version);

class VertexValues {
 public:
  void write(ByteWriter& out, const GridPoint& p, const GridPoint& predicted, ValueCoding coding);
  // About how many bits write would spend on p: a listed value by its rank's distance from the
  // prediction's, another by its difference (a varsint's growth, not the entropy coder's models).
  double estimated_bits(const GridPoint& p, const GridPoint& predicted, ValueCoding coding) const;
  // Refuses (PayloadError) a rank outside the table and a coordinate beyond 2^52 steps.
  GridPoint read(ByteReader& in, const GridPoint& predicted, ValueCoding coding);

 private:
  // Where ranks on `axis` are counted from for a prediction `predicted`, and whether it is listed.
  int64_t reference_place(int axis, int64_t predicted, ValueCoding coding, bool& listed) const;
  // The same on every axis, and whether all three predictions are listed.
  struct References {
    GridPoint place;
    std::array<bool, 3> listed;
    bool all_listed;
  };
  References references(const GridPoint& predicted, ValueCoding coding) const;
  // Adds `value` to the axis's table at `place` (where lower_bound puts it) unless it is listed there.
  void remember(int axis, int64_t value, int64_t place);
  std::array<std::vector<int64_t>, 3> sorted_;
};

}  // namespace cadnurbs::cnb
