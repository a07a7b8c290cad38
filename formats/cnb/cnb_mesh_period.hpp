#pragma once
// A traversal-coded mesh's period (docs/cnb.md, "Traversal-coded triangle mesh", version 5 on): a move R on
// the grid that carries much of the mesh onto itself, such as the pitch of a pin header's body, whose
// cells repeat along one axis in one piece, or the spacing of a connector's contacts. Beyond a gate a->b,
// where the triangle a period before (or after) is decoded already, the new vertex is predicted as that
// triangle's third corner moved by the period: exact wherever the cell repeats, where the parallelogram
// guesses a cell's every corner anew.
//
// dominant_period (writer): the axis-aligned move that maps the most of the points onto points. The
// PeriodPredictor is kept alike by writer and reader: vertices and triangles are added in decoded order,
// with their decoded numbers.
#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "formats/cnb/cnb_vertex_values.hpp"

namespace cadnurbs::cnb {

struct GridPointHash {
  size_t operator()(const GridPoint& p) const;
};

// The axis-aligned move (one coordinate non-zero, positive) that maps the most of `points` onto points of
// the list, among those between points met along the mesh's grid lines; zero when none maps at least 8
// points, or a tenth of them.
GridPoint dominant_period(const std::vector<GridPoint>& points);

// dominant_period, remembered by the points it was found for: the writer codes a file several ways, and
// each way meets the same meshes.
class PeriodCache {
 public:
  GridPoint period_of(const std::vector<GridPoint>& points);

 private:
  std::unordered_map<uint64_t, std::vector<std::pair<std::vector<GridPoint>, GridPoint>>> found_;
};

class PeriodPredictor {
 public:
  explicit PeriodPredictor(const GridPoint& period);

  bool active() const { return active_; }
  // Vertex `number` (0, 1, 2, ... in decoded order) at p; the first vertex at a grid point stands for it.
  void add_vertex(int number, const GridPoint& p);
  // A decoded triangle, its corners' numbers in its orientation.
  void add_triangle(int a, int b, int c);
  // The far corner of the triangle (b, a, v) beyond the gate a->b of the triangle (a, b, c), taken from the
  // decoded triangle (b', a', v') a period before (a' = a - period, ...; v = v' + period), else one a
  // period after, where the gate's own triangle is repeated there too ((a', b', c') decoded); none when
  // neither is.
  std::optional<GridPoint> predict(const GridPoint& a, const GridPoint& b, const GridPoint& c) const;

 private:
  struct EdgeHash {
    size_t operator()(const std::pair<int, int>& e) const;
  };
  GridPoint period_;
  bool active_;
  std::unordered_map<GridPoint, int, GridPointHash> first_at_;
  std::unordered_map<std::pair<int, int>, int, EdgeHash> apex_;  // directed edge -> the third corner
  std::vector<GridPoint> points_;                                 // by number
};

}  // namespace cadnurbs::cnb
