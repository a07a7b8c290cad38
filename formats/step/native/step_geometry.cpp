#include "formats/step/native/step_geometry.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/conic_curves.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs::step {

namespace {

using part21::Value;

Eigen::Vector3d triple(const Value& list, double scale) {
  if (list.size() != 3) throw part21::ValueError("expected 3 coordinates, found " + std::to_string(list.size()));
  return Eigen::Vector3d(list.item(0).number(), list.item(1).number(), list.item(2).number()) * scale;
}

std::optional<Eigen::Vector3d> optional_direction(const StepContext& context, const Value& value) {
  if (value.kind() == part21::ValueKind::unset) return std::nullopt;
  return read_direction(context, value.reference());
}

// A knot vector from STEP's distinct knots and multiplicities.
std::vector<double> expanded_knots(const Value& multiplicities, const Value& knots) {
  if (multiplicities.size() != knots.size())
    throw part21::ValueError(std::to_string(knots.size()) + " knots but " + std::to_string(multiplicities.size()) +
                             " multiplicities");
  std::vector<double> out;
  for (std::size_t k = 0; k < knots.size(); ++k) {
    const std::int64_t m = multiplicities.item(k).integer();
    if (m < 1 || m > 64) throw part21::ValueError("knot multiplicity " + std::to_string(m));
    out.insert(out.end(), static_cast<std::size_t>(m), knots.item(k).number());
  }
  return out;
}

// The B-spline subtypes whose knots ISO 10303-42 implies from the degree and the number of control points.
enum class ImpliedKnots { uniform, quasi_uniform, bezier };

// ISO 10303-42's knots for `count` control points of `degree`: uniform: -degree, ..., count, each once
// (the curve runs over [0, count - degree]); quasi-uniform: 0 and count - degree with multiplicity
// degree + 1, the integers between once; Bezier: 0 to (count - 1) / degree, inner knots degree times, end
// knots degree + 1 times (count - 1 must be a multiple of the degree).
std::vector<double> implied_knots(ImpliedKnots form, int degree, int count) {
  if (degree < 1 || count < degree + 1)
    throw part21::ValueError(std::to_string(count) + " control points for degree " + std::to_string(degree));
  std::vector<double> out;
  switch (form) {
    case ImpliedKnots::uniform:
      for (int i = 0; i < count + degree + 1; ++i) out.push_back(i - degree);
      break;
    case ImpliedKnots::quasi_uniform:
      out.assign(static_cast<std::size_t>(degree), 0.0);
      for (int i = 0; i <= count - degree; ++i) out.push_back(i);
      out.insert(out.end(), static_cast<std::size_t>(degree), static_cast<double>(count - degree));
      break;
    case ImpliedKnots::bezier: {
      if ((count - 1) % degree != 0)
        throw part21::ValueError("a Bezier form with " + std::to_string(count) + " control points of degree " +
                                 std::to_string(degree));
      const int segments = (count - 1) / degree;
      out.push_back(0.0);
      for (int k = 0; k <= segments; ++k) out.insert(out.end(), static_cast<std::size_t>(degree), static_cast<double>(k));
      out.push_back(segments);
      break;
    }
  }
  return out;
}

// The implied-knot subtype that `entity` is or holds, if any.
std::optional<ImpliedKnots> implied_form(const StepContext& context, EntityId entity, TypeId uniform,
                                         TypeId quasi_uniform, TypeId bezier) {
  const std::pair<TypeId, ImpliedKnots> forms[] = {
      {uniform, ImpliedKnots::uniform}, {quasi_uniform, ImpliedKnots::quasi_uniform}, {bezier, ImpliedKnots::bezier}};
  for (const auto& [type, form] : forms)
    if (type != part21::none && context.is(entity, type)) return form;
  return std::nullopt;
}

NurbsCurve read_bspline_curve(const StepContext& context, EntityId curve) {
  const auto& t = context.types;
  const part21::Model& m = context.model;
  // Simple B_SPLINE_CURVE_WITH_KNOTS: name, degree, points, form, closed, self_intersect, mults, knots, spec;
  // simple UNIFORM_CURVE, QUASI_UNIFORM_CURVE, BEZIER_CURVE: name, degree, points, form, closed, self.
  // Complex: B_SPLINE_CURVE(degree, points, form, closed, self) and B_SPLINE_CURVE_WITH_KNOTS(mults, knots,
  // spec) or an empty implied-knot record; RATIONAL_B_SPLINE_CURVE(weights).
  const std::optional<ImpliedKnots> implied = implied_form(context, curve, t.uniform_curve, t.quasi_uniform_curve, t.bezier_curve);
  const TypeId type = m.type(curve);
  const bool simple = type != part21::none;
  const part21::Record& shape = simple ? m.records(curve)[0] : context.record(curve, t.b_spline_curve, "a B-spline curve");
  const std::size_t first = simple ? 1 : 0, knots_first = simple ? 6 : 0;
  NurbsCurve out;
  out.order = static_cast<int>(m.parameter(shape, first).integer()) + 1;
  const Value points = m.parameter(shape, first + 1);
  for (std::size_t i = 0; i < points.size(); ++i) out.points.push_back(read_point(context, points.item(i).reference()));
  if (implied) {
    out.knots = implied_knots(*implied, out.order - 1, static_cast<int>(out.points.size()));
  } else {
    const part21::Record& knotted = context.record(curve, t.b_spline_curve_with_knots, "a B-spline curve with knots");
    out.knots = expanded_knots(m.parameter(knotted, knots_first), m.parameter(knotted, knots_first + 1));
  }
  if (!simple && context.is(curve, t.rational_b_spline_curve)) {
    const Value weights = m.parameter(*m.record(curve, t.rational_b_spline_curve), 0);
    for (std::size_t i = 0; i < weights.size(); ++i) out.weights.push_back(weights.item(i).number());
  }
  try {
    validate(out, "curve");
  } catch (const GeometryError& error) {
    context.refuse(curve, error.reason());
  }
  return out;
}

NurbsSurface read_bspline_surface(const StepContext& context, EntityId surface) {
  const auto& t = context.types;
  const part21::Model& m = context.model;
  // Simple B_SPLINE_SURFACE_WITH_KNOTS: name, u_degree, v_degree, points, form, u_closed, v_closed,
  // self_intersect, u_mults, v_mults, u_knots, v_knots, spec. Complex: B_SPLINE_SURFACE(u_degree, v_degree,
  // points, form, u_closed, v_closed, self) B_SPLINE_SURFACE_WITH_KNOTS(u_mults, v_mults, u_knots, v_knots,
  // spec) RATIONAL_B_SPLINE_SURFACE(weights).
  // Simple UNIFORM_SURFACE, QUASI_UNIFORM_SURFACE, BEZIER_SURFACE: as B_SPLINE_SURFACE, knots implied.
  const std::optional<ImpliedKnots> implied =
      implied_form(context, surface, t.uniform_surface, t.quasi_uniform_surface, t.bezier_surface);
  const bool simple = m.type(surface) != part21::none;
  const part21::Record& shape = simple ? m.records(surface)[0] : context.record(surface, t.b_spline_surface, "a B-spline surface");
  const std::size_t first = simple ? 1 : 0, knots_first = simple ? 8 : 0;
  const bool rational = !simple && context.is(surface, t.rational_b_spline_surface);
  NurbsSurface out;
  out.u_order = static_cast<int>(m.parameter(shape, first).integer()) + 1;
  out.v_order = static_cast<int>(m.parameter(shape, first + 1).integer()) + 1;
  const Value points = m.parameter(shape, first + 2);
  // STEP's control points are a list over u of lists over v; ours run u fastest.
  out.u_count = static_cast<int>(points.size());
  out.v_count = out.u_count > 0 ? static_cast<int>(points.item(0).size()) : 0;
  out.points.resize(static_cast<std::size_t>(out.u_count) * static_cast<std::size_t>(out.v_count));
  if (rational) out.weights.resize(out.points.size());
  for (int i = 0; i < out.u_count; ++i) {
    const Value row = points.item(static_cast<std::size_t>(i));
    if (static_cast<int>(row.size()) != out.v_count) context.refuse(surface, "control point rows of unequal lengths");
    for (int j = 0; j < out.v_count; ++j)
      out.points[static_cast<std::size_t>(out.index(i, j))] = read_point(context, row.item(static_cast<std::size_t>(j)).reference());
  }
  if (rational) {
    const Value weights = m.parameter(*m.record(surface, t.rational_b_spline_surface), 0);
    if (static_cast<int>(weights.size()) != out.u_count) context.refuse(surface, "weights do not match the control points");
    for (int i = 0; i < out.u_count; ++i) {
      const Value row = weights.item(static_cast<std::size_t>(i));
      if (static_cast<int>(row.size()) != out.v_count) context.refuse(surface, "weights do not match the control points");
      for (int j = 0; j < out.v_count; ++j)
        out.weights[static_cast<std::size_t>(out.index(i, j))] = row.item(static_cast<std::size_t>(j)).number();
    }
  }
  if (implied) {
    out.u_knots = implied_knots(*implied, out.u_order - 1, out.u_count);
    out.v_knots = implied_knots(*implied, out.v_order - 1, out.v_count);
  } else {
    const part21::Record& knotted =
        context.record(surface, t.b_spline_surface_with_knots, "a B-spline surface with knots");
    out.u_knots = expanded_knots(m.parameter(knotted, knots_first), m.parameter(knotted, knots_first + 2));
    out.v_knots = expanded_knots(m.parameter(knotted, knots_first + 1), m.parameter(knotted, knots_first + 3));
  }
  try {
    validate(out, "surface");
  } catch (const GeometryError& error) {
    context.refuse(surface, error.reason());
  }
  return out;
}

double positive_length(const StepContext& context, EntityId entity, const Value& value) {
  const double length = value.number() * context.millimetres;
  if (!(length > 0) || !std::isfinite(length)) context.refuse(entity, "a radius or length that is not positive");
  return length;
}

}  // namespace

Eigen::Vector3d read_point(const StepContext& context, EntityId point) {
  return reading(context, point, [&] {
    const auto& r = context.record(point, context.types.cartesian_point, "a CARTESIAN_POINT");
    return triple(context.model.parameter(r, 1), context.millimetres);
  });
}

double cartesian_points_size(const StepContext& context) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (EntityId point : context.model.of_type(context.types.cartesian_point)) {
    try {
      const Value coordinates = context.model.parameter(*context.model.record(point, context.types.cartesian_point), 1);
      if (coordinates.size() != 3) continue;
      const Eigen::Vector3d p = triple(coordinates, 1.0);
      if (!p.allFinite()) continue;
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    } catch (const part21::ValueError&) {
    }
  }
  return lo.x() <= hi.x() ? (hi - lo).norm() : 0.0;
}

Eigen::Vector3d read_direction(const StepContext& context, EntityId direction) {
  return reading(context, direction, [&] {
    const auto& r = context.record(direction, context.types.direction, "a DIRECTION");
    return triple(context.model.parameter(r, 1), 1.0);
  });
}

AxisFrame read_frame(const StepContext& context, EntityId placement) {
  return reading(context, placement, [&] {
    const auto& r = context.record(placement, context.types.axis2_placement_3d, "an AXIS2_PLACEMENT_3D");
    const part21::Model& m = context.model;
    try {
      return axis_frame(read_point(context, m.parameter(r, 1).reference()), optional_direction(context, m.parameter(r, 2)),
                        optional_direction(context, m.parameter(r, 3)), m.entity_text(placement));
    } catch (const GeometryError& error) {
      context.refuse(placement, error.reason());
    }
  });
}

StepCurve read_curve(const StepContext& context, EntityId curve) {
  const auto& t = context.types;
  const part21::Model& m = context.model;
  return reading(context, curve, [&]() -> StepCurve {
    const TypeId type = m.type(curve);
    if (type == t.line && type != part21::none) {
      const auto& r = *m.record(curve, t.line);
      const Eigen::Vector3d point = read_point(context, m.parameter(r, 1).reference());
      const EntityId vector = m.parameter(r, 2).reference();
      const auto& v = context.record(vector, t.vector, "a VECTOR");
      const Eigen::Vector3d direction = read_direction(context, m.parameter(v, 1).reference());
      const double magnitude = m.parameter(v, 2).number() * context.millimetres;
      if (!(direction.norm() > 0) || !(magnitude > 0)) context.refuse(curve, "a line without a direction");
      return StepLine{point, direction.normalized() * magnitude};
    }
    if (type == t.circle && type != part21::none) {
      const auto& r = *m.record(curve, t.circle);
      return StepCircle{read_frame(context, m.parameter(r, 1).reference()), positive_length(context, curve, m.parameter(r, 2))};
    }
    if (type == t.ellipse && type != part21::none) {
      const auto& r = *m.record(curve, t.ellipse);
      return StepEllipse{read_frame(context, m.parameter(r, 1).reference()), positive_length(context, curve, m.parameter(r, 2)),
                         positive_length(context, curve, m.parameter(r, 3))};
    }
    if ((type == t.surface_curve || type == t.seam_curve) && type != part21::none)
      return read_curve(context, m.parameter(m.records(curve)[0], 1).reference());
    for (TypeId bspline : {t.b_spline_curve_with_knots, t.b_spline_curve, t.uniform_curve, t.quasi_uniform_curve, t.bezier_curve})
      if (bspline != part21::none && context.is(curve, bspline)) return read_bspline_curve(context, curve);
    context.refuse(curve, "a curve type the native reader does not read");
  });
}

StepSurface read_surface(const StepContext& context, EntityId surface) {
  const auto& t = context.types;
  const part21::Model& m = context.model;
  return reading(context, surface, [&]() -> StepSurface {
    const TypeId type = m.type(surface);
    auto frame = [&] { return read_frame(context, m.parameter(m.records(surface)[0], 1).reference()); };
    auto length = [&](std::size_t k) { return positive_length(context, surface, m.parameter(m.records(surface)[0], k)); };
    try {
      if (type == part21::none || type == t.uniform_surface || type == t.quasi_uniform_surface || type == t.bezier_surface) {
        if (type != part21::none || context.is(surface, t.b_spline_surface)) return read_bspline_surface(context, surface);
      } else if (type == t.plane) {
        return AnalyticSurface{PlaneSurface{frame()}};
      } else if (type == t.cylindrical_surface) {
        return AnalyticSurface{CylinderSurface{frame(), length(2)}};
      } else if (type == t.conical_surface) {
        const double radius = m.parameter(m.records(surface)[0], 2).number() * context.millimetres;
        const double semi_angle = m.parameter(m.records(surface)[0], 3).number() * context.radians;
        if (!(radius >= 0) || !(std::abs(semi_angle) > 0) || !(std::abs(semi_angle) < std::numbers::pi / 2))
          context.refuse(surface, "a cone with radius < 0 or a semi-angle not strictly between 0 and 90 degrees");
        return AnalyticSurface{ConeSurface{frame(), radius, semi_angle}};
      } else if (type == t.spherical_surface) {
        return AnalyticSurface{SphereSurface{frame(), length(2)}};
      } else if (type == t.toroidal_surface) {
        return AnalyticSurface{TorusSurface{frame(), length(2), length(3)}};
      } else if (type == t.surface_of_revolution) {
        const auto& r = m.records(surface)[0];
        const NurbsCurve profile = curve_nurbs(read_curve(context, m.parameter(r, 1).reference()));
        const EntityId axis = m.parameter(r, 2).reference();
        const auto& a = context.record(axis, t.axis1_placement, "an AXIS1_PLACEMENT");
        const Eigen::Vector3d origin = read_point(context, m.parameter(a, 1).reference());
        const Eigen::Vector3d direction = m.parameter(a, 2).kind() == part21::ValueKind::unset
                                              ? Eigen::Vector3d(0, 0, 1)
                                              : read_direction(context, m.parameter(a, 2).reference());
        if (!(direction.norm() > 0)) context.refuse(axis, "a zero axis");
        return AnalyticSurface{RevolutionSurface{profile, origin, direction.normalized()}};
      } else if (type == t.surface_of_linear_extrusion) {
        const auto& r = m.records(surface)[0];
        const NurbsCurve profile = curve_nurbs(read_curve(context, m.parameter(r, 1).reference()));
        const EntityId vector = m.parameter(r, 2).reference();
        const auto& v = context.record(vector, t.vector, "a VECTOR");
        const Eigen::Vector3d direction = read_direction(context, m.parameter(v, 1).reference());
        const double magnitude = m.parameter(v, 2).number() * context.millimetres;
        if (!(direction.norm() > 0) || !(magnitude > 0)) context.refuse(vector, "a zero extrusion");
        return AnalyticSurface{ExtrusionSurface{profile, direction.normalized() * magnitude}};
      } else if (type == t.b_spline_surface_with_knots) {
        return read_bspline_surface(context, surface);
      }
    } catch (const GeometryError& error) {
      context.refuse(surface, error.reason());
    }
    context.refuse(surface, "a surface type the native reader does not read");
  });
}

NurbsCurve curve_nurbs(const StepCurve& curve) {
  constexpr double turn = 2 * std::numbers::pi;
  if (const auto* line = std::get_if<StepLine>(&curve)) return line_segment(line->point, line->point + line->direction, 0, 1);
  if (const auto* circle = std::get_if<StepCircle>(&curve)) return circle_arc(circle->frame, circle->radius, 0, turn);
  if (const auto* ellipse = std::get_if<StepEllipse>(&curve))
    return ellipse_arc(ellipse->frame, ellipse->semi_axis_1, ellipse->semi_axis_2, 0, turn);
  return std::get<NurbsCurve>(curve);
}

}  // namespace cadnurbs::step
