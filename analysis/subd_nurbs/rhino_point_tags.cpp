#include "analysis/subd_nurbs/rhino_point_tags.hpp"

#include <algorithm>

namespace cadnurbs::subd_nurbs {

NetEdges net_edges(const SubdControlNet& net) {
  NetEdges edges;
  for (size_t f = 0; f < net.faces.size(); ++f) {
    const auto& face = net.faces[f];
    for (size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      edges[{std::min(a, b), std::max(a, b)}].faces.push_back(static_cast<int>(f));
    }
  }
  for (auto& [points, edge] : edges) edge.crease = edge.faces.size() == 1;
  for (const auto& [a, b] : net.crease_edges) edges.at({std::min(a, b), std::max(a, b)}).crease = true;
  return edges;
}

std::vector<PointTag> rhino_point_tags(const SubdControlNet& net, const NetEdges& edges) {
  std::vector<int> creases(net.points.size(), 0);
  for (const auto& [points, edge] : edges)
    if (edge.crease) ++creases[points[0]], ++creases[points[1]];
  static constexpr PointTag kByCreaseCount[] = {PointTag::smooth, PointTag::dart, PointTag::crease};
  std::vector<PointTag> tags(net.points.size());
  for (size_t v = 0; v < tags.size(); ++v) tags[v] = creases[v] < 3 ? kByCreaseCount[creases[v]] : PointTag::corner;
  for (int v : net.corner_points) tags[v] = PointTag::corner;
  return tags;
}

}  // namespace cadnurbs::subd_nurbs
