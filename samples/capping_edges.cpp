#include "samples/capping_edges.hpp"

#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {

namespace {

Eigen::Vector3d on_segment(const TrimmedSurface& t, const TrimSegment& s, double fraction) {
  const Eigen::Vector2d uv = segment_uv(s, segment_t0(s) + fraction * (segment_t1(s) - segment_t0(s)));
  return surface_point(t.surface, uv.x(), uv.y());
}

}  // namespace

void share_capping_edges(Scene& scene) {
  auto& shapes = scene.root.shapes;
  TrimmedSurface& body = std::get<TrimmedSurface>(shapes[0].geometry);
  TrimLoop loop = domain_loop(body.surface);
  loop.edges = {{1, false}, {3, false}, {2, false}, {3, true}};
  body.loops = {loop};
  // Each lid's loop runs along its body side one way or the other.
  for (int lid = 1; lid <= 2; ++lid) {
    TrimmedSurface& t = std::get<TrimmedSurface>(shapes[lid].geometry);
    const TrimSegment& side = body.loops[0].segments[lid == 1 ? 0 : 2];
    const TrimSegment& trim = t.loops[0].segments[0];
    const bool same = (on_segment(body, side, 0.3) - on_segment(t, trim, 0.3)).norm() <
                      (on_segment(body, side, 0.3) - on_segment(t, trim, 0.7)).norm();
    t.loops[0].edges = {{lid, !same}};
  }
}

}  // namespace cadnurbs
