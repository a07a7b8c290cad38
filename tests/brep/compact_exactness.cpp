#include "compact_exactness.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "analysis/compaction/compact_scene.hpp"
#include "analysis/measure/mesh_distance.hpp"
#include "analysis/measure/scene_area.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/bounding_box.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"

namespace cadnurbs::test {
namespace {

struct Plane {
  Eigen::Vector3d point, normal;
};

// Planes of the source's planar bilinear faces, in world coordinates.
std::vector<Plane> source_planes(const Scene& scene) {
  std::vector<Plane> planes;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    const auto* t = std::get_if<TrimmedSurface>(&shape.geometry);
    if (!t || t->surface.u_order != 2 || t->surface.v_order != 2 || t->surface.u_count != 2 || t->surface.v_count != 2)
      return;
    const auto& s = t->surface;
    const Eigen::Vector3d o = world * s.point(0, 0);
    const Eigen::Vector3d n = (world * s.point(1, 0) - o).cross(world * s.point(0, 1) - o);
    if (n.norm() > 0) planes.push_back({o, n.normalized()});
  });
  return planes;
}

// Triangles of polygon sets read back: meshes without normals (fallback meshes carry normals).
TriangleMesh polygon_set_triangles(const Scene& scene) {
  TriangleMesh out;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    const auto* m = std::get_if<TriangleMesh>(&shape.geometry);
    if (!m || !m->corner_normals.empty()) return;
    TriangleMesh placed = *m;
    for (auto& p : placed.positions) p = world * p;
    append(out, placed);
  });
  return out;
}

}  // namespace

void check_compact_is_exact(const Scene& source, const std::string& name) {
  const auto box = scene_bounding_box(source);
  const double diagonal = box.diagonal().norm();
  const double tau = 1e-6 * diagonal;  // the writer's default precision
  auto written = [&](const Scene& scene, double precision, const std::string& what) {
    VrmlWriteOptions options;
    options.encoding = VrmlEncoding::x3d_classic;
    options.coordinate_tolerance = precision;
    return parse_vrml(format_vrml(scene, options), name + " " + what);
  };
  const Scene compact = written(compact_scene(source, tau), tau, "compact");
  const Scene exact = written(source, tau, "exact");

  // Area: the written precision alone moves a face's border by up to tau, which changes thin parts'
  // areas by more than 1e-6; so the area compares both forms written at tau / 100 (the rewrites then
  // at tau / 100 too). 1e-7: a tenth of what is checked; finer takes minutes on faces of hundreds of
  // knots (linkrods).
  const double fine = 0.01 * tau;
  const double compact_area = scene_area(written(compact_scene(source, fine), fine, "compact, fine"), 1e-7);
  const double exact_area = scene_area(written(source, fine, "exact, fine"), 1e-7);
  EXPECT_NEAR(compact_area, exact_area, 1e-6 * exact_area) << name << " area";

  const double d = 0.005 * diagonal;
  const TriangleMesh a = scene_triangles(tessellate_to_deviation(compact, d));
  const TriangleMesh b = scene_triangles(tessellate_to_deviation(exact, d));
  const MeshDistance distance = mesh_distance(a, b);
  EXPECT_LE(distance.overall.max, 2 * d) << name << " mesh distance";

  const auto planes = source_planes(source);
  const TriangleMesh polygons = polygon_set_triangles(compact);
  int off_plane = 0;
  for (const auto& t : polygons.triangles) {
    bool on_a_plane = false;
    for (const auto& plane : planes) {
      bool all = true;
      for (int k : t) all = all && std::abs(plane.normal.dot(polygons.positions[k] - plane.point)) <= 1.5 * tau;
      if (all) {
        on_a_plane = true;
        break;
      }
    }
    off_plane += !on_a_plane;
  }
  EXPECT_EQ(off_plane, 0) << name << ": triangles of polygon sets off every source plane, of "
                          << polygons.triangles.size();
  std::printf("%s: area %.9g (exact %.9g, rel %.1e), mesh distance %.3g D, %zu polygon-set triangles\n", name.c_str(),
              compact_area, exact_area, std::abs(compact_area - exact_area) / exact_area, distance.overall.max / d,
              polygons.triangles.size());
}

}  // namespace cadnurbs::test
