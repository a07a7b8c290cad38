#include "report/storage_accounting.hpp"

namespace cadnurbs {

NurbsStorage nurbs_storage(const Scene& scene) {
  NurbsStorage s;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      ++s.surfaces;
      s.control_points += static_cast<long>(t->surface.points.size());
      s.knots += static_cast<long>(t->surface.u_knots.size() + t->surface.v_knots.size());
      for (const auto& loop : t->loops)
        for (const auto& segment : loop.segments) {
          if (const auto* curve = std::get_if<NurbsCurve>(&segment)) {
            ++s.trim_curves;
            s.trim_control_points += curve->count();
            s.trim_knots += static_cast<long>(curve->knots.size());
          } else {
            s.trim_polyline_points += static_cast<long>(std::get<Polyline2D>(segment).points.size());
          }
        }
    } else if (const auto* curve = std::get_if<NurbsCurve>(&shape.geometry)) {
      s.control_points += curve->count();
      s.knots += static_cast<long>(curve->knots.size());
    } else if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) {
      s.polygon_vertices += static_cast<long>(polygons->positions.size());
      for (const auto& polygon : polygons->polygons) s.polygon_corners += static_cast<long>(polygon.size());
    }
  });
  s.floats = 4 * s.control_points + s.knots;
  s.trim_floats = 3 * s.trim_control_points + s.trim_knots + 2 * s.trim_polyline_points;
  s.polygon_floats = 3 * s.polygon_vertices;
  return s;
}

MeshStorage mesh_storage(const TriangleMesh& mesh) {
  MeshStorage s;
  s.vertices = static_cast<long>(mesh.positions.size());
  s.triangles = static_cast<long>(mesh.triangles.size());
  s.indexed_floats = 3 * s.vertices;
  s.indexed_integers = 3 * s.triangles;
  s.indexed_floats_with_normals = 6 * s.vertices;
  s.soup_floats = 9 * s.triangles;
  s.soup_floats_with_normals = 12 * s.triangles;
  return s;
}

}  // namespace cadnurbs
