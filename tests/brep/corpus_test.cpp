// Every STEP and IGES file of the shared corpus (MANIFEST.tsv): read by read_step / read_iges and measured
// against OCCT's own reading of the same file. One test per file, so each file is read once per run.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <set>

#include "core/geometry_error.hpp"
#include "corpus_manifest.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/step/step_reader.hpp"
#include "occt_reference.hpp"
#include "trimmed_measure.hpp"

namespace cadnurbs::test {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

BrepTranslation read_corpus_file(const std::string& relative) {
  const std::string path = corpus_file(relative);
  return relative.rfind("step/", 0) == 0 ? read_step(path) : read_iges(path);
}

// Per node holding faces: how often each edge is used, and how often against its direction.
struct EdgeUses {
  std::map<int, int> uses, against;
};

void gather_edge_uses(const SceneNode& node, const std::string& path, std::map<std::string, EdgeUses>& out) {
  for (const auto& shape : node.shapes)
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry))
      for (const auto& loop : t->loops)
        for (const auto& ref : loop.edges) {
          if (ref.edge < 0) continue;
          ++out[path].uses[ref.edge];
          if (ref.reversed) ++out[path].against[ref.edge];
        }
  for (size_t i = 0; i < node.children.size(); ++i)
    gather_edge_uses(node.children[i], path + "/" + std::to_string(i), out);
}

// The first and last `order` knots equal: what viewers expect (DESIGN.md: clamped knot vectors).
bool clamped(const std::vector<double>& knots, int order) {
  for (int i = 1; i < order; ++i)
    if (knots[i] != knots[0] || knots[knots.size() - 1 - i] != knots.back()) return false;
  return true;
}

class BrepCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(BrepCorpus, EveryFaceTranslatedAndMeasured) {
  const std::string relative = GetParam();
  const auto start = std::chrono::steady_clock::now();
  const BrepTranslation translation = read_corpus_file(relative);
  const double read_seconds = seconds_since(start);
  const auto reference_start = std::chrono::steady_clock::now();
  const OcctReference reference = occt_reference(corpus_file(relative));
  const double reference_seconds = seconds_since(reference_start);
  const auto measure_start = std::chrono::steady_clock::now();

  EXPECT_EQ(translation.scene.unit.name, "mm");
  int nurbs = 0, meshes = 0, loops = 0, loops_wrong_way = 0, unclamped = 0;
  SurfaceMeasure nurbs_measure, mesh_measure;
  for_each_shape(translation.scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      ++nurbs;
      EXPECT_NO_THROW(validate(*t, shape.name)) << relative << " " << shape.name;
      if (!clamped(t->surface.u_knots, t->surface.u_order) || !clamped(t->surface.v_knots, t->surface.v_order))
        ++unclamped;
      for (const auto& loop : t->loops)
        for (const auto& segment : loop.segments)
          if (const auto* c = std::get_if<NurbsCurve>(&segment); c && !clamped(c->knots, c->order)) ++unclamped;
      for (size_t l = 0; l < t->loops.size(); ++l) {
        ++loops;
        EXPECT_EQ(t->loops[l].edges.size(), t->loops[l].segments.size()) << shape.name;
        for (const auto& ref : t->loops[l].edges)
          EXPECT_LT(ref.edge, static_cast<int>(translation.degenerated_edges.size())) << shape.name;
        if (!region_left_of_loop(*t, l)) ++loops_wrong_way;
      }
      const SurfaceMeasure m = measure_trimmed_surface(*t, world);
      nurbs_measure.area += m.area;
      nurbs_measure.volume += m.volume;
    } else if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
      ++meshes;
      const SurfaceMeasure m = measure_mesh(*mesh, world);
      mesh_measure.area += m.area;
      mesh_measure.volume += m.volume;
    }
  });
  const double measure_seconds = seconds_since(measure_start);
  EXPECT_EQ(nurbs + meshes, translation.face_count);
  EXPECT_EQ(meshes, static_cast<int>(translation.fallbacks.size()));
  EXPECT_EQ(translation.face_count, reference.faces) << "faces in the scene vs OCCT's TopExp::MapShapes";
  EXPECT_EQ(loops_wrong_way, 0) << "loops not outer counter-clockwise / holes clockwise";
  EXPECT_EQ(unclamped, 0) << "surfaces or trim curves with unclamped knot vectors";

  const double area = nurbs_measure.area + mesh_measure.area;
  const double area_difference = area / reference.area - 1;
  const double adaptive_difference = area / reference.adaptive_area - 1;
  EXPECT_LT(std::abs(area_difference), 1e-3) << "area ours " << area << " vs OCCT " << reference.area;
  // OCCT's two integrations disagree by up to 0.3 % on some faces (see OcctReference); ours lies within
  // 2e-4 of one of them on every file.
  EXPECT_LT(std::min(std::abs(area_difference), std::abs(adaptive_difference)), 2e-4)
      << "area ours " << area << " vs OCCT " << reference.area << " and " << reference.adaptive_area;
  double volume_difference = 0;
  if (reference.faces_all_in_solids) {
    // Outward normals make the flux volume positive and equal to OCCT's volume.
    const double volume = nurbs_measure.volume + mesh_measure.volume;
    volume_difference = volume / reference.volume - 1;
    EXPECT_GT(volume, 0);
    EXPECT_LT(std::abs(volume_difference), 1e-3) << "volume ours " << volume << " vs OCCT " << reference.volume;
    if (translation.fallbacks.empty()) {
      // A closed oriented solid uses each edge twice, once each way (degenerated edges aside).
      std::map<std::string, EdgeUses> uses;
      gather_edge_uses(translation.scene.root, "", uses);
      int bad = 0;
      for (const auto& [node, u] : uses)
        for (const auto& [edge, count] : u.uses) {
          if (translation.degenerated_edges[edge]) continue;
          const int against = u.against.count(edge) ? u.against.at(edge) : 0;
          if (count != 2 || against != 1) ++bad;
        }
      EXPECT_EQ(bad, 0) << "edges not used exactly twice, once each way";
    }
  }
  for (const auto& f : translation.fallbacks)
    std::printf("  fallback: %s face %d (%s): %s\n", f.node.c_str(), f.face_index, f.surface_type.c_str(), f.reason.c_str());
  std::printf("| %-32s | %5d | %4d | %-5s | %14.8g | %14.8g | %+9.2e | %+9.2e | %+9.2e | %6.2f s |\n", relative.c_str(),
              translation.face_count, meshes, translation.scene.source_unit.name.c_str(), area, reference.area,
              area_difference, adaptive_difference, volume_difference, read_seconds);
  std::printf("   reference %.2f s, measure %.2f s\n", reference_seconds, measure_seconds);
  RecordProperty("faces", translation.face_count);
  RecordProperty("fallbacks", meshes);
  RecordProperty("area_relative_difference", std::to_string(area_difference));
}

INSTANTIATE_TEST_SUITE_P(Corpus, BrepCorpus, ::testing::ValuesIn(corpus_paths({"step/", "iges/"})),
                         [](const auto& info) { return corpus_test_name(info.param); });

TEST(BrepCorpusManifest, ListsStepAndIgesFiles) {
  const auto paths = corpus_paths({"step/", "iges/"});
  EXPECT_GE(paths.size(), 20u);
  std::printf("| file | faces | meshes | unit | area ours | area OCCT | vs OCCT | vs OCCT adaptive | volume vs OCCT | read |\n");
}

}  // namespace
}  // namespace cadnurbs::test
