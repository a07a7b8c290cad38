// Issue 3's geometry and watertightness checks on every STEP and IGES file of the shared corpus: our
// tessellation at D = 0.01 x the bounding-box diagonal (tessellate_to_deviation of read_step /
// read_iges)
//  - lies within D of our exact trimmed NURBS (measure_deviation, two-sided),
//  - lies within 2 D of OCCT's BRepMesh of OCCT's own reading of the file at deflection D (mesh_distance,
//    two-sided),
//  - has no boundary and no non-manifold edge on every closed solid (a node whose faces use each of
//    their edges twice, once each way), welded by exact position.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <map>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/measure/face_area_check.hpp"
#include "analysis/measure/measure_deviation.hpp"
#include "analysis/measure/mesh_distance.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/bounding_box.hpp"
#include "closed_solid.hpp"
#include "corpus_manifest.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/step/step_reader.hpp"
#include "occt_mesh.hpp"
#include "occt_reference.hpp"

namespace cadnurbs::test {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Watertightness {
  int closed_solids = 0;
  long boundary = 0, non_manifold = 0;
};

// `exact` and `meshed` are the same tree (tessellate_to_deviation keeps it): the faces of every closed
// solid of `exact` are welded from `meshed` and their edges counted.
void count_open_edges(const SceneNode& exact, const SceneNode& meshed, const std::vector<bool>& degenerated,
                      const std::string& path, Watertightness& out) {
  if (closed_solid(exact, degenerated)) {
    TriangleMesh solid;
    for (const auto& shape : meshed.shapes)
      if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) append(solid, *m);
    const EdgeCounts edges = count_boundary_edges(weld_exact(solid));
    ++out.closed_solids;
    out.boundary += edges.boundary;
    out.non_manifold += edges.non_manifold;
    if (edges.boundary || edges.non_manifold)
      std::printf("  open solid %s: %ld boundary, %ld non-manifold edges\n", path.c_str(), edges.boundary,
                  edges.non_manifold);
  }
  for (size_t i = 0; i < exact.children.size(); ++i)
    count_open_edges(exact.children[i], meshed.children[i], degenerated, path + "/" + std::to_string(i), out);
}

// Faces of `exact` whose mesh in `meshed` differs in area by more than face_area_check allows: a face
// covered twice, or tilted across a twisted surface (issue 9), printed by name.
int faces_beyond_area_allowance(const Scene& exact, const Scene& meshed, double d) {
  int beyond = 0;
  for (const auto& [face, check] : check_face_areas(exact, meshed, d)) {
    if (!check.beyond()) continue;
    ++beyond;
    std::printf("  face %s: mesh area %g, face %g, allowance %g\n", display_name(*face).c_str(), check.mesh_area,
                check.area, check.allowance);
  }
  return beyond;
}

class TessellationCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(TessellationCorpus, WithinDeviationCloseToOcctAndWatertight) {
  const std::string relative = GetParam();
  const std::string path = corpus_file(relative);
  const BrepTranslation translation = relative.rfind("step/", 0) == 0 ? read_step(path) : read_iges(path);
  const double d = 0.01 * scene_bounding_box(translation.scene).diagonal().norm();

  auto start = std::chrono::steady_clock::now();
  TessellationReport report;
  const Scene meshed = tessellate_to_deviation(translation.scene, d, &report);
  const double ours_seconds = seconds_since(start);
  const TriangleMesh ours = scene_triangles(meshed);

  start = std::chrono::steady_clock::now();
  const DeviationMeasure deviation = measure_deviation(ours, translation.scene);
  const double measure_seconds = seconds_since(start);

  const OcctReference reference = occt_reference(path);
  start = std::chrono::steady_clock::now();
  occt_mesh(reference.shape, d);
  const double occt_seconds = seconds_since(start);
  const TriangleMesh theirs = occt_triangles(reference.shape);
  const MeshDistance between = mesh_distance(ours, theirs);

  Watertightness water;
  count_open_edges(translation.scene.root, meshed.root, translation.degenerated_edges, "", water);

  std::printf("| %-32s | %9.4g | %7zu | %7zu | %6.3f | %6.3f | %6.3f | %3d | %5ld | %3ld / %3d | %6.2f s | %6.2f s | %6.2f s |\n",
              relative.c_str(), d, ours.triangles.size(), theirs.triangles.size(), deviation.overall.max / d,
              between.a_to_b.max / d, between.b_to_a.max / d, water.closed_solids, water.boundary,
              report.uncertified_triangles, report.unshared_edge_uses, ours_seconds, occt_seconds, measure_seconds);

  EXPECT_LE(deviation.overall.max, d) << "our tessellation vs our exact NURBS";
  EXPECT_LE(between.overall.max, 2 * d) << "our tessellation vs OCCT's BRepMesh";
  EXPECT_EQ(water.boundary, 0) << "boundary edges over " << water.closed_solids << " closed solids";
  EXPECT_EQ(water.non_manifold, 0) << "non-manifold edges over " << water.closed_solids << " closed solids";
  if (reference.faces_all_in_solids) {
    EXPECT_GT(water.closed_solids, 0) << "OCCT sees solids; we found none closed";
  }
  // Every triangle certified within D by the rigorous bound, not only measured within it. (Chords of a
  // shared edge used to be checked on the edge's first face only; as1-tu-203 then left 9 slivers.)
  EXPECT_EQ(report.uncertified_triangles, 0);
  // Every use of a shared edge must find the edge's samples on its own pcurve within D: a miss
  // means the faces' conversions disagree (Ventilator.stp's half cylinders did, by 1.6 mm).
  EXPECT_EQ(report.unshared_edge_uses, 0);
  // No face covered twice: each face's mesh area within what a mesh within D may differ by.
  EXPECT_EQ(faces_beyond_area_allowance(translation.scene, meshed, d), 0);
}

INSTANTIATE_TEST_SUITE_P(Corpus, TessellationCorpus, ::testing::ValuesIn(corpus_paths({"step/", "iges/"})),
                         [](const auto& info) { return corpus_test_name(info.param); });

TEST(TessellationCorpusTable, Header) {
  std::printf("| file | D (mm) | triangles ours | triangles OCCT | ours vs NURBS / D | ours to OCCT / D | OCCT to ours / D "
              "| closed solids | open edges | uncertified / unshared | time ours | time OCCT | measure |\n");
  EXPECT_GE(corpus_paths({"step/", "iges/"}).size(), 20u);
}

}  // namespace
}  // namespace cadnurbs::test
