#include "analysis/subd_nurbs/rhino_limit_surface.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "analysis/subd_nurbs/check_manifold.hpp"

namespace cadnurbs::subd_nurbs {

namespace {

RhinoNet base_net(const SubdControlNet& net, const std::string& entity) {
  check_manifold(net, entity);
  RhinoNet level0 = rhino_net(net);
  const bool all_quads = std::all_of(net.faces.begin(), net.faces.end(), [](const auto& f) { return f.size() == 4; });
  return all_quads ? level0 : rhino_subdivision_step(level0);
}

// Faces with a corner on an edge that has a sector coefficient other than 1/2 (at either end): the faces
// whose limit Rhino's rules change (a face's limit depends on the rules at its corners' edges only).
std::vector<bool> touched_faces(const RhinoNet& rhino) {
  std::unordered_set<int> ends;
  for (const auto& [end, w] : rhino.coefficients) ends.insert({end[0], end[1]});
  std::vector<bool> touched;
  for (const auto& face : rhino.net.faces)
    touched.push_back(std::any_of(face.begin(), face.end(), [&](int p) { return ends.count(p) > 0; }));
  return touched;
}

}  // namespace

RhinoLimitSurface::RhinoLimitSurface(const SubdControlNet& net, const std::string& entity, int levels)
    : base_net_(base_net(net, entity)),
      base_(base_net_.net, entity),
      rhino_patch_(touched_faces(base_net_)),
      levels_(levels) {
  if (std::none_of(rhino_patch_.begin(), rhino_patch_.end(), [](bool b) { return b; })) return;
  // Refine everything (simple, and the step is linear in the net), keeping where each face lies in its patch.
  RhinoNet refined = base_net_;
  struct Origin {
    int patch, i, j;
  };
  std::vector<Origin> origin;
  for (int p = 0; p < patch_count(); ++p) origin.push_back({p, 0, 0});
  static constexpr int kChild[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int level = 0; level < levels; ++level) {
    refined = rhino_subdivision_step(refined);
    std::vector<Origin> next;
    for (const Origin& o : origin)
      for (const auto& c : kChild) next.push_back({o.patch, 2 * o.i + c[0], 2 * o.j + c[1]});
    origin = std::move(next);
  }
  refined_ = std::make_unique<SubdLimitSurface>(refined.net, entity);
  const std::vector<bool> inexact = touched_faces(refined);
  const int side = 1 << levels;
  children_.resize(patch_count());
  rhino_pieces_.resize(patch_count());
  for (int p = 0; p < patch_count(); ++p)
    if (rhino_patch_[p]) children_[p].resize(side * side);
  for (size_t f = 0; f < origin.size(); ++f) {
    const auto [p, i, j] = origin[f];
    if (!rhino_patch_[p]) continue;
    children_[p][i + side * j] = static_cast<int>(f);
    for (LimitPiece piece : refined_->pieces(static_cast<int>(f))) {
      piece.u0 = (i + piece.u0) / side;
      piece.v0 = (j + piece.v0) / side;
      piece.size /= side;
      if (inexact[f]) piece.bspline.reset();
      rhino_pieces_[p].push_back(piece);
    }
  }
}

Eigen::Vector3d RhinoLimitSurface::point(int patch, double u, double v) const {
  if (!rhino_patch_[patch]) return base_.point(patch, u, v);
  const int side = 1 << levels_;
  const int i = std::clamp(static_cast<int>(std::floor(u * side)), 0, side - 1);
  const int j = std::clamp(static_cast<int>(std::floor(v * side)), 0, side - 1);
  return refined_->point(children_[patch][i + side * j], u * side - i, v * side - j);
}

const std::vector<LimitPiece>& RhinoLimitSurface::pieces(int patch) const {
  return rhino_patch_[patch] ? rhino_pieces_[patch] : base_.pieces(patch);
}

}  // namespace cadnurbs::subd_nurbs
