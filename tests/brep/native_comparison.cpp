#include "native_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/measure/trimmed_surface_area.hpp"
#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "closed_solid.hpp"
#include "core/bounding_box.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs::test {
namespace {

struct Comparison {
  int faces = 0;
  double worst_area = 0;  // largest relative area difference
  std::string worst_face;
};

void compare_nodes(const SceneNode& ours, const SceneNode& theirs, const Colour& our_inherited,
                   const Colour& their_inherited, const std::string& path, double area_tolerance, Comparison& out) {
  EXPECT_EQ(ours.name, theirs.name) << path;
  EXPECT_EQ(ours.source_entity, theirs.source_entity) << path;
  EXPECT_TRUE(ours.transform.isApprox(theirs.transform, 1e-9)) << path;
  ASSERT_EQ(ours.shapes.size(), theirs.shapes.size()) << path;
  ASSERT_EQ(ours.children.size(), theirs.children.size()) << path;
  const Colour our_colour = ours.colour.value_or(our_inherited), their_colour = theirs.colour.value_or(their_inherited);
  for (std::size_t i = 0; i < ours.shapes.size(); ++i) {
    const Shape& a = ours.shapes[i];
    const Shape& b = theirs.shapes[i];
    const std::string where = path + " " + display_name(b);
    // OCCT's path writes a face it cannot convert as a mesh, "face N (mesh)"; ours may convert it.
    const bool occt_meshed = std::holds_alternative<TriangleMesh>(b.geometry);
    EXPECT_EQ(a.source_entity + (occt_meshed && !std::holds_alternative<TriangleMesh>(a.geometry) ? " (mesh)" : ""),
              b.source_entity)
        << where;
    EXPECT_EQ(a.source_type, b.source_type) << where;
    const Colour ca = a.colour.value_or(our_colour), cb = b.colour.value_or(their_colour);
    EXPECT_NEAR(ca.r, cb.r, 1e-6) << where;
    EXPECT_NEAR(ca.g, cb.g, 1e-6) << where;
    EXPECT_NEAR(ca.b, cb.b, 1e-6) << where;
    const auto* sa = std::get_if<TrimmedSurface>(&a.geometry);
    const auto* sb = std::get_if<TrimmedSurface>(&b.geometry);
    if (!sa || !sb) continue;  // OCCT fell back to a mesh: no exact area to compare
    const double area_a = trimmed_surface_area(*sa, 1e-8), area_b = trimmed_surface_area(*sb, 1e-8);
    const double relative = std::abs(area_a - area_b) / std::max(area_b, 1e-300);
    ++out.faces;
    if (relative > out.worst_area) out.worst_area = relative, out.worst_face = where;
    EXPECT_LE(relative, area_tolerance) << where << ": area " << area_a << " vs OCCT's " << area_b;
  }
  for (std::size_t i = 0; i < ours.children.size(); ++i)
    compare_nodes(ours.children[i], theirs.children[i], our_colour, their_colour, path + "/" + theirs.children[i].source_entity,
                  area_tolerance, out);
}

long open_edges(const SceneNode& exact, const SceneNode& meshed, const std::vector<bool>& degenerated) {
  long open = 0;
  if (closed_solid(exact, degenerated)) {
    TriangleMesh solid;
    for (const auto& shape : meshed.shapes)
      if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) append(solid, *m);
    const EdgeCounts edges = count_boundary_edges(weld_exact(solid));
    open += edges.boundary + edges.non_manifold;
  }
  for (std::size_t i = 0; i < exact.children.size(); ++i) open += open_edges(exact.children[i], meshed.children[i], degenerated);
  return open;
}

}  // namespace

void expect_same_as_occt(const BrepTranslation& native, const std::string& path, const std::string& relative,
                         double area_tolerance) {
  const BrepTranslation occt = read_step(path);
  EXPECT_EQ(native.face_count, occt.face_count);
  EXPECT_NEAR(native.scene.source_unit.millimetres, occt.scene.source_unit.millimetres, 1e-12);
  Comparison comparison;
  compare_nodes(native.scene.root, occt.scene.root, Colour{}, Colour{}, native.scene.root.name, area_tolerance, comparison);

  const double d = 0.01 * scene_bounding_box(occt.scene).diagonal().norm();
  TessellationReport report;
  const Scene meshed = tessellate_to_deviation(native.scene, d, &report);
  const DeviationMeasure deviation = measure_deviation(scene_triangles(meshed), occt.scene);
  const long open = open_edges(native.scene.root, meshed.root, native.degenerated_edges);
  // Watertight wherever OpenCASCADE's path is: its scene meshed the same way, open edges counted alike.
  const Scene occt_meshed = tessellate_to_deviation(occt.scene, d);
  const long occt_open = open_edges(occt.scene.root, occt_meshed.root, occt.degenerated_edges);
  std::printf("| %-28s | %5d faces | area worst %.2e (%s) | mesh to OCCT's faces %.3f D | open edges %ld (OCCT's path %ld) |\n",
              relative.c_str(), comparison.faces, comparison.worst_area, comparison.worst_face.c_str(),
              deviation.overall.max / d, open, occt_open);
  EXPECT_LE(deviation.overall.max, d);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_EQ(report.unshared_edge_uses, 0);
  if (occt_open == 0) EXPECT_EQ(open, 0);
}

}  // namespace cadnurbs::test
