#include "formats/vrml/geometry_to_nodes.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "core/chars_to_double.hpp"
#include "core/equal_points.hpp"
#include "formats/vrml/nurbs_tolerances.hpp"

namespace cadnurbs {

namespace {

// Unit normals only steer shading: 1e-3 is far below a visible change (0.06 degrees).
constexpr double normal_tolerance = 1e-3;

NumberPrecision with_digits(double tolerance, const GeometryPrecision& p) {
  return NumberPrecision{tolerance, p.significant_digits};
}

double written_value(double value, const NumberPrecision& precision) {
  const std::string text = format_number(value, precision);
  double parsed = 0.0;
  chars_to_double(text.data(), text.data() + text.size(), parsed);
  return parsed;
}

bool all_ones(const std::vector<double>& weights) {
  return std::all_of(weights.begin(), weights.end(), [](double w) { return w == 1.0; });
}

// Single-precision viewers keep about 7 significant digits; finer precision needs CoordinateDouble.
bool needs_double(const std::vector<Eigen::Vector3d>& points, const NumberPrecision& precision) {
  if (precision.significant_digits > 0) return precision.significant_digits > 7;
  double largest = 0.0;
  for (const auto& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return precision.tolerance < largest * 6e-8;
}

NodePtr coordinate_node(VrmlDialect dialect, std::vector<Eigen::Vector3d> points, const NumberPrecision& precision) {
  const bool use_double = dialect == VrmlDialect::x3d && needs_double(points, precision);
  auto node = make_node(use_double ? "CoordinateDouble" : "Coordinate");
  node->set("point", MFVec3f{std::move(points)}, precision);
  return node;
}

// Control points as written: w·P or P.
template <class Point>
std::vector<Point> written_points(const std::vector<Point>& points, const std::vector<double>& weights,
                                  bool homogeneous) {
  std::vector<Point> out = points;
  if (homogeneous && !weights.empty())
    for (size_t i = 0; i < out.size(); ++i) out[i] *= weights[i];
  return out;
}

// The fields every NURBS surface node has (NurbsSurface, NurbsPatchSurface, NurbsTrimmedSurface).
void set_surface_fields(Node& node, const NurbsSurface& s, VrmlDialect dialect, const GeometryPrecision& p) {
  const NurbsTolerances t = surface_tolerances(s, p.coordinate_tolerance, p.homogeneous);
  const bool rational = s.is_rational() && !all_ones(s.weights);
  const auto points = written_points(s.points, rational ? s.weights : std::vector<double>{}, p.homogeneous);
  node.set("uDimension", s.u_count);
  node.set("vDimension", s.v_count);
  node.set("uKnot", MFFloat{s.u_knots}, knot_precision(s.u_knots, t.knot, p.significant_digits));
  node.set("vKnot", MFFloat{s.v_knots}, knot_precision(s.v_knots, t.knot, p.significant_digits));
  node.set("uOrder", s.u_order);
  node.set("vOrder", s.v_order);
  if (dialect == VrmlDialect::vrml97)
    node.set("controlPoint", MFVec3f{points}, with_digits(t.control_point, p));
  if (rational) node.set("weight", MFFloat{s.weights}, with_digits(t.weight, p));
  node.set("solid", false);
  if (dialect == VrmlDialect::x3d)
    node.set("controlPoint", SFNode{coordinate_node(dialect, points, with_digits(t.control_point, p))});
}

NodePtr trim_segment_node(const TrimSegment& segment, VrmlDialect dialect, double parameter_tolerance,
                          const GeometryPrecision& p) {
  const std::string points_field = dialect == VrmlDialect::vrml97 ? "point" : "controlPoint";
  if (const auto* polyline = std::get_if<Polyline2D>(&segment)) {
    auto node = make_node(dialect == VrmlDialect::vrml97 ? "Polyline2D" : "ContourPolyline2D");
    node->set(points_field, MFVec2f{polyline->points}, with_digits(parameter_tolerance, p));
    return node;
  }
  const auto& c = std::get<NurbsCurve>(segment);
  const NurbsTolerances t = curve_tolerances(c, parameter_tolerance, p.homogeneous);
  const bool rational = c.is_rational() && !all_ones(c.weights);
  std::vector<Eigen::Vector2d> uv;
  for (const auto& q : c.points) uv.push_back(q.head<2>());
  auto node = make_node("NurbsCurve2D");
  node->set(points_field, MFVec2f{written_points(uv, rational ? c.weights : std::vector<double>{}, p.homogeneous)},
            with_digits(t.control_point, p));
  node->set("knot", MFFloat{c.knots}, knot_precision(c.knots, t.knot, p.significant_digits));
  node->set("order", c.order);
  if (rational) node->set("weight", MFFloat{c.weights}, with_digits(t.weight, p));
  return node;
}

MFNode trimming_contours(const TrimmedSurface& trimmed, VrmlDialect dialect, const GeometryPrecision& p,
                         const TessellationHints* hints) {
  const double parameter_tolerance = trim_parameter_tolerance(trimmed.surface, p.coordinate_tolerance);
  MFNode contours;
  for (size_t l = 0; l < trimmed.loops.size(); ++l) {
    const auto& loop = trimmed.loops[l];
    MFNode segments;
    for (size_t k = 0; k < loop.segments.size(); ++k) {
      NodePtr node = trim_segment_node(loop.segments[k], dialect, parameter_tolerance, p);
      const int count = hints && l < hints->trim_segments.size() && k < hints->trim_segments[l].size()
                            ? hints->trim_segments[l][k] : 0;
      if (count > 0 && std::holds_alternative<NurbsCurve>(loop.segments[k])) node->set("tessellation", count);
      segments.nodes.push_back(node);
    }
    auto contour = make_node("Contour2D");
    contour->set("children", std::move(segments));
    contours.nodes.push_back(contour);
  }
  return contours;
}

void set_surface_tessellation(Node& node, const TessellationHints* hints) {
  if (hints && hints->u > 0) node.set("uTessellation", hints->u);
  if (hints && hints->v > 0) node.set("vTessellation", hints->v);
}

NodePtr surface_node(const TrimmedSurface& trimmed, VrmlDialect dialect, const GeometryPrecision& p,
                     const TessellationHints* hints) {
  if (dialect == VrmlDialect::vrml97) {
    auto surface = make_node("NurbsSurface");
    set_surface_fields(*surface, trimmed.surface, dialect, p);
    set_surface_tessellation(*surface, hints);
    if (trimmed.loops.empty()) return surface;
    auto node = make_node("TrimmedSurface");
    node->set("surface", SFNode{surface});
    node->set("trimmingContour", trimming_contours(trimmed, dialect, p, hints));
    return node;
  }
  auto node = make_node(trimmed.loops.empty() ? "NurbsPatchSurface" : "NurbsTrimmedSurface");
  set_surface_fields(*node, trimmed.surface, dialect, p);
  set_surface_tessellation(*node, hints);
  if (!trimmed.loops.empty()) node->set("trimmingContour", trimming_contours(trimmed, dialect, p, hints));
  return node;
}

NodePtr curve_node(const NurbsCurve& c, VrmlDialect dialect, const GeometryPrecision& p) {
  const NurbsTolerances t = curve_tolerances(c, p.coordinate_tolerance, p.homogeneous);
  const bool rational = c.is_rational() && !all_ones(c.weights);
  const auto points = written_points(c.points, rational ? c.weights : std::vector<double>{}, p.homogeneous);
  auto node = make_node("NurbsCurve");
  if (dialect == VrmlDialect::vrml97) node->set("controlPoint", MFVec3f{points}, with_digits(t.control_point, p));
  node->set("knot", MFFloat{c.knots}, knot_precision(c.knots, t.knot, p.significant_digits));
  node->set("order", c.order);
  if (rational) node->set("weight", MFFloat{c.weights}, with_digits(t.weight, p));
  if (dialect == VrmlDialect::x3d)
    node->set("controlPoint", SFNode{coordinate_node(dialect, points, with_digits(t.control_point, p))});
  return node;
}

NodePtr mesh_node(const TriangleMesh& mesh, VrmlDialect dialect, const GeometryPrecision& p) {
  auto node = make_node("IndexedFaceSet");
  node->set("coord", SFNode{coordinate_node(dialect, mesh.positions, with_digits(p.coordinate_tolerance, p))});
  MFInt32 indices;
  indices.values.reserve(mesh.triangles.size() * 4);
  for (const auto& t : mesh.triangles) indices.values.insert(indices.values.end(), {t[0], t[1], t[2], -1});
  node->set("coordIndex", std::move(indices));
  if (!mesh.corner_normals.empty()) {
    // Corners share a written normal when their normals are written alike: smooth regions store each once,
    // and normals that differ only below the written precision are one vector in the file. Each bitwise-
    // distinct normal is rounded once, then shared by its rounded value (-0 taken as 0, as the text does),
    // the first one kept as it came.
    const NumberPrecision normal_precision = with_digits(normal_tolerance, p);
    EqualPoints distinct;
    std::vector<int> distinct_of_corner(mesh.corner_normals.size());
    for (size_t corner = 0; corner < mesh.corner_normals.size(); ++corner)
      distinct_of_corner[corner] = distinct.add(mesh.corner_normals[corner]);
    EqualPoints written;
    std::vector<int> written_of_distinct(distinct.points().size());
    MFVec3f vectors;
    for (size_t d = 0; d < distinct.points().size(); ++d) {
      const Eigen::Vector3d& n = distinct.points()[d];
      const Eigen::Vector3d rounded(written_value(n.x(), normal_precision) + 0.0,
                                    written_value(n.y(), normal_precision) + 0.0,
                                    written_value(n.z(), normal_precision) + 0.0);
      written_of_distinct[d] = written.add(rounded);
      if (written_of_distinct[d] == static_cast<int>(vectors.values.size())) vectors.values.push_back(n);
    }
    MFInt32 normal_indices;
    normal_indices.values.reserve(mesh.corner_normals.size() / 3 * 4);
    for (size_t corner = 0; corner < mesh.corner_normals.size(); ++corner) {
      normal_indices.values.push_back(written_of_distinct[distinct_of_corner[corner]]);
      if (corner % 3 == 2) normal_indices.values.push_back(-1);
    }
    auto normal = make_node("Normal");
    normal->set("vector", std::move(vectors), with_digits(normal_tolerance, p));
    node->set("normal", SFNode{normal});
    node->set("normalIndex", std::move(normal_indices));
    node->set("normalPerVertex", true);
  } else {
    // Without normals the viewer makes them: smooth across edges below ~29 degrees, creased above.
    node->set("creaseAngle", 0.5, NumberPrecision{});
  }
  node->set("solid", false);
  return node;
}

// Exact planar faces: convex polygons sharing vertices, corners within τ/2 like control points (they are
// the exact geometry, not an approximation within a deviation). No normals: creaseAngle 0 (the default) shades
// every polygon flat, which is what a plane is.
NodePtr polygon_mesh_node(const PolygonMesh& mesh, VrmlDialect dialect, const GeometryPrecision& p) {
  auto node = make_node("IndexedFaceSet");
  node->set("coord", SFNode{coordinate_node(dialect, mesh.positions, with_digits(0.5 * p.coordinate_tolerance, p))});
  MFInt32 indices;
  for (const auto& polygon : mesh.polygons) {
    indices.values.insert(indices.values.end(), polygon.begin(), polygon.end());
    indices.values.push_back(-1);
  }
  if (!indices.values.empty()) indices.values.pop_back();  // the last face needs no terminator
  node->set("coordIndex", std::move(indices));
  node->set("solid", false);
  return node;
}

}  // namespace

NumberPrecision knot_precision(const std::vector<double>& knots, double tolerance, int significant_digits) {
  auto keeps_order = [&](const NumberPrecision& precision) {
    for (size_t i = 0; i + 1 < knots.size(); ++i) {
      const double a = written_value(knots[i], precision), b = written_value(knots[i + 1], precision);
      if ((knots[i] < knots[i + 1]) != (a < b) || a > b) return false;
    }
    return true;
  };
  NumberPrecision precision{tolerance, significant_digits};
  for (int attempt = 0; attempt < 40 && !keeps_order(precision); ++attempt) {
    if (precision.significant_digits > 0)
      precision.significant_digits = std::min(17, precision.significant_digits + 1);
    else
      precision.tolerance *= 0.1;
    if (precision.significant_digits == 17 || precision.tolerance < 1e-300) return NumberPrecision{};
  }
  return keeps_order(precision) ? precision : NumberPrecision{};
}

NodePtr geometry_node(const Geometry& geometry, VrmlDialect dialect, const GeometryPrecision& precision,
                      const TessellationHints* hints) {
  if (const auto* trimmed = std::get_if<TrimmedSurface>(&geometry))
    return surface_node(*trimmed, dialect, precision, hints);
  if (const auto* curve = std::get_if<NurbsCurve>(&geometry)) return curve_node(*curve, dialect, precision);
  if (const auto* polygons = std::get_if<PolygonMesh>(&geometry)) return polygon_mesh_node(*polygons, dialect, precision);
  return mesh_node(std::get<TriangleMesh>(geometry), dialect, precision);
}

}  // namespace cadnurbs
