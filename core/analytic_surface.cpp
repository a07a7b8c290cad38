#include "core/analytic_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/conic_curves.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"
#include "core/split_curve.hpp"

namespace cadnurbs {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * kPi;
// Below this fraction of the surface's size a point is on the axis (pole, apex): its angle is undefined.
constexpr double kOnAxis = 1e-13;

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;  // clang 14 (the fuzz build) deduces aggregates only with a guide

// An angle (any branch) within pi of near's, else in (-pi, pi].
double placed_angle(double angle, std::optional<double> near) {
  if (near) return angle + kTwoPi * std::round((*near - angle) / kTwoPi);
  const double wrapped = std::remainder(angle, kTwoPi);
  return wrapped <= -kPi ? wrapped + kTwoPi : wrapped;
}

double undefined_angle(std::optional<double> near) { return near ? *near : 0.0; }

std::optional<double> component(const std::optional<Eigen::Vector2d>& near, int i) {
  if (!near) return std::nullopt;
  return (*near)[i];
}

// Cylindrical coordinates of p about a frame's z axis.
struct Cylindrical {
  double rho, phi, z;
};
Cylindrical cylindrical(const AxisFrame& frame, const Eigen::Vector3d& p) {
  const Eigen::Vector3d l = to_local(frame, p);
  return {std::hypot(l.x(), l.y()), std::atan2(l.y(), l.x()), l.z()};
}

Eigen::Vector3d radial(const AxisFrame& frame, double a) { return std::cos(a) * frame.x + std::sin(a) * frame.y; }

// The part of v across the unit direction d.
Eigen::Vector3d across(const Eigen::Vector3d& v, const Eigen::Vector3d& d) { return v - v.dot(d) * d; }

// p turned by angle a about the line through `point` along the unit d (Rodrigues).
Eigen::Vector3d turned(const Eigen::Vector3d& p, double a, const Eigen::Vector3d& point, const Eigen::Vector3d& d) {
  const Eigen::Vector3d q = p - point;
  const Eigen::Vector3d w = across(q, d);
  return point + (q - w) + std::cos(a) * w + std::sin(a) * d.cross(w);
}

struct Terms {
  double f, d1, d2;
};

// The nearest parameter of a curve problem: minimises f(t) given by `terms` (returns f, f', f''), by
// Newton with step halving, started at t (clamped to [t0, t1]).
template <class TermsOf>
double newton_minimum(double t, double t0, double t1, TermsOf terms) {
  t = std::clamp(t, t0, t1);
  auto [f, d1, d2] = terms(t);
  for (int iteration = 0; iteration < 60; ++iteration) {
    if (!(d2 > 0)) d2 = std::abs(d1) / (0.01 * (t1 - t0)) + std::numeric_limits<double>::min();  // concave: small step
    double step = -d1 / d2;
    bool moved = false;
    for (int halving = 0; halving < 40; ++halving, step /= 2) {
      const double next = std::clamp(t + step, t0, t1);
      if (next == t) break;
      const auto [nf, nd1, nd2] = terms(next);
      if (nf <= f) {
        moved = std::abs(next - t) > 1e-15 * (t1 - t0);
        t = next;
        f = nf;
        d1 = nd1;
        d2 = nd2;
        break;
      }
    }
    if (!moved) break;
  }
  return t;
}

// The profile cut at its C0 knots: Newton inside a piece then sees the derivatives of that piece's
// side at a corner (an evaluation at the knot itself takes the next piece's).
std::vector<NurbsCurve> smooth_pieces(const NurbsCurve& profile) {
  std::vector<NurbsCurve> pieces{profile};
  for (double knot : c0_knots(profile.knots, profile.order, profile.count())) {
    auto [before, after] = split_curve(pieces.back(), knot);
    pieces.back() = std::move(before);
    pieces.push_back(std::move(after));
  }
  return pieces;
}

// The profile parameter minimising f (`terms(piece, t)` gives f, f', f''): Newton within each knot span
// from every sample (64 per span) whose f is below its neighbours', the least result kept (a profile may
// come near the same place on several branches: a single start can settle on the wrong one). With
// `near`, Newton from near's parameter too, kept unless another minimum is clearly lower (continuity).
template <class TermsOf>
double profile_minimum(const NurbsCurve& profile, std::optional<double> near, TermsOf terms) {
  // Fine enough on a 90-degree arc of a 219 mm profile to find a 2 mm feature (KiCad's axial inductors).
  constexpr int kSamples = 64;
  double best = profile.domain_start(), best_f = std::numeric_limits<double>::infinity(), near_t = 0,
         near_f = std::numeric_limits<double>::infinity();
  const std::optional<double> hint =
      near ? std::optional(std::clamp(*near, profile.domain_start(), profile.domain_end())) : std::nullopt;
  const std::vector<NurbsCurve> pieces = smooth_pieces(profile);
  if (hint) {
    for (const NurbsCurve& piece : pieces) {
      if (*hint < piece.domain_start() || (*hint >= piece.domain_end() && piece.domain_end() != profile.domain_end()))
        continue;
      auto piece_terms = [&](double t) { return terms(piece, t); };
      near_t = newton_minimum(*hint, piece.domain_start(), piece.domain_end(), piece_terms);
      near_f = piece_terms(near_t).f;
      break;
    }
    // On the surface from the neighbour's parameter (the common case, along an edge): no search needed.
    const double scale = std::max(1.0, curve_point(profile, near_t).norm());
    if (std::sqrt(2 * near_f) <= 1e-9 * scale) return near_t;
  }
  for (const NurbsCurve& piece : pieces) {
    auto piece_terms = [&](double t) { return terms(piece, t); };
    const std::vector<double> breaks = domain_breaks(piece.knots, piece.order, piece.count());
    for (size_t k = 0; k + 1 < breaks.size(); ++k) {
      std::array<double, kSamples + 1> f;
      auto sample = [&](int i) { return breaks[k] + (breaks[k + 1] - breaks[k]) * i / kSamples; };
      for (int i = 0; i <= kSamples; ++i) f[i] = piece_terms(sample(i)).f;
      for (int i = 0; i <= kSamples; ++i) {
        if ((i > 0 && f[i - 1] < f[i]) || (i < kSamples && f[i + 1] < f[i])) continue;
        const double t = newton_minimum(sample(i), breaks[k], breaks[k + 1], piece_terms);
        const double value = piece_terms(t).f;
        if (value < best_f) best_f = value, best = t;
      }
    }
  }
  if (hint) {
    const double scale = std::max(1.0, curve_point(profile, near_t).norm());
    // Continuity wins over a rival within 1e-9 of the size: where the surface meets itself (a profile
    // crossing the axis) both are on it, and only round-off tells them apart.
    if (std::sqrt(2 * near_f) <= std::sqrt(2 * best_f) + 1e-9 * scale) return near_t;
  }
  return best;
}

// The meridian coordinates (rho = distance from the axis, z = along the axis) of a revolution's profile
// at t with their first two derivatives, and its part across the axis (whose direction gives its angle).
struct Meridian {
  double rho, rho1, rho2, z, z1, z2;
  Eigen::Vector3d w;  // the part across the axis
};
Meridian meridian(const NurbsCurve& profile, const Eigen::Vector3d& axis_point, const Eigen::Vector3d& d, double t) {
  const std::vector<Eigen::Vector3d> c = curve_derivatives(profile, t, 2);
  Meridian m;
  const Eigen::Vector3d q = c[0] - axis_point;
  m.z = q.dot(d), m.z1 = c[1].dot(d), m.z2 = c[2].dot(d);
  m.w = across(q, d);
  const Eigen::Vector3d w1 = across(c[1], d), w2 = across(c[2], d);
  m.rho = m.w.norm();
  if (m.rho > 0) {
    m.rho1 = m.w.dot(w1) / m.rho;
    m.rho2 = (w1.squaredNorm() + m.w.dot(w2)) / m.rho - m.rho1 * m.rho1 / m.rho;
  } else {
    m.rho1 = w1.norm(), m.rho2 = 0;
  }
  return m;
}

// The unit direction across the axis of the plane through the axis that holds every control point of the
// profile (within 1e-9 of its size), if there is one (then the profile lies in it).
std::optional<Eigen::Vector3d> plane_across(const NurbsCurve& profile, const Eigen::Vector3d& axis_point,
                                            const Eigen::Vector3d& d) {
  Eigen::Vector3d widest = Eigen::Vector3d::Zero();
  double size = 0;
  for (const auto& point : profile.points) {
    const Eigen::Vector3d w = across(point - axis_point, d);
    if (w.norm() > widest.norm()) widest = w;
    size = std::max(size, (point - axis_point).norm());
  }
  if (!(widest.norm() > 1e-9 * size)) return std::nullopt;
  const Eigen::Vector3d e = widest.normalized();
  for (const auto& point : profile.points) {
    const Eigen::Vector3d w = across(point - axis_point, d);
    if ((w - w.dot(e) * e).norm() > 1e-9 * size) return std::nullopt;
  }
  return e;
}

Eigen::Vector3d unit_direction(const Eigen::Vector3d& d, const std::string& entity) {
  const double length = d.norm();
  if (!std::isfinite(length) || length == 0) throw GeometryError(entity, "its direction is zero or not finite");
  return d / length;
}

Eigen::Vector2d revolution_inverse(const RevolutionSurface& s, const Eigen::Vector3d& p,
                                   const std::optional<Eigen::Vector2d>& near) {
  const Eigen::Vector3d d = unit_direction(s.axis_direction, "surface of revolution");
  const Eigen::Vector3d q = p - s.axis_point;
  const double z = q.dot(d);
  const Eigen::Vector3d w = across(q, d);
  const double rho = w.norm();
  double t;
  if (const std::optional<Eigen::Vector3d> e = plane_across(s.profile, s.axis_point, d)) {
    // The profile lies in a plane through the axis: distances in that plane with a signed radius are
    // smooth where the profile crosses the axis; |radius| folds the profile there, and a false minimum
    // beside the true one misled the sampled search (KiCad's axial inductors: a 213 mm arc through the
    // axis, 0.4 mm off). p's image on either side of the axis, the nearer kept.
    auto nearest = [&](double target) {
      const double found = profile_minimum(s.profile, component(near, 1), [&](const NurbsCurve& piece, double t) {
        const std::vector<Eigen::Vector3d> c = curve_derivatives(piece, t, 2);
        const double dr = (c[0] - s.axis_point).dot(*e) - target, dz = (c[0] - s.axis_point).dot(d) - z;
        const double r1 = c[1].dot(*e), z1 = c[1].dot(d);
        return Terms{(dr * dr + dz * dz) / 2, dr * r1 + dz * z1, r1 * r1 + dr * c[2].dot(*e) + z1 * z1 + dz * c[2].dot(d)};
      });
      const Eigen::Vector3d c = curve_point(s.profile, found) - s.axis_point;
      return std::pair{found, std::hypot(c.dot(*e) - target, c.dot(d) - z)};
    };
    // The side near's profile point is on first: along an edge the next point is almost always there.
    double side = 1.0;
    if (near) side = (curve_point(s.profile, std::clamp((*near)[1], s.profile.domain_start(), s.profile.domain_end())) - s.axis_point).dot(*e) < 0 ? -1.0 : 1.0;
    const auto [first, first_distance] = nearest(side * rho);
    const double scale = std::max({1.0, rho, std::abs(z)});
    if (near && first_distance <= 1e-9 * scale) {
      t = first;
    } else {
      const auto [second, second_distance] = nearest(-side * rho);
      t = second_distance < first_distance ? second : first;
    }
  } else {
    t = profile_minimum(s.profile, component(near, 1), [&](const NurbsCurve& piece, double t) {
      const Meridian m = meridian(piece, s.axis_point, d, t);
      const double dr = m.rho - rho, dz = m.z - z;
      return Terms{(dr * dr + dz * dz) / 2, dr * m.rho1 + dz * m.z1,
                   m.rho1 * m.rho1 + dr * m.rho2 + m.z1 * m.z1 + dz * m.z2};
    });
  }
  const Meridian m = meridian(s.profile, s.axis_point, d, t);
  const double size = std::max({rho, std::abs(z), m.rho, std::abs(m.z)});
  if (rho <= kOnAxis * size || m.rho <= kOnAxis * size) return {undefined_angle(component(near, 0)), t};
  // The angle turning the profile point's across-axis part onto p's.
  const double a = std::atan2(m.w.cross(w).dot(d), m.w.dot(w));
  return {placed_angle(a, component(near, 0)), t};
}

Eigen::Vector2d extrusion_inverse(const ExtrusionSurface& s, const Eigen::Vector3d& p,
                                  const std::optional<Eigen::Vector2d>& near) {
  const Eigen::Vector3d d = unit_direction(s.direction, "surface of linear extrusion");
  const double t = profile_minimum(s.profile, component(near, 0), [&](const NurbsCurve& piece, double t) {
    const std::vector<Eigen::Vector3d> c = curve_derivatives(piece, t, 2);
    const Eigen::Vector3d g = across(c[0] - p, d), g1 = across(c[1], d), g2 = across(c[2], d);
    return Terms{g.squaredNorm() / 2, g.dot(g1), g1.squaredNorm() + g.dot(g2)};
  });
  return {t, (p - curve_point(s.profile, t)).dot(s.direction) / s.direction.squaredNorm()};
}

}  // namespace

Eigen::Vector3d natural_point(const AnalyticSurface& surface, const Eigen::Vector2d& n) {
  const double u = n.x(), v = n.y();
  return std::visit(
      Overloaded{
          [&](const PlaneSurface& s) -> Eigen::Vector3d {
            return to_world(s.frame, {u, v, 0});
          },
          [&](const CylinderSurface& s) -> Eigen::Vector3d {
            return s.frame.origin + s.radius * radial(s.frame, u) + v * s.frame.z;
          },
          [&](const ConeSurface& s) -> Eigen::Vector3d {
            return s.frame.origin + (s.radius + v * std::tan(s.semi_angle)) * radial(s.frame, u) + v * s.frame.z;
          },
          [&](const SphereSurface& s) -> Eigen::Vector3d {
            return s.frame.origin + s.radius * std::cos(v) * radial(s.frame, u) + s.radius * std::sin(v) * s.frame.z;
          },
          [&](const TorusSurface& s) -> Eigen::Vector3d {
            return s.frame.origin + (s.major_radius + s.minor_radius * std::cos(v)) * radial(s.frame, u) +
                   s.minor_radius * std::sin(v) * s.frame.z;
          },
          [&](const RevolutionSurface& s) -> Eigen::Vector3d {
            return turned(curve_point(s.profile, v), u, s.axis_point, s.axis_direction.normalized());
          },
          [&](const ExtrusionSurface& s) -> Eigen::Vector3d { return curve_point(s.profile, u) + v * s.direction; },
      },
      surface);
}

std::array<bool, 2> angular_directions(const AnalyticSurface& surface) {
  return std::visit(Overloaded{
                        [](const PlaneSurface&) {
                          return std::array<bool, 2>{false, false};
                        },
                        [](const TorusSurface&) {
                          return std::array<bool, 2>{true, true};
                        },
                        [](const ExtrusionSurface&) {
                          return std::array<bool, 2>{false, false};
                        },
                        [](const auto&) {
                          return std::array<bool, 2>{true, false};
                        },
                    },
                    surface);
}

Eigen::Vector2d natural_inverse(const AnalyticSurface& surface, const Eigen::Vector3d& p,
                                const std::optional<Eigen::Vector2d>& near) {
  const std::optional<double> near_u = component(near, 0), near_v = component(near, 1);
  // The angle about the frame's axis, or near's on the axis.
  auto axial_angle = [&](const Cylindrical& c, double size) {
    return c.rho <= kOnAxis * size ? undefined_angle(near_u) : placed_angle(c.phi, near_u);
  };
  return std::visit(Overloaded{
                        [&](const PlaneSurface& s) -> Eigen::Vector2d { return to_local(s.frame, p).head<2>(); },
                        [&](const CylinderSurface& s) -> Eigen::Vector2d {
                          const Cylindrical c = cylindrical(s.frame, p);
                          return {axial_angle(c, s.radius + c.rho), c.z};
                        },
                        [&](const ConeSurface& s) -> Eigen::Vector2d {
                          // In p's meridian plane the cone is the line (r + v k, v) over signed radii: nearest v for
                          // radius +rho (angle phi) and -rho (angle phi + pi, the other nappe); the nearer wins.
                          const Cylindrical c = cylindrical(s.frame, p);
                          const double k = std::tan(s.semi_angle);
                          auto foot = [&](double signed_rho) {
                            const double v = (c.z + k * (signed_rho - s.radius)) / (1 + k * k);
                            return std::pair{v, std::hypot(s.radius + v * k - signed_rho, v - c.z)};
                          };
                          const auto [v_front, d_front] = foot(c.rho);
                          const auto [v_back, d_back] = foot(-c.rho);
                          const bool back = d_back < d_front;
                          const double v = back ? v_back : v_front;
                          const double size = s.radius + c.rho + std::abs(c.z);
                          if (c.rho <= kOnAxis * size || std::abs(s.radius + v * k) <= kOnAxis * size)
                            return {undefined_angle(near_u), v};
                          return {placed_angle(back ? c.phi + kPi : c.phi, near_u), v};
                        },
                        [&](const SphereSurface& s) -> Eigen::Vector2d {
                          const Cylindrical c = cylindrical(s.frame, p);
                          return {axial_angle(c, s.radius + c.rho + std::abs(c.z)), std::atan2(c.z, c.rho)};
                        },
                        [&](const TorusSurface& s) -> Eigen::Vector2d {
                          // In p's meridian plane the torus is two circles of radius r about (+-R, 0) over signed
                          // radii: the nearer wins (the second is met only when r > R, or for points off the surface).
                          const Cylindrical c = cylindrical(s.frame, p);
                          const double big = s.major_radius, small = s.minor_radius;
                          const double d_front = std::abs(std::hypot(c.rho - big, c.z) - small);
                          const double d_back = std::abs(std::hypot(-c.rho - big, c.z) - small);
                          const bool back = d_back < d_front;
                          const double signed_rho = back ? -c.rho : c.rho;
                          const double size = big + small + c.rho + std::abs(c.z);
                          const double a = c.rho <= kOnAxis * size ? undefined_angle(near_u)
                                                                   : placed_angle(back ? c.phi + kPi : c.phi, near_u);
                          const double b = std::hypot(signed_rho - big, c.z) <= kOnAxis * size
                                               ? undefined_angle(near_v)
                                               : placed_angle(std::atan2(c.z, signed_rho - big), near_v);
                          return {a, b};
                        },
                        [&](const RevolutionSurface& s) -> Eigen::Vector2d { return revolution_inverse(s, p, near); },
                        [&](const ExtrusionSurface& s) -> Eigen::Vector2d { return extrusion_inverse(s, p, near); },
                    },
                    surface);
}

namespace {

// The tensor product of two curves' control nets: P_ij = point(u_curve point i, v_curve point j),
// weights multiplied.
template <class Point>
NurbsSurface tensor(const NurbsCurve& u_curve, const NurbsCurve& v_curve, Point point) {
  NurbsSurface s;
  s.u_order = u_curve.order, s.v_order = v_curve.order;
  s.u_count = u_curve.count(), s.v_count = v_curve.count();
  s.u_knots = u_curve.knots, s.v_knots = v_curve.knots;
  const bool rational = u_curve.is_rational() || v_curve.is_rational();
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i) {
      s.points.push_back(point(u_curve.points[i], v_curve.points[j]));
      if (rational) s.weights.push_back(u_curve.weight(i) * v_curve.weight(j));
    }
  return s;
}

// A straight parameter segment: its control points' x are the parameter values v0, v1.
NurbsCurve segment(double v0, double v1) { return line_segment({v0, 0, 0}, {v1, 0, 0}, v0, v1); }

ArcSpans angle_range(double a0, double a1, const std::string& entity) {
  try {
    return arc_spans(a0, a1);
  } catch (const GeometryError& error) {
    throw GeometryError(entity, "angular range: " + error.reason());
  }
}

void check_positive(double value, const char* what, const std::string& entity) {
  if (!(value > 0) || !std::isfinite(value))
    throw GeometryError(entity, std::string(what) + " " + std::to_string(value) + " is not positive");
}

// The profile over [t0, t1] (clamped to its domain when within 1e-12 of its length), in its own
// parameters.
NurbsCurve profile_piece(const NurbsCurve& profile, double t0, double t1, const std::string& entity) {
  validate(profile, entity);
  const double start = profile.domain_start(), end = profile.domain_end(), slack = 1e-12 * (end - start);
  if (t0 < start - slack || t1 > end + slack)
    throw GeometryError(entity, "the box's profile range [" + std::to_string(t0) + ", " + std::to_string(t1) +
                                    "] leaves the profile's domain [" + std::to_string(start) + ", " +
                                    std::to_string(end) + "]");
  t0 = std::max(t0, start), t1 = std::min(t1, end);
  NurbsCurve piece = profile;
  piece.dimension = 3;
  if (t0 > start) piece = split_curve(piece, t0).second;
  if (t1 < end) piece = split_curve(piece, t1).first;
  return piece;
}

const char* step_name(const AnalyticSurface& surface) {
  static constexpr const char* names[] = {"plane",
                                          "cylindrical surface",
                                          "conical surface",
                                          "spherical surface",
                                          "toroidal surface",
                                          "surface of revolution",
                                          "surface of linear extrusion"};
  return names[surface.index()];
}

}  // namespace

Eigen::Vector2d SurfaceConversion::to_nurbs(const Eigen::Vector2d& natural) const {
  Eigen::Vector2d out = natural;
  for (int i = 0; i < 2; ++i)
    if (arcs[i]) out[i] = arc_parameter(*arcs[i], natural[i]);
  return out;
}

Eigen::Vector2d SurfaceConversion::to_natural(const Eigen::Vector2d& nurbs) const {
  Eigen::Vector2d out = nurbs;
  for (int i = 0; i < 2; ++i)
    if (arcs[i]) out[i] = arc_angle(*arcs[i], nurbs[i]);
  return out;
}

SurfaceConversion analytic_to_nurbs(const AnalyticSurface& surface, const NaturalBox& box) {
  const std::string entity = step_name(surface);
  if (!std::isfinite(box.u0) || !std::isfinite(box.u1) || !std::isfinite(box.v0) || !std::isfinite(box.v1))
    throw GeometryError(entity, "its parameter box is not finite");
  if (!(box.u1 > box.u0) || !(box.v1 > box.v0))
    throw GeometryError(entity, "its parameter box [" + std::to_string(box.u0) + ", " + std::to_string(box.u1) +
                                    "] x [" + std::to_string(box.v0) + ", " + std::to_string(box.v1) + "] is empty");
  const std::array<bool, 2> angular = angular_directions(surface);
  SurfaceConversion out;
  if (angular[0]) out.arcs[0] = angle_range(box.u0, box.u1, entity);
  if (angular[1]) out.arcs[1] = angle_range(box.v0, box.v1, entity);
  out.surface = std::visit(
      Overloaded{
          [&](const PlaneSurface& s) {
            return tensor(segment(box.u0, box.u1), segment(box.v0, box.v1), [&](const auto& u, const auto& v) {
              return Eigen::Vector3d(s.frame.origin + u.x() * s.frame.x + v.x() * s.frame.y);
            });
          },
          [&](const CylinderSurface& s) {
            check_positive(s.radius, "radius", entity);
            return tensor(unit_arc(*out.arcs[0]), segment(box.v0, box.v1), [&](const auto& c, const auto& v) {
              return Eigen::Vector3d(s.frame.origin + s.radius * (c.x() * s.frame.x + c.y() * s.frame.y) +
                                     v.x() * s.frame.z);
            });
          },
          [&](const ConeSurface& s) {
            if (!(s.radius >= 0) || !std::isfinite(s.radius))
              throw GeometryError(entity, "radius " + std::to_string(s.radius) + " is negative");
            if (!(s.semi_angle > 0 && s.semi_angle < kPi / 2))
              throw GeometryError(entity, "semi-angle " + std::to_string(s.semi_angle) + " is not in (0, pi/2)");
            const double k = std::tan(s.semi_angle);
            return tensor(unit_arc(*out.arcs[0]), segment(box.v0, box.v1), [&](const auto& c, const auto& v) {
              // Linear in v along each ruling, so the apex (radius 0) and beyond stay exact.
              return Eigen::Vector3d(s.frame.origin + (s.radius + v.x() * k) * (c.x() * s.frame.x + c.y() * s.frame.y) +
                                     v.x() * s.frame.z);
            });
          },
          [&](const SphereSurface& s) {
            check_positive(s.radius, "radius", entity);
            const double slack = 1e-9;
            if (box.v0 < -kPi / 2 - slack || box.v1 > kPi / 2 + slack)
              throw GeometryError(entity, "its latitude range [" + std::to_string(box.v0) + ", " +
                                              std::to_string(box.v1) + "] leaves [-pi/2, pi/2]");
            out.arcs[1] = angle_range(std::max(box.v0, -kPi / 2), std::min(box.v1, kPi / 2), entity);
            return tensor(unit_arc(*out.arcs[0]), unit_arc(*out.arcs[1]), [&](const auto& a, const auto& b) {
              return Eigen::Vector3d(s.frame.origin + s.radius * b.x() * (a.x() * s.frame.x + a.y() * s.frame.y) +
                                     s.radius * b.y() * s.frame.z);
            });
          },
          [&](const TorusSurface& s) {
            check_positive(s.major_radius, "major radius", entity);
            check_positive(s.minor_radius, "minor radius", entity);
            return tensor(unit_arc(*out.arcs[0]), unit_arc(*out.arcs[1]), [&](const auto& a, const auto& b) {
              return Eigen::Vector3d(
                  s.frame.origin + (s.major_radius + s.minor_radius * b.x()) * (a.x() * s.frame.x + a.y() * s.frame.y) +
                  s.minor_radius * b.y() * s.frame.z);
            });
          },
          [&](const RevolutionSurface& s) {
            const Eigen::Vector3d d = unit_direction(s.axis_direction, entity);
            const NurbsCurve profile = profile_piece(s.profile, box.v0, box.v1, entity);
            return tensor(unit_arc(*out.arcs[0]), profile, [&](const auto& c, const Eigen::Vector3d& q) {
              // Piegl & Tiller A8.1: the profile point's across-axis part swept by the unit arc.
              const Eigen::Vector3d w = across(q - s.axis_point, d);
              return Eigen::Vector3d(q - w + c.x() * w + c.y() * d.cross(w));
            });
          },
          [&](const ExtrusionSurface& s) {
            unit_direction(s.direction, entity);
            const NurbsCurve profile = profile_piece(s.profile, box.u0, box.u1, entity);
            return tensor(profile, segment(box.v0, box.v1), [&](const Eigen::Vector3d& q, const auto& v) {
              return Eigen::Vector3d(q + v.x() * s.direction);
            });
          },
      },
      surface);
  validate(out.surface, entity);
  return out;
}

}  // namespace cadnurbs
