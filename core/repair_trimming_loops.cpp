#include "core/repair_trimming_loops.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/clip_loop_to_domain.hpp"
#include "core/geometry_error.hpp"
#include "core/loop_self_crossing.hpp"
#include "core/number_format.hpp"
#include "core/polygon_2d.hpp"

namespace cadnurbs {

namespace {

// Excursions up to this share of the domain are round-off (1e-16 is common): repaired without a word.
constexpr double kRoundOff = 1e-12;
// A loop crosses itself only where its chords cross by more than this share of the domain (slivers of
// real files touch themselves within round-off).
constexpr double kCrossingTolerance = 1e-9;
// A loop that crosses itself is repaired by cutting off the lobe on one side of the crossing when that
// lobe bounds at most this share of the other's area (an edge that curls round on itself: up to 0.03 on
// KiCad's Bourns toroids, where OpenCASCADE's area of the face agrees with the rest to 4e-5); a larger one
// is refused. At most kMaxLobeCuts lobes per loop.
constexpr double kLobeShare = 1e-1;
constexpr int kMaxLobeCuts = 8;

// The domain box (clip_loop_to_domain's DomainBox) with the measures the repairs use.
struct Domain : DomainBox {
  double du() const { return u1 - u0; }
  double dv() const { return v1 - v0; }
  // How far p lies outside, as a share of the domain's size in that direction (0 inside).
  double outside(const Eigen::Vector2d& p) const {
    const double eu = std::max({u0 - p.x(), p.x() - u1, 0.0}) / du();
    const double ev = std::max({v0 - p.y(), p.y() - v1, 0.0}) / dv();
    return std::max(eu, ev);
  }
  Eigen::Vector2d clamped(const Eigen::Vector2d& p) const {
    return {std::clamp(p.x(), u0, u1), std::clamp(p.y(), v0, v1)};
  }
};

// The points that define a segment (2D control points or polyline points), x and y only.
template <class Visit>
void for_each_defining_point(TrimSegment& segment, Visit&& visit) {
  if (auto* c = std::get_if<NurbsCurve>(&segment)) {
    for (auto& p : c->points) {
      Eigen::Vector2d q = p.head<2>();
      visit(q);
      p.head<2>() = q;
    }
  } else {
    for (auto& p : std::get<Polyline2D>(segment).points) visit(p);
  }
}

// Whether the surface's first and last rows of control points in u (or v) coincide, weights too: a clamped
// surface then joins itself there, and a point a whole domain width away in that direction means the
// same point (a periodic surface converted to a clamped one).
bool joins_itself(const NurbsSurface& s, bool in_u) {
  const int rows = in_u ? s.v_count : s.u_count, last = (in_u ? s.u_count : s.v_count) - 1;
  if (last < 1 || s.points.empty()) return false;
  Eigen::Vector3d lo = s.points.front(), hi = lo;
  for (const auto& p : s.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double tolerance = 1e-9 * std::max((hi - lo).norm(), 1e-300);
  for (int r = 0; r < rows; ++r) {
    const int i0 = in_u ? 0 : r, j0 = in_u ? r : 0, i1 = in_u ? last : r, j1 = in_u ? r : last;
    if ((s.point(i0, j0) - s.point(i1, j1)).norm() > tolerance) return false;
    if (std::abs(s.weight(i0, j0) - s.weight(i1, j1)) > 1e-12 * s.weight(i0, j0)) return false;
  }
  return true;
}

// The whole periods (domain widths) by which to move a loop whose sampled points are `polygon` so that it
// lies in the domain (within kDomainSlack), in each direction where the surface joins itself; none when
// no such move brings it in.
std::optional<Eigen::Vector2d> period_shift(const NurbsSurface& s, const Domain& domain,
                                           const std::vector<Eigen::Vector2d>& polygon) {
  Eigen::Vector2d lo = polygon.front(), hi = lo;
  for (const auto& p : polygon) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  Eigen::Vector2d shift(0, 0);
  for (int axis = 0; axis < 2; ++axis) {
    const double start = axis == 0 ? domain.u0 : domain.v0, width = axis == 0 ? domain.du() : domain.dv();
    const double periods = std::floor((lo[axis] - start + kDomainSlack * width) / width);
    if (periods != 0 && joins_itself(s, axis == 0)) shift[axis] = -periods * width;
  }
  if (shift == Eigen::Vector2d::Zero()) return std::nullopt;
  for (const auto& p : polygon)
    if (domain.outside(p + shift) > kDomainSlack) return std::nullopt;
  return shift;
}

std::string periods_text(const Eigen::Vector2d& shift, const Domain& domain) {
  std::string text;
  if (shift.x() != 0) text += message_number(-shift.x() / domain.du()) + " in u";
  if (shift.y() != 0) text += std::string(text.empty() ? "" : " and ") + message_number(-shift.y() / domain.dv()) + " in v";
  return text;
}

// A polynomial bilinear patch (a plane, as readers write planes) extends exactly beyond its domain:
// widens the domain to the box of every loop's defining points (which holds the loops: convex hull).
// True when it widened it.
bool widen_bilinear_domain(TrimmedSurface& face) {
  NurbsSurface& s = face.surface;
  if (s.u_order != 2 || s.v_order != 2 || s.u_count != 2 || s.v_count != 2 || s.is_rational()) return false;
  Eigen::Vector2d lo(s.u_start(), s.v_start()), hi(s.u_end(), s.v_end());
  const Eigen::Vector2d lo0 = lo, hi0 = hi;
  for (auto& loop : face.loops)
    for (auto& segment : loop.segments)
      for_each_defining_point(segment, [&](Eigen::Vector2d& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); });
  if (lo == lo0 && hi == hi0) return false;
  auto at = [&](double u, double v) {
    const double a = (u - lo0.x()) / (hi0.x() - lo0.x()), b = (v - lo0.y()) / (hi0.y() - lo0.y());
    return Eigen::Vector3d((1 - a) * (1 - b) * s.point(0, 0) + a * (1 - b) * s.point(1, 0) +
                           (1 - a) * b * s.point(0, 1) + a * b * s.point(1, 1));
  };
  s.points = {at(lo.x(), lo.y()), at(hi.x(), lo.y()), at(lo.x(), hi.y()), at(hi.x(), hi.y())};
  s.u_knots = {lo.x(), lo.x(), hi.x(), hi.x()};
  s.v_knots = {lo.y(), lo.y(), hi.y(), hi.y()};
  return true;
}

void repair_node(SceneNode& node, const std::string& path, LoopsOutsideDomain outside, std::vector<std::string>& done) {
  std::vector<Shape> kept;
  for (size_t i = 0; i < node.shapes.size(); ++i) {
    Shape& shape = node.shapes[i];
    if (auto* face = std::get_if<TrimmedSurface>(&shape.geometry)) {
      const std::string entity =
          path + "/" + (display_name(shape).empty() ? "shape " + std::to_string(i) : display_name(shape));
      try {
        for (const auto& line : repair_trimming_loops(*face, entity, outside)) done.push_back(entity + ": " + line);
      } catch (const FaceWithoutArea& e) {
        done.push_back(std::string(e.what()) + ": dropped");
        continue;
      } catch (const GeometryError& e) {  // one bad face never costs the file: the rest converts
        done.push_back(std::string(e.what()) + ": face left out");
        continue;
      }
    }
    kept.push_back(std::move(shape));
  }
  node.shapes = std::move(kept);
  for (size_t i = 0; i < node.children.size(); ++i) {
    SceneNode& child = node.children[i];
    repair_node(child, path + "/" + (display_name(child).empty() ? "node " + std::to_string(i) : display_name(child)),
                outside, done);
  }
}

}  // namespace

std::vector<std::string> repair_trimming_loops(Scene& scene, LoopsOutsideDomain outside) {
  std::vector<std::string> done;
  repair_node(scene.root, display_name(scene.root).empty() ? "scene" : display_name(scene.root), outside, done);
  return done;
}

std::vector<std::string> repair_trimming_loops(TrimmedSurface& face, const std::string& entity,
                                               LoopsOutsideDomain outside) {
  std::vector<std::string> done;
  if (face.loops.empty()) return done;
  // Each loop is sampled once here (16 points per span) and again only where points were moved.
  std::vector<std::vector<Eigen::Vector2d>> polygons;
  for (const auto& loop : face.loops) polygons.push_back(loop_polygon(loop));
  const NurbsSurface& s = face.surface;
  const Domain before{{s.u_start(), s.u_end(), s.v_start(), s.v_end()}};
  auto excursion = [](const Domain& domain, const std::vector<Eigen::Vector2d>& polygon) {
    double out = 0;
    for (const auto& p : polygon) out = std::max(out, domain.outside(p));
    return out;
  };
  double outside_before = 0;
  for (const auto& polygon : polygons) outside_before = std::max(outside_before, excursion(before, polygon));
  if (outside_before > 0 && widen_bilinear_domain(face) && outside_before > kRoundOff)
    done.push_back("trimming loops left the bilinear patch's domain by " + message_number(outside_before) +
                   " of its size: domain widened (the patch extends exactly)");
  const Domain domain{{s.u_start(), s.u_end(), s.v_start(), s.v_end()}};
  const double domain_area = domain.du() * domain.dv();

  // Loops that bound no area go first: they are dropped whatever else is wrong with them.
  std::vector<TrimLoop> kept;
  std::vector<std::vector<Eigen::Vector2d>> kept_polygons;
  for (size_t k = 0; k < face.loops.size(); ++k) {
    if (std::abs(polygon_signed_area(polygons[k])) <= 1e-12 * domain_area) {
      done.push_back("trimming loop " + std::to_string(k) + " bounds no area: dropped");
      continue;
    }
    kept.push_back(std::move(face.loops[k]));
    kept_polygons.push_back(std::move(polygons[k]));
  }
  if (kept.empty()) throw FaceWithoutArea(entity, "every trimming loop bounds no area: the face has no area");

  // Loops far outside the domain: moved back by whole periods where the surface joins itself (a seam
  // written elsewhere, a periodic surface's loop a period away), else cut to the domain as GLU draws them.
  {
    std::vector<TrimLoop> placed;
    std::vector<std::vector<Eigen::Vector2d>> placed_polygons;
    for (size_t k = 0; k < kept.size(); ++k) {
      const double out = excursion(domain, kept_polygons[k]);
      if (out <= kDomainSlack) {
        placed.push_back(std::move(kept[k]));
        placed_polygons.push_back(std::move(kept_polygons[k]));
        continue;
      }
      if (const auto shift = period_shift(s, domain, kept_polygons[k])) {
        for (auto& segment : kept[k].segments) for_each_defining_point(segment, [&](Eigen::Vector2d& p) { p += *shift; });
        for (auto& p : kept_polygons[k]) p += *shift;
        done.push_back("trimming loop " + std::to_string(k) + " lay whole periods off the domain (" +
                       periods_text(*shift, domain) + ") on a surface that joins itself there: moved back");
        placed.push_back(std::move(kept[k]));
        placed_polygons.push_back(std::move(kept_polygons[k]));
        continue;
      }
      if (outside == LoopsOutsideDomain::refuse)
        throw GeometryError(entity, "trimming loop " + std::to_string(k) + " leaves the surface's domain by " +
                                        message_number(out) + " of its size (more than " +
                                        message_number(kDomainSlack) + " cannot be moved onto it)");
      const std::vector<TrimLoop> clipped = clip_loop_to_domain(kept[k], domain);
      done.push_back("trimming loop " + std::to_string(k) + " leaves the surface's domain by " + message_number(out) +
                     " of its size: cut to the domain, as GLU-based viewers draw it (" +
                     (clipped.empty() ? std::string("nothing of it is inside: dropped")
                                      : std::to_string(clipped.size()) + (clipped.size() == 1 ? " loop" : " loops") + " left") +
                     ")");
      for (const TrimLoop& loop : clipped) {
        placed.push_back(loop);
        placed_polygons.push_back(loop_polygon(loop));
      }
    }
    kept = std::move(placed);
    kept_polygons = std::move(placed_polygons);
    if (kept.empty()) throw FaceWithoutArea(entity, "no trimming loop meets the surface's domain: the face has no area");
  }

  for (size_t k = 0; k < kept.size(); ++k) {
    TrimLoop& loop = kept[k];
    std::vector<Eigen::Vector2d>& polygon = kept_polygons[k];
    const double sampled = excursion(domain, polygon);
    if (sampled > 0) {
      // First only points about as far out as the curve: a control point further out may belong to a
      // curve that stays inside there (an arc's control polygon near the edge).
      auto clamp_points = [&](double limit) {
        int moved = 0;
        for (auto& segment : loop.segments)
          for_each_defining_point(segment, [&](Eigen::Vector2d& p) {
            const double e = domain.outside(p);
            if (e > 0 && e <= limit) p = domain.clamped(p), ++moved;
          });
        return moved;
      };
      const std::vector<Eigen::Vector2d> original = polygon;
      int moved = clamp_points(std::max(2 * sampled, kRoundOff));
      polygon = loop_polygon(loop);
      double left = excursion(domain, polygon);
      // Then every point out by up to kDomainSlack, kept only if the loop moves by little more than
      // it left the domain (in units of the domain's size).
      if (left > kRoundOff) {
        const TrimLoop first = loop;
        const int more = clamp_points(kDomainSlack);
        std::vector<Eigen::Vector2d> now = loop_polygon(loop);
        double shift = 0;
        for (size_t i = 0; i < now.size(); ++i)
          shift = std::max(shift, std::max(std::abs(now[i].x() - original[i].x()) / domain.du(),
                                           std::abs(now[i].y() - original[i].y()) / domain.dv()));
        if (shift <= 2 * sampled + kRoundOff) {
          moved += more;
          polygon = std::move(now);
          left = excursion(domain, polygon);
        } else {
          loop = first;
        }
      }
      if (sampled > kRoundOff)
        done.push_back("trimming loop " + std::to_string(k) + " left the surface's domain by " + message_number(sampled) +
                       " of its size: " + std::to_string(moved) + " points moved onto the domain's edge" +
                       (left > kRoundOff ? " (" + message_number(left) + " still outside)" : ""));
    }
    // A crossing of the 16-per-span chords may be the chords' own (two pieces of the loop passing close
    // by): only one that stays at 128 per span counts. A small lobe on one side of it is cut off.
    const double tolerance = kCrossingTolerance * std::max(domain.du(), domain.dv());
    for (int cuts = 0; polygon_crosses_itself(polygon, tolerance); ++cuts) {
      const auto crossing = find_self_crossing(loop, 128, tolerance);
      if (!crossing) break;
      const double between = std::abs(crossing->between_area), outer = std::abs(crossing->outer_area);
      const double lobe = std::min(between, outer), rest = std::max(between, outer);
      if (cuts == kMaxLobeCuts || !(lobe <= kLobeShare * rest))
        throw GeometryError(entity, "trimming loop " + std::to_string(k) + " crosses itself (its smaller lobe bounds " +
                                        message_number(lobe / rest) + " of the larger's area; lobes up to " +
                                        message_number(kLobeShare) + " are cut off" +
                                        (cuts ? ", " + std::to_string(cuts) + " were" : "") + ")");
      loop = cut_lobe(loop, *crossing, between < outer ? KeptLobe::outer : KeptLobe::between);
      polygon = loop_polygon(loop);
      done.push_back("trimming loop " + std::to_string(k) + " crossed itself at (" + message_number(crossing->point.x()) +
                     ", " + message_number(crossing->point.y()) + "): a lobe of " + message_number(lobe / rest) +
                     " of its area cut off");
    }
  }
  face.loops = std::move(kept);
  return done;
}

}  // namespace cadnurbs
