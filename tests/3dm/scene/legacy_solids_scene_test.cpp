// Rhino 1's five legacy solids (v1_five_solids.3dm: a box, a cylinder and a cone as shells, a torus and a
// sphere as single closed faces) through the scene and the tessellator. The file stores no meshes of
// them (Rhino 1 wrote none: its chunks are the preview bitmap, settings, views, a layer and the five
// legacy objects), so the independent measure is each solid's closed-form area and volume, with its
// dimensions taken from the bounding box Rhino 1 stored with the object (shell stuff: after two int32;
// face stuff: after three int32), not from the geometry this reader builds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "analysis/measure/scene_area.hpp"
#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/bounding_box.hpp"
#include "formats/3dm/rhino_scene.hpp"
#include "formats/3dm/typecodes.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs::rhino {
namespace {

const std::string kFile = CADNURBS_SHARED_DIR "/corpus/3dm/v1_five_solids.3dm";
constexpr double kPi = std::numbers::pi;

// The bounding box extents Rhino 1 stored with each object, in file order.
std::vector<Eigen::Vector3d> stored_extents(const std::string& bytes) {
  std::vector<Eigen::Vector3d> out;
  ArchiveReader reader(bytes, "v1", 1, 32);
  while (reader.bytes_left() > 0) {
    const ChunkHeader h = reader.begin_chunk();
    if (h.is_short()) continue;
    const bool shell = h.typecode == tcode::kLegacyShell, face = h.typecode == tcode::kLegacyFace;
    if (shell || face) {
      const std::uint32_t stuff = shell ? tcode::kLegacyShellStuff : tcode::kLegacyFaceStuff;
      for (ChunkHeader a = reader.begin_chunk(); a.typecode != stuff; a = reader.begin_chunk())
        if (!a.is_short()) reader.end_chunk();
      reader.skip(shell ? 8 : 12);
      const Eigen::Vector3d lo = reader.point3(), hi = reader.point3();
      out.push_back(hi - lo);
      reader.end_chunk();
    }
    reader.end_chunk();
  }
  return out;
}

struct Measures {
  double area, volume;
};

// The extent that differs from the other two (a solid of revolution's axis), and the value of the pair.
std::pair<double, double> odd_and_pair(const Eigen::Vector3d& e) {
  std::array<double, 3> s = {e.x(), e.y(), e.z()};
  std::sort(s.begin(), s.end());
  return s[1] - s[0] < s[2] - s[1] ? std::pair{s[2], s[0]} : std::pair{s[0], s[2]};
}

Measures box(const Eigen::Vector3d& e) {
  return {2 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x()), e.x() * e.y() * e.z()};
}
Measures cylinder(const Eigen::Vector3d& e) {
  const auto [h, d] = odd_and_pair(e);
  const double r = d / 2;
  return {2 * kPi * r * r + 2 * kPi * r * h, kPi * r * r * h};
}
Measures cone(const Eigen::Vector3d& e) {
  const auto [h, d] = odd_and_pair(e);
  const double r = d / 2;
  return {kPi * r * r + kPi * r * std::hypot(r, h), kPi * r * r * h / 3};
}
Measures torus(const Eigen::Vector3d& e) {
  const auto [thickness, d] = odd_and_pair(e);
  const double tube = thickness / 2, centre = d / 2 - tube;
  return {4 * kPi * kPi * centre * tube, 2 * kPi * kPi * centre * tube * tube};
}
Measures sphere(const Eigen::Vector3d& e) {
  const double r = e.x() / 2;
  return {4 * kPi * r * r, 4 * kPi * r * r * r / 3};
}

// Volume enclosed by a closed, outward-oriented triangle mesh (divergence theorem).
double enclosed_volume(const TriangleMesh& mesh) {
  double six_v = 0;
  for (const auto& t : mesh.triangles)
    six_v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]]));
  return six_v / 6;
}

void collect_objects(const SceneNode& node, std::map<std::string, const SceneNode*>& out) {
  if (node.source_entity.rfind("object ", 0) == 0) out[node.source_entity] = &node;
  for (const auto& child : node.children) collect_objects(child, out);
}

TEST(LegacySolids, AreasAndVolumesMatchTheClosedFormsOfTheStoredBoxesAndTheMeshesAreWatertight) {
  const std::vector<Eigen::Vector3d> extents = stored_extents(read_file(kFile));
  ASSERT_EQ(extents.size(), 5u);
  const std::array<Measures (*)(const Eigen::Vector3d&), 5> closed_form = {box, cylinder, cone, torus, sphere};
  const std::array<const char*, 5> names = {"box", "cylinder", "cone", "torus", "sphere"};

  const RhinoScene read = read_3dm(kFile);
  EXPECT_EQ(read.face_count, 13);
  EXPECT_EQ(read.skipped_faces, 0);
  // D: a thousandth of the scene's diagonal. The mesh lies within D of the surface (both ways), so the
  // volume between them is at most area x D: the bound the mesh volumes are held to.
  const double d = 1e-3 * scene_bounding_box(read.scene).diagonal().norm();
  TessellationReport report;
  const Scene meshed = tessellate_to_deviation(read.scene, d, &report);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_EQ(report.unshared_edge_uses, 0);
  std::map<std::string, const SceneNode*> objects, meshed_objects;
  collect_objects(read.scene.root, objects);
  collect_objects(meshed.root, meshed_objects);
  ASSERT_EQ(objects.size(), 5u);

  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE(names[i]);
    const std::string entity = "object " + std::to_string(i);
    const Measures expected = closed_form[i](extents[i]);
    double area = 0;
    for (const auto& shape : objects.at(entity)->shapes) area += shape_area(shape, Eigen::Affine3d::Identity(), 1e-9);
    TriangleMesh solid;
    for (const auto& shape : meshed_objects.at(entity)->shapes)
      if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) append(solid, *m);
    const TriangleMesh welded = weld_exact(solid);
    const EdgeCounts edges = count_boundary_edges(welded);
    const double volume = enclosed_volume(welded);
    std::printf(
        "  %-8s area %.9g (closed form %.9g, rel %.1e), mesh area %.6g, mesh volume %.6g (closed form %.6g, "
        "%.3f of area x D), %zu triangles, %ld boundary edges\n",
        names[i], area, expected.area, area / expected.area - 1, mesh_area(welded), volume, expected.volume,
        std::abs(volume - expected.volume) / (expected.area * d), welded.triangles.size(), edges.boundary);
    // The faces are exact NURBS (rational circles) and the stored box is Rhino's own, so the closed form
    // is the exact area; the quadrature is asked for 1e-9 of it.
    EXPECT_NEAR(area / expected.area, 1.0, 1e-9);
    EXPECT_LE(std::abs(volume - expected.volume), expected.area * d);
    EXPECT_EQ(edges.boundary, 0);
    EXPECT_EQ(edges.non_manifold, 0);
  }
}

}  // namespace
}  // namespace cadnurbs::rhino
