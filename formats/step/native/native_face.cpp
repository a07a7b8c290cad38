#include "formats/step/native/native_face.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "core/analytic_surface.hpp"
#include "core/arc_parameterization.hpp"
#include "core/fit_trim_curve.hpp"
#include "core/geometry_error.hpp"
#include "core/loop_closure.hpp"
#include "core/loop_orientation.hpp"
#include "core/mirror_in_u.hpp"
#include "core/nearest_surface_point.hpp"
#include "core/number_format.hpp"

namespace cadnurbs::step {

namespace {

constexpr double kTurn = 2 * std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

[[noreturn]] void refuse(const std::string& reason) { throw GeometryError("face", reason); }

// Parameters at which an edge's path is sampled: evenly inside every knot span, enough for its degree.
std::vector<double> sample_parameters(const NurbsCurve& path) {
  const int per_span = path.order == 2 ? 2 : 2 * path.order;
  std::vector<double> out;
  for (std::size_t k = static_cast<std::size_t>(path.order - 1); k < path.points.size(); ++k) {
    const double a = path.knots[k], b = path.knots[k + 1];
    if (!(b > a)) continue;
    for (int i = 0; i < per_span; ++i) out.push_back(a + (b - a) * i / per_span);
  }
  out.push_back(path.domain_end());
  return out;
}

// One use of an edge in a loop, sampled and located in the surface's natural parameters.
struct UseSamples {
  EdgeUse use;
  std::vector<double> t;            // path parameters, in the use's direction
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> natural;
  double offset = 0;  // largest distance of a sample from the surface point it was located at
};

// The face's surface before its NURBS exists: natural parameters, how to locate points, which are angles.
class Chart {
 public:
  explicit Chart(const StepSurface& surface) {
    if (const auto* analytic = std::get_if<AnalyticSurface>(&surface)) {
      analytic_ = analytic;
      angular_ = angular_directions(*analytic);
      if (const auto* sphere = std::get_if<SphereSurface>(analytic)) axis_ = {sphere->frame.origin, sphere->frame.z};
      if (const auto* cone = std::get_if<ConeSurface>(analytic)) axis_ = {cone->frame.origin, cone->frame.z};
      if (const auto* revolution = std::get_if<RevolutionSurface>(analytic)) {
        axis_ = {revolution->axis_point, revolution->axis_direction};
        set_closed_profile(1, revolution->profile);
      }
      if (const auto* extrusion = std::get_if<ExtrusionSurface>(analytic)) set_closed_profile(0, extrusion->profile);
    } else {
      nurbs_ = &std::get<NurbsSurface>(surface);
    }
  }

  bool angular(int d) const { return angular_[d]; }
  // The period of natural parameter d: a turn for an angle, the profile's domain for a closed profile's
  // parameter (an extruded or revolved circle); none otherwise.
  std::optional<double> period(int d) const {
    if (angular_[d]) return kTurn;
    if (closed_[d]) return closed_[d]->second - closed_[d]->first;
    return std::nullopt;
  }
  // A closed profile's parameter range, [start, end].
  const std::optional<std::pair<double, double>>& closed_profile(int d) const { return closed_[d]; }
  const NurbsSurface* nurbs() const { return nurbs_; }

  // Angles and closed profiles' parameters unwrapped to lie within half a period of near's.
  // On a NURBS surface, where Newton from `near` ends farther than `relocate_above` from p: again from
  // `ahead` (optional), then by the global search.
  Eigen::Vector2d locate(const Eigen::Vector3d& p, const std::optional<Eigen::Vector2d>& near,
                         const std::optional<Eigen::Vector2d>& ahead = std::nullopt,
                         double relocate_above = std::numeric_limits<double>::infinity()) const {
    if (!analytic_) return locate_on_nurbs(p, near, ahead, relocate_above);
    if (!near || (!closed_[0] && !closed_[1])) return natural_inverse(*analytic_, p, near);
    Eigen::Vector2d uv = natural_inverse(*analytic_, p, wrapped(*near));
    for (int d = 0; d < 2; ++d)
      if (closed_[d]) uv[d] += *period(d) * std::round(((*near)[d] - uv[d]) / *period(d));
    return uv;
  }
  Eigen::Vector3d point(const Eigen::Vector2d& natural) const {
    return analytic_ ? natural_point(*analytic_, wrapped(natural)) : surface_point(*nurbs_, natural.x(), natural.y());
  }
  // Whether p is on the axis of revolution, where the angle means nothing (a pole, an apex).
  bool at_axis(const Eigen::Vector3d& p, double size) const {
    if (!axis_) return false;
    const Eigen::Vector3d r = p - axis_->first;
    return (r - r.dot(axis_->second) * axis_->second).norm() <= 1e-9 * (size + r.norm());
  }

  // The NURBS parameters, once the angular ranges are fixed.
  void set_arcs(const std::array<std::optional<ArcSpans>, 2>& arcs) { arcs_ = arcs; }
  Eigen::Vector2d to_nurbs(const Eigen::Vector2d& natural) const {
    Eigen::Vector2d out = natural;
    for (int d = 0; d < 2; ++d)
      if (arcs_[d]) out[d] = arc_parameter(*arcs_[d], std::clamp(natural[d], arcs_[d]->start, arcs_[d]->end));
    return out;
  }
  Eigen::Vector2d to_natural(const Eigen::Vector2d& uv) const {
    Eigen::Vector2d out = uv;
    for (int d = 0; d < 2; ++d)
      if (arcs_[d]) out[d] = arc_angle(*arcs_[d], std::clamp(uv[d], arcs_[d]->start, arcs_[d]->end));
    return out;
  }

 private:
  // Newton from the previous sample can stop on a crease of the surface (a knot of full multiplicity:
  // capping-moulded.step's profile corners, where the derivative on one side points away from the point):
  // from the sample before extrapolated past it, then from the global search, the nearest result is taken.
  Eigen::Vector2d locate_on_nurbs(const Eigen::Vector3d& p, const std::optional<Eigen::Vector2d>& near,
                                  const std::optional<Eigen::Vector2d>& ahead, double relocate_above) const {
    if (!near) return nearest_surface_parameter(*nurbs_, p);
    Eigen::Vector2d best = nearest_surface_parameter(*nurbs_, p, *near);
    double off = (surface_point(*nurbs_, best.x(), best.y()) - p).norm();
    auto try_from = [&](const Eigen::Vector2d& uv) {
      const double d = (surface_point(*nurbs_, uv.x(), uv.y()) - p).norm();
      if (d < off) best = uv, off = d;
    };
    if (off > relocate_above && ahead) try_from(nearest_surface_parameter(*nurbs_, p, *ahead));
    if (off > relocate_above) try_from(nearest_surface_parameter(*nurbs_, p));
    return best;
  }
  void set_closed_profile(int d, const NurbsCurve& profile) {
    const double a = profile.domain_start(), b = profile.domain_end();
    const Eigen::Vector3d start = curve_point(profile, a), end = curve_point(profile, b);
    double extent = 0;
    for (const auto& q : profile.points) extent = std::max(extent, (q - start).norm());
    if ((end - start).norm() <= 1e-9 * extent) closed_[d] = {a, b};
  }
  // Closed profiles' parameters moved by whole periods into [start, end].
  Eigen::Vector2d wrapped(Eigen::Vector2d natural) const {
    for (int d = 0; d < 2; ++d) {
      if (!closed_[d]) continue;
      const auto [a, b] = *closed_[d];
      if (natural[d] < a || natural[d] > b) natural[d] -= (b - a) * std::floor((natural[d] - a) / (b - a));
    }
    return natural;
  }

  const AnalyticSurface* analytic_ = nullptr;
  const NurbsSurface* nurbs_ = nullptr;
  std::array<bool, 2> angular_{false, false};
  std::array<std::optional<std::pair<double, double>>, 2> closed_;
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> axis_;  // point, unit direction
  std::array<std::optional<ArcSpans>, 2> arcs_;
};

// The loop's uses sampled and located, angles continuous along the loop. Where the loop passes a pole its
// angle is free, so the rest of the loop is moved by whole turns until the loop closes.
std::vector<UseSamples> locate_loop(const StepBound& bound, const std::vector<StepEdge>& edges, const Chart& chart,
                                    double size) {
  std::vector<UseSamples> out;
  std::optional<Eigen::Vector2d> previous;
  std::vector<std::size_t> after_pole;  // uses that start right after a pole
  for (const EdgeUse& use : bound.uses) {
    const NurbsCurve& path = edges[static_cast<std::size_t>(use.edge)].path;
    UseSamples s;
    s.use = use;
    s.t = sample_parameters(path);
    if (!use.forward) std::reverse(s.t.begin(), s.t.end());
    for (double t : s.t) {
      s.points.push_back(curve_point(path, t));
      const std::size_t n = s.natural.size();
      const std::optional<Eigen::Vector2d> ahead =
          n >= 2 ? std::optional<Eigen::Vector2d>(2.0 * s.natural[n - 1] - s.natural[n - 2]) : std::nullopt;
      // Located again only where it matters: a tenth of the offset refused below (goteborg.step's edges lie
      // off their faces by up to 0.015 mm, and every sample located again took twice the time).
      const Eigen::Vector2d uv =
          chart.locate(s.points.back(), s.natural.empty() ? previous : s.natural.back(), ahead, 1e-4 * (size + 1.0));
      s.natural.push_back(uv);
    }
    // Samples on the axis take the angle of their nearest neighbour off it.
    std::vector<bool> pole(s.points.size());
    bool any_off = false;
    for (std::size_t i = 0; i < pole.size(); ++i) any_off |= !(pole[i] = chart.at_axis(s.points[i], size));
    if (!any_off && pole.size() > 0 && pole[0]) refuse("an edge lies wholly on the axis of revolution");
    for (std::size_t i = 0; i < pole.size(); ++i) {
      if (!pole[i]) continue;
      std::size_t j = i;
      while (j < pole.size() && pole[j]) ++j;
      if (j == pole.size()) {
        j = i;
        while (pole[j]) --j;
      }
      s.natural[i].x() = s.natural[j].x();
    }
    for (std::size_t i = 0; i < s.points.size(); ++i)
      s.offset = std::max(s.offset, (chart.point(s.natural[i]) - s.points[i]).norm());
    if (s.offset > 1e-3 * (size + 1.0))
      refuse("an edge lies " + message_number(s.offset) + " mm off the surface");
    if (pole.front()) after_pole.push_back(out.size());
    previous = s.natural.back();
    out.push_back(std::move(s));
  }
  for (int d = 0; d < 2; ++d) {
    if (!chart.period(d)) continue;
    const double period = *chart.period(d);
    const double gap = out.back().natural.back()[d] - out.front().natural.front()[d];
    const double turns = std::round(gap / period);
    if (turns == 0) continue;
    if (std::abs(gap - turns * period) > 1e-6 * period) continue;  // not a whole turn: the closing gap is checked later
    if (after_pole.empty())
      refuse("a loop wraps " + message_number(turns) + " times around the surface without closing (no seam edge)");
    if (after_pole.front() == 0) continue;  // it starts at a pole: the closing joint is the pole's bridge
    for (std::size_t k = after_pole.front(); k < out.size(); ++k)
      for (auto& uv : out[k].natural) uv[d] -= turns * period;
  }
  return out;
}


// Moves each loop by whole periods in the periodic directions so that it lies beside the reference loop
// (the outer bound): all loops of a face within one period. A closed profile's parameter is then moved
// into the profile's range (the surface's NURBS is the profile cut to the loops' range).
void gather_loops(std::vector<std::vector<UseSamples>>& loops, std::size_t reference, const Chart& chart) {
  for (int d = 0; d < 2; ++d) {
    if (!chart.period(d)) continue;
    const double period = *chart.period(d);
    auto centre = [&](const std::vector<UseSamples>& loop) {
      double lo = kInfinity, hi = -kInfinity;
      for (const auto& use : loop)
        for (const auto& uv : use.natural) lo = std::min(lo, uv[d]), hi = std::max(hi, uv[d]);
      return 0.5 * (lo + hi);
    };
    const double target = centre(loops[reference]);
    for (auto& loop : loops) {
      const double turns = std::round((centre(loop) - target) / period);
      if (turns != 0)
        for (auto& use : loop)
          for (auto& uv : use.natural) uv[d] -= turns * period;
    }
    if (!chart.closed_profile(d)) continue;
    const auto [start, end] = *chart.closed_profile(d);
    double lo = kInfinity, hi = -kInfinity;
    for (const auto& loop : loops)
      for (const auto& use : loop)
        for (const auto& uv : use.natural) lo = std::min(lo, uv[d]), hi = std::max(hi, uv[d]);
    const double slack = 1e-9 * period;
    const double shift = period * std::floor((lo - start + slack) / period);
    if (hi - shift > end + slack)
      refuse("its loops cross the start of its closed profile (" + message_number(lo - shift) + " to " +
             message_number(hi - shift) + ", the profile " + message_number(start) + " to " + message_number(end) + ")");
    for (auto& loop : loops)
      for (auto& use : loop)
        for (auto& uv : use.natural) uv[d] = std::clamp(uv[d] - shift, start, end);
  }
}

// Whether the use's samples keep parameter d (an iso-curve of the surface).
bool keeps(const UseSamples& use, int d, double scale) {
  double lo = kInfinity, hi = -kInfinity;
  for (const auto& uv : use.natural) lo = std::min(lo, uv[d]), hi = std::max(hi, uv[d]);
  return hi - lo <= 1e-9 * std::max(1.0, scale);
}

NurbsCurve segment_2d(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  NurbsCurve out;
  out.dimension = 2;
  out.order = 2;
  out.knots = {0, 0, 1, 1};
  out.points = {Eigen::Vector3d(from.x(), from.y(), 0), Eigen::Vector3d(to.x(), to.y(), 0)};
  return out;
}

// An affine chart of a plane: (u, v) = uv0 + ((p - origin) . du, (p - origin) . dv), du and dv the dual
// basis of the plane's parameter directions (a point off the plane is projected along its normal).
struct AffineChart {
  Eigen::Vector3d origin, du, dv;
  Eigen::Vector2d uv0 = Eigen::Vector2d::Zero();
  Eigen::Vector2d operator()(const Eigen::Vector3d& p) const { return uv0 + Eigen::Vector2d((p - origin).dot(du), (p - origin).dot(dv)); }
};

// A polynomial bilinear B-spline patch (2 x 2 control points) whose net is a parallelogram (within 1e-12
// of its size) is an affine map of the plane: its chart, if so (STEP writers' flat faces, dm1-id-214's
// QUASI_UNIFORM_SURFACEs).
std::optional<AffineChart> affine_chart(const NurbsSurface& s) {
  if (s.u_order != 2 || s.v_order != 2 || s.u_count != 2 || s.v_count != 2) return std::nullopt;
  if (s.is_rational() && (s.weights[1] != s.weights[0] || s.weights[2] != s.weights[0] || s.weights[3] != s.weights[0]))
    return std::nullopt;
  const Eigen::Vector3d p00 = s.points[static_cast<std::size_t>(s.index(0, 0))], p10 = s.points[static_cast<std::size_t>(s.index(1, 0))];
  const Eigen::Vector3d p01 = s.points[static_cast<std::size_t>(s.index(0, 1))], p11 = s.points[static_cast<std::size_t>(s.index(1, 1))];
  const double du = s.u_end() - s.u_start(), dv = s.v_end() - s.v_start();
  const Eigen::Vector3d a = (p10 - p00) / du, b = (p01 - p00) / dv;
  const double size = std::max((p11 - p00).norm(), (p10 - p01).norm());
  if (!(a.cross(b).norm() > 0) || (p11 - p10 - p01 + p00).norm() > 1e-12 * size) return std::nullopt;
  // The dual basis in the plane: du . a = 1, du . b = 0, and likewise dv.
  Eigen::Matrix2d gram;
  gram << a.dot(a), a.dot(b), a.dot(b), b.dot(b);
  const Eigen::Matrix2d inverse = gram.inverse();
  AffineChart chart{p00, inverse(0, 0) * a + inverse(0, 1) * b, inverse(1, 0) * a + inverse(1, 1) * b};
  chart.uv0 = Eigen::Vector2d(s.u_start(), s.v_start());
  return chart;
}

// The edge's path in an affine chart: exact (an affine map keeps a NURBS a NURBS).
NurbsCurve affine_pcurve(const NurbsCurve& path, const AffineChart& chart, bool forward) {
  NurbsCurve out = forward ? path : reversed(path);
  out.dimension = 2;
  for (auto& p : out.points) {
    const Eigen::Vector2d uv = chart(p);
    p = Eigen::Vector3d(uv.x(), uv.y(), 0);
  }
  return out;
}

// Closes the joints of a loop: moves ends together where they nearly meet, bridges a gap that is one point
// in 3D (a pole) with a straight segment.
TrimLoop close_loop(TrimLoop loop, const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& point,
                    double domain_size, double tolerance) {
  std::vector<std::pair<std::size_t, Polyline2D>> bridges;
  const std::size_t n = loop.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = (i + 1) % n;
    const Eigen::Vector2d end = segment_end(loop.segments[i]), start = segment_start(loop.segments[next]);
    const double gap = (end - start).norm();
    if (gap == 0.0) continue;
    const double distance = (point(end) - point(start)).norm();
    // Ends a little apart in (u, v) and one point in 3D: moved together (an angle clamped to a full turn,
    // an edge a little off its face).
    if (gap <= 1e-4 * domain_size && distance <= tolerance) {
      join_segments(loop.segments[i], loop.segments[next]);
      continue;
    }
    for (int k = 0; k <= 8; ++k)
      if ((point(end + (start - end) * (k / 8.0)) - point(end)).norm() > tolerance)
        refuse("its loop does not close: a gap of " + message_number(distance) + " mm between two edges");
    bridges.emplace_back(i, Polyline2D{{end, start}});
  }
  for (auto it = bridges.rbegin(); it != bridges.rend(); ++it) {
    loop.segments.insert(loop.segments.begin() + static_cast<long>(it->first) + 1, it->second);
    loop.edges.insert(loop.edges.begin() + static_cast<long>(it->first) + 1, TrimEdgeRef{});
  }
  return loop;
}

std::size_t reference_bound(const StepFace& face) {
  for (std::size_t b = 0; b < face.bounds.size(); ++b)
    if (face.bounds[b].outer) return b;
  return 0;
}

// A face on a plane, or on a B-spline patch that is an affine map of one: every trimming curve exact.
// `patch`: the B-spline patch the face lies on; none for a plane, whose NURBS is made over the loops' box.
TrimmedSurface affine_face(const StepFace& face, const AffineChart& chart, const std::vector<StepEdge>& edges,
                           double tolerance, const NurbsSurface* patch) {
  TrimmedSurface out;
  Eigen::AlignedBox2d box;
  for (const auto& bound : face.bounds) {
    TrimLoop loop;
    for (const auto& use : bound.uses) {
      NurbsCurve curve = affine_pcurve(edges[static_cast<std::size_t>(use.edge)].path, chart, use.forward);
      for (const auto& p : curve.points) box.extend(Eigen::Vector2d(p.x(), p.y()));
      loop.segments.emplace_back(std::move(curve));
      loop.edges.push_back({use.edge, !use.forward});
    }
    out.loops.push_back(std::move(loop));
  }
  if (box.isEmpty() || !(box.sizes().minCoeff() > 0)) refuse("its loops bound no area in its plane");
  if (patch) {
    out.surface = *patch;
  } else {
    const PlaneSurface plane{axis_frame(chart.origin, chart.du.cross(chart.dv), chart.du, "plane")};
    out.surface = analytic_to_nurbs(AnalyticSurface{plane}, {box.min().x(), box.max().x(), box.min().y(), box.max().y()}).surface;
  }
  const TrimmedSurface& result = out;
  const auto point = [&](const Eigen::Vector2d& uv) { return surface_point(result.surface, uv.x(), uv.y()); };
  for (auto& loop : out.loops) loop = close_loop(std::move(loop), point, box.sizes().maxCoeff(), tolerance);
  return out;
}

}  // namespace

double face_size(const StepFace& face, const std::vector<StepEdge>& edges) {
  Eigen::AlignedBox3d box;
  for (const auto& bound : face.bounds)
    for (const auto& use : bound.uses)
      for (const auto& p : edges[static_cast<std::size_t>(use.edge)].path.points) box.extend(p);
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

TrimmedSurface native_face(const StepFace& face, const std::vector<StepEdge>& edges, double fit_tolerance) {
  if (face.bounds.empty()) refuse("a face without bounds");
  const double size = face_size(face, edges);
  TrimmedSurface out;
  const auto* analytic = std::get_if<AnalyticSurface>(&face.surface);
  const auto* patch = std::get_if<NurbsSurface>(&face.surface);
  const std::optional<AffineChart> flat_patch = patch ? affine_chart(*patch) : std::nullopt;
  if (analytic && std::holds_alternative<PlaneSurface>(*analytic)) {
    const AxisFrame& frame = std::get<PlaneSurface>(*analytic).frame;
    out = affine_face(face, AffineChart{frame.origin, frame.x, frame.y}, edges, fit_tolerance, nullptr);
  } else if (flat_patch) {
    out = affine_face(face, *flat_patch, edges, fit_tolerance, patch);
  } else {
    Chart chart(face.surface);
    std::vector<std::vector<UseSamples>> loops;
    for (const auto& bound : face.bounds) loops.push_back(locate_loop(bound, edges, chart, size));
    gather_loops(loops, reference_bound(face), chart);

    // The natural box of the samples; angles padded a little (curves bulge between samples), within a turn.
    std::array<double, 2> lo{kInfinity, kInfinity}, hi{-kInfinity, -kInfinity};
    for (const auto& loop : loops)
      for (const auto& use : loop)
        for (const auto& uv : use.natural)
          for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], uv[d]), hi[d] = std::max(hi[d], uv[d]);
    std::array<std::optional<ArcSpans>, 2> arcs;
    const bool sphere = analytic && std::holds_alternative<SphereSurface>(*analytic);
    if (analytic) {
      for (int d = 0; d < 2; ++d) {
        if (!chart.angular(d)) continue;
        // A full turn measured from samples may exceed 2 pi by the round-off of the located angles, or by an
        // edge's offset from its face (a torus's seam 3e-6 mm off it in KiCad's axial inductors: 1e-5 rad).
        if (hi[d] - lo[d] > kTurn + 1e-4)
          refuse(std::string("its loops span more than one turn in ") + (d == 0 ? "u" : "v") + " (" +
                 message_number(lo[d]) + " to " + message_number(hi[d]) + " rad)");
        hi[d] = std::min(hi[d], lo[d] + kTurn);
        const double extent = hi[d] - lo[d];
        double pad = std::min(1e-3 * extent, 0.5 * std::max(0.0, kTurn - extent));
        double a = lo[d] - pad, b = hi[d] + pad;
        if (sphere && d == 1) a = std::max(a, -0.5 * std::numbers::pi), b = std::min(b, 0.5 * std::numbers::pi);
        if (!(b > a)) refuse("its loops bound no area");
        arcs[d] = arc_spans(a, b);
      }
      chart.set_arcs(arcs);
    }
    const auto point = [&](const Eigen::Vector2d& uv) { return chart.point(chart.to_natural(uv)); };
    const auto locate = [&](const Eigen::Vector3d& p, const Eigen::Vector2d& previous) {
      return chart.to_nurbs(chart.locate(p, chart.to_natural(previous)));
    };

    // On a B-spline the located points lie in its domain; so must the fitted curves (see fit_trim_curve).
    std::optional<Eigen::AlignedBox2d> domain;
    if (patch)
      domain = Eigen::AlignedBox2d(Eigen::Vector2d(patch->u_start(), patch->v_start()),
                                   Eigen::Vector2d(patch->u_end(), patch->v_end()));
    Eigen::AlignedBox2d uv_box;
    for (const auto& loop : loops) {
      TrimLoop trim;
      for (const auto& use : loop) {
        const Eigen::Vector2d a = chart.to_nurbs(use.natural.front()), b = chart.to_nurbs(use.natural.back());
        NurbsCurve curve;
        bool iso = false;
        for (int d = 0; d < 2 && !iso; ++d) {
          if (!keeps(use, d, chart.angular(d) ? 1.0 : hi[d] - lo[d])) continue;
          // An iso-curve: the straight segment between its ends, the kept parameter exactly the same.
          Eigen::Vector2d from = a, to = b;
          to[d] = from[d];
          curve = segment_2d(from, to);
          iso = true;
        }
        if (!iso) {
          const NurbsCurve& path = edges[static_cast<std::size_t>(use.use.edge)].path;
          const double t0 = use.use.forward ? path.domain_start() : path.domain_end();
          const double t1 = use.use.forward ? path.domain_end() : path.domain_start();
          // The edge may lie off the surface by the file's precision: the fit follows its projection.
          // Where the file's edge is off its surface by more, a hundredth of that is the precision that
          // means anything (KiCad's QFP parts: 6e-4 mm off faces 0.1 mm across).
          const double tolerance = std::max(fit_tolerance, 0.01 * use.offset);
          // The offset varies along the edge; between our samples it may be larger (a torus seam 3e-6 mm
          // off its face): the fit refuses only points farther off than any edge a file keeps.
          const double off_surface = 4 * use.offset + 1e-4 * size + tolerance;
          curve = fit_trim_curve(path, t0, t1, a, locate, point, tolerance, off_surface, domain).curve;
        }
        for (const auto& p : curve.points) uv_box.extend(Eigen::Vector2d(p.x(), p.y()));
        trim.segments.emplace_back(std::move(curve));
        trim.edges.push_back({use.use.edge, !use.use.forward});
      }
      out.loops.push_back(std::move(trim));
    }
    if (analytic) {
      // Non-angular parameters are the natural ones: the box is the trimming curves' hull (exact cover).
      NaturalBox box{uv_box.min().x(), uv_box.max().x(), uv_box.min().y(), uv_box.max().y()};
      if (arcs[0]) box.u0 = arcs[0]->start, box.u1 = arcs[0]->end;
      if (arcs[1]) box.v0 = arcs[1]->start, box.v1 = arcs[1]->end;
      // A closed profile is cut to the loops' range, which lies in its own (gather_loops).
      if (const auto& range = chart.closed_profile(0)) box.u0 = std::max(box.u0, range->first), box.u1 = std::min(box.u1, range->second);
      if (const auto& range = chart.closed_profile(1)) box.v0 = std::max(box.v0, range->first), box.v1 = std::min(box.v1, range->second);
      if (!(box.u1 > box.u0) || !(box.v1 > box.v0)) refuse("its loops bound no area");
      out.surface = analytic_to_nurbs(*analytic, box).surface;
    } else {
      out.surface = *chart.nurbs();
    }
    const double domain_size =
        std::max(out.surface.u_end() - out.surface.u_start(), out.surface.v_end() - out.surface.v_start());
    double offset = 0;
    for (const auto& loop : loops)
      for (const auto& use : loop) offset = std::max(offset, use.offset);
    for (auto& loop : out.loops)
      loop = close_loop(std::move(loop), point, domain_size, fit_tolerance + 4 * offset + 1e-6 * size);
  }
  if (!face.same_sense) mirror_in_u(out);
  orient_loops(out.loops);
  validate(out, "face");
  return out;
}

}  // namespace cadnurbs::step
