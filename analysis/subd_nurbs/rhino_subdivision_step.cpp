#include "analysis/subd_nurbs/rhino_subdivision_step.hpp"

#include <algorithm>

namespace cadnurbs::subd_nurbs {

RhinoNet rhino_net(const SubdControlNet& net) {
  const NetEdges edges = net_edges(net);
  return {net, rhino_sector_coefficients(net, edges, rhino_point_tags(net, edges))};
}

RhinoNet rhino_subdivision_step(const RhinoNet& in) {
  using Eigen::Vector3d;
  const SubdControlNet& net = in.net;
  const NetEdges edges = net_edges(net);
  const std::vector<PointTag> tags = rhino_point_tags(net, edges);
  const int points = static_cast<int>(net.points.size());

  std::vector<Vector3d> centroid;
  for (const auto& face : net.faces) {
    Vector3d sum = Vector3d::Zero();
    for (int p : face) sum += net.points[p];
    centroid.push_back(sum / static_cast<double>(face.size()));
  }

  RhinoNet out;
  auto& refined = out.net.points;
  refined.resize(points);
  std::map<std::array<int, 2>, int> edge_point;
  std::vector<Vector3d> neighbour_sum(points, Vector3d::Zero()), crease_sum(points, Vector3d::Zero());
  for (const auto& [ab, edge] : edges) {
    const auto [a, b] = ab;
    const Vector3d &A = net.points[a], &B = net.points[b];
    edge_point[ab] = static_cast<int>(refined.size());
    neighbour_sum[a] += B, neighbour_sum[b] += A;
    if (edge.crease) {
      crease_sum[a] += B, crease_sum[b] += A;
      refined.push_back((A + B) / 2);
      continue;
    }
    double wa = 0.5, wb = 0.5;
    const bool a_tagged = tags[a] != PointTag::smooth, b_tagged = tags[b] != PointTag::smooth;
    if (a_tagged != b_tagged) {
      const auto w = in.coefficients.find(a_tagged ? ab : std::array{b, a});
      if (w != in.coefficients.end()) (a_tagged ? wa : wb) = w->second, (a_tagged ? wb : wa) = 1 - w->second;
    }
    refined.push_back(0.75 * (wa * A + wb * B) - (A + B) / 8 + (centroid[edge.faces[0]] + centroid[edge.faces[1]]) / 4);
  }
  std::vector<Vector3d> face_sum(points, Vector3d::Zero());
  std::vector<int> face_count(points, 0);
  for (size_t f = 0; f < net.faces.size(); ++f)
    for (int p : net.faces[f]) face_sum[p] += centroid[f], ++face_count[p];
  for (int v = 0; v < points; ++v) {
    const Vector3d& V = net.points[v];
    const double n = face_count[v];
    switch (tags[v]) {
      case PointTag::corner:
        refined[v] = V;
        break;
      case PointTag::crease:
        refined[v] = (6 * V + crease_sum[v]) / 8;
        break;
      default:
        refined[v] = (1 - 2 / n) * V + (neighbour_sum[v] + face_sum[v]) / (n * n);
    }
  }
  const int first_face_point = static_cast<int>(refined.size());
  refined.insert(refined.end(), centroid.begin(), centroid.end());

  auto point_of_edge = [&](int a, int b) { return edge_point.at({std::min(a, b), std::max(a, b)}); };
  for (size_t f = 0; f < net.faces.size(); ++f) {
    const auto& q = net.faces[f];
    const int n = static_cast<int>(q.size());
    for (int k = 0; k < n; ++k) {
      const std::array<int, 4> child = {q[k], point_of_edge(q[k], q[(k + 1) % n]),
                                        first_face_point + static_cast<int>(f),
                                        point_of_edge(q[k], q[(k + n - 1) % n])};
      std::vector<int> face(4);
      // a quad's child starts where the quad's (u, v) is least on it
      for (int r = 0; r < 4; ++r) face[r] = n == 4 ? child[(r - k + 4) % 4] : child[r];
      out.net.faces.push_back(std::move(face));
    }
  }
  for (const auto& [ab, edge] : edges)
    if (edge.crease) {
      const int e = edge_point.at(ab);
      out.net.crease_edges.push_back({ab[0], e});
      out.net.crease_edges.push_back({e, ab[1]});
    }
  out.net.corner_points = net.corner_points;  // points of 3+ creases stay corners by their creases
  for (const auto& [end, w] : in.coefficients) out.coefficients[{end[0], point_of_edge(end[0], end[1])}] = w;
  return out;
}

}  // namespace cadnurbs::subd_nurbs
