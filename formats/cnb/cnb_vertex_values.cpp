#include "formats/cnb/cnb_vertex_values.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "formats/cnb/cnb_numbers.hpp"

namespace cadnurbs::cnb {

namespace {
// Where `value` falls in the sorted table: the place of the first value not below it.
int64_t place_of(const std::vector<int64_t>& sorted, int64_t value) {
  return std::lower_bound(sorted.begin(), sorted.end(), value) - sorted.begin();
}
}  // namespace

std::vector<GridPoint> grid_points(const TriangleMesh& mesh, double q) {
  std::vector<GridPoint> grid;
  grid.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) grid.push_back({on_grid(p.x(), q), on_grid(p.y(), q), on_grid(p.z(), q)});
  return grid;
}

void VertexValues::remember(int axis, int64_t value, int64_t place) {
  auto& sorted = sorted_[axis];
  const bool listed = place < static_cast<int64_t>(sorted.size()) && sorted[static_cast<size_t>(place)] == value;
  if (!listed && sorted.size() < value_table_limit) sorted.insert(sorted.begin() + place, value);
}

double VertexValues::estimated_bits(const GridPoint& p, const GridPoint& predicted) const {
  double bits = 0;
  for (int k = 0; k < 3; ++k) {
    const int64_t place = place_of(sorted_[k], p[k]);
    const bool listed =
        place < static_cast<int64_t>(sorted_[k].size()) && sorted_[k][static_cast<size_t>(place)] == p[k];
    const double off = listed ? static_cast<double>(std::abs(place - place_of(sorted_[k], predicted[k])))
                              : static_cast<double>(std::abs(p[k] - predicted[k]));
    bits += (listed ? 1.0 : 3.0) + 2.0 * std::log2(1.0 + off);
  }
  return bits;
}

void VertexValues::write(ByteWriter& out, const GridPoint& p, const GridPoint& predicted, bool by_axis) {
  GridPoint place;
  uint8_t known = 0;
  for (int k = 0; k < 3; ++k) {
    place[k] = place_of(sorted_[k], p[k]);
    if (place[k] < static_cast<int64_t>(sorted_[k].size()) && sorted_[k][static_cast<size_t>(place[k])] == p[k])
      known |= static_cast<uint8_t>(1 << k);
  }
  out.byte(known, Field::mesh_axes);
  for (int k = 0; k < 3; ++k) {
    const Field field = known & (1 << k) ? Field::mesh_rank : Field::mesh_point;
    const int64_t value = known & (1 << k) ? place[k] - place_of(sorted_[k], predicted[k]) : p[k] - predicted[k];
    out.varsint_in(value, field, axis_context(field, by_axis ? k : 0));
    remember(k, p[k], place[k]);
  }
}

GridPoint VertexValues::read(ByteReader& in, const GridPoint& predicted, bool by_axis) {
  const size_t known_at = in.offset();
  const uint8_t known = in.byte(Field::mesh_axes);
  if (known > 7) in.fail("vertex axis flags " + std::to_string(known) + " above 7", known_at);
  GridPoint p;
  for (int k = 0; k < 3; ++k) {
    const size_t at = in.offset();
    if (known & (1 << k)) {
      const int64_t rank =
          place_of(sorted_[k], predicted[k]) + in.varsint_in(Field::mesh_rank, axis_context(Field::mesh_rank, by_axis ? k : 0));
      if (rank < 0 || rank >= static_cast<int64_t>(sorted_[k].size()))
        in.fail("vertex value rank " + std::to_string(rank) + " outside the " + std::to_string(sorted_[k].size()) +
                    " values met",
                at);
      p[k] = sorted_[k][static_cast<size_t>(rank)];
      remember(k, p[k], rank);
    } else {
      p[k] = predicted[k] + in.varsint_in(Field::mesh_point, axis_context(Field::mesh_point, by_axis ? k : 0));
      if (std::abs(static_cast<double>(p[k])) > 0x1p52) in.fail("vertex coordinate outside the grid's range", at);
      remember(k, p[k], place_of(sorted_[k], p[k]));
    }
  }
  return p;
}

}  // namespace cadnurbs::cnb
