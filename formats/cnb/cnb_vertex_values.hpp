#pragma once
// The coordinates of a traversal-coded mesh's vertices (docs/cnb.md, "Traversal-coded triangle mesh"),
// on the grid q, coded against a prediction. Each axis keeps the sorted values met so far; a coordinate
// equal to one of them is coded by its rank counted from where the prediction falls among them,
// otherwise by its difference from the prediction. CAD parts repeat few values per axis (the 539
// vertices of a DIP-10 tessellated within 0.005 mm take 71, 54 and 20), and the true value's rank lies
// near the prediction's, so a repeated value costs a few bits where a difference costs ten or more.
// Writer and reader update the tables in the same order; a table stops growing at value_table_limit
// values (so that a mesh of a million distinct values does not cost quadratic time).
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

class VertexValues {
 public:
  // `by_axis` (format version 4 on): each axis's first byte of a rank or difference in its own context.
  void write(ByteWriter& out, const GridPoint& p, const GridPoint& predicted, bool by_axis);
  // About how many bits write would spend on p: a listed value by its rank's distance from the
  // prediction's, another by its difference (a varsint's growth, not the entropy coder's models).
  double estimated_bits(const GridPoint& p, const GridPoint& predicted) const;
  // Refuses (PayloadError) a rank outside the table and a coordinate beyond 2^52 steps.
  GridPoint read(ByteReader& in, const GridPoint& predicted, bool by_axis);

 private:
  // Adds `value` to the axis's table at `place` (where lower_bound puts it) unless it is listed there.
  void remember(int axis, int64_t value, int64_t place);
  std::array<std::vector<int64_t>, 3> sorted_;
};

}  // namespace cadnurbs::cnb
