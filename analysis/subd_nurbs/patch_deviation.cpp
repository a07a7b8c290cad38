#include "analysis/subd_nurbs/patch_deviation.hpp"

#include <algorithm>
#include <vector>

#include "core/bezier_extraction.hpp"

namespace cadnurbs::subd_nurbs {

namespace {

using Bezier = std::array<Eigen::Vector3d, 16>;

// Uniform cubic B-spline segment -> Bezier points: b = M p.
constexpr double kBsplineToBezier[4][4] = {
    {1.0 / 6, 4.0 / 6, 1.0 / 6, 0}, {0, 4.0 / 6, 2.0 / 6, 0}, {0, 2.0 / 6, 4.0 / 6, 0}, {0, 1.0 / 6, 4.0 / 6, 1.0 / 6}};

// The cubic's blossom at (t1, t2, t3): de Casteljau with one parameter per level.
Eigen::Vector3d blossom(std::array<Eigen::Vector3d, 4> c, double t1, double t2, double t3) {
  const double t[3] = {t1, t2, t3};
  for (int level = 0; level < 3; ++level)
    for (int i = 0; i + level < 3; ++i) c[i] = (1 - t[level]) * c[i] + t[level] * c[i + 1];
  return c[0];
}

// The cubic of Bezier points c over [0, 1] as Bezier points over [a, b].
std::array<Eigen::Vector3d, 4> restricted(const std::array<Eigen::Vector3d, 4>& c, double a, double b) {
  return {blossom(c, a, a, a), blossom(c, a, a, b), blossom(c, a, b, b), blossom(c, b, b, b)};
}

// The bicubic of Bezier points p over [0, 1]^2 as Bezier points over [u0, u1] x [v0, v1].
Bezier restricted(const Bezier& p, double u0, double u1, double v0, double v1) {
  Bezier rows;
  for (int j = 0; j < 4; ++j) {
    const auto row = restricted({p[4 * j], p[4 * j + 1], p[4 * j + 2], p[4 * j + 3]}, u0, u1);
    for (int i = 0; i < 4; ++i) rows[i + 4 * j] = row[i];
  }
  Bezier out;
  for (int i = 0; i < 4; ++i) {
    const auto column = restricted({rows[i], rows[i + 4], rows[i + 8], rows[i + 12]}, v0, v1);
    for (int j = 0; j < 4; ++j) out[i + 4 * j] = column[j];
  }
  return out;
}

}  // namespace

Bezier bicubic_bezier_points(const Bezier& bspline) {
  Bezier out;
  out.fill(Eigen::Vector3d::Zero());
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a)
          out[i + 4 * j] += kBsplineToBezier[i][a] * kBsplineToBezier[j][b] * bspline[a + 4 * b];
  return out;
}

PatchDeviation patch_deviation(const NurbsSurface& fit, const RhinoLimitSurface& limit, int patch) {
  std::vector<double> breaks(fit.u_knots.begin() + 3, fit.u_knots.end() - 3);  // the spans' ends
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  const int spans = static_cast<int>(breaks.size()) - 1;
  std::vector<Bezier> cells;
  for (const NurbsSurface& cell : bezier_patches(fit)) {
    Bezier points;
    std::copy(cell.points.begin(), cell.points.end(), points.begin());
    cells.push_back(points);
  }
  PatchDeviation deviation;
  for (const LimitPiece& piece : limit.pieces(patch)) {
    if (!piece.bspline) {
      for (int b = 0; b <= 4; ++b)
        for (int a = 0; a <= 4; ++a) {
          const double u = piece.u0 + piece.size * a / 4, v = piece.v0 + piece.size * b / 4;
          deviation.sampled = std::max(deviation.sampled, (surface_point(fit, u, v) - limit.point(patch, u, v)).norm());
        }
      continue;
    }
    const Bezier exact = bicubic_bezier_points(*piece.bspline);
    for (int iv = 0; iv < spans; ++iv) {
      const double v0 = std::max(piece.v0, breaks[iv]), v1 = std::min(piece.v0 + piece.size, breaks[iv + 1]);
      if (v1 <= v0) continue;
      for (int iu = 0; iu < spans; ++iu) {
        const double u0 = std::max(piece.u0, breaks[iu]), u1 = std::min(piece.u0 + piece.size, breaks[iu + 1]);
        if (u1 <= u0) continue;
        const double du = breaks[iu + 1] - breaks[iu], dv = breaks[iv + 1] - breaks[iv];
        const Bezier limit_part = restricted(exact, (u0 - piece.u0) / piece.size, (u1 - piece.u0) / piece.size,
                                             (v0 - piece.v0) / piece.size, (v1 - piece.v0) / piece.size);
        const Bezier fit_part = restricted(cells[iu + spans * iv], (u0 - breaks[iu]) / du, (u1 - breaks[iu]) / du,
                                           (v0 - breaks[iv]) / dv, (v1 - breaks[iv]) / dv);
        for (int k = 0; k < 16; ++k)
          deviation.proven = std::max(deviation.proven, (limit_part[k] - fit_part[k]).norm());
      }
    }
  }
  return deviation;
}

}  // namespace cadnurbs::subd_nurbs
