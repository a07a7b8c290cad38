// The .3dm files of the shared corpus (written by Rhino) as scenes: issue 12's checks that they convert
// with no Brep face left out, that each Brep's trimmed area agrees with the render meshes Rhino stored
// with it (within 1 %), and that they pass the STEP/IGES path's tessellation checks: within D of the
// exact faces, every triangle certified, every shared edge matched, closed solids watertight.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/measure/measure_deviation.hpp"
#include "analysis/measure/scene_area.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/bounding_box.hpp"
#include "formats/3dm/rhino_scene.hpp"
#include "tests/brep/closed_solid.hpp"

namespace cadnurbs::rhino {
namespace {

std::string corpus(const std::string& name) { return std::string(CADNURBS_SHARED_DIR) + "/corpus/3dm/" + name; }

// The object nodes of the scene by their source entity ("object N").
void collect_objects(const SceneNode& node, std::map<std::string, const SceneNode*>& out) {
  if (node.source_entity.rfind("object ", 0) == 0) out[node.source_entity] = &node;
  for (const auto& child : node.children) collect_objects(child, out);
}

struct Expected {
  std::string file;
  int min_faces;        // Brep/Extrusion faces the scene must hold at least
  int render_meshed;    // Breps whose render meshes are compared (all faces meshed)
};

class RhinoCorpus : public ::testing::TestWithParam<Expected> {};

TEST_P(RhinoCorpus, NoFaceLeftOutAreasMatchRenderMeshesAndMeshesAreWatertight) {
  const Expected expected = GetParam();
  const Rhino3dmFile file = read_3dm_file(corpus(expected.file));
  const RhinoScene read = scene_from_3dm(file, expected.file);
  for (const auto& line : read.warnings) std::printf("  %s: %s\n", expected.file.c_str(), line.c_str());
  EXPECT_EQ(read.skipped_faces, 0);
  EXPECT_GE(read.face_count, expected.min_faces);

  // Trimmed area of each Brep against the render meshes stored with it (file units -> mm).
  std::map<std::string, const SceneNode*> objects;
  collect_objects(read.scene.root, objects);
  const double mm2 = file.unit.millimetres * file.unit.millimetres;
  int compared = 0;
  for (const auto& object : file.objects) {
    const auto* brep = std::get_if<RhinoBrep>(&object.geometry);
    if (!brep || brep->render_meshes.empty()) continue;
    bool all_meshed = true;
    double render = 0;
    for (const auto& mesh : brep->render_meshes) {
      if (!mesh) all_meshed = false;
      else render += mesh_area(*mesh) * mm2;
    }
    if (!all_meshed || brep->render_meshes.size() != brep->faces.size()) continue;
    const SceneNode* node = objects.at("object " + std::to_string(object.index));
    double trimmed = 0;
    for (const auto& shape : node->shapes) trimmed += shape_area(shape, Eigen::Affine3d::Identity(), 1e-7);
    std::printf("  %s object %d: trimmed area %.6g mm2, render meshes %.6g mm2 (ratio %.5f)\n",
                expected.file.c_str(), object.index, trimmed, render, render / trimmed);
    EXPECT_NEAR(render / trimmed, 1.0, 0.01) << "object " << object.index;
    ++compared;
  }
  EXPECT_EQ(compared, expected.render_meshed);

  // The STEP/IGES path's tessellation checks at D = 0.01 of the diagonal.
  const double d = 0.01 * scene_bounding_box(read.scene).diagonal().norm();
  TessellationReport report;
  const Scene meshed = tessellate_to_deviation(read.scene, d, &report);
  const DeviationMeasure deviation = measure_deviation(scene_triangles(meshed), read.scene);
  EXPECT_LE(deviation.overall.max, d);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_EQ(report.unshared_edge_uses, 0);
  std::map<std::string, const SceneNode*> meshed_objects;
  collect_objects(meshed.root, meshed_objects);
  int closed = 0;
  for (const auto& [entity, node] : objects) {
    if (!test::closed_solid(*node)) continue;
    ++closed;
    TriangleMesh solid;
    for (const auto& shape : meshed_objects.at(entity)->shapes)
      if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) append(solid, *m);
    const EdgeCounts edges = count_boundary_edges(weld_exact(solid));
    EXPECT_EQ(edges.boundary, 0) << entity;
    EXPECT_EQ(edges.non_manifold, 0) << entity;
  }
  std::printf("  %s: %d faces, %d edges, D %.4g: deviation %.3f D, %ld triangles, %d closed solids\n",
              expected.file.c_str(), read.face_count, read.edge_count, d, deviation.overall.max / d,
              report.triangles, closed);
}

INSTANTIATE_TEST_SUITE_P(Corpus, RhinoCorpus,
                         ::testing::Values(Expected{"v2_my_trimmed_surface.3dm", 1, 0},
                                           Expected{"v4_MechPartA.3dm", 1, 1},
                                           Expected{"v5_teapot.3dm", 3, 0},
                                           Expected{"v5_extrusions.3dm", 7, 0},
                                           Expected{"v7_my_brep.3dm", 6, 0},
                                           Expected{"v7_rhino_logo_nurbs.3dm", 6, 6}),
                         [](const auto& info) {
                           std::string name = info.param.file.substr(0, info.param.file.size() - 4);
                           for (auto& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace cadnurbs::rhino
