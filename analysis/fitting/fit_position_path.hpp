#pragma once
// A keyframe path (VRML/X3D PositionInterpolator: keys and values, linear in between) as one NURBS curve
// whose parameter is the interpolator's fraction, within a deviation of the path at every fraction.
//
// The path is the interpolator's function f on [0, 1]: keyValue[0] before the first key, the last value
// after the last key, linear between keys. A key repeated with values at least the deviation apart is a
// jump: f has a left and a right limit there. One repeated with closer values (keys written with few
// decimals) is fitted as one key at the values' midpoint, and measured against both. The curve:
//   - is polynomial (no weights), so that no reading of "controlPoint" (Euclidean or w·P) can change it;
//   - has a clamped knot vector on exactly [0, 1], so the fraction is the curve parameter whether a
//     browser maps the fraction onto the knot domain (X_ITE) or uses it as the parameter directly;
//   - is fitted between the first and the last key by analysis/fitting/fit_curve (automatic knots, local
//     refinement) to the keys and to the path's points halfway between keys, its end points then set to
//     the first and last key values (so it starts and stops exactly where the path does), and joined to
//     constant pieces on [0, first key] and [last key, 1] when the keys do not span [0, 1];
//   - at a jump, is two such fits joined by a knot of full multiplicity (the order) at the key, each
//     ending on its own side's value, so it jumps where the path does (within the deviation both sides);
//   - is measured as `as_written` returns it (the caller's writer rounds its numbers): the error is that
//     of the curve a reader gets back, not of the one in memory. When that exceeds the deviation, the fit
//     is redone to a tighter tolerance (at most a few times).
// Why `max_error` bounds the error everywhere (not only at samples): the curve is cut into Bézier pieces
// at its knots and at the keys, so on each piece the path is one straight segment, which is itself a
// Bézier curve of the piece's degree (its points spread evenly along the segment); the difference of
// the two is a Bézier curve whose control points bound it (convex hull). `max_error` is the largest of
// these control points' lengths over all pieces (a piece ending at a jump against that side's limit).
//
// Refuses (GeometryError, entity "PositionInterpolator"): no keys, key and value counts that differ,
// decreasing keys, keys outside [0, 1], non-finite numbers, a deviation <= 0, and a path no curve with
// fewer control points than samples meets within the deviation.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

struct PositionPathFit {
  NurbsCurve curve;        // dimension 3, polynomial, clamped on [0, 1], as fitted (before as_written)
  double max_error = 0;    // bound on |as_written(curve)(t) - f(t)| over t in [0, 1] (see above)
  int fitted_samples = 0;  // samples the last fit used (keys and halfway points)
};

// The curve as a reader of the output will get it back (numbers rounded as written); null: unchanged.
using CurveAsWritten = std::function<NurbsCurve(const NurbsCurve&)>;

PositionPathFit fit_position_path(const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values,
                                  double deviation, const CurveAsWritten& as_written = nullptr);

// The bound described above for any polynomial curve on [0, 1] against the path (keys, values).
double path_error_bound(const NurbsCurve& curve, const std::vector<double>& keys,
                        const std::vector<Eigen::Vector3d>& values);

}  // namespace cadnurbs
