#pragma once
// STEP's analytic surfaces (ISO 10303-42: PLANE, CYLINDRICAL_, CONICAL_, SPHERICAL_, TOROIDAL_SURFACE,
// SURFACE_OF_REVOLUTION, SURFACE_OF_LINEAR_EXTRUSION) in their natural parameters, the nearest natural
// parameters of a point in closed form, and each surface over a box of natural parameters as an exact
// NURBS with an exact map between the two parameterisations.
// Sources: Piegl & Tiller, The NURBS Book, 2nd ed.: §7.3-7.5 (the circle as rational quadratic arcs),
// §8.2 (the bilinear plane), §8.3 (general cylinder / extrusion: the profile times a degree-1 direction),
// §8.5 (surfaces of revolution, A8.1: the profile's control points swept along arcs, weights multiplied;
// the sphere and the torus are revolutions of a meridian circle arc); §4.3 (affine invariance).
//
// Why the NURBS are exact: each NURBS here is a tensor product of a unit arc (core/arc_parameterization)
// or a straight segment with another, and each control point is linear in the factors' control points
// (P_ij = L(c_i, d_j) with L bilinear, weights w_i v_j). Then the rational surface factorises into
// L(arc point, other factor's point) exactly: (cos a, sin a) from the arc, the profile from the profile.
// The natural -> NURBS map is arc_parameter in an angular direction and the identity otherwise.
//
// In:  a surface (frames from core/axis_frame), a NaturalBox of natural parameters.
// Out: SurfaceConversion: the NURBS (validate() passes), per direction the arc map or none, to_nurbs
//      / to_natural.
// Refuses (GeometryError(surface's STEP name, reason)): radii that are not positive (a cone's radius may
//      be 0: the apex at v = 0; its semi-angle must lie in (0, pi/2)); a zero or non-finite direction;
//      an empty or non-finite box; an angular range over 2 pi + 1e-9; a sphere's b outside
//      [-pi/2, pi/2] (+ 1e-9, then clamped); a profile range outside the profile's domain (+ 1e-12 of its
//      length). A torus whose minor radius reaches or exceeds its major radius (apple / spindle torus,
//      self-intersecting) is allowed: its NURBS is the same exact map.
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <variant>

#include "core/arc_parameterization.hpp"
#include "core/axis_frame.hpp"
#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

struct PlaneSurface {  // (u, v) -> o + u x + v y
  AxisFrame frame;
};
struct CylinderSurface {  // (a, v) -> o + r (cos a x + sin a y) + v z
  AxisFrame frame;
  double radius;
};
struct ConeSurface {  // (a, v) -> o + (r + v tan(semi_angle)) (cos a x + sin a y) + v z (STEP: radius at v = 0)
  AxisFrame frame;
  double radius, semi_angle;
};
struct SphereSurface {  // (a, b) -> o + r cos b (cos a x + sin a y) + r sin b z, b in [-pi/2, pi/2]
  AxisFrame frame;
  double radius;
};
struct TorusSurface {  // (a, b) -> o + (R + r cos b)(cos a x + sin a y) + r sin b z
  AxisFrame frame;
  double major_radius, minor_radius;
};
// (a, t) -> profile(t) turned by angle a about the axis, right-handed around axis_direction (normalised
// here: any non-zero length).
struct RevolutionSurface {
  NurbsCurve profile;
  Eigen::Vector3d axis_point, axis_direction;
};
// (t, v) -> profile(t) + v direction (direction as given, not normalised).
struct ExtrusionSurface {
  NurbsCurve profile;
  Eigen::Vector3d direction;
};
using AnalyticSurface = std::variant<PlaneSurface, CylinderSurface, ConeSurface, SphereSurface, TorusSurface,
                                     RevolutionSurface, ExtrusionSurface>;

// The point at natural parameters (u, v); a profile parameter is clamped to the profile's domain.
Eigen::Vector3d natural_point(const AnalyticSurface& surface, const Eigen::Vector2d& natural);

// Whether each natural parameter is an angle (period 2 pi): cylinder, cone, sphere, revolution
// {true, false}; torus {true, true}; plane, extrusion {false, false}.
std::array<bool, 2> angular_directions(const AnalyticSurface& surface);

// The natural parameters of the surface point nearest p. Closed forms for plane, cylinder, cone (both
// nappes: past the apex the point lies at angle a + pi), sphere, torus (also a spindle torus's inner
// sheet); revolution (nearest in the meridian half-plane) and extrusion (nearest in the plane across the
// direction) by Newton on the profile (cut at its C0 knots) from every local minimum of 8 samples per
// knot span, the nearest result kept; with `near`, Newton from near's profile parameter too, whose
// result is kept unless another is nearer (beyond rounding): continuity along a trim.
// Angles: when `near` is given, within pi of near's (unwrapped), else in (-pi, pi]. On the axis (pole,
// apex, axis of revolution; the torus's centre circle for b) the angle is undefined: near's, else 0.
Eigen::Vector2d natural_inverse(const AnalyticSurface& surface, const Eigen::Vector3d& p,
                                const std::optional<Eigen::Vector2d>& near = {});

// A box of natural parameters: angular ranges at most 2 pi (+ 1e-9) long, a sphere's b within
// [-pi/2, pi/2]. RevolutionSurface: u = angle, v = profile parameter; ExtrusionSurface: u = profile
// parameter, v = distance along the direction (in multiples of it).
struct NaturalBox {
  double u0, u1, v0, v1;
};

struct SurfaceConversion {
  NurbsSurface surface;
  std::array<std::optional<ArcSpans>, 2> arcs;                     // per direction: the arc map, or empty for identity
  Eigen::Vector2d to_nurbs(const Eigen::Vector2d& natural) const;  // exact (arc_parameter per angle)
  Eigen::Vector2d to_natural(const Eigen::Vector2d& nurbs) const;  // arc_angle per angle
};

// The surface over the box as an exact NURBS: plane bilinear (order 2 x 2); cylinder and cone arc (u,
// order 3) x segment (v, order 2; a cone's apex inside the box is a degenerate row); sphere and torus
// arc x arc (rational biquadratic); revolution arc (u) x profile cut to [v0, v1] (v, core/split_curve);
// extrusion profile cut to [u0, u1] (u) x segment (v). Weights multiply.
SurfaceConversion analytic_to_nurbs(const AnalyticSurface& surface, const NaturalBox& box);

}  // namespace cadnurbs
