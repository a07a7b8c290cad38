#include "formats/cnb/cnb_mesh_copies.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <tuple>

#include "core/union_find.hpp"

namespace cadnurbs::cnb {

namespace {

// A piece is compared with at most this many earlier pieces of its shape's counts and box (a mesh of many
// alike pieces that are not copies must not cost quadratic time).
constexpr size_t sources_tried = 16;

constexpr int axis_orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};

// A piece in its own numbering: its vertices' grid points in the order its triangles meet them, and its
// triangles over those.
struct Piece {
  std::vector<GridPoint> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> mesh_triangles;  // the mesh's triangle of each
  std::vector<GridPoint> sorted_points() const {
    std::vector<GridPoint> sorted = points;
    std::sort(sorted.begin(), sorted.end());
    return sorted;
  }
};

// The pieces of a mesh in the order of their first triangles.
std::vector<Piece> pieces_of(const TriangleMesh& mesh, const std::vector<GridPoint>& grid) {
  UnionFind joined(mesh.positions.size());
  for (const auto& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) joined.unite(t[0], t[k]);
  std::map<int, size_t> piece_of_root;
  std::vector<Piece> pieces;
  std::vector<int> local(mesh.positions.size(), -1);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [found, added] = piece_of_root.emplace(joined.find(mesh.triangles[t][0]), pieces.size());
    if (added) pieces.emplace_back();
    Piece& piece = pieces[found->second];
    std::array<int, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (local[v] < 0) {
        local[v] = static_cast<int>(piece.points.size());
        piece.points.push_back(grid[v]);
      }
      corners[k] = local[v];
    }
    piece.triangles.push_back(corners);
    piece.mesh_triangles.push_back(static_cast<int>(t));
  }
  return pieces;
}

// The pieces' places in the order both sides compute (by sorted points; ties keep the given order).
std::vector<size_t> ordered(const std::vector<Piece>& pieces, const std::vector<size_t>& which, bool& ties) {
  std::vector<std::vector<GridPoint>> keys(pieces.size());
  for (size_t i : which) keys[i] = pieces[i].sorted_points();
  std::vector<size_t> order = which;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  ties = false;
  for (size_t k = 1; k < order.size(); ++k) ties = ties || keys[order[k]] == keys[order[k - 1]];
  return order;
}

GridPoint lowest_corner(const std::vector<GridPoint>& points) {
  GridPoint low = points.front();
  for (const auto& p : points)
    for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], p[k]);
  return low;
}

// Triangle (a, b, c) as a turn leaves it facing: reversed by a mirror, so that it still faces outwards.
std::array<int, 3> facing(int a, int b, int c, bool mirrors) {
  return mirrors ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c};
}

// The triangle as a cycle starting at its smallest index, so that rotations compare equal.
std::array<int, 3> cycle(int a, int b, int c) {
  if (a < b && a < c) return {a, b, c};
  if (b < c) return {b, c, a};
  return {c, a, b};
}

// A triangle set's planar regions: for each plane its triangles lie in (the exact plane through their
// grid points, facing as they do), the directed edges of that plane's triangles that no triangle of the
// same plane runs back along. Two triangle sets over the same points with the same regions cover the same
// surface: a plane's region is bounded by its edges, however it is cut into triangles. So a piece whose
// flat faces were triangulated another way (the tessellator's choice of diagonal in a rectangle) is still a
// copy, decoded with its source's triangles. Empty when a triangle has no area or a plane's numbers are
// too large to compare.
using Plane = std::array<int64_t, 4>;  // normal / gcd, and its offset
using Edge = std::pair<int, int>;
std::map<Plane, std::vector<Edge>> planar_regions(const std::vector<GridPoint>& points,
                                                  const std::vector<std::array<int, 3>>& triangles) {
  std::map<Plane, std::map<Edge, int>> edges;
  for (const auto& t : triangles) {
    const GridPoint &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    std::array<__int128, 3> u, v, n;
    for (int k = 0; k < 3; ++k) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
    n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    __int128 g = 0;
    for (__int128 x : n) {
      __int128 y = x < 0 ? -x : x;
      while (y != 0) g %= y, std::swap(g, y);
    }
    if (g == 0) return {};
    Plane plane;
    __int128 offset = 0;
    for (int k = 0; k < 3; ++k) {
      n[k] /= g;
      if (n[k] > INT64_MAX / 4 || n[k] < -INT64_MAX / 4) return {};
      plane[k] = static_cast<int64_t>(n[k]);
      offset += n[k] * a[k];
    }
    if (offset > INT64_MAX || offset < INT64_MIN) return {};
    plane[3] = static_cast<int64_t>(offset);
    auto& in_plane = edges[plane];
    for (int k = 0; k < 3; ++k) {
      const Edge e{t[k], t[(k + 1) % 3]};
      const auto back = in_plane.find({e.second, e.first});
      if (back != in_plane.end() && back->second > 0) {
        if (--back->second == 0) in_plane.erase(back);
      } else {
        ++in_plane[e];
      }
    }
  }
  std::map<Plane, std::vector<Edge>> regions;
  for (const auto& [plane, counted] : edges)
    for (const auto& [e, count] : counted) regions[plane].insert(regions[plane].end(), count, e);
  return regions;
}

// The turn and move taking `source` onto `target`: the lowest turn that maps its triangles onto the
// target's, else the lowest that maps its planar regions onto the target's; none when no turn does.
std::optional<PieceCopy> piece_map(const Piece& source, const Piece& target) {
  if (source.points.size() != target.points.size() || source.triangles.size() != target.triangles.size())
    return std::nullopt;
  std::map<GridPoint, int> target_at;
  for (size_t i = 0; i < target.points.size(); ++i)
    if (!target_at.emplace(target.points[i], static_cast<int>(i)).second) return std::nullopt;  // points coincide
  std::set<std::array<int, 3>> target_cycles;
  for (const auto& t : target.triangles) target_cycles.insert(cycle(t[0], t[1], t[2]));
  const GridPoint target_low = lowest_corner(target.points);
  // Each turn that lands the source's points on the target's: the source's triangles over the target's points.
  std::vector<std::pair<PieceCopy, std::vector<std::array<int, 3>>>> landing;
  std::vector<GridPoint> moved(source.points.size());
  std::vector<int> image(source.points.size());
  for (int turn = 0; turn < turn_count; ++turn) {
    for (size_t i = 0; i < moved.size(); ++i) moved[i] = turned(turn, source.points[i]);
    const GridPoint low = lowest_corner(moved);
    const GridPoint move{target_low[0] - low[0], target_low[1] - low[1], target_low[2] - low[2]};
    std::vector<bool> taken(target.points.size(), false);
    bool lands = true;
    for (size_t i = 0; i < moved.size() && lands; ++i) {
      const auto found = target_at.find({moved[i][0] + move[0], moved[i][1] + move[1], moved[i][2] + move[2]});
      lands = found != target_at.end() && !taken[found->second];
      if (lands) taken[found->second] = true, image[i] = found->second;
    }
    if (!lands) continue;
    const bool mirrors = turn_mirrors(turn);
    std::vector<std::array<int, 3>> images;
    for (const auto& t : source.triangles)
      images.push_back(facing(image[t[0]], image[t[1]], image[t[2]], mirrors));
    std::set<std::array<int, 3>> met;
    bool same_triangles = true;
    for (const auto& t : images) {
      const auto c = cycle(t[0], t[1], t[2]);
      same_triangles = same_triangles && target_cycles.count(c) && met.insert(c).second;
    }
    if (same_triangles) return PieceCopy{0, 0, turn, move};
    landing.push_back({PieceCopy{0, 0, turn, move}, std::move(images)});
  }
  if (landing.empty()) return std::nullopt;
  const auto target_regions = planar_regions(target.points, target.triangles);
  if (target_regions.empty()) return std::nullopt;
  for (const auto& [copy, images] : landing)
    if (planar_regions(target.points, images) == target_regions) return copy;
  return std::nullopt;
}

// What a piece must share with another to be its copy: counts, and its box's sides in sorted order.
std::array<int64_t, 5> signature(const Piece& piece) {
  GridPoint low = piece.points.front(), high = low;
  for (const auto& p : piece.points)
    for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
  std::array<int64_t, 3> sides{high[0] - low[0], high[1] - low[1], high[2] - low[2]};
  std::sort(sides.begin(), sides.end());
  return {static_cast<int64_t>(piece.points.size()), static_cast<int64_t>(piece.triangles.size()), sides[0],
          sides[1], sides[2]};
}

// The prediction of a run's next move from its moves so far: the last extended by its step, the last
// alone, or none.
GridPoint predicted_move(const std::vector<GridPoint>& moves) {
  const size_t k = moves.size();
  if (k >= 2) {
    GridPoint p;
    for (int a = 0; a < 3; ++a) p[a] = 2 * moves[k - 1][a] - moves[k - 2][a];
    return p;
  }
  return k == 1 ? moves[0] : GridPoint{0, 0, 0};
}

// Appends `piece` turned and moved as `c` says to `mesh`, counting the numbers it adds against the room.
void append_copy(ByteReader& in, size_t at, TriangleMesh& mesh, const Piece& piece, const PieceCopy& c, double q,
                 size_t& added, size_t number_room) {
  added += 3 * (piece.points.size() + piece.triangles.size());
  if (added > number_room)
    in.fail("copies would add more than the " + std::to_string(number_room) + " numbers the scene has room for", at);
  const int first = static_cast<int>(mesh.positions.size());
  for (const GridPoint& p : piece.points) {
    const GridPoint t = turned(c.turn, p);
    Eigen::Vector3d position;
    for (int k = 0; k < 3; ++k) {
      const double g = static_cast<double>(t[k]) + static_cast<double>(c.move[k]);
      if (std::abs(g) > 0x1p52) in.fail("a copied vertex outside the grid's range", at);
      position[k] = g * q;
    }
    mesh.positions.push_back(position);
  }
  const bool mirrors = turn_mirrors(c.turn);
  for (const auto& t : piece.triangles)
    mesh.triangles.push_back(facing(first + t[0], first + t[1], first + t[2], mirrors));
}

}  // namespace

GridPoint turned(int turn, const GridPoint& p) {
  const int* order = axis_orders[turn / 8];
  GridPoint out;
  for (int k = 0; k < 3; ++k) out[k] = (turn >> k) & 1 ? -p[order[k]] : p[order[k]];
  return out;
}

bool turn_mirrors(int turn) {
  const bool odd_order = turn / 8 >= 3;  // the last three orders exchange two axes
  const int flips = (turn & 1) + ((turn >> 1) & 1) + ((turn >> 2) & 1);
  return odd_order != (flips % 2 == 1);
}

GroupCopies find_group_copies(const std::vector<const TriangleMesh*>& meshes, double q, size_t smallest_piece) {
  GroupCopies found;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const TriangleMesh& mesh = *meshes[m];
    const std::vector<Piece> pieces = pieces_of(mesh, grid_points(mesh, q));
    std::map<std::array<int64_t, 5>, std::vector<size_t>> originals_by_signature;
    std::vector<size_t> originals;
    std::vector<std::pair<size_t, PieceCopy>> copies;  // original's piece, copy
    std::vector<bool> copied(pieces.size(), false);
    for (size_t i = 0; i < pieces.size(); ++i) {
      auto& same = originals_by_signature[signature(pieces[i])];
      std::optional<PieceCopy> copy;
      if (pieces[i].triangles.size() >= smallest_piece)
        for (size_t k = 0; k < same.size() && k < sources_tried && !copy; ++k)
          if ((copy = piece_map(pieces[same[k]], pieces[i]))) copies.push_back({same[k], *copy});
      if (copy) {
        copied[i] = true;
      } else {
        same.push_back(i);
        originals.push_back(i);
      }
    }
    bool ties = false;
    const std::vector<size_t> order = copies.empty() ? originals : ordered(pieces, originals, ties);
    TriangleMesh kept{mesh.positions, {}, {}};
    if (ties || copies.empty()) {
      kept.triangles = mesh.triangles;
    } else {
      std::vector<bool> keep(mesh.triangles.size(), true);
      for (size_t i = 0; i < pieces.size(); ++i)
        if (copied[i])
          for (int t : pieces[i].mesh_triangles) keep[t] = false;
      for (size_t t = 0; t < mesh.triangles.size(); ++t)
        if (keep[t]) kept.triangles.push_back(mesh.triangles[t]);
      std::vector<int> place(pieces.size(), -1);
      for (size_t k = 0; k < order.size(); ++k) place[order[k]] = static_cast<int>(k);
      for (auto& [original, copy] : copies) {
        copy.member = static_cast<int>(m);
        copy.source = place[original];
        found.copies.push_back(copy);
      }
    }
    found.kept.push_back(std::move(kept));
  }
  return found;
}

void write_piece_copies(ByteWriter& out, const std::vector<PieceCopy>& copies) {
  // Runs of copies of one source by one turn, each run's moves in order, so that a row of pins is a run
  // whose moves step evenly.
  std::vector<PieceCopy> sorted = copies;
  const auto key = [](const PieceCopy& c) { return std::tuple(c.member, c.source, c.turn, c.move); };
  std::sort(sorted.begin(), sorted.end(), [&](const PieceCopy& a, const PieceCopy& b) { return key(a) < key(b); });
  std::vector<std::pair<size_t, size_t>> runs;  // first, end
  for (size_t i = 0; i < sorted.size(); ++i)
    if (runs.empty() || sorted[i].member != sorted[i - 1].member || sorted[i].source != sorted[i - 1].source ||
        sorted[i].turn != sorted[i - 1].turn)
      runs.push_back({i, i + 1});
    else
      runs.back().second = i + 1;
  out.varuint(runs.size(), Field::count);
  for (const auto& [first, end] : runs) {
    const PieceCopy& c = sorted[first];
    out.varuint(static_cast<uint64_t>(c.member), Field::index);
    out.varuint(static_cast<uint64_t>(c.source), Field::index);
    out.byte(static_cast<uint8_t>(c.turn), Field::structure);
    out.varuint(end - first - 1, Field::count);
    std::vector<GridPoint> moves;
    for (size_t i = first; i < end; ++i) {
      const GridPoint predicted = predicted_move(moves);
      for (int k = 0; k < 3; ++k) out.varsint(sorted[i].move[k] - predicted[k], Field::point);
      moves.push_back(sorted[i].move);
    }
  }
}

void read_piece_copies(ByteReader& in, std::vector<TriangleMesh>& meshes, double q, size_t number_room) {
  // Each mesh's pieces in the union, in the order that names them.
  std::vector<std::vector<Piece>> pieces(meshes.size());
  std::vector<std::vector<size_t>> order(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m) {
    pieces[m] = pieces_of(meshes[m], grid_points(meshes[m], q));
    std::vector<size_t> all(pieces[m].size());
    std::iota(all.begin(), all.end(), 0);
    bool ties = false;
    order[m] = ordered(pieces[m], all, ties);
  }
  const size_t runs = in.count(7);
  size_t added = 0;
  for (size_t r = 0; r < runs; ++r) {
    PieceCopy c;
    const size_t member_at = in.offset();
    const uint64_t member = in.varuint(Field::index);
    if (member >= meshes.size())
      in.fail("a copy in mesh " + std::to_string(member + 1) + " of a group of " + std::to_string(meshes.size()),
              member_at);
    c.member = static_cast<int>(member);
    const size_t source_at = in.offset();
    const uint64_t source = in.varuint(Field::index);
    if (source >= order[c.member].size())
      in.fail("copy source " + std::to_string(source) + " beyond the " + std::to_string(order[c.member].size()) +
                  " pieces of mesh " + std::to_string(c.member + 1),
              source_at);
    c.source = static_cast<int>(source);
    const size_t turn_at = in.offset();
    c.turn = in.byte(Field::structure);
    if (c.turn >= turn_count) in.fail("copy turn " + std::to_string(c.turn) + " above 47", turn_at);
    const size_t n = in.count(3) + 1;
    std::vector<GridPoint> moves;
    for (size_t i = 0; i < n; ++i) {
      const size_t move_at = in.offset();
      const GridPoint predicted = predicted_move(moves);
      for (int k = 0; k < 3; ++k) {
        const double move = static_cast<double>(predicted[k]) + static_cast<double>(in.varsint(Field::point));
        if (std::abs(move) > 0x1p52) in.fail("copy move outside the grid's range", move_at);
        c.move[k] = static_cast<int64_t>(move);
      }
      moves.push_back(c.move);
      append_copy(in, move_at, meshes[c.member], pieces[c.member][order[c.member][c.source]], c, q, added, number_room);
    }
  }
}

}  // namespace cadnurbs::cnb
