#pragma once
// A planar chain of lines and circular arcs, read from the small text format of shapes/README.md.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

struct OutlineSegment {
  bool is_arc = false;
  Eigen::Vector2d start, end;
  double sweep = 0.0;        // radians, arcs only; positive = counter-clockwise
  Eigen::Vector2d centre{0, 0};  // arcs only
  double radius = 0.0;       // arcs only

  Eigen::Vector2d start_tangent() const;
  Eigen::Vector2d end_tangent() const;
};

struct Outline {
  std::string plane = "xy";  // paths only: "xy" or "xz"
  std::vector<OutlineSegment> segments;
};

// Parses the text; `name` is used in errors ("<name>: line N: <reason>"). Throws std::runtime_error.
Outline parse_outline(const std::string& text, const std::string& name);

// Throws unless each segment starts in the direction the previous one ended (within 1e-9 rad).
void require_smooth(const Outline& outline, const std::string& name);

// The outline as one rational quadratic 2D NURBS: arcs split into pieces of at most 90 degrees with
// middle weight cos(theta/2), lines as three collinear points; pieces joined by double knots at
// 0, 1, 2, ... (seed 001, 2.3.3).
NurbsCurve outline_to_nurbs(const Outline& outline);

// For each control point of outline_to_nurbs, the left normal to carry an offset exactly: unit for
// lines and arc ends, (B1 - centre)/R (length 1/cos(theta/2)) for arc middles, so that
// curve + d * normals is the exact offset curve at distance d.
std::vector<Eigen::Vector2d> outline_offset_normals(const Outline& outline);

// Angle from an arc's start to the direction of q, measured in the arc's turning sense, in [0, 2 pi).
double angle_along_arc(const OutlineSegment& arc, const Eigen::Vector2d& q);

// Distance from q to the segment (line or arc) itself, ends included.
double distance_to_segment(const OutlineSegment& segment, const Eigen::Vector2d& q);

// Points along the outline: lines by their ends, arcs divided so that no chord is farther than
// `max_chord_deviation` from its arc (the thesis's STL rule), taken on a circle `radius_margin`
// larger than the arc (so that a profile swept at up to that offset keeps the bound too).
// Each point with its unit left normal.
struct OutlineSample {
  Eigen::Vector2d point, left_normal;
};
std::vector<OutlineSample> sample_outline(const Outline& outline, double max_chord_deviation,
                                         double radius_margin = 0.0);

}  // namespace cadnurbs
