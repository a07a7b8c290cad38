// No .cnb loses a face (issue 39): every corpus STEP/IGES file and the 20 library parts, written as
// `convert --deviation D -o P.cnb` writes them (the compact form, each body as NURBS or as a certified
// mesh, whichever codes smaller) and also with every body as NURBS (the candidate the choice may take),
// at D = 1e-2, 1e-3 and 1e-4 of the part's diagonal and at 1 mm. Each file is read back as convert reads
// it (load_scene: the loops repaired, faces without area dropped with a line) and meshed at D as convert
// meshes it (certified_mesh: sewn at D/4 first when it holds polygon sets or names no edges):
//  - as many trimmed surfaces as were written (nothing dropped on reading);
//  - the mesh at D has no more uncertified triangles and no more loops without area than the part's own;
//  - the writer's bound is within D;
//  - the read-back mesh (welded by position) has no longer a boundary than the compact form's own mesh
//    made the same way, or than its rim as sewing samples it (1 % and D allowed for the sampling of an
//    open part's rim), and none where the file holds the exact part's meshes (cheapest_coding's
//    exact_meshed or merged_meshes candidate) and the part's own mesh is closed. Non-manifold edges are
//    counted, not refused: at a coarse D the vertex grid puts the corners of features thinner than it
//    on one point (triangles of no area, within D), which welding then pinches.
// Prints the sizes and what was meshed, one line per file and D.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "analysis/compaction/compact_scene.hpp"
#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "converters/cnb_coding.hpp"
#include "converters/file_formats.hpp"
#include "converters/scene_preparation.hpp"
#include "core/bounding_box.hpp"
#include "core/flatten_transforms.hpp"
#include "corpus_manifest.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "part_library.hpp"
#include "temporary_folder.hpp"

namespace cadnurbs::test {
namespace {

struct Meshed {
  TessellationReport report;
  EdgeCounts edges;
  double rim = 0;  // the open boundary's length as sewing samples it (8 points per span), when sewn
};

Meshed mesh_at(const Scene& scene, double d) {
  Meshed m;
  m.edges = count_boundary_edges(weld_exact(scene_triangles(tessellate_to_deviation(scene, d, &m.report))));
  return m;
}

// As `convert X.cnb --mesh` meshes a file that names no B-rep faces: sewn first where certified_mesh sews.
Meshed mesh_as_read(const Scene& scene, double d) {
  BrepTranslation no_brep;
  no_brep.face_count = 0;
  CertifiedMesh c = certified_mesh(no_brep, scene, d);
  Meshed m;
  m.report = c.report;
  m.rim = c.sewing.open_length;
  m.edges = count_boundary_edges(weld_exact(scene_triangles(c.meshes)));
  return m;
}

int trimmed_surfaces(const Scene& scene) { return static_cast<int>(count_entities(scene).trimmed_surfaces); }

// One file written and read back: the checks above against the part's own mesh `own`.
void check_file(const std::string& bytes, double bound, const Scene& written, const Meshed& own,
                const Meshed& own_compact, bool exact_meshes, double d, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_LE(bound, d * (1 + 1e-12));
  TemporaryFolder folder;
  const std::string path = (folder.path() / "part.cnb").string();
  write_file_atomically(path, bytes);
  const BrepTranslation read = load_scene(path);
  EXPECT_EQ(trimmed_surfaces(read.scene), trimmed_surfaces(written));
  const Meshed back = mesh_as_read(read.scene, d);
  EXPECT_LE(back.report.uncertified_triangles, own.report.uncertified_triangles);
  EXPECT_LE(back.report.loops_without_area, own.report.loops_without_area);
  // An open part's rim meshed finer is longer (chords approach the curve from below): the reference is the
  // longer of the compact form's mesh rim and its rim as sewing samples it.
  EXPECT_LE(back.edges.boundary_length, 1.01 * std::max(own_compact.edges.boundary_length, own_compact.rim) + d);
  if (exact_meshes && own.edges.boundary == 0 && own.edges.non_manifold == 0) EXPECT_EQ(back.edges.boundary, 0);
  std::cout << what << ": " << bytes.size() << " bytes, " << read.repairs.size() << " repair lines on reading, "
            << back.edges.boundary << " boundary edges, length " << back.edges.boundary_length << ", "
            << back.edges.non_manifold << " non-manifold (compact form " << own_compact.edges.boundary << ", "
            << own_compact.edges.boundary_length << "; part " << own.edges.boundary << ")\n";
}

void check_part(const Scene& scene, const std::string& name) {
  const double diagonal = scene_bounding_box(scene).diagonal().norm();
  const Scene compact = compact_scene(scene, written_tolerance(scene, 0));
  for (double d : {1e-2 * diagonal, 1e-3 * diagonal, 1e-4 * diagonal, 1.0}) {
    const Meshed own = mesh_at(scene, d), own_compact = mesh_as_read(compact, d);
    const CnbCoding as_is = cnb_coding(compact, d, nullptr, false);
    check_file(as_is.bytes, as_is.written.deviation_bound(), compact, own, own_compact, false, d,
               name + ", NURBS as they are, D = " + std::to_string(d));
    const CnbCoding chosen = cnb_coding(compact, d, &scene);
    using Whole = CodingChoiceReport::Whole;
    check_file(chosen.bytes, chosen.written.deviation_bound(), chosen.scene, own, own_compact,
               chosen.choice.chosen == Whole::exact_meshed || chosen.choice.chosen == Whole::merged_meshes, d,
               name + ", as convert writes it (" + std::to_string(chosen.choice.bodies_meshed) + " of " +
                   std::to_string(chosen.choice.bodies) + " bodies meshed), D = " + std::to_string(d));
  }
}

class CnbReadBackCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(CnbReadBackCorpus, NoFaceLost) { check_part(read_scene(corpus_file(GetParam())), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Corpus, CnbReadBackCorpus, ::testing::ValuesIn(corpus_paths({"step/", "iges/"})),
                         [](const auto& info) { return corpus_test_name(info.param); });

class CnbReadBackLibrary : public ::testing::TestWithParam<std::string> {};

TEST_P(CnbReadBackLibrary, NoFaceLost) {
  check_part(read_scene(library_file(GetParam(), ".step")), library_part_name(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Library, CnbReadBackLibrary, ::testing::ValuesIn(library_parts()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
