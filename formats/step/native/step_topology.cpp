#include "formats/step/native/step_topology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/conic_curves.hpp"
#include "core/geometry_error.hpp"
#include "core/number_format.hpp"
#include "core/nearest_curve_parameter.hpp"
#include "core/split_curve.hpp"

namespace cadnurbs::step {

namespace {

// How far a vertex may lie from its edge's curve unsaid: files keep vertices within their edges'
// tolerance, not exactly on the curve (KiCad's QFP parts by 6e-4 mm at an uncertainty of 1e-5); the path
// is then snapped to them.
double vertex_tolerance(const NurbsCurve& curve) {
  double size = 0;
  for (const auto& p : curve.points) size = std::max(size, (p - curve.points.front()).norm());
  return 1e-3 * (size + 1.0);
}

}  // namespace

namespace {

constexpr double kTurn = 2 * std::numbers::pi;
// A vertex may be moved onto, said, up to this share of the file's size (the default deviation's share).
constexpr double kFileShare = 1e-3;

// The curve over [t0, t1] of its domain (t0 < t1), cut exactly.
NurbsCurve piece(const NurbsCurve& curve, double t0, double t1) {
  NurbsCurve out = curve;
  const double a = curve.domain_start(), b = curve.domain_end(), eps = 1e-12 * (b - a);
  if (t0 > a + eps) out = split_curve(out, t0).second;
  if (t1 < b - eps) out = split_curve(out, t1).first;
  return out;
}

// The angle of a point in the conic's frame, the ellipse's axes scaled to a circle.
double conic_angle(const AxisFrame& frame, double rx, double ry, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = to_local(frame, p);
  return std::atan2(local.y() / ry, local.x() / rx);
}

}  // namespace

int TopologyReader::edge(EntityId edge_curve) {
  if (auto found = edge_index_.find(edge_curve); found != edge_index_.end()) return found->second;
  const part21::Model& m = context_.model;
  StepEdge out = reading(context_, edge_curve, [&] {
    const auto& r = context_.record(edge_curve, context_.types.edge_curve, "an EDGE_CURVE");
    auto vertex = [&](std::size_t k) {
      const EntityId v = m.parameter(r, k).reference();
      const auto& vr = context_.record(v, context_.types.vertex_point, "a VERTEX_POINT");
      return std::pair{v, read_point(context_, m.parameter(vr, 1).reference())};
    };
    const auto [v1, p1] = vertex(1);
    const auto [v2, p2] = vertex(2);
    StepEdge e;
    e.entity = edge_curve;
    e.curve = read_curve(context_, m.parameter(r, 3).reference());
    e.start = p1;
    e.end = p2;
    const bool same_sense = m.parameter(r, 4).boolean();
    const bool closed = v1 == v2 || p1 == p2;
    try {
      if (std::holds_alternative<StepLine>(e.curve)) {
        if (closed) context_.refuse(edge_curve, "a closed edge on a line");
        e.path = line_segment(p1, p2, 0, (p2 - p1).norm());
      } else if (std::holds_alternative<StepCircle>(e.curve) || std::holds_alternative<StepEllipse>(e.curve)) {
        const auto* circle = std::get_if<StepCircle>(&e.curve);
        const auto* ellipse = std::get_if<StepEllipse>(&e.curve);
        const AxisFrame& frame = circle ? circle->frame : ellipse->frame;
        const double rx = circle ? circle->radius : ellipse->semi_axis_1, ry = circle ? circle->radius : ellipse->semi_axis_2;
        const double a1 = conic_angle(frame, rx, ry, p1);
        double a2 = conic_angle(frame, rx, ry, p2);
        // Along the curve's sense from v1 to v2 (or back, against it): a full turn when the edge is closed.
        if (same_sense) {
          while (a2 <= a1 + (closed ? kTurn * 0.5 : 0.0)) a2 += kTurn;
          if (closed) a2 = a1 + kTurn;
        } else {
          while (a2 >= a1 - (closed ? kTurn * 0.5 : 0.0)) a2 -= kTurn;
          if (closed) a2 = a1 - kTurn;
        }
        const double lo = std::min(a1, a2), hi = std::max(a1, a2);
        e.path = circle ? circle_arc(frame, rx, lo, hi) : ellipse_arc(frame, rx, ry, lo, hi);
        if (!same_sense) e.path = reversed(e.path);
      } else {
        const NurbsCurve& curve = std::get<NurbsCurve>(e.curve);
        const double a = curve.domain_start(), b = curve.domain_end();
        double t1 = nearest_curve_parameter(curve, p1), t2 = nearest_curve_parameter(curve, p2);
        if (closed) {
          // A closed curve: the whole of it, from the end at the vertex.
          if (std::abs(t1 - a) > 1e-9 * (b - a) && std::abs(t1 - b) > 1e-9 * (b - a))
            context_.refuse(edge_curve, "a closed edge whose vertex is not at its curve's ends");
          t1 = same_sense ? a : b;
          t2 = same_sense ? b : a;
        }
        if (!closed && (same_sense ? !(t2 > t1) : !(t1 > t2))) {
          // The curve passes a vertex more than once (KiCad's Bourns toroids: a wire's curve with a small
          // loop, both vertices near both passes): the passes in the edge's sense nearest their vertices.
          const double within = vertex_tolerance(curve);
          double best = std::numeric_limits<double>::infinity();
          for (double c1 : curve_parameters_near(curve, p1, within))
            for (double c2 : curve_parameters_near(curve, p2, within)) {
              if (same_sense ? !(c2 > c1) : !(c1 > c2)) continue;
              const double off = std::max((curve_point(curve, c1) - p1).norm(), (curve_point(curve, c2) - p2).norm());
              if (off < best) best = off, t1 = c1, t2 = c2;
            }
        }
        if (same_sense ? !(t2 > t1) : !(t1 > t2)) context_.refuse(edge_curve, "its vertices run against its curve's sense");
        e.path = piece(curve, std::min(t1, t2), std::max(t1, t2));
        if (!same_sense) e.path = reversed(e.path);
      }
    } catch (const GeometryError& error) {
      context_.refuse(edge_curve, error.reason());
    }
    // The vertices must lie on the curve: they are where it is cut.
    const Eigen::Vector3d q1 = curve_point(e.path, e.path.domain_start()), q2 = curve_point(e.path, e.path.domain_end());
    // Farther than the edge's tolerance, up to the file's (KiCad's Bourns toroids: a winding's vertex
    // 0.017 mm off its curve's small loop in a 42 mm part), the move is said.
    const double tolerance = vertex_tolerance(e.path);
    const double off = std::max((q1 - p1).norm(), (q2 - p2).norm());
    if (off > tolerance) {
      // The file's size only where needed: one more pass over its points.
      if (!points_size_) points_size_ = cartesian_points_size(context_);
      if (!(off <= kFileShare * *points_size_ * context_.millimetres))
        context_.refuse(edge_curve, "a vertex " + message_number(off) + " mm from its curve");
      e.vertex_moved = off;
    }
    // The path runs exactly through the vertices (their points, not the curve's rounding of them).
    e.path.points.front() = p1;
    e.path.points.back() = p2;
    return e;
  });
  const int index = static_cast<int>(edges_.size());
  edges_.push_back(std::move(out));
  edge_index_.emplace(edge_curve, index);
  return index;
}

StepFace TopologyReader::face(EntityId advanced_face) {
  const part21::Model& m = context_.model;
  const auto& t = context_.types;
  return reading(context_, advanced_face, [&] {
    const auto& r = context_.record(advanced_face, t.advanced_face, "an ADVANCED_FACE");
    StepFace out;
    out.entity = advanced_face;
    out.surface_entity = m.parameter(r, 2).reference();
    out.surface = read_surface(context_, out.surface_entity);
    out.same_sense = m.parameter(r, 3).boolean();
    const part21::Value bounds = m.parameter(r, 1);
    for (std::size_t b = 0; b < bounds.size(); ++b) {
      const EntityId bound = bounds.item(b).reference();
      const bool outer = context_.is(bound, t.face_outer_bound);
      const auto& br = outer ? *m.record(bound, t.face_outer_bound) : context_.record(bound, t.face_bound, "a FACE_BOUND");
      const EntityId loop = m.parameter(br, 1).reference();
      const bool orientation = m.parameter(br, 2).boolean();
      if (context_.is(loop, t.vertex_loop)) continue;  // a point: trims nothing
      const auto& lr = context_.record(loop, t.edge_loop, "an EDGE_LOOP");
      StepBound out_bound;
      out_bound.outer = outer;
      out_bound.entity = bound;
      const part21::Value list = m.parameter(lr, 1);
      for (std::size_t k = 0; k < list.size(); ++k) {
        const EntityId oriented = list.item(k).reference();
        const auto& orr = context_.record(oriented, t.oriented_edge, "an ORIENTED_EDGE");
        const EntityId element = m.parameter(orr, 3).reference();
        out_bound.uses.push_back({edge(element), m.parameter(orr, 4).boolean()});
      }
      if (out_bound.uses.empty()) context_.refuse(loop, "an edge loop without edges");
      if (!orientation) {
        std::reverse(out_bound.uses.begin(), out_bound.uses.end());
        for (auto& use : out_bound.uses) use.forward = !use.forward;
      }
      out.bounds.push_back(std::move(out_bound));
    }
    return out;
  });
}

std::vector<EntityId> TopologyReader::shell_faces(EntityId shell) const {
  const part21::Model& m = context_.model;
  const auto& t = context_.types;
  return reading(context_, shell, [&] {
    if (context_.is(shell, t.oriented_closed_shell)) {
      // Its faces are the closed shell's; the orientation flips the solid's inside out (a void).
      const auto& r = *m.record(shell, t.oriented_closed_shell);
      if (!m.parameter(r, 3).boolean()) context_.refuse(shell, "a reversed shell (a void) is not read natively");
      return shell_faces(m.parameter(r, 2).reference());
    }
    const part21::Record* r = context_.is(shell, t.closed_shell) ? m.record(shell, t.closed_shell)
                              : context_.is(shell, t.open_shell) ? m.record(shell, t.open_shell)
                                                                 : nullptr;
    if (!r) context_.refuse(shell, "expected a CLOSED_SHELL or OPEN_SHELL");
    std::vector<EntityId> faces;
    const part21::Value list = m.parameter(*r, 1);
    for (std::size_t k = 0; k < list.size(); ++k) faces.push_back(list.item(k).reference());
    return faces;
  });
}

}  // namespace cadnurbs::step
