#include "formats/cnb/cnb_vertex_predictors.hpp"

#include <cmath>

namespace cadnurbs::cnb {

namespace {
using Vector = std::array<double, 3>;

Vector difference(const GridPoint& a, const GridPoint& b) {
  return {static_cast<double>(a[0] - b[0]), static_cast<double>(a[1] - b[1]), static_cast<double>(a[2] - b[2])};
}
double dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// base + offset, each coordinate rounded half away from zero.
GridPoint moved(const GridPoint& base, const Vector& offset) {
  return {base[0] + std::llround(offset[0]), base[1] + std::llround(offset[1]), base[2] + std::llround(offset[2])};
}
}  // namespace

GridPoint parallelogram(const GridPoint& from, const GridPoint& to, const GridPoint& apex) {
  return {from[0] + to[0] - apex[0], from[1] + to[1] - apex[1], from[2] + to[2] - apex[2]};
}

GridPoint arc_continuation(const GridPoint& c0, const GridPoint& c1, const GridPoint& c2) {
  const Vector d0 = difference(c0, c1), d1 = difference(c1, c2);
  const double d0_squared = dot(d0, d0), d1_squared = dot(d1, d1);
  if (d0_squared == 0 || d1_squared == 0) return {c0[0] + c0[0] - c1[0], c0[1] + c0[1] - c1[1], c0[2] + c0[2] - c1[2]};
  const double along = 2 * dot(d1, d0), lengths = std::sqrt(d1_squared * d0_squared);
  Vector step;
  for (int k = 0; k < 3; ++k) step[k] = (along * d0[k] - d0_squared * d1[k]) / lengths;
  return moved(c0, step);
}

GridPoint mirrored_apex(const GridPoint& from, const GridPoint& to, const GridPoint& apex) {
  const Vector line = difference(to, from), to_apex = difference(apex, from);
  const double length_squared = dot(line, line);
  if (length_squared == 0) return parallelogram(from, to, apex);
  const double along = 2 * dot(line, to_apex) / length_squared;
  Vector offset;  // from the apex to its mirror image
  for (int k = 0; k < 3; ++k) offset[k] = along * line[k] - 2 * to_apex[k];
  return moved(apex, offset);
}

std::array<GridPoint, vertex_predictor_count> vertex_predictions(const GridPoint& from, const GridPoint& to,
                                                                 const GridPoint& apex,
                                                                 const std::optional<BorderChain>& after_to,
                                                                 const std::optional<BorderChain>& before_from) {
  const GridPoint across = parallelogram(from, to, apex);
  return {across, after_to ? arc_continuation(to, after_to->c1, after_to->c2) : across,
          before_from ? arc_continuation(from, before_from->c1, before_from->c2) : across,
          mirrored_apex(from, to, apex)};
}

}  // namespace cadnurbs::cnb
