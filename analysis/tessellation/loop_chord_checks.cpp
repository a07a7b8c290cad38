#include "analysis/tessellation/loop_chord_checks.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "analysis/eval/sample_trim_segment.hpp"

namespace cadnurbs::tessellation {

void crossing_chords(const Face& f, std::set<CurveSpan>& out) {
  struct Chord {
    Eigen::Vector2d a, b;
    std::optional<CurveSpan> span;
  };
  std::vector<Chord> chords;
  Eigen::AlignedBox2d box;
  for (const auto& loop : f.points) {
    std::vector<Eigen::Vector2d> distinct;
    for (size_t k = 0; k < loop.size(); ++k) {
      const LoopPoint& p = loop[k];
      const Eigen::Vector2d& q = loop[(k + 1) % loop.size()].uv;
      box.extend(p.uv);
      // Three distinct points are enough to know: no quadratic search on long loops.
      if (distinct.size() < 3 &&
          std::none_of(distinct.begin(), distinct.end(), [&](const Eigen::Vector2d& x) { return x == p.uv; }))
        distinct.push_back(p.uv);
      if (p.uv != q) chords.push_back({p.uv, q, p.chord});
    }
    if (distinct.size() < 3)
      for (const auto& p : loop)
        if (p.chord) out.insert(*p.chord);
  }
  if (chords.size() < 2) return;
  // Buckets of a uniform grid over the loops' box; pairs are tested within a bucket.
  const int n = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(chords.size()))), 1, 256);
  const Eigen::Vector2d lo = box.min(), size = (box.max() - box.min()).cwiseMax(1e-300);
  auto cell = [&](double x, double extent, double origin) {
    return std::clamp(static_cast<int>((x - origin) / extent * n), 0, n - 1);
  };
  std::vector<std::vector<int>> buckets(static_cast<size_t>(n) * n);
  for (size_t c = 0; c < chords.size(); ++c) {
    const Chord& h = chords[c];
    const int i0 = cell(std::min(h.a.x(), h.b.x()), size.x(), lo.x()), i1 = cell(std::max(h.a.x(), h.b.x()), size.x(), lo.x());
    const int j0 = cell(std::min(h.a.y(), h.b.y()), size.y(), lo.y()), j1 = cell(std::max(h.a.y(), h.b.y()), size.y(), lo.y());
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) buckets[i + j * n].push_back(static_cast<int>(c));
  }
  auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const double x = (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
    return (x > 0) - (x < 0);
  };
  for (const auto& bucket : buckets)
    for (size_t x = 0; x < bucket.size(); ++x)
      for (size_t y = x + 1; y < bucket.size(); ++y) {
        const Chord& p = chords[bucket[x]];
        const Chord& q = chords[bucket[y]];
        if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b) continue;  // neighbours
        // Proper crossings only: chords that touch or overlap follow loops that touch or overlap
        // themselves in the file (Ventilator.stp), which no split can undo; CGAL joins those
        // constraints without new vertices.
        if (side(p.a, p.b, q.a) * side(p.a, p.b, q.b) >= 0 || side(q.a, q.b, p.a) * side(q.a, q.b, p.b) >= 0) continue;
        if (p.span) out.insert(*p.span);
        if (q.span) out.insert(*q.span);
      }
}

void coarse_chords(const Face& f, double max_deviation, std::set<CurveSpan>& out) {
  for (const auto& loop : f.points) {
    std::vector<Eigen::Vector3d> on_face(loop.size());  // this face's points at the loop's (u,v)
    for (size_t k = 0; k < loop.size(); ++k) on_face[k] = f.eval->point(loop[k].uv.x(), loop[k].uv.y());
    for (size_t k = 0; k < loop.size(); ++k) {
      const LoopPoint& p = loop[k];
      if (!p.chord) continue;
      const size_t next = (k + 1) % loop.size();
      const Eigen::Vector2d& a = p.uv;
      const Eigen::Vector2d& b = loop[next].uv;
      if (lines_between(f.us, a.x(), b.x()) > 1 || lines_between(f.vs, a.y(), b.y()) > 1 ||
          !surface_chord_within(*f.eval, f.bound, a, on_face[k], b, on_face[next], max_deviation))
        out.insert(*p.chord);
    }
  }
}

}  // namespace cadnurbs::tessellation
