// A .cnb read back meshes as watertight as the scene written: the shared-edge numbers are kept, so the
// tessellator samples each shared edge once for both faces although their trims were quantised apart.
#include <gtest/gtest.h>

#include <iostream>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/bounding_box.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs {
namespace {

EdgeCounts mesh_edges(const Scene& scene, double deviation, TessellationReport* report) {
  return count_boundary_edges(weld_exact(scene_triangles(tessellate_to_deviation(scene, deviation, report))));
}

TEST(CnbWatertight, StepPartMeshesAsClosedAfterReadBack) {
  const Scene scene = read_step(std::string(CADNURBS_SHARED_DIR) + "/corpus/step/dm1-id-214.stp").scene;
  const double mesh_deviation = 0.01 * scene_bounding_box(scene).diagonal().norm();
  const EdgeCounts original = mesh_edges(scene, mesh_deviation, nullptr);
  for (double d : {1.0, 0.01}) {
    CnbOptions options;
    options.max_deviation = d;
    const Scene decoded = read_cnb(write_cnb(scene, options), "dm1-id-214.cnb");
    TessellationReport report;
    const EdgeCounts read_back = mesh_edges(decoded, mesh_deviation, &report);
    std::cout << "D=" << d << ": boundary edges " << original.boundary << " -> " << read_back.boundary
              << ", non-manifold " << original.non_manifold << " -> " << read_back.non_manifold
              << ", unshared edge uses " << report.unshared_edge_uses << "\n";
    EXPECT_EQ(read_back.boundary, original.boundary) << "D = " << d;
    EXPECT_EQ(read_back.non_manifold, original.non_manifold) << "D = " << d;
    EXPECT_EQ(report.unshared_edge_uses, 0) << "D = " << d;
  }
}

}  // namespace
}  // namespace cadnurbs
