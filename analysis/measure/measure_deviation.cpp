#include "analysis/measure/measure_deviation.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "analysis/eval/point_inversion.hpp"
#include "analysis/mesh/sample_triangles.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/mesh/triangulate_polygon.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"
#include "core/point_in_loops.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {

namespace {

using K = CGAL::Simple_cartesian<double>;
using TriangleIt = std::vector<K::Triangle_3>::const_iterator;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, TriangleIt>>>;
using SegmentIt = std::vector<K::Segment_3>::const_iterator;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, SegmentIt>>>;

K::Point_3 cg(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }
Eigen::Vector3d eg(const K::Point_3& p) { return {p.x(), p.y(), p.z()}; }

struct MeasuredFace {
  TrimmedSurface trimmed;  // in world coordinates
  std::unique_ptr<SurfaceEvaluator> eval;
  std::unique_ptr<PointInLoops> region;
  // Domain start, C0 knots, domain end, per direction: the surface is smooth between two of them and
  // may have a crease on each inner one.
  std::vector<double> u_smooth, v_smooth;
};

// Domain start, the C0 knots, domain end.
std::vector<double> smooth_pieces(const std::vector<double>& knots, int order, int count) {
  std::vector<double> out{knots[order - 1]};
  for (double k : c0_knots(knots, order, count)) out.push_back(k);
  out.push_back(knots[count]);
  return out;
}

// Which piece [pieces[i], pieces[i + 1]] holds x; a value on an inner break is in both pieces beside it:
// `lower` picks the one before it, else the one after.
size_t piece_of(const std::vector<double>& pieces, double x, bool lower = false) {
  const auto after = lower ? std::lower_bound(pieces.begin() + 1, pieces.end() - 1, x)
                           : std::upper_bound(pieces.begin() + 1, pieces.end() - 1, x);
  return static_cast<size_t>(after - pieces.begin()) - 1;
}

// The pieces from the one holding lo to the one holding hi (both sides of a break included), at most
// `reach` on either side of piece `around`.
std::pair<size_t, size_t> pieces_between(const std::vector<double>& pieces, double lo, double hi, size_t around,
                                         size_t reach) {
  const size_t first = piece_of(pieces, lo, true), last = piece_of(pieces, hi);
  return {std::max(first, around > reach ? around - reach : 0), std::min(last, around + reach)};
}

// x brought into piece i, a hair inside it so the surface is evaluated on that side of a crease.
double into_piece(const std::vector<double>& pieces, size_t i, double x) {
  const double hair = 1e-9 * (pieces[i + 1] - pieces[i]);
  return std::clamp(x, pieces[i] + hair, pieces[i + 1] - hair);
}

// A reference triangle: which face, and the (u,v) of its corners.
struct ReferenceTriangle {
  int face;
  Eigen::Vector2d uv[3];
};

// A boundary piece: face, loop, segment and the parameter range of the chord.
struct BoundaryPiece {
  int face, loop, segment;
  double t0, t1;
};

// Grid parameters of one direction: each knot span in steps about `spacing` long in 3D.
std::vector<double> grid(const SurfaceEvaluator& e, bool along_u, double spacing, int cap) {
  const NurbsSurface& s = e.surface();
  const auto& knots = along_u ? s.u_knots : s.v_knots;
  const int order = along_u ? s.u_order : s.v_order, count = along_u ? s.u_count : s.v_count;
  const std::vector<double> b = domain_breaks(knots, order, count);
  const double o0 = along_u ? s.v_start() : s.u_start(), o1 = along_u ? s.v_end() : s.u_end();
  std::vector<double> out{b.front()};
  for (size_t i = 0; i + 1 < b.size(); ++i) {
    double longest = 0, turning = 0;
    for (int k = 0; k <= 4; ++k) {
      const double other = o0 + (o1 - o0) * k / 4;
      double len = 0, angle = 0;
      Eigen::Vector3d prev, prev_step = Eigen::Vector3d::Zero();
      for (int m = 0; m <= 8; ++m) {
        const double x = b[i] + (b[i + 1] - b[i]) * m / 8;
        const Eigen::Vector3d p = along_u ? e.point(x, other) : e.point(other, x);
        if (m > 0) {
          const Eigen::Vector3d step = p - prev;
          len += step.norm();
          if (step.norm() > 0 && prev_step.norm() > 0)
            angle += std::acos(std::clamp(step.normalized().dot(prev_step.normalized()), -1.0, 1.0));
          if (step.norm() > 0) prev_step = step;
        }
        prev = p;
      }
      longest = std::max(longest, len);
      turning = std::max(turning, angle);
    }
    // Steps of at most `spacing` and of at most 1/32 turn: the reference triangles (every second
    // line) then stay close enough to the surface to start Newton near the right foot.
    const int by_length = static_cast<int>(std::ceil(longest / spacing));
    const int by_turning = static_cast<int>(std::ceil(turning / (M_PI / 16)));
    const int n = std::clamp(std::max(by_length, by_turning), 1, cap);
    for (int m = 1; m < n; ++m) out.push_back(b[i] + (b[i + 1] - b[i]) * m / n);
    out.push_back(b[i + 1]);
  }
  return out;
}

// Loops as dense (u,v) polygons with the segment and parameter of every point.
struct DenseLoop {
  std::vector<Eigen::Vector2d> uv;
  std::vector<std::pair<int, double>> at;  // segment, t
};

// Every knot span (polyline piece) of every segment in pieces about `spacing` long in 3D.
std::vector<DenseLoop> dense_loops(const TrimmedSurface& t, const SurfaceEvaluator& e, double spacing) {
  std::vector<DenseLoop> out;
  for (const auto& loop : t.loops) {
    DenseLoop d;
    for (size_t k = 0; k < loop.segments.size(); ++k) {
      const TrimSegment& seg = loop.segments[k];
      const auto breaks = segment_breaks(seg);
      for (size_t i = 0; i + 1 < breaks.size(); ++i) {
        double length = 0;
        Eigen::Vector3d prev = Eigen::Vector3d::Zero();
        for (int m = 0; m <= 8; ++m) {
          const Eigen::Vector2d uv = segment_uv(seg, breaks[i] + (breaks[i + 1] - breaks[i]) * m / 8);
          const Eigen::Vector3d p = e.point(uv.x(), uv.y());
          if (m > 0) length += (p - prev).norm();
          prev = p;
        }
        const int per = std::clamp(static_cast<int>(std::ceil(length / spacing)), 8, 4000);
        for (int m = 0; m < per; ++m) {
          const double tt = breaks[i] + (breaks[i + 1] - breaks[i]) * m / per;
          d.uv.push_back(segment_uv(seg, tt));
          d.at.emplace_back(static_cast<int>(k), tt);
        }
      }
    }
    out.push_back(std::move(d));
  }
  return out;
}

class Measurer {
 public:
  Measurer(const TriangleMesh& mesh, std::vector<TrimmedSurface> surfaces, const DeviationOptions& options)
      : mesh_(mesh) {
    if (mesh.triangles.empty()) throw GeometryError("measure_deviation", "the mesh has no triangles");
    spacing_ = options.spacing > 0 ? options.spacing : default_sample_spacing(mesh);
    for (size_t i = 0; i < surfaces.size(); ++i) {
      validate(surfaces[i], "surface " + std::to_string(i));
      auto f = std::make_unique<MeasuredFace>();
      f->trimmed = std::move(surfaces[i]);
      f->eval = std::make_unique<SurfaceEvaluator>(f->trimmed.surface);
      const NurbsSurface& surface = f->trimmed.surface;
      f->u_smooth = smooth_pieces(surface.u_knots, surface.u_order, surface.u_count);
      f->v_smooth = smooth_pieces(surface.v_knots, surface.v_order, surface.v_count);
      faces_.push_back(std::move(f));
    }
    build_references();
    for (const auto& t : mesh.triangles) {
      const K::Triangle_3 tri(cg(mesh.positions[t[0]]), cg(mesh.positions[t[1]]), cg(mesh.positions[t[2]]));
      if (!tri.is_degenerate()) mesh_triangles_.push_back(tri);
    }
    if (mesh_triangles_.empty()) throw GeometryError("measure_deviation", "every triangle of the mesh is degenerate");
    mesh_tree_.insert(mesh_triangles_.begin(), mesh_triangles_.end());
    mesh_tree_.accelerate_distance_queries();
    // CGAL builds trees lazily: one query of each before they are shared by threads.
    mesh_tree_.closest_point(cg(mesh.positions[0]));
    reference_tree_.closest_point(cg(mesh.positions[0]));
    if (!boundary_segments_.empty()) boundary_tree_.closest_point(cg(mesh.positions[0]));
  }

  DeviationMeasure run() {
    DeviationMeasure out;
    double sum_a = 0, sum_b = 0;
    // Mesh -> surface: corners once, then each triangle's lattice without its corners.
    const std::vector<Eigen::Vector3d> points = sample_triangles(mesh_, spacing_);
    for (double d : in_parallel(points, [this](const Eigen::Vector3d& p) { return to_surface(p); }))
      add(out.mesh_to_surface, sum_a, d);
    // Surface -> mesh.
    for (double d : in_parallel(surface_samples_, [this](const Eigen::Vector3d& p) { return to_mesh(p); }))
      add(out.surface_to_mesh, sum_b, d);
    finish(out.mesh_to_surface, sum_a);
    finish(out.surface_to_mesh, sum_b);
    out.overall.samples = out.mesh_to_surface.samples + out.surface_to_mesh.samples;
    out.overall.max = std::max(out.mesh_to_surface.max, out.surface_to_mesh.max);
    out.overall.rms = out.overall.samples ? std::sqrt((sum_a + sum_b) / out.overall.samples) : 0.0;
    return out;
  }

 private:
  const TriangleMesh& mesh_;
  double spacing_;
  std::vector<std::unique_ptr<MeasuredFace>> faces_;
  std::vector<K::Triangle_3> reference_triangles_;
  std::vector<ReferenceTriangle> reference_info_;
  TriangleTree reference_tree_;
  // Per face: its reference triangles' tree and box, for the search that goes on past the nearest face.
  std::vector<std::unique_ptr<TriangleTree>> face_trees_;
  std::vector<Eigen::AlignedBox3d> face_boxes_;
  std::vector<K::Segment_3> boundary_segments_;
  std::vector<BoundaryPiece> boundary_info_;
  SegmentTree boundary_tree_;
  std::vector<Eigen::Vector3d> surface_samples_;
  std::vector<K::Triangle_3> mesh_triangles_;
  TriangleTree mesh_tree_;

  // f over all points on every hardware thread (the trees are only read).
  template <class F>
  static std::vector<double> in_parallel(const std::vector<Eigen::Vector3d>& points, F f) {
    std::vector<double> out(points.size());
    const size_t threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (size_t t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        for (size_t i = t; i < points.size(); i += threads) out[i] = f(points[i]);
      });
    for (auto& th : pool) th.join();
    return out;
  }

  static void add(DeviationStats& s, double& sum, double d) {
    s.max = std::max(s.max, d);
    sum += d * d;
    ++s.samples;
  }
  static void finish(DeviationStats& s, double sum) { s.rms = s.samples ? std::sqrt(sum / s.samples) : 0.0; }

  void build_references() {
    std::vector<std::pair<size_t, size_t>> face_ranges;  // reference triangles of each face
    for (size_t fi = 0; fi < faces_.size(); ++fi) {
      MeasuredFace& f = *faces_[fi];
      const SurfaceEvaluator& e = *f.eval;
      const size_t first_triangle = reference_triangles_.size();
      const auto loops = dense_loops(f.trimmed, e, spacing_);
      std::vector<std::vector<Eigen::Vector2d>> polys;
      for (const auto& l : loops) polys.push_back(l.uv);
      f.region = std::make_unique<PointInLoops>(polys);
      // Dense grid: surface samples; every second line: the reference triangulation.
      const auto us = grid(e, true, spacing_, 2000), vs = grid(e, false, spacing_, 2000);
      std::vector<Eigen::Vector2d> coarse;
      for (size_t j = 0; j < vs.size(); ++j)
        for (size_t i = 0; i < us.size(); ++i) {
          const Eigen::Vector2d uv(us[i], vs[j]);
          if (!f.region->inside(uv)) continue;
          surface_samples_.push_back(e.point(uv.x(), uv.y()));
          const bool ci = i % 2 == 0 || i + 1 == us.size(), cj = j % 2 == 0 || j + 1 == vs.size();
          if (ci && cj) coarse.push_back(uv);
        }
      std::vector<std::vector<Eigen::Vector2d>> ref_loops = polys;
      if (ref_loops.empty()) {
        ref_loops.push_back({{e.u_start(), e.v_start()}, {e.u_end(), e.v_start()}, {e.u_end(), e.v_end()}, {e.u_start(), e.v_end()}});
        for (double u : us) surface_samples_.push_back(e.point(u, e.v_start())), surface_samples_.push_back(e.point(u, e.v_end()));
        for (double v : vs) surface_samples_.push_back(e.point(e.u_start(), v)), surface_samples_.push_back(e.point(e.u_end(), v));
      }
      const PlanarTriangulation cdt = reference_triangulation(e, ref_loops, std::move(coarse));
      for (const auto& t : cdt.triangles) {
        const K::Triangle_3 tri(cg(e.point(cdt.points[t[0]].x(), cdt.points[t[0]].y())),
                                cg(e.point(cdt.points[t[1]].x(), cdt.points[t[1]].y())),
                                cg(e.point(cdt.points[t[2]].x(), cdt.points[t[2]].y())));
        if (tri.is_degenerate()) continue;
        reference_triangles_.push_back(tri);
        reference_info_.push_back({static_cast<int>(fi), {cdt.points[t[0]], cdt.points[t[1]], cdt.points[t[2]]}});
      }
      face_ranges.emplace_back(first_triangle, reference_triangles_.size());
      // Boundary: every dense loop chord, and the loop points as surface samples.
      for (size_t l = 0; l < loops.size(); ++l) {
        const auto& d = loops[l];
        for (size_t k = 0; k < d.uv.size(); ++k) {
          const size_t n = (k + 1) % d.uv.size();
          const Eigen::Vector3d a = e.point(d.uv[k].x(), d.uv[k].y()), b = e.point(d.uv[n].x(), d.uv[n].y());
          surface_samples_.push_back(a);
          // Extra samples along long chords.
          const int extra = std::min(64, static_cast<int>((b - a).norm() / spacing_));
          const TrimSegment& seg = f.trimmed.loops[l].segments[d.at[k].first];
          const double t0 = d.at[k].second;
          const double t1 = d.at[n].first == d.at[k].first && d.at[n].second > t0 ? d.at[n].second : segment_t1(seg);
          for (int m = 1; m <= extra; ++m) {
            const Eigen::Vector2d uv = segment_uv(seg, t0 + (t1 - t0) * m / (extra + 1));
            surface_samples_.push_back(e.point(uv.x(), uv.y()));
          }
          if ((b - a).norm() == 0) continue;
          boundary_segments_.emplace_back(cg(a), cg(b));
          boundary_info_.push_back({static_cast<int>(fi), static_cast<int>(l), d.at[k].first, t0, t1});
        }
      }
    }
    if (reference_triangles_.empty()) throw GeometryError("measure_deviation", "the surfaces have no area");
    reference_tree_.insert(reference_triangles_.begin(), reference_triangles_.end());
    reference_tree_.accelerate_distance_queries();
    for (const auto& [first, last] : face_ranges) {
      Eigen::AlignedBox3d box;
      for (size_t i = first; i < last; ++i)
        for (int k = 0; k < 3; ++k) box.extend(eg(reference_triangles_[i][k]));
      face_boxes_.push_back(box);
      auto tree = std::make_unique<TriangleTree>();
      if (last > first) {
        tree->insert(reference_triangles_.begin() + static_cast<std::ptrdiff_t>(first),
                     reference_triangles_.begin() + static_cast<std::ptrdiff_t>(last));
        tree->accelerate_distance_queries();
        tree->closest_point(reference_triangles_[first][0]);  // built before threads share it
      }
      face_trees_.push_back(std::move(tree));
    }
    if (!boundary_segments_.empty()) {
      boundary_tree_.insert(boundary_segments_.begin(), boundary_segments_.end());
      boundary_tree_.accelerate_distance_queries();
    }
  }

  // The trimmed domain triangulated so that every triangle's centroid lies within a quarter of the
  // sample spacing of the surface: a reference triangle far below a curved surface (loop points
  // joined across a narrow cylinder face) would hide the face from the nearest-triangle search.
  PlanarTriangulation reference_triangulation(const SurfaceEvaluator& e,
                                              const std::vector<std::vector<Eigen::Vector2d>>& loops,
                                              std::vector<Eigen::Vector2d> interior) const {
    PlanarTriangulation cdt = triangulate_polygon(loops, interior);
    for (int round = 0; round < 8; ++round) {
      size_t added = 0;
      for (const auto& t : cdt.triangles) {
        const Eigen::Vector2d c = (cdt.points[t[0]] + cdt.points[t[1]] + cdt.points[t[2]]) / 3.0;
        Eigen::Vector3d chord = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) chord += e.point(cdt.points[t[k]].x(), cdt.points[t[k]].y()) / 3.0;
        if ((e.point(c.x(), c.y()) - chord).norm() > 0.25 * spacing_) interior.push_back(c), ++added;
      }
      if (added == 0) break;
      cdt = triangulate_polygon(loops, interior);
    }
    return cdt;
  }

  static Eigen::Vector3d barycentric(const K::Triangle_3& t, const Eigen::Vector3d& p) {
    const Eigen::Vector3d a = eg(t[0]), b = eg(t[1]), c = eg(t[2]);
    const Eigen::Vector3d v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1), d20 = v2.dot(v0), d21 = v2.dot(v1);
    const double den = d00 * d11 - d01 * d01;
    if (den == 0) return {1, 0, 0};
    const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
    return {1 - v - w, v, w};
  }

  double to_surface(const Eigen::Vector3d& p) const {
    const auto hit = reference_tree_.closest_point_and_primitive(cg(p));
    const double near = (eg(hit.first) - p).norm();
    double best = std::numeric_limits<double>::infinity();
    bool settled = false;
    project_from(p, static_cast<size_t>(hit.second - reference_triangles_.begin()), eg(hit.first), best, settled);
    if (settled) return best;
    // The projection ran into the edge of the domain (a seam: the foot is on the other side), out of
    // the trims, or to a farther foot: start again from the nearest reference triangle of every face
    // that may hold a nearer foot. Reference triangles lie within a quarter spacing of their surface
    // (reference_triangulation), so such a face's box is within this reach.
    const double reach = std::min(best, near + 0.5 * spacing_);
    for (size_t fi = 0; fi < faces_.size(); ++fi) {
      if (face_boxes_[fi].isEmpty() || face_boxes_[fi].exteriorDistance(p) > reach) continue;
      const auto face_hit = face_trees_[fi]->closest_point_and_primitive(cg(p));
      const size_t index = static_cast<size_t>(face_hit.second - reference_triangles_.begin());
      bool face_settled = false;
      project_from(p, index, eg(face_hit.first), best, face_settled);
    }
    return boundary_segments_.empty() ? best : std::min(best, to_boundary(p));
  }

  // Newton from the (u,v) of `near` on reference triangle `index`.
  // A reference triangle across a crease (a C0 knot line: a profile's corner) is a chord over it: the
  // (u,v) of `near` may lie on the far side, where Newton can only reach that side's own foot
  // (capping-post: 2.67 mm off the arc of a cove for a point 0.26 mm off the flat beside it). So
  // Newton also starts in every smooth piece the triangle touches (a few on either side at most).
  void project_from(const Eigen::Vector3d& p, size_t index, const Eigen::Vector3d& near, double& best,
                    bool& settled) const {
    const ReferenceTriangle& r = reference_info_[index];
    const Eigen::Vector3d l = barycentric(reference_triangles_[index], near);
    const Eigen::Vector2d start = l[0] * r.uv[0] + l[1] * r.uv[1] + l[2] * r.uv[2];
    const MeasuredFace& f = *faces_[r.face];
    newton_from(p, f, start, near, best, settled);
    const size_t start_i = piece_of(f.u_smooth, start.x()), start_j = piece_of(f.v_smooth, start.y());
    const auto us = pieces_between(f.u_smooth, std::min({r.uv[0].x(), r.uv[1].x(), r.uv[2].x()}),
                                   std::max({r.uv[0].x(), r.uv[1].x(), r.uv[2].x()}), start_i, 3);
    const auto vs = pieces_between(f.v_smooth, std::min({r.uv[0].y(), r.uv[1].y(), r.uv[2].y()}),
                                   std::max({r.uv[0].y(), r.uv[1].y(), r.uv[2].y()}), start_j, 3);
    for (size_t i = us.first; i <= us.second; ++i)
      for (size_t j = vs.first; j <= vs.second; ++j)
        if (i != start_i || j != start_j)
          newton_from(p, f, {into_piece(f.u_smooth, i, start.x()), into_piece(f.v_smooth, j, start.y())}, near, best,
                      settled);
  }

  // One Newton run from `start`; a foot inside the trims and away from the domain's edge settles the answer.
  void newton_from(const Eigen::Vector3d& p, const MeasuredFace& f, const Eigen::Vector2d& start,
                   const Eigen::Vector3d& near, double& best, bool& settled) const {
    const SurfaceEvaluator& e = *f.eval;
    // The start is a surface point too: every candidate inside the trims bounds the distance.
    const double start_distance = (e.point(start.x(), start.y()) - p).norm();
    if (f.region->inside(start)) best = std::min(best, start_distance);
    const SurfaceProjection proj = project_to_surface(e, p, start);
    if (!f.region->inside(proj.uv)) return;
    best = std::min(best, proj.distance);
    // Settled only when the foot is no farther than the reference triangle: otherwise Newton may
    // have gone to another foot (a coarse reference triangle, a torus), and the search goes on.
    if (proj.distance > 1.01 * (near - p).norm()) return;
    const bool on_edge = proj.uv.x() <= e.u_start() || proj.uv.x() >= e.u_end() || proj.uv.y() <= e.v_start() ||
                         proj.uv.y() >= e.v_end();
    if (!on_edge) settled = true;
  }

  double to_boundary(const Eigen::Vector3d& p) const {
    const auto hit = boundary_tree_.closest_point_and_primitive(cg(p));
    const size_t index = static_cast<size_t>(hit.second - boundary_segments_.begin());
    const BoundaryPiece& b = boundary_info_[index];
    const Eigen::Vector3d a = eg(hit.second->source()), c = eg(hit.second->target());
    const double len2 = (c - a).squaredNorm();
    const double s = len2 > 0 ? std::clamp((eg(hit.first) - a).dot(c - a) / len2, 0.0, 1.0) : 0.0;
    const MeasuredFace& f = *faces_[b.face];
    const TrimSegment& seg = f.trimmed.loops[b.loop].segments[b.segment];
    // The nearest boundary point may lie on a neighbouring chord: search the whole segment.
    const CurveProjection proj =
        project_to_trim_curve(*f.eval, seg, p, b.t0 + s * (b.t1 - b.t0), segment_t0(seg), segment_t1(seg));
    return proj.distance;
  }

  double to_mesh(const Eigen::Vector3d& p) const { return std::sqrt(mesh_tree_.squared_distance(cg(p))); }
};

TrimmedSurface placed(const TrimmedSurface& t, const Eigen::Affine3d& world) {
  TrimmedSurface out = t;
  for (auto& p : out.surface.points) p = world * p;
  return out;
}

}  // namespace

DeviationMeasure measure_deviation(const TriangleMesh& mesh, const TrimmedSurface& surface,
                                   const DeviationOptions& options) {
  return Measurer(mesh, {surface}, options).run();
}

DeviationMeasure measure_deviation(const TriangleMesh& mesh, const Scene& scene, const DeviationOptions& options) {
  std::vector<TrimmedSurface> surfaces;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) surfaces.push_back(placed(*t, world));
  });
  return Measurer(mesh, std::move(surfaces), options).run();
}

namespace {

// The triangles of every shape of `meshes`, in scene_triangles' order (fanned polygons included).
std::vector<std::size_t> triangles_per_shape(const Scene& meshes) {
  std::vector<std::size_t> counts;
  for_each_shape(meshes, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) { counts.push_back(shape_triangle_count(shape)); });
  return counts;
}

// Triangles [first, first + count) of `mesh` with only the positions they use.
TriangleMesh triangle_range(const TriangleMesh& mesh, std::size_t first, std::size_t count) {
  TriangleMesh out;
  std::vector<int> index(mesh.positions.size(), -1);
  for (std::size_t t = first; t < first + count; ++t) {
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k) {
      int& i = index[mesh.triangles[t][k]];
      if (i < 0) {
        i = static_cast<int>(out.positions.size());
        out.positions.push_back(mesh.positions[mesh.triangles[t][k]]);
      }
      corners[k] = i;
    }
    out.triangles.push_back(corners);
  }
  return out;
}

void add_stats(DeviationStats& total, double& squares, const DeviationStats& face) {
  total.max = std::max(total.max, face.max);
  squares += face.rms * face.rms * static_cast<double>(face.samples);
  total.samples += face.samples;
}

}  // namespace

DeviationMeasure measure_deviation_by_face(const TriangleMesh& mesh, const Scene& meshes, const Scene& faces,
                                           const DeviationOptions& options) {
  const std::vector<std::size_t> counts = triangles_per_shape(meshes);
  std::vector<std::optional<TrimmedSurface>> surfaces;
  for_each_shape(faces, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    const auto* t = std::get_if<TrimmedSurface>(&shape.geometry);
    surfaces.push_back(t ? std::optional<TrimmedSurface>(placed(*t, world)) : std::nullopt);
  });
  std::size_t total = 0;
  for (std::size_t c : counts) total += c;
  if (surfaces.size() != counts.size())
    throw GeometryError("measure", std::to_string(counts.size()) + " meshes for " + std::to_string(surfaces.size()) +
                                       " shapes: not a tessellation of these faces");
  if (total != mesh.triangles.size())
    throw GeometryError("measure", "the mesh has " + std::to_string(mesh.triangles.size()) + " triangles where the " +
                                       "tessellation has " + std::to_string(total));
  DeviationMeasure out;
  double squares[3] = {0, 0, 0};
  std::size_t first = 0;
  for (std::size_t k = 0; k < counts.size(); first += counts[k], ++k) {
    if (!surfaces[k] || counts[k] == 0) continue;
    const DeviationMeasure face = measure_deviation(triangle_range(mesh, first, counts[k]), *surfaces[k], options);
    add_stats(out.mesh_to_surface, squares[0], face.mesh_to_surface);
    add_stats(out.surface_to_mesh, squares[1], face.surface_to_mesh);
    add_stats(out.overall, squares[2], face.overall);
  }
  DeviationStats* stats[3] = {&out.mesh_to_surface, &out.surface_to_mesh, &out.overall};
  for (int i = 0; i < 3; ++i)
    if (stats[i]->samples > 0) stats[i]->rms = std::sqrt(squares[i] / static_cast<double>(stats[i]->samples));
  return out;
}

}  // namespace cadnurbs
