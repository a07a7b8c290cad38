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

ValueCoding value_coding(uint8_t version) {
  return version >= 9 ? ValueCoding::by_listed_prediction
         : version >= 4 ? ValueCoding::by_axis
                        : ValueCoding::shared_contexts;
}

int64_t VertexValues::reference_place(int axis, int64_t predicted, ValueCoding coding, bool& listed) const {
  const auto& sorted = sorted_[axis];
  const int64_t place = place_of(sorted, predicted), size = static_cast<int64_t>(sorted.size());
  listed = place < size && sorted[static_cast<size_t>(place)] == predicted;
  if (coding != ValueCoding::by_listed_prediction || listed || place == 0) return place;
  // Unlisted: the nearer neighbour, the one above at equal distance.
  if (place == size) return place - 1;
  const int64_t below = predicted - sorted[static_cast<size_t>(place - 1)];
  const int64_t above = sorted[static_cast<size_t>(place)] - predicted;
  return below < above ? place - 1 : place;
}

void VertexValues::remember(int axis, int64_t value, int64_t place) {
  auto& sorted = sorted_[axis];
  const bool listed = place < static_cast<int64_t>(sorted.size()) && sorted[static_cast<size_t>(place)] == value;
  if (!listed && sorted.size() < value_table_limit) sorted.insert(sorted.begin() + place, value);
}

double VertexValues::estimated_bits(const GridPoint& p, const GridPoint& predicted, ValueCoding coding) const {
  double bits = 0;
  for (int k = 0; k < 3; ++k) {
    const int64_t place = place_of(sorted_[k], p[k]);
    const bool listed =
        place < static_cast<int64_t>(sorted_[k].size()) && sorted_[k][static_cast<size_t>(place)] == p[k];
    bool prediction_listed = false;
    const double off = listed ? static_cast<double>(std::abs(place - reference_place(k, predicted[k], coding, prediction_listed)))
                              : static_cast<double>(std::abs(p[k] - predicted[k]));
    bits += (listed ? 1.0 : 3.0) + 2.0 * std::log2(1.0 + off);
  }
  return bits;
}

namespace {
// The context of the axes byte, given whether all three predictions are listed.
int axes_byte_context(bool all_listed, ValueCoding coding) {
  return axes_context(all_listed || coding != ValueCoding::by_listed_prediction);
}

// The context of the first byte of a value on `axis` (a rank or a difference, as `field`).
int first_value_context(Field field, int axis, bool prediction_listed, ValueCoding coding) {
  switch (coding) {
    case ValueCoding::shared_contexts: return axis_context(field, 0);
    case ValueCoding::by_axis: return axis_context(field, axis);
    case ValueCoding::by_listed_prediction: break;
  }
  return value_context(field, axis, prediction_listed);
}
}  // namespace

VertexValues::References VertexValues::references(const GridPoint& predicted, ValueCoding coding) const {
  References r;
  for (int k = 0; k < 3; ++k) r.place[k] = reference_place(k, predicted[k], coding, r.listed[k]);
  r.all_listed = r.listed[0] && r.listed[1] && r.listed[2];
  return r;
}

void VertexValues::write(ByteWriter& out, const GridPoint& p, const GridPoint& predicted, ValueCoding coding) {
  const References reference = references(predicted, coding);
  GridPoint place;
  uint8_t known = 0;
  for (int k = 0; k < 3; ++k) {
    place[k] = place_of(sorted_[k], p[k]);
    if (place[k] < static_cast<int64_t>(sorted_[k].size()) && sorted_[k][static_cast<size_t>(place[k])] == p[k])
      known |= static_cast<uint8_t>(1 << k);
  }
  out.byte_in(known, axes_byte_context(reference.all_listed, coding));
  for (int k = 0; k < 3; ++k) {
    const Field field = known & (1 << k) ? Field::mesh_rank : Field::mesh_point;
    const int64_t value = known & (1 << k) ? place[k] - reference.place[k] : p[k] - predicted[k];
    out.varsint_in(value, field, first_value_context(field, k, reference.listed[k], coding));
    remember(k, p[k], place[k]);
  }
}

GridPoint VertexValues::read(ByteReader& in, const GridPoint& predicted, ValueCoding coding) {
  const size_t known_at = in.offset();
  const References reference = references(predicted, coding);
  const uint8_t known = in.byte_in(axes_byte_context(reference.all_listed, coding));
  if (known > 7) in.fail("vertex axis flags " + std::to_string(known) + " above 7", known_at);
  GridPoint p;
  for (int k = 0; k < 3; ++k) {
    const size_t at = in.offset();
    if (known & (1 << k)) {
      const int64_t rank =
          reference.place[k] + in.varsint_in(Field::mesh_rank, first_value_context(Field::mesh_rank, k, reference.listed[k], coding));
      if (rank < 0 || rank >= static_cast<int64_t>(sorted_[k].size()))
        in.fail("vertex value rank " + std::to_string(rank) + " outside the " + std::to_string(sorted_[k].size()) +
                    " values met",
                at);
      p[k] = sorted_[k][static_cast<size_t>(rank)];
      remember(k, p[k], rank);
    } else {
      p[k] = predicted[k] + in.varsint_in(Field::mesh_point, first_value_context(Field::mesh_point, k, reference.listed[k], coding));
      if (std::abs(static_cast<double>(p[k])) > 0x1p52) in.fail("vertex coordinate outside the grid's range", at);
      remember(k, p[k], place_of(sorted_[k], p[k]));
    }
  }
  return p;
}

}  // namespace cadnurbs::cnb
