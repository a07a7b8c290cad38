#pragma once
// The curve classes of a .3dm file as core NURBS curves. Each read_* function reads one class's data:
// the reader stands inside the object's TCODE_OPENNURBS_CLASS_DATA chunk, at the one-byte chunk version
// the class writes first (layouts from openNURBS's Write/Read of each class). Every curve returned has
// passed core's validate(); anything that would not (a count past the chunk, an order < 2, decreasing
// knots, a weight <= 0, a dimension other than 2 or 3, an unknown major chunk version) is refused with
// ArchiveError "<file>: chunk 0x... at offset N: <class>: <reason>".
//
// Conventions, and why:
// - openNURBS stores order + cv_count - 2 knots (no end knots); core keeps the full vector, so the first
//   and last stored knot appear once more. The domain is the file's: a Brep's trims live in its
//   surfaces' parameter spaces and edges refer to curve parameters, so nothing is reparametrized.
// - openNURBS stores rational CVs homogeneous, (w*x, w*y, w*z, w). Core keeps Euclidean points, computed
//   the way openNURBS computes the Euclidean point it reports (ON_NurbsCurve::GetCV(i, ON_3dPoint&) and
//   GetCV with ON::euclidean_rational): r = 1.0 / w once, then x*r, y*r, z*r, a multiplication by the
//   reciprocal, not a division. So our points are bit-equal to openNURBS's Euclidean CVs. (rhino3dm's
//   NurbsCurve.points.get(i) hands out the homogeneous ON_4dPoint; a script that wants to compare
//   Euclidean values bit for bit must do the same x * (1 / w).) Weights are stored as the file has them.
// - A 2D curve (dimension 2, a Brep's trims) is a dimension-2 NurbsCurve with z = 0.
// - Curves that openNURBS evaluates in closed form become exact NURBS in their own domain: a line is
//   order 2 with two CVs, a polyline order 2 with one CV per point and its parameters as knots, an arc
//   the rational quadratic that ON_ArcCurve::GetNurbForm makes (1, 2 or 4 equal spans of at most a
//   quarter turn; the middle CV of a span of angle 2a at distance radius / cos(a) from the centre, weight
//   cos(a); knots equally spaced in the arc's domain m_t). The arc's NURBS parameter is not its angle
//   parameter in the interior of a span (both agree at span ends): point locus and domain are exact.
// - ON_CurveProxy is never written to a file: its Write and Read return false in openNURBS. The one
//   proxy-derived class that is written, ON_PolyEdgeSegment (inside an ON_PolyEdgeCurve), stores only a
//   reference to another object's Brep edge, no geometry; it has no reader here.
#include <vector>

#include "core/nurbs_curve.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// ON_NurbsCurve (also the demoted legacy ids TL_NurbsCurve and the old V2 NURBS curve).
NurbsCurve read_nurbs_curve(ArchiveReader& reader);
// ON_LineCurve: order 2, 2 CVs, knots {t0, t0, t1, t1}.
NurbsCurve read_line_curve(ArchiveReader& reader);
// ON_ArcCurve: the rational quadratic above. Refuses a radius <= 0, an angle outside (0, 2 pi], a domain
// that does not increase.
NurbsCurve read_arc_curve(ArchiveReader& reader);
// The obsolete V2 circle curve (class id CF33BE29-...): a full circle in the same form.
NurbsCurve read_obsolete_circle_curve(ArchiveReader& reader);
// ON_PolylineCurve: order 2, knots = the point parameters with the ends doubled. Refuses fewer than 2
// points, a parameter count other than the point count, parameters that do not increase.
NurbsCurve read_polyline_curve(ArchiveReader& reader);
// ON_PolyCurve: its segments (nested objects, read with read_object) joined into one NURBS curve, see
// join_segments. Refuses a segment that is not a curve cadnurbs reads, a parameter count other than
// segment count + 1, parameters that do not increase.
NurbsCurve read_poly_curve(ArchiveReader& reader);

// A circular arc as openNURBS keeps it: centre (the plane's origin), the plane's unit x and y axes, the
// radius, and the angle interval in radians (angle0 < angle1 <= angle0 + 2 pi).
struct CircularArc {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d y_axis = Eigen::Vector3d::UnitY();
  double radius = 1.0;
  double angle0 = 0.0, angle1 = 0.0;
};

// The arc as a rational quadratic NURBS of `dimension` (2: z dropped) over [t0, t1] (t0 < t1), as
// described above. A full turn ends exactly at its start point. Does not validate its input.
NurbsCurve arc_as_nurbs(const CircularArc& arc, double t0, double t1, int dimension);

// Where arc_as_nurbs(arc, t0, t1, ...) has the point that the arc curve itself (openNURBS's ON_ArcCurve,
// whose angle moves linearly with its parameter) has at s in [t0, t1]. Within a span of angle 2a over
// NURBS parameters [u0, u1], the point at angle phi from the span's bisector is at
// u0 + (u1 - u0) (1 + tan(phi / 2) / tan(a / 2)) / 2 (the arc's rational quadratic is the circle's
// half-angle-tangent parametrization, affinely). Ends and span ends map to themselves.
double arc_nurbs_parameter(const CircularArc& arc, double t0, double t1, double s);

// The curve with its end knots at full multiplicity (order), by knot insertion at the domain ends; a
// clamped curve comes back unchanged. openNURBS allows unclamped (e.g. periodic) knot vectors.
NurbsCurve clamped(const NurbsCurve& curve);

// The same curve with order raised to `order` (>= curve.order), exactly: split into Bezier pieces, each
// raised in homogeneous coordinates, joined again with knots of multiplicity degree at the old breaks.
NurbsCurve with_order(const NurbsCurve& curve, int order);

// Joins curves end to start into one NURBS: segment i is mapped affinely from its own domain onto
// [breaks[i], breaks[i+1]] (breaks.size() == segments.size() + 1, increasing), clamped, raised to the
// highest order, made rational if any segment is (weights rescaled per segment so that joints agree; a
// NURBS is unchanged by scaling all its weights), and chained with a C0 joint (knot multiplicity degree)
// at each break. The joint's CV is the earlier segment's end point (segments of a valid polycurve meet
// within the model tolerance). The dimension is the highest of the segments'.
NurbsCurve join_segments(const std::vector<NurbsCurve>& segments, const std::vector<double>& breaks);

}  // namespace cadnurbs::rhino
