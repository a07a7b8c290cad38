#pragma once
// The surface classes of a .3dm file as core NURBS surfaces. Each read_* function reads one class's data
// (the reader stands inside the object's TCODE_OPENNURBS_CLASS_DATA chunk, at its one-byte chunk version)
// and returns a surface that passed core's validate(); a count past the chunk, an order < 2, decreasing
// knots, a weight <= 0 or an unknown major chunk version is refused with ArchiveError
// "<file>: chunk 0x... at offset N: <class>: <reason>". Knots and CVs follow curve_objects.hpp's
// conventions (end knots added once more; Euclidean points x * (1 / w), bit-equal to openNURBS's GetCV).
//
// Domains are the file's, because a Brep's 2D trims live in them: nothing is reparametrized, except
// inside a revolution's angle direction (see read_rev_surface).
//
// ON_SurfaceProxy is never written to a file (its Write and Read return false in openNURBS), nor is its
// subclass ON_OffsetSurface; there is no reader for them.
#include <Eigen/Core>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// ON_NurbsSurface (also the demoted legacy ids TL_NurbsSurface and the old V2 NURBS surface). openNURBS
// writes CV(i, j) with j (the v index) varying fastest; core's order is u fastest, so the grid is
// transposed on reading. A dimension-2 surface gets z = 0.
NurbsSurface read_nurbs_surface(ArchiveReader& reader);

// ON_PlaneSurface: the bilinear patch over the plane's extents (corner (s, t) at origin + s x + t y),
// with the plane surface's domain as knots {d0, d0, d1, d1} in each direction. Refuses an empty domain or
// extent.
NurbsSurface read_plane_surface(ArchiveReader& reader);

// An ON_RevSurface's data: `profile` revolved about the line axis_from -> axis_to (right-handed about
// that direction) from angle0 to angle1 (radians, 0 < angle1 - angle0 <= 2 pi); the angle parameter runs
// over [t0, t1]; transposed: u is the profile's parameter and v the angle's (else u the angle's).
struct Revolution {
  NurbsCurve profile;
  Eigen::Vector3d axis_from = Eigen::Vector3d::Zero(), axis_to = Eigen::Vector3d::UnitZ();
  double angle0 = 0.0, angle1 = 0.0;
  double t0 = 0.0, t1 = 0.0;
  bool transposed = false;
};

// Reads ON_RevSurface's data (chunk versions 1.x, where the angle parameter is the angle, and 2.x); its
// profile is a nested curve object read with read_object. Refuses a missing or non-curve profile, an
// axis of zero length, an angle outside (0, 2 pi], an angle domain that does not increase.
Revolution read_revolution(ArchiveReader& reader);

// The revolution as exact NURBS: the tensor product of the profile with the rational quadratic arc of
// arc_as_nurbs over [t0, t1] (1, 2 or 4 spans, as ON_RevSurface::GetNurbForm). CV (k, j) is profile CV j
// rotated to arc CV k's angle and pushed out by its radius factor (1, or 1 / cos(half span) for a middle
// CV), weight = arc weight * profile weight; profile CVs within 1e-12 of the axis stay on it (poles). A
// full turn's last angle column equals its first. Domain: [t0, t1] x the profile's domain (swapped when
// transposed). Note: openNURBS's angle parameter moves linearly with the angle; the NURBS angle parameter
// agrees with it at span ends only (revolution_nurbs_parameter maps one to the other), so a trim inside
// a span that was written in the RevSurface's parameters lands at a slightly different angle on the NURBS.
NurbsSurface revolution_as_nurbs(const Revolution& revolution);
// The NURBS angle-direction parameter of the revolution's angle parameter s in [t0, t1].
double revolution_nurbs_parameter(const Revolution& revolution, double s);

// read_revolution, then revolution_as_nurbs.
NurbsSurface read_rev_surface(ArchiveReader& reader);

// ON_SumSurface: basepoint + curve0(u) + curve1(v), exactly: CV (i, j) = basepoint + P0_i + P1_j with
// weight w0_i * w1_j (the sum of two rational curves is this tensor product: the numerator
// A(u) b(v) + a(u) B(v) has homogeneous CVs w0_i w1_j (P0_i + P1_j)). Both curves are nested objects.
NurbsSurface read_sum_surface(ArchiveReader& reader);
NurbsSurface sum_as_nurbs(const NurbsCurve& u_curve, const NurbsCurve& v_curve, const Eigen::Vector3d& basepoint);

// The same surface with u and v swapped (CV (i, j) becomes (j, i)); exact, nothing is recomputed.
NurbsSurface transposed(const NurbsSurface& surface);

}  // namespace cadnurbs::rhino
