// make_report_page OUT.html: the HTML report of two inputs for the browser test
// (tests/viewers/report_html_check.mjs): samples/capping-90.x3dv, measured here, and a file that does
// not exist, failed with the reader's own message.
//
// The capping's record comes from real files: the sample's own text (the NURBS view and the NURBS
// figures), and the scene tessellated at D = 1 mm (analysis/tessellation/tessellate_to_deviation) written as X3D
// classic IndexedFaceSets (the mesh view and figures). The storage curve holds that mesh's bytes at
// D = 4, 2, 1, 0.5 and 0.25 mm; floats are the thesis's (report/storage_accounting).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "report/html/report_html.hpp"
#include "report/storage_crossover.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "report/storage_accounting.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/bounding_box.hpp"
#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"

namespace cadnurbs {
namespace {

const std::string sample = CADNURBS_SOURCE_DIR "/samples/capping-90.x3dv";
const std::string missing = CADNURBS_SOURCE_DIR "/samples/no-such-part.x3dv";

struct MeshFile {
  std::string text;
  MeshStorage storage;
  double certified_deviation = 0;
};

MeshFile mesh_file(const Scene& scene, double deviation) {
  TessellationReport report;
  const Scene mesh = tessellate_to_deviation(scene, deviation, &report);
  VrmlWriteOptions options;
  options.encoding = VrmlEncoding::x3d_classic;
  return {format_vrml(mesh, options), mesh_storage(weld_exact(scene_triangles(mesh))), report.certified_deviation};
}

PartRecord capping_record(const std::string& nurbs_text, const Scene& scene, const MeshFile& mesh) {
  PartRecord r;
  r.input = sample;
  r.unit = "mm";
  r.diagonal = scene_bounding_box(scene).diagonal().norm();
  r.deviation = 1.0;
  r.nurbs = nurbs_storage(scene);
  r.compact_nurbs = r.nurbs;
  r.mesh = mesh.storage;
  r.mesh_certified_deviation = mesh.certified_deviation;
  RepresentationFigures nurbs;
  nurbs.key = "x3dv-compact";
  nurbs.label = "X3D classic NURBS (the sample file)";
  nurbs.bytes = long(nurbs_text.size());
  nurbs.gzip_bytes = long(gzip(nurbs_text).size());
  nurbs.floats = r.nurbs.total_floats();
  nurbs.integers = r.nurbs.polygon_corners;
  nurbs.deviation_basis = "not measured (the file itself)";
  RepresentationFigures faces;
  faces.key = "x3dv-mesh";
  faces.label = "X3D classic IndexedFaceSet at D";
  faces.kind = RepresentationKind::mesh;
  faces.bytes = long(mesh.text.size());
  faces.gzip_bytes = long(gzip(mesh.text).size());
  faces.floats = mesh.storage.indexed_floats;
  faces.integers = mesh.storage.indexed_integers;
  faces.deviation = mesh.certified_deviation;
  faces.deviation_kind = DeviationKind::bound;
  faces.deviation_basis = "bound: the tessellator's certificate";
  r.representations = {nurbs, faces};

  std::vector<BytesAtDeviation> points;
  for (double d : {4.0, 2.0, 1.0, 0.5, 0.25}) {
    const MeshFile at_d = d == 1.0 ? mesh : mesh_file(scene, d);
    const long bytes = long(at_d.text.size()), gzip_bytes = long(gzip(at_d.text).size());
    r.curve.push_back({"x3dv-mesh", d, bytes, gzip_bytes, at_d.storage.indexed_floats});
    points.push_back({d, double(std::min(bytes, gzip_bytes))});
  }
  const long nurbs_bytes = std::min(nurbs.bytes, nurbs.gzip_bytes);
  const Crossover crossing = storage_crossover(points, double(nurbs_bytes));
  CrossoverFigure figure{"x3dv-mesh", nurbs.key, nurbs_bytes};
  if (crossing.deviation) figure.deviation = *crossing.deviation;
  figure.mesh_larger_everywhere = crossing.mesh_larger_everywhere;
  r.crossovers = {figure};
  return r;
}

PartRecord missing_record() {
  PartRecord r;
  r.input = missing;
  r.failed = true;
  try {
    read_vrml(missing);
    r.error = "read unexpectedly";
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

}  // namespace
}  // namespace cadnurbs

int main(int argc, char** argv) {
  using namespace cadnurbs;
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_report_page OUT.html\n");
    return 2;
  }
  try {
    const std::string nurbs_text = read_file(sample);
    const Scene scene = parse_vrml(nurbs_text, sample);
    const MeshFile mesh = mesh_file(scene, 1.0);
    const std::vector<PartRecord> records{capping_record(nurbs_text, scene, mesh), missing_record()};
    const std::vector<PartViews> views{{nurbs_text, mesh.text}, {}};
    const std::string page = report_html(records, views);
    write_file_atomically(argv[1], page);
    std::printf("make_report_page: %s: %zu bytes; mesh at 1 mm: %ld triangles, %zu bytes\n", argv[1], page.size(),
                mesh.storage.triangles, mesh.text.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_report_page: %s\n", e.what());
    return 1;
  }
  return 0;
}
