#include "formats/vrml/nodes_to_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <type_traits>

#include "core/analytic_surface.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"
#include "formats/vrml/parse_error.hpp"

namespace cadnurbs {

namespace {

class GeometryReader {
 public:
  GeometryReader(const Node& node, const GeometryReadContext& context) : node_(node), context_(context) {}

  [[noreturn]] void fail(const Node& node, const std::string& reason) const {
    throw_parse_error(context_.file, node.line, node.type + ": " + reason);
  }

  std::vector<Geometry> read() const;

  // One reader per geometry node type; kGeometryNodes below says which serves which.
  std::vector<Geometry> patch_surface() const { return {checked(TrimmedSurface{surface(node_), {}}, node_)}; }
  std::vector<Geometry> trimmed_patch_surface() const {
    return {checked(TrimmedSurface{surface(node_), loops(node_)}, node_)};
  }
  // VRML97's TrimmedSurface holds its surface as a node of its own.
  std::vector<Geometry> surface_with_contours() const {
    const auto* s = node_.get<SFNode>("surface");
    if (!s || !s->node) fail(node_, "has no surface");
    if (s->node->type != "NurbsSurface") fail(node_, "surface is a " + s->node->type + ", not a NurbsSurface");
    return {checked(TrimmedSurface{surface(*s->node), loops(node_)}, node_)};
  }
  std::vector<Geometry> space_curve() const { return {checked(curve(node_, 3), node_)}; }
  std::vector<Geometry> indexed_faces() const { return {checked(face_set(), node_)}; }
  std::vector<Geometry> indexed_lines() const { return line_set(); }
  std::vector<Geometry> indexed_triangles() const { return {checked(triangle_set(), node_)}; }
  std::vector<Geometry> box_mesh() const { return {box()}; }
  std::vector<Geometry> sphere_surface() const { return {checked(sphere(), node_)}; }

 private:
  template <class G>
  Geometry checked(G geometry, const Node& node) const {
    try {
      if constexpr (std::is_same_v<G, TrimmedSurface>) {
        validate(geometry.surface, node.type);  // the closure tolerance needs a valid domain
        close_loops(geometry);
        validate(geometry, node.type, closure_tolerance(geometry.surface));
      } else {
        validate(geometry, node.type);
      }
    } catch (const GeometryError& e) {
      throw_parse_error(context_.file, node.line, e.what());
    }
    return geometry;
  }

  static double closure_tolerance(const NurbsSurface& s) {
    return 1e-3 * std::hypot(s.u_end() - s.u_start(), s.v_end() - s.v_start());
  }

  int integer_field(const Node& node, const char* name, int fallback) const {
    const auto* v = node.get<int>(name);
    return v ? *v : fallback;
  }

  std::vector<double> doubles(const Node& node, const char* name) const {
    const auto* v = node.get<MFFloat>(name);
    return v ? v->values : std::vector<double>{};
  }

  // An absent or empty knot vector is the clamped uniform one; a wrong length is an error.
  std::vector<double> knots(const Node& node, const char* name, int order, int count) const {
    std::vector<double> k = doubles(node, name);
    if (k.empty() && order >= 2 && count >= order) return clamped_uniform_knots(order, count);
    if (k.size() != static_cast<size_t>(order + count))
      fail(node, std::string(name) + " has " + std::to_string(k.size()) + " values; " + std::to_string(count) +
                     " control points of order " + std::to_string(order) + " need " + std::to_string(order + count));
    return k;
  }

  std::vector<double> weights(const Node& node, size_t count) const {
    std::vector<double> w = doubles(node, "weight");
    if (!w.empty() && w.size() != count)
      fail(node, std::to_string(w.size()) + " weights for " + std::to_string(count) + " control points");
    return w;
  }

  // Control points of a NURBS node: MFVec3f in VRML97, a Coordinate node in X3D.
  std::vector<Eigen::Vector3d> control_points(const Node& node) const {
    if (const auto* mf = node.get<MFVec3f>("controlPoint")) return mf->values;
    if (const auto* sf = node.get<SFNode>("controlPoint")) {
      if (!sf->node) return {};
      if (sf->node->type != "Coordinate" && sf->node->type != "CoordinateDouble")
        fail(node, "controlPoint is a " + sf->node->type + ", not a Coordinate");
      if (const auto* points = sf->node->get<MFVec3f>("point")) return points->values;
    }
    return {};
  }

  template <class Point>
  void to_euclidean(std::vector<Point>& points, const std::vector<double>& weights) const {
    if (!context_.homogeneous || weights.empty()) return;
    for (size_t i = 0; i < points.size(); ++i) points[i] /= weights[i];
  }

  NurbsSurface surface(const Node& node) const {
    NurbsSurface s;
    s.u_count = integer_field(node, "uDimension", 0);
    s.v_count = integer_field(node, "vDimension", 0);
    s.u_order = integer_field(node, "uOrder", 3);
    s.v_order = integer_field(node, "vOrder", 3);
    s.points = control_points(node);
    if (s.u_count < 0 || s.v_count < 0 || s.points.size() != static_cast<size_t>(s.u_count) * s.v_count)
      fail(node, std::to_string(s.points.size()) + " control points, but uDimension x vDimension = " +
                     std::to_string(s.u_count) + " x " + std::to_string(s.v_count));
    s.u_knots = knots(node, "uKnot", s.u_order, s.u_count);
    s.v_knots = knots(node, "vKnot", s.v_order, s.v_count);
    s.weights = weights(node, s.points.size());
    to_euclidean(s.points, s.weights);
    return s;
  }

  NurbsCurve curve(const Node& node, int dimension) const {
    NurbsCurve c;
    c.dimension = dimension;
    c.order = integer_field(node, "order", 3);
    if (dimension == 3) {
      c.points = control_points(node);
    } else {
      const auto* uv = node.get<MFVec2f>(node.find("point") ? "point" : "controlPoint");
      if (uv)
        for (const auto& p : uv->values) c.points.emplace_back(p.x(), p.y(), 0.0);
    }
    c.knots = knots(node, "knot", c.order, c.count());
    c.weights = weights(node, c.points.size());
    to_euclidean(c.points, c.weights);
    try {
      validate(c, node.type);
    } catch (const GeometryError& e) {
      throw_parse_error(context_.file, node.line, e.what());
    }
    return c;
  }

  // A trimming segment without a single point.
  static bool is_empty_segment(const Node& segment) {
    for (const char* field : {"point", "controlPoint"})
      if (const auto* points = segment.get<MFVec2f>(field); points && !points->values.empty()) return false;
    return true;
  }

  std::vector<TrimLoop> loops(const Node& owner) const {
    std::vector<TrimLoop> out;
    const auto* contours = owner.get<MFNode>("trimmingContour");
    if (!contours) return out;
    for (const auto& contour : contours->nodes) {
      if (!contour) continue;
      if (contour->type != "Contour2D") fail(*contour, "a trimmingContour must be a Contour2D");
      TrimLoop loop;
      if (const auto* children = contour->get<MFNode>("children"))
        for (const auto& segment : children->nodes) {
          if (!segment || is_empty_segment(*segment)) continue;  // draws nothing (white_dune writes such)
          if (segment->type == "NurbsCurve2D") {
            loop.segments.emplace_back(curve(*segment, 2));
          } else if (segment->type == "Polyline2D" || segment->type == "ContourPolyline2D") {
            const auto* points = segment->get<MFVec2f>(segment->type == "Polyline2D" ? "point" : "controlPoint");
            Polyline2D polyline;
            if (points) polyline.points = points->values;
            if (polyline.points.size() < 2) fail(*segment, "a polyline needs at least 2 points");
            loop.segments.emplace_back(std::move(polyline));
          } else {
            fail(*segment, "is not a trimming segment (NurbsCurve2D or a 2D polyline)");
          }
        }
      if (loop.segments.empty()) continue;  // trims nothing
      out.push_back(std::move(loop));
    }
    return out;
  }

  // Rounded numbers leave small gaps at joints; where a segment starts or ends at a control point
  // (clamped knots, polylines), that point is moved onto its neighbour's end.
  static void close_loops(TrimmedSurface& trimmed) {
    const double tolerance = closure_tolerance(trimmed.surface);
    for (auto& loop : trimmed.loops) {
      const size_t n = loop.segments.size();
      for (size_t i = 0; i < n; ++i) {
        auto& current = loop.segments[i];
        auto& following = loop.segments[(i + 1) % n];
        const Eigen::Vector2d end = segment_end(current);
        if ((end - segment_start(following)).norm() > tolerance || (end - segment_start(following)).norm() == 0.0) continue;
        if (!move_start(following, end)) move_end(current, segment_start(following));
      }
    }
  }

  static bool clamped_start(const NurbsCurve& c) { return c.knots[0] == c.knots[c.order - 1]; }
  static bool clamped_end(const NurbsCurve& c) {
    return c.knots[c.points.size()] == c.knots.back();
  }

  static bool move_start(TrimSegment& segment, const Eigen::Vector2d& p) {
    if (auto* polyline = std::get_if<Polyline2D>(&segment)) {
      polyline->points.front() = p;
      return true;
    }
    auto& c = std::get<NurbsCurve>(segment);
    if (!clamped_start(c)) return false;
    c.points.front() = Eigen::Vector3d(p.x(), p.y(), 0.0);
    return true;
  }

  static void move_end(TrimSegment& segment, const Eigen::Vector2d& p) {
    if (auto* polyline = std::get_if<Polyline2D>(&segment)) {
      polyline->points.back() = p;
      return;
    }
    auto& c = std::get<NurbsCurve>(segment);
    if (clamped_end(c)) c.points.back() = Eigen::Vector3d(p.x(), p.y(), 0.0);
  }

  std::vector<Eigen::Vector3d> coordinates(const Node& node) const {
    const auto* coord = node.get<SFNode>("coord");
    if (!coord || !coord->node) return {};
    if (coord->node->type != "Coordinate" && coord->node->type != "CoordinateDouble")
      fail(node, "coord is a " + coord->node->type + ", not a Coordinate");
    const auto* points = coord->node->get<MFVec3f>("point");
    return points ? points->values : std::vector<Eigen::Vector3d>{};
  }

  // Index lists split at -1 (the last may end without one).
  static std::vector<std::vector<int>> faces(const std::vector<int>& indices) {
    std::vector<std::vector<int>> out(1);
    for (int i : indices) {
      if (i == -1) out.emplace_back();
      else out.back().push_back(i);
    }
    if (out.back().empty()) out.pop_back();
    return out;
  }

  TriangleMesh face_set() const {
    TriangleMesh mesh;
    mesh.positions = coordinates(node_);
    const auto* coord_index = node_.get<MFInt32>("coordIndex");
    const auto polygons = faces(coord_index ? coord_index->values : std::vector<int>{});
    const bool ccw = node_.get<bool>("ccw") ? *node_.get<bool>("ccw") : true;
    // Normals: per corner (normalIndex, else coordIndex) or per face (normalIndex, else face order).
    std::vector<Eigen::Vector3d> vectors;
    if (const auto* normal = node_.get<SFNode>("normal"); normal && normal->node) {
      if (normal->node->type != "Normal") fail(node_, "normal is a " + normal->node->type + ", not a Normal");
      if (const auto* v = normal->node->get<MFVec3f>("vector")) vectors = v->values;
    }
    const bool per_vertex = node_.get<bool>("normalPerVertex") ? *node_.get<bool>("normalPerVertex") : true;
    const auto* normal_index = node_.get<MFInt32>("normalIndex");
    std::vector<std::vector<int>> normal_polygons;
    std::vector<int> face_normals;
    if (!vectors.empty()) {
      if (per_vertex) {
        normal_polygons = normal_index && !normal_index->values.empty() ? faces(normal_index->values) : polygons;
        if (normal_polygons.size() != polygons.size()) fail(node_, "normalIndex and coordIndex list different faces");
      } else {
        for (size_t f = 0; f < polygons.size(); ++f)
          face_normals.push_back(normal_index && !normal_index->values.empty()
                                     ? (f < normal_index->values.size() ? normal_index->values[f] : -1)
                                     : static_cast<int>(f));
      }
    }
    auto normal_at = [&](int index) {
      if (index < 0 || static_cast<size_t>(index) >= vectors.size())
        fail(node_, "normal index " + std::to_string(index) + " is out of range (" + std::to_string(vectors.size()) +
                        " normals)");
      return vectors[static_cast<size_t>(index)];
    };
    for (size_t f = 0; f < polygons.size(); ++f) {
      const auto& polygon = polygons[f];
      if (polygon.size() < 3) fail(node_, "face " + std::to_string(f) + " has fewer than 3 corners");
      if (!normal_polygons.empty() && normal_polygons[f].size() != polygon.size())
        fail(node_, "face " + std::to_string(f) + " has a different number of normal indices and coordinate indices");
      for (size_t k = 1; k + 1 < polygon.size(); ++k) {
        std::array<size_t, 3> corners = {0, k, k + 1};
        if (!ccw) std::swap(corners[1], corners[2]);
        mesh.triangles.push_back({polygon[corners[0]], polygon[corners[1]], polygon[corners[2]]});
        for (size_t c : corners) {
          if (!normal_polygons.empty()) mesh.corner_normals.push_back(normal_at(normal_polygons[f][c]));
          else if (!face_normals.empty()) mesh.corner_normals.push_back(normal_at(face_normals[f]));
        }
      }
    }
    return mesh;
  }

  std::vector<Geometry> line_set() const {
    std::vector<Geometry> out;
    const auto points = coordinates(node_);
    const auto* coord_index = node_.get<MFInt32>("coordIndex");
    for (const auto& polyline : faces(coord_index ? coord_index->values : std::vector<int>{})) {
      if (polyline.size() < 2) continue;  // a single point draws nothing
      NurbsCurve c;
      c.order = 2;
      for (int i : polyline) {
        if (i < 0 || static_cast<size_t>(i) >= points.size())
          fail(node_, "coordIndex " + std::to_string(i) + " is out of range (" + std::to_string(points.size()) + " points)");
        c.points.push_back(points[static_cast<size_t>(i)]);
      }
      c.knots = clamped_uniform_knots(2, c.count());
      out.push_back(checked(std::move(c), node_));
    }
    return out;
  }

  // The exact rational biquadratic sphere about the origin, its poles on the y axis (X3D's up).
  TrimmedSurface sphere() const {
    const double radius = node_.get<double>("radius") ? *node_.get<double>("radius") : 1.0;
    if (!(radius > 0.0)) fail(node_, "radius must be positive");
    SphereSurface sphere{AxisFrame{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                   Eigen::Vector3d::UnitY()},
                         radius};
    return TrimmedSurface{analytic_to_nurbs(sphere, NaturalBox{0.0, 2.0 * M_PI, -M_PI / 2, M_PI / 2}).surface, {}};
  }

  TriangleMesh triangle_set() const {
    TriangleMesh mesh;
    mesh.positions = coordinates(node_);
    const auto* index = node_.get<MFInt32>("index");
    const std::vector<int> corners = index ? index->values : std::vector<int>{};
    if (corners.size() % 3 != 0) fail(node_, "index holds " + std::to_string(corners.size()) + " values, not whole triangles");
    const bool ccw = node_.get<bool>("ccw") ? *node_.get<bool>("ccw") : true;
    for (size_t i = 0; i < corners.size(); i += 3) {
      for (size_t k = 0; k < 3; ++k)
        if (corners[i + k] < 0 || static_cast<size_t>(corners[i + k]) >= mesh.positions.size())
          fail(node_, "index " + std::to_string(corners[i + k]) + " is out of range (" +
                          std::to_string(mesh.positions.size()) + " points)");
      if (ccw) mesh.triangles.push_back({corners[i], corners[i + 1], corners[i + 2]});
      else mesh.triangles.push_back({corners[i], corners[i + 2], corners[i + 1]});
    }
    return mesh;
  }

  Geometry box() const {
    const auto* size = node_.get<SFVec3f>("size");
    const Eigen::Vector3d half = 0.5 * (size ? size->value : Eigen::Vector3d(2, 2, 2));
    if (!(half.minCoeff() > 0.0)) fail(node_, "size must be positive");
    TriangleMesh mesh;
    for (int i = 0; i < 8; ++i)
      mesh.positions.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                                  (i & 4) ? half.z() : -half.z());
    // Two counter-clockwise triangles per face, seen from outside.
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
      mesh.triangles.push_back({q[0], q[1], q[2]});
      mesh.triangles.push_back({q[0], q[2], q[3]});
    }
    return mesh;
  }

  const Node& node_;
  const GeometryReadContext& context_;
};

// The geometry nodes cadnurbs reads, one row each. `needs_coord`: without a coord node X3D draws nothing
// (white_dune's robot fills one in by a Script later), so such a node gives no geometry.
struct GeometryNodeRow {
  std::string_view type;
  bool needs_coord;
  std::vector<Geometry> (GeometryReader::*read)() const;
};

constexpr GeometryNodeRow kGeometryNodes[] = {
    {"NurbsSurface", false, &GeometryReader::patch_surface},
    {"NurbsPatchSurface", false, &GeometryReader::patch_surface},
    {"NurbsTrimmedSurface", false, &GeometryReader::trimmed_patch_surface},
    {"TrimmedSurface", false, &GeometryReader::surface_with_contours},
    {"NurbsCurve", false, &GeometryReader::space_curve},
    {"IndexedFaceSet", true, &GeometryReader::indexed_faces},
    {"IndexedLineSet", true, &GeometryReader::indexed_lines},
    {"IndexedTriangleSet", true, &GeometryReader::indexed_triangles},
    {"Box", false, &GeometryReader::box_mesh},
    {"Sphere", false, &GeometryReader::sphere_surface},
};

const GeometryNodeRow* geometry_node_row(std::string_view type) {
  for (const auto& row : kGeometryNodes)
    if (row.type == type) return &row;
  return nullptr;
}

std::vector<Geometry> GeometryReader::read() const {
  const GeometryNodeRow* row = geometry_node_row(node_.type);
  if (!row) fail(node_, "is not a geometry node cadnurbs reads");
  if (row->needs_coord && !(node_.get<SFNode>("coord") && node_.get<SFNode>("coord")->node)) return {};
  return (this->*(row->read))();
}

}  // namespace

bool reads_geometry_node(const std::string& type) { return geometry_node_row(type) != nullptr; }

std::vector<Geometry> geometry_from_node(const Node& node, const GeometryReadContext& context) {
  return GeometryReader(node, context).read();
}

}  // namespace cadnurbs
