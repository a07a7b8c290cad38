#include "analysis/subd_nurbs/subd_to_nurbs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <numeric>
#include <optional>

#include "analysis/subd_nurbs/cubic_spline_fit.hpp"
#include "analysis/subd_nurbs/patch_deviation.hpp"
#include "analysis/subd_nurbs/rhino_limit_surface.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_insertion.hpp"
#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

using subd_nurbs::RhinoLimitSurface;
using Row = std::vector<Eigen::Vector3d>;

constexpr int kMaxLevel = 10;  // the smallest span 2^-10, OpenSubdiv's deepest isolation

// Corner c of a patch is where side c starts: (0,0), (1,0), (1,1), (0,1).
constexpr double kCornerUv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

// The point of side `side` at t in [0, 1], running counter-clockwise from corner `side`.
Eigen::Vector2d side_uv(int side, double t) {
  static constexpr double kStep[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  return {kCornerUv[side][0] + t * kStep[side][0], kCornerUv[side][1] + t * kStep[side][1]};
}

// Index of the k-th control point of side `side` (counter-clockwise) in a count x count grid.
int side_index(int side, int k, int count) {
  const int last = count - 1;
  switch (side) {
    case 0:
      return k;
    case 1:
      return last + count * k;
    case 2:
      return (last - k) + count * last;
    default:
      return count * (last - k);
  }
}

NurbsSurface bezier_of(const std::array<Eigen::Vector3d, 16>& bspline) {
  NurbsSurface s;
  s.u_order = s.v_order = 4;
  s.u_count = s.v_count = 4;
  s.u_knots = s.v_knots = {0, 0, 0, 0, 1, 1, 1, 1};
  const auto points = subd_nurbs::bicubic_bezier_points(bspline);
  s.points.assign(points.begin(), points.end());
  return s;
}

NurbsSurface fitted_surface(const std::vector<double>& knots) {
  NurbsSurface s;
  s.u_order = s.v_order = 4;
  s.u_count = s.v_count = static_cast<int>(knots.size()) - 4;
  s.u_knots = s.v_knots = knots;
  s.points.assign(static_cast<size_t>(s.u_count) * s.v_count, Eigen::Vector3d::Zero());
  return s;
}

Row side_row(const NurbsSurface& s, int side) {
  Row row(s.u_count);
  for (int k = 0; k < s.u_count; ++k) row[k] = s.points[side_index(side, k, s.u_count)];
  return row;
}

void set_side_row(NurbsSurface& s, int side, const Row& row) {
  for (int k = 0; k < s.u_count; ++k) s.points[side_index(side, k, s.u_count)] = row[k];
}

// A side curve (cubic) on knots `from` as the same curve on knots `to`, which hold every knot of `from`.
Row reknotted(const Row& points, const std::vector<double>& from, const std::vector<double>& to) {
  std::vector<double> extra;
  std::set_difference(to.begin() + 4, to.end() - 4, from.begin() + 4, from.end() - 4, std::back_inserter(extra));
  if (extra.empty()) return points;
  NurbsCurve curve;
  curve.order = 4;
  curve.knots = from;
  curve.points = points;
  Row row = refine_knots(curve, extra).points;
  row.front() = points.front();  // the corners stay the shared values, bit for bit
  row.back() = points.back();
  return row;
}

struct Sides {
  std::vector<std::array<int, 4>> number;     // per patch and side: edge number from 0
  std::vector<std::array<bool, 4>> reversed;  // the side runs against its edge (the owner's direction)
  std::vector<std::array<int, 2>> owner;      // per edge: (patch, side) whose direction it takes
};

Sides number_sides(const RhinoLimitSurface& limit) {
  Sides sides;
  const int patches = limit.patch_count();
  sides.number.assign(patches, {-1, -1, -1, -1});
  sides.reversed.assign(patches, {false, false, false, false});
  for (int p = 0; p < patches; ++p)
    for (int k = 0; k < 4; ++k) {
      if (sides.number[p][k] >= 0) continue;
      const int edge = static_cast<int>(sides.owner.size());
      sides.owner.push_back({p, k});
      sides.number[p][k] = edge;
      const auto other = limit.neighbour(p, k);
      if (other.patch >= 0 && !(other.patch == p && other.side == k)) {
        sides.number[other.patch][other.side] = edge;
        sides.reversed[other.patch][other.side] = true;
      }
    }
  return sides;
}

// One position per point of the net where patches meet (corners joined across shared sides), taken from the first patch
// corner there.
std::vector<std::array<Eigen::Vector3d, 4>> corner_positions(const RhinoLimitSurface& limit) {
  const int patches = limit.patch_count();
  UnionFind corners(4 * patches);
  for (int p = 0; p < patches; ++p)
    for (int c = 0; c < 4; ++c) {
      const auto other = limit.neighbour(p, c);  // side c starts at corner c; the neighbour's side ends there
      if (other.patch >= 0) corners.unite(4 * p + c, 4 * other.patch + (other.side + 1) % 4);
    }
  std::vector<Eigen::Vector3d> of_class(4 * patches);
  std::vector<bool> known(4 * patches, false);
  std::vector<std::array<Eigen::Vector3d, 4>> positions(patches);
  for (int p = 0; p < patches; ++p)
    for (int c = 0; c < 4; ++c) {
      const int root = corners.find(4 * p + c);
      if (!known[root]) {
        of_class[root] = limit.point(p, kCornerUv[c][0], kCornerUv[c][1]);
        known[root] = true;
      }
      positions[p][c] = of_class[root];
    }
  return positions;
}

}  // namespace

SubdNurbs subd_to_nurbs(const SubdControlNet& net, double deviation, int first_edge_number, const std::string& entity) {
  if (!(deviation > 0)) throw GeometryError(entity, "deviation must be > 0");
  const RhinoLimitSurface limit(net, entity);
  const int patches = limit.patch_count();
  const Sides sides = number_sides(limit);
  const auto corners = corner_positions(limit);
  const int edges = static_cast<int>(sides.owner.size());

  // Exact patches, their corners the shared values.
  std::vector<std::optional<NurbsSurface>> exact(patches);
  for (int p = 0; p < patches; ++p)
    if (const auto& pieces = limit.pieces(p); pieces.size() == 1 && pieces[0].bspline) {
      exact[p] = bezier_of(*pieces[0].bspline);
      for (int c = 0; c < 4; ++c) exact[p]->points[side_index(c, 0, 4)] = corners[p][c];
    }
  // Sides between exact patches: the owner's row in both, bit for bit.
  for (int e = 0; e < edges; ++e) {
    const auto [p, k] = sides.owner[e];
    const auto other = limit.neighbour(p, k);
    if (!exact[p] || other.patch < 0 || !exact[other.patch]) continue;
    Row row = side_row(*exact[p], k);
    std::reverse(row.begin(), row.end());
    set_side_row(*exact[other.patch], other.side, row);
  }

  // Levels: each fitted patch wants its own k, raised while it is not within D. A side between fitted patches
  // is fitted at the larger k of the two; a patch's knots are those of the largest k among itself and its
  // fitted neighbours, so every side it holds lies in its space (graded knots nest) and goes in by knot
  // insertion where its k is lower (the same curve to rounding; bit for bit where the k are equal).
  SubdNurbs result;
  // One knot family per SubD, so that every side nests in both its patches' knots.
  bool halved = false;
  for (int p = 0; p < patches; ++p) halved = halved || limit.follows_sector_coefficients(p);
  std::vector<NurbsSurface> fitted(patches);
  std::vector<int> wanted(patches, 1), level_of(patches, 0);
  auto fitted_neighbour = [&](int p, int k) {
    const int q = limit.neighbour(p, k).patch;
    return q >= 0 && !exact[q] ? q : -1;
  };
  while (std::any_of(exact.begin(), exact.end(), [](const auto& s) { return !s; })) {
    for (int p = 0; p < patches; ++p) {
      level_of[p] = wanted[p];
      for (int k = 0; k < 4; ++k)
        if (const int q = fitted_neighbour(p, k); q >= 0) level_of[p] = std::max(level_of[p], wanted[q]);
    }
    // Side curves of fitted patches, in their owner's direction, with their level (0: an exact patch's
    // Bezier side).
    std::vector<Row> curves(edges);
    std::vector<int> curve_level(edges, 0);
    for (int e = 0; e < edges; ++e) {
      const auto [p, k] = sides.owner[e];
      const auto other = limit.neighbour(p, k);
      const bool owner_exact = exact[p].has_value(), other_exact = other.patch >= 0 && exact[other.patch];
      if (owner_exact && (other_exact || other.patch < 0)) continue;  // no fitted patch on it
      if (owner_exact || other_exact) {
        curves[e] = owner_exact ? side_row(*exact[p], k) : side_row(*exact[other.patch], other.side);
        if (!owner_exact) std::reverse(curves[e].begin(), curves[e].end());
        continue;
      }
      const int level = other.patch >= 0 ? std::max(wanted[p], wanted[other.patch]) : wanted[p];
      const std::vector<double> knots = subd_nurbs::graded_cubic_knots(level, halved);
      const std::vector<double> params = subd_nurbs::sample_params(knots, 4, 6);
      Row samples;
      for (double t : params) {
        const Eigen::Vector2d uv = side_uv(k, t);
        samples.push_back(limit.point(p, uv.x(), uv.y()));
      }
      curves[e] = subd_nurbs::fit_cubic_curve(knots, params, samples, corners[p][k], corners[p][(k + 1) % 4]);
      curve_level[e] = level;
    }
    bool all_within = true;
    for (int p = 0; p < patches; ++p) {
      if (exact[p]) continue;
      const std::vector<double> knots = subd_nurbs::graded_cubic_knots(level_of[p], halved);
      const std::vector<double> params = subd_nurbs::sample_params(knots, 4, 6);
      NurbsSurface& s = fitted[p] = fitted_surface(knots);
      for (int k = 0; k < 4; ++k) {
        const int e = sides.number[p][k];
        const std::vector<double> bezier = {0, 0, 0, 0, 1, 1, 1, 1};
        Row row = reknotted(
            curves[e], curve_level[e] == 0 ? bezier : subd_nurbs::graded_cubic_knots(curve_level[e], halved), knots);
        if (sides.reversed[p][k]) std::reverse(row.begin(), row.end());
        set_side_row(s, k, row);
      }
      Row samples;
      samples.reserve(params.size() * params.size());
      for (double v : params)
        for (double u : params) samples.push_back(limit.point(p, u, v));
      subd_nurbs::fit_cubic_surface_interior(knots, params, samples, s.points);
      const subd_nurbs::PatchDeviation off = subd_nurbs::patch_deviation(s, limit, p);
      result.fitted_bound = std::max(result.fitted_bound, off.proven);
      result.fitted_sampled_at_features = std::max(result.fitted_sampled_at_features, off.sampled);
      result.fitted_levels = std::max(result.fitted_levels, level_of[p]);
      if (std::max(off.proven, off.sampled) <= deviation) continue;
      all_within = false;
      if (wanted[p] == kMaxLevel)
        throw GeometryError(entity, "patch " + std::to_string(p) + " stays " +
                                        std::to_string(std::max(off.proven, off.sampled)) +
                                        " from the limit surface with spans down to 2^-" + std::to_string(kMaxLevel) +
                                        ", above the deviation " + std::to_string(deviation));
      ++wanted[p];
    }
    if (all_within) break;
    result.fitted_bound = result.fitted_sampled_at_features = 0;
    result.fitted_levels = 0;
  }

  for (int p = 0; p < patches; ++p) {
    TrimmedSurface patch;
    patch.surface = exact[p] ? *exact[p] : fitted[p];
    TrimLoop loop = domain_loop(patch.surface);
    for (int k = 0; k < 4; ++k) loop.edges.push_back({first_edge_number + sides.number[p][k], sides.reversed[p][k]});
    patch.loops.push_back(std::move(loop));
    result.patches.push_back(std::move(patch));
    ++(exact[p] ? result.exact_patches : result.fitted_patches);
    result.rhino_rule_patches += limit.follows_sector_coefficients(p);
  }
  result.edges_used = edges;
  return result;
}

}  // namespace cadnurbs
