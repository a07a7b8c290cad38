#pragma once
// Knot vectors as whole numbers. CAD exporters write knots in whatever parameter units their kernel used
// (2.094395, 4.18879 for thirds of a turn; 10.337675 for a plane's side length), each costing digits in a
// text file. An affine change of parameter t -> (t - t0) / unit leaves a NURBS curve or surface exactly
// the same shape; when every distinct knot is then a whole number, the knots cost a digit or two.
#include <optional>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// t' = (t - origin) / unit.
struct KnotMap {
  double origin = 0.0, unit = 1.0;
  double operator()(double t) const { return (t - origin) / unit; }
};

// The map that takes the first knot to 0 and every distinct knot to within 1e-9 of the vector's length
// of a whole number, the largest being at most `max_whole` (more would cost more digits than it saves);
// units tried: the shortest non-empty span divided by 1 to 12. Nothing when no unit fits, or when the
// knots already are whole numbers from 0.
std::optional<KnotMap> whole_number_knot_map(const std::vector<double>& knots, int max_whole = 1000);

// The knot vector through the map, distinct knots rounded to their whole numbers.
std::vector<double> mapped_knots(const std::vector<double>& knots, const KnotMap& map);

// The trimmed surface with whole-number knots in u and/or v where a map exists and it makes the face
// shorter to write (the trimming curves are mapped with the surface, exactly: an affine map of control
// points; but a plane parametrised in millimetres has trims at round millimetre values that a map to
// [0, 1] would make long), weighed by written_length with the coordinate tolerance `tolerance`; and each
// NURBS trimming curve with whole-number knots of its own. Returns how many knot vectors were changed.
int use_whole_number_knots(TrimmedSurface& face, double tolerance);

// About how many characters the face's knots and trimming loops take as text, coordinates written within
// `tolerance` (trims within the parameter tolerance it implies, knots within 1/1000 of their shortest
// span): what the choice of parametrisation changes.
size_t written_length(const TrimmedSurface& face, double tolerance);

// The same for a 3D curve. Returns 1 when its knots were changed.
int use_whole_number_knots(NurbsCurve& curve);

}  // namespace cadnurbs
