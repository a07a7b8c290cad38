// Trimming loops: segments (2D NURBS curves or polylines) with their edge numbers, control points on the
// face's (u,v) grid, predicted along the loop.
#include <array>
#include <bit>
#include <cmath>
#include <string>

#include "formats/cnb/cnb_geometry.hpp"
#include "formats/cnb/cnb_numbers.hpp"

namespace cadnurbs::cnb {

namespace {

using Cell2 = std::array<int64_t, 2>;
enum SegmentKind : uint8_t { curve_segment = 0, polyline_segment = 1 };

std::vector<Eigen::Vector2d> control_points(const TrimSegment& segment) {
  std::vector<Eigen::Vector2d> points;
  if (const auto* c = std::get_if<NurbsCurve>(&segment))
    for (const auto& p : c->points) points.push_back(p.head<2>());
  else
    points = std::get<Polyline2D>(segment).points;
  return points;
}

bool within_half_step(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double step) {
  return (a - b).cwiseAbs().maxCoeff() <= 0.5 * step;
}

// Every control point of the loop on the grid, starts snapped onto the previous segment's end (and the
// loop's end onto its start) where the originals were within half a step.
std::vector<std::vector<Cell2>> loop_cells(const TrimLoop& loop, double step) {
  std::vector<std::vector<Eigen::Vector2d>> points;
  for (const auto& segment : loop.segments) points.push_back(control_points(segment));
  std::vector<std::vector<Cell2>> cells(points.size());
  for (size_t s = 0; s < points.size(); ++s)
    for (const auto& p : points[s]) cells[s].push_back({on_grid(p.x(), step), on_grid(p.y(), step)});
  for (size_t s = 1; s < points.size(); ++s)
    if (within_half_step(points[s].front(), points[s - 1].back(), step)) cells[s].front() = cells[s - 1].back();
  if (points.size() > 1 && within_half_step(points.back().back(), points.front().front(), step))
    cells.back().back() = cells.front().front();
  return cells;
}

// The prediction of the next trim point of a face: the previous point (DPCM), or, within a segment,
// the line through the two previous points continued (pcurves are smooth, their points nearly evenly
// spaced). A segment's first point is always predicted by the previous point, which it usually is.
struct TrimPrediction {
  bool extrapolate = false;
  Cell2 last{0, 0}, before{0, 0};
  int seen = 0;  // points so far in the face

  Cell2 predict(bool segment_start) const {
    if (!extrapolate || segment_start || seen < 2) return last;
    return {2 * last[0] - before[0], 2 * last[1] - before[1]};
  }
  void push(const Cell2& c) {
    before = last;
    last = c;
    ++seen;
  }
};

void write_cells(ByteWriter& out, const std::vector<Cell2>& cells, TrimPrediction& prediction) {
  for (size_t i = 0; i < cells.size(); ++i) {
    const Cell2 p = prediction.predict(i == 0);
    out.varsint(cells[i][0] - p[0], Field::trim);
    out.varsint(cells[i][1] - p[1], Field::trim);
    prediction.push(cells[i]);
  }
}

// Bits the residuals of a face's trim points take with or without extrapolation, roughly.
uint64_t residual_bits(const std::vector<std::vector<std::vector<Cell2>>>& face, bool extrapolate) {
  TrimPrediction prediction;
  prediction.extrapolate = extrapolate;
  uint64_t bits = 0;
  for (const auto& loop : face)
    for (const auto& segment : loop)
      for (size_t i = 0; i < segment.size(); ++i) {
        const Cell2 p = prediction.predict(i == 0);
        for (int k = 0; k < 2; ++k) bits += std::bit_width(zigzag(segment[i][k] - p[k])) + 1;
        prediction.push(segment[i]);
      }
  return bits;
}

std::vector<Eigen::Vector2d> read_cells(ByteReader& in, size_t n, double step, TrimPrediction& prediction) {
  if (n > in.left() / 2) in.fail(std::to_string(n) + " trim points cannot fit in the " + std::to_string(in.left()) + " bytes left");
  std::vector<Eigen::Vector2d> points;
  points.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    Cell2 c = prediction.predict(i == 0);
    for (int k = 0; k < 2; ++k) {
      const size_t at = in.offset();
      c[k] += in.varsint(Field::trim);
      if (std::abs(static_cast<double>(c[k])) > 0x1p52) in.fail("trim coordinate outside the grid's range", at);
    }
    prediction.push(c);
    points.emplace_back(static_cast<double>(c[0]) * step, static_cast<double>(c[1]) * step);
  }
  return points;
}

}  // namespace

void write_trim_loops(ByteWriter& out, const std::vector<TrimLoop>& loops, int exponent, CodingState& state) {
  int& previous_edge = state.previous_edge;
  const double step = std::ldexp(1.0, exponent);
  out.varuint(loops.size(), Field::count);
  if (loops.empty()) return;
  std::vector<std::vector<std::vector<Cell2>>> face;
  for (const auto& loop : loops) face.push_back(loop_cells(loop, step));
  TrimPrediction prediction;
  prediction.extrapolate = state.trim_extrapolation && residual_bits(face, true) < residual_bits(face, false);
  out.byte(prediction.extrapolate ? 1 : 0, Field::structure);
  for (size_t l = 0; l < loops.size(); ++l) {
    const TrimLoop& loop = loops[l];
    out.varuint(loop.segments.size(), Field::count);
    const bool has_edges = !loop.edges.empty();
    out.byte(has_edges ? 1 : 0, Field::structure);
    const auto& cells = face[l];
    for (size_t s = 0; s < loop.segments.size(); ++s) {
      const auto& segment = loop.segments[s];
      const auto* curve = std::get_if<NurbsCurve>(&segment);
      out.byte(curve ? curve_segment : polyline_segment, Field::structure);
      if (has_edges) {
        const TrimEdgeRef& e = loop.edges[s];
        out.varuint(2 * zigzag(static_cast<int64_t>(e.edge) - previous_edge) + (e.reversed ? 1 : 0), Field::index);
        previous_edge = e.edge;
      }
      if (curve) {
        out.varuint(curve->order, Field::count);
        out.varuint(curve->points.size(), Field::count);
        write_knots(out, curve->knots, state.knots);
        write_weights(out, curve->weights, state.weights);
      } else {
        out.varuint(cells[s].size(), Field::count);
      }
      write_cells(out, cells[s], prediction);
    }
  }
}

std::vector<TrimLoop> read_trim_loops(ByteReader& in, int exponent, CodingState& state) {
  int& previous_edge = state.previous_edge;
  const double step = std::ldexp(1.0, exponent);
  const size_t loop_count = in.count(3);
  std::vector<TrimLoop> loops(loop_count);
  if (loops.empty()) return loops;
  TrimPrediction prediction;
  const size_t predictor_at = in.offset();
  const uint8_t extrapolate = in.byte(Field::structure);
  if (extrapolate > 1) in.fail("trim predictor " + std::to_string(extrapolate) + " is neither 0 nor 1", predictor_at);
  prediction.extrapolate = extrapolate == 1;
  for (auto& loop : loops) {
    const size_t segments_at = in.offset();
    const size_t segment_count = in.count(4);
    if (segment_count == 0) in.fail("a trimming loop without segments", segments_at);
    const size_t flag_at = in.offset();
    const uint8_t has_edges = in.byte(Field::structure);
    if (has_edges > 1) in.fail("edge flag " + std::to_string(has_edges) + " is neither 0 nor 1", flag_at);
    loop.segments.reserve(segment_count);
    for (size_t s = 0; s < segment_count; ++s) {
      const size_t kind_at = in.offset();
      const uint8_t kind = in.byte(Field::structure);
      if (kind > polyline_segment) in.fail("unknown trim segment kind " + std::to_string(kind), kind_at);
      if (has_edges) {
        const size_t at = in.offset();
        const uint64_t v = in.varuint(Field::index);
        const int64_t edge = previous_edge + unzigzag(v >> 1);
        if (edge < -1 || edge > 0x7FFFFFFF) in.fail("edge number " + std::to_string(edge) + " out of range", at);
        loop.edges.push_back({static_cast<int>(edge), (v & 1) != 0});
        previous_edge = static_cast<int>(edge);
      }
      if (kind == curve_segment) {
        NurbsCurve c;
        c.dimension = 2;
        const uint64_t order = read_order(in);
        c.order = static_cast<int>(order);
        const size_t n_at = in.offset();
        const size_t n = in.count(2);
        if (n < 1) in.fail("a trimming curve without control points", n_at);
        c.knots = read_knots(in, n + order, state.knots);
        c.weights = read_weights(in, n, state.weights);
        for (const auto& p : read_cells(in, n, step, prediction)) c.points.emplace_back(p.x(), p.y(), 0.0);
        loop.segments.emplace_back(std::move(c));
      } else {
        const size_t n_at = in.offset();
        const size_t n = in.count(2);
        if (n < 2) in.fail("a polyline of " + std::to_string(n) + " points", n_at);
        loop.segments.emplace_back(Polyline2D{read_cells(in, n, step, prediction)});
      }
    }
  }
  return loops;
}

}  // namespace cadnurbs::cnb
