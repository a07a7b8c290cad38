#include "analysis/sewing/piece_matching.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "analysis/sewing/model_vertices.hpp"

namespace cadnurbs::sewing {

namespace {

// Every interior sample of `a` lies within `tolerance` of b's 3D image.
bool runs_along(const Piece& a, const Piece& b, const SurfaceEvaluator& b_surface, double tolerance) {
  for (size_t k = 1; k + 1 < a.points.size(); ++k)
    if (project_to_piece(b, b_surface, a.points[k]).distance > tolerance) return false;
  return true;
}

}  // namespace

bool runs_against(const Piece& a, const Piece& b, const SurfaceEvaluator& b_surface) {
  if (a.start != a.end) return b.start != a.start;
  const size_t n = a.points.size();
  return project_to_piece(b, b_surface, a.points[n / 3]).t > project_to_piece(b, b_surface, a.points[(2 * n) / 3]).t;
}

UnionFind match_pieces(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces, double tolerance) {
  std::map<std::pair<VertexId, VertexId>, std::vector<int>> by_ends;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    if (!p.is_point) by_ends[std::minmax(p.start, p.end)].push_back(static_cast<int>(i));
  }
  UnionFind edges(pieces.size());
  for (const auto& [ends, group] : by_ends)
    for (size_t a = 0; a < group.size(); ++a)
      for (size_t b = a + 1; b < group.size(); ++b) {
        const Piece &pa = pieces[group[a]], &pb = pieces[group[b]];
        if (edges.find(group[a]) == edges.find(group[b])) continue;
        if (runs_along(pa, pb, *faces[pb.face].surface, tolerance) &&
            runs_along(pb, pa, *faces[pa.face].surface, tolerance))
          edges.unite(group[a], group[b]);
      }
  return edges;
}

// Gaps of the source model itself (STEP files written with a tolerance of their own): the pieces still
// open are matched among themselves at ten times the tolerance, and again, up to the largest.
void match_open_pieces(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces,
                       const SewingTolerance& tolerance, UnionFind& edges, SewingReport& report) {
  for (double wider = tolerance.first; wider < tolerance.largest;) {
    wider = std::min(10 * wider, tolerance.largest);
    std::vector<int> open_index;
    std::vector<int> uses(pieces.size(), 0);
    for (size_t i = 0; i < pieces.size(); ++i) ++uses[edges.find(static_cast<int>(i))];
    auto longer_than_wider = [&](const Piece& p) {
      return std::any_of(p.points.begin(), p.points.end(),
                         [&](const Eigen::Vector3d& q) { return (q - p.points.front()).norm() > wider; });
    };
    for (size_t i = 0; i < pieces.size(); ++i)
      if (!pieces[i].is_point && uses[edges.find(static_cast<int>(i))] < 2 && longer_than_wider(pieces[i]))
        open_index.push_back(static_cast<int>(i));
    if (open_index.size() < 2) break;
    std::vector<Piece> open;
    for (int i : open_index) open.push_back(pieces[i]);
    find_model_vertices(open, wider);
    UnionFind matched = match_pieces(open, faces, wider);
    for (size_t k = 0; k < open.size(); ++k) {
      const int root = matched.find(static_cast<int>(k));
      if (root != static_cast<int>(k)) {
        edges.unite(open_index[k], open_index[root]);
        report.widest_gap = std::max(report.widest_gap, wider);
      }
    }
  }
}

std::vector<int> split_by_solid(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces, UnionFind& edges) {
  const int n = static_cast<int>(pieces.size());
  std::vector<int> uses(n, 0), edge_of(n);
  for (int i = 0; i < n; ++i) ++uses[edge_of[i] = edges.find(i)];
  UnionFind solids(faces.size());
  std::vector<int> other_face(n, -1);
  for (int i = 0; i < n; ++i)
    if (uses[edge_of[i]] == 2) {
      int& seen = other_face[edge_of[i]];
      if (seen < 0) seen = pieces[i].face;
      else solids.unite(seen, pieces[i].face);
    }
  // Classes (root, solid) of the crowded edges get the indices of their first piece: unused as roots.
  std::map<std::pair<int, int>, int> split;
  std::map<int, std::vector<int>> crowded;  // root -> its pieces
  for (int i = 0; i < n; ++i)
    if (uses[edge_of[i]] > 2) {
      crowded[edge_of[i]].push_back(i);
      edge_of[i] = split.emplace(std::pair{edge_of[i], solids.find(pieces[i].face)}, i).first->second;
    }
  // A piece left alone by the split (a face joined to its solid by crowded edges only, as in two copies
  // of one solid at one place) is paired with another such piece running the other way, in order.
  for (const auto& [root, members] : crowded) {
    std::map<int, int> count;
    for (int i : members) ++count[edge_of[i]];
    std::vector<int> forward, backward;
    for (int i : members)
      if (count[edge_of[i]] == 1)
        (runs_against(pieces[members.front()], pieces[i], *faces[pieces[i].face].surface) ? backward : forward)
            .push_back(i);
    for (size_t k = 0; k < std::min(forward.size(), backward.size()); ++k) edge_of[backward[k]] = edge_of[forward[k]];
  }
  return edge_of;
}

}  // namespace cadnurbs::sewing
