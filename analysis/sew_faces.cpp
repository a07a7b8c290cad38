#include "analysis/sew_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

#include "analysis/point_hash_grid.hpp"
#include "analysis/point_inversion.hpp"
#include "analysis/sample_trim_segment.hpp"
#include "analysis/surface_evaluator.hpp"
#include "core/flatten_transforms.hpp"
#include "core/knot_vector.hpp"
#include "core/planar_polygon_surface.hpp"
#include "core/split_curve.hpp"
#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

constexpr int kSamplesPerSpan = 8;

struct VertexId {
  int value = -1;
  bool operator==(const VertexId&) const = default;
  auto operator<=>(const VertexId&) const = default;
};

// One piece of a face's loop and its sampled 3D image.
struct Piece {
  int face = 0, loop = 0;
  TrimSegment segment;
  std::vector<double> ts;
  std::vector<Eigen::Vector3d> points;  // the surface at segment_uv(ts[k])
  VertexId start, end;
  bool is_point = false;  // the whole image lies within the tolerance of its start
  TrimEdgeRef edge;
};

struct SewFace {
  TrimmedSurface* trimmed;
  std::unique_ptr<SurfaceEvaluator> surface;
  int group;
};

// ---- preparing the scene: polygons as faces, untrimmed faces with their domain rectangle ----

// The polygons of a polygon set: a PolygonMesh's, or a TriangleMesh's triangles when it has no normals
// (how the readers return the compact writer's IndexedFaceSets of planar faces); empty for other shapes.
std::vector<std::vector<Eigen::Vector3d>> planar_polygons(const Shape& shape) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  if (const auto* mesh = std::get_if<PolygonMesh>(&shape.geometry)) {
    for (const auto& polygon : mesh->polygons) {
      out.emplace_back();
      for (int i : polygon) out.back().push_back(mesh->positions[i]);
    }
  } else if (const auto* triangles = std::get_if<TriangleMesh>(&shape.geometry); triangles && triangles->corner_normals.empty()) {
    for (const auto& t : triangles->triangles)
      out.push_back({triangles->positions[t[0]], triangles->positions[t[1]], triangles->positions[t[2]]});
  }
  return out;
}

// Narrower than the tolerance everywhere (twice the area over the longest side): a sliver, such as a fan
// triangle over collinear corners of a polygon; it bounds nothing and its sides lie on its neighbours'.
bool is_sliver(const std::vector<Eigen::Vector3d>& corners, double tolerance) {
  Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
  double longest = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector3d& a = corners[i];
    const Eigen::Vector3d& b = corners[(i + 1) % corners.size()];
    twice_area += (a - corners[0]).cross(b - corners[0]);
    longest = std::max(longest, (b - a).norm());
  }
  return twice_area.norm() <= tolerance * longest;
}

void polygons_as_faces(SceneNode& node, double tolerance, SewingReport& report) {
  std::vector<Shape> shapes;
  for (auto& shape : node.shapes) {
    const auto polygons = planar_polygons(shape);
    if (polygons.empty()) {
      shapes.push_back(std::move(shape));
      continue;
    }
    for (const auto& corners : polygons) {
      auto face = is_sliver(corners, tolerance) ? std::nullopt : planar_polygon_surface(corners);
      if (!face) {
        ++report.dropped_polygons;
        continue;
      }
      Shape piece;
      piece.name = shape.name;
      piece.geometry = std::move(*face);
      piece.colour = shape.colour;
      piece.source_type = shape.source_type.empty() ? "polygon" : shape.source_type;
      piece.source_entity = shape.source_entity;
      shapes.push_back(std::move(piece));
      ++report.polygon_faces;
    }
  }
  node.shapes = std::move(shapes);
  for (auto& child : node.children) polygons_as_faces(child, tolerance, report);
}

// Faces in scene order, each with its group: the nearest named node above it (a solid or part, as the
// source file named it) with all the unnamed nodes below it (writers' Groups and Transforms). Faces are
// sewn within their group only, so that parts of an assembly that touch stay separate solids.
void collect_faces(SceneNode& node, int group, int& groups, std::vector<SewFace>& faces) {
  if (!node.name.empty()) group = groups++;
  for (auto& shape : node.shapes)
    if (auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      if (t->loops.empty()) t->loops.push_back(domain_loop(t->surface));
      faces.push_back({t, std::make_unique<SurfaceEvaluator>(t->surface), group});
    }
  for (auto& child : node.children) collect_faces(child, group, groups, faces);
}

// ---- step 1: pieces and their 3D images ----

// kSamplesPerSpan per knot span of the piece, and as many again per knot line of the surface that a
// sample interval crosses (a straight (u,v) side across a many-patch surface is one span long).
void sample(Piece& piece, const SurfaceEvaluator& surface, double tolerance) {
  const std::vector<double> us = distinct_knots(surface.surface().u_knots), vs = distinct_knots(surface.surface().v_knots);
  piece.ts.clear();
  piece.points.clear();
  const auto breaks = segment_breaks(piece.segment);
  std::vector<double> coarse;
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
    for (int k = (i == 0 ? 0 : 1); k <= kSamplesPerSpan; ++k)
      coarse.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / kSamplesPerSpan);
  Eigen::Vector2d previous = segment_uv(piece.segment, coarse.front());
  piece.ts.push_back(coarse.front());
  for (size_t i = 1; i < coarse.size(); ++i) {
    const Eigen::Vector2d uv = segment_uv(piece.segment, coarse[i]);
    // (lines_between counts -1 for a side that runs along a knot line)
    const int crossed = std::max(0, lines_between(us, previous.x(), uv.x())) + std::max(0, lines_between(vs, previous.y(), uv.y()));
    const int steps = 1 + kSamplesPerSpan * crossed;
    for (int k = 1; k <= steps; ++k) piece.ts.push_back(coarse[i - 1] + (coarse[i] - coarse[i - 1]) * k / steps);
    previous = uv;
  }
  for (double t : piece.ts) {
    const Eigen::Vector2d uv = segment_uv(piece.segment, t);
    piece.points.push_back(surface.point(uv.x(), uv.y()));
  }
  piece.is_point = std::all_of(piece.points.begin(), piece.points.end(),
                               [&](const Eigen::Vector3d& p) { return (p - piece.points.front()).norm() <= tolerance; });
}

std::vector<Piece> cut_into_pieces(const std::vector<SewFace>& faces, const std::vector<int>& members) {
  std::vector<Piece> pieces;
  auto add = [&](int face, size_t loop, TrimSegment segment) {
    Piece piece;
    piece.face = face;
    piece.loop = static_cast<int>(loop);
    piece.segment = std::move(segment);
    pieces.push_back(std::move(piece));
  };
  for (const int f : members)
    for (size_t l = 0; l < faces[f].trimmed->loops.size(); ++l)
      for (const auto& segment : faces[f].trimmed->loops[l].segments) {
        const auto* polyline = std::get_if<Polyline2D>(&segment);
        if (!polyline) {
          add(f, l, segment);
          continue;
        }
        for (size_t i = 0; i + 1 < polyline->points.size(); ++i)
          if (polyline->points[i] != polyline->points[i + 1])
            add(f, l, Polyline2D{{polyline->points[i], polyline->points[i + 1]}});
      }
  return pieces;
}

// ---- step 2: model vertices ----

// Cluster id per point: points closer than `tolerance` share one (transitively); ids 0, 1, ... in
// order of first appearance.
std::vector<int> cluster_points(const std::vector<Eigen::Vector3d>& points, double tolerance) {
  PointHashGrid grid(tolerance);
  UnionFind classes(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    grid.find_near(points[i], [&](int j) {
      if ((points[j] - points[i]).norm() <= tolerance) classes.unite(static_cast<int>(i), j);
      return false;  // every neighbour, not only the first
    });
    grid.insert(points[i], static_cast<int>(i));
  }
  std::vector<int> id(points.size(), -1), id_of_root(points.size(), -1);
  int next = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    int& root_id = id_of_root[classes.find(static_cast<int>(i))];
    if (root_id < 0) root_id = next++;
    id[i] = root_id;
  }
  return id;
}

// Gives every piece its end vertices; returns one position per vertex.
std::vector<Eigen::Vector3d> find_vertices(std::vector<Piece>& pieces, double tolerance) {
  std::vector<Eigen::Vector3d> ends;
  for (const auto& p : pieces) {
    ends.push_back(p.points.front());
    ends.push_back(p.points.back());
  }
  const std::vector<int> id = cluster_points(ends, tolerance);
  std::vector<Eigen::Vector3d> position(ends.empty() ? 0 : *std::max_element(id.begin(), id.end()) + 1);
  for (size_t i = ends.size(); i-- > 0;) position[id[i]] = ends[i];  // the first point of each cluster
  for (size_t i = 0; i < pieces.size(); ++i) pieces[i].start = {id[2 * i]}, pieces[i].end = {id[2 * i + 1]};
  return position;
}

// ---- step 3: cuts at other faces' vertices ----

// Nearest point of the piece's 3D image to p, by Newton from the nearest point of its sample polygon
// (not the nearest sample: beside the shared start of a closed piece that may lie at the wrong end).
CurveProjection project(const Piece& piece, const SurfaceEvaluator& surface, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity(), t_start = piece.ts.front();
  for (size_t k = 0; k + 1 < piece.points.size(); ++k) {
    const Eigen::Vector3d chord = piece.points[k + 1] - piece.points[k];
    const double length2 = chord.squaredNorm();
    const double f = length2 > 0 ? std::clamp((p - piece.points[k]).dot(chord) / length2, 0.0, 1.0) : 0.0;
    const double d2 = (piece.points[k] + f * chord - p).squaredNorm();
    if (d2 < best) best = d2, t_start = piece.ts[k] + f * (piece.ts[k + 1] - piece.ts[k]);
  }
  return project_to_trim_curve(surface, piece.segment, p, t_start, piece.ts.front(), piece.ts.back());
}

struct Cut {
  double t;
  VertexId vertex;
};

std::vector<Cut> cuts_of(const Piece& piece, const SurfaceEvaluator& surface, const std::vector<Eigen::Vector3d>& vertices,
                         const std::vector<int>& by_x, double tolerance) {
  Eigen::AlignedBox3d box;
  double spacing = 0;
  for (size_t k = 0; k < piece.points.size(); ++k) {
    box.extend(piece.points[k]);
    if (k > 0) spacing = std::max(spacing, (piece.points[k] - piece.points[k - 1]).norm());
  }
  const double margin = tolerance + 0.5 * spacing;  // the curve may bulge past its samples
  const Eigen::Vector3d lo = box.min().array() - margin, hi = box.max().array() + margin;
  auto first = std::lower_bound(by_x.begin(), by_x.end(), lo.x(), [&](int v, double x) { return vertices[v].x() < x; });
  std::vector<Cut> cuts;
  const double t0 = piece.ts.front(), t1 = piece.ts.back();
  for (auto it = first; it != by_x.end() && vertices[*it].x() <= hi.x(); ++it) {
    const VertexId v{*it};
    const Eigen::Vector3d& p = vertices[v.value];
    if (v == piece.start || v == piece.end || (p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
    const CurveProjection foot = project(piece, surface, p);
    if (foot.distance <= tolerance && foot.t > t0 && foot.t < t1) cuts.push_back({foot.t, v});
  }
  std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.t < b.t; });
  return cuts;
}

// The piece as consecutive pieces between its cuts.
std::vector<Piece> cut_piece(const Piece& piece, const std::vector<Cut>& cuts) {
  std::vector<Piece> out;
  Piece rest = piece;
  for (const Cut& cut : cuts) {
    Piece before = rest;
    if (const auto* curve = std::get_if<NurbsCurve>(&rest.segment)) {
      if (!(cut.t > curve->domain_start() && cut.t < curve->domain_end())) continue;  // two cuts at one t
      auto [a, b] = split_curve(*curve, cut.t);
      before.segment = std::move(a);
      rest.segment = std::move(b);
    } else {
      const auto& ends = std::get<Polyline2D>(rest.segment).points;
      const Eigen::Vector2d at = segment_uv(piece.segment, cut.t);  // cut.t is on the uncut 2-point piece
      if (at == ends.front() || at == ends.back()) continue;
      before.segment = Polyline2D{{ends.front(), at}};
      rest.segment = Polyline2D{{at, ends.back()}};
    }
    before.end = cut.vertex;
    rest.start = cut.vertex;
    out.push_back(std::move(before));
  }
  out.push_back(std::move(rest));
  return out;
}

// ---- step 4: pieces that are one edge ----

// Every interior sample of `a` lies within `tolerance` of b's 3D image.
bool runs_along(const Piece& a, const Piece& b, const SurfaceEvaluator& b_surface, double tolerance) {
  for (size_t k = 1; k + 1 < a.points.size(); ++k)
    if (project(b, b_surface, a.points[k]).distance > tolerance) return false;
  return true;
}

// Whether b runs against a (both from one vertex to another, coinciding).
bool runs_against(const Piece& a, const Piece& b, const SurfaceEvaluator& b_surface) {
  if (a.start != a.end) return b.start != a.start;
  const size_t n = a.points.size();
  return project(b, b_surface, a.points[n / 3]).t > project(b, b_surface, a.points[(2 * n) / 3]).t;
}

// Step 4: pieces between the same two vertices whose images coincide, as classes of a union-find.
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
        if (runs_along(pa, pb, *faces[pb.face].surface, tolerance) && runs_along(pb, pa, *faces[pa.face].surface, tolerance))
          edges.unite(group[a], group[b]);
      }
  return edges;
}

// Step 6: the edge of each piece (an index < pieces.size()). A class of more than two coinciding pieces is
// split by solid, a solid being the faces joined by the classes of exactly two pieces: two solids that touch
// along an edge (coincident faces of parts in an assembly) keep an edge each instead of one non-manifold one.
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
        (runs_against(pieces[members.front()], pieces[i], *faces[pieces[i].face].surface) ? backward : forward).push_back(i);
    for (size_t k = 0; k < std::min(forward.size(), backward.size()); ++k) edge_of[backward[k]] = edge_of[forward[k]];
  }
  return edge_of;
}

// Steps 1-6 on the faces `members` (one group); their loops are rebuilt from the pieces.
void sew_group(std::vector<SewFace>& faces, const std::vector<int>& members, const SewingTolerance& tolerance,
               SewingReport& report) {
  std::vector<Piece> pieces = cut_into_pieces(faces, members);
  for (auto& p : pieces) sample(p, *faces[p.face].surface, tolerance.first);
  std::vector<Eigen::Vector3d> vertices = find_vertices(pieces, tolerance.first);

  std::vector<int> by_x(vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) by_x[v] = static_cast<int>(v);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return vertices[a].x() < vertices[b].x(); });
  std::vector<Piece> cut;
  for (const auto& p : pieces) {
    const SurfaceEvaluator& surface = *faces[p.face].surface;
    const std::vector<Cut> cuts = p.is_point ? std::vector<Cut>{} : cuts_of(p, surface, vertices, by_x, tolerance.first);
    if (cuts.empty()) {
      cut.push_back(p);
      continue;
    }
    report.cuts += static_cast<long>(cuts.size());
    for (auto& q : cut_piece(p, cuts)) {
      sample(q, surface, tolerance.first);
      cut.push_back(std::move(q));
    }
  }
  pieces = std::move(cut);

  UnionFind edges = match_pieces(pieces, faces, tolerance.first);

  // Gaps of the source model itself (STEP files written with a tolerance of their own): the pieces still
  // open are matched among themselves at ten times the tolerance, and again, up to the largest.
  for (double wider = tolerance.first; wider < tolerance.largest;) {
    wider = std::min(10 * wider, tolerance.largest);
    std::vector<int> open_index;
    std::vector<int> uses(pieces.size(), 0);
    for (size_t i = 0; i < pieces.size(); ++i) ++uses[edges.find(static_cast<int>(i))];
    auto longer_than_wider = [&](const Piece& p) {
      return std::any_of(p.points.begin(), p.points.end(), [&](const Eigen::Vector3d& q) { return (q - p.points.front()).norm() > wider; });
    };
    for (size_t i = 0; i < pieces.size(); ++i)
      if (!pieces[i].is_point && uses[edges.find(static_cast<int>(i))] < 2 && longer_than_wider(pieces[i]))
        open_index.push_back(static_cast<int>(i));
    if (open_index.size() < 2) break;
    std::vector<Piece> open;
    for (int i : open_index) open.push_back(pieces[i]);
    find_vertices(open, wider);
    UnionFind matched = match_pieces(open, faces, wider);
    for (size_t k = 0; k < open.size(); ++k) {
      const int root = matched.find(static_cast<int>(k));
      if (root != static_cast<int>(k)) {
        edges.unite(open_index[k], open_index[root]);
        report.widest_gap = std::max(report.widest_gap, wider);
      }
    }
  }

  const std::vector<int> edge_of = split_by_solid(pieces, faces, edges);
  std::vector<int> uses(pieces.size(), 0), first_use(pieces.size(), -1), edge_id(pieces.size(), -1);
  for (size_t i = 0; i < pieces.size(); ++i)
    if (uses[edge_of[i]]++ == 0) first_use[edge_of[i]] = static_cast<int>(i);
  for (size_t i = 0; i < pieces.size(); ++i) {
    Piece& p = pieces[i];
    const int e = edge_of[i];
    if (p.is_point) {
      ++report.point_pieces;
    } else if (uses[e] < 2) {
      ++report.open_pieces;
    } else {
      if (edge_id[e] < 0) edge_id[e] = static_cast<int>(report.shared_edges++);
      const int first = first_use[e];
      p.edge = {edge_id[e], first != static_cast<int>(i) && runs_against(pieces[first], p, *faces[p.face].surface)};
      ++report.sewn_pieces;
    }
  }
  report.pieces += static_cast<long>(pieces.size());

  // The loops again, from their pieces (in loop order: pieces were made and cut in order).
  for (const int f : members)
    for (auto& loop : faces[f].trimmed->loops) loop = {};
  for (auto& p : pieces) {
    TrimLoop& loop = faces[p.face].trimmed->loops[p.loop];
    loop.segments.push_back(std::move(p.segment));
    loop.edges.push_back(p.edge);
  }
}

}  // namespace

SewingTolerance sewing_tolerance(double bounding_box_diagonal, double max_deviation) {
  const double largest = 0.25 * max_deviation;
  return {std::min(1e-5 * bounding_box_diagonal, largest), largest};
}

Scene sew_faces(const Scene& scene, const SewingTolerance& tolerance, SewingReport* report_out) {
  if (!(tolerance.first > 0) || !std::isfinite(tolerance.first) || !(tolerance.largest >= tolerance.first) ||
      !std::isfinite(tolerance.largest))
    throw std::invalid_argument("sew_faces: the tolerances must be positive numbers, the largest at least the first, not " +
                                std::to_string(tolerance.first) + " and " + std::to_string(tolerance.largest));
  SewingReport report;
  Scene out = flatten_transforms(scene);
  polygons_as_faces(out.root, tolerance.first, report);
  std::vector<SewFace> faces;
  int groups = 1;  // group 0: faces under no named node
  collect_faces(out.root, 0, groups, faces);
  report.faces = static_cast<int>(faces.size());
  std::vector<std::vector<int>> members(groups);
  for (size_t f = 0; f < faces.size(); ++f) members[faces[f].group].push_back(static_cast<int>(f));
  for (const auto& group : members)
    if (!group.empty()) sew_group(faces, group, tolerance, report);
  if (report_out) *report_out = report;
  return out;
}

}  // namespace cadnurbs
