#include "read_back_watertight.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "analysis/compaction/compact_scene.hpp"
#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/bounding_box.hpp"
#include "core/repair_trimming_loops.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"

namespace cadnurbs::test {
namespace {

EdgeCounts open_edges(const Scene& scene, double d, TessellationReport& report) {
  return count_boundary_edges(weld_exact(scene_triangles(tessellate_to_deviation(scene, d, &report))));
}

// Edges the B-rep path shares: (placement, edge id) used by two or more trim segments.
long shared_edges(const Scene& scene) {
  std::map<std::pair<std::vector<double>, int>, int> uses;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    const auto* t = std::get_if<TrimmedSurface>(&shape.geometry);
    if (!t) return;
    const std::vector<double> placement(world.matrix().data(), world.matrix().data() + 16);
    for (const auto& loop : t->loops)
      for (const auto& ref : loop.edges)
        if (ref.edge >= 0) ++uses[{placement, ref.edge}];
  });
  long shared = 0;
  for (const auto& [key, n] : uses) shared += n >= 2;
  return shared;
}

}  // namespace

EdgeCounts read_back_edges(const Scene& source, VrmlEncoding encoding, bool compact, double deviation,
                           SewingReport* sewing, TessellationReport* report) {
  const double diagonal = scene_bounding_box(source).diagonal().norm();
  const double tau = 1e-6 * diagonal;  // the writer's default precision
  VrmlWriteOptions options;
  options.encoding = encoding;
  options.coordinate_tolerance = tau;
  Scene read = parse_vrml(format_vrml(compact ? compact_scene(source, tau) : source, options), "read back");
  repair_trimming_loops(read);  // as every reader's output on its way into convert (load_scene)
  const Scene sewn = sew_faces(read, sewing_tolerance(diagonal, deviation), sewing);
  TessellationReport own_report;
  return open_edges(sewn, deviation, report ? *report : own_report);
}

void check_read_back_watertight(const Scene& source, const std::string& name) {
  const double diagonal = scene_bounding_box(source).diagonal().norm();
  const double d = 0.01 * diagonal;
  TessellationReport step_report;
  const EdgeCounts step = open_edges(source, d, step_report);
  const long step_shared = shared_edges(source);
  std::printf("%s: B-rep: %ld shared edges, %ld boundary, %ld non-manifold\n", name.c_str(), step_shared, step.boundary,
              step.non_manifold);
  struct Form {
    const char* what;
    VrmlEncoding encoding;
    bool compact;
  };
  for (const Form form : {Form{"x3dv", VrmlEncoding::x3d_classic, true}, Form{"x3dv --exact-nurbs", VrmlEncoding::x3d_classic, false},
                          Form{"wrl", VrmlEncoding::vrml97, true}, Form{"x3d", VrmlEncoding::x3d_xml, true}}) {
    SewingReport sewing;
    TessellationReport report;
    const EdgeCounts back = read_back_edges(source, form.encoding, form.compact, d, &sewing, &report);
    std::printf("  %-18s %ld shared edges (%ld cuts, widest gap %.3g), %ld open and %ld point pieces; %ld boundary, "
                "%ld non-manifold, %d unshared uses\n",
                form.what, sewing.shared_edges, sewing.cuts, sewing.widest_gap, sewing.open_pieces, sewing.point_pieces,
                back.boundary, back.non_manifold, report.unshared_edge_uses);
    EXPECT_EQ(report.unshared_edge_uses, 0) << name << " " << form.what;
    if (step.boundary + step.non_manifold > 0) continue;  // open in the B-rep: the counts are printed only
    EXPECT_EQ(back.boundary, 0) << name << " " << form.what;
    EXPECT_EQ(back.non_manifold, 0) << name << " " << form.what;
    if (!form.compact && sewing.cuts == 0 && sewing.point_pieces == 0) {
      EXPECT_EQ(sewing.shared_edges, step_shared) << name << " " << form.what;
    }
  }
}

}  // namespace cadnurbs::test
