// Surfaces and 3D curves: orders, counts, exact knots and weights, then the control points on the grid q
// as residuals of a prediction.
#include <array>
#include <bit>
#include <string>

#include "formats/cnb/cnb_geometry.hpp"
#include "formats/cnb/cnb_numbers.hpp"

namespace cadnurbs::cnb {

namespace {

using Cell = std::array<int64_t, 3>;

enum Predictor : uint8_t { along_rows = 0, parallelogram = 1 };

Cell cell(const Eigen::Vector3d& p, double q) { return {on_grid(p.x(), q), on_grid(p.y(), q), on_grid(p.z(), q)}; }

// The prediction of net point (i, j) from the points before it.
Cell predicted(const std::vector<Cell>& net, int u_count, int i, int j, Predictor predictor) {
  const auto at = [&](int a, int b) -> const Cell& { return net[a + b * u_count]; };
  if (i > 0 && j > 0 && predictor == parallelogram) {
    Cell c;
    for (int k = 0; k < 3; ++k) c[k] = at(i - 1, j)[k] + at(i, j - 1)[k] - at(i - 1, j - 1)[k];
    return c;
  }
  if (i > 0) return at(i - 1, j);
  if (j > 0) return at(0, j - 1);
  return {0, 0, 0};
}

// Bits of the residuals as varint payload, roughly: what the entropy stage has to code.
uint64_t residual_bits(const std::vector<Cell>& net, int u_count, int v_count, Predictor predictor) {
  uint64_t bits = 0;
  for (int j = 0; j < v_count; ++j)
    for (int i = 0; i < u_count; ++i) {
      const Cell p = predicted(net, u_count, i, j, predictor);
      for (int k = 0; k < 3; ++k) bits += std::bit_width(zigzag(net[i + j * u_count][k] - p[k])) + 1;
    }
  return bits;
}

// A count of control points that take at least `bytes_each` bytes.
uint64_t read_point_count(ByteReader& in, size_t bytes_each) {
  const size_t at = in.offset();
  const uint64_t n = in.count(bytes_each);
  if (n < 1) in.fail("no control points", at);
  return n;
}

Eigen::Vector3d point_of(const Cell& c, double q) {
  return {static_cast<double>(c[0]) * q, static_cast<double>(c[1]) * q, static_cast<double>(c[2]) * q};
}

Cell read_residual_added(ByteReader& in, const Cell& prediction) {
  Cell c;
  for (int k = 0; k < 3; ++k) {
    const size_t at = in.offset();
    const int64_t r = in.varsint(Field::point);
    c[k] = prediction[k] + r;
    if (std::abs(static_cast<double>(c[k])) > 0x1p52) in.fail("coordinate outside the grid's range", at);
  }
  return c;
}

}  // namespace

bool write_surface(ByteWriter& out, const NurbsSurface& s, double q, CodingState& state, const WeightCoding& weights) {
  out.varuint(s.u_order, Field::count);
  out.varuint(s.v_order, Field::count);
  out.varuint(s.u_count, Field::count);
  out.varuint(s.v_count, Field::count);
  write_knots(out, s.u_knots, state.knots);
  write_knots(out, s.v_knots, state.knots);
  if (weights.factors)
    write_weight_factors(out, *weights.factors, state.weights);
  else
    write_weights(out, s.weights, state.weights, weights.log_step);
  std::vector<Cell> net;
  net.reserve(s.points.size());
  for (const auto& p : s.points) net.push_back(cell(p, q));
  const Predictor predictor = residual_bits(net, s.u_count, s.v_count, parallelogram) <
                                      residual_bits(net, s.u_count, s.v_count, along_rows)
                                  ? parallelogram
                                  : along_rows;
  out.byte(predictor, Field::structure);
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i) {
      const Cell p = predicted(net, s.u_count, i, j, predictor);
      for (int k = 0; k < 3; ++k) out.varsint(net[s.index(i, j)][k] - p[k], Field::point);
    }
  return predictor == parallelogram;
}

NurbsSurface read_surface(ByteReader& in, double q, CodingState& state) {
  NurbsSurface s;
  s.u_order = static_cast<int>(read_order(in));
  s.v_order = static_cast<int>(read_order(in));
  const size_t counts_at = in.offset();
  const uint64_t u_count = read_point_count(in, 1), v_count = read_point_count(in, 1);
  // Each point takes at least 3 bytes (three residuals).
  if (u_count > in.left() || v_count > in.left() || u_count * v_count > in.left() / 3)
    in.fail(std::to_string(u_count) + " x " + std::to_string(v_count) + " control points cannot fit in the " +
                std::to_string(in.left()) + " bytes left",
            counts_at);
  s.u_count = static_cast<int>(u_count);
  s.v_count = static_cast<int>(v_count);
  s.u_knots = read_knots(in, u_count + s.u_order, state.knots);
  s.v_knots = read_knots(in, v_count + s.v_order, state.knots);
  const size_t n = u_count * v_count;
  s.weights = read_surface_weights(in, u_count, v_count, state.weights, state.version >= 6);
  const size_t predictor_at = in.offset();
  const uint8_t predictor = in.byte(Field::structure);
  if (predictor > parallelogram) in.fail("unknown predictor " + std::to_string(predictor), predictor_at);
  if (n > in.left() / 3) in.fail(std::to_string(n) + " control points cannot fit in the " + std::to_string(in.left()) + " bytes left");
  std::vector<Cell> net(n);
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i)
      net[s.index(i, j)] = read_residual_added(in, predicted(net, s.u_count, i, j, static_cast<Predictor>(predictor)));
  s.points.reserve(n);
  for (const auto& c : net) s.points.push_back(point_of(c, q));
  return s;
}

void write_curve(ByteWriter& out, const NurbsCurve& curve, double q, CodingState& state) {
  out.varuint(curve.order, Field::count);
  out.varuint(curve.points.size(), Field::count);
  write_knots(out, curve.knots, state.knots);
  write_weights(out, curve.weights, state.weights);
  Cell previous{0, 0, 0};
  for (const auto& p : curve.points) {
    const Cell c = cell(p, q);
    for (int k = 0; k < 3; ++k) out.varsint(c[k] - previous[k], Field::point);
    previous = c;
  }
}

NurbsCurve read_curve(ByteReader& in, double q, CodingState& state) {
  NurbsCurve curve;
  curve.dimension = 3;
  curve.order = static_cast<int>(read_order(in));
  const uint64_t n = read_point_count(in, 3);
  curve.knots = read_knots(in, n + curve.order, state.knots);
  curve.weights = read_weights(in, n, state.weights);
  if (n > in.left() / 3) in.fail(std::to_string(n) + " control points cannot fit in the " + std::to_string(in.left()) + " bytes left");
  Cell previous{0, 0, 0};
  curve.points.reserve(n);
  for (uint64_t i = 0; i < n; ++i) {
    previous = read_residual_added(in, previous);
    curve.points.push_back(point_of(previous, q));
  }
  return curve;
}

}  // namespace cadnurbs::cnb
