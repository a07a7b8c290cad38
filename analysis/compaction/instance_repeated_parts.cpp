#include "analysis/compaction/instance_repeated_parts.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numeric>
#include <optional>

namespace cadnurbs {

namespace {

// Union-find over the shapes of one node.
class Components {
 public:
  explicit Components(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  size_t find(size_t i) { return parent_[i] == i ? i : parent_[i] = find(parent_[i]); }
  void join(size_t a, size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<size_t> parent_;
};

// Keys hold numbers of order 1 (normalised knots, weights, colours) to 1e-7, far below any trimming
// precision; exporters' round-off (-2e-15 for 0) vanishes.
void append_number(std::string& key, double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7f,", std::round(x * 1e7) / 1e7 + 0.0);
  key += text;
}

// A knot vector mapped to [0,1], read forwards or backwards, whichever is smaller: copies of a part
// often have their parameters reversed or swapped (a pin on the other side of a package).
std::string knot_key(const std::vector<double>& knots) {
  const double first = knots.front(), length = knots.back() - knots.front();
  std::string forwards, backwards;
  for (double k : knots) append_number(forwards, (k - first) / length);
  for (auto it = knots.rbegin(); it != knots.rend(); ++it) append_number(backwards, (knots.back() - *it) / length);
  return std::min(forwards, backwards);
}

// A face as a motion (and parametrisation) leaves it: its control points with their weights and points
// of its trimming loops in 3D, as sets; and a key of what must be equal besides.
struct FaceGeometry {
  std::string key;  // orders, counts, knots (up to reversal and swap), weights, loop sizes, colour
  std::vector<Eigen::Vector3d> points;  // control points, then trimming points in 3D
  std::vector<double> weights;          // per point (1 for trimming points)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // of the control points
  // Points a motion carries along and a reparametrisation (affine, reversed or swapped parameters)
  // leaves where they are: the control points' centroid, the point at the middle of the domain, the
  // trimming points' centroid. A part's anchors fix the motion even when it has only two faces.
  std::vector<Eigen::Vector3d> anchors;
};

FaceGeometry face_geometry(const Shape& shape) {
  const auto& face = std::get<TrimmedSurface>(shape.geometry);
  const NurbsSurface& s = face.surface;
  FaceGeometry g;
  const std::string u = std::to_string(s.u_order) + ":" + knot_key(s.u_knots);
  const std::string v = std::to_string(s.v_order) + ":" + knot_key(s.v_knots);
  g.key = std::min(u, v) + "|" + std::max(u, v) + "|" + std::to_string(s.points.size()) + "|";
  std::vector<double> sorted_weights = s.weights;
  std::sort(sorted_weights.begin(), sorted_weights.end());
  for (double w : sorted_weights) append_number(g.key, w);
  for (size_t i = 0; i < s.points.size(); ++i) {
    g.points.push_back(s.points[i]);
    g.weights.push_back(s.weight(static_cast<int>(i) % s.u_count, static_cast<int>(i) / s.u_count));
    g.centroid += s.points[i];
  }
  g.centroid /= double(s.points.size());
  g.anchors = {g.centroid, surface_point(s, 0.5 * (s.u_start() + s.u_end()), 0.5 * (s.v_start() + s.v_end()))};
  const size_t control_points = g.points.size();
  // Trimming loops by their points on the surface: polyline vertices, NURBS segments at five evenly
  // spaced parameters (a reversed segment gives the same five).
  for (const auto& loop : face.loops) {
    size_t count = 0;
    auto add = [&](const Eigen::Vector2d& uv) {
      g.points.push_back(surface_point(s, uv.x(), uv.y()));
      g.weights.push_back(1.0);
      ++count;
    };
    for (const auto& segment : loop.segments) {
      if (const auto* polyline = std::get_if<Polyline2D>(&segment)) {
        for (const auto& p : polyline->points) add(p);
      } else {
        const auto& c = std::get<NurbsCurve>(segment);
        for (int k = 0; k <= 4; ++k)
          add(curve_point(c, c.domain_start() + 0.25 * k * (c.domain_end() - c.domain_start())).head<2>());
      }
    }
    g.key += "L" + std::to_string(count);
  }
  if (g.points.size() > control_points) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (size_t i = control_points; i < g.points.size(); ++i) sum += g.points[i];
    g.anchors.push_back(sum / double(g.points.size() - control_points));
  }
  if (shape.colour) {
    g.key += "#";
    append_number(g.key, shape.colour->r), append_number(g.key, shape.colour->g), append_number(g.key, shape.colour->b);
  }
  return g;
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : points) sum += p;
  return sum / double(std::max<size_t>(points.size(), 1));
}

// The rigid motion that best takes `from` onto `to` point by point (Kabsch's least squares), or nothing
// for a reflection. A pure translation when that already fits within `tolerance` (no rounding from a
// rotation matrix).
std::optional<Eigen::Affine3d> best_motion(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                                           double tolerance) {
  const Eigen::Vector3d from_centre = centroid(from), to_centre = centroid(to);
  Eigen::Affine3d motion = Eigen::Affine3d::Identity();
  motion.translation() = to_centre - from_centre;
  bool translation = true;
  for (size_t i = 0; i < from.size() && translation; ++i) translation = (motion * from[i] - to[i]).norm() <= tolerance;
  if (translation) return motion;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) covariance += (from[i] - from_centre) * (to[i] - to_centre).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d rotation = svd.matrixV() * svd.matrixU().transpose();
  if (rotation.determinant() < 0) return std::nullopt;
  motion.linear() = rotation;
  motion.translation() = to_centre - rotation * from_centre;
  return motion;
}

// One part: its faces sorted by key, equal keys by the distance of their centroid from the part's
// centroid (both unchanged by a motion), so that copies list corresponding faces at the same places.
struct Part {
  std::vector<size_t> faces;  // shape indices, original order
  std::vector<FaceGeometry> geometry;
  std::string key;
};

Part make_part(const SceneNode& node, const std::vector<size_t>& faces) {
  Part part;
  part.faces = faces;
  for (size_t i : faces) part.geometry.push_back(face_geometry(node.shapes[i]));
  std::vector<Eigen::Vector3d> centroids;
  for (const auto& g : part.geometry) centroids.push_back(g.centroid);
  const Eigen::Vector3d centre = centroid(centroids);
  std::sort(part.geometry.begin(), part.geometry.end(), [&](const FaceGeometry& a, const FaceGeometry& b) {
    return a.key != b.key ? a.key < b.key : (a.centroid - centre).norm() < (b.centroid - centre).norm();
  });
  for (const auto& g : part.geometry) part.key += g.key + ";";
  return part;
}

// Every point of `a`, moved, lies within `tolerance` of a point of `b` with the same weight, and the
// other way round (equal counts and a one-to-one search).
bool same_point_sets(const FaceGeometry& a, const FaceGeometry& b, const Eigen::Affine3d& motion, double tolerance) {
  if (a.points.size() != b.points.size()) return false;
  std::vector<bool> used(b.points.size(), false);
  for (size_t i = 0; i < a.points.size(); ++i) {
    const Eigen::Vector3d p = motion * a.points[i];
    bool found = false;
    for (size_t j = 0; j < b.points.size() && !found; ++j)
      if (!used[j] && std::abs(a.weights[i] - b.weights[j]) <= 1e-9 * a.weights[i] && (p - b.points[j]).norm() <= tolerance)
        used[j] = found = true;
    if (!found) return false;
  }
  return true;
}

// Whether every face of part `b` is a face of part `a` (equal keys) with the same key, moved by `motion`
// within `tolerance`.
bool lands_on(const Part& a, const Part& b, const Eigen::Affine3d& motion, double tolerance) {
  std::vector<bool> used(a.geometry.size(), false);
  for (const auto& face : b.geometry) {
    bool matched = false;
    for (size_t i = 0; i < a.geometry.size() && !matched; ++i)
      if (!used[i] && a.geometry[i].key == face.key && same_point_sets(a.geometry[i], face, motion, tolerance))
        used[i] = matched = true;
    if (!matched) return false;
  }
  return true;
}

// `motion` with every entry rounded to `digits` decimals, as a writer's exact numbers read them back
// (n / 10^digits).
Eigen::Affine3d rounded(const Eigen::Affine3d& motion, int digits) {
  const double scale = std::pow(10.0, static_cast<double>(digits));
  Eigen::Affine3d r = motion;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r.linear()(i, j) = std::round(motion.linear()(i, j) * scale) / scale;
    r.translation()(i) = std::round(motion.translation()(i) * scale) / scale;
  }
  return r;
}

// The motion taking part `a` onto part `b` (equal keys) within `tolerance`: estimated from the faces'
// anchors in sorted order, then every face of `b` must be a face of `a` with the same key, moved. Least
// squares leaves rounding in the motion (a quarter turn as 0.99999999999999978 and 4.4e-16, a pitch of
// 3.81 as 3.8100000000000005), which a writer must then spell out in full (17 digits in VRML, 8 bytes in
// .cnb: 52 of the 396 transform entries of a Phoenix MC 1,5/5-GF connector). So the motion is rounded to
// the fewest decimals that still land every face within the same tolerance, and kept as found otherwise.
std::optional<Eigen::Affine3d> part_motion(const Part& a, const Part& b, double tolerance) {
  std::vector<Eigen::Vector3d> from, to;
  for (size_t i = 0; i < a.geometry.size(); ++i) {
    from.insert(from.end(), a.geometry[i].anchors.begin(), a.geometry[i].anchors.end());
    to.insert(to.end(), b.geometry[i].anchors.begin(), b.geometry[i].anchors.end());
  }
  if (from.size() != to.size()) return std::nullopt;
  const auto motion = best_motion(from, to, tolerance);
  if (!motion || !lands_on(a, b, *motion, tolerance)) return std::nullopt;
  for (int digits : {0, 1, 2, 3, 4, 6, 8, 10, 12})
    if (const Eigen::Affine3d tidy = rounded(*motion, digits); lands_on(a, b, tidy, tolerance)) return tidy;
  return motion;
}

}  // namespace

namespace {

// Finds the parts (lists of shape indices of `node`) that are copies of an earlier one and moves them,
// with their originals, into child nodes as instance_repeated_parts says. Returns the copies placed.
int place_copies(SceneNode& node, const std::vector<std::vector<size_t>>& part_faces, double tolerance,
                 const std::string& what) {
  std::vector<Part> parts;
  for (const auto& faces : part_faces) parts.push_back(make_part(node, faces));
  std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.faces < b.faces; });  // file order

  std::map<std::string, std::vector<size_t>> parts_by_key;
  for (size_t p = 0; p < parts.size(); ++p) parts_by_key[parts[p].key].push_back(p);
  std::vector<int> original_of(parts.size(), -1);  // -1: not a copy
  std::vector<Eigen::Affine3d> motion_of(parts.size(), Eigen::Affine3d::Identity());
  std::vector<bool> has_copies(parts.size(), false);
  for (const auto& [key, group] : parts_by_key)
    for (size_t a = 0; a < group.size(); ++a) {
      const size_t original = group[a];
      if (original_of[original] >= 0) continue;
      for (size_t b = a + 1; b < group.size(); ++b) {
        const size_t copy = group[b];
        if (original_of[copy] >= 0) continue;
        if (auto motion = part_motion(parts[original], parts[copy], tolerance)) {
          original_of[copy] = static_cast<int>(original);
          motion_of[copy] = *motion;
          has_copies[original] = true;
        }
      }
    }

  // Originals and copies become child nodes (in the order of their first face); the rest stays.
  int copies = 0;
  std::vector<bool> moved(node.shapes.size(), false);
  std::vector<SceneNode> placed;
  for (size_t p = 0; p < parts.size(); ++p) {
    const size_t source = original_of[p] >= 0 ? static_cast<size_t>(original_of[p]) : p;
    if (!has_copies[source]) continue;
    SceneNode part;
    part.source_entity = what + " of " + std::to_string(parts[p].faces.size()) + " faces";
    part.transform = motion_of[p];
    for (size_t i : parts[source].faces) part.shapes.push_back(node.shapes[i]);
    for (size_t i : parts[p].faces) moved[i] = true;
    placed.push_back(std::move(part));
    if (original_of[p] >= 0) ++copies;
  }
  if (placed.empty()) return copies;
  std::vector<Shape> staying;
  for (size_t i = 0; i < node.shapes.size(); ++i)
    if (!moved[i]) staying.push_back(std::move(node.shapes[i]));
  node.shapes = std::move(staying);
  node.children.insert(node.children.begin(), std::make_move_iterator(placed.begin()),
                       std::make_move_iterator(placed.end()));
  return copies;
}

}  // namespace

int instance_repeated_parts(SceneNode& node, double tolerance) {
  int copies = 0;
  for (auto& child : node.children) copies += instance_repeated_parts(child, tolerance);

  std::vector<size_t> faces;
  for (size_t i = 0; i < node.shapes.size(); ++i)
    if (std::holds_alternative<TrimmedSurface>(node.shapes[i].geometry) && node.shapes[i].name.empty())
      faces.push_back(i);
  if (faces.size() < 2) return copies;
  // A part is also one colour: a fused pin shares edges with the body it stands on.
  Components components(node.shapes.size());
  std::map<int, std::vector<size_t>> faces_of_edge;
  for (size_t i : faces)
    for (const auto& loop : std::get<TrimmedSurface>(node.shapes[i].geometry).loops)
      for (const auto& edge : loop.edges)
        if (edge.edge >= 0) faces_of_edge[edge.edge].push_back(i);
  for (const auto& [edge, users] : faces_of_edge)
    for (size_t a : users)
      for (size_t b : users)
        if (a < b && node.shapes[a].colour == node.shapes[b].colour) components.join(a, b);
  std::map<size_t, std::vector<size_t>> faces_by_root;
  for (size_t i : faces) faces_by_root[components.find(i)].push_back(i);
  std::vector<std::vector<size_t>> parts;
  for (auto& [root, part_faces] : faces_by_root) parts.push_back(std::move(part_faces));
  return copies + place_copies(node, parts, tolerance, "part");
}

int instance_repeated_faces(SceneNode& node, double tolerance, const std::function<bool(const Shape&)>& eligible) {
  int copies = 0;
  for (auto& child : node.children) copies += instance_repeated_faces(child, tolerance, eligible);
  std::vector<std::vector<size_t>> faces;
  for (size_t i = 0; i < node.shapes.size(); ++i)
    if (std::holds_alternative<TrimmedSurface>(node.shapes[i].geometry) && node.shapes[i].name.empty() &&
        eligible(node.shapes[i]))
      faces.push_back({i});
  if (faces.size() < 2) return copies;
  return copies + place_copies(node, faces, tolerance, "copy");
}

}  // namespace cadnurbs
